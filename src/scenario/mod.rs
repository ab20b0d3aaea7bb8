//! Scenario files: TOML → validated model types in SI units.
//!
//! A scenario is read in two steps, so that the physics never sees a string or a unit:
//! 1. `raw`: serde reads the TOML into one struct per table, every value wrapped in
//!    [`toml::Spanned`] and unknown keys rejected;
//! 2. `validate`: every quantity is converted to SI ("10 MPa" → 1e7; a bare number is
//!    already SI) and checked against its range once, giving a [`leak::StaticProblem`] and
//!    a [`simulate::LifeProblem`] (`life`: the O-ring/flat seal, `[environment]`,
//!    `[failure]`, `[ageing]`, `[simulation]`), and the optional `[motion]` of a reciprocating
//!    seal ([`crate::dynamic::MotionSpec`]).
//!
//! Every error is a [`ScenarioError`] naming the file, the line and the key, e.g.
//! `scenarios/x.toml:7: surface.hurst_exponent: must lie strictly between 0 and 1, got 1.2`.
//! Every key is defined once in the key registry, [`keys`], which renders the reference
//! `docs/src/reference/keys.md` (`sealsim generate keys`).
//!
//! [`leak::StaticProblem`]: crate::leak::StaticProblem
//! [`simulate::LifeProblem`]: crate::simulate::LifeProblem

pub mod ageing_data;
#[cfg(test)]
mod ageing_fit_tests;
pub mod as568;
#[cfg(test)]
mod library_tests;
pub use crate::material::compatibility;
mod contamination;
pub mod datasheet;
mod error;
mod field;
pub mod figure_set;
pub mod fit_data;
mod gland;
pub mod gsf;
mod height_map;
mod history;
pub mod keys;
#[cfg(test)]
mod keys_tests;
pub mod library;
pub mod library_check;
pub mod life;
mod material;
mod motion;
pub mod profile;
mod psd;
mod raw;
mod seal_kind;
mod seal_spec;
pub mod study;
mod surface_files;
pub mod templates;
mod text;
mod validate;
mod validated;

pub use error::{InputWarning, ScenarioError};
pub use height_map::{MAX_HEIGHT, MAX_PIXELS, NO_DATA, implausible_height};
pub use material::{PARAMETERS, load_material_file, material_from_str};
pub use surface_files::{is_gsf, parse_height_map, read_height_map, read_psd_file};
pub use text::DataFileError;
pub use validated::Scenario;

use crate::material::Material;
use error::Source;
use raw::RawScenario;
use std::path::Path;
use text::read;

