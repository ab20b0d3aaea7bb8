//! `sealsim ageing-fit`: lifetime from accelerated-ageing data by ISO 11346
//! ([`crate::material::ageing_fit`]), reported by [`crate::report::ageing_fit`].

use super::{CliError, write_output};
use crate::material::ageing_fit::{
    AgeingKind, Crossing, ageing_constants, fit_arrhenius, resolve_kind, time_to_criterion,
};
use crate::report::ageing_fit::AgeingFitReport;
use crate::report::material_toml::ageing_toml;
use crate::scenario::ageing_data::read_ageing_data;
use crate::units::parse_temperature;
use clap::{Args, ValueEnum};
use std::path::PathBuf;

/// Arguments of `sealsim ageing-fit`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "Data file (CSV, '#' comments allowed): header temperature,time,value, \
    then a units row, e.g. C,h,1 (value a fraction 1 or %).\n\
    Time to criterion per temperature: linear interpolation in ln t between the bracketing \
    points; at least 3 temperatures must reach the criterion.\n\
    Fit: ln t = ln A + Ea/(R T), least squares; Ea with its 95 % confidence interval \
    (Student t); the life at the service temperature with the 95 % confidence interval of the \
    regression line (and the wider prediction interval).\n\
    --write-material-ageing: k_ref from the life at the reference temperature by the \
    two-network model: CS = 1 - exp(-k t) -> k = -ln(1 - c)/t*; F/F0 = exp(-k t) -> \
    k = -ln(c)/t*."
)]
pub struct AgeingFitArgs {
    /// Data file (CSV): temperature, time, value.
    #[arg(value_name = "DATA.csv")]
    pub data: PathBuf,

    /// End-of-life criterion, a fraction: the compression set reached, or the force fraction
    /// retained.
    #[arg(long, value_name = "C", default_value_t = 0.5)]
    pub criterion: f64,

    /// Service temperature for the extrapolated life, e.g. 60C.
    #[arg(long, value_name = "T")]
    pub service_temperature: Option<String>,

    /// What the value column is (default: inferred from the direction of every series).
    #[arg(long, value_enum)]
    pub kind: Option<KindArg>,

    /// Write JSON instead of the text summary.
    #[arg(long)]
    pub json: bool,

    /// Write the result to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Write the Arrhenius chart (SVG, PNG or PDF) to FILE.
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub plot: Option<PathBuf>,

    /// Write a [material.ageing] table (reference temperature: the service temperature, or
    /// the lowest ageing temperature) to FILE.
    #[arg(long, value_name = "FILE.toml")]
    pub write_material_ageing: Option<PathBuf>,
}

/// `--kind` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum KindArg {
    /// Compression set, rising with ageing time.
    CompressionSet,
    /// Retained-force fraction F/F0, falling with ageing time.
    RetainedForce,
}

impl From<KindArg> for AgeingKind {
    fn from(k: KindArg) -> Self {
        match k {
            KindArg::CompressionSet => AgeingKind::CompressionSet,
            KindArg::RetainedForce => AgeingKind::RetainedForce,
        }
    }
}

/// Runs `sealsim ageing-fit`.
pub fn run(args: AgeingFitArgs) -> Result<(), CliError> {
    super::guard_outputs(
        &[args.data.as_path()],
        &[
            ("-o", args.output.as_deref()),
            ("--plot", args.plot.as_deref()),
            (
                "--write-material-ageing",
                args.write_material_ageing.as_deref(),
            ),
        ],
    )?;
    let source = args.data.display().to_string();
    if !(args.criterion > 0.0 && args.criterion < 1.0) {
        return Err(CliError::Input(format!(
            "--criterion must be a fraction between 0 and 1, got {}",
            args.criterion
        )));
    }
    let service_temperature = args
        .service_temperature
        .as_deref()
        .map(parse_temperature)
        .transpose()
        .map_err(|e| CliError::Input(format!("--service-temperature: {e}")))?;
    let series = read_ageing_data(&args.data).map_err(|e| CliError::Input(e.to_string()))?;
    let located = |line: Option<usize>, message: String| {
        CliError::Input(match line {
            Some(l) => format!("{source}:{l}: {message}"),
            None => format!("{source}: {message}"),
        })
    };
    let last_line = series
        .iter()
        .filter_map(|s| s.points.last().map(|p| p.line))
        .max();
    if series.len() < 3 {
        return Err(located(
            last_line,
            format!(
                "{} ageing temperatures, ISO 11346 needs at least 3",
                series.len()
            ),
        ));
    }
    let (kind, kind_inferred) =
        resolve_kind(&series, args.kind.map(AgeingKind::from)).map_err(|(l, m)| located(l, m))?;
    let crossings: Vec<(f64, Crossing)> = series
        .iter()
        .map(|s| (s.temperature, time_to_criterion(s, kind, args.criterion)))
        .collect();
    let usable: Vec<(f64, f64)> = crossings
        .iter()
        .filter_map(|&(t, c)| match c {
            Crossing::Reached(time) => Some((t, time)),
            _ => None,
        })
        .collect();
    let fit = fit_arrhenius(&usable).map_err(|m| {
        located(
            last_line,
            format!(
                "{m} (of {} temperatures, the rest never cross the criterion)",
                series.len()
            ),
        )
    })?;
    let report = AgeingFitReport {
        source: source.clone(),
        kind,
        kind_inferred,
        criterion: args.criterion,
        crossings,
        fit,
        service_temperature,
    };
    // Render everything before writing anything.
    let main = if args.json {
        report.json()?
    } else {
        report.text()
    };
    let svg = match &args.plot {
        Some(_) => Some(
            report
                .chart()
                .to_svg()
                .map_err(|e| CliError::Internal(e.to_string()))?,
        ),
        None => None,
    };
    let svg = super::plot_file(args.plot.as_deref(), svg.as_deref())?;
    let toml = args.write_material_ageing.as_ref().map(|_| {
        let reference = service_temperature
            .unwrap_or_else(|| usable.iter().map(|p| p.0).fold(f64::INFINITY, f64::min));
        let (ageing, basis) = ageing_constants(&report.fit, kind, args.criterion, reference);
        format!(
            "# Ageing constants fitted by sealsim ageing-fit (ISO 11346) to {source}.\n\
             # k_ref from the fitted life t* at reference_temperature: {}.\n{}",
            match kind {
                AgeingKind::CompressionSet => "CS = 1 - exp(-k t), k = -ln(1 - CS*)/t*",
                AgeingKind::RetainedForce => "F/F0 = exp(-k t), k = -ln(F*/F0)/t*",
            },
            ageing_toml(&ageing, Some(&basis))
        )
    });
    if let (Some(path), Some(svg)) = (&args.plot, &svg) {
        write_output(Some(path), svg)?;
    }
    if let (Some(path), Some(toml)) = (&args.write_material_ageing, &toml) {
        write_output(Some(path), toml.as_bytes())?;
        eprintln!(
            "ageing-fit: wrote {} (k_ref by the two-network relation, crosslinking = 1)",
            path.display()
        );
    }
    write_output(args.output.as_deref(), main.as_bytes())
}
