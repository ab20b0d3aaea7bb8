//! Frictionless normal contact of an elastic half-space with a rigid rough surface: FFT boundary
//! elements solved by the constrained conjugate-gradient method of Polonsky & Keer (Wear 231
//! (1999) 206), load-controlled to a prescribed mean nominal pressure (docs/model.md §3.5), or
//! displacement-controlled to a prescribed rigid-body approach ([`solve_displacement`]).
//!
//! # Geometry and sign conventions
//!
//! The rigid surface has heights `h(x)` (m, [`HeightMap`], peaks positive). The elastic body
//! (effective modulus `E* = E/(1 − ν²)`, or the combined `1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂`)
//! presses on it from above; its undeformed surface sits at `z = s` and a compressive pressure
//! `p ≥ 0` pushes its surface back by the normal displacement `u(x) = (K p)(x)`. The
//! interfacial separation (gap) is
//!
//! ```text
//! g(x) = s + u(x) − h(x) ≥ 0,     p(x) ≥ 0,     p(x) g(x) = 0,     ⟨p⟩ = p̄ (target).
//! ```
//!
//! This is the minimum of the complementary energy `½ pᵀKp − pᵀh` over `p ≥ 0` with the load
//! constraint; `s` is its Lagrange multiplier. The reported `approach` is `max h − s`, the overlap
//! of the undeformed surfaces (the Hertz indentation δ for a single sphere).
//!
//! # Elastic kernel
//!
//! * [`Boundary::Periodic`] — the continuous half-space compliance sampled at the grid's
//!   wavevectors, `ũ(q) = 2 p̃(q) / (E* |q|)` for `q ≠ 0` (the 2-D Fourier transform of
//!   Boussinesq's `u = F/(π E* r)`). The `q = 0` mode (an infinite mean displacement for a
//!   periodic load) is absorbed in the rigid-body position: `u` has zero mean, so `s` is the mean
//!   plane of the deformed elastic surface and the mean gap is `s − ⟨h⟩`. Pixel pressures are
//!   treated as samples of a band-limited field (no pixel-shape factor), the usual choice for
//!   rough-surface studies (Stanley & Kato 1997; Campañá & Müser 2006).
//! * [`Boundary::Free`] — an isolated `n × n` patch on an infinite half-space: pressure on a
//!   uniformly loaded square pixel of side `Δ` displaces the surface point `(x, y)` by Love's
//!   (1929) closed form (Johnson, *Contact Mechanics*, §3.9),
//!
//!   ```text
//!   u = p/(π E*) Σ_corners ± F(x ∓ Δ/2, y ∓ Δ/2),   F(x, y) = x asinh(y/|x|) + y asinh(x/|y|),
//!   ```
//!
//!   and the linear (non-periodic) convolution is evaluated exactly by zero-padding to `2n`
//!   (the DC-FFT method, Liu, Wang & Liu, Wear 243 (2000) 101).
//!
//! # Iteration
//!
//! Polonsky & Keer's scheme: conjugate gradients on the set of points carrying pressure, the
//! gap's mean over that set removed (the load constraint), negative pressures clipped to zero,
//! non-contact points that penetrate the surface re-admitted, and after each step the pressure
//! rescaled to the exact target load. Two departures from the paper, both measured to converge
//! faster and neither changing the solution:
//!
//! * re-admitted points join the working set of the next conjugate-gradient step (the
//!   bound-constrained CG form of Vollebregt, JOTA 162 (2014) 931) instead of PK's separate
//!   `p −= τ g` update, which keeps the step dimensionally consistent when preconditioned;
//! * conjugacy is kept when the working set changes (PK restart it whenever points are
//!   re-admitted), with a steepest-descent restart if the direction stops being one of descent.
//!   On the benchmark surface at 512² (cold start) this took the preconditioned iteration from
//!   39 to 32 steps and the plain one from 101 to 95.
//!
//! Two accelerations, each behind a flag of [`BemSettings`]:
//!
//! * `preconditioned` — the search direction is `Π S Π g`, with `S` the full-contact stiffness
//!   `p̃ = (E* |q| / 2) ũ` (the exact inverse of `K` in full contact) and `Π` the projection on
//!   the working set with zero mean;
//! * `coarse_to_fine` — the problem is first solved on a grid of half the resolution (heights
//!   low-passed: Fourier truncation for a periodic map, 2 × 2 averaging for a free one),
//!   recursively down to [`COARSEST`] points a side, each coarse level only to a relative
//!   change of 10⁻², and the pressure is interpolated up (bilinear) as the starting guess.
//!
//! Convergence: the relative pressure change of one iteration `Σ|Δp| / Σp` (PK's criterion) and
//! the rms misfit of the gap on the working set relative to the rms height, both below
//! `tolerance`.
//!
//! The convolutions are [`Convolver`]'s ([`Fft2`] is used only for set-up): rows, then columns
//! in cache-sized tiles with the multiplier applied between the forward and inverse column
//! transforms, so no full transposes, on up to `threads` scoped threads.
//!
//! # Cost
//!
//! One iteration costs two FFT convolutions (`S g`, `K t`), three while the contact set still
//! loses points to clipping (`K p` is then recomputed; otherwise `u` is updated as
//! `c (u − τ K t)`), plus a few streaming passes. Memory: about 9 fields of `n²` values (≈ 300 MB
//! at 2048²); `Free` works on `(2n)²` FFT grids. On the benchmark surface (`benches/bem.rs`:
//! H = 0.8, 8 pixels per shortest wavelength, A/A0 ≈ 0.2, tolerance 1e-8; one FFT thread on a
//! shared 2-core VM) the default settings took 25, 31, 41 iterations on 512², 1024², 2048²
//! (plus coarse levels worth a few more) in about 0.2–0.4 s, 1.5–3 s and 8–9 s; without the
//! preconditioner 96, 129, 172 iterations and 3–4 times as long.

use std::fmt;

use super::HeightMap;
use crate::math::fft::{Complex, Convolver, Fft2, signed_index};
use crate::units::show;

/// Coarse-to-fine recursion stops at grids with fewer points a side than this (or odd ones).
pub const COARSEST: usize = 32;

/// FFT grids smaller than this a side are transformed on one thread whatever
/// [`BemSettings::threads`] says (a pass is then too short to pay for a thread).
pub const PARALLEL_MIN: usize = 512;

/// The coarse levels of the warm start are solved to this relative tolerance (or the fine one,
/// if looser): they only supply a starting guess.
const COARSE_TOLERANCE: f64 = 1e-2;

/// Solver settings.
#[derive(Debug, Clone, PartialEq)]
pub struct BemSettings {
    /// Convergence threshold on the relative pressure change per iteration `Σ|Δp|/Σp` and on the
    /// rms gap misfit in the contact set relative to the rms height. Default 1e-8.
    pub tolerance: f64,
    /// Iteration limit on the finest grid (each coarse level gets the same). Default 20 000.
    pub max_iterations: usize,
    /// Fourier stiffness (|q|) preconditioner in the conjugate-gradient step. Default on.
    pub preconditioned: bool,
    /// Warm start from the solution on successively halved grids. Default on.
    pub coarse_to_fine: bool,
    /// Threads for the FFTs (scoped threads per transform pass, only on FFT grids of at least
    /// [`PARALLEL_MIN`] points a side; 0 counts as 1). The result is bit-identical for any
    /// count. Default: the available parallelism, at most 2 (1024² on a quiet 2-core machine:
    /// 1.32 s → 0.88 s). With the second core busy elsewhere a second thread costs time instead
    /// (every pass waits for the slower thread): set 1 there.
    pub threads: usize,
}

