//! `sealsim advise` end to end (issue 41 item 7): the new user's piston ring gets changes that,
//! applied and run by `sealsim run`, each meet the target; a scenario that passes needs none;
//! bad flags exit 2 naming the flag; the advice is the same on one thread and two.

use crate::support::sealsim;
use std::path::Path;

/// The new user's AS568-214 NBR piston ring (1 back-up ring, ISO VG 46 at 210 bar and 80 °C):
/// `sealsim run` gives FAILS after 407 days by retained_force.
const PISTON: &str = r#"name = "AS568-214 NBR piston, VG46 210 bar 80 C, 1 backup"

[material]
library = "nbr-70"

[surface]
ra = "0.4 um"

[groove_surface]
ra = "1.6 um"

[fluid]
library = "iso-vg-46"
pressure_difference = "210 bar"

[seal]
kind = "o-ring"
gland = "piston"
size = "AS568-214"
bore_diameter = "31.75 mm"
groove_depth = "2.91 mm"
groove_depth_tolerance = "0.09 mm"
groove_width = "5.6 mm"
diametral_clearance = "0.06 mm"
backup_rings = 1

[environment]
temperature = "80 C"

[failure]
max_leaked_volume = "1 L"
min_retained_force = 0.1

[simulation]
duration = "10 year"
"#;

const TEN_YEARS: f64 = 10.0 * 365.25 * 86400.0;

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// `sealsim run --summary` on `scenario`: (life in s, +∞ when it survives; verdict; stderr).
fn run(scenario: &Path) -> (f64, String, String) {
    let json = scenario.with_extension("json");
    let out = sealsim()
        .arg("run")
        .arg(scenario)
        .arg("--summary")
        .arg(&json)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let life = v["time_to_failure_s"].as_f64().unwrap_or(f64::INFINITY);
    (
        life,
        v["verdict"].as_str().unwrap().to_owned(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn the_piston_ring_gets_changes_that_each_pass_when_run() {
    let dir = tempfile::tempdir().unwrap();
    let base = write(dir.path(), "piston.toml", PISTON);
    // the base fails the target
    let (life, _, _) = run(&base);
    assert!(life < TEN_YEARS, "{life}");
    let (json, out) = (dir.path().join("a.json"), dir.path().join("proposals"));
    let o = sealsim()
        .args([
            "advise",
            "--life",
            "10y",
            "--max-runs",
            "60",
            "--threads",
            "2",
        ])
        .arg(&base)
        .arg("--json")
        .arg(&json)
        .arg("--write")
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8(o.stdout).unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // the verdict first, then the count of changes that pass
    let first = stdout.lines().nth(1).unwrap();
    assert!(
        first.starts_with("FAILS after 407 days") && first.contains("target 10 years"),
        "{stdout}"
    );
    assert!(first.contains("pass"), "{stdout}");
    let advice: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let proposals = advice["proposals"].as_array().unwrap();
    let passing: Vec<_> = proposals.iter().filter(|p| p["passes"] == true).collect();
    assert!(!passing.is_empty(), "{stdout}");
    assert!(advice["runs"].as_u64().unwrap() <= 60);
    // every written proposal, run by `sealsim run`, meets the target with a compound the
    // fluid's ratings allow
    let mut written: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    written.sort();
    assert_eq!(written.len(), proposals.len());
    for (p, proposal) in written.iter().zip(proposals) {
        let (life, verdict, stderr) = run(p);
        if proposal["passes"] == true {
            assert!(life >= TEN_YEARS, "{}: {life}", p.display());
            assert_eq!(verdict, "survives", "{}", p.display());
        }
        for line in stderr.lines().filter(|l| l.contains(" is rated ")) {
            assert!(
                line.contains("is rated A") || line.contains("is rated B"),
                "{}: {line}",
                p.display()
            );
        }
    }
    // a compound proposal names its rating, never X
    for p in proposals {
        for n in p["notes"].as_array().unwrap() {
            let n = n.as_str().unwrap();
            if n.contains("rated") {
                assert!(n.contains("rated A") || n.contains("rated B"), "{n}");
            }
        }
    }
}

#[test]
fn a_scenario_that_passes_needs_no_change() {
    let dir = tempfile::tempdir().unwrap();
    // the same ring for one year: the NBR fails after 407 days, so one year passes
    let base = write(dir.path(), "piston.toml", PISTON);
    let json = dir.path().join("a.json");
    let o = sealsim()
        .args(["advise", "--life", "300 days", "--max-runs", "20"])
        .arg(&base)
        .arg("--json")
        .arg(&json)
        .output()
        .unwrap();
    let stdout = String::from_utf8(o.stdout).unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(stdout.contains("it already passes"), "{stdout}");
    assert!(stdout.contains("No change is needed"), "{stdout}");
    let advice: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(advice["base"]["passes"], true);
    assert!(advice["proposals"].as_array().unwrap().is_empty());
    // its margin is given: the retained force is above its 10 % at 300 days
    assert!(advice["base"]["margin"]["margin"].as_f64().unwrap() >= 0.0);
}

#[test]
fn bad_input_exits_2_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let base = write(dir.path(), "piston.toml", PISTON);
    for (life, words) in [("banana", "--life"), ("-1y", "--life: must be positive")] {
        let o = sealsim()
            .args(["advise", "--life", life])
            .arg(&base)
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(2), "{life}");
        let err = String::from_utf8(o.stderr).unwrap();
        assert!(err.contains(words), "{life}: {err}");
    }
    let o = sealsim()
        .args(["advise", "--life", "10y"])
        .arg(dir.path().join("missing.toml"))
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert!(
        String::from_utf8(o.stderr)
            .unwrap()
            .contains("missing.toml")
    );
    // the JSON may not replace the scenario
    let o = sealsim()
        .args(["advise", "--life", "10y", "--json"])
        .arg(&base)
        .arg(&base)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&base).unwrap(), PISTON);
}

#[test]
fn one_thread_and_two_give_the_same_advice() {
    let dir = tempfile::tempdir().unwrap();
    let base = write(dir.path(), "piston.toml", PISTON);
    let json = |threads: &str| {
        let path = dir.path().join(format!("a{threads}.json"));
        let o = sealsim()
            .args([
                "advise",
                "--life",
                "10y",
                "--max-runs",
                "40",
                "--threads",
                threads,
            ])
            .arg(&base)
            .arg("--json")
            .arg(&path)
            .output()
            .unwrap();
        assert!(o.status.success());
        std::fs::read(&path).unwrap()
    };
    assert_eq!(json("1"), json("2"));
}
