//! Measured viscoelastic data for `sealsim fit-prony`: CSV files of a relaxation test
//! (t, E) or of a DMA master curve (f or ω, E′, E″).
//!
//! Two layouts are accepted, told apart by the second row:
//!
//! * **pyvisco style** (the master-curve files of NREL's pyvisco, github.com/NREL/pyvisco):
//!   two header rows, the quantity names and then their units, e.g.
//!   ```text
//!   t,E_relax            f, E_stor, E_loss
//!   s, MPa               Hz, MPa, MPa
//!   ```
//!   Units are read by [`crate::units::parse_unit`]: the time column must be a time, a
//!   frequency column a frequency, the moduli pressures. In DMA files E′ and E″ must carry the
//!   *same* unit string: mixed units (E_stor in MPa, E_loss in Pa) are refused, since they are
//!   almost always an export mistake.
//! * **plain**: one header row and SI values (s, Pa, Hz for `f`, rad/s for `omega`).
//!
//! Column names, case-insensitive, in any order: time `t` | `time`; frequency `f` | `freq` |
//! `frequency` (Hz, converted to ω = 2π f) or `omega` (rad/s; the unit `rad/s` is read as
//! 1/s); relaxation modulus `E_relax` | `E` | `E_rel`; storage modulus `E_stor` | `storage` |
//! `E'`; loss modulus `E_loss` | `loss` | `E''`. Lines starting with `#` and blank lines are
//! skipped. Data rows: every cell a finite positive number, times or frequencies strictly
//! increasing, at least 3 rows. Parsed by hand (like the PSD files) so that every error names
//! the real line: `data.csv:7: E_loss: must be positive, got -3e5`.

use crate::units::{self, Dimension, show};
use std::f64::consts::TAU;
use std::fmt;
use std::path::{Path, PathBuf};

/// Which measurement a file holds (the `--kind` of `sealsim fit-prony`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitKind {
    /// Stress relaxation: E(t).
    Relaxation,
    /// Dynamic mechanical analysis: E′(ω) and E″(ω).
    Dma,
}

impl FitKind {
    /// `relaxation` or `dma`, as on the command line.
    pub fn as_str(self) -> &'static str {
        match self {
            FitKind::Relaxation => "relaxation",
            FitKind::Dma => "dma",
        }
    }

    fn columns(self) -> &'static str {
        match self {
            FitKind::Relaxation => "t,E_relax",
            FitKind::Dma => "f,E_stor,E_loss (or omega,E_stor,E_loss)",
        }
    }
}

/// The data of a fit file in SI units, rows in file order.
#[derive(Debug, Clone, PartialEq)]
pub enum FitData {
    /// Times (s) and relaxation moduli (Pa).
    Relaxation { times: Vec<f64>, moduli: Vec<f64> },
    /// Angular frequencies ω (rad/s), storage and loss moduli (Pa).
    Dma {
        omegas: Vec<f64>,
        storage: Vec<f64>,
        loss: Vec<f64>,
    },
}

impl FitData {
    /// Number of data rows.
    pub fn points(&self) -> usize {
        match self {
            FitData::Relaxation { times, .. } => times.len(),
            FitData::Dma { omegas, .. } => omegas.len(),
        }
    }
}

/// A fit file that cannot be used: the file, the 1-based line when the problem is on one
/// line, and what is wrong. Displayed as `path:line: message`.
#[derive(Debug, Clone, PartialEq)]
pub struct FitDataError {
    pub path: PathBuf,
    pub line: Option<usize>,
    pub message: String,
}

impl fmt::Display for FitDataError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.path.display())?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for FitDataError {}

/// Reads and checks the fit file at `path`, which must hold data of `kind`.
pub fn read_fit_data(path: &Path, kind: FitKind) -> Result<FitData, FitDataError> {
    let text = std::fs::read_to_string(path).map_err(|e| FitDataError {
        path: path.to_path_buf(),
        line: None,
        message: format!("cannot read the data file: {e}"),
    })?;
    parse_fit_data(&text, path, kind)
}

/// Checks fit-file `text` as if read from `path` (used only in messages).
pub fn parse_fit_data(text: &str, path: &Path, kind: FitKind) -> Result<FitData, FitDataError> {
    parse(text, kind).map_err(|(line, message)| FitDataError {
        path: path.to_path_buf(),
        line,
        message,
    })
}

