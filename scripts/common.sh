# Shared by the scripts in this folder: where dependencies live and how to run privileged commands.
# Sourced, not executed.

PHYSIM_ROOT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# Dependencies that are not Debian packages (the ROOT wheel) live outside the build tree and are reused.
PHYSIM_DEPS_DIR="${PHYSIM_DEPS_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/physim}"
PHYSIM_ROOT_VENV="$PHYSIM_DEPS_DIR/root-venv"
PHYSIM_ROOT_WHEEL_VERSION="${PHYSIM_ROOT_WHEEL_VERSION:-0.1a12}"
PHYSIM_DASK_VERSION="${PHYSIM_DASK_VERSION:-2026.8.0}"

physim_log() { printf '[physim] %s\n' "$*" >&2; }

physim_sudo() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# The directory holding ROOTConfig.cmake inside the venv (python version independent).
physim_root_cmake_dir() {
  local d
  for d in "$PHYSIM_ROOT_VENV"/lib/python3*/site-packages/ROOT/cmake; do
    [ -f "$d/ROOTConfig.cmake" ] && { echo "$d"; return 0; }
  done
  return 1
}

physim_jobs() { nproc 2>/dev/null || echo 2; }
