//! The seal-life time loop (docs/model.md §1, §3.2, §5–6, §8).
//!
//! Each step: temperature T(t) → reduced time ξ (exact for constant T, adaptive quadrature
//! otherwise) → squeeze ε(t) with thermal strain → exact Prony update of the hereditary
//! sealing stress on Lindley's squeeze function g(ε) → optional ageing factor
//! `exp(−∫ k(T) dt)` → nominal pressure profile → asperity modulus → critical junction of each
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

pub mod events;

use std::cell::RefCell;

use crate::clogging::{Contamination, effective_threshold};
use crate::contact::{ContactSettings, CriticalJunction, Elastic, Junction, PerssonContact};
use crate::dynamic::{DragSettings, DragTable, MotionPoint, MotionSpec};
use crate::fluid::{Conduction, Fluid};
use crate::leak::{ContactPath, Fidelity, FlatSeal};
use crate::material::shift::reduced_time;
use crate::material::{Ageing, Material, RelaxationState, Shift, TemperatureHistory};
use crate::math::quadrature::gauss_legendre;
use crate::seal::{Profile, SealGeometry, oring_contact_width, squeeze_function};
use crate::surface::Spectrum;
use crate::validity::{self, At, ContactState, Findings};
pub use events::{FailureCriteria, FailureEvent, FailureMode};

/// Quadrature of the re-routing junctions: both u_c(a_eff) and u_c(a_c) of the ratio
/// `(u_c(a_eff)/u_c(a_c))³` use it, so its error (≈ 6e-5 in u_c, measured against the default
/// rule on the paper's surface) largely cancels, at a third of the cost.
const REROUTE_QUADRATURE: crate::contact::QuadratureSettings = crate::contact::QuadratureSettings {
    panel_width: 2.0,
    order: 4,
};

/// Spacing in ln f of the nodes at which the re-routing ratio is computed within one step
/// (linear interpolation between them: error ≈ h²/8 · R″, below 1e-6 relative).
const REROUTE_NODE_SPACING: f64 = 1e-3;

/// Largest temperature change within one internal step when the squeeze depends on the
/// temperature \[K\].
const MAX_STEP_TEMPERATURE: f64 = 10.0;
/// Largest change of log10 a_T within one internal step when the squeeze depends on the
/// temperature.
const MAX_STEP_LOG_SHIFT: f64 = 0.5;
/// Largest temperature change within one internal step that crosses the WLF frozen limit
/// (where a_T is infinite at one end) \[K\].
const MAX_STEP_TEMPERATURE_FROZEN_EDGE: f64 = 1.0;
/// Upper bound of the pieces one internal step is split into for the thermal strain.
const MAX_THERMAL_PIECES: f64 = 10_000.0;

/// Which modulus the asperity contact sees (docs/model.md §6).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AsperityModulus {
    /// E∞, the low-frequency modulus PY08 uses (conservative). The default.
    Relaxed,
    /// E0.
    Instantaneous,
    /// The bulk's own relaxation: E(ξ(t)) under displacement loading, 1/J(ξ(t)) under force
    /// loading (the contact creeps under a constant load).
    Follow,
    /// A fixed modulus \[Pa\].
    Fixed(f64),
}

/// How the seal is held.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Loading {
    /// Fixed squeeze (O-ring in a groove): the sealing force relaxes.
    Displacement,
    /// Fixed load (spring-loaded): the sealing force stays.
    Force,
}

/// Thermal strain of an O-ring: the cord expands with the rubber's CTE, the groove depth with
/// the housing's. `ε(T) = ε0 + (α_r − α_h (1 − ε0)) (T − T_install)` (first order).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalStrain {
    /// Rubber linear CTE α_r \[1/K\].
    pub rubber_expansion: f64,
    /// Housing linear CTE α_h \[1/K\].
    pub housing_expansion: f64,
    /// Installation temperature \[K\].
    pub installation_temperature: f64,
}

/// The output/evaluation grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeGrid {
    /// First time after installation \[s\] (> 0).
    pub start: f64,
    /// Last time \[s\] (> start).
    pub duration: f64,
    /// Log-uniform points per decade.
    pub points_per_decade: f64,
}

impl TimeGrid {
    /// 0, then `start · 10^{k/n}` up to `duration` (which is always the last point).
    pub fn times(&self) -> Vec<f64> {
        let mut t = vec![0.0];
        let decades = (self.duration / self.start).log10();
        let n = (decades * self.points_per_decade).ceil().max(1.0) as usize;
        for k in 0..n {
            t.push(self.start * 10f64.powf(decades * k as f64 / n as f64));
        }
        t.push(self.duration);
        t
    }
}

