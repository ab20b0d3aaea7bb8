//! End-to-end tests of `sealsim fit-prony`: pyvisco-style and plain data files of both kinds
//! give a material TOML whose series reproduces the data, and every kind of bad input exits
//! with status 2, names the file and line, and never creates or touches the `-o` file.

use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use sealsim::material::{Prony, PronyTerm};
use sealsim::math::log_spaced;
use sealsim::units::{Dimension, parse_quantity};
use std::fmt::Write;
use std::fs;
use std::path::PathBuf;
use tempfile::TempDir;

/// 13 terms, τ = 1e-4 … 1e8 s, E∞ = 2 MPa (the example of tests/fit.rs).
fn truth() -> Prony {
    let terms: Vec<PronyTerm> = (-4..=8)
        .map(|k| PronyTerm {
            modulus: 1e6 * (3.5 + 2.5 * (1.3 * k as f64).sin()),
            tau: 10f64.powi(k),
        })
        .collect();
    Prony::new(2e6, &terms).unwrap()
}

/// Relaxation data, 60 points over 1e-4 … 1e8 s: pyvisco style in MPa, or plain SI.
fn relaxation_csv(pyvisco: bool) -> String {
    let p = truth();
    let mut text = if pyvisco {
        "t,E_relax\ns, MPa\n".to_string()
    } else {
        "# SI units\ntime,E\ns,Pa\n".to_string()
    };
    for t in log_spaced(1e-4, 1e8, 60) {
        let e = p.relaxation(t);
        let _ = if pyvisco {
            writeln!(text, "{t:e}, {:e}", e / 1e6)
        } else {
            writeln!(text, "{t:e},{e:e}")
        };
    }
    text
}

/// DMA data, 60 points over ω = 1e-7 … 1e3 rad/s: pyvisco style (f in Hz, MPa), or plain
/// SI with omega.
fn dma_csv(pyvisco: bool) -> String {
    let p = truth();
    let mut text = if pyvisco {
        "f, E_stor, E_loss\nHz, MPa, MPa\n".to_string()
    } else {
        "omega,storage,loss\nrad/s,Pa,Pa\n".to_string()
    };
    for w in log_spaced(1e-7, 1e3, 60) {
        let (s, l) = (p.storage(w), p.loss(w));
        let _ = if pyvisco {
            writeln!(
                text,
                "{:e},{:e},{:e}",
                w / std::f64::consts::TAU,
                s / 1e6,
                l / 1e6
            )
        } else {
            writeln!(text, "{w:e},{s:e},{l:e}")
        };
    }
    text
}

fn write(dir: &TempDir, name: &str, text: &str) -> PathBuf {
    let path = dir.path().join(name);
    fs::write(&path, text).unwrap();
    path
}

/// The Prony series of a material TOML text, read with the unit parser.
fn series_of(text: &str) -> Prony {
    let doc: toml::Table = toml::from_str(text).unwrap();
    let m = doc["material"].as_table().unwrap();
    let q = |v: &toml::Value, d| parse_quantity(v.as_str().unwrap(), d).unwrap();
    let terms: Vec<PronyTerm> = m["prony"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| PronyTerm {
            modulus: q(&t["modulus"], Dimension::PRESSURE),
            tau: q(&t["tau"], Dimension::TIME),
        })
        .collect();
    Prony::new(q(&m["long_term_modulus"], Dimension::PRESSURE), &terms).unwrap()
}

fn fit_ok(args: &[&str]) -> (String, String) {
    let out = cargo_bin_cmd!("sealsim")
        .arg("fit-prony")
        .args(args)
        .assert()
        .success();
    let o = out.get_output();
    (
        String::from_utf8(o.stdout.clone()).unwrap(),
        String::from_utf8(o.stderr.clone()).unwrap(),
    )
}

fn worst(fitted: &Prony, f: impl Fn(&Prony, f64) -> f64, xs: &[f64]) -> f64 {
    let p = truth();
    xs.iter()
        .map(|&x| (f(fitted, x) / f(&p, x) - 1.0).abs())
        .fold(0.0, f64::max)
}

#[test]
fn pyvisco_relaxation_file_gives_a_user_material() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "nbr-relax.csv", &relaxation_csv(true));
    let (stdout, stderr) = fit_ok(&[data.to_str().unwrap(), "--kind", "relaxation"]);
    let doc: toml::Table = toml::from_str(&stdout).unwrap();
    let m = doc["material"].as_table().unwrap();
    assert_eq!(m["name"].as_str(), Some("nbr-relax"));
    assert!(
        m.get("status").is_none(),
        "a fitted material is a user material"
    );
    assert_eq!(m["poisson_ratio"].as_float(), Some(0.5));
    let provenance = m["provenance"].as_table().unwrap();
    assert_eq!(
        provenance["poisson_ratio"].as_str(),
        Some("assumed: incompressible rubber; replace with a measured value")
    );
    let fitted = provenance["prony"].as_str().unwrap();
    let expected = format!(
        "fitted by sealsim fit-prony (NNLS, 3 terms per decade) to {}: 60 points, rms relative residual",
        data.display()
    );
    assert!(fitted.starts_with(&expected), "{fitted}");
    assert_eq!(provenance["long_term_modulus"].as_str(), Some(fitted));
    // the series reproduces the data (the grid holds the true τ: exact up to MPa rounding)
    let p = series_of(&stdout);
    assert!(worst(&p, Prony::relaxation, &log_spaced(1e-4, 1e8, 500)) < 1e-6);
    assert!(
        stderr.contains("60 points") && stderr.contains("rms relative residual"),
        "{stderr}"
    );
    assert!(!stderr.contains("warning"), "{stderr}");
}

