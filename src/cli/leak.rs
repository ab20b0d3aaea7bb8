//! `sealsim leak`: leak rate of a flat seal at one or more nominal pressures, as CSV.

use super::{CliError, print_findings, print_scenario_warnings, progress_bar, write_output};
use crate::leak::Fidelity;
use crate::math::log_spaced;
use crate::report::csv::{leak_outcome_table, pressure_difference_table};
use crate::scenario::Scenario;
use crate::units::{self, Dimension};
use crate::workflow;
use clap::Args;
use std::path::PathBuf;

/// Default number of points of `--sweep`.
const DEFAULT_SWEEP_POINTS: u32 = 20;
/// Upper limit of `--points` (a guard against typos that would exhaust memory).
const MAX_SWEEP_POINTS: i64 = 1_000_000;

/// Arguments of `sealsim leak`.
#[derive(Debug, Clone, Args)]
#[command(group(clap::ArgGroup::new("sweeps").args(["sweep", "pressure_difference_sweep"])))]
#[command(
    after_help = "Two kinds of pressure: --contact-pressures (alias --pressures) and --sweep give the \
    CONTACT pressure (a flat seal's nominal pressure P0, an O-ring's peak contact pressure); \
    --pressure-differences and --pressure-difference-sweep give the FLUID pressure difference ΔP \
    (\"at 50 bar and 210 bar of oil\"), each row the installed seal at that ΔP as `sealsim run` \
    starts from it, with the columns pressure_difference_Pa, extrudes (yes|no at installation, \
    blank without a gland) and contact_pressure_Pa before zeta_c; a pressure history is not \
    applied. Without either: the scenario's own state.\n\
    Pressures need their units (\"0.2 MPa\", \"2bar\", \"30psi\"): a bare number is \
    refused.\n\
    Output columns: nominal_pressure_Pa, zeta_c, lambda_c_m, u_c_m, ubar_c_m, hrms_c_m, \
    leak_rate_m3_per_s, state (leaking|sealed|lift_off), area_fraction, mean_gap_m; lambda_c = \
    2π/(zeta_c q0); area_fraction (A/A0) and mean_gap_m (ū) are the interface at full \
    magnification at the nominal pressure (Persson's theory at the analytic levels, the \
    boundary-element ensemble means at the numerical level; blank for an O-ring). The fluid \
    pressure inside the interface relieves the asperities (docs/model.md §3.6); a flat seal lifts \
    off when ΔP reaches its nominal pressure.\n\
    An O-ring scenario is evaluated in the state `sealsim run` starts from: its installed Hertz \
    profile plus the energisation k_e ΔP of a groove-seated ring, with the fluid pressure inside \
    the interface, along the counterface and, in a gland, the groove bottom in parallel; a \
    pressure is the peak contact pressure (with k_e ΔP), and the junction columns are the \
    counterface's at that peak less the fluid pressure there.\n\
    With --fidelity effective-medium, u_c_m is the effective gap (12 η σ_eff)^(1/3) and the other \
    junction columns are the critical junction's at the same pressure; with rule-of-thumb, \
    u_c_m = ubar_c_m = hrms_c_m (the level computes no separation).\n\
    With [motion] (a reciprocating seal, PY08 §8) the columns drag_leak_rate_m3_per_s (the drag \
    L_y d v at the sliding speed, or at the out-stroke speed of a stroke cycle), film_thickness_m \
    (the film d = β u_c the countersurface carries out, PY08 eq. 16) and speed_bound_m_per_s (the \
    validity bound of PY08's second eq. 17; blank when sealed) follow mean_gap_m, and for a stroke \
    cycle out_stroke_volume_m3, in_stroke_volume_m3 and net_volume_per_cycle_m3 (one cycle's \
    volumes, positive from the pressurised side to the outside), cycle_mean_leak_rate_m3_per_s, \
    out_stroke_film_m and in_stroke_film_m (the inverse-hydrodynamic films h* = √(8ηv/(9w)) of \
    a rod seal, docs/model.md §3.4.1), film_parameter (h*/σ), speed_regime and film_regime. With \
    constant sliding leak_rate_m3_per_s is static + drag; with a stroke cycle it stays the static \
    rate in the low-speed regime (the drag volumes cancel over a cycle in the linear theory) and \
    is the cycle-averaged net leak once the inverse-hydrodynamic film has weight. The drag always uses the exact critical \
    junction and Persson's P(u) (the theory of PY08 §8 is built on the critical junction), \
    whatever --fidelity; a warning reports a speed above the bound (hydrodynamic lift-off is not \
    modelled)."
)]
pub struct LeakArgs {
    /// Scenario file (TOML).
    #[arg(value_name = "SCENARIO")]
    pub scenario: PathBuf,

