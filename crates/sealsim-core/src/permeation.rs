//! Gas permeation through the rubber of a seal (docs/model.md §13): steady Fickian permeation, its
//! temperature dependence, the build-up from an empty membrane (time lag), the path through a
//! squeezed O-ring or a flat gasket, and a small table of permeability data with provenance.
//!
//! Everything is SI and knows no file or unit string.
//!
//! **Units.** The permeability coefficient Π is carried in **mol·m/(m²·s·Pa)** = mol/(m·s·Pa):
//! moles of gas through unit area per unit time, per unit thickness, per pascal of partial
//! pressure difference. A throughput in Pa·m³/s (the leak-test form) is n·R·T at the temperature
//! the pV is stated at ([`pv_throughput`]). Literature values come in barrer:
//!
//! 1 barrer = 1e-10 cm³(STP)·cm/(cm²·s·cmHg)
//!          = 1e-10 · (1e-6 m³)(1e-2 m)/((1e-4 m²)·s·(1333.224 Pa))
//!          = 1e-14/1333.224 = 7.5006e-18 m³(STP)·m/(m²·s·Pa)
//!
//! (the definition as stated in the Taylor & Francis chapter abstract cited in docs/model.md §13:
//! "7.5E−14 cm3·cm/cm2 Pa s or 1.0E−10 cm3 cm/cm2 s cm Hg"); one cm³(STP) at 0 °C and 1 atm is
//! 1e-6/(R·273.15 K/101325 Pa) = 1e-6/0.0224140 mol, so
//! 1 barrer = 7.5006e-18/0.0224140 = 3.3464e-16 mol·m/(m²·s·Pa) ([`BARRER`]).
//!
//! **Relations** (Henry's-law sorption, concentration-independent diffusivity):
//!
//! * solubility–diffusion: `Π = D·S` (D \[m²/s\], S \[mol/(m³·Pa)\]);
//! * steady flux through a slab of thickness ℓ: `J = Π (p_a − p_b)/ℓ` \[mol/(m²·s)\] (Fick's
//!   first law with the surface concentrations `S p_a`, `S p_b`);
//! * Arrhenius: `Π(T) = Π_ref exp(−E_P/R (1/T − 1/T_ref))`, D likewise with E_D;
//! * time lag `t_lag = ℓ²/(6D)`, and the amount through unit area of an initially empty slab
//!   (upstream face at C1 = S p_a from t = 0, downstream face held at 0):
//!   `Q(t)/(ℓ C1) = τ − 1/6 − (2/π²) Σ (−1)ⁿ/n² exp(−n²π²τ)`, τ = D t/ℓ². Derived in
//!   docs/model.md §13.2 by separation of variables (the form is Crank's, *The Mathematics of
//!   Diffusion*, eq. 4.24a \[recalled\]); at long times it is the line τ − 1/6, whose intercept on
//!   the time axis is the time lag.

use std::f64::consts::PI;
use std::fmt;

/// Molar gas constant R \[J/(mol·K)\] (2019 SI, exact).
pub const GAS_CONSTANT: f64 = 8.314_462_618;

/// One centimetre of mercury \[Pa\] (10 × 133.322 4 Pa).
pub const CM_HG: f64 = 1333.224;

/// Standard temperature of "cm³(STP)" \[K\] (0 °C).
pub const STP_TEMPERATURE: f64 = 273.15;

/// Standard pressure of "cm³(STP)" \[Pa\] (1 atm).
pub const STP_PRESSURE: f64 = 101_325.0;

/// One barrer as a volume permeability: 1e-10 cm³(STP)·cm/(cm²·s·cmHg) in
/// m³(STP)·m/(m²·s·Pa) = 1e-14/1333.224 ≈ 7.5006e-18.
pub const BARRER_STP_VOLUME: f64 = 1e-14 / CM_HG;

/// One barrer in mol·m/(m²·s·Pa): [`BARRER_STP_VOLUME`] divided by the molar volume at STP,
/// R·273.15/101325 = 0.022414 m³/mol, ≈ 3.3464e-16.
pub const BARRER: f64 = BARRER_STP_VOLUME / (GAS_CONSTANT * STP_TEMPERATURE / STP_PRESSURE);

/// A permeability in barrer → mol·m/(m²·s·Pa).
pub fn barrer_to_si(barrer: f64) -> f64 {
    barrer * BARRER
}

/// A permeability in mol·m/(m²·s·Pa) → barrer.
pub fn si_to_barrer(permeability: f64) -> f64 {
    permeability / BARRER
}

/// The Arrhenius factor `exp(−E/R (1/T − 1/T_ref))` (E \[J/mol\], T, T_ref \[K\]): the ratio of a
/// thermally activated coefficient at T to its value at T_ref.
pub fn arrhenius_factor(activation_energy: f64, temperature: f64, reference: f64) -> f64 {
    (-activation_energy / GAS_CONSTANT * (1.0 / temperature - 1.0 / reference)).exp()
}

/// Permeability from solubility and diffusivity, `Π = D·S` \[mol/(m·s·Pa)\], with D \[m²/s\] and
/// S \[mol/(m³·Pa)\] (Henry's law: dissolved concentration C = S p).
pub fn permeability_from(diffusivity: f64, solubility: f64) -> f64 {
    diffusivity * solubility
}

/// Steady Fickian flux through a slab \[mol/(m²·s)\]: `J = Π (p_a − p_b)/ℓ`, Π \[mol/(m·s·Pa)\],
/// partial pressures p \[Pa\], thickness ℓ \[m\].
pub fn steady_flux(permeability: f64, p_high: f64, p_low: f64, thickness: f64) -> f64 {
    permeability * (p_high - p_low) / thickness
}

/// Time lag of a slab, `t_lag = ℓ²/(6D)` \[s\]: where the long-time line of the permeated amount
/// crosses the time axis.
pub fn time_lag(thickness: f64, diffusivity: f64) -> f64 {
    thickness * thickness / (6.0 * diffusivity)
}

/// Below this τ = D t/ℓ² the short-time (image) forms are used; above it the Fourier series.
/// Both are exact; at τ = 0.1 the first neglected image term is exp(−9/0.4) ≈ 1.7e-10 and the
/// Fourier series needs ≈ 7 terms.
const SHORT_TIME: f64 = 0.1;

/// Number of Fourier terms for exp(−n²π²τ) < 1e-18 at the last one.
fn fourier_terms(tau: f64) -> usize {
    ((41.5 / (PI * PI * tau)).sqrt().ceil() as usize).clamp(1, 1_000_000) + 1
}

/// ierfc(x) = ∫ₓ^∞ erfc(s) ds = exp(−x²)/√π − x·erfc(x).
fn ierfc(x: f64) -> f64 {
    (-x * x).exp() / PI.sqrt() - x * libm::erfc(x)
}