impl Default for BemSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-8,
            max_iterations: 20_000,
            preconditioned: true,
            coarse_to_fine: true,
            // asked once per process: the query reads cgroup files, and every scenario's
            // validation makes default settings (a study validates one per case)
            threads: {
                static THREADS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
                *THREADS.get_or_init(|| {
                    std::thread::available_parallelism().map_or(1, |t| t.get().min(2))
                })
            },
        }
    }
}

/// Lateral boundary condition of the elastic half-space.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Boundary {
    /// The map is one cell of a periodic surface (rough-surface studies).
    Periodic,
    /// The map is an isolated patch on an infinite half-space, unloaded outside it (zero-padded
    /// DC-FFT; single asperities such as the Hertz check).
    Free,
}

/// Result of [`solve`]. Fields are on the map's grid (`heights[iy * n + ix]` layout).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSolution {
    /// Contact pressure (Pa), ≥ 0; its mean over the cell equals the requested mean pressure.
    pub pressure: Vec<f64>,
    /// Mean of `pressure` over the cell (Pa): the requested mean pressure under load control
    /// ([`solve`]), the one the approach needs under displacement control
    /// ([`solve_displacement`]).
    pub mean_pressure: f64,
    /// Interfacial separation `s + u − h` (m), ≥ 0, exactly 0 where `pressure > 0`.
    pub gap: Vec<f64>,
    /// Fraction of points in contact (`pressure > 0`), A/A0.
    pub contact_fraction: f64,
    /// Mean of `gap` over the cell (m), the mean interfacial separation ū.
    pub mean_gap: f64,
    /// Rigid-body approach `max h − s` (m): overlap of the undeformed surfaces.
    pub approach: f64,
    /// Conjugate-gradient iterations on the finest grid (under displacement control: summed
    /// over the load-controlled solves of the search, [`solve_displacement`]).
    pub iterations: usize,
    /// Iterations spent on the coarse grids of the warm start (0 without it).
    pub coarse_iterations: usize,
    /// Final residual: the larger of the relative pressure change and the relative gap misfit.
    pub residual: f64,
}

/// Reasons [`solve`] refuses or fails.
#[derive(Debug, Clone, PartialEq)]
pub enum BemError {
    /// Effective modulus not positive and finite (Pa).
    InvalidModulus(f64),
    /// Mean pressure not positive and finite (Pa).
    InvalidPressure(f64),
    /// Approach not finite, or (periodic) at or beyond full contact: the periodic cell's
    /// approach cannot exceed `max h − ⟨h⟩` (m), reached at full contact under any larger load.
    InvalidApproach {
        /// The requested approach (m).
        approach: f64,
        /// The largest approach a solution exists for (m; infinite for a free patch).
        limit: f64,
    },
    /// Grid inconsistent: `n` odd or < 2, `heights.len() ≠ n²`, or pixel not positive/finite.
    InvalidGrid(String),
    /// A height is NaN or infinite.
    NonFiniteHeights,
    /// Tolerance not positive/finite or zero iteration limit.
    InvalidSettings(String),
    /// The iteration limit was reached before the tolerance.
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// Residual reached.
        residual: f64,
    },
    /// Arithmetic broke down (overflow to a non-finite value).
    Breakdown,
}

impl fmt::Display for BemError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BemError::InvalidModulus(e) => {
                write!(
                    f,
                    "effective modulus must be positive and finite, got {} Pa",
                    show(*e)
                )
            }
            BemError::InvalidPressure(p) => {
                write!(
                    f,
                    "mean pressure must be positive and finite, got {} Pa",
                    show(*p)
                )
            }
            BemError::InvalidApproach { approach, limit } => {
                if approach.is_finite() {
                    write!(
                        f,
                        "approach {} m is at or beyond full contact: a periodic cell's approach \
                         must stay below max h − ⟨h⟩ = {} m",
                        show(*approach),
                        show(*limit)
                    )
                } else {
                    write!(f, "approach must be finite, got {} m", show(*approach))
                }
            }
            BemError::InvalidGrid(msg) => write!(f, "invalid height map: {msg}"),
            BemError::NonFiniteHeights => write!(f, "height map contains NaN or infinite values"),
            BemError::InvalidSettings(msg) => write!(f, "invalid solver settings: {msg}"),
            BemError::NotConverged {
                iterations,
                residual,
            } => write!(
                f,
                "contact solver did not converge in {iterations} iterations (residual {})",
                show(*residual)
            ),
            BemError::Breakdown => write!(f, "contact solver broke down (non-finite values)"),
        }
    }
}

impl std::error::Error for BemError {}

/// Solves the contact of an elastic half-space (`e_star` = E* in Pa) pressed on the rigid surface
/// `map` at the mean nominal pressure `mean_pressure` (Pa, averaged over the whole cell
/// `(n·pixel)²`). See the module documentation for conventions and method.
pub fn solve(
    map: &HeightMap,
    e_star: f64,
    mean_pressure: f64,
    boundary: Boundary,
    settings: &BemSettings,
) -> Result<ContactSolution, BemError> {
    validate(map, e_star, mean_pressure, settings)?;
    solve_from(map, e_star, mean_pressure, boundary, settings, None)
}

/// [`solve`] after validation, from the starting pressure `start` (any non-negative field, its
/// sum rescaled to the load) instead of the coarse-to-fine warm start when given.
fn solve_from(
    map: &HeightMap,
    e_star: f64,
    mean_pressure: f64,
    boundary: Boundary,
    settings: &BemSettings,
    start: Option<&[f64]>,
) -> Result<ContactSolution, BemError> {
    let n = map.n;
    let mut coarse_iterations = 0;
    let uniform = || vec![mean_pressure; n * n];
    let mut pressure = if let Some(start) = start {
        start.to_vec()
    } else if settings.coarse_to_fine && n.is_multiple_of(2) && n / 2 >= COARSEST {
        let coarse_settings = BemSettings {
            tolerance: settings.tolerance.max(COARSE_TOLERANCE),
            ..settings.clone()
        };
        // A failed coarse level only costs the warm start.
        match solve(
            &coarsen(map, boundary),
            e_star,
            mean_pressure,
            boundary,
            &coarse_settings,
        ) {
            Ok(coarse) => {
                coarse_iterations = coarse.iterations + coarse.coarse_iterations;
                prolong(&coarse.pressure, n / 2, boundary)
            }
            Err(_) => uniform(),
        }
    } else {
        uniform()
    };
    let mut elastic = Elastic::new(n, map.pixel, e_star, boundary, settings.threads);
    let outcome = polonsky_keer(
        &mut elastic,
        &map.heights,
        &mut pressure,
        mean_pressure,
        settings,
    )?;
    let mut solution = finish(&mut elastic, &map.heights, pressure, outcome);
    solution.coarse_iterations = coarse_iterations;
    solution.mean_pressure = mean_pressure;
    let finite = solution
        .pressure
        .iter()
        .chain(&solution.gap)
        .all(|v| v.is_finite())
        && solution.mean_gap.is_finite()
        && solution.approach.is_finite();
    if finite {
        Ok(solution)
    } else {
        Err(BemError::Breakdown)
    }
}

