//! Deterministic mutation fuzz of the shipped input files through the binary (issue 13, item 3a).
//!
//! Each case takes one shipped file — a scenario (`scenarios/*.toml` but the figure set), a
//! material file (`materials/*.toml`, through `sealsim compare`), the tabulated spectrum
//! (`scenarios/psd-example.csv`, through `psd-example.toml`) or the temperature history
//! (`scenarios/cold-night.csv`, through `cold-night-nbr.toml`) — applies one to three seeded
//! mutations (a number replaced by an extreme, a line deleted or duplicated, `[x]` inserted, the
//! file truncated, a unit swapped for one of another dimension), writes it to a temporary
//! directory and runs the command with every output requested. It asserts: exit status 0 or 2;
//! no "panicked" and no "internal error" on stderr; no hang (a case is killed after
//! [`CASE_TIMEOUT`] plus [`HANG_FACTOR`] times its unmutated file's own run); after status 2 no
//! output file; after status 0 no NaN or infinity in the CSV, the JSON or the SVG.
//!
//! The default run is [`DEFAULT_CASES`] cases (≈ 4 minutes on 2 cores in release: a valid case
//! runs the whole life and its level band, up to ~10 s for the gas and cold scenarios); the
//! inputs that once failed are replayed on their own (`fuzz/reproducers/`, a test below).
//! `SEALSIM_FUZZ_CASES=N` runs N, `SEALSIM_FUZZ_SEED=S` another seed. The test prints one summary
//! line, the figures quoted in docs/src/validation.md's "Robustness" section.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Cases of the default run.
const DEFAULT_CASES: u64 = 1500;
/// Seed of the default run.
const DEFAULT_SEED: u64 = 0x5EA1_5EED;
/// Failures of the default seed that are input-range bugs in `src/scenario` (absurd values
/// accepted: `width = 1e308 mm` overflows the sealing force, `temperature = 1e308 C` the reduced
/// time — an internal error, exit 1), fixed by the input ranges of the `ranges` branch. They are
/// tolerated (and listed) until that merge; then this list must be emptied. Any other failure
/// fails the test.
const AWAITING_RANGES: &[(u64, &str)] = &[];
/// A case is a hang when it runs longer than this plus [`HANG_FACTOR`] times its unmutated
/// file (timed by the same test, on the same loaded machine): a mutation may legitimately make
/// a run longer (a failure criterion removed: the whole duration to simulate), never unbounded;
/// the shipped files themselves take from milliseconds to ~10 s (a gas's effective-medium band).
const CASE_TIMEOUT: Duration = Duration::from_secs(20);
/// See [`CASE_TIMEOUT`].
const HANG_FACTOR: u32 = 5;

use crate::support::Rng;

/// What a mutated file is and how the binary is run on it.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// A scenario: `sealsim run FILE -o --summary --plot`.
    Scenario,
    /// A material file: `sealsim compare oring-nbr-water-80c.toml --materials FILE -o --plot`.
    Material,
    /// The spectrum: `psd-example.toml` next to the mutated `psd-example.csv`, `sealsim run`.
    Psd,
    /// The temperature history: `cold-night-nbr.toml` next to the mutated `cold-night.csv`.
    History,
}

