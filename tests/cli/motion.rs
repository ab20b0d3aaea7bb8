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

const LEAK_HEADER: &str = "nominal_pressure_Pa,zeta_c,lambda_c_m,u_c_m,ubar_c_m,hrms_c_m,leak_rate_m3_per_s,state,area_fraction,mean_gap_m";
const DRAG_COLUMNS: &str = "drag_leak_rate_m3_per_s,film_thickness_m,speed_bound_m_per_s";
const STROKE_COLUMNS: &str = "out_stroke_volume_m3,in_stroke_volume_m3,net_volume_per_cycle_m3,\
     cycle_mean_leak_rate_m3_per_s,out_stroke_film_m,in_stroke_film_m,film_parameter,speed_regime,\
     film_regime";

/// The rod scenario's profile line, replaced by the bad-input cases.
const ROD_PROFILE: &str = "contact_profile = \"hydraulic-rod-seal-profile.csv\"   # x, p across the contact (illustrative)";

/// The wiper's sliding-speed line, replaced by the bad-input cases.
const WIPER_SPEED: &str = "sliding_speed = \"1 cm/s\"        # PY08 §8's example speed";

/// `sealsim leak <scenario> <args>` → (header, rows as cells, stderr), expecting success.
fn leak(scenario: &Path, args: &[&str]) -> (String, Vec<Vec<String>>, String) {
    let out = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(scenario)
        .arg("--verbose") // the warnings in full
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
    assert_eq!(r.len(), 13);
    assert_eq!(r[7], "leaking");
    let (leak_rate, drag, film, bound) = (num(&r[6]), num(&r[10]), num(&r[11]), num(&r[12]));
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
    assert!(warnings[0].starts_with("warning[W"), "{stderr}");
    assert!(
        warnings[0].contains("sliding speed = 0.01 m/s is above 0.006539 m/s"),
        "{stderr}"
    );
    // within the bound: no warning
    let slow = Case::new(&WIPER.replace(WIPER_SPEED, "sliding_speed = \"3 mm/s\""));
    let (_, rows, stderr) = leak(&slow.scenario(), &[]);
    assert!(!stderr.contains("lift-off"), "{stderr}");
    assert!(rel(num(&rows[0][10]), 0.5 * film * 3e-3) < 1e-9);
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
        assert_eq!(a[..], b[..10], "the static cells, byte for byte");
        assert_eq!(b[10], "0e0");
        if b[7] == "sealed" {
            // sealed: no film, no bound (blank)
            assert_eq!((b[11].as_str(), b[12].as_str()), ("0e0", ""));
        } else {
            assert!(num(&b[11]) > 0.0 && num(&b[12]) > 0.0);
        }
    }
    // the wiper at rest: ΔP = 0, nothing leaks
    let wiper = Case::new(&WIPER.replace(WIPER_SPEED, "sliding_speed = \"0 m/s\""));
    let (_, rows, _) = leak(&wiper.scenario(), &[]);
    assert_eq!((rows[0][6].as_str(), rows[0][10].as_str()), ("0e0", "0e0"));
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
        let (d1, d2) = (num(&a[10]), num(&b[10]));
        assert!(d1 > 0.0);
        assert_eq!(d2, 2.0 * d1, "doubling the speed doubles the drag exactly");
        assert_eq!(
            a[11..],
            b[11..],
            "film and bound do not depend on the speed"
        );
        assert_eq!(num(&a[6]), num(&s[6]) + d1, "leak = static + drag");
        assert_eq!(num(&b[6]), num(&s[6]) + d2);
        // L_y d v with L_y = 1 mm
        assert!(rel(d1, 1e-3 * num(&a[11]) * 1e-3) < 1e-9);
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

/// The column `name` of a CSV header.
fn column(header: &str, name: &str) -> usize {
    header
        .split(',')
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no column {name} in {header}"))
}

/// The rod scenario's profile flanks are `rise · (1 − ξ²)^{3/2}` over the half width a
/// (hydraulic-rod-seal-profile.csv): steepest `1.5 rise/a`; the fluid flank rises from ΔP =
/// 0.2 MPa to the 1.866 MPa peak, the air flank from 0; a = 2.435 mm/2.
fn rod_profile_gradients() -> (f64, f64) {
    let a = 2.435e-3 / 2.0;
    (1.5 * (1.866e6 - 0.2e6) / a, 1.5 * 1.866e6 / a)
}

