//! `sealsim figures`: the critical constriction and leak rate of groups of scenarios over a
//! pressure sweep, as one CSV and a set of log–log SVG charts per group (PY08 §3 figures).

use super::{CliError, print_findings, progress_bar, write_output};
use crate::contact::Junction;
use crate::leak::{Fidelity, LeakPoint};
use crate::report::csv::scenario_leak_table;
use crate::report::plot::{LogLogChart, Series};
use crate::scenario::figure_set::{FigureGroup, FigureSet, PlotKind, output_paths};
use crate::workflow;
use crate::workflow::figures::{Curve, GroupCurves};
use clap::Args;
use std::path::PathBuf;

/// Arguments of `sealsim figures`.
#[derive(Debug, Clone, Args)]
pub struct FiguresArgs {
    /// Figure-set file (TOML), e.g. scenarios/persson-yang-2008-figures.toml.
    #[arg(value_name = "FIGURE_SET")]
    pub figure_set: PathBuf,

    /// Directory for the outputs (created if missing): per group `ID.csv` and `ID-PLOT.svg`.
    #[arg(long, value_name = "DIR")]
    pub out_dir: PathBuf,

    /// Fidelity level.
    #[arg(
        long,
        value_name = "LEVEL",
        value_parser = super::FidelityArg,
        default_value = "critical-junction"
    )]
    pub fidelity: Fidelity,
}

/// Runs `sealsim figures`: everything is computed before the first file is written.
pub fn run(args: FiguresArgs) -> Result<(), CliError> {
    let set = FigureSet::load(&args.figure_set)?;
    // no figure may replace the set, a scenario of it or a data file a scenario reads
    let planned: Vec<PathBuf> = set
        .groups
        .iter()
        .flat_map(|group| {
            let (csv, svgs) = output_paths(&args.out_dir, group);
            std::iter::once(csv).chain(svgs.into_iter().map(|(_, path)| path))
        })
        .collect();
    let inputs: Vec<&std::path::Path> = std::iter::once(args.figure_set.as_path())
        .chain(set.groups.iter().flat_map(|g| {
            g.scenarios.iter().flat_map(|s| {
                std::iter::once(s.path.as_path()).chain(s.inputs.iter().map(PathBuf::as_path))
            })
        }))
        .collect();
    let outputs: Vec<(&str, Option<&std::path::Path>)> = planned
        .iter()
        .map(|p| ("--out-dir", Some(p.as_path())))
        .collect();
    super::guard_outputs(&inputs, &outputs)?;
    let groups =
        workflow::figures::evaluate(&set, args.fidelity, &mut progress_bar("numerical level"));
    let mut files: Vec<(PathBuf, String)> = Vec::new();
    for GroupCurves { group, curves } in &groups {
        for c in curves {
            print_findings(Some(&c.name), &c.findings);
        }
        let (csv_path, svg_paths) = output_paths(&args.out_dir, group);
        let rows = curves
            .iter()
            .flat_map(|c| c.points.iter().map(|p| (c.name.as_str(), p)));
        files.push((csv_path, scenario_leak_table(rows)?));
        for (kind, path) in svg_paths {
            let svg = chart(kind, group, curves)
                .to_svg()
                .map_err(|e| CliError::Internal(e.to_string()))?;
            files.push((path, svg));
        }
    }
    std::fs::create_dir_all(&args.out_dir).map_err(|source| CliError::Output {
        target: args.out_dir.display().to_string(),
        source,
    })?;
    for (path, text) in &files {
        write_output(Some(path), text.as_bytes())?;
    }
    eprintln!(
        "{}: wrote {} files to {}",
        set.name,
        files.len(),
        args.out_dir.display()
    );
    Ok(())
}

/// One junction quantity against P0 for every curve; sealed points are left out.
fn series(label: String, curve: &Curve, value: impl Fn(&LeakPoint) -> Option<f64>) -> Series {
    Series {
        label,
        points: curve
            .points
            .iter()
            .filter_map(|p| Some((p.nominal_pressure, value(p)?)))
            .collect(),
    }
}

fn junction_value(
    p: &LeakPoint,
    f: impl Fn(&crate::contact::CriticalJunction) -> f64,
) -> Option<f64> {
    match &p.junction {
        Junction::Leaking(j) => Some(f(j)),
        Junction::Sealed => None,
    }
}

fn chart(kind: PlotKind, group: &FigureGroup, curves: &[Curve]) -> LogLogChart {
    let (what, y_label, series): (&str, &str, Vec<Series>) = match kind {
        PlotKind::LambdaC => (
            "lateral size of the critical constriction",
            "λc [m]",
            curves
                .iter()
                .map(|c| series(c.name.clone(), c, |p| junction_value(p, |j| j.lambda_c)))
                .collect(),
        ),
        PlotKind::UC => (
            "height of the critical constriction",
            "u_c [m]",
            curves
                .iter()
                .map(|c| series(c.name.clone(), c, |p| junction_value(p, |j| j.u_c)))
                .collect(),
        ),
        PlotKind::LeakRate => (
            "leak rate",
            "Q̇ [m³/s]",
            curves
                .iter()
                .map(|c| series(c.name.clone(), c, |p| Some(p.leak_rate)))
                .collect(),
        ),
        PlotKind::UcAndHrmsC => (
            "u_c and h_rms(ζc)",
            "length [m]",
            curves
                .iter()
                .flat_map(|c| {
                    [
                        series(format!("u_c, {}", c.name), c, |p| {
                            junction_value(p, |j| j.u_c)
                        }),
                        series(format!("h_rms(ζc), {}", c.name), c, |p| {
                            junction_value(p, |j| j.hrms_c)
                        }),
                    ]
                })
                .collect(),
        ),
    };
    LogLogChart {
        title: format!("{} — {what}", group.title),
        x_label: "nominal pressure P0 [Pa]".into(),
        y_label: y_label.into(),
        series,
    }
}