/// What is prescribed: the mean nominal pressure p̄ (Pa, [`solve`]) or the rigid-body approach
/// δ (m, [`solve_displacement`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Load {
    /// Load control: the mean pressure over the cell (Pa).
    MeanPressure(f64),
    /// Displacement control: the approach `max h − s` (m).
    Approach(f64),
}

/// [`solve`] or [`solve_displacement`], as `load` says.
pub fn solve_load(
    map: &HeightMap,
    e_star: f64,
    load: Load,
    boundary: Boundary,
    settings: &BemSettings,
) -> Result<ContactSolution, BemError> {
    match load {
        Load::MeanPressure(p) => solve(map, e_star, p, boundary, settings),
        Load::Approach(delta) => solve_displacement(map, e_star, delta, boundary, settings),
    }
}

/// Most load-controlled solves [`solve_displacement`] spends on finding the load.
pub const MAX_LOAD_STEPS: usize = 100;

/// Solves the contact at a prescribed rigid-body approach `approach` = δ = `max h − s` (m; the
/// overlap of the undeformed surfaces, the Hertz indentation for a single sphere) instead of a
/// prescribed load: the mean pressure p̄ (Pa) follows, [`ContactSolution::mean_pressure`].
///
/// * `δ ≤ 0` (the elastic body at or above the highest point): no contact, zero pressure, the gap
///   `s − h` (not an error).
/// * [`Boundary::Periodic`]: the approach is measured from the mean plane of the deformed
///   surface, so it cannot reach `max h − ⟨h⟩` (full contact, at any larger load):
///   [`BemError::InvalidApproach`] there. [`Boundary::Free`]: any `δ > 0`.
///
/// Method: δ(p̄) of the load-controlled problem is continuous and increasing, so p̄ is found by a
/// safeguarded secant search on `ln p̄` (a Hertz-like `δ ∝ p̄^{2/3}` first step, bisection
/// whenever the secant leaves the bracket of the solves at the final tolerance), each step a
/// load-controlled [`solve`] warm-started
/// from the previous pressure field when the load changed by less than a factor 2, at an inner
/// tolerance one tenth of the remaining approach error relative to the rms height (between
/// `tolerance/10` and 10⁻²: inexact steps while far off). Converged when the last solve ran at
/// `tolerance/10` and `|δ(p̄) − δ| ≤ tolerance · h_rms` (the scale of the load-controlled gap
/// criterion; δ itself for a flat map), or when the bracket on p̄ is narrower than `tolerance`
/// (relative). The direct displacement-controlled conjugate-gradient iteration was not used:
/// the preconditioner `S` has no mean (q = 0) mode, which the load then carries, so it would run
/// unpreconditioned (three to four times the iterations, module docs).
pub fn solve_displacement(
    map: &HeightMap,
    e_star: f64,
    approach: f64,
    boundary: Boundary,
    settings: &BemSettings,
) -> Result<ContactSolution, BemError> {
    validate(map, e_star, 1.0, settings)?;
    let h = &map.heights;
    let len = h.len();
    let h_max = h.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    let h_mean = h.iter().sum::<f64>() / len as f64;
    let limit = match boundary {
        Boundary::Periodic => h_max - h_mean,
        Boundary::Free => f64::INFINITY,
    };
    if !approach.is_finite() {
        return Err(BemError::InvalidApproach { approach, limit });
    }
    if approach <= 0.0 {
        // Above the highest point: nothing touches, the surface stays flat.
        let s = h_max - approach;
        let gap: Vec<f64> = h.iter().map(|h| (s - h).max(0.0)).collect();
        return Ok(ContactSolution {
            pressure: vec![0.0; len],
            mean_pressure: 0.0,
            contact_fraction: 0.0,
            mean_gap: gap.iter().sum::<f64>() / len as f64,
            gap,
            approach,
            iterations: 0,
            coarse_iterations: 0,
            residual: 0.0,
        });
    }
    if approach >= limit {
        return Err(BemError::InvalidApproach { approach, limit });
    }
    let scale = {
        let r = rms(h);
        if r > 0.0 { r } else { approach }
    };
    let tight = 0.1 * settings.tolerance;
    // x = ln p̄; f = δ(p̄) − δ. Bracket ends (x, f) with f < 0 and f > 0.
    let mut lo: Option<f64> = None;
    let mut hi: Option<f64> = None;
    let mut previous: Option<(f64, f64)> = None;
    let mut x = (e_star * approach / map.side()).ln();
    let mut inner = COARSE_TOLERANCE.max(tight);
    let mut warm: Option<(f64, Vec<f64>)> = None;
    let (mut iterations, mut coarse_iterations) = (0, 0);
    let mut residual = f64::INFINITY;
    for _ in 0..MAX_LOAD_STEPS {
        let p = x.exp();
        if !(p.is_finite() && p > 0.0) {
            return Err(BemError::Breakdown);
        }
        let step_settings = BemSettings {
            tolerance: inner,
            ..settings.clone()
        };
        let start = warm
            .as_ref()
            .filter(|(xw, _)| (x - xw).abs() < std::f64::consts::LN_2)
            .map(|(_, field)| field.as_slice());
        let sol = solve_from(map, e_star, p, boundary, &step_settings, start)?;
        iterations += sol.iterations;
        coarse_iterations += sol.coarse_iterations;
        let f = sol.approach - approach;
        residual = (f.abs() / scale).max(sol.residual);
        let exact = inner <= tight;
        // Only a solve at the final tolerance brackets the root: an inexact one's δ can be off
        // by more than |f| (a wrong side would exclude the root for good).
        if exact && f < 0.0 {
            lo = Some(lo.map_or(x, |l: f64| l.max(x)));
        } else if exact && f > 0.0 {
            hi = Some(hi.map_or(x, |u: f64| u.min(x)));
        }
        let narrow = matches!((lo, hi), (Some(l), Some(u)) if u - l <= settings.tolerance);
        if exact && (f.abs() <= settings.tolerance * scale || narrow) {
            return Ok(ContactSolution {
                iterations,
                coarse_iterations,
                residual,
                ..sol
            });
        }
        inner = (0.1 * f.abs() / scale).clamp(tight, COARSE_TOLERANCE.max(tight));
        let secant = previous
            .filter(|(xp, fp)| *xp != x && *fp != f)
            .map(|(xp, fp)| x - f * (x - xp) / (f - fp));
        let guess = match secant {
            Some(next) => next,
            // One point: δ ∝ p̄^{2/3} (Hertz), a factor 10 while nothing is measurable.
            None if sol.approach > 0.0 => x + 1.5 * (approach / sol.approach).ln(),
            None => x + std::f64::consts::LN_10,
        };
        // At most a factor 1000 per step, in the direction that reduces |f|.
        let max_step = 1000f64.ln();
        let mut next = x + (guess - x).clamp(-max_step, max_step);
        if !next.is_finite() || (next - x) * f > 0.0 {
            next = x - f.signum() * 4f64.ln();
        }
        if let (Some(l), Some(u)) = (lo, hi)
            && !(next > l && next < u)
        {
            next = 0.5 * (l + u);
        }
        previous = Some((x, f));
        warm = Some((x, sol.pressure));
        x = next;
    }
    Err(BemError::NotConverged {
        iterations,
        residual,
    })
}