#[test]
fn rod_seal_leak_reports_the_inverse_hydrodynamic_films() {
    let (header, rows, stderr) = leak(&scenario_path("hydraulic-rod-seal.toml"), &[]);
    assert_eq!(
        header,
        format!("{LEAK_HEADER},{DRAG_COLUMNS},{STROKE_COLUMNS}")
    );
    let r = &rows[0];
    let get = |name: &str| num(&r[column(&header, name)]);
    let s = sealsim::scenario::Scenario::load(&scenario_path("hydraulic-rod-seal.toml")).unwrap();
    let (eta, l_y) = (s.problem.fluid.viscosity, s.life.geometry.sealing_length());
    // the films against the closed form with the profile's analytic flanks (the table's secants
    // sit within 0.5 % of them: films within 0.3 %)
    let (w_out, w_in) = rod_profile_gradients();
    let (h_out, h_in) = (get("out_stroke_film_m"), get("in_stroke_film_m"));
    eprintln!("rod: h_out {h_out:.4e} m, h_in {h_in:.4e} m, η {eta} Pa·s");
    assert!(
        rel(h_out, (8.0 * eta * 0.2 / (9.0 * w_out)).sqrt()) < 3e-3,
        "{h_out}"
    );
    assert!(
        rel(h_in, (8.0 * eta * 0.2 / (9.0 * w_in)).sqrt()) < 3e-3,
        "{h_in}"
    );
    assert!(h_out > h_in, "the pressurised flank is the gentler");
    // volumes: L_y S h/2 out, back; net = L_y S (h_out − h_in)/2; 1 s cycle
    let (out, back, net) = (
        get("out_stroke_volume_m3"),
        get("in_stroke_volume_m3"),
        get("net_volume_per_cycle_m3"),
    );
    assert!(rel(out, l_y * 0.1 * h_out / 2.0) < 1e-12);
    assert!(rel(back, -l_y * 0.1 * h_in / 2.0) < 1e-12);
    assert!(rel(net, l_y * 0.1 * (h_out - h_in) / 2.0) < 1e-9);
    assert_eq!(get("cycle_mean_leak_rate_m3_per_s"), net);
    // the leak rate is the cycle mean; the static contact is sealed on the Ra 0.2 µm rod
    assert_eq!(get("leak_rate_m3_per_s"), net);
    assert_eq!(r[column(&header, "u_c_m")], "");
    assert_eq!(r[column(&header, "speed_regime")], "inverse_hydrodynamic");
    assert_eq!(r[column(&header, "film_regime")], "full_film");
    // Λ = h_in/σ with σ = Rq = √(π/2) · 0.2 µm (the callout's band; the extension adds ≈ 0)
    let sigma = (std::f64::consts::PI / 2.0).sqrt() * 0.2e-6;
    assert!(rel(get("film_parameter"), h_in / sigma) < 1e-3);
    // a profile is given: no estimate, no lift-off, no transition warning
    for w in ["lift-off", "estimated", "blend"] {
        assert!(!stderr.contains(w), "{stderr}");
    }
}

#[test]
fn rod_seal_run_reports_the_films_and_leaks_the_cycle_mean() {
    let case = Case::new(ROD);
    let (h, s) = (case.path("h.csv"), case.path("s.json"));
    let start = std::time::Instant::now();
    let out = cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(scenario_path("hydraulic-rod-seal.toml"))
        .arg("--verbose")
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
        stdout.contains("stroke 100 mm") && stdout.contains("inverse-hydrodynamic films"),
        "{stdout}"
    );
    assert!(
        stderr
            .lines()
            .all(|l| l.starts_with("warning[W") || l.starts_with("note[N")),
        "{stderr}"
    );
    assert!(!stderr.contains("lift-off"), "{stderr}");
    let csv = fs::read_to_string(&h).unwrap();
    no_nan(&csv, "history");
    let mut lines = csv.lines();
    let header = lines.next().unwrap().to_owned();
    assert_eq!(
        header,
        format!(
            "{HISTORY_HEADER},drag_leak_rate_m3_per_s,net_volume_per_cycle_m3,out_stroke_film_m,\
             in_stroke_film_m,speed_regime"
        )
    );
    let mut rows = 0;
    let mut net_in_service = 0.0;
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells.len(), 20, "{line}");
        let (leak_rate, net) = (num(cells[9]), num(cells[16]));
        net_in_service = net;
        // a 1 s cycle: the leak rate is the net volume per cycle per second
        assert_eq!(leak_rate, net, "{line}");
        assert!(num(cells[17]) > num(cells[18]), "{line}");
        assert_eq!(cells[19], "inverse_hydrodynamic");
        rows += 1;
    }
    assert!(rows > 10);
    let json: Value = serde_json::from_str(&fs::read_to_string(&s).unwrap()).unwrap();
    let m = &json["motion"];
    assert_eq!(m["kind"], "stroke");
    assert_eq!(m["cycle_period_s"], 1.0);
    assert_eq!(m["speed_above_bound"], false);
    let c = &m["initial_cycle"];
    assert_eq!(c["speed_regime"], "inverse_hydrodynamic");
    let i = &c["ihl"];
    assert_eq!(i["gradient_source"], "profile");
    assert_eq!(i["starved"], false);
    assert_eq!(i["film_regime"], "full_film");
    let (w_out, w_in) = rod_profile_gradients();
    let g_out = i["inlet_gradient_out_pa_per_m"].as_f64().unwrap();
    let g_in = i["inlet_gradient_in_pa_per_m"].as_f64().unwrap();
    assert!(
        g_out < w_out && rel(g_out, w_out) < 5e-3,
        "{g_out} vs {w_out}"
    );
    assert!(g_in < w_in && rel(g_in, w_in) < 5e-3, "{g_in} vs {w_in}");
    let net = c["net_volume_per_cycle_m3"].as_f64().unwrap();
    let carried = i["out_stroke_carried_m3"].as_f64().unwrap();
    let returned = i["in_stroke_returned_m3"].as_f64().unwrap();
    assert!(rel(net, carried - returned) < 1e-12);
    // constant leak rate in service: failure by the 0.5 L criterion at 0.5 L/(net per second),
    // the net of the service temperature (the ring is fitted at 23 °C and warms to 50 °C within
    // its first 2 minutes, docs/model.md §5.2: the installation's cycle is a cooler one)
    let t = json["time_to_failure_s"].as_f64().unwrap();
    assert_eq!(json["failure_mode"], "leaked_volume");
    assert!(
        rel(t, 0.5e-3 / net_in_service) < 1e-3,
        "{t} vs {}",
        0.5e-3 / net_in_service
    );
    eprintln!(
        "rod seal: net {net:.4e} m³/cycle, carried {carried:.4e} m³, failure after {t:.4e} s"
    );
}

