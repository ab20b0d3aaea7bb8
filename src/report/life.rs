//! Reports of seal-life runs (`sealsim run`, `sealsim compare`): the history CSV, the summary
//! JSON, the readable terminal summary, and the comparison table.
//!
//! As everywhere in [`crate::report`], numbers go out in SI units (the column and field names
//! carry them) in shortest round-trip scientific notation, every one checked to be finite
//! first: a non-finite value is a bug, reported as [`ReportError::NonFinite`], and nothing is
//! written.

use super::ReportError;
use super::csv::{Cell, Table, csv_error, finish, number};
use super::plot::{LogLogChart, Series};
use super::units::{Quantity, UnitSystem};
use crate::dynamic::{Motion, MotionPoint, MotionSpec, StrokeCycle};
use crate::fluid::Fluid;
use crate::material::shift::{DAY, YEAR};
use crate::material::{Material, Status};
use crate::report::findings::{FindingRecord, records};
use crate::simulate::{AsperityModulus, LevelBand, LifeProblem, LifeResult, Loading, Outcome};
use crate::units::human;
use crate::validity::Limit;
use serde::Serialize;

/// Columns of the history CSV, in order (units in the names).
///
/// * `shift_factor` a_T is blank where the rubber is frozen (WLF at or below T_ref − C2,
///   a_T = ∞) or a_T overflows a double;
/// * `u_c_m`, the critical constriction at the peak pressure, is blank where that strip is
///   sealed (no percolating channel);
/// * `state` is `sealed` (no percolating channel, or a critical gap narrower than a molecule of
///   the fluid: the computed `u_c_m` stays), `leaking`, `pressure_held` (held by the fluid
///   pressure alone) or `lift_off` (the fluid pressure exceeds the contact pressure: the seal is
///   open, and the leak rate shown is the seal's at the threshold of lift-off, a lower bound);
///   docs/model.md §8.1;
/// * `open_fraction` is the open share f of the critical channels' flow under particle
///   clogging (docs/model.md §7), always written (1 without `[contamination]`) so that the schema is
///   one;
/// * `compression_set` is the chemical compression set (a fraction) of the two-network ageing
///   model, after a full recovery (docs/model.md §6.5), blank without `[ageing]`;
/// * `shutdown_squeeze` is the squeeze the set ring keeps at the shutdown condition (its
///   recovered cord at the shutdown temperature, docs/model.md §8.2), blank where the check
///   does not apply.
pub const HISTORY_COLUMNS: [&str; 15] = [
    "time_s",
    "temperature_K",
    "reduced_time_s",
    "shift_factor",
    "sealing_force_N_per_m",
    "peak_pressure_Pa",
    "mean_pressure_Pa",
    "contact_width_m",
    "u_c_m",
    "leak_rate_m3_per_s",
    "leaked_volume_m3",
    "state",
    "open_fraction",
    "compression_set",
    "shutdown_squeeze",
];

/// Columns the history gets after [`HISTORY_COLUMNS`] with `[motion]` (PY08 §8): the first
/// always, the second for a stroke cycle.
///
/// * `drag_leak_rate_m3_per_s`: the drag term `L_y d v` at the peak strip — constant
///   sliding: at the sliding speed, *included* in `leak_rate_m3_per_s`; stroke cycle: at the
///   out-stroke speed (the instantaneous drag while the rod moves out), *not* included (the
///   drag volumes cancel over a cycle in the linear theory, the leak rate is the static one);
/// * `net_volume_per_cycle_m3`: out-stroke volume + in-stroke volume of one cycle
///   (= the static leak rate × the cycle time in the linear theory; with inverse-hydrodynamic
///   films, docs/model.md §3.4.1, their blend, and then `leak_rate_m3_per_s` is this over the
///   cycle time);
/// * `out_stroke_film_m`, `in_stroke_film_m`: the inverse-hydrodynamic films h* (blank
///   without inlet gradients); `speed_regime`: `low_speed`, `transition`,
///   `inverse_hydrodynamic` or `low_speed_no_profile`.
pub const MOTION_HISTORY_COLUMNS: [&str; 5] = [
    "drag_leak_rate_m3_per_s",
    "net_volume_per_cycle_m3",
    "out_stroke_film_m",
    "in_stroke_film_m",
    "speed_regime",
];

/// Column the history gets after [`HISTORY_COLUMNS`] for a gas (docs/model.md §3.9): the
/// throughput (pV flow) at the gas temperature \[Pa·m³/s\], `p̄ × leak_rate_m3_per_s`, where
/// a gas's `leak_rate_m3_per_s` is its volume flow at the mean pressure p̄ = (P_a + P_b)/2.
pub const GAS_HISTORY_COLUMN: &str = "throughput_Pa_m3_per_s";

/// Column after [`GAS_HISTORY_COLUMN`] for a gas (docs/model.md §13.7): the permeation
/// throughput through the rubber at the row's time and temperature \[Pa·m³/s\] (blank when the
/// run carries no permeation; the notes say why). Not included in `throughput_Pa_m3_per_s`.
pub const PERMEATION_HISTORY_COLUMN: &str = "permeation_Pa_m3_per_s";

/// Column after [`PERMEATION_HISTORY_COLUMN`] for a gas: how the permeation figure was obtained
/// (`published`, `illustrative`, `bound` — NOT SOURCED, a stated conservative bound — or
/// `user`; docs/model.md §13.4), so that a bound is never read as a figure.
pub const PERMEATION_BASIS_HISTORY_COLUMN: &str = "permeation_basis";

/// The history of a life run as CSV: the header and one row per output time (t = 0, the
/// installation, first). With `[motion]` the rows carry [`MOTION_HISTORY_COLUMNS`] too.
pub fn history_table(result: &LifeResult) -> Result<String, ReportError> {
    history_cells(result, None)?.to_csv()
}

/// [`history_table`] of a run whose fluid is `fluid`: a gas adds [`GAS_HISTORY_COLUMN`] and
/// [`PERMEATION_HISTORY_COLUMN`].
pub fn history_table_for(result: &LifeResult, fluid: &Fluid) -> Result<String, ReportError> {
    history_for(result, fluid)?.to_csv()
}

/// The cells of [`history_table_for`] (what the Python package reads).
pub fn history_for(result: &LifeResult, fluid: &Fluid) -> Result<Table, ReportError> {
    history_cells(result, fluid.mean_pressure())
}

/// The history's cells, with the throughput column when `mean_pressure` p̄ \[Pa\] is given.
fn history_cells(result: &LifeResult, mean_pressure: Option<f64>) -> Result<Table, ReportError> {
    let motion = result.rows.iter().any(|r| r.motion.is_some());
    let stroke = result
        .rows
        .iter()
        .any(|r| r.motion.is_some_and(|m| m.cycle.is_some()));
    let extra = match (motion, stroke) {
        (false, _) => 0,
        (true, false) => 1,
        (true, true) => MOTION_HISTORY_COLUMNS.len(),
    };
    let header: Vec<&'static str> = HISTORY_COLUMNS
        .iter()
        .chain(mean_pressure.map(|_| &GAS_HISTORY_COLUMN))
        .chain(mean_pressure.map(|_| &PERMEATION_HISTORY_COLUMN))
        .chain(mean_pressure.map(|_| &PERMEATION_BASIS_HISTORY_COLUMN))
        .chain(&MOTION_HISTORY_COLUMNS[..extra])
        .copied()
        .collect();
    let mut rows = Vec::with_capacity(result.rows.len());
    for (i, r) in result.rows.iter().enumerate() {
        let row = i + 1;
        let cell = |column: usize, value: f64| Cell::number(row, HISTORY_COLUMNS[column], value);
        let optional =
            |column: usize, value: Option<f64>| Cell::optional(row, HISTORY_COLUMNS[column], value);
        let shift = (r.shift_factor.is_finite()).then_some(r.shift_factor);
        let mut cells = Vec::with_capacity(header.len());
        cells.extend([
            cell(0, r.time)?,
            cell(1, r.temperature)?,
            cell(2, r.reduced_time)?,
            optional(3, shift)?,
            cell(4, r.sealing_force)?,
            cell(5, r.peak_pressure)?,
            cell(6, r.mean_pressure)?,
            cell(7, r.contact_width)?,
            optional(8, r.u_c)?,
            cell(9, r.leak_rate)?,
            cell(10, r.leaked_volume)?,
            Cell::Text(r.state.as_str().to_owned()),
            cell(12, r.open_fraction)?,
            optional(13, r.compression_set)?,
            optional(14, r.shutdown.map(|s| s.remaining_squeeze))?,
        ]);
        if let Some(p) = mean_pressure {
            cells.push(Cell::number(row, GAS_HISTORY_COLUMN, p * r.leak_rate)?);
            cells.push(Cell::optional(
                row,
                PERMEATION_HISTORY_COLUMN,
                r.permeation,
            )?);
            cells.push(match (r.permeation, result.permeation_status) {
                (Some(_), Some(status)) => Cell::Text(status.as_str().to_owned()),
                _ => Cell::Blank,
            });
        }
        match r.motion {
            _ if extra == 0 => {}
            None => cells.extend(std::iter::repeat_n(Cell::Blank, extra)),
            Some(m) => {
                cells.push(Cell::number(
                    row,
                    MOTION_HISTORY_COLUMNS[0],
                    m.drag_leak_rate,
                )?);
                if extra == MOTION_HISTORY_COLUMNS.len() {
                    cells.push(Cell::optional(
                        row,
                        MOTION_HISTORY_COLUMNS[1],
                        m.cycle.map(|c| c.net_volume),
                    )?);
                    cells.push(Cell::optional(
                        row,
                        MOTION_HISTORY_COLUMNS[2],
                        m.ihl.map(|ihl| ihl.out_film),
                    )?);
                    cells.push(Cell::optional(
                        row,
                        MOTION_HISTORY_COLUMNS[3],
                        m.ihl.map(|ihl| ihl.in_film),
                    )?);
                    cells.push(Cell::Text(m.regime.id().to_owned()));
                }
            }
        }
        rows.push(cells);
    }
    Ok(Table { header, rows })
}

/// The machine-readable summary of a run (`--summary`), serialised as JSON.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// The scenario's name.
    pub scenario: String,
    /// The scenario file, as given.
    pub scenario_file: String,
    /// The material's name.
    pub material: String,
    /// `published`, `illustrative` or `user`.
    pub material_status: String,
    /// Where the chemical ageing comes from: `compound`, `scenario`, `off`, `no_data` or
    /// `missing_in_comparison` (docs/model.md §6.5).
    pub ageing: &'static str,
    /// The compound's low-temperature limit T10 \[K\] (docs/model.md §5.1; absent without a
    /// shift, or when the modulus never rises tenfold).
    #[serde(
        rename = "low_temperature_limit_K",
        skip_serializing_if = "Option::is_none"
    )]
    pub low_temperature_limit_k: Option<f64>,
    /// `flat` or `o-ring`.
    pub seal: String,
    /// `displacement` or `force`.
    pub loading: String,
    /// `critical-junction` (contact table) or `exact`.
    pub fidelity: String,
    /// The contact-area relation when it is not the default: `corrected` (docs/model.md §2;
    /// absent for Persson's).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_area: Option<&'static str>,
    /// `fails`, `open` (no criterion crossed, but the seal was open or held by the fluid
    /// pressure alone: a waived lift-off) or `survives` (docs/model.md §8.1).
    pub verdict: &'static str,
    /// The verdict as the terminal summary prints it.
    pub verdict_text: String,
    /// The same life at the neighbouring fidelity level (docs/model.md §4.1; absent where it was
    /// not run).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub level_band: Option<BandSummary>,
    /// The state at the end of the run: `sealed`, `leaking`, `pressure_held` or `lift_off`.
    pub final_state: &'static str,
    /// The states in the order the run passed through them, each with the first output time
    /// at which it held.
    pub states: Vec<StateRecord>,
    /// Time to failure \[s\]; `null` when the seal survives the whole run.
    pub time_to_failure_s: Option<f64>,
    /// The failure mode ([`crate::simulate::FailureMode::as_str`]) or `none`.
    pub failure_mode: String,
    /// Leak rate right after installation (t = 0) \[m³/s\].
    pub initial_leak_rate_m3_per_s: f64,
    /// Leak rate at the end of the run \[m³/s\].
    pub final_leak_rate_m3_per_s: f64,
    /// Volume leaked over the whole run \[m³\].
    pub leaked_volume_m3: f64,
    /// Whether `leaked_volume_m3` is a lower bound: it includes a lifted-off span, whose flow
    /// the model bounds from below only.
    pub leaked_volume_is_lower_bound: bool,
    /// The lowest sealing force per length over the run \[N/m\] and its time \[s\].
    #[serde(rename = "minimum_sealing_force_N_per_m")]
    pub minimum_sealing_force_n_per_m: f64,
    pub minimum_sealing_force_time_s: f64,
    /// The lowest peak contact pressure (with k_e ΔP) \[Pa\] and its time \[s\].
    #[serde(rename = "minimum_peak_pressure_Pa")]
    pub minimum_peak_pressure_pa: f64,
    pub minimum_peak_pressure_time_s: f64,
    /// The highest leak rate \[m³/s\] and its time \[s\].
    pub maximum_leak_rate_m3_per_s: f64,
    pub maximum_leak_rate_time_s: f64,
    /// Sealing force per unit length right after installation \[N/m\].
    #[serde(rename = "initial_sealing_force_N_per_m")]
    pub initial_sealing_force_n_per_m: f64,
    /// Sealing force per unit length at the end of the run \[N/m\].
    #[serde(rename = "final_sealing_force_N_per_m")]
    pub final_sealing_force_n_per_m: f64,
    /// The time after installation the retained force is referred to \[s\].
    pub retained_force_reference_s: f64,
    /// Sealing force per unit length at that reference \[N/m\].
    #[serde(rename = "reference_sealing_force_N_per_m")]
    pub reference_sealing_force_n_per_m: f64,
    /// The final sealing force over the reference one.
    pub final_retained_force: f64,
    /// Chemical compression set at the end of the run (with `[ageing]`): the two networks'
    /// set after a full recovery (docs/model.md §6.5).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub final_compression_set: Option<f64>,
    /// The shutdown check (docs/model.md §8.2), where it applies.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shutdown: Option<ShutdownSummary>,
    /// The coldest temperature over the run \[K\] and its first time \[s\].
    #[serde(rename = "coldest_temperature_K")]
    pub coldest_temperature_k: f64,
    pub coldest_temperature_time_s: f64,
    /// The cold limit (docs/model.md §8.3), where it applies (a compound with a T10, not
    /// waived).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub low_temperature: Option<ColdLimitSummary>,
    /// Length of the run \[s\].
    pub duration_s: f64,
    /// Open fraction of the critical channels at the end of the run (1 without
    /// `[contamination]`).
    pub final_open_fraction: f64,
    /// The validity limits the run crossed, each with its worst value and when (docs/model.md
    /// §9), as records; their `message` is what `--verbose` shows on stderr, their `code` what
    /// `sealsim explain` expands.
    pub warnings: Vec<FindingRecord>,
    /// The scenario's input warnings and notes (`FILE:LINE: key: …`) with their codes (absent
    /// when there are none; filled in by the caller, which has the scenario).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub input_warnings: Vec<crate::report::findings::InputRecord>,
    /// `[motion]` (absent from the JSON for a static seal).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub motion: Option<MotionSummary>,
    /// A groove-seated O-ring's gland (absent otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gland: Option<GlandSummary>,
    /// A gas's pressures and throughputs (absent for a liquid; docs/model.md §3.9).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gas: Option<GasSummary>,
}

