//! `sealsim fit-prony`: a Prony series fitted to relaxation or DMA data
//! ([`crate::material::fit`]), written as a material TOML file
//! ([`crate::report::material_toml`]).

use super::{CliError, positive_flag, write_output};
use crate::material::csr::{Normalisation, TestPiece};
use crate::material::fit::{
    Fit, FitError, FitSettings, Regularisation, TERMS_PER_DECADE, fit_dma, fit_relaxation,
};
use crate::material::tts::{
    Isotherm as TtsIsotherm, MasterCurve, ShiftLaw, TtsError, TtsSettings, master_curve,
};
use crate::material::{Material, Shift, Status};
use crate::report::master_curve::{law_text, master_chart, shift_chart, text as master_text};
use crate::report::material_toml::material_toml;
use crate::report::plot::LogLogChart;
use crate::scenario::fit_data::{FitData, FitKind, Isotherm, Measured, read_fit_data, show_kelvin};
use crate::scenario::library;
use crate::units::{Dimension, parse_temperature, show};
use clap::builder::NonEmptyStringValueParser;
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};

/// Poisson's ratio written to fitted materials, and where it comes from.
const ASSUMED_POISSON_RATIO: f64 = 0.5;
const ASSUMED_POISSON_PROVENANCE: &str =
    "assumed: incompressible rubber; replace with a measured value";

/// An rms relative residual above this earns a warning: the series does not describe the data.
const POOR_FIT: f64 = 0.05;

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

    /// Write the shifted data on the master curve (SVG) to FILE.
    #[arg(long, value_name = "FILE.svg")]
    pub plot_master: Option<PathBuf>,

    /// Write the shift factors a_T against T with the fitted law (SVG) to FILE.
    #[arg(long, value_name = "FILE.svg")]
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
    let like = args.like.as_deref().map(like_compound).transpose()?;
    let kind = FitKind::from(args.kind);
    let data = read_fit_data(&args.data, kind).map_err(|e| CliError::Input(e.to_string()))?;
    let settings = FitSettings {
        terms_per_decade: args.terms_per_decade,
        regularisation: args.regularisation.into(),
    };
    let source = args.data.display().to_string();
    let stated_temperature = args
        .temperature
        .as_deref()
        .map(parse_temperature)
        .transpose()
        .map_err(|e| CliError::Input(format!("--temperature: {e}")))?;
    let (fit, data_temperature, normalisation) = match &data {
        FitData::Relaxation {
            measured,
            isotherms,
            temperature_column,
        } => {
            let normalisation = normalisation(&args.csr, *measured, isotherms)?;
            if isotherms.len() > 1 {
                return master(
                    &args,
                    &settings,
                    isotherms,
                    normalisation.as_ref(),
                    *measured,
                    like.as_ref(),
                );
            }
            let [isotherm] = isotherms.as_slice() else {
                return Err(CliError::Internal("a data file without points".into()));
            };
            if tts_given(&args.tts) {
                let (line, column) = temperature_column.unwrap_or((1, 1));
                return Err(CliError::Input(format!(
                    "{source}:{line}:{column}: {}: --shift, --reference-temperature and the \
                     master-curve plots need relaxation data at two or more temperatures (a \
                     temperature column)",
                    match isotherm.temperature {
                        Some(t) => format!("one temperature ({})", show_kelvin(t)),
                        None => "no temperature column".into(),
                    }
                )));
            }
            if let (Some(t), Some(_)) = (isotherm.temperature, stated_temperature) {
                return Err(CliError::Input(format!(
                    "--temperature: the data give their temperature ({}) in a column",
                    show_kelvin(t)
                )));
            }
            let moduli = match &normalisation {
                Some(n) => n.moduli(&isotherm.values),
                None => isotherm.values.clone(),
            };
            let fit = fit_relaxation(&isotherm.times, &moduli, &settings)
                .map_err(|e| fit_error(&args.data, e))?;
            (
                fit,
                isotherm.temperature.or(stated_temperature),
                normalisation.map(|n| (n, *measured)),
            )
        }
        FitData::Dma {
            omegas,
            storage,
            loss,
        } => {
            if tts_given(&args.tts) {
                return Err(CliError::Input(
                    "--shift, --reference-temperature and the master-curve plots need \
                     relaxation data at several temperatures; DMA data are fitted as a master \
                     curve already shifted"
                        .into(),
                ));
            }
            if csr_given(&args.csr) {
                return Err(CliError::Input(
                    "--test-piece, --squeeze, --reference-modulus etc. convert CSR forces; DMA \
                     data give moduli"
                        .into(),
                ));
            }
            let fit =
                fit_dma(omegas, storage, loss, &settings).map_err(|e| fit_error(&args.data, e))?;
            (fit, stated_temperature, None)
        }
    };

    let name = args
        .name
        .clone()
        .unwrap_or_else(|| default_name(&args.data));
    let mut material = fitted_material(name, &fit, &source, args.terms_per_decade);
    if let Some(t) = data_temperature {
        material.data_temperature = Some((t, t));
        material.provenance.push((
            "data_temperature".into(),
            format!("the test temperature of {source}"),
        ));
    }
    if let Some((n, measured)) = &normalisation {
        let note = format!(
            "; moduli from the {} by {}",
            measured.describe(),
            describe(n)
        );
        for (key, text) in material.provenance.iter_mut() {
            if key == "prony" || key == "long_term_modulus" {
                text.push_str(&note);
            }
        }
    }
    let copied = match &like {
        Some(l) => Some(copy_like(&mut material, l, false, &source)?),
        None => None,
    };
    let text = format!(
        "{}{}{}",
        header(&source, kind, &fit, &material),
        like_header(like.as_ref()),
        material_toml(&material)
    );
    print_summary(&source, &fit);
    if let Some((n, _)) = &normalisation {
        print_normalisation(&source, n);
    }
    if let (Some(l), Some(notes)) = (&like, &copied) {
        print_like(&source, l, notes);
    }
    if data_temperature.is_none() {
        eprintln!(
            "note: {source}: no test temperature (a temperature column or --temperature): a run \
             at another temperature cannot be warned about"
        );
    }
    write_output(args.output.as_deref(), text.as_bytes())
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

