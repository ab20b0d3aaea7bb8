//! `sealsim.contact`: the contact problem on its own (issue 34), as contact researchers use it.
//!
//! * Analytic levels: Persson's theory at each nominal pressure — the relative contact area
//!   A(q1/q0)/A0 and the mean gap ū(ζ = 1) ([`ContactPath::full_contact`], the very function
//!   behind `sealsim leak`'s `area_fraction` and `mean_gap_m`), and the level's critical
//!   junction (ζc, u_c, λc).
//! * The numerical level: the boundary-element contact, the percolation of the non-contact
//!   region and the Reynolds flow of the scenario's numerical level
//!   ([`reference::evaluate_loaded`], called exactly as the numerical table of `sealsim leak`
//!   and of the life run calls it: E* = 1 at the reduced pressure P0/E*, η = 1, the same
//!   `[numerical]` settings, threads and tolerances), on a height map handed over as raw `f64`
//!   bytes (bit for bit) or on the scenario's random realisations; with the fields (heights, gap
//!   and contact pressure of every realisation) as `f64` bytes for numpy.

use crate::{
    PyScenario, ScenarioError, blocking, fidelity, float_column, guarded, internal, pressure,
};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList, PyString};
use sealsim::contact::{ContactSettings, Elastic, Junction};
use sealsim::leak::{ContactPath, Fidelity, PathOptions};
use sealsim::numerical::bem::{self, BemError, Boundary, Load};
use sealsim::numerical::reference::{self, NumericalError, NumericalSettings, Surfaces};
use sealsim::numerical::{HeightMap, Topography, psd};
use sealsim::plausibility::HeightStatistics;
use sealsim::scenario::Scenario;
use sealsim::surface::Spectrum;
use sealsim::units::{self, Dimension};
use std::sync::Arc;

/// Smallest side of a height map, as a scenario's height map file (`scenario::height_map`).
const MIN_SIDE: usize = 8;

/// Viscosity of the conductance column without a scenario (Pa·s): water near 20 °C. σ_eff is
/// inversely proportional to it; `u_c_m = (12 η σ_eff)^{1/3}` does not depend on it.
const DEFAULT_VISCOSITY: f64 = 1e-3;

/// Invalid input: `sealsim.ScenarioError` (a `ValueError`).
fn bad(message: String) -> PyErr {
    ScenarioError::new_err(format!("contact: {message}"))
}

/// Checks a height map's shape `(ny, nx)` before its heights are copied anywhere: each side at
/// least [`MIN_SIDE`], at most [`reference::MAX_GRID_PIXELS`] in all (8192², D6: larger
/// aborted on its allocation). The Python side calls it before it makes the array contiguous.
#[pyfunction]
fn _height_map_shape(shape: (usize, usize)) -> PyResult<()> {
    let (ny, nx) = shape;
    if nx < MIN_SIDE || ny < MIN_SIDE {
        return Err(bad(format!(
            "height_map is {ny} × {nx}: each side needs at least {MIN_SIDE} samples"
        )));
    }
    let max = reference::MAX_GRID_PIXELS;
    if nx.saturating_mul(ny) > max {
        return Err(bad(format!(
            "height_map is {ny} × {nx}: the contact solver takes at most {max} pixels \
             (8192 × 8192, ≈ 4.8 GB while it solves); crop or resample the map"
        )));
    }
    Ok(())
}

/// A 2-D grid of heights from numpy: `heights` the native-endian `f64` bytes of a C-contiguous
/// `ny × nx` array (row `iy`, column `ix` along the flow) in `unit` (m per unit), `pixel` the
/// spacing (m). The shape passed [`_height_map_shape`]; every height must be finite and
/// plausible (the scenario reader's bound).
fn topography(
    heights: &[u8],
    shape: (usize, usize),
    pixel: Option<f64>,
    unit: f64,
) -> PyResult<Topography> {
    let (ny, nx) = shape;
    let pixel = pixel.ok_or_else(|| {
        bad("height_map needs pixel_size, the spacing of its samples (m)".to_owned())
    })?;
    if !(pixel.is_finite() && pixel > 0.0) {
        return Err(bad(format!(
            "pixel_size must be positive and finite, got {pixel} m"
        )));
    }
    let heights: Vec<f64> = heights
        .chunks_exact(8)
        .map(|b| f64::from_ne_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]) * unit)
        .collect();
    if let Some(i) = heights.iter().position(|h| !h.is_finite()) {
        return Err(bad(format!(
            "height_map[{}, {}] is {}: every height must be a finite number (m)",
            i / nx,
            i % nx,
            heights[i]
        )));
    }
    // the scenario reader's bound (±10 mm, no-data markers): a map in µm passed as metres
    for (i, &h) in heights.iter().enumerate() {
        if let Some(why) = sealsim::scenario::implausible_height(h, 1.0) {
            return Err(bad(format!("height_map[{}, {}]: {why}", i / nx, i % nx)));
        }
    }
    Ok(Topography {
        nx,
        ny,
        pixel,
        heights,
    })
}

