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
//! * a face gland's `pressure_side` (`"inside"` | `"outside"`): the wall the ring must bear on;
//! * `energisation_factor` (0–1.5, default 1);
//! * the thermal strain: `housing` XOR `housing_expansion` (default `housing = "steel"`),
//!   `installation_temperature` (default 23 °C).
//!
//! `mean_diameter` (a ring between plates) is refused: the installed mean diameter follows from
//! the ring and its seat.
//!
//! A ring that cannot be assembled is refused with the reason and the nearest AS568 sizes of
//! the same cross-section that fit the given diameter (and the diameter that fits the given
//! ring); the handbook limits warn (the model's decisions in `crate::gland`, docs/model.md
//! §6.2).

use super::as568;
use super::error::{ScenarioError, Source};
use super::raw::{Quantity, RawSeal};
// `seal.cross_section` and `seal.squeeze` are the keys of a ring between plates too: one
// definition each, in `seal_spec` (the key registry names them once).
use super::field::{Bound, Field, field};
use super::seal_spec::{
    CROSS_SECTION, DEFAULT_INSTALLATION_TEMPERATURE, HousingExpansion, SQUEEZE, SealSpec,
};
use crate::gland::{
    GlandDesign, GlandError, GlandKind, Installed, Limit, Locator, MAX_COMPRESSION_GUIDANCE,
    MAX_FILL_GUIDANCE, MAX_STRETCH_GUIDANCE, MIN_FILL_GUIDANCE, NOMINAL_FILL_GUIDANCE,
    PressureSide, Ring, SeatMeasure,
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
        ("fit", raw.fit.as_ref().map(Spanned::span)),
        ("extrusion_gap", q(&raw.extrusion_gap)),
        ("bore_diameter", q(&raw.bore_diameter)),
        ("rod_diameter", q(&raw.rod_diameter)),
        ("groove_outer_diameter", q(&raw.groove_outer_diameter)),
        ("groove_inner_diameter", q(&raw.groove_inner_diameter)),
        (
            "pressure_side",
            raw.pressure_side.as_ref().map(Spanned::span),
        ),
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
        let gland = GlandTable {
            source: self,
            table,
            raw,
            kind,
            a_gland: format!("a {} gland", kind.name()),
        };
        gland.refuse_mean_diameter()?;
        let (ring, size) = gland.ring()?;
        let seat = gland.seat()?;
        let side = gland.pressure_side()?;
        let groove_width = gland.groove_width()?;
        let mut design = GlandDesign {
            kind,
            ring,
            locator: seat.locator,
            gland_depth: 0.0,
            gland_depth_tolerance: 0.0,
            groove_width,
            extrusion_gap: seat.extrusion_gap,
        };
        let depth = gland.gland_depth(&mut design, seat.key)?;
        let swollen = swell_ring(&mut design, swell);
        let dry = Dry { ring, size };
        let installed = design
            .installed()
            .map_err(|e| gland.refusal(&e, &design, &dry, &depth, seat.key, &swollen))?;
        let limits = gland.feasibility(&design, &dry, side, &depth, seat.key, &swollen)?;
        let mut warnings = gland.warnings(&design, &installed, &depth, seat.key, &swollen)?;
        warnings.extend(gland.limit_warnings(&design, &dry, &limits, seat.key));

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
        let gland = crate::gland::Gland {
            backup_rings: gland.backup_rings()?,
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
            // a groove-seated ring is fitted at its installation temperature, 23 °C unless
            // given, like the geometry it is referred to (docs/model.md §5.2, §6.2): not T(0)
            fitting_temperature: Some(installation_temperature),
            design: Some(design),
            warnings,
            thickness: None,
        })
    }

    /// The gland's warnings that depend on the service (docs/model.md §6.2): the squeeze over
    /// the tolerances outside the static or, `dynamic` (a `[motion]` seal), the dynamic
    /// range; and a face ring on the outer wall of a `vacuum` service (a gas whose outlet is
    /// below 1 atm) without `pressure_side` — a vacuum flange usually has its vacuum inside
    /// the ring, where the ring must bear on the inner wall.
    pub(super) fn gland_service_warnings(
        &self,
        table: &Spanned<RawSeal>,
        design: Option<&GlandDesign>,
        dynamic: bool,
        vacuum: bool,
    ) -> Vec<super::InputWarning> {
        let Some(design) = design else {
            return Vec::new();
        };
        let raw = table.get_ref();
        let mut warnings = Vec::new();
        let nominal = design.installed().map(|i| i.squeeze);
        if let (Ok(limits), Ok(nominal)) = (design.feasibility(dynamic), nominal) {
            for l in limits {
                let Limit::Squeeze {
                    min,
                    max,
                    range,
                    dynamic,
                } = l
                else {
                    continue;
                };
                let (span, key) = match (&raw.groove_depth, &raw.squeeze) {
                    (Some(q), _) => (q.span(), GROOVE_DEPTH.key),
                    (None, Some(q)) => (q.span(), SQUEEZE.key),
                    (None, None) => (table.span(), GROOVE_DEPTH.key),
                };
                let why = if min < range.0 {
                    "below it the seal may leak at low pressure (O-Ring Supply Co.: \"under-compression \
                     below 10% risks low-pressure leakage\")"
                } else if dynamic {
                    "above the manufacturers' 16 % maximum for dynamic seals (Kutz, Mechanical \
                     Engineers' Handbook vol. 3, p. 290, citing Parker): friction, wear and \
                     compression set"
                } else {
                    "above the manufacturers' 30 % maximum for static seals (Kutz, Mechanical \
                     Engineers' Handbook vol. 3, p. 290, citing Parker): compression set, and \
                     little room for swell"
                };
                warnings.push(
                    self.error(
                        span,
                        key,
                        format!(
                            "squeeze {}–{} % over the tolerances (nominal {} %), outside the \
                             {}–{} % of a {} gland: {why} [docs/model.md §6.2]",
                            percent(min),
                            percent(max),
                            percent(nominal),
                            show(100.0 * range.0),
                            show(100.0 * range.1),
                            if dynamic {
                                "dynamic ([motion])"
                            } else {
                                "static"
                            }
                        ),
                    )
                    .warning(&crate::codes::GLAND_SQUEEZE_RANGE),
                );
            }
        }
        if vacuum
            && raw.pressure_side.is_none()
            && let (Locator::GrooveOuter(_), Some(q)) =
                (design.locator, raw.groove_outer_diameter.as_ref())
        {
            warnings.push(
                self.error(
                    q.span(),
                    GROOVE_OUTER_DIAMETER.key,
                    "the ring bears on the groove's outer wall (pressure inside), but the \
                     gas's outlet is below 1 atm: a vacuum flange has its vacuum inside \
                     the ring and the pressure outside, which pushes the ring onto the \
                     inner wall, off this seat — give groove_inner_diameter (the ring's ID \
                     on the inner wall), or pressure_side = \"inside\" if the pressure \
                     really is inside [docs/model.md §6.2]",
                )
                .warning(&crate::codes::VACUUM_OUTER_SEAT),
            );
        }
        warnings
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
            GlandError::OverfilledAtMaximumMaterial { .. } => self.error(
                raw.groove_width
                    .as_ref()
                    .map_or(table.span(), Spanned::span),
                GROOVE_WIDTH.key,
                e.to_string(),
            ),
            GlandError::CannotSeat { .. }
            | GlandError::Overstretched { .. }
            | GlandError::Overcompressed { .. }
            | GlandError::WrongWall { .. } => {
                self.error(span_of(locator_key), locator_key, e.to_string())
            }
        }
    }
}

