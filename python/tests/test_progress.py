"""Progress reporting (a callable, a tqdm-style bar, a text bar) and the overhead benchmark's
smoke run."""

import re
import subprocess
import sys

import pytest

import sealsim


def small_study(cases):
    text = open("scenarios/studies/headline-monte-carlo.study.toml").read()
    assert "samples = 10000" in text
    return text.replace("samples = 10000", f"samples = {cases}").replace(
        'base = "../', 'base = "scenarios/'
    )


def test_a_callable_sees_every_case_done_once_and_in_order():
    calls = []
    result = sealsim.study(small_study(120), threads=2, progress=lambda d, t: calls.append((d, t)))
    assert calls, "the callback was never called"
    assert all(t == 120 for _, t in calls)
    done = [d for d, _ in calls]
    assert done == sorted(done) and len(set(done)) == len(done)
    assert calls[-1] == (120, 120)
    assert len(result.cases) == 120


def test_a_tqdm_style_bar_is_advanced_to_its_total():
    class Bar:
        def __init__(self):
            self.total, self.n, self.refreshed = None, 0, 0

        def update(self, k):
            assert k >= 0
            self.n += k

        def refresh(self):
            self.refreshed += 1

    bar = Bar()
    sealsim.study(small_study(60), progress=bar)
    assert (bar.n, bar.total) == (60, 60) and bar.refreshed >= 1


def test_a_text_bar_goes_to_stderr(capfd):
    sealsim.study(small_study(40), progress=True)
    err = capfd.readouterr().err
    assert err.endswith("cases [" + "=" * 30 + "] 40/40\n"), err[-80:]


def test_an_exception_in_the_callback_ends_the_call_with_it():
    def stop(done, total):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        sealsim.study(small_study(200), progress=stop)


def test_progress_of_a_wrong_type_is_a_type_error():
    with pytest.raises(TypeError, match="progress must be"):
        sealsim.study(small_study(10), progress=3)


def test_the_life_run_accepts_progress_and_is_unchanged_by_it():
    scenario = sealsim.Scenario.from_file("scenarios/oring-nbr-water-80c.toml")
    calls = []
    with_bar = scenario.run(progress=lambda d, t: calls.append((d, t)))
    plain = scenario.run()
    assert with_bar.summary == plain.summary
    assert calls == []  # the critical-junction level tabulates nothing to report


def test_the_overhead_benchmark_runs(cli_path, repo):
    done = subprocess.run(
        [sys.executable, str(repo / "python/benches/overhead.py"), "--quick", "--cli", cli_path],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    rows = [line for line in done.stdout.splitlines() if re.match(r"\| (headline|\d+-case)", line)]
    assert len(rows) == 3, done.stdout
    for row in rows:
        assert re.search(r"\| [+-]\d+\.\d %", row), row
