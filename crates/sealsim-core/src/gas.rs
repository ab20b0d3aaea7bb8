//! Gases: molar mass, viscosity against temperature, molecular diameter and mean free path
//! (docs/model.md §3.9).
//!
//! A gas is a compressible fluid: sealsim treats it as an isothermal ideal gas whose mass flux
//! is conserved along the interface (`Fluid::throughput` in the `fluid` module). Its viscosity follows
//! Sutherland's law `μ(T) = μ0 (T/T0)^{3/2} (T0 + S)/(T + S)` (or a constant for a custom gas);
//! its hard-sphere diameter d gives the mean free path `λ = k_B T/(√2 π d² p)` and, at a
//! constriction of height u, the Knudsen number `Kn = λ/u`. Through a constriction the gas
//! flows rarefied: slip, transition or free molecular by Kn ([`slit_rarefaction`],
//! docs/model.md §3.10), or by the continuum law on request ([`FlowLaw::Continuum`]).
//!
//! Sources (research notes; SECONDARY means the values were read where a source is quoted,
//! not in the source itself):
//! * Sutherland constants of air, N₂, O₂, H₂, CO₂, Ar: F. M. White, *Viscous Fluid Flow*, 3rd
//!   ed., McGraw-Hill 2006, Table 1-2, p. 28 — SECONDARY (the same numbers in several public
//!   codes that cite it; the book itself was not read).
//! * Helium and methane are not in that table as quoted: their constants are illustrative
//!   (see [`HELIUM`], [`METHANE`]).
//! * Molar masses and hard-sphere diameters: the CRC Handbook of Chemistry and Physics (100th
//!   ed.) table as quoted by Engineers Edge ("Mean Free Path of Gases Formulae and Calculator")
//!   and launchloop.com "MeanFreePath" — SECONDARY. The diameters are viscosity-derived
//!   (kinetic theory), the ones "typically utilized to calculate the mean free path" (Kunze et
//!   al., Sci. Rep. 12, 2057 (2022), whose Eq. (1) is the λ above).

/// Boltzmann constant k_B \[J/K\] (exact, SI 2019).
pub const BOLTZMANN: f64 = 1.380_649e-23;
/// Molar gas constant R = N_A k_B \[J/(mol·K)\] (exact, SI 2019); defined in `units` with the
/// gas-flow units that need it.
pub use crate::units::GAS_CONSTANT;

/// Sutherland's law for a gas's dynamic viscosity: `μ(T) = μ0 (T/T0)^{3/2} (T0 + S)/(T + S)`
/// \[Pa·s\] (T in K). μ0, T0 and S belong together: a constant from one published set is only
/// valid with that set's T0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sutherland {
    /// μ0, the viscosity at T0 \[Pa·s\].
    pub mu0: f64,
    /// T0, the reference temperature \[K\].
    pub t0: f64,
    /// S, Sutherland's constant \[K\].
    pub s: f64,
}

impl Sutherland {
    /// μ(T) \[Pa·s\] at `temperature` \[K\] (> 0).
    pub fn viscosity(&self, temperature: f64) -> f64 {
        self.mu0 * (temperature / self.t0).powf(1.5) * (self.t0 + self.s) / (temperature + self.s)
    }
}

/// How a gas's viscosity follows the temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GasViscosity {
    /// A constant \[Pa·s\] (a custom gas given one value).
    Constant(f64),
    /// Sutherland's law.
    Sutherland(Sutherland),
}

impl GasViscosity {
    /// μ at `temperature` \[K\] \[Pa·s\].
    pub fn at(&self, temperature: f64) -> f64 {
        match self {
            GasViscosity::Constant(mu) => *mu,
            GasViscosity::Sutherland(s) => s.viscosity(temperature),
        }
    }
}