/// Flux into the low-pressure side of an initially empty slab relative to its steady value,
/// `J(t)/J_ss = 1 + 2 Σ_{n≥1} (−1)ⁿ exp(−n²π²τ)`, τ = D t/ℓ² (dimensionless, in \[0, 1\]).
/// For τ < 0.1 the equivalent image form `(2/√(πτ)) Σ_{m≥0} exp(−(2m+1)²/(4τ))` (Poisson
/// summation of the series, docs/model.md §13.2) is used: it converges in a few terms there.
pub fn transient_flux_ratio(tau: f64) -> f64 {
    if tau.is_nan() || tau <= 0.0 {
        return 0.0;
    }
    let ratio = if tau < SHORT_TIME {
        let mut sum = 0.0;
        for m in 0..64 {
            let k = (2 * m + 1) as f64;
            let term = (-k * k / (4.0 * tau)).exp();
            sum += term;
            if term < 1e-300 {
                break;
            }
        }
        2.0 / (PI * tau).sqrt() * sum
    } else {
        let mut sum = 0.0;
        for n in 1..=fourier_terms(tau) {
            let sign = if n % 2 == 1 { -1.0 } else { 1.0 };
            let nf = n as f64;
            sum += sign * (-nf * nf * PI * PI * tau).exp();
        }
        1.0 + 2.0 * sum
    };
    ratio.clamp(0.0, 1.0)
}

/// Amount permeated through unit area of an initially empty slab, in units of ℓ·C1
/// (C1 = S·p_a the dissolved concentration at the upstream face; the downstream face held at
/// zero): `Q/(ℓ C1) = τ − 1/6 − (2/π²) Σ_{n≥1} (−1)ⁿ/n² exp(−n²π²τ)`, τ = D t/ℓ².
/// For τ < 0.1 the time integral of the image form, `4√τ Σ_{m≥0} ierfc((2m+1)/(2√τ))`, is used.
pub fn transient_amount(tau: f64) -> f64 {
    if tau.is_nan() || tau <= 0.0 {
        return 0.0;
    }
    let amount = if tau < SHORT_TIME {
        let root = tau.sqrt();
        let mut sum = 0.0;
        for m in 0..64 {
            let term = ierfc((2 * m + 1) as f64 / (2.0 * root));
            sum += term;
            if term < 1e-300 {
                break;
            }
        }
        4.0 * root * sum
    } else {
        let mut sum = 0.0;
        for n in 1..=fourier_terms(tau) {
            let sign = if n % 2 == 1 { -1.0 } else { 1.0 };
            let nf = n as f64;
            sum += sign / (nf * nf) * (-nf * nf * PI * PI * tau).exp();
        }
        tau - 1.0 / 6.0 - 2.0 / (PI * PI) * sum
    };
    amount.max(0.0)
}

/// pV throughput of a molar flow \[Pa·m³/s\]: `Q_pV = ṅ R T`, T \[K\] the temperature at which the
/// pV is stated (the gas's temperature for a leak detector reading; 273.15 K for "std" units).
pub fn pv_throughput(molar_flow: f64, temperature: f64) -> f64 {
    molar_flow * GAS_CONSTANT * temperature
}

/// Why a permeation path could not be built.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathError {
    /// A length that must be finite and positive is not \[m\].
    NotPositive { what: &'static str, value: f64 },
    /// The squeeze is outside \[0, 1).
    Squeeze(f64),
}

impl fmt::Display for PathError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PathError::NotPositive { what, value } => {
                write!(f, "{what} must be finite and positive, got {value}")
            }
            PathError::Squeeze(s) => write!(f, "squeeze must be in [0, 1), got {s}"),
        }
    }
}

impl std::error::Error for PathError {}

fn positive(what: &'static str, value: f64) -> Result<f64, PathError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(PathError::NotPositive { what, value })
    }
}

/// The permeation path through a seal's rubber, as an equivalent slab (docs/model.md §13.3):
/// gas enters through `area` \[m²\] on the pressurised side and crosses `length` \[m\] of rubber
/// to the low-pressure side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PermeationPath {
    /// Exposed area on the high-pressure side \[m²\].
    pub area: f64,
    /// Path length through the rubber \[m\].
    pub length: f64,
}

impl PermeationPath {
    /// A flat slab of face area `area` \[m²\] and thickness `thickness` \[m\].
    pub fn slab(area: f64, thickness: f64) -> Result<Self, PathError> {
        Ok(PermeationPath {
            area: positive("area", area)?,
            length: positive("thickness", thickness)?,
        })
    }

    /// A squeezed O-ring (docs/model.md §13.3): the compressed cord of free cross-section d is
    /// taken as a rectangle of height `h = d(1 − ε)` (the gland depth it is squeezed to) and
    /// width `w = πd²/(4h)` (the cord's area conserved: rubber is nearly incompressible); the gas
    /// enters through the flank of height h facing the pressure and crosses the width w. Around
    /// the mean circumference πD: area `πD·h`, length `w`, so the steady molar flow is
    /// `πD Π h Δp / w = 4 D (1 − ε)² Π Δp`. ε = 0 gives h = d, w = πd/4.
    /// `cross_section` d, `mean_diameter` D \[m\], `squeeze` ε in \[0, 1).
    pub fn o_ring(cross_section: f64, mean_diameter: f64, squeeze: f64) -> Result<Self, PathError> {
        let d = positive("cross-section", cross_section)?;
        let diameter = positive("mean diameter", mean_diameter)?;
        if !(squeeze.is_finite() && (0.0..1.0).contains(&squeeze)) {
            return Err(PathError::Squeeze(squeeze));
        }
        let (h, w) = squeezed_cord(d, squeeze);
        Ok(PermeationPath {
            area: PI * diameter * h,
            length: w,
        })
    }

    /// A flat gasket: the exposed inner edge of thickness `thickness` \[m\] (compressed) around the
    /// circumference `circumference` \[m\], crossed over the land width `land_width` \[m\].
    pub fn gasket(thickness: f64, land_width: f64, circumference: f64) -> Result<Self, PathError> {
        Ok(PermeationPath {
            area: positive("thickness", thickness)? * positive("circumference", circumference)?,
            length: positive("land width", land_width)?,
        })
    }

    /// Steady molar flow through the path \[mol/s\]: `Π A (p_a − p_b)/ℓ`, Π \[mol/(m·s·Pa)\],
    /// partial pressures \[Pa\].
    pub fn steady_molar_flow(&self, permeability: f64, p_high: f64, p_low: f64) -> f64 {
        self.area * steady_flux(permeability, p_high, p_low, self.length)
    }

    /// Time lag of the path, ℓ²/(6D) \[s\], D \[m²/s\].
    pub fn time_lag(&self, diffusivity: f64) -> f64 {
        time_lag(self.length, diffusivity)
    }

    /// Molar flow \[mol/s\] at time `t` \[s\] after the pressure was applied to a gas-free seal:
    /// the steady flow times [`transient_flux_ratio`] of τ = D t/ℓ². With no diffusivity known
    /// (`None`) the steady flow is returned (the upper bound).
    pub fn molar_flow_at(
        &self,
        permeability: f64,
        diffusivity: Option<f64>,
        p_high: f64,
        p_low: f64,
        time: f64,
    ) -> f64 {
        let steady = self.steady_molar_flow(permeability, p_high, p_low);
        match diffusivity {
            Some(d) if d > 0.0 => {
                steady * transient_flux_ratio(d * time / (self.length * self.length))
            }
            _ => steady,
        }
    }

