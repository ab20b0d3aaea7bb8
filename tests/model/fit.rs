//! Prony fitting: the NNLS solver against its optimality (KKT) conditions, and fits of data
//! sampled from known Prony series, noise-free and with 1 % multiplicative Gaussian noise.
//! All random numbers come from a seeded SplitMix64, so every run is identical.

use nalgebra::{DMatrix, DVector};
use sealsim::material::fit::{
    Fit, FitError, FitSettings, Honour, KK_TOLERANCE, Regularisation, fit_dma, fit_relaxation,
};
use sealsim::material::{Prony, PronyTerm};
use sealsim::math::log_spaced;
use sealsim::math::nnls::{NnlsSolution, nnls};

use crate::rng::SplitMix64;

// ---------------------------------------------------------------------------------------
// NNLS
// ---------------------------------------------------------------------------------------

/// Checks the KKT conditions of `min ‖Ax − b‖, x ≥ 0` at `s`, with the dual recomputed here:
/// `x ≥ 0`; `w = Aᵀ(b − Ax) ≤ tol` where `x_j = 0`; `w ≈ 0` where `x_j > 0`, to the
/// rounding error of a backward-stable solve, `100 ε max(m, n) ‖A‖ (‖A‖ ‖x‖ + ‖b‖)` (this
/// grows with ‖x‖, hence with the conditioning).
fn assert_kkt(a: &DMatrix<f64>, b: &DVector<f64>, s: &NnlsSolution, label: &str) {
    let w = a.tr_mul(&(b - a * &s.x));
    assert_eq!(w, s.dual, "{label}: reported dual");
    let norm_a = a.norm();
    let (m, n) = a.shape();
    let passive_tol =
        100.0 * f64::EPSILON * m.max(n) as f64 * norm_a * (norm_a * s.x.norm() + b.norm());
    for j in 0..n {
        assert!(s.x[j] >= 0.0, "{label}: x[{j}] = {} < 0", s.x[j]);
        if s.x[j] == 0.0 {
            assert!(
                w[j] <= s.tolerance,
                "{label}: active w[{j}] = {:e} > tol {:e}",
                w[j],
                s.tolerance
            );
        } else {
            assert!(
                w[j].abs() <= passive_tol,
                "{label}: passive w[{j}] = {:e} > {passive_tol:e}",
                w[j]
            );
        }
    }
}

/// A random m×n matrix with singular values log-spaced from 1 to 1/cond (random orthogonal
/// factors from QR of Gaussian matrices).
fn random_matrix(rng: &mut SplitMix64, m: usize, n: usize, cond: f64) -> DMatrix<f64> {
    let g1 = DMatrix::from_fn(m, n, |_, _| rng.normal());
    let g2 = DMatrix::from_fn(n, n, |_, _| rng.normal());
    let u = g1.qr().q();
    let v = g2.qr().q();
    let sigma = log_spaced(1.0, 1.0 / cond, n.max(2));
    let s = DMatrix::from_fn(n, n, |i, j| if i == j { sigma[i] } else { 0.0 });
    u * s * v.transpose()
}

#[test]
fn nnls_satisfies_kkt_on_random_problems() {
    let mut rng = SplitMix64(0x5ea1_5117);
    let mut clamped = 0;
    for case in 0..200 {
        let n = 2 + (rng.next_u64() % 19) as usize;
        let m = n + (rng.next_u64() % 30) as usize;
        let cond = [1.0, 1e3, 1e6, 1e10][case % 4];
        let a = random_matrix(&mut rng, m, n, cond);
        let b = DVector::from_fn(m, |_, _| rng.normal());
        let s = nnls(&a, &b).unwrap_or_else(|e| panic!("case {case}: {e}"));
        assert_kkt(&a, &b, &s, &format!("case {case} ({m}x{n}, cond {cond:e})"));
        clamped += s.x.iter().filter(|&&v| v == 0.0).count();
    }
    assert!(
        clamped > 100,
        "the problems should exercise the bounds ({clamped} zeros)"
    );
}

#[test]
fn nnls_on_ill_conditioned_exponential_basis() {
    // The Prony basis itself: e^{−t/τ} at 4 τ per decade, condition number ≈ 1e12.
    let t = log_spaced(1e-3, 1e3, 80);
    let tau = log_spaced(1e-4, 1e4, 33);
    let a = DMatrix::from_fn(t.len(), tau.len(), |i, j| (-t[i] / tau[j]).exp());
    let sigma = a.singular_values();
    let cond = sigma.max() / sigma.min();
    assert!(cond > 1e11, "cond {cond:e}");
    let mut rng = SplitMix64(7);
    for case in 0..20 {
        // relaxation-like (decreasing) data, and rising data that no positive series fits
        let sign = if case % 2 == 0 { -1.0 } else { 1.0 };
        let b = DVector::from_fn(t.len(), |i, _| {
            1.0 + sign * 0.5 * (t[i] / 10.0).ln().tanh() + 0.01 * rng.normal()
        });
        let s = nnls(&a, &b).unwrap();
        assert_kkt(&a, &b, &s, &format!("exponential case {case}"));
    }
}

#[test]
fn nnls_equals_least_squares_when_that_is_positive() {
    let mut rng = SplitMix64(42);
    for case in 0..50 {
        let n = 2 + case % 10;
        let m = n + 5 + case % 7;
        let a = random_matrix(&mut rng, m, n, 1e2);
        let x_true = DVector::from_fn(n, |_, _| 0.5 + rng.uniform());
        let b = &a * &x_true + DVector::from_fn(m, |_, _| 1e-3 * rng.normal());
        let ls = a.clone().svd(true, true).solve(&b, 0.0).unwrap();
        assert!(ls.iter().all(|&v| v > 0.0));
        let s = nnls(&a, &b).unwrap();
        assert!(
            (&s.x - &ls).amax() <= 1e-10 * ls.amax(),
            "case {case}: {} vs {}",
            s.x,
            ls
        );
    }
}

#[test]
fn nnls_clamps_by_hand() {
    // Two columns e1+e2 and e2; b = (1, 0, 0)ᵀ... here b = (2, 1): unconstrained
    // x = (2, −1); the optimum with x ≥ 0 is x = (1.5, 0) (projection of b on column 1).
    let a = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 1.0, 1.0]);
    let b = DVector::from_vec(vec![2.0, 1.0]);
    let s = nnls(&a, &b).unwrap();
    assert!((s.x[0] - 1.5).abs() < 1e-15 && s.x[1] == 0.0, "{}", s.x);
    // w₂ = a₂ᵀ(b − A x) = (0,1)·(0.5, −0.5) = −0.5 < 0: optimal
    assert!((s.dual[1] + 0.5).abs() < 1e-15);
}

