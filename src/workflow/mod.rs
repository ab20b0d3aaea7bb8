//! What each command does, as library calls: the static leak of a scenario ([`leak`]), its life
//! ([`life`]), the same life with other compounds ([`compare`]), figure sets ([`figures`]), the
//! fidelity trade-off ([`tradeoff`]), a Prony series fitted to lab data ([`fit_prony`]) and the
//! summary of a roughness source ([`surface`]). The command line only parses arguments, calls these,
//! renders and writes; a library user (or a binding) reaches the same results.
//!
//! Every workflow returns its validity [`Findings`] (docs/model.md §9) with its results, so
//! that every command reports them the same way.

pub mod advise;
pub mod compare;
pub mod datasheet;
pub mod figures;
pub mod fit_prony;
pub mod gland;
pub mod leak;
pub mod life;
pub mod study;
pub mod surface;
pub mod tradeoff;

use crate::leak::{ContactPath, Fidelity, PathOptions};
use crate::scenario::Scenario;
use crate::simulate::{LevelBand, LifeProblem, LifeResult, Simulator};
use crate::validity::Findings;

/// A progress report `(done, total)` for long work (the numerical level's realisations, the
/// trade-off's settings); `&mut |_, _| {}` for none.
pub type Progress<'a> = &'a mut dyn FnMut(usize, usize);

/// The scenario's contact path at `fidelity`, built with its height map and `[numerical]`
/// settings, and the path's own findings (docs/model.md §9.10). `numerical_nodes`: reduced
/// pressures P0/E* at which the numerical level solves (`None`: its default table nodes).
pub fn scenario_path(
    scenario: &Scenario,
    fidelity: Fidelity,
    numerical_nodes: Option<Vec<f64>>,
    progress: Progress<'_>,
) -> (ContactPath, Findings) {
    let options = PathOptions {
        height_map: scenario.height_map.as_ref(),
        numerical: numerical_settings(scenario),
        numerical_nodes,
        molecular_size: scenario.life.fluid.molecular_size(),
        ..PathOptions::default()
    };
    let pb = &scenario.problem;
    let path = ContactPath::build(&pb.spectrum, pb.contact, fidelity, &options, progress);
    let mut findings = Findings::default();
    path.assess(&options, &mut findings);
    (path, findings)
}

/// The scenario's `[numerical]` settings as its contact path uses them: a rarefied gas's cells
/// rarefy at p̄ and the installation temperature, and a cell no wider than a molecule of the
/// fluid conducts nothing (also the Python package's `sealsim.contact` at the numerical level).
pub fn numerical_settings(scenario: &Scenario) -> crate::numerical::reference::NumericalSettings {
    let mut numerical = scenario.numerical.clone();
    let life = &scenario.life;
    numerical.flow.gas = life.fluid.at(life.environment.at(0.0)).mean_free_path();
    numerical.flow.molecular_size = life.fluid.molecular_size();
    numerical
}

/// `result`, the life of `life`, with its band: the same life at the neighbouring fidelity level
/// ([`Fidelity::neighbour`]) on `path`, built for that level (docs/model.md §4.1). Its findings
/// are not kept: the summary's warnings are the level's own.
fn with_band(life: &LifeProblem, mut result: LifeResult, path: ContactPath) -> LifeResult {
    let level = life.fidelity.neighbour();
    let neighbour = LifeProblem {
        fidelity: level,
        ..life.clone()
    };
    let other = Simulator::with_path(&neighbour, path).run();
    result.band = Some(LevelBand::of(level, &other));
    result
}

/// The life of `life` on a contact path built beforehand, its findings after the path's own
/// `findings`.
fn life_on(life: &LifeProblem, path: ContactPath, mut findings: Findings) -> LifeResult {
    let mut result = Simulator::with_path(life, path).run();
    findings.extend(std::mem::take(&mut result.findings));
    result.findings = findings;
    result
}

/// Scenario `text` (read from `path`) with each dotted key of `values` set as a study's
/// `[vary]` sets a case's value (`("seal.squeeze", "22 %")`; tables are created on the way, and
/// setting `material.library` or `material.file` replaces the compound), then validated:
/// the new scenario and its TOML text. Used by the Python package's `Scenario.replace`.
///
/// An invalid result is an error at `path` naming the key (the replaced key the validation
/// names, else the first replaced), without a line: the lines of the rewritten text are not
/// the file's.
pub fn replace(
    text: &str,
    path: &std::path::Path,
    values: &[(String, toml::Value)],
) -> Result<(String, Scenario), crate::scenario::ScenarioError> {
    use crate::scenario::ScenarioError;
    let invalid = |key: Option<String>, message: String| ScenarioError::Invalid {
        path: path.to_path_buf(),
        line: None,
        key,
        message,
    };
    let mut table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| invalid(None, e.message().to_owned()))?;
    for (key, value) in values {
        crate::scenario::study::set(&mut table, key, value.clone())
            .map_err(|m| invalid(Some(key.clone()), m))?;
    }
    let new_text = toml::to_string(&table).map_err(|e| invalid(None, e.to_string()))?;
    let described = values
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect::<Vec<_>>()
        .join(", ");
    let scenario = Scenario::from_str(&new_text, path).map_err(|e| match e {
        ScenarioError::Invalid { key, message, .. } => {
            let named = key
                .clone()
                .filter(|k| values.iter().any(|(v, _)| v == k))
                .or_else(|| values.first().map(|(k, _)| k.clone()));
            let inner = match &key {
                Some(k) if Some(k) != named.as_ref() => format!("{k}: {message}"),
                _ => message,
            };
            invalid(named, format!("{inner} (with {described})"))
        }
        other => other,
    })?;
    Ok((new_text, scenario))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    const PAPER: &str = include_str!("../../scenarios/persson-yang-2008.toml");

    #[test]
    fn replace_equals_the_edited_file_and_names_the_key_of_an_error() {
        let path = Path::new("dir/x.toml");
        let values = [
            (
                "seal.nominal_pressure".to_owned(),
                toml::Value::String("0.3 MPa".into()),
            ),
            ("model.shape_factor".to_owned(), toml::Value::Integer(2)),
        ];
        let (text, replaced) = replace(PAPER, path, &values).unwrap();
        // the same scenario as the file edited by hand
        let edited = PAPER.replace("\"0.2 MPa\"", "\"0.3 MPa\"") + "\n[model]\nshape_factor = 2\n";
        let direct = Scenario::from_str(&edited, path).unwrap();
        assert_eq!(replaced, direct);
        assert_eq!(replaced.problem.seal.nominal_pressure, 3e5);
        assert_eq!(replaced.problem.shape_factor, 2.0);
        // the new text validates to the same scenario again
        assert_eq!(Scenario::from_str(&text, path).unwrap(), replaced);
        // an invalid value: the file and the replaced key, no line of the rewritten text
        let bad = [(
            "seal.nominal_pressure".to_owned(),
            toml::Value::String("3 m".into()),
        )];
        let e = replace(PAPER, path, &bad).unwrap_err().to_string();
        assert!(
            e.starts_with("dir/x.toml: seal.nominal_pressure: expected a pressure"),
            "{e}"
        );
        assert!(e.ends_with("(with seal.nominal_pressure = \"3 m\")"), "{e}");
        // a key path through a value
        let through = [("seal.width.x".to_owned(), toml::Value::Integer(1))];
        let e = replace(PAPER, path, &through).unwrap_err().to_string();
        assert!(
            e.contains("seal.width.x: `width` in the base scenario is not a table"),
            "{e}"
        );
    }
}