    /// Moles permeated \[mol\] by time `t` \[s\] from a gas-free seal: `A ℓ C1 · Q/(ℓC1)(τ)` with
    /// C1 = (Π/D)·Δp, i.e. `A Π Δp ℓ/D · transient_amount(τ)`. Tends to
    /// `steady flow × (t − t_lag)`.
    pub fn permeated_moles(
        &self,
        permeability: f64,
        diffusivity: f64,
        p_high: f64,
        p_low: f64,
        time: f64,
    ) -> f64 {
        let l = self.length;
        let tau = diffusivity * time / (l * l);
        self.area * permeability * (p_high - p_low) * l / diffusivity * transient_amount(tau)
    }
}

/// Height and width of the squeezed cord as a rectangle of the same area:
/// `h = d(1 − ε)`, `w = πd²/(4h)` \[m\].
pub fn squeezed_cord(cross_section: f64, squeeze: f64) -> (f64, f64) {
    let h = cross_section * (1.0 - squeeze);
    (h, PI * cross_section * cross_section / (4.0 * h))
}

/// How a data row was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DataStatus {
    /// The number read in a cited source: a dataset row whose original paper is named (of the
    /// class's polymer or, said so, of its homopolymer proxy), with its units and temperature.
    Published,
    /// Derived from published numbers by a stated step (air from N2 and O2, Π = D·S of a
    /// secondary table); not for design decisions.
    Illustrative,
    /// NOT SOURCED: no figure of the class was found; a stated conservative bound (the highest
    /// plausible value) stands in. Every output that shows the permeation says so.
    Bound,
    /// The user's own figure (`[material.permeation]`).
    User,
}

impl DataStatus {
    /// The word the machine-readable outputs carry.
    pub fn as_str(self) -> &'static str {
        match self {
            DataStatus::Published => "published",
            DataStatus::Illustrative => "illustrative",
            DataStatus::Bound => "bound",
            DataStatus::User => "user",
        }
    }

    /// The words people read beside a figure.
    pub fn words(self) -> &'static str {
        match self {
            DataStatus::Published => "sourced",
            DataStatus::Illustrative => "ILLUSTRATIVE (derived or secondary)",
            DataStatus::Bound => "NOT SOURCED bound",
            DataStatus::User => "the user's figure",
        }
    }

    /// The weaker of two statuses (a figure derived from both is no better than either).
    fn weaker(self, other: DataStatus) -> DataStatus {
        let rank = |s: DataStatus| match s {
            DataStatus::Published => 0,
            DataStatus::User => 1,
            DataStatus::Illustrative => 2,
            DataStatus::Bound => 3,
        };
        if rank(other) > rank(self) {
            other
        } else {
            self
        }
    }
}

/// Permeation data of one gas in one compound class at `reference_temperature`.
#[derive(Debug, Clone, PartialEq)]
pub struct PermeationData {
    /// Compound class ([`FAMILIES`]), or `user` for the user's figure.
    pub family: String,
    /// Gas: a [`GASES`] id ("carbon dioxide" spelt with a space), `argon` or `custom` for a
    /// user's figure.
    pub gas: String,
    /// Π at the reference temperature \[mol/(m·s·Pa)\].
    pub permeability: f64,
    /// E_P \[J/mol\].
    pub permeability_activation: f64,
    /// D at the reference temperature \[m²/s\], when a value or a bound exists.
    pub diffusivity: Option<f64>,
    /// Whether D is the upper bound Π/S_min ([`HELIUM_SOLUBILITY_FLOOR`],
    /// [`HYDROGEN_SOLUBILITY_FLOOR`]) rather than a measured value: a shorter time lag, an
    /// earlier breakthrough.
    pub diffusivity_is_bound: bool,
    /// E_D \[J/mol\] (taken equal to E_P: temperature-independent solubility).
    pub diffusivity_activation: f64,
    /// T_ref \[K\].
    pub reference_temperature: f64,
    pub status: DataStatus,
    /// Where Π comes from, in a line (printed beside `compare` rows and by `materials show`).
    pub source: String,
    /// The whole chain: Π, D and E_P (docs/model.md §13.4).
    pub provenance: String,
}

impl PermeationData {
    /// Π at T \[K\] by Arrhenius.
    pub fn permeability_at(&self, temperature: f64) -> f64 {
        self.permeability
            * arrhenius_factor(
                self.permeability_activation,
                temperature,
                self.reference_temperature,
            )
    }

    /// D at T \[K\] by Arrhenius, when known.
    pub fn diffusivity_at(&self, temperature: f64) -> Option<f64> {
        self.diffusivity.map(|d| {
            d * arrhenius_factor(
                self.diffusivity_activation,
                temperature,
                self.reference_temperature,
            )
        })
    }

    /// Henry solubility S = Π/D at T \[mol/(m³·Pa)\], when D is known.
    pub fn solubility_at(&self, temperature: f64) -> Option<f64> {
        self.diffusivity_at(temperature)
            .map(|d| self.permeability_at(temperature) / d)
    }

    /// `"<status words>: <source>"`, e.g. `"NOT SOURCED bound: …"` (the outputs' label).
    pub fn basis(&self) -> String {
        let d = if self.diffusivity_is_bound {
            "; D an upper bound (shortest time lag)"
        } else {
            ""
        };
        format!("{}: {}{d}", self.status.words(), self.source)
    }

    /// The user's figure `user` for its gas (docs/model.md §13.4): Π and D at 23 °C as given,
    /// E_P and E_D the table's for that gas (`activation_energy` of `family`, silicone's
    /// small values for `vmq` and `fvmq`), and for a gas the table lacks (argon, a custom gas)
    /// the table's largest, 45 kJ/mol (conservative above 23 °C).
    pub fn user(user: &UserPermeation, family: Option<&str>) -> Self {
        let table_gas = GASES.iter().find(|g| **g == user.gas.replace('-', " "));
        let energy = match table_gas {
            Some(g) => activation_energy(family.unwrap_or("nbr"), g),
            None => 45e3,
        };
        let source = user
            .source
            .clone()
            .unwrap_or_else(|| "the material's [material.permeation] (no source given)".into());
        PermeationData {
            family: "user".into(),
            gas: user.gas.clone(),
            permeability: user.permeability,
            permeability_activation: energy,
            diffusivity: user.diffusivity,
            diffusivity_is_bound: false,
            diffusivity_activation: energy,
            reference_temperature: TABLE_REFERENCE_TEMPERATURE,
            status: DataStatus::User,
            provenance: format!(
                "the user's figure ({source}) at 23 °C; E_P = E_D = {} kJ/mol (sealsim's table)",
                energy / 1e3
            ),
            source,
        }
    }
}

/// A user's permeation figure for one gas (`[material.permeation] GAS = { … }`), in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct UserPermeation {
    /// The gas library id (`helium`, `carbon-dioxide`, …, `argon`) or `custom`.
    pub gas: String,
    /// Π at 23 °C \[mol/(m·s·Pa)\].
    pub permeability: f64,
    /// D at 23 °C \[m²/s\] (`None`: the steady flow from installation, an upper bound).
    pub diffusivity: Option<f64>,
    /// Where the figure comes from.
    pub source: Option<String>,
}

