//! `sealsim gland SIZE --service face|piston|rod [--pressure inside|outside] [--dynamic]
//! [--backup-rings N] [--bore/--rod D] [--fit H8/f7] [--temperature MIN,MAX] [-o FILE]
//! [--json]`: the recommended housing of an AS568 ring for a service, with ISO 286 fits, and
//! its tolerance stack-up ([`crate::gland_design`], docs/model.md §6.2.1); `-o` writes the
//! designed gland into the o-ring template of the service as a runnable scenario.

use super::{CliError, positive_flag, write_output};
use crate::gland::GlandKind;
use crate::report::gland::{json, text};
use crate::units::Dimension;
use crate::workflow::gland::{GlandError, GlandRequest};
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
    let seat = match (&args.bore, &args.rod) {
        (Some(b), _) => positive_flag(Some(b), "bore", Dimension::LENGTH)?,
        (_, Some(r)) => positive_flag(Some(r), "rod", Dimension::LENGTH)?,
        _ => None,
    };
    let temperatures = args
        .temperature
        .as_deref()
        .map(parse_temperatures)
        .transpose()?;
    let pressure_difference = match &args.pressure_difference {
        Some(p) => positive_flag(Some(p), "pressure-difference", Dimension::PRESSURE)?
            .map(|v| (v, p.clone())),
        None => None,
    };
    let request = GlandRequest {
        size: args.size.clone(),
        kind,
        dynamic: args.dynamic,
        pressure_outside: args.pressure == Some(PressureSide::Outside),
        backup_rings: args.backup_rings,
        seat,
        fit: args.fit.clone(),
        temperatures,
        pressure_difference,
        material: args.material.clone(),
        housing: args.housing.clone(),
    };
    let designed = crate::workflow::gland::design(&request).map_err(|e| match e {
        GlandError::Input(m) => CliError::Input(flag_message(m)),
        GlandError::Internal(m) => CliError::Internal(m),
    })?;
    if let Some(path) = &args.output {
        write_scenario(path, &designed.scenario)?;
    }
    let out = if args.json {
        json(&designed.design, &designed.stack, &designed.context)?
    } else {
        text(&designed.design, &designed.stack, &designed.context)
    };
    write_output(None, out.as_bytes())
}

/// The workflow's message with its input named as the flag (`fit: …` → `--fit: …`).
fn flag_message(message: String) -> String {
    for name in ["fit", "material", "housing"] {
        if message.starts_with(&format!("{name}:")) || message.starts_with(&format!("{name} ")) {
            return format!("--{message}");
        }
    }
    message
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

fn write_scenario(path: &Path, scenario: &str) -> Result<(), CliError> {
    if path.exists() {
        return Err(input(format!(
            "-o {}: the file exists; sealsim gland never overwrites a file: give another name \
             or remove it first",
            path.display()
        )));
    }
    write_output(Some(path), scenario.as_bytes())?;
    eprintln!(
        "wrote {} (run it with `sealsim run {}`)",
        path.display(),
        path.display()
    );
    Ok(())
}
