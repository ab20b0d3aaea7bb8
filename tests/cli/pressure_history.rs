//! Pressure histories (docs/model.md §8.4; issue 41 item 6): the history CSV's `pressure`
//! column, the daily pressure cycle and the proof before service drive the energisation, the
//! lift-off, the leak, the extrusion and a gas's permeation at each step; the steps break on the
//! pressure's knots; bad pressure columns exit 2 at their line with the fix.

use crate::support::{edited, run_in, run_text, sealsim, shipped};
use serde_json::Value;
use std::fs;
use tempfile::TempDir;

/// (failure mode, time to failure \[s\]; ∞ when it survives).
fn failure(json: &Value) -> (String, f64) {
    (
        json["failure_mode"].as_str().unwrap_or("none").to_owned(),
        json["time_to_failure_s"].as_f64().unwrap_or(f64::INFINITY),
    )
}

/// Runs `text` as `s.toml` beside the CSV files `files` (name, text); the summary JSON.
fn run_with(text: &str, files: &[(&str, &str)], args: &[&str]) -> Value {
    let dir = TempDir::new().unwrap();
    for (name, body) in files {
        fs::write(dir.path().join(name), body).unwrap();
    }
    run_in(dir.path(), text, args).0
}

/// The cold night of `scenarios/cold-night-nbr.toml` (two warm days at 25 °C, cooled 30–34 h to
/// −30 °C, held to 42 h, rewarmed by 46 h) with the ring unenergised (k_e = 0: the squeeze alone
/// holds ΔP, Green & English's criterion, §6.3) at 5 bar, the run's own states deciding: the
/// hypothetical shutdown check, the cold limit and the leak criterion are off.
fn cold_night(history: &str) -> String {
    edited(
        &shipped("cold-night-nbr.toml"),
        &[
            ("pressure_difference", "pressure_difference = \"5 bar\""),
            (
                "installation_temperature",
                "installation_temperature = \"25 C\"\nenergisation_factor = 0",
            ),
            ("history", &format!("history = \"{history}\"")),
            (
                "max_leak_rate",
                "lost_interference = false\nlow_temperature = false",
            ),
        ],
    )
}

/// The night's CSV with the pressure column `rows` of (hour, °C, bar).
fn night_csv(rows: &[(f64, f64, f64)]) -> String {
    let mut out = String::from("time,temperature,pressure\nh,C,bar\n");
    for (t, c, p) in rows {
        out += &format!("{t},{c},{p}\n");
    }
    out
}