/// What a column holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Quantity {
    Time,
    /// Ordinary frequency f \[Hz\]; ω = 2π f.
    Frequency,
    /// Angular frequency ω \[rad/s\].
    Omega,
    Relaxation,
    Storage,
    Loss,
}

impl Quantity {
    /// The quantity of a header cell (case-insensitive, except that a capital `T` is
    /// pyvisco's temperature column, not the time).
    fn from_name(name: &str) -> Option<Self> {
        if name == "T" {
            return None;
        }
        Some(match name.to_lowercase().as_str() {
            "t" | "time" => Quantity::Time,
            "f" | "freq" | "frequency" => Quantity::Frequency,
            "omega" | "ω" => Quantity::Omega,
            "e_relax" | "e" | "e_rel" => Quantity::Relaxation,
            "e_stor" | "storage" | "e'" | "e′" => Quantity::Storage,
            "e_loss" | "loss" | "e''" | "e″" => Quantity::Loss,
            _ => return None,
        })
    }

    fn is_axis(self) -> bool {
        matches!(self, Quantity::Time | Quantity::Frequency | Quantity::Omega)
    }

    fn dimension(self) -> Dimension {
        match self {
            Quantity::Time => Dimension::TIME,
            Quantity::Frequency | Quantity::Omega => Dimension::FREQUENCY,
            Quantity::Relaxation | Quantity::Storage | Quantity::Loss => Dimension::PRESSURE,
        }
    }

    fn what(self) -> &'static str {
        match self {
            Quantity::Time => "a time (e.g. s)",
            Quantity::Frequency => "a frequency in Hz",
            Quantity::Omega => "an angular frequency (rad/s)",
            _ => "a modulus (e.g. MPa)",
        }
    }
}

/// One column: its header text, quantity and factor to SI.
struct Column<'a> {
    name: &'a str,
    quantity: Quantity,
    factor: f64,
    unit: Option<&'a str>,
}

type Located = (Option<usize>, String);

fn at(line: usize, message: String) -> Located {
    (Some(line), message)
}

fn cells(row: &str) -> Vec<&str> {
    row.split(',')
        .map(|c| {
            let c = c.trim();
            c.strip_prefix('"')
                .and_then(|c| c.strip_suffix('"'))
                .unwrap_or(c)
                .trim()
        })
        .collect()
}

fn is_number(cell: &str) -> bool {
    cell.parse::<f64>().is_ok()
}

fn parse(text: &str, kind: FitKind) -> Result<FitData, Located> {
    let mut rows = super::data_lines(text).peekable();
    let Some((header_line, header)) = rows.next() else {
        return Err((
            None,
            format!("no data: expected a header row {}", kind.columns()),
        ));
    };
    let mut columns = header_columns(header_line, header, kind)?;
    // pyvisco style: a second header row of units (no cell is a number).
    if let Some(&(units_line, units_row)) = rows.peek()
        && !cells(units_row).iter().any(|c| is_number(c))
    {
        rows.next();
        read_units(units_line, units_row, &mut columns)?;
    }
    let width = columns.len();
    let mut values: Vec<Vec<f64>> = vec![Vec::new(); width];
    let mut last_line = header_line;
    // The axis value of the previous row (line, SI value) and its text.
    let mut previous_axis: Option<(usize, f64)> = None;
    let mut previous_cell = "";
    for (line, row) in rows {
        last_line = line;
        let row_cells = cells(row);
        if row_cells.len() != width {
            let names: Vec<&str> = columns.iter().map(|c| c.name).collect();
            return Err(at(
                line,
                format!(
                    "expected {width} comma-separated columns ({}), found {}",
                    names.join(", "),
                    row_cells.len()
                ),
            ));
        }
        for (k, (cell, column)) in row_cells.iter().zip(&columns).enumerate() {
            let value = match cell.parse::<f64>() {
                Ok(v) if v.is_finite() => v * column.factor,
                Ok(v) => {
                    return Err(at(
                        line,
                        format!("{}: must be finite, got {}", column.name, show(v)),
                    ));
                }
                Err(_) => {
                    return Err(at(line, format!("{}: not a number: {cell:?}", column.name)));
                }
            };
            if value <= 0.0 {
                return Err(at(
                    line,
                    format!("{}: must be positive, got {cell}", column.name),
                ));
            }
            let value = if column.quantity == Quantity::Frequency {
                TAU * value
            } else {
                value
            };
            if column.quantity.is_axis() {
                if let Some(&(previous_line, previous)) = previous_axis.as_ref()
                    && value <= previous
                {
                    return Err(at(
                        line,
                        format!(
                            "{}: must increase strictly from row to row, got {cell} after {} (line {previous_line})",
                            column.name, previous_cell
                        ),
                    ));
                }
                previous_axis = Some((line, value));
                previous_cell = cell;
            }
            values[k].push(value);
        }
    }
    let points = values.first().map_or(0, Vec::len);
    if points < 3 {
        return Err(at(
            last_line,
            format!("too few points: {points} data rows, a fit needs at least 3"),
        ));
    }
    // The header check guarantees every column of `kind`.
    let index = |wanted: fn(Quantity) -> bool| columns.iter().position(|c| wanted(c.quantity));
    let (axis, first, second) = match kind {
        FitKind::Relaxation => (
            index(Quantity::is_axis),
            index(|q| q == Quantity::Relaxation),
            None,
        ),
        FitKind::Dma => (
            index(Quantity::is_axis),
            index(|q| q == Quantity::Storage),
            index(|q| q == Quantity::Loss),
        ),
    };
    let mut take = |k: Option<usize>| {
        k.map(|k| std::mem::take(&mut values[k]))
            .unwrap_or_default()
    };
    Ok(match kind {
        FitKind::Relaxation => FitData::Relaxation {
            times: take(axis),
            moduli: take(first),
        },
        FitKind::Dma => FitData::Dma {
            omegas: take(axis),
            storage: take(first),
            loss: take(second),
        },
    })
}

