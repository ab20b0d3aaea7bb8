//! Speed of the seal-life simulation: a 30-year O-ring run (the shipped NBR scenario, a face
//! gland: counterface and groove bottom, 20 points per decade, critical-junction fidelity, the
//! fluid pressure inside the interface by shooting across the Hertz profile, memoised in the
//! reduced peak and pressure difference — docs/model.md §3.6 — with the default `follow`
//! asperity moduli and the two-network ageing with compression set of its `[ageing]`), contact
//! table build included. Target: within 2× of the run before ageing and the consistent asperity
//! moduli (43.8 ms, `relaxed`, no ageing), measured here too; the figures go in docs/src/performance.md. The
//! EPDM outdoor run has ≈ 9×10⁴ states (daily and yearly cycles over 30 years).
//! With particle clogging (docs/model.md §7): the shipped dirty-oil gasket
//! (`gasket-nbr-dirty-oil.toml`, a seal that leaks), clean and dirty, without and with re-routing;
//! target ≤ 3× the clean run.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

use criterion::{Criterion, criterion_group, criterion_main};
use sealsim::leak::Fidelity;
use sealsim::scenario::Scenario;
use sealsim::simulate::simulate;
use std::hint::black_box;
use std::path::Path;

fn life(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml");
    let scenario = Scenario::load(&path).expect("the shipped scenario loads");
    let mut problem = scenario.life;
    // the scenario's own settings, stated here so that the benchmark keeps its meaning
    problem.time.points_per_decade = 20.0;
    problem.time.duration = 30.0 * 365.25 * 86400.0;
    problem.fidelity = Fidelity::Table;
    let rows = simulate(&problem).rows.len();
    assert!(problem.ageing.is_some(), "the headline scenario ages");
    // a stable id (benches/performance.py reads the result by it); the row count goes to stderr
    eprintln!("headline life run: {rows} rows");
    c.bench_function(
        "30-year O-ring life run with ageing and set (headline scenario, critical-junction, follow)",
        |b| b.iter(|| simulate(black_box(&problem))),
    );
    // the run as it was before this issue: no ageing, `relaxed` asperities
    let mut before = problem.clone();
    before.ageing = None;
    before.asperity_modulus = sealsim::simulate::AsperityModulus::Relaxed;
    c.bench_function(
        "30-year O-ring life run without ageing, asperity modulus relaxed",
        |b| b.iter(|| simulate(black_box(&before))),
    );
    let mut unaged = problem.clone();
    unaged.ageing = None;
    c.bench_function("30-year O-ring life run without ageing (follow)", |b| {
        b.iter(|| simulate(black_box(&unaged)))
    });
    // clogging: the shipped dirty-oil gasket (a seal that leaks), clean and dirty
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/gasket-nbr-dirty-oil.toml");
    let gasket = Scenario::load(&path)
        .expect("the shipped clogging scenario loads")
        .life;
    assert!(
        gasket.contamination.is_some(),
        "the clogging scenario is dirty"
    );
    let rows = simulate(&gasket).rows.len();
    let mut clean = gasket.clone();
    clean.contamination = None;
    eprintln!("gasket life run: {rows} rows");
    c.bench_function("30-year gasket life run in clean oil", |b| {
        b.iter(|| simulate(black_box(&clean)))
    });
    for reroute in [false, true] {
        let mut dirty = gasket.clone();
        if let Some(contamination) = dirty.contamination.as_mut() {
            contamination.reroute = reroute;
        }
        c.bench_function(
            &format!("30-year gasket life run with clogging, reroute = {reroute}"),
            |b| b.iter(|| simulate(black_box(&dirty))),
        );
    }
    // the same without the failure criteria (no bisection for the failure time)
    problem.failure = Default::default();
    c.bench_function("30-year O-ring life run, no failure criteria", |b| {
        b.iter(|| simulate(black_box(&problem)))
    });
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-epdm-outdoor-cycles.toml");
    let epdm = Scenario::load(&path)
        .expect("the shipped scenario loads")
        .life;
    let mut group = c.benchmark_group("cycles");
    group.sample_size(10);
    group.bench_function("30-year EPDM outdoor run, daily and yearly cycles", |b| {
        b.iter(|| simulate(black_box(&epdm)))
    });
    group.finish();
}

criterion_group!(benches, life);
criterion_main!(benches);
