#!/usr/bin/env bash
# The code's shape: no source file in core/, wasm/ or web/ over 600 lines, no C++ function over 80
# lines (clang-tidy's readability-function-size), and the core's includes only down its floors. Long files and functions are
# where a newcomer gets lost; the limits keep each part readable in one sitting.
# Usage: tests/run-code-shape.sh [BUILD_DIR]  (a CMake build dir with compile_commands.json; made
# here when absent). Exits non-zero, naming each file or function over its limit.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build-tidy}"
max_file_lines=600
max_function_lines=80
failures=0

cd "$root"
# Files: every tracked source file (generated output in wasm/dist is not tracked).
while IFS= read -r file; do
  lines=$(wc -l <"$file")
  if ((lines > max_file_lines)); then
    echo "code-shape: $file has $lines lines (limit $max_file_lines)"
    failures=$((failures + 1))
  fi
done < <(git ls-files 'core/*.cpp' 'core/*.h' 'wasm/*.cpp' 'wasm/*.h' 'wasm/*.js' 'wasm/*.mjs' \
  'wasm/*.ts' 'web/*.js' 'web/*.mjs' 'web/*.html' 'web/*.css')

# Option names written by hand: each option is written once in option_table.h and read
# where it is used; these two, used in one place each, stay in at most four hand-written files.
max_option_files=4
for option in sizeMeasure noSegmentSteiner; do
  mapfile -t spelled < <(git ls-files core wasm web | grep -v '^wasm/dist/' | xargs grep -lw "$option" || true)
  if ((${#spelled[@]} > max_option_files)); then
    echo "code-shape: $option is spelled in ${#spelled[@]} files (limit $max_option_files): ${spelled[*]}"
    failures=$((failures + 1))
  fi
done

# The core's includes run only down its floors, with no circles (the floors are listed there).
if ! floors="$(node "$root/tests/code-shape/include-floors.mjs")"; then
  echo "$floors"
  failures=$((failures + 1))
fi

if ! command -v clang-tidy >/dev/null 2>&1; then
  echo "code-shape: clang-tidy not found (Debian package clang-tidy)"
  exit 1
fi
if [[ ! -f "$build/compile_commands.json" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DRUPPERT_BUILD_TESTS=ON >/dev/null
fi

config="{Checks: '-*,readability-function-size', CheckOptions: [{key: readability-function-size.LineThreshold, value: $max_function_lines}]}"
tidy_log="$(mktemp)"
trap 'rm -f "$tidy_log"' EXIT
mapfile -t native < <(git ls-files 'core/*.cpp')
clang-tidy -p "$build" --quiet --config="$config" "${native[@]}" >"$tidy_log" 2>/dev/null || true
# The binding is compiled by emcc, so it is not in the native compile database: give clang-tidy
# Emscripten's headers directly.
mapfile -t binding < <(git ls-files 'wasm/*.cpp')
if ((${#binding[@]})); then
  # emcc's own flags for clang (its target, sysroot and compat headers), minus the -mllvm ones
  # that only its clang understands.
  read -r -a emflags < <(NODE_PATH=/usr/share/nodejs em++ --cflags 2>/dev/null | sed 's/-mllvm [^ ]*//g')
  clang-tidy --quiet --config="$config" "${binding[@]}" -- "${emflags[@]}" -std=c++17 \
    -I"$root/core/include" -I"$root/core/src" -I"$root/core/cli" >>"$tidy_log" 2>/dev/null || true
fi
if grep -q "readability-function-size" "$tidy_log"; then
  grep -A1 "readability-function-size" "$tidy_log" | grep -v "^--$"
  failures=$((failures + $(grep -c "readability-function-size" "$tidy_log")))
fi
if grep -q "error:" "$tidy_log"; then
  echo "code-shape: clang-tidy could not parse a file:"
  grep "error:" "$tidy_log" | head -20
  failures=$((failures + 1))
fi

echo "code-shape: $failures finding(s)"
((failures == 0))
