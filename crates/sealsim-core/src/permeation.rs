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
    /// Every number read in a cited source, with its units and temperature.
    Published,
    /// At least one number estimated (the provenance says how); not for design decisions.
    Illustrative,
}

/// Permeation data of one gas in one compound class at `reference_temperature`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PermeationData {
    /// Compound class: "nbr", "hnbr", "fkm", "epdm", "vmq".
    pub family: &'static str,
    /// Gas: "helium", "hydrogen", "nitrogen", "oxygen", "air", "carbon dioxide", "methane".
    pub gas: &'static str,
    /// Π at the reference temperature \[mol/(m·s·Pa)\].
    pub permeability: f64,
    /// E_P \[J/mol\].
    pub permeability_activation: f64,
    /// D at the reference temperature \[m²/s\], when any basis was found.
    pub diffusivity: Option<f64>,
    /// E_D \[J/mol\] (taken equal to E_P: temperature-independent solubility).
    pub diffusivity_activation: f64,
    /// T_ref \[K\].
    pub reference_temperature: f64,
    pub status: DataStatus,
    /// Where the numbers came from (docs/model.md §13.4 has the chain in full).
    pub provenance: &'static str,
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
}

/// Compound classes with data.
pub const FAMILIES: [&str; 5] = ["nbr", "hnbr", "fkm", "epdm", "vmq"];

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

/// Reference temperature of the table \[K\] (23 °C; the sources' "room temperature" and 25 °C
/// values are used as they are: a 2 K difference is ≈ 10 % at 40 kJ/mol, far inside the spread).
pub const TABLE_REFERENCE_TEMPERATURE: f64 = 296.15;

/// Silex "(6.1) Gas Permeability" table for VMQ, relative values (its units and temperature were
/// not in the text read; only the ratios between gases are used): air 0.382, N2 0.307,
/// O2 0.660, H2 0.729, CO2 3.87, He 0.436. Methane is not in it: CH4/N2 = 3 is an
/// ILLUSTRATIVE ratio \[recalled for silicone, not verified\].
fn silicone_relative(gas: &str) -> Option<f64> {
    Some(match gas {
        "air" => 0.382,
        "nitrogen" => 0.307,
        "oxygen" => 0.660,
        "hydrogen" => 0.729,
        "carbon dioxide" => 3.87,
        "helium" => 0.436,
        "methane" => 3.0 * 0.307,
        _ => return None,
    })
}

/// VMQ O2 anchor \[barrer\]: Versaperm's dimethylsilicone row "60.0" in cm³·cm/(s·cm²·cmHg)
/// with the power of ten missing from the text read, taken as ×1e-9 (ASSUMED) = 600 barrer.
const VMQ_OXYGEN_BARRER: f64 = 600.0;

/// Silicone ≈ 30 × natural rubber (Silex, "30 times that of natural rubber").
const SILICONE_OVER_NR: f64 = 30.0;

/// Perbunan (NBR) H2 permeability is "one-third to one-eighth" of natural rubber's ("The
/// Permeability of Rubberlike Substances to Gases", abstract read on scilit.net); the geometric
/// middle √(3·8) is used.
const NR_OVER_NBR: f64 = 4.898_979_485_566_356; // √24

/// Helium ranking (Hennig Gasket, "Sealing Helium"): NBR lowest, "EPDM has only slightly higher
/// permeation, closely followed by FKM". ILLUSTRATIVE factors on NBR, applied to every gas.
fn family_factor(family: &str) -> Option<f64> {
    Some(match family {
        "nbr" => 1.0,
        "hnbr" => 1.0, // ASSUMED like NBR: no source found
        "epdm" => 1.5,
        "fkm" => 2.0,
        _ => return None,
    })
}