/// The heights' bytes checked against their `shape` ([`_height_map_shape`] and the byte
/// count) and copied, so that the worker reads them without the GIL.
fn map_bytes(heights: &[u8], shape: (usize, usize)) -> PyResult<Vec<u8>> {
    _height_map_shape(shape)?;
    let (ny, nx) = shape;
    // nx · ny ≤ MAX_GRID_PIXELS: no overflow
    if heights.len() != nx * ny * 8 {
        return Err(bad(format!(
            "height_map has {} bytes, not the {} of {ny} × {nx} float64 values",
            heights.len(),
            nx * ny * 8
        )));
    }
    Ok(heights.to_vec())
}

/// What the contact is solved on.
struct Problem {
    spectrum: Option<Spectrum>,
    settings: ContactSettings,
    e_star: f64,
    viscosity: f64,
    map: Option<HeightMap>,
    numerical: NumericalSettings,
    /// The analytic level (`None`: the numerical level).
    level: Option<Fidelity>,
}

/// The surface, the rubber and the level from the arguments (see `sealsim.contact`).
#[allow(clippy::too_many_arguments)]
fn problem(
    scenario: Option<&Scenario>,
    map: Option<Topography>,
    youngs_modulus: Option<f64>,
    poisson_ratio: f64,
    rms_roughness: Option<f64>,
    hurst_exponent: Option<f64>,
    q0: Option<f64>,
    q1: Option<f64>,
    level: Option<Fidelity>,
    viscosity: Option<f64>,
) -> PyResult<Problem> {
    let level = match level {
        Some(Fidelity::Numerical) => None,
        Some(analytic) => Some(analytic),
        // a height map is the numerical level's surface; a scenario at the numerical level
        // runs it, as the CLI does; otherwise Persson's theory by quadrature
        None if map.is_some() => None,
        None if scenario.is_some_and(|s| s.life.fidelity == Fidelity::Numerical) => None,
        None => Some(Fidelity::Exact),
    };
    if let Some(eta) = viscosity
        && !(eta.is_finite() && eta > 0.0)
    {
        return Err(bad(format!(
            "viscosity must be positive and finite, got {eta} Pa·s"
        )));
    }
    // a measured map: the numerical level's single realisation; its spectrum estimate (as a
    // scenario's height map gets it) for the analytic levels
    let estimated = match (&map, level) {
        (Some(t), Some(_)) => Some(
            psd::estimate_topography(t, &psd::PsdOptions::default())
                .map_err(|e| bad(format!("the height map's spectrum: {e}")))?,
        ),
        _ => None,
    };
    // the array's map, else the scenario's own (its height map file, cropped as read)
    let map = map.map(|t| t.square_crop().0).or_else(|| {
        level
            .is_none()
            .then(|| scenario.and_then(|s| s.height_map.clone()))
            .flatten()
    });
    let need =
        |name: &str, v: Option<f64>| v.ok_or_else(|| bad(format!("give {name} (or a scenario)")));
    let (spectrum, settings, e_star, eta, numerical) = match scenario {
        Some(s) => {
            let pb = &s.problem;
            (
                estimated.or_else(|| map.is_none().then(|| pb.spectrum.clone())),
                pb.contact,
                pb.material.effective_modulus(),
                viscosity.unwrap_or(pb.fluid.viscosity),
                sealsim::workflow::numerical_settings(s),
            )
        }
        None => {
            let e = need("youngs_modulus", youngs_modulus)?;
            // the scenario key's range (material.youngs_modulus, 1e3–1e12 Pa): 5e-324 once gave
            // an infinite reduced pressure, 1e300 a NaN mean gap
            if !(e.is_finite() && (1e3..=1e12).contains(&e)) {
                return Err(bad(format!(
                    "youngs_modulus must lie in 1e3–1e12 Pa (a rubber's modulus, as the \
                     scenario key material.youngs_modulus), got {e} Pa"
                )));
            }
            if !(poisson_ratio > -1.0 && poisson_ratio <= 0.5) {
                return Err(bad(format!(
                    "poisson_ratio must lie in (-1, 0.5], got {poisson_ratio}"
                )));
            }
            let spectrum = match (&map, estimated) {
                (_, Some(sp)) => Some(sp),
                (Some(_), None) => None,
                (None, None) => Some(
                    Spectrum::self_affine(
                        need("rms_roughness", rms_roughness)?,
                        need("hurst_exponent", hurst_exponent)?,
                        need("q0", q0)?,
                        need("q1", q1)?,
                        None,
                    )
                    .map_err(|e| bad(e.to_string()))?,
                ),
            };
            let elastic = Elastic {
                youngs_modulus: e,
                poisson_ratio,
            };
            (
                spectrum,
                ContactSettings::default(),
                elastic.effective_modulus(),
                viscosity.unwrap_or(DEFAULT_VISCOSITY),
                NumericalSettings::default(),
            )
        }
    };
    Ok(Problem {
        spectrum,
        settings,
        e_star,
        viscosity: eta,
        map,
        numerical,
        level,
    })
}

