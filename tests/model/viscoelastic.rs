//! Viscoelastic numerics against closed forms and independent references (issue 3, docs/model.md §5).

use sealsim::material::{Prony, PronyTerm, RelaxationState};

/// One term per decade, τ from 1e-2 s to 1e28 s, moduli varied so no symmetry hides errors.
fn wide() -> Prony {
    let terms: Vec<PronyTerm> = (-2..=28)
        .map(|k| PronyTerm {
            modulus: 1e6 * (1.2 + (0.7 * k as f64).sin()),
            tau: 10f64.powi(k),
        })
        .collect();
    Prony::new(0.5e6, &terms).unwrap()
}

/// `φ(x) = (1 − e^{−x})/x` for x ≥ 0.
fn phi(x: f64) -> f64 {
    if x < 1e-12 { 1.0 } else { -(-x).exp_m1() / x }
}

/// `∫_0^t e^{−(t−s)/τ} e^{−s/λ} ds`, in a form free of cancellation: `t e^{−min(a,b)} φ(|a−b|)`
/// with `a = t/λ`, `b = t/τ` (symmetric in a and b).
fn overlap(t: f64, tau: f64, lambda: f64) -> f64 {
    let (a, b) = (t / lambda, t / tau);
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    t * (-lo).exp() * phi(hi - lo)
}

/// Creep and relaxation are consistent: `∫_0^t E(t−s) dJ(s) = 1` (the interconversion
/// identity), evaluated in closed form term by term — not through sealsim's J(t).
#[test]
fn creep_and_relaxation_convolve_to_one() {
    let p = wide();
    let c = p.creep();
    let (tau_min, tau_max) = (1e-2, 1e28);
    let mut worst: f64 = 0.0;
    let mut t = 1e-3 * tau_min;
    while t <= 1e3 * tau_max {
        // dJ = J0 δ(s) + Σ_j (B_j/λ_j) e^{−s/λ_j} ds
        let mut total = p.relaxation(t) * c.instantaneous();
        for r in c.retardation() {
            let e_inf_part = p.long_term() * r.tau * (-(-t / r.tau).exp_m1());
            let branches: f64 = p
                .terms()
                .iter()
                .map(|e| e.modulus * overlap(t, e.tau, r.tau))
                .sum();
            total += r.modulus / r.tau * (e_inf_part + branches);
        }
        worst = worst.max((total - 1.0).abs());
        t *= 10f64.powf(0.25);
    }
    assert!(worst <= 1e-6, "worst |∫E dJ − 1| = {worst:e}");
}

#[test]
fn creep_limits() {
    let p = wide();
    let c = p.creep();
    assert!((c.compliance(0.0) * p.instantaneous() - 1.0).abs() < 1e-12);
    assert!((c.compliance(1e40) * p.long_term() - 1.0).abs() < 1e-9);
    // retardation times interlace the relaxation times
    let taus: Vec<f64> = p.terms().iter().map(|t| t.tau).collect();
    for (j, r) in c.retardation().iter().enumerate() {
        assert!(r.tau > taus[j] && taus.get(j + 1).is_none_or(|&next| r.tau < next));
        assert!(r.modulus > 0.0);
    }
    // J is monotone
    let mut last = 0.0;
    for k in -40..=300 {
        let j = c.compliance(10f64.powf(k as f64 / 10.0));
        assert!(j >= last);
        last = j;
    }
}

#[test]
fn liquid_like_series_creeps_with_steady_flow() {
    // E∞ = 0: J(t) → t/η0 with η0 = Σ E_i τ_i
    let p = Prony::new(
        0.0,
        &[
            PronyTerm {
                modulus: 2e6,
                tau: 1.0,
            },
            PronyTerm {
                modulus: 1e6,
                tau: 100.0,
            },
        ],
    )
    .unwrap();
    let c = p.creep();
    let eta0 = 2e6 * 1.0 + 1e6 * 100.0;
    let t = 1e9;
    assert!((c.compliance(t) / (t / eta0) - 1.0).abs() < 1e-6);
}

/// Strain history: ramp to 20 % over 100 s, hold 1e4 s, unload to 5 % over 50 s, hold.
const HISTORY: [(f64, f64); 5] = [
    (0.0, 0.0),
    (100.0, 0.2),
    (1.01e4, 0.2),
    (1.015e4, 0.05),
    (1e6, 0.05),
];

/// σ(t) = ∫_0^t E(t−s) ε′(s) ds by the midpoint rule with `n` steps per segment: an independent
/// fine-step reference (no exponential update, no closed form).
fn hereditary_midpoint(p: &Prony, t: f64, n: usize) -> f64 {
    let mut sigma = 0.0;
    for w in HISTORY.windows(2) {
        let ((s0, e0), (s1, e1)) = (w[0], w[1]);
        if s0 >= t {
            break;
        }
        let rate = (e1 - e0) / (s1 - s0);
        let end = s1.min(t);
        let h = (end - s0) / n as f64;
        sigma += (0..n)
            .map(|k| p.relaxation(t - (s0 + (k as f64 + 0.5) * h)))
            .sum::<f64>()
            * h
            * rate;
    }
    sigma
}

fn strain_at(t: f64) -> f64 {
    let k = HISTORY
        .partition_point(|&(s, _)| s <= t)
        .clamp(1, HISTORY.len() - 1);
    let ((s0, e0), (s1, e1)) = (HISTORY[k - 1], HISTORY[k]);
    e0 + (e1 - e0) * ((t - s0) / (s1 - s0)).min(1.0)
}

#[test]
fn piecewise_linear_history_matches_fine_step_reference() {
    let terms: Vec<PronyTerm> = (-1..=5)
        .map(|k| PronyTerm {
            modulus: 1e6 * (1.0 + 0.5 * k as f64),
            tau: 10f64.powi(k),
        })
        .collect();
    let p = Prony::new(2e6, &terms).unwrap();
    // output times: coarse steps that straddle the history's kinks
    let outputs = [30.0, 100.0, 500.0, 1.01e4, 1.012e4, 1.015e4, 2e4, 1e5, 1e6];
    let mut state = RelaxationState::new(&p);
    let mut t = 0.0;
    let mut kinks: Vec<f64> = HISTORY.iter().map(|h| h.0).collect();
    kinks.extend(outputs);
    kinks.sort_by(f64::total_cmp);
    kinks.dedup();
    for &next in kinks.iter().filter(|&&k| k > 0.0) {
        state.step(&p, next - t, strain_at(next) - strain_at(t));
        t = next;
        if outputs.contains(&t) {
            let reference = hereditary_midpoint(&p, t, 200_000);
            let got = state.stress(&p);
            assert!(
                (got / reference - 1.0).abs() < 1e-6,
                "t = {t}: {got} vs {reference}"
            );
        }
    }
}
