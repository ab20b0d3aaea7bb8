//! End-to-end tests of `sealsim surface`: the shipped traces and scenarios, the JSON keys, the
//! rms-slope warning, and bad traces (exit 2, file and line, nothing written).

use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use std::fmt::Write;
use std::fs;
use tempfile::TempDir;

fn json_of(args: &[&str]) -> serde_json::Value {
    let out = cargo_bin_cmd!("sealsim")
        .arg("surface")
        .args(args)
        .arg("--json")
        .assert()
        .success();
    serde_json::from_slice(&out.get_output().stdout).unwrap()
}

#[test]
fn shipped_traces_give_gaussian_parameters_and_their_hurst_exponent() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    // (trace, the H of the spectrum it was made from)
    for (trace, hurst) in [("ground-fine.csv", 0.8), ("ground-coarse.csv", 0.7)] {
        let path = format!("{manifest}/scenarios/traces/{trace}");
        let j = json_of(&[&path]);
        for key in [
            "ra_m",
            "rq_m",
            "rz_m",
            "rms_slope",
            "hurst_exponent",
            "q0_per_m",
            "q1_per_m",
        ] {
            assert!(j[key].is_number(), "{trace}: {key} in {j}");
        }
        // Gaussian heights: Rq/Ra = √(π/2) = 1.2533, to the scatter of one 8192-point trace
        let ratio = j["rq_m"].as_f64().unwrap() / j["ra_m"].as_f64().unwrap();
        assert!(
            (ratio / 1.2533 - 1.0).abs() < 0.03,
            "{trace}: Rq/Ra {ratio}"
        );
        // the fitted H within 0.06 of the generator's (one trace; the interval is printed)
        let h = j["hurst_exponent"].as_f64().unwrap();
        assert!((h - hurst).abs() < 0.06, "{trace}: H {h}");
        assert!(
            j["warnings"]
                .as_array()
                .unwrap()
                .iter()
                .all(|w| !w.as_str().unwrap().contains("rms slope"))
        );
    }
}

#[test]
fn every_shipped_scenario_has_a_surface_summary() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let mut seen = 0;
    for entry in fs::read_dir(format!("{manifest}/scenarios")).unwrap() {
        let path = entry.unwrap().path();
        // figure sets (`[[group]]` of scenarios) are not scenarios
        if path.extension().is_some_and(|e| e == "toml")
            && !fs::read_to_string(&path).unwrap().contains("[[group]]")
        {
            let j = json_of(&[path.to_str().unwrap()]);
            let slope = j["rms_slope"].as_f64().unwrap();
            let warned = j["warnings"]
                .as_array()
                .unwrap()
                .iter()
                .any(|w| w.as_str().unwrap().contains("rms slope"));
            assert_eq!(warned, slope > 0.5, "{}: slope {slope}", path.display());
            seen += 1;
        }
    }
    assert!(seen >= 10, "{seen} scenarios");
}

#[test]
fn a_steep_spectrum_is_warned_about() {
    // the old headline surface: 0.8 µm rms, H = 0.7, q0 = 3e5 1/m, q1 = 1e10 1/m → slope 8.3
    let dir = TempDir::new().unwrap();
    let psd = dir.path().join("steep.csv");
    let mut text = "q [1/m],C [m^4]\n".to_string();
    let (q0, q1, h, hrms): (f64, f64, f64, f64) = (3e5, 1e10, 0.7, 0.8e-6);
    let c0 = h / std::f64::consts::PI * hrms * hrms / (q0.powf(-2.0 * h) - q1.powf(-2.0 * h));
    for q in [q0, 1e7, q1] {
        let _ = writeln!(text, "{q:e},{:e}", c0 * q.powf(-2.0 * (1.0 + h)));
    }
    fs::write(&psd, text).unwrap();
    let j = json_of(&[psd.to_str().unwrap()]);
    let slope = j["rms_slope"].as_f64().unwrap();
    assert!((slope / 8.33 - 1.0).abs() < 0.01, "{slope}");
    assert!(j["warnings"].to_string().contains("rms slope 8.3"), "{j}");
}

