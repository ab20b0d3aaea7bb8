//! `[surface] height_map`: a measured (here: synthesized) grid of heights as the surface of a
//! scenario. The analytic levels get its PSD estimate, the numerical level the map itself;
//! every malformed map exits with status 2 and names the map file and its line.

use assert_cmd::cargo::cargo_bin_cmd;
use predicates::prelude::*;
use sealsim::numerical::HeightMap;
use sealsim::numerical::surface::synthesize;
use sealsim::scenario::Scenario;
use sealsim::surface::Spectrum;
use std::fs;
use std::path::PathBuf;
use tempfile::TempDir;

/// Grid side of the test maps (64 µm at 0.5 µm pixels).
const N: usize = 128;

/// A periodic surface of H = 0.8, h_rms = 1 µm on q0 … π/pixel with 0.5 µm pixels.
fn synthetic_map(seed: u64) -> HeightMap {
    let pixel = 0.5e-6;
    let q0 = 2.0 * std::f64::consts::PI / (N as f64 * pixel);
    let q1 = std::f64::consts::PI / pixel;
    let spectrum = Spectrum::self_affine(1e-6, 0.8, q0, q1, None).unwrap();
    let map = synthesize(&spectrum, N, seed);
    assert!((map.pixel / pixel - 1.0).abs() < 1e-12);
    map
}

/// The map as CSV, heights divided by `unit` (1 for metres, 1e-6 for µm), a comment line
/// first.
fn csv(map: &HeightMap, unit: f64) -> String {
    let mut text = String::from("# synthesized height map\n");
    for row in map.heights.chunks(map.n) {
        let cells: Vec<String> = row.iter().map(|h| format!("{:e}", h / unit)).collect();
        text.push_str(&cells.join(","));
        text.push('\n');
    }
    text
}

/// A scenario with `surface` as its `[surface]` table (line 6 on) next to the map file.
fn scenario_text(surface: &str) -> String {
    format!(
        "name = \"height map\"\n\
         [material]\n\
         youngs_modulus = \"10 MPa\"\n\
         poisson_ratio = 0.5\n\
         [surface]\n\
         {surface}\n\
         [fluid]\n\
         viscosity = \"1e-3 Pa*s\"\n\
         pressure_difference = \"0.01 MPa\"\n\
         [seal]\n\
         nominal_pressure = \"0.2 MPa\"\n\
         width = \"1 mm\"\n\
         length = \"1 mm\"\n"
    )
}

/// A tempdir with `scenario.toml` and `map.csv`.
struct Case {
    dir: TempDir,
}

impl Case {
    fn new(surface: &str, map: &str) -> Case {
        let dir = TempDir::new().unwrap();
        fs::write(dir.path().join("scenario.toml"), scenario_text(surface)).unwrap();
        fs::write(dir.path().join("map.csv"), map).unwrap();
        Case { dir }
    }

    /// The standard surface table with the given map text.
    fn with_map(map: &str) -> Case {
        Case::new(
            "height_map = \"map.csv\"\npixel_size = \"0.5 um\"\nheight_unit = \"m\"",
            map,
        )
    }

    fn scenario(&self) -> PathBuf {
        self.dir.path().join("scenario.toml")
    }

    fn output(&self) -> PathBuf {
        self.dir.path().join("out.csv")
    }

    /// `sealsim leak scenario.toml -o out.csv` must exit 2 with every needle in stderr, no
    /// panic and no output file.
    fn rejects(&self, needles: &[&str]) {
        let assert = cargo_bin_cmd!("sealsim")
            .arg("leak")
            .arg(self.scenario())
            .arg("-o")
            .arg(self.output())
            .assert()
            .code(2)
            .stdout(predicate::str::is_empty())
            .stderr(predicate::str::contains("panicked").not());
        let stderr = String::from_utf8(assert.get_output().stderr.clone()).unwrap();
        for needle in needles {
            assert!(
                stderr.contains(needle),
                "stderr lacks {needle:?}:\n{stderr}"
            );
        }
        assert!(!self.output().exists(), "the -o file was created");
    }
}