/// A `[seal]` table of a groove-seated ring being read: the file, the table, the gland's kind
/// and its name in the messages ("a piston gland").
struct GlandTable<'s, 'a> {
    source: &'s Source<'a>,
    table: &'s Spanned<RawSeal>,
    raw: &'s RawSeal,
    kind: GlandKind,
    a_gland: String,
}

/// The clearance and the diameter that fixes the stretch.
struct Seat {
    /// The extrusion gap \[m\]: the flange separation of a face gland, half the diametral
    /// clearance of a piston or rod gland.
    extrusion_gap: f64,
    locator: Locator,
    /// The key of the seat's diameter (`seal.gland` for a free face-gland ring).
    key: &'static str,
}

/// The key the gland depth came from (`groove_depth` or `squeeze`) and its value's span.
struct DepthSource {
    span: Range<usize>,
    key: &'static str,
}

/// A fraction as a percentage rounded to 0.1 %.
fn percent(x: f64) -> String {
    show((1000.0 * x).round() / 10.0)
}

/// The fluid's volume swell (docs/model.md §3.8): the ring's free dimensions × λ_s in the gland
/// designed for the dry ring (its depth, from groove_depth or the dry squeeze); the words the
/// messages then add (empty without swell).
fn swell_ring(design: &mut GlandDesign, swell: Option<&VolumeSwell>) -> String {
    swell.map_or(String::new(), |s| {
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
    })
}

/// `e` with the swell's words (`swollen`) after its message.
fn with_swell(e: ScenarioError, swollen: &str) -> ScenarioError {
    match e {
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
    }
}

/// The ring as given (before any swell): its dimensions and, if named, its AS568 size — what
/// the nearest valid sizes are looked up from.
struct Dry {
    ring: Ring,
    size: Option<as568::Size>,
}

/// A length in mm to 0.01 mm.
fn mm(x: f64) -> String {
    show((x * 1e5).round() / 100.0)
}

/// A seat measure in words: "stretch 2.1 %" or "OD compression 1.2 %".
fn measure_words(m: SeatMeasure) -> String {
    match m {
        SeatMeasure::Stretch(v) => format!("stretch {} %", percent(v)),
        SeatMeasure::OdCompression(v) => format!("OD compression {} %", percent(v)),
    }
}

