//! The gland an O-ring sits in: its geometry (docs/model.md §6.2) — stretch of the ring onto its
//! seat, the cross-section left after stretching, squeeze, gland fill and their range over the
//! tolerances, the housing's thermal expansion — and what the fluid pressure does to a
//! groove-seated ring (energisation, extrusion into the clearance gap; docs/model.md §6.3).
//!
//! Everything here is SI (m, 1/K) and knows no file or unit; the scenario boundary
//! (`[seal] gland = …`, `src/scenario/gland.rs`) validates the keys into a [`GlandDesign`].
//!
//! **Relations** (docs/model.md §6.2):
//!
//! * stretch `s = (ID′ − ID)/ID`, ID the ring's free inside diameter, ID′ installed (the
//!   definition of Parker's gland-design note, re-posted at
//!   <https://www.gallagherseals.com/blog/how-to-design-o-ring-gland-stretch>: "the diameter of
//!   the hardware minus the O-ring inner diameter (ID), all divided by the O-ring ID");
//! * cross-section after stretch: the ring's volume is conserved and its section stays round —
//!   the assumption Apple Rubber states for its relation
//!   (<https://www.applerubber.com/seal-design-guide/operating-environment-factors/seal-compression-squeeze/>:
//!   "assumes the o-ring volume does not change and the cross-section remains round when
//!   stretched"). sealsim uses the torus exactly: volume `V = (π d²/4) · π D` with D = ID + d the
//!   centreline diameter, so `d′² D′ = d² D`, i.e. `d′ = d /√(1 + s_c)` with
//!   `s_c = (D′ − D)/D` the stretch of the centreline, solved together with the seat
//!   (`D′ = S + d′` on an inner seat S, `D′ = S − d′` on an outer one). To first order
//!   `Δd/d ≈ −s/2`, Marco Rubber's "% cross section reduction due to stretch about half of the
//!   % ID stretch" (<http://www.marcorubber.com/gd-directory.htm>). Parker's empirical curve
//!   was not found in a readable source and is not used;
//! * squeeze `ε = 1 − h/d′`, h the gland depth (the height the cord is squeezed into);
//! * gland fill `F = (π d′²/4)/(h w)`, w the groove width; warned above
//!   [`MAX_FILL_GUIDANCE`] = 90 % at maximum material condition (Parker, "Gland overfill",
//!   <https://www.parker.com/us/en/divisions/o-ring-and-engineered-seals-division/resources/oring-ehandbook/failure-modes/gland-overfill.html>:
//!   "a maximum material condition gland fill of 90%") or [`NOMINAL_FILL_GUIDANCE`] = 85 %
//!   nominal, and below [`MIN_FILL_GUIDANCE`] = 50 % (a mis-specified groove); refused at
//!   100 % (the ring does not fit);
//! * stretch warned above [`MAX_STRETCH_GUIDANCE`] = 5 %, refused at [`MAX_STRETCH`] = 50 %;
//! * circumferential compression `c` (a ring larger than the wall it is held by: the handbook's
//!   "OD compression" of a rod or internally pressurised face ring, `(OD − S)/OD`; a piston ring
//!   whose ID is larger than its groove diameter G, `(ID − G)/ID`) warned above
//!   [`MAX_COMPRESSION_GUIDANCE`] = 3 %, refused at [`MAX_COMPRESSION`] = 10 % (assumed);
//! * gland fill at maximum material condition refused at 100 % ([`GlandDesign::feasibility`]);
//! * a face ring on the wall opposite its pressure side refused ([`PressureSide`]);
//! * squeeze over the tolerances warned outside [`STATIC_SQUEEZE`] or [`DYNAMIC_SQUEEZE`].

use sealsim_math::roots;
use std::f64::consts::PI;
use std::fmt;

/// Where the groove is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GlandKind {
    /// Axial squeeze between a grooved flange and a flat counterface.
    Face,
    /// Radial squeeze, groove in the piston, sealing on the bore.
    Piston,
    /// Radial squeeze, groove in the housing bore, sealing on the rod.
    Rod,
}

impl GlandKind {
    /// The scenario's name of the kind (`gland = "face"`).
    pub fn name(self) -> &'static str {
        match self {
            GlandKind::Face => "face",
            GlandKind::Piston => "piston",
            GlandKind::Rod => "rod",
        }
    }
}

/// A groove-seated O-ring's gland, validated, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gland {
    pub kind: GlandKind,
    /// The gap the ring is pushed against on its low-pressure side \[m\]: half the diametral
    /// clearance of a piston or rod gland, the flange separation of a face gland.
    pub extrusion_gap: f64,
    /// Lowest and highest squeeze over the ring's and the groove's tolerances (reported; the
    /// run uses the nominal squeeze).
    pub squeeze_range: Option<(f64, f64)>,
    /// Back-up rings on the low-pressure side: 0, 1 or 2 (the extrusion limit,
    /// [`crate::extrusion::limit`]).
    pub backup_rings: u8,
}

/// Gland fill above which a warning is given, at maximum material condition: 0.90 (Parker,
/// "Gland overfill": "Parker recommends a gland design where the O-ring has a maximum material
/// condition gland fill of 90%", stretchable to 95 % with little fluid swell or thermal
/// expansion).
pub const MAX_FILL_GUIDANCE: f64 = 0.90;

/// Nominal gland fill above which a warning is given: 0.85 (O-Ring Supply Co., "O-Ring Groove
/// Design Guide", <https://oringsupplyco.com/blog/o-ring-groove-design-guide/>: "65–85% fill
/// rate … Always verify fill rate stays below 85% at ambient — thermal expansion and fluid
/// swell will increase it further in service").
pub const NOMINAL_FILL_GUIDANCE: f64 = 0.85;

