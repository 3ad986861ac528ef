#!/usr/bin/env bash
# The main job: set up, build, and render headless into out/:
#   - the hero cutscene timelines/giant_wave.tl (15 s, 360 frames) at
#     854x480: every frame as PNG (out/giant_wave/) and an H.264 movie
#     (out/giant_wave.mp4), a few minutes on 2 cores without a GPU
#     (the README has the measured time);
#   - a still of the default ocean as PNG and linear EXR (out/ocean.*).
# Extra flags go to the cutscene render and win over the defaults here, e.g.
# scripts/render.sh --size 1280x720 (the timeline's full size) or
# scripts/render.sh --quality draft
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p out
echo "render: a still of the default ocean -> out/ocean.png, out/ocean.exr"
build/tideline still -o out/ocean.png -o out/ocean.exr
echo "render: timelines/giant_wave.tl -> out/giant_wave/ (PNG frames) and out/giant_wave.mp4"
build/tideline render timelines/giant_wave.tl -o out/giant_wave/giant_wave_####.png \
  --movie out/giant_wave.mp4 --size 854x480 "$@"
