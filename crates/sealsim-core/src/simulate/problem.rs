//! A seal-life problem and its result: what the time loop needs (SI units) and what it returns.

use super::events::{self, FailureCriteria, FailureEvent};
use crate::clogging::Contamination;
use crate::contact::ContactSettings;
use crate::dynamic::{MotionPoint, MotionSpec};
use crate::extrusion::{self, ExtrusionLimit};
use crate::fluid::Fluid;
use crate::gland::Gland;
use crate::leak::Fidelity;
pub use crate::leak::SealState;
use crate::material::{Ageing, Material, TemperatureHistory};
use crate::seal::{Profile, SealGeometry, ThermalStrain};
use crate::surface::Spectrum;
use crate::validity::{self, At, Findings};

/// The time scale of a Shore A reading \[s\] (the hardness the extrusion chart is drawn for).
const HARDNESS_TEST_TIME: f64 = 3.0;

/// Which modulus the asperity contact sees (docs/model.md §6.1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AsperityModulus {
    /// E∞, the low-frequency modulus PY08 uses for a seal at rest since long: at a relaxing
    /// sealing pressure it *under*-predicts the leak (not conservative).
    Relaxed,
    /// E0 (with a series through the glass transition: the glassy modulus).
    Instantaneous,
    /// The bulk's own relaxation, consistent with linear viscoelasticity (the default): under
    /// displacement loading the stress response to the installation alone (E(ξ(t)) after an
    /// instantaneous installation, with the chemical ageing), so that at a fixed squeeze P0/E*
    /// and the whole gap field stay as installed; under force loading 1/J(ξ(t)) (the contact
    /// creeps under a constant load).
    Follow,
    /// A fixed modulus \[Pa\].
    Fixed(f64),
}

/// The second sealing interface of a groove-seated O-ring: the ring also seals on the groove
/// bottom, in parallel with the counterface (`[surface]`).
#[derive(Debug, Clone, PartialEq)]
pub enum GrooveInterface {
    /// None modelled: a flat seal, or a ring between plates (one interface, as before glands).
    None,
    /// The groove bottom has the counterface's surface: the same leak again.
    Counterface,
    /// The groove bottom's own surface (`[groove_surface]`).
    Own(Spectrum),
}

/// How the seal is held.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Loading {
    /// Fixed squeeze (O-ring in a groove): the sealing force relaxes.
    Displacement,
    /// Fixed load (spring-loaded): the sealing force stays.
    Force,
}

/// Where a run's chemical ageing constants come from (docs/model.md §6.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AgeingSource {
    /// The compound's `[material.ageing]`, on by default.
    Compound,
    /// The scenario's `[ageing]` table (each constant it leaves out from the compound's).
    Scenario,
    /// Switched off: `[ageing] enabled = false`.
    Off,
    /// The compound has no ageing constants and the scenario gives none: no chemical ageing.
    #[default]
    NoData,
    /// `compare`: the scenario asks for ageing but this compound has no constants to complete
    /// it, so it runs without (its row says so).
    MissingInComparison,
}

impl AgeingSource {
    /// What the reports say about it.
    pub fn describe(self) -> &'static str {
        match self {
            AgeingSource::Compound => "the compound's own constants ([material.ageing])",
            AgeingSource::Scenario => "the scenario's [ageing] (the compound's for the rest)",
            AgeingSource::Off => "off: [ageing] enabled = false",
            AgeingSource::NoData => "none: the compound has no ageing constants",
            AgeingSource::MissingInComparison => {
                "none in this comparison: the compound has no ageing constants to complete the \
                 scenario's [ageing]"
            }
        }
    }
}

/// The output/evaluation grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeGrid {
    /// First time after installation \[s\] (> 0).
    pub start: f64,
    /// Last time \[s\] (> start).
    pub duration: f64,
    /// Log-uniform output points per decade (the history's rows; the internal steps do not
    /// depend on it, docs/model.md §10.1).
    pub points_per_decade: f64,
    /// Relative tolerance of the integrated quantities — the leaked volume, the located state
    /// changes and extremes — of the internal steps' error control (docs/model.md §10.1;
    /// `[simulation] tolerance`, default [`TimeGrid::DEFAULT_TOLERANCE`]).
    pub tolerance: f64,
}

