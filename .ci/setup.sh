#!/usr/bin/env bash
# Installs everything the builds and tests need, from Debian's archive and the npm registry only.
# Idempotent: apt-get runs (update + install) only when a needed package or command is missing, so a
# second run on a prepared machine touches nothing but node_modules.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# Native build and core tests: cmake g++ make catch2 libgmp-dev.
# WebAssembly build and browser tests: emscripten chromium, plus Node.js and npm.
# Sanitizer and fuzz runs: clang with its runtime libraries (libFuzzer), which clang only recommends.
# The code-shape check (tests/run-code-shape.sh): clang-tidy.
# Consumers of the .msh and .vtu output (tests/core/test_consumers.cpp): python3-meshio and gmsh.
debian_packages=(cmake g++ make catch2 libgmp-dev emscripten chromium clang libclang-rt-14-dev python3-meshio gmsh clang-tidy)

missing=()
for package in "${debian_packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
# Node.js and npm are checked as commands, not packages: a machine may have Node from another
# source (NodeSource's nodejs bundles npm, and Debian's npm package would conflict with it).
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)

if ((${#missing[@]})); then
  echo "setup: installing from Debian: ${missing[*]}"
  sudo=()
  if [[ "$(id -u)" != 0 ]]; then sudo=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update
  "${sudo[@]}" apt-get install -y "${missing[@]}"
else
  echo "setup: Debian packages already installed"
fi

if [[ -f package.json ]]; then
  if [[ -f package-lock.json ]]; then
    npm ci --no-audit --no-fund
  else
    npm install --no-audit --no-fund
  fi
fi
