"""Every function of the package, its types and its exceptions."""

import math
import pathlib

import numpy
import pytest

import sealsim

HEADLINE = "scenarios/oring-nbr-water-80c.toml"
PAPER = "scenarios/persson-yang-2008.toml"


def test_from_file_and_from_toml_give_the_same_scenario():
    a = sealsim.Scenario.from_file(HEADLINE)
    b = sealsim.Scenario.from_toml(pathlib.Path(HEADLINE).read_text(), path=HEADLINE)
    assert a.name == b.name == "NBR O-ring face seal, water at 80 °C"
    assert a.path == HEADLINE and a.fidelity == "critical-junction"
    assert a.run().summary == b.run().summary
    # a path-like works too
    assert sealsim.Scenario.from_file(pathlib.Path(HEADLINE)).name == a.name
    assert "Scenario(" in repr(a)


def test_missing_file_is_file_not_found():
    with pytest.raises(FileNotFoundError, match="no-such.toml"):
        sealsim.Scenario.from_file("scenarios/no-such.toml")


def test_invalid_toml_is_a_scenario_error_naming_line_and_key():
    with pytest.raises(sealsim.ScenarioError) as e:
        sealsim.Scenario.from_toml("[seal]\nwidth = 10\n")
    assert isinstance(e.value, ValueError)
    # FILE:LINE: KEY: message, as the CLI prints it
    assert str(e.value).startswith("<string>:1: material: missing table [material]"), str(e.value)
    # a wrong value names its own line and key
    text = pathlib.Path(PAPER).read_text().replace("hurst_exponent = 0.8", "hurst_exponent = 1.2")
    with pytest.raises(sealsim.ScenarioError, match=r"^x\.toml:7: surface\.hurst_exponent: must lie strictly between 0 and 1"):
        sealsim.Scenario.from_toml(text, path="x.toml")


