//! The public scenario API: shipped scenarios load into SI model types; a `psd_file` is
//! resolved against the scenario's directory and can be restricted to a band.

use crate::common::scenario_path;
use sealsim::scenario::{Scenario, ScenarioError};
use std::fs;
use std::path::Path;

#[test]
fn paper_scenario_loads_in_si_units() {
    let s = Scenario::load(&scenario_path("persson-yang-2008.toml")).unwrap();
    assert_eq!(s.name, "Persson & Yang 2008, section 3");
    let p = &s.problem;
    assert_eq!(p.material.effective_modulus(), 1e7 / 0.75);
    assert!((p.spectrum.rms_roughness() / 2e-6 - 1.0).abs() < 1e-12);
    assert_eq!(
        (p.seal.nominal_pressure, p.seal.width, p.seal.length),
        (2e5, 1e-3, 1e-3)
    );
    assert_eq!(
        (p.fluid.viscosity, p.fluid.pressure_difference),
        (1e-3, 1e4)
    );
}

#[test]
fn psd_example_is_the_self_affine_law_it_tabulates() {
    let s = Scenario::load(&scenario_path("psd-example.toml")).unwrap();
    let sp = &s.problem.spectrum;
    assert!((sp.q0() / 1e4 - 1.0).abs() < 1e-12);
    assert!((sp.q1() / 1e9 - 1.0).abs() < 1e-3);
    // h_rms = 2 um up to the 4-digit rounding of the table
    assert!(
        (sp.rms_roughness() / 2e-6 - 1.0).abs() < 1e-3,
        "{}",
        sp.rms_roughness()
    );
    // flat below the roll-off, C ~ q^-3.6 above it
    assert!((sp.c(2e4) / sp.c(9e4) - 1.0).abs() < 1e-3);
    assert!((sp.c(1e6) / sp.c(1e7) / 10f64.powf(3.6) - 1.0).abs() < 1e-3);
}

#[test]
fn psd_band_can_be_restricted_and_path_is_relative_to_the_scenario() {
    let dir = tempfile::tempdir().unwrap();
    let sub = dir.path().join("data");
    fs::create_dir(&sub).unwrap();
    fs::copy(scenario_path("psd-example.csv"), sub.join("psd.csv")).unwrap();
    let text = fs::read_to_string(scenario_path("psd-example.toml"))
        .unwrap()
        .replace("\"psd-example.csv\"", "\"data/psd.csv\"")
        .replace("# q0 = \"2e4 1/m\"", "q0 = \"2e4 1/m\"")
        .replace("# q1 = \"5e8 1/m\"", "q1 = \"5e8 1/m\"");
    let path = dir.path().join("restricted.toml");
    fs::write(&path, text).unwrap();
    let sp = Scenario::load(&path).unwrap().problem.spectrum;
    assert!((sp.q0() / 2e4 - 1.0).abs() < 1e-12);
    assert!((sp.q1() / 5e8 - 1.0).abs() < 1e-12);
}

#[test]
fn errors_point_at_the_file_to_fix() {
    let text = fs::read_to_string(scenario_path("psd-example.toml")).unwrap();
    let err = Scenario::from_str(&text, Path::new("/nowhere/s.toml")).unwrap_err();
    assert!(
        matches!(err, ScenarioError::PsdRead { line: 10, .. }),
        "{err}"
    );
    assert_eq!(err.file(), Path::new("/nowhere/s.toml"));
    let err = Scenario::load(Path::new("/nowhere/s.toml")).unwrap_err();
    assert!(matches!(err, ScenarioError::Read { .. }), "{err}");
}
