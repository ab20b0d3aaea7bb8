#!/usr/bin/env bash
# Where the time goes (issue 43): a CPU profile of (a) one headline life run and (b) a 1 000-case
# study, each recorded with `perf record -g` on a release build with debug symbols; prints the
# top functions by self time and by time including callees, and writes flame graphs to
# target/profile/ when inferno is installed. The method is committed, not the pictures
# (docs/src/performance.md, "How these were measured"). Not run by CI.
#
# Usage: benches/profile.sh [RUNS]     (RUNS: repetitions of the life run, default 200)
#        SEALSIM_BIN=target/release/sealsim benches/profile.sh   profiles that binary, no build
#        (its symbol table names the functions; without debug lines inlined calls are folded
#        into their callers)
# Needs: perf (Debian: `apt-get install linux-perf`; as non-root, kernel.perf_event_paranoid ≤ 1).
# Optional: inferno (`cargo install inferno`) for the SVG flame graphs.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-200}
out=target/profile
if ! command -v perf > /dev/null; then
  echo "profile.sh: perf not found; on Debian: apt-get install linux-perf" >&2
  exit 1
fi
mkdir -p "$out"

# A release build with debug symbols (line tables for the report), into its own target
# directory so that the ordinary release build is not replaced by this one.
if [ -n "${SEALSIM_BIN:-}" ]; then
  bin=$(realpath "$SEALSIM_BIN")
else
  export CARGO_PROFILE_RELEASE_DEBUG=true
  CARGO_TARGET_DIR=target/profile/build cargo build --release --locked
  bin=$(realpath target/profile/build/release/sealsim)
fi

# (a) one headline life run, repeated so that the profile has enough samples (one run is a few
# milliseconds; the process start-up is in it too, as it is for a user)
cat > "$out/life-runs.sh" << EOF
#!/usr/bin/env bash
for _ in \$(seq $runs); do "$bin" run scenarios/oring-nbr-water-80c.toml > /dev/null; done
EOF
chmod +x "$out/life-runs.sh"

# (b) the throughput study cut to 1 000 cases: a copy with `samples = 1000`, its base absolute
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
study=scenarios/studies/headline-monte-carlo.study.toml
base=$(realpath scenarios/oring-nbr-water-80c.toml)
sed -e 's/^samples *= *[0-9]*/samples = 1000/' -e "s|^base *= *\".*\"|base = \"$base\"|" \
  "$study" > "$tmp/study.toml"
grep -q '^samples = 1000$' "$tmp/study.toml"

profile() { # NAME COMMAND...
  local name=$1
  shift
  echo "== $name: $*" >&2
  perf record --call-graph dwarf,16384 -F 199 -o "$out/$name.perf.data" -- "$@" > /dev/null
  echo "== $name: top functions by self time" >&2
  perf report -i "$out/$name.perf.data" --stdio --no-children --percent-limit 1.5 \
    2> /dev/null | grep -E '^ +[0-9.]+%' | head -25
  echo "== $name: top functions including callees" >&2
  perf report -i "$out/$name.perf.data" --stdio --children --percent-limit 5 \
    2> /dev/null | grep -E '^ +[0-9.]+%' | head -25
  if command -v inferno-collapse-perf > /dev/null && command -v inferno-flamegraph > /dev/null; then
    perf script -i "$out/$name.perf.data" 2> /dev/null | inferno-collapse-perf \
      | inferno-flamegraph > "$out/$name.svg"
    echo "== $name: flame graph $out/$name.svg" >&2
  fi
}

profile life "$out/life-runs.sh"
profile study "$bin" study "$tmp/study.toml" --threads 2
