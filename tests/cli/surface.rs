//! End-to-end tests of `sealsim surface`: the shipped traces and scenarios, the JSON keys, the
//! rms-slope warning, and bad traces (exit 2, file and line, nothing written).

use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use std::fmt::Write;
use std::fs;
use tempfile::TempDir;

fn json_of(args: &[&str]) -> serde_json::Value {
    let out = cargo_bin_cmd!("sealsim")
        .arg("surface")
        .args(args)
        .arg("--json")
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).unwrap()
}

#[test]
fn shipped_traces_give_gaussian_parameters_and_their_hurst_exponent() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    // (trace, the H of the spectrum it was made from)
    for (trace, hurst) in [("ground-fine.csv", 0.8), ("ground-coarse.csv", 0.7)] {
        let path = format!("{manifest}/scenarios/traces/{trace}");
        let j = json_of(&[&path]);
        for key in [
            "ra_m",
            "rq_m",
            "rz_m",
            "rms_slope",
            "hurst_exponent",
            "q0_per_m",
            "q1_per_m",
        ] {
            assert!(j[key].is_number(), "{trace}: {key} in {j}");
        }
        // Gaussian heights: Rq/Ra = √(π/2) = 1.2533, to the scatter of one 8192-point trace
        let ratio = j["rq_m"].as_f64().unwrap() / j["ra_m"].as_f64().unwrap();
        assert!(
            (ratio / 1.2533 - 1.0).abs() < 0.03,
            "{trace}: Rq/Ra {ratio}"
        );
        // the fitted H within 0.06 of the generator's (one trace; the interval is printed)
        let h = j["hurst_exponent"].as_f64().unwrap();
        assert!((h - hurst).abs() < 0.06, "{trace}: H {h}");
        assert!(
            j["warnings"]
                .as_array()
                .unwrap()
                .iter()
                .all(|w| !w.as_str().unwrap().contains("rms slope"))
        );
    }
}

#[test]
fn every_shipped_scenario_has_a_surface_summary() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let mut seen = 0;
    for entry in fs::read_dir(format!("{manifest}/scenarios")).unwrap() {
        let path = entry.unwrap().path();
        // figure sets (`[[group]]` of scenarios) are not scenarios
        if path.extension().is_some_and(|e| e == "toml")
            && !fs::read_to_string(&path).unwrap().contains("[[group]]")
        {
            let j = json_of(&[path.to_str().unwrap()]);
            let slope = j["rms_slope"].as_f64().unwrap();
            let warned = j["warnings"]
                .as_array()
                .unwrap()
                .iter()
                .any(|w| w.as_str().unwrap().contains("rms slope"));
            assert_eq!(warned, slope > 0.5, "{}: slope {slope}", path.display());
            seen += 1;
        }
    }
    assert!(seen >= 10, "{seen} scenarios");
}

#[test]
fn a_steep_spectrum_is_warned_about() {
    // the old headline surface: 0.8 µm rms, H = 0.7, q0 = 3e5 1/m, q1 = 1e10 1/m → slope 8.3
    let dir = TempDir::new().unwrap();
    let psd = dir.path().join("steep.csv");
    let mut text = "q,C\n".to_string();
    let (q0, q1, h, hrms): (f64, f64, f64, f64) = (3e5, 1e10, 0.7, 0.8e-6);
    let c0 = h / std::f64::consts::PI * hrms * hrms / (q0.powf(-2.0 * h) - q1.powf(-2.0 * h));
    for q in [q0, 1e7, q1] {
        let _ = writeln!(text, "{q:e},{:e}", c0 * q.powf(-2.0 * (1.0 + h)));
    }
    fs::write(&psd, text).unwrap();
    let j = json_of(&[psd.to_str().unwrap()]);
    let slope = j["rms_slope"].as_f64().unwrap();
    assert!((slope / 8.33 - 1.0).abs() < 0.01, "{slope}");
    assert!(j["warnings"].to_string().contains("rms slope 8.3"), "{j}");
}

