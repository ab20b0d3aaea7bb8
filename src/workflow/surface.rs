//! `sealsim surface` as a library call: what a roughness source gives the contact — a
//! scenario's spectrum, one or more line traces ([`crate::profile`]), a height map or a PSD
//! file — with Ra, Rq, Rz, h_rms, rms slope, the Hurst exponent, the cut-offs and the warnings
//! ([`SurfaceReport`]; its text, JSON and chart are `report::surface`'s). The command line
//! parses the flags into [`SurfaceOptions`] (SI), calls these, renders and writes.

use crate::numerical::Topography;
use crate::numerical::psd::{PsdOptions, fit_psd, radial_psd_topography};
use crate::plausibility::HeightStatistics;
use crate::profile::{ProfileOptions, Trace, analyse, profile_parameters};
use crate::roughness::{Band, DEFAULT_CUTOFF, DEFAULT_SHORT_CUTOFF, ra_from_rq, rz_over_rq};
use crate::scenario::profile::read_trace;
use crate::scenario::{Scenario, ScenarioError};
use crate::surface::Spectrum;
use crate::units::show;
use crate::validity::MAX_RMS_SLOPE;
use std::fmt;
use std::path::{Path, PathBuf};

/// The fewest samples a trace's cut-off λc may span (ISO 3274 asks for far more: λc/λs = 300
/// at λc = 0.8 mm, with several samples per λs — recalled).
pub const MIN_SAMPLES_PER_CUTOFF: f64 = 10.0;

/// Everything `sealsim surface` reports; SI units (m, 1/m, m⁴).
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceReport {
    /// The source as given (file name(s)).
    pub source: String,
    /// What the source is: `trace`, `traces`, `scenario`, `psd file`, `height map`.
    pub kind: String,
    /// Ra, Rq, Rz \[m\] and how they were obtained (measured on traces, or from the spectrum
    /// over the callout band for Gaussian heights).
    pub ra: f64,
    pub rq: f64,
    pub rz: Option<f64>,
    pub parameters_basis: String,
    /// rms roughness \[m\] and rms slope of the spectrum over `band`.
    pub h_rms: f64,
    pub rms_slope: f64,
    /// The band of q the figures above cover \[1/m\] (for traces: the trusted band).
    pub band: (f64, f64),
    /// Hurst exponent with its 95 % interval when it was fitted.
    pub hurst: Option<(f64, Option<(f64, f64)>)>,
    /// The band of q the Hurst exponent was fitted over \[1/m\], when it is not `band`
    /// (height maps).
    pub fit_band: Option<(f64, f64)>,
    /// For a height map: its rms height about its mean (or best-fit plane) \[m\] and its rms
    /// slope from finite differences, measured on the map directly (beside the spectrum's).
    pub map_figures: Option<(f64, f64)>,
    /// Lower and upper cut-off of the spectrum \[1/m\].
    pub q0: f64,
    pub q1: f64,
    /// Roll-off wavevector \[1/m\], when there is one.
    pub rolloff: Option<f64>,
    /// Warnings: validity of the small-slope theory, the band, the data.
    pub warnings: Vec<String>,
    /// The spectrum to plot: (q, C) points.
    pub spectrum_points: Vec<(f64, f64)>,
    /// The fitted or given law over its range: (q, C) points.
    pub law_points: Vec<(f64, f64)>,
}

/// The options of a summary, SI (m); `None`: not given (the cut-offs then take
/// [`DEFAULT_CUTOFF`] and [`DEFAULT_SHORT_CUTOFF`]).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SurfaceOptions {
    /// Sampling length λc of the profile parameters \[m\].
    pub cutoff: Option<f64>,
    /// Short-wavelength cut-off λs of the profile parameters of a spectrum \[m\].
    pub short_cutoff: Option<f64>,
    /// Stylus tip radius of traces \[m\]: limits the trusted band.
    pub tip_radius: Option<f64>,
    /// Pixel size of a CSV height grid \[m\]: makes a CSV source a height map.
    pub pixel_size: Option<f64>,
    /// Metres per unit of the heights of a CSV height grid (`None`: 1, metres).
    pub height_unit: Option<f64>,
}

/// Why a source could not be summarised. The messages name the command line's flags
/// (`--cutoff`, …), as `sealsim surface` prints them.
#[derive(Debug)]
pub enum SurfaceError {
    /// A source, option or combination the user must fix.
    Input(String),
    /// The scenario given as the source is invalid.
    Scenario(ScenarioError),
}

