#!/usr/bin/env bash
# tideline bench in miniature (64x36, 2 frames, 2 presets): the table, the
# CSV and the plot appear, the CSV has its columns and finite numbers, and
# bad flags are refused before anything renders.
# ARGS: the tideline binary, the timelines folder, and the part to run:
# `measure` (the table, the CSV, --time-only, --passes, progress) or
# `options` (the reference cache, usage errors, compare, the rounds,
# PRESET@DIR, no OpenGL); both without one. ctest runs the two as
# test_bench and test_bench_options, about 12 s each here, so that neither
# is a slow test.
set -euo pipefail
tideline=$1
timelines=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
part=${3:-all}
case $part in all | measure | options) ;; *) fail "unknown part '$part' (measure or options)" ;; esac

if [ "$part" != options ]; then
  "$tideline" bench "$timelines/calm.tl" --size 64x36 --frames 0,120 --presets draft,final:lod=off \
    --repeat 2 --csv "$work/out/bench.csv" --plot "$work/out/bench.png" -q >"$work/table.md"
  cat "$work/table.md"
  grep -q '^| preset | ms/frame | render | readback | encode | PSNR dB | SSIM | p99 |' "$work/table.md" ||
    fail "table header"
  [ "$(grep -c '^| \(reference\|draft\|final:lod=off\)' "$work/table.md")" -eq 3 ] || fail "table rows"

  csv=$work/out/bench.csv
  head -1 "$csv" | grep -qx 'preset,width,height,frames,repeat,ms_total,ms_render,ms_readback,ms_encode,psnr_db,ssim,p99_levels,worst_psnr_db,worst_frame,pareto' ||
    fail "CSV header: $(head -1 "$csv")"
  [ "$(wc -l <"$csv")" -eq 4 ] || fail "CSV rows"
  # Every numeric field finite; sizes and counts as asked; times >= 0 (a
  # fast GPU can time a 64x36 frame as 0.0 ms); errors in range; the
  # reference scores the PSNR cap against itself.
  awk -F, 'NR > 1 {
    for (i = 2; i <= 13; i++) if ($i !~ /^-?[0-9]+(\.[0-9]+)?$/) { print "field " i ": " $i; bad = 1 }
    if ($2 != 64 || $3 != 36 || $4 != 2) { print "size/frames: " $0; bad = 1 }
    if ($6 < 0 || $7 < 0 || $8 < 0 || $9 < 0) { print "time: " $0; bad = 1 }
    if ($1 == "reference" && $10 != 200) { print "reference PSNR: " $0; bad = 1 }
    if ($1 != "reference" && ($10 <= 0 || $10 >= 200 || $11 <= 0 || $11 > 1 || $14 !~ /^calm\.tl:(0|120)$/)) {
      print "metrics: " $0; bad = 1 }
  } END { exit bad }' "$csv" || fail "CSV values"
  [ "$(awk -F, 'NR > 1 && $1 != "reference" { n += $15 } END { print n }' "$csv")" -ge 1 ] ||
    fail "no preset on the Pareto front"
  head -c 8 "$work/out/bench.png" | od -An -tx1 | grep -q '89 50 4e 47 0d 0a 1a 0a' || fail "plot is not a PNG"
  ls -A "$work/out" | grep -q '^\.' && fail "a temporary file was left behind"

  # --time-only: no reference row, timings only, error columns empty; with
  # --shader-dir the shaders of a folder (the source tree's) are timed.
  "$tideline" bench "$timelines/calm.tl" --size 64x36 --frames 0 --presets draft --repeat 1 --time-only \
    --shader-dir "$(dirname "$timelines")/shaders" --csv "$work/t.csv" -q >"$work/t.md"
  grep -q '^| reference' "$work/t.md" && fail "--time-only rendered the reference"
  grep -q '^| draft | [0-9.]* | [0-9.]* | [0-9.]* | [0-9.]* | | | | |$' "$work/t.md" ||
    fail "--time-only table: $(cat "$work/t.md")"
  awk -F, 'NR == 2 { if ($1 != "draft" || $6 !~ /^[0-9]+(\.[0-9]+)?$/ || $10 != "" || $15 != 0) exit 1 }
    END { if (NR != 2) exit 1 }' \
    "$work/t.csv" || fail "--time-only CSV: $(cat "$work/t.csv")"

  # --passes: a second table of the median frame's passes. voyage's frame 120
  # has the boat and the giant wave in view (still -v lists them), calm's
  # frame none of them, so their columns are 0 for calm; the passes add up
  # to their total, which the frame's render time holds. seed runs the
  # prepass over the giant wave alone (quality.giant_prepass): not on calm.
  # A pass that runs is not asserted to take > 0.0 ms: at 64x36 a GPU draws
  # it in microseconds, which the table's 0.1 ms rounds to 0.0; a pass that
  # does not run is exactly 0.
  "$tideline" still "$timelines/voyage.tl" --frame 120 --size 64x36 --quality draft -v \
    -o "$work/v120.png" 2>"$work/v120.err"
  grep -q '^tideline still: features: .*giant wave.*boat' "$work/v120.err" ||
    fail "voyage frame 120 lacks the boat or the giant wave: $(cat "$work/v120.err")"

  "$tideline" bench "$timelines/voyage.tl" --size 64x36 --frames 120 --presets draft,seed --repeat 1 \
    --time-only --passes -q >"$work/p.md"
  "$tideline" bench "$timelines/calm.tl" --size 64x36 --frames 120 --presets draft,seed --repeat 1 \
    --time-only --passes -q >>"$work/p.md"
  cat "$work/p.md"
  [ "$(grep -c '^| preset | boat | prepass | ocean | giant wave | glare | display | filter | all passes | render | frame |$' "$work/p.md")" -eq 2 ] ||
    fail "--passes header"
  awk -F' *[|] *' '$2 ~ /^(draft|seed)$/ && NF == 13 {
    rows++
    sum = 0
    for (i = 3; i <= 9; i++) { if ($i !~ /^[0-9]+\.[0-9]$/) { print "field " i ": " $0; bad = 1 }; sum += $i }
    if (sum < $10 - 0.4 || sum > $10 + 0.4) { print "sum " sum ": " $0; bad = 1 }
    if (!($11 >= $10 - 0.1)) { print "render: " $0; bad = 1 }
    if ($12 == "calm.tl:120" && !($3 == 0 && $6 == 0)) { print "calm boat/giant: " $0; bad = 1 }
    if ($2 == "seed" && $12 == "calm.tl:120" && $4 != 0) { print "seed prepass: " $0; bad = 1 }
    if ($12 != "voyage.tl:120" && $12 != "calm.tl:120") { print "frame: " $0; bad = 1 }
  } END { if (rows != 4) { print "rows " rows; bad = 1 }; exit bad }' "$work/p.md" || fail "--passes table"
  grep -q '^| preset | boat' "$work/t.md" && fail "a passes table without --passes"

  # Progress: every `reference` frame has a line, and those after the
  # first say how long is left.
  "$tideline" bench "$timelines/calm.tl" --size 32x18 --frames 0,1,2 --presets draft --repeat 1 \
    2>"$work/progress" >/dev/null
  grep -q '^bench: reference calm.tl frame 0 (1/3)$' "$work/progress" || fail "progress: $(cat "$work/progress")"
  [ "$(grep -cE '^bench: reference calm.tl frame [12] \([23]/3\) ETA [0-9]+s$' "$work/progress")" -eq 2 ] ||
    fail "progress ETA: $(cat "$work/progress")"
