//! The seal-life tables of a scenario → the pieces of a [`LifeProblem`]:
//! `[seal]`'s thermal strain (the kinds are read in `seal_kind`), `[environment]` (temperature history),
//! `[failure]`, `[ageing]` and `[simulation]`, each error located like the rest of the file.
//!
//! [`LifeProblem`]: crate::simulate::LifeProblem

use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::history;
use super::raw::{Quantity, RawEnvironment, RawFailure, RawScenarioAgeing, RawSeal, RawSimulation};
pub use super::seal_kind::DEFAULT_FLAT_COMPRESSION;
use super::seal_spec::SealSpec;
use crate::leak::Fidelity;
use crate::material::shift::{Cycle, DAY, YEAR};
use crate::material::{Ageing, BALANCED_CROSSLINKING, Material, Shift, TemperatureHistory};
use crate::simulate::{AgeingSource, FailureCriteria, ThermalStrain, TimeGrid};
use crate::units::{Dimension, show};
use toml::Spanned;

pub(super) const DAILY_AMPLITUDE: Field = field(
    "environment.daily_amplitude",
    Dimension::TEMPERATURE,
    "K",
    Bound::Range(0.0, 500.0),
);
pub(super) const YEARLY_AMPLITUDE: Field = field(
    "environment.yearly_amplitude",
    Dimension::TEMPERATURE,
    "K",
    Bound::Range(0.0, 500.0),
);
pub(super) const DAILY_PRESSURE: Field = field(
    "environment.daily_pressure",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(0.0, 1e10),
);
pub(super) const PROOF_PRESSURE: Field = field(
    "environment.proof_pressure",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(0.0, 1e10),
);
pub(super) const PROOF_DURATION: Field = field(
    "environment.proof_duration",
    Dimension::TIME,
    "s",
    Bound::Open(0.0, 1e9),
);
pub(super) const MAX_LEAK_RATE: Field = field(
    "failure.max_leak_rate",
    Dimension::VOLUME_FLOW,
    "m^3/s",
    Bound::Range(1e-30, 1.0),
);
pub(super) const MAX_LEAKED_VOLUME: Field = field(
    "failure.max_leaked_volume",
    Dimension::VOLUME,
    "m^3",
    Bound::Range(1e-30, 1e6),
);
pub(super) const REFERENCE_PRESSURE: Field = field(
    "failure.reference_pressure",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(1.0, 1e10),
);
pub(super) const MINIMUM_PRESSURE_DIFFERENCE: Field = field(
    "failure.minimum_pressure_difference",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(0.0, 1e10),
);
pub(super) const LOW_TEMPERATURE_MARGIN: Field = field(
    "failure.low_temperature_margin",
    Dimension::TEMPERATURE,
    "K",
    Bound::Range(0.0, 100.0),
);
/// The default static margin of the cold limit \[K\] (docs/model.md §8.3): how far below its
/// T10 a static seal is still taken to hold. Parker's O-ring handbook (Low Temperature Effects):
/// "an O-ring elastomer will seal statically 10 to 15 degrees below the TR-10 temperature",
/// degrees Fahrenheit, and "the low temperature sealing limit is generally about 8 °C (15 °F)
/// below the TR-10 value"; Problem Solving Products: "generally 15 °F below TR-10 for static
/// seals"; the Elastomer-Institut: 10–15 °C. The low end of that band, 10 °F = 5.6 K, rounded
/// down: the conservative side, and the library's T10 stands at a chart service limit rather
/// than a measured TR-10 (§6.7), so a wider margin would count the chart's own allowance twice.
pub const DEFAULT_LOW_TEMPERATURE_MARGIN: f64 = 5.0;
/// A moving seal's margin \[K\]: "in dynamic applications, O-rings perform well at and above
/// TR-10" (Parker, as above), so none.
pub const DYNAMIC_LOW_TEMPERATURE_MARGIN: f64 = 0.0;
/// The default shutdown temperature's upper end \[K\]: 23 °C, the laboratory's standard
/// temperature (ISO 23529), a plant at rest indoors (docs/model.md §8.2).
pub const DEFAULT_SHUTDOWN_TEMPERATURE: f64 = 296.15;
pub(super) const MIN_RETAINED_FORCE: Field = field(
    "failure.min_retained_force",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);
pub(super) const RETAINED_FORCE_REFERENCE: Field = field(
    "failure.retained_force_reference",
    Dimension::TIME,
    "s",
    Bound::Range(0.0, MAX_DURATION),
);
pub(super) const MIN_SEALING_FORCE: Field = field(
    "failure.min_sealing_force",
    Dimension::FORCE_PER_LENGTH,
    "N/m",
    Bound::Open(0.0, 1e9),
);
pub(super) const MIN_CONTACT_PRESSURE: Field = field(
    "failure.min_contact_pressure",
    Dimension::PRESSURE,
    "Pa",
    Bound::Open(0.0, 1e10),
);
pub(super) const GASKET_FACTOR: Field = field(
    "failure.gasket_factor",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(0.0, 100.0),
);
pub(super) const MAX_COMPRESSION_SET: Field = field(
    "failure.max_compression_set",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);
pub(super) const INSTALLATION_TIME: Field = field(
    "seal.installation_time",
    Dimension::TIME,
    "s",
    Bound::Range(0.0, 1e6),
);
/// ISO 3384 practice: the force 30 min after compression is the reference of the retained
/// force (docs/model.md §8).
pub const DEFAULT_RETAINED_FORCE_REFERENCE: f64 = 1800.0;
/// An O-ring is pressed into its gland, or a flange bolted up, within seconds: the squeeze's
/// ramp at installation (docs/model.md §5.2).
pub const DEFAULT_INSTALLATION_TIME: f64 = 1.0;
pub(super) const AGEING_ACTIVATION_ENERGY: Field = field(
    "ageing.activation_energy",
    Dimension::MOLAR_ENERGY,
    "J/mol",
    Bound::Range(1.0, 1e6),
);
pub(super) const AGEING_RATE: Field = field(
    "ageing.rate",
    Dimension::FREQUENCY,
    "1/s",
    Bound::Range(1e-30, 1e3),
);
pub(super) const AGEING_CROSSLINKING: Field = field(
    "ageing.crosslinking",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(0.0, 10.0),
);
pub(super) const DURATION: Field = field(
    "simulation.duration",
    Dimension::TIME,
    "s",
    Bound::Range(1e-9, MAX_DURATION),
);
pub(super) const START: Field = field(
    "simulation.start",
    Dimension::TIME,
    "s",
    Bound::Range(1e-9, MAX_DURATION),
);
pub(super) const POINTS_PER_DECADE: Field = field(
    "simulation.points_per_decade",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(0.1, MAX_POINTS_PER_DECADE),
);

pub(super) const TOLERANCE: Field = field(
    "simulation.tolerance",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(1e-8, 0.1),
);

/// Default `simulation.duration` \[s\]: 30 years.
pub const DEFAULT_DURATION: f64 = 30.0 * YEAR;
/// Default `simulation.start` \[s\].
pub const DEFAULT_START: f64 = 1.0;
/// Default `simulation.points_per_decade`.
pub const DEFAULT_POINTS_PER_DECADE: f64 = 20.0;
/// Upper limit of `simulation.duration` and `simulation.start` \[s\]: 1000 years (the run's
/// cost grows with the number of temperature cycles in it, eight internal steps each).
pub const MAX_DURATION: f64 = 1000.0 * YEAR;
/// Most internal steps the temperature cycles may ask of one run: eight per period of the
/// shortest cycle over the simulated time. 400 000 is 137 years of daily cycles; the cost is
/// linear in them (bounded work per step, docs/model.md §11.1): 130 years of the daily and
/// yearly cycles of `scenarios/oring-epdm-outdoor-cycles.toml` (380 000 steps) run in about
/// 4 s (`sealsim run`, the run and its band, on the 2-core VM; `benches/life_long.rs`).
/// Beyond it the run is refused (exit 2) rather than left to run for minutes.
pub const MAX_CYCLE_STEPS: f64 = 400_000.0;
pub use super::history::MAX_HISTORY_ROWS;
/// Upper limit of `simulation.points_per_decade` (a guard against typos that would make a
/// run take minutes).
pub const MAX_POINTS_PER_DECADE: f64 = 1000.0;
/// Temperature when neither `[environment]` nor the material's shift gives one: 23 °C \[K\].
pub const DEFAULT_TEMPERATURE: f64 = 296.15;

/// Phase (upward zero crossing) of the daily cycle \[s after midnight\]: the maximum falls a
/// quarter period later, at 15:00.
pub const DAILY_PHASE: f64 = 9.0 * 3600.0;
/// Time of the yearly maximum \[s after t = 0, midnight of 1 January\]: noon on 21 July, day
/// 201.5 of a non-leap year.
pub const YEARLY_MAXIMUM: f64 = 201.5 * DAY;

