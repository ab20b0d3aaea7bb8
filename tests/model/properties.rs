//! Property tests of the static engine over wide parameter ranges, including the extremes
//! the issue names: P0 from 1 Pa to 1 GPa, H from 0.05 to 0.95, q1/q0 from 10 to 1e8,
//! h_rms from 1 nm to 1 mm, ν from 0 to 0.5.

use proptest::prelude::*;
use sealsim::contact::{ContactSettings, Elastic, Junction};
use sealsim::fluid::Fluid;
use sealsim::leak::{Fidelity, FlatSeal, LeakPoint, SealState, StaticProblem, StaticSolver};
use sealsim::surface::Spectrum;

#[derive(Debug, Clone, Copy)]
struct Params {
    h_rms: f64,
    hurst: f64,
    q0: f64,
    ratio: f64,
    youngs: f64,
    nu: f64,
}

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..=hi.ln()).prop_map(f64::exp)
}

fn params() -> impl Strategy<Value = Params> {
    (
        log_uniform(1e-9, 1e-3),
        0.05..=0.95f64,
        log_uniform(1e2, 1e6),
        log_uniform(10.0, 1e8),
        log_uniform(1e5, 1e10),
        0.0..=0.5f64,
    )
        .prop_map(|(h_rms, hurst, q0, ratio, youngs, nu)| Params {
            h_rms,
            hurst,
            q0,
            ratio,
            youngs,
            nu,
        })
}

fn solver(p: Params, fidelity: Fidelity) -> StaticSolver {
    let problem = StaticProblem {
        material: Elastic {
            youngs_modulus: p.youngs,
            poisson_ratio: p.nu,
        },
        spectrum: Spectrum::self_affine(p.h_rms, p.hurst, p.q0, p.q0 * p.ratio, None).unwrap(),
        fluid: Fluid {
            viscosity: 1e-3,
            pressure_difference: 1e4,
            law: sealsim::fluid::ViscosityLaw::Constant,
            gas: None,
        },
        seal: FlatSeal {
            nominal_pressure: 1e5,
            width: 1e-3,
            length: 1e-3,
        },
        contact: ContactSettings::default(),
        shape_factor: 1.0,
    };
    StaticSolver::new(problem, fidelity)
}

fn check_point(pt: &LeakPoint) -> Result<(), TestCaseError> {
    prop_assert!(
        pt.leak_rate.is_finite() && pt.leak_rate >= 0.0,
        "leak rate {}",
        pt.leak_rate
    );
    match pt.junction {
        Junction::Leaking(j) => {
            for v in [j.zeta_c, j.lambda_c, j.u_c, j.ubar_c, j.hrms_c] {
                prop_assert!(v.is_finite(), "non-finite in {j:?}");
            }
            prop_assert!(j.zeta_c >= 1.0);
            prop_assert!(
                j.u_c > j.ubar_c && j.ubar_c > 0.0,
                "u_c > ū_c > 0 fails: {j:?}"
            );
            // a percolating channel leaks, unless its gap is narrower than a molecule (§8.1)
            prop_assert!(
                pt.leak_rate > 0.0 || pt.state == SealState::BelowMolecule || j.u_c < 1e-100,
                "{pt:?}"
            );
        }
        // sealed where the asperities carry most (the outlet, P0): the fluid pressure relieves
        // the rest of the width, and the flow leaves across the contact's outlet edge (docs/model.md
        // §3.6) — a leak only in the leaking state
        Junction::Sealed => prop_assert!(
            pt.leak_rate == 0.0 || pt.state != SealState::Sealed,
            "{pt:?}"
        ),
    }
    Ok(())
}

