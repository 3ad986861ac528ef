#!/usr/bin/env bash
# The main job: set up, build, and render the bundled cutscene headless into
# out/: every frame as PNG (out/calm/) and an H.264 movie (out/calm.mp4).
# Re-running resumes nothing and replaces the frames atomically; pass extra
# flags through, e.g. scripts/render.sh --quality draft.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/tideline render timelines/calm.tl -o out/calm/calm_####.png --movie out/calm.mp4 "$@"
