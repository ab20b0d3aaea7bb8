//! `[material]` tables and material files → [`Material`] in SI units, every error located.
//!
//! The keys are those of the material TOML schema in [`crate::material::compound`]. One table
//! is read in one of four ways:
//! * a **library file** (`materials/ID.toml`): `name`, `status` (`published` |
//!   `illustrative`) and a `[material.provenance]` string for every parameter present are
//!   required;
//! * a **material file** given by path (e.g. the output of `sealsim fit-prony`): with a
//!   `status`, the same rules as a library file (a claim about the data needs its sources);
//!   without one it is a [`Status::User`] material, provenance optional and `name` defaulting
//!   to the file stem;
//! * an **inline scenario material**: the same keys without `status` (it is
//!   [`Status::User`]); `name` defaults to the scenario's name, provenance is optional;
//! * a **scenario reference** `library = "ID"` (no other keys except the scenario option
//!   `asperity_modulus`): the library compound.
//!
//! Whenever provenance is given it is checked: every key names a parameter the material gives,
//! every value is a non-empty string.
//!
//! The static leak problem takes the relaxed modulus E∞ and the material's ν (docs/model.md §6,
//! default `relaxed`); a scenario material with E∞ = 0 is therefore an error.

use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::library;
use super::raw::{
    Quantity, RawAgeing, RawBand, RawCompatibility, RawMaterial, RawMaterialFile, RawPermeation,
    RawPronyTerm, RawQuantity, RawShift,
};
use crate::contact::Elastic;
use crate::material::compatibility::{Compatibility, FluidClass, Rating};
use crate::material::{
    Ageing, AgeingBasis, BALANCED_CROSSLINKING, FigureBand, Material, Prony, PronyTerm, Shift,
    Status,
};
use crate::permeation::UserPermeation;
use crate::simulate::AsperityModulus;
use crate::units::{self, Dimension, show};
use std::collections::BTreeMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

/// The parameters that carry a provenance, in schema order (the keys of
/// `[material.provenance]`).
pub const PARAMETERS: [&str; 9] = [
    "poisson_ratio",
    "youngs_modulus",
    "long_term_modulus",
    "prony",
    "shift",
    "glass_transition",
    "thermal_expansion",
    "glassy_thermal_expansion",
    "ageing",
];

/// Keys that may carry a provenance without requiring one: the windows of the data a series
/// was fitted to (`fit-prony` says where its data temperature came from).
pub const DATA_WINDOWS: [&str; 2] = ["data_reduced_time", "data_temperature"];

pub(super) const YOUNGS_MODULUS: Field = field(
    "material.youngs_modulus",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(1e3, 1e12),
);
pub(super) const POISSON_RATIO: Field = field(
    "material.poisson_ratio",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(0.0, 0.5),
);
pub(super) const LONG_TERM_MODULUS: Field = field(
    "material.long_term_modulus",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(0.0, 1e12),
);
/// `material.prony[i].modulus`; the key is replaced by the indexed one in errors.
pub(super) const TERM_MODULUS: Field = field(
    "material.prony.modulus",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(1e-6, 1e12),
);
/// `material.prony[i].tau`; the key is replaced by the indexed one in errors.
pub(super) const TERM_TAU: Field = field(
    "material.prony.tau",
    Dimension::TIME,
    "s",
    Bound::Range(1e-20, 1e20),
);
pub(super) const DATA_REDUCED_TIME: Field = field(
    "material.data_reduced_time",
    Dimension::TIME,
    "s",
    Bound::Range(1e-20, 1e30),
);
pub(super) const THERMAL_EXPANSION: Field = field(
    "material.thermal_expansion",
    Dimension::THERMAL_EXPANSION,
    "1/K",
    Bound::Range(1e-8, 1e-2),
);
/// The linear CTE below T_g (glassy); used by the O-ring thermal strain below `glass_transition`.
pub(super) const GLASSY_THERMAL_EXPANSION: Field = field(
    "material.glassy_thermal_expansion",
    Dimension::THERMAL_EXPANSION,
    "1/K",
    Bound::Range(1e-8, 1e-2),
);
pub(super) const WLF_C1: Field = field(
    "material.shift.c1",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(1e-3, 1e3),
);
/// A temperature difference (a bare number or `"101.6 K"`; `"101.6 C"` is the same).
pub(super) const WLF_C2: Field = field(
    "material.shift.c2",
    Dimension::TEMPERATURE,
    "K",
    Bound::Range(1e-3, 1e3),
);
pub(super) const SHIFT_ACTIVATION_ENERGY: Field = field(
    "material.shift.activation_energy",
    Dimension::MOLAR_ENERGY,
    "J/mol",
    Bound::Range(1.0, 1e6),
);
pub(super) const AGEING_ACTIVATION_ENERGY: Field = field(
    "material.ageing.activation_energy",
    Dimension::MOLAR_ENERGY,
    "J/mol",
    Bound::Range(1.0, 1e6),
);
/// The figures a compound may give a band for (`[material.bands]`), each with the fields its
/// `min` and `max` are read as; a study draws from the band with `"<key>" = "band"`.
pub(super) const BAND_KEYS: [(&str, [Field; 2]); 1] = [(
    "ageing.activation_energy",
    [
        field(
            "material.bands.KEY.min",
            Dimension::MOLAR_ENERGY,
            "J/mol",
            Bound::Range(1.0, 1e6),
        ),
        field(
            "material.bands.KEY.max",
            Dimension::MOLAR_ENERGY,
            "J/mol",
            Bound::Range(1.0, 1e6),
        ),
    ],
)];

pub(super) const AGEING_ACTIVATION_ENERGY_ABOVE: Field = field(
    "material.ageing.activation_energy_above",
    Dimension::MOLAR_ENERGY,
    "J/mol",
    Bound::Range(1.0, 1e6),
);
pub(super) const AGEING_RATE: Field = field(
    "material.ageing.rate",
    Dimension::FREQUENCY,
    "1/s",
    Bound::Range(1e-30, 1e3),
);
pub(super) const AGEING_CROSSLINKING: Field = field(
    "material.ageing.crosslinking",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(0.0, 10.0),
);
/// A gas permeability Π (`[material.permeation] GAS.permeability`): mol/(m·s·Pa), or
/// `barrer` (read apart: a volume-based unit, 1 barrer = 3.3464e-16 mol/(m·s·Pa)).
pub(super) const PERMEABILITY: Field = field(
    "material.permeation.GAS.permeability",
    Dimension::new(0, -1, 1, 0, 1),
    "mol/(m*s*Pa)",
    Bound::Range(1e-30, 1e-9),
);
/// A gas diffusivity D in the rubber (`[material.permeation] GAS.diffusivity`).
pub(super) const DIFFUSIVITY: Field = field(
    "material.permeation.GAS.diffusivity",
    Dimension::KINEMATIC_VISCOSITY,
    "m^2/s",
    Bound::Range(1e-20, 1e-4),
);
/// A fixed asperity modulus (`asperity_modulus = "3 MPa"`).
pub(super) const ASPERITY_MODULUS: Field = field(
    "material.asperity_modulus",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(1e3, 1e12),
);

/// Plausible range of an absolute temperature \[K\] (README "Ranges", docs/model.md §11.1).
pub(super) const TEMPERATURE_RANGE: (f64, f64) = (1.0, 1000.0);

