//! The scenario file exactly as written: one struct per TOML table, every value spanned.
//!
//! Nothing here checks a value or knows a unit; that is validation's job (`validate` and the module of each table). Adding a
//! key means adding a field here, reading it there, and its entry in the key registry
//! (`keys`; a test fails until it has one). All tables reject unknown keys, so a
//! misspelt key is an error with the key named, never silently ignored.

use serde::de::{self, Deserialize, Deserializer, Visitor};
use std::collections::BTreeMap;
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
    pub groove_surface: Option<Spanned<RawSurface>>,
    pub rubber_surface: Option<Spanned<RawSurface>>,
    pub fluid: Spanned<RawFluid>,
    pub seal: Spanned<RawSeal>,
    pub model: Option<Spanned<RawModel>>,
    pub environment: Option<Spanned<RawEnvironment>>,
    pub failure: Option<Spanned<RawFailure>>,
    pub ageing: Option<Spanned<RawScenarioAgeing>>,
    pub simulation: Option<Spanned<RawSimulation>>,
    pub contamination: Option<Spanned<RawContamination>>,
    pub numerical: Option<Spanned<RawNumerical>>,
    pub motion: Option<Spanned<RawMotion>>,
}

impl RawScenario {
    /// Top-level keys that are tables (a missing one is reported as a missing table).
    pub const TABLES: &[&str] = &[
        "material",
        "surface",
        "groove_surface",
        "rubber_surface",
        "fluid",
        "seal",
        "model",
        "environment",
        "failure",
        "ageing",
        "simulation",
        "contamination",
        "numerical",
        "motion",
    ];
}

/// `[material]`: the rubber compound (schema in [`crate::material::compound`]): a library
/// reference (`library = "ID"`), an elastic rubber (`youngs_modulus`) or a viscoelastic one
/// (`long_term_modulus` + `prony`). Which keys are required or allowed together is checked in
/// validation (the `material` module), where the message can explain the choices. The same table
/// is the whole content of a library file (`materials/ID.toml`).
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMaterial {
    pub library: Option<Spanned<String>>,
    /// A material file (e.g. `sealsim fit-prony` output), relative to the scenario file.
    pub file: Option<Spanned<String>>,
    pub name: Option<Spanned<String>>,
    pub status: Option<Spanned<String>>,
    pub poisson_ratio: Option<Quantity>,
    pub youngs_modulus: Option<Quantity>,
    pub long_term_modulus: Option<Quantity>,
    pub prony: Option<Spanned<Vec<Spanned<RawPronyTerm>>>>,
    pub glass_transition: Option<Quantity>,
    pub thermal_expansion: Option<Quantity>,
    pub glassy_thermal_expansion: Option<Quantity>,
    /// `[lo, hi]`: the reduced-time window of the data the series was fitted to.
    pub data_reduced_time: Option<Spanned<Vec<Quantity>>>,
    /// `[lo, hi]`: the temperature window of the data.
    pub data_temperature: Option<Spanned<Vec<Quantity>>>,
    pub shift: Option<Spanned<RawShift>>,
    pub ageing: Option<Spanned<RawAgeing>>,
    /// Fluid class key (`mineral-oil`, `water`, `hot-water`, `water-glycol`) → its rating.
    pub compatibility: Option<Spanned<BTreeMap<String, Spanned<RawCompatibility>>>>,
    /// The compound class (`nbr`, …) whose data kept by class apply (gas permeation).
    pub class: Option<Spanned<String>>,
    /// Gas library id (or `custom`) → the compound's own permeation figure for that gas.
    pub permeation: Option<Spanned<BTreeMap<String, Spanned<RawPermeation>>>>,
    /// Parameter key → where its value came from.
    pub provenance: Option<Spanned<BTreeMap<String, Spanned<String>>>>,
    /// Figure key (`ageing.activation_energy`) → its uncertainty band.
    pub bands: Option<Spanned<BTreeMap<String, Spanned<RawBand>>>>,
    /// Scenario option (not a property of the compound): which modulus the asperity contact
    /// sees — `"relaxed"`, `"instantaneous"`, `"follow"` or a modulus such as `"3 MPa"`.
    /// Refused in material files.
    pub asperity_modulus: Option<Quantity>,
}

/// One `[material.bands]` entry: `{ min = "70 kJ/mol", max = "82 kJ/mol", source = "…" }`.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawBand {
    pub min: Quantity,
    pub max: Quantity,
    pub source: Option<Spanned<String>>,
}

