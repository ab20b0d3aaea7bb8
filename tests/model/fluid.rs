//! A fluid whose viscosity follows the temperature in the life loop (issue 15, item 5;
//! docs/model.md §3.7).

use sealsim::fluid::{Fluid, ViscosityLaw};
use sealsim::material::{Material, TemperatureHistory};
use sealsim::simulate::{LifeProblem, TimeGrid, simulate};

/// The hot phase starts here \[s\].
const STEP: f64 = 1e5;

/// An elastic O-ring (no relaxation, no shift, no thermal strain): only η changes with T —
/// the life tests' O-ring with the viscosity `law`, `environment` and a short time grid.
fn problem(law: ViscosityLaw, environment: TemperatureHistory) -> LifeProblem {
    let base = crate::life::oring_problem(Material::elastic("elastic", 5e6, 0.5).unwrap());
    LifeProblem {
        fluid: Fluid { law, ..base.fluid },
        environment,
        time: TimeGrid {
            start: 1.0,
            duration: 1e6,
            points_per_decade: 4.0,
            tolerance: TimeGrid::DEFAULT_TOLERANCE,
        },
        ..base
    }
}

/// 20 °C, then a one-hour ramp to 80 °C at `STEP`.
fn hot_step() -> TemperatureHistory {
    TemperatureHistory::table(vec![(0.0, 293.15), (STEP, 293.15), (STEP + 3600.0, 353.15)])
}

#[test]
fn a_hotter_phase_raises_the_leak_by_the_viscosity_ratio() {
    let r = simulate(&problem(ViscosityLaw::Water, hot_step()));
    let cold = r.rows.iter().find(|row| row.time > 0.0).unwrap();
    let hot = r.rows.last().unwrap();
    assert_eq!((cold.temperature, hot.temperature), (293.15, 353.15));
    // everything but η is the same: Q̇ ∝ 1/η
    let ratio = hot.leak_rate / cold.leak_rate;
    let law = sealsim::fluid::water_viscosity(293.15) / sealsim::fluid::water_viscosity(353.15);
    assert!((ratio / law - 1.0).abs() < 1e-9, "{ratio} vs {law}");
    // and the ratio is the tabulated water's (Chaplin, LSBU: 1.002 / 0.355 mPa·s) within 1 %
    assert!((ratio / (1.002 / 0.355) - 1.0).abs() < 0.01, "{ratio}");
    // every row before the step leaks as the first (the mechanics do not change)
    for row in r.rows.iter().filter(|row| row.time <= STEP) {
        assert_eq!(row.leak_rate, r.rows[0].leak_rate, "t = {}", row.time);
    }
}

#[test]
fn a_constant_law_ignores_the_temperature_bit_for_bit() {
    let stepped = simulate(&problem(ViscosityLaw::Constant, hot_step()));
    let constant = simulate(&problem(
        ViscosityLaw::Constant,
        TemperatureHistory::constant(293.15),
    ));
    let last = |r: &sealsim::simulate::LifeResult| r.rows.last().unwrap().leak_rate;
    assert_eq!(last(&stepped), last(&constant));
    assert_eq!(stepped.rows[0].leak_rate, constant.rows[0].leak_rate);
}
