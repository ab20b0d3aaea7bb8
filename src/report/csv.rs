//! CSV tables of results, one row per evaluated point.
//!
//! Numbers are written in the shortest scientific form that round-trips to the same `f64`
//! (`2e5`, `1.6186061430236213e1`); a cell that has no value (a junction quantity of a sealed
//! point) is empty, never `NaN`. Every number is checked to be finite before anything is
//! formatted: a non-finite result is a bug, reported as [`ReportError::NonFinite`].

use super::ReportError;
use crate::contact::{FullContact, Junction};
use crate::dynamic::MotionPoint;
use crate::leak::LeakPoint;

/// Columns of the leak table, in order. Units are in the names; `state` is `leaking`, `lift_off` or
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

/// Columns the leak table gets after `state` for a scenario with `[motion]` (PY08 §8): the
/// first three always, the last three for a stroke cycle.
///
/// * `drag_leak_rate_m3_per_s`: the drag term `L_y d v` at the sliding speed (or the
///   out-stroke speed of a cycle); with constant sliding `leak_rate_m3_per_s` includes it;
/// * `film_thickness_m`: the film `d = β u_c` dragged out (PY08 eq. 16);
/// * `speed_bound_m_per_s`: the validity bound of PY08's second eq. 17 (blank when sealed:
///   no constriction to open);
/// * `out_stroke_volume_m3`, `in_stroke_volume_m3`, `net_volume_per_cycle_m3`: the volumes
///   of one cycle, positive from the pressurised side a to the outside b (blended between the
///   low-speed and the inverse-hydrodynamic values, docs/model.md §3.4.1);
/// * `cycle_mean_leak_rate_m3_per_s`: `net_volume_per_cycle_m3` over the cycle time;
/// * `out_stroke_film_m`, `in_stroke_film_m`: the inverse-hydrodynamic films h* under the
///   pressure maximum (blank without inlet gradients: a flat seal without a profile);
/// * `film_parameter`: the thinner h* over the rms roughness (blank likewise);
/// * `speed_regime`: `low_speed`, `transition`, `inverse_hydrodynamic` or
///   `low_speed_no_profile`; `film_regime`: `boundary`, `mixed` or `full_film` (blank likewise).
pub const MOTION_COLUMNS: [&str; 12] = [
    "drag_leak_rate_m3_per_s",
    "film_thickness_m",
    "speed_bound_m_per_s",
    "out_stroke_volume_m3",
    "in_stroke_volume_m3",
    "net_volume_per_cycle_m3",
    "cycle_mean_leak_rate_m3_per_s",
    "out_stroke_film_m",
    "in_stroke_film_m",
    "film_parameter",
    "speed_regime",
    "film_regime",
];

/// Columns of `sealsim leak`'s table after [`LEAK_COLUMNS`]: the interface at full
/// magnification at the nominal pressure ([`crate::leak::ContactPath::full_contact`]):
///
/// * `area_fraction`: the relative contact area A/A0 (Persson's A(q1/q0)/A0 at every analytic
///   level, the ensemble-mean boundary-element contact fraction at the numerical level);
/// * `mean_gap_m`: the mean interfacial separation ū (ū(ζ = 1), or the ensemble-mean gap).
///
/// Blank for an O-ring (its contact pressure varies across the profile).
pub const CONTACT_COLUMNS: [&str; 2] = ["area_fraction", "mean_gap_m"];

/// `sealsim leak`'s table of `outcome` (the CLI's `-o` file and the Python package's
/// `Scenario.leak`): [`motion_leak_table`] with `[motion]`, else [`gas_leak_table`] for a gas
/// of mean pressure `mean_pressure` \[Pa\], else [`leak_table`].
pub fn leak_outcome_table(
    outcome: &crate::workflow::leak::LeakOutcome,
    mean_pressure: Option<f64>,
) -> Result<String, ReportError> {
    match (&outcome.motion, mean_pressure) {
        (Some(motion), _) => {
            motion_leak_table(&outcome.points, &outcome.contact, motion, outcome.stroke)
        }
        (None, Some(p)) => gas_leak_table(&outcome.points, &outcome.contact, p),
        (None, None) => leak_table(&outcome.points, &outcome.contact),
    }
}

