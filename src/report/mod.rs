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
pub mod staging;
pub mod study;
pub mod surface;
pub mod tradeoff;
pub mod units;

use std::fmt;
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
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

/// How many symbolic links an output path may pass through (Linux's own limit, `MAXSYMLINKS`).
const MAX_LINKS: usize = 40;

/// Where an output path leads once its symbolic links are followed (see [`write_atomic`]).
#[derive(Debug)]
pub enum OutputTarget {
    /// A regular file to replace whole, or a new file to create (`existing` is `None`): the
    /// path with every link followed, so a link is written through and kept, and a dangling
    /// link creates its target.
    File {
        path: PathBuf,
        existing: Option<fs::Metadata>,
    },
    /// A stream written in place, never replaced: a character device (`/dev/null`), a FIFO or
    /// a socket (`append` false), or a descriptor (`/dev/stdout`, `/dev/fd/N`,
    /// `/proc/self/fd/N`), which may be a redirected regular file (`append` true, so that
    /// `-o /dev/stdout >> log.txt` keeps the log's earlier lines).
    Stream { path: PathBuf, append: bool },
}

/// `/dev/stdout`, `/dev/stderr`, `/dev/fd/N`, `/proc/self/fd/N`, `/proc/PID/fd/N`: a path that
/// names an open descriptor; following it would name the file the descriptor was opened on,
/// which the writer must not replace (the shell's redirect, maybe in append mode, holds it).
fn names_a_descriptor(path: &Path) -> bool {
    let text = path.to_string_lossy();
    if matches!(&*text, "/dev/stdout" | "/dev/stderr" | "/dev/stdin") {
        return true;
    }
    if text.starts_with("/dev/fd/") {
        return true;
    }
    let Some(rest) = text.strip_prefix("/proc/") else {
        return false;
    };
    let mut parts = rest.splitn(3, '/');
    let owner = parts.next().unwrap_or("");
    let fd = parts.next() == Some("fd");
    fd && (owner == "self"
        || owner == "thread-self"
        || (!owner.is_empty() && owner.bytes().all(|b| b.is_ascii_digit())))
}

/// The descriptor number a descriptor path names (`/dev/stdout` → 1), when it is ours.
fn own_descriptor(path: &Path) -> Option<u32> {
    let text = path.to_string_lossy();
    match &*text {
        "/dev/stdout" => return Some(1),
        "/dev/stderr" => return Some(2),
        _ => {}
    }
    let pid = std::process::id().to_string();
    let number = text
        .strip_prefix("/dev/fd/")
        .or_else(|| text.strip_prefix("/proc/self/fd/"))
        .or_else(|| text.strip_prefix("/proc/thread-self/fd/"))
        .or_else(|| {
            text.strip_prefix("/proc/")
                .and_then(|r| r.strip_prefix(pid.as_str()))
                .and_then(|r| r.strip_prefix("/fd/"))
        })?;
    number.parse().ok()
}

/// Follows `path`'s symbolic links (at most `MAX_LINKS`, 40) to what an output there writes.
///
/// Errors: a link loop (or a chain longer than `MAX_LINKS`), a directory, a block device (a
/// disk: never written at offset 0 by mistake), or metadata that cannot be read.
pub fn output_target(path: &Path) -> io::Result<OutputTarget> {
    let mut current = path.to_path_buf();
    for _ in 0..=MAX_LINKS {
        if names_a_descriptor(&current) {
            return Ok(OutputTarget::Stream {
                path: current,
                append: true,
            });
        }
        let meta = match fs::symlink_metadata(&current) {
            Ok(meta) => meta,
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                return Ok(OutputTarget::File {
                    path: current,
                    existing: None,
                });
            }
            Err(e) => return Err(e),
        };
        let kind = meta.file_type();
        if kind.is_symlink() {
            let target = fs::read_link(&current)?;
            current = match current.parent() {
                Some(dir) if target.is_relative() => dir.join(target),
                _ => target,
            };
            continue;
        }
        if kind.is_dir() {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                format!("{} is a directory", current.display()),
            ));
        }
        if kind.is_file() {
            return Ok(OutputTarget::File {
                path: current,
                existing: Some(meta),
            });
        }
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if kind.is_block_device() {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    format!(
                        "{} is a block device (a disk): an output is never written onto one",
                        current.display()
                    ),
                ));
            }
        }
        return Ok(OutputTarget::Stream {
            path: current,
            append: false,
        });
    }
    Err(io::Error::new(
        io::ErrorKind::InvalidInput,
        format!(
            "{} is a symbolic link loop (more than {MAX_LINKS} links, or a link to itself)",
            path.display()
        ),
    ))
}

