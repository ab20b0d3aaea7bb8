//! `[seal]` of a groove-seated O-ring (`gland = "face" | "piston" | "rod"`) → a
//! [`GlandDesign`] and the O-ring geometry the life model runs on (docs/model.md §6.2).
//!
//! Keys (README, "Scenario file reference"):
//! * the ring: `size = "AS568-214"` XOR `cross_section` + `inner_diameter` (free ID);
//! * the groove: `groove_width` (required), `groove_depth` (required unless `squeeze` is given
//!   instead; never both) with optional `groove_depth_tolerance` (±);
//! * the clearance: `diametral_clearance` (piston, rod; required; extrusion gap = half of it)
//!   or `extrusion_gap` (face: the flange separation, default 0);
//! * the diameter that fixes the stretch: `bore_diameter` (piston, required), `rod_diameter`
//!   (rod, required), `groove_outer_diameter` or `groove_inner_diameter` (face, optional);
//! * `energisation_factor` (0–1.5, default 1);
//! * the thermal strain: `housing` XOR `housing_expansion` (default `housing = "steel"`),
//!   `installation_temperature` (default 23 °C).
//!
//! `mean_diameter` (a ring between plates) is refused: the installed mean diameter follows from
//! the ring and its seat.

use super::as568;
use super::error::{ScenarioError, Source};
use super::life::{HousingExpansion, SealSpec};
use super::raw::{Quantity, RawSeal};
// `seal.cross_section` and `seal.squeeze` are the keys of a ring between plates too: one
// definition each, in `life` (the key registry, `super::keys`, names them once).
use super::life::{CROSS_SECTION, SQUEEZE};
use super::validate::{Bound, Field, field};
use crate::gland::{
    GlandDesign, GlandError, GlandKind, Locator, MAX_FILL_GUIDANCE, MAX_STRETCH_GUIDANCE,
    MIN_FILL_GUIDANCE, NOMINAL_FILL_GUIDANCE, Ring,
};
use crate::seal::{SealGeometry, VolumeSwell};
use crate::simulate::Loading;
use crate::units::{Dimension, show};
use std::ops::Range;
use toml::Spanned;

const fn length(key: &'static str, bound: Bound) -> Field {
    field(key, Dimension::LENGTH, "m", bound)
}

pub(super) const INNER_DIAMETER: Field = length("seal.inner_diameter", Bound::Range(1e-9, 10.0));
pub(super) const GROOVE_DEPTH: Field = length("seal.groove_depth", Bound::Range(1e-9, 10.0));
pub(super) const GROOVE_DEPTH_TOLERANCE: Field =
    length("seal.groove_depth_tolerance", Bound::Range(0.0, 10.0));
pub(super) const GROOVE_WIDTH: Field = length("seal.groove_width", Bound::Range(1e-9, 10.0));
pub(super) const DIAMETRAL_CLEARANCE: Field =
    length("seal.diametral_clearance", Bound::Range(0.0, 10.0));
pub(super) const EXTRUSION_GAP: Field = length("seal.extrusion_gap", Bound::Range(0.0, 10.0));
pub(super) const BORE_DIAMETER: Field = length("seal.bore_diameter", Bound::Range(1e-9, 10.0));
pub(super) const ROD_DIAMETER: Field = length("seal.rod_diameter", Bound::Range(1e-9, 10.0));
pub(super) const GROOVE_OUTER_DIAMETER: Field =
    length("seal.groove_outer_diameter", Bound::Range(1e-9, 10.0));
pub(super) const GROOVE_INNER_DIAMETER: Field =
    length("seal.groove_inner_diameter", Bound::Range(1e-9, 10.0));
pub(super) const ENERGISATION_FACTOR: Field = field(
    "seal.energisation_factor",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(0.0, 1.5),
);

/// Default energisation factor of a groove-seated ring (docs/model.md §6.3).
pub const DEFAULT_ENERGISATION_FACTOR: f64 = 1.0;
/// Default installation temperature of a groove-seated ring: 23 °C \[K\].
pub const DEFAULT_INSTALLATION_TEMPERATURE: f64 = 296.15;

