//! Environment histories: a CSV file of `time, temperature` rows, optionally with a `pressure`
//! column, or `time, pressure` alone (`environment.history`).
//!
//! Format:
//! * lines starting with `#` and blank lines are ignored (a leading byte-order mark too);
//! * the first row is the header: `time,temperature`, `time,temperature,pressure` or
//!   `time,pressure` (names case-insensitive);
//! * a units row must follow, one unit a column, e.g. `day,C`, `h,K,bar` or `min,psi`: the time
//!   unit is any time unit of [`crate::units`] (`s`, `min`, `h`, `day`, `week`, `year`, …), the
//!   temperature unit an absolute scale (`K`, `C`, `°C`, `degC`, `F`, …), the pressure unit a
//!   unit of pressure (`Pa`, `kPa`, `bar`, `MPa`, `psi`, …); a file without one, or with a column
//!   left without its unit, is refused (its line named), since a bare number is ambiguous;
//! * or, instead of the header and units rows, column names that carry their units,
//!   `time_<unit>`, `temperature_<unit>` and/or `pressure_<unit>` (`time_s,temperature_F`), other
//!   columns ignored: so the history CSV of `sealsim run -o` (in any `--units`) reads back as an
//!   environment history, to the same SI values;
//! * then at least one data row of finite numbers; times strictly increasing (t = 0 is the
//!   installation); temperatures above 0 K; pressures finite (what they may be — ΔP ≥ 0 for a
//!   liquid, an absolute inlet pressure at or above the outlet's for a gas — is checked against
//!   the fluid by the scenario, at the row's line).
//!
//! Between rows the values are linear in time; before the first and after the last row they
//! are constant ([`crate::material::TemperatureHistory::table`],
//! [`crate::pressure::PressureHistory::table`]). Parsed by hand (like the PSD files) so that
//! every error names the real line.

use crate::units::{self, Dimension, show};

/// Most data rows of an `environment.history` file: each row is a knot of T(t) (or of the
/// pressure), so an internal step of the run, whose cost is linear in them (10⁵ rows over 30
/// years, a swing of up to 7 K between rows: 1.5 s; 10⁶: 17 s — `sealsim run`, the run and its
/// band, on the 2-core VM). The bound is the cycles' step budget (`MAX_CYCLE_STEPS` of
/// `scenario::life`, which re-exports this one): 45 years of hourly rows. Beyond it the file is
/// refused at its first row over the limit (exit 2), rather than left to run for minutes.
pub const MAX_HISTORY_ROWS: usize = 400_000;

/// A malformed history file: what is wrong and, when it is on one row, the 1-based line.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct HistoryError {
    pub line: Option<usize>,
    pub message: String,
}

fn at(line: usize, message: impl Into<String>) -> HistoryError {
    HistoryError {
        line: Some(line),
        message: message.into(),
    }
}

/// One pressure of a history file: time \[s\], pressure \[Pa\] and the 1-based line it is on.
pub(super) type PressureRow = (f64, f64, usize);

/// The columns of a history file, in SI: `(t [s], T [K])` and `(t [s], P [Pa], line)`.
#[derive(Debug, Clone, PartialEq, Default)]
pub(super) struct History {
    pub temperature: Option<Vec<(f64, f64)>>,
    pub pressure: Option<Vec<PressureRow>>,
}

/// Which quantity a column after `time` holds.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Column {
    Temperature,
    Pressure,
}

impl Column {
    fn name(self) -> &'static str {
        match self {
            Column::Temperature => "temperature",
            Column::Pressure => "pressure",
        }
    }
}

/// The accepted headers: their columns after `time`.
const HEADERS: [&[Column]; 3] = [
    &[Column::Temperature],
    &[Column::Temperature, Column::Pressure],
    &[Column::Pressure],
];

/// The unit of one column: seconds per time unit, the temperature unit, or pascals per
/// pressure unit.
enum Unit {
    Temperature(String),
    Pressure(f64),
}

