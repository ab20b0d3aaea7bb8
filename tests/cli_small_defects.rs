//! End-to-end tests of small defects a new user found: help texts that miss a fidelity level,
//! a generated header naming a command that fails, "a o-ring", binary noise in numbers of
//! error messages, negative flag values read as options, and README statements that drifted.

use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use std::fs;
use std::path::{Path, PathBuf};
use tempfile::TempDir;

/// The five levels of the fidelity ladder, as the command line names them.
const LEVELS: [&str; 5] = [
    "rule-of-thumb",
    "critical-junction",
    "exact",
    "effective-medium",
    "numerical",
];

fn repo_file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(name)
}

fn scenario_path(name: &str) -> PathBuf {
    repo_file("scenarios").join(name)
}

/// Runs `sealsim <args>`, expects success and returns stdout.
fn stdout_ok(args: &[&str]) -> String {
    let out = cargo_bin_cmd!("sealsim").args(args).assert().success();
    String::from_utf8(out.get_output().stdout.clone()).unwrap()
}

/// Runs `sealsim <args>`, expects exit status 2, an `error: ` line and no panic; returns stderr.
fn stderr_rejected(args: &[&str]) -> String {
    let out = cargo_bin_cmd!("sealsim")
        .args(args)
        .assert()
        .code(2)
        .stdout(predicate::str::is_empty())
        .stderr(predicate::str::contains("panicked").not());
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(stderr.starts_with("error: "), "{stderr}");
    stderr
}

#[test]
fn every_fidelity_flag_lists_all_five_levels() {
    for command in ["run", "leak", "compare", "figures"] {
        for help in ["--help", "-h"] {
            let text = stdout_ok(&[command, help]);
            assert!(text.contains("--fidelity"), "{command} {help}:\n{text}");
            for level in LEVELS {
                assert!(
                    text.contains(level),
                    "`sealsim {command} {help}` does not name {level}:\n{text}"
                );
            }
        }
        // the alias of the contact-table level is documented
        let text = stdout_ok(&[command, "--help"]);
        assert!(text.contains("table"), "{command} --help:\n{text}");
    }
    // tradeoff runs every level itself and takes no --fidelity
    let text = stdout_ok(&["tradeoff", "--help"]);
    assert!(!text.contains("--fidelity"), "{text}");
}

#[test]
fn every_fidelity_level_and_alias_is_accepted() {
    let dir = TempDir::new().unwrap();
    for level in ["rule-of-thumb", "critical-junction", "table", "exact"] {
        let out = dir.path().join(format!("{level}.csv"));
        cargo_bin_cmd!("sealsim")
            .arg("leak")
            .arg(scenario_path("persson-yang-2008.toml"))
            .args(["--fidelity", level, "--pressures", "0.2MPa", "-o"])
            .arg(&out)
            .assert()
            .success();
        assert!(fs::read_to_string(&out).unwrap().lines().count() == 2);
    }
    let stderr = stderr_rejected(&[
        "leak",
        scenario_path("persson-yang-2008.toml").to_str().unwrap(),
        "--fidelity",
        "fast",
    ]);
    assert!(stderr.contains("invalid value 'fast'"), "{stderr}");
    for level in LEVELS {
        assert!(stderr.contains(level), "{stderr}");
    }
}