def test_scenario_error_message_equals_the_cli(cli, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(pathlib.Path(PAPER).read_text().replace('"0.2 MPa"', '"10 m"'))
    with pytest.raises(sealsim.ScenarioError) as e:
        sealsim.Scenario.from_file(str(bad))
    # the CLI prints "error: MESSAGE" and exits 2
    done = cli("run", bad, expect=2)
    assert f"error: {e.value}" in done.stderr
    assert ":14: seal.nominal_pressure: expected a pressure" in str(e.value)


def test_replace_sets_dotted_keys_and_returns_a_new_scenario():
    base = sealsim.Scenario.from_file(HEADLINE)
    cooler = base.replace({"environment.temperature": "60 C"})
    assert cooler is not base and cooler.path == base.path
    # cooler ageing: a longer life (Arrhenius), the base unchanged
    assert cooler.run().time_to_failure > base.run().time_to_failure
    assert base.run().summary["time_to_failure_s"] == base.run().time_to_failure
    # as a study's [vary]: the same value through the text gives the same scenario
    text = base.text.replace('temperature = "80 C"', 'temperature = "60 C"')
    assert text != base.text
    direct = sealsim.Scenario.from_toml(text, path=HEADLINE)
    assert direct.run().history.equals(cooler.run().history)
    # keyword form, numbers, a compound change
    flat = sealsim.Scenario.from_file(PAPER).replace(**{"model.shape_factor": 2})
    assert flat.run().summary["initial_leak_rate_m3_per_s"] > 0
    fkm = base.replace({"material.library": "fkm-75"})
    assert "FKM" in fkm.run().summary["material"]
    # chained
    # the same run; the input warnings name the lines of the rewritten text
    def physics(r):
        return {k: v for k, v in r.summary.items() if k != "input_warnings"}

    assert physics(cooler.replace({"environment.temperature": "80 C"}).run()) == physics(base.run())


def test_replace_errors_are_scenario_errors_naming_the_key():
    base = sealsim.Scenario.from_file(PAPER)
    with pytest.raises(sealsim.ScenarioError, match=r"seal\.nominal_pressure: .*expected a pressure.*with seal\.nominal_pressure"):
        base.replace({"seal.nominal_pressure": "3 m"})
    with pytest.raises(sealsim.ScenarioError, match="seal.width.x"):
        base.replace({"seal.width.x": 1})
    with pytest.raises(ValueError, match="cannot write a"):
        base.replace({"seal.width": object()})


def test_run_result():
    r = sealsim.Scenario.from_file(HEADLINE).run()
    h = r.history
    assert list(h.columns)[:3] == ["time_s", "temperature_K", "reduced_time_s"]
    assert h["time_s"].iloc[0] == 0.0 and h["time_s"].dtype == numpy.float64
    assert h["state"].iloc[0] == "sealed"
    # SI: fitted at 23 °C (296.15 K), then the service's 80 °C (353.15 K) after the lead-in
    # (docs/model.md §5.2); a 30-year run in s
    assert h["temperature_K"].iloc[0] == pytest.approx(296.15)
    assert h["temperature_K"].iloc[-1] == pytest.approx(353.15)
    assert h["time_s"].iloc[-1] == pytest.approx(30 * 365.25 * 86400, rel=1e-9)
    assert r.failure_mode == "retained_force" and r.verdict == "fails"
    assert 2.0e7 < r.time_to_failure < 2.5e7
    assert isinstance(r.warnings, list) and r.warnings and isinstance(r.warnings[0], dict)
    assert r.summary["warnings"] == r.warnings
    # a survivor has no time to failure
    s = sealsim.Scenario.from_file(PAPER).run()
    assert s.time_to_failure is None and s.failure_mode == "none" and s.verdict == "survives"
    # fidelity override
    rot = sealsim.Scenario.from_file(PAPER).run(fidelity="rule-of-thumb")
    assert rot.summary["fidelity"] == "rule-of-thumb"
    with pytest.raises(ValueError, match="unknown fidelity"):
        sealsim.Scenario.from_file(PAPER).run(fidelity="best")


def test_plot_draws_three_axes():
    import matplotlib

    matplotlib.use("Agg")
    fig = sealsim.Scenario.from_file(HEADLINE).run().plot()
    assert len(fig.axes) == 3
    assert fig.axes[0].get_yscale() == "log"
    assert "leak rate" in fig.axes[0].get_ylabel()
    assert "temperature" in fig.axes[2].get_ylabel()


def test_leak_table():
    t = sealsim.Scenario.from_file(PAPER).leak(pressures=["0.2 MPa"])
    assert list(t["nominal_pressure_Pa"]) == [2e5]
    # PY08 §3 (the library's doc example): ζc ≈ 16.19, u_c ≈ 0.1236 µm, Q ≈ 2.0e-15 m³/s
    assert t["zeta_c"][0] == pytest.approx(16.19, abs=0.01)
    assert t["u_c_m"][0] == pytest.approx(0.1236e-6, abs=1e-10)
    assert 1.95e-15 < t["leak_rate_m3_per_s"][0] < 2.05e-15
    assert isinstance(t.attrs["warnings"], list)
    with pytest.raises(ValueError, match="positive"):
        sealsim.Scenario.from_file(PAPER).leak(pressures=[-1.0])
    with pytest.raises(ValueError, match="pressure"):
        sealsim.Scenario.from_file(PAPER).leak(pressures=["3 m"])


def test_compare_rows_and_errors():
    t = sealsim.compare(sealsim.Scenario.from_file(HEADLINE), ["nbr-70", "fkm-75"])
    assert list(t["material"]) == ["nbr-70", "fkm-75"]
    assert set(t.attrs["warnings"]) == {"nbr-70", "fkm-75"}
    # the nbr-70 row is the scenario's own run (its compound is nbr-70)
    own = sealsim.Scenario.from_file(HEADLINE).run()
    assert t["time_to_failure_s"][0] == own.time_to_failure
    with pytest.raises(sealsim.ScenarioError, match="unobtainium"):
        sealsim.compare(sealsim.Scenario.from_file(HEADLINE), ["unobtainium"])
    with pytest.raises(sealsim.ScenarioError, match="cannot read material file"):
        sealsim.compare(sealsim.Scenario.from_file(HEADLINE), ["missing/compound.toml"])


def test_compare_ranks_compatible_compounds_first():
    """Issue 40: in mineral oil EPDM (rated X) survives like FKM (rated A) but never leads;
    the headline names a compound rated A; ``raw=True`` is the CLI's ``--all`` (by life)."""
    oil = sealsim.Scenario.from_file("scenarios/oring-nbr-hydraulic-oil-clean.toml")
    ids = ["epdm-70", "nbr-70", "fkm-75", "hnbr-75"]
    t = sealsim.compare(oil, ids)
    assert list(t["material"]) == ["fkm-75", "nbr-70", "hnbr-75", "epdm-70"]
    assert list(t["rank"]) == [1, 2, 3, 4]
    assert list(t["rating"][:2]) == ["A", "A"]
    assert t["rank_basis"][3] == "incompatible (rated X in mineral oil)"
    assert "incompatible with mineral oils" in t["rating_source"][3]
    headline = t.attrs["headline"]
    assert headline.startswith("Longest life among the compounds rated A (recommended) for mineral oil: fkm-75")
    assert "epdm-70" not in headline
    raw = sealsim.compare(oil, ids, raw=True)
    # by life: the two survivors (blank time) in the given order, then the longer-lived
    assert list(raw["material"]) == ["epdm-70", "fkm-75", "hnbr-75", "nbr-70"]
    assert raw.attrs["headline"] == headline


def test_study_errors():
    with pytest.raises(FileNotFoundError):
        sealsim.study("scenarios/studies/no-such.study.toml")
    with pytest.raises(sealsim.ScenarioError, match="design"):
        sealsim.study('base = "scenarios/oring-nbr-water-80c.toml"\ndesign = "random"\n[vary]\n"seal.squeeze" = "±1 %"\n')


def test_materials():
    m = sealsim.materials()
    assert "nbr-70" in list(m["id"]) and "fkm-75" in list(m["id"])
    assert list(m.columns) == [
        "id", "name", "status", "E0_Pa", "E_inf_Pa", "glass_transition_K", "low_temperature_limit_K",
    ]
    # SI: moduli of a rubber in Pa (MPa range), the instantaneous above the relaxed
    assert (m["E0_Pa"] > m["E_inf_Pa"]).all()
    assert ((m["E_inf_Pa"] > 1e5) & (m["E_inf_Pa"] < 1e8)).all()


def test_quantity_is_the_unit_parser():
    assert sealsim.quantity("210 bar") == 210e5
    assert sealsim.quantity("0.8 um") == 0.8e-6
    assert sealsim.quantity("1 year") == 365.25 * 86400
    assert sealsim.quantity("80 C", "temperature") == pytest.approx(353.15)
    assert sealsim.quantity("2 MPa", "pressure") == 2e6
    assert sealsim.quantity("0.25") == 0.25
    with pytest.raises(ValueError):
        sealsim.quantity("2 MPa", "length")
    with pytest.raises(ValueError):
        sealsim.quantity("lots")
    with pytest.raises(ValueError, match="unknown dimension"):
        sealsim.quantity("1 m", "colour")


def test_tables_without_pandas_are_dicts_of_arrays(monkeypatch):
    import builtins

    real = builtins.__import__

    def no_pandas(name, *args, **kwargs):
        if name == "pandas":
            raise ImportError(name)
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_pandas)
    h = sealsim.Scenario.from_file(PAPER).run().history
    assert isinstance(h, dict) and isinstance(h["time_s"], numpy.ndarray)
    assert h["time_s"].dtype == numpy.float64 and h["state"][0] in ("sealed", "leaking")


