//! `sealsim study` as a library call (docs/model.md §14): every case of a study (or of a
//! shard's slice of it) validated, then run in parallel, each contact path built once for all
//! the cases that share it.
//!
//! Determinism: a case's inputs depend only on the study's seed, design and the case's index
//! ([`crate::study::design`]); its run is a pure function of its scenario; results are
//! collected in case order. So the outcomes are bit-identical whatever the thread count and
//! however the cases are sharded.

use super::{life_on, numerical_settings, scenario_path};
use crate::contact::ContactSettings;
use crate::leak::{ContactPath, Fidelity};
use crate::numerical::HeightMap;
use crate::numerical::reference::NumericalSettings;
use crate::scenario::study::Study;
use crate::scenario::{Scenario, ScenarioError};
use crate::study::{CaseOutcome, Cell};
use crate::surface::Spectrum;
use crate::validity::Findings;
use rayon::prelude::*;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// A progress report `(done, total)` callable from any thread.
pub type SharedProgress<'a> = &'a (dyn Fn(usize, usize) + Sync);

/// The scenarios of the cases from index `first` with the input `values` (the design's, in
/// case order), each validated: an invalid case is its error, located at the study file's line
/// of the varied input that makes it invalid.
pub fn scenarios(
    study: &Study,
    first: usize,
    values: &[Vec<f64>],
) -> Vec<Result<Scenario, ScenarioError>> {
    values
        .par_iter()
        .enumerate()
        .map(|(k, v)| study.scenario(first + k, v))
        .collect()
}

/// The outcomes of cases `range` of `study`, on `threads` threads (`None`: all cores). An
/// invalid case is recorded with its reason and counted as failed at installation
/// ([`CaseOutcome::invalid`]); the rest run. Only a study none of whose cases is valid is an
/// error (its first case's).
pub fn run(
    study: &Study,
    range: Range<usize>,
    threads: Option<usize>,
    progress: SharedProgress<'_>,
) -> Result<Vec<CaseOutcome>, ScenarioError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| ScenarioError::Invalid {
            path: study.path.clone(),
            line: None,
            key: None,
            message: format!("cannot start {threads:?} threads: {e}"),
        })?;
    pool.install(|| {
        let values = study.plan.values(range.clone());
        let mut scenarios = scenarios(study, range.start, &values);
        if range.len() == study.cases()
            && scenarios.iter().all(Result::is_err)
            && let Some(Err(e)) = scenarios.drain(..).next()
        {
            return Err(e);
        }
        Ok(run_scenarios(
            study,
            range.start,
            &values,
            &scenarios,
            progress,
        ))
    })
}

/// What a contact path depends on (as [`scenario_path`] builds it).
#[derive(Debug, PartialEq)]
struct PathKey<'a> {
    spectrum: &'a Spectrum,
    contact: ContactSettings,
    fidelity: Fidelity,
    /// The numerical level's settings and height map (`None` at the other levels).
    numerical: Option<(NumericalSettings, Option<&'a HeightMap>)>,
}

impl<'a> PathKey<'a> {
    fn of(s: &'a Scenario) -> Self {
        let fidelity = s.life.fidelity;
        PathKey {
            spectrum: &s.life.spectrum,
            contact: s.life.contact,
            fidelity,
            numerical: (fidelity == Fidelity::Numerical)
                .then(|| (numerical_settings(s), s.height_map.as_ref())),
        }
    }

    /// A 64-bit FNV-1a hash of the key's exact (round-trip) debug text, streamed.
    fn hash(&self) -> u64 {
        let mut h = crate::math::fnv::Fnv1a::default();
        let _ = write!(h, "{self:?}");
        h.0
    }
}

/// One distinct contact path: built by the first case that needs it, dropped after the last.
struct Slot {
    path: Mutex<Option<Arc<(ContactPath, Findings)>>>,
    remaining: AtomicUsize,
}

fn run_scenarios(
    study: &Study,
    first: usize,
    values: &[Vec<f64>],
    scenarios: &[Result<Scenario, ScenarioError>],
    progress: SharedProgress<'_>,
) -> Vec<CaseOutcome> {
    // group the valid cases by contact path (exact equality behind the hash)
    let keys: Vec<Option<PathKey>> = scenarios
        .iter()
        .map(|s| s.as_ref().ok().map(PathKey::of))
        .collect();
    let mut by_hash: HashMap<u64, Vec<usize>> = HashMap::new();
    let mut slot_of = Vec::with_capacity(keys.len());
    let mut representative: Vec<usize> = Vec::new();
    for (i, key) in keys.iter().enumerate() {
        let Some(key) = key else {
            slot_of.push(usize::MAX);
            continue;
        };
        let candidates = by_hash.entry(key.hash()).or_default();
        let slot = match candidates
            .iter()
            .find(|&&s| keys[representative[s]].as_ref() == Some(key))
        {
            Some(&s) => s,
            None => {
                representative.push(i);
                candidates.push(representative.len() - 1);
                representative.len() - 1
            }
        };
        slot_of.push(slot);
    }
    let slots: Vec<Slot> = (0..representative.len())
        .map(|s| Slot {
            path: Mutex::new(None),
            remaining: AtomicUsize::new(slot_of.iter().filter(|&&k| k == s).count()),
        })
        .collect();

    let total = scenarios.len();
    let done = AtomicUsize::new(0);
    progress(0, total);
    (0..total)
        .into_par_iter()
        .map(|i| {
            let inputs: Vec<Cell> = study
                .inputs
                .iter()
                .zip(&values[i])
                .map(|(input, &x)| input.cell(x))
                .collect();
            let scenario = match &scenarios[i] {
                Ok(s) => s,
                Err(e) => {
                    progress(done.fetch_add(1, Ordering::AcqRel) + 1, total);
                    return CaseOutcome::invalid(
                        first + i,
                        inputs,
                        e.to_string(),
                        study.report_times.len(),
                    );
                }
            };
            let slot = &slots[slot_of[i]];
            let shared = {
                let mut guard = slot.path.lock().unwrap_or_else(|p| p.into_inner());
                match &*guard {
                    Some(shared) => Arc::clone(shared),
                    None => {
                        let built = Arc::new(scenario_path(
                            scenario,
                            scenario.life.fidelity,
                            None,
                            &mut |_, _| {},
                        ));
                        *guard = Some(Arc::clone(&built));
                        built
                    }
                }
            };
            let (path, findings) = (&shared.0, &shared.1);
            let result = life_on(&scenario.life, path.clone(), findings.clone());
            drop(shared);
            if slot.remaining.fetch_sub(1, Ordering::AcqRel) == 1 {
                *slot.path.lock().unwrap_or_else(|p| p.into_inner()) = None;
            }
            let outcome = CaseOutcome::new(first + i, inputs, &result, &study.report_times);
            progress(done.fetch_add(1, Ordering::AcqRel) + 1, total);
            outcome
        })
        .collect()
}
