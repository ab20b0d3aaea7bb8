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
use std::path::Path;

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
            FitKind::Relaxation => "t,E_relax (or t,force or t,retained; optionally temperature)",
            FitKind::Dma => "f,E_stor,E_loss (or omega,E_stor,E_loss)",
        }
    }
}

/// What the relaxation column of a file measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measured {
    /// The relaxation modulus E(t) \[Pa\] (column `E_relax` | `E` | `E_rel`).
    Modulus,
    /// The counterforce of a compression-stress-relaxation test (ISO 3384) \[N\] (column
    /// `force` | `F`).
    Force,
    /// The force retained, F(t)/F0, as a fraction (column `retained` | `retention` |
    /// `F/F0`; unit `1` or `%`).
    Retained,
}

impl Measured {
    /// The column's quantity in words.
    pub fn describe(self) -> &'static str {
        match self {
            Measured::Modulus => "relaxation modulus",
            Measured::Force => "compression-stress-relaxation force",
            Measured::Retained => "force retained",
        }
    }
}

/// The points of one temperature (or of the whole file when it has no temperature column):
/// times (s) strictly increasing, values in SI (Pa, N or a fraction).
#[derive(Debug, Clone, PartialEq)]
pub struct Isotherm {
    /// The test temperature \[K\], when the file has a `temperature` column.
    pub temperature: Option<f64>,
    pub times: Vec<f64>,
    pub values: Vec<f64>,
    /// The file line of the first point (for messages).
    pub first_line: usize,
}

/// The data of a fit file in SI units, rows in file order.
#[derive(Debug, Clone, PartialEq)]
pub enum FitData {
    /// Relaxation tests: one isotherm per temperature, in order of first appearance.
    Relaxation {
        measured: Measured,
        isotherms: Vec<Isotherm>,
        /// Line and 1-based column of the temperature column's header, when there is one.
        temperature_column: Option<(usize, usize)>,
    },
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
            FitData::Relaxation { isotherms, .. } => isotherms.iter().map(|i| i.times.len()).sum(),
            FitData::Dma { omegas, .. } => omegas.len(),
        }
    }
}

/// The largest rise a force or retention series may show above its running minimum, as a
/// fraction of its first value, before the file is refused as not a relaxation test. Stress
/// relaxation at a fixed deformation never raises the counterforce; rig noise is a fraction
/// of a per cent (ISO 3384 asks for a force-measuring accuracy of about 1 % — recalled), so
/// a rise of 5 % of the initial force means a mix-up (columns swapped, a re-loaded sample, a
/// temperature step within one series) rather than scatter.
pub const MONOTONIC_TOLERANCE: f64 = 0.05;

/// The SI unit of a data column named `name` (as the header row names it: `t`, `force`,
/// `E_stor`, `T`, …) as the units row takes it (`s`, `N`, `Pa`, `K`, `Hz`, `rad/s`, `1`), or
/// `None` for a name the fit does not know. Used by the Python package to write columns in SI.
pub fn si_unit(name: &str) -> Option<&'static str> {
    Quantity::from_name(name).map(|q| match q {
        Quantity::Time => "s",
        Quantity::Frequency => "Hz",
        Quantity::Omega => "rad/s",
        Quantity::Force => "N",
        Quantity::Retained => "1",
        Quantity::Temperature => "K",
        Quantity::Relaxation | Quantity::Storage | Quantity::Loss => "Pa",
    })
}

/// A fit file that cannot be used: the one data-file error, [`DataFileError`](crate::scenario::DataFileError)
/// (`path:line: message`), under the name this module's callers know.
pub type FitDataError = super::text::DataFileError;

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
    Force,
    Retained,
    Storage,
    Loss,
    Temperature,
}

impl Quantity {
    /// The quantity of a header cell (case-insensitive, except that a capital `T` is the
    /// temperature, as in pyvisco's raw files, and a lower-case `t` the time).
    fn from_name(name: &str) -> Option<Self> {
        if name == "T" {
            return Some(Quantity::Temperature);
        }
        Some(match name.to_lowercase().as_str() {
            "t" | "time" => Quantity::Time,
            "f" | "freq" | "frequency" => Quantity::Frequency,
            "omega" | "ω" => Quantity::Omega,
            "e_relax" | "e" | "e_rel" => Quantity::Relaxation,
            "force" | "f_n" => Quantity::Force,
            "retained" | "retention" | "f/f0" | "f_f0" => Quantity::Retained,
            "e_stor" | "storage" | "e'" | "e′" => Quantity::Storage,
            "e_loss" | "loss" | "e''" | "e″" => Quantity::Loss,
            "temperature" | "temp" => Quantity::Temperature,
            _ => return None,
        })
    }

