#!/usr/bin/env bash
# Every number of docs/quality.md, measured in one run on this machine (a
# benchmark, not a test: run it on a quiet machine, it takes ~30 minutes
# on 2 cores). Prints Markdown; writes the bench's CSVs and plot to OUT and
# its tables into docs/quality.md between marker comments, so the page is
# always one run's numbers and nobody copies them by hand.
#
#   scripts/bench-quality.sh [OUT_FOLDER] [BEFORE_TIDELINE]
#   scripts/bench-quality.sh --tables [OUT_FOLDER]
#
# BEFORE_TIDELINE: a tideline binary built from an earlier commit, to time
# `render` before and after the pipeline changes side by side.
# --tables: measure nothing; rewrite the blocks that come from OUT's CSVs
# (after editing this script's table code, or to check it).
# DOC names the page to write (default docs/quality.md).
set -euo pipefail
cd "$(dirname "$0")/.."
tables_only=
if [ "${1:-}" = --tables ]; then
  tables_only=1
  shift
fi
out=${1:-docs/images}
before=${2:-}
doc=${DOC:-docs/quality.md}
size=640x360
tl=build/tideline
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$out"
# The benches below that share frames render their `reference` once.
cache=(--reference-cache "$scratch/reference")

# block NAME FILE: replaces the lines between
#   <!-- bench-quality:begin NAME --> and <!-- bench-quality:end NAME -->
# in $doc with FILE. A page without the markers is left alone, with a warning:
# every table this script prints has a NAME (to NAME below), and the page
# keeps those it has markers for.
block() {
  local name=$1 file=$2
  if ! grep -qF "<!-- bench-quality:begin $name -->" "$doc" ||
    ! grep -qF "<!-- bench-quality:end $name -->" "$doc"; then
    echo "bench-quality: $doc has no block '$name'; not written" >&2
    return 0
  fi
  awk -v b="<!-- bench-quality:begin $name -->" -v e="<!-- bench-quality:end $name -->" -v f="$file" '
    $0 == b { print; while ((getline l < f) > 0) print l; skip = 1; next }
    $0 == e { skip = 0 }
    !skip' "$doc" >"$doc.tmp.$$"
  mv "$doc.tmp.$$" "$doc"
}
# presets CSV: the bench's own table (as `tideline bench` prints it) from its CSV.
presets() {
  awk -F, 'BEGIN {
      print "| preset | ms/frame | render | readback | encode | PSNR dB | SSIM | p99 | worst frame (PSNR dB) |"
      print "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |" }
    NR == 1 { next }
    $1 == "reference" && $6 == "" { print "| reference | (cached) | | | | (yardstick) | | | |"; next }
    $1 == "reference" { printf "| reference | %.0f | %.0f | | | (yardstick) | | | |\n", $6, $7; next }
    { printf "| %s%s | %.1f | %.1f | %.1f | %.1f | %.2f | %.4f | %.0f | %s (%.2f) |\n",
        $1, $15 == 1 ? " *" : "", $6, $7, $8, $9, $10, $11, $12, $14, $13 }' "$1"
}
# variants CSV: one knob changed per row; time and error only.
variants() {
  awk -F, 'BEGIN {
      print "| variant | ms/frame | PSNR dB | SSIM | p99 |"
      print "| --- | ---: | ---: | ---: | ---: |" }
    NR == 1 || $1 == "reference" { next }
    { printf "| %s | %.1f | %.2f | %.4f | %.0f |\n", $1, $6, $10, $11, $12 }' "$1"
}
csv_blocks() {
  presets "$out/quality-seed.csv" >"$scratch/b-seed"
  block presets-seed "$scratch/b-seed"
  presets "$out/quality-bench.csv" >"$scratch/b-bench"
  block presets "$scratch/b-bench"
  presets "$out/quality-targets.csv" >"$scratch/b-targets"
  block presets-targets "$scratch/b-targets"
  variants "$out/quality-changes.csv" >"$scratch/b-changes"
  block changes "$scratch/b-changes"
}
if [ -n "$tables_only" ]; then
  csv_blocks
  exit 0
fi

ms() { sed -nE 's/.*median ([0-9.]+) ms\/frame.*/\1/p'; }
psnr() { "$tl" compare "$1" "$2" | awk '{ print $2 }'; }
# ... | to NAME: prints the lines and keeps them for block NAME.
to() { tee -a "$scratch/b-$1"; }

