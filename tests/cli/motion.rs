//! End-to-end tests of `[motion]` (reciprocating seals, PY08 §8) through `sealsim leak` and
//! `sealsim run`: the drag columns of the shipped wiper and rod scenarios, v0 = 0 is the static
//! CSV, the drag is linear in the speed, the stroke volumes, and that every bad `[motion]`
//! exits with status 2 naming `file:line: motion.KEY:` and writes nothing.

use crate::common::{PAPER, rel, scenario_path};
use crate::support::{HISTORY_HEADER, no_nan};
use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use serde_json::Value;
use std::fs;
use std::path::{Path, PathBuf};
use tempfile::TempDir;

const WIPER: &str = include_str!("../../scenarios/wiper-blade-water.toml");
const ROD: &str = include_str!("../../scenarios/hydraulic-rod-seal.toml");

const LEAK_HEADER: &str =
    "nominal_pressure_Pa,zeta_c,lambda_c_m,u_c_m,ubar_c_m,hrms_c_m,leak_rate_m3_per_s,state";
const DRAG_COLUMNS: &str = "drag_leak_rate_m3_per_s,film_thickness_m,speed_bound_m_per_s";
const STROKE_COLUMNS: &str = "out_stroke_volume_m3,in_stroke_volume_m3,net_volume_per_cycle_m3";

/// The wiper's sliding-speed line, replaced by the bad-input cases.
const WIPER_SPEED: &str = "sliding_speed = \"1 cm/s\"        # PY08 §8's example speed";

/// `sealsim leak <scenario> <args>` → (header, rows as cells, stderr), expecting success.
fn leak(scenario: &Path, args: &[&str]) -> (String, Vec<Vec<String>>, String) {
    let out = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(scenario)
        .args(args)
        .assert()
        .success();
    let o = out.get_output();
    let stdout = String::from_utf8(o.stdout.clone()).unwrap();
    no_nan(&stdout, "leak CSV");
    let mut lines = stdout.lines();
    let header = lines.next().unwrap().to_owned();
    let rows = lines
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    (header, rows, String::from_utf8(o.stderr.clone()).unwrap())
}

fn num(cell: &str) -> f64 {
    cell.parse()
        .unwrap_or_else(|_| panic!("not a number: {cell:?}"))
}

/// A scenario text in a temporary directory.
struct Case {
    dir: TempDir,
}

impl Case {
    fn new(text: &str) -> Self {
        let dir = TempDir::new().unwrap();
        fs::write(dir.path().join("s.toml"), text).unwrap();
        Case { dir }
    }
    fn scenario(&self) -> PathBuf {
        self.dir.path().join("s.toml")
    }
    fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }
}

/// The line of `needle` (1-based) in `text`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("{needle:?} not found"))
        + 1
}

#[test]
fn wiper_leak_has_the_drag_columns_and_warns_above_the_speed_bound() {
    let (header, rows, stderr) = leak(&scenario_path("wiper-blade-water.toml"), &[]);
    assert_eq!(header, format!("{LEAK_HEADER},{DRAG_COLUMNS}"));
    assert_eq!(rows.len(), 1);
    let r = &rows[0];
    assert_eq!(r.len(), 11);
    assert_eq!(r[7], "leaking");
    let (leak_rate, drag, film, bound) = (num(&r[6]), num(&r[8]), num(&r[9]), num(&r[10]));
    let u_c = num(&r[3]);
    eprintln!(
        "wiper: u_c = {u_c:.4e} m, d = {film:.4e} m, bound = {bound:.4e} m/s, drag = {drag:.4e} m³/s"
    );
    // PY08 §8: u_c ≈ 0.1 µm, d ≈ 0.01 µm; sealsim: u_c = 0.124 µm, d = 8.2 nm, bound 6.1 mm/s
    assert!(rel(u_c, 0.1236e-6) < 1e-3, "{u_c}");
    assert!(rel(film, 8.2e-9) < 0.01, "{film}");
    // the bound is ∝ 1/η: 6.1 mm/s at PY08's 1 mPa·s; the scenario's water (library
    // "water", Huber et al. 2009) at 23 °C has η = 0.932 mPa·s
    assert!(rel(bound, 6.1e-3 / 0.932) < 0.01, "{bound}");
    // the drag is L_y d v (L_y = 0.5 m, v = 1 cm/s); ΔP = 0: the whole leak
    assert!(rel(drag, 0.5 * film * 0.01) < 1e-9, "{drag}");
    assert_eq!(leak_rate, drag);
    // 1 cm/s > 6.54 mm/s (6.095 mm/s × 1/0.932, the water at 23 °C): one warning line
    let warnings: Vec<&str> = stderr
        .lines()
        .filter(|l| l.contains("hydrodynamic lift-off is not modelled"))
        .collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(warnings[0].starts_with("warning: "), "{stderr}");
    assert!(
        warnings[0].contains("sliding speed = 0.01 m/s is above 0.006539 m/s"),
        "{stderr}"
    );
    // within the bound: no warning
    let slow = Case::new(&WIPER.replace(WIPER_SPEED, "sliding_speed = \"3 mm/s\""));
    let (_, rows, stderr) = leak(&slow.scenario(), &[]);
    assert!(!stderr.contains("lift-off"), "{stderr}");
    assert!(rel(num(&rows[0][8]), 0.5 * film * 3e-3) < 1e-9);
}

