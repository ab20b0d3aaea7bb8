//! Time–temperature superposition (crates/sealsim-core/src/material/tts.rs): master curves from relaxation
//! isotherms synthesised from a known Prony series and a known shift law, noise-free and with
//! 1 % multiplicative Gaussian noise (seeded SplitMix64, so every run is identical).
//!
//! Data: 5 temperatures, 25 log-spaced times from 1 s to 1e4 s each. The spectrum is
//! quasi-continuous over 16 decades (τ = 1e-4 … 1e12 s, ten per decade,
//! E_i ∝ τ^−0.3 (1 + 0.3 sin log10 τ), E∞ = 1e5 Pa): E falls from ≈ 5e8 to ≈ 3e5 Pa with a
//! log–log slope of −0.23 … −0.36 over the reduced window, so every isotherm carries time
//! information (on a flat rubbery plateau no method can find a shift).

use sealsim::material::Prony;
use sealsim::material::shift::{GAS_CONSTANT, Shift};
use sealsim::material::tts::{
    FittedLaw, Isotherm, MasterCurve, Parameter, ShiftLaw, TtsError, TtsSettings, master_curve,
};
use sealsim::math::log_spaced;

use crate::rng::SplitMix64;

/// The true master curve at the true law's reference temperature.
fn spectrum() -> Prony {
    crate::fit::wavy_series((1e-4, 1e12, 161), 1e8, -0.45, 4.0, 1e4)
}

const C: f64 = 273.15;

/// WLF with the classic constants C1 = 8.86, C2 = 101.6 K (Williams, Landel & Ferry 1955;
/// recalled), here at Tr = 20 °C.
const WLF: Shift = Shift::Wlf {
    reference: 20.0 + C,
    c1: 8.86,
    c2: 101.6,
};
/// WLF data: −10 … 50 °C in 15 K steps (log10 a_T = 3.71 … −2.02; adjacent isotherms overlap
/// by ≥ 1.8 decades). The median, 20 °C, is the law's reference.
const WLF_TEMPERATURES: [f64; 5] = [-10.0, 5.0, 20.0, 35.0, 50.0];

/// Arrhenius, Ea = 100 kJ/mol at 60 °C.
const EA: f64 = 100e3;
const ARRHENIUS: Shift = Shift::Arrhenius {
    reference: 60.0 + C,
    activation_energy: EA,
};
/// Arrhenius data: 20 … 100 °C (log10 a_T = 2.14 … −1.68).
const ARRHENIUS_TEMPERATURES: [f64; 5] = [20.0, 40.0, 60.0, 80.0, 100.0];

/// log10(1.02): a_T within 2 %.
fn two_percent() -> f64 {
    1.02f64.log10()
}

/// Isotherms E(t, T) = E_ref(t / a_T) at `celsius`, times (1 + noise ε), ε standard normal.
fn synthesise(law: &Shift, celsius: &[f64], noise: f64, rng: &mut SplitMix64) -> Vec<Isotherm> {
    let truth = spectrum();
    celsius
        .iter()
        .map(|c| {
            let temperature = c + C;
            let a = law.factor(temperature);
            let times = log_spaced(1.0, 1e4, 30);
            let moduli = times
                .iter()
                .map(|&t| truth.relaxation(t / a) * (1.0 + noise * rng.normal()))
                .collect();
            Isotherm {
                temperature,
                times,
                moduli,
            }
        })
        .collect()
}

/// Largest |Δ log10 a_T| of the estimated shifts against `law`.
fn shift_error(m: &MasterCurve, law: &Shift) -> f64 {
    let base = law.log10_factor(m.reference);
    m.shifts
        .iter()
        .map(|s| (s.log10_shift - (law.log10_factor(s.temperature) - base)).abs())
        .fold(0.0, f64::max)
}