/// Persson's theory at `level` (analytic): one row per pressure.
fn analytic_rows(
    spectrum: Spectrum,
    settings: ContactSettings,
    level: Fidelity,
    e_star: f64,
    pressures: &[f64],
) -> Vec<[f64; 7]> {
    let path = ContactPath::build(
        &spectrum,
        settings,
        level,
        &PathOptions::default(),
        &mut |_, _| {},
    );
    pressures
        .iter()
        .map(|&p| {
            let s = p / e_star;
            let full = path
                .full_contact(s)
                .map_or([f64::NAN; 2], |c| [c.area_fraction, c.mean_gap]);
            let j = match path.critical_junction(s) {
                Junction::Leaking(j) => [j.zeta_c, j.u_c, j.lambda_c],
                Junction::Sealed => [f64::NAN; 3],
            };
            [p, s, full[0], full[1], j[0], j[1], j[2]]
        })
        .collect()
}

/// One realisation's fields and scalars, as the boundary elements left them.
struct Solved {
    seed: Option<u64>,
    /// Grid side and pixel size (m).
    n: usize,
    pixel: f64,
    heights: Vec<f64>,
    gap: Vec<f64>,
    /// Contact pressure at E* = 1 (the reduced pressure P/E*).
    reduced_pressure: Vec<f64>,
    /// Its mean over the cell, P0/E*.
    reduced_mean: f64,
    area_fraction: f64,
    mean_gap: f64,
    /// Rigid-body approach `max h − s` (m).
    approach: f64,
    /// Conjugate-gradient iterations (summed over the load search under displacement control).
    iterations: usize,
    /// Percolation and σ_eff at η = 1 (`None` on a free patch: not computed).
    flow: Option<(bool, f64)>,
}

impl Solved {
    fn new(
        map: &HeightMap,
        seed: Option<u64>,
        c: &sealsim::numerical::bem::ContactSolution,
        flow: Option<(bool, f64)>,
    ) -> Self {
        Solved {
            seed,
            n: map.n,
            pixel: map.pixel,
            heights: map.heights.clone(),
            gap: c.gap.clone(),
            reduced_pressure: c.pressure.clone(),
            reduced_mean: c.mean_pressure,
            area_fraction: c.contact_fraction,
            mean_gap: c.mean_gap,
            approach: c.approach,
            iterations: c.iterations + c.coarse_iterations,
            flow,
        }
    }
}

/// The numerical level at one load: every realisation's fields.
struct NumericalPoint {
    solved: Vec<Solved>,
}

/// Why a free patch has no flow columns (the result's `flow`).
const FREE_FLOW: &str = "percolation and flow not computed: the percolation test and the \
    Reynolds cell are periodic (a seal made of copies of the cell, docs/model.md §3.5), which an \
    isolated patch on a half-space (boundary=\"free\") is not";