impl fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SurfaceError::Input(m) => f.write_str(m),
            SurfaceError::Scenario(e) => e.fmt(f),
        }
    }
}

impl std::error::Error for SurfaceError {}

impl From<ScenarioError> for SurfaceError {
    fn from(e: ScenarioError) -> Self {
        SurfaceError::Scenario(e)
    }
}

fn input(message: impl Into<String>) -> SurfaceError {
    SurfaceError::Input(message.into())
}

/// What the sources are.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SourceKind {
    /// A height map: a `.gsf` file, or a CSV grid with a pixel size.
    Map,
    /// A scenario (`.toml`): its counterface spectrum as the contact sees it.
    Scenario,
    /// Line traces (CSV with the header `x,z`).
    Traces,
    /// A PSD file (CSV of q, C).
    Psd,
}

/// The callout band's cut-offs (λc, λs) \[m\] of `options`, defaults filled in; λs must be
/// shorter than λc.
pub fn callout(options: &SurfaceOptions) -> Result<(f64, f64), SurfaceError> {
    let (lc, ls) = (
        options.cutoff.unwrap_or(DEFAULT_CUTOFF),
        options.short_cutoff.unwrap_or(DEFAULT_SHORT_CUTOFF),
    );
    if ls >= lc {
        return Err(input(format!(
            "--short-cutoff ({} m) must be shorter than --cutoff ({} m)",
            show(ls),
            show(lc)
        )));
    }
    Ok((lc, ls))
}

/// What `sources` are (by the first's extension and header, and whether a pixel size was
/// given), with the checks of their number and of the height-map options
/// (`pixel_size`/`height_unit`: whether those were given).
pub fn classify(
    sources: &[PathBuf],
    pixel_size: bool,
    height_unit: bool,
) -> Result<SourceKind, SurfaceError> {
    let Some(first) = sources.first() else {
        return Err(input(
            "give a source: a scenario, trace(s), a height map or a PSD file",
        ));
    };
    let is_scenario = first.extension().is_some_and(|e| e == "toml");
    let is_gsf = crate::scenario::is_gsf(first);
    let is_map = is_gsf || (pixel_size && !is_scenario);
    if !is_map || is_gsf {
        for (given, flag) in [(pixel_size, "--pixel-size"), (height_unit, "--height-unit")] {
            if given {
                return Err(input(format!(
                    "{flag} only applies to a CSV height grid (a .gsf file states its own pixel \
                     size and units)"
                )));
            }
        }
    }
    if is_map {
        if sources.len() > 1 {
            return Err(input("give one height map"));
        }
        Ok(SourceKind::Map)
    } else if is_scenario {
        if sources.len() > 1 {
            return Err(input("give one scenario (several files are for traces)"));
        }
        Ok(SourceKind::Scenario)
    } else if is_trace(first)? {
        Ok(SourceKind::Traces)
    } else {
        if sources.len() > 1 {
            return Err(input("give one PSD file"));
        }
        Ok(SourceKind::Psd)
    }
}

/// The summary of `sources` (`sealsim surface SOURCE…`): [`callout`], [`classify`], then
/// [`summarise`].
pub fn summary(
    sources: &[PathBuf],
    options: &SurfaceOptions,
) -> Result<SurfaceReport, SurfaceError> {
    callout(options)?;
    let kind = classify(
        sources,
        options.pixel_size.is_some(),
        options.height_unit.is_some(),
    )?;
    summarise(sources, kind, options)
}

/// The summary of `sources` of `kind` ([`classify`]), read and measured.
pub fn summarise(
    sources: &[PathBuf],
    kind: SourceKind,
    options: &SurfaceOptions,
) -> Result<SurfaceReport, SurfaceError> {
    let band = callout(options)?;
    let Some(first) = sources.first() else {
        return Err(input(
            "give a source: a scenario, trace(s), a height map or a PSD file",
        ));
    };
    match kind {
        SourceKind::Map => {
            let map = crate::scenario::read_height_map(
                first,
                options.pixel_size,
                options.height_unit.unwrap_or(1.0),
            )
            .map_err(|e| input(e.to_string()))?;
            map_report(first.display().to_string(), &map, options.cutoff)
        }
        SourceKind::Scenario => {
            let scenario = Scenario::load(first)?;
            Ok(spectrum_report(
                first.display().to_string(),
                "scenario",
                &scenario.problem.spectrum,
                band,
            ))
        }
        SourceKind::Traces => {
            let traces = sources
                .iter()
                .map(|p| {
                    read_trace(p)
                        .map(|t| (p.display().to_string(), t))
                        .map_err(|e| input(e.to_string()))
                })
                .collect::<Result<Vec<_>, _>>()?;
            traces_report(&traces, options.cutoff, options.tip_radius)
        }
        SourceKind::Psd => {
            let spectrum =
                crate::scenario::read_psd_file(first).map_err(|e| input(e.to_string()))?;
            Ok(spectrum_report(
                first.display().to_string(),
                "psd file",
                &spectrum,
                band,
            ))
        }
    }
}

