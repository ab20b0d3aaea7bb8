//! `sealsim advise` as a library call (docs/model.md §16): what would make a scenario meet a life
//! target. The design variables that apply to the seal (the compound, the squeeze, the finish,
//! back-up rings, the groove width, a flat seal's seating stress and compression) are each
//! stepped (the sensitivity), pushed to the end of their admissible range and, where that
//! passes, bisected for the smallest change that does; pairs of the most effective ones are
//! tried too; every proposal is then verified by a full run (with the neighbouring level's band).
//!
//! A value is *admissible* when the scenario with it validates (a gland that cannot be
//! assembled — over-filled at maximum material, over-compressed, over-stretched — is refused by
//! the validator and dropped) and it breaks no handbook limit the base scenario keeps (the
//! squeeze range over the tolerances, the fill, the stretch; docs/model.md §6.2). A compound is
//! proposed only when it is rated A or B for the scenario's fluid class (docs/model.md §6.8).
//!
//! Determinism: each stage's runs are fixed before it starts, run in parallel and collected in
//! order; the next stage depends only on those results. So the output is the same on any
//! number of threads.

use super::study::SharedProgress;
use super::{life_on, scenario_path};
use crate::contact::ContactSettings;
use crate::gland::{
    GlandKind, Limit, MAX_STRETCH_GUIDANCE, MIN_FILL_GUIDANCE, NOMINAL_FILL_GUIDANCE,
    STATIC_SQUEEZE,
};
use crate::leak::{ContactPath, Fidelity};
use crate::material::compatibility::{Compatibility, Rating};
use crate::scenario::{Scenario, ScenarioError};
use crate::simulate::LifeResult;
use crate::surface::Spectrum;
use crate::units::{Dimension, parse_quantity};
use crate::validity::Findings;
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// The finest practical counterface finish the search goes down to: Ra 0.05 µm \[m\], the low
/// end of super-finishing (0.05–0.2 µm) and lapping (0.05–0.4 µm) on normal production
/// machines (CalQlata, "Surface Finish (machining)", <http://calqlata.com/Maths/Surface_Finish.html>,
/// a secondary source). The search never proposes a finer finish, and never a rougher one.
pub const FINEST_RA: f64 = 0.05e-6;

/// The step of the sensitivity: ±5 % of the variable's value (at least one practical step).
pub const SENSITIVITY_STEP: f64 = 0.05;

/// A flat seal's seating stress and compression are searched within this factor of their
/// given values (× 1/2 … × 2): **assumed**, sealsim's bound where the gasket's own maximum
/// seating stress (its maker's figure) is not in the scenario.
pub const FLAT_FACTOR: f64 = 2.0;

/// The default bound on the number of life runs (`--max-runs`).
pub const DEFAULT_MAX_RUNS: usize = 200;

/// How many of the most effective variables are paired.
const PAIRED: usize = 4;

/// Bisection steps of the admissible range (validation only, no life run).
const ADMISSIBLE_STEPS: usize = 24;

/// The life target and the bounds of the search.
#[derive(Debug, Clone)]
pub struct Options {
    /// The life to meet \[s\].
    pub target: f64,
    /// The target as the user wrote it (`"10y"`): written into a proposal whose scenario runs
    /// for another duration.
    pub target_text: String,
    /// At most this many life runs (search and verification).
    pub max_runs: usize,
    /// Worker threads (`None`: all cores).
    pub threads: Option<usize>,
}

/// Whether a variable is a design choice (proposed) or the service (its sensitivity printed
/// for information only).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Domain {
    Design,
    Service,
}

/// A variable on a grid of practical steps: its value at step `n` is
/// `grid0 + n · step` (display unit), admissible for `lo ≤ n ≤ hi`.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// The base value in the display unit.
    pub base: f64,
    /// The base rounded to the grid.
    grid0: f64,
    pub step: f64,
    /// The display unit written into the TOML string (`mm`, `um`, `MPa`, `%`).
    pub unit: &'static str,
    decimals: usize,
    /// The admissible steps: `lo ≤ 0 ≤ hi`.
    pub lo: i64,
    pub hi: i64,
    /// What bounds the range, for the report.
    pub bound: String,
}

impl Grid {
    /// The value at step `n`, in the display unit.
    pub fn value(&self, n: i64) -> f64 {
        if n == 0 {
            self.base
        } else {
            self.grid0 + n as f64 * self.step
        }
    }

    /// The TOML string of step `n`: `"2.84 mm"`.
    pub fn text(&self, n: i64) -> String {
        if n == 0 {
            return format!("{} {}", crate::units::exact(self.base), self.unit);
        }
        format!("{:.*} {}", self.decimals, self.value(n), self.unit)
    }
}

/// How a variable's values are given.
#[derive(Debug, Clone, PartialEq)]
pub enum Levels {
    /// A continuous quantity on a grid of practical steps.
    Continuous(Grid),
    /// A few choices (the compounds, the back-up rings), each a set of keys.
    Choices(Vec<Choice>),
}

/// One choice of a discrete variable.
#[derive(Debug, Clone, PartialEq)]
pub struct Choice {
    /// The keys it sets, as TOML values.
    pub values: Vec<(String, toml::Value)>,
    /// What the choice rests on (a compound's rating in the fluid, the handbook's width).
    pub note: String,
}

/// A variable the search moves.
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// The scenario key (dotted) it sets.
    pub key: String,
    /// What it is, in words.
    pub label: String,
    pub domain: Domain,
    pub levels: Levels,
}

/// A setting: the keys changed from the base and the words for it.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    pub values: Vec<(String, toml::Value)>,
    /// Each change's note (a compound's rating), in the order of `values`' variables.
    pub notes: Vec<String>,
}

impl Setting {
    fn id(&self) -> String {
        self.values
            .iter()
            .map(|(k, v)| format!("{k}={v}"))
            .collect::<Vec<_>>()
            .join(";")
    }