fn validate(
    map: &HeightMap,
    e_star: f64,
    mean_pressure: f64,
    settings: &BemSettings,
) -> Result<(), BemError> {
    if !(e_star.is_finite() && e_star > 0.0) {
        return Err(BemError::InvalidModulus(e_star));
    }
    if !(mean_pressure.is_finite() && mean_pressure > 0.0) {
        return Err(BemError::InvalidPressure(mean_pressure));
    }
    let n = map.n;
    if n < 2 || !n.is_multiple_of(2) {
        return Err(BemError::InvalidGrid(format!(
            "points per side must be even and at least 2, got {n}"
        )));
    }
    if n.checked_mul(n) != Some(map.heights.len()) {
        return Err(BemError::InvalidGrid(format!(
            "{} heights for a {n} × {n} grid",
            map.heights.len()
        )));
    }
    if !(map.pixel.is_finite() && map.pixel > 0.0) {
        return Err(BemError::InvalidGrid(format!(
            "pixel size must be positive and finite, got {} m",
            show(map.pixel)
        )));
    }
    if map.heights.iter().any(|h| !h.is_finite()) {
        return Err(BemError::NonFiniteHeights);
    }
    if !(settings.tolerance.is_finite() && settings.tolerance > 0.0) {
        return Err(BemError::InvalidSettings(format!(
            "tolerance must be positive and finite, got {}",
            show(settings.tolerance)
        )));
    }
    if settings.max_iterations == 0 {
        return Err(BemError::InvalidSettings(
            "at least one iteration is needed".into(),
        ));
    }
    Ok(())
}

/// The elastic operator `K` (pressure → displacement) and the preconditioner `S ≈ K⁻¹` as Fourier
/// multipliers on an `m × m` FFT grid (`m = n` periodic, `2n` zero-padded).
struct Elastic {
    /// Side of the map (m) and E* (Pa), for the displacement scale of a flat map.
    side: f64,
    e_star: f64,
    /// Multiplier of `K` on the half spectrum (m/Pa, [`Convolver::columns_first`] layout); the
    /// inverse transform carries the `1/m²`.
    compliance: Vec<f64>,
    /// Multiplier of `S` on the half spectrum (Pa/m, same layout).
    stiffness: Vec<f64>,
    convolver: Convolver,
}

#[derive(Clone, Copy)]
enum Apply {
    Compliance,
    Stiffness,
}

impl Elastic {
    fn new(n: usize, pixel: f64, e_star: f64, boundary: Boundary, threads: usize) -> Self {
        let m = match boundary {
            Boundary::Periodic => n,
            Boundary::Free => 2 * n,
        };
        let half = m / 2 + 1;
        let side = m as f64 * pixel;
        let mut stiffness = vec![0.0; m * half];
        for ky in 0..m {
            let qy = 2.0 * std::f64::consts::PI * signed_index(ky, m) as f64 / side;
            for kx in 0..half {
                let qx = 2.0 * std::f64::consts::PI * kx as f64 / side;
                stiffness[ky * half + kx] = 0.5 * e_star * qx.hypot(qy);
            }
        }
        let compliance: Vec<f64> = match boundary {
            Boundary::Periodic => stiffness
                .iter()
                .map(|&s| if s > 0.0 { 1.0 / s } else { 0.0 })
                .collect(),
            Boundary::Free => {
                let mut field = vec![0.0; m * m];
                for iy in 0..m {
                    let y = wrapped_offset(iy, n) as f64 * pixel;
                    for ix in 0..m {
                        let x = wrapped_offset(ix, n) as f64 * pixel;
                        field[iy * m + ix] =
                            love_square(x, y, pixel) / (std::f64::consts::PI * e_star);
                    }
                }
                let mut fft = Fft2::new(m);
                let mut spectrum = vec![Complex::new(0.0, 0.0); m * half];
                fft.forward(&mut field, &mut spectrum);
                // The kernel is even, so its transform is real.
                spectrum.iter().map(|c| c.re).collect()
            }
        };
        Self {
            side: n as f64 * pixel,
            e_star,
            compliance: Convolver::columns_first(m, &compliance),
            stiffness: Convolver::columns_first(m, &stiffness),
            convolver: Convolver::new(n, m, if m >= PARALLEL_MIN { threads } else { 1 }),
        }
    }

    /// `output = K input` or `S input` (fields on the `n × n` map grid).
    fn apply(&mut self, which: Apply, input: &[f64], output: &mut [f64]) {
        let multiplier = match which {
            Apply::Compliance => &self.compliance,
            Apply::Stiffness => &self.stiffness,
        };
        self.convolver.apply(multiplier, input, output);
    }
}

/// Signed pixel offset of index `i` on the `2n` zero-padded grid (the entry `i = n` is never
/// used by the linear convolution of two `n`-point fields).
fn wrapped_offset(i: usize, n: usize) -> i64 {
    if i <= n {
        i as i64
    } else {
        i as i64 - 2 * n as i64
    }
}

/// `∬ dA'/|r − r'|` over the square pixel of side `a` centred at the origin, seen from `(x, y)`
/// (Love 1929): the displacement per unit pressure is this divided by `π E*`.
fn love_square(x: f64, y: f64, a: f64) -> f64 {
    // Primitive of 1/r with the single-variable terms dropped (they cancel in the corner sum).
    fn primitive(x: f64, y: f64) -> f64 {
        let fx = if x != 0.0 {
            x * (y / x.abs()).asinh()
        } else {
            0.0
        };
        let fy = if y != 0.0 {
            y * (x / y.abs()).asinh()
        } else {
            0.0
        };
        fx + fy
    }
    let (x1, x2, y1, y2) = (x - 0.5 * a, x + 0.5 * a, y - 0.5 * a, y + 0.5 * a);
    primitive(x2, y2) - primitive(x1, y2) - primitive(x2, y1) + primitive(x1, y1)
}

struct Outcome {
    iterations: usize,
    residual: f64,
}

/// Rescales `p` so that it sums to `total`.
fn normalise(p: &mut [f64], total: f64) {
    let sum: f64 = p.iter().sum();
    if sum > 0.0 {
        let c = total / sum;
        p.iter_mut().for_each(|v| *v *= c);
    } else {
        p.fill(total / p.len() as f64);
    }
}

/// Root-mean-square deviation about the mean.
fn rms(values: &[f64]) -> f64 {
    let count = values.len() as f64;
    let mean = values.iter().sum::<f64>() / count;
    (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / count).sqrt()
}

