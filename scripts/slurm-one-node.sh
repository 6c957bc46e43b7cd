#!/usr/bin/env bash
# A one-node Slurm cluster on localhost, for trying studies and for the study test (root only):
#   scripts/slurm-one-node.sh start DIR   writes DIR/slurm.conf, starts munged (unless one runs),
#                                         slurmctld and slurmd; prints "export SLURM_CONF=..."
#   scripts/slurm-one-node.sh stop DIR    stops what start started (pids in DIR/*.pid)
# Debian 12 packages: slurmctld slurmd slurm-client munge (Slurm 22.05).
set -euo pipefail
command="${1:-}"
dir="${2:-}"
if [[ -z "$command" || -z "$dir" ]]; then
    sed -n '2,6p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
    exit 2
fi

stop_pid() {
    local file="$1"
    [[ -f "$file" ]] || return 0
    local pid
    pid="$(cat "$file")"
    if [[ -n "$pid" ]] && kill -0 "$pid" 2>/dev/null; then
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$pid" 2>/dev/null || true
    fi
    rm -f "$file"
}

case "$command" in
start)
    if [[ "$(id -u)" != 0 ]]; then
        echo "slurm-one-node: needs root (slurmd runs jobs as their user)" >&2
        exit 1
    fi
    for tool in slurmctld slurmd sbatch munged; do
        if ! command -v "$tool" >/dev/null && [[ ! -x "/usr/sbin/$tool" ]]; then
            echo "slurm-one-node: $tool is not installed (apt-get install slurmctld slurmd slurm-client munge)" >&2
            exit 1
        fi
    done
    mkdir -p "$dir"/state "$dir"/spool "$dir"/log
    dir="$(cd "$dir" && pwd)"
    host="$(hostname -s)"
    cat >"$dir/slurm.conf" <<CONF
ClusterName=stratamesh
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldPort=${SLURMCTLD_PORT:-6917}
SlurmdPort=${SLURMD_PORT:-6918}
ReturnToService=2
MpiDefault=none
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
    # munge authenticates Slurm's messages; reuse a running munged, else start one as munge.
    if ! munge -n >/dev/null 2>&1; then
        if [[ ! -s /etc/munge/munge.key ]]; then
            echo "slurm-one-node: /etc/munge/munge.key is missing (reinstall munge)" >&2
            exit 1
        fi
        mkdir -p /run/munge && chown munge:munge /run/munge
        runuser -u munge -- /usr/sbin/munged
        for _ in $(seq 50); do [[ -s /run/munge/munged.pid ]] && break; sleep 0.1; done
        cp /run/munge/munged.pid "$dir/munged.pid"
    fi
    export SLURM_CONF="$dir/slurm.conf"
    /usr/sbin/slurmctld -f "$SLURM_CONF" -i
    /usr/sbin/slurmd -f "$SLURM_CONF"
    for _ in $(seq 100); do
        if sinfo -h -o '%T' 2>/dev/null | grep -qE '^(idle|mixed|allocated)'; then
            echo "export SLURM_CONF=$SLURM_CONF"
            exit 0
        fi
        sleep 0.2
    done
    echo "slurm-one-node: the node did not come up; see $dir/log" >&2
    exit 1
    ;;
stop)
    stop_pid "$dir/slurmd.pid"
    stop_pid "$dir/slurmctld.pid"
    stop_pid "$dir/munged.pid"
    ;;
*)
    echo "slurm-one-node: unknown command '$command' (start or stop)" >&2
    exit 2
    ;;
esac