/// Largest and rms |E_fit/E_true − 1| over 2000 log-spaced reduced times of the window, at the
/// master curve's reference.
fn master_error(m: &MasterCurve, law: &Shift) -> (f64, f64) {
    let truth = spectrum();
    let a = law.factor(m.reference);
    let xs = log_spaced(m.window.0, m.window.1, 2000);
    let e: Vec<f64> = xs
        .iter()
        .map(|&x| (m.fit.prony.relaxation(x) / truth.relaxation(x / a) - 1.0).abs())
        .collect();
    let max = e.iter().copied().fold(0.0, f64::max);
    let rms = (e.iter().map(|v| v * v).sum::<f64>() / e.len() as f64).sqrt();
    (max, rms)
}

fn wlf_parameters(m: &MasterCurve) -> (Parameter, Parameter) {
    match m.law.law {
        FittedLaw::Wlf { c1, c2 } => (c1, c2),
        FittedLaw::Arrhenius { .. } => panic!("expected WLF"),
    }
}

fn activation_energy(m: &MasterCurve) -> Parameter {
    match m.law.law {
        FittedLaw::Arrhenius { activation_energy } => activation_energy,
        FittedLaw::Wlf { .. } => panic!("expected Arrhenius"),
    }
}

fn arrhenius_settings() -> TtsSettings {
    TtsSettings {
        law: ShiftLaw::Arrhenius,
        reference: None,
        ..TtsSettings::default()
    }
}

#[test]
fn wlf_round_trip_noise_free() {
    let data = synthesise(&WLF, &WLF_TEMPERATURES, 0.0, &mut SplitMix64(0));
    let m = master_curve(&data, &TtsSettings::default()).unwrap();
    assert_eq!(m.reference, 20.0 + C);
    assert_eq!(m.data_reference, 20.0 + C);
    assert_eq!(m.temperature_range, (-10.0 + C, 50.0 + C));
    let err = shift_error(&m, &WLF);
    let (c1, c2) = wlf_parameters(&m);
    let (max, rms) = master_error(&m, &WLF);
    eprintln!(
        "WLF noise-free: {} iterations (converged {}), max |Δlog a| = {err:.2e}, \
         C1 = {:.4} [{:?}], C2 = {:.3} [{:?}], Birge {:.3}; master curve over {:.2e}–{:.2e} s: \
         max {max:.2e}, rms {rms:.2e}; fit rms residual {:.2e}",
        m.iterations,
        m.converged,
        c1.value,
        c1.interval,
        c2.value,
        c2.interval,
        m.law.birge_ratio,
        m.window.0,
        m.window.1,
        m.fit.rms_relative_residual
    );
    assert!(m.converged);
    assert!(err <= two_percent(), "{err}");
    assert!(c1.covers(8.86), "{c1:?}");
    assert!(c2.covers(101.6), "{c2:?}");
    assert_eq!(m.law.degrees_of_freedom, 2);
    assert!(max < 1e-3, "{max}");
    // the shift ready for a material file is the fitted law
    assert_eq!(
        m.shift,
        Shift::Wlf {
            reference: 20.0 + C,
            c1: c1.value,
            c2: c2.value
        }
    );
    // the reduced data: every point, sorted, inside the window
    assert_eq!(m.reduced.len(), 150);
    assert!(
        m.reduced
            .windows(2)
            .all(|w| w[0].reduced_time <= w[1].reduced_time)
    );
    assert_eq!(m.reduced[0].reduced_time, m.window.0);
    assert_eq!(m.reduced[149].reduced_time, m.window.1);
    // the coldest isotherm relaxes slowest: the shortest reduced times
    assert_eq!(m.shifts[m.reduced[0].isotherm].temperature, -10.0 + C);
    assert_eq!(m.shifts[m.reduced[149].isotherm].temperature, 50.0 + C);
}

