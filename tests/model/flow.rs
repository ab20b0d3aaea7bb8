//! Integration tests of the numerical flow reference on a realistic rough gap field, and a
//! timing table (ignored by default):
//! `cargo test --release --test model flow:: -- --ignored --nocapture` (sizes from
//! `SEALSIM_FLOW_SIZES`, default "256,512,1024").

use sealsim::numerical::flow::{FlowSettings, Preconditioner, solve, solve_field};
use sealsim::numerical::percolation;
use std::time::Instant;

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

/// Smooth periodic random heights (`n × n`, unit rms).
fn rough_heights(n: usize, modes: usize, seed: u64) -> Vec<f64> {
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
    h.iter().map(|v| (v - mean) / rms).collect()
}

/// Gap `1 µm · max(0, d − h)` of a rigid flat at level `d` over the heights `h`.
fn gap_at(h: &[f64], d: f64) -> Vec<f64> {
    h.iter().map(|&v| 1e-6 * (d - v).max(0.0)).collect()
}

/// Gap field (m, `n × n`, 1 µm rms roughness) with `contact` of the cells closed.
fn rough_gap(n: usize, modes: usize, contact: f64, seed: u64) -> Vec<f64> {
    let h = rough_heights(n, modes, seed);
    let mut sorted = h.clone();
    sorted.sort_by(f64::total_cmp);
    let d = sorted[(((1.0 - contact) * (n * n) as f64) as usize).min(n * n - 1)];
    gap_at(&h, d)
}

const ETA: f64 = 1e-3;
const PIXEL: f64 = 1e-7;
const ALL: [Preconditioner; 3] = [
    Preconditioner::Jacobi,
    Preconditioner::IncompleteCholesky,
    Preconditioner::Multigrid,
];

fn settings(preconditioner: Preconditioner) -> FlowSettings {
    let tolerance = std::env::var("SEALSIM_FLOW_TOL")
        .ok()
        .and_then(|t| t.parse().ok())
        .unwrap_or(1e-10);
    FlowSettings {
        preconditioner,
        tolerance,
        ..FlowSettings::default()
    }
}

#[test]
fn rough_gap_all_preconditioners_agree_and_conserve_flux() {
    let n = 256;
    let gap = rough_gap(n, 300, 0.25, 7);
    let open = percolation::open_mask(&gap);
    assert!(percolation::percolates(&open, n));
    let mut values = Vec::new();
    for p in ALL {
        let f = solve_field(&gap, n, PIXEL, ETA, &settings(p)).expect("solve");
        let s = f.solution;
        assert!(s.residual <= 1e-10, "{p:?}: {s:?}");
        let spread = f
            .cross_section_flux
            .iter()
            .map(|q| (q - s.conductance).abs() / s.conductance)
            .fold(0.0, f64::max);
        assert!(spread <= 1e-7, "{p:?}: flux spread {spread:e}");
        values.push(s.conductance);
    }
    for v in &values {
        assert!((v - values[2]).abs() <= 1e-9 * values[2], "{values:?}");
    }
    // Wiener bounds: below the arithmetic mean of u³/12η over the cells, above 0.
    let mean = gap.iter().map(|u| u.powi(3) / (12.0 * ETA)).sum::<f64>() / (n * n) as f64;
    assert!(values[2] > 0.0 && values[2] < mean);
}

#[test]
fn more_contact_less_flow() {
    let n = 128;
    let mut last = f64::INFINITY;
    for contact in [0.0, 0.1, 0.2, 0.3, 0.4] {
        let gap = rough_gap(n, 300, contact, 3);
        let s = solve(&gap, n, PIXEL, ETA, &FlowSettings::default()).expect("solve");
        assert!(s.conductance < last, "contact {contact}: {s:?}");
        last = s.conductance;
    }
    // Far beyond the percolation threshold nothing flows.
    let gap = rough_gap(n, 300, 0.9, 3);
    let s = solve(&gap, n, PIXEL, ETA, &FlowSettings::default()).expect("solve");
    assert_eq!(s.conductance, 0.0);
}

#[test]
fn sizes_that_are_not_powers_of_two() {
    for n in [2, 3, 5, 17, 100, 257] {
        let gap = rough_gap(n, 200, 0.2, 40 + n as u64);
        let reference =
            solve(&gap, n, PIXEL, ETA, &settings(Preconditioner::Jacobi)).expect("solve");
        for p in [
            Preconditioner::IncompleteCholesky,
            Preconditioner::Multigrid,
        ] {
            let s = solve(&gap, n, PIXEL, ETA, &settings(p)).expect("solve");
            assert_eq!(s.percolates, reference.percolates);
            assert!(
                (s.conductance - reference.conductance).abs() <= 1e-9 * reference.conductance,
                "n = {n}, {p:?}: {s:?} vs {reference:?}"
            );
        }
    }
}

