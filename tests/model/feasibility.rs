//! Gland feasibility through the library (docs/model.md §6.2): every shipped gland scenario
//! still validates, and the new user's impossible piston ring is refused at its key with the
//! nearest size (worked by hand: groove diameter 25.4 − 2 × 2.9 = 19.6 mm under the -214's ID
//! of 0.984 in = 24.9936 mm; -210, ID 0.734 in = 18.6436 mm, stretched 19.6/18.6436 − 1 = 5.1 %).

use sealsim::scenario::{Scenario, ScenarioError};
use std::fs;
use std::path::{Path, PathBuf};

/// Every `*.toml` under `dir` (not the studies, whose files name a base).
fn scenario_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            scenario_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "toml")
            && !path.to_string_lossy().ends_with(".study.toml")
        {
            out.push(path);
        }
    }
}

#[test]
fn every_shipped_gland_scenario_validates() {
    let mut files = Vec::new();
    scenario_files(&crate::common::scenarios_dir(), &mut files);
    let mut glands = 0;
    for path in files {
        let text = fs::read_to_string(&path).unwrap();
        if !text.lines().any(|l| l.trim_start().starts_with("gland =")) {
            continue;
        }
        glands += 1;
        let scenario = Scenario::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for w in &scenario.warnings {
            assert!(
                !w.contains("compressed circumferentially") && !w.contains("wrong wall"),
                "{}: {w}",
                path.display()
            );
        }
    }
    // the shipped gland scenarios, templates and tutorials (21 when this was written)
    assert!(glands >= 20, "{glands}");
}

#[test]
fn an_impossible_piston_ring_is_refused_at_its_key_with_the_nearest_size() {
    let text = r#"name = "piston"
[material]
library = "nbr-70"
[surface]
rms_roughness = "0.8 um"
hurst_exponent = 0.7
q0 = "3e5 1/m"
q1 = "1e10 1/m"
[fluid]
viscosity = "1 mPa*s"
pressure_difference = "2 bar"
[seal]
kind = "o-ring"
gland = "piston"
size = "AS568-214"
bore_diameter = "25.4 mm"
groove_depth = "2.9 mm"
groove_width = "5.6 mm"
diametral_clearance = "0.05 mm"
"#;
    match Scenario::from_str(text, Path::new("dir/p.toml")) {
        Err(ScenarioError::Invalid {
            line, key, message, ..
        }) => {
            assert_eq!(
                (line, key.as_deref()),
                (Some(16), Some("seal.bore_diameter"))
            );
            assert!(
                message.contains("circumferential compression 21.6 %")
                    && message.contains("AS568-210 (ID 18.64 mm, OD 25.7 mm: stretch 5.1 %)"),
                "{message}"
            );
        }
        other => panic!("not refused: {other:?}"),
    }
}