/// A shipped file to mutate.
struct Base {
    kind: Kind,
    /// Path relative to the crate root.
    path: PathBuf,
    text: String,
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn bases() -> Vec<Base> {
    let mut out = Vec::new();
    let mut add = |kind, path: PathBuf| {
        let text = fs::read_to_string(root().join(&path)).unwrap();
        out.push(Base { kind, path, text });
    };
    for (dir, kind) in [("scenarios", Kind::Scenario), ("materials", Kind::Material)] {
        let mut names: Vec<PathBuf> = fs::read_dir(root().join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            // A figure set is the input of `sealsim figures`, not a scenario.
            .filter(|p| !p.ends_with("persson-yang-2008-figures.toml"))
            .map(|p| Path::new(dir).join(p.file_name().unwrap()))
            .collect();
        names.sort();
        for name in names {
            add(kind, name);
        }
    }
    add(Kind::Psd, "scenarios/psd-example.csv".into());
    add(Kind::History, "scenarios/cold-night.csv".into());
    out
}

/// Replacement values for a number.
const EXTREMES: &[&str] = &[
    "0", "-1", "1e308", "-1e308", "1e-308", "nan", "inf", "-inf", "NaN", "1e400", "-0",
];

/// Units swapped for one of another dimension (or none at all).
const UNIT_SWAPS: &[(&str, &str)] = &[
    ("mm", "kg"),
    ("um", "s"),
    ("MPa", "m"),
    ("bar", "K"),
    ("Pa*s", "Pa"),
    ("1/m", "m"),
    ("year", "Pa"),
    ("day", "mm"),
    (" C", " kg"),
    ("m^3/s", "m^3"),
    ("L", "N"),
    ("h,C", "kg,C"),
    ("mm", ""),
];

/// Byte ranges of the numbers in `line` (a digit run with its fraction, exponent and sign).
fn numbers(line: &str) -> Vec<(usize, usize)> {
    let b = line.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let word = |k: usize| b[k].is_ascii_alphanumeric() || b[k] == b'_' || b[k] == b'.';
        // Not inside a word ("h2o") or a code ("AS568-225").
        let starts = b[i].is_ascii_digit()
            && (i == 0 || !word(i - 1))
            && !(i >= 2 && b[i - 1] == b'-' && word(i - 2));
        if !starts {
            i += 1;
            continue;
        }
        let mut start = i;
        if start > 0 && (b[start - 1] == b'-' || b[start - 1] == b'+') {
            start -= 1;
        }
        let mut j = i;
        while j < b.len() {
            let c = b[j];
            let sign_after_e = (c == b'-' || c == b'+') && matches!(b[j - 1], b'e' | b'E');
            if c.is_ascii_digit() || c == b'.' || c == b'e' || c == b'E' || sign_after_e {
                j += 1;
            } else {
                break;
            }
        }
        // A trailing `e` belongs to a word ("1e" in "1em" is unlikely, "2 day" is fine).
        while j > i && matches!(b[j - 1], b'e' | b'E' | b'-' | b'+') {
            j -= 1;
        }
        out.push((start, j));
        i = j.max(i + 1);
    }
    out
}

/// Lines whose numbers are worth mutating: not comments, not the free-text `name`, `source`,
/// `notes`… (a number in a name reaches the outputs as text, which is not a computed NaN).
fn mutable_line(line: &str) -> bool {
    let t = line.trim_start();
    !(t.is_empty()
        || t.starts_with('#')
        || t.starts_with("name")
        || t.starts_with("source")
        || t.starts_with("description")
        || t.starts_with("notes"))
}

/// Applies one mutation to `text`; returns its description.
fn mutate(text: &mut String, rng: &mut Rng) -> String {
    let lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let mut lines = if lines.is_empty() {
        vec![String::new()]
    } else {
        lines
    };
    let which = rng.below(10);
    let desc = match which {
        // A number: the most productive mutation, so the most frequent.
        0..=3 => {
            let spots: Vec<(usize, (usize, usize))> = lines
                .iter()
                .enumerate()
                .filter(|(_, l)| mutable_line(l))
                .flat_map(|(n, l)| numbers(l).into_iter().map(move |r| (n, r)))
                .collect();
            if spots.is_empty() {
                return "no number to replace".into();
            }
            let (n, (a, b)) = *rng.pick(&spots);
            let value = if rng.below(12) == 0 {
                "9".repeat(400)
            } else {
                (*rng.pick(EXTREMES)).to_owned()
            };
            let old = lines[n][a..b].to_owned();
            lines[n].replace_range(a..b, &value);
            format!("line {}: {old} -> {value}", n + 1)
        }
        4 => {
            let n = rng.below(lines.len());
            let old = lines.remove(n);
            format!("delete line {}: {old:?}", n + 1)
        }
        5 => {
            let n = rng.below(lines.len());
            let dup = lines[n].clone();
            lines.insert(n, dup);
            format!("duplicate line {}", n + 1)
        }
        6 => {
            let n = rng.below(lines.len() + 1);
            lines.insert(n, "[x]".into());
            format!("insert [x] before line {}", n + 1)
        }
        7 => {
            let joined = lines.join("\n");
            let mut cut = rng.below(joined.len().max(1));
            while !joined.is_char_boundary(cut) {
                cut -= 1;
            }
            *text = joined[..cut].to_owned();
            return format!("truncate at byte {cut}");
        }
        _ => {
            let spots: Vec<(usize, &str, &str)> = lines
                .iter()
                .enumerate()
                .filter(|(_, l)| mutable_line(l))
                .flat_map(|(n, l)| {
                    UNIT_SWAPS
                        .iter()
                        .filter(|(from, _)| l.contains(from))
                        .map(move |&(from, to)| (n, from, to))
                })
                .collect();
            if spots.is_empty() {
                return "no unit to swap".into();
            }
            let &(n, from, to) = rng.pick(&spots);
            lines[n] = lines[n].replacen(from, to, 1);
            format!("line {}: unit {from:?} -> {to:?}", n + 1)
        }
    };
    *text = lines.join("\n");
    text.push('\n');
    desc
}

/// The result of one case.
#[derive(Debug, PartialEq)]
enum Outcome {
    Exit(i32),
    Signal,
    Hang,
}

struct Case {
    base: usize,
    mutations: Vec<String>,
    input: String,
    outcome: Outcome,
    /// Assertions this case broke.
    failures: Vec<String>,
    panicked: bool,
    internal: bool,
    nan: bool,
}

/// The outputs a case asks for (absent for `compare`: `summary`).
const OUTPUTS: [&str; 3] = ["out.csv", "summary.json", "plot.svg"];

fn run_case(index: u64, seed: u64, bases: &[Base], bin: &Path, limits: &[Duration]) -> Case {
    let mut rng = Rng::new(seed ^ index.wrapping_mul(0xA24B_AED4_963E_E407));
    let base_index = rng.below(bases.len());
    let mut input = bases[base_index].text.clone();
    let mutations: Vec<String> = (0..1 + rng.below(3))
        .map(|_| mutate(&mut input, &mut rng))
        .collect();
    execute(bases, base_index, input, mutations, bin, limits[base_index])
}

/// The hang limit of each base: [`CASE_TIMEOUT`] plus [`HANG_FACTOR`] times its unmutated run
/// (which must itself pass every check of a case).
fn hang_limits(bases: &[Base], bin: &Path, workers: usize) -> Vec<Duration> {
    let next = Mutex::new(0usize);
    let limits = Mutex::new(vec![Duration::ZERO; bases.len()]);
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| {
                loop {
                    let i = {
                        let mut n = next.lock().unwrap();
                        *n += 1;
                        *n - 1
                    };
                    let Some(base) = bases.get(i) else { break };
                    let start = Instant::now();
                    let case = execute(
                        bases,
                        i,
                        base.text.clone(),
                        Vec::new(),
                        bin,
                        10 * CASE_TIMEOUT,
                    );
                    assert!(
                        case.failures.is_empty(),
                        "the unmutated {}: {}",
                        base.path.display(),
                        case.failures.join("; ")
                    );
                    limits.lock().unwrap()[i] = CASE_TIMEOUT + HANG_FACTOR * start.elapsed();
                }
            });
        }
    });
    limits.into_inner().unwrap()
}

