//! The fluid and the leak law: how a fluid driven by the pressures at the seal's two ends flows
//! through the interface's conductance (docs/model.md §3.1–§3.2).
//!
//! This is the one place where a conductance becomes a leak rate. Every path of the simulator —
//! the static leak of a flat seal, the strips in series of a life run, the numerical reference,
//! the reciprocating seal's pressure-driven part and the clogged interface — hands the fluid a
//! [`FlowGeometry`] and a [`Conduction`] and gets the leak rate back from [`Fluid::leak_rate`].
//! It is the fluid that decides how the boundary pressures drive the flow: an incompressible
//! liquid linearly in ΔP, a gas ([`GasService`], docs/model.md §3.9) as an isothermal ideal gas
//! with its mass flux conserved, so that its throughput goes with P_a² − P_b².

use crate::gas::Gas;

/// A Newtonian fluid and the pressure it pushes across the seal: an incompressible liquid, or
/// (with [`Fluid::gas`]) an isothermal ideal gas.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fluid {
    /// Dynamic viscosity η \[Pa·s\] at the reference (installation) temperature T(0): the
    /// static problem's.
    pub viscosity: f64,
    /// ΔP = P_a − P_b across the seal \[Pa\] (≥ 0).
    pub pressure_difference: f64,
    /// How η follows the temperature (docs/model.md §3.7); the life loop evaluates it at T(t).
    pub law: ViscosityLaw,
    /// `Some` for a gas: the gas and the absolute outlet pressure (docs/model.md §3.9).
    pub gas: Option<GasService>,
}

/// A gas on the pressurised side of the seal: which gas, and the absolute pressure P_b \[Pa\]
/// on the outlet side (≥ 0; vacuum is 0). The inlet pressure is P_a = P_b + ΔP.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GasService {
    pub gas: Gas,
    /// P_b, absolute \[Pa\].
    pub outlet_pressure: f64,
    /// The gas temperature T \[K\] the fluid was last evaluated at ([`Fluid::at`]): the
    /// temperature of its throughput and of its mean free path.
    pub temperature: f64,
    /// How the gas flows through the constrictions: with rarefaction (slip, transition, free
    /// molecular; the default) or by the continuum law (docs/model.md §3.10).
    pub flow_law: crate::gas::FlowLaw,
}

/// How a fluid's dynamic viscosity follows the temperature (docs/model.md §3.7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ViscosityLaw {
    /// η does not depend on T: [`Fluid::viscosity`] at every temperature.
    Constant,
    /// Liquid water at 0.1 MPa ([`water_viscosity`]).
    Water,
    /// A mineral oil by ASTM D341 (Walther) with a linear density ([`Walther`]).
    Walther(Walther),
    /// A dynamic viscosity by a Vogel fit to tabulated points ([`Vogel`]).
    Vogel(Vogel),
    /// A gas's law (Sutherland, or a constant; docs/model.md §3.9).
    Gas(Gas),
}

/// The Vogel (Vogel–Fulcher–Tammann) equation for the dynamic viscosity,
/// `η = exp(A + B/(T − C))` mPa·s (T in K), fitted to a table of η(T) (docs/model.md §3.7).
/// Used where ASTM D341's double logarithm does not fit a fluid over its range (an aqueous
/// glycol, whose η(T) curves like a glass-former's, not like an oil's).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vogel {
    /// A (dimensionless; ln of mPa·s).
    pub a: f64,
    /// B \[K\].
    pub b: f64,
    /// C \[K\] (below the fluid's range: the divergence temperature of the fit).
    pub c: f64,
    /// Where the numbers come from, short (the run summary's fluid line).
    pub source: &'static str,
}

impl Vogel {
    /// Dynamic viscosity η(T) = exp(A + B/(T − C)) · 1e-3 \[Pa·s\] at `temperature` \[K\] (> C).
    pub fn dynamic(&self, temperature: f64) -> f64 {
        (self.a + self.b / (temperature - self.c)).exp() * 1e-3
    }
}

/// ASTM D341 (Walther) kinematic viscosity with a linear density: `log10 log10(ν + 0.7) =
/// A − B log10 T` (ν in mm²/s = cSt, T in K), A and B through the kinematic viscosities at 40 °C
/// and 100 °C; `η = ρ(T) ν` with `ρ(T) = ρ15 (1 − α (T − 288.15 K))` (docs/model.md §3.7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Walther {
    /// A of ASTM D341 (dimensionless).
    pub a: f64,
    /// B of ASTM D341 (dimensionless, per log10 K).
    pub b: f64,
    /// ρ15, the density at 15 °C \[kg/m³\].
    pub density_15c: f64,
    /// α, the volumetric thermal expansion of the density \[1/K\].
    pub expansion: f64,
    /// Where the numbers come from, short (the run summary's fluid line).
    pub source: &'static str,
}

