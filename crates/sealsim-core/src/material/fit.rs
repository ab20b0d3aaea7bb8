//! Prony series fitted to measured relaxation or DMA data (docs/model.md §5, "Fitting").
//!
//! The relaxation times are fixed on a log-spaced grid, so the model is linear in its
//! unknowns, E∞ ≥ 0 and E_i ≥ 0, and the fit is a non-negative least-squares problem
//! ([`crate::math::nnls`], Lawson & Hanson 1974): no starting guess, a global optimum,
//! and no negative moduli (which would make the material store energy it never received).
//!
//! * Grid: `terms_per_decade` = N (0.25–4, fractional allowed: 0.5 is one τ every two
//!   decades) τ per decade, log-spaced (rounded to 4 significant digits) over the data window
//!   widened by one decade on each side, so that relaxation just outside the window can still
//!   be represented: relaxation data `[t_min/10, 10 t_max]`; DMA data
//!   `\[1/(10 ω_max), 10/ω_min\]` (a branch shows in E″ around ωτ = 1). A window of `d`
//!   decades gets `⌈d N⌉ + 1` terms, both ends included, so the spacing is `d/⌈d N⌉ ≤ 1/N`
//!   decades (exactly 1/N when `d N` is whole).
//! * Relaxation rows: `E∞ + Σ E_i e^{−t_k/τ_i} ≈ E_k`.
//!   DMA rows (stacked): `E∞ + Σ E_i ω_k²τ_i²/(1+ω_k²τ_i²) ≈ E′_k` and
//!   `Σ E_i ω_kτ_i/(1+ω_k²τ_i²) ≈ E″_k`.
//! * Relative least squares: each row is divided by its datum, so that every point counts
//!   by its relative error (the modulus of a rubber spans three decades from the glassy to
//!   the rubbery side). The unknowns are scaled by the largest datum, so that the matrix is
//!   of order one.
//! * Terms that come out empty (exactly 0 from NNLS, or below 1e-12 of E0) are dropped.
//!
//! Regularisation (default [`Regularisation::Gcv`]): NNLS passes noise straight through to
//! the moduli, so the default fit minimises, over x ≥ 0,
//!
//! `Σ_k (model_k/datum_k − 1)² + λ² Σ_i (x̃_{i−1} − 2 x̃_i + x̃_{i+1})²`, `x̃_i = E_i/E_ref(τ_i)`,
//!
//! a Tikhonov penalty on the second difference (in log τ: the grid is uniform there) of the
//! *relative* spectrum. `E_ref(τ)` is the unregularised (pilot) fit's E(t) at t = τ, clamped to
//! the data window: a smooth, positive local modulus level, so that λ is dimensionless and the
//! penalty does not let the glassy GPa terms outweigh the rubbery MPa ones. E∞ is not
//! penalised (it is one well-determined number, not part of the spectrum). The problem is
//! NNLS on the stacked system `[A; λ L'] x = [1; 0]` (A compressed to its QR factor R first,
//! which leaves the minimiser unchanged).
//!
//! λ is chosen by generalised cross-validation (G.H. Golub, M. Heath & G. Wahba,
//! Technometrics 21 (1979) 215): the minimiser of `V(λ) = n RSS(λ)/(n − tr H(λ))²`, with
//! `H = A_F (A_Fᵀ A_F + λ² L_Fᵀ L_F)⁻¹ A_Fᵀ` the influence matrix on the free (non-zero)
//! unknowns F and n the number of fitted values; scanned over λ = 0 and 1e-6 … 1e3 (2 per
//! decade), then refined by golden section. Why GCV: it needs no noise level (unknown for
//! real data); it is invariant to rotations of the data, and asymptotically minimises the
//! expected predictive error (Golub, Heath & Wahba; Craven & Wahba 1979, recalled). The
//! L-curve is a heuristic without such a property; AIC/BIC need a parameter count, which
//! the penalty blurs (edf below). `tr H = edf` is the effective number of parameters
//! ([`Fit::effective_parameters`]). [`Regularisation::None`] is plain NNLS,
//! [`Regularisation::Fixed`] a given λ. GCV considers only λ that leave at least one
//! residual degree of freedom, `edf ≤ n − 1` (below it RSS and `n − edf` both vanish and V is
//! a ratio of rounding errors; σ̂² below needs it too).
//!
//! Fewer values than unknowns (n < p, e.g. ISO 3384 readings at 1, 3, 10, …, 1000 h: 7
//! points for the 17 unknowns of 3 τ per decade): plain NNLS (and a fixed λ = 0) refuses
//! them ([`FitError::TooFewPoints`]), the regularised fits take them, down to 3 points. The
//! penalty leaves free only E∞ and a relative spectrum linear in log τ (its null space, 3
//! dimensions), which 3 points determine, so `[A; λL]` has full column rank for every λ > 0.
//! λ is then chosen as above with two differences: λ = 0 is not a candidate (it is the
//! underdetermined plain fit), and when no λ of the scan leaves a residual degree of freedom
//! (3 points, which the null space alone interpolates) the largest λ of the scan is taken,
//! the smoothest fit, with no uncertainty band (σ̂ is not estimable). GCV's trace term uses
//! the n × n influence matrix and stays meaningful for n < p; checked on 7 and 17 readings
//! of a three-term relaxation (tests/model/fit.rs): noise-free, GCV picks λ ≈ 5e-3, edf ≈ 5
//! of 7 (rms residual 1.2e-3, worst error of E(t) over the window 0.5 %, the grid's ripple of
//! three off-grid τ); with 0.5 % noise GCV alone picked edf ≈ n − 0.5 on some seeds (an
//! interpolation of the noise), which the edf ≤ n − 1 cap removes at no cost in accuracy,
//! while a tighter cap (edf ≤ n − 2) over-smooths (median worst error 2.6 % against 1.0 %).
//!
//! Uncertainty band: `σ̂² = RSS/(n − edf)`, and the Bayesian posterior covariance of the free
//! unknowns `C = σ̂² (A_Fᵀ A_F + λ² L_Fᵀ L_F)⁻¹` (G. Wahba, J. R. Stat. Soc. B 45 (1983) 133,
//! "Bayesian confidence intervals for the cross-validated smoothing spline": unlike the
//! sandwich form it accounts, on average, for the smoothing bias). The pointwise relative
//! standard deviation of E(t) is `√(gᵀ C g)/E(t)` with g the basis row at t. The band is
//! simultaneous over the window: a Scheffé-type multiplier `√(χ²_{edf, 0.95})` (the bound
//! `sup_g (gᵀ δ)²/(gᵀ C g) = δᵀ C⁻¹ δ` of a Gaussian δ, with the edf-dimensional space the
//! data resolve in place of the number of free unknowns — a heuristic, checked by the
//! coverage measured below). The free set is taken as fixed (the non-negativity
//! constraints are not part of the band).
//!
//! Accuracy (measured in tests/model/fit.rs, data sampled from known series): when the true τ lie
//! on the grid the fit is exact to rounding (GCV picks λ = 0 on such clean data). Otherwise a
//! sum of decaying exponentials with non-negative weights cannot shift a relaxation time
//! between grid points, and the fit ripples: on a quasi-continuous 12-decade spectrum, 4 % in
//! E(t) with one term per decade, 4e-4 with three. With noisy data the worst error sits at the
//! window's ends. Measured on 120 points over 14 decades with 1 % noise, 50 seeds, worst
//! error of E(t) over the window: a rubber-like quasi-continuous spectrum, GCV median 0.85 %,
//! max 1.65 % (plain NNLS 1.32 %, 2.50 %), edf ≈ 10–20 (median 11.6); a one-term-per-decade
//! spectrum, GCV ≈ plain NNLS (median 1.2 %, max 2.5 %: little to smooth in isolated lines).
//! A worst error of 0.5 % is not reached: a fit with edf effective parameters passes on about
//! √(edf/n) of the noise (0.3 % rms for 11 of 120), more at the ends. Clean data: 7e-6
//! (rubber-like) and 2e-14 (one per decade), λ ≈ 3e-4 and 0. The simultaneous 95 % band
//! held the truth at all 2000 check points in 50/50 (rubber-like) and 49/50 (one per decade)
//! of the noisy repeats.
//!
//! Fits of this family on one or two τ per decade are standard practice (S.W. Park &
//! R.A. Schapery, Int. J. Solids Struct. 36 (1999) 1653; N.W. Tschoegl, *The
//! Phenomenological Theory of Linear Viscoelastic Behavior*, Springer 1989, ch. 4).

