//! Gases (docs/model.md §3.9): the continuum compressible leak law against its closed forms and
//! the liquid limit, Sutherland's law, the mean free path, throughput units and the Knudsen
//! warnings.

use crate::common::rel;
use sealsim::fluid::{
    Conduction, FlowGeometry, Fluid, GasService, ViscosityLaw, junction_conductance,
};
use sealsim::gas::{self, GAS_CONSTANT, Gas};
use sealsim::units::{UnitError, parse_throughput};
use sealsim::validity::{At, Findings, Limit, knudsen};

const GEOMETRY: FlowGeometry = FlowGeometry {
    along_flow: 2e-3,
    across_flow: 0.15,
};

/// `gas` between `inlet` and `outlet` \[Pa, absolute\] at `temperature` \[K\].
fn gas_fluid(gas: Gas, inlet: f64, outlet: f64, temperature: f64) -> Fluid {
    Fluid {
        viscosity: 0.0,
        pressure_difference: inlet - outlet,
        law: ViscosityLaw::Gas(gas),
        gas: Some(GasService {
            gas,
            outlet_pressure: outlet,
            temperature,
            flow_law: sealsim::gas::FlowLaw::Continuum,
        }),
    }
    .at(temperature)
}

#[test]
fn small_pressure_difference_is_the_liquid_law_at_the_mean_density() {
    // mass flow of the gas = ρ(p̄) × the incompressible law with the gas's viscosity, for
    // ΔP/P_b from 1e-6 to 1e-3, uniform and series conduction
    let t = 300.0;
    let pb = 1e5;
    for ratio in [1e-6, 1e-5, 1e-4, 1e-3] {
        let f = gas_fluid(gas::NITROGEN, pb * (1.0 + ratio), pb, t);
        let mu = f.viscosity;
        assert!(rel(mu, gas::NITROGEN.viscosity.at(t)) < 1e-15);
        let sigma = junction_conductance(50e-9, 1.0, mu);
        let liquid = Fluid {
            viscosity: mu,
            pressure_difference: f.pressure_difference,
            law: ViscosityLaw::Constant,
            gas: None,
        };
        let mean_density = gas::NITROGEN.density(pb * (1.0 + 0.5 * ratio), t);
        for c in [
            Conduction::Uniform { conductance: sigma },
            Conduction::Series {
                resistance: GEOMETRY.along_flow / sigma,
            },
        ] {
            let q = f.throughput(GEOMETRY, c).unwrap();
            let mass = q * gas::NITROGEN.molar_mass / (GAS_CONSTANT * t);
            let expected = mean_density * liquid.leak_rate(GEOMETRY, c);
            assert!(rel(mass, expected) < 1e-9, "{ratio}: {mass} vs {expected}");
            // the volume flow at the mean pressure is the liquid's
            assert!(rel(f.leak_rate(GEOMETRY, c), liquid.leak_rate(GEOMETRY, c)) < 1e-9);
        }
    }
}

#[test]
fn continuum_throughput_of_a_uniform_interface_is_its_closed_form() {
    // Q = (L_y/L_x) σ (P_a² − P_b²)/2, also against vacuum (P_b = 0)
    let sigma = 3e-20;
    for (pa, pb) in [(2e5, 1e5), (1e5, 0.0), (1e7, 1e5), (1e5, 1e-4)] {
        let f = gas_fluid(gas::HELIUM, pa, pb, 296.15);
        let closed = GEOMETRY.across_flow / GEOMETRY.along_flow * sigma * (pa * pa - pb * pb) / 2.0;
        let uniform = f
            .throughput(GEOMETRY, Conduction::Uniform { conductance: sigma })
            .unwrap();
        assert!(rel(uniform, closed) < 1e-9, "{pa} {pb}");
        let series = f
            .throughput(
                GEOMETRY,
                Conduction::Series {
                    resistance: GEOMETRY.along_flow / sigma,
                },
            )
            .unwrap();
        assert!(rel(series, closed) < 1e-9);
        // throughput = p̄ × the leak rate (the volume flow at the mean pressure)
        let q = f.leak_rate(GEOMETRY, Conduction::Uniform { conductance: sigma });
        assert!(rel(f.throughput_of(q).unwrap(), closed) < 1e-12);
    }
}

#[test]
fn strips_in_series_conserve_the_mass_flux() {
    // unequal strips: with J = (P_a² − P_b²)/(2R), marching p² down strip by strip
    // (p_{i+1}² = p_i² − 2 J Δx/σ_i, the isothermal mass balance) must land on P_b
    let (pa, pb) = (3e5, 1e3);
    let sigmas = [1e-19, 3e-21, 7e-20, 2e-20, 5e-21];
    let dx = GEOMETRY.along_flow / sigmas.len() as f64;
    let r: f64 = sigmas.iter().map(|s| dx / s).sum();
    let f = gas_fluid(gas::HYDROGEN, pa, pb, 320.0);
    let q = f
        .throughput(GEOMETRY, Conduction::Series { resistance: r })
        .unwrap();
    let j = q / GEOMETRY.across_flow;
    let mut p2 = pa * pa;
    for s in sigmas {
        p2 -= 2.0 * j * dx / s;
    }
    assert!(rel(p2.sqrt(), pb) < 1e-6, "{} vs {pb}", p2.sqrt());
}

