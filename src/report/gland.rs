//! `sealsim gland`: the designed housing and its stack-up table as text and JSON
//! ([`crate::gland_design`]; docs/model.md §6.2.1). Lengths in mm (and inch for the table's
//! own values), ratios in %.

use super::ReportError;
use crate::gland::GlandKind;
use crate::gland_design::{Design, INCH, Limits, Quantity, Row, StackUp};
use serde_json::{Value, json};

pub use crate::workflow::gland::Context;

fn mm(v: f64) -> String {
    format!("{:.3}", v * 1e3)
}

fn range_mm(l: Limits) -> String {
    format!("{} … {} mm", mm(l.min), mm(l.max))
}

fn celsius(k: f64) -> String {
    let c = k - 273.15;
    let s = format!("{c:.1}");
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// A quantity's value as printed: % with two decimals for ratios, mm with three for lengths.
fn value(q: Quantity, v: f64) -> String {
    if q.is_ratio() {
        format!("{:.2} %", v * 100.0)
    } else {
        format!("{} mm", mm(v))
    }
}

fn service_name(design: &Design) -> String {
    let s = design.service;
    let mut text = match s.kind {
        GlandKind::Face if s.pressure_outside => "face gland, pressure outside".to_owned(),
        GlandKind::Face => "face gland, pressure inside".to_owned(),
        kind => format!(
            "{} gland, {}",
            kind.name(),
            if s.dynamic {
                "dynamic (reciprocating)"
            } else {
                "static"
            }
        ),
    };
    if s.kind != GlandKind::Face {
        text += &format!(", {} back-up ring(s)", s.backup_rings);
    }
    text
}

/// The seat's name and the mate's.
fn names(kind: GlandKind, pressure_outside: bool) -> (&'static str, &'static str, &'static str) {
    match kind {
        GlandKind::Piston => ("bore", "piston", "groove diameter"),
        GlandKind::Rod => ("rod", "housing bore", "groove diameter"),
        GlandKind::Face if pressure_outside => ("groove inner diameter", "", ""),
        GlandKind::Face => ("groove outer diameter", "", ""),
    }
}

/// The design and the stack-up, readable.
pub fn text(design: &Design, stack: &StackUp, ctx: &Context) -> String {
    let r = &design.ring;
    let h = &design.housing;
    let row = &design.row;
    let (seat_name, mate_name, groove_name) =
        names(design.service.kind, design.service.pressure_outside);
    let mut out = format!(
        "gland design      {} in a {}\n\
         ring              ID {} ± {} mm, cross-section {} ± {} mm\n\
         table             row {} in: {}\n",
        ctx.size,
        service_name(design),
        mm(r.inner_diameter),
        mm(r.inner_diameter_tolerance),
        mm(r.cross_section),
        mm(r.cross_section_tolerance),
        row.cross_section,
        design.source
    );
    let class = |hole: bool| {
        if hole {
            design.fit.hole.name()
        } else {
            design.fit.shaft.name()
        }
    };
    if let Some(seat) = h.seat {
        let (seat_class, mate_class) = match design.service.kind {
            GlandKind::Piston => (class(true), class(false)),
            GlandKind::Rod => (class(false), class(true)),
            GlandKind::Face if design.service.pressure_outside => (class(false), String::new()),
            GlandKind::Face => (class(true), String::new()),
        };
        let origin = match (design.service.kind, design.paired) {
            (GlandKind::Piston, true) => "; the ring's AS568 nominal OD",
            (GlandKind::Rod, true) => "; the ring's AS568 nominal ID",
            (GlandKind::Face, _) if design.service.pressure_outside => {
                "; 2 % over the ring's ID (assumed)"
            }
            (GlandKind::Face, _) => "; 1 % under the ring's OD (assumed)",
            _ => "; as given",
        };
        out += &format!(
            "{:<18}{} mm {} ({:.4} in{}): {}\n",
            seat_name,
            mm(h.seat_nominal),
            seat_class,
            h.seat_nominal / INCH,
            origin,
            range_mm(seat)
        );
        if let Some(mate) = h.mate {
            out += &format!(
                "{:<18}{} mm {}: {}\n",
                mate_name,
                mm(h.seat_nominal),
                mate_class,
                range_mm(mate)
            );
        }
    }
    if let Some(g) = h.groove_diameter {
        out += &format!("{:<18}{}\n", groove_name, range_mm(g));
    }
    let depth_name = if design.service.kind == GlandKind::Face {
        "groove depth"
    } else {
        "gland depth L"
    };
    out += &format!(
        "{:<18}{} ({}–{} in)\n",
        depth_name,
        range_mm(h.depth),
        row.depth.0,
        row.depth.1
    );
    for (n, w) in row.width.iter().enumerate() {
        if let Some(w) = w {
            let label = if design.service.kind == GlandKind::Face {
                "liquids".to_owned()
            } else {
                format!("{n} back-up ring(s)")
            };
            out += &format!(
                "{:<18}{} … {} mm ({}–{} in), {}{}\n",
                if n == 0 { "groove width G" } else { "" },
                mm(w.0 * INCH),
                mm(w.1 * INCH),
                w.0,
                w.1,
                label,
                if usize::from(design.service.backup_rings) == n {
                    "  <- designed"
                } else {
                    ""
                }
            );
        }
    }
    if let Some(w) = row.width_gas {
        out += &format!(
            "{:<18}{} … {} mm ({}–{} in), gases and vacuum\n",
            "",
            mm(w.0 * INCH),
            mm(w.1 * INCH),
            w.0,
            w.1
        );
    }
    out += &format!(
        "{:<18}{} … {} mm ({}–{} in)\n",
        "groove radius",
        mm(row.radius.0 * INCH),
        mm(row.radius.1 * INCH),
        row.radius.0,
        row.radius.1
    );
    out += &stack_text(design, stack, ctx);
    out
}

/// The stack-up table, the limits' sources and the back-up ring advice.
fn stack_text(design: &Design, stack: &StackUp, ctx: &Context) -> String {
    let mut out = String::new();
    out += &format!(
        "\nstack-up          23 °C: nominal and worst case over every tolerance limit; service \
         {} … {} °C: worst case\n                  ring CTE {} 1/K ({}), housing CTE {} 1/K \
         ({})\n",
        celsius(ctx.temperatures.0),
        celsius(ctx.temperatures.1),
        ctx.ring_expansion,
        ctx.material,
        ctx.housing_expansion,
        ctx.housing
    );
    out += &format!(
        "{:<20} {:>11} {:>11} {:>11} {:>11} {:>11}  {:<5} limit\n",
        "quantity", "nominal", "23 °C min", "23 °C max", "service min", "service max", "check"
    );
    for row in &stack.rows {
        let q = row.quantity;
        out += &format!(
            "{:<20} {:>11} {:>11} {:>11} {:>11} {:>11}  {:<5} {}\n",
            q.name(),
            value(q, row.nominal),
            value(q, row.assembly.0),
            value(q, row.assembly.1),
            value(q, row.service.0),
            value(q, row.service.1),
            if row.ok { "ok" } else { "WARN" },
            row.limit_text
        );
    }
    out += "\nmin/max: the worst-case combination for each quantity separately (for squeeze and \
            fill the max is the maximum material condition — largest cord, smallest gland — \
            and the min the least material condition).\nlimits:\n";
    for row in &stack.rows {
        out += &format!("  {:<20} {}\n", row.quantity.name(), row.source);
    }
    match &stack.backup {
        None => out += "\nback-up rings     none: the flanges meet metal to metal (no gap)\n",
        Some(b) => {
            let advice = match b.needed {
                Some(0) => "none needed".to_owned(),
                Some(n) => format!("{n} needed"),
                None => "none suffices: reduce the clearance or the pressure".to_owned(),
            };
            out += &format!(
                "\nback-up rings     {} at {} bar and a largest diametral clearance of {} mm \
                 ({} Shore A; the extrusion chart, docs/model.md §6.3); designed: {}\n",
                advice,
                format_args!("{:.1}", ctx.pressure / 1e5),
                mm(b.clearance),
                ctx.hardness,
                design.service.backup_rings
            );
        }
    }
    out
}

fn limits_json(l: Limits) -> Value {
    json!({ "min_mm": l.min * 1e3, "max_mm": l.max * 1e3 })
}

fn row_json(row: &Row) -> Value {
    let scale = if row.quantity.is_ratio() { 1.0 } else { 1e3 };
    let unit = if row.quantity.is_ratio() { "1" } else { "mm" };
    json!({
        "quantity": row.quantity.key(),
        "unit": unit,
        "nominal": row.nominal * scale,
        "assembly_min": row.assembly.0 * scale,
        "assembly_max": row.assembly.1 * scale,
        "service_min": row.service.0 * scale,
        "service_max": row.service.1 * scale,
        "limit_min": row.limit.0.map(|v| v * scale),
        "limit_max": row.limit.1.map(|v| v * scale),
        "limit": row.limit_text,
        "source": row.source,
        "ok": row.ok,
    })
}

/// The design and the stack-up as a JSON object.
pub fn json(design: &Design, stack: &StackUp, ctx: &Context) -> Result<String, ReportError> {
    let h = &design.housing;
    let row = &design.row;
    let widths: Vec<Value> = row
        .width
        .iter()
        .map(|w| w.map_or(Value::Null, |w| json!({"min_in": w.0, "max_in": w.1, "min_mm": w.0 * 25.4, "max_mm": w.1 * 25.4})))
        .collect();
    let value = json!({
        "size": ctx.size,
        "service": design.service.kind.name(),
        "dynamic": design.service.dynamic,
        "pressure_outside": design.service.pressure_outside,
        "backup_rings": design.service.backup_rings,
        "fit": design.fit.name(),
        "table": {
            "source": design.source,
            "cross_section_in": row.cross_section,
            "depth_in": [row.depth.0, row.depth.1],
            "squeeze_in": [row.squeeze.0, row.squeeze.1],
            "squeeze_percent": [row.squeeze_percent.0, row.squeeze_percent.1],
            "diametral_clearance_in": row.clearance.map(|c| vec![c.0, c.1]),
            "width_in": widths,
            "width_gas_in": row.width_gas.map(|w| vec![w.0, w.1]),
            "radius_in": [row.radius.0, row.radius.1],
        },
        "ring": {
            "inner_diameter_mm": design.ring.inner_diameter * 1e3,
            "inner_diameter_tolerance_mm": design.ring.inner_diameter_tolerance * 1e3,
            "cross_section_mm": design.ring.cross_section * 1e3,
            "cross_section_tolerance_mm": design.ring.cross_section_tolerance * 1e3,
        },
        "housing": {
            "seat_nominal_mm": h.seat_nominal * 1e3,
            "seat_nominal_in": h.seat_nominal / INCH,
            "seat_from_as568_pairing": design.paired,
            "seat": h.seat.map(limits_json),
            "mate": h.mate.map(limits_json),
            "groove_diameter": h.groove_diameter.map(limits_json),
            "depth": limits_json(h.depth),
            "groove_width": limits_json(h.width),
        },
        "conditions": {
            "temperature_min_c": ctx.temperatures.0 - 273.15,
            "temperature_max_c": ctx.temperatures.1 - 273.15,
            "pressure_difference_bar": ctx.pressure / 1e5,
            "hardness_shore_a": ctx.hardness,
            "ring_expansion_per_k": ctx.ring_expansion,
            "material": ctx.material,
            "housing_expansion_per_k": ctx.housing_expansion,
            "housing": ctx.housing,
        },
        "stack_up": stack.rows.iter().map(row_json).collect::<Vec<_>>(),
        "backup_rings_needed": stack.backup.as_ref().map(|b| b.needed),
        "largest_diametral_clearance_mm": stack.backup.as_ref().map(|b| b.clearance * 1e3),
    });
    serde_json::to_string_pretty(&value)
        .map(|s| s + "\n")
        .map_err(|e| ReportError::Csv(e.to_string()))
}
