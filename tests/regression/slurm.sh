#!/usr/bin/env bash
# examples/batch/slurm_array.sh on a real Slurm: starts a single-node
# cluster on this machine (Debian slurm-wlm and munge: munged, slurmctld and
# slurmd as root, everything under a temporary folder, on free local ports),
# then
#   1. submits the example's array job in 3 shards, waits for the merge job
#      and compares its results.jsonl byte for byte with an unsharded run;
#   2. passes an option through SBATCH_OPTIONS (--cpus-per-task=2 wins over
#      the script's default: the array job has 2 CPUs per task and its
#      shards run with --threads 2);
#   3. makes one shard fail (exit 4): the merge job must end (fail, naming
#      the shard) and write no results, never wait for ever.
# Stops the daemons it started (by their process ids) at the end.
#
#   tests/regression/slurm.sh TMCERT_BINARY SOURCE_DIR
#
# Exits 77 (skipped, with a message) when it cannot start a cluster: not
# root, Slurm or munge not installed (bash scripts/deps.sh installs them),
# or the daemons do not come up.  About 30 s.
set -uo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 TMCERT_BINARY SOURCE_DIR" >&2
  exit 2
fi
tmcert=$(realpath "$1")
src=$(realpath "$2")
skip() {
  echo "skipped: $*"
  exit 77
}
[ "$(id -u)" -eq 0 ] || skip "starting slurmctld, slurmd and munged needs root"
for tool in munged slurmctld slurmd sbatch squeue scontrol sinfo; do
  command -v "$tool" >/dev/null 2>&1 || skip "$tool is not installed (Debian slurm-wlm, munge: bash scripts/deps.sh)"
done

work=$(mktemp -d /tmp/tmcert-slurm.XXXXXX)
chmod 755 "$work"
pids=()
cleanup() {
  if [ -n "${SLURM_CONF:-}" ]; then scancel --quiet --user=root >/dev/null 2>&1 || true; fi
  local pid
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  done
  rm -rf "$work"
}
trap cleanup EXIT

passed=0
failed=0
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }
ok() { passed=$((passed + 1)); }

# ---------------------------------------------------------------- the cluster
free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
ctld_port=$(free_port)
slurmd_port=$(free_port)
host=$(hostname -s)
cpus=$(nproc)
mkdir -p "$work/state" "$work/spool" "$work/munge"
chmod 700 "$work/munge"
head -c 1024 /dev/urandom >"$work/munge/munge.key"
chmod 400 "$work/munge/munge.key"
socket="$work/munge/munge.socket"
munged --force --key-file="$work/munge/munge.key" --socket="$socket" --pid-file="$work/munge/munged.pid" \
  --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" >"$work/munged.out" 2>&1 ||
  skip "munged does not start: $(tail -3 "$work/munged.out" "$work/munge/munged.log" 2>/dev/null | tr '\n' ' ')"
pids+=("$(cat "$work/munge/munged.pid")")

export SLURM_CONF="$work/slurm.conf"
cat >"$SLURM_CONF" <<EOF
ClusterName=tmcerttest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
NodeName=tmcertnode NodeAddr=127.0.0.1 NodeHostname=$host CPUs=$cpus State=UNKNOWN
PartitionName=tmcert Nodes=tmcertnode Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -i >"$work/slurmctld.out" 2>&1 &
pids+=("$!")
slurmd -D -N tmcertnode >"$work/slurmd.out" 2>&1 &
pids+=("$!")
up=""
for _ in $(seq 60); do
  state=$(sinfo -h -n tmcertnode -o '%t' 2>/dev/null || true)
  case "$state" in idle*) up=1; break ;; esac
  sleep 0.5
done
if [ -z "$up" ]; then
  skip "the cluster does not come up (node state '${state:-none}'): $(tail -3 "$work/slurmctld.log" "$work/slurmd.log" 2>/dev/null | tr '\n' ' ')"
fi

