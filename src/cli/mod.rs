//! The `sealsim` command line: argument parsing (clap derive), dispatch, exit codes.
//!
//! Each subcommand lives in its own module with an `Args` struct and a
//! `run(args) -> Result<(), CliError>`; adding one means a variant in [`Command`] and an arm in
//! [`run()`]. Exit status: 0 success, 2 bad input (usage, flag values, scenario files), 1 failure
//! to write the output or an internal error.

pub mod advise;
pub mod ageing_fit;
pub mod compare;
pub mod explain;
pub mod figures;
pub mod fit_prony;
pub mod generate;
pub mod gland;
pub mod leak;
pub mod materials;
pub mod new;
pub mod run;
pub mod sizes;
pub mod study;
pub mod surface;
pub mod tradeoff;

use crate::report::{self, ReportError};
use crate::scenario::ScenarioError;
use clap::{Parser, Subcommand};
use std::fmt;
use std::io::{self, Write};
use std::path::Path;

/// A progress reporter for long work (the numerical level): an indicatif bar on stderr, which
/// indicatif hides when stderr is not a terminal. `report(done, total)` as the physics calls it.
pub(crate) fn progress_bar(what: &str) -> impl FnMut(usize, usize) {
    let bar = styled_bar(what);
    move |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
        if done >= total {
            bar.finish_and_clear();
        }
    }
}

/// The bar behind [`progress_bar`]: `what [====>   ] done/total (elapsed, ~ETA left)`, for
/// callers that report from several threads (its methods take `&self`).
pub(crate) fn styled_bar(what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{msg} [{bar:30}] {pos}/{len} ({elapsed}, ~{eta} left)",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    bar.set_message(what.to_owned());
    bar
}

/// Whether `--verbose` was given: the full text of every warning, and the notes.
static VERBOSE: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Sets `--verbose` for the warnings and notes printed from now on.
pub(crate) fn set_verbose(verbose: bool) {
    VERBOSE.store(verbose, std::sync::atomic::Ordering::Relaxed);
}

fn verbose() -> bool {
    VERBOSE.load(std::sync::atomic::Ordering::Relaxed)
}

/// Prints validity findings to stderr, one `warning[W0xx]:` line each of at most 120 characters
/// (in full with `--verbose`), `context` (e.g. a compound's id) leading each line.
pub(crate) fn print_findings(context: Option<&str>, findings: &crate::validity::Findings) {
    if verbose() {
        eprint!("{}", report::findings::warning_lines(context, findings));
    } else {
        eprint!("{}", report::findings::short_lines(context, findings));
    }
}

/// Prints one input warning (short, or in full with `--verbose`); a note only with `--verbose`.
fn print_input(context: Option<&str>, w: &crate::scenario::InputWarning) {
    if verbose() {
        eprintln!("{}", report::findings::input_line(context, w));
    } else if !w.is_note() {
        eprintln!("{}", report::findings::input_short(context, w));
    }
}

/// Prints a scenario's input warnings (e.g. a gland fill above the guidance) to stderr, one
/// `warning[W0xx]:` line each, `context` (e.g. a compound's id) leading each line.
pub(crate) fn print_scenario_warnings(context: Option<&str>, scenario: &crate::scenario::Scenario) {
    for w in &scenario.warnings {
        print_input(context, w);
    }
}

/// Prints the input messages of several variants of one scenario (`compare`'s compounds)
/// once each: a message every variant has without context, the others led by the variants
/// that have it (`nbr-70, fkm-75: …`).
pub(crate) fn print_shared_warnings<'a>(
    variants: impl IntoIterator<Item = (&'a str, &'a crate::scenario::Scenario)>,
) {
    let variants: Vec<(&str, &crate::scenario::Scenario)> = variants.into_iter().collect();
    let mut seen: Vec<&str> = Vec::new();
    for (_, scenario) in &variants {
        for w in &scenario.warnings {
            if seen.contains(&w.text.as_str()) {
                continue;
            }
            seen.push(&w.text);
            let having: Vec<&str> = variants
                .iter()
                .filter(|(_, s)| s.warnings.contains(w))
                .map(|(label, _)| *label)
                .collect();
            let context = (having.len() < variants.len()).then(|| having.join(", "));
            print_input(context.as_deref(), w);
        }
    }
}

