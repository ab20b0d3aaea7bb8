//! The seal-life time loop (docs/model.md §1, §3.2, §5–6, §8).
//!
//! The seal is installed by a ramp of the squeeze over `installation_time` (t = 0 is its end).
//! Each step: temperature T(t) → reduced time ξ (exact for constant T, adaptive quadrature
//! otherwise) → squeeze ε(t) with thermal strain → exact Prony update of the hereditary
//! sealing stress on Lindley's squeeze function g(ε), with the two-network chemical ageing
//! when `[ageing]` is on ([`RelaxationState::step_aged`]) → nominal pressure profile → asperity
//! modulus (by default the response to the installation alone, so that at a fixed squeeze the
//! contact state stays as installed) → critical junction of each
//! strip (contact table, built once) → leak rate through the strips in series → leaked volume
//! (integrated as a power law in time between steps, exact for power-law segments) → failure
//! criteria, located between steps by bisection on the exact state update to ≤ 1e-12 relative
//! in time.
//!
//! With a `[contamination]` block (docs/model.md §7, [`crate::clogging`]) the open fraction f of the
//! critical channels is integrated alongside, segment by segment between the internal time
//! points (see `Simulator::integrate_clogging`); without it nothing of that runs.
//!
//! With a `[motion]` block (PY08 §8, [`crate::dynamic`]) each state also gets the drag of
//! the sliding countersurface, evaluated at the *peak strip* (an approximation: the most
//! compressed strip holds the critical junction of the series, and its film
//! `d = β u_c` is what the countersurface carries through): its critical junction (the
//! level's critical-junction table, [`ContactPath::persson_junction`]), the integral I from a
//! table built once per run ([`DragTable`]), the contact width as the seal width L and the
//! asperity contact's modulus as E of the speed bound. Constant sliding adds `L_y d v` to the
//! leak rate (so to the leaked volume and the failure criteria); a stroke cycle leaves the
//! leak rate static (its drag volumes cancel over a cycle in the linear theory) and reports
//! the volumes per stroke. Without `[motion]` nothing of that runs.
//!
//! Steps are log-uniform in time from `start` (with an installation row at t = 0);
//! temperature cycles add internal sub-steps (eight per shortest period), and with a thermal
//! strain each sub-step is split further until a_T changes by at most half a decade within it,
//! so that the strain is close to piecewise linear in reduced time, as the exact update
//! requires.
//!
//! Layout: [`problem`](LifeProblem) holds the problem and result types; what depends on the
//! seal kind (squeeze with thermal strain, the load variable, the pressure profile) lives with
//! the seal ([`crate::seal::SealGeometry`]); `clogging` applies the open fraction and
//! integrates its ODE; [`events`] the failure criteria.

mod clogging;
pub mod events;
mod problem;
mod stepping;

pub use problem::{
    AgeingSource, AsperityModulus, Course, GrooveInterface, HistoryRow, LevelBand, LifeProblem,
    LifeResult, Loading, Outcome, SealState, TimeGrid,
};

use crate::contact::{ContactSettings, Elastic, Junction, PerssonContact};
use crate::dynamic::{DragSettings, DragTable, MotionPoint, MotionSpec};
use crate::extrusion::ExtrusionLimit;
use crate::fluid::Conduction;
use crate::interface::{self, HertzContact, HertzMemo, InterfaceFlow, InterfaceSettings};
use crate::leak::{ContactPath, FlatSeal};
use crate::material::shift::reduced_time;
use crate::material::{ChemicalStep, RelaxationState, TemperatureHistory};
use crate::math::quadrature::gauss_legendre;
use crate::seal::Profile;
pub use crate::seal::ThermalStrain;
use crate::validity::{self, At, ContactState, Findings};
pub use events::{ColdLimit, FailureCriteria, FailureEvent, FailureMode, Shutdown};

/// ΔP over the contact pressure below which the fluid pressure inside the interface changes the
/// leak by rounding only (the mean of σ over [P0 − ΔP, P0] is σ(P0) to ≈ 1e-16).
const NEGLIGIBLE_PRESSURE_RATIO: f64 = 1e-8;

/// Accuracy of the interface-pressure solutions in the life loop: 128 RK4 steps across a Hertz
/// profile keep the flux within 1e-6 of the converged one from ΔP/p_max = 0.002 to 0.8, with
/// and without energisation (the ignored study `interface::study_hertz_steps_against_cost`); the
/// flux's root to 1e-9 in ln q, far below that (1e-12 costs 40 % more shots for nothing).
const INTERFACE: InterfaceSettings = InterfaceSettings {
    panels_per_log_unit: 4.0,
    steps: 128,
    tolerance: 1e-9,
    outlet_breaks: 0,
    ceiling: f64::INFINITY,
};

/// Quadrature of the clogging contact path (the detour junctions and the reach): both
/// u_c(a_eff) and u_c(a_c) of the detour ratio `(u_c(a_eff)/u_c(a_c))³`, and both u1 of the reach
/// ratio u1(ζc/2)/u1(ζc), use it, so its error (≈ 6e-5 in u_c, measured against the default
/// rule on the paper's surface) largely cancels, at a third of the cost.
const REROUTE_QUADRATURE: crate::contact::QuadratureSettings = crate::contact::QuadratureSettings {
    panel_width: 2.0,
    order: 4,
};

/// Largest temperature change within one internal step when the squeeze depends on the
/// temperature \[K\].
const MAX_STEP_TEMPERATURE: f64 = 10.0;
/// Largest change of log10 a_T within one internal step when the squeeze depends on the
/// temperature.
const MAX_STEP_LOG_SHIFT: f64 = 0.5;
/// Largest temperature change within one internal step that crosses the WLF frozen limit
/// (where a_T is infinite at one end) \[K\].
const MAX_STEP_TEMPERATURE_FROZEN_EDGE: f64 = 1.0;
/// Relative tolerance of the sealing stress in the error control of the mechanical update under
/// a temperature-dependent squeeze ([`Simulator::advance_mechanics`]), as a multiple of the
/// run's tolerance (1e-5 at the default): below it, since near a lift-off the time of the
/// event is the stress's error over its rate of change (on the cold night of
/// `scenarios/cold-night-nbr.toml` the leaked volume moves by 3e-5 relative from 1e-5 to 1e-8,
/// by 3e-4 at 1e-4; without the control, at the 0.5-decade pieces of the thermal splitting,
/// it was 10 % low).
const MECHANICS_RTOL: f64 = 1e-1;
/// Deepest halving of one mechanical piece.
const MECHANICS_MAX_DEPTH: u32 = 40;
/// Upper bound of the pieces one internal step is split into for the thermal strain.
const MAX_THERMAL_PIECES: f64 = 10_000.0;

/// The integrals over the temperature history that one mechanical update takes: additive over
/// adjacent intervals.
#[derive(Debug, Clone, Copy)]
struct Increment {
    /// Δξ = ∫ dt / a_T \[s\].
    reduced_time: f64,
    /// ΔK = ∫ k_s dt (0 without ageing).
    scission: f64,
}

impl Increment {
    /// The increment over `[a, c]` from those over `[a, b]` (self) and `[b, c]`.
    fn then(self, next: Increment) -> Increment {
        Increment {
            reduced_time: self.reduced_time + next.reduced_time,
            scission: self.scission + next.scission,
        }
    }
}

/// Everything evaluated at one instant from the mechanical state.
#[derive(Debug, Clone, Copy)]
struct Snapshot {
    temperature: f64,
    profile: Profile,
    u_c: Option<f64>,
    /// The critical junction at the peak strip (with the re-routed u_c under clogging).
    peak_junction: Junction,
    /// A groove bottom with its own surface: its critical junction at the peak strip.
    groove_junction: Option<Junction>,
    leak_rate: f64,
    state: SealState,
    retained: f64,
    /// Chemical compression set with ageing on (docs/model.md §6.5).
    compression_set: Option<f64>,
    /// The shutdown check (docs/model.md §8.2); `None` where it does not apply.
    shutdown: Option<ShutdownState>,
    /// Flow through the critical channels with all of them open \[m³/s\]: `leak_rate` when
    /// clean, except for a stroke cycle with an inverse-hydrodynamic film, whose film rides over
    /// the contact and whose channels carry the static leak alone.
    open_leak_rate: f64,
    /// u_c at the peak strip with all channels open \[m\] (0 when sealed there).
    open_u_c: f64,
    /// λ_c at the peak strip with all channels open \[m\] (0 when sealed there).
    lambda_c: f64,
    /// Peak reduced pressure P_peak/E*.
    peak_reduced_pressure: f64,
    /// Under clogging: d_reach, the largest particle that reaches the critical constriction
    /// \[m\] (docs/model.md §7; 0 when clean or sealed).
    reach: f64,
    /// Under clogging: ū(ζ = 1) at the peak, the slit the cake sits in \[m\] (0 otherwise).
    entry_gap: f64,
    /// Under clogging: 1 + R_cake/R_seal, the cake's series factor on the static leak (1 clean).
    cake_factor: f64,
    /// Under straining: the critical constrictions and the particles' survival to them.
    capture: clogging::Capture,
    /// Open fraction f the leak rate was evaluated with.
    open_fraction: f64,
    /// `[motion]`: the motion quantities at the peak strip (all channels open until
    /// [`Simulator::clogged`] scales them).
    motion: Option<MotionPoint>,
    /// A groove-seated ring: its diametral clearance over the extrusion chart's limit at the
    /// state's temperature, and the limit (`None` without a gland).
    extrusion: Option<(f64, ExtrusionLimit)>,
    /// `[motion]`: the pressure-driven part of `open_leak_rate` \[m³/s\] (constant sliding:
    /// `open_leak_rate` = this + the drag; a stroke cycle: = `open_leak_rate`); `None` without
    /// motion.
    open_static_leak_rate: Option<f64>,
    /// Permeation throughput through the rubber \[Pa·m³/s\] (`None` without
    /// [`LifeProblem::permeation`]).
    permeation: Option<f64>,
    /// The permeation as the volume flow at the mean pressure p̄ it stands for, Q/p̄ \[m³/s\]:
    /// what the leak-rate criterion adds to `leak_rate` (a detector sees both; §8).
    permeation_flow: f64,
    /// The pressure difference ΔP at the snapshot's time \[Pa\] (docs/model.md §8.4).
    pressure_difference: f64,
}

