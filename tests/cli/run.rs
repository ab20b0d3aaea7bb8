//! End-to-end tests of `sealsim run` and `sealsim compare`: every shipped scenario runs, the
//! CSV and JSON contracts, a closed-form failure time through the whole CLI, and that bad input
//! exits with status 2, names the file, line and key, and writes nothing.

use crate::common::scenarios_dir;
use crate::support::{HISTORY_HEADER, no_nan};
use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use serde_json::Value;
use std::fs;
use std::path::{Path, PathBuf};
use tempfile::TempDir;

const COMPARE_HEADER: &str = "material,name,status,time_to_failure_s,failure_mode,\
leak_rate_1day_m3_per_s,leak_rate_1year_m3_per_s,leak_rate_10years_m3_per_s,\
sealing_force_end_N_per_m,retained_force_end,leaked_volume_end_m3,leaked_volume_is_lower_bound,\
compression_set_end,state_end,verdict,neighbour_level,neighbour_verdict,notes,activation_energy_source,\
rank,rank_basis,rating,rating_source";

const SUMMARY_KEYS: [&str; 10] = [
    "scenario",
    "material",
    "time_to_failure_s",
    "failure_mode",
    "initial_leak_rate_m3_per_s",
    "final_leak_rate_m3_per_s",
    "leaked_volume_m3",
    "duration_s",
    "warnings",
    "material_status",
];

const YEAR: f64 = 365.25 * 86400.0;

/// Every scenario file shipped in `scenarios/` (recursively), not the figure sets.
fn shipped_scenarios() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "toml")
                && !path.to_string_lossy().ends_with("-figures.toml")
                && is_scenario(&path)
            {
                out.push(path);
            }
        }
    }
    // a scenario has a [seal]; a study (`base = …`) or a material file (one [material] table,
    // e.g. the lab-data tutorial's fit) has none
    fn is_scenario(path: &Path) -> bool {
        let table: toml::Table = fs::read_to_string(path).unwrap().parse().unwrap();
        table.contains_key("seal") && !table.contains_key("base")
    }
    let mut out = Vec::new();
    walk(&scenarios_dir(), &mut out);
    out.sort();
    out
}

/// The data rows of a CSV text (quoted cells unquoted).
fn csv_rows(text: &str) -> Vec<Vec<String>> {
    csv::Reader::from_reader(text.as_bytes())
        .records()
        .map(|r| r.unwrap().iter().map(str::to_owned).collect())
        .collect()
}

/// The outputs of one `run` in a temporary directory.
struct Outputs {
    dir: TempDir,
}

impl Outputs {
    fn new() -> Self {
        Outputs {
            dir: tempfile::tempdir().unwrap(),
        }
    }
    fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }
    fn write(&self, name: &str, text: &str) -> PathBuf {
        let p = self.path(name);
        fs::write(&p, text).unwrap();
        p
    }
    /// The command `run SCENARIO -o h.csv --summary s.json --plot p.svg <extra>`.
    fn run_cmd(&self, scenario: &Path, extra: &[&str]) -> assert_cmd::Command {
        let mut cmd = cargo_bin_cmd!("sealsim");
        cmd.arg("run")
            .arg(scenario)
            .arg("--verbose")
            .arg("-o")
            .arg(self.path("h.csv"))
            .arg("--summary")
            .arg(self.path("s.json"))
            .arg("--plot")
            .arg(self.path("p.svg"))
            .args(extra);
        cmd
    }

    /// `run SCENARIO -o h.csv --summary s.json --plot p.svg <extra>` → (stdout, stderr),
    /// expecting success.
    fn run_ok(&self, scenario: &Path, extra: &[&str]) -> (String, String) {
        let out = self.run_cmd(scenario, extra).assert().success();
        let o = out.get_output();
        (
            String::from_utf8(o.stdout.clone()).unwrap(),
            String::from_utf8(o.stderr.clone()).unwrap(),
        )
    }
    fn summary(&self) -> Value {
        let text = fs::read_to_string(self.path("s.json")).unwrap();
        no_nan(&text, "summary JSON");
        serde_json::from_str(&text).unwrap()
    }
    /// `run` expecting exit 2 with every needle in stderr, and no output file.
    fn run_rejects(&self, scenario: &Path, extra: &[&str], needles: &[&str]) {
        let out = self
            .run_cmd(scenario, extra)
            .assert()
            .code(2)
            .stdout(predicate::str::is_empty())
            .stderr(predicate::str::contains("panicked").not());
        let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
        assert!(stderr.starts_with("error: "), "{stderr}");
        for needle in needles {
            assert!(
                stderr.contains(needle),
                "stderr lacks {needle:?}:\n{stderr}"
            );
        }
        for f in ["h.csv", "s.json", "p.svg"] {
            assert!(!self.path(f).exists(), "{f} was written");
        }
    }
}

