//! The ageing-data file of `sealsim ageing-fit` (ISO 11346): one series per ageing temperature,
//! read once into SI model types ([`AgeingSeries`]) at the input boundary; the fit itself is
//! [`crate::material::ageing_fit`].

use crate::material::ageing_fit::{AgeingPoint, AgeingSeries};
use crate::units::{self, Dimension};
use std::path::Path;

/// A data file or fit that cannot be used: the one data-file error, [`DataFileError`](crate::scenario::DataFileError)
/// (`path:line: message`), under the name this module's callers know.
pub type AgeingFitError = super::text::DataFileError;

type Located = (Option<usize>, String);

fn cells(row: &str) -> Vec<&str> {
    row.split(',').map(str::trim).collect()
}

/// Reads the ageing data file at `path` ([`parse_ageing_data`]).
pub fn read_ageing_data(path: &Path) -> Result<Vec<AgeingSeries>, AgeingFitError> {
    let text = std::fs::read_to_string(path).map_err(|e| AgeingFitError {
        path: path.to_path_buf(),
        line: None,
        message: format!("cannot read the data file: {e}"),
    })?;
    parse_ageing_data(&text, path)
}

/// Parses ageing-data `text` (as if read from `path`, used only in messages) into one series
/// per temperature, in order of first appearance.
///
/// Header `temperature,time,value` (case-insensitive; `T`, `t` accepted), then a units row:
/// an absolute temperature unit (`C`, `K`, `F`, …), a time unit (`s`, `h`, `d`, …), `1` or `%`.
/// Values in SI (K, s, fraction). Times ≥ 0 and, within one temperature, strictly increasing;
/// values finite and ≥ 0. `#` lines and blank lines are skipped.
pub fn parse_ageing_data(text: &str, path: &Path) -> Result<Vec<AgeingSeries>, AgeingFitError> {
    parse(text).map_err(|(line, message)| AgeingFitError {
        path: path.to_path_buf(),
        line,
        message,
    })
}

fn parse(text: &str) -> Result<Vec<AgeingSeries>, Located> {
    let mut rows = super::text::data_lines(text);
    let Some((header_line, header)) = rows.next() else {
        return Err((
            None,
            "no data: expected a header row temperature,time,value".into(),
        ));
    };
    let names: Vec<String> = cells(header).iter().map(|c| c.to_lowercase()).collect();
    let expected = [
        ["temperature", "t"].as_slice(),
        ["time", "t"].as_slice(),
        ["value"].as_slice(),
    ];
    if names.len() != 3
        || names
            .iter()
            .zip(expected)
            .any(|(n, e)| !e.contains(&n.as_str()))
    {
        return Err((
            Some(header_line),
            format!("expected the header row temperature,time,value, found {header:?}"),
        ));
    }
    let Some((units_line, units_row)) = rows.next() else {
        return Err((
            Some(header_line),
            "no units row: expected e.g. C,h,1 after the header".into(),
        ));
    };
    let units_cells = cells(units_row);
    if units_cells.len() != 3 {
        return Err((
            Some(units_line),
            format!(
                "the units row has {} cells, expected 3 (e.g. C,h,1)",
                units_cells.len()
            ),
        ));
    }
    let temperature_unit = units_cells[0];
    units::absolute_temperature(300.0, temperature_unit).map_err(|e| {
        (
            Some(units_line),
            format!("temperature: unit {temperature_unit:?}: {e} (expected C, K or F)"),
        )
    })?;
    let time_unit = units_cells[1];
    let time_factor = match units::parse_unit(time_unit) {
        Ok((factor, Dimension::TIME)) => factor,
        Ok((_, dimension)) => {
            return Err((
                Some(units_line),
                format!("time: unit {time_unit:?} is {dimension}, expected a time (e.g. h)"),
            ));
        }
        Err(e) => return Err((Some(units_line), format!("time: {e}"))),
    };
    let value_factor = match units_cells[2] {
        "1" | "" => 1.0,
        "%" => 0.01,
        other => {
            return Err((
                Some(units_line),
                format!("value: unit {other:?}, expected 1 (a fraction) or %"),
            ));
        }
    };
    let mut series: Vec<AgeingSeries> = Vec::new();
    for (line, row) in rows {
        let row_cells = cells(row);
        if row_cells.len() != 3 {
            return Err((
                Some(line),
                format!(
                    "expected 3 comma-separated columns (temperature, time, value), found {}",
                    row_cells.len()
                ),
            ));
        }
        let number = |k: usize, name: &str| -> Result<f64, Located> {
            match row_cells[k].parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err((
                    Some(line),
                    format!("{name}: not a finite number: {:?}", row_cells[k]),
                )),
            }
        };
        let temperature = units::absolute_temperature(number(0, "temperature")?, temperature_unit)
            .map_err(|e| (Some(line), format!("temperature: {e}")))?;
        let time = number(1, "time")? * time_factor;
        let value = number(2, "value")? * value_factor;
        if time < 0.0 {
            return Err((
                Some(line),
                format!("time: must be ≥ 0, got {}", row_cells[1]),
            ));
        }
        if value < 0.0 {
            return Err((
                Some(line),
                format!("value: must be ≥ 0, got {}", row_cells[2]),
            ));
        }
        let point = AgeingPoint { line, time, value };
        match series.iter_mut().find(|s| s.temperature == temperature) {
            Some(s) => {
                if let Some(previous) = s.points.last()
                    && time <= previous.time
                {
                    return Err((
                        Some(line),
                        format!(
                            "time: must increase strictly within one temperature, got {} after line {}",
                            row_cells[1], previous.line
                        ),
                    ));
                }
                s.points.push(point);
            }
            None => series.push(AgeingSeries {
                temperature,
                points: vec![point],
            }),
        }
    }
    if series.is_empty() {
        return Err((Some(units_line), "no data rows".into()));
    }
    Ok(series)
}
