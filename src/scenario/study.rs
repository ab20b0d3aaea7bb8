//! Study files (`sealsim study`, docs/model.md §14.1): a base scenario, the inputs to vary with
//! their distributions, and the design — TOML → a validated [`Study`] whose cases are scenarios.
//!
//! ```toml
//! base = "oring.toml"            # relative to the study file
//! design = "monte-carlo"         # "grid", "latin-hypercube"
//! samples = 200
//! seed = 7
//! [vary]
//! "seal.squeeze" = { distribution = "normal", mean = 0.25, std = 0.02 }
//! "surface.rms_roughness" = { distribution = "lognormal", median = "0.8 um", geometric_std = 1.2 }
//! "seal.groove_depth" = "±0.05 mm"              # a tolerance band about the base's value
//! "material.library" = { values = ["nbr-70", "fkm-75"] }
//! ```
//!
//! Each input is addressed by its scenario key path and sampled in the unit its parameters give
//! (all converted to the unit of its first location parameter); a case's value is written into
//! the base scenario in that unit, and the scenario is validated as any other — so a case obeys
//! exactly the rules and defaults of a scenario file. Setting `material.library` or
//! `material.file` replaces the compound (the `[material]` table keeps only its
//! `asperity_modulus`).
//!
//! Other keys: `name`, `levels` (a grid's levels of a continuous input, default 3),
//! `correlations = [{ inputs = ["a", "b"], spearman = 0.5 }]` (Monte Carlo only; a Gaussian
//! copula, [`crate::study::design`]), `confidence` (of the bands and bounds, default 0.95), `report_times` (the per-case leak rates,
//! default 1 day, 1 year, 10 years), `run_after_failure` (default false: a case ends at its
//! failure).

use super::error::Source;
use super::{Scenario, ScenarioError};
use crate::study::Cell;
use crate::study::design::{Design, Distribution, Plan};
use crate::units::{self, Dimension};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// Keys whose temperatures are differences (a value in °C is a difference of kelvins there);
/// every other temperature key is absolute.
const TEMPERATURE_DIFFERENCES: &[&str] = &[
    "environment.daily_amplitude",
    "environment.yearly_amplitude",
    "material.shift.c2",
    "fluid.sutherland_constant",
];

/// The report times of the per-case leak rates when the study gives none.
const DEFAULT_REPORT_TIMES: [f64; 3] = [86_400.0, 365.25 * 86_400.0, 3652.5 * 86_400.0];

#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawStudy {
    name: Option<Spanned<String>>,
    base: Spanned<String>,
    design: Spanned<String>,
    samples: Option<Spanned<i64>>,
    levels: Option<Spanned<i64>>,
    seed: Option<Spanned<i64>>,
    confidence: Option<Spanned<f64>>,
    report_times: Option<Spanned<Vec<Spanned<String>>>>,
    run_after_failure: Option<Spanned<bool>>,
    correlations: Option<Spanned<Vec<Spanned<RawCorrelation>>>>,
    /// `"fits"`: every dimension the base gives a tolerance for is drawn from it (the ring from
    /// its size's, `seal.X` from `seal.X_tolerance`), after the `[vary]` inputs.
    tolerances: Option<Spanned<String>>,
    vary: Spanned<BTreeMap<String, Spanned<toml::Value>>>,
}

/// `correlations = [{ inputs = ["a", "b"], spearman = 0.5 }]`.
#[derive(Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawCorrelation {
    inputs: Vec<String>,
    spearman: f64,
}

/// How an input's values reach the scenario and the per-case table.
#[derive(Debug, Clone, PartialEq)]
pub enum InputKind {
    /// A number in `unit` ("" for a bare number, which a scenario reads as SI); `si` converts
    /// it to SI for the tables: `x·scale + offset`, `dimension` its SI dimension (`None` when
    /// bare).
    Quantity {
        unit: String,
        scale: f64,
        offset: f64,
        dimension: Option<Dimension>,
    },
    /// Words (compound ids, fidelity levels): the distribution's values are indices.
    Words(Vec<String>),
    /// A ring dimension (`seal.cross_section`, `seal.inner_diameter`) within its size's own
    /// tolerance (`tolerance = "size"`): the value z ∈ [−1, 1] is the fraction of the case's
    /// AS568 ± tolerance, so that it follows a varied `seal.size`; the case's ring is then
    /// written out as `cross_section` + `inner_diameter`.
    SizeTolerance,
    /// `seal.diametral_clearance` within the case's ISO 286 `seal.fit` (`tolerance = "fit"`):
    /// the value z ∈ [−1, 1] places the clearance between the fit's smallest (−1) and largest
    /// (+1) at the case's bore or rod diameter, so that it follows a varied `seal.fit`.
    FitTolerance,
}

/// One varied input.
#[derive(Debug, Clone, PartialEq)]
pub struct StudyInput {
    /// The scenario key path, e.g. `seal.squeeze`.
    pub key: String,
    /// The study file's line of its entry.
    pub line: usize,
    pub kind: InputKind,
}

impl StudyInput {
    /// The per-case table's column: the key path and, for a quantity, its SI unit
    /// (`surface.rms_roughness_m`).
    pub fn column(&self) -> String {
        match &self.kind {
            InputKind::Quantity {
                dimension: Some(d), ..
            } if *d != Dimension::DIMENSIONLESS => format!("{}_{}", self.key, si_suffix(*d)),
            InputKind::SizeTolerance | InputKind::FitTolerance => {
                format!("{}_tolerance_fraction", self.key)
            }
            _ => self.key.clone(),
        }
    }

    /// The table's cell of value `x`: the SI number, or the word.
    pub fn cell(&self, x: f64) -> Cell {
        match &self.kind {
            InputKind::Quantity { scale, offset, .. } => Cell::Number(x * scale + offset),
            InputKind::Words(w) => Cell::Word(w[x as usize].clone()),
            InputKind::SizeTolerance | InputKind::FitTolerance => Cell::Number(x),
        }
    }

    /// The scenario's TOML value of `x`.
    fn toml_value(&self, x: f64) -> toml::Value {
        match &self.kind {
            InputKind::Quantity { unit, .. } if unit.is_empty() => {
                if x.fract() == 0.0 && x.abs() < 9.0e15 {
                    toml::Value::Integer(x as i64)
                } else {
                    toml::Value::Float(x)
                }
            }
            InputKind::Quantity { unit, .. } => {
                toml::Value::String(format!("{} {unit}", units::exact(x)))
            }
            InputKind::Words(w) => toml::Value::String(w[x as usize].clone()),
            InputKind::SizeTolerance | InputKind::FitTolerance => toml::Value::Float(x),
        }
    }