#[test]
fn scenario_spectrum_carries_the_maps_roughness_and_leak_runs() {
    let map = synthetic_map(3);
    let case = Case::with_map(&csv(&map, 1.0));
    let scenario = Scenario::load(&case.scenario()).unwrap();
    let spectrum = &scenario.problem.spectrum;
    let h_rms = spectrum.rms_roughness();
    assert!(
        (h_rms / map.rms() - 1.0).abs() < 0.02,
        "spectrum h_rms {h_rms} vs map {}",
        map.rms()
    );
    assert_eq!(scenario.life.spectrum, *spectrum);
    // The band: from q0/√π (the lattice cells of the map) to the Nyquist wavevector π/pixel.
    let q0 = 2.0 * std::f64::consts::PI / map.side();
    assert!((spectrum.q0() * std::f64::consts::PI.sqrt() / q0 - 1.0).abs() < 1e-9);
    assert!((spectrum.q1() * 0.5e-6 / std::f64::consts::PI - 1.0).abs() < 1e-9);
    // The map itself is kept, in SI units.
    let kept = scenario.height_map.as_ref().expect("the map is kept");
    assert_eq!((kept.n, kept.pixel), (N, 0.5e-6));
    for (a, b) in kept.heights.iter().zip(&map.heights) {
        assert!((a - b).abs() <= 1e-15 * map.rms());
    }

    let out = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(case.scenario())
        .args(["--pressures", "0.1MPa,0.5MPa"])
        .assert()
        .success();
    let stdout = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    let rows: Vec<&str> = stdout.lines().collect();
    assert!(rows[0].starts_with("nominal_pressure_Pa,"), "{stdout}");
    assert_eq!(rows.len(), 3, "{stdout}");
    for row in &rows[1..] {
        assert!(!row.contains("NaN") && !row.contains("inf"), "{row}");
    }
}

#[test]
fn heights_in_micrometres_and_a_band_restriction() {
    let map = synthetic_map(5);
    let q0 = 2.0 * std::f64::consts::PI / map.side();
    let surface = format!(
        "height_map = \"data/map.csv\"\npixel_size = \"0.5 um\"\nheight_unit = \"um\"\n\
         q0 = \"{:e} 1/m\"\nq1 = \"{:e} 1/m\"",
        q0,
        16.0 * q0
    );
    let case = Case::new(&surface, "");
    fs::create_dir(case.dir.path().join("data")).unwrap();
    fs::write(case.dir.path().join("data/map.csv"), csv(&map, 1e-6)).unwrap();
    let scenario = Scenario::load(&case.scenario()).unwrap();
    let kept = scenario.height_map.unwrap();
    assert!((kept.rms() / map.rms() - 1.0).abs() < 1e-12);
    let spectrum = &scenario.problem.spectrum;
    assert!((spectrum.q0() / q0 - 1.0).abs() < 1e-9);
    assert!((spectrum.q1() / (16.0 * q0) - 1.0).abs() < 1e-9);
    // The restricted band lacks the map's power below q0 and above 16 q0.
    assert!(spectrum.rms_roughness() < kept.rms());
}

/// Replaces the `index`-th data row of the map (line `index + 2` of the file).
fn with_row(map: &HeightMap, index: usize, row: &str) -> String {
    let text = csv(map, 1.0);
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    lines[index + 1] = row.to_owned();
    lines.join("\n") + "\n"
}

#[test]
fn a_text_cell_is_located() {
    let map = synthetic_map(1);
    let text = csv(&map, 1.0);
    let row = format!(
        "abc,{}",
        text.lines().nth(5).unwrap().split_once(',').unwrap().1
    );
    let case = Case::with_map(&with_row(&map, 4, &row));
    case.rejects(&[
        "map.csv:6: surface.height_map: column 1: not a number: \"abc\"",
        "scenario.toml:6",
    ]);
}

#[test]
fn a_ragged_row_is_located() {
    let map = synthetic_map(1);
    let row = csv(&map, 1.0).lines().nth(10).unwrap().to_owned() + ",1e-6";
    let case = Case::with_map(&with_row(&map, 9, &row));
    case.rejects(&[
        "map.csv:11: surface.height_map: ragged row: 129 values",
        "scenario.toml:6",
    ]);
}