/// The `(time [s], temperature [K])` points of a temperature history file's text (a file that
/// must carry its temperature).
#[cfg(test)]
pub(super) fn parse(text: &str) -> Result<Vec<(f64, f64)>, HistoryError> {
    let history = parse_history(text)?;
    history.temperature.ok_or(HistoryError {
        line: None,
        message: "no temperature column".into(),
    })
}

/// The columns of a history file's text.
pub(super) fn parse_history(text: &str) -> Result<History, HistoryError> {
    let mut rows = super::text::data_lines(text).peekable();
    let Some((line, header)) = rows.next() else {
        return Err(HistoryError {
            line: None,
            message: "empty file: expected the header row `time,temperature` (or \
                      `time,temperature,pressure`, `time,pressure`) and at least one data row"
                .into(),
        });
    };
    let names: Vec<String> = header
        .split(',')
        .map(|c| c.trim().to_ascii_lowercase())
        .collect();
    let plain = HEADERS.into_iter().find(|h| {
        names.len() == h.len() + 1
            && names[0] == "time"
            && h.iter().zip(&names[1..]).all(|(c, n)| c.name() == n)
    });
    // a history written by `sealsim run -o` carries its units in its column names
    let named = plain.map_or_else(|| named_columns(header), |_| None);
    let Some(columns) = plain.or(named.as_ref().map(|n| n.columns)) else {
        return Err(at(
            line,
            format!(
                "expected the header row `time,temperature` (or `time,temperature,pressure`, \
                 `time,pressure`, or the columns of a `sealsim run -o` history such as `time_s` \
                 and `temperature_K`), got {header:?}"
            ),
        ));
    };
    // which cells of a row are time and the columns, of how many
    let (width, picks) = match &named {
        Some(n) => (names.len(), n.picks.clone()),
        None => (columns.len() + 1, (0..=columns.len()).collect()),
    };
    // the units row is required: a bare `0,20` is 20 K to a parser and 20 °C to a reader
    let (seconds, units) = match named {
        Some(n) => units_row(line, &n.units, columns)?,
        None => match rows.next() {
            Some((line, row)) if row.split(',').all(|c| c.trim().parse::<f64>().is_err()) => {
                units_row(line, row, columns)?
            }
            Some((line, _)) => {
                return Err(at(
                    line,
                    format!(
                        "no units row: add one after the header, e.g. `{}` — without it \"20\" \
                     could be 20 K or 20 °C, \"3\" 3 bar or 3 MPa",
                        example_units(columns)
                    ),
                ));
            }
            None => {
                return Err(at(
                    line,
                    format!(
                        "no units row and no data: expected e.g. `{}` after the header, then data \
                     rows",
                        example_units(columns)
                    ),
                ));
            }
        },
    };
    let mut temperature: Vec<(f64, f64)> = Vec::new();
    let mut pressure: Vec<PressureRow> = Vec::new();
    let mut last: Option<f64> = None;
    let mut count = 0;
    while let Some((line, row)) = rows.next() {
        count += 1;
        if count > MAX_HISTORY_ROWS {
            return Err(too_long(line, count + rows.count()));
        }
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        if cells.len() != width {
            return Err(at(
                line,
                format!(
                    "expected {} comma-separated columns (time, {}), found {}",
                    width,
                    columns
                        .iter()
                        .map(|c| c.name())
                        .collect::<Vec<_>>()
                        .join(", "),
                    cells.len()
                ),
            ));
        }
        let t = number(cells[picks[0]], "time", line)? * seconds;
        if !t.is_finite() {
            return Err(at(line, "the value is too large once converted to SI"));
        }
        if let Some(prev) = last
            && t <= prev
        {
            return Err(at(
                line,
                format!(
                    "time must increase strictly from row to row, got {} s after {} s",
                    show(t),
                    show(prev)
                ),
            ));
        }
        last = Some(t);
        for (cell, unit) in picks[1..].iter().map(|&i| cells[i]).zip(&units) {
            match unit {
                Unit::Temperature(u) => temperature.push((t, kelvin(cell, u, line)?)),
                Unit::Pressure(pascal) => {
                    let p = number(cell, "pressure", line)? * pascal;
                    if !p.is_finite() {
                        return Err(at(line, "the value is too large once converted to SI"));
                    }
                    pressure.push((t, p, line));
                }
            }
        }
    }
    if last.is_none() {
        return Err(HistoryError {
            line: None,
            message: "no data rows: a history needs at least one (time, …) row".into(),
        });
    }
    Ok(History {
        temperature: columns
            .contains(&Column::Temperature)
            .then_some(temperature),
        pressure: columns.contains(&Column::Pressure).then_some(pressure),
    })
}

