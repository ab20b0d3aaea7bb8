//! Helpers shared by the two test binaries, `tests/model` and `tests/cli` (included in each as
//! `#[path = "../common/mod.rs"] mod common;`).

use std::path::{Path, PathBuf};

/// The shipped scenario of the paper's §3 case, `scenarios/persson-yang-2008.toml`.
pub const PAPER: &str = include_str!("../../scenarios/persson-yang-2008.toml");

/// The directory of the shipped scenarios, `scenarios/` in the package.
pub fn scenarios_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios")
}

/// Path of the shipped scenario `scenarios/NAME`.
pub fn scenario_path(name: &str) -> PathBuf {
    scenarios_dir().join(name)
}

/// Relative difference `|a − b| / |b|` (`b = 0` counts as the smallest positive number).
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}
