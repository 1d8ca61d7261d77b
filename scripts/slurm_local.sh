#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, for testing the sweep's Slurm path
# for real (docs/user/slurm.md): Debian's slurm-wlm and munge,
# run as root without systemd, all state under DIR.
#
#   scripts/slurm_local.sh start DIR    install (if needed), configure, start; prints SLURM_CONF
#   scripts/slurm_local.sh stop DIR     stop the daemons started from DIR
#
# Clients need SLURM_CONF=DIR/slurm.conf in their environment.
set -euo pipefail
cmd="${1:-}"
dir="$(mkdir -p "${2:?usage: slurm_local.sh start|stop DIR}" && cd "$2" && pwd)"
conf="$dir/slurm.conf"

stop() {
  for pidfile in "$dir/run/slurmd.pid" "$dir/run/slurmctld.pid" /run/munge/munged.pid; do
    [ -f "$pidfile" ] || continue
    pid="$(cat "$pidfile")"
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  done
}

case "$cmd" in
  start)
    [ "$(id -u)" -eq 0 ] || { echo "slurm_local.sh: needs root (the daemons run as root)" >&2; exit 2; }
    if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
      DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge >/dev/null
    fi
    host="$(hostname -s)"
    mkdir -p "$dir/state" "$dir/spool" "$dir/run" "$dir/log"
    cat >"$conf" <<CONF
ClusterName=icedem
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CryptoType=crypto/munge
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$conf"
    install -d -o munge -g munge -m 755 /run/munge
    [ -f /run/munge/munged.pid ] && kill -0 "$(cat /run/munge/munged.pid)" 2>/dev/null || runuser -u munge -- /usr/sbin/munged
    /usr/sbin/slurmctld -f "$conf"
    /usr/sbin/slurmd -f "$conf"
    for _ in $(seq 100); do
      [ "$(sinfo -h -o %t 2>/dev/null | head -1)" = "idle" ] && { echo "SLURM_CONF=$conf"; exit 0; }
      sleep 0.2
    done
    echo "slurm_local.sh: the node did not become idle in 20 s; logs in $dir/log" >&2
    stop
    exit 1
    ;;
  stop) stop ;;
  *) echo "usage: slurm_local.sh start|stop DIR" >&2; exit 2 ;;
esac