// ---------------------------------------------------------------------------------------
// Prony fits
// ---------------------------------------------------------------------------------------

/// The example series of the issue: 13 terms, one per decade, τ = 1e-4 … 1e8 s, moduli
/// varied between 1 and 6 MPa, E∞ = 2 MPa.
fn one_per_decade() -> Prony {
    let terms: Vec<PronyTerm> = (-4..=8)
        .map(|k| PronyTerm {
            modulus: 1e6 * (3.5 + 2.5 * (1.3 * k as f64).sin()),
            tau: 10f64.powi(k),
        })
        .collect();
    Prony::new(2e6, &terms).unwrap()
}

/// A rubber-like quasi-continuous series: `n` log-spaced τ over `[lo, hi]` \[s\], moduli
/// `level · 10^(slope (log10 τ + offset)) · (1 + 0.3 sin log10 τ)` \[Pa\] (a power-law
/// spectrum with a ±30 % wave), E∞ = `long_term` \[Pa\]. Shared by the fit and TTS tests.
pub(crate) fn wavy_series(
    (lo, hi, n): (f64, f64, usize),
    level: f64,
    slope: f64,
    offset: f64,
    long_term: f64,
) -> Prony {
    let terms: Vec<PronyTerm> = log_spaced(lo, hi, n)
        .into_iter()
        .map(|tau| {
            let k = tau.log10();
            PronyTerm {
                modulus: level * 10f64.powf(slope * (k + offset)) * (1.0 + 0.3 * k.sin()),
                tau,
            }
        })
        .collect();
    Prony::new(long_term, &terms).unwrap()
}

/// A rubber-like series with a quasi-continuous spectrum: 10 terms per decade over the same
/// 12 decades, the moduli falling as τ^-0.45 with a ±30 % wave, so that E(t) drops from
/// 1 GPa (glassy) to 2 MPa (rubbery), E∞ = 2 MPa.
fn quasi_continuous() -> Prony {
    wavy_series((1e-4, 1e8, 121), 1e8, -0.45, 4.0, 2e6)
}

/// Largest and root-mean-square `|fitted/true − 1|` over 2000 log-spaced points of [lo, hi]
/// (20× denser than the data).
fn errors(lo: f64, hi: f64, fitted: impl Fn(f64) -> f64, truth: impl Fn(f64) -> f64) -> (f64, f64) {
    let xs = log_spaced(lo, hi, 2000);
    let e: Vec<f64> = xs
        .iter()
        .map(|&x| (fitted(x) / truth(x) - 1.0).abs())
        .collect();
    let max = e.iter().copied().fold(0.0, f64::max);
    let rms = (e.iter().map(|v| v * v).sum::<f64>() / e.len() as f64).sqrt();
    (max, rms)
}

/// `values` with 1 % multiplicative Gaussian noise.
fn with_noise(rng: &mut SplitMix64, values: &[f64]) -> Vec<f64> {
    values
        .iter()
        .map(|&v| v * (1.0 + 0.01 * rng.normal()))
        .collect()
}

// Accuracy with noise is judged by the rms error over the window: an unweighted least-squares
// fit of p moduli to N points passes on a fraction √(p/N) of the noise (0.39 % rms for the 15
// unknowns and 100 points here), and its worst point, at the window's ends, is about three
// times that. The worst case is asserted only loosely (measured values in the messages).

#[test]
fn relaxation_round_trip_of_the_issue_example() {
    let truth = one_per_decade();
    // 100 points over the series' 12 decades
    let (lo, hi) = (1e-4, 1e8);
    let t = log_spaced(lo, hi, 100);
    let clean: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let fit = fit_relaxation(&t, &clean, &FitSettings::default()).unwrap();
    let (max, _) = errors(lo, hi, |x| fit.prony.relaxation(x), |x| truth.relaxation(x));
    eprintln!("relaxation, issue example, noise-free: worst {max:.1e}");
    assert!(max <= 1e-3, "noise-free: worst {max:e}");
    assert_eq!(fit.points, 100);
    assert!(fit.max_relative_residual <= 1e-3);

    let noisy = with_noise(&mut SplitMix64(2024), &clean);
    let fit = fit_relaxation(&t, &noisy, &FitSettings::default()).unwrap();
    let (max, rms) = errors(lo, hi, |x| fit.prony.relaxation(x), |x| truth.relaxation(x));
    eprintln!("relaxation, issue example, 1 % noise: rms {rms:.1e}, worst {max:.1e}");
    assert!(
        rms <= 5e-3 && max <= 2e-2,
        "1 % noise: rms {rms:e}, worst {max:e}"
    );
    // the residual is the noise: about 1 % rms
    let r = fit.rms_relative_residual;
    assert!(r > 0.007 && r < 0.012, "rms residual {r}");
}

#[test]
fn dma_round_trip_of_the_issue_example() {
    let truth = one_per_decade();
    let (lo, hi) = (1e-7, 1e3); // rad/s: ωτ = 1 inside the window for every term
    let w = log_spaced(lo, hi, 100);
    let storage: Vec<f64> = w.iter().map(|&x| truth.storage(x)).collect();
    let loss: Vec<f64> = w.iter().map(|&x| truth.loss(x)).collect();
    let fit = fit_dma(&w, &storage, &loss, &FitSettings::default()).unwrap();
    let (s_max, _) = errors(lo, hi, |x| fit.prony.storage(x), |x| truth.storage(x));
    let (l_max, _) = errors(lo, hi, |x| fit.prony.loss(x), |x| truth.loss(x));
    eprintln!("dma, issue example, noise-free: E' {s_max:.1e}, E'' {l_max:.1e}");
    assert!(
        s_max <= 1e-3 && l_max <= 1e-3,
        "noise-free: E' {s_max:e}, E'' {l_max:e}"
    );

    let mut rng = SplitMix64(99);
    let (noisy_s, noisy_l) = (with_noise(&mut rng, &storage), with_noise(&mut rng, &loss));
    let fit = fit_dma(&w, &noisy_s, &noisy_l, &FitSettings::default()).unwrap();
    let (s_max, s_rms) = errors(lo, hi, |x| fit.prony.storage(x), |x| truth.storage(x));
    let (l_max, l_rms) = errors(lo, hi, |x| fit.prony.loss(x), |x| truth.loss(x));
    eprintln!(
        "dma, issue example, 1 % noise: E' rms {s_rms:.1e} worst {s_max:.1e}; E'' rms {l_rms:.1e} worst {l_max:.1e}"
    );
    assert!(
        s_rms <= 5e-3 && l_rms <= 5e-3 && s_max <= 2e-2 && l_max <= 3e-2,
        "1 % noise: E' rms {s_rms:e} worst {s_max:e}; E'' rms {l_rms:e} worst {l_max:e}"
    );
}

