//! Verdicts an engineer can act on (docs/model.md §8.1–§8.2): every output states the seal's
//! state, lift-off is never "survives", no verdict comes from rounding, the set and cooled ring
//! fails at a shutdown, extrusion beyond the chart, compare of a gas with its permeation, and
//! the keys that state all this refuse bad values.

use crate::common::{rel, scenario_path};
use crate::support::{compare_csv, edited, sealsim, shipped};
use serde_json::Value;
use std::fs;
use std::path::{Path, PathBuf};
use tempfile::TempDir;

const YEAR: f64 = 365.25 * 86400.0;

/// The scission rate of the library's nbr-70 at `t` \[K\] (its `[material.ageing]`: 1.464e-9
/// 1/s at 23 °C, Ea 57.5 kJ/mol).
fn k_nbr(t: f64) -> f64 {
    1.464e-9 * (-(57.5e3 / 8.314_462_618) * (1.0 / t - 1.0 / 296.15)).exp()
}

/// One run's outputs.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
    json: Option<Value>,
    csv: Option<String>,
    html: Option<String>,
}

/// `sealsim run` of `text` (written as `s.toml` in `dir`) with the history, summary and report.
fn run_in(dir: &Path, text: &str, extra: &[&str]) -> Run {
    let scenario = dir.join("s.toml");
    fs::write(&scenario, text).unwrap();
    let (csv, json, html) = (dir.join("h.csv"), dir.join("s.json"), dir.join("r.html"));
    for p in [&csv, &json, &html] {
        let _ = fs::remove_file(p);
    }
    let out = sealsim()
        .current_dir(dir)
        .arg("run")
        .arg(&scenario)
        .args([
            "--verbose",
            "-o",
            "h.csv",
            "--summary",
            "s.json",
            "--report",
            "r.html",
        ])
        .args(extra)
        .output()
        .unwrap();
    Run {
        code: out.status.code(),
        stdout: String::from_utf8(out.stdout).unwrap(),
        stderr: String::from_utf8(out.stderr).unwrap(),
        json: fs::read_to_string(&json)
            .ok()
            .map(|t| serde_json::from_str(&t).unwrap()),
        csv: fs::read_to_string(&csv).ok(),
        html: fs::read_to_string(&html).ok(),
    }
}

fn run(text: &str) -> Run {
    let dir = TempDir::new().unwrap();
    run_in(dir.path(), text, &[])
}

/// The headline ring (`oring-nbr-water-80c.toml`) edited: `edits` are (line prefix, the line's
/// replacement; empty: deleted).
fn headline_with(edits: &[(&str, &str)]) -> String {
    edited(&shipped("oring-nbr-water-80c.toml"), edits)
}

fn time_to_failure(r: &Run) -> (String, f64) {
    let json = r.json.as_ref().unwrap();
    (
        json["failure_mode"].as_str().unwrap().to_owned(),
        json["time_to_failure_s"].as_f64().unwrap_or(f64::INFINITY),
    )
}

/// The verdict is the state wherever it is printed: the summary's `result`, the JSON's
/// `verdict`, `final_state` and `states`, the HTML verdict box; never "survives".
fn assert_open_everywhere(r: &Run, context: &str) {
    assert_eq!(r.code, Some(0), "{context}: {}", r.stderr);
    let result = r
        .stdout
        .lines()
        .find(|l| l.starts_with("result"))
        .unwrap_or("");
    assert!(
        result.contains("OPEN (lift-off)") || result.contains("by lift_off"),
        "{context}: {result}"
    );
    assert!(!r.stdout.contains("survives"), "{context}: {}", r.stdout);
    assert!(
        r.stdout
            .contains("state          OPEN (lift-off) from installation"),
        "{context}: {}",
        r.stdout
    );
    let json = r.json.as_ref().unwrap();
    assert_ne!(json["verdict"], "survives", "{context}");
    assert_eq!(json["final_state"], "lift_off", "{context}");
    assert_eq!(json["states"][0]["state"], "lift_off", "{context}");
    assert_eq!(json["states"][0]["from_s"], 0.0, "{context}");
    let html = r.html.as_ref().unwrap();
    let verdict = html
        .split("<div class=\"verdict ")
        .nth(1)
        .and_then(|v| v.split("</div>").next())
        .unwrap_or("");
    assert!(verdict.starts_with("fails\">"), "{context}: {verdict}");
    assert!(!verdict.contains("urvives"), "{context}: {verdict}");
    // every history row says so
    let csv = r.csv.as_ref().unwrap();
    assert!(
        csv.lines().skip(1).all(|l| l.contains(",lift_off,")),
        "{context}"
    );
}

