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
source scripts/lib/build.sh
source scripts/lib/sheet.sh
tl_build build -- tideline >/dev/null
tl_sheet "${1:-docs/images/boat-sheet.png}" "${2:-final}" "boat sheet" \
  scripts/boat-shots/side.tl:1 scripts/boat-shots/bow_wave.tl:2 \
  scripts/boat-shots/shadows.tl:1 scripts/boat-shots/wake.tl:8.33 \
  timelines/dive.tl:6.25 scripts/boat-shots/lights.tl:1 \
  scripts/boat-shots/deck.tl:2 timelines/rescue.tl:11
