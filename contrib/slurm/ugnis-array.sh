#!/usr/bin/env bash
# Render one flame on a SLURM cluster: each array task renders one part of the samples, and a
# job that depends on the array merges them (ugnis sums the histograms exactly, then runs
# density estimation and tone mapping once).
#
#   jid=$(sbatch --parsable --array=0-7 contrib/slurm/ugnis-array.sh)
#   sbatch --dependency=afterok:$jid contrib/slurm/ugnis-array.sh merge
#
# Settings come from the environment (sbatch passes it on): FLAME, OUT, SIZE, QUALITY, SEED,
# UGNIS. PARTS defaults to the array size; the output directory must be on a shared file
# system. A part that fails can be run again alone (sbatch --array=5 …): parts do not depend on
# each other, and each is written atomically.
#SBATCH --job-name=ugnis-poster
#SBATCH --cpus-per-task=4
#SBATCH --mem=4G
#SBATCH --output=ugnis-%A_%a.log
set -euo pipefail

UGNIS=${UGNIS:-ugnis}
FLAME=${FLAME:-poster.flame}
OUT=${OUT:-ugnis-out}
SIZE=${SIZE:-20000x15000}
QUALITY=${QUALITY:-2000}
SEED=${SEED:-1}
PARTS=${PARTS:-${SLURM_ARRAY_TASK_COUNT:-8}}
mkdir -p "$OUT"

if [ "${1:-}" = merge ]; then
  # The final step: every part must be there (a missing one is an error, not a dim picture).
  n=$(find "$OUT" -maxdepth 1 -name 'part-*.ugnis-state' | wc -l)
  if [ "$n" -ne "$PARTS" ]; then
    echo "ugnis-array: $n of $PARTS parts in $OUT; not merging" >&2
    exit 1
  fi
  exec "$UGNIS" merge "$OUT"/part-*.ugnis-state -o "$OUT/poster.png" --progress plain
fi

i=${SLURM_ARRAY_TASK_ID:?run as a SLURM array job (sbatch --array=0-N), or set SLURM_ARRAY_TASK_ID}
exec "$UGNIS" render "$FLAME" --size "$SIZE" --quality "$QUALITY" --seed "$SEED" \
  --threads "${SLURM_CPUS_PER_TASK:-0}" --part "$i/$PARTS" \
  --save-state "$OUT/part-$i.ugnis-state" --progress plain