    fn join(&self, other: &Setting) -> Setting {
        let mut values = self.values.clone();
        values.extend(other.values.iter().cloned());
        let mut notes = self.notes.clone();
        notes.extend(other.notes.iter().cloned());
        Setting { values, notes }
    }
}

/// The margin of the limiting quantity of a run that survives the target: how far it stayed
/// from its criterion, as a fraction of the criterion (0.25: 25 % to spare).
#[derive(Debug, Clone, PartialEq)]
pub struct Margin {
    /// The failure mode the quantity belongs to (`retained_force`).
    pub quantity: &'static str,
    /// The quantity's worst value over the run (SI, or a fraction).
    pub value: f64,
    /// Its criterion.
    pub limit: f64,
    /// `value/limit − 1` for a lower limit, `1 − value/limit` for an upper one.
    pub margin: f64,
}

/// What one run says about the target.
#[derive(Debug, Clone, PartialEq)]
pub struct Measure {
    /// Survives the target, held by its squeeze (not open), and — for a verified run — the
    /// neighbouring level agrees.
    pub passes: bool,
    /// When it failed, or was first open \[s\]; `None`: neither within the target.
    pub life: Option<f64>,
    /// The failure mode, or `"open"`.
    pub mode: Option<&'static str>,
    /// The limiting quantity's margin of a run that passes (`None`: no criterion measures one).
    pub margin: Option<Margin>,
    /// The neighbouring level gives another outcome (verified runs only).
    pub undecided: bool,
    /// One number for the ranking: `life/target − 1` (< 0) for a run that does not pass, the
    /// margin (≥ 0; 0 when none is measured) for one that does.
    pub score: f64,
}

/// A proposal: a change (one variable, or two) verified by a full run.
#[derive(Debug, Clone)]
pub struct Proposal {
    pub setting: Setting,
    /// The labels of the variables it moves.
    pub variables: Vec<String>,
    /// The verified run's measure.
    pub measure: Measure,
    /// The runs its search and verification took.
    pub runs: usize,
    /// The scenario text with the change (and the target's duration), as `--write` writes it.
    pub text: String,
}

/// One row of the sensitivity table: the variable stepped down and up by
/// [`SENSITIVITY_STEP`] (within its admissible range).
#[derive(Debug, Clone)]
pub struct Sensitivity {
    pub key: String,
    pub label: String,
    pub domain: Domain,
    /// The base value as written (`"2.91 mm"`).
    pub base: String,
    /// The value stepped down and its measure (`None`: not admissible, or not run).
    pub down: Option<(String, Measure)>,
    pub up: Option<(String, Measure)>,
    /// The larger change of the score over the two steps.
    pub effect: f64,
}

/// A variable the search could not use, and why.
#[derive(Debug, Clone)]
pub struct Skipped {
    pub what: String,
    pub why: String,
}

/// What `advise` found.
#[derive(Debug, Clone)]
pub struct Advice {
    /// The base scenario (run over the target) and its verified run.
    pub base: Scenario,
    pub base_result: LifeResult,
    pub base_measure: Measure,
    pub target: f64,
    /// Passing proposals first (fewest variables, then most margin), then the best that do not
    /// pass when none does.
    pub proposals: Vec<Proposal>,
    /// Ranked by effect, the design variables first.
    pub sensitivity: Vec<Sensitivity>,
    pub skipped: Vec<Skipped>,
    /// Life runs made, and the bound.
    pub runs: usize,
    pub max_runs: usize,
    /// The bound stopped the search before it finished.
    pub exhausted: bool,
}

/// What a contact path depends on (the numerical level is not shared: its height map and
/// settings would join the key).
type PathKey = (Spectrum, ContactSettings, Fidelity);

/// The contact paths built so far, each with its findings.
type Paths = Mutex<Vec<(PathKey, Arc<(ContactPath, Findings)>)>>;

/// The search's shared state: the base text, the contact paths built so far, the run count.
struct Search<'a> {
    text: &'a str,
    path: &'a Path,
    base: &'a Scenario,
    options: &'a Options,
    /// `simulation.duration` set to the target when the base's differs.
    duration: Option<(String, toml::Value)>,
    paths: Paths,
    runs: AtomicUsize,
    progress: SharedProgress<'a>,
    /// Runs kept for the verification of the proposals.
    search_budget: usize,
    exhausted: std::sync::atomic::AtomicBool,
}

/// The advice for the scenario `text` read from `path` (validated as `base`) and `options`.
/// Errors: the pool of threads cannot start (bad input never reaches here: the base has been
/// validated).
pub fn advise(
    text: &str,
    path: &Path,
    base: &Scenario,
    options: &Options,
    progress: SharedProgress<'_>,
) -> Result<Advice, ScenarioError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.threads.unwrap_or(0))
        .build()
        .map_err(|e| ScenarioError::Invalid {
            path: path.to_path_buf(),
            line: None,
            key: None,
            message: format!("cannot start {:?} threads: {e}", options.threads),
        })?;
    let duration = (base.life.time.duration != options.target).then(|| {
        (
            "simulation.duration".to_owned(),
            toml::Value::String(options.target_text.clone()),
        )
    });
    let search = Search {
        text,
        path,
        base,
        options,
        duration,
        paths: Mutex::new(Vec::new()),
        runs: AtomicUsize::new(0),
        progress,
        // a quarter of the runs (at least 4) kept for the verification
        search_budget: options
            .max_runs
            .saturating_sub((options.max_runs / 4).max(4)),
        exhausted: std::sync::atomic::AtomicBool::new(false),
    };
    pool.install(|| search.run())
}

