//! End-to-end tests of `sealsim ageing-fit`: a compression-set file from a known Ea gives it
//! back in the JSON with every field, and bad input exits with status 2, names the file and
//! line, and writes nothing.

use crate::support::{sealsim, sealsim_ok};
use predicates::prelude::*;
use std::fmt::Write;
use std::fs;
use std::path::PathBuf;
use tempfile::TempDir;

const R: f64 = 8.314_462_618;

/// CS = 1 − exp(−k t), k = 1e-6/s · exp(−Ea/R (1/T − 1/373.15 K)), Ea = 90 kJ/mol, at
/// 100–145 C; times in h, log-spaced at 4 per decade around each t* = ln 2/k.
fn data(temperatures: &[f64]) -> String {
    let mut text = "temperature,time,value\nC,h,%\n".to_string();
    for c in temperatures {
        let t = c + 273.15;
        let k = 1e-6 * (-90e3 / R * (1.0 / t - 1.0 / 373.15)).exp();
        let t_star = std::f64::consts::LN_2 / k;
        for j in -8..=8 {
            let time = t_star * 10f64.powf(f64::from(j) / 4.0);
            let _ = writeln!(
                text,
                "{c},{:e},{:e}",
                time / 3600.0,
                100.0 * (1.0 - (-k * time).exp())
            );
        }
    }
    text
}

fn write(dir: &TempDir, name: &str, text: &str) -> PathBuf {
    let path = dir.path().join(name);
    fs::write(&path, text).unwrap();
    path
}

#[test]
fn json_gives_ea_and_life() {
    let dir = TempDir::new().unwrap();
    let file = write(&dir, "cs.csv", &data(&[100.0, 115.0, 130.0, 145.0]));
    let out = dir.path().join("r.json");
    let toml = dir.path().join("ageing.toml");
    let svg = dir.path().join("a.svg");
    sealsim()
        .args(["ageing-fit", "--service-temperature", "60C", "--json", "-o"])
        .arg(&out)
        .arg("--write-material-ageing")
        .arg(&toml)
        .arg("--plot")
        .arg(&svg)
        .arg(&file)
        .assert()
        .success();
    let v: serde_json::Value = serde_json::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(v["kind"], "compression-set");
    assert_eq!(v["kind_inferred"], true);
    assert_eq!(v["criterion"], 0.5);
    let ea = v["activation_energy_J_per_mol"].as_f64().unwrap();
    assert!((ea / 90e3 - 1.0).abs() < 1e-6, "{ea}");
    let interval = v["activation_energy_interval_J_per_mol"]
        .as_array()
        .unwrap();
    assert_eq!(interval.len(), 2);
    // life at 60 C by hand: ln 2 / k(333.15 K)
    let k = 1e-6 * (-90e3 / R * (1.0 / 333.15 - 1.0 / 373.15)).exp();
    let life = v["life_at_service_s"].as_f64().unwrap();
    assert!(
        (life * k / std::f64::consts::LN_2 - 1.0).abs() < 1e-6,
        "{life}"
    );
    assert_eq!(v["life_interval_s"].as_array().unwrap().len(), 2);
    assert!((v["r_squared"].as_f64().unwrap() - 1.0).abs() < 1e-9);
    let times = v["times_to_criterion"].as_array().unwrap();
    assert_eq!(times.len(), 4);
    assert!((times[0]["temperature_K"].as_f64().unwrap() - 373.15).abs() < 1e-9);
    assert!(
        (times[0]["time_s"].as_f64().unwrap() * 1e-6 / std::f64::consts::LN_2 - 1.0).abs() < 1e-6
    );
    // the ageing table: k at the service temperature
    let doc: toml::Table = toml::from_str(&fs::read_to_string(&toml).unwrap()).unwrap();
    let a = doc["material"]["ageing"].as_table().unwrap();
    assert_eq!(a["crosslinking"].as_float(), Some(1.0));
    let rate: f64 = a["rate"]
        .as_str()
        .unwrap()
        .trim_end_matches(" 1/s")
        .parse()
        .unwrap();
    assert!((rate / k - 1.0).abs() < 1e-6, "{rate} vs {k}");
    assert!(fs::read_to_string(&svg).unwrap().starts_with("<svg"));
}

fn rejected(text: &str, extra: &[&str], message: &str) {
    let dir = TempDir::new().unwrap();
    let file = write(&dir, "bad.csv", text);
    let out = dir.path().join("r.json");
    let toml = dir.path().join("ageing.toml");
    sealsim()
        .args(["ageing-fit", "--json", "-o"])
        .arg(&out)
        .arg("--write-material-ageing")
        .arg(&toml)
        .args(extra)
        .arg(&file)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(message));
    assert!(!out.exists() && !toml.exists(), "nothing written");
}

#[test]
fn bad_input_exits_2_with_file_and_line() {
    rejected(
        &data(&[100.0, 130.0]),
        &[],
        "bad.csv:36: 2 ageing temperatures",
    );
    rejected(
        "temperature,time,value\nC,furlong,1\n100,1,0.1\n",
        &[],
        "bad.csv:2: time:",
    );
    rejected(
        "temperature,time,value\nPa,h,1\n100,1,0.1\n",
        &[],
        "bad.csv:2: temperature: unit",
    );
    // a retained-force series that rises (line 5 ends it)
    rejected(
        "temperature,time,value\nC,h,1\n100,1,0.9\n100,10,0.8\n110,1,0.8\n110,10,0.9\n120,1,0.9\n120,10,0.5\n",
        &["--kind", "retained-force"],
        "bad.csv:6: the series at 383.15 K rises",
    );
}

/// The lab-data tutorial's shipped ageing data (scenarios/lab-data/cs-ageing-nbr.csv) are made
/// from CS = 1 − exp(−k t), k = ln 2 / 1000 h at 100 °C, Ea = 95 kJ/mol, with ±1.5 % scatter
/// (its header): the fit recovers that law — the 95 % interval of Ea holds 95 kJ/mol, and each
/// time to 50 % is within 3 % of 1000 h · exp((Ea/R)(1/T − 1/373.15 K)).
#[test]
fn the_tutorial_ageing_data_give_back_the_law_they_were_made_from() {
    let path = crate::common::scenario_path("lab-data/cs-ageing-nbr.csv");
    let out = sealsim_ok(&[&"ageing-fit", &path, &"--json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let (ea, r) = (95e3, 8.314_462_618);
    let interval = &v["activation_energy_interval_J_per_mol"];
    let (lo, hi) = (interval[0].as_f64().unwrap(), interval[1].as_f64().unwrap());
    assert!(lo < ea && ea < hi, "Ea interval [{lo}, {hi}] misses {ea}");
    let times = v["times_to_criterion"].as_array().unwrap();
    assert_eq!(times.len(), 3);
    for point in times {
        let t = point["temperature_K"].as_f64().unwrap();
        let fitted = point["time_s"].as_f64().unwrap();
        let law = 1000.0 * 3600.0 * ((ea / r) * (1.0 / t - 1.0 / 373.15)).exp();
        assert!(
            (fitted / law - 1.0).abs() < 0.03,
            "at {t} K: {fitted} s against the law's {law} s"
        );
    }
}
