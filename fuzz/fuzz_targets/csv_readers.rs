//! The CSV readers: the tabulated spectrum (`psd_file`), the temperature history (`history`)
//! and the fit data of `sealsim fit-prony`. The spectrum and history readers are private to
//! the scenario module, so the data go through a scenario that names a file holding them.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sealsim::scenario::Scenario;
use sealsim::scenario::fit_data::{FitKind, parse_fit_data};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

const PSD_SCENARIO: &str = r#"name = "fuzz"
[material]
youngs_modulus = "10 MPa"
poisson_ratio = 0.5
[surface]
psd_file = "data.csv"
[fluid]
viscosity = "1e-3 Pa*s"
pressure_difference = "0.01 MPa"
[seal]
nominal_pressure = "0.2 MPa"
width = "1 mm"
length = "1 mm"
"#;

const HISTORY_SCENARIO: &str = r#"name = "fuzz"
[material]
library = "nbr-70"
[surface]
rms_roughness = "0.8 um"
hurst_exponent = 0.7
q0 = "3e5 1/m"
q1 = "1e10 1/m"
[fluid]
viscosity = "1 mPa*s"
pressure_difference = "2 bar"
[seal]
kind = "flat"
nominal_pressure = "1 MPa"
width = "1 mm"
length = "1 m"
[environment]
history = "data.csv"
[failure]
max_leak_rate = "2.0e-10 m^3/s"
"#;

/// A directory of this process for the data file.
fn dir() -> &'static PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let d = std::env::temp_dir().join(format!("sealsim-fuzz-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&d);
        d
    })
}

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    match selector % 4 {
        0 | 1 => {
            let scenario = if selector % 4 == 0 {
                PSD_SCENARIO
            } else {
                HISTORY_SCENARIO
            };
            if std::fs::write(dir().join("data.csv"), text).is_ok() {
                let _ = Scenario::from_str(scenario, &dir().join("fuzz.toml"));
            }
        }
        2 => {
            let _ = parse_fit_data(text, Path::new("fuzz.csv"), FitKind::Relaxation);
        }
        _ => {
            let _ = parse_fit_data(text, Path::new("fuzz.csv"), FitKind::Dma);
        }
    }
});
