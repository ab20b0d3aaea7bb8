//! Lifetime from accelerated-ageing data by ISO 11346 (docs/model.md §6.6): the time to an
//! end-of-life criterion at each ageing temperature, an Arrhenius fit of those times, and the
//! life extrapolated to a service temperature.
//!
//! * **Data** (read at the input boundary, `scenario::ageing_data::parse_ageing_data`): a CSV file `temperature,time,value` with a units row
//!   (`C,h,1`: an absolute temperature unit, a time unit, `1` or `%` for the value). The value
//!   is a compression set (rising with time) or a retained-force fraction F/F0 (falling).
//! * **Time to criterion** ([`time_to_criterion`]): the first pair of consecutive points
//!   (t_a, v_a), (t_b, v_b) of one temperature that brackets the criterion c, interpolated
//!   linearly in ln t: `ln t* = ln t_a + (c − v_a)/(v_b − v_a) · (ln t_b − ln t_a)`. Points at
//!   t = 0 take no part (ln 0 does not exist). A temperature whose data never reach c, or
//!   reach it at the first positive time, gives no time: ISO 11346 then asks for longer (or
//!   shorter) ageing, and the temperature is left out of the fit.
//! * **Arrhenius fit** ([`fit_arrhenius`]): `ln t* = ln A + Ea/(R T)`, ordinary least squares
//!   in x = 1/T over n ≥ 3 usable temperatures (ISO 11346:2014 §7–8). With the residual
//!   variance s² = Σ r²/(n − 2), S_xx = Σ (x − x̄)² and the Student t quantile
//!   t_q = t_{0.975, n−2}: Ea = R b, its 95 % confidence interval R (b ± t_q s/√S_xx); the
//!   life at T_s, `t_s = exp(a + b/T_s)`, with the 95 % confidence interval of the regression
//!   line, `exp(ŷ ± t_q s √(1/n + (x_s − x̄)²/S_xx))`, and the wider 95 % prediction interval of
//!   one new determination (`1 +` under the root); r² = 1 − Σ r²/Σ (y − ȳ)².
//! * **Ageing constants** ([`ageing_constants`]): the rate k_ref of the two-network model at a
//!   reference temperature from the life there, by the model's balanced relation (§6.5):
//!   compression set CS = 1 − exp(−k t) → `k = −ln(1 − c)/t*`; retained force
//!   F/F0 = exp(−k t) → `k = −ln(c)/t*`.

use crate::material::{Ageing, AgeingBasis, BALANCED_CROSSLINKING};
use crate::units::show;
use statrs::distribution::{ContinuousCDF, StudentsT};

/// Molar gas constant R \[J/(mol K)\] (CODATA 2018, exact).
pub const GAS_CONSTANT: f64 = 8.314_462_618;

/// Fewest usable temperatures of a fit (ISO 11346: at least three ageing temperatures).
pub const MIN_TEMPERATURES: usize = 3;

/// What the value column measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AgeingKind {
    /// Compression set, a fraction rising with ageing time; end of life when it reaches c.
    CompressionSet,
    /// Retained sealing force F/F0, falling with ageing time; end of life when it falls to c.
    RetainedForce,
}

impl AgeingKind {
    /// `compression-set` or `retained-force`, as on the command line.
    pub fn as_str(self) -> &'static str {
        match self {
            AgeingKind::CompressionSet => "compression-set",
            AgeingKind::RetainedForce => "retained-force",
        }
    }

    /// Whether the value rises with ageing time.
    fn rises(self) -> bool {
        self == AgeingKind::CompressionSet
    }

    /// Whether `value` has reached the criterion `c`.
    fn reached(self, value: f64, c: f64) -> bool {
        match self {
            AgeingKind::CompressionSet => value >= c,
            AgeingKind::RetainedForce => value <= c,
        }
    }

    /// The two-network rate that reaches criterion `c` after `time` \[s\] (§6.5):
    /// −ln(1 − c)/t for a compression set, −ln(c)/t for a retained force \[1/s\].
    pub fn rate(self, c: f64, time: f64) -> f64 {
        match self {
            AgeingKind::CompressionSet => -(1.0 - c).ln() / time,
            AgeingKind::RetainedForce => -c.ln() / time,
        }
    }
}

/// One measured point: the 1-based line of the data file, time \[s\] and value (fraction).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AgeingPoint {
    pub line: usize,
    pub time: f64,
    pub value: f64,
}

/// The points of one ageing temperature, in file order (times strictly increasing).
#[derive(Debug, Clone, PartialEq)]
pub struct AgeingSeries {
    /// Ageing temperature \[K\].
    pub temperature: f64,
    pub points: Vec<AgeingPoint>,
}

