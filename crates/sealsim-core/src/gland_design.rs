//! The gland designer and the tolerance stack-up (docs/model.md §6.2.1): the recommended
//! housing of an AS568 ring for a service (face, piston, rod; static or dynamic; 0, 1 or 2
//! back-up rings), with ISO 286 fits on the diameters ([`crate::fits`]), and the table every
//! gland calculator prints — squeeze, stretch, OD compression, gland fill and extrusion gap at
//! nominal and at the worst-case combinations of every tolerance, at assembly and over the
//! service temperatures — each with the limit it is checked against and where the limit is
//! from.
//!
//! **The tables** (inch, as printed; [`STATIC_RADIAL`], [`DYNAMIC`], [`FACE`]). ISO 3601-2's
//! own numbers were not found in a readable source; the AS568 (ISO 3601-1 class A) tables of
//! the handbooks are used:
//! * static radial and face: The O-Ring Store LLC, "O-Ring Groove Chart", tables "Static O-Ring
//!   Radial Glands" and "Static O-Ring Axial Face Seal Glands"
//!   (<https://www.theoringstore.com/store/index.php?main_page=page&id=39&chapter=6>): gland
//!   depth, squeeze (inch and %), diametral clearance, groove width for 0/1/2 back-up rings
//!   (face: for liquids and gases), groove radius. These are the Parker O-Ring Handbook
//!   (ORD 5700) industrial design-chart values as commonly reproduced; Parker's own chart was
//!   not read.
//! * dynamic (reciprocating) radial: Engineers Edge, "O-Ring Installation Design and
//!   Specification For Dynamic / Reciprocating Applications"
//!   (<http://engineersedge.com/general_engineering/oring_gland_size_dynamic_cylinder.htm>):
//!   gland depth, squeeze, groove width (no back-up ring), radius. It gives neither a clearance
//!   nor back-up-ring widths; its no-back-up widths equal the static table's in every row, so
//!   the static table's clearance and back-up widths are used with it (**assumed**). Its
//!   1/16-in width is printed ".093 to .089" (upper below lower): the static .093–.098 is used.
//!
//! Every table's squeeze column is the stack-up of the cord's AS568 tolerance and the depth
//! range (e.g. static radial −2xx: 0.139 ± 0.004 in in 0.111–0.113 in → 0.022–0.032 in);
//! `tests/model/gland_design.rs` checks that this module reproduces every printed squeeze.
//!
//! **The hardware** a design gives (module [`design`]):
//! * piston: bore A = the ring's AS568 nominal OD (or `--bore`) with the fit's hole class;
//!   piston OD = A with the shaft class; groove (bottom) diameter B chosen so that the gland
//!   depth L = (A − B)/2 stays inside the table's range at every bore in tolerance:
//!   B = [A_max − 2 L_max, A_min − 2 L_min] (U.S. Seal, "General Design and Gland Dimensions",
//!   <http://www.usseal.com/orings/Glanddimensions/general_oring_2.html>: "B min. = A max. minus
//!   2 F max.");
//! * rod: rod R = the ring's nominal ID (or `--rod`) with the shaft class; housing bore = R with
//!   the hole class; groove diameter D = [R_max + 2 L_min, R_min + 2 L_max] (U.S. Seal,
//!   <http://www.usseal.com/orings/Glanddimensions/general_oring_4.html>: "D max. = C min. plus
//!   2F max.");
//! * face: groove depth from the table; metal-to-metal flanges (no extrusion gap); pressure
//!   inside: the groove's outer diameter 1 % under the ring's OD, its tolerance the fit's hole
//!   class; pressure outside (vacuum): the groove's inner diameter 2 % over the ring's ID, the
//!   shaft class. Global O-Ring and Seal, "O-Ring Groove Design"
//!   (<https://www.globaloring.com/o-ring-groove-design/>) asks the OD to be "slightly larger
//!   than the gland outer diameter (max 3%)" and the ID "slightly smaller than the gland inner
//!   diameter (max 5%)"; Apple Rubber ("Dimensional considerations",
//!   <http://www.applerubber.com/seal-design-guide/oring-basics/dimensional-considerations.cfm>)
//!   gives "1%-5% with 2% as the ideal" for a stretched ring. The 1 % and 2 % are **assumed**
//!   within those bands.
//!
//! **The AS568 pairing** ([`as568_nominal`]): a ring's nominal (fractional) ID × OD × W name
//! the hardware it fits — the bore is the nominal OD, the rod the nominal ID (ponnmachine.com,
//! "O-Ring Groove Design", <http://ponnmachine.com/groove_design.html>: bore 1.000 in →
//! AS-568-210, "1 OD x 1/8 W nominal"; rod 0.500 in → AS-568-112, "1/2 ID x 3/32 W nominal").
//! No table of the nominal sizes was found, so they are derived: the nominal OD is the actual
//! OD (ID + 2 W) rounded to 1/16 in (1/32 in for the −0xx and −1xx series), the nominal W the
//! series' fraction (1/16, 3/32, 1/8, 3/16, 1/4 in; Global O-Ring's AS568 chart), the nominal
//! ID = OD − 2 W. It gives −210 → 1.000 in bore, −112 → 0.500 in rod, −214 → 1.250 in bore
//! (tests). Where it is wrong, `--bore`/`--rod` give the diameter.

