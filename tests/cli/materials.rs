//! End-to-end tests of `sealsim materials` (list, show, curve, export) and of viscoelastic
//! scenario materials in `sealsim leak`. Expected values are computed here from the Prony terms
//! and shift constants read through the public `sealsim::scenario` API, never copied from the
//! program's output.

use crate::common::PAPER;
use crate::support::sealsim;
use predicates::prelude::*;
use sealsim::material::{Material, Shift};
use sealsim::scenario::{library, load_material_file};
use std::fs;
use std::path::{Path, PathBuf};
use tempfile::TempDir;

const CURVE_HEADER: &str = "time_s,reduced_time_s,relaxation_modulus_Pa,creep_compliance_per_Pa,\
                            angular_frequency_rad_per_s,storage_modulus_Pa,loss_modulus_Pa,tan_delta";

/// The issue's single-term test rubber as a library-format file.
const TEST_RUBBER: &str = r#"[material]
name = "single-term test rubber"
status = "illustrative"
poisson_ratio = 0.5
long_term_modulus = "4 MPa"
prony = [ { modulus = "6 MPa", tau = "1000 h" } ]
[material.shift]
kind = "wlf"
reference_temperature = "23 C"
c1 = 8.86
c2 = "101.6 K"
[material.provenance]
poisson_ratio = "test value: incompressible"
long_term_modulus = "test value: E_inf"
prony = "test value: one term"
shift = "test value: universal WLF constants"
"#;

/// Runs `sealsim <args>`, expects success, returns (stdout, stderr).
fn ok(args: &[&str]) -> (String, String) {
    let out = sealsim().args(args).assert().success();
    let o = out.get_output();
    (
        String::from_utf8(o.stdout.clone()).unwrap(),
        String::from_utf8(o.stderr.clone()).unwrap(),
    )
}

/// Runs `sealsim <args>`, expects exit status 2 and no panic; returns stderr.
fn rejected(args: &[&str]) -> String {
    let out = sealsim()
        .args(args)
        .assert()
        .code(2)
        .stderr(predicate::str::contains("panicked").not());
    String::from_utf8(out.get_output().stderr.clone()).unwrap()
}

struct Dir(TempDir);

impl Dir {
    fn new() -> Self {
        Dir(tempfile::tempdir().unwrap())
    }

    fn write(&self, name: &str, text: &str) -> PathBuf {
        let path = self.0.path().join(name);
        fs::write(&path, text).unwrap();
        path
    }

    fn path(&self, name: &str) -> PathBuf {
        self.0.path().join(name)
    }
}

fn s(path: &Path) -> &str {
    path.to_str().unwrap()
}

/// One parsed row of the curve CSV.
#[derive(Debug, Clone, Copy)]
struct Row {
    time: f64,
    reduced_time: f64,
    relaxation: f64,
    compliance: f64,
    omega: f64,
    storage: f64,
    loss: f64,
    tan_delta: f64,
}

fn parse_curve(text: &str) -> Vec<Row> {
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(CURVE_HEADER));
    lines
        .map(|line| {
            let v: Vec<f64> = line
                .split(',')
                .map(|c| c.parse::<f64>().unwrap_or_else(|_| panic!("{line}")))
                .collect();
            assert_eq!(v.len(), 8, "{line}");
            assert!(v.iter().all(|x| x.is_finite()), "{line}");
            Row {
                time: v[0],
                reduced_time: v[1],
                relaxation: v[2],
                compliance: v[3],
                omega: v[4],
                storage: v[5],
                loss: v[6],
                tan_delta: v[7],
            }
        })
        .collect()
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

/// E(t), E′(ω), E″(ω) from the series' terms, written out here independently of the library.
fn series_values(m: &Material, t: f64, omega: f64) -> (f64, f64, f64) {
    let e_inf = m.prony.long_term();
    let terms = m.prony.terms();
    let e = e_inf
        + terms
            .iter()
            .map(|p| p.modulus * (-t / p.tau).exp())
            .sum::<f64>();
    let storage = e_inf
        + terms
            .iter()
            .map(|p| {
                let w = omega * p.tau;
                p.modulus * w * w / (1.0 + w * w)
            })
            .sum::<f64>();
    let loss = terms
        .iter()
        .map(|p| {
            let w = omega * p.tau;
            p.modulus * w / (1.0 + w * w)
        })
        .sum::<f64>();
    (e, storage, loss)
}

/// WLF log10 a_T written out here: −C1 (T − Tref)/(C2 + T − Tref).
fn wlf_shift_factor(shift: Shift, t: f64) -> f64 {
    match shift {
        Shift::Wlf { reference, c1, c2 } => {
            10f64.powf(-c1 * (t - reference) / (c2 + t - reference))
        }
        other => panic!("not WLF: {other:?}"),
    }
}

#[test]
fn list_shows_every_library_compound() {
    let (out, _) = ok(&["materials", "list"]);
    let mut lines = out.lines();
    let header = lines.next().unwrap();
    for column in ["id", "name", "status", "E0 [MPa]", "E∞ [MPa]", "T_g [°C]"] {
        assert!(header.contains(column), "{header}");
    }
    let rows: Vec<&str> = lines.collect();
    let ids: Vec<&str> = library::ids().collect();
    assert_eq!(rows.len(), ids.len());
    for (row, id) in rows.iter().zip(&ids) {
        let m = library::get(id).unwrap().load().unwrap();
        assert!(row.starts_with(id), "{row}");
        assert!(
            row.contains(&m.name) && row.contains(m.status.as_str()),
            "{row}"
        );
        // E0 and E∞ in MPa, T_g and T10 in °C, to four significant digits
        let numbers: Vec<f64> = row
            .split_whitespace()
            .rev()
            .take(4)
            .filter_map(|c| c.parse().ok())
            .collect();
        assert!(
            close(numbers[3], m.prony.instantaneous() / 1e6, 1e-3),
            "{row}"
        );
        assert!(close(numbers[2], m.prony.long_term() / 1e6, 1e-3), "{row}");
        let t10 = m.low_temperature_limit().unwrap() - 273.15;
        assert!(close(numbers[0], t10, 1e-3), "{row}");
    }
}

