#!/usr/bin/env bash
# Stop the daemons started by start-slurm.sh (by their pid files), then munged.
set -euo pipefail
[ "$(id -u)" = 0 ] || exec sudo -E bash "$0" "$@"

stop() {  # stop <pidfile>: TERM the process and wait (bounded) for it to exit
  local pid
  [ -s "$1" ] && pid=$(cat "$1") && kill -0 "$pid" 2>/dev/null || return 0
  kill "$pid"
  for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.1; done
  kill -9 "$pid" 2>/dev/null || true
}
stop /run/slurmd.pid
stop /run/slurmctld.pid
[ "${1:-}" = --keep-munge ] || stop /run/munge/munged.pid