/// One `prony` entry: `{ modulus = "6 MPa", tau = "1000 h" }`.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPronyTerm {
    pub modulus: Quantity,
    pub tau: Quantity,
}

/// `[material.shift]`: WLF (`c1`, `c2`) or Arrhenius (`activation_energy`); which keys belong to
/// which `kind` is checked in validation.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawShift {
    pub kind: Spanned<String>,
    pub reference_temperature: Option<Quantity>,
    pub c1: Option<Quantity>,
    pub c2: Option<Quantity>,
    pub activation_energy: Option<Quantity>,
}

/// `[material.ageing]`: two-network chemical ageing with an Arrhenius rate.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawAgeing {
    pub activation_energy: Quantity,
    /// Ea above `reference_temperature` (absent: `activation_energy` on both sides).
    pub activation_energy_above: Option<Quantity>,
    pub rate: Quantity,
    pub reference_temperature: Quantity,
    pub crosslinking: Option<Quantity>,
    /// What the constants were measured on (required in library files).
    pub property: Option<Spanned<String>>,
    /// The end-of-life criterion of the data (required in library files).
    pub criterion: Option<Spanned<String>>,
    /// The medium the compound was aged in (`air`, `mineral-oil`, `water`, `water-glycol`).
    pub medium: Option<Spanned<String>>,
    /// Where the activation energy comes from, in a line (printed beside `compare` rows).
    pub source: Option<Spanned<String>>,
}

/// One `[material.permeation]` entry: `{ permeability = "5 barrer", diffusivity = "3e-10
/// m^2/s", source = "…" }`.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPermeation {
    pub permeability: Quantity,
    pub diffusivity: Option<Quantity>,
    pub source: Option<Spanned<String>>,
}

/// One `[material.compatibility]` entry: `{ rating = "A", source = "…" }`.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCompatibility {
    pub rating: Spanned<String>,
    pub source: Option<Spanned<String>>,
}

/// A material file (`materials/ID.toml`): one `[material]` table.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMaterialFile {
    pub material: Spanned<RawMaterial>,
}

/// `[surface]` (and `[groove_surface]`, `[rubber_surface]`): the self-affine parameters, a
/// drawing callout (`ra`, `rq` or `rz` with `cutoff`, `short_cutoff`, `short_wavelength`),
/// `psd_file`, or `height_map` with its `pixel_size` and optional `height_unit` (which go
/// together is checked in validation, so that the message can explain the options).
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSurface {
    pub rms_roughness: Option<Quantity>,
    pub hurst_exponent: Option<Quantity>,
    pub q0: Option<Quantity>,
    pub q1: Option<Quantity>,
    pub rolloff: Option<Quantity>,
    pub psd_file: Option<Spanned<String>>,
    pub height_map: Option<Spanned<String>>,
    pub pixel_size: Option<Quantity>,
    pub height_unit: Option<Spanned<String>>,
    /// Callout: arithmetic mean roughness Ra over the band λs … λc.
    pub ra: Option<Quantity>,
    /// Callout: rms roughness Rq over the band.
    pub rq: Option<Quantity>,
    /// Callout: mean peak-to-valley height Rz over one sampling length λc.
    pub rz: Option<Quantity>,
    /// Callout: long-wave cut-off λc (the sampling length).
    pub cutoff: Option<Quantity>,
    /// Callout: short-wave cut-off λs.
    pub short_cutoff: Option<Quantity>,
    /// Callout: the rule below λs, `"extend"` or `"stop"`.
    pub short_wavelength: Option<Spanned<String>>,
    /// Line traces (CSV `x,z`): one file or a list, relative to the scenario.
    pub profile: Option<Spanned<Files>>,
    /// The direction of the machining marks: `"isotropic"` (default), `"spiral"` (a turned
    /// face) or `"radial"` (docs/model.md §9.15).
    pub lay: Option<Spanned<String>>,
}

/// One file name or a list of them.
#[derive(Debug, serde::Deserialize)]
#[serde(untagged)]
pub(super) enum Files {
    One(String),
    Many(Vec<String>),
}

impl Files {
    /// The names, in order.
    pub fn names(&self) -> Vec<&str> {
        match self {
            Files::One(f) => vec![f.as_str()],
            Files::Many(v) => v.iter().map(String::as_str).collect(),
        }
    }
}