#[test]
fn plain_relaxation_file_with_output_and_name() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "plain.csv", &relaxation_csv(false));
    let out = dir.path().join("material.toml");
    let (stdout, stderr) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "--terms-per-decade",
        "2",
        "--name",
        "NBR 70, fitted",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(stdout.is_empty(), "{stdout}");
    assert!(stderr.contains("rms relative residual"), "{stderr}");
    let text = fs::read_to_string(&out).unwrap();
    assert!(text.contains("name = \"NBR 70, fitted\"\n"), "{text}");
    assert!(text.contains("(NNLS, 2 terms per decade)"), "{text}");
    let p = series_of(&text);
    assert!(worst(&p, Prony::relaxation, &log_spaced(1e-4, 1e8, 500)) < 1e-6);
    // only the output file was added
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
}

#[test]
fn dma_files_of_both_styles() {
    let dir = TempDir::new().unwrap();
    let grid = log_spaced(1e-7, 1e3, 500);
    for (name, pyvisco) in [("dma-pyvisco.csv", true), ("dma-plain.csv", false)] {
        let data = write(&dir, name, &dma_csv(pyvisco));
        let (stdout, _) = fit_ok(&[data.to_str().unwrap(), "--kind", "dma"]);
        let p = series_of(&stdout);
        let (s, l) = (
            worst(&p, Prony::storage, &grid),
            worst(&p, Prony::loss, &grid),
        );
        assert!(s < 1e-6 && l < 1e-6, "{name}: E' {s:e}, E'' {l:e}");
    }
}

/// Runs `fit-prony` on `text` with `-o`, expects exit 2, `needle` in stderr, and no output.
fn rejected(text: &str, kind: &str, needle: &str) {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "data.csv", text);
    let out = dir.path().join("out.toml");
    cargo_bin_cmd!("sealsim")
        .arg("fit-prony")
        .arg(&data)
        .args(["--kind", kind, "-o"])
        .arg(&out)
        .assert()
        .code(2)
        .stdout("")
        .stderr(predicate::str::contains(format!(
            "{}{needle}",
            data.display()
        )));
    assert!(!out.exists(), "no output file on bad input");
    assert_eq!(
        fs::read_dir(dir.path()).unwrap().count(),
        1,
        "no temporary files"
    );
}

#[test]
fn text_cell_is_located() {
    rejected(
        "t,E_relax\ns,MPa\n1,5\n# note\n2,abc\n3,3\n",
        "relaxation",
        ":5: E_relax: not a number",
    );
}

#[test]
fn non_monotonic_time_is_located() {
    rejected(
        "t,E\ns,Pa\n1,5e6\n3,4e6\n2,3e6\n",
        "relaxation",
        ":5: t: must increase strictly",
    );
    rejected(
        "f,E_stor,E_loss\nHz,MPa,MPa\n1,5,1\n1,5,1\n2,5,1\n",
        "dma",
        ":4: f: must increase strictly",
    );
}

#[test]
fn wrong_column_count_is_located() {
    rejected(
        "t,E\ns,Pa\n1,5e6\n2,4e6,7\n3,3e6\n",
        "relaxation",
        ":4: expected 2 comma-separated columns",
    );
}

#[test]
fn non_positive_values_are_located() {
    rejected(
        "t,E\ns,Pa\n1,5e6\n2,0\n3,3e6\n",
        "relaxation",
        ":4: E: must be positive",
    );
    rejected(
        "f,E_stor,E_loss\nHz,MPa,MPa\n1,5,1\n2,5,-1\n3,5,1\n",
        "dma",
        ":4: E_loss: must be positive",
    );
    rejected(
        "t,E\ns,Pa\n0,5e6\n2,4e6\n3,3e6\n",
        "relaxation",
        ":3: t: must be positive",
    );
}

#[test]
fn too_few_points_are_located() {
    rejected(
        "t,E\ns,Pa\n1,5e6\n2,4e6\n",
        "relaxation",
        ":4: too few points: 2 data rows",
    );
}

#[test]
fn too_few_points_for_the_unknowns_name_both_numbers() {
    // plain NNLS, 4 points over 6 decades: 25 grid terms (3 per decade over 8 decades, plus
    // one) + E∞ = 26 unknowns
    rejected_with(
        "t,E\ns,Pa\n1,5e6\n1e2,4e6\n1e4,3e6\n1e6,2e6\n",
        &["--regularisation", "none"],
        ": --regularisation none: too few points for a fit without smoothing: 4 data points give \
         4 values for 26 unknowns (E∞ and 25 Prony terms); give more points, --terms-per-decade \
         0.25 or less, or leave out --regularisation none",
    );
}

#[test]
fn mixed_modulus_units_are_refused() {
    rejected(
        "f,E_stor,E_loss\nHz,MPa,Pa\n1,5,1\n2,5,1\n3,5,1\n",
        "dma",
        ":2: mixed units",
    );
}

#[test]
fn wrong_unit_dimension_is_located() {
    rejected(
        "t,E_relax\nMPa,MPa\n1,5\n2,4\n3,3\n",
        "relaxation",
        ":2: t: unit \"MPa\" is pressure, expected a time",
    );
    rejected(
        "f,E_stor,E_loss\nHz,MPa*s,MPa*s\n1,5,1\n2,5,1\n3,5,1\n",
        "dma",
        ":2: E_stor: unit",
    );
}

#[test]
fn kind_must_match_the_columns() {
    rejected(
        &dma_csv(true),
        "relaxation",
        ":1: --kind relaxation expects columns t,E_relax (or t,force or t,retained; optionally temperature), but the header has f,E_stor,E_loss, which is DMA data (use --kind dma)",
    );
    rejected(
        &relaxation_csv(true),
        "dma",
        ":1: --kind dma expects columns",
    );
}

#[test]
fn missing_header_and_unknown_columns_are_located() {
    rejected(
        "1,5e6\n2,4e6\n3,3e6\n",
        "relaxation",
        ":1: expected a header row",
    );
    rejected(
        "t,E,Set\n1,5e6,20\n",
        "relaxation",
        ":1: unknown column \"Set\"",
    );
}

