#!/usr/bin/env bash
# The under-water contact sheet: the dive's key moments and the shots in
# scripts/dive-shots/, rendered at 1280x720 and tiled two across at half
# size into one PNG, to look at every change under the water as a
# cinematographer would (docs/rendering.md, "Under water", says what each
# shows).
#
#   scripts/dive-sheet.sh [OUT.png] [PRESET]
#   scripts/dive-sheet.sh docs/images/dive-sheet.png final
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
source scripts/lib/sheet.sh
tl_build build -- tideline >/dev/null
tl_sheet "${1:-docs/images/dive-sheet.png}" "${2:-final}" "dive sheet" \
  timelines/dive.tl:1 timelines/dive.tl:3 \
  timelines/dive.tl:6.5 timelines/dive.tl:9.5 \
  timelines/dive.tl:12 timelines/dive.tl:4.5 \
  scripts/dive-shots/deep.tl:1 scripts/dive-shots/dusk.tl:1
