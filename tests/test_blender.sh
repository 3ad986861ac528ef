#!/bin/sh
# tideline's EXR passes in real clients: OpenImageIO's oiiotool lists every
# layer and the camera's and Cryptomatte's attributes; Blender 3.4's
# compositor pulls the boat's and the giant wave's mattes with its
# Cryptomatte node, and they match tideline's own masks (intersection over
# union at least 0.97); its Vector Blur node blurs a panning shot along
# the pan; its glTF importer reads `tideline export-camera`'s file with the
# camera, its lens and the boat where `tideline eval` puts them at every
# frame (positions within 1e-4 m, angles within 1e-3 degrees). Skipped (77) where blender or oiiotool is missing
# (scripts/setup.sh installs both).
# Usage: test_blender.sh TIDELINE TIMELINES_DIR TESTS_DIR
set -eu
tideline=$1
timelines=$2
tests=$3
for tool in blender oiiotool; do
  if ! command -v $tool >/dev/null 2>&1; then
    echo "test_blender: $tool is not installed: skipped (scripts/setup.sh installs it)"
    exit 77
  fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
w=320
h=180
"$tideline" still "$timelines/giant_wave.tl" --time 10.4 --size ${w}x$h --spp 4 --passes all \
  -o "$work/hero.exr"

fail=0
check() { # what, then a command that must succeed
  what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; fail=1; fi
}

# Every layer and attribute, as OpenImageIO reads the file.
oiiotool --info -v "$work/hero.exr" >"$work/info.txt"
for channel in ViewLayer.Combined.R ViewLayer.Combined.A ViewLayer.Depth.Z ViewLayer.Normal.Z \
  ViewLayer.Position.X ViewLayer.mask_water.X ViewLayer.mask_foam.X ViewLayer.mask_giant.X \
  ViewLayer.mask_boat.X ViewLayer.mask_sky.X ViewLayer.mask_underwater.X \
  ViewLayer.CryptoObject00.r ViewLayer.CryptoObject02.a ViewLayer.Vector.X ViewLayer.Vector.W \
  ViewLayer.CryptoMaterial00.r ViewLayer.CryptoMaterial02.a ViewLayer.light_sky.R \
  ViewLayer.light_reflection.G ViewLayer.light_body.B ViewLayer.light_glitter.R \
  ViewLayer.light_foam.R ViewLayer.light_spray.R ViewLayer.light_boat.R ViewLayer.light_glare.B; do
  check "oiiotool lists $channel" grep -q "$channel" "$work/info.txt"
done
check "the Cryptomatte's IDs are 32-bit float" \
  grep -q 'ViewLayer.CryptoObject00.r (float)' "$work/info.txt"
for attribute in worldToCamera worldToNDC chromaticities framesPerSecond \
  'cryptomatte/542cafa/name: "ViewLayer.CryptoObject"' 'cryptomatte/542cafa/hash: "MurmurHash3_32"' \
  'cryptomatte/542cafa/conversion: "uint32_to_float32"' 'cryptomatte/542cafa/manifest: "{"sky"' \
  tideline/position_origin tideline/focal_length_mm; do
  check "oiiotool shows $attribute" grep -qF "$attribute" "$work/info.txt"
done

# Blender's Cryptomatte node against tideline's masks.
matte() { # object (or material), its mask pass[, the Cryptomatte layer]
  blender -b --factory-startup --python "$tests/blender_cryptomatte.py" -- \
    "$work/hero.exr" "$1" "$2" "$work/iou_$1.exr" $w $h ${3:-} >"$work/blender_$1.txt" 2>&1 || true
  grep -E '^(PASSES|MATTE|IOU|ERROR)' "$work/blender_$1.txt" || tail -5 "$work/blender_$1.txt"
  iou=$(sed -n 's/^IOU //p' "$work/blender_$1.txt")
  pixels=$(sed -n 's/^MATTE \([0-9]*\) of.*/\1/p' "$work/blender_$1.txt")
  check "Blender's matte of $1 matches $2 (IoU ${iou:-none} >= 0.97)" \
    awk -v v="${iou:-0}" 'BEGIN { exit !(v >= 0.97) }'
  check "Blender's matte of $1 covers pixels (${pixels:-none})" \
    awk -v v="${pixels:-0}" 'BEGIN { exit !(v >= 50) }'
}
matte boat mask_boat
matte giant mask_giant
# The material Cryptomatte: the built-in boat's material is its hull.
matte builtin_boat mask_boat ViewLayer.CryptoMaterial
# Blender's image node offers each light layer as a pass.
for layer in sky reflection body glitter foam spray boat glare; do
  check "Blender reads light_$layer as a pass" grep -q "^PASSES.*,light_$layer," "$work/blender_boat.txt"