#[test]
fn missing_data_file_is_named() {
    let dir = TempDir::new().unwrap();
    let missing = dir.path().join("nope.csv");
    cargo_bin_cmd!("sealsim")
        .arg("fit-prony")
        .arg(&missing)
        .args(["--kind", "dma"])
        .assert()
        .code(2)
        .stderr(predicate::str::contains(format!(
            "{}: cannot read the data file",
            missing.display()
        )));
}

#[test]
fn bad_flags_are_usage_errors() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "d.csv", &relaxation_csv(false));
    for args in [
        vec!["--kind", "relaxation", "--terms-per-decade", "5"],
        vec!["--kind", "relaxation", "--terms-per-decade", "0"],
        vec!["--kind", "relaxation", "--terms-per-decade", "0.2"],
        vec!["--kind", "relaxation", "--terms-per-decade", "NaN"],
        vec!["--kind", "relaxation", "--terms-per-decade", "two"],
        vec!["--kind", "creep"],
        vec![],
        vec!["--kind", "relaxation", "--name", ""],
    ] {
        cargo_bin_cmd!("sealsim")
            .arg("fit-prony")
            .arg(&data)
            .args(&args)
            .assert()
            .code(2);
    }
}

#[test]
fn existing_output_is_untouched_on_error() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "d.csv", "t,E\ns,Pa\n1,5e6\n2,abc\n3,3e6\n");
    let out = write(&dir, "keep.toml", "old\n");
    cargo_bin_cmd!("sealsim")
        .arg("fit-prony")
        .arg(&data)
        .args(["--kind", "relaxation", "-o"])
        .arg(&out)
        .assert()
        .code(2);
    assert_eq!(fs::read_to_string(&out).unwrap(), "old\n");
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 2);
}

#[test]
fn output_reads_back_as_a_user_material() {
    use sealsim::material::Status;
    use sealsim::scenario::material_from_str;

    let dir = TempDir::new().unwrap();
    let data = write(&dir, "dma.csv", &dma_csv(true));
    let (stdout, _) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "dma",
        "--terms-per-decade",
        "3",
    ]);
    let m = material_from_str(&stdout, &dir.path().join("fitted.toml"))
        .unwrap_or_else(|e| panic!("{e}\n{stdout}"));
    assert_eq!(m.status, Status::User);
    assert_eq!(m.name, "dma");
    assert_eq!(m.poisson_ratio, 0.5);
    assert_eq!(m.prony, series_of(&stdout), "the numbers read back exactly");
    assert!(
        m.provenance_of("prony")
            .unwrap()
            .contains("(NNLS, 3 terms per decade)")
    );
}

#[test]
fn a_fitted_material_runs_by_path_and_warns_beyond_its_data() {
    // fit-prony writes the data's window (1e-4 … 1e8 s) into the material; a scenario names the
    // file by path (relative to itself); a 30-year run at the reference temperature (no shift:
    // reduced time = time) goes 9.5× beyond the data, and says so once, with how far and when
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "data.csv", &relaxation_csv(false));
    let fitted = dir.path().join("fitted.toml");
    fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "-o",
        fitted.to_str().unwrap(),
    ]);
    let text = fs::read_to_string(&fitted).unwrap();
    assert!(
        text.contains("data_reduced_time = [\"1e-4 s\", \"1e8 s\"]"),
        "{text}"
    );
    let scenario = write(
        &dir,
        "s.toml",
        "name = \"fitted\"\n[material]\nfile = \"fitted.toml\"\n\
         [surface]\nrms_roughness = \"1 um\"\nhurst_exponent = 0.8\nq0 = \"1e4 1/m\"\nq1 = \"1e9 1/m\"\n\
         [fluid]\nviscosity = \"1 mPa*s\"\npressure_difference = \"0.1 bar\"\n\
         [seal]\nnominal_pressure = \"1 MPa\"\nwidth = \"1 mm\"\nlength = \"0.1 m\"\n",
    );
    let out = cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&scenario)
        .arg("--verbose") // the derivation and the warnings in full
        .arg("--summary")
        .arg(dir.path().join("s.json"))
        .assert()
        .success();
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    let stdout = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    assert!(stdout.contains("material       data [user]"), "{stdout}");
    let line = stderr
        .lines()
        .find(|l| l.contains("reduced time = "))
        .unwrap_or_else(|| panic!("no data-window warning in {stderr}"));
    assert!(
        line.contains("is above 1e8 s")
            && line.contains("worst at t = 9.467e8 s (30 years)")
            && line.contains("docs/model.md §9.13"),
        "{line}"
    );
    assert_eq!(stderr.matches("reduced time = ").count(), 1, "{stderr}");
    // a missing file is a located scenario error, nothing written
    let missing = write(
        &dir,
        "m.toml",
        &fs::read_to_string(&scenario)
            .unwrap()
            .replace("fitted.toml", "nope.toml"),
    );
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&missing)
        .arg("--summary")
        .arg(dir.path().join("m.json"))
        .assert()
        .code(2)
        .stderr(predicates::str::contains(
            "m.toml:3: material.file: no material file",
        ));
    assert!(!dir.path().join("m.json").exists());
}

// ---------------------------------------------------------------------------------------
// Compression stress relaxation (ISO 3384): forces and retained forces
// ---------------------------------------------------------------------------------------

/// CSR data of the true series: `value(E)` per time over 1e-4 … 1e8 s, header and units given.
fn csr_csv(header: &str, value: impl Fn(f64) -> f64) -> String {
    let p = truth();
    let mut text = format!("{header}\n");
    for t in log_spaced(1e-4, 1e8, 60) {
        let _ = writeln!(text, "{t:e},{:.12e}", value(p.relaxation(t)));
    }
    text
}

/// Lindley's squeeze function, written out here so that the test does not borrow the code's.
fn lindley(eps: f64) -> f64 {
    1.25 * eps.powf(1.5) + 50.0 * eps.powi(6)
}