    /// Comma-separated CONTACT pressures: a flat seal's nominal pressure, an O-ring's peak
    /// contact pressure with k_e ΔP (default: the scenario's own). Not the fluid pressure: for
    /// "at 50 bar of oil" use --pressure-differences.
    // allow_hyphen_values: a negative pressure reaches parse_pressure (and its message)
    // instead of being read as an option
    #[arg(long, visible_alias = "pressures", value_name = "P,...", value_delimiter = ',',
          value_parser = parse_pressure, allow_hyphen_values = true)]
    pub contact_pressures: Option<Vec<f64>>,

    /// Log-spaced contact pressures from A to B inclusive, e.g. 0.05MPa..1MPa.
    #[arg(long, value_name = "A..B", value_parser = parse_sweep,
          conflicts_with = "contact_pressures", allow_hyphen_values = true)]
    pub sweep: Option<Sweep>,

    /// Comma-separated FLUID pressure differences ΔP across the seal, e.g. "50 bar, 210 bar":
    /// the installed seal at its own squeeze evaluated at each ΔP (energisation, the profile's
    /// strips, lift-off by the fluid pressure), the first row of `sealsim run` with
    /// fluid.pressure_difference = ΔP.
    #[arg(long, value_name = "ΔP,...", value_delimiter = ',', value_parser = parse_difference,
          conflicts_with_all = ["contact_pressures", "sweep"], allow_hyphen_values = true)]
    pub pressure_differences: Option<Vec<f64>>,

    /// Log-spaced fluid pressure differences from A to B inclusive, e.g. 10bar..300bar (as
    /// --pressure-differences).
    #[arg(long, value_name = "A..B", value_parser = parse_sweep,
          conflicts_with_all = ["contact_pressures", "sweep", "pressure_differences"],
          allow_hyphen_values = true)]
    pub pressure_difference_sweep: Option<Sweep>,

    /// Number of points of --sweep or --pressure-difference-sweep (default: 20).
    #[arg(long, value_name = "N", requires = "sweeps", allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(2..=MAX_SWEEP_POINTS))]
    pub points: Option<u32>,

    /// Fidelity level (default: the scenario's simulation.fidelity, else critical-junction).
    #[arg(long, value_name = "LEVEL", value_parser = super::FidelityArg)]
    pub fidelity: Option<Fidelity>,

    /// Print every warning in full (not its one line) and the notes (how inputs were read:
    /// a callout's spectrum, the compound's rating for the fluid).
    #[arg(short, long)]
    pub verbose: bool,

    /// Write the CSV to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// `--sweep A..B`: pressures in Pa with `0 < from < to`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sweep {
    pub from: f64,
    pub to: f64,
}

impl Sweep {
    /// `points` log-spaced pressures from `from` to `to`, both included.
    pub fn pressures(&self, points: u32) -> Vec<f64> {
        log_spaced(self.from, self.to, points as usize)
    }
}

/// A positive nominal pressure with its unit: "0.2 MPa", "2bar" (a bare number is refused:
/// 200000 is Pa to a parser and bar to a reader).
fn parse_pressure(text: &str) -> Result<f64, String> {
    let text = text.trim();
    let value = match text.parse::<f64>() {
        Ok(v) => return Err(Dimension::PRESSURE.bare_number_fix(v)),
        Err(_) => units::parse_quantity(text, Dimension::PRESSURE).map_err(|e| e.to_string())?,
    };
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(format!(
            "a nominal pressure must be positive and finite, got {} Pa",
            units::show(value)
        ))
    }
}

/// A fluid pressure difference ΔP ≥ 0 with its unit ("210 bar"; a bare number is refused).
fn parse_difference(text: &str) -> Result<f64, String> {
    let text = text.trim();
    let value = match text.parse::<f64>() {
        Ok(v) => return Err(Dimension::PRESSURE.bare_number_fix(v)),
        Err(_) => units::parse_quantity(text, Dimension::PRESSURE).map_err(|e| e.to_string())?,
    };
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(format!(
            "a pressure difference must be at least 0 and finite, got {} Pa",
            units::show(value)
        ))
    }
}

/// `A..B` with `0 < A < B`.
fn parse_sweep(text: &str) -> Result<Sweep, String> {
    let (a, b) = text
        .split_once("..")
        .ok_or_else(|| format!("expected A..B (e.g. 0.05MPa..1MPa), got {text:?}"))?;
    let (from, to) = (parse_pressure(a)?, parse_pressure(b)?);
    if to > from {
        Ok(Sweep { from, to })
    } else {
        Err(format!(
            "the end of the sweep must exceed its start, got {} Pa..{} Pa",
            units::show(from),
            units::show(to)
        ))
    }
}