impl Search<'_> {
    fn run(&self) -> Result<Advice, ScenarioError> {
        // the base over the target, verified
        let empty = Setting {
            values: Vec::new(),
            notes: Vec::new(),
        };
        let (base, _) = self.scenario(&empty)?;
        let base_result = self.full_run(&base);
        let base_measure = measure(&base, &base_result, self.options.target, true);

        let (variables, skipped) = self.variables();
        let design: Vec<&Variable> = variables
            .iter()
            .filter(|v| v.domain == Domain::Design)
            .collect();

        // stage 1: the sensitivity steps, each design variable at the ends of its range, every
        // choice
        let mut batch: Vec<Setting> = Vec::new();
        for v in &variables {
            if let Levels::Continuous(g) = &v.levels {
                let (down, up) = sensitivity_steps(g);
                for n in [down, up].into_iter().flatten() {
                    batch.push(continuous(v, g, n));
                }
                if v.domain == Domain::Design {
                    for n in [g.lo, g.hi] {
                        if n != 0 {
                            batch.push(continuous(v, g, n));
                        }
                    }
                }
            }
        }
        for v in &design {
            if let Levels::Choices(choices) = &v.levels {
                batch.extend(choices.iter().map(choice));
            }
        }
        let mut results: BTreeMap<String, Measure> = BTreeMap::new();
        self.evaluate(&batch, &mut results);

        let mut sensitivity = sensitivity_table(&variables, &results);
        rank_sensitivity(&mut sensitivity, &base_measure);

        // stage 2: each design variable's smallest passing change
        let mut singles: Vec<(Setting, Vec<String>, usize)> = Vec::new();
        if !base_measure.passes {
            singles = self.singles(&design, &mut results);
        }

        // stage 3: pairs of the most effective variables: when no single change passes, and
        // the best pair otherwise
        let pairs = if base_measure.passes {
            Vec::new()
        } else {
            self.pairs(&design, &singles, &mut results)
        };

        // stage 4: every proposal verified by a full run
        let mut candidates = singles;
        candidates.extend(pairs);
        let mut proposals = self.verify(candidates);
        if !base_measure.passes && !proposals.iter().any(|p| p.measure.passes) {
            // nothing passes: the best found, verified
            let best = self.best_unverified(&design, &results);
            proposals.extend(self.verify(best));
        }
        proposals.sort_by(|a, b| {
            b.measure
                .passes
                .cmp(&a.measure.passes)
                .then(a.variables.len().cmp(&b.variables.len()))
                .then(b.measure.score.total_cmp(&a.measure.score))
        });
        if !base_measure.passes && !proposals.iter().any(|p| p.measure.passes) {
            proposals.truncate(3);
        }
        Ok(Advice {
            base,
            base_result,
            base_measure,
            target: self.options.target,
            proposals,
            sensitivity,
            skipped,
            runs: self.runs.load(Ordering::Acquire),
            max_runs: self.options.max_runs,
            exhausted: self.exhausted.load(Ordering::Acquire),
        })
    }

    /// The base with `setting` (and the target's duration): its text and validated scenario.
    fn scenario(&self, setting: &Setting) -> Result<(Scenario, String), ScenarioError> {
        let mut values = setting.values.clone();
        values.extend(self.duration.clone());
        if values.is_empty() {
            return Ok((self.base.clone(), self.text.to_owned()));
        }
        let (text, scenario) = super::replace(self.text, self.path, &values)?;
        Ok((scenario, text))
    }

    /// The setting's scenario when it is admissible.
    fn admissible(&self, setting: &Setting) -> Option<(Scenario, String)> {
        let (s, text) = self.scenario(setting).ok()?;
        admissible(self.base, &s).then_some((s, text))
    }

    /// Runs every setting of `batch` not yet in `results` (in parallel, within the search
    /// budget), recording its measure; an inadmissible setting records nothing.
    fn evaluate(&self, batch: &[Setting], results: &mut BTreeMap<String, Measure>) {
        let mut todo: Vec<&Setting> = Vec::new();
        for s in batch {
            if !results.contains_key(&s.id()) && !todo.iter().any(|t| t.id() == s.id()) {
                todo.push(s);
            }
        }
        let scenarios: Vec<(String, Scenario)> = todo
            .par_iter()
            .filter_map(|s| self.admissible(s).map(|(sc, _)| (s.id(), sc)))
            .collect();
        let room = self
            .search_budget
            .saturating_sub(self.runs.load(Ordering::Acquire));
        if scenarios.len() > room {
            self.exhausted.store(true, Ordering::Release);
        }
        let measures: Vec<(String, Measure)> = scenarios
            .into_par_iter()
            .take(room)
            .map(|(id, s)| {
                let r = self.quick_run(&s);
                (id, measure(&s, &r, self.options.target, false))
            })
            .collect();
        results.extend(measures);
    }

    /// A search run: the life at the scenario's level, without the band, on a shared path.
    fn quick_run(&self, s: &Scenario) -> LifeResult {
        let life = &s.life;
        let shared = if life.fidelity == Fidelity::Numerical {
            Arc::new(scenario_path(s, life.fidelity, None, &mut |_, _| {}))
        } else {
            let key = (life.spectrum.clone(), life.contact, life.fidelity);
            let mut paths = self.paths.lock().unwrap_or_else(|p| p.into_inner());
            match paths.iter().find(|(k, _)| *k == key) {
                Some((_, p)) => Arc::clone(p),
                None => {
                    let built = Arc::new(scenario_path(s, life.fidelity, None, &mut |_, _| {}));
                    paths.push((key, Arc::clone(&built)));
                    built
                }
            }
        };
        let result = life_on(life, shared.0.clone(), shared.1.clone());
        self.count();
        result
    }

    /// A verification run: `sealsim run`'s, with the band.
    fn full_run(&self, s: &Scenario) -> LifeResult {
        let result = super::life::run(s, &mut |_, _| {});
        self.count();
        result
    }

    fn count(&self) {
        let done = self.runs.fetch_add(1, Ordering::AcqRel) + 1;
        (self.progress)(done.min(self.options.max_runs), self.options.max_runs);
    }

    /// The design and service variables of the base scenario, and those it cannot vary.
    fn variables(&self) -> (Vec<Variable>, Vec<Skipped>) {
        let mut skipped = Vec::new();
        let table: toml::Table = self.text.parse().unwrap_or_default();
        let mut out = Vec::new();
        out.extend(self.compounds(&mut skipped));
        let seal = table.get("seal").and_then(toml::Value::as_table);
        let get = |t: Option<&toml::Table>, k: &str| -> Option<String> {
            t.and_then(|t| t.get(k))
                .and_then(|v| v.as_str())
                .map(str::to_owned)
        };
        let gland = self.base.gland.as_ref();
        if let Some(g) = gland {
            if let Some(text) = get(seal, "groove_depth") {
                out.extend(self.grid(
                    "seal.groove_depth",
                    "squeeze (the gland depth; shallower: more squeeze)",
                    &text,
                    Dimension::LENGTH,
                    1e-3,
                    "mm",
                    0.01,
                    (0.5, 1.0),
                    false,
                    "the squeeze range over the tolerances (10–30 % static, 10–16 % dynamic), \
                     the fill and the stretch (docs/model.md §6.2)",
                ));
            } else if let Some(text) = get(seal, "squeeze") {
                out.extend(self.squeeze(&text));
            }
            if let Some(text) = get(seal, "groove_width") {
                out.extend(self.grid(
                    "seal.groove_width",
                    "groove width (the fill)",
                    &text,
                    Dimension::LENGTH,
                    1e-3,
                    "mm",
                    0.01,
                    (0.7, 1.5),
                    false,
                    "the fill 50–85 % (docs/model.md §6.2) and at most 100 % at maximum material",
                ));
            }
            if g.kind != GlandKind::Face {
                out.extend(self.backup_rings(g));
            }
        } else if let Some(text) = get(seal, "squeeze") {
            out.extend(self.squeeze(&text));
        } else {
            let flat =
                ("sealsim's bound: × 1/2 … × 2 of the given value (assumed; the gasket maker's \
                 maximum seating stress is the real limit)")
                    .to_owned();
            if let Some(text) = get(seal, "nominal_pressure") {
                out.extend(self.grid(
                    "seal.nominal_pressure",
                    "seating stress",
                    &text,
                    Dimension::PRESSURE,
                    1e6,
                    "MPa",
                    0.01,
                    (1.0 / FLAT_FACTOR, FLAT_FACTOR),
                    false,
                    &flat,
                ));
            }
            if let Some(text) = get(seal, "compression") {
                out.extend(self.grid(
                    "seal.compression",
                    "compression",
                    &text,
                    Dimension::DIMENSIONLESS,
                    0.01,
                    "%",
                    0.1,
                    (1.0 / FLAT_FACTOR, FLAT_FACTOR),
                    false,
                    &flat,
                ));
            }
        }
        for (section, what) in [
            ("surface", "counterface finish"),
            ("groove_surface", "groove-bottom finish"),
        ] {
            out.extend(self.finish(&table, section, what, &mut skipped));
        }
        // the service: information only
        let fluid = table.get("fluid").and_then(toml::Value::as_table);
        if let Some(text) = get(fluid, "pressure_difference") {
            out.extend(self.grid(
                "fluid.pressure_difference",
                "pressure difference (the service)",
                &text,
                Dimension::PRESSURE,
                1e5,
                "bar",
                0.1,
                (0.9, 1.1),
                true,
                "the service",
            ));
        }
        (out, skipped)
    }

    /// A seal's `squeeze` key (a ring between plates, or a gland given by its squeeze).
    fn squeeze(&self, text: &str) -> Option<Variable> {
        self.grid(
            "seal.squeeze",
            "squeeze",
            text,
            Dimension::DIMENSIONLESS,
            0.01,
            "%",
            0.1,
            // hard bounds only: `admissible` keeps the squeeze range
            (0.25, 4.0),
            false,
            "the static squeeze range 10–30 % (docs/model.md §6.2)",
        )
    }

    /// A continuous variable given as `text` in the scenario, on a grid of `step` (in `unit`,
    /// `scale` SI per unit), admissible within `factor` (lo, hi) × its value and as far as the
    /// validator and the handbook limits allow.
    #[allow(clippy::too_many_arguments)]
    fn grid(
        &self,
        key: &str,
        label: &str,
        text: &str,
        dimension: Dimension,
        scale: f64,
        unit: &'static str,
        step: f64,
        factor: (f64, f64),
        service: bool,
        bound: &str,
    ) -> Option<Variable> {
        let si = parse_quantity(text, dimension).ok()?;
        if !(si.is_finite() && si > 0.0) {
            return None;
        }
        let base = si / scale;
        let decimals = (-step.log10()).ceil().max(0.0) as usize;
        let grid0 = (base / step).round() * step;
        let mut g = Grid {
            base,
            grid0,
            step,
            unit,
            decimals,
            lo: 0,
            hi: 0,
            bound: bound.to_owned(),
        };
        let lo_hard = -(((base - factor.0 * base) / step).floor() as i64);
        let hi_hard = ((factor.1 * base - base) / step).floor() as i64;
        if service {
            // the service is stepped for its sensitivity only, never bounded by the design
            g.lo = lo_hard;
            g.hi = hi_hard;
        } else {
            g.lo = self.reach(key, &g, lo_hard);
            g.hi = self.reach(key, &g, hi_hard);
        }
        Some(Variable {
            key: key.to_owned(),
            label: label.to_owned(),
            domain: if service {
                Domain::Service
            } else {
                Domain::Design
            },
            levels: Levels::Continuous(g),
        })
    }

    /// The farthest admissible step from 0 towards `hard` (bisection on the validator and the
    /// handbook limits, no life run; the admissible set is taken as an interval about 0).
    fn reach(&self, key: &str, g: &Grid, hard: i64) -> i64 {
        let ok = |n: i64| {
            n == 0
                || self
                    .admissible(&Setting {
                        values: vec![(key.to_owned(), toml::Value::String(g.text(n)))],
                        notes: vec![String::new()],
                    })
                    .is_some()
        };
        if hard == 0 || ok(hard) {
            return hard;
        }
        let (mut good, mut bad) = (0i64, hard);
        for _ in 0..ADMISSIBLE_STEPS {
            if (bad - good).abs() <= 1 {
                break;
            }
            let mid = good + (bad - good) / 2;
            if ok(mid) {
                good = mid;
            } else {
                bad = mid;
            }
        }
        good
    }

    /// The library compounds rated A or B for the base's fluid class, other than its own.
    fn compounds(&self, skipped: &mut Vec<Skipped>) -> Option<Variable> {
        let Some(class) = self.base.fluid_class else {
            skipped.push(Skipped {
                what: "compound".into(),
                why: "the ratings cover mineral oil, water, hot water and water–glycol only: no \
                      compound is proposed for this fluid (docs/model.md §6.8)"
                    .into(),
            });
            return None;
        };
        let own: Option<String> = self.text.parse::<toml::Table>().ok().and_then(|t| {
            t.get("material")?
                .get("library")?
                .as_str()
                .map(str::to_owned)
        });
        let choices: Vec<Choice> = crate::scenario::library::ids()
            .filter_map(|id| {
                let setting = Setting {
                    values: vec![(
                        "material.library".to_owned(),
                        toml::Value::String(id.to_owned()),
                    )],
                    notes: vec![String::new()],
                };
                if own.as_deref() == Some(id) {
                    return None;
                }
                let (s, _) = self.scenario(&setting).ok()?;
                let c: &Compatibility = s.compatibility.as_ref()?;
                (c.rating != Rating::NotRecommended).then(|| Choice {
                    values: setting.values,
                    note: format!(
                        "rated {} ({}) in {}",
                        c.rating.letter(),
                        c.rating.words(),
                        class.as_str()
                    ),
                })
            })
            .collect();
        (!choices.is_empty()).then(|| Variable {
            key: "material.library".into(),
            label: "compound".into(),
            domain: Domain::Design,
            levels: Levels::Choices(choices),
        })
    }

    /// Back-up rings from the base's count up to 2, each with the handbook's groove width for
    /// that count when the groove is narrower.
    fn backup_rings(&self, g: &crate::gland::GlandDesign) -> Option<Variable> {
        let have = self.base.life.gland.map_or(0, |g| g.backup_rings);
        let dynamic = self.base.life.motion.is_some();
        let table = if dynamic {
            &crate::gland_design::DYNAMIC
        } else {
            &crate::gland_design::STATIC_RADIAL
        };
        let cs_in = g.ring.cross_section / crate::gland_design::INCH;
        let row = table
            .iter()
            .find(|r| (r.cross_section - cs_in).abs() < 0.01);
        let choices: Vec<Choice> = (have + 1..=2)
            .map(|n| {
                let mut values = vec![(
                    "seal.backup_rings".to_owned(),
                    toml::Value::Integer(i64::from(n)),
                )];
                let mut note = format!("{n} back-up ring{}", if n == 1 { "" } else { "s" });
                if let Some(w) = row.and_then(|r| r.width[usize::from(n)]) {
                    let min = w.0 * crate::gland_design::INCH;
                    if g.groove_width < min {
                        let mm = (min * 1e5).ceil() / 100.0;
                        values.push((
                            "seal.groove_width".to_owned(),
                            toml::Value::String(format!("{mm:.2} mm")),
                        ));
                        note += &format!(
                            " in the handbook's groove width for {n} ({}–{} in; docs/model.md \
                             §6.2.1)",
                            w.0, w.1
                        );
                    }
                }
                Choice { values, note }
            })
            .collect();
        (!choices.is_empty()).then(|| Variable {
            key: "seal.backup_rings".into(),
            label: "back-up rings".into(),
            domain: Domain::Design,
            levels: Levels::Choices(choices),
        })
    }

    /// A callout's roughness (`ra`, `rq`, `rz`) or a self-affine `rms_roughness`, finer only,
    /// down to [`FINEST_RA`].
    fn finish(
        &self,
        table: &toml::Table,
        section: &str,
        what: &str,
        skipped: &mut Vec<Skipped>,
    ) -> Option<Variable> {
        let t = table.get(section).and_then(toml::Value::as_table)?;
        let rq_per_ra = (std::f64::consts::PI / 2.0).sqrt();
        // the key and the finest value in its own measure (Rq = √(π/2) Ra; Rz ≈ 7.2 Ra)
        let (key, finest, step, unit) = if t.contains_key("ra") {
            ("ra", FINEST_RA, 0.01, "um")
        } else if t.contains_key("rq") {
            ("rq", FINEST_RA * rq_per_ra, 0.01, "um")
        } else if t.contains_key("rz") {
            ("rz", FINEST_RA * 7.2, 0.1, "um")
        } else if t.contains_key("rms_roughness") {
            ("rms_roughness", FINEST_RA * rq_per_ra, 0.01, "um")
        } else {
            skipped.push(Skipped {
                what: what.to_owned(),
                why: format!(
                    "[{section}] is a measurement (a PSD file, a height map or traces): its \
                     finish is not scaled"
                ),
            });
            return None;
        };
        let text = t.get(key).and_then(toml::Value::as_str)?;
        let si = parse_quantity(text, Dimension::LENGTH).ok()?;
        if si <= finest {
            skipped.push(Skipped {
                what: what.to_owned(),
                why: format!(
                    "{section}.{key} = {text:?} is already at or below the finest practical \
                     finish (Ra 0.05 µm: super-finishing, lapping)"
                ),
            });
            return None;
        }
        self.grid(
            &format!("{section}.{key}"),
            &format!("{what} ({key}; finer only)"),
            text,
            Dimension::LENGTH,
            1e-6,
            unit,
            step,
            (finest / si, 1.0),
            false,
            "finer only, to the finest practical finish Ra 0.05 µm (super-finishing, lapping)",
        )
    }

    /// Each design variable's smallest passing change: a choice that passes (the first
    /// compound in library order, each that passes; the fewest back-up rings), or a continuous
    /// variable bisected between the base and the end of its range that passes.
    fn singles(
        &self,
        design: &[&Variable],
        results: &mut BTreeMap<String, Measure>,
    ) -> Vec<(Setting, Vec<String>, usize)> {
        let mut out = Vec::new();
        // continuous: (variable, grid, direction end) whose end passes
        let mut brackets: Vec<(&Variable, &Grid, i64, i64, usize)> = Vec::new();
        for v in design {
            match &v.levels {
                Levels::Choices(choices) => {
                    for c in choices {
                        let s = choice(c);
                        if results.get(&s.id()).is_some_and(|m| m.passes) {
                            out.push((s, vec![v.label.clone()], 1));
                            if v.key == "seal.backup_rings" {
                                break;
                            }
                        }
                    }
                }
                Levels::Continuous(g) => {
                    for end in [g.lo, g.hi] {
                        let s = continuous(v, g, end);
                        if end != 0 && results.get(&s.id()).is_some_and(|m| m.passes) {
                            brackets.push((v, g, 0, end, 1));
                        }
                    }
                }
            }
        }
        // bisection in lock-step: every bracket's midpoint in one batch
        loop {
            let mids: Vec<Setting> = brackets
                .iter()
                .filter(|(_, _, bad, good, _)| (good - bad).abs() > 1)
                .map(|(v, g, bad, good, _)| continuous(v, g, bad + (good - bad) / 2))
                .collect();
            if mids.is_empty() || self.exhausted.load(Ordering::Acquire) {
                break;
            }
            self.evaluate(&mids, results);
            for (v, g, bad, good, runs) in &mut brackets {
                if (*good - *bad).abs() <= 1 {
                    continue;
                }
                let mid = *bad + (*good - *bad) / 2;
                match results.get(&continuous(v, g, mid).id()) {
                    Some(m) if m.passes => *good = mid,
                    Some(_) => *bad = mid,
                    None => *bad = *good, // not run: stop here
                }
                *runs += 1;
            }
        }
        for (v, g, _, good, runs) in brackets {
            out.push((continuous(v, g, good), vec![v.label.clone()], runs));
        }
        out
    }

    /// Pairs of the most effective design variables, each at its best setting; a passing
    /// pair with a continuous member is reduced by bisection on a common fraction of the way.
    fn pairs(
        &self,
        design: &[&Variable],
        singles: &[(Setting, Vec<String>, usize)],
        results: &mut BTreeMap<String, Measure>,
    ) -> Vec<(Setting, Vec<String>, usize)> {
        // each variable's best setting among the runs made
        let mut best: Vec<(&Variable, Setting, f64)> = design
            .iter()
            .filter_map(|v| {
                extremes(v)
                    .into_iter()
                    .filter_map(|s| results.get(&s.id()).map(|m| (m.score, s)))
                    .max_by(|a, b| a.0.total_cmp(&b.0))
                    .map(|(score, s)| (*v, s, score))
            })
            .collect();
        // stable: equal scores keep the variables' order
        best.sort_by(|a, b| b.2.total_cmp(&a.2));
        best.truncate(PAIRED);
        let mut pairs: Vec<(usize, usize, Setting)> = Vec::new();
        for i in 0..best.len() {
            for j in i + 1..best.len() {
                pairs.push((i, j, best[i].1.join(&best[j].1)));
            }
        }
        let batch: Vec<Setting> = pairs.iter().map(|p| p.2.clone()).collect();
        self.evaluate(&batch, results);
        let passing_alone = |label: &str| {
            singles
                .iter()
                .any(|(_, l, _)| l.len() == 1 && l[0] == label)
        };
        let mut out = Vec::new();
        let mut best_pair: Option<(f64, usize)> = None;
        for (k, (i, j, s)) in pairs.iter().enumerate() {
            let Some(m) = results.get(&s.id()) else {
                continue;
            };
            if !m.passes {
                continue;
            }
            let (a, b) = (best[*i].0, best[*j].0);
            if !passing_alone(&a.label) && !passing_alone(&b.label) {
                let reduced = self.reduce(a, &best[*i].1, b, &best[*j].1, results);
                out.push((reduced.0, vec![a.label.clone(), b.label.clone()], reduced.1));
            } else if best_pair.is_none_or(|(score, _)| m.score > score) {
                best_pair = Some((m.score, k));
            }
        }
        // the best pair is listed only where it buys more margin than the best single change
        let best_single = singles
            .iter()
            .filter_map(|(s, _, _)| results.get(&s.id()).map(|m| m.score))
            .fold(f64::NEG_INFINITY, f64::max);
        if out.is_empty()
            && let Some((score, k)) = best_pair
            && score > best_single
        {
            let (i, j, s) = &pairs[k];
            out.push((
                s.clone(),
                vec![best[*i].0.label.clone(), best[*j].0.label.clone()],
                1,
            ));
        }
        out
    }

    /// A passing pair's smallest version: its continuous members moved a common fraction
    /// `L/M` of the way to their settings (the choices kept), bisected on `L`.
    fn reduce(
        &self,
        a: &Variable,
        sa: &Setting,
        b: &Variable,
        sb: &Setting,
        results: &mut BTreeMap<String, Measure>,
    ) -> (Setting, usize) {
        let end = |v: &Variable, s: &Setting| -> Option<(Grid, i64)> {
            let Levels::Continuous(g) = &v.levels else {
                return None;
            };
            [g.lo, g.hi]
                .into_iter()
                .find(|&n| continuous(v, g, n) == *s)
                .map(|n| (g.clone(), n))
        };
        let (ea, eb) = (end(a, sa), end(b, sb));
        let m = ea
            .iter()
            .chain(eb.iter())
            .map(|(_, n)| n.abs())
            .max()
            .unwrap_or(0);
        if m <= 1 {
            return (sa.join(sb), 1);
        }
        let at = |level: i64| -> Setting {
            let part = |v: &Variable, s: &Setting, e: &Option<(Grid, i64)>| match e {
                // the step rounded away from the base: the fraction is at least reached
                Some((g, n)) => continuous(v, g, (n * level + n.signum() * (m - 1)) / m),
                None => s.clone(),
            };
            part(a, sa, &ea).join(&part(b, sb, &eb))
        };
        let (mut bad, mut good, mut runs) = (0i64, m, 1usize);
        while good - bad > 1 && !self.exhausted.load(Ordering::Acquire) {
            let mid = bad + (good - bad) / 2;
            let s = at(mid);
            self.evaluate(std::slice::from_ref(&s), results);
            runs += 1;
            match results.get(&s.id()) {
                Some(r) if r.passes => good = mid,
                Some(_) => bad = mid,
                None => break,
            }
        }
        (at(good), runs)
    }

    /// When nothing passes: each design variable's best setting found, to verify and list.
    fn best_unverified(
        &self,
        design: &[&Variable],
        results: &BTreeMap<String, Measure>,
    ) -> Vec<(Setting, Vec<String>, usize)> {
        let mut all: Vec<(f64, Setting, Vec<String>)> = Vec::new();
        for v in design {
            for s in extremes(v) {
                if let Some(m) = results.get(&s.id()) {
                    all.push((m.score, s, vec![v.label.clone()]));
                }
            }
        }
        // the best pair too, when one was run
        all.sort_by(|a, b| b.0.total_cmp(&a.0));
        all.truncate(3);
        all.into_iter().map(|(_, s, l)| (s, l, 1)).collect()
    }

    /// Every candidate verified by a full run (in parallel, in order; at most as many as the
    /// runs left).
    fn verify(&self, candidates: Vec<(Setting, Vec<String>, usize)>) -> Vec<Proposal> {
        let room = self
            .options
            .max_runs
            .saturating_sub(self.runs.load(Ordering::Acquire));
        if candidates.len() > room {
            self.exhausted.store(true, Ordering::Release);
        }
        candidates
            .into_par_iter()
            .take(room)
            .filter_map(|(setting, variables, runs)| {
                let (s, text) = self.admissible(&setting)?;
                let result = self.full_run(&s);
                Some(Proposal {
                    measure: measure(&s, &result, self.options.target, true),
                    setting,
                    variables,
                    runs: runs + 1,
                    text,
                })
            })
            .collect()
    }
}

