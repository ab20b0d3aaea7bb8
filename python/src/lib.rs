//! `sealsim._sealsim`: the extension module behind the Python package `sealsim` (issue 34).
//!
//! Every call goes through the library's workflows ([`sealsim::workflow`]) and its reports
//! ([`sealsim::report`]), never through the command line, so a Python result is the CLI's:
//! tables are the report's CSV text parsed back into columns (its numbers are shortest
//! round-trip scientific notation, so every value crosses bit for bit), summaries its JSON text
//! (parsed by the Python side). Numbers are SI floats.
//!
//! Every call's work runs on a worker thread ([`blocking`]) with the GIL released; the calling
//! thread only converts the arguments and the results, waits, and checks for signals every
//! 50 ms, so Ctrl-C raises `KeyboardInterrupt` at once whatever the call (the abandoned
//! computation finishes in the background and its result is dropped). A panic in the library
//! becomes `sealsim.InternalError` (a `RuntimeError`), never a crash of the interpreter nor
//! pyo3's `PanicException`: the worker catches it, and the little parsing done on the calling
//! thread runs inside [`guarded`].

mod contact;
mod fit;
mod gland;
mod surface;

use pyo3::exceptions::{PyFileNotFoundError, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyBytes, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use sealsim::leak::Fidelity;
use sealsim::material::Material;
use sealsim::report::csv::{Cell, Table, leak_outcome_table, pressure_difference_table};
use sealsim::report::life::{CompareRow, Summary, compare_table, history_for};
use sealsim::scenario::study::Study;
use sealsim::scenario::{Scenario, ScenarioError as RustScenarioError, library};
use sealsim::units::{self, Dimension};
use sealsim::workflow;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
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

pub(crate) fn internal(e: impl std::fmt::Display) -> PyErr {
    InternalError::new_err(format!("internal error: {e}"))
}

/// Runs `work` on a worker thread with the GIL released, checking for signals (Ctrl-C) every
/// 50 ms; a panic is an [`InternalError`]. Every call that does Rust work beyond converting its
/// arguments goes through here (issue 44, D8): on the calling thread Ctrl-C was not seen until
/// the call returned, and was lost altogether in 7 of 9 long calls of the reliability review.
pub(crate) fn blocking<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce() -> T + Send + 'static,
{
    blocking_with_progress(py, None, move |_| work())
}

/// Runs `work` on the calling thread, holding the GIL, with a panic as an [`InternalError`]
/// (never pyo3's `PanicException`, a `BaseException` that `except Exception` misses). Only for
/// work of microseconds, not worth a thread hand-off: reading a call's arguments (Python
/// objects, which need the GIL) before its work goes to [`blocking`], and `quantity`.
pub(crate) fn guarded<T>(work: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(work))
        .map_err(|payload| internal(format!("sealsim panicked: {}", panic_text(&*payload))))?
}

/// The message of a panic's payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic".to_owned())
}

/// The progress of work on the worker thread: `done` of `total` units (cases, states), read by
/// the waiting thread.
#[derive(Default)]
pub(crate) struct Meter {
    done: AtomicUsize,
    total: AtomicUsize,
}

impl Meter {
    /// Records that `done` of `total` units are finished (from any thread).
    pub(crate) fn set(&self, done: usize, total: usize) {
        self.total.store(total, Ordering::Relaxed);
        self.done.fetch_max(done, Ordering::Relaxed);
    }

    fn get(&self) -> (usize, usize) {
        (
            self.done.load(Ordering::Relaxed),
            self.total.load(Ordering::Relaxed),
        )
    }
}

/// A job for a worker thread.
type Job = Box<dyn FnOnce() + Send + 'static>;

/// Idle worker threads, each waiting on its own channel. A call reuses one rather than starting
/// a thread (whose start, and whose first allocations in a fresh arena, cost a tenth of a
/// millisecond, a few per cent of a life run); concurrent calls from several Python threads
/// each get their own.
static IDLE: std::sync::Mutex<Vec<mpsc::Sender<Job>>> = std::sync::Mutex::new(Vec::new());

