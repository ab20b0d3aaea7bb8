//! The seal kinds of the input, one section each, registered in [`KINDS`]: a kind's keys, its
//! validation and the [`SealSpec`] it gives (docs/model.md §6). A new kind is its entry in
//! [`KINDS`] and its reader here, beside its core kind (`crate::seal`); ARCHITECTURE.md, "A new
//! seal kind".

use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::raw::{Quantity, RawSeal};
use super::seal_spec::{CROSS_SECTION, HousingExpansion, SQUEEZE, SealSpec};
use crate::gland::Housing;
use crate::seal::{SealGeometry, VolumeSwell};
use crate::simulate::Loading;
use crate::units::{Dimension, show};
use toml::Spanned;

/// One seal kind of the input: its `kind` value, its name with the article for the messages,
/// and its reader.
struct Kind {
    name: &'static str,
    a_seal: &'static str,
    read: fn(&SealTable, Loading, Option<&VolumeSwell>) -> Result<SealSpec, ScenarioError>,
}

/// The seal kinds, the default (`kind` absent) first.
const KINDS: [Kind; 2] = [
    Kind {
        name: "flat",
        a_seal: "a flat seal",
        read: |table, loading, _| table.flat(loading),
    },
    Kind {
        name: "o-ring",
        a_seal: "an O-ring seal",
        read: |table, loading, swell| table.o_ring(loading, swell),
    },
];

/// `"a"`, `"a" or "b"`, `"a", "b" or "c"`: the values `names` for a message.
fn one_of(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("{n:?}")).collect();
    match quoted.split_last() {
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// The `kind` values, for the key registry.
pub(super) const KIND_NAMES: [&str; 2] = [KINDS[0].name, KINDS[1].name];

// --- flat seal ---

pub(super) const NOMINAL_PRESSURE: Field = field(
    "seal.nominal_pressure",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(1.0, 1e10),
);
pub(super) const THICKNESS: Field = field(
    "seal.thickness",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-6, 1.0),
);
pub(super) const COMPRESSION: Field = field(
    "seal.compression",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);
/// A bolted flat gasket's installed compression ε0 when `compression` is not given: 10 % of
/// its free thickness, **assumed** — the low end of the vendors' bands read (Elasto Proxy,
/// "Enclosure gasket compression": "the ideal compression percentage is 40, the maximum is 50,
/// and the minimum is between 10 to 15"; EMI Seals: "25% min – 50% max, … sweet spot being 35%
/// compression"). The smallest ε0 is the conservative end: a given thermal contraction
/// (α_r − α_h) ΔT takes the largest fraction of it (docs/model.md §6).
pub const DEFAULT_FLAT_COMPRESSION: f64 = 0.10;
pub(super) const WIDTH: Field = field(
    "seal.width",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 10.0),
);
pub(super) const LENGTH: Field = field(
    "seal.length",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 10.0),
);

// --- O-ring ---

pub(super) const MEAN_DIAMETER: Field = field(
    "seal.mean_diameter",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 10.0),
);

/// The keys of each seal kind (for the messages).
const FLAT_KEYS: &str = "nominal_pressure, width, length, loading and thickness; under \
                         displacement loading also compression, housing or housing_expansion, \
                         and installation_temperature";
const ORING_KEYS: &str = "cross_section, mean_diameter, squeeze, loading, housing or \
                          housing_expansion, installation_temperature, and gland with its ring \
                          and groove keys";

impl Source<'_> {
    /// `[seal]`: `kind = "flat"` (default) or `"o-ring"`; an O-ring swollen by the fluid's
    /// `swell` (docs/model.md §3.8): the cord (and a seated ring's inside diameter) × λ_s in the
    /// same gland.
    pub(super) fn seal(
        &self,
        table: &Spanned<RawSeal>,
        swell: Option<&VolumeSwell>,
    ) -> Result<SealSpec, ScenarioError> {
        let raw = table.get_ref();
        let name = raw
            .kind
            .as_ref()
            .map_or(KINDS[0].name, |k| k.get_ref().as_str());
        let kind = KINDS.iter().find(|k| k.name == name);
        let seal = SealTable {
            source: self,
            table,
            raw,
            // the kind with its article, for the messages (an unknown kind is rejected below)
            a_seal: kind.map_or(KINDS[0].a_seal, |k| k.a_seal),
        };
        let loading = self.loading(raw)?;
        match kind {
            Some(kind) => (kind.read)(&seal, loading, swell),
            None => {
                let span = raw.kind.as_ref().map_or(table.span(), Spanned::span);
                Err(self.error(
                    span,
                    "seal.kind",
                    format!("must be {}, got {name:?}", one_of(&KIND_NAMES)),
                ))
            }
        }
    }

    /// `seal.loading`: displacement (default) or force.
    fn loading(&self, raw: &RawSeal) -> Result<Loading, ScenarioError> {
        match &raw.loading {
            None => Ok(Loading::Displacement),
            Some(l) => match l.get_ref().as_str() {
                "displacement" => Ok(Loading::Displacement),
                "force" => Ok(Loading::Force),
                other => Err(self.error(
                    l.span(),
                    "seal.loading",
                    format!(
                        "must be \"displacement\" (fixed squeeze, e.g. an O-ring in a groove) \
                         or \"force\" (fixed load, e.g. spring-loaded), got {other:?}"
                    ),
                )),
            },
        }
    }
}

