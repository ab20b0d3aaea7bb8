//! `sealsim._sealsim`: the extension module behind the Python package `sealsim` (issue 34).
//!
//! Every call goes through the library's workflows ([`sealsim::workflow`]) and its reports
//! ([`sealsim::report`]), never through the command line, so a Python result is the CLI's:
//! tables are the report's CSV text parsed back into columns (its numbers are shortest
//! round-trip scientific notation, so every value crosses bit for bit), summaries its JSON text
//! (parsed by the Python side). Numbers are SI floats.
//!
//! Long work runs on a worker thread with the GIL released; the calling thread waits for it and
//! checks for signals every 50 ms, so Ctrl-C raises `KeyboardInterrupt` at once (the abandoned
//! computation finishes in the background and its result is dropped). A panic in the library
//! becomes `sealsim.InternalError` (a `RuntimeError`), never a crash of the interpreter.

mod fit;
mod surface;

use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use sealsim::leak::Fidelity;
use sealsim::material::Material;
use sealsim::report::csv::{gas_leak_table, leak_table, motion_leak_table};
use sealsim::report::life::{CompareRow, Summary, compare_table, history_table_for};
use sealsim::scenario::study::Study;
use sealsim::scenario::{Scenario, ScenarioError as RustScenarioError, library};
use sealsim::units::{self, Dimension};
use sealsim::workflow;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::mpsc;
use std::time::Duration;

pyo3::create_exception!(
    sealsim,
    ScenarioError,
    PyValueError,
    "An invalid scenario, study or input: the message names the file, the line and the key, as \
     the command line prints it."
);
pyo3::create_exception!(
    sealsim,
    InternalError,
    PyRuntimeError,
    "A bug in sealsim (a panic or a non-finite result caught at the boundary): please report it."
);

/// The file name given to a scenario or study read from a string.
const STRING_SOURCE: &str = "<string>";

/// A scenario error as the Python exception: a file that cannot be read is `FileNotFoundError`
/// (or `OSError`), anything else `ScenarioError` with the CLI's message.
fn scenario_error(e: RustScenarioError) -> PyErr {
    match &e {
        RustScenarioError::Read { source, .. } => {
            if source.kind() == std::io::ErrorKind::NotFound {
                PyFileNotFoundError::new_err(e.to_string())
            } else {
                PyOSError::new_err(e.to_string())
            }
        }
        _ => ScenarioError::new_err(e.to_string()),
    }
}

fn internal(e: impl std::fmt::Display) -> PyErr {
    InternalError::new_err(format!("internal error: {e}"))
}

/// Runs `work` on a worker thread with the GIL released, checking for signals (Ctrl-C) every
/// 50 ms; a panic is an [`InternalError`].
fn blocking<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce() -> T + Send + 'static,
{
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name("sealsim".into())
        .spawn(move || {
            let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(work));
            let _ = tx.send(outcome);
        })
        .map_err(|e| PyOSError::new_err(format!("cannot start a worker thread: {e}")))?;
    let mut rx = rx;
    loop {
        let (received, back) = py.detach(move || {
            let received = rx.recv_timeout(Duration::from_millis(50));
            (received, rx)
        });
        rx = back;
        match received {
            Ok(Ok(value)) => return Ok(value),
            Ok(Err(payload)) => {
                let what = payload
                    .downcast_ref::<&str>()
                    .map(|s| (*s).to_owned())
                    .or_else(|| payload.downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "a panic".to_owned());
                return Err(internal(format!("sealsim panicked: {what}")));
            }
            Err(mpsc::RecvTimeoutError::Timeout) => py.check_signals()?,
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(internal("the worker thread ended without a result"));
            }
        }
    }
}