/// 40 °C \[K\] (the ISO 3448 grade temperature).
pub const T40: f64 = 313.15;
/// 100 °C \[K\].
pub const T100: f64 = 373.15;
/// 15 °C \[K\] (the density reference of ASTM D1250 / ISO 91).
pub const T15: f64 = 288.15;

impl Walther {
    /// The law through the kinematic viscosities `nu40` at 40 °C and `nu100` at 100 °C
    /// \[m²/s\] (ASTM D341 §A1: two points fix A and B), with density `density_15c`
    /// \[kg/m³\] at 15 °C and volumetric expansion `expansion` \[1/K\]. `None` unless
    /// ν40 > ν100 > 0 (an oil thins when heated) and the density is positive.
    pub fn through(
        nu40: f64,
        nu100: f64,
        density_15c: f64,
        expansion: f64,
        source: &'static str,
    ) -> Option<Walther> {
        let z = |nu: f64| (nu * 1e6 + 0.7).log10().log10();
        if !(nu100 > 0.0 && nu40 > nu100 && density_15c > 0.0 && expansion.is_finite()) {
            return None;
        }
        let (z40, z100) = (z(nu40), z(nu100));
        let b = (z40 - z100) / (T100.log10() - T40.log10());
        let a = z40 + b * T40.log10();
        (a.is_finite() && b.is_finite()).then_some(Walther {
            a,
            b,
            density_15c,
            expansion,
            source,
        })
    }

    /// Kinematic viscosity ν(T) \[m²/s\]: `ν = 10^(10^(A − B log10 T)) − 0.7` cSt.
    pub fn kinematic(&self, temperature: f64) -> f64 {
        let z = self.a - self.b * temperature.log10();
        (10f64.powf(10f64.powf(z)) - 0.7) * 1e-6
    }

    /// Density ρ(T) = ρ15 (1 − α (T − 15 °C)) \[kg/m³\].
    pub fn density(&self, temperature: f64) -> f64 {
        self.density_15c * (1.0 - self.expansion * (temperature - T15))
    }

    /// Dynamic viscosity η(T) = ρ(T) ν(T) \[Pa·s\].
    pub fn dynamic(&self, temperature: f64) -> f64 {
        self.density(temperature) * self.kinematic(temperature)
    }
}

/// The viscosity of liquid water at 0.1 MPa \[Pa·s\] at `temperature` \[K\]: the
/// correlation of Huber et al., J. Phys. Chem. Ref. Data 38 (2009) 101, §3.7 (the IAPWS 2008
/// formulation's companion for liquid water at 0.1 MPa, 253.15–383.15 K),
/// `η = Σ a_i (T/300 K)^b_i µPa·s` with a = (280.68, 511.45, 61.131, 0.45903),
/// b = (−1.9, −7.7, −19.6, −40) — recalled (the paper could not be read here); checked against
/// two tables that were (Chaplin's LSBU water data, Perry's 9th ed. Table 2-135) to ≤ 0.3 %.
/// Outside 0–100 °C at 1 atm the water is ice or steam: the scenario warns ([`WATER_LIQUID`]).
pub fn water_viscosity(temperature: f64) -> f64 {
    const TERMS: [(f64, f64); 4] = [
        (280.68, -1.9),
        (511.45, -7.7),
        (61.131, -19.6),
        (0.45903, -40.0),
    ];
    let t = temperature / 300.0;
    TERMS.iter().map(|&(a, b)| a * t.powf(b)).sum::<f64>() * 1e-6
}

/// Liquid water at 1 atm: from the melting to the boiling point \[K\].
pub const WATER_LIQUID: (f64, f64) = (273.15, 373.15);

impl ViscosityLaw {
    /// η at `temperature` \[K\] \[Pa·s\]; `None` for [`ViscosityLaw::Constant`] (the
    /// fluid's own value).
    fn at(&self, temperature: f64) -> Option<f64> {
        match self {
            ViscosityLaw::Constant => None,
            ViscosityLaw::Water => Some(water_viscosity(temperature)),
            ViscosityLaw::Walther(w) => Some(w.dynamic(temperature)),
            ViscosityLaw::Vogel(v) => Some(v.dynamic(temperature)),
            ViscosityLaw::Gas(g) => Some(g.viscosity.at(temperature)),
        }
    }

    /// Where the law's numbers come from, short; `None` for a constant.
    pub fn source(&self) -> Option<&'static str> {
        match self {
            ViscosityLaw::Constant => None,
            ViscosityLaw::Water => Some(WATER_SOURCE),
            ViscosityLaw::Walther(w) => Some(w.source),
            ViscosityLaw::Vogel(v) => Some(v.source),
            ViscosityLaw::Gas(g) => Some(g.source),
        }
    }
}

/// The water law's provenance.
const WATER_SOURCE: &str = "water, Huber et al. 2009 (IAPWS 2008) at 0.1 MPa";