/// Nominal gland fill below which the groove is taken as mis-specified (a warning): 0.5, well
/// under the 65 % low end of the range above — a ring that fills half its groove or less
/// shifts and rolls in it; a fill of a few per cent is a groove width or depth in the wrong
/// unit.
pub const MIN_FILL_GUIDANCE: f64 = 0.5;

/// Installed stretch of the ID above which a warning is given: 5 % (Parker's gland-design
/// note, re-posted at <https://www.gallagherseals.com/blog/how-to-design-o-ring-gland-stretch>:
/// "For male groove designs, up to 5% stretch is recommended"; Apple Rubber, "Dimensional
/// considerations": "A stretch greater than 5% is not recommended. The resulting stress on the
/// O-ring will cause accelerated aging and cross section reduction").
pub const MAX_STRETCH_GUIDANCE: f64 = 0.05;

/// Installed stretch at or above which the ring is refused: 50 %, the most an O-ring may be
/// stretched even momentarily to mount it (Cutler Group, "What is stretch of O-ring?": "it
/// should stretch no more than 50%"); held in service it is not a seal (its cord thins by a
/// fifth and it ages under the strain).
pub const MAX_STRETCH: f64 = 0.5;

/// Circumferential compression above which a warning is given: 3 %. The handbook rule for a
/// ring held by its OD: "Axial compression: 1 to 3% (compressed) max. 6% (stretch)" for face
/// glands (O-Ring Stocks, "Static O-ring grooves",
/// <https://www.o-ring-stocks.eu/knowledge-base/o-ring-groove-dimensions/o-ring-groove-static>);
/// "Rod seals are normally compressed or have line-to-line fit on the outside diameter without
/// any stretch" (Marco Rubber, <http://www.marcorubber.com/static_face_seal_dovetail.htm>).
/// Applied to every seat: a piston ring whose ID is larger than its groove diameter is
/// compressed the same way (Apple Rubber, "Dimensional considerations",
/// <http://www.applerubber.com/seal-design-guide/oring-basics/dimensional-considerations.cfm>: the ID "must be smaller
/// than the piston groove diameter, so that the O-ring is slightly stretched").
pub const MAX_COMPRESSION_GUIDANCE: f64 = 0.03;

/// Circumferential compression at or above which the ring is refused: 10 % — **assumed**
/// (sealsim's decision, no source read gives the compression a ring cannot take): three times
/// the handbook's 3 %; a ring that much too large buckles or is pinched on assembly, and the
/// constant-volume thickening the model would give it is not a seal. The impossible fits of the
/// new-user review (AS568-214 in a 25.4 mm bore, the groove diameter as bore) lie at 19–22 %.
pub const MAX_COMPRESSION: f64 = 0.10;

/// Squeeze range of a static gland (face, static radial) outside which a warning is given, at
/// the tolerance limits: 10–30 %. The upper limit: "The maximum linear compression suggested
/// by manufacturers is 30% for static applications and 16% for dynamic seals (up to 25% for
/// small cross-sectional diameters)" (M. Kutz (ed.), Mechanical Engineers' Handbook, Vol. 3,
/// chapter "Seal Technology", p. 290, citing the Parker O-Ring Handbook; read at
/// <https://fliphtml5.com/osspz/lzbm/Mechanical_Engineers%26%2339%3B_Handbook._Vol._3_Manufacturing_and_Management/306>).
/// The lower: "under-compression below 10% risks low-pressure leakage" (O-Ring Supply Co.,
/// "O-Ring Compression Rate Guide", <https://oringsupplyco.com/blog/o-ring-compression-rate-guide/>).
/// The Parker O-Ring Handbook's (ORD 5700) own design-chart squeeze ranges were not found in a
/// readable copy and are not used.
pub const STATIC_SQUEEZE: (f64, f64) = (0.10, 0.30);

/// Squeeze range of a dynamic (reciprocating, `[motion]`) gland: 10–16 %, the same sources as
/// [`STATIC_SQUEEZE`] (16 % the manufacturers' maximum for dynamic seals; the 25 % allowed
/// "for small cross-sectional diameters" is not used, the size it starts at not being stated).
pub const DYNAMIC_SQUEEZE: (f64, f64) = (0.10, 0.16);

/// An O-ring as made: free inside diameter and cross-section with their (±) tolerances \[m\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ring {
    /// Free inside diameter ID \[m\].
    pub inner_diameter: f64,
    /// ± tolerance of the ID \[m\] (0 when unknown).
    pub inner_diameter_tolerance: f64,
    /// Free cross-section (cord diameter) d \[m\].
    pub cross_section: f64,
    /// ± tolerance of d \[m\] (0 when unknown).
    pub cross_section_tolerance: f64,
}

/// The hardware diameter that decides the ring's stretch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Locator {
    /// None given: the ring lies in the groove at its free diameters (stretch 0; a face gland).
    Free,
    /// Piston gland: the bore B \[m\]; the groove bottom is at `B − 2h`.
    Bore(f64),
    /// Rod gland: the rod diameter R \[m\]; the groove bottom (outer) is at `R + 2h`.
    Rod(f64),
    /// Face gland, internally pressurised: the groove's outer diameter \[m\], the ring's OD is
    /// brought onto it (stretched or compressed).
    GrooveOuter(f64),
    /// Face gland, externally pressurised (vacuum): the groove's inner diameter \[m\], the ring's
    /// ID is brought onto it.
    GrooveInner(f64),
}

/// The side of a face ring the (higher) pressure is on: it pushes the ring onto the groove wall
/// opposite, which is the wall the ring must bear on — its OD on the groove's outer wall for
/// pressure inside, its ID on the inner wall for pressure outside (a vacuum flange).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PressureSide {
    Inside,
    Outside,
}

