//! One case of a study and what the study keeps of its life run (docs/model.md §14.2).

use crate::simulate::{FailureMode, LifeResult};

/// A per-case table cell of a varied input: an SI number, or a word (a compound id, a level).
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    Number(f64),
    Word(String),
}

/// The `state_end` of an invalid case.
pub const INVALID_STATE: &str = "invalid";

/// What a study keeps of one case's life run.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseOutcome {
    /// The case's index in the study (0-based).
    pub index: usize,
    /// The varied inputs' values, in input order.
    pub inputs: Vec<Cell>,
    /// The time to failure, or the end of the run for a survivor (censored there) \[s\].
    pub life: f64,
    /// How it failed; `None`: it survived the run (censored).
    pub mode: Option<FailureMode>,
    /// The leak rate at each of the study's report times \[m³/s\]; `None` past the run's end.
    pub leak_rates: Vec<Option<f64>>,
    /// The sealing force per unit length at the end of the run \[N/m\].
    pub final_force: f64,
    /// That force over the force at the retained-force reference time (1 at installation).
    pub retained_force: f64,
    /// The leaked volume at the end of the run \[m³\].
    pub leaked_volume: f64,
    /// Compression set at the end of the run (with ageing), else `None`.
    pub compression_set: Option<f64>,
    /// The seal's state at the end of the run (`sealed`, `leaking`, `pressure_held`,
    /// `lift_off`; docs/model.md §8.1).
    pub final_state: String,
    /// The ids of the validity limits the case crossed (docs/model.md §9), sorted.
    pub warnings: Vec<String>,
    /// Why the case is not a valid scenario (`None`: it ran). An invalid case — a tolerance
    /// corner that cannot seat the ring, a groove it overfills — is counted as failed at
    /// installation (life 0; docs/model.md §14.2): the conservative reading, since such a part
    /// is not a seal.
    pub invalid: Option<String>,
}

/// The `warnings` entry of a gas case whose permeation through the rubber is a NOT SOURCED
/// bound rather than a figure of its compound's class (docs/model.md §13.4).
pub const PERMEATION_BOUND: &str = "permeation_not_sourced_bound";

impl CaseOutcome {
    /// The outcome of case `index` with `inputs` from its life run, its leak rates taken at
    /// `report_times` \[s\].
    pub fn new(index: usize, inputs: Vec<Cell>, result: &LifeResult, report_times: &[f64]) -> Self {
        let end = result.rows.last();
        let end_time = end.map_or(0.0, |r| r.time);
        let (life, mode) = match result.failure {
            Some(f) => (f.time, Some(f.mode)),
            None => (end_time, None),
        };
        let final_force = end.map_or(0.0, |r| r.sealing_force);
        let mut warnings: Vec<String> = result
            .findings
            .iter()
            .map(|f| f.limit.id().to_owned())
            .collect();
        // a gas case whose permeation figure is a stated bound says so (docs/model.md §13.4)
        if result.permeation_status == Some(crate::permeation::DataStatus::Bound) {
            warnings.push(PERMEATION_BOUND.to_owned());
        }
        warnings.sort();
        warnings.dedup();
        CaseOutcome {
            index,
            inputs,
            life,
            mode,
            leak_rates: report_times
                .iter()
                .map(|&t| (t <= end_time).then(|| result.leak_rate_at(t)).flatten())
                .collect(),
            final_force,
            retained_force: if result.reference_force > 0.0 {
                final_force / result.reference_force
            } else {
                0.0
            },
            leaked_volume: result.leaked_volume(),
            compression_set: end.and_then(|r| r.compression_set),
            final_state: result.final_state().as_str().to_owned(),
            warnings,
            invalid: None,
        }
    }

    /// The record of case `index` with `inputs` that is not a valid scenario, for `reason`.
    pub fn invalid(index: usize, inputs: Vec<Cell>, reason: String, report_times: usize) -> Self {
        CaseOutcome {
            index,
            inputs,
            life: 0.0,
            mode: None,
            leak_rates: vec![None; report_times],
            final_force: 0.0,
            retained_force: 0.0,
            leaked_volume: 0.0,
            compression_set: None,
            final_state: INVALID_STATE.to_owned(),
            warnings: Vec::new(),
            invalid: Some(reason),
        }
    }

    /// Whether the case failed within its run, or is invalid (failed at installation).
    pub fn failed(&self) -> bool {
        self.mode.is_some() || self.invalid.is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::permeation::DataStatus;

    fn result(permeation_status: Option<DataStatus>) -> LifeResult {
        LifeResult {
            rows: Vec::new(),
            failure: None,
            findings: Default::default(),
            reference_force: 0.0,
            continuum_leak_rate: None,
            permeation_status,
        }
    }

    /// A gas case run on a NOT SOURCED bound says so in its warnings (and so in the study's
    /// per-case table and summary); a sourced figure, a user's, or a liquid says nothing.
    #[test]
    fn a_case_on_a_permeation_bound_says_so() {
        let warnings = |s| CaseOutcome::new(0, Vec::new(), &result(s), &[]).warnings;
        assert_eq!(warnings(Some(DataStatus::Bound)), [PERMEATION_BOUND]);
        for s in [
            None,
            Some(DataStatus::Published),
            Some(DataStatus::Illustrative),
            Some(DataStatus::User),
        ] {
            assert!(warnings(s).is_empty(), "{s:?}");
        }
    }
}
