//! `sealsim study`: the life as a distribution (docs/model.md §14). The statistics against a
//! closed-form life distribution, censoring, determinism across threads and shards, merge,
//! the Slurm script, bad input.

use crate::support::sealsim;
use statrs::distribution::{ContinuousCDF, Normal};
use std::path::{Path, PathBuf};

/// The flat seal of a one-term Prony rubber (`run.rs`), WLF at T_ref = 23 °C, the force referred
/// to the installation: it falls to half its installed value at t0·a_T(T),
/// t0 = τ ln(E1/(½(E∞ + E1) − E∞)) = 1e5 s · ln 3; run for `duration`.
fn one_term(duration: &str) -> String {
    format!(
        "{}[simulation]\nduration = \"{duration}\"\n",
        crate::run::one_term_referred("23 C", "0 s")
    )
}

const C1: f64 = 8.86;
const C2: f64 = 101.6;
const SIGMA: f64 = 5.0;

fn t0() -> f64 {
    1e5 * 3f64.ln()
}

/// log10 a_T at T_ref + x.
fn log_shift(x: f64) -> f64 {
    -C1 * x / (C2 + x)
}

/// The temperature offset from T_ref at which the life is `t`.
fn offset_for(t: f64) -> f64 {
    let l = (t / t0()).log10();
    -C2 * l / (C1 + l)
}

struct Dir {
    dir: tempfile::TempDir,
}

impl Dir {
    fn new() -> Self {
        Dir {
            dir: tempfile::tempdir().unwrap(),
        }
    }
    fn path(&self, name: &str) -> PathBuf {
        self.dir.path().join(name)
    }
    fn write(&self, name: &str, text: &str) -> PathBuf {
        let p = self.path(name);
        std::fs::write(&p, text).unwrap();
        p
    }
    fn read(&self, name: &str) -> String {
        std::fs::read_to_string(self.path(name)).unwrap()
    }
}

fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap()
}

/// Runs `sealsim study` with `args`, expecting success; returns stdout.
fn study_ok(args: &[&dyn AsRef<std::ffi::OsStr>]) -> String {
    let mut all: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"study"];
    all.extend_from_slice(args);
    crate::support::sealsim_ok(&all)
}

/// Runs `sealsim study` with `args`, expecting exit 2; returns stderr.
fn study_bad(args: &[&dyn AsRef<std::ffi::OsStr>]) -> String {
    let out = sealsim()
        .arg("study")
        .args(args.iter().map(|a| a.as_ref()))
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "stdout: {}\nstderr: {}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stderr).unwrap()
}