#[test]
fn sutherland_against_hand_values() {
    // μ = μ0 (T/T0)^1.5 (T0 + S)/(T + S), evaluated by hand:
    // N2 (1.663e-5, 273, 107): 300 K → 1.788625e-5, 500 K → 2.580466e-5 Pa·s
    let n2 = gas::NITROGEN.viscosity;
    assert!(rel(n2.at(300.0), 1.788_625e-5) < 1e-6);
    assert!(rel(n2.at(500.0), 2.580_466e-5) < 1e-6);
    // at T0 it is μ0
    assert!(rel(n2.at(273.0), 1.663e-5) < 1e-14);
    // He (1.9e-5, 273, 79.4): 300 K → 2.032966e-5; H2 (8.411e-6, 273, 97): 400 K → 1.110552e-5
    assert!(rel(gas::HELIUM.viscosity.at(300.0), 2.032_966e-5) < 1e-6);
    assert!(rel(gas::HYDROGEN.viscosity.at(400.0), 1.110_552e-5) < 1e-6);
}

#[test]
fn mean_free_paths_match_the_crc_table() {
    // CRC Handbook (100th ed.) as quoted: λ at 25 °C and 100 kPa [nm]; the hard-sphere
    // λ = k_B T/(√2 π d² p) with the same table's d reproduces it within 0.3 % (the table's
    // rounding of d to three digits)
    for (g, nm) in [
        (gas::NITROGEN, 67.6),
        (gas::HELIUM, 200.0),
        (gas::HYDROGEN, 126.0),
        (gas::OXYGEN, 73.6),
        (gas::ARGON, 72.2),
        (gas::CARBON_DIOXIDE, 45.1),
    ] {
        let lambda = g.mean_free_path(298.15, 1e5);
        assert!(rel(lambda, nm * 1e-9) < 3e-3, "{}: {lambda}", g.id);
    }
    // λ ∝ T/p
    let n2 = gas::NITROGEN;
    assert!(
        rel(
            n2.mean_free_path(596.3, 2e5),
            n2.mean_free_path(298.15, 1e5)
        ) < 1e-14
    );
}

#[test]
fn throughput_units_round_trip() {
    let t = 296.15;
    // 1 mbar·L/s = 1e2 Pa × 1e-3 m³ / s = 0.1 Pa·m³/s exactly
    assert_eq!(parse_throughput("1 mbar*L/s", t).unwrap(), 0.1);
    assert!(rel(parse_throughput("1e-9 mbar*L/s", t).unwrap(), 1e-10) < 1e-15);
    assert_eq!(parse_throughput("2 Pa*m^3/s", t).unwrap(), 2.0);
    assert!(
        rel(
            parse_throughput("1 Torr*L/s", t).unwrap(),
            101_325.0 / 760.0 * 1e-3
        ) < 1e-15
    );
    // sccm: 101325 Pa × 1 cm³ per minute at 273.15 K (SEMI), so at 273.15 K it is
    // 1.68875e-3 Pa·m³/s, and at T the same moles carry × T/273.15
    assert!(rel(parse_throughput("1 sccm", 273.15).unwrap(), 1.688_75e-3) < 1e-12);
    assert!(
        rel(
            parse_throughput("1 sccm", t).unwrap(),
            1.688_75e-3 * t / 273.15
        ) < 1e-12
    );
    assert!(rel(parse_throughput("1 slm", 273.15).unwrap(), 1.688_75) < 1e-12);
    for x in [1e-6, 0.37, 12.0] {
        let q = parse_throughput(&format!("{x} sccm"), t).unwrap();
        assert!(rel(gas::to_sccm(q, t), x) < 1e-12);
    }
    // mol/s through R T, and back
    let q = parse_throughput("1e-12 mol/s", t).unwrap();
    assert!(rel(q, 1e-12 * GAS_CONSTANT * t) < 1e-15);
    assert!(rel(gas::to_mol_per_s(q, t), 1e-12) < 1e-15);
    // a volume flow is not a throughput
    assert!(matches!(
        parse_throughput("1e-9 m^3/s", t),
        Err(UnitError::NotAThroughput { .. })
    ));
    assert!(parse_throughput("1e-9", t).is_err());
}

#[test]
fn knudsen_number_and_its_regimes() {
    // N2 at 25 °C between 1.5 and 0.5 bar: p̄ = 1 bar, λ = 67.7 nm
    let f = gas_fluid(gas::NITROGEN, 1.5e5, 0.5e5, 298.15);
    let lambda = gas::NITROGEN.mean_free_path(298.15, 1e5);
    assert!(rel(f.knudsen(100e-9).unwrap(), lambda / 100e-9) < 1e-14);
    // a liquid has none
    let water = Fluid {
        viscosity: 1e-3,
        pressure_difference: 1e5,
        law: ViscosityLaw::Constant,
        gas: None,
    };
    assert!(water.knudsen(1e-9).is_none() && water.throughput_of(1.0).is_none());
    // each regime fires past its threshold only
    let fired = |kn: f64| {
        let mut out = Findings::default();
        knudsen(kn, At::Installation, &mut out);
        [
            Limit::KnudsenSlip,
            Limit::KnudsenTransition,
            Limit::KnudsenFreeMolecular,
        ]
        .map(|l| out.get(l).is_some())
    };
    assert_eq!(fired(0.009), [false, false, false]);
    assert_eq!(fired(0.011), [true, false, false]);
    assert_eq!(fired(0.2), [true, true, false]);
    assert_eq!(fired(11.0), [true, true, true]);
}
