//! The chart of a life run (docs/model.md §15.3): three panels over one time axis in the
//! reader's unit (h, days or years) — the leak rate (log, clipped at the [`LeakFloor`], the
//! leak-rate threshold as a dashed line, lift-off shaded), the sealing force (the retained-force
//! threshold dashed; the compression set on the right axis where ageing is modelled) and the
//! temperature (frozen spans shaded) (for a cycling temperature its daily envelope, not
//! aliased samples); the failure marked in every panel. Okabe–Ito colours
//! (distinguishable with the common colour-vision deficiencies).

use super::life::LeakFloor;
use super::plot::PlotError;
use super::plot::svg::OKABE_ITO;
use crate::leak::SealState;
use crate::simulate::{LifeProblem, LifeResult};
use crate::units::human;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

const BLUE: RGBColor = RGBColor(0, 114, 178);
const VERMILLION: RGBColor = RGBColor(213, 94, 0);
const ORANGE: RGBColor = RGBColor(230, 159, 0);
const GREEN: RGBColor = RGBColor(0, 158, 115);
const GREY: RGBColor = RGBColor(110, 110, 110);

const HOUR: f64 = 3600.0;
const DAY: f64 = 86_400.0;
const YEAR: f64 = 365.25 * DAY;

fn err<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError(e.to_string())
}

/// A chart over log time and a linear (or log10-valued) y, as every panel here is.
type Panel<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, RangedCoordf64>>;

/// The legend box, at `position`.
pub(crate) fn legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(err)
}

/// A log10 axis value as its decade (`1e-12`), blank between decades.
fn decade_label(v: &f64) -> String {
    if (v - v.round()).abs() < 1e-9 {
        format!("1e{}", v.round())
    } else {
        String::new()
    }
}

/// The floor as a grey dashed line across `x_lo..x_hi` at log10 `y`, labelled with its value
/// `shown` (in the panel's unit) and `label`.
fn floor_line(
    chart: &mut Panel<'_, '_>,
    span: (f64, f64),
    y: f64,
    shown: &str,
    floor: &LeakFloor,
    label: &str,
) -> Result<(), PlotError> {
    let text = format!("floor {shown} ({}){label}", floor.meaning());
    level_line(chart, span, y, (4, 4), GREY.stroke_width(1), text)
}

/// A horizontal dashed line at `y` across `x_lo..x_hi` (`dash`: on and off lengths in
/// pixels), in `style`, with its legend entry `label`: the floor and the limits of the charts.
fn level_line(
    chart: &mut Panel<'_, '_>,
    (x_lo, x_hi): (f64, f64),
    y: f64,
    (on, off): (u32, u32),
    style: ShapeStyle,
    label: String,
) -> Result<(), PlotError> {
    chart
        .draw_series(DashedLineSeries::new(
            vec![(x_lo, y), (x_hi, y)],
            on,
            off,
            style,
        ))
        .map_err(err)?
        .label(label)
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style));
    Ok(())
}

/// The time unit a reader would use for a run ending at `end` \[s\]: (seconds per unit, name).
pub fn time_unit(end: f64) -> (f64, &'static str) {
    if end >= 2.0 * YEAR {
        (YEAR, "years")
    } else if end >= 2.0 * DAY {
        (DAY, "days")
    } else if end >= 2.0 * HOUR {
        (HOUR, "h")
    } else {
        (1.0, "s")
    }
}

/// The chart's lowest leak-rate decade: the floor's (the axis never runs below it).
pub fn leak_axis_bottom(floor: &LeakFloor) -> f64 {
    floor.rate.log10().floor()
}

