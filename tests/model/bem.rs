//! Slow checks of the FFT boundary-element contact solver, all `#[ignore]`d; run with
//! `cargo test --release --test model bem:: -- --ignored --nocapture`.
//!
//! * `timings_of_the_accelerations` — wall time, iterations and agreement of the four
//!   preconditioner / warm-start combinations on the benchmark surface (`benches/bem.rs`).
//!   `BEM_SIZES` (default `512,1024`), `BEM_COMBOS=fast` (default settings only),
//!   `BEM_THREADS` (FFT threads).
//! * `one_solve_for_peak_memory` — one default solve at `BEM_N` (default 2048) for
//!   `/usr/bin/time -v target/release/deps/bem-<hash> --ignored one_solve_for_peak_memory`.

use sealsim::numerical::HeightMap;
use sealsim::numerical::bem::{BemSettings, Boundary, solve};
use sealsim::numerical::surface::synthesize;
use sealsim::surface::Spectrum;
use std::time::Instant;

/// Benchmark surface: self-affine H = 0.8, h_rms = 1 µm (spectrum's), q1/q0 = n/8.
fn surface(n: usize, seed: u64) -> HeightMap {
    let q0 = 1e4;
    let spectrum = Spectrum::self_affine(1e-6, 0.8, q0, q0 * (n / 8) as f64, None).unwrap();
    synthesize(&spectrum, n, seed)
}

fn env_settings() -> BemSettings {
    let mut settings = BemSettings::default();
    if let Some(t) = std::env::var("BEM_THREADS")
        .ok()
        .and_then(|t| t.parse().ok())
    {
        settings.threads = t;
    }
    settings
}

#[test]
#[ignore = "slow: timings of the accelerations"]
fn timings_of_the_accelerations() {
    let sizes: Vec<usize> = std::env::var("BEM_SIZES")
        .ok()
        .map(|s| s.split(',').filter_map(|v| v.trim().parse().ok()).collect())
        .unwrap_or_else(|| vec![512, 1024]);
    let combos: Vec<(bool, bool)> = match std::env::var("BEM_COMBOS").ok().as_deref() {
        Some("fast") => vec![(true, true)],
        _ => vec![(true, true), (true, false), (false, true), (false, false)],
    };
    for n in sizes {
        let map = surface(n, 1);
        // p̄ / (E* h'_rms) = 0.1: A/A0 ≈ 0.2.
        let pressure = 0.1 * map.rms_slope();
        let mut reference: Option<Vec<f64>> = None;
        for &(preconditioned, coarse_to_fine) in &combos {
            let settings = BemSettings {
                preconditioned,
                coarse_to_fine,
                ..env_settings()
            };
            let start = Instant::now();
            let sol = solve(&map, 1.0, pressure, Boundary::Periodic, &settings).unwrap();
            let elapsed = start.elapsed().as_secs_f64();
            let diff = reference.as_ref().map_or(0.0, |r| {
                r.iter()
                    .zip(&sol.pressure)
                    .map(|(a, b)| (a - b).abs())
                    .sum::<f64>()
                    / r.iter().sum::<f64>()
            });
            println!(
                "n = {n:5}  precond {preconditioned:5}  warm {coarse_to_fine:5}: {elapsed:7.3} s, \
                 {:4} + {:3} coarse iterations, A/A0 = {:.4}, ū/h_rms = {:.4}, residual {:.1e}, \
                 Σ|Δp|/Σp vs first {diff:.1e}",
                sol.iterations,
                sol.coarse_iterations,
                sol.contact_fraction,
                sol.mean_gap / map.rms(),
                sol.residual
            );
            assert!(diff < 1e-6);
            if reference.is_none() {
                reference = Some(sol.pressure);
            }
        }
    }
}

#[test]
#[ignore = "slow: run under /usr/bin/time -v for the peak memory"]
fn one_solve_for_peak_memory() {
    let n = std::env::var("BEM_N")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2048);
    let map = surface(n, 1);
    let pressure = 0.1 * map.rms_slope();
    let start = Instant::now();
    let sol = solve(&map, 1.0, pressure, Boundary::Periodic, &env_settings()).unwrap();
    println!(
        "n = {n}: {:.2} s, {} + {} coarse iterations, A/A0 = {:.4}",
        start.elapsed().as_secs_f64(),
        sol.iterations,
        sol.coarse_iterations,
        sol.contact_fraction
    );
}
