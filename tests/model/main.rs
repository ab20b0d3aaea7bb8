//! Integration tests of the library (one test binary: linking one is much faster than one per
//! file). Each module is a former `tests/NAME.rs`; run one with
//! `cargo test --release --test model NAME::`.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests and benches: a failure is a test failure"
)]

#[path = "../common/mod.rs"]
mod common;

mod architecture;
mod bem;
mod clogging;
mod contact_area;
mod datasheet;
mod docs_facts;
mod dynamic;
mod effective_medium;
mod feasibility;
mod fit;
mod flat_cold;
mod flow;
mod fluid;
mod gas;
mod gland;
mod gland_design;
mod height_map;
mod ihl;
mod interface;
mod life;
mod model_reference;
mod motion;
mod numerical;
mod permeation;
mod physics;
mod profile;
mod properties;
mod rng;
mod scenario;
mod tts;
mod viscoelastic;
