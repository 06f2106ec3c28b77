#!/usr/bin/env bash
# The whole CI: install what is needed, then run every test suite.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash .ci/setup.sh

# Debian's emcc needs Debian's JavaScript modules (acorn) on NODE_PATH.
export NODE_PATH="${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs"

if [[ -f package.json ]] && node -e 'process.exit(require("./package.json").scripts?.test ? 0 : 1)'; then
  npm test
else
  bash tests/run-native.sh
fi

# The code's shape: no source file over 600 lines, no C++ function over 80 (clang-tidy).
bash tests/run-code-shape.sh

# Hostile input: the core tests again under AddressSanitizer + UBSan, then each libFuzzer
# target for 60 s (any crash, sanitizer report, hang or runaway memory fails the run).
bash tests/run-sanitize.sh
bash tests/run-fuzz.sh 60
