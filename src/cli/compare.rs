//! `sealsim compare`: the same scenario with several compounds — time to failure, failure
//! mode and leak rates at 1 day, 1 year and 10 years for each, as a table on standard output,
//! optionally as CSV (`-o`) and as an overlay chart of the leak-rate histories (`--plot`).
//!
//! A compound is a library id (`nbr-70`) or the path of a material file (anything with a
//! `/` or ending in `.toml`). It replaces the scenario's own `[material]` compound; the
//! scenario's `asperity_modulus` still applies, and whatever depends on the compound (default
//! temperature, thermal strain, ageing defaults) is validated against it.

use super::{CliError, print_findings, print_scenario_warnings, progress_bar, write_output};
use crate::leak::Fidelity;
use crate::material::Material;
use crate::report::life::{
    CompareRow, compare_table, compare_text, has_positive_leak_rate, leak_rate_chart,
};
use crate::scenario::{library, load_material_file};
use crate::workflow;
use clap::Args;
use std::path::{Path, PathBuf};

/// Arguments of `sealsim compare`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "CSV columns: material, name, status, time_to_failure_s (blank when it \
    survives), failure_mode (leak_rate|leaked_volume|retained_force|lift_off|none), \
    leak_rate_1day_m3_per_s, leak_rate_1year_m3_per_s, leak_rate_10years_m3_per_s (blank beyond \
    the scenario's duration); for a gas also throughput_1day_Pa_m3_per_s, \
    throughput_1year_Pa_m3_per_s, throughput_10years_Pa_m3_per_s (the interface only)."
)]
pub struct CompareArgs {
    /// Scenario file (TOML).
    #[arg(value_name = "SCENARIO")]
    pub scenario: PathBuf,

    /// Comma-separated library ids (see `sealsim materials list`) or material-file paths.
    #[arg(long, value_name = "ID,...", value_delimiter = ',', required = true)]
    pub materials: Vec<String>,

    /// Write the comparison CSV to FILE (atomically).
    #[arg(short, long, value_name = "FILE.csv")]
    pub output: Option<PathBuf>,

    /// Write an overlay chart of the leak-rate histories to FILE (SVG).
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,

    /// Override the scenario's simulation.fidelity.
    #[arg(long, value_name = "LEVEL", value_enum)]
    pub fidelity: Option<Fidelity>,
}

/// Runs `sealsim compare`.
pub fn run(args: CompareArgs) -> Result<(), CliError> {
    // every compound and every scenario variant is checked before anything runs
    let materials: Vec<(String, Material)> = args
        .materials
        .iter()
        .map(|spec| Ok((spec.trim().to_owned(), resolve(spec.trim())?)))
        .collect::<Result<_, CliError>>()?;
    let runs = workflow::compare::compare(
        &args.scenario,
        materials,
        args.fidelity,
        &mut progress_bar("numerical level"),
    )?;
    let rows: Vec<CompareRow<'_>> = runs
        .iter()
        .map(|run| CompareRow {
            label: &run.label,
            material: &run.material,
            result: &run.result,
            duration: run.scenario.life.time.duration,
            mean_pressure: run.scenario.life.fluid.mean_pressure(),
        })
        .collect();
    let csv = args
        .output
        .as_ref()
        .map(|_| compare_table(&rows))
        .transpose()?;
    let name = runs.first().map_or("", |r| r.scenario.name.as_str());
    let svg = match &args.plot {
        Some(path) if !has_positive_leak_rate(runs.iter().map(|r| &r.result)) => {
            eprintln!(
                "warning: every leak rate is zero throughout (sealed): no chart written to {}",
                path.display()
            );
            None
        }
        Some(_) => Some(
            leak_rate_chart(
                &format!("{name}: leak rate by compound"),
                rows.iter().map(|r| (r.label, r.result)),
            )
            .to_svg()
            .map_err(|e| CliError::Internal(e.to_string()))?,
        ),
        None => None,
    };

    for run in &runs {
        print_scenario_warnings(Some(&run.label), &run.scenario);
        print_findings(Some(&run.label), &run.result.findings);
    }
    if let (Some(path), Some(csv)) = (&args.output, &csv) {
        write_output(Some(path), csv.as_bytes())?;
    }
    if let (Some(path), Some(svg)) = (&args.plot, &svg) {
        write_output(Some(path), svg.as_bytes())?;
    }
    let mut text = format!("{name} ({})\n", args.scenario.display());
    text += &compare_text(&rows);
    write_output(None, text.as_bytes())
}

/// A library compound by id, or a material file by path.
fn resolve(spec: &str) -> Result<Material, CliError> {
    match library::get(spec) {
        Ok(entry) => Ok(entry.load()?),
        Err(_) if spec.contains('/') || spec.contains('\\') || spec.ends_with(".toml") => {
            Ok(load_material_file(Path::new(spec))?)
        }
        Err(unknown) => Err(CliError::Input(format!(
            "--materials: {unknown} (or give the path of a material file)"
        ))),
    }
}