/// Whether any master-curve flag was given.
fn tts_given(t: &TtsArgs) -> bool {
    t.shift.is_some()
        || t.reference_temperature.is_some()
        || t.plot_master.is_some()
        || t.plot_shift.is_some()
}

/// `fit-prony` on data at several temperatures: the master curve, its material file and
/// plots (written only when everything has been computed).
fn master(
    args: &FitPronyArgs,
    settings: &FitSettings,
    isotherms: &[Isotherm],
    normalisation: Option<&Normalisation>,
    measured: Measured,
    like: Option<&Like>,
) -> Result<(), CliError> {
    let source = args.data.display().to_string();
    if args.temperature.is_some() {
        return Err(CliError::Input(
            "--temperature: the data give their temperatures in a column".into(),
        ));
    }
    let reference = args
        .tts
        .reference_temperature
        .as_deref()
        .map(parse_temperature)
        .transpose()
        .map_err(|e| CliError::Input(format!("--reference-temperature: {e}")))?;
    let law = match args.tts.shift.unwrap_or(ShiftArg::Wlf) {
        ShiftArg::Wlf => ShiftLaw::Wlf,
        ShiftArg::Arrhenius => ShiftLaw::Arrhenius,
    };
    let data: Vec<TtsIsotherm> = isotherms
        .iter()
        .map(|i| TtsIsotherm {
            temperature: i.temperature.unwrap_or(f64::NAN),
            times: i.times.clone(),
            moduli: match normalisation {
                Some(n) => n.moduli(&i.values),
                None => i.values.clone(),
            },
        })
        .collect();
    let m = master_curve(
        &data,
        &TtsSettings {
            law,
            reference,
            fit: *settings,
        },
    )
    .map_err(|e| match e {
        TtsError::Fit(FitError::Solver(_) | FitError::Degenerate(_)) => {
            CliError::Internal(format!("{source}: {e}"))
        }
        _ => CliError::Input(format!("{source}: {e}")),
    })?;
    let name = args
        .name
        .clone()
        .unwrap_or_else(|| default_name(&args.data));
    let mut material = fitted_material(name, &m.fit, &source, args.terms_per_decade);
    material.shift = m.shift;
    material.data_reduced_time = Some(m.window);
    material.data_temperature = Some(m.temperature_range);
    let superposition = format!(
        "master curve at {:.2} K by time–temperature superposition of {} isotherms \
         ({:.2}–{:.2} K, horizontal shifts only)",
        m.reference,
        m.shifts.len(),
        m.temperature_range.0,
        m.temperature_range.1
    );
    let mut note = format!("; {superposition}");
    if let Some(n) = normalisation {
        note.push_str(&format!(
            "; moduli from the {} by {}",
            measured.describe(),
            describe(n)
        ));
    }
    for (key, text) in material.provenance.iter_mut() {
        if key == "prony" || key == "long_term_modulus" {
            text.push_str(&note);
        }
    }
    material.provenance.push((
        "shift".into(),
        format!(
            "fitted by sealsim fit-prony on {} to the shift factors of {source}: {}",
            fit_date(),
            law_text(&m)
        ),
    ));
    material.provenance.push((
        "data_temperature".into(),
        format!("the test temperatures of {source}"),
    ));
    let copied = like
        .map(|l| copy_like(&mut material, l, true, &source))
        .transpose()?;
    let text = format!(
        "# Prony series of the master curve fitted by sealsim fit-prony to relaxation data at \
         {} temperatures in {source} ({} points).\n\
         # E(t) = E∞ + Σ E_i exp(−ξ/τ_i) in reduced time ξ at the reference temperature of \
         [material.shift].\n{}{}",
        m.shifts.len(),
        m.reduced.len(),
        like_header(like),
        material_toml(&material)
    );
    let svg = |path: &Option<PathBuf>, chart: fn(&str, &MasterCurve) -> LogLogChart| {
        path.as_ref()
            .map(|_| {
                chart(&source, &m)
                    .to_svg()
                    .map_err(|e| CliError::Internal(e.to_string()))
            })
            .transpose()
    };
    let master_svg = svg(&args.tts.plot_master, master_chart)?;
    let shift_svg = svg(&args.tts.plot_shift, shift_chart)?;
    eprint!("{}", master_text(&source, &m));
    print_summary(&source, &m.fit);
    if let Some(n) = normalisation {
        print_normalisation(&source, n);
    }
    if let (Some(l), Some(notes)) = (like, &copied) {
        print_like(&source, l, notes);
    }
    for (path, svg) in [
        (&args.tts.plot_master, &master_svg),
        (&args.tts.plot_shift, &shift_svg),
    ] {
        if let (Some(path), Some(svg)) = (path, svg) {
            write_output(Some(path), svg.as_bytes())?;
        }
    }
    write_output(args.output.as_deref(), text.as_bytes())
}

