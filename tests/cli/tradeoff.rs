//! End-to-end tests of the fidelity ladder on the command line: `sealsim tradeoff` (the
//! measured speed/accuracy table) and every level through `sealsim leak --fidelity`.

use crate::common::scenario_path;
use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use std::collections::HashMap;
use std::fs;
use tempfile::TempDir;

/// The CSV as (header → cell) maps, with no NaN or infinity anywhere.
fn parse(text: &str) -> Vec<HashMap<String, String>> {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let header: Vec<String> = reader
        .headers()
        .unwrap()
        .iter()
        .map(str::to_owned)
        .collect();
    reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            assert!(
                r.iter().all(|c| !c.contains("NaN") && !c.contains("inf")),
                "{r:?}"
            );
            header
                .iter()
                .cloned()
                .zip(r.iter().map(str::to_owned))
                .collect()
        })
        .collect()
}

fn number(row: &HashMap<String, String>, key: &str) -> f64 {
    row[key]
        .parse()
        .unwrap_or_else(|_| panic!("{key}: {:?}", row[key]))
}

#[test]
fn tradeoff_measures_every_level_and_the_table_converges() {
    let dir = TempDir::new().unwrap();
    let (csv_path, svg_path) = (dir.path().join("t.csv"), dir.path().join("t.svg"));
    let out = cargo_bin_cmd!("sealsim")
        .arg("tradeoff")
        .arg(scenario_path("persson-yang-2008.toml"))
        .args(["--band", "8", "-o"])
        .arg(&csv_path)
        .arg("--plot")
        .arg(&svg_path)
        .assert()
        .success();
    let stdout = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    assert!(stdout.starts_with("| section | level |"), "{stdout}");
    let rows = parse(&fs::read_to_string(&csv_path).unwrap());
    assert!(fs::read_to_string(&svg_path).unwrap().contains("<svg"));

    let find = |section: &str, level: &str, setting: &str| {
        rows.iter()
            .find(|r| r["section"] == section && r["level"] == level && r["setting"] == setting)
            .unwrap_or_else(|| panic!("no row {section}/{level}/{setting}"))
    };
    // every level appears
    for level in [
        "rule-of-thumb",
        "critical-junction",
        "exact",
        "effective-medium",
        "numerical",
    ] {
        assert!(rows.iter().any(|r| r["level"] == level), "{level}");
    }
    // the full-spectrum reference has zero error; the table converges as it is refined
    let reference = find(
        "full-spectrum",
        "exact",
        "quadrature ×4, time grid ×4 (reference)",
    );
    assert_eq!(number(reference, "static_error"), 0.0);
    let table_error = |ppd: &str| {
        number(
            find(
                "full-spectrum",
                "critical-junction",
                &format!("table {ppd} pts/decade"),
            ),
            "static_error",
        )
    };
    let errors = [
        table_error("3"),
        table_error("6"),
        table_error("12"),
        table_error("24"),
    ];
    // (at a single pressure the interpolation error need not fall monotonically: measured
    // 2.4e-2, 7.5e-6, 1.2e-5, 2.1e-6 on this scenario)
    assert!(
        errors[3] < 0.01 * errors[0] && errors[1..].iter().all(|&e| e < 1e-3),
        "{errors:?}"
    );
    // the rule of thumb is a different model: a visible, finite difference
    let rot = number(
        find("full-spectrum", "rule-of-thumb", "closed form"),
        "static_error",
    );
    assert!(rot > 1e-3 && rot.is_finite());
    // timings are positive; the band-limited numerical reference has zero error by definition
    for r in &rows {
        assert!(number(r, "static_seconds_s") > 0.0);
    }
    let numerical: Vec<_> = rows.iter().filter(|r| r["level"] == "numerical").collect();
    assert_eq!(number(numerical.last().unwrap(), "static_error"), 0.0);
    assert!(
        numerical
            .iter()
            .all(|r| !r["leak_rate_std_m3_per_s"].is_empty())
    );
}

