//! `sealsim gland` as a library call (the command line and Python's `sealsim.gland`): the
//! recommended housing of an AS568 ring for a service with its ISO 286 fits and tolerance
//! stack-up ([`crate::gland_design`], docs/model.md §6.2.1), and the service's o-ring template
//! with the designed gland as a runnable scenario.

use crate::gland::{GlandKind, Housing};
use crate::gland_design::{self, Conditions, Design, INCH, Service, StackUp};
use crate::scenario::{as568, library, templates};
use crate::units::{Dimension, parse_quantity};

/// What to design, in SI (flag-level checks — which flag belongs to which service — are the
/// caller's).
#[derive(Debug, Clone)]
pub struct GlandRequest {
    /// The ring, an AS568 size (`AS568-214`, `214`).
    pub size: String,
    pub kind: GlandKind,
    /// Piston and rod glands: reciprocating (the dynamic table).
    pub dynamic: bool,
    /// Face glands: the pressure is outside (vacuum; the ring's ID is located).
    pub pressure_outside: bool,
    /// Back-up rings on the low-pressure side (0–2).
    pub backup_rings: u8,
    /// The bore of a piston gland or the rod of a rod gland \[m\] (`None`: the ring's AS568
    /// nominal OD or ID).
    pub seat: Option<f64>,
    /// The ISO 286 fit `HOLE/SHAFT`, e.g. `H8/f7`.
    pub fit: String,
    /// Service temperatures (min, max) \[K\] (`None`: 23 °C and the template's).
    pub temperatures: Option<(f64, f64)>,
    /// The pressure difference \[Pa\] and its text as the user typed it (written into the
    /// scenario); `None`: the template's.
    pub pressure_difference: Option<(f64, String)>,
    /// The ring's compound, a library id.
    pub material: String,
    /// The housing's material (its CTE), [`Housing::from_name`].
    pub housing: String,
}

/// What the report names besides the design: the size, the temperatures, the conditions.
#[derive(Debug, Clone)]
pub struct Context {
    /// `AS568-214`.
    pub size: String,
    /// Service temperatures \[K\].
    pub temperatures: (f64, f64),
    /// Pressure difference \[Pa\].
    pub pressure: f64,
    /// Hardness \[Shore A\] and where it came from.
    pub hardness: f64,
    /// Ring CTE \[1/K\] and its compound.
    pub ring_expansion: f64,
    pub material: String,
    /// Housing CTE \[1/K\] and its name.
    pub housing_expansion: f64,
    pub housing: String,
}

/// A designed gland: the design, its stack-up, the context the reports print and the runnable
/// scenario's TOML.
#[derive(Debug, Clone)]
pub struct GlandDesign {
    pub design: Design,
    pub stack: StackUp,
    pub context: Context,
    /// The service's o-ring template with the designed `[seal]` table.
    pub scenario: String,
}

/// Why a gland cannot be designed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GlandError {
    /// An input the user must fix (the message names it).
    Input(String),
    /// A shipped table or template is broken.
    Internal(String),
}