/// The numerical level at each load (P0/E* or the approach in m), as
/// [`sealsim::numerical::table`] solves its nodes: E* = 1, η = 1. Periodic: the numerical
/// level's own pipeline ([`reference::evaluate_loaded`]: contact, percolation, flow); free: the
/// boundary elements alone on each of its surfaces.
fn numerical_points(
    surfaces: Surfaces<'_>,
    loads: &[Load],
    boundary: Boundary,
    settings: &NumericalSettings,
) -> Result<Vec<NumericalPoint>, (String, NumericalError)> {
    let describe = |load: &Load| match load {
        Load::MeanPressure(s) => format!("P0/E* = {s:e}"),
        Load::Approach(d) => format!("approach {d:e} m"),
    };
    loads
        .iter()
        .map(|&load| {
            let mut solved = Vec::new();
            let result = match boundary {
                Boundary::Periodic => {
                    let mut observe =
                        |map: &HeightMap,
                         c: &sealsim::numerical::bem::ContactSolution,
                         r: &reference::Realisation| {
                            solved.push(Solved::new(
                                map,
                                r.seed,
                                c,
                                Some((r.percolates, r.conductance)),
                            ));
                        };
                    reference::evaluate_loaded(
                        surfaces,
                        1.0,
                        load,
                        1.0,
                        settings,
                        &mut |_, _| {},
                        &mut observe,
                    )
                    .map(|_| ())
                }
                Boundary::Free => {
                    reference::for_each_surface(surfaces, settings, &mut |map, seed, _, _| {
                        let c = bem::solve_load(map, 1.0, load, Boundary::Free, &settings.bem)
                            .map_err(NumericalError::Contact)?;
                        solved.push(Solved::new(map, seed, &c, None));
                        Ok(())
                    })
                }
            };
            result.map_err(|e| (format!("numerical level at {}: {e}", describe(&load)), e))?;
            Ok(NumericalPoint { solved })
        })
        .collect()
}

/// The ensemble mean of one scalar, as the numerical level's summary takes it
/// ([`reference::Spread::of`]: the CLI's number bit for bit).
fn ensemble(point: &NumericalPoint, get: impl Fn(&Solved) -> f64) -> f64 {
    let values: Vec<f64> = point.solved.iter().map(get).collect();
    if values.is_empty() {
        f64::NAN
    } else {
        reference::Spread::of(&values).mean
    }
}

