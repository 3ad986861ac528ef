#!/usr/bin/env bash
# Progress on a terminal (a pseudo-terminal from script(1)). still: the
# line appears, its share only rises and ends at 100%, and the frame is
# the same as one rendered without a terminal, which prints no progress at
# all. bench: each `reference` frame shows its share drawn, rising.
set -euo pipefail
tideline=$1
timelines=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# A line only for a frame slower than a second, and at most two a second,
# would make this test depend on the machine's speed (a GPU draws these
# frames in milliseconds): with no delay every draw's share is shown.
export TIDELINE_PROGRESS_DELAY=0

args=("$timelines/calm.tl" --frame 120 --size 48x27 --quality reference)
"$tideline" still "${args[@]}" -o "$work/plain.png" 2>"$work/plain.err"
[ ! -s "$work/plain.err" ] || fail "progress without a terminal: $(cat "$work/plain.err")"

printf -v cmd '%q ' "$tideline" still "${args[@]}" -o "$work/tty.png"
script -qec "$cmd" /dev/null | tr '\r' '\n' >"$work/tty.out"
cat "$work/tty.out"
shares=$(sed -nE 's/^tideline still: +([0-9]+)% drawn, ETA .*/\1/p' "$work/tty.out")
[ -n "$shares" ] || fail "no progress line on a terminal"
[ "$(tail -n1 <<<"$shares")" = 100 ] || fail "the last share is not 100%: $shares"
[ "$(wc -l <<<"$shares")" -ge 2 ] || fail "one progress line only: $shares"
sort -n -c <<<"$shares" || fail "the share went down: $shares"
"$tideline" compare "$work/plain.png" "$work/tty.png" | grep -q 'max 0.0 levels' ||
  fail "the frame differs with the progress line: $("$tideline" compare "$work/plain.png" "$work/tty.png")"

printf -v cmd '%q ' "$tideline" bench "$timelines/calm.tl" --size 32x18 --frames 0,120 \
  --presets draft --repeat 1
script -qec "$cmd" /dev/null | tr '\r' '\n' >"$work/bench.out"
for frame in 0 120; do
  shares=$(sed -nE "s/^bench: reference calm.tl frame $frame \([12]\/2\) +([0-9]+)% .*/\1/p" "$work/bench.out")
  [ -n "$shares" ] || fail "bench: no share for reference frame $frame: $(cat "$work/bench.out")"
  sort -n -c <<<"$shares" || fail "bench: frame $frame's share went down: $shares"
done
grep -q '^| draft' "$work/bench.out" || fail "bench: no table"
echo "PROGRESS_OK"