/// The summary's `level_band`: the outcome and figures at the neighbouring fidelity level.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BandSummary {
    /// The neighbouring level.
    pub level: &'static str,
    /// `fails`, `open` or `survives` there.
    pub verdict: &'static str,
    /// Whether that differs from this level's outcome (the verdict is then `undecided`).
    pub undecided: bool,
    pub time_to_failure_s: Option<f64>,
    pub failure_mode: String,
    pub leaked_volume_m3: f64,
    pub leaked_volume_is_lower_bound: bool,
    pub maximum_leak_rate_m3_per_s: f64,
}

impl BandSummary {
    fn new(result: &LifeResult) -> Option<Self> {
        let band = result.band.as_ref()?;
        Some(BandSummary {
            level: band.level.name(),
            verdict: VerdictKind::of(band.outcome()).as_str(),
            undecided: result.undecided(),
            time_to_failure_s: band.failure.map(|f| f.time),
            failure_mode: band.failure.map_or("none", |f| f.mode.as_str()).to_owned(),
            leaked_volume_m3: band.leaked_volume,
            leaked_volume_is_lower_bound: band.leaked_volume_is_lower_bound,
            maximum_leak_rate_m3_per_s: band.maximum_leak_rate,
        })
    }
}

/// One entry of the summary's `states`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StateRecord {
    /// `sealed`, `leaking`, `pressure_held` or `lift_off`.
    pub state: &'static str,
    /// For `sealed`: `no_percolating_channel` or `critical_gap_below_a_molecule`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<&'static str>,
    /// The first output time at which it held \[s\].
    pub from_s: f64,
}

/// The `shutdown` object of the summary (docs/model.md §8.2).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ShutdownSummary {
    /// T_sd \[K\].
    #[serde(rename = "temperature_K")]
    pub temperature_k: f64,
    /// ΔP_min \[Pa\].
    #[serde(rename = "minimum_pressure_difference_Pa")]
    pub minimum_pressure_difference_pa: f64,
    /// The set ring's squeeze at T_sd at the end of the run.
    pub final_remaining_squeeze: f64,
    /// When the interference was lost \[s\] (the located failure time when it is the failure;
    /// else the first output time), `null` when it held throughout.
    pub lost_s: Option<f64>,
}

/// The `low_temperature` object of the summary (docs/model.md §8.3).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ColdLimitSummary {
    /// The compound's T10 \[K\].
    #[serde(rename = "limit_K")]
    pub limit_k: f64,
    /// The margin below T10 the seal is taken to hold to \[K\].
    #[serde(rename = "margin_K")]
    pub margin_k: f64,
    /// T10 − margin \[K\]: colder fails.
    #[serde(rename = "threshold_K")]
    pub threshold_k: f64,
    /// When the rubber first went colder than the threshold \[s\] (the located failure time
    /// when it is the failure; else the first output time), `null` when it never did.
    pub crossed_s: Option<f64>,
}

/// The `gas` object of the summary: the throughput (pV flow at the gas temperature) that goes
/// with the leak rates above, which for a gas are volume flows at the mean pressure.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GasSummary {
    /// Library id or `custom`.
    pub gas: String,
    /// P_a, absolute \[Pa\].
    #[serde(rename = "inlet_pressure_Pa")]
    pub inlet_pressure_pa: f64,
    /// P_b, absolute \[Pa\].
    #[serde(rename = "outlet_pressure_Pa")]
    pub outlet_pressure_pa: f64,
    /// p̄ = (P_a + P_b)/2 \[Pa\], at which the leak rates are volume flows.
    #[serde(rename = "mean_pressure_Pa")]
    pub mean_pressure_pa: f64,
    /// Throughput at installation \[Pa·m³/s\].
    #[serde(rename = "initial_throughput_Pa_m3_per_s")]
    pub initial_throughput: f64,
    /// Throughput at the end \[Pa·m³/s\].
    #[serde(rename = "final_throughput_Pa_m3_per_s")]
    pub final_throughput: f64,
    /// The same in mbar·L/s (1 mbar·L/s = 0.1 Pa·m³/s), the helium-leak-test form.
    #[serde(rename = "initial_throughput_mbar_L_per_s")]
    pub initial_throughput_mbar_l: f64,
    #[serde(rename = "final_throughput_mbar_L_per_s")]
    pub final_throughput_mbar_l: f64,
    /// Permeation throughput through the rubber at the end \[Pa·m³/s\] (docs/model.md §13.7;
    /// absent when the run carries none).
    #[serde(
        rename = "permeation_Pa_m3_per_s",
        skip_serializing_if = "Option::is_none"
    )]
    pub final_permeation: Option<f64>,
    /// Interface + permeation throughput at the end \[Pa·m³/s\]: what a leak detector sees,
    /// and what `max_leak_rate` is compared with.
    #[serde(rename = "total_throughput_Pa_m3_per_s")]
    pub final_total: f64,
    /// The permeation time lag w²/(6D) at the final temperature \[s\], when D is known.
    #[serde(
        rename = "permeation_time_lag_s",
        skip_serializing_if = "Option::is_none"
    )]
    pub permeation_time_lag: Option<f64>,
    /// How the permeation figure was obtained: `published`, `illustrative`, `bound` (NOT
    /// SOURCED: a stated conservative bound) or `user` (docs/model.md §13.4).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub permeation_basis: Option<&'static str>,
    /// Where the figure comes from (or how the bound was chosen), and whether D is a bound.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub permeation_source: Option<String>,
    /// `"rarefied"` or `"continuum"`: the flow law through the constrictions (docs/model.md
    /// §3.10).
    pub flow_law: &'static str,
    /// A rarefied gas: the throughput at installation the continuum law would give
    /// \[Pa·m³/s\].
    #[serde(
        rename = "continuum_initial_throughput_Pa_m3_per_s",
        skip_serializing_if = "Option::is_none"
    )]
    pub continuum_initial_throughput: Option<f64>,
}

impl GasSummary {
    fn new(problem: &LifeProblem, result: &LifeResult) -> Option<Self> {
        let fluid = &problem.fluid;
        let gas = fluid.gas?;
        let p = fluid.mean_pressure()?;
        let (first, last) = (p * result.initial_leak_rate(), p * result.final_leak_rate());
        let final_permeation = result.rows.last().and_then(|r| r.permeation);
        let permeation_time_lag = match (&problem.permeation, result.rows.last()) {
            // a diffusivity that underflows (a very cold rubber) has no finite lag: absent
            (Some(s), Some(r)) => s.time_lag(r.temperature).filter(|x| x.is_finite()),
            _ => None,
        };
        Some(GasSummary {
            gas: gas.gas.id.to_owned(),
            inlet_pressure_pa: gas.outlet_pressure + fluid.pressure_difference,
            outlet_pressure_pa: gas.outlet_pressure,
            mean_pressure_pa: p,
            initial_throughput: first,
            final_throughput: last,
            initial_throughput_mbar_l: first * 10.0,
            final_throughput_mbar_l: last * 10.0,
            final_permeation,
            final_total: last + final_permeation.unwrap_or(0.0),
            permeation_time_lag,
            permeation_basis: problem.permeation.as_ref().map(|s| s.data.status.as_str()),
            permeation_source: problem.permeation.as_ref().map(|s| s.data.basis()),
            flow_law: match gas.flow_law {
                crate::gas::FlowLaw::Rarefied => "rarefied",
                crate::gas::FlowLaw::Continuum => "continuum",
            },
            continuum_initial_throughput: result.continuum_leak_rate.map(|c| p * c),
        })
    }

    fn values(&self) -> Vec<(&'static str, f64)> {
        vec![
            ("initial_throughput_Pa_m3_per_s", self.initial_throughput),
            ("final_throughput_Pa_m3_per_s", self.final_throughput),
            (
                "permeation_Pa_m3_per_s",
                self.final_permeation.unwrap_or(0.0),
            ),
            ("total_throughput_Pa_m3_per_s", self.final_total),
            (
                "permeation_time_lag_s",
                self.permeation_time_lag.unwrap_or(0.0),
            ),
            (
                "continuum_initial_throughput_Pa_m3_per_s",
                self.continuum_initial_throughput.unwrap_or(0.0),
            ),
        ]
    }
}

/// A throughput \[Pa·m³/s\] in SI and in the helium-leak-test form:
/// `"1.2e-9 Pa·m³/s (1.2e-8 mbar·L/s)"`.
fn throughput(q: f64) -> String {
    if q == 0.0 {
        return "0 Pa·m³/s".to_owned();
    }
    format!("{} Pa·m³/s ({} mbar·L/s)", human(q, 3), human(q * 10.0, 3))
}

/// A gas's throughput `p̄ q`, or "≈ 0" below the floor.
fn floored_throughput(floor: &LeakFloor, p: f64, q: f64) -> String {
    if floor.seals(q) {
        format!(
            "≈ 0 (below {}, {})",
            throughput(p * floor.rate),
            floor.meaning()
        )
    } else {
        throughput(p * q)
    }
}

/// The `gland` object of the summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GlandSummary {
    /// `face`, `piston` or `rod`.
    pub kind: String,
    /// The squeeze the run uses (nominal).
    pub squeeze: f64,
    /// Lowest squeeze over the ring's and the groove's tolerances.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub squeeze_min: Option<f64>,
    /// Highest squeeze over the tolerances.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub squeeze_max: Option<f64>,
    /// k_e.
    pub energisation_factor: f64,
    /// The extrusion gap \[m\].
    pub extrusion_gap_m: f64,
}

/// The `motion` object of the summary: the drag of the sliding countersurface at the peak
/// strip (PY08 §8).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MotionSummary {
    /// `steady` (constant sliding: the drag is included in the leak rate) or `stroke` (a stroke
    /// cycle: the leak rate is the static one, the drag volumes are in the cycles below).
    pub kind: String,
    /// Constant sliding: the speed \[m/s\].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sliding_speed_m_per_s: Option<f64>,
    /// Stroke cycle: the stroke length \[m\].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stroke_m: Option<f64>,
    /// Stroke cycle: the out-stroke speed \[m/s\].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub out_speed_m_per_s: Option<f64>,
    /// Stroke cycle: the in-stroke speed \[m/s\].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub in_speed_m_per_s: Option<f64>,
    /// Stroke cycle: `S/v_out + S/v_in` \[s\].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycle_period_s: Option<f64>,
    /// `L_a/L_x` of the critical junction.
    pub junction_position: f64,
    /// The drag term `L_y d v` at installation \[m³/s\] (sliding speed, or out-stroke speed).
    pub initial_drag_leak_rate_m3_per_s: f64,
    /// The drag term at the end of the run \[m³/s\].
    pub final_drag_leak_rate_m3_per_s: f64,
    /// The film `d = β u_c` at the peak strip at installation \[m\].
    pub initial_film_thickness_m: f64,
    /// The film at the end of the run \[m\].
    pub final_film_thickness_m: f64,
    /// The smallest speed bound of PY08 eq. 17 over the history rows \[m/s\]; `null` when the
    /// peak strip is sealed throughout (no bound).
    pub speed_bound_m_per_s: Option<f64>,
    /// Whether the fastest speed exceeded the bound at some time of the run (a warning).
    pub speed_above_bound: bool,
    /// Stroke cycle: the volumes of one cycle at installation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub initial_cycle: Option<CycleSummary>,
    /// Stroke cycle: the volumes of one cycle at the end of the run.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub final_cycle: Option<CycleSummary>,
}

/// One stroke cycle's volumes \[m³\], counted positive from the pressurised side to the outside
/// (blended between the low-speed and the inverse-hydrodynamic values, docs/model.md §3.4.1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CycleSummary {
    /// `low_speed`, `transition`, `inverse_hydrodynamic` or `low_speed_no_profile`.
    pub speed_regime: &'static str,
    /// `net_volume_per_cycle_m3` over the cycle time \[m³/s\].
    pub cycle_mean_leak_rate_m3_per_s: f64,
    /// The inverse-hydrodynamic cycle (absent without inlet gradients).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ihl: Option<IhlSummary>,
    /// Passed out during the out-stroke: static leak over its duration + the dragged film
    /// `L_y d S`.
    pub out_stroke_volume_m3: f64,
    /// Passed out during the in-stroke: static leak over its duration − the film carried
    /// back (negative when the drag dominates).
    pub in_stroke_volume_m3: f64,
    /// `out + in`: the net leak of one cycle (the static leak over the cycle time in the
    /// linear theory).
    pub net_volume_per_cycle_m3: f64,
    /// The film volume `L_y d S` carried out on the out-stroke and back on the in-stroke.
    pub drag_volume_per_stroke_m3: f64,
}

/// The inverse-hydrodynamic part of a cycle (docs/model.md §3.4.1), SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct IhlSummary {
    /// `given`, `profile` or `oring_estimate`.
    pub gradient_source: &'static str,
    /// Steepest inlet gradient of the out-stroke (pressurised side) \[Pa/m\].
    pub inlet_gradient_out_pa_per_m: f64,
    /// Steepest inlet gradient of the in-stroke (air side) \[Pa/m\].
    pub inlet_gradient_in_pa_per_m: f64,
    /// `h_out = √(8ηv_out/(9 w_out))` \[m\].
    pub out_stroke_film_m: f64,
    /// `h_in = √(8ηv_in/(9 w_in))` \[m\].
    pub in_stroke_film_m: f64,
    /// `L_y S h_out/2` \[m³\].
    pub out_stroke_carried_m3: f64,
    /// `min(L_y S h_in/2, out)` \[m³\].
    pub in_stroke_returned_m3: f64,
    /// The starvation cap acted (the seal pumps back all it let out).
    pub starved: bool,
    /// The IHL weights of the out- and in-stroke (0: low-speed theory, 1: IHL).
    pub weight_out: f64,
    pub weight_in: f64,
    /// min(h_out, h_in)/σ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub film_parameter: Option<f64>,
    /// `boundary`, `mixed` or `full_film`.
    pub film_regime: &'static str,
}

impl CycleSummary {
    fn new(m: &MotionPoint) -> Option<Self> {
        let c: &StrokeCycle = m.cycle.as_ref()?;
        Some(CycleSummary {
            speed_regime: m.regime.id(),
            cycle_mean_leak_rate_m3_per_s: if c.period > 0.0 {
                c.net_volume / c.period
            } else {
                0.0
            },
            ihl: m.ihl.map(|i| IhlSummary {
                gradient_source: i.source.id(),
                inlet_gradient_out_pa_per_m: i.gradients.out_stroke,
                inlet_gradient_in_pa_per_m: i.gradients.in_stroke,
                out_stroke_film_m: i.out_film,
                in_stroke_film_m: i.in_film,
                out_stroke_carried_m3: i.out_volume,
                in_stroke_returned_m3: i.back_volume,
                starved: i.starved,
                weight_out: m.ihl_weights.0,
                weight_in: m.ihl_weights.1,
                film_parameter: i.film_parameter.is_finite().then_some(i.film_parameter),
                film_regime: i.film_regime().id(),
            }),
            out_stroke_volume_m3: c.out_volume,
            in_stroke_volume_m3: c.in_volume,
            net_volume_per_cycle_m3: c.net_volume,
            drag_volume_per_stroke_m3: c.drag_volume,
        })
    }