    fn is_axis(self) -> bool {
        matches!(self, Quantity::Time | Quantity::Frequency | Quantity::Omega)
    }

    fn is_relaxation(self) -> bool {
        matches!(
            self,
            Quantity::Relaxation | Quantity::Force | Quantity::Retained
        )
    }

    fn dimension(self) -> Dimension {
        match self {
            Quantity::Time => Dimension::TIME,
            Quantity::Frequency | Quantity::Omega => Dimension::FREQUENCY,
            Quantity::Force => Dimension::FORCE,
            Quantity::Retained => Dimension::DIMENSIONLESS,
            Quantity::Temperature => Dimension::TEMPERATURE,
            Quantity::Relaxation | Quantity::Storage | Quantity::Loss => Dimension::PRESSURE,
        }
    }

    fn what(self) -> &'static str {
        match self {
            Quantity::Time => "a time (e.g. s)",
            Quantity::Frequency => "a frequency in Hz",
            Quantity::Omega => "an angular frequency (rad/s)",
            Quantity::Force => "a force (e.g. N)",
            Quantity::Retained => "1 (a fraction) or %",
            Quantity::Temperature => "an absolute temperature unit (C, K or F)",
            _ => "a modulus (e.g. MPa)",
        }
    }
}

/// One column: its header text, quantity and factor to SI (for the temperature, the unit
/// string, converted by [`units::absolute_temperature`]).
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

/// A series being read: its isotherm, the last axis value with its line and text, and the
/// running minimum of the force or retention (for the monotonicity check).
struct Series<'a> {
    isotherm: Isotherm,
    last: Option<(usize, f64, &'a str)>,
    minimum: Option<(usize, f64)>,
}

fn parse(text: &str, kind: FitKind) -> Result<FitData, Located> {
    let mut rows = super::text::data_lines(text).peekable();
    let Some((header_line, header)) = rows.next() else {
        return Err((
            None,
            format!("no data: expected a header row {}", kind.columns()),
        ));
    };
    let mut columns = header_columns(header_line, header, kind)?;
    units_row(rows.next(), header_line, &mut columns)?;
    let width = columns.len();
    let temperature_index = columns
        .iter()
        .position(|c| c.quantity == Quantity::Temperature);
    let mut series: Vec<Series> = Vec::new();
    let mut dma: Vec<Vec<f64>> = vec![Vec::new(); width];
    let mut last_line = header_line;
    for (line, row) in rows {
        last_line = line;
        let row_cells = cells(row);
        let values = row_values(line, &row_cells, &columns)?;
        let temperature = temperature_index.map(|k| values[k]);
        let current = series_of(&mut series, temperature, line);
        let axis = current.check_row(line, &row_cells, &values, &columns)?;
        match kind {
            FitKind::Relaxation => {
                let v = columns
                    .iter()
                    .position(|c| c.quantity.is_relaxation())
                    .map_or(f64::NAN, |k| values[k]);
                current.isotherm.times.push(axis);
                current.isotherm.values.push(v);
            }
            FitKind::Dma => {
                current.isotherm.times.push(axis);
                for (column, value) in dma.iter_mut().zip(values) {
                    column.push(value);
                }
            }
        }
    }
    enough_points(&series, last_line)?;
    Ok(fit_data(
        kind,
        &columns,
        series,
        dma,
        temperature_index,
        header_line,
    ))
}