/// E_P \[J/mol\]. H2 in NBR: 36 kJ/mol, the middle of the 33–39 kJ/mol of Gim et al., Polymers
/// 16 (2024) 280 (abstract). Every other value ILLUSTRATIVE: inside the 18–51 kJ/mol range
/// reported for O2 and H2O through polymer O-rings — Kalrez, Viton, … — (J. IEST 38(2) 43,
/// abstract), larger for larger molecules; silicone's small values \[recalled: its permeability depends weakly on
/// temperature\].
fn activation_energy(family: &str, gas: &str) -> f64 {
    let kj = if family == "vmq" {
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

/// FKM's Π \[barrer\] for the gases its source gives (He, N2, O2, and air from N2 and O2).
fn fkm_barrer(gas: &str) -> Option<f64> {
    let of = |g| fkm_diffusivity_solubility(g).map(|(d, s)| barrer_of_ds(d, s));
    match gas {
        "air" => Some(air_of(of("nitrogen")?, of("oxygen")?)),
        _ => of(gas),
    }
}

/// The helium/nitrogen permeability ratio of a compound class at 23 °C and what it rests on:
/// measured D·S for FKM and silicone's own table for VMQ; for NBR, HNBR and EPDM the silicone
/// ratio stands in for want of a readable source (docs/model.md §13.4).
pub fn helium_nitrogen_ratio(family: &str) -> Option<(f64, &'static str)> {
    let he = data(family, "helium")?.permeability;
    let n2 = data(family, "nitrogen")?.permeability;
    let basis = match family {
        "fkm" => {
            "D·S of He and N2 in Viton (EXO/nEXO model file citing arXiv:1703.09144; secondary)"
        }
        "vmq" => "Silex's silicone table (He 0.436, N2 0.307)",
        _ => {
            "NOT SOURCED: silicone's ratio stands in (no readable He and N2 values for this class; \
             published rubbers are more selective, so helium is likely underestimated against air)"
        }
    };
    Some((he / n2, basis))
}

/// D at 23 °C \[m²/s\] where some basis exists (ILLUSTRATIVE): He 3e-10, the geometric middle of
/// the 1e-10 … 1e-9 m²/s given for helium in O-rings at 25 °C (Composite Analytica forum reply,
/// low authority); H2 1e-10, inside the 0.1e-6 … 4.1e-6 cm²/s (1e-11 … 4.1e-10 m²/s) of an
/// abstract on H2 in carbon-black-filled NBR (discovery.researcher.life; authors not shown).
/// Silicone and the other gases: none found.
fn diffusivity(family: &str, gas: &str) -> Option<f64> {
    if family == "vmq" {
        return None;
    }
    if family == "fkm" && gas != "air" {
        // the same source's D, cm²/s → m²/s; for H2, CO2, CH4 the shared estimates below
        if let Some((d, _)) = fkm_diffusivity_solubility(gas) {
            return Some(d * 1e-4);
        }
    }
    match gas {
        "helium" => Some(3e-10),
        "hydrogen" => Some(1e-10),
        _ => None,
    }
}

/// The permeability of `gas` in `family` at 23 °C \[barrer\] (docs/model.md §13.4; every value
/// ILLUSTRATIVE): VMQ = 600 barrer O2 × the Silex ratio of the gas to O2; NBR H2 = VMQ H2/30/√24
/// (silicone ≈ 30 × NR, NBR ≈ NR/3 … NR/8), other gases in NBR by the silicone ratios to H2;
/// HNBR, EPDM, FKM = NBR × the helium ranking factor; FKM's He, N2, O2 and air from its own
/// D·S ([`fkm_barrer`]).
fn permeability_barrer(family: &str, gas: &str) -> Option<f64> {
    let rel = silicone_relative(gas)?;
    if let Some(measured) = fkm_barrer(gas).filter(|_| family == "fkm") {
        return Some(measured);
    }
    let vmq = VMQ_OXYGEN_BARRER * rel / 0.660;
    if family == "vmq" {
        return Some(vmq);
    }
    let nbr_h2 = VMQ_OXYGEN_BARRER * 0.729 / 0.660 / SILICONE_OVER_NR / NR_OVER_NBR;
    Some(nbr_h2 * rel / 0.729 * family_factor(family)?)
}

/// The compound class of a material-library id ("nbr-70" → "nbr"), if it has data.
pub fn family_of(library_id: &str) -> Option<&'static str> {
    let stem = library_id.split('-').next()?.to_ascii_lowercase();
    FAMILIES.iter().copied().find(|f| *f == stem)
}

/// Permeation data of `gas` (see [`GASES`]) in a compound `family` (see [`FAMILIES`]), or `None`.
/// Every row is [`DataStatus::Illustrative`]: no multi-gas, multi-compound table with units and
/// temperature was found (docs/model.md §13.4).
pub fn data(family: &str, gas: &str) -> Option<PermeationData> {
    let family = FAMILIES.iter().copied().find(|f| *f == family)?;
    let gas = GASES.iter().copied().find(|g| *g == gas)?;
    let barrer = permeability_barrer(family, gas)?;
    let energy = activation_energy(family, gas);
    let provenance = if family == "vmq" {
        "ILLUSTRATIVE: O2 600 barrer (Versaperm row, multiplier assumed) × Silex gas ratio; \
         E_P illustrative"
    } else if family == "fkm" && fkm_barrer(gas).is_some() {
        "D and S of Viton from the EXO/nEXO model file citing arXiv:1703.09144 (secondary; S taken \
         per atm), Π = D·S; air = 0.79 N2 + 0.21 O2; E_P illustrative"
    } else if family == "nbr" && gas == "hydrogen" {
        "ILLUSTRATIVE Π: silicone/30 (Silex) /√24 (NBR = NR/3…NR/8, scilit abstract); \
         E_P 36 kJ/mol from Gim et al. 2024 (33–39); D inside the range of an NBR/H2 abstract"
    } else {
        "ILLUSTRATIVE: NBR H2 estimate × Silex gas ratio × Hennig helium ranking; E_P, D illustrative"
    };
    Some(PermeationData {
        family,
        gas,
        permeability: barrer_to_si(barrer),
        permeability_activation: energy,
        diffusivity: diffusivity(family, gas),
        diffusivity_activation: energy,
        reference_temperature: TABLE_REFERENCE_TEMPERATURE,
        status: DataStatus::Illustrative,
        provenance,
    })
}

/// Permeation through a seal in a life run (docs/model.md §13.7): the path through the ring or
/// gasket at its installation squeeze, the gas's data in the compound, and the absolute
/// pressures of the gas service (P_a on the pressurised side, P_b on the other; the gas is
/// taken as pure, so its partial pressures are the absolute ones).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SealPermeation {
    pub path: PermeationPath,
    pub data: PermeationData,
    /// P_a, absolute \[Pa\].
    pub p_high: f64,
    /// P_b, absolute \[Pa\].
    pub p_low: f64,
}

