#!/usr/bin/env bash
# Frames per second of a timeline for each quality preset (a benchmark, not
# a test): renders every 24th frame at the given size to a scratch folder
# and reports tideline's own ms/frame (render + readback + file write).
#
#   scripts/bench-presets.sh [TIMELINE.tl] [WxH]
set -euo pipefail
cd "$(dirname "$0")/.."
timeline=${1:-timelines/calm.tl}
size=${2:-640x360}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
echo "| preset | ms per frame | frames per second |"
echo "| --- | --- | --- |"
for preset in draft preview final reference seed; do
  line=$(build/tideline render "$timeline" -o "$scratch/${preset}_####.png" --frames 0-239:24 \
           --size "$size" --quality "$preset" -q 2>&1 | grep 'ms/frame')
  ms=$(sed -E 's/.*\(([0-9]+) ms\/frame\).*/\1/' <<<"$line")
  fps=$(awk -v ms="$ms" 'BEGIN { printf "%.2f", 1000 / ms }')
  echo "| $preset | $ms | $fps |"
done
