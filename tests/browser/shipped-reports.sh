#!/usr/bin/env bash
# The HTML reports of the shipped headline scenario (`run`), of a `compare` and of a small
# `study`, opened in headless Chromium from Debian's packages (check-report.sh beside this
# script): no console errors or warnings, no request but the page itself, every plot present
# and drawn. Screenshots go to OUTDIR (default target/report-screenshots). Run by .ci/run.
# Usage: tests/browser/shipped-reports.sh [SEALSIM] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
SEALSIM=$(realpath "${1:-target/release/sealsim}")
OUT=$(realpath -m "${2:-target/report-screenshots}")
mkdir -p "$OUT"
WORK=$(mktemp -d /tmp/sealsim-reports.XXXXXX)
trap 'rm -rf "$WORK"' EXIT

"$SEALSIM" run scenarios/oring-nbr-water-80c.toml --report "$WORK/run.html" >/dev/null 2>&1
"$SEALSIM" run scenarios/oring-epdm-outdoor-cycles.toml --report "$WORK/run-cycles.html" >/dev/null 2>&1
"$SEALSIM" compare scenarios/oring-nbr-water-80c.toml --materials nbr-70,hnbr-75,fkm-75,epdm-70 \
  --report "$WORK/compare.html" >/dev/null 2>&1
sed -e 's/^samples = .*/samples = 60/' \
    -e "s#^base = .*#base = \"$PWD/scenarios/studies/as568-225-face-water-80c.toml\"#" \
    scenarios/studies/as568-225-squeeze-tolerance.study.toml > "$WORK/study.toml"
"$SEALSIM" study "$WORK/study.toml" --report "$WORK/study.html" >/dev/null 2>&1

bash tests/browser/check-report.sh --min-plots 1 "$OUT" \
  "$WORK/run.html" "$WORK/run-cycles.html" "$WORK/compare.html"
bash tests/browser/check-report.sh --min-plots 2 "$OUT" "$WORK/study.html"
echo "PASS: every report rendered in Chromium without errors or requests; screenshots in $OUT"