/// `sealsim leak --pressure-differences`'s table (the Python package's
/// `Scenario.leak(pressure_differences=…)`): one row per fluid pressure difference,
/// `pressure_difference_Pa` and `extrudes` (`yes`/`no` at installation, blank without a gland)
/// before the columns of [`leak_outcome_table`] at that ΔP, whose first column is named
/// `contact_pressure_Pa` here (a flat seal's nominal pressure, an O-ring's peak contact pressure
/// with k_e ΔP): the two pressures side by side, so neither is mistaken for the other.
pub fn pressure_difference_table(
    rows: &[crate::workflow::leak::DifferenceRow],
) -> Result<String, ReportError> {
    let mut out = String::new();
    for (index, row) in rows.iter().enumerate() {
        let table = leak_outcome_table(&row.outcome, row.mean_pressure)?;
        let mut lines = table.lines();
        let (Some(header), Some(record), None) = (lines.next(), lines.next(), lines.next()) else {
            return Err(ReportError::Csv(format!(
                "row {}: a pressure difference gives one point, got {} lines",
                index + 1,
                table.lines().count()
            )));
        };
        if index == 0 {
            let rest = header.strip_prefix(LEAK_COLUMNS[0]).unwrap_or(header);
            out.push_str("pressure_difference_Pa,extrudes,contact_pressure_Pa");
            out.push_str(rest);
            out.push('\n');
        }
        let dp = number(index + 1, "pressure_difference_Pa", row.pressure_difference)?;
        let extrudes = match row.extrudes {
            Some(true) => "yes",
            Some(false) => "no",
            None => "",
        };
        out.push_str(&format!("{dp},{extrudes},{record}\n"));
    }
    if rows.is_empty() {
        out.push_str("pressure_difference_Pa,extrudes,contact_pressure_Pa\n");
    }
    Ok(out)
}

/// The leak table of `points` with the [`CONTACT_COLUMNS`] of `contact` (`contact[i]` belongs
/// to `points[i]`; `None` leaves its cells blank), header plus one row per point, as CSV text.
pub fn leak_table(
    points: &[LeakPoint],
    contact: &[Option<FullContact>],
) -> Result<String, ReportError> {
    same_length(points, contact.len(), "contact")?;
    table(
        None,
        &CONTACT_COLUMNS,
        points
            .iter()
            .zip(contact)
            .enumerate()
            .map(|(i, (p, c))| ("", p, contact_cells(i + 1, c.as_ref()))),
    )
}

/// The leak table of a gas (docs/model.md §3.9): [`LEAK_COLUMNS`], [`CONTACT_COLUMNS`] and
/// `throughput_Pa_m3_per_s`, the pV flow `p̄ × leak_rate_m3_per_s` at the gas temperature (a
/// gas's leak rate is its volume flow at the mean pressure `mean_pressure` p̄ \[Pa\]), and the
/// same in the leak-test trade's unit, `throughput_mbar_L_per_s` (1 mbar·L/s = 0.1 Pa·m³/s).
/// Flow through the interface only: permeation through the rubber is not in these columns.
pub fn gas_leak_table(
    points: &[LeakPoint],
    contact: &[Option<FullContact>],
    mean_pressure: f64,
) -> Result<String, ReportError> {
    const COLUMNS: [&str; 2] = ["throughput_Pa_m3_per_s", "throughput_mbar_L_per_s"];
    /// Pa·m³/s per mbar·L/s: 100 Pa × 1e-3 m³.
    const MBAR_L: f64 = 0.1;
    same_length(points, contact.len(), "contact")?;
    let columns: Vec<&str> = CONTACT_COLUMNS.into_iter().chain(COLUMNS).collect();
    table(
        None,
        &columns,
        points.iter().zip(contact).enumerate().map(|(i, (p, c))| {
            let q = mean_pressure * p.leak_rate;
            let cells = contact_cells(i + 1, c.as_ref()).and_then(|mut cells| {
                cells.push(number(i + 1, COLUMNS[0], q)?);
                cells.push(number(i + 1, COLUMNS[1], q / MBAR_L)?);
                Ok(cells)
            });
            ("", p, cells)
        }),
    )
}