/// The result dict at the numerical level: `table` (columns), `fields` (one dict per load:
/// `heights_m`, `gap_m`, `pressure_Pa` as f64 bytes of `realisations × n × n`, and the
/// per-realisation scalars), `n`, `pixel_size`, `realisations`, `effective_modulus`,
/// `boundary`, `control`, `tolerance` and `flow` (why the flow columns are missing, or `None`).
/// `pressures`: the prescribed nominal pressures (load control), or `None` (displacement
/// control: each realisation's mean pressure, the table's the ensemble mean).
#[allow(clippy::too_many_arguments)]
fn numerical_result<'py>(
    py: Python<'py>,
    points: &[NumericalPoint],
    pressures: Option<&[f64]>,
    e_star: f64,
    viscosity: f64,
    boundary: Boundary,
    tolerance: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let (n, pixel) = points
        .first()
        .and_then(|p| p.solved.first())
        .map_or((0, f64::NAN), |s| (s.n, s.pixel));
    let flow = boundary == Boundary::Periodic;
    let table = PyDict::new(py);
    let column =
        |f: &dyn Fn(&NumericalPoint) -> f64| -> Vec<f64> { points.iter().map(f).collect() };
    let nominal: Vec<f64> = match pressures {
        Some(p) => p.to_vec(),
        None => column(&|p| ensemble(p, |s| s.reduced_mean) * e_star),
    };
    table.set_item("nominal_pressure_Pa", nominal.clone())?;
    table.set_item(
        "reduced_pressure",
        nominal.iter().map(|p| p / e_star).collect::<Vec<f64>>(),
    )?;
    table.set_item("approach_m", column(&|p| ensemble(p, |s| s.approach)))?;
    table.set_item(
        "area_fraction",
        column(&|p| ensemble(p, |s| s.area_fraction)),
    )?;
    table.set_item("mean_gap_m", column(&|p| ensemble(p, |s| s.mean_gap)))?;
    let conductance = |p: &NumericalPoint| ensemble(p, |s| s.flow.map_or(f64::NAN, |f| f.1));
    let percolating = |p: &NumericalPoint| {
        let count = p
            .solved
            .iter()
            .filter(|s| s.flow.is_some_and(|f| f.0))
            .count();
        count as f64 / p.solved.len().max(1) as f64
    };
    if flow {
        table.set_item(
            "percolates",
            points
                .iter()
                .map(|p| percolating(p) > 0.0)
                .collect::<Vec<bool>>(),
        )?;
        table.set_item("percolating_fraction", column(&percolating))?;
        table.set_item(
            "conductance_m3_per_Pa_s",
            column(&|p| conductance(p) / viscosity),
        )?;
        // the numerical table's node value, as `sealsim leak` reports it (blank there: NaN here)
        table.set_item(
            "u_c_m",
            column(&|p| {
                let cubed = 12.0 * conductance(p);
                if cubed > 0.0 { cubed.cbrt() } else { f64::NAN }
            }),
        )?;
    }
    let fields = PyList::empty(py);
    for point in points {
        let f = PyDict::new(py);
        let all = |get: fn(&Solved) -> &Vec<f64>| point.solved.iter().flat_map(get).copied();
        f.set_item("heights_m", float_column(py, all(|s| &s.heights)))?;
        f.set_item("gap_m", float_column(py, all(|s| &s.gap)))?;
        f.set_item(
            "pressure_Pa",
            float_column(py, all(|s| &s.reduced_pressure).map(|p| p * e_star)),
        )?;
        let scalar =
            |get: &dyn Fn(&Solved) -> f64| point.solved.iter().map(get).collect::<Vec<f64>>();
        f.set_item("area_fraction", scalar(&|s| s.area_fraction))?;
        f.set_item("mean_gap_m", scalar(&|s| s.mean_gap))?;
        f.set_item("approach_m", scalar(&|s| s.approach))?;
        f.set_item("mean_pressure_Pa", scalar(&|s| s.reduced_mean * e_star))?;
        f.set_item(
            "iterations",
            point
                .solved
                .iter()
                .map(|s| s.iterations)
                .collect::<Vec<usize>>(),
        )?;
        if flow {
            f.set_item(
                "percolates",
                point
                    .solved
                    .iter()
                    .map(|s| s.flow.is_some_and(|f| f.0))
                    .collect::<Vec<_>>(),
            )?;
            f.set_item(
                "conductance_m3_per_Pa_s",
                scalar(&|s| s.flow.map_or(f64::NAN, |f| f.1) / viscosity),
            )?;
        }
        f.set_item(
            "seed",
            point.solved.iter().map(|s| s.seed).collect::<Vec<_>>(),
        )?;
        fields.append(f)?;
    }
    let out = PyDict::new(py);
    out.set_item("level", "numerical")?;
    out.set_item("table", table)?;
    out.set_item("fields", fields)?;
    out.set_item("n", n)?;
    out.set_item("pixel_size", pixel)?;
    out.set_item("realisations", points.first().map_or(0, |p| p.solved.len()))?;
    out.set_item("effective_modulus", e_star)?;
    out.set_item("viscosity", viscosity)?;
    out.set_item(
        "boundary",
        match boundary {
            Boundary::Periodic => "periodic",
            Boundary::Free => "free",
        },
    )?;
    out.set_item(
        "control",
        if pressures.is_some() {
            "pressure"
        } else {
            "displacement"
        },
    )?;
    out.set_item("tolerance", tolerance)?;
    out.set_item("flow", if flow { None } else { Some(FREE_FLOW) })?;
    Ok(out)
}

/// A rigid-body approach (m): a float in m or a string with its unit ("1 um"), finite; zero or
/// negative (the body above the highest point) is allowed and gives no contact.
fn approach(value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let d = if value.is_instance_of::<PyString>() {
        let text: String = value.extract()?;
        units::parse_quantity(&text, Dimension::LENGTH)
            .map_err(|e| bad(format!("displacement \"{text}\": {e}")))?
    } else {
        value.extract::<f64>()?
    };
    if d.is_finite() {
        Ok(d)
    } else {
        Err(bad(format!(
            "displacement must be a finite rigid-body approach (m), got {d}"
        )))
    }
}

