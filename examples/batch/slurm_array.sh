#!/usr/bin/env bash
# A tmcert batch run as a Slurm job array: one array task per shard, then a
# merge job that runs only when every shard succeeded (examples/batch/README.md).
#
#   examples/batch/slurm_array.sh REQUESTS.jsonl ENVIRONMENT.json OUT_DIR [SHARDS]
#
# submits both jobs from a login node and prints their ids.  OUT_DIR must be
# on a file system that every node sees; the merged results end up in
# OUT_DIR/results.jsonl, the same bytes as one unsharded
# `tmcert batch REQUESTS.jsonl --scene ENVIRONMENT.json`.
#
# Set TMCERT to the tmcert binary (default: tmcert on the PATH) and
# SBATCH_OPTIONS to site options (partition, account, time), e.g.
#   SBATCH_OPTIONS="--partition=short --time=02:00:00" examples/batch/slurm_array.sh ...
set -euo pipefail

if [ "${1:-}" = "--task" ]; then
  # One array task: shard $SLURM_ARRAY_TASK_ID of $SLURM_ARRAY_TASK_COUNT.
  # Slurm numbers this array's tasks 0..SHARDS-1 (--array=0-(SHARDS-1)).
  shift
  requests=$1 environment=$2 out=$3
  tmcert=${TMCERT:-tmcert}
  shard="$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT"
  part="$out/shard-$SLURM_ARRAY_TASK_ID.jsonl"
  # Results go to a temporary name and are renamed only when the shard ran
  # to its end, so the merge never sees a partial file.  Exit codes 0, 1
  # and 2 are verdicts (all safe, a collision, an undecided or bad line),
  # not failures of the task; 3 (bad environment or options) and 4
  # (internal error, out of memory) fail it, and then the merge does not run.
  rc=0
  "$tmcert" batch "$requests" --scene "$environment" --shard "$shard" \
    --threads "${SLURM_CPUS_PER_TASK:-1}" -o "$part.tmp" || rc=$?
  case $rc in
    0 | 1 | 2) mv -f "$part.tmp" "$part" ;;
    *) echo "tmcert batch shard $shard failed with exit code $rc" >&2; exit "$rc" ;;
  esac
  exit 0
fi

if [ "${1:-}" = "--merge" ]; then
  # After every array task succeeded (--dependency=afterok).
  shift
  out=$1 shards=$2
  tmcert=${TMCERT:-tmcert}
  files=()
  for ((i = 0; i < shards; i++)); do files+=("$out/shard-$i.jsonl"); done
  "$tmcert" batch-merge "${files[@]}" -o "$out/results.jsonl"
  exit 0
fi

if [ $# -lt 3 ] || [ $# -gt 4 ]; then
  echo "usage: $0 REQUESTS.jsonl ENVIRONMENT.json OUT_DIR [SHARDS (default 16)]" >&2
  exit 2
fi
requests=$(realpath "$1")
environment=$(realpath "$2")
mkdir -p "$3"
out=$(realpath "$3")
shards=${4:-16}
script=$(realpath "$0")
# The array: task ids 0..shards-1; %64 caps the tasks running at once.
# --parsable prints "jobid" (or "jobid;cluster"): keep the id.
array_id=$(sbatch --parsable ${SBATCH_OPTIONS:-} --job-name=tmcert-batch --array="0-$((shards - 1))%64" \
  --cpus-per-task=1 --output="$out/shard-%a.log" \
  "$script" --task "$requests" "$environment" "$out")
array_id=${array_id%%;*}
# afterok on the array job id waits for every task of the array to end
# with exit code 0.
merge_id=$(sbatch --parsable ${SBATCH_OPTIONS:-} --job-name=tmcert-merge --dependency="afterok:$array_id" \
  --output="$out/merge.log" "$script" --merge "$out" "$shards")
merge_id=${merge_id%%;*}
echo "shards: job array $array_id ($shards tasks); merge: job $merge_id -> $out/results.jsonl"