#[test]
fn zero_speed_gives_exactly_the_static_csv() {
    // the paper's seal (ΔP = 0.01 MPa) over a sweep, with and without [motion]
    let sweep = ["--sweep", "0.05MPa..2.5MPa", "--points", "7"];
    let (header, static_rows, _) = leak(&scenario_path("persson-yang-2008.toml"), &sweep);
    assert_eq!(header, LEAK_HEADER, "no [motion]: the CSV is unchanged");
    let still = Case::new(&format!("{PAPER}[motion]\nsliding_speed = 0\n"));
    let (header, rows, stderr) = leak(&still.scenario(), &sweep);
    assert_eq!(header, format!("{LEAK_HEADER},{DRAG_COLUMNS}"));
    assert!(!stderr.contains("lift-off"), "{stderr}");
    assert!(
        rows.iter().any(|r| r[7] == "sealed"),
        "the sweep reaches sealing"
    );
    for (a, b) in static_rows.iter().zip(&rows) {
        assert_eq!(a[..], b[..8], "the static cells, byte for byte");
        assert_eq!(b[8], "0e0");
        if b[7] == "sealed" {
            // sealed: no film, no bound (blank)
            assert_eq!((b[9].as_str(), b[10].as_str()), ("0e0", ""));
        } else {
            assert!(num(&b[9]) > 0.0 && num(&b[10]) > 0.0);
        }
    }
    // the wiper at rest: ΔP = 0, nothing leaks
    let wiper = Case::new(&WIPER.replace(WIPER_SPEED, "sliding_speed = \"0 m/s\""));
    let (_, rows, _) = leak(&wiper.scenario(), &[]);
    assert_eq!((rows[0][6].as_str(), rows[0][8].as_str()), ("0e0", "0e0"));
}

#[test]
fn drag_is_linear_in_speed_and_adds_to_the_static_leak() {
    let pressures = ["--pressures", "0.1MPa,0.2MPa,0.5MPa"];
    let (_, static_rows, _) = leak(&scenario_path("persson-yang-2008.toml"), &pressures);
    let at = |speed: &str| {
        let case = Case::new(&format!("{PAPER}[motion]\nsliding_speed = \"{speed}\"\n"));
        leak(&case.scenario(), &pressures).1
    };
    let (one, two) = (at("1 mm/s"), at("2 mm/s"));
    for ((s, a), b) in static_rows.iter().zip(&one).zip(&two) {
        let (d1, d2) = (num(&a[8]), num(&b[8]));
        assert!(d1 > 0.0);
        assert_eq!(d2, 2.0 * d1, "doubling the speed doubles the drag exactly");
        assert_eq!(a[9..], b[9..], "film and bound do not depend on the speed");
        assert_eq!(num(&a[6]), num(&s[6]) + d1, "leak = static + drag");
        assert_eq!(num(&b[6]), num(&s[6]) + d2);
        // L_y d v with L_y = 1 mm
        assert!(rel(d1, 1e-3 * num(&a[9]) * 1e-3) < 1e-9);
    }
    // the drag uses the exact critical junction whatever the level
    let case = Case::new(&format!("{PAPER}[motion]\nsliding_speed = \"1 mm/s\"\n"));
    let (_, rot, _) = leak(
        &case.scenario(),
        &[&pressures[..], &["--fidelity", "rule-of-thumb"]].concat(),
    );
    for (a, b) in one.iter().zip(&rot) {
        assert_eq!(a[8..], b[8..]);
    }
}