impl PressureSide {
    /// The scenario's name (`pressure_side = "inside"`).
    pub fn name(self) -> &'static str {
        match self {
            PressureSide::Inside => "inside",
            PressureSide::Outside => "outside",
        }
    }

    /// The side a face ring's seat implies (`None`: a free ring or a radial gland).
    pub fn of(locator: Locator) -> Option<PressureSide> {
        match locator {
            Locator::GrooveOuter(_) => Some(PressureSide::Inside),
            Locator::GrooveInner(_) => Some(PressureSide::Outside),
            _ => None,
        }
    }
}

/// The handbook's measures of how a ring sits on the wall that holds it, from its free
/// dimensions (docs/model.md §6.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fit {
    /// The measure a size is chosen by: the stretch `(S − ID)/ID` onto an inner seat S (piston:
    /// the groove diameter G = B − 2h; face, pressure outside: the groove's inner diameter) or
    /// the OD compression `(OD − S)/OD` into an outer one (rod: the groove diameter R + 2h;
    /// face, pressure inside: the groove's outer diameter). `None` for a free face ring.
    pub measure: Option<SeatMeasure>,
    /// Circumferential compression c ≥ 0: how much the ring is larger than the wall that
    /// holds it (0 when it is stretched or free).
    pub compression: f64,
    /// The wall's diameter S \[m\] (0 for a free ring).
    pub seat: f64,
}

/// Which of the two handbook measures a seat is judged by, and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SeatMeasure {
    /// Stretch of the ID onto an inner seat (recommended 0–5 %).
    Stretch(f64),
    /// Compression of the OD into an outer seat (recommended 0–3 %).
    OdCompression(f64),
}

impl SeatMeasure {
    /// The measure's value and its recommended band (the nearest-size rule).
    pub fn band(self) -> (f64, f64, f64) {
        match self {
            SeatMeasure::Stretch(s) => (s, 0.0, MAX_STRETCH_GUIDANCE),
            SeatMeasure::OdCompression(c) => (c, 0.0, MAX_COMPRESSION_GUIDANCE),
        }
    }

    /// How far the value lies outside its band (0 inside).
    pub fn distance(self) -> f64 {
        let (v, lo, hi) = self.band();
        (lo - v).max(v - hi).max(0.0)
    }
}

/// The feasibility of a gland: the refusals come as [`GlandError`]; what passes may still break
/// a handbook limit (the warnings, [`Limit`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Limit {
    /// Circumferential compression above [`MAX_COMPRESSION_GUIDANCE`].
    Compression { compression: f64, seat: f64 },
    /// Squeeze at the tolerance limits outside the static or dynamic range.
    Squeeze {
        min: f64,
        max: f64,
        range: (f64, f64),
        dynamic: bool,
    },
}

/// Where the ring is held circumferentially.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Seat {
    /// Its ID on the diameter \[m\].
    Inner(f64),
    /// Its OD on the diameter \[m\].
    Outer(f64),
    /// Nowhere: free diameters.
    Free,
}

/// The ring as installed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Installed {
    /// Stretch of the ID, `s = (ID′ − ID)/ID` (negative: circumferential compression).
    pub stretch: f64,
    /// Installed inside diameter ID′ \[m\].
    pub inner_diameter: f64,
    /// Cross-section after stretch d′ \[m\] (constant volume, round section).
    pub cross_section: f64,
    /// Centreline (mean) diameter D′ = ID′ + d′ \[m\]: the sealing length is π D′.
    pub mean_diameter: f64,
    /// Squeeze `ε = 1 − h/d′` (≤ 0: the cord does not touch both walls).
    pub squeeze: f64,
    /// Gland fill `(π d′²/4)/(h w)`.
    pub fill: f64,
}

/// The squeeze over the tolerances: the lowest and highest over every combination of the
/// ring's ID and cross-section and the gland depth at their tolerance limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SqueezeRange {
    pub min: f64,
    pub nominal: f64,
    pub max: f64,
}

/// Why a ring does not fit its gland.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GlandError {
    /// The piston's groove bottom `B − 2h` is not positive.
    NoGrooveBottom { bore: f64, depth: f64 },
    /// The ring cannot be brought onto its outer seat (its section would close the hole).
    CannotSeat { diameter: f64 },
    /// `h ≥ d′`: the groove is deeper than the (stretched) cross-section.
    GrooveTooDeep { cross_section: f64, depth: f64 },
    /// Gland fill ≥ 100 %.
    Overfilled { fill: f64 },
    /// Installed stretch ≥ [`MAX_STRETCH`].
    Overstretched { stretch: f64 },
    /// The ring is larger than the wall that holds it by [`MAX_COMPRESSION`] or more
    /// (circumferential compression `compression`; `ring` its free ID or OD, `seat` the wall's
    /// diameter \[m\]).
    Overcompressed {
        compression: f64,
        ring: f64,
        seat: f64,
        outer: bool,
    },
    /// Gland fill ≥ 100 % at maximum material condition (the largest cord in the shallowest
    /// gland over the tolerances), though not at nominal.
    OverfilledAtMaximumMaterial { fill: f64, nominal: f64 },
    /// A face ring seated on the wall opposite the one its pressure side pushes it onto.
    WrongWall { side: PressureSide },
}

