#!/usr/bin/env bash
# `cmake --install` gives a C program all it needs to link tideline without
# add_subdirectory: static libraries, headers and pkg-config files. The
# library example, built against the installed copy alone, renders a frame;
# the headless library does not link the window system (GLFW).
#   test_install.sh BUILD_DIR SOURCE_DIR [EXTRA_CFLAGS]
# EXTRA_CFLAGS: what the build's own objects were compiled with that a
# program linking them needs too (the sanitizer build's -fsanitize=...).
set -euo pipefail
build=$1 src=$2 extra=${3:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
cmake --install "$build" --prefix "$dir/prefix" >"$dir/install.log"
pc=$(echo "$dir"/prefix/lib*/pkgconfig)
[ -f "$pc/tideline.pc" ] || fail "no tideline.pc under $dir/prefix"
[ -f "$dir/prefix/include/tideline/tideline.h" ] || fail "no tideline.h installed"
[ ! -e "$dir/prefix/include/tideline/cli" ] || fail "the commands' headers were installed"
export PKG_CONFIG_PATH=$pc
flags=$(pkg-config --cflags --libs tideline)
grep -q glfw <<<"$flags" && fail "the headless library links GLFW: $flags"
grep -q glfw <<<"$(pkg-config --libs tideline-window)" || fail "tideline-window lacks GLFW"
# shellcheck disable=SC2086 # word splitting of the flags is meant
cc -std=c11 $extra -o "$dir/render_frame" "$src/examples/render_frame.c" $flags
ldd "$dir/render_frame" | grep -q libglfw && fail "the example linked GLFW"
"$dir/render_frame" "$src/timelines/calm.tl" 12 "$dir/frame.png" 32x18 >"$dir/out.txt"
grep -q "frame 12 (t = 0.5000 s)" "$dir/out.txt" || fail "the example said: $(cat "$dir/out.txt")"
[ -s "$dir/frame.png" ] || fail "no frame written"
echo "install: the example builds from the installed library and renders"
