//! Speed of the thin-film Reynolds solve (docs/model.md §3.5) on a realistic gap field: 512² cells with
//! each preconditioner, 1024² with the default multigrid (target: 1024² ≤ 5 s; Jacobi and
//! MIC(0) take tens of seconds there — see `tests/flow.rs`, test `timings`, for a one-shot
//! table of every size and preconditioner). The gap is
//! `max(0, d − h)` for a smooth periodic random field `h` (a few hundred cosines, wavevectors
//! log-uniform in |k| ≤ n/8, amplitude ∝ |k|^−0.8, i.e. self-affine with H = 0.8), `d` set so that
//! 25 % of the cells are in contact. The iteration counts are printed before the timings.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

use criterion::{Criterion, criterion_group, criterion_main};
use sealsim::numerical::flow::{FlowSettings, Preconditioner, solve};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// SplitMix64: a tiny seeded generator, enough for the phases and wavevectors.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Gap field (m, `n × n`, 1 µm rms roughness) with `contact` of the cells closed.
fn rough_gap(n: usize, modes: usize, contact: f64, seed: u64) -> Vec<f64> {
    use std::f64::consts::PI;
    let mut rng = SplitMix(seed);
    let kmax = (n / 8).max(2) as f64;
    let mut h = vec![0.0; n * n];
    let (mut cx, mut sx) = (vec![0.0; n], vec![0.0; n]);
    for _ in 0..modes {
        let k = kmax.powf(rng.next());
        let angle = 2.0 * PI * rng.next();
        let (kx, ky) = ((k * angle.cos()).round(), (k * angle.sin()).round());
        if kx == 0.0 && ky == 0.0 {
            continue;
        }
        let amp = (kx * kx + ky * ky).sqrt().powf(-0.8);
        let phase = 2.0 * PI * rng.next();
        for ix in 0..n {
            let a = 2.0 * PI * kx * ix as f64 / n as f64;
            (cx[ix], sx[ix]) = (a.cos(), a.sin());
        }
        for iy in 0..n {
            let b = 2.0 * PI * ky * iy as f64 / n as f64 + phase;
            let (c, s) = (amp * b.cos(), amp * b.sin());
            for ((v, ca), sa) in h[iy * n..(iy + 1) * n].iter_mut().zip(&cx).zip(&sx) {
                *v += c * ca - s * sa;
            }
        }
    }
    let mean = h.iter().sum::<f64>() / (n * n) as f64;
    let rms = (h.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n * n) as f64).sqrt();
    let mut sorted = h.clone();
    sorted.sort_by(f64::total_cmp);
    let d = sorted[(((1.0 - contact) * (n * n) as f64) as usize).min(n * n - 1)];
    h.iter().map(|&v| 1e-6 * (d - v).max(0.0) / rms).collect()
}

const ETA: f64 = 1e-3;
const PIXEL: f64 = 1e-7;

fn settings(preconditioner: Preconditioner) -> FlowSettings {
    FlowSettings {
        preconditioner,
        ..FlowSettings::default()
    }
}

fn flow(c: &mut Criterion) {
    let cases = [
        (512, Preconditioner::Jacobi),
        (512, Preconditioner::IncompleteCholesky),
        (512, Preconditioner::Multigrid),
        (1024, Preconditioner::Multigrid),
    ];
    let mut group = c.benchmark_group("reynolds");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(100));
    for n in [512, 1024] {
        let gap = rough_gap(n, 400, 0.25, 7);
        for &(_, p) in cases.iter().filter(|(m, _)| *m == n) {
            let start = Instant::now();
            let s = solve(&gap, n, PIXEL, ETA, &settings(p)).expect("solve");
            eprintln!(
                "{n}² {p:?}: {:.2} s, {} iterations, residual {:.1e}, σ_eff = {:.6e} m³/(Pa·s), \
                 effective gap {:.4e} m, contact {:.3}, spanning {:.3}",
                start.elapsed().as_secs_f64(),
                s.iterations,
                s.residual,
                s.conductance,
                s.effective_gap,
                s.contact_fraction,
                s.spanning_fraction
            );
            group.bench_function(format!("{n}² {p:?}"), |b| {
                b.iter(|| solve(black_box(&gap), n, PIXEL, ETA, &settings(p)))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, flow);
criterion_main!(benches);