#[test]
fn tradeoff_rejects_a_bad_band_and_writes_nothing() {
    let dir = TempDir::new().unwrap();
    let csv_path = dir.path().join("t.csv");
    cargo_bin_cmd!("sealsim")
        .arg("tradeoff")
        .arg(scenario_path("persson-yang-2008.toml"))
        .args(["--band", "1", "-o"])
        .arg(&csv_path)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "the band must be a number from 4 to 512",
        ));
    assert!(!csv_path.exists());
}

fn leak(level: &str) -> (String, String) {
    let out = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(scenario_path("persson-yang-2008.toml"))
        .args([
            "--fidelity",
            level,
            "--pressures",
            "0.1MPa,0.2MPa",
            "--verbose",
        ])
        .assert()
        .success();
    let o = out.get_output();
    (
        String::from_utf8(o.stdout.clone()).unwrap(),
        String::from_utf8(o.stderr.clone()).unwrap(),
    )
}

#[test]
fn every_level_answers_through_leak_and_the_numerical_one_is_reproducible() {
    let mut rates = HashMap::new();
    for level in [
        "rule-of-thumb",
        "critical-junction",
        "exact",
        "effective-medium",
        "numerical",
    ] {
        let (stdout, stderr) = leak(level);
        let rows = parse(&stdout);
        assert_eq!(rows.len(), 2, "{level}");
        let q: Vec<f64> = rows
            .iter()
            .map(|r| number(r, "leak_rate_m3_per_s"))
            .collect();
        assert!(q.iter().all(|&q| q > 0.0), "{level}: {q:?}");
        assert!(
            q[1] < q[0],
            "{level}: leak rate must fall with pressure: {q:?}"
        );
        rates.insert(level, q[1]);
        if level == "numerical" {
            // the paper's spectrum spans q1/q0 = 7.8e5: the level says it saw only a band
            assert!(stderr.contains("q1/q0 = 780000 is above 32"), "{stderr}");
            // same seed, same bits
            assert_eq!(leak(level).0, stdout);
        }
    }
    // the two critical-junction paths agree to the table's tolerance
    assert!((rates["critical-junction"] / rates["exact"] - 1.0).abs() < 3e-3);
}

#[test]
fn numerical_settings_are_validated_with_file_line_and_key() {
    let dir = TempDir::new().unwrap();
    let text = fs::read_to_string(scenario_path("persson-yang-2008.toml")).unwrap();
    for (block, needle) in [
        (
            "[numerical]\nrealisations = 2.5\n",
            "numerical.realisations: must be a whole number",
        ),
        ("[numerical]\nband = 1000\n", "numerical.band: must"),
        (
            "[numerical]\npixels_per_wavelength = 1\n",
            "numerical.pixels_per_wavelength: must",
        ),
        ("[numerical]\nseeds = 3\n", "seeds"),
    ] {
        let path = dir.path().join("s.toml");
        fs::write(&path, format!("{text}\n{block}")).unwrap();
        let line = text.lines().count() + 3;
        let out = cargo_bin_cmd!("sealsim")
            .arg("leak")
            .arg(&path)
            .assert()
            .code(2)
            .stdout(predicate::str::is_empty());
        let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
        assert!(stderr.contains(needle), "{stderr}");
        assert!(
            stderr.contains(&format!("s.toml:{line}:")),
            "{line}: {stderr}"
        );
    }
    // a valid block changes the numerical level's answer (another seed, other surfaces)
    let path = dir.path().join("ok.toml");
    fs::write(
        &path,
        format!("{text}\n[numerical]\nrealisations = 2\nseed = 99\npixels_per_wavelength = 4\n"),
    )
    .unwrap();
    cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(&path)
        .args(["--fidelity", "numerical"])
        .assert()
        .success()
        .stdout(predicate::str::contains(",leaking"));
}