    fn values(&self) -> Vec<(&'static str, f64)> {
        let mut v = vec![
            ("out_stroke_volume_m3", self.out_stroke_volume_m3),
            ("in_stroke_volume_m3", self.in_stroke_volume_m3),
            ("net_volume_per_cycle_m3", self.net_volume_per_cycle_m3),
            ("drag_volume_per_stroke_m3", self.drag_volume_per_stroke_m3),
            (
                "cycle_mean_leak_rate_m3_per_s",
                self.cycle_mean_leak_rate_m3_per_s,
            ),
        ];
        if let Some(i) = &self.ihl {
            v.extend([
                ("inlet_gradient_out_pa_per_m", i.inlet_gradient_out_pa_per_m),
                ("inlet_gradient_in_pa_per_m", i.inlet_gradient_in_pa_per_m),
                ("out_stroke_film_m", i.out_stroke_film_m),
                ("in_stroke_film_m", i.in_stroke_film_m),
                ("out_stroke_carried_m3", i.out_stroke_carried_m3),
                ("in_stroke_returned_m3", i.in_stroke_returned_m3),
                ("weight_out", i.weight_out),
                ("weight_in", i.weight_in),
            ]);
            v.extend(i.film_parameter.map(|x| ("film_parameter", x)));
        }
        v
    }
}

impl MotionSummary {
    /// The summary of the motion `spec` over `result`'s rows; `None` when the rows carry no
    /// motion.
    pub fn new(spec: &MotionSpec, result: &LifeResult) -> Option<Self> {
        let first: MotionPoint = result.rows.first()?.motion?;
        let last: MotionPoint = result.rows.last()?.motion?;
        let bound = result
            .rows
            .iter()
            .filter_map(|r| r.motion.map(|m| m.speed_bound))
            .fold(f64::INFINITY, f64::min);
        let warned = result.findings.get(Limit::SpeedBound).is_some();
        let (kind, sliding, stroke) = match spec.motion {
            Motion::Steady { speed } => ("steady", Some(speed), None),
            Motion::Stroke {
                stroke,
                out_speed,
                in_speed,
            } => ("stroke", None, Some((stroke, out_speed, in_speed))),
        };
        Some(MotionSummary {
            kind: kind.to_owned(),
            sliding_speed_m_per_s: sliding,
            stroke_m: stroke.map(|s| s.0),
            out_speed_m_per_s: stroke.map(|s| s.1),
            in_speed_m_per_s: stroke.map(|s| s.2),
            cycle_period_s: spec.period(),
            junction_position: spec.junction_position,
            initial_drag_leak_rate_m3_per_s: first.drag_leak_rate,
            final_drag_leak_rate_m3_per_s: last.drag_leak_rate,
            initial_film_thickness_m: first.film_thickness,
            final_film_thickness_m: last.film_thickness,
            speed_bound_m_per_s: bound.is_finite().then_some(bound),
            speed_above_bound: warned
                || result
                    .rows
                    .iter()
                    .any(|r| r.motion.is_some_and(|m| m.above_bound)),
            initial_cycle: CycleSummary::new(&first),
            final_cycle: CycleSummary::new(&last),
        })
    }

    /// Every number of the object, named, for the finiteness check.
    fn values(&self) -> Vec<(&'static str, f64)> {
        let mut v = vec![
            ("junction_position", self.junction_position),
            (
                "initial_drag_leak_rate_m3_per_s",
                self.initial_drag_leak_rate_m3_per_s,
            ),
            (
                "final_drag_leak_rate_m3_per_s",
                self.final_drag_leak_rate_m3_per_s,
            ),
            ("initial_film_thickness_m", self.initial_film_thickness_m),
            ("final_film_thickness_m", self.final_film_thickness_m),
        ];
        for (name, value) in [
            ("sliding_speed_m_per_s", self.sliding_speed_m_per_s),
            ("stroke_m", self.stroke_m),
            ("out_speed_m_per_s", self.out_speed_m_per_s),
            ("in_speed_m_per_s", self.in_speed_m_per_s),
            ("cycle_period_s", self.cycle_period_s),
            ("speed_bound_m_per_s", self.speed_bound_m_per_s),
        ] {
            v.extend(value.map(|x| (name, x)));
        }
        for cycle in [&self.initial_cycle, &self.final_cycle]
            .into_iter()
            .flatten()
        {
            v.extend(cycle.values());
        }
        v
    }
}

impl Summary {
    /// The summary of `result`, a run of `problem` from scenario `scenario` (file `file`).
    pub fn new(scenario: &str, file: &str, problem: &LifeProblem, result: &LifeResult) -> Self {
        let first = result.rows.first();
        let last = result.rows.last();
        Summary {
            scenario: scenario.to_owned(),
            scenario_file: file.to_owned(),
            material: problem.material.name.clone(),
            material_status: problem.material.status.as_str().to_owned(),
            ageing: match problem.ageing_source {
                crate::simulate::AgeingSource::Compound => "compound",
                crate::simulate::AgeingSource::Scenario => "scenario",
                crate::simulate::AgeingSource::Off => "off",
                crate::simulate::AgeingSource::NoData => "no_data",
                crate::simulate::AgeingSource::MissingInComparison => "missing_in_comparison",
            },
            low_temperature_limit_k: problem.material.low_temperature_limit(),
            seal: problem.geometry.name().to_owned(),
            loading: loading_name(problem.loading).to_owned(),
            fidelity: problem.fidelity.name().to_owned(),
            contact_area: (problem.contact.area != crate::contact::AreaModel::default())
                .then(|| problem.contact.area.name()),
            verdict: verdict(problem, result).kind.as_str(),
            verdict_text: verdict(problem, result).text,
            level_band: BandSummary::new(result),
            final_state: result.final_state().as_str(),
            states: result
                .state_changes()
                .into_iter()
                .map(|(state, t)| StateRecord {
                    state: state.as_str(),
                    reason: state.reason(),
                    from_s: t,
                })
                .collect(),
            time_to_failure_s: result.failure.map(|f| f.time),
            failure_mode: failure_mode(result).to_owned(),
            initial_leak_rate_m3_per_s: result.initial_leak_rate(),
            final_leak_rate_m3_per_s: result.final_leak_rate(),
            leaked_volume_m3: result.leaked_volume(),
            leaked_volume_is_lower_bound: result.leaked_volume_is_lower_bound(),
            minimum_sealing_force_n_per_m: result.minimum_force().map_or(0.0, |m| m.0),
            minimum_sealing_force_time_s: result.minimum_force().map_or(0.0, |m| m.1),
            minimum_peak_pressure_pa: result.minimum_peak_pressure().map_or(0.0, |m| m.0),
            minimum_peak_pressure_time_s: result.minimum_peak_pressure().map_or(0.0, |m| m.1),
            maximum_leak_rate_m3_per_s: result.maximum_leak_rate().map_or(0.0, |m| m.0),
            maximum_leak_rate_time_s: result.maximum_leak_rate().map_or(0.0, |m| m.1),
            initial_sealing_force_n_per_m: first.map_or(0.0, |r| r.sealing_force),
            final_sealing_force_n_per_m: last.map_or(0.0, |r| r.sealing_force),
            retained_force_reference_s: problem.failure.retained_force_reference,
            reference_sealing_force_n_per_m: result.reference_force,
            final_retained_force: retained_fraction(
                last.map_or(0.0, |r| r.sealing_force),
                result.reference_force,
            ),
            final_compression_set: last.and_then(|r| r.compression_set),
            shutdown: match (problem.failure.shutdown, last.and_then(|r| r.shutdown)) {
                (Some(sd), Some(end)) => Some(ShutdownSummary {
                    temperature_k: sd.temperature,
                    minimum_pressure_difference_pa: sd.pressure_difference,
                    final_remaining_squeeze: end.remaining_squeeze,
                    lost_s: result.interference_lost(),
                }),
                _ => None,
            },
            coldest_temperature_k: problem.environment.coldest(0.0, problem.time.duration).0,
            coldest_temperature_time_s: problem.environment.coldest(0.0, problem.time.duration).1,
            low_temperature: problem.failure.low_temperature.map(|c| ColdLimitSummary {
                limit_k: c.limit,
                margin_k: c.margin,
                threshold_k: c.threshold(),
                crossed_s: problem.cold_limit_crossed(result),
            }),
            duration_s: problem.time.duration,
            final_open_fraction: result.final_open_fraction(),
            warnings: records(&result.findings),
            input_warnings: Vec::new(),
            motion: problem
                .motion
                .as_ref()
                .and_then(|spec| MotionSummary::new(spec, result)),
            gland: problem.gland.as_ref().map(|g| GlandSummary {
                kind: g.kind.name().to_owned(),
                squeeze: problem.geometry.ring_squeeze().unwrap_or(0.0),
                squeeze_min: g.squeeze_range.map(|r| r.0),
                squeeze_max: g.squeeze_range.map(|r| r.1),
                energisation_factor: problem.energisation_factor,
                extrusion_gap_m: g.extrusion_gap,
            }),
            gas: GasSummary::new(problem, result),
        }
    }

    /// The summary as pretty-printed JSON (with a final newline); every number checked to be
    /// finite.
    pub fn to_json(&self) -> Result<String, ReportError> {
        let values = [
            ("time_to_failure_s", self.time_to_failure_s.unwrap_or(0.0)),
            (
                "initial_leak_rate_m3_per_s",
                self.initial_leak_rate_m3_per_s,
            ),
            ("final_leak_rate_m3_per_s", self.final_leak_rate_m3_per_s),
            ("leaked_volume_m3", self.leaked_volume_m3),
            (
                "minimum_sealing_force_N_per_m",
                self.minimum_sealing_force_n_per_m,
            ),
            ("minimum_peak_pressure_Pa", self.minimum_peak_pressure_pa),
            (
                "maximum_leak_rate_m3_per_s",
                self.maximum_leak_rate_m3_per_s,
            ),
            (
                "initial_sealing_force_n_per_m",
                self.initial_sealing_force_n_per_m,
            ),
            (
                "final_sealing_force_n_per_m",
                self.final_sealing_force_n_per_m,
            ),
            ("duration_s", self.duration_s),
            ("final_open_fraction", self.final_open_fraction),
            ("coldest_temperature_K", self.coldest_temperature_k),
            (
                "coldest_temperature_time_s",
                self.coldest_temperature_time_s,
            ),
            (
                "retained_force_reference_s",
                self.retained_force_reference_s,
            ),
            (
                "reference_sealing_force_N_per_m",
                self.reference_sealing_force_n_per_m,
            ),
            ("final_retained_force", self.final_retained_force),
            (
                "final_compression_set",
                self.final_compression_set.unwrap_or(0.0),
            ),
        ];
        let motion = self.motion.as_ref().map(MotionSummary::values);
        let gas = self.gas.as_ref().map(GasSummary::values);
        for (column, value) in values
            .into_iter()
            .chain(motion.into_iter().flatten())
            .chain(gas.into_iter().flatten())
        {
            if !value.is_finite() {
                return Err(ReportError::NonFinite {
                    row: 1,
                    column,
                    value,
                });
            }
        }
        let mut text =
            serde_json::to_string_pretty(self).map_err(|e| ReportError::Csv(e.to_string()))?;
        text.push('\n');
        Ok(text)
    }
}

/// What a run's verdict is, for every output that states one (summary, JSON, HTML, compare).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VerdictKind {
    /// A failure criterion was crossed.
    Fails,
    /// No criterion crossed, but the seal was open (lift-off waived by `[failure] lift_off =
    /// false`) or held by the fluid pressure alone at some time: never "survives".
    Open,
    /// No criterion crossed, and the seal held by its squeeze throughout.
    Survives,
    /// The neighbouring fidelity level gives another outcome: the model, not the physics it
    /// resolves, would decide (docs/model.md §4.1). Never read as a pass.
    Undecided,
}

impl VerdictKind {
    /// `fails`, `open`, `survives` or `undecided` (JSON, the HTML verdict's class).
    pub fn as_str(self) -> &'static str {
        match self {
            VerdictKind::Fails => "fails",
            VerdictKind::Open => "open",
            VerdictKind::Survives => "survives",
            VerdictKind::Undecided => "undecided",
        }
    }

    /// The kind of an outcome.
    fn of(outcome: Outcome) -> Self {
        match outcome {
            Outcome::Fails => VerdictKind::Fails,
            Outcome::Open => VerdictKind::Open,
            Outcome::Survives => VerdictKind::Survives,
        }
    }
}

/// A run's verdict: its kind and the sentence every output prints.
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    pub kind: VerdictKind,
    pub text: String,
}

/// The verdict of `result`, a run of `problem` (docs/model.md §8.1): "FAILS after … by …", or,
/// without a failure, "OPEN …" when the seal was ever open or held by the pressure alone (a
/// waived lift-off), else "survives …" with the state it ended in — or "UNDECIDED by the
/// model" with both when the neighbouring fidelity level gives another outcome (§4.1).
pub fn verdict(problem: &LifeProblem, result: &LifeResult) -> Verdict {
    let own = level_verdict(problem, result);
    match &result.band {
        Some(band) if result.undecided() => Verdict {
            kind: VerdictKind::Undecided,
            text: format!(
                "UNDECIDED by the model: {} at {}, but {} at {} (the neighbouring fidelity \
                 level; docs/model.md §4.1)",
                own.text,
                problem.fidelity.name(),
                band_outcome_text(problem, band),
                band.level.name()
            ),
        },
        _ => own,
    }
}

/// The outcome at the neighbouring level in a few words.
fn band_outcome_text(problem: &LifeProblem, band: &LevelBand) -> String {
    match (band.failure, band.open_since) {
        (Some(f), _) => format!(
            "FAILS {} by {}",
            if f.time == 0.0 {
                "at installation".to_owned()
            } else {
                format!("after {}", human_time(f.time))
            },
            f.mode.as_str()
        ),
        (None, Some(t)) => format!("OPEN from {}", at_time(t)),
        (None, None) => format!("survives {}", human_time(problem.time.duration)),
    }
}

/// The verdict at the run's own level (see [`verdict`]).
fn level_verdict(problem: &LifeProblem, result: &LifeResult) -> Verdict {
    let duration = human_time(problem.time.duration);
    // the states with their located times (docs/model.md §10.1), not the output rows
    let states = &result.course.states;
    let open = states.iter().find(|(s, _)| s.is_open());
    match (result.failure, open) {
        (Some(f), _) => {
            // the open state the lift-off failure found: in effect at its time, or beginning
            // within the simultaneous-events window after it (docs/model.md §8)
            let window = f.time * (1.0 + crate::simulate::events::SIMULTANEOUS_EVENTS);
            let how = match f.mode {
                crate::simulate::FailureMode::LiftOff => states
                    .iter()
                    .enumerate()
                    .find(|&(i, (s, t))| {
                        let until = states.get(i + 1).map_or(f64::INFINITY, |n| n.1);
                        s.is_open() && *t <= window && until > f.time
                    })
                    .map_or(String::new(), |(_, (s, _))| {
                        format!(": {}, {}", s.label(), s.meaning())
                    }),
                _ => String::new(),
            };
            let when = if f.time == 0.0 {
                "at installation".to_owned()
            } else {
                format!("after {} (t = {} s)", human_time(f.time), human(f.time, 3))
            };
            Verdict {
                kind: VerdictKind::Fails,
                text: format!("FAILS {when} by {}{how}", f.mode.as_str()),
            }
        }
        (None, Some(&(state, time))) => Verdict {
            kind: VerdictKind::Open,
            text: format!(
                "{} ({}) from {}: not counted as a failure only because [failure] lift_off = \
                 false waives it",
                state.label(),
                state.meaning(),
                if time == 0.0 {
                    "installation".to_owned()
                } else {
                    format!("t = {}", human_time(time))
                }
            ),
        },
        (None, None) => {
            let end = result.final_state();
            let no_criterion = if problem.can_fail() {
                ""
            } else {
                " (no failure criterion set)"
            };
            Verdict {
                kind: VerdictKind::Survives,
                text: format!(
                    "survives {duration}{no_criterion}; {} at the end",
                    end.label()
                ),
            }
        }
    }
}

