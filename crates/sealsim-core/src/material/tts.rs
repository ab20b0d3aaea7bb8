//! Time–temperature superposition (TTS) from stress-relaxation isotherms: shift factors a_T
//! with standard errors, a fitted shift law (WLF or Arrhenius) with 95 % intervals, and a Prony
//! series of the master curve at a reference temperature, ready for a material file
//! (docs/model.md §5).
//!
//! Conventions: temperatures in K, times in s, moduli in Pa. The reduced time of a point
//! measured at time t and temperature T is `ξ = t / a_T`, so `E(t, T) = E_ref(t / a_T)`; a_T > 1
//! below the reference (slower relaxation), as in [`Shift`].
//!
//! # Algorithm ([`master_curve`])
//!
//! 1. **Data.** Isotherms at the same temperature (within [`SAME_TEMPERATURE`]) are merged;
//!    each isotherm's points are sorted by time; at least [`MIN_POINTS`] per isotherm and two
//!    distinct temperatures are needed. The data reference T_d is the data temperature nearest
//!    the median of the distinct temperatures (the lower one on a tie); everything is computed
//!    relative to T_d and converted to a user reference at the end (step 6).
//! 2. **Horizontal shifts only.** The simulator shifts time only ([`Shift`]), so the master
//!    curve is built the same way. The entropic vertical factor `b_T = T ρ / (T0 ρ0)` of rubber
//!    elasticity (Ferry, *Viscoelastic Properties of Polymers*, 3rd ed., Wiley 1980, ch. 11 —
//!    recalled) changes E by a few % over a 100 K range (T/T0 alone is 1.34 from 293 K to
//!    393 K; ρ falls by ≈ 6 % over the same range at a volume expansion of ≈ 6e-4 /K — both
//!    figures recalled); it is **not applied**: such a vertical offset is absorbed partly
//!    into the horizontal shifts and the fitted curve.
//! 3. **Initial shifts** by overlap matching, chained outward from T_d: for adjacent
//!    isotherms (one already placed), the relative shift d (decades) minimises the mean square
//!    difference of log10 E between the two curves over their overlap in log reduced time, each
//!    curve interpolated linearly in log E – log t at the other's points (both directions).
//!    d is scanned in steps of [`SCAN_STEP`] decades over every position with at least
//!    [`MIN_OVERLAP`] overlapping points, then refined by golden-section search. Two adjacent
//!    isotherms whose modulus ranges do not overlap cannot be shifted onto each other
//!    ([`TtsError::NoOverlap`]).
//! 4. **Refinement**, alternating (block coordinate descent on one objective, the sum of
//!    squared relative residuals `E_master(ξ_k)/E_k − 1` over all points, which is also what
//!    [`fit_relaxation`] minimises): (a) fit a Prony master curve to all shifted data
//!    ([`fit_relaxation`] without smoothing, points sorted by reduced time); (b) for each
//!    non-reference isotherm re-estimate log10 a_T by golden-section minimisation (Kiefer,
//!    Proc. Amer. Math. Soc. 4 (1953) 502 — recalled) of its residual sum against that master
//!    curve, over ±[`REFINE_BRACKET`] decades around the current value (re-centred if the
//!    minimum lands on the bracket's edge). Alone, (a)–(b) converge linearly and slowly (the
//!    master curve, fitted to an isotherm where it is, holds it back: with 1 % noise the
//!    shifts still moved by 5e-5 decades per iteration after 20 iterations, ratio ≈ 0.86 per
//!    iteration, measured). So each iteration also tries (c) a joint Gauss–Newton step on all
//!    shifts with the master curve re-fitted (`Δ = −(ZᵀZ)⁻¹ Zᵀ r`, Z of step 5, each
//!    component capped at ±[`REFINE_BRACKET`]) and keeps whichever of (b) and (c) gives the
//!    smaller residual sum (for (c) after re-fitting, for (b) against the old master curve,
//!    an upper bound of its re-fitted sum): the objective never increases. Repeat until no
//!    shift changes by more than [`SHIFT_TOLERANCE`] decades, at most [`MAX_ITERATIONS`]
//!    times (the result says whether it converged; 2–8 iterations in the tests), then fit
//!    the master curve once more at the final shifts, with [`TtsSettings::fit`] (by default
//!    regularised, λ by GCV: the series written to the material file).
//! 5. **Standard errors of the shifts** (Gauss–Newton linearisation at the optimum; e.g. Bates
//!    & Watts, *Nonlinear Regression Analysis and Its Applications*, Wiley 1988 — recalled):
//!    with J_s the derivatives of the relative residuals with respect to the shifts
//!    (`∂r_k/∂ log10 a_i = ln 10 · Σ_j E_j (ξ_k/τ_j) e^{−ξ_k/τ_j} / E_k` on isotherm i's rows)
//!    and A the derivatives with respect to the master curve's non-zero moduli (E∞ and the
//!    NNLS passive terms), the curvature of the residual sum in the shifts *with the master
//!    curve re-fitted* is `M = J_sᵀ (I − P_A) J_s`, P_A the projector on A's columns (the
//!    variable-projection reduction, Golub & Pereyra, SIAM J. Numer. Anal. 10 (1973) 413).
//!    `Cov = σ̂² M⁻¹`, `σ̂² = Σ r² / (N − q − m)` (N points, q master moduli, m shifts). Holding
//!    the master curve fixed instead would understate the errors: outside the overlaps the
//!    master curve follows each isotherm wherever it is put, only the overlaps pin the shift.
//!    The reference's shift is 0 by definition (standard error 0).
//! 6. **Law fit** to (T_i, log10 a_i) of the non-reference temperatures (the reference point
//!    is 0 by definition and not a datum), weighted by `w_i = 1/σ_i²` from step 5:
//!    * WLF `log10 a_T = −C1 (T − T_d)/(C2 + T − T_d)` (Williams, Landel & Ferry, J. Am.
//!      Chem. Soc. 77 (1955) 3701): for fixed C2 the model is linear in C1 (weighted linear
//!      least squares); C2 is found by a scan of ln(C2 − C2_min) over 1e-3 … 1e6 K followed by
//!      golden-section refinement, with `C2_min = max(0, T_d − T_min)` so that the law never
//!      freezes (T ≤ T_d − C2, see [`Shift`]) inside the data range. An optimum on either end
//!      of the scan, or C1 ≤ 0, is not a WLF law ([`TtsError::LawFit`], which suggests
//!      Arrhenius). Needs ≥ 3 temperatures (2 parameters).
//!    * Arrhenius `log10 a_T = (Ea/(R ln 10)) (1/T − 1/T_d)`: one parameter, weighted linear
//!      least squares through the origin; Ea ≤ 0 is rejected.
//!
//!    Covariance `(Jᵀ W J)⁻¹ · max(1, χ²/ν)`, χ² = Σ w_i r_i², ν = points − parameters: the
//!    shift errors propagated, scaled up by the Birge ratio² when the shifts scatter about the
//!    law more than their standard errors say (R.T. Birge, Phys. Rev. 40 (1932) 207; the same
//!    rule as the Particle Data Group's scale factor — both recalled). Why not just the
//!    standard errors: with noise-free or nearly noise-free data the shift errors are
//!    systematic (the master curve's Prony ripple, the model's coupling), not independent;
//!    the residual scatter about the law measures them. Why not just the scatter: with few
//!    temperatures the scatter can be small by chance. 95 % intervals `value ± t_{0.975,ν} ·
//!    std error` (Student t, as in [`super::ageing_fit`]); with ν = 0 (WLF from 3
//!    temperatures, Arrhenius from 2) the law is exact through the points, the intervals are
//!    `None` and [`LawFit::note`] says so (the standard errors are then the propagated ones).
//! 7. **User reference T0** (if given): converted exactly from the fit at T_d. WLF:
//!    `C2' = C2 + T0 − T_d`, `C1' = C1 C2 / C2'` (the same function of T), covariance
//!    propagated linearly; Arrhenius: Ea unchanged. The shifts become
//!    `log10 a_i − log10 a_law(T0)`, the Prony times `τ' = τ · a_law(T0)` (E_T0(t) =
//!    E_Td(t / a_law(T0))), the reduced times likewise. T0 must not be at or below the WLF
//!    freezing temperature.
//!
//! Accuracy (measured in tests/model/tts.rs on data synthesised from a known 16-decade
//! spectrum with log–log slopes −0.24 … −0.53, 5 temperatures 15 K apart, 30 points over
//! 1–1e4 s each): noise-free, log10 a_T to 2e-6 decades (WLF) and 1e-7 (Arrhenius), C1, C2, Ea
//! to 1e-5 relative, the master curve to 3e-4 of E over its 10-decade window. With 1 %
//! multiplicative noise the standard errors of log10 a_T are 0.0023–0.0054 decades (0.5–1.3 %
//! in a_T, largest at the end isotherms, which overlap one neighbour only); the errors stayed
//! within 0.0074 decades (1.7 %) in 20 repeats; 79 of 80 estimates lay within 1.96 standard
//! errors; the 95 % intervals of C1, C2 and Ea covered the truth in 20 of 20 repeats each
//! (half-widths ≈ 1.4 % for C1 and C2, 0.3 % for Ea); the master curve ≈ 0.5 % rms, 2.5 % at
//! worst at the window's ends.

