#!/usr/bin/env bash
# Core tests under AddressSanitizer + UndefinedBehaviorSanitizer.
#
# Configures its own build directory (build-sanitize) with -DRUPPERT_SANITIZE=ON, builds the test
# binary (and the CLI it runs), then runs ctest. Any sanitizer report aborts the test that caused it
# (the top CMakeLists compiles with -fno-sanitize-recover=all and we set halt_on_error), so a report
# is a failing test, and the script exits non-zero.
#
# Usage: tests/run-sanitize.sh            (compiler: $CXX, else g++)
#        CXX=clang++ tests/run-sanitize.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-sanitize"
cxx="${CXX:-g++}"

# RelWithDebInfo: optimized enough that refinement tests finish, with line numbers in reports.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRUPPERT_SANITIZE=ON -DRUPPERT_BUILD_TESTS=ON \
  -DCMAKE_CXX_COMPILER="$cxx"
cmake --build "$build" -j2 --target ruppert_tests ruppert

# detect_leaks: a leak is a bug too. abort_on_error gives a core-dump-style failure ctest reports.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

start=$(date +%s)
status=0
(cd "$build" && ctest --output-on-failure -j2) || status=$?
echo "run-sanitize: ctest under ASan+UBSan ($cxx) took $(( $(date +%s) - start )) s, status $status"
exit "$status"
