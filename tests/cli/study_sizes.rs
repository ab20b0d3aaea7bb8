//! Issue 41, item 4: studies over sizes and fits — `"seal.size"` as a study input with the B10
//! of each size, a ring drawn within its own size's AS568 tolerance (`tolerance = "size"`), and
//! `tolerances = "fits"` drawing every dimension the base gives a tolerance for.

use crate::support::{read_csv, sealsim};
use sealsim::scenario::study::Study;

/// The new-user review's piston ring, AS568-214 NBR 70 in a 31.75 mm (1.250 in) bore at 80 °C,
/// 210 bar of ISO VG 46 with one back-up ring (its groove depth with a tolerance).
const BASE: &str = r#"name = "AS568-214 NBR piston"

[material]
library = "nbr-70"

[surface]
ra = "0.4 um"

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
min_retained_force = 0.1

[simulation]
duration = "10 year"
"#;

const SIZES: [&str; 3] = ["AS568-213", "AS568-214", "AS568-215"];

fn study(dir: &std::path::Path, name: &str, extra: &str, vary: &str) -> std::path::PathBuf {
    std::fs::write(dir.join("base.toml"), BASE).unwrap();
    let path = dir.join(format!("{name}.study.toml"));
    std::fs::write(
        &path,
        format!(
            "name = \"{name}\"\nbase = \"base.toml\"\ndesign = \"monte-carlo\"\nsamples = 60\n\
             seed = 3\n{extra}\n[vary]\n{vary}"
        ),
    )
    .unwrap();
    path
}

/// Three sizes with every tolerance drawn (`tolerances = "fits"`): the summary gives the B10 of
/// each size, each equal to the Kaplan–Meier B10 of that size's cases recomputed here from the
/// case table (every case fails: B10 is the ⌈n/10⌉-th smallest life), the case counts add up,
/// and the JSON says the same.
#[test]
fn a_study_over_three_sizes_and_their_fits_gives_b10_per_size() {
    let dir = tempfile::tempdir().unwrap();
    study(
        dir.path(),
        "sizes",
        "tolerances = \"fits\"\n",
        &format!(
            "\"seal.size\" = {{ values = {SIZES:?} }}\n\"environment.temperature\" = {{ \
             distribution = \"normal\", mean = \"80 C\", std = \"5 K\" }}\n"
        ),
    );
    let (csv, json) = (dir.path().join("cases.csv"), dir.path().join("s.json"));
    let stdout = run_study(dir.path(), "sizes");
    let (header, rows) = read_csv(&csv);
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    // every dimension with a tolerance is an input: the ring within its size's, the groove depth
    for name in [
        "seal.cross_section_tolerance_fraction",
        "seal.inner_diameter_tolerance_fraction",
        "seal.groove_depth_m",
    ] {
        let k = col(name);
        let values: Vec<f64> = rows.iter().map(|r| r[k].parse().unwrap()).collect();
        assert!(
            values.iter().any(|v| *v != values[0]),
            "{name} is not drawn"
        );
    }
    for r in &rows {
        for name in [
            "seal.cross_section_tolerance_fraction",
            "seal.inner_diameter_tolerance_fraction",
        ] {
            let z: f64 = r[col(name)].parse().unwrap();
            assert!((-1.0..=1.0).contains(&z), "{z}");
        }
    }
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let levels = summary["by_level"].as_array().unwrap();
    assert_eq!(levels.len(), 3);
    let mut total = 0;
    for (level, size) in levels.iter().zip(SIZES) {
        assert_eq!(level["input"], "seal.size");
        assert_eq!(level["level"], size);
        let mut lives: Vec<f64> = rows
            .iter()
            .filter(|r| r[col("seal.size")] == size)
            .map(|r| {
                assert_eq!(
                    r[col("status")],
                    "failed",
                    "the recomputation assumes no survivor"
                );
                r[col("life_s")].parse().unwrap()
            })
            .collect();
        lives.sort_by(f64::total_cmp);
        let n = lives.len();
        assert_eq!(level["cases"].as_u64(), Some(n as u64));
        total += n;
        let b10 = lives[(n as f64 * 0.1).ceil() as usize - 1];
        let got = level["b10_s"].as_f64().unwrap();
        assert!((got / b10 - 1.0).abs() < 1e-12, "{size}: {got} vs {b10}");
        let line = stdout
            .lines()
            .find(|l| l.trim_start().starts_with(size))
            .unwrap_or_else(|| panic!("{stdout}"));
        assert!(line.contains(&format!("{n} of {n} failed")), "{line}");
    }
    assert_eq!(total, rows.len());
    assert!(stdout.contains("B10 by seal.size"), "{stdout}");
}