impl fmt::Display for GlandError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::units::show;
        match *self {
            GlandError::NoGrooveBottom { bore, depth } => write!(
                f,
                "the groove bottom diameter bore − 2·depth = {} m − 2·{} m is not positive",
                show(bore),
                show(depth)
            ),
            GlandError::CannotSeat { diameter } => write!(
                f,
                "the ring cannot be brought onto the diameter {} m: its cross-section would \
                 close the ring",
                show(diameter)
            ),
            GlandError::GrooveTooDeep {
                cross_section,
                depth,
            } => write!(
                f,
                "groove deeper than the cross-section: the cord ({} m after stretch) is not \
                 squeezed by a gland depth of {} m (squeeze {} %)",
                show(cross_section),
                show(depth),
                show(100.0 * (1.0 - depth / cross_section))
            ),
            GlandError::Overstretched { stretch } => write!(
                f,
                "the ring cannot be seated: it would be stretched {} % onto its seat (refused \
                 at {} %, the most an O-ring may be stretched even to mount it; 5 % is the \
                 recommended limit): choose a ring with a larger inside diameter",
                show((1000.0 * stretch).round() / 10.0),
                show(100.0 * MAX_STRETCH)
            ),
            GlandError::Overfilled { fill } => write!(
                f,
                "the ring does not fit: its cross-section fills {} % of the groove (depth × \
                 width); widen or deepen the groove",
                show(100.0 * fill)
            ),
            GlandError::Overcompressed {
                compression,
                ring,
                seat,
                outer,
            } => write!(
                f,
                "the ring cannot be assembled: its {} ({} mm) is larger than the {} it must \
                 sit on ({} mm) — circumferential compression {} % (refused at {} %, assumed; \
                 the handbook limit is 3 %)",
                if outer { "OD" } else { "ID" },
                show((ring * 1e5).round() / 100.0),
                if outer { "wall" } else { "groove diameter" },
                show((seat * 1e5).round() / 100.0),
                show((1000.0 * compression).round() / 10.0),
                show(100.0 * MAX_COMPRESSION)
            ),
            GlandError::OverfilledAtMaximumMaterial { fill, nominal } => write!(
                f,
                "the ring does not fit at maximum material condition: the largest cord in the \
                 shallowest gland the tolerances allow fills {} % of the groove (nominal {} %); \
                 the groove must hold the largest ring",
                show((1000.0 * fill).round() / 10.0),
                show((1000.0 * nominal).round() / 10.0)
            ),
            GlandError::WrongWall { side } => write!(
                f,
                "the ring is seated on the wrong wall: with the pressure {} the ring is pushed \
                 onto the groove's {} wall, so that is where it must bear ({}) — on the other \
                 wall it is pushed off its seat by the pressure",
                side.name(),
                match side {
                    PressureSide::Inside => "outer",
                    PressureSide::Outside => "inner",
                },
                match side {
                    PressureSide::Inside => "its OD on the groove's outer diameter",
                    PressureSide::Outside => "its ID on the groove's inner diameter",
                }
            ),
        }
    }
}

impl std::error::Error for GlandError {}

/// A ring in its gland, validated, SI: everything [`Installed`] and [`SqueezeRange`] need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GlandDesign {
    pub kind: GlandKind,
    pub ring: Ring,
    /// What fixes the stretch.
    pub locator: Locator,
    /// Gland depth h \[m\]: the height the cord is squeezed into — bore to groove bottom
    /// (piston), rod to groove bottom (rod), groove depth plus flange separation (face).
    pub gland_depth: f64,
    /// ± tolerance of h \[m\].
    pub gland_depth_tolerance: f64,
    /// Groove width w \[m\].
    pub groove_width: f64,
    /// Extrusion gap \[m\] (see [`Gland::extrusion_gap`]).
    pub extrusion_gap: f64,
}

impl GlandDesign {
    /// The gland as the life model sees it.
    pub fn gland(&self) -> Gland {
        let squeeze_range = self.squeeze_range().ok().map(|r| (r.min, r.max));
        Gland {
            kind: self.kind,
            extrusion_gap: self.extrusion_gap,
            squeeze_range,
            backup_rings: 0,
        }
    }

    /// The nominal installation, or why the ring does not fit: a seat that cannot be reached,
    /// a groove deeper than the stretched cord (ε ≤ 0), a fill of 100 % or more.
    pub fn installed(&self) -> Result<Installed, GlandError> {
        let r = &self.ring;
        let inst = install(
            r.inner_diameter,
            r.cross_section,
            self.gland_depth,
            self.groove_width,
            self.locator,
        )?;
        if inst.squeeze <= 0.0 {
            return Err(GlandError::GrooveTooDeep {
                cross_section: inst.cross_section,
                depth: self.gland_depth,
            });
        }
        if inst.fill >= 1.0 {
            return Err(GlandError::Overfilled { fill: inst.fill });
        }
        if inst.stretch >= MAX_STRETCH {
            return Err(GlandError::Overstretched {
                stretch: inst.stretch,
            });
        }
        Ok(inst)
    }

    /// The installations at every combination of ID, cross-section and gland depth at their
    /// tolerance limits (those that can be seated).
    fn corners(&self) -> Vec<Installed> {
        let r = &self.ring;
        let mut out = Vec::with_capacity(8);
        for id in [-1.0, 1.0] {
            for d in [-1.0, 1.0] {
                for h in [-1.0, 1.0] {
                    if let Ok(inst) = install(
                        r.inner_diameter + id * r.inner_diameter_tolerance,
                        r.cross_section + d * r.cross_section_tolerance,
                        self.gland_depth + h * self.gland_depth_tolerance,
                        self.groove_width,
                        self.locator,
                    ) {
                        out.push(inst);
                    }
                }
            }
        }
        out
    }

    /// Minimum, nominal and maximum squeeze over the tolerances of the ring (ID, cross-section)
    /// and of the gland depth (each ±, all 8 combinations; the extremes need no monotonicity).
    pub fn squeeze_range(&self) -> Result<SqueezeRange, GlandError> {
        let nominal = self.installed()?.squeeze;
        let (mut min, mut max) = (nominal, nominal);
        for inst in self.corners() {
            min = min.min(inst.squeeze);
            max = max.max(inst.squeeze);
        }
        Ok(SqueezeRange { min, nominal, max })
    }