#[test]
fn show_gives_every_parameter_with_units_and_provenance() {
    for id in library::ids() {
        let m = library::get(id).unwrap().load().unwrap();
        let (out, _) = ok(&["materials", "show", id]);
        assert!(out.starts_with(&format!("{id}: {}", m.name)), "{out}");
        assert!(out.contains(&format!("status: {}", m.status.as_str())));
        // the derived low-temperature limit, every library series reaching its glassy plateau
        assert!(out.contains("low_temperature     T10 = "), "{id}: {out}");
        for (key, source) in &m.provenance {
            assert!(out.contains(&format!("{key:<20}")), "{id}: {key} missing");
            assert!(
                out.contains(&format!("source: {source}")),
                "{id}: source of {key}"
            );
        }
        assert!(out.contains("MPa") && out.contains("tau [s]") && out.contains("E_i [MPa]"));
        // one line per Prony term
        let term_lines = out
            .lines()
            .filter(|l| {
                let cells: Vec<&str> = l.split_whitespace().collect();
                cells.len() == 4 && cells.iter().all(|c| c.parse::<f64>().is_ok())
            })
            .count();
        assert_eq!(term_lines, m.prony.terms().len(), "{id}");
        if m.glass_transition.is_some() {
            assert!(out.contains("T_g = ") && out.contains("°C"));
        }
        if m.ageing.is_some() {
            assert!(out.contains("kJ/mol") && out.contains("1/s"));
        }
    }
}

/// Issue 39.3 / 40.4: `materials show` prints where the ageing activation energy comes from,
/// and every gas figure the compound runs with, each with its source or "NOT SOURCED bound".
#[test]
fn show_gives_each_gas_figure_with_its_source_or_its_bound_and_the_ea_source() {
    let gases = [
        "helium",
        "hydrogen",
        "nitrogen",
        "oxygen",
        "air",
        "carbon-dioxide",
        "methane",
    ];
    for id in library::ids() {
        let m = library::get(id).unwrap().load().unwrap();
        let (out, _) = ok(&["materials", "show", id]);
        let source = m.ageing_basis.as_ref().unwrap().source.clone().unwrap();
        assert!(out.contains(&format!("Ea source: {source}")), "{id}: {out}");
        for gas in gases {
            let line = out
                .lines()
                .position(|l| l.trim_start().starts_with(&format!("{gas}: ")))
                .unwrap_or_else(|| panic!("{id}: {gas} missing: {out}"));
            let figure = out.lines().nth(line).unwrap();
            let basis = out.lines().nth(line + 1).unwrap().trim();
            assert!(figure.contains(" barrer"), "{id} {gas}: {figure}");
            assert!(
                ["sourced: ", "ILLUSTRATIVE", "NOT SOURCED bound: "]
                    .iter()
                    .any(|w| basis.starts_with(w)),
                "{id} {gas}: {basis}"
            );
        }
    }
    // the classes with no figure of their own say so for every gas; silicone's He is PDMS's
    let (ffkm, _) = ok(&["materials", "show", "ffkm-75"]);
    assert_eq!(ffkm.matches("NOT SOURCED bound").count(), 7, "{ffkm}");
    assert!(ffkm.contains("band about the anchor"), "{ffkm}");
    let (vmq, _) = ok(&["materials", "show", "vmq-70"]);
    assert!(vmq.contains("helium: 339 barrer"), "{vmq}");
    assert!(vmq.contains("He/N2 = 1.22"), "{vmq}");
}

#[test]
fn curve_at_the_reference_temperature_is_the_series() {
    let dir = Dir::new();
    let file = dir.write("rubber.toml", TEST_RUBBER);
    let m = load_material_file(&file).unwrap();
    let (out, err) = ok(&["materials", "curve", "--file", s(&file)]);
    assert!(err.is_empty(), "{err}");
    let rows = parse_curve(&out);
    // τ = 3.6e6 s widened by two decades each side, 10 points per decade
    assert_eq!(rows.len(), 41);
    assert!(close(rows[0].time, 3.6e4, 1e-12) && close(rows[40].time, 3.6e8, 1e-12));
    let creep_lambda = 3.6e6 * 10.0 / 4.0; // standard linear solid: λ = τ E0/E∞
    for r in &rows {
        assert_eq!(r.time, r.reduced_time);
        assert!(close(r.omega * r.time, 1.0, 1e-15));
        let (e, storage, loss) = series_values(&m, r.time, r.omega);
        assert!(close(r.relaxation, e, 1e-13), "{r:?} vs {e}");
        assert!(close(r.storage, storage, 1e-12), "{r:?} vs {storage}");
        assert!(close(r.loss, loss, 1e-12), "{r:?} vs {loss}");
        assert!(close(r.tan_delta, loss / storage, 1e-12));
        let j = 1.0 / 4e6 - (1.0 / 4e6 - 1.0 / 1e7) * (-r.time / creep_lambda).exp();
        assert!(close(r.compliance, j, 1e-12), "{r:?} vs {j}");
    }
    // the same through a library compound, checked on a few rows
    let nbr = library::get("nbr-70").unwrap().load().unwrap();
    let (out, _) = ok(&["materials", "curve", "nbr-70", "--points-per-decade", "3"]);
    let rows = parse_curve(&out);
    let (lo, hi) = (
        nbr.prony.terms()[0].tau,
        nbr.prony.terms().last().unwrap().tau,
    );
    assert!(close(rows[0].time, lo / 100.0, 1e-12));
    assert!(close(rows.last().unwrap().time, hi * 100.0, 1e-12));
    for r in rows.iter().step_by(7) {
        let (e, storage, loss) = series_values(&nbr, r.time, r.omega);
        assert!(close(r.relaxation, e, 1e-12), "{r:?}");
        assert!(
            close(r.storage, storage, 1e-12) && close(r.loss, loss, 1e-10),
            "{r:?}"
        );
    }
}