/// The three-panel SVG of `result`.
pub fn life_chart(
    title: &str,
    problem: &LifeProblem,
    result: &LifeResult,
    floor: &LeakFloor,
) -> Result<String, PlotError> {
    let rows = &result.rows;
    let end = rows.last().map_or(0.0, |r| r.time);
    let first = rows
        .iter()
        .map(|r| r.time)
        .find(|t| *t > 0.0)
        .ok_or_else(|| PlotError("the run has no time after installation".into()))?;
    let (unit, unit_name) = time_unit(end);
    let axis = TimeAxis {
        unit,
        x_lo: first / unit,
        x_hi: (end / unit).max(first / unit * 1.0001),
        label: format!("time after installation [{unit_name}]"),
        first,
        end,
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 1000)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let root = root.titled(title, ("sans-serif", 22)).map_err(err)?;
        let panels = root.split_evenly((3, 1));
        leak_panel(&panels[0], &axis, problem, result, floor)?;
        force_panel(&panels[1], &axis, problem, result)?;
        temperature_panel(&panels[2], &axis, problem, rows)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

/// The time axis the three panels share: the reader's unit, the axis's range in it and its
/// label; the first output time after installation and the run's end \[s\].
struct TimeAxis {
    unit: f64,
    x_lo: f64,
    x_hi: f64,
    label: String,
    first: f64,
    end: f64,
}

/// Points of a line: (time in the axis's unit, value).
type Points = Vec<(f64, f64)>;

/// One panel's drawing area.
type Area<'b> = DrawingArea<SVGBackend<'b>, plotters::coord::Shift>;

/// The leak panel's unit: a liquid's volume flow \[m³/s\]; a gas's throughput \[Pa·m³/s\], the
/// volume flow at the mean pressure p̄ times p̄ (docs/model.md §13.7), the quantity its
/// `max_leak_rate` is given and compared in (interface + permeation).
struct LeakUnit {
    /// Multiplies a volume flow \[m³/s\] into the panel's unit: p̄ for a gas, 1 for a liquid.
    scale: f64,
    gas: bool,
}

impl LeakUnit {
    fn of(problem: &LifeProblem) -> LeakUnit {
        match (problem.fluid.gas, problem.fluid.mean_pressure()) {
            (Some(_), Some(p)) if p > 0.0 => LeakUnit {
                scale: p,
                gas: true,
            },
            _ => LeakUnit {
                scale: 1.0,
                gas: false,
            },
        }
    }

    /// `v` in the panel's unit to `digits` significant digits, with its unit (and mbar·L/s
    /// beside Pa·m³/s: 1 Pa·m³/s = 10 mbar·L/s).
    fn show(&self, v: f64, digits: usize) -> String {
        if self.gas {
            format!(
                "{} Pa·m³/s ({} mbar·L/s)",
                human(v, digits),
                human(10.0 * v, digits)
            )
        } else {
            format!("{} m³/s", human(v, digits))
        }
    }
}

/// Panel 1, the leak rate: log10 of the rate, never below the floor; the floor and the
/// leak-rate threshold dashed, lift-off shaded, the failure marked on the curve the criterion
/// compares. For a gas the throughput \[Pa·m³/s\] through the interface, by permeation
/// through the rubber and their total (what a leak detector sees and `max_leak_rate` is
/// A criterion's limit as a dashed vermillion line at `y` across `x`, labelled for the legend.
fn limit_line(
    chart: &mut Panel<'_, '_>,
    span: (f64, f64),
    y: f64,
    label: String,
) -> Result<(), PlotError> {
    level_line(chart, span, y, (8, 5), VERMILLION.stroke_width(2), label)
}

/// The lift-off stretches of a history (shaded on the leak panel), in the axis's time `unit`.
fn lift_off_spans(rows: &[crate::simulate::HistoryRow], unit: f64) -> Vec<(f64, f64)> {
    rows.windows(2)
        .filter(|w| w[1].state == SealState::LiftOff && w[0].time > 0.0)
        .map(|w| (w[0].time / unit, w[1].time / unit))
        .collect()
}

/// compared with, docs/model.md §13.7), the threshold on the same axis.
fn leak_panel(
    area: &Area<'_>,
    axis: &TimeAxis,
    problem: &LifeProblem,
    result: &LifeResult,
    floor: &LeakFloor,
) -> Result<(), PlotError> {
    let (rows, failure) = (&result.rows, result.failure);
    let (unit, x_lo, x_hi, x_label) = (axis.unit, axis.x_lo, axis.x_hi, &axis.label);
    let leak = LeakUnit::of(problem);
    let floor_value = floor.rate * leak.scale;
    let y_lo = floor_value.log10().floor();
    let clip = |q: f64| q.max(floor_value).log10();
    let mean_pressure = leak.gas.then_some(leak.scale);
    // the panel's quantities of a row, in its unit: interface, permeation (a gas with
    // permeation data) and their total
    let interface = |r: &crate::simulate::HistoryRow| r.leak_rate * leak.scale;
    let permeation = |r: &crate::simulate::HistoryRow| r.permeation.filter(|_| leak.gas);
    let total = |r: &crate::simulate::HistoryRow| r.detected_leak_rate(mean_pressure) * leak.scale;
    let permeates = rows.iter().any(|r| permeation(r).is_some());
    let threshold = problem.failure.max_leak_rate.map(|q| q * leak.scale);
    let top = rows
        .iter()
        .map(total)
        .chain(threshold)
        .fold(floor_value * 10.0, f64::max);
    let y_hi = top.log10().ceil() + 0.5;
    let all_sealed = rows.iter().all(|r| floor.seals(r.leak_rate));
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d((x_lo..x_hi).log_scale(), y_lo..y_hi)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .x_label_formatter(&|v| human(*v, 2))
        .y_desc(if leak.gas {
            "throughput [Pa·m³/s] (×10: mbar·L/s)"
        } else {
            "leak rate [m³/s]"
        })
        .y_label_formatter(&decade_label)
        .draw()
        .map_err(err)?;
    let spans = lift_off_spans(rows, unit);
    chart
        .draw_series(
            spans
                .iter()
                .map(|&(a, b)| Rectangle::new([(a, y_lo), (b, y_hi)], ORANGE.mix(0.15).filled())),
        )
        .map_err(err)?;
    let line = |value: &dyn Fn(&crate::simulate::HistoryRow) -> f64| -> Points {
        rows.iter()
            .filter(|r| r.time > 0.0)
            .map(|r| (r.time / unit, clip(value(r))))
            .collect()
    };
    if permeates {
        // the total first and widest, so that the part it shares with either term shows
        chart
            .draw_series(LineSeries::new(line(&total), BLACK.stroke_width(4)))
            .map_err(err)?
            .label("total: interface + permeation (what max_leak_rate is compared with)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(4)));
        chart
            .draw_series(LineSeries::new(
                line(&|r| permeation(r).unwrap_or(0.0)),
                GREEN.stroke_width(2),
            ))
            .map_err(err)?
            .label("permeation through the rubber")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], GREEN.stroke_width(2)));
    }
    let name = match (leak.gas, permeates) {
        (true, true) => "interface (through the contact)",
        (true, false) => "throughput through the interface",
        (false, _) => "leak rate",
    };
    chart
        .draw_series(LineSeries::new(line(&interface), BLUE.stroke_width(2)))
        .map_err(err)?
        .label(if all_sealed {
            format!("{name}: {}", floor.sealed())
        } else {
            name.to_owned()
        })
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(2)));
    floor_line(
        &mut chart,
        (x_lo, x_hi),
        clip(floor_value),
        &leak.show(floor_value, 2),
        floor,
        ": below it reads sealed",
    )?;
    if let Some(q) = threshold {
        let label = format!("max_leak_rate {}", leak.show(q, 3));
        limit_line(&mut chart, (x_lo, x_hi), clip(q), label)?;
    }
    if !spans.is_empty() {
        chart
            .draw_series(std::iter::empty::<Rectangle<(f64, f64)>>())
            .map_err(err)?
            .label("lift-off (shaded)")
            .legend(|(x, y)| {
                Rectangle::new([(x, y - 5), (x + 20, y + 5)], ORANGE.mix(0.3).filled())
            });
    }
    // on the total: the curve the leak-rate criterion crosses (the interface for a liquid)
    let mark = failure.map(|f| {
        let q = result.detected_leak_rate_at(f.time, mean_pressure);
        (
            (f.time / unit).clamp(x_lo, x_hi),
            clip(q.unwrap_or(0.0) * leak.scale),
        )
    });
    if let (Some(f), Some(at)) = (failure, mark) {
        chart
            .draw_series(std::iter::once(Cross::new(
                at,
                8,
                VERMILLION.stroke_width(3),
            )))
            .map_err(err)?
            .label(format!(
                "fails: {} after {}",
                f.mode.as_str(),
                super::life::human_time(f.time)
            ))
            .legend(|(x, y)| Cross::new((x + 10, y), 6, VERMILLION.stroke_width(3)));
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    // the mark again over the legend box, which may cover it
    if let Some(at) = mark {
        chart
            .draw_series(std::iter::once(Cross::new(
                at,
                8,
                VERMILLION.stroke_width(3),
            )))
            .map_err(err)?;
    }
    Ok(())
}

