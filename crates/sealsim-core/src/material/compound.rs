//! A rubber compound: its viscoelastic modulus, shift function, thermal and ageing data, and
//! where each number came from.
//!
//! # Material TOML schema (shared by library files, scenario \[material\] tables and fit-prony output)
//!
//! A material file holds one `[material]` table; a scenario's inline `[material]` table uses the same keys.
//! Quantities: bare number = SI, or "`<number> <unit>`" strings (crates/sealsim-core/src/units.rs: parse_quantity, parse_temperature).
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
//! glassy_thermal_expansion = "7.7e-5 1/K"   # optional, linear CTE below glass_transition, > 0; absent = thermal_expansion
//! data_reduced_time = ["1 s", "1000 h"]     # optional: the reduced-time window of the data (fit-prony writes it)
//! data_temperature = ["23 C", "23 C"]        # optional: the temperature window of the data
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
//! long_term_modulus = "..."                 # prony, shift, glass_transition, thermal_expansion,
//!                                           # glassy_thermal_expansion, ageing
//! prony = "..."
//! shift = "..."
//! glass_transition = "..."
//! thermal_expansion = "..."
//! glassy_thermal_expansion = "..."
//! ageing = "..."
//! ```
//! Rules: exactly one of `youngs_modulus` or (`long_term_modulus` with optional `prony`) [prony without
//! long_term_modulus: E∞ = 0 is allowed only if written explicitly]. A scenario's \[material\] may instead be
//! `library = "ID"` (no other keys except, later, scenario-level options such as asperity_modulus).
//! Model type: `sealsim::material::Material` (crates/sealsim-core/src/material/compound.rs) with `prony: Prony`
//! (crates/sealsim-core/src/material/prony.rs; `Prony::new(long_term, &[PronyTerm{modulus,tau}])`, `Prony::elastic(E)`), `shift: Shift`
//! (crates/sealsim-core/src/material/shift.rs: `Shift::None | Wlf{reference,c1,c2} | Arrhenius{reference,activation_energy}`),
//! `status: Status` (Published | Illustrative | User — inline scenario materials and fit output are User),
//! `provenance: Vec<(String, String)>`.

use super::{Prony, Shift};

/// Time after applying the torque at which a Gehman reading is taken \[s\] (ASTM D1053 /
/// ISO 1432; see [`Material::low_temperature_limit`]).
pub const GEHMAN_READING_TIME: f64 = 10.0;

/// The room temperature of the Gehman test's reference reading, 23 °C \[K\].
pub const GEHMAN_ROOM_TEMPERATURE: f64 = 296.15;

/// The stiffening ratio that defines the low-temperature limit T10 (modulus 10 × its value at
/// 23 °C).
pub const T10_RATIO: f64 = 10.0;

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
///
/// The activation energy may differ on the two sides of the anchor T_ref (a band of Ea about a
/// rating, docs/model.md §6.5): `Ea = activation_energy` at and below T_ref,
/// `activation_energy_above` above it. k is continuous at T_ref; one Arrhenius law when the two
/// are equal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ageing {
    /// Ea at and below `reference_temperature` \[J/mol\].
    pub activation_energy: f64,
    /// Ea above `reference_temperature` \[J/mol\] (= `activation_energy` for one law).
    pub activation_energy_above: f64,
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

impl Ageing {
    /// One Arrhenius law: Ea \[J/mol\] on both sides of T_ref \[K\], k_ref \[1/s\], r.
    pub fn arrhenius(
        activation_energy: f64,
        rate: f64,
        reference_temperature: f64,
        crosslinking: f64,
    ) -> Self {
        Ageing {
            activation_energy,
            activation_energy_above: activation_energy,
            rate,
            reference_temperature,
            crosslinking,
        }
    }

    /// Whether the activation energy differs above T_ref.
    pub fn is_two_sided(&self) -> bool {
        self.activation_energy_above != self.activation_energy
    }

    /// The activation energy in force at T \[K\]: above T_ref `activation_energy_above`, else
    /// `activation_energy` \[J/mol\].
    pub fn activation_energy_at(&self, temperature: f64) -> f64 {
        if temperature > self.reference_temperature {
            self.activation_energy_above
        } else {
            self.activation_energy
        }
    }

    /// `k(T) = k_ref exp(−(Ea(T)/R)(1/T − 1/T_ref))` \[1/s\] at T \[K\].
    pub fn rate_at(&self, temperature: f64) -> f64 {
        let ea = self.activation_energy_at(temperature);
        self.rate
            * (-(ea / super::shift::GAS_CONSTANT)
                * (1.0 / temperature - 1.0 / self.reference_temperature))
                .exp()
    }

