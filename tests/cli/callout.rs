//! Drawing callouts (`[surface] ra`, `rq`, `rz` with `cutoff`, `short_cutoff`,
//! `short_wavelength`) and a rough rubber (`[rubber_surface]`), issue 16 items 1 and 3:
//! bad input exits 2 with `file:line: key` and writes nothing; the sum of spectra is what the
//! contact sees, whichever body carries which roughness.

use super::support::{run_text, sealsim};
use std::path::Path;

/// A flat elastic seal (PY08 §3's rubber and fluid, P0 = 0.1 MPa) on the surface tables given.
fn flat(surfaces: &str) -> String {
    format!(
        "name = \"callout\"\n\
         [material]\n\
         youngs_modulus = \"10 MPa\"\n\
         poisson_ratio = 0.5\n\
         {surfaces}\n\
         [fluid]\n\
         viscosity = \"1e-3 Pa*s\"\n\
         pressure_difference = \"0.01 MPa\"\n\
         [seal]\n\
         nominal_pressure = \"0.1 MPa\"\n\
         width = \"1 mm\"\n\
         length = \"1 mm\"\n"
    )
}

/// 1-based line of the first line starting with `start` in `text`.
fn line_of(text: &str, start: &str) -> usize {
    text.lines().position(|l| l.starts_with(start)).unwrap() + 1
}

/// `sealsim run` on `text` with `-o` and `--summary`: asserts exit 2, the message located at
/// `s.toml:line: key` containing `needle`, and no output.
fn refused(text: &str, line: usize, key: &str, needle: &str) {
    let (code, _, stderr, csv, summary) = run_text(text);
    assert_eq!(code, Some(2), "{stderr}");
    let at = format!("s.toml:{line}: {key}: ");
    assert!(stderr.contains(&at), "expected {at:?} in:\n{stderr}");
    assert!(stderr.contains(needle), "expected {needle:?} in:\n{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(csv.is_none() && summary.is_none(), "an output was written");
}

#[test]
fn ra_with_rms_roughness_is_refused() {
    let text = flat("[surface]\nra = \"0.4 um\"\nrms_roughness = \"1 um\"");
    let line = line_of(&text, "rms_roughness");
    refused(
        &text,
        line,
        "surface.rms_roughness",
        "rms_roughness and ra are mutually exclusive",
    );
}

#[test]
fn ra_and_rz_together_are_refused() {
    let text = flat("[surface]\nra = \"0.4 um\"\nrz = \"3 um\"");
    refused(
        &text,
        line_of(&text, "rz"),
        "surface.rz",
        "ra and rz are mutually exclusive",
    );
}

#[test]
fn a_callout_with_psd_file_or_rolloff_is_refused() {
    let text = flat("[surface]\nrq = \"0.5 um\"\npsd_file = \"p.csv\"");
    refused(
        &text,
        line_of(&text, "psd_file"),
        "surface.psd_file",
        "psd_file and rq are mutually exclusive",
    );
    let text = flat("[surface]\nrq = \"0.5 um\"\nrolloff = \"1e4 1/m\"");
    refused(
        &text,
        line_of(&text, "rolloff"),
        "surface.rolloff",
        "2π/cutoff",
    );
}

#[test]
fn cutoff_not_longer_than_short_cutoff_is_refused() {
    let text = flat("[surface]\nra = \"0.4 um\"\ncutoff = \"25 um\"\nshort_cutoff = \"25 um\"");
    refused(
        &text,
        line_of(&text, "cutoff"),
        "surface.cutoff",
        "must be longer than the short cut-off",
    );
    // the default λs = 2.5 µm against a given λc of 2 µm
    let text = flat("[surface]\nra = \"0.4 um\"\ncutoff = \"2 um\"");
    refused(
        &text,
        line_of(&text, "cutoff"),
        "surface.cutoff",
        "must lie in [1e-5, 0.1] m, got 2e-6 m",
    );
    let text = flat("[surface]\nra = \"0.4 um\"\ncutoff = \"20 um\"\nshort_cutoff = \"30 um\"");
    refused(
        &text,
        line_of(&text, "cutoff"),
        "surface.cutoff",
        "must be longer than the short cut-off",
    );
}

#[test]
fn out_of_range_and_stray_keys_are_refused() {
    let text = flat("[surface]\nra = \"0.5 nm\"");
    refused(&text, line_of(&text, "ra"), "surface.ra", "must lie in");
    let text = flat("[surface]\nra = \"0.4 um\"\nshort_wavelength = \"maybe\"");
    refused(
        &text,
        line_of(&text, "short_wavelength"),
        "surface.short_wavelength",
        "\"extend\"",
    );
    let text = flat("[surface]\nra = \"0.4 um\"\nshort_wavelength = \"stop\"\nq1 = \"1e9 1/m\"");
    refused(
        &text,
        line_of(&text, "short_wavelength"),
        "surface.short_wavelength",
        "short_wavelength and q1 are mutually exclusive",
    );
    let text = flat("[surface]\nra = \"0.4 um\"\nq1 = \"1e6 1/m\"");
    refused(
        &text,
        line_of(&text, "q1"),
        "surface.q1",
        "must be at least 2π/short_cutoff",
    );
    let text = flat(
        "[surface]\nrms_roughness = \"1 um\"\nhurst_exponent = 0.8\nq0 = \"1e4 1/m\"\n\
         q1 = \"1e9 1/m\"\ncutoff = \"0.8 mm\"",
    );
    refused(
        &text,
        line_of(&text, "cutoff"),
        "surface.cutoff",
        "only applies to a drawing callout",
    );
}

#[test]
fn rubber_surface_errors_name_their_table() {
    let text = flat("[surface]\nra = \"0.4 um\"\n[rubber_surface]\nra = \"0.2 um\"\nrz = \"1 um\"");
    refused(
        &text,
        line_of(&text, "rz"),
        "rubber_surface.rz",
        "ra and rz are mutually exclusive",
    );
    let text = flat(
        "[surface]\nra = \"0.4 um\"\n[rubber_surface]\nheight_map = \"m.csv\"\npixel_size = \"1 um\"",
    );
    refused(
        &text,
        line_of(&text, "height_map"),
        "rubber_surface.height_map",
        "as a spectrum",
    );
}

/// `sealsim leak` on `text`: (stdout CSV, stderr).
fn leak(text: &str) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    let scenario = dir.path().join("s.toml");
    std::fs::write(&scenario, text).unwrap();
    let out = sealsim()
        .arg("leak")
        .arg(&scenario)
        .arg("--verbose") // the notes say how the callout was read
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    (String::from_utf8(out.stdout).unwrap(), stderr)
}

