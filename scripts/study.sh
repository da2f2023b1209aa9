#!/usr/bin/env bash
# The accuracy study in one command: every reference scene under every accuracy setting the engine has, each
# case an independent headless run, in parallel here or on a Dask cluster (docs/accuracy.md).
#   scripts/study.sh [--quick] [--jobs N] [--dask ADDRESS] [--no-plots] --out DIR
#   scripts/study.sh --replot --out DIR     redraw DIR's summary.md and plots from its runs.csv, running nothing
# Writes DIR/runs.csv, DIR/runs.root (the cases' .root files merged by hadd), DIR/summary.md and
# DIR/pareto_<scene>.png. Sets up dependencies and builds physim_study (build/default) first, unless
# PHYSIM_STUDY names an already built program (ctest does).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

bin="${PHYSIM_STUDY:-}"
if [ -z "$bin" ]; then
  "$PHYSIM_ROOT_DIR/scripts/setup.sh"
  cd "$PHYSIM_ROOT_DIR"
  # Configure only a build tree that has none: ninja configures again by itself when a CMake file changed.
  [ -f build/default/CMakeCache.txt ] || cmake --preset default >/dev/null
  cmake --build build/default --target physim_study -j "$(physim_jobs)" >/dev/null
  bin="$PHYSIM_ROOT_DIR/build/default/bin/physim_study"
  cd - >/dev/null
fi
exec "$PHYSIM_ROOT_VENV/bin/python" "$PHYSIM_ROOT_DIR/scripts/study.py" --bin "$bin" "$@"
