//! `sealsim tradeoff`: the scenario's static state and life run at every fidelity level and at
//! a ladder of numerical settings, with wall time and error against the most accurate setting
//! ([`crate::workflow::tradeoff`]).

use super::{CliError, print_findings, print_scenario_warnings, progress_bar, write_output};
use crate::report::tradeoff::{tradeoff_chart, tradeoff_markdown, tradeoff_table};
use crate::scenario::Scenario;
use crate::workflow::tradeoff::{self, ScenarioTradeoff, TradeoffOptions};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `sealsim tradeoff`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Two sections: 'full-spectrum' compares the analytic levels (static state and \
    life run) with the critical junction by quadrature at 4x nodes and 4x time grid; \
    'band-limited' compares them with the numerical reference on the band q1/q0 = --band of the \
    spectrum (static, at the pressure where Persson's contact fraction is 0.2), the finest \
    numerical setting being the reference. CSV columns: section, level, setting, \
    nominal_pressure_Pa, static_seconds_s, leak_rate_m3_per_s, leak_rate_std_m3_per_s, \
    static_error, life_seconds_s, time_to_failure_s, leaked_volume_m3, life_error."
)]
pub struct TradeoffArgs {
    /// Scenario file (TOML).
    #[arg(value_name = "SCENARIO")]
    pub scenario: PathBuf,

    /// Write the table as CSV to FILE (atomically).
    #[arg(short, long, value_name = "FILE.csv")]
    pub output: Option<PathBuf>,

    /// Write the error-against-time chart (log–log; SVG, PNG or PDF) to FILE.
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub plot: Option<PathBuf>,

    /// Band q1/q0 resolved by the numerical level (default: the scenario's numerical.band, 32).
    #[arg(long, allow_hyphen_values = true, value_parser = parse_band)]
    pub band: Option<f64>,

    /// Seed of the synthetic surfaces (default: the scenario's numerical.seed, 1).
    #[arg(long)]
    pub seed: Option<u64>,

    /// Leave out the numerical level (the band-limited section; seconds to minutes).
    #[arg(long)]
    pub skip_numerical: bool,

    /// Write a self-contained HTML report to FILE: the ladder's table and chart, the warnings
    /// and the scenario (inline SVG and CSS, nothing fetched).
    #[arg(long, value_name = "FILE.html")]
    pub report: Option<PathBuf>,
}

fn parse_band(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(b) if b.is_finite() && (4.0..=512.0).contains(&b) => Ok(b),
        _ => Err(format!(
            "the band must be a number from 4 to 512, got {text:?}"
        )),
    }
}

/// Runs `sealsim tradeoff`.
pub fn run(args: TradeoffArgs) -> Result<(), CliError> {
    let scenario = Scenario::load(&args.scenario)?;
    let inputs: Vec<&std::path::Path> = std::iter::once(args.scenario.as_path())
        .chain(scenario.inputs.iter().map(std::path::PathBuf::as_path))
        .collect();
    super::guard_outputs(
        &inputs,
        &[
            ("-o", args.output.as_deref()),
            ("--plot", args.plot.as_deref()),
            ("--report", args.report.as_deref()),
        ],
    )?;
    if let Some(path) = args.output.as_deref() {
        super::expect_extension("-o", path, &["csv"])?;
    }
    let options = TradeoffOptions {
        band: args.band.unwrap_or(scenario.numerical.band),
        seed: args.seed.unwrap_or(scenario.numerical.seed),
        skip_numerical: args.skip_numerical,
        ..TradeoffOptions::default()
    };
    let ScenarioTradeoff { rows, findings } =
        tradeoff::for_scenario(&scenario, &options, &mut progress_bar("trade-off"));
    let csv = args
        .output
        .as_ref()
        .map(|_| tradeoff_table(&rows))
        .transpose()?;
    let svg = match args.plot.is_some() || args.report.is_some() {
        true => Some(
            tradeoff_chart(&format!("{}: error against time", scenario.name), &rows)
                .to_svg()
                .map_err(|e| CliError::Internal(e.to_string()))?,
        ),
        false => None,
    };
    let table = tradeoff_markdown(&rows);
    let page = args.report.as_ref().map(|_| {
        use crate::report::html;
        let mut body = format!(
            "<h1>{}: speed against accuracy</h1>\n<p class=\"meta\">scenario file {} · sealsim \
             tradeoff</p>\n",
            html::escape(&scenario.name),
            html::escape(&args.scenario.display().to_string())
        );
        body += &html::verdict(
            "info",
            "Each fidelity level and numerical setting with its wall time and its error against \
             the most accurate setting of its section.",
        );
        body += &html::heading("The ladder");
        body += &html::pre(&table);
        if let Some(svg) = &svg {
            body += &html::heading("Error against time");
            body += &html::figure(svg, "Error against wall time, one point per setting.");
        }
        body += &html::validity(&html::validity_lines(None, &scenario.warnings, &findings));
        body += &html::file(
            html::SCENARIO_TITLE,
            &std::fs::read_to_string(&args.scenario).unwrap_or_default(),
        );
        html::document(&format!("{}: speed against accuracy", scenario.name), &body)
    });
    let plot = super::plot_file(args.plot.as_deref(), svg.as_deref())?;
    for (path, bytes) in [
        (&args.output, csv.as_deref().map(str::as_bytes)),
        (&args.plot, plot.as_deref()),
        (&args.report, page.as_deref().map(str::as_bytes)),
    ] {
        if let (Some(path), Some(bytes)) = (path, bytes) {
            write_output(Some(path), bytes)?;
        }
    }
    print_scenario_warnings(None, &scenario);
    print_findings(None, &findings);
    write_output(None, table.as_bytes())
}
