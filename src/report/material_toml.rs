//! A [`Material`] written as a material TOML file (the schema in
//! `crates/sealsim-core/src/material/compound.rs`), e.g. the output of `sealsim fit-prony`.
//!
//! Quantities are written as strings in SI units with the shortest scientific form that
//! round-trips to the same `f64` (`"4e6 Pa"`, `"3.6e3 s"`, `"2.9615e2 K"`), so that reading
//! the file back gives exactly the same numbers; dimensionless numbers (Poisson's ratio, C1)
//! are bare TOML floats. Optional parts (status, shift, glass transition, thermal expansion,
//! ageing, provenance) are written only when present; `status` is omitted for
//! [`Status::User`], which is what a file without it means.

use crate::material::{Ageing, AgeingBasis, Material, Shift, Status};
use std::fmt::Write;

/// The material TOML text of `m`: one `[material]` table with its sub-tables.
///
/// A series without terms is written as the elastic `youngs_modulus`, unless the provenance
/// names `long_term_modulus` (then `long_term_modulus`, so that the provenance keys match the
/// keys present).
pub fn material_toml(m: &Material) -> String {
    let mut out = String::from("[material]\n");
    line(&mut out, "name", &string(&m.name));
    if m.status != Status::User {
        line(&mut out, "status", &string(m.status.as_str()));
    }
    line(&mut out, "poisson_ratio", &float(m.poisson_ratio));
    let terms = m.prony.terms();
    if terms.is_empty() && m.provenance_of("long_term_modulus").is_none() {
        line(
            &mut out,
            "youngs_modulus",
            &quantity(m.prony.long_term(), "Pa"),
        );
    } else {
        line(
            &mut out,
            "long_term_modulus",
            &quantity(m.prony.long_term(), "Pa"),
        );
    }
    if !terms.is_empty() {
        out.push_str("prony = [\n");
        for t in terms {
            let _ = writeln!(
                out,
                "  {{ modulus = {}, tau = {} }},",
                quantity(t.modulus, "Pa"),
                quantity(t.tau, "s")
            );
        }
        out.push_str("]\n");
    }
    if let Some(tg) = m.glass_transition {
        line(&mut out, "glass_transition", &quantity(tg, "K"));
    }
    if let Some(alpha) = m.thermal_expansion {
        line(&mut out, "thermal_expansion", &quantity(alpha, "1/K"));
    }
    if let Some(alpha) = m.glassy_thermal_expansion {
        line(
            &mut out,
            "glassy_thermal_expansion",
            &quantity(alpha, "1/K"),
        );
    }
    if let Some((lo, hi)) = m.data_reduced_time {
        line(
            &mut out,
            "data_reduced_time",
            &format!("[{}, {}]", quantity(lo, "s"), quantity(hi, "s")),
        );
    }
    if let Some((lo, hi)) = m.data_temperature {
        line(
            &mut out,
            "data_temperature",
            &format!("[{}, {}]", quantity(lo, "K"), quantity(hi, "K")),
        );
    }
    if let Some(class) = &m.class {
        line(&mut out, "class", &string(class));
    }
    match m.shift {
        Shift::None => {}
        Shift::Wlf { reference, c1, c2 } => {
            out.push_str("\n[material.shift]\n");
            line(&mut out, "kind", &string("wlf"));
            line(&mut out, "reference_temperature", &quantity(reference, "K"));
            line(&mut out, "c1", &float(c1));
            line(&mut out, "c2", &quantity(c2, "K"));
        }
        Shift::Arrhenius {
            reference,
            activation_energy,
        } => {
            out.push_str("\n[material.shift]\n");
            line(&mut out, "kind", &string("arrhenius"));
            line(&mut out, "reference_temperature", &quantity(reference, "K"));
            line(
                &mut out,
                "activation_energy",
                &quantity(activation_energy, "J/mol"),
            );
        }
    }
    if let Some(a) = m.ageing {
        out.push('\n');
        out.push_str(&ageing_toml(&a, m.ageing_basis.as_ref()));
    }
    if !m.compatibility.is_empty() {
        out.push_str("\n[material.compatibility]\n");
        for c in &m.compatibility {
            out.push_str(&format!(
                "{} = {{ rating = \"{}\", source = {} }}\n",
                c.class.key(),
                c.rating.letter(),
                string(&c.source)
            ));
        }
    }
    if !m.permeation.is_empty() {
        out.push_str("\n[material.permeation]\n");
        for p in &m.permeation {
            let mut fields = vec![format!(
                "permeability = {}",
                quantity(p.permeability, "mol/(m*s*Pa)")
            )];
            if let Some(d) = p.diffusivity {
                fields.push(format!("diffusivity = {}", quantity(d, "m^2/s")));
            }
            if let Some(source) = &p.source {
                fields.push(format!("source = {}", string(source)));
            }
            out.push_str(&format!(
                "{} = {{ {} }}\n",
                bare_or_quoted_key(&p.gas),
                fields.join(", ")
            ));
        }
    }
    if !m.bands.is_empty() {
        out.push_str("\n[material.bands]\n");
        for b in &m.bands {
            let unit = b.unit();
            out.push_str(&format!(
                "{} = {{ min = {}, max = {}, source = {} }}\n",
                bare_or_quoted_key(&b.key),
                quantity(b.min, unit),
                quantity(b.max, unit),
                string(&b.source)
            ));
        }
    }
    if !m.provenance.is_empty() {
        out.push_str("\n[material.provenance]\n");
        for (key, text) in &m.provenance {
            line(&mut out, &bare_or_quoted_key(key), &string(text));
        }
    }
    out
}