/// The energisation factor of the restart check (docs/model.md §8.2): 0. A restart starts from
/// ΔP = 0, so the ring must first seal on its squeeze alone before the pressure can push it
/// against the groove flank — the criterion Green & English state, leakage once ΔP exceeds the
/// *unenergised* peak contact stress (§6.3). With the service's k_e = 1 the check would ask
/// only `p_sq > τ ΔP_min` and ignore ΔP_min.
pub const RESTART_ENERGISATION: f64 = 0.0;

/// The shutdown check of one state (docs/model.md §8.2; computed by `Simulator::shutdown`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShutdownState {
    /// The set ring's squeeze at the shutdown temperature over its recovered cord, ε_r.
    pub remaining_squeeze: f64,
    /// Its fully relaxed peak contact pressure there \[Pa\].
    pub peak_pressure: f64,
    /// Below the compound's T10: the peak contact pressure of the ring cooled to the shutdown
    /// temperature through its hereditary response \[Pa\] (`Simulator::glassy_shutdown`;
    /// `None` at or above T10).
    pub glassy_peak_pressure: Option<f64>,
    /// Whether it still closes the roughness and holds the minimum pressure difference (and,
    /// below T10, still presses on the face once cooled).
    pub holds: bool,
}

/// The leak through a profile with the fluid pressure inside the interface.
#[derive(Debug, Clone, Copy)]
struct InterfaceLeak {
    leak_rate: f64,
    junction: Junction,
    /// The asperity pressure e the junction is evaluated at \[Pa\].
    junction_pressure: f64,
    /// The interface's state: open ([`SealState::is_open`]) as the stresses or the interface
    /// decide, otherwise leaking, sealed, or sealed below a molecule.
    state: SealState,
    /// A groove bottom with its own surface: its critical junction (for the validity checks).
    groove_junction: Option<Junction>,
}

impl InterfaceLeak {
    /// The state with the total leak rate `leak_rate` \[m³/s\] (the interface's, or with a
    /// sliding countersurface's drag added).
    fn state_with(&self, leak_rate: f64) -> SealState {
        match self.state {
            open if open.is_open() => open,
            _ if leak_rate > 0.0 => SealState::Leaking,
            SealState::Leaking => SealState::Sealed,
            sealed => sealed,
        }
    }

    fn new(
        leak_rate: f64,
        (junction, junction_pressure): (Junction, f64),
        state: SealState,
    ) -> Self {
        InterfaceLeak {
            leak_rate,
            junction,
            junction_pressure,
            state,
            groove_junction: None,
        }
    }
}

/// The Hertz interface solutions of one surface over a run, memoised in the reduced peak and
/// pressure difference ([`HertzMemo`]; the ΔP axis is interpolated only when the asperity
/// modulus changes over the run, `follow`).
struct InterfaceSolver {
    memo: HertzMemo,
    /// The reduced pressure at and above which its path conducts nothing for the run's fluid
    /// ([`ContactPath::molecular_cut`]): found on first use, since a ring that seals all its
    /// life never needs it (a root search with the exact path near sealing; a function of the
    /// path and the fluid alone, so when it is found does not change its bits).
    cut: std::cell::OnceCell<f64>,
    molecular_size: f64,
}

impl InterfaceSolver {
    fn new(problem: &LifeProblem) -> Self {
        let pressure_spacing = (problem.asperity_modulus == AsperityModulus::Follow)
            .then_some(interface::MEMO_PRESSURE_SPACING);
        InterfaceSolver {
            memo: HertzMemo::new(interface::MEMO_SPACING, pressure_spacing),
            cut: std::cell::OnceCell::new(),
            molecular_size: problem.fluid.molecular_size(),
        }
    }

    /// [`Self::cut`] on `path`, the path this solver serves.
    fn cut(&self, path: &ContactPath) -> f64 {
        *self
            .cut
            .get_or_init(|| path.molecular_cut(self.molecular_size))
    }

    fn solve(
        &self,
        sigma_hat: &dyn Fn(f64) -> f64,
        e_star: f64,
        contact: HertzContact,
        viscosity: f64,
        dp: f64,
    ) -> interface::HertzSolution {
        self.memo
            .solve(sigma_hat, e_star, contact, viscosity, dp, &INTERFACE)
    }
}

/// The moduli of the asperity contact for the two parts of the contact pressure \[Pa\]
/// ([`Simulator::asperity_moduli`]).
#[derive(Debug, Clone, Copy, PartialEq)]
struct AsperityModuli {
    /// For the squeeze's part (held by displacement).
    squeeze: f64,
    /// For the fluid's part k_e ΔP − p_f (a load).
    fluid: f64,
}

impl AsperityModuli {
    /// The profile the asperity contact sees at E_fl: the squeeze's scaled by E_fl/E_sq.
    fn equivalent(&self, profile: &Profile) -> Profile {
        if self.fluid == self.squeeze {
            *profile
        } else {
            profile.scaled(self.fluid / self.squeeze)
        }
    }
}

/// The mechanical state carried along the time loop.
#[derive(Debug, Clone)]
struct Mechanics {
    time: f64,
    reduced_time: f64,
    /// The sealing stress's hereditary state on the load variable (with the chemical ageing).
    relaxation: RelaxationState,
    /// The response to the installation alone at a unit load (the same operator): the
    /// asperity modulus of `follow` for the squeeze's part of the contact pressure.
    installation: RelaxationState,
    /// Under a constant unit stress, the equilibrium strain the networks formed since
    /// installation hold (`y` of the two-network model under creep, \[1/Pa\]): the chemical
    /// part of the creep compliance ([`Simulator::asperity_moduli`]).
    creep_set: f64,
    /// The chemical networks on the material strain (the squeeze ε of an O-ring, the unit load
    /// of a flat seal): their set strain y/c is what the ring keeps when released
    /// (docs/model.md §6.5), the compression set's numerator and the shutdown check's set.
    networks: RelaxationState,
    leaked_volume: f64,
    /// Sieving: ln f, the log of the open fraction of the critical channels (0 when clean; −∞
    /// when every channel is blocked).
    log_open_fraction: f64,
    /// Straining: the particles that have arrived at the critical level, by relative size.
    straining: clogging::Straining,
    /// Solid volume of the particles caked at the entry \[m³\] (0 when clean).
    cake_volume: f64,
    /// Their surface π Σ d² \[m²\] (the cake's Sauter diameter is 6 V/A).
    cake_surface: f64,
    /// The clogging ODE could not follow a stiff closure within a step: the seal is taken
    /// as closed from then on.
    clogged_shut: bool,
}

/// A prepared life simulation: the contact path (table) is built once here.
pub struct Simulator<'a> {
    problem: &'a LifeProblem,
    path: ContactPath,
    rule: (Vec<f64>, Vec<f64>),
    /// The load variable right after installation (g(ε0) for an O-ring, 1 for a flat seal).
    load0: f64,
    /// The material strain right after installation (ε0 for an O-ring, 1 for a flat seal).
    deformation0: f64,
    initial_profile: Profile,
    /// The sealing force per unit length at the retained-force reference time \[N/m\].
    reference_force: f64,
    creep: crate::material::Creep,
    /// Under clogging: the exact contact path (the constrictions of every octave, the entry
    /// gap and, with re-routing, the detour junctions at other thresholds) on a coarser
    /// quadrature ([`REROUTE_QUADRATURE`]), and the nodes of the size distribution.
    clogging: Option<clogging::CloggingSetup>,
    /// The last `(s, u_c(s, a_c))` of the re-routing reference junction: a step's ratio nodes
    /// and its end snapshot share one pressure, hence one reference evaluation.
    reference_memo: std::cell::Cell<Option<(f64, Option<f64>)>>,
    /// The counterface's interface solutions.
    counterface: InterfaceSolver,
    /// The groove bottom's own surface: its contact path and interface solutions.
    groove: Option<(ContactPath, InterfaceSolver)>,
    /// `[motion]`: the motion and the table of I (built once; `None` for a static seal).
    drag: Option<(MotionSpec, DragTable)>,
    /// The compound's T10 \[K\] (`None`: none), below which the shutdown check follows the
    /// hereditary response ([`Self::glassy_shutdown`]).
    low_temperature_limit: Option<f64>,
    /// [`LifeProblem::installed_modulus`], a constant of the run that every profile needs.
    installed_modulus: f64,
    /// The creep series' weights of the installation ramp ([`crate::material::Creep::ramp_weights`]).
    ramp_weights: Vec<f64>,
}

