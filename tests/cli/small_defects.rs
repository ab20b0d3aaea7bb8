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

use crate::common::scenario_path;

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

/// The command after `marker` on a comment line of `text`, split into words (the test's paths
/// hold no spaces or quotes).
fn quoted_command(text: &str, marker: &str) -> Vec<String> {
    let line = text
        .lines()
        .find(|l| l.contains(marker))
        .unwrap_or_else(|| panic!("no line with {marker:?} in\n{text}"));
    let command = &line[line.find(marker).unwrap()..];
    let words: Vec<String> = command.split_whitespace().map(str::to_owned).collect();
    assert_eq!(words[0], "sealsim", "{line}");
    words[1..].to_vec()
}

#[test]
fn export_header_of_a_material_file_names_commands_that_work() {
    let dir = TempDir::new().unwrap();
    // a user material whose file stem is no library id
    let file = dir.path().join("my-compound.toml");
    fs::copy(repo_file("materials/nbr-70.toml"), &file).unwrap();
    let file = file.to_str().unwrap();
    for (format, comment) in [("abaqus", "** "), ("ansys", "! ")] {
        let text = stdout_ok(&["materials", "export", "--file", file, "--format", format]);
        let show = quoted_command(&text, "sealsim materials show");
        assert_eq!(show, ["materials", "show", "--file", file], "{text}");
        let described = stdout_ok(&show.iter().map(String::as_str).collect::<Vec<_>>());
        assert!(described.contains("NBR"), "{described}");
        // the first line repeats the export itself
        let first = text.lines().next().unwrap();
        assert!(first.starts_with(comment), "{first}");
        let export = quoted_command(first, "sealsim materials export");
        let again = stdout_ok(&export.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(again, text);
    }
    // a library compound is still named by its id
    let text = stdout_ok(&["materials", "export", "epdm-70", "--format", "abaqus"]);
    let show = quoted_command(&text, "sealsim materials show");
    assert_eq!(show, ["materials", "show", "epdm-70"]);
    stdout_ok(&show.iter().map(String::as_str).collect::<Vec<_>>());
}

/// A small O-ring scenario (line numbers in the tests refer to this text).
const ORING: &str = r#"name = "o-ring"
[material]
library = "nbr-70"
[surface]
rms_roughness = "0.8 um"
hurst_exponent = 0.7
q0 = "3e5 1/m"
q1 = "1e10 1/m"
[fluid]
viscosity = "1 mPa*s"
pressure_difference = "2 bar"
[seal]
kind = "o-ring"
cross_section = "3.53 mm"
mean_diameter = "50 mm"
squeeze = 0.2
"#;

/// `ORING` with `from` replaced by `to`, written to `dir/s.toml`.
fn oring_with(dir: &TempDir, from: &str, to: &str) -> PathBuf {
    assert!(ORING.contains(from), "{from}");
    let path = dir.path().join("s.toml");
    fs::write(&path, ORING.replacen(from, to, 1)).unwrap();
    path
}

#[test]
fn seal_and_shift_kinds_take_the_right_article() {
    let dir = TempDir::new().unwrap();
    let scenario = oring_with(&dir, "squeeze = 0.2\n", "squeeze = 0.2\nwidth = \"1 mm\"\n");
    let stderr = stderr_rejected(&["leak", scenario.to_str().unwrap()]);
    assert!(
        stderr.contains("s.toml:17: seal.width: not a key of an O-ring seal, which takes"),
        "{stderr}"
    );
    let scenario = oring_with(&dir, "squeeze = 0.2\n", "");
    let stderr = stderr_rejected(&["run", scenario.to_str().unwrap()]);
    assert!(
        stderr.contains("seal.squeeze: missing key `squeeze` in [seal] (an O-ring seal needs"),
        "{stderr}"
    );
    // a material file whose Arrhenius shift has a WLF constant
    let text = fs::read_to_string(repo_file("materials/nbr-70.toml"))
        .unwrap()
        .replacen(
            "kind = \"wlf\"\n",
            "kind = \"arrhenius\"\nactivation_energy = \"90 kJ/mol\"\n",
            1,
        );
    let material = dir.path().join("m.toml");
    fs::write(&material, text).unwrap();
    let stderr = stderr_rejected(&["materials", "show", "--file", material.to_str().unwrap()]);
    assert!(
        stderr.contains("not a parameter of an Arrhenius shift, which takes"),
        "{stderr}"
    );
    for bad in ["a o-ring", "a arrhenius", "a O-ring"] {
        assert!(!stderr.to_lowercase().contains(bad), "{stderr}");
    }
}

#[test]
fn no_text_of_the_project_says_a_o_ring() {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path
                .extension()
                .is_some_and(|e| ["rs", "md", "toml"].iter().any(|x| e == *x))
            {
                out.push(path);
            }
        }
    }
    let mut files = vec![repo_file("README.md")];
    for dir in ["src", "scenarios", "materials"] {
        walk(&repo_file(dir), &mut files);
    }
    for file in files {
        let text = fs::read_to_string(&file).unwrap().to_lowercase();
        for bad in ["a o-ring", "a arrhenius shift"] {
            assert!(!text.contains(bad), "{} says {bad:?}", file.display());
        }
    }
}