#[test]
fn ring_forces_give_the_modulus_by_the_life_runs_force_law() {
    use std::f64::consts::PI;
    let dir = TempDir::new().unwrap();
    // an AS568-214 ring (cord 3.53 mm, ID 24.99 mm → mean diameter 28.52 mm) at 25 %
    let k = PI * 28.52e-3 * 3.53e-3 * lindley(0.25);
    let data = write(&dir, "csr.csv", &csr_csv("t,force\ns,N", |e| e * k));
    let (stdout, stderr) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "--test-piece",
        "ring",
        "--cross-section",
        "3.53 mm",
        "--mean-diameter",
        "28.52mm",
        "--squeeze",
        "25%",
        "--temperature",
        "23C",
    ]);
    let p = series_of(&stdout);
    let w = worst(&p, Prony::relaxation, &log_spaced(1e-4, 1e8, 500));
    assert!(w < 1e-5, "worst {w:e}");
    assert!(stderr.contains("ring test piece"), "{stderr}");
    let doc: toml::Table = toml::from_str(&stdout).unwrap();
    let m = doc["material"].as_table().unwrap();
    assert!(
        m["provenance"]["prony"]
            .as_str()
            .unwrap()
            .contains("moduli from the compression-stress-relaxation force by a ring test piece"),
        "{stdout}"
    );
    // the test temperature is the material's data temperature
    let window = m["data_temperature"].as_array().unwrap();
    assert_eq!(window[0].as_str(), window[1].as_str());
    let kelvin = parse_quantity(window[0].as_str().unwrap(), Dimension::TEMPERATURE).unwrap();
    assert!((kelvin - 296.15).abs() < 1e-9, "{window:?}");
}

#[test]
fn disc_forces_and_retained_forces_give_the_modulus() {
    use std::f64::consts::PI;
    let dir = TempDir::new().unwrap();
    // ISO 3384 type B disc, 13 mm across, at 25 %: F = E (πD²/4)(λ⁻² − λ)/3, λ = 0.75
    let lambda: f64 = 0.75;
    let k = 0.25 * PI * 0.013 * 0.013 * (lambda.powi(-2) - lambda) / 3.0;
    let data = write(
        &dir,
        "disc.csv",
        &csr_csv("t,F_N\nmin,kN", |e| e * k / 60e3),
    );
    // minutes and kilonewtons: the same numbers, other units (times 60, forces 1/1000)
    let text = fs::read_to_string(&data).unwrap();
    let mut scaled = String::from("t,F_N\nmin,kN\n");
    for line in text.lines().skip(2) {
        let (t, f) = line.split_once(',').unwrap();
        let t: f64 = t.parse().unwrap();
        let f: f64 = f.parse().unwrap();
        let _ = writeln!(scaled, "{:e},{:.12e}", t / 60.0, f * 60.0);
    }
    fs::write(&data, scaled).unwrap();
    let (stdout, stderr) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "--test-piece",
        "disc",
        "--diameter",
        "13mm",
        "--height",
        "6.3mm",
        "--squeeze",
        "0.25",
    ]);
    let w = worst(
        &series_of(&stdout),
        Prony::relaxation,
        &log_spaced(1e-4, 1e8, 500),
    );
    assert!(w < 1e-5, "worst {w:e}");
    assert!(stderr.contains("up to ×1.53"), "{stderr}");

    // retained force in per cent with the modulus at the first reading stated
    let p = truth();
    let e0 = p.relaxation(1e-4);
    let data = write(
        &dir,
        "retained.csv",
        &csr_csv("t,retained\ns,%", |e| 100.0 * e / e0),
    );
    let (stdout, _) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "--reference-modulus",
        &format!("{:.12e} Pa", e0),
    ]);
    let w = worst(
        &series_of(&stdout),
        Prony::relaxation,
        &log_spaced(1e-4, 1e8, 500),
    );
    assert!(w < 1e-5, "worst {w:e}");
}

#[test]
fn csr_bad_input_is_located_or_named() {
    // a retention that rises by 10 % of its first value: not a relaxation test
    rejected(
        "t,retained\nh,1\n0.5,1\n1,0.9\n2,0.85\n4,0.95\n8,0.8\n",
        "relaxation",
        ":6: retained: the force rises from 0.85 (line 5) to 0.95",
    );
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "f.csv", "t,force\nh,N\n1,100\n2,90\n3,85\n");
    let out = dir.path().join("out.toml");
    for (flags, needle) in [
        (vec![], "forces need a test piece"),
        (
            vec!["--test-piece", "ring", "--squeeze", "25%"],
            "--test-piece ring needs --cross-section",
        ),
        (
            vec![
                "--test-piece",
                "disc",
                "--diameter",
                "13mm",
                "--squeeze",
                "90%",
            ],
            "squeeze must be between 0 and 60 %",
        ),
        (vec!["--squeeze", "25%"], "--squeeze describes a test piece"),
        (
            vec!["--reference-modulus", "6MPa", "--initial-force", "100N"],
            "--initial-force is for retained-force data",
        ),
        (vec!["--reference-modulus", "6 m"], "--reference-modulus:"),
    ] {
        cargo_bin_cmd!("sealsim")
            .arg("fit-prony")
            .arg(&data)
            .args(["--kind", "relaxation", "-o"])
            .arg(&out)
            .args(&flags)
            .assert()
            .code(2)
            .stderr(predicate::str::contains(needle));
        assert!(!out.exists(), "{flags:?}: nothing written");
    }
}

// ---------------------------------------------------------------------------------------
// Master curves: data at several temperatures
// ---------------------------------------------------------------------------------------