#[test]
fn curve_at_a_higher_temperature_is_shifted_by_a_t() {
    let dir = Dir::new();
    let file = dir.write("rubber.toml", TEST_RUBBER);
    let m = load_material_file(&file).unwrap();
    let (reference, _) = ok(&["materials", "curve", "--file", s(&file)]);
    let csv = dir.path("hot.csv");
    let svg = dir.path("hot.svg");
    let (out, err) = ok(&[
        "materials",
        "curve",
        "--file",
        s(&file),
        "--temperature",
        "80C",
        "-o",
        s(&csv),
        "--plot",
        s(&svg),
    ]);
    assert!(out.is_empty() && err.is_empty(), "{out}{err}");
    assert!(fs::read_to_string(&svg).unwrap().contains("<svg"));
    let a_t = wlf_shift_factor(m.shift, 353.15);
    assert!(a_t < 1e-3, "{a_t}");
    let (reference, hot) = (
        parse_curve(&reference),
        parse_curve(&fs::read_to_string(&csv).unwrap()),
    );
    assert_eq!(reference.len(), hot.len());
    for (r, h) in reference.iter().zip(&hot) {
        // same reduced time, physical time moved by exactly a_T, same moduli
        assert!(close(h.time, a_t * r.time, 1e-12), "{h:?} {r:?}");
        assert!(close(h.reduced_time, h.time / a_t, 1e-12));
        assert_eq!(h.relaxation, r.relaxation);
        assert_eq!(h.compliance, r.compliance);
        // E′(ω; T) = E′(ω a_T) at the reference temperature
        let (e, storage, loss) = series_values(&m, h.time / a_t, h.omega * a_t);
        assert!(close(h.relaxation, e, 1e-12));
        assert!(close(h.storage, storage, 1e-12) && close(h.loss, loss, 1e-12));
    }
    // colder than the reference: slower
    let (cold, _) = ok(&[
        "materials",
        "curve",
        "--file",
        s(&file),
        "--temperature",
        "0 C",
    ]);
    let cold = parse_curve(&cold);
    assert!(close(
        cold[0].time / reference[0].time,
        wlf_shift_factor(m.shift, 273.15),
        1e-12
    ));
}

#[test]
fn frozen_temperature_warns_and_gives_the_instantaneous_response() {
    let dir = Dir::new();
    let file = dir.write("rubber.toml", TEST_RUBBER);
    // Tref − C2 = 23 − 101.6 = −78.6 °C
    let (out, err) = ok(&[
        "materials",
        "curve",
        "--file",
        s(&file),
        "--temperature",
        "-100C",
    ]);
    assert!(
        err.starts_with("warning: ") && err.contains("frozen"),
        "{err}"
    );
    assert!(err.contains("-78.6 °C"), "{err}");
    let rows = parse_curve(&out);
    assert!(!rows.is_empty());
    for r in rows {
        assert_eq!((r.reduced_time, r.relaxation, r.storage), (0.0, 1e7, 1e7));
        assert_eq!((r.loss, r.tan_delta), (0.0, 0.0));
        assert!(close(r.compliance, 1e-7, 1e-15));
    }
    // at the frozen limit itself too
    let (out, err) = ok(&[
        "materials",
        "curve",
        "--file",
        s(&file),
        "--temperature",
        "194.55 K",
    ]);
    assert!(err.contains("frozen"), "{err}");
    assert!(parse_curve(&out).iter().all(|r| r.relaxation == 1e7));
}

/// The data lines of an Abaqus export.
struct Abaqus {
    /// (E0, ν) of `*ELASTIC`.
    elastic: (f64, f64),
    /// (g_i, k_i, τ_i) of `*VISCOELASTIC`.
    terms: Vec<[f64; 3]>,
    /// (T_ref, C1, C2) of `*TRS, DEFINITION=WLF`.
    trs: Option<[f64; 3]>,
}

fn parse_abaqus(text: &str) -> Abaqus {
    let numbers = |line: &str| -> Vec<f64> {
        line.split(',')
            .map(|c| c.trim().parse::<f64>().unwrap())
            .collect()
    };
    let lines: Vec<&str> = text.lines().filter(|l| !l.starts_with("**")).collect();
    let at = |keyword: &str| lines.iter().position(|l| l.starts_with(keyword));
    let elastic = numbers(lines[at("*ELASTIC, MODULI=INSTANTANEOUS").unwrap() + 1]);
    let start = at("*VISCOELASTIC, TIME=PRONY").unwrap() + 1;
    let terms = lines[start..]
        .iter()
        .take_while(|l| !l.starts_with('*'))
        .map(|l| {
            let v = numbers(l);
            [v[0], v[1], v[2]]
        })
        .collect();
    let trs = at("*TRS, DEFINITION=WLF").map(|i| {
        let v = numbers(lines[i + 1]);
        [v[0], v[1], v[2]]
    });
    Abaqus {
        elastic: (elastic[0], elastic[1]),
        terms,
        trs,
    }
}

#[test]
fn abaqus_export_is_relative_to_the_instantaneous_modulus() {
    for id in library::ids() {
        let m = library::get(id).unwrap().load().unwrap();
        let (out, _) = ok(&["materials", "export", id, "--format", "abaqus"]);
        assert!(out.contains("*MATERIAL, NAME="), "{out}");
        assert!(out.contains("** k_i = 0: no bulk relaxation"), "{out}");
        assert!(
            out.contains("Pa") && out.contains("reference temperature"),
            "{out}"
        );
        assert!(out.is_ascii());
        let Abaqus {
            elastic: (e0, nu),
            terms,
            trs,
        } = parse_abaqus(&out);
        assert_eq!(e0, m.prony.instantaneous());
        assert_eq!(nu, m.poisson_ratio);
        assert_eq!(terms.len(), m.prony.terms().len());
        let sum: f64 = terms.iter().map(|t| t[0]).sum();
        assert!(
            close(sum, 1.0 - m.prony.long_term() / e0, 1e-12),
            "{id}: Σ g = {sum}"
        );
        for (t, p) in terms.iter().zip(m.prony.terms()) {
            assert!(close(t[0], p.modulus / e0, 1e-15));
            assert_eq!((t[1], t[2]), (0.0, p.tau));
        }
        match (m.shift, trs) {
            (Shift::Wlf { reference, c1, c2 }, Some(trs)) => assert_eq!(trs, [reference, c1, c2]),
            (Shift::Wlf { .. }, None) => panic!("{id}: no *TRS"),
            (_, trs) => assert!(trs.is_none()),
        }
    }
}