/// `leak_rate`, `leaked_volume`, `retained_force`, `lift_off`, or `none` when the seal
/// survives.
pub fn failure_mode(result: &LifeResult) -> &'static str {
    result.failure.map_or("none", |f| f.mode.as_str())
}

fn loading_name(loading: Loading) -> &'static str {
    match loading {
        Loading::Displacement => "displacement",
        Loading::Force => "force",
    }
}

/// A duration in the unit a reader would use: s, min, h, days or years, 3 significant digits
/// (`"45 s"`, `"12.5 min"`, `"3.2 days"`, `"17.4 years"`).
pub fn human_time(seconds: f64) -> String {
    let (value, unit) = if seconds < 120.0 {
        (seconds, "s")
    } else if seconds < 2.0 * 3600.0 {
        (seconds / 60.0, "min")
    } else if seconds < 2.0 * DAY {
        (seconds / 3600.0, "h")
    } else if seconds < 2.0 * YEAR {
        (seconds / DAY, "days")
    } else {
        (seconds / YEAR, "years")
    };
    format!("{} {unit}", human(value, 3))
}

/// A volume flow with tangible units beside it: `"1.2e-12 m³/s (0.0043 mL/h, 0.104 mL/day)"`.
fn flow(q: f64) -> String {
    if q == 0.0 {
        return "0 m³/s".to_owned();
    }
    format!(
        "{} m³/s ({} mL/h, {} mL/day)",
        human(q, 3),
        human(q * 1e6 * 3600.0, 3),
        human(q * 1e6 * 86_400.0, 3)
    )
}

/// `"80 °C (353.15 K)"`.
fn celsius(kelvin: f64) -> String {
    format!("{} °C", human(kelvin - 273.15, 4))
}

/// The leak rate below which a report says "≈ 0" (docs/model.md §15.2): by default one
/// molecule a second ([`crate::fluid::Fluid::one_molecule_per_second`]), or a floor the user
/// gives (`--leak-floor`). Only what is shown changes: tables keep the raw value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeakFloor {
    /// \[m³/s\]
    pub rate: f64,
    /// Given by the user rather than the molecular default.
    pub given: bool,
}

impl LeakFloor {
    /// The floor for `fluid`: `given` \[m³/s\], else one molecule a second.
    pub fn of(fluid: &crate::fluid::Fluid, given: Option<f64>) -> LeakFloor {
        match given {
            Some(rate) => LeakFloor { rate, given: true },
            None => LeakFloor {
                rate: fluid.one_molecule_per_second(),
                given: false,
            },
        }
    }

    /// What the floor stands for.
    pub fn meaning(&self) -> &'static str {
        if self.given {
            "the floor given"
        } else {
            "one molecule a second"
        }
    }

    /// Whether a leak rate is below the floor (sealed in practice; 0 included).
    pub fn seals(&self, q: f64) -> bool {
        q < self.rate
    }

    /// `"≈ 0 (below 3e-29 m³/s, one molecule a second)"`: what a rate below the floor means.
    /// Not "sealed": whether the seal is sealed is its state's to say (a percolating channel
    /// may carry less than a molecule a second; docs/model.md §8.1).
    pub fn sealed(&self) -> String {
        format!(
            "≈ 0 (below {} m³/s, {})",
            human(self.rate, 2),
            self.meaning()
        )
    }

    /// A leak rate for people: m³/s with mL/h above the floor, [`LeakFloor::sealed`] below.
    pub fn flow(&self, q: f64) -> String {
        if self.seals(q) {
            self.sealed()
        } else {
            flow(q)
        }
    }
}

/// The readable summary of a run, for the terminal; leak rates below `floor` read "≈ 0".
pub fn human_summary(
    scenario: &str,
    file: &str,
    problem: &LifeProblem,
    result: &LifeResult,
    floor: &LeakFloor,
) -> String {
    let run = SummaryRun {
        problem,
        result,
        floor,
        duration: human_time(problem.time.duration),
    };
    let mut out = SummaryText::default();
    out.line("scenario", format!("{scenario} ({file})"));
    material_lines(&mut out, &problem.material);
    out.line("seal", seal_description(problem));
    out.line("fluid", fluid_line(problem));
    out.line("temperature", temperature_line(&problem.environment));
    out.line("ageing", ageing_line(problem));
    out.optional("contact area", contact_area_line(problem));
    if let (Some(first), Some(last)) = (result.rows.first(), result.rows.last()) {
        out.line("sealing force", sealing_force_line(&run, first, last));
        out.optional("lowest", lowest_line(&run, first));
        out.optional("set", set_line(&run, last));
        out.optional("shutdown", shutdown_line(&run, last));
    }
    out.optional("cold limit", cold_limit_line(&run));
    out.line("state", state_line(result));
    out.line("leak rate", leak_rate_line(&run));
    if let Some((q, t)) = result.maximum_leak_rate()
        && !floor.seals(q)
    {
        out.line(
            "highest",
            format!("leak rate {} {}", floor.flow(q), at_time(t)),
        );
    }
    if let Some(p) = problem.fluid.mean_pressure() {
        gas_flow_lines(&mut out, &run, p);
    }
    out.line("leaked volume", leaked_volume_line(&run));
    if let Some(spec) = &problem.motion
        && let Some(m) = MotionSummary::new(spec, result)
    {
        out.line("motion", motion_description(spec, &m, &run.duration));
    }
    if let Some(band) = &result.band {
        out.line("level band", band_line(problem, result, band));
    }
    out.line("result", verdict(problem, result).text);
    out.text
}

/// How much of a run's summary the terminal gets (`--quiet`, the default, `--verbose`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Detail {
    /// The verdict line only.
    Quiet,
    /// The verdict line and the short table of key figures ([`brief_summary`]).
    #[default]
    Brief,
    /// The verdict line and the full derivation ([`human_summary`], SI).
    Verbose,
}

/// The terminal summary of a run: [`verdict_line`] first, then what `detail` asks for. The
/// verdict line and the short table are in `units`; the verbose derivation stays SI.
pub fn run_summary(
    scenario: &str,
    file: &str,
    problem: &LifeProblem,
    result: &LifeResult,
    floor: &LeakFloor,
    units: UnitSystem,
    detail: Detail,
) -> String {
    let mut text = verdict_line(problem, result, floor, units);
    text.push('\n');
    match detail {
        Detail::Quiet => {}
        Detail::Brief => text += &brief_summary(scenario, file, problem, result, floor, units),
        Detail::Verbose => text += &human_summary(scenario, file, problem, result, floor),
    }
    text
}

/// `"30-year"`, `"500-day"`: the run's duration as the target a verdict is read against.
fn target(duration: f64) -> String {
    let text = human_time(duration);
    match text.split_once(' ') {
        Some((n, unit)) => {
            let unit = match unit {
                "s" => "second",
                "min" => "minute",
                "h" => "hour",
                other => other.strip_suffix('s').unwrap_or(other),
            };
            format!("{n}-{unit}")
        }
        None => text,
    }
}

/// One criterion of a run against its limit, for the verdict line: what it compares and, for
/// the quantities with a ratio, the factor by which the worst value over the run stays inside
/// the limit (below 1: crossed).
struct Margin {
    mode: crate::simulate::FailureMode,
    text: String,
    factor: Option<f64>,
}

/// `limit / worst` (∞ when the worst is 0) for a criterion with a maximum.
fn below(worst: f64, limit: f64) -> f64 {
    if worst > 0.0 {
        limit / worst
    } else {
        f64::INFINITY
    }
}

/// Every criterion the run checks with the worst value over the run beside its limit (for a
/// decreasing force the lowest, for a leak the highest: the run's tightest point, so never a
/// margin larger than the end's).
fn margins(
    problem: &LifeProblem,
    result: &LifeResult,
    floor: &LeakFloor,
    units: UnitSystem,
) -> Vec<Margin> {
    use crate::simulate::FailureMode as M;
    use Quantity as Q;
    let c = &problem.failure;
    let mut out = Vec::new();
    let min_force = result.minimum_force().map_or(0.0, |m| m.0);
    // e^{-K} run to 1e-26 is arithmetic, not a force: shown as 0 ("fully set")
    let shown_force =
        if result.reference_force > 0.0 && min_force < FULLY_SET * result.reference_force {
            0.0
        } else {
            min_force
        };
    if let Some(limit) = c.max_leak_rate {
        let p = problem.fluid.mean_pressure();
        let worst = result
            .rows
            .iter()
            .map(|r| r.detected_leak_rate(p))
            .fold(result.maximum_leak_rate().map_or(0.0, |m| m.0), f64::max);
        let (q, scale) = match p {
            Some(p) => (Q::Throughput, p),
            None => (Q::VolumeFlow, 1.0),
        };
        let shown = if floor.seals(worst) { 0.0 } else { worst };
        out.push(Margin {
            mode: M::LeakRate,
            text: versus(units, q, "highest leak rate", shown * scale, limit * scale),
            factor: Some(below(worst, limit)),
        });
    }
    if let Some(limit) = c.max_leaked_volume {
        let v = result.leaked_volume();
        out.push(Margin {
            mode: M::LeakedVolume,
            text: versus(
                units,
                Q::Volume,
                &format!(
                    "leaked volume{}",
                    if result.leaked_volume_is_lower_bound() {
                        " ≥"
                    } else {
                        ""
                    }
                ),
                v,
                limit,
            ),
            factor: Some(below(v, limit)),
        });
    }
    if let Some(fraction) = c.min_retained_force
        && result.reference_force > 0.0
    {
        let limit = fraction * result.reference_force;
        out.push(Margin {
            mode: M::RetainedForce,
            text: versus(units, Q::ForcePerLength, "lowest force", shown_force, limit),
            factor: Some(min_force / limit),
        });
    }
    if let Some(limit) = c.min_sealing_force {
        out.push(Margin {
            mode: M::SealingForce,
            text: versus(units, Q::ForcePerLength, "lowest force", shown_force, limit),
            factor: (limit > 0.0).then(|| min_force / limit),
        });
    }
    if let Some(limit) = c.max_compression_set {
        let set = result
            .rows
            .iter()
            .filter_map(|r| r.compression_set)
            .fold(0.0, f64::max);
        out.push(Margin {
            mode: M::CompressionSet,
            text: format!(
                "compression set {} % (limit {})",
                human(100.0 * set, 3),
                human(100.0 * limit, 3)
            ),
            factor: Some(below(set, limit)),
        });
    }
    if let Some(limit) = c.min_contact_pressure {
        out.push(Margin {
            mode: M::ContactPressure,
            text: format!(
                "installed peak contact pressure vs {} limit",
                units.show(Q::Pressure, limit, 3)
            ),
            factor: None,
        });
    } else if let Some(m) = c.gasket_factor {
        out.push(Margin {
            mode: M::ContactPressure,
            text: format!(
                "installed mean contact pressure vs m·ΔP (m = {})",
                human(m, 3)
            ),
            factor: None,
        });
    }
    if c.lift_off {
        out.push(Margin {
            mode: M::LiftOff,
            text: "the fluid pressure opens the contact".to_owned(),
            factor: None,
        });
    }
    if c.extrusion {
        out.push(Margin {
            mode: M::Extrusion,
            text: "the clearance gap beyond the extrusion chart's limit".to_owned(),
            factor: None,
        });
    }
    if let (Some(sd), Some(end)) = (c.shutdown, result.rows.last().and_then(|r| r.shutdown)) {
        out.push(Margin {
            mode: M::LostInterference,
            text: format!(
                "{} {} % at the end, at the shutdown's {}",
                problem.geometry.set_quantity(),
                human(100.0 * end.remaining_squeeze, 3),
                units.show(Q::Temperature, sd.temperature, 4),
            ),
            factor: None,
        });
    }
    if let Some(cold) = c.low_temperature {
        let (coldest, _) = problem.environment.coldest(0.0, problem.time.duration);
        out.push(Margin {
            mode: M::LowTemperature,
            text: format!(
                "coldest {} (limit {}: T10 less {} K)",
                units.show(Q::Temperature, coldest, 4),
                units.show(Q::Temperature, cold.threshold(), 4),
                human(cold.margin, 3)
            ),
            factor: None,
        });
    }
    out
}

/// `"lowest force 0.2 N/mm (limit 0.51)"`: a worst value `value` and its limit \[SI\] in
/// `units` (the unit once; a value of 0 reads "≈ 0").
fn versus(units: UnitSystem, quantity: Quantity, what: &str, value: f64, limit: f64) -> String {
    let unit = units.display(quantity);
    let value = if value == 0.0 {
        "≈ 0".to_owned()
    } else {
        human(unit.from_si(value), 3)
    };
    format!(
        "{what} {value} {} (limit {})",
        unit.symbol,
        human(unit.from_si(limit), 3)
    )
}