/// The columns named by the header row, checked against `kind`.
fn header_columns(line: usize, header: &str, kind: FitKind) -> Result<Vec<Column<'_>>, Located> {
    let names = cells(header);
    if names.iter().any(|c| is_number(c)) {
        return Err(at(
            line,
            format!(
                "expected a header row naming the columns ({}), found numbers",
                kind.columns()
            ),
        ));
    }
    let mut columns: Vec<Column> = Vec::with_capacity(names.len());
    for name in names {
        let Some(quantity) = Quantity::from_name(name) else {
            let hint = match name {
                "T" | "Set" | "RefT" | "log_aT" => {
                    " (temperatures and measurement sets belong to raw DMA data: fit-prony \
                     needs a master curve, shifted to one reference temperature)"
                }
                _ if name.to_lowercase().starts_with('g') => {
                    " (shear moduli are not fitted: sealsim's Prony series is the tensile \
                     modulus E; for rubber E ≈ 3G)"
                }
                _ => "",
            };
            return Err(at(
                line,
                format!(
                    "unknown column {name:?}{hint}; expected t|time, f|freq|frequency|omega, \
                     E_relax|E|E_rel, E_stor|storage|E', E_loss|loss|E''"
                ),
            ));
        };
        if let Some(other) = columns.iter().find(|c| c.quantity == quantity) {
            return Err(at(
                line,
                format!(
                    "columns {:?} and {name:?} give the same quantity",
                    other.name
                ),
            ));
        }
        if quantity.is_axis()
            && let Some(other) = columns.iter().find(|c| c.quantity.is_axis())
        {
            return Err(at(
                line,
                format!(
                    "columns {:?} and {name:?}: give only one time or frequency",
                    other.name
                ),
            ));
        }
        columns.push(Column {
            name,
            quantity,
            factor: 1.0,
            unit: None,
        });
    }
    let has = |q: Quantity| columns.iter().any(|c| c.quantity == q);
    let found = match (
        has(Quantity::Time),
        has(Quantity::Frequency) || has(Quantity::Omega),
        has(Quantity::Relaxation),
        has(Quantity::Storage) && has(Quantity::Loss),
    ) {
        (true, false, true, false) if columns.len() == 2 => Some(FitKind::Relaxation),
        (false, true, false, true) if columns.len() == 3 => Some(FitKind::Dma),
        _ => None,
    };
    let header_text = columns.iter().map(|c| c.name).collect::<Vec<_>>().join(",");
    match found {
        Some(found) if found == kind => Ok(columns),
        Some(found) => Err(at(
            line,
            format!(
                "--kind {} expects columns {}, but the header has {header_text}, which is {} data (use --kind {})",
                kind.as_str(),
                kind.columns(),
                match found {
                    FitKind::Relaxation => "relaxation",
                    FitKind::Dma => "DMA",
                },
                found.as_str()
            ),
        )),
        None => Err(at(
            line,
            format!(
                "--kind {} expects columns {}, but the header has {header_text}",
                kind.as_str(),
                kind.columns()
            ),
        )),
    }
}

