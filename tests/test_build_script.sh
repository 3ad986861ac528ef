#!/usr/bin/env bash
# scripts/lib/build.sh, which every script builds through: a compile error
# fails it (and so setup.sh, test.sh and CI) with the compiler's message,
# a warning fails it under TIDELINE_WERROR=ON (what scripts/test.sh sets),
# and a clean project builds.
#   test_build_script.sh SOURCE_DIR
set -uo pipefail
source "$1/scripts/lib/build.sh"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
cd "$dir"
cat >CMakeLists.txt <<'CMAKE'
cmake_minimum_required(VERSION 3.18)
project(probe C)
option(TIDELINE_WERROR "" OFF)
add_compile_options(-Wall -Wextra)
if(TIDELINE_WERROR)
  add_compile_options(-Werror)
endif()
add_executable(probe probe.c)
CMAKE

echo 'int main(void) { return }' >probe.c
out=$(unset TIDELINE_WERROR; tl_build b 2>&1) && fail "a syntax error built: $out"
grep -q "error:" <<<"$out" || fail "no compiler message: $out"

echo 'int main(void) { int unused; return 0; }' >probe.c
out=$(TIDELINE_WERROR=OFF tl_build b 2>&1) || fail "a warning failed without -Werror: $out"
out=$(TIDELINE_WERROR=ON tl_build b 2>&1) && fail "a warning built under TIDELINE_WERROR=ON: $out"
grep -q "unused" <<<"$out" || fail "no warning shown: $out"

echo 'int main(void) { return 0; }' >probe.c
out=$(TIDELINE_WERROR=ON tl_build b 2>&1) || fail "a clean file failed: $out"
[ -x b/probe ] || fail "no program built"
echo "build script: errors and warnings fail, a clean build passes"