fi

if [ "$part" != measure ]; then
  # --reference-cache: the first run renders and keeps the reference
  # frames, the second reads them (the same scores, the reference row
  # untimed); a timeline changed by a comment alone, or a kept file cut
  # short, renders afresh.
  cache=$work/cache
  bench_cached() {
    "$tideline" bench "$1" --size 32x18 --frames 0,120 --presets draft --repeat 1 \
      --reference-cache "$cache" --csv "$2" -q >"$2.md" 2>"$2.err"
  }
  psnr_of() { awk -F, '$1 == "draft" { print $10 }' "$1"; }
  ref_ms() { awk -F, '$1 == "reference" { print $6 }' "$1"; }
  bench_cached "$timelines/calm.tl" "$work/c1.csv"
  [ "$(ls "$cache" | grep -c '\.tlref$')" -eq 2 ] || fail "cache files: $(ls -A "$cache")"
  [ -n "$(ref_ms "$work/c1.csv")" ] || fail "first cached run: reference untimed"
  bench_cached "$timelines/calm.tl" "$work/c2.csv"
  grep -q '^| reference | (cached) |' "$work/c2.csv.md" || fail "second run: $(cat "$work/c2.csv.md")"
  [ -z "$(ref_ms "$work/c2.csv")" ] || fail "second run rendered the reference: $(cat "$work/c2.csv")"
  [ "$(psnr_of "$work/c1.csv")" = "$(psnr_of "$work/c2.csv")" ] || fail "cached scores differ"
  cp "$timelines/calm.tl" "$work/calm.tl"
  echo '# a comment' >>"$work/calm.tl"
  bench_cached "$work/calm.tl" "$work/c3.csv"
  [ -n "$(ref_ms "$work/c3.csv")" ] || fail "a changed timeline hit the cache"
  [ "$(ls "$cache" | grep -c '\.tlref$')" -eq 4 ] || fail "cache files after a change: $(ls -A "$cache")"
  for f in "$cache"/*.tlref; do truncate -s 100 "$f"; done
  bench_cached "$work/calm.tl" "$work/c4.csv"
  [ -n "$(ref_ms "$work/c4.csv")" ] || fail "a file cut short hit the cache"
  [ "$(psnr_of "$work/c3.csv")" = "$(psnr_of "$work/c4.csv")" ] || fail "re-rendered scores differ"
  ls -A "$cache" | grep -vq '\.tlref$' && fail "a temporary left in the cache: $(ls -A "$cache")"

  # Usage errors: status 2, a message naming the flag, nothing written.
  expect_usage() {
    local want=$1; shift
    set +e
    "$tideline" bench "$@" >"$work/o" 2>"$work/e"
    local rc=$?
    set -e
    [ $rc -eq 2 ] || fail "status $rc for: $*"
    grep -q -- "$want" "$work/e" || fail "message for $*: $(cat "$work/e")"
  }
  expect_usage "--presets" "$timelines/calm.tl" --presets draft,nope
  expect_usage "always rendered" "$timelines/calm.tl" --presets reference
  expect_usage "no quality knob 'nope'" "$timelines/calm.tl" --presets final:nope=1
  expect_usage "lod=maybe is not on or off" "$timelines/calm.tl" --presets final:lod=maybe
  expect_usage "march_steps=1.5 is not a whole number in 1..10000" "$timelines/calm.tl" --presets final:march_steps=1.5
  expect_usage "--repeat" "$timelines/calm.tl" --repeat 0
  expect_usage "not a .png" "$timelines/calm.tl" --plot "$work/p.svg"
  expect_usage "no timeline" --size 64x36
  expect_usage "--time-only does not measure" "$timelines/calm.tl" --time-only --plot "$work/p.png"
  expect_usage "shader" "$timelines/calm.tl" --shader-dir "$work/nowhere" --size 64x36
  expect_usage "--frames" "$timelines/calm.tl" --frames 99999 --size 64x36
  expect_usage "--reference-cache: --time-only" "$timelines/calm.tl" --time-only --reference-cache "$cache"
  expect_usage "--reference-cache: .* is not a writable folder" "$timelines/calm.tl" \
    --reference-cache "$work/calm.tl"
  expect_usage "--reference-cache: cannot create folder" "$timelines/calm.tl" \
    --reference-cache "$work/calm.tl/sub"
  [ ! -e "$work/p.svg" ] || fail "wrote a plot on a usage error"
  "$tideline" bench --help | grep -q 'Usage: tideline bench' || fail "--help"

  # tideline compare: an image against itself, against another, and refusals.
  "$tideline" still --size 32x18 --quality draft -o "$work/a.png"
  "$tideline" still --size 32x18 --quality draft --time 5 -o "$work/b.png"
  "$tideline" still --size 18x32 --quality draft -o "$work/c.png"
  "$tideline" compare "$work/a.png" "$work/a.png" | grep -q '^PSNR 200.00 dB  SSIM 1.00000  p99 0.0 levels  max 0.0 levels  (32x18)$' ||
    fail "compare with itself"
  line=$("$tideline" compare "$work/a.png" "$work/b.png" --diff "$work/d.png")
  awk '{ if (!($2 > 5 && $2 < 200 && $5 < 1)) exit 1 }' <<<"$line" || fail "compare: $line"
  [ -s "$work/d.png" ] || fail "no --diff image"
  set +e
  "$tideline" compare "$work/a.png" "$work/b.png" --min-psnr 150 >/dev/null 2>"$work/e"; rc1=$?
  "$tideline" compare "$work/a.png" "$work/c.png" >/dev/null 2>"$work/e2"; rc2=$?
  "$tideline" compare "$work/a.png" >/dev/null 2>"$work/e3"; rc3=$?
  set -e
  [ $rc1 -eq 1 ] && grep -q 'below --min-psnr 150' "$work/e" || fail "--min-psnr: $rc1 $(cat "$work/e")"
  [ $rc2 -eq 1 ] && grep -q 'a.png is 32x18 but .*c.png is 18x32' "$work/e2" || fail "sizes: $(cat "$work/e2")"
  [ $rc3 -eq 2 ] && grep -q 'two images are needed' "$work/e3" || fail "one image: $(cat "$work/e3")"

  # The presets take turns, round by round, and each round starts one
  # preset further along: draft, final, then final, draft.
  "$tideline" bench "$timelines/calm.tl" --size 32x18 --frames 0 --presets draft,final --repeat 2 \
    --time-only 2>"$work/rounds" >/dev/null
  [ "$(sed -nE 's/^bench: ([a-z]+) +calm.tl frame 0 \(1\/1\) round ([12])\/2$/\1 \2/p' "$work/rounds" | paste -sd,)" = \
    "draft 1,final 1,final 2,draft 2" ] || fail "rounds: $(cat "$work/rounds")"

  # PRESET@DIR: a preset with a folder's shaders, timed in the same rounds
  # (the source tree's shaders, the same as the built-in ones: the same
  # error); a folder without shaders is refused, naming the preset.
  "$tideline" bench "$timelines/calm.tl" --size 32x18 --frames 0 --presets draft,draft@"$(dirname "$timelines")/shaders" \
    --repeat 1 -q --csv "$work/at.csv" >/dev/null
  awk -F, 'NR > 1 { p[$1] = $10 } END {
    if (!("draft" in p) || !(("draft@" shaders) in p) || p["draft"] != p["draft@" shaders]) exit 1 }' \
    shaders="$(dirname "$timelines")/shaders" "$work/at.csv" || fail "PRESET@DIR: $(cat "$work/at.csv")"
  if "$tideline" bench "$timelines/calm.tl" --presets draft@"$work" --time-only 2>"$work/at.err"; then
    fail "PRESET@DIR without shaders was accepted"
  fi
  grep -q "^tideline bench: --presets: draft@$work: '$work' holds no ocean.frag$" "$work/at.err" ||
    fail "PRESET@DIR error: $(cat "$work/at.err")"
  # A folder whose shaders do not compile stops the bench with the row's
  # name and the shader's error.
  mkdir "$work/broken"
  cp "$(dirname "$timelines")"/shaders/* "$work/broken/"
  echo "this is not glsl" >>"$work/broken/water.glsl"
  if "$tideline" bench "$timelines/calm.tl" --size 32x18 --frames 0 --presets draft,draft@"$work/broken" \
    --time-only -q 2>"$work/broken.err" >/dev/null; then
    fail "a folder of broken shaders was benched"
  fi
  grep -q "^tideline bench: draft@$work/broken: calm.tl: shader ocean.frag failed to compile:" "$work/broken.err" ||
    fail "broken shaders' error: $(cat "$work/broken.err")"
  grep -q '^water.glsl:[0-9]*' "$work/broken.err" || fail "no shader line: $(cat "$work/broken.err")"

  # No OpenGL at all (no EGL vendor to load): the context's error, exit 1,
  # no crash.
  set +e
  __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json "$tideline" bench "$timelines/calm.tl" \
    --size 32x18 --frames 0 --presets draft 2>"$work/nogl.err" >/dev/null
  status=$?
  set -e
  [ "$status" -eq 1 ] || fail "bench without OpenGL exited $status: $(cat "$work/nogl.err")"
  grep -q '^tideline bench: no headless OpenGL 3.3 context' "$work/nogl.err" ||
    fail "bench without OpenGL: $(cat "$work/nogl.err")"
fi

# Last: ctest passes on this line alone (it ignores the exit status).
echo BENCH_OK
