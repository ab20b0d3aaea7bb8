//! `sealsim compare`: the same scenario with several compounds — time to failure, failure
//! mode and leak rates at 1 day, 1 year and 10 years for each, as a table on standard output,
//! optionally as CSV (`-o`) and as an overlay chart of the leak-rate histories (`--plot`).
//!
//! A compound is a library id (`nbr-70`) or the path of a material file (anything with a
//! `/` or ending in `.toml`). It replaces the scenario's own `[material]` compound; the
//! scenario's `asperity_modulus` still applies, and whatever depends on the compound (default
//! temperature, thermal strain, ageing defaults) is validated against it.

use super::{CliError, print_findings, progress_bar, write_output};
use crate::leak::Fidelity;
use crate::material::Material;
use crate::report::life::{CompareRow, CompareSummary, compare_cells, compare_table, compare_text};
use crate::report::life_chart::compare_chart;
use crate::scenario::{library, load_material_file};
use crate::workflow;
use clap::Args;
use std::path::{Path, PathBuf};

/// Arguments of `sealsim compare`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "CSV columns: material, name, status, time_to_failure_s (blank when it \
    survives), failure_mode (leak_rate|leaked_volume|retained_force|compression_set|lift_off|\
    extrusion|lost_interference|sealing_force|contact_pressure|low_temperature|none), \
    leak_rate_1day_m3_per_s, leak_rate_1year_m3_per_s, leak_rate_10years_m3_per_s (blank beyond \
    the scenario's duration); for a gas also throughput_1day_Pa_m3_per_s, \
    throughput_1year_Pa_m3_per_s, throughput_10years_Pa_m3_per_s (the interface) and \
    total_throughput_1day_Pa_m3_per_s, … (with the permeation through the rubber); then at the \
    end of the run sealing_force_end_N_per_m, retained_force_end (over the retained-force \
    reference), leaked_volume_end_m3, compression_set_end (with ageing), state_end \
    (sealed|leaking|pressure_held|lift_off); last rank, rank_basis (compatible|missing_figure|\
    not_rated|incompatible, with the reason), rating (A|B|X, blank: not rated) and \
    rating_source. Rows are ranked: the compounds rated A or B for the run's medium first, by \
    life; then those run without a figure the verdict needs, the unrated and the X-rated, each \
    by life. The headline names only a compound rated A/B (--all: the raw order by life)."
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

    /// Write the comparison as JSON to FILE (atomically, SI): the headline, then each
    /// compound in the listed order with its rank, rank basis, rating, rating source and its
    /// run summary as `sealsim run --summary` writes it.
    #[arg(long, value_name = "FILE.json")]
    pub summary: Option<PathBuf>,

    /// Write an overlay chart of the leak-rate histories to FILE (SVG, PNG or PDF).
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub plot: Option<PathBuf>,

    /// Override the scenario's simulation.fidelity.
    #[arg(long, value_name = "LEVEL", value_parser = super::FidelityArg)]
    pub fidelity: Option<Fidelity>,

    /// Print every warning in full (not its one line) and the notes (how inputs were read:
    /// a callout's spectrum, the compound's rating for the fluid).
    #[arg(short, long)]
    pub verbose: bool,

    /// Write a self-contained HTML report to FILE: the table, the overlay chart, each
    /// compound's warnings (inline SVG and CSS, nothing fetched).
    #[arg(long, value_name = "FILE.html")]
    pub report: Option<PathBuf>,

    /// Leak rates below RATE read "sealed" in the table (default: one molecule a second; the
    /// CSV keeps the raw values), e.g. "1e-15 m^3/s".
    #[arg(long, value_name = "RATE")]
    pub leak_floor: Option<String>,

    /// List the compounds in the raw order by life, ratings ignored (the headline still
    /// names only a compound rated A/B for the medium; the rank columns stay).
    #[arg(long)]
    pub all: bool,

    #[command(flatten)]
    pub fail: super::FailExitCode,
}

