//! `sealsim surface`: the flags parsed into the options of the workflow
//! ([`crate::workflow::surface`]: what a roughness source gives the contact), its summary
//! rendered ([`crate::report::surface`]: text, JSON, the C(q) chart) and written.

use super::{CliError, positive_flag, write_output};
use crate::units::Dimension;
use crate::workflow::surface::{
    SourceKind, SurfaceError, SurfaceOptions, callout, classify, summarise,
};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `sealsim surface`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "SOURCE: a scenario (.toml: its counterface spectrum as the contact \
    sees it), one or more line traces (CSV with header x,z and a units row such as \
    mm,um, required; several files are averaged), a height map (a Gwyddion Simple Field .gsf file, or a \
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

    /// Write the C(q) chart (SVG, PNG or PDF) to FILE.
    #[arg(long, value_name = "FILE.svg|png|pdf")]
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
    let mut options = SurfaceOptions {
        cutoff: length(args.cutoff.as_deref(), "cutoff")?,
        short_cutoff: length(args.short_cutoff.as_deref(), "short-cutoff")?,
        tip_radius: length(args.tip_radius.as_deref(), "tip-radius")?,
        ..SurfaceOptions::default()
    };
    callout(&options)?;
    options.pixel_size = length(args.pixel_size.as_deref(), "pixel-size")?;
    let kind = classify(
        &args.sources,
        options.pixel_size.is_some(),
        args.height_unit.is_some(),
    )?;
    if kind == SourceKind::Map {
        options.height_unit = args
            .height_unit
            .as_deref()
            .map(|text| match crate::units::parse_unit(text.trim()) {
                Ok((factor, dimension)) if dimension == Dimension::LENGTH => Ok(factor),
                _ => Err(CliError::Input(format!(
                    "--height-unit: expected a length unit such as m, um or nm, got {text:?}"
                ))),
            })
            .transpose()?;
    }
    let report = summarise(&args.sources, kind, &options)?;
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
    if let (Some(path), Some(plot)) = (
        &args.plot,
        super::plot_file(args.plot.as_deref(), svg.as_deref())?,
    ) {
        write_output(Some(path), &plot)?;
    }
    write_output(args.output.as_deref(), main.as_bytes())
}

impl From<SurfaceError> for CliError {
    fn from(e: SurfaceError) -> Self {
        match e {
            SurfaceError::Input(m) => CliError::Input(m),
            SurfaceError::Scenario(e) => CliError::Scenario(e),
        }
    }
}