echo "## The yardstick: seed 002's shader alone ($size)"
echo
printf '%s\n' "| harness run | ms/frame | PSNR vs the document's settings (dB) |" "| --- | ---: | ---: |" | to yardstick
base=$(build/seed002 --size $size --repeat 10 --srgb --out "$scratch/h.png" | ms)
echo "| document's settings (12 march / 36 normal octaves, 64 adaptive steps) | $base | — |" | to yardstick
m36=$(build/seed002 --size $size --repeat 10 --srgb --march-octaves 36 --out "$scratch/h36.png" | ms)
echo "| 36 octaves marched too (one count for both) | $m36 | $(psnr "$scratch/h.png" "$scratch/h36.png") |" | to yardstick
for n in 64 256 1024; do
  f=$(build/seed002 --size $size --repeat 3 --srgb --fixed-steps $n --out "$scratch/f$n.png" | ms)
  echo "| $n fixed steps across the slab | $f | $(psnr "$scratch/h.png" "$scratch/f$n.png") |" | to yardstick
done
block yardstick "$scratch/b-yardstick"
echo
echo "## tideline's \`seed\` against the shader (bench/seed002.tl)"
echo
for t in 10 37; do
  build/seed002 --size $size --time $t --repeat 1 --srgb --out "$scratch/s$t.png" >/dev/null
  "$tl" still bench/seed002.tl --time $t --dither off -o "$scratch/t$t.png"
  echo "- t = $t s: $("$tl" compare "$scratch/s$t.png" "$scratch/t$t.png")" | to faithful
done
block faithful "$scratch/b-faithful"
echo
echo "## Presets on the seed's scene, against the yardstick ($base ms/frame)"
echo
"$tl" bench bench/seed002.tl --size $size --frames 240,888 --repeat 3 -q \
  --presets draft,preview,final,seed --csv "$out/quality-seed.csv" | tee "$scratch/seed.md"
echo
awk -F, -v base="$base" 'NR > 1 && $1 != "reference" {
  printf "- %s: %.2fx the shader alone (render %.2fx)\n", $1, $6 / base, $7 / base }' "$out/quality-seed.csv"
echo
echo "## Against the targets: each preset's time over the shader's, interleaved ($size)"
echo
# A shared machine's speed drifts 10-20% over minutes, so each of three
# rounds times the shader (t = 10 s and 37 s, before and after), then the
# presets on the seed's scene and on the targets' scenes (calm.tl and
# bench/voyage.tl with the seed's sky), and divides neighbours in time; the
# table gives the median of the rounds' ratios.
# voyage: bench/voyage.tl, the bundled shot as it was when the targets were
# set (the bundled one now opens on a boat close-up).
for t in calm voyage; do
  src=timelines/$t.tl
  [ $t = voyage ] && src=bench/voyage.tl
  { cat "$src"; echo 'set sky.model seed'; } >"$scratch/$t.tl"
done
shader() { echo "($(build/seed002 --size $size --time 10 --repeat 6 | ms) + $(build/seed002 --size $size --time 37 --repeat 6 | ms)) / 2" | bc -l; }
for round in 1 2 3; do
  h1=$(shader)
  "$tl" bench bench/seed002.tl --size $size --frames 240,888 --repeat 3 -q --time-only \
    --presets draft,preview,final,seed --csv "$scratch/seed-$round.csv" >/dev/null
  "$tl" bench "$scratch/calm.tl" "$scratch/voyage.tl" --size $size --frames 60,180 --repeat 3 -q \
    --time-only --presets draft,preview,final,seed --csv "$scratch/cv-$round.csv" >/dev/null
  # Each scene alone too: the pooled median sits between calm's slowest
  # frame and voyage's fastest, and says little about either.
  for t in calm voyage; do
    "$tl" bench "$scratch/$t.tl" --size $size --frames 60,180 --repeat 3 -q --time-only \
      --presets draft,preview,final,seed --csv "$scratch/$t-$round.csv" >/dev/null
  done
  h2=$(shader)
  h=$(echo "($h1 + $h2) / 2" | bc -l)
  for k in seed cv calm voyage; do
    awk -F, -v h="$h" -v r=$round -v k=$k 'NR > 1 { printf "%s %s %s %.4f %.4f\n", k, r, $1, $6 / h, $7 / h }' \
      "$scratch/$k-$round.csv"
  done >>"$scratch/ratios"
  echo "- round $round: the shader alone $(printf '%.1f' "$h") ms/frame"
done
echo
printf '%s\n' "| preset | seed's scene: end to end | render | calm + voyage (seed sky): end to end | render |" \
  "| --- | ---: | ---: | ---: | ---: |" | to ratios