/// The constrained conjugate-gradient iteration (see the module docs), starting from `p`
/// (non-negative, any sum) and leaving the solution in it.
///
/// Passes over the grid are fused so that one iteration streams each field only a few times
/// besides the two or three operator applications (`S g`, `K t`, and `K p` after clipping); the
/// sums use four interleaved partial sums ([`sums`]), in a fixed order.
fn polonsky_keer(
    elastic: &mut Elastic,
    h: &[f64],
    p: &mut [f64],
    mean_pressure: f64,
    settings: &BemSettings,
) -> Result<Outcome, BemError> {
    let preconditioned = settings.preconditioned;
    let len = p.len();
    assert_eq!(h.len(), len);
    let total = mean_pressure * len as f64;
    normalise(p, total);
    // Gap misfit is measured against the roughness; a flat map falls back to the displacement
    // scale of the mean pressure over the cell.
    let gap_scale = {
        let r = rms(h);
        if r > 0.0 {
            r
        } else {
            mean_pressure * elastic.side / elastic.e_star
        }
    };
    let mut u = vec![0.0; len];
    let mut g = vec![0.0; len];
    let mut z = vec![0.0; len];
    let mut t = vec![0.0; len];
    let mut r = vec![0.0; len];
    // Working-set membership: bit 0 now, bit 1 the previous iteration.
    let mut active = vec![0u8; len];
    elastic.apply(Apply::Compliance, p, &mut u);
    let [mut contact_sum, mut contact_count] = contact_gap_sum(p, &u, h);
    let mut gz_old = 1.0;
    let mut residual = f64::INFINITY;
    for iteration in 1..=settings.max_iterations {
        // Gap relative to its mean over the points carrying pressure (that mean is −s); working
        // set: pressure > 0, or no pressure but penetrating.
        let gbar = contact_sum / contact_count.max(1.0);
        let [sum_a, count_a] = sums(len, |i| {
            let gi = u[i] - h[i] - gbar;
            let was = active[i] & 1;
            let now = p[i] > 0.0 || gi < 0.0;
            active[i] = (was << 1) | now as u8;
            g[i] = if now { gi } else { 0.0 };
            [g[i], now as u8 as f64]
        });
        // Projected gradient: zero mean on the working set (the load constraint).
        let count_a = count_a.max(1.0);
        let mean_a = sum_a / count_a;
        let [misfit] = sums(len, |i| {
            if active[i] & 1 == 1 {
                g[i] -= mean_a;
            }
            [g[i] * g[i]]
        });
        let gap_residual = (misfit / count_a).sqrt() / gap_scale;
        if misfit == 0.0 {
            return Ok(Outcome {
                iterations: iteration,
                residual: 0.0,
            });
        }
        // Search direction t = Π z + β t, z = S g (preconditioned) or g. Since g = Π g,
        // g·Π z = g·z and g·Π t = g·t.
        if preconditioned {
            elastic.apply(Apply::Stiffness, &g, &mut z);
        }
        let direction: &[f64] = if preconditioned { &z } else { &g };
        let [sum_z, gz] = sums(len, |i| {
            let on = (active[i] & 1) as f64;
            [on * direction[i], g[i] * direction[i]]
        });
        let mean_z = sum_z / count_a;
        // Conjugacy is kept across working-set changes (PK restart it when points are
        // re-admitted; keeping it converges markedly faster here), with a steepest-descent
        // restart whenever t stops being a descent direction.
        let mut beta = if iteration == 1 { 0.0 } else { gz / gz_old };
        gz_old = gz;
        let mut gt = 0.0;
        for _attempt in 0..2 {
            let [sum_t, dot] = sums(len, |i| {
                t[i] = if active[i] & 1 == 1 {
                    direction[i] - mean_z + beta * t[i]
                } else {
                    0.0
                };
                [t[i], g[i] * t[i]]
            });
            let mean_t = sum_t / count_a;
            for (ti, a) in t.iter_mut().zip(&active) {
                if a & 1 == 1 {
                    *ti -= mean_t;
                }
            }
            gt = dot;
            if gt > 0.0 || beta == 0.0 {
                break;
            }
            beta = 0.0;
        }
        elastic.apply(Apply::Compliance, &t, &mut r);
        let [trt] = sums(len, |i| [t[i] * r[i]]);
        let tau = gt / trt;
        if !(tau.is_finite() && tau > 0.0) {
            return Err(BemError::Breakdown);
        }
        // Step and clip; z keeps the old pressure.
        let mut clipped = false;
        let [sum_p] = sums(len, |i| {
            z[i] = p[i];
            if active[i] & 1 == 1 {
                let v = p[i] - tau * t[i];
                clipped |= v < 0.0;
                p[i] = v.max(0.0);
            }
            [p[i]]
        });
        if !(sum_p.is_finite() && sum_p > 0.0) {
            return Err(BemError::Breakdown);
        }
        // Rescale to the exact load. Without clipping the step is linear and u follows as
        // c (u − τ K t); otherwise it is recomputed.
        let c = total / sum_p;
        let change = if clipped {
            let [change] = sums(len, |i| {
                p[i] *= c;
                [(p[i] - z[i]).abs()]
            });
            elastic.apply(Apply::Compliance, p, &mut u);
            [contact_sum, contact_count] = contact_gap_sum(p, &u, h);
            change
        } else {
            let [change, sum, count] = sums(len, |i| {
                p[i] *= c;
                u[i] = c * (u[i] - tau * r[i]);
                let on = p[i] > 0.0;
                [
                    (p[i] - z[i]).abs(),
                    if on { u[i] - h[i] } else { 0.0 },
                    on as u8 as f64,
                ]
            });
            (contact_sum, contact_count) = (sum, count);
            change
        };
        let pressure_change = change / total;
        residual = pressure_change.max(gap_residual);
        if residual < settings.tolerance {
            return Ok(Outcome {
                iterations: iteration,
                residual,
            });
        }
    }
    Err(BemError::NotConverged {
        iterations: settings.max_iterations,
        residual,
    })
}

/// `[Σ (u − h), count]` over the points carrying pressure.
fn contact_gap_sum(p: &[f64], u: &[f64], h: &[f64]) -> [f64; 2] {
    sums(p.len(), |i| {
        let on = p[i] > 0.0;
        [if on { u[i] - h[i] } else { 0.0 }, on as u8 as f64]
    })
}

/// `Σ_{i < len} f(i)` for `K` quantities at once, with `f` called for `i = 0, 1, …` in order.
/// Four interleaved partial sums break the floating-point add latency chain (several times
/// faster on these memory-streaming loops); the summation order is fixed, so the result is
/// deterministic.
#[inline(always)]
fn sums<const K: usize>(len: usize, mut f: impl FnMut(usize) -> [f64; K]) -> [f64; K] {
    let mut lanes = [[0.0; K]; 4];
    let mut i = 0;
    while i + 4 <= len {
        for (lane, acc) in lanes.iter_mut().enumerate() {
            let v = f(i + lane);
            for k in 0..K {
                acc[k] += v[k];
            }
        }
        i += 4;
    }
    while i < len {
        let v = f(i);
        for k in 0..K {
            lanes[0][k] += v[k];
        }
        i += 1;
    }
    let mut out = [0.0; K];
    for k in 0..K {
        out[k] = (lanes[0][k] + lanes[1][k]) + (lanes[2][k] + lanes[3][k]);
    }
    out
}

/// Builds the solution from the converged pressure: fresh displacement, gap, statistics.
fn finish(
    elastic: &mut Elastic,
    h: &[f64],
    pressure: Vec<f64>,
    outcome: Outcome,
) -> ContactSolution {
    let len = pressure.len();
    let mut u = vec![0.0; len];
    elastic.apply(Apply::Compliance, &pressure, &mut u);
    let (mut sum, mut count) = (0.0, 0usize);
    for i in 0..len {
        if pressure[i] > 0.0 {
            sum += h[i] - u[i];
            count += 1;
        }
    }
    // Rigid-body position s: the contact points close the gap on average.
    let s = sum / count.max(1) as f64;
    let gap: Vec<f64> = (0..len)
        .map(|i| {
            if pressure[i] > 0.0 {
                0.0
            } else {
                (s + u[i] - h[i]).max(0.0)
            }
        })
        .collect();
    let h_max = h.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
    ContactSolution {
        mean_pressure: pressure.iter().sum::<f64>() / len as f64,
        contact_fraction: count as f64 / len as f64,
        mean_gap: gap.iter().sum::<f64>() / len as f64,
        approach: h_max - s,
        pressure,
        gap,
        iterations: outcome.iterations,
        coarse_iterations: 0,
        residual: outcome.residual,
    }
}