impl TimeGrid {
    /// Default relative tolerance of the integrated quantities (`[simulation] tolerance`).
    pub const DEFAULT_TOLERANCE: f64 = 1e-3;

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
    /// The groove an O-ring sits in (`None`: a flat seal, or a ring squeezed between plates).
    pub gland: Option<Gland>,
    /// The groove bottom's interface of a groove-seated ring, which leaks in parallel with the
    /// counterface's (docs/model.md §6.3).
    pub groove: GrooveInterface,
    /// Energisation factor k_e: the fluid pressure adds `k_e ΔP` to the contact pressure across
    /// the width (docs/model.md §6.3; 1 for a groove-seated ring by default, 0 otherwise).
    pub energisation_factor: f64,
    pub loading: Loading,
    /// The time over which the squeeze is applied at installation \[s\] (a linear ramp ending
    /// at t = 0; 0: a jump, which a series through the glass transition answers with the
    /// glassy modulus).
    pub installation_time: f64,
    /// The temperature history; with a fitting temperature (`[seal] installation_temperature`)
    /// its first value is that temperature, reached from the environment's over the ring's
    /// thermal settling time ([`TemperatureHistory::with_lead_in`], docs/model.md §5.2).
    pub environment: TemperatureHistory,
    pub thermal_strain: Option<ThermalStrain>,
    pub ageing: Option<Ageing>,
    /// Where `ageing` comes from, for the reports.
    pub ageing_source: AgeingSource,
    pub failure: FailureCriteria,
    pub time: TimeGrid,
    pub fidelity: Fidelity,
    /// Gauss–Legendre points across the Hertz profile (strips in series).
    pub strips: usize,
    /// Particle clogging of the critical constrictions (`None`: clean fluid, zero cost).
    pub contamination: Option<Contamination>,
    /// The countersurface's motion (`[motion]`, PY08 §8; `None`: a static seal, zero cost).
    pub motion: Option<MotionSpec>,
    /// A gas through an O-ring of a compound with data: permeation through the rubber, carried
    /// beside the interface leak (docs/model.md §13.7); `None` otherwise.
    pub permeation: Option<crate::permeation::SealPermeation>,
    /// The fluid pressure against time (docs/model.md §8.4): `None` for the constant
    /// `fluid.pressure_difference` (or a gas's inlet pressure), which is then the same run bit
    /// for bit as before pressure histories.
    pub pressure: Option<crate::pressure::PressureHistory>,
}

impl LifeProblem {
    /// The temperature of the installation, T(0) \[K\].
    pub fn installed_temperature(&self) -> f64 {
        self.environment.at(0.0)
    }

    /// The pressure difference ΔP(t) across the seal at time `t` \[Pa\]: the pressure history's
    /// (docs/model.md §8.4), or the fluid's constant one.
    pub fn pressure_at(&self, t: f64) -> f64 {
        match &self.pressure {
            Some(history) => history.difference_at(t),
            None => self.fluid.pressure_difference,
        }
    }

    /// The fluid at time `t`: the run's fluid with the pressure difference ΔP(t) (a gas: its
    /// inlet pressure P_b + ΔP(t), the outlet fixed). Without a pressure history the fluid
    /// itself.
    pub fn fluid_at(&self, t: f64) -> crate::fluid::Fluid {
        crate::fluid::Fluid {
            pressure_difference: self.pressure_at(t),
            ..self.fluid
        }
    }

    /// The highest pressure difference over the run \[Pa\] (the service's without a history).
    pub fn highest_pressure_difference(&self) -> f64 {
        match &self.pressure {
            Some(history) => history.highest_difference(),
            None => self.fluid.pressure_difference,
        }
    }

