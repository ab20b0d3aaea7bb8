//! `sealsim compare` as a library call: one life scenario with each of several compounds.

use super::{Progress, life_on, scenario_path, with_band};
use crate::contact::ContactSettings;
use crate::leak::{ContactPath, Fidelity};
use crate::material::Material;
use crate::scenario::compatibility::Compatibility;
use crate::scenario::{Scenario, ScenarioError};
use crate::simulate::{LifeProblem, LifeResult};
use crate::surface::Spectrum;
use crate::validity::Findings;
use std::path::Path;

/// What a contact path depends on.
type PathKey = (Spectrum, ContactSettings, Fidelity);

/// One compound's run.
#[derive(Debug, Clone)]
pub struct CompoundRun {
    /// The compound as the caller named it (a library id or a file path).
    pub label: String,
    pub material: Material,
    /// The scenario validated with this compound.
    pub scenario: Scenario,
    /// Its life, with its findings (the shared contact path's included in the first run's).
    pub result: LifeResult,
}

/// The scenario at `scenario_path` run with each of `compounds` (label, material) in place of
/// its `[material]` compound, at `fidelity` (the scenario's when `None`). The contact table is
/// built once for every compound that shares the surface, the contact settings and the level.
pub fn compare(
    scenario_path_on_disk: &Path,
    compounds: Vec<(String, Material)>,
    fidelity: Option<Fidelity>,
    progress: Progress<'_>,
) -> Result<Vec<CompoundRun>, ScenarioError> {
    let scenarios: Vec<Scenario> = compounds
        .iter()
        .map(|(_, m)| Scenario::load_with_material(scenario_path_on_disk, m))
        .collect::<Result<_, ScenarioError>>()?;
    Ok(compare_scenarios(scenarios, compounds, fidelity, progress))
}

/// [`compare`] on `scenarios` validated beforehand, one per compound of `compounds` (in
/// order; e.g. [`Scenario::from_str_with_material`] of a text that is not on disk).
pub fn compare_scenarios(
    mut scenarios: Vec<Scenario>,
    compounds: Vec<(String, Material)>,
    fidelity: Option<Fidelity>,
    progress: Progress<'_>,
) -> Vec<CompoundRun> {
    if let Some(f) = fidelity {
        for s in &mut scenarios {
            s.life.fidelity = f;
        }
    }
    // One contact table for all compounds: it depends only on the surface, the contact
    // settings and the level, which the variants share (checked, in case a material file
    // changed them).
    let mut shared: Option<(PathKey, ContactPath)> = None;
    // the neighbouring level's path for the bands (docs/model.md §4.1), shared the same way
    let mut shared_band: Option<(PathKey, ContactPath)> = None;
    let mut runs = Vec::with_capacity(scenarios.len());
    for ((label, material), scenario) in compounds.into_iter().zip(scenarios) {
        let life = &scenario.life;
        let key = (life.spectrum.clone(), life.contact, life.fidelity);
        let (path, findings) = match &shared {
            Some((first, path)) if *first == key => (path.clone(), Findings::default()),
            _ => {
                let (path, findings) = scenario_path(&scenario, life.fidelity, None, progress);
                shared = Some((key, path.clone()));
                (path, findings)
            }
        };
        let neighbour = life.fidelity.neighbour();
        let band_key = (life.spectrum.clone(), life.contact, neighbour);
        let band_path = match &shared_band {
            Some((first, path)) if *first == band_key => path.clone(),
            _ => {
                let (path, _) = scenario_path(&scenario, neighbour, None, &mut |_, _| {});
                shared_band = Some((band_key, path.clone()));
                path
            }
        };
        let result = with_band(life, life_on(life, path, findings), band_path);
        runs.push(CompoundRun {
            label,
            material,
            scenario,
            result,
        });
    }
    runs
}

/// What a compound's run left out for want of data, "; "-separated (the `notes` column of
/// `sealsim compare`): the compound's rating in the fluid's class when rated, ageing the
/// scenario asks for (docs/model.md §6.5, §6.8). A gas without a permeation figure is refused
/// before it runs (§13.7).
pub fn notes(life: &LifeProblem, compatibility: Option<&Compatibility>) -> String {
    let mut notes = Vec::new();
    let flag;
    if let Some(c) = compatibility {
        flag = format!(
            "{} in {}: {} (docs/model.md §6.8)",
            c.rating.words(),
            c.class.as_str(),
            c.rating.letter()
        );
        notes.push(flag.as_str());
    }
    if life.ageing_source == crate::simulate::AgeingSource::MissingInComparison {
        notes.push("no ageing constants: run without ageing");
    }
    notes.join("; ")
}

/// Where the compound's ageing activation energy comes from (docs/model.md §6.5): its value
/// (or its band about the anchor) and the `[material.ageing] source` of the compound, or the
/// scenario's `[ageing]`, or why there is none. `sealsim compare` prints it beside each row.
pub fn ageing_source(life: &LifeProblem, material: &Material) -> String {
    use crate::simulate::AgeingSource;
    let Some(a) = life.ageing else {
        return match life.ageing_source {
            AgeingSource::Off => "no ageing (switched off)".to_owned(),
            _ => "no ageing constants".to_owned(),
        };
    };
    let kj = |e: f64| crate::units::human(e / 1e3, 3);
    let energy = if a.is_two_sided() {
        format!(
            "Ea {} kJ/mol at and below {}, {} above",
            kj(a.activation_energy),
            crate::units::show_temperature(a.reference_temperature, 4),
            kj(a.activation_energy_above)
        )
    } else {
        format!("Ea {} kJ/mol", kj(a.activation_energy))
    };
    let source = match life.ageing_source {
        AgeingSource::Scenario => "the scenario's [ageing]".to_owned(),
        _ => material
            .ageing_basis
            .as_ref()
            .and_then(|b| b.source.clone())
            .unwrap_or_else(|| "no source given".to_owned()),
    };
    format!("{energy}: {source}")
}

/// A gas: what the permeation figure is and where it comes from (sourced, derived, a NOT
/// SOURCED bound, the user's; docs/model.md §13.4), `None` for a liquid.
pub fn permeation_source(life: &LifeProblem) -> Option<String> {
    life.permeation.as_ref().map(|p| p.data.basis())
}