/// A seal-life problem in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct LifeProblem {
    pub material: Material,
    pub asperity_modulus: AsperityModulus,
    pub spectrum: Spectrum,
    pub contact: ContactSettings,
    pub shape_factor: f64,
    pub fluid: Fluid,
    pub geometry: SealGeometry,
    pub loading: Loading,
    pub environment: TemperatureHistory,
    pub thermal_strain: Option<ThermalStrain>,
    pub ageing: Option<Ageing>,
    pub failure: FailureCriteria,
    pub time: TimeGrid,
    pub fidelity: Fidelity,
    /// Gauss–Legendre points across the Hertz profile (strips in series).
    pub strips: usize,
    /// Particle clogging of the critical constrictions (`None`: clean fluid, zero cost).
    pub contamination: Option<Contamination>,
    /// The countersurface's motion (`[motion]`, PY08 §8; `None`: a static seal, zero cost).
    pub motion: Option<MotionSpec>,
}

impl LifeProblem {
    /// The nominal pressure profile right after installation (t = 0): the instantaneous
    /// modulus E0 on the load at the temperature T(0) (Lindley force and Hertz profile for an
    /// O-ring, including the thermal strain at T(0); the given nominal pressure for a flat seal).
    pub fn initial_profile(&self) -> Profile {
        let t0 = self.environment.at(0.0);
        profile_for(
            self,
            self.material.prony.instantaneous() * load_variable(self, t0),
            t0,
        )
    }

    /// Records the findings of the installation state (t = 0) into `out`: the temperature
    /// against the glass transition and the WLF frozen limit, an O-ring's squeeze against
    /// Lindley's range (docs/model.md §9.6–§9.7). A life run evaluates the same at every step.
    pub fn assess_installation(&self, out: &mut Findings) {
        self.assess_rubber(self.environment.at(0.0), At::Installation, out);
    }

    /// The rubber's temperature `t` \[K\] and, for an O-ring, its squeeze at `t`.
    fn assess_rubber(&self, t: f64, at: At, out: &mut Findings) {
        if let SealGeometry::ORing { .. } = self.geometry {
            validity::squeeze(squeeze_at(self, t), at, out);
        }
        validity::temperature(
            t,
            self.material.glass_transition,
            self.material.shift.frozen_below(),
            at,
            out,
        );
    }
}

/// State of the interface at one time.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SealState {
    Leaking,
    /// No channel percolates (somewhere across the width).
    Sealed,
    /// The peak contact pressure is below the fluid pressure: the seal opens; the leak rate
    /// shown is the model's, which no longer applies.
    LiftOff,
}

impl SealState {
    pub fn as_str(self) -> &'static str {
        match self {
            SealState::Leaking => "leaking",
            SealState::Sealed => "sealed",
            SealState::LiftOff => "lift_off",
        }
    }
}

/// One row of the history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryRow {
    pub time: f64,
    pub temperature: f64,
    pub reduced_time: f64,
    pub shift_factor: f64,
    /// Sealing force per unit length \[N/m\].
    pub sealing_force: f64,
    pub peak_pressure: f64,
    pub mean_pressure: f64,
    pub contact_width: f64,
    /// Height of the critical constriction at the peak pressure \[m\]; `None` when sealed there.
    pub u_c: Option<f64>,
    pub leak_rate: f64,
    pub leaked_volume: f64,
    pub state: SealState,
    /// Open fraction f of the critical channels (1 without contamination).
    pub open_fraction: f64,
    /// `[motion]`: drag, film, speed bound and stroke volumes at the peak strip (`None` for a
    /// static seal). Constant sliding: `drag_leak_rate` is included in `leak_rate`; a stroke
    /// cycle: it is the out-stroke's instantaneous drag, not included (`leak_rate` is the
    /// static, cycle-averaged one).
    pub motion: Option<MotionPoint>,
}

/// The result of a life run.
#[derive(Debug, Clone, PartialEq)]
pub struct LifeResult {
    pub rows: Vec<HistoryRow>,
    pub failure: Option<FailureEvent>,
    /// The validity limits crossed during the run, each once with its worst value and when
    /// (docs/model.md §9.11).
    pub findings: Findings,
}

impl LifeResult {
    pub fn initial_leak_rate(&self) -> f64 {
        self.rows.first().map_or(0.0, |r| r.leak_rate)
    }

    pub fn final_leak_rate(&self) -> f64 {
        self.rows.last().map_or(0.0, |r| r.leak_rate)
    }

    pub fn leaked_volume(&self) -> f64 {
        self.rows.last().map_or(0.0, |r| r.leaked_volume)
    }

    /// Open fraction of the critical channels at the end of the run (1 when clean).
    pub fn final_open_fraction(&self) -> f64 {
        self.rows.last().map_or(1.0, |r| r.open_fraction)
    }

