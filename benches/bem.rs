//! Speed of the FFT boundary-element contact solve (docs/model.md §3.5; targets 512² ≤ 0.5 s,
//! 1024² ≤ 3 s, 2048² ≤ 30 s on 2 cores).
//!
//! Surface: `numerical::surface::synthesize` of a self-affine spectrum, H = 0.8, h_rms = 1 µm
//! (the spectrum's), q0 = 10⁴ 1/m, q1/q0 = n/8 (8 pixels per shortest wavelength: 64 at 512²),
//! seed 1. E* = 1 Pa (the problem is scale-free) and mean pressure `p̄ = 0.1 E* h'_rms`, with
//! `h'_rms` the map's rms slope (finite differences), which gives A/A0 ≈ 0.19–0.20 — the issue's
//! p/E* = 0.01 for a surface of rms slope 0.1. Periodic boundary, tolerance 1e-8.
//!
//! Groups: 512² with each combination of the preconditioner and the coarse-to-fine warm start;
//! 1024² with the preconditioner, with and without the warm start, and with 2 FFT threads;
//! 2048² (default settings, 1 and 2 threads) only when `BEM_BENCH_2048` is set. Iteration
//! counts and contact fraction are printed first. `cargo bench --bench bem` takes about three
//! minutes without the 2048² group (add about four with it).

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

use criterion::{Criterion, criterion_group, criterion_main};
use sealsim::numerical::HeightMap;
use sealsim::numerical::bem::{BemSettings, Boundary, solve};
use sealsim::numerical::surface::synthesize;
use sealsim::surface::Spectrum;
use std::hint::black_box;
use std::time::{Duration, Instant};

fn surface(n: usize) -> HeightMap {
    let q0 = 1e4;
    let spectrum =
        Spectrum::self_affine(1e-6, 0.8, q0, q0 * (n / 8) as f64, None).expect("valid spectrum");
    synthesize(&spectrum, n, 1)
}

/// (preconditioned, coarse-to-fine, FFT threads).
type Combo = (bool, bool, usize);

fn settings((preconditioned, coarse_to_fine, threads): Combo) -> BemSettings {
    BemSettings {
        preconditioned,
        coarse_to_fine,
        threads,
        ..BemSettings::default()
    }
}

fn label((preconditioned, coarse_to_fine, threads): Combo) -> String {
    format!(
        "{}, {}{}",
        if preconditioned {
            "preconditioned"
        } else {
            "plain"
        },
        if coarse_to_fine {
            "coarse-to-fine"
        } else {
            "cold start"
        },
        if threads > 1 { ", 2 threads" } else { "" }
    )
}

fn group(c: &mut Criterion, n: usize, combos: &[Combo], measurement: Duration) {
    let map = surface(n);
    let pressure = 0.1 * map.rms_slope();
    for &combo in combos {
        let start = Instant::now();
        let sol = solve(&map, 1.0, pressure, Boundary::Periodic, &settings(combo))
            .expect("benchmark solve converges");
        println!(
            "{n}², {}: {} + {} coarse iterations, A/A0 = {:.3}, one solve {:.2} s",
            label(combo),
            sol.iterations,
            sol.coarse_iterations,
            sol.contact_fraction,
            start.elapsed().as_secs_f64()
        );
    }
    let mut g = c.benchmark_group(format!("bem {n}²"));
    g.sample_size(10).measurement_time(measurement);
    for &combo in combos {
        let s = settings(combo);
        g.bench_function(label(combo), |b| {
            b.iter(|| solve(black_box(&map), 1.0, pressure, Boundary::Periodic, &s))
        });
    }
    g.finish();
}

fn bem(c: &mut Criterion) {
    let all = [
        (true, true, 1),
        (true, false, 1),
        (false, true, 1),
        (false, false, 1),
    ];
    group(c, 512, &all, Duration::from_secs(5));
    group(
        c,
        1024,
        &[(true, true, 1), (true, false, 1), (true, true, 2)],
        Duration::from_secs(20),
    );
    if std::env::var_os("BEM_BENCH_2048").is_some() {
        group(
            c,
            2048,
            &[(true, true, 1), (true, true, 2)],
            Duration::from_secs(90),
        );
    }
}

criterion_group!(benches, bem);
criterion_main!(benches);