/// Today's date (UTC, `YYYY-MM-DD`) for provenance, or the date of `SOURCE_DATE_EPOCH` when
/// set (the reproducible-builds convention), so that a pinned run writes the same bytes.
fn fit_date() -> String {
    let seconds = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|s| s.trim().parse::<i64>().ok())
        .unwrap_or_else(|| {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(0))
        });
    let (y, m, d) = civil_from_days(seconds.div_euclid(86_400));
    format!("{y:04}-{m:02}-{d:02}")
}

/// The proleptic Gregorian date of a day count from 1970-01-01 (H. Hinnant's
/// `civil_from_days`, <http://howardhinnant.github.io/date_algorithms.html> — recalled).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

/// Whether any CSR flag was given.
fn csr_given(c: &CsrArgs) -> bool {
    c.test_piece.is_some()
        || c.squeeze.is_some()
        || c.cross_section.is_some()
        || c.mean_diameter.is_some()
        || c.diameter.is_some()
        || c.height.is_some()
        || c.initial_force.is_some()
        || c.reference_modulus.is_some()
}

fn required(value: Option<f64>, name: &str, piece: &str) -> Result<f64, CliError> {
    value.ok_or_else(|| CliError::Input(format!("--test-piece {piece} needs --{name}")))
}

/// The test piece of the flags, when one is named.
fn test_piece(c: &CsrArgs) -> Result<Option<TestPiece>, CliError> {
    let Some(kind) = c.test_piece else {
        for (given, name) in [
            (&c.squeeze, "squeeze"),
            (&c.cross_section, "cross-section"),
            (&c.mean_diameter, "mean-diameter"),
            (&c.diameter, "diameter"),
            (&c.height, "height"),
        ] {
            if given.is_some() {
                return Err(CliError::Input(format!(
                    "--{name} describes a test piece: give --test-piece ring or disc"
                )));
            }
        }
        return Ok(None);
    };
    let length =
        |v: &Option<String>, name: &str| positive_flag(v.as_deref(), name, Dimension::LENGTH);
    let squeeze = positive_flag(c.squeeze.as_deref(), "squeeze", Dimension::DIMENSIONLESS)?;
    let piece = match kind {
        PieceArg::Ring => {
            for (given, name) in [(&c.diameter, "diameter"), (&c.height, "height")] {
                if given.is_some() {
                    return Err(CliError::Input(format!(
                        "--{name} is a disc's: a ring takes --cross-section and --mean-diameter"
                    )));
                }
            }
            TestPiece::Ring {
                cross_section: required(
                    length(&c.cross_section, "cross-section")?,
                    "cross-section",
                    "ring",
                )?,
                mean_diameter: required(
                    length(&c.mean_diameter, "mean-diameter")?,
                    "mean-diameter",
                    "ring",
                )?,
                squeeze: required(squeeze, "squeeze", "ring")?,
            }
        }
        PieceArg::Disc => {
            for (given, name) in [
                (&c.cross_section, "cross-section"),
                (&c.mean_diameter, "mean-diameter"),
            ] {
                if given.is_some() {
                    return Err(CliError::Input(format!(
                        "--{name} is a ring's: a disc takes --diameter (and --height)"
                    )));
                }
            }
            TestPiece::Disc {
                diameter: required(length(&c.diameter, "diameter")?, "diameter", "disc")?,
                height: length(&c.height, "height")?,
                squeeze: required(squeeze, "squeeze", "disc")?,
            }
        }
    };
    piece
        .check()
        .map_err(|e| CliError::Input(format!("--test-piece: {e}")))?;
    Ok(Some(piece))
}