/// The refusal of a file of `rows` data rows, more than [`MAX_HISTORY_ROWS`], at `line`, the
/// first row over the limit.
fn too_long(line: usize, rows: usize) -> HistoryError {
    at(
        line,
        format!(
            "{rows} data rows, more than the limit of {MAX_HISTORY_ROWS} (this line is row {}): \
             every row is an internal step of the run, whose cost grows with them; thin the \
             history (e.g. hourly means: {MAX_HISTORY_ROWS} rows are 45 years of hours) or \
             shorten it to the simulated time",
            MAX_HISTORY_ROWS + 1
        ),
    )
}

/// The columns of a history written by `sealsim run -o` (any `--units`): `time_<unit>`,
/// `temperature_<unit>` and `pressure_<unit>`, the unit after the first `_` (`time_s`,
/// `temperature_F`); the other columns are not read.
struct NamedColumns {
    columns: &'static [Column],
    /// The cells of time and of each column, in a row.
    picks: Vec<usize>,
    /// The units as a units row (`s,F`).
    units: String,
}

/// The [`NamedColumns`] of a header row, if it names a time and a temperature or pressure.
fn named_columns(header: &str) -> Option<NamedColumns> {
    let cells: Vec<&str> = header.split(',').map(str::trim).collect();
    let find = |stem: &str| {
        let mut found = cells.iter().enumerate().filter_map(|(i, c)| {
            let (name, unit) = c.split_once('_')?;
            (name.eq_ignore_ascii_case(stem) && !unit.is_empty()).then_some((i, unit))
        });
        // a name given twice is ambiguous: not this form
        match (found.next(), found.next()) {
            (Some(one), None) => Some(Some(one)),
            (None, _) => Some(None),
            _ => None,
        }
    };
    let time = find("time")??;
    let (temperature, pressure) = (find("temperature")?, find("pressure")?);
    let (columns, rest): (&'static [Column], Vec<(usize, &str)>) = match (temperature, pressure) {
        (Some(t), Some(p)) => (HEADERS[1], vec![t, p]),
        (Some(t), None) => (HEADERS[0], vec![t]),
        (None, Some(p)) => (HEADERS[2], vec![p]),
        (None, None) => return None,
    };
    let all: Vec<(usize, &str)> = std::iter::once(time).chain(rest).collect();
    Some(NamedColumns {
        columns,
        picks: all.iter().map(|&(i, _)| i).collect(),
        units: all.iter().map(|&(_, u)| u).collect::<Vec<_>>().join(","),
    })
}

/// A units row to suggest for `columns`.
fn example_units(columns: &[Column]) -> String {
    let mut out = String::from("h");
    for c in columns {
        out.push_str(match c {
            Column::Temperature => ",C",
            Column::Pressure => ",bar",
        });
    }
    out
}

