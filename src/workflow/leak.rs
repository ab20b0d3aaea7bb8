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
