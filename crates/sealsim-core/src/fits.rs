//! ISO 286 limits and fits for the gland designer (docs/model.md §6.2.1): the standard
//! tolerance grades IT5–IT11 and the fundamental deviations of the hole H and the shafts d, e,
//! f, g and h, for nominal sizes up to 500 mm.
//!
//! **Sources** (ISO 286-1 tables as reproduced; the standard itself was not read):
//! * IT grades: MechGuru, "DIN ISO 286 standard tolerance zone size table"
//!   (<http://mechguru.com/machine-design/din-iso-286-standard-tolerance-zone-size-table-different-grades-nominal-size>),
//!   IT5–IT11 in mm for 0–3150 mm; the rows up to 500 mm are transcribed in `IT`. The h
//!   shafts' columns of BIG DAISHOWA's catalogue, "Shaft tolerances", p. 139
//!   (<https://catalog.bigdaishowa.com/view/510119233/139>), give the same IT5–IT9 values
//!   (h5–h9 lower deviations) in every row up to 500 mm.
//! * Shaft fundamental deviations (upper deviation es of d, e, f, g; h is 0): up to 120 mm
//!   MechGuru, "DIN ISO 286 tolerance fundamental deviation tables – shaft"
//!   (<https://mechguru.com/machine-design/din-iso-286-tolerance-fundamental-deviation-tables-shaft/>);
//!   120–180 mm Coban Engineering, "Upper and lower deviations – shafts"
//!   (<https://www.cobanengineering.com/Tolerances/UpperAndLowerDeviationsShafts.asp>), whose
//!   rows up to 120 mm agree with MechGuru's; 180–500 mm K.L. Narayana et al., *Machine
//!   Drawing*, Table 15.2 "Fundamental deviations for shafts of types a to k of sizes up to
//!   500 mm" (read at <https://issuhub.com/view/index?id=5590&pageIndex=238>).
//! * The relations: a hole H has its lower deviation EI = 0 and ES = EI + IT; a shaft's lower
//!   deviation is ei = es − IT (Coban Engineering, same page: "es=ei+IT, ei=es-IT").
//!
//! So `30 H8` = +0/+33 µm and `30 f7` = −20/−41 µm (30 mm lies in the row "over 18 up to and
//! including 30").

use std::fmt;

/// The upper ends of the nominal-size rows \[mm\]: a size belongs to the first row whose end is
/// at or above it ("over … up to and including").
const ROW_ENDS_MM: [f64; 13] = [
    3.0, 6.0, 10.0, 18.0, 30.0, 50.0, 80.0, 120.0, 180.0, 250.0, 315.0, 400.0, 500.0,
];

/// Standard tolerance grades IT5…IT11 \[µm\], one row per nominal-size row of
/// [`ROW_ENDS_MM`] (MechGuru's table, module docs).
const IT: [[f64; 7]; 13] = [
    [4.0, 6.0, 10.0, 14.0, 25.0, 40.0, 60.0],
    [5.0, 8.0, 12.0, 18.0, 30.0, 48.0, 75.0],
    [6.0, 9.0, 15.0, 22.0, 36.0, 58.0, 90.0],
    [8.0, 11.0, 18.0, 27.0, 43.0, 70.0, 110.0],
    [9.0, 13.0, 21.0, 33.0, 52.0, 84.0, 130.0],
    [11.0, 16.0, 25.0, 39.0, 62.0, 100.0, 160.0],
    [13.0, 19.0, 30.0, 46.0, 74.0, 120.0, 190.0],
    [15.0, 22.0, 35.0, 54.0, 87.0, 140.0, 220.0],
    [18.0, 25.0, 40.0, 63.0, 100.0, 160.0, 250.0],
    [20.0, 29.0, 46.0, 72.0, 115.0, 185.0, 290.0],
    [23.0, 32.0, 52.0, 81.0, 130.0, 210.0, 320.0],
    [25.0, 36.0, 57.0, 89.0, 140.0, 230.0, 360.0],
    [27.0, 40.0, 63.0, 97.0, 155.0, 250.0, 400.0],
];