#[test]
fn numbers_in_error_messages_are_readable() {
    let dir = TempDir::new().unwrap();
    // 3.53 mm is 0.0035299999999999997 m in binary
    let scenario = oring_with(
        &dir,
        "mean_diameter = \"50 mm\"",
        "mean_diameter = \"3 mm\"",
    );
    for command in ["leak", "run"] {
        let stderr = stderr_rejected(&[command, scenario.to_str().unwrap()]);
        assert!(
            stderr.contains(
                "s.toml:15: seal.mean_diameter: must exceed the cross_section (0.00353 m), got 0.003 m"
            ),
            "{stderr}"
        );
    }
    // 0.07 mm is 7.000000000000001e-5 m in binary
    let scenario = oring_with(&dir, "\"0.8 um\"", "\"-0.07 mm\"");
    let stderr = stderr_rejected(&["leak", scenario.to_str().unwrap()]);
    assert!(
        stderr.contains("s.toml:5: surface.rms_roughness: must be positive, got -7e-5 m"),
        "{stderr}"
    );
    // a bound of a quantity with a unit
    let scenario = oring_with(&dir, "\"3.53 mm\"", "\"-3.53 mm\"");
    let stderr = stderr_rejected(&["leak", scenario.to_str().unwrap()]);
    assert!(
        stderr.contains("s.toml:14: seal.cross_section: must be positive, got -0.00353 m"),
        "{stderr}"
    );
    // a flag value
    let stderr = stderr_rejected(&[
        "leak",
        scenario_path("persson-yang-2008.toml").to_str().unwrap(),
        "--sweep",
        "0.7MPa..0.07MPa",
    ]);
    assert!(
        stderr.contains("the end of the sweep must exceed its start, got 700000 Pa..70000 Pa"),
        "{stderr}"
    );
}