# The median of the rounds' ratios: scene $1, column $2, preset $p.
med() { awk -v k=$1 -v p=$p -v c=$2 '$1 == k && $3 == p { print $c }' "$scratch/ratios" | sort -n | sed -n 2p; }
for p in draft preview final seed; do
  printf '| %s | %.2fx | %.2fx | %.2fx | %.2fx |\n' $p "$(med seed 4)" "$(med seed 5)" "$(med cv 4)" "$(med cv 5)"
done | to ratios
block ratios "$scratch/b-ratios"
echo
echo "Each of the targets' scenes alone (seed sky, frames 60 and 180, the same rounds):"
echo
printf '%s\n' "| preset | calm: end to end | render | voyage: end to end | render |" \
  "| --- | ---: | ---: | ---: | ---: |" | to ratios-scenes
for p in draft preview final seed; do
  printf '| %s | %.2fx | %.2fx | %.2fx | %.2fx |\n' $p "$(med calm 4)" "$(med calm 5)" "$(med voyage 4)" "$(med voyage 5)"
done | to ratios-scenes
block ratios-scenes "$scratch/b-ratios-scenes"
if [ -n "$before" ]; then
  # The same, once, with the earlier binary (it renders `reference` too).
  h1=$(shader)
  "$before" bench bench/seed002.tl --size $size --frames 240,888 --repeat 3 -q \
    --presets draft,preview,final,seed --csv "$scratch/bseed.csv" >/dev/null
  "$before" bench "$scratch/calm.tl" "$scratch/voyage.tl" --size $size --frames 60,180 --repeat 3 -q \
    --presets draft,preview,final,seed --csv "$scratch/bcv.csv" >/dev/null
  h2=$(shader)
  h=$(echo "($h1 + $h2) / 2" | bc -l)
  # Preset $p's column $2 of CSV $1 over the shader's time.
  r() { awk -F, -v h="$h" -v p=$p -v c=$2 '$1 == p { printf "%.2f", $c / h }' "$1"; }
  for p in draft preview final seed; do
    echo "| $p (before) | $(r "$scratch/bseed.csv" 6)x | $(r "$scratch/bseed.csv" 7)x | $(r "$scratch/bcv.csv" 6)x | $(r "$scratch/bcv.csv" 7)x |"
  done
fi
echo
echo "## Pass by pass: each preset's median frame on the targets' scenes (ms)"
for t in calm voyage; do
  echo
  "$tl" bench "$scratch/$t.tl" --size $size --frames 60,180 --repeat 3 -q --time-only --passes \
    --presets draft,preview,final,seed | sed -n '/^| preset | boat/,$p' | to passes-$t
  block passes-$t "$scratch/b-passes-$t"
done
echo
echo "\`tideline render\` of the seed's scene to PNG (render and write overlap), steady"
echo "frames (the time of 28 frames less that of 4, over 24), against the shader timed"
echo "just before and after:"
echo
# steady PRESET [TIMELINE FIRST COUNT]: ms per frame of COUNT frames after
# the four from FIRST (the time of 4 + COUNT frames less that of 4).
steady() {
  local a b s tlf=${2:-bench/seed002.tl} f=${3:-240} n=${4:-24}
  s=$(date +%s.%N); "$tl" render "$tlf" --quality $1 --frames $f-$((f + 3)) --size $size -q -o "$scratch/e2e/a_####.png" 2>/dev/null; a=$(echo "$(date +%s.%N) - $s" | bc -l)
  s=$(date +%s.%N); "$tl" render "$tlf" --quality $1 --frames $f-$((f + n + 3)) --size $size -q -o "$scratch/e2e/b_####.png" 2>/dev/null; b=$(echo "$(date +%s.%N) - $s" | bc -l)
  echo "($b - $a) * 1000 / $n" | bc -l
}
printf '%s\n' "| preset | render to PNG (ms/frame) | the shader (ms/frame) | ratio |" \
  "| --- | ---: | ---: | ---: |" | to render-png
for p in draft preview final seed; do
  h1=$(shader); e=$(steady $p); h2=$(shader)
  printf '| %s | %.1f | %.1f | %.2fx |\n' $p "$e" "$(echo "($h1 + $h2) / 2" | bc -l)" \
    "$(echo "$e * 2 / ($h1 + $h2)" | bc -l)" | to render-png
done
block render-png "$scratch/b-render-png"
echo
echo "The same on each target scene (seed sky), frames 174-193 less 170-173:"
echo
printf '%s\n' "| preset | scene | render to PNG (ms/frame) | the shader (ms/frame) | ratio |" \
  "| --- | --- | ---: | ---: | ---: |" | to render-png-scenes
