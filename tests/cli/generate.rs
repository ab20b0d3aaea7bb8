//! `sealsim generate keys`: the scenario key reference, to standard output or atomically to a
//! file, byte for byte the committed `docs/src/reference/keys.md`; `keys` is hidden from help.

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