use super::{Prony, PronyError, PronyTerm};
use crate::math::log_spaced;
use crate::math::nnls::{NnlsError, nnls};
use crate::units::show;
use nalgebra::{DMatrix, DVector};
use statrs::distribution::{ChiSquared, ContinuousCDF};
use std::fmt;

/// Terms dropped as empty: below this fraction of E0 = E∞ + Σ E_i.
pub const EMPTY_TERM_FRACTION: f64 = 1e-12;

/// Significant digits of the grid's relaxation times.
pub const TAU_DIGITS: usize = 4;

/// Allowed range of [`FitSettings::terms_per_decade`]: from one term every four decades to
/// four per decade.
pub const TERMS_PER_DECADE: std::ops::RangeInclusive<f64> = 0.25..=4.0;

/// How the spectrum is regularised (module docs, "Regularisation").
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Regularisation {
    /// Smoothing weight λ chosen by generalised cross-validation (the default).
    #[default]
    Gcv,
    /// Plain NNLS, λ = 0.
    None,
    /// A given λ ≥ 0 (dimensionless; module docs).
    Fixed(f64),
}

/// Settings of a Prony fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitSettings {
    /// Relaxation times per decade of the grid, N = 0.25–4, fractional allowed (0.5: one
    /// every two decades); the grid's spacing is at most 1/N decades (default 3: with one per
    /// decade a spectrum whose τ fall between grid points leaves a ≈4 % ripple in E(t); three
    /// bring it below 0.04 %, measured in tests/model/fit.rs).
    pub terms_per_decade: f64,
    /// Smoothing of the relative spectrum (default: λ by GCV).
    pub regularisation: Regularisation,
    /// Which DMA values the fit honours where E′ and E″ disagree (module docs,
    /// "Kramers–Kronig check"; default [`Honour::Both`]). Ignored for relaxation data.
    pub honour: Honour,
}

/// Which DMA values a fit honours (module docs, "Kramers–Kronig check").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Honour {
    /// Every E′ and E″ value, each by its relative error (the default: where the data
    /// disagree it gives the lower E∞, i.e. the lower late sealing force — more leak).
    #[default]
    Both,
    /// E′ everywhere, E″ only in the decades the check finds consistent with E′; in the
    /// others the E″ that E′ implies takes the measured one's place (dropping those values
    /// instead would let the fit carry the storage plateau on a term beyond the window). Keeps
    /// the long-term modulus E∞ (the storage plateau) that a seal's late force lives on.
    Storage,
}

/// A decade's ratio of measured E″ to the E″ that E′ implies, beyond this factor (or below
/// its inverse), is flagged as inconsistent (module docs, "Kramers–Kronig check"). An
/// assumed tolerance: the E′-alone fit's E″ is good to a few per cent on exact data
/// (measured in tests/model/fit.rs), 1 % noise moves a decade's ratio by well under 10 %,
/// and the inconsistency the check is for is a factor of 2–4 (issue 40).
pub const KK_TOLERANCE: f64 = 1.5;

/// One decade of the Kramers–Kronig check.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DecadeCheck {
    /// The decade's first and last angular frequency \[rad/s\].
    pub omegas: (f64, f64),
    /// Data points in the decade.
    pub points: usize,
    /// Geometric mean over the decade of measured E″ / E″ implied by E′ (1: consistent).
    pub ratio: f64,
    /// |mean measured E″ − mean implied E″| over the decade, in units of the E″ that the
    /// scatter of E′ can hide, σ̂ · mean E′ (σ̂ the E′-alone fit's relative scatter): where E″
    /// is small against E′ (tan δ below the E′ noise) E′ cannot imply it.
    pub excess: f64,
}

/// A decade is flagged only when its E″ differs from the implied one by more than this many
/// σ̂ · E′ ([`DecadeCheck::excess`]): 1 % noise on E′ otherwise flags the rubbery plateau,
/// where tan δ ≈ 0.005 (measured in tests/model/fit.rs).
pub const KK_RESOLUTION: f64 = 3.0;

impl DecadeCheck {
    /// Whether the ratio lies outside `[1/KK_TOLERANCE, KK_TOLERANCE]` and the difference
    /// is resolved by E′ ([`KK_RESOLUTION`]).
    pub fn inconsistent(&self) -> bool {
        !(1.0 / KK_TOLERANCE..=KK_TOLERANCE).contains(&self.ratio) && self.excess > KK_RESOLUTION
    }
}

/// The Kramers–Kronig check of DMA data (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Consistency {
    /// Per decade of frequency, from the lowest.
    pub decades: Vec<DecadeCheck>,
    /// E∞ of the fit of E′ alone \[Pa\]: the long-term modulus the storage data imply.
    pub storage_long_term: f64,
    /// E″ values the fit replaced by the E″ that E′ implies ([`Honour::Storage`]: those of
    /// the inconsistent decades).
    pub replaced_loss: usize,
    /// The E″ that E′ implies at each data frequency \[Pa\] (the E′-alone fit's).
    pub implied_loss: Vec<f64>,
}

impl Consistency {
    /// The decades whose E′ and E″ disagree.
    pub fn inconsistent(&self) -> impl Iterator<Item = &DecadeCheck> {
        self.decades.iter().filter(|d| d.inconsistent())
    }

    /// The decade with the largest disagreement (ratio farthest from 1 in log), if any is
    /// inconsistent.
    pub fn worst(&self) -> Option<&DecadeCheck> {
        self.inconsistent()
            .max_by(|a, b| a.ratio.ln().abs().total_cmp(&b.ratio.ln().abs()))
    }
}

/// Default of [`FitSettings::terms_per_decade`].
pub const DEFAULT_TERMS_PER_DECADE: f64 = 3.0;

impl Default for FitSettings {
    fn default() -> Self {
        FitSettings {
            terms_per_decade: DEFAULT_TERMS_PER_DECADE,
            regularisation: Regularisation::Gcv,
            honour: Honour::Both,
        }
    }
}

/// A fitted Prony series and how well it matches the data.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The fitted series (empty terms dropped).
    pub prony: Prony,
    /// Data points used: times, or frequencies (each giving E′ and E″).
    pub points: usize,
    /// Terms on the τ grid before empty ones were dropped.
    pub grid_terms: usize,
    /// Root mean square of the relative residuals `model/datum − 1` over all fitted values
    /// (for DMA data, the E′ and the E″ values).
    pub rms_relative_residual: f64,
    /// Largest `|model/datum − 1|`.
    pub max_relative_residual: f64,
    /// The time window of the data \[s\] (for DMA data, 1/ω_max to 1/ω_min): where the series
    /// is backed by data.
    pub window: (f64, f64),
    /// The regularisation asked for.
    pub regularisation: Regularisation,
    /// The smoothing weight λ used (dimensionless, module docs); 0 when unregularised, or when
    /// GCV found no smoothing better than none.
    pub smoothing: f64,
    /// Effective number of parameters `edf = tr H(λ)`, H the influence matrix on the free
    /// (non-zero) unknowns (module docs); the number of free unknowns when λ = 0.
    pub effective_parameters: f64,
    /// The uncertainty band of E(t) over the window ([`Fit::relative_band`]; for DMA fits
    /// whose relaxation times were refined, the band of the grid fit they started from).
    pub band: Band,
    /// DMA data: the Kramers–Kronig check of E′ against E″ (None for relaxation data, or
    /// when the E′-alone fit fails).
    pub consistency: Option<Consistency>,
    /// DMA data: whether the relaxation times were moved off the grid (module docs,
    /// "Relaxation times off the grid").
    pub refined: bool,
}