#[test]
fn ansys_export_pairs_sum_correctly() {
    let dir = Dir::new();
    let file = dir.write("rubber.toml", TEST_RUBBER);
    let out_file = dir.path("rubber.mac");
    for (args, m) in [
        (
            vec!["--file", s(&file), "-o", s(&out_file)],
            load_material_file(&file).unwrap(),
        ),
        (
            vec!["nbr-70"],
            library::get("nbr-70").unwrap().load().unwrap(),
        ),
    ] {
        let mut all = vec!["materials", "export", "--format", "ansys"];
        all.extend(args.iter());
        let (stdout, _) = ok(&all);
        let text = if args.contains(&"-o") {
            assert!(stdout.is_empty());
            fs::read_to_string(&out_file).unwrap()
        } else {
            stdout
        };
        let e0 = m.prony.instantaneous();
        assert!(
            text.contains(&format!("MP,PRXY,1,{}", m.poisson_ratio)),
            "{text}"
        );
        let ex: f64 = text
            .lines()
            .find_map(|l| l.strip_prefix("MP,EX,1,"))
            .unwrap()
            .parse()
            .unwrap();
        assert_eq!(ex, e0);
        let n = m.prony.terms().len();
        let prony_at = text
            .lines()
            .position(|l| l == format!("TB,PRONY,1,,{n},SHEAR"))
            .unwrap_or_else(|| panic!("{text}"));
        // TBDATA lines with (a_i, τ_i) pairs, starting locations 1, 7, 13, ...
        let mut values = Vec::new();
        for (k, line) in text
            .lines()
            .skip(prony_at + 1)
            .take_while(|l| l.starts_with("TBDATA"))
            .enumerate()
        {
            let cells: Vec<&str> = line.split(',').collect();
            assert_eq!(cells[1], (1 + 6 * k).to_string(), "{line}");
            values.extend(cells[2..].iter().map(|c| c.parse::<f64>().unwrap()));
        }
        assert_eq!(values.len(), 2 * n);
        let sum: f64 = values.chunks(2).map(|p| p[0]).sum();
        assert!(
            close(sum, 1.0 - m.prony.long_term() / e0, 1e-12),
            "Σ a = {sum}"
        );
        for (pair, term) in values.chunks(2).zip(m.prony.terms()) {
            assert_eq!(pair[1], term.tau);
        }
        if let Shift::Wlf { reference, c1, c2 } = m.shift {
            let at = text.lines().position(|l| l == "TB,SHIFT,1,,3").unwrap();
            let line = text.lines().nth(at + 1).unwrap();
            assert_eq!(line, format!("TBDATA,1,{reference},{c1},{c2}"));
        }
    }
}

#[test]
fn bad_materials_exit_2_and_write_nothing() {
    let dir = Dir::new();
    let out = dir.path("out.csv");
    let svg = dir.path("out.svg");
    let err = rejected(&["materials", "curve", "nbr-99", "-o", s(&out)]);
    assert!(err.contains("unknown library material \"nbr-99\""), "{err}");
    for id in library::ids() {
        assert!(err.contains(id), "{err}");
    }
    assert!(!out.exists());
    let err = rejected(&["materials", "show", "nbr-99"]);
    assert!(err.contains("the library has: "), "{err}");
    let cases = [
        (
            "tau = \"1000 h\"",
            "tau = \"-1 s\"",
            "rubber.toml:6: material.prony[0].tau: must be positive, got -1 s",
        ),
        (
            "modulus = \"6 MPa\"",
            "modulus = 0",
            "rubber.toml:6: material.prony[0].modulus: must be positive, got 0 Pa",
        ),
        (
            "modulus = \"6 MPa\"",
            "modulus = \"-6 MPa\"",
            "rubber.toml:6: material.prony[0].modulus: must be positive",
        ),
        (
            "long_term_modulus = \"4 MPa\"",
            "long_term_modulus = \"-4 MPa\"",
            "rubber.toml:5: material.long_term_modulus: must not be negative",
        ),
        (
            "c2 = \"101.6 K\"",
            "c2 = 0",
            "rubber.toml:11: material.shift.c2: must be positive, got 0 K",
        ),
        (
            "c2 = \"101.6 K\"",
            "c2 = \"-5 K\"",
            "rubber.toml:11: material.shift.c2: must be positive, got -5 K",
        ),
        (
            "shift = \"test value: universal WLF constants\"\n",
            "",
            "rubber.toml:7: material.shift: missing provenance",
        ),
    ];
    for (from, to, expected) in cases {
        let file = dir.write("rubber.toml", &TEST_RUBBER.replacen(from, to, 1));
        for command in [
            vec![
                "materials",
                "curve",
                "--file",
                s(&file),
                "-o",
                s(&out),
                "--plot",
                s(&svg),
            ],
            vec![
                "materials",
                "export",
                "--file",
                s(&file),
                "--format",
                "abaqus",
                "-o",
                s(&out),
            ],
            vec!["materials", "show", "--file", s(&file)],
        ] {
            let err = rejected(&command);
            assert!(
                err.starts_with("error: ") && err.contains(expected),
                "{to}: {err}"
            );
            assert!(!out.exists());
            assert!(!svg.exists());
        }
    }
    // flags
    for args in [
        vec!["materials", "curve", "nbr-70", "--temperature", "80 m"],
        vec!["materials", "curve", "nbr-70", "--temperature", "-300 C"],
        vec!["materials", "curve", "nbr-70", "--points-per-decade", "0"],
        vec!["materials", "export", "nbr-70", "--format", "nastran"],
        vec!["materials", "export", "nbr-70"],
        vec!["materials", "show"],
        vec!["materials", "show", "nbr-70", "--file", "x.toml"],
        vec!["materials", "show", "--file", "/nowhere/x.toml"],
    ] {
        rejected(&args);
    }
}