#[test]
fn b10_and_the_survival_curve_match_a_closed_form_life_distribution() {
    // T ~ N(23 °C, 5 K): life = t0·a_T(T) falls with T, so S(t) = P(life > t) = Φ(x(t)/σ),
    // x(t) the offset whose life is t. The run ends at the life of x = −0.5σ: the coldest ≈ 31 %
    // survive it (censored).
    let d = Dir::new();
    let duration = t0() * 10f64.powf(log_shift(-0.5 * SIGMA));
    let base = one_term(&format!("{duration} s"));
    d.write("one.toml", &base);
    let study = d.write(
        "study.toml",
        "base = \"one.toml\"\ndesign = \"monte-carlo\"\nsamples = 400\nseed = 11\n\
         report_times = [\"1 h\"]\n[vary]\n\
         \"environment.temperature\" = { distribution = \"normal\", mean = \"23 C\", std = \"5 K\" }\n",
    );
    let (cases, summary) = (d.path("cases.csv"), d.path("summary.json"));
    study_ok(&[&study, &"-o", &cases, &"--summary", &summary]);
    let s = json(&d.read("summary.json"));
    let mut reader = csv::Reader::from_path(&cases).unwrap();
    let header = reader.headers().unwrap().clone();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (t_col, life_col, status_col) = (
        col("environment.temperature_K"),
        col("life_s"),
        col("status"),
    );
    let mut failures = 0;
    for r in reader.records() {
        let r = r.unwrap();
        let x = r[t_col].parse::<f64>().unwrap() - 296.15;
        let closed = t0() * 10f64.powf(log_shift(x));
        let life: f64 = r[life_col].parse().unwrap();
        if &r[status_col] == "failed" {
            failures += 1;
            assert!((life / closed - 1.0).abs() < 1e-6, "{life} vs {closed}");
        } else {
            // a survivor: its closed-form life lies beyond the run, and it is not a failure
            assert_eq!(&r[status_col], "censored");
            assert!(closed > duration * (1.0 - 1e-6), "{closed} ≤ {duration}");
            assert!((life / duration - 1.0).abs() < 1e-9);
        }
    }
    assert_eq!(s["failures"].as_u64(), Some(failures));
    assert_eq!(s["censored"].as_u64(), Some(400 - failures));
    assert!(
        (100..160).contains(&(400 - failures)),
        "{failures} failures"
    );

    // B10 = the life at x = σ Φ⁻¹(0.9) (the hottest 10 % fail first): inside its bounds
    let n = Normal::standard();
    let b10 = t0() * 10f64.powf(log_shift(SIGMA * n.inverse_cdf(0.9)));
    let (lo, hi) = (
        s["b10_lower_s"].as_f64().unwrap(),
        s["b10_upper_s"].as_f64().unwrap(),
    );
    assert!(lo <= b10 && b10 <= hi, "B10 {b10} outside [{lo}, {hi}]");
    assert!((s["b10_s"].as_f64().unwrap() / b10 - 1.0).abs() < 0.15);
    // B50 = t0 (x = 0) within its bounds; B1 too
    let b1 = t0() * 10f64.powf(log_shift(SIGMA * n.inverse_cdf(0.99)));
    for (name, truth) in [("b50", t0()), ("b1", b1)] {
        let lo = s[format!("{name}_lower_s")].as_f64().unwrap();
        let hi = s[format!("{name}_upper_s")].as_f64().unwrap();
        assert!(
            lo <= truth && truth <= hi,
            "{name} {truth} outside [{lo}, {hi}]"
        );
    }
    // the Kaplan–Meier band holds the true S(t) at the true 5 … 60 % failure times
    let steps = s["survival"].as_array().unwrap();
    for p in [0.05, 0.1, 0.2, 0.4, 0.6] {
        let t = t0() * 10f64.powf(log_shift(SIGMA * n.inverse_cdf(1.0 - p)));
        let truth = n.cdf(offset_for(t) / SIGMA);
        assert!((truth - (1.0 - p)).abs() < 1e-9);
        let step = steps
            .iter()
            .rev()
            .find(|st| st["time_s"].as_f64().unwrap() <= t)
            .unwrap();
        let (lo, hi) = (
            step["lower"].as_f64().unwrap(),
            step["upper"].as_f64().unwrap(),
        );
        assert!(
            lo <= truth && truth <= hi,
            "S({t}) = {truth} outside [{lo}, {hi}]"
        );
    }
    // the temperature is the only input: it drives the life, ρ ≈ −1 (monotone; the survivors
    // tie at the run's end, which keeps |ρ| just below 1)
    let sens = &s["sensitivity"][0];
    assert_eq!(sens["input"], "environment.temperature");
    let rho = sens["value"].as_f64().unwrap();
    assert!((-1.0..-0.95).contains(&rho), "{rho}");
}

/// A study of the headline ring with a word input (the fidelity level) and a Latin hypercube.
fn headline_study(d: &Dir, samples: usize) -> PathBuf {
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml");
    d.write(
        "study.toml",
        &format!(
            "base = {base:?}\ndesign = \"latin-hypercube\"\nsamples = {samples}\nseed = 5\n[vary]\n\
             \"seal.groove_depth\" = \"±0.08 mm\"\n\
             \"environment.temperature\" = {{ distribution = \"triangular\", min = \"75 C\", mode = \"80 C\", max = \"90 C\" }}\n\
             \"surface.ra\" = {{ distribution = \"lognormal\", median = \"0.4 um\", geometric_std = 1.5, max = \"2 um\" }}\n\
             \"simulation.fidelity\" = {{ values = [\"critical-junction\", \"rule-of-thumb\"] }}\n"
        ),
    )
}

