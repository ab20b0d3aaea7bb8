//! Plausible ranges at the boundary (issue 13): values that passed validation and then
//! overflowed (`internal error: non-finite value`) or ran for minutes are refused up front with
//! exit 2, `file:line: key: must lie in [a, b] unit, got x`, and nothing written.

use super::support::sealsim;
use std::path::Path;

/// A shipped scenario with the line `key = …` replaced by `key = value`.
fn mutated(shipped: &str, key: &str, value: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios")
        .join(shipped);
    let text = std::fs::read_to_string(path).unwrap();
    let mut found = false;
    let lines: Vec<String> = text
        .lines()
        .map(|l| {
            if l.starts_with(&format!("{key} =")) {
                found = true;
                format!("{key} = {value}")
            } else {
                l.to_string()
            }
        })
        .collect();
    assert!(found, "{shipped} has no `{key} =` line");
    lines.join("\n") + "\n"
}

/// The shipped hot-oil FKM scenario with its callout face replaced by a self-affine surface
/// (`rms_roughness`, H 0.7, q0 3e5 1/m, `q1`), each key on its own line.
fn self_affine_fkm(rms: &str, q1: &str) -> String {
    let text = mutated("oring-fkm-hot-oil-ageing.toml", "ra", "\"0.8 um\"");
    let mut out = String::new();
    for l in text.lines() {
        if l.starts_with("ra =") {
            out += &format!(
                "rms_roughness = {rms}\nhurst_exponent = 0.7\nq0 = \"3e5 1/m\"\nq1 = \"{q1} 1/m\"\n"
            );
        } else if !(l.starts_with("cutoff =")
            || l.starts_with("short_cutoff =")
            || l.starts_with("short_wavelength ="))
        {
            out += l;
            out.push('\n');
        }
    }
    out
}

/// 1-based line of `key = ` in `text`.
fn line_of(text: &str, key: &str) -> usize {
    text.lines()
        .position(|l| l.starts_with(&format!("{key} =")))
        .unwrap()
        + 1
}

/// Runs `sealsim run` on `text` and asserts exit 2, the located range message and no output.
/// `sealsim run` on scenario `text` (written as `s.toml`) with `-o out.csv --summary out.json`,
/// killed after `seconds`: (exit code, stderr, whether an output exists).
fn run_text(text: &str, seconds: u64) -> (Option<i32>, String, bool) {
    let dir = tempfile::tempdir().unwrap();
    let scenario = dir.path().join("s.toml");
    std::fs::write(&scenario, text).unwrap();
    let (csv, summary) = (dir.path().join("out.csv"), dir.path().join("out.json"));
    let out = sealsim()
        .arg("run")
        .arg(&scenario)
        .arg("-o")
        .arg(&csv)
        .arg("--summary")
        .arg(&summary)
        .timeout(std::time::Duration::from_secs(seconds))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code(), stderr, csv.exists() || summary.exists())
}

fn refused(text: &str, line: usize, key: &str, range: &str) {
    let (code, stderr, written) = run_text(text, 10);
    assert_eq!(code, Some(2), "stderr: {stderr}");
    let expected = format!("s.toml:{line}: {key}: must lie in {range}, got 1e308 m");
    assert!(
        stderr.contains(&expected),
        "want {expected:?}, got:\n{stderr}"
    );
    assert!(!stderr.contains("internal error"), "{stderr}");
    assert!(!written, "something was written");
}

#[test]
fn a_huge_flat_seal_width_is_refused_with_its_range() {
    let text = mutated("spring-loaded-face-seal.toml", "width", "\"1e308 m\"");
    refused(&text, line_of(&text, "width"), "seal.width", "[1e-9, 10] m");
}

#[test]
fn a_huge_flat_seal_length_is_refused_with_its_range() {
    let text = mutated("persson-yang-2008.toml", "length", "\"1e308 m\"");
    refused(
        &text,
        line_of(&text, "length"),
        "seal.length",
        "[1e-9, 10] m",
    );
}

#[test]
fn a_huge_oring_diameter_between_plates_is_refused_with_its_range() {
    let text = "[material]\nlibrary = \"nbr-70\"\n\n[surface]\nrms_roughness = \"0.8 um\"\n\
                hurst_exponent = 0.7\nq0 = \"3e5 1/m\"\nq1 = \"1e10 1/m\"\n\n[fluid]\n\
                viscosity = \"1 mPa*s\"\npressure_difference = \"2 bar\"\n\n[seal]\n\
                kind = \"o-ring\"\ncross_section = \"3.53 mm\"\nmean_diameter = \"1e308 m\"\n\
                squeeze = 0.2\n";
    refused(
        text,
        line_of(text, "mean_diameter"),
        "seal.mean_diameter",
        "[1e-9, 10] m",
    );
}

#[test]
fn a_huge_roughness_with_daily_cycles_is_refused_not_run_for_minutes() {
    // the scenario's face is a callout: its `ra` has the range of a drawing's Ra
    let text = mutated("oring-epdm-outdoor-cycles.toml", "ra", "\"1e308 m\"");
    let line = line_of(&text, "ra");
    refused(&text, line, "surface.ra", "[1e-9, 1e-4] m");
}

#[test]
fn a_huge_roughness_with_ageing_in_hot_oil_is_refused_not_run_for_minutes() {
    let text = mutated("oring-fkm-hot-oil-ageing.toml", "ra", "\"1e308 m\"");
    let line = line_of(&text, "ra");
    refused(&text, line, "surface.ra", "[1e-9, 1e-4] m");
    // … and so does a self-affine surface's rms roughness in the same scenario
    let text = self_affine_fkm("\"1e308 m\"", "1e10");
    let line = line_of(&text, "rms_roughness");
    refused(&text, line, "surface.rms_roughness", "[1e-10, 0.001] m");
}

#[test]
fn too_many_daily_cycles_are_refused_with_the_step_budget() {
    let text = mutated(
        "oring-epdm-outdoor-cycles.toml",
        "duration",
        "\"1000 year\"",
    );
    let (code, stderr, written) = run_text(&text, 10);
    assert_eq!(code, Some(2), "stderr: {stderr}");
    assert!(!written);
    let at = format!(
        "s.toml:{}: simulation.duration:",
        line_of(&text, "duration")
    );
    assert!(stderr.contains(&at), "{stderr}");
    assert!(stderr.contains("internal steps"), "{stderr}");
    assert!(stderr.contains("limit of 400000"), "{stderr}");
}

#[test]
fn the_edges_of_the_ranges_still_run() {
    // the largest roughness and q1 accepted finish (quickly) without an internal error: a
    // self-affine surface at its edges, and the largest callout
    for (rms, q1) in [("\"1 mm\"", "1e10"), ("\"0.8 um\"", "1e12")] {
        let text = self_affine_fkm(rms, q1);
        let (code, stderr, written) = run_text(&text, 60);
        assert_eq!(code, Some(0), "rms_roughness = {rms}, q1 = {q1}: {stderr}");
        assert!(written);
    }
    let text = mutated("oring-fkm-hot-oil-ageing.toml", "ra", "\"100 um\"");
    let (code, stderr, written) = run_text(&text, 60);
    assert_eq!(code, Some(0), "ra = 100 um: {stderr}");
    assert!(written);
}
