//! `sealsim gland SIZE --service face|piston|rod [--pressure inside|outside] [--dynamic]
//! [--backup-rings N] [--bore/--rod D] [--fit H8/f7] [--temperature MIN,MAX] [-o FILE]
//! [--json]`: the recommended housing of an AS568 ring for a service, with ISO 286 fits, and
//! its tolerance stack-up ([`crate::gland_design`], docs/model.md §6.2.1); `-o` writes the
//! designed gland into the o-ring template of the service as a runnable scenario.

use super::{CliError, positive_flag, write_output};
use crate::fits::Fit;
use crate::gland::{GlandKind, Housing};
use crate::gland_design::{self, Conditions, Design, INCH, Service};
use crate::report::gland::{Context, json, text};
use crate::scenario::{as568, library, templates};
use crate::units::{Dimension, parse_quantity};
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};

/// The service of `--service`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ServiceArg {
    Face,
    Piston,
    Rod,
}

/// The pressure side of a face gland.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PressureSide {
    Inside,
    Outside,
}

/// Arguments of `sealsim gland`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "The tables: static radial and face glands from The O-Ring Store's \
    reproduction of the Parker ORD 5700 design charts, dynamic glands from Engineers Edge \
    (docs/model.md §6.2.1 cites both); fits from ISO 286 tables (IT5–IT11; H; d, e, f, g, h; up \
    to 500 mm). min/max in the stack-up are the worst-case combinations of every tolerance \
    limit for each quantity separately. -o writes the service's o-ring template with the \
    designed gland (nominal dimensions, the largest clearance)."
)]
pub struct GlandArgs {
    /// The ring, an AS568 size (ISO 3601-1 class A uses the same dash numbers), e.g. AS568-214.
    #[arg(value_name = "SIZE")]
    pub size: String,

    /// Where the groove is: face (axial), piston (groove in the piston), rod (groove in the
    /// housing).
    #[arg(long, value_enum)]
    pub service: ServiceArg,

    /// Face glands: the pressure's side (outside: vacuum; the ring's ID is located).
    #[arg(long, value_enum)]
    pub pressure: Option<PressureSide>,

    /// Piston and rod glands: reciprocating (the dynamic table).
    #[arg(long)]
    pub dynamic: bool,

    /// Piston and rod glands: back-up rings on the low-pressure side.
    #[arg(long, value_name = "N", default_value_t = 0,
          value_parser = clap::value_parser!(u8).range(0..=2))]
    pub backup_rings: u8,

    /// Piston glands: the bore, e.g. "31.75 mm" (default: the ring's AS568 nominal OD).
    #[arg(long, value_name = "DIAMETER")]
    pub bore: Option<String>,

    /// Rod glands: the rod, e.g. "25.4 mm" (default: the ring's AS568 nominal ID).
    #[arg(long, value_name = "DIAMETER")]
    pub rod: Option<String>,

    /// The ISO 286 fit HOLE/SHAFT of the bore and the piston (or the housing and the rod).
    #[arg(long, value_name = "FIT", default_value = "H8/f7")]
    pub fit: String,

    /// Service temperatures MIN,MAX, e.g. "-20 C,80 C" (default: 23 °C and the template's).
    #[arg(long, value_name = "MIN,MAX", allow_hyphen_values = true)]
    pub temperature: Option<String>,

    /// Pressure difference for the back-up-ring advice, e.g. "210 bar" (default: the
    /// template's; written into the scenario).
    #[arg(long, value_name = "PRESSURE")]
    pub pressure_difference: Option<String>,

    /// The ring's compound, a library id (its CTE and the hardness in its name).
    #[arg(long, value_name = "ID", default_value = "nbr-70")]
    pub material: String,

    /// The housing's material (its CTE): steel, stainless, aluminium, brass, bronze,
    /// cast-iron, titanium.
    #[arg(long, value_name = "NAME", default_value = "steel")]
    pub housing: String,

    /// Write a runnable scenario with the designed gland to FILE (refused if FILE exists).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
}

