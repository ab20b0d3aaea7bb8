//! Errors of the scenario boundary. Every one names the file, and where it can the line and
//! the key path (`surface.hurst_exponent`), so that a user can go straight to the mistake.

use super::raw::RawScenario;
use std::fmt;
use std::io;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// Why a scenario could not be loaded.
#[derive(Debug)]
pub enum ScenarioError {
    /// The scenario file itself could not be read.
    Read { path: PathBuf, source: io::Error },
    /// The scenario file is wrong: TOML syntax, an unknown or missing key, a wrong type, unit
    /// or value.
    Invalid {
        /// The scenario file.
        path: PathBuf,
        /// 1-based line of the offending key or value, when known.
        line: Option<usize>,
        /// Dotted key path (`surface.hurst_exponent`), when the error belongs to a key.
        key: Option<String>,
        message: String,
    },
    /// The PSD file named by `surface.psd_file` could not be read.
    PsdRead {
        /// The PSD file, as resolved against the scenario's directory.
        psd: PathBuf,
        /// The scenario file and the line of its `psd_file` key.
        scenario: PathBuf,
        line: usize,
        source: io::Error,
    },
    /// The PSD file was read but its contents are not a valid spectrum.
    PsdFormat {
        psd: PathBuf,
        /// 1-based line in the PSD file, when the problem is on one line.
        psd_line: Option<usize>,
        scenario: PathBuf,
        line: usize,
        message: String,
    },
    /// The height map named by `surface.height_map` was read but its contents are not a valid
    /// grid of heights (or give no power spectrum).
    HeightMapFormat {
        /// The height map file, as resolved against the scenario's directory.
        map: PathBuf,
        /// 1-based line in the height map file, when the problem is on one line.
        map_line: Option<usize>,
        /// The scenario file and the line of its `height_map` key.
        scenario: PathBuf,
        line: usize,
        message: String,
    },
    /// The temperature history named by `environment.history` was read but its contents are
    /// invalid.
    /// A line trace named by `surface.profile` cannot be read or used.
    TraceFormat {
        /// The trace file, as resolved against the scenario's directory.
        trace: PathBuf,
        /// 1-based line in the trace file, when the problem is on one line.
        trace_line: Option<usize>,
        /// The scenario file and the line of its `profile` key.
        scenario: PathBuf,
        line: usize,
        message: String,
    },
    HistoryFormat {
        /// The history file, as resolved against the scenario's directory.
        history: PathBuf,
        /// 1-based line in the history file, when the problem is on one line.
        history_line: Option<usize>,
        /// The scenario file and the line of its `history` key.
        scenario: PathBuf,
        line: usize,
        message: String,
    },
}

impl ScenarioError {
    /// The file the user should open to fix the error.
    pub fn file(&self) -> &Path {
        match self {
            ScenarioError::Read { path, .. } | ScenarioError::Invalid { path, .. } => path,
            ScenarioError::PsdRead { scenario, .. } => scenario,
            ScenarioError::PsdFormat { psd, .. } => psd,
            ScenarioError::HistoryFormat { history, .. } => history,
            ScenarioError::HeightMapFormat { map, .. } => map,
            ScenarioError::TraceFormat { trace, .. } => trace,
        }
    }
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ScenarioError::Read { path, source } => {
                write!(f, "{}: cannot read scenario file: {source}", path.display())
            }
            ScenarioError::Invalid {
                path,
                line,
                key,
                message,
            } => {
                write!(f, "{}", path.display())?;
                if let Some(line) = line {
                    write!(f, ":{line}")?;
                }
                if let Some(key) = key {
                    write!(f, ": {key}")?;
                }
                write!(f, ": {message}")
            }
            ScenarioError::PsdRead {
                psd,
                scenario,
                line,
                source,
            } => write!(
                f,
                "{}:{line}: surface.psd_file: cannot read PSD file {}: {source}",
                scenario.display(),
                psd.display()
            ),
            ScenarioError::PsdFormat {
                psd,
                psd_line,
                scenario,
                line,
                message,
            } => {
                write!(f, "{}", psd.display())?;
                if let Some(l) = psd_line {
                    write!(f, ":{l}")?;
                }
                write!(
                    f,
                    ": {message} (PSD file named by surface.psd_file at {}:{line})",
                    scenario.display()
                )
            }
            ScenarioError::TraceFormat {
                trace,
                trace_line,
                scenario,
                line,
                message,
            } => {
                write!(f, "{}", trace.display())?;
                if let Some(l) = trace_line {
                    write!(f, ":{l}")?;
                }
                write!(
                    f,
                    ": {message} (line trace named by surface.profile at {}:{line})",
                    scenario.display()
                )
            }
            ScenarioError::HeightMapFormat {
                map,
                map_line,
                scenario,
                line,
                message,
            } => {
                write!(f, "{}", map.display())?;
                if let Some(l) = map_line {
                    write!(f, ":{l}")?;
                }
                write!(
                    f,
                    ": surface.height_map: {message} (height map named at {}:{line})",
                    scenario.display()
                )
            }
            ScenarioError::HistoryFormat {
                history,
                history_line,
                scenario,
                line,
                message,
            } => {
                write!(f, "{}", history.display())?;
                if let Some(l) = history_line {
                    write!(f, ":{l}")?;
                }
                write!(
                    f,
                    ": {message} (temperature history named by environment.history at {}:{line})",
                    scenario.display()
                )
            }
        }
    }
}