#[test]
fn every_shipped_scenario_runs_without_nan() {
    let scenarios = shipped_scenarios();
    assert!(scenarios.len() >= 15, "{scenarios:?}");
    for scenario in scenarios {
        let out = Outputs::new();
        let (stdout, stderr) = out.run_ok(&scenario, &[]);
        let name = scenario.display().to_string();
        no_nan(&stdout, &name);
        assert!(stdout.contains("result"), "{name}: {stdout}");
        assert!(
            stderr
                .lines()
                .all(|l| l.starts_with("warning[W") || l.starts_with("note[N")),
            "{name}: {stderr}"
        );
        let csv = fs::read_to_string(out.path("h.csv")).unwrap();
        no_nan(&csv, &name);
        let mut lines = csv.lines();
        // a scenario with [motion] has the drag column (and a stroke cycle's net volume) after
        // the static columns
        let header = lines.next().unwrap();
        // (and a rod seal's films and speed regime)
        let extra = match [
            "",
            ",drag_leak_rate_m3_per_s",
            ",drag_leak_rate_m3_per_s,net_volume_per_cycle_m3,out_stroke_film_m,\
             in_stroke_film_m,speed_regime",
            // a gas: its throughput and its permeation through the rubber
            ",throughput_Pa_m3_per_s,permeation_Pa_m3_per_s,permeation_basis",
        ]
        .iter()
        .position(|e| header == format!("{HISTORY_HEADER}{e}"))
        .unwrap_or_else(|| panic!("{name}: header {header}"))
        {
            2 => 5,
            3 => 3,
            k => k,
        };
        let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
        assert!(rows.len() > 100, "{name}: {} rows", rows.len());
        assert_eq!(
            rows[0][0], "0e0",
            "{name}: the installation row comes first"
        );
        for row in &rows {
            assert_eq!(row.len(), 15 + extra, "{name}: {row:?}");
            // compression set: blank without [ageing], a fraction of the squeeze as fitted with
            // it (above 1 when the service temperature squeezes the ring harder than fitted,
            // docs/model.md §6.5: the shipped rings by at most 6 %)
            if !row[13].is_empty() {
                let set: f64 = row[13].parse().unwrap();
                assert!((0.0..=1.1).contains(&set), "{name}: compression set {set}");
            }
            // the set ring's squeeze at shutdown: blank where the check does not apply
            if !row[14].is_empty() {
                let squeeze: f64 = row[14].parse().unwrap();
                assert!(
                    (0.0..1.0).contains(&squeeze),
                    "{name}: shutdown squeeze {squeeze}"
                );
            }
            for cell in &row[15..] {
                let regime = ["low_speed", "transition", "inverse_hydrodynamic"];
                // a gas's permeation basis
                let basis = ["published", "illustrative", "bound", "user"];
                let blank_film = cell.is_empty() || *cell == "low_speed_no_profile";
                assert!(
                    regime.contains(cell)
                        || basis.contains(cell)
                        || blank_film
                        || cell.parse::<f64>().unwrap().is_finite(),
                    "{name}: {cell}"
                );
            }
            let f: f64 = row[12].parse().unwrap();
            assert!((0.0..=1.0).contains(&f), "{name}: open fraction {f}");
            for (i, cell) in row[..11].iter().enumerate() {
                if cell.is_empty() {
                    assert!(i == 3 || i == 8, "{name}: empty column {i}");
                } else {
                    assert!(cell.parse::<f64>().unwrap().is_finite(), "{name}: {cell}");
                }
            }
            assert!(
                ["leaking", "sealed", "pressure_held", "lift_off"].contains(&row[11]),
                "{name}: {row:?}"
            );
        }
        let json = out.summary();
        for key in SUMMARY_KEYS {
            assert!(json.get(key).is_some(), "{name}: no {key} in {json}");
        }
        assert!(json["warnings"].is_array());
        let mode = json["failure_mode"].as_str().unwrap();
        assert!(
            [
                "leak_rate",
                "leaked_volume",
                "retained_force",
                "compression_set",
                "lift_off",
                "extrusion",
                "lost_interference",
                "sealing_force",
                "contact_pressure",
                "none"
            ]
            .contains(&mode),
            "{name}: {mode}"
        );
        assert_eq!(
            json["time_to_failure_s"].is_null(),
            mode == "none",
            "{name}"
        );
        // the chart is always written (force and temperature at least; a sealed seal's leak
        // rate lies on the floor)
        assert!(out.path("p.svg").exists(), "{name}");
    }
}