/// How the measured column becomes moduli (`None`: it is one).
fn normalisation(
    c: &CsrArgs,
    measured: Measured,
    isotherms: &[Isotherm],
) -> Result<Option<Normalisation>, CliError> {
    let piece = test_piece(c)?;
    let reference = positive_flag(
        c.reference_modulus.as_deref(),
        "reference-modulus",
        Dimension::PRESSURE,
    )?;
    let initial = positive_flag(
        c.initial_force.as_deref(),
        "initial-force",
        Dimension::FORCE,
    )?;
    if piece.is_some() && reference.is_some() {
        return Err(CliError::Input(
            "give either a test piece or --reference-modulus, not both".into(),
        ));
    }
    let first_value = isotherms
        .first()
        .and_then(|i| i.values.first())
        .copied()
        .unwrap_or(1.0);
    match measured {
        Measured::Modulus => {
            if csr_given(c) {
                return Err(CliError::Input(
                    "--test-piece, --squeeze, --reference-modulus etc. convert CSR forces; this \
                     file gives the relaxation modulus itself"
                        .into(),
                ));
            }
            Ok(None)
        }
        Measured::Force => {
            if initial.is_some() {
                return Err(CliError::Input(
                    "--initial-force is for retained-force data; this file gives forces".into(),
                ));
            }
            match (piece, reference) {
                (Some(piece), None) => Ok(Some(Normalisation::Piece(piece))),
                (None, Some(modulus)) => Ok(Some(Normalisation::Modulus {
                    modulus,
                    reference_value: first_value,
                })),
                _ => Err(CliError::Input(
                    "forces need a test piece (--test-piece ring|disc with its dimensions and \
                     --squeeze) or a stated --reference-modulus at the first reading"
                        .into(),
                )),
            }
        }
        Measured::Retained => {
            if isotherms.len() > 1 {
                return Err(CliError::Input(
                    "retained force at several temperatures cannot be put on one curve: each \
                     series is relative to its own initial force; give the forces (N) with the \
                     test piece"
                        .into(),
                ));
            }
            match (piece, reference, initial) {
                (Some(piece), None, Some(initial_force)) => Ok(Some(Normalisation::RetainedOf {
                    piece,
                    initial_force,
                })),
                (None, Some(modulus), None) => Ok(Some(Normalisation::Modulus {
                    modulus,
                    reference_value: 1.0,
                })),
                (None, Some(_), Some(_)) => Err(CliError::Input(
                    "--initial-force goes with a test piece, not with --reference-modulus".into(),
                )),
                (Some(_), None, None) => Err(CliError::Input(
                    "retained-force data with a test piece need --initial-force (the force at a \
                     retention of 1)"
                        .into(),
                )),
                _ => Err(CliError::Input(
                    "retained-force data need --reference-modulus (the modulus at a retention of \
                     1) or a test piece with --initial-force"
                        .into(),
                )),
            }
        }
    }
}

/// The normalisation in words, for the provenance.
fn describe(n: &Normalisation) -> String {
    let piece = |p: &TestPiece| match *p {
        TestPiece::Ring {
            cross_section,
            mean_diameter,
            squeeze,
        } => format!(
            "a ring test piece (cord {} mm, mean diameter {} mm, squeeze {} %; Lindley's O-ring \
             force law, as in the life run)",
            show(cross_section * 1e3),
            show(mean_diameter * 1e3),
            show(squeeze * 100.0)
        ),
        TestPiece::Disc {
            diameter, squeeze, ..
        } => format!(
            "a disc test piece (diameter {} mm, squeeze {} %; neo-Hookean compression between \
             lubricated plates)",
            show(diameter * 1e3),
            show(squeeze * 100.0)
        ),
    };
    match n {
        Normalisation::Piece(p) => piece(p),
        Normalisation::RetainedOf {
            piece: p,
            initial_force,
        } => format!(
            "{} with an initial force of {} N",
            piece(p),
            show(*initial_force)
        ),
        Normalisation::Modulus { modulus, .. } => format!(
            "a stated modulus of {} MPa at the reference reading",
            show(modulus * 1e-6)
        ),
    }
}

/// How forces were turned into moduli, and the plate-friction caveat for discs.
fn print_normalisation(source: &str, n: &Normalisation) {
    eprintln!(
        "fit-prony: {source}: moduli = {} × the measured value, from {}",
        show(n.factor()),
        describe(n)
    );
    let piece = match n {
        Normalisation::Piece(p) | Normalisation::RetainedOf { piece: p, .. } => Some(p),
        Normalisation::Modulus { .. } => None,
    };
    if let Some(bound) = piece.and_then(TestPiece::friction_bound) {
        eprintln!(
            "note: {source}: if the plates were not lubricated, friction raises the force of \
             this disc by up to ×{bound:.2} (fully bonded, 1 + 2S²): the moduli would be \
             overstated by up to that factor"
        );
    }
}