    /// `key = value` as a case's input reads (for messages).
    pub fn describe(&self, x: f64) -> String {
        if self.kind == InputKind::SizeTolerance {
            return format!("{} = nominal {x:+.3} × the size's tolerance", self.key);
        }
        if self.kind == InputKind::FitTolerance {
            return format!("{} = the fit's middle {x:+.3} × its half range", self.key);
        }
        match self.toml_value(x) {
            toml::Value::String(s) => format!("{} = \"{s}\"", self.key),
            v => format!("{} = {v}", self.key),
        }
    }
}

/// A validated study.
#[derive(Debug, Clone)]
pub struct Study {
    /// The `name` key, or the file stem.
    pub name: String,
    /// The study file.
    pub path: PathBuf,
    /// The study file's text, as read.
    text: String,
    /// The base scenario file and its text.
    pub base_path: PathBuf,
    base_text: String,
    base: toml::Table,
    /// The base scenario, validated.
    pub base_scenario: Scenario,
    pub inputs: Vec<StudyInput>,
    pub plan: Plan,
    /// Times of the per-case leak rates \[s\].
    pub report_times: Vec<f64>,
    /// Two-sided confidence of the bands and bounds (default 0.95).
    pub confidence: f64,
    /// Run every case to its duration (`run_after_failure = true`); by default a case ends at
    /// its failure, which is all a life distribution needs.
    pub run_after_failure: bool,
    /// A hash of the study file, the base scenario and this build's version: shards of
    /// different studies never merge.
    pub fingerprint: String,
}

impl Study {
    /// Reads and validates the study file at `path` and its base scenario.
    pub fn load(path: &Path) -> Result<Study, ScenarioError> {
        let text = std::fs::read_to_string(path).map_err(|source| ScenarioError::Read {
            path: path.to_path_buf(),
            source,
        })?;
        Study::from_str(&text, path)
    }

    /// Validates study `text` read from `path` (the base is resolved against its directory).
    pub fn from_str(text: &str, path: &Path) -> Result<Study, ScenarioError> {
        let source = Source { path, text };
        let raw: RawStudy = source.deserialize()?;
        let base_path = path
            .parent()
            .unwrap_or(Path::new(""))
            .join(raw.base.get_ref());
        let base_text = std::fs::read_to_string(&base_path).map_err(|e| {
            source.error(
                raw.base.span(),
                "base",
                format!("cannot read the base scenario {}: {e}", base_path.display()),
            )
        })?;
        let base_scenario = Scenario::from_str(&base_text, &base_path)?;
        let base: toml::Table = base_text.parse().map_err(|e: toml::de::Error| {
            source.error(raw.base.span(), "base", e.message().to_owned())
        })?;

        let design = raw.design(&source)?;
        let samples = raw.samples(&source, design)?;
        let levels = count(&source, &raw.levels, "levels", 3, 1000)?;
        let seed = raw.seed(&source)?;
        let confidence = raw.confidence(&source)?;
        let report_times = raw.report_times(&source)?;
        let (inputs, distributions) =
            raw.inputs(&source, &base, &base_scenario.life.material.bands)?;
        let correlation = raw.correlation(&source, design, &inputs)?;
        let plan = Plan {
            design,
            inputs: distributions,
            samples,
            levels,
            seed,
            correlation,
        };
        if plan.cases() > 10_000_000 {
            return Err(source.error(
                raw.vary.span(),
                "vary",
                format!("the grid has {} cases; at most 10 000 000", plan.cases()),
            ));
        }
        let fingerprint = fingerprint(text, &base_text);
        let study = Study {
            name: raw
                .name
                .as_ref()
                .map_or_else(|| source.file_stem(), |n| n.get_ref().clone()),
            path: path.to_path_buf(),
            text: text.to_owned(),
            base_path,
            base_text,
            base,
            base_scenario,
            inputs,
            plan,
            report_times,
            confidence,
            run_after_failure: raw.run_after_failure.as_ref().is_some_and(|b| *b.get_ref()),
            fingerprint,
        };
        // Every key path must be one a scenario accepts: each input alone at its median.
        // A fraction of a case's own tolerance (of its size, of its fit) goes with the input it
        // follows when that is varied too.
        let median = |j: usize| (&study.inputs[j], study.plan.inputs[j].quantile(0.5));
        for (j, input) in study.inputs.iter().enumerate() {
            let follows = match input.kind {
                InputKind::SizeTolerance => Some("seal.size"),
                InputKind::FitTolerance => Some("seal.fit"),
                _ => None,
            };
            let mut alone = vec![median(j)];
            if let Some(k) = follows.and_then(|key| study.inputs.iter().position(|i| i.key == key))
            {
                alone.push(median(k));
            }
            study.scenario_with(&alone, None)?;
        }
        Ok(study)
    }

    /// The number of cases.
    pub fn cases(&self) -> usize {
        self.plan.cases()
    }

    /// The scenario of one case: the base with the case's `values` (in input order), validated;
    /// an invalid case is reported at the study file's line of the first input, naming the case.
    pub fn scenario(&self, index: usize, values: &[f64]) -> Result<Scenario, ScenarioError> {
        let assignments: Vec<(&StudyInput, f64)> =
            self.inputs.iter().zip(values.iter().copied()).collect();
        self.scenario_with(&assignments, Some(index))
            .map_err(|e| self.name_culprits(&assignments, index, e))
    }

    /// An invalid case's error, at the line of the varied input that makes it invalid: each
    /// input is tried alone at the case's value (the others at the base's); the first that is
    /// refused alone is named (issue 30: a cross-section tolerance that unseats the ring is
    /// named, not the groove depth the message's check happens to read). When no input is
    /// refused alone the combination is named.
    fn name_culprits(
        &self,
        assignments: &[(&StudyInput, f64)],
        index: usize,
        error: ScenarioError,
    ) -> ScenarioError {
        if assignments.len() < 2 {
            return error;
        }
        let culprits: Vec<&(&StudyInput, f64)> = assignments
            .iter()
            .filter(|a| self.scenario_with(&[**a], None).is_err())
            .collect();
        let message = match &error {
            ScenarioError::Invalid { message, .. } => message.clone(),
            other => other.to_string(),
        };
        match culprits.first() {
            Some((input, x)) => self.error(
                input,
                format!(
                    "{message} — made invalid by {} (refused on its own at case {index}'s value)",
                    input.describe(*x)
                ),
            ),
            None => match error {
                ScenarioError::Invalid {
                    path, line, key, ..
                } => ScenarioError::Invalid {
                    path,
                    line,
                    key,
                    message: format!(
                        "{message} — made invalid by the combination (each input alone is valid)"
                    ),
                },
                other => other,
            },
        }
    }