/// Runs `sealsim leak`.
pub fn run(args: LeakArgs) -> Result<(), CliError> {
    super::set_verbose(args.verbose);
    let scenario = Scenario::load(&args.scenario)?;
    let inputs: Vec<&std::path::Path> = std::iter::once(args.scenario.as_path())
        .chain(scenario.inputs.iter().map(std::path::PathBuf::as_path))
        .collect();
    super::guard_outputs(&inputs, &[("-o", args.output.as_deref())])?;
    if let Some(path) = args.output.as_deref() {
        super::expect_extension("-o", path, &["csv"])?;
    }
    let points = args.points.unwrap_or(DEFAULT_SWEEP_POINTS);
    let differences = match (&args.pressure_differences, args.pressure_difference_sweep) {
        (Some(list), _) => Some(list.clone()),
        (None, Some(sweep)) => Some(sweep.pressures(points)),
        (None, None) => None,
    };
    if let Some(differences) = differences {
        return run_differences(&args, &scenario, &differences);
    }
    let pressures = match (&args.contact_pressures, args.sweep) {
        (Some(list), _) => Some(list.clone()),
        (None, Some(sweep)) => Some(sweep.pressures(points)),
        (None, None) => None,
    };
    let fidelity = args.fidelity.unwrap_or(scenario.life.fidelity);
    let outcome = workflow::leak::evaluate(
        &scenario,
        pressures.as_deref(),
        fidelity,
        &mut progress_bar("numerical level"),
    );
    let csv = leak_outcome_table(&outcome, scenario.life.fluid.mean_pressure())?;
    print_scenario_warnings(None, &scenario);
    print_findings(None, &outcome.findings);
    if let Some(note) = workflow::leak::oring_state_note(&scenario, pressures.is_some()) {
        eprintln!("note: {note}");
    }
    gas_note(&scenario);
    write_output(args.output.as_deref(), csv.as_bytes())
}

/// `sealsim leak --pressure-differences`: one row per fluid ΔP.
fn run_differences(
    args: &LeakArgs,
    scenario: &Scenario,
    differences: &[f64],
) -> Result<(), CliError> {
    let fidelity = args.fidelity.unwrap_or(scenario.life.fidelity);
    let (rows, findings) = workflow::leak::at_pressure_differences(
        scenario,
        differences,
        fidelity,
        &mut progress_bar("numerical level"),
    );
    let csv = pressure_difference_table(&rows)?;
    print_scenario_warnings(None, scenario);
    print_findings(None, &findings);
    if scenario.life.pressure.is_some() {
        eprintln!(
            "note: each row holds its ΔP constant: the scenario's pressure history is not applied"
        );
    }
    gas_note(scenario);
    write_output(args.output.as_deref(), csv.as_bytes())
}

/// A gas's throughput columns are the interface's only.
fn gas_note(scenario: &Scenario) {
    if scenario.life.fluid.gas.is_some() {
        eprintln!(
            "note: the throughput columns are the flow through the interface only; permeation \
             through the rubber is not in them (`sealsim run` adds it where the compound has \
             permeation data: permeation_Pa_m3_per_s) [docs/model.md §3.9, §13.7]"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweeps_are_log_spaced_and_inclusive() {
        let p = Sweep { from: 5e4, to: 1e6 }.pressures(20);
        assert_eq!(p.len(), 20);
        assert_eq!((p[0], p[19]), (5e4, 1e6));
        let r = p[1] / p[0];
        assert!(p.windows(2).all(|w| (w[1] / w[0] / r - 1.0).abs() < 1e-12));
    }

    #[test]
    fn pressures_take_units_or_pascals() {
        assert_eq!(parse_pressure("0.2 MPa"), Ok(2e5));
        assert!(
            parse_pressure(" 2e5 ")
                .unwrap_err()
                .contains("needs its unit")
        );
        assert!(parse_pressure("10 m").is_err());
        assert!(parse_pressure("-1 MPa").is_err());
        assert!(parse_pressure("0").is_err());
        assert_eq!(
            parse_sweep("0.05MPa..1MPa"),
            Ok(Sweep { from: 5e4, to: 1e6 })
        );
        assert!(parse_sweep("1MPa..0.05MPa").is_err());
        assert!(parse_sweep("1MPa").is_err());
    }
}