/// Compound classes with data (sourced rows or stated bounds for every gas of [`GASES`]).
pub const FAMILIES: [&str; 10] = [
    "acm", "cr", "epdm", "ffkm", "fkm", "fvmq", "hnbr", "iir", "nbr", "vmq",
];

/// Gases with data.
pub const GASES: [&str; 7] = [
    "helium",
    "hydrogen",
    "nitrogen",
    "oxygen",
    "air",
    "carbon dioxide",
    "methane",
];

/// Reference temperature of the table \[K\] (23 °C). Rows measured at 20–25 °C are used as
/// they are (2–3 K is ≈ 10 % at 30–45 kJ/mol, inside the spread between sources); rows
/// measured hotter (35–50 °C) are used at 23 °C as they are, an upper bound there (Π rises
/// with T), and said so.
pub const TABLE_REFERENCE_TEMPERATURE: f64 = 296.15;

/// The lowest helium solubility of a rubbery polymer in the polyVERSE compilation (npj Comput.
/// Mater. 2024, doi:10.1038/s41524-024-01373-9; `s_exp_He`): poly(methyl acrylate)'s
/// 1.459e-4 cm³(STP)/(cm³·cmHg) (cis-polybutadiene 2.23e-4, Viton 0.093/76 = 1.2e-3; only
/// glassy or crystalline PVC, nylon-11 and a substituted polyacetylene dissolve less), in
/// mol/(m³·Pa). Where no helium diffusivity was found, D ≤ Π/S_min bounds it from above:
/// helium, a weakly sorbing gas, dissolves in every rubber of the table at least this well
/// (ASSUMED for the classes without a value; the bound holds for the three that have one).
pub const HELIUM_SOLUBILITY_FLOOR: f64 = 1.459e-4 * CM3_STP_PER_CM3_CMHG;

/// The low end of the hydrogen solubility of carbon-black-filled NBR, 2.2e-4
/// cm³(STP)/(cm³·cmHg) (abstract on H2 in filled NBR, docs/model.md §13.6 \[NBR-H2\]), in
/// mol/(m³·Pa): the floor of the H2 diffusivity bound D ≤ Π/S_min (ASSUMED for the other
/// classes: no other H2 solubility was found).
pub const HYDROGEN_SOLUBILITY_FLOOR: f64 = 2.2e-4 * CM3_STP_PER_CM3_CMHG;

/// One cm³(STP)/(cm³·cmHg) in mol/(m³·Pa): (1e-6 m³/0.022414 m³/mol)/(1e-6 m³ · 1333.224 Pa).
const CM3_STP_PER_CM3_CMHG: f64 = 1.0 / (GAS_CONSTANT * STP_TEMPERATURE / STP_PRESSURE) / CM_HG;

// Original papers of the sourced rows (docs/model.md §13.4; values as read from the NIMS
// PoLyInfo conversion in jsunn-y/PolymerGasMembraneML and from Ramprasad-Group/polyVERSE).
const YASUDA: &str = "Yasuda & Rosengren, J. Appl. Polym. Sci. 14 (1970) 2839 (PDMS, 25 °C)";
const NPJ: &str = "npj Comput. Mater. (2024), doi:10.1038/s41524-024-01373-9, compiled \
                   experimental value (298 K)";
const ITO: &str = "Ito, Kobunshi Kagaku 18 (1961) 124 (20 °C)";
const SCHUCK: &str = "Schuck, Kautsch. Gummi Kunstst. 33 (1980) 705 (23 °C)";
const AMERONGEN: &str = "van Amerongen, J. Appl. Phys. 17 (1946) 972 (43 °C, used at 23 °C: an \
                         upper bound there)";
const PAUL79: &str = "Paul, Ber. Bunsenges. Phys. Chem. 83 (1979) 294 (25 °C)";
const KENBISHI: &str = "Kenbishi, Int. Polym. Sci. Technol. 8 (1981) T105 (50 °C, used at 23 °C: \
                        an upper bound there)";
const MOGRI_PAUL: &str = "Mogri & Paul, Polymer 42 (2001) 7765 (poly(ethyl acrylate) as ACM's \
                          proxy, 35 °C, used at 23 °C: an upper bound there)";
const VITON: &str = "D·S of Viton from the EXO/nEXO model file citing arXiv:1703.09144 \
                     (secondary; S taken per atm)";

/// The bound for a class without its own figure, per gas \[barrer\] and what it is: the
/// highest value of the non-silicone rubbers read near room temperature (20–25 °C, and ACM's
/// proxy at 35 °C; hotter rows, polybutadiene at 35–50 °C for one, are left out: docs/model.md
/// §13.4). Hennig Gasket ranks helium "nitrile … lowest. EPDM has only slightly higher
/// permeation, closely followed by FKM": NBR and EPDM are bounded by FKM's own helium figure
/// (a tie, not an inversion).
fn envelope(gas: &str) -> Option<(f64, &'static str)> {
    Some(match gas {
        "helium" => (
            fkm_barrer("helium")?,
            "NBR ≤ EPDM ≤ FKM for helium (Hennig Gasket), so FKM's own 53.4 barrer (Viton D·S), \
             the highest non-silicone helium figure in the table",
        ),
        "hydrogen" => (
            60.4,
            "the highest non-silicone H2 figure in the table: poly(ethyl acrylate) 60.4 barrer, \
             Mogri & Paul 2001, 35 °C",
        ),
        "nitrogen" => (
            25.1,
            "the highest non-silicone N2 figure in the table: cis-polybutadiene 25.1 barrer \
             (NBR's diene part; npj Comput. Mater. 2024 compilation, 298 K)",
        ),
        "oxygen" => (
            23.3,
            "the highest non-silicone O2 figure in the table: natural rubber 23.3 barrer, Paul \
             1979, 25 °C",
        ),
        "carbon dioxide" => (
            176.0,
            "the highest non-silicone CO2 figure in the table: poly(ethyl acrylate) 176 barrer, \
             Mogri & Paul 2001, 35 °C",
        ),
        "methane" => (
            30.3,
            "the highest non-silicone CH4 figure read near room temperature: natural rubber \
             30.3 barrer, Michaels & Bixler, J. Polym. Sci. 50 (1961) 413, 25 °C",
        ),
        _ => return None,
    })
}

