"""No call can crash the interpreter: random replacements, Ctrl-C, panics."""

import os
import random
import signal
import subprocess
import sys
import textwrap
import threading

import pytest

import sealsim

KEYS = [
    "seal.squeeze", "seal.cross_section", "seal.mean_diameter", "seal.inner_diameter",
    "seal.groove_depth", "seal.kind", "seal.gland", "seal.width", "seal.length",
    "seal.nominal_pressure", "surface.rms_roughness", "surface.hurst_exponent", "surface.q0",
    "surface.q1", "surface.ra", "fluid.library", "fluid.pressure_difference", "fluid.viscosity",
    "environment.temperature", "environment.daily_amplitude", "material.library",
    "material.asperity_modulus", "failure.max_leak_rate", "failure.max_leaked_volume",
    "failure.min_retained_force", "model.shape_factor", "model.percolation_threshold",
    "model.gamma", "ageing.rate", "contamination.concentration", "motion.sliding_speed",
    "numerical.grid", "nonsense.key", "seal", "", ".", "seal..squeeze", "material.file",
]
UNITS = ["", " %", " mm", " um", " m", " bar", " MPa", " Pa", " C", " K", " year", " h", " 1/m",
         " mPa*s", " m^3/s", " L", " furlong"]
WORDS = ["nbr-70", "fkm-75", "epdm-70", "o-ring", "flat", "face", "water", "mineral-oil", "x",
         "", "follow", "nan", "inf", "-inf", "1e400", "NaN bar"]


# plausible values, so that a fair share of the replacements is valid and runs
PLAUSIBLE = [
    ("environment.temperature", "60 C"), ("environment.temperature", "100 C"),
    ("fluid.pressure_difference", "1 bar"), ("surface.hurst_exponent", 0.7),
    ("model.shape_factor", 1.5), ("model.percolation_threshold", 0.5),
    ("material.library", "fkm-75"), ("material.library", "epdm-70"),
    ("failure.max_leaked_volume", "1 L"), ("surface.rms_roughness", "0.5 um"),
]


def random_value(rng):
    kind = rng.randrange(8)
    if kind == 0:
        return rng.choice(WORDS)
    if kind == 1:
        return rng.choice([True, False])
    if kind == 2:
        return rng.randint(-10**6, 10**6)
    if kind == 3:
        return rng.choice([0.0, -1.0, 1e-300, 1e300, float("nan"), float("inf"), rng.uniform(-2, 2)])
    if kind == 4:
        return [rng.uniform(0, 1) for _ in range(rng.randrange(3))]
    if kind == 5:
        return {"x": 1}
    x = rng.choice([0, -1, 1e-9, 0.2, 0.25, 3, 50, 80, 1e6, 1e30, rng.uniform(0, 100)])
    return f"{x}{rng.choice(UNITS)}"


def test_random_replacements_never_crash():
    """200 random (key, value) replacements of a scenario, seeded: each is a valid scenario
    (which then runs) or a ScenarioError/ValueError — never a crash, never an InternalError."""
    rng = random.Random(34)
    bases = [sealsim.Scenario.from_file(p) for p in (
        "scenarios/oring-nbr-water-80c.toml", "scenarios/persson-yang-2008.toml",
        "scenarios/hydrogen-line-100bar.toml",
    )]
    outcomes = {"valid": 0, "refused": 0}
    for _ in range(200):
        base = rng.choice(bases)
        values = {rng.choice(KEYS): random_value(rng) for _ in range(rng.randrange(1, 3))}
        if rng.random() < 0.3:
            values = dict([rng.choice(PLAUSIBLE)])
        try:
            changed = base.replace(values)
        except ValueError as e:  # ScenarioError is a ValueError
            assert str(e), values
            outcomes["refused"] += 1
            continue
        outcomes["valid"] += 1
        changed.run()
    assert outcomes["valid"] + outcomes["refused"] == 200
    assert outcomes["valid"] >= 20 and outcomes["refused"] >= 100, outcomes


def test_a_study_is_interrupted_by_ctrl_c(tmp_path):
    """SIGINT during a long study raises KeyboardInterrupt promptly (the GIL is released, and
    the waiting thread checks for signals)."""
    script = textwrap.dedent(
        """
        import os, signal, threading, time, sys
        import sealsim
        threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
        start = time.perf_counter()
        try:
            sealsim.study("scenarios/studies/headline-monte-carlo.study.toml", threads=1)
        except KeyboardInterrupt:
            print("interrupted after", time.perf_counter() - start)
            os._exit(0)
        print("not interrupted")
        os._exit(1)
        """
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    seconds = float(done.stdout.split()[-1])
    assert 0.9 < seconds < 5.0, seconds
