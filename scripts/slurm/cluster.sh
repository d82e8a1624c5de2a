#!/usr/bin/env bash
# A single-node SLURM cluster on this machine, for trying the sweep's job array (issue 23) and for CI:
# munged, slurmctld and slurmd run as root on localhost, everything (config, keys, sockets, state, logs) in one
# state directory, nothing in /etc touched. Needs Debian's slurm-wlm and munge (`cluster.sh install` installs them).
#
#   scripts/slurm/cluster.sh install     apt-get install slurm-wlm munge (when missing)
#   scripts/slurm/cluster.sh start       write slurm.conf, start the daemons, wait until the node is idle
#   scripts/slurm/cluster.sh stop        stop the daemons (state directory kept: logs)
#   scripts/slurm/cluster.sh status      sinfo
#
# After `start`, point the SLURM commands at the cluster:  export SLURM_CONF=$STATE/slurm.conf  (start prints it).
# STATE is $ROLLBEM_SLURM_STATE, default /tmp/rollbem-slurm. Ports: $ROLLBEM_SLURM_PORT (slurmctld, default 6817)
# and the next one (slurmd).
set -euo pipefail

STATE=${ROLLBEM_SLURM_STATE:-/tmp/rollbem-slurm}
PORT=${ROLLBEM_SLURM_PORT:-6817}
CONF=$STATE/slurm.conf
SOCKET=$STATE/munge/munge.socket.2

say() { echo "cluster.sh: $*" >&2; }

install() {
    if command -v slurmctld >/dev/null && command -v slurmd >/dev/null && command -v munged >/dev/null \
        && command -v sbatch >/dev/null; then
        say "slurm-wlm and munge are installed"
        return
    fi
    [ "$(id -u)" -eq 0 ] || { say "installing needs root"; exit 1; }
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge >/dev/null
    say "installed slurm-wlm and munge"
}

# Kill the process whose pid is in file $1 (and wait for it), if it runs.
stop_pid() {
    local f=$1 pid
    [ -f "$f" ] || return 0
    pid=$(cat "$f")
    if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
        kill "$pid"
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -0 "$pid" 2>/dev/null && kill -9 "$pid"
    fi
    rm -f "$f"
}

stop() {
    stop_pid "$STATE/slurmd.pid"
    stop_pid "$STATE/slurmctld.pid"
    stop_pid "$STATE/munge/munged.pid"
    say "stopped (logs in $STATE)"
}

write_conf() {
    local host node
    host=$(hostname -s)
    # The node line as slurmd sees this machine (CPUs, sockets, cores, memory), addressed on the loopback.
    node=$(slurmd -C | head -n 1 | sed -e "s/^NodeName=[^ ]*/NodeName=$host NodeAddr=127.0.0.1/")
    cat >"$CONF" <<CONF
# Written by scripts/slurm/cluster.sh: a single-node cluster on localhost, daemons as root, no accounting.
ClusterName=rollbem
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$SOCKET
StateSaveLocation=$STATE/ctld
SlurmdSpoolDir=$STATE/d
SlurmctldPidFile=$STATE/slurmctld.pid
SlurmdPidFile=$STATE/slurmd.pid
SlurmctldLogFile=$STATE/slurmctld.log
SlurmdLogFile=$STATE/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
KillWait=5
MinJobAge=30
$node State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
}

start() {
    [ "$(id -u)" -eq 0 ] || { say "the daemons run as root here: run as root"; exit 1; }
    for c in munged slurmctld slurmd sbatch; do
        command -v "$c" >/dev/null || { say "$c not found: scripts/slurm/cluster.sh install"; exit 1; }
    done
    stop 2>/dev/null || true
    # A fresh cluster each time: no jobs left over from the last one.
    rm -rf "$STATE/munge" "$STATE/ctld" "$STATE/d"
    mkdir -p "$STATE/munge" "$STATE/ctld" "$STATE/d"
    chmod 700 "$STATE" "$STATE/munge"
    # A key of our own, so that /etc/munge is neither needed nor touched.
    [ -s "$STATE/munge/munge.key" ] || { dd if=/dev/urandom of="$STATE/munge/munge.key" bs=1024 count=1 status=none; }
    chmod 400 "$STATE/munge/munge.key"
    munged --force --key-file="$STATE/munge/munge.key" --socket="$SOCKET" \
        --pid-file="$STATE/munge/munged.pid" --log-file="$STATE/munge/munged.log" --seed-file="$STATE/munge/munged.seed"
    write_conf
    slurmctld -f "$CONF"
    slurmd -f "$CONF"
    export SLURM_CONF=$CONF
    # Wait (at most a minute) for the node to be idle.
    for _ in $(seq 120); do
        if sinfo -h -o '%t' 2>/dev/null | grep -qx 'idle'; then
            say "up: $(sinfo -h -o '%N %c CPUs %m MB %t')"
            echo "export SLURM_CONF=$CONF"
            return
        fi
        sleep 0.5
    done
    say "the node did not come up; logs:"
    tail -n 20 "$STATE/slurmctld.log" "$STATE/slurmd.log" "$STATE/munge/munged.log" >&2 || true
    exit 1
}

case "${1:-}" in
    install) install ;;
    start) start ;;
    stop) stop ;;
    status) SLURM_CONF=$CONF sinfo ;;
    *) echo "usage: $0 install|start|stop|status" >&2; exit 2 ;;
esac