/// Where a `[material]` table is read; decides which keys are required.
#[derive(Debug, Clone, Copy)]
enum Origin<'a> {
    /// A library file: `name`, `status` and complete provenance required.
    Library,
    /// A material file given by path: `status` optional (absent: a user material whose `name`
    /// defaults to `default_name`); with a status, complete provenance required.
    File { default_name: &'a str },
    /// Inline in a scenario: status `user`, provenance optional, `name` defaults to
    /// `default_name`.
    Inline { default_name: &'a str },
}

/// Validates the text of a material file read from `path` (used in messages and for the
/// default name, the file stem): a library file, or a user material without `status` (see
/// the module docs).
pub fn material_from_str(text: &str, path: &Path) -> Result<Material, ScenarioError> {
    let source = Source { path, text };
    let stem = source.file_stem();
    source.material_file(Origin::File {
        default_name: &stem,
    })
}

/// A library file's text (strict: `name`, `status` and complete provenance required).
pub(super) fn library_material_from_str(
    text: &str,
    path: &Path,
) -> Result<Material, ScenarioError> {
    Source { path, text }.material_file(Origin::Library)
}

/// Reads and validates the material file at `path` (see [`material_from_str`]).
pub fn load_material_file(path: &Path) -> Result<Material, ScenarioError> {
    let text = std::fs::read_to_string(path).map_err(|e| ScenarioError::Invalid {
        path: path.to_path_buf(),
        line: None,
        key: None,
        message: format!("cannot read material file: {e}"),
    })?;
    material_from_str(&text, path)
}

/// Replaces the key of a located error (for keys with an index, such as `material.prony[2].tau`).
fn rekey(error: ScenarioError, key: &str) -> ScenarioError {
    match error {
        ScenarioError::Invalid {
            path,
            line,
            message,
            ..
        } => ScenarioError::Invalid {
            path,
            line,
            key: Some(key.to_owned()),
            message,
        },
        other => other,
    }
}

impl Source<'_> {
    /// Where `key`, missing from the scenario's material, can be given, as the fix of a
    /// message: a key the program then accepts. An inline `[material]` takes it; a `file`
    /// material takes no other keys in the scenario, so the key goes into that file (or the
    /// file is refitted with `fit-prony --like`, which copies it from a library compound); a
    /// `library` compound (or one `compare` put in) is complete as shipped, so the material
    /// must be given another way.
    pub(super) fn material_key_fix(&self, raw: &RawMaterial, replaced: bool, key: &str) -> String {
        if replaced {
            return format!(
                "add `{key}` to [material] in the compared compound's material file (the \
                 scenario's [material] table does not apply to it)"
            );
        }
        match (&raw.file, &raw.library) {
            (Some(file), _) => format!(
                "add `{key}` to [material] in the material file {} itself (a scenario's `file` \
                 material takes no other keys), or write that file with `sealsim fit-prony \
                 --like COMPOUND`, which copies `{key}` and the temperature shift from a library \
                 compound (`sealsim materials list`)",
                self.relative_path(file.get_ref()).display()
            ),
            (None, Some(_)) => format!(
                "give the material inline in [material] with `{key}` (a `library` material takes \
                 no other keys)"
            ),
            (None, None) => format!("add `{key}` to [material]"),
        }
    }

    /// The whole text as a material file.
    fn material_file(&self, origin: Origin<'_>) -> Result<Material, ScenarioError> {
        let raw: RawMaterialFile = self.deserialize()?;
        self.material(&raw.material, origin)
    }

    /// A scenario's `[material]`: the material, the elastic constants of the static leak
    /// problem (the relaxed modulus E∞ with the material's ν) and the asperity-modulus option.
    ///
    /// With `replacement` (`sealsim compare`), that compound is used instead of the one the
    /// table names; the table's scenario options (`asperity_modulus`) still apply.
    pub(super) fn scenario_material(
        &self,
        table: &Spanned<RawMaterial>,
        default_name: &str,
        replacement: Option<&Material>,
    ) -> Result<(Material, Elastic, AsperityModulus), ScenarioError> {
        let raw = table.get_ref();
        let asperity = self.asperity_modulus(raw)?;
        if let (Some(_), Some(file)) = (&raw.library, &raw.file) {
            return Err(self.error(
                file.span(),
                "material.file",
                "give either `library` or `file`, not both".to_owned(),
            ));
        }
        let (material, span, key) = match (raw.library.as_ref().or(raw.file.as_ref()), replacement)
        {
            (Some(id), _) => {
                let by_file = raw.file.is_some();
                let what = if by_file { "file" } else { "library" };
                if let Some((other, span)) = present_keys(raw).into_iter().find(|(key, _)| {
                    !matches!(*key, "library" | "file" | "asperity_modulus" | "permeation")
                }) {
                    return Err(self.error(
                        span,
                        &format!("material.{other}"),
                        format!(
                            "a {what} material takes no other keys (except the scenario option \
                             `asperity_modulus` and its own gas figures `[material.permeation]`): \
                             remove `{other}`, or remove `{what}` and give the whole material \
                             inline"
                        ),
                    ));
                }
                let key = if by_file {
                    "material.file"
                } else {
                    "material.library"
                };
                let material = match (replacement, by_file) {
                    (Some(m), _) => m.clone(),
                    (None, true) => {
                        let path = self.relative_path(id.get_ref());
                        if !path.is_file() {
                            return Err(self.error(
                                id.span(),
                                key,
                                format!(
                                    "no material file {} (relative to the scenario's directory)",
                                    path.display()
                                ),
                            ));
                        }
                        load_material_file(&path)?
                    }
                    (None, false) => library::get(id.get_ref())
                        .map_err(|e| self.error(id.span(), key, e.to_string()))?
                        .load()?,
                };
                // the scenario's own gas figures belong to its compound, not to a compared one
                let material = match (&raw.permeation, replacement) {
                    (Some(table), None) => {
                        let mut material = material;
                        let own = self.own_permeation(table)?;
                        material
                            .permeation
                            .retain(|p| !own.iter().any(|o| o.gas == p.gas));
                        material.permeation.extend(own);
                        material
                    }
                    _ => material,
                };
                (material, id.span(), key)
            }
            (None, replacement) => {
                let inline = self.material(table, Origin::Inline { default_name })?;
                let (span, key) = match (&raw.long_term_modulus, &raw.youngs_modulus) {
                    (Some(q), _) => (q.span(), LONG_TERM_MODULUS.key),
                    (None, Some(q)) => (q.span(), YOUNGS_MODULUS.key),
                    (None, None) => (table.span(), "material"),
                };
                (replacement.cloned().unwrap_or(inline), span, key)
            }
        };
        let relaxed = material.prony.long_term();
        if relaxed <= 0.0 {
            return Err(self.error(
                span,
                key,
                format!(
                    "no relaxed modulus: the material ({}) has E∞ = 0 (no equilibrium modulus), \
                     but the static leak problem takes the relaxed modulus E∞ (docs/model.md §6); give \
                     a long_term_modulus > 0",
                    material.name
                ),
            ));
        }
        let elastic = Elastic {
            youngs_modulus: relaxed,
            poisson_ratio: material.poisson_ratio,
        };
        Ok((material, elastic, asperity))
    }

    /// `material.asperity_modulus`: `"follow"` (default), `"relaxed"`, `"instantaneous"`, or a
    /// fixed modulus (`"3 MPa"`, or a bare number in Pa).
    fn asperity_modulus(&self, raw: &RawMaterial) -> Result<AsperityModulus, ScenarioError> {
        let Some(q) = &raw.asperity_modulus else {
            return Ok(AsperityModulus::Follow);
        };
        if let RawQuantity::Text(text) = q.get_ref() {
            match text.trim() {
                "relaxed" => return Ok(AsperityModulus::Relaxed),
                "instantaneous" => return Ok(AsperityModulus::Instantaneous),
                "follow" => return Ok(AsperityModulus::Follow),
                word if word.chars().next().is_some_and(char::is_alphabetic) => {
                    return Err(self.error(
                        q.span(),
                        ASPERITY_MODULUS.key,
                        format!(
                            "must be \"relaxed\", \"instantaneous\", \"follow\" or a modulus \
                             such as \"3 MPa\", got {word:?}"
                        ),
                    ));
                }
                _ => {}
            }
        }
        Ok(AsperityModulus::Fixed(self.quantity(q, &ASPERITY_MODULUS)?))
    }

    /// A `[material]` table (not a `library` reference) → a checked [`Material`].
    fn material(
        &self,
        table: &Spanned<RawMaterial>,
        origin: Origin<'_>,
    ) -> Result<Material, ScenarioError> {
        let raw = table.get_ref();
        if let Some(id) = &raw.library {
            return Err(self.error(
                id.span(),
                "material.library",
                "a material file cannot refer to a library material; `library` is for scenarios",
            ));
        }
        if let Some(file) = &raw.file {
            return Err(self.error(
                file.span(),
                "material.file",
                "a material file cannot refer to another material file; `file` is for scenarios",
            ));
        }
        if let (Some(q), Origin::Library | Origin::File { .. }) = (&raw.asperity_modulus, origin) {
            return Err(self.error(
                q.span(),
                ASPERITY_MODULUS.key,
                "asperity_modulus is a scenario option, not a property of the compound; set it \
                 in the scenario's [material] table",
            ));
        }
        let name = self.material_name(table, origin)?;
        let status = self.status(table, origin)?;
        let poisson_ratio = match &raw.poisson_ratio {
            Some(q) => self.quantity(q, &POISSON_RATIO)?,
            None => {
                return Err(self.error(
                    table.span(),
                    POISSON_RATIO.key,
                    "missing key `poisson_ratio` in [material]",
                ));
            }
        };
        let prony = self.modulus(table)?;
        let glass_transition = raw
            .glass_transition
            .as_ref()
            .map(|q| self.absolute_temperature(q, "material.glass_transition"))
            .transpose()?;
        let thermal_expansion = raw
            .thermal_expansion
            .as_ref()
            .map(|q| self.quantity(q, &THERMAL_EXPANSION))
            .transpose()?;
        let glassy_thermal_expansion = raw
            .glassy_thermal_expansion
            .as_ref()
            .map(|q| self.quantity(q, &GLASSY_THERMAL_EXPANSION))
            .transpose()?;
        let shift = match &raw.shift {
            Some(shift) => self.shift(shift)?,
            None => Shift::None,
        };
        let ageing = raw.ageing.as_ref().map(|a| self.ageing(a)).transpose()?;
        let data_reduced_time = raw
            .data_reduced_time
            .as_ref()
            .map(|w| {
                self.window(w, "material.data_reduced_time", |q| {
                    self.quantity(q, &DATA_REDUCED_TIME)
                })
            })
            .transpose()?;
        let data_temperature = raw
            .data_temperature
            .as_ref()
            .map(|w| {
                self.window(w, "material.data_temperature", |q| {
                    self.absolute_temperature(q, "material.data_temperature")
                })
            })
            .transpose()?;
        let ageing_basis = raw
            .ageing
            .as_ref()
            .map(|a| self.ageing_basis(a, status != Status::User))
            .transpose()?
            .flatten();
        let compatibility = raw
            .compatibility
            .as_ref()
            .map(|table| self.compatibility(table, status != Status::User))
            .transpose()?
            .unwrap_or_default();
        let class = raw
            .class
            .as_ref()
            .map(|c| {
                crate::permeation::FAMILIES
                    .iter()
                    .find(|f| **f == c.get_ref().as_str())
                    .map(|f| (*f).to_owned())
                    .ok_or_else(|| {
                        self.error(
                            c.span(),
                            "material.class",
                            format!(
                                "unknown compound class {:?}: give one of {}",
                                c.get_ref(),
                                crate::permeation::FAMILIES
                                    .map(|f| format!("\"{f}\""))
                                    .join(", ")
                            ),
                        )
                    })
            })
            .transpose()?;
        let permeation = raw
            .permeation
            .as_ref()
            .map(|table| self.own_permeation(table))
            .transpose()?
            .unwrap_or_default();
        // published or illustrative data must say where every number comes from
        let provenance = self.provenance(raw, status != Status::User)?;
        let bands = raw
            .bands
            .as_ref()
            .map(|table| self.bands(table, status != Status::User))
            .transpose()?
            .unwrap_or_default();
        Ok(Material {
            name,
            status,
            prony,
            poisson_ratio,
            shift,
            glass_transition,
            thermal_expansion,
            glassy_thermal_expansion,
            ageing,
            ageing_basis,
            data_reduced_time,
            data_temperature,
            compatibility,
            provenance,
            library_id: None,
            class,
            permeation,
            bands,
        })
    }

    /// `[material.bands]` in file order: each key one of [`BAND_KEYS`], `min` below `max` in
    /// the figure's unit, a `source` (required when `sourced`: a compound with a status).
    fn bands(
        &self,
        table: &Spanned<BTreeMap<String, Spanned<RawBand>>>,
        sourced: bool,
    ) -> Result<Vec<FigureBand>, ScenarioError> {
        let mut entries: Vec<_> = table.get_ref().iter().collect();
        entries.sort_by_key(|(_, value)| value.span().start);
        let mut bands = Vec::new();
        for (key, value) in entries {
            let path = format!("material.bands.{key}");
            let Some((_, [min_field, max_field])) = BAND_KEYS.iter().find(|(k, _)| k == key) else {
                return Err(self.error(
                    value.span(),
                    &path,
                    format!(
                        "unknown key `{key}`: the bands a study can draw are {}",
                        BAND_KEYS.map(|(k, _)| format!("`{k}`")).join(", ")
                    ),
                ));
            };
            let band = value.get_ref();
            let min = self
                .quantity(&band.min, min_field)
                .map_err(|e| rekey(e, &format!("{path}.min")))?;
            let max = self
                .quantity(&band.max, max_field)
                .map_err(|e| rekey(e, &format!("{path}.max")))?;
            if min >= max {
                return Err(self.error(
                    value.span(),
                    &path,
                    format!(
                        "`min` must be below `max`, got {} and {} {}",
                        show(min),
                        show(max),
                        min_field.unit()
                    ),
                ));
            }
            let source = match &band.source {
                Some(s) if !s.get_ref().trim().is_empty() => s.get_ref().trim().to_owned(),
                _ if sourced => {
                    return Err(self.error(
                        value.span(),
                        &path,
                        "needs a `source`: where the band comes from (a datasheet's rounding, a \
                         class's spread)",
                    ));
                }
                _ => "user's band".to_owned(),
            };
            bands.push(FigureBand {
                key: key.clone(),
                min,
                max,
                source,
            });
        }
        Ok(bands)
    }

    /// `[material.compatibility]`: a key per fluid class, each `{ rating = "A"|"B"|"X", source
    /// = "…" }`; the source is required when the data make a claim (library files, materials
    /// with a `status`).
    fn compatibility(
        &self,
        table: &Spanned<BTreeMap<String, Spanned<RawCompatibility>>>,
        source_required: bool,
    ) -> Result<Vec<Compatibility>, ScenarioError> {
        let mut entries: Vec<_> = table.get_ref().iter().collect();
        entries.sort_by_key(|(_, value)| value.span().start);
        entries
            .into_iter()
            .map(|(key, value)| {
                let path = format!("material.compatibility.{key}");
                let class = FluidClass::from_key(key).ok_or_else(|| {
                    self.error(
                        value.span(),
                        &path,
                        format!(
                            "unknown fluid class `{key}`: give one of {}",
                            FluidClass::ALL.map(|c| format!("`{}`", c.key())).join(", ")
                        ),
                    )
                })?;
                let raw = value.get_ref();
                let rating = Rating::from_letter(raw.rating.get_ref()).ok_or_else(|| {
                    self.error(
                        raw.rating.span(),
                        &format!("{path}.rating"),
                        format!(
                            "rating {:?} is outside the scale: give \"A\" (recommended), \"B\" \
                             (limited) or \"X\" (not recommended)",
                            raw.rating.get_ref()
                        ),
                    )
                })?;
                let source = match &raw.source {
                    Some(s) if !s.get_ref().trim().is_empty() => s.get_ref().trim().to_owned(),
                    _ if !source_required => "the material file".to_owned(),
                    _ => {
                        return Err(self.error(
                            value.span(),
                            &format!("{path}.source"),
                            "missing `source`: a rating in published or illustrative data says                              which chart it comes from, e.g. source = \"<maker>, <chart>, row                              '<fluid>'\"",
                        ));
                    }
                };
                Ok(Compatibility {
                    class,
                    rating,
                    source,
                })
            })
            .collect()
    }

    /// `[material.permeation]`: a key per gas (a gas library id, or `custom`), each
    /// `{ permeability, diffusivity, source }` (docs/model.md §13.4).
    fn own_permeation(
        &self,
        table: &Spanned<BTreeMap<String, Spanned<RawPermeation>>>,
    ) -> Result<Vec<UserPermeation>, ScenarioError> {
        let mut entries: Vec<_> = table.get_ref().iter().collect();
        entries.sort_by_key(|(_, value)| value.span().start);
        entries
            .into_iter()
            .map(|(gas, value)| {
                let path = format!("material.permeation.{gas}");
                if gas != "custom" && crate::gas::library(gas).is_none() {
                    return Err(self.error(
                        value.span(),
                        &path,
                        format!(
                            "unknown gas `{gas}`: give one of {}, or `custom` for the scenario's \
                             custom gas",
                            crate::gas::library_ids()
                                .iter()
                                .map(|g| format!("`{g}`"))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    ));
                }
                let raw = value.get_ref();
                let key = format!("{path}.permeability");
                let permeability = match raw.permeability.get_ref() {
                    RawQuantity::Text(text) if text.trim().ends_with("barrer") => {
                        let number = text.trim().trim_end_matches("barrer").trim();
                        match number.parse::<f64>() {
                            Ok(v) if v.is_finite() && v > 0.0 => crate::permeation::barrer_to_si(v),
                            _ => {
                                return Err(self.error(
                                    raw.permeability.span(),
                                    &key,
                                    format!(
                                        "must be a positive number of barrer, e.g. \"5 barrer\", \
                                         got {text:?}"
                                    ),
                                ));
                            }
                        }
                    }
                    _ => self
                        .quantity(&raw.permeability, &PERMEABILITY)
                        .map_err(|e| rekey(e, &key))?,
                };
                let diffusivity = raw
                    .diffusivity
                    .as_ref()
                    .map(|q| {
                        self.quantity(q, &DIFFUSIVITY)
                            .map_err(|e| rekey(e, &format!("{path}.diffusivity")))
                    })
                    .transpose()?;
                Ok(UserPermeation {
                    gas: gas.clone(),
                    permeability,
                    diffusivity,
                    source: raw
                        .source
                        .as_ref()
                        .map(|s| s.get_ref().trim().to_owned())
                        .filter(|s| !s.is_empty()),
                })
            })
            .collect()
    }

    /// A `[lo, hi]` window of two values, each read by `value`, with lo ≤ hi.
    fn window(
        &self,
        raw: &Spanned<Vec<Quantity>>,
        key: &str,
        value: impl Fn(&Quantity) -> Result<f64, ScenarioError>,
    ) -> Result<(f64, f64), ScenarioError> {
        let [lo, hi] = raw.get_ref().as_slice() else {
            return Err(self.error(
                raw.span(),
                key,
                format!(
                    "must be a window of two values [low, high], got {}",
                    raw.get_ref().len()
                ),
            ));
        };
        let (lo, hi) = (value(lo)?, value(hi)?);
        if lo > hi {
            return Err(self.error(
                raw.span(),
                key,
                "the window's low end is above its high end".to_owned(),
            ));
        }
        Ok((lo, hi))
    }

    fn material_name(
        &self,
        table: &Spanned<RawMaterial>,
        origin: Origin<'_>,
    ) -> Result<String, ScenarioError> {
        match (&table.get_ref().name, origin) {
            (Some(name), _) if name.get_ref().trim().is_empty() => {
                Err(self.error(name.span(), "material.name", "must not be empty"))
            }
            (Some(name), _) => Ok(name.get_ref().trim().to_owned()),
            (None, Origin::Library) => Err(self.error(
                table.span(),
                "material.name",
                "missing key `name` in [material] (a library file must name its compound)",
            )),
            (None, Origin::File { default_name } | Origin::Inline { default_name }) => {
                Ok(default_name.to_owned())
            }
        }
    }

    fn status(
        &self,
        table: &Spanned<RawMaterial>,
        origin: Origin<'_>,
    ) -> Result<Status, ScenarioError> {
        match (&table.get_ref().status, origin) {
            (Some(status), Origin::Library | Origin::File { .. }) => {
                match status.get_ref().as_str() {
                    "published" => Ok(Status::Published),
                    "illustrative" => Ok(Status::Illustrative),
                    other => {
                        let or_absent = match origin {
                            Origin::File { .. } => " (or no status for a user material)",
                            _ => "",
                        };
                        Err(self.error(
                            status.span(),
                            "material.status",
                            format!(
                                "must be \"published\" or \"illustrative\"{or_absent}, got \
                                 {other:?}"
                            ),
                        ))
                    }
                }
            }
            (None, Origin::File { .. }) => Ok(Status::User),
            (None, Origin::Library) => Err(self.error(
                table.span(),
                "material.status",
                "missing key `status` in [material] (a library file must say whether its data \
                 are \"published\" or \"illustrative\")",
            )),
            (Some(status), Origin::Inline { .. }) => Err(self.error(
                status.span(),
                "material.status",
                "status belongs in library files; a material given in a scenario is a user \
                 material (remove `status`)",
            )),
            (None, Origin::Inline { .. }) => Ok(Status::User),
        }
    }

    /// The modulus: exactly one of `youngs_modulus` (elastic) or `long_term_modulus` with an
    /// optional `prony` series.
    fn modulus(&self, table: &Spanned<RawMaterial>) -> Result<Prony, ScenarioError> {
        let raw = table.get_ref();
        match (&raw.youngs_modulus, &raw.long_term_modulus, &raw.prony) {
            (Some(e), None, None) => {
                let e = self.quantity(e, &YOUNGS_MODULUS)?;
                Prony::elastic(e)
                    .map_err(|err| self.error(table.span(), YOUNGS_MODULUS.key, err.to_string()))
            }
            (Some(e), _, _) => Err(self.error(
                e.span(),
                YOUNGS_MODULUS.key,
                "give either youngs_modulus (elastic) or long_term_modulus with prony \
                 (viscoelastic), not both",
            )),
            (None, Some(long_term), terms) => {
                let e_inf = self.quantity(long_term, &LONG_TERM_MODULUS)?;
                let terms = match terms {
                    Some(terms) => self.prony_terms(terms.get_ref())?,
                    None => Vec::new(),
                };
                Prony::new(e_inf, &terms).map_err(|err| {
                    self.error(long_term.span(), LONG_TERM_MODULUS.key, err.to_string())
                })
            }
            (None, None, Some(terms)) => Err(self.error(
                terms.span(),
                "material.prony",
                "a Prony series needs long_term_modulus (E∞; write `long_term_modulus = 0` \
                 explicitly for a rubber without an equilibrium modulus)",
            )),
            (None, None, None) => Err(self.error(
                table.span(),
                "material",
                "no modulus: give youngs_modulus (elastic) or long_term_modulus with an optional \
                 prony series (viscoelastic)",
            )),
        }
    }

    fn prony_terms(&self, raw: &[Spanned<RawPronyTerm>]) -> Result<Vec<PronyTerm>, ScenarioError> {
        raw.iter()
            .enumerate()
            .map(|(i, term)| {
                let term = term.get_ref();
                let modulus = self
                    .quantity(&term.modulus, &TERM_MODULUS)
                    .map_err(|e| rekey(e, &format!("material.prony[{i}].modulus")))?;
                let tau = self
                    .quantity(&term.tau, &TERM_TAU)
                    .map_err(|e| rekey(e, &format!("material.prony[{i}].tau")))?;
                Ok(PronyTerm { modulus, tau })
            })
            .collect()
    }

    /// `[material.shift]`: `kind = "wlf"` with c1, c2, or `"arrhenius"` with
    /// activation_energy; both need reference_temperature.
    fn shift(&self, table: &Spanned<RawShift>) -> Result<Shift, ScenarioError> {
        let raw = table.get_ref();
        let kind = raw.kind.get_ref().as_str();
        // (the kind with its article for the messages, the keys the kind needs, the keys of
        // the other kind)
        let (a_shift, needs, foreign): (&str, &str, Vec<(&Option<Quantity>, &str)>) = match kind {
            "wlf" => (
                "a WLF shift",
                "reference_temperature, c1 and c2",
                vec![(&raw.activation_energy, "activation_energy")],
            ),
            "arrhenius" => (
                "an Arrhenius shift",
                "reference_temperature and activation_energy",
                vec![(&raw.c1, "c1"), (&raw.c2, "c2")],
            ),
            other => {
                return Err(self.error(
                    raw.kind.span(),
                    "material.shift.kind",
                    format!("must be \"wlf\" or \"arrhenius\", got {other:?}"),
                ));
            }
        };
        for (present, key) in foreign {
            if let Some(q) = present {
                return Err(self.error(
                    q.span(),
                    &format!("material.shift.{key}"),
                    format!("not a parameter of {a_shift}, which takes {needs}"),
                ));
            }
        }
        let missing = |key: &str| {
            self.error(
                table.span(),
                &format!("material.shift.{key}"),
                format!("missing key `{key}` ({a_shift} needs {needs})"),
            )
        };
        let reference = raw
            .reference_temperature
            .as_ref()
            .ok_or_else(|| missing("reference_temperature"))?;
        let reference =
            self.absolute_temperature(reference, "material.shift.reference_temperature")?;
        Ok(if kind == "wlf" {
            let c1 = raw.c1.as_ref().ok_or_else(|| missing("c1"))?;
            let c2 = raw.c2.as_ref().ok_or_else(|| missing("c2"))?;
            Shift::Wlf {
                reference,
                c1: self.quantity(c1, &WLF_C1)?,
                c2: self.quantity(c2, &WLF_C2)?,
            }
        } else {
            let energy = raw
                .activation_energy
                .as_ref()
                .ok_or_else(|| missing("activation_energy"))?;
            Shift::Arrhenius {
                reference,
                activation_energy: self.quantity(energy, &SHIFT_ACTIVATION_ENERGY)?,
            }
        })
    }

    fn ageing(&self, table: &Spanned<RawAgeing>) -> Result<Ageing, ScenarioError> {
        let raw = table.get_ref();
        let activation_energy = self.quantity(&raw.activation_energy, &AGEING_ACTIVATION_ENERGY)?;
        Ok(Ageing {
            activation_energy,
            activation_energy_above: match &raw.activation_energy_above {
                Some(q) => self.quantity(q, &AGEING_ACTIVATION_ENERGY_ABOVE)?,
                None => activation_energy,
            },
            rate: self.quantity(&raw.rate, &AGEING_RATE)?,
            reference_temperature: self.absolute_temperature(
                &raw.reference_temperature,
                "material.ageing.reference_temperature",
            )?,
            crosslinking: match &raw.crosslinking {
                Some(q) => self.quantity(q, &AGEING_CROSSLINKING)?,
                None => BALANCED_CROSSLINKING,
            },
        })
    }

    /// `property` and `criterion` of `[material.ageing]`: both or neither; both required when
    /// the data make a claim (library files and materials with a `status`).
    fn ageing_basis(
        &self,
        table: &Spanned<RawAgeing>,
        required: bool,
    ) -> Result<Option<AgeingBasis>, ScenarioError> {
        let raw = table.get_ref();
        let medium = match &raw.medium {
            None => None,
            Some(m) => Some(
                crate::material::AgeingMedium::from_name(m.get_ref()).ok_or_else(|| {
                    self.error(
                        m.span(),
                        "material.ageing.medium",
                        format!(
                            "unknown medium {:?}: give one of {}",
                            m.get_ref(),
                            crate::material::AgeingMedium::ALL
                                .map(|m| format!("\"{}\"", m.as_str()))
                                .join(", ")
                        ),
                    )
                })?,
            ),
        };
        match (&raw.property, &raw.criterion) {
            (Some(p), Some(c)) => Ok(Some(AgeingBasis {
                property: p.get_ref().clone(),
                criterion: c.get_ref().clone(),
                medium,
                source: raw
                    .source
                    .as_ref()
                    .map(|s| s.get_ref().trim().to_owned())
                    .filter(|s| !s.is_empty()),
            })),
            (None, None) if !required => Ok(None),
            (p, _) => {
                let key = if p.is_none() { "property" } else { "criterion" };
                Err(self.error(
                    table.span(),
                    &format!("material.ageing.{key}"),
                    format!(
                        "missing key `{key}` in [material.ageing]: ageing constants that make a \
                         claim say what they were measured on and to which end-of-life \
                         criterion (`property` and `criterion`)"
                    ),
                ))
            }
        }
    }

    /// An absolute temperature \[K\]: a bare number in kelvin, or a string with a unit
    /// (`"23 C"`, `"296.15 K"`, `"73.4 F"`); must be above absolute zero.
    pub(super) fn absolute_temperature(
        &self,
        raw: &Quantity,
        key: &str,
    ) -> Result<f64, ScenarioError> {
        let kelvin = match raw.get_ref() {
            // "100": °C or K? Both are common; guessing wrong is a 373 K error.
            RawQuantity::Number(v) => {
                return Err(self.error(
                    raw.span(),
                    key,
                    format!(
                        "a temperature needs its unit: write \"{v} C\" or \"{v} K\" (a bare \
                         number is ambiguous)"
                    ),
                ));
            }
            RawQuantity::Text(text) => units::parse_temperature(text)
                .map_err(|e| self.error(raw.span(), key, e.to_string()))?,
        };
        if !(kelvin.is_finite() && kelvin > 0.0) {
            return Err(self.error(
                raw.span(),
                key,
                format!(
                    "must be an absolute temperature above 0 K, got {} K",
                    show(kelvin)
                ),
            ));
        }
        let (lo, hi) = TEMPERATURE_RANGE;
        if !(lo..=hi).contains(&kelvin) {
            return Err(self.error(
                raw.span(),
                key,
                format!(
                    "must lie in [{}, {}] K, got {} K",
                    show(lo),
                    show(hi),
                    show(kelvin)
                ),
            ));
        }
        Ok(kelvin)
    }

    /// `[material.provenance]` in file order: every key names a parameter the material gives,
    /// every value is a non-empty string; if `complete`, every parameter present needs one.
    fn provenance(
        &self,
        raw: &RawMaterial,
        complete: bool,
    ) -> Result<Vec<(String, String)>, ScenarioError> {
        let present = present_keys(raw);
        let gives = |key: &str| present.iter().any(|(k, _)| *k == key);
        let mut provenance = Vec::new();
        if let Some(table) = &raw.provenance {
            let mut entries: Vec<_> = table.get_ref().iter().collect();
            entries.sort_by_key(|(_, value)| value.span().start);
            for (key, value) in entries {
                let path = format!("material.provenance.{key}");
                if !PARAMETERS.contains(&key.as_str()) && !DATA_WINDOWS.contains(&key.as_str()) {
                    return Err(self.error(
                        value.span(),
                        &path,
                        format!(
                            "unknown key `{key}`, expected one of the parameters {} (or the data \
                             windows {})",
                            PARAMETERS.map(|p| format!("`{p}`")).join(", "),
                            DATA_WINDOWS.map(|p| format!("`{p}`")).join(", ")
                        ),
                    ));
                }
                // a compound without ageing constants may say why (the library's do)
                if !gives(key) && key != "ageing" {
                    return Err(self.error(
                        value.span(),
                        &path,
                        format!("provenance of `{key}`, which this material does not give"),
                    ));
                }
                let text = value.get_ref().trim();
                if text.is_empty() {
                    return Err(self.error(
                        value.span(),
                        &path,
                        "must not be empty: say where the value comes from",
                    ));
                }
                provenance.push((key.clone(), text.to_owned()));
            }
        }
        if complete {
            let missing = present.iter().find(|(key, _)| {
                PARAMETERS.contains(key) && !provenance.iter().any(|(k, _)| k == key)
            });
            if let Some((key, span)) = missing {
                return Err(self.error(
                    span.clone(),
                    &format!("material.{key}"),
                    format!(
                        "missing provenance: published or illustrative data must say where \
                         every number comes from; add `{key} = \"<source>\"` to \
                         [material.provenance]"
                    ),
                ));
            }
        }
        Ok(provenance)
    }
}

/// The keys a `[material]` table gives (other than `provenance`), with their spans, in schema
/// order.
fn present_keys(raw: &RawMaterial) -> Vec<(&'static str, Range<usize>)> {
    let quantity = |q: &Option<Quantity>| q.as_ref().map(Spanned::span);
    [
        ("library", raw.library.as_ref().map(Spanned::span)),
        ("file", raw.file.as_ref().map(Spanned::span)),
        ("name", raw.name.as_ref().map(Spanned::span)),
        ("status", raw.status.as_ref().map(Spanned::span)),
        ("poisson_ratio", quantity(&raw.poisson_ratio)),
        ("youngs_modulus", quantity(&raw.youngs_modulus)),
        ("long_term_modulus", quantity(&raw.long_term_modulus)),
        ("prony", raw.prony.as_ref().map(Spanned::span)),
        ("shift", raw.shift.as_ref().map(Spanned::span)),
        ("glass_transition", quantity(&raw.glass_transition)),
        (
            "data_reduced_time",
            raw.data_reduced_time.as_ref().map(Spanned::span),
        ),
        (
            "data_temperature",
            raw.data_temperature.as_ref().map(Spanned::span),
        ),
        ("thermal_expansion", quantity(&raw.thermal_expansion)),
        (
            "glassy_thermal_expansion",
            quantity(&raw.glassy_thermal_expansion),
        ),
        ("ageing", raw.ageing.as_ref().map(Spanned::span)),
        ("provenance", raw.provenance.as_ref().map(Spanned::span)),
        ("asperity_modulus", quantity(&raw.asperity_modulus)),
        ("class", raw.class.as_ref().map(Spanned::span)),
        ("permeation", raw.permeation.as_ref().map(Spanned::span)),
        ("bands", raw.bands.as_ref().map(Spanned::span)),
    ]
    .into_iter()
    .filter_map(|(key, span)| Some((key, span?)))
    .collect()
}

/// A library compound parsed: in the material module, which reads every material table, so
/// that the library (the embedded files) needs nothing of it.
impl library::Entry {
    /// Parses and validates the entry (once per process: the text is embedded, so the result
    /// cannot change, and a study's cases each load their compound).
    pub fn load(&self) -> Result<Material, ScenarioError> {
        // more than the library holds: nothing is ever dropped (a failure is not kept: it is
        // parsed again for its message)
        static LOADED: crate::math::memo::Memo<&'static str, Option<Material>> =
            crate::math::memo::Memo::new(1024);
        match LOADED.get_or_insert_with(self.id, || self.parse().ok()) {
            Some(material) => Ok(material),
            None => self.parse(),
        }
    }

    fn parse(&self) -> Result<Material, ScenarioError> {
        let mut material = library_material_from_str(self.text, &self.path())?;
        material.library_id = Some(self.id.to_owned());
        material.class = crate::permeation::family_of(self.id).map(str::to_owned);
        Ok(material)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::Scenario;

    /// The issue's single-term test rubber in library format, every optional key present.
    /// Line numbers in the tests below refer to this text.
    const TEST_RUBBER: &str = r#"[material]
name = "single-term test rubber"
status = "illustrative"
poisson_ratio = 0.5
long_term_modulus = "4 MPa"
prony = [ { modulus = "6 MPa", tau = "1000 h" } ]
glass_transition = "-30 C"
thermal_expansion = "2.3e-4 1/K"
[material.shift]
kind = "wlf"
reference_temperature = "23 C"
c1 = 8.86
c2 = "101.6 K"
[material.ageing]
activation_energy = "90 kJ/mol"
rate = "1e-9 1/s"
reference_temperature = "100 C"
property = "test: compression set"
criterion = "test: 80 % set"
[material.provenance]
poisson_ratio = "test: incompressible"
long_term_modulus = "test: E_inf"
prony = "test: one term"
shift = "test: universal WLF"
glass_transition = "test: T_g"
thermal_expansion = "test: CTE"
ageing = "test: ageing"
"#;

    fn parse(text: &str) -> Result<Material, ScenarioError> {
        library_material_from_str(text, Path::new("materials/x.toml"))
    }

    fn error(text: &str) -> String {
        parse(text)
            .expect_err("the material should be rejected")
            .to_string()
    }

    /// `TEST_RUBBER` with a glassy CTE `value` (and its provenance) after the rubbery one, on
    /// line 9 (the lines after it move down by one; the provenance goes on line 26).
    fn with_glassy(value: &str) -> String {
        with(
            "thermal_expansion = \"2.3e-4 1/K\"\n",
            &format!("thermal_expansion = \"2.3e-4 1/K\"\nglassy_thermal_expansion = {value}\n"),
        )
        .replacen(
            "thermal_expansion = \"test: CTE\"\n",
            "thermal_expansion = \"test: CTE\"\nglassy_thermal_expansion = \"test: glassy CTE\"\n",
            1,
        )
    }

    #[test]
    fn glassy_thermal_expansion_is_parsed_and_checked_like_the_rubbery_one() {
        let m = parse(&with_glassy("\"7.7e-5 1/K\"")).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.glassy_thermal_expansion, Some(7.7e-5));
        assert_eq!(m.thermal_expansion, Some(2.3e-4));
        assert_eq!(
            m.provenance_of("glassy_thermal_expansion"),
            Some("test: glassy CTE")
        );
        for (value, message) in [
            (
                "\"-7.7e-5 1/K\"",
                ":9: material.glassy_thermal_expansion: must be positive",
            ),
            (
                "\"0 1/K\"",
                ":9: material.glassy_thermal_expansion: must be positive",
            ),
            ("\"7.7e-5 K\"", ":9: material.glassy_thermal_expansion: "),
            ("\"1 1/K\"", ":9: material.glassy_thermal_expansion: "),
        ] {
            let e = error(&with_glassy(value));
            assert!(e.contains(message), "{value}: {e}");
        }
        // a library file must say where it comes from
        let bare = with_glassy("\"7.7e-5 1/K\"").replacen(
            "glassy_thermal_expansion = \"test: glassy CTE\"\n",
            "",
            1,
        );
        let e = error(&bare);
        assert!(
            e.contains(":9: material.glassy_thermal_expansion: missing provenance"),
            "{e}"
        );
    }

    /// `TEST_RUBBER` with `from` replaced by `to` (which must occur).
    fn with(from: &str, to: &str) -> String {
        assert!(TEST_RUBBER.contains(from), "{from}");
        TEST_RUBBER.replacen(from, to, 1)
    }

    #[test]
    fn library_format_parses_into_si() {
        let m = parse(TEST_RUBBER).unwrap();
        assert_eq!(m.name, "single-term test rubber");
        assert_eq!(m.status, Status::Illustrative);
        assert_eq!(m.poisson_ratio, 0.5);
        assert_eq!(m.prony.long_term(), 4e6);
        assert_eq!(
            m.prony.terms(),
            &[PronyTerm {
                modulus: 6e6,
                tau: 3.6e6
            }]
        );
        assert_eq!(m.prony.instantaneous(), 1e7);
        assert!((m.glass_transition.unwrap() - 243.15).abs() < 1e-9);
        assert_eq!(m.thermal_expansion, Some(2.3e-4));
        match m.shift {
            Shift::Wlf { reference, c1, c2 } => {
                assert!((reference - 296.15).abs() < 1e-9);
                assert_eq!((c1, c2), (8.86, 101.6));
            }
            other => panic!("{other:?}"),
        }
        let a = m.ageing.unwrap();
        assert_eq!((a.activation_energy, a.rate), (9e4, 1e-9));
        assert!((a.reference_temperature - 373.15).abs() < 1e-9);
        let keys: Vec<&str> = m.provenance.iter().map(|(k, _)| k.as_str()).collect();
        assert_eq!(
            keys,
            PARAMETERS
                .iter()
                .filter(|k| **k != "youngs_modulus" && **k != "glassy_thermal_expansion")
                .copied()
                .collect::<Vec<_>>()
        );
        assert_eq!(m.glassy_thermal_expansion, None);
        assert_eq!(m.provenance_of("prony"), Some("test: one term"));
        // C2 is a temperature difference: "101.6 C" is 101.6 K, not 374.75 K
        let m = parse(&with("c2 = \"101.6 K\"", "c2 = \"101.6 C\"")).unwrap();
        assert!(matches!(m.shift, Shift::Wlf { c2, .. } if (c2 - 101.6).abs() < 1e-12));
        // an Arrhenius shift
        let arrhenius = with(
            "kind = \"wlf\"\nreference_temperature = \"23 C\"\nc1 = 8.86\nc2 = \"101.6 K\"",
            "kind = \"arrhenius\"\nreference_temperature = \"296.15 K\"\nactivation_energy = \"120 kJ/mol\"",
        );
        let m = parse(&arrhenius).unwrap();
        assert_eq!(
            m.shift,
            Shift::Arrhenius {
                reference: 296.15,
                activation_energy: 1.2e5
            }
        );
    }

    /// Each case replaces `from` by `to` in [`TEST_RUBBER`]; the error must name the file, the
    /// line and the key, and contain `expected`.
    fn assert_bounds(cases: &[(&str, &str, &str)]) {
        for (from, to, expected) in cases {
            let e = error(&with(from, to));
            assert!(
                e.starts_with("materials/x.toml:") && e.contains(expected),
                "{from} → {to}:\n  got      {e}\n  expected {expected}"
            );
        }
    }

    /// The Poisson ratio, the relaxed modulus and the Prony terms.
    #[test]
    fn elastic_and_prony_bounds_are_checked_with_file_line_and_key() {
        assert_bounds(&[
            (
                "poisson_ratio = 0.5",
                "poisson_ratio = 0.6",
                ":4: material.poisson_ratio: must lie between 0 and 0.5, got 0.6",
            ),
            (
                "poisson_ratio = 0.5",
                "poisson_ratio = -0.1",
                ":4: material.poisson_ratio: must lie between 0 and 0.5, got -0.1",
            ),
            (
                "\"4 MPa\"",
                "\"-4 MPa\"",
                ":5: material.long_term_modulus: must not be negative, got -4e6 Pa",
            ),
            (
                "\"6 MPa\"",
                "\"0 MPa\"",
                ":6: material.prony[0].modulus: must be positive, got 0 Pa",
            ),
            (
                "\"6 MPa\"",
                "\"-6 MPa\"",
                ":6: material.prony[0].modulus: must be positive, got -6e6 Pa",
            ),
            (
                "\"1000 h\"",
                "\"-1 s\"",
                ":6: material.prony[0].tau: must be positive, got -1 s",
            ),
            (
                "\"1000 h\"",
                "\"0 s\"",
                ":6: material.prony[0].tau: must be positive, got 0 s",
            ),
            (
                "\"1000 h\"",
                "\"1 m\"",
                ":6: material.prony[0].tau: expected a time",
            ),
        ]);
    }

    /// The glass transition and the thermal expansion.
    #[test]
    fn temperature_and_expansion_bounds_are_checked_with_file_line_and_key() {
        assert_bounds(&[
            ("\"-30 C\"", "\"-300 C\"", ":7: material.glass_transition: "),
            (
                "\"-30 C\"",
                "\"0 K\"",
                ":7: material.glass_transition: must be an absolute temperature above 0 K, got 0 K",
            ),
            (
                "\"-30 C\"",
                "243",
                ":7: material.glass_transition: a temperature needs its unit: write \"243 C\" or \"243 K\"",
            ),
            (
                "\"2.3e-4 1/K\"",
                "\"-2.3e-4 1/K\"",
                ":8: material.thermal_expansion: must be positive, got -2.3e-4 1/K",
            ),
            (
                "\"2.3e-4 1/K\"",
                "0",
                ":8: material.thermal_expansion: must be positive, got 0 1/K",
            ),
        ]);
    }

    /// A WLF shift: its kind, reference, C1 and C2, and no foreign or missing key.
    #[test]
    fn wlf_shift_bounds_are_checked_with_file_line_and_key() {
        assert_bounds(&[
            (
                "kind = \"wlf\"",
                "kind = \"vft\"",
                ":10: material.shift.kind: must be \"wlf\" or \"arrhenius\", got \"vft\"",
            ),
            (
                "reference_temperature = \"23 C\"",
                "reference_temperature = \"23 m\"",
                ":11: material.shift.reference_temperature: expected a temperature",
            ),
            (
                "reference_temperature = \"23 C\"",
                "reference_temperature = \"0 K\"",
                ":11: material.shift.reference_temperature: must be an absolute temperature above 0 K",
            ),
            (
                "c1 = 8.86",
                "c1 = 0",
                ":12: material.shift.c1: must be positive, got 0",
            ),
            (
                "c1 = 8.86",
                "c1 = -8.86",
                ":12: material.shift.c1: must be positive, got -8.86",
            ),
            (
                "c2 = \"101.6 K\"",
                "c2 = \"-101.6 K\"",
                ":13: material.shift.c2: must be positive, got -101.6 K",
            ),
            (
                "c2 = \"101.6 K\"",
                "c2 = 0",
                ":13: material.shift.c2: must be positive, got 0 K",
            ),
            (
                "c2 = \"101.6 K\"",
                "c2 = \"101.6 s\"",
                ":13: material.shift.c2: expected a temperature",
            ),
            (
                "c2 = \"101.6 K\"",
                "activation_energy = \"90 kJ/mol\"",
                ":13: material.shift.activation_energy: not a parameter of a WLF shift",
            ),
            (
                "c2 = \"101.6 K\"\n",
                "",
                ":9: material.shift.c2: missing key `c2` (a WLF shift needs reference_temperature, c1 and c2)",
            ),
        ]);
    }

    /// The ageing constants.
    #[test]
    fn ageing_bounds_are_checked_with_file_line_and_key() {
        assert_bounds(&[
            (
                "activation_energy = \"90 kJ/mol\"",
                "activation_energy = \"-90 kJ/mol\"",
                ":15: material.ageing.activation_energy: must be positive, got -90000 J/mol",
            ),
            (
                "rate = \"1e-9 1/s\"",
                "rate = 0",
                ":16: material.ageing.rate: must be positive, got 0 1/s",
            ),
            (
                "rate = \"1e-9 1/s\"",
                "rate = \"1e-9 s\"",
                ":16: material.ageing.rate: expected a frequency",
            ),
            (
                "\"100 C\"",
                "\"-500 F\"",
                ":17: material.ageing.reference_temperature: ",
            ),
        ]);
    }

    /// An Arrhenius shift takes its own keys only, with a positive activation energy.
    #[test]
    fn arrhenius_shift_keys_are_checked_with_file_line_and_key() {
        let arrhenius = with(
            "kind = \"wlf\"\nreference_temperature = \"23 C\"\nc1 = 8.86\nc2 = \"101.6 K\"",
            "kind = \"arrhenius\"\nreference_temperature = \"23 C\"\nactivation_energy = 0\nc1 = 1",
        );
        let e = error(&arrhenius);
        assert!(
            e.contains(":13: material.shift.c1: not a parameter of an Arrhenius shift"),
            "{e}"
        );
        let e = error(&arrhenius.replace("c1 = 1\n", ""));
        assert!(
            e.contains(":12: material.shift.activation_energy: must be positive, got 0 J/mol"),
            "{e}"
        );
    }

    /// A Prony term's error names the offending term by its index.
    #[test]
    fn prony_errors_name_the_term() {
        let two = with(
            "prony = [ { modulus = \"6 MPa\", tau = \"1000 h\" } ]",
            "prony = [\n  { modulus = \"6 MPa\", tau = \"1000 h\" },\n  { modulus = \"1 MPa\", tau = \"10 s\" },\n  { modulus = \"1 MPa\", tau = \"-1 s\" },\n]",
        );
        let e = error(&two);
        assert!(
            e.contains(":9: material.prony[2].tau: must be positive, got -1 s"),
            "{e}"
        );
        let e = error(&with("tau = \"1000 h\"", "tau = \"1000 h\", g = 1"));
        assert!(
            e.contains(":6: material.prony[0].g: unknown key `g`"),
            "{e}"
        );
    }

    #[test]
    fn every_parameter_needs_provenance_in_a_library_file() {
        let lines = [
            ("poisson_ratio", 4),
            ("long_term_modulus", 5),
            ("prony", 6),
            ("shift", 9),
            ("glass_transition", 7),
            ("thermal_expansion", 8),
            ("ageing", 14),
        ];
        for (key, line) in lines {
            let start = TEST_RUBBER.find(&format!("\n{key} = \"test")).unwrap() + 1;
            let end = start + TEST_RUBBER[start..].find('\n').unwrap() + 1;
            let text = format!("{}{}", &TEST_RUBBER[..start], &TEST_RUBBER[end..]);
            let e = error(&text);
            let expected = format!("materials/x.toml:{line}: material.{key}: missing provenance");
            assert!(e.starts_with(&expected), "{key}: {e}");
            assert!(
                e.contains(&format!(
                    "add `{key} = \"<source>\"` to [material.provenance]"
                )),
                "{e}"
            );
        }
        // no provenance table at all
        let bare = &TEST_RUBBER[..TEST_RUBBER.find("[material.provenance]").unwrap()];
        assert!(error(bare).contains(":4: material.poisson_ratio: missing provenance"));
        // the elastic form needs it for youngs_modulus
        let elastic = "[material]\nname = \"e\"\nstatus = \"published\"\npoisson_ratio = 0.5\n\
                       youngs_modulus = \"10 MPa\"\n[material.provenance]\npoisson_ratio = \"x\"\n";
        let e = error(elastic);
        assert!(
            e.contains(":5: material.youngs_modulus: missing provenance"),
            "{e}"
        );
        let m = parse(&format!("{elastic}youngs_modulus = \"y\"\n")).unwrap();
        assert_eq!((m.prony.long_term(), m.prony.instantaneous()), (1e7, 1e7));
        // unknown keys, keys of absent parameters, empty sources
        let e = error(&with(
            "ageing = \"test: ageing\"",
            "ageing = \"x\"\nhardness = \"y\"",
        ));
        assert!(
            e.contains(":28: material.provenance.hardness: unknown key `hardness`"),
            "{e}"
        );
        let e = error(&with("glass_transition = \"-30 C\"\n", ""));
        assert!(e.contains("material.provenance.glass_transition: provenance of `glass_transition`, which this material does not give"), "{e}");
        // `ageing` may say why a compound has no ageing constants
        let m = parse(&with(
            "[material.ageing]\nactivation_energy = \"90 kJ/mol\"\nrate = \"1e-9 1/s\"\nreference_temperature = \"100 C\"\nproperty = \"test: compression set\"\ncriterion = \"test: 80 % set\"\n",
            "",
        ))
        .unwrap();
        assert_eq!(m.ageing, None);
        assert_eq!(m.provenance_of("ageing"), Some("test: ageing"));
        let e = error(&with("\"test: CTE\"", "\"  \""));
        assert!(
            e.contains(":26: material.provenance.thermal_expansion: must not be empty"),
            "{e}"
        );
    }

    #[test]
    fn library_files_need_name_and_status() {
        let e = error(&with("name = \"single-term test rubber\"\n", ""));
        assert!(
            e.starts_with("materials/x.toml:1: material.name: missing key `name`"),
            "{e}"
        );
        let e = error(&with("status = \"illustrative\"\n", ""));
        assert!(
            e.starts_with("materials/x.toml:1: material.status: missing key `status`"),
            "{e}"
        );
        let e = error(&with("\"illustrative\"", "\"measured\""));
        assert!(
            e.contains(
                ":3: material.status: must be \"published\" or \"illustrative\", got \"measured\""
            ),
            "{e}"
        );
        let e = error(&with(
            "status = \"illustrative\"",
            "status = \"illustrative\"\nlibrary = \"nbr-70\"",
        ));
        assert!(
            e.contains(":4: material.library: a material file cannot refer"),
            "{e}"
        );
        let e = error("name = \"x\"\n");
        assert!(
            e.contains("missing table [material]") || e.contains("unknown key"),
            "{e}"
        );
        let e = error(&with("[material.ageing]", "[material.aging]"));
        assert!(e.contains("material.aging: unknown key `aging`"), "{e}");
    }

    #[test]
    fn material_files_by_path_without_status_are_user_materials() {
        let path = Path::new("out/fitted.toml");
        let user = "[material]\npoisson_ratio = 0.5\nlong_term_modulus = \"4 MPa\"\n\
                    prony = [ { modulus = \"6 MPa\", tau = \"1000 h\" } ]\n\
                    [material.provenance]\nprony = \"fitted\"\n";
        let m = material_from_str(user, path).unwrap();
        assert_eq!((m.name.as_str(), m.status), ("fitted", Status::User));
        assert_eq!(
            m.provenance,
            vec![("prony".to_owned(), "fitted".to_owned())]
        );
        // a status is a claim: then every parameter needs its source
        let claimed = user.replace("[material]\n", "[material]\nstatus = \"published\"\n");
        let e = material_from_str(&claimed, path).unwrap_err().to_string();
        assert!(
            e.starts_with("out/fitted.toml:3: material.poisson_ratio: missing provenance"),
            "{e}"
        );
        let e = material_from_str(
            &user.replace("[material]\n", "[material]\nstatus = \"user\"\n"),
            path,
        )
        .unwrap_err()
        .to_string();
        assert!(
            e.contains(":2: material.status: must be \"published\" or \"illustrative\""),
            "{e}"
        );
        // the library-format test file reads the same through either entry point
        assert_eq!(
            material_from_str(TEST_RUBBER, path).unwrap(),
            parse(TEST_RUBBER).unwrap()
        );
        // and what `fit-prony` writes reads back to the same material
        let written = crate::report::material_toml::material_toml(&m);
        assert_eq!(material_from_str(&written, path).unwrap(), m, "{written}");
        let library = parse(TEST_RUBBER).unwrap();
        let written = crate::report::material_toml::material_toml(&library);
        assert_eq!(parse(&written).unwrap(), library, "{written}");
    }

    /// `[material.compatibility]` (issue 31): read with its sources, written back the same,
    /// and every malformed entry refused naming the file, line and key.
    #[test]
    fn compatibility_ratings_are_read_written_and_checked() {
        let table = concat!(
            "[material.compatibility]\n",
            "water = { rating = \"A\", source = \"test chart, row water\" }\n",
            "mineral-oil = { rating = \"X\", source = \"test chart, row oil\" }\n",
        );
        let text = format!("{TEST_RUBBER}{table}");
        let m = parse(&text).unwrap();
        let found: Vec<_> = m
            .compatibility
            .iter()
            .map(|c| (c.class, c.rating, c.source.as_str()))
            .collect();
        assert_eq!(
            found,
            [
                (
                    FluidClass::Water,
                    Rating::Recommended,
                    "test chart, row water"
                ),
                (
                    FluidClass::MineralOil,
                    Rating::NotRecommended,
                    "test chart, row oil"
                ),
            ]
        );
        let written = crate::report::material_toml::material_toml(&m);
        assert_eq!(parse(&written).unwrap(), m, "{written}");
        // the table starts on line 28: its entries are on lines 29 and 30
        let e = error(&text.replace("water = {", "brine = {"));
        assert!(
            e.contains("materials/x.toml:29: material.compatibility.brine: unknown fluid class `brine`: give one of `mineral-oil`, `water`, `hot-water`, `water-glycol`"),
            "{e}"
        );
        let e = error(&text.replace("\"X\"", "\"C\""));
        assert!(
            e.contains("materials/x.toml:30: material.compatibility.mineral-oil.rating: rating \"C\" is outside the scale"),
            "{e}"
        );
        let e = error(&text.replace(", source = \"test chart, row oil\"", ""));
        assert!(
            e.contains(
                "materials/x.toml:30: material.compatibility.mineral-oil.source: missing `source`"
            ),
            "{e}"
        );
        // a user's own file may rate without a source
        let user = format!("[material]\nyoungs_modulus = \"5 MPa\"\npoisson_ratio = 0.5\n{table}")
            .replace(", source = \"test chart, row oil\"", "");
        let m = material_from_str(&user, Path::new("mine.toml")).unwrap();
        assert_eq!(m.compatibility.len(), 2);
    }

    #[test]
    fn modulus_is_elastic_or_viscoelastic_not_both() {
        let e = error(&with(
            "long_term_modulus",
            "youngs_modulus = \"10 MPa\"\nlong_term_modulus",
        ));
        assert!(
            e.contains(":5: material.youngs_modulus: give either youngs_modulus"),
            "{e}"
        );
        let e = error(&with("long_term_modulus = \"4 MPa\"\n", ""));
        assert!(
            e.contains(":5: material.prony: a Prony series needs long_term_modulus"),
            "{e}"
        );
        let start = TEST_RUBBER.find("long_term_modulus").unwrap();
        let end = TEST_RUBBER.find("glass_transition").unwrap();
        let none = format!("{}{}", &TEST_RUBBER[..start], &TEST_RUBBER[end..]).replace(
            "long_term_modulus = \"test: E_inf\"\nprony = \"test: one term\"\n",
            "",
        );
        let e = error(&none);
        assert!(e.contains(":1: material: no modulus"), "{e}");
        // E∞ = 0 with terms is a valid (fluid-like) material file ...
        let fluid = parse(&with("\"4 MPa\"", "0")).unwrap();
        assert_eq!(fluid.prony.long_term(), 0.0);
        // ... but E∞ = 0 and no terms is no material
        let e = error(&with("\"4 MPa\"", "0").replace(
            "prony = [ { modulus = \"6 MPa\", tau = \"1000 h\" } ]",
            "prony = []",
        ));
        assert!(
            e.contains(":5: material.long_term_modulus: the modulus is zero"),
            "{e}"
        );
    }

    /// The paper scenario with its `[material]` table replaced.
    fn scenario_with_material(material: &str) -> String {
        include_str!("../../scenarios/persson-yang-2008.toml").replace(
            "[material]\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.5\n",
            material,
        )
    }

    fn scenario(text: &str) -> Result<Scenario, ScenarioError> {
        Scenario::from_str(text, Path::new("dir/s.toml"))
    }

    #[test]
    fn scenario_materials_inline_elastic_viscoelastic_and_library() {
        // the issue-2 form is an elastic user material named after the scenario
        let s = scenario(&scenario_with_material(
            "[material]\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.5\n",
        ))
        .unwrap();
        assert_eq!(s.material.status, Status::User);
        assert_eq!(s.material.name, "Persson & Yang 2008, section 3");
        assert_eq!(s.problem.material.youngs_modulus, 1e7);
        // inline viscoelastic: the static problem takes the asperity modulus at the end of the
        // 1 s installation ramp (`follow`), E∞ + E1 τ (1 − e^{−1 s/τ})/1 s, and ν
        let s = scenario(&scenario_with_material(
            "[material]\nname = \"inline\"\npoisson_ratio = 0.49\nlong_term_modulus = \"4 MPa\"\n\
             prony = [ { modulus = \"6 MPa\", tau = \"1000 h\" } ]\n\
             [material.shift]\nkind = \"wlf\"\nreference_temperature = \"23 C\"\nc1 = 8.86\nc2 = \"101.6 K\"\n",
        ))
        .unwrap();
        assert_eq!(s.material.name, "inline");
        assert_eq!(s.material.prony.instantaneous(), 1e7);
        let tau: f64 = 3.6e6;
        let installed = 4e6 + 6e6 * tau * -(-1.0 / tau).exp_m1();
        assert!((s.problem.material.youngs_modulus / installed - 1.0).abs() < 1e-12);
        assert_eq!(s.problem.material.poisson_ratio, 0.49);
        assert_eq!(s.problem.seal.nominal_pressure, 2e5);
        // a library compound by id
        let s = scenario(&scenario_with_material(
            "[material]\nlibrary = \"nbr-70\"\n",
        ))
        .unwrap();
        let nbr = library::get("nbr-70").unwrap().load().unwrap();
        assert_eq!(s.material, nbr);
        assert_eq!(
            s.problem.material.youngs_modulus,
            s.life.installed_asperity_modulus()
        );
        // between the relaxed and the glassy modulus: the rubbery modulus after 1 s
        let e = s.problem.material.youngs_modulus;
        assert!(e > 1.2 * nbr.prony.long_term() && e < 0.01 * nbr.prony.instantaneous());
        assert_eq!(s.problem.material.poisson_ratio, nbr.poisson_ratio);
    }

    #[test]
    fn scenario_material_errors_are_located() {
        let e = scenario(&scenario_with_material(
            "[material]\nlibrary = \"nbr-99\"\n",
        ))
        .unwrap_err()
        .to_string();
        assert!(e.starts_with("dir/s.toml:3: material.library: unknown library material \"nbr-99\"; the library has: "), "{e}");
        for id in library::ids() {
            assert!(e.contains(id), "{e}");
        }
        let e = scenario(&scenario_with_material(
            "[material]\nlibrary = \"nbr-70\"\npoisson_ratio = 0.4\n",
        ))
        .unwrap_err()
        .to_string();
        assert!(
            e.starts_with(
                "dir/s.toml:4: material.poisson_ratio: a library material takes no other keys"
            ),
            "{e}"
        );
        let e = scenario(&scenario_with_material(
            "[material]\npoisson_ratio = 0.5\nlong_term_modulus = 0\nprony = [ { modulus = \"6 MPa\", tau = \"1 s\" } ]\n",
        ))
        .unwrap_err()
        .to_string();
        assert!(
            e.starts_with("dir/s.toml:4: material.long_term_modulus: no relaxed modulus"),
            "{e}"
        );
        let e = scenario(&scenario_with_material(
            "[material]\nstatus = \"published\"\npoisson_ratio = 0.5\nyoungs_modulus = \"10 MPa\"\n",
        ))
        .unwrap_err()
        .to_string();
        assert!(
            e.starts_with("dir/s.toml:3: material.status: status belongs in library files"),
            "{e}"
        );
        let e = scenario(&scenario_with_material(
            "[material]\nyoungs_modulus = \"10 MPa\"\n",
        ))
        .unwrap_err()
        .to_string();
        assert!(
            e.starts_with("dir/s.toml:2: material.poisson_ratio: missing key `poisson_ratio`"),
            "{e}"
        );
        // inline provenance is optional, but checked when given
        let s = scenario(&scenario_with_material(
            "[material]\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.5\n[material.provenance]\nyoungs_modulus = \"datasheet\"\n",
        ))
        .unwrap();
        assert_eq!(
            s.material.provenance_of("youngs_modulus"),
            Some("datasheet")
        );
        let e = scenario(&scenario_with_material(
            "[material]\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.5\n[material.provenance]\nprony = \"x\"\n",
        ))
        .unwrap_err()
        .to_string();
        assert!(e.contains(":6: material.provenance.prony: provenance of `prony`, which this material does not give"), "{e}");
    }
}
