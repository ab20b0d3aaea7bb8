//! Issue 30's traps, one by one: each slip a seal engineer made writing scenarios from the
//! README and `--help` alone that used to run a *different seal* with exit 0. Each now exits 2
//! naming file:line:key with a suggestion that the program accepts (re-run here), writing
//! nothing — or, for a default, behaves as an engineer expects. Traps with their own test
//! elsewhere are named there: gland stretch and fill (`gland.rs`), fit-prony's units row, short
//! tests, fractional terms per decade and `--like` (`fit.rs`), ageing on by default
//! (`rubber.rs`), studies that finish (`study.rs`).

use crate::support::{sealsim, shipped};
use std::path::{Path, PathBuf};

/// `sealsim ARGS` in `dir`: (exit code, stdout, stderr).
fn sealsim_in(dir: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let out = sealsim().current_dir(dir).args(args).output().unwrap();
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The first `"…"` of `message` after `marker`: the fix a message suggests.
fn suggested(message: &str, marker: &str) -> String {
    let after = &message[message.find(marker).unwrap() + marker.len()..];
    let start = after.find('"').unwrap() + 1;
    let end = start + after[start..].find('"').unwrap();
    after[start..end].to_owned()
}

/// Writes `text` as `s.toml` in `dir`, runs `sealsim run` on it with a history output, and
/// returns (exit code, stderr, whether the output exists).
fn run_text(dir: &Path, text: &str) -> (Option<i32>, String, bool) {
    std::fs::write(dir.join("s.toml"), text).unwrap();
    let out = dir.join("h.csv");
    let _ = std::fs::remove_file(&out);
    // --verbose: the warnings in full, which these tests read
    let (code, _, stderr) = sealsim_in(dir, &["run", "s.toml", "--verbose", "-o", "h.csv"]);
    (code, stderr, out.exists())
}

/// `pressure_difference = 210` (meant bar), `width = 10  # mm`, `groove_width = 4.8  # mm`:
/// refused at their line with the units engineers use; the first suggestion runs.
#[test]
fn bare_pressures_and_lengths_are_refused_and_the_suggested_unit_runs() {
    let dir = tempfile::tempdir().unwrap();
    let base = shipped("oring-nbr-water-80c.toml");
    for (from, to, line_key, unit_word) in [
        (
            "pressure_difference = \"2 bar\"",
            "pressure_difference = 210",
            ":25: fluid.pressure_difference: a pressure needs its unit",
            "bar",
        ),
        (
            "groove_width = \"4.8 mm\"",
            "groove_width = 4.8  # mm",
            ":32: seal.groove_width: a length needs its unit",
            "mm",
        ),
    ] {
        assert!(base.contains(from), "{from}");
        let (code, stderr, written) = run_text(dir.path(), &base.replacen(from, to, 1));
        assert_eq!(code, Some(2), "{to}: {stderr}");
        assert!(stderr.contains(&format!("s.toml{line_key}")), "{stderr}");
        assert!(!written);
        let fix = suggested(&stderr, "write ");
        assert!(fix.ends_with(unit_word), "{fix}");
        let key = to.split(" = ").next().unwrap();
        let (code, stderr, written) = run_text(
            dir.path(),
            &base.replacen(from, &format!("{key} = \"{fix}\""), 1),
        );
        assert_eq!(code, Some(0), "{fix}: {stderr}");
        assert!(written);
    }
    // a flat seal's width (`[seal] kind = "flat"`): the same rule
    let flat = shipped("gasket-nbr-dirty-oil.toml");
    let width = flat
        .lines()
        .find(|l| l.starts_with("width = "))
        .unwrap()
        .to_owned();
    let (code, stderr, written) =
        run_text(dir.path(), &flat.replacen(&width, "width = 10  # mm", 1));
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("seal.width: a length needs its unit"),
        "{stderr}"
    );
    assert!(!written);
}

/// A temperature history without its units row used to be read in kelvin (20 → 20 K).
#[test]
fn a_history_without_its_units_row_is_refused_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let text = shipped("cold-night-nbr.toml");
    std::fs::write(
        dir.path().join("cold-night.csv"),
        "time,temperature\n0,20\n24,20\n",
    )
    .unwrap();
    let (code, stderr, written) = run_text(dir.path(), &text);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("cold-night.csv:2"), "{stderr}");
    assert!(stderr.contains("units row"), "{stderr}");
    assert!(!written);
    // with the row it names, the run goes
    std::fs::write(
        dir.path().join("cold-night.csv"),
        "time,temperature\nh,C\n0,20\n24,20\n",
    )
    .unwrap();
    let (code, stderr, _) = run_text(dir.path(), &text);
    assert_eq!(code, Some(0), "{stderr}");
}