#[test]
fn off_grid_spectrum_needs_three_terms_per_decade() {
    // A window whose fit grid falls between the decades, on a quasi-continuous spectrum;
    // 300 points for the 44 unknowns of three terms per decade.
    let truth = quasi_continuous();
    let (lo, hi) = (3e-5, 3e8);
    let t = log_spaced(lo, hi, 300);
    let clean: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let fit_with = |e: &[f64], n| {
        fit_relaxation(
            &t,
            e,
            &FitSettings {
                terms_per_decade: n,
                ..FitSettings::default()
            },
        )
        .unwrap()
    };
    let error_with = |e: &[f64], n| {
        let fit = fit_with(e, n);
        errors(lo, hi, |x| fit.prony.relaxation(x), |x| truth.relaxation(x))
    };
    // one per decade leaves a ripple of a few per cent (measured 4.4 %); three remove it
    let (one, _) = error_with(&clean, 1.0);
    assert!(one > 1e-2 && one < 6e-2, "1/decade: worst {one:e}");
    let (three, _) = error_with(&clean, 3.0);
    eprintln!(
        "relaxation, off grid, noise-free: worst {one:.1e} (1/decade), {three:.1e} (3/decade)"
    );
    assert!(three <= 1e-3, "3/decade: worst {three:e}");
    let (max, rms) = error_with(&with_noise(&mut SplitMix64(11), &clean), 3.0);
    eprintln!("relaxation, off grid, 3/decade, 1 % noise: rms {rms:.1e}, worst {max:.1e}");
    assert!(
        rms <= 5e-3 && max <= 2e-2,
        "3/decade, 1 % noise: rms {rms:e}, worst {max:e}"
    );

    let (lo, hi) = (3e-8, 3e3);
    let w = log_spaced(lo, hi, 300);
    let storage: Vec<f64> = w.iter().map(|&x| truth.storage(x)).collect();
    let loss: Vec<f64> = w.iter().map(|&x| truth.loss(x)).collect();
    let settings = FitSettings {
        terms_per_decade: 3.0,
        ..FitSettings::default()
    };
    let fit = fit_dma(&w, &storage, &loss, &settings).unwrap();
    let (s_max, _) = errors(lo, hi, |x| fit.prony.storage(x), |x| truth.storage(x));
    let (l_max, _) = errors(lo, hi, |x| fit.prony.loss(x), |x| truth.loss(x));
    eprintln!("dma, off grid, 3/decade, noise-free: E' {s_max:.1e}, E'' {l_max:.1e}");
    assert!(
        s_max <= 1e-3 && l_max <= 1e-3,
        "3/decade: E' {s_max:e}, E'' {l_max:e}"
    );
    let mut rng = SplitMix64(12);
    let (noisy_s, noisy_l) = (with_noise(&mut rng, &storage), with_noise(&mut rng, &loss));
    let fit = fit_dma(&w, &noisy_s, &noisy_l, &settings).unwrap();
    let (s_max, s_rms) = errors(lo, hi, |x| fit.prony.storage(x), |x| truth.storage(x));
    let (l_max, l_rms) = errors(lo, hi, |x| fit.prony.loss(x), |x| truth.loss(x));
    eprintln!(
        "dma, off grid, 3/decade, 1 % noise: E' rms {s_rms:.1e} worst {s_max:.1e}; E'' rms {l_rms:.1e} worst {l_max:.1e}"
    );
    assert!(
        s_rms <= 5e-3 && l_rms <= 5e-3 && s_max <= 2e-2 && l_max <= 3e-2,
        "3/decade, 1 % noise: E' rms {s_rms:e} worst {s_max:e}; E'' rms {l_rms:e} worst {l_max:e}"
    );
}

#[test]
fn taus_on_the_grid_are_recovered() {
    let truth = one_per_decade();
    // data window 1e-4 … 1e8 s: the fit grid is 1e-5 … 1e9 s, one per decade, and holds
    // every true τ exactly
    let t = log_spaced(1e-4, 1e8, 100);
    let e: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let fit = fit_relaxation(
        &t,
        &e,
        &FitSettings {
            terms_per_decade: 1.0,
            ..FitSettings::default()
        },
    )
    .unwrap();
    assert_eq!(fit.grid_terms, 15);
    let e_inf = fit.prony.long_term();
    assert!(
        (e_inf / truth.long_term() - 1.0).abs() < 1e-6,
        "E∞ = {e_inf}"
    );
    let fitted = fit.prony.terms();
    for term in truth.terms() {
        let found = fitted
            .iter()
            .find(|f| (f.tau / term.tau - 1.0).abs() < 1e-12)
            .unwrap_or_else(|| panic!("no fitted term at τ = {}", term.tau));
        let ratio = found.modulus / term.modulus;
        assert!(
            (ratio - 1.0).abs() < 1e-6,
            "τ = {}: {} vs {}",
            term.tau,
            found.modulus,
            term.modulus
        );
    }
    // the grid's extra terms (1e-5 s, 1e9 s) are empty, or nearly
    let extra: f64 = fitted
        .iter()
        .filter(|f| f.tau < 5e-5 || f.tau > 5e8)
        .map(|f| f.modulus)
        .sum();
    assert!(extra < 1e-6 * truth.instantaneous(), "extra {extra}");

    // DMA data whose grid 1/(10 ω_max) … 10/ω_min also lands on the τ
    let w = log_spaced(1e-7, 1e3, 100);
    let s: Vec<f64> = w.iter().map(|&x| truth.storage(x)).collect();
    let l: Vec<f64> = w.iter().map(|&x| truth.loss(x)).collect();
    let fit = fit_dma(&w, &s, &l, &FitSettings::default()).unwrap();
    assert!((fit.prony.long_term() / truth.long_term() - 1.0).abs() < 1e-6);
    for term in truth.terms() {
        let found = fit
            .prony
            .terms()
            .iter()
            .find(|f| (f.tau / term.tau - 1.0).abs() < 1e-12)
            .unwrap();
        assert!((found.modulus / term.modulus - 1.0).abs() < 1e-6);
    }
}

