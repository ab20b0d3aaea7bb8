//! Reciprocating seals at low speed (PY08 §8, docs/model.md §3.4): the paper's wiper example, the
//! static limit, linearity in v0, convergence of the integral I, and properties over inputs.

use crate::common::rel;
use proptest::prelude::*;
use sealsim::contact::effective_medium::FoldedGaussian;
use sealsim::contact::{
    ContactSettings, CriticalJunction, Elastic, Junction, PerssonContact, SeparationDistribution,
};
use sealsim::dynamic::{
    DragCoefficients, DragSettings, ReciprocatingSeal, drag_leak_rate, leak_rate,
    probability_above, separation_integral, stroke_cycle,
};
use sealsim::fluid::Fluid;
use sealsim::leak::FlatSeal;
use sealsim::surface::Spectrum;

const RUBBER: Elastic = Elastic {
    youngs_modulus: 10e6,
    poisson_ratio: 0.5,
};

fn contact(h_rms: f64, hurst: f64) -> PerssonContact {
    let sp = Spectrum::self_affine(h_rms, hurst, 1e4, 7.8e9, None).unwrap();
    PerssonContact::new(sp, ContactSettings::default())
}

/// The paper's wiper (§8): P0 ≈ 0.2 MPa, L ≈ 0.1 mm, water.
fn wiper(p0: f64) -> ReciprocatingSeal {
    ReciprocatingSeal {
        material: RUBBER,
        seal: FlatSeal {
            nominal_pressure: p0,
            width: 0.1e-3,
            length: 1.0,
        },
        viscosity: 1e-3,
        shape_factor: 1.0,
        junction_position: 0.5,
    }
}

fn within_factor(x: f64, target: f64, factor: f64) -> bool {
    x > target / factor && x < target * factor
}

#[test]
fn paper_wiper_example() {
    let c = contact(2e-6, 0.8);
    let seal = wiper(0.2e6);
    let k = DragCoefficients::compute(&c, &seal, &DragSettings::default());
    let j = *k.junction.leaking().expect("the paper's wiper leaks");
    // paper's rough form of the bound, E u_c³/(L η λ_c)
    let rough_bound = RUBBER.youngs_modulus * j.u_c.powi(3) / (0.1e-3 * 1e-3 * j.lambda_c);
    eprintln!("PY08 §8 wiper (h_rms 2 µm, H 0.8, q0 1e4, q1 7.8e9, P0 0.2 MPa, E 10 MPa, ν 0.5,");
    eprintln!("            L 0.1 mm, η 1e-3 Pa·s, α 1, junction at the centre):");
    eprintln!("  ζc           = {:.4}", j.zeta_c);
    eprintln!("  u_c          = {:.4e} m   (paper ≈ 0.1 µm)", j.u_c);
    eprintln!(
        "  λ_c          = {:.4e} m   (paper ≈ 10 µm; sealsim λc = 2π/(ζc q0))",
        j.lambda_c
    );
    eprintln!(
        "  I            = {:.4}        (paper ≈ 0.1–0.2)",
        k.integral_i
    );
    eprintln!("  β = αI/2     = {:.4}        (paper ≈ 0.1)", k.beta);
    eprintln!(
        "  d = β u_c    = {:.4e} m   (paper ≈ 0.01 µm)",
        k.film_thickness
    );
    eprintln!("  M            = {:.4e} m³/(Pa·s)", k.m);
    eprintln!("  B_a = B_b    = {:.4e} Pa·s/m", k.b_a);
    eprintln!(
        "  v_max (eq17) = {:.4e} m/s (paper ≈ 1 cm/s)",
        k.speed_bound
    );
    eprintln!("  E u_c³/(Lηλ_c) = {rough_bound:.4e} m/s (the paper's ≈ form, sealsim λ_c)");

    assert!(within_factor(j.u_c, 0.1e-6, 3.0), "u_c = {}", j.u_c);
    assert!(
        k.integral_i > 0.1 / 3.0 && k.integral_i < 0.2 * 3.0,
        "I = {}",
        k.integral_i
    );
    assert!(within_factor(k.beta, 0.1, 3.0), "β = {}", k.beta);
    assert!(
        within_factor(k.film_thickness, 0.01e-6, 3.0),
        "d = {}",
        k.film_thickness
    );
    assert!(
        within_factor(k.speed_bound, 0.01, 3.0),
        "v_max = {}",
        k.speed_bound
    );
    // definitions hold together
    assert!(rel(k.beta, 0.5 * k.integral_i) < 1e-15);
    assert!(rel(k.film_thickness, k.beta * j.u_c) < 1e-15);
    let v0 = 1e-3;
    // d = Q̇/(L_y v0) at ΔP = 0 (eqs. 15–16)
    let d = drag_leak_rate(&k, v0) / (seal.seal.length * v0);
    assert!(
        rel(d, k.film_thickness) < 1e-12,
        "{d} vs {}",
        k.film_thickness
    );
    // the bound's two forms
    let explicit = RUBBER.youngs_modulus * j.u_c.powi(3)
        / (6.0 * seal.seal.width * seal.viscosity * j.lambda_c * k.integral_i);
    assert!(rel(k.speed_bound, explicit) < 1e-12);
}