/// Why a life run carries no permeation, or with which simplification (a note, not an error).
pub type PermeationNote = String;

impl SealPermeation {
    /// The permeation of gas `gas` (a [`GASES`] id) through a seal of material-library id
    /// `library_id` and geometry `geometry`, with P_a = `p_high`, P_b = `p_low` \[Pa\].
    /// An O-ring uses [`PermeationPath::o_ring`] at its installation squeeze ε0; a flat
    /// gasket its edge ([`PermeationPath::gasket`]) when its compressed `thickness` \[m\] is
    /// given, none without it (the exposed edge is unknown).
    /// Returns the permeation (if any) and a note saying what was left out or bounded.
    pub fn for_seal(
        library_id: Option<&str>,
        gas: &str,
        geometry: &crate::seal::SealGeometry,
        thickness: Option<f64>,
        p_high: f64,
        p_low: f64,
    ) -> (Option<SealPermeation>, Option<PermeationNote>) {
        let Some(family) = library_id.and_then(family_of) else {
            return (
                None,
                Some(format!(
                    "no permeation through the rubber in this run: the material is not the \
                     scenario's `[material] library` compound of a class with permeation data \
                     ({}; an inline, file or `compare` material has none) [docs/model.md §13.7]",
                    FAMILIES.join(", ")
                )),
            );
        };
        // the gas library spells "carbon-dioxide", the permeation table "carbon dioxide"
        let Some(data) = data(family, &gas.replace('-', " ")) else {
            return (
                None,
                Some(format!(
                    "no permeation through the rubber in this run: no permeation data for \
                     {gas} in {family} [docs/model.md §13.4]"
                )),
            );
        };
        let path = match (*geometry, thickness) {
            (
                crate::seal::SealGeometry::ORing {
                    cross_section,
                    mean_diameter,
                    squeeze,
                },
                _,
            ) => PermeationPath::o_ring(cross_section, mean_diameter, squeeze),
            (crate::seal::SealGeometry::Flat { width, length, .. }, Some(t)) => {
                PermeationPath::gasket(t, width, length)
            }
            (crate::seal::SealGeometry::Flat { .. }, None) => {
                return (
                    None,
                    Some(
                        "no permeation through the rubber in this run: a flat seal needs its \
                         compressed `thickness` in [seal] for the edge the gas permeates \
                         through [docs/model.md §13.7]"
                            .to_owned(),
                    ),
                );
            }
        };
        let path = match path {
            Ok(path) => path,
            Err(e) => {
                return (
                    None,
                    Some(format!(
                        "no permeation through the rubber in this run: {e} [docs/model.md §13.3]"
                    )),
                );
            }
        };
        let note = data.diffusivity.is_none().then(|| {
            format!(
                "permeation of {gas} through {family}: no diffusivity known, so the steady \
                 flow is taken from installation on (an upper bound: the build-up over the \
                 time lag is left out) [docs/model.md §13.7]"
            )
        });
        (
            Some(SealPermeation {
                path,
                data,
                p_high,
                p_low,
            }),
            note,
        )
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
    fn seal_permeation_covers_o_rings_with_data_and_notes_the_rest() {
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
        };
        // helium in NBR: D known, no note; 0 at installation
        let (he, note) = SealPermeation::for_seal(Some("nbr-70"), "helium", &ring, None, 2e5, 1e5);
        let he = he.unwrap();
        assert!(note.is_none());
        assert_eq!(he.molar_flow(0.0, 296.15), 0.0);
        assert!(he.time_lag(296.15).is_some());
        // nitrogen: no D, so the steady flow from t = 0 (the upper bound) and a note
        let (n2, note) =
            SealPermeation::for_seal(Some("nbr-70"), "nitrogen", &ring, None, 2e5, 1e5);
        let n2 = n2.unwrap();
        assert!(note.unwrap().contains("upper bound"));
        let steady = n2
            .path
            .steady_molar_flow(n2.data.permeability_at(296.15), 2e5, 1e5);
        assert_eq!(n2.molar_flow(0.0, 296.15), steady);
        // the gas library's "carbon-dioxide" finds the table's "carbon dioxide"
        let (co2, _) =
            SealPermeation::for_seal(Some("fkm-75"), "carbon-dioxide", &ring, None, 2e5, 1e5);
        assert!(co2.is_some());
        // a flat gasket with its compressed thickness: its edge, Π t L Δp/w (1 mm land,
        // 0.1 m around, 2 mm thick)
        let (gasket, note) =
            SealPermeation::for_seal(Some("nbr-70"), "nitrogen", &flat, Some(2e-3), 2e5, 1e5);
        let gasket = gasket.unwrap();
        assert!(note.unwrap().contains("upper bound"));
        let pi = gasket.data.permeability_at(296.15);
        let hand = pi * 2e-3 * 0.1 * 1e5 / 1e-3;
        assert!((gasket.molar_flow(1.0, 296.15) / hand - 1.0).abs() < 1e-12);
        // a flat seal without thickness, an inline material, a gas without data: none, with a
        // note
        for (id, gas, geometry) in [
            (Some("nbr-70"), "helium", &flat),
            (None, "helium", &ring),
            (Some("nbr-70"), "argon", &ring),
        ] {
            let (none, note) = SealPermeation::for_seal(id, gas, geometry, None, 2e5, 1e5);
            assert!(none.is_none());
            assert!(note.unwrap().contains("no permeation"));
        }
    }