#[test]
fn threads_and_shards_merged_in_any_order_give_the_same_bits() {
    let d = Dir::new();
    let study = headline_study(&d, 36);
    let run = |tag: &str, threads: Option<&str>| {
        let (c, s) = (
            d.path(&format!("{tag}.csv")),
            d.path(&format!("{tag}.json")),
        );
        let table = match threads {
            Some(t) => study_ok(&[&study, &"-o", &c, &"--summary", &s, &"--threads", &t]),
            None => study_ok(&[&study, &"-o", &c, &"--summary", &s]),
        };
        (
            d.read(&format!("{tag}.csv")),
            d.read(&format!("{tag}.json")),
            table,
        )
    };
    let one = run("one", Some("1"));
    let all = run("all", None);
    assert_eq!(one, all);
    // 4 shards (2 threads each), merged in a shuffled order
    let parts: Vec<PathBuf> = (1..=4)
        .map(|k| {
            let part = d.path(&format!("part-{k}.csv"));
            let shard = format!("{k}/4");
            study_ok(&[&study, &"--shard", &shard, &"--threads", &"2", &"-o", &part]);
            part
        })
        .collect();
    let (c, s) = (d.path("merged.csv"), d.path("merged.json"));
    let table = study_ok(&[
        &"merge",
        &study,
        &parts[2],
        &parts[0],
        &parts[3],
        &parts[1],
        &"-o",
        &c,
        &"--summary",
        &s,
    ]);
    assert_eq!(d.read("merged.csv"), one.0);
    assert_eq!(d.read("merged.json"), one.1);
    assert_eq!(table, one.2);
    // the table says what a study must: counts, B lives, the ranking
    let summary = json(&one.1);
    for key in ["b1_s", "b10_s", "b50_s", "failures", "censored"] {
        assert!(summary.get(key).is_some(), "{key}");
    }
    assert_eq!(summary["cases"], 36);
    crate::support::no_nan(&one.0, "cases.csv");
    crate::support::no_nan(&one.1, "summary.json");
}

#[test]
fn bad_studies_exit_2_naming_file_line_and_key_and_write_nothing() {
    let d = Dir::new();
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml");
    let head = format!("base = {base:?}\ndesign = \"monte-carlo\"\nsamples = 4\n[vary]\n");
    let out = d.path("cases.csv");
    for (entry, wanted) in [
        (
            "\"seal.squeezee\" = { distribution = \"uniform\", min = 0.2, max = 0.3 }",
            "unknown key",
        ),
        (
            "\"seal.groove_depth\" = { distribution = \"normal\", mean = \"2.6 mm\", std = \"-0.1 mm\" }",
            "std > 0",
        ),
        (
            "\"surface.ra\" = { distribution = \"lognormal\", median = \"0.4 um\", geometric_std = 0.8 }",
            "geometric_std > 1",
        ),
        (
            "\"surface.ra\" = { distribution = \"uniform\", min = \"0.4 um\", max = \"0.2 um\" }",
            "min < max",
        ),
        (
            "\"surface.ra\" = { distribution = \"gaussian\", mean = \"0.4 um\" }",
            "unknown distribution",
        ),
        (
            "\"surface.ra\" = { distribution = \"normal\", mean = \"0.4 um\", std = \"1 MPa\" }",
            "different quantities",
        ),
    ] {
        let key = entry.split('=').next().unwrap().trim();
        let study = d.write("bad.toml", &format!("{head}{entry}\n"));
        let err = study_bad(&[&study, &"-o", &out]);
        let at = format!("{}:5: vary.{key}", study.display());
        assert!(err.contains(&at), "{entry}: wanted {at} in {err}");
        assert!(err.contains(wanted), "{entry}: wanted {wanted} in {err}");
        assert!(!out.exists());
    }
    // a study none of whose cases the scenario accepts (a study with some valid cases
    // records the others: `invalid_cases_are_recorded_…`): named with its inputs, at the
    // input's line
    let study = d.write(
        "bad.toml",
        &format!("{head}\"seal.groove_depth\" = {{ values = [\"-1 mm\", \"-2 mm\"] }}\n")
            .replace("samples = 4", "samples = 12"),
    );
    let err = study_bad(&[&study, &"-o", &out]);
    assert!(err.contains(":5: vary.\"seal.groove_depth\""), "{err}");
    assert!(err.contains("not a valid scenario"), "{err}");
    assert!(!out.exists());
    // a shard out of range
    let good = headline_study(&d, 8);
    for shard in ["5/4", "0/4", "2", "a/b"] {
        let err = study_bad(&[&good, &"--shard", &shard, &"-o", &out]);
        assert!(err.contains("--shard"), "{shard}: {err}");
        assert!(!out.exists());
    }
}

