"""Shared fixtures: the repository root and the CLI binary the Python results are checked
against (``--sealsim-cli PATH`` or ``$SEALSIM_CLI``, default ``target/release/sealsim``)."""

import csv
import json
import math
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


def pytest_addoption(parser):
    parser.addoption("--sealsim-cli", default=os.environ.get("SEALSIM_CLI"))


@pytest.fixture(scope="session")
def repo():
    return REPO


@pytest.fixture(scope="session")
def cli_path(pytestconfig):
    """The CLI binary's absolute path."""
    path = pytestconfig.getoption("--sealsim-cli") or str(REPO / "target/release/sealsim")
    path = str(pathlib.Path(path).resolve())
    if not os.access(path, os.X_OK):
        pytest.fail(f"the sealsim binary {path} is missing: build it (cargo build --release)")
    return path


@pytest.fixture(scope="session")
def cli(cli_path):
    path = cli_path

    def run(*args, cwd=REPO, expect=0):
        done = subprocess.run([path, *map(str, args)], cwd=cwd, capture_output=True, text=True)
        assert done.returncode == expect, done.stderr
        return done

    return run


@pytest.fixture(autouse=True)
def _in_repo(monkeypatch):
    """Every test runs in the repository (scenario paths are given relative to it, as to the
    CLI)."""
    monkeypatch.chdir(REPO)


def read_csv(path):
    """A CSV file as (header, rows of strings)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def assert_table_equals_csv(table, path):
    """``table`` (DataFrame or dict of arrays) has exactly the CSV's columns, in order, and
    every cell: a number equal as a float (bit for bit: ``==``, and NaN for a blank cell), a
    word equal as text."""
    header, rows = read_csv(path)
    assert list(table.keys()) == header
    for j, name in enumerate(header):
        column = list(table[name])
        assert len(column) == len(rows), name
        for i, (got, row) in enumerate(zip(column, rows)):
            cell = row[j]
            if isinstance(got, str):
                assert got == cell, (name, i)
            elif cell == "":
                assert math.isnan(got), (name, i, got)
            else:
                want = float(cell)
                assert got == want and math.copysign(1, got) == math.copysign(1, want), (
                    name,
                    i,
                    got,
                    cell,
                )


def read_json(path):
    with open(path) as f:
        return json.load(f)
