#!/usr/bin/env bash
# Builds the libFuzzer targets (the 'fuzz' preset: clang, ASan + UBSan) and runs each for a while.
#   scripts/fuzz.sh [SECONDS]   each target runs SECONDS (default 60); exit 1 on any crash or sanitizer report.
# A crashing input is left in build/fuzz/ (crash-*); replay it with build/fuzz/tests/fuzz/fuzz_<target> FILE and
# keep it as a regression case in tests/core/StabilityFuzzTest.cpp.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$PHYSIM_ROOT_DIR"
seconds="${1:-60}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(physim_jobs)"
for target in collide world; do
  corpus="build/fuzz/corpus-$target"
  mkdir -p "$corpus"
  physim_log "fuzz_$target: ${seconds} s"
  (cd build/fuzz && "tests/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=2048 -print_final_stats=1 \
    "../../$corpus")
done