/// Runs `input` (the mutated text of base `base_index`) with every output and checks it.
fn execute(
    bases: &[Base],
    base_index: usize,
    input: String,
    mutations: Vec<String>,
    bin: &Path,
    limit: Duration,
) -> Case {
    let base = &bases[base_index];

    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let file_name = base.path.file_name().unwrap();
    fs::write(d.join(file_name), &input).unwrap();
    let copy = |name: &str| {
        fs::copy(root().join("scenarios").join(name), d.join(name)).unwrap();
    };
    let mut cmd = Command::new(bin);
    let outs = |cmd: &mut Command, summary: bool| {
        cmd.arg("-o").arg(d.join(OUTPUTS[0]));
        if summary {
            cmd.arg("--summary").arg(d.join(OUTPUTS[1]));
        }
        cmd.arg("--plot").arg(d.join(OUTPUTS[2]));
    };
    match base.kind {
        Kind::Scenario => {
            // The spectrum and history a scenario names, beside it.
            for companion in ["psd-example.csv", "cold-night.csv"] {
                if input.contains(companion) {
                    copy(companion);
                }
            }
            cmd.arg("run").arg(d.join(file_name));
            outs(&mut cmd, true);
        }
        Kind::Material => {
            copy("oring-nbr-water-80c.toml");
            cmd.arg("compare")
                .arg(d.join("oring-nbr-water-80c.toml"))
                .arg("--materials")
                .arg(d.join(file_name));
            outs(&mut cmd, false);
        }
        Kind::Psd => {
            copy("psd-example.toml");
            cmd.arg("run").arg(d.join("psd-example.toml"));
            outs(&mut cmd, true);
        }
        Kind::History => {
            copy("cold-night-nbr.toml");
            cmd.arg("run").arg(d.join("cold-night-nbr.toml"));
            outs(&mut cmd, true);
        }
    }
    let stderr_path = d.join("stderr.txt");
    cmd.stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(fs::File::create(&stderr_path).unwrap());
    let mut child = cmd.spawn().unwrap();
    let start = Instant::now();
    let outcome = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status.code().map_or(Outcome::Signal, Outcome::Exit);
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            break Outcome::Hang;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let stderr = fs::read_to_string(&stderr_path).unwrap_or_default();

    let mut case = Case {
        base: base_index,
        mutations,
        input,
        failures: Vec::new(),
        panicked: stderr.contains("panicked"),
        internal: stderr.to_lowercase().contains("internal error"),
        nan: false,
        outcome,
    };
    if case.panicked {
        case.failures
            .push(format!("panicked: {}", first_lines(&stderr)));
    }
    if case.internal {
        case.failures
            .push(format!("internal error: {}", first_lines(&stderr)));
    }
    match case.outcome {
        Outcome::Exit(0) => {
            for name in OUTPUTS {
                let Ok(text) = fs::read_to_string(d.join(name)) else {
                    continue;
                };
                if let Some(bad) = non_finite(&text, name.ends_with(".svg")) {
                    case.nan = true;
                    case.failures.push(format!("{name} contains {bad}"));
                }
            }
        }
        Outcome::Exit(2) => {
            for name in OUTPUTS {
                if d.join(name).exists() {
                    case.failures.push(format!("exit 2 but {name} was written"));
                }
            }
        }
        Outcome::Exit(code) => case
            .failures
            .push(format!("exit status {code}: {}", first_lines(&stderr))),
        Outcome::Signal => case.failures.push("killed by a signal".into()),
        Outcome::Hang => case.failures.push(format!("no exit within {limit:.1?}")),
    }
    case
}

