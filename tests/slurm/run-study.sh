#!/usr/bin/env bash
# The real Slurm run of a study (issue 19; docs/src/reference/studies.md, "Studies on a Slurm cluster"): brings up a
# single-node Slurm cluster from Debian's packages (start-slurm.sh), generates the job-array
# script with `sealsim study slurm`, submits it, waits for the shards and the dependent merge,
# and checks the merged per-case table and summary against a local run of the same study, bit
# for bit. Needs root (apt, munge, slurmd). Usage: tests/slurm/run-study.sh [SEALSIM]
set -euo pipefail
cd "$(dirname "$0")/../.."
SEALSIM=$(realpath "${1:-target/release/sealsim}")
[ -x "$SEALSIM" ] || { echo "no sealsim binary at $SEALSIM (cargo build --release)" >&2; exit 1; }
# the services this test starts, it stops when it ends (ones already running are left alone)
started=()
for d in slurmctld slurmd munged; do pgrep -x "$d" > /dev/null || started+=("$d"); done
bash tests/slurm/start-slurm.sh

WORK=$(mktemp -d /tmp/sealsim-slurm.XXXXXX)
stop_services() {
  rm -rf "$WORK"
  for d in "${started[@]}"; do pkill -x "$d" 2> /dev/null || true; done
}
trap stop_services EXIT
# a small study of the shipped tolerance base: 24 cases, 4 shards
sed -e 's/^samples = .*/samples = 24/' \
    -e "s#^base = .*#base = \"$PWD/scenarios/studies/as568-225-face-water-80c.toml\"#" \
    scenarios/studies/as568-225-squeeze-tolerance.study.toml > "$WORK/study.toml"

set -x
"$SEALSIM" study slurm "$WORK/study.toml" --shards 4 --time 00:10:00 \
  --results "$WORK/results" -o "$WORK/submit.sh"
bash "$WORK/submit.sh" | tee "$WORK/submitted.txt"
set +x
array=$(sed -n 's/.*job array \([0-9]*\).*/\1/p' "$WORK/submitted.txt")
merge=$(sed -n 's/.*merge as job \([0-9]*\).*/\1/p' "$WORK/submitted.txt")

# wait (bounded) until neither job is queued any more
for ((i = 0; i < 600; i++)); do
  [ -z "$(squeue -h -j "$array,$merge" 2>/dev/null)" ] && break
  sleep 0.5
done
# every record (one per array task) COMPLETED with exit code 0
job_ok() { local o; o=$(scontrol -o show job "$1") || return 1; ! grep -vq 'JobState=COMPLETED .*ExitCode=0:0' <<<"$o"; }
for j in "$array" "$merge"; do
  if ! job_ok "$j"; then
    scontrol -o show job "$j" >&2 || true
    tail -n 20 "$WORK"/results/*.log >&2 || true
    echo "FAIL: job $j did not complete" >&2
    exit 1
  fi
done
echo "jobs:"
scontrol -o show job "$array" | grep -o 'JobId=[0-9]* ArrayJobId=[0-9]* ArrayTaskId=[0-9]*\|JobState=[A-Z]*\|ExitCode=[0-9:]*' | paste -d' ' - - - 
scontrol -o show job "$merge" | grep -o 'JobId=[0-9]*\|JobState=[A-Z]*\|Dependency=[^ ]*\|ExitCode=[0-9:]*' | paste -d' ' - - - -
echo "merge log:"; cat "$WORK/results/merge.log"

# the same study run here, on this machine's cores
"$SEALSIM" study "$WORK/study.toml" -o "$WORK/local.csv" --summary "$WORK/local.json" >/dev/null 2>&1
cmp "$WORK/results/cases.csv" "$WORK/local.csv"
cmp "$WORK/results/summary.json" "$WORK/local.json"
echo "cluster vs local: cases.csv $(sha256sum < "$WORK/local.csv" | cut -c1-16) and summary.json $(sha256sum < "$WORK/local.json" | cut -c1-16) identical ($(wc -l < "$WORK/local.csv") lines)"
echo "PASS: the Slurm job array and its merge equal the local run bit for bit"