    fn scenario_with(
        &self,
        assignments: &[(&StudyInput, f64)],
        case: Option<usize>,
    ) -> Result<Scenario, ScenarioError> {
        let mut table = self.base.clone();
        let mut ring = Vec::new();
        let mut fit = None;
        for (input, x) in assignments {
            match input.kind {
                InputKind::SizeTolerance => ring.push((*input, *x)),
                InputKind::FitTolerance => fit = Some((*input, *x)),
                _ => set(&mut table, &input.key, input.toml_value(*x))
                    .map_err(|m| self.error(input, m))?,
            }
        }
        if let Some((first, _)) = ring.first() {
            size_within_tolerance(&mut table, &ring).map_err(|m| self.error(first, m))?;
        }
        if let Some((input, z)) = fit {
            clearance_within_fit(&mut table, z).map_err(|m| self.error(input, m))?;
        } else if assignments.iter().any(|(i, _)| i.key == "seal.fit")
            && !assignments
                .iter()
                .any(|(i, _)| i.key == "seal.diametral_clearance")
            && let Some(toml::Value::Table(seal)) = table.get_mut("seal")
        {
            // a varied fit sets the clearance (its largest): the base's own was for its fit
            seal.remove("diametral_clearance");
        }
        let text =
            toml::to_string(&table).map_err(|e| self.error(assignments[0].0, e.to_string()))?;
        let mut scenario = Scenario::from_str(&text, &self.base_path).map_err(|e| {
            // the input the scenario's message names, else the first
            let (input, _) = match &e {
                ScenarioError::Invalid { key: Some(k), .. } => assignments
                    .iter()
                    .find(|(i, _)| i.key == *k)
                    .unwrap_or(&assignments[0]),
                _ => &assignments[0],
            };
            let what = match case {
                Some(i) => format!(
                    "case {i} ({})",
                    assignments
                        .iter()
                        .map(|(inp, x)| inp.describe(*x))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
                None => "this input".to_owned(),
            };
            let inner = match &e {
                ScenarioError::Invalid { key, message, .. } => match key {
                    Some(k) => format!("{k}: {message}"),
                    None => message.clone(),
                },
                other => other.to_string(),
            };
            self.error(
                input,
                format!(
                    "{what} is not a valid scenario (base {}): {inner}",
                    self.base_path.display()
                ),
            )
        })?;
        scenario.life.failure.stop_at_failure = !self.run_after_failure;
        // the base's compound, with what it has computed once (its creep series), when the
        // case did not change it
        let base = &self.base_scenario.life.material.prony;
        if scenario.life.material.prony == *base {
            scenario.life.material.prony = base.clone();
        }
        Ok(scenario)
    }

    fn error(&self, input: &StudyInput, message: impl Into<String>) -> ScenarioError {
        ScenarioError::Invalid {
            path: self.path.clone(),
            line: Some(input.line),
            key: Some(format!("vary.\"{}\"", input.key)),
            message: message.into(),
        }
    }

    /// The base scenario's text (for reports).
    pub fn base_text(&self) -> &str {
        &self.base_text
    }

    /// The study file's text, as validated (for reports).
    pub fn text(&self) -> &str {
        &self.text
    }
}

/// A hash of sealsim's version, the study and its base, each closed by a 0 byte: shards of
/// different studies never merge.
fn fingerprint(text: &str, base_text: &str) -> String {
    let mut hash = crate::math::fnv::Fnv1a::default();
    for part in [env!("CARGO_PKG_VERSION"), text, base_text] {
        hash.bytes(part.as_bytes()).bytes(&[0]);
    }
    format!("{:016x}", hash.0)
}

/// A count key (`samples`, `levels`): a whole number from 1 to `max`, `default` when absent.
fn count(
    source: &Source,
    v: &Option<Spanned<i64>>,
    key: &str,
    default: i64,
    max: i64,
) -> Result<usize, ScenarioError> {
    match v {
        None => Ok(default as usize),
        Some(s) if (1..=max).contains(s.get_ref()) => Ok(*s.get_ref() as usize),
        Some(s) => Err(source.error(
            s.span(),
            key,
            format!(
                "must be a whole number from 1 to {max}, got {}",
                s.get_ref()
            ),
        )),
    }
}

impl RawStudy {
    /// `design`: grid, monte-carlo or latin-hypercube.
    fn design(&self, source: &Source) -> Result<Design, ScenarioError> {
        match Design::ALL
            .into_iter()
            .find(|d| d.name() == self.design.get_ref())
        {
            Some(d) => Ok(d),
            None => Err(source.error(
                self.design.span(),
                "design",
                format!(
                    "unknown design \"{}\": one of grid, monte-carlo, latin-hypercube",
                    self.design.get_ref()
                ),
            )),
        }
    }

    /// `samples`: required by a sampling design, refused by a grid.
    fn samples(&self, source: &Source, design: Design) -> Result<usize, ScenarioError> {
        match (&self.samples, design) {
            (None, Design::MonteCarlo | Design::LatinHypercube) => Err(source.error(
                self.design.span(),
                "samples",
                format!("a {} design needs `samples`", design.name()),
            )),
            (Some(s), Design::Grid) => Err(source.error(
                s.span(),
                "samples",
                "a grid's cases are the product of its levels: give `levels` (for \
                 continuous inputs) or lists, not `samples`",
            )),
            _ => count(source, &self.samples, "samples", 1, 10_000_000),
        }
    }

    /// `seed` (≥ 0, default 0).
    fn seed(&self, source: &Source) -> Result<u64, ScenarioError> {
        match &self.seed {
            None => Ok(0),
            Some(s) if *s.get_ref() >= 0 => Ok(*s.get_ref() as u64),
            Some(s) => Err(source.error(s.span(), "seed", "must be ≥ 0")),
        }
    }

    /// `confidence` (strictly between 0.5 and 1, default 0.95).
    fn confidence(&self, source: &Source) -> Result<f64, ScenarioError> {
        match &self.confidence {
            None => Ok(0.95),
            Some(c) if *c.get_ref() > 0.5 && *c.get_ref() < 1.0 => Ok(*c.get_ref()),
            Some(c) => Err(source.error(
                c.span(),
                "confidence",
                "must lie strictly between 0.5 and 1",
            )),
        }
    }

