//! A rubber compound: its viscoelastic modulus, shift function, thermal and ageing data, and
//! where each number came from.
//!
//! # Material TOML schema (shared by library files, scenario \[material\] tables and fit-prony output)
//!
//! A material file holds one `[material]` table; a scenario's inline `[material]` table uses the same keys.
//! Quantities: bare number = SI, or "`<number> <unit>`" strings (src/units.rs: parse_quantity, parse_temperature).
//!
//! ```toml
//! [material]
//! name = "NBR, 70 Shore A"                 # string, required in library files
//! status = "illustrative"                   # "published" | "illustrative"; library files only (required there)
//! poisson_ratio = 0.4995                    # dimensionless, [0, 0.5]
//! # EITHER elastic:
//! youngs_modulus = "10 MPa"                 # > 0  (static engine's key from issue 2; must keep working)
//! # OR viscoelastic (Prony series in reduced time at the shift's reference temperature):
//! long_term_modulus = "4 MPa"               # E∞ >= 0
//! prony = [ { modulus = "6 MPa", tau = "1000 h" }, { modulus = 1.5e6, tau = 3600 } ]   # E_i > 0, τ_i > 0 (time)
//! glass_transition = "-30 C"                # optional, absolute temperature (parse_temperature)
//! thermal_expansion = "2.3e-4 1/K"          # optional, linear CTE, > 0 (Dimension::THERMAL_EXPANSION)
//! [material.shift]                          # optional; absent = no temperature dependence
//! kind = "wlf"                              # "wlf" | "arrhenius"
//! reference_temperature = "23 C"            # absolute temperature
//! c1 = 8.86                                 # wlf: dimensionless, > 0
//! c2 = "101.6 K"                            # wlf: temperature DIFFERENCE (parse_quantity with Dimension::TEMPERATURE), > 0
//! # activation_energy = "90 kJ/mol"         # arrhenius: > 0 (Dimension::MOLAR_ENERGY)
//! [material.ageing]                         # optional: two-network chemical ageing (Arrhenius)
//! activation_energy = "90 kJ/mol"           # > 0
//! rate = "1e-9 1/s"                         # k_ref > 0 (Dimension::FREQUENCY)
//! reference_temperature = "100 C"
//! crosslinking = 1.0                        # optional, r = k_x/k_s in [0, 10], default 1 (balanced)
//! property = "compression set (ISO 815)"    # what Ea and k were measured on; required in library files
//! criterion = "80 % compression set"        # the end-of-life criterion; required in library files
//! [material.provenance]                     # string per parameter; REQUIRED in library files for every
//! poisson_ratio = "..."                     # parameter present: poisson_ratio, long_term_modulus (or youngs_modulus),
//! long_term_modulus = "..."                 # prony, shift, glass_transition, thermal_expansion, ageing
//! prony = "..."
//! shift = "..."
//! glass_transition = "..."
//! thermal_expansion = "..."
//! ageing = "..."
//! ```
//! Rules: exactly one of `youngs_modulus` or (`long_term_modulus` with optional `prony`) [prony without
//! long_term_modulus: E∞ = 0 is allowed only if written explicitly]. A scenario's \[material\] may instead be
//! `library = "ID"` (no other keys except, later, scenario-level options such as asperity_modulus).
//! Model type: `sealsim::material::Material` (src/material/compound.rs) with `prony: Prony`
//! (src/material/prony.rs; `Prony::new(long_term, &[PronyTerm{modulus,tau}])`, `Prony::elastic(E)`), `shift: Shift`
//! (src/material/shift.rs: `Shift::None | Wlf{reference,c1,c2} | Arrhenius{reference,activation_energy}`),
//! `status: Status` (Published | Illustrative | User — inline scenario materials and fit output are User),
//! `provenance: Vec<(String, String)>`.

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

/// Chemical ageing by the two-network model (docs/model.md §6.5; Andrews, Tobolsky & Hanson,
/// J. Appl. Phys. 17 (1946) 352): the original network breaks at the Arrhenius rate
/// `k(T) = k_ref exp(−(Ea/R)(1/T − 1/T_ref))` \[1/s\] (ISO 11346 practice), and a new network
/// forms at `r·k(T)` in the deformed state ([`crate::material::RelaxationState::step_aged`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ageing {
    /// Ea \[J/mol\].
    pub activation_energy: f64,
    /// k_ref \[1/s\] at `reference_temperature`.
    pub rate: f64,
    /// T_ref \[K\].
    pub reference_temperature: f64,
    /// r = k_x/k_s: 1 (the default) balances scission by crosslinking in the deformed state,
    /// so that compression set = 1 − F/F0 at constant squeeze; 0 is scission alone (no set:
    /// the sealing stress is multiplied by `exp(−∫ k dt)`).
    pub crosslinking: f64,
}

/// The default r of [`Ageing::crosslinking`].
pub const BALANCED_CROSSLINKING: f64 = 1.0;

/// What a compound's ageing constants were measured on (library files): the property
/// (compression stress relaxation, compression set, …) and the end-of-life criterion.
#[derive(Debug, Clone, PartialEq)]
pub struct AgeingBasis {
    pub property: String,
    pub criterion: String,
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
    /// Glass transition temperature T_g \[K\].
    pub glass_transition: Option<f64>,
    /// Linear thermal expansion coefficient \[1/K\].
    pub thermal_expansion: Option<f64>,
    pub ageing: Option<Ageing>,
    /// What the ageing constants were measured on (library files require it with `ageing`).
    pub ageing_basis: Option<AgeingBasis>,
    /// (parameter key, where its value came from), in file order.
    pub provenance: Vec<(String, String)>,
}

impl Material {
    /// A linear-elastic, temperature-independent material (a scenario's `youngs_modulus`).
    pub fn elastic(
        name: impl Into<String>,
        youngs_modulus: f64,
        poisson_ratio: f64,
    ) -> Option<Self> {
        Some(Material {
            name: name.into(),
            status: Status::User,
            prony: Prony::elastic(youngs_modulus).ok()?,
            poisson_ratio,
            shift: Shift::None,
            glass_transition: None,
            thermal_expansion: None,
            ageing: None,
            ageing_basis: None,
            provenance: Vec::new(),
        })
    }

    /// The provenance of `key`, if recorded.
    pub fn provenance_of(&self, key: &str) -> Option<&str> {
        self.provenance
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}