#[test]
fn a_lifted_off_seal_is_open_in_every_output() {
    // repro A: the 100-bar FKM face seal not energised, lift-off waived: OPEN, not "survives"
    let text = shipped("oring-fkm-hydraulic-face-100bar.toml")
        .replace("lift_off = true", "lift_off = false")
        .replace(
            "loading = \"displacement\"",
            "loading = \"displacement\"\nenergisation_factor = 0",
        );
    let r = run(&text);
    assert_open_everywhere(&r, "FKM, k_e = 0, lift-off waived");
    assert_eq!(r.json.as_ref().unwrap()["verdict"], "open");
    assert!(
        r.stdout.contains("[failure] lift_off = false waives it"),
        "{}",
        r.stdout
    );
    // repro B: a flat NBR gasket at 0.3 MPa holding 5 bar of oil (lift-off on by default)
    let gasket = r#"[material]
library = "nbr-70"
[surface]
ra = "0.8 um"
[fluid]
library = "iso-vg-46"
pressure_difference = "5 bar"
[seal]
kind = "flat"
nominal_pressure = "0.3 MPa"
width = "10 mm"
length = "300 mm"
[failure]
max_leak_rate = "1 mL/h"
"#;
    let r = run(gasket);
    assert_open_everywhere(&r, "flat gasket");
    let json = r.json.as_ref().unwrap();
    assert_eq!(json["verdict"], "fails");
    assert_eq!(json["failure_mode"], "lift_off");
    assert_eq!(json["time_to_failure_s"], 0.0);
    // its leak is the lower bound at the threshold of lift-off, and said to be one
    assert_eq!(json["leaked_volume_is_lower_bound"], true);
    assert!(r.stdout.contains("≥ "), "{}", r.stdout);
}

#[test]
fn no_verdict_follows_the_rounding_of_the_pressure_difference() {
    // the headline ring with only lift-off left (the review's variants): the lift-off used to
    // come when the squeeze peak fell below ½ ulp of ΔP, at ln(p_sq/(ΔP 2⁻⁵³))/k
    let k80 = k_nbr(353.15);
    let p_sq = 1.306e6; // Pa, the squeeze peak of the reference row
    let rounding = |dp: f64| (p_sq / (dp * 2f64.powi(-53))).ln() / k80;
    let mut held = Vec::new();
    for (dp, text) in [
        (0.2e5, "0.2 bar"),
        (2e5, "2 bar"),
        (20e5, "20 bar"),
        (200e5, "200 bar"),
    ] {
        let base = headline_with(&[
            (
                "pressure_difference",
                &format!("pressure_difference = \"{text}\""),
            ),
            ("extrusion_gap", "extrusion_gap = \"0.005 mm\""),
            ("max_leak_rate", ""),
            ("max_leaked_volume", ""),
            ("min_retained_force", ""),
        ]);
        // with the shutdown check (the default): the set ring's interference at 23 °C decides,
        // whatever the service pressure
        let (mode, t) = time_to_failure(&run(&base));
        assert_eq!(mode, "lost_interference", "{text}");
        assert!((t / 5.71e7 - 1.0).abs() < 0.02, "{text}: {t}");
        // without it: held by the fluid pressure alone once p_sq < τ ΔP, never at the rounding
        let waived = base.replace(
            "lift_off = true",
            "lift_off = true\nlost_interference = false",
        );
        let r = run(&waived);
        let (mode, t) = time_to_failure(&r);
        assert_eq!(mode, "lift_off", "{text}");
        assert!(
            t < rounding(dp) - 10.0 * YEAR,
            "{text}: {t} vs {}",
            rounding(dp)
        );
        assert_eq!(r.json.as_ref().unwrap()["final_state"], "pressure_held");
        held.push(t);
    }
    // τ ΔP: a decade of ΔP costs ln 10/k, the physics of a threshold proportional to ΔP
    for w in held.windows(2) {
        let step = (w[0] - w[1]) * k80 / 10f64.ln();
        assert!((step - 1.0).abs() < 0.05, "{held:?}");
    }
}