/// The line every run summary opens with (issue 42): `PASS`, `FAIL`, `OPEN` (failed at
/// installation, or open with lift-off waived) or `UNDECIDED` (the neighbouring fidelity level
/// gives another outcome, docs/model.md §4.1; never a pass), the life against the run's
/// duration (the target), the failure mode and its quantity against its limit, or for a pass
/// the criterion with the smallest margin (worst value over the run); `[ILLUSTRATIVE data]`
/// when the compound's data are estimates. `--quiet` prints this line alone.
pub fn verdict_line(
    problem: &LifeProblem,
    result: &LifeResult,
    floor: &LeakFloor,
    units: UnitSystem,
) -> String {
    let target = target(problem.time.duration);
    let margins = margins(problem, result, floor, units);
    let of_mode = |mode| {
        margins
            .iter()
            .find(|m| m.mode == mode)
            .map_or(String::new(), |m| format!(": {}", m.text))
    };
    let kind = verdict(problem, result).kind;
    let line = match (kind, result.failure) {
        (VerdictKind::Undecided, _) => format!(
            "UNDECIDED by the model (a {target} target): {}",
            verdict(problem, result)
                .text
                .trim_start_matches("UNDECIDED by the model: ")
        ),
        (VerdictKind::Fails, Some(f)) if f.time == 0.0 => format!(
            "OPEN at installation (a {target} target) by {}{}",
            f.mode.as_str(),
            of_mode(f.mode)
        ),
        (VerdictKind::Fails, Some(f)) => format!(
            "FAIL after {} of a {target} target by {}{}",
            human_time(f.time),
            f.mode.as_str(),
            of_mode(f.mode)
        ),
        (VerdictKind::Open, _) | (VerdictKind::Fails, None) => format!(
            "OPEN {} (a {target} target): {}; not a failure only because [failure] lift_off = \
             false",
            result
                .open_since()
                .map_or("at installation".to_owned(), at_time),
            result.final_state().label()
        ),
        (VerdictKind::Survives, _) => {
            let tightest = margins
                .iter()
                .filter(|m| m.factor.is_some_and(f64::is_finite))
                .min_by(|a, b| {
                    a.factor
                        .partial_cmp(&b.factor)
                        .unwrap_or(std::cmp::Ordering::Equal)
                });
            let margin = match tightest {
                Some(m) => format!(
                    "; tightest: {} ×{}",
                    m.text,
                    human(m.factor.unwrap_or(f64::INFINITY), 3)
                ),
                None if margins.is_empty() => "; no failure criterion set".to_owned(),
                None => format!(
                    "; none reached ({})",
                    margins
                        .iter()
                        .map(|m| m.mode.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            };
            format!(
                "PASS over the {target} target, {} at the end{margin}",
                result.final_state().as_str()
            )
        }
    };
    if problem.material.status == Status::Illustrative {
        format!("{line} [ILLUSTRATIVE data]")
    } else {
        line
    }
}

/// The short table under the verdict line (the default summary): the key figures in `units`,
/// each line at most ~120 characters. The derivations are `--verbose`'s ([`human_summary`]),
/// the report's and the JSON's.
pub fn brief_summary(
    scenario: &str,
    file: &str,
    problem: &LifeProblem,
    result: &LifeResult,
    floor: &LeakFloor,
    units: UnitSystem,
) -> String {
    use Quantity as Q;
    let duration = human_time(problem.time.duration);
    let mut out = SummaryText::default();
    brief_setup(&mut out, scenario, file, problem, result, units);
    if let (Some(first), Some(last)) = (result.rows.first(), result.rows.last()) {
        let fraction = retained_fraction(last.sealing_force, result.reference_force);
        let end = if result.reference_force > 0.0 && fraction < FULLY_SET {
            format!(
                "≈ 0 {} (fully set)",
                units.display(Q::ForcePerLength).symbol
            )
        } else {
            units.show(Q::ForcePerLength, last.sealing_force, 3)
        };
        out.line(
            "sealing force",
            format!(
                "{} at installation, {end} after {duration}",
                units.show(Q::ForcePerLength, first.sealing_force, 3)
            ),
        );
        if let Some((peak, t)) = result.minimum_peak_pressure() {
            out.line(
                "contact",
                format!(
                    "peak pressure {} at installation, lowest {} {}",
                    units.show(Q::Pressure, first.peak_pressure, 3),
                    units.show(Q::Pressure, peak, 3),
                    at_time(t)
                ),
            );
        }
    }
    let changes = result.state_changes();
    let states: Vec<String> = changes
        .iter()
        .take(3)
        .map(|(state, t)| {
            let name = state.as_str();
            if *t == 0.0 {
                format!("{name} from installation")
            } else {
                format!("{name} from {}", human_time(*t))
            }
        })
        .collect();
    let more = if changes.len() > 3 {
        format!("; {} more changes (--verbose)", changes.len() - 3)
    } else {
        String::new()
    };
    out.line("state", format!("{}{more}", states.join("; then ")));
    let rate = |row: Option<&crate::simulate::HistoryRow>, show: &dyn Fn(f64) -> String| match row {
        Some(r) if r.state == crate::simulate::SealState::LiftOff && floor.seals(r.leak_rate) => {
            "OPEN (flow not modelled)".to_owned()
        }
        Some(r) if r.state == crate::simulate::SealState::LiftOff => {
            format!("≥ {} (OPEN: a lower bound)", show(r.leak_rate))
        }
        Some(r) if floor.seals(r.leak_rate) && r.permeation.is_none() => "≈ 0".to_owned(),
        Some(r) => show(r.leak_rate),
        None => "≈ 0".to_owned(),
    };
    match problem.fluid.mean_pressure() {
        Some(p) => {
            // what a leak detector sees: interface + permeation (docs/model.md §13.7)
            let total = |q: f64| units.show(Q::Throughput, q, 3);
            let row_total = |r: Option<&crate::simulate::HistoryRow>| {
                r.map_or(0.0, |r| p * r.leak_rate + r.permeation.unwrap_or(0.0))
            };
            out.line(
                "throughput",
                format!(
                    "{} at installation, {} after {duration} (interface{})",
                    total(row_total(result.rows.first())),
                    total(row_total(result.rows.last())),
                    if result.rows.iter().any(|r| r.permeation.is_some()) {
                        " + permeation"
                    } else {
                        ""
                    }
                ),
            );
        }
        None => {
            let show = |q: f64| units.show(Q::VolumeFlow, q, 3);
            let highest = match result.maximum_leak_rate() {
                Some((q, t)) if !floor.seals(q) => format!("; highest {} {}", show(q), at_time(t)),
                _ => String::new(),
            };
            let (first, last) = (
                rate(result.rows.first(), &show),
                rate(result.rows.last(), &show),
            );
            // what "≈ 0" stands for (docs/model.md §15.2)
            let zero = if first.starts_with("≈ 0") || last.starts_with("≈ 0") {
                format!(" (≈ 0: below {}, {})", show(floor.rate), floor.meaning())
            } else {
                String::new()
            };
            out.line(
                "leak rate",
                format!("{first} at installation, {last} after {duration}{highest}{zero}"),
            );
        }
    }
    let lower = if result.leaked_volume_is_lower_bound() {
        " (a lower bound: lifted off)"
    } else {
        ""
    };
    out.line(
        "leaked volume",
        format!(
            "{}{} in {duration}{lower}",
            at_least(result.leaked_volume_is_lower_bound()),
            units.show(Q::Volume, result.leaked_volume(), 3)
        ),
    );
    brief_checks(&mut out, problem, result, units, &duration);
    out.line(
        "details",
        "--verbose: the derivations; --summary FILE.json: every figure (SI); --report: both"
            .to_owned(),
    );
    out.text
}

/// The brief summary's set-up lines: the scenario, the material (and the illustrative flag)
/// and the service (temperature, pressure, seal kind, contact width) in `units`.
fn brief_setup(
    out: &mut SummaryText,
    scenario: &str,
    file: &str,
    problem: &LifeProblem,
    result: &LifeResult,
    units: UnitSystem,
) {
    use Quantity as Q;
    let both = format!("{scenario} ({file})");
    if both.chars().count() <= 100 {
        out.line("scenario", both);
    } else {
        out.line("scenario", scenario.to_owned());
        out.line("", file.to_owned());
    }
    let m = &problem.material;
    out.line("material", format!("{} [{}]", m.name, m.status.as_str()));
    if m.status == Status::Illustrative {
        out.line(
            "",
            "!!! ILLUSTRATIVE material data: estimated, not measured; trends only, NOT for design \
             decisions !!!"
                .to_owned(),
        );
    }
    let (lo, hi) = problem.environment.range();
    let temperature = if problem.environment.is_constant() || lo == hi {
        units.show(Q::Temperature, lo, 4)
    } else {
        format!(
            "{} to {}",
            units.show(Q::Temperature, lo, 4),
            units.show(Q::Temperature, hi, 4)
        )
    };
    let pressure = match (problem.fluid.gas, problem.fluid.mean_pressure()) {
        (Some(gas), Some(_)) => format!(
            "P_a {}, P_b {} abs.",
            units.show(
                Q::Pressure,
                gas.outlet_pressure + problem.fluid.pressure_difference,
                3
            ),
            units.show(Q::Pressure, gas.outlet_pressure, 3)
        ),
        _ => {
            let dp = result.rows.iter().map(|r| r.pressure_difference);
            let (a, b) = dp.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p), b.max(p))
            });
            if a.is_finite() && a < b {
                format!(
                    "ΔP {} to {}",
                    units.show(Q::Pressure, a, 3),
                    units.show(Q::Pressure, b, 3)
                )
            } else {
                format!(
                    "ΔP {}",
                    units.show(Q::Pressure, problem.fluid.pressure_difference, 3)
                )
            }
        }
    };
    let width = result.rows.first().map_or(String::new(), |r| {
        format!(
            ", contact width {} at installation",
            units.show(Q::Length, r.contact_width, 3)
        )
    });
    out.line(
        "service",
        format!(
            "{temperature}, {pressure}; {}{width}",
            problem.geometry.name()
        ),
    );
}

/// The brief summary's checks: the compression set, the shutdown, the cold limit and the
/// neighbouring level's outcome.
fn brief_checks(
    out: &mut SummaryText,
    problem: &LifeProblem,
    result: &LifeResult,
    units: UnitSystem,
    duration: &str,
) {
    use Quantity as Q;
    if let Some(set) = result.rows.last().and_then(|r| r.compression_set) {
        out.line(
            "set",
            format!(
                "chemical compression set {} % after {duration}",
                human(100.0 * set, 3)
            ),
        );
    }
    if let (Some(sd), Some(end)) = (
        problem.failure.shutdown,
        result.rows.last().and_then(|r| r.shutdown),
    ) {
        let lost = result
            .interference_lost()
            .map_or("holds throughout".to_owned(), |t| {
                format!("interference lost by {}", human_time(t))
            });
        out.line(
            "shutdown",
            format!(
                "at {}, ΔP {}: {} {} % after {duration}; {lost}",
                units.show(Q::Temperature, sd.temperature, 4),
                units.show(Q::Pressure, sd.pressure_difference, 3),
                problem.geometry.set_quantity(),
                human(100.0 * end.remaining_squeeze, 3)
            ),
        );
    }
    if let Some(cold) = problem.failure.low_temperature {
        let (coldest, when) = problem.environment.coldest(0.0, problem.time.duration);
        if coldest < cold.limit {
            out.line(
                "cold limit",
                format!(
                    "T10 {}, holds to {}; coldest {} {}",
                    units.show(Q::Temperature, cold.limit, 4),
                    units.show(Q::Temperature, cold.threshold(), 4),
                    units.show(Q::Temperature, coldest, 4),
                    at_time(when)
                ),
            );
        }
    }
    if let Some(band) = &result.band {
        let same = if result.undecided() {
            "another outcome: UNDECIDED"
        } else {
            "the same outcome"
        };
        out.line(
            "level band",
            format!(
                "at {}: {}; {same}",
                band.level.name(),
                band_outcome_text(problem, band)
            ),
        );
    }
}

/// The contact-area relation when it is not the default (`[model] area`, docs/model.md §2).
fn contact_area_line(problem: &LifeProblem) -> Option<String> {
    match problem.contact.area {
        crate::contact::AreaModel::Persson => None,
        crate::contact::AreaModel::Corrected => Some(
            "corrected (Wang & Müser 2017; the default \"persson\" gives a smaller contact area \
             and, mostly, a larger leak)"
                .to_owned(),
        ),
    }
}

/// The terminal summary being written: labelled lines.
#[derive(Default)]
struct SummaryText {
    text: String,
}

impl SummaryText {
    /// `text` under `label` (in a column 15 wide).
    fn line(&mut self, label: &str, text: String) {
        self.text += &format!("{label:<15}{text}\n");
    }

    /// `text`, if any, under `label`.
    fn optional(&mut self, label: &str, text: Option<String>) {
        if let Some(text) = text {
            self.line(label, text);
        }
    }
}

/// The run a summary describes: the problem, its result, the leak floor and the run's
/// duration for people.
struct SummaryRun<'a> {
    problem: &'a LifeProblem,
    result: &'a LifeResult,
    floor: &'a LeakFloor,
    duration: String,
}

/// The compound, its status and T10, and the banner of illustrative data.
fn material_lines(out: &mut SummaryText, m: &Material) {
    let t10 = m.low_temperature_limit().map_or(String::new(), |t| {
        format!(
            "; low-temperature limit T10 = {} (modulus at 10 s ten times its 23 °C value)",
            celsius(t)
        )
    });
    out.line(
        "material",
        format!("{} [{}]{t10}", m.name, m.status.as_str()),
    );
    if m.status == Status::Illustrative {
        out.line(
            "",
            "!!! ILLUSTRATIVE material data: at least one number is estimated, not measured; \
             the results show trends, they are NOT for design decisions !!!"
                .to_owned(),
        );
    }
}

/// The gas and its pressures, or the liquid's viscosity and pressure difference.
fn fluid_line(problem: &LifeProblem) -> String {
    if let (Some(gas), Some(p_mean)) = (problem.fluid.gas, problem.fluid.mean_pressure()) {
        return format!(
            "gas {} (μ = {} Pa·s at installation, following T(t); {}), P_a = {} Pa, P_b = {} \
             Pa absolute; leak rates below are volume flows at the mean pressure p̄ = {} Pa",
            gas.gas.id,
            human(problem.fluid.viscosity, 3),
            gas.gas.source,
            human(gas.outlet_pressure + problem.fluid.pressure_difference, 4),
            human(gas.outlet_pressure, 4),
            human(p_mean, 4)
        );
    }
    match problem.fluid.law.source() {
        None => format!(
            "η = {} Pa·s, ΔP = {} MPa",
            human(problem.fluid.viscosity, 3),
            human(problem.fluid.pressure_difference / 1e6, 4)
        ),
        Some(source) => format!(
            "η = {} Pa·s at installation, following T(t) ({source}), ΔP = {} MPa",
            human(problem.fluid.viscosity, 3),
            human(problem.fluid.pressure_difference / 1e6, 4)
        ),
    }
}

/// The temperature: constant, or its bounds and start.
fn temperature_line(env: &crate::material::TemperatureHistory) -> String {
    if env.is_constant() {
        format!("{} (constant)", celsius(env.at(0.0)))
    } else {
        let (lo, hi) = env.range();
        format!(
            "varies between {} and {} (bounds); {} at t = 0",
            celsius(lo),
            celsius(hi),
            celsius(env.at(0.0))
        )
    }
}

/// The two-network ageing's constants and their source, or why there is none.
fn ageing_line(problem: &LifeProblem) -> String {
    match problem.ageing {
        Some(ag) => format!(
            "two networks: scission k = {} 1/s at {}, Ea = {} kJ/mol, new network at {} k \
             in the compressed state; from {}{}",
            human(ag.rate, 3),
            celsius(ag.reference_temperature),
            human(ag.activation_energy / 1e3, 3),
            human(ag.crosslinking, 3),
            problem.ageing_source.describe(),
            problem
                .material
                .ageing_basis
                .as_ref()
                .filter(|_| problem.ageing_source == crate::simulate::AgeingSource::Compound)
                .map_or(String::new(), |b| format!(", measured on {}", b.property)),
        ),
        None => problem.ageing_source.describe().to_owned(),
    }
}