impl std::error::Error for ScenarioError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ScenarioError::Read { source, .. } | ScenarioError::PsdRead { source, .. } => {
                Some(source)
            }
            _ => None,
        }
    }
}

/// The text of one scenario file and its name: turns byte spans into located errors.
#[derive(Debug, Clone, Copy)]
pub(super) struct Source<'a> {
    pub path: &'a Path,
    pub text: &'a str,
}

impl Source<'_> {
    /// 1-based line of a byte offset.
    pub fn line(&self, offset: usize) -> usize {
        let end = offset.min(self.text.len());
        self.text.as_bytes()[..end]
            .iter()
            .filter(|&&b| b == b'\n')
            .count()
            + 1
    }

    /// An error at `span` belonging to `key`.
    pub fn error(
        &self,
        span: Range<usize>,
        key: &str,
        message: impl Into<String>,
    ) -> ScenarioError {
        ScenarioError::Invalid {
            path: self.path.to_path_buf(),
            line: Some(self.line(span.start)),
            key: Some(key.to_owned()),
            message: message.into(),
        }
    }

    /// Parses the text as TOML and deserializes it into the raw structs `T`, with located
    /// syntax and schema errors.
    pub fn deserialize<T: serde::de::DeserializeOwned>(&self) -> Result<T, ScenarioError> {
        let doc = DeTable::parse(self.text).map_err(|e| self.syntax_error(&e))?;
        T::deserialize(toml::de::Deserializer::from(doc.clone()))
            .map_err(|e| self.schema_error(&doc, &e))
    }

    /// The file stem, the default name of a scenario or figure set.
    pub fn file_stem(&self) -> String {
        self.path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    }

    /// A TOML syntax error (from parsing the document).
    pub fn syntax_error(&self, err: &toml::de::Error) -> ScenarioError {
        ScenarioError::Invalid {
            path: self.path.to_path_buf(),
            line: err.span().map(|s| self.line(s.start)),
            key: None,
            message: format!("TOML syntax error: {}", err.message().trim_end()),
        }
    }

    /// A schema error from deserializing the raw structs (unknown key, missing key, wrong
    /// type), with the key path recovered from the span.
    pub fn schema_error(&self, doc: &Spanned<DeTable<'_>>, err: &toml::de::Error) -> ScenarioError {
        let message = err.message().trim_end();
        let span = err.span();
        let line = span.as_ref().map(|s| self.line(s.start));
        // The table or key the span points at ("" for the document itself).
        let at = match &span {
            Some(s) if *s != doc.span() => key_path_at(doc.get_ref(), s).unwrap_or_default(),
            _ => String::new(),
        };
        let (key, message) = if let Some(field) = backticked_after(message, "missing field ") {
            let key = join_key(&at, field);
            let message = if at.is_empty() && RawScenario::TABLES.contains(&field) {
                format!("missing table [{field}]")
            } else if at.is_empty() {
                format!("missing key `{field}`")
            } else {
                format!("missing key `{field}` in [{at}]")
            };
            (key, message)
        } else if let Some(rest) = message.strip_prefix("unknown field ") {
            (at, format!("unknown key {rest}"))
        } else {
            (at, message.to_owned())
        };
        ScenarioError::Invalid {
            path: self.path.to_path_buf(),
            line,
            key: (!key.is_empty()).then_some(key),
            message,
        }
    }
}