/// The `[material.ageing]` table of `a` (with `property` and `criterion` when `basis` is
/// given): Ea in J/mol, k_ref in 1/s, T_ref in K, crosslinking a bare float (docs/model.md
/// §6.5), e.g. the output of `sealsim ageing-fit --write-material-ageing`.
pub fn ageing_toml(a: &Ageing, basis: Option<&AgeingBasis>) -> String {
    let mut out = String::from("[material.ageing]\n");
    line(
        &mut out,
        "activation_energy",
        &quantity(a.activation_energy, "J/mol"),
    );
    if a.is_two_sided() {
        line(
            &mut out,
            "activation_energy_above",
            &quantity(a.activation_energy_above, "J/mol"),
        );
    }
    line(&mut out, "rate", &quantity(a.rate, "1/s"));
    line(
        &mut out,
        "reference_temperature",
        &quantity(a.reference_temperature, "K"),
    );
    line(&mut out, "crosslinking", &float(a.crosslinking));
    if let Some(b) = basis {
        line(&mut out, "property", &string(&b.property));
        line(&mut out, "criterion", &string(&b.criterion));
        if let Some(m) = b.medium {
            line(&mut out, "medium", &string(m.as_str()));
        }
        if let Some(source) = &b.source {
            line(&mut out, "source", &string(source));
        }
    }
    out
}

fn line(out: &mut String, key: &str, value: &str) {
    let _ = writeln!(out, "{key} = {value}");
}

/// `"<shortest round-trip scientific> <unit>"`, e.g. `"4e6 Pa"`.
fn quantity(value: f64, unit: &str) -> String {
    string(&format!("{value:e} {unit}"))
}

/// A TOML float: Rust's shortest round-trip form always has a `.` or an exponent (`0.5`,
/// `1.0`, `1e-7`), so it never reads back as an integer.
fn float(value: f64) -> String {
    format!("{value:?}")
}

