//! Units of choice for what people read (`--units si|metric|us`, issue 42): the run summary, the
//! HTML report body and the history CSV's columns. The physics, the JSON summaries and
//! `--units si` stay SI; this module is the one home of the output conversions.
//!
//! | quantity | si (CSV / summary) | metric | us |
//! |---|---|---|---|
//! | length | m / mm | mm | in |
//! | pressure | Pa / MPa | bar | psi |
//! | temperature | K / °C | °C | °F |
//! | force per length | N/m / N/mm | N/mm | lbf/in |
//! | liquid volume flow | m³/s | mL/min | cc/min |
//! | volume | m³ | mL | cc |
//! | gas throughput (pV flow) | Pa·m³/s | mbar·L/s | atm·cc/s |
//!
//! Factors, all exact by definition (NIST Special Publication 811, 2008 edition, Appendix B;
//! the inch and the pound of the 1959 international yard and pound agreement): 1 in = 0.0254 m;
//! 1 lbf = 4.4482216152605 N (the avoirdupois pound, 0.45359237 kg, under standard gravity
//! 9.80665 m/s²); 1 psi = 1 lbf/in² = 6894.757293168 Pa; 1 bar = 10⁵ Pa; 1 atm = 101325 Pa;
//! 1 mL = 1 cc = 10⁻⁶ m³; 1 mbar·L/s = 0.1 Pa·m³/s; 1 atm·cc/s = 0.101325 Pa·m³/s;
//! T\[°C\] = T\[K\] − 273.15; T\[°F\] = T\[K\] × 9/5 − 459.67. The tests check each against the
//! input parser ([`crate::units`]), so that a file written here reads back to its SI values.
//!
//! A CSV column carries its unit in its name, `stem_unit`, the unit spelled for a file name:
//! `_per_` for "/", `_` between factors (`leak_rate_cc_per_min`, `throughput_mbar_L_per_s`),
//! `C` and `F` for °C and °F (`temperature_F`): read back with `_per_` → `/` and `_` → `*`, every
//! such unit is one the scenario parser accepts.

use super::ReportError;
use super::csv::{Cell, Table, csv_error, finish};
use crate::units::human;

/// The unit system of what is printed (`--units`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum UnitSystem {
    /// SI: the CSV in base units (m, Pa, K, N/m, m³/s), the summary as before (mm, MPa, °C, N/mm).
    #[default]
    Si,
    /// mm, bar, °C, N/mm, mL/min, mL, mbar·L/s.
    Metric,
    /// in, psi, °F, lbf/in, cc/min, cc, atm·cc/s.
    Us,
}

impl UnitSystem {
    /// The names `--units` takes.
    pub const NAMES: [&'static str; 3] = ["si", "metric", "us"];

    /// The system of its name (`si`, `metric` or `us`).
    pub fn from_name(name: &str) -> Option<UnitSystem> {
        match name {
            "si" => Some(UnitSystem::Si),
            "metric" => Some(UnitSystem::Metric),
            "us" => Some(UnitSystem::Us),
            _ => None,
        }
    }

    /// `si`, `metric` or `us`.
    pub fn name(self) -> &'static str {
        match self {
            UnitSystem::Si => "si",
            UnitSystem::Metric => "metric",
            UnitSystem::Us => "us",
        }
    }

    /// The unit a summary prints `quantity` in.
    pub fn display(self, quantity: Quantity) -> Unit {
        use Quantity::*;
        match (self, quantity) {
            (UnitSystem::Si, Length) => MILLIMETRE,
            (UnitSystem::Si, Pressure) => MEGAPASCAL,
            (UnitSystem::Si, Temperature) => CELSIUS,
            (UnitSystem::Si, ForcePerLength) => NEWTON_PER_MILLIMETRE,
            (UnitSystem::Si, VolumeFlow) => CUBIC_METRE_PER_SECOND,
            (UnitSystem::Si, Volume) => CUBIC_METRE,
            (UnitSystem::Si, Throughput) => PASCAL_CUBIC_METRE_PER_SECOND,
            (_, q) => self.csv(q),
        }
    }

