//! The temporaries of this process's output writes, and the batch that renames a command's
//! outputs together (issue 44, item 3).
//!
//! Every temporary [`super::write_atomic`] creates is recorded here *before* it is created and
//! forgotten once renamed or removed, so [`remove_all_and_exit`] (the command line's SIGINT /
//! SIGTERM handler) can delete every one in flight: an interrupted run leaves no
//! `.NAME.tmp-…` behind. Inside a batch ([`begin`] … [`commit`]) a write stops after its
//! temporary is whole and synced; [`commit`] then renames them all, one after another, under
//! the same lock the handler takes — an interrupt lands before the first rename (every
//! previous output kept) or after the last (every new one in place), never between, so a
//! command's outputs never come from two runs. SIGKILL, a power cut and the kernel's
//! out-of-memory killer cannot be caught; their temporaries carry a random part (so a later
//! process with the same PID never collides with one) and are hidden dotfiles.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

#[derive(Default)]
struct Ledger {
    /// Temporaries that may exist: being created or written, or staged.
    temporaries: Vec<PathBuf>,
    /// Staged outputs `(temporary, target)` waiting for [`commit`], in write order.
    staged: Vec<(PathBuf, PathBuf)>,
    /// A batch is open: writes stage rather than rename.
    batch: bool,
}

static LEDGER: Mutex<Ledger> = Mutex::new(Ledger {
    temporaries: Vec::new(),
    staged: Vec::new(),
    batch: false,
});

fn ledger() -> MutexGuard<'static, Ledger> {
    LEDGER.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Opens a batch: until [`commit`] or [`abandon`], every [`super::write_atomic`] to a file
/// leaves its output as a synced temporary and renames nothing.
pub fn begin() {
    ledger().batch = true;
}

/// Renames every staged output over its target, in write order, and closes the batch. On
/// the first failure the outputs not yet renamed are removed and the error names the target
/// (with the ones already in place, so the caller can say which files are new).
pub fn commit() -> Result<(), (PathBuf, io::Error)> {
    let mut ledger = ledger();
    ledger.batch = false;
    let staged = std::mem::take(&mut ledger.staged);
    let mut failed = None;
    for (tmp, target) in staged {
        if failed.is_none()
            && let Err(e) = fs::rename(&tmp, &target)
        {
            failed = Some((target, e));
        }
        if failed.is_some() {
            let _ = fs::remove_file(&tmp);
        }
        ledger.temporaries.retain(|t| *t != tmp);
    }
    failed.map_or(Ok(()), Err)
}

/// Closes the batch and removes every staged temporary: nothing of the command is written.
pub fn abandon() {
    let mut ledger = ledger();
    ledger.batch = false;
    for (tmp, _) in std::mem::take(&mut ledger.staged) {
        let _ = fs::remove_file(&tmp);
        ledger.temporaries.retain(|t| *t != tmp);
    }
}

/// Records `tmp` as a temporary that may exist, then runs `create` (which creates it); a
/// failed creation forgets it again. Under the lock, so a signal handler never misses a file
/// created between the two.
pub(super) fn create<T>(tmp: &Path, create: impl FnOnce() -> io::Result<T>) -> io::Result<T> {
    let mut ledger = ledger();
    ledger.temporaries.push(tmp.to_path_buf());
    let made = create();
    if made.is_err() {
        ledger.temporaries.retain(|t| t != tmp);
    }
    made
}

/// The whole, synced temporary `tmp` of `target`: renamed now, or staged when a batch is
/// open. Either way it is forgotten once renamed.
pub(super) fn finish(tmp: &Path, target: &Path) -> io::Result<()> {
    let mut ledger = ledger();
    if ledger.batch {
        ledger
            .staged
            .push((tmp.to_path_buf(), target.to_path_buf()));
        return Ok(());
    }
    let renamed = fs::rename(tmp, target);
    ledger.temporaries.retain(|t| t != tmp);
    renamed
}

/// Removes the temporary `tmp` after a failed write and forgets it.
pub(super) fn discard(tmp: &Path) {
    let mut ledger = ledger();
    let _ = fs::remove_file(tmp);
    ledger.temporaries.retain(|t| t != tmp);
}

/// Removes every temporary this process may have in flight and ends the process with `code`,
/// holding the lock so that no write starts, finishes or renames afterwards. For a signal
/// handler running on its own thread (not in signal context: it may lock and allocate).
pub fn remove_all_and_exit(code: i32) -> ! {
    let ledger = ledger();
    for tmp in &ledger.temporaries {
        let _ = fs::remove_file(tmp);
    }
    std::process::exit(code)
}

/// A random 64-bit number for a temporary's name: the standard library's per-process random
/// hash keys (seeded from the operating system), so two processes — even of the same PID in
/// two containers sharing a folder — do not pick the same name.
pub(super) fn random_part() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    let mut h = std::collections::hash_map::RandomState::new().build_hasher();
    h.write_u64(super::next_serial());
    h.finish()
}