#[test]
fn more_terms_per_decade_fit_a_power_law() {
    // A smooth power law E = 1 MPa (1 + (t/1 s)^-0.3) over 8 decades: denser grids fit better.
    let t = log_spaced(1e-3, 1e5, 120);
    let e: Vec<f64> = t.iter().map(|&x| 1e6 * (1.0 + x.powf(-0.3))).collect();
    let mut previous = f64::INFINITY;
    for per_decade in [1.0, 2.0, 3.0, 4.0] {
        let fit = fit_relaxation(
            &t,
            &e,
            &FitSettings {
                terms_per_decade: per_decade,
                ..FitSettings::default()
            },
        )
        .unwrap();
        let max = fit.max_relative_residual;
        assert!(max < 0.02, "{per_decade}/decade: {max:e}");
        assert!(
            max <= previous,
            "{per_decade}/decade: {max:e} after {previous:e}"
        );
        previous = fit.max_relative_residual;
    }
}

#[test]
fn too_few_points_names_both_numbers() {
    // plain NNLS only: the regularised fit takes fewer points than unknowns
    let t = log_spaced(1.0, 1e6, 5);
    let e: Vec<f64> = t.iter().map(|&x| 1e6 * (1.0 + (-x).exp())).collect();
    let err = fit_relaxation(
        &t,
        &e,
        &FitSettings {
            terms_per_decade: 1.0,
            regularisation: Regularisation::None,
            ..FitSettings::default()
        },
    )
    .unwrap_err();
    assert!(
        matches!(
            err,
            FitError::TooFewPoints {
                points: 5,
                unknowns: 10,
                ..
            }
        ),
        "{err:?}"
    );
    let text = err.to_string();
    assert!(text.contains('5') && text.contains("10 unknowns"), "{text}");
}

// ---------------------------------------------------------------------------------------
// Material TOML round trip
// ---------------------------------------------------------------------------------------

#[test]
fn material_toml_round_trips_through_the_parser() {
    use sealsim::material::{Ageing, Material, Shift, Status};
    use sealsim::report::material_toml::material_toml;
    use sealsim::scenario::material_from_str;
    use std::path::Path;

    // awkward values: shortest round-trip forms of non-decimal numbers
    let terms = [
        PronyTerm {
            modulus: 1.0 / 3.0 * 1e6,
            tau: 0.1 + 0.2,
        },
        PronyTerm {
            modulus: 6.02e6,
            tau: 3.6e6,
        },
    ];
    let full = Material {
        name: "NBR \"70\" Shore A".into(),
        status: Status::Published,
        prony: Prony::new(4e6 + 0.1, &terms).unwrap(),
        poisson_ratio: 0.4995,
        shift: Shift::Wlf {
            reference: 296.15,
            c1: 8.86,
            c2: 101.6,
        },
        glass_transition: Some(243.15),
        thermal_expansion: Some(2.3e-4),
        glassy_thermal_expansion: Some(7.7e-5),
        ageing: Some(Ageing {
            activation_energy: 9e4,
            activation_energy_above: 9e4,
            rate: 1e-9,
            reference_temperature: 373.15,
            crosslinking: 1.0,
        }),
        ageing_basis: Some(sealsim::material::AgeingBasis {
            property: "compression stress relaxation".into(),
            criterion: "50 % force retained".into(),
            medium: None,
            source: None,
        }),
        data_reduced_time: Some((1e-3, 3.6e6)),
        data_temperature: Some((253.15, 373.15)),
        provenance: [
            "poisson_ratio",
            "long_term_modulus",
            "prony",
            "shift",
            "glass_transition",
            "thermal_expansion",
            "glassy_thermal_expansion",
            "ageing",
        ]
        .iter()
        .map(|k| (k.to_string(), format!("source of {k}, p. 1")))
        .collect(),
        compatibility: Vec::new(),
        library_id: None,
        class: None,
        permeation: Vec::new(),
        bands: Vec::new(),
    };
    let text = material_toml(&full);
    let parsed =
        material_from_str(&text, Path::new("full.toml")).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(parsed, full, "{text}");

    // Arrhenius shift; a user material (no status), no provenance
    let user = Material {
        status: Status::User,
        shift: Shift::Arrhenius {
            reference: 296.15,
            activation_energy: 123_456.7,
        },
        ageing: None,
        ageing_basis: None,
        glass_transition: None,
        provenance: Vec::new(),
        library_id: None,
        class: None,
        permeation: Vec::new(),
        bands: Vec::new(),
        ..full.clone()
    };
    let parsed = material_from_str(&material_toml(&user), Path::new("user.toml")).unwrap();
    assert_eq!(parsed, user);

    // an elastic material
    let elastic = Material::elastic("elastic", 1e7, 0.5).unwrap();
    let parsed = material_from_str(&material_toml(&elastic), Path::new("e.toml")).unwrap();
    assert_eq!(parsed, elastic);
}

/// With denser data the noise averages out: 2000 points over the same 12 decades bring the
/// *worst* error of E(t) under 0.5 % (the issue's bound), for the default 3 terms per decade.
#[test]
fn dense_noisy_data_meet_the_worst_case_bound() {
    let truth = one_per_decade();
    let (lo, hi) = (1e-4, 1e8);
    let t = log_spaced(lo, hi, 2000);
    let clean: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let noisy = with_noise(&mut SplitMix64(7), &clean);
    let fit = fit_relaxation(&t, &noisy, &FitSettings::default()).unwrap();
    let (max, rms) = errors(lo, hi, |x| fit.prony.relaxation(x), |x| truth.relaxation(x));
    eprintln!("relaxation, 2000 points, 1 % noise: rms {rms:.1e}, worst {max:.1e}");
    assert!(max <= 5e-3, "worst {max:e}, rms {rms:e}");
}

