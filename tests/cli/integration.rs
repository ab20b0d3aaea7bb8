//! The verdict depends on the physics and the named tolerance, not on the output grid
//! (docs/model.md §10.1): volumes, states, extremes and failure times come from the internal
//! steps with their error control; `points_per_decade` only samples the history.

use crate::common::scenario_path;
use crate::support::run_in;
use serde_json::Value;
use std::fs;
use std::path::Path;
use tempfile::TempDir;

/// The cold night of the physics review's N1: 25 °C, a 4 h ramp to −40 °C, 8 h at −40 °C, back.
const NIGHT: &str = "time,temperature\nh,C\n0,25\n30,25\n34,-40\n42,-40\n46,25\n120,25\n";

/// The review's N1 scenario: a waived lift-off and a 2 mL leaked-volume limit.
fn n1(points_per_decade: f64, extra: &str) -> String {
    format!(
        "name = \"N1: leaked volume through one cold night\"\n\
         [material]\nlibrary = \"nbr-70\"\n\
         [surface]\nra = \"0.8 um\"\n\
         [fluid]\nviscosity = \"1 mPa*s\"\npressure_difference = \"2 bar\"\n\
         [seal]\nkind = \"o-ring\"\ngland = \"face\"\nsize = \"AS568-225\"\n\
         groove_depth = \"3.16 mm\"\ngroove_width = \"4.8 mm\"\n\
         groove_outer_diameter = \"54.3 mm\"\nextrusion_gap = \"0.02 mm\"\n\
         installation_temperature = \"25 C\"\n\
         [environment]\nhistory = \"night.csv\"\n\
         [failure]\nmax_leaked_volume = \"2 mL\"\nlift_off = false\n\
         lost_interference = false\nlow_temperature = false\n\
         [simulation]\nduration = \"5 day\"\npoints_per_decade = {points_per_decade}\n{extra}"
    )
}

/// `sealsim run` of `text` in `dir` (beside the night's history): its summary JSON.
fn summary(dir: &Path, text: &str, args: &[&str]) -> Value {
    fs::write(dir.join("night.csv"), NIGHT).unwrap();
    run_in(dir, text, args).0
}

/// The JSON's states: (state, reason, from \[s\]).
fn states(json: &Value) -> Vec<(String, String, f64)> {
    json["states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            (
                s["state"].as_str().unwrap().to_owned(),
                s["reason"].as_str().unwrap_or("").to_owned(),
                s["from_s"].as_f64().unwrap(),
            )
        })
        .collect()
}

/// The review's N1: at 5–10 points per decade the seal "survived", at 20 it read "OPEN", from
/// 40 it failed by the volume, which ran from 0.9 to 9.97 mL with the grid. Now every grid gives
/// the same verdict, states, extremes and volume (bit for bit: the grid only samples).
#[test]
fn the_output_grid_does_not_move_the_verdict_or_the_volume() {
    let dir = TempDir::new().unwrap();
    let reference = summary(dir.path(), &n1(20.0, ""), &[]);
    assert_eq!(reference["verdict"], "fails", "{reference}");
    assert_eq!(reference["failure_mode"], "leaked_volume");
    let volume = reference["leaked_volume_m3"].as_f64().unwrap();
    assert!(volume > 2e-6, "{volume}");
    for ppd in [5.0, 10.0, 40.0, 80.0, 160.0] {
        let json = summary(dir.path(), &n1(ppd, ""), &[]);
        for key in [
            "verdict",
            "verdict_text",
            "failure_mode",
            "time_to_failure_s",
            "final_state",
            "maximum_leak_rate_m3_per_s",
            "maximum_leak_rate_time_s",
            "minimum_sealing_force_N_per_m",
            "leaked_volume_is_lower_bound",
        ] {
            assert_eq!(
                json[key], reference[key],
                "{key} at {ppd} points per decade"
            );
        }
        assert_eq!(states(&json), states(&reference), "{ppd}");
        let v = json["leaked_volume_m3"].as_f64().unwrap();
        assert!((v / volume - 1.0).abs() < 0.01, "{v} vs {volume} at {ppd}");
    }
    // the lift-off inside the cold hold is a state of its own, located in time
    let lifted = states(&reference)
        .into_iter()
        .find(|(s, _, _)| s == "lift_off")
        .expect("the seal lifts off in the night");
    assert!(
        lifted.2 > 30.0 * 3600.0 && lifted.2 < 35.0 * 3600.0,
        "{lifted:?}"
    );
}

