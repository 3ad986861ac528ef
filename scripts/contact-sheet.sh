#!/usr/bin/env bash
# The giant wave's contact sheet: key frames of the bundled giant-wave shots
# rendered at 1280x720, tiled two across at half size into one PNG, to look
# at every change to the wave as a cinematographer would (docs/rendering.md
# lists what each frame shows).
#
#   scripts/contact-sheet.sh [OUT.png] [PRESET]
#   scripts/contact-sheet.sh docs/images/giant-wave-sheet.png final
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
source scripts/lib/sheet.sh
tl_build build -- tideline >/dev/null
tl_sheet "${1:-docs/images/giant-wave-sheet.png}" "${2:-final}" "contact sheet" \
  timelines/giant_wave.tl:4.2 timelines/giant_wave.tl:7.2 timelines/giant_wave.tl:8.9 \
  timelines/giant_wave.tl:10.4 timelines/giant_wave.tl:10.8 timelines/giant_wave.tl:13.5 \
  timelines/voyage.tl:5 timelines/voyage.tl:9.4