#[test]
fn user_material_files_work_by_path() {
    // what `sealsim fit-prony` writes: no status, provenance only where known
    let dir = Dir::new();
    let file = dir.write(
        "fitted.toml",
        "[material]\npoisson_ratio = 0.4995\nlong_term_modulus = \"1.5 MPa\"\n\
         prony = [ { modulus = \"2 MPa\", tau = \"0.1 s\" }, { modulus = \"1 MPa\", tau = \"1e3 s\" } ]\n\
         [material.provenance]\nprony = \"NNLS fit to relaxation.csv\"\n",
    );
    let (out, _) = ok(&["materials", "show", "--file", s(&file)]);
    assert!(out.starts_with("fitted: fitted\nstatus: user"), "{out}");
    assert!(
        out.contains("source: NNLS fit to relaxation.csv") && out.contains("source: (none given)")
    );
    let (out, _) = ok(&[
        "materials",
        "export",
        "--file",
        s(&file),
        "--format",
        "abaqus",
    ]);
    let Abaqus {
        elastic,
        terms,
        trs,
    } = parse_abaqus(&out);
    assert_eq!(elastic, (4.5e6, 0.4995));
    assert_eq!(
        terms,
        vec![[2e6 / 4.5e6, 0.0, 0.1], [1e6 / 4.5e6, 0.0, 1e3]]
    );
    assert!(trs.is_none() && out.contains("no time-temperature shift"));
    let (out, err) = ok(&[
        "materials",
        "curve",
        "--file",
        s(&file),
        "--temperature",
        "80C",
    ]);
    assert!(err.contains("no time–temperature shift"), "{err}");
    // τ from 0.1 s to 1e3 s, widened to 1e-3 s .. 1e5 s: 8 decades, 10 points each
    assert_eq!(parse_curve(&out).len(), 81);
}

/// The paper scenario with its `[material]` table replaced.
fn paper_with_material(material: &str) -> String {
    PAPER.replace(
        "[material]\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.5\n",
        material,
    )
}

#[test]
fn leak_takes_the_installed_asperity_modulus_of_a_viscoelastic_material() {
    // the static problem's E is the asperity modulus of the installed state: with `relaxed` E∞;
    // with `follow` (the default) the modulus at the end of the 1 s installation ramp — either
    // way the same leak as an elastic rubber of that modulus
    let dir = Dir::new();
    let elastic = dir.write(
        "elastic.toml",
        &paper_with_material("[material]\nyoungs_modulus = \"4 MPa\"\npoisson_ratio = 0.5\n"),
    );
    let rubber = "[material]\nname = \"inline test rubber\"\npoisson_ratio = 0.5\n\
             long_term_modulus = \"4 MPa\"\nprony = [ { modulus = \"6 MPa\", tau = \"1000 h\" } ]\n\
             [material.shift]\nkind = \"wlf\"\nreference_temperature = \"23 C\"\nc1 = 8.86\n\
             c2 = \"101.6 K\"\n";
    let viscoelastic = dir.write(
        "viscoelastic.toml",
        &paper_with_material(&rubber.replace(
            "poisson_ratio = 0.5\n",
            "poisson_ratio = 0.5\nasperity_modulus = \"relaxed\"\n",
        )),
    );
    let following = dir.write("following.toml", &paper_with_material(rubber));
    let sweep = ["--sweep", "0.05MPa..1MPa", "--points", "7"];
    let run = |path: &Path| {
        let mut args = vec!["leak", s(path)];
        args.extend(sweep);
        ok(&args).0
    };
    let (a, b) = (run(&elastic), run(&viscoelastic));
    assert_eq!(a, b);
    assert_eq!(a.lines().count(), 8);
    let elastic_at = |name: &str, e: f64, nu: f64| {
        dir.write(
            name,
            &paper_with_material(&format!(
                "[material]\nyoungs_modulus = \"{e:e} Pa\"\npoisson_ratio = {nu:e}\n"
            )),
        )
    };
    let installed = |path: &Path| {
        sealsim::scenario::Scenario::load(path)
            .unwrap()
            .life
            .installed_asperity_modulus()
    };
    // follow: E∞ + E1 τ (1 − e^{−1 s/τ})/1 s
    let e = installed(&following);
    let tau: f64 = 3.6e6;
    assert!((e / (4e6 + 6e6 * tau * -(-1.0 / tau).exp_m1()) - 1.0).abs() < 1e-12);
    assert_eq!(run(&following), run(&elastic_at("f.toml", e, 0.5)));
    // a library compound: the same as an elastic rubber with its installed modulus and ν, or
    // with E∞ under `relaxed`
    let nbr = library::get("nbr-70").unwrap().load().unwrap();
    let by_id = dir.write(
        "nbr.toml",
        &paper_with_material("[material]\nlibrary = \"nbr-70\"\n"),
    );
    let e = installed(&by_id);
    assert_eq!(
        run(&by_id),
        run(&elastic_at("nbr-elastic.toml", e, nbr.poisson_ratio))
    );
    let relaxed = dir.write(
        "nbr-relaxed.toml",
        &paper_with_material("[material]\nlibrary = \"nbr-70\"\nasperity_modulus = \"relaxed\"\n"),
    );
    assert_eq!(
        run(&relaxed),
        run(&elastic_at(
            "nbr-e-inf.toml",
            nbr.prony.long_term(),
            nbr.poisson_ratio
        ))
    );
    // E∞ = 0 cannot give a static leak problem
    let fluid = dir.write(
        "fluid.toml",
        &paper_with_material(
            "[material]\npoisson_ratio = 0.5\nlong_term_modulus = 0\n\
             prony = [ { modulus = \"6 MPa\", tau = \"1000 h\" } ]\n",
        ),
    );
    let out = dir.path("leak.csv");
    let err = rejected(&["leak", s(&fluid), "-o", s(&out)]);
    assert!(
        err.contains("fluid.toml:4: material.long_term_modulus: no relaxed modulus"),
        "{err}"
    );
    assert!(!out.exists());
    let unknown = dir.write(
        "unknown.toml",
        &paper_with_material("[material]\nlibrary = \"nope\"\n"),
    );
    let err = rejected(&["leak", s(&unknown)]);
    assert!(
        err.contains("unknown.toml:3: material.library: unknown library material \"nope\""),
        "{err}"
    );
}