#[test]
fn bad_traces_are_located_and_nothing_is_written() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.json");
    let plot = dir.path().join("psd.svg");
    let mut gap = "x,z\nmm,um\n".to_string();
    for j in 0..300 {
        let x = if j < 150 { j as f64 } else { j as f64 + 0.5 } * 1e-3;
        let _ = writeln!(gap, "{x},{}", (j as f64).sin());
    }
    let short = "x,z\nmm,um\n0,1\n0.001,2\n0.002,1\n";
    for (name, text, needle) in [
        ("gap.csv", gap.as_str(), "gap.csv:153:"),
        ("short.csv", short, "short.csv"),
    ] {
        let path = dir.path().join(name);
        fs::write(&path, text).unwrap();
        cargo_bin_cmd!("sealsim")
            .arg("surface")
            .arg(&path)
            .arg("-o")
            .arg(&out)
            .arg("--plot")
            .arg(&plot)
            .assert()
            .code(2)
            .stderr(predicate::str::contains(needle));
        assert!(!out.exists() && !plot.exists(), "{name}: nothing written");
    }
}

/// The shipped trace scenario with its `[surface]` replaced by `surface` (written next to a
/// copy of the traces directory).
fn trace_scenario(dir: &TempDir, surface: &str) -> std::path::PathBuf {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let text = fs::read_to_string(format!(
        "{manifest}/scenarios/oring-nbr-water-80c-trace.toml"
    ))
    .unwrap();
    let start = text.find("[surface]").unwrap();
    let end = text.find("[fluid]").unwrap();
    let text = format!("{}{surface}\n\n{}", &text[..start], &text[end..]);
    fs::create_dir_all(dir.path().join("traces")).unwrap();
    fs::copy(
        format!("{manifest}/scenarios/traces/ground-fine.csv"),
        dir.path().join("traces/ground-fine.csv"),
    )
    .unwrap();
    let path = dir.path().join("s.toml");
    fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_scenario_reads_its_face_from_a_line_trace() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let out = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(format!(
            "{manifest}/scenarios/oring-nbr-water-80c-trace.toml"
        ))
        .arg("--verbose") // the note says how the trace was read
        .assert()
        .success();
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.contains("surface.profile: 1 trace(s): band") && stderr.contains("fitted H"),
        "{stderr}"
    );
    // the spectrum the contact sees is the traces' (its Hurst exponent is the fitted one)
    let j = json_of(&[&format!(
        "{manifest}/scenarios/oring-nbr-water-80c-trace.toml"
    )]);
    assert!(j["hurst_exponent"].is_null(), "a tabulated spectrum: {j}");
    let slope = j["rms_slope"].as_f64().unwrap();
    assert!(slope > 0.1 && slope < 0.5, "{slope}");
}

#[test]
fn trace_scenario_bad_input() {
    let dir = TempDir::new().unwrap();
    // a callout and a trace at once
    let path = trace_scenario(
        &dir,
        "[surface]\nprofile = \"traces/ground-fine.csv\"\nra = \"0.4 um\"",
    );
    cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(&path)
        .assert()
        .code(2)
        .stderr(
            predicate::str::contains("s.toml:").and(predicate::str::contains(
                "surface.profile: profile and ra are mutually exclusive",
            )),
        );
    // a trace with a gap: the trace's line and the scenario's key
    let mut gap = "x,z\nmm,um\n".to_string();
    for j in 0..300 {
        let x = if j < 150 { j as f64 } else { j as f64 + 0.5 } * 1e-3;
        let _ = writeln!(gap, "{x},{}", (j as f64).sin());
    }
    fs::write(dir.path().join("traces/gap.csv"), gap).unwrap();
    let path = trace_scenario(&dir, "[surface]\nprofile = [\"traces/gap.csv\"]");
    let out = dir.path().join("out.csv");
    cargo_bin_cmd!("sealsim")
        .arg("run")
        .arg(&path)
        .arg("-o")
        .arg(&out)
        .assert()
        .code(2)
        .stderr(
            predicate::str::contains("gap.csv:153:").and(predicate::str::contains(
                "(line trace named by surface.profile at",
            )),
        );
    assert!(!out.exists());
}

#[test]
fn a_cutoff_shorter_than_the_sampling_is_refused() {
    let manifest = env!("CARGO_MANIFEST_DIR");
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.txt");
    // the shipped traces are sampled every 0.5 µm: a 4 µm cut-off spans 8 samples
    cargo_bin_cmd!("sealsim")
        .arg("surface")
        .arg(format!("{manifest}/scenarios/traces/ground-fine.csv"))
        .args(["--cutoff", "4um", "--short-cutoff", "1um", "-o"])
        .arg(&out)
        .assert()
        .code(2)
        .stderr(predicate::str::contains(
            "--cutoff: 0.004 mm is shorter than 10 samples",
        ));
    assert!(!out.exists());
}