proptest! {
    // a fixed seed: the same 200 cases on every run, so that CI is reproducible (a random seed
    // found the known defect below once)
    #![proptest_config(ProptestConfig {
        cases: 200,
        rng_seed: proptest::test_runner::RngSeed::Fixed(1),
        ..ProptestConfig::default()
    })]

    #[test]
    fn every_output_is_finite_over_the_extremes(p in params(), p0 in log_uniform(1.0, 1e9)) {
        for fidelity in [Fidelity::Exact, Fidelity::Table] {
            check_point(&solver(p, fidelity).evaluate(p0))?;
        }
        // the end points themselves
        let exact = solver(p, Fidelity::Exact);
        check_point(&exact.evaluate(1.0))?;
        check_point(&exact.evaluate(1e9))?;
    }

    #[test]
    fn leak_rate_does_not_increase_with_pressure(p in params(), a in log_uniform(1.0, 1e9), b in log_uniform(1.0, 1e9)) {
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        let s = solver(p, Fidelity::Exact);
        let (at_lo, at_hi) = (s.evaluate(lo), s.evaluate(hi));
        // lifted off (P0 ≤ ΔP = 1e4 Pa) the seal is open and the number is the onset's lower
        // bound (docs/model.md §3.6): monotonicity is a property of the closed interface
        prop_assert_eq!(at_lo.state == SealState::LiftOff, lo <= 1e4);
        prop_assert_eq!(at_hi.state == SealState::LiftOff, hi <= 1e4);
        if lo > 1e4 {
            let (q_lo, q_hi) = (at_lo.leak_rate, at_hi.leak_rate);
            prop_assert!(q_hi <= q_lo * (1.0 + 1e-9), "Q({hi}) = {q_hi} > Q({lo}) = {q_lo}");
        }
    }

    /// Around the sealing pressure, where the critical gaps fall below a molecule (docs/model.md
    /// §3.6, §8.1): more load never leaks more, and never turns a sealed interface into a
    /// leaking one; it leaks exactly when its rate is positive.
    #[test]
    fn near_sealing_more_load_never_unseals(p in params(), a in 0.2..1.5f64, b in 0.2..1.5f64) {
        for fidelity in [Fidelity::RuleOfThumb, Fidelity::Table] {
            let s = solver(p, fidelity);
            let e_star = Elastic { youngs_modulus: p.youngs, poisson_ratio: p.nu }.effective_modulus();
            let seal = s.path().exact().sealing_reduced_pressure() * e_star;
            let (lo, hi) = if a < b { (a * seal, b * seal) } else { (b * seal, a * seal) };
            if lo <= 1e4 {
                continue;
            }
            let (at_lo, at_hi) = (s.evaluate(lo), s.evaluate(hi));
            for pt in [&at_lo, &at_hi] {
                prop_assert_eq!(pt.state == SealState::Leaking, pt.leak_rate > 0.0, "{:?}", pt);
            }
            prop_assert!(
                at_hi.leak_rate <= at_lo.leak_rate * (1.0 + 1e-9),
                "{:?}: {:?} after {:?}", fidelity, at_hi, at_lo
            );
            prop_assert!(
                !(at_lo.state.is_sealed() && at_hi.state == SealState::Leaking),
                "{:?}: {:?} after {:?}", fidelity, at_hi, at_lo
            );
        }
    }

    #[test]
    fn leak_rate_does_not_decrease_with_roughness(p in params(), f in 1.0..100.0f64, p0 in log_uniform(1.0, 1e9)) {
        let rougher = Params { h_rms: (p.h_rms * f).min(1e-3), ..p };
        let q_smooth = solver(p, Fidelity::Exact).evaluate(p0).leak_rate;
        let q_rough = solver(rougher, Fidelity::Exact).evaluate(p0).leak_rate;
        // below one molecule a second the continuum figure means nothing (docs/model.md §15.2)
        // and a critical gap below a molecule is sealed (§9.3): a rougher face whose gap is
        // still below a molecule reads 0 where the smoother one kept, say, 1e-69 m³/s
        let one_molecule_per_second = 3.0e-29;
        prop_assert!(
            q_rough >= q_smooth * (1.0 - 1e-9) || q_smooth < one_molecule_per_second,
            "{q_rough} < {q_smooth}"
        );
    }
}

/// The surface a random seed of this file's proptest found (docs/model.md §3.6, §8.1): 3.7 nm rms,
/// so every critical gap of its contact at 10–60 kPa is below a water molecule (0.31 nm) but
/// those of the least-loaded strips, relieved by the fluid pressure.
fn sub_molecular_surface() -> Params {
    Params {
        h_rms: 3.736678053346745e-9,
        hurst: 0.3980502758485178,
        q0: 2343.777197387261,
        ratio: 48695.07713461603,
        youngs: 17401446.51325103,
        nu: 0.0,
    }
}

