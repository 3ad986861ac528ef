#!/usr/bin/env bash
# Do the presets' rays meet the surface `reference` meets? For each frame,
# the share of pixels (nearer than 2 km at `reference`, away from depth
# edges) whose depth at draft, preview and final lies within a factor 1.5
# of reference's; a preset pixel that sees the sky there disagrees
# (tests/wrong_surface.c says how, and why reference may take one sample).
#
#   scripts/wrong-surface.sh                  # the table: the bundled giant-wave
#                                             # shots and the low shots beside the face
#   scripts/wrong-surface.sh TIMELINE.tl FRAMES [wrong_surface options...]
#   scripts/wrong-surface.sh timelines/giant_wave.tl 180 --size 480x270 \
#       --set camera.position=9,2,60 --set camera.yaw=-170deg --set sun.elevation=2deg
#   scripts/wrong-surface.sh tests/grazing/dusk_face.tl 96 --presets draft,draft:march_steps=64
#   scripts/wrong-surface.sh tests/grazing/day_face.tl 72 --shader-dir my-shaders --dump out/
#
# SIZE (default 320x180) sets the table's size. test_wrong_surface checks
# grazing frames at 99%.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
tl_build build >/dev/null
tool=build/tests/wrong_surface
if (($#)); then
  exec "$tool" "$@"
fi
size=${SIZE:-320x180}
# Frames at 24 fps: giant_wave 100 (shot 1) and 180 (shot 2, at the foot of
# the face); voyage 6-8 s (the cut to the crane shot); the low shots beside
# the face at dusk and in daylight as the crest comes on.
"$tool" --size "$size" timelines/giant_wave.tl 100,180
"$tool" --size "$size" timelines/voyage.tl 150,180
"$tool" --size "$size" tests/grazing/dusk_face.tl 90,96,104
"$tool" --size "$size" tests/grazing/day_face.tl 0,72,96,108