/// The leak table with the [`CONTACT_COLUMNS`] of `contact` and the [`MOTION_COLUMNS`] of each
/// point's motion (`contact[i]` and `motion[i]` belong to `points[i]`); the stroke columns only
/// when `stroke`.
pub fn motion_leak_table(
    points: &[LeakPoint],
    contact: &[Option<FullContact>],
    motion: &[MotionPoint],
    stroke: bool,
) -> Result<String, ReportError> {
    same_length(points, motion.len(), "motion")?;
    same_length(points, contact.len(), "contact")?;
    let count = if stroke { MOTION_COLUMNS.len() } else { 3 };
    let columns: Vec<&str> = CONTACT_COLUMNS
        .into_iter()
        .chain(MOTION_COLUMNS[..count].iter().copied())
        .collect();
    table(
        None,
        &columns,
        points
            .iter()
            .zip(contact)
            .zip(motion)
            .enumerate()
            .map(|(i, ((p, c), m))| {
                let cells = contact_cells(i + 1, c.as_ref()).and_then(|mut cells| {
                    cells.extend(motion_cells(i + 1, m, count)?);
                    Ok(cells)
                });
                ("", p, cells)
            }),
    )
}

/// An error unless there are as many `what` values (`len`) as `points`.
fn same_length(points: &[LeakPoint], len: usize, what: &str) -> Result<(), ReportError> {
    if points.len() == len {
        Ok(())
    } else {
        Err(ReportError::Csv(format!(
            "{} leak points but {len} {what} points",
            points.len()
        )))
    }
}

/// The [`CONTACT_COLUMNS`] cells of data row `row` (1-based); blank without a value.
fn contact_cells(row: usize, contact: Option<&FullContact>) -> Result<Vec<String>, ReportError> {
    match contact {
        Some(c) => Ok(vec![
            number(row, CONTACT_COLUMNS[0], c.area_fraction)?,
            number(row, CONTACT_COLUMNS[1], c.mean_gap)?,
        ]),
        None => Ok(vec![String::new(), String::new()]),
    }
}

/// The motion cells of data row `row` (1-based).
fn motion_cells(row: usize, m: &MotionPoint, columns: usize) -> Result<Vec<String>, ReportError> {
    let cell = |column: usize, value: f64| number(row, MOTION_COLUMNS[column], value);
    let mut cells = vec![
        cell(0, m.drag_leak_rate)?,
        cell(1, m.film_thickness)?,
        if m.speed_bound.is_finite() {
            cell(2, m.speed_bound)?
        } else {
            String::new()
        },
    ];
    if columns == MOTION_COLUMNS.len() {
        match &m.cycle {
            Some(c) => {
                cells.push(cell(3, c.out_volume)?);
                cells.push(cell(4, c.in_volume)?);
                cells.push(cell(5, c.net_volume)?);
                cells.push(if c.period > 0.0 {
                    cell(6, c.net_volume / c.period)?
                } else {
                    String::new()
                });
            }
            None => cells.extend([String::new(), String::new(), String::new(), String::new()]),
        }
        match &m.ihl {
            Some(ihl) => {
                cells.push(cell(7, ihl.out_film)?);
                cells.push(cell(8, ihl.in_film)?);
                cells.push(if ihl.film_parameter.is_finite() {
                    cell(9, ihl.film_parameter)?
                } else {
                    String::new()
                });
                cells.push(m.regime.id().to_owned());
                cells.push(ihl.film_regime().id().to_owned());
            }
            None => {
                cells.extend([String::new(), String::new(), String::new()]);
                cells.push(m.regime.id().to_owned());
                cells.push(String::new());
            }
        }
    }
    Ok(cells)
}

/// The leak table with a leading `scenario` column naming the scenario of each row (for
/// results of several scenarios in one file).
pub fn scenario_leak_table<'a>(
    rows: impl IntoIterator<Item = (&'a str, &'a LeakPoint)>,
) -> Result<String, ReportError> {
    table(
        Some("scenario"),
        &[],
        rows.into_iter().map(|(l, p)| (l, p, Ok(Vec::new()))),
    )
}

/// The table: an optional label column, [`LEAK_COLUMNS`], then `extra_columns` whose cells
/// each row brings along (or the error that stops the table).
fn table<'a>(
    label_column: Option<&str>,
    extra_columns: &[&str],
    rows: impl IntoIterator<Item = (&'a str, &'a LeakPoint, Result<Vec<String>, ReportError>)>,
) -> Result<String, ReportError> {
    let mut writer = ::csv::Writer::from_writer(Vec::new());
    let header = label_column
        .into_iter()
        .chain(LEAK_COLUMNS)
        .chain(extra_columns.iter().copied());
    writer.write_record(header).map_err(csv_error)?;
    for (index, (label, point, extra)) in rows.into_iter().enumerate() {
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
                point.state.as_str().to_owned(),
            ],
            Junction::Sealed => [
                cell(0, point.nominal_pressure)?,
                String::new(),
                String::new(),
                String::new(),
                String::new(),
                String::new(),
                cell(6, point.leak_rate)?,
                point.state.as_str().to_owned(),
            ],
        };
        let label = label_column.map(|_| label.to_owned());
        writer
            .write_record(label.into_iter().chain(record).chain(extra?))
            .map_err(csv_error)?;
    }
    finish(writer)
}

