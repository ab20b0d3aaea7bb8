//! `sealsim new TEMPLATE [-o FILE] [--base SCENARIO]` and `sealsim new --list`: a commented,
//! runnable scenario or study to start one's own from (the templates in
//! `scenarios/templates/`, listed by [`crate::scenario::templates::TEMPLATES`]).

use super::{CliError, write_output};
use crate::scenario::templates::{self, Template, TemplateKind};
use clap::Args;
use std::path::{Path, PathBuf};

/// Arguments of `sealsim new`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Each template runs unchanged (`sealsim run FILE`, or `sealsim study FILE` for \
    the study); every key's comment gives its SI unit, range and default. `sealsim new study -o \
    S.toml` also writes its base scenario beside it (S.base.toml, the o-ring-face template) \
    unless --base names an existing one. An existing file is never overwritten."
)]
pub struct NewArgs {
    /// The template (see --list).
    #[arg(value_name = "TEMPLATE", required_unless_present = "list",
          value_parser = clap::builder::PossibleValuesParser::new(
              templates::TEMPLATES.iter().map(|t| t.name)))]
    pub template: Option<String>,

    /// List the templates and what each models.
    #[arg(long, conflicts_with_all = ["template", "output", "base"])]
    pub list: bool,

    /// Write the template to FILE (refused if FILE exists) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// study: the base scenario the study varies, an existing scenario file (default: write
    /// the o-ring-face template beside the study as its base).
    #[arg(long, value_name = "SCENARIO")]
    pub base: Option<PathBuf>,
}

/// Runs `sealsim new`.
pub fn run(args: NewArgs) -> Result<(), CliError> {
    if args.list {
        return write_output(None, list().as_bytes());
    }
    let name = args.template.as_deref().unwrap_or_default();
    let template = templates::template(name).ok_or_else(|| {
        CliError::Input(format!("no template {name:?}: see `sealsim new --list`"))
    })?;
    if args.base.is_some() && template.kind != TemplateKind::Study {
        return Err(CliError::Input(format!(
            "--base: only the study template has a base scenario, not {name}"
        )));
    }
    match (template.kind, args.output.as_deref()) {
        (TemplateKind::Scenario, output) => {
            refuse_existing(output)?;
            write_output(output, template.text.as_bytes())
        }
        (TemplateKind::Study, None) => {
            let base = match &args.base {
                Some(base) => existing_base(base)?.display().to_string(),
                None => {
                    eprintln!(
                        "note: the study's base scenario is o-ring-face.toml beside it: write it \
                         with `sealsim new o-ring-face -o o-ring-face.toml`, or give --base"
                    );
                    "o-ring-face.toml".to_owned()
                }
            };
            write_output(None, templates::study_with_base(template, &base).as_bytes())
        }
        (TemplateKind::Study, Some(output)) => {
            study_to_file(template, output, args.base.as_deref())
        }
    }
}

/// `--list`: one line per template.
fn list() -> String {
    let width = templates::TEMPLATES
        .iter()
        .map(|t| t.name.len())
        .max()
        .unwrap_or(0);
    let mut text = String::new();
    for t in templates::TEMPLATES {
        text.push_str(&format!("{:width$}  {}\n", t.name, t.summary));
    }
    text.push_str("\nsealsim new TEMPLATE -o FILE writes one; sealsim run FILE runs it.\n");
    text
}

/// The study and, unless `base` names an existing scenario, its base beside it.
fn study_to_file(template: &Template, output: &Path, base: Option<&Path>) -> Result<(), CliError> {
    refuse_existing(Some(output))?;
    let folder = output.parent().filter(|p| !p.as_os_str().is_empty());
    let (base_text, written_base) = match base {
        Some(base) => {
            let base = existing_base(base)?;
            (relative_to(&base, folder.unwrap_or(Path::new("."))), None)
        }
        None => {
            let stem = output
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_else(|| "study".to_owned());
            let file_name = format!("{stem}.base.toml");
            let path = folder.map_or_else(|| PathBuf::from(&file_name), |f| f.join(&file_name));
            refuse_existing(Some(&path))?;
            (file_name, Some(path))
        }
    };
    let base_template = templates::template("o-ring-face")
        .ok_or_else(|| CliError::Internal("the o-ring-face template is missing".into()))?;
    // the base first: a study is never written naming a base that is not there
    if let Some(path) = &written_base {
        write_output(Some(path), base_template.text.as_bytes())?;
    }
    write_output(
        Some(output),
        templates::study_with_base(template, &base_text).as_bytes(),
    )?;
    if let Some(path) = written_base {
        eprintln!(
            "wrote {} (the study) and {} (its base scenario, the o-ring-face template)",
            output.display(),
            path.display()
        );
    }
    Ok(())
}

/// Refuses to write over an existing file (exit 2): a template is a start, never a
/// replacement for a user's file.
fn refuse_existing(output: Option<&Path>) -> Result<(), CliError> {
    match output {
        Some(path) if path.exists() => Err(CliError::Input(format!(
            "-o {}: the file exists; sealsim new never overwrites a file: give another name or \
             remove it first",
            path.display()
        ))),
        _ => Ok(()),
    }
}

/// `--base`, which must be an existing file, as an absolute path.
fn existing_base(base: &Path) -> Result<PathBuf, CliError> {
    base.canonicalize()
        .ok()
        .filter(|p| p.is_file())
        .ok_or_else(|| {
            CliError::Input(format!(
                "--base {}: no such scenario file (write one with `sealsim new o-ring-face -o {}`)",
                base.display(),
                base.display()
            ))
        })
}

/// `path` (absolute) as the study file names it: its file name when it is in the study's
/// folder, else the absolute path.
fn relative_to(path: &Path, folder: &Path) -> String {
    let same_folder = folder
        .canonicalize()
        .ok()
        .zip(path.parent())
        .is_some_and(|(f, p)| f == p);
    match path.file_name() {
        Some(name) if same_folder => name.to_string_lossy().into_owned(),
        _ => path.display().to_string(),
    }
}
