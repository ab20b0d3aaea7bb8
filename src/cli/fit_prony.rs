//! `sealsim fit-prony`: the flags parsed into the options of the workflow
//! ([`crate::workflow::fit_prony`], the fit and the material), its result rendered
//! ([`crate::report::fit_prony`], the material TOML file and the summary on stderr) and written.

use super::{CliError, positive_flag, write_output};
use crate::material::fit::{FitSettings, Honour, Regularisation, TERMS_PER_DECADE};
use crate::material::tts::{MasterCurve, ShiftLaw};
use crate::report::fit_prony::{material_file, summary};
use crate::report::master_curve::{master_chart, shift_chart};
use crate::report::plot::LogLogChart;
use crate::scenario::fit_data::{FitKind, read_fit_data};
use crate::units::{Dimension, parse_temperature};
use crate::workflow::fit_prony::{
    CsrOptions, FitOptions, FitPronyError, Like, PieceKind, TtsOptions, fit,
};
use clap::builder::NonEmptyStringValueParser;
use clap::{Args, ValueEnum};
use std::path::PathBuf;

/// Arguments of `sealsim fit-prony`.
#[derive(Debug, Clone, Args)]
#[command(after_help = "Data files (CSV, '#' comments allowed):\n  \
    relaxation: t,E_relax  (also time; E, E_rel)\n  \
    CSR (ISO 3384): t,force (N; also F_N) or t,retained (1 or %; also retention, F/F0), with \
    --test-piece and --squeeze (forces; retained with --initial-force) or --reference-modulus\n  \
    an optional temperature column (also T; unit C, K or F) gives the test temperature\n  \
    dma:        f,E_stor,E_loss  (f in Hz, or omega in rad/s; also storage/E', loss/E'')\n\
    A second header row of units is required (pyvisco style: \"s,MPa\" or \"Hz,MPa,MPa\"; E_stor \
    and E_loss in the same unit).\n\
    The fit: non-negative least squares of E∞ and E_i on log-spaced τ_i over the data window \
    widened by a decade on each side, each point weighted by its relative error. One term per \
    decade leaves a ripple of a few per cent on a smooth spectrum; three make it negligible.\n\
    Output: a material TOML file (poisson_ratio = 0.5 assumed, no temperature shift), or with \
    --like COMPOUND the library compound's Poisson's ratio, thermal expansion, glass transition, \
    temperature shift and ageing, so that the file runs in a gland as written.")]
pub struct FitPronyArgs {
    /// Data file (CSV): a relaxation test or a DMA master curve.
    #[arg(value_name = "DATA.csv")]
    pub data: PathBuf,

    /// What the data file holds.
    #[arg(long, value_enum)]
    pub kind: KindArg,

    /// Relaxation times per decade of the fit grid, 0.25–4, fractional allowed (0.5: one term
    /// every two decades; 3 keeps the ripple of an off-grid spectrum below 0.04 %).
    #[arg(long, value_name = "N", default_value_t = crate::material::fit::DEFAULT_TERMS_PER_DECADE, value_parser = terms_per_decade)]
    pub terms_per_decade: f64,

    /// Smoothing of the fitted spectrum: `gcv`, a second-difference penalty on the relative
    /// spectrum with its weight chosen by generalised cross-validation; `none`, plain NNLS.
    #[arg(long, value_enum, default_value_t = RegularisationArg::Gcv)]
    pub regularisation: RegularisationArg,

    /// DMA data whose E″ disagrees with E′ (the Kramers–Kronig check the summary prints):
    /// `both` fits every value by its relative error (the lower long-term modulus: more leak);
    /// `storage` fits E′ everywhere and, where E″ disagrees, the E″ that E′ implies instead,
    /// keeping the storage plateau's long-term modulus.
    #[arg(long, value_enum, default_value_t = HonourArg::Both)]
    pub honour: HonourArg,

    /// Write the material TOML to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Material name (default: the data file's name without extension).
    #[arg(long, value_name = "NAME", value_parser = NonEmptyStringValueParser::new())]
    pub name: Option<String>,

    /// The test temperature of data without a temperature column (e.g. 23C): written as the
    /// material's data temperature, so that a run far from it is warned about.
    #[arg(long, value_name = "T")]
    pub temperature: Option<String>,

    /// Copy what a relaxation test does not measure from this material-library compound
    /// (`sealsim materials list`, e.g. nbr-70): Poisson's ratio, thermal expansion (rubbery
    /// and glassy), glass transition, the temperature shift (moved to the test temperature;
    /// not when the data give their own) and the ageing constants, each with its provenance.
    #[arg(long, value_name = "COMPOUND")]
    pub like: Option<String>,

    #[command(flatten)]
    pub csr: CsrArgs,

    #[command(flatten)]
    pub tts: TtsArgs,
}

/// Time–temperature superposition of relaxation data at several temperatures
/// (`crate::material::tts`).
#[derive(Debug, Clone, Default, Args)]
#[command(next_help_heading = "Master curves (data with a temperature column)")]
pub struct TtsArgs {
    /// The shift law fitted to the shift factors (default: wlf when the data have several
    /// temperatures).
    #[arg(long, value_enum)]
    pub shift: Option<ShiftArg>,

    /// Reference temperature of the master curve and the law (e.g. 23C) (default: the data
    /// temperature nearest their median).
    #[arg(long, value_name = "T")]
    pub reference_temperature: Option<String>,

    /// Write the shifted data on the master curve (SVG, PNG or PDF) to FILE.
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub plot_master: Option<PathBuf>,

    /// Write the shift factors a_T against T with the fitted law (SVG, PNG or PDF) to FILE.
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub plot_shift: Option<PathBuf>,
}

/// `--shift` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ShiftArg {
    /// Williams–Landel–Ferry: log10 a_T = −C1 (T − Tref)/(C2 + T − Tref).
    Wlf,
    /// Arrhenius: ln a_T = (Ea/R)(1/T − 1/Tref).
    Arrhenius,
}