/// Idle workers kept; one finishing beyond this ends.
const MAX_IDLE: usize = 4;

/// Runs `job` on an idle worker, or on a new one.
fn submit(mut job: Job) -> std::io::Result<()> {
    let idle = || {
        IDLE.lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    };
    loop {
        let Some(worker) = idle().pop() else { break };
        match worker.send(job) {
            Ok(()) => return Ok(()),
            // that worker has ended: try the next
            Err(mpsc::SendError(back)) => job = back,
        }
    }
    let (tx, rx) = mpsc::channel::<Job>();
    std::thread::Builder::new()
        .name("sealsim".into())
        .spawn(move || {
            job();
            loop {
                {
                    let mut pool = idle();
                    if pool.len() >= MAX_IDLE {
                        break;
                    }
                    pool.push(tx.clone());
                }
                match rx.recv() {
                    Ok(next) => next(),
                    Err(_) => break,
                }
            }
        })
        .map(|_| ())
}

/// [`blocking`] with progress: `work` reports to its [`Meter`], and `progress(done, total)` is
/// called on the calling thread (with the GIL) whenever that changed, at most every 50 ms and
/// once at the end. An exception raised by `progress` ends the wait with it.
pub(crate) fn blocking_with_progress<T, F>(
    py: Python<'_>,
    progress: Option<&Bound<'_, PyAny>>,
    work: F,
) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&Meter) -> T + Send + 'static,
{
    let meter = Arc::new(Meter::default());
    let (tx, rx) = mpsc::channel();
    let worker_meter = Arc::clone(&meter);
    submit(Box::new(move || {
        let outcome =
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| work(&worker_meter)));
        let _ = tx.send(outcome);
    }))
    .map_err(|e| PyOSError::new_err(format!("cannot start a worker thread: {e}")))?;
    let mut shown = (0, 0);
    let mut report = |meter: &Meter| -> PyResult<()> {
        let now = meter.get();
        if let Some(callback) = progress
            && now != shown
            && now.1 > 0
        {
            shown = now;
            callback.call1(now)?;
        }
        Ok(())
    };
    let mut rx = rx;
    loop {
        let (received, back) = py.detach(move || {
            let received = rx.recv_timeout(Duration::from_millis(50));
            (received, rx)
        });
        rx = back;
        match received {
            Ok(Ok(value)) => {
                report(&meter)?;
                return Ok(value);
            }
            Ok(Err(payload)) => {
                return Err(internal(format!(
                    "sealsim panicked: {}",
                    panic_text(&*payload)
                )));
            }
            Err(mpsc::RecvTimeoutError::Timeout) => {
                py.check_signals()?;
                report(&meter)?;
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(internal("the worker thread ended without a result"));
            }
        }
    }
}

/// A table's column on its way to Python: numbers as the native-endian bytes of their f64s
/// (a blank cell NaN: no value), which the Python side reads with `numpy.frombuffer`, or words.
pub(crate) enum Column {
    Numbers(Vec<u8>),
    Words(Vec<String>),
}

/// A table's columns in order, made on the worker thread, so that the calling thread only
/// copies them into Python objects.
pub(crate) type Columns = Vec<(String, Column)>;

/// Floats as the bytes of native-endian f64s.
fn f64_bytes(values: impl IntoIterator<Item = f64>) -> Vec<u8> {
    values.into_iter().flat_map(f64::to_ne_bytes).collect()
}

/// A column of numbers and blanks as [`Column::Numbers`] (a blank NaN), any other as words.
fn column<'a>(cells: impl Iterator<Item = &'a str> + Clone) -> Column {
    let numbers: Option<Vec<f64>> = cells
        .clone()
        .map(|c| {
            if c.is_empty() {
                Some(f64::NAN)
            } else {
                c.parse::<f64>().ok()
            }
        })
        .collect();
    match numbers {
        Some(v) => Column::Numbers(f64_bytes(v)),
        None => Column::Words(cells.map(str::to_owned).collect()),
    }
}

