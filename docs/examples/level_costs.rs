//! The cost of each analytic fidelity level on every shipped scenario (docs/src/reference/fidelity.md
//! quotes its table).
//!
//!     cargo run --release --example level_costs [-- [--timeout SECONDS] [SCENARIO …]]
//!
//! For every scenario `sealsim run` accepts (default: every `scenarios/**/*.toml`; files that are
//! not a life scenario — studies, figure sets — are skipped) and every analytic level
//! (rule-of-thumb, critical-junction, exact, effective-medium) it builds the level's contact path
//! and runs the life *without* its band, in a child process of its own (so that a level that does
//! not finish is stopped at `--timeout`, default 120 s), and prints one Markdown row: the wall
//! time of the build and of the run \[s\], the outcome and the leaked volume. The band of
//! `sealsim run` costs the neighbouring level's row on top (docs/model.md §4.1).

use sealsim::leak::Fidelity;
use sealsim::scenario::Scenario;
use sealsim::simulate::Simulator;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const LEVELS: [Fidelity; 4] = [
    Fidelity::RuleOfThumb,
    Fidelity::Table,
    Fidelity::Exact,
    Fidelity::EffectiveMedium,
];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    // the child: one scenario at one level
    if args.first().map(String::as_str) == Some("--one") && args.len() == 3 {
        return one(Path::new(&args[1]), &args[2]);
    }
    let mut timeout = 120.0;
    if let Some(i) = args.iter().position(|a| a == "--timeout") {
        timeout = args.get(i + 1).ok_or("--timeout SECONDS")?.parse()?;
        args.drain(i..i + 2);
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<PathBuf> = if args.is_empty() {
        let mut all = Vec::new();
        collect(&root.join("scenarios"), &mut all)?;
        all
    } else {
        args.iter().map(PathBuf::from).collect()
    };
    files.sort();
    let me = std::env::current_exe()?;
    println!(
        "| scenario | level | build \\[s\\] | run \\[s\\] | outcome | leaked volume \\[m³\\] |"
    );
    println!("|---|---|---|---|---|---|");
    for file in files {
        if Scenario::load(&file).is_err() {
            continue;
        }
        let name = file
            .strip_prefix(root)
            .unwrap_or(&file)
            .display()
            .to_string();
        for level in LEVELS {
            let mut child = Command::new(&me)
                .args(["--one", &file.display().to_string(), level.name()])
                .stdout(Stdio::piped())
                .spawn()?;
            let start = Instant::now();
            let row = loop {
                if let Some(status) = child.try_wait()? {
                    let mut out = String::new();
                    if let Some(mut s) = child.stdout.take() {
                        std::io::Read::read_to_string(&mut s, &mut out)?;
                    }
                    break if status.success() {
                        out.trim().to_owned()
                    } else {
                        format!("failed ({status}) | | | |")
                    };
                }
                if start.elapsed() > Duration::from_secs_f64(timeout) {
                    child.kill()?;
                    child.wait()?;
                    break format!("> {timeout:.0} (stopped) | | | |");
                }
                std::thread::sleep(Duration::from_millis(20));
            };
            println!("| `{name}` | {} | {row}", level.name());
        }
    }
    Ok(())
}

/// Every `.toml` under `dir`.
fn collect(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            collect(&path, out)?;
        } else if path.extension().is_some_and(|e| e == "toml") {
            out.push(path);
        }
    }
    Ok(())
}

/// One scenario at one level: `build | run | outcome | leaked volume |`.
fn one(file: &Path, level: &str) -> Result<(), Box<dyn std::error::Error>> {
    let mut scenario = Scenario::load(file)?;
    scenario.life.fidelity = Fidelity::from_name(level).ok_or("unknown level")?;
    let start = Instant::now();
    let (path, _) =
        sealsim::workflow::scenario_path(&scenario, scenario.life.fidelity, None, &mut |_, _| {});
    let built = start.elapsed().as_secs_f64();
    let result = Simulator::with_path(&scenario.life, path).run();
    let total = start.elapsed().as_secs_f64();
    let outcome = match (result.failure, result.open_since()) {
        (Some(f), _) => format!("fails at {:.4e} s by {}", f.time, f.mode.as_str()),
        (None, Some(_)) => "open".to_owned(),
        (None, None) => "survives".to_owned(),
    };
    println!(
        "{built:.2} | {:.2} | {outcome} | {:.4e} |",
        total - built,
        result.leaked_volume()
    );
    Ok(())
}
