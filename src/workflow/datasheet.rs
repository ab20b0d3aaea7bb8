//! `sealsim materials new`: a datasheet's compound with the provenance of every figure and a
//! summary (docs/model.md §5.4).

use crate::material::datasheet::{self, Conversion, DatasheetError, LowTemperature, gent_modulus};
use crate::material::{AgeingBasis, Material};
use crate::scenario::datasheet::DatasheetFile;
use crate::units::human as human_sig;

/// 3 significant digits.
fn human(v: f64) -> String {
    human_sig(v, 3)
}

/// The class's Ea band \[J/mol\]: the two sides of its ageing law (one value when one-sided).
pub fn class_band(class: &Material) -> Option<(f64, f64)> {
    class.ageing.map(|a| {
        (
            a.activation_energy.min(a.activation_energy_above),
            a.activation_energy.max(a.activation_energy_above),
        )
    })
}

/// The compound of `file` and its summary (text).
pub fn compound(file: &DatasheetFile) -> Result<(Material, String), DatasheetError> {
    let sheet = &file.datasheet;
    let band = class_band(&file.class).ok_or(DatasheetError::NoClassActivationEnergy)?;
    let (mut m, c) = datasheet::from_datasheet(&file.class, band, sheet)?;
    if let Some(alpha) = file.thermal_expansion {
        m.thermal_expansion = Some(alpha);
    }
    let class_id = file.class_id;
    let low = match sheet.low_temperature {
        LowTemperature::T10(t) => format!("TR-10 = {}", celsius(t)),
        LowTemperature::GlassTransition(t) => format!("T_g = {}", celsius(t)),
    };
    let curve = format!(
        "{class_id}'s master curve (its provenance: {}) moved by {:+.2} K to the datasheet's {low} \
         and scaled ×{:.4} to E(3 s, 23 °C) = {} MPa, Gent's modulus of {} Shore A (A.N. Gent \
         1958, the form the library was calibrated with); datasheet: {}",
        file.class.provenance_of("prony").unwrap_or("not stated"),
        c.shift,
        c.scale,
        human(gent_modulus(sheet.hardness) / 1e6),
        sheet.hardness,
        sheet.source
    );
    let readings: Vec<String> = c.points.iter().map(reading).collect();
    let ea = &c.bands.activation_energy;
    let ageing = format!(
        "k(T) from the datasheet's compression set (ASTM D395 B / ISO 815-1): {}; Ea = {} kJ/mol \
         (band {}–{} kJ/mol: {}); crosslinking r of the class; datasheet: {}",
        readings.join("; "),
        human(ea.value / 1e3),
        human(ea.low / 1e3),
        human(ea.high / 1e3),
        ea.basis,
        sheet.source
    );
    let moved = format!(
        "{class_id}'s, moved by {:+.2} K with the master curve; datasheet: {}",
        c.shift, sheet.source
    );
    m.provenance = vec![
        ("poisson_ratio".into(), format!("{class_id}'s")),
        ("long_term_modulus".into(), curve.clone()),
        ("prony".into(), curve),
        ("shift".into(), moved.clone()),
        ("glass_transition".into(), moved),
        (
            "thermal_expansion".into(),
            match file.thermal_expansion {
                Some(_) => format!("datasheet: {}", sheet.source),
                None => format!("{class_id}'s (class value)"),
            },
        ),
        (
            "glassy_thermal_expansion".into(),
            format!("{class_id}'s (class value)"),
        ),
        ("ageing".into(), ageing),
    ];
    m.provenance.retain(|(key, _)| {
        key != "glassy_thermal_expansion" || m.glassy_thermal_expansion.is_some()
    });
    m.ageing_basis = Some(AgeingBasis {
        property: "compression set (supplier datasheet)".into(),
        criterion: "the datasheet's readings, less their viscoelastic part".into(),
        medium: Some(crate::material::AgeingMedium::Air),
        source: Some(format!(
            "{} (Ea band {}–{} kJ/mol)",
            sheet.source,
            human(ea.low / 1e3),
            human(ea.high / 1e3)
        )),
    });
    m.class = file.class.class.clone();
    let text = summary(file, &m, &c);
    Ok((m, text))
}

/// `k` \[K\] in °C to a tenth.
fn celsius(k: f64) -> String {
    format!("{:.1} °C", k - 273.15)
}

/// One reading: its set, the viscoelastic part (30 min at 23 °C), the chemical set and k.
fn reading((p, ve, chem, k): &(datasheet::SetPoint, f64, f64, f64)) -> String {
    format!(
        "{} h at {}: {:.1} % = viscoelastic {:.1} % + chemical {:.1} % → k = {} 1/s",
        human(p.time / 3600.0),
        celsius(p.temperature),
        p.set * 100.0,
        ve * 100.0,
        chem * 100.0,
        human(*k)
    )
}

fn summary(file: &DatasheetFile, m: &Material, c: &Conversion) -> String {
    let sheet = &file.datasheet;
    let t10 = m.low_temperature_limit();
    let room_modulus = datasheet::hardness_modulus(m);
    let mut out = format!(
        "compound       {} — from the datasheet ({}), on {}'s master curve; a user compound: \
         the curve's shape is the class's, not measured\n",
        m.name, sheet.source, file.class_id
    );
    out += &format!(
        "T10            {} (class curve moved {:+.2} K)\n",
        t10.map_or("none".into(), celsius),
        c.shift
    );
    out += &format!(
        "E(3 s, 23 °C)  {} MPa (Gent, {} Shore A; moduli ×{:.4})\n",
        human(room_modulus / 1e6),
        sheet.hardness,
        c.scale
    );
    for point in &c.points {
        out += &format!("set reading    {}\n", reading(point));
    }
    let ea = &c.bands.activation_energy;
    out += &format!(
        "Ea             {} kJ/mol, band {}–{} kJ/mol ({})\n",
        human(ea.value / 1e3),
        human(ea.low / 1e3),
        human(ea.high / 1e3),
        ea.basis
    );
    if let Some(a) = m.ageing {
        let rate = &c.bands.rate;
        out += &format!(
            "k at {:.1} °C   {} 1/s (the anchor: where the readings pin k), band {}–{} 1/s; \
             chemical t50 at 100 °C: {} h\n",
            a.reference_temperature - 273.15,
            human(a.rate),
            human(rate.low),
            human(rate.high),
            human(std::f64::consts::LN_2 / a.rate_at(373.15) / 3600.0)
        );
    }
    out += &format!(
        "study          [vary] \"ageing.activation_energy\" = \"band\"   # Ea uniform over \
         {}–{} kJ/mol (the compound file's [material.bands]), about the anchor\n",
        human(ea.low / 1e3),
        human(ea.high / 1e3)
    );
    out
}