/// Π of `gas` in `family` at 23 °C \[barrer\], its status and its source; air is derived
/// ([`air_of`]) by the caller.
fn row(family: &str, gas: &str) -> Option<(f64, DataStatus, String)> {
    use DataStatus::{Bound, Illustrative, Published};
    let sourced = |barrer: f64, source: &str| Some((barrer, Published, source.to_owned()));
    let bound =
        |why: &str| envelope(gas).map(|(barrer, what)| (barrer, Bound, format!("{why}: {what}")));
    const NONE: &str = "no figure of this class found";
    match (family, gas) {
        // PDMS: the higher of the two sourced rows per gas (conservative)
        ("vmq", "helium") => sourced(339.0, NPJ),
        ("vmq", "hydrogen") => sourced(770.0, NPJ),
        ("vmq", "nitrogen") => sourced(277.0, NPJ),
        ("vmq", "oxygen") => sourced(551.0, NPJ),
        ("vmq", "carbon dioxide") => sourced(3240.0, YASUDA),
        ("vmq", "methane") => sourced(908.0, NPJ),
        // poly(methyltrifluoropropylsiloxane)
        ("fvmq", "helium") => sourced(247.0, NPJ),
        ("fvmq", "nitrogen") => sourced(88.3, NPJ),
        ("fvmq", "oxygen") => sourced(200.0, NPJ),
        ("fvmq", "carbon dioxide") => sourced(1390.0, NPJ),
        ("fvmq", "methane") => sourced(201.0, NPJ),
        ("fvmq", "hydrogen") => Some((
            770.0,
            Bound,
            "no FVMQ H2 figure found: PDMS's 770 barrer (npj 2024), since the same compilation \
             puts FVMQ below PDMS for every other gas (He 247/339, O2 200/551, N2 88/277, CO2 \
             1390/3040, CH4 201/908)"
                .to_owned(),
        )),
        // polyisobutylene, butyl's homopolymer proxy: the highest near-room-temperature row
        ("iir", "helium") => sourced(8.11, ITO),
        ("iir", "hydrogen") => sourced(6.5, ITO),
        ("iir", "nitrogen") => sourced(0.3, ITO),
        ("iir", "oxygen") => sourced(0.6384, SCHUCK),
        ("iir", "carbon dioxide") => sourced(5.5, ITO),
        // Schuck's 23 °C CH4 equals its O2 (a suspected conversion artefact)
        ("iir", "methane") => sourced(0.7237, AMERONGEN),
        // polychloroprene
        ("cr", "helium") => sourced(5.37, ITO),
        ("cr", "hydrogen") => sourced(37.5, KENBISHI),
        ("cr", "nitrogen") => sourced(1.2, PAUL79),
        ("cr", "oxygen") => sourced(4.0, PAUL79),
        ("cr", "carbon dioxide") => sourced(25.8, PAUL79),
        ("cr", "methane") => sourced(12.89, KENBISHI),
        // poly(ethyl acrylate), ACM's proxy (the more permeable of the two acrylates)
        ("acm", "helium") => sourced(44.0, MOGRI_PAUL),
        ("acm", "hydrogen") => sourced(60.4, MOGRI_PAUL),
        ("acm", "nitrogen") => sourced(6.46, MOGRI_PAUL),
        ("acm", "oxygen") => sourced(19.0, MOGRI_PAUL),
        ("acm", "carbon dioxide") => sourced(176.0, MOGRI_PAUL),
        ("acm", "methane") => sourced(14.9, MOGRI_PAUL),
        // Viton's own D·S where it exists, the bound elsewhere
        ("fkm", "helium" | "nitrogen" | "oxygen") => {
            Some((fkm_barrer(gas)?, Illustrative, VITON.to_owned()))
        }
        ("fkm", _) => bound("no FKM figure for this gas found"),
        ("nbr" | "hnbr" | "epdm" | "ffkm", _) => bound(NONE),
        _ => None,
    }
}

/// E_P \[J/mol\]. H2 in NBR: 36 kJ/mol, the middle of the 33–39 kJ/mol of Gim et al., Polymers
/// 16 (2024) 280 (abstract). Every other value ILLUSTRATIVE: inside the 18–51 kJ/mol range
/// reported for O2 and H2O through polymer O-rings — Kalrez, Viton, … — (J. IEST 38(2) 43,
/// abstract), larger for larger molecules; the siloxanes' small values \[recalled: silicone's
/// permeability depends weakly on temperature\].
fn activation_energy(family: &str, gas: &str) -> f64 {
    let kj = if matches!(family, "vmq" | "fvmq") {
        match gas {
            "carbon dioxide" => 0.0,
            "helium" => 8.0,
            _ => 10.0,
        }
    } else {
        match gas {
            "helium" => 30.0,
            "hydrogen" => 36.0,
            "carbon dioxide" => 35.0,
            "oxygen" => 40.0,
            "air" => 43.0,
            _ => 45.0, // nitrogen, methane
        }
    };
    kj * 1000.0
}

/// FKM (Viton) diffusivity D \[cm²/s\] and solubility S of He, N2 and O2 as tabulated in the
/// EXO/nEXO xenon-purity model file (a public GitHub code file whose comments cite
/// arXiv:1703.09144; secondary: the paper itself was not read): He 436e-8 and 0.093, N2 2.2e-8
/// and 0.51, O2 6.8e-8 and 0.22. The file says "Solubility given as fraction"; it is taken as
/// cm³(STP)/(cm³·atm) (ASSUMED basis; the He/N2 ratio does not depend on it). The file's one
/// activation energy for every gas and polymer (0.17 eV) looks like a placeholder and is not used.
fn fkm_diffusivity_solubility(gas: &str) -> Option<(f64, f64)> {
    match gas {
        "helium" => Some((436e-8, 0.093)),
        "nitrogen" => Some((2.2e-8, 0.51)),
        "oxygen" => Some((6.8e-8, 0.22)),
        _ => None,
    }
}

/// Π \[barrer\] of D \[cm²/s\] times S \[cm³(STP)/(cm³·atm)\]: D·S is in
/// cm³(STP)·cm/(cm²·s·atm); one atm is 76 cmHg and one barrer 1e-10 cm³(STP)·cm/(cm²·s·cmHg).
fn barrer_of_ds(diffusivity_cm2: f64, solubility_per_atm: f64) -> f64 {
    diffusivity_cm2 * solubility_per_atm / 76.0 / 1e-10
}

/// Air as 79 % N2 and 21 % O2 by partial pressure: each gas permeates on its own partial
/// pressure difference, so the mixture's Π is the partial-pressure-weighted mean.
fn air_of(nitrogen: f64, oxygen: f64) -> f64 {
    0.79 * nitrogen + 0.21 * oxygen
}

/// FKM's Π \[barrer\] for the gases its source gives (He, N2, O2).
fn fkm_barrer(gas: &str) -> Option<f64> {
    fkm_diffusivity_solubility(gas).map(|(d, s)| barrer_of_ds(d, s))
}

/// The helium/nitrogen permeability ratio of a compound class at 23 °C and what it rests on.
pub fn helium_nitrogen_ratio(family: &str) -> Option<(f64, String)> {
    let he = data(family, "helium")?;
    let n2 = data(family, "nitrogen")?;
    let status = he.status.weaker(n2.status);
    Some((
        he.permeability / n2.permeability,
        format!("{}: He {}; N2 {}", status.words(), he.basis(), n2.basis()),
    ))
}

/// D at 23 °C \[m²/s\] and whether it is a bound: Viton's own He, N2 and O2 for FKM
/// (secondary); elsewhere, for helium and hydrogen, the upper bound Π/S_min
/// ([`HELIUM_SOLUBILITY_FLOOR`], [`HYDROGEN_SOLUBILITY_FLOOR`]); none for the other gases
/// (the steady flow from installation, the upper bound of the build-up).
fn diffusivity(family: &str, gas: &str, permeability: f64) -> Option<(f64, bool)> {
    if family == "fkm"
        && let Some((d, _)) = fkm_diffusivity_solubility(gas)
    {
        return Some((d * 1e-4, false));
    }
    match gas {
        "helium" => Some((permeability / HELIUM_SOLUBILITY_FLOOR, true)),
        "hydrogen" => Some((permeability / HYDROGEN_SOLUBILITY_FLOOR, true)),
        _ => None,
    }
}