#[test]
fn a_depressurised_cold_night_opens_nothing_until_the_pressure_returns_onto_the_cold_ring() {
    // Physics (§3.6, §6.3, §8.1, §8.4): an unenergised ring is open when the fluid pressure
    // reaches its squeeze's contact pressure. Cooled, the ring contracts and that contact pressure
    // falls: at a constant 5 bar it opens within minutes of the cool-down (30.1 h). With the plant
    // depressurised through the night (0 bar from 30 h to 47 h) nothing can push the cold ring
    // open — the night itself no longer fails it; it fails only later, warm, when its squeeze
    // has relaxed below 5 bar (≈ 51 h). A restart while the ring is still cold (the pressure back
    // at 38.0–38.1 h, at −30 °C) finds the contracted ring and opens it at once: the failure is
    // located on the restart ramp, not on the output grid.
    let constant = night_csv(&[
        (0.0, 25.0, 5.0),
        (30.0, 25.0, 5.0),
        (34.0, -30.0, 5.0),
        (42.0, -30.0, 5.0),
        (46.0, 25.0, 5.0),
        (120.0, 25.0, 5.0),
    ]);
    let shut_down = night_csv(&[
        (0.0, 25.0, 5.0),
        (29.0, 25.0, 5.0),
        (30.0, 25.0, 0.0),
        (34.0, -30.0, 0.0),
        (42.0, -30.0, 0.0),
        (46.0, 25.0, 0.0),
        (47.0, 25.0, 5.0),
        (120.0, 25.0, 5.0),
    ]);
    let cold_restart = night_csv(&[
        (0.0, 25.0, 5.0),
        (29.0, 25.0, 5.0),
        (30.0, 25.0, 0.0),
        (34.0, -30.0, 0.0),
        (38.0, -30.0, 0.0),
        (38.1, -30.0, 5.0),
        (42.0, -30.0, 5.0),
        (46.0, 25.0, 5.0),
        (120.0, 25.0, 5.0),
    ]);
    let life = |csv: &str, ppd: &str| {
        let text = cold_night("p.csv").replace(
            "points_per_decade = 40",
            &format!("points_per_decade = {ppd}"),
        );
        failure(&run_with(&text, &[("p.csv", csv)], &[]))
    };
    let hour = 3600.0;
    let (mode, t_constant) = life(&constant, "40");
    assert_eq!(mode, "lift_off");
    assert!(
        (30.0 * hour..31.0 * hour).contains(&t_constant),
        "{t_constant}"
    );
    let (mode, t_shut) = life(&shut_down, "40");
    assert_eq!(mode, "lift_off");
    assert!(
        t_shut > 47.0 * hour,
        "the depressurised night opened it: {t_shut}"
    );
    let (mode, t_restart) = life(&cold_restart, "40");
    assert_eq!(mode, "lift_off");
    assert!(
        (38.0 * hour..=38.1 * hour).contains(&t_restart),
        "not on the cold restart: {t_restart}"
    );
    assert!(t_constant < t_restart && t_restart < t_shut);
    // the restart is located on the pressure's knots, not the output grid
    let (_, t_fine) = life(&cold_restart, "160");
    assert!(
        (t_fine / t_restart - 1.0).abs() < 1e-9,
        "{t_restart} vs {t_fine}"
    );
}

#[test]
fn a_constant_pressure_history_is_the_run_without_one_bit_for_bit() {
    // a liquid (ΔP, 2 bar) and a gas (its absolute inlet pressure: 100 bar over the outlet's
    // 1 atm = 101325 Pa, in pascals so that the difference is exactly the service's)
    for (name, pressure) in [
        ("oring-nbr-water-80c.toml", None),
        ("hydrogen-line-100bar.toml", Some("10101325")),
    ] {
        let base = shipped(name);
        let dp = base
            .lines()
            .find_map(|l| l.strip_prefix("pressure_difference = \""))
            .and_then(|l| l.split(' ').next())
            .unwrap()
            .to_owned();
        let (p, unit) = pressure.map_or((dp, "bar"), |p| (p.to_owned(), "Pa"));
        let history = format!("time,pressure\nday,{unit}\n0,{p}\n1000,{p}\n");
        let with = base.replace("[environment]\n", "[environment]\nhistory = \"p.csv\"\n");
        assert_ne!(with, base);
        let dir = TempDir::new().unwrap();
        fs::write(dir.path().join("p.csv"), &history).unwrap();
        let out = |text: &str, tag: &str| {
            let (json, stdout) = run_in(dir.path(), text, &["-o", &format!("{tag}.csv")]);
            let csv = fs::read_to_string(dir.path().join(format!("{tag}.csv"))).unwrap();
            (json, stdout, csv)
        };
        let (j0, s0, c0) = out(&base, "a");
        let (j1, s1, c1) = out(&with, "b");
        assert_eq!(c0, c1, "{name}: history CSV");
        assert_eq!(j0["leaked_volume_m3"], j1["leaked_volume_m3"], "{name}");
        assert_eq!(j0["time_to_failure_s"], j1["time_to_failure_s"], "{name}");
        assert_eq!(j0["failure_mode"], j1["failure_mode"], "{name}");
        let result = |s: &str| {
            s.lines()
                .find(|l| l.starts_with("result"))
                .map(str::to_owned)
        };
        assert_eq!(result(&s0), result(&s1), "{name}");
    }
}