/// Relaxation forces of a ring (as in the ring test above) at −10 … 50 °C, 30 points over
/// 1 s … 1e4 s each, from the rubber-like series of tests/model/tts.rs at 20 °C shifted by WLF
/// (C1 = 8.86, C2 = 101.6 K at 20 °C); each line `t,force,temperature`.
fn isotherm_csv(k: f64) -> String {
    let terms: Vec<PronyTerm> = log_spaced(1e-4, 1e12, 161)
        .into_iter()
        .map(|tau| {
            let x = tau.log10();
            PronyTerm {
                modulus: 1e8 * 10f64.powf(-0.45 * (x + 4.0)) * (1.0 + 0.3 * x.sin()),
                tau,
            }
        })
        .collect();
    let truth = Prony::new(1e4, &terms).unwrap();
    let mut text = "t,force,temperature\ns,N,C\n".to_string();
    for celsius in [-10.0, 5.0, 20.0, 35.0, 50.0] {
        let dt: f64 = celsius - 20.0;
        let log_a = -8.86 * dt / (101.6 + dt);
        for t in log_spaced(1.0, 1e4, 30) {
            let e = truth.relaxation(t / 10f64.powf(log_a));
            let _ = writeln!(text, "{t:e},{:.12e},{celsius}", e * k);
        }
    }
    text
}

#[test]
fn data_at_several_temperatures_give_a_master_curve_with_its_shift() {
    use sealsim::material::Shift;
    use sealsim::scenario::material_from_str;
    use std::f64::consts::PI;
    let dir = TempDir::new().unwrap();
    let k = PI * 28.52e-3 * 3.53e-3 * lindley(0.25);
    let data = write(&dir, "csr-5t.csv", &isotherm_csv(k));
    let master = dir.path().join("master.svg");
    let shift = dir.path().join("shift.svg");
    let out = dir.path().join("fkm.toml");
    let assert = cargo_bin_cmd!("sealsim")
        .env("SOURCE_DATE_EPOCH", "1795478400")
        .arg("fit-prony")
        .arg(&data)
        .args([
            "--kind",
            "relaxation",
            "--test-piece",
            "ring",
            "--cross-section",
            "3.53mm",
            "--mean-diameter",
            "28.52mm",
            "--squeeze",
            "25%",
            "--reference-temperature",
            "20C",
            "-o",
        ])
        .arg(&out)
        .arg("--plot-master")
        .arg(&master)
        .arg("--plot-shift")
        .arg(&shift)
        .assert()
        .success();
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.contains("master curve from 5 temperatures (150 points)"),
        "{stderr}"
    );
    let text = fs::read_to_string(&out).unwrap();
    let m = material_from_str(&text, &out).unwrap_or_else(|e| panic!("{e}\n{text}"));
    // the WLF law at 20 °C comes back (noise-free data: to a fraction of a per cent)
    let Shift::Wlf { reference, c1, c2 } = m.shift else {
        panic!("{:?}", m.shift)
    };
    assert!((reference - 293.15).abs() < 1e-9);
    assert!(
        (c1 / 8.86 - 1.0).abs() < 1e-3 && (c2 / 101.6 - 1.0).abs() < 1e-3,
        "{c1} {c2}"
    );
    assert_eq!(m.data_temperature, Some((263.15, 323.15)));
    let provenance = m.provenance_of("shift").unwrap();
    assert!(
        provenance.starts_with("fitted by sealsim fit-prony on 2026-11-24 to the shift factors of"),
        "{provenance}"
    );
    assert!(
        m.provenance_of("prony")
            .unwrap()
            .contains("time–temperature superposition of 5 isotherms")
    );
    for svg in [&master, &shift] {
        let s = fs::read_to_string(svg).unwrap();
        assert!(
            s.starts_with("<svg") && s.ends_with("</svg>\n"),
            "{}",
            svg.display()
        );
    }
    // Arrhenius instead: a different law, the same data
    let (stdout, _) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "--reference-modulus",
        "10MPa",
        "--shift",
        "arrhenius",
    ]);
    assert!(stdout.contains("kind = \"arrhenius\""), "{stdout}");
}

#[test]
fn a_master_curve_needs_two_temperatures() {
    // one temperature given to the superposition: located at the temperature column
    rejected_with(
        "t,E_relax,temperature\ns,MPa,C\n1,5,23\n2,4,23\n3,3,23\n",
        &["--shift", "wlf"],
        ":1:3: one temperature (296.15 K (23 °C))",
    );
    rejected_with(
        "t,E_relax\ns,MPa\n1,5\n2,4\n3,3\n",
        &["--reference-temperature", "23C"],
        ":1:1: no temperature column",
    );
}

fn rejected_with(text: &str, flags: &[&str], needle: &str) {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "data.csv", text);
    let out = dir.path().join("out.toml");
    cargo_bin_cmd!("sealsim")
        .arg("fit-prony")
        .arg(&data)
        .args(["--kind", "relaxation", "-o"])
        .arg(&out)
        .args(flags)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(format!(
            "{}{needle}",
            data.display()
        )));
    assert!(!out.exists(), "no output file on bad input");
}

// ---------------------------------------------------------------------------------------
// What labs report: few readings, and the properties a relaxation test does not measure
// ---------------------------------------------------------------------------------------

/// A three-term relaxation, τ off the fit grid: E∞ = 2.5 MPa, (0.8 MPa, 1000 s),
/// (1.2 MPa, 3e4 s), (1.5 MPa, 1e6 s).
fn three_terms() -> Prony {
    let terms =
        [(0.8e6, 1e3), (1.2e6, 3e4), (1.5e6, 1e6)].map(|(modulus, tau)| PronyTerm { modulus, tau });
    Prony::new(2.5e6, &terms).unwrap()
}

/// ISO 3384 readings of [`three_terms`] as force retained (%, relative to t = 0) at `hours`.
fn retained_csv(hours: &[f64]) -> String {
    let p = three_terms();
    let mut text = String::from("t,retained\nh,%\n");
    for h in hours {
        let _ = writeln!(
            text,
            "{h},{:.4}",
            100.0 * p.relaxation(h * 3600.0) / p.instantaneous()
        );
    }
    text
}

const SEVEN_HOURS: [f64; 7] = [1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0];