/// The compound class of a material-library id ("nbr-70" → "nbr"), if it has data.
pub fn family_of(library_id: &str) -> Option<&'static str> {
    let stem = library_id.split('-').next()?.to_ascii_lowercase();
    FAMILIES.iter().copied().find(|f| *f == stem)
}

/// Permeation data of `gas` (see [`GASES`]; "carbon-dioxide" is read as "carbon dioxide") in a
/// compound `family` (see [`FAMILIES`]), or `None` (an unknown class or gas). Every pair of the
/// two lists has a row: sourced, derived, or a stated bound (docs/model.md §13.4).
pub fn data(family: &str, gas: &str) -> Option<PermeationData> {
    let family = FAMILIES.iter().copied().find(|f| *f == family)?;
    let spelt = gas.replace('-', " ");
    let gas = GASES.iter().copied().find(|g| *g == spelt)?;
    let (barrer, status, source) = if gas == "air" {
        let (n2, n2_status, _) = row(family, "nitrogen")?;
        let (o2, o2_status, _) = row(family, "oxygen")?;
        let status = n2_status.weaker(o2_status).weaker(DataStatus::Illustrative);
        let status = if status == DataStatus::Bound {
            DataStatus::Bound
        } else {
            DataStatus::Illustrative
        };
        (
            air_of(n2, o2),
            status,
            "air = 0.79 N2 + 0.21 O2 of this class's rows".to_owned(),
        )
    } else {
        row(family, gas)?
    };
    let permeability = barrer_to_si(barrer);
    let energy = activation_energy(family, gas);
    let d = diffusivity(family, gas, permeability);
    let provenance = format!(
        "Π = {} barrer at 23 °C: {} ({}); D {}; E_P = E_D = {} kJ/mol (ILLUSTRATIVE except H2 \
         in nitrile, Gim et al. 2024)",
        crate::units::human(barrer, 4),
        source,
        status.words(),
        match d {
            Some((d, true)) => format!(
                "≤ Π/S_min = {} m²/s (an upper bound: the shortest time lag)",
                crate::units::human(d, 3)
            ),
            Some((d, false)) => format!("{} m²/s ({VITON})", crate::units::human(d, 3)),
            None => "unknown: the steady flow from installation (an upper bound)".to_owned(),
        },
        energy / 1e3
    );
    Some(PermeationData {
        family: family.to_owned(),
        gas: gas.to_owned(),
        permeability,
        permeability_activation: energy,
        diffusivity: d.map(|d| d.0),
        diffusivity_is_bound: d.is_some_and(|d| d.1),
        diffusivity_activation: energy,
        reference_temperature: TABLE_REFERENCE_TEMPERATURE,
        status,
        source,
        provenance,
    })
}

/// Why a gas run has no permeation figure: the scenario layer refuses it at the key to give.
#[derive(Debug, Clone, PartialEq)]
pub enum Missing {
    /// The material has no class (an inline or file material without `class`) and no figure
    /// of its own for the gas.
    NoClass,
    /// The class has no row for the gas (argon, a custom gas) and the material no figure.
    NoRow { family: &'static str },
    /// A flat seal without its compressed `thickness`: the edge the gas enters is unknown.
    NoThickness,
    /// The path could not be built.
    Path(PathError),
}

/// The figure a run uses for `gas` (a gas library id: `carbon-dioxide`, `argon`, `custom`) in a
/// compound of class `family` with its own figures `user`: the user's for that gas, else the
/// class's row.
pub fn figure(
    family: Option<&str>,
    user: &[UserPermeation],
    gas: &str,
) -> Result<PermeationData, Missing> {
    if let Some(own) = user.iter().find(|u| u.gas == gas) {
        return Ok(PermeationData::user(own, family));
    }
    let Some(family) = family.and_then(|f| FAMILIES.iter().copied().find(|k| *k == f)) else {
        return Err(Missing::NoClass);
    };
    data(family, gas).ok_or(Missing::NoRow { family })
}

/// Permeation through a seal in a life run (docs/model.md §13.7): the path through the ring or
/// gasket at its installation squeeze, the gas's data in the compound, and the absolute
/// pressures of the gas service (P_a on the pressurised side, P_b on the other; the gas is
/// taken as pure, so its partial pressures are the absolute ones).
#[derive(Debug, Clone, PartialEq)]
pub struct SealPermeation {
    pub path: PermeationPath,
    pub data: PermeationData,
    /// P_a, absolute \[Pa\].
    pub p_high: f64,
    /// P_b, absolute \[Pa\].
    pub p_low: f64,
}

/// A simplification of a run's permeation, said as a note (not an error).
pub type PermeationNote = String;

impl SealPermeation {
    /// The permeation of `data` through a seal of geometry `geometry`, with P_a = `p_high`,
    /// P_b = `p_low` \[Pa\]. An O-ring uses [`PermeationPath::o_ring`] at its installation
    /// squeeze ε0; a flat gasket its edge ([`PermeationPath::gasket`]), which needs its
    /// compressed `thickness` \[m\] ([`Missing::NoThickness`] without it). The note says what
    /// is bounded (no diffusivity: the steady flow from installation).
    pub fn for_seal(
        data: PermeationData,
        geometry: &crate::seal::SealGeometry,
        thickness: Option<f64>,
        p_high: f64,
        p_low: f64,
    ) -> Result<(SealPermeation, Option<PermeationNote>), Missing> {
        use crate::seal::PermeationSection;
        let path = match geometry.permeation_section(thickness) {
            Some(PermeationSection::Ring {
                cross_section,
                mean_diameter,
                squeeze,
            }) => PermeationPath::o_ring(cross_section, mean_diameter, squeeze),
            Some(PermeationSection::Gasket {
                thickness,
                land_width,
                circumference,
            }) => PermeationPath::gasket(thickness, land_width, circumference),
            None => return Err(Missing::NoThickness),
        }
        .map_err(Missing::Path)?;
        let note = data.diffusivity.is_none().then(|| {
            format!(
                "permeation of {} through {}: no diffusivity known, so the steady flow is taken \
                 from installation on (an upper bound: the build-up over the time lag is left \
                 out) [docs/model.md §13.7]",
                data.gas, data.family
            )
        });
        Ok((
            SealPermeation {
                path,
                data,
                p_high,
                p_low,
            },
            note,
        ))
    }
    /// Molar flow \[mol/s\] at `time` \[s\] after installation (the pressure applied to a
    /// gas-free ring then) at the temperature `temperature` \[K\]:
    /// [`PermeationPath::molar_flow_at`] with Π(T) and D(T). Under a varying temperature this
    /// is quasi-steady: the build-up uses the current D as if it had held since installation.
    pub fn molar_flow(&self, time: f64, temperature: f64) -> f64 {
        let flow = self.path.molar_flow_at(
            self.data.permeability_at(temperature),
            self.data.diffusivity_at(temperature),
            self.p_high,
            self.p_low,
            time,
        );
        if flow.is_finite() { flow.max(0.0) } else { 0.0 }
    }

