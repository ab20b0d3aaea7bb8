//! `sealsim run`: the seal-life simulation of one scenario — the history of sealing force,
//! contact and leak rate over the seal's life, and when (and how) it fails.
//!
//! A readable summary always goes to standard output and the run's validity warnings to
//! standard error (`warning: …`); the history CSV (`-o`), the summary JSON (`--summary`) and
//! the leak-rate chart (`--plot`) are written only when asked for, each atomically, and only
//! after the whole run has succeeded (on bad input nothing is written).

use super::{CliError, print_findings, print_scenario_warnings, progress_bar, write_output};
use crate::leak::Fidelity;
use crate::report::html;
use crate::report::life::{
    Detail, LeakFloor, Summary, brief_summary, history_for, human_summary, run_summary,
};
use crate::report::life_chart::life_chart;
use crate::report::units::table_csv;
use crate::scenario::Scenario;
use crate::simulate::LifeResult;
use crate::workflow;
use clap::Args;
use std::path::PathBuf;

/// Arguments of `sealsim run`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Summary: a verdict line first (PASS, FAIL, OPEN or UNDECIDED, the life against the run's duration, the failure mode and its quantity against the limit), then the key figures; --quiet the verdict line alone, --verbose the full derivation.\n\
    History columns (CSV; SI units, or those of --units in the names, e.g. temperature_F, peak_pressure_psi, leak_rate_cc_per_min): time_s, temperature_K, reduced_time_s, \
    shift_factor (blank when frozen), sealing_force_N_per_m, peak_pressure_Pa, mean_pressure_Pa, \
    contact_width_m, u_c_m (blank when sealed at the peak), leak_rate_m3_per_s, \
    leaked_volume_m3, state (sealed|leaking|pressure_held|lift_off), open_fraction (open share of the critical channels' flow under particle clogging; 1 without [contamination]), compression_set (chemical, with [ageing]), shutdown_squeeze (the set ring's squeeze at the shutdown condition). The first row is the installation, t = 0. With --fail-exit-code N the run exits N when the seal fails or is open (docs/model.md §8.1).\n\
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

    /// Write the chart of the run to FILE (SVG, PNG or PDF by its extension): leak rate (clipped
    /// at the floor, with the leak-rate threshold; a gas's interface, permeation and total),
    /// sealing force (with the retained-force threshold) and temperature against time in h, days
    /// or years, the failure marked.
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub plot: Option<PathBuf>,

    /// Write a self-contained HTML report to FILE: the verdict, the summary, the chart, the
    /// warnings, the fidelity level and the scenario with its provenance (inline SVG and CSS,
    /// nothing fetched).
    #[arg(long, value_name = "FILE.html")]
    pub report: Option<PathBuf>,

    /// Leak rates below RATE read "sealed" in the summary and are clipped in the charts
    /// (default: one molecule a second; the CSV keeps the raw values), e.g. "1e-15 m^3/s".
    #[arg(long, value_name = "RATE")]
    pub leak_floor: Option<String>,

    /// Override the scenario's simulation.fidelity.
    #[arg(long, value_name = "LEVEL", value_parser = super::FidelityArg)]
    pub fidelity: Option<Fidelity>,

    /// Print the verdict line only (PASS, FAIL, OPEN or UNDECIDED; the life against the
    /// run's duration, the failure mode and its quantity against the limit).
    #[arg(short, long, conflicts_with = "verbose")]
    pub quiet: bool,

    /// Print the verdict line and the full derivation (material, seal, fluid, ageing, level
    /// band; SI) instead of the short table, every warning in full (not its one line) and the
    /// notes (how inputs were read: a callout's spectrum, the compound's rating for the fluid).
    #[arg(short, long)]
    pub verbose: bool,

    /// Units of the summary, the HTML report and the history CSV's columns: si (the CSV in
    /// m, Pa, K, N/m, m³/s), metric (mm, bar, °C, N/mm, mL/min, mL, mbar·L/s) or us (in, psi,
    /// °F, lbf/in, cc/min, cc, atm·cc/s). The CSV's column names carry the unit; the JSON
    /// summary is SI always.
    #[arg(long, value_name = "SYSTEM", default_value = "si", value_parser = units_arg)]
    pub units: crate::report::units::UnitSystem,

    #[command(flatten)]
    pub fail: super::FailExitCode,
}

/// `--units`: `si`, `metric` or `us` (shared by the commands that take it).
pub(crate) fn units_arg(text: &str) -> Result<crate::report::units::UnitSystem, String> {
    crate::report::units::UnitSystem::from_name(text).ok_or_else(|| {
        format!(
            "unknown unit system {text:?}: expected one of {}",
            crate::report::units::UnitSystem::NAMES.join(", ")
        )
    })
}