/// What a simultaneous uncertainty band of E(t) needs (module docs, "Uncertainty band"):
/// the grid, the posterior covariance of the scaled unknowns and the band's multiplier.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    /// The τ grid \[s\], all terms (also those that came out empty).
    pub taus: Vec<f64>,
    /// Moduli are `scale · x` \[Pa\]: the largest datum.
    pub scale: f64,
    /// Posterior covariance of `x = (E∞, E_1, …, E_m)/scale`,
    /// `σ̂² (A_Fᵀ A_F + λ² L_Fᵀ L_F)⁻¹` on the free unknowns, 0 on the others
    /// (dimensionless; (m+1)×(m+1)).
    pub covariance: DMatrix<f64>,
    /// Estimated standard deviation of the relative residuals, `σ̂ = √(RSS/(n − edf))`.
    pub sigma: f64,
    /// The simultaneous multiplier `√(χ²_{edf, 0.95})` (module docs).
    pub multiplier: f64,
    /// The grid fit the covariance belongs to: the band is relative to its E(t) (the same
    /// as [`Fit::prony`] unless the relaxation times were refined, [`Fit::refined`]).
    pub series: Prony,
}

/// Confidence level of [`Band`].
pub const BAND_LEVEL: f64 = 0.95;

impl Fit {
    /// Pointwise relative standard deviation of the fitted E(t), `√(gᵀ C g) / (E(t)/scale)`
    /// (E(t) of the grid fit, [`Band::series`])
    /// with `g = (1, e^{−t/τ_1}, …, e^{−t/τ_m})` (module docs); infinite when the fit leaves
    /// less than one residual degree of freedom (n − edf < 1: the scatter is not estimable).
    pub fn relative_standard_deviation(&self, t: f64) -> f64 {
        let b = &self.band;
        let g: Vec<f64> = std::iter::once(1.0)
            .chain(b.taus.iter().map(|&tau| (-t / tau).exp()))
            .collect();
        let n = g.len().min(b.covariance.nrows());
        let mut variance = 0.0;
        for i in 0..n {
            let row: f64 = (0..n).map(|j| b.covariance[(i, j)] * g[j]).sum();
            variance += g[i] * row;
        }
        if variance.is_nan() {
            // an unbounded covariance (0 · ∞ where a basis value underflows): no bound
            return f64::INFINITY;
        }
        variance.max(0.0).sqrt() / (b.series.relaxation(t) / b.scale)
    }

    /// Relative half-width of the simultaneous 95 % band of E(t): the band is
    /// `E(t) (1 ± relative_band(t))`; meant for t inside [`Fit::window`].
    pub fn relative_band(&self, t: f64) -> f64 {
        self.band.multiplier * self.relative_standard_deviation(t)
    }

    /// The simultaneous 95 % band of E(t) \[Pa\], `(lower, upper)`; the lower end is
    /// clamped at 0.
    pub fn band(&self, t: f64) -> (f64, f64) {
        let (e, h) = (self.prony.relaxation(t), self.relative_band(t));
        ((e * (1.0 - h)).max(0.0), e * (1.0 + h))
    }

    /// The widest relative half-width of the band over the window (200 log-spaced times)
    /// and where it is \[s\].
    pub fn widest_relative_band(&self) -> (f64, f64) {
        log_spaced(self.window.0, self.window.1.max(self.window.0), 200)
            .into_iter()
            .map(|t| (self.relative_band(t), t))
            .fold((0.0, self.window.0), |a, b| if b.0 > a.0 { b } else { a })
    }
}

/// Why data could not be fitted. Indices are 1-based positions in the data arrays.
#[derive(Debug, Clone, PartialEq)]
pub enum FitError {
    /// `terms_per_decade` outside 0.25–4 (or not finite).
    Settings { terms_per_decade: f64 },
    /// A fixed smoothing weight λ that is negative or not finite.
    Smoothing { value: f64 },
    /// Arrays of one data set differ in length.
    LengthMismatch {
        what: &'static str,
        expected: usize,
        found: usize,
    },
    /// Fewer than 3 points, or (plain NNLS only) fewer data values than unknowns; then
    /// `max_terms_per_decade` is the densest grid that these values determine, when it is
    /// within [`TERMS_PER_DECADE`] (rounded down to 2 decimals).
    TooFewPoints {
        points: usize,
        values: usize,
        unknowns: usize,
        max_terms_per_decade: Option<f64>,
    },
    /// A value is NaN, infinite, zero or negative.
    NotPositive {
        what: &'static str,
        index: usize,
        value: f64,
    },
    /// Times decrease (ties are allowed in relaxation times).
    Decreasing {
        what: &'static str,
        index: usize,
        previous: f64,
        value: f64,
    },
    /// Every time is the same.
    NoSpread { what: &'static str, value: f64 },
    /// Frequencies do not increase strictly.
    NotIncreasing {
        what: &'static str,
        index: usize,
        previous: f64,
        value: f64,
    },
    /// The least-squares solver failed.
    Solver(NnlsError),
    /// The fitted series is invalid (e.g. every modulus came out zero).
    Degenerate(PronyError),
}

impl fmt::Display for FitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FitError::Settings { terms_per_decade } => {
                write!(
                    f,
                    "terms per decade must be 0.25 to 4, got {}",
                    show(*terms_per_decade)
                )
            }
            FitError::LengthMismatch {
                what,
                expected,
                found,
            } => write!(
                f,
                "{what} has {found} values but the times or frequencies have {expected}"
            ),
            FitError::TooFewPoints {
                points,
                values,
                unknowns,
                max_terms_per_decade,
            } => {
                if *points < 3 {
                    write!(
                        f,
                        "too few points: {points} data points, at least 3 are needed"
                    )
                } else {
                    write!(
                        f,
                        "too few points for a fit without smoothing: {points} data points give \
                         {values} values for {unknowns} unknowns (E∞ and {} Prony terms); give \
                         more points, {}or the regularised fit (the default), which takes fewer \
                         points than unknowns",
                        unknowns.saturating_sub(1),
                        match max_terms_per_decade {
                            Some(n) => format!("at most {} terms per decade, ", show(*n)),
                            None => String::new(),
                        }
                    )
                }
            }
            FitError::NotPositive { what, index, value } => write!(
                f,
                "{what} of point {index} must be positive and finite, got {}",
                show(*value)
            ),
            FitError::Smoothing { value } => write!(
                f,
                "the smoothing weight must be finite and not negative, got {}",
                show(*value)
            ),
            FitError::Decreasing {
                what,
                index,
                previous,
                value,
            } => write!(
                f,
                "{what} must not decrease: point {index} has {} after {}",
                show(*value),
                show(*previous)
            ),
            FitError::NoSpread { what, value } => write!(
                f,
                "every {what} is {}: the data must span an interval",
                show(*value)
            ),
            FitError::NotIncreasing {
                what,
                index,
                previous,
                value,
            } => write!(
                f,
                "{what} must increase strictly: point {index} has {} after {}",
                show(*value),
                show(*previous)
            ),
            FitError::Solver(e) => e.fmt(f),
            FitError::Degenerate(e) => write!(f, "the fit gives no valid Prony series: {e}"),
        }
    }
}

impl std::error::Error for FitError {}

impl From<NnlsError> for FitError {
    fn from(e: NnlsError) -> Self {
        FitError::Solver(e)
    }
}