    /// The nominal pressure profile right after installation (t = 0): the instantaneous
    /// modulus E0 on the load at the temperature T(0) (Lindley force and Hertz profile for an
    /// O-ring, including the thermal strain at T(0); the given nominal pressure for a flat seal).
    pub fn initial_profile(&self) -> Profile {
        let t0 = self.installed_temperature();
        let thermal = self.thermal_strain.as_ref();
        let e_install = self.installed_modulus();
        self.geometry.profile(
            e_install * self.geometry.load_variable(thermal, t0),
            e_install,
            thermal,
            t0,
        )
    }

    /// The installation ramp in reduced time at the installation temperature T_i:
    /// `installation_time / a_T(T_i)`.
    pub fn installation_reduced_time(&self) -> f64 {
        let a_t = self.material.shift.factor(self.installed_temperature());
        if self.installation_time > 0.0 && a_t.is_finite() {
            self.installation_time / a_t
        } else {
            0.0
        }
    }

    /// The modulus the asperity contact sees right after installation (docs/model.md §6.1): with
    /// `follow`, the installed modulus under displacement loading, 1/J over the ramp under force
    /// loading; E∞, E0 or the fixed value otherwise \[Pa\]. The static leak problem's modulus.
    pub fn installed_asperity_modulus(&self) -> f64 {
        let prony = &self.material.prony;
        match self.asperity_modulus {
            AsperityModulus::Relaxed => prony.long_term(),
            AsperityModulus::Instantaneous => prony.instantaneous(),
            AsperityModulus::Fixed(e) => e,
            AsperityModulus::Follow => match self.loading {
                Loading::Displacement => self.installed_modulus(),
                Loading::Force => {
                    1.0 / prony
                        .creep()
                        .ramp_compliance(0.0, self.installation_reduced_time())
                }
            },
        }
    }

    /// The stress at the end of the installation ramp per unit load \[Pa\]:
    /// `E∞ + Σ E_i φ(ξ_r/τ_i)`, ξ_r the ramp in reduced time, φ(x) = (1 − e^{−x})/x (E0 for an
    /// instantaneous installation). A flat seal's `nominal_pressure` is the pressure then.
    pub fn installed_modulus(&self) -> f64 {
        let prony = &self.material.prony;
        let mut state = crate::material::RelaxationState::new(prony);
        state.step(prony, self.installation_reduced_time(), 1.0);
        state.stress(prony)
    }

    /// Records the findings of the installation state (t = 0) into `out`: the temperature
    /// against the glass transition and the WLF frozen limit, an O-ring's squeeze against
    /// Lindley's range (docs/model.md §9.6–§9.7). A life run evaluates the same at every step.
    pub fn assess_installation(&self, out: &mut Findings) {
        let t0 = self.installed_temperature();
        self.assess_rubber(t0, At::Installation, out);
        validity::contact_width(
            self.initial_profile().width(),
            self.spectrum.q0(),
            At::Installation,
            out,
        );
        if let Some((ratio, limit)) = self.extrusion_at(t0, self.pressure_at(0.0)) {
            validity::extrusion(ratio, &limit, At::Installation, out);
        }
    }

    /// Whether any criterion can end the life: one of `[failure]`'s, the extrusion check of a
    /// groove-seated ring, the shutdown check of an O-ring under displacement loading, or the
    /// cold limit where the temperature history can reach below it.
    pub fn can_fail(&self) -> bool {
        !self.failure.is_empty()
            || (self.failure.extrusion && self.gland.is_some())
            || self.has_shutdown_check()
            || self
                .failure
                .low_temperature
                .is_some_and(|c| self.environment.range().0 < c.threshold())
    }

    /// Whether the shutdown check applies (docs/model.md §8.2): an O-ring or a flat gasket
    /// under displacement loading, unless `[failure] lost_interference = false` waived it.
    pub fn has_shutdown_check(&self) -> bool {
        self.failure.shutdown.is_some() && self.loading == Loading::Displacement
    }

