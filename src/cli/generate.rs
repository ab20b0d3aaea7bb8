//! `sealsim generate …`: files generated from the code's own definitions, so that the
//! documentation cannot drift from it. `generate keys [-o FILE]` renders the scenario key
//! reference (`docs/src/reference/keys.md`) from the key registry
//! ([`crate::scenario::keys`]), `generate columns` the CSV column reference
//! (`docs/src/reference/columns.md`) from [`crate::report::columns`]; tests check that the
//! committed files are what they render.

use super::{CliError, write_output};
use clap::{Args, Subcommand};
use std::path::PathBuf;

/// Arguments of `sealsim generate`.
#[derive(Debug, Clone, Args)]
pub struct GenerateArgs {
    #[command(subcommand)]
    pub what: Generated,
}

/// What `sealsim generate` writes.
#[derive(Debug, Clone, Subcommand)]
pub enum Generated {
    /// The scenario key reference in Markdown (docs/src/reference/keys.md), from the key
    /// registry.
    #[command(hide = true)]
    Keys(OutputArgs),
    /// The CSV column reference in Markdown (docs/src/reference/columns.md), from the column
    /// registry.
    #[command(hide = true)]
    Columns(OutputArgs),
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
        Generated::Keys(out) => write_output(
            out.output.as_deref(),
            crate::scenario::keys::markdown().as_bytes(),
        ),
        Generated::Columns(out) => write_output(
            out.output.as_deref(),
            crate::report::columns::markdown().as_bytes(),
        ),
    }
}
