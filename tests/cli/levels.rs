//! The level band of `sealsim run` and `compare` (docs/model.md §4.1): a verdict that the
//! neighbouring fidelity level decides otherwise is UNDECIDED in every output, one it decides
//! the same way says so.

use crate::support::{compare_csv, run_text, sealsim};

/// The spring-loaded face seal (HNBR, 0.5 bar of water over 30 years) judged on its leaked
/// volume: the critical junction leaks 4.1e-9 m³ and the effective medium 7.3e-8 m³ in 30 years
/// (measured, docs/src/reference/fidelity.md), so a limit of 1e-8 m³ lies between the levels.
fn spring_seal(limit: &str) -> String {
    let text =
        std::fs::read_to_string(crate::common::scenario_path("spring-loaded-face-seal.toml"))
            .unwrap();
    assert!(text.contains("max_leak_rate = \"1e-9 m^3/s\""));
    text.replace(
        "max_leak_rate = \"1e-9 m^3/s\"",
        &format!("max_leaked_volume = \"{limit}\""),
    )
}

#[test]
fn a_verdict_the_levels_disagree_on_is_undecided_everywhere() {
    let text = spring_seal("1e-8 m^3");
    let (code, stdout, stderr, _, json) = run_text(&text);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stdout.contains("UNDECIDED by the model"), "{stdout}");
    assert!(stdout.contains("level band"), "{stdout}");
    let json: serde_json::Value = serde_json::from_str(&json.unwrap()).unwrap();
    assert_eq!(json["verdict"], "undecided", "{json}");
    let band = &json["level_band"];
    assert_eq!(band["level"], "effective-medium", "{band}");
    // the neighbour's volume lies above the limit, this level's below it
    let own = json["leaked_volume_m3"].as_f64().unwrap();
    let other = band["leaked_volume_m3"].as_f64().unwrap();
    assert!(own < 1e-8 && other > 1e-8, "{own} {other}");

    // --fail-exit-code: undecided is not a pass
    let dir = tempfile::tempdir().unwrap();
    let scenario = dir.path().join("s.toml");
    std::fs::write(&scenario, &text).unwrap();
    let out = sealsim()
        .arg("run")
        .arg(&scenario)
        .args(["--fail-exit-code", "7", "-o"])
        .arg(dir.path().join("h.csv"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(7));

    // compare: the neighbour's verdict beside this level's
    let (_, header, rows) = compare_csv(&scenario, "hnbr-75");
    let row = &rows[0];
    let col = |name: &str| &row[header.iter().position(|h| h == name).unwrap()];
    assert_eq!(col("verdict"), "undecided", "{rows:?}");
    assert_eq!(col("neighbour_level"), "effective-medium", "{rows:?}");
    assert!(col("neighbour_verdict").starts_with("fails"), "{rows:?}");
}

#[test]
fn a_verdict_the_levels_agree_on_says_so() {
    // a limit above both levels' volumes: both survive
    let (code, stdout, stderr, _, json) = run_text(&spring_seal("1e-6 m^3"));
    assert_eq!(code, Some(0), "{stderr}");
    assert!(!stdout.contains("UNDECIDED"), "{stdout}");
    assert!(
        stdout.contains("the same outcome: the model does not decide the verdict"),
        "{stdout}"
    );
    let json: serde_json::Value = serde_json::from_str(&json.unwrap()).unwrap();
    assert_eq!(json["verdict"], "survives", "{json}");
    assert_eq!(json["level_band"]["level"], "effective-medium");
}