impl<'a> Simulator<'a> {
    /// Prepares the run (builds the contact table when the fidelity asks for it).
    pub fn new(problem: &'a LifeProblem) -> Self {
        Self::with_path(problem, Self::contact_path(problem))
    }

    /// The contact path a problem needs: it depends only on the surface, the contact settings
    /// and the fidelity, so runs that share those (e.g. `sealsim compare` across materials)
    /// can build it once.
    pub fn contact_path(problem: &LifeProblem) -> ContactPath {
        ContactPath::for_fluid(
            &problem.spectrum,
            problem.contact,
            problem.fidelity,
            &problem.fluid,
        )
    }

    /// Prepares the run with a contact path built beforehand by [`Self::contact_path`] for a
    /// problem with the same surface, contact settings and fidelity.
    pub fn with_path(problem: &'a LifeProblem, path: ContactPath) -> Self {
        let load0 = problem.geometry.load_variable(
            problem.thermal_strain.as_ref(),
            problem.installed_temperature(),
        );
        let initial_profile = problem.initial_profile();
        let clogging = problem.contamination.as_ref().map(|c| {
            let settings = ContactSettings {
                quadrature: REROUTE_QUADRATURE,
                ..problem.contact
            };
            clogging::CloggingSetup::new(PerssonContact::new(problem.spectrum.clone(), settings), c)
        });
        let drag = problem.motion.map(|spec| {
            (
                spec,
                DragTable::build(path.exact(), DragSettings::default()),
            )
        });
        let creep = problem.material.prony.creep();
        let ramp_weights = creep.ramp_weights(problem.installation_reduced_time());
        let mut simulator = Simulator {
            problem,
            rule: gauss_legendre(problem.strips.max(2)),
            load0,
            deformation0: problem.geometry.deformation(
                problem.thermal_strain.as_ref(),
                problem.installed_temperature(),
            ),
            initial_profile,
            reference_force: initial_profile.force_per_length(),
            creep,
            clogging,
            reference_memo: std::cell::Cell::new(None),
            counterface: InterfaceSolver::new(problem),
            groove: match &problem.groove {
                GrooveInterface::Own(spectrum) => {
                    let own = ContactPath::for_fluid(
                        spectrum,
                        problem.contact,
                        problem.fidelity,
                        &problem.fluid,
                    );
                    let solver = InterfaceSolver::new(problem);
                    Some((own, solver))
                }
                _ => None,
            },
            path,
            drag,
            low_temperature_limit: problem.material.low_temperature_limit(),
            installed_modulus: problem.installed_modulus(),
            ramp_weights,
        };
        simulator.reference_force = simulator.force_at_reference();
        simulator
    }

    /// The sealing force per unit length at the retained-force reference time (docs/model.md
    /// §8; ISO 3384 refers compression stress relaxation to the force a stated time after
    /// compression): the mechanics alone advanced to it along the temperature history \[N/m\].
    /// Under force loading, the installed force.
    fn force_at_reference(&self) -> f64 {
        let p = self.problem;
        let reference = p.failure.retained_force_reference;
        if reference <= 0.0 || p.loading == Loading::Force {
            return self.initial_profile.force_per_length();
        }
        let mut state = self.installed();
        for t in self.substeps(0.0, reference) {
            self.advance_mechanics(&mut state, t);
            state.time = t;
        }
        self.profile_at(&state, reference).force_per_length()
    }

    /// The sealing force per unit length at the retained-force reference time \[N/m\].
    pub fn reference_force(&self) -> f64 {
        self.reference_force
    }