/// The template a service's scenario starts from.
fn template_name(kind: GlandKind) -> &'static str {
    match kind {
        GlandKind::Face => "o-ring-face",
        GlandKind::Piston => "o-ring-piston",
        GlandKind::Rod => "o-ring-rod",
    }
}

/// A quantity string from a template's TOML (`section.key`), in SI.
fn template_quantity(text: &str, section: &str, key: &str, dim: Dimension) -> Option<f64> {
    let value: toml::Value = toml::from_str(text).ok()?;
    let s = value.get(section)?.get(key)?.as_str()?;
    if dim == Dimension::TEMPERATURE {
        return crate::units::parse_temperature(s).ok();
    }
    parse_quantity(s, dim).ok()
}

fn input(msg: impl Into<String>) -> CliError {
    CliError::Input(msg.into())
}

/// Runs `sealsim gland`.
pub fn run(args: GlandArgs) -> Result<(), CliError> {
    let kind = match args.service {
        ServiceArg::Face => GlandKind::Face,
        ServiceArg::Piston => GlandKind::Piston,
        ServiceArg::Rod => GlandKind::Rod,
    };
    if kind != GlandKind::Face && args.pressure.is_some() {
        return Err(input(
            "--pressure inside|outside is for face glands: a piston or rod gland seals on \
             either side; drop --pressure",
        ));
    }
    if kind == GlandKind::Face && args.dynamic {
        return Err(input(
            "--dynamic is for piston and rod glands (the tables have no dynamic face gland)",
        ));
    }
    if args.bore.is_some() && kind != GlandKind::Piston {
        return Err(input(
            "--bore is the bore of a piston gland; a rod gland takes --rod",
        ));
    }
    if args.rod.is_some() && kind != GlandKind::Rod {
        return Err(input(
            "--rod is the rod of a rod gland; a piston gland takes --bore",
        ));
    }
    let size = as568::lookup(&args.size).map_err(|e| match e {
        as568::LookupError::Table(t) => CliError::Internal(t.to_string()),
        other => CliError::Input(format!("{other} (`sealsim sizes` lists them)")),
    })?;
    let fit = Fit::parse(&args.fit).map_err(|e| input(format!("--fit: {e}")))?;
    let seat = match (&args.bore, &args.rod) {
        (Some(b), _) => positive_flag(Some(b), "bore", Dimension::LENGTH)?,
        (_, Some(r)) => positive_flag(Some(r), "rod", Dimension::LENGTH)?,
        _ => None,
    };
    let template = templates::template(template_name(kind))
        .ok_or_else(|| CliError::Internal("an o-ring template is missing".into()))?;
    let template_t = template_quantity(
        template.text,
        "environment",
        "temperature",
        Dimension::TEMPERATURE,
    )
    .ok_or_else(|| CliError::Internal("the template has no temperature".into()))?;
    let temperatures = match &args.temperature {
        None => (
            template_t.min(gland_design::ASSEMBLY_TEMPERATURE),
            template_t.max(gland_design::ASSEMBLY_TEMPERATURE),
        ),
        Some(text) => parse_temperatures(text)?,
    };
    let pressure = match &args.pressure_difference {
        Some(p) => {
            positive_flag(Some(p), "pressure-difference", Dimension::PRESSURE)?.unwrap_or_default()
        }
        None => template_quantity(
            template.text,
            "fluid",
            "pressure_difference",
            Dimension::PRESSURE,
        )
        .ok_or_else(|| CliError::Internal("the template has no pressure".into()))?,
    };
    let material = library::get(&args.material)
        .map_err(|e| input(format!("--material: {e}")))?
        .load()?;
    let ring_expansion = material.thermal_expansion.ok_or_else(|| {
        input(format!(
            "--material {}: the compound has no thermal_expansion; choose another",
            args.material
        ))
    })?;
    // the grade in the compound's id ("nbr-70" → 70 Shore A)
    let hardness = args
        .material
        .rsplit('-')
        .next()
        .and_then(|g| g.parse::<f64>().ok())
        .unwrap_or(70.0);
    let housing = Housing::from_name(&args.housing).ok_or_else(|| {
        input(format!(
            "--housing {:?}: expected one of {}",
            args.housing,
            Housing::ALL.map(Housing::name).join(", ")
        ))
    })?;
    let service = Service {
        kind,
        dynamic: args.dynamic,
        pressure_outside: args.pressure == Some(PressureSide::Outside),
        backup_rings: args.backup_rings,
    };
    let nominal =
        gland_design::as568_nominal(size.id_in, size.cs_in).map(|(id, od)| (id * INCH, od * INCH));
    let design = gland_design::design(size.ring(), nominal, service, fit, seat)
        .map_err(|e| input(format!("{}: {e}", size.name())))?;
    let conditions = Conditions {
        temperatures,
        ring_expansion,
        housing_expansion: housing.expansion(),
        pressure,
        hardness,
    };
    let stack = gland_design::stack_up(&design, &conditions)
        .map_err(|e| input(format!("{}: {e}", size.name())))?;
    let ctx = Context {
        size: size.name(),
        temperatures,
        pressure,
        hardness,
        ring_expansion,
        material: args.material.clone(),
        housing_expansion: housing.expansion(),
        housing: housing.name().to_owned(),
    };
    if let Some(path) = &args.output {
        write_scenario(path, template.text, &design, &stack, &ctx, &args)?;
    }
    let out = if args.json {
        json(&design, &stack, &ctx)?
    } else {
        text(&design, &stack, &ctx)
    };
    write_output(None, out.as_bytes())
}

