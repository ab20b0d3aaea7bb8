//! Bounded work of long life runs (issue 44, reliability defect D7): the cost of a run must grow
//! about linearly with what it is given — the years of temperature cycles and the rows of a
//! temperature history — not faster.
//!
//! * **130 years of daily and yearly cycles**: the shipped outdoor EPDM scenario
//!   (`scenarios/oring-epdm-outdoor-cycles.toml`) run for 130 years instead of 30, ≈ 380 000
//!   internal steps (eight a day), just under the cycle budget (`MAX_CYCLE_STEPS`, 137 years).
//!   Before the fix: > 600 s (`sealsim run`, killed); target ≤ 10 s.
//! * **A 10⁵-row temperature history**: the cold-night NBR scenario
//!   (`scenarios/cold-night-nbr.toml`) over 30 years on a history generated here,
//!   `T = 20 + 20 sin(0.37 k)` °C at 10⁵ rows k evenly over the 30 years (a swing of up to 7 K
//!   between rows), read through the scenario loader as a user's file is. Before: 136 s; target
//!   ≤ 10 s.
//!
//! One library run each (`simulate`: the run alone; `sealsim run` adds its band at the
//! neighbouring fidelity, a second run). Each iteration is seconds long, so criterion takes 10
//! samples of one iteration each (flat sampling).

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

use criterion::{Criterion, SamplingMode, criterion_group, criterion_main};
use sealsim::scenario::Scenario;
use sealsim::simulate::simulate;
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

/// A Julian year \[s\].
const YEAR: f64 = 365.25 * 86_400.0;
/// Rows of the generated temperature history.
const ROWS: usize = 100_000;

/// The cold-night NBR scenario over 30 years on a generated history of `ROWS` rows, written
/// to `dir` and loaded as a user's scenario is.
fn long_history(dir: &Path) -> Scenario {
    let mut csv = String::from("time,temperature\ns,C\n");
    let span = 30.0 * YEAR;
    for k in 0..ROWS {
        let t = span * k as f64 / (ROWS - 1) as f64;
        let celsius = 20.0 + 20.0 * (0.37 * k as f64).sin();
        writeln!(csv, "{t},{celsius}").unwrap();
    }
    let history = dir.join("long-history.csv");
    std::fs::write(&history, csv).unwrap();
    let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/cold-night-nbr.toml");
    let text = std::fs::read_to_string(shipped).unwrap();
    let text = text
        .replace(
            "history = \"cold-night.csv\"",
            &format!("history = {:?}", history.display().to_string()),
        )
        .replace("duration = \"5 day\"", "duration = \"30 year\"");
    assert!(text.contains("long-history.csv") && text.contains("\"30 year\""));
    let path = dir.join("long-history.toml");
    std::fs::write(&path, text).unwrap();
    Scenario::load(&path).expect("the generated scenario loads")
}

fn life_long(c: &mut Criterion) {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-epdm-outdoor-cycles.toml");
    let mut cycles = Scenario::load(&path)
        .expect("the shipped scenario loads")
        .life;
    cycles.time.duration = 130.0 * YEAR;
    let dir = tempfile::tempdir().unwrap();
    let history = long_history(dir.path()).life;
    let mut group = c.benchmark_group("life_long");
    group.sample_size(10);
    group.sampling_mode(SamplingMode::Flat);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(30));
    group.bench_function("130-year EPDM outdoor run, daily and yearly cycles", |b| {
        b.iter(|| simulate(black_box(&cycles)))
    });
    group.bench_function(
        "30-year NBR run on a 100 000-row temperature history",
        |b| b.iter(|| simulate(black_box(&history))),
    );
    group.finish();
}

criterion_group!(benches, life_long);
criterion_main!(benches);
