//! `sealsim generate …`: files generated from the code's own definitions, so that the
//! documentation cannot drift from the program. From the one clap definition of the commands
//! ([`super::Cli`]): man pages (roff, by clap_mangen: `sealsim.1` and one `sealsim-COMMAND.1`
//! per command and subcommand) and shell completion scripts (by clap_complete). Hidden, for the
//! guide: `generate keys [-o FILE]` renders the scenario key reference
//! (`docs/src/reference/keys.md`) from the key registry ([`crate::scenario::keys`]), `generate
//! columns` the CSV column reference (`docs/src/reference/columns.md`) from
//! [`crate::report::columns`], `generate warnings` the warnings page
//! (`docs/src/reference/warnings.md`) from [`crate::codes`]; tests check that the committed files are what they render.

use super::{CliError, write_output};
use clap::{Args, CommandFactory, Subcommand};
use std::path::{Path, PathBuf};

/// Arguments of `sealsim generate`.
#[derive(Debug, Clone, Args)]
pub struct GenerateArgs {
    #[command(subcommand)]
    pub what: Generate,
}

/// What to generate.
#[derive(Debug, Clone, Subcommand)]
pub enum Generate {
    /// Man pages: sealsim.1 and one sealsim-COMMAND.1 per command, written into a folder
    /// (install with e.g. `sealsim generate man --out-dir ~/.local/share/man/man1`).
    Man {
        /// The folder to write the pages into (created if missing).
        #[arg(long, value_name = "DIR")]
        out_dir: PathBuf,
    },
    /// A shell completion script on standard output, or in FILE with -o (bash: `source <(sealsim
    /// generate completions bash)`).
    Completions {
        /// The shell.
        #[arg(value_enum)]
        shell: clap_complete::Shell,
        /// Write the script to FILE instead of standard output.
        #[arg(short, long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
    /// The scenario key reference in Markdown (docs/src/reference/keys.md), from the key
    /// registry.
    #[command(hide = true)]
    Keys(OutputArgs),
    /// The CSV column reference in Markdown (docs/src/reference/columns.md), from the column
    /// registry.
    #[command(hide = true)]
    Columns(OutputArgs),
    /// The warnings page in Markdown (docs/src/reference/warnings.md), from the code registry.
    #[command(hide = true)]
    Warnings(OutputArgs),
}

/// Where a generated file goes.
#[derive(Debug, Clone, Args)]
pub struct OutputArgs {
    /// Write to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// Runs `sealsim generate`.
pub fn run(args: GenerateArgs) -> Result<(), CliError> {
    match args.what {
        Generate::Man { out_dir } => man_pages(&out_dir),
        Generate::Completions { shell, output } => {
            let mut command = super::Cli::command();
            let mut script = Vec::new();
            clap_complete::generate(shell, &mut command, "sealsim", &mut script);
            write_output(output.as_deref(), &script)
        }
        Generate::Keys(out) => write_output(
            out.output.as_deref(),
            crate::scenario::keys::markdown().as_bytes(),
        ),
        Generate::Columns(out) => write_output(
            out.output.as_deref(),
            crate::report::columns::markdown().as_bytes(),
        ),
        Generate::Warnings(out) => {
            write_output(out.output.as_deref(), super::explain::markdown().as_bytes())
        }
    }
}

/// Every page: the top level and, recursively, each visible subcommand, named by its path
/// (`sealsim-study-merge.1`). Rendered first and written only when all rendered.
fn man_pages(out_dir: &Path) -> Result<(), CliError> {
    let mut command = super::Cli::command();
    command.build();
    let mut pages = Vec::new();
    render(&command, "sealsim", &mut pages)?;
    std::fs::create_dir_all(out_dir).map_err(|source| CliError::Output {
        target: out_dir.display().to_string(),
        source,
    })?;
    for (name, page) in &pages {
        write_output(Some(&out_dir.join(name)), page)?;
    }
    eprintln!("wrote {} man pages into {}", pages.len(), out_dir.display());
    Ok(())
}

fn render(
    command: &clap::Command,
    name: &str,
    pages: &mut Vec<(String, Vec<u8>)>,
) -> Result<(), CliError> {
    let mut page = Vec::new();
    clap_mangen::Man::new(command.clone().display_name(name.to_owned()))
        .render(&mut page)
        .map_err(|e| CliError::Internal(format!("man page {name}: {e}")))?;
    pages.push((format!("{name}.1"), page));
    for sub in command.get_subcommands().filter(|s| !s.is_hide_set()) {
        if sub.get_name() == "help" {
            continue;
        }
        render(sub, &format!("{name}-{}", sub.get_name()), pages)?;
    }
    Ok(())
}
