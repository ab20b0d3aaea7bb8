//! `sealsim fit-prony`: a Prony series fitted to relaxation or DMA data
//! ([`crate::material::fit`]), written as a material TOML file
//! ([`crate::report::material_toml`]).

use super::{CliError, write_output};
use crate::material::fit::{Fit, FitError, FitSettings, Regularisation, fit_dma, fit_relaxation};
use crate::material::{Material, Shift, Status};
use crate::report::material_toml::material_toml;
use crate::scenario::fit_data::{FitData, FitKind, read_fit_data};
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
    dma:        f,E_stor,E_loss  (f in Hz, or omega in rad/s; also storage/E', loss/E'')\n\
    Either a second header row of units (pyvisco style: \"s,MPa\" or \"Hz,MPa,MPa\"; E_stor and \
    E_loss in the same unit) or plain SI values (s, Pa, Hz).\n\
    The fit: non-negative least squares of E∞ and E_i on log-spaced τ_i over the data window \
    widened by a decade on each side, each point weighted by its relative error. One term per \
    decade leaves a ripple of a few per cent on a smooth spectrum; three make it negligible.\n\
    Output: a material TOML file (poisson_ratio = 0.5 assumed, no temperature shift).")]
pub struct FitPronyArgs {
    /// Data file (CSV): a relaxation test or a DMA master curve.
    #[arg(value_name = "DATA.csv")]
    pub data: PathBuf,

    /// What the data file holds.
    #[arg(long, value_enum)]
    pub kind: KindArg,

    /// Relaxation times per decade of the fit grid (1–4; 3 keeps the ripple of an off-grid
    /// spectrum below 0.04 %).
    #[arg(long, value_name = "N", default_value_t = crate::material::fit::DEFAULT_TERMS_PER_DECADE, value_parser = clap::value_parser!(u32).range(1..=4))]
    pub terms_per_decade: u32,

    /// Smoothing of the fitted spectrum: `gcv`, a second-difference penalty on the relative
    /// spectrum with its weight chosen by generalised cross-validation; `none`, plain NNLS.
    #[arg(long, value_enum, default_value_t = RegularisationArg::Gcv)]
    pub regularisation: RegularisationArg,

    /// Write the material TOML to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Material name \[default: the data file's name without extension\].
    #[arg(long, value_name = "NAME", value_parser = NonEmptyStringValueParser::new())]
    pub name: Option<String>,
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
    let kind = FitKind::from(args.kind);
    let data = read_fit_data(&args.data, kind).map_err(|e| CliError::Input(e.to_string()))?;
    let settings = FitSettings {
        terms_per_decade: args.terms_per_decade,
        regularisation: args.regularisation.into(),
    };
    let fit = match &data {
        FitData::Relaxation { times, moduli } => fit_relaxation(times, moduli, &settings),
        FitData::Dma {
            omegas,
            storage,
            loss,
        } => fit_dma(omegas, storage, loss, &settings),
    }
    .map_err(|e| fit_error(&args.data, e))?;

    let source = args.data.display().to_string();
    let name = args
        .name
        .clone()
        .unwrap_or_else(|| default_name(&args.data));
    let material = fitted_material(name, &fit, &source, args.terms_per_decade);
    let text = format!(
        "{}{}",
        header(&source, kind, &fit),
        material_toml(&material)
    );
    print_summary(&source, &fit);
    write_output(args.output.as_deref(), text.as_bytes())
}

/// The material of a fit: a user material, Poisson's ratio assumed, no temperature shift,
/// with the provenance of every number.
pub fn fitted_material(name: String, fit: &Fit, source: &str, terms_per_decade: u32) -> Material {
    let fitted = format!(
        "fitted by sealsim fit-prony (NNLS, {terms_per_decade} {} per decade) to {source}: \
         {} points, rms relative residual {:.2e}, max {:.2e}; {}",
        if terms_per_decade == 1 {
            "term"
        } else {
            "terms"
        },
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
    }
}

/// A comment block for the top of the file.
fn header(source: &str, kind: FitKind, fit: &Fit) -> String {
    let what = match kind {
        FitKind::Relaxation => "relaxation data",
        FitKind::Dma => "DMA data",
    };
    format!(
        "# Prony series fitted by sealsim fit-prony to {what} in {source} ({} points).\n\
         # E(t) = E∞ + Σ E_i exp(−t/τ_i), at the temperature of the data (or of its master curve):\n\
         # add a [material.shift] table for temperature dependence.\n",
        fit.points
    )
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
    eprintln!(
        "fit-prony: {source}: {} points, {} of {} grid terms kept + E∞; \
         rms relative residual {:.2e}, max {:.2e}\n\
         fit-prony: {}; simultaneous 95 % band of E(t) over the data window: \
         ±{:.2} % at most (at t = {} s)",
        fit.points,
        fit.prony.terms().len(),
        fit.grid_terms,
        fit.rms_relative_residual,
        fit.max_relative_residual,
        regularisation_note(fit),
        100.0 * widest,
        crate::units::show(at)
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

/// Data the fit refuses are bad input; a solver failure is an internal error.
fn fit_error(path: &Path, e: FitError) -> CliError {
    match e {
        FitError::Solver(_) | FitError::Degenerate(_) => {
            CliError::Internal(format!("{}: {e}", path.display()))
        }
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
                terms_per_decade: 1,
                ..FitSettings::default()
            },
        )
        .unwrap();
        let m = fitted_material("x".into(), &fit, "data.csv", 1);
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
}