use super::fit::{Fit, FitError, FitSettings, Regularisation, fit_relaxation};
use super::shift::{GAS_CONSTANT, Shift};
use super::{Prony, PronyTerm};
use crate::units::show;
use nalgebra::{DMatrix, DVector, Matrix2};
use sealsim_math::roots::golden_section;
use statrs::distribution::{ContinuousCDF, StudentsT};
use std::f64::consts::LN_10;
use std::fmt;

/// Fewest points per isotherm (after merging isotherms at one temperature).
pub const MIN_POINTS: usize = 3;

/// Fewest overlapping points (both curves together) for an overlap match.
pub const MIN_OVERLAP: usize = 3;

/// Isotherms whose temperatures differ by at most this much \[K\] are merged.
pub const SAME_TEMPERATURE: f64 = 1e-6;

/// Step of the initial overlap scan \[decades\].
pub const SCAN_STEP: f64 = 0.01;

/// Half-width of the refinement's 1-D search around the current shift \[decades\].
pub const REFINE_BRACKET: f64 = 0.25;

/// Refinement stops when no shift changes by more than this \[decades\].
pub const SHIFT_TOLERANCE: f64 = 1e-6;

/// Most refinement iterations.
pub const MAX_ITERATIONS: usize = 20;

/// Smallest standard error used as a weight in the law fit \[decades\] (guards 1/0).
const SIGMA_FLOOR: f64 = 1e-9;

/// One isotherm: relaxation modulus E(t) measured at one temperature.
#[derive(Debug, Clone, PartialEq)]
pub struct Isotherm {
    /// Temperature \[K\].
    pub temperature: f64,
    /// Times \[s\], positive (any order; sorted here).
    pub times: Vec<f64>,
    /// Relaxation moduli \[Pa\], positive, one per time.
    pub moduli: Vec<f64>,
}

/// Which shift law to fit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ShiftLaw {
    /// WLF, `log10 a_T = −C1 (T − Tr)/(C2 + T − Tr)` (default).
    #[default]
    Wlf,
    /// Arrhenius, `log10 a_T = (Ea/(R ln 10))(1/T − 1/Tr)`.
    Arrhenius,
}

impl ShiftLaw {
    fn name(self) -> &'static str {
        match self {
            ShiftLaw::Wlf => "WLF",
            ShiftLaw::Arrhenius => "Arrhenius",
        }
    }
}

/// Settings of [`master_curve`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct TtsSettings {
    /// The shift law to fit (default WLF).
    pub law: ShiftLaw,
    /// Reference temperature \[K\]; default (`None`): the data temperature nearest the median
    /// of the data temperatures.
    pub reference: Option<f64>,
    /// The settings of the final master-curve fit (default: regularised, λ by GCV). The shifts
    /// themselves are estimated with the same grid but without smoothing (module docs, step 4).
    pub fit: FitSettings,
}