/// A CSV table (the report's text) as an ordered dict of columns: a column whose every
/// non-empty cell is a number is a list of floats (an empty cell is NaN: no value), any other a
/// list of strings. The reports write shortest round-trip numbers, so the floats are exact.
fn columns<'py>(py: Python<'py>, csv_text: &str) -> PyResult<Bound<'py, PyDict>> {
    let mut reader = ::csv::Reader::from_reader(csv_text.as_bytes());
    let header: Vec<String> = reader
        .headers()
        .map_err(internal)?
        .iter()
        .map(str::to_owned)
        .collect();
    let rows: Vec<::csv::StringRecord> = reader
        .records()
        .collect::<Result<_, _>>()
        .map_err(internal)?;
    let dict = PyDict::new(py);
    for (j, name) in header.iter().enumerate() {
        let cells: Vec<&str> = rows.iter().map(|r| r.get(j).unwrap_or("")).collect();
        let numbers: Option<Vec<f64>> = cells
            .iter()
            .map(|c| {
                if c.is_empty() {
                    Some(f64::NAN)
                } else {
                    c.parse::<f64>().ok()
                }
            })
            .collect();
        match numbers {
            Some(v) => dict.set_item(name, v)?,
            None => dict.set_item(name, cells)?,
        }
    }
    Ok(dict)
}

/// A fidelity level by its name (`exact`, `critical-junction`, …), as `--fidelity` takes it.
fn fidelity(name: Option<&str>) -> PyResult<Option<Fidelity>> {
    name.map(|n| {
        Fidelity::ALL
            .into_iter()
            .find(|f| f.name() == n)
            .ok_or_else(|| {
                let names: Vec<&str> = Fidelity::ALL.iter().map(|f| f.name()).collect();
                PyValueError::new_err(format!(
                    "unknown fidelity \"{n}\": one of {}",
                    names.join(", ")
                ))
            })
    })
    .transpose()
}

/// A Python value as a TOML value (str, bool, int, float, list, tuple, dict).
fn toml_value(value: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() {
        return Ok(toml::Value::Integer(value.extract()?));
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(value.extract()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(value.extract()?));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let mut items = Vec::new();
        for item in value.try_iter()? {
            items.push(toml_value(&item?)?);
        }
        return Ok(toml::Value::Array(items));
    }
    if let Ok(dict) = value.cast::<PyDict>() {
        let mut table = toml::Table::new();
        for (k, v) in dict.iter() {
            table.insert(k.extract::<String>()?, toml_value(&v)?);
        }
        return Ok(toml::Value::Table(table));
    }
    Err(PyValueError::new_err(format!(
        "cannot write a {} into a scenario: give a str (\"22 %\"), a number, a bool, a list or \
         a dict",
        value.get_type().name()?
    )))
}

/// A scenario: the validated model (SI), its TOML text and its file.
#[pyclass(name = "Scenario", module = "sealsim._sealsim", frozen)]
struct PyScenario {
    inner: Arc<Scenario>,
    text: String,
    /// The file as given (the summary's `scenario_file`, as the CLI's).
    file: String,
}

impl PyScenario {
    fn new(text: String, file: String) -> PyResult<PyScenario> {
        let scenario = Scenario::from_str(&text, Path::new(&file)).map_err(scenario_error)?;
        Ok(PyScenario {
            inner: Arc::new(scenario),
            text,
            file,
        })
    }

    /// The scenario with its fidelity overridden, shared when not.
    fn at(&self, level: Option<Fidelity>) -> Arc<Scenario> {
        match level {
            None => Arc::clone(&self.inner),
            Some(f) => {
                let mut s = (*self.inner).clone();
                s.life.fidelity = f;
                Arc::new(s)
            }
        }
    }
}

#[pymethods]
impl PyScenario {
    /// Reads and validates a scenario file.
    #[staticmethod]
    fn from_file(path: PathBuf) -> PyResult<PyScenario> {
        let text = std::fs::read_to_string(&path).map_err(|source| {
            scenario_error(RustScenarioError::Read {
                path: path.clone(),
                source,
            })
        })?;
        PyScenario::new(text, path.display().to_string())
    }

    /// Validates scenario TOML text; `path` names it in messages and resolves relative data
    /// files (default `<string>`, relative to the working directory).
    #[staticmethod]
    #[pyo3(signature = (text, path = None))]
    fn from_toml(text: String, path: Option<PathBuf>) -> PyResult<PyScenario> {
        let file = path.map_or_else(|| STRING_SOURCE.to_owned(), |p| p.display().to_string());
        PyScenario::new(text, file)
    }