/// The spring-loaded face seal (force loading) with the relaxed asperity modulus and no ageing:
/// a leak rate that depends on ΔP alone, constant in time at a constant ΔP.
fn steady_face_seal(history: Option<&str>, ppd: u32) -> String {
    let mut text = edited(
        &shipped("spring-loaded-face-seal.toml"),
        &[
            ("asperity_modulus", "asperity_modulus = \"relaxed\""),
            ("duration", "duration = \"10 day\""),
            ("max_leak_rate", ""),
        ],
    );
    text += &format!("points_per_decade = {ppd}\n\n[ageing]\nenabled = false\n");
    if let Some(h) = history {
        text = text.replace(
            "[environment]\n",
            &format!("[environment]\nhistory = \"{h}\"\n"),
        );
    }
    text
}

#[test]
fn the_leaked_volume_over_a_pressure_step_is_the_integral_of_the_two_rates() {
    // 0.5 bar for two days, down to 0.2 bar over an hour, 0.2 bar to day 10: the leak rate is
    // constant at each pressure (force loading, a fixed modulus, no ageing, constant T), so the
    // volume is Q1·48 h + Q2·191 h plus the hour of the ramp, bounded by its two rates
    let rate = |dp: &str| {
        let text = steady_face_seal(None, 20).replace(
            "pressure_difference = \"0.5 bar\"",
            &format!("pressure_difference = \"{dp}\""),
        );
        let json = run_with(&text, &[], &[]);
        let (a, b) = (
            json["initial_leak_rate_m3_per_s"].as_f64().unwrap(),
            json["final_leak_rate_m3_per_s"].as_f64().unwrap(),
        );
        assert!((a / b - 1.0).abs() < 1e-9, "not steady: {a} {b}");
        a
    };
    let (q1, q2) = (rate("0.5 bar"), rate("0.2 bar"));
    assert!(q2 < 0.9 * q1, "{q1} {q2}");
    let csv = "time,pressure\nh,bar\n0,0.5\n48,0.5\n49,0.2\n240,0.2\n";
    let volume = |ppd: u32| {
        run_with(
            &steady_face_seal(Some("p.csv"), ppd),
            &[("p.csv", csv)],
            &[],
        )["leaked_volume_m3"]
            .as_f64()
            .unwrap()
    };
    let hour = 3600.0;
    let steady = q1 * 48.0 * hour + q2 * 191.0 * hour;
    let (lo, hi) = (steady + q2 * hour, steady + q1 * hour);
    let v = volume(20);
    assert!(
        v >= lo * (1.0 - 1e-3) && v <= hi * (1.0 + 1e-3),
        "{v} outside [{lo}, {hi}]"
    );
    // and it does not move with the output grid (the steps are the pressure's knots)
    let fine = volume(80);
    assert!((fine / v - 1.0).abs() < 1e-9, "{v} vs {fine}");
}

#[test]
fn a_proof_at_one_and_a_half_times_the_service_extrudes_at_installation() {
    // FKM 75 with a 0.06 mm diametral clearance and no back-up ring: 200 bar (2900 psi) is
    // within the extrusion chart, its 1.5× proof (300 bar, 4350 psi) is beyond the chart's
    // 3000 psi, where a bare ring extrudes (ERIKS, docs/model.md §6.3)
    let service = shipped("oring-fkm-hydraulic-face-100bar.toml").replace(
        "pressure_difference = \"100 bar\"",
        "pressure_difference = \"200 bar\"",
    );
    let (mode, _) = failure(&run_with(&service, &[], &[]));
    assert_ne!(mode, "extrusion");
    let proof = service.replace(
        "[environment]\n",
        "[environment]\nproof_pressure = \"300 bar\"\nproof_duration = \"10 min\"\n",
    );
    assert_ne!(proof, service);
    let (mode, t) = failure(&run_with(&proof, &[], &[]));
    assert_eq!((mode.as_str(), t), ("extrusion", 0.0));
    // a proof at the service pressure changes nothing
    let same = service.replace(
        "[environment]\n",
        "[environment]\nproof_pressure = \"200 bar\"\nproof_duration = \"10 min\"\n",
    );
    assert_eq!(failure(&run_with(&same, &[], &[])).0, mode_of(&service));
}

fn mode_of(text: &str) -> String {
    failure(&run_with(text, &[], &[])).0
}