#[test]
fn the_verdict_is_continuous_in_the_energisation_factor() {
    let mut times = Vec::new();
    for ke in ["0.999", "1.0", "1.001"] {
        for shutdown in [true, false] {
            let mut text = headline_with(&[
                (
                    "loading",
                    &format!("loading = \"displacement\"\nenergisation_factor = {ke}"),
                ),
                ("min_retained_force", ""),
            ]);
            if !shutdown {
                text = text.replace(
                    "lift_off = true",
                    "lift_off = true\nlost_interference = false",
                );
            }
            let (mode, t) = time_to_failure(&run(&text));
            times.push((ke, shutdown, mode, t));
        }
    }
    for shutdown in [true, false] {
        let same: Vec<_> = times.iter().filter(|x| x.1 == shutdown).collect();
        for x in &same {
            assert_eq!(x.2, same[0].2, "{times:?}");
            assert!((x.3 / same[0].3 - 1.0).abs() < 0.05, "{times:?}");
        }
    }
    // and a 0.1 % change of an input moves the time by about as much (not a jump)
    let base = headline_with(&[("min_retained_force", "")]);
    let (_, t0) = time_to_failure(&run(&base));
    for (key, from, to) in [
        (
            "groove_depth",
            "groove_depth = \"2.65 mm\"",
            "groove_depth = \"2.65265 mm\"",
        ),
        (
            "pressure_difference",
            "pressure_difference = \"2 bar\"",
            "pressure_difference = \"2.002 bar\"",
        ),
    ] {
        let (_, t) = time_to_failure(&run(&base.replace(from, to)));
        let moved = (t / t0 - 1.0).abs();
        assert!(moved < 0.02, "{key}: {t0} → {t} ({moved})");
    }
}

#[test]
fn a_set_ring_cooled_to_a_shutdown_loses_its_interference_when_hand_derived() {
    // the headline ring aged at 80 °C, checked at 23 °C: squeeze at T (docs/model.md §6),
    // ε(T) = 1 − (1 − ε0)(1 + α_h ΔT)/(1 + α_r ΔT) from 23 °C; the networks set s = ε(80)(1 −
    // e^{−kt}) (r = 1, constant squeeze); interference lost when (ε(23) − s) d ≤ h_rms
    let r = run(&headline_with(&[("min_retained_force", "")]));
    let json = r.json.as_ref().unwrap();
    let eps0 = json["gland"]["squeeze"].as_f64().unwrap();
    let (alpha_r, alpha_h) = (165e-6, 11.7e-6); // nbr-70, steel (the gland's default)
    let squeeze = |t: f64| {
        let dt = t - 296.15;
        1.0 - (1.0 - eps0) * (1.0 + alpha_h * dt) / (1.0 + alpha_r * dt)
    };
    let k80 = k_nbr(353.15);
    // Ra 0.4 µm read as Rq = √(π/2) Ra over the extended band; the cord ≈ 3.53 mm
    let h_rms = 0.4e-6 * (std::f64::consts::PI / 2.0).sqrt();
    let set_at_loss = squeeze(296.15) - h_rms / 3.53e-3;
    let by_hand = -(1.0 - set_at_loss / squeeze(353.15)).ln() / k80;
    let (mode, t) = time_to_failure(&r);
    assert_eq!(mode, "lost_interference");
    assert!(rel(t, by_hand) < 0.01, "{t} vs {by_hand} by hand");
    assert!(
        (json["shutdown"]["lost_s"].as_f64().unwrap() / t - 1.0).abs() < 1e-12,
        "{json}"
    );
    assert_eq!(json["shutdown"]["temperature_K"], 296.15);
    // the history's column: the set ring's squeeze at 23 °C falls from ε(23) to 0
    let csv = r.csv.as_ref().unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let col = header
        .iter()
        .position(|c| *c == "shutdown_squeeze")
        .unwrap();
    let first: f64 = csv
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(col)
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        rel(first, squeeze(296.15)) < 1e-3,
        "{first} vs {}",
        squeeze(296.15)
    );
}