/// A fluid of the library (`[fluid] library = "…"`): its law and where the numbers come from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LibraryFluid {
    pub id: &'static str,
    pub law: ViscosityLaw,
    /// Short provenance for the run summary.
    pub source: &'static str,
    /// The fluid's liquid range at 1 atm \[K\] (freezing or pour point, boiling point; infinite
    /// for an oil) where known: a run outside it, the boiling point taken at the run's absolute
    /// pressure ([`LibraryFluid::boiling_point`]), is refused (the law there would be evaluated
    /// past a phase change).
    pub liquid_range: Option<(f64, f64)>,
}

/// 50/50 (by volume) ethylene glycol–water: the Vogel fit ([`Vogel`]) to the dynamic viscosity
/// table of "Ethylene Glycol Heat-Transfer Fluid" (The Engineering ToolBox, as copied at
/// <https://www.scribd.com/document/671664902/Ethylene-Glycol-Heat>), 50 % by volume:
/// 22, 6.5, 2.8, 1.5, 0.95, 0.7 cP at 0, 40, 80, 120, 160, 200 °F (−17.8 … 93.3 °C).
/// Least-squares fit of ln η (fitted here): A = −3.2408, B = 579.11 K, C = 163.98 K; it
/// reproduces the six points within 2.4 % ([`GLYCOL_WATER_POINTS`]).
pub const GLYCOL_WATER_50: Vogel = Vogel {
    a: -3.2408,
    b: 579.11,
    c: 163.98,
    source: "50/50 vol ethylene glycol–water, Vogel fit to the Engineering ToolBox table (22–0.7 cP, −17.8–93.3 °C)",
};

/// The source points of [`GLYCOL_WATER_50`]: (T \[K\], η \[Pa·s\]).
pub const GLYCOL_WATER_POINTS: [(f64, f64); 6] = [
    (255.35, 22e-3),
    (277.55, 6.5e-3),
    (299.85, 2.8e-3),
    (322.05, 1.5e-3),
    (344.25, 0.95e-3),
    (366.45, 0.7e-3),
];

/// Liquid range of 50/50 vol ethylene glycol–water at 1 atm \[K\]: freezing point −37 °C (the
/// Engineering ToolBox freezing-point table above, 50 % by volume: −37 °C / −36 °F) to the
/// boiling point ≈ 106 °C ("Around 106°C (222.8°F) at atmospheric pressure", ExcelCalcs,
/// "50-50 Ethylene glycol-water and air properties",
/// <https://www.excelcalcs.com/calcs/repository/Fluids/50-50-Ethylene-glycol-water--and--air-properties/>).
pub const GLYCOL_WATER_LIQUID: (f64, f64) = (236.15, 379.15);

/// Density of a typical mineral oil at 15 °C \[kg/m³\] (illustrative: ISO VG 32–100 hydraulic
/// oils' data sheets give 0.86–0.89 g/cm³).
pub const MINERAL_OIL_DENSITY_15C: f64 = 870.0;
/// Volumetric expansion of a typical mineral oil \[1/K\] (illustrative, the usual 6.4e-4 1/K of
/// petroleum oils near 870 kg/m³).
pub const MINERAL_OIL_EXPANSION: f64 = 6.4e-4;

/// The ISO VG grades of the library: id, ν40 = the grade's midpoint (ISO 3448) \[mm²/s\], and
/// ν100 \[mm²/s\] of a typical VI ≈ 100 mineral hydraulic oil (illustrative data-sheet values),
/// with a short provenance.
const ISO_VG: [(&str, f64, f64, &str); 4] = [
    (
        "iso-vg-32",
        32.0,
        5.4,
        "ISO VG 32 mineral oil, ASTM D341; ν100 and density illustrative",
    ),
    (
        "iso-vg-46",
        46.0,
        6.8,
        "ISO VG 46 mineral oil, ASTM D341; ν100 and density illustrative",
    ),
    (
        "iso-vg-68",
        68.0,
        8.7,
        "ISO VG 68 mineral oil, ASTM D341; ν100 and density illustrative",
    ),
    (
        "iso-vg-100",
        100.0,
        11.1,
        "ISO VG 100 mineral oil, ASTM D341; ν100 and density illustrative",
    ),
];

/// Id of the glycol–water library fluid.
const GLYCOL_WATER_ID: &str = "ethylene-glycol-water-50";

/// The ids of the library's fluids.
pub fn library_ids() -> Vec<&'static str> {
    ["water", GLYCOL_WATER_ID]
        .into_iter()
        .chain(ISO_VG.iter().map(|g| g.0))
        .collect()
}