#[test]
fn shipped_life_scenarios_show_their_point() {
    let run = |name: &str| {
        let out = Outputs::new();
        let (stdout, _) = out.run_ok(&scenarios_dir().join(name), &[]);
        (stdout, out.summary())
    };
    // the README's first command: an O-ring that ages, fails by its retained force within a
    // year, loses its interference at a 23 °C shutdown within two, and is held by the fluid
    // pressure alone — never leaking — once its squeeze has relaxed away
    let (stdout, nbr) = run("oring-nbr-water-80c.toml");
    assert!(stdout.contains("ILLUSTRATIVE"), "{stdout}");
    assert_eq!(nbr["failure_mode"], "retained_force");
    assert!(nbr["time_to_failure_s"].as_f64().unwrap() < YEAR);
    assert_eq!(nbr["final_leak_rate_m3_per_s"].as_f64(), Some(0.0));
    assert_eq!(nbr["final_state"], "pressure_held");
    let lost = nbr["shutdown"]["lost_s"].as_f64().unwrap();
    assert!((YEAR..2.0 * YEAR).contains(&lost), "{lost}");
    // ageing ends the FKM's life
    let (_, fkm) = run("oring-fkm-hot-oil-ageing.toml");
    assert_eq!(fkm["failure_mode"], "retained_force");
    // cold night: NBR fails (its shutdown at −40 °C, below T10, loses the glassy ring's
    // contact from the start; the night crosses its cold limit in the evening ramp), silicone
    // survives
    let (_, nbr) = run("cold-night-nbr.toml");
    let (_, vmq) = run("cold-night-vmq.toml");
    assert_eq!(nbr["failure_mode"], "lost_interference");
    assert_eq!(nbr["time_to_failure_s"].as_f64(), Some(0.0));
    let t = nbr["low_temperature"]["crossed_s"].as_f64().unwrap();
    assert!((30.0 * 3600.0..34.0 * 3600.0).contains(&t), "{t}");
    assert_eq!(vmq["failure_mode"], "none");
    // the spring-loaded seal: the asperities creep under the held load, the leak rate falls
    let (_, spring) = run("spring-loaded-face-seal.toml");
    let (q0, q1) = (
        spring["initial_leak_rate_m3_per_s"].as_f64().unwrap(),
        spring["final_leak_rate_m3_per_s"].as_f64().unwrap(),
    );
    assert!(q1 < q0 / 3.0, "{q0} → {q1}");
}

/// A flat seal of a one-term Prony rubber: E(t) = E∞ + E1 e^(−t/τ), WLF at T_ref = 23 °C,
/// installed instantaneously, the retained force referred to the installation (`"0 s"`).
fn one_term(temperature: &str) -> String {
    one_term_referred(temperature, "0 s")
}

/// [`one_term`] with the retained force referred to `reference` after installation.
pub(crate) fn one_term_referred(temperature: &str, reference: &str) -> String {
    format!(
        r#"name = "one-term Prony"
[material]
poisson_ratio = 0.5
# next to none: the closed forms these runs are checked against have no thermal strain
thermal_expansion = "1e-8 1/K"
long_term_modulus = "2 MPa"
prony = [ {{ modulus = "6 MPa", tau = "1e5 s" }} ]
[material.shift]
kind = "wlf"
reference_temperature = "23 C"
c1 = 8.86
c2 = "101.6 K"
[surface]
rms_roughness = "1 um"
hurst_exponent = 0.8
q0 = "1e4 1/m"
q1 = "1e9 1/m"
[fluid]
viscosity = "1 mPa*s"
pressure_difference = "0.1 bar"
[seal]
nominal_pressure = "1 MPa"
width = "1 mm"
length = "0.1 m"
installation_time = "0 s"
[environment]
temperature = "{temperature}"
[failure]
min_retained_force = 0.5
retained_force_reference = "{reference}"
"#
    )
}

#[test]
fn one_term_prony_fails_at_the_closed_form_time() {
    // referred to 30 min (the default), then to 0.5 and 1 day: E(t) = r E(t_ref) ⇔
    // t = τ ln(E1 / (r E(t_ref) − E∞)) (a_T = 1 at 23 °C); then "0 s", below
    let (e_inf, e1, tau): (f64, f64, f64) = (2e6, 6e6, 1e5);
    for (reference, t_ref) in [
        ("30 min", 1800.0_f64),
        ("0.5 day", 43200.0),
        ("1 day", 86400.0),
    ] {
        let out = Outputs::new();
        let scenario = out.write("one.toml", &one_term_referred("23 C", reference));
        out.run_ok(&scenario, &[]);
        let json = out.summary();
        let e_ref = e_inf + e1 * (-t_ref / tau).exp();
        let closed = tau * (e1 / (0.5 * e_ref - e_inf)).ln();
        let t = json["time_to_failure_s"].as_f64().unwrap();
        assert!(
            (t / closed - 1.0).abs() < 1e-6,
            "{reference}: {t} vs {closed}"
        );
        let f_ref = json["reference_sealing_force_N_per_m"].as_f64().unwrap();
        let f0 = json["initial_sealing_force_N_per_m"].as_f64().unwrap();
        assert!(
            (f_ref / f0 - e_ref / (e_inf + e1)).abs() < 1e-12,
            "{reference}"
        );
    }
    // "0 s": the installation's force, E(t) = 0.5 E0 ⇔ t = τ ln(E1 / (0.5 E0 − E∞)) = 1e5 ln 3
    let closed = 1e5 * 3f64.ln();
    let out = Outputs::new();
    let scenario = out.write("one.toml", &one_term("23 C"));
    out.run_ok(&scenario, &[]);
    let json = out.summary();
    assert_eq!(json["failure_mode"], "retained_force");
    let t = json["time_to_failure_s"].as_f64().unwrap();
    assert!((t / closed - 1.0).abs() < 1e-6, "{t} vs {closed}");
    // 20 K hotter: a_T times sooner
    let hot = out.write("hot.toml", &one_term("43 C"));
    out.run_ok(&hot, &[]);
    let a_t = 10f64.powf(-8.86 * 20.0 / (101.6 + 20.0));
    let t = out.summary()["time_to_failure_s"].as_f64().unwrap();
    assert!(
        (t / (a_t * closed) - 1.0).abs() < 1e-6,
        "{t} vs {}",
        a_t * closed
    );
}

