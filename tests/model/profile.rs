//! Line traces → the isotropic 2-D spectrum (crates/sealsim-core/src/profile.rs) and the trace CSV reader.

use sealsim::profile::{
    ProfileOptions, Trace, abel_inverse, analyse, one_d_from_two_d, power_law_factor,
    profile_parameters, synthesize_gaussian,
};
use sealsim::scenario::profile::parse_trace;
use sealsim::surface::Spectrum;
use std::f64::consts::PI;
use std::path::Path;
use std::time::Instant;

const PIXEL: f64 = 0.5e-6;
const N: usize = 2048;

fn dq() -> f64 {
    2.0 * PI / (N as f64 * PIXEL)
}

/// The known spectrum of the round trip: H = 0.8, roll-off at 32 · 2π/L of the surface.
fn known() -> Spectrum {
    Spectrum::self_affine(1e-6, 0.8, dq(), PI / PIXEL, Some(32.0 * dq())).unwrap()
}

/// Half-rows (1024 points, not periodic) of `surfaces` Gaussian surfaces, `rows` per surface.
fn traces(surfaces: u64, rows: usize) -> Vec<Trace> {
    let spectrum = known();
    let mut out = Vec::new();
    for seed in 0..surfaces {
        let h = synthesize_gaussian(&spectrum, N, PIXEL, 1000 + seed);
        for r in 0..rows {
            let row = &h[r * (N / rows) * N..][..N];
            for half in row.chunks_exact(N / 2) {
                out.push(Trace {
                    spacing: PIXEL,
                    heights: half.to_vec(),
                });
            }
        }
    }
    out
}

/// 8 Gaussian 2048² surfaces (H = 0.8, roll-off at 32 · 2π/L), 32 rows each cut in two
/// halves: 512 traces of 1024 points.
#[test]
fn round_trip_recovers_the_known_spectrum() {
    let start = Instant::now();
    let traces = traces(8, 32);
    let result = analyse(&traces, &ProfileOptions::default()).unwrap();
    let spectrum = known();
    let q_r = 32.0 * dq();
    let (mut worst_all, mut worst_law): (f64, f64) = (0.0, 0.0);
    for (q, inv) in result.psd_1d.q.iter().zip(&result.inversion) {
        let signed = result.spectrum.c(*q) / spectrum.c(*q) - 1.0;
        let e = signed.abs();
        eprintln!(
            "q/q_r = {:.3}  C err {signed:+.4} (non-parametric inversion {:+.4})",
            q / q_r,
            inv / spectrum.c(*q) - 1.0
        );
        worst_all = worst_all.max(e);
        if *q >= 2.0 * q_r {
            worst_law = worst_law.max(e);
        }
    }
    let band = spectrum.restricted(result.band.0, result.band.1).unwrap();
    let e_h = result.h_rms / band.rms_roughness() - 1.0;
    let e_s = result.rms_slope / band.rms_slope() - 1.0;
    eprintln!(
        "band {:?}; worst C error {worst_all:.3} (band), {worst_law:.3} (q ≥ 2 q_r); H {:?}; \
         roll-off {:?} (true {q_r}); h_rms {e_h:+.4}; slope {e_s:+.4}; model {}; {:?}",
        result.band,
        result.hurst,
        result.q0,
        result.from_model,
        start.elapsed()
    );
    assert!(result.from_model, "the roll-off model should be reported");
    assert!(worst_all <= 0.05, "{worst_all}");
    assert!(worst_law < 0.05, "{worst_law}");
    assert!((result.hurst.0 - 0.8).abs() < 0.03, "{:?}", result.hurst);
    assert!(e_h.abs() < 0.03 && e_s.abs() < 0.03, "{e_h} {e_s}");
    assert!(result.q0.is_some());
}

/// A spectrum that is not "flat + power law" (two power laws, H = 0.8 below 4e5 1/m and 0.3
/// above, no roll-off): the model misfits the 1-D data and the non-parametric inversion is
/// reported. 2 surfaces, 128 traces.
#[test]
fn a_bent_spectrum_is_reported_by_the_inversion() {
    let q_b = 4e5;
    let q: Vec<f64> = (0..=40)
        .map(|i| dq() * (PI / PIXEL / dq()).powf(i as f64 / 40.0))
        .collect();
    let c: Vec<f64> = q
        .iter()
        .map(|&q| {
            if q < q_b {
                1e-30 * (q / q_b).powf(-3.6)
            } else {
                1e-30 * (q / q_b).powf(-2.6)
            }
        })
        .collect();
    let spectrum = Spectrum::tabulated(&q, &c).unwrap();
    let mut traces = Vec::new();
    for seed in 0..2 {
        let h = synthesize_gaussian(&spectrum, N, PIXEL, 2000 + seed);
        for r in 0..32 {
            for half in h[r * (N / 32) * N..][..N].chunks_exact(N / 2) {
                traces.push(Trace {
                    spacing: PIXEL,
                    heights: half.to_vec(),
                });
            }
        }
    }
    let result = analyse(&traces, &ProfileOptions::default()).unwrap();
    for (q, c) in result.psd_1d.q.iter().zip(&result.inversion) {
        eprintln!(
            "q = {q:.4e}  inversion err {:+.4}  model err {:+.4}",
            c / spectrum.c(*q) - 1.0,
            result.model.c(*q) / spectrum.c(*q) - 1.0
        );
    }
    eprintln!("model {:?}; H {:?}", result.model, result.hurst);
    assert!(!result.from_model);
    assert!((result.spectrum.c(result.band.0) / result.inversion[0] - 1.0).abs() < 1e-9);
}