/// The setting of a continuous variable at step `n`.
/// A variable's settings at the ends of its range (a continuous one's ends other than the
/// base, each choice of a discrete one): where its best is looked for.
fn extremes(v: &Variable) -> Vec<Setting> {
    match &v.levels {
        Levels::Choices(cs) => cs.iter().map(choice).collect(),
        Levels::Continuous(g) => [g.lo, g.hi]
            .into_iter()
            .filter(|&n| n != 0)
            .map(|n| continuous(v, g, n))
            .collect(),
    }
}

fn continuous(v: &Variable, g: &Grid, n: i64) -> Setting {
    Setting {
        values: vec![(v.key.clone(), toml::Value::String(g.text(n)))],
        notes: vec![String::new()],
    }
}

/// The setting of a choice.
fn choice(c: &Choice) -> Setting {
    Setting {
        values: c.values.clone(),
        notes: vec![c.note.clone()],
    }
}

/// The sensitivity's steps down and up: ±[`SENSITIVITY_STEP`] of the value (at least one
/// grid step), within the admissible range (`None`: no room that way).
pub fn sensitivity_steps(g: &Grid) -> (Option<i64>, Option<i64>) {
    let k = ((SENSITIVITY_STEP * g.base / g.step).round() as i64).max(1);
    let down = (-k).max(g.lo);
    let up = k.min(g.hi);
    ((down != 0).then_some(down), (up != 0).then_some(up))
}