/// Upper deviations es of the shafts d, e, f, g \[µm\] per nominal-size row (module docs; the
/// standard's sub-rows, e.g. 10–14 and 14–18, carry the same values for these letters).
const SHAFT_ES: [[f64; 4]; 13] = [
    [-20.0, -14.0, -6.0, -2.0],
    [-30.0, -20.0, -10.0, -4.0],
    [-40.0, -25.0, -13.0, -5.0],
    [-50.0, -32.0, -16.0, -6.0],
    [-65.0, -40.0, -20.0, -7.0],
    [-80.0, -50.0, -25.0, -9.0],
    [-100.0, -60.0, -30.0, -10.0],
    [-120.0, -72.0, -36.0, -12.0],
    [-145.0, -85.0, -43.0, -14.0],
    [-170.0, -100.0, -50.0, -15.0],
    [-190.0, -110.0, -56.0, -17.0],
    [-210.0, -125.0, -62.0, -18.0],
    [-230.0, -135.0, -68.0, -20.0],
];

/// The lowest and highest tolerance grade of the tables.
pub const GRADES: std::ops::RangeInclusive<u8> = 5..=11;
/// The largest nominal size of the tables \[m\].
pub const MAX_NOMINAL: f64 = 0.5;

/// A tolerance class: a fundamental deviation (letter) and a grade, e.g. `H8`, `f7`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ToleranceClass {
    /// `H` (a hole) or `d`, `e`, `f`, `g`, `h` (a shaft).
    pub letter: char,
    /// IT grade, 5–11.
    pub grade: u8,
}

/// Why a class or a size is not in the tables.
#[derive(Debug, Clone, PartialEq)]
pub enum FitError {
    /// Not a class of the tables (the text given).
    UnknownClass(String),
    /// A hole class where a shaft is needed, or the reverse (the class, what was needed).
    WrongFeature(String, &'static str),
    /// The nominal size \[m\] is outside (0, 500 mm].
    OutOfRange(f64),
}

impl fmt::Display for FitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FitError::UnknownClass(text) => write!(
                f,
                "unknown tolerance class {text:?}: expected a hole H5…H11 or a shaft d, e, f, \
                 g or h with grade 5…11 (ISO 286), e.g. \"H8/f7\""
            ),
            FitError::WrongFeature(class, needed) => write!(
                f,
                "{class} is not a {needed} class: holes are upper case (H8), shafts lower case \
                 (f7); write the fit as HOLE/SHAFT, e.g. \"H8/f7\""
            ),
            FitError::OutOfRange(nominal) => write!(
                f,
                "nominal size {} mm is outside the ISO 286 tables sealsim carries (up to \
                 500 mm)",
                crate::units::show(nominal * 1e3)
            ),
        }
    }
}

impl std::error::Error for FitError {}

impl ToleranceClass {
    /// Parses `H8`, `f7`, … (letter then grade).
    pub fn parse(text: &str) -> Result<ToleranceClass, FitError> {
        let unknown = || FitError::UnknownClass(text.to_owned());
        let t = text.trim();
        let mut chars = t.chars();
        let letter = chars.next().ok_or_else(unknown)?;
        let grade: u8 = chars.as_str().parse().map_err(|_| unknown())?;
        if !"Hdefgh".contains(letter) || !GRADES.contains(&grade) {
            return Err(unknown());
        }
        Ok(ToleranceClass { letter, grade })
    }

    /// Whether it is a hole class (upper-case letter).
    pub fn is_hole(self) -> bool {
        self.letter.is_ascii_uppercase()
    }

    /// `H8`.
    pub fn name(self) -> String {
        format!("{}{}", self.letter, self.grade)
    }

    /// The (lower, upper) limit deviations \[m\] of a feature of nominal size `nominal` \[m\].
    pub fn deviations(self, nominal: f64) -> Result<(f64, f64), FitError> {
        let row = row(nominal)?;
        let it = IT[row][usize::from(self.grade - GRADES.start())];
        let (lower, upper) = match self.letter {
            'H' => (0.0, it),
            'h' => (-it, 0.0),
            letter => {
                let column = match letter {
                    'd' => 0,
                    'e' => 1,
                    'f' => 2,
                    _ => 3,
                };
                let es = SHAFT_ES[row][column];
                (es - it, es)
            }
        };
        Ok((lower * 1e-6, upper * 1e-6))
    }

    /// The (smallest, largest) size \[m\] of a feature of nominal size `nominal` \[m\].
    pub fn limits(self, nominal: f64) -> Result<(f64, f64), FitError> {
        let (lo, hi) = self.deviations(nominal)?;
        Ok((nominal + lo, nominal + hi))
    }
}