#[test]
fn negative_pressures_reach_the_parser() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.csv");
    let scenario = scenario_path("persson-yang-2008.toml");
    let scenario = scenario.to_str().unwrap();
    let out_arg = out.to_str().unwrap();
    let cases: [(&[&str], &str); 5] = [
        (
            &["--pressures", "-1MPa"],
            "invalid value '-1MPa' for '--contact-pressures <P,...>': a nominal pressure must be \
             positive and finite, got -1e6 Pa",
        ),
        (
            &["--pressures", "-2e5"],
            "invalid value '-2e5' for '--contact-pressures <P,...>': a pressure needs its unit",
        ),
        (
            &["--pressures", "-0.1MPa,0.2MPa"],
            "invalid value '-0.1MPa' for '--contact-pressures <P,...>'",
        ),
        (
            &["--sweep", "-1MPa..1MPa"],
            "invalid value '-1MPa..1MPa' for '--sweep <A..B>': a nominal pressure must be \
             positive and finite, got -1e6 Pa",
        ),
        (
            &["--sweep", "0.1MPa..1MPa", "--points", "-3"],
            "invalid value '-3' for '--points <N>'",
        ),
    ];
    for (flags, expected) in cases {
        let mut args = vec!["leak", scenario];
        args.extend_from_slice(flags);
        args.extend_from_slice(&["-o", out_arg]);
        let stderr = stderr_rejected(&args);
        assert!(stderr.contains(expected), "{flags:?}:\n{stderr}");
        assert!(!stderr.contains("unexpected argument"), "{stderr}");
        assert!(!out.exists(), "{flags:?}: the output was written");
    }
    // the flags still take their ordinary values
    cargo_bin_cmd!("sealsim")
        .args([
            "leak",
            scenario,
            "--pressures",
            "0.1MPa,0.2MPa",
            "-o",
            out_arg,
        ])
        .assert()
        .success();
    assert_eq!(fs::read_to_string(&out).unwrap().lines().count(), 3);
}

/// The README's text.
fn readme() -> String {
    fs::read_to_string(repo_file("README.md")).unwrap()
}

/// The section of `text` from the heading `heading` to the next heading of any level.
fn section<'a>(text: &'a str, heading: &str) -> &'a str {
    let start = text
        .find(&format!("\n{heading}\n"))
        .unwrap_or_else(|| panic!("no heading {heading:?}"))
        + heading.len()
        + 2;
    let rest = &text[start..];
    let end = rest.find("\n#").unwrap_or(rest.len());
    &rest[..end]
}

#[test]
fn readme_says_how_to_install_and_lists_every_command() {
    let text = readme();
    // right after the set-up commands, before the first section
    let intro = &text[..text.find("\n## ").unwrap()];
    assert!(intro.contains("cargo install --path ."), "{intro}");
    assert!(intro.contains("cargo test --release"), "{intro}");
    // the commands table has a row for every subcommand
    let table = section(&text, "## Commands");
    let help = stdout_ok(&["--help"]);
    let commands: Vec<&str> = help
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .collect();
    assert!(commands.contains(&"fit-prony"), "{help}");
    for command in commands {
        assert!(
            table.contains(&format!("| `sealsim {command} ")),
            "the README's commands table has no row for {command}:\n{table}"
        );
    }
}

/// `(name, version)` of every package in Cargo.lock.
fn locked_packages() -> Vec<(String, String)> {
    let lock = fs::read_to_string(repo_file("Cargo.lock")).unwrap();
    let mut out = Vec::new();
    let mut name = None;
    for line in lock.lines() {
        if let Some(n) = line.strip_prefix("name = ") {
            name = Some(n.trim_matches('"').to_owned());
        } else if let (Some(v), Some(n)) = (line.strip_prefix("version = "), name.take()) {
            out.push((n, v.trim_matches('"').to_owned()));
        }
    }
    out
}