use crate::extrusion;
use crate::fits::{Fit, FitError};
use crate::gland::{
    self, GlandError, GlandKind, Locator, MAX_FILL_GUIDANCE, MAX_STRETCH_GUIDANCE,
    NOMINAL_FILL_GUIDANCE, Ring,
};
use std::fmt;

/// Metres per inch.
pub const INCH: f64 = 0.0254;
/// The temperature the hardware and the ring are measured and assembled at: 23 °C \[K\].
pub const ASSEMBLY_TEMPERATURE: f64 = 296.15;

/// A (min, max) pair as printed \[in\].
pub type Span = (f64, f64);

/// One row of a gland table (inch, as printed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableRow {
    /// Nominal actual cross-section W \[in\].
    pub cross_section: f64,
    /// Gland depth: L (radial: bore or rod to groove bottom) or the face groove's depth.
    pub depth: Span,
    /// Squeeze \[in\] as printed.
    pub squeeze: Span,
    /// Squeeze \[%\] as printed.
    pub squeeze_percent: Span,
    /// Diametral clearance \[in\] (radial tables).
    pub clearance: Option<Span>,
    /// Groove width G for 0, 1, 2 back-up rings (face: liquids only, in slot 0).
    pub width: [Option<Span>; 3],
    /// Face glands: the groove width for gases (vacuum).
    pub width_gas: Option<Span>,
    /// Groove bottom radius \[in\].
    pub radius: Span,
}

const fn radial(
    cross_section: f64,
    depth: Span,
    squeeze: Span,
    squeeze_percent: Span,
    clearance: Span,
    width: [Span; 3],
    radius: Span,
) -> TableRow {
    TableRow {
        cross_section,
        depth,
        squeeze,
        squeeze_percent,
        clearance: Some(clearance),
        width: [Some(width[0]), Some(width[1]), Some(width[2])],
        width_gas: None,
        radius,
    }
}

const fn face(
    cross_section: f64,
    depth: Span,
    squeeze: Span,
    squeeze_percent: Span,
    liquids: Span,
    gases: Span,
    radius: Span,
) -> TableRow {
    TableRow {
        cross_section,
        depth,
        squeeze,
        squeeze_percent,
        clearance: None,
        width: [Some(liquids), None, None],
        width_gas: Some(gases),
        radius,
    }
}

/// Static radial glands (The O-Ring Store, "Static O-Ring Radial Glands"; module docs).
pub const STATIC_RADIAL: [TableRow; 5] = [
    radial(
        0.070,
        (0.050, 0.052),
        (0.015, 0.023),
        (22.0, 32.0),
        (0.002, 0.005),
        [(0.093, 0.098), (0.138, 0.143), (0.205, 0.210)],
        (0.005, 0.015),
    ),
    radial(
        0.103,
        (0.081, 0.083),
        (0.017, 0.025),
        (17.0, 24.0),
        (0.002, 0.005),
        [(0.140, 0.145), (0.171, 0.176), (0.238, 0.243)],
        (0.005, 0.015),
    ),
    radial(
        0.139,
        (0.111, 0.113),
        (0.022, 0.032),
        (16.0, 23.0),
        (0.003, 0.006),
        [(0.187, 0.192), (0.208, 0.213), (0.275, 0.280)],
        (0.010, 0.025),
    ),
    radial(
        0.210,
        (0.170, 0.173),
        (0.032, 0.045),
        (15.0, 21.0),
        (0.003, 0.006),
        [(0.281, 0.286), (0.311, 0.316), (0.410, 0.415)],
        (0.020, 0.035),
    ),
    radial(
        0.275,
        (0.226, 0.229),
        (0.040, 0.055),
        (15.0, 20.0),
        (0.004, 0.007),
        [(0.375, 0.380), (0.408, 0.413), (0.538, 0.543)],
        (0.020, 0.035),
    ),
];

