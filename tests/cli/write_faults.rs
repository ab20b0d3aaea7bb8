//! Faults while writing an output (issue 13, item 4). `write_atomic` writes a hidden temporary
//! `.NAME.tmp-PID-SERIAL` beside the target, syncs it and renames it over the target.
//!
//! The faults are ones that fail even as root (which ignores permission bits, so a read-only
//! directory is no fault there): a file-size limit (`ulimit -f`, the kernel's EFBIG: a full disk
//! as the writer sees it), the same limit with its default signal (SIGXFSZ kills the process in
//! the middle of writing the temporary, i.e. between its creation and the rename), an output path
//! under a missing directory, and an output path that is an existing directory.

use super::support::sealsim;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

const SCENARIO: &str = "scenarios/oring-nbr-water-80c.toml";
const PREVIOUS: &str = "previous output, must survive\n";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// `sealsim run SCENARIO -o out` under bash with a 1 KiB file-size limit; `ignore_xfsz` makes
/// the write fail with EFBIG instead of the kernel killing the process with SIGXFSZ.
fn run_with_size_limit(out: &Path, ignore_xfsz: bool) -> std::process::Output {
    let trap = if ignore_xfsz { "trap '' XFSZ; " } else { "" };
    Command::new("bash")
        .arg("-c")
        .arg(format!(
            "{trap}ulimit -f 1; exec \"$0\" run \"$1\" -o \"$2\""
        ))
        .arg(env!("CARGO_BIN_EXE_sealsim"))
        .arg(root().join(SCENARIO))
        .arg(out)
        .output()
        .unwrap()
}

#[test]
fn full_disk_keeps_the_previous_output_and_removes_the_temporary() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("history.csv");
    fs::write(&out, PREVIOUS).unwrap();
    let result = run_with_size_limit(&out, true);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert_eq!(result.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains(&format!("cannot write {}", out.display())) && stderr.contains("large"),
        "{stderr}"
    );
    assert_eq!(fs::read_to_string(&out).unwrap(), PREVIOUS);
    assert_eq!(names(dir.path()), ["history.csv"], "a temporary was left");
}

#[test]
fn killed_while_writing_keeps_the_previous_output_and_the_next_run_succeeds() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("history.csv");
    fs::write(&out, PREVIOUS).unwrap();
    // SIGXFSZ's default action kills the process the moment it writes past the limit: after the
    // temporary was created, before the rename — deterministically, unlike a timed kill.
    let result = run_with_size_limit(&out, false);
    assert_eq!(
        result.status.signal(),
        Some(25), // SIGXFSZ on Linux
        "{:?}: {}",
        result.status,
        String::from_utf8_lossy(&result.stderr)
    );
    assert_eq!(fs::read_to_string(&out).unwrap(), PREVIOUS);
    // A killed process cannot clean up: its temporary stays, hidden and named for its process,
    // holding a truncated prefix of the output.
    let left = names(dir.path());
    assert_eq!(left.len(), 2, "{left:?}");
    let tmp = &left[0];
    assert!(tmp.starts_with(".history.csv.tmp-"), "{left:?}");
    let partial = fs::read_to_string(dir.path().join(tmp)).unwrap();
    assert!(
        partial.len() <= 1024 && partial.starts_with("time_s,"),
        "{partial}"
    );

    // The stale temporary does not get in the way: the next run writes the whole output.
    sealsim()
        .args(["run", SCENARIO, "-o"])
        .arg(&out)
        .current_dir(root())
        .assert()
        .success();
    let history = fs::read_to_string(&out).unwrap();
    assert!(
        history.starts_with(super::support::HISTORY_HEADER),
        "{history}"
    );
    assert!(history.len() > partial.len());
    assert_eq!(names(dir.path()), [tmp.clone(), "history.csv".into()]);
}

#[test]
fn missing_directory_is_a_clear_error_and_creates_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("no-such-dir").join("history.csv");
    let assert = sealsim()
        .args(["run", SCENARIO, "-o"])
        .arg(&out)
        .current_dir(root())
        .assert()
        .code(1);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert!(
        stderr.contains(&format!("cannot write {}", out.display())),
        "{stderr}"
    );
    assert!(names(dir.path()).is_empty());
}

#[test]
fn output_onto_a_directory_keeps_it_and_removes_the_temporary() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("history.csv");
    fs::create_dir(&out).unwrap();
    fs::write(out.join("keep.txt"), PREVIOUS).unwrap();
    let assert = sealsim()
        .args(["run", SCENARIO, "-o"])
        .arg(&out)
        .current_dir(root())
        .assert()
        .code(1);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert!(
        stderr.contains(&format!("cannot write {}", out.display())),
        "{stderr}"
    );
    assert_eq!(names(dir.path()), ["history.csv"]);
    assert_eq!(fs::read_to_string(out.join("keep.txt")).unwrap(), PREVIOUS);
}

/// An output named for another format than the flag writes is refused before anything runs
/// (issue 42, item 2: `--plot life.png` wrote SVG text into a `.png`, `-o hist.xlsx` CSV): exit 2
/// naming the flag and the name that would be right, nothing written; the right extension in any
/// case and a path without one (a device) are taken.
#[test]
fn an_output_named_for_another_format_is_refused_and_nothing_is_written() {
    for (flag, name, wanted) in [
        ("--plot", "life.xlsx", "life.svg"),
        ("-o", "hist.xlsx", "hist.csv"),
        ("--summary", "s.txt", "s.json"),
        ("--report", "r.pdf", "r.html"),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let out = sealsim()
            .current_dir(root())
            .args(["run", SCENARIO, flag])
            .arg(dir.path().join(name))
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{flag} {name}: {err}");
        assert!(err.contains(flag) && err.contains(wanted), "{err}");
        assert!(
            names(dir.path()).is_empty(),
            "{flag} {name} wrote something"
        );
    }
    let dir = tempfile::tempdir().unwrap();
    let out = sealsim()
        .current_dir(root())
        .args(["run", SCENARIO, "--plot"])
        .arg(dir.path().join("LIFE.SVG"))
        .args(["-o", "/dev/null"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(names(dir.path()), ["LIFE.SVG"]);
}
