//! A rubber compound: its viscoelastic modulus, shift function, thermal and ageing data, and
//! where each number came from.

use super::{Prony, Shift};

/// Whether a compound's data are measured and published, or estimated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Every number traced to a publication (table, page).
    Published,
    /// At least one number estimated (e.g. modulus from hardness, WLF from T_g with the
    /// universal constants); the provenance says how. Not for design decisions.
    Illustrative,
    /// Given by the user (inline in a scenario, or fitted); no claim is made.
    User,
}

impl Status {
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Published => "published",
            Status::Illustrative => "illustrative",
            Status::User => "user",
        }
    }
}

/// Arrhenius chemical stress relaxation (DESIGN §6, ISO 11346 practice): the sealing stress
/// is multiplied by `exp(−∫ k(T) dt)`, `k(T) = k_ref exp(−(Ea/R)(1/T − 1/T_ref))`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ageing {
    /// Ea [J/mol].
    pub activation_energy: f64,
    /// k_ref [1/s] at `reference_temperature`.
    pub rate: f64,
    /// T_ref [K].
    pub reference_temperature: f64,
}

/// A rubber compound in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct Material {
    pub name: String,
    pub status: Status,
    /// Relaxation modulus E(ξ) in reduced time at the shift's reference temperature.
    pub prony: Prony,
    pub poisson_ratio: f64,
    pub shift: Shift,
    /// Glass transition temperature T_g [K].
    pub glass_transition: Option<f64>,
    /// Linear thermal expansion coefficient [1/K].
    pub thermal_expansion: Option<f64>,
    pub ageing: Option<Ageing>,
    /// (parameter key, where its value came from), in file order.
    pub provenance: Vec<(String, String)>,
}

impl Material {
    /// A linear-elastic, temperature-independent material (a scenario's `youngs_modulus`).
    pub fn elastic(name: impl Into<String>, youngs_modulus: f64, poisson_ratio: f64) -> Option<Self> {
        Some(Material {
            name: name.into(),
            status: Status::User,
            prony: Prony::elastic(youngs_modulus).ok()?,
            poisson_ratio,
            shift: Shift::None,
            glass_transition: None,
            thermal_expansion: None,
            ageing: None,
            provenance: Vec::new(),
        })
    }

    /// The provenance of `key`, if recorded.
    pub fn provenance_of(&self, key: &str) -> Option<&str> {
        self.provenance.iter().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }
}
