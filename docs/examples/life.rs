//! A life run from a shipped scenario, as a library call: the headline NBR O-ring in 80 °C water.
//!
//!     cargo run --release --example life
//!
//! Prints the time to failure and its mode, and the sealing force and leak rate at the start and
//! the end — the same numbers `sealsim run scenarios/oring-nbr-water-80c.toml` prints.

use sealsim::scenario::Scenario;
use sealsim::workflow;
use std::path::Path;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/oring-nbr-water-80c.toml");
    // units parsed, every value checked once; an error names the file, line and key
    let scenario = Scenario::load(&path)?;
    let result = workflow::life::run(&scenario, &mut |_, _| {});
    let (first, last) = (&result.rows[0], &result.rows[result.rows.len() - 1]);
    println!("{}", scenario.name);
    println!(
        "sealing force {:.3} N/mm at installation, {:.3} N/mm at the end of the run ({:.0} years)",
        first.sealing_force / 1e3,
        last.sealing_force / 1e3,
        last.time / (365.25 * 86_400.0)
    );
    match &result.failure {
        Some(f) => println!(
            "fails after {:.0} days by {}",
            f.time / 86_400.0,
            f.mode.as_str()
        ),
        None => println!("survives the run"),
    }
    for finding in result.findings.iter() {
        println!("warning: {finding}");
    }
    Ok(())
}