/// The DMA counterpart: 2000 frequencies with 1 % noise on E′ and E″. E′ stays under 0.5 %
/// everywhere; E″, small and weakly constrained at the window's ends, reaches ≈0.8 % there
/// while its rms error is far below 0.5 % (measured values in the message).
#[test]
fn dense_noisy_dma_meets_the_worst_case_bound() {
    let truth = one_per_decade();
    let (lo, hi) = (1e-7, 1e3);
    let w = log_spaced(lo, hi, 2000);
    let storage: Vec<f64> = w.iter().map(|&x| truth.storage(x)).collect();
    let loss: Vec<f64> = w.iter().map(|&x| truth.loss(x)).collect();
    let mut rng = SplitMix64(11);
    let (s, l) = (with_noise(&mut rng, &storage), with_noise(&mut rng, &loss));
    let fit = fit_dma(&w, &s, &l, &FitSettings::default()).unwrap();
    let (s_max, s_rms) = errors(lo, hi, |x| fit.prony.storage(x), |x| truth.storage(x));
    let (l_max, l_rms) = errors(lo, hi, |x| fit.prony.loss(x), |x| truth.loss(x));
    eprintln!(
        "dma, 2000 points, 1 % noise: E' rms {s_rms:.1e} worst {s_max:.1e}; E'' rms {l_rms:.1e} worst {l_max:.1e}"
    );
    assert!(
        s_max <= 5e-3 && l_max <= 1e-2,
        "worst E' {s_max:e}, E'' {l_max:e}"
    );
    assert!(
        s_rms <= 2.5e-3 && l_rms <= 2.5e-3,
        "rms E' {s_rms:e}, E'' {l_rms:e}"
    );
}

// ---------------------------------------------------------------------------------------
// Regularised fits (GCV) and the uncertainty band
// ---------------------------------------------------------------------------------------

/// A rubber-like quasi-continuous series for a 14-decade window (1e-5 … 1e9 s): 10 terms per
/// decade, τ = 1e-7 … 1e11 s (the spectrum runs on beyond the window, as a real one does),
/// moduli falling as τ^-0.4 with a ±30 % wave; over the window E(t) falls from ≈0.6 GPa to
/// ≈3 MPa, E∞ = 3 MPa.
fn rubber_14_decades() -> Prony {
    wavy_series((1e-7, 1e11, 181), 1.5e7, -0.4, 5.0, 3e6)
}

/// [`one_per_decade`] extended to 14 decades: 15 terms, τ = 1e-5 … 1e9 s.
fn one_per_decade_14() -> Prony {
    let terms: Vec<PronyTerm> = (-5..=9)
        .map(|k| PronyTerm {
            modulus: 1e6 * (3.5 + 2.5 * (1.3 * k as f64).sin()),
            tau: 10f64.powi(k),
        })
        .collect();
    Prony::new(2e6, &terms).unwrap()
}

/// The hidden-style data: 120 log-spaced times over 1e-5 … 1e9 s, clean or with 1 %
/// multiplicative noise from `seed`.
fn hidden_style_data(truth: &Prony, seed: Option<u64>) -> (Vec<f64>, Vec<f64>) {
    let t = log_spaced(1e-5, 1e9, 120);
    let clean: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let e = match seed {
        Some(s) => with_noise(&mut SplitMix64(s), &clean),
        None => clean,
    };
    (t, e)
}

/// Worst error of a fit to the hidden-style data over the window, and whether its band holds
/// the truth at each of the 2000 points (simultaneously).
fn hidden_style(truth: &Prony, seed: Option<u64>, settings: &FitSettings) -> (f64, bool, Fit) {
    let (lo, hi) = (1e-5, 1e9);
    let (t, e) = hidden_style_data(truth, seed);
    let fit = fit_relaxation(&t, &e, settings).unwrap();
    let (max, _) = errors(lo, hi, |x| fit.prony.relaxation(x), |x| truth.relaxation(x));
    let covered = log_spaced(lo, hi, 2000).iter().all(|&x| {
        let (l, u) = fit.band(x);
        let e = truth.relaxation(x);
        l <= e && e <= u
    });
    (max, covered, fit)
}

fn median_and_max(mut v: Vec<f64>) -> (f64, f64) {
    v.sort_by(f64::total_cmp);
    (v[v.len() / 2], v[v.len() - 1])
}

/// The hidden-style case: 14 decades, 120 points, 1 % noise, 50 seeds, for the two truths.
///
/// Measured (default settings, GCV; worst |fitted/true − 1| over the window per seed):
/// * rubber-like spectrum: median 0.85 %, max 1.65 % over the 50 seeds (unregularised NNLS:
///   1.32 % and 2.50 %); edf 9.8–20 (median 11.6);
/// * one term per decade: median 1.21 %, max 2.54 % (unregularised: 1.22 %, 2.53 %): GCV
///   finds little to smooth in a spectrum of isolated lines (λ median 4e-3, edf ≈ 26).
///
/// The 0.5 % worst-case target is NOT met: with 1 % noise on 120 points a fit with `edf`
/// effective parameters has a pointwise error of about 1 % · √(edf/120) rms (0.3 % for
/// edf = 11), larger at the window's ends where the worst point lies; 0.5 % everywhere
/// would need edf ≈ 4, which biases the fit more than it saves (measured with fixed λ).
/// The assertions are the measured figures with a margin.
///
/// The simultaneous 95 % band holds the truth at all 2000 points in 50/50 (rubber) and
/// 49/50 (one per decade) repeats.
#[test]
fn hidden_style_case_rubber_like() {
    hidden_style_case("rubber-like", &rubber_14_decades());
}

/// See [`hidden_style_case_rubber_like`].
#[test]
fn hidden_style_case_one_per_decade() {
    hidden_style_case("one per decade", &one_per_decade_14());
}

fn hidden_style_case(name: &str, truth: &Prony) {
    let settings = FitSettings::default();
    let none = FitSettings {
        regularisation: Regularisation::None,
        ..settings
    };
    let (mut worst, mut worst_none, mut edf) = (Vec::new(), Vec::new(), Vec::new());
    let mut covered = 0;
    for seed in 0..50 {
        let (max, inside, fit) = hidden_style(truth, Some(seed), &settings);
        worst.push(max);
        edf.push(fit.effective_parameters);
        covered += usize::from(inside);
        worst_none.push(hidden_style(truth, Some(seed), &none).0);
    }
    let (median, max) = median_and_max(worst);
    let (median_none, max_none) = median_and_max(worst_none);
    let (edf_median, _) = median_and_max(edf);
    eprintln!(
        "hidden-style, {name}, 1 % noise, 50 seeds: worst error median {median:.2e}, max \
         {max:.2e} (unregularised {median_none:.2e}, {max_none:.2e}); edf median \
         {edf_median:.1}; band covers the truth in {covered}/50"
    );
    assert!(covered >= 45, "{name}: band covers in {covered}/50");
    assert!(
        median <= 1.5e-2 && max <= 3e-2,
        "{name}: worst median {median:e}, max {max:e}"
    );
    assert!(
        median <= median_none * 1.05,
        "{name}: {median:e} vs {median_none:e}"
    );
}

