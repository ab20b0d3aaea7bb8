"""``sealsim.fit_prony`` and ``sealsim.surface``: the command line's files and JSON exactly, a
Prony series recovered from data made from a known one, and bad input."""

import json
import math
import struct

import numpy
import pytest

import sealsim

LAB = "scenarios/lab-data/csr-nbr-70c.csv"
# the lab-data tutorial's command (docs/src/tutorials/lab-data.md)
LAB_FLAGS = dict(
    test_piece="ring",
    cross_section="3.53mm",
    mean_diameter="28.52mm",
    squeeze="25%",
    temperature="70C",
    like="nbr-70",
    name="nbr-lab",
)
LAB_ARGS = [
    "--test-piece", "ring", "--cross-section", "3.53mm", "--mean-diameter", "28.52mm",
    "--squeeze", "25%", "--temperature", "70C", "--like", "nbr-70", "--name", "nbr-lab",
]


def cli_fit(cli, tmp_path, data, *args):
    """The CLI's material file and stderr lines."""
    out = tmp_path / "cli.toml"
    done = cli("fit-prony", data, "--kind", "relaxation", *args, "-o", out)
    return out.read_text(encoding="utf-8"), done.stderr.splitlines()


def lab_columns():
    """The lab file's columns as written (t in h, force in N)."""
    rows = [l for l in open(LAB, encoding="utf-8") if l.strip() and not l.startswith("#")]
    assert rows[0].strip() == "t,force" and rows[1].strip() == "h,N"
    values = [[float(c) for c in r.split(",")] for r in rows[2:]]
    return {"t": [v[0] for v in values], "force": [v[1] for v in values]}


def test_fit_of_the_lab_file_is_the_cli_file(cli, tmp_path):
    want, stderr = cli_fit(cli, tmp_path, LAB, *LAB_ARGS)
    fitted = sealsim.fit_prony(LAB, "relaxation", **LAB_FLAGS)
    assert fitted.material_toml == want
    assert fitted.summary == stderr
    assert fitted.source == LAB and fitted.name == "nbr-lab"
    # the terms are the file's [material] prony table, in SI
    assert len(fitted.terms["tau_s"]) == want.count("tau =")
    assert math.isclose(fitted.E0, fitted.E_inf + sum(fitted.terms["E_i_Pa"]), rel_tol=1e-12)
    # write() writes the same bytes
    fitted.write(tmp_path / "py.toml")
    assert (tmp_path / "py.toml").read_bytes() == (tmp_path / "cli.toml").read_bytes()


def test_fit_of_columns_is_the_cli_file(cli, tmp_path):
    pandas = pytest.importorskip("pandas")
    want, stderr = cli_fit(cli, tmp_path, LAB, *LAB_ARGS)
    columns = lab_columns()
    # a DataFrame in the file's units
    frame = pandas.DataFrame(columns)
    fitted = sealsim.fit_prony(
        frame, "relaxation", units={"t": "h", "force": "N"}, source=LAB, **LAB_FLAGS
    )
    assert fitted.material_toml == want and fitted.summary == stderr
    # a dict of columns in SI (t in s), the options as SI floats
    si = {"t": [t * 3600.0 for t in columns["t"]], "force": columns["force"]}
    flags = dict(LAB_FLAGS, cross_section=3.53e-3, mean_diameter=28.52e-3, squeeze=0.25,
                 temperature=343.15)
    si_fit = sealsim.fit_prony(si, "relaxation", source=LAB, **flags)
    # the same series up to the last bits of the unit conversions (3.53 mm → m, h → s)
    assert si_fit.E_inf == pytest.approx(fitted.E_inf, rel=1e-9)
    assert list(si_fit.terms["tau_s"]) == pytest.approx(list(fitted.terms["tau_s"]), rel=1e-9)
    assert list(si_fit.terms["E_i_Pa"]) == pytest.approx(list(fitted.terms["E_i_Pa"]), rel=1e-6)


