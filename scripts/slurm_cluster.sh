#!/usr/bin/env bash
# A throw-away one-node Slurm cluster on localhost, for tests: munged, slurmctld and slurmd from
# the Debian packages (slurm-wlm, munge), every file — munge key and socket, slurm.conf, state,
# spool, logs, PID files — under one folder, private ports, nothing in /etc or /run touched.
#
#   scripts/slurm_cluster.sh start DIR   # writes DIR/env (source it: SLURM_CONF=DIR/slurm.conf)
#   scripts/slurm_cluster.sh stop DIR    # stops the three daemons by the PIDs in their PID files
#
# Runs the daemons as the calling user (SlurmUser = SlurmdUser = that user; root in CI).
# Exit code 77 = Slurm or munge is not installed (a test skips then).
set -euo pipefail

usage() {
  echo "usage: $0 start|stop DIR" >&2
  exit 2
}
(($# == 2)) || usage
action=$1
dir=$2

# The PID files of the daemons, in the order they are stopped.
pid_files=(slurmd.pid slurmctld.pid munged.pid)

stop() {
  [ -d "$dir" ] || return 0
  local f pid
  for f in "${pid_files[@]}"; do
    [ -s "$dir/run/$f" ] || continue
    pid=$(cat "$dir/run/$f")
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do  # 5 s, then SIGKILL
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.1
    done
    kill -9 "$pid" 2>/dev/null || true
    rm -f "$dir/run/$f"
  done
}

free_port() {  # a TCP port nobody listens on, from a range away from the well-known ones
  local p
  for _ in $(seq 100); do
    p=$((20000 + RANDOM % 20000))
    if ! ss -Htln "sport = :$p" 2>/dev/null | grep -q .; then
      echo "$p"
      return
    fi
  done
  echo "slurm_cluster: no free port found" >&2
  exit 1
}

# daemon NAME COMMAND...: starts a daemon in the foreground (it does not fork) in the background of
# this script, its output in log/NAME.out and its PID in run/NAME.pid at once: a wait can then tell a
# daemon still starting (on a loaded machine that may take long) from one that has died, and stop
# finds it even before the daemon wrote the PID file itself (the same PID, to the same file).
daemon() {
  local name=$1
  shift
  "$@" </dev/null >>"$dir/log/$name.out" 2>&1 &
  echo $! >"$dir/run/$name.pid"
}

dead_daemon() {  # prints the name of a started daemon that is no longer running; fails if none
  local f
  for f in "${pid_files[@]}"; do
    [ -s "$dir/run/$f" ] || continue
    kill -0 "$(cat "$dir/run/$f")" 2>/dev/null || { echo "${f%.pid}"; return 0; }
  done
  return 1
}

wait_for() {  # wait_for WHAT COMMAND...: until COMMAND succeeds, however long; fails if a daemon died
  local what=$1 dead
  shift
  until "$@" >/dev/null 2>&1; do
    if dead=$(dead_daemon); then
      echo "slurm_cluster: $dead exited before $what; logs:" >&2
      tail -n 20 "$dir"/log/* >&2 || true
      return 1
    fi
    sleep 0.1
  done
}

start() {
  for tool in munged slurmctld slurmd sbatch; do
    if ! command -v "$tool" >/dev/null && ! [ -x "/usr/sbin/$tool" ]; then
      echo "slurm_cluster: '$tool' is not installed (Debian packages: slurm-wlm munge)" >&2
      exit 77
    fi
  done
  export PATH="$PATH:/usr/sbin"
  mkdir -p "$dir"
  dir=$(cd "$dir" && pwd)
  chmod 700 "$dir"
  mkdir -p "$dir"/{munge,run,log,state,spool}
  chmod 700 "$dir"/munge

  # munge: a fresh key and a private socket (munged insists the key is the user's and mode 0600).
  dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
  chmod 600 "$dir/munge/munge.key"
  local socket="$dir/munge/munge.socket"
  daemon munged munged --foreground --socket="$socket" --key-file="$dir/munge/munge.key" \
    --pid-file="$dir/run/munged.pid" --log-file="$dir/log/munged.log" \
    --seed-file="$dir/munge/munged.seed" --force
  wait_for "munge's socket answered" munge --socket="$socket" -n

  local user host ctld_port slurmd_port
  user=$(id -un)
  host=$(hostname -s)
  ctld_port=$(free_port)
  slurmd_port=$(free_port)
  while [ "$slurmd_port" = "$ctld_port" ]; do slurmd_port=$(free_port); done
  cat >"$dir/slurm.conf" <<EOF
# One-node test cluster written by scripts/slurm_cluster.sh; everything lives in $dir.
ClusterName=sextant-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
SchedulerType=sched/backfill
SlurmctldTimeout=30
# A loaded machine answers late, and late is no failure: clients (squeue, sbatch, scontrol) wait 60 s
# for slurmctld's answer (MessageTimeout, 10 s by default); a batch job may take 120 s to launch
# (10 s by default); slurmd is given Slurm's default 300 s to answer pings before the node is set
# DOWN and its jobs killed (NODE_FAIL).
MessageTimeout=60
BatchStartTimeout=120
SlurmdTimeout=300
InactiveLimit=0
MinJobAge=30
KillWait=5
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
  cat >"$dir/env" <<EOF
export SLURM_CONF=$dir/slurm.conf
export PATH="\$PATH:/usr/sbin"
EOF
  export SLURM_CONF="$dir/slurm.conf"
  # -D: in the foreground (see daemon); -i: ignore any state left in the folder. The node is usable
  # once slurmd has registered and answered: "idle" (not "idle*", not responding; nor "unknown").
  daemon slurmctld slurmctld -D -i -f "$SLURM_CONF"
  wait_for "slurmctld answered a ping" scontrol ping
  daemon slurmd slurmd -D -f "$SLURM_CONF"
  wait_for "the node was idle" sh -c "sinfo -h -o %t | grep -qx idle"
  echo "slurm_cluster: up in $dir (slurmctld :$ctld_port, slurmd :$slurmd_port); source $dir/env"
}

case "$action" in
  start) start ;;
  stop) stop ;;
  *) usage ;;
esac