/// One cell of a report [`Table`]: a finite number, a blank (no value) or a word.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A finite number, written in shortest round-trip scientific notation.
    Number(f64),
    /// No value: an empty cell (e.g. `u_c_m` where the strip is sealed).
    Blank,
    /// A word (a state, a regime).
    Text(String),
}

impl Cell {
    /// A number cell, checked finite: a non-finite value is a bug, reported with its `row`
    /// (1-based, the header is row 0) and `column`.
    pub fn number(row: usize, column: &'static str, value: f64) -> Result<Cell, ReportError> {
        if value.is_finite() {
            Ok(Cell::Number(value))
        } else {
            Err(ReportError::NonFinite { row, column, value })
        }
    }

    /// [`Cell::number`] of `Some` value, [`Cell::Blank`] of `None`.
    pub fn optional(
        row: usize,
        column: &'static str,
        value: Option<f64>,
    ) -> Result<Cell, ReportError> {
        value.map_or(Ok(Cell::Blank), |v| Cell::number(row, column, v))
    }

    /// The cell's CSV text (a number in shortest round-trip scientific notation).
    pub fn text(&self) -> String {
        match self {
            Cell::Number(v) => format!("{v:e}"),
            Cell::Blank => String::new(),
            Cell::Text(t) => t.clone(),
        }
    }
}

/// A report table: a header and rows of [`Cell`]s whose numbers were checked finite when they
/// were made. [`Table::to_csv`] writes it; the Python package reads its columns as floats
/// directly, which are the CSV's bit for bit (the CSV's notation round-trips), without
/// formatting and parsing every cell.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The column names (SI units in them).
    pub header: Vec<&'static str>,
    /// The rows, each as long as the header.
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// The table as CSV text: the header, then one record per row.
    pub fn to_csv(&self) -> Result<String, ReportError> {
        let mut writer = ::csv::Writer::from_writer(Vec::new());
        writer.write_record(&self.header).map_err(csv_error)?;
        for row in &self.rows {
            writer
                .write_record(row.iter().map(Cell::text))
                .map_err(csv_error)?;
        }
        finish(writer)
    }
}