def prony(t, e_inf, terms):
    t = numpy.asarray(t, dtype=float)
    return e_inf + sum(e * numpy.exp(-t / tau) for tau, e in terms)


# E(t) = 2 MPa + 1 MPa e^(−t/10 s) + 0.5 MPa e^(−t/1000 s) + 0.8 MPa e^(−t/1e5 s)
E_INF = 2e6
TERMS = [(10.0, 1e6), (1e3, 0.5e6), (1e5, 0.8e6)]


def test_a_known_prony_series_is_recovered_from_its_relaxation():
    t = numpy.logspace(-1, 7, 81)
    fitted = sealsim.fit_prony({"t": t, "E_relax": prony(t, E_INF, TERMS)}, "relaxation")
    # the curve within 0.1 % over the data window, data points and between them
    between = numpy.logspace(-1, 7, 797)
    worst = numpy.max(numpy.abs(fitted.relaxation(between) / prony(between, E_INF, TERMS) - 1))
    assert worst < 1e-3, worst
    # E∞ (the curve is flat for t ≫ 1e5 s) and E0 (t = 0.1 s ≪ 10 s) within 0.5 %
    assert abs(fitted.E_inf / E_INF - 1) < 5e-3
    assert abs(fitted.E0 / (E_INF + sum(e for _, e in TERMS)) - 1) < 5e-3
    assert fitted.source == "<data>" and fitted.points == 81
    assert any("no test temperature" in line for line in fitted.summary)


def test_a_known_prony_series_is_recovered_from_its_dma_spectrum():
    # E′ = E∞ + Σ E_i ω²τ²/(1 + ω²τ²), E″ = Σ E_i ωτ/(1 + ω²τ²), ω = 2π f
    f = numpy.logspace(-7, 1, 81)
    w = 2 * numpy.pi * f
    storage = E_INF + sum(e * (w * tau) ** 2 / (1 + (w * tau) ** 2) for tau, e in TERMS)
    loss = sum(e * w * tau / (1 + (w * tau) ** 2) for tau, e in TERMS)
    fitted = sealsim.fit_prony({"f": f, "E_stor": storage, "E_loss": loss}, "dma")
    # the window is 1/ω_max … 1/ω_min
    assert fitted.window == pytest.approx((1 / w[-1], 1 / w[0]), rel=1e-12)
    # a looser match than from E(t) itself (measured: 1.5 % at worst over the window, E∞
    # and E0 within 0.9 %): the relative weighting of E″ where it is a thousandth of E′
    t = numpy.logspace(numpy.log10(fitted.window[0]), numpy.log10(fitted.window[1]), 300)
    worst = numpy.max(numpy.abs(fitted.relaxation(t) / prony(t, E_INF, TERMS) - 1))
    assert worst < 0.02, worst
    assert abs(fitted.E_inf / E_INF - 1) < 0.01
    assert abs(fitted.E0 / (E_INF + sum(e for _, e in TERMS)) - 1) < 0.01


def test_a_master_curve_is_the_cli_file(cli, tmp_path, monkeypatch):
    # isotherms of one series shifted by WLF (C1 = 8.86, C2 = 101.6 K at 23 C)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    lines = ["t,E_relax,T", "s,Pa,C"]
    for celsius in (0.0, 23.0, 50.0, 80.0):
        dt = celsius - 23.0
        log_a = -8.86 * dt / (101.6 + dt)
        for t in numpy.logspace(0, 4, 13):
            e = prony(t / 10**log_a, E_INF, TERMS)
            lines.append(f"{float(t)!r},{float(e)!r},{celsius!r}")
    data = tmp_path / "isotherms.csv"
    data.write_text("\n".join(lines) + "\n")
    want, stderr = cli_fit(cli, tmp_path, data, "--shift", "wlf", "--reference-temperature", "23C")
    fitted = sealsim.fit_prony(str(data), "relaxation", shift="wlf", reference_temperature="23C")
    assert fitted.material_toml == want and fitted.summary == stderr
    assert "[material.shift]" in want