impl GlandTable<'_, '_> {
    /// The span of the seat's key (`bore_diameter`, …), or the table's.
    fn locator_span(&self, locator_key: &str) -> Range<usize> {
        let raw = self.raw;
        match locator_key {
            "seal.groove_outer_diameter" => raw.groove_outer_diameter.as_ref(),
            "seal.groove_inner_diameter" => raw.groove_inner_diameter.as_ref(),
            "seal.bore_diameter" => raw.bore_diameter.as_ref(),
            "seal.rod_diameter" => raw.rod_diameter.as_ref(),
            _ => None,
        }
        .map_or(self.table.span(), Spanned::span)
    }

    /// `pressure_side` (face glands only): `"inside"` or `"outside"`.
    fn pressure_side(&self) -> Result<Option<PressureSide>, ScenarioError> {
        let Some(p) = &self.raw.pressure_side else {
            return Ok(None);
        };
        if self.kind != GlandKind::Face {
            return Err(self.source.error(
                p.span(),
                "seal.pressure_side",
                format!(
                    "not a key of {}: a radial ring is held by its groove whichever side the \
                     pressure is on (it decides only which wall a face ring must bear on); \
                     remove it",
                    self.a_gland
                ),
            ));
        }
        match p.get_ref().as_str() {
            "inside" => Ok(Some(PressureSide::Inside)),
            "outside" => Ok(Some(PressureSide::Outside)),
            other => Err(self.source.error(
                p.span(),
                "seal.pressure_side",
                format!(
                    "must be \"inside\" (the pressure inside the ring: its OD bears on the \
                     groove's outer wall, groove_outer_diameter) or \"outside\" (a vacuum \
                     flange: its ID bears on the inner wall, groove_inner_diameter), got \
                     {other:?}"
                ),
            )),
        }
    }

    /// A refusal `e` at its key, with what would fit: the nearest sizes and the diameter for
    /// this ring (a ring that cannot be seated), the groove width (a groove too small at
    /// maximum material condition); then the swell's words.
    fn refusal(
        &self,
        e: &GlandError,
        design: &GlandDesign,
        dry: &Dry,
        depth: &DepthSource,
        locator_key: &str,
        swollen: &str,
    ) -> ScenarioError {
        let fix = match *e {
            GlandError::Overcompressed { .. }
            | GlandError::Overstretched { .. }
            | GlandError::CannotSeat { .. } => {
                format!(
                    "{}{}",
                    self.groove_diameter_as_bore(design),
                    self.suggestions(design, dry)
                )
            }
            GlandError::OverfilledAtMaximumMaterial { fill, .. } => {
                // the fill is inversely proportional to the width
                format!(
                    "; widen the groove to at least {} mm (fill {} % at maximum material \
                     condition, Parker's guidance) or deepen it",
                    mm(design.groove_width * fill / MAX_FILL_GUIDANCE),
                    show(100.0 * MAX_FILL_GUIDANCE)
                )
            }
            GlandError::WrongWall { side } => self.wall_fix(design, side),
            _ => String::new(),
        };
        let e = self
            .source
            .gland_error(e, depth.span.clone(), depth.key, self.table, locator_key);
        with_swell(
            with_swell(e, &format!("{fix} [docs/model.md §6.2]")),
            swollen,
        )
    }

    /// The refusals [`GlandDesign::installed`] does not make (a face ring on the wrong wall
    /// for `side`, a ring larger than its wall, a groove overfilled at maximum material
    /// condition), and the handbook limits the gland breaks.
    fn feasibility(
        &self,
        design: &GlandDesign,
        dry: &Dry,
        side: Option<PressureSide>,
        depth: &DepthSource,
        locator_key: &str,
        swollen: &str,
    ) -> Result<Vec<Limit>, ScenarioError> {
        let refuse = |e: GlandError| self.refusal(&e, design, dry, depth, locator_key, swollen);
        if let Some(side) = side {
            design.check_side(side).map_err(refuse)?;
        }
        // the squeeze range is checked with the service (static or dynamic): see
        // `Source::gland_service_warnings`
        design.feasibility(false).map_err(refuse)
    }

    /// What to write instead of a face ring's wrong wall for `side`.
    fn wall_fix(&self, design: &GlandDesign, side: PressureSide) -> String {
        let r = &design.ring;
        match side {
            PressureSide::Outside => format!(
                ": give groove_inner_diameter instead of groove_outer_diameter, {}–{} mm for \
                 this ring (its ID {} mm stretched 0–5 %), or pressure_side = \"inside\" if \
                 the pressure is inside",
                mm(r.inner_diameter),
                mm(r.inner_diameter * (1.0 + MAX_STRETCH_GUIDANCE)),
                mm(r.inner_diameter)
            ),
            PressureSide::Inside => {
                let od = r.inner_diameter + 2.0 * r.cross_section;
                format!(
                    ": give groove_outer_diameter instead of groove_inner_diameter, {}–{} mm \
                     for this ring (its OD {} mm compressed 0–3 %), or pressure_side = \
                     \"outside\" if the pressure is outside",
                    mm(od * (1.0 - MAX_COMPRESSION_GUIDANCE)),
                    mm(od),
                    mm(od)
                )
            }
        }
    }

