//! `sealsim fit-prony` as a library call: a Prony series fitted to relaxation, CSR or DMA data
//! ([`crate::material::fit`]; a master curve by time–temperature superposition,
//! [`crate::material::tts`], for relaxation data at several temperatures) and the material it
//! gives, with the provenance of every number. The material file's text and the summary
//! lines are rendered by `report::fit_prony`; the command line parses the flags into
//! [`FitOptions`] (SI), calls [`fit`], prints and writes.

use crate::material::csr::{Normalisation, TestPiece};
use crate::material::fit::{Fit, FitError, FitSettings, Regularisation, fit_dma, fit_relaxation};
use crate::material::tts::{
    FittedLaw, Isotherm as TtsIsotherm, MasterCurve, Parameter, ShiftLaw, TtsError, TtsSettings,
    master_curve,
};
use crate::material::{Material, Shift, Status};
use crate::scenario::fit_data::{FitData, FitKind, Isotherm, Measured, show_kelvin};
use crate::scenario::library;
use crate::units::show;
use std::fmt;
use std::path::Path;

/// Poisson's ratio written to fitted materials, and where it comes from.
const ASSUMED_POISSON_RATIO: f64 = 0.5;
const ASSUMED_POISSON_PROVENANCE: &str =
    "assumed: incompressible rubber; replace with a measured value";

/// An rms relative residual above this earns a warning: the series does not describe the data.
pub const POOR_FIT: f64 = 0.05;

/// Why a fit could not be made. The messages name the command line's flags (`--squeeze`, …),
/// as `sealsim fit-prony` prints them.
#[derive(Debug, Clone, PartialEq)]
pub enum FitPronyError {
    /// Data, options or a combination of them the user must fix.
    Input(String),
    /// A solver failure or a library compound that does not load: a bug.
    Internal(String),
}

impl fmt::Display for FitPronyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FitPronyError::Input(m) | FitPronyError::Internal(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for FitPronyError {}

fn input(message: impl Into<String>) -> FitPronyError {
    FitPronyError::Input(message.into())
}

/// The kind of a compression-stress-relaxation test piece.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PieceKind {
    /// A ring or O-ring compressed across its cord (Lindley's force law, as in the life run).
    Ring,
    /// A cylindrical disc between lubricated plates (neo-Hookean uniaxial compression).
    Disc,
}

impl PieceKind {
    fn name(self) -> &'static str {
        match self {
            PieceKind::Ring => "ring",
            PieceKind::Disc => "disc",
        }
    }
}

/// How a compression-stress-relaxation force (or retained force) becomes a modulus
/// (`crate::material::csr`); SI: m, N, Pa, and the squeeze as a fraction. `None`: not given.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CsrOptions {
    pub test_piece: Option<PieceKind>,
    /// Compression as a fraction of the cord diameter or disc height.
    pub squeeze: Option<f64>,
    /// Ring cord diameter \[m\].
    pub cross_section: Option<f64>,
    /// Ring mean diameter \[m\].
    pub mean_diameter: Option<f64>,
    /// Disc diameter \[m\].
    pub diameter: Option<f64>,
    /// Disc height before compression \[m\].
    pub height: Option<f64>,
    /// The force at a retention of 1 \[N\], for retained data with a test piece.
    pub initial_force: Option<f64>,
    /// A stated modulus at the first force reading or at a retention of 1 \[Pa\].
    pub reference_modulus: Option<f64>,
}

impl CsrOptions {
    /// Whether any option was given.
    fn given(&self) -> bool {
        self.test_piece.is_some()
            || self.squeeze.is_some()
            || self.cross_section.is_some()
            || self.mean_diameter.is_some()
            || self.diameter.is_some()
            || self.height.is_some()
            || self.initial_force.is_some()
            || self.reference_modulus.is_some()
    }
}

/// Time–temperature superposition of relaxation data at several temperatures.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct TtsOptions {
    /// The shift law fitted to the shift factors (`None`: WLF).
    pub shift: Option<ShiftLaw>,
    /// Reference temperature of the master curve \[K\] (`None`: the data temperature nearest
    /// their median).
    pub reference_temperature: Option<f64>,
    /// Whether the master-curve charts were asked for (they need a master curve).
    pub plots: bool,
}