/// The measured shift of one temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShiftEstimate {
    /// Temperature \[K\].
    pub temperature: f64,
    /// log10 a_T relative to [`MasterCurve::reference`].
    pub log10_shift: f64,
    /// Standard error of log10 a_T \[decades\] relative to the data reference
    /// [`MasterCurve::data_reference`] (0 there); module docs, step 5.
    pub std_error: f64,
}

/// A fitted parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameter {
    pub value: f64,
    /// Standard error (same unit as the value).
    pub std_error: f64,
    /// 95 % confidence interval, `value ± t_{0.975,ν} · std_error`; `None` when ν = 0.
    pub interval: Option<(f64, f64)>,
}

impl Parameter {
    /// Whether `x` lies in the interval (false without one).
    pub fn covers(&self, x: f64) -> bool {
        self.interval.is_some_and(|(lo, hi)| lo <= x && x <= hi)
    }
}

/// The fitted shift law's parameters, at [`MasterCurve::reference`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FittedLaw {
    /// WLF: C1 (dimensionless), C2 \[K\].
    Wlf { c1: Parameter, c2: Parameter },
    /// Arrhenius: Ea \[J/mol\].
    Arrhenius { activation_energy: Parameter },
}

/// The law fit and its statistics (module docs, step 6).
#[derive(Debug, Clone, PartialEq)]
pub struct LawFit {
    pub law: FittedLaw,
    /// Points fitted: the non-reference temperatures.
    pub points: usize,
    /// ν = points − parameters.
    pub degrees_of_freedom: usize,
    /// Root mean square of `log10 a_i − law(T_i)` \[decades\] (unweighted).
    pub rms_residual: f64,
    /// Birge ratio `√(χ²/ν)` (1 when ν = 0): above 1 the shifts scatter about the law more
    /// than their standard errors say, and the covariance was scaled up by its square.
    pub birge_ratio: f64,
    /// Student t quantile t_{0.975,ν}; `None` when ν = 0.
    pub t_quantile: Option<f64>,
    /// Why the intervals are missing, when they are.
    pub note: Option<String>,
}

/// One data point on the master curve (for plots).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReducedPoint {
    /// Reduced time `t / a_T` at [`MasterCurve::reference`] \[s\], with the *measured* a_T.
    pub reduced_time: f64,
    /// Measured modulus \[Pa\].
    pub modulus: f64,
    /// Index into [`MasterCurve::shifts`].
    pub isotherm: usize,
}

/// The result of [`master_curve`].
#[derive(Debug, Clone, PartialEq)]
pub struct MasterCurve {
    /// Reference temperature \[K\] of everything below (the user's, or [`Self::data_reference`]).
    pub reference: f64,
    /// The data temperature the shifts were measured from \[K\] (module docs, step 1).
    pub data_reference: f64,
    /// One per distinct temperature, ascending.
    pub shifts: Vec<ShiftEstimate>,
    /// The fitted law with intervals.
    pub law: LawFit,
    /// The fitted law as a [`Shift`] at [`Self::reference`] (for a material file).
    pub shift: Shift,
    /// The Prony master curve at [`Self::reference`] (time arguments are reduced times).
    pub fit: Fit,
    /// All points, sorted by reduced time.
    pub reduced: Vec<ReducedPoint>,
    /// Reduced-time range of the data at [`Self::reference`] \[s\]: where the master curve is
    /// backed by data.
    pub window: (f64, f64),
    /// Lowest and highest data temperature \[K\].
    pub temperature_range: (f64, f64),
    /// Refinement iterations done.
    pub iterations: usize,
    /// Whether the shifts converged to [`SHIFT_TOLERANCE`] within [`MAX_ITERATIONS`].
    pub converged: bool,
}

/// Why a master curve could not be built. Temperatures in K.
#[derive(Debug, Clone, PartialEq)]
pub enum TtsError {
    /// No isotherms at all.
    NoData,
    /// All isotherms are at one temperature.
    OneTemperature { temperature: f64 },
    /// A temperature is not positive and finite.
    InvalidTemperature { value: f64 },
    /// An isotherm's times and moduli differ in length.
    LengthMismatch {
        temperature: f64,
        times: usize,
        moduli: usize,
    },
    /// A time or modulus is not positive and finite (index 1-based within the isotherm).
    NotPositive {
        temperature: f64,
        what: &'static str,
        index: usize,
        value: f64,
    },
    /// Too few points in an isotherm.
    TooFewPoints {
        temperature: f64,
        points: usize,
        needed: usize,
    },
    /// Two adjacent isotherms do not overlap in modulus: they cannot be shifted onto each
    /// other.
    NoOverlap { lower: f64, upper: f64 },
    /// The shifts cannot be determined (e.g. flat isotherms: no slope to match).
    Unidentifiable { temperature: f64 },
    /// The master curve's Prony fit failed.
    Fit(FitError),
    /// The shift law could not be fitted.
    LawFit { law: ShiftLaw, reason: String },
    /// The requested reference temperature cannot be used.
    InvalidReference { value: f64, reason: String },
}

/// `253.15 K (−20 °C)`.
fn kelvin(t: f64) -> String {
    format!("{} K ({} °C)", show(t), show(t - 273.15))
}