/// `run same.toml -o same.toml` replaced the scenario; `--plot x.svg --report x.svg` wrote
/// x.svg twice.
#[test]
fn an_output_onto_an_input_or_another_output_is_refused_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let text = shipped("oring-nbr-water-80c.toml");
    std::fs::write(dir.path().join("same.toml"), &text).unwrap();
    let (code, _, stderr) = sealsim_in(dir.path(), &["run", "same.toml", "-o", "same.toml"]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("-o same.toml: that is an input"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("same.toml")).unwrap(),
        text
    );
    let (code, _, stderr) = sealsim_in(
        dir.path(),
        &[
            "run",
            "same.toml",
            "-o",
            "h.csv",
            "--plot",
            "x.svg",
            "--report",
            "x.svg",
        ],
    );
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("--report x.svg: --plot writes the same file"),
        "{stderr}"
    );
    let names: Vec<PathBuf> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(names.len(), 1, "{names:?}");
}

/// Helium leak testing: the trade's units on the command line and in `[failure]`; `leak` on a
/// gas prints mbar·L/s and says permeation is not in it.
#[test]
fn leak_test_units_are_accepted_where_rates_are_and_leak_says_what_it_leaves_out() {
    let dir = tempfile::tempdir().unwrap();
    let gasket =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/helium-leak-test-gasket.toml");
    let gasket = gasket.to_str().unwrap();
    for floor in [
        "1e-9 mbar*L/s",
        "1e-8 atm*cc/s",
        "1e-8 std cc/s",
        "1e-6 sccm",
    ] {
        let (code, stdout, stderr) = sealsim_in(
            dir.path(),
            &["run", gasket, "--leak-floor", floor, "--summary", "s.json"],
        );
        assert_eq!(code, Some(0), "{floor}: {stderr}");
        let _ = stdout;
    }
    // a bare number is refused, naming the units
    let (code, _, stderr) = sealsim_in(dir.path(), &["run", gasket, "--leak-floor", "1e-9"]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(stderr.contains("mbar*L/s"), "{stderr}");
    // a throughput for a liquid is refused, naming a volume flow that works
    let water = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml");
    let water = water.to_str().unwrap();
    let (code, _, stderr) =
        sealsim_in(dir.path(), &["run", water, "--leak-floor", "1e-9 mbar*L/s"]);
    assert_eq!(code, Some(2), "{stderr}");
    let fix = suggested(&stderr, "e.g. ");
    let (code, _, stderr) = sealsim_in(
        dir.path(),
        &["run", water, "--leak-floor", &fix, "-o", "h.csv"],
    );
    assert_eq!(code, Some(0), "{fix}: {stderr}");
    // drops per minute for a liquid
    let (code, _, stderr) = sealsim_in(
        dir.path(),
        &["run", water, "--leak-floor", "1 drops/min", "-o", "h2.csv"],
    );
    assert_eq!(code, Some(0), "{stderr}");
    // `leak` on a gas: both units, and what is not in them
    let (code, stdout, stderr) =
        sealsim_in(dir.path(), &["leak", gasket, "--pressures", "0.1 MPa"]);
    assert_eq!(code, Some(0), "{stderr}");
    let header = stdout.lines().next().unwrap();
    assert!(
        header.ends_with("throughput_Pa_m3_per_s,throughput_mbar_L_per_s"),
        "{header}"
    );
    let row: Vec<f64> = stdout
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .rev()
        .take(2)
        .map(|c| c.parse().unwrap())
        .collect();
    // 1 mbar·L/s = 0.1 Pa·m³/s
    assert!((row[0] / (10.0 * row[1]) - 1.0).abs() < 1e-12, "{row:?}");
    assert!(
        stderr.contains("permeation through the rubber is not in them"),
        "{stderr}"
    );
}

/// A gas scenario at 1 K was accepted and ended in an internal error (an infinite permeation
/// time lag); now refused at the temperature's line with a temperature that runs.
#[test]
fn a_gas_colder_than_its_condensation_point_is_refused_with_a_temperature_that_runs() {
    let dir = tempfile::tempdir().unwrap();
    let text = shipped("hydrogen-line-100bar.toml");
    let line = text
        .lines()
        .find(|l| l.starts_with("temperature = "))
        .unwrap()
        .to_owned();
    let (code, stderr, written) = run_text(
        dir.path(),
        &text.replacen(&line, "temperature = \"1 K\"", 1),
    );
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("environment.temperature: the temperature reaches -272.15 °C (1 K)"),
        "{stderr}"
    );
    assert!(!written);
    let fix = suggested(&stderr, "e.g. ");
    let (code, stderr, _) = run_text(
        dir.path(),
        &text.replacen(&line, &format!("temperature = \"{fix}\""), 1),
    );
    assert_eq!(code, Some(0), "{fix}: {stderr}");
    assert!(!stderr.contains("internal error"), "{stderr}");
}

