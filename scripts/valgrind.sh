#!/usr/bin/env bash
# Runs a headless still (the giant wave and the boat) and a 3-frame render
# under valgrind's memcheck: no memory errors and no definite leak may be
# reported. The GL driver's own reports are suppressed
# (tests/sanitizers/valgrind.supp, each entry explained). Tiny frames and
# the draft preset: llvmpipe under valgrind is slow (1 to 2 minutes on 2 cores,
# the two runs side by side). Logs and output in build/valgrind/. Needs
# build/ (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || {
  echo "valgrind: not installed (Debian package 'valgrind')" >&2
  exit 1
}
# Mesa's on-disk shader cache compresses (zstd) blobs that hold
# uninitialised padding, which memcheck reports inside the driver whenever a
# program is compiled that the cache has not seen yet. It is Mesa's cache,
# not tideline's memory: keep it out of these runs (they compile every
# program fresh, the same on every machine).
export MESA_SHADER_CACHE_DISABLE=true
out=build/valgrind
rm -rf "$out" && mkdir -p "$out"
vg=(valgrind --tool=memcheck --error-exitcode=99 --keep-debuginfo=yes --num-callers=40
  --leak-check=full --show-leak-kinds=definite --errors-for-leak-kinds=definite
  --suppressions=tests/sanitizers/valgrind.supp)

"${vg[@]}" --log-file="$out/still.log" build/tideline still timelines/giant_wave.tl \
  --time 10.5s --size 32x18 --quality draft -o "$out/still.png" -o "$out/still.exr" >"$out/still.out" 2>&1 &
still=$!
"${vg[@]}" --log-file="$out/render.log" build/tideline render timelines/calm.tl \
  --frames 0-2 --size 32x18 --quality draft -q -o "$out/render_####.png" >"$out/render.out" 2>&1 &
render=$!

status=0
for job in "still:$still" "render:$render"; do
  name=${job%%:*}
  if wait "${job#*:}"; then
    echo "valgrind: $name clean ($(grep -o 'ERROR SUMMARY: .*' "$out/$name.log"))"
  else
    cat "$out/$name.out" "$out/$name.log"
    echo "valgrind: $name reported errors (log above, also in $out/$name.log)"
    status=1
  fi
done
test -s "$out/still.png" && test -s "$out/still.exr" && test -s "$out/render_0002.png"
exit $status