/// What `[failure]`'s defaults depend on beyond the fluid and the environment.
pub(super) struct FailureContext {
    /// The compound's T10 \[K\] (`None`: it has none, and the cold limit does not apply).
    pub low_temperature_limit: Option<f64>,
    /// A `[motion]` seal: the cold limit's margin is the dynamic one.
    pub moving: bool,
    /// The shutdown check's cool-down (docs/model.md §5.2, §8.2): an O-ring's thermal
    /// settling time d²/a, a flat gasket's t_c²/a over its compressed thickness \[s\] (0, cooled
    /// at once — the least relaxation — without `thickness`).
    pub cooling_time: f64,
    /// Why the shutdown check does not apply to this seal (`None`: it does): its keys are
    /// then refused rather than ignored.
    pub no_shutdown: Option<&'static str>,
    /// The highest pressure difference of a pressure history \[Pa\] (`None`: the service's).
    pub highest_pressure: Option<f64>,
}

impl Source<'_> {
    /// The thermal strain of an O-ring with a housing CTE (`housing`, `housing_expansion`, or a
    /// groove-seated ring's default steel): the rubber's CTE is the material's
    /// `thermal_expansion` (required), the installation temperature defaults to the
    /// environment at t = 0 (to 23 °C in a gland, set by [`Source::gland_seal`]).
    /// `fix` says where a missing `thermal_expansion` goes ([`Source::material_key_fix`]).
    pub(super) fn thermal_strain(
        &self,
        seal: &SealSpec,
        material: &Material,
        environment: &TemperatureHistory,
        fix: &str,
    ) -> Result<Option<ThermalStrain>, ScenarioError> {
        let Some(housing) = &seal.housing_expansion else {
            return Ok(None);
        };
        let Some(rubber_expansion) = material.thermal_expansion else {
            if housing.by_default && seal.geometry.bolted() {
                // a bolted gasket by default: refused later only where the temperature departs
                // from the bolting's (Source::flat_without_expansion)
                return Ok(None);
            }
            let message = if housing.by_default {
                format!(
                    "a groove-seated ring follows the temperature by default (housing \"steel\", \
                     installed at 23 °C; docs/model.md §6.2), which needs the rubber's \
                     expansion, but the material ({}) gives no thermal_expansion; {fix}",
                    material.name
                )
            } else {
                format!(
                    "the thermal strain needs the rubber's expansion too, but the material ({}) \
                     gives no thermal_expansion; {fix}, or remove {}",
                    material.name,
                    housing.key.trim_start_matches("seal.")
                )
            };
            return Err(self.error(housing.span.clone(), housing.key, message));
        };
        Ok(Some(ThermalStrain {
            rubber_expansion,
            housing_expansion: housing.value,
            installation_temperature: seal.thermal_reference(environment),
            glassy_expansion: material.glassy_thermal_expansion,
            glass_transition: material.glass_transition,
        }))
    }

    /// A bolted flat gasket (displacement loading) whose compound gives no `thermal_expansion`
    /// runs without the thermal strain only where it would be zero: the whole temperature
    /// history and the shutdown at the bolting temperature. Elsewhere it is refused, naming
    /// the missing key — its compression changes with the temperature (docs/model.md §6), and a
    /// run without that strain would be the silent, non-conservative answer of a cold restart.
    pub(super) fn flat_without_expansion(
        &self,
        table: &Spanned<RawSeal>,
        seal: &SealSpec,
        material: &Material,
        environment: &TemperatureHistory,
        failure: &FailureCriteria,
        fix: &str,
    ) -> Result<(), ScenarioError> {
        let (Some(housing), true) = (&seal.housing_expansion, seal.geometry.bolted()) else {
            return Ok(());
        };
        let installed = seal.thermal_reference(environment);
        let (coldest, hottest) = environment.range();
        let shutdown = failure.shutdown.map_or(installed, |s| s.temperature);
        let departs = |t: f64| (t - installed).abs() > 1e-9;
        let Some(t) = [coldest, hottest, shutdown]
            .into_iter()
            .find(|&t| departs(t))
        else {
            return Ok(());
        };
        let span = table
            .get_ref()
            .kind
            .as_ref()
            .map_or(table.span(), Spanned::span);
        Err(self.error(
            span,
            housing.key,
            format!(
                "a flat gasket under displacement loading follows the temperature: its \
                 compression changes from the bolting temperature ({} K) to {} K (docs/model.md \
                 §6), which needs the rubber's expansion, but the material ({}) gives no \
                 thermal_expansion; {fix}, or set loading = \"force\" if springs or bolts \
                 keep the load",
                show(installed),
                show(t),
                material.name
            ),
        ))
    }

    /// `[environment]` (absent: constant at the shift's reference temperature, or 23 °C).
    ///
    /// Cycles: t = 0 is midnight of 1 January; the daily cycle peaks at 15:00
    /// (phase [`DAILY_PHASE`]), the yearly one at noon on 21 July ([`YEARLY_MAXIMUM`]).
    pub(super) fn environment(
        &self,
        table: Option<&Spanned<RawEnvironment>>,
        material: &Material,
    ) -> Result<TemperatureHistory, ScenarioError> {
        let default = match material.shift {
            Shift::Wlf { reference, .. } | Shift::Arrhenius { reference, .. } => reference,
            Shift::None => DEFAULT_TEMPERATURE,
        };
        let Some(table) = table else {
            return Ok(TemperatureHistory::constant(default));
        };
        let raw = table.get_ref();
        // a file of `time,pressure` leaves the temperature to `temperature` or its default
        let file = raw
            .history
            .as_ref()
            .map(|file| Ok::<_, ScenarioError>((file, self.history_file(file)?.temperature)))
            .transpose()?;
        let mut history = match (&raw.temperature, file) {
            (Some(_), Some((file, Some(_)))) => {
                return Err(self.error(
                    file.span(),
                    "environment.history",
                    "temperature and history are mutually exclusive: give a constant \
                     temperature or a history file with a temperature column, not both",
                ));
            }
            (_, Some((_, Some(points)))) => TemperatureHistory::table(points),
            (Some(t), _) => TemperatureHistory::constant(
                self.absolute_temperature(t, "environment.temperature")?,
            ),
            (None, _) => TemperatureHistory::constant(default),
        };
        let daily = self.optional(raw.daily_amplitude.as_ref(), &DAILY_AMPLITUDE)?;
        let yearly = self.optional(raw.yearly_amplitude.as_ref(), &YEARLY_AMPLITUDE)?;
        if let Some(amplitude) = daily {
            history = history.with_cycle(Cycle {
                amplitude,
                period: DAY,
                phase: DAILY_PHASE,
            });
        }
        if let Some(amplitude) = yearly {
            history = history.with_cycle(Cycle {
                amplitude,
                period: YEAR,
                phase: YEARLY_MAXIMUM - YEAR / 4.0,
            });
        }
        let (lowest, _) = history.range();
        if lowest <= 0.0 {
            let span = raw
                .daily_amplitude
                .as_ref()
                .or(raw.yearly_amplitude.as_ref())
                .map_or(table.span(), Spanned::span);
            let key = if raw.daily_amplitude.is_some() {
                DAILY_AMPLITUDE.key
            } else {
                YEARLY_AMPLITUDE.key
            };
            return Err(self.error(
                span,
                key,
                format!(
                    "the cycles take the temperature down to {} K, below absolute zero",
                    show(lowest)
                ),
            ));
        }
        Ok(history)
    }

    /// Reads `environment.history` (relative to the scenario's directory).
    fn history_file(&self, file: &Spanned<String>) -> Result<history::History, ScenarioError> {
        let path = self.relative_path(file.get_ref());
        let text = std::fs::read_to_string(&path).map_err(|e| {
            self.error(
                file.span(),
                "environment.history",
                format!("cannot read temperature history {}: {e}", path.display()),
            )
        })?;
        history::parse_history(&text).map_err(|e| self.history_error(file, e.line, e.message))
    }

    /// An error on line `line` of the history file `environment.history` names.
    fn history_error(
        &self,
        file: &Spanned<String>,
        line: Option<usize>,
        message: String,
    ) -> ScenarioError {
        ScenarioError::HistoryFormat {
            history: self.relative_path(file.get_ref()),
            history_line: line,
            scenario: self.path.to_path_buf(),
            line: self.line(file.span().start),
            message,
        }
    }

    /// The fluid pressure against time (docs/model.md §8.4): the history file's `pressure`
    /// column, `daily_pressure` (the low phase of a daily cycle, 21:00–09:00) and the proof
    /// before service (`proof_pressure` held for `proof_duration` from the installation).
    /// Pressures are in the fluid's terms: ΔP for a liquid (≥ 0), a gas's absolute inlet
    /// pressure (at or above its outlet pressure, which stays fixed). `None` when none is
    /// given: the run then has the constant service pressure, bit for bit as before.
    pub(super) fn pressure_history(
        &self,
        table: Option<&Spanned<RawEnvironment>>,
        fluid: &crate::fluid::Fluid,
    ) -> Result<Option<crate::pressure::PressureHistory>, ScenarioError> {
        use crate::pressure::{PressureHistory, Proof};
        let Some(table) = table else {
            return Ok(None);
        };
        let raw = table.get_ref();
        let datum = fluid.gas.map_or(0.0, |g| g.outlet_pressure);
        let service = datum + fluid.pressure_difference;
        // what a pressure may be, and the fix when it is not
        let check = |p: f64| -> Result<(), String> {
            match fluid.gas {
                Some(_) if p < 0.0 => Err(format!(
                    "{} Pa is a negative absolute pressure: for a gas the pressure is the \
                     absolute inlet pressure (a gauge reading plus the atmosphere, e.g. 7 bar \
                     gauge is \"8.01325 bar\")",
                    show(p)
                )),
                Some(_) if p < datum => Err(format!(
                    "{} Pa is below the gas's outlet pressure ({} Pa): the inlet pressure of a \
                     gas is absolute and the flow runs from inlet to outlet; give at least the \
                     outlet pressure (equal to it: depressurised)",
                    show(p),
                    show(datum)
                )),
                None if p < 0.0 => Err(format!(
                    "{} Pa is a negative pressure difference: the pressure of a liquid is the \
                     difference ΔP across the seal, 0 when depressurised (a reversed ΔP, the \
                     seal pushed from the other side, is not modelled)",
                    show(p)
                )),
                _ => Ok(()),
            }
        };
        let key = |q: &Quantity, field: &Field| -> Result<f64, ScenarioError> {
            let p = self.quantity(q, field)?;
            check(p).map_err(|m| self.error(q.span(), field.key, m))?;
            Ok(p)
        };
        let mut history = match &raw.history {
            Some(file) => match self.history_file(file)?.pressure {
                Some(rows) => {
                    for &(_, p, line) in &rows {
                        check(p).map_err(|m| self.history_error(file, Some(line), m))?;
                    }
                    Some(PressureHistory::table(
                        rows.into_iter().map(|(t, p, _)| (t, p)).collect(),
                        datum,
                    ))
                }
                None => None,
            },
            None => None,
        };
        if let Some(q) = &raw.daily_pressure {
            let low = key(q, &DAILY_PRESSURE)?;
            history = Some(
                history
                    .unwrap_or_else(|| PressureHistory::constant(service, datum))
                    .with_daily_low(low),
            );
        }
        match (&raw.proof_pressure, &raw.proof_duration) {
            (Some(q), Some(d)) => {
                let pressure = key(q, &PROOF_PRESSURE)?;
                let duration = self.quantity(d, &PROOF_DURATION)?;
                history = Some(
                    history
                        .unwrap_or_else(|| PressureHistory::constant(service, datum))
                        .with_proof(Proof { pressure, duration }),
                );
            }
            (Some(q), None) => {
                return Err(self.error(
                    q.span(),
                    PROOF_PRESSURE.key,
                    "a proof pressure needs its duration: add proof_duration (e.g. \
                     \"10 min\"), the time it is held from the installation before service",
                ));
            }
            (None, Some(d)) => {
                return Err(self.error(
                    d.span(),
                    PROOF_DURATION.key,
                    "a proof duration without its pressure: add proof_pressure (e.g. 1.5 times \
                     the service pressure) or remove proof_duration",
                ));
            }
            (None, None) => {}
        }
        Ok(history)
    }

    /// `[failure]`: any subset of the criteria (none: the run warns that the seal can only
    /// survive). Lift-off, the extrusion check and the shutdown check (docs/model.md §8.2) are on
    /// unless waived (`lift_off = false`, `extrusion = false`, `lost_interference = false`).
    /// The shutdown is at `shutdown_temperature` (default: the lower of 23 °C and the run's
    /// coldest temperature; not above the run's hottest) and `minimum_pressure_difference`
    /// (default 0, not above the service ΔP).
    pub(super) fn failure(
        &self,
        table: Option<&Spanned<RawFailure>>,
        fluid: &crate::fluid::Fluid,
        environment: &crate::material::TemperatureHistory,
        context: &FailureContext,
    ) -> Result<FailureCriteria, ScenarioError> {
        // the restart's pressure is bounded by the highest of the run (the service's, or a
        // pressure history's, docs/model.md §8.4)
        let highest = context
            .highest_pressure
            .unwrap_or(fluid.pressure_difference);
        let (coldest, hottest) = environment.range();
        let default_shutdown = crate::simulate::Shutdown {
            temperature: DEFAULT_SHUTDOWN_TEMPERATURE.min(coldest),
            pressure_difference: 0.0,
            cooling_time: context.cooling_time,
        };
        let default_margin = if context.moving {
            DYNAMIC_LOW_TEMPERATURE_MARGIN
        } else {
            DEFAULT_LOW_TEMPERATURE_MARGIN
        };
        let cold_limit = |margin: f64| {
            context
                .low_temperature_limit
                .map(|limit| crate::simulate::ColdLimit { limit, margin })
        };
        let Some(table) = table else {
            // the extrusion, shutdown and cold checks are on unless switched off; lift-off is
            // a failure unless waived
            return Ok(FailureCriteria {
                extrusion: true,
                lift_off: true,
                shutdown: Some(default_shutdown),
                low_temperature: cold_limit(default_margin),
                retained_force_reference: DEFAULT_RETAINED_FORCE_REFERENCE,
                ..FailureCriteria::default()
            });
        };
        let raw = table.get_ref();
        let reference = self.reference_state(raw, fluid)?;
        let waived = |b: &Option<Spanned<bool>>| b.as_ref().is_some_and(|b| !*b.get_ref());
        let (shutdown_temperature, minimum) = self.shutdown_keys(
            raw,
            context,
            (default_shutdown.temperature, hottest),
            highest,
        )?;
        let margin = self
            .optional(raw.low_temperature_margin.as_ref(), &LOW_TEMPERATURE_MARGIN)?
            .unwrap_or(default_margin);
        if let Some(q) = &raw.low_temperature_margin
            && waived(&raw.low_temperature)
        {
            return Err(self.error(
                q.span(),
                LOW_TEMPERATURE_MARGIN.key,
                "a margin for a cold limit that low_temperature = false waives: remove one of \
                 the two"
                    .to_owned(),
            ));
        }
        Ok(FailureCriteria {
            max_leak_rate: raw
                .max_leak_rate
                .as_ref()
                .map(|q| self.max_leak_rate(q, fluid, reference))
                .transpose()?,
            max_leaked_volume: raw
                .max_leaked_volume
                .as_ref()
                .map(|q| self.max_leaked_volume(q, fluid, reference))
                .transpose()?,
            min_retained_force: self
                .optional(raw.min_retained_force.as_ref(), &MIN_RETAINED_FORCE)?,
            retained_force_reference: self
                .optional(
                    raw.retained_force_reference.as_ref(),
                    &RETAINED_FORCE_REFERENCE,
                )?
                .unwrap_or(DEFAULT_RETAINED_FORCE_REFERENCE),
            max_compression_set: self
                .optional(raw.max_compression_set.as_ref(), &MAX_COMPRESSION_SET)?,
            min_sealing_force: self.optional(raw.min_sealing_force.as_ref(), &MIN_SEALING_FORCE)?,
            min_contact_pressure: self
                .optional(raw.min_contact_pressure.as_ref(), &MIN_CONTACT_PRESSURE)?,
            gasket_factor: self.optional(raw.gasket_factor.as_ref(), &GASKET_FACTOR)?,
            // on unless waived: an open seal is a failed seal
            lift_off: !waived(&raw.lift_off),
            // on unless switched off: it applies to groove-seated rings only
            extrusion: !waived(&raw.extrusion),
            shutdown: (!waived(&raw.lost_interference)).then_some(crate::simulate::Shutdown {
                temperature: shutdown_temperature,
                pressure_difference: minimum,
                cooling_time: context.cooling_time,
            }),
            // on unless waived, for a compound with a T10 (docs/model.md §8.3)
            low_temperature: if waived(&raw.low_temperature) {
                None
            } else {
                cold_limit(margin)
            },
            stop_at_failure: false,
        })
    }

    /// `[failure] shutdown_temperature` and `minimum_pressure_difference` (docs/model.md §8.2):
    /// refused where the check does not run, bounded by the run's hottest temperature and its
    /// highest pressure difference \[Pa\]; `(default_temperature, hottest)` \[K\].
    fn shutdown_keys(
        &self,
        raw: &RawFailure,
        context: &FailureContext,
        (default_temperature, hottest): (f64, f64),
        highest: f64,
    ) -> Result<(f64, f64), ScenarioError> {
        let waived = |b: &Option<Spanned<bool>>| b.as_ref().is_some_and(|b| !*b.get_ref());
        // a key of a check that does not run is an error, never ignored
        for (q, key) in [
            (&raw.shutdown_temperature, "failure.shutdown_temperature"),
            (
                &raw.minimum_pressure_difference,
                MINIMUM_PRESSURE_DIFFERENCE.key,
            ),
        ] {
            let Some(q) = q else { continue };
            if let Some(reason) = context.no_shutdown {
                return Err(self.error(
                    q.span(),
                    key,
                    format!(
                        "sets the shutdown check (docs/model.md §8.2), which does not apply here: \
                         {reason}; remove it"
                    ),
                ));
            }
            if waived(&raw.lost_interference) {
                return Err(self.error(
                    q.span(),
                    key,
                    "sets the shutdown check that lost_interference = false waives: remove one \
                     of the two",
                ));
            }
        }
        let shutdown_temperature = match &raw.shutdown_temperature {
            None => default_temperature,
            Some(q) => {
                let t = self.absolute_temperature(q, "failure.shutdown_temperature")?;
                if t > hottest + 1e-9 {
                    let unit = match q.get_ref() {
                        super::raw::RawQuantity::Text(text) => {
                            crate::units::TemperatureUnit::of(text)
                        }
                        super::raw::RawQuantity::Number(_) => Default::default(),
                    };
                    return Err(self.error(
                        q.span(),
                        "failure.shutdown_temperature",
                        format!(
                            "{} is above the run's hottest temperature ({}): a shutdown is the \
                             seal at rest, no hotter than in service; give a temperature of at \
                             most \"{}\"",
                            unit.show(t),
                            unit.show(hottest),
                            unit.input(hottest),
                        ),
                    ));
                }
                t
            }
        };
        let minimum = self
            .optional(
                raw.minimum_pressure_difference.as_ref(),
                &MINIMUM_PRESSURE_DIFFERENCE,
            )?
            .unwrap_or(0.0);
        if let Some(q) = &raw.minimum_pressure_difference
            && minimum > highest
        {
            return Err(self.error(
                q.span(),
                MINIMUM_PRESSURE_DIFFERENCE.key,
                format!(
                    "{} Pa is above the service pressure difference ({} Pa): the minimum is the \
                     lowest pressure the seal must hold at a restart; give at most the service \
                     ΔP, e.g. \"0 bar\"",
                    show(minimum),
                    show(highest)
                ),
            ));
        }
        Ok((shutdown_temperature, minimum))
    }

    /// `[failure] max_leak_rate` as the leak rate the run compares it with: a liquid's volume
    /// flow \[m³/s\]; for a gas a throughput ([`crate::units::parse_throughput`] at the gas
    /// temperature T(0): Pa·m³/s, mbar·L/s, Torr·L/s, sccm, slm, mol/s), returned as the
    /// volume flow at the mean pressure it stands for, `Q/p̄` (docs/model.md §3.9). A
    /// throughput for a liquid is refused; a volume flow for a gas only with its
    /// `reference` state (its volume flow depends on the pressure it is counted at).
    fn max_leak_rate(
        &self,
        raw: &super::raw::Quantity,
        fluid: &crate::fluid::Fluid,
        reference: Option<ReferenceState>,
    ) -> Result<f64, ScenarioError> {
        let text = match raw.get_ref() {
            super::raw::RawQuantity::Text(t) => Some(t.as_str()),
            super::raw::RawQuantity::Number(_) => None,
        };
        let (Some(gas), Some(p_mean)) = (fluid.gas, fluid.mean_pressure()) else {
            if let Some(t) = text
                && crate::units::parse_throughput(t, 293.15).is_ok()
            {
                return Err(self.error(
                    raw.span(),
                    MAX_LEAK_RATE.key,
                    format!(
                        "\"{t}\" is a gas throughput, but [fluid] is a liquid: give a volume flow \
                         (e.g. \"1e-9 m^3/s\"), or make [fluid] a gas (`gas = \"helium\"`)"
                    ),
                ));
            }
            return self.quantity(raw, &MAX_LEAK_RATE);
        };
        let Some(t) = text else {
            return Err(self.error(
                raw.span(),
                MAX_LEAK_RATE.key,
                "a gas's leak-rate criterion needs its unit: a throughput such as \
                 \"1e-9 mbar*L/s\", \"1e-10 Pa*m^3/s\", \"1e-4 sccm\" or \"1e-12 mol/s\"",
            ));
        };
        let q = if let Ok(v) = crate::units::parse_quantity(t, Dimension::VOLUME_FLOW) {
            let Some(r) = reference else {
                return Err(self.error(
                    raw.span(),
                    MAX_LEAK_RATE.key,
                    format!(
                        "\"{t}\" is a volume flow, but [fluid] is a gas, whose volume flow \
                         depends on the pressure it is counted at: give a throughput (Pa*m^3/s, \
                         mbar*L/s, Torr*L/s, sccm, slm or mol/s), or state the conditions with \
                         `reference_pressure` (and `reference_temperature`) in [failure]"
                    ),
                ));
            };
            r.throughput(v, gas.temperature)
        } else {
            crate::units::parse_throughput(t, gas.temperature)
                .map_err(|e| self.error(raw.span(), MAX_LEAK_RATE.key, e.to_string()))?
        };
        if !(1e-30..=1e6).contains(&q) {
            return Err(self.error(
                raw.span(),
                MAX_LEAK_RATE.key,
                format!("must lie in [1e-30, 1e6] Pa·m³/s, got {} Pa·m³/s", show(q)),
            ));
        }
        Ok(q / p_mean)
    }

    /// `[failure] reference_pressure` and `reference_temperature`: the state at which a gas's
    /// volume criteria are counted (docs/model.md §3.9). Only for a gas; the temperature
    /// defaults to the gas temperature at installation.
    fn reference_state(
        &self,
        raw: &RawFailure,
        fluid: &crate::fluid::Fluid,
    ) -> Result<Option<ReferenceState>, ScenarioError> {
        let Some(pressure) = raw.reference_pressure.as_ref() else {
            if let Some(t) = raw.reference_temperature.as_ref() {
                return Err(self.error(
                    t.span(),
                    "failure.reference_temperature",
                    "goes with `reference_pressure`: a volume of gas is counted at a pressure \
                     and a temperature",
                ));
            }
            return Ok(None);
        };
        let Some(gas) = fluid.gas else {
            return Err(self.error(
                pressure.span(),
                REFERENCE_PRESSURE.key,
                "the reference state of a volume criterion belongs to a gas; a liquid's volume \
                 does not depend on it",
            ));
        };
        let temperature = match raw.reference_temperature.as_ref() {
            Some(t) => self.absolute_temperature(t, "failure.reference_temperature")?,
            None => gas.temperature,
        };
        Ok(Some(ReferenceState {
            pressure: self.quantity(pressure, &REFERENCE_PRESSURE)?,
            temperature,
        }))
    }

    /// `[failure] max_leaked_volume` as the volume the run integrates: a liquid's volume
    /// \[m³\]; for a gas, the volume at the mean pressure p̄ that carries the same amount of gas
    /// at the gas temperature T(0): a pV amount (`mbar*L`, `Pa*m^3`) `/p̄`, an amount (`mol`)
    /// `n R T/p̄`, or a volume at the stated reference state `p_ref V T/(T_ref p̄)` (docs/model.md
    /// §3.9). A volume of gas without its reference state is refused.
    fn max_leaked_volume(
        &self,
        raw: &super::raw::Quantity,
        fluid: &crate::fluid::Fluid,
        reference: Option<ReferenceState>,
    ) -> Result<f64, ScenarioError> {
        let (Some(gas), Some(p_mean), super::raw::RawQuantity::Text(t)) =
            (fluid.gas, fluid.mean_pressure(), raw.get_ref())
        else {
            return self.quantity(raw, &MAX_LEAKED_VOLUME);
        };
        let pv = if let Ok(v) = crate::units::parse_quantity(t, Dimension::VOLUME) {
            let Some(r) = reference else {
                return Err(self.error(
                    raw.span(),
                    MAX_LEAKED_VOLUME.key,
                    format!(
                        "\"{t}\" is a volume, but [fluid] is a gas, whose volume depends on the \
                         pressure it is counted at: give an amount of gas (\"1 mbar*L\", \
                         \"1e-3 Pa*m^3\", \"1e-6 mol\"), or state the conditions with \
                         `reference_pressure` (and `reference_temperature`) in [failure]"
                    ),
                ));
            };
            r.throughput(v, gas.temperature)
        } else if let Ok(pv) = crate::units::parse_quantity(t, Dimension::ENERGY) {
            pv
        } else if let Ok(n) = crate::units::parse_quantity(t, Dimension::AMOUNT) {
            n * crate::gas::GAS_CONSTANT * gas.temperature
        } else {
            return Err(self.error(
                raw.span(),
                MAX_LEAKED_VOLUME.key,
                format!(
                    "\"{t}\" is not an amount of gas: give a pV amount (\"1 mbar*L\", \
                     \"1e-3 Pa*m^3\"), a molar amount (\"1e-6 mol\"), or a volume with \
                     `reference_pressure` stated"
                ),
            ));
        };
        let v = pv / p_mean;
        if !(1e-30..=1e6).contains(&v) {
            return Err(self.error(
                raw.span(),
                MAX_LEAKED_VOLUME.key,
                format!(
                    "as a volume at the mean pressure p̄ = {} Pa it must lie in [1e-30, 1e6] m³, \
                     got {} m³",
                    show(p_mean),
                    show(v)
                ),
            ));
        }
        Ok(v)
    }

    /// `seal.installation_time` (default [`DEFAULT_INSTALLATION_TIME`]).
    pub(super) fn installation_time(&self, table: &Spanned<RawSeal>) -> Result<f64, ScenarioError> {
        Ok(self
            .optional(
                table.get_ref().installation_time.as_ref(),
                &INSTALLATION_TIME,
            )?
            .unwrap_or(DEFAULT_INSTALLATION_TIME))
    }

    /// Chemical ageing (docs/model.md §6.5): **on whenever constants are known** — the
    /// compound's `[material.ageing]` without an `[ageing]` table; the table's own constants,
    /// each missing one from the compound's; off with `[ageing] enabled = false`. In a
    /// comparison (`in_comparison`) a compound that cannot complete the table runs without
    /// ageing instead of failing the whole comparison; elsewhere that is an error naming the
    /// missing key.
    pub(super) fn scenario_ageing(
        &self,
        table: Option<&Spanned<RawScenarioAgeing>>,
        material: &Material,
        in_comparison: bool,
    ) -> Result<(Option<Ageing>, AgeingSource), ScenarioError> {
        let own = material.ageing;
        let Some(table) = table else {
            return Ok(match own {
                Some(a) => (Some(a), AgeingSource::Compound),
                None => (None, AgeingSource::NoData),
            });
        };
        let raw = table.get_ref();
        if let Some(enabled) = &raw.enabled
            && !*enabled.get_ref()
        {
            let given = [
                (raw.activation_energy.as_ref(), "activation_energy"),
                (raw.rate.as_ref(), "rate"),
                (raw.reference_temperature.as_ref(), "reference_temperature"),
                (raw.crosslinking.as_ref(), "crosslinking"),
            ];
            if let Some((q, key)) = given.into_iter().find_map(|(q, k)| q.map(|q| (q, k))) {
                return Err(self.error(
                    q.span(),
                    &format!("ageing.{key}"),
                    "[ageing] is switched off (enabled = false): remove the constant, or \
                     `enabled = false`",
                ));
            }
            return Ok((None, AgeingSource::Off));
        }
        let complete = own.is_some()
            || (raw.activation_energy.is_some()
                && raw.rate.is_some()
                && raw.reference_temperature.is_some());
        if !complete && in_comparison {
            return Ok((None, AgeingSource::MissingInComparison));
        }
        let missing = |key: &str| {
            self.error(
                table.span(),
                &format!("ageing.{key}"),
                format!(
                    "missing key `{key}` in [ageing], and the material ({}) gives no ageing \
                     constants ([material.ageing]) to default to; give activation_energy, rate \
                     and reference_temperature, or switch ageing off with `enabled = false`",
                    material.name
                ),
            )
        };
        // a scenario's energy is one law on both sides; the compound's keeps its band
        let (activation_energy, activation_energy_above) = match &raw.activation_energy {
            Some(q) => {
                let e = self.quantity(q, &AGEING_ACTIVATION_ENERGY)?;
                (e, e)
            }
            None => own
                .map(|a| (a.activation_energy, a.activation_energy_above))
                .ok_or_else(|| missing("activation_energy"))?,
        };
        let rate = match &raw.rate {
            Some(q) => self.quantity(q, &AGEING_RATE)?,
            None => own.map(|a| a.rate).ok_or_else(|| missing("rate"))?,
        };
        let reference_temperature = match &raw.reference_temperature {
            Some(q) => self.absolute_temperature(q, "ageing.reference_temperature")?,
            None => own
                .map(|a| a.reference_temperature)
                .ok_or_else(|| missing("reference_temperature"))?,
        };
        let crosslinking = match &raw.crosslinking {
            Some(q) => self.quantity(q, &AGEING_CROSSLINKING)?,
            None => own.map_or(BALANCED_CROSSLINKING, |a| a.crosslinking),
        };
        let source = if raw.activation_energy.is_none()
            && raw.rate.is_none()
            && raw.reference_temperature.is_none()
            && raw.crosslinking.is_none()
        {
            AgeingSource::Compound
        } else {
            AgeingSource::Scenario
        };
        Ok((
            Some(Ageing {
                activation_energy,
                activation_energy_above,
                rate,
                reference_temperature,
                crosslinking,
            }),
            source,
        ))
    }

    /// `[simulation]`: the time grid and the fidelity.
    pub(super) fn simulation(
        &self,
        table: Option<&Spanned<RawSimulation>>,
    ) -> Result<(TimeGrid, Fidelity), ScenarioError> {
        let Some(table) = table else {
            return Ok((
                TimeGrid {
                    start: DEFAULT_START,
                    duration: DEFAULT_DURATION,
                    points_per_decade: DEFAULT_POINTS_PER_DECADE,
                    tolerance: TimeGrid::DEFAULT_TOLERANCE,
                },
                Fidelity::Table,
            ));
        };
        let raw = table.get_ref();
        let duration = self
            .optional(raw.duration.as_ref(), &DURATION)?
            .unwrap_or(DEFAULT_DURATION);
        let start = self
            .optional(raw.start.as_ref(), &START)?
            .unwrap_or(DEFAULT_START);
        if duration <= start {
            let (span, key) = match (&raw.duration, &raw.start) {
                (Some(q), _) => (q.span(), DURATION.key),
                (None, Some(q)) => (q.span(), START.key),
                (None, None) => (table.span(), DURATION.key),
            };
            return Err(self.error(
                span,
                key,
                format!(
                    "duration ({} s) must exceed start ({} s), the first time after installation",
                    show(duration),
                    show(start)
                ),
            ));
        }
        let points_per_decade = self
            .optional(raw.points_per_decade.as_ref(), &POINTS_PER_DECADE)?
            .unwrap_or(DEFAULT_POINTS_PER_DECADE);
        let tolerance = self
            .optional(raw.tolerance.as_ref(), &TOLERANCE)?
            .unwrap_or(TimeGrid::DEFAULT_TOLERANCE);
        let fidelity = match &raw.fidelity {
            None => Fidelity::Table,
            Some(f) => parse_fidelity(f.get_ref())
                .map_err(|message| self.error(f.span(), "simulation.fidelity", message))?,
        };
        Ok((
            TimeGrid {
                start,
                duration,
                points_per_decade,
                tolerance,
            },
            fidelity,
        ))
    }

    /// Refuses a run whose temperature cycles would need more than [`MAX_CYCLE_STEPS`]
    /// internal steps (eight per period of the shortest cycle between `start` and `duration`),
    /// reported at `simulation.duration` (or, if that is not written, at the cycle's amplitude).
    pub(super) fn cycle_budget(
        &self,
        simulation: Option<&Spanned<RawSimulation>>,
        environment: Option<&Spanned<RawEnvironment>>,
        (history, pressure): (
            &TemperatureHistory,
            Option<&crate::pressure::PressureHistory>,
        ),
        time: &TimeGrid,
    ) -> Result<(), ScenarioError> {
        // a daily pressure cycle costs four knots a day, counted as a cycle's eight (the bound)
        let Some(period) = history
            .shortest_period()
            .into_iter()
            .chain(pressure.and_then(crate::pressure::PressureHistory::period))
            .min_by(f64::total_cmp)
        else {
            return Ok(());
        };
        let steps = 8.0 * (time.duration - time.start) / period;
        if steps <= MAX_CYCLE_STEPS {
            return Ok(());
        }
        let written = simulation.and_then(|t| t.get_ref().duration.as_ref());
        let (span, key) = match (written, environment) {
            (Some(q), _) => (q.span(), DURATION.key),
            (None, Some(env)) => {
                let raw = env.get_ref();
                match (&raw.daily_amplitude, &raw.yearly_amplitude) {
                    (None, _) if period < YEAR && raw.daily_pressure.is_some() => (
                        raw.daily_pressure
                            .as_ref()
                            .map_or(env.span(), Spanned::span),
                        DAILY_PRESSURE.key,
                    ),
                    (Some(q), _) if period < YEAR => (q.span(), DAILY_AMPLITUDE.key),
                    (_, Some(q)) => (q.span(), YEARLY_AMPLITUDE.key),
                    _ => (env.span(), DURATION.key),
                }
            }
            (None, None) => return Ok(()),
        };
        Err(self.error(
            span,
            key,
            format!(
                "a run of {} s with a temperature cycle of period {} s needs {} internal steps \
                 (8 per cycle), more than the limit of {} ({} s of this cycle): shorten \
                 simulation.duration or drop the cycle",
                show(time.duration),
                show(period),
                show(steps.round()),
                show(MAX_CYCLE_STEPS),
                show((MAX_CYCLE_STEPS / 8.0 * period).round())
            ),
        ))
    }
}