impl AgeingSeries {
    /// +1 when the value rises from the first to the last point, −1 when it falls, 0 when equal.
    fn direction(&self) -> i8 {
        match (self.points.first(), self.points.last()) {
            (Some(a), Some(b)) if b.value > a.value => 1,
            (Some(a), Some(b)) if b.value < a.value => -1,
            _ => 0,
        }
    }
}

/// The kind of the data: `given`, checked against every series' net direction (first to last
/// point: a compression set must rise, a retained force fall), or inferred from the directions
/// when `None`. Returns the kind and whether it was inferred.
pub fn resolve_kind(
    series: &[AgeingSeries],
    given: Option<AgeingKind>,
) -> Result<(AgeingKind, bool), (Option<usize>, String)> {
    let last_line = |s: &AgeingSeries| s.points.last().map(|p| p.line);
    if let Some(kind) = given {
        for s in series {
            let d = s.direction();
            if (kind.rises() && d < 0) || (!kind.rises() && d > 0) || d == 0 {
                return Err((
                    last_line(s),
                    format!(
                        "the series at {} K {} with ageing time, but a {} must {}",
                        show(s.temperature),
                        match d {
                            1 => "rises",
                            -1 => "falls",
                            _ => "does not change",
                        },
                        kind.as_str(),
                        if kind.rises() { "rise" } else { "fall" }
                    ),
                ));
            }
        }
        return Ok((kind, false));
    }
    let rising = series.iter().filter(|s| s.direction() > 0).count();
    let falling = series.iter().filter(|s| s.direction() < 0).count();
    match (rising, falling) {
        (r, 0) if r == series.len() => Ok((AgeingKind::CompressionSet, true)),
        (0, f) if f == series.len() => Ok((AgeingKind::RetainedForce, true)),
        _ => Err((
            None,
            format!(
                "cannot infer the kind: {rising} series rise, {falling} fall and {} stay flat \
                 with ageing time; give --kind compression-set or --kind retained-force",
                series.len() - rising - falling
            ),
        )),
    }
}

/// The time to criterion of one temperature, or why there is none.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Crossing {
    /// Time t* \[s\] interpolated linearly in ln t between the bracketing points.
    Reached(f64),
    /// The criterion is already passed at the first positive time: shorter ageing times needed.
    AtFirstTime,
    /// The data never reach the criterion: longer ageing needed.
    NotReached,
}

/// The time at which `series` first reaches criterion `c` (module doc: log-time linear
/// interpolation between the bracketing points; points at t = 0 ignored).
pub fn time_to_criterion(series: &AgeingSeries, kind: AgeingKind, c: f64) -> Crossing {
    let points: Vec<&AgeingPoint> = series.points.iter().filter(|p| p.time > 0.0).collect();
    match points.first() {
        None => return Crossing::NotReached,
        Some(p) if kind.reached(p.value, c) => return Crossing::AtFirstTime,
        Some(_) => {}
    }
    for pair in points.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        if kind.reached(b.value, c) {
            let fraction = (c - a.value) / (b.value - a.value);
            let ln_t = a.time.ln() + fraction * (b.time.ln() - a.time.ln());
            return Crossing::Reached(ln_t.exp());
        }
    }
    Crossing::NotReached
}

/// An Arrhenius fit `ln t = ln A + Ea/(R T)` with its 95 % intervals (module doc).
#[derive(Debug, Clone, PartialEq)]
pub struct ArrheniusFit {
    /// Usable points (temperature \[K\], time \[s\]).
    pub points: Vec<(f64, f64)>,
    /// Intercept ln A (A in s).
    pub intercept: f64,
    /// Slope Ea/R \[K\].
    pub slope: f64,
    /// Ea \[J/mol\].
    pub activation_energy: f64,
    /// 95 % confidence interval of Ea \[J/mol\].
    pub activation_energy_interval: (f64, f64),
    /// r² of the regression of ln t on 1/T.
    pub r_squared: f64,
    /// Residual standard deviation s of ln t.
    pub residual_sd: f64,
    /// Student t quantile t_{0.975, n−2}.
    pub t_quantile: f64,
    mean_x: f64,
    sxx: f64,
}

impl ArrheniusFit {
    /// The fitted time \[s\] at temperature `t` \[K\]: exp(ln A + (Ea/R)/T).
    pub fn time_at(&self, t: f64) -> f64 {
        (self.intercept + self.slope / t).exp()
    }