/// A gas: what the interface flow and the Knudsen number need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gas {
    /// Library id (`"helium"`, …) or `"custom"`.
    pub id: &'static str,
    /// Molar mass M \[kg/mol\].
    pub molar_mass: f64,
    /// μ(T).
    pub viscosity: GasViscosity,
    /// Hard-sphere (viscosity-derived) molecular diameter d \[m\], for the mean free path.
    pub molecular_diameter: f64,
    /// Where the numbers come from, short (the run summary's fluid line).
    pub source: &'static str,
}

impl Gas {
    /// Mean free path of the hard-sphere gas \[m\] at `temperature` \[K\] and absolute
    /// `pressure` \[Pa\] (> 0): `λ = k_B T/(√2 π d² p)` (Kunze et al. 2022, Eq. (1); the CRC
    /// table's definition). ∞ at p = 0.
    pub fn mean_free_path(&self, temperature: f64, pressure: f64) -> f64 {
        BOLTZMANN * temperature
            / (std::f64::consts::SQRT_2
                * std::f64::consts::PI
                * self.molecular_diameter.powi(2)
                * pressure)
    }

    /// The viscosity-based mean free path \[m\] at `temperature` \[K\] and absolute
    /// `pressure` \[Pa\]: `λ_μ = (μ(T)/p) √(π R T/(2 M))` (docs/model.md §3.10), the mean free
    /// path in which the rarefied slit-flow law is written ([`slit_rarefaction`]). Within a few
    /// % of the hard-sphere [`Self::mean_free_path`] for the library gases (a test). ∞ at
    /// p = 0.
    pub fn viscous_mean_free_path(&self, temperature: f64, pressure: f64) -> f64 {
        self.viscosity.at(temperature) / pressure
            * (std::f64::consts::PI * GAS_CONSTANT * temperature / (2.0 * self.molar_mass)).sqrt()
    }

    /// Density of the ideal gas ρ = p M/(R T) \[kg/m³\] at absolute `pressure` \[Pa\] and
    /// `temperature` \[K\].
    pub fn density(&self, pressure: f64, temperature: f64) -> f64 {
        pressure * self.molar_mass / (GAS_CONSTANT * temperature)
    }
}

/// How a gas flows through the interface's constrictions (docs/model.md §3.10).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlowLaw {
    /// The continuum (no-slip Poiseuille) law at every Knudsen number: for comparison.
    Continuum,
    /// Each constriction's conductance times the slit rarefaction factor
    /// [`slit_rarefaction`] at its local Knudsen number (the default).
    Rarefied,
}

/// A gas at one local pressure, as the rarefied conductance of a gap needs it
/// (docs/model.md §3.10).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rarefied {
    /// The viscosity-based mean free path λ_μ \[m\] ([`Gas::viscous_mean_free_path`]).
    pub free_path: f64,
    /// The hard-sphere molecular diameter d \[m\]: a gap no wider passes no molecule.
    pub molecular_diameter: f64,
}

/// Whether a gap of height `gap` \[m\] passes a fluid whose molecule is `molecular_size` \[m\]
/// (`fluid::Fluid::molecular_size`) — only if it is wider (docs/model.md §8.1). The one rule for every
/// gap the model lets a fluid through, liquid or gas: the critical junction of each strip of the
/// interface (§3.6) at every level, each local gap of the effective medium's Bruggeman average
/// (§3.3) and each cell of the numerical level's Reynolds solve (§3.5); a rarefied gas's factor
/// ([`Rarefied::factor`]) applies it too (§3.10).
pub fn passes_molecule(gap: f64, molecular_size: f64) -> bool {
    gap > molecular_size
}

impl Rarefied {
    /// The conductance of a gap of height `u` \[m\] and lateral extent `width` \[m\] over
    /// its continuum value: [`slit_rarefaction`] at Kn = λ_μ/u and aspect width/u, and 0 for a
    /// gap no wider than a molecule.
    pub fn factor(&self, u: f64, width: f64) -> f64 {
        if !passes_molecule(u, self.molecular_diameter) {
            0.0
        } else {
            slit_rarefaction(self.free_path / u, width / u)
        }
    }
}

