#!/usr/bin/env bash
# The library example (examples/render_frame.c) draws what `tideline still`
# draws: the hero cutscene's frame with its boat, pixel for pixel; and a
# timeline whose boat model is missing fails it as it fails the CLI, at the
# timeline's line.
#   test_example.sh RENDER_FRAME TIDELINE TIMELINES_DIR
set -euo pipefail
example=$1 tideline=$2 timelines=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

out=$("$example" "$timelines/giant_wave.tl" 100 "$dir/example.png" 160x90)
grep -qx 'frame 100 (t = 4.1667 s) -> .*example.png' <<<"$out" || fail "example said: $out"
grep -qE '^features: .*\bboat\b' <<<"$out" || fail "the example's frame has no boat: $out"
"$tideline" still "$timelines/giant_wave.tl" --frame 100 --size 160x90 -o "$dir/still.png"
same=$("$tideline" compare "$dir/example.png" "$dir/still.png")
grep -q 'max 0.0 levels' <<<"$same" || fail "the example's frame differs from still's: $same"

printf 'tideline 1\npath boat\n  0s 0 0\n  5s 0 20\nset boat.model %s/none.glb\n' "$dir" >"$dir/boat.tl"
status=0
"$example" "$dir/boat.tl" 0 "$dir/bad.png" 32x18 2>"$dir/err.txt" || status=$?
[ "$status" -eq 1 ] || fail "a missing model exits $status, not 1"
grep -q "boat.tl:5:16: error: boat model " "$dir/err.txt" || fail "message: $(cat "$dir/err.txt")"
[ ! -e "$dir/bad.png" ] || fail "a failed load left a frame"
echo EXAMPLE_OK