/// The sealing force at installation, at the reference and at the end, with the fraction
/// retained.
fn sealing_force_line(
    run: &SummaryRun,
    first: &crate::simulate::HistoryRow,
    last: &crate::simulate::HistoryRow,
) -> String {
    let (problem, result, duration) = (run.problem, run.result, &run.duration);
    let reference = problem.failure.retained_force_reference;
    let at_reference = if reference > 0.0 {
        format!(
            ", {} N/mm at {} (the reference)",
            human(result.reference_force / 1e3, 3),
            human_time(reference)
        )
    } else {
        " (the reference)".to_owned()
    };
    let fraction = retained_fraction(last.sealing_force, result.reference_force);
    let (end_force, retained) = if result.reference_force > 0.0 && fraction < FULLY_SET {
        // e^{-K} run to 1e-26 is arithmetic, not a force: what it means is "fully set"
        (
            "≈ 0".to_owned(),
            " (fully set; the CSV keeps the figure)".to_owned(),
        )
    } else if result.reference_force > 0.0 {
        (
            human(last.sealing_force / 1e3, 3),
            format!(
                " ({} % of the reference retained)",
                human(100.0 * fraction, 3)
            ),
        )
    } else {
        (human(last.sealing_force / 1e3, 3), String::new())
    };
    format!(
        "{} N/mm at installation{at_reference}, {end_force} N/mm after \
         {duration}{retained}",
        human(first.sealing_force / 1e3, 3),
    )
}

/// The lowest sealing force and peak contact pressure, and when.
fn lowest_line(run: &SummaryRun, first: &crate::simulate::HistoryRow) -> Option<String> {
    let result = run.result;
    let ((force, t_force), (peak, t_peak)) =
        (result.minimum_force()?, result.minimum_peak_pressure()?);
    let low = |v: f64, reference: f64, scale: f64| {
        if reference > 0.0 && v < FULLY_SET * reference {
            "≈ 0".to_owned()
        } else {
            human(v / scale, 3)
        }
    };
    Some(format!(
        "sealing force {} N/mm {}, peak contact pressure {} MPa {}",
        low(force, result.reference_force, 1e3),
        at_time(t_force),
        low(peak, first.peak_pressure, 1e6),
        at_time(t_peak),
    ))
}

/// The chemical compression set at the end.
fn set_line(run: &SummaryRun, last: &crate::simulate::HistoryRow) -> Option<String> {
    let set = last.compression_set?;
    Some(format!(
        "chemical compression set {} % after {} (fully recovered: without the \
         viscoelastic part a D395 reading 30 min after release adds)",
        human(100.0 * set, 3),
        run.duration
    ))
}

/// The set ring's squeeze at the shutdown condition, and whether the interference holds.
fn shutdown_line(run: &SummaryRun, last: &crate::simulate::HistoryRow) -> Option<String> {
    let (Some(shutdown), Some(s)) = (run.problem.failure.shutdown, last.shutdown) else {
        return None;
    };
    let result = run.result;
    let located = result
        .failure
        .is_some_and(|f| f.mode == crate::simulate::FailureMode::LostInterference);
    let lost = result.interference_lost().map_or_else(
        || "holds throughout".to_owned(),
        |t| {
            if located {
                format!("interference lost {}", at_time(t))
            } else {
                // not the run's failure: found on the output grid, not located
                format!(
                    "interference found lost by the output time {} (not located: the run \
                     had failed before)",
                    at_time(t).trim_start_matches("at ")
                )
            }
        },
    );
    // below T10 the ring was also cooled through its hereditary response (§8.2)
    let glassy = s.glassy_peak_pressure.map_or(String::new(), |peak| {
        format!(
            "; below T10, cooled from service over {}: contact pressure {} MPa after {}",
            human_time(shutdown.cooling_time),
            human(peak / 1e6, 3),
            run.duration,
        )
    });
    // a flat gasket keeps a compression of its recovered thickness (§8.2)
    let kept = run.problem.geometry.set_quantity();
    Some(format!(
        "at {} and ΔP = {} MPa: {kept} {} % after {}{glassy}; {lost}",
        celsius(shutdown.temperature),
        human(shutdown.pressure_difference / 1e6, 3),
        human(100.0 * s.remaining_squeeze, 3),
        run.duration,
    ))
}

/// The cold limit (docs/model.md §8.3): the compound's T10, the margin, the coldest temperature
/// and whether (and when) the run went colder. Shown where the run goes below T10, or the cold
/// limit is its failure; the JSON always carries it.
fn cold_limit_line(run: &SummaryRun) -> Option<String> {
    let p = run.problem;
    let t10 = p.material.low_temperature_limit()?;
    let (coldest, when) = p.environment.coldest(0.0, p.time.duration);
    let failed = run
        .result
        .failure
        .is_some_and(|f| f.mode == crate::simulate::FailureMode::LowTemperature);
    if coldest >= t10 && !failed {
        return None;
    }
    let coldest = format!("coldest {} {}", celsius(coldest), at_time(when));
    Some(match p.failure.low_temperature {
        None => format!(
            "T10 = {}, {coldest}; not checked: [failure] low_temperature = false waives it",
            celsius(t10)
        ),
        Some(c) => {
            let crossed = match p.cold_limit_crossed(run.result) {
                None => format!(
                    "holds ({} K above it)",
                    human(
                        p.environment.coldest(0.0, p.time.duration).0 - c.threshold(),
                        3
                    )
                ),
                Some(t) if failed || run.result.failure.is_none() => {
                    format!("colder {}", at_time(t).replacen("at ", "from ", 1))
                }
                Some(t) => format!(
                    "colder {} (after the run had failed)",
                    at_time(t).replacen("at ", "from ", 1)
                ),
            };
            format!(
                "T10 = {} less the margin {} K: holds to {}; {coldest}; {crossed}",
                celsius(t10),
                human(c.margin, 3),
                celsius(c.threshold()),
            )
        }
    })
}

/// The seal's states in order, with when each began.
fn state_line(result: &LifeResult) -> String {
    result
        .state_changes()
        .iter()
        .map(|(state, t)| {
            let name = state.label();
            if *t == 0.0 {
                format!("{name} from installation")
            } else {
                format!("{name} from t = {}", human_time(*t))
            }
        })
        .collect::<Vec<_>>()
        .join("; then ")
}

/// The leak rate at installation and at the end (an open seal's a lower bound).
fn leak_rate_line(run: &SummaryRun) -> String {
    let floor = run.floor;
    let rate = |row: Option<&crate::simulate::HistoryRow>| match row {
        Some(r) if r.state == crate::simulate::SealState::LiftOff && floor.seals(r.leak_rate) => {
            "OPEN (the flow of an open seal is not modelled; the model's lower bound is ≈ 0)"
                .to_owned()
        }
        Some(r) if r.state == crate::simulate::SealState::LiftOff => format!(
            "≥ {} (OPEN: a lower bound, the flow of an open seal is not modelled)",
            floor.flow(r.leak_rate)
        ),
        Some(r) => floor.flow(r.leak_rate),
        None => floor.flow(0.0),
    };
    format!(
        "{} at installation, {} after {}",
        rate(run.result.rows.first()),
        rate(run.result.rows.last()),
        run.duration
    )
}

/// A gas's throughput through the interface at the mean pressure `p`, with the flow law; the
/// permeation through the rubber and the total, where computed.
fn gas_flow_lines(out: &mut SummaryText, run: &SummaryRun, p: f64) {
    let (problem, result, floor, duration) = (run.problem, run.result, run.floor, &run.duration);
    let sealed = result.course.max_leak_rate.0 == 0.0;
    let law = match result.continuum_leak_rate {
        _ if sealed => "sealed through the interface: no channel percolates".to_owned(),
        Some(c) if c > 0.0 && result.initial_leak_rate() > 0.0 => format!(
            "rarefied flow; the continuum law would give {} at installation: rarefaction ×{}",
            throughput(p * c),
            human(result.initial_leak_rate() / c, 3)
        ),
        Some(_) => "rarefied flow".to_owned(),
        None if problem.fluid.mean_free_path().is_some() => "rarefied flow".to_owned(),
        None => "continuum law".to_owned(),
    };
    out.line(
        "throughput",
        format!(
            "{} at installation, {} after {duration} ({law}{})",
            floored_throughput(floor, p, result.initial_leak_rate()),
            floored_throughput(floor, p, result.final_leak_rate()),
            if sealed {
                ""
            } else {
                "; see the Knudsen warnings"
            }
        ),
    );
    let permeation = |r: Option<&crate::simulate::HistoryRow>| r.and_then(|r| r.permeation);
    let (Some(first), Some(last)) = (
        permeation(result.rows.first()),
        permeation(result.rows.last()),
    ) else {
        return;
    };
    let lag = match (&problem.permeation, result.rows.last()) {
        (Some(s), Some(r)) => s.time_lag(r.temperature).map_or_else(
            || "time lag unknown: steady flow from installation, an upper bound".to_owned(),
            |lag| {
                format!(
                    "time lag {} s ({} h)",
                    human(lag, 3),
                    human(lag / 3600.0, 3)
                )
            },
        ),
        _ => String::new(),
    };
    let basis = problem
        .permeation
        .as_ref()
        .map_or_else(String::new, |s| format!("; {}", s.data.basis()));
    out.line(
        "permeation",
        format!(
            "{} at installation, {} after {duration} (through the rubber; {lag}{basis})",
            throughput(first),
            throughput(last)
        ),
    );
    out.line(
        "total",
        format!(
            "{} at installation, {} after {duration} (interface + permeation: what a \
             leak detector sees, and what max_leak_rate is compared with)",
            throughput(p * result.initial_leak_rate() + first),
            throughput(p * result.final_leak_rate() + last)
        ),
    );
}

/// The volume leaked over the run; "≥" when the seal was ever lifted off, where the model gives
/// only a lower bound of the flow (docs/model.md §8.1) — also when that bound is 0.
fn leaked_volume_line(run: &SummaryRun) -> String {
    let result = run.result;
    let volume = result.leaked_volume();
    let amount = format!("{} m³ ({} mL)", human(volume, 3), human(volume * 1e6, 3));
    if !result.leaked_volume_is_lower_bound() {
        return format!("{amount} in {}", run.duration);
    }
    let course = &result.course;
    let lifted = human_time(course.lifted_duration);
    let bound = if course.lifted_volume > 0.0 {
        format!(
            "{} mL of it while lifted off for {lifted}, where the model gives only a lower \
             bound of the flow",
            human(course.lifted_volume * 1e6, 3)
        )
    } else {
        format!(
            "lifted off for {lifted}, where the model's lower bound of the flow is 0: the \
             true volume is larger by an unknown amount"
        )
    };
    format!("≥ {amount} in {} (a lower bound: {bound})", run.duration)
}

/// How far the result moves at the neighbouring fidelity level (docs/model.md §4.1).
fn band_line(problem: &LifeProblem, result: &LifeResult, band: &LevelBand) -> String {
    let own = result.leaked_volume();
    let ratio = if own > 0.0 && band.leaked_volume > 0.0 {
        format!(" (×{} this level's)", human(band.leaked_volume / own, 2))
    } else {
        String::new()
    };
    let decided = if result.undecided() {
        "another outcome: UNDECIDED by the model"
    } else {
        "the same outcome: the model does not decide the verdict"
    };
    format!(
        "at {} (the neighbouring level): leaked volume {}{} m³{ratio}, highest leak rate {} \
         m³/s; {}; {decided}",
        band.level.name(),
        at_least(band.leaked_volume_is_lower_bound),
        human(band.leaked_volume, 3),
        human(band.maximum_leak_rate, 3),
        band_outcome_text(problem, band),
    )
}

/// "≥ " before a volume that is a lower bound (§8.1), nothing before one that is not.
fn at_least(lower_bound: bool) -> &'static str {
    if lower_bound { "≥ " } else { "" }
}

/// The retained fraction below which a force reads "≈ 0 (fully set)": e^{−K} at K ≈ 14, where
/// the first-order ageing law has long left its data (docs/model.md §15.2).
pub const FULLY_SET: f64 = 1e-6;

/// `"at installation"` or `"at 3.2 days"`.
fn at_time(t: f64) -> String {
    if t == 0.0 {
        "at installation".to_owned()
    } else {
        format!("at {}", human_time(t))
    }
}

/// `force / reference` (0 when the reference is not positive).
fn retained_fraction(force: f64, reference: f64) -> f64 {
    if reference > 0.0 {
        force / reference
    } else {
        0.0
    }
}

/// A speed for a reader: `"1 cm/s"`, `"0.1 m/s"`, `"6.1 mm/s"`.
fn speed(v: f64) -> String {
    if v == 0.0 {
        "0 m/s".to_owned()
    } else if v.abs() < 1e-3 {
        format!("{} µm/s", human(v * 1e6, 3))
    } else if v.abs() < 1e-2 {
        format!("{} mm/s", human(v * 1e3, 3))
    } else if v.abs() < 1.0 {
        format!("{} cm/s", human(v * 1e2, 3))
    } else {
        format!("{} m/s", human(v, 3))
    }
}

/// The motion line of the terminal summary.
fn motion_description(spec: &MotionSpec, m: &MotionSummary, duration: &str) -> String {
    let bound = match m.speed_bound_m_per_s {
        Some(b) if m.speed_above_bound => format!(
            "; EXCEEDS the speed bound of PY08 eq. 17 ({}, lowest over the run): lift-off not \
             modelled",
            speed(b)
        ),
        Some(b) => format!("; speed bound (PY08 eq. 17) {} or more", speed(b)),
        None => String::new(),
    };
    let film = format!(
        "film {} nm at installation, {} nm after {duration}",
        human(m.initial_film_thickness_m * 1e9, 3),
        human(m.final_film_thickness_m * 1e9, 3)
    );
    match (spec.motion, &m.initial_cycle, &m.final_cycle) {
        (
            Motion::Stroke {
                stroke,
                out_speed,
                in_speed,
            },
            Some(first @ CycleSummary { ihl: Some(a), .. }),
            Some(last @ CycleSummary { ihl: Some(b), .. }),
        ) => format!(
            "stroke {} mm, out at {}, in at {} (cycle {}), {} at installation: \
             inverse-hydrodynamic films h_out {} µm, h_in {} µm ({} gradients {}/{} MPa/mm, {}{}) \
             at installation, {} µm, {} µm after {duration}; net leak per cycle {} m³ at \
             installation, {} m³ after {duration}",
            human(stroke * 1e3, 4),
            speed(out_speed),
            speed(in_speed),
            human_time(spec.period().unwrap_or(0.0)),
            first.speed_regime,
            human(a.out_stroke_film_m * 1e6, 3),
            human(a.in_stroke_film_m * 1e6, 3),
            a.gradient_source,
            human(a.inlet_gradient_out_pa_per_m * 1e-9, 3),
            human(a.inlet_gradient_in_pa_per_m * 1e-9, 3),
            a.film_regime,
            if a.starved {
                ", in-stroke starved: all carried out is pumped back"
            } else {
                ""
            },
            human(b.out_stroke_film_m * 1e6, 3),
            human(b.in_stroke_film_m * 1e6, 3),
            human(first.net_volume_per_cycle_m3, 3),
            human(last.net_volume_per_cycle_m3, 3),
        ),
        (
            Motion::Stroke {
                stroke,
                out_speed,
                in_speed,
            },
            Some(first),
            Some(last),
        ) => format!(
            "stroke {} mm, out at {}, in at {} (cycle {}): a film of {} m³ carried out and \
             back per cycle at installation, {} m³ after {duration}; net leak per cycle {} m³ at \
             installation, {} m³ after {duration}; {film}{bound}",
            human(stroke * 1e3, 4),
            speed(out_speed),
            speed(in_speed),
            human_time(spec.period().unwrap_or(0.0)),
            human(first.drag_volume_per_stroke_m3, 3),
            human(last.drag_volume_per_stroke_m3, 3),
            human(first.net_volume_per_cycle_m3, 3),
            human(last.net_volume_per_cycle_m3, 3),
        ),
        _ => format!(
            "sliding at {}: drag {} at installation, {} after {duration} (included in the leak \
             rate); {film}{bound}",
            speed(spec.drag_speed()),
            flow(m.initial_drag_leak_rate_m3_per_s),
            flow(m.final_drag_leak_rate_m3_per_s),
        ),
    }
}