/// Issue 31: `materials check` prints every compound beside its class's published figures and
/// passes them all (T10 within ±5 K of the low-temperature limit, 500–2000 h to 50 % chemical
/// force loss at the rated temperature; the same checks are unit tests of the library).
#[test]
fn materials_check_prints_every_compound_beside_the_published_figures() {
    let out = crate::support::sealsim()
        .args(["materials", "check"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    for id in ["cr-70", "epdm-70", "fkm-75", "hnbr-75", "nbr-70", "vmq-70"] {
        let row = text.lines().find(|l| l.starts_with(id)).unwrap();
        assert_eq!(row.matches(" ok ").count(), 2, "{row}");
        assert!(row.contains("Bode Seal"), "{row}");
    }
    assert!(text.contains("1,000 hours continuous service"), "{text}");
}

/// `sealsim compare` on `scenario` (the headline ring edited by `edits`) with `materials`:
/// (stdout, the CSV rows by compound id).
fn compare_rows(edits: &[(&str, &str)], materials: &str) -> Vec<(String, Vec<String>)> {
    let dir = tempfile::tempdir().unwrap();
    let mut text = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml"),
    )
    .unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replacen(from, to, 1);
    }
    let scenario = dir.path().join("s.toml");
    fs::write(&scenario, text).unwrap();
    let (_, _, rows) = crate::support::compare_csv(&scenario, materials);
    rows.into_iter().map(|r| (r[0].clone(), r)).collect()
}

/// Issue 31: the rankings field practice makes. In 80 °C water and in 110 °C glycol coolant
/// standard FKM is flagged not recommended and EPDM recommended (docs/model.md §6.8); in 120 °C
/// mineral oil HNBR outlives NBR by more than 3× (ageing calibrated to the rated temperatures,
/// §6.7) and EPDM is flagged.
#[test]
fn compare_flags_fkm_in_hot_water_and_coolant_and_hnbr_outlives_nbr_in_hot_oil() {
    let notes = |rows: &[(String, Vec<String>)], id: &str| {
        rows.iter()
            .find(|(k, _)| k == id)
            // the notes column; the compound's Ea source and the four rank columns follow it
            .map(|(_, r)| r[r.len() - 6].clone())
            .unwrap()
    };
    let water = compare_rows(&[], "fkm-75,epdm-70");
    let glycol = compare_rows(
        &[
            (
                "library = \"water\"",
                "library = \"ethylene-glycol-water-50\"",
            ),
            ("temperature = \"80 C\"", "temperature = \"110 C\""),
        ],
        "fkm-75,epdm-70",
    );
    for rows in [&water, &glycol] {
        assert!(
            notes(rows, "fkm-75").starts_with("NOT RECOMMENDED in hot water"),
            "{rows:?}"
        );
        assert!(
            notes(rows, "epdm-70").starts_with("recommended in hot water"),
            "{rows:?}"
        );
    }
    let oil = compare_rows(
        &[
            ("library = \"water\"", "library = \"iso-vg-46\""),
            ("temperature = \"80 C\"", "temperature = \"120 C\""),
        ],
        "nbr-70,hnbr-75,epdm-70",
    );
    let life = |id: &str| -> f64 {
        oil.iter().find(|(k, _)| k == id).unwrap().1[3]
            .parse()
            .unwrap()
    };
    assert!(life("hnbr-75") > 3.0 * life("nbr-70"), "{oil:?}");
    assert!(
        notes(&oil, "epdm-70").starts_with("NOT RECOMMENDED in mineral oil"),
        "{oil:?}"
    );
    assert!(
        notes(&oil, "nbr-70").starts_with("recommended in mineral oil"),
        "{oil:?}"
    );
}

