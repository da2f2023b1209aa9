#!/usr/bin/env bash
# Sets up dependencies if needed, builds, and runs the main demo (examples/falling_box).
# With a display it opens a window; without one it runs headless and writes its results to out/demo/.
# Extra arguments go to the demo (see: scripts/demo.sh --help).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
"$PHYSIM_ROOT_DIR/scripts/setup.sh"
cd "$PHYSIM_ROOT_DIR"
cmake --preset default >/dev/null
cmake --build --preset default -j "$(physim_jobs)" --target falling_box
demo="$PHYSIM_ROOT_DIR/build/default/bin/falling_box"

if [ $# -gt 0 ]; then
  exec "$demo" "$@"
elif [ -n "${DISPLAY:-}" ]; then
  exec "$demo"
else
  physim_log "no display: running headless for 5 simulated seconds, files in out/demo/"
  "$demo" --headless --seconds 5 --out "$PHYSIM_ROOT_DIR/out/demo"
  ls -l "$PHYSIM_ROOT_DIR/out/demo"
fi