done
# A name the frame does not hold pulls an empty matte: the comparison can fail.
blender -b --factory-startup --python "$tests/blender_cryptomatte.py" -- \
  "$work/hero.exr" ocean mask_boat "$work/iou_x.exr" $w $h >"$work/blender_x.txt" 2>&1 || true
iou=$(sed -n 's/^IOU //p' "$work/blender_x.txt")
check "the ocean's matte is not the boat's mask (IoU ${iou:-none} < 0.1)" \
  awk -v v="${iou:-1}" 'BEGIN { exit !(v < 0.1) }'
# Vector Blur on a camera panning at 8 degrees a frame: the detail across
# the pan is smeared (neighbouring pixels across differ much less), the
# detail down the frame far less.
cat >"$work/pan.tl" <<'EOF'
tideline 1
fps 24
duration 2s
size 160x90
quality draft
set camera.position 0 3 0
set camera.pitch -12deg
set camera.fov 50deg
key camera.yaw linear
  0s 0deg
  2s 192deg
EOF
"$tideline" render "$work/pan.tl" --frames 24 --passes vector,depth -o "$work/pan_##.exr" -q
blender -b --factory-startup --python "$tests/blender_vector_blur.py" -- \
  "$work/pan_24.exr" "$work" 160 90 >"$work/blender_blur.txt" 2>&1 || true
grep -E '^(GRADIENT|ERROR)' "$work/blender_blur.txt" || tail -5 "$work/blender_blur.txt"
set -- $(sed -n 's/^GRADIENT //p' "$work/blender_blur.txt") 1 1 1 1
check "Vector Blur smears across the pan (detail across $1 -> $2, down $3 -> $4)" \
  awk -v xb="$1" -v xa="$2" -v yb="$3" -v ya="$4" \
  'BEGIN { rx = xa / xb; ry = ya / yb; exit !(rx < 0.8 && rx < ry - 0.15) }'
# The camera and boat through glTF, at every frame of the two shots.
"$tideline" export-camera "$timelines/giant_wave.tl" -o "$work/camera.gltf"
frames=$("$tideline" check "$timelines/giant_wave.tl" | sed -n 's/.*= \([0-9]*\) frames.*/\1/p')
"$tideline" eval "$timelines/giant_wave.tl" --frames 0-$((frames - 1)) --json >"$work/eval.json"
blender -b --factory-startup --python "$tests/blender_camera.py" -- \
  "$work/camera.gltf" "$work/eval.json" >"$work/blender_camera.txt" 2>&1 || true
grep -E '^(OBJECTS|CAMERA|UP|BOAT|FRAMES|ERROR)' "$work/blender_camera.txt" || tail -5 "$work/blender_camera.txt"
set -- $(sed -n 's/^FRAMES //p' "$work/blender_camera.txt") 0 ANGLE_Y 0
check "Blender's import was compared at every frame ($1 of $frames)" test "$1" = "$frames"
check "Blender's camera has the first shot's lens ($3)" \
  awk -v a="${3#ANGLE_Y }" 'BEGIN { exit !(a > 0.8726 && a < 0.8727) }'
set -- $(sed -n 's/^CAMERA //p' "$work/blender_camera.txt") 9 9 9
check "Blender's camera at tideline's at every frame (worst ${1} m, ${2} rad, lens ${3} rad off)" \
  awk -v p="$1" -v d="$2" -v f="$3" 'BEGIN { exit !(p < 1e-4 && d < 1.75e-5 && f < 1.75e-5) }'
set -- $(sed -n 's/^UP //p' "$work/blender_camera.txt") 9
check "Blender's camera is rolled as tideline's at every frame (up ${1} rad off at worst)" \
  awk -v u="$1" 'BEGIN { exit !(u < 1.75e-5) }'
set -- $(sed -n 's/^BOAT //p' "$work/blender_camera.txt") 9 9 9
check "Blender's boat at tideline's at every frame (worst ${1} m, heading ${2}, deck ${3} rad off)" \
  awk -v p="$1" -v h="$2" -v d="$3" 'BEGIN { exit !(p < 1e-4 && h < 1.75e-5 && d < 1.75e-5) }'
exit $fail