/// Dynamic (reciprocating) radial glands (Engineers Edge; clearance and back-up widths from
/// [`STATIC_RADIAL`], assumed; module docs).
pub const DYNAMIC: [TableRow; 5] = [
    radial(
        0.070,
        (0.055, 0.057),
        (0.010, 0.018),
        (15.0, 25.0),
        (0.002, 0.005),
        [(0.093, 0.098), (0.138, 0.143), (0.205, 0.210)],
        (0.005, 0.015),
    ),
    radial(
        0.103,
        (0.088, 0.090),
        (0.010, 0.018),
        (10.0, 17.0),
        (0.002, 0.005),
        [(0.140, 0.145), (0.171, 0.176), (0.238, 0.243)],
        (0.005, 0.015),
    ),
    radial(
        0.139,
        (0.121, 0.123),
        (0.012, 0.022),
        (9.0, 16.0),
        (0.003, 0.006),
        [(0.187, 0.192), (0.208, 0.213), (0.275, 0.280)],
        (0.010, 0.025),
    ),
    radial(
        0.210,
        (0.185, 0.188),
        (0.017, 0.030),
        (8.0, 14.0),
        (0.003, 0.006),
        [(0.281, 0.286), (0.311, 0.316), (0.410, 0.415)],
        (0.020, 0.035),
    ),
    radial(
        0.275,
        (0.237, 0.240),
        (0.029, 0.044),
        (11.0, 16.0),
        (0.004, 0.007),
        [(0.375, 0.380), (0.408, 0.413), (0.538, 0.543)],
        (0.020, 0.035),
    ),
];

/// Face (axial) glands (The O-Ring Store, "Static O-Ring Axial Face Seal Glands").
pub const FACE: [TableRow; 5] = [
    face(
        0.070,
        (0.050, 0.054),
        (0.013, 0.023),
        (19.0, 32.0),
        (0.101, 0.107),
        (0.084, 0.089),
        (0.005, 0.015),
    ),
    face(
        0.103,
        (0.074, 0.080),
        (0.020, 0.032),
        (20.0, 30.0),
        (0.136, 0.142),
        (0.120, 0.125),
        (0.005, 0.015),
    ),
    face(
        0.139,
        (0.101, 0.107),
        (0.028, 0.042),
        (20.0, 30.0),
        (0.177, 0.187),
        (0.158, 0.164),
        (0.010, 0.025),
    ),
    face(
        0.210,
        (0.152, 0.162),
        (0.043, 0.063),
        (21.0, 30.0),
        (0.270, 0.290),
        (0.239, 0.244),
        (0.020, 0.035),
    ),
    face(
        0.275,
        (0.201, 0.211),
        (0.058, 0.080),
        (21.0, 29.0),
        (0.342, 0.362),
        (0.309, 0.314),
        (0.020, 0.035),
    ),
];

/// The source of [`STATIC_RADIAL`] and [`FACE`].
pub const STATIC_SOURCE: &str = "The O-Ring Store LLC, \"O-Ring Groove Chart\" \
    (https://www.theoringstore.com/store/index.php?main_page=page&id=39&chapter=6), the Parker \
    ORD 5700 industrial design-chart values as reproduced there";
/// The source of [`DYNAMIC`].
pub const DYNAMIC_SOURCE: &str = "Engineers Edge, \"O-Ring Installation Design and \
    Specification For Dynamic / Reciprocating Applications\" \
    (http://engineersedge.com/general_engineering/oring_gland_size_dynamic_cylinder.htm); \
    clearance and back-up-ring widths from the static radial table (assumed)";

/// The nominal (fractional) cross-section of each AS568 series \[in\] (Global O-Ring and Seal,
/// "AS568 O-Ring Size Chart", <https://www.globaloring.com/as568-size-chart/>).
const NOMINAL_CROSS_SECTION: [(f64, f64); 5] = [
    (0.070, 1.0 / 16.0),
    (0.103, 3.0 / 32.0),
    (0.139, 1.0 / 8.0),
    (0.210, 3.0 / 16.0),
    (0.275, 1.0 / 4.0),
];

/// Whether two cross-sections \[in\] are the same table class.
fn same_class(a: f64, b: f64) -> bool {
    (a - b).abs() < 0.0015
}

/// The AS568 nominal (ID, OD) \[in\] of a ring of actual ID `id` and cross-section `cs` \[in\]
/// (module docs: derived, not read from a table), or `None` for a cross-section outside the
/// five series.
pub fn as568_nominal(id: f64, cs: f64) -> Option<(f64, f64)> {
    let &(_, w) = NOMINAL_CROSS_SECTION
        .iter()
        .find(|(actual, _)| same_class(*actual, cs))?;
    let step = if cs < 0.12 { 1.0 / 32.0 } else { 1.0 / 16.0 };
    let od = ((id + 2.0 * cs) / step).round() * step;
    Some((od - 2.0 * w, od))
}

