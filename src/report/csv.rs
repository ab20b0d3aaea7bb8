//! CSV tables of results, one row per evaluated point.
//!
//! Numbers are written in the shortest scientific form that round-trips to the same `f64`
//! (`2e5`, `1.6186061430236213e1`); a cell that has no value (a junction quantity of a sealed
//! point) is empty, never `NaN`. Every number is checked to be finite before anything is
//! formatted: a non-finite result is a bug, reported as [`ReportError::NonFinite`].

use super::ReportError;
use crate::contact::Junction;
use crate::leak::LeakPoint;

/// Columns of the leak table, in order. Units are in the names; `state` is `leaking` or
/// `sealed`. `lambda_c_m` is λc = 2π/(ζc q0).
pub const LEAK_COLUMNS: [&str; 8] = [
    "nominal_pressure_Pa",
    "zeta_c",
    "lambda_c_m",
    "u_c_m",
    "ubar_c_m",
    "hrms_c_m",
    "leak_rate_m3_per_s",
    "state",
];

/// The leak table of `points` (header plus one row per point), as CSV text.
pub fn leak_table(points: &[LeakPoint]) -> Result<String, ReportError> {
    table(None, points.iter().map(|p| ("", p)))
}

/// The leak table with a leading `scenario` column naming the scenario of each row (for
/// results of several scenarios in one file).
pub fn scenario_leak_table<'a>(
    rows: impl IntoIterator<Item = (&'a str, &'a LeakPoint)>,
) -> Result<String, ReportError> {
    table(Some("scenario"), rows)
}

fn table<'a>(
    label_column: Option<&str>,
    rows: impl IntoIterator<Item = (&'a str, &'a LeakPoint)>,
) -> Result<String, ReportError> {
    let mut writer = ::csv::Writer::from_writer(Vec::new());
    let header = label_column.into_iter().chain(LEAK_COLUMNS);
    writer.write_record(header).map_err(csv_error)?;
    for (index, (label, point)) in rows.into_iter().enumerate() {
        let cell = |column: usize, value: f64| number(index + 1, LEAK_COLUMNS[column], value);
        let record = match point.junction {
            Junction::Leaking(j) => [
                cell(0, point.nominal_pressure)?,
                cell(1, j.zeta_c)?,
                cell(2, j.lambda_c)?,
                cell(3, j.u_c)?,
                cell(4, j.ubar_c)?,
                cell(5, j.hrms_c)?,
                cell(6, point.leak_rate)?,
                "leaking".to_owned(),
            ],
            Junction::Sealed => [
                cell(0, point.nominal_pressure)?,
                String::new(),
                String::new(),
                String::new(),
                String::new(),
                String::new(),
                cell(6, point.leak_rate)?,
                "sealed".to_owned(),
            ],
        };
        let label = label_column.map(|_| label.to_owned());
        writer
            .write_record(label.into_iter().chain(record))
            .map_err(csv_error)?;
    }
    finish(writer)
}

/// A finite value in shortest round-trip scientific notation.
pub(crate) fn number(row: usize, column: &'static str, value: f64) -> Result<String, ReportError> {
    if value.is_finite() {
        Ok(format!("{value:e}"))
    } else {
        Err(ReportError::NonFinite { row, column, value })
    }
}

/// A CSV writer error as a report error.
pub(crate) fn csv_error(e: ::csv::Error) -> ReportError {
    ReportError::Csv(e.to_string())
}

/// The text a CSV writer over a byte buffer has produced.
pub(crate) fn finish(writer: ::csv::Writer<Vec<u8>>) -> Result<String, ReportError> {
    let bytes = writer
        .into_inner()
        .map_err(|e| ReportError::Csv(e.to_string()))?;
    String::from_utf8(bytes).map_err(|e| ReportError::Csv(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::CriticalJunction;

    fn leaking(p0: f64, u_c: f64) -> LeakPoint {
        let j = CriticalJunction {
            zeta_c: 16.5,
            lambda_c: 3.8e-5,
            u_c,
            ubar_c: 2e-7,
            hrms_c: 1e-7,
        };
        LeakPoint {
            nominal_pressure: p0,
            junction: Junction::Leaking(j),
            leak_rate: 1.25e-12,
        }
    }

    #[test]
    fn rows_are_round_trip_scientific_and_sealed_cells_blank() {
        let sealed = LeakPoint {
            nominal_pressure: 3e6,
            junction: Junction::Sealed,
            leak_rate: 0.0,
        };
        let text = leak_table(&[leaking(2e5, 0.1), sealed]).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], LEAK_COLUMNS.join(","));
        assert_eq!(
            lines[1],
            "2e5,1.65e1,3.8e-5,1e-1,2e-7,1e-7,1.25e-12,leaking"
        );
        assert_eq!(lines[2], "3e6,,,,,,0e0,sealed");
        assert_eq!(lines.len(), 3);
        let x = 0.1 + 0.2;
        let t = leak_table(&[leaking(2e5, x)]).unwrap();
        let cell: f64 = t
            .lines()
            .nth(1)
            .unwrap()
            .split(',')
            .nth(3)
            .unwrap()
            .parse()
            .unwrap();
        assert_eq!(cell, x);
    }

    #[test]
    fn non_finite_values_are_refused() {
        let err = leak_table(&[leaking(2e5, f64::NAN)]).unwrap_err();
        assert!(err.to_string().contains("u_c_m"));
        assert!(matches!(
            err,
            ReportError::NonFinite {
                row: 1,
                column: "u_c_m",
                ..
            }
        ));
    }
}