/// The material of a fit: a user material, Poisson's ratio assumed, no temperature shift,
/// with the provenance of every number.
pub fn fitted_material(name: String, fit: &Fit, source: &str, terms_per_decade: f64) -> Material {
    let fitted = format!(
        "fitted by sealsim fit-prony (NNLS, {} per decade) to {source}: \
         {} points, rms relative residual {:.2e}, max {:.2e}; {}",
        per_decade_text(terms_per_decade),
        fit.points,
        fit.rms_relative_residual,
        fit.max_relative_residual,
        regularisation_note(fit)
    );
    let mut provenance = vec![(
        "poisson_ratio".to_string(),
        ASSUMED_POISSON_PROVENANCE.to_string(),
    )];
    provenance.push(("long_term_modulus".into(), fitted.clone()));
    if !fit.prony.terms().is_empty() {
        provenance.push(("prony".into(), fitted));
    }
    Material {
        name,
        status: Status::User,
        prony: fit.prony.clone(),
        poisson_ratio: ASSUMED_POISSON_RATIO,
        shift: Shift::None,
        glass_transition: None,
        thermal_expansion: None,
        glassy_thermal_expansion: None,
        ageing: None,
        ageing_basis: None,
        data_reduced_time: Some(fit.window),
        data_temperature: None,
        provenance,
        compatibility: Vec::new(),
        library_id: None,
    }
}

/// "1 term", "3 terms", "0.5 terms" (of a number of terms per decade).
fn per_decade_text(n: f64) -> String {
    format!("{} {}", show(n), if n == 1.0 { "term" } else { "terms" })
}

/// A comment block for the top of the file.
fn header(source: &str, kind: FitKind, fit: &Fit, material: &Material) -> String {
    let what = match kind {
        FitKind::Relaxation => "relaxation data",
        FitKind::Dma => "DMA data",
    };
    let shift = if material.shift == Shift::None {
        "at the temperature of the data (or of its master curve):\n\
         # add a [material.shift] table for temperature dependence."
    } else {
        "in reduced time at the reference temperature of [material.shift]."
    };
    format!(
        "# Prony series fitted by sealsim fit-prony to {what} in {source} ({} points).\n\
         # E(t) = E∞ + Σ E_i exp(−t/τ_i), {shift}\n",
        fit.points
    )
}

/// A library compound whose unmeasured properties `--like` copies.
pub struct Like {
    /// The library id, e.g. `nbr-70`.
    pub id: &'static str,
    pub compound: Material,
}

/// The compound of `--like ID`, or an input error naming the flag and listing the ids.
fn like_compound(id: &str) -> Result<Like, CliError> {
    let entry = library::get(id).map_err(|e| {
        CliError::Input(format!(
            "--like {id}: {e} (`sealsim materials list` describes them)"
        ))
    })?;
    let compound = entry
        .load()
        .map_err(|e| CliError::Internal(format!("--like {id}: {e}")))?;
    Ok(Like {
        id: entry.id,
        compound,
    })
}

/// What `--like` copied (parameter keys, in file order) and what it noted.
pub struct Copied {
    pub keys: Vec<&'static str>,
    pub notes: Vec<String>,
}