fn first_lines(text: &str) -> String {
    text.lines().take(3).collect::<Vec<_>>().join(" | ")
}

/// The first NaN or infinity token in `text` (CSV fields, JSON values; in an SVG only `NaN`,
/// whose labels are words).
fn non_finite(text: &str, svg: bool) -> Option<String> {
    if svg {
        return text.contains("NaN").then(|| "NaN".into());
    }
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .find(|t| {
            let l = t.to_ascii_lowercase();
            l == "nan" || l == "inf" || l == "infinity"
        })
        .map(str::to_owned)
}

fn env_u64(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

#[test]
fn mutated_inputs_exit_cleanly_without_nan_or_partial_output() {
    let cases = env_u64("SEALSIM_FUZZ_CASES", DEFAULT_CASES);
    let seed = env_u64("SEALSIM_FUZZ_SEED", DEFAULT_SEED);
    let bases = bases();
    let bin = PathBuf::from(env!("CARGO_BIN_EXE_sealsim"));
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get().min(4));

    let start = Instant::now();
    let limits = hang_limits(&bases, &bin, workers);
    let next = Mutex::new(0u64);
    let results: Mutex<Vec<(u64, Case)>> = Mutex::new(Vec::new());
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| {
                loop {
                    let index = {
                        let mut n = next.lock().unwrap();
                        let i = *n;
                        *n += 1;
                        i
                    };
                    if index >= cases {
                        break;
                    }
                    let case = run_case(index, seed, &bases, &bin, &limits);
                    results.lock().unwrap().push((index, case));
                }
            });
        }
    });
    let seconds = start.elapsed().as_secs_f64();
    let mut results = results.into_inner().unwrap();
    results.sort_by_key(|(i, _)| *i);

    let mut histogram: BTreeMap<String, usize> = BTreeMap::new();
    for (_, c) in &results {
        let key = match c.outcome {
            Outcome::Exit(code) => format!("exit {code}"),
            Outcome::Signal => "signal".into(),
            Outcome::Hang => "hang".into(),
        };
        *histogram.entry(key).or_default() += 1;
    }
    let count = |f: fn(&Case) -> bool| results.iter().filter(|(_, c)| f(c)).count();
    let panics = count(|c| c.panicked);
    let internal = count(|c| c.internal);
    let hangs = count(|c| c.outcome == Outcome::Hang);
    let nan = count(|c| c.nan);
    let histogram: Vec<String> = histogram.iter().map(|(k, v)| format!("{k}: {v}")).collect();
    println!(
        "fuzz: {cases} cases (seed {seed:#x}, {workers} workers) in {seconds:.1} s; {}; \
         {panics} panics, {internal} internal errors, {hangs} hangs, {nan} with NaN/inf",
        histogram.join(", ")
    );

    let failed: Vec<&(u64, Case)> = results
        .iter()
        .filter(|(_, c)| !c.failures.is_empty())
        .collect();
    let awaiting = |i: u64, c: &Case| {
        seed == DEFAULT_SEED
            && AWAITING_RANGES
                .iter()
                .any(|&(k, path)| k == i && bases[c.base].path == Path::new(path))
    };
    for (i, c) in failed.iter().take(40) {
        let known = if awaiting(*i, c) {
            " (known: awaiting the input ranges)"
        } else {
            ""
        };
        println!(
            "case {i}{known}: {} [{}]: {}",
            bases[c.base].path.display(),
            c.mutations.join("; "),
            c.failures.join("; ")
        );
    }
    if let Ok(dir) = std::env::var("SEALSIM_FUZZ_KEEP") {
        // Reproducers: the mutated inputs of the failed cases.
        fs::create_dir_all(&dir).unwrap();
        for (i, c) in &failed {
            let name = bases[c.base].path.file_name().unwrap().to_string_lossy();
            fs::write(Path::new(&dir).join(format!("case-{i}-{name}")), &c.input).unwrap();
        }
    }
    let unexpected = failed.iter().filter(|(i, c)| !awaiting(*i, c)).count();
    assert_eq!(
        unexpected, 0,
        "{unexpected} of {cases} fuzz cases broke an assertion (listed above)"
    );
}

