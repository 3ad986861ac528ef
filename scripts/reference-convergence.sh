#!/usr/bin/env bash
# Is `reference` converged? Renders one frame of each timeline with
# `reference` and with every reference knob doubled (64 octaves marched and
# for normals, twice the steps, half the hit and normal epsilons, twice the
# refinement steps, 128 samples per pixel), and prints the PSNR between the
# two next to the PSNR of `final` against `reference`. A converged
# reference changes less when doubled than any preset differs from it.
#
#   scripts/reference-convergence.sh [WxH] [TIMELINE.tl...]
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-320x180}
shift || true
timelines=("$@")
((${#timelines[@]})) || timelines=(timelines/calm.tl timelines/voyage.tl timelines/giant_wave.tl timelines/dive.tl)
scratch=$(mktemp -d)
doubled=()
trap 'rm -rf "$scratch" "${doubled[@]}"' EXIT
tl=build/tideline
echo "| timeline | frame | doubled vs reference (dB) | final vs reference (dB) |"
echo "| --- | ---: | ---: | ---: |"
for t in "${timelines[@]}"; do
  name=$(basename "$t" .tl)
  frames=$("$tl" check "$t" | sed -nE 's/.*= ([0-9]+) frames.*/\1/p' | head -1)
  frame=$((frames / 2))
  # The doubled timeline sits beside the original, so relative model paths hold.
  twin="$(dirname "$t")/.${name}.doubled.$$.tl"
  doubled+=("$twin")
  { grep -v '^quality ' "$t"; printf '%s\n' 'quality reference' 'set quality.march_octaves 64' \
      'set quality.normal_octaves 64' 'set quality.march_steps 2000' 'set quality.hit_epsilon 0.00005' \
      'set quality.normal_epsilon 0.001' 'set quality.refine_steps 8' 'set quality.spp 128'; } >"$twin"
  "$tl" still "$t" --frame "$frame" --size "$size" --quality reference --dither off -o "$scratch/$name.ref.png"
  "$tl" still "$twin" --frame "$frame" --size "$size" --dither off -o "$scratch/$name.ref2.png"
  "$tl" still "$t" --frame "$frame" --size "$size" --quality final --dither off -o "$scratch/$name.final.png"
  d=$("$tl" compare "$scratch/$name.ref.png" "$scratch/$name.ref2.png" | awk '{ print $2 }')
  f=$("$tl" compare "$scratch/$name.ref.png" "$scratch/$name.final.png" | awk '{ print $2 }')
  echo "| $name | $frame | $d | $f |"
done