    /// A piston bore that is where the ring's ID would sit (stretch 0–5 %): most likely the
    /// groove diameter written as the bore; the bore it implies.
    fn groove_diameter_as_bore(&self, design: &GlandDesign) -> String {
        let Locator::Bore(b) = design.locator else {
            return String::new();
        };
        let id = design.ring.inner_diameter;
        let s = (b - id) / id;
        if (0.0..=MAX_STRETCH_GUIDANCE).contains(&s) {
            format!(
                "; bore_diameter ({} mm) is a groove diameter for this ring (its ID stretched \
                 {} % onto it): if it is the groove diameter, the bore is {} + 2 × {} = {} mm",
                mm(b),
                percent(s),
                mm(b),
                mm(design.gland_depth),
                mm(b + 2.0 * design.gland_depth)
            )
        } else {
            String::new()
        }
    }

    /// The nearest valid sizes: the AS568 sizes of the ring's cross-section whose seat measure
    /// lies in its band (stretch 0–5 % onto an inner seat, OD compression 0–3 % into an outer
    /// one), nearest the band's middle first (at most three), or the one nearest the band if
    /// none is in it; and the seat diameter that fits the given ring.
    fn suggestions(&self, design: &GlandDesign, dry: &Dry) -> String {
        let Some(own) = design.fit().measure else {
            return String::new();
        };
        // the swell scales the ring in the gland; the sizes are named dry
        let scale = design.ring.cross_section / dry.ring.cross_section;
        let cs = dry.ring.cross_section;
        let same_section = |s: &&as568::Size| match dry.size {
            Some(n) => s.cs_in == n.cs_in && s.dash != n.dash,
            None => (s.cs_in * as568::INCH - cs).abs() <= s.cs_tol_in * as568::INCH,
        };
        let mut candidates: Vec<(as568::Size, SeatMeasure)> = as568::sizes()
            .unwrap_or(&[])
            .iter()
            .filter(same_section)
            .filter_map(|s| {
                let mut d = *design;
                let r = s.ring();
                d.ring = Ring {
                    inner_diameter: r.inner_diameter * scale,
                    inner_diameter_tolerance: r.inner_diameter_tolerance * scale,
                    cross_section: r.cross_section * scale,
                    cross_section_tolerance: r.cross_section_tolerance * scale,
                };
                d.fit().measure.map(|m| (*s, m))
            })
            .collect();
        let middle = |m: SeatMeasure| {
            let (v, lo, hi) = m.band();
            (v - 0.5 * (lo + hi)).abs()
        };
        let seat_words = match design.locator {
            Locator::Bore(_) => "groove diameter",
            Locator::Rod(_) => "groove diameter",
            Locator::GrooveOuter(_) => "groove outer diameter",
            Locator::GrooveInner(_) => "groove inner diameter",
            Locator::Free => "seat",
        };
        let seat = design.fit().seat;
        let name = |s: &as568::Size, m: SeatMeasure| {
            let r = s.ring();
            format!(
                "{} (ID {} mm, OD {} mm: {})",
                s.name(),
                mm(r.inner_diameter),
                mm(r.inner_diameter + 2.0 * r.cross_section),
                measure_words(m)
            )
        };
        let mut inside: Vec<&(as568::Size, SeatMeasure)> = candidates
            .iter()
            .filter(|(_, m)| m.distance() == 0.0)
            .collect();
        inside.sort_by(|a, b| middle(a.1).total_cmp(&middle(b.1)));
        let sizes = if inside.is_empty() {
            candidates.sort_by(|a, b| a.1.distance().total_cmp(&b.1.distance()));
            match candidates.first() {
                Some((s, m)) => format!(
                    "; no AS568 size of this cross-section fits the {} mm {seat_words} within \
                     the recommended band; the nearest is {}",
                    mm(seat),
                    name(s, *m)
                ),
                None => "; no AS568 size has this cross-section".to_owned(),
            }
        } else {
            let list: Vec<String> = inside.iter().take(3).map(|(s, m)| name(s, *m)).collect();
            format!(
                "; nearest valid size{} for the {} mm {seat_words}: {}",
                if list.len() > 1 { "s" } else { "" },
                mm(seat),
                list.join(", ")
            )
        };
        let r = &design.ring;
        let (id, od, h) = (
            r.inner_diameter,
            r.inner_diameter + 2.0 * r.cross_section,
            design.gland_depth,
        );
        let keep = match design.locator {
            Locator::Bore(_) => Some((
                "bore_diameter",
                id + 2.0 * h,
                id * (1.0 + MAX_STRETCH_GUIDANCE) + 2.0 * h,
                "stretch 0–5 % onto B − 2 × depth",
            )),
            Locator::GrooveInner(_) => Some((
                "groove_inner_diameter",
                id,
                id * (1.0 + MAX_STRETCH_GUIDANCE),
                "stretch 0–5 %",
            )),
            Locator::Rod(_) => Some((
                "rod_diameter",
                od * (1.0 - MAX_COMPRESSION_GUIDANCE) - 2.0 * h,
                od - 2.0 * h,
                "OD compression 0–3 % into R + 2 × depth",
            )),
            Locator::GrooveOuter(_) => Some((
                "groove_outer_diameter",
                od * (1.0 - MAX_COMPRESSION_GUIDANCE),
                od,
                "OD compression 0–3 %",
            )),
            Locator::Free => None,
        };
        let keep = keep.map_or(String::new(), |(key, lo, hi, rule)| {
            format!(
                "; or keep this ring ({}) with {key} = {}–{} mm ({rule})",
                measure_words(own),
                mm(lo),
                mm(hi)
            )
        });
        format!("{sizes}{keep}")
    }

