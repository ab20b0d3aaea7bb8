//! The seal-life time loop against closed forms, invariances and refinement (issue 4).

use sealsim::contact::ContactSettings;
use sealsim::fluid::Fluid;
use sealsim::leak::Fidelity;
use sealsim::material::shift::Cycle;
use sealsim::material::{Material, Prony, PronyTerm, Shift, Status, TemperatureHistory};
use sealsim::seal::SealGeometry;
use sealsim::simulate::{
    AsperityModulus, FailureCriteria, FailureMode, GrooveInterface, LifeProblem, Loading,
    SealState, TimeGrid, simulate,
};
use sealsim::surface::Spectrum;
use sealsim::validity::Limit;

const TREF: f64 = 296.15;
const WLF: Shift = Shift::Wlf {
    reference: TREF,
    c1: 8.86,
    c2: 101.6,
};
const YEAR: f64 = 365.25 * 86400.0;

fn material(long_term: f64, terms: &[(f64, f64)], shift: Shift) -> Material {
    let terms: Vec<PronyTerm> = terms
        .iter()
        .map(|&(modulus, tau)| PronyTerm { modulus, tau })
        .collect();
    Material {
        name: "test".into(),
        status: Status::User,
        prony: Prony::new(long_term, &terms).unwrap(),
        poisson_ratio: 0.5,
        shift,
        glass_transition: None,
        thermal_expansion: None,
        glassy_thermal_expansion: None,
        ageing: None,
        ageing_basis: None,
        provenance: Vec::new(),
    }
}

fn oring_problem(material: Material) -> LifeProblem {
    LifeProblem {
        material,
        asperity_modulus: AsperityModulus::Relaxed,
        spectrum: Spectrum::self_affine(10e-6, 0.8, 1e4, 1e9, None).unwrap(),
        contact: ContactSettings::default(),
        shape_factor: 1.0,
        fluid: Fluid {
            viscosity: 1e-3,
            pressure_difference: 1e5,
        },
        geometry: SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze: 0.2,
        },
        gland: None,
        groove: GrooveInterface::None,
        energisation_factor: 0.0,
        loading: Loading::Displacement,
        // an instantaneous installation: the closed forms below start from E0
        installation_time: 0.0,
        environment: TemperatureHistory::constant(TREF),
        thermal_strain: None,
        ageing: None,
        failure: FailureCriteria::default(),
        time: TimeGrid {
            start: 1.0,
            duration: 30.0 * YEAR,
            points_per_decade: 20.0,
        },
        fidelity: Fidelity::Table,
        strips: 16,
        contamination: None,
        motion: None,
    }
}

fn nbr_like() -> Material {
    let terms: Vec<(f64, f64)> = (-2..=10).map(|k| (0.4e6, 10f64.powi(k))).collect();
    material(3e6, &terms, WLF)
}

#[test]
fn follow_modulus_keeps_the_leak_rate_constant() {
    // Linear-viscoelastic invariance (docs/model.md §6): P0 and the asperity modulus relax alike
    // — as long as the fluid pressure in the interface, which does not relax, is negligible
    // (ΔP/p_max ≈ 1e-9: the strips in series at the contact pressure, §3.6)
    let mut p = oring_problem(nbr_like());
    p.asperity_modulus = AsperityModulus::Follow;
    p.fluid.pressure_difference = 1e-3;
    let r = simulate(&p);
    let q0 = r.initial_leak_rate();
    assert!(q0 > 0.0);
    for row in &r.rows {
        assert!(
            (row.leak_rate / q0 - 1.0).abs() < 1e-9,
            "t = {}: {} vs {q0}",
            row.time,
            row.leak_rate
        );
    }
    // while the sealing force itself relaxes
    assert!(r.rows.last().unwrap().sealing_force < 0.8 * r.rows[0].sealing_force);
}

