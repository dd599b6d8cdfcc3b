#!/usr/bin/env bash
# A sharded sweep on a real, one-node Slurm cluster (docs/scale.md), from nothing to nothing:
# installs Debian's slurm-wlm and munge where missing, writes a one-node configuration for
# this host into a temporary directory, starts munged, slurmctld and slurmd from it (their own
# socket, key, ports, state, spool, logs and pid files, so that a system munged or Slurm is
# left alone), submits the sweep as a job array of `sweep --shard`, merges the shards, and
# checks that the merged files equal the unsharded sweep's in everything but the measured
# times and that a merge missing a shard is refused. Every wait is bounded; on any exit the
# job is cancelled, every daemon it started stopped and the directory removed. Runs as root
# (slurmd's user, as in CI's chroot; no systemd, and no /sys, needed).
#
# slurm-wlm and munge are installed here, not by scripts/setup.sh: on a machine with systemd
# their packages enable system services (munged starts at once) that only this test would
# want, and it uses none of them.
#
#   scripts/slurm_sweep_test.sh [SHADOWLAB]   SHADOWLAB: the command (default build/app/shadowlab)
#
# scripts/test.sh runs it (and CI); --no-cluster leaves it out.
set -euo pipefail
shadowlab=${1:+$(realpath -m "$1")}
cd "$(dirname "${BASH_SOURCE[0]}")/.."
shadowlab=${shadowlab:-$PWD/build/app/shadowlab}
blank_times=$PWD/tests/app/blank_times.py
[[ -x $shadowlab ]] || { echo "slurm_sweep_test: no $shadowlab (build it: scripts/setup.sh)" >&2; exit 2; }
[[ $(id -u) -eq 0 ]] || { echo "slurm_sweep_test: run it as root (slurmd's user)" >&2; exit 2; }
source scripts/install_missing.sh
install_missing slurm-wlm munge python3

# slurmd will not start without a cgroup file system it knows at /sys/fs/cgroup, though with
# proctrack/linuxproc and task/none it puts nothing there. Where the host has a cgroup v1
# hierarchy named systemd (a Debian VM with cgroup v1, as here) slurmd takes it as it is.
# Elsewhere (a chroot, which may have no cgroup mounted; a cgroup v2 host, where slurmd would
# want systemd, a scope for its steps) the rest runs in a mount namespace of its own, where
# /sys/fs/cgroup is a tmpfs holding only a named v1 hierarchy (nothing is put in it), all of it
# gone with the namespace. Its mounts are private, so that none reaches the host: the whole
# tree's where / is a mount point; in a chroot, whose root is none, /sys's, made private
# inside the namespace (and the chroot must have /sys mounted).
if [[ -z ${SHADOWLAB_SLURM_NAMESPACE:-} ]] && ! mountpoint -q /sys/fs/cgroup/systemd; then
  propagation=private
  mountpoint -q / || propagation=unchanged
  SHADOWLAB_SLURM_NAMESPACE=$propagation exec unshare --mount --propagation "$propagation" \
      "$PWD/scripts/slurm_sweep_test.sh" "$shadowlab"
fi
if [[ -n ${SHADOWLAB_SLURM_NAMESPACE:-} ]]; then
  if [[ $SHADOWLAB_SLURM_NAMESPACE == unchanged ]]; then
    mountpoint -q /sys || { echo "slurm_sweep_test: no cgroup file system for slurmd, and /sys is not mounted in this chroot: mount it (mount --bind /sys CHROOT/sys)" >&2; exit 1; }
    mount --make-rprivate /sys
  fi
  [[ -d /sys/fs/cgroup ]] || { mount -t tmpfs sysfs-stand-in /sys; mkdir -p /sys/fs/cgroup; }
  mount -t tmpfs cgroup-stand-in /sys/fs/cgroup
  mkdir /sys/fs/cgroup/systemd
  mount -t cgroup -o none,name=systemd cgroup /sys/fs/cgroup/systemd
fi