# Waits until job $1 has ended (at most $2 seconds); prints its final state.
job_state() { scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -1; }
wait_job() {
  local id=$1 limit=$2 state=""
  for _ in $(seq $((limit * 2))); do
    state=$(job_state "$id")
    case "$state" in
      COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE | PREEMPTED)
        echo "$state"
        return 0
        ;;
    esac
    sleep 0.5
  done
  echo "${state:-UNKNOWN} (still after ${limit} s)"
  return 1
}
# The job ids slurm_array.sh printed: "shards: job array A (...); merge: job M -> ...".
submit() {  # submit OUT_DIR SHARDS [VAR=VALUE...]: runs slurm_array.sh, sets array_id and merge_id
  local out=$1 shards=$2 line
  shift 2
  line=$(env "$@" bash "$src/examples/batch/slurm_array.sh" "$src/examples/batch/requests.jsonl" \
    "$src/examples/batch/environment.json" "$out" "$shards" 2>"$work/submit.err")
  array_id=$(sed -n 's/^shards: job array \([0-9]*\) .*/\1/p' <<<"$line")
  merge_id=$(sed -n 's/.*merge: job \([0-9]*\) .*/\1/p' <<<"$line")
  if [ -z "$array_id" ] || [ -z "$merge_id" ]; then
    fail "slurm_array.sh did not submit: $line $(cat "$work/submit.err")"
    return 1
  fi
}

# The unsharded run, for comparison.
"$tmcert" batch "$src/examples/batch/requests.jsonl" --scene "$src/examples/batch/environment.json" \
  -o "$work/unsharded.jsonl" 2>/dev/null
[ -s "$work/unsharded.jsonl" ] || fail "the unsharded batch run wrote nothing"

# ---------------------------------------------------------------- 1 and 2
if submit "$work/out" 3 TMCERT="$tmcert" SBATCH_OPTIONS="--cpus-per-task=2"; then
  cpus_per_task=$(scontrol show job "$array_id" 2>/dev/null | sed -n 's/.*CPUs\/Task=\([0-9]*\).*/\1/p' | head -1)
  state=$(wait_job "$merge_id" 120)
  if [ "$state" != COMPLETED ]; then
    fail "merge job $merge_id: $state; $(cat "$work/out/merge.log" "$work/out"/shard-*.log 2>/dev/null | tail -5 | tr '\n' ' ')"
  elif ! cmp -s "$work/out/results.jsonl" "$work/unsharded.jsonl"; then
    fail "the merged results differ from the unsharded run"
    diff "$work/unsharded.jsonl" "$work/out/results.jsonl" | head -5
  else
    ok
  fi
  # SBATCH_OPTIONS comes after the script's --cpus-per-task=1: it wins, and
  # the shards run with --threads 2 ($SLURM_CPUS_PER_TASK).
  if [ "$cpus_per_task" = 2 ]; then ok; else fail "SBATCH_OPTIONS=--cpus-per-task=2: the array job has CPUs/Task=${cpus_per_task:-?}"; fi
fi

# ---------------------------------------------------------------- 3
# A tmcert that fails (exit 4, as when out of memory) for shard 1 only.
cat >"$work/flaky-tmcert" <<EOF
#!/usr/bin/env bash
for arg in "\$@"; do
  if [ "\$arg" = "1/3" ]; then echo "tmcert: out of memory" >&2; exit 4; fi
done
exec "$tmcert" "\$@"
EOF
chmod 755 "$work/flaky-tmcert"
if submit "$work/out-failed" 3 TMCERT="$work/flaky-tmcert"; then
  if state=$(wait_job "$merge_id" 120); then
    if [ -e "$work/out-failed/results.jsonl" ]; then
      fail "a shard failed, yet the merge wrote results.jsonl"
    elif [ "$state" = COMPLETED ]; then
      fail "a shard failed, yet the merge job completed"
    elif ! grep -q "shard(s) 1 of 3 failed" "$work/out-failed/merge.log" 2>/dev/null && [ "$state" != CANCELLED ]; then
      fail "merge job $merge_id ended $state without naming the failed shard: $(cat "$work/out-failed/merge.log" 2>/dev/null)"
    else
      ok
    fi
  else
    fail "a shard failed and the merge job $merge_id is still waiting: $state"
  fi
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