#[test]
fn fluid_pressure_that_does_not_relax_raises_the_leak_as_the_contact_relaxes() {
    // With ΔP = 1 bar in the interface, the asperities carry p_c(t) − p_f: p_c relaxes with the
    // modulus, p_f does not, so under `follow` the leak rate rises monotonically over the life
    // (and exceeds the ΔP → 0 one from the start)
    let mut p = oring_problem(nbr_like());
    p.asperity_modulus = AsperityModulus::Follow;
    let r = simulate(&p);
    for pair in r.rows.windows(2) {
        assert!(
            pair[1].leak_rate >= pair[0].leak_rate * (1.0 - 1e-9),
            "t = {}: {} after {}",
            pair[1].time,
            pair[1].leak_rate,
            pair[0].leak_rate
        );
    }
    let (first, last) = (r.initial_leak_rate(), r.final_leak_rate());
    assert!(last > 1.5 * first, "{first} → {last}");
    let mut tiny = p.clone();
    tiny.fluid.pressure_difference = 1e-3;
    let reference = simulate(&tiny).initial_leak_rate() * 1e5 / 1e-3;
    assert!(first > reference, "{first} vs ΔP → 0 scaled {reference}");
}

fn one_term_flat(shift: Shift, temperature: f64) -> (LifeProblem, f64) {
    let (e_inf, e1, tau) = (2e6, 6e6, 1e5);
    let mut p = oring_problem(material(e_inf, &[(e1, tau)], shift));
    p.geometry = SealGeometry::Flat {
        nominal_pressure: 1e6,
        width: 1e-3,
        length: 0.1,
    };
    p.environment = TemperatureHistory::constant(temperature);
    p.failure = FailureCriteria {
        min_retained_force: Some(0.5),
        ..Default::default()
    };
    // E(t) = 0.5 E0 ⇔ t = τ ln(E1 / (0.5 E0 − E∞))
    let closed = tau * (e1 / (0.5 * (e_inf + e1) - e_inf)).ln();
    (p, closed)
}

#[test]
fn retained_force_failure_matches_closed_form() {
    let (p, closed) = one_term_flat(WLF, TREF);
    let r = simulate(&p);
    let f = r.failure.expect("fails");
    assert_eq!(f.mode, FailureMode::RetainedForce);
    assert!(
        (f.time / closed - 1.0).abs() < 1e-6,
        "{} vs {closed}",
        f.time
    );
    // at Tref + 20 K the same failure comes a_T times sooner, exactly
    let (hot, _) = one_term_flat(WLF, TREF + 20.0);
    let fh = simulate(&hot).failure.expect("fails hot");
    let a_t = WLF.factor(TREF + 20.0);
    assert!(
        (fh.time / (a_t * closed) - 1.0).abs() < 1e-6,
        "{} vs {}",
        fh.time,
        a_t * closed
    );
}

#[test]
fn time_to_failure_is_converged_in_the_grid() {
    let mut p = oring_problem(nbr_like());
    p.asperity_modulus = AsperityModulus::Instantaneous;
    let q0 = simulate(&p).initial_leak_rate();
    p.failure = FailureCriteria {
        max_leak_rate: Some(q0 * 30.0),
        ..Default::default()
    };
    let coarse = simulate(&p).failure.expect("fails");
    p.time.points_per_decade *= 4.0;
    let fine = simulate(&p).failure.expect("fails");
    assert_eq!(coarse.mode, FailureMode::LeakRate);
    eprintln!("refinement: {:e}", coarse.time / fine.time - 1.0);
    assert!(
        (coarse.time / fine.time - 1.0).abs() < 1e-3,
        "{} vs {}",
        coarse.time,
        fine.time
    );
}

#[test]
fn leaked_volume_integrates_a_constant_rate_exactly() {
    let mut p = oring_problem(nbr_like());
    p.asperity_modulus = AsperityModulus::Follow; // constant Q̇ (ΔP → 0, §3.6)
    p.fluid.pressure_difference = 1e-3;
    let r = simulate(&p);
    let q = r.initial_leak_rate();
    let last = r.rows.last().unwrap();
    assert!((last.leaked_volume / (q * last.time) - 1.0).abs() < 1e-9);
    // and the volume criterion is located on it
    p.failure = FailureCriteria {
        max_leaked_volume: Some(q * 1e6),
        ..Default::default()
    };
    let f = simulate(&p).failure.unwrap();
    assert_eq!(f.mode, FailureMode::LeakedVolume);
    assert!((f.time / 1e6 - 1.0).abs() < 1e-6, "{}", f.time);
}

#[test]
fn immediate_lift_off_at_time_zero() {
    let mut p = oring_problem(nbr_like());
    p.fluid.pressure_difference = 1e9;
    p.failure = FailureCriteria {
        lift_off: true,
        ..Default::default()
    };
    let r = simulate(&p);
    let f = r.failure.unwrap();
    assert_eq!((f.time, f.mode), (0.0, FailureMode::LiftOff));
    assert_eq!(r.rows[0].state, SealState::LiftOff);
}

