#!/usr/bin/env bash
# A one-node Slurm cluster on localhost from Debian's slurm-wlm and munge, every
# key, socket, state, spool, log and pid file in one folder; sourced by
# tests/slurm_cluster.sh and experiments/slurm/scaling.sh. Needs root (slurmd
# runs the jobs as their user). Ports 26817/26818 are not Slurm's defaults, so a
# real cluster on the machine is left alone.
#   cluster_start DIR   starts munged, slurmctld, slurmd; exports SLURM_CONF
#   cluster_stop        stops every daemon cluster_start started, by pid
#   job_state ID        the state of a job (an array: every task's state)
#   wait_jobs SECONDS ID...   waits until none of the jobs is pending or running

FS_CLUSTER_PIDS=()

cluster_conf() { # DIR HOST CPUS
  cat <<EOF
ClusterName=fluidsurf
SlurmctldHost=$2(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$1/munge.sock
SlurmctldPort=${FS_SLURM_PORT:-26817}
SlurmdPort=$(( ${FS_SLURM_PORT:-26817} + 1 ))
StateSaveLocation=$1/state
SlurmdSpoolDir=$1/spool
SlurmctldPidFile=$1/slurmctld.pid
SlurmdPidFile=$1/slurmd.pid
SlurmctldLogFile=$1/slurmctld.log
SlurmdLogFile=$1/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
MinJobAge=600
NodeName=$2 NodeAddr=127.0.0.1 CPUs=$3 State=UNKNOWN
PartitionName=main Nodes=$2 Default=YES MaxTime=INFINITE State=UP
EOF
}

cluster_start() {
  local d=$1 host cpus i
  host=$(hostname -s) cpus=$(nproc)
  mkdir -p "$d/state" "$d/spool" && chmod 700 "$d" || return 1
  head -c 1024 /dev/urandom > "$d/munge.key" && chmod 400 "$d/munge.key"
  munged -F --force --key-file="$d/munge.key" --socket="$d/munge.sock" --pid-file="$d/munged.pid" \
         --log-file="$d/munged.log" --seed-file="$d/munged.seed" > "$d/munged.out" 2>&1 &
  FS_CLUSTER_PIDS+=($!)
  for i in $(seq 50); do [ -S "$d/munge.sock" ] && break; sleep 0.1; done
  [ -S "$d/munge.sock" ] || { echo "local_cluster: munged did not start ($d/munged.log)" >&2; return 1; }
  cluster_conf "$d" "$host" "$cpus" > "$d/slurm.conf"
  export SLURM_CONF=$d/slurm.conf
  slurmctld -D -i -f "$SLURM_CONF" > "$d/slurmctld.out" 2>&1 &
  FS_CLUSTER_PIDS+=($!)
  slurmd -D -f "$SLURM_CONF" > "$d/slurmd.out" 2>&1 &
  FS_CLUSTER_PIDS+=($!)
  for i in $(seq 300); do
    sinfo -h -N -o %t 2>/dev/null | grep -qx 'idle' && return 0
    sleep 0.1
  done
  echo "local_cluster: the node did not come up in 30 s ($d/slurmctld.log, $d/slurmd.log)" >&2
  return 1
}

cluster_stop() {
  local p i
  [ ${#FS_CLUSTER_PIDS[@]} -gt 0 ] || return 0
  kill "${FS_CLUSTER_PIDS[@]}" 2>/dev/null || true
  for i in $(seq 50); do
    local alive=0
    for p in "${FS_CLUSTER_PIDS[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    [ $alive -eq 0 ] && break
    sleep 0.1
  done
  # || true: callers run under set -e, and a daemon already gone (or killed) is no failure
  kill -9 "${FS_CLUSTER_PIDS[@]}" 2>/dev/null || true
  wait "${FS_CLUSTER_PIDS[@]}" 2>/dev/null || true
  FS_CLUSTER_PIDS=()
  return 0
}

job_state() { scontrol -o show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p'; }

wait_jobs() {
  local limit=$1 t0=$SECONDS id busy; shift
  while [ $((SECONDS - t0)) -lt "$limit" ]; do
    busy=0
    for id in "$@"; do job_state "$id" | grep -qE 'PENDING|RUNNING|CONFIGURING|COMPLETING|SUSPENDED' && busy=1; done
    [ $busy -eq 0 ] && return 0
    sleep 0.2
  done
  return 1
}
