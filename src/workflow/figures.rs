//! `sealsim figures` as a library call: every scenario of a figure set's groups over the set's
//! pressure sweep (e.g. the data of PY08 §3, figs. 6–12).

use super::{Progress, leak::evaluate_on, scenario_path};
use crate::leak::{Fidelity, LeakPoint};
use crate::scenario::figure_set::{FigureGroup, FigureSet};
use crate::validity::Findings;

/// One scenario's sweep.
#[derive(Debug, Clone)]
pub struct Curve {
    /// The scenario's name (the legend).
    pub name: String,
    pub points: Vec<LeakPoint>,
    pub findings: Findings,
}

/// A group's curves.
#[derive(Debug, Clone)]
pub struct GroupCurves<'a> {
    pub group: &'a FigureGroup,
    pub curves: Vec<Curve>,
}

/// Every group of `set` at `fidelity`. The sweep is static: a scenario's `[motion]` is not
/// applied; the numerical level uses its default table nodes, not one solve per pressure.
pub fn evaluate<'a>(
    set: &'a FigureSet,
    fidelity: Fidelity,
    progress: Progress<'_>,
) -> Vec<GroupCurves<'a>> {
    set.groups
        .iter()
        .map(|group| GroupCurves {
            group,
            curves: group
                .scenarios
                .iter()
                .map(|sc| {
                    let mut scenario = sc.clone();
                    scenario.life.motion = None;
                    let (path, findings) = scenario_path(&scenario, fidelity, None, progress);
                    let outcome = evaluate_on(&scenario, path, findings, Some(&set.pressures));
                    Curve {
                        name: scenario.name,
                        points: outcome.points,
                        findings: outcome.findings,
                    }
                })
                .collect(),
        })
        .collect()
}
