#!/usr/bin/env bash
# The display transforms side by side: the hero frame of giant_wave.tl
# (10.4 s) at 1280x720 through tideline's ACES fit (the default), and
# through its own OpenColorIO config's views "ACES 1.0 - SDR Video" and
# "Un-tone-mapped", tiled at half size (docs/compositing.md shows it).
#
#   scripts/display-sheet.sh [OUT.png] [TIME]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
tl_build build -- tideline >/dev/null
out=${1:-docs/images/display-views.png}
time=${2:-10.4}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
views=("" "ACES 1.0 - SDR Video" "Un-tone-mapped")
labels=("ACES fit (default)" "OpenColorIO view ACES 1.0 - SDR Video" "OpenColorIO view Un-tone-mapped")
inputs=()
for i in 0 1 2; do
  echo "display-sheet: ${labels[$i]}" >&2
  args=()
  [ -n "${views[$i]}" ] && args=(--view "${views[$i]}")
  env -u OCIO build/tideline still timelines/giant_wave.tl --time "$time" --size 1280x720 \
    "${args[@]}" -o "$work/$i.png"
  ffmpeg -loglevel error -y -i "$work/$i.png" -vf \
    "scale=640:-1,drawtext=text='${labels[$i]}':x=8:y=8:fontsize=20:fontcolor=white:box=1:boxcolor=black@0.6" \
    "$work/label_$i.png" 2>/dev/null || ffmpeg -loglevel error -y -i "$work/$i.png" \
    -vf scale=640:-1 "$work/label_$i.png"
  inputs+=(-i "$work/label_$i.png")
done
ffmpeg -loglevel error -y "${inputs[@]}" -filter_complex "[0][1][2]hstack=inputs=3" "$out"
echo "display-sheet: wrote $out" >&2
