//! `sealsim.fit_prony`: the workflow `sealsim::workflow::fit_prony` (the CLI's `fit-prony`)
//! on a data file, or on CSV text the Python side wrote from columns, so that the parser and
//! its messages are the command line's. Options are SI floats or strings with units.

use crate::{ScenarioError, blocking, guarded, internal};
use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use sealsim::material::fit::{FitSettings, Honour, Regularisation};
use sealsim::material::tts::ShiftLaw;
use sealsim::report::fit_prony::{material_file, summary};
use sealsim::scenario::fit_data::{FitKind, parse_fit_data, si_unit};
use sealsim::units::{self, Dimension};
use sealsim::workflow::fit_prony::{
    CsrOptions, FitOptions, FitPronyError, Like, PieceKind, TtsOptions, fit,
};
use std::path::PathBuf;

/// A workflow error as the Python exception: bad input `ScenarioError`, a bug `InternalError`.
fn fit_error(e: FitPronyError) -> PyErr {
    match e {
        FitPronyError::Input(m) => ScenarioError::new_err(m),
        FitPronyError::Internal(m) => internal(m),
    }
}

/// A positive quantity: a float in SI, or a string with its unit; `name` leads the message.
pub(crate) fn positive(
    value: Option<&Bound<'_, PyAny>>,
    name: &str,
    dimension: Dimension,
) -> PyResult<Option<f64>> {
    let Some(value) = value else { return Ok(None) };
    let v = if value.is_instance_of::<PyString>() {
        let text: String = value.extract()?;
        units::parse_quantity(&text, dimension)
            .map_err(|e| ScenarioError::new_err(format!("{name}: {e}")))?
    } else {
        value.extract::<f64>()?
    };
    if v.is_finite() && v > 0.0 {
        Ok(Some(v))
    } else {
        Err(ScenarioError::new_err(format!(
            "{name}: must be positive, got {v}"
        )))
    }
}

/// An absolute temperature: a float in K, or a string with its unit ("70 C").
pub(crate) fn temperature(value: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<f64>> {
    let Some(value) = value else { return Ok(None) };
    if value.is_instance_of::<PyString>() {
        let text: String = value.extract()?;
        units::parse_temperature(&text)
            .map(Some)
            .map_err(|e| ScenarioError::new_err(format!("{name}: {e}")))
    } else {
        let t: f64 = value.extract()?;
        if t.is_finite() && t > 0.0 {
            Ok(Some(t))
        } else {
            Err(ScenarioError::new_err(format!(
                "{name}: an absolute temperature in K must be positive, got {t}"
            )))
        }
    }
}

/// One of `choices` (name, value) by name, or a `ValueError` listing them.
fn choice<T: Copy>(value: &str, what: &str, choices: &[(&str, T)]) -> PyResult<T> {
    choices
        .iter()
        .find(|(n, _)| *n == value)
        .map(|(_, v)| *v)
        .ok_or_else(|| {
            let names: Vec<&str> = choices.iter().map(|(n, _)| *n).collect();
            PyValueError::new_err(format!(
                "unknown {what} \"{value}\": one of {}",
                names.join(", ")
            ))
        })
}

/// Where `fit_prony`'s data are: CSV text, or a file to read.
enum Data {
    Text(String),
    File(PathBuf),
}

impl Data {
    /// The CSV text: a file that cannot be read is `FileNotFoundError` (or `OSError`).
    fn read(self) -> PyResult<String> {
        match self {
            Data::Text(text) => Ok(text),
            Data::File(path) => std::fs::read_to_string(&path).map_err(|e| {
                let message = format!("{}: cannot read the data file: {e}", path.display());
                if e.kind() == std::io::ErrorKind::NotFound {
                    PyFileNotFoundError::new_err(message)
                } else {
                    PyOSError::new_err(message)
                }
            }),
        }
    }
}

/// `sealsim fit-prony`: a dict with `material_toml` (the `-o` file's text), `summary` (the
/// standard-error lines), `name`, `source`, `tau_s` and `E_i_Pa` (the terms), `E_inf_Pa`,
/// `E0_Pa`, `points`, `rms_relative_residual`, `max_relative_residual`, `window_s`.
/// `text`: CSV text to parse as if read from `source`; else the file `path`.
#[pyfunction]
#[pyo3(signature = (kind, path = None, text = None, source = None, terms_per_decade = 3.0,
                    regularisation = "gcv", honour = "both", name = None, temperature = None, like = None,
                    test_piece = None, squeeze = None, cross_section = None,
                    mean_diameter = None, diameter = None, height = None,
                    initial_force = None, reference_modulus = None, shift = None,
                    reference_temperature = None))]
