#!/bin/bash
# Soak: render FRAMES tiny frames with --skip-existing while killing the
# process (SIGKILL and SIGTERM in turn) at random moments and restarting it
# until a run completes. The folder must then hold exactly the files of an
# uninterrupted run, byte for byte, and no temporary: a temporary a SIGKILL
# leaves is removed by the next run (a stale one is planted to be sure).
# The kill times come from a fixed seed (SOAK_SEED) so a failure reproduces.
# Usage: test_soak.sh TIDELINE [FRAMES]
set -u
tideline=$1
frames=${2:-400}
seed=${SOAK_SEED:-15}
max_kills=16 # then the last run goes uninterrupted, so the test always ends

work=$(mktemp -d /tmp/tideline-soak-XXXXXX)
trap 'rm -rf "$work"' EXIT
# calm.tl's turning camera, but a fixed sun: a moving sun rebuilds the sky's
# tables every frame, which would leave time for few kills.
timeline=$work/soak.tl
cat >"$timeline" <<'TL'
tideline 1
fps 24
duration 20s
set sun.elevation 5deg
set sun.azimuth -10deg
key camera.yaw linear
  0s   -35deg
  20s  -8deg
TL
fail() {
    echo "SOAK FAILED: $*"
    exit 1
}
args=(--frames "0-$((frames - 1))" --size 16x9 --quality draft)

start=$SECONDS
t0=$(date +%s%N)
"$tideline" render "$timeline" -o "$work/ref/f_####.png" "${args[@]}" -q 2>/dev/null ||
    fail "the uninterrupted reference run"
ref_ms=$((($(date +%s%N) - t0) / 1000000))
echo "reference: $frames frames in $ref_ms ms"

# A temporary as a SIGKILL mid-write leaves it (no writer holds it).
mkdir -p "$work/soak"
echo partial >"$work/soak/.f_0001.png.tmp-SOAK15"

RANDOM=$seed
echo "seed $seed"
kills=0
runs=0
while :; do
    runs=$((runs + 1))
    log="$work/run$runs.log"
    "$tideline" render "$timeline" -o "$work/soak/f_####.png" "${args[@]}" --skip-existing \
        2>"$log" &
    pid=$!
    if [ $kills -ge $max_kills ]; then
        wait $pid
        status=$?
        [ $status -eq 0 ] || fail "run $runs (uninterrupted) exited $status: $(tail -2 "$log")"
        break
    fi
    # Up to a third of the reference run (so a run rarely finishes before
    # several kills, however fast the machine): some kills land in start-up,
    # most between or inside frames (milliseconds each).
    delay_ms=$((100 + RANDOM % (ref_ms / 3 + 1)))
    signal=$([ $((kills % 2)) -eq 0 ] && echo KILL || echo TERM)
    waited=0
    while [ $waited -lt $delay_ms ] && kill -0 $pid 2>/dev/null; do
        sleep 0.05
        waited=$((waited + 50))
    done
    if kill -0 $pid 2>/dev/null; then
        kill -$signal $pid
        wait $pid 2>/dev/null # no job-control notice for the kill
        status=$?
        kills=$((kills + 1))
        files=$(ls "$work/soak" | wc -l)
        temps=$(ls -A "$work/soak" | grep -c '^\.' || true)
        echo "run $runs: SIG$signal at ${delay_ms} ms -> exit $status, $files frames," \
            "$temps temporaries"
        # SIGTERM: 130 once the handler is installed, 143 during start-up.
        # 0: the run finished its last frame between the check above and
        # the signal (only with every frame there); it ends the soak.
        case $signal:$status in
        KILL:137 | TERM:130 | TERM:143) ;;
        *:0)
            [ "$(ls "$work/soak" | wc -l)" -eq "$frames" ] ||
                fail "run $runs: SIG$signal gave exit status 0 with frames missing"
            echo "run $runs: finished as its kill was sent"
            break
            ;;
        *) fail "run $runs: SIG$signal gave exit status $status: $(tail -2 "$log")" ;;
        esac
    else
        wait $pid
        status=$?
        echo "run $runs: finished before its kill at ${delay_ms} ms -> exit $status"
        [ $status -eq 0 ] || fail "run $runs exited $status: $(tail -2 "$log")"
        break
    fi
done
removed=$(cat "$work"/run*.log | grep -c 'temporary file.* left by an interrupted run' || true)
echo "$runs runs, $kills kills, $removed runs removed stale temporaries, $((SECONDS - start)) s"

[ "$removed" -ge 1 ] || fail "the planted stale temporary was never reported removed"
leftover=$(ls -A "$work/soak" | grep '^\.' || true)
[ -z "$leftover" ] || fail "temporaries left: $leftover"
[ "$(ls "$work/soak")" = "$(ls "$work/ref")" ] || fail "the set of files differs from the reference"
[ "$(ls "$work/soak" | wc -l)" -eq "$frames" ] || fail "expected $frames files"
for f in "$work"/ref/*; do
    cmp -s "$f" "$work/soak/${f##*/}" || fail "${f##*/} differs from the uninterrupted run"
done
echo SOAK_OK
