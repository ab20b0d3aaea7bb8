//! `sealsim advise`: what would make a scenario meet a life target — the sensitivity of the
//! verdict to each design variable, and the smallest changes (alone and in pairs) that meet
//! `--life`, each verified by a full run (docs/model.md §16).

use super::{CliError, write_output};
use crate::report::advise as out;
use crate::scenario::Scenario;
use crate::workflow::advise::{self, Options};
use clap::Args;
use std::path::{Path, PathBuf};

/// Arguments of `sealsim advise`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "The design variables, where they apply to the seal: the compound \
    (library compounds rated A or B for the fluid), the squeeze (groove depth or squeeze), the \
    groove width, back-up rings (piston and rod glands), the finish (finer only, to Ra 0.05 µm), \
    a flat seal's seating stress and compression. The temperature and the pressure are the \
    service: their sensitivity is printed, never proposed. A value the validator refuses, or \
    one that breaks a handbook limit the scenario keeps, is never proposed. Exit 0 whatever the \
    advice (\"no change within the bounds passes\" included)."
)]
pub struct AdviseArgs {
    /// Scenario file (TOML).
    #[arg(value_name = "SCENARIO")]
    pub scenario: PathBuf,

    /// The life to meet, a time with its unit: "10y", "10 year", "87600 h".
    #[arg(long, value_name = "TIME", allow_hyphen_values = true)]
    pub life: String,

    /// At most N life runs (search and verification).
    #[arg(long, value_name = "N", default_value_t = advise::DEFAULT_MAX_RUNS as u32,
          value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub max_runs: u32,

    /// Worker threads (default: all cores); the advice is the same on any number.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u16).range(1..))]
    pub threads: Option<u16>,

    /// Write the advice as JSON (SI) to FILE.
    #[arg(long, value_name = "FILE.json")]
    pub json: Option<PathBuf>,

    /// Write each proposal as a runnable scenario into DIR (`<stem>-advise-<n>.toml`).
    #[arg(long, value_name = "DIR")]
    pub write: Option<PathBuf>,
}

/// `--life TIME`: a positive time \[s\], or a bad-input error naming the flag.
pub fn life_flag(text: &str) -> Result<f64, CliError> {
    super::positive_flag(Some(text), "life", crate::units::Dimension::TIME)?
        .ok_or_else(|| CliError::Input("--life: a time is required".into()))
}

/// Runs `sealsim advise`.
pub fn run(args: AdviseArgs) -> Result<(), CliError> {
    let target = life_flag(&args.life)?;
    let text = std::fs::read_to_string(&args.scenario).map_err(|e| {
        CliError::Input(format!(
            "{}: cannot read the scenario: {e}",
            args.scenario.display()
        ))
    })?;
    let base = Scenario::from_str(&text, &args.scenario)?;
    let mut inputs: Vec<&Path> = vec![args.scenario.as_path()];
    inputs.extend(base.inputs.iter().map(PathBuf::as_path));
    super::guard_outputs(&inputs, &[("--json", args.json.as_deref())])?;
    super::print_scenario_warnings(None, &base);

    let options = Options {
        target,
        target_text: args.life.trim().to_owned(),
        max_runs: args.max_runs as usize,
        threads: args.threads.map(usize::from),
    };
    let bar = super::styled_bar("life runs");
    let progress = |done: usize, total: usize| {
        bar.set_length(total as u64);
        bar.set_position(done as u64);
    };
    let advice = advise::advise(&text, &args.scenario, &base, &options, &progress)?;
    bar.finish_and_clear();

    let file = args.scenario.display().to_string();
    let json = args
        .json
        .as_ref()
        .map(|_| out::json(&advice, &file))
        .transpose()
        .map_err(CliError::Internal)?;
    // every proposal file rendered, named and checked before anything is written
    let files = match &args.write {
        Some(dir) => proposal_files(&advice, &args.scenario, dir, &inputs)?,
        None => Vec::new(),
    };
    if let Some(dir) = &args.write {
        std::fs::create_dir_all(dir).map_err(|source| CliError::Output {
            target: dir.display().to_string(),
            source,
        })?;
    }
    for (path, bytes) in &files {
        write_output(Some(path), bytes.as_bytes())?;
    }
    if let (Some(path), Some(json)) = (&args.json, &json) {
        write_output(Some(path), json.as_bytes())?;
    }
    let mut text = out::text(&advice, &file);
    if let Some(dir) = &args.write {
        text += &format!(
            "{} proposal{} written to {}\n",
            files.len(),
            if files.len() == 1 { "" } else { "s" },
            dir.display()
        );
    }
    write_output(None, text.as_bytes())
}

/// Each proposal's file in `dir`: its path and text. A proposal that would not validate where
/// it is written (a file it reads by a relative path) is an error before anything is written;
/// so is a name that is an input.
fn proposal_files(
    advice: &advise::Advice,
    scenario: &Path,
    dir: &Path,
    inputs: &[&Path],
) -> Result<Vec<(PathBuf, String)>, CliError> {
    let stem = scenario
        .file_stem()
        .map_or_else(|| "scenario".into(), |s| s.to_string_lossy().into_owned());
    let file = scenario.display().to_string();
    let mut files = Vec::new();
    for (i, p) in advice.proposals.iter().enumerate() {
        let path = dir.join(format!("{stem}-advise-{}.toml", i + 1));
        let text = out::scenario_file(advice, p, &file);
        Scenario::from_str(&text, &path).map_err(|e| {
            CliError::Input(format!(
                "--write {}: the proposal does not validate there ({e}); the scenario reads \
                 files by relative paths: write into its own directory",
                dir.display()
            ))
        })?;
        files.push((path, text));
    }
    let outputs: Vec<(&str, Option<&Path>)> = files
        .iter()
        .map(|(p, _)| ("--write", Some(p.as_path())))
        .collect();
    super::guard_outputs(inputs, &outputs)?;
    Ok(files)
}
