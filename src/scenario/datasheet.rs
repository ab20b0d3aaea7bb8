//! A supplier datasheet file (`sealsim materials new`): TOML with unit strings, validated
//! once into [`crate::material::datasheet::Datasheet`] and the library compound of its class.
//!
//! ```toml
//! [datasheet]
//! name = "Acme N7001, NBR 70"
//! source = "Acme datasheet N7001 rev. 3 (2024)"
//! class = "nbr"                 # the library compound of this class is the master curve
//! hardness = 70                 # Shore A
//! t10 = "-28 C"                 # TR-10 (or: glass_transition = "-35 C")
//! thermal_expansion = "2.3e-4 1/K"   # optional: the rubbery CTE (else the class's)
//!
//! [[datasheet.compression_set]] # ASTM D395 B / ISO 815-1, one to three readings
//! time = "70 h"
//! temperature = "100 C"
//! set = "18 %"
//! ```

use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::library;
use super::raw::{Quantity, RawQuantity};
use super::text::read;
use crate::material::Material;
use crate::material::datasheet::{Datasheet, LowTemperature, SetPoint};
use crate::units::Dimension;
use serde::Deserialize;
use std::path::Path;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    datasheet: Spanned<RawDatasheet>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDatasheet {
    name: Option<String>,
    source: Option<String>,
    class: Spanned<String>,
    hardness: Option<Quantity>,
    t10: Option<Quantity>,
    glass_transition: Option<Quantity>,
    /// The rubbery linear CTE, when the datasheet gives one.
    thermal_expansion: Option<Quantity>,
    #[serde(default)]
    compression_set: Vec<Spanned<RawSet>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSet {
    time: Option<Quantity>,
    temperature: Option<Quantity>,
    set: Option<Quantity>,
}

const HARDNESS: Field = field(
    "datasheet.hardness",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(30.0, 95.0),
);
const SET_TIME: Field = field(
    "datasheet.compression_set.time",
    Dimension::TIME,
    "s",
    Bound::Range(3600.0, 1e9),
);
const SET: Field = field(
    "datasheet.compression_set.set",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);

/// The rubbery linear CTE a datasheet may give (elastomers: about 1e-4 to 3e-4 1/K).
const THERMAL_EXPANSION: Field = field(
    "datasheet.thermal_expansion",
    Dimension::THERMAL_EXPANSION,
    "1/K",
    Bound::Range(1e-5, 1e-3),
);

/// The most readings a datasheet may give.
const MAX_READINGS: usize = 3;

/// A validated datasheet file: the datasheet and its class's library compound (id, compound).
#[derive(Debug, Clone)]
pub struct DatasheetFile {
    pub datasheet: Datasheet,
    pub class_id: &'static str,
    pub class: Material,
    /// The datasheet's rubbery linear CTE \[1/K\] (`thermal_expansion`); `None`: the class's.
    pub thermal_expansion: Option<f64>,
}

/// Half the last printed digit of a written fraction (`"18 %"` → 0.005, `0.185` → 0.0005).
fn resolution(raw: &RawQuantity) -> f64 {
    let (number, scale) = match raw {
        RawQuantity::Number(v) => (format!("{v}"), 1.0),
        RawQuantity::Text(text) => {
            let number = text
                .split_whitespace()
                .next()
                .unwrap_or("")
                .trim_end_matches('%');
            let scale = if text.contains('%') { 0.01 } else { 1.0 };
            (number.to_owned(), scale)
        }
    };
    let decimals = number.split_once('.').map_or(0, |(_, d)| {
        d.chars().take_while(char::is_ascii_digit).count()
    });
    0.5 * 10f64.powi(-(decimals as i32)) * scale
}

impl DatasheetFile {
    /// Reads and validates `path`.
    pub fn load(path: &Path) -> Result<DatasheetFile, ScenarioError> {
        let text = read(path)?;
        let source = Source { path, text: &text };
        let raw: RawFile = source.deserialize()?;
        let table = raw.datasheet.span();
        let d = raw.datasheet.into_inner();
        let class_name = d.class.get_ref().to_ascii_lowercase();
        let class_id = library::ids()
            .find(|id| crate::permeation::family_of(id) == Some(class_name.as_str()))
            .ok_or_else(|| {
                let known: Vec<&str> = library::ids()
                    .filter_map(crate::permeation::family_of)
                    .collect();
                source.error(
                    d.class.span(),
                    "datasheet.class",
                    format!(
                        "no library compound of class {:?}; one of {}",
                        d.class.get_ref(),
                        known.join(", ")
                    ),
                )
            })?;
        let class = library::get(class_id)
            .map_err(|e| source.error(d.class.span(), "datasheet.class", e.to_string()))?
            .load()?;
        let hardness = source.required(
            &d.hardness,
            &HARDNESS,
            table.clone(),
            "(Shore A, e.g. hardness = 70)",
        )?;
        let low_temperature = match (&d.t10, &d.glass_transition) {
            (Some(t), None) => {
                LowTemperature::T10(source.absolute_temperature(t, "datasheet.t10")?)
            }
            (None, Some(t)) => LowTemperature::GlassTransition(
                source.absolute_temperature(t, "datasheet.glass_transition")?,
            ),
            (Some(t), Some(_)) => {
                return Err(source.error(
                    t.span(),
                    "datasheet.t10",
                    "give t10 or glass_transition, not both (t10 is matched; T_g follows)",
                ));
            }
            (None, None) => {
                return Err(source.error(
                    table,
                    "datasheet.t10",
                    "missing key `t10`: the TR-10 of the datasheet (e.g. t10 = \"-28 C\"), or \
                     glass_transition = \"-35 C\"",
                ));
            }
        };
        if d.compression_set.is_empty() || d.compression_set.len() > MAX_READINGS {
            return Err(source.error(
                table,
                "datasheet.compression_set",
                format!(
                    "give one to {MAX_READINGS} [[datasheet.compression_set]] readings (time, \
                     temperature, set), got {}",
                    d.compression_set.len()
                ),
            ));
        }
        let mut compression_set = Vec::new();
        for reading in &d.compression_set {
            let span = reading.span();
            let r = reading.get_ref();
            let time =
                source.required(&r.time, &SET_TIME, span.clone(), "(e.g. time = \"70 h\")")?;
            let Some(t) = &r.temperature else {
                return Err(source.error(
                    span,
                    "datasheet.compression_set.temperature",
                    "missing key `temperature` (e.g. temperature = \"100 C\")",
                ));
            };
            let temperature =
                source.absolute_temperature(t, "datasheet.compression_set.temperature")?;
            let set = source.required(&r.set, &SET, span.clone(), "(e.g. set = \"18 %\")")?;
            let resolution = r.set.as_ref().map_or(0.005, |q| resolution(q.get_ref()));
            compression_set.push(SetPoint {
                time,
                temperature,
                set,
                resolution,
            });
        }
        let thermal_expansion = d
            .thermal_expansion
            .as_ref()
            .map(|q| source.quantity(q, &THERMAL_EXPANSION))
            .transpose()?;
        let name = d.name.unwrap_or_else(|| source.file_stem());
        Ok(DatasheetFile {
            datasheet: Datasheet {
                source: d
                    .source
                    .unwrap_or_else(|| format!("datasheet {name} (no source given)")),
                name,
                hardness,
                low_temperature,
                compression_set,
            },
            class_id,
            class,
            thermal_expansion,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reading_is_as_sure_as_its_last_digit() {
        assert_eq!(resolution(&RawQuantity::Text("18 %".into())), 0.005);
        assert!((resolution(&RawQuantity::Text("18.5 %".into())) - 0.0005).abs() < 1e-15);
        assert!((resolution(&RawQuantity::Number(0.185)) - 0.0005).abs() < 1e-15);
    }
}
