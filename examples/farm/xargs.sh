#!/usr/bin/env bash
# Render a timeline on one machine with N parallel processes, no scheduler:
#
#   examples/farm/xargs.sh timelines/calm.tl out/calm 4 [extra tideline render flags]
#
# Each process renders one chunk; re-running the script resumes (complete
# frames are skipped). The exit status is non-zero if any chunk failed.
set -euo pipefail
usage="usage: xargs.sh TIMELINE.tl OUTPUT_FOLDER [PROCESSES] [FLAGS...]"
timeline=${1:?$usage}
out=${2:?$usage}
jobs=${3:-$(nproc)}
shift $(($# < 3 ? $# : 3))
tideline=${TIDELINE:-build/tideline}
name=$(basename "$timeline" .tl)

seq 0 $((jobs - 1)) | xargs -P "$jobs" -I{} \
  "$tideline" render "$timeline" -o "$out/${name}_####.exr" --chunk "{}/$jobs" \
  --skip-existing -q "$@"