/// The service a gland is designed for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Service {
    pub kind: GlandKind,
    /// Reciprocating (radial glands only).
    pub dynamic: bool,
    /// Face glands: the pressure is outside (vacuum): the ring's ID is located on the groove's
    /// inner wall. Otherwise inside: its OD on the outer wall.
    pub pressure_outside: bool,
    /// Back-up rings, 0–2 (radial glands).
    pub backup_rings: u8,
}

/// Which table a service reads.
pub fn table(service: Service) -> (&'static [TableRow; 5], &'static str) {
    match (service.kind, service.dynamic) {
        (GlandKind::Face, _) => (&FACE, STATIC_SOURCE),
        (_, true) => (&DYNAMIC, DYNAMIC_SOURCE),
        (_, false) => (&STATIC_RADIAL, STATIC_SOURCE),
    }
}

/// A closed interval \[m\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    pub min: f64,
    pub max: f64,
}

impl Limits {
    fn new(min: f64, max: f64) -> Limits {
        Limits { min, max }
    }

    fn inch(span: Span) -> Limits {
        Limits::new(span.0 * INCH, span.1 * INCH)
    }

    /// The mid-point.
    pub fn mid(&self) -> f64 {
        0.5 * (self.min + self.max)
    }
}

/// The designed (or given) housing, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Housing {
    /// The diameter that locates the ring: the bore (piston), the rod (rod), the groove's
    /// outer (face, pressure inside) or inner (face, pressure outside) diameter; `None`: a face
    /// groove that does not locate the ring (its free diameters).
    pub seat: Option<Limits>,
    /// Its nominal size (the fit's basis) \[m\].
    pub seat_nominal: f64,
    /// The part across the clearance: the piston (piston gland), the housing bore (rod gland).
    pub mate: Option<Limits>,
    /// The groove's diameter: its bottom (piston) or its outer diameter (rod); `None` for a face
    /// groove, whose depth is [`Self::depth`].
    pub groove_diameter: Option<Limits>,
    /// The gland depth: L of a radial gland (follows from the seat and the groove diameter;
    /// kept for the report) or the face groove's depth.
    pub depth: Limits,
    /// Groove width.
    pub width: Limits,
}

/// A designed gland.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Design {
    pub service: Service,
    pub ring: Ring,
    pub fit: Fit,
    /// The table row the design reads.
    pub row: TableRow,
    /// The table's source.
    pub source: &'static str,
    /// Whether the seat's nominal size is the AS568 pairing (not given).
    pub paired: bool,
    pub housing: Housing,
}

/// Why a gland cannot be designed or stacked up.
#[derive(Debug, Clone, PartialEq)]
pub enum DesignError {
    /// The ring's cross-section is not one of the tables' five.
    NoTableRow { cross_section: f64 },
    /// Back-up rings in a face gland (the face table has no such widths).
    BackupInFace,
    /// The fit's tables do not cover the size, or the class is not one.
    Fit(FitError),
    /// The seat's tolerance is wider than twice the depth's range: no groove diameter keeps
    /// the depth inside the table's range.
    ToleranceTooWide {
        seat_tolerance: f64,
        depth_range: f64,
    },
    /// A tolerance corner cannot be assembled.
    Gland(GlandError),
}