impl TtsOptions {
    /// Whether any master-curve option was given.
    fn given(&self) -> bool {
        self.shift.is_some() || self.reference_temperature.is_some() || self.plots
    }
}

/// What to fit and how, in SI.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FitOptions {
    /// Grid density and smoothing of the fit.
    pub settings: FitSettings,
    /// Material name (`None`: the data file's name without extension).
    pub name: Option<String>,
    /// The test temperature \[K\] of data without a temperature column.
    pub temperature: Option<f64>,
    pub csr: CsrOptions,
    pub tts: TtsOptions,
}

/// A library compound whose unmeasured properties `--like` copies.
pub struct Like {
    /// The library id, e.g. `nbr-70`.
    pub id: &'static str,
    pub compound: Material,
}

impl Like {
    /// The library compound `id`, or an input error naming the flag and listing the ids.
    pub fn of(id: &str) -> Result<Like, FitPronyError> {
        let entry = library::get(id).map_err(|e| {
            input(format!(
                "--like {id}: {e} (`sealsim materials list` describes them)"
            ))
        })?;
        let compound = entry
            .load()
            .map_err(|e| FitPronyError::Internal(format!("--like {id}: {e}")))?;
        Ok(Like {
            id: entry.id,
            compound,
        })
    }
}

/// What `--like` copied (parameter keys, in file order) and what it noted.
#[derive(Debug, Clone, PartialEq)]
pub struct Copied {
    /// The library id and the compound's status.
    pub id: &'static str,
    pub status: Status,
    pub keys: Vec<&'static str>,
    pub notes: Vec<String>,
}

/// A fit and the material it gives.
#[derive(Debug, Clone)]
pub struct FitOutcome {
    /// The data as named in messages and the provenance (the file as given).
    pub source: String,
    pub kind: FitKind,
    /// The fit (of the master curve, for data at several temperatures).
    pub fit: Fit,
    /// The fitted material, with the provenance of every parameter.
    pub material: Material,
    /// How the measured column became moduli, when it was not one.
    pub normalisation: Option<(Normalisation, Measured)>,
    /// What `--like` copied.
    pub copied: Option<Copied>,
    /// The master curve of data at several temperatures.
    pub master: Option<MasterCurve>,
}