/// What `seeds` noisy repeats gave.
struct Repeats {
    /// Largest |Δ log10 a_T| over all runs and temperatures.
    worst_shift: f64,
    /// Shift estimates (non-reference) and how many lie within 1.96 standard errors of the truth.
    estimates: usize,
    within_two_se: usize,
    /// Per parameter: runs whose interval covers the truth.
    covered: Vec<usize>,
    /// Per parameter: mean interval half-width relative to the value.
    half_width: Vec<f64>,
    /// Largest and mean rms master-curve error (module docs of the test).
    worst_master: f64,
    mean_master_rms: f64,
    most_iterations: usize,
}

/// Runs `seeds` noisy repeats (1 % noise); `parameters` gives each fitted parameter with its
/// true value.
fn noisy_repeats(
    law: &Shift,
    celsius: &[f64],
    settings: &TtsSettings,
    seeds: u64,
    parameters: impl Fn(&MasterCurve) -> Vec<(Parameter, f64)>,
) -> Repeats {
    let mut r = Repeats {
        worst_shift: 0.0,
        estimates: 0,
        within_two_se: 0,
        covered: Vec::new(),
        half_width: Vec::new(),
        worst_master: 0.0,
        mean_master_rms: 0.0,
        most_iterations: 0,
    };
    for seed in 0..seeds {
        let data = synthesise(law, celsius, 0.01, &mut SplitMix64(1000 + seed));
        let m = master_curve(&data, settings).unwrap();
        assert!(m.converged, "seed {seed}");
        r.most_iterations = r.most_iterations.max(m.iterations);
        r.worst_shift = r.worst_shift.max(shift_error(&m, law));
        let base = law.log10_factor(m.reference);
        for s in m
            .shifts
            .iter()
            .filter(|s| s.temperature != m.data_reference)
        {
            let d = s.log10_shift - (law.log10_factor(s.temperature) - base);
            r.estimates += 1;
            r.within_two_se += usize::from(d.abs() <= 1.96 * s.std_error);
        }
        let (max, rms) = master_error(&m, law);
        r.worst_master = r.worst_master.max(max);
        r.mean_master_rms += rms / seeds as f64;
        let p = parameters(&m);
        r.covered.resize(p.len(), 0);
        r.half_width.resize(p.len(), 0.0);
        for (k, (param, truth)) in p.iter().enumerate() {
            r.covered[k] += usize::from(param.covers(*truth));
            if let Some((lo, hi)) = param.interval {
                r.half_width[k] += 0.5 * (hi - lo) / param.value / seeds as f64;
            }
        }
    }
    r
}

#[test]
fn wlf_round_trip_with_one_percent_noise() {
    let seeds = 20;
    let r = noisy_repeats(
        &WLF,
        &WLF_TEMPERATURES,
        &TtsSettings::default(),
        seeds,
        |m| {
            let (c1, c2) = wlf_parameters(m);
            vec![(c1, 8.86), (c2, 101.6)]
        },
    );
    eprintln!(
        "WLF 1 % noise, {seeds} seeds: max |Δlog a| = {:.2e} (2 %: {:.2e}); {} of {} shifts \
         within 1.96 standard errors; C1 interval covers the truth {} times (mean half-width \
         {:.1} %), C2 {} times ({:.1} %); master curve max error {:.2e}, mean rms {:.2e}; at \
         most {} iterations",
        r.worst_shift,
        two_percent(),
        r.within_two_se,
        r.estimates,
        r.covered[0],
        100.0 * r.half_width[0],
        r.covered[1],
        100.0 * r.half_width[1],
        r.worst_master,
        r.mean_master_rms,
        r.most_iterations
    );
    check_repeats(&r, seeds);
}

