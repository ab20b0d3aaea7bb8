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

/// Issue 44: a study's per-case table is written as its blocks of cases come (a 10⁶-case
/// table is never held whole). A write that fails in the middle of the table — past a 1 KiB
/// file-size limit (EFBIG), on the first block's 300 rows (≈ 46 KB, more than the writer's
/// 8 KiB buffer) — leaves the previous table, no temporary and none of the other outputs; an output
/// under a missing directory is refused and creates nothing either.
#[test]
fn a_study_table_that_cannot_be_written_leaves_the_previous_one_and_no_temporary() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let base = root().join(SCENARIO);
    fs::write(
        d.join("s.toml"),
        format!(
            "base = {base:?}\ndesign = \"monte-carlo\"\nsamples = 300\nseed = 3\n[vary]\n\
             \"seal.groove_depth\" = \"±0.05 mm\"\n"
        ),
    )
    .unwrap();
    fs::write(d.join("cases.csv"), PREVIOUS).unwrap();
    let (code, stderr) = shell(
        d,
        "trap '' XFSZ; ulimit -f 1; exec \"$B\" study s.toml -o cases.csv --summary s.json",
    );
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("cannot write cases.csv") && stderr.contains("large"),
        "{stderr}"
    );
    assert_eq!(fs::read_to_string(d.join("cases.csv")).unwrap(), PREVIOUS);
    assert_eq!(
        names(d),
        ["cases.csv", "s.toml"],
        "a temporary or an output was left"
    );
    let (code, stderr) = in_dir(d, &["study", "s.toml", "-o", "no-such-dir/cases.csv"]);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("cannot write no-such-dir/cases.csv"),
        "{stderr}"
    );
    assert_eq!(names(d), ["cases.csv", "s.toml"]);
    // the same study with room to write: the table is whole (a header and 300 rows)
    let (code, stderr) = in_dir(d, &["study", "s.toml", "-o", "cases.csv"]);
    assert_eq!(code, Some(0), "{stderr}");
    let table = fs::read_to_string(d.join("cases.csv")).unwrap();
    assert_eq!(table.lines().count(), 301);
    assert!(table.len() > 8 * 1024, "{} B", table.len());
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

// ---- Nothing lost on write (issue 42, item 10; the file-safety audit's 12 failing cases) ----

/// `sealsim ARGS` in `dir`, its exit status and stderr.
fn in_dir(dir: &Path, args: &[&str]) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_sealsim"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `bash -c SCRIPT` in `dir` with `$B` the binary and `$S` the scenario: for redirections.
fn shell(dir: &Path, script: &str) -> (Option<i32>, String) {
    let out = Command::new("bash")
        .current_dir(dir)
        .arg("-c")
        .arg(script)
        .env("B", env!("CARGO_BIN_EXE_sealsim"))
        .env("S", root().join(SCENARIO))
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn copy_in(dir: &Path, from: &str) -> PathBuf {
    let to = dir.join(Path::new(from).file_name().unwrap());
    fs::copy(root().join(from), &to).unwrap();
    to
}

#[cfg(unix)]
fn mode(path: &Path) -> u32 {
    use std::os::unix::fs::PermissionsExt;
    fs::metadata(path).unwrap().permissions().mode() & 0o7777
}

#[cfg(unix)]
fn set_mode(path: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    fs::set_permissions(path, fs::Permissions::from_mode(mode)).unwrap();
}

/// `study slurm` once wrote its script over the study file, or over the base scenario.
#[test]
fn study_slurm_never_replaces_the_study_or_its_base() {
    let dir = tempfile::tempdir().unwrap();
    let study = copy_in(
        dir.path(),
        "scenarios/studies/as568-225-squeeze-tolerance.study.toml",
    );
    let base = copy_in(
        dir.path(),
        "scenarios/studies/as568-225-face-water-80c.toml",
    );
    let (study_text, base_text) = (fs::read(&study).unwrap(), fs::read(&base).unwrap());
    for out in [&study, &base] {
        let (code, err) = in_dir(
            dir.path(),
            &[
                "study",
                "slurm",
                "as568-225-squeeze-tolerance.study.toml",
                "--shards",
                "4",
                "-o",
                out.file_name().unwrap().to_str().unwrap(),
            ],
        );
        assert_eq!(code, Some(2), "{err}");
        assert!(err.contains("that is an input of this command"), "{err}");
        assert_eq!(fs::read(&study).unwrap(), study_text);
        assert_eq!(fs::read(&base).unwrap(), base_text);
    }
    assert_eq!(names(dir.path()).len(), 2, "something was written");
}

/// `figures --out-dir` once replaced a scenario's PSD file by a group's CSV of the same name.
#[test]
fn figures_never_replace_a_data_file_a_scenario_reads() {
    let dir = tempfile::tempdir().unwrap();
    let psd = copy_in(dir.path(), "scenarios/psd-example.csv");
    copy_in(dir.path(), "scenarios/psd-example.toml");
    fs::write(
        dir.path().join("set.toml"),
        "name = \"x\"\npressures = { from = \"0.1 MPa\", to = \"1 MPa\", points = 3 }\n\
         [[group]]\nid = \"psd-example\"\ntitle = \"t\"\nscenarios = [\"psd-example.toml\"]\n\
         plots = [\"leak_rate\"]\n",
    )
    .unwrap();
    let before = fs::read(&psd).unwrap();
    let (code, err) = in_dir(dir.path(), &["figures", "set.toml", "--out-dir", "."]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("psd-example.csv") && err.contains("input of this command"),
        "{err}"
    );
    assert_eq!(fs::read(&psd).unwrap(), before);
    assert_eq!(
        names(dir.path()),
        ["psd-example.csv", "psd-example.toml", "set.toml"]
    );
}

/// `materials curve nbr-70 -o c.csv --plot c.csv` once wrote the SVG, then the CSV over it;
/// `materials curve|export --file m.toml -o m.toml` replaced the compound file.
#[test]
fn materials_outputs_never_collide_or_replace_the_compound_file() {
    let dir = tempfile::tempdir().unwrap();
    let (code, err) = in_dir(
        dir.path(),
        &[
            "materials",
            "curve",
            "nbr-70",
            "-o",
            "c.csv",
            "--plot",
            "c.csv",
        ],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("writes the same file"), "{err}");
    assert!(names(dir.path()).is_empty());
    let m = copy_in(dir.path(), "materials/nbr-70.toml");
    let text = fs::read(&m).unwrap();
    for args in [
        &[
            "materials",
            "curve",
            "--file",
            "nbr-70.toml",
            "-o",
            "nbr-70.toml",
        ][..],
        &[
            "materials",
            "curve",
            "--file",
            "nbr-70.toml",
            "--plot",
            "./nbr-70.toml",
        ],
        &[
            "materials",
            "export",
            "--file",
            "nbr-70.toml",
            "--format",
            "abaqus",
            "-o",
            "nbr-70.toml",
        ],
    ] {
        let (code, err) = in_dir(dir.path(), args);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains("input of this command"), "{err}");
        assert_eq!(fs::read(&m).unwrap(), text);
    }
}

