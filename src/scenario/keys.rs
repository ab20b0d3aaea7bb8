//! The key registry: every key of a scenario file (and of a material file, whose one table is
//! `[material]`) defined once, with its kind, default and meaning.
//!
//! A numeric key's entry holds the very `Field` the validator checks it with (dimension, SI
//! unit, range), so that the reference cannot disagree with the code. [`markdown`] renders the
//! registry as `docs/src/reference/keys.md` (`sealsim generate keys`); the tests check that the
//! registry names exactly the keys the raw TOML structs accept (table by table, from serde's own
//! field lists), that every literal default is what the validator assumes when the key is absent,
//! and that the committed reference is the rendered one.

use super::contamination as cont;
use super::field::{Bound, Field};
use super::gland;
use super::life;
use super::material as mat;
use super::motion;
use super::seal_kind;
use super::seal_spec;
use super::validate as val;
use crate::units::{Dimension, show};
use std::fmt::Write as _;

/// What a key takes.
#[derive(Debug, Clone, Copy)]
pub(super) enum Kind {
    /// A quantity checked by its [`Field`].
    Quantity(Field),
    /// A quantity whose range depends on the context: (context, field) pairs.
    Quantities(&'static [(&'static str, Field)]),
    /// `[lo, hi]`: two quantities of the field.
    QuantityPair(Field),
    /// An absolute temperature (`"23 C"`, `"296.15 K"`), within [`mat::TEMPERATURE_RANGE`].
    Temperature,
    /// `[lo, hi]`: two absolute temperatures.
    TemperaturePair,
    /// One of the words, or a quantity of the field.
    ChoiceOrQuantity(&'static [&'static str], Field),
    /// One of the words.
    Choice(&'static [&'static str]),
    /// A whole number in \[lo, hi\].
    Integer(i64, i64),
    /// A plain number within the bound.
    Real(Bound),
    /// A list of times (`["1 day", "1 year"]`), each > 0.
    Times,
    /// Free text.
    Text,
    /// A list of strings.
    Texts,
    /// `true` or `false`.
    Bool,
    /// A file path, relative to the file's directory.
    File,
    /// A file path or a list of them.
    Files,
    /// A table (its keys are the registry's table of that path).
    Table,
    /// A list of inline tables (the registry's table of that path).
    Tables,
    /// A table whose keys are named in the meaning (not a fixed set of fields).
    Map,
}