/// Every `(crate, version)` the README names: a locked package's name as a word, then
/// (after an optional closing backtick) a space and a version number.
fn versions_named_in(text: &str, packages: &[(String, String)]) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (name, _) in packages {
        for (at, _) in text.match_indices(name.as_str()) {
            let before = text[..at].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || "_-./".contains(c)) {
                continue;
            }
            let after = &text[at + name.len()..];
            let after = after.strip_prefix('`').unwrap_or(after);
            let Some(after) = after.strip_prefix(' ') else {
                continue;
            };
            let version: String = after
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.')
                .collect();
            let version = version.trim_end_matches('.');
            if version.contains('.') {
                out.push((name.clone(), version.to_owned()));
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

#[test]
fn readme_crate_versions_match_the_lock_file() {
    let packages = locked_packages();
    assert!(packages.iter().any(|(n, _)| n == "statrs"));
    // the README and the guide's install page, where the dependencies moved
    let text =
        readme() + &fs::read_to_string(repo_file("docs/src/getting-started/install.md")).unwrap();
    let named = versions_named_in(&text, &packages);
    // they name at least these
    for name in ["statrs", "nalgebra", "ode_solvers"] {
        assert!(named.iter().any(|(n, _)| n == name), "{named:?}");
    }
    for (name, version) in named {
        let locked: Vec<&str> = packages
            .iter()
            .filter(|(n, _)| *n == name)
            .map(|(_, v)| v.as_str())
            .collect();
        assert!(
            locked
                .iter()
                .any(|v| *v == version || v.starts_with(&format!("{version}."))),
            "the README or the guide names {name} {version}, Cargo.lock has {locked:?}"
        );
    }
}

/// The declared minimum Rust version is the toolchain the tests run on (CI's), and the README
/// says the same: no minimum is claimed that nothing checks.
#[test]
fn no_unchecked_minimum_rust_version_is_claimed() {
    let manifest = fs::read_to_string(repo_file("Cargo.toml")).unwrap();
    let declared = manifest
        .lines()
        .find_map(|l| l.strip_prefix("rust-version = \""))
        .and_then(|rest| rest.strip_suffix('"'))
        .expect("[workspace.package] rust-version");
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let out = std::process::Command::new(rustc)
        .arg("--version")
        .output()
        .unwrap();
    let running = String::from_utf8(out.stdout).unwrap();
    // "rustc 1.95.0 (…)": the major.minor of the toolchain running the tests
    let minor: String = running
        .split_whitespace()
        .nth(1)
        .unwrap()
        .split('.')
        .take(2)
        .collect::<Vec<_>>()
        .join(".");
    assert_eq!(declared, minor, "declared {declared}, tested on {running}");
    let text = readme();
    assert!(
        !text.contains("(1.88+"),
        "the README still claims Rust 1.88+"
    );
    assert!(
        text.contains(&format!(
            "a stable Rust toolchain (tested with {declared}, the one CI uses)"
        )),
        "the README does not say which toolchain it is tested with"
    );
}

/// The licence the manifests declare is the one the repository carries (both texts, the Rust
/// convention "MIT OR Apache-2.0"), every crate of the workspace inherits it, and the citation
/// file names this version and the paper sealsim implements.
#[test]
fn licence_and_citation_files_match_the_manifests() {
    let manifest = fs::read_to_string(repo_file("Cargo.toml")).unwrap();
    assert!(
        manifest.contains("\nlicense = \"MIT OR Apache-2.0\"\n"),
        "[workspace.package] declares the licence"
    );
    for krate in [
        "Cargo.toml",
        "crates/sealsim-core/Cargo.toml",
        "crates/sealsim-math/Cargo.toml",
    ] {
        let text = fs::read_to_string(repo_file(krate)).unwrap();
        assert!(
            text.contains("\nlicense.workspace = true\n"),
            "{krate} does not inherit the workspace licence"
        );
    }
    let mit = fs::read_to_string(repo_file("LICENSE-MIT")).unwrap();
    assert!(mit.starts_with("MIT License") && mit.contains("WITHOUT WARRANTY OF ANY KIND"));
    let apache = fs::read_to_string(repo_file("LICENSE-APACHE")).unwrap();
    assert!(apache.contains("Apache License") && apache.contains("Version 2.0, January 2004"));
    assert!(apache.contains("END OF TERMS AND CONDITIONS"));

    let version = manifest
        .lines()
        .find_map(|l| l.strip_prefix("version = \""))
        .and_then(|rest| rest.strip_suffix('"'))
        .expect("[workspace.package] version");
    let cff = fs::read_to_string(repo_file("CITATION.cff")).unwrap();
    assert!(cff.starts_with("# ") && cff.contains("\ncff-version: 1.2.0\n"));
    assert!(
        cff.contains(&format!("\nversion: {version}\n")),
        "CITATION.cff names another version than Cargo.toml's {version}"
    );
    assert!(cff.contains("- MIT\n") && cff.contains("- Apache-2.0\n"));
    assert!(cff.contains("title: \"Theory of the leak-rate of seals\""));
    assert!(cff.contains("start: 315011"));
}