/// Fits `data` (read from `path`, which names it in messages and gives the default name),
/// copying what the test does not measure from `like`.
///
/// # Errors
/// [`FitPronyError::Input`] for data or options the fit refuses, with the command line's
/// message; [`FitPronyError::Internal`] for a solver failure.
pub fn fit(
    data: &FitData,
    path: &Path,
    like: Option<&Like>,
    options: &FitOptions,
) -> Result<FitOutcome, FitPronyError> {
    let source = path.display().to_string();
    let (fit, data_temperature, normalisation) = match data {
        FitData::Relaxation {
            measured,
            isotherms,
            temperature_column,
        } => {
            let normalisation = normalisation(&options.csr, *measured, isotherms)?;
            if isotherms.len() > 1 {
                return master(
                    path,
                    options,
                    isotherms,
                    normalisation.as_ref(),
                    *measured,
                    like,
                );
            }
            let [isotherm] = isotherms.as_slice() else {
                return Err(FitPronyError::Internal("a data file without points".into()));
            };
            if options.tts.given() {
                let (line, column) = temperature_column.unwrap_or((1, 1));
                return Err(input(format!(
                    "{source}:{line}:{column}: {}: --shift, --reference-temperature and the \
                     master-curve plots need relaxation data at two or more temperatures (a \
                     temperature column)",
                    match isotherm.temperature {
                        Some(t) => format!("one temperature ({})", show_kelvin(t)),
                        None => "no temperature column".into(),
                    }
                )));
            }
            if let (Some(t), Some(_)) = (isotherm.temperature, options.temperature) {
                return Err(input(format!(
                    "--temperature: the data give their temperature ({}) in a column",
                    show_kelvin(t)
                )));
            }
            let moduli = match &normalisation {
                Some(n) => n.moduli(&isotherm.values),
                None => isotherm.values.clone(),
            };
            let fit = fit_relaxation(&isotherm.times, &moduli, &options.settings)
                .map_err(|e| fit_error(path, e))?;
            (
                fit,
                isotherm.temperature.or(options.temperature),
                normalisation.map(|n| (n, *measured)),
            )
        }
        FitData::Dma {
            omegas,
            storage,
            loss,
        } => {
            if options.tts.given() {
                return Err(input(
                    "--shift, --reference-temperature and the master-curve plots need \
                     relaxation data at several temperatures; DMA data are fitted as a master \
                     curve already shifted",
                ));
            }
            if options.csr.given() {
                return Err(input(
                    "--test-piece, --squeeze, --reference-modulus etc. convert CSR forces; DMA \
                     data give moduli",
                ));
            }
            let fit = fit_dma(omegas, storage, loss, &options.settings)
                .map_err(|e| fit_error(path, e))?;
            (fit, options.temperature, None)
        }
    };

    let name = options.name.clone().unwrap_or_else(|| default_name(path));
    let mut material = fitted_material(name, &fit, &source, options.settings.terms_per_decade);
    if let Some(note) = consistency_note(&fit) {
        note_fit(&mut material, &note);
    }
    if let Some(t) = data_temperature {
        material.data_temperature = Some((t, t));
        material.provenance.push((
            "data_temperature".into(),
            format!("the test temperature of {source}"),
        ));
    }
    if let Some((n, measured)) = &normalisation {
        note_fit(&mut material, &moduli_note(n, *measured));
    }
    let copied = like
        .map(|l| copy_like(&mut material, l, false, &source))
        .transpose()?;
    Ok(FitOutcome {
        source,
        kind: match data {
            FitData::Relaxation { .. } => FitKind::Relaxation,
            FitData::Dma { .. } => FitKind::Dma,
        },
        fit,
        material,
        normalisation,
        copied,
        master: None,
    })
}

/// [`fit`] of data at several temperatures: the master curve and its material.
fn master(
    path: &Path,
    options: &FitOptions,
    isotherms: &[Isotherm],
    normalisation: Option<&Normalisation>,
    measured: Measured,
    like: Option<&Like>,
) -> Result<FitOutcome, FitPronyError> {
    let source = path.display().to_string();
    if options.temperature.is_some() {
        return Err(input(
            "--temperature: the data give their temperatures in a column",
        ));
    }
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
            law: options.tts.shift.unwrap_or(ShiftLaw::Wlf),
            reference: options.tts.reference_temperature,
            fit: options.settings,
        },
    )
    .map_err(|e| match e {
        TtsError::Fit(FitError::Solver(_) | FitError::Degenerate(_)) => {
            FitPronyError::Internal(format!("{source}: {e}"))
        }
        _ => input(format!("{source}: {e}")),
    })?;
    let name = options.name.clone().unwrap_or_else(|| default_name(path));
    let mut material = fitted_material(name, &m.fit, &source, options.settings.terms_per_decade);
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
        note.push_str(&moduli_note(n, measured));
    }
    note_fit(&mut material, &note);
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
    Ok(FitOutcome {
        source,
        kind: FitKind::Relaxation,
        fit: m.fit.clone(),
        material,
        normalisation: normalisation.map(|n| (*n, measured)),
        copied,
        master: Some(m),
    })
}

/// How the measured column became moduli, as a provenance note: "; moduli from the … by …".
fn moduli_note(n: &Normalisation, measured: Measured) -> String {
    format!(
        "; moduli from the {} by {}",
        measured.describe(),
        describe(n)
    )
}