/// Smoluchowski's shape integral of a long rectangular channel of height `h` and width `w`
/// \[m³\] (docs/model.md §3.10):
/// `A_S = 2[h² w asinh(w/h) + h w² asinh(h/w) − (h² + w²)^{3/2}/3 + (h³ + w³)/3]`, so that the free-molecular throughput conductance of a channel of length L
/// is `C_FM = (v̄/8) A_S/L` ([`free_molecular_conductance`]). For a slit (w ≫ h)
/// `A_S → 2 h² w (ln(2w/h) + ½)`: the conductance per unit width grows like ln(w/h), the
/// logarithm of the plane channel. Source: the formula as implemented in eznuk/sedmodel
/// (`sedmodel.py`, the superposition model of Kunze et al., Sci. Rep. 12, 2057 (2022)) —
/// SECONDARY (code). Its circular case, `A_S = 16πr³/3`, is Knudsen's long tube,
/// `C = (π/12) v̄ d³/L` = 12.1 d³/L L/s for air at 20 °C with d, L in cm (the vacuum rule read
/// at codingace.net "Molecular Flow Conductance Calculator"; a test).
pub fn smoluchowski_shape(h: f64, w: f64) -> f64 {
    let (h, w) = if h <= w { (h, w) } else { (w, h) };
    // (h² + w²)^{3/2} − w³ without cancellation for w ≫ h: w³ expm1(1.5 ln1p(h²/w²))
    let r = h / w;
    let excess = w.powi(3) * (1.5 * (r * r).ln_1p()).exp_m1();
    2.0 * (h * h * w * (w / h).asinh() + h * w * w * r.asinh() - (excess - h.powi(3)) / 3.0)
}

/// The mean thermal speed `v̄ = √(8 R T/(π M))` \[m/s\] of `gas` at `temperature` \[K\].
pub fn mean_speed(gas: &Gas, temperature: f64) -> f64 {
    (8.0 * GAS_CONSTANT * temperature / (std::f64::consts::PI * gas.molar_mass)).sqrt()
}

/// The free-molecular throughput conductance \[m³/s\] (throughput per pressure difference)
/// of a long rectangular channel `h` × `w` of length `length` (all in m), diffuse walls:
/// `C_FM = (v̄/8) A_S/L` ([`smoluchowski_shape`]). Independent of the pressure.
pub fn free_molecular_conductance(gas: &Gas, temperature: f64, h: f64, w: f64, length: f64) -> f64 {
    mean_speed(gas, temperature) / 8.0 * smoluchowski_shape(h, w) / length
}

/// α0 of Beskok & Karniadakis's unified model as its public implementations give it,
/// `64/(3π(1 − 4/b))` with b = −1, i.e. 64/(15π) ≈ 1.358 — derived in their book for the pipe's
/// free-molecular limit and used for channels too (SECONDARY: two codes agree).
pub const BESKOK_ALPHA0: f64 = 64.0 / (15.0 * std::f64::consts::PI);

