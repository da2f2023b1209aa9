#!/usr/bin/env bash
# Times two revisions of the core against each other in one process (docs/performance.md, "scripts/ab.sh"):
# the ratio holds where separate runs of each drift by tens of percent.
#   scripts/ab.sh REV_A [REV_B] [-- ab_bench options]     e.g. scripts/ab.sh HEAD~1 -- --scenes pyramid40 --rounds 6
# REV_B defaults to the working tree ("work"). Each revision's core is built (build/ab/) twice, with its namespace
# renamed to physim_a and to physim_b, and two programs (bench/ab/AbBench.cpp) link them both ways round: where a
# copy of the code lands in a program moves its time by a few percent, so the ratio reported is the geometric mean
# of the two programs'. The scenes and the engine adapter are the working tree's (bench/peers), built against each
# revision's headers, so both revisions must have the working tree's public API.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cd "$PHYSIM_ROOT_DIR"

[ $# -ge 1 ] || { echo "usage: scripts/ab.sh REV_A [REV_B] [-- ab_bench options]" >&2; exit 2; }
rev_a=$1; shift
rev_b=work
if [ $# -ge 1 ] && [ "$1" != "--" ]; then rev_b=$1; shift; fi
[ $# -ge 1 ] && [ "$1" = "--" ] && shift

"$PHYSIM_ROOT_DIR/scripts/setup.sh" >/dev/null
out="$PHYSIM_ROOT_DIR/build/ab"
mkdir -p "$out"
flags="-O2 -g -DNDEBUG -std=c++17 -ffp-contract=off -Wno-psabi"

# source_of SIDE REV: a directory holding REV's sources (the working tree, or an archive of the commit, extracted
# again only when the commit changes).
source_of() {
  local side=$1 rev=$2
  if [ "$rev" = work ]; then echo "$PHYSIM_ROOT_DIR"; return; fi
  local commit src="$out/src-$side"
  commit=$(git rev-parse --verify "$rev^{commit}")
  if [ "$(cat "$src.commit" 2>/dev/null)" != "$commit" ]; then
    rm -rf "$src" && mkdir -p "$src"
    git archive "$commit" | tar -x -C "$src"
    # tar gives the files the commit's time: an older commit's sources would look older than the objects built
    # from the last one, and ninja would keep those. Now is newer than every object.
    find "$src" -exec touch {} +
    echo "$commit" > "$src.commit"
  fi
  echo "$src"
}

# build SRC DIR NS: SRC's core with namespace physim renamed to physim_NS, and the engine adapter against it.
build() {
  local src=$1 dir=$2 ns=$3
  local renamed="-Dphysim=physim_$ns -DphysimEngines=physimEngines_$ns"
  # A build directory configured from another source directory starts over.
  if [ -f "$dir/CMakeCache.txt" ] && ! grep -qx "CMAKE_HOME_DIRECTORY:INTERNAL=$src" "$dir/CMakeCache.txt"; then
    rm -rf "${dir:?}"
  fi
  cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$renamed" \
    -DPHYSIM_BUILD_FRAMEWORK=OFF -DPHYSIM_BUILD_TESTS=OFF -DPHYSIM_BUILD_BENCHMARKS=OFF -DPHYSIM_TEST_INSTALL=OFF \
    >/dev/null
  cmake --build "$dir" --target physim_core -j "$(physim_jobs)" >/dev/null
  # shellcheck disable=SC2086
  g++ $flags $renamed -I"$src/include" -I"$PHYSIM_ROOT_DIR/bench/peers" $(pkg-config --cflags eigen3) \
    -c "$PHYSIM_ROOT_DIR/bench/peers/PhysimEngine.cpp" -o "$dir/PhysimEngine.o"
}

# program NAME DIR_AS_A DIR_AS_B
program() {
  # shellcheck disable=SC2086
  g++ $flags -I"$PHYSIM_ROOT_DIR/bench/peers" -I"$PHYSIM_ROOT_DIR/tests" $(pkg-config --cflags eigen3) \
    "$PHYSIM_ROOT_DIR/bench/ab/AbBench.cpp" "$PHYSIM_ROOT_DIR/bench/peers/Scenes.cpp" \
    "$2/PhysimEngine.o" "$2/src/core/libphysim_core.a" "$3/PhysimEngine.o" "$3/src/core/libphysim_core.a" \
    -ltbb -pthread -o "$out/$1"
}

src_a=$(source_of a "$rev_a")
src_b=$(source_of b "$rev_b")
physim_log "ab: A = $rev_a, B = $rev_b; building each twice"
build "$src_a" "$out/a-as-a" a
build "$src_b" "$out/b-as-b" b
build "$src_a" "$out/a-as-b" b
build "$src_b" "$out/b-as-a" a
program ab_bench "$out/a-as-a" "$out/b-as-b"
program ab_bench_swapped "$out/b-as-a" "$out/a-as-b"

physim_log "ab: A linked first"
"$out/ab_bench" "$@" | tee "$out/first.md"
physim_log "ab: B linked first"
"$out/ab_bench_swapped" --swap "$@" | tee "$out/second.md"
echo
echo "Both ways round (geometric mean of the two programs' B / A):"
echo
echo "| scene | threads | B / A |"
echo "|---|---|---|"
paste -d'|' <(grep '^| [a-z]' "$out/first.md" | grep -v '^| scene') <(grep '^| [a-z]' "$out/second.md" | grep -v '^| scene') |
  awk -F'|' '{ printf "| %s | %s | %.3f |\n", $2, $3, sqrt($6 * $14) }' | sed 's/  */ /g'