impl fmt::Display for DesignError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::units::show;
        match self {
            DesignError::NoTableRow { cross_section } => write!(
                f,
                "no gland table row for a cross-section of {} in ({} mm): the tables cover the \
                 AS568 series 0.070, 0.103, 0.139, 0.210 and 0.275 in (-004…-050, -102…-178, \
                 -201…-284, -309…-395, -425…-475)",
                show(cross_section / INCH),
                show(cross_section * 1e3)
            ),
            DesignError::BackupInFace => f.write_str(
                "a face gland has no back-up rings in the tables (its flanges meet metal to \
                 metal, so there is no extrusion gap): drop --backup-rings",
            ),
            DesignError::Fit(e) => e.fmt(f),
            DesignError::ToleranceTooWide {
                seat_tolerance,
                depth_range,
            } => write!(
                f,
                "the fit's tolerance on the seat diameter ({} mm) is wider than twice the \
                 gland depth's range ({} mm): no groove diameter keeps the depth in the \
                 table's range; choose a finer grade (e.g. H7/f7)",
                show(seat_tolerance * 1e3),
                show(2.0 * depth_range * 1e3)
            ),
            DesignError::Gland(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for DesignError {}

impl From<FitError> for DesignError {
    fn from(e: FitError) -> Self {
        DesignError::Fit(e)
    }
}

/// The OD compression a face ring gets on its groove's outer wall (pressure inside), and the
/// stretch onto the inner wall (pressure outside): assumed (module docs).
pub const FACE_OD_COMPRESSION: f64 = 0.01;
/// See [`FACE_OD_COMPRESSION`].
pub const FACE_ID_STRETCH: f64 = 0.02;

/// The recommended housing for `ring` (SI, with its ± tolerances; `cross_section_in` the
/// series' actual cross-section \[in\] that selects the table row) in `service` with `fit`;
/// `seat` the bore (piston) or the rod (rod) \[m\], `None` for the AS568 pairing of
/// `nominal` (ID, OD) \[m\].
pub fn design(
    ring: Ring,
    nominal: Option<(f64, f64)>,
    service: Service,
    fit: Fit,
    seat: Option<f64>,
) -> Result<Design, DesignError> {
    let (rows, source) = table(service);
    let cs_in = ring.cross_section / INCH;
    let row = *rows
        .iter()
        .find(|r| same_class(r.cross_section, cs_in))
        .ok_or(DesignError::NoTableRow {
            cross_section: ring.cross_section,
        })?;
    if service.kind == GlandKind::Face && service.backup_rings > 0 {
        return Err(DesignError::BackupInFace);
    }
    let depth = Limits::inch(row.depth);
    let width_span = row.width[usize::from(service.backup_rings.min(2))]
        .or(row.width[0])
        .unwrap_or((0.0, 0.0));
    let width = Limits::inch(width_span);
    let free_od = ring.inner_diameter + 2.0 * ring.cross_section;
    let (nominal_id, nominal_od) = nominal.unwrap_or((ring.inner_diameter, free_od));
    let limits = |class: crate::fits::ToleranceClass, size: f64| {
        class.limits(size).map(|(lo, hi)| Limits::new(lo, hi))
    };
    let housing = match service.kind {
        GlandKind::Piston => {
            let a = seat.unwrap_or(nominal_od);
            let bore = limits(fit.hole, a)?;
            let piston = limits(fit.shaft, a)?;
            let groove = Limits::new(bore.max - 2.0 * depth.max, bore.min - 2.0 * depth.min);
            check_width(bore, depth)?;
            Housing {
                seat: Some(bore),
                seat_nominal: a,
                mate: Some(piston),
                groove_diameter: Some(groove),
                depth,
                width,
            }
        }
        GlandKind::Rod => {
            let r = seat.unwrap_or(nominal_id);
            let rod = limits(fit.shaft, r)?;
            let bore = limits(fit.hole, r)?;
            let groove = Limits::new(rod.max + 2.0 * depth.min, rod.min + 2.0 * depth.max);
            check_width(rod, depth)?;
            Housing {
                seat: Some(rod),
                seat_nominal: r,
                mate: Some(bore),
                groove_diameter: Some(groove),
                depth,
                width,
            }
        }
        GlandKind::Face => {
            let (size, class) = if service.pressure_outside {
                (ring.inner_diameter * (1.0 + FACE_ID_STRETCH), fit.shaft)
            } else {
                (free_od * (1.0 - FACE_OD_COMPRESSION), fit.hole)
            };
            Housing {
                seat: Some(limits(class, size)?),
                seat_nominal: size,
                mate: None,
                groove_diameter: None,
                depth,
                width,
            }
        }
    };
    Ok(Design {
        service,
        ring,
        fit,
        row,
        source,
        paired: seat.is_none(),
        housing,
    })
}

/// Refuses a seat tolerance that leaves no groove diameter (module docs).
fn check_width(seat: Limits, depth: Limits) -> Result<(), DesignError> {
    let seat_tolerance = seat.max - seat.min;
    let depth_range = depth.max - depth.min;
    if seat_tolerance > 2.0 * depth_range {
        return Err(DesignError::ToleranceTooWide {
            seat_tolerance,
            depth_range,
        });
    }
    Ok(())
}

/// The conditions of a stack-up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conditions {
    /// Lowest and highest service temperature \[K\].
    pub temperatures: (f64, f64),
    /// The ring's linear CTE \[1/K\].
    pub ring_expansion: f64,
    /// The housing's linear CTE \[1/K\] (every part of it).
    pub housing_expansion: f64,
    /// Pressure difference \[Pa\] (back-up-ring advice).
    pub pressure: f64,
    /// The ring's hardness \[Shore A\] (the extrusion chart).
    pub hardness: f64,
}

/// What a stack-up quantity is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Squeeze of the (stretched) cord, `1 − h/d′`.
    Squeeze,
    /// Stretch of the ID onto its seat, `(ID′ − ID)/ID`.
    Stretch,
    /// Circumferential compression of the OD onto an outer seat, `(OD − OD′)/OD`.
    OdCompression,
    /// Gland fill, `(π d′²/4)/(h w)`.
    Fill,
    /// Extrusion gap: the diametral clearance \[m\] (a radial gap of half of it).
    Clearance,
}