/// The solver tolerance: `None` the core's default, else in (0, 1).
fn tolerance(value: Option<f64>) -> PyResult<Option<f64>> {
    match value {
        Some(t) if !(t.is_finite() && t > 0.0 && t < 1.0) => Err(bad(format!(
            "tolerance must lie in (0, 1) (the boundary elements' relative convergence \
             threshold; default 1e-8), got {t}"
        ))),
        other => Ok(other),
    }
}

/// The elastic half-space's lateral boundary: "periodic" (default) or "free".
fn boundary(value: Option<&str>) -> PyResult<Boundary> {
    match value {
        None | Some("periodic") => Ok(Boundary::Periodic),
        Some("free") => Ok(Boundary::Free),
        Some(other) => Err(bad(format!(
            "boundary must be \"periodic\" (the map is one cell of a periodic surface) or \
             \"free\" (an isolated patch on a half-space), got \"{other}\""
        ))),
    }
}

/// The contact problem on its own (python/sealsim/__init__.py `contact` documents it): at each
/// nominal pressure \[Pa\] (or, at the numerical level, each rigid-body approach `displacement`
/// \[m\]), at an analytic level Persson's A/A0 at full magnification, ū(ζ = 1) and the critical
/// junction; at the numerical level the boundary-element A/A0, ū and approach, the percolation
/// verdict, the Reynolds conductance (periodic cell only) and the fields. `height_map`: the
/// native `f64` bytes of a C-contiguous array of `shape` (ny, nx), heights in `height_unit`
/// (default m), `pixel_size` m or a string with its unit. `tolerance`: the boundary elements'
/// (default 1e-8); `boundary`: "periodic" or "free". The dict's `height_warning`: the unit-slip
/// warning of implausible heights, or `None`.
#[pyfunction]
#[pyo3(signature = (pressures = None, scenario = None, youngs_modulus = None, poisson_ratio = 0.5,
                    rms_roughness = None, hurst_exponent = None, q0 = None, q1 = None,
                    height_map = None, shape = None, pixel_size = None, fidelity = None,
                    viscosity = None, height_unit = None, displacement = None,
                    tolerance = None, boundary = None))]
#[allow(clippy::too_many_arguments)]
fn _contact<'py>(
    py: Python<'py>,
    pressures: Option<Vec<Bound<'py, PyAny>>>,
    scenario: Option<&PyScenario>,
    youngs_modulus: Option<f64>,
    poisson_ratio: f64,
    rms_roughness: Option<f64>,
    hurst_exponent: Option<f64>,
    q0: Option<f64>,
    q1: Option<f64>,
    height_map: Option<Bound<'py, PyBytes>>,
    shape: Option<(usize, usize)>,
    pixel_size: Option<Bound<'py, PyAny>>,
    fidelity: Option<&str>,
    viscosity: Option<f64>,
    height_unit: Option<&str>,
    displacement: Option<Vec<Bound<'py, PyAny>>>,
    tolerance: Option<f64>,
    boundary: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    // the arguments read here (a panic in it an InternalError), the heights copied out of
    // their bytes object; everything else on the worker (a map's spectrum estimate, its
    // checks and the solves take seconds on a large map)
    let request = guarded(|| {
        let (pressures, approaches) = loads(pressures, displacement)?;
        let tolerance = self::tolerance(tolerance)?;
        let boundary = self::boundary(boundary)?;
        let pixel_size = pixel(pixel_size.as_ref())?;
        let unit = match height_unit {
            Some(text) => crate::surface::height_unit(text)?,
            None => 1.0,
        };
        let heights = match (height_map, shape) {
            (Some(h), Some(shape)) => Some((map_bytes(h.as_bytes(), shape)?, shape)),
            (Some(_), None) => return Err(bad("height_map needs its shape".to_owned())),
            (None, _) => None,
        };
        Ok(Request {
            pressures,
            approaches,
            tolerance,
            boundary,
            pixel_size,
            unit,
            heights,
            // raised on the worker after the heights' own checks, as always
            level: self::fidelity(fidelity),
            scenario: scenario.map(|s| Arc::clone(&s.inner)),
            youngs_modulus,
            poisson_ratio,
            spectrum: [rms_roughness, hurst_exponent, q0, q1],
            viscosity,
        })
    })?;
    match blocking(py, move || solve(request))?? {
        Outcome::Analytic {
            level,
            rows,
            warning,
        } => analytic_result(py, level, &rows, warning),
        Outcome::Numerical {
            points,
            pressures,
            e_star,
            viscosity,
            boundary,
            tolerance,
            warning,
        } => {
            let out = numerical_result(
                py,
                &points,
                pressures.as_deref(),
                e_star,
                viscosity,
                boundary,
                tolerance,
            )?;
            out.set_item("height_warning", warning)?;
            Ok(out)
        }
    }
}

