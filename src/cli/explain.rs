//! `sealsim explain [CODE]`: the long explanation of a warning's code (`W001` …) or a note's
//! (`N001` …), with the section of docs/model.md that defines it; without a code, the list of
//! every code. All from the one registry, [`crate::codes`].

use super::CliError;
use crate::codes::{self, Code, Kind};
use std::io::Write;

/// Arguments of `sealsim explain`.
#[derive(Debug, Clone, clap::Args)]
pub struct ExplainArgs {
    /// The code a warning or note printed (`W001`, `w001`, `N001`); without one, every code is
    /// listed.
    #[arg(value_name = "CODE")]
    pub code: Option<String>,
}

/// Runs `sealsim explain`.
pub fn run(args: ExplainArgs) -> Result<(), CliError> {
    let text = match args.code.as_deref() {
        None => list(),
        Some(code) => match codes::lookup(code) {
            Some(c) => explanation(c),
            None => {
                return Err(CliError::Input(format!(
                    "unknown code {code:?}: the codes are W001 … and N001 … \
                     (`sealsim explain` lists them all)"
                )));
            }
        },
    };
    let mut out = std::io::stdout().lock();
    // a closed pipe (`| head`) is not an error of the explanation
    let _ = out.write_all(text.as_bytes());
    Ok(())
}

/// What a kind of code is, in a phrase.
fn kind_phrase(kind: Kind) -> &'static str {
    match kind {
        Kind::Validity => "validity limit of the model (a `warning`, the result still computed)",
        Kind::Input => "input warning (the scenario is accepted, the value is questionable)",
        Kind::Note => "note (how an input was read; shown with --verbose)",
    }
}

/// The long explanation of one code.
pub fn explanation(c: &Code) -> String {
    format!(
        "{} {}: {}\n{}\n\n{}\n\nSee docs/model.md {} (the model reference).\n",
        c.code,
        c.id,
        c.title,
        kind_phrase(c.kind),
        wrap(c.explanation, 96),
        c.section
    )
}

/// Every code, one line each.
fn list() -> String {
    let mut out = String::new();
    for c in codes::ALL {
        out += &format!(
            "{}  {:<30} {} (docs/model.md {})\n",
            c.code, c.id, c.title, c.section
        );
    }
    out + "\n`sealsim explain CODE` prints one code's explanation.\n"
}

/// `text` wrapped at `width` characters on spaces.
fn wrap(text: &str, width: usize) -> String {
    let mut out = String::new();
    let mut line = 0;
    for word in text.split_whitespace() {
        let n = word.chars().count();
        if line > 0 && line + 1 + n > width {
            out.push('\n');
            line = 0;
        } else if line > 0 {
            out.push(' ');
            line += 1;
        }
        out += word;
        line += n;
    }
    out
}

/// The guide's warnings page (`docs/src/reference/warnings.md`, `sealsim generate warnings`),
/// from the registry.
pub fn markdown() -> String {
    let mut out = String::from(
        "<!-- Generated from crates/sealsim-core/src/codes.rs by `sealsim generate warnings -o \
         docs/src/reference/warnings.md`; do not edit by hand. -->\n\n\
         # Warnings and their codes\n\n\
         Every warning sealsim prints has a stable code, defined once in \
         `crates/sealsim-core/src/codes.rs`: `W001`–`W029` the validity limits of the model \
         (`crates/sealsim-core/src/validity.rs`, explained in [docs/model.md](../model/index.md) \
         §9), evaluated the same way by `leak`, `run`, `compare`, `tradeoff` and `figures`; \
         `W030`– the scenario's input warnings; `N001`– the notes that say how an input was \
         read. On stderr each warning is one line of at most 120 characters:\n\n\
         ```text\n\
         warning[W001]: ΔP/P0 = 1 > 0.5 from 350 d (worst 10 y): fluid pressure comparable to the contact … — sealsim explain W001\n\
         warning[W034]: g.toml:17: seal.groove_width: gland fill above the 85 %/90 % guidance — sealsim explain W034\n\
         ```\n\n\
         A validity line gives the quantity at its worst against its bound, where it was first \
         crossed and where it was worst (the time of a life step, the nominal pressure of a \
         static point); an input line gives the file's name, the line and the key. \
         `sealsim explain CODE` prints the explanation below; `--verbose` (`run`, `compare`, \
         `leak`) prints every warning in full, and the notes. The HTML report and the JSON \
         summary keep the full text: the summary's `warnings` are the validity findings as \
         records (`code`, `id`, `quantity`, `unit`, `value`, `bound`, `at`, `worst_time_s`, \
         `first_time_s` or `worst_nominal_pressure_Pa`, `evaluations`, `section`, `message`), \
         its `input_warnings` the input warnings and notes (`code`, `id`, `kind`, `message`). \
         In Python each is issued with `warnings.warn` as a `sealsim.ValidityWarning` or \
         `sealsim.InputWarning` carrying `.code`.\n\n\
         A code is never reused for another meaning.\n\n\
         | code | id | what | docs/model.md |\n|---|---|---|---|\n",
    );
    for c in codes::ALL {
        out += &format!(
            "| [`{}`](#{}) | `{}` | {} | {} |\n",
            c.code,
            c.code.to_ascii_lowercase(),
            c.id,
            c.title,
            c.section
        );
    }
    for c in codes::ALL {
        out += &format!(
            "\n## {}\n\n`{}` — {}; a {}.\n\n{}\n\nModel reference: docs/model.md {}.\n",
            c.code,
            c.id,
            c.title,
            kind_phrase(c.kind),
            c.explanation,
            c.section
        );
    }
    out
}