#[test]
fn a_rectangular_grid_is_accepted_and_too_few_rows_are_located() {
    let map = synthetic_map(1);
    // the first 100 rows of 128: a 128 × 100 map (its spectrum from the whole map; the
    // numerical level's crop named in a note)
    let text: String = csv(&map, 1.0)
        .lines()
        .take(101)
        .map(|l| format!("{l}\n"))
        .collect();
    let case = Case::with_map(&text);
    let scenario = Scenario::load(&case.scenario()).unwrap();
    let crop = scenario.height_map.as_ref().unwrap();
    assert_eq!(crop.n, 100, "the centred even square crop");
    assert_eq!(
        crop.heights[0], map.heights[14],
        "starts at column 15 of row 1"
    );
    let out = cargo_bin_cmd!("sealsim")
        .arg("leak")
        .arg(case.scenario())
        .arg("--verbose") // the note says how the map was cropped
        .assert()
        .success();
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.contains("the map is 128 × 100 pixels")
            && stderr.contains("centred 100 × 100 crop (columns 15–114, rows 1–100)"),
        "{stderr}"
    );
    // h_rms of the spectrum is the (levelled) rectangle's own, close to the whole map's
    let h = scenario.problem.spectrum.rms_roughness();
    assert!((h / map.rms() - 1.0).abs() < 0.3, "{h} vs {}", map.rms());

    let text: String = csv(&map, 1.0)
        .lines()
        .take(8)
        .map(|l| format!("{l}\n"))
        .collect();
    Case::with_map(&text).rejects(&[
        "map.csv:8: surface.height_map: the grid ends after 7 row(s)",
        "scenario.toml:6",
    ]);
}

/// The map as a Gwyddion Simple Field file (heights rounded to f32 by the format).
fn gsf(map: &HeightMap) -> Vec<u8> {
    let side = map.n as f64 * map.pixel;
    sealsim::scenario::gsf::write(map.n, map.n, side, side, &map.heights)
}

#[test]
fn a_gsf_map_gives_the_same_spectrum_as_its_csv() {
    let map = synthetic_map(2);
    let case = Case::with_map(&csv(&map, 1.0));
    fs::write(case.dir.path().join("map.gsf"), gsf(&map)).unwrap();
    let from_csv = Scenario::load(&case.scenario()).unwrap();
    fs::write(case.scenario(), scenario_text("height_map = \"map.gsf\"")).unwrap();
    let from_gsf = Scenario::load(&case.scenario()).unwrap();
    let (a, b) = (&from_csv.problem.spectrum, &from_gsf.problem.spectrum);
    assert!((a.q0() / b.q0() - 1.0).abs() < 1e-12 && (a.q1() / b.q1() - 1.0).abs() < 1e-12);
    // f32 rounding of the heights only
    assert!((a.rms_roughness() / b.rms_roughness() - 1.0).abs() < 1e-6);
    assert_eq!(from_gsf.height_map.as_ref().unwrap().n, N);
}

#[test]
fn bad_gsf_maps_are_named() {
    let map = synthetic_map(1);
    let good = gsf(&map);
    let with = |surface: &str, bytes: &[u8]| {
        let case = Case::new(surface, "");
        fs::write(case.dir.path().join("map.gsf"), bytes).unwrap();
        case
    };
    let plain = "height_map = \"map.gsf\"";
    with(plain, &good[..good.len() - 10]).rejects(&[
        "map.gsf: surface.height_map: XRes × YRes = 128 × 128 needs 65536 bytes",
        "truncated",
        "scenario.toml:6",
    ]);
    let mut wrong = good.clone();
    wrong[..8].copy_from_slice(b"Gwiddion");
    with(plain, &wrong).rejects(&["map.gsf:1: surface.height_map: not a Gwyddion Simple Field"]);
    let text = String::from_utf8_lossy(&good).replace("XRes = 128\n", "");
    with(plain, text.as_bytes())
        .rejects(&["map.gsf: surface.height_map: missing header field XRes"]);
    with("height_map = \"map.gsf\"\npixel_size = \"0.5 um\"", &good)
        .rejects(&["scenario.toml:7: surface.pixel_size: a .gsf height map states its pixel size"]);
}