impl Quantity {
    /// The row's name.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Squeeze => "squeeze",
            Quantity::Stretch => "stretch",
            Quantity::OdCompression => "OD compression",
            Quantity::Fill => "gland fill",
            Quantity::Clearance => "diametral clearance",
        }
    }

    /// The JSON key.
    pub fn key(self) -> &'static str {
        match self {
            Quantity::Squeeze => "squeeze",
            Quantity::Stretch => "stretch",
            Quantity::OdCompression => "od_compression",
            Quantity::Fill => "fill",
            Quantity::Clearance => "diametral_clearance",
        }
    }

    /// Whether it is a ratio (printed in %) rather than a length.
    pub fn is_ratio(self) -> bool {
        self != Quantity::Clearance
    }
}

/// One row of the stack-up table.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub quantity: Quantity,
    /// At nominal dimensions, 23 °C.
    pub nominal: f64,
    /// Worst-case lowest and highest at 23 °C over every combination of the tolerance limits.
    pub assembly: (f64, f64),
    /// The same over the service temperatures (the lowest, 23 °C and the highest).
    pub service: (f64, f64),
    /// The limits checked (lower, upper), in the quantity's unit.
    pub limit: (Option<f64>, Option<f64>),
    /// The limit in words, and where it is from.
    pub limit_text: String,
    pub source: &'static str,
    /// Every checked value within the limit.
    pub ok: bool,
}

/// Back-up ring advice from the extrusion chart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BackupAdvice {
    /// The largest diametral clearance over tolerances and temperatures \[m\].
    pub clearance: f64,
    /// The fewest back-up rings (0–2) the chart accepts at this clearance, if any.
    pub needed: Option<u8>,
    /// The chart's limit with the back-up rings designed \[m\] (and whether over-rated).
    pub limit: extrusion::ExtrusionLimit,
}

/// The stack-up.
#[derive(Debug, Clone, PartialEq)]
pub struct StackUp {
    pub rows: Vec<Row>,
    /// Radial glands; `None` for a face gland (no gap).
    pub backup: Option<BackupAdvice>,
}

/// The source of the squeeze limits: the design table's own squeeze column.
const TABLE_SQUEEZE: &str = "the design table's squeeze column (for the unstretched cord)";
/// Stretch limit: Parker's gland-design note and Apple Rubber (as [`MAX_STRETCH_GUIDANCE`]).
const STRETCH_SOURCE: &str = "Parker gland-design note (gallagherseals.com re-post): \"up to 5% \
    stretch\"; Apple Rubber: \"greater than 5% is not recommended\"";
/// OD compression limits (Global O-Ring and Seal, "O-Ring Groove Design").
const OD_SOURCE: &str = "Global O-Ring and Seal, \"O-Ring Groove Design\": OD interference max \
    3 % (internal-pressure face seals), max 2 % (rod glands)";
/// Fill limits (as [`MAX_FILL_GUIDANCE`], [`NOMINAL_FILL_GUIDANCE`]).
const FILL_SOURCE: &str = "Parker, \"Gland overfill\": 90 % at maximum material condition; \
    O-Ring Supply Co.: below 85 % at ambient";
/// Clearance limit: the table's and the extrusion chart's.
const CLEARANCE_SOURCE: &str = "the design table's diametral clearance and the extrusion chart \
    (Seal & Design after Parker; docs/model.md §6.3) at the pressure, hardness and back-up rings";

/// One combination of the tolerance limits at one temperature: the quantities.
#[derive(Debug, Clone, Copy)]
struct Corner {
    squeeze: f64,
    stretch: f64,
    od_compression: f64,
    fill: f64,
}

