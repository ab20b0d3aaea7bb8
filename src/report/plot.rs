//! Log–log line charts of one quantity against another, rendered as SVG (plotters) with the
//! `cli` feature.

use std::fmt;

/// One labelled curve; points with non-positive or non-finite coordinates are not drawn
/// (on log axes they do not exist — e.g. a sealed state with zero leak rate).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// A log–log chart.
#[derive(Debug, Clone, PartialEq)]
pub struct LogLogChart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
}

/// Why a chart could not be drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct PlotError(pub String);

impl fmt::Display for PlotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "plot: {}", self.0)
    }
}

impl std::error::Error for PlotError {}

/// Rendering (plotters): only with the `cli` feature, which brings the plotting dependency.
#[cfg(feature = "cli")]
pub(crate) mod svg {
    use super::{LogLogChart, PlotError, Series};
    use plotters::prelude::*;

    /// The Okabe–Ito colours (distinguishable with the common colour-vision deficiencies),
    /// black last.
    pub(crate) const OKABE_ITO: [RGBColor; 7] = [
        RGBColor(0, 114, 178),
        RGBColor(213, 94, 0),
        RGBColor(0, 158, 115),
        RGBColor(230, 159, 0),
        RGBColor(204, 121, 167),
        RGBColor(86, 180, 233),
        RGBColor(0, 0, 0),
    ];
    use std::fmt;

    fn err<E: fmt::Display>(e: E) -> PlotError {
        PlotError(e.to_string())
    }

    /// Bounds of the drawable points; with `whole_decades`, widened to powers of ten.
    fn bounds(values: impl Iterator<Item = f64>, whole_decades: bool) -> Option<(f64, f64)> {
        let (lo, hi) = values
            .filter(|v| v.is_finite() && *v > 0.0)
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        if hi <= 0.0 {
            return None;
        }
        if !whole_decades && hi > lo {
            return Some((lo, hi));
        }
        let (a, mut b) = (lo.log10().floor(), hi.log10().ceil());
        if b <= a {
            b = a + 1.0;
        }
        Some((10f64.powf(a), 10f64.powf(b)))
    }

    /// Tick positions on a log x axis: the powers of 1, 2 and 5 in each decade when the range
    /// spans a decade or more (thinned to at most 12); below a decade (a temperature axis,
    /// 1/T of an Arrhenius chart) evenly spaced round values, which a log axis of plotters
    /// would leave unlabelled.
    fn x_ticks((lo, hi): (f64, f64)) -> Vec<f64> {
        if !(lo > 0.0 && hi > lo) {
            return vec![lo];
        }
        if hi / lo >= 10.0 {
            let mut ticks = Vec::new();
            let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
            let decades = (b - a).max(1) as usize;
            let mantissas: &[f64] = if decades <= 3 {
                &[1.0, 2.0, 5.0]
            } else {
                &[1.0]
            };
            let step = decades.div_ceil(12).max(1);
            for k in (a..=b).step_by(step) {
                for m in mantissas {
                    let v = m * 10f64.powi(k);
                    if v >= lo * (1.0 - 1e-12) && v <= hi * (1.0 + 1e-12) {
                        ticks.push(v);
                    }
                }
            }
            return ticks;
        }
        // a round step giving 4–10 ticks
        let raw = (hi - lo) / 6.0;
        let magnitude = 10f64.powf(raw.log10().floor());
        let step = [1.0, 2.0, 2.5, 5.0, 10.0]
            .iter()
            .map(|m| m * magnitude)
            .find(|s| (hi - lo) / s <= 8.0)
            .unwrap_or(10.0 * magnitude);
        let first = (lo / step).ceil() * step;
        (0..)
            .map(|k| first + f64::from(k) * step)
            .take_while(|v| *v <= hi * (1.0 + 1e-12))
            .take(20)
            .collect()
    }

    /// An x label: scientific over a decade or more, plain digits within one.
    fn x_label(v: f64, (lo, hi): (f64, f64)) -> String {
        if hi / lo >= 10.0 {
            format!("{v:.0e}")
        } else {
            let digits = (-(((hi - lo) / 6.0).log10().floor()) as i32).clamp(0, 8) as usize;
            format!("{v:.digits$}")
        }
    }

    /// Series with at most this many points get a marker at each point.
    const MARKED_POINTS: usize = 30;

    /// The corner of the plot (a third of each axis, in log coordinates) holding the fewest points:
    /// where the legend hides the least.
    fn emptiest_corner(points: &[(f64, f64)], x: (f64, f64), y: (f64, f64)) -> SeriesLabelPosition {
        let (x0, x1) = (x.0.log10(), x.1.log10());
        let fraction = |v: f64, lo: f64, hi: f64| if hi > lo { (v - lo) / (hi - lo) } else { 0.5 };
        let count = |left: bool, upper: bool| {
            points
                .iter()
                .filter(|(px, py)| {
                    let fx = fraction(px.log10(), x0, x1);
                    let fy = fraction(py.log10(), y.0, y.1);
                    (if left { fx < 0.4 } else { fx > 0.6 })
                        && (if upper { fy > 0.6 } else { fy < 0.4 })
                })
                .count()
        };
        [
            (SeriesLabelPosition::UpperLeft, count(true, true)),
            (SeriesLabelPosition::UpperRight, count(false, true)),
            (SeriesLabelPosition::LowerRight, count(false, false)),
            (SeriesLabelPosition::LowerLeft, count(true, false)),
        ]
        .into_iter()
        .min_by_key(|(_, n)| *n)
        .map_or(SeriesLabelPosition::UpperLeft, |(p, _)| p)
    }

