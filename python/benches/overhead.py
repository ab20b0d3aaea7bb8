"""What the Python package costs over the Rust library (issue 34's overhead figures).

1. The headline scenario (scenarios/oring-nbr-water-80c.toml, 30 years, 182 rows): the life
   workflow timed inside the extension in Rust (``Scenario._time_in_rust``: no Python between
   start and stop) against ``scenario.run()`` and ``scenario.run().history`` (the DataFrame)
   from Python. Each is the fastest of many single calls, the three interleaved in rounds so
   that a busy machine slows them alike.
2. A 2 000-case Monte-Carlo study of the headline ring (scenarios/studies/headline-monte-carlo
   with ``samples = 2000``): ``sealsim study FILE -o cases.csv --summary s.json`` (the binary,
   a process per call) against ``sealsim.study(FILE)`` (cases DataFrame and summary), the same
   thread count, alternated, fastest of the rounds.

Usage: python benches/overhead.py [--cli PATH/TO/sealsim] [--rounds N] [--quick]
(run from the repository's root or from python/; --quick: a smoke run, 100 cases).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
import timeit
from pathlib import Path

import sealsim

ROOT = Path(__file__).resolve().parents[2]


def best(call, repeat: int) -> float:
    return min(timeit.repeat(call, number=1, repeat=repeat))


def headline(rounds: int, repeat: int) -> dict:
    scenario = sealsim.Scenario.from_file(ROOT / "scenarios/oring-nbr-water-80c.toml")
    inner = scenario._inner
    rust, run, history = [], [], []
    for _ in range(rounds):
        rust.append(min(inner._time_in_rust(1)[0] for _ in range(repeat)))
        run.append(best(scenario.run, repeat))
        history.append(best(lambda: scenario.run().history, repeat))
    return {"rust": min(rust), "run": min(run), "history": min(history)}


def study(cli: str, rounds: int, samples: int, threads: int) -> dict:
    text = (ROOT / "scenarios/studies/headline-monte-carlo.study.toml").read_text()
    base = (ROOT / "scenarios/oring-nbr-water-80c.toml").as_posix()
    text = text.replace("samples = 10000", f"samples = {samples}")
    text = text.replace('base = "../oring-nbr-water-80c.toml"', f'base = "{base}"')
    cli_times, py_times = [], []
    with tempfile.TemporaryDirectory() as work:
        path = Path(work) / "study.toml"
        path.write_text(text)
        for k in range(rounds):
            out = Path(work) / f"cases{k}.csv"
            summary = Path(work) / f"summary{k}.json"
            start = time.perf_counter()
            subprocess.run(
                [cli, "study", str(path), "-o", str(out), "--summary", str(summary),
                 "--threads", str(threads)],
                check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            )
            cli_times.append(time.perf_counter() - start)
            start = time.perf_counter()
            result = sealsim.study(path, threads=threads)
            py_times.append(time.perf_counter() - start)
            assert len(result.cases) == samples
    return {"cli": min(cli_times), "python": min(py_times)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "target/release/sealsim"))
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    repeat = 5 if args.quick else 100
    rounds = 1 if args.quick else args.rounds
    samples = 100 if args.quick else 2000
    threads = os.cpu_count() or 1
    h = headline(rounds, repeat)
    s = study(args.cli, rounds if not args.quick else 1, samples, threads)
    print(f"sealsim {sealsim.__version__}, Python {sys.version.split()[0]}, {threads} threads")
    print("| what | Rust | Python | overhead |")
    print("|---|---|---|---|")
    r = h["rust"]
    print(f"| headline life run, `run()` | {r * 1e3:.2f} ms | {h['run'] * 1e3:.2f} ms | "
          f"{(h['run'] / r - 1) * 100:+.1f} % |")
    print(f"| headline life run, `run().history` (DataFrame) | {r * 1e3:.2f} ms | "
          f"{h['history'] * 1e3:.2f} ms | {(h['history'] / r - 1) * 100:+.1f} % |")
    print(f"| {samples}-case study, `sealsim study` vs `sealsim.study()` | {s['cli']:.2f} s | "
          f"{s['python']:.2f} s | {(s['python'] / s['cli'] - 1) * 100:+.1f} % |")


if __name__ == "__main__":
    main()