/// The map on a grid of half the resolution (pixel doubled): Fourier truncation for a periodic
/// map (samples at the even points of the fine grid), 2 × 2 block means for a free one (samples
/// at the block centres).
fn coarsen(map: &HeightMap, boundary: Boundary) -> HeightMap {
    let n = map.n;
    let nc = n / 2;
    let heights = match boundary {
        Boundary::Periodic => {
            let mut fine = Fft2::new(n);
            let mut coarse = Fft2::new(nc);
            let (hf, hc) = (fine.half(), coarse.half());
            let mut field = map.heights.clone();
            let mut spectrum = vec![Complex::new(0.0, 0.0); n * hf];
            fine.forward(&mut field, &mut spectrum);
            let scale = (nc * nc) as f64 / (n * n) as f64;
            let mut low = vec![Complex::new(0.0, 0.0); nc * hc];
            for kyc in 0..nc {
                let ky = signed_index(kyc, nc);
                if ky.unsigned_abs() as usize == nc / 2 {
                    continue;
                }
                let kyf = ky.rem_euclid(n as i64) as usize;
                for kx in 0..hc - 1 {
                    low[kyc * hc + kx] = spectrum[kyf * hf + kx] * scale;
                }
            }
            let mut out = vec![0.0; nc * nc];
            coarse.inverse(&mut low, &mut out);
            out
        }
        Boundary::Free => {
            let mut out = vec![0.0; nc * nc];
            for j in 0..nc {
                for i in 0..nc {
                    let at = |y: usize, x: usize| map.heights[y * n + x];
                    out[j * nc + i] = 0.25
                        * (at(2 * j, 2 * i)
                            + at(2 * j, 2 * i + 1)
                            + at(2 * j + 1, 2 * i)
                            + at(2 * j + 1, 2 * i + 1));
                }
            }
            out
        }
    };
    HeightMap {
        n: nc,
        pixel: 2.0 * map.pixel,
        heights,
    }
}