#[test]
fn a_non_finite_or_tiny_grid_is_refused() {
    let map = synthetic_map(1);
    let row = csv(&map, 1.0)
        .lines()
        .nth(3)
        .unwrap()
        .replacen(',', ",NaN,", 1);
    let row = row.rsplit_once(',').unwrap().0.to_owned();
    Case::with_map(&with_row(&map, 2, &row))
        .rejects(&["map.csv:4: surface.height_map: column 2: the height must be finite"]);
    // heights in metres within the readers' ±10 mm bound (issue 42): the size is what fails
    let tiny = "0,1e-6,2e-6,3e-6\n1e-6,2e-6,3e-6,4e-6\n2e-6,3e-6,4e-6,5e-6\n3e-6,4e-6,5e-6,6e-6\n";
    Case::with_map(tiny).rejects(&["map.csv:1: surface.height_map: 4 value(s) per row"]);
}

#[test]
fn missing_pixel_size_is_named() {
    let map = synthetic_map(1);
    let case = Case::new("height_map = \"map.csv\"", &csv(&map, 1.0));
    case.rejects(&["scenario.toml:6: surface.height_map: needs pixel_size"]);
}

#[test]
fn height_map_excludes_the_other_spectra() {
    let map = synthetic_map(1);
    let case = Case::new(
        "height_map = \"map.csv\"\npixel_size = \"0.5 um\"\nhurst_exponent = 0.8",
        &csv(&map, 1.0),
    );
    case.rejects(&[
        "scenario.toml:8: surface.hurst_exponent: height_map gives the whole surface; remove",
    ]);
    let case = Case::new(
        "psd_file = \"p.csv\"\nheight_map = \"map.csv\"\npixel_size = \"0.5 um\"",
        &csv(&map, 1.0),
    );
    case.rejects(&["scenario.toml:6: surface.psd_file: height_map gives the whole surface"]);
    let case = Case::new(
        "rms_roughness = \"1 um\"\nhurst_exponent = 0.8\nq0 = \"1e5 1/m\"\nq1 = \"1e7 1/m\"\n\
         pixel_size = \"0.5 um\"",
        "",
    );
    case.rejects(&["scenario.toml:10: surface.pixel_size: only applies to a height map"]);
}

#[test]
fn unreadable_map_and_bad_unit_are_named() {
    let case = Case::new(
        "height_map = \"nothere.csv\"\npixel_size = \"0.5 um\"\nheight_unit = \"um\"",
        "",
    );
    case.rejects(&[
        "scenario.toml:6: surface.height_map: cannot read height map",
        "nothere.csv",
    ]);
    let map = synthetic_map(1);
    let case = Case::new(
        "height_map = \"map.csv\"\npixel_size = \"0.5 um\"\nheight_unit = \"MPa\"",
        &csv(&map, 1.0),
    );
    case.rejects(&["scenario.toml:8: surface.height_unit: expected a length unit"]);
    let case = Case::new(
        "height_map = \"map.csv\"\npixel_size = \"0.5 MPa\"",
        &csv(&map, 1.0),
    );
    case.rejects(&["scenario.toml:7: surface.pixel_size: expected a length"]);
    // without height_unit: refused (a bare height could be m or µm), with a fix that works
    let case = Case::new(
        "height_map = \"map.csv\"\npixel_size = \"0.5 um\"",
        &csv(&map, 1.0),
    );
    case.rejects(&["scenario.toml:6: surface.height_map: needs height_unit"]);
}

#[test]
fn the_numerical_level_runs_on_the_measured_map_itself() {
    // The map is the single realisation: no band-limited warning, the same bits on a second
    // run, and a leak rate that falls with pressure (the map is 128² here).
    let map = synthetic_map(5);
    let case = Case::with_map(&csv(&map, 1.0));
    let run = || {
        let out = cargo_bin_cmd!("sealsim")
            .arg("leak")
            .arg(case.scenario())
            .args(["--fidelity", "numerical", "--pressures", "0.05MPa,0.2MPa"])
            .assert()
            .success();
        let o = out.get_output();
        (
            String::from_utf8(o.stdout.clone()).unwrap(),
            String::from_utf8(o.stderr.clone()).unwrap(),
        )
    };
    let (stdout, stderr) = run();
    assert!(!stderr.contains("resolves q1/q0"), "{stderr}");
    assert_eq!(run().0, stdout);
    let rates: Vec<f64> = stdout
        .lines()
        .skip(1)
        .map(|row| row.split(',').nth(6).unwrap().parse().unwrap())
        .collect();
    assert_eq!(rates.len(), 2);
    assert!(rates[0] > rates[1] && rates[1] >= 0.0, "{rates:?}");
}

