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

/// A scenario text on the rough face the main scenario had before its callout (0.8 µm rms,
/// H 0.7, q0 3e5 1/m, q1 1e10 1/m: a face that leaks from the start): the `ra = …` line replaced
/// by those self-affine keys and the callout's cut-off keys dropped. For tests that need a leak
/// (on the ground face the ring seals).
pub fn on_former_rough_face(text: &str) -> String {
    text.lines()
        .filter(|l| {
            !["cutoff", "short_cutoff", "short_wavelength"]
                .iter()
                .any(|k| l.starts_with(k))
        })
        .map(|l| {
            if l.starts_with("ra = ") {
                "rms_roughness = \"0.8 um\"\nhurst_exponent = 0.7\nq0 = \"3e5 1/m\"\nq1 = \"1e10 1/m\"\n"
                    .to_owned()
            } else {
                format!("{l}\n")
            }
        })
        .collect()
}
