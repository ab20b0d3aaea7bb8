//! Speed of the static engine: exact evaluation per pressure point, contact-table build per
//! surface, and table lookup (targets: ≤ 1 ms, ≤ 5 ms, ≤ 1 µs); the effective-medium level per
//! state (target ≤ 1 ms with its table). Figures go in docs/src/performance.md.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

use criterion::{Criterion, criterion_group, criterion_main};
use sealsim::contact::{
    ContactSettings, ContactTable, EffectiveMediumSettings, EffectiveMediumTable, PerssonContact,
    SeparationDistribution, TableSettings,
};
use sealsim::surface::Spectrum;
use std::hint::black_box;

fn paper_contact() -> PerssonContact {
    // PY08 §3: h_rms = 2 µm, H = 0.8, q0 = 1e4 1/m, q1 = 7.8e9 1/m
    let sp = Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None).expect("valid spectrum");
    PerssonContact::new(sp, ContactSettings::default())
}

fn engine(c: &mut Criterion) {
    let exact = paper_contact();
    let s = 0.2e6 / (10e6 / 0.75); // P0 = 0.2 MPa on E = 10 MPa, ν = 0.5
    c.bench_function("exact critical junction (paper case, P0 = 0.2 MPa)", |b| {
        b.iter(|| exact.critical_junction(black_box(s)))
    });
    c.bench_function("contact table build (paper surface)", |b| {
        b.iter(|| ContactTable::build(black_box(exact.clone()), TableSettings::default()))
    });
    let em = EffectiveMediumSettings::default();
    c.bench_function("effective medium: P(u) (paper case, 0.2 MPa)", |b| {
        b.iter(|| SeparationDistribution::persson(&exact, black_box(s), em))
    });
    let dist = SeparationDistribution::persson(&exact, s, em);
    c.bench_function(
        "effective medium: Bruggeman solve (paper case, 0.2 MPa)",
        |b| b.iter(|| black_box(&dist).bruggeman_cubed_gap(em)),
    );
    let em_table =
        EffectiveMediumTable::build(exact.clone(), TableSettings::effective_medium(), em);
    c.bench_function(
        "effective medium: table lookup (paper case, 0.2 MPa)",
        |b| b.iter(|| em_table.effective_gap(black_box(s))),
    );
    let mut slow = c.benchmark_group("slow");
    slow.sample_size(10);
    slow.bench_function("effective medium: table build (paper surface)", |b| {
        b.iter(|| {
            EffectiveMediumTable::build(
                black_box(exact.clone()),
                TableSettings::effective_medium(),
                em,
            )
        })
    });
    slow.finish();
    let table = ContactTable::build(exact.clone(), TableSettings::default());
    let pressures: Vec<f64> = (0..64)
        .map(|i| s * 10f64.powf(-1.0 + i as f64 / 64.0))
        .collect();
    c.bench_function("contact table lookup (64 pressures, per batch)", |b| {
        b.iter(|| {
            for &p in &pressures {
                black_box(table.critical_junction(black_box(p)));
            }
        })
    });
}

criterion_group!(benches, engine);
criterion_main!(benches);
