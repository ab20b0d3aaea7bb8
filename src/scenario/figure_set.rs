//! Figure-set files: groups of scenarios swept over the same pressures, one chart per group
//! and quantity (e.g. `scenarios/persson-yang-2008-figures.toml`, the data of PY08 §3).
//!
//! ```toml
//! name = "Persson & Yang 2008, section 3"
//! pressures = { from = "0.05 MPa", to = "1 MPa", points = 40 }   # log-spaced, inclusive
//! [[group]]
//! id = "rms-roughness"            # file-name stem of the group's outputs
//! title = "H = 0.8, h_rms = 1, 2, 4, 6 um"
//! scenarios = ["persson-yang-2008/hrms-1um.toml", "..."]   # relative to this file
//! plots = ["lambda_c", "u_c", "leak_rate"]   # also "u_c_and_hrms_c"; default: the first three
//! ```

use super::Scenario;
use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::raw::Quantity;
use super::text::read;
use crate::math::log_spaced;
use crate::units::{Dimension, show};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use toml::Spanned;

/// A chart of one group against the nominal pressure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlotKind {
    /// λc (PY08 figs. 6, 9).
    LambdaC,
    /// u_c (PY08 figs. 7, 10).
    UC,
    /// Q̇ (PY08 figs. 8, 11).
    LeakRate,
    /// u_c together with h_rms(ζc) (PY08 fig. 12).
    UcAndHrmsC,
}

impl PlotKind {
    const ALL: [(&'static str, PlotKind); 4] = [
        ("lambda_c", PlotKind::LambdaC),
        ("u_c", PlotKind::UC),
        ("leak_rate", PlotKind::LeakRate),
        ("u_c_and_hrms_c", PlotKind::UcAndHrmsC),
    ];

    /// The name used in figure-set files and output file names.
    pub fn id(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(_, k)| *k == self)
            .map_or("", |(id, _)| id)
    }
}

/// One group of scenarios drawn together.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureGroup {
    pub id: String,
    pub title: String,
    pub scenarios: Vec<Scenario>,
    pub plots: Vec<PlotKind>,
}

/// A validated figure set.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureSet {
    pub name: String,
    /// Nominal pressures \[Pa\], log-spaced and increasing.
    pub pressures: Vec<f64>,
    pub groups: Vec<FigureGroup>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFigureSet {
    name: Option<String>,
    pressures: Spanned<RawSweep>,
    group: Vec<Spanned<RawGroup>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSweep {
    from: Quantity,
    to: Quantity,
    points: Spanned<i64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGroup {
    id: Spanned<String>,
    title: Option<String>,
    scenarios: Vec<Spanned<String>>,
    plots: Option<Vec<Spanned<String>>>,
}

const FROM: Field = field(
    "pressures.from",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(1.0, 1e10),
);
const TO: Field = field(
    "pressures.to",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(1.0, 1e10),
);
const MAX_POINTS: i64 = 10_000;

impl FigureSet {
    /// Reads and validates a figure set and every scenario it names.
    pub fn load(path: &Path) -> Result<FigureSet, ScenarioError> {
        let text = read(path)?;
        let source = Source { path, text: &text };
        let raw: RawFigureSet = source.deserialize()?;

        let sweep = raw.pressures.get_ref();
        let (from, to) = (
            source.quantity(&sweep.from, &FROM)?,
            source.quantity(&sweep.to, &TO)?,
        );
        if to <= from {
            return Err(source.error(
                sweep.to.span(),
                TO.key,
                format!(
                    "must exceed pressures.from = {} Pa, got {} Pa",
                    show(from),
                    show(to)
                ),
            ));
        }
        let points = *sweep.points.get_ref();
        if !(2..=MAX_POINTS).contains(&points) {
            return Err(source.error(
                sweep.points.span(),
                "pressures.points",
                format!("must lie between 2 and {MAX_POINTS}, got {points}"),
            ));
        }
        let pressures = log_spaced(from, to, points as usize);

        if raw.group.is_empty() {
            return Err(source.error(0..0, "group", "a figure set needs at least one [[group]]"));
        }
        let dir = path.parent().unwrap_or(Path::new(""));
        let mut groups: Vec<FigureGroup> = Vec::new();
        for g in &raw.group {
            let g_ref = g.get_ref();
            let id = g_ref.id.get_ref();
            let safe = !id.is_empty()
                && id
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'))
                && !id.starts_with('.');
            if !safe {
                return Err(source.error(
                    g_ref.id.span(),
                    "group.id",
                    format!(
                        "must be a file-name stem of letters, digits, '-', '_' or '.', got {id:?}"
                    ),
                ));
            }
            if groups.iter().any(|other| &other.id == id) {
                return Err(source.error(
                    g_ref.id.span(),
                    "group.id",
                    format!("{id:?} is used twice"),
                ));
            }
            if g_ref.scenarios.is_empty() {
                return Err(source.error(g.span(), "group.scenarios", "lists no scenario"));
            }
            let scenarios = g_ref
                .scenarios
                .iter()
                .map(|s| Scenario::load(&dir.join(s.get_ref())))
                .collect::<Result<Vec<_>, _>>()?;
            let plots = match &g_ref.plots {
                None => vec![PlotKind::LambdaC, PlotKind::UC, PlotKind::LeakRate],
                Some(list) => list
                    .iter()
                    .map(|p| {
                        PlotKind::ALL
                            .iter()
                            .find(|(name, _)| name == p.get_ref())
                            .map(|(_, k)| *k)
                            .ok_or_else(|| {
                                let names: Vec<&str> =
                                    PlotKind::ALL.iter().map(|(n, _)| *n).collect();
                                source.error(
                                    p.span(),
                                    "group.plots",
                                    format!(
                                        "unknown plot {:?}, expected one of {}",
                                        p.get_ref(),
                                        names.join(", ")
                                    ),
                                )
                            })
                    })
                    .collect::<Result<Vec<_>, _>>()?,
            };
            groups.push(FigureGroup {
                id: id.clone(),
                title: g_ref.title.clone().unwrap_or_else(|| id.clone()),
                scenarios,
                plots,
            });
        }
        let name = raw.name.unwrap_or_else(|| source.file_stem());
        Ok(FigureSet {
            name,
            pressures,
            groups,
        })
    }
}

/// Where a group's outputs go: `DIR/{id}.csv` and `DIR/{id}-{plot}.svg`.
pub fn output_paths(dir: &Path, group: &FigureGroup) -> (PathBuf, Vec<(PlotKind, PathBuf)>) {
    let csv = dir.join(format!("{}.csv", group.id));
    let svgs = group
        .plots
        .iter()
        .map(|&k| (k, dir.join(format!("{}-{}.svg", group.id, k.id()))))
        .collect();
    (csv, svgs)
}