/// `a.b` from `a` and `b`; `b` alone when `a` is empty.
fn join_key(table: &str, key: &str) -> String {
    if table.is_empty() {
        key.to_owned()
    } else {
        format!("{table}.{key}")
    }
}

/// The text between the first pair of backticks after `prefix`, if `message` starts with it.
fn backticked_after<'m>(message: &'m str, prefix: &str) -> Option<&'m str> {
    let rest = message.strip_prefix(prefix)?.strip_prefix('`')?;
    rest.split_once('`').map(|(field, _)| field)
}

/// The dotted key path of the innermost key or value whose span contains `span`.
fn key_path_at(table: &DeTable<'_>, span: &Range<usize>) -> Option<String> {
    let mut best: Option<(usize, String)> = None;
    visit_table(table, "", &mut |path, candidate| {
        if candidate.start <= span.start && span.end <= candidate.end {
            let width = candidate.end - candidate.start;
            if best.as_ref().is_none_or(|(w, _)| width < *w) {
                best = Some((width, path.to_owned()));
            }
        }
    });
    best.map(|(_, path)| path)
}

/// Calls `f(path, span)` for every key and every value in the tree.
fn visit_table(table: &DeTable<'_>, prefix: &str, f: &mut dyn FnMut(&str, Range<usize>)) {
    for (key, value) in table.iter() {
        let path = join_key(prefix, key.get_ref());
        f(&path, key.span());
        visit_value(value, &path, f);
    }
}

fn visit_value(value: &Spanned<DeValue<'_>>, path: &str, f: &mut dyn FnMut(&str, Range<usize>)) {
    f(path, value.span());
    match value.get_ref() {
        DeValue::Table(t) => visit_table(t, path, f),
        DeValue::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                visit_value(item, &format!("{path}[{i}]"), f);
            }
        }
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_one_based() {
        let s = Source {
            path: Path::new("x.toml"),
            text: "a = 1\nb = 2\n",
        };
        assert_eq!(s.line(0), 1);
        assert_eq!(s.line(6), 2);
        assert_eq!(s.line(1000), 3);
    }

    #[test]
    fn key_paths_are_found_in_nested_and_inline_tables() {
        let text = "[material]\ne = 1\nnu = { x = 2 }\n";
        let doc = DeTable::parse(text).unwrap();
        let at = |needle: &str, len: usize| {
            let start = text.find(needle).unwrap();
            key_path_at(doc.get_ref(), &(start..start + len))
        };
        assert_eq!(at("e =", 1).as_deref(), Some("material.e"));
        assert_eq!(at("x =", 1).as_deref(), Some("material.nu.x"));
        assert_eq!(at("2", 1).as_deref(), Some("material.nu.x"));
        assert_eq!(at("[material]", 10).as_deref(), Some("material"));
    }
}

/// A scenario input's warning or note (`FILE:LINE: key: …`): its registered code
/// ([`crate::codes`]) and its located text. It reads as its text (`Deref<Target = str>`).
#[derive(Debug, Clone, PartialEq)]
pub struct InputWarning {
    /// The registered code (`W034`, or `N001` for a note).
    pub code: &'static crate::codes::Code,
    /// `FILE:LINE: key: message`, in full (a note's message starts with `note: `).
    pub text: String,
    /// `NAME:LINE: key`, with the file's name only (the one-line form's place).
    pub place: String,
}

impl InputWarning {
    /// Whether this is a note (how an input was read) rather than a warning.
    pub fn is_note(&self) -> bool {
        self.code.kind == crate::codes::Kind::Note
    }
}

impl std::ops::Deref for InputWarning {
    type Target = str;
    fn deref(&self) -> &str {
        &self.text
    }
}

impl fmt::Display for InputWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl ScenarioError {
    /// This located message as an input warning (or note) with `code`.
    pub fn warning(self, code: &'static crate::codes::Code) -> InputWarning {
        let place = match &self {
            ScenarioError::Invalid {
                path, line, key, ..
            } => {
                let name = path.file_name().map_or_else(
                    || path.display().to_string(),
                    |n| n.to_string_lossy().into(),
                );
                let line = line.map(|l| format!(":{l}")).unwrap_or_default();
                let key = key.as_deref().map(|k| format!(": {k}")).unwrap_or_default();
                format!("{name}{line}{key}")
            }
            _ => String::new(),
        };
        InputWarning {
            code,
            text: self.to_string(),
            place,
        }
    }
}