/// The error control converges: the leaked volume at the default tolerance (1e-3) and at 1e-2
/// are within a few times their tolerance of the one at 1e-4, and the verdict is the same.
#[test]
fn the_leaked_volume_converges_with_the_tolerance() {
    let dir = TempDir::new().unwrap();
    let tight = summary(dir.path(), &n1(20.0, "tolerance = 1e-4\n"), &[]);
    let converged = tight["leaked_volume_m3"].as_f64().unwrap();
    for (tolerance, bound) in [(1e-2, 3e-2), (1e-3, 3e-3)] {
        let json = summary(
            dir.path(),
            &n1(20.0, &format!("tolerance = {tolerance}\n")),
            &[],
        );
        let v = json["leaked_volume_m3"].as_f64().unwrap();
        assert!(
            (v / converged - 1.0).abs() < bound,
            "{v} vs {converged} at {tolerance}"
        );
        assert_eq!(json["verdict_text"], tight["verdict_text"], "{tolerance}");
    }
}

/// The shipped cold night (lift-off on): the same verdict and time at every grid; the failure
/// mode the same at the two fastest levels, whose leak crosses its limit seconds before the
/// lift-off that causes it (simultaneous events: the earlier time, the damage's mode).
#[test]
fn the_shipped_cold_night_fails_the_same_way_at_every_grid_and_level() {
    let dir = TempDir::new().unwrap();
    fs::copy(
        scenario_path("cold-night.csv"),
        dir.path().join("cold-night.csv"),
    )
    .unwrap();
    // the night's own opening: the cold checks (which fail it at installation, §8.2–§8.3) waived
    let text = fs::read_to_string(scenario_path("cold-night-nbr.toml"))
        .unwrap()
        .replace(
            "lift_off = true",
            "lift_off = true\nlost_interference = false\nlow_temperature = false",
        );
    let at = |ppd: &str, level: &str| {
        let t = text.replace(
            "points_per_decade = 40",
            &format!("points_per_decade = {ppd}"),
        );
        summary(dir.path(), &t, &["--fidelity", level])
    };
    let reference = at("40", "critical-junction");
    assert_eq!(reference["failure_mode"], "lift_off", "{reference}");
    for ppd in ["5", "10", "160"] {
        let json = at(ppd, "critical-junction");
        assert_eq!(json["verdict_text"], reference["verdict_text"], "{ppd}");
        // the grid only samples: the volume to round-off (3e-12 measured), far inside the 1e-3
        // tolerance of the internal steps
        let (v, r) = (
            json["leaked_volume_m3"].as_f64().unwrap(),
            reference["leaked_volume_m3"].as_f64().unwrap(),
        );
        assert!((v / r - 1.0).abs() < 1e-9, "{v} vs {r} at {ppd}");
    }
    let rough = at("40", "rule-of-thumb");
    assert_eq!(rough["failure_mode"], "lift_off", "{rough}");
    let (a, b) = (
        rough["time_to_failure_s"].as_f64().unwrap(),
        reference["time_to_failure_s"].as_f64().unwrap(),
    );
    assert!((a / b - 1.0).abs() < 1e-2, "{a} vs {b}");
}

/// An O-ring open all its life (k_e = 0 at 100 bar, lift-off waived): the model's bound of the
/// open flow is 0, but the volume is a lower bound, flagged and printed with "≥" (review N10).
#[test]
fn an_open_ring_with_a_zero_bound_still_reads_as_a_lower_bound() {
    let dir = TempDir::new().unwrap();
    let text = fs::read_to_string(scenario_path("oring-fkm-hydraulic-face-100bar.toml"))
        .unwrap()
        .replace("lift_off = true", "lift_off = false")
        .replace("[seal]", "[seal]\nenergisation_factor = 0");
    let (json, stdout) = run_in(dir.path(), &text, &[]);
    assert_eq!(json["verdict"], "open", "{json}");
    assert_eq!(json["leaked_volume_is_lower_bound"], true);
    let line = stdout
        .lines()
        .find(|l| l.starts_with("leaked volume"))
        .unwrap();
    assert!(line.contains('≥') && line.contains("lower bound"), "{line}");
}