#[test]
fn merging_parts_of_another_study_or_an_incomplete_set_is_refused() {
    let d = Dir::new();
    let study = headline_study(&d, 6);
    let part = |k: usize, n: usize| {
        let p = d.path(&format!("p{k}of{n}.csv"));
        let shard = format!("{k}/{n}");
        study_ok(&[&study, &"--shard", &shard, &"-o", &p]);
        p
    };
    let (a, b) = (part(1, 2), part(2, 2));
    let c = part(2, 3);
    let out = d.path("merged.csv");
    // the other study: the same inputs with another seed
    let other = d.write(
        "other.toml",
        &std::fs::read_to_string(&study)
            .unwrap()
            .replace("seed = 5", "seed = 6"),
    );
    let err = study_bad(&[&"merge", &other, &a, &b, &"-o", &out]);
    assert!(err.contains(&format!("{}:1:", a.display())), "{err}");
    assert!(err.contains("another study"), "{err}");
    // missing and overlapping parts
    let err = study_bad(&[&"merge", &study, &a, &"-o", &out]);
    assert!(err.contains("in no part"), "{err}");
    let err = study_bad(&[&"merge", &study, &a, &b, &c, &"-o", &out]);
    assert!(err.contains("also in"), "{err}");
    // a tampered input value
    let tampered = d.write("t.csv", &{
        let text = std::fs::read_to_string(&b).unwrap();
        let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
        let mut cells: Vec<String> = lines[2].split(',').map(str::to_owned).collect();
        cells[1] = "0.0025".into();
        lines[2] = cells.join(",");
        lines.join("\n") + "\n"
    });
    let err = study_bad(&[&"merge", &study, &a, &tampered, &"-o", &out]);
    assert!(err.contains(":3: seal.groove_depth_m"), "{err}");
    assert!(!out.exists());
    // and the good set merges
    study_ok(&[&"merge", &study, &b, &a, &"-o", &out]);
    assert!(out.exists());
}

/// Issue 44: a merge reads its parts one at a time in case order, never all of them at once:
/// each part must hold the cases its first line names, in order. A part with two rows
/// swapped, one cut short or one whose first line was edited is refused at its line; nothing
/// is written.
#[test]
fn a_part_out_of_order_cut_short_or_with_an_edited_first_line_is_refused() {
    let d = Dir::new();
    let study = headline_study(&d, 6);
    let part = |k: usize| {
        let p = d.path(&format!("p{k}.csv"));
        let shard = format!("{k}/2");
        study_ok(&[&study, &"--shard", &shard, &"-o", &p]);
        p
    };
    let (a, b) = (part(1), part(2));
    let text = std::fs::read_to_string(&b).unwrap();
    assert!(
        text.starts_with("# sealsim study ")
            && text.lines().next().unwrap().contains(" cases 3..6 of 6")
    );
    let lines: Vec<&str> = text.lines().collect();
    let out = d.path("merged.csv");
    let summary = d.path("merged.json");
    let refused = |edited: Vec<&str>, wanted: &[&str]| {
        let e = d.write("edited.csv", &(edited.join("\n") + "\n"));
        let err = study_bad(&[
            &"merge",
            &study,
            &a,
            &e,
            &"-o",
            &out,
            &"--summary",
            &summary,
        ]);
        for w in wanted {
            assert!(err.contains(w), "wanted {w} in {err}");
        }
        assert!(!out.exists() && !summary.exists());
    };
    let mut swapped = lines.clone();
    swapped.swap(2, 3);
    refused(
        swapped,
        &["edited.csv:3: case", "case 4 where case 3 belongs"],
    );
    refused(
        lines[..lines.len() - 1].to_vec(),
        &["edited.csv:5", "ends after case 4", "truncated"],
    );
    for (from, to) in [
        (" cases 3..6 ", " cases 3..7 "),
        (" of 6", " of 7"),
        (" cases 3..6", ""),
    ] {
        let first = lines[0].replace(from, to);
        let mut edited = lines.clone();
        edited[0] = &first;
        refused(
            edited,
            &["edited.csv:1:", "does not say which of the study's 6 cases"],
        );
    }
    // a first line that claims fewer cases than the part holds leaves the others in no part
    let first = lines[0].replace(" cases 3..6 ", " cases 3..5 ");
    let mut edited = lines.clone();
    edited[0] = &first;
    refused(
        edited,
        &["1 of its 6 cases are in no part (the first: case 5)"],
    );
    study_ok(&[&"merge", &study, &b, &a, &"-o", &out]);
}