/// The library fluid `id` (`"water"`, `"iso-vg-46"`, …), `None` if unknown.
pub fn library(id: &str) -> Option<LibraryFluid> {
    if id == "water" {
        return Some(LibraryFluid {
            id: "water",
            law: ViscosityLaw::Water,
            source: WATER_SOURCE,
            liquid_range: Some(WATER_LIQUID),
        });
    }
    if id == GLYCOL_WATER_ID {
        return Some(LibraryFluid {
            id: GLYCOL_WATER_ID,
            law: ViscosityLaw::Vogel(GLYCOL_WATER_50),
            source: GLYCOL_WATER_50.source,
            liquid_range: Some(GLYCOL_WATER_LIQUID),
        });
    }
    let &(id, nu40, nu100, source) = ISO_VG.iter().find(|g| g.0 == id)?;
    let walther = Walther::through(
        nu40 * 1e-6,
        nu100 * 1e-6,
        MINERAL_OIL_DENSITY_15C,
        MINERAL_OIL_EXPANSION,
        source,
    )?;
    Some(LibraryFluid {
        id,
        law: ViscosityLaw::Walther(walther),
        source,
        // a mineral oil's pour point is a property of the product, not of its grade: the
        // illustrative one of a VG 46 (it does not boil in a seal's range)
        liquid_range: Some((MINERAL_OIL_POUR_POINT, f64::INFINITY)),
    })
}

/// One standard atmosphere \[Pa\]: the outlet of a liquid seal, and the pressure of the liquid
/// ranges above.
pub const ATMOSPHERE: f64 = 101_325.0;

/// Pour point taken for the library's ISO VG mineral oils \[K\]: −39 °C, **illustrative** —
/// "an ISOVG 46 mineral oil might have a pour point of −39 degree C, whereas an ISOVG 460 would
/// have a pour point of −15 degree C" (Herguth Laboratories, "Pour Point",
/// <http://www.herguth.com/table_of_contents/pour_point.htm>); the pour point rises with the
/// grade, so VG 68 and VG 100 products usually stop flowing warmer, and a VG 32 product may
/// flow a few kelvin colder. A product's own data sheet governs: give the oil inline to run
/// colder.
pub const MINERAL_OIL_POUR_POINT: f64 = 234.15;

/// The saturation temperature of water at absolute pressure `p` \[Pa\] \[K\]: the
/// IAPWS-IF97 region-4 saturation-temperature equation (eq. 31 of the IAPWS Revised Release
/// on the IAPWS Industrial Formulation 1997, 2007, <http://www.iapws.org/relguide/IF97-Rev.html>,
/// as implemented in the `iapws` Python package, `iapws97._TSat_P`, whose check value
/// T_sat(10 MPa) = 584.149488 K the test reproduces), valid from the triple-point pressure
/// 611.213 Pa to the critical pressure 22.064 MPa. Below that range the triple-point
/// temperature 273.16 K; above it the critical temperature 647.096 K (beyond it water is no
/// longer a liquid that boils).
pub fn water_saturation_temperature(p: f64) -> f64 {
    const N: [f64; 10] = [
        0.116_705_214_527_67e4,
        -0.724_213_167_032_06e6,
        -0.170_738_469_400_92e2,
        0.120_208_247_024_70e5,
        -0.323_255_503_223_33e7,
        0.149_151_086_135_30e2,
        -0.482_326_573_615_91e4,
        0.405_113_405_420_57e6,
        -0.238_555_575_678_49,
        0.650_175_348_447_98e3,
    ];
    if p.is_nan() || p <= 611.213 {
        return 273.16;
    }
    if p >= 22.064e6 {
        return 647.096;
    }
    let beta = (p / 1e6).powf(0.25);
    let e = beta * beta + N[2] * beta + N[5];
    let f = N[0] * beta * beta + N[3] * beta + N[6];
    let g = N[1] * beta * beta + N[4] * beta + N[7];
    let d = 2.0 * g / (-f - (f * f - 4.0 * e * g).sqrt());
    (N[9] + d - ((N[9] + d).powi(2) - 4.0 * (N[8] + N[9] * d)).sqrt()) / 2.0
}

impl LibraryFluid {
    /// The fluid's boiling point at absolute pressure `p` \[Pa\] \[K\]: water on the
    /// IAPWS-IF97 saturation line ([`water_saturation_temperature`]); 50/50 glycol–water its
    /// 1-atm boiling point shifted as water's is (**assumed**: the boiling-point elevation of
    /// the glycol, 106 − 100 ≈ 6 K at 1 atm, taken as constant; no pressure data for the
    /// mixture was found); a mineral oil none (infinite: it does not boil in a seal's range).
    pub fn boiling_point(&self, p: f64) -> f64 {
        let Some((_, at_atmosphere)) = self.liquid_range else {
            return f64::INFINITY;
        };
        match self.law {
            ViscosityLaw::Water => water_saturation_temperature(p),
            _ if at_atmosphere.is_finite() => {
                at_atmosphere + water_saturation_temperature(p)
                    - water_saturation_temperature(ATMOSPHERE)
            }
            _ => f64::INFINITY,
        }
    }
}

/// The seal's extent along and across the flow. Built with named fields only, so that the two
/// lengths cannot be swapped silently.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowGeometry {
    /// L_x: the extent along the flow, from the pressurised side to the outlet \[m\] (the contact
    /// width).
    pub along_flow: f64,
    /// L_y: the extent across the flow \[m\] (the sealing length; an O-ring's mean circumference
    /// π D).
    pub across_flow: f64,
}

