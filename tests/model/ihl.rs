//! Rod seals at working speed: the inverse-hydrodynamic film (docs/model.md §3.4.1) against the
//! Reynolds equation and hand calculations, the starvation cap, the O-ring's gradient estimate
//! and the continuity of the stroke volumes across the transition from PY08 §8.

use crate::common::{PAPER, rel};
use proptest::prelude::*;
use sealsim::contact::PerssonContact;
use sealsim::dynamic::ihl::{
    ContactProfile, GradientSource, IhlCycle, InletGradients, SpeedRegime, TRANSITION_FACTOR,
    carried_film, film_thickness,
};
use sealsim::dynamic::{DragCoefficients, DragSettings, IhlInput, Motion, MotionSpec};
use sealsim::scenario::Scenario;
use std::f64::consts::PI;
use std::path::Path;

/// The largest `dp/dx = 6ηv (h − h*)/h³` (steady 1-D Reynolds with the flux `v h*/2` of the
/// pressure maximum) over films h, found numerically on a fine log grid refined by golden
/// section — no closed form used.
fn steepest_reynolds_gradient(eta: f64, v: f64, h_star: f64) -> f64 {
    let f = |h: f64| 6.0 * eta * v * (h - h_star) / h.powi(3);
    let (mut best, mut at) = (f64::MIN, h_star);
    for k in 0..2000 {
        let h = h_star * 10f64.powf(-0.1 + 2.0 * k as f64 / 1999.0);
        if f(h) > best {
            (best, at) = (f(h), h);
        }
    }
    let (mut a, mut b) = (at / 1.01, at * 1.01);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if f(c) > f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    f(0.5 * (a + b))
}

#[test]
fn the_film_is_the_one_the_reynolds_equation_allows_on_a_linear_flank() {
    // a trapezoid: linear flanks of known slope (6 MPa/mm fluid side, 2 MPa/mm air side)
    let (w_out, w_in) = (6e9, 2e9);
    let x = vec![0.0, 0.2e-3, 0.5e-3, 0.8e-3, 1.4e-3];
    let p = vec![0.0, w_out * 0.2e-3, w_out * 0.2e-3, w_out * 0.2e-3, 0.0];
    let g = ContactProfile::new(x, p).unwrap().inlet_gradients();
    assert!(rel(g.out_stroke, w_out) < 1e-12 && rel(g.in_stroke, w_in) < 1e-12);
    for (eta, v, w) in [(0.03, 0.2, w_out), (0.03, 0.2, w_in), (1e-3, 0.5, 3e8)] {
        let h = film_thickness(eta, v, w);
        // the closed form, h* = √(8ηv/(9w))
        assert!(rel(h, (8.0 * eta * v / (9.0 * w)).sqrt()) < 1e-15);
        // the steepest inlet gradient the Reynolds equation gives for that film is w …
        let g_max = steepest_reynolds_gradient(eta, v, h);
        assert!(rel(g_max, w) < 1e-9, "{g_max} vs {w}");
        // … so a thicker film could not climb the flank and a thinner one is not the largest
        assert!(steepest_reynolds_gradient(eta, v, h * 1.001) < w);
        assert!(steepest_reynolds_gradient(eta, v, h * 0.999) > w);
        assert_eq!(carried_film(h), h / 2.0);
    }
    // √v, 1/√w, √η
    let h = film_thickness(0.03, 0.2, 4e9);
    assert!(rel(film_thickness(0.03, 0.8, 4e9), 2.0 * h) < 1e-14);
    assert!(rel(film_thickness(0.03, 0.2, 16e9), 0.5 * h) < 1e-14);
    assert!(rel(film_thickness(0.12, 0.2, 4e9), 2.0 * h) < 1e-14);
    assert_eq!(film_thickness(0.03, 0.0, 4e9), 0.0);
}

#[test]
fn a_sampled_parabolic_flank_converges_to_its_edge_gradient() {
    // p = p_m (1 − (x/a)²) for |x| ≤ a: steepest at the edges, 2 p_m/a
    let (p_m, a) = (3e6, 1e-3);
    let mut last = f64::INFINITY;
    for n in [10usize, 20, 40, 80, 160] {
        let x: Vec<f64> = (0..=2 * n).map(|i| -a + a * i as f64 / n as f64).collect();
        let p: Vec<f64> = x.iter().map(|x| p_m * (1.0 - (x / a).powi(2))).collect();
        let g = ContactProfile::new(x, p).unwrap().inlet_gradients();
        let exact = 2.0 * p_m / a;
        // the first secant is p_m (2 − 1/n)/a: first order
        assert!(rel(g.out_stroke, exact * (1.0 - 0.5 / n as f64)) < 1e-9);
        assert!(rel(g.in_stroke, g.out_stroke) < 1e-9, "symmetric");
        let e = rel(g.out_stroke, exact);
        assert!(e < last / 1.9);
        last = e;
    }
}

