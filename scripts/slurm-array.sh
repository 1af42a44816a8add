#!/usr/bin/env bash
# A study as a Slurm job array: each array task runs one shard, and a last job merges them.
#
#   sbatch --array=1-16 scripts/slurm-array.sh scripts/studies/bbob.ini studies/bbob
#   # when every task has finished (or submit it with --dependency=afterok:<array job id>):
#   bash scripts/slurm-array.sh --merge 16 studies/bbob
#
# Each task writes studies/bbob.shards/<i>/ and resumes it if the task is requeued (the same
# command completes an interrupted shard). The split is deterministic and balanced by estimated
# cost, so tasks may run on different machines in any order; the merged directory holds the
# records one process would have written, byte for byte. Outside Slurm, SLURM_ARRAY_TASK_ID and
# SLURM_ARRAY_TASK_COUNT can be set by hand to run a shard.
#SBATCH --job-name=mhbench
#SBATCH --cpus-per-task=8
#SBATCH --time=04:00:00
#SBATCH --output=mhbench-%A_%a.log
set -euo pipefail
mhbench="${MHBENCH:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build/release/runner/mhbench}"

if [ "${1:-}" = "--merge" ]; then
    count="${2:?usage: slurm-array.sh --merge N OUT}"
    out="${3:?usage: slurm-array.sh --merge N OUT}"
    shards=()
    for i in $(seq 1 "$count"); do shards+=("$out.shards/$i"); done
    exec "$mhbench" merge "$out" "${shards[@]}"
fi

study_file="${1:?usage: sbatch --array=1-N slurm-array.sh STUDY_FILE OUT}"
out="${2:?usage: sbatch --array=1-N slurm-array.sh STUDY_FILE OUT}"
index="${SLURM_ARRAY_TASK_ID:?not an array task: run with sbatch --array=1-N, or set SLURM_ARRAY_TASK_ID}"
count="${SLURM_ARRAY_TASK_COUNT:?not an array task: set SLURM_ARRAY_TASK_COUNT}"
# Progress goes to the task's log as a plain line every 60 s.
threads=()
[ -n "${SLURM_CPUS_PER_TASK:-}" ] && threads=(--threads "$SLURM_CPUS_PER_TASK")
exec "$mhbench" run --study-file "$study_file" --shard "$index/$count" --out "$out.shards/$index" \
    "${threads[@]}" --progress-interval 60