/// `sealsim run` on `text` beside `p.csv` = `csv`: (exit status, stderr).
fn refused(text: &str, csv: &str) -> (Option<i32>, String) {
    let dir = TempDir::new().unwrap();
    fs::write(dir.path().join("s.toml"), text).unwrap();
    fs::write(dir.path().join("p.csv"), csv).unwrap();
    let out = sealsim()
        .current_dir(dir.path())
        .args(["run", "s.toml"])
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn bad_pressure_columns_and_keys_exit_2_at_their_line_with_the_fix() {
    let liquid = shipped("oring-nbr-water-80c.toml")
        .replace("temperature = \"80 C\"", "history = \"p.csv\"");
    // a pressure column without its unit
    let (code, err) = refused(&liquid, "time,temperature,pressure\nh,C\n0,80,2\n");
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("p.csv:2:"), "{err}");
    assert!(err.contains("the pressure column has no unit"), "{err}");
    assert!(err.contains("h,C,bar"), "{err}");
    // no units row at all
    let (code, err) = refused(&liquid, "time,pressure\n0,2\n");
    assert_eq!(code, Some(2));
    assert!(
        err.contains("p.csv:2:") && err.contains("no units row"),
        "{err}"
    );
    // a unit that is not a pressure
    let (code, err) = refused(&liquid, "time,pressure\nh,C\n0,2\n");
    assert_eq!(code, Some(2));
    assert!(err.contains("is not a pressure unit"), "{err}");
    // a negative ΔP for a liquid, at its line
    let (code, err) = refused(&liquid, "time,pressure\nh,bar\n0,2\n5,-1\n");
    assert_eq!(code, Some(2));
    assert!(
        err.contains("p.csv:4:") && err.contains("negative pressure difference"),
        "{err}"
    );
    // a gas: a negative absolute inlet pressure (a gauge reading?) and one below the outlet
    let gas = shipped("hydrogen-line-100bar.toml").replace(
        "temperature = \"23 C\"",
        "temperature = \"23 C\"\nhistory = \"p.csv\"",
    );
    let (code, err) = refused(
        &gas,
        "time,pressure\nh,bar\n0,101\n# gauge by mistake\n3,-0.5\n",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("p.csv:5:"), "{err}");
    assert!(err.contains("negative absolute pressure"), "{err}");
    assert!(err.contains("plus the atmosphere"), "{err}");
    let (code, err) = refused(&gas, "time,pressure\nh,bar\n0,0.5\n");
    assert_eq!(code, Some(2));
    assert!(err.contains("below the gas's outlet pressure"), "{err}");
    // the proof's two keys go together
    let (code, _, err, _, _) = run_text(&liquid.replace(
        "history = \"p.csv\"",
        "temperature = \"80 C\"\nproof_pressure = \"3 bar\"",
    ));
    assert_eq!(code, Some(2));
    assert!(
        err.contains("environment.proof_pressure") && err.contains("proof_duration"),
        "{err}"
    );
    // the restart's pressure is bounded by the history's highest, not the service's
    let minimum = liquid
        .replace(
            "history = \"p.csv\"",
            "temperature = \"80 C\"\ndaily_pressure = \"0 bar\"",
        )
        .replace(
            "lift_off = true",
            "lift_off = true\nminimum_pressure_difference = \"3 bar\"",
        );
    let (code, _, err, _, _) = run_text(&minimum);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("failure.minimum_pressure_difference"), "{err}");
}

#[test]
fn a_nightly_depressurisation_lowers_the_leaked_volume_by_the_hours_without_pressure() {
    // the leaking face seal above at 0.5 bar, depressurised 21:00–09:00 every day: half the
    // time without a flow (plus the two one-minute ramps), so about half the volume
    let base = steady_face_seal(None, 20);
    let full = run_with(&base, &[], &[])["leaked_volume_m3"]
        .as_f64()
        .unwrap();
    let nightly = base.replace(
        "[environment]\n",
        "[environment]\ndaily_pressure = \"0 bar\"\n",
    );
    let cycled = run_with(&nightly, &[], &[])["leaked_volume_m3"]
        .as_f64()
        .unwrap();
    let ratio = cycled / full;
    assert!(
        (0.45..=0.55).contains(&ratio),
        "{cycled} / {full} = {ratio}"
    );
}
