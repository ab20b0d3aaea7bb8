//! `sealsim.surface`: the workflow `sealsim::workflow::surface` (the CLI's `surface`) on
//! files, on a height grid or on line traces; grids and traces arrive as CSV text the Python
//! side wrote (shortest round-trip floats, so every value is exact) and are read by the
//! command line's parsers, with their messages.

use crate::{ScenarioError, blocking, guarded, internal, scenario_error};
use pyo3::exceptions::{PyFileNotFoundError, PyValueError};
use pyo3::prelude::*;
use sealsim::report::surface::SurfaceReport;
use sealsim::scenario::parse_height_map;
use sealsim::scenario::profile::parse_trace;
use sealsim::units::{self, Dimension};
use sealsim::workflow::surface::{
    SurfaceError, SurfaceOptions, callout, map_report, summary, traces_report,
};
use std::path::{Path, PathBuf};

/// A positive length: a float in m, or a string with its unit; `name` leads the message.
fn length(value: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<f64>> {
    crate::fit::positive(value, name, Dimension::LENGTH)
}

/// The length unit of heights (`"um"`) as m per unit, by the scenario files' unit parser.
pub(crate) fn height_unit(text: &str) -> PyResult<f64> {
    match units::parse_unit(text.trim()) {
        Ok((factor, dimension)) if dimension == Dimension::LENGTH => Ok(factor),
        _ => Err(ScenarioError::new_err(format!(
            "height_unit: expected a length unit such as m, um or nm, got {text:?}"
        ))),
    }
}

/// A surface error as the Python exception: a source that does not exist
/// `FileNotFoundError`, other bad input `ScenarioError`, each with the CLI's message.
fn surface_error(e: SurfaceError, sources: &[PathBuf]) -> PyErr {
    match e {
        SurfaceError::Input(m) if sources.iter().any(|p| !p.exists()) => {
            PyFileNotFoundError::new_err(m)
        }
        SurfaceError::Input(m) => ScenarioError::new_err(m),
        SurfaceError::Scenario(e) => scenario_error(e),
    }
}

/// The report as (JSON text, C(q) points, law points).
type Outcome = (String, Vec<(f64, f64)>, Vec<(f64, f64)>);

fn outcome(report: &SurfaceReport) -> PyResult<Outcome> {
    Ok((
        report.json().map_err(internal)?,
        report.spectrum_points.clone(),
        report.law_points.clone(),
    ))
}

/// `sealsim surface`: (the `--json` text, the C(q) points, the fitted or given law's points).
/// One of: `sources` (paths, as the CLI takes them), `grid` (CSV text of a height grid, heights
/// times `height_unit`, with `pixel_size`) or `traces` (a list of (name, CSV text `x,z`)).
/// `name`: the grid's name in the summary. Lengths are SI floats or strings with units.
#[pyfunction]
#[pyo3(signature = (sources = None, grid = None, traces = None, name = None, cutoff = None,
                    short_cutoff = None, tip_radius = None, pixel_size = None,
                    height_unit = None))]
#[allow(clippy::too_many_arguments)]
fn _surface<'py>(
    py: Python<'py>,
    sources: Option<Vec<PathBuf>>,
    grid: Option<String>,
    traces: Option<Vec<(String, String)>>,
    name: Option<String>,
    cutoff: Option<Bound<'py, PyAny>>,
    short_cutoff: Option<Bound<'py, PyAny>>,
    tip_radius: Option<Bound<'py, PyAny>>,
    pixel_size: Option<Bound<'py, PyAny>>,
    height_unit: Option<&str>,
) -> PyResult<Outcome> {
    // the options' parsing here, a panic in it an InternalError; every file, grid and trace
    // is read on the worker (a height map can take seconds)
    let (options, unit) = guarded(|| {
        let unit = height_unit.map(self::height_unit).transpose()?;
        let options = SurfaceOptions {
            cutoff: length(cutoff.as_ref(), "cutoff")?,
            short_cutoff: length(short_cutoff.as_ref(), "short_cutoff")?,
            tip_radius: length(tip_radius.as_ref(), "tip_radius")?,
            pixel_size: length(pixel_size.as_ref(), "pixel_size")?,
            height_unit: unit,
        };
        Ok((options, unit))
    })?;
    let input = |e: SurfaceError| surface_error(e, &[]);
    // the report's JSON is written on the worker too
    match (sources, grid, traces) {
        (Some(sources), None, None) => blocking(py, move || {
            let report = summary(&sources, &options).map_err(|e| surface_error(e, &sources))?;
            outcome(&report)
        })?,
        (None, Some(grid), None) => {
            callout(&options).map_err(input)?;
            let pixel = options
                .pixel_size
                .ok_or_else(|| PyValueError::new_err("surface: a height grid needs pixel_size"))?;
            let name = name.unwrap_or_else(|| "<heights>".to_owned());
            blocking(py, move || {
                let map = parse_height_map(&grid, Path::new(&name), pixel, unit.unwrap_or(1.0))
                    .map_err(|e| ScenarioError::new_err(e.to_string()))?;
                outcome(&map_report(name, &map, options.cutoff).map_err(input)?)
            })?
        }
        (None, None, Some(traces)) => {
            callout(&options).map_err(input)?;
            blocking(py, move || {
                let named = traces
                    .iter()
                    .map(|(name, text)| {
                        parse_trace(text, Path::new(name))
                            .map(|t| (name.clone(), t))
                            .map_err(|e| ScenarioError::new_err(e.to_string()))
                    })
                    .collect::<PyResult<Vec<_>>>()?;
                outcome(&traces_report(&named, options.cutoff, options.tip_radius).map_err(input)?)
            })?
        }
        _ => Err(PyValueError::new_err(
            "surface: give one of sources, grid or traces",
        )),
    }
}

/// Adds this module's functions to the extension module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_surface, m)?)?;
    Ok(())
}