    /// The extrusion check of a groove-seated ring at `temperature` \[K\] and the pressure
    /// difference `pressure_difference` \[Pa\] (docs/model.md §6.3, §8.4): the rubber's Shore A
    /// from its modulus at 3 s at that temperature (Gent's relation inverted), the chart's limit
    /// at ΔP with the gland's back-up rings, and the diametral
    /// clearance (twice the gap) over it; `None` without a gland. The ring extrudes when the
    /// ratio exceeds 1 or the pressure is above the arrangement's rating
    /// ([`ExtrusionLimit::extrudes`]).
    pub fn extrusion_at(
        &self,
        temperature: f64,
        pressure_difference: f64,
    ) -> Option<(f64, ExtrusionLimit)> {
        let gland = self.gland.as_ref()?;
        let a_t = self.material.shift.factor(temperature);
        let modulus = self.material.prony.relaxation(HARDNESS_TEST_TIME / a_t);
        let limit = extrusion::limit(
            pressure_difference,
            extrusion::shore_a_from_modulus(modulus),
            gland.backup_rings,
        );
        Some((2.0 * gland.extrusion_gap / limit.diametral_clearance, limit))
    }

    /// The rubber's temperature `t` \[K\] and, for an O-ring, its squeeze at `t`.
    pub(super) fn assess_rubber(&self, t: f64, at: At, out: &mut Findings) {
        // Lindley's squeeze range: a ring's (a kind with a ring squeeze)
        if self.geometry.ring_squeeze().is_some() {
            validity::squeeze(
                self.geometry.squeeze_at(self.thermal_strain.as_ref(), t),
                at,
                out,
            );
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
    /// The pressure difference ΔP across the seal at the row's time \[Pa\] (docs/model.md §8.4).
    pub pressure_difference: f64,
    pub contact_width: f64,
    /// Height of the critical constriction at the peak pressure \[m\]; `None` when sealed there.
    pub u_c: Option<f64>,
    pub leak_rate: f64,
    /// A gas with [`LifeProblem::permeation`]: the permeation throughput through the rubber at
    /// the row's time and temperature \[Pa·m³/s\] (docs/model.md §13.7); not in `leak_rate`.
    pub permeation: Option<f64>,
    pub leaked_volume: f64,
    pub state: SealState,
    /// Chemical compression set with ageing on: the part of the installed compression the aged
    /// networks keep at rest, after a full recovery (docs/model.md §6.5).
    pub compression_set: Option<f64>,
    /// The shutdown check (docs/model.md §8.2): the set ring at the shutdown temperature and
    /// the minimum pressure difference; `None` where it does not apply.
    pub shutdown: Option<super::ShutdownState>,
    /// Open fraction f of the critical channels (1 without contamination).
    pub open_fraction: f64,
    /// `[motion]`: drag, film, speed bound and stroke volumes at the peak strip (`None` for a
    /// static seal). Constant sliding: `drag_leak_rate` is included in `leak_rate`; a stroke
    /// cycle: it is the out-stroke's instantaneous drag, not included (`leak_rate` is the
    /// static, cycle-averaged one).
    pub motion: Option<MotionPoint>,
}

impl HistoryRow {
    /// The interface's leak rate plus a gas's permeation as the volume flow at the mean pressure
    /// `mean_pressure` p̄ \[m³/s\]: what a leak detector sees and what `max_leak_rate` is
    /// compared with (docs/model.md §13.7).
    pub fn detected_leak_rate(&self, mean_pressure: Option<f64>) -> f64 {
        match (self.permeation, mean_pressure) {
            (Some(q), Some(p)) if p > 0.0 => self.leak_rate + q / p,
            _ => self.leak_rate,
        }
    }
}

/// The result of a life run.
#[derive(Debug, Clone, PartialEq)]
pub struct LifeResult {
    /// The history at the output times (samples of the run; `points_per_decade`).
    pub rows: Vec<HistoryRow>,
    /// The same problem at the neighbouring fidelity level ([`Fidelity::neighbour`]), where the
    /// caller ran it (`sealsim run` and `compare` do; a study's cases do not): how far the
    /// model's own uncertainty moves the result (docs/model.md §4.1).
    pub band: Option<LevelBand>,
    /// What the internal steps found (states with their located times, extremes, the leaked
    /// volume): independent of the output grid (docs/model.md §10.1).
    pub course: Course,
    pub failure: Option<FailureEvent>,
    /// The validity limits crossed during the run, each once with its worst value and when
    /// (docs/model.md §9.11).
    pub findings: Findings,
    /// The sealing force per unit length at the retained-force reference time \[N/m\].
    pub reference_force: f64,
    /// A rarefied gas: the leak rate at installation \[m³/s\] the continuum law would give
    /// instead (docs/model.md §3.10), to show what rarefaction changes; `None` otherwise.
    pub continuum_leak_rate: Option<f64>,
    /// A gas: how the permeation figure was obtained (sourced, derived, a stated NOT SOURCED
    /// bound, the user's), which every output states beside the permeation (docs/model.md
    /// §13.4); `None` without permeation.
    pub permeation_status: Option<crate::permeation::DataStatus>,
}

/// A life run's outcome, as its verdict names it (docs/model.md §8.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// A failure criterion was crossed.
    Fails,
    /// No criterion crossed, but the seal was open (a waived lift-off) or held by the fluid
    /// pressure alone at some time.
    Open,
    /// No criterion crossed, and the seal held by its squeeze throughout.
    Survives,
}

/// The same life at the neighbouring fidelity level (docs/model.md §4.1): the figures a summary
/// sets beside its own, and the outcome that decides whether the model decides the verdict.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelBand {
    /// The neighbouring level.
    pub level: Fidelity,
    pub failure: Option<FailureEvent>,
    /// When the seal was first open there \[s\].
    pub open_since: Option<f64>,
    /// Its leaked volume \[m³\], and whether that is a lower bound.
    pub leaked_volume: f64,
    pub leaked_volume_is_lower_bound: bool,
    /// Its highest leak rate \[m³/s\].
    pub maximum_leak_rate: f64,
    pub final_state: SealState,
}