/// Noise-free data: GCV picks a small λ and the fit stays as good as plain NNLS (measured
/// worst 7.4e-6 rubber-like, 1.6e-14 one per decade).
#[test]
fn hidden_style_clean_data_are_not_spoiled() {
    for (name, truth) in [
        ("rubber-like", rubber_14_decades()),
        ("one per decade", one_per_decade_14()),
    ] {
        let (max, _, fit) = hidden_style(&truth, None, &FitSettings::default());
        eprintln!(
            "hidden-style, {name}, noise-free: worst {max:.1e}, lambda {:.1e}, edf {:.1}",
            fit.smoothing, fit.effective_parameters
        );
        assert!(max <= 1e-3, "{name}: worst {max:e}");
    }
}

/// edf lies between 1 and the number of unknowns and falls as λ rises; GCV's λ is smaller
/// on clean data than on noisy data.
#[test]
fn effective_parameters_fall_with_smoothing() {
    let truth = rubber_14_decades();
    let (t, e) = hidden_style_data(&truth, Some(3));
    let mut previous = f64::INFINITY;
    for lambda in [0.0, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0] {
        let fit = fit_relaxation(
            &t,
            &e,
            &FitSettings {
                regularisation: Regularisation::Fixed(lambda),
                ..FitSettings::default()
            },
        )
        .unwrap();
        let edf = fit.effective_parameters;
        let unknowns = (fit.grid_terms + 1) as f64;
        eprintln!("lambda {lambda:.0e}: edf {edf:.2}");
        assert!(edf >= 1.0 && edf <= unknowns, "λ {lambda}: edf {edf}");
        assert!(
            edf <= previous + 1e-9,
            "λ {lambda}: edf {edf} after {previous}"
        );
        assert_eq!(fit.smoothing, lambda);
        previous = edf;
    }
    let (_, _, noisy) = hidden_style(&truth, Some(3), &FitSettings::default());
    let (_, _, clean) = hidden_style(&truth, None, &FitSettings::default());
    assert!(
        clean.smoothing < noisy.smoothing,
        "λ clean {:e}, noisy {:e}",
        clean.smoothing,
        noisy.smoothing
    );
    assert!(noisy.effective_parameters < clean.effective_parameters);
}

/// Why the 0.5 % worst-case target of the issue is not reachable on the one-per-decade truth:
/// least squares on the *true* relaxation times (1 per decade, the grid holds them; no
/// smoothing needed or possible) — the best an estimator can do without knowing more than
/// the data — leaves a median worst error of 1.06 % (max 2.33 %) over the 50 seeds, because
/// 17 free amplitudes on 120 points with 1 % noise give a pointwise error of about
/// 1 % · √(17/120) ≈ 0.4 % rms, and the worst of 2000 correlated points is 2–3 times that.
/// (On the rubber-like truth GCV is at its best: fixing λ at 0.3, 3 or 10 times GCV's choice
/// gave median worst errors of 0.91 %, 1.28 % and 3.3 % against GCV's 0.85 %; 4 τ per decade
/// 0.87 % — measured once, not asserted.)
#[test]
fn the_worst_case_floor_of_one_per_decade_data() {
    let truth = one_per_decade_14();
    let oracle = FitSettings {
        terms_per_decade: 1.0,
        regularisation: Regularisation::None,
        ..FitSettings::default()
    };
    let worst: Vec<f64> = (0..50)
        .map(|seed| hidden_style(&truth, Some(seed), &oracle).0)
        .collect();
    let (median, max) = median_and_max(worst);
    eprintln!(
        "one per decade, least squares on the true τ: worst median {median:.2e}, max {max:.2e}"
    );
    assert!(
        median > 5e-3,
        "the floor is below the target after all: {median:e}"
    );
}

// ---------------------------------------------------------------------------------------
// Fewer points than unknowns: what a lab reports (ISO 3384 readings at 1, 3, 10, … h)
// ---------------------------------------------------------------------------------------

/// A three-term relaxation of an aged-looking seal compound, τ off the fit grid:
/// E∞ = 2.5 MPa, (0.8 MPa, 1000 s), (1.2 MPa, 3e4 s), (1.5 MPa, 1e6 s).
fn three_terms() -> Prony {
    let terms =
        [(0.8e6, 1e3), (1.2e6, 3e4), (1.5e6, 1e6)].map(|(modulus, tau)| PronyTerm { modulus, tau });
    Prony::new(2.5e6, &terms).unwrap()
}

/// The ISO 3384 reading times of a 1000-hour test: 1, 3, 10, 30, 100, 300, 1000 h \[s\].
fn seven_readings() -> Vec<f64> {
    [1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0]
        .iter()
        .map(|h| h * 3600.0)
        .collect()
}

/// 17 readings from 30 s to 1000 h.
fn seventeen_readings() -> Vec<f64> {
    let mut t: Vec<f64> = [30.0, 60.0, 180.0, 600.0, 1800.0].to_vec();
    t.extend(
        [
            1.0, 2.0, 3.0, 6.0, 10.0, 20.0, 30.0, 60.0, 100.0, 200.0, 300.0, 1000.0,
        ]
        .iter()
        .map(|h| h * 3600.0),
    );
    t
}

/// Measured (noise-free data of [`three_terms`], default settings, 16 and 23 grid τ):
/// 7 points: λ 5.4e-3, edf 4.95, rms residual 1.17e-3, worst error 5.0e-3 over the window;
/// 17 points: λ 5.5e-3, edf 6.9, rms 1.6e-3, worst 4.3e-3. The error is the grid's: three
/// isolated τ between grid points (on 7 points λ → 0 gives the same fit: the non-negative
/// least-squares solution is sparse there, 4 terms, edf 5).
#[test]
fn fewer_points_than_unknowns_fit_when_regularised() {
    let truth = three_terms();
    for (label, t, unknowns) in [
        ("7 points", seven_readings(), 17),
        ("17 points", seventeen_readings(), 24),
    ] {
        let e: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
        let fit = fit_relaxation(&t, &e, &FitSettings::default()).unwrap();
        let n = t.len() as f64;
        let (lo, hi) = (t[0], t[t.len() - 1]);
        let (max, _) = errors(lo, hi, |x| fit.prony.relaxation(x), |x| truth.relaxation(x));
        eprintln!(
            "{label}, {} unknowns: lambda {:.2e}, edf {:.2}, rms residual {:.2e}, worst error \
             {max:.2e}",
            fit.grid_terms + 1,
            fit.smoothing,
            fit.effective_parameters,
            fit.rms_relative_residual
        );
        assert_eq!(fit.grid_terms + 1, unknowns, "{label}");
        assert!(fit.points < unknowns);
        // GCV neither interpolates (λ → 0, edf → n) nor flattens the curve
        assert!(fit.smoothing > 0.0, "{label}: {fit:?}");
        assert!(fit.effective_parameters <= n - 1.0 + 1e-6, "{label}");
        assert!(fit.effective_parameters >= 4.0, "{label}: over-smoothed");
        assert!(fit.rms_relative_residual < 3e-3, "{label}: {fit:?}");
        assert!(max < 1e-2, "{label}: worst {max:e}");
        assert!(fit.widest_relative_band().0.is_finite());
        // plain NNLS refuses them
        let plain = FitSettings {
            regularisation: Regularisation::None,
            ..FitSettings::default()
        };
        assert!(matches!(
            fit_relaxation(&t, &e, &plain),
            Err(FitError::TooFewPoints { .. })
        ));
    }
}