/// Fits `E(t) = E∞ + Σ E_i e^{−t/τ_i}` to relaxation data: `times` (s) positive and
/// non-decreasing (repeated times, e.g. repeated tests or merged shifted data, are allowed),
/// `moduli` (Pa) positive (module docs).
pub fn fit_relaxation(
    times: &[f64],
    moduli: &[f64],
    settings: &FitSettings,
) -> Result<Fit, FitError> {
    check_settings(settings)?;
    check_axis("time", times, false)?;
    check_values("relaxation modulus", moduli, times.len())?;
    let (first, last) = (times[0], times[times.len() - 1]);
    let taus = tau_grid(first / 10.0, last * 10.0, settings.terms_per_decade);
    check_count(
        times.len(),
        times.len(),
        taus.len() + 1,
        (100.0 * last / first).log10(),
        settings.regularisation,
    )?;
    let scale = moduli.iter().copied().fold(0.0, f64::max);
    let mut a = DMatrix::zeros(times.len(), taus.len() + 1);
    for (k, (&t, &e)) in times.iter().zip(moduli).enumerate() {
        let weight = scale / e;
        a[(k, 0)] = weight;
        for (i, &tau) in taus.iter().enumerate() {
            a[(k, i + 1)] = weight * (-t / tau).exp();
        }
    }
    let window = (first, last);
    let solved = solve(&a, &taus, scale, window, settings.regularisation)?;
    let prony = solved.prony;
    let (rms, max) = statistics(
        times
            .iter()
            .zip(moduli)
            .map(|(&t, &e)| prony.relaxation(t) / e - 1.0),
    );
    Ok(Fit {
        prony,
        points: times.len(),
        grid_terms: taus.len(),
        rms_relative_residual: rms,
        max_relative_residual: max,
        window,
        regularisation: settings.regularisation,
        smoothing: solved.smoothing,
        effective_parameters: solved.effective_parameters,
        band: solved.band,
        consistency: None,
        refined: false,
    })
}

/// Fits `E′(ω)` and `E″(ω)` of a Prony series to DMA data: `omegas` (rad/s) strictly
/// increasing and positive, `storage` and `loss` (Pa) positive (module docs). The data are
/// checked for Kramers–Kronig consistency first ([`Fit::consistency`]); with
/// [`Honour::Storage`] the E″ values of inconsistent decades are replaced by the E″ that E′
/// implies. The relaxation
/// times are then refined off the grid when that pays (module docs).
pub fn fit_dma(
    omegas: &[f64],
    storage: &[f64],
    loss: &[f64],
    settings: &FitSettings,
) -> Result<Fit, FitError> {
    check_settings(settings)?;
    check_axis("angular frequency", omegas, true)?;
    check_values("storage modulus", storage, omegas.len())?;
    check_values("loss modulus", loss, omegas.len())?;
    let n = omegas.len();
    let (first, last) = (omegas[0], omegas[n - 1]);
    let taus = tau_grid(1.0 / (10.0 * last), 10.0 / first, settings.terms_per_decade);
    check_count(
        n,
        2 * n,
        taus.len() + 1,
        (100.0 * last / first).log10(),
        settings.regularisation,
    )?;
    let scale = storage.iter().chain(loss).copied().fold(0.0, f64::max);
    let mut consistency = kramers_kronig(omegas, storage, loss, &taus, scale);
    // the E″ values fitted: the measured ones, or (E′ honoured) in inconsistent decades
    // the E″ that E′ implies
    let keep_loss: Vec<bool> = match (&consistency, settings.honour) {
        (Some(c), Honour::Storage) => omegas
            .iter()
            .map(|&w| {
                c.decades
                    .iter()
                    .find(|d| w >= d.omegas.0 && w <= d.omegas.1)
                    .is_none_or(|d| !d.inconsistent())
            })
            .collect(),
        _ => vec![true; n],
    };
    let fitted_loss: Vec<f64> = match &consistency {
        Some(c) => (0..n)
            .map(|k| {
                if keep_loss[k] {
                    loss[k]
                } else {
                    c.implied_loss[k]
                }
            })
            .collect(),
        None => loss.to_vec(),
    };
    if let Some(c) = consistency.as_mut() {
        c.replaced_loss = keep_loss.iter().filter(|&&k| !k).count();
    }
    let loss = &fitted_loss[..];
    let mut rows = storage_rows(omegas, storage, scale);
    rows.extend(omegas.iter().zip(loss).map(|(&omega, &e)| Row::Loss {
        omega,
        weight: scale / e,
    }));
    let a = design(&rows, &taus);
    let window = (1.0 / last, 1.0 / first);
    let solved = solve(&a, &taus, scale, window, settings.regularisation)?;
    let (prony, refined) = match refine_taus(&rows, &solved, &taus, scale) {
        Some(p) => (p, true),
        None => (solved.prony, false),
    };
    // statistics over the values fitted (E″ replaced where E′ was honoured: the check
    // reports how far the measured ones are)
    let (rms, max) = statistics(omegas.iter().enumerate().flat_map(|(k, &omega)| {
        [
            prony.storage(omega) / storage[k] - 1.0,
            prony.loss(omega) / loss[k] - 1.0,
        ]
    }));
    Ok(Fit {
        prony,
        points: n,
        grid_terms: taus.len(),
        rms_relative_residual: rms,
        max_relative_residual: max,
        window,
        regularisation: settings.regularisation,
        smoothing: solved.smoothing,
        effective_parameters: solved.effective_parameters,
        band: solved.band,
        consistency,
        refined,
    })
}

/// One weighted row of a DMA fit: `weight · (E∞ + Σ E_i x²/(1+x²))` (storage) or
/// `weight · Σ E_i x/(1+x²)` (loss), `x = ωτ_i`, fitted to 1.
#[derive(Debug, Clone, Copy)]
enum Row {
    Storage { omega: f64, weight: f64 },
    Loss { omega: f64, weight: f64 },
}

impl Row {
    /// The weighted basis value of a term of unit modulus at `tau`, its derivative with
    /// respect to ln τ, and the weight of E∞ in the row.
    fn basis(self, tau: f64) -> (f64, f64, f64) {
        match self {
            Row::Storage { omega, weight } => {
                let x = omega * tau;
                let d = 1.0 + x * x;
                // d/d ln τ of x²/(1+x²) = 2x²/(1+x²)²
                (weight * x * x / d, weight * 2.0 * x * x / (d * d), weight)
            }
            Row::Loss { omega, weight } => {
                let x = omega * tau;
                let d = 1.0 + x * x;
                // d/d ln τ of x/(1+x²) = x(1−x²)/(1+x²)²
                (weight * x / d, weight * x * (1.0 - x * x) / (d * d), 0.0)
            }
        }
    }
}

/// The design matrix of `rows` on `taus`: column 0 E∞, then one per τ.
fn design(rows: &[Row], taus: &[f64]) -> DMatrix<f64> {
    let mut a = DMatrix::zeros(rows.len(), taus.len() + 1);
    for (k, row) in rows.iter().enumerate() {
        for (i, &tau) in taus.iter().enumerate() {
            let (value, _, long_term) = row.basis(tau);
            a[(k, 0)] = long_term;
            a[(k, i + 1)] = value;
        }
    }
    a
}