#[test]
fn stroke_cycle_leak_has_the_volumes_per_stroke() {
    let (header, rows, stderr) = leak(&scenario_path("hydraulic-rod-seal.toml"), &[]);
    assert_eq!(
        header,
        format!("{LEAK_HEADER},{DRAG_COLUMNS},{STROKE_COLUMNS}")
    );
    let r = &rows[0];
    let (leak_rate, drag, film) = (num(&r[6]), num(&r[8]), num(&r[9]));
    let (out, back, net) = (num(&r[11]), num(&r[12]), num(&r[13]));
    // L_y = π D′ (the ring as installed on the rod), S = 100 mm, v_out = v_in = 0.1 m/s (1 s
    // per stroke)
    let l_y = sealsim::scenario::Scenario::load(&scenario_path("hydraulic-rod-seal.toml"))
        .unwrap()
        .life
        .geometry
        .sealing_length();
    let film_volume = l_y * film * 0.1;
    assert!(rel(drag, l_y * film * 0.1) < 1e-9);
    assert!(rel(out, leak_rate * 1.0 + film_volume) < 1e-9);
    assert!(rel(back, leak_rate * 1.0 - film_volume) < 1e-9);
    assert!(rel(net, out + back) < 1e-12);
    // the stroke leaves the leak rate static; net = static × cycle time (to rounding)
    assert!((net - 2.0 * leak_rate).abs() <= 1e-9 * film_volume, "{net}");
    assert!(
        stderr.contains("hydrodynamic lift-off is not modelled"),
        "{stderr}"
    );
}

#[test]
fn rod_seal_run_reports_the_stroke_volumes() {
    let case = Case::new(ROD);
    let (h, s) = (case.path("h.csv"), case.path("s.json"));
    let start = std::time::Instant::now();
    let out = cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(scenario_path("hydraulic-rod-seal.toml"))
        .arg("-o")
        .arg(&h)
        .arg("--summary")
        .arg(&s)
        .assert()
        .success();
    eprintln!("rod seal run: {:.2?}", start.elapsed());
    let stdout = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    no_nan(&stdout, "summary");
    assert!(
        stdout.contains("motion") && stdout.contains("stroke 100 mm"),
        "{stdout}"
    );
    assert!(
        stderr.lines().all(|l| l.starts_with("warning: ")),
        "{stderr}"
    );
    assert_eq!(
        stderr.matches("lift-off is not modelled").count(),
        1,
        "{stderr}"
    );
    let csv = fs::read_to_string(&h).unwrap();
    no_nan(&csv, "history");
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        format!("{HISTORY_HEADER},drag_leak_rate_m3_per_s,net_volume_per_cycle_m3")
    );
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells.len(), 16, "{line}");
        let (leak_rate, drag, net) = (num(cells[9]), num(cells[14]), num(cells[15]));
        assert!(drag > 0.0, "{line}");
        assert!(rel(net, 2.0 * leak_rate) < 1e-9 || net == 0.0, "{line}");
    }
    let text = fs::read_to_string(&s).unwrap();
    no_nan(&text, "summary JSON");
    let json: Value = serde_json::from_str(&text).unwrap();
    let m = &json["motion"];
    assert_eq!(m["kind"], "stroke");
    assert_eq!(m["stroke_m"], 0.1);
    assert_eq!(m["cycle_period_s"], 2.0);
    assert_eq!(m["speed_above_bound"], true);
    assert!(m["speed_bound_m_per_s"].as_f64().unwrap() < 1e-3);
    for key in ["initial_cycle", "final_cycle"] {
        let c = &m[key];
        let (o, i, n, d) = (
            c["out_stroke_volume_m3"].as_f64().unwrap(),
            c["in_stroke_volume_m3"].as_f64().unwrap(),
            c["net_volume_per_cycle_m3"].as_f64().unwrap(),
            c["drag_volume_per_stroke_m3"].as_f64().unwrap(),
        );
        eprintln!("{key}: out {o:.4e} m³, in {i:.4e} m³, net {n:.4e} m³, film {d:.4e} m³");
        // out ≈ back (the linear theory): the film dominates one stroke's static leak
        assert!(o > 0.0 && i < 0.0 && d > 0.0);
        assert!(rel(-i, o) < 1e-3, "{c}");
        assert!(rel(n, o + i) < 1e-9);
    }
    let life = json["time_to_failure_s"].clone();
    eprintln!(
        "rod seal: failure {} ({life}), leaked {} m³, leak rate {} → {} m³/s",
        json["failure_mode"],
        json["leaked_volume_m3"],
        json["initial_leak_rate_m3_per_s"],
        json["final_leak_rate_m3_per_s"]
    );
}