impl fmt::Display for TtsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TtsError::NoData => write!(f, "no relaxation data were given"),
            TtsError::OneTemperature { temperature } => write!(
                f,
                "all data are at one temperature, {}: time–temperature superposition needs \
                 isotherms at two or more temperatures",
                kelvin(*temperature)
            ),
            TtsError::InvalidTemperature { value } => write!(
                f,
                "temperature {} K is not a positive absolute temperature",
                show(*value)
            ),
            TtsError::LengthMismatch {
                temperature,
                times,
                moduli,
            } => write!(
                f,
                "the isotherm at {} has {times} times but {moduli} moduli",
                kelvin(*temperature)
            ),
            TtsError::NotPositive {
                temperature,
                what,
                index,
                value,
            } => write!(
                f,
                "the isotherm at {}: {what} of point {index} must be positive and finite, got {}",
                kelvin(*temperature),
                show(*value)
            ),
            TtsError::TooFewPoints {
                temperature,
                points,
                needed,
            } => write!(
                f,
                "the isotherm at {} has {points} points, at least {needed} are needed",
                kelvin(*temperature)
            ),
            TtsError::NoOverlap { lower, upper } => write!(
                f,
                "the isotherms at {} and {} do not overlap in modulus, so they cannot be shifted \
                 onto each other; measure longer (at the higher temperature) or shorter \
                 times, or add a temperature in between",
                kelvin(*lower),
                kelvin(*upper)
            ),
            TtsError::Unidentifiable { temperature } => write!(
                f,
                "the shift of the isotherm at {} cannot be determined: the data are too flat \
                 where it overlaps the others (a plateau carries no time information)",
                kelvin(*temperature)
            ),
            TtsError::Fit(e) => write!(f, "the Prony fit of the master curve failed: {e}"),
            TtsError::LawFit { law, reason } => {
                write!(
                    f,
                    "the {} fit of the shift factors failed: {reason}",
                    law.name()
                )
            }
            TtsError::InvalidReference { value, reason } => {
                write!(f, "reference temperature {}: {reason}", kelvin(*value))
            }
        }
    }
}

impl std::error::Error for TtsError {}

impl From<FitError> for TtsError {
    fn from(e: FitError) -> Self {
        TtsError::Fit(e)
    }
}

/// One isotherm, sorted by time, with logs.
struct Curve {
    temperature: f64,
    times: Vec<f64>,
    moduli: Vec<f64>,
    log_t: Vec<f64>,
    log_e: Vec<f64>,
}

impl Curve {
    fn log_e_range(&self) -> (f64, f64) {
        self.log_e
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &y| {
                (lo.min(y), hi.max(y))
            })
    }

    /// log10 E at log10 t = `x`, linear in the log–log points (x inside the range).
    fn interpolate(&self, x: f64) -> f64 {
        let xs = &self.log_t;
        let k = xs.partition_point(|&v| v <= x).clamp(1, xs.len() - 1);
        let (x0, x1) = (xs[k - 1], xs[k]);
        let (y0, y1) = (self.log_e[k - 1], self.log_e[k]);
        if x1 > x0 {
            y0 + (y1 - y0) * (x - x0) / (x1 - x0)
        } else {
            0.5 * (y0 + y1)
        }
    }
}

/// Builds the master curve (module docs). Errors: [`TtsError`].
pub fn master_curve(
    isotherms: &[Isotherm],
    settings: &TtsSettings,
) -> Result<MasterCurve, TtsError> {
    let curves = prepare(isotherms)?;
    if let Some(t0) = settings.reference
        && !(t0.is_finite() && t0 > 0.0)
    {
        return Err(TtsError::InvalidReference {
            value: t0,
            reason: "not a positive absolute temperature".into(),
        });
    }
    let r = data_reference(&curves);
    let td = curves[r].temperature;
    let mut shifts = initial_shifts(&curves, r)?;

    // The shifts minimise one fixed objective, the plain least-squares misfit: a smoothing
    // weight re-chosen by GCV at every iteration would move the objective under the search
    // (and the variable-projection errors of step 5 assume the plain NNLS active set).
    let plain = FitSettings {
        regularisation: Regularisation::None,
        ..settings.fit
    };
    let mut iterations = 0;
    let mut converged = false;
    let (mut fit, _) = fit_master(&curves, &shifts, &plain)?;
    while iterations < MAX_ITERATIONS {
        iterations += 1;
        // (b) one isotherm at a time against the fixed master curve
        let mut swept = shifts.clone();
        let mut swept_sse = 0.0;
        for (i, curve) in curves.iter().enumerate() {
            if i != r {
                swept[i] = refine_shift(&fit.prony, curve, shifts[i]);
            }
            swept_sse += isotherm_misfit(&fit.prony, curve, swept[i]);
        }
        // (c) all shifts at once, the master curve re-fitted (Gauss–Newton, accepted when it
        // beats the sweep)
        let jump = Linearisation::new(&fit.prony, &curves, &shifts, r)?.step(&shifts);
        let (jump_fit, _) = fit_master(&curves, &jump, &plain)?;
        let jump_sse = total_misfit(&jump_fit.prony, &curves, &jump);
        let next = if jump_sse < swept_sse {
            fit = jump_fit;
            jump
        } else {
            fit = fit_master(&curves, &swept, &plain)?.0;
            swept
        };
        let change = next
            .iter()
            .zip(&shifts)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        shifts = next;
        if change < SHIFT_TOLERANCE {
            converged = true;
            break;
        }
    }
    let (plain_fit, mut reduced) = fit_master(&curves, &shifts, &plain)?;
    let errors =
        Linearisation::new(&plain_fit.prony, &curves, &shifts, r)?.std_errors(curves.len());
    let (mut fit, _) = fit_master(&curves, &shifts, &settings.fit)?;
    if let Some(i) = errors.iter().position(|e| !e.is_finite()) {
        return Err(TtsError::Unidentifiable {
            temperature: curves[i].temperature,
        });
    }

    // law fit at the data reference
    let points: Vec<(f64, f64, f64)> = (0..curves.len())
        .filter(|&i| i != r)
        .map(|i| (curves[i].temperature, shifts[i], errors[i]))
        .collect();
    let raw = fit_law(settings.law, td, &points)?;

    // conversion to the user's reference
    let t0 = settings.reference.unwrap_or(td);
    let shift_d = raw.shift(td);
    if shift_d.is_frozen(t0) {
        return Err(TtsError::InvalidReference {
            value: t0,
            reason: format!(
                "at or below the fitted WLF law's freezing temperature {}, where a_T is infinite",
                kelvin(shift_d.frozen_below().unwrap_or(t0))
            ),
        });
    }
    let offset = shift_d.log10_factor(t0); // log10 a(T0) relative to T_d
    let factor = 10f64.powf(offset);
    if !(factor.is_finite() && factor > 0.0) {
        return Err(TtsError::InvalidReference {
            value: t0,
            reason: format!(
                "the fitted law's shift factor there, 1e{}, is out of range",
                show(offset)
            ),
        });
    }
    let law = raw.at_reference(td, t0);
    let shift = match law.law {
        FittedLaw::Wlf { c1, c2 } => Shift::Wlf {
            reference: t0,
            c1: c1.value,
            c2: c2.value,
        },
        FittedLaw::Arrhenius { activation_energy } => Shift::Arrhenius {
            reference: t0,
            activation_energy: activation_energy.value,
        },
    };
    if t0 != td {
        let terms: Vec<PronyTerm> = fit
            .prony
            .terms()
            .iter()
            .map(|t| PronyTerm {
                modulus: t.modulus,
                tau: t.tau * factor,
            })
            .collect();
        fit.prony = Prony::new(fit.prony.long_term(), &terms)
            .map_err(|e| TtsError::Fit(FitError::Degenerate(e)))?;
        fit.window = (fit.window.0 * factor, fit.window.1 * factor);
        for p in &mut reduced {
            p.reduced_time *= factor;
        }
    }
    let shifts = curves
        .iter()
        .enumerate()
        .map(|(i, c)| ShiftEstimate {
            temperature: c.temperature,
            log10_shift: shifts[i] - offset,
            std_error: errors[i],
        })
        .collect();
    let temperature_range = (curves[0].temperature, curves[curves.len() - 1].temperature);
    Ok(MasterCurve {
        reference: t0,
        data_reference: td,
        shifts,
        law,
        shift,
        window: fit.window,
        fit,
        reduced,
        temperature_range,
        iterations,
        converged,
    })
}