/// The noisy-repeat claims: every a_T within 2 %; the shifts' standard errors honest (at least
/// 85 % of the estimates within 1.96 of them, 95 % expected); each interval covering the truth
/// in at least 17 of 20 runs (95 % nominal); the master curve within 4 % everywhere in the window
/// (the window's ends are backed by one isotherm's points only) and 0.8 % rms.
fn check_repeats(r: &Repeats, seeds: u64) {
    assert!(r.worst_shift <= two_percent(), "{}", r.worst_shift);
    assert!(
        r.within_two_se as f64 >= 0.85 * r.estimates as f64,
        "{} of {}",
        r.within_two_se,
        r.estimates
    );
    for &c in &r.covered {
        assert!(c as f64 >= 0.85 * seeds as f64, "{:?}", r.covered);
    }
    assert!(r.worst_master < 0.04, "{}", r.worst_master);
    assert!(r.mean_master_rms < 0.008, "{}", r.mean_master_rms);
    assert!(r.most_iterations <= 20);
}

#[test]
fn arrhenius_round_trip_noise_free() {
    let data = synthesise(&ARRHENIUS, &ARRHENIUS_TEMPERATURES, 0.0, &mut SplitMix64(0));
    let m = master_curve(&data, &arrhenius_settings()).unwrap();
    assert_eq!(m.reference, 60.0 + C);
    let err = shift_error(&m, &ARRHENIUS);
    let ea = activation_energy(&m);
    let (max, rms) = master_error(&m, &ARRHENIUS);
    eprintln!(
        "Arrhenius noise-free: {} iterations, max |Δlog a| = {err:.2e}, Ea = {:.1} J/mol \
         [{:?}], Birge {:.3}; master curve max {max:.2e}, rms {rms:.2e}",
        m.iterations, ea.value, ea.interval, m.law.birge_ratio
    );
    assert!(m.converged);
    assert!(err <= two_percent(), "{err}");
    assert!(ea.covers(EA), "{ea:?}");
    assert_eq!(m.law.degrees_of_freedom, 3);
    assert!(max < 1e-3, "{max}");
    assert_eq!(
        m.shift,
        Shift::Arrhenius {
            reference: 60.0 + C,
            activation_energy: ea.value
        }
    );
}

#[test]
fn arrhenius_round_trip_with_one_percent_noise() {
    let seeds = 20;
    let r = noisy_repeats(
        &ARRHENIUS,
        &ARRHENIUS_TEMPERATURES,
        &arrhenius_settings(),
        seeds,
        |m| vec![(activation_energy(m), EA)],
    );
    eprintln!(
        "Arrhenius 1 % noise, {seeds} seeds: max |Δlog a| = {:.2e}; {} of {} shifts within \
         1.96 standard errors; Ea interval covers the truth {} times (mean half-width {:.2} %); \
         master curve max error {:.2e}, mean rms {:.2e}; at most {} iterations",
        r.worst_shift,
        r.within_two_se,
        r.estimates,
        r.covered[0],
        100.0 * r.half_width[0],
        r.worst_master,
        r.mean_master_rms,
        r.most_iterations
    );
    check_repeats(&r, seeds);
}