/// `sealsim leak scenario.toml` of `case`: (status, stderr).
fn leak_stderr(dir: &std::path::Path) -> (Option<i32>, String) {
    let out = cargo_bin_cmd!("sealsim")
        .current_dir(dir)
        .args(["leak", "scenario.toml", "--verbose"])
        .output()
        .unwrap();
    (out.status.code(), String::from_utf8(out.stderr).unwrap())
}

/// Issue 42: a height map in µm with `height_unit = "m"` (the review's slip: rms ≈ 1 m over
/// 0.5 µm pixels) is refused by the readers' ±10 mm bound, naming the height unit; read as mm
/// (heights within the bound, slopes of ~10³) it warns (W044) with the likely slip and the fix
/// at the height_unit line; the same file with the right unit, and the map in metres, do not.
/// Fails on the old code (no warning, no refusal).
#[test]
fn a_height_map_in_micrometres_read_as_metres_warns_with_the_slip() {
    let map = synthetic_map(3);
    let in_um = csv(&map, 1e-6);
    let slipped = Case::with_map(&in_um);
    let (code, stderr) = leak_stderr(slipped.dir.path());
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("the likely slip is the height unit"),
        "{stderr}"
    );
    let as_mm = Case::new(
        "height_map = \"map.csv\"\npixel_size = \"0.5 um\"\nheight_unit = \"mm\"",
        &in_um,
    );
    let (code, stderr) = leak_stderr(as_mm.dir.path());
    assert_eq!(code, Some(0), "{stderr}");
    let line = stderr
        .lines()
        .find(|l| l.contains("heights look like"))
        .unwrap_or_else(|| panic!("no unit-slip warning:\n{stderr}"));
    assert!(line.starts_with("warning[W044]: "), "{line}");
    assert!(line.contains("surface.height_unit"), "{line}");
    assert!(line.contains("heights look like µm read as mm"), "{line}");
    assert!(line.contains("write height_unit = \"um\""), "{line}");
    for good in [
        Case::new(
            "height_map = \"map.csv\"\npixel_size = \"0.5 um\"\nheight_unit = \"um\"",
            &in_um,
        ),
        Case::with_map(&csv(&map, 1.0)),
    ] {
        let (code, stderr) = leak_stderr(good.dir.path());
        assert_eq!(code, Some(0), "{stderr}");
        assert!(!stderr.contains("heights look"), "{stderr}");
    }
}

/// The same for line traces: the shipped fine-ground trace (x in mm, z in µm) with its units
/// row saying `mm,m` warns that the heights look 10⁶ times too large for their unit.
#[test]
fn a_trace_in_micrometres_under_a_unit_of_metres_warns() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let scenario = fs::read_to_string(root.join("oring-nbr-water-80c-trace.toml")).unwrap();
    let trace = fs::read_to_string(root.join("traces/ground-fine.csv")).unwrap();
    for (units, warns) in [("mm,um", false), ("mm,m", true)] {
        let dir = TempDir::new().unwrap();
        fs::create_dir(dir.path().join("traces")).unwrap();
        fs::write(dir.path().join("scenario.toml"), &scenario).unwrap();
        fs::write(
            dir.path().join("traces/ground-fine.csv"),
            trace.replacen("\nmm,um\n", &format!("\n{units}\n"), 1),
        )
        .unwrap();
        let (code, stderr) = leak_stderr(dir.path());
        let warning = stderr.lines().find(|l| l.contains("heights look"));
        assert_eq!(warning.is_some(), warns, "{units}: {code:?}\n{stderr}");
        if let Some(line) = warning {
            assert!(line.starts_with("warning[W044]: "), "{line}");
            assert!(
                line.contains("heights look 1.0e6 times too large"),
                "{line}"
            );
            assert!(line.contains("surface.profile"), "{line}");
        }
    }
}