    /// The warnings of the handbook limits `limits` (the circumferential compression; the
    /// squeeze range is the service's, `Source::gland_service_warnings`).
    fn limit_warnings(
        &self,
        design: &GlandDesign,
        dry: &Dry,
        limits: &[Limit],
        locator_key: &'static str,
    ) -> Vec<super::InputWarning> {
        limits
            .iter()
            .filter_map(|l| match *l {
                Limit::Compression { compression, seat } => Some(
                    self.source
                        .error(
                            self.locator_span(locator_key),
                            locator_key,
                            format!(
                                "the ring is compressed circumferentially {} % onto the {} mm \
                                 wall that holds it, above the {} % recommended (O-Ring \
                                 Stocks: face rings 1–3 % compressed; Marco Rubber: a rod \
                                 ring compressed or line-to-line on its OD; Apple Rubber: a \
                                 piston ring's ID smaller than its groove diameter): it may \
                                 buckle or be pinched on assembly{} [docs/model.md §6.2]",
                                percent(compression),
                                mm(seat),
                                show(100.0 * MAX_COMPRESSION_GUIDANCE),
                                self.suggestions(design, dry)
                            ),
                        )
                        .warning(&crate::codes::CIRCUMFERENTIAL_COMPRESSION),
                ),
                Limit::Squeeze { .. } => None,
            })
            .collect()
    }

    /// `present`, a key this gland does not take, refused with the keys it takes `instead`.
    fn refuse(
        &self,
        present: &Option<Quantity>,
        key: &str,
        instead: &str,
    ) -> Result<(), ScenarioError> {
        match present {
            Some(q) => Err(self.source.error(
                q.span(),
                &format!("seal.{key}"),
                format!("not a key of {}, which takes {instead}", self.a_gland),
            )),
            None => Ok(()),
        }
    }

    /// The diametral clearance of a piston or rod gland: as `given`, checked against the ISO
    /// 286 `fit` at the seat `diameter` \[m\] when both are given; the fit's largest (the
    /// conservative end for extrusion, docs/model.md §6.2.1) when only the fit is.
    fn fit_clearance(&self, given: Option<f64>, diameter: f64) -> Result<f64, ScenarioError> {
        let Some(fit) = &self.raw.fit else {
            return given.ok_or_else(|| {
                self.missing(
                    "diametral_clearance",
                    "the diametral clearance (bore minus piston, or housing bore minus rod; 0 \
                     for none) or the `fit` (\"H8/f7\"), which decides extrusion",
                )
            });
        };
        // clearances are tens of µm: to 1 µm
        let mm3 = |v: f64| format!("{:.3}", v * 1e3);
        let bad = |message: String| self.source.error(fit.span(), "seal.fit", message);
        let (min, max) = crate::fits::Fit::parse(fit.get_ref())
            .and_then(|f| f.clearance(diameter))
            .map_err(|e| bad(e.to_string()))?;
        if min < 0.0 {
            return Err(bad(format!(
                "{} is not a clearance fit at {} mm (clearance {} … {} mm): a seal's piston \
                 or rod must move; choose a shaft d, e, f, g or h with hole H",
                fit.get_ref(),
                mm3(diameter),
                mm3(min),
                mm3(max)
            )));
        }
        match given {
            None => Ok(max),
            // 1 nm: the rounding of a clearance typed in mm
            Some(c) if c >= min - 1e-9 && c <= max + 1e-9 => Ok(c),
            Some(c) => Err(bad(format!(
                "diametral_clearance {} mm is outside the {} clearance {} … {} mm at {} mm: \
                 remove diametral_clearance (the fit's largest is used) or fix one of them",
                mm3(c),
                fit.get_ref(),
                mm3(min),
                mm3(max),
                mm3(diameter)
            ))),
        }
    }

    /// `key`, which this gland needs for `what`, missing from the table.
    fn missing(&self, key: &str, what: &str) -> ScenarioError {
        self.source.error(
            self.table.span(),
            &format!("seal.{key}"),
            format!(
                "missing key `{key}` in [seal]: {} needs {what}",
                self.a_gland
            ),
        )
    }

