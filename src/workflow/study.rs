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

/// Cases validated and run together: each block's scenarios (≈ 16 KB a case) are built, run
/// and dropped before the next, so memory stays flat in the number of cases (the review's
/// 10⁶-case study aborted on a 2.7 GB vector of every case's scenario, built up front).
pub const BLOCK: usize = 4096;

/// Contact paths carried from one block to the next: the most shared ones, so a study whose
/// cases share few paths (a numerical table, minutes to build) builds each about once.
const CARRIED: usize = 8;

/// The outcomes of cases `range` of `study`, on `threads` threads (`None`: all cores), in
/// blocks of [`BLOCK`] cases: [`run_blocks`] with every block kept.
pub fn run(
    study: &Study,
    range: Range<usize>,
    threads: Option<usize>,
    progress: SharedProgress<'_>,
) -> Result<Vec<CaseOutcome>, ScenarioError> {
    let mut outcomes = Vec::with_capacity(range.len());
    run_blocks(study, range, threads, progress, |block| {
        outcomes.extend(block);
        Ok::<(), ScenarioError>(())
    })?;
    Ok(outcomes)
}

/// Runs cases `range` of `study` on `threads` threads (`None`: all cores) in blocks of
/// [`BLOCK`] cases, handing each block's outcomes (in case order, the blocks in case order) to
/// `each_block` before the next block is built, so that a caller that keeps less than the
/// outcomes (a table written as it comes, the summary's records) runs any number of cases in
/// flat memory. An invalid case is recorded with its reason and counted as failed at
/// installation ([`CaseOutcome::invalid`]); the rest run. Only a study none of whose cases is
/// valid is an error (its first case's), returned after every block was handed over;
/// `each_block`'s first error stops the run.
pub fn run_blocks<E: From<ScenarioError>>(
    study: &Study,
    range: Range<usize>,
    threads: Option<usize>,
    progress: SharedProgress<'_>,
    mut each_block: impl FnMut(Vec<CaseOutcome>) -> Result<(), E>,
) -> Result<(), E> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| ScenarioError::Invalid {
            path: study.path.clone(),
            line: None,
            key: None,
            message: format!("cannot start {threads:?} threads: {e}"),
        })?;
    let design = study.plan.sampler();
    let mut carried: Vec<Carried> = Vec::new();
    let mut first_error = None;
    let mut any_valid = false;
    let count = Count {
        done: AtomicUsize::new(0),
        total: range.len(),
        progress,
    };
    progress(0, count.total);
    for start in range.clone().step_by(BLOCK) {
        let end = (start + BLOCK).min(range.end);
        let (outcomes, scenarios, keep) = pool.install(|| {
            let values = design.values(start..end);
            let scenarios = scenarios(study, start, &values);
            let block = Block {
                first: start,
                values: &values,
                scenarios: &scenarios,
            };
            let (outcomes, keep) = run_block(study, &block, &carried, &count);
            (outcomes, scenarios, keep)
        });
        any_valid |= scenarios.iter().any(Result::is_ok);
        carried = keep
            .into_iter()
            .filter_map(|(i, path)| {
                let scenario = scenarios[i].as_ref().ok()?;
                Some((Arc::new(scenario.clone()), path))
            })
            .collect();
        // the block's scenarios (≈ 16 KB a case) dropped before its outcomes are handed over
        let first = scenarios.into_iter().next();
        if first_error.is_none() && !any_valid {
            first_error = first.and_then(Result::err);
        }
        each_block(outcomes)?;
    }
    match first_error {
        Some(e) if range.len() == study.cases() && !any_valid => Err(e.into()),
        _ => Ok(()),
    }
}

/// A contact path kept across blocks, with the scenario that built it (its key).
type Carried = (Arc<Scenario>, Arc<(ContactPath, Findings)>);

/// The contact paths a block keeps for the next, each with the index (in the block) of the
/// case whose scenario is its key.
type Kept = Vec<(usize, Arc<(ContactPath, Findings)>)>;

/// The cases of one block: the first's index, the design's values and the validated scenarios.
struct Block<'a> {
    first: usize,
    values: &'a [Vec<f64>],
    scenarios: &'a [Result<Scenario, ScenarioError>],
}