    /// A new scenario with dotted keys replaced, as a study's `[vary]` sets them.
    fn replace(&self, values: &Bound<'_, PyDict>) -> PyResult<PyScenario> {
        let mut assignments = Vec::new();
        for (k, v) in values.iter() {
            assignments.push((k.extract::<String>()?, toml_value(&v)?));
        }
        let (text, scenario) = workflow::replace(&self.text, Path::new(&self.file), &assignments)
            .map_err(scenario_error)?;
        Ok(PyScenario {
            inner: Arc::new(scenario),
            text,
            file: self.file.clone(),
        })
    }

    /// The scenario's name.
    #[getter]
    fn name(&self) -> String {
        self.inner.name.clone()
    }

    /// The file (as given), or `<string>`.
    #[getter]
    fn path(&self) -> String {
        self.file.clone()
    }

    /// The TOML text.
    #[getter]
    fn text(&self) -> String {
        self.text.clone()
    }

    /// The input's warnings (`FILE:LINE: KEY: …`).
    #[getter]
    fn input_warnings(&self) -> Vec<String> {
        self.inner.warnings.clone()
    }

    /// The fidelity level the scenario runs at.
    #[getter]
    fn fidelity(&self) -> &'static str {
        self.inner.life.fidelity.name()
    }

    /// `sealsim run`: (history columns, summary JSON text).
    #[pyo3(signature = (fidelity = None))]
    fn _run<'py>(
        &self,
        py: Python<'py>,
        fidelity: Option<&str>,
    ) -> PyResult<(Bound<'py, PyDict>, String)> {
        let scenario = self.at(self::fidelity(fidelity)?);
        let file = self.file.clone();
        let (history, summary) = blocking(py, move || {
            let result = workflow::life::run(&scenario, &mut |_, _| {});
            let history = history_table_for(&result, &scenario.life.fluid);
            let summary = Summary::new(&scenario.name, &file, &scenario.life, &result).to_json();
            (history, summary)
        })?;
        let history = history.map_err(internal)?;
        let summary = summary.map_err(internal)?;
        Ok((columns(py, &history)?, summary))
    }

    /// `sealsim leak`: (table columns, findings JSON text). `pressures` in Pa (or strings with
    /// units); `None`: the scenario's own.
    #[pyo3(signature = (pressures = None, fidelity = None))]
    fn _leak<'py>(
        &self,
        py: Python<'py>,
        pressures: Option<Vec<Bound<'py, PyAny>>>,
        fidelity: Option<&str>,
    ) -> PyResult<(Bound<'py, PyDict>, String)> {
        let pressures = pressures
            .map(|list| list.iter().map(pressure).collect::<PyResult<Vec<f64>>>())
            .transpose()?;
        let level = self::fidelity(fidelity)?.unwrap_or(self.inner.life.fidelity);
        let scenario = Arc::clone(&self.inner);
        let (csv, findings) = blocking(py, move || {
            let outcome =
                workflow::leak::evaluate(&scenario, pressures.as_deref(), level, &mut |_, _| {});
            let csv = match (&outcome.motion, scenario.life.fluid.mean_pressure()) {
                (None, Some(p)) => gas_leak_table(&outcome.points, p),
                (None, None) => leak_table(&outcome.points),
                (Some(motion), _) => motion_leak_table(&outcome.points, motion, outcome.stroke),
            };
            let findings =
                serde_json::to_string(&sealsim::report::findings::records(&outcome.findings));
            (csv, findings)
        })?;
        let csv = csv.map_err(internal)?;
        Ok((columns(py, &csv)?, findings.map_err(internal)?))
    }

    fn __repr__(&self) -> String {
        format!("Scenario({:?}, path={:?})", self.inner.name, self.file)
    }
}

