//! `sealsim run` as a library call: a scenario's seal over its life.

use super::{Progress, life_on, scenario_path};
use crate::scenario::Scenario;
use crate::simulate::LifeResult;

/// The life of `scenario`'s seal at its `simulation.fidelity`. The result's findings include
/// the contact path's (docs/model.md §9.10); `progress` reports the numerical level's
/// realisations.
pub fn run(scenario: &Scenario, progress: Progress<'_>) -> LifeResult {
    let life = &scenario.life;
    let (path, findings) = scenario_path(scenario, life.fidelity, None, progress);
    life_on(life, path, findings)
}
