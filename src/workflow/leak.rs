//! `sealsim leak` as a library call: the leak of a scenario's seal at a list of nominal
//! pressures, with the drag of a sliding countersurface when the scenario has `[motion]`.

use super::{Progress, scenario_path};
use crate::contact::FullContact;
use crate::dynamic::{DragCoefficients, DragSettings, IhlInput, MotionPoint, MotionSpec};
use crate::leak::{ContactPath, Fidelity, FlatSeal, LeakPoint, StaticSolver};
use crate::scenario::Scenario;
use crate::simulate::{LifeProblem, Simulator};
use crate::validity::{self, At, Findings};

/// The leak of a scenario at several pressures.
#[derive(Debug, Clone)]
pub struct LeakOutcome {
    /// One point per pressure asked for. With constant sliding the drag is included in each
    /// point's leak rate; with a stroke cycle the leak rate is the static one in the low-speed
    /// regime and the cycle-averaged net leak once the inverse-hydrodynamic film has weight
    /// (docs/model.md §3.4.1).
    pub points: Vec<LeakPoint>,
    /// `[motion]`: the motion quantities at each point (`None` for a static seal).
    pub motion: Option<Vec<MotionPoint>>,
    /// Whether the motion is a stroke cycle (its per-stroke volumes are reported).
    pub stroke: bool,
    /// The interface at full magnification at each point's nominal pressure (`contact[i]`
    /// belongs to `points[i]`): A/A0 and ū ([`ContactPath::full_contact`] at P0/E*, the
    /// reduced pressure of the point's junction). `None` for an O-ring, whose contact pressure
    /// varies across its profile and whose asperities see the installation's moduli, and at
    /// the numerical level where a node's solve failed.
    pub contact: Vec<Option<FullContact>>,
    /// The validity findings: the contact path's, the surface's, the seal's installation
    /// state (temperature, squeeze), every point's contact state and sliding speed.
    pub findings: Findings,
}

/// The leak of `scenario`'s seal at each of `pressures` \[Pa\] at `fidelity`. The numerical
/// level solves exactly at these pressures; `progress` reports its realisations.
pub fn evaluate(
    scenario: &Scenario,
    pressures: Option<&[f64]>,
    fidelity: Fidelity,
    progress: Progress<'_>,
) -> LeakOutcome {
    // the numerical level solves exactly at a flat seal's pressures and at each less ΔP (the
    // ends of the interface-pressure integral, docs/model.md §3.6; between them its table
    // interpolates); an O-ring's strips need its table over all pressures
    let dp = scenario.problem.fluid.pressure_difference;
    let e_star = scenario.problem.material.effective_modulus();
    let ends = |p0: f64| {
        [p0, p0 - dp]
            .into_iter()
            .filter(|p| *p > 0.0)
            .map(|p| p / e_star)
    };
    // a seal of given P0 (flat): the table's nodes around it or the swept pressures; a ring's
    // pressure follows from its squeeze, so no nodes
    let nodes = match (scenario.life.geometry.given_pressure(), pressures) {
        (Some(_), Some(list)) => Some(list.iter().flat_map(|&p| ends(p)).collect()),
        (Some(nominal_pressure), None) => Some(ends(nominal_pressure).collect()),
        (None, _) => None,
    };
    let (path, findings) = scenario_path(scenario, fidelity, nodes, progress);
    evaluate_on(scenario, path, findings, pressures)
}