/// The Kramers–Kronig check (module docs): E′ alone fitted on the grid (GCV), the E″ it
/// implies compared with the measured E″, decade by decade from the lowest frequency (a
/// last decade of fewer than 3 points joins the one before). None when the E′-alone fit
/// fails.
fn kramers_kronig(
    omegas: &[f64],
    storage: &[f64],
    loss: &[f64],
    taus: &[f64],
    scale: f64,
) -> Option<Consistency> {
    let rows = storage_rows(omegas, storage, scale);
    let a = design(&rows, taus);
    let window = (1.0 / omegas[omegas.len() - 1], 1.0 / omegas[0]);
    let alone = solve(&a, taus, scale, window, Regularisation::Gcv).ok()?;
    let mut decades: Vec<(usize, usize)> = Vec::new(); // index ranges [start, end)
    let first = omegas[0];
    let mut start = 0;
    for k in 1..=omegas.len() {
        let new_decade = k == omegas.len()
            || (omegas[k] / first).log10().floor() > (omegas[start] / first).log10().floor();
        if new_decade {
            decades.push((start, k));
            start = k;
        }
    }
    if decades.len() > 1
        && decades[decades.len() - 1].1 - decades[decades.len() - 1].0 < 3
        && let Some((_, end)) = decades.pop()
    {
        let l = decades.len() - 1;
        decades[l].1 = end;
    }
    // an implied E″ of 0 (no term near this frequency): a ratio capped at 1e6
    let implied_loss: Vec<f64> = omegas
        .iter()
        .zip(loss)
        .map(|(&w, &l)| alone.prony.loss(w).max(l * 1e-6))
        .collect();
    let decades = decades
        .into_iter()
        .map(|(s, e)| {
            let mean_log = (s..e)
                .map(|k| (loss[k] / implied_loss[k]).ln())
                .sum::<f64>()
                / (e - s) as f64;
            let count = (e - s) as f64;
            let mean = |v: &[f64]| v[s..e].iter().sum::<f64>() / count;
            let hidden = alone.band.sigma * mean(storage);
            let difference = (mean(loss) - mean(&implied_loss)).abs();
            DecadeCheck {
                omegas: (omegas[s], omegas[e - 1]),
                points: e - s,
                ratio: mean_log.exp(),
                // σ̂ not estimable (no residual degree of freedom): nothing is resolved
                excess: if hidden.is_finite() && hidden > 0.0 {
                    difference / hidden
                } else if hidden == 0.0 {
                    f64::INFINITY
                } else {
                    0.0
                },
            }
        })
        .collect();
    Some(Consistency {
        decades,
        storage_long_term: alone.prony.long_term(),
        replaced_loss: 0,
        implied_loss,
    })
}

/// Largest number of Levenberg–Marquardt steps of [`refine_taus`].
const REFINE_STEPS: usize = 200;

/// Relaxation times off the grid (module docs): the non-empty terms of the grid fit, their
/// moduli and ln τ (and E∞) refined together by Levenberg–Marquardt on the unpenalised
/// relative residual, moduli kept ≥ 0 by projection. Kept only when it lowers the GCV score
/// counting each freed τ as a parameter, `n RSS/(n − edf − m)²` (so that a fit of noise by
/// the extra freedom is refused); None otherwise.
fn refine_taus(rows: &[Row], solved: &Solved, grid: &[f64], scale: f64) -> Option<Prony> {
    let n = rows.len();
    let terms = solved.prony.terms();
    let m = terms.len();
    let dof = n as f64 - solved.effective_parameters - m as f64;
    if m == 0 || dof < MIN_RESIDUAL_DOF {
        return None;
    }
    // parameters: [E∞, E_1, ln τ_1, E_2, ln τ_2, …], moduli scaled by `scale`
    let mut p = DVector::zeros(1 + 2 * m);
    p[0] = solved.prony.long_term() / scale;
    for (i, t) in terms.iter().enumerate() {
        p[1 + 2 * i] = t.modulus / scale;
        p[2 + 2 * i] = t.tau.ln();
    }
    let (lo, hi) = (
        grid.first().copied()?.ln() - 10f64.ln(),
        grid.last().copied()?.ln() + 10f64.ln(),
    );
    let residual = |p: &DVector<f64>| -> DVector<f64> {
        DVector::from_iterator(
            n,
            rows.iter().map(|row| {
                let mut v = 0.0;
                for i in 0..m {
                    let (b, _, w0) = row.basis(p[2 + 2 * i].exp());
                    v += p[1 + 2 * i] * b;
                    if i == 0 {
                        v += p[0] * w0;
                    }
                }
                v - 1.0
            }),
        )
    };
    let rss0 = residual(&p).norm_squared();
    let mut rss = rss0;
    let mut mu = 1e-3;
    for _ in 0..REFINE_STEPS {
        let r = residual(&p);
        let mut j = DMatrix::zeros(n, 1 + 2 * m);
        for (k, row) in rows.iter().enumerate() {
            for i in 0..m {
                let (b, db, w0) = row.basis(p[2 + 2 * i].exp());
                j[(k, 1 + 2 * i)] = b;
                j[(k, 2 + 2 * i)] = p[1 + 2 * i] * db;
                if i == 0 {
                    j[(k, 0)] = w0;
                }
            }
        }
        let h = j.transpose() * &j;
        let g = j.transpose() * &r;
        let mut improved = false;
        for _ in 0..12 {
            let mut damped = h.clone();
            for d in 0..damped.nrows() {
                damped[(d, d)] += mu * h[(d, d)].max(1e-12);
            }
            let Some(step) = damped.cholesky().map(|c| c.solve(&(-&g))) else {
                mu *= 4.0;
                continue;
            };
            let mut trial = &p + step;
            trial[0] = trial[0].max(0.0);
            for i in 0..m {
                trial[1 + 2 * i] = trial[1 + 2 * i].max(0.0);
                trial[2 + 2 * i] = trial[2 + 2 * i].clamp(lo, hi);
            }
            let trial_rss = residual(&trial).norm_squared();
            if trial_rss.is_finite() && trial_rss < rss {
                let gain = rss - trial_rss;
                p = trial;
                rss = trial_rss;
                mu = (mu / 3.0).max(1e-12);
                improved = gain > 1e-12 * rss0;
                break;
            }
            mu *= 4.0;
        }
        if !improved {
            break;
        }
    }
    let before = n as f64 * rss0 / (n as f64 - solved.effective_parameters).powi(2);
    let after = n as f64 * rss / dof.powi(2);
    if after.partial_cmp(&before) != Some(std::cmp::Ordering::Less) {
        return None;
    }
    let terms: Vec<PronyTerm> = (0..m)
        .map(|i| PronyTerm {
            modulus: scale * p[1 + 2 * i],
            tau: round_tau(p[2 + 2 * i].exp()),
        })
        .filter(|t| t.modulus > 0.0)
        .collect();
    let refined = Prony::new(scale * p[0], &terms).ok()?;
    // rounding τ to TAU_DIGITS must not undo the gain
    let rounded_rss: f64 = rows
        .iter()
        .map(|row| {
            let v = match *row {
                Row::Storage { omega, weight } => weight * refined.storage(omega),
                Row::Loss { omega, weight } => weight * refined.loss(omega),
            };
            (v / scale - 1.0).powi(2)
        })
        .sum();
    (n as f64 * rounded_rss / dof.powi(2) < before).then_some(refined)
}

/// `tau` rounded to [`TAU_DIGITS`] significant digits.
fn round_tau(tau: f64) -> f64 {
    format!("{tau:.prec$e}", prec = TAU_DIGITS - 1)
        .parse()
        .unwrap_or(tau)
}

/// The τ grid over `[lo, hi]`: `⌈log10(hi/lo) N⌉ + 1` log-spaced values, both ends included,
/// each rounded to [`TAU_DIGITS`] significant digits (the grid is arbitrary anyway, and round
/// values make the written material readable: `tau = "3.162e-3 s"`).
fn tau_grid(lo: f64, hi: f64, per_decade: f64) -> Vec<f64> {
    let decades = (hi / lo).log10();
    // A window of a whole number of decades must not gain a term from rounding.
    let steps = (decades * per_decade - 1e-9).ceil().max(1.0) as usize;
    log_spaced(lo, hi, steps + 1)
        .into_iter()
        .map(|tau| {
            format!("{tau:.prec$e}", prec = TAU_DIGITS - 1)
                .parse()
                .unwrap_or(tau)
        })
        .collect()
}

/// The fewest residual degrees of freedom n − edf that GCV accepts (module docs).
const MIN_RESIDUAL_DOF: f64 = 1.0;

