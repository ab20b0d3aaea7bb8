//! Units as engineers write them in scenario files, and the one ambiguity that is refused: a
//! temperature without its unit.

use crate::support::sealsim;
use std::fs;
use tempfile::TempDir;

const ORING: &str = r#"name = "units"
[material]
library = "nbr-70"
[surface]
rms_roughness = "2 um"
hurst_exponent = 0.8
q0 = "1e4 1/m"
q1 = "1e8 1/m"
[fluid]
viscosity = "1 mPa*s"
pressure_difference = "14.5 psig"
[seal]
kind = "o-ring"
cross_section = "0.139 in"
mean_diameter = "50 mm"
squeeze = "25 %"
[environment]
temperature = "100 C"
[simulation]
duration = "2 years"
"#;

#[test]
fn inches_percent_gauge_pressure_and_plural_times_run() {
    let dir = TempDir::new().unwrap();
    fs::write(dir.path().join("s.toml"), ORING).unwrap();
    let out = sealsim()
        .current_dir(dir.path())
        .args(["run", "s.toml", "--verbose", "--summary", "s.json"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("O-ring d = 3.531 mm"), "{text}");
    assert!(text.contains("squeeze 25 %"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(dir.path().join("s.json")).unwrap()).unwrap();
    assert_eq!(json["duration_s"], 2.0 * 365.25 * 86_400.0);
}

#[test]
fn a_bare_temperature_is_refused_with_its_place() {
    let dir = TempDir::new().unwrap();
    let text = ORING.replace("temperature = \"100 C\"", "temperature = 100");
    fs::write(dir.path().join("s.toml"), text).unwrap();
    let out = sealsim()
        .current_dir(dir.path())
        .args(["run", "s.toml", "-o", "h.csv", "--summary", "s.json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.starts_with("error: s.toml:18: environment.temperature: a temperature needs its unit"),
        "{err}"
    );
    assert!(err.contains("\"100 C\" or \"100 K\""), "{err}");
    assert!(!dir.path().join("h.csv").exists() && !dir.path().join("s.json").exists());
}
