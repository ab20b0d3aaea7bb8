//! `sealsim generate keys`: the scenario key reference, to standard output or atomically to a
//! file, byte for byte the committed `docs/src/reference/keys.md`; `keys` is hidden from help.
//! `sealsim generate columns` likewise, and the CSV headers `run` and `leak` write are the column
//! registry's.

use super::support::sealsim;
use std::path::Path;

/// The committed key reference.
fn committed() -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/reference/keys.md"),
    )
    .unwrap()
}

#[test]
fn keys_goes_to_stdout_or_to_a_file_and_is_the_committed_reference() {
    let out = sealsim().args(["generate", "keys"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(stdout, committed());
    assert!(stdout.contains("| `squeeze` |"), "{stdout}");

    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("keys.md");
    let out = sealsim()
        .args(["generate", "keys", "-o"])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&file).unwrap(), stdout);
}

#[test]
fn keys_is_hidden_from_help() {
    let out = sealsim().args(["generate", "--help"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(help.contains("Usage: sealsim generate"), "{help}");
    assert!(!help.contains("keys"), "{help}");
}

/// The header line of CSV text.
fn header(csv: &str) -> Vec<String> {
    csv.lines()
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect()
}

/// The registry's columns of `file` (0 leak, 1 run) for the groups `which`.
fn registered(file: usize, which: &[usize]) -> Vec<String> {
    let groups = sealsim::report::columns::FILES[file].groups;
    let chosen: Vec<_> = which.iter().map(|&i| groups[i]).collect();
    sealsim::report::columns::names(&chosen)
        .into_iter()
        .map(str::to_owned)
        .collect()
}

#[test]
fn the_csv_headers_written_are_the_column_registry_s() {
    let dir = tempfile::tempdir().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    // (scenario, the groups of its history and of its leak table)
    let cases: [(&str, &[usize], &[usize]); 3] = [
        ("persson-yang-2008.toml", &[0], &[0]),
        ("hydrogen-line-100bar.toml", &[0, 1], &[0, 1]),
        ("hydraulic-rod-seal.toml", &[0, 2, 3], &[0, 2, 3]),
    ];
    for (scenario, history, leak) in cases {
        let csv = dir.path().join(format!("{scenario}.csv"));
        let out = sealsim()
            .arg("run")
            .arg(root.join(scenario))
            .arg("-o")
            .arg(&csv)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{scenario}");
        let text = std::fs::read_to_string(&csv).unwrap();
        assert_eq!(header(&text), registered(1, history), "run {scenario}");
        let out = sealsim()
            .arg("leak")
            .arg(root.join(scenario))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{scenario}");
        let text = String::from_utf8(out.stdout).unwrap();
        assert_eq!(header(&text), registered(0, leak), "leak {scenario}");
    }
}

#[test]
fn columns_is_the_committed_reference() {
    let out = sealsim().args(["generate", "columns"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let committed = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/reference/columns.md"),
    )
    .unwrap();
    assert_eq!(String::from_utf8(out.stdout).unwrap(), committed);
}

#[test]
fn warnings_is_the_committed_page_and_lists_every_code() {
    let out = sealsim().args(["generate", "warnings"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let committed = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/reference/warnings.md"),
    )
    .unwrap();
    assert!(
        stdout == committed,
        "docs/src/reference/warnings.md is stale: run `sealsim generate warnings -o \
         docs/src/reference/warnings.md`"
    );
    for c in sealsim::codes::ALL {
        assert!(stdout.contains(&format!("\n## {}\n", c.code)), "{}", c.code);
    }
}