fn sensitivity_table(
    variables: &[Variable],
    results: &BTreeMap<String, Measure>,
) -> Vec<Sensitivity> {
    let mut rows: Vec<Sensitivity> = variables
        .iter()
        .filter_map(|v| {
            let Levels::Continuous(g) = &v.levels else {
                return None;
            };
            let (down, up) = sensitivity_steps(g);
            let at = |n: Option<i64>| {
                n.and_then(|n| {
                    results
                        .get(&continuous(v, g, n).id())
                        .map(|m| (g.text(n), m.clone()))
                })
            };
            let (down, up) = (at(down), at(up));
            Some(Sensitivity {
                key: v.key.clone(),
                label: v.label.clone(),
                domain: v.domain,
                base: g.text(0),
                down,
                up,
                effect: 0.0,
            })
        })
        .collect();
    rows.sort_by_key(|r| r.domain == Domain::Service);
    rows
}

/// The sensitivity table's effects against the base's score, ranked (design variables first,
/// then by effect, largest first).
pub fn rank_sensitivity(rows: &mut [Sensitivity], base: &Measure) {
    for r in rows.iter_mut() {
        r.effect = [&r.down, &r.up]
            .into_iter()
            .flatten()
            .map(|(_, m)| (m.score - base.score).abs())
            .fold(0.0, f64::max);
    }
    rows.sort_by(|a, b| {
        (a.domain == Domain::Service)
            .cmp(&(b.domain == Domain::Service))
            .then(b.effect.total_cmp(&a.effect))
    });
}