/// Warnings printed K for an input in °C; a long callout note was a `warning:` repeated per
/// compound; a fully set ring's force printed as "2.32e-42 N/mm (6.23e-41 % retained)".
#[test]
fn messages_speak_the_inputs_terms_notes_are_notes_once_and_nothing_prints_below_meaning() {
    let dir = tempfile::tempdir().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    // the glass-transition warning of a -40 °C night: in °C, kelvin beside
    let cold = root.join("cold-night-nbr.toml");
    let (code, _, stderr) = sealsim_in(
        dir.path(),
        &["run", cold.to_str().unwrap(), "--verbose", "-o", "c.csv"],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stderr.contains("T = -40 °C (233.1 K) is below"), "{stderr}");
    // the callout note: a note, once for three compounds
    let water = root.join("oring-nbr-water-80c.toml");
    let (code, _, stderr) = sealsim_in(
        dir.path(),
        &[
            "compare",
            water.to_str().unwrap(),
            "--verbose",
            "--materials",
            "nbr-70,fkm-75,vmq-70",
            "-o",
            "c.csv",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stderr.matches("surface.ra: callout").count(), 1, "{stderr}");
    assert!(stderr.contains("note[N001]: "), "{stderr}");
    assert!(
        !stderr
            .lines()
            .any(|l| l.starts_with("warning") && l.contains("callout")),
        "{stderr}"
    );
    // a compound without ageing constants in a scenario that ages (a file compound: every
    // library one has them): its row says so, the comparison goes on
    std::fs::write(dir.path().join("soft.toml"), crate::support::SOFT_MATERIAL).unwrap();
    let (code, _, stderr) = sealsim_in(
        dir.path(),
        &[
            "compare",
            water.to_str().unwrap(),
            "--materials",
            "nbr-70,soft.toml",
            "-o",
            "c2.csv",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    let table = std::fs::read_to_string(dir.path().join("c2.csv")).unwrap();
    let soft = table.lines().find(|l| l.contains("soft")).unwrap();
    assert!(soft.contains("no ageing constants"), "{soft}");
    // a fully set ring: "≈ 0 N/mm" in the summary, the figure in the CSV
    let base = shipped("studies/as568-225-face-water-80c.toml")
        .replace(
            "lift_off = true",
            "lift_off = false\nlost_interference = false\nextrusion = false",
        )
        .replace("max_leak_rate = \"1e-11 m^3/s\"", "")
        .replace("max_leaked_volume = \"0.5 L\"", "");
    std::fs::write(dir.path().join("set.toml"), base).unwrap();
    let (code, stdout, stderr) = sealsim_in(dir.path(), &["run", "set.toml", "-o", "set.csv"]);
    assert_eq!(code, Some(0), "{stderr}");
    let force = stdout
        .lines()
        .find(|l| l.starts_with("sealing force"))
        .unwrap();
    assert!(force.contains("≈ 0 N/mm"), "{force}");
    assert!(!force.contains("e-"), "{force}");
    let csv = std::fs::read_to_string(dir.path().join("set.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "sealing_force_N_per_m")
        .unwrap();
    let last: f64 = csv
        .lines()
        .last()
        .unwrap()
        .split(',')
        .nth(col)
        .unwrap()
        .parse()
        .unwrap();
    assert!((0.0..1e-6).contains(&last), "{last}");
}

/// Plausible ranges: a library compound run above its class's rated temperature is warned at
/// the temperature's line, in °C, naming the rating and its source.
#[test]
fn a_compound_above_its_rated_temperature_is_warned() {
    let dir = tempfile::tempdir().unwrap();
    let text = shipped("oring-nbr-water-80c.toml");
    let (code, stderr, _) = run_text(
        dir.path(),
        &text.replacen("temperature = \"80 C\"", "temperature = \"120 C\"", 1),
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stderr.contains(
            "environment.temperature: the temperature reaches 120 °C (393.1 K), 20 K above the \
             rated 100 °C (373.1 K)"
        ),
        "{stderr}"
    );
    assert!(stderr.contains("Bode Seal"), "{stderr}");
    // at its 80 °C: no such warning
    let (_, stderr, _) = run_text(dir.path(), &text);
    assert!(!stderr.contains("above the rated"), "{stderr}");
}