    /// The unit the history CSV writes `quantity` in (its column name carries it).
    pub fn csv(self, quantity: Quantity) -> Unit {
        use Quantity::*;
        match (self, quantity) {
            (UnitSystem::Si, Length) => METRE,
            (UnitSystem::Si, Pressure) => PASCAL,
            (UnitSystem::Si, Temperature) => KELVIN,
            (UnitSystem::Si, ForcePerLength) => NEWTON_PER_METRE,
            (UnitSystem::Si, VolumeFlow) => CUBIC_METRE_PER_SECOND,
            (UnitSystem::Si, Volume) => CUBIC_METRE,
            (UnitSystem::Si, Throughput) => PASCAL_CUBIC_METRE_PER_SECOND,
            (UnitSystem::Metric, Length) => MILLIMETRE,
            (UnitSystem::Metric, Pressure) => BAR,
            (UnitSystem::Metric, Temperature) => CELSIUS,
            (UnitSystem::Metric, ForcePerLength) => NEWTON_PER_MILLIMETRE,
            (UnitSystem::Metric, VolumeFlow) => MILLILITRE_PER_MINUTE,
            (UnitSystem::Metric, Volume) => MILLILITRE,
            (UnitSystem::Metric, Throughput) => MBAR_LITRE_PER_SECOND,
            (UnitSystem::Us, Length) => INCH,
            (UnitSystem::Us, Pressure) => PSI,
            (UnitSystem::Us, Temperature) => FAHRENHEIT,
            (UnitSystem::Us, ForcePerLength) => POUND_FORCE_PER_INCH,
            (UnitSystem::Us, VolumeFlow) => CC_PER_MINUTE,
            (UnitSystem::Us, Volume) => CC,
            (UnitSystem::Us, Throughput) => ATM_CC_PER_SECOND,
        }
    }

    /// `si` \[SI\] of `quantity` as the summary prints it: `"29 psi"`, `"176 °F"` (`sig`
    /// significant digits).
    pub fn show(self, quantity: Quantity, si: f64, sig: usize) -> String {
        let unit = self.display(quantity);
        format!("{} {}", human(unit.from_si(si), sig), unit.symbol)
    }
}

/// What a number measures, for the choice of its unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    Length,
    Pressure,
    /// An absolute temperature.
    Temperature,
    ForcePerLength,
    /// A liquid's (or a gas's volume) flow.
    VolumeFlow,
    Volume,
    /// A gas's pV flow.
    Throughput,
}

/// A unit: `value = si × scale + offset`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unit {
    /// How people write it: `"psi"`, `"°F"`, `"mbar·L/s"`.
    pub symbol: &'static str,
    /// How a CSV column name ends with it: `"psi"`, `"F"`, `"mbar_L_per_s"`.
    pub suffix: &'static str,
    scale: f64,
    offset: f64,
}

impl Unit {
    /// The value in this unit of `si` \[SI\].
    pub fn from_si(&self, si: f64) -> f64 {
        si * self.scale + self.offset
    }

    /// The SI value of `value` in this unit (the inverse of [`Unit::from_si`]).
    pub fn to_si(&self, value: f64) -> f64 {
        (value - self.offset) / self.scale
    }
}

const fn unit(symbol: &'static str, suffix: &'static str, scale: f64, offset: f64) -> Unit {
    Unit {
        symbol,
        suffix,
        scale,
        offset,
    }
}

/// The international inch \[m\] (exact).
pub const INCH_M: f64 = 0.0254;
/// The pound-force \[N\] (exact: 0.45359237 kg × 9.80665 m/s²).
pub const POUND_FORCE_N: f64 = 4.448_221_615_260_5;
/// The psi, lbf/in² \[Pa\] (exact).
pub const PSI_PA: f64 = 6_894.757_293_168;
/// The standard atmosphere \[Pa\] (exact).
pub const ATM_PA: f64 = 101_325.0;

