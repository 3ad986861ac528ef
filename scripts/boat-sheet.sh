#!/usr/bin/env bash
# The boat's contact sheet: the shots in scripts/boat-shots/ and the dive's
# look up at the hull, rendered at 1280x720 and tiled two across at half
# size into one PNG, to look at every change to the boat as a
# cinematographer would (docs/rendering.md, "The boat", says what each
# shows).
#
#   scripts/boat-sheet.sh [OUT.png] [PRESET]
#   scripts/boat-sheet.sh docs/images/boat-sheet.png final
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/boat-sheet.png}
preset=${2:-final}
source scripts/lib/build.sh
tl_build build -- tideline >/dev/null
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# timeline:time pairs, in the sheet's order (left to right, top to bottom).
shots=(scripts/boat-shots/side.tl:1 scripts/boat-shots/bow_wave.tl:2
       scripts/boat-shots/shadows.tl:1 scripts/boat-shots/wake.tl:8.33
       timelines/dive.tl:6.25 scripts/boat-shots/lights.tl:1)
inputs=()
for i in "${!shots[@]}"; do
  timeline=${shots[$i]%%:*} time=${shots[$i]##*:}
  echo "boat sheet: $timeline at $time s ($((i + 1)) of ${#shots[@]})"
  build/tideline still "$timeline" --time "$time" --size 1280x720 --quality "$preset" \
    -o "$scratch/$i.png"
  inputs+=(-i "$scratch/$i.png")
done
filter="" rows=""
for ((i = 0; i < ${#shots[@]}; i += 2)); do
  filter+="[$i]scale=640:360[a$i];[$((i + 1))]scale=640:360[b$i];[a$i][b$i]hstack[r$i];"
  rows+="[r$i]"
done
filter+="${rows}vstack=inputs=$((${#shots[@]} / 2))"
ffmpeg -loglevel error -y "${inputs[@]}" -filter_complex "$filter" "$scratch/sheet.png"
mv "$scratch/sheet.png" "$out"
echo "boat sheet: $out"