#[test]
fn the_slurm_script_submits_an_array_and_a_dependent_merge() {
    let d = Dir::new();
    let study = headline_study(&d, 10);
    let script = d.path("submit.sh");
    study_ok(&[
        &"slurm",
        &study,
        &"--shards",
        &"3",
        &"--partition",
        &"debug",
        &"--time",
        &"00:10:00",
        &"-o",
        &script,
    ]);
    let text = std::fs::read_to_string(&script).unwrap();
    for wanted in [
        "sbatch --parsable",
        "--array=1-3",
        "--partition='debug'",
        "--time='00:10:00'",
        "--shard \"\\$SLURM_ARRAY_TASK_ID/3\"",
        "--dependency=afterok:\"$array\"",
        "study merge",
    ] {
        assert!(text.contains(wanted), "{wanted} not in\n{text}");
    }
    // valid shell
    let status = std::process::Command::new("bash")
        .arg("-n")
        .arg(&script)
        .status()
        .unwrap();
    assert!(status.success());
    // more shards than cases: one per case
    let text = study_ok(&[&"slurm", &study, &"--shards", &"50"]);
    assert!(text.contains("--array=1-10 "), "{text}");
}

#[test]
fn every_shipped_study_runs() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/studies");
    let mut seen = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if !path.to_string_lossy().ends_with(".study.toml") {
            continue;
        }
        seen += 1;
        // a slice of each (the whole runs are the README's timings)
        let d = Dir::new();
        let part = d.path("part.csv");
        study_ok(&[&path, &"--shard", &"1/100", &"-o", &part]);
        let text = d.read("part.csv");
        crate::support::no_nan(&text, &path.display().to_string());
        assert!(text.lines().count() >= 2, "{}: {text}", path.display());
    }
    assert!(seen >= 3, "{seen} studies");
}