/// The rarefaction factor of pressure-driven flow through a slit at Knudsen number `kn`
/// (λ_μ over the gap u) whose lateral extent is `aspect` gaps (docs/model.md §3.10): the flow
/// over its continuum (no-slip Poiseuille) value at the same local pressure and pressure
/// gradient,
///
/// `f = (1 + α Kn)(1 + 6 Kn/(1 − b Kn))`, b = −1, `α = α0 (2/π) tan⁻¹(α1 Kn^β)`, α1 = 4,
/// β = 0.4 — the unified model of Beskok & Karniadakis (Microscale Thermophys. Eng. 3 (1999)
/// 43; its structure and b = −1 read in Karniadakis, Beskok & Aluru, *Microflows and
/// Nanoflows* (2005), section 4.2; α1, β as two public implementations give them —
/// SECONDARY).
/// As Kn → 0, `f = 1 + 6 Kn + O(Kn^1.4)`: first-order slip with Maxwell's coefficient for
/// diffuse walls. As Kn → ∞, `f → 7 α0 Kn`, and α0 sets the free-molecular flow.
///
/// α0 [derived here, not a published model]: Beskok & Karniadakis fix α0 by the geometry's
/// free-molecular limit. A plane channel has none — its free-molecular flow grows like
/// ln(Kn) while the channel is longer than λ, like ln(L/h) once it is shorter (Beskok, "Unified
/// Flow Model", read) — so here `α0 = max(α0_BK, 12 X(min(Kn, a))/(7π))` (min and max smoothed),
/// where
/// `X(a) = A_S(1, a)/(2a)` ≈ ln(2a) + ½ is Smoluchowski's slit integral
/// ([`smoluchowski_shape`]) and α0_BK = [`BESKOK_ALPHA0`]: the published coefficient up to
/// Kn ≈ 3.7 (where X = 7π α0_BK/12), growing like ln Kn beyond, and for Kn > a exactly the
/// free-molecular conductance of the slit a gaps wide (a test). 1 at Kn = 0.
pub fn slit_rarefaction(kn: f64, aspect: f64) -> f64 {
    if kn.is_nan() || kn <= 0.0 {
        return 1.0;
    }
    // smooth min and max (C∞, so that the pressure quadratures stay spectrally accurate): the
    // cut-off (Kn⁻⁴ + a⁻⁴)^{−1/4}, and α0 = (α0_BK¹⁶ + y¹⁶)^{1/16}, each within 2⁻¹ᐟ⁴ resp.
    // 2¹ᐟ¹⁶ of the sharp one at the crossing and exact away from it
    let a = aspect.max(f64::MIN_POSITIVE);
    let cutoff = (kn.powi(-4) + a.powi(-4)).powf(-0.25);
    let x = if cutoff > 0.0 && cutoff.is_finite() {
        smoluchowski_shape(1.0, cutoff) / (2.0 * cutoff)
    } else {
        0.0
    };
    let y = 12.0 * x / (7.0 * std::f64::consts::PI) / BESKOK_ALPHA0;
    let alpha0 = BESKOK_ALPHA0 * (1.0 + y.powi(16)).powf(1.0 / 16.0);
    let alpha = alpha0 * std::f64::consts::FRAC_2_PI * (4.0 * kn.powf(0.4)).atan();
    if kn > 1e150 {
        // (1 + α Kn)(1 + 6 Kn/(1 + Kn)) without overflow: 7 α Kn to rounding
        return 7.0 * alpha * kn;
    }
    (1.0 + alpha * kn) * (1.0 + 6.0 * kn / (1.0 + kn))
}

/// White 2006 Table 1-2 (SECONDARY, see the module doc): T0 = 273 K for every row.
const WHITE_T0: f64 = 273.0;
/// Provenance of the White rows.
const WHITE: &str =
    "Sutherland constants White 2006 Table 1-2 (as quoted); M, d from the CRC table (as quoted)";

/// Air: μ0 = 1.716e-5 Pa·s, S = 111 K (White); M = 28.960 g/mol, d = 3.66e-10 m (CRC).
pub const AIR: Gas = white("air", 1.716e-5, 111.0, 28.960e-3, 3.66e-10);
/// Nitrogen: μ0 = 1.663e-5 Pa·s, S = 107 K; M = 28.014 g/mol, d = 3.70e-10 m.
pub const NITROGEN: Gas = white("nitrogen", 1.663e-5, 107.0, 28.014e-3, 3.70e-10);
/// Oxygen: μ0 = 1.919e-5 Pa·s, S = 139 K; M = 31.999 g/mol, d = 3.55e-10 m.
pub const OXYGEN: Gas = white("oxygen", 1.919e-5, 139.0, 31.999e-3, 3.55e-10);
/// Hydrogen: μ0 = 8.411e-6 Pa·s, S = 97 K; M = 2.0159 g/mol, d = 2.71e-10 m.
pub const HYDROGEN: Gas = white("hydrogen", 8.411e-6, 97.0, 2.0159e-3, 2.71e-10);
/// Carbon dioxide: μ0 = 1.370e-5 Pa·s, S = 222 K; M = 44.01 g/mol, d = 4.53e-10 m.
pub const CARBON_DIOXIDE: Gas = white("carbon-dioxide", 1.370e-5, 222.0, 44.01e-3, 4.53e-10);
/// Argon: μ0 = 2.125e-5 Pa·s, S = 144 K; M = 39.948 g/mol, d = 3.58e-10 m.
pub const ARGON: Gas = white("argon", 2.125e-5, 144.0, 39.948e-3, 3.58e-10);