/// Progress over all blocks.
struct Count<'a> {
    done: AtomicUsize,
    total: usize,
    progress: SharedProgress<'a>,
}

impl Count<'_> {
    fn one(&self) {
        (self.progress)(self.done.fetch_add(1, Ordering::AcqRel) + 1, self.total);
    }
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

/// One distinct contact path: built by the first case that needs it (or carried from the
/// previous block), dropped after the last unless `keep` (carried to the next block).
struct Slot {
    path: Mutex<Option<Arc<(ContactPath, Findings)>>>,
    remaining: AtomicUsize,
    keep: bool,
}

/// Runs one block: its valid cases grouped by contact path (exact equality behind the hash),
/// each path built by the first case that needs it — or taken from `carried` — and dropped
/// after its last case, except the [`CARRIED`] most shared, returned with the index of the
/// case whose scenario is their key.
fn run_block(
    study: &Study,
    block: &Block<'_>,
    carried: &[Carried],
    count: &Count<'_>,
) -> (Vec<CaseOutcome>, Kept) {
    let scenarios = block.scenarios;
    let old_keys: Vec<PathKey> = carried.iter().map(|(s, _)| PathKey::of(s)).collect();
    let keys: Vec<Option<PathKey>> = scenarios
        .iter()
        .map(|s| s.as_ref().ok().map(PathKey::of))
        .collect();
    let (slot_of, representative) = group(&keys);
    let mut counts = vec![0usize; representative.len()];
    for &s in slot_of.iter().filter(|&&s| s != usize::MAX) {
        counts[s] += 1;
    }
    // the most shared paths outlive the block (ties: the first)
    let mut by_count: Vec<usize> = (0..counts.len()).filter(|&s| counts[s] > 1).collect();
    by_count.sort_by_key(|&s| std::cmp::Reverse(counts[s]));
    by_count.truncate(CARRIED);
    let slots: Vec<Slot> = (0..representative.len())
        .map(|s| {
            let key = keys[representative[s]].as_ref();
            let old = old_keys.iter().position(|k| Some(k) == key);
            Slot {
                path: Mutex::new(old.map(|k| Arc::clone(&carried[k].1))),
                remaining: AtomicUsize::new(counts[s]),
                keep: by_count.contains(&s),
            }
        })
        .collect();
    let outcomes = (0..scenarios.len())
        .into_par_iter()
        .map(|i| {
            run_case(
                study,
                block,
                i,
                slot_of.get(i).and_then(|&s| slots.get(s)),
                count,
            )
        })
        .collect();
    let keep = by_count
        .iter()
        .filter_map(|&s| {
            let path = slots[s]
                .path
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .take()?;
            Some((representative[s], path))
        })
        .collect();
    (outcomes, keep)
}

/// Each valid case's slot (`usize::MAX` for an invalid one) and each slot's first case.
fn group(keys: &[Option<PathKey<'_>>]) -> (Vec<usize>, Vec<usize>) {
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
    (slot_of, representative)
}

/// Case `i` of the block on its contact path's `slot` (`None`: an invalid case).
fn run_case(
    study: &Study,
    block: &Block<'_>,
    i: usize,
    slot: Option<&Slot>,
    count: &Count<'_>,
) -> CaseOutcome {
    let index = block.first + i;
    let inputs: Vec<Cell> = study
        .inputs
        .iter()
        .zip(&block.values[i])
        .map(|(input, &x)| input.cell(x))
        .collect();
    let (scenario, slot) = match (&block.scenarios[i], slot) {
        (Ok(s), Some(slot)) => (s, slot),
        (Err(e), _) => {
            count.one();
            return CaseOutcome::invalid(index, inputs, e.to_string(), study.report_times.len());
        }
        (Ok(_), None) => {
            count.one();
            let why = "internal error: a valid case without its contact path".to_owned();
            return CaseOutcome::invalid(index, inputs, why, study.report_times.len());
        }
    };
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
    if slot.remaining.fetch_sub(1, Ordering::AcqRel) == 1 && !slot.keep {
        *slot.path.lock().unwrap_or_else(|p| p.into_inner()) = None;
    }
    let outcome = CaseOutcome::new(index, inputs, &result, &study.report_times);
    count.one();
    outcome
}
