#!/usr/bin/env bash
# Whole processes, natively: ruppert's CLI against Triangle's on the same files, in paired runs
# that alternate which goes first (the machine's noise then falls on both alike). Cases:
#   cdt-N       a CDT of N uniformly random points (no output files: ruppert --min-angle 0 --quiet,
#               triangle -Q -N -E: both read, triangulate and write nothing)
#   square-q30  the unit square at 30 degrees and max area 1e-6 (~1.6 M triangles; ruppert
#               --min-angle 30 --max-area 1e-6, triangle -pq30a0.000001 -N -E -P: Triangle's
#               switches take no exponent)
# Prints per case the median wall time and median peak resident memory (GNU time's %e and %M) of
# each, and ruppert's ratios to Triangle.
#
# Usage: TRIANGLE_BIN=/path/to/triangle tests/bench/native-cdt.sh [RUNS] [SIZES...]
#   RUNS   paired runs per case (default 5); SIZES default: 100000 1000000
#   RUPPERT_CLI  the CLI to time (default build-native/core/ruppert)
#   BENCH_DIR    where the inputs are written (default a fresh temporary folder)
# Triangle is not part of this repository: without TRIANGLE_BIN (Triangle 1.6, e.g. built with
# gcc -O2) the script says so and stops.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
runs="${1:-5}"
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(100000 1000000)
ruppert="${RUPPERT_CLI:-$root/build-native/core/ruppert}"
triangle="${TRIANGLE_BIN:-}"
if [[ -z "$triangle" || ! -x "$triangle" ]]; then
  echo "native-cdt: skipped, set TRIANGLE_BIN to a Triangle 1.6 executable"
  exit 0
fi
[[ -x "$ruppert" ]] || { echo "native-cdt: no ruppert CLI at $ruppert (build-native first)"; exit 1; }
[[ -x /usr/bin/time ]] || { echo "native-cdt: needs GNU time at /usr/bin/time"; exit 1; }
dir="${BENCH_DIR:-$(mktemp -d)}"
mkdir -p "$dir"

# n points in the unit square, Park and Miller's generator (exact in awk's doubles, so the same
# file under any awk), seed 41; 17 significant digits read back exactly.
write_points() {
  awk -v n="$1" 'BEGIN {
    s = 41; m = 2147483647; print n, 2, 0, 0
    for (i = 0; i < n; ++i) {
      s = (16807 * s) % m; x = s / m; s = (16807 * s) % m; y = s / m
      printf "%d %.17g %.17g\n", i, x, y
    }
  }' >"$2"
}

write_square() {
  printf '4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n' >"$1"
}

# One timed run: prints "seconds kilobytes".
timed() {
  /usr/bin/time -f "%e %M" -o "$dir/time.out" "$@" >/dev/null 2>&1
  cat "$dir/time.out"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# case NAME, then the ruppert and triangle command lines separated by "--".
run_case() {
  local name="$1"; shift
  local r=() t=()
  while [[ "$1" != "--" ]]; do r+=("$1"); shift; done
  shift
  t=("$@")
  : >"$dir/$name.r"; : >"$dir/$name.t"
  for ((k = 0; k < runs; ++k)); do
    if ((k % 2 == 0)); then
      timed "${r[@]}" >>"$dir/$name.r"; timed "${t[@]}" >>"$dir/$name.t"
    else
      timed "${t[@]}" >>"$dir/$name.t"; timed "${r[@]}" >>"$dir/$name.r"
    fi
  done
  local rs rm ts tm
  rs=$(cut -d' ' -f1 "$dir/$name.r" | median); rm=$(cut -d' ' -f2 "$dir/$name.r" | median)
  ts=$(cut -d' ' -f1 "$dir/$name.t" | median); tm=$(cut -d' ' -f2 "$dir/$name.t" | median)
  awk -v n="$name" -v rs="$rs" -v ts="$ts" -v rm="$rm" -v tm="$tm" 'BEGIN {
    printf "| %-12s | %7.2f s | %7.2f s | %5.2fx | %8.1f MB | %8.1f MB | %5.2fx |\n", n, rs, ts, rs / ts, rm / 1024, tm / 1024, rm / tm
  }'
}

echo "runs per case: $runs (paired, alternating); ruppert $ruppert; triangle $triangle"
echo "| case         | ruppert   | Triangle  | time  | ruppert peak | Triangle peak | memory |"
echo "|--------------|-----------|-----------|-------|--------------|---------------|--------|"
for n in "${sizes[@]}"; do
  write_points "$n" "$dir/cdt-$n.node"
  run_case "cdt-$n" "$ruppert" --min-angle 0 --quiet "$dir/cdt-$n.node" -- "$triangle" -Q -N -E "$dir/cdt-$n.node"
done
write_square "$dir/square.poly"
run_case "square-q30" "$ruppert" --min-angle 30 --max-area 1e-6 --quiet "$dir/square.poly" -- \
  "$triangle" -Q -N -E -P -pq30a0.000001 "$dir/square.poly"