/// `--fidelity LEVEL` of every command: the levels, their aliases and help all come from
/// [`Fidelity::ALL`](crate::leak::Fidelity::ALL), so no command's help can miss one. (A value
/// parser rather than `clap::ValueEnum` on `Fidelity`: the type lives in `sealsim-core`, which
/// knows no command line.)
#[derive(Debug, Clone, Copy)]
pub struct FidelityArg;

impl FidelityArg {
    fn possible_value(level: &crate::leak::Fidelity) -> clap::builder::PossibleValue {
        let aliases = level.aliases();
        let help = match aliases {
            [] => level.description().to_owned(),
            _ => format!("{} (alias: {})", level.description(), aliases.join(", ")),
        };
        clap::builder::PossibleValue::new(level.name())
            .aliases(aliases.iter().copied())
            .help(help)
    }
}

impl clap::builder::TypedValueParser for FidelityArg {
    type Value = crate::leak::Fidelity;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<Self::Value, clap::Error> {
        // clap's own parser for the listed values gives its usual error and suggestions
        let values: Vec<_> = crate::leak::Fidelity::ALL
            .iter()
            .map(Self::possible_value)
            .collect();
        let text = clap::builder::PossibleValuesParser::new(values).parse_ref(cmd, arg, value)?;
        crate::leak::Fidelity::ALL
            .into_iter()
            .find(|level| level.name() == text || level.aliases().contains(&text.as_str()))
            .ok_or_else(|| clap::Error::new(clap::error::ErrorKind::InvalidValue).with_cmd(cmd))
    }

    fn possible_values(
        &self,
    ) -> Option<Box<dyn Iterator<Item = clap::builder::PossibleValue> + '_>> {
        Some(Box::new(
            crate::leak::Fidelity::ALL.iter().map(Self::possible_value),
        ))
    }
}

/// Exit status for bad input, the same as clap's for usage errors.
pub const EXIT_BAD_INPUT: i32 = 2;
/// Exit status for a failure to write the output, or an internal error.
pub const EXIT_FAILURE: i32 = 1;

/// Leak rate of rubber seals from rough-surface contact mechanics (Persson & Yang 2008).
#[derive(Debug, Parser)]
#[command(name = "sealsim", version, about, propagate_version = true)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Seal-life simulation: leak rate, sealing force and failure over the seal's life.
    Run(run::RunArgs),
    /// The same life scenario with several compounds, side by side.
    Compare(compare::CompareArgs),
    /// What would make it pass: the sensitivity of the verdict to each design variable and the
    /// smallest changes (alone and in pairs) that meet a life target, each verified by a run.
    Advise(Box<advise::AdviseArgs>),
    /// Leak rate of the installed seal (the first state of `run`) at fluid pressure differences
    /// (--pressure-differences "50 bar, 210 bar") or at contact pressures, as CSV.
    Leak(leak::LeakArgs),
    /// Speed against accuracy: the scenario at every fidelity level and a ladder of numerical
    /// settings, with wall time and error against the most accurate setting.
    Tradeoff(tradeoff::TradeoffArgs),
    /// Data and SVG charts of groups of scenarios over a pressure sweep (PY08 §3 figures).
    Figures(figures::FiguresArgs),
    /// Prony series fitted to relaxation or DMA data, written as a material TOML file.
    FitProny(Box<fit_prony::FitPronyArgs>),
    /// Lifetime from accelerated-ageing data (ISO 11346): Arrhenius fit of the times to a
    /// compression-set or retained-force criterion, extrapolated to a service temperature.
    AgeingFit(ageing_fit::AgeingFitArgs),
    /// The material library: list, show, response curves, Abaqus/ANSYS export.
    Materials(materials::MaterialsArgs),
    /// AS568 O-ring sizes: one size's dimensions (inch and mm, tolerances, source), or all.
    Sizes(sizes::SizesArgs),
    /// The recommended gland of an AS568 ring for a service (face, piston, rod), with ISO 286
    /// fits and the tolerance stack-up (squeeze, stretch, OD compression, fill, clearance).
    Gland(Box<gland::GlandArgs>),
    /// A roughness source (scenario, line traces, PSD file): Ra, Rq, Rz, h_rms, rms slope,
    /// Hurst exponent, cut-offs and warnings, with an optional C(q) chart.
    Surface(surface::SurfaceArgs),
    /// Tolerances, uncertainty and sweeps: a study's cases in parallel, the time to failure as a
    /// distribution (survival curve, B1/B10/B50 lives, Weibull fit, what drives the life);
    /// shards, their merge and a Slurm job array for clusters.
    Study(Box<study::StudyArgs>),
    /// A commented, runnable scenario or study to start your own from (`--list` shows them).
    New(new::NewArgs),
    /// Documentation generated from the commands themselves: man pages and shell completions.
    Generate(generate::GenerateArgs),
    /// What a warning's code means (`sealsim explain W001`): its explanation and the model
    /// section; without a code, every code.
    Explain(explain::ExplainArgs),
}