/// Bilinear interpolation of a coarse field (`nc²`) onto the grid of twice the resolution,
/// matching the sample positions of [`coarsen`] (periodic wrap, or clamped edges for `Free`).
fn prolong(coarse: &[f64], nc: usize, boundary: Boundary) -> Vec<f64> {
    let n = 2 * nc;
    // Fine index → (lower coarse index, upper coarse index, weight of the upper one).
    let stencil = |i: usize| -> (usize, usize, f64) {
        match boundary {
            Boundary::Periodic => {
                let j = i / 2;
                if i.is_multiple_of(2) {
                    (j, j, 0.0)
                } else {
                    (j, (j + 1) % nc, 0.5)
                }
            }
            Boundary::Free => {
                // Fine centre (i + ½)Δ sits at coarse coordinate i/2 − ¼.
                let x = i as f64 / 2.0 - 0.25;
                if x <= 0.0 {
                    (0, 0, 0.0)
                } else if x >= (nc - 1) as f64 {
                    (nc - 1, nc - 1, 0.0)
                } else {
                    let j = x.floor() as usize;
                    (j, j + 1, x - j as f64)
                }
            }
        }
    };
    let mut fine = vec![0.0; n * n];
    for iy in 0..n {
        let (y0, y1, wy) = stencil(iy);
        for ix in 0..n {
            let (x0, x1, wx) = stencil(ix);
            let v = (1.0 - wy) * ((1.0 - wx) * coarse[y0 * nc + x0] + wx * coarse[y0 * nc + x1])
                + wy * ((1.0 - wx) * coarse[y1 * nc + x0] + wx * coarse[y1 * nc + x1]);
            fine[iy * n + ix] = v;
        }
    }
    fine
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerical::surface::synthesize;
    use crate::surface::Spectrum;

    /// Self-affine H = 0.8 map, q1/q0 = n/8 (8 pixels per shortest wavelength), h_rms = 1 µm.
    fn rough(n: usize, seed: u64) -> HeightMap {
        let q0 = 1e4;
        let spectrum = Spectrum::self_affine(1e-6, 0.8, q0, q0 * (n / 8) as f64, None).unwrap();
        synthesize(&spectrum, n, seed)
    }

    fn settings(preconditioned: bool, coarse_to_fine: bool) -> BemSettings {
        BemSettings {
            preconditioned,
            coarse_to_fine,
            ..BemSettings::default()
        }
    }

    /// Raw gap `s + u − h` from the solution's pressure and approach (not clipped).
    fn raw_gap(
        map: &HeightMap,
        e_star: f64,
        boundary: Boundary,
        sol: &ContactSolution,
    ) -> Vec<f64> {
        let mut elastic = Elastic::new(map.n, map.pixel, e_star, boundary, 1);
        let mut u = vec![0.0; map.heights.len()];
        elastic.apply(Apply::Compliance, &sol.pressure, &mut u);
        let h_max = map
            .heights
            .iter()
            .cloned()
            .fold(f64::NEG_INFINITY, f64::max);
        let s = h_max - sol.approach;
        u.iter().zip(&map.heights).map(|(u, h)| s + u - h).collect()
    }

    #[test]
    fn love_kernel_centre_and_far_field() {
        // Centre of a uniformly loaded square of side a: 4 a asinh(1) (Johnson §3.9).
        let centre = love_square(0.0, 0.0, 2.0);
        assert!((centre - 8.0 * 1f64.asinh()).abs() < 1e-12);
        // Far away the pixel acts as a point load: a²/r.
        let far = love_square(300.0, 400.0, 1.0);
        assert!((far / (1.0 / 500.0) - 1.0).abs() < 1e-5, "{far}");
    }

    #[test]
    fn hertz_sphere_free_boundary() {
        // Paraboloid h = −r²/(2R) centred on pixel (128, 128) of a 256² grid, Δ = 1, R = 100:
        // load chosen for a = 50 pixels (contact 100 pixels across).
        let (n, pixel, radius, e_star) = (256, 1.0, 100.0, 1.0);
        let a_target: f64 = 50.0;
        let force = 4.0 * e_star * a_target.powi(3) / (3.0 * radius);
        let mean_pressure = force / ((n * n) as f64 * pixel * pixel);
        let heights = (0..n * n)
            .map(|i| {
                let (x, y) = ((i % n) as f64 - 128.0, (i / n) as f64 - 128.0);
                -(x * x + y * y) * pixel * pixel / (2.0 * radius)
            })
            .collect();
        let map = HeightMap { n, pixel, heights };
        for (pre, c2f) in [(true, true), (false, false)] {
            let sol = solve(
                &map,
                e_star,
                mean_pressure,
                Boundary::Free,
                &settings(pre, c2f),
            )
            .unwrap();
            let a_hertz = (3.0 * force * radius / (4.0 * e_star)).cbrt();
            let area = sol.contact_fraction * (n * n) as f64 * pixel * pixel;
            let a_num = (area / std::f64::consts::PI).sqrt();
            let err_a = a_num / a_hertz - 1.0;
            let f_hertz = 4.0 / 3.0 * e_star * radius.sqrt() * sol.approach.powf(1.5);
            let err_f = f_hertz / force - 1.0;
            let p0 = 3.0 * force / (2.0 * std::f64::consts::PI * a_hertz * a_hertz);
            let p_max = sol.pressure.iter().cloned().fold(0.0, f64::max);
            let err_p = p_max / p0 - 1.0;
            eprintln!(
                "Hertz (precond {pre}, warm {c2f}): a {err_a:+.6}, F(δ) {err_f:+.6}, p0 {err_p:+.6}, A/A0 {:.5} res {:.2e}, {} + {} iterations",
                sol.contact_fraction, sol.residual, sol.iterations, sol.coarse_iterations
            );
            assert!(err_a.abs() < 0.02, "contact radius error {err_a}");
            assert!(err_f.abs() < 0.02, "load–indentation error {err_f}");
            assert!(err_p.abs() < 0.03, "peak pressure error {err_p}");
        }
    }

    #[test]
    fn displacement_control_inverts_load_control() {
        // p̄ → δ (load control), then δ → p̄ (displacement control): the same solution back,
        // periodic and free, at the default tolerance 1e-8.
        let map = rough(128, 7);
        let e_star = 1.0;
        let s = BemSettings::default();
        for boundary in [Boundary::Periodic, Boundary::Free] {
            for load in [0.01, 0.1] {
                let p = load * map.rms_slope() * e_star;
                let by_load = solve(&map, e_star, p, boundary, &s).unwrap();
                let by_approach =
                    solve_displacement(&map, e_star, by_load.approach, boundary, &s).unwrap();
                let dp: f64 = by_load
                    .pressure
                    .iter()
                    .zip(&by_approach.pressure)
                    .map(|(a, b)| (a - b).abs())
                    .sum();
                let field = dp / by_load.pressure.iter().sum::<f64>();
                let mean = by_approach.mean_pressure / p - 1.0;
                let approach = (by_approach.approach - by_load.approach) / map.rms();
                eprintln!(
                    "{boundary:?} p̄ {p:.3e}: p̄ back {mean:+.2e}, Σ|Δp|/Σp {field:.2e}, δ {approach:+.2e}, A/A0 {} vs {}, {} iterations ({} by load)",
                    by_approach.contact_fraction,
                    by_load.contact_fraction,
                    by_approach.iterations,
                    by_load.iterations
                );
                // measured ≤ 1.3e-9 (mean) and ≤ 4.1e-9 (field) at tolerance 1e-8
                assert!(mean.abs() < 1e-8, "{boundary:?}: mean pressure {mean}");
                assert!(field < 5e-8, "{boundary:?}: pressure field {field}");
                assert!(approach.abs() <= 1e-8, "{boundary:?}: approach {approach}");
                assert!(
                    (by_approach.contact_fraction - by_load.contact_fraction).abs()
                        <= 2.0 / (128.0 * 128.0)
                );
                let mean_of_field =
                    by_approach.pressure.iter().sum::<f64>() / by_approach.pressure.len() as f64;
                assert!((mean_of_field / by_approach.mean_pressure - 1.0).abs() < 1e-12);
                assert!(by_approach.residual < 1e-8);
            }
        }
    }

    #[test]
    fn hertz_sphere_by_approach() {
        // Free paraboloid indented δ: F = (4/3) E* √R δ^{3/2}, a = √(Rδ) (Johnson 1985 §4.2).
        let (n, radius, e_star) = (128usize, 50.0, 1.0);
        let heights = (0..n * n)
            .map(|i| {
                let (x, y) = ((i % n) as f64 - 64.0, (i / n) as f64 - 64.0);
                -(x * x + y * y) / (2.0 * radius)
            })
            .collect();
        let map = HeightMap {
            n,
            pixel: 1.0,
            heights,
        };
        let delta: f64 = 12.5; // a = 25 pixels
        let sol = solve_displacement(&map, e_star, delta, Boundary::Free, &BemSettings::default())
            .unwrap();
        let force = sol.mean_pressure * (n * n) as f64;
        let hertz = 4.0 / 3.0 * e_star * radius.sqrt() * delta.powf(1.5);
        let a = (sol.contact_fraction * (n * n) as f64 / std::f64::consts::PI).sqrt();
        eprintln!(
            "Hertz by approach: F {:+.4}, a {:+.4}",
            force / hertz - 1.0,
            a / (radius * delta).sqrt() - 1.0
        );
        assert!((force / hertz - 1.0).abs() < 0.02);
        assert!((a / (radius * delta).sqrt() - 1.0).abs() < 0.02);
    }

    #[test]
    fn approach_below_the_top_touches_nothing_and_full_contact_is_refused() {
        let map = rough(32, 4);
        let s = BemSettings::default();
        let top = map
            .heights
            .iter()
            .cloned()
            .fold(f64::NEG_INFINITY, f64::max);
        for boundary in [Boundary::Periodic, Boundary::Free] {
            for delta in [0.0, -1e-7] {
                let sol = solve_displacement(&map, 1.0, delta, boundary, &s).unwrap();
                assert!(sol.pressure.iter().all(|&p| p == 0.0));
                assert_eq!((sol.mean_pressure, sol.contact_fraction), (0.0, 0.0));
                for (g, h) in sol.gap.iter().zip(&map.heights) {
                    assert_eq!(*g, top - delta - h);
                }
            }
            assert!(matches!(
                solve_displacement(&map, 1.0, f64::NAN, boundary, &s),
                Err(BemError::InvalidApproach { .. })
            ));
        }
        // periodic: the approach stays below max h − ⟨h⟩ (full contact)
        let mean = map.heights.iter().sum::<f64>() / map.heights.len() as f64;
        let full = top - mean;
        let err = solve_displacement(&map, 1.0, full, Boundary::Periodic, &s).unwrap_err();
        assert!(matches!(err, BemError::InvalidApproach { .. }), "{err}");
        assert!(err.to_string().contains("full contact"));
        // just below it: nearly full contact and a finite load; a free patch takes any approach
        let near = solve_displacement(&map, 1.0, 0.999 * full, Boundary::Periodic, &s).unwrap();
        assert!(near.contact_fraction > 0.9 && near.mean_pressure.is_finite());
        assert!(solve_displacement(&map, 1.0, 2.0 * full, Boundary::Free, &s).is_ok());
    }

    #[test]
    fn load_signs_and_complementarity() {
        let map = rough(128, 7);
        let e_star = 1.0;
        let mean_pressure = 0.05 * map.rms_slope() * e_star;
        for boundary in [Boundary::Periodic, Boundary::Free] {
            let sol = solve(
                &map,
                e_star,
                mean_pressure,
                boundary,
                &BemSettings::default(),
            )
            .unwrap();
            let mean = sol.pressure.iter().sum::<f64>() / sol.pressure.len() as f64;
            assert!(
                (mean / mean_pressure - 1.0).abs() < 1e-12,
                "load {mean} vs {mean_pressure}"
            );
            assert!(sol.pressure.iter().all(|&p| p >= 0.0 && p.is_finite()));
            assert!(sol.gap.iter().all(|&g| g >= 0.0 && g.is_finite()));
            assert!(sol.pressure.iter().zip(&sol.gap).all(|(p, g)| p * g == 0.0));
            // The unclipped gap vanishes on the contact set and is ≥ 0 elsewhere, to tolerance.
            let scale = map.rms();
            let raw = raw_gap(&map, e_star, boundary, &sol);
            let worst_contact = sol
                .pressure
                .iter()
                .zip(&raw)
                .filter(|(p, _)| **p > 0.0)
                .map(|(_, g)| g.abs())
                .fold(0.0, f64::max);
            let worst_penetration = raw.iter().map(|g| -g).fold(0.0, f64::max);
            assert!(
                worst_contact < 1e-6 * scale,
                "{boundary:?}: contact gap {worst_contact}"
            );
            assert!(
                worst_penetration < 1e-6 * scale,
                "{boundary:?}: penetration {worst_penetration}"
            );
            assert!(sol.contact_fraction > 0.0 && sol.contact_fraction < 1.0);
            assert!(sol.residual < 1e-8);
        }
    }

    #[test]
    fn flat_surface_gives_uniform_pressure() {
        let n = 32;
        let map = HeightMap {
            n,
            pixel: 1e-6,
            heights: vec![3e-7; n * n],
        };
        let sol = solve(&map, 2e6, 1e5, Boundary::Periodic, &BemSettings::default()).unwrap();
        assert_eq!(sol.contact_fraction, 1.0);
        assert!(sol.pressure.iter().all(|&p| (p / 1e5 - 1.0).abs() < 1e-14));
        assert!(sol.gap.iter().all(|&g| g == 0.0));
        assert_eq!(sol.mean_gap, 0.0);
        assert!(sol.approach.abs() < 1e-20);
    }

    #[test]
    fn preconditioned_and_plain_agree() {
        let map = rough(128, 3);
        let mean_pressure = 0.01 * map.rms_slope();
        let plain = solve(
            &map,
            1.0,
            mean_pressure,
            Boundary::Periodic,
            &settings(false, false),
        )
        .unwrap();
        for (pre, c2f) in [(true, false), (false, true), (true, true)] {
            let fast = solve(
                &map,
                1.0,
                mean_pressure,
                Boundary::Periodic,
                &settings(pre, c2f),
            )
            .unwrap();
            let diff: f64 = plain
                .pressure
                .iter()
                .zip(&fast.pressure)
                .map(|(a, b)| (a - b).abs())
                .sum();
            let total: f64 = plain.pressure.iter().sum();
            eprintln!(
                "precond {pre} warm {c2f}: {} (+{}) iterations vs plain {}; Σ|Δp|/Σp = {:.2e}",
                fast.iterations,
                fast.coarse_iterations,
                plain.iterations,
                diff / total
            );
            assert!(diff / total < 1e-6);
            assert!((fast.mean_gap / plain.mean_gap - 1.0).abs() < 1e-6);
            assert!((fast.approach / plain.approach - 1.0).abs() < 1e-6);
        }
    }

    #[test]
    fn more_load_more_contact_less_gap() {
        let map = rough(64, 11);
        let slope = map.rms_slope();
        let mut last: Option<ContactSolution> = None;
        for k in 0..8 {
            let p = slope * 0.002 * 1.6f64.powi(k);
            let sol = solve(&map, 1.0, p, Boundary::Periodic, &BemSettings::default()).unwrap();
            if let Some(prev) = &last {
                assert!(sol.contact_fraction > prev.contact_fraction);
                assert!(sol.mean_gap < prev.mean_gap);
                assert!(sol.approach > prev.approach);
            }
            last = Some(sol);
        }
    }

    #[test]
    fn deterministic_for_any_thread_count() {
        // Free boundary: the FFT grid is 2n = 512 ≥ PARALLEL_MIN, so the threads are used.
        let map = rough(256, 5);
        let p = 0.1 * map.rms_slope();
        let run = |threads| {
            let s = BemSettings {
                threads,
                ..BemSettings::default()
            };
            solve(&map, 1.0, p, Boundary::Free, &s).unwrap()
        };
        let a = run(2);
        assert_eq!(a, run(2));
        assert_eq!(a, run(1));
        assert_eq!(a, run(0));
    }

    #[test]
    fn small_grids_and_both_boundaries_work() {
        for n in [2usize, 4, 6, 64] {
            let heights: Vec<f64> = (0..n * n)
                .map(|i| 1e-6 * ((i * 7 % 11) as f64 / 11.0))
                .collect();
            let map = HeightMap {
                n,
                pixel: 1e-6,
                heights,
            };
            for boundary in [Boundary::Periodic, Boundary::Free] {
                for p in [1e-3, 1.0, 1e3] {
                    let sol = solve(&map, 1.0, p, boundary, &BemSettings::default()).unwrap();
                    let mean = sol.pressure.iter().sum::<f64>() / (n * n) as f64;
                    assert!((mean / p - 1.0).abs() < 1e-12);
                    assert!(sol.gap.iter().all(|g| *g >= 0.0));
                    assert!(sol.contact_fraction > 0.0 && sol.contact_fraction <= 1.0);
                }
            }
        }
    }

    #[test]
    fn extreme_scales_give_a_solution_or_an_error_never_nan() {
        let base = rough(32, 2);
        for scale in [1e-300, 1e-200, 1e200, 1e300] {
            for (e_star, p) in [(1.0, 1e-3), (1e300, 1e290), (1e-300, 1e-310), (1.0, 1e300)] {
                let map = HeightMap {
                    heights: base.heights.iter().map(|h| h * scale).collect(),
                    ..base.clone()
                };
                for boundary in [Boundary::Periodic, Boundary::Free] {
                    if let Ok(sol) = solve(&map, e_star, p, boundary, &BemSettings::default()) {
                        assert!(sol.pressure.iter().chain(&sol.gap).all(|v| v.is_finite()));
                        assert!(sol.mean_gap.is_finite() && sol.approach.is_finite());
                    }
                }
            }
        }
    }

    #[test]
    fn rejects_bad_input() {
        let map = rough(16, 1);
        let s = BemSettings::default();
        let per = Boundary::Periodic;
        assert!(matches!(
            solve(&map, 0.0, 1.0, per, &s),
            Err(BemError::InvalidModulus(_))
        ));
        assert!(matches!(
            solve(&map, f64::NAN, 1.0, per, &s),
            Err(BemError::InvalidModulus(_))
        ));
        assert!(matches!(
            solve(&map, 1.0, -1.0, per, &s),
            Err(BemError::InvalidPressure(_))
        ));
        assert!(matches!(
            solve(&map, 1.0, f64::INFINITY, per, &s),
            Err(BemError::InvalidPressure(_))
        ));
        let mut bad = map.clone();
        bad.heights.pop();
        assert!(matches!(
            solve(&bad, 1.0, 1.0, per, &s),
            Err(BemError::InvalidGrid(_))
        ));
        let odd = HeightMap {
            n: 3,
            pixel: 1.0,
            heights: vec![0.0; 9],
        };
        assert!(matches!(
            solve(&odd, 1.0, 1.0, per, &s),
            Err(BemError::InvalidGrid(_))
        ));
        let mut nan = map.clone();
        nan.heights[3] = f64::NAN;
        assert!(matches!(
            solve(&nan, 1.0, 1.0, per, &s),
            Err(BemError::NonFiniteHeights)
        ));
        let mut zero_pixel = map.clone();
        zero_pixel.pixel = 0.0;
        assert!(matches!(
            solve(&zero_pixel, 1.0, 1.0, per, &s),
            Err(BemError::InvalidGrid(_))
        ));
        let few = BemSettings {
            max_iterations: 1,
            coarse_to_fine: false,
            ..s.clone()
        };
        let p = 0.01 * map.rms_slope();
        assert!(matches!(
            solve(&map, 1.0, p, per, &few),
            Err(BemError::NotConverged { .. })
        ));
        let bad_tol = BemSettings {
            tolerance: 0.0,
            ..s
        };
        assert!(matches!(
            solve(&map, 1.0, p, per, &bad_tol),
            Err(BemError::InvalidSettings(_))
        ));
    }
}
