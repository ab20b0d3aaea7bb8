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

/// Why a compound stands where it does in a comparison's ranking (docs/model.md §6.8), best
/// group first. The scale has no "C"/"conditional" grade: each source's "fair" or
/// "short-term only" maps to B (limited). B is compatible here (the issue asks for the
/// compounds rated A or B), but within a group every A comes before every B: the life runs
/// model no fluid attack, so the attack a B warns of is missing from a B compound's life,
/// which reads longer than it is (the conservative order).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum RankBasis {
    /// Rated A (recommended) or B (limited) for the run's medium, with every figure its
    /// verdict needs: the only compounds a headline may name.
    Compatible,
    /// Rated A or B, but run without a figure the scenario's verdict needs (ageing constants):
    /// its life is an optimistic one (no ageing), so it is listed after the compatible ones.
    MissingFigure,
    /// No source rated the compound for the run's medium, or the ratings do not cover the
    /// medium (a gas, an inline fluid): unknown is not compatible.
    NotRated,
    /// Rated X (not recommended) for the run's medium: whatever its life, never first.
    Incompatible,
}

impl RankBasis {
    /// The word of the `rank_basis` column.
    pub fn as_str(self) -> &'static str {
        match self {
            RankBasis::Compatible => "compatible",
            RankBasis::MissingFigure => "missing_figure",
            RankBasis::NotRated => "not_rated",
            RankBasis::Incompatible => "incompatible",
        }
    }
}

/// A compound's place in a comparison: its rank (1 first, in the listed order), its basis,
/// the reason it is not compatible (empty when it is) and a flag on a compatible verdict
/// that rests on a NOT SOURCED bound.
#[derive(Debug, Clone, PartialEq)]
pub struct Standing {
    pub rank: usize,
    pub basis: RankBasis,
    /// Why the compound is listed after the compatible ones (empty for a compatible one).
    pub reason: String,
    /// The verdict relies on a NOT SOURCED permeation bound (docs/model.md §13.4): ranked,
    /// but flagged.
    pub not_sourced: bool,
    /// 0 for A, 1 for B, 2 not rated or X: A before B within a group.
    pub tier: u8,
}

impl Standing {
    /// The `rank_basis` column: the basis, its reason, the NOT SOURCED flag.
    pub fn describe(&self) -> String {
        let mut out = self.basis.as_str().to_owned();
        if !self.reason.is_empty() {
            out += &format!(" ({})", self.reason);
        }
        if self.not_sourced {
            out += "; flagged: NOT SOURCED permeation bound";
        }
        out
    }
}

/// The medium the ratings are read for: the fluid class's name, or a phrase for a fluid the
/// ratings do not cover.
pub fn medium(run: &CompoundRun) -> &'static str {
    run.scenario
        .fluid_class
        .map_or("this fluid", |c| c.as_str())
}

/// A run's life for the ranking \[s\]: the time to failure, +∞ for a run that survives (the
/// criterion `compare` has always ranked by).
pub fn life(run: &CompoundRun) -> f64 {
    run.result.failure.map_or(f64::INFINITY, |f| f.time)
}

/// The basis of one compound's run, with its reason and flag (rank 0: set by [`rank`]).
pub fn standing(run: &CompoundRun) -> Standing {
    let life_problem = &run.scenario.life;
    let not_sourced = life_problem
        .permeation
        .as_ref()
        .is_some_and(|p| p.data.status == crate::permeation::DataStatus::Bound);
    let (basis, reason) = match (run.scenario.fluid_class, &run.scenario.compatibility) {
        (None, _) => (
            RankBasis::NotRated,
            "the ratings cover mineral oil, water, hot water and water–glycol only".to_owned(),
        ),
        (Some(class), None) => (
            RankBasis::NotRated,
            format!("no source rated it for {}", class.as_str()),
        ),
        (Some(_), Some(c))
            if c.rating == crate::material::compatibility::Rating::NotRecommended =>
        {
            (
                RankBasis::Incompatible,
                format!("rated {} in {}", c.rating.letter(), c.class.as_str()),
            )
        }
        _ if life_problem.ageing_source == crate::simulate::AgeingSource::MissingInComparison => (
            RankBasis::MissingFigure,
            "no ageing constants: run without ageing".to_owned(),
        ),
        _ => (RankBasis::Compatible, String::new()),
    };
    use crate::material::compatibility::Rating;
    let tier = match run.scenario.compatibility.as_ref().map(|c| c.rating) {
        Some(Rating::Recommended) => 0,
        Some(Rating::Limited) => 1,
        _ => 2,
    };
    Standing {
        rank: 0,
        basis,
        reason,
        not_sourced,
        tier,
    }
}

/// `runs` in the order `sealsim compare` lists them, each with its [`Standing`]: by basis
/// (compatible, missing figure, not rated, incompatible), within it A before B, then by life,
/// longest first; ties keep the order the compounds were given in. `raw` (`--all`): by life alone, ratings
/// ignored. The ranks count from 1 in the returned order.
pub fn rank(runs: Vec<CompoundRun>, raw: bool) -> Vec<(CompoundRun, Standing)> {
    let mut ranked: Vec<(CompoundRun, Standing)> = runs
        .into_iter()
        .map(|run| {
            let s = standing(&run);
            (run, s)
        })
        .collect();
    // a stable sort: equal keys keep the given order
    ranked.sort_by(|(a, sa), (b, sb)| {
        let group = if raw {
            std::cmp::Ordering::Equal
        } else {
            (sa.basis, sa.tier).cmp(&(sb.basis, sb.tier))
        };
        group.then(life(b).total_cmp(&life(a)))
    });
    for (i, (_, s)) in ranked.iter_mut().enumerate() {
        s.rank = i + 1;
    }
    ranked
}