/// How a compression-stress-relaxation force (or retained force) becomes a modulus
/// (`crate::material::csr`).
#[derive(Debug, Clone, Default, Args)]
#[command(next_help_heading = "Compression stress relaxation (force or retained columns)")]
pub struct CsrArgs {
    /// The CSR test piece: a ring (or O-ring: --cross-section, --mean-diameter) or a disc
    /// (--diameter, optional --height) between lubricated plates.
    #[arg(long, value_enum)]
    pub test_piece: Option<PieceArg>,

    /// The test's compression as a fraction or per cent of the cord diameter or disc height
    /// (e.g. 25%).
    #[arg(long, value_name = "SQUEEZE")]
    pub squeeze: Option<String>,

    /// Ring cord diameter (e.g. 3.53mm).
    #[arg(long, value_name = "LENGTH")]
    pub cross_section: Option<String>,

    /// Ring mean diameter (e.g. 30mm).
    #[arg(long, value_name = "LENGTH")]
    pub mean_diameter: Option<String>,

    /// Disc diameter (e.g. 13mm).
    #[arg(long, value_name = "LENGTH")]
    pub diameter: Option<String>,

    /// Disc height before compression (e.g. 6.3mm): only to bound the effect of plate friction.
    #[arg(long, value_name = "LENGTH")]
    pub height: Option<String>,

    /// The force at a retention of 1 (e.g. 180N), for retained data with a test piece.
    #[arg(long, value_name = "FORCE")]
    pub initial_force: Option<String>,

    /// A stated normalisation instead of a test piece: the modulus at the first force reading,
    /// or at a retention of 1 (e.g. 6MPa).
    #[arg(long, value_name = "MODULUS")]
    pub reference_modulus: Option<String>,
}

/// `--test-piece` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PieceArg {
    /// A ring or O-ring compressed across its cord (Lindley's force law, as in the life run).
    Ring,
    /// A cylindrical disc between lubricated plates (neo-Hookean uniaxial compression).
    Disc,
}

/// `--kind` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum KindArg {
    /// Stress relaxation E(t): columns t, E_relax.
    Relaxation,
    /// Dynamic mechanical analysis: columns f (or omega), E_stor, E_loss.
    Dma,
}

/// `--regularisation` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RegularisationArg {
    /// Smoothing weight by generalised cross-validation.
    Gcv,
    /// Plain non-negative least squares.
    None,
}

/// `--honour` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum HonourArg {
    /// Every E′ and E″ value.
    Both,
    /// E′ everywhere; E″ where it agrees with E′, else the E″ that E′ implies.
    Storage,
}

impl From<HonourArg> for Honour {
    fn from(h: HonourArg) -> Self {
        match h {
            HonourArg::Both => Honour::Both,
            HonourArg::Storage => Honour::Storage,
        }
    }
}

impl From<RegularisationArg> for Regularisation {
    fn from(r: RegularisationArg) -> Self {
        match r {
            RegularisationArg::Gcv => Regularisation::Gcv,
            RegularisationArg::None => Regularisation::None,
        }
    }
}

impl From<KindArg> for FitKind {
    fn from(k: KindArg) -> Self {
        match k {
            KindArg::Relaxation => FitKind::Relaxation,
            KindArg::Dma => FitKind::Dma,
        }
    }
}