#[allow(clippy::too_many_arguments)]
fn _fit_prony<'py>(
    py: Python<'py>,
    kind: &str,
    path: Option<PathBuf>,
    text: Option<String>,
    source: Option<String>,
    terms_per_decade: f64,
    regularisation: &str,
    honour: &str,
    name: Option<String>,
    temperature: Option<Bound<'py, PyAny>>,
    like: Option<String>,
    test_piece: Option<&str>,
    squeeze: Option<Bound<'py, PyAny>>,
    cross_section: Option<Bound<'py, PyAny>>,
    mean_diameter: Option<Bound<'py, PyAny>>,
    diameter: Option<Bound<'py, PyAny>>,
    height: Option<Bound<'py, PyAny>>,
    initial_force: Option<Bound<'py, PyAny>>,
    reference_modulus: Option<Bound<'py, PyAny>>,
    shift: Option<&str>,
    reference_temperature: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let kind = choice(
        kind,
        "kind",
        &[("relaxation", FitKind::Relaxation), ("dma", FitKind::Dma)],
    )?;
    if name.as_deref() == Some("") {
        return Err(PyValueError::new_err("name: must not be empty"));
    }
    // the data are read and parsed on the worker (with the fit); here only where they are
    let (file, source) = match (text, path) {
        (Some(text), _) => (
            PathBuf::from(source.unwrap_or_else(|| "<data>".to_owned())),
            Data::Text(text),
        ),
        (None, Some(path)) => (
            PathBuf::from(source.unwrap_or_else(|| path.display().to_string())),
            Data::File(path),
        ),
        (None, None) => return Err(PyValueError::new_err("fit_prony: give a path or columns")),
    };
    // parsed here (Python objects), a panic in it an InternalError; an error is raised on the
    // worker after those of `like` and of the data, in the order the checks always had
    let options = guarded(|| {
        let length =
            |v: &Option<Bound<'py, PyAny>>, n: &str| positive(v.as_ref(), n, Dimension::LENGTH);
        Ok(FitOptions {
            settings: FitSettings {
                terms_per_decade,
                regularisation: choice(
                    regularisation,
                    "regularisation",
                    &[("gcv", Regularisation::Gcv), ("none", Regularisation::None)],
                )?,
                honour: choice(
                    honour,
                    "honour",
                    &[("both", Honour::Both), ("storage", Honour::Storage)],
                )?,
            },
            name,
            temperature: self::temperature(temperature.as_ref(), "temperature")?,
            csr: CsrOptions {
                test_piece: test_piece
                    .map(|p| {
                        choice(
                            p,
                            "test_piece",
                            &[("ring", PieceKind::Ring), ("disc", PieceKind::Disc)],
                        )
                    })
                    .transpose()?,
                squeeze: positive(squeeze.as_ref(), "squeeze", Dimension::DIMENSIONLESS)?,
                cross_section: length(&cross_section, "cross_section")?,
                mean_diameter: length(&mean_diameter, "mean_diameter")?,
                diameter: length(&diameter, "diameter")?,
                height: length(&height, "height")?,
                initial_force: positive(initial_force.as_ref(), "initial_force", Dimension::FORCE)?,
                reference_modulus: positive(
                    reference_modulus.as_ref(),
                    "reference_modulus",
                    Dimension::PRESSURE,
                )?,
            },
            tts: TtsOptions {
                shift: shift
                    .map(|s| {
                        choice(
                            s,
                            "shift",
                            &[("wlf", ShiftLaw::Wlf), ("arrhenius", ShiftLaw::Arrhenius)],
                        )
                    })
                    .transpose()?,
                reference_temperature: self::temperature(
                    reference_temperature.as_ref(),
                    "reference_temperature",
                )?,
                plots: false,
            },
        })
    });
    let outcome = blocking(py, move || {
        let like = like
            .as_deref()
            .map(Like::of)
            .transpose()
            .map_err(fit_error)?;
        let text = source.read()?;
        let data = parse_fit_data(&text, &file, kind)
            .map_err(|e| ScenarioError::new_err(e.to_string()))?;
        fit(&data, &file, like.as_ref(), &options?)
            .map(|o| (material_file(&o), summary(&o), o))
            .map_err(fit_error)
    })??;
    let (toml_text, summary_text, o) = outcome;
    let prony = &o.material.prony;
    let dict = PyDict::new(py);
    dict.set_item("material_toml", toml_text)?;
    dict.set_item("summary", summary_text)?;
    dict.set_item("name", &o.material.name)?;
    dict.set_item("source", &o.source)?;
    dict.set_item(
        "tau_s",
        prony.terms().iter().map(|t| t.tau).collect::<Vec<f64>>(),
    )?;
    dict.set_item(
        "E_i_Pa",
        prony
            .terms()
            .iter()
            .map(|t| t.modulus)
            .collect::<Vec<f64>>(),
    )?;
    dict.set_item("E_inf_Pa", prony.long_term())?;
    dict.set_item("E0_Pa", prony.instantaneous())?;
    dict.set_item("points", o.fit.points)?;
    dict.set_item("rms_relative_residual", o.fit.rms_relative_residual)?;
    dict.set_item("max_relative_residual", o.fit.max_relative_residual)?;
    dict.set_item("window_s", (o.fit.window.0, o.fit.window.1))?;
    Ok(dict)
}

/// The SI unit of a fit data column by its name (`t` → `s`), as a units row takes it.
#[pyfunction]
fn _fit_column_unit(name: &str) -> Option<&'static str> {
    si_unit(name)
}

/// Adds this module's functions to the extension module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_fit_prony, m)?)?;
    m.add_function(wrap_pyfunction!(_fit_column_unit, m)?)?;
    Ok(())
}