    impl LogLogChart {
        /// Renders the chart as an SVG document.
        pub fn to_svg(&self) -> Result<String, PlotError> {
            let drawable = |s: &Series| -> Vec<(f64, f64)> {
                s.points
                    .iter()
                    .copied()
                    .filter(|(x, y)| x.is_finite() && y.is_finite() && *x > 0.0 && *y > 0.0)
                    .collect()
            };
            let all: Vec<(f64, f64)> = self.series.iter().flat_map(drawable).collect();
            let x = bounds(all.iter().map(|p| p.0), false)
                .ok_or_else(|| PlotError("no positive x values".into()))?;
            let y = bounds(all.iter().map(|p| p.1), true)
                .ok_or_else(|| PlotError("no positive y values".into()))?;
            let (y_lo, y_hi) = (y.0.log10().round(), y.1.log10().round());
            // one label per decade, or every other/third... when there are many
            let decades = (y_hi - y_lo) as usize;
            let step = decades.div_ceil(12).max(1);
            let y_ticks = decades / step + 1;
            let mut svg = String::new();
            {
                let root = SVGBackend::with_string(&mut svg, (800, 560)).into_drawing_area();
                root.fill(&WHITE).map_err(err)?;
                let mut chart = ChartBuilder::on(&root)
                    .caption(&self.title, ("sans-serif", 20))
                    .margin(16)
                    .x_label_area_size(48)
                    .y_label_area_size(80)
                    // y is drawn as log10(y) on a linear axis: plotters' log-axis labels thin out
                    // over the 20+ decades a leak rate spans.
                    .build_cartesian_2d(
                        (x.0..x.1).log_scale().with_key_points(x_ticks(x)),
                        y_lo..y_hi,
                    )
                    .map_err(err)?;
                chart
                    .configure_mesh()
                    .x_desc(&self.x_label)
                    .y_desc(&self.y_label)
                    .x_labels(8)
                    .y_labels(y_ticks)
                    .x_label_formatter(&|v| x_label(*v, x))
                    .y_label_formatter(&|v| {
                        if (v - v.round()).abs() < 1e-9 {
                            format!("1e{}", v.round())
                        } else {
                            String::new()
                        }
                    })
                    .draw()
                    .map_err(err)?;
                for (i, s) in self.series.iter().enumerate() {
                    let colour = OKABE_ITO[i % OKABE_ITO.len()].to_rgba();
                    let points: Vec<(f64, f64)> = drawable(s)
                        .into_iter()
                        .map(|(x, y)| (x, y.log10()))
                        .collect();
                    // short series are data points (a sweep, a ladder of settings): mark them, so
                    // that a single point is visible too
                    if points.len() <= MARKED_POINTS {
                        chart
                            .draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))
                            .map_err(err)?;
                    }
                    chart
                        .draw_series(LineSeries::new(points, colour.stroke_width(2)))
                        .map_err(err)?
                        .label(s.label.clone())
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                        });
                }
                chart
                    .configure_series_labels()
                    .position(emptiest_corner(&all, x, (y_lo, y_hi)))
                    .background_style(WHITE.mix(0.8))
                    .border_style(BLACK)
                    .draw()
                    .map_err(err)?;
                root.present().map_err(err)?;
            }
            Ok(svg)
        }
    }
}

#[cfg(all(test, feature = "cli"))]
mod tests {
    use super::*;

    #[test]
    fn draws_curves_and_skips_non_positive_points() {
        let chart = LogLogChart {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            series: vec![Series {
                label: "a".into(),
                points: vec![(1.0, 1.0), (10.0, 0.1), (100.0, 0.0)],
            }],
        };
        let svg = chart.to_svg().unwrap();
        assert!(svg.starts_with("<svg") && svg.contains("</svg>"));
        assert!(svg.contains(">\na\n</text>"), "legend label drawn");
        // the zero point is skipped: the curve is a polyline of two vertices
        let curve = svg
            .lines()
            .find(|l| l.contains("stroke-width=\"2\" points="))
            .unwrap();
        assert_eq!(curve.matches(',').count(), 2, "{curve}");
    }

    #[test]
    fn empty_chart_is_an_error_not_a_panic() {
        let chart = LogLogChart {
            title: "t".into(),
            x_label: "x".into(),
            y_label: "y".into(),
            series: vec![],
        };
        assert!(chart.to_svg().is_err());
    }
}