/// Why an existing regular file may not be replaced by an output: it is read-only (no write
/// permission bit at all, e.g. 0444: a protection even root is held to here, as `cp` and an
/// editor warn), or this process may not write it (another user's file, as a shell redirect
/// would refuse). `None`: it may be replaced.
pub fn replace_refusal(path: &Path, meta: &fs::Metadata) -> Option<String> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = meta.permissions().mode() & 0o7777;
        if mode & 0o222 == 0 {
            return Some(format!(
                "{} is read-only (mode {mode:04o}): it is not replaced; make it writable \
                 (chmod u+w) or give the output another name",
                path.display()
            ));
        }
    }
    #[cfg(not(unix))]
    if meta.permissions().readonly() {
        return Some(format!(
            "{} is read-only: it is not replaced; make it writable or give the output another \
             name",
            path.display()
        ));
    }
    // Opening for writing (no truncation, no creation) changes nothing and asks the kernel
    // the question a shell redirect asks: may this process write the file?
    match OpenOptions::new().write(true).open(path) {
        Err(e) if e.kind() == io::ErrorKind::PermissionDenied => Some(format!(
            "{} is not writable by this user (another user's file, or one without write \
             permission for you): it is not replaced; give the output another name",
            path.display()
        )),
        _ => None,
    }
}

/// Writes `bytes` to `path` whole or not at all.
///
/// A regular file (or a new path) is written to a temporary file in the same directory
/// (`.{name}.tmp-{pid}-{random}`, [`staging`]), flushed and synced and renamed over it (at the
/// end of the command, with its other outputs, inside a [`staging::begin`] batch). On any error the
/// temporary file is removed and an existing file is left untouched. The replaced file keeps
/// its permission bits (a 0600 file stays private) and, where the process may set them (root,
/// or a group the user is in), its owner and group; a read-only file (mode without any write
/// bit, e.g. 0444) or one this process may not write is refused ([`replace_refusal`]).
///
/// Symbolic links are followed ([`output_target`]): the file a link points to is replaced and
/// the link kept; a dangling link creates its target (as a shell redirect does); a link loop is
/// refused. An existing path that is not a regular file (`/dev/null`, a FIFO) is a stream that
/// cannot be replaced, so the bytes are written into it directly; renaming over it would turn,
/// say, `/dev/null` into a regular file for every other program on the machine. A descriptor
/// path (`/dev/stdout`, `/dev/fd/N`, `/proc/self/fd/N`, or a link to one) is written to that
/// descriptor, appending when it is a redirected file: `-o /dev/stdout >> log.txt` adds to
/// the log, never replaces it. A block device is refused.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut file = StagedFile::create(path)?;
    file.write_all(bytes)?;
    file.finish()
}

/// An output written as it is produced and put in place whole at [`StagedFile::finish`], as
/// [`write_atomic`] puts its bytes (the same targets, refusals, temporary, mode and owner): a
/// table of 10⁶ rows is never held in memory. The temporary is created at
/// [`StagedFile::create`] (so a missing directory is an error before any work) and filled
/// through a buffer; on any error, or if the writer is dropped unfinished, it is removed. A
/// stream target (`/dev/stdout`, a FIFO, a device), written in place and never replaced, is
/// held in memory and written at `finish`, so that it too gets nothing from a command that
/// fails.
pub struct StagedFile {
    state: Staged,
}

enum Staged {
    /// The temporary being written, and the file it will replace.
    File {
        writer: io::BufWriter<File>,
        tmp: PathBuf,
        target: PathBuf,
    },
    /// The bytes for a stream.
    Stream {
        path: PathBuf,
        append: bool,
        bytes: Vec<u8>,
    },
    /// Finished (or failed): nothing left to remove.
    Done,
}

impl StagedFile {
    /// Starts an output to `path` ([`write_atomic`]'s rules): a regular file or a new path gets
    /// its temporary now.
    ///
    /// Errors: what [`output_target`] refuses, a read-only file or one this process may not
    /// write ([`replace_refusal`]), a temporary that cannot be created (a missing directory).
    pub fn create(path: &Path) -> io::Result<Self> {
        let state = match output_target(path)? {
            OutputTarget::File { path, existing } => {
                if let Some(meta) = &existing
                    && let Some(why) = replace_refusal(&path, meta)
                {
                    return Err(io::Error::new(io::ErrorKind::PermissionDenied, why));
                }
                let (file, tmp) = temporary(&path)?;
                if let Err(e) = keep_mode_and_owner(&file, existing.as_ref()) {
                    staging::discard(&tmp);
                    return Err(e);
                }
                Staged::File {
                    writer: io::BufWriter::new(file),
                    tmp,
                    target: path,
                }
            }
            OutputTarget::Stream { path, append } => Staged::Stream {
                path,
                append,
                bytes: Vec::new(),
            },
        };
        Ok(StagedFile { state })
    }

    /// Ends the output: the temporary flushed, synced (so a rename never exposes a file whose
    /// bytes are still only in the page cache) and renamed over the target — or staged, inside
    /// a [`staging::begin`] batch —; a stream's bytes written into it. On an error the
    /// temporary is removed and an existing file left untouched.
    pub fn finish(mut self) -> io::Result<()> {
        match std::mem::replace(&mut self.state, Staged::Done) {
            Staged::File {
                writer,
                tmp,
                target,
            } => {
                let synced = writer
                    .into_inner()
                    .map_err(io::IntoInnerError::into_error)
                    .and_then(|file| file.sync_all());
                match synced {
                    Ok(()) => {
                        staging::finish(&tmp, &target).inspect_err(|_| staging::discard(&tmp))
                    }
                    Err(e) => {
                        staging::discard(&tmp);
                        Err(e)
                    }
                }
            }
            Staged::Stream {
                path,
                append,
                bytes,
            } => write_stream(&path, append, &bytes),
            Staged::Done => Ok(()),
        }
    }
}

