//! `sealsim figures` end to end: the PY08 §3 figure set, and bad figure-set input.

use crate::support::sealsim;
use std::fs;
use std::path::Path;

fn column(header: &str, name: &str) -> usize {
    header
        .split(',')
        .position(|c| c == name)
        .expect("column present")
}

#[test]
fn paper_figure_set_writes_every_csv_and_chart() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("figs");
    sealsim()
        .args([
            "figures",
            "scenarios/persson-yang-2008-figures.toml",
            "--out-dir",
        ])
        .arg(&out)
        .assert()
        .success();
    let mut names: Vec<String> = fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 10, "{names:?}");
    for svg in names.iter().filter(|n| n.ends_with(".svg")) {
        let text = fs::read_to_string(out.join(svg)).unwrap();
        assert!(
            text.starts_with("<svg") && text.trim_end().ends_with("</svg>"),
            "{svg}"
        );
    }

    // figs. 6-8: at every pressure the leak rate grows with the roughness (1, 2, 4, 6 µm)
    let csv = fs::read_to_string(out.join("rms-roughness.csv")).unwrap();
    let mut lines = csv.lines();
    let header = lines.next().unwrap();
    assert!(header.starts_with("scenario,nominal_pressure_Pa,"));
    let (p_col, q_col) = (
        column(header, "nominal_pressure_Pa"),
        column(header, "leak_rate_m3_per_s"),
    );
    let rows: Vec<Vec<String>> = lines
        .map(|l| {
            // the scenario name is quoted (it contains commas); split after it
            let (name, rest) = l
                .rsplit_once("\",")
                .map(|(n, r)| (n.trim_start_matches('"'), r))
                .unwrap();
            std::iter::once(name.to_owned())
                .chain(rest.split(',').map(str::to_owned))
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), 4 * 60);
    for i in 0..60 {
        let q: Vec<f64> = (0..4)
            .map(|k| rows[k * 60 + i][q_col].parse().unwrap())
            .collect();
        let p: Vec<&str> = (0..4).map(|k| rows[k * 60 + i][p_col].as_str()).collect();
        assert!(p.windows(2).all(|w| w[0] == w[1]));
        assert!(
            q.windows(2).all(|w| w[1] > w[0]),
            "pressure {}: {q:?}",
            p[0]
        );
    }
}

#[test]
fn bad_figure_set_is_located_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let shipped = fs::read_to_string("scenarios/persson-yang-2008-figures.toml").unwrap();
    let scenarios = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/persson-yang-2008/");
    let bad = shipped
        .replace(
            "plots = [\"u_c_and_hrms_c\"]",
            "plots = [\"u_c_and_friction\"]",
        )
        .replace(
            "\"persson-yang-2008/",
            &format!("\"{}", scenarios.display()),
        );
    let set = dir.path().join("bad-figure-set.toml");
    fs::write(&set, bad).unwrap();
    let out = dir.path().join("figs");
    let assert = sealsim()
        .args(["figures"])
        .arg(&set)
        .arg("--out-dir")
        .arg(&out)
        .assert();
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert.code(2);
    assert!(
        stderr.contains("bad-figure-set.toml:") && stderr.contains("group.plots"),
        "{stderr}"
    );
    assert!(stderr.contains("u_c_and_friction"), "{stderr}");
    assert!(!out.exists(), "nothing is written");
}