    /// The scission `K = ∫_a^b k(T(t)) dt` over `history` between times `a` and `b` \[s\]
    /// ([`super::shift::reduced_time_two_sided`]: exact at constant temperature, split where
    /// T crosses T_ref otherwise).
    pub fn scission(&self, history: &super::TemperatureHistory, a: f64, b: f64) -> f64 {
        self.rate
            * super::shift::reduced_time_two_sided(
                history,
                self.reference_temperature,
                self.activation_energy,
                self.activation_energy_above,
                a,
                b,
            )
    }
}

/// What a compound's ageing constants were measured on (library files): the property
/// (compression stress relaxation, compression set, …) and the end-of-life criterion.
#[derive(Debug, Clone, PartialEq)]
pub struct AgeingBasis {
    pub property: String,
    pub criterion: String,
    /// The medium the compound was aged in (`None`: not stated); a run in another medium warns
    /// (docs/model.md §6.8).
    pub medium: Option<AgeingMedium>,
    /// Where the activation energy comes from, in a line (`[material.ageing] source`; the
    /// `ageing` provenance has the whole chain); `sealsim compare` prints it beside each row.
    pub source: Option<String>,
}

/// The medium ageing constants were measured in (`[material.ageing] medium`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AgeingMedium {
    /// An air oven.
    Air,
    /// Mineral (petroleum) oil or hydraulic fluid.
    MineralOil,
    /// Water.
    Water,
    /// Water–glycol coolant.
    WaterGlycol,
}

impl AgeingMedium {
    pub const ALL: [AgeingMedium; 4] = [
        AgeingMedium::Air,
        AgeingMedium::MineralOil,
        AgeingMedium::Water,
        AgeingMedium::WaterGlycol,
    ];

    /// The file's word for it.
    pub fn as_str(self) -> &'static str {
        match self {
            AgeingMedium::Air => "air",
            AgeingMedium::MineralOil => "mineral-oil",
            AgeingMedium::Water => "water",
            AgeingMedium::WaterGlycol => "water-glycol",
        }
    }

    /// The medium of its [`AgeingMedium::as_str`] word.
    pub fn from_name(name: &str) -> Option<AgeingMedium> {
        AgeingMedium::ALL.into_iter().find(|m| m.as_str() == name)
    }
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
    /// Linear thermal expansion coefficient \[1/K\] (rubbery: above `glass_transition`).
    pub thermal_expansion: Option<f64>,
    /// Linear thermal expansion coefficient below `glass_transition` (glassy) \[1/K\]; `None`:
    /// `thermal_expansion` at every temperature ([`crate::seal::ThermalStrain`]).
    pub glassy_thermal_expansion: Option<f64>,
    pub ageing: Option<Ageing>,
    /// What the ageing constants were measured on (library files require it with `ageing`).
    pub ageing_basis: Option<AgeingBasis>,
    /// The reduced-time window \[s\] (at the shift's reference temperature) of the data the
    /// series was fitted to (`data_reduced_time`; `sealsim fit-prony` writes it): a life run
    /// warns when it goes beyond (docs/model.md §9.13).
    pub data_reduced_time: Option<(f64, f64)>,
    /// The temperature window \[K\] of the data (`data_temperature`): a run outside it warns.
    pub data_temperature: Option<(f64, f64)>,
    /// The compound's fluid compatibility, one rating per rated fluid class with its source
    /// (`[material.compatibility]`, docs/model.md §6.8); empty: not rated.
    pub compatibility: Vec<super::compatibility::Compatibility>,
    /// (parameter key, where its value came from), in file order.
    pub provenance: Vec<(String, String)>,
    /// The material-library id the compound was loaded from (`nbr-70`); `None` for an inline,
    /// fitted or user-file material. Data kept by compound class (permeation, docs/model.md
    /// §13.4) follow it.
    pub library_id: Option<String>,
    /// The compound class (`nbr`, `hnbr`, `fkm`, `ffkm`, `epdm`, `vmq`, `fvmq`, `iir`, `cr`,
    /// `acm`: [`crate::permeation::FAMILIES`]) whose data kept by class apply to it (gas
    /// permeation, docs/model.md §13.4): a library compound's from its id, another material's
    /// from its `class` key; `None`: none.
    pub class: Option<String>,
    /// The compound's own gas permeation figures (`[material.permeation]`), which take
    /// precedence over its class's.
    pub permeation: Vec<crate::permeation::UserPermeation>,
    /// The uncertainty bands of its figures (`[material.bands]`, docs/model.md §5.4): what a
    /// study draws from with `"band"`; empty: none stated.
    pub bands: Vec<FigureBand>,
}

