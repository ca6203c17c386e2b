#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for tests and trying the Slurm path of `parksim
# sweep` (docs/sweeps.md). Needs root and the Debian packages slurm-wlm and munge
# (scripts/install-deps.sh installs them).
#
#   scripts/slurm-local.sh start STATE_DIR   # munged (unless one runs), slurmctld, slurmd
#   export SLURM_CONF=STATE_DIR/slurm.conf   # then sbatch, squeue, sinfo talk to it
#   scripts/slurm-local.sh stop STATE_DIR    # stops only what `start` started
#
# The configuration lives in STATE_DIR (scratch): ProctrackType=proctrack/linuxproc and
# TaskPlugin=task/none (no cgroups), one node with this machine's CPUs and memory as `slurmd -C`
# reports them, on 127.0.0.1 and ports 16817/16818 (clear of a real Slurm's 6817/6818).
# Every wait is bounded; a failed start stops what it had started.
set -euo pipefail

usage() { echo "usage: $0 start|stop STATE_DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action=$1
state=$(realpath -m "$2")

stop_pidfile() {  # stop_pidfile NAME FILE: TERM, then KILL after 10 s
  local name=$1 file=$2 pid
  [ -s "$file" ] || return 0
  pid=$(cat "$file")
  if kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    if kill -0 "$pid" 2>/dev/null; then
      echo "slurm-local: $name ($pid) ignored TERM; killing it" >&2
      kill -KILL "$pid" 2>/dev/null || true
    fi
  fi
  rm -f "$file"
}

stop() {
  stop_pidfile slurmd "$state/slurmd.pid"
  stop_pidfile slurmctld "$state/slurmctld.pid"
  # munged only if this script started it (its pid was recorded then).
  stop_pidfile munged "$state/munged.started.pid"
}

munge_ok() { munge -n 2>/dev/null | unmunge >/dev/null 2>&1; }

start() {
  if [ "$(id -u)" -ne 0 ]; then echo "slurm-local: needs root" >&2; exit 1; fi
  for p in munged munge unmunge slurmctld slurmd sbatch sinfo; do
    command -v "$p" >/dev/null || { echo "slurm-local: $p not found (scripts/install-deps.sh)" >&2; exit 1; }
  done
  mkdir -p "$state/spool" "$state/state" "$state/log"
  trap 'echo "slurm-local: start failed; stopping what was started" >&2; stop' ERR

  if ! munge_ok; then
    if [ ! -s /etc/munge/munge.key ]; then
      mkdir -p /etc/munge
      dd if=/dev/urandom of=/etc/munge/munge.key bs=1024 count=1 status=none
      chown munge:munge /etc/munge/munge.key
      chmod 400 /etc/munge/munge.key
    fi
    mkdir -p /run/munge /var/log/munge /var/lib/munge
    chown munge:munge /run/munge /var/log/munge /var/lib/munge
    runuser -u munge -- /usr/sbin/munged
    for _ in $(seq 100); do [ -s /run/munge/munged.pid ] && munge_ok && break; sleep 0.1; done
    munge_ok || { echo "slurm-local: munged did not come up" >&2; false; }
    cp /run/munge/munged.pid "$state/munged.started.pid"
  fi

  local host node
  host=$(hostname -s)
  # slurmd -C: this machine as Slurm sees it (CPUs, sockets, cores, threads, memory).
  node=$(slurmd -C | head -n 1)
  # MinJobAge=4: `sbatch --wait` polls after 2 s, then after 8 and 32 more unless MinJobAge is
  # under 5 (it must not sleep past a finished job's purge), so a 3-s job waited 10 s; with 4 it
  # polls every 2 s. Finished jobs leave squeue after 4 s instead of 300.
  # batch_sched_delay=0: an array task waited up to 3 s for a CPU another task had freed.
  cat > "$state/slurm.conf" <<CONF
ClusterName=parksim-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
AuthType=auth/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$state/state
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
InactiveLimit=0
KillWait=5
MinJobAge=4
SchedulerParameters=batch_sched_delay=0
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF=$state/slurm.conf
  slurmctld -c
  for _ in $(seq 100); do [ -s "$state/slurmctld.pid" ] && scontrol ping >/dev/null 2>&1 && break; sleep 0.1; done
  slurmd
  local up=""
  for _ in $(seq 300); do
    if sinfo -h -o %T 2>/dev/null | grep -qx idle; then up=1; break; fi
    sleep 0.1
  done
  if [ -z "$up" ]; then
    echo "slurm-local: the node did not become idle in 30 s; logs in $state/log" >&2
    false
  fi
  trap - ERR
  echo "slurm-local: one-node cluster up ($host, $(nproc) CPUs); export SLURM_CONF=$state/slurm.conf"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  *) usage ;;
esac