/// One temperature cell in the unit `unit` → kelvin, checked.
fn kelvin(cell: &str, unit: &str, line: usize) -> Result<f64, HistoryError> {
    let value = number(cell, "temperature", line)?;
    let kelvin = units::absolute_temperature(value, unit)
        .map_err(|e| at(line, format!("temperature: {e}")))?;
    if !kelvin.is_finite() {
        return Err(at(line, "the value is too large once converted to SI"));
    }
    if kelvin <= 0.0 {
        return Err(at(
            line,
            format!(
                "temperature must be above absolute zero, got {} K",
                show(kelvin)
            ),
        ));
    }
    // the scenario's plausible range of absolute temperatures (as for its own keys)
    let (lo, hi) = super::material::TEMPERATURE_RANGE;
    if !(lo..=hi).contains(&kelvin) {
        return Err(at(
            line,
            format!(
                "temperature must lie in [{}, {}] K, got {} K",
                show(lo),
                show(hi),
                show(kelvin)
            ),
        ));
    }
    Ok(kelvin)
}

/// The units row: a time unit, then one unit for each column (an absolute temperature unit, a
/// pressure unit). Returns seconds per time unit and the columns' units.
fn units_row(line: usize, row: &str, columns: &[Column]) -> Result<(f64, Vec<Unit>), HistoryError> {
    let cells: Vec<&str> = row.split(',').map(str::trim).collect();
    if cells.len() != columns.len() + 1 || cells.iter().any(|c| c.is_empty()) {
        let missing = columns
            .iter()
            .enumerate()
            .filter(|(i, _)| cells.get(i + 1).is_none_or(|c| c.is_empty()))
            .map(|(_, c)| c.name())
            .collect::<Vec<_>>();
        return Err(at(
            line,
            format!(
                "expected a units row of {} columns (e.g. `{}`), found {} cells{}",
                columns.len() + 1,
                example_units(columns),
                cells.len(),
                if missing.is_empty() {
                    String::new()
                } else {
                    format!(
                        ": the {} column has no unit — a bare number is ambiguous, add it",
                        missing.join(" and ")
                    )
                }
            ),
        ));
    }
    let time_unit = cells[0];
    let seconds = match units::parse_unit(time_unit) {
        Ok((factor, Dimension::TIME)) => factor,
        Ok((_, found)) => {
            return Err(at(
                line,
                format!(
                    "time unit {time_unit:?} is not a unit of time ({})",
                    found.describe()
                ),
            ));
        }
        Err(e) => return Err(at(line, format!("time unit: {e}"))),
    };
    let mut units = Vec::with_capacity(columns.len());
    for (column, unit) in columns.iter().zip(&cells[1..]) {
        let (dimension, what) = match column {
            Column::Temperature => (Dimension::TEMPERATURE, "a temperature unit"),
            Column::Pressure => (Dimension::PRESSURE, "a pressure unit (e.g. bar, MPa, psi)"),
        };
        match units::parse_unit(unit) {
            Ok((factor, d)) if d == dimension => units.push(match column {
                Column::Temperature => Unit::Temperature((*unit).to_owned()),
                Column::Pressure => Unit::Pressure(factor),
            }),
            Ok((_, found)) => {
                return Err(at(
                    line,
                    format!(
                        "{} unit {unit:?} is not {what} ({})",
                        column.name(),
                        found.describe()
                    ),
                ));
            }
            Err(e) => return Err(at(line, format!("{} unit: {e}", column.name()))),
        }
    }
    Ok((seconds, units))
}