/// Whether a CSV file's header names `x,z` (a trace) rather than `q,C` (a PSD file).
fn is_trace(path: &Path) -> Result<bool, SurfaceError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| input(format!("{}: cannot read the file: {e}", path.display())))?;
    let header = text
        .lines()
        .map(str::trim)
        .find(|l| !l.is_empty() && !l.starts_with('#'))
        .unwrap_or("");
    let cells: Vec<String> = header
        .split(',')
        .map(|c| c.trim().trim_matches('"').to_lowercase())
        .collect();
    Ok(cells.first().is_some_and(|c| c == "x"))
}

/// The report of a spectrum (a scenario's or a PSD file's): Rq over the callout band
/// `2π/λc … 2π/λs` (clipped to the spectrum), Ra = Rq √(2/π) for Gaussian heights.
pub fn spectrum_report(
    source: String,
    kind: &str,
    spectrum: &Spectrum,
    (lc, ls): (f64, f64),
) -> SurfaceReport {
    let (q0, q1) = (spectrum.q0(), spectrum.q1());
    let mut warnings = Vec::new();
    let band = Band {
        cutoff: lc,
        short_cutoff: ls,
    };
    let rq = band.rms(spectrum);
    if q0 > band.q_lo() || q1 < band.q_hi() {
        warnings.push(format!(
            "the spectrum covers only q = {} … {} 1/m of the callout band {} … {} 1/m: Ra, Rq \
             and Rz miss the rest",
            show(q0),
            show(q1),
            show(band.q_lo()),
            show(band.q_hi())
        ));
    }
    let slope = spectrum.rms_slope();
    if slope > MAX_RMS_SLOPE {
        warnings.push(format!(
            "rms slope {slope:.3} is above {MAX_RMS_SLOPE}: the small-slope contact theory is \
             stretched [docs/model.md §9.8]"
        ));
    }
    let points: Vec<(f64, f64)> = crate::math::log_spaced(q0, q1, 200)
        .into_iter()
        .map(|q| (q, spectrum.c(q)))
        .collect();
    SurfaceReport {
        source,
        kind: kind.into(),
        ra: ra_from_rq(rq),
        rq,
        rz: Some(rq * rz_over_rq(lc, ls)),
        parameters_basis: format!(
            "from the spectrum over the callout band λc = {} mm, λs = {} µm for Gaussian heights: \
             Ra = Rq·√(2/π), Rz = {:.2} Rq (docs/model.md §2.1)",
            show(lc * 1e3),
            show(ls * 1e6),
            rz_over_rq(lc, ls)
        ),
        h_rms: spectrum.rms_roughness(),
        rms_slope: slope,
        band: (q0, q1),
        hurst: spectrum.hurst_exponent().map(|h| (h, None)),
        fit_band: None,
        map_figures: None,
        q0,
        q1,
        rolloff: None,
        warnings,
        spectrum_points: points,
        law_points: Vec::new(),
    }
}

