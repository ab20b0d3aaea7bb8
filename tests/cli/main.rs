//! End-to-end tests of the `sealsim` binary (one test binary: linking one is much faster than
//! one per file). Each module is a former `tests/cli_NAME.rs`; run one with
//! `cargo test --release --test cli NAME::`.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

#[path = "../common/mod.rs"]
mod common;
mod support;

mod advise;
mod ageing_fit;
mod callout;
mod cold;
mod contact_area;
mod engineering_units;
mod feasibility;
mod figures;
mod fit;
mod flat_cold;
mod fuzz;
mod gas;
mod generate;
mod generate_reference;
mod gland;
mod gland_design;
mod gland_pressure;
mod hardening;
mod integration;
mod leak;
mod levels;
mod materials;
mod motion;
mod new;
mod plots;
mod pressure_history;
mod ranges;
mod ranking;
mod reader_fuzz;
mod report;
mod rubber;
mod run;
mod small_defects;
mod study;
mod study_sizes;
mod summary_units;
mod surface;
mod swell;
mod tradeoff;
mod traps;
mod validity;
mod verdicts;
mod warning_codes;
mod write_faults;
