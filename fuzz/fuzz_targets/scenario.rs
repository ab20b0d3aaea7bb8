//! The scenario parser and validator on any text (a `psd_file`, `history` or material file it
//! names is looked up beside a path that does not exist: an error, not a crash).
#![no_main]

use libfuzzer_sys::fuzz_target;
use sealsim::scenario::Scenario;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let _ = Scenario::from_str(text, Path::new("/nonexistent-sealsim-fuzz/fuzz.toml"));
    let _ = sealsim::scenario::material_from_str(text, Path::new("fuzz-material.toml"));
});