/// `--temperature MIN,MAX`.
fn parse_temperatures(text: &str) -> Result<(f64, f64), CliError> {
    let (lo, hi) = text.split_once(',').ok_or_else(|| {
        input(format!(
            "--temperature: expected MIN,MAX such as \"-20 C,80 C\", got {text:?}"
        ))
    })?;
    let t = |s: &str| {
        crate::units::parse_temperature(s.trim())
            .map_err(|e| input(format!("--temperature: {e}")))
            .and_then(|v| {
                if v.is_finite() && v > 0.0 {
                    Ok(v)
                } else {
                    Err(input(format!("--temperature: not above 0 K: {s}")))
                }
            })
    };
    let (lo, hi) = (t(lo)?, t(hi)?);
    if lo > hi {
        return Err(input(format!(
            "--temperature: MIN above MAX in {text:?}: give the lowest first"
        )));
    }
    Ok((lo, hi))
}

/// A length for the scenario file, in mm to 0.1 µm.
fn mm(v: f64) -> String {
    let s = format!("{:.4}", v * 1e3);
    format!("\"{} mm\"", s.trim_end_matches('0').trim_end_matches('.'))
}

/// The `[seal]` table of the designed gland (nominal dimensions; the largest clearance).
fn seal_table(
    design: &Design,
    stack: &gland_design::StackUp,
    ctx: &Context,
    args: &GlandArgs,
) -> String {
    let h = &design.housing;
    let kind = design.service.kind;
    let mut lines = vec![
        "[seal]".to_owned(),
        format!(
            "# designed by `sealsim gland {} --service {}`: nominal dimensions of the designed \
             housing;",
            ctx.size,
            kind.name()
        ),
        "# the clearance is the fit's largest (the conservative end). The stack-up is in the \
         command's output."
            .to_owned(),
        "kind = \"o-ring\"".to_owned(),
        format!("gland = \"{}\"", kind.name()),
        format!("size = \"{}\"", ctx.size),
    ];
    let depth_tol = 0.5 * (h.depth.max - h.depth.min);
    match (kind, h.seat, h.groove_diameter) {
        (GlandKind::Piston, Some(seat), Some(groove))
        | (GlandKind::Rod, Some(seat), Some(groove)) => {
            let key = if kind == GlandKind::Piston {
                "bore_diameter"
            } else {
                "rod_diameter"
            };
            let depth = if kind == GlandKind::Piston {
                0.5 * (seat.mid() - groove.mid())
            } else {
                0.5 * (groove.mid() - seat.mid())
            };
            lines.push(format!("{key} = {}", mm(seat.mid())));
            lines.push(format!("groove_depth = {}", mm(depth)));
            lines.push(format!("groove_depth_tolerance = {}", mm(depth_tol)));
            lines.push(format!("groove_width = {}", mm(h.width.mid())));
            let clearance = stack
                .rows
                .iter()
                .find(|r| r.quantity == gland_design::Quantity::Clearance)
                .map_or(0.0, |r| r.assembly.1.max(0.0));
            lines.push(format!("diametral_clearance = {}", mm(clearance)));
            lines.push(format!("backup_rings = {}", design.service.backup_rings));
        }
        (_, seat, _) => {
            lines.push(format!("groove_depth = {}", mm(h.depth.mid())));
            lines.push(format!("groove_depth_tolerance = {}", mm(depth_tol)));
            lines.push(format!("groove_width = {}", mm(h.width.mid())));
            if let Some(seat) = seat {
                let key = if design.service.pressure_outside {
                    "groove_inner_diameter"
                } else {
                    "groove_outer_diameter"
                };
                lines.push(format!("{key} = {}", mm(seat.mid())));
            }
            lines.push("extrusion_gap = \"0 mm\"".to_owned());
        }
    }
    if args.housing != "steel" {
        lines.push(format!("housing = \"{}\"", ctx.housing));
    }
    lines.push("loading = \"displacement\"".to_owned());
    lines.join("\n") + "\n"
}