#[test]
fn summary_on_stdout_is_readable() {
    let out = Outputs::new();
    let scenario = out.write("one.toml", &one_term("23 C"));
    let (stdout, _) = out.run_ok(&scenario, &[]);
    for needle in [
        "scenario       one-term Prony",
        "material       one-term Prony [user]",
        "flat, P0 = 1 MPa",
        "23 °C (constant)",
        "leak rate",
        "FAILS after 30.5 h (t = 109861 s)",
        "by retained_force",
    ] {
        assert!(stdout.contains(needle), "{needle:?} not in\n{stdout}");
    }
    assert!(!stdout.contains("ILLUSTRATIVE"));
    // without -o, only the summary is produced
    let bare = Outputs::new();
    let scenario = bare.write("one.toml", &one_term("23 C"));
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&scenario)
        .current_dir(bare.dir.path())
        .assert()
        .success()
        .stdout(predicate::str::contains("leaked volume"));
    let mut names: Vec<_> = fs::read_dir(bare.dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    names.sort();
    assert_eq!(names, ["one.toml"]);
}

#[test]
fn fidelity_flag_overrides_the_scenario() {
    let scenario = scenarios_dir().join("oring-nbr-water-80c.toml");
    let table = Outputs::new();
    table.run_ok(&scenario, &["--fidelity", "critical-junction"]);
    let exact = Outputs::new();
    exact.run_ok(&scenario, &["--fidelity", "exact"]);
    let (a, b) = (table.summary(), exact.summary());
    assert_eq!(b["fidelity"], "exact");
    let (ta, tb) = (
        a["time_to_failure_s"].as_f64().unwrap(),
        b["time_to_failure_s"].as_f64().unwrap(),
    );
    assert!((ta / tb - 1.0).abs() < 1e-2, "{ta} vs {tb}");
}

#[test]
fn failure_block_without_criterion_warns_and_survives() {
    let out = Outputs::new();
    // lift-off is a criterion unless waived: waived, and no other, the seal can only survive
    // (and the shutdown check of the bolted gasket switched off)
    let text = one_term("23 C").replace(
        "min_retained_force = 0.5\n",
        "lift_off = false\nlost_interference = false\n",
    );
    let scenario = out.write("none.toml", &text);
    let (stdout, stderr) = out.run_ok(&scenario, &[]);
    assert!(
        stderr.contains("]: the [failure] block sets no criterion: the seal can only survive"),
        "{stderr}"
    );
    assert!(
        stdout.contains("survives 30 years (no failure criterion set); sealed (no percolating channel) at the end"),
        "{stdout}"
    );
    let json = out.summary();
    assert!(json["time_to_failure_s"].is_null());
    assert_eq!(json["failure_mode"], "none");
    assert_eq!(json["warnings"][0]["id"], "no_failure_criterion");
    assert!(json["warnings"][0]["value"].is_null());
    assert!(
        json["warnings"][0]["message"]
            .as_str()
            .unwrap()
            .contains("no criterion")
    );
}

/// The NBR O-ring scenario with `from` replaced by `to`, written to a temporary directory.
fn nbr_with(out: &Outputs, from: &str, to: &str) -> PathBuf {
    let text = fs::read_to_string(scenarios_dir().join("oring-nbr-water-80c.toml")).unwrap();
    assert!(text.contains(from), "{from}");
    out.write("s.toml", &text.replacen(from, to, 1))
}

