//! `sealsim study`: a study's cases (tolerances, uncertainties, sweeps) run in parallel, the
//! time to failure as a distribution; `--shard K/N` runs one slice, `study merge` joins the
//! slices, `study slurm` writes a Slurm job array that does both on a cluster.
//!
//! The summary table goes to standard output; the per-case CSV (`-o`), the summary JSON
//! (`--summary`) and the charts are written only when asked for, each atomically (on bad input
//! nothing is written). The cases run, and a merge reads its parts, in blocks: each block's
//! rows go to the table's temporary as they come and the summary keeps a few numbers a case
//! ([`CaseRecords`]), so a 10⁶-case study or merge runs in flat memory; every output is put in
//! place at the end.

use super::{CliError, print_scenario_warnings, write_output};
use crate::report::StagedFile;
use crate::report::study::{self as out, charts};
use crate::scenario::study::Study;
use crate::study::CaseOutcome;
use crate::study::design::shard_range;
use crate::study::summary::{CaseRecords, StudySummary};
use crate::workflow;
use clap::{Args, Subcommand};
use std::io::Write as _;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// Arguments of `sealsim study`.
#[derive(Debug, Clone, Args)]
#[command(
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    after_help = "Per-case columns (CSV, SI units): case, one column per varied input (its key \
    path, with its SI unit for a quantity: surface.rms_roughness_m), life_s (the time to failure, \
    or the end of the run for a survivor), status (failed|censored), mode (the failure mode), \
    leak_rate_at_<t>_s_m3_per_s for each report time (blank past the run's end), \
    sealing_force_end_N_per_m, retained_force_end (over the force at the retained-force \
    reference), leaked_volume_end_m3, compression_set_end (with ageing), warnings (the validity \
    limits the case crossed, ;-separated).\n\
    Summary JSON: cases, failures, censored, b1_s, b10_s, b50_s with _lower_s/_upper_s \
    (Kaplan–Meier, null where not reached), modes, weibull (shape, scale_s, fits), \
    sensitivity (input, measure, value), survival (the Kaplan–Meier steps with their band), \
    warnings (cases per limit).\n\
    The cases are deterministic: the same study gives the same bits whatever --threads, and \
    shards merged in any order give the single run's files."
)]
pub struct StudyArgs {
    #[command(subcommand)]
    pub action: Option<StudyAction>,

    #[command(flatten)]
    pub run: RunArgs,
}

/// `sealsim study FILE …`.
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// Study file (TOML): base scenario, inputs to vary, design.
    #[arg(value_name = "STUDY", required = true)]
    pub study: Option<PathBuf>,

    /// Worker threads (default: all cores).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u16).range(1..))]
    pub threads: Option<u16>,

    /// Run only shard K of N (1 ≤ K ≤ N), a contiguous slice of the cases, into a part file
    /// for `study merge` (needs -o).
    #[arg(long, value_name = "K/N", value_parser = parse_shard, requires = "output",
          conflicts_with_all = ["summary", "survival_plot", "tornado_plot", "report"])]
    pub shard: Option<(usize, usize)>,

    /// Write the per-case table (CSV) to FILE; with --shard, the part file.
    #[arg(short, long, value_name = "FILE.csv")]
    pub output: Option<PathBuf>,

    #[command(flatten)]
    pub outputs: SummaryOutputs,
}

/// The summary's outputs, shared by a run and a merge.
#[derive(Debug, Clone, Args)]
pub struct SummaryOutputs {
    /// Write the summary as JSON to FILE.
    #[arg(long, value_name = "FILE.json")]
    pub summary: Option<PathBuf>,

    /// Write the survival curve (Kaplan–Meier with its band, the Weibull fit) to FILE (SVG, PNG or PDF).
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub survival_plot: Option<PathBuf>,

    /// Write the tornado chart of the inputs' influence on the life to FILE (SVG, PNG or PDF).
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub tornado_plot: Option<PathBuf>,

    /// Write a self-contained HTML report to FILE: the summary, the survival curve, the
    /// sensitivities, the warnings, the study and its base scenario (inline SVG and CSS).
    #[arg(long, value_name = "FILE.html")]
    pub report: Option<PathBuf>,
}

/// `study merge` and `study slurm`.
#[derive(Debug, Clone, Subcommand)]
pub enum StudyAction {
    /// Join the part files of `study FILE --shard K/N` runs (any order) into the single run's
    /// per-case table and summary, bit for bit.
    Merge(MergeArgs),
    /// Write a Slurm job-array script: one array task per shard, the merge as a job that
    /// depends on them all. Run the script (bash) on the cluster's login node to submit.
    Slurm(SlurmArgs),
}

/// Arguments of `sealsim study merge`.
#[derive(Debug, Clone, Args)]
pub struct MergeArgs {
    /// The study file the parts were run from.
    #[arg(value_name = "STUDY")]
    pub study: PathBuf,

