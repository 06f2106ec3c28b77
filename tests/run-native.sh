#!/usr/bin/env bash
# Native build and tests: configure + build (Release, the test suite turned on) into build-native, run ctest, then run the CLI
# on every real PLC of the shared data folder when it is present. Exits non-zero on any failure.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-native"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DRUPPERT_BUILD_TESTS=ON
cmake --build "$build" -j2
# Keep going when ctest fails: the CLI run below may tell more; the exit status reports both.
ctest_status=0
(cd "$build" && ctest --output-on-failure -j2) || ctest_status=$?

data=""
for candidate in /work/shared/data "$root/../shared/data"; do
  if [[ -d "$candidate" ]]; then data="$candidate"; break; fi
done
if [[ -z "$data" ]]; then
  echo "run-native: shared data folder not found (/work/shared/data or ../shared/data): skipping the CLI run"
  exit "$ctest_status"
fi

cli="$build/core/ruppert"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
failures=0
checked=0

# Clean PLCs: the CLI must succeed.
for file in "$data"/*.poly; do
  [[ -e "$file" ]] || continue
  name="$(basename "$file" .poly)"
  checked=$((checked + 1))
  status=0
  "$cli" --min-angle 0 -o "$out/$name" "$file" >"$out/$name.log" 2>&1 || status=$?
  if [[ $status -ne 0 ]]; then
    echo "FAIL: ruppert --min-angle 0 $file exited with status $status"
    sed 's/^/    /' "$out/$name.log" | head -20
    failures=$((failures + 1))
  fi
done

# Crossing PLCs: repaired (status 0) or rejected (status 1) with an "error:" line; never a crash.
for file in "$data"/crossing/*.poly; do
  [[ -e "$file" ]] || continue
  name="crossing-$(basename "$file" .poly)"
  checked=$((checked + 1))
  status=0
  "$cli" --min-angle 0 -o "$out/$name" "$file" >"$out/$name.log" 2>&1 || status=$?
  if [[ $status -eq 0 ]]; then
    continue
  elif [[ $status -eq 1 ]] && grep -q "error:" "$out/$name.log"; then
    continue
  fi
  echo "FAIL: ruppert --min-angle 0 $file exited with status $status (expected 0, or 1 with an error: line)"
  sed 's/^/    /' "$out/$name.log" | head -20
  failures=$((failures + 1))
done

echo "run-native: CLI ran on $checked shared PLCs, $failures failure(s)"
if [[ $ctest_status -ne 0 ]]; then echo "run-native: ctest failed (status $ctest_status)"; fi
[[ $failures -eq 0 && $ctest_status -eq 0 ]]