/// `[fluid]`: Newtonian fluid and the pressure across the seal; its viscosity one of
/// `viscosity` (constant), `library` (a fluid of [`crate::fluid::library`]) or the inline
/// ASTM D341 law `viscosity_40c`, `viscosity_100c` with `density` (and optional
/// `thermal_expansion`); which combinations are allowed is checked in validation.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFluid {
    pub viscosity: Option<Quantity>,
    pub library: Option<Spanned<String>>,
    pub viscosity_40c: Option<Quantity>,
    pub viscosity_100c: Option<Quantity>,
    pub density: Option<Quantity>,
    pub thermal_expansion: Option<Quantity>,
    /// ΔP (for a gas: with the outlet at `outlet_pressure`, default 1 atm).
    pub pressure_difference: Option<Quantity>,
    /// A gas of [`crate::gas::library`] or `"custom"` (docs/model.md §3.8).
    pub gas: Option<Spanned<String>>,
    /// Custom gas: molar mass, hard-sphere diameter, Sutherland μ0, T0, S.
    pub molar_mass: Option<Quantity>,
    pub molecular_diameter: Option<Quantity>,
    pub sutherland_viscosity: Option<Quantity>,
    pub sutherland_temperature: Option<Quantity>,
    pub sutherland_constant: Option<Quantity>,
    /// Gas: absolute pressures on the pressurised and the outlet side.
    pub inlet_pressure: Option<Quantity>,
    pub outlet_pressure: Option<Quantity>,
    /// Gas: `false` for the continuum law through the constrictions (default: rarefied).
    pub rarefaction: Option<Spanned<bool>>,
    /// ASTM D471 equilibrium volume change ΔV/V0 of the compound in this fluid.
    pub volume_swell: Option<Quantity>,
}

/// `[seal]`: a flat seal (`nominal_pressure`, `width`, `length`) or an O-ring
/// (`cross_section`, `mean_diameter`, `squeeze`, optional thermal strain; or, seated in a
/// `gland`, its ring and groove); which keys belong to which `kind` is checked in validation.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSeal {
    pub kind: Option<Spanned<String>>,
    pub nominal_pressure: Option<Quantity>,
    pub width: Option<Quantity>,
    pub length: Option<Quantity>,
    /// A flat gasket's compressed thickness: the exposed edge gas permeates through.
    pub thickness: Option<Quantity>,
    /// A bolted flat gasket's installed compression of its free thickness (docs/model.md §6).
    pub compression: Option<Quantity>,
    pub cross_section: Option<Quantity>,
    pub mean_diameter: Option<Quantity>,
    pub squeeze: Option<Quantity>,
    pub loading: Option<Spanned<String>>,
    pub housing_expansion: Option<Quantity>,
    pub installation_temperature: Option<Quantity>,
    /// The squeeze's ramp at installation (default 1 s).
    pub installation_time: Option<Quantity>,
    /// A groove-seated O-ring (docs/model.md §6.2): `"face"`, `"piston"` or `"rod"`, and its
    /// ring (`size`, or `cross_section` with `inner_diameter`) and groove.
    pub gland: Option<Spanned<String>>,
    pub size: Option<Spanned<String>>,
    pub inner_diameter: Option<Quantity>,
    pub groove_depth: Option<Quantity>,
    pub groove_depth_tolerance: Option<Quantity>,
    pub groove_width: Option<Quantity>,
    pub diametral_clearance: Option<Quantity>,
    /// A piston or rod gland's ISO 286 fit `HOLE/SHAFT` (`"H8/f7"`): the clearance range at
    /// the bore or rod diameter.
    pub fit: Option<Spanned<String>>,
    pub extrusion_gap: Option<Quantity>,
    pub bore_diameter: Option<Quantity>,
    pub rod_diameter: Option<Quantity>,
    pub groove_outer_diameter: Option<Quantity>,
    pub groove_inner_diameter: Option<Quantity>,
    /// A face gland's pressure side, `"inside"` or `"outside"` (the wall the ring must bear on).
    pub pressure_side: Option<Spanned<String>>,
    pub energisation_factor: Option<Quantity>,
    /// Back-up rings on the ring's low-pressure side: 0, 1 or 2 (docs/model.md §6.3).
    pub backup_rings: Option<Spanned<i64>>,
    /// The housing's material (`"steel"`, …), for its thermal expansion.
    pub housing: Option<Spanned<String>>,
}

