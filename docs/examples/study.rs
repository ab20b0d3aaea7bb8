//! A tolerance study as a library call: the first 40 cases of the shipped AS568-225 study
//! (cord, inside diameter and groove depth within their tolerances, 80 °C ± 3 K), their
//! Kaplan–Meier B10 life and the failure modes.
//!
//!     cargo run --release --example study
//!
//! `sealsim study scenarios/studies/as568-225-squeeze-tolerance.study.toml` runs all 400.

use sealsim::scenario::study::Study;
use sealsim::study::summary::StudySummary;
use sealsim::workflow;
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios/studies/as568-225-squeeze-tolerance.study.toml");
    let study = Study::load(&path)?;
    let cases = 40.min(study.cases());
    // all cores; the outcomes are the same bits on any number of threads
    let outcomes = workflow::study::run(&study, 0..cases, None, &|_, _| {})?;
    let summary = StudySummary::new(&outcomes, 0.95);
    println!("{}: {cases} of {} cases", study.name, study.cases());
    println!(
        "{} failed, {} survived, {} invalid",
        summary.failures, summary.censored, summary.invalid
    );
    for (mode, n) in &summary.modes {
        println!("  {n} by {}", mode.as_str());
    }
    for (p, life) in &summary.b_lives {
        if let Some(t) = life.estimate {
            println!("B{:.0}: {:.0} days", p * 100.0, t / 86_400.0);
        }
    }
    Ok(())
}
