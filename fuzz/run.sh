#!/usr/bin/env bash
# Runs each cargo-fuzz target for a fixed time (default 60 s each; `fuzz/run.sh 600` for 10 min).
# Needs a nightly toolchain and cargo-fuzz (`cargo install cargo-fuzz --locked`). Seeds come from
# the shipped files; a crash is written to fuzz/artifacts/TARGET/ and stops the script with its
# status at the end (each target still runs; turn a crash into a regression test).
set -euo pipefail
cd "$(dirname "$0")"
seconds="${1:-60}"
mkdir -p corpus/units corpus/scenario corpus/csv_readers
# Seed corpora: the shipped scenarios and material files, the spectrum and the history (with the
# selector byte of csv_readers in front), a few quantities.
for f in ../scenarios/*.toml ../materials/*.toml; do cp "$f" corpus/scenario/; done
{ printf '\000'; cat ../scenarios/psd-example.csv; } > corpus/csv_readers/psd
{ printf '\001'; cat ../scenarios/cold-night.csv; } > corpus/csv_readers/history
printf '\001time,modulus\ns,MPa\n1,10\n10,8\n100,6\n' > corpus/csv_readers/relaxation
for q in '\0010.8 um' '\0063e5 1/m' '\0062 bar' '\0070.35 mPa*s' '\0041e-11 m^3/s' '\00480 C' '\0042 year'; do
    printf "$q" > "corpus/units/$(printf "$q" | cksum | cut -d' ' -f1)"
done
status=0
for target in units scenario csv_readers; do
    echo "== $target: ${seconds} s"
    cargo +nightly fuzz run "$target" "corpus/$target" -- -max_total_time="$seconds" -timeout=10 \
        -rss_limit_mb=4096 -print_final_stats=1 || status=$?
done
exit "$status"