    /// Issue 31: each class's He/N2 selectivity is its own source's. FKM: D·S of He and N2 in
    /// Viton, (436e-8 · 0.093)/(2.2e-8 · 0.51) = 36.1 (the published range for fluoroelastomers
    /// the issue quotes is ≈ 10–40); VMQ: Silex's 0.436/0.307 = 1.42 (PDMS ≈ 1–2).
    #[test]
    fn helium_nitrogen_selectivity_follows_each_source() {
        let (fkm, basis) = helium_nitrogen_ratio("fkm").unwrap();
        assert!((fkm - 436.0 * 0.093 / (2.2 * 0.51)).abs() < 1e-9, "{fkm}");
        assert!((10.0..=40.0).contains(&fkm) && basis.contains("Viton"));
        let (vmq, basis) = helium_nitrogen_ratio("vmq").unwrap();
        assert!((vmq - 0.436 / 0.307).abs() < 1e-9 && basis.contains("Silex"));
        for family in ["nbr", "hnbr", "epdm"] {
            let (ratio, basis) = helium_nitrogen_ratio(family).unwrap();
            assert!((ratio - vmq).abs() < 1e-9 && basis.starts_with("NOT SOURCED"));
        }
        // FKM's absolute He: 436e-8 cm²/s · 0.093 / 76 cmHg = 5.335e-9 → 53.4 barrer
        let he = si_to_barrer(data("fkm", "helium").unwrap().permeability);
        assert!((he - 53.352_631_578_947_37).abs() < 1e-9, "{he}");
        // air is the partial-pressure mean of N2 and O2
        let n2 = data("fkm", "nitrogen").unwrap().permeability;
        let o2 = data("fkm", "oxygen").unwrap().permeability;
        let air = data("fkm", "air").unwrap().permeability;
        assert!((air - (0.79 * n2 + 0.21 * o2)).abs() < 1e-12 * air);
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
    fn every_pair_has_finite_positive_data() {
        for family in FAMILIES {
            for gas in GASES {
                let row = data(family, gas).expect("a row for every pair");
                assert!(row.permeability.is_finite() && row.permeability > 0.0);
                assert!(row.permeability_at(373.15) >= row.permeability_at(250.0));
                assert_eq!(row.status, DataStatus::Illustrative);
                if let Some(s) = row.solubility_at(296.15) {
                    assert!(s.is_finite() && s > 0.0);
                }
            }
        }
        assert!(data("cr", "helium").is_none());
        assert!(data("nbr", "argon").is_none());
        assert_eq!(family_of("nbr-70"), Some("nbr"));
        assert_eq!(family_of("HNBR-75"), Some("hnbr"));
        assert_eq!(family_of("cr-70"), None);
    }

    #[test]
    fn data_follow_their_sources_rankings() {
        let he = |f| {
            data(f, "helium")
                .map(|r| r.permeability)
                .unwrap_or(f64::NAN)
        };
        // Hennig: NBR < EPDM < FKM for helium; silicone far above (FKM's He is its own D·S,
        // 53 barrer, 7.4× below silicone's 396)
        assert!(he("nbr") < he("epdm") && he("epdm") < he("fkm") && he("fkm") * 5.0 < he("vmq"));
        // silicone ≈ 30× NR, NBR = NR/3 … NR/8 → VMQ/NBR in [90, 240] for H2
        let h2 = |f| {
            data(f, "hydrogen")
                .map(|r| r.permeability)
                .unwrap_or(f64::NAN)
        };
        let ratio = h2("vmq") / h2("nbr");
        assert!((90.0..=240.0).contains(&ratio), "{ratio}");
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