impl Scenario {
    /// Reads and validates the scenario file at `path` (a `psd_file` or `height_map` is
    /// resolved against its directory).
    pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
        Scenario::from_str(&read(path)?, path)
    }

    /// Validates scenario `text` as if it had been read from `path` (used for the messages,
    /// the default name and to resolve a relative `psd_file`; `path` itself is not read).
    pub fn from_str(text: &str, path: &Path) -> Result<Scenario, ScenarioError> {
        Scenario::validate(text, path, None)
    }

    /// Reads the scenario file at `path` with `material` in place of the compound its
    /// `[material]` table gives (the table's `asperity_modulus` still applies); used by
    /// `sealsim compare`. Everything that depends on the material (the environment's default
    /// temperature, the thermal strain, the ageing defaults) is validated against `material`.
    pub fn load_with_material(path: &Path, material: &Material) -> Result<Scenario, ScenarioError> {
        Scenario::validate(&read(path)?, path, Some(material))
    }

    /// [`Scenario::from_str`] with an optional replacement material.
    pub fn from_str_with_material(
        text: &str,
        path: &Path,
        material: &Material,
    ) -> Result<Scenario, ScenarioError> {
        Scenario::validate(text, path, Some(material))
    }

    fn validate(
        text: &str,
        path: &Path,
        replacement: Option<&Material>,
    ) -> Result<Scenario, ScenarioError> {
        let source = Source { path, text };
        let raw: RawScenario = source.deserialize()?;
        source.scenario(&raw, replacement)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PAPER: &str = include_str!("../../scenarios/persson-yang-2008.toml");

    fn load(text: &str) -> Result<Scenario, ScenarioError> {
        Scenario::from_str(text, Path::new("dir/x.toml"))
    }

    fn error(text: &str) -> String {
        load(text)
            .expect_err("the scenario should be rejected")
            .to_string()
    }

    #[test]
    fn paper_scenario_is_in_si_units() {
        let s = load(PAPER).unwrap();
        let p = &s.problem;
        assert_eq!(s.name, "Persson & Yang 2008, section 3");
        assert_eq!(p.material.youngs_modulus, 1e7);
        assert_eq!(p.material.poisson_ratio, 0.5);
        assert!((p.spectrum.rms_roughness() / 2e-6 - 1.0).abs() < 1e-12);
        assert!((p.spectrum.q0() / 1e4 - 1.0).abs() < 1e-12);
        assert!((p.spectrum.q1() / 7.8e9 - 1.0).abs() < 1e-12);
        assert_eq!(p.fluid.viscosity, 1e-3);
        assert_eq!(p.fluid.pressure_difference, 1e4);
        assert_eq!(p.seal.nominal_pressure, 2e5);
        assert_eq!(p.seal.width, 1e-3);
        assert_eq!(p.seal.length, 1e-3);
        assert_eq!(p.contact, crate::contact::ContactSettings::default());
        assert_eq!(p.shape_factor, 1.0);
    }

    #[test]
    fn name_defaults_to_the_file_stem_and_bare_numbers_need_units() {
        let unnamed = PAPER.replace("name = \"Persson & Yang 2008, section 3\"\n", "");
        assert_eq!(load(&unnamed).unwrap().name, "x");
        // `1e7` for a modulus: Pa to a parser, MPa to a reader — refused with the units it takes
        let e = error(&unnamed.replace("\"10 MPa\"", "1e7"));
        assert!(
            e.contains(
                "material.youngs_modulus: a pressure needs its unit: write \"1e7 bar\", \"1e7 \
                 MPa\" or \"1e7 psi\""
            ),
            "{e}"
        );
        // each suggestion is accepted
        for unit in ["bar", "MPa", "psi"] {
            let fixed = unnamed.replace("\"10 MPa\"", &format!("\"10 {unit}\""));
            assert!(load(&fixed).is_ok(), "{unit}");
        }
    }

    #[test]
    fn model_table_overrides_defaults() {
        let text = format!(
            "{PAPER}\n[model]\npercolation_threshold = 0.42\nshape_factor = 2\ngamma = 0.5\n"
        );
        let p = load(&text).unwrap().problem;
        assert_eq!(p.contact.percolation_threshold, 0.42);
        assert_eq!(p.contact.gamma, 0.5);
        assert_eq!(p.shape_factor, 2.0);
    }

    #[test]
    fn errors_name_file_line_and_key() {
        let e = error(&PAPER.replace("hurst_exponent = 0.8", "hurst_exponent = 1.2"));
        assert!(
            e.starts_with(
                "dir/x.toml:7: surface.hurst_exponent: must lie strictly between 0 and 1"
            ),
            "{e}"
        );
        let e = error(&PAPER.replace("poisson_ratio", "poisson"));
        assert!(
            e.starts_with("dir/x.toml:4: material.poisson: unknown key `poisson`"),
            "{e}"
        );
        let e = error(&PAPER.replace("viscosity = \"1e-3 Pa*s\"\n", ""));
        assert!(e.starts_with("dir/x.toml:"), "{e}");
        assert!(
            e.contains("fluid.viscosity: missing key `viscosity` in [fluid]"),
            "{e}"
        );
        let e = error(&PAPER.replace("\"0.2 MPa\"", "\"10 m\""));
        assert!(
            e.contains(":14: seal.nominal_pressure: expected a pressure"),
            "{e}"
        );
        let e = error(&PAPER.replace("poisson_ratio = 0.5", "poisson_ratio = true"));
        assert!(
            e.contains(":4: material.poisson_ratio: invalid type"),
            "{e}"
        );
        let e = error(&PAPER.replace("[seal]", "[seal"));
        assert!(e.contains(":13: TOML syntax error"), "{e}");
        let e = error(&PAPER.replace("[fluid]", "[fluidx]"));
        assert!(e.contains("fluidx: unknown key"), "{e}");
    }

    #[test]
    fn surface_needs_exactly_one_kind_of_spectrum() {
        let start = PAPER.find("rms_roughness").unwrap();
        let end = PAPER.find("[fluid]").unwrap();
        let none = format!("{}{}", &PAPER[..start], &PAPER[end..]);
        let e = error(&none);
        assert!(
            e.contains(": surface: no spectrum given") && e.contains("psd_file"),
            "{e}"
        );
        let both = PAPER.replace("[surface]", "[surface]\npsd_file = \"p.csv\"");
        let e = error(&both);
        assert!(
            e.contains("surface.rms_roughness: psd_file gives the whole spectrum"),
            "{e}"
        );
        let partial = PAPER.replace("q1 = \"7.8e9 1/m\"\n", "");
        let e = error(&partial);
        assert!(e.contains(":5: surface.q1: missing key"), "{e}");
    }
}