/// Copies from the library compound of `like` into the fitted `material` what a relaxation
/// test does not measure: Poisson's ratio (the fit assumes 0.5), `thermal_expansion`,
/// `glassy_thermal_expansion`, `glass_transition`, the ageing constants with their property
/// and criterion, and — unless `data_shift` (a master curve gave one) — the temperature
/// shift. Each copied key's provenance reads "copied from library compound ID (sealsim
/// fit-prony --like): " and the library's own.
///
/// The series is the relaxation at the test temperature T_d (`material.data_temperature`),
/// so a copied shift is moved to T_d as its reference: WLF `C2′ = C2 + T_d − T_ref`,
/// `C1′ = C1 C2/C2′` (the same a_T between any two temperatures: log a_T(T; T_d) =
/// log a_T(T; T_ref) − log a_T(T_d; T_ref), WLF 1955), Arrhenius `T_ref′ = T_d`. A T_d at or
/// below the WLF frozen limit T_ref − C2 is refused (the copied law gives no shift there).
/// Without a test temperature the data are taken at the shift's own reference (noted).
/// Permeation data follow a library id, not a material file (docs/model.md §13.7): noted.
pub fn copy_like(
    material: &mut Material,
    like: &Like,
    data_shift: bool,
    source: &str,
) -> Result<Copied, CliError> {
    let c = &like.compound;
    let id = like.id;
    let prefix = format!("copied from library compound {id} (sealsim fit-prony --like)");
    let from = |key: &str| match c.provenance_of(key) {
        Some(text) => format!("{prefix}: {text}"),
        None => prefix.clone(),
    };
    let mut copied = Copied {
        keys: Vec::new(),
        notes: Vec::new(),
    };
    let mut provenance: Vec<(String, String)> = Vec::new();
    material.poisson_ratio = c.poisson_ratio;
    provenance.push(("poisson_ratio".into(), from("poisson_ratio")));
    copied.keys.push("poisson_ratio");
    for (key, value, own) in [
        (
            "glass_transition",
            &mut material.glass_transition,
            c.glass_transition,
        ),
        (
            "thermal_expansion",
            &mut material.thermal_expansion,
            c.thermal_expansion,
        ),
        (
            "glassy_thermal_expansion",
            &mut material.glassy_thermal_expansion,
            c.glassy_thermal_expansion,
        ),
    ] {
        if own.is_some() {
            *value = own;
            provenance.push((key.into(), from(key)));
            copied.keys.push(key);
        }
    }
    if !data_shift && c.shift != Shift::None {
        let at = material.data_temperature.map(|(lo, _)| lo);
        let (shift, moved) = moved_shift(c.shift, at).map_err(|limit| {
            CliError::Input(format!(
                "--like {id}: the test temperature {} of {source} is at or below the frozen \
                 limit of the compound's WLF shift ({}: T_ref − C2), where it gives no \
                 temperature dependence to copy; fit without --like and add a [material.shift] \
                 measured for this compound",
                show_kelvin(at.unwrap_or(limit)),
                show_kelvin(limit)
            ))
        })?;
        material.shift = shift;
        let note = match (moved, at) {
            (true, Some(t)) => format!(
                "; its reference temperature moved to the test temperature {} (the same a_T \
                 between any two temperatures)",
                show_kelvin(t)
            ),
            (false, Some(_)) => String::new(),
            (_, None) => {
                let reference = shift_reference(c.shift).unwrap_or(f64::NAN);
                copied.notes.push(format!(
                    "the shift copied from {id} takes the data as measured at its reference \
                     temperature, {}: give --temperature (the test's) to move it there",
                    show_kelvin(reference)
                ));
                format!(
                    "; the data taken as measured at its reference temperature {} (no test \
                     temperature given)",
                    show_kelvin(reference)
                )
            }
        };
        provenance.push(("shift".into(), format!("{}{note}", from("shift"))));
        copied.keys.push("shift");
    }
    if c.ageing.is_some() {
        material.ageing = c.ageing;
        material.ageing_basis = c.ageing_basis.clone();
        provenance.push(("ageing".into(), from("ageing")));
        copied.keys.push("ageing");
    }
    // a copied key's provenance replaces the fit's (the assumed poisson_ratio) where it was
    for (key, text) in provenance {
        match material.provenance.iter_mut().find(|(k, _)| *k == key) {
            Some(entry) => entry.1 = text,
            None => material.provenance.push((key, text)),
        }
    }
    if crate::permeation::family_of(id).is_some() {
        copied.notes.push(format!(
            "permeation data are kept by compound class and follow only a scenario's `library = \
             \"{id}\"`, not a material file: a gas run with this file has no permeation \
             through the rubber (docs/model.md §13.7)"
        ));
    }
    Ok(copied)
}

/// The WLF or Arrhenius shift `shift` with its reference moved to `at` \[K\] (`None`: kept),
/// and whether it moved; `Err(T_ref − C2)` when `at` is at or below the WLF frozen limit.
fn moved_shift(shift: Shift, at: Option<f64>) -> Result<(Shift, bool), f64> {
    let Some(t) = at else {
        return Ok((shift, false));
    };
    match shift {
        Shift::None => Ok((shift, false)),
        Shift::Wlf { reference, .. } | Shift::Arrhenius { reference, .. } if reference == t => {
            Ok((shift, false))
        }
        Shift::Wlf { reference, c1, c2 } => {
            let moved = c2 + t - reference;
            if moved > 0.0 {
                Ok((
                    Shift::Wlf {
                        reference: t,
                        c1: c1 * c2 / moved,
                        c2: moved,
                    },
                    true,
                ))
            } else {
                Err(reference - c2)
            }
        }
        Shift::Arrhenius {
            activation_energy, ..
        } => Ok((
            Shift::Arrhenius {
                reference: t,
                activation_energy,
            },
            true,
        )),
    }
}

/// The reference temperature of a shift \[K\].
fn shift_reference(shift: Shift) -> Option<f64> {
    match shift {
        Shift::None => None,
        Shift::Wlf { reference, .. } | Shift::Arrhenius { reference, .. } => Some(reference),
    }
}

