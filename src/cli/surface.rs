//! `sealsim surface`: what a roughness source gives the contact — a scenario's spectrum, one or
//! more line traces ([`crate::profile`]) or a PSD file — with Ra, Rq, Rz, h_rms, rms slope, the
//! Hurst exponent, the cut-offs and the warnings ([`crate::report::surface`]).

use super::{CliError, positive_flag, write_output};
use crate::numerical::Topography;
use crate::numerical::psd::{PsdOptions, fit_psd, radial_psd_topography};
use crate::profile::{ProfileOptions, analyse, profile_parameters};
use crate::report::surface::SurfaceReport;
use crate::roughness::{Band, DEFAULT_CUTOFF, DEFAULT_SHORT_CUTOFF, ra_from_rq, rz_over_rq};
use crate::scenario::Scenario;
use crate::scenario::profile::read_trace;
use crate::surface::Spectrum;
use crate::units::{Dimension, show};
use crate::validity::MAX_RMS_SLOPE;
use clap::Args;
use std::path::{Path, PathBuf};

/// The fewest samples a trace's cut-off λc may span (ISO 3274 asks for far more: λc/λs = 300
/// at λc = 0.8 mm, with several samples per λs — recalled).
pub const MIN_SAMPLES_PER_CUTOFF: f64 = 10.0;

/// Arguments of `sealsim surface`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "SOURCE: a scenario (.toml: its counterface spectrum as the contact \
    sees it), one or more line traces (CSV with header x,z and an optional units row such as \
    mm,um; several files are averaged), a height map (a Gwyddion Simple Field .gsf file, or a \
    CSV grid of heights — one row per line, no header — when --pixel-size is given), or a PSD \
    file (CSV of q [1/m], C [m^4]).\n\
    Height maps: Ra, Rq, Rz measured on every row as a profile along x (same mean-line rule as \
    traces) and averaged; h_rms and rms slope both from the map and from its radially averaged \
    spectrum; H fitted over the map's trusted band (q0 from the shorter side).\n\
    Traces: Ra, Rq, Rz measured on each trace (mean line: Gaussian filter with the cut-off when \
    the trace holds at least one, else the least-squares line) and averaged; the isotropic 2-D \
    spectrum from the averaged 1-D spectrum over the band the traces can be trusted in \
    (docs/model.md §2).\n\
    Spectra: Rq over the callout band 2π/λc … 2π/λs, Ra = Rq·√(2/π) for Gaussian heights."
)]
pub struct SurfaceArgs {
    /// Scenario, trace(s) or PSD file.
    #[arg(value_name = "SOURCE", required = true)]
    pub sources: Vec<PathBuf>,

    /// Sampling length λc of the profile parameters (e.g. 0.8mm).
    #[arg(long, value_name = "LENGTH")]
    pub cutoff: Option<String>,

    /// Short-wavelength cut-off λs of the profile parameters of a spectrum (e.g. 2.5um).
    #[arg(long, value_name = "LENGTH")]
    pub short_cutoff: Option<String>,

    /// Stylus tip radius of the traces (e.g. 2um): limits the trusted band.
    #[arg(long, value_name = "LENGTH")]
    pub tip_radius: Option<String>,

    /// Pixel size of a CSV height grid (e.g. 0.5um): makes a CSV SOURCE a height map.
    #[arg(long, value_name = "LENGTH")]
    pub pixel_size: Option<String>,

    /// Unit of the heights of a CSV height grid (default m; e.g. um, nm).
    #[arg(long, value_name = "UNIT")]
    pub height_unit: Option<String>,

    /// Write JSON instead of the text summary.
    #[arg(long)]
    pub json: bool,

    /// Write the C(q) chart (SVG) to FILE.
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,