#[test]
fn sealed_throughout_survives_with_zero_leak() {
    let mut p = oring_problem(nbr_like());
    p.spectrum = Spectrum::self_affine(1e-9, 0.8, 1e4, 1e6, None).unwrap();
    p.failure = FailureCriteria {
        max_leak_rate: Some(1e-12),
        ..Default::default()
    };
    let r = simulate(&p);
    assert!(r.failure.is_none());
    assert!(
        r.rows
            .iter()
            .all(|row| row.leak_rate == 0.0 && row.state == SealState::Sealed)
    );
}

fn all_finite(r: &sealsim::simulate::LifeResult) -> bool {
    r.rows.iter().all(|row| {
        [
            row.time,
            row.temperature,
            row.reduced_time,
            row.sealing_force,
            row.peak_pressure,
            row.mean_pressure,
            row.contact_width,
            row.leak_rate,
            row.leaked_volume,
        ]
        .iter()
        .all(|v| v.is_finite())
            && row.u_c.is_none_or(f64::is_finite)
            && row.shift_factor >= 0.0
    })
}

#[test]
fn extremes_stay_finite() {
    // durations from 1 s to 1000 years
    for duration in [1.0, 1e3, 1000.0 * YEAR] {
        let mut p = oring_problem(nbr_like());
        p.time = TimeGrid {
            start: 1e-3_f64.min(duration / 10.0),
            duration,
            points_per_decade: 20.0,
        };
        assert!(all_finite(&simulate(&p)), "duration {duration}");
    }
    // τ over 25 decades
    let terms: Vec<(f64, f64)> = (-5..=20).map(|k| (0.2e6, 10f64.powi(k))).collect();
    assert!(all_finite(&simulate(&oring_problem(material(
        1e6, &terms, WLF
    )))));
    // at and below the WLF singularity (Tref − C2): frozen, with a warning, never NaN
    for t in [TREF - 101.6, TREF - 150.0] {
        let mut p = oring_problem(nbr_like());
        p.environment = TemperatureHistory::constant(t);
        let r = simulate(&p);
        assert!(all_finite(&r));
        assert!(r.findings.get(Limit::Frozen).is_some());
        assert!(r.rows.iter().all(|row| row.reduced_time == 0.0));
    }
    // squeeze outside Lindley's range warns
    for squeeze in [0.02, 0.4] {
        let mut p = oring_problem(nbr_like());
        p.geometry = SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze,
        };
        let r = simulate(&p);
        assert!(all_finite(&r));
        assert!(r.findings.get(Limit::Squeeze).is_some());
    }
    // a cold night crossing the singularity every day
    let mut p = oring_problem(nbr_like());
    p.environment = TemperatureHistory::constant(TREF - 80.0).with_cycle(Cycle {
        amplitude: 40.0,
        period: 86400.0,
        phase: 0.0,
    });
    p.time.duration = 30.0 * 86400.0;
    assert!(all_finite(&simulate(&p)));
}

#[test]
fn a_cold_snap_inside_one_step_is_resolved() {
    // The squeeze follows the temperature (thermal strain): a 65 K drop within one output step,
    // a_T changing by 11 decades, must give the sealing force of a fine output grid.
    let mut p = oring_problem(nbr_like());
    p.environment =
        TemperatureHistory::table(vec![(0.0, TREF), (1e5, TREF), (1e5 + 3600.0, TREF - 65.0)]);
    p.thermal_strain = Some(sealsim::simulate::ThermalStrain {
        rubber_expansion: 1.65e-4,
        housing_expansion: 1.2e-5,
        installation_temperature: TREF,
        glassy_expansion: None,
        glass_transition: None,
    });
    p.time = TimeGrid {
        start: 1.0,
        duration: 2e5,
        points_per_decade: 2.0,
    };
    let coarse = simulate(&p);
    p.time.points_per_decade = 400.0;
    let fine = simulate(&p);
    let (c, f) = (
        coarse.rows.last().unwrap().sealing_force,
        fine.rows.last().unwrap().sealing_force,
    );
    assert!((c / f - 1.0).abs() < 2e-3, "{c} vs {f}");
    // and the cold unloading is stiff: more force lost than the relaxed modulus would give
    assert!(c < 0.9 * coarse.rows[coarse.rows.len() - 3].sealing_force);
}