/// The file's comment line on what `--like` copied.
fn like_header(like: Option<&Like>) -> String {
    like.map_or(String::new(), |l| {
        format!(
            "# Poisson's ratio, thermal expansion, glass transition, temperature shift and ageing \
             copied from library compound {} ({} data): see [material.provenance].\n",
            l.id,
            l.compound.status.as_str().to_uppercase()
        )
    })
}

/// Lines on stderr: what `--like` copied, and its notes.
fn print_like(source: &str, like: &Like, copied: &Copied) {
    eprintln!(
        "fit-prony: {source}: copied from library compound {} ({}): {}",
        like.id,
        like.compound.status.as_str(),
        copied.keys.join(", ")
    );
    for note in &copied.notes {
        eprintln!("note: {source}: {note}");
    }
}

/// The regularisation of a fit in words: method, λ and the effective number of parameters.
fn regularisation_note(fit: &Fit) -> String {
    let method = match fit.regularisation {
        Regularisation::Gcv => "smoothing of the relative spectrum, weight by GCV",
        Regularisation::None => "no smoothing",
        Regularisation::Fixed(_) => "smoothing of the relative spectrum, weight given",
    };
    format!(
        "{method}: lambda {:.3e}, {:.1} effective parameters",
        fit.smoothing, fit.effective_parameters
    )
}

/// Lines on stderr: what was fitted and how well, with the regularisation and the widest
/// half-width of the simultaneous 95 % band over the data window; a warning when the fit is
/// poor.
fn print_summary(source: &str, fit: &Fit) {
    let (widest, at) = fit.widest_relative_band();
    let band = if widest.is_finite() {
        format!(
            "simultaneous 95 % band of E(t) over the data window: ±{:.2} % at most (at t = {} s)",
            100.0 * widest,
            crate::units::show(at)
        )
    } else {
        "no uncertainty band: the fit leaves no residual degree of freedom to estimate the \
         scatter from (give more points)"
            .to_string()
    };
    eprintln!(
        "fit-prony: {source}: {} points, {} of {} grid terms kept + E∞; \
         rms relative residual {:.2e}, max {:.2e}\n\
         fit-prony: {}; {band}",
        fit.points,
        fit.prony.terms().len(),
        fit.grid_terms,
        fit.rms_relative_residual,
        fit.max_relative_residual,
        regularisation_note(fit),
    );
    if fit.rms_relative_residual > POOR_FIT {
        eprintln!(
            "warning: {source}: the series misses the data by {:.1} % rms: check the data, or raise --terms-per-decade",
            100.0 * fit.rms_relative_residual
        );
    }
}

/// The data file's name without its extension.
fn default_name(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "fitted material".to_string())
}