/// Load control (nominal pressures, Pa) or displacement control (approaches, m): exactly one.
type Loads = (Option<Vec<f64>>, Option<Vec<f64>>);

/// The loads of `_contact` from its `pressures` and `displacement`.
fn loads(
    pressures: Option<Vec<Bound<'_, PyAny>>>,
    displacement: Option<Vec<Bound<'_, PyAny>>>,
) -> PyResult<Loads> {
    match (pressures, displacement) {
        (Some(_), Some(_)) => Err(bad(
            "give either pressures (load control) or displacement (the rigid-body approach), \
             not both"
                .to_owned(),
        )),
        (None, None) => Err(bad(
            "give pressures (nominal pressures, Pa) or displacement (rigid-body approaches, m)"
                .to_owned(),
        )),
        (Some(p), None) => Ok((
            Some(p.iter().map(pressure).collect::<PyResult<Vec<f64>>>()?),
            None,
        )),
        (None, Some(d)) => Ok((
            None,
            Some(d.iter().map(approach).collect::<PyResult<Vec<f64>>>()?),
        )),
    }
}

/// The pixel size: "0.5 um" by the scenario files' parser, or a float in m.
fn pixel(value: Option<&Bound<'_, PyAny>>) -> PyResult<Option<f64>> {
    match value {
        Some(v) if v.is_instance_of::<PyString>() => {
            let text: String = v.extract()?;
            Ok(Some(
                units::parse_quantity(&text, Dimension::LENGTH)
                    .map_err(|e| bad(format!("pixel_size: {e}")))?,
            ))
        }
        Some(v) => Ok(Some(v.extract::<f64>()?)),
        None => Ok(None),
    }
}

/// `_contact`'s arguments as plain values, for the worker.
struct Request {
    pressures: Option<Vec<f64>>,
    approaches: Option<Vec<f64>>,
    tolerance: Option<f64>,
    boundary: Boundary,
    pixel_size: Option<f64>,
    /// m per unit of the heights.
    unit: f64,
    /// The heights' native f64 bytes and their shape (ny, nx).
    heights: Option<(Vec<u8>, (usize, usize))>,
    /// The level asked for (an unknown name: the error, raised in its turn).
    level: PyResult<Option<Fidelity>>,
    scenario: Option<Arc<Scenario>>,
    youngs_modulus: Option<f64>,
    poisson_ratio: f64,
    /// rms_roughness, hurst_exponent, q0, q1.
    spectrum: [Option<f64>; 4],
    viscosity: Option<f64>,
}

/// What the worker solved, for the calling thread to turn into Python objects.
enum Outcome {
    Analytic {
        level: Fidelity,
        rows: Vec<[f64; 7]>,
        warning: Option<String>,
    },
    Numerical {
        points: Vec<NumericalPoint>,
        pressures: Option<Vec<f64>>,
        e_star: f64,
        viscosity: f64,
        boundary: Boundary,
        tolerance: f64,
        warning: Option<String>,
    },
}