#[test]
fn bad_scenarios_exit_2_and_write_nothing() {
    let cases: [(&str, &str, &[&str]); 7] = [
        (
            "library = \"nbr-70\"",
            "library = \"nbr-99\"",
            &[
                "s.toml:15: material.library: unknown library material \"nbr-99\"; the library has: acm-70, cr-70, epdm-70",
            ],
        ),
        (
            "duration = \"30 year\"",
            "duration = \"1 s\"",
            &["s.toml:47: simulation.duration: duration (1 s) must exceed start (1 s)"],
        ),
        (
            "groove_depth = \"2.65 mm\"",
            "groove_depth = \"4 mm\"",
            &["s.toml:31: seal.groove_depth: groove deeper than the cross-section"],
        ),
        (
            "fidelity = \"critical-junction\"",
            "fidelity = \"fast\"",
            &[
                "s.toml:49: simulation.fidelity: must be one of \"rule-of-thumb\", \"critical-junction\"",
            ],
        ),
        (
            "\n[ageing]",
            "\n[ageing]\ncrosslinking = 20 #",
            &["s.toml:52: ageing.crosslinking: "],
        ),
        (
            "library = \"nbr-70\"",
            "youngs_modulus = \"10 MPa\"\npoisson_ratio = 0.5",
            // fine: an elastic rubber; the next case adds the housing
            &[],
        ),
        (
            "loading = \"displacement\"",
            "loading = \"displacement\"\nhousing_expansion = \"12e-6 1/K\"",
            &[],
        ),
    ];
    for (from, to, needles) in &cases[..5] {
        let out = Outputs::new();
        let scenario = nbr_with(&out, from, to);
        out.run_rejects(&scenario, &[], needles);
    }
    // housing_expansion with a material that has no thermal_expansion
    let out = Outputs::new();
    let text = fs::read_to_string(scenarios_dir().join("oring-nbr-water-80c.toml"))
        .unwrap()
        .replacen(cases[5].0, cases[5].1, 1)
        .replacen(cases[6].0, cases[6].1, 1);
    let scenario = out.write("s.toml", &text);
    out.run_rejects(
        &scenario,
        &[],
        &["s.toml:37: seal.housing_expansion: the thermal strain needs the rubber's expansion too, but the material (NBR O-ring face seal, water at 80 °C) gives no thermal_expansion"],
    );
    // a groove-seated ring follows the temperature by default: the same material is refused
    let out = Outputs::new();
    let scenario = nbr_with(&out, cases[5].0, cases[5].1);
    out.run_rejects(
        &scenario,
        &[],
        &["s.toml:30: seal.gland: a groove-seated ring follows the temperature by default"],
    );
    // an unknown --fidelity
    let out = Outputs::new();
    let scenario = nbr_with(&out, "groove_depth", "groove_depth");
    out.run_rejects(
        &scenario,
        &["--fidelity", "fast"],
        &["invalid value 'fast'"],
    );
}

#[test]
fn malformed_temperature_histories_are_located() {
    let cases = [
        (
            "time,temperature\nh,C\n0,25\n10,warm\n",
            "T.csv:4: temperature is not a number: \"warm\" (temperature history named by environment.history at ",
        ),
        (
            "time,temperature\ns,K\n0,300\n100,290\n50,280\n",
            "T.csv:5: time must increase strictly from row to row, got 50 s after 100 s",
        ),
        // no units row: 20 could be 20 K or 20 °C
        ("time,temperature\n0,20\n", "T.csv:2: no units row"),
        ("time,temperature\nh,C\n", "T.csv: no data rows"),
        (
            "t,T\n0,300\n",
            "T.csv:1: expected the header row `time,temperature`",
        ),
    ];
    for (csv, needle) in cases {
        let out = Outputs::new();
        out.write("T.csv", csv);
        let scenario = nbr_with(&out, "temperature = \"80 C\"", "history = \"T.csv\"");
        out.run_rejects(&scenario, &[], &[needle, "s.toml:38)"]);
    }
    // more rows than the run-time budget (sealsim::scenario::life::MAX_HISTORY_ROWS): refused
    // at the first row over it, with the file's row count and the limit (exit 2)
    let limit = sealsim::scenario::life::MAX_HISTORY_ROWS;
    let mut csv = String::from("time,temperature\ns,C\n");
    for k in 0..limit + 10 {
        csv.push_str(&format!("{k},20\n"));
    }
    let out = Outputs::new();
    out.write("T.csv", &csv);
    let scenario = nbr_with(&out, "temperature = \"80 C\"", "history = \"T.csv\"");
    let line = format!(
        "T.csv:{}: {} data rows, more than the limit of {limit}",
        limit + 3,
        limit + 10
    );
    out.run_rejects(&scenario, &[], &[&line, "s.toml:38)"]);
    // a good one runs
    let out = Outputs::new();
    out.write("T.csv", "# ramp\ntime,temperature\nday,C\n0,20\n1,80\n");
    let scenario = nbr_with(&out, "temperature = \"80 C\"", "history = \"T.csv\"");
    out.run_ok(&scenario, &[]);
    let csv = fs::read_to_string(out.path("h.csv")).unwrap();
    // the temperature column of a row
    let temperature = |row: &str| -> f64 { row.split(',').nth(1).unwrap().parse().unwrap() };
    let first = temperature(csv.lines().nth(1).unwrap());
    // fitted at 23 °C (the gland's default, docs/model.md §5.2), then the history's 20 °C at
    // t = 0 onwards; the last row at the history's 80 °C
    assert!((first - 296.15).abs() < 1e-9, "{first}");
    let last = temperature(csv.lines().last().unwrap());
    assert!((last - 353.15).abs() < 1e-9, "{last}");
}

