//! `sealsim sizes [SIZE] [--json]`: the AS568 O-ring size table — one size's dimensions (inch
//! and mm, with tolerances and the table's source line), or every size. An unknown size exits
//! with status 2 and lists the nearest sizes.

use super::{CliError, write_output};
use crate::report::sizes::{describe, size_json, table, table_json};
use crate::scenario::as568;
use clap::Args;

/// Arguments of `sealsim sizes`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Sizes are named AS568-NNN (case-insensitive), e.g. AS568-214. Inch values are \
    as transcribed; mm = inch × 25.4 exactly. The table (src/scenario/as568.csv) covers -001…-050, \
    -102…-178, -201…-284, -309…-390 and -425…-467; its header states the source and corrections."
)]
pub struct SizesArgs {
    /// The size, e.g. AS568-214 (without it: every size).
    #[arg(value_name = "SIZE")]
    pub size: Option<String>,

    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// Runs `sealsim sizes`.
pub fn run(args: SizesArgs) -> Result<(), CliError> {
    let text = match &args.size {
        Some(name) => {
            let size = as568::lookup(name).map_err(|e| match e {
                as568::LookupError::Table(t) => CliError::Internal(t.to_string()),
                other => CliError::Input(other.to_string()),
            })?;
            if args.json {
                size_json(&size)?
            } else {
                describe(&size)
            }
        }
        None => {
            let sizes = as568::sizes().map_err(|e| CliError::Internal(e.to_string()))?;
            if args.json {
                table_json(sizes)?
            } else {
                table(sizes)
            }
        }
    };
    write_output(None, text.as_bytes())
}
