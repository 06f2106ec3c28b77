#!/usr/bin/env bash
# The README's native commands, run as written, and the paths and links of the documentation.
#   tests/readme/run-native-blocks.sh BUILD_DIR
# 1. Every ```sh block of README.md runs line by line with bash in a scratch folder that holds
#    links to docs/ and to BUILD_DIR as build-native (so `build-native/core/ruppert` is the binary
#    under test), with HOME in the scratch folder (so `cmake --install ... --prefix "$HOME/.local"`
#    installs there). The ```cpp block is written to out/example.cpp first, for the lines that build
#    it. Everything the commands write must land in out/ (ignored by git): the clone stays clean.
#    Lines for npm and npx are the package tests' (tests/package/readme.test.mjs); the build line
#    must be package.json's build:native script, which tests/run-native.sh has just run.
# 2. The usage block of README.md is the program's own usage line.
# 3. README.md has at most 300 lines and names at most 3 commit hashes.
# 4. Links and repository paths in README.md, CONTRIBUTING.md and docs/*.md exist (in
#    docs/measurements.md only links: its text names files as they were when it was measured).
# Exits non-zero on the first failing command or after listing every missing path.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:?usage: run-native-blocks.sh BUILD_DIR}" && pwd)"
readme="$root/README.md"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "readme: $*" >&2; exit 1; }

