#!/usr/bin/env bash
# A tmcert batch run as a Slurm job array: one array task per shard, then a
# merge job that writes the merged results when every shard succeeded and
# fails, naming the shards, when one did not (examples/batch/README.md).
#
#   examples/batch/slurm_array.sh REQUESTS.jsonl ENVIRONMENT.json OUT_DIR [SHARDS]
#
# submits both jobs from a login node and prints their ids.  OUT_DIR must be
# on a file system that every node sees; the merged results end up in
# OUT_DIR/results.jsonl, the same bytes as one unsharded
# `tmcert batch REQUESTS.jsonl --scene ENVIRONMENT.json`.
#
# Set TMCERT to the tmcert binary (default: tmcert on the PATH) and
# SBATCH_OPTIONS to site options (partition, account, time, CPUs per task:
# they come after this script's defaults, so they win), e.g.
#   SBATCH_OPTIONS="--partition=short --time=02:00:00 --cpus-per-task=4" examples/batch/slurm_array.sh ...
# Each shard runs with --threads $SLURM_CPUS_PER_TASK.
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
  # After every array task ended, however it ended (--dependency=afterany):
  # a shard that failed left no shard-<i>.jsonl, and then this job fails
  # at once, naming the shards, instead of the merge waiting for ever on a
  # dependency that can no longer be satisfied.
  shift
  out=$1 shards=$2
  tmcert=${TMCERT:-tmcert}
  files=() missing=()
  for ((i = 0; i < shards; i++)); do
    files+=("$out/shard-$i.jsonl")
    [ -f "$out/shard-$i.jsonl" ] || missing+=("$i")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "tmcert merge: shard(s) ${missing[*]} of $shards failed (see $out/shard-<i>.log); no results written" >&2
    exit 1
  fi
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
# --parsable prints "jobid" (or "jobid;cluster"): keep the id.  This
# script's defaults come first and SBATCH_OPTIONS after them: sbatch takes
# the last value of an option, so the site's options win.
# shellcheck disable=SC2086  # SBATCH_OPTIONS is a list of options
array_id=$(sbatch --parsable --job-name=tmcert-batch --array="0-$((shards - 1))%64" \
  --cpus-per-task=1 --output="$out/shard-%a.log" ${SBATCH_OPTIONS:-} \
  "$script" --task "$requests" "$environment" "$out")
array_id=${array_id%%;*}
# afterany on the array job id: the merge starts once every task of the
# array has ended, successfully or not, and checks for itself (above).
# (With afterok, a failed task would leave it pending for ever.)
# shellcheck disable=SC2086
merge_id=$(sbatch --parsable --job-name=tmcert-merge --dependency="afterany:$array_id" --kill-on-invalid-dep=yes \
  --cpus-per-task=1 --output="$out/merge.log" ${SBATCH_OPTIONS:-} "$script" --merge "$out" "$shards")
merge_id=${merge_id%%;*}
echo "shards: job array $array_id ($shards tasks); merge: job $merge_id -> $out/results.jsonl"