/// The row of units after the header (pyvisco style), required: a bare 24 could be seconds or
/// hours. Its first cell is never a number (a retention's unit may be `1`, so the other cells
/// are not a test).
fn units_row<'a>(
    row: Option<(usize, &'a str)>,
    header_line: usize,
    columns: &mut [Column<'a>],
) -> Result<(), Located> {
    match row {
        Some((units_line, units_row))
            if cells(units_row).first().is_some_and(|c| !is_number(c)) =>
        {
            read_units(units_line, units_row, columns)
        }
        Some((line, _)) => {
            let example: Vec<&str> = columns
                .iter()
                .map(|c| match c.quantity {
                    Quantity::Time => "h",
                    Quantity::Frequency => "Hz",
                    Quantity::Omega => "rad/s",
                    Quantity::Force => "N",
                    Quantity::Retained => "%",
                    Quantity::Temperature => "C",
                    _ => "MPa",
                })
                .collect();
            Err(at(
                line,
                format!(
                    "no units row: add one after the header, e.g. `{}` — without it a time of \
                     24 could be seconds or hours",
                    example.join(",")
                ),
            ))
        }
        None => Err(at(
            header_line,
            "no units row and no data: expected a units row after the header, then data \
             rows"
                .into(),
        )),
    }
}

/// A data row's values in SI, one per column.
fn row_values(line: usize, row_cells: &[&str], columns: &[Column]) -> Result<Vec<f64>, Located> {
    let width = columns.len();
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
    let mut values = Vec::with_capacity(width);
    for (cell, column) in row_cells.iter().zip(columns) {
        values.push(cell_value(line, cell, column)?);
    }
    Ok(values)
}

/// The series of `temperature` (a new one, first on `line`, if none yet).
fn series_of<'s, 'a>(
    series: &'s mut Vec<Series<'a>>,
    temperature: Option<f64>,
    line: usize,
) -> &'s mut Series<'a> {
    let k = match series
        .iter()
        .position(|s| s.isotherm.temperature == temperature)
    {
        Some(k) => k,
        None => {
            series.push(Series {
                isotherm: Isotherm {
                    temperature,
                    times: Vec::new(),
                    values: Vec::new(),
                    first_line: line,
                },
                last: None,
                minimum: None,
            });
            series.len() - 1
        }
    };
    &mut series[k]
}

impl<'a> Series<'a> {
    /// Checks a data row against the series' rows before it (the axis increases strictly, the
    /// force or retention does not rise beyond scatter); the row's axis value.
    fn check_row(
        &mut self,
        line: usize,
        row_cells: &[&'a str],
        values: &[f64],
        columns: &[Column],
    ) -> Result<f64, Located> {
        let mut axis = f64::NAN;
        for (j, column) in columns.iter().enumerate() {
            let value = values[j];
            if column.quantity.is_axis() {
                self.check_axis(line, row_cells[j], value, column)?;
                axis = value;
            }
            if matches!(column.quantity, Quantity::Force | Quantity::Retained) {
                self.check_relaxes(line, row_cells[j], value, column)?;
            }
        }
        Ok(axis)
    }

    /// The axis `value` (written `cell`) increases strictly over the series.
    fn check_axis(
        &mut self,
        line: usize,
        cell: &'a str,
        value: f64,
        column: &Column,
    ) -> Result<(), Located> {
        if let Some((previous_line, previous, previous_cell)) = self.last
            && value <= previous
        {
            let within = if self.isotherm.temperature.is_some() {
                " within one temperature"
            } else {
                " from row to row"
            };
            return Err(at(
                line,
                format!(
                    "{}: must increase strictly{within}, got {} after {previous_cell} (line {previous_line})",
                    column.name, cell
                ),
            ));
        }
        self.last = Some((line, value, cell));
        Ok(())
    }

    /// A force or retention `value` (written `cell`) does not rise above the running minimum by
    /// more than the scatter allowed.
    fn check_relaxes(
        &mut self,
        line: usize,
        cell: &str,
        value: f64,
        column: &Column,
    ) -> Result<(), Located> {
        let first = self.isotherm.values.first().copied().unwrap_or(value);
        match self.minimum {
            Some((min_line, min)) if value > min + MONOTONIC_TOLERANCE * first => {
                return Err(at(
                    line,
                    format!(
                        "{}: the force rises from {} (line {min_line}) to {}, by {:.1} % of \
                         its first value: stress relaxation at a fixed deformation never \
                         raises the force (check the column order, a re-loaded test piece \
                         or a temperature step; rises up to {:.0} % are taken as scatter)",
                        column.name,
                        show(min / column.factor),
                        cell,
                        100.0 * (value - min) / first,
                        100.0 * MONOTONIC_TOLERANCE
                    ),
                ));
            }
            Some((_, min)) if value >= min => {}
            _ => self.minimum = Some((line, value)),
        }
        Ok(())
    }
}

/// At least 3 points in every series (the error at the file's `last_line`).
fn enough_points(series: &[Series], last_line: usize) -> Result<(), Located> {
    if series.is_empty() {
        return Err(at(
            last_line,
            "too few points: 0 data rows, a fit needs at least 3".to_string(),
        ));
    }
    for s in series {
        let points = s.isotherm.times.len();
        if points < 3 {
            let which = match s.isotherm.temperature {
                Some(t) if series.len() > 1 => {
                    format!(
                        " at {} (first on line {})",
                        show_kelvin(t),
                        s.isotherm.first_line
                    )
                }
                _ => String::new(),
            };
            return Err(at(
                last_line,
                format!("too few points: {points} data rows{which}, a fit needs at least 3"),
            ));
        }
    }
    Ok(())
}

/// The data read: a relaxation's isotherms, or a DMA's columns.
fn fit_data(
    kind: FitKind,
    columns: &[Column],
    series: Vec<Series>,
    mut dma: Vec<Vec<f64>>,
    temperature_index: Option<usize>,
    header_line: usize,
) -> FitData {
    let position = |wanted: fn(Quantity) -> bool| columns.iter().position(|c| wanted(c.quantity));
    match kind {
        FitKind::Relaxation => {
            let measured = match position(Quantity::is_relaxation).map(|k| columns[k].quantity) {
                Some(Quantity::Force) => Measured::Force,
                Some(Quantity::Retained) => Measured::Retained,
                _ => Measured::Modulus,
            };
            FitData::Relaxation {
                measured,
                isotherms: series.into_iter().map(|s| s.isotherm).collect(),
                temperature_column: temperature_index.map(|k| (header_line, k + 1)),
            }
        }
        FitKind::Dma => {
            let mut take = |wanted: fn(Quantity) -> bool| {
                position(wanted)
                    .map(|k| std::mem::take(&mut dma[k]))
                    .unwrap_or_default()
            };
            FitData::Dma {
                omegas: take(Quantity::is_axis),
                storage: take(|q| q == Quantity::Storage),
                loss: take(|q| q == Quantity::Loss),
            }
        }
    }
}

/// A temperature for messages: `296.15 K (23 °C)`.
pub fn show_kelvin(t: f64) -> String {
    format!("{} K ({:.4} °C)", show(t), t - 273.15).replace(".0000 °C", " °C")
}

/// The range a cell of `quantity` must lie in (SI), its unit and the likely slip beyond it.
/// Bounds (assumed, chosen wide): a rubber's modulus lies between its rubbery plateau
/// (~1e5 Pa) and its glass (~3e9 Pa), so 1 Pa–1e12 Pa holds any rubber with decades to spare
/// (the scenario's modulus key takes 1e3–1e12 Pa); times and frequencies within 1e-30–1e30 (a
/// shifted master curve spans some 30 decades); forces 1e-9–1e9 N. Beyond them the fitter's
/// least squares overflowed (a modulus of 1e308 Pa or 1e-320 MPa: exit 1, "not finite").
fn plausible_range(quantity: Quantity) -> Option<(f64, f64, &'static str, &'static str)> {
    match quantity {
        Quantity::Relaxation | Quantity::Storage | Quantity::Loss => Some((
            1.0,
            1e12,
            "Pa",
            ": not a rubber's modulus; check the units row (MPa for Pa, or kPa?)",
        )),
        Quantity::Time => Some((1e-30, 1e30, "s", ": check the units row")),
        Quantity::Frequency => Some((1e-30, 1e30, "Hz", ": check the units row")),
        Quantity::Omega => Some((1e-30, 1e30, "rad/s", ": check the units row")),
        Quantity::Force => Some((1e-9, 1e9, "N", ": check the units row")),
        Quantity::Retained | Quantity::Temperature => None,
    }
}

/// One cell in SI: finite, positive (temperatures: above absolute zero), within
/// [`plausible_range`]; frequencies as ω.
fn cell_value(line: usize, cell: &str, column: &Column) -> Result<f64, Located> {
    let number = match cell.parse::<f64>() {
        Ok(v) if v.is_finite() => v,
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
    if column.quantity == Quantity::Temperature {
        return units::absolute_temperature(number, column.unit.unwrap_or("K"))
            .map_err(|e| at(line, format!("{}: {e}", column.name)));
    }
    let value = number * column.factor;
    if value <= 0.0 {
        return Err(at(
            line,
            format!("{}: must be positive, got {cell}", column.name),
        ));
    }
    if let Some((lo, hi, unit, hint)) = plausible_range(column.quantity)
        && !(lo..=hi).contains(&value)
    {
        return Err(at(
            line,
            format!(
                "{}: {cell} is {} {unit}, outside {}–{} {unit}{hint}",
                column.name,
                show(value),
                show(lo),
                show(hi)
            ),
        ));
    }
    Ok(if column.quantity == Quantity::Frequency {
        TAU * value
    } else {
        value
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
                "Set" | "RefT" | "log_aT" => {
                    " (measurement sets and shift factors belong to pyvisco's raw files: give \
                     t, E_relax and temperature, and fit-prony shifts the data itself)"
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
                     E_relax|E|E_rel, force|F_N, retained|retention|F/F0, E_stor|storage|E', \
                     E_loss|loss|E'', temperature|T"
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
    let relaxation_columns = columns
        .iter()
        .filter(|c| c.quantity.is_relaxation())
        .count();
    if relaxation_columns > 1 {
        return Err(at(
            line,
            "give one of E_relax, force and retained: the fit uses one relaxation column".into(),
        ));
    }
    let temperature = usize::from(has(Quantity::Temperature));
    let found = match (
        has(Quantity::Time),
        has(Quantity::Frequency) || has(Quantity::Omega),
        relaxation_columns == 1,
        has(Quantity::Storage) && has(Quantity::Loss),
    ) {
        (true, false, true, false) if columns.len() == 2 + temperature => Some(FitKind::Relaxation),
        (false, true, false, true) if columns.len() == 3 + temperature => Some(FitKind::Dma),
        _ => None,
    };
    if found == Some(FitKind::Dma) && temperature == 1 {
        return Err(at(
            line,
            "a temperature column in DMA data: fit-prony shifts relaxation data (t, E_relax, \
             temperature); for DMA sweeps at several temperatures give the master curve, \
             shifted to one reference temperature"
                .into(),
        ));
    }
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
        if column.quantity == Quantity::Temperature {
            units::absolute_temperature(300.0, unit).map_err(|e| {
                at(
                    line,
                    format!("{}: unit {unit:?}: {e} (expected C, K or F)", column.name),
                )
            })?;
            column.unit = Some(unit);
            continue;
        }
        if column.quantity == Quantity::Retained && unit == "1" {
            column.unit = Some(unit);
            continue;
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
                measured: Measured::Modulus,
                isotherms: vec![Isotherm {
                    temperature: None,
                    times: vec![0.1, 1.0, 10.0],
                    values: vec![1e7, 5e6, 2e6],
                    first_line: 3,
                }],
                temperature_column: None,
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
    fn a_file_without_its_units_row_is_refused() {
        // `24` could be seconds or hours: the line and a units row the parser takes
        let e = error("time,E\n1,3e6\n2,2e6\n3,1e6\n", FitKind::Relaxation);
        assert!(e.starts_with("d.csv:2: no units row"), "{e}");
        assert!(e.contains("`h,MPa`"), "{e}");
        let d = parse_ok("time,E\nh,MPa\n1,3\n2,2\n3,1\n", FitKind::Relaxation);
        assert_eq!(d.points(), 3);
        let e = error(
            "omega,storage,loss\n1,3e6,1e5\n2,3e6,1e5\n3,3e6,1e5\n",
            FitKind::Dma,
        );
        assert!(e.contains("`rad/s,MPa,MPa`"), "{e}");
        let d = parse_ok(
            "omega,storage,loss\nrad/s,Pa,Pa\n1,3e6,1e5\n2,3e6,1e5\n3,3e6,1e5\n",
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
        let e = error("t,E\ns,Pa\n1,3e6\n# c\n2,abc\n3,1\n", r);
        assert!(e.starts_with("d.csv:5: E: not a number"), "{e}");
        let e = error("t,E\ns,Pa\n1,3e6\n2,2e6\n2,1e6\n", r);
        assert!(e.starts_with("d.csv:5: t: must increase strictly"), "{e}");
        let e = error("t,E\ns,Pa\n1,3e6\n2,-2e6\n3,1e6\n", r);
        assert!(e.starts_with("d.csv:4: E: must be positive"), "{e}");
        let e = error("t,E\ns,Pa\n1,3e6\n2,2e6,5\n3,1e6\n", r);
        assert!(
            e.starts_with("d.csv:4: expected 2 comma-separated columns"),
            "{e}"
        );
        let e = error("t,E\ns,Pa\n1,3e6\n2,2e6\n", r);
        assert!(e.starts_with("d.csv:4: too few points: 2 data rows"), "{e}");
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
        assert!(
            e.starts_with("d.csv:1: a temperature column in DMA data"),
            "{e}"
        );
        let e = error("t,E,Set\n", r);
        assert!(
            e.contains("unknown column \"Set\" (measurement sets"),
            "{e}"
        );
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
            "f,E_stor,E_loss\nHz,MPa,MPa\n1,1,1\n2,1,1\n3,1,1\n",
            FitKind::Relaxation,
        );
        assert!(e.contains("DMA data (use --kind dma)"), "{e}");
        let e = error("f,E_stor\nHz,MPa\n1,1\n2,1\n3,1\n", d);
        assert!(e.starts_with("d.csv:1: --kind dma expects"), "{e}");
        let e = error("f,omega,E_stor,E_loss\n", d);
        assert!(e.contains("only one time or frequency"), "{e}");
        let e = error("f,E_stor,storage\n", d);
        assert!(e.contains("the same quantity"), "{e}");
    }

    #[test]
    fn forces_retention_and_temperatures() {
        let r = FitKind::Relaxation;
        // several temperatures, in blocks or interleaved; times increase within each
        let d = parse_ok(
            "t,force,temperature\nmin,N,C\n1,100,23\n1,90,70\n2,99,23\n3,98,23\n2,85,70\n4,80,70\n",
            r,
        );
        let FitData::Relaxation {
            measured,
            isotherms,
            temperature_column,
        } = d
        else {
            panic!()
        };
        assert_eq!(measured, Measured::Force);
        assert_eq!(temperature_column, Some((1, 3)));
        assert_eq!(isotherms.len(), 2);
        assert_eq!(isotherms[0].temperature, Some(296.15));
        assert_eq!(isotherms[0].times, [60.0, 120.0, 180.0]);
        assert_eq!(isotherms[1].values, [90.0, 85.0, 80.0]);
        assert_eq!(isotherms[1].first_line, 4);
        // retention in per cent; scatter below 5 % of the first value is accepted
        let d = parse_ok("t,retained\nh,%\n1,100\n2,96\n3,97\n4,95\n", r);
        let FitData::Relaxation {
            isotherms,
            measured,
            ..
        } = d
        else {
            panic!()
        };
        assert_eq!(measured, Measured::Retained);
        let expected = [1.0, 0.96, 0.97, 0.95];
        assert!(
            isotherms[0]
                .values
                .iter()
                .zip(expected)
                .all(|(v, e)| (v - e).abs() < 1e-15)
        );
        assert!(parse_ok("t,F/F0\nh,1\n1,1\n2,0.9\n3,0.8\n", r).points() == 3);
    }

    /// A modulus of 1e200 MPa or 1e-320 MPa (the review's D10) once reached the fitter, whose
    /// least squares overflowed: exit 1 "not finite". Now refused at its line with the range.
    #[test]
    fn moduli_beyond_a_rubbers_are_refused_at_their_line() {
        for cell in ["1e200", "1e-320"] {
            let e = error(
                &format!("t,E_relax\ns,MPa\n1,10\n10,9\n100,8\n1000,7.5\n10000,{cell}\n"),
                FitKind::Relaxation,
            );
            assert!(
                e.starts_with("d.csv:7: E_relax:") && e.contains("outside 1–1e12 Pa"),
                "{e}"
            );
        }
    }

    #[test]
    fn relaxation_checks() {
        let r = FitKind::Relaxation;
        let e = error("t,retained\nh,1\n1,1\n2,0.8\n3,0.9\n", r);
        assert!(
            e.starts_with("d.csv:5: retained: the force rises from 0.8 (line 4) to 0.9, by 10.0 %"),
            "{e}"
        );
        let e = error("t,force,T\ns,N,C\n1,10,23\n2,9,23\n2,8,23\n", r);
        assert!(
            e.starts_with("d.csv:5: t: must increase strictly within one temperature"),
            "{e}"
        );
        let e = error(
            "t,force,T\ns,N,C\n1,10,23\n2,9,23\n3,8,23\n1,9,70\n2,8,70\n",
            r,
        );
        assert!(
            e.starts_with(
                "d.csv:7: too few points: 2 data rows at 343.15 K (70 °C) (first on line 6)"
            ),
            "{e}"
        );
        let e = error("t,force,T\ns,N,Pa\n", r);
        assert!(e.starts_with("d.csv:2: T: unit \"Pa\""), "{e}");
        let e = error("t,force,T\ns,N,C\n1,10,-300\n", r);
        assert!(e.starts_with("d.csv:3: T:"), "{e}");
        let e = error("t,force\ns,MPa\n1,1\n2,1\n3,1\n", r);
        assert!(e.starts_with("d.csv:2: force: unit \"MPa\" is"), "{e}");
        let e = error("t,force,retained\n", r);
        assert!(e.contains("one relaxation column"), "{e}");
    }
}