#[test]
fn net_volume_per_cycle_against_a_hand_calculation() {
    // D = 50 mm rod, S = 0.1 m, η = 0.05 Pa·s, v = 0.2 m/s both ways, w_out = 1 MPa/mm,
    // w_in = 4 MPa/mm. By hand: h_out = √(8·0.05·0.2/(9·1e9)) = 2.98142e-6 m,
    // h_in = √(8·0.05·0.2/(9·4e9)) = 1.49071e-6 m, net = π·0.05·0.1·(h_out − h_in)/2
    // = 0.01570796 · 1.490712e-6/2 = 1.170802e-8 m³; carried out π·0.05·0.1·h_out/2
    // = 2.341605e-8 m³.
    let gradients = InletGradients {
        out_stroke: 1e9,
        in_stroke: 4e9,
    };
    let c = IhlCycle::new(
        gradients,
        GradientSource::Given,
        0.05,
        PI * 0.05,
        0.1,
        0.2,
        0.2,
        0.2e-6,
    );
    assert!(rel(c.out_film, 2.98142e-6) < 2e-6, "{}", c.out_film);
    assert!(rel(c.in_film, 1.49071e-6) < 2e-6, "{}", c.in_film);
    assert!(rel(c.out_volume, 2.341605e-8) < 5e-6, "{}", c.out_volume);
    assert!(
        rel(c.net_volume(), 1.170802e-8) < 5e-6,
        "{}",
        c.net_volume()
    );
    assert!(!c.starved);
    // the exact form used: π D S (h_out − h_in)/2
    assert!(
        rel(
            c.net_volume(),
            PI * 0.05 * 0.1 * (c.out_film - c.in_film) / 2.0
        ) < 1e-14
    );
    // film parameter: the thinner film over σ = 0.2 µm
    assert!(rel(c.film_parameter, 1.49071e-6 / 0.2e-6) < 2e-6);
}

#[test]
fn the_in_stroke_returns_no_more_than_the_out_stroke_carried() {
    // the same seal turned round: the air flank is the gentler one, h_in > h_out
    let c = IhlCycle::new(
        InletGradients {
            out_stroke: 4e9,
            in_stroke: 1e9,
        },
        GradientSource::Given,
        0.05,
        PI * 0.05,
        0.1,
        0.2,
        0.2,
        0.2e-6,
    );
    assert!(c.in_film > c.out_film);
    assert!(c.starved);
    assert_eq!(c.back_volume, c.out_volume);
    assert_eq!(c.net_volume(), 0.0);
}

proptest! {
    #[test]
    fn the_cycle_never_pumps_in_more_than_it_let_out(
        w_out in 1e7f64..1e11, w_in in 1e7f64..1e11,
        v_out in 1e-3f64..2.0, v_in in 1e-3f64..2.0,
        eta in 1e-3f64..1.0,
    ) {
        let c = IhlCycle::new(
            InletGradients { out_stroke: w_out, in_stroke: w_in },
            GradientSource::Given, eta, 0.15, 0.1, v_out, v_in, 1e-7,
        );
        prop_assert!(c.back_volume <= c.out_volume);
        prop_assert!(c.net_volume() >= 0.0);
        let expected = 0.15 * 0.1 * (c.out_film - c.in_film).max(0.0) / 2.0;
        prop_assert!((c.net_volume() - expected).abs() <= 1e-12 * c.out_volume);
        prop_assert_eq!(c.starved, c.in_film > c.out_film);
    }
}

#[test]
fn the_oring_estimate_is_the_hertz_slope_at_half_rise_with_the_fluid_pressure() {
    let (peak, b) = (2e6, 2.4e-3);
    let g = InletGradients::oring_estimate(peak, b, 0.0).unwrap();
    // the Hertz ellipse p = peak √(1 − (2x/b)²): its slope where p = peak/2, by finite
    // differences
    let x_half = 0.5 * b * (0.75f64).sqrt();
    let p = |x: f64| peak * (1.0 - (2.0 * x / b).powi(2)).sqrt();
    let dx = 1e-9;
    let slope = (p(x_half - dx) - p(x_half + dx)) / (2.0 * dx);
    assert!(
        rel(g.out_stroke, slope) < 1e-6,
        "{} vs {slope}",
        g.out_stroke
    );
    assert_eq!(g.out_stroke, g.in_stroke);
    // ΔP: the pressurised flank rises from ΔP only, the air flank from 0
    let e = InletGradients::oring_estimate(peak, b, 0.5e6).unwrap();
    assert!(rel(e.out_stroke, slope * 0.75) < 1e-6);
    assert!(rel(e.in_stroke, slope) < 1e-6);
    assert!(e.in_stroke > e.out_stroke, "the air side is the steeper");
    assert_eq!(InletGradients::oring_estimate(peak, b, 2.5e6), None);
}