/// The leak rate of the one row of `sealsim leak`'s CSV.
fn leak_rate(csv: &str) -> f64 {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let row: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header
        .iter()
        .position(|&h| h == "leak_rate_m3_per_s")
        .unwrap();
    row[k].parse().unwrap()
}

#[test]
fn rough_rubber_on_a_counterface_is_the_swapped_pair() {
    // C_counterface + C_rubber is symmetric: which body carries which roughness cannot matter
    let a = "[surface]\nra = \"0.8 um\"\nhurst_exponent = 0.7\n";
    let b =
        "rms_roughness = \"0.3 um\"\nhurst_exponent = 0.85\nq0 = \"2e4 1/m\"\nq1 = \"1e9 1/m\"\n";
    let one = flat(&format!("{a}[rubber_surface]\n{b}"));
    let two = flat(&format!(
        "[surface]\n{b}[rubber_surface]\n{}",
        a.trim_start_matches("[surface]\n")
    ));
    let (x, _) = leak(&one);
    let (y, _) = leak(&two);
    assert_eq!(x, y);
    assert!(leak_rate(&x) > 0.0, "{x}");
}

#[test]
fn the_same_callout_on_both_bodies_is_root_two_on_one() {
    // same H and band: C_sum = 2 C, i.e. Rq × √2 on one body (exact: one power law)
    let rq = 0.9e-6;
    let both = flat(&format!(
        "[surface]\nrq = \"{rq:e} m\"\n[rubber_surface]\nrq = \"{rq:e} m\""
    ));
    let one = flat(&format!(
        "[surface]\nrq = \"{:e} m\"",
        rq * std::f64::consts::SQRT_2
    ));
    let (x, stderr) = leak(&both);
    let (y, _) = leak(&one);
    assert!(stderr.contains("rubber_surface.rq: callout rq"), "{stderr}");
    let (qx, qy) = (leak_rate(&x), leak_rate(&y));
    assert!(qx > 0.0 && (qx / qy - 1.0).abs() < 1e-9, "{qx} vs {qy}");
    // and a smooth rubber (no table) changes nothing against the same file without it
    let (z, _) = leak(&flat(&format!("[surface]\nrq = \"{rq:e} m\"")));
    assert!(leak_rate(&z) < qx, "a rougher pair leaks more");
}

#[test]
fn the_headline_callout_scenario_runs_end_to_end() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml");
    let dir = tempfile::tempdir().unwrap();
    let summary = dir.path().join("s.json");
    let out = sealsim()
        .arg("run")
        .arg(&path)
        .arg("--verbose") // the notes say how the callout was read
        .arg("--summary")
        .arg(&summary)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    // the rule below λs is printed
    assert!(
        stderr.contains("surface.ra: callout ra = 4e-7 m")
            && stderr.contains("short_wavelength = \"extend\""),
        "{stderr}"
    );
    // a ground face is not steep: no rms-slope warning (it had 8.3 before)
    assert!(!stderr.contains("the surface is steep"), "{stderr}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&summary).unwrap()).unwrap();
    // Physics, not this output: Rq 0.5 µm, h'_rms 0.075 ⇒ no channel percolates above
    // P_seal ≈ 0.262 E* h'_rms ≈ 0.02 E* (docs/model.md §2), far below the installed ring's
    // MPa contact pressure for any rubbery modulus: sealed at installation.
    assert_eq!(json["initial_leak_rate_m3_per_s"].as_f64().unwrap(), 0.0);
}
