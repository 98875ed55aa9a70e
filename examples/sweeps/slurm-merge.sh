#!/usr/bin/env bash
# Merges the shards of examples/sweeps/slurm.sh into $OUT/merged/results.csv, in case order,
# after checking that every shard finished and belongs to the same sweep. Submit it with
# --dependency=afterok:<the array's job id>.
#SBATCH --job-name=vehicle-sweep-merge
#SBATCH --cpus-per-task=1
#SBATCH --time=00:10:00
#SBATCH --output=sweep-out/slurm-merge-%j.log
set -euo pipefail

OUT=${OUT:-sweep-out}
exec vehicle-sim sweep-merge "$OUT"/shard-* --out "$OUT/merged"
