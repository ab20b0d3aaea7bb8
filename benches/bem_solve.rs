//! One BEM contact solve, timed alone (no percolation, no flow), for the side-by-side with peer
//! solvers (`benches/bem-peers.sh`). Not a criterion bench: `harness = false`, and it does
//! nothing unless given a map, so `cargo bench` and CI skip it cheaply.
//!
//! ```text
//! cargo bench --bench bem_solve -- MAP N PIXEL_M E_STAR_PA MEAN_PRESSURE_PA TOLERANCE THREADS [PRESSURE_OUT]
//! ```
//!
//! `MAP` holds the `N²` heights (m) as little-endian f64, row-major (`heights[iy * N + ix]`,
//! numpy's `tofile`). The solve is periodic with the default settings except the tolerance and
//! the FFT threads. Prints one line of JSON: wall time of the solve alone (s), fine and coarse
//! iterations, A/A0, mean gap ū (m), approach (m), residual. With `PRESSURE_OUT`, the pressure
//! field (Pa, same layout and encoding) is written there for the error comparison.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "a benchmark runner: a failure is reported and ends it"
)]

use sealsim::numerical::HeightMap;
use sealsim::numerical::bem::{BemSettings, Boundary, solve};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    if args.len() < 7 {
        eprintln!(
            "usage: bem_solve MAP N PIXEL_M E_STAR_PA MEAN_PRESSURE_PA TOLERANCE THREADS [PRESSURE_OUT]"
        );
        return;
    }
    let number = |i: usize| -> f64 {
        args[i]
            .parse()
            .unwrap_or_else(|_| panic!("argument {} is not a number: {}", i + 1, args[i]))
    };
    let n = number(1) as usize;
    let bytes = std::fs::read(&args[0]).expect("height map readable");
    assert_eq!(bytes.len(), n * n * 8, "{} must hold {n}² f64", args[0]);
    let heights: Vec<f64> = bytes
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().expect("8 bytes")))
        .collect();
    drop(bytes); // one n² field less at the peak (512 MB at 8192²)
    let map = HeightMap {
        n,
        pixel: number(2),
        heights,
    };
    let settings = BemSettings {
        tolerance: number(5),
        threads: number(6) as usize,
        ..BemSettings::default()
    };
    let start = Instant::now();
    let sol = solve(&map, number(3), number(4), Boundary::Periodic, &settings)
        .expect("the solve converges");
    let seconds = start.elapsed().as_secs_f64();
    println!(
        "{{\"time_s\": {seconds:.6}, \"iterations\": {}, \"coarse_iterations\": {}, \
         \"area_fraction\": {:.17e}, \"mean_gap_m\": {:.17e}, \"approach_m\": {:.17e}, \
         \"residual\": {:.3e}}}",
        sol.iterations,
        sol.coarse_iterations,
        sol.contact_fraction,
        sol.mean_gap,
        sol.approach,
        sol.residual
    );
    if let Some(out) = args.get(7) {
        let bytes: Vec<u8> = sol.pressure.iter().flat_map(|v| v.to_le_bytes()).collect();
        std::fs::write(out, bytes).expect("pressure written");
    }
}