    /// The part files, in any order.
    #[arg(value_name = "PART.csv", required = true, num_args = 1..)]
    pub parts: Vec<PathBuf>,

    /// Write the merged per-case table (CSV) to FILE.
    #[arg(short, long, value_name = "FILE.csv")]
    pub output: Option<PathBuf>,

    #[command(flatten)]
    pub outputs: SummaryOutputs,
}

/// Arguments of `sealsim study slurm`.
#[derive(Debug, Clone, Args)]
pub struct SlurmArgs {
    /// The study file.
    #[arg(value_name = "STUDY")]
    pub study: PathBuf,

    /// Number of shards (array tasks).
    #[arg(long, value_name = "N", default_value_t = 4,
          value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub shards: u32,

    /// CPUs per array task (each task runs its cases on as many threads).
    #[arg(long, value_name = "N", default_value_t = 1,
          value_parser = clap::value_parser!(u16).range(1..))]
    pub cpus_per_task: u16,

    /// Slurm partition (default: the cluster's default partition).
    #[arg(long, value_name = "NAME")]
    pub partition: Option<String>,

    /// Wall-time limit of each task (Slurm's format, e.g. 01:00:00).
    #[arg(long, value_name = "TIME")]
    pub time: Option<String>,

    /// Directory for the part files, logs and merged results (default: next to the study,
    /// `<study>-slurm`).
    #[arg(long, value_name = "DIR")]
    pub results: Option<PathBuf>,

    /// The sealsim binary the jobs run (default: this one).
    #[arg(long, value_name = "PATH")]
    pub sealsim: Option<PathBuf>,

    /// Write the script to FILE (default: standard output).
    #[arg(short, long, value_name = "FILE.sh")]
    pub output: Option<PathBuf>,
}

/// `K/N` with 1 ≤ K ≤ N.
fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let bad = || format!("\"{text}\" is not a shard K/N with 1 ≤ K ≤ N (e.g. 2/4)");
    let (k, n) = text.split_once('/').ok_or_else(bad)?;
    let (k, n): (usize, usize) = (
        k.trim().parse().map_err(|_| bad())?,
        n.trim().parse().map_err(|_| bad())?,
    );
    if k == 0 || n == 0 || k > n {
        return Err(bad());
    }
    Ok((k, n))
}

/// Runs `sealsim study`.
pub fn run(args: StudyArgs) -> Result<(), CliError> {
    match args.action {
        Some(StudyAction::Merge(m)) => merge(m),
        Some(StudyAction::Slurm(s)) => slurm(s),
        None => run_cases(args.run),
    }
}

fn run_cases(args: RunArgs) -> Result<(), CliError> {
    let path = args
        .study
        .ok_or_else(|| CliError::Input("a study file is required".into()))?;
    let study = Study::load(&path)?;
    let inputs: Vec<&Path> = [path.as_path(), study.base_path.as_path()]
        .into_iter()
        .chain(study.base_scenario.inputs.iter().map(PathBuf::as_path))
        .collect();
    let o = &args.outputs;
    super::guard_outputs(
        &inputs,
        &[
            ("-o", args.output.as_deref()),
            ("--summary", o.summary.as_deref()),
            ("--survival-plot", o.survival_plot.as_deref()),
            ("--tornado-plot", o.tornado_plot.as_deref()),
            ("--report", o.report.as_deref()),
        ],
    )?;
    if let Some(path) = args.output.as_deref() {
        super::expect_extension("-o", path, &["csv"])?;
    }
    let total = study.cases();
    let range = match args.shard {
        Some((k, n)) => shard_range(k, n, total),
        None => 0..total,
    };
    // the table's temporary first: a bad output path fails before the cases run
    let head = match args.shard {
        Some(shard) => out::part_head(&study, shard, range.clone())?,
        None => out::header_row(&study)?,
    };
    let table = args
        .output
        .as_deref()
        .map(|path| OutFile::create(path, &head))
        .transpose()?;
    let records = args
        .shard
        .is_none()
        .then(|| CaseRecords::with_capacity(range.len()));
    let mut sink = Sink {
        study: &study,
        table,
        records,
    };
    print_scenario_warnings(Some("base scenario"), &study.base_scenario);
    let bar = super::styled_bar("cases");
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    workflow::study::run_blocks(
        &study,
        range.clone(),
        args.threads.map(usize::from),
        &progress,
        |block| sink.take(&block),
    )?;
    bar.finish_and_clear();

    if let Some((k, n)) = args.shard {
        if let Some(table) = sink.table {
            table.finish()?;
        }
        eprintln!(
            "shard {k}/{n}: cases {}..{} of {total} written; join the parts with `sealsim \
             study merge`",
            range.start, range.end
        );
        return Ok(());
    }
    finish(sink, &args.outputs)
}

