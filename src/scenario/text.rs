//! The lowest layer of the input boundary's files: reading a file as text, the data rows of a
//! CSV-like file, and the one error of a data file. Every reader of a data file uses these;
//! they use nothing of the scenario but its error type.

use super::error::{ScenarioError, Source};
use std::path::{Path, PathBuf};

/// A data file that cannot be used: the file, the 1-based line when the problem is on one
/// line, and what is wrong. Displayed as `path:line: message`.
#[derive(Debug, Clone, PartialEq)]
pub struct DataFileError {
    pub path: std::path::PathBuf,
    pub line: Option<usize>,
    pub message: String,
}

impl std::fmt::Display for DataFileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.path.display())?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for DataFileError {}

/// The data rows of a CSV-like text file with their 1-based line numbers: a leading byte-order
/// mark (spreadsheet exports) is dropped, rows are trimmed, blank and `#` lines skipped.
pub(crate) fn data_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
}

/// The text of a scenario-like file, or a located read error.
pub(super) fn read(path: &Path) -> Result<String, ScenarioError> {
    std::fs::read_to_string(path).map_err(|source| ScenarioError::Read {
        path: path.to_path_buf(),
        source,
    })
}

impl Source<'_> {
    /// A file named in the scenario, resolved against the scenario file's directory.
    pub(super) fn relative_path(&self, file: &str) -> PathBuf {
        match self.path.parent() {
            Some(dir) => dir.join(file),
            None => PathBuf::from(file),
        }
    }
}