/// A nominal pressure: a float in Pa, or a string with its unit ("2 bar").
fn pressure(value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let p = if value.is_instance_of::<PyString>() {
        let text: String = value.extract()?;
        units::parse_quantity(&text, Dimension::PRESSURE)
            .map_err(|e| PyValueError::new_err(format!("pressure \"{text}\": {e}")))?
    } else {
        value.extract::<f64>()?
    };
    if p.is_finite() && p > 0.0 {
        Ok(p)
    } else {
        Err(PyValueError::new_err(format!(
            "a nominal pressure must be positive and finite, got {p} Pa"
        )))
    }
}

/// A library compound by id, or a material file by path (as `sealsim compare --materials`).
fn compound(spec: &str) -> PyResult<Material> {
    match library::get(spec) {
        Ok(entry) => entry.load().map_err(scenario_error),
        Err(_) if spec.contains('/') || spec.contains('\\') || spec.ends_with(".toml") => {
            sealsim::scenario::load_material_file(Path::new(spec)).map_err(scenario_error)
        }
        Err(unknown) => Err(ScenarioError::new_err(format!(
            "{unknown} (or give the path of a material file)"
        ))),
    }
}

/// `sealsim compare`: the comparison table's columns and each compound's findings (JSON).
#[pyfunction]
#[pyo3(signature = (scenario, compounds, fidelity = None))]
fn _compare<'py>(
    py: Python<'py>,
    scenario: &PyScenario,
    compounds: Vec<String>,
    fidelity: Option<&str>,
) -> PyResult<(Bound<'py, PyDict>, String)> {
    let level = self::fidelity(fidelity)?;
    let materials: Vec<(String, Material)> = compounds
        .iter()
        .map(|c| Ok((c.trim().to_owned(), compound(c.trim())?)))
        .collect::<PyResult<_>>()?;
    let scenarios: Vec<Scenario> = materials
        .iter()
        .map(|(_, m)| {
            Scenario::from_str_with_material(&scenario.text, Path::new(&scenario.file), m)
                .map_err(scenario_error)
        })
        .collect::<PyResult<_>>()?;
    let (csv, findings) = blocking(py, move || {
        let runs =
            workflow::compare::compare_scenarios(scenarios, materials, level, &mut |_, _| {});
        let rows: Vec<CompareRow<'_>> = runs.iter().map(|run| CompareRow::of(run, None)).collect();
        let findings: serde_json::Map<String, serde_json::Value> = runs
            .iter()
            .map(|run| {
                let records = sealsim::report::findings::records(&run.result.findings);
                (
                    run.label.clone(),
                    serde_json::to_value(records).unwrap_or(serde_json::Value::Null),
                )
            })
            .collect();
        (compare_table(&rows), serde_json::to_string(&findings))
    })?;
    let csv = csv.map_err(internal)?;
    Ok((columns(py, &csv)?, findings.map_err(internal)?))
}

/// `sealsim study`: (cases columns, summary JSON text). `source` is a study file's path or its
/// TOML text (whose `base` is then relative to the working directory).
#[pyfunction]
#[pyo3(signature = (source, threads = None))]
fn _study<'py>(
    py: Python<'py>,
    source: String,
    threads: Option<usize>,
) -> PyResult<(Bound<'py, PyDict>, String)> {
    let study = if source.contains('\n') || source.contains('=') {
        Study::from_str(&source, Path::new(STRING_SOURCE))
    } else {
        Study::load(Path::new(&source))
    }
    .map_err(scenario_error)?;
    let (csv, json) = blocking(py, move || {
        let progress = |_: usize, _: usize| {};
        workflow::study::run(&study, 0..study.cases(), threads, &progress).map(|outcomes| {
            let summary = sealsim::study::summary::StudySummary::new(&outcomes, study.confidence);
            (
                sealsim::report::study::cases_csv(&study, &outcomes),
                sealsim::report::study::summary_json(&study, &summary),
            )
        })
    })?
    .map_err(scenario_error)?;
    let csv = csv.map_err(internal)?;
    Ok((columns(py, &csv)?, json.map_err(internal)?))
}