/// What an absent key means.
#[derive(Debug, Clone, Copy)]
// the conditions of `LiteralWhere` and `SameAs` are read by the tests, which check the defaults
#[cfg_attr(not(test), allow(dead_code))]
pub(super) enum Fallback {
    /// The key must be given (under the condition, "" for always).
    Required(&'static str),
    /// Optional; absent it does nothing, or what the text says ("" for nothing to say).
    Absent(&'static str),
    /// Absent, the key is as if written `key = VALUE` (the TOML text), where the note says
    /// ("" everywhere the key is allowed). Checked by the tests.
    Literal(&'static str, &'static str),
    /// [`Fallback::Literal`] where the key named last is given (e.g. `seal.gland`); elsewhere
    /// what the note says. Checked by the tests where that key is given.
    LiteralWhere(&'static str, &'static str, &'static str),
    /// The value of the key named first (dotted) where that key is given, as the text says;
    /// checked by the tests where it is given.
    SameAs(&'static str, &'static str),
    /// The default depends on other keys or the compound: the sentence says how (not checked
    /// as a literal).
    Derived(&'static str),
}

/// One key.
#[derive(Debug, Clone, Copy)]
pub(super) struct Key {
    /// The key's name in its table.
    pub name: &'static str,
    pub kind: Kind,
    pub default: Fallback,
    /// Its meaning, in a line (Markdown).
    pub doc: &'static str,
}

/// One TOML table and its keys.
#[derive(Debug, Clone, Copy)]
pub(super) struct Table {
    /// Dotted path as errors print it ("" for the top level; `[i]` for an entry of a list,
    /// `CLASS` for a key chosen by the user).
    pub path: &'static str,
    /// What the table is and how its keys go together (Markdown).
    pub prose: &'static str,
    pub keys: &'static [Key],
}

impl Table {
    /// The dotted name of `key` in this table, as errors print it.
    #[cfg(test)]
    pub(super) fn dotted(&self, key: &Key) -> String {
        if self.path.is_empty() {
            key.name.to_owned()
        } else {
            format!("{}.{}", self.path, key.name)
        }
    }
}

const fn key(name: &'static str, kind: Kind, default: Fallback, doc: &'static str) -> Key {
    Key {
        name,
        kind,
        default,
        doc,
    }
}

use Fallback::{Absent, Derived, Literal, LiteralWhere, Required, SameAs};
use Kind::{
    Bool, Choice, ChoiceOrQuantity, File, Files, Integer, Map, Quantities, Quantity, QuantityPair,
    Real, Table as Tbl, Tables, Temperature, TemperaturePair, Text, Texts, Times,
};

/// The library fluids (`fluid.library`); a test checks them against [`crate::fluid`].
pub(super) const FLUIDS: &[&str] = &[
    "water",
    "ethylene-glycol-water-50",
    "iso-vg-32",
    "iso-vg-46",
    "iso-vg-68",
    "iso-vg-100",
];
/// The gases (`fluid.gas`): the library's and `"custom"`; a test checks them against
/// [`crate::gas`].
pub(super) const GASES: &[&str] = &[
    "helium",
    "hydrogen",
    "nitrogen",
    "air",
    "argon",
    "carbon-dioxide",
    "methane",
    "oxygen",
    "custom",
];
/// The housings (`seal.housing`); a test checks them against [`crate::gland::Housing`].
pub(super) const HOUSINGS: &[&str] = &[
    "steel",
    "stainless",
    "aluminium",
    "aluminum",
    "brass",
    "bronze",
    "cast-iron",
    "titanium",
];
/// The fidelity levels and aliases (`simulation.fidelity`); a test checks them against
/// [`crate::leak::Fidelity`].
pub(super) const FIDELITIES: &[&str] = &[
    "rule-of-thumb",
    "critical-junction",
    "table",
    "exact",
    "effective-medium",
    "numerical",
];
/// The ageing media (`material.ageing.medium`); a test checks them against
/// [`crate::material::AgeingMedium`].
pub(super) const MEDIA: &[&str] = &["air", "mineral-oil", "water", "water-glycol"];
/// The compatibility ratings (`material.compatibility.CLASS.rating`).
pub(super) const RATINGS: &[&str] = &["A", "B", "X"];

/// The top level of a scenario file.
const TOP: &[Key] = &[
    key(
        "name",
        Text,
        Derived("the file name without extension"),
        "label of the scenario",
    ),
    key("material", Tbl, Required(""), "the rubber compound"),
    key(
        "surface",
        Tbl,
        Required(""),
        "the roughness of the countersurface",
    ),
    key(
        "groove_surface",
        Tbl,
        Absent("the counterface's spectrum"),
        "a groove-seated O-ring's groove bottom roughness (docs/model.md §6.3)",
    ),
    key(
        "rubber_surface",
        Tbl,
        Absent("a smooth rubber"),
        "the rubber's own roughness, added to the countersurface's (docs/model.md §2.2)",
    ),
    key(
        "fluid",
        Tbl,
        Required(""),
        "the sealed fluid and the pressure across the seal",
    ),
    key("seal", Tbl, Required(""), "the seal's geometry and loading"),
    key(
        "model",
        Tbl,
        Absent("the theory's defaults"),
        "settings of the critical-junction theory",
    ),
    key(
        "environment",
        Tbl,
        Absent("constant at the shift's reference temperature, or 23 °C"),
        "the temperature and pressure history of a life run",
    ),
    key(
        "failure",
        Tbl,
        Absent("no criterion but the default checks"),
        "the end-of-life criteria",
    ),
    key(
        "ageing",
        Tbl,
        Absent("the compound's own ageing constants, if any"),
        "chemical ageing (docs/model.md §6.5)",
    ),
    key(
        "simulation",
        Tbl,
        Absent("the defaults of its keys"),
        "the time grid and fidelity of a life run",
    ),
    key(
        "contamination",
        Tbl,
        Absent("clean fluid"),
        "particles that clog the critical constrictions (docs/model.md §7)",
    ),
    key(
        "numerical",
        Tbl,
        Absent("the defaults of its keys"),
        "settings of the numerical level (docs/model.md §3.5)",
    ),
    key(
        "motion",
        Tbl,
        Absent("a static seal"),
        "the countersurface slides (a reciprocating seal, PY08 §8)",
    ),
];

const MATERIAL: &[Key] = &[
    key(
        "library",
        Text,
        Absent(""),
        "id of a library compound (`sealsim materials list`); no other key with it but \
         `asperity_modulus`",
    ),
    key(
        "file",
        File,
        Absent(""),
        "a material file (e.g. `sealsim fit-prony` output), relative to the scenario; no other \
         key with it but `asperity_modulus`; not with `library`",
    ),
    key(
        "name",
        Text,
        SameAs(
            "name",
            "the scenario's name (a material file: its file stem)",
        ),
        "label of the material",
    ),
    key(
        "status",
        Choice(&["published", "illustrative"]),
        Absent("a user material; required in library files, refused inline"),
        "what the data claim: every number published, or illustrative",
    ),
    key(
        "poisson_ratio",
        Quantity(mat::POISSON_RATIO),
        Required(""),
        "Poisson ratio ν",
    ),
    key(
        "youngs_modulus",
        Quantity(mat::YOUNGS_MODULUS),
        Required("elastic form"),
        "Young's modulus E of an elastic rubber",
    ),
    key(
        "long_term_modulus",
        Quantity(mat::LONG_TERM_MODULUS),
        Required("viscoelastic form"),
        "relaxed modulus E∞ of the Prony series (> 0 in a scenario)",
    ),
    key(
        "prony",
        Tables,
        Absent("no relaxation"),
        "Prony terms `[{ modulus = \"6 MPa\", tau = \"1000 h\" }, …]`: E(t) = E∞ + Σ E_i e^(−t/τ_i), \
         τ_i at the shift's reference temperature; needs `long_term_modulus`",
    ),
    key(
        "glass_transition",
        Temperature,
        Absent(""),
        "glass transition temperature T_g",
    ),
    key(
        "thermal_expansion",
        Quantity(mat::THERMAL_EXPANSION),
        Absent("no thermal strain"),
        "linear thermal expansion coefficient (above T_g)",
    ),
    key(
        "glassy_thermal_expansion",
        Quantity(mat::GLASSY_THERMAL_EXPANSION),
        // not `SameAs`: absent, the material holds none and the strain uses `thermal_expansion`
        Derived("`thermal_expansion`"),
        "linear thermal expansion coefficient below `glass_transition` (docs/model.md §5.1)",
    ),
    key(
        "data_reduced_time",
        QuantityPair(mat::DATA_REDUCED_TIME),
        Absent(""),
        "`[lo, hi]`: the reduced-time window the series was fitted to; a run beyond hi warns \
         (docs/model.md §9.13)",
    ),
    key(
        "data_temperature",
        TemperaturePair,
        Absent(""),
        "`[lo, hi]`: the temperature window of the material's data; a run outside it warns",
    ),
    key(
        "shift",
        Tbl,
        Absent("no temperature dependence"),
        "time–temperature superposition",
    ),
    key(
        "ageing",
        Tbl,
        Absent("no ageing constants"),
        "two-network chemical ageing constants (docs/model.md §6.5)",
    ),
    key(
        "compatibility",
        Map,
        Absent("no rating"),
        "fluid class (`mineral-oil`, `water`, `hot-water`, `water-glycol`) → `{ rating = \"A\", \
         source = \"…\" }` (docs/model.md §6.8)",
    ),
    key(
        "class",
        Choice(CLASSES),
        Absent(
            "a library compound's class comes from its id; another material has none, and a \
             gas run then needs the gas's figure in `[material.permeation]`",
        ),
        "the compound class whose data kept by class apply: gas permeation (docs/model.md \
         §13.4; sourced figures or stated NOT SOURCED bounds). Not with `library` or `file`",
    ),
    key(
        "bands",
        Map,
        Absent("no band stated"),
        "figure key (`\"ageing.activation_energy\"`) → `{ min = …, max = …, source = \"…\" }`: \
         the band a study draws with `\"band\"` (docs/model.md §5.4)",
    ),
    key(
        "permeation",
        Map,
        Absent("the class's figures"),
        "gas (`helium`, `hydrogen`, `nitrogen`, `oxygen`, `air`, `carbon-dioxide`, `methane`, \
         `argon`, or `custom` for a custom gas) → `{ permeability = \"5 barrer\", diffusivity \
         = \"3e-10 m^2/s\", source = \"…\" }`: the compound's own figure at 23 °C, used \
         instead of its class's (docs/model.md §13.4); allowed next to `library` and `file`",
    ),
    key(
        "provenance",
        Map,
        Absent("required in library files"),
        "parameter (`poisson_ratio`, `youngs_modulus`, `long_term_modulus`, `prony`, `shift`, \
         `glass_transition`, `thermal_expansion`, `glassy_thermal_expansion`, `ageing`, and \
         the data windows) → a string saying where its value comes from",
    ),
    key(
        "asperity_modulus",
        ChoiceOrQuantity(
            &["follow", "relaxed", "instantaneous"],
            mat::ASPERITY_MODULUS,
        ),
        Literal("\"follow\"", ""),
        "scenario option (refused in material files): the modulus the asperity contact sees — \
         the bulk's own response (`follow`), E∞ (`relaxed`, PY08's choice), E0 \
         (`instantaneous`, a bound) or a fixed modulus (docs/model.md §6.1)",
    ),
];

const PRONY: &[Key] = &[
    key(
        "modulus",
        Quantity(mat::TERM_MODULUS),
        Required(""),
        "E_i, the term's modulus",
    ),
    key(
        "tau",
        Quantity(mat::TERM_TAU),
        Required(""),
        "τ_i, its relaxation time at the shift's reference temperature",
    ),
];

const SHIFT: &[Key] = &[
    key(
        "kind",
        Choice(&["wlf", "arrhenius"]),
        Required(""),
        "`wlf`: log10 a_T = −C1 (T − T_ref)/(C2 + T − T_ref), frozen at T ≤ T_ref − C2; \
         `arrhenius`: ln a_T = (Ea/R)(1/T − 1/T_ref)",
    ),
    key(
        "reference_temperature",
        Temperature,
        Required(""),
        "T_ref, at which the Prony τ_i hold",
    ),
    key("c1", Quantity(mat::WLF_C1), Required("wlf"), "WLF C1"),
    key(
        "c2",
        Quantity(mat::WLF_C2),
        Required("wlf"),
        "WLF C2, a temperature difference (`\"101.6 K\"`; `\"101.6 C\"` is the same)",
    ),
    key(
        "activation_energy",
        Quantity(mat::SHIFT_ACTIVATION_ENERGY),
        Required("arrhenius"),
        "Ea",
    ),
];

const MATERIAL_AGEING: &[Key] = &[
    key(
        "activation_energy",
        Quantity(mat::AGEING_ACTIVATION_ENERGY),
        Required(""),
        "Ea of the scission rate (at and below `reference_temperature` when \
         `activation_energy_above` is given)",
    ),
    key(
        "activation_energy_above",
        Quantity(mat::AGEING_ACTIVATION_ENERGY_ABOVE),
        SameAs(
            "material.ageing.activation_energy",
            "`activation_energy`: one Arrhenius law",
        ),
        "Ea above `reference_temperature`: a band [low, high] of Ea about a rating anchor takes \
         the low end below the anchor and the high end above it, the shorter life on both sides \
         (docs/model.md §6.5)",
    ),
    key(
        "rate",
        Quantity(mat::AGEING_RATE),
        Required(""),
        "scission rate k_ref at `reference_temperature`",
    ),
    key(
        "reference_temperature",
        Temperature,
        Required(""),
        "T_ref of `rate`",
    ),
    key(
        "crosslinking",
        Quantity(mat::AGEING_CROSSLINKING),
        Literal("1", ""),
        "r = k_x/k_s: the new network's rate over the scission rate (1: compression set = \
         1 − F/F0; 0: scission alone)",
    ),
    key(
        "property",
        Text,
        Required("in library files and files with a `status`; with `criterion`"),
        "what the constants were measured on",
    ),
    key(
        "criterion",
        Text,
        Required("as `property`"),
        "the end-of-life criterion of the data",
    ),
    key(
        "medium",
        Choice(MEDIA),
        Absent(""),
        "the medium the compound was aged in",
    ),
    key(
        "source",
        Text,
        Absent("every library file has one"),
        "where the activation energy comes from, in a line (`sealsim compare` prints it beside \
         each compound)",
    ),
];

/// The compound classes of `material.class` ([`crate::permeation::FAMILIES`]; a test checks
/// them against it).
pub(super) const CLASSES: &[&str] = &[
    "acm", "cr", "epdm", "ffkm", "fkm", "fvmq", "hnbr", "iir", "nbr", "vmq",
];

const PERMEATION: &[Key] = &[
    key(
        "permeability",
        Quantity(mat::PERMEABILITY),
        Required(""),
        "Π at 23 °C, in `barrer` (1e-10 cm³(STP)·cm/(cm²·s·cmHg)) or `mol/(m*s*Pa)`",
    ),
    key(
        "diffusivity",
        Quantity(mat::DIFFUSIVITY),
        Absent("the steady flow from installation (an upper bound)"),
        "D at 23 °C, for the build-up over the time lag w²/6D",
    ),
    key("source", Text, Absent(""), "where the figure comes from"),
];

const BANDS: &[Key] = &[
    key(
        "min",
        Quantity(mat::BAND_KEYS[0].1[0]),
        Required(""),
        "lower end of the figure's band, in its unit",
    ),
    key(
        "max",
        Quantity(mat::BAND_KEYS[0].1[1]),
        Required(""),
        "upper end, above `min`",
    ),
    key(
        "source",
        Text,
        Absent("required in a compound with a `status`"),
        "where the band comes from",
    ),
];

const COMPATIBILITY: &[Key] = &[
    key(
        "rating",
        Choice(RATINGS),
        Required(""),
        "A recommended, B limited, X not recommended",
    ),
    key("source", Text, Absent(""), "where the rating comes from"),
];

const SURFACE: &[Key] = &[
    key(
        "rms_roughness",
        Quantity(val::RMS_ROUGHNESS),
        Required("self-affine"),
        "h_rms over [q0, q1]",
    ),
    key(
        "hurst_exponent",
        Quantity(val::HURST_EXPONENT),
        Literal("0.8", "with a callout; required for the self-affine form"),
        "Hurst exponent H, C ∝ q^−2(1+H)",
    ),
    key(
        "q0",
        Quantity(val::Q0),
        Derived(
            "required (self-affine); `psd_file`: its first row; callout: 2π/λc; height map: from \
             its shorter side",
        ),
        "lower cut-off wavevector (magnification ζ = q/q0)",
    ),
    key(
        "q1",
        Quantity(val::Q1),
        Derived("required (self-affine); `psd_file`: its last row; callout: `short_wavelength`"),
        "upper cut-off wavevector",
    ),
    key(
        "rolloff",
        Quantity(val::ROLLOFF),
        Absent("no roll-off"),
        "roll-off q_r: C is flat below it (self-affine only; q0 < q_r < q1)",
    ),
    key(
        "psd_file",
        File,
        Absent(""),
        "CSV of the spectrum C(q) (README \"Tabulated spectrum\")",
    ),
    key(
        "height_map",
        File,
        Absent(""),
        "a measured surface: a CSV grid of heights or a Gwyddion `.gsf` file",
    ),
    key(
        "pixel_size",
        Quantity(val::PIXEL_SIZE),
        Required("with a CSV `height_map`"),
        "the grid's sample spacing (refused with `.gsf`)",
    ),
    key(
        "height_unit",
        Text,
        Required("with a CSV `height_map`"),
        "the length unit of the grid's heights, e.g. `\"um\"` (refused with `.gsf`)",
    ),
    key(
        "ra",
        Quantity(val::RA),
        Absent(""),
        "callout: arithmetic mean roughness Ra over λs … λc; Rq = √(π/2) Ra",
    ),
    key(
        "rq",
        Quantity(val::RQ),
        Absent(""),
        "callout: rms roughness Rq over λs … λc",
    ),
    key(
        "rz",
        Quantity(val::RZ),
        Absent(""),
        "callout: mean peak-to-valley height Rz over one λc (Rz ≈ 7.2 Ra at the defaults)",
    ),
    key(
        "cutoff",
        Quantity(val::CUTOFF),
        Literal("\"0.8 mm\"", "with a callout"),
        "callout: long-wave cut-off λc (sampling length); the spectrum starts at 2π/λc",
    ),
    key(
        "short_cutoff",
        Quantity(val::SHORT_CUTOFF),
        Literal("\"2.5 um\"", "with a callout"),
        "callout: short-wave cut-off λs (ISO 3274), shorter than `cutoff`",
    ),
    key(
        "short_wavelength",
        Choice(&["extend", "stop"]),
        Literal("\"extend\"", "with a callout"),
        "callout: below λs the power law continues to 10 nm (`extend`) or ends (`stop`); not \
         with `q1`",
    ),
    key(
        "profile",
        Files,
        Absent(""),
        "line traces (CSV `x,z`): one file or a list (docs/model.md §2.3)",
    ),
    key(
        "lay",
        Choice(&["isotropic", "spiral", "radial"]),
        Literal("\"isotropic\"", ""),
        "direction of the machining marks; `spiral` and `radial` warn that the channel along \
         the lay is not modelled (docs/model.md §9.15)",
    ),
];

const FLUID: &[Key] = &[
    key(
        "viscosity",
        Quantities(&[
            ("liquid", val::VISCOSITY),
            ("custom gas", val::GAS_VISCOSITY),
        ]),
        Required("a liquid: one of `viscosity`, `library`, `viscosity_40c`"),
        "dynamic viscosity η, the same at every temperature (a custom gas: its constant μ)",
    ),
    key(
        "library",
        Choice(FLUIDS),
        Absent(""),
        "a library liquid, its viscosity a law of the temperature (docs/model.md §3.7)",
    ),
    key(
        "viscosity_40c",
        Quantity(val::VISCOSITY_40C),
        Absent(""),
        "ASTM D341 law: kinematic viscosity ν at 40 °C (`\"46 cSt\"`)",
    ),
    key(
        "viscosity_100c",
        Quantity(val::VISCOSITY_100C),
        Required("with `viscosity_40c`"),
        "ASTM D341 law: ν at 100 °C, below ν40",
    ),
    key(
        "density",
        Quantity(val::DENSITY),
        Required("with `viscosity_40c`"),
        "ρ at 15 °C, for η = ρ ν",
    ),
    key(
        "thermal_expansion",
        Quantity(val::FLUID_EXPANSION),
        Literal("\"6.4e-4 1/K\"", "with `viscosity_40c`"),
        "α of ρ(T) = ρ15 (1 − α (T − 15 °C))",
    ),
    key(
        "pressure_difference",
        Quantity(val::PRESSURE_DIFFERENCE),
        Required("a liquid; a gas: or `inlet_pressure`"),
        "ΔP across the seal (a gas: with the outlet at `outlet_pressure`)",
    ),
    key(
        "gas",
        Choice(GASES),
        Absent("a liquid"),
        "a gas instead of a liquid (docs/model.md §3.9–§3.10); `custom` takes the keys below",
    ),
    key(
        "molar_mass",
        Quantity(val::MOLAR_MASS),
        Required("custom gas"),
        "custom gas: molar mass M (`\"28 g/mol\"`)",
    ),
    key(
        "molecular_diameter",
        Quantity(val::MOLECULAR_DIAMETER),
        Required("custom gas"),
        "custom gas: hard-sphere diameter d, for the mean free path",
    ),
    key(
        "sutherland_viscosity",
        Quantity(val::SUTHERLAND_VISCOSITY),
        Required("custom gas without `viscosity`; the three together"),
        "custom gas: μ0 of μ = μ0 (T/T0)^1.5 (T0 + S)/(T + S)",
    ),
    key(
        "sutherland_temperature",
        Temperature,
        Required("as `sutherland_viscosity`"),
        "custom gas: Sutherland T0",
    ),
    key(
        "sutherland_constant",
        Quantity(val::SUTHERLAND_CONSTANT),
        Required("as `sutherland_viscosity`"),
        "custom gas: Sutherland S",
    ),
    key(
        "inlet_pressure",
        Quantity(val::INLET_PRESSURE),
        Absent("`pressure_difference`"),
        "gas: absolute pressure P_a on the pressurised side; needs `outlet_pressure`",
    ),
    key(
        "outlet_pressure",
        Quantity(val::OUTLET_PRESSURE),
        Literal("\"1 atm\"", "a gas given `pressure_difference`"),
        "gas: absolute pressure P_b on the outlet side (vacuum: 0)",
    ),
    key(
        "rarefaction",
        Bool,
        Literal("true", "a gas"),
        "`false`: the continuum law through the constrictions, for comparison",
    ),
    key(
        "volume_swell",
        Quantity(val::VOLUME_SWELL),
        Literal("0", ""),
        "ASTM D471 equilibrium volume change ΔV/V0 of the compound in this fluid (`\"8 %\"`): \
         dimensions × (1 + ΔV/V0)^{1/3}, moduli × (1 + ΔV/V0)^{−1/3}; warned above +30 % \
         (docs/model.md §3.8)",
    ),
];

const SEAL: &[Key] = &[
    key(
        "kind",
        Choice(&seal_kind::KIND_NAMES),
        Literal("\"flat\"", ""),
        "a flat seal, or an O-ring (between plates, or seated in a `gland`)",
    ),
    key(
        "loading",
        Choice(&["displacement", "force"]),
        Literal("\"displacement\"", ""),
        "fixed squeeze (a groove: the force relaxes) or fixed load (a spring: the force stays)",
    ),
    key(
        "nominal_pressure",
        Quantity(seal_kind::NOMINAL_PRESSURE),
        Required("flat"),
        "flat: nominal squeezing pressure P0 at the end of installation",
    ),
    key(
        "width",
        Quantity(seal_kind::WIDTH),
        Required("flat"),
        "flat: L_x, along the flow",
    ),
    key(
        "length",
        Quantity(seal_kind::LENGTH),
        Required("flat"),
        "flat: L_y, across the flow",
    ),
    key(
        "thickness",
        Quantity(seal_kind::THICKNESS),
        Absent(
            "a liquid needs none; a gas run on a flat seal is refused without it; the shutdown \
             check then asks only that the compression stays positive, and the gasket cools at \
             once",
        ),
        "flat: compressed thickness t_c, the edge a gas permeates through (docs/model.md \
         §13.3); with `compression` the free thickness t_c/(1 − ε0) whose interference the \
         shutdown check compares with the roughness, and the cool-down t_c²/a (§8.2)",
    ),
    key(
        "compression",
        Quantity(seal_kind::COMPRESSION),
        Derived(
            "0.1 for a flat seal under displacement loading (assumed: the low end of vendors' \
             10–50 %, the conservative end; docs/model.md §6)",
        ),
        "flat, displacement loading: ε0, the installed compression of the free thickness; the \
         thermal strain changes it and the force with it, P = P0 ε(T)/ε0 (docs/model.md §6)",
    ),
    key(
        "cross_section",
        Quantity(seal_spec::CROSS_SECTION),
        Required("o-ring"),
        "O-ring: cord diameter d (in a gland: the free cord, with `inner_diameter`)",
    ),
    key(
        "mean_diameter",
        Quantity(seal_kind::MEAN_DIAMETER),
        Required("o-ring between plates"),
        "O-ring: mean diameter D; the sealing length is π D (an error with `gland`)",
    ),
    key(
        "squeeze",
        Quantity(seal_spec::SQUEEZE),
        Required("o-ring between plates; in a gland: or `groove_depth`"),
        "O-ring: compression / d at installation (Lindley's relations hold for 5–30 %, warned \
         outside)",
    ),
    key(
        "housing_expansion",
        Quantity(seal_spec::HOUSING_EXPANSION),
        Derived(
            "none (no thermal strain) for an O-ring between plates; steel's in a gland and for a \
             flat seal under displacement loading",
        ),
        "O-ring, or a flat seal under displacement loading (its flanges and bolts): the \
         housing's linear CTE, so that the squeeze follows the temperature (docs/model.md §6); \
         not with `housing`; refused under force loading",
    ),
    key(
        "housing",
        Choice(HOUSINGS),
        LiteralWhere(
            "\"steel\"",
            "in a gland and for a flat seal under displacement loading; none between plates",
            "seal.gland",
        ),
        "O-ring, or a flat seal under displacement loading: the housing's (flanges' and \
         bolts') material, for its CTE (docs/model.md §6.2); not with `housing_expansion`; \
         refused under force loading",
    ),
    key(
        "installation_temperature",
        Temperature,
        Derived(
            "the environment's temperature at t = 0; 23 °C in a gland; for a flat seal under \
             displacement loading the hotter of 23 °C and T(0)",
        ),
        "O-ring: T_install, the fitting temperature (the ring then settles to the environment over \
         its thermal time, docs/model.md §5.2) and the reference of the thermal strain; a flat \
         seal under displacement loading: the bolting temperature, the thermal strain's \
         reference only (docs/model.md §6); refused under force loading",
    ),
    key(
        "installation_time",
        Quantity(life::INSTALLATION_TIME),
        Literal("\"1 s\"", ""),
        "the squeeze's linear ramp, ending at t = 0 (`\"0 s\"`: a jump; docs/model.md §5.2)",
    ),
    key(
        "gland",
        Choice(&["face", "piston", "rod"]),
        Absent("a ring between plates"),
        "O-ring seated in a groove (docs/model.md §6.2)",
    ),
    key(
        "size",
        Text,
        Required("gland: or `cross_section` + `inner_diameter`"),
        "gland: the ring's AS568 size, `\"AS568-214\"` (`sealsim sizes` lists them)",
    ),
    key(
        "inner_diameter",
        Quantity(gland::INNER_DIAMETER),
        Required("gland without `size`"),
        "gland: the ring's free inside diameter",
    ),
    key(
        "groove_depth",
        Quantity(gland::GROOVE_DEPTH),
        Required("gland, unless `squeeze` is given"),
        "gland: the depth the cord is squeezed into (piston: bore to groove bottom; rod: rod to \
         groove bottom; face: groove depth, plus `extrusion_gap`)",
    ),
    key(
        "groove_depth_tolerance",
        Quantity(gland::GROOVE_DEPTH_TOLERANCE),
        Literal("\"0 m\"", "gland"),
        "gland: ± tolerance of `groove_depth`, for the squeeze range",
    ),
    key(
        "groove_width",
        Quantity(gland::GROOVE_WIDTH),
        Required("gland"),
        "gland: the groove's width w (gland fill π d′²/4 / (h w), warned above 90 %)",
    ),
    key(
        "diametral_clearance",
        Quantity(gland::DIAMETRAL_CLEARANCE),
        Required("piston, rod"),
        "gland: bore minus piston (housing bore minus rod); the extrusion gap is half of it",
    ),
    key(
        "fit",
        Text,
        Absent("the clearance as given"),
        "piston, rod: the ISO 286 fit `\"HOLE/SHAFT\"` of bore and piston (housing and rod), e.g. \
         `\"H8/f7\"` (IT5–IT11; H; d, e, f, g, h; to 500 mm): `diametral_clearance` defaults to \
         the fit's largest at the bore (rod) diameter and must lie within its range; a study's \
         `tolerances = \"fits\"` draws the clearance within it",
    ),
    key(
        "extrusion_gap",
        Quantity(gland::EXTRUSION_GAP),
        Literal("\"0 m\"", "face gland"),
        "face gland: the flange separation",
    ),
    key(
        "bore_diameter",
        Quantity(gland::BORE_DIAMETER),
        Required("piston"),
        "piston: the bore B; the ring's ID is stretched onto B − 2·`groove_depth`",
    ),
    key(
        "rod_diameter",
        Quantity(gland::ROD_DIAMETER),
        Required("rod"),
        "rod: the rod diameter, onto which the ring's ID is stretched",
    ),
    key(
        "groove_outer_diameter",
        Quantity(gland::GROOVE_OUTER_DIAMETER),
        Absent("no stretch"),
        "face, pressure inside: the groove's outer wall, the ring's OD is brought onto it; not \
         with `groove_inner_diameter`",
    ),
    key(
        "groove_inner_diameter",
        Quantity(gland::GROOVE_INNER_DIAMETER),
        Absent("no stretch"),
        "face, pressure outside (vacuum): the groove's inner wall, the ring's ID is brought \
         onto it",
    ),
    key(
        "pressure_side",
        Choice(&["inside", "outside"]),
        Absent("the side the wall key implies"),
        "face: where the pressure is; the ring must bear on the wall it is pushed onto (inside: \
         `groove_outer_diameter`, outside: `groove_inner_diameter`), else refused",
    ),
    key(
        "energisation_factor",
        Quantity(gland::ENERGISATION_FACTOR),
        Literal("1", "gland"),
        "k_e: the fluid pressure adds k_e ΔP to the contact pressure (docs/model.md §6.3)",
    ),
    key(
        "backup_rings",
        Integer(0, 2),
        Literal("0", "gland"),
        "back-up rings on the low-pressure side: 0, 1, or 2 for a pressure that may reverse \
         (docs/model.md §6.3)",
    ),
];

const MODEL: &[Key] = &[
    key(
        "percolation_threshold",
        Quantity(val::PERCOLATION_THRESHOLD),
        Literal("0.4", ""),
        "A/A0 at which the non-contact area percolates (PY08: 0.4; Dapp et al. 2012: 0.42)",
    ),
    key(
        "shape_factor",
        Quantity(val::SHAPE_FACTOR),
        Literal("1", ""),
        "α in Q̇ = (L_y/L_x) α u_c³ ΔP/(12η)",
    ),
    key(
        "gamma",
        Quantity(val::GAMMA),
        Literal("0.4", ""),
        "γ of the mean-separation kernel",
    ),
    key(
        "area",
        Choice(&["persson", "corrected"]),
        Literal("\"persson\"", ""),
        "the contact area A(ζ)/A0: `\"persson\"` (Persson 2001, κ = √(8/π) ≈ 1.60: the smaller \
         area, so the larger leak) or `\"corrected\"` (Wang & Müser 2017, κ ≈ 2.14, within 10 % \
         of the numerical level's area; docs/model.md §2, docs/src/validation.md)",
    ),
];

const ENVIRONMENT: &[Key] = &[
    key(
        "temperature",
        Temperature,
        SameAs(
            "material.shift.reference_temperature",
            "the material shift's reference temperature, or 23 °C without a shift",
        ),
        "constant temperature; not with `history`",
    ),
    key(
        "history",
        File,
        Absent(""),
        "CSV of the temperature, the fluid pressure or both against time (README \"Temperature \
         history\"; a `pressure` column is ΔP for a liquid, a gas's absolute inlet pressure; \
         docs/model.md §8.4); or a `sealsim run -o` history in any `--units`, whose \
         `time_<unit>` and `temperature_<unit>` columns are read",
    ),
    key(
        "daily_amplitude",
        Quantity(life::DAILY_AMPLITUDE),
        Absent("no daily cycle"),
        "amplitude of a sinusoidal daily cycle added to the temperature, maximum at 15:00",
    ),
    key(
        "yearly_amplitude",
        Quantity(life::YEARLY_AMPLITUDE),
        Absent("no yearly cycle"),
        "amplitude of a sinusoidal yearly cycle (365.25 d), maximum at noon on 21 July",
    ),
    key(
        "daily_pressure",
        Quantity(life::DAILY_PRESSURE),
        Absent("no pressure cycle"),
        "the fluid pressure from 21:00 to 09:00 each day (a nightly shutdown, e.g. \"0 bar\"; \
         ΔP for a liquid, a gas's absolute inlet pressure), the service's the rest of the day, \
         each change over 60 s (docs/model.md §8.4)",
    ),
    key(
        "proof_pressure",
        Quantity(life::PROOF_PRESSURE),
        Absent("no proof"),
        "a proof test before service: this pressure from the installation for \
         `proof_duration`, then the service's (extrusion and lift-off at it count; \
         docs/model.md §8.4)",
    ),
    key(
        "proof_duration",
        Quantity(life::PROOF_DURATION),
        Absent("required with `proof_pressure`"),
        "how long the proof pressure is held from the installation",
    ),
];

const FAILURE: &[Key] = &[
    key(
        "max_leak_rate",
        Quantity(life::MAX_LEAK_RATE),
        Absent(""),
        "the leak rate exceeds this (a gas: a throughput, `\"1e-9 mbar*L/s\"`, `\"1 sccm\"`, \
         compared with interface leak + permeation)",
    ),
    key(
        "max_leaked_volume",
        Quantity(life::MAX_LEAKED_VOLUME),
        Absent(""),
        "the cumulative leaked volume exceeds this (a gas: an amount, `\"1 mbar*L\"`, \
         `\"1e-6 mol\"`)",
    ),
    key(
        "reference_pressure",
        Quantity(life::REFERENCE_PRESSURE),
        Absent(""),
        "a gas: the pressure a volume or volume-flow criterion is counted at",
    ),
    key(
        "reference_temperature",
        Temperature,
        Derived("the gas temperature at installation"),
        "a gas: the temperature of that state (with `reference_pressure`)",
    ),
    key(
        "min_retained_force",
        Quantity(life::MIN_RETAINED_FORCE),
        Absent(""),
        "the sealing force falls below this fraction of its value at \
         `retained_force_reference`",
    ),
    key(
        "retained_force_reference",
        Quantity(life::RETAINED_FORCE_REFERENCE),
        Literal("\"30 min\"", ""),
        "the time after installation the retained force is referred to (ISO 3384; `\"0 s\"`: \
         the end of the installation)",
    ),
    key(
        "max_compression_set",
        Quantity(life::MAX_COMPRESSION_SET),
        Absent(""),
        "the compression set of the ageing model (ASTM D395) exceeds this",
    ),
    key(
        "min_sealing_force",
        Quantity(life::MIN_SEALING_FORCE),
        Absent(""),
        "the sealing force per unit length falls below this (absolute)",
    ),
    key(
        "min_contact_pressure",
        Quantity(life::MIN_CONTACT_PRESSURE),
        Absent(""),
        "the installed (squeeze) peak contact pressure falls below this",
    ),
    key(
        "gasket_factor",
        Quantity(life::GASKET_FACTOR),
        Absent(""),
        "m: the installed mean contact pressure falls below m·ΔP (ASME VIII Div. 1 App. 2; \
         docs/model.md §8)",
    ),
    key(
        "lift_off",
        Bool,
        Literal("true", ""),
        "ΔP reaches the peak contact pressure with k_e ΔP: the seal opens (docs/model.md §3.6)",
    ),
    key(
        "extrusion",
        Bool,
        Literal("true", ""),
        "a groove-seated ring's clearance exceeds the extrusion chart's limit (docs/model.md \
         §6.3, §9.12)",
    ),
    key(
        "lost_interference",
        Bool,
        Literal("true", ""),
        "an O-ring or a flat seal under displacement loading no longer closes the roughness at a \
         shutdown, or cannot hold ΔP_min there (docs/model.md §8.2)",
    ),
    key(
        "shutdown_temperature",
        Temperature,
        Derived("the lower of 23 °C and the run's coldest temperature"),
        "T_sd of the shutdown check; at most the run's hottest temperature; refused where the \
         check does not apply (force loading, or `lost_interference = false`)",
    ),
    key(
        "minimum_pressure_difference",
        Quantity(life::MINIMUM_PRESSURE_DIFFERENCE),
        Literal("\"0 bar\"", ""),
        "ΔP_min, the lowest pressure difference the seal must hold at a restart, on its \
         unenergised squeeze (p_sq > ΔP_min whatever k_e; at most the service ΔP; docs/model.md \
         §8.2); refused where the check does not apply (force loading, or \
         `lost_interference = false`)",
    ),
    key(
        "low_temperature",
        Bool,
        Literal("true", ""),
        "the rubber colder than its compound's T10 less `low_temperature_margin` (docs/model.md \
         §8.3); a compound without a T10 has no cold limit",
    ),
    key(
        "low_temperature_margin",
        Quantity(life::LOW_TEMPERATURE_MARGIN),
        LiteralWhere(
            "\"0 K\"",
            "with [motion]; \"5 K\" for a static seal (docs/model.md §8.3)",
            "motion",
        ),
        "how far below T10 the seal is still taken to hold (a temperature difference: \"9 F\" \
         = 5 K)",
    ),
];

const AGEING: &[Key] = &[
    key(
        "enabled",
        Bool,
        Literal("true", ""),
        "`false` switches the compound's ageing off (no constant may be given then)",
    ),
    key(
        "activation_energy",
        Quantity(life::AGEING_ACTIVATION_ENERGY),
        Derived("the material's"),
        "Ea of the scission rate",
    ),
    key(
        "rate",
        Quantity(life::AGEING_RATE),
        Derived("the material's"),
        "k_ref at `reference_temperature`",
    ),
    key(
        "reference_temperature",
        Temperature,
        Derived("the material's"),
        "T_ref of `rate`",
    ),
    key(
        "crosslinking",
        Quantity(life::AGEING_CROSSLINKING),
        Derived("the material's, else 1"),
        "r = k_x/k_s, the new network's rate over the scission rate",
    ),
];

const SIMULATION: &[Key] = &[
    key(
        "duration",
        Quantity(life::DURATION),
        Literal("\"30 years\"", ""),
        "length of the run (longer than `start`; at most 400 000 cycle steps)",
    ),
    key(
        "start",
        Quantity(life::START),
        Literal("\"1 s\"", ""),
        "first output time after installation",
    ),
    key(
        "points_per_decade",
        Quantity(life::POINTS_PER_DECADE),
        Literal("20", ""),
        "output points per decade of time (the history's rows only: the internal steps, the \
         volumes, states and failure times do not depend on it)",
    ),
    key(
        "tolerance",
        Quantity(life::TOLERANCE),
        Literal("1e-3", ""),
        "relative tolerance of the internal steps' error control: the leaked volume, the \
         located state changes and extremes (docs/model.md §10.1)",
    ),
    key(
        "fidelity",
        Choice(FIDELITIES),
        Literal("\"critical-junction\"", ""),
        "contact model (docs/model.md §4; `table` = `critical-junction`), unless `--fidelity` \
         is given",
    ),
    key(
        "clogging_tolerance",
        Quantity(cont::CLOGGING_TOLERANCE),
        Literal("1e-8", ""),
        "relative tolerance of the open fraction in the clogging ODE (with `[contamination]`)",
    ),
];

const CONTAMINATION: &[Key] = &[
    key(
        "number_concentration",
        Quantity(cont::NUMBER_CONCENTRATION),
        Required("or `volume_fraction`"),
        "particle number concentration n_p",
    ),
    key(
        "volume_fraction",
        Quantity(cont::VOLUME_FRACTION),
        Required("or `number_concentration`"),
        "particle volume fraction φ; n_p = φ / E[π d³/6]",
    ),
    key(
        "size_distribution",
        Tbl,
        Required(""),
        "inline table of the particle sizes, by `kind`",
    ),
    key(
        "capture",
        Choice(&["straining", "sieving"]),
        Literal("\"straining\"", ""),
        "capture law: `straining`, continuous in particle size (the constrictions of every \
         octave spread like P(u), depth filtration into the entry cake); `sieving`, its sharp \
         limit (u_c < d ≤ d_reach block a critical channel)",
    ),
    key(
        "reroute",
        Bool,
        Literal("true", ""),
        "a blocked channel detours through the next-narrowest constriction (`false`: it carries \
         nothing)",
    ),
];

const SIZE_DISTRIBUTION: &[Key] = &[
    key(
        "kind",
        Choice(&["monodisperse", "lognormal", "weibull", "table"]),
        Required(""),
        "the distribution (by number)",
    ),
    key(
        "diameter",
        Quantity(cont::DIAMETER),
        Required("monodisperse"),
        "the particles' diameter",
    ),
    key(
        "median",
        Quantity(cont::MEDIAN),
        Required("lognormal"),
        "median diameter",
    ),
    key(
        "geometric_std",
        Quantity(cont::GEOMETRIC_STD),
        Required("lognormal"),
        "geometric standard deviation σg (> 1)",
    ),
    key(
        "scale",
        Quantity(cont::SCALE),
        Required("weibull"),
        "scale of F = 1 − exp(−(d/scale)^shape)",
    ),
    key(
        "shape",
        Quantity(cont::SHAPE),
        Required("weibull"),
        "shape of the Weibull law",
    ),
    key(
        "file",
        File,
        Required("table"),
        "CSV of `d, F` rows: the cumulative fraction by number",
    ),
];

const NUMERICAL: &[Key] = &[
    key(
        "band",
        Quantity(val::NUMERICAL_BAND),
        Literal("32", ""),
        "wavevector band q1/q0 of the synthetic surfaces (the spectrum is cut to [q0, band·q0])",
    ),
    key(
        "pixels_per_wavelength",
        Quantity(val::NUMERICAL_PIXELS),
        Literal("8", ""),
        "pixels per shortest wavelength (grid n = band × this, at most 8192); whole",
    ),
    key(
        "realisations",
        Quantity(val::NUMERICAL_REALISATIONS),
        Literal("8", ""),
        "number of random surfaces averaged; whole",
    ),
    key(
        "seed",
        Quantity(val::NUMERICAL_SEED),
        Literal("1", ""),
        "seed of the first surface (surface k uses seed + k); whole",
    ),
];

const MOTION: &[Key] = &[
    key(
        "sliding_speed",
        Quantity(motion::SLIDING_SPEED),
        Absent(""),
        "constant sliding, dragging fluid out; not with `stroke`",
    ),
    key(
        "stroke",
        Quantity(motion::STROKE),
        Absent(""),
        "stroke length of a reciprocating cycle, with `frequency` or both speeds",
    ),
    key(
        "frequency",
        Quantity(motion::FREQUENCY),
        Absent(""),
        "strokes per second (out and in speed = 2·stroke·frequency)",
    ),
    key(
        "out_speed",
        Quantity(motion::OUT_SPEED),
        Absent(""),
        "out-stroke speed, with `in_speed`",
    ),
    key(
        "in_speed",
        Quantity(motion::IN_SPEED),
        Absent(""),
        "in-stroke speed, with `out_speed`",
    ),
    key(
        "junction_position",
        Quantity(motion::JUNCTION_POSITION),
        Literal("0.5", ""),
        "where the critical junction sits across the width (splits B_a/B_b; never changes Q̇)",
    ),
    key(
        "inlet_gradient_out",
        Quantity(motion::INLET_GRADIENT_OUT),
        Derived("an O-ring: estimated from its Hertz profile (warned)"),
        "steepest rise of the contact pressure on the pressurised side (docs/model.md §3.4.1); \
         with `inlet_gradient_in`",
    ),
    key(
        "inlet_gradient_in",
        Quantity(motion::INLET_GRADIENT_IN),
        Derived("as `inlet_gradient_out`"),
        "steepest rise on the air side",
    ),
    key(
        "contact_profile",
        File,
        Absent(""),
        "CSV of the contact pressure across the seal (`x,p` and a units row), giving both \
         gradients",
    ),
];

/// Every table of a scenario file, in reading order.
pub(super) const TABLES: &[Table] = &[
    Table {
        path: "",
        prose: "The top level: the scenario's `name` and its tables. Every table rejects keys \
                it does not know, naming them.",
        keys: TOP,
    },
    Table {
        path: "material",
        prose: "The rubber, against a rigid countersurface. Three forms: **elastic** \
                (`youngs_modulus`, `poisson_ratio`); **viscoelastic** (`long_term_modulus` with \
                an optional `prony` series, `poisson_ratio`, optionally `glass_transition`, \
                `thermal_expansion`, `[material.shift]`, `[material.ageing]`); **library** \
                (`library = \"ID\"` alone, or `file = \"PATH\"`, each with at most the scenario \
                option `asperity_modulus`). A material file (`materials/ID.toml`, `sealsim \
                fit-prony` output) is this one table: a library file needs `name`, `status` and \
                a provenance for every parameter; `library`, `file` and `asperity_modulus` are \
                refused there. An inline material must not have a `status`; one with E∞ = 0 is \
                an error in a scenario.",
        keys: MATERIAL,
    },
    Table {
        path: "material.prony[i]",
        prose: "One term of the Prony series; equal τ are added.",
        keys: PRONY,
    },
    Table {
        path: "material.shift",
        prose: "Time–temperature superposition, reduced time ξ = t/a_T: WLF (`c1`, `c2`) or \
                Arrhenius (`activation_energy`).",
        keys: SHIFT,
    },
    Table {
        path: "material.ageing",
        prose: "Two-network chemical ageing (docs/model.md §6.5): scission at k(T) = k_ref \
                exp(−(Ea/R)(1/T − 1/T_ref)), a new network formed in the deformed state at r·k.",
        keys: MATERIAL_AGEING,
    },
    Table {
        path: "material.compatibility.CLASS",
        prose: "The compound's rating in a fluid class (`mineral-oil`, `water`, `hot-water`, \
                `water-glycol`), an inline table.",
        keys: COMPATIBILITY,
    },
    Table {
        path: "material.permeation.GAS",
        prose: "The compound's own gas permeation figure for one gas (an inline table), used \
                instead of its class's; E_P and E_D are the table's for that gas (docs/model.md \
                §13.4).",
        keys: PERMEATION,
    },
    Table {
        path: "material.bands.KEY",
        prose: "The uncertainty band of one of the compound's figures (an inline table; KEY \
                `\"ageing.activation_energy\"`, the one `sealsim materials new` writes): a \
                study draws it uniformly with `\"ageing.activation_energy\" = \"band\"` \
                (docs/model.md §5.4).",
        keys: BANDS,
    },
    Table {
        path: "surface",
        prose: "The roughness power spectrum C(q) of the countersurface, given by **one** of: \
                the self-affine parameters (`rms_roughness`, `hurst_exponent`, `q0`, `q1`, \
                optional `rolloff`); a drawing **callout** (`ra`, `rq` or `rz`, with optional \
                `cutoff`, `short_cutoff`, `hurst_exponent`, `q0` and `short_wavelength` or \
                `q1`; docs/model.md §2.1); `psd_file` (optional `q0`, `q1` inside its band); \
                `height_map` (with `pixel_size`, `height_unit` for a CSV grid); or `profile` \
                line traces. `[groove_surface]` (a groove-seated ring's groove bottom; absent: \
                the counterface's spectrum) and `[rubber_surface]` (the rubber's own roughness, \
                added to C; absent: smooth) take the same keys but `height_map`, messages \
                naming `groove_surface.KEY` and `rubber_surface.KEY`.",
        keys: SURFACE,
    },
    Table {
        path: "fluid",
        prose: "A Newtonian liquid — its viscosity one of a constant `viscosity`, a `library` \
                fluid or the ASTM D341 law `viscosity_40c` + `viscosity_100c` + `density` — or \
                a `gas` (an isothermal ideal gas whose constrictions rarefy at their Knudsen \
                number; docs/model.md §3.9–§3.10). Liquid keys are refused with a gas and gas \
                keys with a liquid; `[motion]` and `[contamination]` are refused with a gas.",
        keys: FLUID,
    },
    Table {
        path: "seal",
        prose: "A flat seal with uniform nominal pressure over `width` × `length` (`kind = \
                \"flat\"`), or an O-ring (`kind = \"o-ring\"`) squeezed between flat faces or \
                seated in a groove (`gland`, with its ring and groove: docs/model.md §6.2). \
                Flat-seal keys are errors in an O-ring table and vice versa. With `gland` the \
                thermal strain is on by default (housing `\"steel\"`, installed at 23 °C) and \
                needs the material's `thermal_expansion`.",
        keys: SEAL,
    },
    Table {
        path: "model",
        prose: "Settings of the contact theory of the analytic levels (critical junction, \
                effective medium): the percolation threshold, the leak's shape factor, the γ of \
                the mean-separation kernel and the contact-area relation.",
        keys: MODEL,
    },
    Table {
        path: "environment",
        prose: "The temperature history of `sealsim run`: constant or a CSV table, plus \
                sinusoidal cycles (t = 0, the installation, is midnight of 1 January). The \
                cycles must not take the temperature to 0 K. The fluid pressure against time \
                (docs/model.md §8.4): the CSV's `pressure` column, a daily cycle to \
                `daily_pressure` and a proof before service; ΔP for a liquid, a gas's absolute \
                inlet pressure.",
        keys: ENVIRONMENT,
    },
    Table {
        path: "failure",
        prose: "Any subset of the criteria; the first event wins, located in time between \
                output points. Without any of the leak, force or set criteria the run warns \
                that the seal can only survive.",
        keys: FAILURE,
    },
    Table {
        path: "ageing",
        prose: "The two-network ageing of the run (docs/model.md §6.5). A compound with ageing \
                constants ages by default; each key defaults to the material's \
                `[material.ageing]`, and a key neither gives is an error.",
        keys: AGEING,
    },
    Table {
        path: "simulation",
        prose: "The output grid of `sealsim run`: the installation row at t = 0, then \
                log-uniform times from `start` to `duration`; the tolerance of the internal \
                steps, which the output grid only samples; and the contact model's fidelity.",
        keys: SIMULATION,
    },
    Table {
        path: "contamination",
        prose: "Particles in the fluid that clog the critical constrictions (docs/model.md §7); \
                exactly one of `number_concentration` and `volume_fraction`.",
        keys: CONTAMINATION,
    },
    Table {
        path: "contamination.size_distribution",
        prose: "`size_distribution = { kind = \"…\", … }`: the keys of its `kind`.",
        keys: SIZE_DISTRIBUTION,
    },
    Table {
        path: "numerical",
        prose: "The numerical level (docs/model.md §3.5), used at `fidelity = \"numerical\"` and \
                by `sealsim tradeoff`.",
        keys: NUMERICAL,
    },
    Table {
        path: "motion",
        prose: "The countersurface slides past the seal (PY08 §8): constant `sliding_speed`, or \
                a stroke cycle (`stroke` with `frequency`, or with `out_speed` and `in_speed`).",
        keys: MOTION,
    },
];

/// The design of a study (`design`); a test checks them against
/// [`crate::study::design::Design`].
pub(super) const DESIGNS: &[&str] = &["grid", "monte-carlo", "latin-hypercube"];

const STUDY: &[Key] = &[
    key(
        "name",
        Text,
        Derived("the file name without extension"),
        "label of the study",
    ),
    key(
        "base",
        File,
        Required(""),
        "the base scenario, relative to the study file",
    ),
    key(
        "design",
        Choice(DESIGNS),
        Required(""),
        "every combination of the inputs' levels or lists (`grid`), random samples \
         (`monte-carlo`), or stratified ones (`latin-hypercube`)",
    ),
    key(
        "samples",
        Integer(1, 10_000_000),
        Required("monte-carlo, latin-hypercube; refused for a grid"),
        "number of cases",
    ),
    key(
        "levels",
        Integer(1, 1000),
        Literal("3", ""),
        "a grid's levels of a continuous input",
    ),
    key(
        "seed",
        Integer(0, i64::MAX),
        Literal("0", ""),
        "seed of the sampling",
    ),
    key(
        "confidence",
        Real(Bound::Open(0.5, 1.0)),
        Literal("0.95", ""),
        "two-sided confidence of the bands and bounds",
    ),
    key(
        "report_times",
        Times,
        Literal("[\"1 day\", \"1 year\", \"10 years\"]", ""),
        "the times of the per-case leak rates",
    ),
    key(
        "run_after_failure",
        Bool,
        Literal("false", ""),
        "`true`: a case runs its whole duration; `false`: it ends at its failure",
    ),
    key(
        "correlations",
        Tables,
        Absent("independent inputs"),
        "rank correlations between inputs (Monte Carlo only; a Gaussian copula)",
    ),
    key(
        "tolerances",
        Choice(&["fits"]),
        Absent("only the `[vary]` inputs"),
        "`\"fits\"`: every dimension the base gives a tolerance for is drawn too — the ring \
         within its size's AS568 tolerance (with `seal.size`), each `seal.X` within \
         `seal.X_tolerance` (±3σ normal)",
    ),
    key(
        "vary",
        Map,
        Required(""),
        "scenario key path (`\"seal.squeeze\"`) → its distribution (below)",
    ),
];

const CORRELATION: &[Key] = &[
    key(
        "inputs",
        Texts,
        Required(""),
        "the two `vary` keys, `[\"a\", \"b\"]`",
    ),
    key(
        "spearman",
        Real(Bound::Open(-1.0, 1.0)),
        Required(""),
        "their Spearman rank correlation",
    ),
];

/// The keys of a study file (`sealsim study`, docs/model.md §14.1).
pub(super) const STUDY_TABLES: &[Table] = &[
    Table {
        path: "",
        prose: "A study runs its base scenario with the `[vary]` inputs sampled (docs/model.md \
                §14.1). Each input is addressed by its scenario key path and written into the \
                base scenario in the unit of its first location parameter, so that a case obeys \
                the rules and defaults of a scenario file; setting `material.library` or \
                `material.file` replaces the compound. An entry of `[vary]` is an inline table \
                `{ distribution = \"…\", … }` — `uniform`, `log-uniform` (`min`, `max`), \
                `triangular` (`min`, `mode`, `max`), `normal` (`mean`, `std`, optional `min`, \
                `max`), `lognormal` (`median`, `geometric_std`, optional `min`, `max`), `range`, \
                `log-range` (`from`, `to`, `count`), `values` (`values = [...]`, no \
                `distribution` needed), `tolerance` (`tolerance = \"±0.08 mm\"` or \
                `\"scenario\"`, optional `nominal`, default the base's value, and `shape`, \
                `\"normal\"` (±3σ, the default) or `\"uniform\"`) — or the shorthand \
                `\"±0.05 mm\"`, a tolerance band about the base's value, or `\"band\"`, the base \
                compound's own band of that figure (`[material.bands]`) drawn uniformly. \
                `{ tolerance = \"size\" }` on `seal.cross_section` or `seal.inner_diameter` \
                draws the ring within its case's `seal.size` tolerance (a fraction z of the AS568 \
                ±, so that it follows a varied size). A word input (`seal.size`, \
                `material.library`) gets its B10 per value in the summary.",
        keys: STUDY,
    },
    Table {
        path: "correlations[i]",
        prose: "One rank correlation: `correlations = [{ inputs = [\"a\", \"b\"], spearman = \
                0.5 }]`.",
        keys: CORRELATION,
    },
];

/// The registry's table at `path`.
#[cfg(test)]
pub(super) fn table(path: &str) -> Option<&'static Table> {
    TABLES.iter().find(|t| t.path == path)
}

/// The values a field accepts, as the messages state them.
fn range(field: &Field) -> String {
    bound_text(field.bound(), field.unit())
}

/// `bound` with `unit` ("" for none).
fn bound_text(bound: Bound, unit: &str) -> String {
    let (open, lo, hi, close) = match bound {
        Bound::Open(lo, hi) => ("(", lo, hi, ")"),
        Bound::Closed(lo, hi) | Bound::Range(lo, hi) => ("[", lo, hi, "]"),
    };
    let body = format!("{open}{}, {}{close}", show(lo), show(hi));
    if unit.is_empty() {
        body
    } else {
        format!("{body} {unit}")
    }
}

/// The unit column: the SI unit of a quantity, else what the key takes.
fn unit_column(kind: &Kind) -> String {
    let si = |f: &Field| {
        if f.dimension() == Dimension::DIMENSIONLESS {
            "1".to_owned()
        } else {
            f.unit().to_owned()
        }
    };
    match kind {
        Quantity(f) | QuantityPair(f) => si(f),
        Quantities(fields) => fields.first().map_or(String::new(), |(_, f)| si(f)),
        ChoiceOrQuantity(_, f) => format!("string or {}", si(f)),
        Temperature | TemperaturePair => "K (absolute)".into(),
        Choice(_) | Text => "string".into(),
        Texts => "list of strings".into(),
        Integer(..) => "integer".into(),
        Real(_) => "1".into(),
        Times => "s (list)".into(),
        Bool => "boolean".into(),
        File => "file path".into(),
        Files => "file path(s)".into(),
        Tbl => "table".into(),
        Tables => "list of tables".into(),
        Map => "table".into(),
    }
}

/// The range column.
fn range_column(kind: &Kind) -> String {
    let words = |w: &[&str]| {
        w.iter()
            .map(|w| format!("`\"{w}\"`"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let (lo, hi) = mat::TEMPERATURE_RANGE;
    match kind {
        Quantity(f) | QuantityPair(f) => range(f),
        Quantities(fields) => fields
            .iter()
            .map(|(context, f)| format!("{context}: {}", range(f)))
            .collect::<Vec<_>>()
            .join("; "),
        ChoiceOrQuantity(w, f) => format!("{}, or {}", words(w), range(f)),
        Temperature | TemperaturePair => format!("[{}, {}] K", show(lo), show(hi)),
        Choice(w) => words(w),
        Integer(lo, hi) if *hi == i64::MAX => format!("≥ {lo}"),
        Integer(lo, hi) => format!("{lo} … {hi}"),
        Real(bound) => bound_text(*bound, ""),
        Times => "each > 0".into(),
        Bool => "`true`, `false`".into(),
        Text | Texts | File | Files | Tbl | Tables | Map => "—".into(),
    }
}

/// The default column.
fn default_column(default: &Fallback) -> String {
    match default {
        Required("") => "required".into(),
        Required(when) => format!("required ({when})"),
        Absent("") => "—".into(),
        Absent(meaning) => format!("none: {meaning}"),
        Literal(value, "") => format!("`{value}`"),
        Literal(value, note) | LiteralWhere(value, note, _) => format!("`{value}` ({note})"),
        Derived(how) | SameAs(_, how) => (*how).to_owned(),
    }
}

/// A table cell: no line breaks, `|` escaped.
fn cell(text: &str) -> String {
    text.replace('|', "\\|").replace('\n', " ")
}

/// The key reference in Markdown (`docs/src/reference/keys.md`).
pub fn markdown() -> String {
    let mut out = String::new();
    out.push_str(
        "<!-- Generated from src/scenario/keys.rs by `sealsim generate keys -o \
         docs/src/reference/keys.md`; do not edit by hand. -->\n\n",
    );
    out.push_str("# Scenario file keys\n\n");
    out.push_str(INTRO);
    render(&mut out, TABLES, "");
    out.push_str(STUDY_INTRO);
    render(&mut out, STUDY_TABLES, "Study file: ");
    out
}

/// The tables in Markdown, each heading led by `lead`.
fn render(out: &mut String, tables: &[Table], lead: &str) {
    for table in tables {
        let heading = if table.path.is_empty() {
            "Top level".to_owned()
        } else if table.path.contains("[i]") || table.path.ends_with("CLASS") {
            // an entry of a list, or a table named by the user
            format!("`{}`", table.path)
        } else {
            format!("`[{}]`", table.path)
        };
        let _ = write!(out, "\n## {lead}{heading}\n\n{}\n\n", table.prose);
        out.push_str("| key | meaning | unit (SI) | default | range |\n");
        out.push_str("|---|---|---|---|---|\n");
        for key in table.keys {
            let _ = writeln!(
                out,
                "| `{}` | {} | {} | {} | {} |",
                key.name,
                cell(key.doc),
                cell(&unit_column(&key.kind)),
                cell(&default_column(&key.default)),
                cell(&range_column(&key.kind)),
            );
        }
    }
}

/// The introduction of the study files' part.
const STUDY_INTRO: &str = "\n# Study file keys\n\nThe keys of a study file (`sealsim study`); \
                           defaults are checked as the scenario's are.\n";

/// The reference's introduction: how values are written.
const INTRO: &str = "\
Every key of a scenario file, table by table; a material file (`materials/ID.toml`, the output \
of `sealsim fit-prony`) is the one table `[material]`. Each key's unit, default and range are \
those the validator checks with: this page is generated from the same definitions. Every table \
rejects keys it does not know; an error names the file, the line and the key \
(`scenarios/x.toml:7: surface.hurst_exponent: must lie strictly between 0 and 1, got 1.2`).

**Values.** A dimensional key takes a quantity string `\"<number> <unit>\"` (the space is \
optional): `\"10 MPa\"`, `\"2 um\"`, `\"7.8e9 1/m\"`, `\"1e-3 Pa*s\"`. Its unit must have the \
key's dimension (`\"10 m\"` for a pressure is an error). A bare TOML number is accepted for a \
dimensionless key (unit column `1`; `\"25 %\"` also works) and, as `0`, for any key; any other \
bare number for a dimensional key is refused with the units it could mean (`1e7` for a modulus: \
write `\"1e7 bar\"`, `\"1e7 MPa\"` or `\"1e7 psi\"`). An absolute temperature always needs its unit \
(`\"100 C\"`, `\"373.15 K\"`, `\"212 F\"`): a bare number is refused, since \"100\" could be \
either. The range column gives the accepted values in SI units after conversion: `(a, b)` \
excludes its ends, `[a, b]` includes them (for a physical quantity: its plausible range, a \
value ≤ 0 reported as \"must be positive\"). The units are listed in README.md, \"Quantities and \
units\"; the model behind each key in docs/model.md.

**Defaults.** `required` keys must be given (under the stated condition); a default in code \
font is the value the key takes when absent, exactly as if written so (a test checks each); \
other defaults depend on other keys or on the compound; `none: …` says what an absent optional \
key means.
";
