//! `sealsim new`: every template, written as a user would, runs unchanged with exit 0; the
//! list names them all; nothing is ever written over an existing file.

use crate::support::sealsim;
use std::fs;

/// The template names `--list` prints, in order.
fn listed() -> Vec<String> {
    let out = sealsim().args(["new", "--list"]).output().unwrap();
    assert!(out.status.success());
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .take_while(|l| !l.is_empty())
        .map(|l| l.split_whitespace().next().unwrap().to_owned())
        .collect()
}

#[test]
fn the_list_names_every_template_in_the_templates_folder() {
    let names = listed();
    let mut files: Vec<String> = fs::read_dir(crate::common::scenarios_dir().join("templates"))
        .unwrap()
        .map(|e| {
            let p = e.unwrap().path();
            p.file_stem().unwrap().to_string_lossy().into_owned()
        })
        .collect();
    files.sort();
    let mut sorted = names.clone();
    sorted.sort();
    assert_eq!(sorted, files);
    for expected in [
        "o-ring-face",
        "o-ring-piston",
        "o-ring-rod",
        "flat-gasket",
        "gas-flange",
        "study",
    ] {
        assert!(
            names.iter().any(|n| n == expected),
            "{expected} missing from --list"
        );
    }
}

/// Each scenario template written with `-o` runs with `sealsim run` unchanged, exit 0, and
/// reaches a verdict; the file is the template's text (the same bytes as on stdout).
#[test]
fn every_scenario_template_runs_unchanged() {
    let dir = tempfile::tempdir().unwrap();
    for name in listed().iter().filter(|n| *n != "study") {
        let file = dir.path().join(format!("{name}.toml"));
        sealsim()
            .args(["new", name, "-o"])
            .arg(&file)
            .assert()
            .success();
        let stdout = sealsim().args(["new", name]).output().unwrap().stdout;
        assert_eq!(
            fs::read(&file).unwrap(),
            stdout,
            "{name}: -o and stdout differ"
        );
        let out = sealsim()
            .arg("run")
            .arg(&file)
            .arg("--summary")
            .arg(dir.path().join(format!("{name}.json")))
            .arg("-o")
            .arg(dir.path().join(format!("{name}.csv")))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{name}: {stderr}");
        assert!(!stderr.contains("error"), "{name}: {stderr}");
        let summary = fs::read_to_string(dir.path().join(format!("{name}.json"))).unwrap();
        assert!(summary.contains("\"verdict\""), "{name}: no verdict");
    }
}

/// The study template with `-o` writes its base beside it; both run with `sealsim study`
/// unchanged. `--base` names an existing scenario instead, and a missing one exits 2.
#[test]
fn the_study_template_runs_with_the_base_it_writes_or_names() {
    let dir = tempfile::tempdir().unwrap();
    let study = dir.path().join("tolerances.toml");
    sealsim()
        .args(["new", "study", "-o"])
        .arg(&study)
        .assert()
        .success();
    let base = dir.path().join("tolerances.base.toml");
    assert!(base.is_file(), "the base scenario was not written");
    let out = sealsim()
        .arg("study")
        .arg(&study)
        .arg("-o")
        .arg(dir.path().join("cases.csv"))
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cases = fs::read_to_string(dir.path().join("cases.csv")).unwrap();
    assert!(cases.lines().count() > 40, "40 cases and a header expected");

    // --base: the study names the given scenario and writes no other file
    let sub = dir.path().join("sub");
    fs::create_dir(&sub).unwrap();
    let own = sub.join("own.toml");
    sealsim()
        .args(["new", "study", "--base"])
        .arg(&base)
        .arg("-o")
        .arg(&own)
        .assert()
        .success();
    assert_eq!(fs::read_dir(&sub).unwrap().count(), 1);
    sealsim()
        .arg("study")
        .arg(&own)
        .arg("-o")
        .arg(sub.join("c.csv"))
        .assert()
        .success();

    sealsim()
        .args(["new", "study", "--base"])
        .arg(dir.path().join("missing.toml"))
        .assert()
        .code(2);
}

/// Never over an existing file: exit 2, the file untouched, and for the study no base
/// written either.
#[test]
fn nothing_is_written_over_an_existing_file() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("mine.toml");
    fs::write(&file, "my own scenario").unwrap();
    for template in ["o-ring-face", "study"] {
        sealsim()
            .args(["new", template, "-o"])
            .arg(&file)
            .assert()
            .code(2);
        assert_eq!(fs::read_to_string(&file).unwrap(), "my own scenario");
    }
    assert!(!dir.path().join("mine.base.toml").exists());
    // an existing base blocks the study too, before anything is written
    let study = dir.path().join("s.toml");
    fs::write(dir.path().join("s.base.toml"), "kept").unwrap();
    sealsim()
        .args(["new", "study", "-o"])
        .arg(&study)
        .assert()
        .code(2);
    assert!(!study.exists());
    assert_eq!(
        fs::read_to_string(dir.path().join("s.base.toml")).unwrap(),
        "kept"
    );
    // an unknown template and --base on a scenario template are bad input
    sealsim().args(["new", "o-ring"]).assert().code(2);
    sealsim()
        .args(["new", "o-ring-face", "--base", "x.toml"])
        .assert()
        .code(2);
}