    /// Leak rate at time `t` \[s\], interpolated as a power law between rows (0 outside).
    pub fn leak_rate_at(&self, t: f64) -> Option<f64> {
        let k = self.rows.partition_point(|r| r.time < t);
        let b = self.rows.get(k)?;
        if k == 0 || b.time == t {
            return Some(b.leak_rate);
        }
        let a = &self.rows[k - 1];
        Some(events::interpolate_power_law(
            a.time,
            a.leak_rate,
            b.time,
            b.leak_rate,
            t,
        ))
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
    leak_rate: f64,
    state: SealState,
    retained: f64,
    /// Leak rate with all critical channels open \[m³/s\] (= `leak_rate` when clean).
    open_leak_rate: f64,
    /// u_c at the peak strip with all channels open \[m\] (0 when sealed there).
    open_u_c: f64,
    /// λ_c at the peak strip with all channels open \[m\] (0 when sealed there).
    lambda_c: f64,
    /// Peak reduced pressure P_peak/E*.
    peak_reduced_pressure: f64,
    /// Open fraction f the leak rate was evaluated with.
    open_fraction: f64,
    /// `[motion]`: the motion quantities at the peak strip (all channels open until
    /// [`Simulator::clogged`] scales them).
    motion: Option<MotionPoint>,
    /// `[motion]`, constant sliding: the pressure-driven part of `open_leak_rate` \[m³/s\]
    /// (`open_leak_rate` = this + the drag); `None` otherwise.
    open_static_leak_rate: Option<f64>,
}

/// The mechanical state carried along the time loop.
#[derive(Debug, Clone)]
struct Mechanics {
    time: f64,
    reduced_time: f64,
    relaxation: RelaxationState,
    /// ∫ k(T)/k_ref dt, for the ageing factor.
    ageing_time: f64,
    leaked_volume: f64,
    /// ln f, the log of the open fraction of the critical channels (0 when clean; −∞ when
    /// every channel is blocked).
    log_open_fraction: f64,
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
    initial_profile: Profile,
    creep: crate::material::Creep,
    /// The exact contact path for re-routed clogging (junctions at other thresholds), on a
    /// coarser quadrature ([`REROUTE_QUADRATURE`]).
    rerouting: Option<PerssonContact>,
    /// The last `(s, u_c(s, a_c))` of the re-routing reference junction: a step's ratio nodes
    /// and its end snapshot share one pressure, hence one reference evaluation.
    reference_memo: std::cell::Cell<Option<(f64, Option<f64>)>>,
    /// `[motion]`: the motion and the table of I (built once; `None` for a static seal).
    drag: Option<(MotionSpec, DragTable)>,
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
        ContactPath::new(&problem.spectrum, problem.contact, problem.fidelity)
    }

    /// Prepares the run with a contact path built beforehand by [`Self::contact_path`] for a
    /// problem with the same surface, contact settings and fidelity.
    pub fn with_path(problem: &'a LifeProblem, path: ContactPath) -> Self {
        let load0 = load_variable(problem, problem.environment.at(0.0));
        let initial_profile = problem.initial_profile();
        let rerouting = problem
            .contamination
            .as_ref()
            .filter(|c| c.reroute)
            .map(|_| {
                let settings = ContactSettings {
                    quadrature: REROUTE_QUADRATURE,
                    ..problem.contact
                };
                PerssonContact::new(problem.spectrum.clone(), settings)
            });
        let drag = problem.motion.map(|spec| {
            (
                spec,
                DragTable::build(path.exact(), DragSettings::default()),
            )
        });
        Simulator {
            problem,
            path,
            rule: gauss_legendre(problem.strips.max(2)),
            load0,
            initial_profile,
            creep: problem.material.prony.creep(),
            rerouting,
            reference_memo: std::cell::Cell::new(None),
            drag,
        }
    }

    /// Runs the whole life.
    pub fn run(&self) -> LifeResult {
        let p = self.problem;
        let mut findings = Findings::default();
        if p.failure.is_empty() {
            validity::no_failure_criterion(&mut findings);
        }
        validity::surface(&p.spectrum, &mut findings);
        let mut state = Mechanics {
            time: 0.0,
            reduced_time: 0.0,
            relaxation: RelaxationState::new(&p.material.prony),
            ageing_time: 0.0,
            leaked_volume: 0.0,
            log_open_fraction: 0.0,
            clogged_shut: false,
        };
        // installation: an instantaneous jump of the load variable
        state.relaxation.step(&p.material.prony, 0.0, self.load0);
        let first = self.snapshot(&state);
        self.assess(&state, &first, &mut findings);
        let mut rows = vec![self.row(&state, &first)];
        let mut failure = p.failure.at_start(&first.as_event_input(0.0));
        let mut last = first;

        let outputs = p.time.times();
        for &target in &outputs[1..] {
            for t in self.substeps(state.time, target) {
                let before = state.clone();
                let before_snap = last;
                let snap = self.advance(&mut state, t, &before_snap);
                self.assess(&state, &snap, &mut findings);
                if failure.is_none() {
                    failure = self.locate_failure(&before, &before_snap, &state, &snap);
                }
                last = snap;
            }
            rows.push(self.row(&state, &last));
        }
        LifeResult {
            rows,
            failure,
            findings,
        }
    }