    /// Gland fill at maximum material condition: the largest over the tolerance combinations
    /// (largest cord, shallowest gland), compared with [`MAX_FILL_GUIDANCE`].
    pub fn max_material_fill(&self) -> Result<f64, GlandError> {
        let nominal = self.installed()?.fill;
        Ok(self.corners().iter().fold(nominal, |m, i| m.max(i.fill)))
    }

    /// How the ring sits on the wall that holds it, from its free dimensions (docs/model.md
    /// §6.2): the handbook's stretch onto an inner seat or OD compression into an outer one,
    /// and the circumferential compression c of a ring larger than its wall — a piston ring's
    /// ID on the groove diameter G = B − 2h, `c = (ID − G)/ID`; a rod ring's OD (its ID not
    /// on the rod) into the groove diameter R + 2h, `c = (OD − S)/OD`; a face ring's OD into
    /// the groove's outer diameter, or its ID onto the inner one.
    pub fn fit(&self) -> Fit {
        let r = &self.ring;
        let (id, od, h) = (
            r.inner_diameter,
            r.inner_diameter + 2.0 * r.cross_section,
            self.gland_depth,
        );
        let stretch = |s: f64| (s - id) / id;
        let od_compression = |s: f64| (od - s) / od;
        let (measure, compression, seat) = match self.locator {
            Locator::Free => (None, 0.0, 0.0),
            Locator::Bore(b) => {
                let g = b - 2.0 * h;
                let s = stretch(g);
                (Some(SeatMeasure::Stretch(s)), (-s).max(0.0), g)
            }
            Locator::GrooveInner(g) => {
                let s = stretch(g);
                (Some(SeatMeasure::Stretch(s)), (-s).max(0.0), g)
            }
            Locator::Rod(rod) => {
                let g = rod + 2.0 * h;
                let c = od_compression(g);
                // a ring stretched onto the rod is held by its ID: its OD is squeezed, not
                // compressed circumferentially
                let held_by_od = id >= rod;
                (
                    Some(SeatMeasure::OdCompression(c)),
                    if held_by_od { c.max(0.0) } else { 0.0 },
                    g,
                )
            }
            Locator::GrooveOuter(g) => {
                let c = od_compression(g);
                (Some(SeatMeasure::OdCompression(c)), c.max(0.0), g)
            }
        };
        Fit {
            measure,
            compression,
            seat,
        }
    }

    /// Whether the ring can be assembled (docs/model.md §6.2), and the handbook limits it
    /// breaks if it can. Refused: everything [`GlandDesign::installed`] refuses; a ring larger
    /// than its wall by [`MAX_COMPRESSION`] or more; a gland fill of 100 % or more at maximum
    /// material condition. Warned ([`Limit`]): a circumferential compression above
    /// [`MAX_COMPRESSION_GUIDANCE`]; a squeeze at the tolerance limits outside
    /// [`STATIC_SQUEEZE`] or, `dynamic`, [`DYNAMIC_SQUEEZE`].
    pub fn feasibility(&self, dynamic: bool) -> Result<Vec<Limit>, GlandError> {
        let nominal = self.installed()?;
        let fit = self.fit();
        if fit.compression >= MAX_COMPRESSION {
            let outer = matches!(self.locator, Locator::Rod(_) | Locator::GrooveOuter(_));
            let r = &self.ring;
            return Err(GlandError::Overcompressed {
                compression: fit.compression,
                ring: if outer {
                    r.inner_diameter + 2.0 * r.cross_section
                } else {
                    r.inner_diameter
                },
                seat: fit.seat,
                outer,
            });
        }
        let fill = self.max_material_fill()?;
        if fill >= 1.0 {
            return Err(GlandError::OverfilledAtMaximumMaterial {
                fill,
                nominal: nominal.fill,
            });
        }
        let mut limits = Vec::new();
        if fit.compression > MAX_COMPRESSION_GUIDANCE {
            limits.push(Limit::Compression {
                compression: fit.compression,
                seat: fit.seat,
            });
        }
        let range = if dynamic {
            DYNAMIC_SQUEEZE
        } else {
            STATIC_SQUEEZE
        };
        let squeeze = self.squeeze_range()?;
        if squeeze.min < range.0 || squeeze.max > range.1 {
            limits.push(Limit::Squeeze {
                min: squeeze.min,
                max: squeeze.max,
                range,
                dynamic,
            });
        }
        Ok(limits)
    }

    /// A face ring's seat against the pressure side `side`: the ring must bear on the wall the
    /// pressure pushes it onto (its OD on the outer wall for pressure inside, its ID on the
    /// inner wall for pressure outside); a free ring or a radial gland has no wall to check.
    pub fn check_side(&self, side: PressureSide) -> Result<(), GlandError> {
        match PressureSide::of(self.locator) {
            Some(seated) if seated != side => Err(GlandError::WrongWall { side }),
            _ => Ok(()),
        }
    }

    /// The gland depth h \[m\] that gives the squeeze `squeeze` (0 < ε < 1) to this ring,
    /// `h = d′ (1 − ε)` with d′ the stretched cord — solved by fixed-point iteration where the
    /// seat depends on h (a piston's groove bottom `B − 2h`): the dependence is weak (∂d′/∂h is
    /// of order d/D), so it converges in a few steps.
    pub fn depth_for_squeeze(&self, squeeze: f64) -> Result<f64, GlandError> {
        let r = &self.ring;
        let mut h = r.cross_section * (1.0 - squeeze);
        for _ in 0..100 {
            let inst = install(
                r.inner_diameter,
                r.cross_section,
                h,
                self.groove_width,
                self.locator,
            )?;
            let next = inst.cross_section * (1.0 - squeeze);
            let done = (next - h).abs() <= 1e-15 * h;
            h = next;
            if done {
                break;
            }
        }
        Ok(h)
    }
}

