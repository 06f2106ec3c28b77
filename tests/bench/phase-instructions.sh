#!/usr/bin/env bash
# Instructions per phase, ruppert's core against Triangle's, natively under callgrind:
# one PLC per shape family (seed 1 unless --seed S), a quality bound of ANGLE degrees.
#
#   build-native/tests/write_shape_families /tmp/families
#   TRIANGLE_BIN=/path/to/triangle bash tests/bench/phase-instructions.sh /tmp/families [ANGLE] [--seed S]
#
# ruppert: the CLI (build-native/core/ruppert, or RUPPERT_CLI), phases as the inclusive instruction
# counts of prepareInput, buildDelaunay, insertSegments (+ insertHull), findDomain + classifyTriangles
# + removeOutside, refine and assembleOutput; "core" is all of triangulate(). RUPPERT_ARGS adds
# options to ruppert's runs (e.g. RUPPERT_ARGS="--placement offcenter", the kind of point
# Triangle places). Triangle (1.6, -pzQq):
# delaunay, formskeleton, carveholes and enforcequality; "core" is their sum (reading and writing
# files left out on both sides). Instruction counts do not depend on the machine's load.
set -euo pipefail
dir=${1:?usage: phase-instructions.sh DIR [ANGLE] [--seed S]}
angle=${2:-30}
seed=1
if [[ "${3:-}" == "--seed" ]]; then seed=${4:?}; fi
here=$(cd "$(dirname "$0")/../.." && pwd)
cli=${RUPPERT_CLI:-$here/build-native/core/ruppert}
triangle=${TRIANGLE_BIN:?set TRIANGLE_BIN to a Triangle 1.6 binary}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# inclusive FUNCTION... : the summed inclusive counts of the functions whose names end so (each once).
inclusive() {
  local file=$1; shift
  callgrind_annotate --inclusive=yes --threshold=100 "$file" 2>/dev/null | awk -v names="$*" '
    BEGIN { n = split(names, want, " ") }
    /^ *[0-9,]+ / {
      count = $1; gsub(",", "", count)
      line = $0; sub(/ \[[^]]*\]$/, "", line)
      for (i = 1; i <= n; i++) {
        pattern = "[:?]" want[i] "(\\(|$)"
        if (line ~ pattern && !(want[i] in seen)) { seen[want[i]] = 1; sum += count }
      }
    }
    END { printf "%d", sum }'
}

k() { awk -v x="$1" 'BEGIN { printf "%.0f", x / 1000 }'; }

echo "Instructions (thousands) per phase at $angle degrees, seed $seed of each family; ruppert / Triangle."
echo
echo "| PLC | triangles r / t | r prepare | r build | r constrain | r classify | r refine | r output | r core | t delaunay | t segments | t holes | t refine | t core | core r/t | per triangle r / t |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
declare -a total=(0 0 0 0 0 0 0 0 0 0 0 0 0 0)
for plc in "$dir"/*-"$seed".poly; do
  name=$(basename "$plc" .poly)
  cp "$plc" "$work/in.poly"
  # shellcheck disable=SC2086  # RUPPERT_ARGS is a list of words
  valgrind --tool=callgrind --callgrind-out-file="$work/r.out" "$cli" --quiet --min-angle "$angle" ${RUPPERT_ARGS:-} -o "$work/r" "$plc" >/dev/null 2>&1
  valgrind --tool=callgrind --callgrind-out-file="$work/t.out" "$triangle" "-pzQq$angle" "$work/in.poly" >/dev/null 2>&1
  rt=$(head -1 "$work/r.ele" | awk '{print $1}')
  tt=$(head -1 "$work/in.1.ele" | awk '{print $1}')
  rp=$(inclusive "$work/r.out" "ruppert::detail::prepareInput")
  rb=$(inclusive "$work/r.out" "ruppert::detail::buildDelaunay")
  rc=$(inclusive "$work/r.out" "ruppert::detail::insertSegments" "ruppert::detail::insertHull")
  rk=$(inclusive "$work/r.out" "ruppert::detail::findDomain" "ruppert::detail::classifyTriangles" "ruppert::detail::removeOutside")
  rr=$(inclusive "$work/r.out" "ruppert::detail::refine")
  ro=$(inclusive "$work/r.out" "ruppert::detail::assembleOutput")
  rall=$(inclusive "$work/r.out" "ruppert::triangulate")
  td=$(inclusive "$work/t.out" "delaunay")
  ts=$(inclusive "$work/t.out" "formskeleton")
  th=$(inclusive "$work/t.out" "carveholes")
  te=$(inclusive "$work/t.out" "enforcequality")
  tall=$((td + ts + th + te))
  ratio=$(awk -v a="$rall" -v b="$tall" 'BEGIN { printf "%.2f", a / b }')
  per=$(awk -v a="$rall" -v b="$rt" -v c="$tall" -v d="$tt" 'BEGIN { printf "%.1f / %.1f k", a / b / 1000, c / d / 1000 }')
  i=0
  for v in $rt $tt $rp $rb $rc $rk $rr $ro $rall $td $ts $th $te $tall; do total[i]=$((total[i] + v)); i=$((i + 1)); done
  echo "| $name | $rt / $tt | $(k $rp) | $(k $rb) | $(k $rc) | $(k $rk) | $(k $rr) | $(k $ro) | $(k $rall) | $(k $td) | $(k $ts) | $(k $th) | $(k $te) | $(k $tall) | $ratio | $per |"
done
t=("${total[@]}")
echo "| all | ${t[0]} / ${t[1]} | $(k ${t[2]}) | $(k ${t[3]}) | $(k ${t[4]}) | $(k ${t[5]}) | $(k ${t[6]}) | $(k ${t[7]}) | $(k ${t[8]}) | $(k ${t[9]}) | $(k ${t[10]}) | $(k ${t[11]}) | $(k ${t[12]}) | $(k ${t[13]}) | $(awk -v a="${t[8]}" -v b="${t[13]}" 'BEGIN { printf "%.2f", a / b }') | $(awk -v a="${t[8]}" -v b="${t[0]}" -v c="${t[13]}" -v d="${t[1]}" 'BEGIN { printf "%.1f / %.1f k", a / b / 1000, c / d / 1000 }') |"