/// The material library: columns id, name, status, E0_Pa, E_inf_Pa, glass_transition_K,
/// low_temperature_limit_K (NaN where the compound has none).
#[pyfunction]
fn _materials(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let mut ids = Vec::new();
    let mut names = Vec::new();
    let mut status = Vec::new();
    let mut e0 = Vec::new();
    let mut e_inf = Vec::new();
    let mut tg = Vec::new();
    let mut t10 = Vec::new();
    for id in library::ids() {
        let m = library::get(id)
            .map_err(internal)?
            .load()
            .map_err(scenario_error)?;
        ids.push(id.to_owned());
        names.push(m.name.clone());
        status.push(m.status.as_str().to_owned());
        e0.push(m.prony.instantaneous());
        e_inf.push(m.prony.long_term());
        tg.push(m.glass_transition.unwrap_or(f64::NAN));
        t10.push(m.low_temperature_limit().unwrap_or(f64::NAN));
    }
    let dict = PyDict::new(py);
    dict.set_item("id", ids)?;
    dict.set_item("name", names)?;
    dict.set_item("status", status)?;
    dict.set_item("E0_Pa", e0)?;
    dict.set_item("E_inf_Pa", e_inf)?;
    dict.set_item("glass_transition_K", tg)?;
    dict.set_item("low_temperature_limit_K", t10)?;
    Ok(dict)
}

/// The dimensions `quantity` knows by name, in the order it tries them without one.
const DIMENSIONS: [(&str, Dimension); 14] = [
    ("pressure", Dimension::PRESSURE),
    ("length", Dimension::LENGTH),
    ("time", Dimension::TIME),
    ("viscosity", Dimension::VISCOSITY),
    ("volume_flow", Dimension::VOLUME_FLOW),
    ("volume", Dimension::VOLUME),
    ("wavevector", Dimension::WAVEVECTOR),
    ("force_per_length", Dimension::FORCE_PER_LENGTH),
    ("force", Dimension::FORCE),
    ("velocity", Dimension::VELOCITY),
    ("frequency", Dimension::FREQUENCY),
    ("area", Dimension::AREA),
    ("thermal_expansion", Dimension::THERMAL_EXPANSION),
    ("dimensionless", Dimension::DIMENSIONLESS),
];

/// A quantity with its unit in SI, with the unit parser of scenario files. `dimension`: one
/// of [`DIMENSIONS`]' names or `temperature` (absolute, K); `None`: whichever the unit has.
#[pyfunction]
#[pyo3(signature = (text, dimension = None))]
fn quantity(text: &str, dimension: Option<&str>) -> PyResult<f64> {
    let bad = |e: String| PyValueError::new_err(format!("\"{text}\": {e}"));
    match dimension {
        Some("temperature") => units::parse_temperature(text).map_err(|e| bad(e.to_string())),
        Some(name) => {
            let (_, d) = DIMENSIONS.iter().find(|(n, _)| *n == name).ok_or_else(|| {
                let names: Vec<&str> = DIMENSIONS.iter().map(|(n, _)| *n).collect();
                PyValueError::new_err(format!(
                    "unknown dimension \"{name}\": one of temperature, {}",
                    names.join(", ")
                ))
            })?;
            units::parse_quantity(text, *d).map_err(|e| bad(e.to_string()))
        }
        None => {
            let mut first_error = None;
            for (_, d) in DIMENSIONS {
                match units::parse_quantity(text, d) {
                    Ok(v) => return Ok(v),
                    Err(e) => {
                        first_error.get_or_insert(e.to_string());
                    }
                }
            }
            if let Ok(v) = units::parse_temperature(text) {
                return Ok(v);
            }
            Err(bad(first_error.unwrap_or_default()))
        }
    }
}

/// Persson's contact mechanics on its own (docs/model.md §2, the exact path): at each nominal
/// pressure \[Pa\] the relative contact area A/A0 at full magnification (q1), the mean gap
/// ū(ζ = 1) of the interface, and the critical junction (ζc, u_c, λc; NaN where no channel percolates). The surface
/// and the rubber are the scenario's (relaxed modulus E∞ and ν, its spectrum and `[model]`
/// settings), or, without one, a self-affine spectrum (h_rms, H, q0, q1 \[m, 1/m\]) on an
/// elastic half-space (E, ν) with default settings.
#[pyfunction]
#[pyo3(signature = (pressures, scenario = None, youngs_modulus = None, poisson_ratio = 0.5,
                    rms_roughness = None, hurst_exponent = None, q0 = None, q1 = None))]