/// Issue 31: the ageing constants' test medium is stored with them; a run in another medium
/// warns at the fluid, one in the same medium does not; an unknown medium in a material file
/// exits 2 naming the file, line and key, with the media it accepts.
#[test]
fn the_ageing_medium_is_stored_checked_and_validated() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let scratch = tempfile::tempdir().unwrap();
    let out = scratch.path().join("history.csv");
    let water = sealsim()
        .arg("run")
        .arg(root.join("oring-nbr-water-80c.toml"))
        .arg("--verbose")
        .args(["-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    let stderr = String::from_utf8(water.stderr).unwrap();
    assert!(
        stderr.contains("fluid: the compound's ageing constants were measured in mineral-oil, this run's fluid is water"),
        "{stderr}"
    );
    let oil = sealsim()
        .arg("run")
        .arg(root.join("oring-nbr-piston-hydraulic.toml"))
        .args(["-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(
        !String::from_utf8(oil.stderr)
            .unwrap()
            .contains("measured in")
    );
    // a material file with an unknown medium
    let dir = tempfile::tempdir().unwrap();
    let text = library::get("nbr-70")
        .unwrap()
        .text
        .replace("medium = \"mineral-oil\"", "medium = \"brake fluid\"");
    let line = text
        .lines()
        .position(|l| l.starts_with("medium = "))
        .unwrap()
        + 1;
    let file = dir.path().join("m.toml");
    fs::write(&file, text.replace("status = \"illustrative\"\n", "")).unwrap();
    let out = sealsim()
        .args(["materials", "show", "--file"])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.contains(&format!(
            "m.toml:{}: material.ageing.medium: unknown medium \"brake fluid\": give one of \"air\"",
            line - 1
        )),
        "{stderr}"
    );
}

/// Issue 31: a library-format compound file with a missing figure, a compatibility entry for
/// an unknown fluid class, or a rating outside the A/B/X scale exits 2 naming the file, the
/// line and the key, and prints nothing on standard output.
#[test]
fn a_broken_compound_file_exits_2_naming_file_line_and_key() {
    let text = library::get("epdm-70").unwrap().text;
    let line_of = |needle: &str| text.lines().position(|l| l.starts_with(needle)).unwrap() + 1;
    let cases = [
        (
            text.replace("poisson_ratio = 0.5\n", ""),
            // the key is missing: the error points at the [material] table's header
            format!(
                ":{}: material.poisson_ratio: missing key",
                line_of("[material]")
            ),
        ),
        (
            text.replace("water-glycol = {", "brine = {"),
            format!(
                ":{}: material.compatibility.brine: unknown fluid class `brine`",
                line_of("water-glycol = {")
            ),
        ),
        (
            text.replacen("rating = \"A\"", "rating = \"C\"", 1),
            format!(
                ":{}: material.compatibility.water.rating: rating \"C\" is outside the scale",
                line_of("water = {")
            ),
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (broken, expected) in cases {
        let file = dir.path().join("epdm-broken.toml");
        fs::write(&file, &broken).unwrap();
        let out = sealsim()
            .args(["materials", "show", "--file"])
            .arg(&file)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{expected}");
        assert!(out.stdout.is_empty());
        let stderr = String::from_utf8(out.stderr).unwrap();
        assert!(
            stderr.contains(&format!("epdm-broken.toml{expected}")),
            "{expected}\n{stderr}"
        );
    }
}

/// The README's and the guide's count of published and illustrative library compounds is the
/// library's (issue 40).
#[test]
fn the_readme_counts_the_library_by_status() {
    let statuses: Vec<String> = library::ids()
        .map(|id| {
            library::get(id)
                .unwrap()
                .load()
                .unwrap()
                .status
                .as_str()
                .to_owned()
        })
        .collect();
    let count = |s: &str| statuses.iter().filter(|x| *x == s).count();
    let sentence = format!(
        "of the library's {} compounds, {} are published (every figure sourced) and {} illustrative",
        statuses.len(),
        count("published"),
        count("illustrative")
    );
    for doc in ["README.md", "docs/src/introduction.md"] {
        let text = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(doc))
            .unwrap()
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        assert!(text.contains(&sentence), "{doc} lacks: {sentence}");
    }
}

/// `materials new`: the shipped example datasheet gives a compound file whose T10 is the
/// datasheet's (read back by the library's own T10) and which a scenario runs on; the summary
/// comes first on standard output.
#[test]
fn materials_new_writes_a_compound_a_run_can_use() {
    let dir = Dir::new();
    let sheet = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/lab-data/datasheet-nbr.toml"),
    )
    .unwrap();
    let sheet_path = dir.write("sheet.toml", &sheet);
    let out_path = dir.0.path().join("compound.toml");
    let (out, _) = ok(&["materials", "new", s(&sheet_path), "-o", s(&out_path)]);
    assert!(out.starts_with("compound "), "{out}");
    assert!(out.contains("T10            -30.0 °C"), "{out}");
    let m = load_material_file(&out_path).unwrap();
    let t10 = m.low_temperature_limit().unwrap() - 273.15;
    assert!((t10 + 30.0).abs() < 0.01, "T10 {t10} °C");
    assert!(m.provenance_of("ageing").unwrap().contains("D395"));
    let scenario = crate::support::edited(
        &crate::support::shipped("oring-nbr-hydraulic-oil-clean.toml"),
        &[("library = \"nbr-70\"", "file = \"compound.toml\"")],
    );
    let scenario_path = dir.write("scenario.toml", &scenario);
    ok(&[
        "run",
        s(&scenario_path),
        "-o",
        s(&dir.0.path().join("out.csv")),
    ]);
}

/// `materials check FILE`: a datasheet compound is checked against its class's published
/// figures (T10 within ±5 K of the class's low-temperature limit, t50 at the rated
/// temperature within 500–2000 h); a compound whose TR-10 sits 25 K below its class's limit is
/// reported FAIL (exit 1, not an input error), and a file without `class` is refused at input
/// (exit 2) naming the key to add.
#[test]
fn materials_check_accepts_a_datasheet_compound() {
    let dir = Dir::new();
    let sheet = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/lab-data/datasheet-nbr.toml"),
    )
    .unwrap();
    let compound = dir.path("compound.toml");
    let sheet_path = dir.write("sheet.toml", &sheet);
    ok(&["materials", "new", s(&sheet_path), "-o", s(&compound)]);
    let (out, _) = ok(&["materials", "check", s(&compound)]);
    let row = out
        .lines()
        .find(|l| l.starts_with(s(&compound)))
        .unwrap_or_else(|| panic!("{out}"));
    assert_eq!(row.matches(" ok ").count(), 2, "{row}");
    assert!(row.contains("-30") && row.contains("100 °C"), "{row}");
    assert!(!out.contains("acm-70"), "only the file is checked: {out}");

    let cold = dir.write(
        "cold.toml",
        &sheet.replace("t10 = \"-30 C\"", "t10 = \"-55 C\""),
    );
    let cold_compound = dir.path("cold-compound.toml");
    ok(&["materials", "new", s(&cold), "-o", s(&cold_compound)]);
    let out = sealsim()
        .args(["materials", "check", s(&cold_compound)])
        .assert()
        .code(1);
    let stdout = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    assert!(stdout.contains("FAIL"), "{stdout}");

    let text = fs::read_to_string(&compound).unwrap();
    let classless = dir.write("classless.toml", &text.replace("class = \"nbr\"\n", ""));
    let err = rejected(&["materials", "check", s(&classless)]);
    assert!(
        err.contains("classless.toml") && err.contains("class = "),
        "{err}"
    );
}

/// A datasheet's own rubbery CTE replaces the class's, with the datasheet as its provenance;
/// out of the elastomers' range it is refused at its key.
#[test]
fn materials_new_takes_the_datasheets_thermal_expansion() {
    let dir = Dir::new();
    let sheet = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/lab-data/datasheet-nbr.toml"),
    )
    .unwrap();
    let with = |cte: &str| {
        sheet.replace(
            "t10 = \"-30 C\"",
            &format!("t10 = \"-30 C\"\nthermal_expansion = \"{cte}\""),
        )
    };
    let path = dir.write("cte.toml", &with("2.9e-4 1/K"));
    let out = dir.path("compound.toml");
    ok(&["materials", "new", s(&path), "-o", s(&out)]);
    let m = load_material_file(&out).unwrap();
    assert_eq!(m.thermal_expansion, Some(2.9e-4));
    assert!(
        m.provenance_of("thermal_expansion")
            .unwrap()
            .starts_with("datasheet")
    );
    let class = library::get("nbr-70").unwrap().load().unwrap();
    assert_ne!(class.thermal_expansion, Some(2.9e-4));
    let bad = dir.write("bad.toml", &with("2.9e-2 1/K"));
    let err = rejected(&["materials", "new", s(&bad), "-o", s(&out)]);
    assert!(err.contains("datasheet.thermal_expansion"), "{err}");
}

