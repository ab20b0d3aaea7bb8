//! Throughput of a study (issue 43): the shipped throughput study
//! (`scenarios/studies/headline-monte-carlo.study.toml`: the headline 30-year O-ring at
//! critical-junction fidelity, groove depth, Ra and temperature varied, each case with its own
//! surface and so its own contact table) cut to its first 1 000 cases, run through the library
//! call `sealsim study` makes (`workflow::study::run`) on 1 and on 2 threads — the CLI's
//! `--threads N` is that call's `threads` argument, a rayon pool of N workers. Target: 10 000
//! cases ≤ 1 min on the 2-core VM, i.e. 1 000 cases ≤ 6 s. The figures go in
//! docs/src/performance.md through `benches/performance.py record`.
//!
//! Each iteration is seconds long, so criterion takes 10 samples of one iteration each (flat
//! sampling): about 1.5 min for the whole bench on the 2-core VM.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

use criterion::{Criterion, SamplingMode, criterion_group, criterion_main};
use sealsim::scenario::study::Study;
use sealsim::workflow;
use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

/// The cases per iteration: the study's `samples` overridden after loading (a Monte Carlo
/// case's inputs depend only on the seed and its index, so these are the file's first 1 000).
const CASES: usize = 1000;

fn study(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios/studies/headline-monte-carlo.study.toml");
    let mut study = Study::load(&path).expect("the shipped study loads");
    study.plan.samples = CASES;
    assert_eq!(study.cases(), CASES);
    let mut group = c.benchmark_group("study");
    group.sample_size(10);
    group.sampling_mode(SamplingMode::Flat);
    group.warm_up_time(Duration::from_secs(1));
    for threads in [1, 2] {
        // ≈ 5.5 s per iteration on 1 thread, 3 s on 2 (2026-11 figures): 10 samples fit
        group.measurement_time(Duration::from_secs(if threads == 1 { 50 } else { 28 }));
        group.bench_function(
            format!("headline monte carlo, {CASES} cases, {threads} thread(s)"),
            |b| {
                b.iter(|| {
                    let outcomes = workflow::study::run(
                        black_box(&study),
                        0..CASES,
                        Some(threads),
                        &|_, _| {},
                    )
                    .expect("the study runs");
                    assert_eq!(outcomes.len(), CASES);
                    outcomes
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, study);
criterion_main!(benches);