/// Data the fit refuses are bad input; a solver failure is an internal error. Too few points
/// for plain NNLS name the flags that fix it.
fn fit_error(path: &Path, e: FitError) -> CliError {
    match e {
        FitError::Solver(_) | FitError::Degenerate(_) => {
            CliError::Internal(format!("{}: {e}", path.display()))
        }
        FitError::TooFewPoints {
            points,
            values,
            unknowns,
            max_terms_per_decade,
        } if points >= 3 => CliError::Input(format!(
            "{}: --regularisation none: too few points for a fit without smoothing: {points} data \
             points give {values} values for {unknowns} unknowns (E∞ and {} Prony terms); give \
             more points, {}or leave out --regularisation none (the default, gcv, takes fewer \
             points than unknowns)",
            path.display(),
            unknowns.saturating_sub(1),
            match max_terms_per_decade {
                Some(n) => format!("--terms-per-decade {} or less, ", show(n)),
                None => String::new(),
            }
        )),
        _ => CliError::Input(format!("{}: {e}", path.display())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::fit::fit_relaxation;

    #[test]
    fn provenance_names_the_method_and_the_residuals() {
        let t = crate::math::log_spaced(1.0, 1e6, 13);
        let e: Vec<f64> = t
            .iter()
            .map(|x| 2e6 * (1.0 + 3.0 / (1.0 + x.sqrt())))
            .collect();
        let fit = fit_relaxation(
            &t,
            &e,
            &FitSettings {
                terms_per_decade: 1.0,
                ..FitSettings::default()
            },
        )
        .unwrap();
        let m = fitted_material("x".into(), &fit, "data.csv", 1.0);
        assert_eq!(
            m.provenance_of("poisson_ratio"),
            Some(ASSUMED_POISSON_PROVENANCE)
        );
        let p = m.provenance_of("prony").unwrap();
        assert!(
            p.starts_with("fitted by sealsim fit-prony (NNLS, 1 term per decade) to data.csv: 13 points, rms relative residual"),
            "{p}"
        );
        assert_eq!(m.provenance_of("long_term_modulus"), Some(p));
        assert_eq!(m.status, Status::User);
        assert_eq!(default_name(Path::new("dir/nbr-70.csv")), "nbr-70");
    }

    #[test]
    fn a_moved_shift_gives_the_same_shift_between_any_two_temperatures() {
        let wlf = Shift::Wlf {
            reference: 296.15,
            c1: 8.28641,
            c2: 108.6,
        };
        let arrhenius = Shift::Arrhenius {
            reference: 296.15,
            activation_energy: 9e4,
        };
        for shift in [wlf, arrhenius] {
            let (moved, did) = moved_shift(shift, Some(343.15)).unwrap();
            assert!(did);
            assert_eq!(shift_reference(moved), Some(343.15));
            assert!(moved.log10_factor(343.15).abs() < 1e-12);
            for (a, b) in [(250.0, 300.0), (300.0, 420.0), (343.15, 380.0)] {
                let before = shift.log10_factor(a) - shift.log10_factor(b);
                let after = moved.log10_factor(a) - moved.log10_factor(b);
                assert!((after - before).abs() < 1e-9, "{shift:?} {a} {b}");
            }
        }
        // the frozen limit T_ref − C2 = 187.55 K
        assert_eq!(moved_shift(wlf, Some(180.0)), Err(296.15 - 108.6));
        assert_eq!(moved_shift(wlf, None), Ok((wlf, false)));
        assert_eq!(moved_shift(wlf, Some(296.15)), Ok((wlf, false)));
    }

    #[test]
    fn like_copies_what_the_test_does_not_measure_with_provenance() {
        let t = crate::math::log_spaced(3600.0, 3.6e6, 7);
        let e: Vec<f64> = t
            .iter()
            .map(|x| 2e6 * (1.0 + 1.0 / (1.0 + x / 1e5)))
            .collect();
        let fit = fit_relaxation(&t, &e, &FitSettings::default()).unwrap();
        let mut m = fitted_material("x".into(), &fit, "data.csv", 0.5);
        assert!(
            m.provenance_of("prony")
                .unwrap()
                .starts_with("fitted by sealsim fit-prony (NNLS, 0.5 terms per decade)")
        );
        m.data_temperature = Some((373.15, 373.15));
        let like = like_compound("nbr-70").unwrap();
        let copied = copy_like(&mut m, &like, false, "data.csv").unwrap();
        let c = &like.compound;
        assert_eq!(m.poisson_ratio, c.poisson_ratio);
        assert_eq!(m.thermal_expansion, c.thermal_expansion);
        assert_eq!(m.glassy_thermal_expansion, c.glassy_thermal_expansion);
        assert_eq!(m.glass_transition, c.glass_transition);
        assert_eq!(m.ageing, c.ageing);
        assert_eq!(m.ageing_basis, c.ageing_basis);
        assert_eq!(shift_reference(m.shift), Some(373.15));
        assert_eq!(m.status, Status::User);
        assert_eq!(m.prony, fit.prony, "the fitted series is kept");
        for key in copied.keys.iter().copied() {
            let text = m.provenance_of(key).unwrap();
            let own = c.provenance_of(key).unwrap();
            assert!(
                text.starts_with(&format!(
                    "copied from library compound nbr-70 (sealsim fit-prony --like): {own}"
                )),
                "{key}: {text}"
            );
        }
        assert_eq!(
            copied.keys,
            [
                "poisson_ratio",
                "glass_transition",
                "thermal_expansion",
                "glassy_thermal_expansion",
                "shift",
                "ageing"
            ]
        );
        assert!(
            m.provenance_of("shift")
                .unwrap()
                .contains("moved to the test temperature")
        );
        // one provenance per key
        let mut keys: Vec<&str> = m.provenance.iter().map(|(k, _)| k.as_str()).collect();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), m.provenance.len());
        // a master curve's own shift is kept
        let mut master = fitted_material("x".into(), &fit, "data.csv", 3.0);
        master.shift = Shift::Arrhenius {
            reference: 300.0,
            activation_energy: 1e5,
        };
        let copied = copy_like(&mut master, &like, true, "data.csv").unwrap();
        assert!(!copied.keys.contains(&"shift"));
        assert_eq!(shift_reference(master.shift), Some(300.0));
        // unknown ids name the flag and list the library
        let Err(CliError::Input(e)) = like_compound("nosuch") else {
            panic!("nosuch is not in the library");
        };
        assert!(
            e.starts_with("--like nosuch: unknown library material"),
            "{e}"
        );
        assert!(e.contains("nbr-70") && e.contains("vmq-70"), "{e}");
    }

    #[test]
    fn civil_dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(-1), (1969, 12, 31));
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        assert_eq!(civil_from_days(20_781), (2026, 11, 24));
    }
}