/// The template with its `[seal]` table replaced by the designed gland, its material and (when
/// given) its pressure difference set.
fn scenario_text(
    template: &str,
    design: &Design,
    stack: &gland_design::StackUp,
    ctx: &Context,
    args: &GlandArgs,
) -> String {
    let mut out = String::new();
    let mut in_seal = false;
    let mut section = String::new();
    for line in template.lines() {
        let trimmed = line.trim_start();
        if trimmed.starts_with('[') {
            section = trimmed
                .trim_start_matches('[')
                .split(']')
                .next()
                .unwrap_or_default()
                .to_owned();
            if section == "seal" {
                in_seal = true;
                out += &seal_table(design, stack, ctx, args);
                out.push('\n');
                continue;
            }
            in_seal = false;
        }
        if in_seal {
            continue;
        }
        let key = trimmed.split('=').next().unwrap_or_default().trim();
        if section == "material" && key == "library" {
            out += &format!("library = \"{}\"\n", args.material);
            continue;
        }
        if let Some(p) = args
            .pressure_difference
            .as_ref()
            .filter(|_| section == "fluid" && key == "pressure_difference")
        {
            let quoted = toml::Value::String(p.clone()).to_string();
            out += &format!("pressure_difference = {quoted}\n");
            continue;
        }
        out += line;
        out.push('\n');
    }
    out
}

fn write_scenario(
    path: &Path,
    template: &str,
    design: &Design,
    stack: &gland_design::StackUp,
    ctx: &Context,
    args: &GlandArgs,
) -> Result<(), CliError> {
    if path.exists() {
        return Err(input(format!(
            "-o {}: the file exists; sealsim gland never overwrites a file: give another name \
             or remove it first",
            path.display()
        )));
    }
    write_output(
        Some(path),
        scenario_text(template, design, stack, ctx, args).as_bytes(),
    )?;
    eprintln!(
        "wrote {} (run it with `sealsim run {}`)",
        path.display(),
        path.display()
    );
    Ok(())
}