    /// `report_times` (times > 0), [`DEFAULT_REPORT_TIMES`] when absent.
    fn report_times(&self, source: &Source) -> Result<Vec<f64>, ScenarioError> {
        match &self.report_times {
            None => Ok(DEFAULT_REPORT_TIMES.to_vec()),
            Some(list) => list
                .get_ref()
                .iter()
                .map(|t| {
                    units::parse_quantity(t.get_ref(), Dimension::TIME)
                        .ok()
                        .filter(|v| *v > 0.0)
                        .ok_or_else(|| {
                            source.error(
                                t.span(),
                                "report_times",
                                format!("\"{}\" is not a time > 0 (e.g. \"1 year\")", t.get_ref()),
                            )
                        })
                })
                .collect(),
        }
    }

    /// The inputs of `[vary]` in file order, with their distributions; `base` is the base
    /// scenario's table, `bands` its compound's (`"band"`).
    fn inputs(
        &self,
        source: &Source,
        base: &toml::Table,
        bands: &[crate::material::FigureBand],
    ) -> Result<(Vec<StudyInput>, Vec<Distribution>), ScenarioError> {
        let mut entries: Vec<(&String, &Spanned<toml::Value>)> =
            self.vary.get_ref().iter().collect();
        entries.sort_by_key(|(_, v)| v.span().start);
        if entries.is_empty() && self.tolerances.is_none() {
            return Err(source.error(self.vary.span(), "vary", "names no input to vary"));
        }
        let mut inputs = Vec::new();
        let mut distributions = Vec::new();
        for (key, value) in entries {
            let entry = Entry {
                source,
                key,
                span: value.span(),
                base,
                bands,
            };
            let (input, distribution) = entry.parse(value.get_ref())?;
            inputs.push(input);
            distributions.push(distribution);
        }
        if let Some(mode) = &self.tolerances {
            if mode.get_ref() != "fits" {
                return Err(source.error(
                    mode.span(),
                    "tolerances",
                    format!(
                        "unknown mode {:?}: \"fits\" draws every dimension the base gives a \
                         tolerance for",
                        mode.get_ref()
                    ),
                ));
            }
            let varied: Vec<String> = inputs.iter().map(|i: &StudyInput| i.key.clone()).collect();
            for (key, band) in toleranced(base, self.vary.get_ref())
                .into_iter()
                .filter(|(k, _)| !varied.contains(k))
            {
                let mut table = toml::Table::new();
                table.insert("tolerance".into(), toml::Value::String(band.into()));
                let entry = Entry {
                    source,
                    key: &key,
                    span: mode.span(),
                    base,
                    bands,
                };
                let (input, distribution) = entry.parse(&toml::Value::Table(table))?;
                inputs.push(input);
                distributions.push(distribution);
            }
        }
        Ok((inputs, distributions))
    }

    /// `correlations` (a Monte Carlo design's only) → the correlation factor of `inputs`.
    fn correlation(
        &self,
        source: &Source,
        design: Design,
        inputs: &[StudyInput],
    ) -> Result<Option<Vec<f64>>, ScenarioError> {
        let Some(list) = &self.correlations else {
            return Ok(None);
        };
        if design != Design::MonteCarlo {
            return Err(source.error(
                list.span(),
                "correlations",
                "correlated inputs need design = \"monte-carlo\"",
            ));
        }
        let mut pairs = Vec::new();
        for c in list.get_ref() {
            pairs.push(correlation_pair(source, c, inputs, &pairs)?);
        }
        crate::study::design::correlation_factor(inputs.len(), &pairs)
            .map(Some)
            .map_err(|m| source.error(list.span(), "correlations", m))
    }
}

/// One `correlations` entry: the indices of its two inputs among `inputs` and its Spearman
/// coefficient, checked against the `pairs` before it.
fn correlation_pair(
    source: &Source,
    c: &Spanned<RawCorrelation>,
    inputs: &[StudyInput],
    pairs: &[(usize, usize, f64)],
) -> Result<(usize, usize, f64), ScenarioError> {
    let bad = |m: String| source.error(c.span(), "correlations", m);
    let raw = c.get_ref();
    let index = |name: &String| {
        inputs
            .iter()
            .position(|i: &StudyInput| i.key == *name)
            .ok_or_else(|| bad(format!("\"{name}\" is not an input in [vary]")))
    };
    let [a, b] = raw.inputs.as_slice() else {
        return Err(bad("`inputs` names two inputs".into()));
    };
    let (i, j) = (index(a)?, index(b)?);
    if i == j {
        return Err(bad("`inputs` names two different inputs".into()));
    }
    if raw.spearman.is_nan() || raw.spearman.abs() >= 1.0 {
        return Err(bad("`spearman` must lie strictly between −1 and 1".into()));
    }
    if pairs
        .iter()
        .any(|&(p, q, _)| (p, q) == (i, j) || (p, q) == (j, i))
    {
        return Err(bad(format!("{a} and {b} are correlated twice")));
    }
    Ok((i, j, raw.spearman))
}

/// Sets `key` (dotted) in `table`, creating tables on the way.
pub(crate) fn set(table: &mut toml::Table, key: &str, value: toml::Value) -> Result<(), String> {
    let parts: Vec<&str> = key.split('.').collect();
    let (last, path) = parts.split_last().ok_or("an empty key path")?;
    let mut t = table;
    for p in path {
        let next = t
            .entry(p.to_string())
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        t = match next {
            toml::Value::Table(inner) => inner,
            _ => return Err(format!("`{p}` in the base scenario is not a table")),
        };
    }
    if path == ["material"] && (*last == "library" || *last == "file") {
        // a new compound: drop the old one's keys, keep the scenario's option
        t.retain(|k, _| k == "asperity_modulus");
    }
    t.insert(last.to_string(), value);
    Ok(())
}

/// A fraction of a case's own tolerance band, normal with the band at ±3σ (truncated there).
const FRACTION_NORMAL: Distribution = Distribution::Normal {
    mean: 0.0,
    std: 1.0 / 3.0,
    lo: -1.0,
    hi: 1.0,
};

/// The ring keys a size's own tolerance can vary (`tolerance = "size"`).
const RING_KEYS: [&str; 2] = ["seal.cross_section", "seal.inner_diameter"];

/// The case's `seal.size` written out as `cross_section` and `inner_diameter` \[m\], each at
/// its nominal plus z × its AS568 ± tolerance for the `(input, z)` in `ring` (the other at its
/// nominal).
fn size_within_tolerance(
    table: &mut toml::Table,
    ring: &[(&StudyInput, f64)],
) -> Result<(), String> {
    let Some(toml::Value::Table(seal)) = table.get_mut("seal") else {
        return Err("tolerance = \"size\" needs a [seal] with `size`".into());
    };
    let Some(toml::Value::String(name)) = seal.remove("size") else {
        return Err(
            "tolerance = \"size\" draws the ring within its size's tolerance: the case has no \
             `seal.size` (give one in the base or vary it)"
                .into(),
        );
    };
    let free = super::as568::lookup(&name)
        .map_err(|e| e.to_string())?
        .ring();
    let nominal = [
        (free.cross_section, free.cross_section_tolerance),
        (free.inner_diameter, free.inner_diameter_tolerance),
    ];
    for (k, key) in RING_KEYS.iter().enumerate() {
        let (value, tolerance) = nominal[k];
        let z = ring
            .iter()
            .find(|(input, _)| input.key == *key)
            .map_or(0.0, |(_, z)| *z);
        let name = key.trim_start_matches("seal.");
        seal.insert(
            name.into(),
            toml::Value::String(format!("{} m", units::exact(value + z * tolerance))),
        );
    }
    Ok(())
}

/// The case's `seal.diametral_clearance` \[m\] at the fraction `z` ∈ [−1, 1] between the
/// smallest and largest clearance of its ISO 286 `seal.fit` at its bore (piston) or rod
/// diameter; the case's own `diametral_clearance` is replaced.
fn clearance_within_fit(table: &mut toml::Table, z: f64) -> Result<(), String> {
    let Some(toml::Value::Table(seal)) = table.get_mut("seal") else {
        return Err("tolerance = \"fit\" needs a [seal] with `fit`".into());
    };
    let Some(toml::Value::String(fit)) = seal.get("fit") else {
        return Err(
            "tolerance = \"fit\" draws the clearance within the case's ISO 286 fit: the case has \
             no `seal.fit` (give one in the base, \"H8/f7\", or vary it)"
                .into(),
        );
    };
    let seat = ["bore_diameter", "rod_diameter"]
        .iter()
        .find_map(|k| seal.get(*k).and_then(toml::Value::as_str))
        .ok_or(
            "tolerance = \"fit\" needs the case's bore_diameter (piston) or rod_diameter (rod)",
        )?;
    let diameter = units::parse_quantity(seat, Dimension::LENGTH).map_err(|e| e.to_string())?;
    let (min, max) = crate::fits::Fit::parse(fit)
        .and_then(|f| f.clearance(diameter))
        .map_err(|e| format!("seal.fit: {e}"))?;
    let clearance = 0.5 * (min + max) + z * 0.5 * (max - min);
    seal.insert(
        "diametral_clearance".into(),
        toml::Value::String(format!("{} m", units::exact(clearance))),
    );
    Ok(())
}

/// The dimensions `tolerances = "fits"` draws, each with its band (`"size"`, `"fit"` or
/// `"scenario"`): the ring within its size's tolerance when the base or `[vary]` gives
/// `seal.size`, the clearance within its ISO 286 fit when they give `seal.fit`, and every
/// `seal.X` whose `seal.X_tolerance` the base gives.
fn toleranced(
    base: &toml::Table,
    vary: &BTreeMap<String, Spanned<toml::Value>>,
) -> Vec<(String, &'static str)> {
    let mut out = Vec::new();
    if get(base, "seal.size").is_some() || vary.contains_key("seal.size") {
        out.extend(RING_KEYS.iter().map(|k| ((*k).to_owned(), "size")));
    }
    if get(base, "seal.fit").is_some() || vary.contains_key("seal.fit") {
        out.push(("seal.diametral_clearance".to_owned(), "fit"));
    }
    if let Some(toml::Value::Table(seal)) = base.get("seal") {
        for key in seal.keys() {
            if let Some(dimension) = key.strip_suffix("_tolerance")
                && seal.contains_key(dimension)
            {
                out.push((format!("seal.{dimension}"), "scenario"));
            }
        }
    }
    out
}

/// A value at a key path of a TOML table.
fn get<'a>(table: &'a toml::Table, key: &str) -> Option<&'a toml::Value> {
    let mut parts = key.split('.');
    let mut v = table.get(parts.next()?)?;
    for p in parts {
        v = v.as_table()?.get(p)?;
    }
    Some(v)
}

