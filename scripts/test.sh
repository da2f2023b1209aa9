#!/usr/bin/env bash
# Sets up dependencies if needed, then configures, builds and runs the whole test suite with ctest.
#   scripts/test.sh                 the 'default' preset (release with debug info)
#   scripts/test.sh asan cuda ...   the named presets, one after the other
# The default preset also runs the long stability cases (ctest preset stability-long, docs/stability.md);
# 'fuzz' runs scripts/fuzz.sh (the libFuzzer targets of the asan build, 60 s each) instead of a ctest preset.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PHYSIM_ROOT_DIR/scripts/setup.sh"
cd "$PHYSIM_ROOT_DIR"

presets=("$@")
[ ${#presets[@]} -gt 0 ] || presets=(default)
for preset in "${presets[@]}"; do
  if [ "$preset" = fuzz ]; then
    "$PHYSIM_ROOT_DIR/scripts/fuzz.sh" 60
    continue
  fi
  physim_log "preset '$preset': configure, build, test"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$(physim_jobs)"
  ctest --preset "$preset" -j "$(physim_jobs)"
  if [ "$preset" = default ]; then ctest --preset stability-long -j "$(physim_jobs)"; fi
  # ctest shows a skipped test's name only; say why (each skip message starts "needs ...").
  log="build/$preset/Testing/Temporary/LastTest.log"
  if [ -f "$log" ] && grep -q "^needs " "$log"; then
    physim_log "preset '$preset': skipped tests, and why: $(grep "^needs " "$log" | sort -u | tr '\n' ' ')"
  fi
done