#[test]
fn correlated_inputs_follow_their_rank_correlation_and_bad_ones_are_refused() {
    let d = Dir::new();
    d.write("one.toml", &one_term("1 day"));
    let head = "base = \"one.toml\"\ndesign = \"monte-carlo\"\nsamples = 600\nseed = 3\n\
                report_times = [\"1 h\"]\n[vary]\n\
                \"environment.temperature\" = { distribution = \"normal\", mean = \"23 C\", std = \"5 K\" }\n\
                \"seal.nominal_pressure\" = { distribution = \"uniform\", min = \"0.8 MPa\", max = \"1.2 MPa\" }\n";
    let study = d.write(
        "c.toml",
        &format!(
            "{head}[[correlations]]\ninputs = [\"environment.temperature\", \"seal.nominal_pressure\"]\nspearman = 0.7\n"
        ),
    );
    let cases = d.path("cases.csv");
    study_ok(&[&study, &"-o", &cases]);
    let mut reader = csv::Reader::from_path(&cases).unwrap();
    let (mut t, mut p) = (vec![], vec![]);
    for r in reader.records() {
        let r = r.unwrap();
        t.push(r[1].parse::<f64>().unwrap());
        p.push(r[2].parse::<f64>().unwrap());
    }
    let rho = sealsim::study::sensitivity::spearman(&t, &p).unwrap();
    // 600 cases: the sample ρ_s has a standard error ≈ 0.03
    assert!((rho - 0.7).abs() < 0.1, "{rho}");
    // refused: a correlation with a Latin hypercube, an unknown input, contradicting ones
    let out = d.path("x.csv");
    let lhs = d.write(
        "l.toml",
        &std::fs::read_to_string(&study)
            .unwrap()
            .replace("monte-carlo", "latin-hypercube"),
    );
    let err = study_bad(&[&lhs, &"-o", &out]);
    assert!(err.contains("l.toml:9: correlations"), "{err}");
    let unknown = d.write(
        "u.toml",
        &std::fs::read_to_string(&study)
            .unwrap()
            .replace("\"seal.nominal_pressure\"]", "\"seal.width\"]"),
    );
    let err = study_bad(&[&unknown, &"-o", &out]);
    assert!(err.contains("not an input"), "{err}");
    let contradicting = d.write(
        "k.toml",
        &format!(
            "{head}\"seal.width\" = {{ distribution = \"uniform\", min = \"0.9 mm\", max = \"1.1 mm\" }}\n\
             [[correlations]]\ninputs = [\"environment.temperature\", \"seal.nominal_pressure\"]\nspearman = 0.9\n\
             [[correlations]]\ninputs = [\"seal.nominal_pressure\", \"seal.width\"]\nspearman = 0.9\n\
             [[correlations]]\ninputs = [\"environment.temperature\", \"seal.width\"]\nspearman = -0.9\n"
        ),
    );
    let err = study_bad(&[&contradicting, &"-o", &out]);
    assert!(err.contains("contradict"), "{err}");
    assert!(!out.exists());
}

/// The shipped AS568-225 tolerance base with an absolute force criterion (1.5 N/mm) and the
/// shutdown check waived, so that the life is set by the force alone.
fn absolute_force_base(d: &Dir) -> PathBuf {
    let shipped = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios/studies/as568-225-face-water-80c.toml");
    let text = std::fs::read_to_string(shipped).unwrap().replace(
        "lift_off = true",
        "lift_off = true\nlost_interference = false\nmin_sealing_force = \"1.5 N/mm\"",
    );
    assert!(text.contains("min_sealing_force"));
    d.write("base.toml", &text)
}

fn groove_study(d: &Dir, name: &str, tolerance: &str, samples: usize) -> PathBuf {
    d.write(
        name,
        &format!(
            "base = \"base.toml\"\ndesign = \"latin-hypercube\"\nsamples = {samples}\nseed = 7\n\
             [vary]\n\"seal.groove_depth\" = {{ tolerance = \"±{tolerance}\" }}\n"
        ),
    )
}

fn summary_b10(d: &Dir, study: &Path, tag: &str) -> f64 {
    let summary = d.path(&format!("{tag}.json"));
    let cases = d.path(&format!("{tag}.csv"));
    study_ok(&[&study, &"-o", &cases, &"--summary", &summary]);
    json(&d.read(&format!("{tag}.json")))["b10_s"]
        .as_f64()
        .unwrap()
}