/// A `[seal]` table being read: the file, the table, and the seal's kind with its article for
/// the messages ("a flat seal").
struct SealTable<'s, 'a> {
    source: &'s Source<'a>,
    table: &'s Spanned<RawSeal>,
    raw: &'s RawSeal,
    a_seal: &'static str,
}

impl SealTable<'_, '_> {
    /// The value of `q`, a key this seal needs (its kind's `keys` named when missing).
    fn required(&self, q: &Option<Quantity>, f: &Field, keys: &str) -> Result<f64, ScenarioError> {
        self.source.required(
            q,
            f,
            self.table.span(),
            &format!("in [seal] ({} needs {keys})", self.a_seal),
        )
    }

    /// The first of `keys` present, refused: this seal `takes` other keys.
    fn foreign(
        &self,
        keys: &[(&Option<Quantity>, &str)],
        takes: &str,
    ) -> Result<(), ScenarioError> {
        for (present, key) in keys {
            if let Some(q) = present {
                return Err(self.source.error(
                    q.span(),
                    &format!("seal.{key}"),
                    format!("not a key of {}, which takes {takes}", self.a_seal),
                ));
            }
        }
        Ok(())
    }

    /// A flat seal: `nominal_pressure`, `width`, `length`, optional `thickness`. Under
    /// displacement loading (a bolted gasket) its compression follows the temperature
    /// (docs/model.md §6): `compression` (default [`DEFAULT_FLAT_COMPRESSION`]), the flanges'
    /// `housing` or `housing_expansion` (default steel) and `installation_temperature` (the
    /// bolting's, default 23 °C). Under force loading those keys would change nothing (the
    /// bolts or springs hold the load) and are refused.
    fn flat(&self, loading: Loading) -> Result<SealSpec, ScenarioError> {
        let raw = self.raw;
        self.foreign(
            &[
                (&raw.cross_section, "cross_section"),
                (&raw.mean_diameter, "mean_diameter"),
                (&raw.squeeze, "squeeze"),
            ],
            FLAT_KEYS,
        )?;
        if let Some(span) = raw.gland.as_ref().map(Spanned::span) {
            return Err(self.source.error(
                span,
                "seal.gland",
                "applies to an O-ring seated in a groove, not a flat gasket (kind = \"flat\", \
                 the default): set kind = \"o-ring\" for a groove-seated ring, or remove gland",
            ));
        }
        for (key, span) in super::gland::gland_only_keys(raw) {
            if let Some(span) = span {
                return Err(self.source.error(
                    span,
                    &format!("seal.{key}"),
                    format!(
                        "applies to an O-ring gland, not a flat gasket (kind = \"flat\", the \
                         default), which takes {FLAT_KEYS}"
                    ),
                ));
            }
        }
        if loading == Loading::Force {
            let q = |q: &Option<Quantity>| q.as_ref().map(Spanned::span);
            for (key, span) in [
                ("compression", q(&raw.compression)),
                ("housing", raw.housing.as_ref().map(Spanned::span)),
                ("housing_expansion", q(&raw.housing_expansion)),
                ("installation_temperature", q(&raw.installation_temperature)),
            ] {
                if let Some(span) = span {
                    return Err(self.source.error(
                        span,
                        &format!("seal.{key}"),
                        "applies to the thermal strain of a gasket held at a fixed compression \
                         (loading = \"displacement\"); under loading = \"force\" the bolts or \
                         springs keep the load whatever the temperature, so it would change \
                         nothing: remove it, or set loading = \"displacement\"",
                    ));
                }
            }
        }
        let displaced = loading == Loading::Displacement;
        let housing_expansion = if displaced {
            Some(
                self.source
                    .housing_expansion(raw)?
                    .unwrap_or(HousingExpansion {
                        value: Housing::Steel.expansion(),
                        span: raw.kind.as_ref().map_or(self.table.span(), Spanned::span),
                        key: "seal.kind",
                        by_default: true,
                    }),
            )
        } else {
            None
        };
        let installation_temperature = match &raw.installation_temperature {
            Some(q) => Some(
                self.source
                    .absolute_temperature(q, "seal.installation_temperature")?,
            ),
            // by default the hotter of 23 °C and T(0), set once the environment is known
            // (SealSpec::thermal_reference)
            None => None,
        };
        let thickness = self.source.optional(raw.thickness.as_ref(), &THICKNESS)?;
        Ok(SealSpec {
            geometry: SealGeometry::Flat {
                nominal_pressure: self.required(
                    &raw.nominal_pressure,
                    &NOMINAL_PRESSURE,
                    FLAT_KEYS,
                )?,
                width: self.required(&raw.width, &WIDTH, FLAT_KEYS)?,
                length: self.required(&raw.length, &LENGTH, FLAT_KEYS)?,
                compression: self
                    .source
                    .optional(raw.compression.as_ref(), &COMPRESSION)?
                    .unwrap_or(DEFAULT_FLAT_COMPRESSION),
                thickness,
            },
            gland: None,
            energisation_factor: 0.0,
            loading,
            housing_expansion,
            installation_temperature,
            // the bolting temperature is the thermal strain's reference only: the installation
            // ramp runs at T(0), as before
            fitting_temperature: None,
            design: None,
            warnings: Vec::new(),
            thickness,
        })
    }

