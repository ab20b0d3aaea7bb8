//! Charts in the format their file names (SVG, PNG, PDF), the gas chart's failing quantity and
//! the HTML report's record (issue 42, items 2, 4 and 7).

use crate::support::sealsim;
use std::fs;
use std::path::Path;

/// The new user's helium flange (review of 2026-11-28, §2(b)): an FKM AS568-345 face seal whose
/// interface seals, failing the 1e-9 mbar·L/s helium test by permeation through the rubber
/// after about 30 min. Reads no other file.
const HELIUM_FLANGE: &str = r#"name = "FKM vacuum flange, AS568-345, He test 1e-9 mbar L/s, 20 C"

[material]
library = "fkm-75"

[surface]
ra = "0.8 um"

[fluid]
gas = "helium"
inlet_pressure = "1 bar"
outlet_pressure = "1e-6 mbar"

[seal]
kind = "o-ring"
gland = "face"
size = "AS568-345"
groove_depth = "4.0 mm"
groove_width = "7.2 mm"
groove_inner_diameter = "101.6 mm"
loading = "displacement"

[environment]
temperature = "20 C"

[failure]
max_leak_rate = "1e-9 mbar*L/s"

[simulation]
duration = "1 day"
points_per_decade = 25
"#;

/// The helium flange written into a fresh directory: (the directory, the scenario's path).
fn flange() -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let scenario = dir.path().join("flange.toml");
    fs::write(&scenario, HELIUM_FLANGE).unwrap();
    (dir, scenario)
}

fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// `--plot` writes the format its extension names: a PNG (its signature, and a bitmap that
/// decodes to twice the chart's 900 × 1000 pixels), a PDF (`%PDF-` … `%%EOF`), an SVG; another
/// extension is refused with the three that can be written, exit 2 and nothing written. The same
/// for another command's chart (`materials curve --plot`).
#[test]
fn charts_are_written_in_the_format_their_extension_names() {
    let (dir, scenario) = flange();
    for name in ["he.png", "he.pdf", "he.svg"] {
        let out = sealsim()
            .arg("run")
            .arg(&scenario)
            .arg("--plot")
            .arg(dir.path().join(name))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let png = fs::read(dir.path().join("he.png")).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"), "PNG signature");
    // IHDR: width and height, big-endian, at bytes 16..24
    let size = |at: usize| u32::from_be_bytes(png[at..at + 4].try_into().unwrap());
    assert_eq!((size(16), size(20)), (1800, 2000));
    let pdf = fs::read(dir.path().join("he.pdf")).unwrap();
    assert!(pdf.starts_with(b"%PDF-"), "PDF header");
    assert!(String::from_utf8_lossy(&pdf).trim_end().ends_with("%%EOF"));
    let svg = fs::read_to_string(dir.path().join("he.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));

    let refused = dir.path().join("he.xlsx");
    let out = sealsim()
        .arg("run")
        .arg(&scenario)
        .arg("--plot")
        .arg(&refused)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--plot") && err.contains(".svg, .png or .pdf") && err.contains("he.svg"),
        "{err}"
    );
    assert!(!refused.exists());
    assert_eq!(
        names(dir.path()),
        ["flange.toml", "he.pdf", "he.png", "he.svg"]
    );

    let curve = dir.path().join("nbr.PNG");
    let out = sealsim()
        .args(["materials", "curve", "nbr-70", "--points-per-decade", "3"])
        .arg("--plot")
        .arg(&curve)
        .args(["-o", "/dev/null"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(fs::read(&curve).unwrap().starts_with(b"\x89PNG"));
}

/// The vertices of the SVG polylines drawn in `stroke` at `width` with more than `min` vertices
/// (a legend's sample has two), in document order.
fn polylines(svg: &str, stroke: &str, width: u32, min: usize) -> Vec<Vec<(f64, f64)>> {
    let head = format!("stroke=\"{stroke}\" stroke-width=\"{width}\" points=\"");
    svg.lines()
        .filter_map(|l| l.split_once(&head).map(|(_, rest)| rest))
        .map(|rest| {
            rest.split('"')
                .next()
                .unwrap()
                .split_whitespace()
                .map(|p| {
                    let (x, y) = p.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect::<Vec<(f64, f64)>>()
        })
        .filter(|v| v.len() > min)
        .collect()
}

/// The y of `line` at `x` (linear between its vertices, as drawn).
fn y_at(line: &[(f64, f64)], x: f64) -> f64 {
    let k = line.iter().position(|p| p.0 >= x).unwrap();
    let (a, b) = (line[k.saturating_sub(1)], line[k]);
    if b.0 == a.0 {
        return b.1;
    }
    a.1 + (x - a.0) / (b.0 - a.0) * (b.1 - a.1)
}

/// Issue 42, item 4 (the review's friction #4): the helium flange fails by permeation, yet the
/// chart drew only the interface's flow, and the failure cross sat on it about 10 decades below
/// the dashed limit. Now the leak panel draws the interface, the permeation and their total in
/// Pa·m³/s, the limit on the same axis; the cross sits on the total where it meets the limit (to
/// the SVG's whole pixels), far above the sealed interface.
#[test]
fn the_helium_chart_draws_the_permeation_that_fails_it_and_marks_the_total() {
    let (dir, scenario) = flange();
    let path = dir.path().join("he.svg");
    let out = sealsim()
        .arg("run")
        .arg(&scenario)
        .arg("--plot")
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("FAILS after 29.9 min by leak_rate"));
    let svg = fs::read_to_string(&path).unwrap();
    assert!(svg.contains("throughput [Pa·m³/s]"), "the gas panel's unit");
    assert!(svg.contains("permeation through the rubber"));
    assert!(svg.contains("total: interface + permeation"));
    assert!(svg.contains("max_leak_rate 1e-10 Pa·m³/s (1e-9 mbar·L/s)"));
    // the leak panel is drawn first: its curves are the first of their colours
    let total = &polylines(&svg, "#000000", 4, 2)[0];
    let permeation = &polylines(&svg, "#009E73", 2, 2)[0];
    let interface = &polylines(&svg, "#0072B2", 2, 2)[0];
    assert!(total.len() >= 20 && permeation.len() >= 20 && interface.len() >= 20);
    // the limit: the dashes of the vermillion width-2 line, all at one y
    let dashes: Vec<f64> = svg
        .lines()
        .filter(|l| l.contains("stroke=\"#D55E00\" stroke-width=\"2\" points="))
        .filter_map(|l| polylines(l, "#D55E00", 2, 1).into_iter().next())
        .filter(|v| v.len() == 2 && v[0].1 == v[1].1 && v[1].0 - v[0].0 < 12.0)
        .map(|v| v[0].1)
        .collect();
    assert!(dashes.len() > 20, "a dashed limit");
    let limit = dashes[dashes.len() / 2];
    assert!(dashes.iter().filter(|y| **y == limit).count() > 20);
    // the total crosses the limit: below it (larger y) early, above it late
    assert!(total.first().unwrap().1 > limit + 100.0);
    assert!(total.last().unwrap().1 < limit - 20.0);
    // the failure cross (two 16-pixel strokes in the leak panel, the first drawn)
    let (x1, y1, x2, y2) = svg
        .lines()
        .filter(|l| l.starts_with("<line") && l.contains("stroke=\"#D55E00\" stroke-width=\"3\""))
        .map(|l| {
            let num = |key: &str| -> f64 {
                let rest = l.split(&format!(" {key}=\"")).nth(1).unwrap();
                rest.split('"').next().unwrap().parse().unwrap()
            };
            (num("x1"), num("y1"), num("x2"), num("y2"))
        })
        .find(|(x1, _, x2, _)| (x2 - x1).abs() == 16.0)
        .unwrap();
    let (cx, cy) = ((x1 + x2) / 2.0, (y1 + y2) / 2.0);
    assert!(
        (cy - limit).abs() <= 2.0,
        "the cross at the limit: {cy} vs {limit}"
    );
    let on_total = y_at(total, cx);
    assert!(
        (cy - on_total).abs() <= 2.0,
        "on the total: {cy} vs {on_total}"
    );
    assert!(
        (y_at(permeation, cx) - on_total).abs() <= 2.0,
        "the total is the permeation"
    );
    assert!(
        y_at(interface, cx) > cy + 150.0,
        "the interface is sealed, far below"
    );
}

/// Issue 42, item 7: the HTML report carries its record after the verdict and before the
/// summary: the date (UTC ISO 8601, fixed by `SOURCE_DATE_EPOCH`), sealsim's version and commit,
/// and the SHA-256 of the scenario file (computed here from the file's bytes); and a print
/// stylesheet for A4.
#[test]
fn a_report_records_date_version_commit_and_input_hashes() {
    use sha2::Digest;
    let (dir, scenario) = flange();
    let report = dir.path().join("r.html");
    let out = sealsim()
        .env("SOURCE_DATE_EPOCH", "1796000000")
        .arg("run")
        .arg(&scenario)
        .arg("--report")
        .arg(&report)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let page = fs::read_to_string(&report).unwrap();
    let hash: String = sha2::Sha256::digest(HELIUM_FLANGE.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    // 1 796 000 000 s after 1970-01-01T00:00:00Z
    let date = "2026-11-30T00:53:20Z";
    for needle in [
        date,
        &format!("sealsim {} (commit ", env!("CARGO_PKG_VERSION")),
        &format!("SHA-256 {hash}"),
        "@media print",
        "size: A4",
    ] {
        assert!(page.contains(needle), "{needle} missing");
    }
    let at = |needle: &str| page.find(needle).unwrap();
    assert!(at("class=\"verdict") < at(date) && at(date) < at("<h2>Summary</h2>"));
}