/// Validates, merges equal temperatures, sorts (module docs, step 1).
fn prepare(isotherms: &[Isotherm]) -> Result<Vec<Curve>, TtsError> {
    for iso in isotherms {
        let t = iso.temperature;
        if !(t.is_finite() && t > 0.0) {
            return Err(TtsError::InvalidTemperature { value: t });
        }
        if iso.times.len() != iso.moduli.len() {
            return Err(TtsError::LengthMismatch {
                temperature: t,
                times: iso.times.len(),
                moduli: iso.moduli.len(),
            });
        }
        for (what, values) in [("time", &iso.times), ("modulus", &iso.moduli)] {
            if let Some(k) = values.iter().position(|v| !(v.is_finite() && *v > 0.0)) {
                return Err(TtsError::NotPositive {
                    temperature: t,
                    what,
                    index: k + 1,
                    value: values[k],
                });
            }
        }
    }
    let mut order: Vec<&Isotherm> = isotherms.iter().collect();
    order.sort_by(|a, b| a.temperature.total_cmp(&b.temperature));
    let mut groups: Vec<(f64, Vec<(f64, f64)>)> = Vec::new();
    for iso in order {
        let pts = iso.times.iter().copied().zip(iso.moduli.iter().copied());
        match groups.last_mut() {
            Some((t, v)) if (iso.temperature - *t).abs() <= SAME_TEMPERATURE => v.extend(pts),
            _ => groups.push((iso.temperature, pts.collect())),
        }
    }
    match groups.len() {
        0 => return Err(TtsError::NoData),
        1 => {
            return Err(TtsError::OneTemperature {
                temperature: groups[0].0,
            });
        }
        _ => {}
    }
    groups
        .into_iter()
        .map(|(temperature, mut pts)| {
            if pts.len() < MIN_POINTS {
                return Err(TtsError::TooFewPoints {
                    temperature,
                    points: pts.len(),
                    needed: MIN_POINTS,
                });
            }
            pts.sort_by(|a, b| a.0.total_cmp(&b.0));
            let times: Vec<f64> = pts.iter().map(|p| p.0).collect();
            let moduli: Vec<f64> = pts.iter().map(|p| p.1).collect();
            Ok(Curve {
                temperature,
                log_t: times.iter().map(|t| t.log10()).collect(),
                log_e: moduli.iter().map(|e| e.log10()).collect(),
                times,
                moduli,
            })
        })
        .collect()
}

/// Index of the data temperature nearest the median of the (sorted, distinct) temperatures;
/// the lower one on a tie.
fn data_reference(curves: &[Curve]) -> usize {
    let n = curves.len();
    let median = if n % 2 == 1 {
        curves[n / 2].temperature
    } else {
        0.5 * (curves[n / 2 - 1].temperature + curves[n / 2].temperature)
    };
    let mut best = 0;
    for (i, c) in curves.iter().enumerate() {
        if (c.temperature - median).abs() < (curves[best].temperature - median).abs() {
            best = i;
        }
    }
    best
}

/// Shifts (log10 a_T relative to curve `r`) by overlap matching, chained outward from `r`.
fn initial_shifts(curves: &[Curve], r: usize) -> Result<Vec<f64>, TtsError> {
    let mut shifts = vec![0.0; curves.len()];
    for i in r + 1..curves.len() {
        shifts[i] = shifts[i - 1] + relative_shift(&curves[i - 1], &curves[i])?;
    }
    for i in (0..r).rev() {
        shifts[i] = shifts[i + 1] + relative_shift(&curves[i + 1], &curves[i])?;
    }
    Ok(shifts)
}

/// Mean square difference of log10 E between `fixed` (at its own log times) and `moving`
/// (at log times − d) over their overlap; `None` with fewer than [`MIN_OVERLAP`] points.
fn overlap_misfit(fixed: &Curve, moving: &Curve, d: f64) -> Option<f64> {
    let (f0, f1) = (fixed.log_t[0], fixed.log_t[fixed.log_t.len() - 1]);
    let (m0, m1) = (
        moving.log_t[0] - d,
        moving.log_t[moving.log_t.len() - 1] - d,
    );
    let mut sum = 0.0;
    let mut count = 0usize;
    for (&x, &y) in moving.log_t.iter().zip(&moving.log_e) {
        let x = x - d;
        if x >= f0 && x <= f1 {
            sum += (y - fixed.interpolate(x)).powi(2);
            count += 1;
        }
    }
    for (&x, &y) in fixed.log_t.iter().zip(&fixed.log_e) {
        if x >= m0 && x <= m1 {
            sum += (moving.interpolate(x + d) - y).powi(2);
            count += 1;
        }
    }
    (count >= MIN_OVERLAP).then(|| sum / count as f64)
}