#[test]
fn wiper_run_includes_the_drag_in_the_leak_rate() {
    let case = Case::new(WIPER);
    let (h, s) = (case.path("h.csv"), case.path("s.json"));
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(scenario_path("wiper-blade-water.toml"))
        .arg("-o")
        .arg(&h)
        .arg("--summary")
        .arg(&s)
        .assert()
        .success()
        .stderr(predicate::str::contains("lift-off is not modelled"));
    let csv = fs::read_to_string(&h).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        format!("{HISTORY_HEADER},drag_leak_rate_m3_per_s")
    );
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells.len(), 15);
        assert_eq!(cells[9], cells[14], "ΔP = 0: the leak is the drag");
        assert_eq!(cells[11], "leaking");
    }
    let json: Value = serde_json::from_str(&fs::read_to_string(&s).unwrap()).unwrap();
    let m = &json["motion"];
    assert_eq!(m["kind"], "steady");
    assert_eq!(m["sliding_speed_m_per_s"], 0.01);
    assert!(m.get("initial_cycle").is_none());
    assert_eq!(
        m["initial_drag_leak_rate_m3_per_s"],
        json["initial_leak_rate_m3_per_s"]
    );
    assert!(rel(m["initial_film_thickness_m"].as_f64().unwrap(), 8.2e-9) < 0.01);
    assert_eq!(m["speed_above_bound"], true);
}

#[test]
fn static_scenario_summary_has_no_motion() {
    let case = Case::new(PAPER);
    let s = case.path("s.json");
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(scenario_path("persson-yang-2008.toml"))
        .arg("--summary")
        .arg(&s)
        .assert()
        .success();
    let json: Value = serde_json::from_str(&fs::read_to_string(&s).unwrap()).unwrap();
    assert!(json.get("motion").is_none(), "{json}");
}

#[test]
fn bad_motion_exits_2_names_the_key_and_writes_nothing() {
    let line = line_of(WIPER, WIPER_SPEED);
    let cases: [(&str, usize, &str); 7] = [
        (
            "sliding_speed = \"-1 cm/s\"",
            line,
            "motion.sliding_speed: must not be negative, got -0.01 m/s",
        ),
        (
            "stroke = \"100 mm\"\nfrequency = \"0 Hz\"",
            line + 1,
            "motion.frequency: must be positive, got 0 Hz",
        ),
        (
            "stroke = \"100 mm\"",
            line,
            "motion.stroke: a stroke cycle needs frequency",
        ),
        (
            "sliding_speed = \"1 cm/s\"\nstroke = \"100 mm\"",
            line + 1,
            "motion.stroke: sliding_speed (constant sliding) and stroke (a stroke cycle) are \
             mutually exclusive",
        ),
        (
            "stroke = \"100 mm\"\nfrequency = \"1 Hz\"\nout_speed = \"0.1 m/s\"",
            line + 1,
            "motion.frequency: frequency (which sets out_speed = in_speed = 2 · stroke · \
             frequency) and out_speed/in_speed are mutually exclusive",
        ),
        (
            "stroke = \"100 mm\"\nout_speed = \"0.1 m/s\"",
            line + 1,
            "motion.in_speed: missing key",
        ),
        (
            "sliding_speed = \"1 MPa\"",
            line,
            "motion.sliding_speed: expected a velocity",
        ),
    ];
    for (replacement, line, message) in cases {
        let case = Case::new(&WIPER.replace(WIPER_SPEED, replacement));
        let expected = format!("s.toml:{line}: {message}");
        for command in ["leak", "run"] {
            let output = case.path("out.csv");
            let summary = case.path("s.json");
            let mut cmd = cargo_bin_cmd!("sealsim");
            cmd.arg(command).arg(case.scenario()).arg("-o").arg(&output);
            if command == "run" {
                cmd.arg("--summary").arg(&summary);
            }
            let out = cmd
                .assert()
                .code(2)
                .stdout(predicate::str::is_empty())
                .stderr(predicate::str::starts_with("error: "))
                .stderr(predicate::str::contains("panicked").not());
            let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
            assert!(
                stderr.contains(&expected),
                "{command} {replacement:?}:\n{stderr}\nexpected {expected}"
            );
            assert!(
                !output.exists() && !summary.exists(),
                "something was written"
            );
        }
    }
}
