//! Results an engineer reads (docs/model.md §15): honest floors, the text formats (snapshots
//! with every number masked: formats, never physics), the HTML reports' structure. The reports
//! are opened in a real browser by `tests/browser/check-report.sh` (run by `.ci/run`).

use crate::common::scenarios_dir;
use crate::support::{sealsim, sealsim_ok as run_ok};
use std::path::Path;

/// The text with every number replaced by `#` (digits with their sign, point and exponent), so
/// that a snapshot compares the layout and the words, not the physics.
fn masked(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let starts = c.is_ascii_digit()
            || (c == '-'
                && chars.get(i + 1).is_some_and(char::is_ascii_digit)
                && !chars
                    .get(i.wrapping_sub(1))
                    .is_some_and(|p| p.is_alphanumeric()));
        if starts {
            i += 1;
            while i < chars.len()
                && (chars[i].is_ascii_digit()
                    || chars[i] == '.'
                    || ((chars[i] == 'e' || chars[i] == 'E')
                        && chars
                            .get(i + 1)
                            .is_some_and(|n| n.is_ascii_digit() || *n == '-' || *n == '+')))
            {
                if chars[i] == 'e' || chars[i] == 'E' {
                    i += 1; // the exponent's sign or first digit
                }
                i += 1;
            }
            out.push('#');
        } else {
            out.push(c);
            i += 1;
        }
    }
    // the masked numbers' widths differ: collapse runs of spaces so columns compare by order
    out.lines()
        .map(|l| {
            l.split(' ')
                .filter(|w| !w.is_empty())
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// Compares `text` (masked) with the snapshot `name`; `UPDATE_SNAPSHOTS=1` rewrites it.
fn snapshot(name: &str, text: &str) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/cli/snapshots")
        .join(name);
    let got = masked(text);
    if std::env::var_os("UPDATE_SNAPSHOTS").is_some() {
        std::fs::write(&path, &got).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        got == want,
        "{name} changed (review it, then UPDATE_SNAPSHOTS=1 cargo test --release --test cli \
         report::):\n--- want\n{want}\n--- got\n{got}"
    );
}

#[test]
fn masking_hides_numbers_and_keeps_words() {
    assert_eq!(
        masked("FAILS after 281 days (t = 2.43e7 s) by retained_force, T10 = -25.5 °C, AS568-225"),
        "FAILS after # days (t = # s) by retained_force, T# = # °C, AS#-#\n"
    );
}

#[test]
fn the_run_summary_and_the_compare_table_keep_their_format() {
    let headline = scenarios_dir().join("oring-nbr-water-80c.toml");
    let text = run_ok(&[&"run", &headline]).replace(&headline.display().to_string(), "SCENARIO");
    snapshot("run-summary.txt", &text);
    let gas = scenarios_dir().join("helium-leak-test-gasket.toml");
    let text = run_ok(&[&"run", &gas]).replace(&gas.display().to_string(), "SCENARIO");
    snapshot("run-summary-gas.txt", &text);
    let text = run_ok(&[
        &"compare",
        &headline,
        &"--materials",
        &"nbr-70,fkm-75,epdm-70",
    ])
    .replace(&headline.display().to_string(), "SCENARIO");
    snapshot("compare-table.txt", &text);
}

#[test]
fn a_leak_below_the_floor_reads_sealed_its_chart_stops_at_the_floor_and_the_csv_keeps_it() {
    // the paper's flat seal leaks ≈ 2e-15 m³/s; with a floor of 1e-12 m³/s it is sealed in
    // practice
    let dir = tempfile::tempdir().unwrap();
    let (csv, svg, html) = (
        dir.path().join("h.csv"),
        dir.path().join("p.svg"),
        dir.path().join("r.html"),
    );
    let paper = scenarios_dir().join("persson-yang-2008.toml");
    let text = run_ok(&[
        &"run",
        &paper,
        &"--verbose",
        &"--leak-floor",
        &"1e-12 m^3/s",
        &"-o",
        &csv,
        &"--plot",
        &svg,
        &"--report",
        &html,
    ]);
    assert!(
        text.contains("leak rate      ≈ 0 (below 1e-12 m³/s, the floor given) at installation"),
        "{text}"
    );
    // the CSV keeps the raw value
    let table = std::fs::read_to_string(&csv).unwrap();
    let q: f64 = table
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(9)
        .unwrap()
        .parse()
        .unwrap();
    assert!(q > 1e-16 && q < 1e-12, "{q}");
    // the chart's leak-rate axis does not run below the floor's decade
    let chart = std::fs::read_to_string(&svg).unwrap();
    let lowest = chart
        .lines()
        .filter_map(|l| l.trim().strip_prefix("1e-")?.parse::<i32>().ok())
        .max()
        .unwrap();
    assert_eq!(lowest, 12, "the axis runs down to 1e-{lowest}");
    // the default floor is one molecule a second
    let text = run_ok(&[
        &"run",
        &"--verbose",
        &scenarios_dir().join("oring-nbr-water-80c.toml"),
    ]);
    assert!(
        text.contains("≈ 0 (below 3e-29 m³/s, one molecule a second) at installation"),
        "{text}"
    );
    // a bad floor is bad input
    let out = sealsim()
        .args(["run", paper.to_str().unwrap(), "--leak-floor", "2 bar"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--leak-floor"));
}

/// What every report must be: one self-contained page with its charts inline.
fn check_page(page: &str, plots: usize) {
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert_eq!(
        page.matches("<figure class=\"plot\">").count(),
        plots,
        "plots"
    );
    assert_eq!(page.matches("<svg").count(), plots, "inline SVG");
    assert!(!page.contains("<script"), "a script");
    assert!(
        !page.contains("<img") && !page.contains("<link"),
        "an outside resource"
    );
    // the only URLs are the SVG namespaces
    let urls = page.matches("http").count();
    let namespaces = page.matches("\"http://www.w3.org/").count();
    assert_eq!(urls, namespaces, "a URL that is not a namespace");
    crate::support::no_nan(page, "report");
}

#[test]
fn every_report_is_one_self_contained_page() {
    let dir = tempfile::tempdir().unwrap();
    let headline = scenarios_dir().join("oring-nbr-water-80c.toml");
    let r = dir.path().join("run.html");
    run_ok(&[&"run", &headline, &"--report", &r]);
    let page = std::fs::read_to_string(&r).unwrap();
    check_page(&page, 1);
    for section in [
        "Summary",
        "Validity warnings",
        "Fidelity",
        "Scenario (inputs",
    ] {
        assert!(page.contains(section), "{section}");
    }
    assert!(page.contains("FAILS after"));
    let c = dir.path().join("compare.html");
    run_ok(&[
        &"compare",
        &headline,
        &"--materials",
        &"nbr-70,fkm-75",
        &"--report",
        &c,
    ]);
    check_page(&std::fs::read_to_string(&c).unwrap(), 1);
    // a study: the survival curve and the tornado chart
    let s = dir.path().join("study.html");
    let base = scenarios_dir().join("oring-nbr-water-80c.toml");
    let study = dir.path().join("s.study.toml");
    std::fs::write(
        &study,
        format!(
            "base = {base:?}\ndesign = \"monte-carlo\"\nsamples = 20\nseed = 1\n[vary]\n\
             \"environment.temperature\" = {{ distribution = \"normal\", mean = \"80 C\", std = \"3 K\" }}\n\
             \"seal.groove_depth\" = \"±0.05 mm\"\n"
        ),
    )
    .unwrap();
    run_ok(&[&"study", &study, &"--report", &s]);
    check_page(&std::fs::read_to_string(&s).unwrap(), 2);
    // bad input writes no report
    let bad = dir.path().join("bad.html");
    let out = sealsim()
        .args(["run", "no-such.toml", "--report", bad.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(!bad.exists());
}
