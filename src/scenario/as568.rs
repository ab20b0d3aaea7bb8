//! The AS568 O-ring size table (`src/scenario/as568.csv`, embedded at compile time): dash
//! number, inside diameter and cross-section with their ± tolerances, in inches as transcribed;
//! metric values are inch × 25.4 exactly. The file's header states where the rows come from
//! (a transcription in a public GitHub repository, cross-checked against a vendor chart) and
//! which rows were corrected; docs/model.md §6.2 repeats it.
//!
//! Sizes are named `AS568-214` (case-insensitive; the dash number may be written without its
//! leading zeros, `AS568-4` = `AS568-004`). An unknown size is an error that lists the nearest
//! sizes of the table.

use std::fmt;
use std::sync::OnceLock;

/// The embedded table.
pub const CSV: &str = include_str!("as568.csv");
/// Where the table is, for messages.
pub const FILE: &str = "src/scenario/as568.csv";
/// The provenance of the table, in one line.
pub const SOURCE: &str = "transcribed from CrispyConductor/waterproof-geocache-container, \
                          oring.scad @ 06814412616917711afcf0395a8a002812be8464, cross-checked \
                          row by row and completed (-391…-395, -468…-475) against ISO 3601-1 \
                          Class A as tabulated in gumyr/bd_warehouse @ \
                          f76fb07fe4f1755309581d1fdfc79915cbf0a263 (Apache-2.0), and against \
                          https://www.globaloring.com/as568-size-chart/";

/// ISO 3601-1 Class A in mm (gumyr/bd_warehouse, Apache-2.0; its notice in the file): the
/// independent table [`CSV`] is checked against (a test).
#[cfg(test)]
const ISO_3601_CLASS_A: &str = include_str!("iso3601-class-a.csv");

/// Metres per inch (the international inch).
pub const INCH: f64 = 0.0254;

/// One size of the table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Size {
    /// Dash number, e.g. 214.
    pub dash: u16,
    /// Inside diameter \[in\].
    pub id_in: f64,
    /// ± tolerance of the inside diameter \[in\].
    pub id_tol_in: f64,
    /// Cross-section \[in\].
    pub cs_in: f64,
    /// ± tolerance of the cross-section \[in\].
    pub cs_tol_in: f64,
    /// Line of the row in [`FILE`].
    pub line: usize,
}

impl Size {
    /// `AS568-214`.
    pub fn name(&self) -> String {
        format!("AS568-{:03}", self.dash)
    }

    /// The series: the hundreds of the dash number (0 for -001…-050).
    pub fn series(&self) -> u16 {
        self.dash / 100
    }

    /// The ring in SI units (inch × 0.0254 m).
    pub fn ring(&self) -> crate::gland::Ring {
        crate::gland::Ring {
            inner_diameter: self.id_in * INCH,
            inner_diameter_tolerance: self.id_tol_in * INCH,
            cross_section: self.cs_in * INCH,
            cross_section_tolerance: self.cs_tol_in * INCH,
        }
    }
}

/// A malformed row of the embedded table (a bug, caught by the unit tests).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TableError(pub String);

impl fmt::Display for TableError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{FILE}: {}", self.0)
    }
}

impl std::error::Error for TableError {}

/// Every size of the table, in file order (by dash number), parsed once.
pub fn sizes() -> Result<&'static [Size], TableError> {
    static TABLE: OnceLock<Result<Vec<Size>, TableError>> = OnceLock::new();
    TABLE
        .get_or_init(|| parse(CSV))
        .as_ref()
        .map(Vec::as_slice)
        .map_err(Clone::clone)
}

fn parse(text: &str) -> Result<Vec<Size>, TableError> {
    let mut out: Vec<Size> = Vec::new();
    for (line, row) in super::text::data_lines(text) {
        if row.starts_with("dash") {
            continue;
        }
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        let [dash, id, id_tol, cs, cs_tol] = cells[..] else {
            return Err(TableError(format!("line {line}: expected 5 columns")));
        };
        let number = |s: &str| {
            s.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && *v > 0.0)
                .ok_or_else(|| TableError(format!("line {line}: not a positive number: {s:?}")))
        };
        let dash = dash
            .parse::<u16>()
            .map_err(|_| TableError(format!("line {line}: bad dash number {dash:?}")))?;
        if out.last().is_some_and(|s| s.dash >= dash) {
            return Err(TableError(format!(
                "line {line}: dash numbers must increase"
            )));
        }
        out.push(Size {
            dash,
            id_in: number(id)?,
            id_tol_in: number(id_tol)?,
            cs_in: number(cs)?,
            cs_tol_in: number(cs_tol)?,
            line,
        });
    }
    Ok(out)
}