    /// Runs the whole life: internal steps chosen by the physics and the error control of
    /// `simulate::stepping` (docs/model.md §10.1), the history sampled at the output times.
    pub fn run(&self) -> LifeResult {
        let p = self.problem;
        let mut findings = Findings::default();
        if !p.can_fail() {
            validity::no_failure_criterion(&mut findings);
        }
        validity::surface(&p.spectrum, &mut findings);
        if let GrooveInterface::Own(groove) = &p.groove {
            validity::surface(groove, &mut findings);
        }
        let installed = self.installed();
        let first = self.snapshot(&installed);
        self.assess(&installed, &first, &mut findings);
        let mut rows = vec![self.row(&installed, &first)];
        let mut course = Course::start(&first, self.snap_peak(&first));
        let mut failure = p.failure.at_start(&first.as_event_input(0.0));
        let outputs = p.time.times();
        let mut next_output = 1;
        let stop = p.failure.stop_at_failure;
        let stepper = stepping::Stepper::new(self);
        let base = self.base_steps();
        let mut at = stepping::Point {
            state: installed,
            snap: first,
        };
        'run: for ends in base.chunks(2) {
            if stop && failure.is_some() {
                break;
            }
            for to in stepper.window(&at, ends) {
                self.assess(&to.state, &to.snap, &mut findings);
                course.record(&at, &to, self.snap_peak(&to.snap));
                if failure.is_none() {
                    failure = self.locate_failure(&at.state, &at.snap, &to.state, &to.snap);
                }
                // the history rows up to this step: sampled on copies, the run goes on from `to`
                while let Some(&t) = outputs.get(next_output) {
                    if t > to.state.time {
                        break;
                    }
                    if t == to.state.time {
                        rows.push(self.row(&to.state, &to.snap));
                    } else {
                        let mut sample = at.state.clone();
                        let snap = self.advance(&mut sample, t, &at.snap);
                        rows.push(self.row(&sample, &snap));
                    }
                    next_output += 1;
                }
                let done = stop && failure.is_some();
                if done && rows.last().is_none_or(|r| r.time < to.state.time) {
                    // the run ends on the step that found the failure
                    rows.push(self.row(&to.state, &to.snap));
                }
                at = to;
                if done {
                    break 'run;
                }
            }
        }
        course.evaluations += stepper.evaluations.get();
        LifeResult {
            rows,
            band: None,
            course,
            failure,
            findings,
            reference_force: self.reference_force,
            continuum_leak_rate: self.continuum_leak_rate(),
            permeation_status: self.problem.permeation.as_ref().map(|p| p.data.status),
        }
    }

    /// The base internal steps in (0, duration] (docs/model.md §10.1): log-uniform at
    /// [`stepping::BASE_POINTS_PER_DECADE`] from min(start, 1 s), with the knots and cycle
    /// sub-steps of the temperature history and the thermal splitting ([`Self::substeps`]) —
    /// independent of the output grid.
    fn base_steps(&self) -> Vec<f64> {
        let grid = TimeGrid {
            start: self.problem.time.start.min(stepping::BASE_START),
            points_per_decade: stepping::BASE_POINTS_PER_DECADE,
            ..self.problem.time
        };
        let times = grid.times();
        let mut out = Vec::with_capacity(times.len());
        for w in times.windows(2) {
            out.extend(self.substeps(w[0], w[1]));
        }
        out
    }

    /// A rarefied gas: the installation's leak rate under the continuum law, on the same
    /// contact path (docs/model.md §3.10); `None` for a liquid, the continuum law itself, or a
    /// numerical table whose cells were rarefied when it was built.
    fn continuum_leak_rate(&self) -> Option<f64> {
        let p = self.problem;
        p.fluid.mean_free_path()?;
        // a numerical table rarefied cell by cell has no continuum twin without a rebuild
        if let ContactPath::Numerical { gas: Some(_), .. } = self.path {
            return None;
        }
        let mut continuum = p.clone();
        if let Some(g) = continuum.fluid.gas.as_mut() {
            g.flow_law = crate::gas::FlowLaw::Continuum;
        }
        let simulator = Simulator::with_path(&continuum, self.path.clone());
        Some(simulator.installed_leak(simulator.installed_peak()).0)
    }

    /// The mechanical state right after installation (t = 0): the load variable ramped up
    /// linearly over the installation time at the temperature T(0) (a jump when it is 0).
    fn installed(&self) -> Mechanics {
        let p = self.problem;
        let prony = &p.material.prony;
        let mut state = Mechanics {
            time: 0.0,
            reduced_time: 0.0,
            relaxation: RelaxationState::new(prony),
            installation: RelaxationState::new(prony),
            creep_set: 0.0,
            networks: RelaxationState::networks_only(),
            leaked_volume: 0.0,
            log_open_fraction: 0.0,
            straining: clogging::Straining::default(),
            cake_volume: 0.0,
            cake_surface: 0.0,
            clogged_shut: false,
        };
        let ramp = p.installation_reduced_time();
        state.relaxation.step(prony, ramp, self.load0);
        state.installation.step(prony, ramp, 1.0);
        state.networks.step(prony, ramp, self.deformation0);
        state
    }

    /// The static leak of the installed seal with its pressure profile scaled so that the peak
    /// contact pressure (with the energisation k_e ΔP) is `peak` \[Pa\]: the interface with the
    /// asperity modulus at installation, exactly as the first row of [`Self::run`] computes it
    /// (at the installation's own peak, the same number). Returns the leak rate \[m³/s\] (all
    /// channels open, no drag), the junction where the asperities carry most, and the state.
    pub fn installed_leak(&self, peak: f64) -> (f64, Junction, SealState) {
        let state = self.installed();
        let moduli = self.asperity_moduli(&state);
        let installed = self.profile_at(&state, 0.0);
        let own = installed.peak();
        let dp = self.problem.pressure_at(0.0);
        let energised = self.contact_peak(&installed, dp);
        // at the installation's own peak the very profile of the run's first row (bit for bit)
        let profile = if peak == energised {
            installed
        } else {
            installed.scaled((peak - (energised - own)).max(0.0) / own)
        };
        let p = self.problem;
        let leak = self.profile_leak(&profile, moduli, p.installed_temperature(), 0.0);
        (
            leak.leak_rate,
            leak.junction,
            leak.state_with(leak.leak_rate),
        )
    }

    /// The peak contact pressure right after installation, with the energisation \[Pa\] (the
    /// first row of [`Self::run`]).
    pub fn installed_peak(&self) -> f64 {
        self.contact_peak(
            &self.profile_at(&self.installed(), 0.0),
            self.problem.pressure_at(0.0),
        )
    }

    /// The nominal pressure profile of `state` at time `t`.
    fn profile_at(&self, state: &Mechanics, t: f64) -> Profile {
        let p = self.problem;
        match p.loading {
            Loading::Displacement => p.geometry.profile(
                state.relaxation.stress(&p.material.prony),
                self.installed_modulus,
                p.thermal_strain.as_ref(),
                p.environment.at(t),
            ),
            Loading::Force => self.initial_profile,
        }
    }

    /// The chemical compression set of `state` (docs/model.md §6.5): the part of the installed
    /// compression the aged networks keep at rest, `CS = (y/c)/ε0` on the material strain —
    /// for an O-ring the squeeze, whose displacement field the networks superpose linearly (the
    /// free ring relaxes to the displaced shape (y/c)/ε0 of the installed one), not Lindley's
    /// force law; for a flat seal the unit load. At a constant squeeze and r = 1 it is
    /// `1 − e^{−K}` exactly, ISO 11346's relation (`sealsim ageing-fit`). It is the set after a
    /// full recovery: the viscoelastic part still unrecovered 30 min after release (ASTM D395's
    /// reading time) is not in it. `None` without ageing or under force loading.
    fn compression_set(&self, state: &Mechanics) -> Option<f64> {
        let p = self.problem;
        if p.ageing.is_none() || p.loading == Loading::Force || self.deformation0 <= 0.0 {
            return None;
        }
        Some(state.networks.set_strain() / self.deformation0)
    }

    /// The shutdown check of a groove-seated or plate-squeezed O-ring under displacement loading
    /// (docs/model.md §8.2): the ring cooled to the shutdown temperature T_sd with the fluid
    /// pressure at its minimum ΔP_min. Its remaining squeeze is the squeeze at T_sd beyond the
    /// set, over the recovered cord, `ε_r = (ε(T_sd) − s)/(1 − s)` (s = y/c, the networks' set
    /// strain); its contact pressure the fully relaxed one, `f = c E∞ d (1 − s) g(ε_r)` over
    /// Lindley's width (the long-term modulus: the least force of a ring that stays rubbery). The
    /// ring has lost its interference when `(ε(T_sd) − s) d` is no more than the counterface's rms
    /// roughness (it no longer closes the roughness it seals on), or, with ΔP_min > 0, when the
    /// squeeze cannot hold ΔP_min at a restart: a restart starts from ΔP = 0, so the ring must
    /// seal on its unenergised squeeze, `p_sq > ΔP_min` ([`crate::leak::opening`] with
    /// [`RESTART_ENERGISATION`] = 0, Green & English's criterion, §6.3), whatever the service's
    /// k_e. Below the compound's T10 the ring is glassy on the time scale of a shutdown and the
    /// relaxed force is not the least one: the check must also hold for the ring cooled through
    /// its hereditary response ([`Self::glassy_shutdown`]). A flat gasket is checked alike: each
    /// kind's set contact is the `set_contact` of [`crate::seal::SealGeometry`]. `None` when the
    /// check does not apply (force loading, or `[failure] lost_interference = false`).
    fn shutdown(&self, state: &Mechanics) -> Option<ShutdownState> {
        let p = self.problem;
        let shutdown = p.failure.shutdown?;
        if p.loading != Loading::Displacement {
            return None;
        }
        let squeeze = p
            .geometry
            .squeeze_at(p.thermal_strain.as_ref(), shutdown.temperature);
        let set = p.geometry.set_contact(&crate::seal::SetInput {
            squeeze,
            set_strain: state.networks.set_strain(),
            network: state.networks.network(),
            long_term: p.material.prony.long_term(),
            installed_modulus: self.installed_modulus,
            roughness: p.spectrum.rms_roughness(),
        });
        let restarts = |peak: f64| {
            crate::leak::opening(peak, RESTART_ENERGISATION, shutdown.pressure_difference).is_none()
        };
        let glassy_peak = self.glassy_shutdown(state, &shutdown);
        // the glassy ring must still press on the face (a force, not a rounding) and restart
        let glassy_holds = glassy_peak.is_none_or(|peak| peak > 0.0 && restarts(peak));
        Some(ShutdownState {
            remaining_squeeze: set.remaining,
            peak_pressure: set.peak_pressure,
            glassy_peak_pressure: glassy_peak,
            holds: set.touches && restarts(set.peak_pressure) && glassy_holds,
        })
    }

    /// The glassy branch of the shutdown check (docs/model.md §8.2): below the compound's T10
    /// (`Shutdown::temperature` < [`crate::material::Material::low_temperature_limit`]) the ring
    /// cooled from the state's temperature T(t) to T_sd does not relax to E∞ within a shutdown —
    /// the contraction is unloaded with the stiff modulus the cold gives it, and that stress is
    /// frozen in. So the state's hereditary stress is carried through a linear cool-down from
    /// T(t) to T_sd over `Shutdown::cooling_time` (the cord's thermal settling time d²/a: the
    /// fastest the ring follows its surroundings, the least relaxation on the way) by the exact
    /// Prony update the run uses, split as the run splits a thermal step (a_T by at most half a
    /// decade, T by at most 10 K a piece), with the squeeze the thermal strain gives. Returns the
    /// peak contact pressure of the Hertz profile at the end \[Pa\] (0 when the ring has come
    /// off the face: a tensile stress is no contact); `None` at or above T10, where the rubber
    /// relaxes within the shutdown and the relaxed check is the least force. The chemical
    /// ageing over the cool-down (minutes) is left out.
    fn glassy_shutdown(&self, state: &Mechanics, shutdown: &Shutdown) -> Option<f64> {
        let p = self.problem;
        let limit = self.low_temperature_limit?;
        if shutdown.temperature >= limit {
            return None;
        }
        let shift = &p.material.shift;
        let prony = &p.material.prony;
        let thermal = p.thermal_strain.as_ref();
        let from = p.environment.at(state.time);
        let to = shutdown.temperature;
        let mut relaxation = state.relaxation.clone();
        let duration = shutdown.cooling_time;
        if duration > 0.0 {
            let ramp = TemperatureHistory::table(vec![(0.0, from), (duration, to)]);
            // a_T is monotone in T along the ramp: its ends bound its change
            let (la, lb) = (shift.log10_factor(from), shift.log10_factor(to));
            let swing = (to - from).abs();
            let by_shift = match (la.is_finite(), lb.is_finite()) {
                (true, true) => (lb - la).abs() / MAX_STEP_LOG_SHIFT,
                (true, false) | (false, true) => swing / MAX_STEP_TEMPERATURE_FROZEN_EDGE,
                (false, false) => 0.0,
            };
            let pieces = (swing / MAX_STEP_TEMPERATURE)
                .max(by_shift)
                .ceil()
                .clamp(1.0, MAX_THERMAL_PIECES);
            let n = pieces as usize;
            for k in 1..=n {
                let (a, b) = (
                    duration * (k - 1) as f64 / pieces,
                    duration * k as f64 / pieces,
                );
                let d_xi = reduced_time(&ramp, shift, a, b);
                let d_load = p.geometry.load_variable(thermal, ramp.at(b)) - relaxation.strain();
                relaxation.step(prony, d_xi, d_load);
            }
        } else {
            // cooled at once: the glassy jump
            let d_load = p.geometry.load_variable(thermal, to) - relaxation.strain();
            relaxation.step(prony, 0.0, d_load);
        }
        let profile = p.geometry.profile(
            relaxation.stress(prony),
            self.installed_modulus,
            thermal,
            to,
        );
        Some(profile.peak())
    }

    /// The leak through `profile` with the fluid pressure inside the interface (docs/model.md
    /// §3.6) and the energisation `k_e ΔP` added to the contact pressure (§6.3), with the
    /// asperity contact's `moduli`: the counterface's interface, plus the groove bottom's in
    /// parallel for a groove-seated ring. The junction and state are the counterface's.
    ///
    /// The asperity contact sees the squeeze's pressure over its modulus and the fluid's over
    /// its own, `e/E* = p_sq/E*_sq + (k_e ΔP − p_f)/E*_fl` (docs/model.md §6.1): solved as one
    /// interface at E*_fl with the squeeze's profile scaled by E_fl/E_sq. Whether the seal is
    /// open is decided by the stresses with the tolerance of docs/model.md §8.1
    /// ([`crate::leak::opening`]: `p_sq ≤ max(1 − k_e, τ) ΔP`), never by rounding. The fluid's
    /// viscosity (§3.7) and a gas's mean free path (§3.10) are the ones at the state's
    /// `temperature` \[K\].
    ///
    /// The pressure difference is the one at time `t` \[s\] (docs/model.md §8.4); a gas's leak
    /// rate is returned as the volume flow at the service's mean pressure p̄ (the one its
    /// criteria are stated at, §3.9), so that it integrates to a leaked amount of gas while
    /// the pressure varies.
    fn profile_leak(
        &self,
        profile: &Profile,
        moduli: AsperityModuli,
        temperature: f64,
        t: f64,
    ) -> InterfaceLeak {
        let p = self.problem;
        let service = p.fluid_at(t);
        let fluid = service.at(temperature);
        let e_star = moduli.fluid / (1.0 - p.material.poisson_ratio.powi(2));
        let equivalent = moduli.equivalent(profile);
        let dp = service.pressure_difference;
        let open = match p.pressure {
            // depressurised in a pressure history (docs/model.md §8.4): the limit ΔP → 0 of the
            // rule p_sq ≤ max(1 − k_e, τ) ΔP — a ring that has come off the face (no squeeze
            // left, e.g. contracted at the cold) is open with or without a pressure to push
            // through it, and the pressure's return finds it open
            Some(_) if dp <= 0.0 && profile.peak() <= 0.0 => Some(SealState::LiftOff),
            _ => crate::leak::opening(profile.peak(), p.energisation_factor, dp),
        };
        let lifted = open == Some(SealState::LiftOff);
        let interface = |path: &ContactPath, solver: &InterfaceSolver| {
            self.interface_leak(
                path,
                solver,
                &equivalent,
                lifted,
                e_star,
                (&service, &fluid),
            )
        };
        let counterface = interface(&self.path, &self.counterface);
        let (groove, groove_junction, groove_state) = match (&self.problem.groove, &self.groove) {
            (GrooveInterface::Counterface, _) => (counterface.leak_rate, None, counterface.state),
            (GrooveInterface::Own(_), Some((path, solver))) => {
                let own = interface(path, solver);
                (own.leak_rate, Some(own.junction), own.state)
            }
            _ => (0.0, None, counterface.state),
        };
        let leak_rate = match p.pressure {
            // depressurised: nothing drives a flow (and a gas against vacuum has p̄ = 0)
            Some(_) if dp <= 0.0 => 0.0,
            _ => (counterface.leak_rate + groove) * self.gas_volume_scale(&service),
        };
        let state = match (open, counterface.state, groove_state) {
            // the interface found no contact left although the squeeze holds: open
            (_, SealState::LiftOff, _) | (_, _, SealState::LiftOff) => SealState::LiftOff,
            (Some(open), _, _) => open,
            _ if leak_rate > 0.0 => SealState::Leaking,
            (_, SealState::BelowMolecule, _) | (_, _, SealState::BelowMolecule) => {
                SealState::BelowMolecule
            }
            _ => SealState::Sealed,
        };
        InterfaceLeak {
            leak_rate,
            groove_junction,
            state,
            ..counterface
        }
    }

    /// One interface of `path` under `profile` (see [`Self::profile_leak`]): the leak rate, the
    /// critical junction where the asperities carry most (the peak of a Hertz profile less the
    /// fluid pressure there; a uniform contact's outlet), and the state. Where ΔP is negligible
    /// against the contact pressure (≤ 1e-8 of it) the strips in series at the contact pressure
    /// (§3.2). Lifted off (`lifted` by the stresses, or found so by the interface): the leak of
    /// the interface loaded just to its threshold of lift-off (contact peak = ΔP), a lower bound
    /// that less load never lowers ([`Self::onset_leak`]). Every strip whose critical gap is no
    /// wider than a molecule of the fluid conducts nothing ([`ContactPath::conductance`],
    /// docs/model.md §3.6, §8.1); an interface that conducts nowhere is sealed — by the molecule
    /// ([`SealState::BelowMolecule`]) when a channel percolates in its least-loaded strip
    /// ([`ContactPath::sealed_state`]).
    fn interface_leak(
        &self,
        path: &ContactPath,
        solver: &InterfaceSolver,
        profile: &Profile,
        lifted: bool,
        e_star: f64,
        (service, fluid): (&crate::fluid::Fluid, &crate::fluid::Fluid),
    ) -> InterfaceLeak {
        let p = self.problem;
        let dp = service.pressure_difference;
        let offset = p.energisation_factor * dp;
        let viscosity = fluid.viscosity;
        let molecule = fluid.molecular_size();
        let sigma_hat = |s: f64| path.conductance(s, p.shape_factor, viscosity, molecule);
        // σ(e, p_f) at asperity pressure e and gauge fluid pressure p_f: for a gas weighed by
        // the local density (P_b + p_f)/p̄, each constriction rarefied at the local pressure
        // (docs/model.md §3.9, §3.10); σ(e) for a liquid
        let local = |e: f64, fluid_pressure: f64| {
            path.gas_conductance(
                e / e_star,
                p.shape_factor,
                viscosity,
                fluid.free_path_at(fluid_pressure),
                molecule,
            ) * fluid.density_weight(fluid_pressure)
        };
        // under a uniform contact pressure `top` the fluid pressure is top − e
        let weighted = |top: f64| move |e: f64| local(e, top - e);
        let geometry = profile.geometry(p.geometry.sealing_length());
        let top = profile.peak() + offset;
        let series = || {
            // ΔP negligible: every strip at p̄ (gauge ΔP/2)
            let resistance =
                profile.series_resistance(&self.rule, |pc| local(pc + offset, 0.5 * dp));
            // the peak strip itself too: the rule's nodes need not fall where it seals
            let conducts = resistance.is_finite() && local(top, 0.5 * dp) > 0.0;
            (
                conducts,
                service.leak_rate(geometry, Conduction::Series { resistance }),
            )
        };
        let junction_at = |e: f64| (path.critical_junction(e.max(0.0) / e_star), e.max(0.0));
        let open = || {
            // the profile loaded just to the threshold: its contact peak is ΔP
            let threshold = if dp > offset {
                profile.with_peak(dp - offset)
            } else {
                *profile
            };
            InterfaceLeak::new(
                self.onset_leak(
                    &local,
                    &threshold,
                    offset,
                    solver.cut(path) * e_star,
                    service,
                ),
                junction_at(top),
                SealState::LiftOff,
            )
        };
        if lifted {
            return open();
        }
        // the strips' σ is already 0 below a molecule: the interface leaks, or it is sealed,
        // by the molecule when its least-loaded strip (asperity pressure `least`) percolates
        // (a conducting interface under no pressure difference leaks nothing: `sealed`, as ever)
        let outcome = |conducts: bool, leak_rate: f64, junction: (Junction, f64), least: f64| {
            if !conducts {
                InterfaceLeak::new(0.0, junction, path.sealed_state(least / e_star))
            } else if leak_rate > 0.0 {
                InterfaceLeak::new(leak_rate, junction, SealState::Leaking)
            } else {
                InterfaceLeak::new(leak_rate, junction, SealState::Sealed)
            }
        };
        if dp <= NEGLIGIBLE_PRESSURE_RATIO * top {
            // every strip at its contact pressure: the peak's decides
            let (conducts, leak_rate) = series();
            return outcome(conducts, leak_rate, junction_at(top), top);
        }
        let (flow, junction) = match *profile {
            Profile::Uniform { pressure, .. } => (
                interface::uniform(
                    &weighted(pressure + offset),
                    pressure + offset,
                    dp,
                    &InterfaceSettings {
                        outlet_breaks: fluid.outlet_breaks(),
                        ceiling: solver.cut(path) * e_star,
                        ..INTERFACE
                    },
                ),
                junction_at(top),
            ),
            Profile::Hertz { peak, width } => {
                let contact = HertzContact {
                    peak,
                    offset,
                    width,
                };
                // a gas: its own pressure profile along the resistance (no memo: its σ depends
                // on the absolute pressures, which do not scale with E*)
                let solved = if fluid.gas.is_some() {
                    interface::hertz_local(&local, contact, dp, &INTERFACE)
                } else {
                    solver.solve(&sigma_hat, e_star, contact, viscosity, dp)
                };
                (solved.flow, junction_at(top - solved.centre_fluid_pressure))
            }
        };
        match flow {
            InterfaceFlow::Conducting(conduction) => outcome(
                true,
                service.leak_rate(geometry, conduction),
                junction,
                top - dp,
            ),
            // no strip conducts even with the whole ΔP relieving it
            InterfaceFlow::Sealed => outcome(false, 0.0, junction, top - dp),
            InterfaceFlow::LiftOff => open(),
        }
    }

    /// The leak at the onset of lift-off (docs/model.md §3.6): the interface with the fluid
    /// pressure in it at its largest — the peak contact pressure, less 1e-9 of it for a Hertz
    /// profile — driving the flux; the last value the model gives for an open seal, a lower
    /// bound. σ is 0 at and above `ceiling` \[Pa\] (the molecular cut, §8.1).
    fn onset_leak(
        &self,
        local: &dyn Fn(f64, f64) -> f64,
        profile: &Profile,
        offset: f64,
        ceiling: f64,
        service: &crate::fluid::Fluid,
    ) -> f64 {
        let p = self.problem;
        let geometry = profile.geometry(p.geometry.sealing_length());
        let dp = service.pressure_difference;
        let conduction = match *profile {
            Profile::Uniform { pressure, .. } => {
                let top = pressure + offset;
                let settings = InterfaceSettings {
                    ceiling,
                    ..INTERFACE
                };
                interface::uniform_onset(&|e| local(e, top - e), top, dp, &settings)
            }
            Profile::Hertz { peak, width } => {
                let onset = (peak + offset) * (1.0 - 1e-9);
                let contact = HertzContact {
                    peak,
                    offset,
                    width,
                };
                match interface::hertz_local(local, contact, onset, &INTERFACE).flow {
                    InterfaceFlow::Conducting(Conduction::Series { resistance }) => {
                        Conduction::Series {
                            resistance: resistance * dp / onset,
                        }
                    }
                    _ => Conduction::Series {
                        resistance: f64::INFINITY,
                    },
                }
            }
        };
        service.leak_rate(geometry, conduction)
    }

    /// Internal step ends in (from, to]: `to`, plus eight per shortest temperature cycle,
    /// the knots of a temperature table and those of the pressure history (docs/model.md §8.4:
    /// every change of the pressure's slope is a step).
    fn substeps(&self, from: f64, to: f64) -> Vec<f64> {
        let h = self.problem.environment.shortest_period().map(|p| p / 8.0);
        let mut v: Vec<f64> = self.problem.environment.knots_between(from, to).collect();
        if let Some(pressure) = &self.problem.pressure {
            v.extend(pressure.knots(from, to));
        }
        if let Some(h) = h {
            let first = (from / h).floor() + 1.0;
            let mut k = first;
            while k * h < to {
                v.push(k * h);
                k += 1.0;
            }
        }
        v.push(to);
        v.sort_by(f64::total_cmp);
        v.dedup();
        self.thermal_substeps(from, v)
    }

    /// With a temperature-dependent squeeze (thermal strain under displacement loading), the
    /// strain is linear in *time* within a piece, while the exact Prony update wants it linear
    /// in *reduced* time: each piece is split so that within it log10 a_T changes by at most
    /// [`MAX_STEP_LOG_SHIFT`] (a_T nearly constant, so ξ nearly linear in t) and the
    /// temperature by at most [`MAX_STEP_TEMPERATURE`]. Without thermal strain nothing is
    /// added. (Without this split a 65 K cold snap within one step, a_T changing by 11 decades,
    /// was treated as if the unloading happened at the warm end and relaxed away.)
    fn thermal_substeps(&self, from: f64, ends: Vec<f64>) -> Vec<f64> {
        let p = self.problem;
        if p.thermal_strain.is_none()
            || p.loading != Loading::Displacement
            || p.environment.is_constant()
        {
            return ends;
        }
        let temperature = |t: f64| p.environment.at(t);
        let log_shift = |t: f64| p.material.shift.log10_factor(temperature(t));
        let mut out = Vec::with_capacity(ends.len());
        let mut a = from;
        for b in ends {
            let m = 0.5 * (a + b);
            let (ta, tm, tb) = (temperature(a), temperature(m), temperature(b));
            let d_temperature = (tb - ta)
                .abs()
                .max(2.0 * (tm - ta).abs())
                .max(2.0 * (tb - tm).abs());
            let (la, lb) = (log_shift(a), log_shift(b));
            let by_shift = match (la.is_finite(), lb.is_finite()) {
                (true, true) => (lb - la).abs() / MAX_STEP_LOG_SHIFT,
                // frozen at one end: a_T diverges inside, follow the temperature closely
                (true, false) | (false, true) => d_temperature / MAX_STEP_TEMPERATURE_FROZEN_EDGE,
                // frozen throughout: nothing relaxes, the update is exact
                (false, false) => 0.0,
            };
            let pieces = (d_temperature / MAX_STEP_TEMPERATURE)
                .max(by_shift)
                .ceil()
                .clamp(1.0, MAX_THERMAL_PIECES);
            let n = pieces as usize;
            for k in 1..n {
                out.push(a + (b - a) * k as f64 / pieces);
            }
            out.push(b);
            a = b;
        }
        out
    }

    /// Advances the hereditary states from `state.time` to `t`; leaves `state.time`. The update
    /// of [`Self::update_mechanics`] is exact for a load linear in ξ; a temperature-dependent
    /// squeeze (thermal strain under displacement loading) is linear in *time* on a ramp, so
    /// there the step is split with an error control (step doubling on the sealing stress to
    /// [`MECHANICS_RTOL`] × tolerance; the update is second order in the piece, so halving a piece quarters
    /// its error) until the load is as good as linear in ξ within each piece — the mechanics,
    /// hence the force, the contact pressure and any lift-off they decide, do not depend on the
    /// time steps (docs/model.md §10.1).
    fn advance_mechanics(&self, state: &mut Mechanics, t: f64) {
        let p = self.problem;
        if p.thermal_strain.is_none()
            || p.loading != Loading::Displacement
            // a constant temperature holds the thermal strain: the update is exact
            || p.environment.constant_on(state.time, t).is_some()
            || t <= state.time
        {
            return self.update_mechanics(state, t);
        }
        let floor = 1e-9 * p.material.prony.instantaneous() * self.load0.abs();
        self.advance_mechanics_controlled(state, t, floor, 0, (None, None));
    }

    /// [`Self::advance_mechanics`]'s error control on one piece `state.time → t`. `whole`: the
    /// one-step update `state → t` if already made (a split piece's left half is its parent's
    /// first half step: the same bits, not recomputed); `span`: the piece's [`Increment`] if
    /// already integrated (a split piece's halves were). The one-step update takes the sum of
    /// the halves' increments (ξ and K are additive): each stretch of the history is integrated
    /// once, not three times.
    fn advance_mechanics_controlled(
        &self,
        state: &mut Mechanics,
        t: f64,
        floor: f64,
        depth: u32,
        (whole, span): (Option<Mechanics>, Option<Increment>),
    ) {
        let prony = &self.problem.material.prony;
        let a = state.time;
        let m = 0.5 * (a + t);
        let (left, right) = (self.increment(a, m), self.increment(m, t));
        let one = whole.unwrap_or_else(|| {
            let mut one = state.clone();
            self.apply_mechanics(&mut one, t, span.unwrap_or(left.then(right)));
            one.time = t;
            one
        });
        let mut half = state.clone();
        self.apply_mechanics(&mut half, m, left);
        half.time = m;
        let mut two = half.clone();
        self.apply_mechanics(&mut two, t, right);
        two.time = t;
        let (s1, s2) = (one.relaxation.stress(prony), two.relaxation.stress(prony));
        if depth >= MECHANICS_MAX_DEPTH
            || !(m > a && m < t)
            || (s1 - s2).abs() <= MECHANICS_RTOL * self.problem.time.tolerance * (s2.abs() + floor)
        {
            let time = state.time;
            *state = two;
            state.time = time;
            return;
        }
        let time = state.time;
        self.advance_mechanics_controlled(state, m, floor, depth + 1, (Some(half), Some(left)));
        state.time = m;
        self.advance_mechanics_controlled(state, t, floor, depth + 1, (None, Some(right)));
        state.time = time;
    }

    /// One exact update of the hereditary states from `state.time` to `t` (exact for strain
    /// linear in ξ over the step, and at constant strain for the chemical ageing); leaves
    /// `state.time`.
    fn update_mechanics(&self, state: &mut Mechanics, t: f64) {
        let step = self.increment(state.time, t);
        self.apply_mechanics(state, t, step);
    }

    /// The reduced time and the scission over `[a, b]` (the two integrals over the temperature
    /// history a mechanical update needs).
    fn increment(&self, a: f64, b: f64) -> Increment {
        let p = self.problem;
        Increment {
            reduced_time: reduced_time(&p.environment, &p.material.shift, a, b),
            scission: p
                .ageing
                .as_ref()
                .map_or(0.0, |ag| ag.scission(&p.environment, a, b)),
        }
    }

    /// [`Self::update_mechanics`] with the step's integrals `step` over `[state.time, t]`.
    fn apply_mechanics(&self, state: &mut Mechanics, t: f64, step: Increment) {
        let p = self.problem;
        let prony = &p.material.prony;
        let d_xi = step.reduced_time;
        let temperature = p.environment.at(t);
        let d_load = match p.loading {
            Loading::Displacement => {
                p.geometry
                    .load_variable(p.thermal_strain.as_ref(), temperature)
                    - state.relaxation.strain()
            }
            Loading::Force => 0.0,
        };
        let chem = ChemicalStep {
            scission: step.scission,
            crosslinking: p.ageing.as_ref().map_or(0.0, |ag| ag.crosslinking),
        };
        let network_before = state.relaxation.network();
        state.relaxation.step_aged(prony, d_xi, d_load, chem);
        state.installation.step_aged(prony, d_xi, 0.0, chem);
        if p.loading == Loading::Displacement {
            let d_strain = p
                .geometry
                .deformation(p.thermal_strain.as_ref(), temperature)
                - state.networks.strain();
            state.networks.step_aged(prony, d_xi, d_strain, chem);
        }
        state.reduced_time += d_xi;
        let e_inf = prony.long_term();
        if chem.scission > 0.0 && e_inf > 0.0 {
            // under σ = 1: x = (1/E∞ + y)/c and dy/dK = r x − y = r/(E∞ c) + (r/c − 1) y,
            // solved with c at the step's middle (exact for r = 1, where c = 1: y = K/E∞)
            let (r, d_k) = (chem.crosslinking, chem.scission);
            let c = 0.5 * (network_before + state.relaxation.network());
            let (a, b) = (r / (e_inf * c), r / c - 1.0);
            let y = state.creep_set;
            // y + (a + b y)(e^{b ΔK} − 1)/b, without cancellation for small b ΔK
            let growth = if (b * d_k).abs() < 1e-12 {
                d_k
            } else {
                (b * d_k).exp_m1() / b
            };
            state.creep_set = y + (a + b * y) * growth;
        }
    }

    /// Advances the mechanical state to time `t` (exact for strain linear in ξ over the step).
    /// Returns the snapshot at the new time (computed once: the leaked volume needs it).
    fn advance(&self, state: &mut Mechanics, t: f64, before: &Snapshot) -> Snapshot {
        let (a, b) = (state.time, t);
        self.advance_mechanics(state, t);
        let p = self.problem;
        let after = match &p.contamination {
            None => self.snapshot_at(state, b),
            Some(c) => {
                let open = self.with_reach(self.open_snapshot_at(state, b));
                self.integrate_clogging(c, state, b, before, &open);
                self.clogged(open, state)
            }
        };
        let volume = events::integrate_power_law(a, before.leak_rate, b, after.leak_rate);
        state.leaked_volume += volume;
        if let Some(c) = &p.contamination {
            // the cake grows with the fluid that carried its particles (explicit: the step's
            // end snapshot used the cake at the step's start)
            self.deposit(c, state, &after, volume);
        }
        state.time = b;
        after
    }

    fn snapshot(&self, state: &Mechanics) -> Snapshot {
        self.snapshot_at(state, state.time)
    }

    /// The snapshot at `t` with the state's open fraction applied.
    fn snapshot_at(&self, state: &Mechanics, t: f64) -> Snapshot {
        let open = self.open_snapshot_at(state, t);
        if self.problem.contamination.is_none() {
            return open;
        }
        self.clogged(self.with_reach(open), state)
    }

    /// Profile, asperity modulus, junctions and leak rate at the state's time `t`, with all
    /// critical channels open.
    fn open_snapshot_at(&self, state: &Mechanics, t: f64) -> Snapshot {
        let p = self.problem;
        let temperature = p.environment.at(t);
        let dp = p.pressure_at(t);
        let permeation = p.permeation.as_ref().map(|s| match &p.pressure {
            // the inlet pressure of the history at t (docs/model.md §8.4, §13.7)
            Some(_) => s.throughput_at(t, temperature, s.p_low + dp),
            None => s.throughput(t, temperature),
        });
        let permeation_flow = match (permeation, p.fluid.mean_pressure()) {
            (Some(q), Some(mean)) if mean > 0.0 => q / mean,
            _ => 0.0,
        };
        let profile = self.profile_at(state, t);
        let retained = profile.force_per_length() / self.reference_force;
        let moduli = self.asperity_moduli(state);
        let e_asperity = moduli.fluid;
        let e_star = e_asperity / (1.0 - p.material.poisson_ratio.powi(2));
        let leak = self.profile_leak(&profile, moduli, temperature, t);
        let viscosity = p.fluid.viscosity_at(temperature);
        let equivalent = moduli.equivalent(&profile);
        let (leak_rate, peak_junction) = (leak.leak_rate, leak.junction);
        // the junction's own reduced pressure (the energised peak less the fluid pressure there)
        let junction_s = leak.junction_pressure / e_star;
        let u_c = peak_junction.leaking().map(|j| j.u_c);
        let lambda_c = peak_junction.leaking().map_or(0.0, |j| j.lambda_c);
        // (motion, the open static leak, the leak rate, the flow through the critical channels)
        let (motion, open_static_leak_rate, leak_rate, channel_rate) = match &self.drag {
            None => (None, None, leak_rate, leak_rate),
            Some((spec, table)) => {
                let static_rate = if leak_rate.is_finite() {
                    leak_rate
                } else {
                    0.0
                };
                let s = junction_s;
                // a critical gap below a molecule carries no film either (§8.1), also where
                // the strips the fluid pressure relieves leak
                let below_molecule = peak_junction.leaking().is_some_and(|j| {
                    !crate::fluid::passes_molecule(j.u_c, p.fluid.molecular_size())
                });
                let junction = match self.path {
                    _ if leak.state == SealState::BelowMolecule || below_molecule => {
                        Junction::Sealed
                    }
                    ContactPath::Table(_) | ContactPath::Exact(_) => peak_junction,
                    _ => self.path.persson_junction(s),
                };
                let seal = spec.seal(
                    Elastic {
                        youngs_modulus: e_asperity,
                        poisson_ratio: p.material.poisson_ratio,
                    },
                    FlatSeal {
                        nominal_pressure: self.contact_peak(&equivalent, dp),
                        width: profile.width(),
                        length: p.geometry.sealing_length(),
                    },
                    viscosity,
                    p.shape_factor,
                );
                let oring = p
                    .geometry
                    .pressure_from_squeeze()
                    .then(|| (seal.seal.nominal_pressure, profile.width(), dp));
                let ihl = crate::dynamic::IhlInput {
                    gradients: spec.gradients_for(oring),
                    viscosity,
                    sealing_length: p.geometry.sealing_length(),
                    roughness: p.spectrum.rms_roughness(),
                };
                let point =
                    spec.evaluate(&table.coefficients(s, &junction, &seal), static_rate, &ihl);
                if spec.is_stroke() {
                    // the cycle-averaged leak once the IHL film has weight (docs/model.md §3.4.1)
                    // The film rides over the whole contact, not through the critical
                    // channels: those carry the static leak (and the particles to clog them).
                    let mean = point.cycle_mean_leak_rate().unwrap_or(leak_rate);
                    (Some(point), Some(static_rate), mean, static_rate)
                } else {
                    let total = static_rate + point.drag_leak_rate;
                    (Some(point), Some(static_rate), total, total)
                }
            }
        };
        let compression_set = self.compression_set(state);
        let shutdown = self.shutdown(state);
        let state = leak.state_with(leak_rate);
        let leak_rate = if leak_rate.is_finite() {
            leak_rate
        } else {
            0.0
        };
        Snapshot {
            temperature,
            profile,
            u_c,
            peak_junction,
            groove_junction: leak.groove_junction,
            leak_rate,
            state,
            retained,
            compression_set,
            shutdown,
            open_leak_rate: if channel_rate.is_finite() {
                channel_rate
            } else {
                0.0
            },
            open_u_c: u_c.unwrap_or(0.0),
            lambda_c,
            peak_reduced_pressure: junction_s,
            reach: 0.0,
            entry_gap: 0.0,
            cake_factor: 1.0,
            capture: clogging::Capture::default(),
            extrusion: p.extrusion_at(temperature, dp),
            open_fraction: 1.0,
            motion,
            open_static_leak_rate,
            permeation,
            permeation_flow,
            pressure_difference: dp,
        }
    }

    /// The peak contact pressure of `profile` with the energisation k_e ΔP at the pressure
    /// difference `dp` \[Pa\].
    fn contact_peak(&self, profile: &Profile, dp: f64) -> f64 {
        profile.peak() + self.problem.energisation_factor * dp
    }

    /// The peak contact pressure of a snapshot with the energisation at its own ΔP \[Pa\].
    fn snap_peak(&self, snap: &Snapshot) -> f64 {
        self.contact_peak(&snap.profile, snap.pressure_difference)
    }

    /// A gas under a pressure history: its volume flow at the mean pressure p̄(t) of `service`
    /// restated at the service's p̄ (the run's fluid), `p̄(t)/p̄`, so that the leak rates of a run
    /// are throughputs over one pressure and integrate to an amount of gas (docs/model.md §8.4);
    /// 1 for a liquid and without a history.
    fn gas_volume_scale(&self, service: &crate::fluid::Fluid) -> f64 {
        let p = self.problem;
        match (
            &p.pressure,
            service.mean_pressure(),
            p.fluid.mean_pressure(),
        ) {
            (Some(_), Some(now), Some(mean)) if mean > 0.0 => now / mean,
            _ => 1.0,
        }
    }

    /// The moduli the asperity contact sees (docs/model.md §6.1). `follow`: the squeeze's part
    /// of the contact pressure is held by displacement, so its modulus is the stress response to
    /// the installation alone per unit load (P0/E* then stays as installed at a fixed squeeze,
    /// ageing included); the fluid's part (and all of a force-loaded seal's) is a load held
    /// since the installation (ramped with the squeeze), so its modulus is 1/J, the creep
    /// compliance J(ξ) (its mean over the ramp, [`crate::material::Creep::ramp_compliance`]) with the two-network
    /// ageing's chemical creep: `J_aged = J(ξ) − 1/E∞ + (1/E∞ + y)/c` (y = `creep_set`, c the
    /// crosslink fraction; J(ξ) unaged). The other options use one fixed modulus for both.
    fn asperity_moduli(&self, state: &Mechanics) -> AsperityModuli {
        let prony = &self.problem.material.prony;
        let one = |e: f64| AsperityModuli {
            squeeze: e,
            fluid: e,
        };
        match self.problem.asperity_modulus {
            AsperityModulus::Relaxed => one(prony.long_term()),
            AsperityModulus::Instantaneous => one(prony.instantaneous()),
            AsperityModulus::Fixed(e) => one(e),
            AsperityModulus::Follow => {
                // the fluid pressure is applied with the squeeze, ramped over the installation
                let ramp = self.problem.installation_reduced_time();
                let compliance = if ramp > 0.0 {
                    self.creep
                        .ramp_compliance_with(state.reduced_time, ramp, &self.ramp_weights)
                } else {
                    self.creep.ramp_compliance(state.reduced_time, ramp)
                };
                let e_inf = prony.long_term();
                let c = state.relaxation.network();
                let aged = if e_inf > 0.0 && (c != 1.0 || state.creep_set != 0.0) {
                    compliance - 1.0 / e_inf + (1.0 / e_inf + state.creep_set) / c
                } else {
                    compliance
                };
                let fluid = 1.0 / aged;
                match self.problem.loading {
                    Loading::Displacement => AsperityModuli {
                        squeeze: state.installation.stress(prony),
                        fluid,
                    },
                    Loading::Force => one(fluid),
                }
            }
        }
    }

    fn row(&self, state: &Mechanics, snap: &Snapshot) -> HistoryRow {
        let p = self.problem;
        HistoryRow {
            time: state.time,
            temperature: snap.temperature,
            reduced_time: state.reduced_time,
            shift_factor: p.material.shift.factor(snap.temperature),
            sealing_force: snap.profile.force_per_length(),
            peak_pressure: self.snap_peak(snap),
            pressure_difference: snap.pressure_difference,
            mean_pressure: snap.profile.mean(),
            contact_width: snap.profile.width(),
            u_c: snap.u_c,
            leak_rate: snap.leak_rate,
            permeation: snap.permeation,
            leaked_volume: state.leaked_volume,
            state: snap.state,
            compression_set: snap.compression_set,
            shutdown: snap.shutdown,
            open_fraction: snap.open_fraction,
            motion: snap.motion,
        }
    }

    /// The earliest criterion crossed between two steps, each located by bisection on the
    /// exact state update to 1e-12 relative in time. Criteria crossed within
    /// [`events::SIMULTANEOUS_EVENTS`] of that time (relative; looked for on the state advanced
    /// that far, which may lie beyond `after`) count as simultaneous: the event keeps the
    /// earliest time and takes the mode that comes first in the tie order
    /// ([`FailureCriteria::MODES`]: the damage first) — so that a leak rate that crosses its limit
    /// seconds before the lift-off that causes it is reported as the lift-off, at every fidelity
    /// and time step (docs/model.md §8).
    fn locate_failure(
        &self,
        before: &Mechanics,
        before_snap: &Snapshot,
        after: &Mechanics,
        after_snap: &Snapshot,
    ) -> Option<FailureEvent> {
        let criteria = &self.problem.failure;
        let start = before_snap.as_event_input(before.leaked_volume);
        let modes = criteria.newly_crossed(&start, &after_snap.as_event_input(after.leaked_volume));
        let earliest = modes
            .into_iter()
            .map(|mode| {
                let (mut lo, mut hi) = (before.time, after.time);
                for _ in 0..200 {
                    if hi - lo <= 1e-12 * hi {
                        break;
                    }
                    let mid = stepping::midpoint(lo, hi);
                    if !(mid > lo && mid < hi) {
                        break;
                    }
                    let mut trial = before.clone();
                    let snap = self.advance(&mut trial, mid, before_snap);
                    if criteria.crossed(mode, &snap.as_event_input(trial.leaked_volume)) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                FailureEvent { time: hi, mode }
            })
            .min_by(|a, b| a.time.total_cmp(&b.time))?;
        let window =
            (earliest.time * (1.0 + events::SIMULTANEOUS_EVENTS)).min(self.problem.time.duration);
        let mut trial = before.clone();
        let snap = self.advance(&mut trial, window, before_snap);
        let mode = criteria
            .newly_crossed(&start, &snap.as_event_input(trial.leaked_volume))
            .into_iter()
            .chain(std::iter::once(earliest.mode))
            .min_by_key(|&m| criteria.precedence(m))
            .unwrap_or(earliest.mode);
        Some(FailureEvent {
            time: earliest.time,
            mode,
        })
    }

    /// Records the validity findings of one step (docs/model.md §9): the rubber's
    /// temperature and squeeze, the contact state of the peak strip, the sliding speed.
    fn assess(&self, state: &Mechanics, snap: &Snapshot, findings: &mut Findings) {
        let p = self.problem;
        let at = At::Time(state.time);
        p.assess_rubber(snap.temperature, at, findings);
        validity::contact_width(snap.profile.width(), p.spectrum.q0(), at, findings);
        validity::data_window(
            state.reduced_time,
            snap.temperature,
            p.material.data_reduced_time,
            p.material.data_temperature,
            at,
            findings,
        );
        validity::contact(
            &ContactState {
                nominal_pressure: self.snap_peak(snap),
                pressure_difference: snap.pressure_difference,
                // lifted off, the contact is open: no contact limit applies (the verdict says lift_off)
                junction: if snap.state == SealState::LiftOff {
                    &Junction::Sealed
                } else {
                    &snap.peak_junction
                },
                cutoff: p.spectrum.q1() / p.spectrum.q0(),
                lifted_off: snap.state == SealState::LiftOff,
            },
            at,
            findings,
        );
        // a gas: its regime at the critical constriction of each leaking interface (docs/model.md
        // §9.14)
        if snap.state != SealState::LiftOff {
            for j in [Some(&snap.peak_junction), snap.groove_junction.as_ref()]
                .into_iter()
                .flatten()
                .filter_map(Junction::leaking)
            {
                if let Some(kn) = p.fluid.at(snap.temperature).knudsen(j.u_c) {
                    validity::knudsen(kn, p.fluid.mean_free_path().is_some(), at, findings);
                }
            }
        }
        if let Some((ratio, limit)) = &snap.extrusion {
            validity::extrusion(*ratio, limit, at, findings);
        }
        if let (Some((spec, _)), Some(m)) = (&self.drag, snap.motion) {
            validity::motion(spec.fastest_speed(), &m, at, findings);
        }
    }
}

