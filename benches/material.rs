//! Speed of the viscoelastic material: E(t) of a 30-term Prony series, one exact recursive
//! update of its 30 branch stresses, and a Prony fit to 100 relaxation points (targets:
//! ≤ 100 ns, ≤ 300 ns, ≤ 10 ms). Figures go in docs/src/performance.md.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

use criterion::{Criterion, criterion_group, criterion_main};
use sealsim::material::fit::{FitSettings, Regularisation, fit_relaxation};
use sealsim::material::{Prony, PronyTerm, RelaxationState};
use sealsim::math::log_spaced;
use std::hint::black_box;

/// 30 terms, τ = 1e-6 … 1e23 s (one per decade), moduli varied, E∞ = 2 MPa.
fn thirty_terms() -> Prony {
    let terms: Vec<PronyTerm> = (-6..24)
        .map(|k| PronyTerm {
            modulus: 1e6 * (3.5 + 2.5 * (1.3 * f64::from(k)).sin()),
            tau: 10f64.powi(k),
        })
        .collect();
    Prony::new(2e6, &terms).expect("valid series")
}

fn material(c: &mut Criterion) {
    let prony = thirty_terms();
    c.bench_function("E(t), 30-term Prony series", |b| {
        b.iter(|| black_box(&prony).relaxation(black_box(1234.5)))
    });

    let mut state = RelaxationState::new(&prony);
    state.step(&prony, 0.0, 0.01);
    c.bench_function("RelaxationState::step, 30 terms", |b| {
        b.iter(|| state.step(black_box(&prony), black_box(10.0), black_box(1e-4)))
    });

    // 100 points over 12 decades of the 13-term example of tests/fit.rs
    let truth = {
        let terms: Vec<PronyTerm> = (-4..=8)
            .map(|k| PronyTerm {
                modulus: 1e6 * (3.5 + 2.5 * (1.3 * f64::from(k)).sin()),
                tau: 10f64.powi(k),
            })
            .collect();
        Prony::new(2e6, &terms).expect("valid series")
    };
    let (lo, hi) = (3e-5, 3e8);
    let times = log_spaced(lo, hi, 100);
    let moduli: Vec<f64> = times.iter().map(|&t| truth.relaxation(t)).collect();
    for (per_decade, regularisation, label) in [
        (3.0, Regularisation::None, "plain NNLS"),
        (1.0, Regularisation::Gcv, "GCV"),
        (3.0, Regularisation::Gcv, "GCV"),
    ] {
        let settings = FitSettings {
            terms_per_decade: per_decade,
            regularisation,
            ..FitSettings::default()
        };
        c.bench_function(
            &format!("Prony fit, 100 relaxation points, {per_decade}/decade, {label}"),
            |b| b.iter(|| fit_relaxation(black_box(&times), black_box(&moduli), &settings)),
        );
    }
}

criterion_group!(benches, material);
criterion_main!(benches);