/// An output written as it comes (the per-case table, the summary JSON), with where it goes
/// for the messages.
struct OutFile {
    file: StagedFile,
    path: PathBuf,
}

impl OutFile {
    /// The output at `path`, `head` written.
    fn create(path: &Path, head: &[u8]) -> Result<Self, CliError> {
        let error = |source| CliError::Output {
            target: path.display().to_string(),
            source,
        };
        let mut file = StagedFile::create(path).map_err(error)?;
        file.write_all(head).map_err(error)?;
        Ok(OutFile {
            file,
            path: path.to_path_buf(),
        })
    }

    fn error(&self, source: std::io::Error) -> CliError {
        CliError::Output {
            target: self.path.display().to_string(),
            source,
        }
    }

    /// The output put in place (staged with the command's other outputs).
    fn finish(self) -> Result<(), CliError> {
        let target = self.path.display().to_string();
        self.file
            .finish()
            .map_err(|source| CliError::Output { target, source })
    }
}

/// Where a study's cases go as their blocks come: the rows to the table (if one is asked
/// for), the summary's records (a run, a merge; not a shard). The outcomes are not kept.
struct Sink<'a> {
    study: &'a Study,
    table: Option<OutFile>,
    records: Option<CaseRecords>,
}

impl Sink<'_> {
    /// One block of cases, in case order.
    fn take(&mut self, block: &[CaseOutcome]) -> Result<(), CliError> {
        if let Some(table) = &mut self.table {
            let rows = out::case_rows(self.study, block)?;
            if let Err(e) = table.file.write_all(&rows) {
                return Err(table.error(e));
            }
        }
        if let Some(records) = &mut self.records {
            for case in block {
                records.push(case);
            }
        }
        Ok(())
    }
}

/// Renders the summary's outputs, then writes: the table, the summary, the charts, the
/// terminal summary.
fn finish(sink: Sink<'_>, outputs: &SummaryOutputs) -> Result<(), CliError> {
    let study = sink.study;
    let summary = sink.records.unwrap_or_default().summary(study.confidence);
    // a chart is drawn for its own file or for the report
    let chart =
        |path: Option<&Path>,
         draw: fn(&Study, &StudySummary) -> Result<String, crate::report::plot::PlotError>|
         -> Option<String> {
            if path.is_none() && outputs.report.is_none() {
                return None;
            }
            match draw(study, &summary) {
                Ok(svg) => Some(svg),
                Err(e) => {
                    let target =
                        path.map_or_else(String::new, |p| format!(" written to {}", p.display()));
                    eprintln!("warning: no chart{target}: {e}");
                    None
                }
            }
        };
    let survival = chart(outputs.survival_plot.as_deref(), charts::survival_chart);
    let tornado = chart(outputs.tornado_plot.as_deref(), charts::tornado_chart);
    let text = out::summary_table(study, &summary);
    let page = outputs.report.as_ref().map(|_| {
        out::report_page(
            study,
            &summary,
            &text,
            survival.as_deref(),
            tornado.as_deref(),
        )
    });
    let survival_file = super::plot_file(outputs.survival_plot.as_deref(), survival.as_deref())?;
    let tornado_file = super::plot_file(outputs.tornado_plot.as_deref(), tornado.as_deref())?;
    if let Some(table) = sink.table {
        table.finish()?;
    }
    if let Some(path) = outputs.summary.as_deref() {
        // written as it is rendered: its survival curve has up to a step per case
        let mut json = OutFile::create(path, b"")?;
        if let Err(e) = out::write_summary_json(study, &summary, &mut json.file) {
            return Err(json.error(e.into()));
        }
        json.finish()?;
    }
    for (path, bytes) in [
        (outputs.survival_plot.as_deref(), survival_file.as_deref()),
        (outputs.tornado_plot.as_deref(), tornado_file.as_deref()),
        (
            outputs.report.as_deref(),
            page.as_deref().map(str::as_bytes),
        ),
    ] {
        if let (Some(path), Some(bytes)) = (path, bytes) {
            write_output(Some(path), bytes)?;
        }
    }
    write_output(None, text.as_bytes())
}