/// The seat of a ring (free ID `id`, cord `d`) in a gland of depth `h`.
fn seat(locator: Locator, id: f64, d: f64, h: f64) -> Result<Seat, GlandError> {
    // radial gland between diameters s_in < s_out (s_out − s_in = 2h): a ring smaller than
    // the inner one is stretched onto it; otherwise its OD, larger than the outer one when
    // d > h, is compressed onto that (a ring that touches neither wall is free)
    let radial = |s_in: f64, s_out: f64| {
        if id < s_in {
            Seat::Inner(s_in)
        } else if id + 2.0 * d > s_out {
            Seat::Outer(s_out)
        } else {
            Seat::Free
        }
    };
    Ok(match locator {
        Locator::Free => Seat::Free,
        Locator::GrooveInner(g) => Seat::Inner(g),
        Locator::GrooveOuter(g) => Seat::Outer(g),
        Locator::Bore(bore) => {
            let bottom = bore - 2.0 * h;
            if bottom <= 0.0 {
                return Err(GlandError::NoGrooveBottom { bore, depth: h });
            }
            radial(bottom, bore)
        }
        Locator::Rod(rod) => radial(rod, rod + 2.0 * h),
    })
}

/// Stretch, stretched cord, squeeze and fill of a ring (free ID `id`, cord `d`) in a gland of
/// depth `h`, width `w`; squeeze and fill are returned as they come (no fit check).
pub fn install(id: f64, d: f64, h: f64, w: f64, locator: Locator) -> Result<Installed, GlandError> {
    // constant volume of the torus: d′² D′ = d² D, D = id + d
    let k = d * d * (id + d);
    let (d1, inner, mean) = match seat(locator, id, d, h)? {
        Seat::Free => (d, id, id + d),
        // d′²(S + d′) = k: increasing in d′, one positive root
        Seat::Inner(s) => {
            let f = |x: f64| x * x * (s + x) - k;
            let mut hi = d;
            for _ in 0..64 {
                if f(hi) >= 0.0 {
                    break;
                }
                hi *= 2.0;
            }
            let d1 = bisect(f, 0.0, hi);
            (d1, s, s + d1)
        }
        // d′²(S − d′) = k with d′ < S/2 (the hole stays open): increasing there
        Seat::Outer(s) => {
            let f = |x: f64| x * x * (s - x) - k;
            if s <= 0.0 || f(0.5 * s) <= 0.0 {
                return Err(GlandError::CannotSeat { diameter: s });
            }
            let d1 = bisect(f, 0.0, 0.5 * s);
            (d1, s - 2.0 * d1, s - d1)
        }
    };
    Ok(Installed {
        stretch: (inner - id) / id,
        inner_diameter: inner,
        cross_section: d1,
        mean_diameter: mean,
        squeeze: 1.0 - h / d1,
        fill: PI * d1 * d1 / 4.0 / (h * w),
    })
}

/// The root of an increasing `f` in (lo, hi) with f(lo) < 0 ≤ f(hi), by bisection to the last
/// bit.
fn bisect(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let (lo, hi) = roots::bisect(lo, hi, 200, roots::to_the_last_bit, |x| f(x) < 0.0);
    0.5 * (lo + hi)
}

/// The housing's material, for the thermal strain of a groove-seated ring (docs/model.md §6):
/// linear CTEs near room temperature, each with the source it was read from; one
/// representative alloy per name, taken constant over the temperature range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Housing {
    Steel,
    Stainless,
    Aluminium,
    Brass,
    Bronze,
    CastIron,
    Titanium,
}

/// AmesWeb, linear thermal expansion coefficients of steels.
const AMES_STEELS: &str =
    "https://amesweb.info/Materials/Linear_Thermal_Expansion_Coefficient_of_Steel.aspx";
/// AmesWeb, linear thermal expansion coefficients of metals.
const AMES_METALS: &str =
    "https://amesweb.info/Materials/Linear-Thermal-Expansion-Coefficient-Metals.aspx";

impl Housing {
    /// Every housing, in the order of the messages.
    pub const ALL: [Housing; 7] = [
        Housing::Steel,
        Housing::Stainless,
        Housing::Aluminium,
        Housing::Brass,
        Housing::Bronze,
        Housing::CastIron,
        Housing::Titanium,
    ];