/// A datasheet that cannot make a compound exits 2 naming file, line and key (or the reading),
/// writes nothing, and never overwrites its own input.
#[test]
fn materials_new_refuses_a_bad_datasheet_and_writes_nothing() {
    let dir = Dir::new();
    let good = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/lab-data/datasheet-nbr.toml"),
    )
    .unwrap();
    let out_path = dir.0.path().join("compound.toml");
    let no_t10 = dir.write("no-t10.toml", &good.replace("t10 = \"-30 C\"", ""));
    let err = rejected(&["materials", "new", s(&no_t10), "-o", s(&out_path)]);
    assert!(
        err.contains("no-t10.toml:") && err.contains("datasheet.t10"),
        "{err}"
    );
    let bare = dir.write("bare.toml", &good.replace("\"-30 C\"", "-30"));
    let err = rejected(&["materials", "new", s(&bare), "-o", s(&out_path)]);
    assert!(
        err.contains("bare.toml:9") && err.contains("needs its unit"),
        "{err}"
    );
    let tiny = dir.write(
        "tiny.toml",
        &good.replace("set = \"18 %\"", "set = \"2 %\""),
    );
    let err = rejected(&["materials", "new", s(&tiny), "-o", s(&out_path)]);
    assert!(err.contains("viscoelasticity alone"), "{err}");
    let class = dir.write(
        "class.toml",
        &good.replace("class = \"nbr\"", "class = \"pvc\""),
    );
    let err = rejected(&["materials", "new", s(&class), "-o", s(&out_path)]);
    assert!(
        err.contains("datasheet.class") && err.contains("nbr"),
        "{err}"
    );
    assert!(!out_path.exists());
    let sheet = dir.write("sheet.toml", &good);
    rejected(&["materials", "new", s(&sheet), "-o", s(&sheet)]);
    assert_eq!(fs::read_to_string(&sheet).unwrap(), good);
}

/// Issue 40: the band `materials new` prints for Ea is a study input as printed, and a study of
/// the datasheet compound drawing Ea from it has wider B10 confidence bounds than the same
/// study with Ea fixed at its value.
#[test]
fn a_study_drawing_a_datasheet_band_has_wider_b10_bounds_than_with_it_fixed() {
    let dir = Dir::new();
    let sheet = fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/lab-data/datasheet-nbr.toml"),
    )
    .unwrap();
    let sheet_path = dir.write("sheet.toml", &sheet);
    let (out, _) = ok(&[
        "materials",
        "new",
        s(&sheet_path),
        "-o",
        s(&dir.path("compound.toml")),
    ]);
    let line = out
        .lines()
        .find_map(|l| l.strip_prefix("study          [vary] "))
        .unwrap_or_else(|| panic!("{out}"));
    let band_input = line.split("   #").next().unwrap().trim().to_owned();
    let m = load_material_file(&dir.path("compound.toml")).unwrap();
    let ea = m.ageing.unwrap().activation_energy / 1e3;
    let scenario = crate::support::edited(
        &crate::support::shipped("oring-nbr-water-80c.toml"),
        &[("library = \"nbr-70\"", "file = \"compound.toml\"")],
    );
    dir.write("base.toml", &scenario);
    let width = |vary: &str, name: &str| {
        let study = format!(
            "name = \"{name}\"\nbase = \"base.toml\"\ndesign = \"monte-carlo\"\nsamples = 16\n\
             seed = 1\n\n[vary]\n{vary}\n"
        );
        let path = dir.write(&format!("{name}.study.toml"), &study);
        let json = dir.path(&format!("{name}.json"));
        ok(&["study", s(&path), "--summary", s(&json), "--threads", "2"]);
        let v: serde_json::Value =
            serde_json::from_str(&fs::read_to_string(&json).unwrap()).unwrap();
        let (lo, hi) = (v["b10_lower_s"].as_f64(), v["b10_upper_s"].as_f64());
        let (lo, hi) = (
            lo.unwrap_or_else(|| panic!("{v}")),
            hi.unwrap_or(f64::INFINITY),
        );
        hi - lo
    };
    let fixed = width(
        &format!("\"ageing.activation_energy\" = {{ values = [\"{ea} kJ/mol\"] }}"),
        "fixed",
    );
    assert_eq!(band_input, "\"ageing.activation_energy\" = \"band\"");
    let banded = width(&band_input, "band");
    assert!(
        banded > fixed && banded > 0.0,
        "B10 bounds: band {banded} s, fixed {fixed} s"
    );
    // "band" is the compound file's band, drawn uniformly: the same study as the range written out
    let band = &m.bands[0];
    assert_eq!(band.key, "ageing.activation_energy");
    assert!(band.min < m.ageing.unwrap().activation_energy && band.max > band.min);
    let explicit = width(
        &format!(
            "\"ageing.activation_energy\" = {{ distribution = \"uniform\", min = \"{:e} J/mol\", \
             max = \"{:e} J/mol\" }}",
            band.min, band.max
        ),
        "explicit",
    );
    assert_eq!(explicit.to_bits(), banded.to_bits());
    // a compound without that band: refused at the key, naming where a band comes from
    let library = dir.write(
        "library.study.toml",
        "base = \"library.toml\"\ndesign = \"monte-carlo\"\nsamples = 4\n\n[vary]\n\
         \"ageing.activation_energy\" = \"band\"\n",
    );
    dir.write(
        "library.toml",
        &crate::support::shipped("oring-nbr-water-80c.toml"),
    );
    let err = rejected(&["study", s(&library)]);
    assert!(
        err.contains("library.study.toml:6") && err.contains("[material.bands]"),
        "{err}"
    );
}