#[test]
fn a_bolted_gasket_never_leaks_more_at_a_higher_load() {
    let out = sealsim()
        .arg("leak")
        .arg(scenario_path("helium-leak-test-gasket.toml"))
        .args(["--sweep", "0.01MPa..0.44MPa", "--points", "12"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let q = header
        .iter()
        .position(|c| *c == "throughput_Pa_m3_per_s")
        .unwrap();
    let state = header.iter().position(|c| *c == "state").unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert!(rows.iter().any(|r| r[state] == "lift_off"), "{text}");
    assert!(rows.iter().any(|r| r[state] != "lift_off"), "{text}");
    for w in rows.windows(2) {
        let (a, b): (f64, f64) = (w[0][q].parse().unwrap(), w[1][q].parse().unwrap());
        assert!(b <= a, "more load, more leak: {a} → {b}\n{text}");
    }
}

#[test]
fn extrusion_beyond_the_chart_needs_back_up_rings() {
    let high = shipped("oring-fkm-hydraulic-face-100bar.toml").replace(
        "pressure_difference = \"100 bar\"",
        "pressure_difference = \"1000 bar\"",
    );
    let r = run(&high);
    assert_eq!(time_to_failure(&r), ("extrusion".to_owned(), 0.0));
    // two back-up rings are rated to 40 MPa (ERIKS): 1000 bar still extrudes, and says why
    let backed = high.replace(
        "loading = \"displacement\"",
        "loading = \"displacement\"\nbackup_rings = 2",
    );
    let r = run(&backed);
    assert_eq!(time_to_failure(&r), ("extrusion".to_owned(), 0.0));
    assert!(
        r.stderr.contains("40 MPa back-up rings are rated for"),
        "{}",
        r.stderr
    );
    // at 300 bar they hold the ring with this 0.06 mm diametral clearance
    let r = run(&backed.replace("\"1000 bar\"", "\"300 bar\""));
    assert_ne!(time_to_failure(&r).0, "extrusion");
    // and without them 300 bar is beyond the chart: extrusion
    let r = run(&high.replace("\"1000 bar\"", "\"300 bar\""));
    assert_eq!(time_to_failure(&r), ("extrusion".to_owned(), 0.0));
}

#[test]
fn compare_of_a_gas_fails_the_compounds_run_fails() {
    let materials = ["fkm-75", "nbr-70", "epdm-70", "vmq-70"];
    let (_, header, rows) = compare_csv(
        &scenario_path("helium-leak-test-flange.toml"),
        &materials.join(","),
    );
    assert!(
        header
            .iter()
            .any(|c| c == "total_throughput_1day_Pa_m3_per_s"),
        "{header:?}"
    );
    let col = |name: &str| header.iter().position(|c| c == name).unwrap();
    let dir = TempDir::new().unwrap();
    for (cells, id) in rows.iter().zip(materials) {
        let variant = shipped("helium-leak-test-flange.toml")
            .replace("library = \"fkm-75\"", &format!("library = \"{id}\""));
        let r = run_in(dir.path(), &variant, &[]);
        let (mode, t) = time_to_failure(&r);
        assert_eq!(&cells[col("failure_mode")], mode.as_str(), "{id}");
        let compared: f64 = cells[col("time_to_failure_s")]
            .parse()
            .unwrap_or(f64::INFINITY);
        assert!(
            compared == t || rel(compared, t) < 1e-12,
            "{id}: {compared} vs {t}"
        );
        assert_eq!(mode, "leak_rate", "{id}: permeation fails the helium test");
    }
}

#[test]
fn fail_exit_code_reports_a_failed_or_open_seal() {
    let dir = TempDir::new().unwrap();
    let scenario = dir.path().join("s.toml");
    fs::write(&scenario, shipped("oring-nbr-water-80c.toml")).unwrap();
    let status = |args: &[&str]| {
        sealsim()
            .current_dir(dir.path())
            .arg("run")
            .arg(&scenario)
            .args(["--summary", "s.json"])
            .args(args)
            .output()
            .unwrap()
            .status
            .code()
    };
    assert_eq!(status(&[]), Some(0));
    assert_eq!(status(&["--fail-exit-code", "9"]), Some(9));
    assert!(
        dir.path().join("s.json").exists(),
        "written before the status"
    );
    // 0–2 and 126+ are taken: refused
    assert_eq!(status(&["--fail-exit-code", "2"]), Some(2));
    assert_eq!(status(&["--fail-exit-code", "200"]), Some(2));
    // a surviving seal exits 0 with it
    let survivor = shipped("oring-fkm-hydraulic-face-100bar.toml");
    fs::write(&scenario, survivor).unwrap();
    assert_eq!(status(&["--fail-exit-code", "9"]), Some(0));
}

#[test]
fn a_gap_below_a_molecule_is_sealed_and_keeps_its_figure() {
    // the review's EPDM ring: 2.62 mm cord, 30 mm, 20 % squeeze, 0.36 µm rms, 0.1 bar
    let text = r#"[material]
library = "epdm-70"
[surface]
rms_roughness = "0.36 um"
hurst_exponent = 0.8
q0 = "1e5 1/m"
q1 = "1e10 1/m"
[fluid]
library = "water"
pressure_difference = "0.1 bar"
[seal]
kind = "o-ring"
cross_section = "2.62 mm"
mean_diameter = "30 mm"
squeeze = 0.2
[failure]
max_leak_rate = "1e-12 m^3/s"
[simulation]
duration = "1 year"
"#;
    let r = run(text);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let json = r.json.as_ref().unwrap();
    let csv = r.csv.as_ref().unwrap();
    let first: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
    let u_c: f64 = first[8].parse().unwrap();
    assert!(
        u_c > 0.0 && u_c < 3.1e-10,
        "u_c = {u_c}: this case needs a sub-molecular gap"
    );
    assert_eq!(first[9], "0e0", "leak 0");
    assert_eq!(first[11], "sealed");
    assert_eq!(json["states"][0]["reason"], "critical_gap_below_a_molecule");
    assert_eq!(json["initial_leak_rate_m3_per_s"], 0.0);
    assert!(
        r.stdout.contains("sealed (critical gap below a molecule)"),
        "{}",
        r.stdout
    );
    assert!(!r.stdout.contains("leaking"), "{}", r.stdout);
}

#[test]
fn a_ring_fitted_warm_and_cooled_loses_force_one_fitted_cold_is_refused() {
    let cold = headline_with(&[
        ("temperature = \"80 C\"", "temperature = \"-50 C\""),
        ("min_retained_force", ""),
        // water freezes at -50 °C (refused since issue 42): a liquid given by its viscosity
        ("library = \"water\"", "viscosity = \"1 mPa*s\""),
    ]);
    // fitted at 23 °C, then the −50 °C environment: it cools over the cord's thermal time and
    // its glassy contraction opens it within minutes
    let warm = cold
        .replace(
            "loading = \"displacement\"",
            "loading = \"displacement\"\ninstallation_temperature = \"23 C\"",
        )
        // the run's own opening (the shutdown check and the cold limit fail it at once)
        .replace(
            "lift_off = true",
            "lift_off = true\nlost_interference = false\nlow_temperature = false",
        );
    let r = run(&warm);
    let json = r.json.as_ref().unwrap();
    assert_eq!(json["states"][0]["state"], "sealed");
    let (mode, t) = time_to_failure(&r);
    assert_eq!(mode, "lift_off");
    assert!(t > 1.0 && t < 600.0, "{t}");
    assert!(
        json["initial_sealing_force_N_per_m"].as_f64().unwrap() < 5e3,
        "rubbery force"
    );
    // stated as fitted at −50 °C: refused, the key named, nothing written
    let fitted_cold = cold.replace(
        "loading = \"displacement\"",
        "loading = \"displacement\"\ninstallation_temperature = \"-50 C\"",
    );
    let r = run(&fitted_cold);
    assert_eq!(r.code, Some(2));
    assert!(
        r.stderr.contains("s.toml:")
            && r.stderr.contains("seal.installation_temperature")
            && r.stderr.contains("T10"),
        "{}",
        r.stderr
    );
    assert!(r.json.is_none() && r.csv.is_none() && r.html.is_none());
    // no fitting temperature given: in a gland the ring is fitted at 23 °C, as stated above
    // (docs/model.md §5.2), not glassy at the environment's first temperature
    let r = run(&cold.replace(
        "lift_off = true",
        "lift_off = true\nlost_interference = false\nlow_temperature = false",
    ));
    assert_eq!(r.code, Some(0));
    assert!(!r.stderr.contains("taken as fitted"), "{}", r.stderr);
    assert_eq!(
        r.json.as_ref().unwrap()["initial_sealing_force_N_per_m"],
        run(&warm).json.as_ref().unwrap()["initial_sealing_force_N_per_m"]
    );
}

#[test]
fn validity_of_narrow_contacts_and_a_lay() {
    // an AS568-001 cord (1.02 mm) on a 0.8 mm cut-off: its contact is narrower than two waves
    let text = r#"[material]
library = "nbr-70"
[surface]
ra = "0.4 um"
[fluid]
library = "water"
pressure_difference = "1 bar"
[seal]
kind = "o-ring"
cross_section = "1.02 mm"
mean_diameter = "1.8 mm"
squeeze = 0.2
[failure]
max_leak_rate = "1e-12 m^3/s"
[simulation]
duration = "1 day"
"#;
    let r = run(text);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(r.stderr.contains("contact width × q0/2π"), "{}", r.stderr);
    // a spiral lay on a gas seal: a clear warning
    let gas =
        shipped("helium-leak-test-flange.toml").replace("[surface]", "[surface]\nlay = \"spiral\"");
    let r = run(&gas);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(
        r.stderr.contains("surface.lay: a spiral (turned) lay"),
        "{}",
        r.stderr
    );
    assert!(r.stderr.contains("on a gas seal"), "{}", r.stderr);
}

#[test]
fn bad_verdict_keys_exit_2_naming_file_line_and_key() {
    let cases: [(String, &str); 3] = [
        (
            shipped("oring-fkm-hydraulic-face-100bar.toml").replace(
                "loading = \"displacement\"",
                "loading = \"displacement\"\nbackup_rings = 3",
            ),
            "seal.backup_rings",
        ),
        (
            headline_with(&[(
                "lift_off",
                "lift_off = true\nshutdown_temperature = \"90 C\"",
            )]),
            "failure.shutdown_temperature",
        ),
        (
            shipped("oring-nbr-water-80c.toml")
                .replace("[surface]", "[surface]\nlay = \"knurled\""),
            "surface.lay",
        ),
    ];
    for (text, key) in cases {
        let r = run(&text);
        assert_eq!(r.code, Some(2), "{key}: {}", r.stderr);
        let line = r.stderr.lines().next().unwrap_or("");
        let prefix = format!("error: {}", PathBuf::from("s.toml").display());
        assert!(
            line.contains("s.toml:") && line.contains(&format!(": {key}: ")),
            "{key}: {line} ({prefix})"
        );
        assert!(
            r.json.is_none() && r.csv.is_none() && r.html.is_none(),
            "{key}"
        );
    }
    // the suggested shutdown temperature is one the program accepts
    let r = run(&headline_with(&[(
        "lift_off",
        "lift_off = true\nshutdown_temperature = \"80 C\"",
    )]));
    assert_eq!(r.code, Some(0), "{}", r.stderr);
}