    /// [`SealPermeation::throughput`] with the inlet pressure `p_high` \[Pa\] instead of the
    /// service's: a pressure history (docs/model.md §8.4, §13.7), quasi-steady like a varying
    /// temperature — the steady flow is linear in P_a − P_b, the build-up since installation is
    /// kept.
    pub fn throughput_at(&self, time: f64, temperature: f64, p_high: f64) -> f64 {
        let flow = self.path.molar_flow_at(
            self.data.permeability_at(temperature),
            self.data.diffusivity_at(temperature),
            p_high.max(self.p_low),
            self.p_low,
            time,
        );
        let flow = if flow.is_finite() { flow.max(0.0) } else { 0.0 };
        pv_throughput(flow, temperature)
    }

    /// Throughput \[Pa·m³/s\] at `time` \[s\] and `temperature` \[K\]: [`pv_throughput`] of
    /// [`SealPermeation::molar_flow`] at the same temperature.
    pub fn throughput(&self, time: f64, temperature: f64) -> f64 {
        pv_throughput(self.molar_flow(time, temperature), temperature)
    }

    /// Time lag w²/(6D(T)) \[s\] at `temperature` \[K\], when D is known.
    pub fn time_lag(&self, temperature: f64) -> Option<f64> {
        self.data
            .diffusivity_at(temperature)
            .map(|d| self.path.time_lag(d))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seal_permeation_covers_o_rings_and_gaskets_and_refuses_what_it_lacks() {
        use crate::seal::SealGeometry;
        let ring = SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze: 0.2,
        };
        let flat = SealGeometry::Flat {
            nominal_pressure: 1e6,
            width: 1e-3,
            length: 0.1,
            compression: 0.25,
            thickness: None,
        };
        let of = |family: &str, gas: &str| figure(Some(family), &[], gas).unwrap();
        // helium in NBR: D (a bound) known, no note; 0 at installation
        let (he, note) =
            SealPermeation::for_seal(of("nbr", "helium"), &ring, None, 2e5, 1e5).unwrap();
        assert!(note.is_none());
        assert_eq!(he.molar_flow(0.0, 296.15), 0.0);
        assert!(he.time_lag(296.15).is_some() && he.data.diffusivity_is_bound);
        // nitrogen: no D, so the steady flow from t = 0 (the upper bound) and a note
        let (n2, note) =
            SealPermeation::for_seal(of("nbr", "nitrogen"), &ring, None, 2e5, 1e5).unwrap();
        assert!(note.unwrap().contains("upper bound"));
        let steady = n2
            .path
            .steady_molar_flow(n2.data.permeability_at(296.15), 2e5, 1e5);
        assert_eq!(n2.molar_flow(0.0, 296.15), steady);
        // the gas library's "carbon-dioxide" finds the table's "carbon dioxide"
        assert_eq!(of("fkm", "carbon-dioxide").gas, "carbon dioxide");
        // a flat gasket with its compressed thickness: its edge, Π t L Δp/w (1 mm land,
        // 0.1 m around, 2 mm thick)
        let (gasket, _) =
            SealPermeation::for_seal(of("nbr", "nitrogen"), &flat, Some(2e-3), 2e5, 1e5).unwrap();
        let pi = gasket.data.permeability_at(296.15);
        let hand = pi * 2e-3 * 0.1 * 1e5 / 1e-3;
        assert!((gasket.molar_flow(1.0, 296.15) / hand - 1.0).abs() < 1e-12);
        // what is missing is said, never read as zero
        assert_eq!(
            SealPermeation::for_seal(of("nbr", "helium"), &flat, None, 2e5, 1e5).unwrap_err(),
            Missing::NoThickness
        );
        assert_eq!(figure(None, &[], "helium").unwrap_err(), Missing::NoClass);
        assert_eq!(
            figure(Some("nbr"), &[], "argon").unwrap_err(),
            Missing::NoRow { family: "nbr" }
        );
        // the user's figure wins over the class's, and covers a gas the table lacks
        let own = UserPermeation {
            gas: "argon".into(),
            permeability: barrer_to_si(3.0),
            diffusivity: None,
            source: Some("supplier sheet".into()),
        };
        let argon = figure(Some("nbr"), std::slice::from_ref(&own), "argon").unwrap();
        assert_eq!(argon.status, DataStatus::User);
        assert!((si_to_barrer(argon.permeability) - 3.0).abs() < 1e-12);
        assert!(argon.basis().contains("supplier sheet"));
        let helium = UserPermeation {
            gas: "helium".into(),
            ..own
        };
        assert_eq!(
            figure(None, &[helium], "helium").unwrap().status,
            DataStatus::User
        );
    }

    /// Issue 40.4: each class's He/N2 selectivity is its own source's. VMQ: PDMS of the npj
    /// 2024 compilation, 339/277 = 1.22 (Yasuda & Rosengren 1970: 255/233 = 1.09; the Silex
    /// ratio 1.42 used before is outside 1.1–1.3); FKM: D·S of He and N2 in Viton,
    /// (436e-8 · 0.093)/(2.2e-8 · 0.51) = 36.1; IIR: Ito 1961, 8.11/0.3 = 27.0 (the sheet's
    /// 27.0); ACM's proxy: Mogri & Paul 2001, 44.0/6.46 = 6.81.
    #[test]
    fn helium_nitrogen_selectivity_follows_each_source() {
        let ratio = |f| helium_nitrogen_ratio(f).unwrap().0;
        let vmq = ratio("vmq");
        assert!((1.1..=1.3).contains(&vmq), "{vmq}");
        assert!((vmq - 339.0 / 277.0).abs() < 1e-12);
        let fkm = ratio("fkm");
        assert!((fkm - 436.0 * 0.093 / (2.2 * 0.51)).abs() < 1e-9, "{fkm}");
        assert!((ratio("iir") - 8.11 / 0.3).abs() < 1e-9);
        assert!((ratio("acm") - 44.0 / 6.46).abs() < 1e-9);
        assert!((ratio("fvmq") - 247.0 / 88.3).abs() < 1e-9);
        // the classes without figures say so
        for family in ["nbr", "hnbr", "epdm", "ffkm"] {
            let (_, basis) = helium_nitrogen_ratio(family).unwrap();
            assert!(basis.starts_with("NOT SOURCED bound"), "{family}: {basis}");
        }
        // FKM's absolute He: 436e-8 cm²/s · 0.093 / 76 cmHg = 5.335e-9 → 53.4 barrer
        let he = si_to_barrer(data("fkm", "helium").unwrap().permeability);
        assert!((he - 53.352_631_578_947_37).abs() < 1e-9, "{he}");
        // air is the partial-pressure mean of N2 and O2
        for family in FAMILIES {
            let n2 = data(family, "nitrogen").unwrap().permeability;
            let o2 = data(family, "oxygen").unwrap().permeability;
            let air = data(family, "air").unwrap().permeability;
            assert!(
                (air - (0.79 * n2 + 0.21 * o2)).abs() < 1e-12 * air,
                "{family}"
            );
        }
    }

    #[test]
    fn barrer_arithmetic() {
        // 1e-10 cm³·cm/(cm²·s·cmHg): 1e-16 m³ · 1e-2 m / (1e-4 m² · 1333.224 Pa) = 7.5006e-18
        assert!((BARRER_STP_VOLUME - 7.5006e-18).abs() < 1e-21);
        // molar volume at STP 22.414 L/mol → 3.3464e-16 mol·m/(m²·s·Pa)
        assert!((BARRER - 3.3464e-16).abs() < 1e-19);
        assert!((si_to_barrer(barrer_to_si(42.0)) - 42.0).abs() < 1e-12);
    }