/// Appends `note` to the provenance of the fitted parameters (`prony`, `long_term_modulus`).
/// The provenance note of a DMA fit whose data fail the Kramers–Kronig check
/// (`material::fit`): the inconsistent bands' count, what was honoured and both long-term
/// moduli, so that the material file says where E∞ comes from.
fn consistency_note(fit: &Fit) -> Option<String> {
    let c = fit.consistency.as_ref()?;
    let worst = c.worst()?;
    Some(format!(
        "; Kramers–Kronig check: E″ disagrees with E′ in {} decade(s) of frequency (worst: \
         measured E″ {:.3}× the E″ that E′ implies at ω = {}–{} rad/s); {}; E′ alone gives \
         E∞ = {} Pa",
        c.inconsistent().count(),
        worst.ratio,
        show(worst.omegas.0),
        show(worst.omegas.1),
        if c.replaced_loss > 0 {
            format!(
                "E′ honoured (--honour storage): {} E″ values replaced by the E″ that E′ \
                 implies",
                c.replaced_loss
            )
        } else {
            "every E′ and E″ value fitted (the lower E∞: more leak)".to_string()
        },
        show(c.storage_long_term)
    ))
}

fn note_fit(material: &mut Material, note: &str) {
    for (key, text) in material.provenance.iter_mut() {
        if key == "prony" || key == "long_term_modulus" {
            text.push_str(note);
        }
    }
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

fn required(value: Option<f64>, name: &str, piece: PieceKind) -> Result<f64, FitPronyError> {
    value.ok_or_else(|| input(format!("--test-piece {} needs --{name}", piece.name())))
}

/// The test piece of the options, when one is named.
fn test_piece(c: &CsrOptions) -> Result<Option<TestPiece>, FitPronyError> {
    let Some(kind) = c.test_piece else {
        for (given, name) in [
            (c.squeeze, "squeeze"),
            (c.cross_section, "cross-section"),
            (c.mean_diameter, "mean-diameter"),
            (c.diameter, "diameter"),
            (c.height, "height"),
        ] {
            if given.is_some() {
                return Err(input(format!(
                    "--{name} describes a test piece: give --test-piece ring or disc"
                )));
            }
        }
        return Ok(None);
    };
    let piece = match kind {
        PieceKind::Ring => {
            for (given, name) in [(c.diameter, "diameter"), (c.height, "height")] {
                if given.is_some() {
                    return Err(input(format!(
                        "--{name} is a disc's: a ring takes --cross-section and --mean-diameter"
                    )));
                }
            }
            TestPiece::Ring {
                cross_section: required(c.cross_section, "cross-section", kind)?,
                mean_diameter: required(c.mean_diameter, "mean-diameter", kind)?,
                squeeze: required(c.squeeze, "squeeze", kind)?,
            }
        }
        PieceKind::Disc => {
            for (given, name) in [
                (c.cross_section, "cross-section"),
                (c.mean_diameter, "mean-diameter"),
            ] {
                if given.is_some() {
                    return Err(input(format!(
                        "--{name} is a ring's: a disc takes --diameter (and --height)"
                    )));
                }
            }
            TestPiece::Disc {
                diameter: required(c.diameter, "diameter", kind)?,
                height: c.height,
                squeeze: required(c.squeeze, "squeeze", kind)?,
            }
        }
    };
    piece
        .check()
        .map_err(|e| input(format!("--test-piece: {e}")))?;
    Ok(Some(piece))
}

/// How the measured column becomes moduli (`None`: it is one).
fn normalisation(
    c: &CsrOptions,
    measured: Measured,
    isotherms: &[Isotherm],
) -> Result<Option<Normalisation>, FitPronyError> {
    let piece = test_piece(c)?;
    let (reference, initial) = (c.reference_modulus, c.initial_force);
    if piece.is_some() && reference.is_some() {
        return Err(input(
            "give either a test piece or --reference-modulus, not both",
        ));
    }
    let first_value = isotherms
        .first()
        .and_then(|i| i.values.first())
        .copied()
        .unwrap_or(1.0);
    match measured {
        Measured::Modulus => {
            if c.given() {
                return Err(input(
                    "--test-piece, --squeeze, --reference-modulus etc. convert CSR forces; this \
                     file gives the relaxation modulus itself",
                ));
            }
            Ok(None)
        }
        Measured::Force => {
            if initial.is_some() {
                return Err(input(
                    "--initial-force is for retained-force data; this file gives forces",
                ));
            }
            match (piece, reference) {
                (Some(piece), None) => Ok(Some(Normalisation::Piece(piece))),
                (None, Some(modulus)) => Ok(Some(Normalisation::Modulus {
                    modulus,
                    reference_value: first_value,
                })),
                _ => Err(input(
                    "forces need a test piece (--test-piece ring|disc with its dimensions and \
                     --squeeze) or a stated --reference-modulus at the first reading",
                )),
            }
        }
        Measured::Retained => {
            if isotherms.len() > 1 {
                return Err(input(
                    "retained force at several temperatures cannot be put on one curve: each \
                     series is relative to its own initial force; give the forces (N) with the \
                     test piece",
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
                (None, Some(_), Some(_)) => Err(input(
                    "--initial-force goes with a test piece, not with --reference-modulus",
                )),
                (Some(_), None, None) => Err(input(
                    "retained-force data with a test piece need --initial-force (the force at a \
                     retention of 1)",
                )),
                _ => Err(input(
                    "retained-force data need --reference-modulus (the modulus at a retention of \
                     1) or a test piece with --initial-force",
                )),
            }
        }
    }
}

/// The normalisation in words, for the provenance and the summary.
pub fn describe(n: &Normalisation) -> String {
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
        data_reduced_time: Some(fit.window),
        provenance,
        ..Material::user(name, fit.prony.clone(), ASSUMED_POISSON_RATIO)
    }
}

/// "1 term", "3 terms", "0.5 terms" (of a number of terms per decade).
fn per_decade_text(n: f64) -> String {
    format!("{} {}", show(n), if n == 1.0 { "term" } else { "terms" })
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
) -> Result<Copied, FitPronyError> {
    let c = &like.compound;
    let id = like.id;
    let prefix = format!("copied from library compound {id} (sealsim fit-prony --like)");
    let from = |key: &str| match c.provenance_of(key) {
        Some(text) => format!("{prefix}: {text}"),
        None => prefix.clone(),
    };
    let mut copied = Copied {
        id,
        status: c.status,
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
            input(format!(
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
    if let Some(class) = &c.class {
        material.class = Some(class.clone());
        copied.notes.push(format!(
            "class = \"{class}\" copied: a gas run with this file takes {class}'s permeation \
             figures (sourced, or a stated NOT SOURCED bound; docs/model.md §13.4)"
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

/// The regularisation of a fit in words: method, λ and the effective number of parameters.
pub fn regularisation_note(fit: &Fit) -> String {
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

/// `value (95 % interval lo – hi)`, or `value ± std error (no interval: …)`.
fn parameter(p: &Parameter, scale: f64, digits: usize) -> String {
    match p.interval {
        Some((lo, hi)) => format!(
            "{:.digits$} (95 % interval {:.digits$} – {:.digits$})",
            p.value * scale,
            lo * scale,
            hi * scale
        ),
        None => format!(
            "{:.digits$} ± {:.digits$} (standard error; no interval)",
            p.value * scale,
            p.std_error * scale
        ),
    }
}

/// The shift law in words with its parameters and intervals.
pub fn law_text(m: &MasterCurve) -> String {
    match m.law.law {
        FittedLaw::Wlf { c1, c2 } => format!(
            "WLF log10 a_T = −C1 (T − Tref)/(C2 + T − Tref), Tref = {:.2} K: C1 = {}, C2 = {} K",
            m.reference,
            parameter(&c1, 1.0, 3),
            parameter(&c2, 1.0, 2)
        ),
        FittedLaw::Arrhenius { activation_energy } => format!(
            "Arrhenius ln a_T = (Ea/R)(1/T − 1/Tref), Tref = {:.2} K: Ea = {} kJ/mol",
            m.reference,
            parameter(&activation_energy, 1e-3, 2)
        ),
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
fn fit_error(path: &Path, e: FitError) -> FitPronyError {
    match e {
        FitError::Solver(_) | FitError::Degenerate(_) => {
            FitPronyError::Internal(format!("{}: {e}", path.display()))
        }
        FitError::TooFewPoints {
            points,
            values,
            unknowns,
            max_terms_per_decade,
        } if points >= 3 => input(format!(
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
        _ => input(format!("{}: {e}", path.display())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::fit::{FitSettings, fit_relaxation};

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
        let like = Like::of("nbr-70").unwrap();
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
        let Err(FitPronyError::Input(e)) = Like::of("nosuch") else {
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
