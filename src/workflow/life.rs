//! `sealsim run` as a library call: a scenario's seal over its life.

use super::{Progress, scenario_path};
use crate::scenario::Scenario;
use crate::simulate::{LifeResult, Simulator};

/// The life of `scenario`'s seal at its `simulation.fidelity`. The result's findings include
/// the contact path's (docs/model.md §9.10); `progress` reports the numerical level's
/// realisations.
pub fn run(scenario: &Scenario, progress: Progress<'_>) -> LifeResult {
    let life = &scenario.life;
    let (path, mut findings) = scenario_path(scenario, life.fidelity, None, progress);
    let mut result = Simulator::with_path(life, path).run();
    findings.extend(std::mem::take(&mut result.findings));
    result.findings = findings;
    result
}
