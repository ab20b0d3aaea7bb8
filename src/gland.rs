//! The gland an O-ring sits in (docs/model.md §6.3): what the fluid pressure does to a
//! groove-seated ring (energisation, extrusion into the clearance gap).

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

/// A groove-seated O-ring's gland, validated, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gland {
    pub kind: GlandKind,
    /// The gap the ring is pushed against on its low-pressure side \[m\]: half the diametral
    /// clearance of a piston or rod gland, the flange separation of a face gland.
    pub extrusion_gap: f64,
}
