#!/usr/bin/env bash
# Builds the libFuzzer targets (in the asan preset's build: clang, ASan + UBSan; build preset 'fuzz' builds only
# them) and runs each for a while.
#   scripts/fuzz.sh [SECONDS]   each target runs SECONDS (default 60); exit 1 on any crash or sanitizer report.
# The targets run side by side (one core each), so the fuzzing takes SECONDS, not twice that.
# A crashing input is left in build/asan/ (crash-*); replay it with build/asan/tests/fuzz/fuzz_<target> FILE and
# keep it as a regression case in tests/core/StabilityFuzzTest.cpp.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$PHYSIM_ROOT_DIR"
seconds="${1:-60}"
cmake --preset asan >/dev/null
cmake --build --preset fuzz -j "$(physim_jobs)"
targets=(collide world)
pids=()
for target in "${targets[@]}"; do
  corpus="build/asan/corpus-$target"
  mkdir -p "$corpus"
  physim_log "fuzz_$target: ${seconds} s (log: build/asan/fuzz_$target.log)"
  (cd build/asan && exec "tests/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=2048 -print_final_stats=1 \
    "../../$corpus" >"fuzz_$target.log" 2>&1) &
  pids+=($!)
done
failed=0
for i in "${!targets[@]}"; do
  log="build/asan/fuzz_${targets[$i]}.log"
  if wait "${pids[$i]}"; then
    physim_log "fuzz_${targets[$i]}: no crash, no sanitizer report ($(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?') inputs)"
  else
    failed=1
    physim_log "fuzz_${targets[$i]} FAILED; the end of its log:"
    tail -n 60 "$log" >&2
  fi
done
exit "$failed"