impl Snapshot {
    fn as_event_input(&self, leaked_volume: f64) -> events::EventInput {
        events::EventInput {
            // a gas's criterion is on what a detector sees: interface + permeation (§8)
            leak_rate: self.leak_rate + self.permeation_flow,
            leaked_volume,
            retained_force: self.retained,
            compression_set: self.compression_set.unwrap_or(0.0),
            lifted: self.state.is_open(),
            lost_interference: self.shutdown.is_some_and(|s| !s.holds),
            extruded: self
                .extrusion
                .is_some_and(|(ratio, limit)| ratio > 1.0 || limit.over_rated),
            sealing_force: self.profile.force_per_length(),
            contact_peak: self.profile.peak(),
            contact_mean: self.profile.mean(),
            pressure_difference: self.pressure_difference,
            temperature: self.temperature,
        }
    }
}

impl LifeProblem {
    /// When the rubber first went colder than the cold limit (docs/model.md §8.3) \[s\]: the
    /// located failure time when `low_temperature` is `result`'s failure, else the first time
    /// the temperature history goes below `T10 − margin` within the run (`None`: never, or
    /// no cold limit).
    pub fn cold_limit_crossed(&self, result: &LifeResult) -> Option<f64> {
        let limit = self.failure.low_temperature?;
        result
            .failure
            .filter(|f| f.mode == FailureMode::LowTemperature)
            .map(|f| f.time)
            .or_else(|| {
                self.environment
                    .first_below(limit.threshold(), 0.0, self.time.duration)
            })
    }
}

/// Runs a life problem (convenience wrapper around [`Simulator`]).
pub fn simulate(problem: &LifeProblem) -> LifeResult {
    Simulator::new(problem).run()
}