/// With noise on 7 points GCV alone can pick an edf of n − 0.5 (measured on 3 of 60 seeds:
/// residuals of 0.02 % on 1 % noise, an interpolation of the noise); the cap edf ≤ n − 1 stops
/// that without costing accuracy. Measured, 60 seeds, worst error over the window (median,
/// max): 0.5 % noise 0.96 %, 3.2 %; 1 % noise 1.9 %, 4.1 %. A tighter cap (edf ≤ n − 2)
/// forces a too-smooth curve: 2.6 %, 3.5 % at 0.5 % noise. Here (40 seeds, 0.5 % noise):
/// median 1.1 %, max 3.0 %.
#[test]
fn noisy_seven_point_fits_keep_a_residual_degree_of_freedom() {
    let truth = three_terms();
    let t = seven_readings();
    let clean: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let mut worst = Vec::new();
    for seed in 0..40 {
        let e: Vec<f64> = with_noise(&mut SplitMix64(seed), &clean)
            .iter()
            .zip(&clean)
            .map(|(noisy, c)| c + 0.5 * (noisy - c))
            .collect();
        let fit = fit_relaxation(&t, &e, &FitSettings::default()).unwrap();
        assert!(
            fit.effective_parameters <= 6.0 + 1e-6,
            "seed {seed}: edf {}",
            fit.effective_parameters
        );
        assert!(fit.smoothing > 0.0);
        let (max, _) = errors(
            t[0],
            t[6],
            |x| fit.prony.relaxation(x),
            |x| truth.relaxation(x),
        );
        worst.push(max);
    }
    let (median, max) = median_and_max(worst);
    eprintln!("7 points, 0.5 % noise, 40 seeds: worst error median {median:.2e}, max {max:.2e}");
    assert!(median < 2e-2 && max < 5e-2, "{median:e}, {max:e}");
}

/// Three points: the penalty's null space (E∞ and a relative spectrum linear in log τ)
/// interpolates them, so every λ leaves n − edf < 1 and GCV has nothing to compare; the fit
/// is the smoothest one (the largest λ of the scan) and has no uncertainty band.
#[test]
fn three_points_give_the_smoothest_fit_and_no_band() {
    let truth = three_terms();
    let t = log_spaced(3600.0, 3.6e6, 3);
    let e: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let fit = fit_relaxation(&t, &e, &FitSettings::default()).unwrap();
    assert_eq!(fit.smoothing, 1e3, "{fit:?}");
    assert!(fit.max_relative_residual < 1e-9);
    assert_eq!(fit.widest_relative_band().0, f64::INFINITY);
    let (max, _) = errors(
        t[0],
        t[2],
        |x| fit.prony.relaxation(x),
        |x| truth.relaxation(x),
    );
    assert!(max < 0.05, "worst {max:e}");
}

/// Half a term per decade: a series with one τ every two decades on the grid is recovered.
#[test]
fn half_a_term_per_decade() {
    // data 1e-4 … 1e8 s: grid 1e-5 … 1e9 s every two decades holds τ = 1e-3, 1e1, 1e5
    let terms =
        [(4e6, 1e-3), (2e6, 10.0), (1e6, 1e5)].map(|(modulus, tau)| PronyTerm { modulus, tau });
    let truth = Prony::new(2e6, &terms).unwrap();
    let t = log_spaced(1e-4, 1e8, 40);
    let e: Vec<f64> = t.iter().map(|&x| truth.relaxation(x)).collect();
    let fit = fit_relaxation(
        &t,
        &e,
        &FitSettings {
            terms_per_decade: 0.5,
            ..FitSettings::default()
        },
    )
    .unwrap();
    assert_eq!(fit.grid_terms, 8);
    let (max, _) = errors(
        1e-4,
        1e8,
        |x| fit.prony.relaxation(x),
        |x| truth.relaxation(x),
    );
    assert!(max < 1e-6, "worst {max:e}");
}

// ---------------------------------------------------------------------------------------
// DMA data: the Kramers–Kronig check, fits that honour E′, relaxation times off the grid
// (issue 40, item 5)
// ---------------------------------------------------------------------------------------

/// pyvisco's DMA master-curve frequencies: 206 points, f = 1e-12 … 1e14 Hz, as ω \[rad/s\].
fn pyvisco_omegas() -> Vec<f64> {
    log_spaced(1e-12, 1e14, 206)
        .into_iter()
        .map(|f| std::f64::consts::TAU * f)
        .collect()
}

/// A rubber-like broad spectrum over the pyvisco window: 10 terms per decade, τ = 1e-15 …
/// 1e14 s, moduli 4 MPa·τ^-0.15 with a ±30 % wave, E∞ = 80 MPa: E′ from 81.5 MPa (storage
/// plateau at 1e-12 Hz) to ≈ 17.5 GPa.
fn broad_rubber() -> Prony {
    wavy_series((1e-15, 1e14, 291), 4e6, -0.15, 0.0, 80e6)
}

/// E″ of the broad rubber plus a low-frequency tail that E′ does not carry (pyvisco's
/// `freq_user_master.csv` shows the same: a flat storage plateau with an E″ several times
/// what its slope allows): `amplitude/(1 + √(f/1e-10 Hz))` \[Pa\], so not a Prony series.
fn with_loss_tail(truth: &Prony, omegas: &[f64], amplitude: f64) -> (Vec<f64>, Vec<f64>) {
    let f_c = std::f64::consts::TAU * 1e-10;
    let storage = omegas.iter().map(|&w| truth.storage(w)).collect();
    let loss = omegas
        .iter()
        .map(|&w| truth.loss(w) + amplitude / (1.0 + (w / f_c).sqrt()))
        .collect();
    (storage, loss)
}