#[test]
fn bad_traces_are_located_and_nothing_is_written() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.json");
    let plot = dir.path().join("psd.svg");
    let mut gap = "x,z\nmm,um\n".to_string();
    for j in 0..300 {
        let x = if j < 150 { j as f64 } else { j as f64 + 0.5 } * 1e-3;
        let _ = writeln!(gap, "{x},{}", (j as f64).sin());
    }
    let short = "x,z\nmm,um\n0,1\n0.001,2\n0.002,1\n";
    for (name, text, needle) in [
        ("gap.csv", gap.as_str(), "gap.csv:153:"),
        ("short.csv", short, "short.csv"),
    ] {
        let path = dir.path().join(name);
        fs::write(&path, text).unwrap();
        cargo_bin_cmd!("sealsim")
            .arg("surface")
            .arg(&path)
            .arg("-o")
            .arg(&out)
            .arg("--plot")
            .arg(&plot)
            .assert()
            .code(2)
            .stderr(predicate::str::contains(needle));
        assert!(!out.exists() && !plot.exists(), "{name}: nothing written");
    }
}

/// The shipped trace scenario with its `[surface]` replaced by `surface` (written next to a
/// copy of the traces directory).
fn trace_scenario(dir: &TempDir, surface: &str) -> std::path::PathBuf {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let text = fs::read_to_string(format!(
        "{manifest}/scenarios/oring-nbr-water-80c-trace.toml"
    ))
    .unwrap();
    let start = text.find("[surface]").unwrap();
    let end = text.find("[fluid]").unwrap();
    let text = format!("{}{surface}\n\n{}", &text[..start], &text[end..]);
    fs::create_dir_all(dir.path().join("traces")).unwrap();
    fs::copy(
        format!("{manifest}/scenarios/traces/ground-fine.csv"),
        dir.path().join("traces/ground-fine.csv"),
    )
    .unwrap();
    let path = dir.path().join("s.toml");
    fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_scenario_reads_its_face_from_a_line_trace() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let out = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(format!(
            "{manifest}/scenarios/oring-nbr-water-80c-trace.toml"
        ))
        .assert()
        .success();
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.contains("surface.profile: note: 1 trace(s): band") && stderr.contains("fitted H"),
        "{stderr}"
    );
    // the spectrum the contact sees is the traces' (its Hurst exponent is the fitted one)
    let j = json_of(&[&format!(
        "{manifest}/scenarios/oring-nbr-water-80c-trace.toml"
    )]);
    assert!(j["hurst_exponent"].is_null(), "a tabulated spectrum: {j}");
    let slope = j["rms_slope"].as_f64().unwrap();
    assert!(slope > 0.1 && slope < 0.5, "{slope}");
}

#[test]
fn trace_scenario_bad_input() {
    let dir = TempDir::new().unwrap();
    // a callout and a trace at once
    let path = trace_scenario(
        &dir,
        "[surface]\nprofile = \"traces/ground-fine.csv\"\nra = \"0.4 um\"",
    );
    cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(
            predicate::str::contains("s.toml:").and(predicate::str::contains(
                "surface.profile: profile and ra are mutually exclusive",
            )),
        );
    // a trace with a gap: the trace's line and the scenario's key
    let mut gap = "x,z\nmm,um\n".to_string();
    for j in 0..300 {
        let x = if j < 150 { j as f64 } else { j as f64 + 0.5 } * 1e-3;
        let _ = writeln!(gap, "{x},{}", (j as f64).sin());
    }
    fs::write(dir.path().join("traces/gap.csv"), gap).unwrap();
    let path = trace_scenario(&dir, "[surface]\nprofile = [\"traces/gap.csv\"]");
    let out = dir.path().join("out.csv");
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&path)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(2)
        .stderr(
            predicate::str::contains("gap.csv:153:").and(predicate::str::contains(
                "(line trace named by surface.profile at",
            )),
        );
    assert!(!out.exists());
}

#[test]
fn a_cutoff_shorter_than_the_sampling_is_refused() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.txt");
    // the shipped traces are sampled every 0.5 µm: a 4 µm cut-off spans 8 samples
    cargo_bin_cmd!("sealsim")
        .arg("surface")
        .arg(format!("{manifest}/scenarios/traces/ground-fine.csv"))
        .args(["--cutoff", "4um", "--short-cutoff", "1um", "-o"])
        .arg(&out)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "--cutoff: 0.004 mm is shorter than 10 samples",
        ));
    assert!(!out.exists());
}