impl Write for StagedFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.state {
            Staged::File { writer, .. } => writer.write(buf),
            Staged::Stream { bytes, .. } => bytes.write(buf),
            Staged::Done => Err(io::Error::other("write after finish")),
        }
    }

    fn write_all(&mut self, buf: &[u8]) -> io::Result<()> {
        match &mut self.state {
            Staged::File { writer, .. } => writer.write_all(buf),
            Staged::Stream { bytes, .. } => bytes.write_all(buf),
            Staged::Done => Err(io::Error::other("write after finish")),
        }
    }

    /// Flushes the buffer into the temporary (a stream is written only at `finish`).
    fn flush(&mut self) -> io::Result<()> {
        match &mut self.state {
            Staged::File { writer, .. } => writer.flush(),
            Staged::Stream { .. } | Staged::Done => Ok(()),
        }
    }
}

impl Drop for StagedFile {
    /// An unfinished output (an error, a failed command) leaves nothing: its temporary is
    /// removed, the buffer dropped unwritten.
    fn drop(&mut self) {
        if let Staged::File { writer, tmp, .. } = std::mem::replace(&mut self.state, Staged::Done) {
            // no flush: the bytes go nowhere
            drop(writer.into_parts());
            staging::discard(&tmp);
        }
    }
}

/// Writes into a stream in place: our own standard output or error through the process's
/// handle (so that the bytes land after, and before, what the command prints there), any other
/// descriptor or device by opening it (appending, for a redirected file).
fn write_stream(path: &Path, append: bool, bytes: &[u8]) -> io::Result<()> {
    match own_descriptor(path) {
        Some(1) => {
            let mut out = io::stdout().lock();
            out.write_all(bytes)?;
            return out.flush();
        }
        Some(2) => {
            let mut err = io::stderr().lock();
            err.write_all(bytes)?;
            return err.flush();
        }
        _ => {}
    }
    let mut options = OpenOptions::new();
    if append {
        options.append(true);
    } else {
        options.write(true);
    }
    let mut stream = options.open(path)?;
    stream.write_all(bytes)?;
    stream.flush()
}

/// A new temporary beside `path` (`.{name}.tmp-{pid}-{random}`), recorded in the [`staging`]
/// ledger before it is created.
fn temporary(path: &Path) -> io::Result<(File, PathBuf)> {
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
    // `create_new`: never clobber a file that is not ours (so only remove it if we made it).
    // The random part keeps a name left by a killed process (of this PID, in a container)
    // from colliding; a collision all the same is retried under a new name.
    let mut attempt = 0;
    loop {
        let tmp = dir.join(format!(
            ".{}.tmp-{}-{:016x}",
            name.to_string_lossy(),
            std::process::id(),
            staging::random_part()
        ));
        let made = staging::create(&tmp, || {
            OpenOptions::new().write(true).create_new(true).open(&tmp)
        });
        match made {
            Ok(file) => return Ok((file, tmp)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && attempt < 64 => attempt += 1,
            Err(e) => return Err(e),
        }
    }
}

/// Gives the temporary the replaced file's owner and group where this process may (root; the
/// group alone for a user in it; otherwise the writer owns the new file), then its permission
/// bits (after the owner: changing the owner clears set-id bits).
fn keep_mode_and_owner(file: &File, existing: Option<&fs::Metadata>) -> io::Result<()> {
    let Some(old) = existing else { return Ok(()) };
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let new = file.metadata()?;
        if (new.uid(), new.gid()) != (old.uid(), old.gid())
            && std::os::unix::fs::fchown(file, Some(old.uid()), Some(old.gid())).is_err()
        {
            let _ = std::os::unix::fs::fchown(file, None, Some(old.gid()));
        }
    }
    file.set_permissions(old.permissions())
}

/// A number unique within this process, mixed into each temporary's random name.
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

    /// A staged output is written in pieces into its temporary and replaces the old file
    /// only at `finish`, whole; one dropped unfinished (a failed command) leaves the old file
    /// and no temporary.
    #[test]
    fn a_staged_file_replaces_whole_at_finish_and_an_unfinished_one_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.csv");
        fs::write(&path, "old").unwrap();
        let mut file = StagedFile::create(&path).unwrap();
        file.write_all(b"head\n").unwrap();
        file.write_all(&[b'x'; 100_000]).unwrap();
        assert_eq!(fs::read_to_string(&path).unwrap(), "old");
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
        file.finish().unwrap();
        let text = fs::read_to_string(&path).unwrap();
        assert!(text.starts_with("head\nx") && text.len() == 5 + 100_000);
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
        let mut file = StagedFile::create(&path).unwrap();
        file.write_all(&[b'y'; 100_000]).unwrap();
        drop(file);
        assert_eq!(fs::read_to_string(&path).unwrap(), text);
        assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
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