/// The inputs that once broke the binary (`fuzz/reproducers/`, named `case-N-<shipped file>`),
/// each run as the fuzz runs its base: refused with exit 2 and nothing written, whatever the
/// default run's case count.
#[test]
fn every_reproducer_is_refused_with_exit_2_and_nothing_written() {
    let bin = PathBuf::from(env!("CARGO_BIN_EXE_sealsim"));
    let mut files: Vec<PathBuf> = fs::read_dir(root().join("fuzz/reproducers"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with("case-"))
        })
        .collect();
    files.sort();
    assert!(files.len() >= 19, "{} reproducers", files.len());
    for file in files {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let shipped = name.splitn(3, '-').nth(2).unwrap();
        let kind = match shipped {
            "psd-example.csv" => Kind::Psd,
            "cold-night.csv" => Kind::History,
            _ => Kind::Scenario,
        };
        let path = Path::new("scenarios").join(shipped);
        let bases = [Base {
            kind,
            text: fs::read_to_string(root().join(&path)).unwrap(),
            path,
        }];
        let input = fs::read_to_string(&file).unwrap();
        let case = execute(&bases, 0, input, Vec::new(), &bin, 10 * CASE_TIMEOUT);
        assert!(
            case.failures.is_empty(),
            "{name}: {}",
            case.failures.join("; ")
        );
        assert_eq!(case.outcome, Outcome::Exit(2), "{name}");
    }
}

#[test]
fn number_scanner_finds_signed_exponent_numbers() {
    let line = r#"q1 = "1e10 1/m"   x = -2.5e-3, AS568-225, h2o"#;
    let found: Vec<&str> = numbers(line).iter().map(|&(a, b)| &line[a..b]).collect();
    assert_eq!(found, ["1e10", "1", "-2.5e-3"]);
}