#[test]
fn compare_runs_each_compound() {
    let out = Outputs::new();
    // a material file by path works alongside library ids
    let file = out.write("soft.toml", crate::support::SOFT_MATERIAL);
    // the soft rubber has no ageing constants: the scenario without its [ageing]; on its ground
    // face (Ra 0.4 µm, rms slope 0.075) every compound seals (P_seal ≈ 0.262 E* h'_rms is far
    // below the ring's contact pressure), so the comparison of leak rates runs on the rough
    // face the scenario had before (0.8 µm rms, H 0.7, q1 1e10 1/m), which leaks
    let text = fs::read_to_string(scenarios_dir().join("oring-nbr-water-80c.toml")).unwrap();
    let text = crate::common::on_former_rough_face(&text);
    let scenario = out.write(
        "s.toml",
        &text.replace("\n[ageing]", "\n[ageing]\nenabled = false"),
    );
    let materials = format!("nbr-70,fkm-75,{}", file.display());
    let assert = cargo_bin_cmd!("sealsim")
        .arg("compare")
        .arg(&scenario)
        .args(["--materials", &materials, "-o"])
        .arg(out.path("c.csv"))
        .arg("--plot")
        .arg(out.path("c.svg"))
        .assert()
        .success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    no_nan(&stdout, "compare stdout");
    for id in ["nbr-70", "fkm-75", "soft.toml"] {
        assert!(stdout.contains(id), "{stdout}");
    }
    let csv = fs::read_to_string(out.path("c.csv")).unwrap();
    no_nan(&csv, "compare CSV");
    assert_eq!(csv.lines().next(), Some(COMPARE_HEADER));
    let rows = csv_rows(&csv);
    assert_eq!(rows.len(), 3);
    // ranked (issue 40): NBR (rated for water) first, the unrated file compound, FKM (rated X
    // for hot water) last
    assert_eq!(rows[0][0], "nbr-70");
    assert_eq!(rows[1][1], "soft test rubber");
    assert_eq!(rows[1][2], "user");
    assert!(rows[1][20].starts_with("not_rated"), "{rows:?}");
    assert_eq!(rows[2][0], "fkm-75");
    assert!(rows[2][20].starts_with("incompatible"), "{rows:?}");
    for row in &rows {
        assert_eq!(row.len(), 23);
        // the leak rates at 1 day, 1 year, 10 years, and the force at the end
        for cell in &row[5..9] {
            assert!(cell.parse::<f64>().unwrap() > 0.0, "{row:?}");
        }
        assert!(
            ["sealed", "leaking", "pressure_held", "lift_off"].contains(&row[13].as_str()),
            "{row:?}"
        );
    }
    // NBR as in `run`
    let run = Outputs::new();
    run.run_ok(&scenario, &[]);
    let t: f64 = rows[0][3].parse().unwrap();
    // the same number; serde_json's default parser may be 1 ulp off the written shortest form
    let from_run = run.summary()["time_to_failure_s"].as_f64().unwrap();
    assert!((t / from_run - 1.0).abs() < 1e-15, "{t} vs {from_run}");
    let svg = fs::read_to_string(out.path("c.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("fkm-75"));
}

#[test]
fn compare_leaves_leak_rates_beyond_the_duration_blank() {
    let out = Outputs::new();
    let scenario = nbr_with(&out, "duration = \"30 year\"", "duration = \"2 year\"");
    let assert = cargo_bin_cmd!("sealsim")
        .arg("compare")
        .arg(&scenario)
        .args(["--materials", "epdm-70", "-o"])
        .arg(out.path("c.csv"))
        .assert()
        .success();
    assert!(!assert.get_output().stdout.is_empty());
    let csv = fs::read_to_string(out.path("c.csv")).unwrap();
    let row = &csv_rows(&csv)[0];
    assert!(
        !row[5].is_empty() && !row[6].is_empty() && row[7].is_empty(),
        "{row:?}"
    );
}

#[test]
fn compare_rejects_unknown_ids() {
    let out = Outputs::new();
    let assert = cargo_bin_cmd!("sealsim")
        .arg("compare")
        .arg(scenarios_dir().join("oring-nbr-water-80c.toml"))
        .args(["--materials", "nbr-70,nbr-99", "-o"])
        .arg(out.path("c.csv"))
        .arg("--plot")
        .arg(out.path("c.svg"))
        .assert()
        .code(2)
        .stdout(predicate::str::is_empty());
    let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.starts_with("error: --materials: unknown library material \"nbr-99\"; the library has: acm-70, cr-70, epdm-70, ffkm-75, fkm-75, fvmq-70, hnbr-75, iir-70, nbr-70, vmq-70"),
        "{stderr}"
    );
    assert!(!out.path("c.csv").exists() && !out.path("c.svg").exists());
    // a compound without the ageing constants the scenario's [ageing] asks for runs without
    // them, and its row says so (a comparison degrades, it does not abort)
    // (every library compound carries ageing constants: a file compound without them)
    let scenario = nbr_with(&out, "[failure]", "[failure]");
    let soft = out.write("soft.toml", crate::support::SOFT_MATERIAL);
    let assert = cargo_bin_cmd!("sealsim")
        .arg("compare")
        .arg(&scenario)
        .args(["--materials", &format!("fkm-75,{}", soft.display())])
        .assert()
        .success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    let row = stdout.lines().find(|l| l.contains("soft")).unwrap();
    // the notes, then where the compound's Ea comes from (here: nowhere)
    assert!(
        row.contains("no ageing constants: run without ageing ")
            && row.ends_with("  no ageing constants"),
        "{stdout}"
    );
    // (rank, material, …: the table ranks the rows)
    let fkm = stdout
        .lines()
        .find(|l| l.split_whitespace().nth(1) == Some("fkm-75"))
        .unwrap();
    assert!(!fkm.contains("no ageing"), "{stdout}");
}

#[test]
fn leak_takes_the_central_strip_of_an_oring() {
    let assert = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(scenarios_dir().join("oring-nbr-water-80c.toml"))
        .assert()
        .success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    let p0: f64 = stdout
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    // Hertz peak of Lindley's force at 24.4 % squeeze with the modulus at the end of the 1 s
    // installation ramp at 80 °C (a_T = 1.4e-3: ≈ 4.6 MPa for nbr-70), plus k_e ΔP = 0.2 MPa
    assert!((1.5e6..2.0e6).contains(&p0), "{p0}");
}

/// `[contamination]` errors (issue 5): located, exit 2, nothing written.
#[test]
fn bad_contamination_exits_2() {
    let good = fs::read_to_string(scenarios_dir().join("gasket-nbr-dirty-oil.toml")).unwrap();
    let line = |needle: &str| good.lines().position(|l| l.contains(needle)).unwrap() + 1;
    let conc = line("number_concentration =");
    let sizes = line("size_distribution =");
    let lognormal = "{ kind = \"lognormal\", median = \"150 nm\", geometric_std = 2.5 }";
    let cases: Vec<(String, String, String)> = vec![
        (
            "\"5e10 1/m^3\"".into(),
            "\"-5e10 1/m^3\"".into(),
            format!("s.toml:{conc}: contamination.number_concentration: must not be negative"),
        ),
        (
            "geometric_std = 2.5".into(),
            "geometric_std = 1.0".into(),
            format!("s.toml:{sizes}: contamination.size_distribution.geometric_std: must exceed 1"),
        ),
        (
            lognormal.into(),
            "{ kind = \"weibull\", scale = \"1 um\", shape = 0 }".into(),
            format!("s.toml:{sizes}: contamination.size_distribution.shape: must be positive"),
        ),
        (
            lognormal.into(),
            "{ kind = \"table\", file = \"sizes.csv\" }".into(),
            format!("s.toml:{sizes}: contamination.size_distribution.file: "),
        ),
        (
            "number_concentration = \"5e10 1/m^3\"".into(),
            "number_concentration = \"5e10 1/m^3\"\nvolume_fraction = 1e-6".into(),
            "contamination.volume_fraction: number_concentration and volume_fraction are mutually exclusive".into(),
        ),
        (
            "number_concentration = \"5e10 1/m^3\"\n".into(),
            "".into(),
            "contamination.number_concentration: missing key".into(),
        ),
        (
            "capture = \"straining\"".into(),
            "capture = \"depth\"".into(),
            format!(
                "s.toml:{}: contamination.capture: must be \"straining\"",
                line("capture = \"straining\"")
            ),
        ),
    ];
    for (from, to, needle) in cases {
        let out = Outputs::new();
        // a size table that is not a CDF (F decreases)
        out.write("sizes.csv", "d,F\num,\n0.5,0.2\n1,0.1\n2,1\n");
        assert!(good.contains(&from), "{from}");
        let scenario = out.write("s.toml", &good.replacen(&from, &to, 1));
        out.run_rejects(&scenario, &[], &[&needle]);
        if to.contains("table") {
            let stderr_needle = "sizes.csv:4: not a CDF";
            out.run_rejects(&scenario, &[], &[stderr_needle]);
        }
    }
}

/// `capture` end to end (docs/model.md §7): without the key the law is `straining`, the same
/// history as the shipped file that names it; `sieving`, its sharp limit, runs too and moves the
/// result; both leak less than the clean twin and never more than it, row by row.
#[test]
fn capture_defaults_to_straining_and_sieving_runs() {
    let text = fs::read_to_string(scenarios_dir().join("gasket-nbr-dirty-oil.toml")).unwrap();
    let named = text
        .lines()
        .find(|l| l.starts_with("capture = "))
        .unwrap()
        .to_owned();
    assert!(named.starts_with("capture = \"straining\""), "{named}");
    let history = |text: &str| {
        let out = Outputs::new();
        let scenario = out.write("s.toml", text);
        out.run_ok(&scenario, &[]);
        (
            fs::read_to_string(out.path("h.csv")).unwrap(),
            out.summary(),
        )
    };
    let (shipped, shipped_summary) = history(&text);
    let (default, _) = history(&text.replace(&format!("{named}\n"), ""));
    assert_eq!(shipped, default, "no capture key is straining");
    let (sieve, sieve_summary) = history(&text.replace(&named, "capture = \"sieving\""));
    assert_ne!(shipped, sieve);
    let clean_text: String = {
        let mut skip = false;
        text.lines()
            .filter(|l| {
                if l.starts_with('[') {
                    skip = l.starts_with("[contamination");
                }
                !skip
            })
            .map(|l| format!("{l}\n"))
            .collect()
    };
    let (clean, clean_summary) = history(&clean_text);
    let volume = |s: &Value| s["leaked_volume_m3"].as_f64().unwrap();
    for (label, s) in [("straining", &shipped_summary), ("sieving", &sieve_summary)] {
        assert!(volume(s) < volume(&clean_summary), "{label}");
    }
    let rate =
        |h: &str| -> Vec<f64> { csv_rows(h).iter().map(|r| r[9].parse().unwrap()).collect() };
    for dirty in [&shipped, &sieve] {
        for (q, c) in rate(dirty).iter().zip(rate(&clean)) {
            assert!(*q <= c * (1.0 + 1e-12));
        }
    }
}

/// The clogging scenario's leak rate falls below that of its clean twin (the same scenario
/// without `[contamination]`); the open fraction is in the history and the summary. The shipped
/// clean-oil O-ring clogs nothing.
#[test]
fn clogging_scenario_against_its_clean_twin() {
    let out = Outputs::new();
    out.run_ok(
        &scenarios_dir().join("oring-nbr-hydraulic-oil-clean.toml"),
        &[],
    );
    assert_eq!(out.summary()["final_open_fraction"].as_f64(), Some(1.0));
    // the clean twin: the clogging scenario with its [contamination] table removed
    let dirty_text = fs::read_to_string(scenarios_dir().join("gasket-nbr-dirty-oil.toml")).unwrap();
    let mut clean_text = String::new();
    let mut skip = false;
    for l in dirty_text.lines() {
        if l.starts_with('[') {
            skip = l.starts_with("[contamination");
        }
        if !skip {
            clean_text += l;
            clean_text.push('\n');
        }
    }
    assert_ne!(clean_text, dirty_text, "no [contamination] table found");
    let twin = out.write("twin.toml", &clean_text);
    out.run_ok(&twin, &[]);
    let clean = out.summary();
    let clean_history = fs::read_to_string(out.path("h.csv")).unwrap();
    assert_eq!(clean["final_open_fraction"].as_f64(), Some(1.0));
    assert!(clean["final_leak_rate_m3_per_s"].as_f64().unwrap() > 0.0);
    out.run_ok(&scenarios_dir().join("gasket-nbr-dirty-oil.toml"), &[]);
    let dirty = out.summary();
    let f = dirty["final_open_fraction"].as_f64().unwrap();
    assert!(f > 0.0 && f < 0.9, "{f}");
    assert!(
        dirty["final_leak_rate_m3_per_s"].as_f64().unwrap()
            < 0.01 * clean["final_leak_rate_m3_per_s"].as_f64().unwrap()
    );
    let history = fs::read_to_string(out.path("h.csv")).unwrap();
    assert!(history.starts_with(HISTORY_HEADER));
    // issue 17, row by row against the clean twin's history (the same time grid): the open
    // fraction never rises and the leak stays within f Q̇_open ≤ Q̇ ≤ Q̇_open, the lower bound
    // loosened by the entry cake's series term (< 1e-3 here)
    let column = |text: &str, name: &str| -> Vec<f64> {
        let mut lines = text.lines();
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let k = header.iter().position(|h| *h == name).unwrap();
        lines
            .map(|l| l.split(',').nth(k).unwrap().parse().unwrap())
            .collect()
    };
    let dirty_q = column(&history, "leak_rate_m3_per_s");
    let f = column(&history, "open_fraction");
    let clean_q = column(&clean_history, "leak_rate_m3_per_s");
    assert_eq!(clean_q.len(), dirty_q.len());
    for i in 0..f.len() {
        assert!(i == 0 || f[i] <= f[i - 1], "row {i}: f rises");
        assert!(dirty_q[i] <= clean_q[i] * (1.0 + 1e-9), "row {i}");
        assert!(dirty_q[i] >= f[i] * clean_q[i] * (1.0 - 1e-3), "row {i}");
    }
    assert!(f[f.len() - 1] < 0.5, "clogging acts within the run");
}