#[allow(clippy::too_many_arguments)]
fn _contact<'py>(
    py: Python<'py>,
    pressures: Vec<Bound<'py, PyAny>>,
    scenario: Option<&PyScenario>,
    youngs_modulus: Option<f64>,
    poisson_ratio: f64,
    rms_roughness: Option<f64>,
    hurst_exponent: Option<f64>,
    q0: Option<f64>,
    q1: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    use sealsim::contact::{ContactSettings, Elastic, Junction, PerssonContact};
    use sealsim::surface::Spectrum;
    let pressures = pressures
        .iter()
        .map(pressure)
        .collect::<PyResult<Vec<f64>>>()?;
    let (spectrum, settings, e_star) = match scenario {
        Some(s) => {
            let pb = &s.inner.problem;
            (
                pb.spectrum.clone(),
                pb.contact,
                pb.material.effective_modulus(),
            )
        }
        None => {
            let need = |name: &str, v: Option<f64>| {
                v.ok_or_else(|| {
                    PyValueError::new_err(format!("contact: give {name} (or a scenario)"))
                })
            };
            let e = need("youngs_modulus", youngs_modulus)?;
            if !(e.is_finite() && e > 0.0 && poisson_ratio > -1.0 && poisson_ratio <= 0.5) {
                return Err(PyValueError::new_err(
                    "contact: youngs_modulus must be positive and poisson_ratio in (-1, 0.5]",
                ));
            }
            let spectrum = Spectrum::self_affine(
                need("rms_roughness", rms_roughness)?,
                need("hurst_exponent", hurst_exponent)?,
                need("q0", q0)?,
                need("q1", q1)?,
                None,
            )
            .map_err(|e| PyValueError::new_err(format!("contact: {e}")))?;
            let elastic = Elastic {
                youngs_modulus: e,
                poisson_ratio,
            };
            (
                spectrum,
                ContactSettings::default(),
                elastic.effective_modulus(),
            )
        }
    };
    let rows = blocking(py, move || {
        let contact = PerssonContact::new(spectrum, settings);
        let zeta1 = contact.spectrum().q1() / contact.spectrum().q0();
        pressures
            .iter()
            .map(|&p| {
                let s = p / e_star;
                // ū at magnification 1: the mean gap of the whole interface
                let gap = contact.separation(1.0, s).mean;
                let j = match contact.critical_junction(s) {
                    Junction::Leaking(j) => [j.zeta_c, j.u_c, j.lambda_c],
                    Junction::Sealed => [f64::NAN; 3],
                };
                [p, s, contact.area_fraction(zeta1, s), gap, j[0], j[1], j[2]]
            })
            .collect::<Vec<[f64; 7]>>()
    })?;
    let dict = PyDict::new(py);
    for (k, name) in [
        "nominal_pressure_Pa",
        "reduced_pressure",
        "area_fraction",
        "mean_gap_m",
        "zeta_c",
        "u_c_m",
        "lambda_c_m",
    ]
    .into_iter()
    .enumerate()
    {
        dict.set_item(name, rows.iter().map(|r| r[k]).collect::<Vec<f64>>())?;
    }
    Ok(dict)
}

/// The compiled module.
#[pymodule]
fn _sealsim(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("ScenarioError", py.get_type::<ScenarioError>())?;
    m.add("InternalError", py.get_type::<InternalError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<PyScenario>()?;
    m.add_function(wrap_pyfunction!(_compare, m)?)?;
    m.add_function(wrap_pyfunction!(_study, m)?)?;
    m.add_function(wrap_pyfunction!(_materials, m)?)?;
    m.add_function(wrap_pyfunction!(_contact, m)?)?;
    m.add_function(wrap_pyfunction!(quantity, m)?)?;
    fit::register(m)?;
    surface::register(m)?;
    Ok(())
}