    /// An O-ring: seated in a gland (`gland`), or squeezed between plates.
    fn o_ring(
        &self,
        loading: Loading,
        swell: Option<&VolumeSwell>,
    ) -> Result<SealSpec, ScenarioError> {
        let raw = self.raw;
        self.foreign(
            &[
                (&raw.nominal_pressure, "nominal_pressure"),
                (&raw.width, "width"),
                (&raw.length, "length"),
                (&raw.thickness, "thickness"),
                (&raw.compression, "compression"),
            ],
            ORING_KEYS,
        )?;
        if let Some(gland) = &raw.gland {
            let kind = self.source.gland_kind(gland)?;
            return self
                .source
                .gland_seal(self.table, kind, gland.span(), loading, swell);
        }
        for (key, span) in super::gland::gland_only_keys(raw) {
            if let Some(span) = span {
                return Err(self.source.error(
                    span,
                    &format!("seal.{key}"),
                    "only applies to a groove-seated ring: set gland = \"face\", \
                     \"piston\" or \"rod\" (without gland the ring is squeezed \
                     between plates, given by cross_section, mean_diameter and squeeze)",
                ));
            }
        }
        self.plate_o_ring(loading, swell)
    }

    /// An O-ring between plates: `cross_section`, `mean_diameter` and `squeeze`, with the
    /// thermal strain's `housing` and `installation_temperature`.
    fn plate_o_ring(
        &self,
        loading: Loading,
        swell: Option<&VolumeSwell>,
    ) -> Result<SealSpec, ScenarioError> {
        let raw = self.raw;
        let cross_section = self.required(&raw.cross_section, &CROSS_SECTION, ORING_KEYS)?;
        let mean_diameter = self.required(&raw.mean_diameter, &MEAN_DIAMETER, ORING_KEYS)?;
        let squeeze = self.required(&raw.squeeze, &SQUEEZE, ORING_KEYS)?;
        if mean_diameter <= cross_section {
            let span = raw
                .mean_diameter
                .as_ref()
                .map_or(self.table.span(), Spanned::span);
            return Err(self.source.error(
                span,
                MEAN_DIAMETER.key,
                format!(
                    "must exceed the cross_section ({} m), got {} m",
                    show(cross_section),
                    show(mean_diameter)
                ),
            ));
        }
        let housing_expansion = self.source.housing_expansion(raw)?;
        let installation_temperature = match &raw.installation_temperature {
            Some(q) if housing_expansion.is_none() => {
                return Err(self.source.error(
                    q.span(),
                    "seal.installation_temperature",
                    "the thermal strain it is the reference of is modelled only with \
                     housing or housing_expansion (or in a gland); set one \
                     (housing_expansion = 0 for a housing that does not expand) or \
                     remove installation_temperature",
                ));
            }
            Some(q) => Some(
                self.source
                    .absolute_temperature(q, "seal.installation_temperature")?,
            ),
            None => None,
        };
        let geometry = SealGeometry::ORing {
            cross_section,
            mean_diameter,
            squeeze,
        };
        Ok(SealSpec {
            geometry: swell.map_or(geometry, |s| s.geometry(geometry)),
            gland: None,
            energisation_factor: 0.0,
            loading,
            housing_expansion,
            installation_temperature,
            fitting_temperature: installation_temperature,
            design: None,
            warnings: Vec::new(),
            thickness: None,
        })
    }
}