/// Runs `sealsim fit-prony`.
pub fn run(args: FitPronyArgs) -> Result<(), CliError> {
    super::guard_outputs(
        &[args.data.as_path()],
        &[
            ("-o", args.output.as_deref()),
            ("--plot-master", args.tts.plot_master.as_deref()),
            ("--plot-shift", args.tts.plot_shift.as_deref()),
        ],
    )?;
    let like = args.like.as_deref().map(Like::of).transpose()?;
    let data = read_fit_data(&args.data, FitKind::from(args.kind))
        .map_err(|e| CliError::Input(e.to_string()))?;
    let temperature = args
        .temperature
        .as_deref()
        .map(parse_temperature)
        .transpose()
        .map_err(|e| CliError::Input(format!("--temperature: {e}")))?;
    let options = FitOptions {
        settings: FitSettings {
            terms_per_decade: args.terms_per_decade,
            regularisation: args.regularisation.into(),
            honour: args.honour.into(),
        },
        name: args.name.clone(),
        temperature,
        csr: csr_options(&args.csr)?,
        tts: tts_options(&args.tts)?,
    };
    let outcome = fit(&data, &args.data, like.as_ref(), &options)?;
    let text = material_file(&outcome);
    let svg = |path: &Option<PathBuf>, chart: fn(&str, &MasterCurve) -> LogLogChart| match (
        path,
        &outcome.master,
    ) {
        (Some(_), Some(m)) => chart(&outcome.source, m)
            .to_svg()
            .map(Some)
            .map_err(|e| CliError::Internal(e.to_string())),
        _ => Ok(None),
    };
    let master_svg = svg(&args.tts.plot_master, master_chart)?;
    let shift_svg = svg(&args.tts.plot_shift, shift_chart)?;
    let master_svg = super::plot_file(args.tts.plot_master.as_deref(), master_svg.as_deref())?;
    let shift_svg = super::plot_file(args.tts.plot_shift.as_deref(), shift_svg.as_deref())?;
    eprint!("{}", summary(&outcome));
    for (path, svg) in [
        (&args.tts.plot_master, &master_svg),
        (&args.tts.plot_shift, &shift_svg),
    ] {
        if let (Some(path), Some(svg)) = (path, svg) {
            write_output(Some(path), svg)?;
        }
    }
    write_output(args.output.as_deref(), text.as_bytes())
}

impl From<FitPronyError> for CliError {
    fn from(e: FitPronyError) -> Self {
        match e {
            FitPronyError::Input(m) => CliError::Input(m),
            FitPronyError::Internal(m) => CliError::Internal(m),
        }
    }
}

/// The CSR flags in SI.
fn csr_options(c: &CsrArgs) -> Result<CsrOptions, CliError> {
    let length =
        |v: &Option<String>, name: &str| positive_flag(v.as_deref(), name, Dimension::LENGTH);
    Ok(CsrOptions {
        test_piece: c.test_piece.map(|p| match p {
            PieceArg::Ring => PieceKind::Ring,
            PieceArg::Disc => PieceKind::Disc,
        }),
        squeeze: positive_flag(c.squeeze.as_deref(), "squeeze", Dimension::DIMENSIONLESS)?,
        cross_section: length(&c.cross_section, "cross-section")?,
        mean_diameter: length(&c.mean_diameter, "mean-diameter")?,
        diameter: length(&c.diameter, "diameter")?,
        height: length(&c.height, "height")?,
        reference_modulus: positive_flag(
            c.reference_modulus.as_deref(),
            "reference-modulus",
            Dimension::PRESSURE,
        )?,
        initial_force: positive_flag(
            c.initial_force.as_deref(),
            "initial-force",
            Dimension::FORCE,
        )?,
    })
}

/// The master-curve flags in SI.
fn tts_options(t: &TtsArgs) -> Result<TtsOptions, CliError> {
    Ok(TtsOptions {
        shift: t.shift.map(|s| match s {
            ShiftArg::Wlf => ShiftLaw::Wlf,
            ShiftArg::Arrhenius => ShiftLaw::Arrhenius,
        }),
        reference_temperature: t
            .reference_temperature
            .as_deref()
            .map(parse_temperature)
            .transpose()
            .map_err(|e| CliError::Input(format!("--reference-temperature: {e}")))?,
        plots: t.plot_master.is_some() || t.plot_shift.is_some(),
    })
}

/// `--terms-per-decade`: a number from 0.25 to 4 ([`TERMS_PER_DECADE`]).
fn terms_per_decade(text: &str) -> Result<f64, String> {
    let value: f64 = text
        .trim()
        .parse()
        .map_err(|_| format!("expected a number of terms per decade (0.25 to 4), got {text:?}"))?;
    if TERMS_PER_DECADE.contains(&value) {
        Ok(value)
    } else {
        Err(format!(
            "must be from {} to {} terms per decade (0.5: one term every two decades), got {text}",
            TERMS_PER_DECADE.start(),
            TERMS_PER_DECADE.end()
        ))
    }
}