/// The ring and the housing at temperature `t`, every tolerance at one of its limits: `pick(i)`
/// chooses the lower (false) or upper (true) limit of variable i.
fn corner(
    design: &Design,
    cond: &Conditions,
    t: f64,
    pick: impl Fn(usize) -> bool,
) -> Result<Corner, DesignError> {
    let r = &design.ring;
    let h = &design.housing;
    let sign = |i: usize| if pick(i) { 1.0 } else { -1.0 };
    let end = |l: Limits, i: usize| if pick(i) { l.max } else { l.min };
    let ring_scale = 1.0 + cond.ring_expansion * (t - ASSEMBLY_TEMPERATURE);
    let hw = 1.0 + cond.housing_expansion * (t - ASSEMBLY_TEMPERATURE);
    let id = (r.inner_diameter + sign(0) * r.inner_diameter_tolerance) * ring_scale;
    let d = (r.cross_section + sign(1) * r.cross_section_tolerance) * ring_scale;
    let w = end(h.width, 4) * hw;
    let (locator, depth) = match (design.service.kind, h.seat, h.groove_diameter) {
        (GlandKind::Piston, Some(seat), Some(groove)) => {
            let a = end(seat, 2) * hw;
            let b = end(groove, 3) * hw;
            (Locator::Bore(a), 0.5 * (a - b))
        }
        (GlandKind::Rod, Some(seat), Some(groove)) => {
            let rod = end(seat, 2) * hw;
            let g = end(groove, 3) * hw;
            (Locator::Rod(rod), 0.5 * (g - rod))
        }
        (_, seat, _) => {
            let depth = end(h.depth, 3) * hw;
            let locator = match seat {
                None => Locator::Free,
                Some(s) if design.service.pressure_outside => Locator::GrooveInner(end(s, 2) * hw),
                Some(s) => Locator::GrooveOuter(end(s, 2) * hw),
            };
            (locator, depth)
        }
    };
    let inst = gland::install(id, d, depth, w, locator).map_err(DesignError::Gland)?;
    let od = id + 2.0 * d;
    let od_installed = inst.inner_diameter + 2.0 * inst.cross_section;
    Ok(Corner {
        squeeze: inst.squeeze,
        stretch: inst.stretch,
        od_compression: if inst.stretch < 0.0 {
            (od - od_installed) / od
        } else {
            0.0
        },
        fill: inst.fill,
    })
}