impl LevelBand {
    /// The band of `result`, a run of the same problem at `level`.
    pub fn of(level: Fidelity, result: &LifeResult) -> Self {
        LevelBand {
            level,
            failure: result.failure,
            open_since: result.open_since(),
            leaked_volume: result.leaked_volume(),
            leaked_volume_is_lower_bound: result.leaked_volume_is_lower_bound(),
            maximum_leak_rate: result.course.max_leak_rate.0,
            final_state: result.final_state(),
        }
    }

    /// The outcome at the neighbouring level.
    pub fn outcome(&self) -> Outcome {
        outcome(self.failure, self.open_since)
    }
}

fn outcome(failure: Option<FailureEvent>, open_since: Option<f64>) -> Outcome {
    match (failure, open_since) {
        (Some(_), _) => Outcome::Fails,
        (None, Some(_)) => Outcome::Open,
        (None, None) => Outcome::Survives,
    }
}

/// The course of a life run over its internal steps (docs/model.md §10.1): what the summary
/// states, independent of the output grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Course {
    /// Each state the run passed through, with the time it began \[s\] (located by bisection to
    /// a relative 1e-6; a state may come back: each return is listed).
    pub states: Vec<(SealState, f64)>,
    /// The highest leak rate \[m³/s\] and when \[s\] (the first, on a tie).
    pub max_leak_rate: (f64, f64),
    /// The lowest sealing force per unit length \[N/m\] and when \[s\].
    pub min_force: (f64, f64),
    /// The lowest peak contact pressure with the energisation \[Pa\] and when \[s\].
    pub min_peak_pressure: (f64, f64),
    /// The leaked volume at the end of the run \[m³\].
    pub leaked_volume: f64,
    /// The part of it that flowed while the seal was lifted off, where the model gives only a
    /// lower bound (§3.6) \[m³\].
    pub lifted_volume: f64,
    /// How long the seal was lifted off \[s\].
    pub lifted_duration: f64,
    /// The first internal time at which the shutdown check found the interference lost \[s\].
    pub interference_lost: Option<f64>,
    /// Internal steps accepted.
    pub steps: usize,
    /// Evaluations of the state (accepted, rejected and bisection steps; the history rows
    /// between internal steps not counted).
    pub evaluations: usize,
}