/// The shift d \[decades\] of `moving` relative to `fixed` (module docs, step 3).
fn relative_shift(fixed: &Curve, moving: &Curve) -> Result<f64, TtsError> {
    let no_overlap = || TtsError::NoOverlap {
        lower: fixed.temperature.min(moving.temperature),
        upper: fixed.temperature.max(moving.temperature),
    };
    let (a0, a1) = fixed.log_e_range();
    let (b0, b1) = moving.log_e_range();
    if a0.max(b0) >= a1.min(b1) {
        return Err(no_overlap());
    }
    let lo = moving.log_t[0] - fixed.log_t[fixed.log_t.len() - 1];
    let hi = moving.log_t[moving.log_t.len() - 1] - fixed.log_t[0];
    let steps = (((hi - lo) / SCAN_STEP).ceil() as usize).clamp(1, 100_000);
    let h = (hi - lo) / steps as f64;
    let mut best: Option<(f64, f64)> = None;
    for k in 0..=steps {
        let d = lo + h * k as f64;
        if let Some(m) = overlap_misfit(fixed, moving, d)
            && best.is_none_or(|(_, b)| m < b)
        {
            best = Some((d, m));
        }
    }
    let (d, _) = best.ok_or_else(no_overlap)?;
    let objective = |x: f64| overlap_misfit(fixed, moving, x).unwrap_or(f64::INFINITY);
    let refined = golden_section(objective, d - h, d + h, 1e-9);
    Ok(if objective(refined) <= objective(d) {
        refined
    } else {
        d
    })
}

/// Prony fit of all points at `shifts`, with the points sorted by reduced time.
fn fit_master(
    curves: &[Curve],
    shifts: &[f64],
    settings: &FitSettings,
) -> Result<(Fit, Vec<ReducedPoint>), TtsError> {
    let mut reduced: Vec<ReducedPoint> = curves
        .iter()
        .enumerate()
        .flat_map(|(i, c)| {
            let f = 10f64.powf(-shifts[i]);
            c.times
                .iter()
                .zip(&c.moduli)
                .map(move |(&t, &e)| ReducedPoint {
                    reduced_time: t * f,
                    modulus: e,
                    isotherm: i,
                })
        })
        .collect();
    reduced.sort_by(|a, b| a.reduced_time.total_cmp(&b.reduced_time));
    let xi: Vec<f64> = reduced.iter().map(|p| p.reduced_time).collect();
    let e: Vec<f64> = reduced.iter().map(|p| p.modulus).collect();
    let fit = fit_relaxation(&xi, &e, settings)?;
    Ok((fit, reduced))
}

/// Σ (E_master(t/a)/E − 1)² of one isotherm at log10 a = `c`.
fn isotherm_misfit(prony: &Prony, curve: &Curve, c: f64) -> f64 {
    let f = 10f64.powf(-c);
    curve
        .times
        .iter()
        .zip(&curve.moduli)
        .map(|(&t, &e)| (prony.relaxation(t * f) / e - 1.0).powi(2))
        .sum()
}

/// Σ over all isotherms of [`isotherm_misfit`].
fn total_misfit(prony: &Prony, curves: &[Curve], shifts: &[f64]) -> f64 {
    curves
        .iter()
        .zip(shifts)
        .map(|(c, &s)| isotherm_misfit(prony, c, s))
        .sum()
}

/// The shift minimising [`isotherm_misfit`] near `current` (module docs, step 4).
fn refine_shift(prony: &Prony, curve: &Curve, current: f64) -> f64 {
    let objective = |c: f64| isotherm_misfit(prony, curve, c);
    let mut centre = current;
    for _ in 0..10 {
        let (a, b) = (centre - REFINE_BRACKET, centre + REFINE_BRACKET);
        let x = golden_section(objective, a, b, 1e-9);
        let edge = (x - a).min(b - x) < 0.01 * REFINE_BRACKET;
        centre = x;
        if !edge {
            break;
        }
    }
    if objective(centre) <= objective(current) {
        centre
    } else {
        current
    }
}

/// The joint least-squares problem linearised in the shifts at a master curve (module docs,
/// step 5): `Z = (I − P_A) J_s` and the Gauss–Newton pieces.
struct Linearisation {
    /// Indices of the non-reference curves (the columns of Z).
    others: Vec<usize>,
    /// `(ZᵀZ)⁻¹`.
    inverse: DMatrix<f64>,
    /// `Zᵀ r`.
    gradient: DVector<f64>,
    /// Σ r² over all points.
    sse: f64,
    /// Residual degrees of freedom N − q − m (at least 1).
    dof: usize,
}

impl Linearisation {
    fn new(prony: &Prony, curves: &[Curve], shifts: &[f64], r: usize) -> Result<Self, TtsError> {
        let n: usize = curves.iter().map(|c| c.times.len()).sum();
        let terms = prony.terms();
        let with_long = prony.long_term() > 0.0;
        let q = terms.len() + usize::from(with_long);
        let others: Vec<usize> = (0..curves.len()).filter(|&i| i != r).collect();
        let m = others.len();
        let mut a = DMatrix::zeros(n, q);
        let mut js = DMatrix::zeros(n, m);
        let mut residual = DVector::zeros(n);
        let mut row = 0;
        for (i, curve) in curves.iter().enumerate() {
            let f = 10f64.powf(-shifts[i]);
            let column = others.iter().position(|&o| o == i);
            for (&t, &e) in curve.times.iter().zip(&curve.moduli) {
                let xi = t * f;
                residual[row] = prony.relaxation(xi) / e - 1.0;
                let mut col = 0;
                if with_long {
                    a[(row, 0)] = 1.0 / e;
                    col = 1;
                }
                let mut slope = 0.0;
                for (j, term) in terms.iter().enumerate() {
                    let x = xi / term.tau;
                    let decay = (-x).exp();
                    a[(row, col + j)] = decay / e;
                    slope += term.modulus * x * decay;
                }
                if let Some(k) = column {
                    js[(row, k)] = LN_10 * slope / e;
                }
                row += 1;
            }
        }
        let unidentifiable = |k: usize| TtsError::Unidentifiable {
            temperature: curves[others[k]].temperature,
        };
        // Z = (I − Q Qᵀ) J_s, Q an orthonormal basis of A's columns
        let z = if q == 0 {
            js.clone()
        } else if q < n {
            let basis = a.qr().q();
            let projection = &basis * (basis.transpose() * &js);
            &js - projection
        } else {
            return Err(unidentifiable(0));
        };
        let curvature = z.transpose() * &z;
        // a shift whose column lies (almost) inside the master curve's span is not determined
        for k in 0..m {
            let full = js.column(k).norm_squared();
            if !(full > 0.0 && curvature[(k, k)] > 1e-12 * full) {
                return Err(unidentifiable(k));
            }
        }
        let inverse = curvature
            .cholesky()
            .map(|c| c.inverse())
            .filter(|inv| inv.iter().all(|v| v.is_finite()))
            .ok_or_else(|| unidentifiable(0))?;
        Ok(Linearisation {
            others,
            inverse,
            gradient: z.transpose() * &residual,
            sse: residual.norm_squared(),
            dof: n.saturating_sub(q + m).max(1),
        })
    }