/// Why a command failed; decides the exit status.
#[derive(Debug)]
pub enum CliError {
    /// A flag value or combination the user must fix.
    Input(String),
    /// The scenario (or a file it names) is invalid.
    Scenario(ScenarioError),
    /// The output could not be written.
    Output { target: String, source: io::Error },
    /// A bug: the result could not be reported faithfully.
    Internal(String),
    /// Not an error: the run succeeded and wrote everything, and the seal fails (or is open);
    /// the exit status `--fail-exit-code` asked for.
    SealFails(u8),
}

impl CliError {
    /// The process exit status for this error.
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Input(_) | CliError::Scenario(_) => EXIT_BAD_INPUT,
            CliError::Output { .. } | CliError::Internal(_) => EXIT_FAILURE,
            CliError::SealFails(code) => i32::from(*code),
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Input(msg) | CliError::Internal(msg) => f.write_str(msg),
            CliError::Scenario(e) => e.fmt(f),
            CliError::Output { target, source } => write!(f, "cannot write {target}: {source}"),
            CliError::SealFails(code) => write!(f, "the seal fails (exit status {code})"),
        }
    }
}

impl std::error::Error for CliError {}

impl From<ScenarioError> for CliError {
    fn from(e: ScenarioError) -> Self {
        CliError::Scenario(e)
    }
}

impl From<ReportError> for CliError {
    fn from(e: ReportError) -> Self {
        CliError::Internal(e.to_string())
    }
}

/// Runs the command line of this process; returns the exit status.
pub fn main() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // Usage errors go to stderr (exit 2), --help and --version to stdout (exit 0).
            let _ = e.print();
            return e.exit_code();
        }
    };
    handle_interrupts();
    crate::report::staging::begin();
    let result = run(cli.command);
    // every output of the command renamed together, or none of them
    let result = match result {
        Ok(()) | Err(CliError::SealFails(_)) => match crate::report::staging::commit() {
            Ok(()) => result,
            Err((target, source)) => Err(CliError::Output {
                target: target.display().to_string(),
                source,
            }),
        },
        Err(e) => {
            crate::report::staging::abandon();
            Err(e)
        }
    };
    match result {
        Ok(()) => 0,
        // a verdict, not an error: everything was written
        Err(e @ CliError::SealFails(_)) => e.exit_code(),
        Err(e) => {
            eprintln!("error: {e}");
            e.exit_code()
        }
    }
}

/// SIGINT and SIGTERM (and SIGHUP) end the process with 128 + the signal's number, as the
/// default action's status reads in a shell, after removing every temporary in flight
/// ([`crate::report::staging`]): an interrupted command leaves its previous outputs and
/// nothing else. If the handler thread cannot start, the default actions stay.
fn handle_interrupts() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return;
    };
    let _ = std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                // a progress bar's line is left open: end it before the note
                eprintln!(
                    "\nsealsim: interrupted (signal {signal}); outputs not yet in place removed"
                );
                crate::report::staging::remove_all_and_exit(128 + signal);
            }
        });
}

/// Dispatches to the subcommand.
pub fn run(command: Command) -> Result<(), CliError> {
    match command {
        Command::Run(args) => run::run(args),
        Command::Compare(args) => compare::run(args),
        Command::Advise(args) => advise::run(*args),
        Command::Leak(args) => leak::run(args),
        Command::Tradeoff(args) => tradeoff::run(args),
        Command::Figures(args) => figures::run(args),
        Command::FitProny(args) => fit_prony::run(*args),
        Command::AgeingFit(args) => ageing_fit::run(args),
        Command::Materials(args) => materials::run(args),
        Command::Sizes(args) => sizes::run(args),
        Command::Gland(args) => gland::run(*args),
        Command::Surface(args) => surface::run(args),
        Command::Study(args) => study::run(*args),
        Command::New(args) => new::run(args),
        Command::Generate(args) => generate::run(args),
        Command::Explain(args) => explain::run(args),
    }
}