fn merge(args: MergeArgs) -> Result<(), CliError> {
    let study = Study::load(&args.study)?;
    let inputs: Vec<&Path> = [args.study.as_path(), study.base_path.as_path()]
        .into_iter()
        .chain(study.base_scenario.inputs.iter().map(PathBuf::as_path))
        .chain(args.parts.iter().map(PathBuf::as_path))
        .collect();
    let o = &args.outputs;
    super::guard_outputs(
        &inputs,
        &[
            ("-o", args.output.as_deref()),
            ("--summary", o.summary.as_deref()),
            ("--survival-plot", o.survival_plot.as_deref()),
            ("--tornado-plot", o.tornado_plot.as_deref()),
            ("--report", o.report.as_deref()),
        ],
    )?;
    if let Some(path) = args.output.as_deref() {
        super::expect_extension("-o", path, &["csv"])?;
    }
    let order = part_order(&study, &args)?;
    let table = args
        .output
        .as_deref()
        .map(|path| OutFile::create(path, &out::header_row(&study)?))
        .transpose()?;
    let mut sink = Sink {
        study: &study,
        table,
        records: Some(CaseRecords::with_capacity(study.cases())),
    };
    let design = study.plan.sampler();
    // the parts one at a time, in case order: each read, checked and handed on in blocks
    for (range, p) in order {
        let path = &args.parts[p];
        let mut reader = open_part(path)?;
        if out::part_cases(&study, path, &mut reader)? != range {
            return Err(CliError::Input(format!(
                "{}: the part file changed while it was merged",
                path.display()
            )));
        }
        out::read_part(
            &study,
            &design,
            path,
            reader,
            (range, workflow::study::BLOCK),
            |block| sink.take(&block),
        )?;
    }
    finish(sink, &args.outputs)
}

/// A part file, buffered.
fn open_part(path: &Path) -> Result<std::io::BufReader<std::fs::File>, CliError> {
    std::fs::File::open(path)
        .map(std::io::BufReader::new)
        .map_err(|e| {
            CliError::Input(format!(
                "{}: cannot read the part file: {e}",
                path.display()
            ))
        })
}

/// The parts of a merge in case order — `(cases, index in args.parts)` — from their first
/// lines, which must name the study and, together, every case once.
fn part_order(study: &Study, args: &MergeArgs) -> Result<Vec<(Range<usize>, usize)>, CliError> {
    let mut order = Vec::with_capacity(args.parts.len());
    for (p, path) in args.parts.iter().enumerate() {
        let range = out::part_cases(study, path, &mut open_part(path)?)?;
        order.push((range, p));
    }
    // an empty part (a shard of more shards than cases) holds nothing to place
    order.retain(|(range, _)| !range.is_empty());
    order.sort_by_key(|(range, p)| (range.start, *p));
    let mut next = 0;
    let (mut missing, mut first_missing) = (0, None);
    for k in 0..order.len() {
        let (range, p) = &order[k];
        if range.start < next {
            let (_, q) = &order[k - 1];
            return Err(CliError::Input(format!(
                "{}: case {} is also in {}: a part given twice, or parts of different \
                 shardings",
                args.parts[*p].display(),
                range.start,
                args.parts[*q].display()
            )));
        }
        if range.start > next {
            missing += range.start - next;
            first_missing.get_or_insert(next);
        }
        next = range.end;
    }
    if next < study.cases() {
        missing += study.cases() - next;
        first_missing.get_or_insert(next);
    }
    if let Some(first) = first_missing {
        return Err(CliError::Input(format!(
            "{}: {missing} of its {} cases are in no part (the first: case {first}); give every \
             shard's part file",
            args.study.display(),
            study.cases()
        )));
    }
    Ok(order)
}

fn slurm(args: SlurmArgs) -> Result<(), CliError> {
    let study = Study::load(&args.study)?;
    let absolute = |p: &Path| -> Result<PathBuf, CliError> {
        std::path::absolute(p).map_err(|e| CliError::Input(format!("{}: {e}", p.display())))
    };
    let study_path = absolute(&args.study)?;
    let results = match &args.results {
        Some(d) => absolute(d)?,
        None => {
            let stem = study_path
                .file_stem()
                .map_or_else(|| "study".into(), |s| s.to_string_lossy().into_owned());
            study_path.with_file_name(format!("{stem}-slurm"))
        }
    };
    let sealsim = match &args.sealsim {
        Some(p) => absolute(p)?,
        None => std::env::current_exe()
            .map_err(|e| CliError::Internal(format!("cannot locate this binary: {e}")))?,
    };
    // the script must never replace the study, its base scenario or a file the base reads
    let inputs: Vec<&Path> = [args.study.as_path(), study.base_path.as_path()]
        .into_iter()
        .chain(study.base_scenario.inputs.iter().map(PathBuf::as_path))
        .collect();
    super::guard_outputs(&inputs, &[("-o", args.output.as_deref())])?;
    let shards = (args.shards as usize).min(study.cases().max(1));
    let script = out::slurm_script(&out::SlurmJob {
        study: &study,
        study_path: &study_path,
        sealsim: &sealsim,
        results: &results,
        shards,
        cpus_per_task: args.cpus_per_task.into(),
        partition: args.partition.as_deref(),
        time: args.time.as_deref(),
    });
    write_output(args.output.as_deref(), script.as_bytes())
}
