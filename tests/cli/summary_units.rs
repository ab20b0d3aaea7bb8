//! The run summary an engineer reads first (issue 42): the verdict line opens it, the default
//! is short, `--quiet` is the verdict line alone, `--verbose` the full derivation; `--units`
//! prints the summary, the report and the CSV columns in SI, metric or US units, and a history
//! CSV written in any of them reads back (as an environment history) to the same SI values.

use crate::common::scenarios_dir;
use crate::support::{HISTORY_HEADER, sealsim, sealsim_ok};

/// The headline scenario (README, face-gland tutorial): it fails after 281 days by the
/// retained force (the scenario's own header comment), over a 30-year run.
fn headline() -> std::path::PathBuf {
    scenarios_dir().join("oring-nbr-water-80c.toml")
}

#[test]
fn the_headline_opens_with_its_verdict_and_is_short_quiet_and_verbose_agree() {
    let brief = sealsim_ok(&[&"run", &headline()]);
    let lines: Vec<&str> = brief.lines().collect();
    assert!(
        lines[0].starts_with("FAIL after 281 days of a 30-year target by retained_force: "),
        "{brief}"
    );
    // the limiting quantity against its limit, and the estimate flagged in the line itself
    assert!(lines[0].contains("(limit "), "{}", lines[0]);
    assert!(lines[0].ends_with("[ILLUSTRATIVE data]"), "{}", lines[0]);
    assert!(lines.len() <= 25, "{} lines:\n{brief}", lines.len());
    for line in &lines[1..] {
        assert!(
            line.chars().count() <= 120,
            "{} chars: {line}",
            line.chars().count()
        );
    }
    assert!(brief.contains("!!! ILLUSTRATIVE material data"), "{brief}");
    // the derivations are --verbose's, not the default's
    assert!(!brief.contains("ageing         two networks"), "{brief}");

    let quiet = sealsim_ok(&[&"run", &headline(), &"--quiet"]);
    assert_eq!(
        quiet,
        format!("{}\n", lines[0]),
        "--quiet: the verdict line alone"
    );

    let verbose = sealsim_ok(&[&"run", &headline(), &"--verbose"]);
    let mut v = verbose.lines();
    assert_eq!(v.next(), Some(lines[0]), "{verbose}");
    let body: Vec<&str> = v.collect();
    // the full body of before: scenario first, the derivations, the result last
    assert!(
        body[0].starts_with("scenario       NBR O-ring face seal"),
        "{verbose}"
    );
    for label in [
        "material",
        "seal",
        "fluid",
        "temperature",
        "ageing",
        "lowest",
        "level band",
    ] {
        assert!(
            body.iter().any(|l| l.starts_with(&format!("{label:<15}"))),
            "--verbose lacks {label}:\n{verbose}"
        );
    }
    assert!(
        body.last()
            .is_some_and(|l| l.starts_with("result         FAILS after 281 days")),
        "{verbose}"
    );
}

