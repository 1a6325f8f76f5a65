#!/bin/bash
# One task of a Slurm job array grading one submission on a large scene suite: task K of N
# grades shard K of N of the scenes (`fosssim-oracle grade --shard K/N`, a deterministic round
# robin over the sorted scene names), and writes $KIT_SHARD_DIR/shard-K.json. When every task
# has finished, one command writes the report of the whole suite:
#   fosssim-oracle merge "$KIT_SHARD_DIR"/shard-*.json --gradescope results.json --junit junit.xml
# Submit with, for example (the submission and the output folder in the environment):
#   KIT_SUBMISSION=/path/to/submission KIT_SHARD_DIR=/path/to/shards \
#     sbatch --array=1-8 --export=ALL autograder/slurm-grade.sh
# K and N come from Slurm's environment: K = SLURM_ARRAY_TASK_ID - SLURM_ARRAY_TASK_MIN + 1 (so
# --array=0-7 works too), N = SLURM_ARRAY_TASK_COUNT. The array's ids must be consecutive (no
# step, no list with gaps). Measure the time-outs once before submitting (run_autograder
# --measure) so that the tasks share one $KIT_TIMEOUTS_FILE; every other setting is
# run_autograder's (docs/autograder.md).
#SBATCH --job-name=fosssim-grade
#SBATCH --cpus-per-task=2
#SBATCH --time=02:00:00
set -eu
: "${SLURM_ARRAY_TASK_ID:?not in a Slurm job array}"
: "${SLURM_ARRAY_TASK_COUNT:?not in a Slurm job array}"
: "${KIT_SHARD_DIR:?set KIT_SHARD_DIR, the folder for the shard results}"
first=${SLURM_ARRAY_TASK_MIN:-1}
shard=$((SLURM_ARRAY_TASK_ID - first + 1))
count=$SLURM_ARRAY_TASK_COUNT
if [ "$shard" -lt 1 ] || [ "$shard" -gt "$count" ]; then
  echo "slurm-grade.sh: task $SLURM_ARRAY_TASK_ID is not in 1..$count counted from $first" >&2
  exit 2
fi
# Under sbatch the script runs from a copy in Slurm's spool: find the kit by SLURM_SUBMIT_DIR or
# KIT_DIR, not by this file's folder.
kit=${KIT_DIR:-$(cd "$(dirname "$0")" && pwd)}
[ -x "$kit/run_autograder" ] || kit=${SLURM_SUBMIT_DIR:-.}/autograder
mkdir -p "$KIT_SHARD_DIR"
KIT_SHARD=$shard/$count KIT_SHARD_RESULT=$KIT_SHARD_DIR/shard-$shard.json exec "$kit/run_autograder"