/// [`evaluate`] on a contact path built beforehand for the scenario ([`scenario_path`]),
/// adding to the path's `findings`.
pub fn evaluate_on(
    scenario: &Scenario,
    path: ContactPath,
    mut findings: Findings,
    pressures: Option<&[f64]>,
) -> LeakOutcome {
    let pb = &scenario.problem;
    validity::surface(&pb.spectrum, &mut findings);
    scenario.life.assess_installation(&mut findings);
    // the groove bottom's own surface, as `run` checks it (the counterface's: the path's findings)
    if let crate::simulate::GrooveInterface::Own(groove) = &scenario.life.groove {
        validity::surface(groove, &mut findings);
    }
    let solver = StaticSolver::with_path(pb.clone(), path);
    let oring = scenario.life.geometry.pressure_from_squeeze();
    let mut points: Vec<LeakPoint> = if oring {
        installed_oring(&scenario.life, solver.path(), pressures)
    } else {
        let own = [pb.seal.nominal_pressure];
        let list = pressures.unwrap_or(&own);
        list.iter().map(|&p0| solver.evaluate(p0)).collect()
    };
    for point in &points {
        solver.assess(point, &mut findings);
    }
    let e_star = pb.material.effective_modulus();
    let contact = points
        .iter()
        .map(|point| {
            if oring {
                None
            } else {
                solver.path().full_contact(point.nominal_pressure / e_star)
            }
        })
        .collect();
    let motion = scenario.life.motion.as_ref().map(|spec| {
        points
            .iter_mut()
            .map(|point| motion_point(&solver, spec, point, oring, &mut findings))
            .collect()
    });
    LeakOutcome {
        points,
        motion,
        stroke: scenario
            .life
            .motion
            .as_ref()
            .is_some_and(MotionSpec::is_stroke),
        contact,
        findings,
    }
}

/// A leak floor the user gives (`sealsim run --leak-floor`, the Python package's
/// `RunResult.plot(leak_floor=…)`) as the volume flow the leak rates are counted in \[m³/s\]. A
/// liquid takes a volume flow (m³/s, mL/h, mL/day, drops/min); a gas a throughput in the
/// leak-test trade's units (Pa·m³/s, mbar·L/s, atm·cc/s, std cc/s, sccm, slm, mol/s, at the gas
/// temperature), turned into the volume flow at the mean pressure it stands for, Q/p̄ — or a
/// volume flow, taken at p̄ (docs/model.md §15.2). The error is the message without the flag.
pub fn parse_leak_floor(text: &str, fluid: &crate::fluid::Fluid) -> Result<f64, String> {
    let bad = |message: String| message;
    let value = match (fluid.gas, fluid.mean_pressure()) {
        (Some(gas), Some(p)) => match crate::units::parse_throughput(text, gas.temperature) {
            Ok(q) => q / p,
            Err(_) => crate::units::parse_quantity(text, crate::units::Dimension::VOLUME_FLOW)
                .map_err(|_| {
                    bad(format!(
                        "{text:?} is neither a throughput nor a volume flow: give e.g. \
                         \"1e-9 mbar*L/s\", \"1e-8 atm*cc/s\", \"1e-6 sccm\" or \"1e-10 Pa*m^3/s\""
                    ))
                })?,
        },
        _ => {
            if crate::units::parse_throughput(text, 293.15).is_ok()
                && crate::units::parse_quantity(text, crate::units::Dimension::VOLUME_FLOW).is_err()
            {
                return Err(bad(format!(
                    "{text:?} is a gas throughput, but the fluid is a liquid: give a volume flow, \
                     e.g. \"1e-15 m^3/s\", \"0.01 mL/h\" or \"1 drops/min\""
                )));
            }
            crate::units::parse_quantity(text, crate::units::Dimension::VOLUME_FLOW)
                .map_err(|e| bad(e.to_string()))?
        }
    };
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(bad(format!("must be positive, got {text}")))
    }
}

/// One row of [`at_pressure_differences`]: the seal evaluated at one fluid pressure difference.
#[derive(Debug, Clone)]
pub struct DifferenceRow {
    /// The fluid pressure difference ΔP across the seal \[Pa\] (constant: the scenario's pressure
    /// history, if any, is not applied).
    pub pressure_difference: f64,
    /// The leak at ΔP: one point, at the scenario's own contact pressure (a flat seal's nominal
    /// pressure; an O-ring's installed peak with the energisation k_e ΔP at this ΔP).
    pub outcome: LeakOutcome,
    /// A gas's mean pressure p̄ = P_b + ΔP/2 at this ΔP \[Pa\] (`None`: a liquid).
    pub mean_pressure: Option<f64>,
    /// A groove-seated ring: whether it extrudes at installation at this ΔP (the life run's
    /// extrusion criterion at t = 0, docs/model.md §6.3); `None` without a gland.
    pub extrudes: Option<bool>,
}