/// A TOML basic string with `"`, `\` and control characters escaped.
fn string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{:04X}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A key as a TOML bare key when it is one (`A-Za-z0-9_-`), else quoted.
fn bare_or_quoted_key(key: &str) -> String {
    let bare = !key.is_empty()
        && key
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    if bare { key.to_string() } else { string(key) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::{Ageing, Prony, PronyTerm};

    fn fitted() -> Material {
        let terms = [
            PronyTerm {
                modulus: 6e6,
                tau: 3.6e6,
            },
            PronyTerm {
                modulus: 1.5e6,
                tau: 3600.0,
            },
        ];
        Material {
            provenance: vec![
                ("poisson_ratio".into(), "assumed".into()),
                ("prony".into(), "fitted\nby sealsim".into()),
            ],
            ..Material::user("NBR \"70\"\\test", Prony::new(4e6, &terms).unwrap(), 0.5)
        }
    }

    #[test]
    fn user_material_text() {
        let text = material_toml(&fitted());
        let expected = "[material]\n\
            name = \"NBR \\\"70\\\"\\\\test\"\n\
            poisson_ratio = 0.5\n\
            long_term_modulus = \"4e6 Pa\"\n\
            prony = [\n  \
              { modulus = \"1.5e6 Pa\", tau = \"3.6e3 s\" },\n  \
              { modulus = \"6e6 Pa\", tau = \"3.6e6 s\" },\n\
            ]\n\
            \n[material.provenance]\n\
            poisson_ratio = \"assumed\"\n\
            prony = \"fitted\\nby sealsim\"\n";
        assert_eq!(text, expected);
        // valid TOML, with the values as written
        let value: toml::Table = toml::from_str(&text).unwrap();
        let material = value["material"].as_table().unwrap();
        assert_eq!(material["name"].as_str(), Some("NBR \"70\"\\test"));
        assert_eq!(material["prony"].as_array().unwrap().len(), 2);
        assert_eq!(
            material["provenance"]["prony"].as_str(),
            Some("fitted\nby sealsim")
        );
    }

    #[test]
    fn every_optional_part_is_written() {
        let mut m = fitted();
        m.status = Status::Illustrative;
        m.shift = Shift::Wlf {
            reference: 296.15,
            c1: 8.86,
            c2: 101.6,
        };
        m.glass_transition = Some(243.15);
        m.thermal_expansion = Some(2.3e-4);
        m.glassy_thermal_expansion = Some(7.7e-5);
        m.ageing = Some(Ageing {
            activation_energy: 9e4,
            activation_energy_above: 9e4,
            rate: 1e-9,
            reference_temperature: 373.15,
            crosslinking: 0.5,
        });
        m.ageing_basis = Some(crate::material::AgeingBasis {
            property: "compression set".into(),
            criterion: "80 % \"set\"".into(),
            medium: None,
            source: None,
        });
        m.provenance.push(("odd key".into(), "x".into()));
        let text = material_toml(&m);
        for needle in [
            "status = \"illustrative\"\n",
            "glass_transition = \"2.4315e2 K\"\n",
            "thermal_expansion = \"2.3e-4 1/K\"\n",
            "glassy_thermal_expansion = \"7.7e-5 1/K\"\n",
            "[material.shift]\nkind = \"wlf\"\nreference_temperature = \"2.9615e2 K\"\nc1 = 8.86\nc2 = \"1.016e2 K\"\n",
            "[material.ageing]\nactivation_energy = \"9e4 J/mol\"\nrate = \"1e-9 1/s\"\nreference_temperature = \"3.7315e2 K\"\ncrosslinking = 0.5\nproperty = \"compression set\"\ncriterion = \"80 % \\\"set\\\"\"\n",
            "\"odd key\" = \"x\"\n",
        ] {
            assert!(text.contains(needle), "missing {needle:?} in\n{text}");
        }
        toml::from_str::<toml::Table>(&text).unwrap();
        m.shift = Shift::Arrhenius {
            reference: 296.15,
            activation_energy: 9e4,
        };
        let text = material_toml(&m);
        assert!(text.contains("kind = \"arrhenius\"\nreference_temperature = \"2.9615e2 K\"\nactivation_energy = \"9e4 J/mol\"\n"));
    }

    #[test]
    fn elastic_materials_use_youngs_modulus() {
        let m = Material::elastic("rubber", 1e7, 0.5).unwrap();
        let text = material_toml(&m);
        assert!(
            text.contains("youngs_modulus = \"1e7 Pa\"\n") && !text.contains("prony"),
            "{text}"
        );
        let mut m = m;
        m.provenance
            .push(("long_term_modulus".into(), "measured".into()));
        assert!(material_toml(&m).contains("long_term_modulus = \"1e7 Pa\"\n"));
    }

    #[test]
    fn quantities_round_trip_through_the_unit_parser() {
        use crate::units::{Dimension, parse_quantity, parse_temperature};
        for v in [0.1 + 0.2, 1.0 / 3.0, 6.02214076e23, 4.9e-324, 2.5e-11] {
            let text = quantity(v, "Pa");
            let inner = text.trim_matches('"');
            assert_eq!(parse_quantity(inner, Dimension::PRESSURE), Ok(v));
        }
        let t = quantity(296.15, "K");
        assert_eq!(parse_temperature(t.trim_matches('"')), Ok(296.15));
        let e = quantity(90_123.456, "J/mol");
        assert_eq!(
            parse_quantity(e.trim_matches('"'), Dimension::MOLAR_ENERGY),
            Ok(90_123.456)
        );
    }
}