/// The band of one of a compound's figures (`[material.bands]`, docs/model.md §5.4): the
/// figure's key relative to `[material]` (`ageing.activation_energy`), which is also the key a
/// study varies in the scenario (`[ageing]` overrides the compound's), its range in SI and
/// where the range comes from (a datasheet's rounding, a class's spread).
#[derive(Debug, Clone, PartialEq)]
pub struct FigureBand {
    pub key: String,
    /// Lower end (SI: J/mol for an activation energy).
    pub min: f64,
    /// Upper end (SI), above `min`.
    pub max: f64,
    pub source: String,
}

impl FigureBand {
    /// The SI unit `min` and `max` are in, as the files write it (`J/mol` for an activation
    /// energy; empty for a bare number).
    pub fn unit(&self) -> &'static str {
        if self.key.ends_with("activation_energy") {
            "J/mol"
        } else {
            ""
        }
    }
}

impl Material {
    /// A user's material of relaxation modulus `prony` and `poisson_ratio`, and nothing else: no
    /// temperature shift, glass transition, thermal expansion, ageing, data window,
    /// provenance or compatibility (set what the data give with struct update syntax).
    pub fn user(name: impl Into<String>, prony: Prony, poisson_ratio: f64) -> Self {
        Material {
            name: name.into(),
            status: Status::User,
            prony,
            poisson_ratio,
            shift: Shift::None,
            glass_transition: None,
            thermal_expansion: None,
            glassy_thermal_expansion: None,
            ageing: None,
            ageing_basis: None,
            data_reduced_time: None,
            data_temperature: None,
            provenance: Vec::new(),
            compatibility: Vec::new(),
            library_id: None,
            class: None,
            permeation: Vec::new(),
            bands: Vec::new(),
        }
    }

    /// A linear-elastic, temperature-independent material (a scenario's `youngs_modulus`).
    pub fn elastic(
        name: impl Into<String>,
        youngs_modulus: f64,
        poisson_ratio: f64,
    ) -> Option<Self> {
        Some(Material::user(
            name,
            Prony::elastic(youngs_modulus).ok()?,
            poisson_ratio,
        ))
    }

    /// The TR-10-like low-temperature limit T10 \[K\]: the temperature at which the modulus read
    /// at the time scale of a Gehman test is [`T10_RATIO`] = 10 times its value at 23 °C,
    ///
    /// `E(t_G / a_T(T10)) = 10 · E(t_G / a_T(23 °C))`, t_G = [`GEHMAN_READING_TIME`] = 10 s,
    ///
    /// with E the relaxation modulus in reduced time (the apparent torsional modulus of the
    /// test is a shear modulus, G = E/3 for an incompressible rubber: the ratio is the same).
    /// The Gehman test (ASTM D1053, ISO 1432) measures the relative torsional stiffness of a
    /// rubber strip from low temperatures up to room temperature, and T2, T5, T10, T100 are
    /// the temperatures at which it is 2, 5, 10, 100 times the 23 °C value. Only the scope of
    /// ISO 1432 (a torsional relative-stiffness test from room temperature to about −120 °C)
    /// and of ASTM D1053 (stiffening at low temperatures) could be read here; the 10 s
    /// reading time and the ratio definition are recalled, not confirmed from the standards.
    ///
    /// Found by bisection on T between the WLF frozen limit `Tref − C2` (1 K for an Arrhenius
    /// shift) and 23 °C: E(t_G/a_T(T)) decreases monotonically with T there. `None` when the
    /// material has no shift, when 23 °C is at or below the frozen limit, or when the modulus
    /// never reaches 10 × (E0 < 10 E(23 °C), e.g. a series without a glassy plateau).
    pub fn low_temperature_limit(&self) -> Option<f64> {
        // a root search to the last bit over the whole series (≈ 60 evaluations), asked by the
        // validation and the run of every case of a study: remembered per (series, shift), the
        // only inputs, by their exact bits
        let mut key: Vec<u64> = vec![self.prony.long_term().to_bits()];
        key.extend(
            self.prony
                .terms()
                .iter()
                .flat_map(|t| [t.modulus.to_bits(), t.tau.to_bits()]),
        );
        key.extend(match self.shift {
            Shift::None => [0, 0, 0, 0],
            Shift::Wlf { reference, c1, c2 } => {
                [1, reference.to_bits(), c1.to_bits(), c2.to_bits()]
            }
            Shift::Arrhenius {
                reference,
                activation_energy,
            } => [2, reference.to_bits(), activation_energy.to_bits(), 0],
        });
        static KNOWN: crate::math::memo::Memo<Vec<u64>, Option<f64>> =
            crate::math::memo::Memo::new(64);
        KNOWN.get_or_insert_with(key, || self.low_temperature_limit_uncached())
    }