/// `"O-ring d = 3.53 mm, D = 50 mm, squeeze 20 %, displacement loading, asperity modulus relaxed"`.
fn seal_description(problem: &LifeProblem) -> String {
    let geometry = problem.geometry.describe(problem.thermal_strain.is_some());
    let asperity = match problem.asperity_modulus {
        AsperityModulus::Relaxed => "relaxed (E∞)".to_owned(),
        AsperityModulus::Instantaneous => "instantaneous (E0)".to_owned(),
        AsperityModulus::Follow => "follow (the bulk's relaxation)".to_owned(),
        AsperityModulus::Fixed(e) => format!("{} MPa", human(e / 1e6, 4)),
    };
    let gland = match &problem.gland {
        Some(g) => {
            let range = g.squeeze_range.map_or(String::new(), |(lo, hi)| {
                format!(
                    " (squeeze {}–{} % over the tolerances)",
                    human(lo * 100.0, 3),
                    human(hi * 100.0, 3)
                )
            });
            format!(
                ", {} gland{range}, extrusion gap {} mm, energisation k_e = {}",
                g.kind.name(),
                human(g.extrusion_gap * 1e3, 3),
                human(problem.energisation_factor, 3)
            )
        }
        None => String::new(),
    };
    let thermal = match problem.thermal_strain {
        Some(th) => format!(
            ", housing expansion {} 1/K from {}",
            human(th.housing_expansion, 3),
            celsius(th.installation_temperature)
        ),
        None => String::new(),
    };
    format!(
        "{geometry}{gland}, {} loading, asperity modulus {asperity}{thermal}",
        loading_name(problem.loading)
    )
}

/// Log–log chart of leak rate against time for one or more runs (zero rates and t = 0 are
/// not drawn).
pub fn leak_rate_chart<'a>(
    title: &str,
    runs: impl IntoIterator<Item = (&'a str, &'a LifeResult)>,
) -> LogLogChart {
    LogLogChart {
        title: title.to_owned(),
        x_label: "time [s]".into(),
        y_label: "leak rate [m³/s]".into(),
        series: runs
            .into_iter()
            .map(|(label, r)| Series {
                label: label.to_owned(),
                points: r.rows.iter().map(|row| (row.time, row.leak_rate)).collect(),
            })
            .collect(),
    }
}

/// Whether a chart of `results` would have anything to draw (a positive leak rate after t = 0).
pub fn has_positive_leak_rate<'a>(results: impl IntoIterator<Item = &'a LifeResult>) -> bool {
    results.into_iter().any(|r| {
        r.rows
            .iter()
            .any(|row| row.time > 0.0 && row.leak_rate > 0.0)
    })
}

/// Columns of the comparison CSV.
pub const COMPARE_COLUMNS: [&str; 8] = [
    "material",
    "name",
    "status",
    "time_to_failure_s",
    "failure_mode",
    "leak_rate_1day_m3_per_s",
    "leak_rate_1year_m3_per_s",
    "leak_rate_10years_m3_per_s",
];

/// The times of the comparison's leak-rate columns \[s\] with their labels.
pub const COMPARE_TIMES: [(f64, &str); 3] =
    [(DAY, "1 day"), (YEAR, "1 year"), (10.0 * YEAR, "10 years")];

/// One compound of a comparison.
#[derive(Debug, Clone)]
pub struct CompareRow<'a> {
    /// As given on the command line (library id or file path).
    pub label: &'a str,
    pub material: &'a Material,
    pub result: &'a LifeResult,
    /// Length of the run \[s\] (leak rates beyond it are blank).
    pub duration: f64,
    /// A gas: the mean pressure p̄ \[Pa\] whose volume flows the leak rates are; the
    /// comparison then gives throughputs `p̄ Q̇` too (docs/model.md §3.9).
    pub mean_pressure: Option<f64>,
    /// Leak rates below it read "≈ 0" in the text table (the CSV keeps them).
    pub floor: LeakFloor,
    /// What this compound's run left out for want of data (`compare` degrades rather than
    /// aborts: no ageing constants), "; "-separated; empty when nothing.
    pub notes: String,
    /// Where the compound's ageing activation energy comes from
    /// ([`crate::workflow::compare::ageing_source`]).
    pub ageing_source: String,
    /// A gas: the permeation figure's basis (sourced, derived, NOT SOURCED bound, user's).
    pub permeation_source: Option<String>,
    /// Its place in the listed order, 1 first ([`crate::workflow::compare::rank`]).
    pub rank: usize,
    /// Why it stands there ([`crate::workflow::compare::Standing::describe`]).
    pub rank_basis: String,
    /// The compound's rating for the run's medium with its source (docs/model.md §6.8);
    /// `None`: not rated.
    pub rating: Option<&'a crate::material::compatibility::Compatibility>,
}

impl<'a> CompareRow<'a> {
    /// The row of one compound's run of [`crate::workflow::compare`] at its `standing` in the
    /// ranking: its run length, mean pressure and notes from the run's own scenario; leak
    /// rates below `floor` \[m³/s\] (`--leak-floor`; `None`: one molecule a second) read "≈ 0".
    pub fn of(
        (run, standing): &'a (
            crate::workflow::compare::CompoundRun,
            crate::workflow::compare::Standing,
        ),
        floor: Option<f64>,
    ) -> Self {
        let life = &run.scenario.life;
        CompareRow {
            label: &run.label,
            material: &run.material,
            result: &run.result,
            duration: life.time.duration,
            mean_pressure: life.fluid.mean_pressure(),
            floor: LeakFloor::of(&life.fluid, floor),
            notes: crate::workflow::compare::notes(life, run.scenario.compatibility.as_ref()),
            ageing_source: crate::workflow::compare::ageing_source(life, &run.material),
            permeation_source: crate::workflow::compare::permeation_source(life),
            rank: standing.rank,
            rank_basis: standing.describe(),
            rating: run.scenario.compatibility.as_ref(),
        }
    }
}

/// The comparison's columns of the end of each run, after the leak rates (and throughputs).
pub const COMPARE_END_COLUMNS: [&str; 10] = [
    "sealing_force_end_N_per_m",
    "retained_force_end",
    "leaked_volume_end_m3",
    "leaked_volume_is_lower_bound",
    "compression_set_end",
    "state_end",
    "verdict",
    "neighbour_level",
    "neighbour_verdict",
    "notes",
];

/// The comparison's last columns: where each compound's ageing activation energy comes from,
/// and (a gas) its permeation figure's basis (docs/model.md §6.5, §13.4).
pub const COMPARE_SOURCE_COLUMNS: [&str; 2] = ["activation_energy_source", "permeation_source"];

/// The comparison's ranking columns, last: the rank in the listed order, its basis
/// (compatible, missing_figure, not_rated, incompatible, with the reason), the compound's
/// rating for the run's medium (A, B, X; blank: not rated) and the rating's source
/// (docs/model.md §6.8).
pub const COMPARE_RANK_COLUMNS: [&str; 4] = ["rank", "rank_basis", "rating", "rating_source"];

impl CompareRow<'_> {
    /// The run's verdict kind (`undecided` where the neighbouring level gives another outcome).
    fn verdict_kind(&self) -> VerdictKind {
        if self.result.undecided() {
            VerdictKind::Undecided
        } else {
            VerdictKind::of(self.result.outcome())
        }
    }

    /// The end of the run: sealing force \[N/m\], retained force (over the reference),
    /// leaked volume \[m³\], compression set, state.
    fn end(&self) -> (f64, f64, f64, Option<f64>, &'static str) {
        let last = self.result.rows.last();
        let force = last.map_or(0.0, |r| r.sealing_force);
        (
            force,
            if self.result.reference_force > 0.0 {
                force / self.result.reference_force
            } else {
                0.0
            },
            self.result.leaked_volume(),
            last.and_then(|r| r.compression_set),
            last.map_or("sealed", |r| r.state.as_str()),
        )
    }

    /// Leak rates at [`COMPARE_TIMES`], `None` beyond the run.
    fn leak_rates(&self) -> [Option<f64>; 3] {
        COMPARE_TIMES.map(|(t, _)| {
            (t <= self.duration)
                .then(|| self.result.leak_rate_at(t))
                .flatten()
        })
    }

    /// What a leak detector sees at [`COMPARE_TIMES`] (a gas: interface + permeation as the
    /// volume flow at p̄; a liquid: the leak rate), `None` beyond the run.
    fn detected_leak_rates(&self) -> [Option<f64>; 3] {
        COMPARE_TIMES.map(|(t, _)| {
            (t <= self.duration)
                .then(|| self.result.detected_leak_rate_at(t, self.mean_pressure))
                .flatten()
        })
    }
}

/// Columns the comparison CSV gets for a gas: the interface's throughputs `p̄ Q̇` at
/// [`COMPARE_TIMES`] \[Pa·m³/s\], then the total with the permeation through the rubber (what a
/// leak detector sees and `max_leak_rate` compares, §13.7).
pub const COMPARE_GAS_COLUMNS: [&str; 6] = [
    "throughput_1day_Pa_m3_per_s",
    "throughput_1year_Pa_m3_per_s",
    "throughput_10years_Pa_m3_per_s",
    "total_throughput_1day_Pa_m3_per_s",
    "total_throughput_1year_Pa_m3_per_s",
    "total_throughput_10years_Pa_m3_per_s",
];

