#!/usr/bin/env bash
# The tutorial's pictures (docs/tutorial.md): each step's timeline in
# scripts/tutorial/ rendered at the moment the step is about, the preview
# with its overlay and the soundtrack's waveform grabbed from a virtual
# display, and frames of the finished movie; into docs/images/tutorial-*.png.
# It also makes the tutorial's soundtrack (scripts/tutorial/score.wav, not
# kept in the repository) and its movie (in a scratch folder). A few
# minutes on two cores without a GPU.
#
#   scripts/tutorial.sh [PRESET]     (default final)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/build.sh
tl_build build -- tideline >/dev/null
preset=${1:-final}
steps=scripts/tutorial
images=docs/images
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

echo "tutorial: the soundtrack $steps/score.wav (a slow chord, made by ffmpeg)"
ffmpeg -hide_banner -loglevel error -y -f lavfi \
  -i "aevalsrc='0.25*(sin(2*PI*110*t)+0.6*sin(2*PI*165*t)+0.4*sin(2*PI*220.5*t))*(1-exp(-3*mod(t,2.5)))*exp(-0.6*mod(t,2.5))':s=44100:d=10" \
  "$steps/score.wav"

# step:time pairs: the moment each step's picture shows.
for shot in 01:0 02:0 03:0 04:5 05:9 06:9 07:9 08:7.5; do
  n=${shot%%:*} t=${shot##*:}
  echo "tutorial: step $n at $t s -> $images/tutorial-$n.png"
  build/tideline still "$steps/step$n.tl" --time "$t" --size 640x360 --quality "$preset" \
    -o "$images/tutorial-$n.png"
done

echo "tutorial: the preview of step 09 with its overlay -> $images/tutorial-09.png"
Xvfb -displayfd 3 -screen 0 640x360x24 -nolisten tcp 3>"$scratch/display" 2>/dev/null &
xvfb=$!
for _ in $(seq 100); do [ -s "$scratch/display" ] && break; sleep 0.1; done
display=":$(cat "$scratch/display")"
# The loop range from 5 s to 8 s (I at frame 120, O at 192), then a click
# at 0.65 of the bar: paused at frame 156, 6.5 s. A step a displayed
# frame: the grab waits until the screenshot, written at each new state,
# holds the last one (--keys ends, the same frame stays).
DISPLAY=$display SDL_AUDIODRIVER=none build/tideline preview "$steps/step09.tl" --paused \
  --time 5 --size 640x360 --quality preview --refine 1 \
  --keys i,shift+right,shift+right,shift+right,o,click:0.65 \
  --screenshot "$scratch/shown.png" --exit-after-frames 100000 >/dev/null 2>&1 &
preview=$!
build/tideline still "$steps/step09.tl" --time 6.5 --size 640x360 --quality preview \
  -o "$scratch/last.png"
for _ in $(seq 1200); do
  [ -s "$scratch/shown.png" ] && build/tideline compare "$scratch/shown.png" "$scratch/last.png" \
    --min-psnr 60 >/dev/null 2>&1 && break
  sleep 0.1
done
sleep 1
DISPLAY=$display ffmpeg -hide_banner -loglevel error -y -f x11grab -draw_mouse 0 \
  -video_size 640x360 -i "$display+0,0" -frames:v 1 "$images/tutorial-09.png"
kill "$preview" "$xvfb" 2>/dev/null || true
wait 2>/dev/null || true

echo "tutorial: the movie of step 09 at 640x360, preset preview (in a scratch folder)"
build/tideline render "$steps/step09.tl" -o "$scratch/frames/f_####.png" \
  --movie "$scratch/shot.mp4" --size 640x360 --quality preview -q
ffprobe -v error -show_entries stream=codec_type,codec_name,duration -of compact=p=0 \
  "$scratch/shot.mp4"
echo "tutorial: four frames of the movie -> $images/tutorial-10.png"
ffmpeg -hide_banner -loglevel error -y -i "$scratch/shot.mp4" \
  -vf "select='eq(n\,24)+eq(n\,96)+eq(n\,150)+eq(n\,228)',scale=320:180,tile=4x1" \
  -frames:v 1 -fps_mode vfr "$images/tutorial-10.png"
echo "tutorial: done"
