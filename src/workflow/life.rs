//! `sealsim run` as a library call: a scenario's seal over its life.

use super::{Progress, life_on, scenario_path, with_band};
use crate::scenario::Scenario;
use crate::simulate::LifeResult;

/// The life of `scenario`'s seal at its `simulation.fidelity`, with its band at the
/// neighbouring level (docs/model.md §4.1). The result's findings include the contact path's
/// (docs/model.md §9.10); `progress` reports the numerical level's realisations.
pub fn run(scenario: &Scenario, progress: Progress<'_>) -> LifeResult {
    let life = &scenario.life;
    let (path, findings) = scenario_path(scenario, life.fidelity, None, progress);
    let result = life_on(life, path, findings);
    let (neighbour, _) = scenario_path(scenario, life.fidelity.neighbour(), None, &mut |_, _| {});
    with_band(life, result, neighbour)
}
