#!/usr/bin/env bash
# The Python package's tests (issue 34, python/README.md): a fresh venv, `pip install ./python`
# (maturin builds the extension into the workspace's target/, so a built tree makes it quick)
# with pytest, pandas, matplotlib and, for the notebook, nbclient and ipykernel; then pytest on
# python/tests against the CLI binary given (its results are compared with the CLI's files).
# Usage: tests/python/run.sh target/release/sealsim
set -euo pipefail
cd "$(dirname "$0")/../.."
cli=$(realpath "${1:?usage: tests/python/run.sh PATH/TO/sealsim}")
venv=$(mktemp -d)/venv
trap 'rm -rf "$(dirname "$venv")"' EXIT
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --disable-pip-version-check ./python pytest pandas matplotlib nbclient ipykernel
# the installed package, not the source folder, is what the tests import
cd python/tests
SEALSIM_CLI="$cli" MPLBACKEND=Agg "$venv/bin/python" -m pytest -q -p no:cacheprovider .
