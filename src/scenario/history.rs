//! Temperature histories: a CSV file of `time, temperature` rows (`environment.history`).
//!
//! Format:
//! * lines starting with `#` and blank lines are ignored (a leading byte-order mark too);
//! * the first row is the header `time,temperature` (names case-insensitive);
//! * a units row must follow, e.g. `day,C` or `h,K`: the time unit is any time unit of
//!   [`crate::units`] (`s`, `min`, `h`, `day`, `week`, `year`, …), the temperature unit an
//!   absolute scale (`K`, `C`, `°C`, `degC`, `F`, …); a file without one is refused (its line
//!   named), since a bare temperature is ambiguous;
//! * then at least one data row of two finite numbers; times strictly increasing (t = 0 is the
//!   installation); temperatures above 0 K.
//!
//! Between rows the temperature is linear in time; before the first and after the last row it
//! is constant ([`crate::material::TemperatureHistory::table`]). Parsed by hand (like the PSD
//! files) so that every error names the real line.

use crate::units::{self, Dimension, show};

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

/// The units of the two columns: seconds per time unit, and the temperature unit (`None`:
/// kelvin).
struct Units {
    seconds: f64,
    temperature: Option<String>,
}

/// The `(time [s], temperature [K])` points of a history file's text.
pub(super) fn parse(text: &str) -> Result<Vec<(f64, f64)>, HistoryError> {
    let mut rows = super::data_lines(text).peekable();
    let Some((line, header)) = rows.next() else {
        return Err(HistoryError {
            line: None,
            message: "empty file: expected the header row `time,temperature` and at least one \
                      data row"
                .into(),
        });
    };
    let names: Vec<String> = header
        .split(',')
        .map(|c| c.trim().to_ascii_lowercase())
        .collect();
    if names != ["time", "temperature"] {
        return Err(at(
            line,
            format!("expected the header row `time,temperature`, got {header:?}"),
        ));
    }
    // the units row is required: a bare `0,20` is 20 K to a parser and 20 °C to a reader
    let unit = match rows.next() {
        Some((line, row)) if row.split(',').all(|c| c.trim().parse::<f64>().is_err()) => {
            units_row(line, row)?
        }
        Some((line, _)) => {
            return Err(at(
                line,
                "no units row: add one after the header, e.g. `h,C` (hours, °C) or `s,K` — \
                 without it \"20\" could be 20 K or 20 °C",
            ));
        }
        None => {
            return Err(at(
                line,
                "no units row and no data: expected e.g. `h,C` after the header, then data rows",
            ));
        }
    };
    let mut points: Vec<(f64, f64)> = Vec::new();
    for (line, row) in rows {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        let [t_cell, temp_cell] = cells[..] else {
            return Err(at(
                line,
                format!(
                    "expected 2 comma-separated columns (time, temperature), found {}",
                    cells.len()
                ),
            ));
        };
        let t = number(t_cell, "time", line)? * unit.seconds;
        let value = number(temp_cell, "temperature", line)?;
        let kelvin = match &unit.temperature {
            None => value,
            Some(u) => units::absolute_temperature(value, u)
                .map_err(|e| at(line, format!("temperature: {e}")))?,
        };
        if !(t.is_finite() && kelvin.is_finite()) {
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
        if let Some(&(prev, _)) = points.last()
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
        points.push((t, kelvin));
    }
    if points.is_empty() {
        return Err(HistoryError {
            line: None,
            message: "no data rows: a temperature history needs at least one (time, \
                      temperature) row"
                .into(),
        });
    }
    Ok(points)
}

/// The units row: a time unit and an absolute temperature unit.
fn units_row(line: usize, row: &str) -> Result<Units, HistoryError> {
    let cells: Vec<&str> = row.split(',').map(str::trim).collect();
    let [time_unit, temperature_unit] = cells[..] else {
        return Err(at(
            line,
            format!(
                "expected a units row of 2 columns (e.g. `day,C`), found {} cells",
                cells.len()
            ),
        ));
    };
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
    match units::parse_unit(temperature_unit) {
        Ok((_, Dimension::TEMPERATURE)) => {}
        Ok((_, found)) => {
            return Err(at(
                line,
                format!(
                    "temperature unit {temperature_unit:?} is not a temperature unit ({})",
                    found.describe()
                ),
            ));
        }
        Err(e) => return Err(at(line, format!("temperature unit: {e}"))),
    }
    Ok(Units {
        seconds,
        temperature: Some(temperature_unit.to_owned()),
    })
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