/// One point of a run's course, as [`Course::observe`] takes it in.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CoursePoint {
    /// \[s\]
    pub time: f64,
    pub state: SealState,
    /// \[m³/s\]
    pub leak_rate: f64,
    /// Sealing force per unit length \[N/m\].
    pub force: f64,
    /// Peak contact pressure with the energisation \[Pa\].
    pub peak_pressure: f64,
    /// Leaked volume since installation \[m³\].
    pub leaked_volume: f64,
    /// Whether the shutdown check finds the interference lost here.
    pub interference_lost: bool,
}

impl Course {
    /// A course with nothing observed yet, `evaluations` state evaluations spent.
    pub(crate) fn empty(evaluations: usize) -> Self {
        Course {
            states: Vec::new(),
            max_leak_rate: (0.0, 0.0),
            min_force: (f64::INFINITY, 0.0),
            min_peak_pressure: (f64::INFINITY, 0.0),
            leaked_volume: 0.0,
            lifted_volume: 0.0,
            lifted_duration: 0.0,
            interference_lost: None,
            steps: 0,
            evaluations,
        }
    }

    /// Takes in the point `p`, reached from `previous` = (time \[s\], leaked volume \[m³\]) of
    /// the point before (`None` for the first): a new state, extremes (the first on a tie), the
    /// volume and time spent lifted off (a step that ends lifted off: its flow is the lower
    /// bound of §3.6), the first loss of interference.
    pub(crate) fn observe(&mut self, p: &CoursePoint, previous: Option<(f64, f64)>) {
        if self.states.last().is_none_or(|&(last, _)| last != p.state) {
            self.states.push((p.state, p.time));
        }
        if p.leak_rate > self.max_leak_rate.0 {
            self.max_leak_rate = (p.leak_rate, p.time);
        }
        if p.force < self.min_force.0 {
            self.min_force = (p.force, p.time);
        }
        if p.peak_pressure < self.min_peak_pressure.0 {
            self.min_peak_pressure = (p.peak_pressure, p.time);
        }
        if let Some((time, volume)) = previous {
            self.steps += 1;
            if p.state == SealState::LiftOff {
                self.lifted_volume += p.leaked_volume - volume;
                self.lifted_duration += p.time - time;
            }
        }
        self.leaked_volume = p.leaked_volume;
        if self.interference_lost.is_none() && p.interference_lost {
            self.interference_lost = Some(p.time);
        }
    }

    /// The course a history shows at its own rows (for results built by hand, e.g. in tests of
    /// the reports): states at the rows they first hold at, extremes over the rows.
    pub fn from_rows(rows: &[HistoryRow]) -> Self {
        let mut course = Course::empty(rows.len());
        let mut previous = None;
        for r in rows {
            let point = CoursePoint {
                time: r.time,
                state: r.state,
                leak_rate: r.leak_rate,
                force: r.sealing_force,
                peak_pressure: r.peak_pressure,
                leaked_volume: r.leaked_volume,
                interference_lost: r.shutdown.is_some_and(|s| !s.holds),
            };
            course.observe(&point, previous);
            previous = Some((r.time, r.leaked_volume));
        }
        course
    }

    /// Whether the seal was ever lifted off (whatever the bound of its flow, 0 included).
    pub fn ever_lifted(&self) -> bool {
        self.states.iter().any(|&(s, _)| s == SealState::LiftOff)
    }
}

impl LifeResult {
    pub fn initial_leak_rate(&self) -> f64 {
        self.rows.first().map_or(0.0, |r| r.leak_rate)
    }

    pub fn final_leak_rate(&self) -> f64 {
        self.rows.last().map_or(0.0, |r| r.leak_rate)
    }

    /// The leaked volume at the end of the run \[m³\] (the internal steps', whatever the output
    /// grid).
    pub fn leaked_volume(&self) -> f64 {
        self.course.leaked_volume
    }

