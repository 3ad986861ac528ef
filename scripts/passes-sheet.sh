#!/usr/bin/env bash
# The compositing passes' contact sheet: the hero frame of giant_wave.tl
# (the boat on the wave's face, 10.4 s) rendered at 1280x720 with every
# pass it tiles (the light layers: scripts/layers-sheet.sh), each layer a tile at half size, four across (docs/compositing.md
# shows it). Needs oiiotool (openimageio-tools) and ffmpeg; the
# Cryptomatte's tile is Blender's own view of it (its Cryptomatte node's
# Pick output), so it needs blender too.
#
#   scripts/passes-sheet.sh [OUT.png] [TIME]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
source scripts/lib/sheet.sh
tl_build build -- tideline >/dev/null
out=${1:-docs/images/passes-sheet.png}
time=${2:-10.4}
for tool in oiiotool ffmpeg blender; do
  command -v $tool >/dev/null || { echo "passes-sheet: needs $tool (scripts/setup.sh)" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
w=1280
h=720
echo "passes-sheet: rendering giant_wave.tl at ${time} s, ${w}x$h, the passes it tiles" >&2
build/tideline still timelines/giant_wave.tl --time "$time" --size ${w}x$h --spp 4 \
  --passes normal,position,depth,masks,cryptomatte -o "$work/frame.exr" -o "$work/display.png"
f="$work/frame.exr"
L=ViewLayer
half=(--resize $((w / 2))x$((h / 2)))
tile() { # name, then oiiotool's steps from the frame to an RGB image
  local name=$1
  shift
  oiiotool "$f" "$@" "${half[@]}" -d uint8 -o "$work/$name.png"
}
gray() { # a one-channel layer as grey
  echo --ch "$1" --chnames Y --ch Y,Y,Y --chnames R,G,B
}
# Combined: the frame's display image (its exposure and tonemap), beside
# which the layers are read.
oiiotool "$work/display.png" "${half[@]}" -o "$work/combined.png"
# Normal: x, y, z from -1..1 as red, green, blue.
tile normal --ch $L.Normal.X,$L.Normal.Y,$L.Normal.Z --chnames R,G,B --mulc 0.5 --addc 0.5
# Position: camera-relative x, y, z within 50 m as red, green, blue.
tile position --ch $L.Position.X,$L.Position.Y,$L.Position.Z --chnames R,G,B \
  --divc 100 --addc 0.5 --clamp:min=0:max=1
# Depth: near bright, 400 m and beyond black.
tile depth $(gray $L.Depth.Z) --divc 400 --clamp:min=0:max=1 --invert --powc 2
for m in water foam giant boat sky underwater; do
  tile mask_$m $(gray $L.mask_$m.X)
done
blender -b --factory-startup --python scripts/lib/blender_pick.py -- "$f" "$work/pick.png" $w $h \
  >"$work/blender.log" 2>&1 || { tail -5 "$work/blender.log" >&2; exit 1; }
oiiotool "$work/pick.png" "${half[@]}" -o "$work/cryptomatte.png"
# Rank 1's coverage: the second object of each pixel (the edges).
tile rank1 $(gray $L.CryptoObject00.a) --mulc 2 --clamp:max=1
names=(combined normal position depth mask_water mask_foam mask_giant mask_boat mask_sky
  mask_underwater cryptomatte rank1)
tl_grid "$out" 4 "$work" "${names[@]}"
echo "passes-sheet: wrote $out" >&2
