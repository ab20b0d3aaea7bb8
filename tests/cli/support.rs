//! Helpers shared by several modules of the `cli` test binary.

/// Header of the history CSV of `sealsim run`.
pub const HISTORY_HEADER: &str = "time_s,temperature_K,reduced_time_s,shift_factor,\
sealing_force_N_per_m,peak_pressure_Pa,mean_pressure_Pa,contact_width_m,u_c_m,\
leak_rate_m3_per_s,leaked_volume_m3,state,open_fraction,compression_set,shutdown_squeeze";

/// The `sealsim` binary as a command.
/// A one-term file compound without ageing constants (every library compound has them): for
/// tests of a comparison that degrades, and of file compounds.
pub const SOFT_MATERIAL: &str = "[material]\nname = \"soft test rubber\"\npoisson_ratio = 0.5\n\
     long_term_modulus = \"2 MPa\"\nprony = [ { modulus = \"2 MPa\", tau = \"1 h\" } ]\n\
     thermal_expansion = \"2e-4 1/K\"\n";

pub fn sealsim() -> assert_cmd::Command {
    assert_cmd::cargo::cargo_bin_cmd!("sealsim")
}

/// Runs `sealsim ARGS…`, expecting success; returns stdout.
pub fn sealsim_ok(args: &[&dyn AsRef<std::ffi::OsStr>]) -> String {
    let out = sealsim()
        .args(args.iter().map(|a| a.as_ref()))
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "sealsim failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

/// `sealsim run` on a scenario written as `s.toml` in a fresh directory, with `-o h.csv
/// --summary s.json`: (status, stdout, stderr, the history CSV and the summary JSON if written),
/// the scenario's path shown as `s.toml` in the two streams.
pub fn run_text(text: &str) -> (Option<i32>, String, String, Option<String>, Option<String>) {
    let dir = tempfile::tempdir().unwrap();
    let scenario = dir.path().join("s.toml");
    std::fs::write(&scenario, text).unwrap();
    let (csv, json) = (dir.path().join("h.csv"), dir.path().join("s.json"));
    let out = sealsim()
        .arg("run")
        .arg(&scenario)
        .arg("--verbose") // the full derivation, which the tests read
        .arg("-o")
        .arg(&csv)
        .arg("--summary")
        .arg(&json)
        .output()
        .unwrap();
    let path = scenario.display().to_string();
    let text = |b: Vec<u8>| String::from_utf8(b).unwrap().replace(&path, "s.toml");
    (
        out.status.code(),
        text(out.stdout),
        text(out.stderr),
        std::fs::read_to_string(&csv).ok(),
        std::fs::read_to_string(&json).ok(),
    )
}

/// The text of the shipped scenario `scenarios/NAME`.
pub fn shipped(name: &str) -> String {
    std::fs::read_to_string(crate::common::scenario_path(name)).unwrap()
}

/// `text` with each line starting with an edit's prefix replaced by its line (empty: deleted).
pub fn edited(text: &str, edits: &[(&str, &str)]) -> String {
    let mut out = String::new();
    for line in text.lines() {
        match edits.iter().find(|(prefix, _)| line.starts_with(prefix)) {
            Some((_, "")) => {}
            Some((_, new)) => {
                out += new;
                out.push('\n');
            }
            None => {
                out += line;
                out.push('\n');
            }
        }
    }
    out
}

/// `sealsim compare SCENARIO --materials IDS -o c.csv` in a fresh directory, expecting
/// success: (stdout, the CSV's header, its rows), read as CSV (names and notes hold commas).
pub fn compare_csv(
    scenario: &std::path::Path,
    ids: &str,
) -> (String, Vec<String>, Vec<Vec<String>>) {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("c.csv");
    let out = sealsim()
        .arg("compare")
        .arg(scenario)
        .args(["--materials", ids, "-o"])
        .arg(&csv)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (header, rows) = read_csv(&csv);
    (String::from_utf8(out.stdout).unwrap(), header, rows)
}

/// A CSV file's header and rows, as strings.
pub fn read_csv(path: &std::path::Path) -> (Vec<String>, Vec<Vec<String>>) {
    let mut reader = ::csv::Reader::from_path(path).unwrap();
    let header = reader
        .headers()
        .unwrap()
        .iter()
        .map(str::to_owned)
        .collect();
    let rows = reader
        .records()
        .map(|r| r.unwrap().iter().map(str::to_owned).collect())
        .collect();
    (header, rows)
}

/// `sealsim run s.toml --summary s.json ARGS…` on `text` written as `s.toml` in `dir` (run
/// there, so that relative files beside it are found), expecting exit 0: (the summary JSON,
/// stdout).
pub fn run_in(dir: &std::path::Path, text: &str, args: &[&str]) -> (serde_json::Value, String) {
    std::fs::write(dir.join("s.toml"), text).unwrap();
    let json = dir.join("s.json");
    let _ = std::fs::remove_file(&json);
    let out = sealsim()
        .current_dir(dir)
        .args(["run", "s.toml", "--verbose", "--summary", "s.json"])
        .args(args)
        .output()
        .unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let summary = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    (summary, stdout)
}

/// Asserts that `text` (named `what` in the message) has no NaN or infinity: as a whole word,
/// so that a temporary directory named like `/tmp/.tmpdKmNaN` is not taken for one.
pub fn no_nan(text: &str, what: &str) {
    let bad = text
        .split(|c: char| !c.is_ascii_alphanumeric())
        .find(|w| matches!(*w, "NaN" | "nan" | "inf" | "Inf" | "infinity" | "Infinity"));
    assert!(bad.is_none(), "{what} contains {bad:?}:\n{text}");
}

#[test]
fn no_nan_looks_at_words() {
    no_nan(
        "{\"file\": \"/tmp/.tmpdKmNaN/one.toml\", \"x\": 1e-3, \"info\": 2}",
        "t",
    );
    for bad in ["1,NaN,2", "x: nan", "-inf", "[inf]"] {
        assert!(
            std::panic::catch_unwind(|| no_nan(bad, "t")).is_err(),
            "{bad}"
        );
    }
}

/// The crate's seeded SplitMix64 ([`sealsim::math::rng::SplitMix64`]) with the draws the
/// scenario fuzz and the data-reader fuzz need: the same stream everywhere.
pub struct Rng(pub sealsim::math::rng::SplitMix64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(sealsim::math::rng::SplitMix64(seed))
    }

    pub fn next(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// Uniform in `0..n` (0 for `n = 0`).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}