    /// Internal step ends in (from, to]: `to`, plus eight per shortest temperature cycle
    /// and the knots of a temperature table.
    fn substeps(&self, from: f64, to: f64) -> Vec<f64> {
        let h = self.problem.environment.shortest_period().map(|p| p / 8.0);
        let mut v: Vec<f64> = self
            .problem
            .environment
            .knots()
            .filter(|&k| k > from && k < to)
            .collect();
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

    /// Advances the mechanical state to time `t` (exact for strain linear in ξ over the step).
    /// Returns the snapshot at the new time (computed once: the leaked volume needs it).
    fn advance(&self, state: &mut Mechanics, t: f64, before: &Snapshot) -> Snapshot {
        let p = self.problem;
        let (a, b) = (state.time, t);
        let d_xi = reduced_time(&p.environment, &p.material.shift, a, b);
        let d_load = match p.loading {
            Loading::Displacement => {
                load_variable(p, p.environment.at(b)) - state.relaxation.strain()
            }
            Loading::Force => 0.0,
        };
        state.relaxation.step(&p.material.prony, d_xi, d_load);
        state.reduced_time += d_xi;
        if let Some(ag) = &p.ageing {
            let arrhenius = Shift::Arrhenius {
                reference: ag.reference_temperature,
                activation_energy: ag.activation_energy,
            };
            state.ageing_time += reduced_time(&p.environment, &arrhenius, a, b);
        }
        let after = match &p.contamination {
            None => self.snapshot_at(state, b),
            Some(c) => {
                let open = self.open_snapshot_at(state, b);
                self.integrate_clogging(c, state, b, before, &open);
                self.clogged(open, state)
            }
        };
        state.leaked_volume += events::integrate_power_law(a, before.leak_rate, b, after.leak_rate);
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
        self.clogged(open, state)
    }

    /// The leak rate of `open` (all channels open) with the state's open fraction f:
    /// * without re-routing the blocked channels carry nothing, the rest are unchanged:
    ///   `Q̇ = f Q̇_open`;
    /// * with re-routing the blocked channels count as contact, the effective threshold is
    ///   `a_eff = 1 − (1 − a_c)/f` and the next, narrower constriction takes over. The
    ///   strips-in-series open leak rate is scaled by the *peak strip's* ratio
    ///   `(u_c(s_peak, a_eff)/u_c(s_peak, a_c))³` (an approximation: the peak strip dominates
    ///   the series resistance), both junctions by the exact path; 0 when a_eff ≤ 0 or the
    ///   peak strip seals at a_eff.
    fn clogged(&self, mut snap: Snapshot, state: &Mechanics) -> Snapshot {
        let f = if state.clogged_shut {
            0.0
        } else {
            state.log_open_fraction.exp().clamp(0.0, 1.0)
        };
        snap.open_fraction = f;
        if f >= 1.0 {
            return snap;
        }
        let (scale, u_c) = match &self.rerouting {
            None => (f, snap.u_c),
            Some(_) if state.clogged_shut => (0.0, None),
            Some(_) => {
                let (ratio, u_eff) = self.reroute_ratio(snap.peak_reduced_pressure, f);
                (ratio, u_eff)
            }
        };
        snap.u_c = u_c;
        snap.peak_junction = match (snap.peak_junction, u_c) {
            (Junction::Leaking(j), Some(u_c)) => Junction::Leaking(CriticalJunction { u_c, ..j }),
            _ => Junction::Sealed,
        };
        // The drag flows through the same channels: without re-routing the blocked ones carry
        // none of it (× f); with re-routing the film is taken to scale with the constriction
        // height, d = β u_c at fixed β (× the cube root of the u_c³ ratio).
        let drag_scale = if self.rerouting.is_some() {
            scale.cbrt()
        } else {
            scale
        };
        snap.leak_rate = match (snap.open_static_leak_rate, snap.motion) {
            (Some(static_rate), Some(m)) => {
                (static_rate * scale + m.drag_leak_rate * drag_scale).max(0.0)
            }
            _ => (snap.open_leak_rate * scale).max(0.0),
        };
        if !snap.leak_rate.is_finite() {
            snap.leak_rate = 0.0;
        }
        if let (Some((spec, _)), Some(m)) = (&self.drag, snap.motion) {
            let static_rate = match snap.open_static_leak_rate {
                Some(static_rate) => (static_rate * scale).max(0.0),
                None => snap.leak_rate,
            };
            snap.motion = Some(spec.rescale(m, static_rate, drag_scale));
        }
        if snap.state == SealState::Leaking && snap.leak_rate <= 0.0 {
            snap.state = SealState::Sealed;
        }
        snap
    }

    /// `((u_c(s, a_eff)/u_c(s, a_c))³, u_c(s, a_eff))` at the peak reduced pressure `s` and
    /// open fraction `f` (re-routing only; `(0, None)` when the junction seals).
    fn reroute_ratio(&self, s: f64, f: f64) -> (f64, Option<f64>) {
        let Some(exact) = &self.rerouting else {
            return (f, None);
        };
        let a_c = self.problem.contact.percolation_threshold;
        let a_eff = effective_threshold(a_c, f);
        if a_eff.is_nan() || a_eff <= 0.0 {
            return (0.0, None);
        }
        let reference = self.reference_junction(exact, s);
        Self::ratio_against(exact, s, a_eff, reference)
    }

    /// `u_c(s, a_c)` on the re-routing quadrature, remembered for the last `s`.
    fn reference_junction(&self, exact: &PerssonContact, s: f64) -> Option<f64> {
        if let Some((last, u)) = self.reference_memo.get()
            && last == s
        {
            return u;
        }
        let a_c = self.problem.contact.percolation_threshold;
        let u = exact
            .critical_junction_at_threshold(s, a_c)
            .leaking()
            .map(|j| j.u_c);
        self.reference_memo.set(Some((s, u)));
        u
    }

    /// `((u_c(s, a_eff)/u_ref)³, u_c(s, a_eff))` for a given reference `u_ref = u_c(s, a_c)`.
    fn ratio_against(
        exact: &PerssonContact,
        s: f64,
        a_eff: f64,
        reference: Option<f64>,
    ) -> (f64, Option<f64>) {
        match (reference, exact.critical_junction_at_threshold(s, a_eff)) {
            (Some(r), Junction::Leaking(n)) if r > 0.0 => {
                ((n.u_c / r).powi(3).min(1.0), Some(n.u_c))
            }
            _ => (0.0, None),
        }
    }

    /// Integrates the open fraction over one internal step `[before, open]` (docs/model.md §7).
    ///
    /// The state is `y = ln f` (so f = e^y can never overshoot below 0, and a huge
    /// concentration drives y to −∞, f to 0, within the step), with
    /// `dy/dt = −n_p [1 − F(u)] Q̇ / (N_ch f)`, N_ch = L_y/λ_c (λ_c of the critical junction
    /// at the peak strip with all channels open: the channels that carry the flow), and
    /// * without re-routing `Q̇ = f Q̇_open`, u = u_c: `dy/dt = −n_p [1 − F(u_c)] Q̇_open/N_ch`;
    /// * with re-routing `Q̇ = Q̇_open (u_c(a_eff)/u_c(a_c))³` and u = u_c(a_eff) (see
    ///   [`Self::clogged`]); the right side vanishes where the seal closes.
    ///
    /// Inside the step u_c, Q̇_open, λ_c and the peak reduced pressure are interpolated as
    /// power laws in time between the step's ends ([`events::interpolate_power_law`]).
    /// Dopri5 (ode_solvers) with sparse output (only the end state is used; its dense output
    /// extrapolates the last point), rtol = atol = the clogging tolerance on ln f (an
    /// absolute error in ln f is a relative error in f). If the integration fails (a stiff
    /// closure under re-routing, which the explicit method cannot follow) the seal is taken
    /// as clogged shut from there on.
    fn integrate_clogging(
        &self,
        c: &Contamination,
        state: &mut Mechanics,
        b: f64,
        before: &Snapshot,
        after: &Snapshot,
    ) {
        let a = state.time;
        if state.clogged_shut || state.log_open_fraction == f64::NEG_INFINITY || b <= a {
            return;
        }
        let length = self.problem.geometry.sealing_length();
        let system = CloggingOde {
            simulator: self,
            contamination: c,
            a,
            b,
            before,
            after,
            length,
            ratios: RefCell::new(Vec::new()),
        };
        // Nothing captured at the ends: nothing in between either (u_c(t) is a power law,
        // hence monotone, and so is F(u_c(t))), the clean case costs no integration; the
        // midpoint is probed as well for safety.
        let probes = [a, 0.5 * (a + b), b];
        if probes
            .iter()
            .all(|&t| system.rate(t, state.log_open_fraction) == 0.0)
        {
            return;
        }
        let y0 = ode_solvers::Vector1::new(state.log_open_fraction);
        let tol = c.tolerance;
        let mut stepper = ode_solvers::Dopri5::new(system, a, b, b - a, y0, tol, tol);
        stepper.set_output(ode_solvers::OutputType::Sparse);
        let y = match stepper.integrate() {
            Ok(_) => stepper.y_out().last().map(|v| v[0]),
            Err(_) => None,
        };
        match y {
            Some(y) if y.is_finite() => {
                // below e^-745 f underflows: every channel is blocked
                state.log_open_fraction = if y < f64::MIN_POSITIVE.ln() {
                    f64::NEG_INFINITY
                } else {
                    y.min(0.0)
                };
            }
            Some(y) if y == f64::NEG_INFINITY => state.log_open_fraction = y,
            _ => {
                if c.reroute {
                    state.clogged_shut = true;
                } else {
                    state.log_open_fraction = f64::NEG_INFINITY;
                }
            }
        }
    }

    /// Profile, asperity modulus, junctions and leak rate at the state's time `t`, with all
    /// critical channels open.
    fn open_snapshot_at(&self, state: &Mechanics, t: f64) -> Snapshot {
        let p = self.problem;
        let temperature = p.environment.at(t);
        let ageing = p
            .ageing
            .map_or(1.0, |ag| (-ag.rate * state.ageing_time).exp());
        let profile = match p.loading {
            Loading::Displacement => profile_for(
                p,
                state.relaxation.stress(&p.material.prony) * ageing,
                temperature,
            ),
            Loading::Force => self.initial_profile,
        };
        let retained = profile.force_per_length() / self.initial_profile.force_per_length();
        let e_asperity = self.asperity_modulus(state);
        let e_star = e_asperity / (1.0 - p.material.poisson_ratio.powi(2));
        let conductance = |pressure: f64| {
            self.path
                .conductance(pressure / e_star, p.shape_factor, p.fluid.viscosity)
        };
        let resistance = profile.series_resistance(&self.rule, conductance);
        let leak_rate = p.fluid.leak_rate(
            profile.geometry(p.geometry.sealing_length()),
            Conduction::Series { resistance },
        );
        let peak_junction = self.path.critical_junction(profile.peak() / e_star);
        let u_c = peak_junction.leaking().map(|j| j.u_c);
        let lambda_c = peak_junction.leaking().map_or(0.0, |j| j.lambda_c);
        let (motion, open_static_leak_rate, leak_rate) = match &self.drag {
            None => (None, None, leak_rate),
            Some((spec, table)) => {
                let static_rate = if leak_rate.is_finite() {
                    leak_rate
                } else {
                    0.0
                };
                let s = profile.peak() / e_star;
                let junction = match self.path {
                    ContactPath::Table(_) | ContactPath::Exact(_) => peak_junction,
                    _ => self.path.persson_junction(s),
                };
                let seal = spec.seal(
                    Elastic {
                        youngs_modulus: e_asperity,
                        poisson_ratio: p.material.poisson_ratio,
                    },
                    FlatSeal {
                        nominal_pressure: profile.peak(),
                        width: profile.width(),
                        length: p.geometry.sealing_length(),
                    },
                    p.fluid.viscosity,
                    p.shape_factor,
                );
                let point = spec.evaluate(&table.coefficients(s, &junction, &seal), static_rate);
                if spec.is_stroke() {
                    (Some(point), None, leak_rate)
                } else {
                    (
                        Some(point),
                        Some(static_rate),
                        static_rate + point.drag_leak_rate,
                    )
                }
            }
        };
        let state = if profile.peak() < p.fluid.pressure_difference {
            SealState::LiftOff
        } else if leak_rate > 0.0 {
            SealState::Leaking
        } else {
            SealState::Sealed
        };
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
            leak_rate,
            state,
            retained,
            open_leak_rate: leak_rate,
            open_u_c: u_c.unwrap_or(0.0),
            lambda_c,
            peak_reduced_pressure: profile.peak() / e_star,
            open_fraction: 1.0,
            motion,
            open_static_leak_rate,
        }
    }

