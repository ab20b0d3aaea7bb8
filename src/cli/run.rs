//! `sealsim run`: the seal-life simulation of one scenario — the history of sealing force,
//! contact and leak rate over the seal's life, and when (and how) it fails.
//!
//! A readable summary always goes to standard output and the run's validity warnings to
//! standard error (`warning: …`); the history CSV (`-o`), the summary JSON (`--summary`) and
//! the leak-rate chart (`--plot`) are written only when asked for, each atomically, and only
//! after the whole run has succeeded (on bad input nothing is written).

use super::{CliError, print_findings, print_scenario_warnings, progress_bar, write_output};
use crate::leak::Fidelity;
use crate::report::life::{
    Summary, has_positive_leak_rate, history_table_for, human_summary, leak_rate_chart,
};
use crate::scenario::Scenario;
use crate::simulate::LifeResult;
use crate::workflow;
use clap::Args;
use std::path::PathBuf;

/// Arguments of `sealsim run`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "History columns (CSV, SI units): time_s, temperature_K, reduced_time_s, \
    shift_factor (blank when frozen), sealing_force_N_per_m, peak_pressure_Pa, mean_pressure_Pa, \
    contact_width_m, u_c_m (blank when sealed at the peak), leak_rate_m3_per_s, \
    leaked_volume_m3, state (leaking|sealed|lift_off), open_fraction (open fraction of the critical channels under particle clogging; 1 without [contamination]). The first row is the installation, t = 0.\n\
    An O-ring's leak rate is integrated over its Hertz profile as strips in series; `sealsim \
    leak` on the same scenario evaluates the same installed state (the first row).\n\
    With [motion] (a reciprocating seal, PY08 §8) the history gets drag_leak_rate_m3_per_s, the \
    drag L_y d v of the peak strip's film d = β u_c (the most compressed strip holds the critical \
    junction): with constant sliding it is included in leak_rate_m3_per_s (hence in the leaked \
    volume and the failure criteria); with a stroke cycle it is the out-stroke's drag and the \
    leak rate stays static in the low-speed regime (the drag volumes cancel over a cycle in the \
    linear theory) and is the cycle-averaged net leak once a rod seal's inverse-hydrodynamic \
    film has weight (docs/model.md §3.4.1); net_volume_per_cycle_m3, out_stroke_film_m, \
    in_stroke_film_m and speed_regime follow. The summary JSON gets a \"motion\" object (drag and film at \
    installation and at the end, the lowest speed bound of PY08 eq. 17, speed_above_bound, and \
    for a stroke cycle the volumes of one cycle at installation and at the end, with an \"ihl\" \
    object: gradients, films, carried and returned volumes, starvation, film parameter); a \
    speed above the bound without inlet gradients is a warning (lift-off not modelled), a speed \
    in the blend band too."
)]
pub struct RunArgs {
    /// Scenario file (TOML).
    #[arg(value_name = "SCENARIO")]
    pub scenario: PathBuf,

    /// Write the history CSV to FILE (atomically); without it no history is written.
    #[arg(short, long, value_name = "FILE.csv")]
    pub output: Option<PathBuf>,

    /// Write the summary as JSON to FILE (atomically).
    #[arg(long, value_name = "FILE.json")]
    pub summary: Option<PathBuf>,

    /// Write a log–log chart of the leak rate against time to FILE (SVG).
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,

    /// Override the scenario's simulation.fidelity.
    #[arg(long, value_name = "LEVEL", value_enum)]
    pub fidelity: Option<Fidelity>,
}

/// Runs `sealsim run`.
pub fn run(args: RunArgs) -> Result<(), CliError> {
    let mut scenario = Scenario::load(&args.scenario)?;
    if let Some(fidelity) = args.fidelity {
        scenario.life.fidelity = fidelity;
    }
    let result = workflow::life::run(&scenario, &mut progress_bar("numerical level"));
    let file = args.scenario.display().to_string();

    // Everything is rendered before anything is written.
    let csv = args
        .output
        .as_ref()
        .map(|_| history_table_for(&result, &scenario.life.fluid))
        .transpose()?;
    let json = args
        .summary
        .as_ref()
        .map(|_| Summary::new(&scenario.name, &file, &scenario.life, &result).to_json())
        .transpose()?;
    let svg = match &args.plot {
        Some(path) => plot(&scenario.name, &result, path)?,
        None => None,
    };

    print_scenario_warnings(None, &scenario);
    print_findings(None, &result.findings);
    for (path, bytes) in [
        (&args.output, csv.as_deref()),
        (&args.summary, json.as_deref()),
        (&args.plot, svg.as_deref()),
    ] {
        if let (Some(path), Some(bytes)) = (path, bytes) {
            write_output(Some(path), bytes.as_bytes())?;
        }
    }
    let text = human_summary(&scenario.name, &file, &scenario.life, &result);
    write_output(None, text.as_bytes())
}

/// The SVG of the leak-rate history, or `None` (with a warning) when the leak rate is zero
/// throughout: there is nothing to draw on a log axis.
fn plot(
    title: &str,
    result: &LifeResult,
    path: &std::path::Path,
) -> Result<Option<String>, CliError> {
    if !has_positive_leak_rate([result]) {
        eprintln!(
            "warning: the leak rate is zero throughout (sealed): no chart written to {}",
            path.display()
        );
        return Ok(None);
    }
    leak_rate_chart(title, [("leak rate", result)])
        .to_svg()
        .map(Some)
        .map_err(|e| CliError::Internal(e.to_string()))
}