    /// The scenario's name (`housing = "cast-iron"`).
    pub fn name(self) -> &'static str {
        match self {
            Housing::Steel => "steel",
            Housing::Stainless => "stainless",
            Housing::Aluminium => "aluminium",
            Housing::Brass => "brass",
            Housing::Bronze => "bronze",
            Housing::CastIron => "cast-iron",
            Housing::Titanium => "titanium",
        }
    }

    /// The housing named `name` (`"aluminum"` is accepted for `"aluminium"`).
    pub fn from_name(name: &str) -> Option<Housing> {
        if name == "aluminum" {
            return Some(Housing::Aluminium);
        }
        Housing::ALL.into_iter().find(|h| h.name() == name)
    }

    /// Linear CTE α_h \[1/K\].
    pub fn expansion(self) -> f64 {
        match self {
            Housing::Steel => 11.7e-6,
            Housing::Stainless => 17.2e-6,
            Housing::Aluminium => 23.6e-6,
            Housing::Brass => 20.5e-6,
            Housing::Bronze => 18.0e-6,
            Housing::CastIron => 11.4e-6,
            Housing::Titanium => 8.6e-6,
        }
    }

    /// Which alloy the value is for and where it was read.
    pub fn source(self) -> String {
        let callister = "the same value in W.D. Callister, Fundamentals of Materials Science \
                         and Engineering: An Integrated Approach, 3rd ed., App. B, Table B.6 \
                         (read at https://issuhub.com/view/index/5550?pageIndex=844)";
        match self {
            Housing::Steel => format!("AISI 1020 carbon steel, annealed, 0–100 °C; {AMES_STEELS}"),
            Housing::Stainless => {
                format!("stainless grade 304, annealed, 0–100 °C; {AMES_STEELS}")
            }
            Housing::Aluminium => format!("aluminium alloy 6061; {AMES_METALS}; {callister}"),
            Housing::Brass => format!("free-cutting brass C36000; {AMES_METALS}; {callister}"),
            Housing::Bronze => format!("bearing bronze C93200; {AMES_METALS}; {callister}"),
            Housing::CastIron => format!(
                "grey cast iron G3000; {AMES_METALS} (Engineering ToolBox gives 5.8e-6 1/°F = \
                 10.4e-6 1/K for grey cast iron, 32–212 °F, \
                 https://www.engineeringtoolbox.com/thermal-expansion-metals-d_859.html)"
            ),
            Housing::Titanium => "Ti-6Al-4V and commercially pure grade 1 (both 8.6e-6 \
                                   1/K): W.D. Callister, Fundamentals of Materials Science \
                                   and Engineering: An Integrated Approach, 3rd ed., App. B, \
                                   Table B.6 (read at \
                                   https://issuhub.com/view/index/5550?pageIndex=844)"
                .to_owned(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(id: f64, d: f64) -> Ring {
        Ring {
            inner_diameter: id,
            inner_diameter_tolerance: 0.0,
            cross_section: d,
            cross_section_tolerance: 0.0,
        }
    }

    fn design(locator: Locator, h: f64) -> GlandDesign {
        GlandDesign {
            kind: GlandKind::Piston,
            ring: ring(24.99e-3, 3.53e-3),
            locator,
            gland_depth: h,
            gland_depth_tolerance: 0.0,
            groove_width: 4.7e-3,
            extrusion_gap: 0.0,
        }
    }

    #[test]
    fn volume_is_conserved_on_every_seat() {
        let v = |id: f64, d: f64| d * d * (id + d);
        let v0 = v(24.99e-3, 3.53e-3);
        for locator in [
            Locator::Free,
            Locator::Bore(32e-3),
            Locator::Rod(26e-3),
            Locator::Rod(24e-3),
            Locator::GrooveOuter(32.5e-3),
            Locator::GrooveInner(25.5e-3),
        ] {
            let i = design(locator, 2.8e-3).installed().unwrap();
            assert!(((i.mean_diameter - i.inner_diameter) / i.cross_section - 1.0).abs() < 1e-12);
            assert!((v(i.inner_diameter, i.cross_section) / v0 - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_piston_ring_is_stretched_onto_the_groove_bottom() {
        // groove bottom 31.06 − 2·2.8 = 25.46 mm > ID 24.99 mm
        let i = design(Locator::Bore(31.06e-3), 2.8e-3).installed().unwrap();
        assert!((i.inner_diameter - 25.46e-3).abs() < 1e-15);
        assert!((i.stretch - (25.46 / 24.99 - 1.0)).abs() < 1e-12);
        assert!(i.cross_section < 3.53e-3);
        // first order: Δd/d ≈ −s_c/2 with s_c the centreline stretch
        let sc = (i.mean_diameter - 28.52e-3) / 28.52e-3;
        assert!(((3.53e-3 - i.cross_section) / 3.53e-3 / (sc / 2.0) - 1.0).abs() < 0.05);
    }

    #[test]
    fn errors_and_ranges() {
        let deep = design(Locator::Free, 3.6e-3);
        assert!(matches!(
            deep.installed(),
            Err(GlandError::GrooveTooDeep { .. })
        ));
        let mut narrow = design(Locator::Free, 2.8e-3);
        narrow.groove_width = 3.0e-3;
        assert!(matches!(
            narrow.installed(),
            Err(GlandError::Overfilled { .. })
        ));
        assert!(matches!(
            design(Locator::Bore(5e-3), 2.8e-3).installed(),
            Err(GlandError::NoGrooveBottom { .. })
        ));
        let mut d = design(Locator::Free, 2.8e-3);
        d.ring.cross_section_tolerance = 0.1e-3;
        d.gland_depth_tolerance = 0.05e-3;
        let r = d.squeeze_range().unwrap();
        // free ring: ε = 1 − h/d at the corners
        assert!((r.min - (1.0 - 2.85 / 3.43)).abs() < 1e-12);
        assert!((r.max - (1.0 - 2.75 / 3.63)).abs() < 1e-12);
        assert!((r.nominal - (1.0 - 2.8 / 3.53)).abs() < 1e-12);
        let h = design(Locator::Bore(31.06e-3), 2.8e-3)
            .depth_for_squeeze(0.2)
            .unwrap();
        let mut back = design(Locator::Bore(31.06e-3), h);
        back.gland_depth = h;
        assert!((back.installed().unwrap().squeeze - 0.2).abs() < 1e-12);
    }

    #[test]
    fn fit_measures_are_the_handbook_closed_forms() {
        let (id, d) = (24.99e-3, 3.53e-3);
        let od = id + 2.0 * d;
        // piston: stretch onto G = B − 2h; a ring larger than G is compressed (ID − G)/ID
        let f = design(Locator::Bore(31.06e-3), 2.8e-3).fit();
        let Some(SeatMeasure::Stretch(s)) = f.measure else {
            panic!("{f:?}")
        };
        assert!((s - (25.46e-3 - id) / id).abs() < 1e-12);
        assert_eq!(f.compression, 0.0);
        let f = design(Locator::Bore(25.4e-3), 2.9e-3).fit();
        assert!((f.compression - (id - 19.6e-3) / id).abs() < 1e-12);
        // rod held by its OD (ID ≥ rod): OD compression into R + 2h
        let f = design(Locator::Rod(24.99e-3), 3.0e-3).fit();
        let c = (od - 30.99e-3) / od;
        let Some(SeatMeasure::OdCompression(m)) = f.measure else {
            panic!("{f:?}")
        };
        assert!((m - c).abs() < 1e-12 && (f.compression - c).abs() < 1e-12);
        // rod stretched onto the rod: its OD is squeezed, not compressed
        assert_eq!(design(Locator::Rod(26e-3), 2.8e-3).fit().compression, 0.0);
        // face: OD into the outer wall, ID onto the inner wall; a free ring has no measure
        let f = design(Locator::GrooveOuter(31e-3), 2.8e-3).fit();
        assert!((f.compression - (od - 31e-3) / od).abs() < 1e-15);
        let f = design(Locator::GrooveInner(24e-3), 2.8e-3).fit();
        assert!((f.compression - (id - 24e-3) / id).abs() < 1e-15);
        assert_eq!(design(Locator::Free, 2.8e-3).fit().measure, None);
    }

    #[test]
    fn compression_is_warned_past_3_percent_and_refused_at_10() {
        let od = 24.99e-3 + 2.0 * 3.53e-3;
        let at = |c: f64| design(Locator::GrooveOuter(od * (1.0 - c)), 2.8e-3);
        let compression = |l: &[Limit]| l.iter().any(|l| matches!(l, Limit::Compression { .. }));
        assert!(!compression(&at(0.029).feasibility(false).unwrap()));
        assert!(compression(&at(0.031).feasibility(false).unwrap()));
        assert!(compression(&at(0.099).feasibility(false).unwrap()));
        assert!(matches!(
            at(0.101).feasibility(false),
            Err(GlandError::Overcompressed { outer: true, .. })
        ));
        // the review's -214 in a 25.4 mm bore: refused at the ID, 21.6 %
        let Err(GlandError::Overcompressed {
            compression,
            outer: false,
            ..
        }) = design(Locator::Bore(25.4e-3), 2.9e-3).feasibility(false)
        else {
            panic!("not refused")
        };
        assert!((compression - (24.99 - 19.6) / 24.99).abs() < 1e-12);
    }

    #[test]
    fn fill_at_maximum_material_is_refused_at_100_percent() {
        // free ring, nominal fill π d²/4/(h w) = 0.96; the corners raise d and lower h
        let (d, h, dt, ht) = (3.53e-3, 2.65e-3, 0.1e-3, 0.05e-3);
        let mut g = design(Locator::Free, h);
        g.groove_width = PI * d * d / 4.0 / (h * 0.96);
        g.ring.cross_section_tolerance = dt;
        g.gland_depth_tolerance = ht;
        let mmc = PI * (d + dt) * (d + dt) / 4.0 / ((h - ht) * g.groove_width);
        assert!(mmc > 1.0);
        let Err(GlandError::OverfilledAtMaximumMaterial { fill, nominal }) = g.feasibility(false)
        else {
            panic!("not refused")
        };
        assert!((fill - mmc).abs() < 1e-12 && (nominal - 0.96).abs() < 1e-12);
        // just inside: the width that gives 99.9 % at maximum material passes
        g.groove_width *= mmc / 0.999;
        assert!(g.feasibility(false).is_ok());
    }

    #[test]
    fn the_squeeze_range_is_static_or_dynamic() {
        // free ring without tolerances: ε = 1 − h/d at every corner
        let d = 3.53e-3;
        let squeeze = |eps: f64, dynamic: bool| {
            design(Locator::Free, d * (1.0 - eps))
                .feasibility(dynamic)
                .unwrap()
                .iter()
                .any(|l| matches!(l, Limit::Squeeze { .. }))
        };
        for (eps, dynamic, warned) in [
            (0.101, false, false),
            (0.099, false, true),
            (0.299, false, false),
            (0.301, false, true),
            (0.159, true, false),
            (0.161, true, true),
            (0.101, true, false),
            (0.099, true, true),
        ] {
            assert_eq!(squeeze(eps, dynamic), warned, "{eps} {dynamic}");
        }
    }

    #[test]
    fn a_face_ring_must_bear_on_the_wall_its_pressure_pushes_it_onto() {
        let outer = design(Locator::GrooveOuter(32.1e-3), 2.8e-3);
        let inner = design(Locator::GrooveInner(25.2e-3), 2.8e-3);
        assert!(outer.check_side(PressureSide::Inside).is_ok());
        assert!(inner.check_side(PressureSide::Outside).is_ok());
        assert_eq!(
            outer.check_side(PressureSide::Outside),
            Err(GlandError::WrongWall {
                side: PressureSide::Outside
            })
        );
        assert!(inner.check_side(PressureSide::Inside).is_err());
        // no wall, no check
        assert!(
            design(Locator::Free, 2.8e-3)
                .check_side(PressureSide::Outside)
                .is_ok()
        );
    }

    #[test]
    fn housings_have_names_and_values() {
        for h in Housing::ALL {
            assert_eq!(Housing::from_name(h.name()), Some(h));
            assert!(h.expansion() > 5e-6 && h.expansion() < 3e-5);
            assert!(h.source().contains("https://"));
        }
        assert_eq!(Housing::from_name("aluminum"), Some(Housing::Aluminium));
        assert_eq!(Housing::from_name("wood"), None);
    }
}
