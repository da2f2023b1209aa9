#!/usr/bin/env bash
# Runs a command with an X display: the current one if it answers, else a private Xvfb (xvfb-run).
set -euo pipefail
if [ -n "${DISPLAY:-}" ] && command -v xdpyinfo >/dev/null 2>&1 && xdpyinfo >/dev/null 2>&1; then
  exec "$@"
fi
if ! command -v xvfb-run >/dev/null 2>&1; then
  echo "with-display.sh: no X display and no xvfb-run (scripts/setup.sh installs xvfb)" >&2
  exit 1
fi
# -noreset: by default an X server resets whenever its last client disconnects, and a connection attempted during
# that reset fails ("Failed to open X11 display"). Tests open and close windows one after another, so they would
# race the reset; a server that never resets has no such window.
exec xvfb-run -a -s "-screen 0 1280x720x24 -noreset" "$@"