#[test]
fn quiet_and_verbose_exclude_each_other_and_an_unknown_unit_system_is_refused() {
    sealsim()
        .args(["run", "x.toml", "--quiet", "--verbose"])
        .assert()
        .code(2);
    let out = sealsim()
        .arg("run")
        .arg(headline())
        .args(["--units", "imperial"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(stderr.contains("si, metric, us"), "{stderr}");
}

/// The CSV's SI value of a US-unit cell of column `name`, by the definitions (independent of
/// sealsim's conversion module): 1 in = 0.0254 m, 1 lbf = 4.4482216152605 N, 1 psi =
/// 6894.757293168 Pa, T[K] = (T[°F] + 459.67) × 5/9, 1 cc = 1e-6 m³.
fn us_to_si(name: &str, value: f64) -> (String, f64) {
    const IN: f64 = 0.0254;
    const LBF: f64 = 4.448_221_615_260_5;
    const PSI: f64 = 6_894.757_293_168;
    let table: [(&str, &str, f64); 8] = [
        ("_F", "_K", f64::NAN),
        ("_lbf_per_in", "_N_per_m", LBF / IN),
        ("_psi", "_Pa", PSI),
        ("_in", "_m", IN),
        ("_cc_per_min", "_m3_per_s", 1e-6 / 60.0),
        ("_cc", "_m3", 1e-6),
        ("_atm_cc_per_s", "_Pa_m3_per_s", 101_325.0 * 1e-6),
        ("_s", "_s", 1.0),
    ];
    for (us, si, factor) in table {
        if let Some(stem) = name.strip_suffix(us) {
            let v = if us == "_F" {
                (value + 459.67) * 5.0 / 9.0
            } else {
                value * factor
            };
            return (format!("{stem}{si}"), v);
        }
    }
    (name.to_owned(), value)
}

#[test]
fn us_units_in_the_summary_and_the_csv_which_reads_back_to_the_same_si_values() {
    let dir = tempfile::tempdir().unwrap();
    let (si, us) = (dir.path().join("si.csv"), dir.path().join("us.csv"));
    sealsim_ok(&[&"run", &headline(), &"--quiet", &"-o", &si]);
    let text = sealsim_ok(&[&"run", &headline(), &"--units", &"us", &"-o", &us]);
    // the summary: pressures in psi, temperatures in °F, lengths in inches, forces in lbf/in
    // (80 °C = 176 °F; ΔP 2 bar = 29.0 psi)
    for needle in [
        "176 °F",
        "ΔP 29 psi",
        " in at installation",
        "lbf/in",
        " cc in 30 years",
    ] {
        assert!(text.contains(needle), "no {needle:?} in:\n{text}");
    }
    // (the scenario's name says "80 °C": the figures are what must not)
    let figures: String = text
        .lines()
        .filter(|l| !l.starts_with("scenario"))
        .collect();
    for si in ["MPa", "°C", "N/mm", "m³"] {
        assert!(!figures.contains(si), "{si} in:\n{text}");
    }

    // the CSV: the same rows, each unit in its column's name, every value the SI file's
    let read = |p: &std::path::Path| {
        let text = std::fs::read_to_string(p).unwrap();
        let mut lines = text.lines().map(str::to_owned);
        let header = lines.next().unwrap();
        (header, lines.collect::<Vec<_>>())
    };
    let ((si_header, si_rows), (us_header, us_rows)) = (read(&si), read(&us));
    assert_eq!(si_header, HISTORY_HEADER);
    for column in [
        "time_s",
        "temperature_F",
        "sealing_force_lbf_per_in",
        "peak_pressure_psi",
        "mean_pressure_psi",
        "contact_width_in",
        "u_c_in",
        "leak_rate_cc_per_min",
        "leaked_volume_cc",
    ] {
        assert!(
            us_header.split(',').any(|c| c == column),
            "{column}: {us_header}"
        );
    }
    assert_eq!(si_rows.len(), us_rows.len());
    let names: Vec<&str> = us_header.split(',').collect();
    let si_names: Vec<&str> = si_header.split(',').collect();
    for (a, b) in si_rows.iter().zip(&us_rows) {
        for ((x, y), name) in a.split(',').zip(b.split(',')).zip(&names) {
            match (x.parse::<f64>(), y.parse::<f64>()) {
                (Ok(x), Ok(y)) => {
                    let (si_name, back) = us_to_si(name, y);
                    assert!(si_names.contains(&si_name.as_str()), "{name} → {si_name}");
                    let scale = x.abs().max(f64::MIN_POSITIVE);
                    assert!(
                        (back - x).abs() <= 1e-9 * scale,
                        "{name}: {y} reads {back}, the SI file has {x}"
                    );
                }
                _ => assert_eq!(x, y, "{name}"),
            }
        }
    }

    // the readers: each file drives a run as its environment history; both runs read the same
    // temperatures (the SI file is the reference), so their histories agree within 1e-9
    let scenario = std::fs::read_to_string(headline()).unwrap();
    let temperature = "temperature = \"80 C\"";
    assert!(scenario.contains(temperature));
    let rerun = |csv: &str| {
        let path = dir.path().join(format!("{csv}.toml"));
        std::fs::write(
            &path,
            scenario.replace(temperature, &format!("history = \"{csv}.csv\"")),
        )
        .unwrap();
        let out = dir.path().join(format!("{csv}-back.csv"));
        sealsim_ok(&[&"run", &path, &"--quiet", &"-o", &out]);
        read(&out).1
    };
    let (from_si, from_us) = (rerun("si"), rerun("us"));
    assert_eq!(from_si.len(), from_us.len());
    for (a, b) in from_si.iter().zip(&from_us) {
        let cell = |row: &str, i: usize| row.split(',').nth(i).unwrap().parse::<f64>().unwrap();
        for i in [0, 1] {
            // time_s, temperature_K
            let (x, y) = (cell(a, i), cell(b, i));
            assert!(
                (x - y).abs() <= 1e-9 * x.abs().max(1.0),
                "column {i}: {x} from the SI file, {y} from the US file"
            );
        }
    }
    // and the SI file's temperatures are the first run's own (the reader reads what was written)
    for (a, b) in si_rows.iter().zip(&from_si) {
        let t = |row: &str| row.split(',').nth(1).unwrap().parse::<f64>().unwrap();
        assert!((t(a) - t(b)).abs() <= 1e-9 * t(a), "{a} / {b}");
    }
}