impl FlowGeometry {
    /// `L_y/L_x`: the number of square cells of side L_x side by side across the flow, each with
    /// one critical constriction (PY08 eq. 3; docs/model.md §3.1).
    pub fn cells(&self) -> f64 {
        self.across_flow / self.along_flow
    }
}

/// How the interface conducts between the two ends of the seal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Conduction {
    /// One conductance per unit width σ \[m³/(Pa·s)\] over the whole extent along the flow
    /// (a flat seal; `σ = α u_c³/(12η)` for the critical junction, σ_eff for an effective
    /// medium or the numerical reference).
    Uniform { conductance: f64 },
    /// Strips in series along the flow: the resistance per unit width `R = ∫ dx/σ(x)`
    /// [Pa·s/m²] over the extent along the flow (docs/model.md §3.2).
    Series { resistance: f64 },
}

/// The volume of one water molecule, `M/(ρ N_A)` \[m³\]: M = 18.015 g/mol, ρ = 997.05 kg/m³
/// (25 °C), N_A = 6.02214076e23/mol.
pub const WATER_MOLECULE_VOLUME: f64 = 0.018_015 / (997.05 * 6.022_140_76e23);

/// The size of one molecule of every liquid \[m\] ([`Fluid::molecular_size`]): the edge of the
/// cube one water molecule fills, `(M/(ρ N_A))^{1/3}` = 3.10e-10 m ([`WATER_MOLECULE_VOLUME`]).
/// The default of the contact paths' `leak::PathOptions::molecular_size`.
pub fn liquid_molecular_size() -> f64 {
    WATER_MOLECULE_VOLUME.cbrt()
}

// The one molecular rule lives with the gases, which use it too (no fluid ↔ gas cycle).
pub use crate::gas::passes_molecule;

impl Fluid {
    /// The dynamic viscosity at `temperature` \[K\] \[Pa·s\] by the fluid's law (its own
    /// [`Fluid::viscosity`], bit for bit, under [`ViscosityLaw::Constant`]).
    pub fn viscosity_at(&self, temperature: f64) -> f64 {
        self.law.at(temperature).unwrap_or(self.viscosity)
    }

    /// The fluid at `temperature` \[K\]: its viscosity evaluated there (docs/model.md §3.7).
    pub fn at(&self, temperature: f64) -> Fluid {
        Fluid {
            viscosity: self.viscosity_at(temperature),
            gas: self.gas.map(|g| GasService { temperature, ..g }),
            ..*self
        }
    }

    /// The leak rate Q̇ \[m³/s\] through `conduction` over `geometry` (docs/model.md §3.1–§3.2):
    /// * uniform: `Q̇ = (L_y/L_x) σ ΔP` (PY08 eq. 3 with the conductance of eq. 2);
    /// * series: `Q̇ = L_y ΔP / ∫ dx/σ(x)` (the flux per unit width is the same through every
    ///   strip; with σ uniform it is the uniform law).
    ///
    /// An incompressible fluid's volume flow is linear in ΔP. For a gas this is the volume flow
    /// **at the mean pressure** p̄ = (P_a + P_b)/2: the throughput ([`Fluid::throughput`])
    /// divided by p̄, which is the same expression (σ (P_a² − P_b²)/2 = σ ΔP p̄): the gas's
    /// continuum leak is the liquid law with the gas's viscosity, carried at the mean density
    /// (docs/model.md §3.9). A sealed interface (σ = 0 or R = ∞) gives 0.
    pub fn leak_rate(&self, geometry: FlowGeometry, conduction: Conduction) -> f64 {
        if let (Some(q), Some(p)) = (self.throughput(geometry, conduction), self.mean_pressure()) {
            return q / p;
        }
        match conduction {
            Conduction::Uniform { conductance } => {
                geometry.cells() * conductance * self.pressure_difference
            }
            Conduction::Series { resistance } => {
                geometry.across_flow * self.pressure_difference / resistance
            }
        }
    }

    /// The throughput (pV flow) of a gas \[Pa·m³/s\] at the gas temperature through
    /// `conduction` over `geometry`; `None` for a liquid (docs/model.md §3.9). Isothermal ideal
    /// gas, mass flux conserved: per unit width `p q = −σ p dp/dx = −(σ/2) d(p²)/dx`, so
    /// * uniform: `Q = (L_y/L_x) σ (P_a² − P_b²)/2`;
    /// * series: `Q = L_y (P_a² − P_b²)/(2 ∫ dx/σ(x))`.
    ///
    /// The continuum law; rarefaction (Kn = λ/u_c not small) is only warned about.
    pub fn throughput(&self, geometry: FlowGeometry, conduction: Conduction) -> Option<f64> {
        let gas = self.gas?;
        let (pa, pb) = (
            gas.outlet_pressure + self.pressure_difference,
            gas.outlet_pressure,
        );
        let half_squares = 0.5 * (pa * pa - pb * pb);
        Some(match conduction {
            Conduction::Uniform { conductance } => geometry.cells() * conductance * half_squares,
            Conduction::Series { resistance } => geometry.across_flow * half_squares / resistance,
        })
    }