    /// The 95 % interval \[s\] at `t` \[K\]: of the regression line (`prediction = false`), or
    /// of one new determination (`prediction = true`).
    pub fn interval_at(&self, t: f64, prediction: bool) -> (f64, f64) {
        let n = self.points.len() as f64;
        let x = 1.0 / t;
        let extra = if prediction { 1.0 } else { 0.0 };
        let half = self.t_quantile
            * self.residual_sd
            * (extra + 1.0 / n + (x - self.mean_x).powi(2) / self.sxx).sqrt();
        let y = self.intercept + self.slope * x;
        ((y - half).exp(), (y + half).exp())
    }
}

/// Least-squares fit of ln t on 1/T over `points` (temperature \[K\], time \[s\]), n ≥ 3
/// (module doc). Errors: too few points, all at one temperature, or Ea ≤ 0 (the times do not
/// shorten with temperature: no Arrhenius extrapolation).
pub fn fit_arrhenius(points: &[(f64, f64)]) -> Result<ArrheniusFit, String> {
    let n = points.len();
    if n < MIN_TEMPERATURES {
        return Err(format!(
            "{n} usable temperatures, an Arrhenius fit needs at least {MIN_TEMPERATURES} (ISO 11346)"
        ));
    }
    let xs: Vec<f64> = points.iter().map(|p| 1.0 / p.0).collect();
    let ys: Vec<f64> = points.iter().map(|p| p.1.ln()).collect();
    let nf = n as f64;
    let mean_x = xs.iter().sum::<f64>() / nf;
    let mean_y = ys.iter().sum::<f64>() / nf;
    let sxx: f64 = xs.iter().map(|x| (x - mean_x).powi(2)).sum();
    let sxy: f64 = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (x - mean_x) * (y - mean_y))
        .sum();
    let syy: f64 = ys.iter().map(|y| (y - mean_y).powi(2)).sum();
    if sxx <= 0.0 || !sxx.is_finite() {
        return Err("the usable points are all at one temperature".into());
    }
    let slope = sxy / sxx;
    let intercept = mean_y - slope * mean_x;
    if slope <= 0.0 || !slope.is_finite() {
        return Err(format!(
            "the times to criterion do not shorten with temperature (Ea = {} J/mol ≤ 0): \
             no Arrhenius extrapolation",
            show(slope * GAS_CONSTANT)
        ));
    }
    let ss_res: f64 = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (y - intercept - slope * x).powi(2))
        .sum();
    let r_squared = if syy > 0.0 { 1.0 - ss_res / syy } else { 1.0 };
    let dof = nf - 2.0;
    let residual_sd = (ss_res / dof).sqrt();
    let t_quantile = StudentsT::new(0.0, 1.0, dof)
        .map_err(|e| format!("Student t distribution: {e}"))?
        .inverse_cdf(0.975);
    let half = t_quantile * residual_sd / sxx.sqrt();
    Ok(ArrheniusFit {
        points: points.to_vec(),
        intercept,
        slope,
        activation_energy: GAS_CONSTANT * slope,
        activation_energy_interval: (GAS_CONSTANT * (slope - half), GAS_CONSTANT * (slope + half)),
        r_squared,
        residual_sd,
        t_quantile,
        mean_x,
        sxx,
    })
}

/// The `[material.ageing]` constants of a fit: k_ref = [`AgeingKind::rate`] of the fitted
/// life at `reference_temperature` \[K\], Ea, crosslinking = 1 (balanced, §6.5), with the
/// property and criterion strings.
pub fn ageing_constants(
    fit: &ArrheniusFit,
    kind: AgeingKind,
    criterion: f64,
    reference_temperature: f64,
) -> (Ageing, AgeingBasis) {
    let life = fit.time_at(reference_temperature);
    let ageing = Ageing {
        activation_energy: fit.activation_energy,
        activation_energy_above: fit.activation_energy,
        rate: kind.rate(criterion, life),
        reference_temperature,
        crosslinking: BALANCED_CROSSLINKING,
    };
    let percent = 100.0 * criterion;
    let basis = match kind {
        AgeingKind::CompressionSet => AgeingBasis {
            property: "compression set (Arrhenius fit by sealsim ageing-fit, ISO 11346); \
                       k_ref = -ln(1 - CS*)/t* (CS = 1 - exp(-k t))"
                .into(),
            criterion: format!("{} % compression set", show(percent)),
            medium: None,
            source: None,
        },
        AgeingKind::RetainedForce => AgeingBasis {
            property: "retained sealing force (Arrhenius fit by sealsim ageing-fit, ISO 11346); \
                       k_ref = -ln(F*/F0)/t* (F/F0 = exp(-k t))"
                .into(),
            criterion: format!("{} % force retained", show(percent)),
            medium: None,
            source: None,
        },
    };
    (ageing, basis)
}