#[test]
fn zero_speed_is_the_static_leak() {
    let c = contact(2e-6, 0.8);
    for p0 in [0.05e6, 0.2e6, 0.5e6, 1e6] {
        for (width, length, alpha, pos) in [(1e-3, 1e-3, 1.0, 0.5), (2e-4, 0.3, 0.7, 0.1)] {
            let seal = ReciprocatingSeal {
                seal: FlatSeal {
                    nominal_pressure: p0,
                    width,
                    length,
                },
                shape_factor: alpha,
                junction_position: pos,
                ..wiper(p0)
            };
            let k = DragCoefficients::compute(&c, &seal, &DragSettings::default());
            let u_c = k.junction.leaking().unwrap().u_c;
            let fluid = Fluid {
                viscosity: seal.viscosity,
                pressure_difference: 0.01e6,
                law: sealsim::fluid::ViscosityLaw::Constant,
                gas: None,
            };
            // PY08 eqs. 1–3 written out: (L_y/L_x) α u_c³ ΔP/(12η)
            let stat = length / width * alpha * u_c.powi(3) * fluid.pressure_difference
                / (12.0 * fluid.viscosity);
            let dynamic = leak_rate(&k, fluid.pressure_difference, 0.0);
            assert!(stat > 0.0);
            assert!(rel(dynamic, stat) < 1e-12, "P0 = {p0}: {dynamic} vs {stat}");
            assert_eq!(drag_leak_rate(&k, 0.0), 0.0);
        }
    }
}

#[test]
fn leak_is_linear_in_speed() {
    let c = contact(2e-6, 0.8);
    let k = DragCoefficients::compute(&c, &wiper(0.2e6), &DragSettings::default());
    assert!(k.b_a > 0.0 && k.b_b > 0.0);
    assert!(rel(k.b_a, k.b_b) < 1e-15, "symmetric seal");
    let dp = 0.01e6;
    let q0 = leak_rate(&k, dp, 0.0);
    let slope = drag_leak_rate(&k, 1.0);
    assert!(slope > 0.0);
    for v in [-1e-2, -1e-4, 1e-6, 3e-3, 1e-2] {
        let q = leak_rate(&k, dp, v);
        assert!(rel(q, q0 + slope * v) < 1e-12, "v = {v}: {q}");
        assert!(rel(drag_leak_rate(&k, v), slope * v) < 1e-12);
        // out-stroke leaks more, in-stroke less
        assert_eq!(q > q0, v > 0.0);
    }
    // the split of B between the two sides moves with the junction, the sum does not
    for pos in [0.0, 0.2, 0.9, 1.0] {
        let seal = ReciprocatingSeal {
            junction_position: pos,
            ..wiper(0.2e6)
        };
        let kp = DragCoefficients::compute(&c, &seal, &DragSettings::default());
        assert!(rel(kp.b(), k.b()) < 1e-12);
        assert!(rel(kp.b_a, pos * k.b()) < 1e-12 || (pos == 0.0 && kp.b_a == 0.0));
        assert!(rel(leak_rate(&kp, dp, 2e-3), leak_rate(&k, dp, 2e-3)) < 1e-12);
    }
}