    /// The throughput \[Pa·m³/s\] that goes with a leak rate `leak_rate` \[m³/s\] of
    /// [`Fluid::leak_rate`] (the volume flow at the mean pressure): `Q = p̄ Q̇`; `None` for a
    /// liquid.
    pub fn throughput_of(&self, leak_rate: f64) -> Option<f64> {
        self.mean_pressure().map(|p| p * leak_rate)
    }

    /// The leak rate of one molecule a second \[m³/s\] (docs/model.md §15.2): below it no flow
    /// is meant, only single molecules. A liquid: one water molecule, `M/(ρ N_A)` = 0.018015
    /// kg/mol / (997.05 kg/m³ × 6.02214076e23/mol) = 3.0e-29 m³, the smallest common liquid
    /// molecule (so the lowest floor of any liquid); a gas: `k_B T/p̄`, one molecule's volume at
    /// the mean pressure and the gas temperature (the volume flow the leak rate is counted in).
    pub fn one_molecule_per_second(&self) -> f64 {
        match (self.gas, self.mean_pressure()) {
            (Some(g), Some(p)) if p > 0.0 => crate::gas::BOLTZMANN * g.temperature / p,
            _ => WATER_MOLECULE_VOLUME,
        }
    }

    /// The size of one molecule of the fluid \[m\] (docs/model.md §8.1): a critical gap no
    /// wider passes nothing. A gas: its hard-sphere diameter ([`crate::gas::Gas`], 0.215 nm for
    /// helium, 0.38 nm for air). A liquid: the edge of the cube one water molecule fills,
    /// `(M/(ρ N_A))^{1/3}` = 0.31 nm ([`WATER_MOLECULE_VOLUME`]) — water has the smallest common
    /// liquid molecule, so every liquid is held to the smallest size, the choice that calls
    /// fewest gaps sealed (an oil's molecules are several times larger).
    pub fn molecular_size(&self) -> f64 {
        match self.gas {
            Some(g) => g.gas.molecular_diameter,
            None => liquid_molecular_size(),
        }
    }

    /// The mean absolute pressure p̄ = (P_a + P_b)/2 \[Pa\] of a gas; `None` for a liquid.
    pub fn mean_pressure(&self) -> Option<f64> {
        self.gas
            .map(|g| g.outlet_pressure + 0.5 * self.pressure_difference)
    }

    /// The Knudsen number `Kn = λ_μ(p̄, T)/u` of a gas at a constriction of height `gap` \[m\],
    /// with the viscosity-based mean free path of the rarefaction law
    /// ([`crate::gas::Gas::viscous_mean_free_path`]) at the mean pressure p̄ = (P_a + P_b)/2 and
    /// the gas temperature T ([`GasService::temperature`]); `None` for a liquid, and for a gap no
    /// wider than a molecule, through which no gas flows at all.
    pub fn knudsen(&self, gap: f64) -> Option<f64> {
        let g = self.gas?;
        if gap <= g.gas.molecular_diameter {
            return None;
        }
        let p = self.mean_pressure()?;
        Some(g.gas.viscous_mean_free_path(g.temperature, p) / gap)
    }

    /// What the rarefaction law needs at gauge pressure `gauge` \[Pa\] over the outlet
    /// (absolute P_b + gauge) and the gas temperature (docs/model.md §3.10); `None` for a liquid
    /// or a gas under the continuum law.
    pub fn free_path_at(&self, gauge: f64) -> Option<crate::gas::Rarefied> {
        let g = self.gas?;
        // the absolute pressure floored as in [`Self::density_weight`], so that against a
        // vacuum σ·(P_b + p_f)/p̄ tends to its free-molecular limit instead of ∞·0
        let floor = PRESSURE_FLOOR * (g.outlet_pressure + 0.5 * self.pressure_difference);
        (g.flow_law == crate::gas::FlowLaw::Rarefied).then(|| crate::gas::Rarefied {
            free_path: g
                .gas
                .viscous_mean_free_path(g.temperature, (g.outlet_pressure + gauge).max(floor)),
            molecular_diameter: g.gas.molecular_diameter,
        })
    }

    /// How many graded breaks the uniform interface's quadrature needs towards the outlet
    /// (`InterfaceSettings::outlet_breaks` in the `interface` module): 16 for a rarefied gas whose
    /// outlet pressure is below ΔP (its free-molecular end is not smooth), 0 otherwise.
    pub fn outlet_breaks(&self) -> usize {
        match self.gas {
            Some(g)
                if g.flow_law == crate::gas::FlowLaw::Rarefied
                    && g.outlet_pressure < self.pressure_difference =>
            {
                16
            }
            _ => 0,
        }
    }

    /// [`Self::free_path_at`] at the mean pressure p̄ (gauge ΔP/2).
    pub fn mean_free_path(&self) -> Option<crate::gas::Rarefied> {
        self.free_path_at(0.5 * self.pressure_difference)
    }

