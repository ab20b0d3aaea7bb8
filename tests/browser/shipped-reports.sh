#!/usr/bin/env bash
# The HTML reports of the shipped headline scenario (`run`), of a `compare` and of a small
# `study`, opened in headless Chromium from Debian's packages (check-report.sh beside this
# script): no console errors or warnings, no request but the page itself, every plot present
# and drawn. Screenshots go to OUTDIR (default target/report-screenshots). Run by .ci/run.
# The run's report is also printed to PDF (A4, its print stylesheet) as an engineer files it
# (issue 42, item 7): the PDF must open (pdfinfo, Debian's poppler-utils) and its first page
# must hold the report's date, sealsim's version and the scenario file's SHA-256.
# Usage: tests/browser/shipped-reports.sh [SEALSIM] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
SEALSIM=$(realpath "${1:-target/release/sealsim}")
OUT=$(realpath -m "${2:-target/report-screenshots}")
mkdir -p "$OUT"
WORK=$(mktemp -d /tmp/sealsim-reports.XXXXXX)
trap 'rm -rf "$WORK"' EXIT

# a fixed date (SOURCE_DATE_EPOCH): 1 796 000 000 s is 2026-11-30T00:53:20Z
SOURCE_DATE_EPOCH=1796000000 "$SEALSIM" run scenarios/oring-nbr-water-80c.toml \
  --report "$WORK/run.html" >/dev/null 2>&1
"$SEALSIM" run scenarios/oring-epdm-outdoor-cycles.toml --report "$WORK/run-cycles.html" >/dev/null 2>&1
"$SEALSIM" compare scenarios/oring-nbr-water-80c.toml --materials nbr-70,hnbr-75,fkm-75,epdm-70 \
  --report "$WORK/compare.html" >/dev/null 2>&1
sed -e 's/^samples = .*/samples = 60/' \
    -e "s#^base = .*#base = \"$PWD/scenarios/studies/as568-225-face-water-80c.toml\"#" \
    scenarios/studies/as568-225-squeeze-tolerance.study.toml > "$WORK/study.toml"
"$SEALSIM" study "$WORK/study.toml" --report "$WORK/study.html" >/dev/null 2>&1

bash tests/browser/check-report.sh --min-plots 1 --pdf "$OUT" "$WORK/run.html"
bash tests/browser/check-report.sh --min-plots 1 "$OUT" \
  "$WORK/run-cycles.html" "$WORK/compare.html"

# the printed report: it opens, and its first page is enough to file it
if ! command -v pdftotext >/dev/null || ! command -v pdfinfo >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y --no-install-recommends poppler-utils >&2 \
    || { apt-get update >&2 && apt-get install -y --no-install-recommends poppler-utils >&2; }
fi
pdfinfo "$OUT/run.pdf" | grep -E '^(Pages|Page size):'
pdfinfo "$OUT/run.pdf" | grep -q '^Page size: .* pts (A4)$' \
  || { echo "FAIL: run.pdf is not A4" >&2; exit 1; }
# page 1's text, hyphen- and line-breaks removed (the hash may wrap)
first=$(pdftotext -f 1 -l 1 -layout "$OUT/run.pdf" - | tr -d ' \n')
hash=$(sha256sum scenarios/oring-nbr-water-80c.toml | cut -d' ' -f1)
version=$("$SEALSIM" --version | awk '{print $2}')
for needle in "2026-11-30T00:53:20Z" "sealsim$version(commit" "SHA-256$hash" "FAIL"; do
  [[ "$first" == *"$needle"* ]] || { echo "FAIL: page 1 of run.pdf lacks $needle" >&2; exit 1; }
done
echo "PASS: run.pdf opens ($(pdfinfo "$OUT/run.pdf" | awk '/^Pages:/{print $2}') A4 pages); page 1 holds date, version, commit and the scenario's SHA-256"
bash tests/browser/check-report.sh --min-plots 2 "$OUT" "$WORK/study.html"
echo "PASS: every report rendered in Chromium without errors or requests; screenshots in $OUT"