/// Helium, **illustrative**: not in White's table as quoted. The whole Sutherland set of the
/// Cableizer documentation "Reference dynamic viscosity of gas" (which takes it from Wikipedia;
/// SECONDARY): μ0 = 1.9e-5 Pa·s, T0 = 273 K, S = 79.4 K (one set, not mixed with another's
/// T0). Cross-check done here: the CRC hard-sphere relation η = 2.67e-20 √(M T)/d² quoted
/// with the diameters gives 19.1 µPa·s at 273.15 K with d = 2.15e-10 m, M = 4.0026 g/mol
/// (0.5 % from μ0). M and d from the CRC table (as quoted).
pub const HELIUM: Gas = Gas {
    id: "helium",
    molar_mass: 4.0026e-3,
    viscosity: GasViscosity::Sutherland(Sutherland {
        mu0: 1.9e-5,
        t0: 273.0,
        s: 79.4,
    }),
    molecular_diameter: 2.15e-10,
    source: "illustrative: Sutherland set of the Cableizer documentation (from Wikipedia; μ0 1.9e-5 Pa·s, T0 273 K, S 79.4 K); M, d from the CRC table (as quoted)",
};

/// Methane, **illustrative**: no citable Sutherland table was found. The set μ0 = 1.027e-5
/// Pa·s, T0 = 273 K, S = 170 K appears in a public code (which cites Bird, Stewart & Lightfoot
/// for the formula, not clearly for the constants): UNVERIFIED. The CRC hard-sphere relation
/// with d = 3.80e-10 m gives 12.2 µPa·s at 273.15 K, 19 % above μ0: the diameter is a
/// mean-free-path diameter, not a viscosity fit at 0 °C. M = 16.043 g/mol, d from the CRC
/// table (as quoted).
pub const METHANE: Gas = Gas {
    id: "methane",
    molar_mass: 16.043e-3,
    viscosity: GasViscosity::Sutherland(Sutherland {
        mu0: 1.027e-5,
        t0: 273.0,
        s: 170.0,
    }),
    molecular_diameter: 3.80e-10,
    source: "illustrative: Sutherland set seen in a public code, unverified (μ0 1.027e-5 Pa·s, T0 273 K, S 170 K); M, d from the CRC table (as quoted)",
};

const fn white(id: &'static str, mu0: f64, s: f64, molar_mass: f64, diameter: f64) -> Gas {
    Gas {
        id,
        molar_mass,
        viscosity: GasViscosity::Sutherland(Sutherland {
            mu0,
            t0: WHITE_T0,
            s,
        }),
        molecular_diameter: diameter,
        source: WHITE,
    }
}

/// The gases of the library.
pub const LIBRARY: [Gas; 8] = [
    HELIUM,
    HYDROGEN,
    NITROGEN,
    AIR,
    ARGON,
    CARBON_DIOXIDE,
    METHANE,
    OXYGEN,
];

