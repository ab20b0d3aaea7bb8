//! Log–log line charts of one quantity against another, rendered as SVG (plotters) with the
//! `cli` feature; every chart of the command line written as SVG, PNG or PDF by its file's
//! extension ([`PlotFormat`], [`encode`]).

use std::fmt;
use std::path::Path;

/// The extensions a chart can be written as, the first the one drawn ([`PlotFormat`]).
pub const PLOT_EXTENSIONS: [&str; 3] = ["svg", "png", "pdf"];

/// The file format of a chart, chosen by its output's extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlotFormat {
    /// The drawing itself (plotters' SVG): vector, text as text.
    Svg,
    /// A bitmap at [`PNG_SCALE`] pixels per SVG pixel (resvg), text in the embedded font.
    Png,
    /// One vector page the size of the chart (svg2pdf), text in the embedded font.
    Pdf,
}

/// Pixels of a PNG per pixel of the SVG drawing: 2, so an 800 × 560 chart is 1600 × 1120 and
/// stays sharp on a printed A4 page at its width (about 190 dpi).
pub const PNG_SCALE: f32 = 2.0;

impl PlotFormat {
    /// The format `path` names by its extension (any case); SVG without one (a device such as
    /// `/dev/stdout`, a pipe) or with another (the command line refuses those before it runs:
    /// `cli::expect_extension` with [`PLOT_EXTENSIONS`]).
    pub fn of(path: &Path) -> PlotFormat {
        match path.extension().and_then(std::ffi::OsStr::to_str) {
            Some(e) if e.eq_ignore_ascii_case("png") => PlotFormat::Png,
            Some(e) if e.eq_ignore_ascii_case("pdf") => PlotFormat::Pdf,
            _ => PlotFormat::Svg,
        }
    }
}

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

/// `svg` (a chart drawn by plotters) as the bytes of `format`: the text itself for SVG; for PNG
/// and PDF parsed by usvg with DejaVu Sans as every family (embedded in the binary: no system
/// font is read, so the output is the same on every machine), then rasterised by resvg
/// ([`PNG_SCALE`]) or converted by svg2pdf (one page of the drawing's size at 72 dpi: 800 SVG
/// pixels are 800 pt, 282 mm).
#[cfg(feature = "cli")]
pub fn encode(svg: &str, format: PlotFormat) -> Result<Vec<u8>, PlotError> {
    use resvg::{tiny_skia, usvg};
    if format == PlotFormat::Svg {
        return Ok(svg.as_bytes().to_vec());
    }
    let mut options = usvg::Options {
        font_family: "DejaVu Sans".to_owned(),
        ..usvg::Options::default()
    };
    {
        let fonts = options.fontdb_mut();
        for face in [
            dejavu::sans::regular(),
            dejavu::sans::bold(),
            dejavu::sans::oblique(),
        ] {
            fonts.load_font_source(usvg::fontdb::Source::Binary(std::sync::Arc::new(face)));
        }
        // plotters writes `font-family="sans-serif"` (and a caller may name serif/monospace)
        fonts.set_sans_serif_family("DejaVu Sans");
        fonts.set_serif_family("DejaVu Sans");
        fonts.set_monospace_family("DejaVu Sans");
    }
    let tree = usvg::Tree::from_str(svg, &options)
        .map_err(|e| PlotError(format!("the chart's SVG could not be read: {e}")))?;
    match format {
        PlotFormat::Svg => Ok(svg.as_bytes().to_vec()),
        PlotFormat::Png => {
            let size = tree
                .size()
                .to_int_size()
                .scale_by(PNG_SCALE)
                .ok_or_else(|| PlotError("the chart is too large to draw as a PNG".to_owned()))?;
            let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
                .ok_or_else(|| PlotError("the chart has no area to draw".to_owned()))?;
            resvg::render(
                &tree,
                tiny_skia::Transform::from_scale(PNG_SCALE, PNG_SCALE),
                &mut pixmap.as_mut(),
            );
            pixmap
                .encode_png()
                .map_err(|e| PlotError(format!("PNG encoding failed: {e}")))
        }
        PlotFormat::Pdf => svg2pdf::to_pdf(
            &tree,
            svg2pdf::ConversionOptions::default(),
            svg2pdf::PageOptions::default(),
        )
        .map_err(|e| PlotError(format!("PDF conversion failed: {e}"))),
    }
}