#[test]
fn integral_converges_under_refinement() {
    let c = contact(2e-6, 0.8);
    for p0 in [0.05e6, 0.2e6, 1e6] {
        let seal = wiper(p0);
        let s = seal.reduced_pressure();
        let u_c = c.critical_junction(s).leaking().unwrap().u_c;
        let base = DragSettings::default();
        let p = SeparationDistribution::persson(&c, s, base.distribution);
        let i1 = separation_integral(&p, u_c, &base);
        let i2 = separation_integral(&p, u_c, &base.refined(2));
        let i4 = separation_integral(&p, u_c, &base.refined(4));
        eprintln!(
            "P0 = {p0:e}: I = {i1:.10} | ×2 {:.2e} | ×4 {:.2e}",
            rel(i1, i4),
            rel(i2, i4)
        );
        assert!(rel(i1, i4) < 1e-6 && rel(i2, i4) < 1e-6);
        // P(u) itself (the ζ nodes): looser, it is the effective-medium level's accuracy
        let fine = DragSettings {
            distribution: base.distribution.refined(2),
            ..base
        };
        let pf = SeparationDistribution::persson(&c, s, fine.distribution);
        let i_fine = separation_integral(&pf, u_c, &fine);
        eprintln!("          P(u) nodes ×2: {:.2e}", rel(i1, i_fine));
        assert!(rel(i1, i_fine) < 1e-3);
        assert!(i1 > 0.0 && i1 <= 1.0);
    }
}

#[test]
fn integral_matches_closed_and_brute_force_forms() {
    let u_c = 1e-7;
    // a point mass at 2 u_c: I = 1/4 exactly, whatever else lies below u_c
    let p = SeparationDistribution::new(
        0.3,
        vec![
            FoldedGaussian {
                weight: 0.2,
                center: 2e-7,
                width: 0.0,
            },
            FoldedGaussian {
                weight: 0.5,
                center: 0.5e-7,
                width: 0.0,
            },
        ],
    );
    let s = DragSettings::default();
    assert!(rel(separation_integral(&p, u_c, &s), 0.25) < 1e-15);
    assert!(rel(probability_above(&p, u_c), 0.2) < 1e-15);

    // two folded Gaussians against a brute-force midpoint rule in u
    let comps = vec![
        FoldedGaussian {
            weight: 0.4,
            center: 1.5e-7,
            width: 0.8e-7,
        },
        FoldedGaussian {
            weight: 0.3,
            center: 0.2e-7,
            width: 0.6e-7,
        },
    ];
    let p = SeparationDistribution::new(0.3, comps);
    let (mut num, mut den) = (0.0, 0.0);
    let (hi, n) = (2e-6, 2_000_000);
    let du = (hi - u_c) / n as f64;
    for k in 0..n {
        let u = u_c + (k as f64 + 0.5) * du;
        let rho = p.density(u);
        num += rho * (u_c / u).powi(2) * du;
        den += rho * du;
    }
    let brute = num / den;
    let quad = separation_integral(&p, u_c, &s);
    assert!(rel(quad, brute) < 1e-6, "{quad} vs {brute}");
    assert!(rel(probability_above(&p, u_c), den) < 1e-6);
    // nothing above u_c: 0, not NaN
    let below = SeparationDistribution::new(
        0.9,
        vec![FoldedGaussian {
            weight: 0.1,
            center: 1e-9,
            width: 1e-10,
        }],
    );
    assert_eq!(separation_integral(&below, u_c, &s), 0.0);
    assert_eq!(separation_integral(&p, 0.0, &s), 0.0);
}

#[test]
fn sealed_junction_has_no_drag() {
    let c = contact(2e-6, 0.8);
    let p0 = 1.1 * c.sealing_reduced_pressure() * RUBBER.effective_modulus();
    let seal = wiper(p0);
    let k = DragCoefficients::compute(&c, &seal, &DragSettings::default());
    assert_eq!(k.junction, Junction::Sealed);
    for x in [
        k.m,
        k.b_a,
        k.b_b,
        k.integral_i,
        k.beta,
        k.film_thickness,
        leak_rate(&k, 1e5, 1e-2),
        drag_leak_rate(&k, -1e-2),
    ] {
        assert_eq!(x, 0.0);
    }
    assert!(k.speed_bound.is_infinite() && k.speed_bound > 0.0);
    let cycle = stroke_cycle(&k, 1e5, 0.1, 0.2, 0.05).unwrap();
    assert_eq!(cycle.net_volume, 0.0);
    assert!(!cycle.net_volume.is_nan() && cycle.within_speed_bound);
}

#[test]
fn vanishing_junction_gives_no_nan() {
    // within rounding of the sealing pressure the critical junction can be 1e-200 m high
    let seal = wiper(0.2e6);
    for u_c in [1e-200, 1e-160, 1e-120, 1e-30] {
        let j = CriticalJunction {
            zeta_c: 1e5,
            lambda_c: 2.0 * std::f64::consts::PI / 1e9,
            u_c,
            ubar_c: 0.5 * u_c,
            hrms_c: u_c,
        };
        let k = DragCoefficients::from_integral(&j, 0.1, &seal);
        for x in [
            k.m,
            k.b_a,
            k.b_b,
            k.film_thickness,
            k.speed_bound,
            leak_rate(&k, 1e5, 1e-2),
            drag_leak_rate(&k, -1e-2),
        ] {
            assert!(x.is_finite(), "u_c = {u_c}: {k:?}");
        }
        assert!(k.film_thickness < u_c && k.speed_bound >= 0.0);
        let cy = stroke_cycle(&k, 1e5, 1e-3, 1e-3, 0.1).unwrap();
        assert!(cy.net_volume.is_finite() && cy.drag_volume.is_finite());
    }
}

