#!/usr/bin/env bash
# A sweep as a Slurm job array: each array task runs one shard (the cases whose index is its
# task index modulo the number of tasks) on the cores Slurm gave it, into its own directory.
#
#   mkdir -p sweep-out
#   jobid=$(sbatch --parsable examples/sweeps/slurm.sh)
#   sbatch --dependency=afterok:$jobid examples/sweeps/slurm-merge.sh
#
# SWEEP and OUT override the sweep file and the output directory (sbatch --export=ALL,...).
# The array must be contiguous (--array=0-15 or 1-16; a throttle like %4 is fine).
#SBATCH --job-name=vehicle-sweep
#SBATCH --array=0-7
#SBATCH --cpus-per-task=2
#SBATCH --time=00:20:00
#SBATCH --output=sweep-out/slurm-%A_%a.log
set -euo pipefail

SWEEP=${SWEEP:-examples/sweeps/brake.toml}
OUT=${OUT:-sweep-out}

# --shard auto reads SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN and SLURM_ARRAY_TASK_COUNT.
exec vehicle-sim sweep "$SWEEP" --shard auto --threads "${SLURM_CPUS_PER_TASK:-1}" \
  --out "$OUT/shard-$SLURM_ARRAY_TASK_ID" --quiet