/// Panel 2, the sealing force \[N/mm\]: the retained-force threshold dashed, the compression
/// set on the right axis where ageing is modelled, the failure marked.
fn force_panel(
    area: &Area<'_>,
    axis: &TimeAxis,
    problem: &LifeProblem,
    result: &LifeResult,
) -> Result<(), PlotError> {
    let (rows, failure) = (&result.rows, result.failure);
    let (unit, x_lo, x_hi, x_label) = (axis.unit, axis.x_lo, axis.x_hi, &axis.label);
    // the right axis: the compression set, with ageing
    let aged = rows.iter().any(|r| r.compression_set.is_some());
    let right = if aged { 70 } else { 0 };
    let force: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.time > 0.0)
        .map(|r| (r.time / unit, r.sealing_force / 1e3))
        .collect();
    let f_max = force.iter().map(|p| p.1).fold(0.0, f64::max).max(1e-9) * 1.15;
    let chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .right_y_label_area_size(right)
        .build_cartesian_2d((x_lo..x_hi).log_scale(), 0.0..f_max)
        .map_err(err)?;
    let set: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.time > 0.0)
        .filter_map(|r| r.compression_set.map(|c| (r.time / unit, 100.0 * c)))
        .collect();
    let mut chart = chart.set_secondary_coord((x_lo..x_hi).log_scale(), 0.0..100.0);
    chart
        .configure_mesh()
        .x_desc(x_label)
        .x_label_formatter(&|v| human(*v, 2))
        .y_desc("sealing force [N/mm]")
        .draw()
        .map_err(err)?;
    if !set.is_empty() {
        chart
            .configure_secondary_axes()
            .y_desc("compression set [%] (dotted)")
            .y_label_formatter(&|v| human(*v, 3))
            .draw()
            .map_err(err)?;
        chart
            .draw_secondary_series(DashedLineSeries::new(
                set.clone(),
                2,
                3,
                GREY.stroke_width(2),
            ))
            .map_err(err)?
            .label("compression set (right axis)")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], GREY.stroke_width(2)));
    }
    chart
        .draw_series(LineSeries::new(force.clone(), GREEN.stroke_width(2)))
        .map_err(err)?
        .label("sealing force per unit length")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], GREEN.stroke_width(2)));
    if let Some(r) = problem.failure.min_retained_force {
        let level = r * result.reference_force / 1e3;
        chart
            .draw_series(DashedLineSeries::new(
                vec![(x_lo, level), (x_hi, level)],
                8,
                5,
                VERMILLION.stroke_width(2),
            ))
            .map_err(err)?
            .label(format!(
                "min_retained_force {} % of {} N/mm",
                human(100.0 * r, 3),
                human(result.reference_force / 1e3, 3)
            ))
            .legend(|(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], VERMILLION.stroke_width(2))
            });
    }
    if let Some(c) = problem.failure.min_sealing_force {
        chart
            .draw_series(DashedLineSeries::new(
                vec![(x_lo, c / 1e3), (x_hi, c / 1e3)],
                8,
                5,
                VERMILLION.stroke_width(2),
            ))
            .map_err(err)?
            .label(format!("min_sealing_force {} N/mm", human(c / 1e3, 3)))
            .legend(|(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], VERMILLION.stroke_width(2))
            });
    }
    if let (Some(c), false) = (problem.failure.max_compression_set, set.is_empty()) {
        chart
            .draw_secondary_series(DashedLineSeries::new(
                vec![(x_lo, 100.0 * c), (x_hi, 100.0 * c)],
                3,
                5,
                VERMILLION.stroke_width(2),
            ))
            .map_err(err)?
            .label(format!(
                "max_compression_set {} % (right axis)",
                human(100.0 * c, 3)
            ))
            .legend(|(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], VERMILLION.stroke_width(2))
            });
    }
    if let Some(f) = failure {
        // on the curve of the quantity that failed: the compression set (right axis) for its
        // criterion, else the sealing force
        let x = (f.time / unit).clamp(x_lo, x_hi);
        let cross = |y: f64| std::iter::once(Cross::new((x, y), 8, VERMILLION.stroke_width(3)));
        if f.mode == crate::simulate::FailureMode::CompressionSet && !set.is_empty() {
            chart
                .draw_secondary_series(cross(on_line(&set, x)))
                .map_err(err)?;
        } else {
            chart.draw_series(cross(on_line(&force, x))).map_err(err)?;
        }
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight)
}