/// Runs `sealsim run`.
pub fn run(args: RunArgs) -> Result<(), CliError> {
    super::set_verbose(args.verbose);
    let mut scenario = Scenario::load(&args.scenario)?;
    let inputs: Vec<&std::path::Path> = std::iter::once(args.scenario.as_path())
        .chain(scenario.inputs.iter().map(std::path::PathBuf::as_path))
        .collect();
    super::guard_outputs(
        &inputs,
        &[
            ("-o", args.output.as_deref()),
            ("--summary", args.summary.as_deref()),
            ("--plot", args.plot.as_deref()),
            ("--report", args.report.as_deref()),
        ],
    )?;
    if let Some(path) = args.output.as_deref() {
        super::expect_extension("-o", path, &["csv"])?;
    }
    if let Some(fidelity) = args.fidelity {
        scenario.life.fidelity = fidelity;
    }
    let given = super::leak_floor_flag(args.leak_floor.as_deref(), &scenario.life.fluid)?;
    let result = workflow::life::run(&scenario, &mut progress_bar("numerical level"));
    let file = args.scenario.display().to_string();
    let floor = LeakFloor::of(&scenario.life.fluid, given);

    // Everything is rendered before anything is written.
    let csv = args
        .output
        .as_ref()
        .map(|_| {
            history_for(&result, &scenario.life.fluid)
                .and_then(|table| table_csv(&table, args.units))
        })
        .transpose()?;
    let json = args
        .summary
        .as_ref()
        .map(|_| {
            let mut summary = Summary::new(&scenario.name, &file, &scenario.life, &result);
            summary.input_warnings = crate::report::findings::input_records(&scenario.warnings);
            summary.to_json()
        })
        .transpose()?;
    let needs_chart = args.plot.is_some() || args.report.is_some();
    let svg = needs_chart
        .then(|| life_chart(&scenario.name, &scenario.life, &result, &floor))
        .transpose()
        .map_err(|e| CliError::Internal(e.to_string()))?;
    let detail = match (args.quiet, args.verbose) {
        (true, _) => Detail::Quiet,
        (_, true) => Detail::Verbose,
        _ => Detail::Brief,
    };
    let text = run_summary(
        &scenario.name,
        &file,
        &scenario.life,
        &result,
        &floor,
        args.units,
        detail,
    );
    let page = args.report.as_ref().map(|_| {
        let life = &scenario.life;
        // the verdict is the report's banner; the key figures follow in the units asked for
        let brief = brief_summary(&scenario.name, &file, life, &result, &floor, args.units);
        let full = human_summary(&scenario.name, &file, life, &result, &floor);
        report_page(
            &scenario,
            &file,
            &result,
            &brief,
            &full,
            svg.as_deref(),
            &floor,
        )
    });

    let plot = super::plot_file(args.plot.as_deref(), svg.as_deref())?;

    print_scenario_warnings(None, &scenario);
    print_findings(None, &result.findings);
    for (path, bytes) in [
        (&args.output, csv.as_deref().map(str::as_bytes)),
        (&args.summary, json.as_deref().map(str::as_bytes)),
        (&args.plot, plot.as_deref()),
        (&args.report, page.as_deref().map(str::as_bytes)),
    ] {
        if let (Some(path), Some(bytes)) = (path, bytes) {
            write_output(Some(path), bytes)?;
        }
    }
    write_output(None, text.as_bytes())?;
    args.fail.verdict(
        crate::report::life::verdict(&scenario.life, &result).kind
            != crate::report::life::VerdictKind::Survives,
    )
}

/// The HTML report of a run: verdict, summary, chart, warnings, fidelity, the scenario file.
fn report_page(
    scenario: &Scenario,
    file: &str,
    result: &LifeResult,
    summary: &str,
    derivation: &str,
    svg: Option<&str>,
    floor: &LeakFloor,
) -> String {
    let life = &scenario.life;
    let mut body = format!("<h1>{}</h1>\n", html::escape(&scenario.name));
    body += &format!(
        "<p class=\"meta\">scenario file {} · sealsim run</p>\n",
        html::escape(file)
    );
    let verdict = crate::report::life::verdict(life, result);
    let kind = match verdict.kind {
        crate::report::life::VerdictKind::Fails | crate::report::life::VerdictKind::Open => "fails",
        crate::report::life::VerdictKind::Undecided => "undecided",
        crate::report::life::VerdictKind::Survives => "survives",
    };
    body += &html::verdict(kind, &verdict.text);
    if life.material.status == crate::material::Status::Illustrative {
        body += "<p class=\"illustrative\">ILLUSTRATIVE material data: at least one number is \
                 estimated, not measured; the results show trends, they are not for design \
                 decisions.</p>\n";
    }
    let inputs: Vec<&std::path::Path> = std::iter::once(std::path::Path::new(file))
        .chain(scenario.inputs.iter().map(std::path::PathBuf::as_path))
        .collect();
    body += &html::record("sealsim run", &inputs);
    body += &html::heading("Summary");
    // the verdict line and the key figures in the units asked for, then the derivation (SI)
    body += &html::summary_table(summary);
    body += &html::heading("Derivation (SI)");
    body += &html::summary_table(derivation);
    body += &html::paragraph(&format!(
        "Leak rates below {} m³/s ({}) read \"sealed\" and are drawn at that floor; the history \
         CSV keeps the raw values.",
        crate::units::human(floor.rate, 2),
        floor.meaning()
    ));
    if let Some(svg) = svg {
        body += &html::heading("Leak rate, sealing force and temperature");
        body += &html::figure(
            svg,
            "Leak rate (log, clipped at the floor; dashed: the leak-rate threshold; shaded: \
             lift-off), sealing force per unit length (dashed: the retained-force threshold) and \
             temperature (for a cycling temperature its daily envelope); the cross \
             marks the failure.",
        );
    }
    body += &html::validity(&html::validity_lines(
        None,
        &scenario.warnings,
        &result.findings,
    ));
    body += &html::fidelity(life.fidelity);
    body += &html::file(
        html::SCENARIO_TITLE,
        &std::fs::read_to_string(&scenario.path).unwrap_or_default(),
    );
    html::document(&scenario.name, &body)
}
