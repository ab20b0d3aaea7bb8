"""Issue 42 (items 4, 5, 8 of the Python part): ``leak`` at fluid pressure differences beside
contact pressures, ``plot()`` floors drawn as floors, lengths and heights as unit strings, and
the unit-slip warning of implausible heights."""

import io
import warnings

import numpy
import pytest

import sealsim

PISTON = "scenarios/templates/o-ring-piston.toml"


def _first_row(scenario, dp):
    """The first history row of ``sealsim run`` of ``scenario`` at ΔP ``dp``: an independent
    path to the installed state (energisation, strips, lift-off) at that ΔP."""
    result = scenario.replace({"fluid.pressure_difference": dp}).run()
    h = result.history
    return h.iloc[0], result


@pytest.mark.parametrize("bore_ra", [None, "6.3 um"])
def test_pressure_differences_are_the_first_row_of_run(bore_ra):
    """The template's honed bore seals (0 = 0 would prove little), so also a turned bore that
    leaks. Fails on the old code (no ``pressure_differences`` keyword)."""
    sc = sealsim.Scenario.from_file(PISTON)
    if bore_ra is not None:
        sc = sc.replace({"surface.ra": bore_ra})
    t = sc.leak(pressure_differences=["50 bar", "210 bar"])
    assert list(t.columns[:3]) == ["pressure_difference_Pa", "extrudes", "contact_pressure_Pa"]
    assert list(t["pressure_difference_Pa"]) == [5e6, 2.1e7]
    for i, dp in enumerate(["50 bar", "210 bar"]):
        row, result = _first_row(sc, dp)
        assert t["contact_pressure_Pa"][i] == row["peak_pressure_Pa"]
        assert t["leak_rate_m3_per_s"][i] == row["leak_rate_m3_per_s"]
        assert t["state"][i] == row["state"]
        extrudes = result.failure_mode == "extrusion" and result.time_to_failure == 0.0
        assert (t["extrudes"][i] == "yes") == extrudes
        if bore_ra is not None:
            assert t["leak_rate_m3_per_s"][i] > 0 and t["state"][i] == "leaking"
    # 210 bar = 3046 psi: above the extrusion chart's 3000 psi without back-up rings
    assert list(t["extrudes"]) == ["no", "yes"]


def test_pressure_differences_equal_the_cli(cli, tmp_path):
    sc = sealsim.Scenario.from_file(PISTON)
    t = sc.leak(pressure_differences=["50 bar", 2.1e7])
    out = cli("leak", PISTON, "--pressure-differences", "50 bar,210 bar").stdout
    import pandas

    expected = pandas.read_csv(io.StringIO(out), keep_default_na=False)
    assert list(expected.columns) == list(t.columns)
    for name in ("pressure_difference_Pa", "contact_pressure_Pa", "leak_rate_m3_per_s"):
        assert list(expected[name]) == list(t[name])
    assert list(expected["state"]) == list(t["state"])


def test_contact_pressures_are_named_and_say_so_for_an_o_ring():
    sc = sealsim.Scenario.from_file(PISTON)
    with pytest.warns(UserWarning, match="CONTACT pressures") as caught:
        a = sc.leak(contact_pressures=["50 bar"])
    note = next(w for w in caught if "CONTACT pressures" in str(w.message))
    assert "pressure_differences=" in str(note.message)
    with pytest.warns(UserWarning, match="CONTACT pressures"):
        b = sc.leak(pressures=["50 bar"])  # the old keyword
    assert list(a["nominal_pressure_Pa"]) == list(b["nominal_pressure_Pa"]) == [5e6]
    assert "CONTACT pressures" in a.attrs["note"]
    with pytest.raises(TypeError, match="not both"):
        sc.leak(contact_pressures=["1 MPa"], pressures=["1 MPa"])
    with pytest.raises(sealsim.ScenarioError, match="not both"):
        sc.leak(contact_pressures=["1 MPa"], pressure_differences=["50 bar"])
    with pytest.raises(ValueError, match="at least 0"):
        sc.leak(pressure_differences=[-1.0])
    with pytest.raises(ValueError, match="pressure"):
        sc.leak(pressure_differences=["3 m"])
    # a flat seal's contact pressures are its nominal pressure: no note (its validity findings,
    # ValidityWarning, are another matter)
    with warnings.catch_warnings():
        warnings.filterwarnings("error", message=".*CONTACT pressures")
        sealsim.Scenario.from_file("scenarios/persson-yang-2008.toml").leak(["0.2 MPa"])


def _leak_axis(fig):
    import matplotlib

    matplotlib.use("Agg")
    ax = fig.axes[0]
    drawn = [line for line in ax.get_lines() if len(line.get_xdata()) > 2]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    return ax, drawn, legend


