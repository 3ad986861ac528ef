#!/usr/bin/env bash
# Render a timeline on a Slurm cluster: one array task per chunk.
#
#   sbatch --array=0-15 examples/farm/slurm.sh timelines/calm.tl /shared/renders/calm
#
# Each task renders chunk $SLURM_ARRAY_TASK_ID of $SLURM_ARRAY_TASK_COUNT
# (array indices must start at 0). Frame times come from frame numbers only,
# so tasks may run on any node, in any order, and be re-queued: a re-run
# task skips the frames it already finished.
#SBATCH --job-name=tideline
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
#SBATCH --output=tideline-%A_%a.log
set -euo pipefail
timeline=${1:?usage: slurm.sh TIMELINE.tl OUTPUT_FOLDER}
out=${2:?usage: slurm.sh TIMELINE.tl OUTPUT_FOLDER}
tideline=${TIDELINE:-build/tideline}

exec "$tideline" render "$timeline" \
  -o "$out/$(basename "$timeline" .tl)_####.exr" \
  --chunk "${SLURM_ARRAY_TASK_ID}/${SLURM_ARRAY_TASK_COUNT}" \
  --skip-existing -q