/// Lower and upper end of the GCV scan of λ, and its points per decade (module docs).
const GCV_RANGE: (f64, f64) = (1e-6, 1e3);
const GCV_PER_DECADE: usize = 2;
/// Golden-section steps refining the scan's best λ between its neighbours (0.618^8 of
/// one decade: well below the flatness of V(λ) near its minimum).
const GCV_REFINE: usize = 8;

/// The result of [`solve`].
struct Solved {
    prony: Prony,
    smoothing: f64,
    effective_parameters: f64,
    band: Band,
}

/// The regularised problem of one data set (module docs), in the scaled unknowns
/// `x = (E∞, E_1, …, E_m)/scale`.
struct Problem<'a> {
    /// Weighted data rows, n × p (right-hand side 1).
    a: &'a DMatrix<f64>,
    /// `R` and `c = Qᵀ 1` of the Householder QR of `a` (k × p and k, k = min(n, p)):
    /// `‖a x − 1‖² = ‖R x − c‖² + const`, so the stacked problems are k + m − 2 rows, not
    /// n + m − 2.
    r: DMatrix<f64>,
    c: DVector<f64>,
    /// The penalty `L diag(scale/E_ref)` on the relative spectrum, (m − 2) × p, column 0
    /// (E∞) zero.
    penalty: DMatrix<f64>,
    /// The unregularised NNLS solution (λ = 0).
    pilot: DVector<f64>,
}

/// The solution at one λ with what GCV and the band need.
struct Candidate {
    lambda: f64,
    x: DVector<f64>,
    rss: f64,
    edf: f64,
    gcv: f64,
    /// Free (non-zero) unknowns and the triangular factor `R̂` of
    /// `[A_F; λ L_F] = Q̂ R̂` (so `A_Fᵀ A_F + λ² L_Fᵀ L_F = R̂ᵀ R̂`).
    free: Vec<usize>,
    r_hat: DMatrix<f64>,
}

impl Problem<'_> {
    /// NNLS on `[R; λ L'] x = [c; 0]`, then RSS, `edf = tr H = ‖Q̂_top‖²_F` (the data rows'
    /// part of the orthogonal factor of `[R_F; λ L'_F]`: `H = A_F (R̂ᵀR̂)⁻¹ A_Fᵀ` has the
    /// same trace) and `V(λ) = n RSS/(n − edf)²`.
    fn at(&self, lambda: f64) -> Result<Candidate, FitError> {
        let (k, p) = self.r.shape();
        let q = self.penalty.nrows();
        let x = if lambda == 0.0 {
            self.pilot.clone()
        } else {
            let s = DMatrix::from_fn(k + q, p, |i, j| {
                if i < k {
                    self.r[(i, j)]
                } else {
                    lambda * self.penalty[(i - k, j)]
                }
            });
            let rhs = DVector::from_fn(k + q, |i, _| if i < k { self.c[i] } else { 0.0 });
            nnls(&s, &rhs)?.x
        };
        let rss = (self.a * &x).add_scalar(-1.0).norm_squared();
        let free: Vec<usize> = (0..p).filter(|&j| x[j] > 0.0).collect();
        let (edf, r_hat) = if free.is_empty() {
            (0.0, DMatrix::zeros(0, 0))
        } else {
            let sf = DMatrix::from_fn(k + q, free.len(), |i, j| {
                if i < k {
                    self.r[(i, free[j])]
                } else {
                    lambda * self.penalty[(i - k, free[j])]
                }
            });
            let qr = sf.qr();
            let edf = qr.q().rows(0, k).norm_squared();
            (edf, qr.r())
        };
        let n = self.a.nrows() as f64;
        // at least one residual degree of freedom (module docs): an interpolation has RSS and
        // n − edf both → 0, and its V is the ratio of two rounding errors
        let gcv = if n - edf >= MIN_RESIDUAL_DOF - 1e-6 {
            n * rss / ((n - edf) * (n - edf))
        } else {
            f64::INFINITY
        };
        Ok(Candidate {
            lambda,
            x,
            rss,
            edf,
            gcv,
            free,
            r_hat,
        })
    }
}

/// The fit of relative rows `a x ≈ 1` with `x ≥ 0` under the regularisation asked for;
/// moduli are `scale · x` (module docs).
fn solve(
    a: &DMatrix<f64>,
    taus: &[f64],
    scale: f64,
    window: (f64, f64),
    regularisation: Regularisation,
) -> Result<Solved, FitError> {
    let (n, p) = a.shape();
    let m = taus.len();
    let ones = DVector::from_element(n, 1.0);
    let pilot = nnls(a, &ones)?.x;
    // E_ref(τ_i): the pilot fit at τ_i clamped to the window, a smooth, positive local
    // modulus level (a sum of decaying exponentials is monotone), so that the penalty acts
    // on E_i/E_ref(τ_i) and weighs the rubbery MPa terms like the glassy GPa ones.
    // E_ref(τ_i): the pilot fit at τ_i clamped to the window, a smooth, positive local
    // modulus level (a sum of decaying exponentials is monotone), so that the penalty acts
    // on E_i/E_ref(τ_i) and weighs the rubbery MPa terms like the glassy GPa ones.
    let reference = |t: f64| {
        pilot[0]
            + taus
                .iter()
                .zip(pilot.iter().skip(1))
                .map(|(&tau, &xi)| xi * (-t / tau).exp())
                .sum::<f64>()
    };
    let weights: Vec<f64> = taus
        .iter()
        .map(|&tau| {
            let level = reference(tau.clamp(window.0, window.1));
            // guards a degenerate pilot (every modulus zero): the scale of the data
            1.0 / if level.is_finite() && level > 1e-12 {
                level
            } else {
                1.0
            }
        })
        .collect();
    let q = m.saturating_sub(2);
    let mut penalty = DMatrix::zeros(q, p);
    for row in 0..q {
        // second difference of x̃ at τ index row + 1; column = τ index + 1
        penalty[(row, row + 1)] = weights[row];
        penalty[(row, row + 2)] = -2.0 * weights[row + 1];
        penalty[(row, row + 3)] = weights[row + 2];
    }
    // with fewer values than unknowns (n < p, regularised fits only) R is n × p: the
    // stacked problem [R; λ L'] has n + m − 2 ≥ p rows for n ≥ 3
    let qr = a.clone().qr();
    let mut qtb = ones.clone();
    qr.q_tr_mul(&mut qtb);
    let problem = Problem {
        a,
        r: qr.r(),
        c: qtb.rows(0, n.min(p)).into_owned(),
        penalty,
        pilot,
    };
    let chosen = match regularisation {
        Regularisation::None => problem.at(0.0)?,
        Regularisation::Fixed(lambda) => problem.at(lambda)?,
        Regularisation::Gcv => gcv(&problem)?,
    };
    let prony = prony_of(&chosen.x, taus, scale)?;
    let band = band(&chosen, taus, scale, n, prony.clone());
    Ok(Solved {
        prony,
        smoothing: chosen.lambda,
        effective_parameters: chosen.edf,
        band,
    })
}