/// `scenario` with the constant fluid pressure difference `dp` \[Pa\] in place of its own (and
/// of its pressure history): what `sealsim run` evaluates with `fluid.pressure_difference = dp`
/// (a gas keeps its outlet pressure, its inlet is P_b + ΔP).
pub fn with_pressure_difference(scenario: &Scenario, dp: f64) -> Scenario {
    let mut at = scenario.clone();
    at.life.fluid.pressure_difference = dp;
    at.life.pressure = None;
    at.problem.fluid.pressure_difference = dp;
    at
}

/// The leak of `scenario`'s seal at each fluid pressure difference of `differences` \[Pa\], as
/// an engineer means "at 50 bar and 210 bar": the installed seal at its own squeeze (an
/// O-ring: the energised Hertz profile, its strips, the fluid pressure inside the interface and
/// lift-off by it, both interfaces of a gland) evaluated with ΔP, the very state of the first
/// row of `sealsim run` with `fluid.pressure_difference = ΔP`. Returns one row per ΔP and the
/// findings of all of them. A liquid's contact path does not depend on ΔP and is built once;
/// a gas's (its rarefaction follows the mean pressure) is built per ΔP.
pub fn at_pressure_differences(
    scenario: &Scenario,
    differences: &[f64],
    fidelity: Fidelity,
    progress: Progress<'_>,
) -> (Vec<DifferenceRow>, Findings) {
    let e_star = scenario.problem.material.effective_modulus();
    let shared = scenario.life.fluid.gas.is_none().then(|| {
        // a flat seal's numerical level solves at P0 and at each P0 − ΔP (docs/model.md §3.6)
        let nodes = scenario.life.geometry.given_pressure().map(|p0| {
            differences
                .iter()
                .flat_map(|&dp| [p0, p0 - dp])
                .filter(|p| *p > 0.0)
                .map(|p| p / e_star)
                .collect()
        });
        scenario_path(scenario, fidelity, nodes, &mut *progress)
    });
    let mut findings = Findings::default();
    let rows = differences
        .iter()
        .map(|&dp| {
            let at = with_pressure_difference(scenario, dp);
            let mut outcome = match &shared {
                Some((path, _)) => evaluate_on(&at, path.clone(), Findings::default(), None),
                None => evaluate(&at, None, fidelity, &mut *progress),
            };
            findings.extend(std::mem::take(&mut outcome.findings));
            let life = &at.life;
            DifferenceRow {
                pressure_difference: dp,
                mean_pressure: life.fluid.mean_pressure(),
                extrudes: life
                    .extrusion_at(life.installed_temperature(), dp)
                    .map(|(ratio, limit)| ratio > 1.0 || limit.over_rated),
                outcome,
            }
        })
        .collect();
    if let Some((_, path_findings)) = shared {
        findings.extend(path_findings);
    }
    (rows, findings)
}

/// Which state `leak` evaluates for an O-ring (issue: say it in the output, not only the help);
/// `given`: contact pressures were given, which the note then says are not fluid pressures.
pub fn oring_state_note(scenario: &Scenario, given: bool) -> Option<String> {
    let life = &scenario.life;
    if !life.geometry.pressure_from_squeeze() {
        return None;
    }
    let interfaces = match life.groove {
        crate::simulate::GrooveInterface::None => "one interface (a ring between plates)",
        crate::simulate::GrooveInterface::Counterface => {
            "counterface and groove bottom (the same surface) in parallel"
        }
        crate::simulate::GrooveInterface::Own(_) => {
            "counterface and groove bottom ([groove_surface]) in parallel"
        }
    };
    let dp = life.fluid.pressure_difference;
    let energised = crate::units::human(life.energisation_factor * dp, 4);
    Some(if given {
        format!(
            "O-ring: the pressures given are CONTACT pressures (the peak contact pressure, with \
             k_e ΔP = {energised} Pa at the scenario's fluid ΔP = {} Pa), not fluid pressures; \
             for the leak at a fluid pressure use --pressure-differences (Python: \
             pressure_differences=); {interfaces}",
            crate::units::human(dp, 4)
        )
    } else {
        format!(
            "O-ring: the installed state `sealsim run` starts from at the scenario's fluid ΔP = \
             {} Pa; nominal_pressure_Pa is the peak contact pressure including k_e ΔP = {energised} \
             Pa; {interfaces}",
            crate::units::human(dp, 4)
        )
    })
}

