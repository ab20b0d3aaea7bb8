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
        },
        AgeingKind::RetainedForce => AgeingBasis {
            property: "retained sealing force (Arrhenius fit by sealsim ageing-fit, ISO 11346); \
                       k_ref = -ln(F*/F0)/t* (F/F0 = exp(-k t))"
                .into(),
            criterion: format!("{} % force retained", show(percent)),
            medium: None,
        },
    };
    (ageing, basis)
}

#[cfg(test)]
mod tests {
    use super::*;
    // the data file is read at the input boundary; these tests feed the fit from text
    use crate::scenario::ageing_data::parse_ageing_data;
    use std::path::Path;

    fn error(text: &str) -> String {
        parse_ageing_data(text, Path::new("a.csv"))
            .expect_err("the file should be rejected")
            .to_string()
    }

    #[test]
    fn reads_units_and_groups_by_temperature() {
        let s = parse_ageing_data(
            "temperature,time,value\nC,h,%\n100,0,0\n125,10,20\n100,10,10\n",
            Path::new("a.csv"),
        )
        .unwrap();
        assert_eq!(s.len(), 2);
        assert_eq!(s[0].temperature, 373.15);
        assert_eq!(s[0].points[1].time, 36_000.0);
        assert_eq!(s[0].points[1].value, 0.1);
        assert_eq!(s[0].points[1].line, 5);
        assert_eq!(s[1].temperature, 398.15);
    }

    #[test]
    fn errors_name_the_line() {
        let e = error("temperature,time,value\nC,m,1\n100,1,0.1\n");
        assert!(e.starts_with("a.csv:2: time: unit \"m\""), "{e}");
        let e = error("temperature,time,value\nPa,h,1\n100,1,0.1\n");
        assert!(e.starts_with("a.csv:2: temperature: unit"), "{e}");
        let e = error("temperature,time,value\nC,h,kg\n");
        assert!(e.starts_with("a.csv:2: value: unit"), "{e}");
        let e = error("temperature,time,value\nC,h,1\n100,2,0.1\n100,1,0.2\n");
        assert!(e.starts_with("a.csv:4: time: must increase"), "{e}");
        let e = error("temperature,time,value\nC,h,1\n100,x,0.1\n");
        assert!(e.starts_with("a.csv:3: time: not a finite number"), "{e}");
        let e = error("temp,time,value\nC,h,1\n");
        assert!(e.starts_with("a.csv:1: expected the header row"), "{e}");
    }

    fn series(temperature: f64, points: &[(f64, f64)]) -> AgeingSeries {
        AgeingSeries {
            temperature,
            points: points
                .iter()
                .enumerate()
                .map(|(i, &(time, value))| AgeingPoint {
                    line: i + 3,
                    time,
                    value,
                })
                .collect(),
        }
    }

    #[test]
    fn interpolation_is_linear_in_log_time() {
        // 0.5 halfway between 0.4 at 10 h and 0.6 at 1000 h: √(10·1000) = 100 h.
        let s = series(373.15, &[(0.0, 0.0), (10.0, 0.4), (1000.0, 0.6)]);
        let Crossing::Reached(t) = time_to_criterion(&s, AgeingKind::CompressionSet, 0.5) else {
            panic!()
        };
        assert!((t / 100.0 - 1.0).abs() < 1e-12, "{t}");
        assert_eq!(
            time_to_criterion(&s, AgeingKind::CompressionSet, 0.7),
            Crossing::NotReached
        );
        assert_eq!(
            time_to_criterion(&s, AgeingKind::CompressionSet, 0.3),
            Crossing::AtFirstTime
        );
        // retained force 0.8 → 0.4 over 1 → 100 h: 0.6 at 10 h.
        let s = series(373.15, &[(1.0, 0.8), (100.0, 0.4)]);
        let Crossing::Reached(t) = time_to_criterion(&s, AgeingKind::RetainedForce, 0.6) else {
            panic!()
        };
        assert!((t / 10.0 - 1.0).abs() < 1e-12, "{t}");
    }

    #[test]
    fn kind_is_inferred_or_checked() {
        let up = series(373.15, &[(1.0, 0.1), (2.0, 0.2)]);
        let down = series(383.15, &[(1.0, 0.9), (2.0, 0.8)]);
        assert_eq!(
            resolve_kind(std::slice::from_ref(&up), None),
            Ok((AgeingKind::CompressionSet, true))
        );
        assert_eq!(
            resolve_kind(std::slice::from_ref(&down), None),
            Ok((AgeingKind::RetainedForce, true))
        );
        assert!(resolve_kind(&[up.clone(), down.clone()], None).is_err());
        let e = resolve_kind(&[up], Some(AgeingKind::RetainedForce)).unwrap_err();
        assert_eq!(e.0, Some(4));
        assert!(e.1.contains("rises"), "{}", e.1);
    }