/// The closed form C = C1D/q · Γ(1+H)/(√π Γ(H+½)) against the numerical Abel pair on exact power
/// laws, both directions.
#[test]
fn abel_pair_matches_the_power_law_closed_form() {
    for h in [0.3, 0.5, 0.8, 0.95] {
        let spectrum = Spectrum::self_affine(1e-6, h, 1.0, 1e12, None).unwrap();
        let q: Vec<f64> = (0..40).map(|i| 1e4 * 10f64.powf(i as f64 / 10.0)).collect();
        let c1: Vec<f64> = q
            .iter()
            .map(|&q| q * spectrum.c(q) / power_law_factor(h))
            .collect();
        let c2 = abel_inverse(&q, &c1, -(1.0 + 2.0 * h));
        for ((qq, a), b) in q.iter().zip(&c2).zip(&c1) {
            assert!((a / spectrum.c(*qq) - 1.0).abs() < 1e-8, "H {h} q {qq}");
            // forward: far below q1 the band edge does not matter
            if *qq < 1e7 {
                let f = one_d_from_two_d(&spectrum, *qq);
                assert!((f / b - 1.0).abs() < 1e-6, "H {h} q {qq}: {f} vs {b}");
            }
        }
    }
}

#[test]
fn rz_of_a_cosine_with_the_gaussian_filter() {
    // wavelength λc/10 passes the Gaussian filter; crests and troughs
    // on samples: Rz = 2a
    let a = 0.4e-6;
    let dx = 1e-6;
    let lc = 0.8e-3;
    let period = 80;
    let n = 6 * 800 + 1;
    let heights: Vec<f64> = (0..n)
        .map(|j| a * (2.0 * PI * j as f64 / period as f64).cos())
        .collect();
    let p = profile_parameters(
        &Trace {
            spacing: dx,
            heights,
        },
        Some(lc),
    )
    .unwrap();
    assert_eq!(p.sampling_lengths, 5);
    // the truncated kernel (±λc/2, renormalised) leaves ~4e-4 of the cosine in the mean line
    assert!((p.rz.unwrap() / (2.0 * a) - 1.0).abs() < 1e-3, "{p:?}");
    assert!((p.rq / (a / 2f64.sqrt()) - 1.0).abs() < 1e-3, "{p:?}");
}

fn file(rows: usize, step: impl Fn(usize) -> f64, units: &str) -> String {
    let mut s = format!("# synthetic\nx,z\n{units}");
    let mut x = 0.0;
    for i in 0..rows {
        s.push_str(&format!("{x},{}\n", (i as f64).sin()));
        x += step(i);
    }
    s
}

#[test]
fn trace_reader_units_and_errors() {
    let path = Path::new("t.csv");
    let t = parse_trace(&file(300, |_| 0.5, "um,nm\n"), path).unwrap();
    assert!((t.spacing - 0.5e-6).abs() < 1e-18);
    assert!((t.heights[1] - 1f64.sin() * 1e-9).abs() < 1e-20);
    // no units row: refused (a bare 0.5 could be metres or micrometres), the fix accepted
    let e = parse_trace(&file(300, |_| 0.5, ""), path)
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("t.csv:3: no units row"), "{e}");
    let t = parse_trace(&file(300, |_| 0.5, "m,m\n"), path).unwrap();
    assert!((t.spacing - 0.5).abs() < 1e-15);

    let err = |text: &str| parse_trace(text, path).unwrap_err().to_string();
    // a gap at the 100th step: line 3 (units) + 101
    let e = err(&file(300, |i| if i == 99 { 1.0 } else { 0.5 }, "mm,um\n"));
    assert!(e.starts_with("t.csv:104: non-uniform spacing"), "{e}");
    let e = err(&file(100, |_| 0.5, "mm,um\n"));
    assert!(e.contains("at least 256"), "{e}");
    let e = err(&file(300, |_| 0.5, "mm,s\n"));
    assert!(e.starts_with("t.csv:3: unit \"s\""), "{e}");
    assert!(e.contains("must be lengths"), "{e}");
    let e = err(&file(300, |_| 0.5, "mm,um\n").replacen("0.5,", "abc,", 1));
    assert!(e.starts_with("t.csv:5: x is not a number"), "{e}");
    let e = err(&file(300, |_| 0.5, "mm,um\n").replacen("1,", "0.25,", 1));
    assert!(e.contains("increase strictly"), "{e}");
    let e = err("q,C\n1,2\n");
    assert!(e.starts_with("t.csv:1: expected the header"), "{e}");
}

