#!/usr/bin/env bash
# Bring up a real single-node Slurm cluster on localhost from Debian's packages
# (slurmctld + slurmd + munge, no systemd, no cgroups). Idempotent: if the
# daemons already run it only checks that the node is usable.
# Logs: /tmp/slurm-logs/. Stop with stop-slurm.sh (same directory).
set -euo pipefail
[ "$(id -u)" = 0 ] || exec sudo -E bash "$0" "$@"   # needs root (apt, munge, slurmd)

LOGS=/tmp/slurm-logs
CONF=/etc/slurm/slurm.conf
NODE=$(hostname -s)
TIMEOUT=${SLURM_START_TIMEOUT:-60}
mkdir -p "$LOGS" /var/spool/slurm/ctld /var/spool/slurm/d

# 1. Packages (only if missing). apt-get update only if the plain install fails.
pkgs=(slurmctld slurmd slurm-client munge)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  inst() { apt-get install -y --no-install-recommends "${missing[@]}"; }
  inst || { apt-get update && inst; }
fi

# 2. munge: key (the package usually makes one), then munged as user munge.
if [ ! -s /etc/munge/munge.key ]; then
  mungekey --create --keyfile=/etc/munge/munge.key
fi
chown munge:munge /etc/munge/munge.key && chmod 400 /etc/munge/munge.key
mkdir -p /run/munge && chown munge:munge /run/munge && chmod 755 /run/munge
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  runuser -u munge -- /usr/sbin/munged   # forks into the background
  for _ in $(seq 50); do munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && break; sleep 0.1; done
fi
munge -n | unmunge >/dev/null || { echo "munge does not work" >&2; exit 1; }

# 3. slurm.conf: one node (this host, reached on 127.0.0.1), one default
#    partition, no cgroup plugins, no accounting. Jobs stay visible to
#    `scontrol show job` for MinJobAge seconds after they end.
new=$(cat <<EOF
ClusterName=local
SlurmctldHost=$NODE(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
MpiDefault=none
MailProg=/bin/true
StateSaveLocation=/var/spool/slurm/ctld
SlurmdSpoolDir=/var/spool/slurm/d
SlurmctldPidFile=/run/slurmctld.pid
SlurmdPidFile=/run/slurmd.pid
SlurmctldLogFile=$LOGS/slurmctld.log
SlurmdLogFile=$LOGS/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$LOGS/jobcomp.log
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
DependencyParameters=kill_invalid_depend
SchedulerParameters=batch_sched_delay=0,sched_min_interval=100000
ReturnToService=2
MinJobAge=600
NodeName=$NODE NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1024 State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF
)
running() { [ -s "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }
if [ "$(cat "$CONF" 2>/dev/null)" != "$new" ]; then
  # A changed config needs fresh daemons (stop-slurm.sh is a no-op if none run).
  if running /run/slurmctld.pid || running /run/slurmd.pid; then
    bash "$(dirname "$0")/stop-slurm.sh" --keep-munge
  fi
  mkdir -p /etc/slurm && printf '%s\n' "$new" > "$CONF"
fi

# 4. Daemons (they fork into the background and write their pid files).
running /run/slurmctld.pid || slurmctld
running /run/slurmd.pid    || slurmd

# Wait until the node is idle (or already busy with jobs); resume it if it
# came back down/drained from saved state. On timeout show logs and fail.
state=
for ((i = 0; i < TIMEOUT; i++)); do
  state=$(sinfo -h -n "$NODE" -o %T 2>/dev/null || true)
  case $state in
    idle | mixed | allocated | completing) echo "slurm up: node $NODE $state"; exit 0 ;;
    down | drain* | fail*) scontrol update nodename="$NODE" state=resume 2>/dev/null || true ;;
  esac
  sleep 1
done
echo "slurm: node $NODE not idle after ${TIMEOUT}s (state: '$state')" >&2
tail -n 50 "$LOGS"/slurmctld.log "$LOGS"/slurmd.log >&2 || true
exit 1