/// The AS568-214 ring of the CSR test (cord 3.53 mm, mean diameter 28.52 mm) at 25 %, with
/// 300 N at a retention of 1.
const RING: [&str; 10] = [
    "--test-piece",
    "ring",
    "--cross-section",
    "3.53mm",
    "--mean-diameter",
    "28.52mm",
    "--squeeze",
    "25%",
    "--initial-force",
    "300N",
];

/// The rms relative residual the summary on stderr reports.
fn rms_residual(stderr: &str) -> f64 {
    let (_, rest) = stderr.split_once("rms relative residual ").unwrap();
    rest.split(',').next().unwrap().parse().unwrap()
}

/// The main scenario (AS568 face gland, water at 80 °C) in `dir` with its `[material]` table
/// replaced by `material`, run; the output.
fn run_gland(dir: &TempDir, name: &str, material: &str) -> std::process::Output {
    let shipped = fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml"),
    )
    .unwrap();
    assert!(shipped.contains("[material]\nlibrary = \"nbr-70\"\n"));
    let text = shipped.replace("[material]\nlibrary = \"nbr-70\"\n", material);
    let scenario = write(dir, name, &text);
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&scenario)
        .arg("--verbose")
        .output()
        .unwrap()
}

#[test]
fn a_seven_point_csr_test_fitted_like_nbr_70_runs_in_a_gland_as_written() {
    use sealsim::scenario::library;
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "csr7.csv", &retained_csv(&SEVEN_HOURS));
    let my = dir.path().join("my.toml");
    let mut args = vec![data.to_str().unwrap(), "--kind", "relaxation"];
    args.extend(RING);
    args.extend(["--temperature", "70C", "--like", "nbr-70", "-o"]);
    args.push(my.to_str().unwrap());
    let (stdout, stderr) = fit_ok(&args);
    assert!(stdout.is_empty());
    // 7 points for 17 unknowns (16 τ at 3 per decade over 1e3 … 1e7 h·s + E∞)
    assert!(
        stderr.contains("7 points") && stderr.contains("of 16 grid terms"),
        "{stderr}"
    );
    let rms = rms_residual(&stderr);
    eprintln!("7-point CSR test: rms relative residual {rms:e}");
    assert!(rms < 3e-3, "{stderr}");
    assert!(
        stderr.contains(
            "copied from library compound nbr-70 (illustrative): poisson_ratio, \
             glass_transition, thermal_expansion, glassy_thermal_expansion, shift, ageing"
        ),
        "{stderr}"
    );
    assert!(
        stderr.contains("class = \"nbr\" copied: a gas run with this file takes nbr's permeation"),
        "{stderr}"
    );
    assert!(
        fs::read_to_string(&my)
            .unwrap()
            .contains("\nclass = \"nbr\"\n")
    );
    let text = fs::read_to_string(&my).unwrap();
    assert!(
        text.contains("copied from library compound nbr-70 (ILLUSTRATIVE data)"),
        "{text}"
    );
    // the series reproduces the retained force of the truth over the test (F ∝ E)
    let p = series_of(&text);
    let truth = three_terms();
    let e1 = p.relaxation(3600.0) / truth.relaxation(3600.0);
    let ratio = log_spaced(3600.0, 3.6e6, 200)
        .iter()
        .map(|&t| (p.relaxation(t) / truth.relaxation(t) / e1 - 1.0).abs())
        .fold(0.0, f64::max);
    assert!(ratio < 1e-2, "worst {ratio:e}");
    // each copied key: the library's value, and its provenance prefixed
    let doc: toml::Table = toml::from_str(&text).unwrap();
    let m = doc["material"].as_table().unwrap();
    let lib: toml::Table = toml::from_str(library::get("nbr-70").unwrap().text).unwrap();
    let lib = lib["material"].as_table().unwrap();
    for key in [
        "poisson_ratio",
        "glass_transition",
        "thermal_expansion",
        "glassy_thermal_expansion",
        "shift",
        "ageing",
    ] {
        let own = lib["provenance"][key].as_str().unwrap();
        let copied = m["provenance"][key].as_str().unwrap();
        assert!(
            copied.starts_with(&format!(
                "copied from library compound nbr-70 (sealsim fit-prony --like): {own}"
            )),
            "{key}: {copied}"
        );
    }
    assert_eq!(
        m["poisson_ratio"].as_float(),
        lib["poisson_ratio"].as_float()
    );
    let q = |v: &toml::Value, d| parse_quantity(v.as_str().unwrap(), d).unwrap();
    assert_eq!(
        q(&m["thermal_expansion"], Dimension::THERMAL_EXPANSION),
        q(&lib["thermal_expansion"], Dimension::THERMAL_EXPANSION)
    );
    assert_eq!(
        m["ageing"]["criterion"].as_str(),
        lib["ageing"]["criterion"].as_str()
    );
    // the shift moved to the test temperature, 70 °C: C2' = C2 + 47 K, C1' = C1 C2/C2'
    let shift = m["shift"].as_table().unwrap();
    let t_ref = q(&shift["reference_temperature"], Dimension::TEMPERATURE);
    assert!((t_ref - 343.15).abs() < 1e-9, "{shift:?}");
    let c2 = q(&shift["c2"], Dimension::TEMPERATURE);
    assert!((c2 - 155.6).abs() < 1e-9, "{shift:?}");
    let c1 = shift["c1"].as_float().unwrap();
    assert!((c1 - 8.28641 * 108.6 / 155.6).abs() < 1e-9, "{shift:?}");
    assert!(
        m["provenance"]["shift"]
            .as_str()
            .unwrap()
            .contains("moved to the test temperature")
    );

    // the file runs in the AS568 face gland of the main scenario, the scenario unchanged but
    // for the material
    let out = run_gland(&dir, "s.toml", "[material]\nfile = \"my.toml\"\n");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("result"), "{stdout}");
}