/// The stack-up of a designed (or given) gland (module docs): every quantity at nominal, its
/// worst-case extremes at 23 °C over the 2⁵ combinations of the ring's ID and cross-section,
/// the seat, the groove diameter (or depth) and the width at their limits, and the same over
/// the service temperatures; the clearance from the fit's limits; back-up advice.
pub fn stack_up(design: &Design, cond: &Conditions) -> Result<StackUp, DesignError> {
    // nominal: every dimension at the middle of its tolerance
    let mid = {
        let mut d = *design;
        let h = &mut d.housing;
        let mid = |l: Option<Limits>| l.map(|l| Limits::new(l.mid(), l.mid()));
        h.seat = mid(h.seat);
        h.groove_diameter = mid(h.groove_diameter);
        h.depth = Limits::new(h.depth.mid(), h.depth.mid());
        h.width = Limits::new(h.width.mid(), h.width.mid());
        d.ring.inner_diameter_tolerance = 0.0;
        d.ring.cross_section_tolerance = 0.0;
        corner(&d, cond, ASSEMBLY_TEMPERATURE, |_| false)?
    };
    let (t_lo, t_hi) = cond.temperatures;
    let mut assembly: Vec<Corner> = Vec::with_capacity(32);
    let mut service: Vec<Corner> = Vec::with_capacity(96);
    for t in [t_lo, ASSEMBLY_TEMPERATURE, t_hi] {
        for bits in 0u32..32 {
            let c = corner(design, cond, t, |i| bits & (1 << i) != 0)?;
            if t == ASSEMBLY_TEMPERATURE {
                assembly.push(c);
            }
            service.push(c);
        }
    }
    let range = |v: &[Corner], f: &dyn Fn(&Corner) -> f64| {
        v.iter()
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            })
    };
    let row = design.row;
    let kind = design.service.kind;
    let mut rows = Vec::new();
    let mut push = |quantity: Quantity,
                    f: &dyn Fn(&Corner) -> f64,
                    limit: (Option<f64>, Option<f64>),
                    limit_text: String,
                    source: &'static str,
                    nominal_max: f64| {
        let service_range = range(&service, f);
        let nominal = f(&mid);
        let within = |x: f64| limit.0.is_none_or(|lo| x >= lo) && limit.1.is_none_or(|hi| x <= hi);
        rows.push(Row {
            quantity,
            nominal,
            assembly: range(&assembly, f),
            service: service_range,
            limit,
            limit_text,
            source,
            ok: within(service_range.0) && within(service_range.1) && nominal <= nominal_max,
        });
    };
    let (sq_lo, sq_hi) = row.squeeze_percent;
    push(
        Quantity::Squeeze,
        &|c| c.squeeze,
        (Some(sq_lo / 100.0), Some(sq_hi / 100.0)),
        format!("{sq_lo}–{sq_hi} %"),
        TABLE_SQUEEZE,
        f64::INFINITY,
    );
    push(
        Quantity::Stretch,
        &|c| c.stretch,
        (None, Some(MAX_STRETCH_GUIDANCE)),
        "≤ 5 %".to_owned(),
        STRETCH_SOURCE,
        f64::INFINITY,
    );
    let od_limit = if kind == GlandKind::Rod { 0.02 } else { 0.03 };
    push(
        Quantity::OdCompression,
        &|c| c.od_compression,
        (None, Some(od_limit)),
        format!("≤ {} %", od_limit * 100.0),
        OD_SOURCE,
        f64::INFINITY,
    );
    push(
        Quantity::Fill,
        &|c| c.fill,
        (None, Some(MAX_FILL_GUIDANCE)),
        "≤ 85 % nominal, ≤ 90 % worst case".to_owned(),
        FILL_SOURCE,
        NOMINAL_FILL_GUIDANCE,
    );
    let backup = match design.housing.mate.zip(design.housing.seat) {
        None => None,
        Some((mate, seat)) => {
            // hole minus shaft: the bore is the hole of a piston gland, the mate of a rod gland
            let (hole, shaft) = if kind == GlandKind::Piston {
                (seat, mate)
            } else {
                (mate, seat)
            };
            let at = |t: f64| {
                let hw = 1.0 + cond.housing_expansion * (t - ASSEMBLY_TEMPERATURE);
                ((hole.min - shaft.max) * hw, (hole.max - shaft.min) * hw)
            };
            let a = at(ASSEMBLY_TEMPERATURE);
            let (lo, hi) = [at(t_lo), a, at(t_hi)]
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                    (l.min(x.0), h.max(x.1))
                });
            let chart = extrusion::limit(cond.pressure, cond.hardness, design.service.backup_rings);
            let table_max = row.clearance.map_or(f64::INFINITY, |c| c.1 * INCH);
            let max = chart.diametral_clearance.min(table_max);
            let nominal = hole.mid() - shaft.mid();
            rows.push(Row {
                quantity: Quantity::Clearance,
                nominal,
                assembly: a,
                service: (lo, hi),
                limit: (Some(0.0), Some(max)),
                limit_text: format!(
                    "≤ {} mm (table {} mm; chart {} mm at {} bar, {} Shore A, {} back-up \
                     ring(s){})",
                    fmt3(max * 1e3),
                    fmt3(table_max * 1e3),
                    fmt3(chart.diametral_clearance * 1e3),
                    fmt3(cond.pressure / 1e5),
                    fmt3(cond.hardness),
                    design.service.backup_rings,
                    if chart.over_rated {
                        ", over the arrangement's rated pressure"
                    } else {
                        ""
                    }
                ),
                source: CLEARANCE_SOURCE,
                ok: lo >= 0.0 && hi <= max && !chart.over_rated,
            });
            let needed = (0u8..=2)
                .find(|&n| !extrusion::limit(cond.pressure, cond.hardness, n).extrudes(hi));
            Some(BackupAdvice {
                clearance: hi,
                needed,
                limit: chart,
            })
        }
    };
    Ok(StackUp { rows, backup })
}

/// Three decimals, trailing zeros dropped.
fn fmt3(v: f64) -> String {
    let s = format!("{v:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_are_ordered_and_consistent() {
        for rows in [&STATIC_RADIAL, &DYNAMIC, &FACE] {
            for r in rows.iter() {
                assert!(r.depth.0 < r.depth.1 && r.depth.1 < r.cross_section);
                assert!(r.squeeze.0 < r.squeeze.1);
                for w in r.width.iter().flatten() {
                    assert!(w.0 < w.1 && w.0 > r.cross_section, "{r:?}");
                }
            }
        }
    }

    #[test]
    fn nominal_pairs() {
        // −214: 1 × 1-1/4 × 1/8; −210: 1.000 in OD; −112: 1/2 in ID
        assert_eq!(as568_nominal(0.984, 0.139), Some((1.0, 1.25)));
        assert_eq!(as568_nominal(0.734, 0.139).map(|p| p.1), Some(1.0));
        assert_eq!(as568_nominal(0.487, 0.103).map(|p| p.0), Some(0.5));
        assert_eq!(as568_nominal(1.0, 0.5), None);
    }
}