/// The λ minimising V(λ) among those leaving at least [`MIN_RESIDUAL_DOF`] (edf ≤ n − 1):
/// λ = 0 (only when there are at least as many values as unknowns) and a log grid over
/// [`GCV_RANGE`], then golden-section refinement (in log λ) between the best grid point's
/// neighbours. A λ at which NNLS fails is skipped. With fewer values than unknowns and no λ
/// of the grid leaving a residual degree of freedom (three points: the penalty's null space
/// alone interpolates them), the largest λ of the grid: the smoothest fit (module docs).
fn gcv(problem: &Problem) -> Result<Candidate, FitError> {
    let decades = (GCV_RANGE.1 / GCV_RANGE.0).log10();
    let count = (decades * GCV_PER_DECADE as f64).round() as usize + 1;
    let lambdas = log_spaced(GCV_RANGE.0, GCV_RANGE.1, count);
    let (n, p) = problem.a.shape();
    // (the best candidate, its index in the grid: None for λ = 0)
    let mut best: Option<(Candidate, Option<usize>)> = if n >= p {
        Some((problem.at(0.0)?, None))
    } else {
        None
    };
    let mut largest = None;
    for (k, &lambda) in lambdas.iter().enumerate() {
        let Ok(c) = problem.at(lambda) else {
            continue;
        };
        if c.gcv.is_finite() && best.as_ref().is_none_or(|(b, _)| c.gcv < b.gcv) {
            best = Some((c, Some(k)));
        } else if k + 1 == count {
            largest = Some(c);
        }
    }
    let (mut best, k) = match (best, largest) {
        (Some((best, Some(k))), _) => (best, k),
        (Some((best, None)), _) => return Ok(best),
        (None, Some(largest)) => return Ok(largest),
        // NNLS failed at every λ of the grid: the error of the smoothest one
        (None, None) => return problem.at(GCV_RANGE.1),
    };
    // golden section on s = log10 λ over the neighbours of the best grid point
    let lo = lambdas[k.saturating_sub(1)].log10();
    let hi = lambdas[(k + 1).min(count - 1)].log10();
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (lo, hi);
    let mut s1 = b - g * (b - a);
    let mut s2 = a + g * (b - a);
    let eval = |s: f64| problem.at(10f64.powf(s)).ok();
    let (mut c1, mut c2) = (eval(s1), eval(s2));
    let v = |c: &Option<Candidate>| c.as_ref().map_or(f64::INFINITY, |c| c.gcv);
    for _ in 0..GCV_REFINE {
        if v(&c1) < v(&c2) {
            b = s2;
            (s2, c2) = (s1, c1);
            s1 = b - g * (b - a);
            c1 = eval(s1);
        } else {
            a = s1;
            (s1, c1) = (s2, c2);
            s2 = a + g * (b - a);
            c2 = eval(s2);
        }
    }
    for c in [c1, c2].into_iter().flatten() {
        if c.gcv < best.gcv {
            best = c;
        }
    }
    Ok(best)
}

/// The band of a solution: `σ̂² = RSS/(n − edf)`, `C = σ̂² (R̂ᵀR̂)⁻¹` on the free unknowns
/// (Wahba 1983), and the multiplier (module docs).
fn band(chosen: &Candidate, taus: &[f64], scale: f64, n: usize, series: Prony) -> Band {
    let p = taus.len() + 1;
    let dof = n as f64 - chosen.edf;
    // below one residual degree of freedom the scatter is not estimable: no bound
    let sigma2 = if dof >= MIN_RESIDUAL_DOF - 1e-6 {
        chosen.rss / dof
    } else {
        f64::INFINITY
    };
    let f = chosen.free.len();
    let mut covariance = DMatrix::zeros(p, p);
    if !sigma2.is_finite() {
        covariance.fill(f64::INFINITY);
    } else if f > 0 {
        match chosen
            .r_hat
            .solve_upper_triangular(&DMatrix::identity(f, f))
        {
            Some(inv) => {
                let c = &inv * inv.transpose() * sigma2;
                for (i, &fi) in chosen.free.iter().enumerate() {
                    for (j, &fj) in chosen.free.iter().enumerate() {
                        covariance[(fi, fj)] = c[(i, j)];
                    }
                }
            }
            // a singular factor (not expected: NNLS keeps the free columns independent):
            // no bound on the error
            None => covariance.fill(f64::INFINITY),
        }
    }
    Band {
        taus: taus.to_vec(),
        scale,
        covariance,
        sigma: sigma2.sqrt(),
        multiplier: multiplier(chosen.edf),
        series,
    }
}

/// The simultaneous multiplier (module docs): `√` of the χ² quantile at [`BAND_LEVEL`] with
/// `edf` degrees of freedom (at least 1).
fn multiplier(edf: f64) -> f64 {
    ChiSquared::new(edf.max(1.0))
        .map(|d| d.inverse_cdf(BAND_LEVEL).sqrt())
        .unwrap_or(f64::INFINITY)
}

/// The Prony series of scaled unknowns `x` (empty terms dropped).
fn prony_of(x: &DVector<f64>, taus: &[f64], scale: f64) -> Result<Prony, FitError> {
    let long_term = scale * x[0];
    let instantaneous = long_term + scale * x.iter().skip(1).sum::<f64>();
    let terms: Vec<PronyTerm> = taus
        .iter()
        .zip(x.iter().skip(1))
        .map(|(&tau, &xi)| PronyTerm {
            modulus: scale * xi,
            tau,
        })
        .filter(|t| t.modulus > 0.0 && t.modulus >= EMPTY_TERM_FRACTION * instantaneous)
        .collect();
    Prony::new(long_term, &terms).map_err(FitError::Degenerate)
}

/// Root mean square and largest magnitude of the relative residuals.
fn statistics(residuals: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut count, mut sum, mut max) = (0usize, 0.0, 0.0f64);
    for r in residuals {
        count += 1;
        sum += r * r;
        max = max.max(r.abs());
    }
    ((sum / count.max(1) as f64).sqrt(), max)
}

fn check_settings(settings: &FitSettings) -> Result<(), FitError> {
    // (a NaN is not contained either)
    if !TERMS_PER_DECADE.contains(&settings.terms_per_decade) {
        return Err(FitError::Settings {
            terms_per_decade: settings.terms_per_decade,
        });
    }
    match settings.regularisation {
        Regularisation::Fixed(value) if !(value.is_finite() && value >= 0.0) => {
            Err(FitError::Smoothing { value })
        }
        _ => Ok(()),
    }
}

/// Times or frequencies: at least 3 (checked again against the unknowns later), positive,
/// finite, increasing (`strict`) or non-decreasing; the first and last must differ.
fn check_axis(what: &'static str, axis: &[f64], strict: bool) -> Result<(), FitError> {
    if axis.len() < 3 {
        return Err(FitError::TooFewPoints {
            points: axis.len(),
            values: axis.len(),
            unknowns: 0,
            max_terms_per_decade: None,
        });
    }
    check_positive(what, axis)?;
    for (k, w) in axis.windows(2).enumerate() {
        let (index, previous, value) = (k + 2, w[0], w[1]);
        if strict && value <= previous {
            return Err(FitError::NotIncreasing {
                what,
                index,
                previous,
                value,
            });
        }
        if value < previous {
            return Err(FitError::Decreasing {
                what,
                index,
                previous,
                value,
            });
        }
    }
    // all times equal: no window to fit a relaxation over
    if axis[axis.len() - 1] <= axis[0] {
        return Err(FitError::NoSpread {
            what,
            value: axis[0],
        });
    }
    Ok(())
}

fn check_values(what: &'static str, values: &[f64], expected: usize) -> Result<(), FitError> {
    if values.len() != expected {
        return Err(FitError::LengthMismatch {
            what,
            expected,
            found: values.len(),
        });
    }
    check_positive(what, values)
}

fn check_positive(what: &'static str, values: &[f64]) -> Result<(), FitError> {
    match values.iter().position(|v| !(v.is_finite() && *v > 0.0)) {
        Some(k) => Err(FitError::NotPositive {
            what,
            index: k + 1,
            value: values[k],
        }),
        None => Ok(()),
    }
}

/// Plain NNLS ([`Regularisation::None`]) needs as many fitted values as unknowns; a
/// regularised fit does not (module docs, "Fewer values than unknowns"): the penalty leaves
/// only E∞ and the linear part of the relative spectrum unpenalised, three directions that
/// three points (checked in [`check_axis`]) determine.
///
/// `decades` is the width of the τ grid's window: `⌈decades · N⌉ + 2 ≤ values` unknowns
/// hold for `N ≤ (values − 2)/decades`, the densest grid the error suggests.
fn check_count(
    points: usize,
    values: usize,
    unknowns: usize,
    decades: f64,
    regularisation: Regularisation,
) -> Result<(), FitError> {
    let unregularised = matches!(regularisation, Regularisation::None)
        || regularisation == Regularisation::Fixed(0.0);
    if unregularised && values < unknowns {
        let densest = ((values as f64 - 2.0) / decades * 100.0).floor() / 100.0;
        Err(FitError::TooFewPoints {
            points,
            values,
            unknowns,
            max_terms_per_decade: TERMS_PER_DECADE.contains(&densest).then_some(densest),
        })
    } else {
        Ok(())
    }
}