/// The temperature at 1 atm below which the library gas `id` is no longer a gas \[K\]: its
/// normal boiling point (carbon dioxide: its sublimation point; air: its bubble point). Below
/// it the ideal-gas, Sutherland and rarefied-flow laws of docs/model.md §3.9–3.10 do not apply,
/// so a run there is refused. Helium 4.2, hydrogen 20, nitrogen 77, oxygen 90, argon 87 K:
/// the cryogen table of "Cryogenics — History" (Science Encyclopedia,
/// <https://science.jrank.org/pages/1889/Cryogenics-History.html>); air 78.8 K, methane
/// 111.7 K, carbon dioxide 194.7 K: recalled (CRC Handbook values), not read here. `None` for
/// a custom gas.
pub fn condensation_point(id: &str) -> Option<f64> {
    match id {
        "helium" => Some(4.2),
        "hydrogen" => Some(20.0),
        "nitrogen" => Some(77.0),
        "air" => Some(78.8),
        "argon" => Some(87.0),
        "oxygen" => Some(90.0),
        "methane" => Some(111.7),
        "carbon-dioxide" => Some(194.7),
        _ => None,
    }
}

/// The library gas `id` (`"helium"`, `"carbon-dioxide"`, …); `None` if unknown.
pub fn library(id: &str) -> Option<Gas> {
    LIBRARY.iter().copied().find(|g| g.id == id)
}

/// The ids of the library's gases.
pub fn library_ids() -> Vec<&'static str> {
    LIBRARY.iter().map(|g| g.id).collect()
}

// The units of gas flow (sccm, slm and their standard state) are unit definitions: they live in
// `units`, the inner layer, and are re-exported here where the gas physics reads them.
pub use crate::units::{SCCM, SLM, STANDARD_PRESSURE, STANDARD_TEMPERATURE};

/// A throughput `q` \[Pa·m³/s\] at `temperature` \[K\] in sccm (SEMI reference state).
pub fn to_sccm(q: f64, temperature: f64) -> f64 {
    q * (STANDARD_TEMPERATURE / temperature) / SCCM
}

/// A throughput `q` \[Pa·m³/s\] at `temperature` \[K\] as a molar flow \[mol/s\]: `ṅ = q/(R T)`.
pub fn to_mol_per_s(q: f64, temperature: f64) -> f64 {
    q / (GAS_CONSTANT * temperature)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_library_gas_has_its_condensation_point() {
        for g in LIBRARY {
            let t = condensation_point(g.id).unwrap();
            // all condense below room temperature; helium lowest, carbon dioxide highest
            assert!((4.0..=195.0).contains(&t), "{}: {t}", g.id);
        }
        assert_eq!(condensation_point("custom"), None);
    }

    #[test]
    fn library_is_complete_and_consistent() {
        assert_eq!(library_ids().len(), 8);
        for id in library_ids() {
            let g = library(id).expect("listed");
            assert_eq!(g.id, id);
            assert!(g.molar_mass > 1e-3 && g.molar_mass < 0.05);
            assert!(g.molecular_diameter > 2e-10 && g.molecular_diameter < 5e-10);
            // the viscosity at 0 °C is 8–22 µPa·s for all of them
            let mu = g.viscosity.at(273.15);
            assert!(mu > 8e-6 && mu < 2.2e-5, "{id}: {mu}");
        }
        assert!(library("neon").is_none());
    }

    #[test]
    fn sccm_is_its_definition() {
        // 1 sccm = 101325 Pa × 1 cm³ / 60 s at 0 °C (the notes' converter: 0.001689 Pa·m³/s)
        assert!((SCCM / 1.688_75e-3 - 1.0).abs() < 1e-12);
        // at 0 °C the throughput of 1 sccm is 1 sccm; NIST: 1 µmol/s = 1.3448 sccm
        assert!((to_sccm(SCCM, 273.15) - 1.0).abs() < 1e-12);
        let mol = to_mol_per_s(SCCM, 273.15);
        assert!((1e-6 / mol / 1.3448 - 1.0).abs() < 1e-4, "{mol}");
    }
}