/// The comparison as CSV, one row per compound ([`COMPARE_COLUMNS`], and for a gas
/// [`COMPARE_GAS_COLUMNS`]).
pub fn compare_table(rows: &[CompareRow<'_>]) -> Result<String, ReportError> {
    let mut writer = ::csv::Writer::from_writer(Vec::new());
    let gas = rows.first().and_then(|r| r.mean_pressure);
    let mut header: Vec<&str> = COMPARE_COLUMNS.to_vec();
    if gas.is_some() {
        header.extend(COMPARE_GAS_COLUMNS);
    }
    header.extend(COMPARE_END_COLUMNS);
    header.push(COMPARE_SOURCE_COLUMNS[0]);
    if gas.is_some() {
        header.push(COMPARE_SOURCE_COLUMNS[1]);
    }
    header.extend(COMPARE_RANK_COLUMNS);
    writer.write_record(&header).map_err(csv_error)?;
    for (i, r) in rows.iter().enumerate() {
        let row = i + 1;
        let optional = |column: usize, value: Option<f64>| {
            value.map_or(Ok(String::new()), |v| {
                number(row, COMPARE_COLUMNS[column], v)
            })
        };
        let [day, year, decade] = r.leak_rates();
        let mut record = vec![
            r.label.to_owned(),
            r.material.name.clone(),
            r.material.status.as_str().to_owned(),
            optional(3, r.result.failure.map(|f| f.time))?,
            failure_mode(r.result).to_owned(),
            optional(5, day)?,
            optional(6, year)?,
            optional(7, decade)?,
        ];
        if let Some(p) = r.mean_pressure {
            let detected = r.detected_leak_rates();
            for (k, q) in [day, year, decade].into_iter().chain(detected).enumerate() {
                record.push(q.map_or(Ok(String::new()), |q| {
                    number(row, COMPARE_GAS_COLUMNS[k], p * q)
                })?);
            }
        }
        let (force, retained, volume, set, state) = r.end();
        record.push(number(row, COMPARE_END_COLUMNS[0], force)?);
        record.push(number(row, COMPARE_END_COLUMNS[1], retained)?);
        record.push(number(row, COMPARE_END_COLUMNS[2], volume)?);
        record.push(r.result.leaked_volume_is_lower_bound().to_string());
        record.push(set.map_or(Ok(String::new()), |c| {
            number(row, COMPARE_END_COLUMNS[4], c)
        })?);
        record.push(state.to_owned());
        record.push(r.verdict_kind().as_str().to_owned());
        let band = r.result.band.as_ref();
        record.push(band.map_or("", |b| b.level.name()).to_owned());
        record.push(
            band.map_or("", |b| VerdictKind::of(b.outcome()).as_str())
                .to_owned(),
        );
        record.push(r.notes.clone());
        record.push(r.ageing_source.clone());
        if gas.is_some() {
            record.push(r.permeation_source.clone().unwrap_or_default());
        }
        record.push(r.rank.to_string());
        record.push(r.rank_basis.clone());
        record.push(
            r.rating
                .map_or(String::new(), |c| c.rating.letter().to_string()),
        );
        record.push(r.rating.map_or(String::new(), |c| c.source.clone()));
        writer.write_record(record).map_err(csv_error)?;
    }
    finish(writer)
}

/// One compound of the comparison's JSON ([`CompareSummary`]): its standing in the ranking,
/// its rating for the run's medium and the full run summary ([`Summary`]).
#[derive(Debug, Clone, Serialize)]
pub struct CompareEntry {
    /// The compound as given on the command line (library id or file path).
    pub material: String,
    /// Its place in the listed order, 1 first.
    pub rank: usize,
    /// `compatible`, `missing_figure`, `not_rated` or `incompatible`, with the reason.
    pub rank_basis: String,
    /// `A`, `B` or `X` for the run's medium; absent: not rated.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rating: Option<String>,
    /// The rating's source; absent: not rated.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rating_source: Option<String>,
    /// Where the ageing activation energy comes from.
    pub activation_energy_source: String,
    /// A gas: the permeation figure's basis.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub permeation_source: Option<String>,
    /// What the run left out for want of data ("; "-separated; empty when nothing).
    pub notes: String,
    /// The run's summary, as `sealsim run --summary` writes it (SI).
    pub summary: Summary,
}

/// The comparison as JSON (`sealsim compare --summary`): the headline, then the compounds in
/// the listed order, each with its rank, rank basis, rating and run summary (SI).
#[derive(Debug, Clone, Serialize)]
pub struct CompareSummary {
    /// The scenario's name.
    pub scenario: String,
    /// The scenario file, as given.
    pub scenario_file: String,
    /// The headline as printed (names only a compound rated A/B for the medium).
    pub headline: String,
    /// One entry per compound, in the listed order.
    pub compounds: Vec<CompareEntry>,
}

impl CompareSummary {
    /// The comparison of `runs` (ranked, [`crate::workflow::compare::rank`]) under
    /// `headline`, from the rows the table is made of.
    pub fn new(
        file: &str,
        headline: &str,
        runs: &[(
            crate::workflow::compare::CompoundRun,
            crate::workflow::compare::Standing,
        )],
        rows: &[CompareRow<'_>],
    ) -> Self {
        let compounds = runs
            .iter()
            .zip(rows)
            .map(|((run, _), row)| CompareEntry {
                material: row.label.to_owned(),
                rank: row.rank,
                rank_basis: row.rank_basis.clone(),
                rating: row.rating.map(|c| c.rating.letter().to_string()),
                rating_source: row.rating.map(|c| c.source.clone()),
                activation_energy_source: row.ageing_source.clone(),
                permeation_source: row.permeation_source.clone(),
                notes: row.notes.clone(),
                summary: Summary::new(&run.scenario.name, file, &run.scenario.life, &run.result),
            })
            .collect();
        CompareSummary {
            scenario: runs
                .first()
                .map_or(String::new(), |(r, _)| r.scenario.name.clone()),
            scenario_file: file.to_owned(),
            headline: headline.to_owned(),
            compounds,
        }
    }

    /// Pretty-printed JSON with a final newline; every compound's numbers checked to be
    /// finite ([`Summary::to_json`]).
    pub fn to_json(&self) -> Result<String, ReportError> {
        for entry in &self.compounds {
            entry.summary.to_json()?;
        }
        let mut text =
            serde_json::to_string_pretty(self).map_err(|e| ReportError::Csv(e.to_string()))?;
        text.push('\n');
        Ok(text)
    }
}

/// The comparison as an aligned text table for the terminal (a gas: throughputs in Pa·m³/s).
pub fn compare_text(rows: &[CompareRow<'_>]) -> String {
    let cells = compare_cells(rows);
    let columns = cells[0].len();
    let width: Vec<usize> = (0..columns)
        .map(|c| {
            cells
                .iter()
                .filter(|r| r.len() == columns)
                .map(|r| r[c].chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = String::new();
    for row in &cells {
        let line: Vec<String> = row
            .iter()
            .zip(&width)
            .map(|(cell, w)| {
                format!(
                    "{cell}{}",
                    " ".repeat(w.saturating_sub(cell.chars().count()))
                )
            })
            .collect();
        out += line.join("  ").trim_end();
        out.push('\n');
    }
    out
}

/// The comparison's cells for people: the header, one row per compound, and a one-cell note on
/// the floor.
pub fn compare_cells(rows: &[CompareRow<'_>]) -> Vec<Vec<String>> {
    let unit = match rows.first().and_then(|r| r.mean_pressure) {
        Some(_) => "Pa·m³/s",
        None => "m³/s",
    };
    let mut cells: Vec<Vec<String>> = vec![vec![
        "rank".to_owned(),
        "material".to_owned(),
        "rating".to_owned(),
        "rank basis".to_owned(),
        "status".to_owned(),
        "time to failure".to_owned(),
        "mode".to_owned(),
        format!("Q 1 day [{unit}]"),
        format!("Q 1 year [{unit}]"),
        format!("Q 10 years [{unit}]"),
        "force at end [N/mm]".to_owned(),
        "retained".to_owned(),
        "leaked [mL]".to_owned(),
        "set".to_owned(),
        "state at end".to_owned(),
        "notes".to_owned(),
        "ageing Ea: source".to_owned(),
    ]];
    if rows.first().is_some_and(|r| r.mean_pressure.is_some()) {
        cells[0].push("permeation: basis".to_owned());
    }
    for r in rows {
        let scale = r.mean_pressure.unwrap_or(1.0);
        let rate = |q: Option<f64>| {
            q.map_or_else(
                || "-".to_owned(),
                |q| {
                    if r.floor.seals(q) {
                        "≈ 0".to_owned()
                    } else {
                        human(scale * q, 2)
                    }
                },
            )
        };
        let [day, year, decade] = r.detected_leak_rates();
        let (force, retained, volume, set, state) = r.end();
        cells.push(vec![
            r.rank.to_string(),
            r.label.to_owned(),
            r.rating
                .map_or_else(|| "-".to_owned(), |c| c.rating.letter().to_string()),
            // the basis word; the reason is in the notes (a rating) or the CSV
            r.rank_basis
                .split(" (")
                .next()
                .unwrap_or_default()
                .replace('_', " ")
                + if r.rank_basis.contains("NOT SOURCED") {
                    " (NOT SOURCED bound)"
                } else {
                    ""
                },
            r.material.status.as_str().to_owned(),
            format!(
                "{}{}",
                if r.result.undecided() {
                    "UNDECIDED: "
                } else {
                    ""
                },
                match (r.result.failure, r.result.open_since()) {
                    (Some(f), _) if f.time == 0.0 => "at installation".to_owned(),
                    (Some(f), _) => human_time(f.time),
                    // a waived lift-off: never "survives"
                    (None, Some(_)) => "OPEN (not counted)".to_owned(),
                    (None, None) => "survives".to_owned(),
                }
            ),
            failure_mode(r.result).to_owned(),
            rate(day),
            rate(year),
            rate(decade),
            // below a µN/mm and a millionth: nothing left, not a number to read
            if force < 1e-3 {
                "< 1e-6".to_owned()
            } else {
                human(force / 1e3, 2)
            },
            if retained < 1e-6 {
                "< 1e-4 %".to_owned()
            } else {
                format!("{} %", human(100.0 * retained, 2))
            },
            format!(
                "{}{}",
                at_least(r.result.leaked_volume_is_lower_bound()),
                human(volume * 1e6, 2)
            ),
            set.map_or_else(|| "-".to_owned(), |c| format!("{} %", human(100.0 * c, 2))),
            state.to_owned(),
            r.notes.clone(),
            r.ageing_source.clone(),
        ]);
        if let Some(p) = &r.permeation_source
            && let Some(row) = cells.last_mut()
        {
            row.push(p.clone());
        }
    }
    if rows.first().is_some_and(|r| r.mean_pressure.is_some()) {
        cells.push(vec![
            "(a gas: Q is the interface's throughput plus the permeation through the rubber, what a \
             leak detector sees and max_leak_rate compares)"
                .to_owned(),
        ]);
    }
    if let Some(f) = rows.first().map(|r| r.floor) {
        cells.push(vec![format!(
            "(\"≈ 0\": below {} m³/s, {}; the CSV keeps the values)",
            human(f.rate, 2),
            f.meaning()
        )]);
    }
    cells
}

/// The comparison's headline (`sealsim compare`, its HTML report, `sealsim.compare`): among the compatible compounds of the best rating present (A,
/// else B), the one(s) with the longest life (every one tied at it); when no compound is
/// compatible, a plain statement that none is, never an unsuitable compound. Independent of
/// the listed order (`--all`).
pub fn compare_headline(
    ranked: &[(
        crate::workflow::compare::CompoundRun,
        crate::workflow::compare::Standing,
    )],
) -> String {
    use crate::workflow::compare::{RankBasis, life, medium};
    let Some((first, _)) = ranked.first() else {
        return String::new();
    };
    let medium = medium(first);
    let tier = ranked
        .iter()
        .filter(|(_, s)| s.basis == RankBasis::Compatible)
        .map(|(_, s)| s.tier)
        .min();
    let compatible: Vec<&crate::workflow::compare::CompoundRun> = ranked
        .iter()
        .filter(|(_, s)| s.basis == RankBasis::Compatible && Some(s.tier) == tier)
        .map(|(r, _)| r)
        .collect();
    let Some(best) = compatible.iter().map(|r| life(r)).reduce(f64::max) else {
        let why = match first.scenario.fluid_class {
            None => "the ratings cover mineral oil, water, hot water and water–glycol only",
            // rated ones run without a figure their verdict needs count as not compatible
            Some(_) => "or none has every figure its verdict needs",
        };
        return format!(
            "No compound in this comparison is rated A/B for {medium} ({why}): no longest life \
             to headline; see each row's rank basis"
        );
    };
    let names: Vec<&str> = compatible
        .iter()
        .filter(|r| life(r) == best)
        .map(|r| r.label.as_str())
        .collect();
    let when = if best.is_finite() {
        format!("fails after {}", human_time(best))
    } else {
        "no failure within the run".to_owned()
    };
    let rated = if tier == Some(0) {
        "A (recommended)"
    } else {
        "B (limited; none is rated A)"
    };
    format!(
        "Longest life among the compounds rated {rated} for {medium}: {} ({when})",
        names.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulate::{FailureEvent, FailureMode, HistoryRow, SealState};

    fn row(time: f64, leak_rate: f64, shift_factor: f64, u_c: Option<f64>) -> HistoryRow {
        HistoryRow {
            time,
            temperature: 353.15,
            reduced_time: time * 10.0,
            shift_factor,
            sealing_force: 1000.0,
            peak_pressure: 2e6,
            mean_pressure: 1.5e6,
            pressure_difference: 1e6,
            contact_width: 1e-3,
            u_c,
            leak_rate,
            permeation: None,
            leaked_volume: leak_rate * time,
            open_fraction: 1.0,
            compression_set: None,
            shutdown: None,
            motion: None,
            state: if u_c.is_some() {
                SealState::Leaking
            } else {
                SealState::Sealed
            },
        }
    }

    fn result(rows: Vec<HistoryRow>) -> LifeResult {
        LifeResult {
            course: crate::simulate::Course::from_rows(&rows),
            band: None,
            rows,
            failure: Some(FailureEvent {
                time: 2.5 * YEAR,
                mode: FailureMode::LeakRate,
            }),
            findings: Default::default(),
            reference_force: 1000.0,
            continuum_leak_rate: None,
            permeation_status: None,
        }
    }

    #[test]
    fn history_cells_are_round_trip_and_blank_when_undefined() {
        let r = result(vec![
            row(0.0, 1e-12, 0.1, Some(2e-7)),
            row(10.0, 0.0, f64::INFINITY, None),
        ]);
        let text = history_table(&r).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], HISTORY_COLUMNS.join(","));
        assert_eq!(
            lines[1],
            "0e0,3.5315e2,0e0,1e-1,1e3,2e6,1.5e6,1e-3,2e-7,1e-12,0e0,leaking,1e0,,"
        );
        assert_eq!(
            lines[2],
            "1e1,3.5315e2,1e2,,1e3,2e6,1.5e6,1e-3,,0e0,0e0,sealed,1e0,,"
        );
        let bad = result(vec![row(0.0, f64::NAN, 1.0, None)]);
        assert!(matches!(
            history_table(&bad),
            Err(ReportError::NonFinite {
                column: "leak_rate_m3_per_s",
                ..
            })
        ));
    }

    #[test]
    fn motion_adds_its_history_columns_only_when_present() {
        use crate::dynamic::{MotionPoint, StrokeCycle};
        let steady = MotionPoint {
            drag_leak_rate: 4e-11,
            film_thickness: 8e-9,
            speed_bound: 6e-3,
            above_bound: false,
            cycle: None,
            ihl: None,
            ihl_weights: (0.0, 0.0),
            regime: crate::dynamic::ihl::SpeedRegime::NoProfile,
        };
        let mut rows = vec![
            row(0.0, 1e-12, 0.1, Some(2e-7)),
            row(10.0, 2e-12, 0.1, Some(2e-7)),
        ];
        for r in &mut rows {
            r.motion = Some(steady);
        }
        let text = history_table(&result(rows.clone())).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            format!("{},drag_leak_rate_m3_per_s", HISTORY_COLUMNS.join(","))
        );
        assert!(lines[1].ends_with(",leaking,1e0,,,4e-11"), "{}", lines[1]);
        let cycle = StrokeCycle {
            period: 2.0,
            out_volume: 1e-12,
            in_volume: -0.5e-12,
            net_volume: 0.5e-12,
            static_volume: 0.5e-12,
            drag_volume: 0.75e-12,
            within_speed_bound: true,
        };
        for r in &mut rows {
            r.motion = Some(MotionPoint {
                cycle: Some(cycle),
                ..steady
            });
        }
        let text = history_table(&result(rows)).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            format!(
                "{},{}",
                HISTORY_COLUMNS.join(","),
                MOTION_HISTORY_COLUMNS.join(",")
            )
        );
        assert!(
            lines[2].ends_with(",leaking,1e0,,,4e-11,5e-13,,,low_speed_no_profile"),
            "{}",
            lines[2]
        );
    }

    #[test]
    fn human_times_pick_the_reader_unit() {
        assert_eq!(human_time(45.0), "45 s");
        assert_eq!(human_time(750.0), "12.5 min");
        assert_eq!(human_time(5.0 * 3600.0), "5 h");
        assert_eq!(human_time(3.2 * DAY), "3.2 days");
        assert_eq!(human_time(17.4 * YEAR), "17.4 years");
        assert_eq!(human_time(0.0), "0 s");
    }

    #[test]
    fn compare_leaves_times_beyond_the_run_blank() {
        let r = result(vec![
            row(0.0, 1e-12, 1.0, Some(1e-7)),
            row(2.0 * DAY, 1e-12, 1.0, Some(1e-7)),
        ]);
        let m = Material::elastic("rubber", 1e7, 0.5).unwrap();
        let rows = [CompareRow {
            label: "x",
            material: &m,
            result: &r,
            duration: 2.0 * DAY,
            mean_pressure: None,
            floor: LeakFloor {
                rate: 1e-20,
                given: true,
            },
            notes: String::new(),
            ageing_source: "no ageing constants".into(),
            permeation_source: None,
            rank: 1,
            rank_basis: "compatible".into(),
            rating: None,
        }];
        let text = compare_table(&rows).unwrap();
        let line = text.lines().nth(1).unwrap();
        // the end-of-run columns: force 1000 N/m, retained 1, the leaked volume (checked
        // against the closed form Q̇ t below), no compression set, leaking
        let volume_cell =
            |line: &str, k: usize| -> f64 { line.split(',').nth(k).unwrap().parse().unwrap() };
        let (head, tail) = line.rsplit_once(",,leaking,").unwrap();
        // verdict, no band (neighbour level and verdict blank), no notes, the Ea source
        // then the rank, its basis, no rating, no rating source
        assert_eq!(tail, "fails,,,,no ageing constants,1,compatible,,");
        assert!(
            head.starts_with("x,rubber,user,7.8894e7,leak_rate,1e-12,,,1e3,1e0,"),
            "{line}"
        );
        assert!((volume_cell(line, 10) / (1e-12 * 2.0 * DAY) - 1.0).abs() < 1e-12);
        assert!(compare_text(&rows).contains("2.5 years"));
        // a gas at p̄ = 1.5 bar: the throughputs p̄ Q̇ after the volume flows (a format test)
        let gas = [CompareRow {
            mean_pressure: Some(1.5e5),
            permeation_source: Some("NOT SOURCED bound: x".into()),
            ..rows[0].clone()
        }];
        let text = compare_table(&gas).unwrap();
        assert!(text.lines().next().unwrap().ends_with(
            ",throughput_1day_Pa_m3_per_s,throughput_1year_Pa_m3_per_s,\
             throughput_10years_Pa_m3_per_s,total_throughput_1day_Pa_m3_per_s,\
             total_throughput_1year_Pa_m3_per_s,total_throughput_10years_Pa_m3_per_s,\
             sealing_force_end_N_per_m,retained_force_end,leaked_volume_end_m3,\
             leaked_volume_is_lower_bound,compression_set_end,state_end,verdict,neighbour_level,\
             neighbour_verdict,notes,activation_energy_source,permeation_source,rank,rank_basis,\
             rating,rating_source"
        ));
        let line = text.lines().nth(1).unwrap();
        assert!(
            line.starts_with("x,rubber,user,7.8894e7,leak_rate,1e-12,,,1.5e-7,,,1.5e-7,,,1e3,1e0,"),
            "{line}"
        );
        assert!(
            line.ends_with(
                ",,leaking,fails,,,,no ageing constants,NOT SOURCED bound: x,1,compatible,,"
            ),
            "{line}"
        );
        assert!((volume_cell(line, 16) / (1e-12 * 2.0 * DAY) - 1.0).abs() < 1e-12);
        assert!(compare_text(&gas).contains("Q 1 day [Pa·m³/s]"));
    }
}
