#!/usr/bin/env bash
# Browser check of sealsim's self-contained HTML reports in headless Chromium.
#
#   tests/browser/check-report.sh [--min-plots N] [--pdf] OUTDIR REPORT.html...
#   tests/browser/check-report.sh --book BOOK_DIR OUTDIR PAGE.html...
#
# For each REPORT.html (e.g. OUTDIR/../study.html) runs check-report.mjs beside this script, which
# fails on console errors/warnings, page errors, any request other than the report itself or a
# data: URI, failed requests, fewer than N `figure.plot svg` (default 1), plots rendered with zero
# size, and <img>/<script>/<link rel=stylesheet> pointing outside the document; see its header.
# Writes a full-page screenshot OUTDIR/<report name without .html>.png for each report and prints
# one JSON summary line per report on stdout; with --pdf also prints each report to
# OUTDIR/<name>.pdf (A4, the report's print stylesheet). Checks every report, then exits 1 if any failed
# (2 on a usage error).
#
# With --book BOOK_DIR it checks pages of a built mdBook (PAGE paths relative to BOOK_DIR; scripts
# and the book's own files allowed) with check-book.mjs instead; see its header (.ci/book uses it).
#
# Sets itself up as needed, so it works on a fresh machine:
#   - Debian's chromium, only if /usr/bin/chromium is missing (apt-get update only if the plain
#     install fails); Playwright's own browser downloads are never used (they can't be fetched here);
#   - `npm ci` in tests/browser, only if tests/browser/node_modules is missing (package-lock.json
#     pins playwright-core).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

usage() {
  echo "usage: $0 [--min-plots N] [--pdf] OUTDIR REPORT.html..." >&2
  echo "       $0 --book BOOK_DIR OUTDIR PAGE.html..." >&2
  exit 2
}

node_opts=()
book=""
pdf=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --min-plots)
      [[ $# -ge 2 ]] || usage
      node_opts+=(--min-plots "$2")
      shift 2
      ;;
    --pdf)
      pdf=1
      shift
      ;;
    --book)
      [[ $# -ge 2 ]] || usage
      book="$2"
      shift 2
      ;;
    --min-plots=*)
      node_opts+=("$1")
      shift
      ;;
    -h | --help) usage ;;
    --) shift; break ;;
    -*) echo "$0: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
[[ $# -ge 2 ]] || usage
outdir="$1"
shift
mkdir -p "$outdir"

if [[ ! -x /usr/bin/chromium ]]; then
  echo "check-report: installing Debian's chromium" >&2
  start=$SECONDS
  export DEBIAN_FRONTEND=noninteractive
  if ! apt-get install -y --no-install-recommends chromium >&2; then
    apt-get update >&2
    apt-get install -y --no-install-recommends chromium >&2
  fi
  echo "check-report: chromium installed in $((SECONDS - start)) s" >&2
fi

if [[ ! -d "$here/node_modules" ]]; then
  echo "check-report: npm ci in $here" >&2
  start=$SECONDS
  (cd "$here" && npm ci --no-audit --no-fund >&2)
  echo "check-report: npm ci done in $((SECONDS - start)) s" >&2
fi

if [[ -n "$book" ]]; then
  exec node "$here/check-book.mjs" "$book" "$outdir" "$@"
fi

status=0
for report in "$@"; do
  name="$(basename "$report")"
  name="${name%.html}"
  name="${name%.htm}"
  pdf_opts=()
  [[ -n "$pdf" ]] && pdf_opts=(--pdf "$outdir/$name.pdf")
  if ! node "$here/check-report.mjs" "$report" "$outdir/$name.png" "${node_opts[@]}" "${pdf_opts[@]}"; then
    echo "check-report: FAILED: $report" >&2
    status=1
  fi
done
exit "$status"