    /// For the interface-pressure model (docs/model.md §3.6, §3.9): the weight by which a gas's
    /// local conductance at gauge fluid pressure `gauge` \[Pa\] over the outlet enters an
    /// effective conductance, `(P_b + gauge)/p̄` (the mass flux carries the local density);
    /// 1 for a liquid.
    ///
    /// Floored at 1e-9: against a vacuum the continuum law's weight vanishes at the outlet, where
    /// the pressure profile's slope diverges (p dp/dx stays finite); the floor keeps the
    /// profile's shooting finite and changes the flux by far less than its tolerance.
    pub fn density_weight(&self, gauge: f64) -> f64 {
        match (self.gas, self.mean_pressure()) {
            (Some(g), Some(p)) => ((g.outlet_pressure + gauge) / p).max(PRESSURE_FLOOR),
            _ => 1.0,
        }
    }
}

/// The lowest absolute pressure a gas is evaluated at, over its mean pressure p̄: against a
/// vacuum the density weight and the mean free path are taken at 1e-9 p̄ rather than at 0
/// ([`Fluid::density_weight`], [`Fluid::free_path_at`]).
const PRESSURE_FLOOR: f64 = 1e-9;

/// Conductance per unit width of one critical constriction of height `u_c` \[m\] (PY08 eqs.
/// 1–2; docs/model.md §3.1): `σ = α u_c³/(12 η)` \[m³/(Pa·s)\], α the shape factor, η the
/// viscosity \[Pa·s\]. The flow through a thin gap between parallel walls (plane Poiseuille).
pub fn junction_conductance(u_c: f64, shape_factor: f64, viscosity: f64) -> f64 {
    shape_factor * u_c.powi(3) / (12.0 * viscosity)
}

#[cfg(test)]
mod tests {
    use super::*;

    const WATER: Fluid = Fluid {
        viscosity: 1e-3,
        pressure_difference: 1e5,
        law: ViscosityLaw::Constant,
        gas: None,
    };