/// The molecular tolerance of docs/model.md §8.1 on every strip (§3.6). Below 21 kPa the
/// outlet's channel percolates with a gap below a molecule; at 22.25 kPa the outlet no longer
/// percolates, and the strips the fluid pressure relieves percolate below a molecule too. When
/// the tolerance was applied to the outlet's junction alone those strips still conducted: the
/// state read `leaking` with Q = 3.7e-27 m³/s at 22.25 kPa after `sealed` at 21 kPa.
#[test]
fn a_sub_molecular_strip_does_not_leak_where_the_outlet_is_sealed() {
    let s = solver(sub_molecular_surface(), Fidelity::Exact);
    let (lo, hi) = (s.evaluate(21_000.0), s.evaluate(22_251.185876516138));
    assert_eq!(lo.state, SealState::BelowMolecule);
    assert!(hi.leak_rate <= lo.leak_rate, "{hi:?} after {lo:?}");
    assert!(hi.state.is_sealed(), "{hi:?}");
    // the outlet does not percolate; the relieved strips do, below a molecule: the molecule
    // is what seals
    assert_eq!(hi.junction, Junction::Sealed);
    assert_eq!(hi.state, SealState::BelowMolecule);
}

/// The review's sweep (`sealsim leak strip.toml --sweep 10kPa..60kPa --points 21`, N7) at every
/// analytic level: past lift-off the leak never rises with the load, the state never returns
/// from sealed to leaking, it leaks exactly when its rate is positive, and a sealed state keeps
/// its leak at 0. On the outlet-only rule every level failed: `leaking` at 22.4–29.3 kPa
/// (3.3e-27 … 3.2e-33 m³/s; the effective medium at 28–36 kPa) after `sealed` below.
#[test]
fn a_load_sweep_never_goes_from_sealed_back_to_leaking_at_any_analytic_level() {
    let (dp, from, to, points): (f64, f64, f64, usize) = (1e4, 1e4, 6e4, 21);
    for fidelity in [
        Fidelity::RuleOfThumb,
        Fidelity::Table,
        Fidelity::Exact,
        Fidelity::EffectiveMedium,
    ] {
        let s = solver(sub_molecular_surface(), fidelity);
        let mut last: Option<LeakPoint> = None;
        let mut seen = Vec::new();
        for k in 0..points {
            let p0 = from * (to / from).powf(k as f64 / (points - 1) as f64);
            let pt = s.evaluate(p0);
            assert!(pt.leak_rate.is_finite() && pt.leak_rate >= 0.0, "{pt:?}");
            assert_eq!(
                pt.state == SealState::LiftOff,
                p0 <= dp,
                "{fidelity:?} {pt:?}"
            );
            if pt.state == SealState::LiftOff {
                continue;
            }
            assert_eq!(
                pt.state == SealState::Leaking,
                pt.leak_rate > 0.0,
                "{fidelity:?} {pt:?}"
            );
            if let Some(before) = last {
                assert!(
                    pt.leak_rate <= before.leak_rate,
                    "{fidelity:?}: {pt:?} after {before:?}"
                );
                assert!(
                    !(before.state.is_sealed() && pt.state == SealState::Leaking),
                    "{fidelity:?}: {pt:?} after {before:?}"
                );
            }
            seen.push(pt.state);
            last = Some(pt);
        }
        // the sweep crosses the cut: it leaks just past lift-off and is sealed by the molecule
        // (not by the loss of percolation) well before 60 kPa
        assert_eq!(
            seen.first(),
            Some(&SealState::Leaking),
            "{fidelity:?} {seen:?}"
        );
        assert!(
            seen.contains(&SealState::BelowMolecule),
            "{fidelity:?} {seen:?}"
        );
        assert!(
            seen.last().is_some_and(|s| s.is_sealed()),
            "{fidelity:?} {seen:?}"
        );
    }
}