#[test]
fn stroke_cycle_volumes() {
    let c = contact(2e-6, 0.8);
    let seal = ReciprocatingSeal {
        seal: FlatSeal {
            nominal_pressure: 0.2e6,
            width: 0.1e-3,
            length: 0.1,
        },
        ..wiper(0.2e6)
    };
    let k = DragCoefficients::compute(&c, &seal, &DragSettings::default());
    let (dp, v_out, v_in, stroke) = (0.01e6, 2e-3, 5e-4, 0.05);
    let cy = stroke_cycle(&k, dp, v_out, v_in, stroke).unwrap();
    let film = seal.seal.length * k.film_thickness * stroke;
    assert!(rel(cy.drag_volume, film) < 1e-12);
    assert!(rel(cy.period, stroke / v_out + stroke / v_in) < 1e-15);
    assert!(rel(cy.out_volume, leak_rate(&k, dp, v_out) * stroke / v_out) < 1e-15);
    assert!(rel(cy.in_volume, leak_rate(&k, dp, -v_in) * stroke / v_in) < 1e-15);
    assert!(
        rel(
            cy.out_volume,
            cy.static_volume * (stroke / v_out) / cy.period + film
        ) < 1e-12
    );
    // the drag volumes cancel: net = static leak over the cycle
    assert!(rel(cy.net_volume, cy.static_volume) < 1e-9);
    assert!(cy.within_speed_bound);
    eprintln!(
        "cycle: out {:.3e} m³, in {:.3e} m³, net {:.3e} m³, film L_y d S {:.3e} m³",
        cy.out_volume, cy.in_volume, cy.net_volume, cy.drag_volume
    );
    // a wiper (ΔP = 0) pumps out and back the same film
    let w = stroke_cycle(&k, 0.0, v_out, v_in, stroke).unwrap();
    assert!(rel(w.out_volume, film) < 1e-12 && rel(-w.in_volume, film) < 1e-12);
    assert!(w.net_volume.abs() <= 1e-12 * film);
    // too fast
    let fast = stroke_cycle(&k, dp, 2.0 * k.speed_bound, v_in, stroke).unwrap();
    assert!(!fast.within_speed_bound);
    // invalid input
    assert!(stroke_cycle(&k, dp, 0.0, v_in, stroke).is_none());
    assert!(stroke_cycle(&k, dp, v_out, -1.0, stroke).is_none());
    assert!(stroke_cycle(&k, dp, v_out, v_in, f64::NAN).is_none());
}

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn drag_is_positive_finite_and_the_film_thinner_than_the_gap(
        p0 in log_uniform(0.01e6, 3e6),
        h_rms in log_uniform(0.2e-6, 20e-6),
        hurst in 0.5..0.95f64,
        alpha in 0.3..1.9f64,
    ) {
        let c = contact(h_rms, hurst);
        let seal = ReciprocatingSeal { shape_factor: alpha, ..wiper(p0) };
        let k = DragCoefficients::compute(&c, &seal, &DragSettings::default());
        match k.junction {
            Junction::Leaking(j) => {
                prop_assert!(k.b_a > 0.0 && k.b_a.is_finite(), "B_a = {}", k.b_a);
                prop_assert!(k.b_b > 0.0 && k.b_b.is_finite(), "B_b = {}", k.b_b);
                prop_assert!(k.integral_i > 0.0 && k.integral_i <= 1.0 + 1e-12, "I = {}", k.integral_i);
                prop_assert!(k.film_thickness > 0.0 && k.film_thickness < j.u_c,
                    "d = {} u_c = {}", k.film_thickness, j.u_c);
                prop_assert!(k.speed_bound > 0.0 && !k.speed_bound.is_nan());
                prop_assert!(leak_rate(&k, 0.01e6, 1e-3).is_finite());
            }
            Junction::Sealed => {
                prop_assert_eq!(k.b(), 0.0);
                prop_assert_eq!(k.film_thickness, 0.0);
            }
        }
    }
}