def test_bad_fit_input_raises_the_cli_message(cli, tmp_path):
    with pytest.raises(FileNotFoundError, match="cannot read the data file"):
        sealsim.fit_prony(tmp_path / "missing.csv", "relaxation")
    bad = tmp_path / "bad.csv"
    bad.write_text("t,E_relax\ns,MPa\n1,5\n2,x\n3,4\n")
    message = cli("fit-prony", bad, "--kind", "relaxation", expect=2).stderr
    with pytest.raises(sealsim.ScenarioError) as e:
        sealsim.fit_prony(str(bad), "relaxation")
    assert message == f"error: {e.value}\n"
    # the same file as columns: the same message, the line of the row
    with pytest.raises(sealsim.ScenarioError) as e:
        sealsim.fit_prony({"t": [1, 2, 3], "E_relax": [5e6, "x", 4e6]}, "relaxation")
    assert str(e.value).startswith("<data>:4:")
    # options: the CLI's messages (which name its flags)
    for flags, args in [
        (dict(squeeze=0.25), ["--squeeze", "25%"]),
        (dict(test_piece="ring", squeeze=0.25), ["--test-piece", "ring", "--squeeze", "25%"]),
        (dict(like="nosuch"), ["--like", "nosuch"]),
    ]:
        message = cli("fit-prony", LAB, "--kind", "relaxation", *args, expect=2).stderr
        with pytest.raises(sealsim.ScenarioError) as e:
            sealsim.fit_prony(LAB, "relaxation", **flags)
        assert message == f"error: {e.value}\n", flags
    with pytest.raises(sealsim.ScenarioError, match="squeeze: must be positive"):
        sealsim.fit_prony(LAB, "relaxation", test_piece="ring", squeeze=-0.25)
    with pytest.raises(ValueError, match="unknown kind"):
        sealsim.fit_prony(LAB, "creep")


def cli_json(cli, *args):
    return json.loads(cli("surface", *args, "--json").stdout)


@pytest.mark.parametrize(
    "sources",
    [
        ["scenarios/psd-example.csv"],
        ["scenarios/traces/ground-fine.csv"],
        ["scenarios/traces/ground-fine.csv", "scenarios/traces/ground-coarse.csv"],
        ["scenarios/oring-nbr-water-80c.toml"],
    ],
)
def test_surface_of_files_is_the_cli_json(cli, sources):
    got = sealsim.surface(sources if len(sources) > 1 else sources[0])
    assert got == cli_json(cli, *sources)
    assert len(got.spectrum["q_per_m"]) > 0


def test_surface_options_are_the_cli_flags(cli):
    trace = "scenarios/traces/ground-fine.csv"
    got = sealsim.surface(trace, cutoff="0.25mm", tip_radius=2e-6)
    assert got == cli_json(cli, trace, "--cutoff", "0.25mm", "--tip-radius", "2um")
    psd = "scenarios/psd-example.csv"
    got = sealsim.surface(psd, cutoff=0.25e-3, short_cutoff="0.8um")
    assert got == cli_json(cli, psd, "--cutoff", "0.25mm", "--short-cutoff", "0.8um")


def trace_arrays(path):
    """A trace file (x in mm, z in µm) as arrays in m."""
    rows = [l for l in open(path, encoding="utf-8") if l.strip() and not l.startswith("#")]
    assert rows[:2] == ["x,z\n", "mm,um\n"]
    values = numpy.array([[float(c) for c in r.split(",")] for r in rows[2:]])
    return values[:, 0] * 1e-3, values[:, 1] * 1e-6


def test_a_trace_as_arrays_is_the_cli_json(cli):
    path = "scenarios/traces/ground-fine.csv"
    x, z = trace_arrays(path)
    got = sealsim.surface((x, z), name=path)
    want = cli_json(cli, path)
    # the unit conversion in Python and in the parser may differ in the last bit of x and z
    for key in want:
        if isinstance(want[key], float):
            assert math.isclose(got[key], want[key], rel_tol=1e-9), key
        elif key != "warnings":
            assert got[key] == want[key] or numpy.allclose(got[key], want[key], rtol=1e-9), key
    assert got["warnings"] == want["warnings"]


