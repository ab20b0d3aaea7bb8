//! Speed of the seal-life simulation: a 30-year O-ring run (the shipped NBR scenario,
//! 20 points per decade, critical-junction fidelity, 16 strips across the Hertz profile),
//! contact table build included. Target ≤ 20 ms; the figure goes in the README.

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
    c.bench_function(
        &format!("30-year O-ring life run (nbr-70, 80 °C, {rows} rows, critical-junction)"),
        |b| b.iter(|| simulate(black_box(&problem))),
    );
    // the same without the failure criteria (no bisection for the failure time)
    problem.failure = Default::default();
    c.bench_function("30-year O-ring life run, no failure criteria", |b| {
        b.iter(|| simulate(black_box(&problem)))
    });
}

criterion_group!(benches, life);
criterion_main!(benches);
