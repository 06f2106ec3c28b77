#!/usr/bin/env bash
# Whole processes, natively, on graded meshes of growing size: ruppert's CLI against Triangle's,
# 30 degrees with an area bound, nothing written (ruppert without -o prints only its summary line;
# triangle -N -E -P writes no files and prints its statistics). Paired runs alternate which goes
# first, so the machine's noise falls on both alike. Cases (area bounds chosen for the sizes named):
#   lake-0.2M, lake-2M, lake-5M     docs/examples/lake.poly
#   greenland-0.4M, greenland-4M    greenland_boundary.poly (2,559 input vertices)
#   superior-0.4M, superior-4M      superior.poly (518 input vertices, a 14-degree input angle)
# The two outlines are read from DATA_DIR (default /work/shared/data); a case whose file is missing
# is skipped with a note. Inputs are copied to a temporary folder (Triangle writes next to them).
# Prints per case both triangle counts, the median CPU time (user + system: on a shared machine
# less disturbed by other loads than wall time, and both are single-threaded), the median wall
# time and the median peak resident memory (GNU time's %U+%S, %e and %M) of each, and ruppert's
# ratios to Triangle.
#
# Usage: TRIANGLE_BIN=/path/to/triangle tests/bench/native-scale.sh [RUNS] [CASES...]
#   RUNS   paired runs per case (default 3); CASES default: all of the above, e.g. lake-2M
#   RUPPERT_CLI    the CLI to time (default build-native/core/ruppert)
#   RUPPERT_FLAGS  extra ruppert flags (e.g. --placement offcenter)
# Triangle is not part of this repository: without TRIANGLE_BIN (Triangle 1.6, e.g. built with
# gcc -O2) the script says so and stops.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
runs="${1:-3}"
shift || true
cases=("$@")
((${#cases[@]})) || cases=(lake-0.2M lake-2M lake-5M greenland-0.4M greenland-4M superior-0.4M superior-4M)
ruppert="${RUPPERT_CLI:-$root/build-native/core/ruppert}"
triangle="${TRIANGLE_BIN:-}"
data="${DATA_DIR:-/work/shared/data}"
read -r -a extra <<<"${RUPPERT_FLAGS:-}"
if [[ -z "$triangle" || ! -x "$triangle" ]]; then
  echo "native-scale: skipped, set TRIANGLE_BIN to a Triangle 1.6 executable"
  exit 0
fi
[[ -x "$ruppert" ]] || { echo "native-scale: no ruppert CLI at $ruppert (build-native first)"; exit 1; }
[[ -x /usr/bin/time ]] || { echo "native-scale: needs GNU time at /usr/bin/time"; exit 1; }
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT

# The input file and area bound of a case (Triangle's -a takes no exponent: plain decimals).
case_input() {
  case "$1" in
    lake-0.2M) echo "$root/docs/examples/lake.poly 0.0005" ;;
    lake-2M) echo "$root/docs/examples/lake.poly 0.00005" ;;
    lake-5M) echo "$root/docs/examples/lake.poly 0.00002" ;;
    greenland-0.4M) echo "$data/greenland_boundary.poly 0.25" ;;
    greenland-4M) echo "$data/greenland_boundary.poly 0.025" ;;
    superior-0.4M) echo "$data/superior.poly 0.0000005" ;;
    superior-4M) echo "$data/superior.poly 0.00000005" ;;
    *) echo "native-scale: unknown case $1" >&2; exit 1 ;;
  esac
}

# One timed run, its output kept in $dir/out: prints "cpu-seconds kilobytes wall-seconds".
timed() {
  /usr/bin/time -f "%U %S %M %e" -o "$dir/time.out" "$@" >"$dir/out" 2>&1
  awk '{ printf "%.2f %d %.2f\n", $1 + $2, $3, $4 }' "$dir/time.out"
}

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

run_case() {
  local name="$1" file area
  read -r file area <<<"$(case_input "$name")"
  if [[ ! -f "$file" ]]; then echo "| $name | skipped: no $file |"; return; fi
  cp "$file" "$dir/$name.poly"
  local r=("$ruppert" --min-angle 30 --max-area "$area" "${extra[@]}" "$dir/$name.poly")
  local t=("$triangle" -N -E -P "-pq30a$area" "$dir/$name.poly")
  : >"$dir/$name.r"; : >"$dir/$name.t"
  local rn tn
  for ((k = 0; k < runs; ++k)); do
    if ((k % 2 == 0)); then
      timed "${r[@]}" >>"$dir/$name.r"; rn=$(sed -n 's/.*, \([0-9]*\) triangles,.*/\1/p' "$dir/out")
      timed "${t[@]}" >>"$dir/$name.t"; tn=$(awk '/Mesh triangles:/ { print $3 }' "$dir/out")
    else
      timed "${t[@]}" >>"$dir/$name.t"; timed "${r[@]}" >>"$dir/$name.r"
    fi
  done
  local rs rm rw ts tm tw
  rs=$(cut -d' ' -f1 "$dir/$name.r" | median); rm=$(cut -d' ' -f2 "$dir/$name.r" | median)
  ts=$(cut -d' ' -f1 "$dir/$name.t" | median); tm=$(cut -d' ' -f2 "$dir/$name.t" | median)
  rw=$(cut -d' ' -f3 "$dir/$name.r" | median); tw=$(cut -d' ' -f3 "$dir/$name.t" | median)
  awk -v n="$name" -v rn="$rn" -v tn="$tn" -v rs="$rs" -v ts="$ts" -v rm="$rm" -v tm="$tm" -v rw="$rw" -v tw="$tw" 'BEGIN {
    printf "| %-14s | %9d | %9d | %6.2f s | %6.2f s | %5.2fx | %6.2f s | %6.2f s | %5.2fx | %7.1f MB | %7.1f MB | %5.2fx |\n",
      n, rn, tn, rs, ts, rs / ts, rw, tw, rw / tw, rm / 1024, tm / 1024, rm / tm
  }'
}

echo "runs per case: $runs (paired, alternating); ruppert $ruppert ${extra[*]}; triangle $triangle"
echo "| case           | ruppert triangles | Triangle triangles | ruppert CPU | Triangle CPU | CPU | ruppert wall | Triangle wall | wall | ruppert peak | Triangle peak | memory |"
echo "|----------------|-----------|-----------|----------|----------|--------|----------|----------|--------|------------|------------|--------|"
for c in "${cases[@]}"; do run_case "$c"; done