/// The column suffix of an SI dimension: `m`, `Pa`, `K`, `Pa_s`, else its formula.
fn si_suffix(d: Dimension) -> String {
    let named = [
        (Dimension::LENGTH, "m"),
        (Dimension::PRESSURE, "Pa"),
        (Dimension::TEMPERATURE, "K"),
        (Dimension::TIME, "s"),
        (Dimension::VISCOSITY, "Pa_s"),
        (Dimension::FORCE_PER_LENGTH, "N_per_m"),
        (Dimension::FORCE, "N"),
        (Dimension::VOLUME_FLOW, "m3_per_s"),
        (Dimension::VOLUME, "m3"),
        (Dimension::WAVEVECTOR, "per_m"),
        (Dimension::THERMAL_EXPANSION, "per_K"),
        (Dimension::VELOCITY, "m_per_s"),
        (Dimension::MOLAR_ENERGY, "J_per_mol"),
        (Dimension::DENSITY, "kg_per_m3"),
    ];
    named
        .iter()
        .find(|(n, _)| *n == d)
        .map_or_else(|| d.formula().replace('·', "_"), |(_, s)| (*s).to_owned())
}

/// A unit's factor to SI and its dimension.
type UnitFactor = (f64, Dimension);

/// A parameter as written: a number and its unit ("" for a bare number).
#[derive(Debug, Clone, PartialEq)]
struct Written {
    value: f64,
    unit: String,
}

/// One `[vary]` entry being read.
struct Entry<'a> {
    source: &'a Source<'a>,
    key: &'a str,
    span: std::ops::Range<usize>,
    base: &'a toml::Table,
    /// The bands of the base's compound (`[material.bands]`): what `"band"` draws from.
    bands: &'a [crate::material::FigureBand],
}

const KINDS: &str = "uniform, triangular, normal, lognormal, log-uniform, range, log-range, \
                     values, tolerance";