/// Issue 30: with an absolute criterion the squeeze tolerance decides the life. The life falls
/// monotonically with the groove depth (less squeeze, less force), so B10 is the life of the
/// ring at the depth's 90 % quantile — for a ±3σ band of a normal truncated at the band,
/// z = Φ⁻¹(Φ(−3) + 0.9 (1 − 2Φ(−3))) = 1.2754 — computed here by an independent `run`.
#[test]
fn an_absolute_force_criterion_makes_b10_move_with_the_tolerance_band() {
    let d = Dir::new();
    let base = absolute_force_base(&d);
    let narrow = groove_study(&d, "narrow.study.toml", "0.02 mm", 200);
    let wide = groove_study(&d, "wide.study.toml", "0.10 mm", 200);
    let b10_narrow = summary_b10(&d, &narrow, "narrow");
    let b10_wide = summary_b10(&d, &wide, "wide");
    assert!(
        b10_wide < 0.9 * b10_narrow,
        "B10 {b10_wide} s (±0.10 mm) vs {b10_narrow} s (±0.02 mm)"
    );
    let n = Normal::new(0.0, 1.0).unwrap();
    let tail = n.cdf(-3.0);
    let z = n.inverse_cdf(tail + 0.9 * (1.0 - 2.0 * tail));
    assert!((z - 1.2754).abs() < 1e-3, "{z}");
    let depth_mm = 2.65 + z * 0.10 / 3.0;
    let text = std::fs::read_to_string(&base).unwrap().replace(
        "groove_depth = \"2.65 mm\"",
        &format!("groove_depth = \"{depth_mm} mm\""),
    );
    let quantile = d.write("quantile.toml", &text);
    let summary = d.path("quantile.json");
    let history = d.path("quantile.csv");
    crate::support::sealsim_ok(&[&"run", &quantile, &"-o", &history, &"--summary", &summary]);
    let s = json(&d.read("quantile.json"));
    assert_eq!(s["failure_mode"], "sealing_force", "{s}");
    let life = s["time_to_failure_s"].as_f64().unwrap();
    assert!(
        (b10_wide / life - 1.0).abs() < 0.03,
        "B10 {b10_wide} s vs the life at the 90 % depth quantile {life} s"
    );
}

/// Issue 30: a study finishes when some cases are not valid seals — each is recorded with its
/// inputs and its reason, which names the varied input that makes it invalid (the cross-section
/// that overfills the groove, not the groove line the fill check reads), and counted as failed
/// at installation.
#[test]
fn invalid_cases_are_recorded_counted_and_named_by_their_varied_input() {
    let d = Dir::new();
    absolute_force_base(&d);
    let study = d.write(
        "mixed.study.toml",
        "base = \"base.toml\"\ndesign = \"latin-hypercube\"\nsamples = 50\nseed = 7\n[vary]\n\
         \"seal.groove_depth\" = { tolerance = \"±0.02 mm\" }\n\
         \"seal.cross_section\" = { tolerance = \"±1.2 mm\" }\n",
    );
    let cases = d.path("cases.csv");
    let summary = d.path("summary.json");
    study_ok(&[&study, &"-o", &cases, &"--summary", &summary]);
    let s = json(&d.read("summary.json"));
    let invalid = s["invalid_cases"].as_u64().unwrap();
    assert!(invalid > 0 && invalid < 50, "{s}");
    let table = d.read("cases.csv");
    let mut reader = csv::Reader::from_reader(table.as_bytes());
    let header = reader.headers().unwrap().clone();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (status, reason, life, cs) = (
        col("status"),
        col("invalid_reason"),
        col("life_s"),
        col("seal.cross_section_m"),
    );
    let mut seen = 0;
    for row in reader.records() {
        let row = row.unwrap();
        if &row[status] == "invalid" {
            seen += 1;
            assert_eq!(&row[life], "0");
            assert!(
                row[reason].contains("mixed.study.toml:7:"),
                "{}",
                &row[reason]
            );
            assert!(
                row[reason].contains("made invalid by seal.cross_section"),
                "{}",
                &row[reason]
            );
            // only cords far from the nominal 3.53 mm overfill the groove or fail to seat
            let cord = row[cs].parse::<f64>().unwrap();
            assert!((cord - 3.53e-3).abs() > 0.3e-3, "{cord}");
        } else {
            assert!(row[reason].is_empty());
        }
    }
    assert_eq!(seen as u64, invalid);
    // the failures count the invalid cases; B1 is the installation
    assert_eq!(s["failures"].as_u64().unwrap(), 50);
    assert_eq!(s["b1_s"].as_f64(), Some(0.0));
    // the merge path reads invalid cases back: a shard's part file round-trips
    let part = d.path("part.csv");
    study_ok(&[&study, &"--shard", &"1/1", &"-o", &part]);
    let merged = d.path("merged.json");
    study_ok(&[&"merge", &study, &part, &"--summary", &merged]);
    let m = json(&d.read("merged.json"));
    assert_eq!(m["invalid_cases"], s["invalid_cases"]);
    assert_eq!(m["b50_s"], s["b50_s"]);
}