/// A flag's positive quantity in SI (`None` when the flag is absent), or a bad-input error
/// naming the flag: `--name: …`.
pub(crate) fn positive_flag(
    value: Option<&str>,
    name: &str,
    dimension: crate::units::Dimension,
) -> Result<Option<f64>, CliError> {
    value
        .map(|text| {
            let v = crate::units::parse_quantity(text, dimension)
                .map_err(|e| CliError::Input(format!("--{name}: {e}")))?;
            if v.is_finite() && v > 0.0 {
                Ok(v)
            } else {
                Err(CliError::Input(format!(
                    "--{name}: must be positive, got {text}"
                )))
            }
        })
        .transpose()
}

/// `--fail-exit-code N` of `run` and `compare`: 3–125, so that a failed seal is never read as
/// bad input (2) or a write failure (1), nor as a shell's signal status (126 and above).
#[derive(Debug, Clone, Copy, clap::Args)]
pub struct FailExitCode {
    /// Exit with status N when the seal fails or is open (compare: when any compound does),
    /// after writing every output; without it a finished run exits 0 whatever the verdict.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(3..=125))]
    pub fail_exit_code: Option<u8>,
}

impl FailExitCode {
    /// `Err(SealFails(N))` when asked for and `fails`, `Ok` otherwise.
    pub fn verdict(self, fails: bool) -> Result<(), CliError> {
        match self.fail_exit_code {
            Some(code) if fails => Err(CliError::SealFails(code)),
            _ => Ok(()),
        }
    }
}

/// The file a path names, for comparing paths: the canonical path when it exists, else its
/// canonical directory joined with its name (an output not yet written; for a dangling link,
/// the target it would create, so that a link and its target are one output).
fn identity(path: &Path) -> std::path::PathBuf {
    if let Ok(p) = path.canonicalize() {
        return p;
    }
    let followed = match report::output_target(path) {
        Ok(report::OutputTarget::File { path, .. }) => path,
        _ => path.to_path_buf(),
    };
    let name = followed.file_name().map(std::ffi::OsStr::to_os_string);
    let dir = match followed.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    match (dir.canonicalize(), name) {
        (Ok(d), Some(n)) => d.join(n),
        _ => followed,
    }
}

/// Refuses an output the writer would not replace (exit 2, before anything runs): a symbolic
/// link loop, a block device, a read-only file or one this user may not write
/// ([`report::replace_refusal`]). A directory is left to the writer (exit 1, as before).
fn refuse_unwritable(flag: &str, path: &Path) -> Result<(), CliError> {
    if path.is_dir() {
        return Ok(());
    }
    let refusal = match report::output_target(path) {
        Ok(report::OutputTarget::File {
            path: target,
            existing: Some(meta),
        }) => report::replace_refusal(&target, &meta),
        Ok(_) => None,
        Err(e) if e.kind() == io::ErrorKind::InvalidInput => Some(e.to_string()),
        Err(_) => None, // unreadable metadata: the write reports it
    };
    match refusal {
        Some(why) => Err(CliError::Input(format!("{flag} {}: {why}", path.display()))),
        None => Ok(()),
    }
}

/// The formats an output flag writes, the first its own (`None`: the command decides, e.g.
/// `-o`, which is CSV for a history and TOML for a material).
fn flag_format(flag: &str) -> Option<&'static [&'static str]> {
    match flag {
        "--plot" | "--plot-master" | "--plot-shift" | "--survival-plot" | "--tornado-plot" => {
            Some(&report::plot::PLOT_EXTENSIONS)
        }
        "--report" => Some(&["html", "htm"]),
        "--summary" | "--json" => Some(&["json"]),
        _ => None,
    }
}

/// Refuses an output whose extension names another format than the flag writes (a `.png` plot
/// would hold SVG text, an `.xlsx` table CSV): exit 2 before anything runs. A path without an
/// extension (`/dev/stdout`, a pipe) is taken as asked.
pub(crate) fn expect_extension(flag: &str, path: &Path, formats: &[&str]) -> Result<(), CliError> {
    let Some(ext) = path.extension().and_then(std::ffi::OsStr::to_str) else {
        return Ok(());
    };
    if formats.iter().any(|f| f.eq_ignore_ascii_case(ext)) {
        return Ok(());
    }
    let fixed = path.with_extension(formats[0]);
    if formats == report::plot::PLOT_EXTENSIONS {
        // a chart: written in the format its extension names
        return Err(CliError::Input(format!(
            "{flag} {}: a chart is written as .svg, .png or .pdf (by the extension), not .{ext}; \
             name it {}, or .png or .pdf",
            path.display(),
            fixed.display()
        )));
    }
    Err(CliError::Input(format!(
        "{flag} {}: this output is {} and would not be a .{ext} file; name it {} (other \
         formats are not written: convert the {} file)",
        path.display(),
        formats[0].to_uppercase(),
        fixed.display(),
        formats[0].to_uppercase()
    )))
}