    /// The variable-projection Gauss–Newton step `−(ZᵀZ)⁻¹ Zᵀ r` applied to `shifts`, each
    /// component limited to ±[`REFINE_BRACKET`].
    fn step(&self, shifts: &[f64]) -> Vec<f64> {
        let delta = -(&self.inverse * &self.gradient);
        let largest = delta.amax();
        let scale = if largest > REFINE_BRACKET {
            REFINE_BRACKET / largest
        } else {
            1.0
        };
        let mut out = shifts.to_vec();
        for (k, &i) in self.others.iter().enumerate() {
            out[i] += scale * delta[k];
        }
        out
    }

    /// Standard errors \[decades\]: `√(σ̂² [(ZᵀZ)⁻¹]_ii)`, σ̂² = Σ r²/(N − q − m); 0 for the
    /// reference.
    fn std_errors(&self, count: usize) -> Vec<f64> {
        let variance = self.sse / self.dof as f64;
        let mut errors = vec![0.0; count];
        for (k, &i) in self.others.iter().enumerate() {
            errors[i] = (variance * self.inverse[(k, k)]).sqrt();
        }
        errors
    }
}

/// A law fitted at the data reference T_d, before conversion.
struct RawLaw {
    kind: RawKind,
    points: usize,
    dof: usize,
    rms: f64,
    birge: f64,
    t_quantile: Option<f64>,
}

enum RawKind {
    /// C1, C2 \[K\] and their covariance.
    Wlf { c1: f64, c2: f64, cov: Matrix2<f64> },
    /// Slope Ea/(R ln 10) \[K\] and its variance.
    Arrhenius { slope: f64, variance: f64 },
}

impl RawLaw {
    /// The law as a [`Shift`] at reference `td`.
    fn shift(&self, td: f64) -> Shift {
        match self.kind {
            RawKind::Wlf { c1, c2, .. } => Shift::Wlf {
                reference: td,
                c1,
                c2,
            },
            RawKind::Arrhenius { slope, .. } => Shift::Arrhenius {
                reference: td,
                activation_energy: slope * GAS_CONSTANT * LN_10,
            },
        }
    }

    /// The parameters at reference `t0` (module docs, step 7).
    fn at_reference(&self, td: f64, t0: f64) -> LawFit {
        let parameter = |value: f64, variance: f64| {
            let std_error = variance.max(0.0).sqrt();
            Parameter {
                value,
                std_error,
                interval: self
                    .t_quantile
                    .map(|t| (value - t * std_error, value + t * std_error)),
            }
        };
        let law = match self.kind {
            RawKind::Wlf { c1, c2, cov } => {
                let c2n = c2 + t0 - td;
                let c1n = c1 * c2 / c2n;
                let g = Matrix2::new(c2 / c2n, c1 * (t0 - td) / (c2n * c2n), 0.0, 1.0);
                let cn = g * cov * g.transpose();
                FittedLaw::Wlf {
                    c1: parameter(c1n, cn[(0, 0)]),
                    c2: parameter(c2n, cn[(1, 1)]),
                }
            }
            RawKind::Arrhenius { slope, variance } => {
                let k = GAS_CONSTANT * LN_10;
                FittedLaw::Arrhenius {
                    activation_energy: parameter(slope * k, variance * k * k),
                }
            }
        };
        let note = self.t_quantile.is_none().then(|| {
            format!(
                "no intervals: {} points for {} parameters leave no degrees of freedom; the \
                 standard errors are the shifts' errors propagated",
                self.points,
                self.points - self.dof
            )
        });
        LawFit {
            law,
            points: self.points,
            degrees_of_freedom: self.dof,
            rms_residual: self.rms,
            birge_ratio: self.birge,
            t_quantile: self.t_quantile,
            note,
        }
    }
}

/// Student t quantile t_{0.975,ν} (ν ≥ 1).
fn t_quantile(dof: usize) -> Result<f64, String> {
    StudentsT::new(0.0, 1.0, dof as f64)
        .map(|t| t.inverse_cdf(0.975))
        .map_err(|e| format!("Student t distribution: {e}"))
}