    #[test]
    fn every_pair_has_finite_positive_data_and_says_what_it_is() {
        for family in FAMILIES {
            for gas in GASES {
                let row = data(family, gas).expect("a row for every pair");
                assert!(row.permeability.is_finite() && row.permeability > 0.0);
                assert!(row.permeability_at(373.15) >= row.permeability_at(250.0));
                if let Some(s) = row.solubility_at(296.15) {
                    assert!(s.is_finite() && s > 0.0);
                }
                // a bound is never presented as a figure
                let bound = matches!(family, "nbr" | "hnbr" | "epdm" | "ffkm")
                    || (family == "fkm"
                        && matches!(gas, "hydrogen" | "carbon dioxide" | "methane"))
                    || (family == "fvmq" && gas == "hydrogen");
                assert_eq!(row.status == DataStatus::Bound, bound, "{family} {gas}");
                assert!(row.basis().starts_with(row.status.words()));
                assert!(!bound || row.basis().starts_with("NOT SOURCED bound"));
            }
        }
        assert!(data("nbr", "argon").is_none());
        assert!(data("sbr", "helium").is_none());
        assert_eq!(family_of("nbr-70"), Some("nbr"));
        assert_eq!(family_of("HNBR-75"), Some("hnbr"));
        assert_eq!(family_of("cr-70"), Some("cr"));
        assert_eq!(family_of("sbr-70"), None);
    }

    /// D ≤ Π/S_min is an upper bound where a measured D exists to test it against: cis-
    /// polybutadiene (D 1.92e-5 cm²/s, S 2.234e-4, Π 42.9 barrer), Viton (436e-8, 0.093/76,
    /// 53.4) and poly(methyl acrylate), whose S is the floor (equality: D 7.88e-6, Π 12.4 →
    /// 12.4e-10/1.459e-4 = 8.5e-6 cm²/s, the floor's product with its own D·S rounding).
    #[test]
    fn the_helium_diffusivity_bound_is_above_every_measured_value() {
        let cm2 = 1e-4;
        let bound = |barrer: f64| barrer_to_si(barrer) / HELIUM_SOLUBILITY_FLOOR;
        for (name, d, barrer) in [
            ("cis-PB", 1.92e-5 * cm2, 42.9),
            ("Viton", 436e-8 * cm2, 53.35),
            ("PMA", 7.88e-6 * cm2, 12.4),
        ] {
            assert!(bound(barrer) >= d * 0.99, "{name}: {} < {d}", bound(barrer));
        }
        // the floor in SI: 1.459e-4 cm³(STP)/(cm³ cmHg) = 1.459e-4/(0.022414 · 1333.224)
        assert!((HELIUM_SOLUBILITY_FLOOR / (1.459e-4 / (0.022414 * 1333.224)) - 1.0).abs() < 1e-4);
        // VMQ's helium lag through the shipped flange ring is now finite, and short
        let vmq = data("vmq", "helium").unwrap();
        let d = vmq.diffusivity.unwrap();
        assert!(vmq.diffusivity_is_bound && d > 1e-8 && d < 1e-7, "{d}");
    }

    /// The ranking sources the table cites: Hennig Gasket for helium ("nitrile … lowest. EPDM
    /// has only slightly higher permeation, closely followed by FKM"): NBR ≤ EPDM ≤ FKM and
    /// close (the old table put FKM 19.8× above NBR); the silicones far above every other
    /// class; butyl the least permeable to N2, O2 and air (Molded Dimensions "E"), silicone
    /// ≈ 400× butyl (Silex; air here 900×).
    #[test]
    fn data_follow_their_sources_rankings() {
        let at = |f: &str, g: &str| data(f, g).unwrap().permeability;
        let he = |f: &str| at(f, "helium");
        assert!(he("nbr") <= he("epdm") && he("epdm") <= he("fkm"));
        assert!(he("fkm") / he("nbr") <= 2.0, "closely followed");
        for f in FAMILIES.iter().filter(|f| !matches!(**f, "vmq" | "fvmq")) {
            assert!(he(f) * 4.0 < he("fvmq") && he("fvmq") < he("vmq"), "{f}");
        }
        for gas in ["nitrogen", "oxygen", "air"] {
            for f in FAMILIES.iter().filter(|f| **f != "iir") {
                assert!(at("iir", gas) < at(f, gas), "{gas}: iir vs {f}");
            }
        }
        let silicone_over_butyl = at("vmq", "air") / at("iir", "air");
        assert!(
            (200.0..=2000.0).contains(&silicone_over_butyl),
            "{silicone_over_butyl}"
        );
    }

    #[test]
    fn path_errors() {
        assert!(PermeationPath::o_ring(3.53e-3, 50e-3, 1.0).is_err());
        assert!(PermeationPath::o_ring(3.53e-3, 50e-3, -0.1).is_err());
        assert!(PermeationPath::o_ring(f64::NAN, 50e-3, 0.2).is_err());
        assert!(PermeationPath::gasket(1e-3, 0.0, 0.1).is_err());
        assert!(PermeationPath::slab(-1.0, 1e-3).is_err());
        let e = PermeationPath::o_ring(3.53e-3, 50e-3, 1.2).expect_err("bad squeeze");
        assert!(e.to_string().contains("squeeze"));
    }

    #[test]
    fn transient_forms_agree_at_the_switch() {
        // the image and Fourier forms are the same function: evaluate both around τ = 0.1
        for &tau in &[0.05, 0.08, 0.1, 0.15, 0.3] {
            let mut fourier_flux = 1.0;
            let mut fourier_amount = tau - 1.0 / 6.0;
            let mut image_flux = 0.0;
            let mut image_amount = 0.0;
            for n in 1..2000 {
                let nf = n as f64;
                let sign = if n % 2 == 1 { -1.0 } else { 1.0 };
                fourier_flux += 2.0 * sign * (-nf * nf * PI * PI * tau).exp();
                fourier_amount -=
                    2.0 / (PI * PI) * sign / (nf * nf) * (-nf * nf * PI * PI * tau).exp();
            }
            for m in 0..50 {
                let k = (2 * m + 1) as f64;
                image_flux += 2.0 / (PI * tau).sqrt() * (-k * k / (4.0 * tau)).exp();
                image_amount += 4.0 * tau.sqrt() * ierfc(k / (2.0 * tau.sqrt()));
            }
            assert!((fourier_flux - image_flux).abs() < 1e-12, "flux at {tau}");
            assert!(
                (fourier_amount - image_amount).abs() < 1e-12,
                "amount at {tau}"
            );
            assert!((transient_flux_ratio(tau) - image_flux).abs() < 1e-12);
            assert!((transient_amount(tau) - image_amount).abs() < 1e-12);
        }
        assert_eq!(transient_amount(0.0), 0.0);
        assert_eq!(transient_flux_ratio(-1.0), 0.0);
        assert_eq!(transient_amount(f64::NAN), 0.0);
    }
}