#[test]
fn just_above_the_percolation_threshold() {
    // The flat sits just above the critical level: the one cell that completes the spanning
    // path has a gap of 1e-4 of the rms roughness, so the flow goes through one constriction of
    // conductance ~1e-12 of the largest (the critical junction of the theory).
    let n = 128;
    let h = rough_heights(n, 300, 21);
    let critical = percolation::critical_level(&h, n).expect("threshold");
    let sealed = solve(
        &gap_at(&h, critical.level),
        n,
        PIXEL,
        ETA,
        &FlowSettings::default(),
    )
    .expect("solve");
    assert!(!sealed.percolates);
    assert_eq!(sealed.conductance, 0.0);
    let gap = gap_at(&h, critical.level + 1e-4);
    let mut values = Vec::new();
    for p in ALL {
        let s = solve(&gap, n, PIXEL, ETA, &settings(p)).expect("solve");
        assert!(s.percolates && s.conductance > 0.0, "{p:?}: {s:?}");
        assert!(
            (s.contact_fraction - critical.contact_fraction).abs() <= 1.5 / (n * n) as f64,
            "{s:?} vs {critical:?}"
        );
        values.push(s.conductance);
    }
    for v in &values {
        assert!((v - values[2]).abs() <= 1e-8 * values[2], "{values:?}");
    }
    // The constriction limits the flow: a series bound with one cell of the critical gap.
    let sigma_neck = (1e-10f64).powi(3) / (12.0 * ETA);
    assert!(values[2] < 2.0 * sigma_neck * n as f64, "{values:?}");
}

#[test]
#[ignore = "timing table; run with --ignored --nocapture"]
fn timings() {
    let sizes = std::env::var("SEALSIM_FLOW_SIZES").unwrap_or_else(|_| "256,512,1024".into());
    let pres: Vec<Preconditioner> = match std::env::var("SEALSIM_FLOW_PRE").as_deref() {
        Ok("mg") => vec![Preconditioner::Multigrid],
        Ok("ic") => vec![Preconditioner::IncompleteCholesky],
        Ok("jacobi") => vec![Preconditioner::Jacobi],
        _ => ALL.to_vec(),
    };
    for n in sizes
        .split(',')
        .map(|s| s.trim().parse::<usize>().expect("size"))
    {
        let t = Instant::now();
        let seed = std::env::var("SEALSIM_FLOW_SEED")
            .ok()
            .and_then(|t| t.parse().ok())
            .unwrap_or(7);
        // SEALSIM_FLOW_CRITICAL=δ: the flat δ (in rms units) above the critical level instead
        // of 25 % contact.
        let mut gap = match std::env::var("SEALSIM_FLOW_CRITICAL") {
            Ok(delta) => {
                let h = rough_heights(n, 400, seed);
                let level = percolation::critical_level(&h, n).expect("threshold").level;
                gap_at(&h, level + delta.parse::<f64>().expect("delta"))
            }
            Err(_) => rough_gap(n, 400, 0.25, seed),
        };
        if let Ok(f) = std::env::var("SEALSIM_FLOW_FLOOR") {
            let f: f64 = f.parse().expect("floor");
            for u in &mut gap {
                if *u > 0.0 {
                    *u = u.max(f);
                }
            }
        }
        let generation = t.elapsed().as_secs_f64();
        if let Ok(path) = std::env::var("SEALSIM_FLOW_DUMP") {
            let bytes: Vec<u8> = gap.iter().flat_map(|v| v.to_le_bytes()).collect();
            std::fs::write(format!("{path}{n}.bin"), bytes).expect("dump");
        }
        let t = Instant::now();
        let perc = percolation::analyse(&percolation::open_mask(&gap), n);
        println!(
            "{n}²: field {generation:.2} s, percolation {:.3} s, contact {:.3}, spanning {:.3}",
            t.elapsed().as_secs_f64(),
            perc.contact_fraction,
            perc.spanning_fraction
        );
        for &p in &pres {
            let t = Instant::now();
            match solve(&gap, n, PIXEL, ETA, &settings(p)) {
                Ok(s) => println!(
                    "  {p:?}: {:.3} s, {} iterations, residual {:.2e}, sigma_eff {:.9e}, \
                     effective gap {:.4e} m",
                    t.elapsed().as_secs_f64(),
                    s.iterations,
                    s.residual,
                    s.conductance,
                    s.effective_gap
                ),
                Err(e) => println!("  {p:?}: {:.3} s, {e}", t.elapsed().as_secs_f64()),
            }
        }
    }
}