/// The contact problem of `r` solved (on the worker): the height map read and checked, the
/// problem set up, then Persson's theory or the boundary elements.
fn solve(r: Request) -> PyResult<Outcome> {
    let map = r
        .heights
        .map(|(bytes, shape)| topography(&bytes, shape, r.pixel_size, r.unit))
        .transpose()?;
    let warning = map.as_ref().and_then(|m| height_warning(m, r.unit));
    let [rms_roughness, hurst_exponent, q0, q1] = r.spectrum;
    let pb = problem(
        r.scenario.as_deref(),
        map,
        r.youngs_modulus,
        r.poisson_ratio,
        rms_roughness,
        hurst_exponent,
        q0,
        q1,
        r.level?,
        r.viscosity,
    )?;
    match pb.level {
        Some(level) => {
            // the boundary elements' keywords mean nothing to Persson's theory
            let numerical_only = [
                r.approaches.is_some().then_some("displacement"),
                (r.boundary == Boundary::Free).then_some("boundary=\"free\""),
                r.tolerance.is_some().then_some("tolerance"),
            ];
            let named: Vec<&str> = numerical_only.into_iter().flatten().collect();
            if !named.is_empty() {
                return Err(bad(format!(
                    "{} need(s) the numerical level (boundary elements on a height map), not \
                     {}: pass a height_map or fidelity=\"numerical\"",
                    named.join(", "),
                    level.name()
                )));
            }
            let spectrum = pb
                .spectrum
                .ok_or_else(|| internal("no spectrum for an analytic level"))?;
            let pressures = r
                .pressures
                .ok_or_else(|| internal("no pressures at an analytic level"))?;
            let rows = analytic_rows(spectrum, pb.settings, level, pb.e_star, &pressures);
            Ok(Outcome::Analytic {
                level,
                rows,
                warning,
            })
        }
        None => numerical(
            pb,
            r.pressures,
            r.approaches,
            r.boundary,
            r.tolerance,
            warning,
        ),
    }
}

/// A height map's unit-slip warning (heights in µm passed as m still make a spectrum: the
/// likely slip, docs/model.md §2.4), or `None`.
fn height_warning(m: &Topography, unit: f64) -> Option<String> {
    HeightStatistics::of_map(m.nx, m.ny, m.pixel, &m.heights)
        .warning(Some(unit))
        .map(|(text, likely)| match likely {
            Some(likely) => format!(
                "contact: height_map: {text}; pass height_unit=\"{likely}\" [docs/model.md §2.4]"
            ),
            None => format!("contact: height_map: {text} [docs/model.md §2.4]"),
        })
}

/// The numerical level of [`solve`] at each load.
fn numerical(
    pb: Problem,
    pressures: Option<Vec<f64>>,
    approaches: Option<Vec<f64>>,
    boundary: Boundary,
    tolerance: Option<f64>,
    warning: Option<String>,
) -> PyResult<Outcome> {
    let Problem {
        spectrum,
        e_star,
        viscosity,
        map,
        mut numerical,
        ..
    } = pb;
    if let Some(t) = tolerance {
        numerical.bem.tolerance = t;
    }
    // the solves run at E* = 1: pressures reduced, approaches (m) as they are
    let loads: Vec<Load> = match (&pressures, &approaches) {
        (Some(p), _) => p.iter().map(|p| Load::MeanPressure(p / e_star)).collect(),
        (None, Some(d)) => d.iter().map(|&d| Load::Approach(d)).collect(),
        (None, None) => return Err(internal("no load")),
    };
    let surfaces = match (&map, &spectrum) {
        (Some(m), _) => Surfaces::Map(m),
        (None, Some(sp)) => Surfaces::Synthetic(sp),
        (None, None) => return Err(internal("numerical level: no surface")),
    };
    let points =
        numerical_points(surfaces, &loads, boundary, &numerical).map_err(|(text, e)| match e {
            // an approach at or beyond a periodic cell's full contact is the caller's
            NumericalError::Contact(BemError::InvalidApproach { .. }) => bad(text),
            _ => internal(text),
        })?;
    Ok(Outcome::Numerical {
        points,
        pressures,
        e_star,
        viscosity,
        boundary,
        tolerance: numerical.bem.tolerance,
        warning,
    })
}

/// The analytic level's result dict: `level`, `table` (one row per pressure) and
/// `height_warning`.
fn analytic_result<'py>(
    py: Python<'py>,
    level: Fidelity,
    rows: &[[f64; 7]],
    warning: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let table = PyDict::new(py);
    for (k, name) in [
        "nominal_pressure_Pa",
        "reduced_pressure",
        "area_fraction",
        "mean_gap_m",
        "zeta_c",
        "u_c_m",
        "lambda_c_m",
    ]
    .into_iter()
    .enumerate()
    {
        table.set_item(name, rows.iter().map(|r| r[k]).collect::<Vec<f64>>())?;
    }
    let out = PyDict::new(py);
    out.set_item("level", level.name())?;
    out.set_item("table", table)?;
    out.set_item("height_warning", warning)?;
    Ok(out)
}

/// Adds `_contact` and its shape check to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_contact, m)?)?;
    m.add_function(wrap_pyfunction!(_height_map_shape, m)?)
}