/// Whether `s` keeps the base's handbook limits: no gland limit the base does not break
/// (squeeze range, circumferential compression), the fill within 50–85 % (or the base's) and
/// the stretch within 5 % (or the base's).
pub fn admissible(base: &Scenario, s: &Scenario) -> bool {
    let dynamic = s.life.motion.is_some();
    match (&base.gland, &s.gland) {
        (Some(b), Some(g)) => {
            let kinds = |limits: &[Limit]| -> (bool, bool) {
                (
                    limits
                        .iter()
                        .any(|l| matches!(l, Limit::Compression { .. })),
                    limits.iter().any(|l| matches!(l, Limit::Squeeze { .. })),
                )
            };
            let (Ok(lb), Ok(lg)) = (b.feasibility(dynamic), g.feasibility(dynamic)) else {
                return false;
            };
            let (kb, kg) = (kinds(&lb), kinds(&lg));
            if (kg.0 && !kb.0) || (kg.1 && !kb.1) {
                return false;
            }
            let (Ok(ib), Ok(ig)) = (b.installed(), g.installed()) else {
                return false;
            };
            ig.fill <= NOMINAL_FILL_GUIDANCE.max(ib.fill)
                && ig.fill >= MIN_FILL_GUIDANCE.min(ib.fill)
                && ig.stretch <= MAX_STRETCH_GUIDANCE.max(ib.stretch)
        }
        (None, None) => match (
            base.life.geometry.ring_squeeze(),
            s.life.geometry.ring_squeeze(),
        ) {
            (Some(b), Some(q)) => {
                let lo = STATIC_SQUEEZE.0.min(b);
                let hi = STATIC_SQUEEZE.1.max(b);
                (lo..=hi).contains(&q)
            }
            _ => true,
        },
        _ => false,
    }
}