#[test]
fn a_user_reference_gives_the_same_shift_function_and_master_curve() {
    let data = synthesise(&WLF, &WLF_TEMPERATURES, 0.01, &mut SplitMix64(7));
    let at_data = master_curve(&data, &TtsSettings::default()).unwrap();
    let t0 = 30.0 + C; // not a data temperature
    let at_user = master_curve(
        &data,
        &TtsSettings {
            law: ShiftLaw::Wlf,
            reference: Some(t0),
            ..TtsSettings::default()
        },
    )
    .unwrap();
    assert_eq!(at_user.reference, t0);
    assert_eq!(at_user.data_reference, 20.0 + C);
    let base = at_data.shift.log10_factor(t0);
    for k in 0..=100 {
        let t = 250.0 + k as f64;
        let (a, b) = (
            at_user.shift.log10_factor(t),
            at_data.shift.log10_factor(t) - base,
        );
        assert!((a - b).abs() < 1e-9, "{t} K: {a} vs {b}");
    }
    // C2' = C2 + T0 − Td, C1' = C1 C2 / C2'
    let ((c1, c2), (c1n, c2n)) = (wlf_parameters(&at_data), wlf_parameters(&at_user));
    assert!((c2n.value - (c2.value + 10.0)).abs() < 1e-9);
    assert!((c1n.value - c1.value * c2.value / c2n.value).abs() < 1e-9);
    // the C2 interval moves with C2; the converted truth is covered
    assert!((c2n.std_error - c2.std_error).abs() < 1e-9);
    let (t1, t2) = (8.86 * 101.6 / 111.6, 111.6);
    assert!(c1n.covers(t1) && c2n.covers(t2), "{c1n:?} {c2n:?}");
    // measured shifts relative to T0, and the Prony master curve: E_T0(ξ a(T0)) = E_Td(ξ)
    for (s, u) in at_data.shifts.iter().zip(&at_user.shifts) {
        assert!((u.log10_shift - (s.log10_shift - base)).abs() < 1e-12);
        assert_eq!(u.std_error, s.std_error);
    }
    let a0 = 10f64.powf(base);
    for xi in log_spaced(at_data.window.0, at_data.window.1, 50) {
        let (e_d, e_u) = (
            at_data.fit.prony.relaxation(xi),
            at_user.fit.prony.relaxation(xi * a0),
        );
        assert!((e_u / e_d - 1.0).abs() < 1e-12, "{xi}: {e_u} vs {e_d}");
    }
    assert!((at_user.window.0 / (at_data.window.0 * a0) - 1.0).abs() < 1e-12);
    // and the Arrhenius fit: Ea does not depend on the reference
    let data = synthesise(
        &ARRHENIUS,
        &ARRHENIUS_TEMPERATURES,
        0.01,
        &mut SplitMix64(8),
    );
    let a = master_curve(&data, &arrhenius_settings()).unwrap();
    let b = master_curve(
        &data,
        &TtsSettings {
            law: ShiftLaw::Arrhenius,
            reference: Some(50.0 + C),
            ..TtsSettings::default()
        },
    )
    .unwrap();
    assert_eq!(activation_energy(&a), activation_energy(&b));
    let base = a.shift.log10_factor(50.0 + C);
    for k in 0..=100 {
        let t = 280.0 + k as f64;
        let d = b.shift.log10_factor(t) - (a.shift.log10_factor(t) - base);
        assert!(d.abs() < 1e-9, "{t} K: {d}");
    }
}

#[test]
fn one_temperature_is_an_error() {
    let mut data = synthesise(&WLF, &[20.0], 0.0, &mut SplitMix64(0));
    let e = master_curve(&data, &TtsSettings::default()).unwrap_err();
    assert_eq!(
        e,
        TtsError::OneTemperature {
            temperature: 20.0 + C
        }
    );
    // two isotherms at one temperature are merged: still one temperature
    data.push(data[0].clone());
    let e = master_curve(&data, &TtsSettings::default()).unwrap_err();
    assert!(matches!(e, TtsError::OneTemperature { .. }), "{e}");
    assert!(e.to_string().contains("two or more temperatures"), "{e}");
    assert_eq!(
        master_curve(&[], &TtsSettings::default()).unwrap_err(),
        TtsError::NoData
    );
}

#[test]
fn isotherms_that_do_not_overlap_are_an_error() {
    // 1 s … 10 s at −10 °C and 50 °C: the reduced windows lie 5.7 decades apart
    let truth = spectrum();
    let data: Vec<Isotherm> = [-10.0, 50.0]
        .iter()
        .map(|c| {
            let a = WLF.factor(c + C);
            let times = log_spaced(1.0, 10.0, 10);
            Isotherm {
                temperature: c + C,
                moduli: times.iter().map(|&t| truth.relaxation(t / a)).collect(),
                times,
            }
        })
        .collect();
    let e = master_curve(&data, &TtsSettings::default()).unwrap_err();
    assert_eq!(
        e,
        TtsError::NoOverlap {
            lower: -10.0 + C,
            upper: 50.0 + C
        }
    );
    let text = e.to_string();
    assert!(
        text.contains("263.15 K (-10 °C)") && text.contains("323.15 K"),
        "{text}"
    );
}

