#!/usr/bin/env bash
# The main job: set up, build, and render headless into out/:
#   - the bundled cutscene timelines/calm.tl: every frame as PNG (out/calm/)
#     and an H.264 movie (out/calm.mp4);
#   - a still of the default ocean as PNG and linear EXR (out/ocean.*).
# Extra flags go to the cutscene render, e.g. scripts/render.sh --quality draft
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p out
build/tideline still -o out/ocean.png -o out/ocean.exr
build/tideline render timelines/calm.tl -o out/calm/calm_####.png --movie out/calm.mp4 "$@"