/// A CSV table (the report's text) as [`Columns`]: a column whose every non-empty cell is a
/// number is [`Column::Numbers`] (an empty cell is NaN: no value), any other words. The
/// reports write shortest round-trip numbers, so the floats are exact.
fn csv_columns(csv_text: &str) -> PyResult<Columns> {
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
    Ok(header
        .into_iter()
        .enumerate()
        .map(|(j, name)| {
            (
                name,
                column(rows.iter().map(move |r| r.get(j).unwrap_or(""))),
            )
        })
        .collect())
}

/// A report [`Table`] as [`Columns`], as [`csv_columns`] reads its CSV text: a column of
/// numbers and blanks is [`Column::Numbers`] (a blank is NaN), any other words. The floats are
/// the cells' own, which the CSV's round-trip notation carries bit for bit, so this equals
/// `csv_columns(table.to_csv())` without formatting and parsing every cell.
fn table_columns(table: &Table) -> Columns {
    let mut out = Columns::new();
    for (j, name) in table.header.iter().enumerate() {
        let cells = table.rows.iter().map(|r| r.get(j).unwrap_or(&Cell::Blank));
        let numbers: Option<Vec<f64>> = cells
            .clone()
            .map(|c| match c {
                Cell::Number(v) => Some(*v),
                Cell::Blank => Some(f64::NAN),
                Cell::Text(_) => None,
            })
            .collect();
        let column = match numbers {
            Some(v) => Column::Numbers(f64_bytes(v)),
            None => Column::Words(cells.map(Cell::text).collect()),
        };
        out.push(((*name).to_owned(), column));
    }
    out
}

/// [`Columns`] as an ordered dict: numbers as bytes, words as a list of str.
fn columns_dict(py: Python<'_>, columns: Columns) -> PyResult<Bound<'_, PyDict>> {
    let dict = PyDict::new(py);
    for (name, column) in columns {
        match column {
            Column::Numbers(bytes) => dict.set_item(name, PyBytes::new(py, &bytes))?,
            Column::Words(words) => dict.set_item(name, words)?,
        }
    }
    Ok(dict)
}

/// A column of floats as the bytes of native-endian f64s, which the Python side reads with
/// `numpy.frombuffer` (one copy, no Python float per cell).
pub(crate) fn float_column<'py>(
    py: Python<'py>,
    values: impl IntoIterator<Item = f64>,
) -> Bound<'py, PyBytes> {
    PyBytes::new(py, &f64_bytes(values))
}

