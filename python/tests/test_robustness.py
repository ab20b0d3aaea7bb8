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


@pytest.mark.parametrize("place", ["worker", "guarded", "bare"])
def test_a_panic_is_an_internal_error_and_the_interpreter_goes_on(place):
    """A Rust panic reaches Python as ``InternalError`` (a ``RuntimeError``), never as pyo3's
    ``PanicException`` (a ``BaseException`` that ``except Exception`` misses, D4): caught on the
    worker, in the calling thread's guard, or (outside both) by the public wrappers."""
    call = sealsim._documented_errors("panic", sealsim._sealsim._panic)
    with pytest.raises(sealsim.InternalError, match="a panic on purpose"):
        call(place)
    assert sealsim.quantity("2 bar") == 2e5


def gsf(path, x_res, y_res, x_real, y_real):
    """A GSF file of the header alone, padded as the format pads it (the review's D4 repro)."""
    header = (
        f"Gwyddion Simple Field 1.0\nXRes = {x_res}\nYRes = {y_res}\nXReal = {x_real}\n"
        f"YReal = {y_real}\n"
    ).encode()
    path.write_bytes(header + b"\0" * (4 - len(header) % 4))
    return path


# XRes · YRes · 4 wraps to 0 (it passed the size check and panicked: capacity overflow), and
# XRes · YRes wraps (index out of bounds in the spectrum estimate)
WRAPPING = [(4294967296, 1073741824, "1e-3", "0.00025"), (2**63, 2**63, "1", "1")]


@pytest.mark.parametrize("header", WRAPPING, ids=["xres-4e9", "xres-2^63"])
def test_a_gsf_header_whose_size_wraps_is_a_scenario_error(tmp_path, repo, header):
    x, y = header[:2]
    size = f"XRes × YRes = {x} × {y} is more than"
    path = gsf(tmp_path / "wrap.gsf", *header)
    with pytest.raises(sealsim.ScenarioError, match=size):
        sealsim.surface(path)
    base = (repo / "scenarios/oring-nbr-water-80c.toml").read_text()
    start = base.index("[surface]")
    end = base.index("\n[", start + 1)
    text = base[:start] + '[surface]\nheight_map = "wrap.gsf"\n' + base[end:]
    scenario = tmp_path / "hm.toml"
    scenario.write_text(text)
    with pytest.raises(sealsim.ScenarioError, match=size):
        sealsim.Scenario.from_file(scenario)
    with pytest.raises(sealsim.ScenarioError, match=size):
        sealsim.Scenario.from_toml(text, path=scenario)


GRID = {"numerical.band": 512, "numerical.pixels_per_wavelength": 64}
# each key within its range; together a 32768² grid, which aborted the interpreter (D6)
REFUSAL = r"32768 × 32768 grid, which needs about [0-9.]+ GB"


def test_an_oversized_numerical_grid_is_refused_by_replace(repo):
    base = sealsim.Scenario.from_file(repo / "scenarios/oring-nbr-water-80c.toml")
    with pytest.raises(sealsim.ScenarioError, match=REFUSAL):
        base.replace(GRID)


def test_an_oversized_numerical_grid_is_refused_by_from_toml(repo):
    text = (repo / "scenarios/gasket-nbr-dirty-oil.toml").read_text()
    assert "[numerical]" not in text
    text += "\n[numerical]\nband = 512\npixels_per_wavelength = 64\nrealisations = 1000\n"
    with pytest.raises(sealsim.ScenarioError, match=REFUSAL):
        sealsim.Scenario.from_toml(text)


def test_a_height_map_above_8192_squared_is_refused_before_it_is_copied():
    """A broadcast view of 8193 × 8192 pixels (one number in memory) is refused on its shape:
    made contiguous first, it would have taken 2 × 537 MB (the array, then its bytes)."""
    import tracemalloc

    import numpy

    heights = numpy.broadcast_to(numpy.float64(1e-7), (8193, 8192))
    tracemalloc.start()
    try:
        with pytest.raises(sealsim.ScenarioError, match="8193 × 8192: the contact solver takes at most"):
            sealsim.contact([2e5], height_map=heights, pixel_size=1e-6, youngs_modulus=1e7)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 10e6, peak