const METRE: Unit = unit("m", "m", 1.0, 0.0);
const MILLIMETRE: Unit = unit("mm", "mm", 1e3, 0.0);
const INCH: Unit = unit("in", "in", 1.0 / INCH_M, 0.0);
const PASCAL: Unit = unit("Pa", "Pa", 1.0, 0.0);
const MEGAPASCAL: Unit = unit("MPa", "MPa", 1e-6, 0.0);
const BAR: Unit = unit("bar", "bar", 1e-5, 0.0);
const PSI: Unit = unit("psi", "psi", 1.0 / PSI_PA, 0.0);
const KELVIN: Unit = unit("K", "K", 1.0, 0.0);
const CELSIUS: Unit = unit("°C", "C", 1.0, -273.15);
const FAHRENHEIT: Unit = unit("°F", "F", 9.0 / 5.0, -459.67);
const NEWTON_PER_METRE: Unit = unit("N/m", "N_per_m", 1.0, 0.0);
const NEWTON_PER_MILLIMETRE: Unit = unit("N/mm", "N_per_mm", 1e-3, 0.0);
const POUND_FORCE_PER_INCH: Unit = unit("lbf/in", "lbf_per_in", INCH_M / POUND_FORCE_N, 0.0);
const CUBIC_METRE_PER_SECOND: Unit = unit("m³/s", "m3_per_s", 1.0, 0.0);
const MILLILITRE_PER_MINUTE: Unit = unit("mL/min", "mL_per_min", 1e6 * 60.0, 0.0);
const CC_PER_MINUTE: Unit = unit("cc/min", "cc_per_min", 1e6 * 60.0, 0.0);
const CUBIC_METRE: Unit = unit("m³", "m3", 1.0, 0.0);
const MILLILITRE: Unit = unit("mL", "mL", 1e6, 0.0);
const CC: Unit = unit("cc", "cc", 1e6, 0.0);
const PASCAL_CUBIC_METRE_PER_SECOND: Unit = unit("Pa·m³/s", "Pa_m3_per_s", 1.0, 0.0);
// 1 mbar·L/s = 100 Pa × 1e-3 m³/s
const MBAR_LITRE_PER_SECOND: Unit = unit("mbar·L/s", "mbar_L_per_s", 10.0, 0.0);
// 1 atm·cc/s = 101325 Pa × 1e-6 m³/s
const ATM_CC_PER_SECOND: Unit = unit("atm·cc/s", "atm_cc_per_s", 1.0 / (ATM_PA * 1e-6), 0.0);

/// The history CSV's columns that carry a unit: their stem and quantity (the SI column is
/// `stem_` + the SI suffix, e.g. `temperature_K`). Columns not listed (times in s, shift factor,
/// fractions, words) are the same in every system.
pub const HISTORY_QUANTITIES: [(&str, Quantity); 14] = [
    ("temperature", Quantity::Temperature),
    ("sealing_force", Quantity::ForcePerLength),
    ("peak_pressure", Quantity::Pressure),
    ("mean_pressure", Quantity::Pressure),
    ("contact_width", Quantity::Length),
    ("u_c", Quantity::Length),
    ("leak_rate", Quantity::VolumeFlow),
    ("leaked_volume", Quantity::Volume),
    ("throughput", Quantity::Throughput),
    ("permeation", Quantity::Throughput),
    ("drag_leak_rate", Quantity::VolumeFlow),
    ("net_volume_per_cycle", Quantity::Volume),
    ("out_stroke_film", Quantity::Length),
    ("in_stroke_film", Quantity::Length),
];

/// The quantity and stem of an SI column name (`"peak_pressure_Pa"` → pressure, `"peak_pressure"`).
fn quantity_of(column: &str) -> Option<(&'static str, Quantity)> {
    HISTORY_QUANTITIES.into_iter().find(|&(stem, q)| {
        column
            .strip_prefix(stem)
            .and_then(|rest| rest.strip_prefix('_'))
            == Some(UnitSystem::Si.csv(q).suffix)
    })
}