def self_affine(n, pixel, seed):
    """A random height map [m] with C(q) ∝ q^−2(1+H), H = 0.8, rms about 1 µm."""
    rng = numpy.random.default_rng(seed)
    q = 2 * numpy.pi * numpy.hypot(*numpy.meshgrid(numpy.fft.fftfreq(n, pixel),
                                                    numpy.fft.fftfreq(n, pixel)))
    q[0, 0] = numpy.inf
    amplitude = q ** -1.8
    h = numpy.fft.ifft2(amplitude * numpy.exp(2j * numpy.pi * rng.random((n, n)))).real
    return h / h.std() * 1e-6


def test_a_height_array_is_the_cli_json_of_its_csv_grid(cli, tmp_path):
    heights = self_affine(64, 1e-6, seed=3)[:, :48]  # 64 rows of 48: rectangular
    grid = tmp_path / "grid.csv"
    grid.write_text("\n".join(",".join(repr(float(v)) for v in row) for row in heights) + "\n")
    want = cli_json(cli, grid, "--pixel-size", "1um")
    assert want["kind"] == "height map"
    got = sealsim.surface(heights, pixel_size=1e-6, name=str(grid))
    assert got == want
    # the same grid in µm with height_unit
    got = sealsim.surface(heights * 1e6, pixel_size="1 um", height_unit="um", name=str(grid))
    assert got["ra_m"] == pytest.approx(want["ra_m"], rel=1e-12)
    # the file itself
    assert sealsim.surface(grid, pixel_size=1e-6) == want


def test_a_gsf_height_map_is_the_cli_json(cli, tmp_path):
    heights = self_affine(64, 0.5e-6, seed=5)
    header = (
        "Gwyddion Simple Field 1.0\nXRes = 64\nYRes = 64\nXReal = 3.2e-5\nYReal = 3.2e-5\n"
        "XYUnits = m\nZUnits = m\n"
    ).encode()
    header += b"\0" * (4 - len(header) % 4)
    gsf = tmp_path / "map.gsf"
    gsf.write_bytes(header + struct.pack("<4096f", *heights.ravel()))
    got = sealsim.surface(str(gsf))
    assert got == cli_json(cli, gsf)
    assert got["kind"] == "height map" and got["hurst_exponent"] is not None


def test_bad_surface_input_raises_the_cli_message(cli, tmp_path):
    with pytest.raises(FileNotFoundError):
        sealsim.surface(tmp_path / "missing.csv")
    with pytest.raises(FileNotFoundError):
        sealsim.surface(str(tmp_path / "missing.toml"))
    cases = [
        (["scenarios/psd-example.csv"], dict(cutoff="1um"), ["--cutoff", "1um"]),
        (["scenarios/psd-example.toml"], dict(pixel_size=1e-6), ["--pixel-size", "1um"]),
        (
            ["scenarios/traces/ground-fine.csv"],
            dict(cutoff="2um"),
            ["--cutoff", "2um"],
        ),
    ]
    for sources, options, flags in cases:
        message = cli("surface", *sources, *flags, expect=2).stderr
        with pytest.raises(sealsim.ScenarioError) as e:
            sealsim.surface(sources[0], **options)
        assert message == f"error: {e.value}\n", options
    ragged = tmp_path / "ragged.csv"
    ragged.write_text("1e-6,2e-6,3e-6\n1e-6,2e-6\n")
    with pytest.raises(sealsim.ScenarioError, match=":2: ragged row"):
        sealsim.surface(ragged, pixel_size=1e-6)
    with pytest.raises(sealsim.ScenarioError, match="a height map needs at least 8"):
        sealsim.surface(numpy.zeros((3, 3)), pixel_size=1e-6)
    with pytest.raises(ValueError, match="pixel_size"):
        sealsim.surface(numpy.zeros((32, 32)))
    with pytest.raises(ValueError, match="give a path"):
        sealsim.surface(42)