def test_the_gil_is_released_during_a_run():
    # another Python thread makes progress while a run computes
    import threading
    import time

    scenario = sealsim.Scenario.from_file("scenarios/air-pneumatic-end-cap.toml")
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.005)

    t = threading.Thread(target=tick)
    t.start()
    start = time.perf_counter()
    scenario.run()
    elapsed = time.perf_counter() - start
    done.set()
    t.join()
    during = [x for x in ticks if start < x < start + elapsed]
    assert elapsed > 0.2 and len(during) >= 10, (elapsed, len(during))


def test_contact_on_its_own():
    # PY08 §3: E = 10 MPa, ν = 0.5, h_rms = 2 µm, H = 0.8, q0 = 1e4 1/m, q1 = 7.8e9 1/m; the
    # paper's critical junction at 0.2 MPa: ζc ≈ 16.19, u_c ≈ 0.1236 µm (the library's doc
    # example)
    params = dict(youngs_modulus=10e6, poisson_ratio=0.5, rms_roughness=2e-6, hurst_exponent=0.8, q0=1e4, q1=7.8e9)
    t = sealsim.contact([1e5, "0.2 MPa", 1e6, 1e7], **params)
    assert list(t.columns) == [
        "nominal_pressure_Pa", "reduced_pressure", "area_fraction", "mean_gap_m", "zeta_c", "u_c_m", "lambda_c_m",
    ]
    assert t["zeta_c"][1] == pytest.approx(16.19, abs=0.01)
    assert t["u_c_m"][1] == pytest.approx(0.1236e-6, abs=1e-10)
    # E* = E/(1 − ν²)
    assert t["reduced_pressure"][1] == pytest.approx(2e5 / (10e6 / 0.75), rel=1e-15)
    # λc = 2π/(ζc q0) by definition
    for z, lam in zip(t["zeta_c"][:3], t["lambda_c_m"][:3]):
        assert lam == pytest.approx(2 * math.pi / (z * 1e4), rel=1e-12)
    # more pressure: more contact, a smaller gap; at 10 MPa no channel percolates
    assert list(t["area_fraction"]) == sorted(t["area_fraction"])
    assert 0 < t["area_fraction"][0] < t["area_fraction"][3] < 1
    assert list(t["mean_gap_m"]) == sorted(t["mean_gap_m"], reverse=True)
    # for small P0/E* the area grows in proportion (Persson: A/A0 ∝ P0)
    assert t["area_fraction"][1] / t["area_fraction"][0] == pytest.approx(2, rel=0.01)
    assert math.isnan(t["zeta_c"][3]) and math.isnan(t["u_c_m"][3])
    # the paper's scenario has the same surface and rubber
    s = sealsim.contact([2e5], sealsim.Scenario.from_file(PAPER))
    assert s["zeta_c"][0] == pytest.approx(t["zeta_c"][1], rel=1e-12)
    with pytest.raises(ValueError, match="rms_roughness"):
        sealsim.contact([1e5], youngs_modulus=1e7)
    with pytest.raises(ValueError, match="Hurst"):
        sealsim.contact([1e5], **{**params, "hurst_exponent": 1.5})


def test_stubs_and_docstrings_cover_the_api():
    import ast
    import inspect

    stub = pathlib.Path(sealsim.__file__).with_name("__init__.pyi")
    assert stub.with_name("py.typed").exists()
    tree = ast.parse(stub.read_text())
    declared = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    declared |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    assert set(sealsim.__all__) <= declared, set(sealsim.__all__) - declared
    for name in sealsim.__all__:
        obj = getattr(sealsim, name)
        if callable(obj):
            assert inspect.getdoc(obj), name
    for name in ("from_file", "from_toml", "replace", "run", "leak"):
        assert inspect.getdoc(getattr(sealsim.Scenario, name)), name