for p in draft preview; do
  for t in calm voyage; do
    h1=$(shader); e=$(steady $p "$scratch/$t.tl" 170 20); h2=$(shader)
    printf '| %s | %s | %.1f | %.1f | %.2fx |\n' $p $t "$e" "$(echo "($h1 + $h2) / 2" | bc -l)" \
      "$(echo "$e * 2 / ($h1 + $h2)" | bc -l)" | to render-png-scenes
  done
done
block render-png-scenes "$scratch/b-render-png-scenes"
echo
echo "## Presets on the bundled cutscenes ($size, 2 frames each)"
echo
"$tl" bench timelines/calm.tl timelines/voyage.tl timelines/giant_wave.tl timelines/dive.tl \
  --size $size --frames 60,180 --repeat 3 -q --presets draft,preview,final,seed "${cache[@]}" \
  --csv "$out/quality-bench.csv" --plot "$out/quality-bench.png"
echo
echo "## Presets on the targets' scenes with the seed's sky, against reference ($size)"
echo
"$tl" bench "$scratch/calm.tl" "$scratch/voyage.tl" --size $size --frames 60,180 --repeat 1 -q \
  --presets draft,preview,final,seed --csv "$out/quality-targets.csv"
echo
echo "## Each change to final, on and off, on the same cutscenes"
echo
"$tl" bench timelines/calm.tl timelines/voyage.tl timelines/giant_wave.tl timelines/dive.tl \
  --size $size --frames 60,180 --repeat 3 -q "${cache[@]}" \
  --presets final,final:lod=off,final:filtered_shading=off,preview:filtered_shading=off,draft:filtered_shading=on,final:pixel_filter=0,preview:pixel_filter=0,draft:pixel_filter=0,final:march_relax=1,preview:march_relax=1,final:march_prepass=off,preview:march_prepass=off,draft:march_prepass=off,final:prepass_budget=0,preview:prepass_budget=0,final:analytic_normals=off,final:lod=off:analytic_normals=off,final:refine_steps=2,final:refine_steps=2:hit_epsilon=0.02,final:polish=off,preview:polish=off,draft:polish=on,final:facing_normals=off,preview:facing_normals=off,draft:facing_normals=off,seed,seed:miss_at_start=off:normalize_smoothed=on,seed:march_octaves=36,draft,preview \
  --csv "$out/quality-changes.csv"
echo
echo "## Feature specialisation ($size, calm.tl frames 0-11, final)"
echo
# The same frames with the giant wave and fog compiled in but all but
# invisible: what every frame would cost if the program were not
# specialised to what the scene needs.
general="timelines/.calm-general.$$.tl"
trap 'rm -rf "$scratch" "$general"' EXIT
{ cat timelines/calm.tl; printf '%s\n' 'set giant.enabled on' 'set giant.fade 0.0001' \
    'set giant.center 0 5000' 'set fog.density 0.000001'; } >"$general"
for t in timelines/calm.tl "$general"; do
  r=$("$tl" render "$t" --frames 0-11 --size $size -o "$scratch/spec/f_####.png" -v 2>&1)
  echo "- $(basename "$t"): $(sed -nE 's/.*\(([0-9]+) ms\/frame\).*/\1/p' <<<"$r") ms/frame, features: $(sed -nE 's/.*frame 0: features: (.*)/\1/p' <<<"$r")" |
    to specialisation
done
block specialisation "$scratch/b-specialisation"
echo
echo "## tideline render, end to end ($size, calm.tl, 12 frames, final)"
echo
printf '%s\n' "| output | binary | ms/frame |" "| --- | --- | ---: |" | to outputs
for bin in "$before" "$tl"; do
  [ -n "$bin" ] || continue
  label=$([ "$bin" = "$tl" ] && echo now || echo before)
  for kind in png exr movie; do
    case $kind in
      png) args=(-o "$scratch/$label/p_####.png") ;;
      exr) args=(-o "$scratch/$label/e_####.exr") ;;
      movie) args=(--movie "$scratch/$label/m.mp4") ;;
    esac
    r=$("$bin" render timelines/calm.tl --frames 0-11 --size $size --quality final "${args[@]}" -q 2>&1 |
      sed -nE 's/.*\(([0-9]+) ms\/frame\).*/\1/p')
    echo "| $kind | $label | $r |" | to outputs
  done
done
block outputs "$scratch/b-outputs"
echo
echo "## Is reference converged? (320x180, the middle frame of each cutscene)"
echo
scripts/reference-convergence.sh 320x180 | to convergence
block convergence "$scratch/b-convergence"
echo
# The bench tables above, from the CSVs they wrote.
csv_blocks
echo "bench-quality: wrote the tables into $doc" >&2