/// The paper's flat seal (a leaking contact) with given inlet gradients, and its drag
/// coefficients: a stroke cycle evaluated directly at any speed.
fn paper_seal(gradients: InletGradients) -> (MotionSpec, DragCoefficients, f64, IhlInput) {
    let s = Scenario::from_str(PAPER, Path::new("paper.toml")).unwrap();
    let spec = MotionSpec {
        motion: Motion::Steady { speed: 0.0 },
        junction_position: 0.5,
        gradients: Some((gradients, GradientSource::Given)),
    };
    let seal = spec.seal(
        s.problem.material,
        s.problem.seal,
        s.problem.fluid.viscosity,
        s.problem.shape_factor,
    );
    let contact = PerssonContact::new(s.problem.spectrum.clone(), s.problem.contact);
    let k = DragCoefficients::compute(&contact, &seal, &DragSettings::default());
    let static_rate = k.static_leak_rate(s.problem.fluid.pressure_difference);
    let ihl = IhlInput {
        gradients: spec.gradients,
        viscosity: s.problem.fluid.viscosity,
        sealing_length: s.problem.seal.length,
        roughness: s.problem.spectrum.rms_roughness(),
    };
    (spec, k, static_rate, ihl)
}

fn stroke_at(spec: &MotionSpec, v: f64) -> MotionSpec {
    MotionSpec {
        motion: Motion::Stroke {
            stroke: 0.05,
            out_speed: v,
            in_speed: v,
        },
        ..*spec
    }
}

#[test]
fn the_stroke_volumes_are_continuous_across_the_transition() {
    // steep gradients: the films stay below the paper's 10 µm rms roughness up to high speeds,
    // so the onset is PY08's speed bound
    for gradients in [
        InletGradients {
            out_stroke: 1e12,
            in_stroke: 3e12,
        },
        InletGradients {
            out_stroke: 3e12,
            in_stroke: 1e12,
        },
    ] {
        let (spec, k, q_s, ihl) = paper_seal(gradients);
        let v_b = k.speed_bound;
        assert!(v_b.is_finite() && v_b > 0.0);
        let at = |v: f64| stroke_at(&spec, v).evaluate(&k, q_s, &ihl);
        let onset = at(v_b).ihl.unwrap().film_onset_speeds;
        assert!(onset.0 > v_b && onset.1 > v_b, "{onset:?} vs {v_b}");
        let eps = 1e-9;
        for edge in [v_b, TRANSITION_FACTOR * v_b] {
            let (lo, hi) = (at(edge * (1.0 - eps)), at(edge * (1.0 + eps)));
            let (a, b) = (lo.cycle.unwrap(), hi.cycle.unwrap());
            let scale = a.out_volume.abs().max(a.in_volume.abs());
            for (x, y) in [
                (a.out_volume, b.out_volume),
                (a.in_volume, b.in_volume),
                (a.net_volume, b.net_volume),
            ] {
                assert!((x - y).abs() <= 1e-6 * scale, "at {edge}: {x} vs {y}");
            }
        }
        // below the band: the low-speed cycle (net = static × period); above: IHL alone
        let low = at(0.5 * v_b);
        assert_eq!(low.regime, SpeedRegime::LowSpeed);
        let c = low.cycle.unwrap();
        assert!(rel(c.net_volume, c.static_volume) < 1e-12);
        let mid = at(3.0 * v_b);
        assert_eq!(mid.regime, SpeedRegime::Transition);
        let high = at(20.0 * v_b);
        assert_eq!(high.regime, SpeedRegime::Ihl);
        let (c, i) = (high.cycle.unwrap(), high.ihl.unwrap());
        assert!(rel(c.out_volume, i.out_volume) < 1e-14);
        assert!(rel(c.net_volume, i.net_volume()) < 1e-9 || c.net_volume == 0.0);
        // every speed: the in-stroke never returns more than went out
        for k in 0..60 {
            let v = v_b * 10f64.powf(-1.0 + 3.0 * k as f64 / 59.0);
            let c = at(v).cycle.unwrap();
            assert!(
                c.in_volume >= -c.out_volume && c.net_volume >= 0.0,
                "{v}: {c:?}"
            );
        }
    }
}

#[test]
fn a_film_thicker_than_the_roughness_starts_the_transition_below_the_speed_bound() {
    // gentle gradients: the film reaches the 10 µm rms roughness below PY08's bound
    let (spec, k, q_s, ihl) = paper_seal(InletGradients {
        out_stroke: 1e3,
        in_stroke: 2e3,
    });
    let at = |v: f64| stroke_at(&spec, v).evaluate(&k, q_s, &ihl);
    let i = at(1.0).ihl.unwrap();
    let v_lambda = i.film_onset_speeds.0.min(i.film_onset_speeds.1);
    assert!(v_lambda < k.speed_bound, "{v_lambda} vs {}", k.speed_bound);
    // the film at the onset is the roughness (Λ = 1 for the thinner stroke's film)
    let at_onset = at(i.film_onset_speeds.1).ihl.unwrap();
    assert!(rel(at_onset.in_film, ihl.roughness) < 1e-12);
    assert_eq!(at(0.9 * v_lambda).regime, SpeedRegime::LowSpeed);
    assert_ne!(
        at(1.1 * i.film_onset_speeds.0).regime,
        SpeedRegime::LowSpeed
    );
}