#[test]
fn bad_rod_profile_exits_2_naming_the_key() {
    let line = line_of(ROD, ROD_PROFILE);
    let unsorted = "# x out of order\nx,p\nmm,MPa\n0,0.2\n0.5,1\n0.4,2\n1.0,0\n";
    let negative = "x,p\nmm,MPa\n0,0.2\n0.5,-1\n1.0,0\n";
    let cases: [(&str, Option<&str>, usize, &str); 6] = [
        (
            "inlet_gradient_out = \"-2 MPa/mm\"\ninlet_gradient_in = \"2 MPa/mm\"",
            None,
            line,
            "motion.inlet_gradient_out: must be positive, got -2e9 Pa/m",
        ),
        (
            "inlet_gradient_out = \"2 MPa/mm\"\ninlet_gradient_in = \"0 MPa/mm\"",
            None,
            line + 1,
            "motion.inlet_gradient_in: must be positive",
        ),
        (
            "inlet_gradient_out = \"2 MPa/mm\"",
            None,
            line,
            "motion.inlet_gradient_in: missing key",
        ),
        (
            "contact_profile = \"p.csv\"",
            Some(unsorted),
            line,
            "motion.contact_profile: ",
        ),
        (
            "contact_profile = \"p.csv\"",
            Some(negative),
            line,
            "motion.contact_profile: ",
        ),
        (
            "inlet_gradient_in = \"2 MPa/mm\"\ncontact_profile = \"p.csv\"",
            Some(unsorted),
            line,
            "motion.inlet_gradient_in: contact_profile gives the gradients",
        ),
    ];
    for (k, (replacement, profile, line, message)) in cases.into_iter().enumerate() {
        let case = Case::new(&ROD.replace(ROD_PROFILE, replacement));
        if let Some(text) = profile {
            fs::write(case.path("p.csv"), text).unwrap();
        }
        let expected = format!("s.toml:{line}: {message}");
        for command in ["leak", "run"] {
            let output = case.path("out.csv");
            let out = cargo_bin_cmd!("sealsim")
                .arg(command)
                .arg(case.scenario())
                .arg("-o")
                .arg(&output)
                .assert()
                .code(2)
                .stdout(predicate::str::is_empty())
                .stderr(predicate::str::contains("panicked").not());
            let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
            assert!(
                stderr.contains(&expected),
                "{command} {replacement:?}:\n{stderr}\nexpected {expected}"
            );
            // the data file's own line: the unsorted row is line 6, the negative one line 4
            match k {
                3 => assert!(
                    stderr.contains("p.csv:6: x must increase strictly"),
                    "{stderr}"
                ),
                4 => assert!(
                    stderr.contains("p.csv:4: the contact pressure must not be negative"),
                    "{stderr}"
                ),
                _ => {}
            }
            assert!(!output.exists(), "something was written");
        }
    }
}

#[test]
fn wiper_run_includes_the_drag_in_the_leak_rate() {
    let case = Case::new(WIPER);
    let (h, s) = (case.path("h.csv"), case.path("s.json"));
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(scenario_path("wiper-blade-water.toml"))
        .arg("--verbose")
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
        assert_eq!(cells.len(), 16);
        assert_eq!(cells[9], cells[15], "ΔP = 0: the leak is the drag");
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