/// The storage rows of a DMA fit: E′ at each ω, weighted by `scale / E′` (relative residuals).
fn storage_rows(omegas: &[f64], storage: &[f64], scale: f64) -> Vec<Row> {
    omegas
        .iter()
        .zip(storage)
        .map(|(&omega, &e)| Row::Storage {
            omega,
            weight: scale / e,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_has_whole_decades_exactly() {
        let g = tau_grid(1e-5, 1e9, 1.0);
        assert_eq!(g.len(), 15);
        assert_eq!((g[0], g[5], g[14]), (1e-5, 1.0, 1e9));
        assert_eq!(tau_grid(3e-5, 3e8, 2.0)[1], 9.487e-5);
        assert_eq!(tau_grid(1e-5, 1e9, 2.0).len(), 29);
        assert_eq!(tau_grid(1.0, 350.0, 1.0).len(), 4);
    }

    #[test]
    fn fractional_grids_space_terms_by_one_over_n_decades() {
        // 0.5 per decade over 14 decades: one τ every two decades, ends included
        let g = tau_grid(1e-5, 1e9, 0.5);
        assert_eq!(g, [1e-5, 1e-3, 1e-1, 1e1, 1e3, 1e5, 1e7, 1e9]);
        // 0.25 per decade: every four decades
        assert_eq!(tau_grid(1e-4, 1e8, 0.25), [1e-4, 1.0, 1e4, 1e8]);
        // a window that is not a multiple of 1/N: ⌈d N⌉ steps, spacing just under 1/N
        let g = tau_grid(1.0, 1e5, 0.5);
        assert_eq!(g.len(), 4);
        assert_eq!(g[1], 46.42);
        // 1.5 per decade over 2 decades: 3 steps of 2/3 decade
        assert_eq!(tau_grid(1.0, 100.0, 1.5), [1.0, 4.642, 21.54, 100.0]);
    }

    #[test]
    fn input_errors() {
        let s = FitSettings {
            terms_per_decade: 1.0,
            ..FitSettings::default()
        };
        let t = [1.0, 2.0, 3.0, 4.0, 5.0];
        let e = [5.0, 4.0, 3.0, 2.0, 1.0];
        assert!(matches!(
            fit_relaxation(&t[..2], &e[..2], &s),
            Err(FitError::TooFewPoints { points: 2, .. })
        ));
        assert!(matches!(
            fit_relaxation(&[1.0, 3.0, 2.0], &e[..3], &s),
            Err(FitError::Decreasing { index: 3, .. })
        ));
        assert!(matches!(
            fit_relaxation(&[2.0, 2.0, 2.0], &e[..3], &s),
            Err(FitError::NoSpread { .. })
        ));
        assert!(matches!(
            fit_dma(&[1.0, 2.0, 2.0, 3.0, 4.0], &e, &e, &s),
            Err(FitError::NotIncreasing { index: 3, .. })
        ));
        assert!(matches!(
            fit_relaxation(
                &t,
                &e,
                &FitSettings {
                    regularisation: Regularisation::Fixed(-1.0),
                    ..s
                }
            ),
            Err(FitError::Smoothing { .. })
        ));
        assert!(matches!(
            fit_relaxation(&t, &e[..4], &s),
            Err(FitError::LengthMismatch { .. })
        ));
        assert!(matches!(
            fit_relaxation(&t, &[1.0, 1.0, f64::NAN, 1.0, 1.0], &s),
            Err(FitError::NotPositive { index: 3, .. })
        ));
        assert!(matches!(
            fit_dma(&t, &e, &[1.0, 1.0, 1.0, 0.0, 1.0], &s),
            Err(FitError::NotPositive {
                what: "loss modulus",
                index: 4,
                ..
            })
        ));
        for n in [5.0, 0.2, 0.0, -1.0, f64::INFINITY] {
            let bad = FitSettings {
                terms_per_decade: n,
                ..FitSettings::default()
            };
            assert_eq!(
                fit_relaxation(&t, &e, &bad),
                Err(FitError::Settings {
                    terms_per_decade: n
                })
            );
        }
        let nan = FitSettings {
            terms_per_decade: f64::NAN,
            ..FitSettings::default()
        };
        assert!(matches!(
            fit_relaxation(&t, &e, &nan),
            Err(FitError::Settings { .. })
        ));
        // plain NNLS, 3 points over 4 decades: 6 unknowns
        let plain = FitSettings {
            regularisation: Regularisation::None,
            ..s
        };
        let err = fit_relaxation(&[1.0, 10.0, 100.0], &[3.0, 2.0, 1.0], &plain).unwrap_err();
        assert_eq!(
            err,
            FitError::TooFewPoints {
                points: 3,
                values: 3,
                unknowns: 6,
                max_terms_per_decade: Some(0.25)
            }
        );
        assert!(
            err.to_string()
                .contains("3 data points give 3 values for 6 unknowns"),
            "{err}"
        );
        // the suggested grid fits: 4 decades at 0.25 per decade, 2 terms + E∞
        let fit = fit_relaxation(
            &[1.0, 10.0, 100.0],
            &[3.0, 2.0, 1.0],
            &FitSettings {
                terms_per_decade: 0.25,
                ..plain
            },
        )
        .unwrap();
        assert_eq!(fit.grid_terms, 2);
        // a fixed λ = 0 is plain NNLS too
        let zero = FitSettings {
            regularisation: Regularisation::Fixed(0.0),
            ..s
        };
        assert!(matches!(
            fit_relaxation(&[1.0, 10.0, 100.0], &[3.0, 2.0, 1.0], &zero),
            Err(FitError::TooFewPoints { unknowns: 6, .. })
        ));
        // the regularised fit takes them: the penalty leaves three directions free
        let e: Vec<f64> = [1.0, 10.0, 100.0]
            .iter()
            .map(|t| 2.0 + 1.0 / (1.0 + t))
            .collect();
        let fit = fit_relaxation(&[1.0, 10.0, 100.0], &e, &s).unwrap();
        // GCV keeps a residual degree of freedom (edf ≤ n − 1), which the band is
        // estimated from
        assert!(fit.effective_parameters <= 2.0 + 1e-6, "{fit:?}");
        assert!(
            fit.smoothing > 0.0 && fit.max_relative_residual < 0.05,
            "{fit:?}"
        );
        assert!(fit.relative_band(10.0).is_finite(), "{fit:?}");
    }

    #[test]
    fn constant_modulus_is_elastic() {
        let t: Vec<f64> = (0..20).map(|k| 10f64.powf(k as f64 / 5.0)).collect();
        let e = vec![3e6; t.len()];
        let fit = fit_relaxation(&t, &e, &FitSettings::default()).unwrap();
        assert!(fit.max_relative_residual < 1e-12, "{fit:?}");
        assert!((fit.prony.instantaneous() / 3e6 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn repeated_times_are_accepted() {
        // each time measured twice, the two values 1 % apart
        let t: Vec<f64> = (0..40).map(|k| 10f64.powf((k / 2) as f64 / 4.0)).collect();
        let e: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(k, &x)| 2e6 * (1.0 + 1.0 / (1.0 + x)) * if k % 2 == 0 { 1.005 } else { 0.995 })
            .collect();
        let fit = fit_relaxation(&t, &e, &FitSettings::default()).unwrap();
        assert_eq!(fit.points, 40);
        assert!(fit.max_relative_residual < 0.01, "{fit:?}");
    }
}