/// The y of the polyline `points` (x on a log axis, y linear, as the panels draw them) at `x`:
/// linear in log x between the vertices about it, so a mark drawn there sits on the line; the
/// end values beyond the ends (0 without points).
fn on_line(points: &[(f64, f64)], x: f64) -> f64 {
    let k = points.partition_point(|p| p.0 < x);
    match (k.checked_sub(1).and_then(|i| points.get(i)), points.get(k)) {
        (Some(a), Some(b)) if b.0 > a.0 && a.0 > 0.0 => {
            let w = (x / a.0).ln() / (b.0 / a.0).ln();
            a.1 + w * (b.1 - a.1)
        }
        (_, Some(b)) => b.1,
        (Some(a), None) => a.1,
        (None, None) => 0.0,
    }
}

/// Panel 3, the temperature \[°C\]: its daily envelope, frozen spans shaded.
fn temperature_panel(
    area: &Area<'_>,
    axis: &TimeAxis,
    problem: &LifeProblem,
    rows: &[crate::simulate::HistoryRow],
) -> Result<(), PlotError> {
    let (unit, x_lo, x_hi, x_label) = (axis.unit, axis.x_lo, axis.x_hi, &axis.label);
    let (low, high) = daily_envelope(axis, problem);
    let t_lo = low.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let t_hi = high.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
    let pad = ((t_hi - t_lo) * 0.15).max(2.0);
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d((x_lo..x_hi).log_scale(), (t_lo - pad)..(t_hi + pad))
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .x_label_formatter(&|v| human(*v, 2))
        .y_desc("temperature [°C]")
        .draw()
        .map_err(err)?;
    // rows where the rubber is frozen (a_T undefined: at or below the WLF limit) shaded
    let frozen: Vec<(f64, f64)> = rows
        .windows(2)
        .filter(|w| w[0].time > 0.0 && !w[1].shift_factor.is_finite())
        .map(|w| (w[0].time / unit, w[1].time / unit))
        .collect();
    let (band_lo, band_hi) = (t_lo - pad, t_hi + pad);
    chart
        .draw_series(
            frozen.iter().map(|&(a, b)| {
                Rectangle::new([(a, band_lo), (b, band_hi)], BLUE.mix(0.12).filled())
            }),
        )
        .map_err(err)?;
    if !frozen.is_empty() {
        chart
            .draw_series(std::iter::empty::<Rectangle<(f64, f64)>>())
            .map_err(err)?
            .label("frozen: below the WLF limit (shaded)")
            .legend(|(x, y)| {
                Rectangle::new([(x, y - 5), (x + 20, y + 5)], BLUE.mix(0.25).filled())
            });
    }
    let cycling = low.iter().zip(&high).any(|(l, h)| h.1 - l.1 > 1e-9);
    if cycling {
        let band: Vec<(f64, f64)> = low
            .iter()
            .copied()
            .chain(high.iter().rev().copied())
            .collect();
        chart
            .draw_series(std::iter::once(Polygon::new(
                band,
                ORANGE.mix(0.35).filled(),
            )))
            .map_err(err)?
            .label("daily range (lowest to highest within ±12 h)")
            .legend(|(x, y)| {
                Rectangle::new([(x, y - 5), (x + 20, y + 5)], ORANGE.mix(0.35).filled())
            });
    }
    chart
        .draw_series(LineSeries::new(high.clone(), VERMILLION.stroke_width(1)))
        .map_err(err)?
        .label(if cycling { "highest" } else { "temperature" })
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], VERMILLION.stroke_width(1)));
    if cycling {
        chart
            .draw_series(LineSeries::new(low, BLUE.stroke_width(1)))
            .map_err(err)?
            .label("lowest")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(1)));
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)
}