/// A periodic 256² surface of H = 0.8, h_rms = 1 µm over q0 … π/a, pixel 0.5 µm.
fn synthetic_map(seed: u64) -> sealsim::numerical::HeightMap {
    let (n, pixel) = (256usize, 0.5e-6);
    let q0 = 2.0 * std::f64::consts::PI / (n as f64 * pixel);
    let spectrum =
        sealsim::surface::Spectrum::self_affine(1e-6, 0.8, q0, std::f64::consts::PI / pixel, None)
            .unwrap();
    sealsim::numerical::surface::synthesize(&spectrum, n, seed)
}

/// The first `rows` rows of `map` as a CSV grid, heights in µm.
fn grid_csv(map: &sealsim::numerical::HeightMap, rows: usize) -> String {
    let mut text = String::new();
    for row in map.heights.chunks(map.n).take(rows) {
        let cells: Vec<String> = row.iter().map(|h| format!("{:e}", h * 1e6)).collect();
        let _ = writeln!(text, "{}", cells.join(","));
    }
    text
}

#[test]
fn a_gsf_height_map_gives_the_surface_summary() {
    let dir = TempDir::new().unwrap();
    let map = synthetic_map(3);
    let side = map.n as f64 * map.pixel;
    let gsf = dir.path().join("map.gsf");
    fs::write(
        &gsf,
        sealsim::scenario::gsf::write(map.n, map.n, side, side, &map.heights),
    )
    .unwrap();
    let plot = dir.path().join("psd.svg");
    let j = json_of(&[gsf.to_str().unwrap(), "--plot", plot.to_str().unwrap()]);
    assert_eq!(j["kind"], "height map");
    for key in [
        "ra_m",
        "rq_m",
        "rz_m",
        "rms_slope",
        "hurst_exponent",
        "q0_per_m",
        "q1_per_m",
        "map_h_rms_m",
        "map_rms_slope",
    ] {
        assert!(j[key].is_number(), "{key} in {j}");
    }
    let f = |k: &str| j[k].as_f64().unwrap();
    // a periodic map: H within 0.03, q0 = 2π/L, q1 = π/a
    assert!((f("hurst_exponent") - 0.8).abs() < 0.03, "{j}");
    assert!((f("q0_per_m") * side / (2.0 * std::f64::consts::PI) - 1.0).abs() < 1e-9);
    assert!((f("q1_per_m") * map.pixel / std::f64::consts::PI - 1.0).abs() < 1e-9);
    // h_rms: the spectrum's equals the map's (Parseval), which is the synthesized map's rms
    assert!((f("h_rms_m") / f("map_h_rms_m") - 1.0).abs() < 1e-6);
    assert!((f("map_h_rms_m") / map.rms() - 1.0).abs() < 1e-6);
    // rms slope: the spectrum's 2π∫q³C dq against the map's finite differences, which see
    // the modes near π/a attenuated (|2 sin(qa/2)/a|² < q²): measured 0.93
    let ratio = f("map_rms_slope") / f("rms_slope");
    assert!((0.8..1.0).contains(&ratio), "{ratio}");
    // rows as profiles: Rq/Ra between a single sinusoid's π/(2√2) = 1.111 and Gaussian
    // heights' √(π/2) = 1.253 (each 128 µm row is dominated by a few long random-phase modes;
    // measured 1.167)
    let r = f("rq_m") / f("ra_m");
    assert!((1.11..1.26).contains(&r), "Rq/Ra {r}");
    // each row's Rq is at most the map's rms (a row's mean line removes part of the long waves)
    assert!(f("rq_m") < f("map_h_rms_m"), "{j}");
    // Rz: mean peak-to-valley of the five parts of each row (the trace rule), positive
    assert!(f("rz_m") > f("ra_m"), "{j}");
    let svg = fs::read_to_string(&plot).unwrap();
    assert!(svg.contains("<svg") && svg.contains("fitted or given law"));
}