/// The bytes of the chart output `path` (`--plot x.png`): `svg` in the format its extension
/// names, SVG, PNG or PDF ([`report::plot::encode`]); `None` when either is absent.
pub(crate) fn plot_file(
    path: Option<&Path>,
    svg: Option<&str>,
) -> Result<Option<Vec<u8>>, CliError> {
    match (path, svg) {
        (Some(path), Some(svg)) => report::plot::encode_for(path, svg)
            .map(Some)
            .map_err(|e| CliError::Internal(e.to_string())),
        _ => Ok(None),
    }
}

/// Refuses, before anything runs, an output that would replace one of `inputs` or another
/// output of the same command, or that the writer would refuse (a read-only file, a link loop:
/// [`refuse_unwritable`]) (exit 2, nothing written): `outputs` are (flag, path) pairs. Every
/// command that writes a file calls it with all its inputs: the files named on the command
/// line and every data file a scenario read (`Scenario::inputs`).
pub(crate) fn guard_outputs(
    inputs: &[&Path],
    outputs: &[(&str, Option<&Path>)],
) -> Result<(), CliError> {
    let inputs: Vec<(std::path::PathBuf, &Path)> =
        inputs.iter().map(|p| (identity(p), *p)).collect();
    let mut seen: Vec<(std::path::PathBuf, &str)> = Vec::new();
    for (flag, path) in outputs {
        let Some(path) = path else { continue };
        let id = identity(path);
        if let Some((_, input)) = inputs.iter().find(|(i, _)| *i == id) {
            return Err(CliError::Input(format!(
                "{flag} {}: that is an input of this command ({}): writing it would replace \
                 it; give the output another name",
                path.display(),
                input.display()
            )));
        }
        if let Some((_, other)) = seen.iter().find(|(o, _)| *o == id) {
            return Err(CliError::Input(format!(
                "{flag} {}: {other} writes the same file; give each output its own name",
                path.display()
            )));
        }
        seen.push((id, flag));
    }
    for (flag, path) in outputs {
        if let Some(path) = path {
            refuse_unwritable(flag, path)?;
        }
    }
    // then the format a name promises (after the overwrites: the worse mistake first)
    for (flag, path) in outputs {
        if let (Some(path), Some(formats)) = (path, flag_format(flag)) {
            expect_extension(flag, path, formats)?;
        }
    }
    Ok(())
}

/// `--leak-floor RATE` as the volume flow the leak rates are counted in \[m³/s\] (`None`: the
/// flag is absent). A liquid takes a volume flow (m³/s, mL/h, mL/day, drops/min); a gas a
/// throughput in the leak-test trade's units (Pa·m³/s, mbar·L/s, atm·cc/s, std cc/s, sccm, slm,
/// mol/s, at the gas temperature), turned into the volume flow at the mean pressure it stands
/// for, Q/p̄ — or a volume flow, taken at p̄ (docs/model.md §15.2).
pub(crate) fn leak_floor_flag(
    text: Option<&str>,
    fluid: &crate::fluid::Fluid,
) -> Result<Option<f64>, CliError> {
    let Some(text) = text else { return Ok(None) };
    crate::workflow::leak::parse_leak_floor(text, fluid)
        .map(Some)
        .map_err(|message| CliError::Input(format!("--leak-floor: {message}")))
}

/// Writes a finished output: atomically to `path`, or to stdout.
pub(crate) fn write_output(path: Option<&Path>, bytes: &[u8]) -> Result<(), CliError> {
    match path {
        Some(path) => report::write_atomic(path, bytes).map_err(|source| CliError::Output {
            target: path.display().to_string(),
            source,
        }),
        None => {
            let mut out = io::stdout().lock();
            out.write_all(bytes)
                .and_then(|()| out.flush())
                .map_err(|source| CliError::Output {
                    target: "standard output".into(),
                    source,
                })
        }
    }
}