    fn asperity_modulus(&self, state: &Mechanics) -> f64 {
        let prony = &self.problem.material.prony;
        match self.problem.asperity_modulus {
            AsperityModulus::Relaxed => prony.long_term(),
            AsperityModulus::Instantaneous => prony.instantaneous(),
            AsperityModulus::Fixed(e) => e,
            AsperityModulus::Follow => match self.problem.loading {
                Loading::Displacement => prony.relaxation(state.reduced_time),
                Loading::Force => 1.0 / self.creep.compliance(state.reduced_time),
            },
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
            peak_pressure: snap.profile.peak(),
            mean_pressure: snap.profile.mean(),
            contact_width: snap.profile.width(),
            u_c: snap.u_c,
            leak_rate: snap.leak_rate,
            leaked_volume: state.leaked_volume,
            state: snap.state,
            open_fraction: snap.open_fraction,
            motion: snap.motion,
        }
    }

    /// The earliest criterion crossed between two steps, each located by bisection on the
    /// exact state update to 1e-12 relative in time.
    fn locate_failure(
        &self,
        before: &Mechanics,
        before_snap: &Snapshot,
        after: &Mechanics,
        after_snap: &Snapshot,
    ) -> Option<FailureEvent> {
        let criteria = &self.problem.failure;
        let modes = criteria.newly_crossed(
            &before_snap.as_event_input(before.leaked_volume),
            &after_snap.as_event_input(after.leaked_volume),
        );
        modes
            .into_iter()
            .map(|mode| {
                let (mut lo, mut hi) = (before.time, after.time);
                for _ in 0..200 {
                    if hi - lo <= 1e-12 * hi {
                        break;
                    }
                    let geometric = if lo > 0.0 {
                        (lo * hi).sqrt()
                    } else {
                        0.5 * (lo + hi)
                    };
                    let mid = if geometric > lo && geometric < hi {
                        geometric
                    } else {
                        0.5 * (lo + hi)
                    };
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
            .min_by(|a, b| a.time.total_cmp(&b.time))
    }

    /// Records the validity findings of one step (docs/model.md §9): the rubber's
    /// temperature and squeeze, the contact state of the peak strip, the sliding speed.
    fn assess(&self, state: &Mechanics, snap: &Snapshot, findings: &mut Findings) {
        let p = self.problem;
        let at = At::Time(state.time);
        p.assess_rubber(snap.temperature, at, findings);
        validity::contact(
            &ContactState {
                nominal_pressure: snap.profile.peak(),
                pressure_difference: p.fluid.pressure_difference,
                junction: &snap.peak_junction,
                cutoff: p.spectrum.q1() / p.spectrum.q0(),
            },
            at,
            findings,
        );
        if let (Some((spec, _)), Some(m)) = (&self.drag, snap.motion) {
            validity::speed(spec.fastest_speed(), m.speed_bound, at, findings);
        }
    }
}

impl Snapshot {
    fn as_event_input(&self, leaked_volume: f64) -> events::EventInput {
        events::EventInput {
            leak_rate: self.leak_rate,
            leaked_volume,
            retained_force: self.retained,
            lifted: self.state == SealState::LiftOff,
        }
    }
}

/// The clogging ODE of one internal step, `d(ln f)/dt` (see
/// [`Simulator::integrate_clogging`]).
struct CloggingOde<'s, 'a> {
    simulator: &'s Simulator<'a>,
    contamination: &'s Contamination,
    a: f64,
    b: f64,
    before: &'s Snapshot,
    after: &'s Snapshot,
    /// L_y \[m\].
    length: f64,
    /// Re-routing ratios `(k, ratio, u_eff)` at `ln f = k h` ([`REROUTE_NODE_SPACING`]) and the
    /// step's end peak pressure, computed on demand and interpolated linearly in
    /// ln f: the right side is then a fixed, smooth function of f within the step (independent
    /// of where the solver samples it), at a few exact junctions per step instead of two per
    /// evaluation.
    ratios: RefCell<Vec<(i64, f64, Option<f64>)>>,
}

impl CloggingOde<'_, '_> {
    /// `−d(ln f)/dt` \[1/s\] at time `t` and `y = ln f` (≥ 0, finite).
    fn rate(&self, t: f64, y: f64) -> f64 {
        let (a, b) = (self.a, self.b);
        let t = t.clamp(a, b);
        let at = |qa: f64, qb: f64| events::interpolate_power_law(a, qa, b, qb, t).max(0.0);
        let q_open = at(self.before.open_leak_rate, self.after.open_leak_rate);
        let lambda_c = at(self.before.lambda_c, self.after.lambda_c);
        if !(q_open > 0.0 && lambda_c > 0.0) {
            return 0.0;
        }
        let channels = self.length / lambda_c;
        let n_p = self.contamination.number_concentration;
        let rate = match &self.simulator.rerouting {
            None => {
                let u_c = at(self.before.open_u_c, self.after.open_u_c);
                n_p * self.contamination.captured_fraction(u_c) * q_open / channels
            }
            Some(_) => {
                let f = y.exp().min(1.0);
                if f <= 0.0 {
                    return 0.0;
                }
                let (ratio, u_eff) = if f >= 1.0 {
                    (1.0, Some(at(self.before.open_u_c, self.after.open_u_c)))
                } else {
                    self.interpolated_ratio(y)
                };
                let Some(u_eff) = u_eff else {
                    return 0.0;
                };
                n_p * self.contamination.captured_fraction(u_eff) * q_open * ratio / (channels * f)
            }
        };
        if rate.is_nan() {
            0.0
        } else {
            rate.min(f64::MAX)
        }
    }
}

impl CloggingOde<'_, '_> {
    /// The step's peak reduced pressure for the re-routing ratio: the end's, the pressure its
    /// end snapshot uses, so the ratio integrated and the ratio reported agree at the end.
    fn step_pressure(&self) -> f64 {
        self.after.peak_reduced_pressure
    }

    /// The re-routing ratio at node `k` (`ln f = k h`), cached.
    fn node(&self, k: i64) -> (f64, Option<f64>) {
        if let Some(&(_, r, u)) = self.ratios.borrow().iter().find(|n| n.0 == k) {
            return (r, u);
        }
        let f = (k as f64 * REROUTE_NODE_SPACING).exp().min(1.0);
        let (r, u) = match &self.simulator.rerouting {
            Some(exact) => {
                let s = self.step_pressure();
                let a_c = self.simulator.problem.contact.percolation_threshold;
                let reference = self.simulator.reference_junction(exact, s);
                let a_eff = effective_threshold(a_c, f);
                if f >= 1.0 {
                    (1.0, reference)
                } else if a_eff.is_nan() || a_eff <= 0.0 {
                    (0.0, None)
                } else {
                    Simulator::ratio_against(exact, s, a_eff, reference)
                }
            }
            None => (f, None),
        };
        self.ratios.borrow_mut().push((k, r, u));
        (r, u)
    }

    /// `(ratio, u_eff)` at `y = ln f`, linear in ln f between the two nearest nodes.
    fn interpolated_ratio(&self, y: f64) -> (f64, Option<f64>) {
        let x = y / REROUTE_NODE_SPACING;
        let k = x.floor();
        let w = x - k;
        let (k, w) = if k.is_finite() {
            (k as i64, w)
        } else {
            return (0.0, None);
        };
        let (r0, u0) = self.node(k);
        let (r1, u1) = self.node(k + 1);
        match (u0, u1) {
            (Some(u0), Some(u1)) => (r0 + w * (r1 - r0), Some(u0 + w * (u1 - u0))),
            // one node sealed: take the nearer one
            _ if w < 0.5 => (r0, u0),
            _ => (r1, u1),
        }
    }
}

impl ode_solvers::System<f64, ode_solvers::Vector1<f64>> for CloggingOde<'_, '_> {
    fn system(&self, t: f64, y: &ode_solvers::Vector1<f64>, dy: &mut ode_solvers::Vector1<f64>) {
        dy[0] = -self.rate(t, y[0]);
    }
}

/// Squeeze at temperature `t` including the thermal strain (O-rings only).
fn squeeze_at(p: &LifeProblem, temperature: f64) -> f64 {
    match p.geometry {
        SealGeometry::ORing { squeeze, .. } => match p.thermal_strain {
            Some(th) => {
                squeeze
                    + (th.rubber_expansion - th.housing_expansion * (1.0 - squeeze))
                        * (temperature - th.installation_temperature)
            }
            None => squeeze,
        },
        SealGeometry::Flat { .. } => 0.0,
    }
}

/// The variable the Prony recursion runs on: g(ε) for an O-ring, 1 for a flat seal.
fn load_variable(p: &LifeProblem, temperature: f64) -> f64 {
    match p.geometry {
        SealGeometry::ORing { .. } => squeeze_function(squeeze_at(p, temperature)),
        SealGeometry::Flat { .. } => 1.0,
    }
}

/// The nominal profile for hereditary stress `stress` (on the load variable) at `temperature`.
fn profile_for(p: &LifeProblem, stress: f64, temperature: f64) -> Profile {
    match p.geometry {
        SealGeometry::Flat {
            nominal_pressure,
            width,
            ..
        } => {
            let e0 = p.material.prony.instantaneous();
            Profile::Uniform {
                pressure: nominal_pressure * stress / e0,
                width,
            }
        }
        SealGeometry::ORing { cross_section, .. } => {
            let eps = squeeze_at(p, temperature);
            let width = oring_contact_width(cross_section, eps).max(f64::MIN_POSITIVE);
            Profile::hertz((cross_section * stress).max(0.0), width)
        }
    }
}

/// Runs a life problem (convenience wrapper around [`Simulator`]).
pub fn simulate(problem: &LifeProblem) -> LifeResult {
    Simulator::new(problem).run()
}
