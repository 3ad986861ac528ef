#!/usr/bin/env bash
# What the giant wave costs (a benchmark, not a test): renders the same
# frames of a timeline with its wave as written and with `giant.enabled
# off`, for each preset, side by side in one run, and reports tideline's own
# ms/frame (render + readback + PNG write) and the ratio.
#
#   scripts/bench-giant.sh [TIMELINE.tl] [WxH] [FRAMES]
set -euo pipefail
cd "$(dirname "$0")/.."
timeline=${1:-timelines/voyage.tl}
size=${2:-640x360}
frames=${3:-48-264:24}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# The same timeline without the wave: the last `set` of a channel wins, so
# append one (a second `set` is an error: replace any existing one).
grep -v '^set giant.enabled' "$timeline" >"$scratch/without.tl"
echo "set giant.enabled off" >>"$scratch/without.tl"
grep -v '^set giant.enabled' "$timeline" >"$scratch/with.tl"
echo "set giant.enabled on" >>"$scratch/with.tl"
ms_of() {
  build/tideline render "$1" -o "$scratch/f_####.png" --frames "$frames" --size "$size" \
    --quality "$2" -q 2>&1 | sed -nE 's/.*\(([0-9]+) ms\/frame\).*/\1/p'
}
echo "| preset | without the wave (ms/frame) | with it (ms/frame) | ratio |"
echo "| --- | --- | --- | --- |"
for preset in draft preview final; do
  off=$(ms_of "$scratch/without.tl" "$preset")
  on=$(ms_of "$scratch/with.tl" "$preset")
  ratio=$(awk -v a="$on" -v b="$off" 'BEGIN { printf "%.2f", a / b }')
  echo "| $preset | $off | $on | $ratio |"
done