/// The temperature's daily envelope \[°C\] over the axis's time: at each of 4 000 log-spaced
/// times the lowest and highest temperature within ±12 h (hourly samples), so a daily cycle
/// shows as its range and a yearly one as the envelope's swing, never as aliased samples.
fn daily_envelope(axis: &TimeAxis, problem: &LifeProblem) -> (Points, Points) {
    let (first, end, unit) = (axis.first, axis.end, axis.unit);
    let grid = 4_000;
    let mut low = Vec::with_capacity(grid);
    let mut high = Vec::with_capacity(grid);
    for k in 0..grid {
        let t = first * (end / first).powf(k as f64 / (grid - 1) as f64);
        let (a, b) = (
            (t - 12.0 * HOUR).max(0.0),
            (t + 12.0 * HOUR).min(end.max(t)),
        );
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for m in 0..=24 {
            let c = problem.environment.at(a + (b - a) * m as f64 / 24.0) - 273.15;
            lo = lo.min(c);
            hi = hi.max(c);
        }
        low.push((t / unit, lo));
        high.push((t / unit, hi));
    }
    (low, high)
}

/// The leak rates of several runs against time (`sealsim compare`): the reader's time unit, the
/// axis never below the floor (lower rates drawn on it), each run's failure marked, Okabe–Ito
/// colours.
pub fn compare_chart(
    title: &str,
    runs: &[(&str, &LifeResult)],
    floor: &LeakFloor,
    mean_pressure: Option<f64>,
) -> Result<String, PlotError> {
    // a gas: what a leak detector sees (interface + permeation), as the criterion compares
    let rate = |row: &crate::simulate::HistoryRow| row.detected_leak_rate(mean_pressure);
    let times = runs
        .iter()
        .flat_map(|(_, r)| r.rows.iter().map(|row| row.time));
    let end = times.clone().fold(0.0, f64::max);
    let first = times.filter(|t| *t > 0.0).fold(f64::INFINITY, f64::min);
    if !first.is_finite() {
        return Err(PlotError("the runs have no time after installation".into()));
    }
    let (unit, unit_name) = time_unit(end);
    let (x_lo, x_hi) = (first / unit, (end / unit).max(first / unit * 1.0001));
    let y_lo = leak_axis_bottom(floor);
    let clip = |q: f64| q.max(floor.rate).log10();
    let top = runs
        .iter()
        .flat_map(|(_, r)| r.rows.iter().map(rate))
        .fold(floor.rate * 10.0, f64::max);
    let y_hi = top.log10().ceil() + 0.5;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(14)
            .x_label_area_size(44)
            .y_label_area_size(90)
            .build_cartesian_2d((x_lo..x_hi).log_scale(), y_lo..y_hi)
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc(format!("time after installation [{unit_name}]"))
            .x_label_formatter(&|v| human(*v, 2))
            .y_desc(if mean_pressure.is_some() {
                "leak rate, interface + permeation [m³/s at p̄]"
            } else {
                "leak rate [m³/s]"
            })
            .y_label_formatter(&decade_label)
            .draw()
            .map_err(err)?;
        for (i, (label, r)) in runs.iter().enumerate() {
            let colour = OKABE_ITO[i % OKABE_ITO.len()];
            let points: Vec<(f64, f64)> = r
                .rows
                .iter()
                .filter(|row| row.time > 0.0)
                .map(|row| (row.time / unit, clip(rate(row))))
                .collect();
            let sealed = r.rows.iter().all(|row| floor.seals(rate(row)));
            chart
                .draw_series(LineSeries::new(points, colour.stroke_width(2)))
                .map_err(err)?
                .label(if sealed {
                    format!("{label}: sealed throughout")
                } else {
                    (*label).to_owned()
                })
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
            if let Some(f) = r.failure {
                // on the drawn curve: for a gas interface + permeation, what the criterion compares
                let q = r
                    .detected_leak_rate_at(f.time, mean_pressure)
                    .unwrap_or(0.0);
                chart
                    .draw_series(std::iter::once(Cross::new(
                        ((f.time / unit).clamp(x_lo, x_hi), clip(q)),
                        7,
                        colour.stroke_width(3),
                    )))
                    .map_err(err)?;
            }
        }
        floor_line(
            &mut chart,
            (x_lo, x_hi),
            clip(floor.rate),
            &format!("{} m³/s", human(floor.rate, 2)),
            floor,
            "; crosses: failures",
        )?;
        legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::on_line;

    /// A mark at x sits on the polyline as drawn on a log-x axis: halfway in log x between
    /// 1 and 100 (x = 10) is halfway in y; the ends hold beyond the line.
    #[test]
    fn a_mark_is_placed_on_the_line_as_drawn() {
        let line = [(1.0, 0.0), (100.0, 2.0), (1000.0, 5.0)];
        assert!((on_line(&line, 10.0) - 1.0).abs() < 1e-12);
        assert!((on_line(&line, 100.0) - 2.0).abs() < 1e-12);
        assert!((on_line(&line, 10f64.powf(2.5)) - 3.5).abs() < 1e-12);
        assert_eq!(on_line(&line, 0.5), 0.0);
        assert_eq!(on_line(&line, 5000.0), 5.0);
        assert_eq!(on_line(&[], 1.0), 0.0);
    }
}