#[test]
fn a_seventeen_point_csr_test_fits_at_the_default_settings() {
    let dir = TempDir::new().unwrap();
    let mut hours: Vec<f64> = [30.0, 60.0, 180.0, 600.0, 1800.0]
        .iter()
        .map(|s| s / 3600.0)
        .collect();
    hours.extend([
        1.0, 2.0, 3.0, 6.0, 10.0, 20.0, 30.0, 60.0, 100.0, 200.0, 300.0, 1000.0,
    ]);
    assert_eq!(hours.len(), 17);
    let data = write(&dir, "csr17.csv", &retained_csv(&hours));
    let mut args = vec![data.to_str().unwrap(), "--kind", "relaxation"];
    args.extend(RING);
    let (stdout, stderr) = fit_ok(&args);
    // 17 points for 24 unknowns
    assert!(
        stderr.contains("17 points") && stderr.contains("of 23 grid terms"),
        "{stderr}"
    );
    let rms = rms_residual(&stderr);
    eprintln!("17-point CSR test: rms relative residual {rms:e}");
    assert!(rms < 3e-3, "{stderr}");
    assert!(stdout.contains("(NNLS, 3 terms per decade)"), "{stdout}");
    assert!(!stderr.contains("warning"), "{stderr}");
}

#[test]
fn fractional_terms_per_decade_are_accepted() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "plain.csv", &relaxation_csv(false));
    let (stdout, stderr) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "--terms-per-decade",
        "0.5",
    ]);
    // 1e-5 … 1e9 s every two decades
    assert!(stderr.contains("of 8 grid terms"), "{stderr}");
    assert!(stdout.contains("(NNLS, 0.5 terms per decade)"), "{stdout}");
    let (stdout, _) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "relaxation",
        "--terms-per-decade",
        "1",
    ]);
    assert!(stdout.contains("(NNLS, 1 term per decade)"), "{stdout}");
    // out of range: a usage error naming the flag and the range
    cargo_bin_cmd!("sealsim")
        .arg("fit-prony")
        .arg(&data)
        .args(["--kind", "relaxation", "--terms-per-decade", "0.1"])
        .assert()
        .code(2)
        .stderr(
            predicate::str::contains("--terms-per-decade")
                .and(predicate::str::contains("from 0.25 to 4 terms per decade")),
        );
}

#[test]
fn an_unknown_like_compound_names_the_flag_and_lists_the_library() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "csr7.csv", &retained_csv(&SEVEN_HOURS));
    let out = dir.path().join("my.toml");
    let mut cmd = cargo_bin_cmd!("sealsim");
    cmd.arg("fit-prony")
        .arg(&data)
        .args(["--kind", "relaxation"])
        .args(RING)
        .args(["--like", "nosuch", "-o"])
        .arg(&out);
    let assert = cmd.assert().code(2).stdout("");
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.contains("--like nosuch: unknown library material \"nosuch\"; the library has: "),
        "{stderr}"
    );
    for id in sealsim::scenario::library::ids() {
        assert!(stderr.contains(id), "{stderr}");
    }
    assert!(!out.exists());
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn too_few_points_without_smoothing_are_refused_with_fixes_that_work() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "csr7.csv", &retained_csv(&SEVEN_HOURS));
    let out = dir.path().join("my.toml");
    let mut base = vec![data.to_str().unwrap(), "--kind", "relaxation"];
    base.extend(RING);
    base.extend(["-o", out.to_str().unwrap()]);
    let mut plain = base.clone();
    plain.extend(["--regularisation", "none"]);
    let assert = cargo_bin_cmd!("sealsim")
        .arg("fit-prony")
        .args(&plain)
        .assert()
        .code(2)
        .stdout("");
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    // 7 points over 3 decades (5 with the grid's margins): at most (7 − 2)/5 = 1 per decade
    assert!(
        stderr.contains(&format!(
            "{}: --regularisation none: too few points for a fit without smoothing: 7 data \
             points give 7 values for 17 unknowns (E∞ and 16 Prony terms); give more points, \
             --terms-per-decade 1 or less, or leave out --regularisation none",
            data.display()
        )),
        "{stderr}"
    );
    assert!(!out.exists());
    // the suggested grid is accepted
    let mut coarser = plain.clone();
    coarser.extend(["--terms-per-decade", "1"]);
    let (_, stderr) = fit_ok(&coarser);
    assert!(
        stderr.contains("no smoothing") && stderr.contains("of 6 grid terms"),
        "{stderr}"
    );
    fs::remove_file(&out).unwrap();
    // and so is the default fit
    let (_, stderr) = fit_ok(&base);
    assert!(stderr.contains("weight by GCV"), "{stderr}");
}

