//! Tests of the ISO 11346 ageing fit (`material::ageing_fit`), fed by the input layer's
//! data-file reader: they live here because the physics crate does not read files.

use crate::material::ageing_fit::*;
// the data file is read at the input boundary; these tests feed the fit from text
use super::ageing_data::parse_ageing_data;
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