/// An O-ring's installed state (what `sealsim run` computes at t = 0: the energised Hertz
/// profile with the fluid pressure inside the interface, both interfaces of a gland, the
/// asperity modulus at installation), with its profile scaled to each of `pressures` as the
/// peak contact pressure \[Pa\] (`None`: the installation's own peak). Static: no drag, all
/// channels open. `sealsim tradeoff`'s static state is the same.
pub(super) fn installed_oring(
    life: &LifeProblem,
    path: &ContactPath,
    pressures: Option<&[f64]>,
) -> Vec<LeakPoint> {
    let mut life = life.clone();
    life.motion = None;
    life.contamination = None;
    let simulator = Simulator::with_path(&life, path.clone());
    let own = [simulator.installed_peak()];
    pressures
        .unwrap_or(&own)
        .iter()
        .map(|&peak| {
            let (leak_rate, junction, state) = simulator.installed_leak(peak);
            LeakPoint {
                nominal_pressure: peak,
                junction,
                leak_rate: if leak_rate.is_finite() {
                    leak_rate
                } else {
                    0.0
                },
                state,
            }
        })
        .collect()
}

/// The motion quantities at `point` (exact critical junction and P(u) at its pressure,
/// docs/model.md §3.4); with constant sliding the drag is added to the point's leak rate.
fn motion_point(
    solver: &StaticSolver,
    spec: &MotionSpec,
    point: &mut LeakPoint,
    oring: bool,
    findings: &mut Findings,
) -> MotionPoint {
    let pb = solver.problem();
    let seal = spec.seal(
        pb.material,
        FlatSeal {
            nominal_pressure: point.nominal_pressure,
            ..pb.seal
        },
        pb.fluid.viscosity,
        pb.shape_factor,
    );
    // a critical gap below a molecule carries no film either (docs/model.md §8.1), also where
    // the strips the fluid pressure relieves leak
    let below_molecule = point
        .junction
        .leaking()
        .is_some_and(|j| !crate::fluid::passes_molecule(j.u_c, pb.fluid.molecular_size()));
    let coeffs = if point.state == crate::leak::SealState::BelowMolecule || below_molecule {
        DragCoefficients::sealed(&seal)
    } else {
        DragCoefficients::compute(solver.path().exact(), &seal, &DragSettings::default())
    };
    let oring = oring.then_some((
        point.nominal_pressure,
        pb.seal.width,
        pb.fluid.pressure_difference,
    ));
    let ihl = IhlInput {
        gradients: spec.gradients_for(oring),
        viscosity: pb.fluid.viscosity,
        sealing_length: pb.seal.length,
        roughness: pb.spectrum.rms_roughness(),
    };
    let m = spec.evaluate(&coeffs, point.leak_rate, &ihl);
    if !spec.is_stroke() {
        point.leak_rate += m.drag_leak_rate;
    } else if let Some(mean) = m.cycle_mean_leak_rate() {
        // the cycle-averaged leak once the IHL film has weight, as `sealsim run` reports it
        point.leak_rate = mean;
        if mean > 0.0 && point.state == crate::leak::SealState::Sealed {
            point.state = crate::leak::SealState::Leaking;
        }
    }
    validity::motion(
        spec.fastest_speed(),
        &m,
        At::Pressure(point.nominal_pressure),
        findings,
    );
    m
}