impl Entry<'_> {
    fn err(&self, message: impl Into<String>) -> ScenarioError {
        self.source.error(
            self.span.clone(),
            &format!("vary.\"{}\"", self.key),
            message,
        )
    }

    /// `"band"`: the base compound's `[material.bands]` entry of this key as a uniform
    /// distribution over it (in SI).
    fn band(&self) -> Result<toml::Table, ScenarioError> {
        let key = self.key.strip_prefix("material.").unwrap_or(self.key);
        let Some(band) = self.bands.iter().find(|b| b.key == key) else {
            let given = if self.bands.is_empty() {
                "gives none".to_owned()
            } else {
                format!(
                    "gives {}",
                    self.bands
                        .iter()
                        .map(|b| format!("\"{}\"", b.key))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            };
            return Err(self.err(format!(
                "\"band\" draws from the base compound's [material.bands], which {given} (a \
                 compound from `sealsim materials new` has \"ageing.activation_energy\"); or \
                 give a distribution such as {{ distribution = \"uniform\", min = …, max = … }}"
            )));
        };
        if key != self.key {
            return Err(self.err(format!(
                "the scenario's `[ageing]` overrides its compound's figures: vary \"{key}\" = \
                 \"band\""
            )));
        }
        let unit = band.unit();
        let mut t = toml::Table::new();
        t.insert("distribution".into(), toml::Value::String("uniform".into()));
        for (k, v) in [("min", band.min), ("max", band.max)] {
            t.insert(
                k.into(),
                toml::Value::String(format!("{v:e} {unit}").trim().into()),
            );
        }
        Ok(t)
    }

    fn parse(&self, value: &toml::Value) -> Result<(StudyInput, Distribution), ScenarioError> {
        let table = match value {
            // the compound's own band of this figure, drawn uniformly (docs/model.md §5.4)
            toml::Value::String(s) if s == "band" => self.band()?,
            // the shorthand "±0.08 mm": a tolerance band about the base's value
            toml::Value::String(s) => {
                let mut t = toml::Table::new();
                t.insert("tolerance".into(), toml::Value::String(s.clone()));
                t
            }
            toml::Value::Table(t) => t.clone(),
            _ => {
                return Err(self.err(
                    "must be a table such as { distribution = \"normal\", mean = …, std = … } \
                     or a tolerance band \"±0.08 mm\"",
                ));
            }
        };
        let kind = match table.get("distribution") {
            Some(toml::Value::String(s)) => s.clone(),
            Some(_) => return Err(self.err("`distribution` must be a string")),
            None if table.contains_key("values") => "values".into(),
            None if table.contains_key("tolerance") => "tolerance".into(),
            None => return Err(self.err(format!("needs a `distribution`: one of {KINDS}"))),
        };
        let allowed: &[&str] = match kind.as_str() {
            "uniform" | "log-uniform" => &["min", "max"],
            "triangular" => &["min", "mode", "max"],
            "normal" => &["mean", "std", "min", "max"],
            "lognormal" => &["median", "geometric_std", "min", "max"],
            "range" | "log-range" => &["from", "to", "count"],
            "values" => &["values"],
            "tolerance" => &["tolerance", "nominal", "shape"],
            other => {
                return Err(self.err(format!("unknown distribution \"{other}\": one of {KINDS}")));
            }
        };
        if let Some(k) = table
            .keys()
            .find(|k| *k != "distribution" && !allowed.contains(&k.as_str()))
        {
            return Err(self.err(format!(
                "unknown key `{k}` for a {kind} distribution: it takes {}",
                allowed.join(", ")
            )));
        }
        if let Some(input) = self.not_a_quantity(&kind, &table) {
            return input;
        }
        let required = |k: &str| -> Result<Written, ScenarioError> {
            match table.get(k) {
                Some(v) => self.written(k, v),
                None => Err(self.err(format!("a {kind} distribution needs `{k}`"))),
            }
        };
        let optional = |k: &str| table.get(k).map(|v| self.written(k, v)).transpose();

        // the location parameters fix the unit; spreads convert into it
        let (unit, dist) = match kind.as_str() {
            "uniform" | "log-uniform" => {
                let (min, max) = (required("min")?, required("max")?);
                let unit = min.unit.clone();
                let (min, max) = (self.at(&min, &unit)?, self.at(&max, &unit)?);
                let d = if kind == "uniform" {
                    Distribution::Uniform { min, max }
                } else {
                    Distribution::LogUniform { min, max }
                };
                (unit, d)
            }
            "triangular" => {
                let (min, mode, max) = (required("min")?, required("mode")?, required("max")?);
                let unit = mode.unit.clone();
                (
                    unit.clone(),
                    Distribution::Triangular {
                        min: self.at(&min, &unit)?,
                        mode: self.at(&mode, &unit)?,
                        max: self.at(&max, &unit)?,
                    },
                )
            }
            "normal" => {
                let mean = required("mean")?;
                let unit = mean.unit.clone();
                let (lo, hi) = self.bounds(optional("min")?, optional("max")?, &unit)?;
                (
                    unit.clone(),
                    Distribution::Normal {
                        mean: mean.value,
                        std: self.spread(&required("std")?, &unit)?,
                        lo,
                        hi,
                    },
                )
            }
            "lognormal" => {
                let median = required("median")?;
                let unit = median.unit.clone();
                let gsd = required("geometric_std")?;
                if !gsd.unit.is_empty() {
                    return Err(self.err("geometric_std is a factor (a bare number > 1)"));
                }
                let (lo, hi) = self.bounds(optional("min")?, optional("max")?, &unit)?;
                (
                    unit.clone(),
                    Distribution::LogNormal {
                        median: median.value,
                        geometric_std: gsd.value,
                        lo: if lo.is_finite() { lo } else { 0.0 },
                        hi,
                    },
                )
            }
            "range" | "log-range" => {
                let (from, to) = (required("from")?, required("to")?);
                let unit = from.unit.clone();
                let (a, b) = (self.at(&from, &unit)?, self.at(&to, &unit)?);
                let n = match table.get("count") {
                    Some(toml::Value::Integer(n)) if (2..=1000).contains(n) => *n as usize,
                    _ => {
                        return Err(
                            self.err("a range needs `count`, a whole number from 2 to 1000")
                        );
                    }
                };
                if kind == "log-range" && (a <= 0.0 || b <= 0.0) {
                    return Err(self.err("a log-range needs from > 0 and to > 0"));
                }
                let levels = (0..n)
                    .map(|k| {
                        let f = k as f64 / (n - 1) as f64;
                        let x = if kind == "log-range" {
                            a * (b / a).powf(f)
                        } else {
                            a + f * (b - a)
                        };
                        // 0.1 … 3.2 in 6 steps: 0.8, not 0.7999999999999999
                        format!("{x:.11e}").parse().unwrap_or(x)
                    })
                    .collect();
                (unit, Distribution::Levels(levels))
            }
            _ => self.tolerance(&table)?,
        };
        dist.check().map_err(|m| self.err(format!("{kind}: {m}")))?;
        Ok((self.quantity_input(&unit)?, dist))
    }

    /// A quantity input in `unit` ("" = SI) with its SI conversion for the tables: a factor,
    /// and for an absolute temperature in °C or °F an offset.
    fn quantity_input(&self, unit: &str) -> Result<StudyInput, ScenarioError> {
        if unit.is_empty() {
            return Ok(self.with_kind(InputKind::Quantity {
                unit: String::new(),
                scale: 1.0,
                offset: 0.0,
                dimension: None,
            }));
        }
        let (scale, dimension) =
            units::parse_unit(unit).map_err(|e| self.err(format!("unit \"{unit}\": {e}")))?;
        let absolute =
            dimension == Dimension::TEMPERATURE && !TEMPERATURE_DIFFERENCES.contains(&self.key);
        let (scale, offset) = if absolute {
            let k =
                |x: f64| units::absolute_temperature(x, unit).map_err(|e| self.err(e.to_string()));
            let k0 = k(0.0)?;
            (k(1.0)? - k0, k0)
        } else {
            (scale, 0.0)
        };
        Ok(self.with_kind(InputKind::Quantity {
            unit: unit.to_owned(),
            scale,
            offset,
            dimension: Some(dimension),
        }))
    }

    fn with_kind(&self, kind: InputKind) -> StudyInput {
        StudyInput {
            key: self.key.to_owned(),
            line: self.source.line(self.span.start),
            kind,
        }
    }

    fn written(&self, k: &str, v: &toml::Value) -> Result<Written, ScenarioError> {
        match v {
            toml::Value::Integer(i) => Ok(Written {
                value: *i as f64,
                unit: String::new(),
            }),
            toml::Value::Float(f) if f.is_finite() => Ok(Written {
                value: *f,
                unit: String::new(),
            }),
            toml::Value::String(s) => {
                let (value, unit) = units::split_quantity(s)
                    .map_err(|e| self.err(format!("`{k}` = \"{s}\": {e}")))?;
                Ok(Written {
                    value,
                    unit: unit.to_owned(),
                })
            }
            _ => Err(self.err(format!(
                "`{k}` must be a number or a quantity such as \"0.8 um\""
            ))),
        }
    }

    /// A location parameter in `unit`.
    fn at(&self, w: &Written, unit: &str) -> Result<f64, ScenarioError> {
        if w.unit == unit {
            return Ok(w.value);
        }
        let (from, to) = self.units_pair(&w.unit, unit)?;
        let absolute =
            from.1 == Dimension::TEMPERATURE && !TEMPERATURE_DIFFERENCES.contains(&self.key);
        if absolute {
            let k = |x: f64, u: &str| {
                units::absolute_temperature(x, u).map_err(|e| self.err(e.to_string()))
            };
            let kelvin = k(w.value, &w.unit)?;
            let (k0, k1) = (k(0.0, unit)?, k(1.0, unit)?);
            return Ok((kelvin - k0) / (k1 - k0));
        }
        Ok(w.value * from.0 / to.0)
    }

    /// A spread (std, band) in `unit`: a difference, scaled only.
    fn spread(&self, w: &Written, unit: &str) -> Result<f64, ScenarioError> {
        if w.unit == unit {
            return Ok(w.value);
        }
        let (from, to) = self.units_pair(&w.unit, unit)?;
        Ok(w.value * from.0 / to.0)
    }

    /// The SI factors and dimensions of two units of the same quantity ("" = SI, taking the
    /// other's dimension).
    fn units_pair(&self, a: &str, b: &str) -> Result<(UnitFactor, UnitFactor), ScenarioError> {
        let parse =
            |u: &str| units::parse_unit(u).map_err(|e| self.err(format!("unit \"{u}\": {e}")));
        let (pa, pb) = match (a.is_empty(), b.is_empty()) {
            (true, true) => {
                return Ok((
                    (1.0, Dimension::DIMENSIONLESS),
                    (1.0, Dimension::DIMENSIONLESS),
                ));
            }
            (true, false) => {
                let pb = parse(b)?;
                ((1.0, pb.1), pb)
            }
            (false, true) => {
                let pa = parse(a)?;
                (pa, (1.0, pa.1))
            }
            (false, false) => (parse(a)?, parse(b)?),
        };
        if pa.1 != pb.1 {
            return Err(self.err(format!(
                "units \"{a}\" and \"{b}\" measure different quantities ({} and {})",
                pa.1.describe(),
                pb.1.describe()
            )));
        }
        Ok((pa, pb))
    }

    fn bounds(
        &self,
        min: Option<Written>,
        max: Option<Written>,
        unit: &str,
    ) -> Result<(f64, f64), ScenarioError> {
        Ok((
            min.map(|m| self.at(&m, unit))
                .transpose()?
                .unwrap_or(f64::NEG_INFINITY),
            max.map(|m| self.at(&m, unit))
                .transpose()?
                .unwrap_or(f64::INFINITY),
        ))
    }

    /// `tolerance = "±0.08 mm"` (or `"scenario"`: the base's `<key>_tolerance`) about `nominal`
    /// (default: the base's value): `shape = "normal"` (default; the band is ±3σ, truncated
    /// there) or `"uniform"`.
    fn tolerance(&self, table: &toml::Table) -> Result<(String, Distribution), ScenarioError> {
        let nominal = match table.get("nominal") {
            Some(v) => self.written("nominal", v)?,
            None => match get(self.base, self.key) {
                Some(v) => self.written(self.key, v).map_err(|_| {
                    self.err("the base scenario's value is not a number: give `nominal`")
                })?,
                None => {
                    return Err(self.err(
                        "a tolerance band needs a nominal value: give `nominal` or set the key \
                         in the base scenario",
                    ));
                }
            },
        };
        let unit = nominal.unit.clone();
        let band_text = match table.get("tolerance") {
            Some(toml::Value::String(s)) => s.trim().to_owned(),
            Some(toml::Value::Integer(i)) => i.to_string(),
            Some(toml::Value::Float(f)) => f.to_string(),
            _ => return Err(self.err("`tolerance` must be a band such as \"±0.08 mm\"")),
        };
        let band = if band_text == "scenario" {
            let key = format!("{}_tolerance", self.key);
            match get(self.base, &key) {
                Some(v) => self.written(&key, v)?,
                None => {
                    return Err(self.err(format!(
                        "tolerance = \"scenario\" reads `{key}` from the base scenario, which \
                         has none"
                    )));
                }
            }
        } else {
            let stripped = band_text
                .strip_prefix('±')
                .or_else(|| band_text.strip_prefix("+/-"))
                .unwrap_or(&band_text);
            self.written("tolerance", &toml::Value::String(stripped.to_owned()))?
        };
        let b = self.spread(&band, &unit)?;
        if b.is_nan() || b <= 0.0 {
            return Err(self.err("the tolerance band must be > 0"));
        }
        let n = nominal.value;
        let shape = match table.get("shape") {
            None => "normal",
            Some(toml::Value::String(s)) if s == "normal" || s == "uniform" => s.as_str(),
            Some(_) => return Err(self.err("`shape` is \"normal\" (±3σ) or \"uniform\"")),
        };
        let d = if shape == "uniform" {
            Distribution::Uniform {
                min: n - b,
                max: n + b,
            }
        } else {
            Distribution::Normal {
                mean: n,
                std: b / 3.0,
                lo: n - b,
                hi: n + b,
            }
        };
        Ok((unit, d))
    }

    /// The entries whose values are not quantities in a unit: `values` (words or quantities)
    /// and `tolerance = "size"`; `None` for the others.
    fn not_a_quantity(
        &self,
        kind: &str,
        table: &toml::Table,
    ) -> Option<Result<(StudyInput, Distribution), ScenarioError>> {
        match (kind, table.get("tolerance")) {
            ("values", _) => Some(self.values(table)),
            ("tolerance", Some(toml::Value::String(t))) if t == "size" => {
                Some(self.size_tolerance(table))
            }
            ("tolerance", Some(toml::Value::String(t))) if t == "fit" => {
                Some(self.fit_tolerance(table))
            }
            _ => None,
        }
    }

    /// `tolerance = "size"` on `seal.cross_section` or `seal.inner_diameter`: the fraction z of
    /// the case's AS568 ± tolerance, normal with the band at ±3σ (truncated there; `shape =
    /// "uniform"`: uniform over it).
    fn size_tolerance(
        &self,
        table: &toml::Table,
    ) -> Result<(StudyInput, Distribution), ScenarioError> {
        if !RING_KEYS.contains(&self.key) {
            return Err(self.err(format!(
                "tolerance = \"size\" applies to the ring's {}: give this key a band such as \
                 \"±0.05 mm\"",
                RING_KEYS.join(" and ")
            )));
        }
        if table.contains_key("nominal") {
            return Err(self.err(
                "tolerance = \"size\" takes the nominal from the case's `seal.size`: remove \
                 `nominal`",
            ));
        }
        Ok((
            self.with_kind(InputKind::SizeTolerance),
            self.fraction(table)?,
        ))
    }

    /// The fraction z ∈ [−1, 1] of a case's own tolerance (`tolerance = "size"`, `"fit"`):
    /// normal with the band at ±3σ, truncated there (default), or `shape = "uniform"`.
    fn fraction(&self, table: &toml::Table) -> Result<Distribution, ScenarioError> {
        match table.get("shape") {
            None => Ok(FRACTION_NORMAL),
            Some(toml::Value::String(s)) if s == "normal" => Ok(FRACTION_NORMAL),
            Some(toml::Value::String(s)) if s == "uniform" => Ok(Distribution::Uniform {
                min: -1.0,
                max: 1.0,
            }),
            _ => Err(self.err("`shape` is \"normal\" (±3σ) or \"uniform\"")),
        }
    }

    /// `tolerance = "fit"` on `seal.diametral_clearance`: the fraction z between the case's
    /// ISO 286 fit's smallest (−1) and largest (+1) clearance, normal with the range at ±3σ
    /// (truncated there; both parts' sizes spread about their tolerance zones' middles) or
    /// `shape = "uniform"`.
    fn fit_tolerance(
        &self,
        table: &toml::Table,
    ) -> Result<(StudyInput, Distribution), ScenarioError> {
        if self.key != "seal.diametral_clearance" {
            return Err(self.err(
                "tolerance = \"fit\" applies to seal.diametral_clearance (the clearance of the \
                 case's ISO 286 `seal.fit`): give this key a band such as \"±0.05 mm\"",
            ));
        }
        if table.contains_key("nominal") {
            return Err(self.err(
                "tolerance = \"fit\" takes the range from the case's `seal.fit`: remove `nominal`",
            ));
        }
        Ok((
            self.with_kind(InputKind::FitTolerance),
            self.fraction(table)?,
        ))
    }

    /// `values = [...]`: quantities (all of one quantity) or words, equally likely.
    fn values(&self, table: &toml::Table) -> Result<(StudyInput, Distribution), ScenarioError> {
        let list = match table.get("values") {
            Some(toml::Value::Array(a)) if !a.is_empty() => a,
            _ => return Err(self.err("`values` must be a non-empty list")),
        };
        let words: Vec<Option<&str>> = list
            .iter()
            .map(|v| match v {
                toml::Value::String(s) if units::split_quantity(s).is_err() => Some(s.as_str()),
                _ => None,
            })
            .collect();
        if words.iter().all(Option::is_some) {
            let words: Vec<String> = words.into_iter().flatten().map(str::to_owned).collect();
            let d = Distribution::Levels((0..words.len()).map(|i| i as f64).collect());
            return Ok((self.with_kind(InputKind::Words(words)), d));
        }
        if words.iter().any(Option::is_some) {
            return Err(self.err("`values` mixes words and numbers"));
        }
        let written: Vec<Written> = list
            .iter()
            .map(|v| self.written("values", v))
            .collect::<Result<_, _>>()?;
        let unit = written[0].unit.clone();
        let levels = written
            .iter()
            .map(|w| self.at(w, &unit))
            .collect::<Result<Vec<_>, _>>()?;
        let d = Distribution::Levels(levels);
        d.check().map_err(|m| self.err(m))?;
        Ok((self.quantity_input(&unit)?, d))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip_through_their_text() {
        for x in [
            0.25,
            8e-7,
            1.0 / 3.0,
            353.15,
            1e7,
            0.0,
            -2.5e-12,
            123456.789,
            5e-324,
        ] {
            let t = units::exact(x);
            assert_eq!(t.parse::<f64>().ok(), Some(x), "{t}");
            // and through a quantity, as a case's scenario reads it
            assert_eq!(
                units::split_quantity(&format!("{t} um")).ok(),
                Some((x, "um"))
            );
        }
    }

    #[test]
    fn set_creates_tables_and_replaces_a_compound() {
        let mut t: toml::Table = "[material]\nlibrary = \"nbr-70\"\nasperity_modulus = \"follow\"\n[seal]\nsqueeze = 0.2\n"
            .parse()
            .unwrap();
        set(
            &mut t,
            "model.percolation_threshold",
            toml::Value::Float(0.42),
        )
        .unwrap();
        set(
            &mut t,
            "material.file",
            toml::Value::String("x.toml".into()),
        )
        .unwrap();
        assert_eq!(
            get(&t, "model.percolation_threshold"),
            Some(&toml::Value::Float(0.42))
        );
        assert!(get(&t, "material.library").is_none());
        assert!(get(&t, "material.asperity_modulus").is_some());
        assert!(set(&mut t, "seal.squeeze.x", toml::Value::Float(1.0)).is_err());
    }
}