/// A fidelity name of the ladder (docs/model.md §4): `rule-of-thumb`, `critical-junction` (= `table`,
/// the contact table), `exact` (critical junction by quadrature), `effective-medium`,
/// `numerical` — the names and aliases of [`Fidelity::ALL`].
pub fn parse_fidelity(name: &str) -> Result<Fidelity, String> {
    Fidelity::from_name(name).ok_or_else(|| {
        let levels: Vec<String> = Fidelity::ALL
            .into_iter()
            .map(|f| {
                let aliases: Vec<String> = f.aliases().iter().map(|a| format!("{a:?}")).collect();
                if aliases.is_empty() {
                    format!("{:?}", f.name())
                } else {
                    format!("{:?} (= {})", f.name(), aliases.join(", "))
                }
            })
            .collect();
        format!("must be one of {}, got {name:?}", levels.join(", "))
    })
}

/// The state at which a gas's volume criteria are counted (`[failure] reference_pressure`,
/// `reference_temperature`).
#[derive(Debug, Clone, Copy)]
struct ReferenceState {
    /// p_ref \[Pa\].
    pressure: f64,
    /// T_ref \[K\].
    temperature: f64,
}

impl ReferenceState {
    /// The pV amount (or flow) at the gas temperature `t` \[K\] of a volume (or volume flow)
    /// `v` counted at this state: the same moles `p_ref v/(R T_ref)` carry `p_ref v t/T_ref`.
    fn throughput(self, v: f64, t: f64) -> f64 {
        self.pressure * v * t / self.temperature
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{Scenario, ScenarioError, library};
    use crate::seal::SealGeometry;
    use crate::simulate::{AsperityModulus, Loading};
    use std::f64::consts::PI;
    use std::path::Path;

    /// An O-ring scenario; line numbers in the tests refer to this text.
    const ORING: &str = r#"name = "o-ring"
[material]
library = "nbr-70"
[surface]
rms_roughness = "0.8 um"
hurst_exponent = 0.7
q0 = "3e5 1/m"
q1 = "1e10 1/m"
[fluid]
viscosity = "1 mPa*s"
pressure_difference = "2 bar"
[seal]
kind = "o-ring"
cross_section = "3.53 mm"
mean_diameter = "50 mm"
squeeze = 0.2
"#;

    fn load(text: &str) -> Result<Scenario, ScenarioError> {
        Scenario::from_str(text, Path::new("dir/s.toml"))
    }

    fn error(text: &str) -> String {
        load(text).expect_err("should be rejected").to_string()
    }

    fn with(extra: &str) -> String {
        format!("{ORING}{extra}")
    }

    #[test]
    fn oring_defaults_and_static_problem() {
        let s = load(ORING).unwrap();
        let life = &s.life;
        let SealGeometry::ORing {
            cross_section,
            mean_diameter,
            squeeze,
        } = life.geometry
        else {
            panic!("an O-ring: {:?}", life.geometry)
        };
        assert!((cross_section / 3.53e-3 - 1.0).abs() < 1e-15);
        assert_eq!((mean_diameter, squeeze), (0.05, 0.2));
        assert_eq!(life.loading, Loading::Displacement);
        assert_eq!(life.asperity_modulus, AsperityModulus::Follow);
        // no [environment]: constant at the WLF reference temperature (23 °C)
        assert!(life.environment.is_constant());
        assert!((life.environment.at(1e6) - 296.15).abs() < 1e-9);
        // no [failure]: the default checks only (lift-off, extrusion, shutdown), no criterion
        assert!(life.failure.lift_off && life.failure.max_leak_rate.is_none());
        // nbr-70 carries ageing constants: on by default
        assert_eq!(life.ageing, life.material.ageing);
        assert!(life.thermal_strain.is_none());
        assert_eq!(
            life.time,
            TimeGrid {
                start: 1.0,
                duration: 30.0 * YEAR,
                points_per_decade: 20.0,
                tolerance: TimeGrid::DEFAULT_TOLERANCE,
            }
        );
        assert_eq!((life.fidelity, life.strips), (Fidelity::Table, 16));
        // `leak`: Hertz peak of Lindley's force with the modulus at the end of the 1 s
        // installation ramp, E∞ + Σ E_i τ_i (1 − e^{−1 s/τ_i})/1 s, Lindley's width, π D
        assert_eq!(life.installation_time, 1.0);
        let prony = &s.material.prony;
        let e0 = prony.long_term()
            + prony
                .terms()
                .iter()
                .map(|t| t.modulus * t.tau * -(-1.0 / t.tau).exp_m1())
                .sum::<f64>();
        let g = 1.25 * 0.2f64.powf(1.5) + 50.0 * 0.2f64.powi(6);
        let b = 3.53e-3 * (1.2 / PI).sqrt();
        let peak = 4.0 * e0 * cross_section * g / (PI * b);
        let seal = s.problem.seal;
        assert!((seal.nominal_pressure / peak - 1.0).abs() < 1e-12);
        assert!((seal.width / b - 1.0).abs() < 1e-12);
        assert!((seal.length / (PI * 0.05) - 1.0).abs() < 1e-12);
        // the static problem's asperities: the installed modulus (`follow`, the default)
        assert!((s.problem.material.youngs_modulus / e0 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn flat_seals_keep_their_keys_and_may_be_force_loaded() {
        let flat = ORING.replace(
            "kind = \"o-ring\"\ncross_section = \"3.53 mm\"\nmean_diameter = \"50 mm\"\nsqueeze = 0.2\n",
            "nominal_pressure = \"1 MPa\"\nwidth = \"2 mm\"\nlength = \"0.1 m\"\nloading = \"force\"\n",
        );
        let s = load(&flat).unwrap();
        assert_eq!(
            s.life.geometry,
            SealGeometry::Flat {
                nominal_pressure: 1e6,
                width: 2e-3,
                length: 0.1,
                compression: DEFAULT_FLAT_COMPRESSION,
                thickness: None,
            }
        );
        assert_eq!(s.life.loading, Loading::Force);
        assert_eq!(s.problem.seal.nominal_pressure, 1e6);
        let e = error(&flat.replace("loading = \"force\"", "loading = \"spring\""));
        assert!(
            e.contains(":16: seal.loading: must be \"displacement\""),
            "{e}"
        );
        let e = error(&format!("{flat}squeeze = 0.2\n"));
        assert!(
            e.contains(":17: seal.squeeze: not a key of a flat seal"),
            "{e}"
        );
        let e = error(&flat.replace("width = \"2 mm\"\n", ""));
        assert!(
            e.contains(":12: seal.width: missing key `width` in [seal]"),
            "{e}"
        );
    }

    #[test]
    fn oring_errors_are_located() {
        let cases = [
            (
                "squeeze = 0.2",
                "squeeze = 1",
                ":16: seal.squeeze: must lie strictly between 0 and 1",
            ),
            (
                "squeeze = 0.2",
                "squeeze = 0",
                ":16: seal.squeeze: must lie strictly between 0 and 1",
            ),
            (
                "\"50 mm\"",
                "\"3 mm\"",
                ":15: seal.mean_diameter: must exceed the cross_section",
            ),
            (
                "\"o-ring\"",
                "\"x-ring\"",
                ":13: seal.kind: must be \"flat\" or \"o-ring\"",
            ),
            (
                "squeeze = 0.2\n",
                "",
                ":12: seal.squeeze: missing key `squeeze` in [seal]",
            ),
            (
                "squeeze = 0.2",
                "squeeze = 0.2\nwidth = 1",
                ":17: seal.width: not a key of an O-ring seal",
            ),
            (
                "squeeze = 0.2",
                "squeeze = 0.2\ninstallation_temperature = \"20 C\"",
                ":17: seal.installation_temperature: the thermal strain",
            ),
        ];
        for (from, to, expected) in cases {
            let e = error(&ORING.replace(from, to));
            assert!(
                e.starts_with("dir/s.toml:") && e.contains(expected),
                "{to}: {e}"
            );
        }
    }

    #[test]
    fn thermal_strain_needs_the_rubbers_expansion() {
        let s = load(&ORING.replace(
            "squeeze = 0.2",
            "squeeze = 0.2\nhousing_expansion = \"12e-6 1/K\"",
        ))
        .unwrap();
        let th = s.life.thermal_strain.unwrap();
        assert_eq!(th.housing_expansion, 12e-6);
        assert_eq!(Some(th.rubber_expansion), s.material.thermal_expansion);
        assert_eq!(th.installation_temperature, 296.15, "T(0) by default");
        let s = load(&ORING.replace(
            "squeeze = 0.2",
            "squeeze = 0.2\nhousing_expansion = 0\ninstallation_temperature = \"-10 C\"",
        ))
        .unwrap();
        assert_eq!(
            s.life.thermal_strain.unwrap().installation_temperature,
            263.15
        );
        // an inline material without thermal_expansion
        let inline = ORING
            .replace(
                "library = \"nbr-70\"",
                "youngs_modulus = \"10 MPa\"\npoisson_ratio = 0.5",
            )
            .replace(
                "squeeze = 0.2",
                "squeeze = 0.2\nhousing_expansion = \"12e-6 1/K\"",
            );
        let e = error(&inline);
        assert!(
            e.contains(":18: seal.housing_expansion: the thermal strain needs the rubber's expansion too, but the material (o-ring) gives no thermal_expansion"),
            "{e}"
        );
    }

    #[test]
    fn asperity_modulus_option() {
        let m = |value: &str| {
            load(&ORING.replace(
                "library = \"nbr-70\"",
                &format!("library = \"nbr-70\"\nasperity_modulus = {value}"),
            ))
            .map(|s| s.life.asperity_modulus)
        };
        assert_eq!(m("\"relaxed\"").unwrap(), AsperityModulus::Relaxed);
        assert_eq!(
            m("\"instantaneous\"").unwrap(),
            AsperityModulus::Instantaneous
        );
        assert_eq!(m("\"follow\"").unwrap(), AsperityModulus::Follow);
        assert_eq!(m("\"3 MPa\"").unwrap(), AsperityModulus::Fixed(3e6));
        assert_eq!(m("\"2e6 Pa\"").unwrap(), AsperityModulus::Fixed(2e6));
        // a bare modulus is ambiguous: refused
        assert!(m("2e6").is_err());
        let e = m("\"relaxd\"").unwrap_err().to_string();
        assert!(
            e.contains(":4: material.asperity_modulus: must be \"relaxed\""),
            "{e}"
        );
        let e = m("\"3 mm\"").unwrap_err().to_string();
        assert!(
            e.contains(":4: material.asperity_modulus: expected a pressure"),
            "{e}"
        );
        let e = m("\"-3 MPa\"").unwrap_err().to_string();
        assert!(e.contains("must be positive"), "{e}");
        // a library reference still takes no other key
        let e = error(&ORING.replace("library = \"nbr-70\"", "library = \"nbr-70\"\nname = \"x\""));
        assert!(
            e.contains(":4: material.name: a library material takes no other keys"),
            "{e}"
        );
        // inline materials take it too; material files do not
        let inline = ORING.replace(
            "library = \"nbr-70\"",
            "youngs_modulus = \"10 MPa\"\npoisson_ratio = 0.5\nasperity_modulus = \"instantaneous\"",
        );
        assert_eq!(
            load(&inline).unwrap().life.asperity_modulus,
            AsperityModulus::Instantaneous
        );
        let file = "[material]\npoisson_ratio = 0.5\nyoungs_modulus = 1e7\nasperity_modulus = \"follow\"\n";
        let e = crate::scenario::material_from_str(file, Path::new("m.toml"))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains(
                "m.toml:4: material.asperity_modulus: asperity_modulus is a scenario option"
            ),
            "{e}"
        );
    }

    #[test]
    fn environment_constant_cycles_and_exclusivity() {
        let s = load(&with("[environment]\ntemperature = \"80 C\"\n")).unwrap();
        assert_eq!(s.life.environment.at(0.0), 353.15);
        let s = load(&with(
            "[environment]\ntemperature = \"10 C\"\ndaily_amplitude = \"8 K\"\nyearly_amplitude = \"12 K\"\n",
        ))
        .unwrap();
        let env = &s.life.environment;
        // daily maximum at 15:00 (the yearly term varies little within a day)
        let day = |h: f64| env.at(200.0 * DAY + h * 3600.0);
        assert!(day(15.0) > day(14.5) && day(15.0) > day(15.5));
        assert!(day(3.0) < day(2.5) && day(3.0) < day(3.5));
        // yearly maximum at noon on 21 July (day 201.5): compare whole days at 15:00
        let at_day = |d: f64| env.at(d * DAY + 15.0 * 3600.0);
        assert!(at_day(201.0) > at_day(171.0) && at_day(201.0) > at_day(231.0));
        let (lo, hi) = env.range();
        assert!((lo - 263.15).abs() < 1e-9 && (hi - 303.15).abs() < 1e-9);
        // mutually exclusive with a file that has a temperature column (read: a `time,pressure`
        // file leaves the temperature to the key), and no temperature below 0 K
        let dir = tempfile::tempdir().unwrap();
        let both = with("[environment]\ntemperature = \"10 C\"\nhistory = \"t.csv\"\n");
        let path = dir.path().join("s.toml");
        std::fs::write(dir.path().join("t.csv"), "time,temperature\nh,C\n0,25\n").unwrap();
        let e = Scenario::from_str(&both, &path).unwrap_err().to_string();
        assert!(
            e.contains(":19: environment.history: temperature and history are mutually exclusive"),
            "{e}"
        );
        std::fs::write(dir.path().join("t.csv"), "time,pressure\nh,bar\n0,2\n1,0\n").unwrap();
        let s = Scenario::from_str(&both, &path).unwrap();
        assert!(s.life.environment.is_constant());
        assert!((s.life.environment.at(0.0) - 283.15).abs() < 1e-9);
        let p = s.life.pressure.as_ref().unwrap();
        assert_eq!((p.difference_at(0.0), p.difference_at(3600.0)), (2e5, 0.0));
        let e = error(&with(
            "[environment]\ntemperature = \"10 K\"\ndaily_amplitude = \"20 K\"\n",
        ));
        assert!(
            e.contains(":19: environment.daily_amplitude: the cycles take the temperature down to"),
            "{e}"
        );
        let e = error(&with(
            "[environment]\ntemperature = \"10 C\"\nhumidity = 0.5\n",
        ));
        assert!(
            e.contains(":19: environment.humidity: unknown key `humidity`"),
            "{e}"
        );
    }

    #[test]
    fn environment_history_is_read_relative_to_the_scenario() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(
            dir.path().join("t.csv"),
            "time,temperature\nh,C\n0,25\n2,-40\n",
        )
        .unwrap();
        let path = dir.path().join("s.toml");
        let text = with("[environment]\nhistory = \"t.csv\"\ndaily_amplitude = \"1 K\"\n");
        let s = Scenario::from_str(&text, &path).unwrap();
        let env = &s.life.environment;
        assert!(!env.is_constant());
        assert!(
            (env.at(3600.0)
                - (273.15 - 7.5)
                - 1.0 * (std::f64::consts::TAU * (3600.0 - DAILY_PHASE) / DAY).sin())
            .abs()
                < 1e-9
        );
        // a malformed file names its own line and the scenario's key
        std::fs::write(
            dir.path().join("t.csv"),
            "time,temperature\ns,K\n0,300\n10,warm\n",
        )
        .unwrap();
        let e = Scenario::from_str(&text, &path).unwrap_err();
        assert!(
            matches!(
                e,
                ScenarioError::HistoryFormat {
                    history_line: Some(4),
                    line: 18,
                    ..
                }
            ),
            "{e}"
        );
        let e = e.to_string();
        assert!(e.contains("t.csv:4: temperature is not a number: \"warm\" (temperature history named by environment.history at "), "{e}");
        assert!(e.ends_with("s.toml:18)"), "{e}");
        // a missing file is an error at the key
        let e = Scenario::from_str(&text.replace("t.csv", "none.csv"), &path)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("s.toml:18: environment.history: cannot read temperature history"),
            "{e}"
        );
    }

    #[test]
    fn failure_criteria() {
        let s = load(&with(
            "[failure]\nmax_leak_rate = \"1e-9 m^3/s\"\nmax_leaked_volume = \"1 L\"\nmin_retained_force = 0.5\nlift_off = true\nmin_sealing_force = \"1.5 N/mm\"\nmin_contact_pressure = \"0.5 MPa\"\ngasket_factor = 2\n",
        ))
        .unwrap();
        assert_eq!(
            s.life.failure,
            FailureCriteria {
                max_leak_rate: Some(1e-9),
                max_leaked_volume: Some(1e-3),
                min_retained_force: Some(0.5),
                retained_force_reference: DEFAULT_RETAINED_FORCE_REFERENCE,
                max_compression_set: None,
                min_sealing_force: Some(1500.0),
                min_contact_pressure: Some(5e5),
                gasket_factor: Some(2.0),
                lift_off: true,
                extrusion: true,
                shutdown: Some(crate::simulate::Shutdown {
                    temperature: 296.15,
                    pressure_difference: 0.0,
                    cooling_time: s.life.failure.shutdown.map_or(0.0, |x| x.cooling_time),
                }),
                low_temperature: Some(crate::simulate::ColdLimit {
                    limit: s.life.material.low_temperature_limit().unwrap(),
                    margin: 5.0,
                }),
                stop_at_failure: false,
            }
        );
        // the shutdown's cool-down is d²/a of the 3.53 mm cord (docs/model.md §5.2, §8.2)
        let cooling = s.life.failure.shutdown.map_or(0.0, |x| x.cooling_time);
        assert!(
            (cooling / (3.53e-3 * 3.53e-3 / 1e-7) - 1.0).abs() < 1e-12,
            "{cooling}"
        );
        // the cold limit: waived, or with its own margin in any temperature-difference unit
        let waived = load(&with("[failure]\nlow_temperature = false\n")).unwrap();
        assert_eq!(waived.life.failure.low_temperature, None);
        let margin = load(&with("[failure]\nlow_temperature_margin = \"18 F\"\n"))
            .unwrap()
            .life
            .failure
            .low_temperature
            .unwrap()
            .margin;
        assert!((margin - 10.0).abs() < 1e-12, "{margin}");
        let e = error(&with(
            "[failure]\nlow_temperature = false\nlow_temperature_margin = \"5 K\"\n",
        ));
        assert!(
            e.contains(":19: failure.low_temperature_margin: a margin for a cold limit"),
            "{e}"
        );
        let e = error(&with("[failure]\nlow_temperature_margin = \"-5 K\"\n"));
        assert!(e.contains(":18: failure.low_temperature_margin"), "{e}");
        // the extrusion, lift-off and shutdown checks are on unless waived
        let off = load(&with(
            "[failure]\nextrusion = false\nlift_off = false\nlost_interference = false\n",
        ))
        .unwrap();
        assert!(!off.life.failure.extrusion && off.life.failure.shutdown.is_none());
        assert!(off.life.failure.is_empty());
        let empty = load(&with("[failure]\n")).unwrap().life.failure;
        assert!(empty.lift_off && empty.extrusion && empty.shutdown.is_some());
        let e = error(&with("[failure]\nmin_retained_force = 1.5\n"));
        assert!(
            e.contains(":18: failure.min_retained_force: must lie strictly between 0 and 1"),
            "{e}"
        );
        let e = error(&with("[failure]\nmax_leak_rate = \"1 m^3\"\n"));
        assert!(
            e.contains(":18: failure.max_leak_rate: expected a volume flow"),
            "{e}"
        );
        let e = error(&with("[failure]\nlift_off = \"yes\"\n"));
        assert!(e.contains(":18: failure.lift_off: invalid type"), "{e}");
    }

    #[test]
    fn ageing_defaults_to_the_materials_constants() {
        let fkm = ORING.replace("nbr-70", "fkm-75");
        let own = library::get("fkm-75")
            .unwrap()
            .load()
            .unwrap()
            .ageing
            .unwrap();
        let s = load(&format!("{fkm}[ageing]\n")).unwrap();
        assert_eq!(s.life.ageing, Some(own));
        let s = load(&format!("{fkm}[ageing]\nrate = \"1e-8 1/s\"\n")).unwrap();
        assert_eq!(s.life.ageing.unwrap().rate, 1e-8);
        assert_eq!(
            s.life.ageing.unwrap().activation_energy,
            own.activation_energy
        );
        // on without a table (the compound's constants), off with enabled = false
        assert_eq!(load(&fkm).unwrap().life.ageing, Some(own));
        let off = load(&format!("{fkm}[ageing]\nenabled = false\n")).unwrap();
        assert!(off.life.ageing.is_none());
        assert_eq!(off.life.ageing_source, AgeingSource::Off);
        let e = error(&format!(
            "{fkm}[ageing]\nenabled = false\nrate = \"1e-8 1/s\"\n"
        ));
        assert!(e.contains("ageing.rate: [ageing] is switched off"), "{e}");
        // a compound without ageing constants (every library compound has them: an inline one;
        // its material takes two lines more than `library = …`)
        let vmq = |extra: &str| {
            with(extra).replace(
                "library = \"nbr-70\"",
                "long_term_modulus = \"2 MPa\"\npoisson_ratio = 0.5\nprony = [ { modulus = \"2 MPa\", tau = \"1 h\" } ]",
            )
        };
        let e = error(&vmq("[ageing]\n"));
        assert!(
            e.contains(":19: ageing.activation_energy: missing key `activation_energy` in [ageing], and the material"),
            "{e}"
        );
        let e = error(&vmq(
            "[ageing]\nactivation_energy = \"80 kJ/mol\"\nrate = \"1e-9 1/s\"\n",
        ));
        assert!(
            e.contains("ageing.reference_temperature: missing key"),
            "{e}"
        );
        let s = load(&vmq(
            "[ageing]\nactivation_energy = \"80 kJ/mol\"\nrate = \"1e-9 1/s\"\nreference_temperature = \"100 C\"\n",
        ))
        .unwrap();
        assert_eq!(
            s.life.ageing,
            Some(Ageing {
                activation_energy: 8e4,
                activation_energy_above: 8e4,
                rate: 1e-9,
                reference_temperature: 373.15,
                crosslinking: 1.0,
            })
        );
    }

    #[test]
    fn simulation_grid_and_fidelity() {
        let s = load(&with(
            "[simulation]\nduration = \"1 year\"\nstart = \"1 ms\"\npoints_per_decade = 5\nfidelity = \"exact\"\n",
        ))
        .unwrap();
        assert_eq!(
            s.life.time,
            TimeGrid {
                start: 1e-3,
                duration: YEAR,
                points_per_decade: 5.0,
                tolerance: TimeGrid::DEFAULT_TOLERANCE,
            }
        );
        assert_eq!(s.life.fidelity, Fidelity::Exact);
        for level in Fidelity::ALL {
            let text = with(&format!("[simulation]\nfidelity = \"{}\"\n", level.name()));
            assert_eq!(load(&text).unwrap().life.fidelity, level);
        }
        for name in ["critical-junction", "table"] {
            let s = load(&with(&format!("[simulation]\nfidelity = \"{name}\"\n"))).unwrap();
            assert_eq!(s.life.fidelity, Fidelity::Table);
        }
        let cases = [
            (
                "duration = \"1 s\"",
                ":18: simulation.duration: duration (1 s) must exceed start (1 s)",
            ),
            (
                "start = \"40 year\"",
                ":18: simulation.start: duration (9.46728e8 s) must exceed start",
            ),
            (
                "duration = \"1 m\"",
                ":18: simulation.duration: expected a time",
            ),
            (
                "points_per_decade = 0",
                ":18: simulation.points_per_decade: must be positive",
            ),
            (
                "points_per_decade = 5000",
                ":18: simulation.points_per_decade: must lie in [0.1, 1000], got 5000",
            ),
            (
                "fidelity = \"fast\"",
                ":18: simulation.fidelity: must be one of \"rule-of-thumb\", \"critical-junction\"",
            ),
        ];
        for (line, expected) in cases {
            let e = error(&with(&format!("[simulation]\n{line}\n")));
            assert!(e.contains(expected), "{line}: {e}");
        }
    }

    #[test]
    fn a_replacement_material_is_validated_in_place() {
        let fkm = library::get("fkm-75").unwrap().load().unwrap();
        let text = with("[ageing]\n").replace(
            "library = \"nbr-70\"",
            "long_term_modulus = \"2 MPa\"\npoisson_ratio = 0.5\nprony = [ { modulus = \"2 MPa\", tau = \"1 h\" } ]",
        );
        // a compound without ageing constants fails ([ageing] without constants); with FKM in
        // its place it loads
        assert!(load(&text).is_err());
        let s = Scenario::from_str_with_material(&text, Path::new("s.toml"), &fkm).unwrap();
        assert_eq!(s.material, fkm);
        assert_eq!(s.life.ageing, fkm.ageing);
        // the static problem at FKM's installed asperity modulus (`follow`)
        assert_eq!(
            s.problem.material.youngs_modulus,
            s.life.installed_asperity_modulus()
        );
        assert!(s.problem.material.youngs_modulus > fkm.prony.long_term());
    }
}