# Fenced blocks, numbered in order: blocks/NN.LANG ("txt" when the fence names no language).
mkdir -p "$work/blocks" "$work/run" "$work/home"
awk -v dir="$work/blocks" '
  /^```/ {
    if (open) { open = 0; close(file); next }
    lang = substr($0, 4); if (lang == "") lang = "txt"
    file = sprintf("%s/%02d.%s", dir, ++n, lang); open = 1; printf "" > file; next
  }
  open { print > file }' "$readme"

ln -s "$root/docs" "$work/run/docs"
ln -s "$build" "$work/run/build-native"
cpp_blocks=("$work"/blocks/*.cpp)
[[ ${#cpp_blocks[@]} -eq 1 && -f "${cpp_blocks[0]}" ]] || fail "expected one cpp block, found ${#cpp_blocks[@]}"
mkdir -p "$work/run/out"
cp "${cpp_blocks[0]}" "$work/run/out/example.cpp"

build_line="$(node -e 'process.stdout.write(require(process.argv[1]).scripts["build:native"])' "$root/package.json")"
ran=0
for block in "$work"/blocks/*.sh; do
  while IFS= read -r line; do
    command="${line%%#*}"                     # the README's comments are not part of the command
    command="${command%"${command##*[![:space:]]}"}"
    [[ -z "$command" ]] && continue
    case "$command" in
      npm\ * | npx\ *) continue ;;          # run by tests/package/readme.test.mjs
      cmake\ -S\ *)
        [[ "$command" == "$build_line" ]] || fail "the README's build line differs from package.json's build:native:
  README:       $command
  package.json: $build_line"
        continue ;;
    esac
    echo "readme: \$ $command"
    (cd "$work/run" && HOME="$work/home" bash -euo pipefail -c "$command") >"$work/out" 2>&1 ||
      { sed 's/^/    /' "$work/out"; fail "failed: $command"; }
    ran=$((ran + 1))
  done <"$block"
done
# What the commands must have made.
[[ $ran -ge 7 ]] || fail "only $ran commands ran: the README's blocks were not found"
for file in lake.ele lake.node lake.poly plate.vtu park.svg example; do
  [[ -s "$work/run/out/$file" ]] || fail "the README's commands did not write out/$file"
done
grep -q '^\$MeshFormat' "$work/run/out/park.msh" || fail "out/park.msh is not a Gmsh file"
# The examples leave the clone clean: everything they write is in out/, which git ignores.
stray="$(cd "$work/run" && find . -mindepth 1 -maxdepth 1 ! -name out ! -name docs ! -name build-native)"
[[ -z "$stray" ]] || fail "the README's commands wrote outside out/: $stray"
git -C "$root" check-ignore -q out/lake.ele || fail "out/ is not ignored by git (.gitignore)"
"$work/home/.local/bin/ruppert" --version | grep -q '^ruppert ' || fail "the installed ruppert does not run"
[[ -f "$work/home/.local/include/ruppert/ruppert.h" && -f "$work/home/.local/lib/libruppert_core.a" ]] ||
  fail "cmake --install did not install the header and the library"

# The usage block is the program's usage line.
usage_block="$(grep -l '^usage: ruppert' "$work"/blocks/*.txt | head -1)"
[[ -n "$usage_block" ]] || fail "no usage block in README.md"
"$build/core/ruppert" --help | sed '/^$/,$d' >"$work/usage"
diff -u "$work/usage" "$usage_block" || fail "README.md's usage block differs from ruppert --help"

# The manual stays a manual: at most 300 lines and 3 commit hashes; figures and their
# history go to docs/measurements.md.
lines=$(wc -l <"$readme")
[[ $lines -le 300 ]] || fail "README.md has $lines lines (limit 300): move details into docs/"
hashes=$({ grep -oE '\b[0-9a-f]{7,40}\b' "$readme" || true; } | { grep '[0-9]' || true; } | { grep '[a-f]' || true; } |
  sort -u | wc -l)
[[ $hashes -le 3 ]] || fail "README.md names $hashes commit hashes (limit 3): figures go to docs/measurements.md"

# Links and paths.
missing=0
slug() { tr 'A-Z' 'a-z' | sed -e 's/[^a-z0-9 _-]//g' -e 's/ /-/g'; }
check_target() {  # FILE TARGET (relative to FILE's folder, maybe with #anchor)
  local file="$1" target="$2" path anchor
  path="${target%%#*}"; anchor=""
  [[ "$target" == *#* ]] && anchor="${target#*#}"
  local full="$(dirname "$file")/$path"
  [[ -z "$path" ]] && full="$file"
  if [[ ! -e "$full" ]]; then echo "readme: ${file#$root/}: '$target' does not exist"; missing=$((missing + 1)); return; fi
  if [[ -n "$anchor" && -f "$full" ]] &&
     ! grep '^#' "$full" | sed 's/^#* *//' | slug | grep -qx -- "$anchor"; then
    echo "readme: ${file#$root/}: no heading for '#$anchor' in ${full#$root/}"; missing=$((missing + 1))
  fi
}
for file in "$root/README.md" "$root/CONTRIBUTING.md" "$root"/docs/*.md; do
  while IFS= read -r target; do
    case "$target" in http*://* | mailto:*) continue ;; esac
    check_target "$file" "$target"
  done < <(grep -o '](\([^)]*\))' "$file" | sed 's/^](\(.*\))$/\1/')
  while IFS= read -r target; do
    check_target "$file" "$target"
  done < <(grep -o 'src="[^"]*"' "$file" | sed 's/^src="\(.*\)"$/\1/' | grep -v '^http')
  [[ "$file" == */measurements.md ]] && continue
  # `core/...`, `tests/...` and the like, from the top of the repository (globs allowed).
  while IFS= read -r token; do
    path="${token%%[?#]*}"
    case "$path" in wasm/dist | wasm/dist/* | */) continue ;; esac
    compgen -G "$root/$path" >/dev/null || { echo "readme: ${file#$root/}: path '$path' does not exist"; missing=$((missing + 1)); }
  done < <(grep -o '`\(core\|wasm\|web\|tests\|docs\|\.ci\)/[^` ]*`' "$file" | tr -d '`' | sed 's/[.,:;)]*$//')
done
[[ $missing -eq 0 ]] || fail "$missing missing path(s) or anchor(s)"
echo "readme: $ran commands ran; usage block, links and paths checked"