/// The report of line traces, each with its name (its file): profile parameters measured on
/// each (averaged), the 2-D spectrum over the trusted band and its power-law fit.
pub fn traces_report(
    named: &[(String, Trace)],
    cutoff: Option<f64>,
    tip_radius: Option<f64>,
) -> Result<SurfaceReport, SurfaceError> {
    let traces: Vec<Trace> = named.iter().map(|(_, t)| t.clone()).collect();
    // a cut-off must span many samples: the Gaussian filter over a few samples is no filter
    if let Some(lc) = cutoff {
        for (name, trace) in named {
            if lc < MIN_SAMPLES_PER_CUTOFF * trace.spacing {
                return Err(input(format!(
                    "--cutoff: {} mm is shorter than {MIN_SAMPLES_PER_CUTOFF} samples of {} \
                     (spacing {} µm): the mean line cannot be resolved",
                    show(lc * 1e3),
                    name,
                    show(trace.spacing * 1e6)
                )));
            }
        }
    }
    // the Gaussian mean line needs at least one sampling length in the trace
    let shortest = traces
        .iter()
        .map(Trace::length)
        .fold(f64::INFINITY, f64::min);
    let lc = cutoff.unwrap_or(DEFAULT_CUTOFF);
    let options = ProfileOptions {
        tip_radius,
        cutoff: (shortest >= 2.0 * lc).then_some(lc),
        ..ProfileOptions::default()
    };
    let source = named
        .iter()
        .map(|(name, _)| name.as_str())
        .collect::<Vec<_>>()
        .join(", ");
    let result = analyse(&traces, &options).map_err(|e| input(format!("{source}: {e}")))?;
    let n = result.parameters.len().max(1) as f64;
    let mean = |f: &dyn Fn(&crate::profile::ProfileParameters) -> f64| {
        result.parameters.iter().map(f).sum::<f64>() / n
    };
    let rz: Vec<f64> = result.parameters.iter().filter_map(|p| p.rz).collect();
    let mut warnings = Vec::new();
    // heights in µm under a units row of m still make a spectrum (docs/model.md §2.4)
    for (name, trace) in named {
        let stats = HeightStatistics::of_trace(trace.spacing, &trace.heights);
        if let Some((text, _)) = stats.warning(None) {
            warnings.push(format!("{name}: {text} [docs/model.md §2.4]"));
        }
    }
    if options.cutoff.is_none() {
        warnings.push(format!(
            "the traces ({} mm) are shorter than two sampling lengths of {} mm: Ra, Rq, Rz are \
             taken about the least-squares line over five equal parts, not per ISO 21920",
            show(shortest * 1e3),
            show(lc * 1e3)
        ));
    }
    if result.rms_slope > MAX_RMS_SLOPE {
        warnings.push(format!(
            "rms slope {:.3} is above {MAX_RMS_SLOPE}: the small-slope contact theory is \
             stretched [docs/model.md §9.8]",
            result.rms_slope
        ));
    }
    if result.replaced_points > 0 {
        warnings.push(format!(
            "{} points of the 2-D spectrum came out ≤ 0 from the noisy 1-D spectrum and were \
             replaced by the local power law",
            result.replaced_points
        ));
    }
    let (h, interval) = result.hurst;
    let (lo, hi) = result.band;
    let spectrum_points: Vec<(f64, f64)> = result
        .psd_1d
        .q
        .iter()
        .filter(|q| **q >= lo && **q <= hi)
        .map(|&q| (q, result.spectrum.c(q)))
        .collect();
    // the fitted power law, drawn through the spectrum at the band's geometric middle
    let mid = (lo * hi).sqrt();
    let c_mid = result.spectrum.c(mid);
    let law_points: Vec<(f64, f64)> = crate::math::log_spaced(lo, hi, 50)
        .into_iter()
        .map(|q| {
            let q_eff = result.q0.map_or(q, |r| q.max(r));
            (q, c_mid * (q_eff / mid).powf(-2.0 * (1.0 + h)))
        })
        .collect();
    Ok(SurfaceReport {
        source,
        kind: if traces.len() == 1 { "trace" } else { "traces" }.into(),
        ra: mean(&|p| p.ra),
        rq: mean(&|p| p.rq),
        rz: (!rz.is_empty()).then(|| rz.iter().sum::<f64>() / rz.len() as f64),
        parameters_basis: format!("measured on {} trace(s), averaged", traces.len()),
        h_rms: result.h_rms,
        rms_slope: result.rms_slope,
        band: result.band,
        hurst: Some((h, Some(interval))),
        fit_band: None,
        map_figures: None,
        q0: lo,
        q1: hi,
        rolloff: result.q0,
        warnings,
        spectrum_points,
        law_points,
    })
}

