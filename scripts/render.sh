#!/usr/bin/env bash
# The main job: set up, build, and render the default ocean headless into
# out/ (a PNG to look at and a linear EXR for compositing).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p out
build/tideline still -v -o out/ocean.png -o out/ocean.exr
echo "render: wrote out/ocean.png and out/ocean.exr"
