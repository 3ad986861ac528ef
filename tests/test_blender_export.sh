#!/bin/sh
# The Blender exporter's round trip: Blender 3.4 builds scenes headless
# (Bezier keys with a free handle, XYZ, ZXY, quaternion and axis-angle
# rotations, a keyed lens, a vertical sensor fit, a rotating and a still
# sun, boats by name and by property, a Noise modifier, two cameras cut
# at a marker), tools/blender/tideline_export.py writes each as a
# timeline, and `tideline eval` agrees with Blender's own evaluation at
# every frame: positions within 1e-4 m, the view, its up, the field of
# view and the sun within 1e-3 degrees. What was baked, `tideline check`
# lists; what the exporter refuses, it says. Skipped (77) without blender.
# Usage: test_blender_export.sh TIDELINE REPO_DIR
set -eu
tideline=$1
repo=$2
if ! command -v blender >/dev/null 2>&1; then
  echo "test_blender_export: blender is not installed: skipped (scripts/setup.sh installs it)"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
check() { # what, then a command that must succeed
  what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAILED: $what"; fail=1; fi
}

blender -b --factory-startup --python "$repo/tests/blender_export_scenes.py" -- \
  "$repo/tools/blender" "$work" >"$work/blender.txt" 2>&1 || true
grep -E '^(EXPORTED|REFUSED|REPORT)|Error|Traceback' "$work/blender.txt" || tail -20 "$work/blender.txt"
for scene in keys quaternion axis_angle zxy formats layered noise cut; do
  check "$scene: exported" test -f "$work/$scene.tl"
  check "$scene: tideline check reads it, without a warning" \
    sh -c "'$tideline' check --strict '$work/$scene.tl' >/dev/null"
  result=$(python3 "$repo/tests/export_compare.py" "$tideline" "$work/$scene.tl" "$work/$scene.json" 2>&1) &&
    ok=0 || ok=1
  echo "$scene: $result"
  check "$scene: tideline eval agrees with Blender at every frame" test $ok = 0
done
# Keys stay keys where tideline expresses them; the rest is baked, and
# check says so.
check "keys: the camera's curves are keys, not baked" \
  sh -c "! grep -q 'key camera.* baked' '$work/keys.tl'"
check "keys: a free handle is written where Blender has it" grep -q 'right free 6f' "$work/keys.tl"
check "keys: the eased key keeps its easing" grep -q 'ease-in-out-sine' "$work/keys.tl"
check "zxy: the back easing keeps its overshoot" grep -q 'ease-out-back back 1.70158' "$work/zxy.tl"
# Blender's render size and rate: 1083x1923 at 50 % is 541x961.
check "formats: the size as Blender renders it" grep -qx 'size 541x961' "$work/formats.tl"
check "formats: 30000/1001 fps" grep -q '^fps 29.9700' "$work/formats.tl"
check "formats: the lens shift reported as left out" \
  grep -q "REPORT formats not carried over: camera 'Cam''s lens shift" "$work/blender.txt"
check "layered: NLA strips baked, saying so" grep -q '^# baked: camera.position (NLA strips animate it)' \
  "$work/layered.tl"
check "layered: a boat in an excluded collection is not exported" \
  sh -c "! grep -q '^path boat' '$work/layered.tl'"
"$tideline" check "$work/noise.tl" >"$work/check_noise.txt"
check "noise: check lists the baked channel" grep -q '^  baked     camera.position$' "$work/check_noise.txt"
check "noise: the .tl says why" grep -q '^# baked: camera.position (its F-curve has a noise modifier)' \
  "$work/noise.tl"
check "noise: Blender's report says so" \
  grep -q 'REPORT noise baked camera.position: its F-curve has a noise modifier' "$work/blender.txt"
"$tideline" check "$work/cut.tl" >"$work/check_cut.txt"
check "cut: the cameras' cut is a cut" grep -q '^  24f cut ' "$work/cut.tl"
check "cut: check lists what was baked" \
  grep -q '^  baked     camera.position, camera.rotation, camera.focal_length$' "$work/check_cut.txt"
# Refusals, in Blender's report and as a headless exit status.
check "no camera: refused, saying why" grep -q 'the scene has no active camera' "$work/no_camera.err"
check "a lamp as a boat: refused, saying why" \
  grep -q "object 'lamp' is a light: a boat is a mesh or an empty" "$work/lamp_boat.err"
# Headless on a .blend: the same file as from within Blender; without a
# camera, exit status 1, the error on stderr and no file.
blender -b "$work/keys.blend" --python "$repo/tools/blender/tideline_export.py" -- \
  "$work/headless_keys.tl" >"$work/headless_keys.txt" 2>&1 && status=0 || status=$?
check "headless: exit status 0 (got $status)" test "$status" = 0
check "headless: the same timeline as from within Blender" \
  cmp -s "$work/keys.tl" "$work/headless_keys.tl"
blender -b "$work/no_camera.blend" --python "$repo/tools/blender/tideline_export.py" -- \
  "$work/empty.tl" >"$work/headless.txt" 2>&1 && status=0 || status=$?
check "headless without a camera: exit status 1 (got $status)" test "$status" = 1
check "headless without a camera: the error on stderr" \
  grep -q 'tideline_export: error: the scene has no active camera' "$work/headless.txt"
check "headless without a camera: no file left" test ! -e "$work/empty.tl"
exit $fail