/// The keys that belong to a groove-seated ring only, with their values' spans (for the
/// message when `gland` is absent).
pub(super) fn gland_only_keys(raw: &RawSeal) -> Vec<(&'static str, Option<Range<usize>>)> {
    let q = |q: &Option<Quantity>| q.as_ref().map(Spanned::span);
    vec![
        ("size", raw.size.as_ref().map(Spanned::span)),
        ("inner_diameter", q(&raw.inner_diameter)),
        ("groove_depth", q(&raw.groove_depth)),
        ("groove_depth_tolerance", q(&raw.groove_depth_tolerance)),
        ("groove_width", q(&raw.groove_width)),
        ("diametral_clearance", q(&raw.diametral_clearance)),
        ("extrusion_gap", q(&raw.extrusion_gap)),
        ("bore_diameter", q(&raw.bore_diameter)),
        ("rod_diameter", q(&raw.rod_diameter)),
        ("groove_outer_diameter", q(&raw.groove_outer_diameter)),
        ("groove_inner_diameter", q(&raw.groove_inner_diameter)),
        ("energisation_factor", q(&raw.energisation_factor)),
        ("backup_rings", raw.backup_rings.as_ref().map(Spanned::span)),
    ]
}

impl Source<'_> {
    /// The `gland = "…"` value.
    pub(super) fn gland_kind(&self, gland: &Spanned<String>) -> Result<GlandKind, ScenarioError> {
        match gland.get_ref().as_str() {
            "face" => Ok(GlandKind::Face),
            "piston" => Ok(GlandKind::Piston),
            "rod" => Ok(GlandKind::Rod),
            other => Err(self.error(
                gland.span(),
                "seal.gland",
                format!(
                    "must be \"face\" (axial squeeze between a grooved flange and a flat face), \
                     \"piston\" (groove in the piston, sealing on the bore) or \"rod\" (groove \
                     in the housing, sealing on the rod), got {other:?}"
                ),
            )),
        }
    }

    /// `[seal]` of an O-ring seated in a gland of `kind` (the `gland` key at `gland_span`).
    pub(super) fn gland_seal(
        &self,
        table: &Spanned<RawSeal>,
        kind: GlandKind,
        gland_span: Range<usize>,
        loading: Loading,
        swell: Option<&VolumeSwell>,
    ) -> Result<SealSpec, ScenarioError> {
        let raw = table.get_ref();
        let a_gland = format!("a {} gland", kind.name());
        if let Some(q) = &raw.mean_diameter {
            return Err(self.error(
                q.span(),
                "seal.mean_diameter",
                format!(
                    "not a key of a groove-seated ring ({a_gland}): its mean diameter follows \
                     from the ring (size, or cross_section and inner_diameter) stretched onto its \
                     seat; remove mean_diameter, or remove gland for a ring squeezed between \
                     plates"
                ),
            ));
        }
        let refuse = |present: &Option<Quantity>, key: &str, instead: &str| match present {
            Some(q) => Err(self.error(
                q.span(),
                &format!("seal.{key}"),
                format!("not a key of {a_gland}, which takes {instead}"),
            )),
            None => Ok(()),
        };
        let missing = |key: &str, what: &str| {
            self.error(
                table.span(),
                &format!("seal.{key}"),
                format!("missing key `{key}` in [seal]: {a_gland} needs {what}"),
            )
        };

        // the ring
        let ring = match (&raw.size, &raw.cross_section, &raw.inner_diameter) {
            (Some(size), cs, id) => {
                for (present, key) in [(cs, "cross_section"), (id, "inner_diameter")] {
                    if let Some(q) = present {
                        return Err(self.error(
                            q.span(),
                            &format!("seal.{key}"),
                            format!(
                                "size ({}) gives the ring's dimensions; remove {key} (or remove \
                                 size and give cross_section and inner_diameter)",
                                size.get_ref()
                            ),
                        ));
                    }
                }
                as568::lookup(size.get_ref())
                    .map_err(|e| self.error(size.span(), "seal.size", e.to_string()))?
                    .ring()
            }
            (None, Some(cs), Some(id)) => Ring {
                inner_diameter: self.quantity(id, &INNER_DIAMETER)?,
                inner_diameter_tolerance: 0.0,
                cross_section: self.quantity(cs, &CROSS_SECTION)?,
                cross_section_tolerance: 0.0,
            },
            (None, Some(_), None) => {
                return Err(missing(
                    "inner_diameter",
                    "the ring's free inside diameter with its cross_section (or a size such as \
                     \"AS568-214\")",
                ));
            }
            (None, None, _) => {
                return Err(missing(
                    "size",
                    "its ring: a size such as \"AS568-214\", or cross_section and \
                     inner_diameter",
                ));
            }
        };

        // the clearance and the diameter that fixes the stretch
        let (extrusion_gap, locator, locator_key) = match kind {
            GlandKind::Face => {
                refuse(
                    &raw.diametral_clearance,
                    "diametral_clearance",
                    "extrusion_gap (the flange separation, default 0)",
                )?;
                refuse(
                    &raw.bore_diameter,
                    "bore_diameter",
                    "groove_outer_diameter or groove_inner_diameter",
                )?;
                refuse(
                    &raw.rod_diameter,
                    "rod_diameter",
                    "groove_outer_diameter or groove_inner_diameter",
                )?;
                let gap = self
                    .optional(raw.extrusion_gap.as_ref(), &EXTRUSION_GAP)?
                    .unwrap_or(0.0);
                let (locator, key) = match (&raw.groove_outer_diameter, &raw.groove_inner_diameter)
                {
                    (Some(_), Some(q)) => {
                        return Err(self.error(
                            q.span(),
                            GROOVE_INNER_DIAMETER.key,
                            "the ring rests on one wall: give groove_outer_diameter (pressure \
                             inside: the ring's OD on the outer wall) or groove_inner_diameter \
                             (pressure outside: its ID on the inner wall), not both",
                        ));
                    }
                    (Some(q), None) => (
                        Locator::GrooveOuter(self.quantity(q, &GROOVE_OUTER_DIAMETER)?),
                        GROOVE_OUTER_DIAMETER.key,
                    ),
                    (None, Some(q)) => (
                        Locator::GrooveInner(self.quantity(q, &GROOVE_INNER_DIAMETER)?),
                        GROOVE_INNER_DIAMETER.key,
                    ),
                    (None, None) => (Locator::Free, "seal.gland"),
                };
                (gap, locator, key)
            }
            GlandKind::Piston | GlandKind::Rod => {
                refuse(
                    &raw.extrusion_gap,
                    "extrusion_gap",
                    "diametral_clearance (the extrusion gap is half of it)",
                )?;
                for (present, key) in [
                    (&raw.groove_outer_diameter, "groove_outer_diameter"),
                    (&raw.groove_inner_diameter, "groove_inner_diameter"),
                ] {
                    refuse(
                        present,
                        key,
                        if kind == GlandKind::Piston {
                            "bore_diameter"
                        } else {
                            "rod_diameter"
                        },
                    )?;
                }
                let clearance = match &raw.diametral_clearance {
                    Some(q) => self.quantity(q, &DIAMETRAL_CLEARANCE)?,
                    None => {
                        return Err(missing(
                            "diametral_clearance",
                            "the diametral clearance (bore minus piston, or housing bore minus \
                             rod; 0 for none), which decides extrusion",
                        ));
                    }
                };
                let (own, other, field) = if kind == GlandKind::Piston {
                    (&raw.bore_diameter, &raw.rod_diameter, &BORE_DIAMETER)
                } else {
                    (&raw.rod_diameter, &raw.bore_diameter, &ROD_DIAMETER)
                };
                let own_key = field.key.trim_start_matches("seal.");
                refuse(
                    other,
                    if kind == GlandKind::Piston {
                        "rod_diameter"
                    } else {
                        "bore_diameter"
                    },
                    own_key,
                )?;
                let diameter = match own {
                    Some(q) => self.quantity(q, field)?,
                    None => {
                        return Err(missing(
                            own_key,
                            "the diameter the ring is stretched on (the groove bottom is \
                             bore − 2·groove_depth for a piston, the ring sits on the rod of a \
                             rod gland)",
                        ));
                    }
                };
                let locator = if kind == GlandKind::Piston {
                    Locator::Bore(diameter)
                } else {
                    Locator::Rod(diameter)
                };
                (0.5 * clearance, locator, field.key)
            }
        };

        let groove_width = match &raw.groove_width {
            Some(q) => self.quantity(q, &GROOVE_WIDTH)?,
            None => {
                return Err(missing(
                    "groove_width",
                    "the groove's width (for the gland fill)",
                ));
            }
        };
        let mut design = GlandDesign {
            kind,
            ring,
            locator,
            gland_depth: 0.0,
            gland_depth_tolerance: 0.0,
            groove_width,
            extrusion_gap,
        };
        // the gland depth h: from groove_depth, or from squeeze
        let gap_in_depth = if kind == GlandKind::Face {
            extrusion_gap
        } else {
            0.0
        };
        let (depth_span, depth_key) = match (&raw.groove_depth, &raw.squeeze) {
            (Some(_), Some(s)) => {
                return Err(self.error(
                    s.span(),
                    SQUEEZE.key,
                    "squeeze and groove_depth are two sources of truth for one number: give \
                     groove_depth (the squeeze then follows from the ring) or squeeze (the \
                     depth then follows), not both",
                ));
            }
            (Some(q), None) => {
                let depth = self.quantity(q, &GROOVE_DEPTH)?;
                design.gland_depth = depth + gap_in_depth;
                if let Some(t) = &raw.groove_depth_tolerance {
                    let tolerance = self.quantity(t, &GROOVE_DEPTH_TOLERANCE)?;
                    if tolerance >= depth {
                        return Err(self.error(
                            t.span(),
                            GROOVE_DEPTH_TOLERANCE.key,
                            format!(
                                "must be smaller than groove_depth ({} m), got {} m",
                                show(depth),
                                show(tolerance)
                            ),
                        ));
                    }
                    design.gland_depth_tolerance = tolerance;
                }
                (q.span(), GROOVE_DEPTH.key)
            }
            (None, Some(s)) => {
                if let Some(t) = &raw.groove_depth_tolerance {
                    return Err(self.error(
                        t.span(),
                        GROOVE_DEPTH_TOLERANCE.key,
                        "applies to groove_depth, which squeeze replaces here; remove it (or \
                         give groove_depth instead of squeeze)",
                    ));
                }
                let squeeze = self.quantity(s, &SQUEEZE)?;
                design.gland_depth = design
                    .depth_for_squeeze(squeeze)
                    .map_err(|e| self.gland_error(&e, s.span(), SQUEEZE.key, table, locator_key))?;
                (s.span(), SQUEEZE.key)
            }
            (None, None) => {
                return Err(missing(
                    "groove_depth",
                    "the depth the cord is squeezed into (or squeeze instead)",
                ));
            }
        };
        if kind == GlandKind::Face && design.gland_depth <= gap_in_depth {
            // squeeze given: the implied groove depth would not be positive
            return Err(self.error(
                depth_span,
                depth_key,
                format!(
                    "the squeeze implies a gland depth of {} m, not more than the flange \
                     separation extrusion_gap ({} m): no groove is left",
                    show(design.gland_depth),
                    show(extrusion_gap)
                ),
            ));
        }
        // the fluid's volume swell (docs/model.md §3.8): the ring's free dimensions × λ_s in
        // the gland designed for the dry ring (its depth, from groove_depth or the dry squeeze)
        let swollen = swell.map_or(String::new(), |s| {
            let l = s.linear_stretch();
            design.ring.cross_section *= l;
            design.ring.cross_section_tolerance *= l;
            design.ring.inner_diameter *= l;
            design.ring.inner_diameter_tolerance *= l;
            format!(
                " (the ring swollen by the fluid's volume_swell of {} %: its free dimensions × {})",
                show(100.0 * s.volume_change),
                show(l)
            )
        });
        let with_swell = |e: ScenarioError| match e {
            ScenarioError::Invalid {
                path,
                line,
                key,
                message,
            } => ScenarioError::Invalid {
                path,
                line,
                key,
                message: format!("{message}{swollen}"),
            },
            other => other,
        };
        let installed = design.installed().map_err(|e| {
            with_swell(self.gland_error(&e, depth_span.clone(), depth_key, table, locator_key))
        })?;

        let mut warnings = Vec::new();
        let range = design
            .squeeze_range()
            .map_err(|e| self.gland_error(&e, depth_span.clone(), depth_key, table, locator_key))?;
        if range.min <= 0.0 {
            warnings.push(
                self.error(
                    depth_span.clone(),
                    depth_key,
                    format!(
                        "at the tolerance limits the squeeze falls to {} % (nominal {} %): the \
                         cord may not touch both walls",
                        show(100.0 * range.min),
                        show(100.0 * range.nominal)
                    ),
                )
                .to_string(),
            );
        }
        let fill = design
            .max_material_fill()
            .map_err(|e| self.gland_error(&e, depth_span.clone(), depth_key, table, locator_key))?;
        let width_span = raw
            .groove_width
            .as_ref()
            .map_or(table.span(), Spanned::span);
        let percent = |x: f64| show((1000.0 * x).round() / 10.0);
        if fill > MAX_FILL_GUIDANCE || installed.fill > NOMINAL_FILL_GUIDANCE {
            warnings.push(
                self.error(
                    width_span.clone(),
                    GROOVE_WIDTH.key,
                    format!(
                        "gland fill {} % nominal, {} % at maximum material condition: above the \
                         85 % nominal (O-Ring Supply Co.) or 90 % maximum-material (Parker, gland \
                         overfill) guidance: little room for thermal expansion or swell{swollen}; \
                         widen the groove [docs/model.md §6.2]",
                        percent(installed.fill),
                        percent(fill)
                    ),
                )
                .to_string(),
            );
        } else if installed.fill < MIN_FILL_GUIDANCE {
            warnings.push(
                self.error(
                    width_span,
                    GROOVE_WIDTH.key,
                    format!(
                        "gland fill {} %: the ring fills less than half its groove (the usual \
                         range is 65–85 %, O-Ring Supply Co.): it can shift and roll — is the \
                         groove width or depth in the intended unit? [docs/model.md §6.2]",
                        percent(installed.fill)
                    ),
                )
                .to_string(),
            );
        }
        if installed.stretch > MAX_STRETCH_GUIDANCE {
            let span = match locator_key {
                "seal.groove_outer_diameter" => raw.groove_outer_diameter.as_ref(),
                "seal.groove_inner_diameter" => raw.groove_inner_diameter.as_ref(),
                "seal.bore_diameter" => raw.bore_diameter.as_ref(),
                "seal.rod_diameter" => raw.rod_diameter.as_ref(),
                _ => None,
            }
            .map_or(table.span(), Spanned::span);
            warnings.push(
                self.error(
                    span,
                    locator_key,
                    format!(
                        "the ring is stretched {} % onto its seat, above the 5 % recommended \
                         (Parker; Apple Rubber: more ages it faster and thins its cord): choose \
                         a ring with a larger inside diameter [docs/model.md §6.2]",
                        percent(installed.stretch)
                    ),
                )
                .to_string(),
            );
        }

        let energisation_factor = self
            .optional(raw.energisation_factor.as_ref(), &ENERGISATION_FACTOR)?
            .unwrap_or(DEFAULT_ENERGISATION_FACTOR);
        let housing_expansion = Some(self.housing_expansion(raw)?.unwrap_or(HousingExpansion {
            value: crate::gland::Housing::Steel.expansion(),
            span: gland_span,
            key: "seal.gland",
            by_default: true,
        }));
        let installation_temperature = match &raw.installation_temperature {
            Some(q) => self.absolute_temperature(q, "seal.installation_temperature")?,
            None => DEFAULT_INSTALLATION_TEMPERATURE,
        };
        let backup_rings = match &raw.backup_rings {
            None => 0,
            Some(n) => match *n.get_ref() {
                k @ 0..=2 => k as u8,
                k => {
                    return Err(self.error(
                        n.span(),
                        "seal.backup_rings",
                        format!(
                            "{k} back-up rings: give 0 (none), 1 (on the low-pressure side) or 2 \
                             (one each side, for a pressure that may reverse) \
                             [docs/model.md §6.3]"
                        ),
                    ));
                }
            },
        };
        let gland = crate::gland::Gland {
            backup_rings,
            ..design.gland()
        };
        Ok(SealSpec {
            geometry: SealGeometry::ORing {
                cross_section: installed.cross_section,
                mean_diameter: installed.mean_diameter,
                squeeze: installed.squeeze,
            },
            gland: Some(gland),
            energisation_factor,
            loading,
            housing_expansion,
            installation_temperature: Some(installation_temperature),
            fitting_temperature: raw
                .installation_temperature
                .is_some()
                .then_some(installation_temperature),
            design: Some(design),
            warnings,
            thickness: None,
        })
    }

    /// A [`GlandError`] at the key it belongs to: the depth (or squeeze) for a cord that is not
    /// squeezed or a groove bottom that does not exist, the width for an overfilled groove, the
    /// seat's diameter for a ring that cannot be seated.
    fn gland_error(
        &self,
        e: &GlandError,
        depth_span: Range<usize>,
        depth_key: &str,
        table: &Spanned<RawSeal>,
        locator_key: &str,
    ) -> ScenarioError {
        let raw = table.get_ref();
        let span_of = |key: &str| {
            let q = match key {
                "seal.groove_outer_diameter" => &raw.groove_outer_diameter,
                "seal.groove_inner_diameter" => &raw.groove_inner_diameter,
                "seal.bore_diameter" => &raw.bore_diameter,
                "seal.rod_diameter" => &raw.rod_diameter,
                _ => &None,
            };
            q.as_ref().map_or(table.span(), Spanned::span)
        };
        match e {
            GlandError::GrooveTooDeep { .. } | GlandError::NoGrooveBottom { .. } => {
                self.error(depth_span, depth_key, e.to_string())
            }
            GlandError::Overfilled { .. } => self.error(
                raw.groove_width
                    .as_ref()
                    .map_or(table.span(), Spanned::span),
                GROOVE_WIDTH.key,
                e.to_string(),
            ),
            GlandError::CannotSeat { .. } | GlandError::Overstretched { .. } => {
                self.error(span_of(locator_key), locator_key, e.to_string())
            }
        }
    }
}