    fn low_temperature_limit_uncached(&self) -> Option<f64> {
        let room = GEHMAN_ROOM_TEMPERATURE;
        let lower = match self.shift {
            Shift::None => return None,
            Shift::Wlf { .. } => self.shift.frozen_below()?,
            Shift::Arrhenius { .. } => 1.0,
        };
        if lower >= room {
            return None;
        }
        let target = T10_RATIO * self.gehman_modulus(room);
        // the modulus at the frozen limit is E0, the largest value it takes
        let top = self.gehman_modulus(lower);
        if top.is_nan() || target.is_nan() || top < target {
            return None;
        }
        // invariant: E(lo) ≥ target > E(hi)
        let (lo, hi) = sealsim_math::roots::bisect(
            lower,
            room,
            200,
            sealsim_math::roots::to_the_last_bit,
            |t| self.gehman_modulus(t) >= target,
        );
        Some(0.5 * (lo + hi))
    }

    /// The modulus read at the Gehman time scale at temperature `t` \[K\]:
    /// `E(t_G / a_T(t))` \[Pa\] (E0 when frozen).
    pub fn gehman_modulus(&self, t: f64) -> f64 {
        let xi = GEHMAN_READING_TIME * self.shift.ln_rate(t).exp();
        self.prony.relaxation(xi)
    }

    /// The provenance of `key`, if recorded.
    pub fn provenance_of(&self, key: &str) -> Option<&str> {
        self.provenance
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::PronyTerm;

    /// E∞ = 1 MPa and one term of 999 MPa at τ = 1 ms (E0 = 1 GPa), WLF at 23 °C.
    fn one_term(shift: Shift) -> Material {
        let mut m = Material::elastic("one term", 1e6, 0.5).unwrap();
        m.prony = Prony::new(
            1e6,
            &[PronyTerm {
                modulus: 999e6,
                tau: 1e-3,
            }],
        )
        .unwrap();
        m.shift = shift;
        m
    }

    #[test]
    fn t10_of_a_single_term_series_is_the_closed_form() {
        let (c1, c2) = (8.86, 101.6);
        let m = one_term(Shift::Wlf {
            reference: GEHMAN_ROOM_TEMPERATURE,
            c1,
            c2,
        });
        // E(ξ) = E∞ + E1 exp(−ξ/τ): the target 10 E(10 s) is reached at
        // ξ* = −τ ln((10 E(10 s) − E∞)/E1), i.e. a_T = 10 s/ξ*, and WLF inverted:
        // log10 a_T = L = −C1 ΔT/(C2 + ΔT) ⇒ ΔT = −C2 L/(C1 + L)
        let e10 = 1e6 + 999e6 * (-1e4_f64).exp();
        let xi = -1e-3 * ((10.0 * e10 - 1e6) / 999e6).ln();
        let l = (10.0 / xi).log10();
        let by_hand = GEHMAN_ROOM_TEMPERATURE - c2 * l / (c1 + l);
        let t10 = m.low_temperature_limit().unwrap();
        assert!((t10 - by_hand).abs() < 1e-9, "{t10} vs {by_hand}");
    }

    #[test]
    fn t10_needs_a_shift_and_a_glassy_rise() {
        assert_eq!(one_term(Shift::None).low_temperature_limit(), None);
        // an elastic material never stiffens
        let mut elastic = Material::elastic("e", 5e6, 0.5).unwrap();
        elastic.shift = Shift::Wlf {
            reference: GEHMAN_ROOM_TEMPERATURE,
            c1: 8.86,
            c2: 101.6,
        };
        assert_eq!(elastic.low_temperature_limit(), None);
        // Arrhenius: bisected down to 1 K, the equation holds there too
        let m = one_term(Shift::Arrhenius {
            reference: GEHMAN_ROOM_TEMPERATURE,
            activation_energy: 1e5,
        });
        let t10 = m.low_temperature_limit().unwrap();
        let ratio = m.gehman_modulus(t10) / m.gehman_modulus(GEHMAN_ROOM_TEMPERATURE);
        assert!((ratio / T10_RATIO - 1.0).abs() < 1e-9, "{ratio}");
        assert!(t10 < GEHMAN_ROOM_TEMPERATURE);
    }
}
