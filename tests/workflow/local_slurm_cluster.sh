#!/bin/bash
# A real single-node Slurm cluster on this machine, for the workflow's cluster test: munged,
# slurmctld and slurmd from Debian's munge and slurm-wlm, with every file (configuration,
# key, sockets, state, logs) under one folder. Without accounting: job states come from
# scontrol, and each finished job is written to the job-completion log DIR/jobs.log.
#   local_slurm_cluster.sh start DIR   # prints the SLURM_CONF to export; fails saying why
#   local_slurm_cluster.sh stop DIR
# Needs root (the daemons run as root, as do the jobs).
set -euo pipefail
action=$1
dir=$(realpath -m "$2")
fail() { echo "local Slurm cluster: $*" >&2; exit 1; }

stop() {
  for daemon in slurmd slurmctld munged; do
    [ -f "$dir/$daemon.pid" ] && kill "$(cat "$dir/$daemon.pid")" 2> /dev/null || true
  done
  sleep 1
}

write_config() {
  local node
  node=$(slurmd -C | head -n1) || fail "slurmd -C failed"
  node=${node/NodeName=* CPUs/NodeName=$(hostname -s) NodeAddr=127.0.0.1 CPUs}
  cat > "$dir/slurm.conf" << EOF
ClusterName=rice-test
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/slurmctld
SlurmdSpoolDir=$dir/slurmd
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobs.log
MinJobAge=3600
$node State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
}

start() {
  [ "$(id -u)" -eq 0 ] || fail "needs root"
  for tool in munged slurmctld slurmd sinfo sbatch scontrol; do
    command -v "$tool" > /dev/null || fail "$tool is not installed (Debian's munge and slurm-wlm)"
  done
  stop
  rm -rf "$dir"
  mkdir -p "$dir/slurmctld" "$dir/slurmd"
  write_config
  dd if=/dev/urandom of="$dir/munge.key" bs=128 count=1 status=none
  chmod 400 "$dir/munge.key"
  munged --force --key-file="$dir/munge.key" --socket="$dir/munge.socket" --pid-file="$dir/munged.pid" \
    --log-file="$dir/munged.log" --seed-file="$dir/munged.seed" || fail "munged did not start: $(cat "$dir/munged.log")"
  export SLURM_CONF=$dir/slurm.conf
  slurmctld || fail "slurmctld did not start: $(tail -n 5 "$dir/slurmctld.log")"
  slurmd || fail "slurmd did not start: $(tail -n 5 "$dir/slurmd.log")"
  for _ in $(seq 60); do
    if sinfo -h -o %t 2> /dev/null | grep -qx idle; then
      echo "$SLURM_CONF"
      return
    fi
    sleep 1
  done
  fail "the node is not idle after 60 s: $(sinfo 2>&1); slurmctld: $(tail -n 5 "$dir/slurmctld.log")"
}

case $action in
  start) start ;;
  stop) stop ;;
  *) fail "usage: local_slurm_cluster.sh start|stop DIR" ;;
esac