/// A finite value in shortest round-trip scientific notation.
pub(crate) fn number(row: usize, column: &'static str, value: f64) -> Result<String, ReportError> {
    Cell::number(row, column, value).map(|cell| cell.text())
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
    use crate::leak::SealState;

    #[test]
    fn a_table_writes_numbers_blanks_and_words_and_refuses_non_finite_numbers() {
        let table = Table {
            header: vec!["gap_m", "state"],
            rows: vec![
                vec![Cell::Number(0.1), Cell::Text("sealed".into())],
                vec![Cell::Blank, Cell::Text("a,b".into())],
            ],
        };
        assert_eq!(
            table.to_csv().expect("finite"),
            "gap_m,state\n1e-1,sealed\n,\"a,b\"\n"
        );
        assert!(matches!(
            Cell::number(3, "gap_m", f64::NAN),
            Err(ReportError::NonFinite {
                row: 3,
                column: "gap_m",
                ..
            })
        ));
        assert_eq!(Cell::optional(1, "gap_m", None).ok(), Some(Cell::Blank));
    }

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
            state: SealState::Leaking,
        }
    }

    #[test]
    fn rows_are_round_trip_scientific_and_sealed_cells_blank() {
        let sealed = LeakPoint {
            nominal_pressure: 3e6,
            junction: Junction::Sealed,
            leak_rate: 0.0,
            state: SealState::Sealed,
        };
        let contact = FullContact {
            area_fraction: 0.125,
            mean_gap: 3e-7,
        };
        let text = leak_table(&[leaking(2e5, 0.1), sealed], &[Some(contact), None]).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            format!("{},{}", LEAK_COLUMNS.join(","), CONTACT_COLUMNS.join(","))
        );
        assert_eq!(
            lines[1],
            "2e5,1.65e1,3.8e-5,1e-1,2e-7,1e-7,1.25e-12,leaking,1.25e-1,3e-7"
        );
        // no contact value (an O-ring): blank cells
        assert_eq!(lines[2], "3e6,,,,,,0e0,sealed,,");
        assert_eq!(lines.len(), 3);
        let x = 0.1 + 0.2;
        let t = leak_table(&[leaking(2e5, x)], &[None]).unwrap();
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
    fn motion_columns_follow_state_and_blank_an_infinite_bound() {
        use crate::dynamic::StrokeCycle;
        let sealed = LeakPoint {
            nominal_pressure: 3e6,
            junction: Junction::Sealed,
            leak_rate: 0.0,
            state: SealState::Sealed,
        };
        let moving = MotionPoint {
            drag_leak_rate: 4e-11,
            film_thickness: 8e-9,
            speed_bound: 6e-3,
            above_bound: true,
            cycle: None,
            ihl: None,
            ihl_weights: (0.0, 0.0),
            regime: crate::dynamic::ihl::SpeedRegime::NoProfile,
        };
        let still = MotionPoint {
            drag_leak_rate: 0.0,
            film_thickness: 0.0,
            speed_bound: f64::INFINITY,
            above_bound: false,
            cycle: None,
            ihl: None,
            ihl_weights: (0.0, 0.0),
            regime: crate::dynamic::ihl::SpeedRegime::NoProfile,
        };
        let points = [leaking(2e5, 0.1), sealed];
        let contact = [None, None];
        let text = motion_leak_table(&points, &contact, &[moving, still], false).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            format!(
                "{},{},{}",
                LEAK_COLUMNS.join(","),
                CONTACT_COLUMNS.join(","),
                MOTION_COLUMNS[..3].join(",")
            )
        );
        assert_eq!(
            lines[1],
            "2e5,1.65e1,3.8e-5,1e-1,2e-7,1e-7,1.25e-12,leaking,,,4e-11,8e-9,6e-3"
        );
        assert_eq!(lines[2], "3e6,,,,,,0e0,sealed,,,0e0,0e0,");
        // a stroke cycle: three more columns
        let cycle = StrokeCycle {
            period: 2.0,
            out_volume: 1e-12,
            in_volume: -0.5e-12,
            net_volume: 0.5e-12,
            static_volume: 0.5e-12,
            drag_volume: 0.75e-12,
            within_speed_bound: true,
        };
        let stroke = MotionPoint {
            cycle: Some(cycle),
            ..moving
        };
        let text = motion_leak_table(&points[..1], &contact[..1], &[stroke], true).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            format!(
                "{},{},{}",
                LEAK_COLUMNS.join(","),
                CONTACT_COLUMNS.join(","),
                MOTION_COLUMNS.join(",")
            )
        );
        assert!(
            lines[1]
                .ends_with(",4e-11,8e-9,6e-3,1e-12,-5e-13,5e-13,2.5e-13,,,,low_speed_no_profile,"),
            "{}",
            lines[1]
        );
        // a non-finite motion value is refused like any other
        let bad = MotionPoint {
            film_thickness: f64::NAN,
            ..moving
        };
        assert!(matches!(
            motion_leak_table(&points[..1], &contact[..1], &[bad], false),
            Err(ReportError::NonFinite {
                row: 1,
                column: "film_thickness_m",
                ..
            })
        ));
        assert!(motion_leak_table(&points, &contact, &[moving], false).is_err());
        assert!(motion_leak_table(&points, &contact[..1], &[moving, still], false).is_err());
    }

    #[test]
    fn non_finite_values_are_refused() {
        let err = leak_table(&[leaking(2e5, f64::NAN)], &[None]).unwrap_err();
        assert!(err.to_string().contains("u_c_m"));
        assert!(matches!(
            err,
            ReportError::NonFinite {
                row: 1,
                column: "u_c_m",
                ..
            }
        ));
        let nan_area = FullContact {
            area_fraction: f64::NAN,
            mean_gap: 1e-6,
        };
        assert!(matches!(
            leak_table(&[leaking(2e5, 0.1)], &[Some(nan_area)]),
            Err(ReportError::NonFinite {
                row: 1,
                column: "area_fraction",
                ..
            })
        ));
        assert!(leak_table(&[leaking(2e5, 0.1)], &[]).is_err());
    }
}