#[test]
fn kramers_kronig_check_passes_consistent_dma_data() {
    let truth = broad_rubber();
    let w = pyvisco_omegas();
    let (s, l) = with_loss_tail(&truth, &w, 0.0);
    let fit = fit_dma(&w, &s, &l, &FitSettings::default()).unwrap();
    let c = fit.consistency.as_ref().unwrap();
    let worst = c
        .decades
        .iter()
        .map(|d| d.ratio.ln().abs())
        .fold(0.0, f64::max)
        .exp();
    eprintln!("consistent DMA: worst decade ratio {worst:.4}");
    assert_eq!(c.decades.len(), 26);
    assert!(worst < 1.05, "exact data: worst ratio {worst}");
    // E′ alone gives the storage plateau (81.5 MPa at 1e-12 Hz: E∞ = 80 MPa plus the
    // terms beyond the window)
    let e_inf = c.storage_long_term;
    assert!((e_inf / s[0] - 1.0).abs() < 0.01, "E′ alone: E∞ {e_inf:e}");
    // 1 % noise is not an inconsistency
    let mut rng = SplitMix64(40);
    let (ns, nl) = (with_noise(&mut rng, &s), with_noise(&mut rng, &l));
    let fit = fit_dma(&w, &ns, &nl, &FitSettings::default()).unwrap();
    let c = fit.consistency.unwrap();
    assert_eq!(c.inconsistent().count(), 0, "{:?}", c.decades);
}

#[test]
fn kramers_kronig_check_flags_an_e2_tail_and_storage_mode_keeps_the_plateau() {
    let truth = broad_rubber();
    let w = pyvisco_omegas();
    let (s, l) = with_loss_tail(&truth, &w, 3e6);
    let plateau = s[0];
    let both = fit_dma(&w, &s, &l, &FitSettings::default()).unwrap();
    let c = both.consistency.as_ref().unwrap();
    let worst = c.worst().unwrap();
    eprintln!(
        "E'' tail: {} inconsistent decades, worst ratio {:.3} at ω = {:.3e}–{:.3e} rad/s; \
         E∞ both {:.4e}, E′ alone {:.4e}, plateau {plateau:.4e}",
        c.inconsistent().count(),
        worst.ratio,
        worst.omegas.0,
        worst.omegas.1,
        both.prony.long_term(),
        c.storage_long_term
    );
    // the lowest decade is flagged, by more than the tolerance's twice, and only the tail's
    // decades (f < 1e-8 Hz) are
    assert!(c.decades[0].inconsistent() && c.decades[0].ratio > 2.0 * KK_TOLERANCE);
    for d in c.inconsistent() {
        assert!(d.omegas.1 < std::f64::consts::TAU * 1e-8, "{d:?}");
    }
    // fitting both E′ and E″ gives up the plateau (measured 67.6 against 81.5 MPa) ...
    assert!(both.prony.long_term() < 0.9 * plateau, "{both:?}");
    // ... honouring E′ keeps it within 5 %
    let storage = fit_dma(
        &w,
        &s,
        &l,
        &FitSettings {
            honour: Honour::Storage,
            ..FitSettings::default()
        },
    )
    .unwrap();
    let e_inf = storage.prony.long_term();
    eprintln!("E'' tail, --honour storage: E∞ {e_inf:.4e}");
    assert!((e_inf / plateau - 1.0).abs() <= 0.05, "E∞ {e_inf:e}");
    let sc = storage.consistency.unwrap();
    assert!(
        sc.replaced_loss > 0 && sc.replaced_loss < w.len() / 4,
        "{sc:?}"
    );
    // E′ is met everywhere, to the rms of a clean fit
    let storage_rms = (w
        .iter()
        .zip(&s)
        .map(|(&x, &e)| (storage.prony.storage(x) / e - 1.0).powi(2))
        .sum::<f64>()
        / w.len() as f64)
        .sqrt();
    assert!(storage_rms < 5e-3, "E′ rms {storage_rms}");
}

/// Exact line spectra whose τ sit at half-decade offsets, 10^(k+½) s (pyvisco's and
/// ANSYS's series are line spectra off sealsim's grid): without the refinement of τ the
/// 3-per-decade grid left 0.65 % rms (E∞ = 0) on these data; refined, ≤ 0.5 % is required
/// (measured ≈ 6e-5).
#[test]
fn off_grid_line_spectra_fit_to_half_a_per_cent() {
    let lines = |long_term: f64| {
        let terms: Vec<PronyTerm> = (-15..=8)
            .map(|k| PronyTerm {
                modulus: 2e8 * (1.0 + 0.5 * (1.3 * k as f64).sin()),
                tau: 10f64.powf(k as f64 + 0.5),
            })
            .collect();
        Prony::new(long_term, &terms).unwrap()
    };
    for (truth, w) in [
        (lines(0.0), pyvisco_omegas()),
        (lines(5e6), pyvisco_omegas()),
        // rad/s on decades: the grid at 10^(k+1/3), 10^(k+2/3), the τ 1/6 decade off it
        (lines(5e6), log_spaced(1e-7, 1e3, 100)),
    ] {
        let s: Vec<f64> = w.iter().map(|&x| truth.storage(x)).collect();
        let l: Vec<f64> = w.iter().map(|&x| truth.loss(x)).collect();
        let fit = fit_dma(&w, &s, &l, &FitSettings::default()).unwrap();
        let (lo, hi) = (w[0], w[w.len() - 1]);
        let (_, s_rms) = errors(lo, hi, |x| fit.prony.storage(x), |x| truth.storage(x));
        let (_, l_rms) = errors(lo, hi, |x| fit.prony.loss(x), |x| truth.loss(x));
        eprintln!(
            "off-grid lines, E∞ {:e}: residual rms {:.1e} max {:.1e}; E′ rms {s_rms:.1e}, E″ rms {l_rms:.1e}, refined {}",
            truth.long_term(),
            fit.rms_relative_residual,
            fit.max_relative_residual,
            fit.refined
        );
        assert!(fit.rms_relative_residual <= 5e-3, "{fit:?}");
        assert!(s_rms <= 5e-3 && l_rms <= 5e-3, "E′ {s_rms}, E″ {l_rms}");
        assert_eq!(fit.consistency.unwrap().inconsistent().count(), 0);
    }
}
