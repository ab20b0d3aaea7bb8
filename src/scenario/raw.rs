//! The scenario file exactly as written: one struct per TOML table, every value spanned.
//!
//! Nothing here checks a value or knows a unit; that is [`super::validate`]'s job. Adding a
//! key means adding a field here and reading it there. All tables reject unknown keys, so a
//! misspelt key is an error with the key named, never silently ignored.

use serde::de::{self, Deserialize, Deserializer, Visitor};
use std::fmt;
use toml::Spanned;

/// A quantity as written: a bare number (already SI) or a string such as `"10 MPa"`.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum RawQuantity {
    Number(f64),
    Text(String),
}

/// A quantity with the byte span of its value in the scenario file.
pub(super) type Quantity = Spanned<RawQuantity>;

impl<'de> Deserialize<'de> for RawQuantity {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct QuantityVisitor;

        impl Visitor<'_> for QuantityVisitor {
            type Value = RawQuantity;

            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number (in SI units) or a quantity string such as \"10 MPa\"")
            }

            fn visit_f64<E: de::Error>(self, v: f64) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Number(v))
            }

            fn visit_i64<E: de::Error>(self, v: i64) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Number(v as f64))
            }

            fn visit_u64<E: de::Error>(self, v: u64) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Number(v as f64))
            }

            fn visit_str<E: de::Error>(self, v: &str) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Text(v.to_owned()))
            }
        }

        deserializer.deserialize_any(QuantityVisitor)
    }
}

/// The whole file.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScenario {
    pub name: Option<Spanned<String>>,
    pub material: Spanned<RawMaterial>,
    pub surface: Spanned<RawSurface>,
    pub fluid: Spanned<RawFluid>,
    pub seal: Spanned<RawSeal>,
    pub model: Option<Spanned<RawModel>>,
}

impl RawScenario {
    /// Top-level keys that are tables (a missing one is reported as a missing table).
    pub const TABLES: &[&str] = &["material", "surface", "fluid", "seal", "model"];
}

/// `[material]`: linear-elastic rubber.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMaterial {
    pub youngs_modulus: Quantity,
    pub poisson_ratio: Quantity,
}

/// `[surface]`: either the self-affine parameters or `psd_file` (checked in validation, so
/// that the message can explain the two options).
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSurface {
    pub rms_roughness: Option<Quantity>,
    pub hurst_exponent: Option<Quantity>,
    pub q0: Option<Quantity>,
    pub q1: Option<Quantity>,
    pub rolloff: Option<Quantity>,
    pub psd_file: Option<Spanned<String>>,
}

/// `[fluid]`: Newtonian fluid and the pressure across the seal.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFluid {
    pub viscosity: Quantity,
    pub pressure_difference: Quantity,
}

/// `[seal]`: a flat seal.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSeal {
    pub nominal_pressure: Quantity,
    pub width: Quantity,
    pub length: Quantity,
}

/// `[model]`: optional settings of the critical-junction theory.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawModel {
    pub percolation_threshold: Option<Quantity>,
    pub shape_factor: Option<Quantity>,
    pub gamma: Option<Quantity>,
}
