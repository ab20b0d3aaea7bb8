//! Output boundary: tables (CSV) and files written atomically.
//!
//! Units are printed only here (column names carry them); the physics hands over SI values.

pub mod advise;
pub mod ageing_fit;
pub mod columns;
pub mod csv;
pub mod findings;
pub mod fit_prony;
pub mod gland;
pub mod html;
pub mod life;
#[cfg(feature = "cli")]
pub mod life_chart;
pub mod master_curve;
pub mod material_toml;
pub mod materials;
pub mod plot;
pub mod sizes;
pub mod study;
pub mod surface;
pub mod tradeoff;
pub mod units;

use std::fmt;
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};

/// Why a report could not be produced. Both cases are internal errors (bugs), not user
/// errors: the physics must never hand over a non-finite number.
#[derive(Debug, Clone, PartialEq)]
pub enum ReportError {
    /// A value to be written is NaN or infinite (`row` counts data rows from 1).
    NonFinite {
        row: usize,
        column: &'static str,
        value: f64,
    },
    /// The CSV encoder failed.
    Csv(String),
}

impl fmt::Display for ReportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReportError::NonFinite { row, column, value } => write!(
                f,
                "internal error: non-finite value {value} in column {column}, row {row}; nothing was written"
            ),
            ReportError::Csv(msg) => write!(f, "internal error: CSV encoding failed: {msg}"),
        }
    }
}

impl std::error::Error for ReportError {}

/// Writes `bytes` to `path` whole or not at all.
///
/// The bytes go to a temporary file in the same directory (`.{name}.tmp-{pid}-{n}`), which is
/// flushed and synced and then renamed over `path`. On any error the temporary file is
/// removed and an existing `path` is left untouched. (A replaced file gets default
/// permissions, not those of the file it replaces.)
///
/// A symbolic link is followed: the file it points to is replaced, the link kept. An
/// existing path that is not a regular file (`/dev/null`, `/dev/stdout`, a FIFO) is a stream
/// that cannot be replaced, so the bytes are written into it directly; renaming over it would
/// turn, say, `/dev/null` into a regular file for every other program on the machine.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    match fs::metadata(path) {
        Ok(meta) if meta.is_file() => {
            if fs::symlink_metadata(path)?.file_type().is_symlink() {
                return replace_whole(&fs::canonicalize(path)?, bytes);
            }
            replace_whole(path, bytes)
        }
        Ok(meta) if meta.is_dir() => Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} is a directory", path.display()),
        )),
        Ok(_) => {
            let mut stream = OpenOptions::new().write(true).open(path)?;
            stream.write_all(bytes)?;
            stream.flush()
        }
        Err(_) => replace_whole(path, bytes),
    }
}

/// The temporary-file-and-rename write of [`write_atomic`], for a regular file or a new path.
fn replace_whole(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let name = path.file_name().ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{} is not a file name", path.display()),
        )
    })?;
    let dir = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    let tmp = dir.join(format!(
        ".{}.tmp-{}-{}",
        name.to_string_lossy(),
        std::process::id(),
        next_serial()
    ));
    // `create_new`: never clobber a file that is not ours (so only remove it if we made it).
    let file = OpenOptions::new().write(true).create_new(true).open(&tmp)?;
    let result = fill_and_rename(file, bytes, &tmp, path);
    if result.is_err() {
        // Best effort: the original error is the one worth reporting.
        let _ = fs::remove_file(&tmp);
    }
    result
}

fn fill_and_rename(mut file: File, bytes: &[u8], tmp: &Path, path: &Path) -> io::Result<()> {
    file.write_all(bytes)?;
    file.flush()?;
    file.sync_all()?;
    drop(file);
    fs::rename(tmp, path)
}

/// A number unique within this process, so that concurrent writes never share a temp file.
fn next_serial() -> u64 {
    static SERIAL: AtomicU64 = AtomicU64::new(0);
    SERIAL.fetch_add(1, Ordering::Relaxed)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression: `-o /dev/null` once renamed a regular file over the machine's /dev/null,
    /// after which every program reading it got text other programs had thrown away.
    #[cfg(unix)]
    #[test]
    fn a_device_is_written_into_not_replaced() {
        use std::os::unix::fs::FileTypeExt;
        let null = Path::new("/dev/null");
        if !fs::metadata(null).is_ok_and(|m| m.file_type().is_char_device()) {
            return; // no device here to check against
        }
        write_atomic(null, b"discarded").unwrap();
        assert!(fs::metadata(null).unwrap().file_type().is_char_device());
        assert_eq!(fs::read(null).unwrap(), b"");
    }

    #[cfg(unix)]
    #[test]
    fn a_symlink_is_followed_and_kept() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("real.csv");
        let link = dir.path().join("link.csv");
        fs::write(&target, "old").unwrap();
        std::os::unix::fs::symlink(&target, &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(
            fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(fs::read(&target).unwrap(), b"new");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
    }

    #[test]
    fn a_directory_is_refused_and_left_alone() {
        let dir = tempfile::tempdir().unwrap();
        assert!(write_atomic(dir.path(), b"x").is_err());
        assert!(dir.path().is_dir());
    }

    #[test]
    fn replaces_whole_file_and_leaves_no_temporaries() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.csv");
        fs::write(&path, "old content that is longer").unwrap();
        write_atomic(&path, b"new").unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "new");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn failure_leaves_nothing_behind() {
        let dir = tempfile::tempdir().unwrap();
        // Renaming a file over a non-empty directory fails.
        let target = dir.path().join("sub");
        fs::create_dir(&target).unwrap();
        fs::write(target.join("keep"), "x").unwrap();
        assert!(write_atomic(&target, b"data").is_err());
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
        assert!(write_atomic(&dir.path().join("missing/out.csv"), b"data").is_err());
    }
}