impl std::fmt::Display for GlandError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GlandError::Input(m) | GlandError::Internal(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for GlandError {}

fn input(msg: impl Into<String>) -> GlandError {
    GlandError::Input(msg.into())
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

/// Designs the gland of `request`: the table row, the fits, the stack-up at the service
/// temperatures and pressure, and the runnable scenario.
pub fn design(request: &GlandRequest) -> Result<GlandDesign, GlandError> {
    let kind = request.kind;
    let size = as568::lookup(&request.size).map_err(|e| match e {
        as568::LookupError::Table(t) => GlandError::Internal(t.to_string()),
        other => input(format!("{other} (`sealsim sizes` lists them)")),
    })?;
    let fit = crate::fits::Fit::parse(&request.fit).map_err(|e| input(format!("fit: {e}")))?;
    let template = templates::template(template_name(kind))
        .ok_or_else(|| GlandError::Internal("an o-ring template is missing".into()))?;
    let template_t = template_quantity(
        template.text,
        "environment",
        "temperature",
        Dimension::TEMPERATURE,
    )
    .ok_or_else(|| GlandError::Internal("the template has no temperature".into()))?;
    let temperatures = request.temperatures.unwrap_or((
        template_t.min(gland_design::ASSEMBLY_TEMPERATURE),
        template_t.max(gland_design::ASSEMBLY_TEMPERATURE),
    ));
    let pressure = match &request.pressure_difference {
        Some((p, _)) => *p,
        None => template_quantity(
            template.text,
            "fluid",
            "pressure_difference",
            Dimension::PRESSURE,
        )
        .ok_or_else(|| GlandError::Internal("the template has no pressure".into()))?,
    };
    let material = library::get(&request.material)
        .map_err(|e| input(format!("material: {e}")))?
        .load()
        .map_err(|e| input(format!("material: {e}")))?;
    let ring_expansion = material.thermal_expansion.ok_or_else(|| {
        input(format!(
            "material {}: the compound has no thermal_expansion; choose another",
            request.material
        ))
    })?;
    // the grade in the compound's id ("nbr-70" → 70 Shore A)
    let hardness = request
        .material
        .rsplit('-')
        .next()
        .and_then(|g| g.parse::<f64>().ok())
        .unwrap_or(70.0);
    let housing = Housing::from_name(&request.housing).ok_or_else(|| {
        input(format!(
            "housing {:?}: expected one of {}",
            request.housing,
            Housing::ALL.map(Housing::name).join(", ")
        ))
    })?;
    let service = Service {
        kind,
        dynamic: request.dynamic,
        pressure_outside: request.pressure_outside,
        backup_rings: request.backup_rings,
    };
    let nominal =
        gland_design::as568_nominal(size.id_in, size.cs_in).map(|(id, od)| (id * INCH, od * INCH));
    let design = gland_design::design(size.ring(), nominal, service, fit, request.seat)
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
    let context = Context {
        size: size.name(),
        temperatures,
        pressure,
        hardness,
        ring_expansion,
        material: request.material.clone(),
        housing_expansion: housing.expansion(),
        housing: housing.name().to_owned(),
    };
    let scenario = scenario_text(template.text, &design, &stack, &context, request);
    refuse_infeasible(&scenario, &context.size)?;
    Ok(GlandDesign {
        design,
        stack,
        context,
        scenario,
    })
}

/// The designed gland checked as a scenario: a ring that cannot be assembled in it (larger
/// than its bore, a fill above 100 % at maximum material condition, the wrong wall) is refused
/// with the scenario validator's reason and nearest valid sizes (docs/model.md §6.2), so that
/// the designer never proposes what `run` refuses.
fn refuse_infeasible(scenario: &str, size: &str) -> Result<(), GlandError> {
    use crate::scenario::{Scenario, ScenarioError};
    match Scenario::from_str(scenario, std::path::Path::new("<designed gland>")) {
        Ok(_) => Ok(()),
        Err(ScenarioError::Invalid { key, message, .. }) => Err(input(format!(
            "{size}: the designed gland cannot be assembled ({}): {message}",
            key.as_deref().unwrap_or("seal")
        ))),
        Err(other) => Err(GlandError::Internal(format!(
            "the designed gland's scenario does not load: {other}"
        ))),
    }
}

/// A length for the scenario file, in mm to 0.1 µm.
fn mm(v: f64) -> String {
    let s = format!("{:.4}", v * 1e3);
    format!("\"{} mm\"", s.trim_end_matches('0').trim_end_matches('.'))
}

/// The `[seal]` table of the designed gland (nominal dimensions; the largest clearance).
fn seal_table(design: &Design, stack: &StackUp, ctx: &Context, request: &GlandRequest) -> String {
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
    if request.housing != "steel" {
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
    stack: &StackUp,
    ctx: &Context,
    request: &GlandRequest,
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
                out += &seal_table(design, stack, ctx, request);
                out.push('\n');
                continue;
            }
            in_seal = false;
        }
        if in_seal {
            continue;
        }
        let key = trimmed.split('=').next().unwrap_or_default().trim();
        if section.is_empty() && key == "name" {
            let name = format!(
                "{} {} gland, {}, designed by sealsim gland",
                ctx.size,
                design.service.kind.name(),
                request.material
            );
            out += &format!("name = {}\n", toml::Value::String(name));
            continue;
        }
        if section == "material" && key == "library" {
            out += &format!("library = \"{}\"\n", request.material);
            continue;
        }
        if let Some((_, p)) = request
            .pressure_difference
            .as_ref()
            .filter(|_| section == "fluid" && key == "pressure_difference")
        {
            let quoted = toml::Value::String(p.clone()).to_string();
            out += &format!("pressure_difference = {quoted}\n");
            continue;
        }
        if let Some((lo, hi)) = request.temperatures {
            // the service range the stack-up was checked over: the run at its hottest (the
            // conservative end for ageing and set), the shutdown check at its coldest
            if section == "environment" && key == "temperature" {
                out += &format!(
                    "temperature = {}  # the hottest of the designed service range\n",
                    celsius(hi)
                );
                continue;
            }
            if trimmed.starts_with("[failure]") && lo < gland_design::ASSEMBLY_TEMPERATURE {
                out += line;
                out += &format!(
                    "\nshutdown_temperature = {}  # the coldest of the designed service range\n",
                    celsius(lo)
                );
                continue;
            }
        }
        out += line;
        out.push('\n');
    }
    out
}

/// A temperature for the scenario file, in °C to 0.01 K.
fn celsius(t: f64) -> String {
    let s = format!("{:.2}", t - 273.15);
    format!("\"{} C\"", s.trim_end_matches('0').trim_end_matches('.'))
}