#[test]
fn a_csv_grid_needs_its_pixel_size_and_may_be_rectangular() {
    let dir = TempDir::new().unwrap();
    let map = synthetic_map(4);
    let square = dir.path().join("square.csv");
    let rect = dir.path().join("rect.csv");
    fs::write(&square, grid_csv(&map, 256)).unwrap();
    fs::write(&rect, grid_csv(&map, 128)).unwrap();
    let args = |p: &std::path::Path| {
        json_of(&[
            p.to_str().unwrap(),
            "--pixel-size",
            "0.5um",
            "--height-unit",
            "um",
        ])
    };
    let (s, r) = (args(&square), args(&rect));
    assert!((s["map_h_rms_m"].as_f64().unwrap() / map.rms() - 1.0).abs() < 1e-6);
    // the rectangle: q0 from its shorter side (128 rows), a warning naming its shape
    let q0 = r["q0_per_m"].as_f64().unwrap();
    assert!((q0 * 128.0 * 0.5e-6 / (2.0 * std::f64::consts::PI) - 1.0).abs() < 1e-9);
    assert!(
        r["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.as_str().unwrap().contains("256 × 128 pixels")),
        "{r}"
    );
    // the same surface: H and the rows' parameters agree between the square and its half
    let h = |j: &serde_json::Value| j["hurst_exponent"].as_f64().unwrap();
    assert!((h(&s) - h(&r)).abs() < 0.05, "{} vs {}", h(&s), h(&r));
    let ra = |j: &serde_json::Value| j["ra_m"].as_f64().unwrap();
    assert!(
        (ra(&s) / ra(&r) - 1.0).abs() < 0.1,
        "{} vs {}",
        ra(&s),
        ra(&r)
    );
    // without --pixel-size the grid is not a map (read as a PSD file, which it is not)
    cargo_bin_cmd!("sealsim")
        .arg("surface")
        .arg(&square)
        .assert()
        .code(2);
}

#[test]
fn bad_height_maps_are_refused_and_nothing_is_written() {
    let dir = TempDir::new().unwrap();
    let out = dir.path().join("out.json");
    let plot = dir.path().join("psd.svg");
    let map = synthetic_map(1);
    let side = map.n as f64 * map.pixel;
    let good = sealsim::scenario::gsf::write(map.n, map.n, side, side, &map.heights);
    let mut wrong = good.clone();
    wrong[0] = b'X';
    let no_xres = String::from_utf8_lossy(&good)
        .replace("XRes = 256\n", "")
        .into_bytes();
    let mut ragged = grid_csv(&map, 20);
    ragged = ragged.replacen('\n', ",1\n", 4); // the 4th row gains a value
    let ragged = ragged.replacen(",1\n", "\n", 3);
    let cases: Vec<(&str, Vec<u8>, Vec<&str>, &str)> = vec![
        (
            "truncated.gsf",
            good[..good.len() - 6].to_vec(),
            vec![],
            "truncated",
        ),
        (
            "magic.gsf",
            wrong,
            vec![],
            "magic.gsf:1: not a Gwyddion Simple Field",
        ),
        ("noxres.gsf", no_xres, vec![], "missing header field XRes"),
        (
            "ragged.csv",
            ragged.into_bytes(),
            // the heights are in µm (read as metres they are refused first, at row 1)
            vec!["--pixel-size", "0.5um", "--height-unit", "um"],
            "ragged.csv:4: ragged row",
        ),
        (
            "small.csv",
            grid_csv(&map, 5).into_bytes(),
            vec!["--pixel-size", "0.5um", "--height-unit", "um"],
            "small.csv:5: the grid ends after 5 row(s)",
        ),
        (
            "unit.csv",
            grid_csv(&map, 20).into_bytes(),
            vec!["--pixel-size", "0.5um", "--height-unit", "bar"],
            "--height-unit",
        ),
        (
            "pixel.gsf",
            good.clone(),
            vec!["--pixel-size", "0.5um"],
            "--pixel-size only applies to a CSV height grid",
        ),
    ];
    for (name, bytes, flags, needle) in cases {
        let path = dir.path().join(name);
        fs::write(&path, bytes).unwrap();
        cargo_bin_cmd!("sealsim")
            .arg("surface")
            .arg(&path)
            .args(flags)
            .arg("-o")
            .arg(&out)
            .arg("--plot")
            .arg(&plot)
            .assert()
            .code(2)
            .stderr(predicate::str::contains(needle))
            .stderr(predicate::str::contains("panicked").not());
        assert!(!out.exists() && !plot.exists(), "{name}: nothing written");
    }
}
