#!/bin/bash
# Render a glsroad sequence as a Slurm job array: every array task runs
# one glsplay that renders its shard of the frames (glsplay --shard slurm:
# frames F with (F - A) mod N = I, I and N from SLURM_ARRAY_TASK_ID and
# SLURM_ARRAY_TASK_COUNT) into the one shared output directory, so that
# when the array is done the directory holds the whole sequence, the same
# bytes as one glsplay would write.  Submit from the repository root after
# `make demo-road` (or set the variables below to your files), e.g. 16 tasks:
#
#   sbatch --array=0-15 docs/cluster/slurm.sh
#   sbatch --array=0-15 docs/cluster/slurm.sh --motion lead=out/road/road/motion/lead.txt
#
# Arguments are passed on to glsplay.  --resume makes a requeued or
# resubmitted task skip the frames it already finished; --progress json
# puts one JSON line per camera frame into the task's log.
#SBATCH --job-name=glscene
#SBATCH --cpus-per-task=2
#SBATCH --mem=4G
#SBATCH --output=glscene_%A_%a.log
set -euo pipefail

GLSPLAY=${GLSPLAY:-build/glsplay}
BUNDLE=${BUNDLE:-out/road/road.glsb}
TRAJECTORY=${TRAJECTORY:-out/road/road/trajectory.txt}
CAMERAS=${CAMERAS:-examples/road/rig/left.cam examples/road/rig/right.cam}
OUTDIR=${OUTDIR:-out/road_cluster}
FRAMES=${FRAMES:-} # A:B, or empty for every frame of the trajectory

cams=()
for c in $CAMERAS; do cams+=(--camera "$c"); done
frames=()
[ -n "$FRAMES" ] && frames=(--frames "$FRAMES")

echo "glscene: task ${SLURM_ARRAY_TASK_ID:-?} of ${SLURM_ARRAY_TASK_COUNT:-?} on $(hostname)" >&2
exec "$GLSPLAY" "$BUNDLE" "${cams[@]}" --trajectory "$TRAJECTORY" "${frames[@]}" \
    --shard slurm --resume --progress json -o "$OUTDIR" "$@"
