#!/usr/bin/env bash
# The GPU figures docs/quality.md sums up ("On a GPU"): presets against
# `reference` and against seed 002's shader at 1920x1080 on a machine with a
# GPU (a benchmark, not a test). Prints Markdown; writes the bench CSVs and
# a few frames to OUT.
#
#   scripts/bench-gpu.sh [OUT_FOLDER] [WxH]
#
# TL and SEED002 name the binaries (default build/tideline, build/seed002),
# so a copy built elsewhere can run from this checkout.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/bench-gpu}
size=${2:-1920x1080}
tl=${TL:-build/tideline}
seed002=${SEED002:-build/seed002}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$out"

# Arithmetic in awk, not bc: a GPU machine's image may lack bc.
calc() { awk "BEGIN { print $1 }"; }
ms() { sed -nE 's/.*median ([0-9.]+) ms\/frame.*/\1/p'; }
shader() {
  local a b
  a=$("$seed002" --shader bench/seed002.frag --size $size --time 10 --repeat 30 | ms)
  b=$("$seed002" --shader bench/seed002.frag --size $size --time 37 --repeat 30 | ms)
  calc "($a + $b) / 2"
}

echo "## $("$tl" still bench/seed002.tl --size 64x36 -o "$scratch/probe.png" -v 2>&1 | sed -n 's/^tideline still: EGL //p')"
echo
h1=$(shader)
for t in calm voyage; do
  { cat timelines/$t.tl; echo 'set sky.model seed'; } >"$scratch/$t.tl"
done
"$tl" bench bench/seed002.tl --size $size --frames 240,888 --repeat 10 -q \
  --presets draft,preview,final,seed --csv "$out/gpu-seed.csv" >"$scratch/seed.md"
"$tl" bench "$scratch/calm.tl" "$scratch/voyage.tl" --size $size --frames 60,180 --repeat 10 -q \
  --presets draft,preview,final,seed --csv "$out/gpu-cv.csv" >"$scratch/cv.md"
h2=$(shader)
h=$(calc "($h1 + $h2) / 2")
printf 'The shader alone (draw + RGBA8 readback): %.2f ms/frame before, %.2f after.\n\n' "$h1" "$h2"
echo "| preset | seed's scene: end to end | render | PSNR (dB) | calm + voyage (seed sky): end to end | render | PSNR (dB) |"
echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
for p in draft preview final seed reference; do
  r() { awk -F, -v h="$h" -v p=$p '$1 == p { printf "%.2fx | %.2fx | %.2f", $6 / h, $7 / h, $10 }' "$1"; }
  echo "| $p | $(r "$out/gpu-seed.csv") | $(r "$out/gpu-cv.csv") |"
done
echo
echo "### The seed's scene"
echo
cat "$scratch/seed.md"
echo
echo "### calm + voyage with the seed's sky"
echo
cat "$scratch/cv.md"
echo
echo "## Presets on the bundled cutscenes ($size, 2 frames each)"
echo
"$tl" bench timelines/calm.tl timelines/voyage.tl timelines/giant_wave.tl timelines/dive.tl \
  --size $size --frames 60,180 --repeat 10 -q --presets draft,preview,final,seed \
  --csv "$out/gpu-bench.csv"
echo
echo "## tideline render, end to end ($size, giant_wave.tl, steady frames)"
echo
echo "Frames 0-55 less frames 0-7, over 48 (the first frames compile the programs);"
echo "the bench's render column above is the GPU's share alone."
echo
echo "| output | writers | ms/frame |"
echo "| --- | ---: | ---: |"
span() {
  local s
  s=$(date +%s.%N)
  "$tl" render timelines/giant_wave.tl --frames "$1" --size $size -o "$scratch/$2/f_####.$3" \
    --writers $4 -q 2>/dev/null
  calc "$(date +%s.%N) - $s"
}
for kind in png exr; do
  for w in 1 4 8; do
    a=$(span 0-7 a$kind$w $kind $w)
    b=$(span 0-55 b$kind$w $kind $w)
    printf '| %s | %d | %.1f |\n' $kind $w "$(calc "($b - $a) * 1000 / 48")"
  done
done
cp "$scratch/bpng4/f_0024.png" "$out/giant_wave_0024.png"
for q in draft preview final; do
  "$tl" still timelines/voyage.tl --frame 60 --size $size --quality $q -o "$out/voyage_60_$q.png" 2>/dev/null
done
"$tl" still timelines/dive.tl --frame 120 --size $size -o "$out/dive_120.png" 2>/dev/null