/// A fidelity level by its name (`exact`, `critical-junction`, …), as `--fidelity` takes it.
pub(crate) fn fidelity(name: Option<&str>) -> PyResult<Option<Fidelity>> {
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

/// A life run with its history table and `--summary` JSON, as `sealsim run` writes them.
fn life_report(
    scenario: &Scenario,
    file: &str,
    progress: workflow::Progress<'_>,
) -> (
    Result<Table, sealsim::report::ReportError>,
    Result<String, sealsim::report::ReportError>,
) {
    let result = workflow::life::run(scenario, progress);
    let history = history_for(&result, &scenario.life.fluid);
    let mut summary = Summary::new(&scenario.name, file, &scenario.life, &result);
    summary.input_warnings = sealsim::report::findings::input_records(&scenario.warnings);
    let summary = summary.to_json();
    (history, summary)
}

/// A scenario: the validated model (SI), its TOML text and its file.
#[pyclass(name = "Scenario", module = "sealsim._sealsim", frozen)]
pub(crate) struct PyScenario {
    pub(crate) inner: Arc<Scenario>,
    text: String,
    /// The file as given (the summary's `scenario_file`, as the CLI's).
    file: String,
}

impl PyScenario {
    /// Reads and validates scenario `text` from `file`: the work of `from_file`, `from_toml`
    /// (a height map it names can take seconds), so callers run it on the worker.
    fn new(text: String, file: String) -> PyResult<PyScenario> {
        let scenario = Scenario::from_str(&text, Path::new(&file)).map_err(scenario_error)?;
        Ok(PyScenario {
            inner: Arc::new(scenario),
            text,
            file,
        })
    }
}

/// `scenario` with its fidelity overridden (a copy, height map and all: made on the worker),
/// shared when not.
fn at(scenario: Arc<Scenario>, level: Option<Fidelity>) -> Arc<Scenario> {
    match level {
        None => scenario,
        Some(f) => {
            let mut s = (*scenario).clone();
            s.life.fidelity = f;
            Arc::new(s)
        }
    }
}

/// `sealsim leak`'s table (CSV text) and findings: at the fluid pressure `differences`, else
/// at the contact `pressures` (`None`: the scenario's own state).
fn leak_report(
    scenario: &Scenario,
    pressures: Option<&[f64]>,
    differences: Option<&[f64]>,
    level: Fidelity,
    progress: workflow::Progress<'_>,
) -> PyResult<(String, String)> {
    let (csv, findings) = match differences {
        Some(differences) => {
            let (rows, findings) =
                workflow::leak::at_pressure_differences(scenario, differences, level, progress);
            (pressure_difference_table(&rows), findings)
        }
        None => {
            let outcome = workflow::leak::evaluate(scenario, pressures, level, progress);
            let csv = leak_outcome_table(&outcome, scenario.life.fluid.mean_pressure());
            (csv, outcome.findings)
        }
    };
    let findings = serde_json::to_string(&sealsim::report::findings::records(&findings));
    Ok((csv.map_err(internal)?, findings.map_err(internal)?))
}

#[pymethods]
impl PyScenario {
    /// Reads and validates a scenario file.
    #[staticmethod]
    fn from_file(py: Python<'_>, path: PathBuf) -> PyResult<PyScenario> {
        blocking(py, move || {
            let text = std::fs::read_to_string(&path).map_err(|source| {
                scenario_error(RustScenarioError::Read {
                    path: path.clone(),
                    source,
                })
            })?;
            PyScenario::new(text, path.display().to_string())
        })?
    }

    /// Validates scenario TOML text; `path` names it in messages and resolves relative data
    /// files (default `<string>`, relative to the working directory).
    #[staticmethod]
    #[pyo3(signature = (text, path = None))]
    fn from_toml(py: Python<'_>, text: String, path: Option<PathBuf>) -> PyResult<PyScenario> {
        let file = path.map_or_else(|| STRING_SOURCE.to_owned(), |p| p.display().to_string());
        blocking(py, move || PyScenario::new(text, file))?
    }

    /// A new scenario with dotted keys replaced, as a study's `[vary]` sets them.
    fn replace(&self, py: Python<'_>, values: &Bound<'_, PyDict>) -> PyResult<PyScenario> {
        let mut assignments = Vec::new();
        for (k, v) in values.iter() {
            assignments.push((k.extract::<String>()?, toml_value(&v)?));
        }
        let (text, file) = (self.text.clone(), self.file.clone());
        blocking(py, move || {
            let (text, scenario) =
                workflow::replace(&text, Path::new(&file), &assignments).map_err(scenario_error)?;
            Ok(PyScenario {
                inner: Arc::new(scenario),
                text,
                file,
            })
        })?
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
        self.inner.warnings.iter().map(|w| w.text.clone()).collect()
    }

    /// The fidelity level the scenario runs at.
    #[getter]
    fn fidelity(&self) -> &'static str {
        self.inner.life.fidelity.name()
    }

    /// `sealsim run`: (history columns, summary JSON text).
    #[pyo3(signature = (fidelity = None, progress = None))]
    fn _run<'py>(
        &self,
        py: Python<'py>,
        fidelity: Option<&str>,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<(Bound<'py, PyDict>, String)> {
        let level = self::fidelity(fidelity)?;
        let (scenario, file) = (Arc::clone(&self.inner), self.file.clone());
        // on the worker at every level: an analytic run can take minutes too (D7, D8)
        let (history, summary) = blocking_with_progress(py, progress.as_ref(), move |meter| {
            let scenario = at(scenario, level);
            let (history, summary) =
                life_report(&scenario, &file, &mut |done, total| meter.set(done, total));
            Ok::<_, PyErr>((
                table_columns(&history.map_err(internal)?),
                summary.map_err(internal)?,
            ))
        })??;
        Ok((columns_dict(py, history)?, summary))
    }

    /// The in-process Rust reference of the overhead benchmark (python/benches/overhead.py):
    /// the fastest of `repeats` runs of the life workflow alone, and of the workflow with the
    /// history table and summary that `_run` returns (seconds, timed on the worker around the
    /// work alone).
    fn _time_in_rust(&self, py: Python<'_>, repeats: usize) -> PyResult<(f64, f64)> {
        let scenario = Arc::clone(&self.inner);
        let file = self.file.clone();
        blocking(py, move || {
            let (mut bare, mut reported) = (f64::INFINITY, f64::INFINITY);
            for _ in 0..repeats.max(1) {
                let start = std::time::Instant::now();
                std::hint::black_box(workflow::life::run(&scenario, &mut |_, _| {}));
                bare = bare.min(start.elapsed().as_secs_f64());
                let start = std::time::Instant::now();
                let _ = std::hint::black_box(life_report(&scenario, &file, &mut |_, _| {}));
                reported = reported.min(start.elapsed().as_secs_f64());
            }
            (bare, reported)
        })
    }

    /// `sealsim advise`: the advice's JSON text (SI), as `--json` writes it. `life`: a time
    /// with its unit (`"10y"`) or seconds.
    #[pyo3(signature = (life, threads = None, max_runs = None, progress = None))]
    fn _advise<'py>(
        &self,
        py: Python<'py>,
        life: &Bound<'py, PyAny>,
        threads: Option<usize>,
        max_runs: Option<usize>,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<String> {
        let (target, target_text) = guarded(|| {
            Ok(if let Ok(text) = life.extract::<String>() {
                let t = units::parse_quantity(&text, Dimension::TIME)
                    .map_err(|e| PyValueError::new_err(format!("life: {e}")))?;
                (t, text.trim().to_owned())
            } else {
                let t: f64 = life.extract()?;
                (t, format!("{} s", units::exact(t)))
            })
        })?;
        if !(target.is_finite() && target > 0.0) {
            return Err(PyValueError::new_err("life: must be positive"));
        }
        if threads == Some(0) || max_runs == Some(0) {
            return Err(PyValueError::new_err("threads and max_runs: at least 1"));
        }
        let options = workflow::advise::Options {
            target,
            target_text,
            max_runs: max_runs.unwrap_or(workflow::advise::DEFAULT_MAX_RUNS),
            threads,
        };
        let (text, file, scenario) = (
            self.text.clone(),
            self.file.clone(),
            Arc::clone(&self.inner),
        );
        let json = blocking_with_progress(py, progress.as_ref(), move |meter| {
            let progress = |done: usize, total: usize| meter.set(done, total);
            workflow::advise::advise(&text, Path::new(&file), &scenario, &options, &progress)
                .map(|advice| sealsim::report::advise::json(&advice, &file))
        })?
        .map_err(scenario_error)?;
        json.map_err(internal)
    }

    /// `sealsim leak`: (table columns, findings JSON text, the O-ring note). `pressures`: contact
    /// pressures in Pa (or strings with units), `None` the scenario's own;
    /// `pressure_differences`: fluid ΔP in Pa (or strings), one row each (`sealsim leak
    /// --pressure-differences`), exclusive of `pressures`.
    #[pyo3(signature = (pressures = None, fidelity = None, progress = None,
                        pressure_differences = None))]
    fn _leak<'py>(
        &self,
        py: Python<'py>,
        pressures: Option<Vec<Bound<'py, PyAny>>>,
        fidelity: Option<&str>,
        progress: Option<Bound<'py, PyAny>>,
        pressure_differences: Option<Vec<Bound<'py, PyAny>>>,
    ) -> PyResult<(Bound<'py, PyDict>, String, Option<String>)> {
        let (pressures, differences) = guarded(|| {
            let pressures = pressures
                .map(|list| list.iter().map(pressure).collect::<PyResult<Vec<f64>>>())
                .transpose()?;
            let differences = pressure_differences
                .map(|list| {
                    list.iter()
                        .map(pressure_difference)
                        .collect::<PyResult<Vec<f64>>>()
                })
                .transpose()?;
            Ok((pressures, differences))
        })?;
        if pressures.is_some() && differences.is_some() {
            return Err(ScenarioError::new_err(
                "leak: give either contact_pressures or pressure_differences, not both",
            ));
        }
        let level = self::fidelity(fidelity)?.unwrap_or(self.inner.life.fidelity);
        let scenario = Arc::clone(&self.inner);
        // on the worker at every level: an analytic leak table can take minutes too (D8)
        let (columns, findings, note) =
            blocking_with_progress(py, progress.as_ref(), move |meter| {
                let note = match differences {
                    Some(_) => None,
                    None => workflow::leak::oring_state_note(&scenario, pressures.is_some()),
                };
                let (csv, findings) = leak_report(
                    &scenario,
                    pressures.as_deref(),
                    differences.as_deref(),
                    level,
                    &mut |done, total| meter.set(done, total),
                )?;
                Ok::<_, PyErr>((csv_columns(&csv)?, findings, note))
            })??;
        Ok((columns_dict(py, columns)?, findings, note))
    }

    /// The leak floor \[m³/s\] of `sealsim run`'s chart and summary (docs/model.md §15.2):
    /// `text` read as `--leak-floor` reads it (a float: m³/s), `None` one molecule a second.
    #[pyo3(signature = (value = None))]
    fn _leak_floor(&self, value: Option<Bound<'_, PyAny>>) -> PyResult<f64> {
        let fluid = &self.inner.life.fluid;
        guarded(|| {
            let floor = match value {
                None => return Ok(fluid.one_molecule_per_second()),
                Some(v) if v.is_instance_of::<PyString>() => {
                    let text: String = v.extract()?;
                    workflow::leak::parse_leak_floor(&text, fluid)
                        .map_err(|m| ScenarioError::new_err(format!("leak_floor: {m}")))?
                }
                Some(v) => v.extract::<f64>()?,
            };
            if floor.is_finite() && floor > 0.0 {
                Ok(floor)
            } else {
                Err(ScenarioError::new_err(format!(
                    "leak_floor: must be positive, got {floor} m³/s"
                )))
            }
        })
    }

    fn __repr__(&self) -> String {
        format!("Scenario({:?}, path={:?})", self.inner.name, self.file)
    }
}