tmp=$(mktemp -d /tmp/shadowlab-slurm.XXXXXX)
chmod 0755 "$tmp"   # munged requires its socket's directories searchable by all
export SLURM_CONF=$tmp/slurm.conf
names=() pids=() logs=()   # the daemons started, in order
job=""             # the job array, once submitted
fail() { echo "slurm_sweep_test: $*" >&2; exit 1; }

# stop PID: SIGTERM, up to 10 s to exit, then SIGKILL.
stop() {
  local k
  kill "$1" 2>/dev/null || return 0
  for ((k = 0; k < 50; ++k)); do kill -0 "$1" 2>/dev/null || break; sleep 0.2; done
  kill -KILL "$1" 2>/dev/null || true
  wait "$1" 2>/dev/null || true
}
cleanup() {
  local status=$? k log
  trap - EXIT
  set +e; trap '' PIPE   # nothing may stop the cleaning up: a failing kill, a reader gone
  # The job's tasks first, while slurmctld and slurmd can end them: slurmstepd and the
  # tasks it runs outlive slurmd by design.
  if [[ -n $job ]] && ((${#pids[@]} == 3)); then
    scancel "$job" 2>/dev/null || true
    for ((k = 0; k < 60; ++k)); do
      [[ -z $(squeue -h -j "$job" 2>/dev/null) && -z $(compgen -G "$tmp/spool/${node}_*") ]] && break
      sleep 0.5
    done
  fi
  for ((k = ${#pids[@]} - 1; k >= 0; --k)); do stop "${pids[k]}"; done
  if ((status != 0)); then
    for log in "$tmp"/*.log "$tmp"/out/*.log; do
      [[ -s $log ]] && { echo "== $log, its last lines:"; tail -n 5 "$log"; }
    done >&2
  fi
  rm -rf "$tmp"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# start NAME LOG COMMAND...: a daemon in the foreground, in the background of this script.
start() {
  local name=$1 log=$2
  shift 2
  "$@" >> "$log" 2>&1 &
  names+=("$name") pids+=($!) logs+=("$log")
}
# wait_for WHAT SECONDS LOG COMMAND...: COMMAND every half second until it succeeds, while
# every daemon lives; a one-line error naming WHAT (or the daemon gone) and its log otherwise.
wait_for() {
  local what=$1 seconds=$2 log=$3 k d
  shift 3
  for ((k = 0; k < 2 * seconds; ++k)); do
    for d in "${!pids[@]}"; do
      kill -0 "${pids[d]}" 2>/dev/null || fail "${names[d]} exited while waiting for $what (log: ${logs[d]})"
    done
    "$@" > /dev/null 2>&1 && return 0
    sleep 0.5
  done
  fail "$what: not after $seconds s (log: $log)"
}

# ---- munge: its own key, socket, seed, log and pid file ------------------------------------
mungekey --create --keyfile="$tmp/munge.key"
start munged "$tmp/munged.log" munged --foreground --socket="$tmp/munge.socket" \
  --key-file="$tmp/munge.key" --seed-file="$tmp/munge.seed" --log-file="$tmp/munged.log" \
  --pid-file="$tmp/munged.pid"
wait_for "munged's credentials" 20 "$tmp/munged.log" \
  bash -c "munge -n -S '$tmp/munge.socket' | unmunge -S '$tmp/munge.socket'"

# ---- Slurm: one node, this host, two free ports --------------------------------------------
# The node is named as slurmd names this host (hostname -s) and reached at 127.0.0.1, so a
# host name that does not resolve (a chroot keeps the host's) does no harm.
node=$(hostname -s)
read -r ctld_port slurmd_port < <(python3 -c '
import socket
ports = [socket.socket() for _ in range(2)]
for p in ports: p.bind(("127.0.0.1", 0))
print(*(p.getsockname()[1] for p in ports))')
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/out"
cat > "$SLURM_CONF" << EOF
ClusterName=shadowlab-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MailProg=/bin/true
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=10 State=UP
EOF
start slurmctld "$tmp/slurmctld.log" slurmctld -D -i
wait_for "slurmctld's answer (scontrol ping)" 30 "$tmp/slurmctld.log" scontrol ping
start slurmd "$tmp/slurmd.log" slurmd -D -N "$node"
wait_for "node $node idle (sinfo)" 60 "$tmp/slurmd.log" \
  bash -c "[[ \$(sinfo -h -n '$node' -o %T) == idle ]]"

# ---- the sweep: 6 settings at 2 thread counts, as 3 array tasks, and whole -----------------
shards=3
grid=(sphere-box --technique shadow-map,pcss --param resolution=256,1024 --param slope-factor=0.5,1.5
      --width 160 --height 100 --threads 1,2 --runs 1 --warmup 0)
stem=sphere-box-shadow-map+pcss
# docs/commands.md's sweep.sbatch, small: each task one CPU, so that tasks run side by side.
cat > "$tmp/sweep.sbatch" << EOF
#!/bin/bash
#SBATCH --job-name=sweep
#SBATCH --array=1-$shards
#SBATCH --cpus-per-task=1
#SBATCH --time=5
#SBATCH --output=$tmp/out/slurm-%A_%a.log
$(printf '%q ' "$shadowlab" sweep "${grid[@]}" --out "$tmp/out/shards") \\
    --shard "\$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT"
EOF
job=$(sbatch --parsable --chdir="$tmp/out" "$tmp/sweep.sbatch")
echo "slurm_sweep_test: job array $job of $shards tasks on node $node"
wait_for "the end of job array $job" 240 "$tmp/out/slurm-${job}_*.log" \
  bash -c "[[ -z \$(squeue -h -j '$job') ]]"
for ((i = 1; i <= shards; ++i)); do
  log=$tmp/out/slurm-${job}_$i.log
  state=$(scontrol -o show job "${job}_$i" | grep -o 'JobState=[A-Z]*' || true)
  [[ $state == JobState=COMPLETED ]] || fail "task $i of job $job: $state (log: $log)"
  grep -qx "sphere-box, shard $i/$shards" "$log" || fail "task $i of job $job ran no shard $i/$shards (log: $log)"
done

"$shadowlab" merge-sweep "$tmp/out/shards/$stem-shard-"*"-of-$shards.json" --out "$tmp/out/merged" > /dev/null
"$shadowlab" sweep "${grid[@]}" --out "$tmp/out/whole" > /dev/null

# ---- the checks --------------------------------------------------------------------------
# Every row and figure the same, the times blanked (blank_times.py), and the rows all there.
for ext in csv json; do
  python3 "$blank_times" "$tmp/out/whole/$stem.$ext" > "$tmp/whole.$ext"
  python3 "$blank_times" "$tmp/out/merged/$stem.$ext" > "$tmp/merged.$ext"
  cmp -s "$tmp/whole.$ext" "$tmp/merged.$ext" ||
    fail "the merged $stem.$ext differs from the unsharded one's with the times blanked: $(diff "$tmp/whole.$ext" "$tmp/merged.$ext" | head -3 | tr '\n' ' ')"
done
rows=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["rows"]))' "$tmp/merged.json")
((rows == 6 * 2)) || fail "the merged sweep has $rows rows, not 6 settings x 2 thread counts"
# A merge missing a shard is refused, with a one-line error naming it.
if "$shadowlab" merge-sweep "$tmp/out/shards/$stem-shard-"{1,3}"-of-$shards.json" --out "$tmp/out/refused" \
    > /dev/null 2> "$tmp/refused.err"; then
  fail "merge-sweep joined shards 1 and 3 of 3"
fi
grep -q "missing shard(s) 2/$shards" "$tmp/refused.err" ||
  fail "merge-sweep without shard 2 said: $(cat "$tmp/refused.err")"
echo "slurm_sweep_test: passed: $shards Slurm array tasks merged equal the unsharded sweep ($rows rows, times aside); a missing shard refused"