    /// The state at the end of the run.
    pub fn final_state(&self) -> SealState {
        self.rows.last().map_or(SealState::Sealed, |r| r.state)
    }

    /// The run's outcome (docs/model.md §8.1).
    pub fn outcome(&self) -> Outcome {
        outcome(self.failure, self.open_since())
    }

    /// Whether the model does not decide the verdict: the neighbouring fidelity level gives
    /// another outcome (docs/model.md §4.1). `false` where the band was not computed.
    pub fn undecided(&self) -> bool {
        self.band
            .as_ref()
            .is_some_and(|b| b.outcome() != self.outcome())
    }

    /// The states in the order the run passed through them, each with the time it began \[s\],
    /// located on the internal steps (a state may come back: each return is listed).
    pub fn state_changes(&self) -> Vec<(SealState, f64)> {
        self.course.states.clone()
    }

    /// When the seal was first open ([`SealState::is_open`]) \[s\] (located).
    pub fn open_since(&self) -> Option<f64> {
        self.course
            .states
            .iter()
            .find(|(s, _)| s.is_open())
            .map(|&(_, t)| t)
    }

    /// Whether the leaked volume is a lower bound: the seal was lifted off at some time, where
    /// the model gives only a lower bound of the flow (docs/model.md §8.1) — also when that
    /// bound is 0.
    pub fn leaked_volume_is_lower_bound(&self) -> bool {
        self.course.ever_lifted()
    }

    /// When the shutdown check found the interference lost \[s\]: the located failure time when
    /// it is the run's failure, else the first internal time at which it did (`None`: held).
    pub fn interference_lost(&self) -> Option<f64> {
        self.failure
            .filter(|f| f.mode == super::FailureMode::LostInterference)
            .map(|f| f.time)
            .or(self.course.interference_lost)
    }

    /// The lowest sealing force per length over the run \[N/m\] and when \[s\].
    pub fn minimum_force(&self) -> Option<(f64, f64)> {
        Some(self.course.min_force)
    }

    /// The lowest peak contact pressure over the run (with the energisation) \[Pa\] and when
    /// \[s\].
    pub fn minimum_peak_pressure(&self) -> Option<(f64, f64)> {
        Some(self.course.min_peak_pressure)
    }

    /// The highest leak rate over the run \[m³/s\] and when \[s\] (the first, on a tie).
    pub fn maximum_leak_rate(&self) -> Option<(f64, f64)> {
        Some(self.course.max_leak_rate)
    }

    /// Open fraction of the critical channels at the end of the run (1 when clean).
    pub fn final_open_fraction(&self) -> f64 {
        self.rows.last().map_or(1.0, |r| r.open_fraction)
    }

    /// Leak rate at time `t` \[s\], interpolated as a power law between rows (0 outside).
    pub fn leak_rate_at(&self, t: f64) -> Option<f64> {
        self.value_at(t, |r| r.leak_rate)
    }

    /// What a leak detector sees at time `t` \[s\] (the interface's leak rate plus a gas's
    /// permeation as the volume flow at the mean pressure `mean_pressure` p̄, what the
    /// `max_leak_rate` criterion compares, docs/model.md §13.7) \[m³/s\], interpolated as a
    /// power law between rows.
    pub fn detected_leak_rate_at(&self, t: f64, mean_pressure: Option<f64>) -> Option<f64> {
        self.value_at(t, |r| r.detected_leak_rate(mean_pressure))
    }

    /// `value` of the rows at time `t` \[s\], interpolated as a power law between rows.
    fn value_at(&self, t: f64, value: impl Fn(&HistoryRow) -> f64) -> Option<f64> {
        let k = self.rows.partition_point(|r| r.time < t);
        let b = self.rows.get(k)?;
        if k == 0 || b.time == t {
            return Some(value(b));
        }
        let a = &self.rows[k - 1];
        Some(events::interpolate_power_law(
            a.time,
            value(a),
            b.time,
            value(b),
            t,
        ))
    }
}