/// Why a size name was not found.
#[derive(Debug, Clone, PartialEq)]
pub enum LookupError {
    /// Not of the form `AS568-NNN`.
    Malformed(String),
    /// A well-formed name that is not in the table; the sizes on either side of its dash number.
    Unknown { name: String, nearest: Vec<String> },
    /// The embedded table is malformed.
    Table(TableError),
}

impl fmt::Display for LookupError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LookupError::Malformed(name) => write!(
                f,
                "expected an AS568 size such as \"AS568-214\", got {name:?} (the table has \
                 -001…-050, -102…-178, -201…-284, -309…-395 and -425…-475)"
            ),
            LookupError::Unknown { name, nearest } => write!(
                f,
                "unknown size {name:?}; the nearest sizes of the AS568 table are {}",
                nearest.join(", ")
            ),
            LookupError::Table(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for LookupError {}

/// The size named `name` (`AS568-214`, case-insensitive).
pub fn lookup(name: &str) -> Result<Size, LookupError> {
    let table = sizes().map_err(LookupError::Table)?;
    let trimmed = name.trim();
    let dash = trimmed
        .get(..6)
        .filter(|p| p.eq_ignore_ascii_case("AS568-"))
        .and_then(|_| trimmed.get(6..))
        .filter(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
        .and_then(|n| n.parse::<u32>().ok())
        .ok_or_else(|| LookupError::Malformed(name.to_owned()))?;
    if let Some(size) = table.iter().find(|s| u32::from(s.dash) == dash) {
        return Ok(*size);
    }
    // the two sizes on either side of the missing dash number
    let at = table.partition_point(|s| u32::from(s.dash) < dash);
    let nearest = &table[at.saturating_sub(2)..(at + 2).min(table.len())];
    Err(LookupError::Unknown {
        name: name.to_owned(),
        nearest: nearest.iter().map(|s| s.name()).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_parses_and_covers_its_series() {
        let t = sizes().unwrap();
        let count = |lo: u16, hi: u16| t.iter().filter(|s| (lo..=hi).contains(&s.dash)).count();
        assert_eq!(count(1, 50), 50);
        assert_eq!(count(102, 178), 77);
        assert_eq!(count(201, 284), 84);
        assert_eq!(count(309, 395), 87);
        assert_eq!(count(425, 475), 51);
        assert_eq!(t.len(), 349);
    }

    /// Every size against ISO 3601-1 Class A in mm (an independent tabulation): ID,
    /// cross-section and both tolerances within 0.006 mm of inch × 25.4 (the mm table's
    /// rounding and the tolerances' conversion), and the same set of sizes.
    #[test]
    fn every_size_matches_iso_3601_class_a() {
        let t = sizes().unwrap();
        let iso: Vec<Vec<f64>> = ISO_3601_CLASS_A
            .lines()
            .filter(|l| !l.starts_with('#') && !l.starts_with("Size"))
            .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
            .collect();
        assert_eq!(iso.len(), t.len());
        for (size, row) in t.iter().zip(&iso) {
            assert_eq!(f64::from(size.dash), row[0]);
            let mm = |inch: f64| inch * 25.4;
            for (ours, theirs, what) in [
                (mm(size.id_in), row[1], "ID"),
                (mm(size.cs_in), row[2], "cross-section"),
                (mm(size.id_tol_in), row[3], "ID tolerance"),
                (mm(size.cs_tol_in), row[4], "cross-section tolerance"),
            ] {
                assert!(
                    (ours - theirs).abs() <= 0.006,
                    "AS568-{:03} {what}: {ours} mm vs ISO {theirs} mm",
                    size.dash
                );
            }
        }
    }

    #[test]
    fn lookup_names_and_errors() {
        let s = lookup("AS568-214").unwrap();
        assert_eq!((s.dash, s.id_in, s.cs_in), (214, 0.984, 0.139));
        assert_eq!(lookup("as568-214").unwrap(), s);
        assert_eq!(lookup("AS568-4").unwrap().dash, 4);
        assert!(matches!(lookup("214"), Err(LookupError::Malformed(_))));
        assert!(matches!(lookup("AS568-"), Err(LookupError::Malformed(_))));
        assert!(matches!(
            lookup("AS568-2x4"),
            Err(LookupError::Malformed(_))
        ));
        let e = lookup("AS568-290").unwrap_err();
        let LookupError::Unknown { nearest, .. } = &e else {
            panic!("{e}")
        };
        assert_eq!(
            nearest,
            &["AS568-283", "AS568-284", "AS568-309", "AS568-310"]
        );
        assert!(e.to_string().contains("AS568-284, AS568-309"), "{e}");
    }
}
