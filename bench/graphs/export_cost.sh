#!/usr/bin/env bash
# What --out costs: every example run headless for S simulated seconds (default 600), without and with --out,
# alternately R times (default 3); prints the median wall times and the share --out adds. The goal: at most
# 30% for every example (the graphs are thinned for drawing; all points still go to the CSV and .root files).
#   bench/graphs/export_cost.sh [build dir] [seconds] [repeats] [example ...]
set -euo pipefail
bin="${1:-build/default}/bin"
seconds="${2:-600}"
repeats="${3:-3}"
shift $(( $# < 3 ? $# : 3 ))
examples=("$@")
[ ${#examples[@]} -gt 0 ] || examples=(falling_box projectile test_scene gas pendulum rope circles incline collisions newtons_cradle pyramid)
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
wall() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); awk "BEGIN { print $t1 - $t0 }"; }
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
printf '%-16s %12s %12s %10s\n' example "run (s)" "--out (s)" "added"
for e in "${examples[@]}"; do
  plain=() with=()
  for _ in $(seq "$repeats"); do
    plain+=("$(wall "$bin/$e" --headless --quiet --seconds "$seconds")")
    with+=("$(wall "$bin/$e" --headless --quiet --seconds "$seconds" --out "$out/$e")")
  done
  p=$(median "${plain[@]}") w=$(median "${with[@]}")
  printf '%-16s %12.2f %12.2f %9.0f%%\n' "$e" "$p" "$w" "$(awk "BEGIN { print 100 * ($w - $p) / $p }")"
done