    #[test]
    fn exact_line_has_zero_width_interval_and_unit_r_squared() {
        // ln t = −20 + 10000/T at three temperatures: Ea = 10000 R.
        let pts: Vec<(f64, f64)> = [350.0f64, 375.0, 400.0]
            .iter()
            .map(|&t| (t, (-20.0 + 10_000.0 / t).exp()))
            .collect();
        let fit = fit_arrhenius(&pts).unwrap();
        assert!((fit.activation_energy / (10_000.0 * GAS_CONSTANT) - 1.0).abs() < 1e-9);
        assert!((fit.r_squared - 1.0).abs() < 1e-12);
        // t_{0.975, 1} = tan(0.475 π) = 12.7062…
        let expected = (0.475 * std::f64::consts::PI).tan();
        assert!(
            (fit.t_quantile / expected - 1.0).abs() < 1e-6,
            "{}",
            fit.t_quantile
        );
        assert!(fit_arrhenius(&pts[..2]).is_err());
        let falling: Vec<(f64, f64)> = pts.iter().map(|&(t, s)| (t, 1.0 / s)).collect();
        assert!(
            fit_arrhenius(&falling)
                .unwrap_err()
                .contains("do not shorten")
        );
    }

    #[test]
    fn rates_follow_the_two_network_relations() {
        // CS 50 % at 1000 s: k = ln 2 / 1000; F/F0 = e^{-1} at 1000 s: k = 1e-3.
        let k = AgeingKind::CompressionSet.rate(0.5, 1000.0);
        assert!((k - std::f64::consts::LN_2 / 1000.0).abs() < 1e-18);
        let k = AgeingKind::RetainedForce.rate((-1.0f64).exp(), 1000.0);
        assert!((k - 1e-3).abs() < 1e-15);
    }

    /// SplitMix64 (Steele, Lea & Flood 2014): a seeded generator for the noise.
    struct SplitMix(u64);

    impl SplitMix {
        fn uniform(&mut self) -> f64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        }

        /// Standard normal by Box–Muller.
        fn normal(&mut self) -> f64 {
            let (u, v) = (self.uniform(), self.uniform());
            (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
        }
    }

    const EA: f64 = 90e3;
    const T_REF: f64 = 373.15;
    const K_REF: f64 = 1e-6;

    /// k(T) = k_ref exp(−Ea/R (1/T − 1/T_ref)) \[1/s\].
    fn rate(t: f64) -> f64 {
        K_REF * (-EA / GAS_CONSTANT * (1.0 / t - 1.0 / T_REF)).exp()
    }

    /// CS = 1 − exp(−k t) at 100, 115, 130, 145 C, 17 times log-spaced at 4 per decade
    /// around each temperature's t* = ln 2/k, values times (1 + noise ε), ε standard normal.
    fn synthetic(noise: f64, rng: &mut SplitMix) -> Vec<AgeingSeries> {
        [100.0, 115.0, 130.0, 145.0]
            .iter()
            .map(|c| {
                let t = c + 273.15;
                let k = rate(t);
                let t_star = std::f64::consts::LN_2 / k;
                let points = (-8..=8)
                    .map(|j| {
                        let time = t_star * 10f64.powf(f64::from(j) / 4.0);
                        let cs = 1.0 - (-k * time).exp();
                        AgeingPoint {
                            line: 0,
                            time,
                            value: cs * (1.0 + noise * rng.normal()),
                        }
                    })
                    .collect();
                AgeingSeries {
                    temperature: t,
                    points,
                }
            })
            .collect()
    }

    fn fit_of(series: &[AgeingSeries]) -> ArrheniusFit {
        let points: Vec<(f64, f64)> = series
            .iter()
            .filter_map(
                |s| match time_to_criterion(s, AgeingKind::CompressionSet, 0.5) {
                    Crossing::Reached(t) => Some((s.temperature, t)),
                    _ => None,
                },
            )
            .collect();
        assert_eq!(points.len(), 4);
        fit_arrhenius(&points).unwrap()
    }

    #[test]
    fn noise_free_data_give_ea_and_the_hand_calculated_life() {
        let fit = fit_of(&synthetic(0.0, &mut SplitMix(1)));
        assert!(
            (fit.activation_energy / EA - 1.0).abs() < 1e-6,
            "{}",
            fit.activation_energy
        );
        // t = −ln(1 − 0.5)/k(60 C), by hand.
        let ts = 333.15;
        let hand = std::f64::consts::LN_2 / rate(ts);
        assert!(
            (fit.time_at(ts) / hand - 1.0).abs() < 1e-6,
            "{} vs {hand}",
            fit.time_at(ts)
        );
        // the ageing constants give back k at the reference temperature
        let (a, _) = ageing_constants(&fit, AgeingKind::CompressionSet, 0.5, ts);
        assert!((a.rate / rate(ts) - 1.0).abs() < 1e-6);
        assert_eq!(a.crosslinking, 1.0);
    }

    #[test]
    fn ea_interval_covers_the_truth_in_at_least_90_percent_of_noisy_repeats() {
        let mut rng = SplitMix(2026);
        let covered = (0..50)
            .filter(|_| {
                let fit = fit_of(&synthetic(0.01, &mut rng));
                let (lo, hi) = fit.activation_energy_interval;
                lo <= EA && EA <= hi
            })
            .count();
        eprintln!("Ea interval coverage: {covered} of 50");
        assert!(covered >= 45, "{covered} of 50");
    }
}
