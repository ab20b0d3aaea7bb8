//! The speed/accuracy trade-off study ([`crate::workflow::tradeoff`]) as CSV, a readable table and an
//! error-against-time chart.

use super::ReportError;
use super::csv::{csv_error, finish, number};
use super::plot::{LogLogChart, Series};
use crate::workflow::tradeoff::TradeoffRow;

/// Columns of the trade-off CSV. Empty cells: no value (a sealed reference, a level without a
/// life run). `static_error` and `life_error` are relative to the most accurate setting of the
/// row's section; the life run is judged by its time to failure when the reference fails, else
/// by the leaked volume.
pub const TRADEOFF_COLUMNS: [&str; 12] = [
    "section",
    "level",
    "setting",
    "nominal_pressure_Pa",
    "static_seconds_s",
    "leak_rate_m3_per_s",
    "leak_rate_std_m3_per_s",
    "static_error",
    "life_seconds_s",
    "time_to_failure_s",
    "leaked_volume_m3",
    "life_error",
];

/// The study as CSV text.
pub fn tradeoff_table(rows: &[TradeoffRow]) -> Result<String, ReportError> {
    let mut writer = ::csv::Writer::from_writer(Vec::new());
    writer.write_record(TRADEOFF_COLUMNS).map_err(csv_error)?;
    for (index, row) in rows.iter().enumerate() {
        let cell = |column: usize, value: Option<f64>| match value {
            Some(v) => number(index + 1, TRADEOFF_COLUMNS[column], v),
            None => Ok(String::new()),
        };
        let life = row.life.as_ref();
        let record = [
            row.section.name().to_owned(),
            row.level.name().to_owned(),
            row.setting.clone(),
            cell(3, Some(row.nominal_pressure))?,
            cell(4, Some(row.static_seconds))?,
            cell(5, Some(row.leak_rate))?,
            cell(6, row.leak_rate_spread)?,
            cell(7, row.static_error)?,
            cell(8, life.map(|l| l.seconds))?,
            cell(9, life.and_then(|l| l.time_to_failure))?,
            cell(10, life.map(|l| l.leaked_volume))?,
            cell(11, life.and_then(|l| l.error))?,
        ];
        writer.write_record(record).map_err(csv_error)?;
    }
    finish(writer)
}

fn short(value: Option<f64>, unit: &str) -> String {
    match value {
        Some(v) => format!("{v:.3e}{unit}"),
        None => "—".to_owned(),
    }
}

/// A Markdown table of the study (what the terminal shows and the guide's fidelity page quotes).
pub fn tradeoff_markdown(rows: &[TradeoffRow]) -> String {
    let mut out = String::from(
        "| section | level | setting | static time | leak rate (m³/s) | static error | life time | time to failure (s) | life error |\n\
         |---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let life = r.life.as_ref();
        let leak = match r.leak_rate_spread {
            Some(sd) => format!("{:.3e} ± {:.1e}", r.leak_rate, sd),
            None => format!("{:.3e}", r.leak_rate),
        };
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            r.section.name(),
            r.level.name(),
            r.setting,
            short(Some(r.static_seconds), " s"),
            leak,
            short(r.static_error, ""),
            short(life.map(|l| l.seconds), " s"),
            short(life.and_then(|l| l.time_to_failure), ""),
            short(life.and_then(|l| l.error), ""),
        ));
    }
    out
}

/// Error against wall time, log–log: one series per section, level and kind (static, life);
/// the reference rows (error 0) do not appear on log axes.
pub fn tradeoff_chart(title: &str, rows: &[TradeoffRow]) -> LogLogChart {
    let mut series: Vec<Series> = Vec::new();
    let mut add = |label: String, point: Option<(f64, f64)>| {
        let Some(point) = point else { return };
        match series.iter_mut().find(|s| s.label == label) {
            Some(s) => s.points.push(point),
            None => series.push(Series {
                label,
                points: vec![point],
            }),
        }
    };
    for r in rows {
        let key = format!("{} {}", r.section.name(), r.level.name());
        add(
            format!("{key} (static)"),
            r.static_error.map(|e| (r.static_seconds, e)),
        );
        if let Some(l) = &r.life {
            add(format!("{key} (life)"), l.error.map(|e| (l.seconds, e)));
        }
    }
    for s in &mut series {
        s.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    LogLogChart {
        title: title.to_owned(),
        x_label: "wall time (s)".to_owned(),
        y_label: "relative error vs the most accurate setting".to_owned(),
        series,
    }
}