#[test]
fn a_fitted_file_without_thermal_expansion_says_how_to_give_it_and_the_fixes_work() {
    let dir = TempDir::new().unwrap();
    let data = write(&dir, "csr7.csv", &retained_csv(&SEVEN_HOURS));
    let my = dir.path().join("my.toml");
    let mut args = vec![data.to_str().unwrap(), "--kind", "relaxation"];
    args.extend(RING);
    args.extend(["--temperature", "23C", "-o", my.to_str().unwrap()]);
    fit_ok(&args);
    // the groove-seated ring needs the rubber's CTE: the message says to put it into the file
    // (the scenario's `file` material takes no other keys), or to refit with --like
    let out = run_gland(&dir, "s.toml", "[material]\nfile = \"my.toml\"\n");
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let fix = format!(
        "gives no thermal_expansion; add `thermal_expansion` to [material] in the material file \
         {} itself (a scenario's `file` material takes no other keys), or write that file with \
         `sealsim fit-prony --like COMPOUND`",
        my.display()
    );
    assert!(stderr.contains(&fix), "{stderr}");
    // the key beside `file` in the scenario is what the message warns against: refused
    let out = run_gland(
        &dir,
        "beside.toml",
        "[material]\nfile = \"my.toml\"\nthermal_expansion = \"1.65e-4 1/K\"\n",
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("a file material takes no other keys"));
    // fix 1: the key in the material file itself. The scenario's [ageing] then needs its
    // constants (the fitted file has none): that message's fix, the constants in [ageing],
    // is given too
    let text = fs::read_to_string(&my).unwrap();
    let edited = text.replacen(
        "data_reduced_time",
        "thermal_expansion = \"1.65e-4 1/K\"\ndata_reduced_time",
        1,
    );
    fs::write(&my, edited).unwrap();
    let out = run_gland(&dir, "s.toml", "[material]\nfile = \"my.toml\"\n");
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("missing key `activation_energy` in [ageing]")
            && stderr.contains("give activation_energy, rate and reference_temperature"),
        "{stderr}"
    );
    let shipped = fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml"),
    )
    .unwrap();
    let with_constants = shipped
        .replace(
            "[material]\nlibrary = \"nbr-70\"\n",
            "[material]\nfile = \"my.toml\"\n",
        )
        .replace(
            "\n[ageing]",
            "\n[ageing]\nactivation_energy = \"57.5 kJ/mol\"\nrate = \"1.464e-9 1/s\"\n\
             reference_temperature = \"23 C\"\n#",
        );
    let scenario = write(&dir, "aged.toml", &with_constants);
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&scenario)
        .assert()
        .success();
    // fix 2: refit with --like
    fs::remove_file(&my).unwrap();
    args.extend(["--like", "nbr-70"]);
    fit_ok(&args);
    let out = run_gland(&dir, "s.toml", "[material]\nfile = \"my.toml\"\n");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn an_inline_material_without_thermal_expansion_is_told_to_add_it_and_that_works() {
    let dir = TempDir::new().unwrap();
    let inline = "[material]\nname = \"inline\"\npoisson_ratio = 0.5\nyoungs_modulus = \"6 MPa\"\n";
    let shipped = fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml"),
    )
    .unwrap();
    // without the compound's ageing constants, [ageing] needs its own: drop it here
    let cut = shipped.find("\n[ageing]").unwrap();
    let base = shipped[..cut].replace("[material]\nlibrary = \"nbr-70\"\n", inline);
    let scenario = write(&dir, "inline.toml", &base);
    let assert = cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&scenario)
        .assert()
        .code(2);
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.contains("gives no thermal_expansion; add `thermal_expansion` to [material]"),
        "{stderr}"
    );
    let fixed = base.replace(
        inline,
        &format!("{inline}thermal_expansion = \"1.65e-4 1/K\"\n"),
    );
    let scenario = write(&dir, "inline.toml", &fixed);
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&scenario)
        .assert()
        .success();
}

/// pyvisco-style DMA data (206 points, 1e-12 … 1e14 Hz) of a broad rubber spectrum (E∞ =
/// 80 MPa, storage plateau 81.5 MPa) whose E″ carries a low-frequency tail E′ does not
/// (`tail` Pa at the lowest frequency, falling as 1/(1 + √(f/1e-10 Hz))): the Kramers–Kronig
/// inconsistency of pyvisco's `freq_user_master.csv` (issue 40). Returns the text and the
/// plateau \[Pa\].
fn dma_with_tail(tail: f64) -> (String, f64) {
    let terms: Vec<PronyTerm> = log_spaced(1e-15, 1e14, 291)
        .into_iter()
        .map(|tau| {
            let k = tau.log10();
            PronyTerm {
                modulus: 4e6 * 10f64.powf(-0.15 * k) * (1.0 + 0.3 * k.sin()),
                tau,
            }
        })
        .collect();
    let p = Prony::new(80e6, &terms).unwrap();
    let mut text = "f, E_stor, E_loss\nHz, MPa, MPa\n".to_string();
    for f in log_spaced(1e-12, 1e14, 206) {
        let w = std::f64::consts::TAU * f;
        let loss = p.loss(w) + tail / (1.0 + (f / 1e-10).sqrt());
        let _ = writeln!(text, "{f:e},{:e},{:e}", p.storage(w) / 1e6, loss / 1e6);
    }
    (text, p.storage(std::f64::consts::TAU * 1e-12))
}

#[test]
fn dma_kramers_kronig_warning_advice_changes_the_fit() {
    let dir = TempDir::new().unwrap();
    let (text, plateau) = dma_with_tail(3e6);
    let data = write(&dir, "tail.csv", &text);
    let (stdout, stderr) = fit_ok(&[data.to_str().unwrap(), "--kind", "dma"]);
    assert!(
        stderr.contains("E″ disagrees with E′ (Kramers–Kronig)")
            && stderr.contains("at f = 1e-12–")
            && stderr.contains("--honour storage"),
        "{stderr}"
    );
    let default = series_of(&stdout).long_term();
    // the advice, followed
    let (stdout, stderr) = fit_ok(&[
        data.to_str().unwrap(),
        "--kind",
        "dma",
        "--honour",
        "storage",
    ]);
    assert!(stderr.contains("--honour storage:"), "{stderr}");
    let honoured = series_of(&stdout).long_term();
    eprintln!("E∞: default {default:e}, --honour storage {honoured:e}, plateau {plateau:e}");
    assert!(default < 0.9 * plateau, "default E∞ {default:e}");
    assert!(
        (honoured / plateau - 1.0).abs() <= 0.05,
        "honoured E∞ {honoured:e}"
    );
    let doc: toml::Table = toml::from_str(&stdout).unwrap();
    let provenance = doc["material"]["provenance"]["long_term_modulus"]
        .as_str()
        .unwrap();
    assert!(provenance.contains("Kramers–Kronig check"), "{provenance}");

    // consistent data: the check says so, and no advice
    let (text, _) = dma_with_tail(0.0);
    let data = write(&dir, "clean.csv", &text);
    let (_, stderr) = fit_ok(&[data.to_str().unwrap(), "--kind", "dma"]);
    assert!(
        stderr.contains("Kramers–Kronig check: E″ agrees") && !stderr.contains("warning"),
        "{stderr}"
    );
}