/// Reads the units row of a pyvisco-style file into the columns' factors.
fn read_units<'a>(line: usize, row: &'a str, columns: &mut [Column<'a>]) -> Result<(), Located> {
    let units_cells = cells(row);
    if units_cells.len() != columns.len() {
        return Err(at(
            line,
            format!(
                "the units row has {} cells but the header has {} columns",
                units_cells.len(),
                columns.len()
            ),
        ));
    }
    for (unit, column) in units_cells.into_iter().zip(columns.iter_mut()) {
        if unit.is_empty() {
            return Err(at(
                line,
                format!(
                    "{}: missing unit, expected {}",
                    column.name,
                    column.quantity.what()
                ),
            ));
        }
        // "rad/s" is an angular frequency in 1/s; only the omega column may carry it.
        let radians = unit.strip_prefix("rad/");
        let expression = match (radians, column.quantity) {
            (Some(rest), Quantity::Omega) => format!("1/{rest}"),
            (Some(_), _) => {
                return Err(at(
                    line,
                    format!(
                        "{}: unit {unit:?} is an angular frequency; name the column omega, or give f in Hz",
                        column.name
                    ),
                ));
            }
            (None, _) => unit.to_string(),
        };
        let (factor, dimension) = units::parse_unit(&expression)
            .map_err(|e| at(line, format!("{}: {e}", column.name)))?;
        if dimension != column.quantity.dimension() {
            return Err(at(
                line,
                format!(
                    "{}: unit {unit:?} is {dimension}, expected {}",
                    column.name,
                    column.quantity.what()
                ),
            ));
        }
        column.factor = factor;
        column.unit = Some(unit);
    }
    let unit_of = |q: Quantity| {
        columns
            .iter()
            .find(|c| c.quantity == q)
            .and_then(|c| c.unit)
    };
    if let (Some(storage), Some(loss)) = (unit_of(Quantity::Storage), unit_of(Quantity::Loss))
        && storage != loss
    {
        return Err(at(
            line,
            format!(
                "mixed units: the storage modulus is in {storage:?} but the loss modulus in {loss:?}; \
                 give both in the same unit (a mismatch is almost always an export mistake)"
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_ok(text: &str, kind: FitKind) -> FitData {
        parse_fit_data(text, Path::new("d.csv"), kind).unwrap()
    }

    fn error(text: &str, kind: FitKind) -> String {
        parse_fit_data(text, Path::new("d.csv"), kind)
            .expect_err("the file should be rejected")
            .to_string()
    }

    #[test]
    fn pyvisco_files_convert_units() {
        let d = parse_ok(
            "t,E_relax\ns, MPa\n0.1,10\n1,5\n10,2\n",
            FitKind::Relaxation,
        );
        assert_eq!(
            d,
            FitData::Relaxation {
                times: vec![0.1, 1.0, 10.0],
                moduli: vec![1e7, 5e6, 2e6]
            }
        );
        let d = parse_ok(
            "# master curve\nf, E_stor, E_loss\nHz, MPa, MPa\n\n1,10,1\n2,11,2\n4,12,3\n",
            FitKind::Dma,
        );
        let FitData::Dma {
            omegas,
            storage,
            loss,
        } = d
        else {
            panic!()
        };
        assert_eq!(omegas, [TAU, 2.0 * TAU, 4.0 * TAU]);
        assert_eq!(storage, [1e7, 1.1e7, 1.2e7]);
        assert_eq!(loss, [1e6, 2e6, 3e6]);
        // omega in rad/s, columns in another order, other accepted names
        let d = parse_ok(
            "Loss,OMEGA,E'\nkPa,rad/s,kPa\n1,1,10\n2,2,11\n3,3,12\n",
            FitKind::Dma,
        );
        let FitData::Dma {
            omegas,
            storage,
            loss,
        } = d
        else {
            panic!()
        };
        assert_eq!((omegas[2], storage[0], loss[1]), (3.0, 1e4, 2e3));
    }

    #[test]
    fn plain_files_are_si() {
        let d = parse_ok("time,E\n1,3e6\n2,2e6\n3,1e6\n", FitKind::Relaxation);
        assert_eq!(d.points(), 3);
        let d = parse_ok(
            "omega,storage,loss\n1,3e6,1e5\n2,3e6,1e5\n3,3e6,1e5\n",
            FitKind::Dma,
        );
        let FitData::Dma { omegas, .. } = d else {
            panic!()
        };
        assert_eq!(omegas, [1.0, 2.0, 3.0]);
    }

    #[test]
    fn errors_name_file_and_line() {
        let r = FitKind::Relaxation;
        let e = error("t,E\n1,3e6\n# c\n2,abc\n3,1\n", r);
        assert!(e.starts_with("d.csv:4: E: not a number"), "{e}");
        let e = error("t,E\n1,3e6\n2,2e6\n2,1e6\n", r);
        assert!(e.starts_with("d.csv:4: t: must increase strictly"), "{e}");
        let e = error("t,E\n1,3e6\n2,-2e6\n3,1e6\n", r);
        assert!(e.starts_with("d.csv:3: E: must be positive"), "{e}");
        let e = error("t,E\n1,3e6\n2,2e6,5\n3,1e6\n", r);
        assert!(
            e.starts_with("d.csv:3: expected 2 comma-separated columns"),
            "{e}"
        );
        let e = error("t,E\n1,3e6\n2,2e6\n", r);
        assert!(e.starts_with("d.csv:3: too few points: 2 data rows"), "{e}");
        let e = error("t,E\ns,m\n1,3e6\n2,2e6\n3,1e6\n", r);
        assert!(e.starts_with("d.csv:2: E: unit \"m\" is"), "{e}");
        let e = error("t,E\nMPa,MPa\n1,3e6\n2,2e6\n3,1e6\n", r);
        assert!(e.starts_with("d.csv:2: t: unit \"MPa\""), "{e}");
        let e = error("t,E\ns,furlong\n1,3e6\n2,2e6\n3,1e6\n", r);
        assert!(e.starts_with("d.csv:2: E: unknown unit"), "{e}");
        let e = error("1,3e6\n2,2e6\n3,1e6\n", r);
        assert!(e.starts_with("d.csv:1: expected a header row"), "{e}");
        let e = error("t,G_relax\ns,MPa\n", r);
        assert!(e.contains("shear moduli"), "{e}");
        let e = error("f,E_stor,E_loss,T\nHz,MPa,MPa,C\n", FitKind::Dma);
        assert!(e.contains("unknown column \"T\" (temperatures"), "{e}");
        let e = error("", r);
        assert!(e.starts_with("d.csv: no data"), "{e}");
    }

    #[test]
    fn dma_checks() {
        let d = FitKind::Dma;
        let e = error("f,E_stor,E_loss\nHz,MPa,Pa\n1,1,1\n2,1,1\n3,1,1\n", d);
        assert!(e.starts_with("d.csv:2: mixed units"), "{e}");
        let e = error("f,E_stor,E_loss\nrad/s,MPa,MPa\n1,1,1\n2,1,1\n3,1,1\n", d);
        assert!(e.contains("name the column omega"), "{e}");
        let e = error("t,E_relax\ns,MPa\n1,1\n2,1\n3,1\n", d);
        assert!(
            e.starts_with("d.csv:1: --kind dma expects columns f,E_stor,E_loss")
                && e.contains("relaxation data (use --kind relaxation)"),
            "{e}"
        );
        let e = error(
            "f,E_stor,E_loss\n1,1,1\n2,1,1\n3,1,1\n",
            FitKind::Relaxation,
        );
        assert!(e.contains("DMA data (use --kind dma)"), "{e}");
        let e = error("f,E_stor\n1,1\n2,1\n3,1\n", d);
        assert!(e.starts_with("d.csv:1: --kind dma expects"), "{e}");
        let e = error("f,omega,E_stor,E_loss\n", d);
        assert!(e.contains("only one time or frequency"), "{e}");
        let e = error("f,E_stor,storage\n", d);
        assert!(e.contains("the same quantity"), "{e}");
    }
}