/// `[environment]`: the temperature history (constant, a CSV table, plus cycles).
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawEnvironment {
    pub temperature: Option<Quantity>,
    pub history: Option<Spanned<String>>,
    pub daily_amplitude: Option<Quantity>,
    pub yearly_amplitude: Option<Quantity>,
    pub daily_pressure: Option<Quantity>,
    pub proof_pressure: Option<Quantity>,
    pub proof_duration: Option<Quantity>,
}

/// `[failure]`: any subset of the criteria.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawFailure {
    pub max_leak_rate: Option<Quantity>,
    pub max_leaked_volume: Option<Quantity>,
    pub reference_pressure: Option<Quantity>,
    pub reference_temperature: Option<Quantity>,
    pub min_retained_force: Option<Quantity>,
    pub retained_force_reference: Option<Quantity>,
    pub max_compression_set: Option<Quantity>,
    pub min_sealing_force: Option<Quantity>,
    pub min_contact_pressure: Option<Quantity>,
    pub gasket_factor: Option<Quantity>,
    pub lift_off: Option<Spanned<bool>>,
    pub extrusion: Option<Spanned<bool>>,
    pub lost_interference: Option<Spanned<bool>>,
    pub shutdown_temperature: Option<Quantity>,
    pub minimum_pressure_difference: Option<Quantity>,
    pub low_temperature: Option<Spanned<bool>>,
    pub low_temperature_margin: Option<Quantity>,
}

/// A scenario's `[ageing]`: each constant defaults to the material's `[material.ageing]`.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawScenarioAgeing {
    /// `false` switches the compound's ageing off (it is on whenever constants are known).
    pub enabled: Option<Spanned<bool>>,
    pub activation_energy: Option<Quantity>,
    pub rate: Option<Quantity>,
    pub reference_temperature: Option<Quantity>,
    pub crosslinking: Option<Quantity>,
}

/// `[numerical]`: grid, band, realisations and seed of the numerical level (docs/model.md §3.5).
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawNumerical {
    pub band: Option<Quantity>,
    pub pixels_per_wavelength: Option<Quantity>,
    pub realisations: Option<Quantity>,
    pub seed: Option<Quantity>,
}

/// `[simulation]`: the time grid and the fidelity of the life run.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSimulation {
    pub duration: Option<Quantity>,
    pub start: Option<Quantity>,
    pub points_per_decade: Option<Quantity>,
    pub tolerance: Option<Quantity>,
    pub fidelity: Option<Spanned<String>>,
    pub clogging_tolerance: Option<Quantity>,
}

/// `[contamination]`: particles in the fluid that clog the critical constrictions
/// (docs/model.md §7); which keys go together is checked in validation.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawContamination {
    pub number_concentration: Option<Quantity>,
    pub volume_fraction: Option<Quantity>,
    pub size_distribution: Option<Spanned<RawSizeDistribution>>,
    pub capture: Option<Spanned<String>>,
    pub reroute: Option<Spanned<bool>>,
}

/// `size_distribution = { kind = "...", ... }`: the keys of each kind are checked in
/// validation.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawSizeDistribution {
    pub kind: Spanned<String>,
    pub diameter: Option<Quantity>,
    pub median: Option<Quantity>,
    pub geometric_std: Option<Quantity>,
    pub scale: Option<Quantity>,
    pub shape: Option<Quantity>,
    pub file: Option<Spanned<String>>,
}

/// `[motion]`: the countersurface slides (a reciprocating seal, PY08 §8): `sliding_speed`
/// (constant) or a stroke cycle (`stroke` with `frequency`, or with `out_speed` and
/// `in_speed`); which keys go together is checked in validation.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawMotion {
    pub sliding_speed: Option<Quantity>,
    pub stroke: Option<Quantity>,
    pub frequency: Option<Quantity>,
    pub out_speed: Option<Quantity>,
    pub in_speed: Option<Quantity>,
    pub junction_position: Option<Quantity>,
    pub inlet_gradient_out: Option<Quantity>,
    pub inlet_gradient_in: Option<Quantity>,
    pub contact_profile: Option<Spanned<String>>,
}

/// `[model]`: optional settings of the critical-junction theory.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawModel {
    pub percolation_threshold: Option<Quantity>,
    pub shape_factor: Option<Quantity>,
    pub gamma: Option<Quantity>,
    /// `"persson"` (default) or `"corrected"` (docs/model.md §2).
    pub area: Option<Spanned<String>>,
}