    /// Write the summary to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// A length flag in metres.
fn length(value: Option<&str>, name: &str) -> Result<Option<f64>, CliError> {
    positive_flag(value, name, Dimension::LENGTH)
}

/// Runs `sealsim surface`.
pub fn run(args: SurfaceArgs) -> Result<(), CliError> {
    let sources: Vec<&std::path::Path> = args.sources.iter().map(PathBuf::as_path).collect();
    super::guard_outputs(
        &sources,
        &[
            ("-o", args.output.as_deref()),
            ("--plot", args.plot.as_deref()),
        ],
    )?;
    let cutoff = length(args.cutoff.as_deref(), "cutoff")?;
    let short_cutoff = length(args.short_cutoff.as_deref(), "short-cutoff")?;
    let tip_radius = length(args.tip_radius.as_deref(), "tip-radius")?;
    let (lc, ls) = (
        cutoff.unwrap_or(DEFAULT_CUTOFF),
        short_cutoff.unwrap_or(DEFAULT_SHORT_CUTOFF),
    );
    if ls >= lc {
        return Err(CliError::Input(format!(
            "--short-cutoff ({} m) must be shorter than --cutoff ({} m)",
            show(ls),
            show(lc)
        )));
    }
    let first = &args.sources[0];
    let is_scenario = first.extension().is_some_and(|e| e == "toml");
    let pixel = length(args.pixel_size.as_deref(), "pixel-size")?;
    let is_map = crate::scenario::is_gsf(first) || (pixel.is_some() && !is_scenario);
    if !is_map || crate::scenario::is_gsf(first) {
        for (given, flag) in [
            (args.pixel_size.is_some(), "--pixel-size"),
            (args.height_unit.is_some(), "--height-unit"),
        ] {
            if given {
                return Err(CliError::Input(format!(
                    "{flag} only applies to a CSV height grid (a .gsf file states its own pixel \
                     size and units)"
                )));
            }
        }
    }
    let report = if is_map {
        if args.sources.len() > 1 {
            return Err(CliError::Input("give one height map".into()));
        }
        let unit = match args.height_unit.as_deref() {
            None => 1.0,
            Some(text) => match crate::units::parse_unit(text.trim()) {
                Ok((factor, dimension)) if dimension == Dimension::LENGTH => factor,
                _ => {
                    return Err(CliError::Input(format!(
                        "--height-unit: expected a length unit such as m, um or nm, got {text:?}"
                    )));
                }
            },
        };
        let map = crate::scenario::read_height_map(first, pixel, unit)
            .map_err(|e| CliError::Input(e.to_string()))?;
        map_report(first, &map, cutoff)?
    } else if is_scenario {
        if args.sources.len() > 1 {
            return Err(CliError::Input(
                "give one scenario (several files are for traces)".into(),
            ));
        }
        let scenario = Scenario::load(first)?;
        spectrum_report(
            first.display().to_string(),
            "scenario",
            &scenario.problem.spectrum,
            (lc, ls),
        )
    } else if is_trace(first)? {
        traces_report(&args.sources, cutoff, tip_radius)?
    } else {
        if args.sources.len() > 1 {
            return Err(CliError::Input("give one PSD file".into()));
        }
        let spectrum =
            crate::scenario::read_psd_file(first).map_err(|e| CliError::Input(e.to_string()))?;
        spectrum_report(first.display().to_string(), "psd file", &spectrum, (lc, ls))
    };
    let main = if args.json {
        report.json()?
    } else {
        report.text()
    };
    let svg = args
        .plot
        .as_ref()
        .map(|_| {
            report
                .chart()
                .to_svg()
                .map_err(|e| CliError::Internal(e.to_string()))
        })
        .transpose()?;
    if let (Some(path), Some(svg)) = (&args.plot, &svg) {
        write_output(Some(path), svg.as_bytes())?;
    }
    write_output(args.output.as_deref(), main.as_bytes())
}

/// Whether a CSV file's header names `x,z` (a trace) rather than `q,C` (a PSD file).
fn is_trace(path: &Path) -> Result<bool, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read the file: {e}", path.display())))?;
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
fn spectrum_report(
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

/// The report of line traces: profile parameters measured on each (averaged), the 2-D
/// spectrum over the trusted band and its power-law fit.
fn traces_report(
    paths: &[PathBuf],
    cutoff: Option<f64>,
    tip_radius: Option<f64>,
) -> Result<SurfaceReport, CliError> {
    let traces = paths
        .iter()
        .map(|p| read_trace(p).map_err(|e| CliError::Input(e.to_string())))
        .collect::<Result<Vec<_>, _>>()?;
    // a cut-off must span many samples: the Gaussian filter over a few samples is no filter
    if let Some(lc) = cutoff {
        for (path, trace) in paths.iter().zip(&traces) {
            if lc < MIN_SAMPLES_PER_CUTOFF * trace.spacing {
                return Err(CliError::Input(format!(
                    "--cutoff: {} mm is shorter than {MIN_SAMPLES_PER_CUTOFF} samples of {} \
                     (spacing {} µm): the mean line cannot be resolved",
                    show(lc * 1e3),
                    path.display(),
                    show(trace.spacing * 1e6)
                )));
            }
        }
    }
    // the Gaussian mean line needs at least one sampling length in the trace
    let shortest = traces
        .iter()
        .map(crate::profile::Trace::length)
        .fold(f64::INFINITY, f64::min);
    let lc = cutoff.unwrap_or(DEFAULT_CUTOFF);
    let options = ProfileOptions {
        tip_radius,
        cutoff: (shortest >= 2.0 * lc).then_some(lc),
        ..ProfileOptions::default()
    };
    let source = paths
        .iter()
        .map(|p| p.display().to_string())
        .collect::<Vec<_>>()
        .join(", ");
    let result =
        analyse(&traces, &options).map_err(|e| CliError::Input(format!("{source}: {e}")))?;
    let n = result.parameters.len().max(1) as f64;
    let mean = |f: &dyn Fn(&crate::profile::ProfileParameters) -> f64| {
        result.parameters.iter().map(f).sum::<f64>() / n
    };
    let rz: Vec<f64> = result.parameters.iter().filter_map(|p| p.rz).collect();
    let mut warnings = Vec::new();
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
fn map_report(
    path: &Path,
    map: &Topography,
    cutoff: Option<f64>,
) -> Result<SurfaceReport, CliError> {
    let source = path.display().to_string();
    let input = |e: String| CliError::Input(format!("{source}: {e}"));
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
        let trace = crate::profile::Trace {
            spacing: map.pixel,
            heights: map.heights[iy * map.nx..(iy + 1) * map.nx].to_vec(),
        };
        rows.push(profile_parameters(&trace, row_cutoff).map_err(|e| input(e.to_string()))?);
    }
    let n = rows.len() as f64;
    let rz: Vec<f64> = rows.iter().filter_map(|p| p.rz).collect();
    let mut warnings = Vec::new();
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