    /// `mean_diameter` is refused: it follows from the ring stretched onto its seat.
    fn refuse_mean_diameter(&self) -> Result<(), ScenarioError> {
        if let Some(q) = &self.raw.mean_diameter {
            return Err(self.source.error(
                q.span(),
                "seal.mean_diameter",
                format!(
                    "not a key of a groove-seated ring ({}): its mean diameter follows \
                     from the ring (size, or cross_section and inner_diameter) stretched onto its \
                     seat; remove mean_diameter, or remove gland for a ring squeezed between \
                     plates",
                    self.a_gland
                ),
            ));
        }
        Ok(())
    }

    /// The ring: `size` (returned too), or `cross_section` and `inner_diameter`.
    fn ring(&self) -> Result<(Ring, Option<as568::Size>), ScenarioError> {
        let raw = self.raw;
        let mut named = None;
        let ring = match (&raw.size, &raw.cross_section, &raw.inner_diameter) {
            (Some(size), cs, id) => {
                for (present, key) in [(cs, "cross_section"), (id, "inner_diameter")] {
                    if let Some(q) = present {
                        return Err(self.source.error(
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
                let found = as568::lookup(size.get_ref())
                    .map_err(|e| self.source.error(size.span(), "seal.size", e.to_string()))?;
                named = Some(found);
                found.ring()
            }
            (None, Some(cs), Some(id)) => Ring {
                inner_diameter: self.source.quantity(id, &INNER_DIAMETER)?,
                inner_diameter_tolerance: 0.0,
                cross_section: self.source.quantity(cs, &CROSS_SECTION)?,
                cross_section_tolerance: 0.0,
            },
            (None, Some(_), None) => {
                return Err(self.missing(
                    "inner_diameter",
                    "the ring's free inside diameter with its cross_section (or a size such as \
                     \"AS568-214\")",
                ));
            }
            (None, None, _) => {
                return Err(self.missing(
                    "size",
                    "its ring: a size such as \"AS568-214\", or cross_section and \
                     inner_diameter",
                ));
            }
        };
        Ok((ring, named))
    }

    /// The clearance and the diameter that fixes the stretch, by the gland's kind.
    fn seat(&self) -> Result<Seat, ScenarioError> {
        match self.kind {
            GlandKind::Face => self.face_seat(),
            GlandKind::Piston | GlandKind::Rod => self.radial_seat(),
        }
    }

    /// A face gland: `extrusion_gap` (default 0) and the groove wall the ring rests on.
    fn face_seat(&self) -> Result<Seat, ScenarioError> {
        let raw = self.raw;
        self.refuse(
            &raw.diametral_clearance,
            "diametral_clearance",
            "extrusion_gap (the flange separation, default 0)",
        )?;
        if let Some(fit) = &raw.fit {
            return Err(self.source.error(
                fit.span(),
                "seal.fit",
                format!(
                    "not a key of {}: a face gland has no bore-and-piston fit (its gap is \
                     extrusion_gap, the flange separation); remove it",
                    self.a_gland
                ),
            ));
        }
        self.refuse(
            &raw.bore_diameter,
            "bore_diameter",
            "groove_outer_diameter or groove_inner_diameter",
        )?;
        self.refuse(
            &raw.rod_diameter,
            "rod_diameter",
            "groove_outer_diameter or groove_inner_diameter",
        )?;
        let gap = self
            .source
            .optional(raw.extrusion_gap.as_ref(), &EXTRUSION_GAP)?
            .unwrap_or(0.0);
        let (locator, key) = match (&raw.groove_outer_diameter, &raw.groove_inner_diameter) {
            (Some(_), Some(q)) => {
                return Err(self.source.error(
                    q.span(),
                    GROOVE_INNER_DIAMETER.key,
                    "the ring rests on one wall: give groove_outer_diameter (pressure \
                     inside: the ring's OD on the outer wall) or groove_inner_diameter \
                     (pressure outside: its ID on the inner wall), not both",
                ));
            }
            (Some(q), None) => (
                Locator::GrooveOuter(self.source.quantity(q, &GROOVE_OUTER_DIAMETER)?),
                GROOVE_OUTER_DIAMETER.key,
            ),
            (None, Some(q)) => (
                Locator::GrooveInner(self.source.quantity(q, &GROOVE_INNER_DIAMETER)?),
                GROOVE_INNER_DIAMETER.key,
            ),
            (None, None) => (Locator::Free, "seal.gland"),
        };
        Ok(Seat {
            extrusion_gap: gap,
            locator,
            key,
        })
    }

    /// A piston or rod gland: `diametral_clearance` (the extrusion gap is half of it) and the
    /// bore or rod diameter the ring is stretched on.
    fn radial_seat(&self) -> Result<Seat, ScenarioError> {
        let (raw, kind) = (self.raw, self.kind);
        self.refuse(
            &raw.extrusion_gap,
            "extrusion_gap",
            "diametral_clearance (the extrusion gap is half of it)",
        )?;
        for (present, key) in [
            (&raw.groove_outer_diameter, "groove_outer_diameter"),
            (&raw.groove_inner_diameter, "groove_inner_diameter"),
        ] {
            self.refuse(
                present,
                key,
                if kind == GlandKind::Piston {
                    "bore_diameter"
                } else {
                    "rod_diameter"
                },
            )?;
        }
        let given = match &raw.diametral_clearance {
            Some(q) => Some(self.source.quantity(q, &DIAMETRAL_CLEARANCE)?),
            None => None,
        };
        let (own, other, field) = if kind == GlandKind::Piston {
            (&raw.bore_diameter, &raw.rod_diameter, &BORE_DIAMETER)
        } else {
            (&raw.rod_diameter, &raw.bore_diameter, &ROD_DIAMETER)
        };
        let own_key = field.key.trim_start_matches("seal.");
        self.refuse(
            other,
            if kind == GlandKind::Piston {
                "rod_diameter"
            } else {
                "bore_diameter"
            },
            own_key,
        )?;
        let diameter = match own {
            Some(q) => self.source.quantity(q, field)?,
            None => {
                return Err(self.missing(
                    own_key,
                    "the diameter the ring is stretched on (the groove bottom is \
                     bore − 2·groove_depth for a piston, the ring sits on the rod of a \
                     rod gland)",
                ));
            }
        };
        let clearance = self.fit_clearance(given, diameter)?;
        let locator = if kind == GlandKind::Piston {
            Locator::Bore(diameter)
        } else {
            Locator::Rod(diameter)
        };
        Ok(Seat {
            extrusion_gap: 0.5 * clearance,
            locator,
            key: field.key,
        })
    }

    /// `groove_width` (required).
    fn groove_width(&self) -> Result<f64, ScenarioError> {
        match &self.raw.groove_width {
            Some(q) => self.source.quantity(q, &GROOVE_WIDTH),
            None => Err(self.missing("groove_width", "the groove's width (for the gland fill)")),
        }
    }

    /// The gland depth h of `design`, from `groove_depth` (with its tolerance) or from
    /// `squeeze`; a face gland's depth includes the flange separation.
    fn gland_depth(
        &self,
        design: &mut GlandDesign,
        locator_key: &str,
    ) -> Result<DepthSource, ScenarioError> {
        let raw = self.raw;
        let gap_in_depth = if self.kind == GlandKind::Face {
            design.extrusion_gap
        } else {
            0.0
        };
        let depth = match (&raw.groove_depth, &raw.squeeze) {
            (Some(_), Some(s)) => {
                return Err(self.source.error(
                    s.span(),
                    SQUEEZE.key,
                    "squeeze and groove_depth are two sources of truth for one number: give \
                     groove_depth (the squeeze then follows from the ring) or squeeze (the \
                     depth then follows), not both",
                ));
            }
            (Some(q), None) => {
                let depth = self.source.quantity(q, &GROOVE_DEPTH)?;
                design.gland_depth = depth + gap_in_depth;
                design.gland_depth_tolerance = self.depth_tolerance(depth)?;
                DepthSource {
                    span: q.span(),
                    key: GROOVE_DEPTH.key,
                }
            }
            (None, Some(s)) => {
                if let Some(t) = &raw.groove_depth_tolerance {
                    return Err(self.source.error(
                        t.span(),
                        GROOVE_DEPTH_TOLERANCE.key,
                        "applies to groove_depth, which squeeze replaces here; remove it (or \
                         give groove_depth instead of squeeze)",
                    ));
                }
                let squeeze = self.source.quantity(s, &SQUEEZE)?;
                design.gland_depth = design.depth_for_squeeze(squeeze).map_err(|e| {
                    self.source
                        .gland_error(&e, s.span(), SQUEEZE.key, self.table, locator_key)
                })?;
                DepthSource {
                    span: s.span(),
                    key: SQUEEZE.key,
                }
            }
            (None, None) => {
                return Err(self.missing(
                    "groove_depth",
                    "the depth the cord is squeezed into (or squeeze instead)",
                ));
            }
        };
        if self.kind == GlandKind::Face && design.gland_depth <= gap_in_depth {
            // squeeze given: the implied groove depth would not be positive
            return Err(self.source.error(
                depth.span,
                depth.key,
                format!(
                    "the squeeze implies a gland depth of {} m, not more than the flange \
                     separation extrusion_gap ({} m): no groove is left",
                    show(design.gland_depth),
                    show(design.extrusion_gap)
                ),
            ));
        }
        Ok(depth)
    }

    /// `groove_depth_tolerance` (±, default 0), smaller than the groove's `depth`.
    fn depth_tolerance(&self, depth: f64) -> Result<f64, ScenarioError> {
        let Some(t) = &self.raw.groove_depth_tolerance else {
            return Ok(0.0);
        };
        let tolerance = self.source.quantity(t, &GROOVE_DEPTH_TOLERANCE)?;
        if tolerance >= depth {
            return Err(self.source.error(
                t.span(),
                GROOVE_DEPTH_TOLERANCE.key,
                format!(
                    "must be smaller than groove_depth ({} m), got {} m",
                    show(depth),
                    show(tolerance)
                ),
            ));
        }
        Ok(tolerance)
    }

    /// The design's warnings, in order: the squeeze at the tolerance limits, the gland fill,
    /// the stretch.
    fn warnings(
        &self,
        design: &GlandDesign,
        installed: &Installed,
        depth: &DepthSource,
        locator_key: &'static str,
        swollen: &str,
    ) -> Result<Vec<super::InputWarning>, ScenarioError> {
        let at_depth = |e: &GlandError| {
            self.source
                .gland_error(e, depth.span.clone(), depth.key, self.table, locator_key)
        };
        let mut warnings = Vec::new();
        let range = design.squeeze_range().map_err(|e| at_depth(&e))?;
        if range.min <= 0.0 {
            warnings.push(
                self.source
                    .error(
                        depth.span.clone(),
                        depth.key,
                        format!(
                            "at the tolerance limits the squeeze falls to {} % (nominal {} %): \
                             the cord may not touch both walls",
                            show(100.0 * range.min),
                            show(100.0 * range.nominal)
                        ),
                    )
                    .warning(&crate::codes::SQUEEZE_AT_TOLERANCE),
            );
        }
        let fill = design.max_material_fill().map_err(|e| at_depth(&e))?;
        warnings.extend(self.fill_warning(installed.fill, fill, swollen));
        warnings.extend(self.stretch_warning(installed.stretch, locator_key));
        Ok(warnings)
    }

    /// A gland fill above the guidance (`nominal` or at maximum material condition,
    /// `max_material`) or below half the groove [docs/model.md §6.2].
    fn fill_warning(
        &self,
        nominal: f64,
        max_material: f64,
        swollen: &str,
    ) -> Option<super::InputWarning> {
        let width_span = self
            .raw
            .groove_width
            .as_ref()
            .map_or(self.table.span(), Spanned::span);
        let (code, message) = if max_material > MAX_FILL_GUIDANCE || nominal > NOMINAL_FILL_GUIDANCE
        {
            (
                &crate::codes::GLAND_OVERFILL,
                format!(
                    "gland fill {} % nominal, {} % at maximum material condition: above the \
                 85 % nominal (O-Ring Supply Co.) or 90 % maximum-material (Parker, gland \
                 overfill) guidance: little room for thermal expansion or swell{swollen}; \
                 widen the groove [docs/model.md §6.2]",
                    percent(nominal),
                    percent(max_material)
                ),
            )
        } else if nominal < MIN_FILL_GUIDANCE {
            (
                &crate::codes::GLAND_UNDERFILL,
                format!(
                    "gland fill {} %: the ring fills less than half its groove (the usual \
                 range is 65–85 %, O-Ring Supply Co.): it can shift and roll — is the \
                 groove width or depth in the intended unit? [docs/model.md §6.2]",
                    percent(nominal)
                ),
            )
        } else {
            return None;
        };
        Some(
            self.source
                .error(width_span, GROOVE_WIDTH.key, message)
                .warning(code),
        )
    }

    /// A ring stretched onto its seat (at `locator_key`) beyond the 5 % recommended.
    fn stretch_warning(
        &self,
        stretch: f64,
        locator_key: &'static str,
    ) -> Option<super::InputWarning> {
        let raw = self.raw;
        let span = match locator_key {
            "seal.groove_outer_diameter" => raw.groove_outer_diameter.as_ref(),
            "seal.groove_inner_diameter" => raw.groove_inner_diameter.as_ref(),
            "seal.bore_diameter" => raw.bore_diameter.as_ref(),
            "seal.rod_diameter" => raw.rod_diameter.as_ref(),
            _ => None,
        }
        .map_or(self.table.span(), Spanned::span);
        (stretch > MAX_STRETCH_GUIDANCE).then(|| {
            self.source
                .error(
                    span,
                    locator_key,
                    format!(
                        "the ring is stretched {} % onto its seat, above the 5 % recommended \
                         (Parker; Apple Rubber: more ages it faster and thins its cord): choose \
                         a ring with a larger inside diameter [docs/model.md §6.2]",
                        percent(stretch)
                    ),
                )
                .warning(&crate::codes::STRETCH)
        })
    }

    /// `backup_rings`: 0 (default), 1 or 2.
    fn backup_rings(&self) -> Result<u8, ScenarioError> {
        match &self.raw.backup_rings {
            None => Ok(0),
            Some(n) => match *n.get_ref() {
                k @ 0..=2 => Ok(k as u8),
                k => Err(self.source.error(
                    n.span(),
                    "seal.backup_rings",
                    format!(
                        "{k} back-up rings: give 0 (none), 1 (on the low-pressure side) or 2 \
                         (one each side, for a pressure that may reverse) \
                         [docs/model.md §6.3]"
                    ),
                )),
            },
        }
    }
}