#[test]
fn input_errors_are_typed() {
    let mut data = synthesise(&WLF, &WLF_TEMPERATURES, 0.0, &mut SplitMix64(0));
    data[1].times.truncate(2);
    data[1].moduli.truncate(2);
    assert_eq!(
        master_curve(&data, &TtsSettings::default()).unwrap_err(),
        TtsError::TooFewPoints {
            temperature: 5.0 + C,
            points: 2,
            needed: 3
        }
    );
    data[1].moduli[1] = -1.0;
    assert!(matches!(
        master_curve(&data, &TtsSettings::default()).unwrap_err(),
        TtsError::NotPositive {
            index: 2,
            what: "modulus",
            ..
        }
    ));
    data[1].moduli.pop();
    assert!(matches!(
        master_curve(&data, &TtsSettings::default()).unwrap_err(),
        TtsError::LengthMismatch { .. }
    ));
}

#[test]
fn wlf_from_three_temperatures_has_no_intervals() {
    let data = synthesise(&WLF, &[5.0, 20.0, 35.0], 0.0, &mut SplitMix64(0));
    let m = master_curve(&data, &TtsSettings::default()).unwrap();
    let (c1, c2) = wlf_parameters(&m);
    assert_eq!(m.law.degrees_of_freedom, 0);
    assert_eq!(
        (c1.interval, c2.interval, m.law.t_quantile),
        (None, None, None)
    );
    assert!(
        m.law
            .note
            .as_deref()
            .is_some_and(|n| n.contains("no intervals"))
    );
    // exact through the two points: the truth to the shifts' accuracy
    assert!((c1.value / 8.86 - 1.0).abs() < 0.01, "{c1:?}");
    assert!((c2.value / 101.6 - 1.0).abs() < 0.01, "{c2:?}");
}

#[test]
fn shifts_that_curve_the_wrong_way_are_not_wlf() {
    // log10 a_T = −0.08 (T − 293.15) − 0.002 (T − 293.15)²: concave, C2 would be negative
    let truth = spectrum();
    let data: Vec<Isotherm> = WLF_TEMPERATURES
        .iter()
        .map(|c| {
            let u: f64 = *c - 20.0;
            let a = 10f64.powf(-0.08 * u - 0.002 * u * u);
            let times = log_spaced(1.0, 1e4, 30);
            Isotherm {
                temperature: c + C,
                moduli: times.iter().map(|&t| truth.relaxation(t / a)).collect(),
                times,
            }
        })
        .collect();
    let e = master_curve(&data, &TtsSettings::default()).unwrap_err();
    assert!(
        matches!(
            e,
            TtsError::LawFit {
                law: ShiftLaw::Wlf,
                ..
            }
        ),
        "{e}"
    );
    assert!(e.to_string().contains("Arrhenius"), "{e}");
    // the shifts themselves were fine; Arrhenius also rejects a law that curves the wrong way
    // only when its slope has the wrong sign, so here it fits
    let m = master_curve(&data, &arrhenius_settings()).unwrap();
    assert!(activation_energy(&m).value > 0.0);
    let _ = GAS_CONSTANT;
}

#[test]
fn repeated_isotherms_at_one_temperature_are_merged() {
    // the same times twice: tied times in the isotherm and in the merged reduced data
    let mut data = synthesise(&WLF, &WLF_TEMPERATURES, 0.0, &mut SplitMix64(0));
    let mut repeat = data[1].clone();
    for e in &mut repeat.moduli {
        *e *= 1.001;
    }
    data.push(repeat);
    let m = master_curve(&data, &TtsSettings::default()).unwrap();
    assert_eq!(m.shifts.len(), 5);
    assert_eq!(m.reduced.len(), 180);
    let err = shift_error(&m, &WLF);
    assert!(err < 1e-3, "{err}");
}
