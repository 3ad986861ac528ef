#!/usr/bin/env bash
# cmake/check_modules.cmake, which every build runs over src/: a module
# including another's header without linking it fails, as does a link no
# code uses and a GL header outside gl/; a tree that keeps the rules passes.
#   test_module_rules.sh SOURCE_DIR
set -uo pipefail
script=$1/cmake/check_modules.cmake
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
mkdir -p "$dir/src/core" "$dir/src/waves" "$dir/src/gl"
echo 'int core(void);' >"$dir/src/core/tl_core.h"
echo 'int core(void) { return 0; }' >"$dir/src/core/tl_core.c"
echo '#include "core/tl_core.h"' >"$dir/src/waves/tl_waves.c"
echo '#include <epoxy/gl.h>' >"$dir/src/gl/tl_gl.c"
check() { # TABLE_TEXT -> the script's output; its status
  printf '%s' "$1" >"$dir/table.txt"
  cmake -DTABLE="$dir/table.txt" -DSRC="$dir/src" -DSTAMP="$dir/stamp" -P "$script" 2>&1
}
s=$dir/src
ok="core|core|||$s/core/tl_core.c
waves|waves|core||$s/waves/tl_waves.c
gl|gl|||$s/gl/tl_gl.c
"
out=$(check "$ok") || fail "a tree that keeps the rules failed: $out"
[ -f "$dir/stamp" ] || fail "no stamp written"

out=$(check "${ok/waves|waves|core|/waves|waves||}") && fail "an include without its link passed"
grep -q "src/waves/tl_waves.c: includes core/tl_core.h of tl_core, which tl_waves does not link" \
  <<<"$out" || fail "message: $out"

out=$(check "${ok/gl|gl||/gl|gl|core|}") && fail "an unused link passed"
grep -q "tl_gl links tl_core, but none of its code includes a header of tl_core" <<<"$out" ||
  fail "message: $out"

echo '#include <epoxy/gl.h>' >>"$s/waves/tl_waves.c"
out=$(check "$ok") && fail "a GL header outside gl/ passed"
grep -q "src/waves/tl_waves.c: includes <epoxy/...> outside src/gl/" <<<"$out" ||
  fail "message: $out"
echo "module rules: a missing link, an unused link and GL outside gl/ fail"