/// Weighted fit of `law` to (T, log10 a, σ) relative to `td` (module docs, step 6).
fn fit_law(law: ShiftLaw, td: f64, points: &[(f64, f64, f64)]) -> Result<RawLaw, TtsError> {
    let fail = |reason: String| TtsError::LawFit { law, reason };
    let weights: Vec<f64> = points
        .iter()
        .map(|p| 1.0 / p.2.max(SIGMA_FLOOR).powi(2))
        .collect();
    let n = points.len();
    let parameters = match law {
        ShiftLaw::Wlf => 2,
        ShiftLaw::Arrhenius => 1,
    };
    if n < parameters {
        return Err(fail(format!(
            "{} temperatures give {n} shift factor(s) besides the reference, too few for \
             {parameters} parameters; measure more temperatures or fit Arrhenius (one parameter)",
            n + 1
        )));
    }
    let dof = n - parameters;
    // parameters with their unscaled covariance, and the model values, by law
    let (kind, predicted): (RawKind, Vec<f64>) = match law {
        ShiftLaw::Arrhenius => {
            let xs: Vec<f64> = points.iter().map(|p| 1.0 / p.0 - 1.0 / td).collect();
            let sxx: f64 = xs.iter().zip(&weights).map(|(x, w)| w * x * x).sum();
            let sxy: f64 = xs
                .iter()
                .zip(points)
                .zip(&weights)
                .map(|((x, p), w)| w * x * p.1)
                .sum();
            let slope = sxy / sxx;
            if !(slope.is_finite() && slope > 0.0) {
                return Err(fail(format!(
                    "the shift factors do not fall with temperature (Ea = {} J/mol ≤ 0)",
                    show(slope * GAS_CONSTANT * LN_10)
                )));
            }
            let predicted = xs.iter().map(|x| slope * x).collect();
            (
                RawKind::Arrhenius {
                    slope,
                    variance: 1.0 / sxx,
                },
                predicted,
            )
        }
        ShiftLaw::Wlf => {
            let us: Vec<f64> = points.iter().map(|p| p.0 - td).collect();
            let u_min = us.iter().copied().fold(f64::INFINITY, f64::min);
            let c2_min = (-u_min).max(0.0);
            // profile: C1 and χ² at C2 = C2_min + e^s
            let profile = |s: f64| {
                let c2 = c2_min + s.exp();
                let (mut sgg, mut sgy) = (0.0, 0.0);
                for ((u, p), w) in us.iter().zip(points).zip(&weights) {
                    let g = -u / (c2 + u);
                    sgg += w * g * g;
                    sgy += w * g * p.1;
                }
                let c1 = sgy / sgg;
                let chi2: f64 = us
                    .iter()
                    .zip(points)
                    .zip(&weights)
                    .map(|((u, p), w)| w * (p.1 + c1 * u / (c2 + u)).powi(2))
                    .sum();
                (
                    c1,
                    c2,
                    if chi2.is_finite() {
                        chi2
                    } else {
                        f64::INFINITY
                    },
                )
            };
            let (s_lo, s_hi) = (1e-3f64.ln(), 1e6f64.ln());
            let steps = 400;
            let s_at = |k: usize| s_lo + (s_hi - s_lo) * k as f64 / steps as f64;
            let best = (0..=steps)
                .min_by(|&a, &b| profile(s_at(a)).2.total_cmp(&profile(s_at(b)).2))
                .unwrap_or(0);
            let wlf_hint = "the shift factors do not follow WLF; fit Arrhenius instead";
            if best == 0 {
                return Err(fail(format!(
                    "the best WLF law freezes at the lowest data temperature (C2 → {} K at \
                     {}): {wlf_hint}",
                    show(c2_min),
                    kelvin(td)
                )));
            }
            if best == steps {
                return Err(fail(format!(
                    "the best WLF law has C2 → ∞ (log a_T linear in T, or curving the wrong \
                     way): {wlf_hint}"
                )));
            }
            let s = golden_section(|s| profile(s).2, s_at(best - 1), s_at(best + 1), 1e-12);
            let (c1, c2, _) = profile(s);
            if !(c1.is_finite() && c1 > 0.0) {
                return Err(fail(format!(
                    "C1 = {} ≤ 0 (the shift factors do not fall with temperature): {wlf_hint}",
                    show(c1)
                )));
            }
            let predicted = us.iter().map(|u| -c1 * u / (c2 + u)).collect();
            let rows: Vec<[f64; 2]> = us
                .iter()
                .map(|u| [-u / (c2 + u), c1 * u / (c2 + u).powi(2)])
                .collect();
            let mut info = Matrix2::zeros();
            for (row, w) in rows.iter().zip(&weights) {
                for i in 0..2 {
                    for j in 0..2 {
                        info[(i, j)] += w * row[i] * row[j];
                    }
                }
            }
            let cov = info.try_inverse().filter(|c: &Matrix2<f64>| {
                c.iter().all(|v: &f64| v.is_finite()) && c[(0, 0)] > 0.0 && c[(1, 1)] > 0.0
            });
            let Some(cov) = cov else {
                return Err(fail(
                    "C1 and C2 cannot be separated by these shift factors (singular \
                     information matrix); fit Arrhenius instead"
                        .into(),
                ));
            };
            (RawKind::Wlf { c1, c2, cov }, predicted)
        }
    };
    let residuals: Vec<f64> = points
        .iter()
        .zip(&predicted)
        .map(|(p, y)| p.1 - y)
        .collect();
    let chi2: f64 = residuals.iter().zip(&weights).map(|(r, w)| w * r * r).sum();
    let rms = (residuals.iter().map(|r| r * r).sum::<f64>() / n as f64).sqrt();
    let (birge, t_q) = if dof > 0 {
        (
            (chi2 / dof as f64).sqrt(),
            Some(t_quantile(dof).map_err(fail)?),
        )
    } else {
        (1.0, None)
    };
    let scale = birge.max(1.0).powi(2);
    let kind = match kind {
        RawKind::Wlf { c1, c2, cov } => RawKind::Wlf {
            c1,
            c2,
            cov: cov * scale,
        },
        RawKind::Arrhenius { slope, variance } => RawKind::Arrhenius {
            slope,
            variance: variance * scale,
        },
    };
    Ok(RawLaw {
        kind,
        points: n,
        dof,
        rms,
        birge,
        t_quantile: t_q,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_is_nearest_the_median() {
        let curve = |t: f64| Curve {
            temperature: t,
            times: vec![],
            moduli: vec![],
            log_t: vec![],
            log_e: vec![],
        };
        let c: Vec<Curve> = [250.0, 260.0, 300.0, 320.0].map(curve).into();
        // median 280: 260 and 300 are equally near, the lower wins
        assert_eq!(data_reference(&c), 1);
        let c: Vec<Curve> = [250.0, 290.0, 300.0].map(curve).into();
        assert_eq!(data_reference(&c), 1);
    }
}