/// [`encode`] in the format `path` names ([`PlotFormat::of`]).
#[cfg(feature = "cli")]
pub fn encode_for(path: &Path, svg: &str) -> Result<Vec<u8>, PlotError> {
    encode(svg, PlotFormat::of(path))
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

    fn chart(title: &str, label: &str) -> LogLogChart {
        LogLogChart {
            title: title.into(),
            x_label: label.into(),
            y_label: label.into(),
            series: vec![Series {
                label: label.into(),
                points: vec![(1.0, 1.0), (10.0, 0.1), (100.0, 3.0)],
            }],
        }
    }

    /// The dark pixels of a PNG (any channel below half): ink, whether lines or glyphs; 0 for
    /// bytes that do not decode (which the tests' ink bounds then refuse).
    fn dark_pixels(png: &[u8]) -> usize {
        let Ok(pixmap) = resvg::tiny_skia::Pixmap::decode_png(png) else {
            return 0;
        };
        pixmap
            .pixels()
            .iter()
            .filter(|p| p.alpha() > 0 && (p.red() < 128 || p.green() < 128 || p.blue() < 128))
            .count()
    }

    #[test]
    fn formats_follow_the_extension_in_any_case() {
        for (name, format) in [
            ("a.svg", PlotFormat::Svg),
            ("a.PNG", PlotFormat::Png),
            ("dir.x/a.pdf", PlotFormat::Pdf),
            ("/dev/stdout", PlotFormat::Svg),
        ] {
            assert_eq!(PlotFormat::of(Path::new(name)), format, "{name}");
        }
    }

    /// A PNG is a PNG of the chart's size × [`PNG_SCALE`], and its text is drawn: the same chart
    /// with long labels has more ink than with one-letter ones (a missing font draws no glyphs,
    /// and both would have the same).
    #[test]
    fn a_png_is_a_bitmap_of_the_chart_with_its_text() {
        let short = encode(&chart("t", "a").to_svg().unwrap(), PlotFormat::Png).unwrap();
        assert!(short.starts_with(b"\x89PNG\r\n\x1a\n"));
        let pixmap = resvg::tiny_skia::Pixmap::decode_png(&short).unwrap();
        assert_eq!((pixmap.width(), pixmap.height()), (1600, 1120));
        let words = "leak rate through the interface and the rubber";
        let long = encode(&chart(words, words).to_svg().unwrap(), PlotFormat::Png).unwrap();
        let (ink_short, ink_long) = (dark_pixels(&short), dark_pixels(&long));
        assert!(ink_short > 1000, "axes and curve drawn: {ink_short}");
        // four labels of 46 glyphs at 2 × 13–20 px: thousands of dark pixels more
        assert!(ink_long > ink_short + 5000, "{ink_long} vs {ink_short}");
    }

    /// A PDF is one page of the chart's size (800 × 560 pt) with its text embedded as a font.
    #[test]
    fn a_pdf_is_one_page_with_an_embedded_font() {
        let pdf = encode(&chart("t", "a").to_svg().unwrap(), PlotFormat::Pdf).unwrap();
        assert!(pdf.starts_with(b"%PDF-"));
        let text = String::from_utf8_lossy(&pdf);
        assert!(text.contains("/MediaBox [0 0 800 560]"), "page size");
        assert!(text.contains("DejaVu"), "the embedded font is named");
        assert!(text.trim_end().ends_with("%%EOF"));
    }

    #[test]
    fn an_svg_is_the_drawing_itself() {
        let svg = chart("t", "a").to_svg().unwrap();
        assert_eq!(encode(&svg, PlotFormat::Svg).unwrap(), svg.as_bytes());
    }
}
