#!/usr/bin/env bash
# Builds the libFuzzer targets (the 'fuzz' preset: clang, ASan + UBSan) and runs each for a while, then runs the
# core tests as clang built them (the other presets build with GCC; the two compilers read our code differently).
#   scripts/fuzz.sh [SECONDS]   each target runs SECONDS (default 60); exit 1 on any crash, sanitizer report or
#                               failed test.
# The targets run side by side (one core each), so the fuzzing takes SECONDS, not twice that.
# A crashing input is left in build/fuzz/ (crash-*); replay it with build/fuzz/tests/fuzz/fuzz_<target> FILE and
# keep it as a regression case in tests/core/StabilityFuzzTest.cpp.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$PHYSIM_ROOT_DIR"
seconds="${1:-60}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(physim_jobs)"
targets=(collide world)
pids=()
for target in "${targets[@]}"; do
  corpus="build/fuzz/corpus-$target"
  mkdir -p "$corpus"
  physim_log "fuzz_$target: ${seconds} s (log: build/fuzz/fuzz_$target.log)"
  (cd build/fuzz && exec "tests/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=2048 -print_final_stats=1 \
    "../../$corpus" >"fuzz_$target.log" 2>&1) &
  pids+=($!)
done
failed=0
for i in "${!targets[@]}"; do
  log="build/fuzz/fuzz_${targets[$i]}.log"
  if wait "${pids[$i]}"; then
    physim_log "fuzz_${targets[$i]}: no crash, no sanitizer report ($(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?') inputs)"
  else
    failed=1
    physim_log "fuzz_${targets[$i]} FAILED; the end of its log:"
    tail -n 60 "$log" >&2
  fi
done
physim_log "core tests, built by clang with ASan + UBSan"
# Less the three long physics sweeps (two thirds of this run's time on 2 cores): the default and asan presets run
# them, and here they would only repeat the step's code paths that the other tests already take.
long_sweeps='^(Energy\.ElasticGasKeepsItsEnergy|Energy\.SpinningBulletsOffElasticWallsNeverGainEnergy|Gravitation\.TreeRunIsTheSameOnAnyThreadCount)$'
ctest --test-dir build/fuzz -L '^physim_core_tests$' -E "$long_sweeps" -j "$(physim_jobs)" --output-on-failure \
  --no-tests=error || failed=1
exit "$failed"
