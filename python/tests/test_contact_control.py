"""`sealsim.contact`'s boundary, displacement control and tolerance (issue 43): the free
boundary against Hertz's sphere and Sneddon's flat punch on a 512² grid, displacement control
against load control, the tolerance against the iterations, bad arguments."""

import math

import numpy
import pytest

import sealsim

# E* given directly: poisson_ratio = 0 makes E* = E (10 MPa, a rubber)
E_STAR = 1e7
# 1 µm pixels, 512² grid: a 0.512 mm patch
PIXEL = 1e-6
N = 512


def radius_grid(n=N, pixel=PIXEL):
    """Distance (m) of each pixel centre from the centre pixel (n/2, n/2)."""
    i = (numpy.arange(n) - n // 2) * pixel
    x, y = numpy.meshgrid(i, i, indexing="xy")
    return numpy.hypot(x, y)


def relative(diff, ref):
    return float(numpy.sum(numpy.abs(diff)) / numpy.sum(numpy.abs(ref)))


# Hertz (Johnson 1985, Contact Mechanics, §4.2): a sphere of radius R on an elastic half-space,
# force F: a = (3FR/(4E*))^(1/3), p0 = 3F/(2πa²), δ = a²/R. R = 10 mm and a = 100 µm (100
# pixels, the contact 200 pixels across on a 512-pixel patch, its edge 156 pixels from the
# patch's): heights h = −r²/(2R), 6.5 µm deep at the corners.
R = 0.01
A_HERTZ = 100e-6
F_HERTZ = 4 * E_STAR * A_HERTZ**3 / (3 * R)


@pytest.fixture(scope="module")
def hertz():
    r = radius_grid()
    heights = -(r**2) / (2 * R)
    mean_pressure = F_HERTZ / (N * PIXEL) ** 2
    result = sealsim.contact(
        [mean_pressure],
        height_map=heights,
        pixel_size=PIXEL,
        youngs_modulus=E_STAR,
        poisson_ratio=0.0,
        boundary="free",
    )
    return heights, mean_pressure, result


def test_free_boundary_hertz_contact_radius_peak_pressure_and_approach(hertz):
    _, mean_pressure, result = hertz
    assert isinstance(result, sealsim.ContactResult)
    assert (result.boundary, result.control, result.tolerance) == ("free", "pressure", 1e-8)
    row = {k: float(v[0]) for k, v in result.table.items()}
    assert row["nominal_pressure_Pa"] == mean_pressure
    a = math.sqrt(row["area_fraction"] * (N * PIXEL) ** 2 / math.pi)
    p0 = 3 * F_HERTZ / (2 * math.pi * A_HERTZ**2)
    p_max = float(result.fields[0]["pressure_Pa"].max())
    delta = A_HERTZ**2 / R
    errors = (a / A_HERTZ - 1, p_max / p0 - 1, row["approach_m"] / delta - 1)
    print("Hertz 512² free: a, p0, δ relative errors", errors)
    # bounds 1 %, 2 %, 2 %; measured +0.10 % (pixel counting: a is from the contact pixels),
    # +4.5e-6 and −3.9e-6
    assert abs(errors[0]) < 0.01
    assert abs(errors[1]) < 0.02
    assert abs(errors[2]) < 0.02
    # the load is the prescribed one, and the fields are the solution's
    f = result.fields[0]
    assert f["mean_pressure_Pa"][0] == pytest.approx(mean_pressure, rel=1e-12)
    assert float(f["pressure_Pa"].mean()) == pytest.approx(mean_pressure, rel=1e-12)
    assert float(f["approach_m"][0]) == row["approach_m"]


def test_a_free_patch_reports_no_flow_rather_than_a_number(hertz):
    _, _, result = hertz
    assert "periodic" in result.flow
    for name in ("percolates", "percolating_fraction", "conductance_m3_per_Pa_s", "u_c_m"):
        assert name not in result.table
        assert name not in result.fields[0]
    for name, column in result.table.items():
        assert numpy.all(numpy.isfinite(numpy.asarray(column, dtype=float))), name


def test_displacement_control_reproduces_the_pressure_controlled_solution(hertz):
    """Solve at p̄, read δ; solve at δ: the mean pressure, A/A0 and the pressure field agree to
    the tolerance (1e-8). The same sphere and load on a 256² grid of 2 µm pixels (a quarter of
    the cost). Measured on the 512² grid: p̄ within 2.4e-11, field Σ|Δp|/Σp 1.4e-9, A/A0
    identical; bound 1e-8 on p̄ and 5e-8 on the field (the tolerance bounds the field's change
    per iteration of a linearly converging iteration, not its error)."""
    heights, mean_pressure, _ = hertz
    common = dict(height_map=heights[::2, ::2], pixel_size=2 * PIXEL, youngs_modulus=E_STAR, poisson_ratio=0.0, boundary="free")
    by_load = sealsim.contact([mean_pressure], **common)
    delta = float(by_load.table["approach_m"][0])
    by_approach = sealsim.contact(displacement=[delta], **common)
    assert by_approach.control == "displacement"
    p_back = float(by_approach.table["nominal_pressure_Pa"][0])
    field = relative(by_approach.fields[0]["pressure_Pa"] - by_load.fields[0]["pressure_Pa"], by_load.fields[0]["pressure_Pa"])
    print("displacement control: p̄", p_back / mean_pressure - 1, "field", field)
    assert abs(p_back / mean_pressure - 1) < 1e-8
    assert field < 5e-8
    assert by_approach.table["area_fraction"][0] == by_load.table["area_fraction"][0]
    assert abs(by_approach.table["approach_m"][0] - delta) <= 1e-8 * heights.std()


# Flat punch (Sneddon 1965; Johnson 1985 §3.8): a rigid flat cylinder of radius a pressed δ into
# a half-space carries F = 2aE*δ with p(r) = F/(2πa√(a² − r²)). The face: the pixels within
# 64 µm of the centre at height 0, the rest 3δ below (nothing else can touch: the gap there is
# at least 2δ); a is the radius of the discrete face (the same area).
A_PUNCH = 64e-6
DELTA_PUNCH = 1e-6


@pytest.fixture(scope="module")
def punch():
    r = radius_grid()
    face = r <= A_PUNCH
    heights = numpy.where(face, 0.0, -3 * DELTA_PUNCH)
    a = math.sqrt(face.sum() / math.pi) * PIXEL
    force = 2 * a * E_STAR * DELTA_PUNCH
    # load control (displacement control of the same punch takes twice as long: the edge
    # singularity makes this the slowest case; the round trip is checked on Hertz above)
    result = sealsim.contact(
        force / (N * PIXEL) ** 2,
        height_map=heights,
        pixel_size=PIXEL,
        youngs_modulus=E_STAR,
        poisson_ratio=0.0,
        boundary="free",
    )
    return r, face, a, force, result


def test_free_boundary_flat_punch_force_and_pressure_profile(punch):
    r, face, a, force, result = punch
    delta = float(result.table["approach_m"][0])
    p = result.fields[0]["pressure_Pa"]
    inner = r < 0.9 * a
    p_sneddon = force / (2 * math.pi * a * numpy.sqrt(a**2 - r[inner] ** 2))
    l2 = float(numpy.linalg.norm(p[inner] - p_sneddon) / numpy.linalg.norm(p_sneddon))
    stiffness = force / (2 * a * E_STAR * delta)
    print("punch 512² free: F/(2aE*δ)", stiffness - 1, "L2 r<0.9a", l2)
    # the whole face is in contact, nothing else
    assert numpy.array_equal(p > 0, face)
    assert abs(stiffness - 1) < 0.02
    # measured 6.6e-3 with 64 pixels on the radius (the pixelated edge: the periodic cell of
    # the peer comparison gave 1.9e-2 at 32 pixels and 1.0e-2 at 64, halving with the pixel);
    # bound 1e-2, 1.5 × the measured value
    assert l2 < 0.01


def test_periodic_displacement_control_and_the_mean_plane_approach():
    """On a periodic rough map: δ = max h − (ū + ⟨h⟩) (the deformed surface's mean plane is the
    rigid-body position), and displacement control at δ gives back p̄, A/A0 and the field."""
    rng = numpy.random.default_rng(3)
    n = 128
    k = numpy.fft.fftfreq(n) * n
    kx, ky = numpy.meshgrid(k, k, indexing="xy")
    kk = numpy.hypot(kx, ky)
    amplitude = numpy.where((kk >= 1) & (kk <= 16), numpy.maximum(kk, 2.0) ** -1.8, 0.0)
    h = numpy.real(numpy.fft.ifft2(amplitude * numpy.exp(2j * numpy.pi * rng.random((n, n)))))
    h *= 1e-6 / h.std()
    common = dict(height_map=h, pixel_size=PIXEL, youngs_modulus=E_STAR, poisson_ratio=0.0)
    p = 0.02 * E_STAR * 0.1
    by_load = sealsim.contact(p, **common)
    delta = float(by_load.table["approach_m"][0])
    mean_plane = h.max() - (by_load.table["mean_gap_m"][0] + h.mean())
    assert delta == pytest.approx(mean_plane, abs=1e-12 * h.std())
    by_approach = sealsim.contact(displacement=delta, **common)
    assert float(by_approach.table["nominal_pressure_Pa"][0]) == pytest.approx(p, rel=1e-8)
    assert by_approach.table["area_fraction"][0] == by_load.table["area_fraction"][0]
    field = relative(by_approach.fields[0]["pressure_Pa"] - by_load.fields[0]["pressure_Pa"], by_load.fields[0]["pressure_Pa"])
    assert field < 5e-8
    # the periodic cell keeps its flow columns under displacement control
    assert by_approach.flow is None and "conductance_m3_per_Pa_s" in by_approach.table
    # δ below the highest point: no contact, zero pressure, the gap s − h
    none = sealsim.contact(displacement=[-1e-7, 0.0], **common)
    assert list(none.table["nominal_pressure_Pa"]) == [0.0, 0.0]
    assert list(none.table["area_fraction"]) == [0.0, 0.0]
    assert numpy.allclose(none.fields[0]["gap_m"], h.max() + 1e-7 - h, rtol=0, atol=1e-18)
    # at or beyond full contact (max h − ⟨h⟩) a periodic cell has no solution
    with pytest.raises(sealsim.ScenarioError, match="full contact"):
        sealsim.contact(displacement=h.max() - h.mean(), **common)


def test_a_looser_tolerance_takes_fewer_iterations_and_stays_within_it(hertz):
    heights, mean_pressure, tight = hertz
    small = heights[::4, ::4]  # the same sphere and load on a 128² grid of 4 µm pixels
    common = dict(height_map=small, pixel_size=4 * PIXEL, youngs_modulus=E_STAR, poisson_ratio=0.0, boundary="free")
    ref = sealsim.contact(mean_pressure, tolerance=1e-10, **common)
    for tol in (1e-3, 1e-6):
        loose = sealsim.contact(mean_pressure, tolerance=tol, **common)
        assert loose.tolerance == tol
        assert loose.fields[0]["iterations"][0] < ref.fields[0]["iterations"][0]
        field = relative(loose.fields[0]["pressure_Pa"] - ref.fields[0]["pressure_Pa"], ref.fields[0]["pressure_Pa"])
        approach = abs(loose.table["approach_m"][0] - ref.table["approach_m"][0]) / small.std()
        print("tolerance", tol, "iterations", loose.fields[0]["iterations"][0], ref.fields[0]["iterations"][0], "field", field, "approach", approach)
        assert field < tol
        assert approach < tol


@pytest.mark.parametrize(
    "kwargs, words",
    [
        (dict(boundary="fixed"), ['"periodic"', '"free"', '"fixed"']),
        (dict(tolerance=0.0), ["tolerance", "(0, 1)"]),
        (dict(tolerance=1.0), ["tolerance", "(0, 1)"]),
        (dict(tolerance=float("nan")), ["tolerance", "(0, 1)"]),
        (dict(displacement=[1e-6]), ["either pressures", "not both"]),
        (dict(pressures=None), ["give pressures", "displacement"]),
        (dict(displacement="1 kg"), ["displacement"]),
    ],
)
def test_bad_arguments_are_refused_with_the_accepted_values(kwargs, words):
    h = -(radius_grid(32) ** 2) / (2 * R)
    args = dict(pressures=[1e3], height_map=h, pixel_size=PIXEL, youngs_modulus=E_STAR)
    args.update(kwargs)
    if "displacement" in kwargs and kwargs["displacement"] == "1 kg":
        args["pressures"] = None
    with pytest.raises(ValueError) as raised:
        sealsim.contact(**args)
    assert isinstance(raised.value, sealsim.ScenarioError)
    for word in words:
        assert word in str(raised.value)


def test_an_analytic_level_refuses_the_boundary_element_keywords():
    spectrum = dict(youngs_modulus=1e7, rms_roughness=1e-6, hurst_exponent=0.8, q0=1e4, q1=1e7)
    for kwargs, name in [
        (dict(boundary="free"), 'boundary="free"'),
        (dict(tolerance=1e-6), "tolerance"),
        (dict(pressures=None, displacement=[1e-6]), "displacement"),
    ]:
        args = dict(pressures=[1e5], **spectrum)
        args.update(kwargs)
        with pytest.raises(sealsim.ScenarioError, match="numerical level") as raised:
            sealsim.contact(**args)
        assert name in str(raised.value)
    # the default boundary is accepted there, and every existing call still works
    table = sealsim.contact([1e5], boundary="periodic", **spectrum)
    assert table["area_fraction"][0] > 0