/// A line trace across an isotropic Gaussian surface of spectrum `c`: N points at `dx`, as a
/// sum of N/2 − 1 Fourier modes with independent normal amplitudes of variance
/// `2 C1D(q_k) Δq` (so that ⟨h²⟩ = 2 Σ C1D Δq, the 1-D convention of `sealsim::profile`),
/// C1D the Abel transform of `c`; normals from SplitMix64 (Box–Muller).
fn synthetic_trace(c: &Spectrum, n: usize, dx: f64, seed: u64) -> Vec<f64> {
    let mut rng = crate::rng::SplitMix64(seed);
    let mut uniform = || rng.uniform();
    let length = n as f64 * dx;
    let dq = 2.0 * PI / length;
    let mut modes = Vec::new();
    for k in 1..n / 2 {
        let q = k as f64 * dq;
        let sigma = (2.0 * one_d_from_two_d(c, q) * dq).sqrt();
        let (u1, u2) = (uniform(), uniform());
        let r = (-2.0 * u1.ln()).sqrt();
        modes.push((
            q,
            sigma * r * (2.0 * PI * u2).cos(),
            sigma * r * (2.0 * PI * u2).sin(),
        ));
    }
    (0..n)
        .map(|j| {
            let x = j as f64 * dx;
            modes
                .iter()
                .map(|&(q, a, b)| a * (q * x).cos() + b * (q * x).sin())
                .sum()
        })
        .collect()
}

/// Writes the example traces of `scenarios/traces/` (run by hand:
/// `cargo test --release --test model write_example_traces -- --ignored`): two synthetic
/// stylus traces, 8192 points at 0.5 µm (4.1 mm, five sampling lengths of 0.8 mm), across
/// isotropic self-affine surfaces scaled to a stated Rq over the callout band 2π/0.8 mm …
/// 2π/2.5 µm.
#[test]
#[ignore]
fn write_example_traces() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/traces");
    std::fs::create_dir_all(&dir).unwrap();
    let (n, dx) = (8192, 0.5e-6);
    for (name, hurst, rolloff_um, rq_um, seed, what) in [
        (
            "ground-fine.csv",
            0.8,
            100.0,
            0.5,
            11,
            "a fine ground counterface",
        ),
        (
            "ground-coarse.csv",
            0.7,
            200.0,
            2.0,
            12,
            "a coarse ground counterface",
        ),
    ] {
        let (q0, q1) = (2.0 * PI / (n as f64 * dx), 2.0 * PI / 1e-6);
        let q_r = 2.0 * PI / (rolloff_um * 1e-6);
        let unit = Spectrum::self_affine(1.0, hurst, q0, q1, Some(q_r)).unwrap();
        let band = unit
            .restricted(2.0 * PI / 0.8e-3, 2.0 * PI / 2.5e-6)
            .unwrap()
            .rms_roughness();
        let c = unit.with_rms_roughness(rq_um * 1e-6 / band);
        let z = synthetic_trace(&c, n, dx, seed);
        let mut text = format!(
            "# SYNTHETIC line trace (not measured): {what}.\n\
             # A line across an isotropic Gaussian self-affine surface: H = {hurst}, roll-off at \
             wavelength {rolloff_um} um, spectrum from q0 = 2pi/(N dx) to q1 = 2pi/1um, scaled to \
             Rq = {rq_um} um over the callout band 2pi/0.8mm ... 2pi/2.5um (Ra = Rq sqrt(2/pi)).\n\
             # h_rms of the whole spectrum {:.4} um, rms slope {:.4}. Seed {seed}.\n\
             # Made by: cargo test --release --test model write_example_traces -- --ignored\n\
             x,z\nmm,um\n",
            c.rms_roughness() * 1e6,
            c.rms_slope()
        );
        for (j, h) in z.iter().enumerate() {
            use std::fmt::Write;
            let _ = writeln!(text, "{:.4},{:.5}", j as f64 * dx * 1e3, h * 1e6);
        }
        std::fs::write(dir.join(name), text).unwrap();
    }
}
