#!/usr/bin/env bash
# The giant wave's contact sheet: key frames of the bundled giant-wave shots
# rendered at 1280x720, tiled two across at half size into one PNG, to look
# at every change to the wave as a cinematographer would (docs/rendering.md
# lists what each frame shows).
#
#   scripts/contact-sheet.sh [OUT.png] [PRESET]
#   scripts/contact-sheet.sh docs/images/giant-wave-sheet.png final
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/giant-wave-sheet.png}
preset=${2:-final}
source scripts/lib/build.sh
tl_build build -- tideline >/dev/null
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# timeline:time pairs, in the sheet's order (left to right, top to bottom).
shots=(giant_wave.tl:2 giant_wave.tl:4.2 giant_wave.tl:7.2 giant_wave.tl:8.6
       giant_wave.tl:10.3 giant_wave.tl:11 voyage.tl:5 voyage.tl:9.4)
inputs=()
for i in "${!shots[@]}"; do
  timeline=${shots[$i]%%:*} time=${shots[$i]##*:}
  echo "contact sheet: $timeline at $time s ($((i + 1)) of ${#shots[@]})"
  build/tideline still "timelines/$timeline" --time "$time" --size 1280x720 --quality "$preset" \
    -o "$scratch/$i.png"
  inputs+=(-i "$scratch/$i.png")
done
# Two across: each frame at 640x360, rows stacked.
filter="" rows=""
for ((i = 0; i < ${#shots[@]}; i += 2)); do
  filter+="[$i]scale=640:360[a$i];[$((i + 1))]scale=640:360[b$i];[a$i][b$i]hstack[r$i];"
  rows+="[r$i]"
done
filter+="${rows}vstack=inputs=$((${#shots[@]} / 2))"
ffmpeg -loglevel error -y "${inputs[@]}" -filter_complex "$filter" "$scratch/sheet.png"
mv "$scratch/sheet.png" "$out"
echo "contact sheet: $out"
