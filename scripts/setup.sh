#!/usr/bin/env bash
# Installs everything physim needs on a Debian machine. Idempotent: a second run only checks.
#   - Debian packages: compilers, CMake, Eigen, oneTBB, SFML (and X11), Dear ImGui, GoogleTest,
#     Google Benchmark, nlohmann-json, Xvfb, Box2D 2.4.1 (the peer engine bench/peers measures against),
#     clang with its sanitizer and libFuzzer runtimes (the asan preset), Doxygen (the `docs` target)
#   - ROOT (CERN) from its official PyPI wheel, into a virtual environment outside the build tree
#   - Dask (`dask`, `distributed` from PyPI) in the same environment: scripts/study.sh --dask runs cases on a cluster
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

APT_PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libtbb-dev libsfml-dev libx11-dev libxcb1-dev libimgui-dev libgtest-dev libgmock-dev libbenchmark-dev
  nlohmann-json3-dev libbox2d-dev xvfb xauth libgl1-mesa-dri fonts-dejavu-core
  clang libclang-rt-14-dev doxygen
  python3 python3-venv
)

install_apt_packages() {
  local missing=()
  for p in "${APT_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if ! command -v apt-get >/dev/null 2>&1; then
    physim_log "No apt-get on this system. Install these packages (or your distribution's equivalents):"
    physim_log "  ${missing[*]}"
    exit 1
  fi
  physim_log "installing Debian packages: ${missing[*]}"
  physim_sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  physim_sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

python_for_venv() {
  # Prefer the interpreter on PATH; fall back to Debian's.
  for py in python3 /usr/bin/python3; do
    if command -v "$py" >/dev/null 2>&1 && "$py" -c 'import venv, ensurepip' >/dev/null 2>&1; then
      echo "$py"; return 0
    fi
  done
  physim_log "no python3 with venv and ensurepip found"; exit 1
}

install_root_wheel() {
  if ! physim_root_cmake_dir >/dev/null; then
    physim_log "installing ROOT (PyPI wheel root==$PHYSIM_ROOT_WHEEL_VERSION) into $PHYSIM_ROOT_VENV"
    mkdir -p "$PHYSIM_DEPS_DIR"
    "$(python_for_venv)" -m venv "$PHYSIM_ROOT_VENV"
    "$PHYSIM_ROOT_VENV/bin/pip" install -q --disable-pip-version-check "root==$PHYSIM_ROOT_WHEEL_VERSION"
  fi
  # Quirk of the wheel: its CMake targets and root-config point into lib/pythonX/mock_site_packages.
  local site
  site="$(dirname "$(dirname "$(physim_root_cmake_dir)")")"
  local mock
  mock="$(dirname "$site")/mock_site_packages"
  [ -e "$mock" ] || ln -s site-packages "$mock"
}

install_dask() {
  local want="$PHYSIM_DASK_VERSION"
  if ! "$PHYSIM_ROOT_VENV/bin/python" -c "import importlib.metadata as m, sys; sys.exit(not all(m.version(p) == '$want' for p in ('dask', 'distributed')))" 2>/dev/null; then
    physim_log "installing dask and distributed $want (PyPI) into $PHYSIM_ROOT_VENV"
    "$PHYSIM_ROOT_VENV/bin/pip" install -q --disable-pip-version-check "dask==$want" "distributed==$want"
  fi
}

install_apt_packages
install_root_wheel
install_dask
physim_log "setup complete (ROOT: $(physim_root_cmake_dir))"