/// `tolerance = "size"` writes the case's ring out at its size's nominal plus z × its AS568 ±
/// tolerance: z = ±1 gives −214's cross-section 0.139 ± 0.004 in and ID 0.984 ± 0.010 in, and a
/// varied size takes its own nominal and tolerance (−215: ID 1.046 ± 0.010 in).
#[test]
fn a_ring_within_its_size_tolerance_follows_the_case_size() {
    let dir = tempfile::tempdir().unwrap();
    let path = study(
        dir.path(),
        "ring",
        "",
        &format!(
            "\"seal.size\" = {{ values = {SIZES:?} }}\n\"seal.cross_section\" = {{ tolerance = \
             \"size\" }}\n\"seal.inner_diameter\" = {{ tolerance = \"size\", shape = \
             \"uniform\" }}\n"
        ),
    );
    let study = Study::load(&path).unwrap();
    let ring = |size: f64, z_cs: f64, z_id: f64| {
        let s = study.scenario(0, &[size, z_cs, z_id]).unwrap();
        let ring = s.gland.unwrap().ring;
        (ring.cross_section / 25.4e-3, ring.inner_diameter / 25.4e-3)
    };
    let close = |a: (f64, f64), b: (f64, f64)| {
        assert!(
            (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9,
            "{a:?} vs {b:?}"
        )
    };
    close(ring(1.0, 1.0, -1.0), (0.143, 0.974));
    close(ring(1.0, -1.0, 1.0), (0.135, 0.994));
    close(ring(1.0, 0.0, 0.0), (0.139, 0.984));
    close(ring(2.0, 0.0, 1.0), (0.139, 1.056));
    // on another key, or with a nominal, "size" is refused at the key
    let bad = study_err(
        dir.path(),
        "\"seal.groove_depth\" = { tolerance = \"size\" }\n",
    );
    assert!(
        bad.contains("seal.groove_depth") && bad.contains("cross_section"),
        "{bad}"
    );
    let bad = study_err(
        dir.path(),
        "\"seal.cross_section\" = { tolerance = \"size\", nominal = \"3.5 mm\" }\n",
    );
    assert!(bad.contains("remove `nominal`"), "{bad}");
}

/// Runs `NAME.study.toml` in `dir` into `cases.csv` and `s.json` (exit 0) and returns stdout.
fn run_study(dir: &std::path::Path, name: &str) -> String {
    let out = sealsim()
        .current_dir(dir)
        .arg("study")
        .arg(format!("{name}.study.toml"))
        .args(["-o", "cases.csv", "--summary", "s.json"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

fn study_err(dir: &std::path::Path, vary: &str) -> String {
    let path = study(dir, "bad", "", vary);
    let out = sealsim().arg("study").arg(&path).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    String::from_utf8(out.stderr).unwrap()
}

/// `tolerance = "fit"` places the clearance within the case's ISO 286 fit at the 31.75 mm bore:
/// H8/f7 in the 30–50 mm row is H8 +0/+39 µm, f7 −25/−50 µm → 25…89 µm; H11/d10 is H11
/// +0/+160 µm, d10 −80/−180 µm → 80…340 µm (ISO 286-2 tables; independent of the code's).
#[test]
fn a_clearance_within_its_fit_follows_the_case_fit() {
    let dir = tempfile::tempdir().unwrap();
    let path = study(
        dir.path(),
        "fit",
        "",
        "\"seal.fit\" = { values = [\"H8/f7\", \"H11/d10\"] }\n\"seal.diametral_clearance\" = \
         { tolerance = \"fit\" }\n",
    );
    let study = Study::load(&path).unwrap();
    let clearance = |fit: f64, z: f64| {
        let s = study.scenario(0, &[fit, z]).unwrap();
        2.0 * s.gland.unwrap().extrusion_gap * 1e6
    };
    for (fit, z, want) in [
        (0.0, -1.0, 25.0),
        (0.0, 1.0, 89.0),
        (0.0, 0.0, 57.0),
        (1.0, -1.0, 80.0),
        (1.0, 1.0, 340.0),
    ] {
        let got = clearance(fit, z);
        assert!(
            (got - want).abs() < 1e-6,
            "fit {fit} z {z}: {got} µm vs {want}"
        );
    }
    // on another key, with a nominal, or without a fit in the case: refused at the key
    let bad = study_err(
        dir.path(),
        "\"seal.groove_depth\" = { tolerance = \"fit\" }\n",
    );
    assert!(
        bad.contains("seal.groove_depth") && bad.contains("diametral_clearance"),
        "{bad}"
    );
    let bad = study_err(
        dir.path(),
        "\"seal.diametral_clearance\" = { tolerance = \"fit\" }\n",
    );
    assert!(bad.contains("seal.fit"), "{bad}");
}

/// Fit grades as a study input with `tolerances = "fits"`: the loose H11/d10 fit (80…340 µm)
/// opens the clearance past what one back-up ring holds at 210 bar in the upper part of its
/// range, so some of its cases fail at installation by extrusion — exactly those above one
/// threshold of the drawn fraction — while no H8/f7 case (at most 89 µm) does; the summary gives
/// the B10 of each fit, the loose fit's lower bound at the installation.
#[test]
fn a_study_over_fit_grades_gives_b10_per_fit_and_the_loose_fit_extrudes() {
    let dir = tempfile::tempdir().unwrap();
    study(
        dir.path(),
        "fits",
        "tolerances = \"fits\"\n",
        "\"seal.fit\" = { values = [\"H8/f7\", \"H11/d10\"] }\n",
    );
    let stdout = run_study(dir.path(), "fits");
    let (header, rows) = read_csv(&dir.path().join("cases.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (z, fit, mode) = (
        col("seal.diametral_clearance_tolerance_fraction"),
        col("seal.fit"),
        col("mode"),
    );
    let cases: Vec<(String, f64, bool)> = rows
        .iter()
        .map(|r| {
            (
                r[fit].clone(),
                r[z].parse().unwrap(),
                r[mode] == "extrusion",
            )
        })
        .collect();
    assert!(cases.iter().all(|(_, z, _)| (-1.0..=1.0).contains(z)));
    assert!(
        cases.iter().all(|(f, _, e)| f == "H11/d10" || !e),
        "an H8/f7 case extrudes"
    );
    let loose: Vec<&(String, f64, bool)> = cases.iter().filter(|c| c.0 == "H11/d10").collect();
    let lowest_extruded = loose
        .iter()
        .filter(|c| c.2)
        .map(|c| c.1)
        .fold(f64::INFINITY, f64::min);
    let highest_held = loose
        .iter()
        .filter(|c| !c.2)
        .map(|c| c.1)
        .fold(-1.0, f64::max);
    assert!(lowest_extruded.is_finite(), "no H11/d10 case extrudes");
    assert!(
        highest_held < lowest_extruded,
        "{highest_held} held, {lowest_extruded} extruded"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("s.json")).unwrap()).unwrap();
    let levels = summary["by_level"].as_array().unwrap();
    let level = |name: &str| {
        let l = levels.iter().find(|l| l["level"] == name).unwrap();
        assert_eq!(l["input"], "seal.fit");
        l.clone()
    };
    assert_eq!(level("H11/d10")["b10_lower_s"].as_f64(), Some(0.0));
    assert!(level("H8/f7")["b10_lower_s"].as_f64().unwrap() > 0.0);
    assert!(stdout.contains("B10 by seal.fit"), "{stdout}");
}