/// The report of a height map (module docs of [`crate::numerical::psd`] for the spectrum):
/// Ra, Rq, Rz on every row as a profile along x ([`crate::profile::profile_parameters`]:
/// Gaussian mean line of cut-off λc when a row holds two, else the least-squares line), averaged
/// over the rows; h_rms and rms slope from the map and from its spectrum; H fitted over the
/// trusted band ([`crate::numerical::psd::fit_psd`]).
pub fn map_report(
    source: String,
    map: &Topography,
    cutoff: Option<f64>,
) -> Result<SurfaceReport, SurfaceError> {
    let input = |e: String| input(format!("{source}: {e}"));
    let psd =
        radial_psd_topography(map, &PsdOptions::default()).map_err(|e| input(e.to_string()))?;
    let spectrum = psd.spectrum().map_err(|e| input(e.to_string()))?;
    let lc = cutoff.unwrap_or(DEFAULT_CUTOFF);
    let row_length = map.nx as f64 * map.pixel;
    let row_cutoff = (row_length >= 2.0 * lc).then_some(lc);
    if map.nx < 10 {
        return Err(input(format!(
            "{} pixels per row: Ra, Rq, Rz need rows of at least 10",
            map.nx
        )));
    }
    let mut rows = Vec::with_capacity(map.ny);
    for iy in 0..map.ny {
        let trace = Trace {
            spacing: map.pixel,
            heights: map.heights[iy * map.nx..(iy + 1) * map.nx].to_vec(),
        };
        rows.push(profile_parameters(&trace, row_cutoff).map_err(|e| input(e.to_string()))?);
    }
    let n = rows.len() as f64;
    let rz: Vec<f64> = rows.iter().filter_map(|p| p.rz).collect();
    let mut warnings = Vec::new();
    // heights in µm read as m still make a spectrum (docs/model.md §2.4)
    let stats = HeightStatistics::of_map(map.nx, map.ny, map.pixel, &map.heights);
    if let Some((text, _)) = stats.warning(None) {
        warnings.push(format!("{source}: {text} [docs/model.md §2.4]"));
    }
    if row_cutoff.is_none() {
        warnings.push(format!(
            "the rows ({} mm) are shorter than two sampling lengths of {} mm: Ra, Rq, Rz are \
             taken about the least-squares line over five equal parts, not per ISO 21920",
            show(row_length * 1e3),
            show(lc * 1e3)
        ));
    }
    let map_slope = map.rms_slope();
    let slope = spectrum.rms_slope();
    for (what, s) in [("of the spectrum", slope), ("of the map", map_slope)] {
        if s > MAX_RMS_SLOPE {
            warnings.push(format!(
                "rms slope {what} {s:.3} is above {MAX_RMS_SLOPE}: the small-slope contact \
                 theory is stretched [docs/model.md §9.8]"
            ));
        }
    }
    if map.nx != map.ny {
        warnings.push(format!(
            "the map is {} × {} pixels: q0 of the trusted band is 2π over the shorter side; \
             the bins below it hold modes along the longer side only",
            map.nx, map.ny
        ));
    }
    let fit = fit_psd(&psd);
    if fit.is_none() {
        warnings.push(
            "too few spectrum bins in the trusted band to fit a Hurst exponent (the map is too \
             small)"
                .into(),
        );
    }
    let spectrum_points: Vec<(f64, f64)> = psd.q.iter().map(|&q| (q, spectrum.c(q))).collect();
    let law_points = fit.map_or_else(Vec::new, |f| {
        let (lo, hi) = f.band;
        let mid = (lo * hi).sqrt();
        let c_mid = spectrum.c(mid);
        crate::math::log_spaced(lo, hi, 50)
            .into_iter()
            .map(|q| (q, c_mid * (q / mid).powf(-2.0 * (1.0 + f.hurst))))
            .collect()
    });
    Ok(SurfaceReport {
        source,
        kind: "height map".into(),
        ra: rows.iter().map(|p| p.ra).sum::<f64>() / n,
        rq: rows.iter().map(|p| p.rq).sum::<f64>() / n,
        rz: (!rz.is_empty()).then(|| rz.iter().sum::<f64>() / rz.len() as f64),
        parameters_basis: format!(
            "measured on the {} rows as profiles along x, averaged",
            map.ny
        ),
        h_rms: spectrum.rms_roughness(),
        rms_slope: slope,
        band: (spectrum.q0(), spectrum.q1()),
        hurst: fit.map(|f| (f.hurst, Some(f.interval))),
        fit_band: fit.map(|f| f.band),
        map_figures: Some((psd.rms, map_slope)),
        q0: psd.q0,
        q1: psd.q_high,
        rolloff: None,
        warnings,
        spectrum_points,
        law_points,
    })
}