    #[test]
    fn uniform_law_counts_cells_across_the_flow() {
        let g = FlowGeometry {
            along_flow: 1e-3,
            across_flow: 0.1,
        };
        let q = WATER.leak_rate(g, Conduction::Uniform { conductance: 2e-18 });
        assert!((q / (100.0 * 2e-18 * 1e5) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn series_of_equal_strips_is_the_uniform_law() {
        let g = FlowGeometry {
            along_flow: 2e-3,
            across_flow: 0.05,
        };
        let sigma = 3e-19;
        let uniform = WATER.leak_rate(g, Conduction::Uniform { conductance: sigma });
        let series = WATER.leak_rate(
            g,
            Conduction::Series {
                resistance: g.along_flow / sigma,
            },
        );
        assert!((series / uniform - 1.0).abs() < 1e-14);
    }

    #[test]
    fn a_sealed_interface_leaks_nothing() {
        let g = FlowGeometry {
            along_flow: 1e-3,
            across_flow: 1e-2,
        };
        assert_eq!(
            WATER.leak_rate(g, Conduction::Uniform { conductance: 0.0 }),
            0.0
        );
        assert_eq!(
            WATER.leak_rate(
                g,
                Conduction::Series {
                    resistance: f64::INFINITY
                }
            ),
            0.0
        );
    }

    /// Relative difference.
    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    #[test]
    fn water_matches_the_reference_tables_within_one_percent() {
        // M. Chaplin, "Water structure and science: data", London South Bank University
        // (www1.lsbu.ac.uk/water/data1.html), dynamic viscosity at 1 atm [cP = mPa·s]
        for (celsius, cp) in [(0.0, 1.792), (20.0, 1.002), (40.0, 0.653), (80.0, 0.355)] {
            let eta = water_viscosity(273.15 + celsius);
            assert!(
                rel(eta, cp * 1e-3) < 0.01,
                "{celsius} °C: {eta} vs {cp} mPa·s"
            );
        }
        // Perry's Chemical Engineers' Handbook, 9th ed., Table 2-135 (saturated liquid, from
        // the IAPWS formulations) [µPa·s]: the pressure difference to 0.1 MPa changes η by
        // far less than 0.1 % below 100 °C
        for (kelvin, upas) in [
            (273.16, 1791.2),
            (300.0, 853.84),
            (350.0, 368.77),
            (370.0, 291.36),
        ] {
            let eta = water_viscosity(kelvin);
            assert!(
                rel(eta, upas * 1e-6) < 0.01,
                "{kelvin} K: {eta} vs {upas} µPa·s"
            );
        }
    }

    #[test]
    fn iso_vg_46_reproduces_its_grade_and_the_walther_line_between() {
        let Some(LibraryFluid {
            law: ViscosityLaw::Walther(w),
            ..
        }) = library("iso-vg-46")
        else {
            panic!("iso-vg-46 is a Walther oil");
        };
        // ISO 3448: VG 46 is 46 mm²/s at 40 °C; the library's 100 °C value 6.8 mm²/s
        assert!(rel(w.kinematic(T40), 46e-6) < 1e-12);
        assert!(rel(w.kinematic(T100), 6.8e-6) < 1e-12);
        // ASTM D341 through those two points, evaluated by hand (log10 log10(ν + 0.7) linear in
        // log10 T): 20.6227 mm²/s at 60 °C, 133.838 at 20 °C, 11.1026 at 80 °C
        for (kelvin, cst) in [(333.15, 20.6227), (293.15, 133.838), (353.15, 11.1026)] {
            assert!(rel(w.kinematic(kelvin), cst * 1e-6) < 1e-5, "{kelvin} K");
        }
        // η = ρ ν with ρ(40 °C) = 870 (1 − 6.4e-4 · 25) kg/m³
        assert!(rel(w.dynamic(T40), 870.0 * (1.0 - 6.4e-4 * 25.0) * 46e-6) < 1e-12);
    }

    #[test]
    fn a_constant_law_is_the_fluid_itself_and_the_library_is_complete() {
        assert_eq!(WATER.viscosity_at(400.0), WATER.viscosity);
        assert_eq!(WATER.at(250.0), WATER);
        for id in library_ids() {
            assert_eq!(library(id).map(|f| f.id), Some(id));
        }
        assert!(library("iso-vg-47").is_none());
        // an oil that thickens when heated is refused
        assert!(Walther::through(6.8e-6, 46e-6, 870.0, 6.4e-4, "").is_none());
    }

    #[test]
    fn glycol_water_vogel_fit_reproduces_its_source_table() {
        // the Engineering ToolBox table, 50 % by volume (GLYCOL_WATER_POINTS): the fit is
        // within 2.4 % of every point (least squares in ln η; largest at 93.3 °C)
        let mut worst: f64 = 0.0;
        for (kelvin, eta) in GLYCOL_WATER_POINTS {
            let e = rel(GLYCOL_WATER_50.dynamic(kelvin), eta);
            assert!(e < 0.025, "{kelvin} K: {e}");
            worst = worst.max(e);
        }
        assert!(worst > 0.02, "the stated error is the fit's: {worst}");
        // the library fluid is that law, with its liquid range
        let f = library("ethylene-glycol-water-50").unwrap();
        assert_eq!(f.law, ViscosityLaw::Vogel(GLYCOL_WATER_50));
        assert_eq!(f.liquid_range, Some((236.15, 379.15)));
        assert_eq!(library("water").unwrap().liquid_range, Some(WATER_LIQUID));
    }

    #[test]
    fn water_boils_on_the_iapws_if97_saturation_line() {
        // IF97 eq. 31's check value (iapws._TSat_P(10) = 584.149488 K)
        assert!((water_saturation_temperature(10e6) - 584.149488).abs() < 1e-5);
        // 1 atm: 99.97 °C (373.124 K); 7 bar absolute: ≈ 165 °C, not 100 °C
        assert!((water_saturation_temperature(ATMOSPHERE) - 373.124).abs() < 2e-3);
        let seven = water_saturation_temperature(7e5) - 273.15;
        assert!((164.5..165.5).contains(&seven), "{seven}");
        // monotone in pressure, bounded by the triple and the critical points
        let mut last = 0.0;
        for k in 0..=60 {
            let t = water_saturation_temperature(10f64.powf(2.0 + 0.1 * f64::from(k)));
            assert!(t >= last && (273.16..=647.096).contains(&t), "{t}");
            last = t;
        }
        let water = library("water").unwrap();
        assert_eq!(water.boiling_point(7e5), water_saturation_temperature(7e5));
        let glycol = library("ethylene-glycol-water-50").unwrap();
        assert!((glycol.boiling_point(ATMOSPHERE) - GLYCOL_WATER_LIQUID.1).abs() < 1e-9);
        assert!(glycol.boiling_point(7e5) > glycol.boiling_point(ATMOSPHERE) + 60.0);
        let oil = library("iso-vg-46").unwrap();
        assert_eq!(oil.boiling_point(ATMOSPHERE), f64::INFINITY);
        assert_eq!(oil.liquid_range.map(|r| r.0), Some(MINERAL_OIL_POUR_POINT));
        // the law is monotone (thins when heated) over the liquid range
        let mut last = f64::INFINITY;
        for k in 0..=143 {
            let eta = GLYCOL_WATER_50.dynamic(236.15 + k as f64);
            assert!(eta < last);
            last = eta;
        }
    }

    #[test]
    fn plane_poiseuille_conductance() {
        // a 1 µm slit, water: u³/(12η) = 1e-18/1.2e-2
        let s = junction_conductance(1e-6, 1.0, 1e-3);
        assert!((s / (1e-18 / 1.2e-2) - 1.0).abs() < 1e-15);
        assert!((junction_conductance(1e-6, 0.5, 1e-3) / s - 0.5).abs() < 1e-15);
    }
}