/// The standard tolerance ITn \[m\] at nominal size `nominal` \[m\].
pub fn standard_tolerance(grade: u8, nominal: f64) -> Result<f64, FitError> {
    if !GRADES.contains(&grade) {
        return Err(FitError::UnknownClass(format!("IT{grade}")));
    }
    Ok(IT[row(nominal)?][usize::from(grade - GRADES.start())] * 1e-6)
}

/// A fit `HOLE/SHAFT`, e.g. `H8/f7`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fit {
    pub hole: ToleranceClass,
    pub shaft: ToleranceClass,
}

impl Fit {
    /// Parses `H8/f7`: a hole class, a slash, a shaft class.
    pub fn parse(text: &str) -> Result<Fit, FitError> {
        let (hole, shaft) = text
            .split_once('/')
            .ok_or_else(|| FitError::UnknownClass(text.to_owned()))?;
        let hole = ToleranceClass::parse(hole)?;
        let shaft = ToleranceClass::parse(shaft)?;
        if !hole.is_hole() {
            return Err(FitError::WrongFeature(hole.name(), "hole"));
        }
        if shaft.is_hole() {
            return Err(FitError::WrongFeature(shaft.name(), "shaft"));
        }
        Ok(Fit { hole, shaft })
    }

    /// `H8/f7`.
    pub fn name(self) -> String {
        format!("{}/{}", self.hole.name(), self.shaft.name())
    }

    /// The (smallest, largest) diametral clearance \[m\] of the fit at nominal size `nominal`
    /// \[m\]: hole minus shaft at their limits.
    pub fn clearance(self, nominal: f64) -> Result<(f64, f64), FitError> {
        let (h_lo, h_hi) = self.hole.deviations(nominal)?;
        let (s_lo, s_hi) = self.shaft.deviations(nominal)?;
        Ok((h_lo - s_hi, h_hi - s_lo))
    }
}

/// The row of [`ROW_ENDS_MM`] of a nominal size \[m\].
fn row(nominal: f64) -> Result<usize, FitError> {
    let mm = nominal * 1e3;
    if !(mm.is_finite() && mm > 0.0) {
        return Err(FitError::OutOfRange(nominal));
    }
    // a size given in inches and converted may land a rounding error above a row's end
    ROW_ENDS_MM
        .iter()
        .position(|&end| mm <= end * (1.0 + 1e-12))
        .ok_or(FitError::OutOfRange(nominal))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn um(class: &str, nominal_mm: f64) -> (f64, f64) {
        let (lo, hi) = ToleranceClass::parse(class)
            .unwrap()
            .deviations(nominal_mm * 1e-3)
            .unwrap();
        ((lo * 1e6).round(), (hi * 1e6).round())
    }

    #[test]
    fn rows_are_over_up_to_and_including() {
        assert_eq!(row(30e-3).unwrap(), 4);
        assert_eq!(row(30.001e-3).unwrap(), 5);
        assert_eq!(row(3e-3).unwrap(), 0);
        assert_eq!(row(500e-3).unwrap(), 12);
        assert!(row(500.1e-3).is_err());
        assert!(row(0.0).is_err());
        assert!(row(f64::NAN).is_err());
    }

    #[test]
    fn grades_grow_with_grade_and_size() {
        for r in &IT {
            assert!(r.windows(2).all(|w| w[0] < w[1]), "{r:?}");
        }
        for g in 0..7 {
            assert!(IT.windows(2).all(|w| w[0][g] < w[1][g]));
        }
        // the shafts' es: d < e < f < g < 0 in every row, and larger for larger sizes
        for r in &SHAFT_ES {
            assert!(r.windows(2).all(|w| w[0] < w[1]) && r[3] < 0.0, "{r:?}");
        }
        for c in 0..4 {
            assert!(SHAFT_ES.windows(2).all(|w| w[0][c] >= w[1][c]));
        }
    }

    #[test]
    fn parse_and_errors() {
        assert_eq!(
            Fit::parse("H8/f7").unwrap().name(),
            "H8/f7",
            "round trip of a fit"
        );
        assert!(matches!(
            ToleranceClass::parse("H12"),
            Err(FitError::UnknownClass(_))
        ));
        assert!(matches!(
            ToleranceClass::parse("k6"),
            Err(FitError::UnknownClass(_))
        ));
        assert!(matches!(
            Fit::parse("f7/H8"),
            Err(FitError::WrongFeature(..))
        ));
        assert!(Fit::parse("H8").is_err());
        assert_eq!(um("H8", 30.0), (0.0, 33.0));
        assert_eq!(um("f7", 30.0), (-41.0, -20.0));
    }
}