/// What a run of `s` says about the `target` life \[s\]; `verified`: the band counts.
pub fn measure(s: &Scenario, r: &LifeResult, target: f64, verified: bool) -> Measure {
    let undecided = verified && r.undecided();
    let (life, mode) = match (r.failure, r.open_since()) {
        (Some(f), _) if f.time < target => (Some(f.time), Some(f.mode.as_str())),
        (_, Some(t)) if t < target => (Some(t), Some("open")),
        _ => (None, None),
    };
    // a failure or an opening past the target is outside the life asked for
    let passes = life.is_none() && !undecided;
    let margin = if passes { margin(s, r) } else { None };
    let score = match life {
        Some(t) => t / target - 1.0,
        None => margin.as_ref().map_or(0.0, |m| m.margin.max(0.0)),
    };
    Measure {
        passes,
        life,
        mode,
        margin,
        undecided,
        score,
    }
}

/// The margin of the limiting quantity of a run that survives: the smallest over the
/// scenario's quantitative criteria (docs/model.md §8), each from the run's samples.
pub fn margin(s: &Scenario, r: &LifeResult) -> Option<Margin> {
    let c = &s.life.failure;
    let rows = &r.rows;
    let mut all: Vec<Margin> = Vec::new();
    let lower = |quantity, value: f64, limit: f64| Margin {
        quantity,
        value,
        limit,
        margin: value / limit - 1.0,
    };
    let upper = |quantity, value: f64, limit: f64| Margin {
        quantity,
        value,
        limit,
        margin: 1.0 - value / limit,
    };
    if let Some(lim) = c.min_retained_force
        && r.reference_force > 0.0
    {
        let f = rows
            .iter()
            .filter(|h| h.time >= c.retained_force_reference)
            .map(|h| h.sealing_force)
            .fold(f64::INFINITY, f64::min);
        if f.is_finite() {
            all.push(lower("retained_force", f / r.reference_force, lim));
        }
    }
    if let Some(lim) = c.max_leaked_volume {
        all.push(upper("leaked_volume", r.leaked_volume(), lim));
    }
    if let Some(lim) = c.max_leak_rate {
        let q = rows.iter().map(|h| h.leak_rate).fold(0.0, f64::max);
        all.push(upper("leak_rate", q, lim));
    }
    if let Some(lim) = c.max_compression_set {
        let set = rows
            .iter()
            .filter_map(|h| h.compression_set)
            .fold(0.0, f64::max);
        all.push(upper("compression_set", set, lim));
    }
    if let Some(lim) = c.min_sealing_force {
        let f = rows
            .iter()
            .map(|h| h.sealing_force)
            .fold(f64::INFINITY, f64::min);
        if f.is_finite() {
            all.push(lower("sealing_force", f, lim));
        }
    }
    all.into_iter()
        .filter(|m| m.margin.is_finite())
        .min_by(|a, b| a.margin.total_cmp(&b.margin))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(base: f64, step: f64, lo: i64, hi: i64) -> Grid {
        Grid {
            base,
            grid0: (base / step).round() * step,
            step,
            unit: "mm",
            decimals: 2,
            lo,
            hi,
            bound: String::new(),
        }
    }

    #[test]
    fn the_grid_writes_the_base_as_given_and_steps_on_the_practical_grid() {
        let g = grid(2.913, 0.01, -50, 9);
        assert_eq!(g.text(0), "2.913 mm");
        assert_eq!(g.text(-3), "2.88 mm");
        assert_eq!(g.text(2), "2.93 mm");
    }

    #[test]
    fn the_sensitivity_steps_five_per_cent_within_the_range() {
        // 5 % of 2 mm is 0.1 mm: 10 steps of 0.01 mm, cut at the range upwards
        let g = grid(2.0, 0.01, -50, 9);
        assert_eq!(sensitivity_steps(&g), (Some(-10), Some(9)));
        // no room upwards: no step that way; at least one step when 5 % is less than a step
        let g = grid(0.1, 0.01, -5, 0);
        assert_eq!(sensitivity_steps(&g), (Some(-1), None));
    }
}