/// Runs `sealsim compare`.
pub fn run(args: CompareArgs) -> Result<(), CliError> {
    super::set_verbose(args.verbose);
    // every compound and every scenario variant is checked before anything runs
    let materials: Vec<(String, Material)> = args
        .materials
        .iter()
        .map(|spec| Ok((spec.trim().to_owned(), resolve(spec.trim())?)))
        .collect::<Result<_, CliError>>()?;
    let material_files: Vec<&Path> = args
        .materials
        .iter()
        .filter(|spec| library::get(spec.trim()).is_err())
        .map(|spec| Path::new(spec.trim()))
        .chain(std::iter::once(args.scenario.as_path()))
        .collect();
    super::guard_outputs(
        &material_files,
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
    let runs = workflow::compare::rank(
        workflow::compare::compare(
            &args.scenario,
            materials,
            args.fidelity,
            &mut progress_bar("numerical level"),
        )?,
        args.all,
    );
    let headline = crate::report::life::compare_headline(&runs);
    let floor = match runs.first() {
        Some((r, _)) => super::leak_floor_flag(args.leak_floor.as_deref(), &r.scenario.life.fluid)?,
        None => None,
    };
    let rows: Vec<CompareRow<'_>> = runs.iter().map(|run| CompareRow::of(run, floor)).collect();
    let csv = args
        .output
        .as_ref()
        .map(|_| compare_table(&rows))
        .transpose()?;
    let json = args
        .summary
        .as_ref()
        .map(|_| {
            CompareSummary::new(
                &args.scenario.display().to_string(),
                &headline,
                &runs,
                &rows,
            )
            .to_json()
        })
        .transpose()?;
    let name = runs.first().map_or("", |(r, _)| r.scenario.name.as_str());
    let wants_chart = args.plot.is_some() || args.report.is_some();
    let svg = match (wants_chart, rows.first()) {
        (true, Some(first)) => Some(
            compare_chart(
                &format!("{name}: leak rate by compound"),
                &rows.iter().map(|r| (r.label, r.result)).collect::<Vec<_>>(),
                &first.floor,
                first.mean_pressure,
            )
            .map_err(|e| CliError::Internal(e.to_string()))?,
        ),
        _ => None,
    };
    let mut text = format!("{name} ({})\n{headline}\n", args.scenario.display());
    text += &compare_text(&rows);
    let page = args.report.as_ref().map(|_| {
        let cells = compare_cells(&rows);
        report_page(
            name,
            &args.scenario.display().to_string(),
            &runs,
            &headline,
            &cells,
            svg.as_deref(),
        )
    });

    let plot = super::plot_file(args.plot.as_deref(), svg.as_deref())?;

    super::print_shared_warnings(runs.iter().map(|(r, _)| (r.label.as_str(), &r.scenario)));
    for (run, _) in &runs {
        print_findings(Some(&run.label), &run.result.findings);
    }
    if let (Some(path), Some(csv)) = (&args.output, &csv) {
        write_output(Some(path), csv.as_bytes())?;
    }
    if let (Some(path), Some(json)) = (&args.summary, &json) {
        write_output(Some(path), json.as_bytes())?;
    }
    if let (Some(path), Some(plot)) = (&args.plot, &plot) {
        write_output(Some(path), plot)?;
    }
    if let (Some(path), Some(page)) = (&args.report, &page) {
        write_output(Some(path), page.as_bytes())?;
    }
    write_output(None, text.as_bytes())?;
    args.fail.verdict(runs.iter().any(|(r, _)| {
        crate::report::life::verdict(&r.scenario.life, &r.result).kind
            != crate::report::life::VerdictKind::Survives
    }))
}

/// The HTML report of a comparison: the table, the overlay chart, each compound's warnings.
fn report_page(
    name: &str,
    file: &str,
    runs: &[(workflow::compare::CompoundRun, workflow::compare::Standing)],
    headline: &str,
    cells: &[Vec<String>],
    svg: Option<&str>,
) -> String {
    use crate::report::html;
    let mut body = format!("<h1>{}: compounds compared</h1>\n", html::escape(name));
    body += &format!(
        "<p class=\"meta\">scenario file {} · sealsim compare</p>\n",
        html::escape(file)
    );
    // the headline names only a compound rated A/B for the medium (workflow::compare::headline)
    body += &html::verdict("info", headline);
    if runs
        .iter()
        .any(|(r, _)| r.material.status == crate::material::Status::Illustrative)
    {
        body += "<p class=\"illustrative\">ILLUSTRATIVE material data in at least one compound: \
                 the results show trends, they are not for design decisions.</p>\n";
    }
    // the scenario and every file a compound's run read (a material file, data), once each
    let mut inputs: Vec<&std::path::Path> = vec![std::path::Path::new(file)];
    for (run, _) in runs {
        for path in &run.scenario.inputs {
            if !inputs.contains(&path.as_path()) {
                inputs.push(path);
            }
        }
    }
    body += &html::record("sealsim compare", &inputs);
    body += &html::heading("Comparison");
    let empty = Vec::new();
    let (header, rest) = cells.split_first().unwrap_or((&empty, &[]));
    let (table_rows, notes): (Vec<Vec<String>>, Vec<Vec<String>>) =
        rest.iter().cloned().partition(|r| r.len() == header.len());
    body += &html::table(header, &table_rows);
    for note in notes {
        body += &html::paragraph(&note.join(" "));
    }
    body += &html::heading("Leak rate by compound");
    body += &match svg {
        Some(svg) => html::figure(
            svg,
            "Leak rate against time, one curve per compound, clipped at the floor; a cross marks \
             each failure.",
        ),
        None => html::paragraph("Every compound seals throughout: no leak rate to draw."),
    };
    let lines: Vec<String> = runs
        .iter()
        .flat_map(|(run, _)| {
            html::validity_lines(
                Some(&run.label),
                &run.scenario.warnings,
                &run.result.findings,
            )
        })
        .collect();
    body += &html::validity(&lines);
    if let Some((run, _)) = runs.first() {
        body += &html::fidelity(run.scenario.life.fidelity);
        body += &html::file(
            html::SCENARIO_TITLE,
            &std::fs::read_to_string(&run.scenario.path).unwrap_or_default(),
        );
    }
    html::document(&format!("{name}: compounds compared"), &body)
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