/// The name a column of an SI table has in `system`: `temperature_K` → `temperature_F` (us).
pub fn column_name(column: &str, system: UnitSystem) -> String {
    match quantity_of(column) {
        Some((stem, q)) => format!("{stem}_{}", system.csv(q).suffix),
        None => column.to_owned(),
    }
}

/// A table of SI values (the history) as CSV in `system`: the column names carry the system's
/// units and the numbers are converted; every converted number checked finite.
pub fn table_csv(table: &Table, system: UnitSystem) -> Result<String, ReportError> {
    if system == UnitSystem::Si {
        return table.to_csv();
    }
    let units: Vec<Option<Unit>> = table
        .header
        .iter()
        .map(|c| quantity_of(c).map(|(_, q)| system.csv(q)))
        .collect();
    let mut writer = ::csv::Writer::from_writer(Vec::new());
    writer
        .write_record(table.header.iter().map(|c| column_name(c, system)))
        .map_err(csv_error)?;
    for (i, row) in table.rows.iter().enumerate() {
        let mut cells = Vec::with_capacity(row.len());
        for ((cell, unit), column) in row.iter().zip(&units).zip(&table.header) {
            cells.push(match (cell, unit) {
                (Cell::Number(v), Some(u)) => Cell::number(i + 1, column, u.from_si(*v))?.text(),
                _ => cell.text(),
            });
        }
        writer.write_record(&cells).map_err(csv_error)?;
    }
    finish(writer)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::{Dimension, absolute_temperature, parse_unit};

    /// A CSV suffix as a unit the scenario parser reads: `_per_` → `/`, `_` → `*`.
    fn parsed(suffix: &str) -> (f64, Dimension) {
        let text = suffix.replace("_per_", "/").replace('_', "*");
        parse_unit(&text).unwrap_or_else(|e| panic!("{suffix}: {e}"))
    }

    fn dimension(q: Quantity) -> Dimension {
        match q {
            Quantity::Length => Dimension::LENGTH,
            Quantity::Pressure => Dimension::PRESSURE,
            Quantity::Temperature => Dimension::TEMPERATURE,
            Quantity::ForcePerLength => Dimension::FORCE_PER_LENGTH,
            Quantity::VolumeFlow => Dimension::VOLUME_FLOW,
            Quantity::Volume => Dimension::VOLUME,
            Quantity::Throughput => Dimension::POWER,
        }
    }

    const ALL: [Quantity; 7] = [
        Quantity::Length,
        Quantity::Pressure,
        Quantity::Temperature,
        Quantity::ForcePerLength,
        Quantity::VolumeFlow,
        Quantity::Volume,
        Quantity::Throughput,
    ];

    /// Every CSV unit is one the input parser reads, with the same factor (an independent
    /// statement of each definition: the parser's table of units), so a file written in any
    /// system reads back to its SI values.
    #[test]
    fn every_csv_unit_is_the_input_parsers_unit() {
        for system in [UnitSystem::Si, UnitSystem::Metric, UnitSystem::Us] {
            for q in ALL {
                let u = system.csv(q);
                if q == Quantity::Temperature {
                    for k in [0.0, 233.15, 353.15, 1000.0] {
                        let back = absolute_temperature(u.from_si(k), u.suffix).unwrap();
                        assert!((back - k).abs() <= 1e-12 * k.max(1.0), "{} {k}", u.suffix);
                    }
                    continue;
                }
                let (factor, dim) = parsed(u.suffix);
                assert_eq!(dim, dimension(q), "{}", u.suffix);
                let si = 1.234_5;
                let rel = (u.from_si(si) * factor - si).abs() / si;
                assert!(rel < 1e-15, "{} off by {rel}", u.suffix);
            }
        }
    }

    /// The definitions themselves: 1 in = 25.4 mm, 1 psi = 6894.757293168 Pa, 32 °F = 273.15 K,
    /// 212 °F = 373.15 K, 1 lbf/in = 175.126835... N/m, 1 mbar·L/s = 0.1 Pa·m³/s.
    #[test]
    fn the_definitions_hold() {
        let us = UnitSystem::Us;
        assert_eq!(us.csv(Quantity::Length).from_si(0.0254), 1.0);
        assert!((us.csv(Quantity::Pressure).from_si(6_894.757_293_168) - 1.0).abs() < 1e-15);
        assert!((us.csv(Quantity::Temperature).from_si(273.15) - 32.0).abs() < 1e-12);
        assert!((us.csv(Quantity::Temperature).from_si(373.15) - 212.0).abs() < 1e-12);
        assert!(
            (us.csv(Quantity::ForcePerLength).to_si(1.0) - 4.448_221_615_260_5 / 0.0254).abs()
                < 1e-12
        );
        let metric = UnitSystem::Metric;
        assert!((metric.csv(Quantity::Throughput).to_si(1.0) - 0.1).abs() < 1e-16);
        assert!((metric.csv(Quantity::Pressure).from_si(2e5) - 2.0).abs() < 1e-15);
        assert!((metric.csv(Quantity::VolumeFlow).from_si(1e-6 / 60.0) - 1.0).abs() < 1e-12);
        assert_eq!(
            us.show(Quantity::Pressure, 6_894.757_293_168 * 30.0, 3),
            "30 psi"
        );
        assert_eq!(UnitSystem::Si.show(Quantity::Pressure, 2e5, 3), "0.2 MPa");
    }

    #[test]
    fn columns_are_renamed_and_converted_the_rest_kept() {
        assert_eq!(
            column_name("temperature_K", UnitSystem::Us),
            "temperature_F"
        );
        assert_eq!(
            column_name("leak_rate_m3_per_s", UnitSystem::Us),
            "leak_rate_cc_per_min"
        );
        assert_eq!(
            column_name("drag_leak_rate_m3_per_s", UnitSystem::Metric),
            "drag_leak_rate_mL_per_min"
        );
        assert_eq!(column_name("time_s", UnitSystem::Us), "time_s");
        assert_eq!(column_name("state", UnitSystem::Us), "state");
        let table = Table {
            header: vec!["time_s", "temperature_K", "u_c_m", "state"],
            rows: vec![vec![
                Cell::Number(1.0),
                Cell::Number(373.15),
                Cell::Blank,
                Cell::Text("sealed".into()),
            ]],
        };
        let csv = table_csv(&table, UnitSystem::Us).unwrap();
        let mut lines = csv.lines();
        assert_eq!(lines.next(), Some("time_s,temperature_F,u_c_in,state"));
        let cells: Vec<&str> = lines.next().unwrap().split(',').collect();
        assert_eq!(cells[0], "1e0");
        // 373.15 K is 212 °F (water's boiling point at 1 atm, by the scale's definition)
        assert!(
            (cells[1].parse::<f64>().unwrap() - 212.0).abs() < 1e-12,
            "{csv}"
        );
        assert_eq!(&cells[2..], ["", "sealed"]);
        assert_eq!(
            table_csv(&table, UnitSystem::Si).unwrap(),
            table.to_csv().unwrap()
        );
    }

    #[test]
    fn every_history_column_with_a_unit_is_registered() {
        for column in crate::report::life::HISTORY_COLUMNS
            .iter()
            .chain(&crate::report::life::MOTION_HISTORY_COLUMNS)
            .chain(&[
                crate::report::life::GAS_HISTORY_COLUMN,
                crate::report::life::PERMEATION_HISTORY_COLUMN,
            ])
        {
            let unitless = [
                "time_s",
                "reduced_time_s",
                "shift_factor",
                "state",
                "open_fraction",
                "compression_set",
                "shutdown_squeeze",
                "speed_regime",
            ];
            assert!(
                unitless.contains(column) || quantity_of(column).is_some(),
                "{column} has a unit but no quantity"
            );
        }
    }
}