def test_plot_draws_a_sealed_run_on_the_floor_labelled_sealed():
    """The piston template is sealed throughout (leak rate 0): the line holds no value below
    the floor of one molecule a second (3.0e-29 m³/s for a liquid), and the legend says sealed.
    Fails on the old code (drawn at 1e-30, no legend)."""
    import matplotlib

    matplotlib.use("Agg")
    result = sealsim.Scenario.from_file(PISTON).run()
    assert (numpy.asarray(result.history["leak_rate_m3_per_s"]) == 0).all()
    floor = 0.018015 / (997.05 * 6.02214076e23)  # one water molecule, m³ (docs/model.md §15.2)
    ax, drawn, legend = _leak_axis(result.plot())
    ys = numpy.concatenate([numpy.asarray(line.get_ydata(), dtype=float) for line in drawn])
    assert ys.min() >= floor * (1 - 1e-3) and ys.min() == pytest.approx(floor, rel=2e-3)
    assert any(text.startswith("sealed (below floor") for text in legend), legend
    # the floor line, dashed, at the floor
    dashed = [l for l in ax.get_lines() if l.get_linestyle() == "--" and l.get_ydata()[0] > 0]
    assert any(l.get_ydata()[0] == pytest.approx(floor, rel=2e-3) for l in dashed)
    assert ax.get_ylim()[0] >= 1e-30
    # a floor given, with units: nothing drawn below it
    ax, drawn, legend = _leak_axis(result.plot(leak_floor="1e-15 m^3/s"))
    ys = numpy.concatenate([numpy.asarray(line.get_ydata(), dtype=float) for line in drawn])
    assert ys.min() == pytest.approx(1e-15)
    assert any("the floor given" in text for text in legend), legend
    with pytest.raises(sealsim.ScenarioError, match="leak_floor"):
        result.plot(leak_floor="1 bar")


def test_plot_of_a_leaking_run_keeps_its_rates():
    import matplotlib

    matplotlib.use("Agg")
    result = sealsim.Scenario.from_file(PISTON).replace({"surface.ra": "6.3 um"}).run()
    q = numpy.asarray(result.history["leak_rate_m3_per_s"], dtype=float)
    assert (q > 1e-25).any()
    ax, drawn, legend = _leak_axis(result.plot())
    ys = numpy.asarray(drawn[0].get_ydata(), dtype=float)
    floor = 3.0e-29
    assert ys.min() >= floor * 0.999
    # every rate above the floor is drawn as it is
    above = q >= floor
    assert numpy.array_equal(ys[above], q[above])
    assert "leak rate" in legend


def _map(n=128, px=0.5e-6, rms=0.5e-6, seed=1):
    """A self-affine-ish map (the review's walkthrough), heights in m."""
    rng = numpy.random.default_rng(seed)
    k = numpy.fft.fftfreq(n, d=px) * 2 * numpy.pi
    kx, ky = numpy.meshgrid(k, k)
    kk = numpy.hypot(kx, ky)
    kk[0, 0] = 1
    amp = kk ** (-(1 + 0.8))
    amp[0, 0] = 0
    z = numpy.real(numpy.fft.ifft2(numpy.fft.fft2(rng.standard_normal((n, n))) * amp))
    return z * (rms / z.std())


def test_pixel_size_and_heights_take_unit_strings():
    z = _map()
    pressures = ["0.5 MPa", "2 MPa"]
    kw = dict(youngs_modulus=10e6, fidelity="exact")
    in_m = sealsim.contact(pressures, height_map=z, pixel_size=0.5e-6, **kw)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        in_um = sealsim.contact(
            pressures, height_map=z * 1e6, pixel_size="0.5 um", height_unit="um", **kw
        )
    for name in ("area_fraction", "mean_gap_m", "u_c_m"):
        numpy.testing.assert_allclose(in_um[name], in_m[name], rtol=1e-12)
    with pytest.raises(sealsim.ScenarioError, match="pixel_size"):
        sealsim.contact(pressures, height_map=z, pixel_size="0.5 bar", **kw)
    with pytest.raises(sealsim.ScenarioError, match="height_unit"):
        sealsim.contact(pressures, height_map=z, pixel_size=0.5e-6, height_unit="K", **kw)
    # surface: the same parser for the grid's pixel and heights, and a trace's z
    a = sealsim.surface(z, pixel_size=0.5e-6)
    b = sealsim.surface(z * 1e6, pixel_size="0.5 um", height_unit="um")
    assert b["rq_m"] == pytest.approx(a["rq_m"], rel=1e-12)
    x = numpy.arange(2048) * 0.5e-6
    zt = z[0].repeat(16)
    t_m = sealsim.surface((x, zt))
    t_um = sealsim.surface((x, zt * 1e6), height_unit="um")
    assert t_um["rq_m"] == pytest.approx(t_m["rq_m"], rel=1e-12)


def test_heights_in_micrometres_passed_as_metres_warn_with_the_slip():
    """The review's repro: a 0.5 µm rms map written in µm and passed as metres ran silently
    (mean gap 0.39 m). Fails on the old code (no warning)."""
    z_um = _map() * 1e6
    # read as metres the heights pass the readers' ±10 mm bound: refused, naming the unit
    with pytest.raises(ValueError, match="height"):
        sealsim.contact(
            ["2 MPa"], height_map=z_um, pixel_size=0.5e-6, youngs_modulus=10e6, fidelity="exact"
        )
    with pytest.raises(ValueError, match="height"):
        sealsim.surface(z_um, pixel_size=0.5e-6)
    # a trace in µm given as metres
    x = numpy.arange(2048) * 0.5e-6
    with pytest.warns(UserWarning, match="times too large"):
        sealsim.surface((x, z_um[0].repeat(16)))