/// A read-only (0444) output is refused, even for root (exit 2, nothing written); a 0600 one is
/// replaced and stays 0600 (the rename once left it 0644, world-readable).
#[cfg(unix)]
#[test]
fn a_read_only_output_is_refused_and_a_private_one_stays_private() {
    let dir = tempfile::tempdir().unwrap();
    let ro = dir.path().join("ro.csv");
    fs::write(&ro, PREVIOUS).unwrap();
    set_mode(&ro, 0o444);
    let (code, err) = in_dir(&root(), &["run", SCENARIO, "-o", ro.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("read-only (mode 0444)"), "{err}");
    assert_eq!(fs::read_to_string(&ro).unwrap(), PREVIOUS);
    assert_eq!(mode(&ro), 0o444);

    let private = dir.path().join("private.csv");
    fs::write(&private, PREVIOUS).unwrap();
    set_mode(&private, 0o600);
    let (code, err) = in_dir(&root(), &["run", SCENARIO, "-o", private.to_str().unwrap()]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        fs::read_to_string(&private)
            .unwrap()
            .starts_with(super::support::HISTORY_HEADER)
    );
    assert_eq!(mode(&private), 0o600);
    assert_eq!(names(dir.path()), ["private.csv", "ro.csv"]);
}

/// Another user's file: refused when this user may not write it (exit 2, intact); when root
/// replaces a file it keeps the file's owner and group. Needs root (to own files as another
/// user) and `setpriv`; skipped otherwise.
#[cfg(unix)]
#[test]
fn another_users_file_is_refused_unless_writable_and_keeps_its_owner() {
    use std::os::unix::fs::MetadataExt;
    let dir = tempfile::tempdir().unwrap();
    if fs::metadata(dir.path()).unwrap().uid() != 0
        || Command::new("setpriv").arg("--version").output().is_err()
    {
        eprintln!("skipped: needs root and setpriv");
        return;
    }
    set_mode(dir.path(), 0o777); // a shared folder: anyone may create and rename here
    let scenario = copy_in(dir.path(), SCENARIO);
    set_mode(&scenario, 0o644);
    let theirs = dir.path().join("theirs.csv");
    fs::write(&theirs, PREVIOUS).unwrap();
    set_mode(&theirs, 0o644); // root's, readable by all, writable by root only
    let out = Command::new("setpriv")
        .args(["--reuid=65534", "--regid=65534", "--clear-groups"])
        .arg(env!("CARGO_BIN_EXE_sealsim"))
        .args(["run", "oring-nbr-water-80c.toml", "-o", "theirs.csv"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("not writable by this user"), "{err}");
    assert_eq!(fs::read_to_string(&theirs).unwrap(), PREVIOUS);
    assert_eq!(fs::metadata(&theirs).unwrap().uid(), 0);

    // root writes a file of uid/gid 65534: replaced, owner and group kept
    std::os::unix::fs::chown(&theirs, Some(65534), Some(65534)).unwrap();
    let (code, err) = in_dir(
        dir.path(),
        &["run", "oring-nbr-water-80c.toml", "-o", "theirs.csv"],
    );
    assert_eq!(code, Some(0), "{err}");
    let meta = fs::metadata(&theirs).unwrap();
    assert_eq!((meta.uid(), meta.gid()), (65534, 65534));
    assert_eq!(mode(&theirs), 0o644);
    assert!(fs::read_to_string(&theirs).unwrap().starts_with("time_s,"));
}

/// Symbolic links are written through: a dangling link creates its target (as a shell
/// redirect does) and stays a link; a link to itself is refused (exit 2); a dangling link to
/// another output is that output (the guard once saw two files, and the JSON replaced the CSV).
#[cfg(unix)]
#[test]
fn links_are_written_through_and_loops_refused() {
    use std::os::unix::fs::symlink;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    symlink("made.csv", d.join("dangling.csv")).unwrap();
    let (code, err) = in_dir(
        &root(),
        &[
            "run",
            SCENARIO,
            "-o",
            d.join("dangling.csv").to_str().unwrap(),
        ],
    );
    assert_eq!(code, Some(0), "{err}");
    assert!(
        fs::symlink_metadata(d.join("dangling.csv"))
            .unwrap()
            .file_type()
            .is_symlink()
    );
    assert!(
        fs::read_to_string(d.join("made.csv"))
            .unwrap()
            .starts_with("time_s,")
    );

    symlink("loop.csv", d.join("loop.csv")).unwrap();
    let (code, err) = in_dir(
        &root(),
        &["run", SCENARIO, "-o", d.join("loop.csv").to_str().unwrap()],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("symbolic link loop"), "{err}");
    assert!(
        fs::symlink_metadata(d.join("loop.csv"))
            .unwrap()
            .file_type()
            .is_symlink()
    );

    symlink("z.csv", d.join("zlink.json")).unwrap();
    let (code, err) = in_dir(
        &root(),
        &[
            "run",
            SCENARIO,
            "-o",
            d.join("z.csv").to_str().unwrap(),
            "--summary",
            d.join("zlink.json").to_str().unwrap(),
        ],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("writes the same file"), "{err}");
    assert_eq!(
        names(d),
        ["dangling.csv", "loop.csv", "made.csv", "zlink.json"]
    );
}

/// `-o /dev/stdout >> log.txt` and a link to `/proc/self/fd/3` opened with `3>> log` append to
/// the log (its earlier lines once vanished: the redirected file was replaced by rename);
/// `-o /dev/stdout > out.txt` keeps both the CSV and the summary printed after it.
#[cfg(target_os = "linux")]
#[test]
fn an_append_mode_stream_is_appended_to_not_replaced() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    fs::write(d.join("log.txt"), "earlier lines\n").unwrap();
    let (code, err) = shell(d, "\"$B\" run \"$S\" -o /dev/stdout >> log.txt");
    assert_eq!(code, Some(0), "{err}");
    let log = fs::read_to_string(d.join("log.txt")).unwrap();
    assert!(log.starts_with("earlier lines\ntime_s,"), "{}", &log[..200]);

    fs::write(d.join("log3.txt"), "earlier lines\n").unwrap();
    std::os::unix::fs::symlink("/proc/self/fd/3", d.join("fd3")).unwrap();
    let (code, err) = shell(d, "\"$B\" run \"$S\" -o fd3 3>> log3.txt > /dev/null");
    assert_eq!(code, Some(0), "{err}");
    let log = fs::read_to_string(d.join("log3.txt")).unwrap();
    assert!(log.starts_with("earlier lines\ntime_s,"), "{}", &log[..200]);
    assert!(
        fs::symlink_metadata(d.join("fd3"))
            .unwrap()
            .file_type()
            .is_symlink()
    );

    let (code, err) = shell(d, "\"$B\" run \"$S\" -o /dev/stdout > out.txt");
    assert_eq!(code, Some(0), "{err}");
    let out = fs::read_to_string(d.join("out.txt")).unwrap();
    // the CSV, then the summary the command prints after writing it, both kept
    let (code, err) = shell(d, "\"$B\" run \"$S\" > alone.txt");
    assert_eq!(code, Some(0), "{err}");
    let summary = fs::read_to_string(d.join("alone.txt")).unwrap();
    assert!(summary.lines().count() > 3, "{summary}");
    assert!(out.starts_with("time_s,"), "{}", &out[..200]);
    assert!(out.ends_with(&summary), "the summary was lost: {out}");
    assert_eq!(
        names(d),
        ["alone.txt", "fd3", "log.txt", "log3.txt", "out.txt"]
    );
}
