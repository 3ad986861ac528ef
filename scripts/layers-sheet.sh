#!/usr/bin/env bash
# The light layers' contact sheet: the hero frame of giant_wave.tl (the
# boat on the wave's face, 10.4 s) rendered at 1280x720 with every light
# layer, each a tile at half size, three across (docs/compositing.md shows
# it): Combined, then each layer, all at the frame's exposure through the
# same soft curve x / (1 + x) and sRGB (no layer clips, and tiles compare:
# the layers add up to Combined before the curve). Needs oiiotool
# (openimageio-tools), ffmpeg and python3.
#
#   scripts/layers-sheet.sh [OUT.png] [TIME]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
source scripts/lib/sheet.sh
tl_build build -- tideline >/dev/null
out=${1:-docs/images/light-layers.png}
time=${2:-10.4}
for tool in oiiotool ffmpeg python3; do
  command -v $tool >/dev/null || { echo "layers-sheet: needs $tool (scripts/setup.sh)" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
w=1280
h=720
tl=timelines/giant_wave.tl
echo "layers-sheet: rendering $tl at ${time} s, ${w}x$h, every light layer" >&2
build/tideline still $tl --time "$time" --size ${w}x$h --spp 4 \
  --passes lights -o "$work/frame.exr"
# The display's exposure: render.exposure times 2^-render.ev at that time.
gain=$(build/tideline eval $tl --at "${time}s" --json | python3 -c \
  'import json,sys; c=json.load(sys.stdin)["samples"][0]["channels"]; print(c["render.exposure"] * 2 ** -c["render.ev"])')
half=(--resize $((w / 2))x$((h / 2)))
tone=(--mulc "$gain" --dup --addc 1 --div --colorconvert linear sRGB "${half[@]}" -d uint8)
oiiotool "$work/frame.exr" --ch ViewLayer.Combined.R,ViewLayer.Combined.G,ViewLayer.Combined.B \
  --chnames R,G,B "${tone[@]}" -o "$work/Combined.png"
names=(Combined)
for layer in sky reflection body glitter foam spray boat glare; do
  oiiotool "$work/frame.exr" --ch ViewLayer.light_$layer.R,ViewLayer.light_$layer.G,ViewLayer.light_$layer.B \
    --chnames R,G,B "${tone[@]}" -o "$work/light_$layer.png"
  names+=(light_$layer)
done
tl_grid "$out" 3 "$work" "${names[@]}"
echo "layers-sheet: wrote $out" >&2