/// A nominal pressure: a float in Pa, or a string with its unit ("2 bar").
pub(crate) fn pressure(value: &Bound<'_, PyAny>) -> PyResult<f64> {
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

/// A fluid pressure difference ΔP ≥ 0: a float in Pa, or a string with its unit ("210 bar").
fn pressure_difference(value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let p = if value.is_instance_of::<PyString>() {
        let text: String = value.extract()?;
        units::parse_quantity(&text, Dimension::PRESSURE)
            .map_err(|e| PyValueError::new_err(format!("pressure difference \"{text}\": {e}")))?
    } else {
        value.extract::<f64>()?
    };
    if p.is_finite() && p >= 0.0 {
        Ok(p)
    } else {
        Err(PyValueError::new_err(format!(
            "a pressure difference must be at least 0 and finite, got {p} Pa"
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
#[pyo3(signature = (scenario, compounds, fidelity = None, progress = None, raw = false))]
fn _compare<'py>(
    py: Python<'py>,
    scenario: &PyScenario,
    compounds: Vec<String>,
    fidelity: Option<&str>,
    progress: Option<Bound<'py, PyAny>>,
    raw: bool,
) -> PyResult<(Bound<'py, PyDict>, String, String)> {
    let level = self::fidelity(fidelity)?;
    let (text, file) = (scenario.text.clone(), scenario.file.clone());
    let (columns, findings, headline) =
        blocking_with_progress(py, progress.as_ref(), move |meter| {
            // each compound's scenario is read again (its height map too): on the worker
            let materials: Vec<(String, Material)> = compounds
                .iter()
                .map(|c| Ok((c.trim().to_owned(), compound(c.trim())?)))
                .collect::<PyResult<_>>()?;
            let scenarios: Vec<Scenario> = materials
                .iter()
                .map(|(_, m)| {
                    Scenario::from_str_with_material(&text, Path::new(&file), m)
                        .map_err(scenario_error)
                })
                .collect::<PyResult<_>>()?;
            compare_report(scenarios, materials, level, raw, &mut |done, total| {
                meter.set(done, total)
            })
        })??;
    Ok((columns_dict(py, columns)?, findings, headline))
}

/// The runs of `sealsim compare`, ranked as it ranks them (`raw`: its `--all`): the table's
/// columns, each compound's findings (JSON) and the headline.
fn compare_report(
    scenarios: Vec<Scenario>,
    materials: Vec<(String, Material)>,
    level: Option<Fidelity>,
    raw: bool,
    progress: workflow::Progress<'_>,
) -> PyResult<(Columns, String, String)> {
    let runs = workflow::compare::rank(
        workflow::compare::compare_scenarios(scenarios, materials, level, progress),
        raw,
    );
    let rows: Vec<CompareRow<'_>> = runs.iter().map(|run| CompareRow::of(run, None)).collect();
    let findings: serde_json::Map<String, serde_json::Value> = runs
        .iter()
        .map(|(run, _)| {
            let records = sealsim::report::findings::records(&run.result.findings);
            (
                run.label.clone(),
                serde_json::to_value(records).unwrap_or(serde_json::Value::Null),
            )
        })
        .collect();
    let csv = compare_table(&rows).map_err(internal)?;
    Ok((
        csv_columns(&csv)?,
        serde_json::to_string(&findings).map_err(internal)?,
        sealsim::report::life::compare_headline(&runs),
    ))
}

/// `sealsim study`: (cases columns, summary JSON text). `source` is a study file's path or its
/// TOML text (whose `base` is then relative to the working directory).
#[pyfunction]
#[pyo3(signature = (source, threads = None, progress = None))]
fn _study<'py>(
    py: Python<'py>,
    source: String,
    threads: Option<usize>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<(Bound<'py, PyDict>, String)> {
    let (columns, json) = blocking_with_progress(py, progress.as_ref(), move |meter| {
        // the study and its base scenario (a height map too) are read on the worker
        let study = if source.contains('\n') || source.contains('=') {
            Study::from_str(&source, Path::new(STRING_SOURCE))
        } else {
            Study::load(Path::new(&source))
        }
        .map_err(scenario_error)?;
        let progress = |done: usize, total: usize| meter.set(done, total);
        let outcomes = workflow::study::run(&study, 0..study.cases(), threads, &progress)
            .map_err(scenario_error)?;
        let summary = sealsim::study::summary::StudySummary::new(&outcomes, study.confidence);
        let csv = sealsim::report::study::cases_csv(&study, &outcomes).map_err(internal)?;
        let json = sealsim::report::study::summary_json(&study, &summary).map_err(internal)?;
        Ok::<_, PyErr>((csv_columns(&csv)?, json))
    })??;
    Ok((columns_dict(py, columns)?, json))
}

/// One library compound's row of [`_materials`]: id, name, status, E0, E∞, Tg, T10 (SI).
type MaterialRow = (String, String, String, f64, f64, f64, f64);

/// The material library: columns id, name, status, E0_Pa, E_inf_Pa, glass_transition_K,
/// low_temperature_limit_K (NaN where the compound has none).
#[pyfunction]
fn _materials(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    // every compound's file is read and validated: on the worker
    let rows: Vec<MaterialRow> = blocking(py, || {
        library::ids()
            .map(|id| {
                let m = library::get(id)
                    .map_err(internal)?
                    .load()
                    .map_err(scenario_error)?;
                Ok((
                    id.to_owned(),
                    m.name.clone(),
                    m.status.as_str().to_owned(),
                    m.prony.instantaneous(),
                    m.prony.long_term(),
                    m.glass_transition.unwrap_or(f64::NAN),
                    m.low_temperature_limit().unwrap_or(f64::NAN),
                ))
            })
            .collect::<PyResult<Vec<MaterialRow>>>()
    })??;
    let dict = PyDict::new(py);
    dict.set_item("id", rows.iter().map(|r| r.0.clone()).collect::<Vec<_>>())?;
    dict.set_item("name", rows.iter().map(|r| r.1.clone()).collect::<Vec<_>>())?;
    dict.set_item(
        "status",
        rows.iter().map(|r| r.2.clone()).collect::<Vec<_>>(),
    )?;
    dict.set_item("E0_Pa", rows.iter().map(|r| r.3).collect::<Vec<_>>())?;
    dict.set_item("E_inf_Pa", rows.iter().map(|r| r.4).collect::<Vec<_>>())?;
    dict.set_item(
        "glass_transition_K",
        rows.iter().map(|r| r.5).collect::<Vec<_>>(),
    )?;
    dict.set_item(
        "low_temperature_limit_K",
        rows.iter().map(|r| r.6).collect::<Vec<_>>(),
    )?;
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

/// The quantity ``text`` in SI, read by the scenario files' unit parser:
/// ``quantity("210 bar")`` is 21000000.0 (Pa), ``quantity("0.4 um")`` 4e-07 (m).
///
/// ``dimension`` names what it must be: pressure, length, time, viscosity, volume_flow,
/// volume, wavevector, force_per_length, force, velocity, frequency, area, thermal_expansion,
/// dimensionless, or temperature (absolute, K: ``quantity("80 C", "temperature")`` is 353.15);
/// None: whichever the unit is. An unknown unit, or one of another dimension, raises
/// ``ValueError``.
#[pyfunction]
#[pyo3(signature = (text, dimension = None))]
fn quantity(text: &str, dimension: Option<&str>) -> PyResult<f64> {
    // microseconds of parsing: on the calling thread, a panic still an InternalError
    guarded(|| parse_quantity(text, dimension))
}

/// [`quantity`]'s work.
fn parse_quantity(text: &str, dimension: Option<&str>) -> PyResult<f64> {
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

/// A panic on purpose, for the tests (python/tests/test_robustness.py): `"worker"` in work
/// handed to [`blocking`], `"guarded"` on the calling thread inside [`guarded`] (both
/// [`InternalError`]), `"bare"` outside either (pyo3's `PanicException`, which the Python
/// layer's wrappers turn into `InternalError`).
#[pyfunction]
#[expect(
    clippy::panic,
    reason = "the tests' way to check that a panic reaches Python as InternalError"
)]
fn _panic(py: Python<'_>, place: &str) -> PyResult<()> {
    let boom = || -> PyResult<()> { panic!("a panic on purpose (sealsim._sealsim._panic)") };
    match place {
        "worker" => blocking(py, boom)?,
        "guarded" => guarded(boom),
        "bare" => boom(),
        other => Err(PyValueError::new_err(format!(
            "place \"{other}\": one of \"worker\", \"guarded\", \"bare\""
        ))),
    }
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
    contact::register(m)?;
    m.add_function(wrap_pyfunction!(quantity, m)?)?;
    m.add_function(wrap_pyfunction!(_panic, m)?)?;
    fit::register(m)?;
    surface::register(m)?;
    gland::register(m)?;
    Ok(())
}