/// A finite number from one cell.
fn number(cell: &str, column: &str, line: usize) -> Result<f64, HistoryError> {
    match cell.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) => Err(at(
            line,
            format!("{column} must be finite, got {}", show(v)),
        )),
        Err(_) => Err(at(line, format!("{column} is not a number: {cell:?}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file of `rows` data rows after its header (line 1) and units row (line 2).
    fn rows(n: usize) -> String {
        let mut text = String::from("time,temperature\ns,C\n");
        for k in 0..n {
            text.push_str(&format!("{k},20\n"));
        }
        text
    }

    /// The bounded-work limit: a file of exactly [`MAX_HISTORY_ROWS`] rows reads; one row more
    /// is refused at that row's line (2 lines of header, so line `MAX + 3`), with the file's
    /// row count and the limit in the message.
    #[test]
    fn a_history_of_more_rows_than_the_limit_is_refused_at_the_first_row_over_it() {
        let at_limit = parse(&rows(MAX_HISTORY_ROWS)).unwrap();
        assert_eq!(at_limit.len(), MAX_HISTORY_ROWS);
        let over = MAX_HISTORY_ROWS + 1234;
        let e = parse(&rows(over)).unwrap_err();
        assert_eq!(e.line, Some(MAX_HISTORY_ROWS + 3));
        for needed in [
            format!("{over} data rows"),
            format!("limit of {MAX_HISTORY_ROWS}"),
            "thin the history".to_owned(),
        ] {
            assert!(e.message.contains(&needed), "{needed}: {}", e.message);
        }
    }

    #[test]
    fn temperatures_outside_the_plausible_range_are_refused_at_their_line() {
        let e = parse("time,temperature\nh,C\n0,25\n1,1e308\n").unwrap_err();
        assert_eq!(e.line, Some(4));
        assert!(
            e.message.contains("must lie in [1, 1000] K"),
            "{}",
            e.message
        );
        assert!(parse("time,temperature\ns,K\n0,0.5\n").is_err());
        assert!(parse("time,temperature\ns,K\n0,1000\n").is_ok());
    }

    #[test]
    fn the_units_row_is_required_and_converts() {
        // without it `20` could be 20 K or 20 °C: refused at the first data line
        let e = parse("# a ramp\ntime,temperature\n0,300\n\n3600,310\n").unwrap_err();
        assert_eq!(e.line, Some(3));
        assert!(e.message.contains("no units row"), "{e:?}");
        // the fix it suggests is accepted
        assert!(parse("time,temperature\nh,C\n0,20\n").is_ok());
        let p = parse("# a ramp\ntime,temperature\ns,K\n0,300\n\n3600,310\n").unwrap();
        assert_eq!(p, [(0.0, 300.0), (3600.0, 310.0)]);
        let p = parse("Time, Temperature\nday, C\n0, 20\n0.5, -40\n").unwrap();
        assert_eq!(p[0], (0.0, 293.15));
        assert_eq!(p[1].0, 43_200.0);
        assert!((p[1].1 - 233.15).abs() < 1e-12);
        let p = parse("\u{feff}time,temperature\nh,K\n1,250\n").unwrap();
        assert_eq!(p, [(3600.0, 250.0)]);
    }

    #[test]
    fn errors_name_the_real_line() {
        let err = |text: &str| parse(text).unwrap_err();
        let e = err("time,temperature\ns,K\n0,300\n# c\n10,warm\n");
        assert_eq!(e.line, Some(5));
        assert!(e.message.contains("temperature is not a number"), "{e:?}");
        let e = err("time,temperature\ns,K\n0,300\n10,301\n5,302\n");
        assert_eq!(e.line, Some(5));
        assert!(e.message.contains("must increase strictly"), "{e:?}");
        let e = err("t,T\n0,300\n");
        assert_eq!(e.line, Some(1));
        assert!(e.message.contains("header row `time,temperature`"), "{e:?}");
        assert_eq!(err("time,temperature\nday,Pa\n0,1\n").line, Some(2));
        assert_eq!(err("time,temperature\nm,C\n0,1\n").line, Some(2));
        assert_eq!(err("time,temperature\ns,K\n0,300,1\n").line, Some(3));
        assert_eq!(err("time,temperature\ns,K\n0,-5\n").line, Some(3));
        assert_eq!(err("time,temperature\nday,C\n0,-300\n").line, Some(3));
        assert_eq!(err("time,temperature\n").line, Some(1));
        assert_eq!(err("# only a comment\n").line, None);
    }
}
