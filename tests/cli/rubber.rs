//! Rubber as compounds behave (issue 14) end to end: a glassy ring loses its contact in the cold
//! (NBR at −50 °C lifts off, VMQ holds), the library's ageing data are shown with what they were
//! measured on, a run that leaves them off says so, and the summary refers the retained force to
//! its reference time.

use crate::support::sealsim;
use serde_json::Value;
use std::fs;
use std::path::Path;

/// A face-gland AS568-225 ring of `library` at 25 % squeeze, 2 bar, through `history`.
fn cold_start(library: &str) -> String {
    format!(
        r#"name = "cold start {library}"
[material]
library = "{library}"
[surface]
rms_roughness = "0.4 um"
hurst_exponent = 0.8
q0 = "1e5 1/m"
q1 = "1e9 1/m"
[fluid]
viscosity = "10 mPa*s"
pressure_difference = "2 bar"
[seal]
kind = "o-ring"
gland = "face"
size = "AS568-225"
groove_depth = "2.65 mm"
groove_width = "4.8 mm"
groove_outer_diameter = "54.3 mm"
extrusion_gap = "0.02 mm"
[environment]
history = "cold.csv"
[failure]
max_leak_rate = "1 mL/h"
lift_off = true
# the run's own loss of contact (the shutdown check and the cold limit fail these rings first)
lost_interference = false
low_temperature = false
[simulation]
duration = "54 h"
"#
    )
}

/// One day at 23 °C (installed at 23 °C in a steel flange), cooled to −50 °C over 6 h, held a
/// day.
const COLD: &str = "time,temperature\nh,C\n0,23\n24,23\n30,-50\n54,-50\n";

/// `sealsim run` of `text` (with [`COLD`] beside it): the summary and stderr.
fn run(dir: &Path, text: &str) -> (Value, String) {
    fs::write(dir.join("cold.csv"), COLD).unwrap();
    let scenario = dir.join("s.toml");
    fs::write(&scenario, text).unwrap();
    let out = sealsim()
        .arg("run")
        .arg(&scenario)
        .arg("-o")
        .arg(dir.join("h.csv"))
        .arg("--summary")
        .arg(dir.join("s.json"))
        .output()
        .unwrap();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let summary = fs::read_to_string(dir.join("s.json")).unwrap();
    (serde_json::from_str(&summary).unwrap(), stderr)
}

#[test]
fn a_glassy_ring_loses_contact_in_the_cold_and_a_rubbery_one_holds() {
    // NBR (T_g −34 °C) turns glassy at −50 °C: the contraction is unloaded with ≈ 2 GPa and the
    // sealing force vanishes — the ring lifts off during the cooling; VMQ (T_g −127 °C) keeps
    // most of its force. FKM (T_g −10 °C) fails too, EPDM (T_g −55 °C) holds.
    let dir = tempfile::tempdir().unwrap();
    for (library, fails) in [
        ("nbr-70", true),
        ("vmq-70", false),
        ("fkm-75", true),
        ("epdm-70", false),
    ] {
        let (summary, _) = run(dir.path(), &cold_start(library));
        let mode = summary["failure_mode"].as_str().unwrap();
        if fails {
            assert!(
                ["lift_off", "leak_rate"].contains(&mode),
                "{library}: {summary}"
            );
            // during the cooling (24–30 h), not before it
            let t = summary["time_to_failure_s"].as_f64().unwrap();
            assert!(
                (24.0 * 3600.0..30.0 * 3600.0).contains(&t),
                "{library}: {t}"
            );
            assert!(summary["final_sealing_force_N_per_m"].as_f64().unwrap() < 1.0);
        } else {
            assert_eq!(mode, "none", "{library}: {summary}");
            assert!(
                summary["final_retained_force"].as_f64().unwrap() > 0.7,
                "{summary}"
            );
        }
    }
}

#[test]
fn the_retained_force_is_referred_to_thirty_minutes_and_reported() {
    let dir = tempfile::tempdir().unwrap();
    // (ageing off: the force's own relaxation alone)
    let (summary, _) = run(
        dir.path(),
        &format!("{}[ageing]\nenabled = false\n", cold_start("vmq-70")),
    );
    assert_eq!(summary["retained_force_reference_s"], 1800.0);
    let reference = summary["reference_sealing_force_N_per_m"].as_f64().unwrap();
    let initial = summary["initial_sealing_force_N_per_m"].as_f64().unwrap();
    let last = summary["final_sealing_force_N_per_m"].as_f64().unwrap();
    // the force relaxes in the first half hour: the reference lies below the installed force
    assert!(
        reference < initial && reference > 0.5 * initial,
        "{summary}"
    );
    let fraction = summary["final_retained_force"].as_f64().unwrap();
    assert!((fraction - last / reference).abs() < 1e-12, "{summary}");
    assert!(summary.get("final_compression_set").is_none(), "{summary}");
}

#[test]
fn a_compound_with_ageing_data_ages_by_default_and_stops_when_switched_off() {
    let dir = tempfile::tempdir().unwrap();
    let text = cold_start("nbr-70").replace("history = \"cold.csv\"", "temperature = \"80 C\"");
    // off, said so in the summary
    let (summary, _) = run(dir.path(), &format!("{text}[ageing]\nenabled = false\n"));
    assert!(summary.get("final_compression_set").is_none());
    assert_eq!(summary["ageing"], "off");
    // on without a table: the compound's constants, the set grows, the history has the column
    let (summary, _) = run(dir.path(), &text);
    assert_eq!(summary["ageing"], "compound");
    let set = summary["final_compression_set"].as_f64().unwrap();
    assert!(set > 0.0 && set < 1.0, "{summary}");
    let csv = fs::read_to_string(dir.path().join("h.csv")).unwrap();
    let last = csv.lines().last().unwrap();
    let cells: Vec<&str> = last.split(',').collect();
    // (serde_json's default float parser may be off by an ulp: compare to 1e-15)
    let cell = cells[13].parse::<f64>().unwrap();
    assert!((cell / set - 1.0).abs() < 1e-15, "{cell} vs {set}");
}

#[test]
fn every_library_compound_shows_its_ageing_basis_or_why_it_has_none() {
    for id in ["nbr-70", "hnbr-75", "fkm-75", "epdm-70", "vmq-70", "cr-70"] {
        let out = sealsim().args(["materials", "show", id]).output().unwrap();
        assert!(out.status.success());
        let text = String::from_utf8(out.stdout).unwrap();
        let at = text
            .find("\nageing ")
            .unwrap_or_else(|| panic!("{id}: {text}"));
        let block = &text[at..];
        if block.starts_with("\nageing              none") {
            assert!(
                block.contains("source: no ageing constants"),
                "{id}: {block}"
            );
        } else {
            for needle in [
                "scission k_ref",
                "Ea =",
                "property: ",
                "criterion: ",
                "source: ",
            ] {
                assert!(block.contains(needle), "{id}: no {needle:?} in {block}");
            }
        }
    }
}
