#!/usr/bin/env bash
# What a feature costs (a benchmark, not a test): renders the same frames of
# a timeline with a channel set to ON and to OFF (default "on" and "off";
# the environment variables ON and OFF give other values), for each
# preset, side by side in one run, and reports tideline's own ms/frame
# (render + readback + PNG write) and the ratio.
#
#   scripts/bench-toggle.sh CHANNEL [TIMELINE.tl] [WxH] [FRAMES]
#   scripts/bench-toggle.sh giant.enabled timelines/voyage.tl
#   scripts/bench-toggle.sh boat.visible timelines/giant_wave.tl 640x360 24-336:24
#   ON=0.006 OFF=0 scripts/bench-toggle.sh fog.density timelines/dusk.tl 640x360 0-143:24
set -euo pipefail
cd "$(dirname "$0")/.."
channel=${1:?usage: scripts/bench-toggle.sh CHANNEL [TIMELINE.tl] [WxH] [FRAMES]}
timeline=${2:-timelines/voyage.tl}
size=${3:-640x360}
frames=${4:-48-264:24}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# A channel is set once: drop the timeline's own line, then set it.
for state in on off; do
  value=$([ "$state" = on ] && echo "${ON:-on}" || echo "${OFF:-off}")
  grep -v "^set $channel " "$timeline" >"$scratch/$state.tl"
  echo "set $channel $value" >>"$scratch/$state.tl"
done
ms_of() {
  build/tideline render "$1" -o "$scratch/f_####.png" --frames "$frames" --size "$size" \
    --quality "$2" -q 2>&1 | sed -nE 's/.*\(([0-9]+) ms\/frame\).*/\1/p'
}
echo "| preset | $channel ${OFF:-off} (ms/frame) | ${ON:-on} (ms/frame) | ratio |"
echo "| --- | --- | --- | --- |"
for preset in draft preview final; do
  off=$(ms_of "$scratch/off.tl" "$preset")
  on=$(ms_of "$scratch/on.tl" "$preset")
  ratio=$(awk -v a="$on" -v b="$off" 'BEGIN { printf "%.2f", a / b }')
  echo "| $preset | $off | $on | $ratio |"
done
