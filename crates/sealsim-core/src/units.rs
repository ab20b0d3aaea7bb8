//! Physical quantities written as text ("10 MPa", "2 um", "80 C") → SI `f64`, with a
//! check of the physical [`Dimension`].
//!
//! This is the input boundary for scenario files and command-line flags; nothing here
//! panics, whatever the input.
//!
//! # Grammar
//!
//! ```text
//! quantity  = number [spaces] [unit]          (surrounding whitespace is ignored)
//! number    = ["+"|"-"] (digits ["." [digits]] | "." digits) [("e"|"E") ["+"|"-"] digits]
//! unit      = numerator { "/" product }       a/b/c means a/(b·c)
//! numerator = product | "1" | ""              "1" or "" only before a "/": "1/m", "/m"
//! product   = factor { separator factor }     separator: "*", "·", "⋅", whitespace, or "."
//!                                             directly between two symbols ("Pa.s")
//! factor    = symbol [exponent]               exponent: "^n", "^-n", "^+n", trailing
//!                                             digits ("m3"), or superscripts ("m³", "m⁻¹")
//! ```
//!
//! Symbols are case-sensitive (`mPa` is not `MPa`). A symbol is looked up whole first,
//! then as an SI prefix followed by a prefixable unit.
//!
//! # Units
//!
//! | symbol | meaning | prefixable |
//! |---|---|---|
//! | `m` | metre | yes |
//! | `g` | gram (so `kg` is the SI base unit) | yes |
//! | `s` | second | yes |
//! | `min`, `h`, `hr`, `d`, `day`, `week` | minute, hour, day, week | no |
//! | `year`, `yr` | Julian year, 365.25 d | no |
//! | `Pa`, `bar` | pascal, bar (10⁵ Pa) | yes |
//! | `psi`, `atm` | 6894.757293168 Pa, 101325 Pa | no |
//! | `Torr` | 101325/760 Pa | yes |
//! | `N`, `J`, `W` | newton, joule, watt | yes |
//! | `mol` | mole | yes |
//! | `K` | kelvin | yes |
//! | `L`, `l` | litre (10⁻³ m³) | yes |
//! | `P` | poise (0.1 Pa·s; `cP` = mPa·s) | yes |
//! | `St` | stokes (10⁻⁴ m²/s; `cSt` = mm²/s) | yes |
//! | `Hz` | hertz | yes |
//!
//! SI prefixes: `P` `T` `G` `M` `k` `c` `m` `u` `µ` (U+00B5) `μ` (U+03BC) `n` `p` `f`.
//! There is deliberately no hecto (`h` is the hour), deca or exa.
//!
//! # Temperatures
//!
//! `C`, `°C`, `degC` (Celsius) and `F`, `°F`, `degF` (Fahrenheit) are affine scales and
//! may only be the *whole* unit: `"80 C"`. In [`parse_temperature`] they give absolute
//! temperatures (`"80 C"` → 353.15 K); in [`parse_quantity`] and [`parse_unit`] with the
//! [`Dimension::TEMPERATURE`] dimension they are temperature *differences*
//! (`"10 C"` → 10 K, `"9 F"` → 5 K). The only compound forms allowed are `1/C` and `1/F`
//! (also written `/C`, `1/°C`, ...), read as "per degree" differences, e.g. a thermal
//! expansion coefficient. Anything else such as `C/s` or `°F*m` is
//! [`UnitError::AffineInCompound`]; use `K` there.

use std::fmt;

/// Molar gas constant R = N_A k_B \[J/(mol·K)\] (exact, SI 2019).
pub const GAS_CONSTANT: f64 = 8.314_462_618_153_24;

/// The standard reference state of sccm and slm (SEMI, as quoted in the Brooks Instrument
/// SLA/MF manual): T_ref = 273.15 K, p_ref = 101325 Pa.
pub const STANDARD_TEMPERATURE: f64 = 273.15;
/// p_ref of sccm and slm \[Pa\].
pub const STANDARD_PRESSURE: f64 = 101_325.0;

/// 1 sccm as a throughput \[Pa·m³/s\] **at T_ref**: 101325 Pa · 1e-6 m³ / 60 s (= 1.68875e-3).
/// A throughput Q at the gas temperature T is `Q (T_ref/T) / SCCM` sccm: the same moles per
/// second carry a pV flow proportional to T.
pub const SCCM: f64 = STANDARD_PRESSURE * 1e-6 / 60.0;
/// 1 slm = 1000 sccm \[Pa·m³/s at T_ref\].
pub const SLM: f64 = 1e3 * SCCM;

/// Exponents of the SI base quantities: length m, mass kg, time s, temperature K, amount mol.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Dimension {
    pub length: i8,
    pub mass: i8,
    pub time: i8,
    pub temperature: i8,
    pub amount: i8,
}

impl Dimension {
    /// Builds a dimension from its exponents of m, kg, s, K and mol.
    pub const fn new(length: i8, mass: i8, time: i8, temperature: i8, amount: i8) -> Self {
        Dimension {
            length,
            mass,
            time,
            temperature,
            amount,
        }
    }

    pub const DIMENSIONLESS: Dimension = Dimension::new(0, 0, 0, 0, 0);
    pub const LENGTH: Dimension = Dimension::new(1, 0, 0, 0, 0);
    /// 1/m.
    pub const WAVEVECTOR: Dimension = Dimension::new(-1, 0, 0, 0, 0);
    pub const AREA: Dimension = Dimension::new(2, 0, 0, 0, 0);
    pub const VOLUME: Dimension = Dimension::new(3, 0, 0, 0, 0);
    /// m⁴, the dimension of the power spectral density C(q) of a 2D surface.
    pub const SPECTRUM: Dimension = Dimension::new(4, 0, 0, 0, 0);
    pub const MASS: Dimension = Dimension::new(0, 1, 0, 0, 0);
    pub const TIME: Dimension = Dimension::new(0, 0, 1, 0, 0);
    /// 1/s.
    pub const FREQUENCY: Dimension = Dimension::new(0, 0, -1, 0, 0);
    /// K, used for temperature *differences* (absolute temperatures go through
    /// [`parse_temperature`]).
    pub const TEMPERATURE: Dimension = Dimension::new(0, 0, 0, 1, 0);
    pub const AMOUNT: Dimension = Dimension::new(0, 0, 0, 0, 1);
    /// Pa = kg·m⁻¹·s⁻².
    pub const PRESSURE: Dimension = Dimension::new(-1, 1, -2, 0, 0);
    /// Pa·s.
    pub const VISCOSITY: Dimension = Dimension::new(-1, 1, -1, 0, 0);
    /// m²/s (ν = η/ρ).
    pub const KINEMATIC_VISCOSITY: Dimension = Dimension::new(2, 0, -1, 0, 0);
    /// kg/m³.
    pub const DENSITY: Dimension = Dimension::new(-3, 1, 0, 0, 0);
    /// 1/K.
    pub const THERMAL_EXPANSION: Dimension = Dimension::new(0, 0, 0, -1, 0);
    /// m³/s.
    pub const VOLUME_FLOW: Dimension = Dimension::new(3, 0, -1, 0, 0);
    /// m/s.
    pub const VELOCITY: Dimension = Dimension::new(1, 0, -1, 0, 0);
    /// 1/m³.
    pub const NUMBER_DENSITY: Dimension = Dimension::new(-3, 0, 0, 0, 0);
    /// J/mol.
    pub const MOLAR_ENERGY: Dimension = Dimension::new(2, 1, -2, 0, -1);
    /// N/m = kg·s⁻².
    pub const FORCE_PER_LENGTH: Dimension = Dimension::new(0, 1, -2, 0, 0);
    /// N.
    pub const FORCE: Dimension = Dimension::new(1, 1, -2, 0, 0);
    /// J.
    pub const ENERGY: Dimension = Dimension::new(2, 1, -2, 0, 0);
    /// W. Also the dimension of a gas throughput (pressure × volume / time, Pa·m³/s): which
    /// one a key means is the key's ([`parse_throughput`]).
    pub const POWER: Dimension = Dimension::new(2, 1, -3, 0, 0);
    /// mol/s.
    pub const MOLAR_FLOW: Dimension = Dimension::new(0, 0, -1, 0, 1);

    /// Human name, e.g. "pressure", "length", "wavevector (1/length)"; for an unnamed
    /// combination a formula like "m^-1·kg·s^-2".
    pub fn describe(&self) -> String {
        match self.named() {
            Some(named) => named.name.to_string(),
            None => self.formula(),
        }
    }

    /// The dimension as a product of base units, e.g. "m^-1·kg·s^-2" ("1" if dimensionless).
    pub fn formula(&self) -> String {
        let parts: Vec<String> = [
            ("m", self.length),
            ("kg", self.mass),
            ("s", self.time),
            ("K", self.temperature),
            ("mol", self.amount),
        ]
        .iter()
        .filter(|(_, e)| *e != 0)
        .map(|&(symbol, e)| {
            if e == 1 {
                symbol.to_string()
            } else {
                format!("{symbol}^{e}")
            }
        })
        .collect();
        if parts.is_empty() {
            "1".to_string()
        } else {
            parts.join("·")
        }
    }

    /// Product of two dimensions, `None` if an exponent overflows.
    pub fn checked_mul(self, other: Dimension) -> Option<Dimension> {
        Some(Dimension::new(
            self.length.checked_add(other.length)?,
            self.mass.checked_add(other.mass)?,
            self.time.checked_add(other.time)?,
            self.temperature.checked_add(other.temperature)?,
            self.amount.checked_add(other.amount)?,
        ))
    }

    /// Quotient of two dimensions, `None` if an exponent overflows.
    pub fn checked_div(self, other: Dimension) -> Option<Dimension> {
        Some(Dimension::new(
            self.length.checked_sub(other.length)?,
            self.mass.checked_sub(other.mass)?,
            self.time.checked_sub(other.time)?,
            self.temperature.checked_sub(other.temperature)?,
            self.amount.checked_sub(other.amount)?,
        ))
    }

    /// Integer power of a dimension, `None` if an exponent overflows.
    pub fn checked_pow(self, n: i8) -> Option<Dimension> {
        Some(Dimension::new(
            self.length.checked_mul(n)?,
            self.mass.checked_mul(n)?,
            self.time.checked_mul(n)?,
            self.temperature.checked_mul(n)?,
            self.amount.checked_mul(n)?,
        ))
    }

    fn named(&self) -> Option<&'static NamedDimension> {
        NAMED_DIMENSIONS
            .iter()
            .find(|named| named.dimension == *self)
    }

    /// The units engineers write this dimension in, most common first (for the fix a message
    /// suggests; every one is accepted by [`parse_quantity`], a test).
    pub fn engineering_units(&self) -> &'static [&'static str] {
        match *self {
            Dimension::LENGTH => &["mm", "um", "in"],
            Dimension::WAVEVECTOR => &["1/m", "1/mm"],
            Dimension::AREA => &["mm^2", "m^2"],
            Dimension::VOLUME => &["mL", "L", "cc"],
            Dimension::SPECTRUM => &["m^4"],
            Dimension::TIME => &["h", "day", "year"],
            Dimension::FREQUENCY => &["Hz", "1/s"],
            Dimension::TEMPERATURE => &["K"],
            Dimension::PRESSURE => &["bar", "MPa", "psi"],
            Dimension::VISCOSITY => &["mPa*s", "cP"],
            Dimension::KINEMATIC_VISCOSITY => &["cSt", "mm^2/s"],
            Dimension::DENSITY => &["kg/m^3", "g/cm^3"],
            Dimension::THERMAL_EXPANSION => &["1/K"],
            Dimension::VOLUME_FLOW => &["mL/h", "mL/day", "m^3/s"],
            Dimension::VELOCITY => &["mm/s", "m/s"],
            Dimension::NUMBER_DENSITY => &["1/m^3", "1/mL"],
            Dimension::MOLAR_ENERGY => &["kJ/mol"],
            Dimension::FORCE_PER_LENGTH => &["N/mm", "N/m"],
            Dimension::FORCE => &["N", "kN"],
            Dimension::POWER => &["mbar*L/s", "Pa*m^3/s"],
            _ => &[],
        }
    }

    /// The fix for a bare number `v` given for this dimension: `write "210 bar", "210 MPa" or
    /// "210 psi" (the unit you mean)`.
    pub fn bare_number_fix(&self, v: f64) -> String {
        let quoted: Vec<String> = self
            .engineering_units()
            .iter()
            .map(|u| format!("\"{} {u}\"", show(v)))
            .collect();
        let list = match quoted.as_slice() {
            [] => format!("\"{} {}\"", show(v), self.formula()),
            [one] => one.clone(),
            [head @ .., last] => format!("{} or {last}", head.join(", ")),
        };
        format!(
            "{} {} needs its unit: write {list} (the one you mean; a bare number is ambiguous)",
            article(&self.describe()),
            self.describe()
        )
    }

    /// "a pressure (e.g. "10 MPa")", used for what was expected.
    fn expected_phrase(&self) -> String {
        match self.named() {
            Some(named) if *self == Dimension::DIMENSIONLESS => {
                format!("a dimensionless number (e.g. \"{}\")", named.example)
            }
            Some(named) => format!(
                "{} {} (e.g. \"{}\")",
                article(named.name),
                named.name,
                named.example
            ),
            None => format!("a quantity of dimension {}", self.formula()),
        }
    }

    /// "is a length", "has dimension m·kg", used for what was found.
    fn found_phrase(&self) -> String {
        match self.named() {
            Some(_) if *self == Dimension::DIMENSIONLESS => "is dimensionless".to_string(),
            Some(named) => format!("is {} {}", article(named.name), named.name),
            None => format!("has dimension {}", self.formula()),
        }
    }
}

impl fmt::Display for Dimension {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe())
    }
}

struct NamedDimension {
    dimension: Dimension,
    name: &'static str,
    example: &'static str,
}

const fn named(dimension: Dimension, name: &'static str, example: &'static str) -> NamedDimension {
    NamedDimension {
        dimension,
        name,
        example,
    }
}

const NAMED_DIMENSIONS: &[NamedDimension] = &[
    named(Dimension::DIMENSIONLESS, "dimensionless", "0.5"),
    named(Dimension::LENGTH, "length", "2 um"),
    named(Dimension::WAVEVECTOR, "wavevector (1/length)", "7.8e9 1/m"),
    named(Dimension::AREA, "area", "1 mm^2"),
    named(Dimension::VOLUME, "volume", "1 mL"),
    named(
        Dimension::SPECTRUM,
        "power spectral density (length^4)",
        "1e-30 m^4",
    ),
    named(Dimension::MASS, "mass", "1 kg"),
    named(Dimension::TIME, "time", "30 year"),
    named(Dimension::FREQUENCY, "frequency (1/time)", "50 Hz"),
    named(Dimension::TEMPERATURE, "temperature", "10 K"),
    named(Dimension::AMOUNT, "amount of substance", "1 mol"),
    named(Dimension::PRESSURE, "pressure", "10 MPa"),
    named(Dimension::VISCOSITY, "dynamic viscosity", "1 mPa*s"),
    named(
        Dimension::KINEMATIC_VISCOSITY,
        "kinematic viscosity",
        "46 cSt",
    ),
    named(Dimension::DENSITY, "density", "870 kg/m^3"),
    named(
        Dimension::THERMAL_EXPANSION,
        "thermal expansion coefficient (1/temperature)",
        "1.2e-5 1/K",
    ),
    named(Dimension::VOLUME_FLOW, "volume flow rate", "1e-9 m^3/s"),
    named(Dimension::VELOCITY, "velocity", "1 cm/s"),
    named(
        Dimension::NUMBER_DENSITY,
        "number density (1/volume)",
        "1e12 1/m^3",
    ),
    named(Dimension::MOLAR_ENERGY, "molar energy", "90 kJ/mol"),
    named(Dimension::FORCE_PER_LENGTH, "force per length", "1 N/m"),
    named(Dimension::FORCE, "force", "1 N"),
    named(Dimension::ENERGY, "energy", "1 J"),
    named(Dimension::POWER, "power", "1 W"),
    named(Dimension::MOLAR_FLOW, "molar flow", "1e-9 mol/s"),
];

fn article(noun: &str) -> &'static str {
    match noun.chars().next() {
        Some('a' | 'e' | 'i' | 'o' | 'u') => "an",
        _ => "a",
    }
}

/// A number for a message: at most six significant digits, no binary noise, plain when
/// moderate (`0.00353`, `1200`), else scientific (`3.5e-7`, `1e10`). Every error message
/// prints its numbers with this (`0.0035299999999999997` reads `0.00353`).
pub fn show(v: f64) -> String {
    human(v, 6)
}

/// An absolute temperature `kelvin` \[K\] as engineers read it, in °C with kelvin beside:
/// `"-40.05 °C (233.1 K)"` (`sig` significant digits for each). Messages print temperatures
/// this way; the data files keep kelvin.
pub fn show_temperature(kelvin: f64, sig: usize) -> String {
    format!(
        "{} °C ({} K)",
        human(kelvin - 273.15, sig),
        human(kelvin, sig)
    )
}

/// A number written exactly: Rust's shortest form that reads back to the same bits, plain when
/// moderate (`0.25`, `353.15`), else with an exponent (`8e-7`, `1.2e7`). For files that are
/// read back (study tables, generated scenarios).
pub fn exact(x: f64) -> String {
    if x != 0.0 && !(1e-4..1e7).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// A number for people: `sig` significant digits, trailing zeros dropped; scientific outside
/// 1e-3 ≤ |v| < 1e6.
pub fn human(v: f64, sig: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let sig = sig.max(1);
    if (1e-3..1e6).contains(&v.abs()) {
        let magnitude = v.abs().log10().floor() as i64;
        let decimals = (sig as i64 - 1 - magnitude).max(0) as usize;
        trim_zeros(format!("{v:.decimals$}"))
    } else {
        let text = format!("{v:.*e}", sig - 1);
        match text.split_once('e') {
            Some((mantissa, exponent)) => format!("{}e{exponent}", trim_zeros(mantissa.into())),
            None => text,
        }
    }
}

fn trim_zeros(text: String) -> String {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    }
}

/// Why a quantity or unit string was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum UnitError {
    /// The text was empty or only whitespace.
    Empty,
    /// The text does not start with a number.
    BadNumber { text: String },
    /// The number (or the converted result) is infinite or NaN: "inf", "nan", "1e999 Pa".
    NotFinite { text: String },
    /// A unit symbol that is neither a known unit nor an SI prefix plus a prefixable unit.
    UnknownUnit { unit: String },
    /// A bare number where a dimensioned quantity was expected.
    MissingUnit { expected: Dimension },
    /// The unit is valid but of the wrong physical dimension.
    WrongDimension {
        unit: String,
        found: Dimension,
        expected: Dimension,
    },
    /// Celsius or Fahrenheit inside a compound unit ("C/s", "°F*m"); only "1/C" and
    /// "1/F" are accepted as compounds.
    AffineInCompound { unit: String },
    /// An absolute temperature below 0 K.
    BelowAbsoluteZero { kelvin: f64 },
    /// A gas throughput was expected (pV flow, standard volume flow or molar flow).
    NotAThroughput { unit: String, found: Dimension },
    /// The unit expression does not follow the grammar ("m^", "m//s", "m**s") or its
    /// exponents or conversion factor are out of range ("m^999").
    MalformedUnit { unit: String, reason: &'static str },
}

const KNOWN_UNITS_HINT: &str = "known units: m, g, s, min, h, hr, d, day, week, year, yr, \
     Pa, bar, psi, atm, Torr, N, J, W, mol, K, L, l, P (poise), St (stokes), Hz, and C/F for \
     temperatures; SI prefixes P T G M k c m u µ μ n p f apply to m, g, s, Pa, bar, Torr, N, J, W, mol, \
     K, L, l, P, St, Hz";

impl fmt::Display for UnitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UnitError::Empty => {
                write!(
                    f,
                    "empty quantity: expected a number and a unit, e.g. \"10 MPa\""
                )
            }
            UnitError::BadNumber { text } => {
                write!(
                    f,
                    "\"{text}\" does not start with a number (e.g. \"10 MPa\")"
                )
            }
            UnitError::NotFinite { text } => write!(f, "\"{text}\" is not a finite number"),
            UnitError::UnknownUnit { unit } => {
                write!(f, "unknown unit \"{unit}\" ({KNOWN_UNITS_HINT})")
            }
            UnitError::MissingUnit { expected } => {
                write!(f, "missing unit: expected {}", expected.expected_phrase())
            }
            UnitError::WrongDimension {
                unit,
                found,
                expected,
            } => write!(
                f,
                "expected {}, but \"{unit}\" {}",
                expected.expected_phrase(),
                found.found_phrase()
            ),
            UnitError::AffineInCompound { unit } => write!(
                f,
                "\"{unit}\": Celsius and Fahrenheit (C, °C, degC, F, °F, degF) can only be \
                 used as the whole unit (e.g. \"80 C\") or as \"1/C\"; use K inside compound units"
            ),
            UnitError::NotAThroughput { unit, found } => write!(
                f,
                "expected a gas throughput (pressure × volume / time: Pa*m^3/s, mbar*L/s, \
                 Torr*L/s; or sccm, slm, mol/s), but \"{unit}\" {}",
                found.found_phrase()
            ),
            UnitError::BelowAbsoluteZero { kelvin } => {
                write!(f, "temperature {} K is below absolute zero", show(*kelvin))
            }
            UnitError::MalformedUnit { unit, reason } => {
                write!(f, "malformed unit \"{unit}\": {reason}")
            }
        }
    }
}

impl std::error::Error for UnitError {}

/// Parse `"<number>[ ]<unit>"` into SI, checking that the unit has the `expected` dimension.
///
/// A temperature dimension here means a temperature DIFFERENCE: "10 K" → 10, "10 C" → 10,
/// "9 F" → 5. A string with no unit is accepted only for [`Dimension::DIMENSIONLESS`].
pub fn parse_quantity(text: &str, expected: Dimension) -> Result<f64, UnitError> {
    let (value, unit) = split_quantity(text)?;
    if unit.is_empty() {
        return if expected == Dimension::DIMENSIONLESS {
            Ok(value)
        } else {
            Err(UnitError::MissingUnit { expected })
        };
    }
    let (si, found) = match resolve_unit(unit)? {
        Resolved::Linear(factor, dimension) => (value * factor, dimension),
        Resolved::Affine(scale) => (scale.difference(value), Dimension::TEMPERATURE),
    };
    if found != expected {
        return Err(UnitError::WrongDimension {
            unit: unit.to_string(),
            found,
            expected,
        });
    }
    finite(si, text)
}

/// A gas throughput \[Pa·m³/s\] at the gas temperature `temperature` \[K\] (docs/model.md
/// §3.9, §11):
/// * a pV flow, any unit of pressure × volume / time (`Pa*m^3/s`, `mbar*L/s` = 0.1 Pa·m³/s
///   exactly, `Torr*L/s`): taken as is (a pV flow has the dimension of a power, W; the key,
///   not the unit, says it is a throughput);
/// * `sccm`, `slm` (standard cm³ or litres per minute at the SEMI reference state, 273.15 K
///   and 101325 Pa): `n × 101325 Pa × 1e-6 m³/60 s` (× 1e3 for slm) is the throughput at
///   273.15 K; at T the same moles carry `× T/273.15`;
/// * a molar flow (`mol/s`, `umol/s`): `ṅ R T`.
pub fn parse_throughput(text: &str, temperature: f64) -> Result<f64, UnitError> {
    let (value, unit) = split_quantity(text)?;
    // the leak-test trade writes "atm cc/s" and "std cc/s" with a space
    let spaced = unit.replace(' ', "*");
    let unit = spaced.as_str();
    let standard = match unit {
        "sccm" => Some(SCCM),
        "slm" => Some(SLM),
        // a standard cubic centimetre a second: 60 sccm
        "std*cc/s" | "scc/s" | "sccs" => Some(60.0 * SCCM),
        _ => None,
    };
    if let Some(per_unit) = standard {
        return finite(value * per_unit * temperature / STANDARD_TEMPERATURE, text);
    }
    if unit.is_empty() {
        return Err(UnitError::MissingUnit {
            expected: Dimension::POWER,
        });
    }
    let si = match resolve_unit(unit)? {
        Resolved::Linear(factor, Dimension::POWER) => value * factor,
        Resolved::Linear(factor, Dimension::MOLAR_FLOW) => {
            value * factor * GAS_CONSTANT * temperature
        }
        Resolved::Linear(_, found) => {
            return Err(UnitError::NotAThroughput {
                unit: unit.to_string(),
                found,
            });
        }
        Resolved::Affine(_) => {
            return Err(UnitError::NotAThroughput {
                unit: unit.to_string(),
                found: Dimension::TEMPERATURE,
            });
        }
    };
    finite(si, text)
}

/// Absolute temperature in kelvin: "80 C" → 353.15, "300 K" → 300, "32 F" → 273.15; the
/// unit may be `K` (with prefixes, "500 mK"), `C`, `°C`, `degC`, `F`, `°F` or `degF`.
pub fn parse_temperature(text: &str) -> Result<f64, UnitError> {
    let (value, unit) = split_quantity(text)?;
    if unit.is_empty() {
        return Err(UnitError::MissingUnit {
            expected: Dimension::TEMPERATURE,
        });
    }
    kelvin(value, unit, text)
}

/// Converts a number in an absolute temperature unit (as accepted by [`parse_temperature`],
/// e.g. from a CSV column headed `"T [C]"`) to kelvin.
pub fn absolute_temperature(value: f64, unit: &str) -> Result<f64, UnitError> {
    kelvin(value, unit.trim(), &format!("{value} {}", unit.trim()))
}

/// Parse a unit expression alone (no number) → (factor to SI, dimension); used by CSV
/// headers etc. A standalone `C` or `F` is taken as a temperature *difference* unit
/// (factor 1 or 5/9, [`Dimension::TEMPERATURE`]); see [`absolute_temperature`] for
/// absolute values. An empty string is [`UnitError::Empty`].
pub fn parse_unit(unit: &str) -> Result<(f64, Dimension), UnitError> {
    Ok(match resolve_unit(unit)? {
        Resolved::Linear(factor, dimension) => (factor, dimension),
        Resolved::Affine(scale) => (scale.difference(1.0), Dimension::TEMPERATURE),
    })
}

fn finite(value: f64, text: &str) -> Result<f64, UnitError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(UnitError::NotFinite {
            text: text.to_string(),
        })
    }
}

fn kelvin(value: f64, unit: &str, text: &str) -> Result<f64, UnitError> {
    let kelvin = match resolve_unit(unit)? {
        Resolved::Affine(scale) => scale.to_kelvin(value),
        Resolved::Linear(factor, Dimension::TEMPERATURE) => value * factor,
        Resolved::Linear(_, found) => {
            return Err(UnitError::WrongDimension {
                unit: unit.to_string(),
                found,
                expected: Dimension::TEMPERATURE,
            });
        }
    };
    let kelvin = finite(kelvin, text)?;
    if kelvin < 0.0 {
        return Err(UnitError::BelowAbsoluteZero { kelvin });
    }
    Ok(kelvin)
}

/// Splits trimmed text into its leading finite number and the trimmed rest.
pub fn split_quantity(text: &str) -> Result<(f64, &str), UnitError> {
    let text = text.trim();
    if text.is_empty() {
        return Err(UnitError::Empty);
    }
    let Some((number, rest)) = split_number(text) else {
        return Err(if names_non_finite(text) {
            UnitError::NotFinite {
                text: text.to_string(),
            }
        } else {
            UnitError::BadNumber {
                text: text.to_string(),
            }
        });
    };
    let value: f64 = number.parse().map_err(|_| UnitError::BadNumber {
        text: text.to_string(),
    })?;
    let value = finite(value, text)?;
    Ok((value, rest.trim()))
}

/// Splits off the longest prefix in float syntax; `None` if there is no digit.
fn split_number(text: &str) -> Option<(&str, &str)> {
    let bytes = text.as_bytes();
    let digits_from = |start: usize| {
        bytes[start.min(bytes.len())..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count()
    };
    let mut end = 0;
    if matches!(bytes.first(), Some(b'+' | b'-')) {
        end = 1;
    }
    let integer_digits = digits_from(end);
    end += integer_digits;
    if bytes.get(end) == Some(&b'.') {
        let fraction_digits = digits_from(end + 1);
        if integer_digits + fraction_digits > 0 {
            end += 1 + fraction_digits;
        }
    } else if integer_digits == 0 {
        return None;
    }
    if !bytes[..end].iter().any(u8::is_ascii_digit) {
        return None;
    }
    if matches!(bytes.get(end), Some(b'e' | b'E')) {
        let mut exponent_end = end + 1;
        if matches!(bytes.get(exponent_end), Some(b'+' | b'-')) {
            exponent_end += 1;
        }
        let exponent_digits = digits_from(exponent_end);
        if exponent_digits > 0 {
            end = exponent_end + exponent_digits;
        }
    }
    // Everything up to `end` is ASCII, so `end` is a char boundary.
    Some(text.split_at(end))
}

/// Whether text spells an infinity or NaN the way `f64::from_str` would ("inf", "-NaN").
fn names_non_finite(text: &str) -> bool {
    let unsigned = text.strip_prefix(['+', '-']).unwrap_or(text);
    let word_len = unsigned.bytes().take_while(u8::is_ascii_alphabetic).count();
    let word = &unsigned[..word_len];
    ["inf", "infinity", "nan"]
        .iter()
        .any(|name| word.eq_ignore_ascii_case(name))
}

/// The scale a temperature was written in, to print temperatures back in the reader's unit
/// (`"80 C"` → °C).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TemperatureUnit {
    Kelvin,
    /// Also the default for a text without a recognised scale.
    #[default]
    Celsius,
    Fahrenheit,
}

impl TemperatureUnit {
    /// The scale of a temperature text such as `"80 C"`, `"176 °F"` or `"353 K"` (°C when it
    /// names none).
    pub fn of(text: &str) -> TemperatureUnit {
        match split_quantity(text).map(|(_, unit)| unit) {
            Ok(unit) => match Scale::from_symbol(unit) {
                Some(Scale::Celsius) => TemperatureUnit::Celsius,
                Some(Scale::Fahrenheit) => TemperatureUnit::Fahrenheit,
                None if unit == "K" => TemperatureUnit::Kelvin,
                None => TemperatureUnit::Celsius,
            },
            Err(_) => TemperatureUnit::Celsius,
        }
    }

    /// `kelvin` \[K\] in this scale with its symbol, four significant digits: `"23 °C"`.
    pub fn show(self, kelvin: f64) -> String {
        match self {
            TemperatureUnit::Kelvin => format!("{} K", human(kelvin, 4)),
            TemperatureUnit::Celsius => format!("{} °C", human(kelvin - 273.15, 4)),
            TemperatureUnit::Fahrenheit => {
                format!("{} °F", human((kelvin - 273.15) * 9.0 / 5.0 + 32.0, 4))
            }
        }
    }

    /// `kelvin` as an input text in this scale that the parser accepts back: `"23 C"`.
    pub fn input(self, kelvin: f64) -> String {
        match self {
            TemperatureUnit::Kelvin => format!("{} K", human(kelvin, 6)),
            TemperatureUnit::Celsius => format!("{} C", human(kelvin - 273.15, 6)),
            TemperatureUnit::Fahrenheit => {
                format!("{} F", human((kelvin - 273.15) * 9.0 / 5.0 + 32.0, 6))
            }
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Scale {
    Celsius,
    Fahrenheit,
}

impl Scale {
    fn from_symbol(symbol: &str) -> Option<Scale> {
        match symbol {
            "C" | "°C" | "degC" => Some(Scale::Celsius),
            "F" | "°F" | "degF" => Some(Scale::Fahrenheit),
            _ => None,
        }
    }

    /// A temperature difference in this scale, in kelvin.
    fn difference(self, value: f64) -> f64 {
        match self {
            Scale::Celsius => value,
            Scale::Fahrenheit => value * 5.0 / 9.0,
        }
    }

    fn to_kelvin(self, value: f64) -> f64 {
        match self {
            Scale::Celsius => value + 273.15,
            Scale::Fahrenheit => (value - 32.0) * 5.0 / 9.0 + 273.15,
        }
    }
}

enum Resolved {
    /// SI value = factor × value.
    Linear(f64, Dimension),
    /// A standalone Celsius or Fahrenheit unit.
    Affine(Scale),
}

fn resolve_unit(unit: &str) -> Result<Resolved, UnitError> {
    let unit = unit.trim();
    if unit.is_empty() {
        return Err(UnitError::Empty);
    }
    if let Some(scale) = Scale::from_symbol(unit) {
        return Ok(Resolved::Affine(scale));
    }
    if let Some(scale) = reciprocal_scale(unit) {
        return Ok(Resolved::Linear(
            1.0 / scale.difference(1.0),
            Dimension::THERMAL_EXPANSION,
        ));
    }
    let (factor, dimension) = parse_compound(unit)?;
    Ok(Resolved::Linear(factor, dimension))
}

/// Recognises "1/C", "/°F" and the like.
fn reciprocal_scale(unit: &str) -> Option<Scale> {
    let rest = unit.strip_prefix('1').unwrap_or(unit).trim_start();
    Scale::from_symbol(rest.strip_prefix('/')?.trim())
}

fn malformed(unit: &str, reason: &'static str) -> UnitError {
    UnitError::MalformedUnit {
        unit: unit.to_string(),
        reason,
    }
}

/// numerator { "/" product }, with a/b/c = a/(b·c).
fn parse_compound(unit: &str) -> Result<(f64, Dimension), UnitError> {
    let mut segments = unit.split('/');
    let numerator = segments.next().unwrap_or_default().trim();
    let (mut factor, mut dimension) =
        if unit.contains('/') && (numerator.is_empty() || numerator == "1") {
            (1.0, Dimension::DIMENSIONLESS)
        } else {
            parse_product(numerator, unit)?
        };
    for segment in segments {
        let segment = segment.trim();
        if segment.is_empty() {
            return Err(malformed(unit, "nothing to divide by after '/'"));
        }
        let (f, d) = parse_product(segment, unit)?;
        factor /= f;
        dimension = dimension
            .checked_div(d)
            .ok_or_else(|| malformed(unit, "dimension exponent out of range"))?;
    }
    if !(factor.is_finite() && factor > 0.0) {
        return Err(malformed(
            unit,
            "conversion factor out of floating-point range",
        ));
    }
    Ok((factor, dimension))
}

fn is_symbol_char(c: char) -> bool {
    c.is_alphabetic() || c == '°' || c == '%'
}

/// factor { separator factor }
fn parse_product(segment: &str, whole: &str) -> Result<(f64, Dimension), UnitError> {
    let chars: Vec<char> = segment.chars().collect();
    let mut pos = 0;
    let mut factor = 1.0;
    let mut dimension = Dimension::DIMENSIONLESS;
    loop {
        let start = pos;
        while chars.get(pos).is_some_and(|&c| is_symbol_char(c)) {
            pos += 1;
        }
        if start == pos {
            return Err(malformed(
                whole,
                if pos >= chars.len() {
                    "expected a unit symbol at the end"
                } else {
                    "expected a unit symbol"
                },
            ));
        }
        let symbol: String = chars[start..pos].iter().collect();
        let (symbol_factor, symbol_dimension) = lookup_symbol(&symbol, whole)?;
        let exponent = parse_exponent(&chars, &mut pos, whole)?;
        factor *= symbol_factor.powi(i32::from(exponent));
        dimension = symbol_dimension
            .checked_pow(exponent)
            .and_then(|d| dimension.checked_mul(d))
            .ok_or_else(|| malformed(whole, "dimension exponent out of range"))?;

        let before_space = pos;
        while chars.get(pos).is_some_and(|c| c.is_whitespace()) {
            pos += 1;
        }
        match chars.get(pos) {
            None => break,
            Some('*' | '·' | '⋅') => pos += 1,
            Some('.') => {
                let next_is_symbol = chars.get(pos + 1).is_some_and(|&c| is_symbol_char(c));
                if pos != before_space || !next_is_symbol {
                    return Err(malformed(
                        whole,
                        "'.' multiplies only directly between two units, as in \"Pa.s\"",
                    ));
                }
                pos += 1;
            }
            Some(_) if pos > before_space => {} // whitespace separates factors
            Some(_) => {
                return Err(malformed(
                    whole,
                    "unexpected character (separate units with '*' or a space)",
                ));
            }
        }
        while chars.get(pos).is_some_and(|c| c.is_whitespace()) {
            pos += 1;
        }
    }
    Ok((factor, dimension))
}

fn ascii_digit(c: char) -> Option<u32> {
    c.to_digit(10)
}

fn superscript_digit(c: char) -> Option<u32> {
    match c {
        '⁰' => Some(0),
        '¹' => Some(1),
        '²' => Some(2),
        '³' => Some(3),
        '⁴'..='⁹' => Some(u32::from(c) - u32::from('⁴') + 4),
        _ => None,
    }
}

/// Optional exponent after a symbol: "^n", "^-n", "^+n", "n", or superscripts ("³", "⁻¹").
fn parse_exponent(chars: &[char], pos: &mut usize, whole: &str) -> Result<i8, UnitError> {
    let digit: fn(char) -> Option<u32>;
    let mut negative = false;
    match chars.get(*pos) {
        Some('^') => {
            *pos += 1;
            match chars.get(*pos) {
                Some('-') => {
                    negative = true;
                    *pos += 1;
                }
                Some('+') => *pos += 1,
                _ => {}
            }
            digit = ascii_digit;
        }
        Some(c) if c.is_ascii_digit() => digit = ascii_digit,
        Some(&c) if c == '⁻' || superscript_digit(c).is_some() => {
            if c == '⁻' {
                negative = true;
                *pos += 1;
            }
            digit = superscript_digit;
        }
        _ => return Ok(1),
    }
    let start = *pos;
    let mut magnitude: u32 = 0;
    while let Some(d) = chars.get(*pos).and_then(|&c| digit(c)) {
        magnitude = magnitude.saturating_mul(10).saturating_add(d);
        *pos += 1;
    }
    if *pos == start {
        return Err(malformed(
            whole,
            "an exponent needs digits, as in \"m^3\" or \"s^-1\"",
        ));
    }
    let signed = i64::from(magnitude) * if negative { -1 } else { 1 };
    i8::try_from(signed).map_err(|_| malformed(whole, "exponent out of range"))
}

struct UnitDef {
    symbol: &'static str,
    factor: f64,
    dimension: Dimension,
    prefixable: bool,
}

const fn unit(
    symbol: &'static str,
    factor: f64,
    dimension: Dimension,
    prefixable: bool,
) -> UnitDef {
    UnitDef {
        symbol,
        factor,
        dimension,
        prefixable,
    }
}

const DAY: f64 = 86_400.0;

/// The volume of one drop in a "drops/min" leak count \[m³\]: 0.05 mL (20 drops per mL, the
/// common rule; API 598's valve-test count is 16 per mL).
pub const DROP_VOLUME: f64 = 5e-8;

const UNITS: &[UnitDef] = &[
    unit("m", 1.0, Dimension::LENGTH, true),
    // the international inch (exactly 25.4 mm): AS568 sizes and US drawings
    unit("in", 0.0254, Dimension::LENGTH, false),
    // the microinch of US surface-finish callouts (Ra 32 µin = 0.81 µm)
    unit("uin", 0.0254e-6, Dimension::LENGTH, false),
    unit("µin", 0.0254e-6, Dimension::LENGTH, false),
    unit("μin", 0.0254e-6, Dimension::LENGTH, false),
    unit("%", 0.01, Dimension::DIMENSIONLESS, false),
    unit("g", 1e-3, Dimension::MASS, true),
    unit("s", 1.0, Dimension::TIME, true),
    unit("min", 60.0, Dimension::TIME, false),
    unit("minutes", 60.0, Dimension::TIME, false),
    unit("h", 3600.0, Dimension::TIME, false),
    unit("hr", 3600.0, Dimension::TIME, false),
    unit("hours", 3600.0, Dimension::TIME, false),
    unit("d", DAY, Dimension::TIME, false),
    unit("day", DAY, Dimension::TIME, false),
    unit("days", DAY, Dimension::TIME, false),
    unit("week", 7.0 * DAY, Dimension::TIME, false),
    unit("weeks", 7.0 * DAY, Dimension::TIME, false),
    unit("year", 365.25 * DAY, Dimension::TIME, false),
    unit("years", 365.25 * DAY, Dimension::TIME, false),
    unit("yr", 365.25 * DAY, Dimension::TIME, false),
    unit("y", 365.25 * DAY, Dimension::TIME, false),
    unit("Pa", 1.0, Dimension::PRESSURE, true),
    unit("bar", 1e5, Dimension::PRESSURE, true),
    unit("psi", 6894.757293168, Dimension::PRESSURE, false),
    unit("ksi", 6894.757293168e3, Dimension::PRESSURE, false),
    // the conventional millimetre and inch of mercury (vacuum and barometer readings)
    unit("mmHg", 133.322_387_415, Dimension::PRESSURE, false),
    unit("inHg", 3_386.388_640_341, Dimension::PRESSURE, false),
    // gauge pressures: relative to the outlet (ambient) side, which is what a pressure
    // difference across a seal to ambient is
    unit("psig", 6894.757293168, Dimension::PRESSURE, false),
    unit("barg", 1e5, Dimension::PRESSURE, false),
    unit("atm", 101_325.0, Dimension::PRESSURE, false),
    // 1 Torr = 101325/760 Pa (exact by definition; mTorr is the vacuum gauges' unit)
    unit("Torr", 101_325.0 / 760.0, Dimension::PRESSURE, true),
    unit("N", 1.0, Dimension::FORCE, true),
    // pound-force and kilogram-force (standard gravity 9.80665 m/s²)
    unit("lbf", 4.448_221_615_260_5, Dimension::FORCE, false),
    unit("kgf", 9.806_65, Dimension::FORCE, false),
    unit("J", 1.0, Dimension::ENERGY, true),
    unit("W", 1.0, Dimension::POWER, true),
    unit("mol", 1.0, Dimension::AMOUNT, true),
    unit("K", 1.0, Dimension::TEMPERATURE, true),
    unit("L", 1e-3, Dimension::VOLUME, true),
    unit("l", 1e-3, Dimension::VOLUME, true),
    // the cubic centimetre of the leak-test trade (atm*cc/s, cc/min)
    unit("cc", 1e-6, Dimension::VOLUME, false),
    // a drop for "drops/min" leak counts: 0.05 mL, the common 20 drops per mL (API 598 counts
    // 16 per mL, 0.0625 mL; docs/model.md §11)
    unit("drop", DROP_VOLUME, Dimension::VOLUME, false),
    unit("drops", DROP_VOLUME, Dimension::VOLUME, false),
    unit("P", 0.1, Dimension::VISCOSITY, true),
    unit("St", 1e-4, Dimension::KINEMATIC_VISCOSITY, true),
    unit("Hz", 1.0, Dimension::FREQUENCY, true),
];

fn prefix_factor(prefix: char) -> Option<f64> {
    Some(match prefix {
        'P' => 1e15,
        'T' => 1e12,
        'G' => 1e9,
        'M' => 1e6,
        'k' => 1e3,
        'c' => 1e-2,
        'm' => 1e-3,
        'u' | 'µ' | 'μ' => 1e-6,
        'n' => 1e-9,
        'p' => 1e-12,
        'f' => 1e-15,
        _ => return None,
    })
}

/// A symbol inside a unit expression: a named unit, or an SI prefix plus a prefixable one.
fn lookup_symbol(symbol: &str, whole: &str) -> Result<(f64, Dimension), UnitError> {
    if Scale::from_symbol(symbol).is_some() {
        return Err(UnitError::AffineInCompound {
            unit: whole.to_string(),
        });
    }
    let find = |s: &str| UNITS.iter().find(|u| u.symbol == s);
    if let Some(u) = find(symbol) {
        return Ok((u.factor, u.dimension));
    }
    let mut chars = symbol.chars();
    if let Some(prefix) = chars.next().and_then(prefix_factor)
        && let Some(u) = find(chars.as_str()).filter(|u| u.prefixable)
    {
        return Ok((prefix * u.factor, u.dimension));
    }
    Err(UnitError::UnknownUnit {
        unit: symbol.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn units_engineers_write() {
        // the inch is exactly 25.4 mm: AS568-214's cord 0.139 in = 3.5306 mm
        let cord = parse_quantity("0.139 in", Dimension::LENGTH);
        assert!(cord.is_ok_and(|v| (v - 3.5306e-3).abs() < 1e-15));
        assert_eq!(parse_quantity("25 %", Dimension::DIMENSIONLESS), Ok(0.25));
        assert_eq!(parse_quantity("25%", Dimension::DIMENSIONLESS), Ok(0.25));
        assert!(parse_quantity("25 %", Dimension::LENGTH).is_err());
        for (text, seconds) in [
            ("30 years", 30.0 * 365.25 * 86_400.0),
            ("2 days", 172_800.0),
            ("3 hours", 10_800.0),
            ("2 weeks", 1_209_600.0),
            ("5 minutes", 300.0),
        ] {
            assert_eq!(parse_quantity(text, Dimension::TIME), Ok(seconds), "{text}");
        }
        // gauge pressure over ambient: a pressure difference to the outlet
        assert_eq!(parse_quantity("100 barg", Dimension::PRESSURE), Ok(1e7));
        assert_eq!(
            parse_quantity("1 psig", Dimension::PRESSURE),
            parse_quantity("1 psi", Dimension::PRESSURE)
        );
    }

    #[test]
    fn numbers_in_messages_have_no_binary_noise() {
        assert_eq!(show(3.53e-3), "0.00353");
        assert_eq!(show(0.0035299999999999997), "0.00353");
        assert_eq!(show(0.1 + 0.2), "0.3");
        assert_eq!(show(1200.0), "1200");
        assert_eq!(show(-90000.0), "-90000");
        assert_eq!(show(1e10), "1e10");
        assert_eq!(show(1.23456789e-7), "1.23457e-7");
        assert_eq!(show(0.0), "0");
        assert_eq!(show(f64::INFINITY), "inf");
    }

    #[test]
    fn human_numbers() {
        assert_eq!(human(3.80976, 6), "3.80976");
        assert_eq!(human(296.15 - 273.15, 6), "23");
        assert_eq!(human(-34.0, 4), "-34");
        assert_eq!(human(1e-6, 4), "1e-6");
        assert_eq!(human(1.65e-4, 6), "1.65e-4");
        assert_eq!(human(1e13, 4), "1e13");
        assert_eq!(human(12.345678, 4), "12.35");
    }

    fn close(actual: f64, expected: f64, rel: f64) -> bool {
        (actual - expected).abs() <= rel * expected.abs()
    }

    #[track_caller]
    fn check(text: &str, dimension: Dimension, expected: f64) {
        match parse_quantity(text, dimension) {
            Ok(v) => assert!(
                close(v, expected, 1e-14),
                "{text:?}: got {v}, expected {expected}"
            ),
            Err(e) => panic!("{text:?}: unexpected error {e}"),
        }
    }

    #[track_caller]
    fn check_kelvin(text: &str, expected: f64) {
        match parse_temperature(text) {
            Ok(v) => assert!(
                close(v, expected, 1e-14),
                "{text:?}: got {v}, expected {expected}"
            ),
            Err(e) => panic!("{text:?}: unexpected error {e}"),
        }
    }

    #[test]
    fn pressures() {
        check("10 MPa", Dimension::PRESSURE, 1e7);
        check("0.05MPa", Dimension::PRESSURE, 5e4);
        check("1 bar", Dimension::PRESSURE, 1e5);
        check("1 mbar", Dimension::PRESSURE, 100.0);
        check("1 psi", Dimension::PRESSURE, 6894.757293168);
        check("1 atm", Dimension::PRESSURE, 101325.0);
        check("1 mPa", Dimension::PRESSURE, 1e-3);
        check("2 GPa", Dimension::PRESSURE, 2e9);
        check("  3 kPa  ", Dimension::PRESSURE, 3e3);
        check("1 N/m^2", Dimension::PRESSURE, 1.0);
        check("1 J/m^3", Dimension::PRESSURE, 1.0);
        check("1 kg m^-1 s^-2", Dimension::PRESSURE, 1.0);
        check("-2.5E+4 Pa", Dimension::PRESSURE, -25000.0);
    }

    #[test]
    fn lengths_and_wavevectors() {
        for text in ["2 um", "2 µm", "2 μm", "2e-6 m"] {
            check(text, Dimension::LENGTH, 2e-6);
        }
        check("3 mm", Dimension::LENGTH, 0.003);
        check("1 cm", Dimension::LENGTH, 0.01);
        check("5 nm", Dimension::LENGTH, 5e-9);
        check(".5 m", Dimension::LENGTH, 0.5);
        check("7. m", Dimension::LENGTH, 7.0);
        check("1e4 1/m", Dimension::WAVEVECTOR, 1e4);
        check("7.8e9 /m", Dimension::WAVEVECTOR, 7.8e9);
        check("7.8e9 1 / m", Dimension::WAVEVECTOR, 7.8e9);
        check("2 m^-1", Dimension::WAVEVECTOR, 2.0);
        check("1 m⁻¹", Dimension::WAVEVECTOR, 1.0);
        check("1 mm^-1", Dimension::WAVEVECTOR, 1e3);
        check("1 mm^2", Dimension::AREA, 1e-6);
        check("2 m²", Dimension::AREA, 2.0);
        check("1 m3", Dimension::VOLUME, 1.0);
        check("1 m³", Dimension::VOLUME, 1.0);
        check("1 L", Dimension::VOLUME, 1e-3);
        check("250 ml", Dimension::VOLUME, 0.25e-3);
        check("1e-30 m^4", Dimension::SPECTRUM, 1e-30);
        check("1e12 1/m^3", Dimension::NUMBER_DENSITY, 1e12);
    }

    #[test]
    fn viscosities() {
        for text in [
            "1e-3 Pa*s",
            "1 mPa*s",
            "1 mPa s",
            "1 mPa·s",
            "1 mPa⋅s",
            "1 mPa.s",
            "1 cP",
            "1e-2 P",
        ] {
            check(text, Dimension::VISCOSITY, 1e-3);
        }
        check("1 Pa s", Dimension::VISCOSITY, 1.0);
        check("1 kg/m/s", Dimension::VISCOSITY, 1.0);
    }

    #[test]
    fn times_and_rates() {
        check("30 year", Dimension::TIME, 30.0 * 365.25 * 86400.0);
        check("30 yr", Dimension::TIME, 946_728_000.0);
        check("1 day", Dimension::TIME, 86400.0);
        check("1 d", Dimension::TIME, 86400.0);
        check("1 week", Dimension::TIME, 604_800.0);
        check("2 h", Dimension::TIME, 7200.0);
        check("2 hr", Dimension::TIME, 7200.0);
        check("1.5 min", Dimension::TIME, 90.0);
        check("10 ms", Dimension::TIME, 0.01);
        check("50 Hz", Dimension::FREQUENCY, 50.0);
        check("1 1/s", Dimension::FREQUENCY, 1.0);
        check("1 kHz", Dimension::FREQUENCY, 1000.0);
        check("1e-9 m^3/s", Dimension::VOLUME_FLOW, 1e-9);
        check("1 L/min", Dimension::VOLUME_FLOW, 1.0 / 60_000.0);
        check("1 mL/h", Dimension::VOLUME_FLOW, 1e-6 / 3600.0);
        check("1 cm/s", Dimension::VELOCITY, 0.01);
        check("90 kJ/mol", Dimension::MOLAR_ENERGY, 9e4);
        check("1 N/m", Dimension::FORCE_PER_LENGTH, 1.0);
        check("1 kg*m/s^2", Dimension::FORCE, 1.0);
        check("1 mW", Dimension::POWER, 1e-3);
    }

    #[test]
    fn temperatures() {
        check_kelvin("80 C", 353.15);
        check_kelvin("80 °C", 353.15);
        check_kelvin("80degC", 353.15);
        check_kelvin("300 K", 300.0);
        check_kelvin("500 mK", 0.5);
        check_kelvin("32 F", 273.15);
        check_kelvin("32 °F", 273.15);
        check_kelvin("212 degF", 373.15);
        check_kelvin("-40 F", 233.15);
        check_kelvin("-40 C", 233.15);
        check_kelvin("0 K", 0.0);

        check("101.6 K", Dimension::TEMPERATURE, 101.6);
        check("10 C", Dimension::TEMPERATURE, 10.0);
        check("9 F", Dimension::TEMPERATURE, 5.0);
        check("9 °F", Dimension::TEMPERATURE, 5.0);
        check("1.2e-5 1/K", Dimension::THERMAL_EXPANSION, 1.2e-5);
        check("1.2e-5 K^-1", Dimension::THERMAL_EXPANSION, 1.2e-5);
        check("1.2e-5 1/C", Dimension::THERMAL_EXPANSION, 1.2e-5);
        check("1.2e-5 /°C", Dimension::THERMAL_EXPANSION, 1.2e-5);
        check("1 1/F", Dimension::THERMAL_EXPANSION, 1.8);

        assert_eq!(absolute_temperature(80.0, "C"), Ok(353.15));
        assert_eq!(absolute_temperature(300.0, " K "), Ok(300.0));
    }

    #[test]
    fn temperature_errors() {
        assert!(matches!(
            parse_temperature("-300 C"),
            Err(UnitError::BelowAbsoluteZero { kelvin }) if close(kelvin, -26.85, 1e-12)
        ));
        assert!(matches!(
            parse_temperature("-1 K"),
            Err(UnitError::BelowAbsoluteZero { .. })
        ));
        assert!(matches!(
            parse_temperature("-500 F"),
            Err(UnitError::BelowAbsoluteZero { .. })
        ));
        assert_eq!(
            parse_temperature("80"),
            Err(UnitError::MissingUnit {
                expected: Dimension::TEMPERATURE
            })
        );
        assert_eq!(
            parse_temperature("80 Pa"),
            Err(UnitError::WrongDimension {
                unit: "Pa".into(),
                found: Dimension::PRESSURE,
                expected: Dimension::TEMPERATURE
            })
        );
        for unit in ["C/s", "°F*m", "K/C", "C^2", "1/C^2", "m C", "/C/s"] {
            let text = format!("80 {unit}");
            assert_eq!(
                parse_quantity(&text, Dimension::DIMENSIONLESS),
                Err(UnitError::AffineInCompound { unit: unit.into() }),
                "{text}"
            );
        }
        assert_eq!(
            parse_quantity("80 C", Dimension::PRESSURE),
            Err(UnitError::WrongDimension {
                unit: "C".into(),
                found: Dimension::TEMPERATURE,
                expected: Dimension::PRESSURE
            })
        );
    }

    #[test]
    fn errors() {
        assert_eq!(
            parse_quantity("10 m", Dimension::PRESSURE),
            Err(UnitError::WrongDimension {
                unit: "m".into(),
                found: Dimension::LENGTH,
                expected: Dimension::PRESSURE
            })
        );
        assert_eq!(
            parse_quantity("5", Dimension::PRESSURE),
            Err(UnitError::MissingUnit {
                expected: Dimension::PRESSURE
            })
        );
        assert_eq!(parse_quantity("5", Dimension::DIMENSIONLESS), Ok(5.0));
        assert_eq!(parse_quantity("2 m/m", Dimension::DIMENSIONLESS), Ok(2.0));
        assert_eq!(
            parse_quantity("", Dimension::PRESSURE),
            Err(UnitError::Empty)
        );
        assert_eq!(
            parse_quantity(" \t", Dimension::PRESSURE),
            Err(UnitError::Empty)
        );
        for text in ["abc", "MPa", "--1", "-", ".", "+.e5", "e5 Pa", ". Pa"] {
            assert_eq!(
                parse_quantity(text, Dimension::PRESSURE),
                Err(UnitError::BadNumber { text: text.into() }),
                "{text}"
            );
        }
        assert_eq!(
            parse_quantity("1 furlong", Dimension::LENGTH),
            Err(UnitError::UnknownUnit {
                unit: "furlong".into()
            })
        );
        assert_eq!(
            parse_quantity("1 m/furlong", Dimension::DIMENSIONLESS),
            Err(UnitError::UnknownUnit {
                unit: "furlong".into()
            })
        );
        // Not prefixable, and no hecto.
        for text in ["1 kmin", "1 kh", "1 kpsi", "1 hPa", "1 dm", "1 Pas", "1 e"] {
            assert!(
                matches!(
                    parse_quantity(text, Dimension::TIME),
                    Err(UnitError::UnknownUnit { .. })
                ),
                "{text}"
            );
        }
        for text in [
            "nan Pa", "NaN Pa", "inf Pa", "-inf Pa", "Infinity", "1e400 Pa",
        ] {
            assert_eq!(
                parse_quantity(text, Dimension::PRESSURE),
                Err(UnitError::NotFinite { text: text.into() }),
                "{text}"
            );
        }
        // Finite number, but the result overflows.
        assert!(matches!(
            parse_quantity("1e300 PPa", Dimension::PRESSURE),
            Err(UnitError::NotFinite { .. })
        ));
        for text in [
            "1 /",
            "1 ^",
            "1 m^",
            "1 m^-",
            "1 m//s",
            "1 m^999",
            "1 m^-999",
            "1 m**s",
            "1 m*",
            "1 *m",
            "1 m .s",
            "1 m.",
            "1 m2x",
            "1 m$",
            "1 1",
            "1 m/1",
            "1 fm^-100",
        ] {
            assert!(
                matches!(
                    parse_quantity(text, Dimension::LENGTH),
                    Err(UnitError::MalformedUnit { .. })
                ),
                "{text}: {:?}",
                parse_quantity(text, Dimension::LENGTH)
            );
        }
    }

    #[test]
    fn case_sensitive() {
        check("1 mPa", Dimension::PRESSURE, 1e-3);
        check("1 MPa", Dimension::PRESSURE, 1e6);
        assert!(parse_quantity("1 mpa", Dimension::PRESSURE).is_err());
    }

    #[test]
    fn unit_alone() {
        assert_eq!(parse_unit("m^3/s"), Ok((1.0, Dimension::VOLUME_FLOW)));
        assert_eq!(parse_unit(" MPa "), Ok((1e6, Dimension::PRESSURE)));
        assert_eq!(parse_unit("1/K"), Ok((1.0, Dimension::THERMAL_EXPANSION)));
        assert_eq!(parse_unit("C"), Ok((1.0, Dimension::TEMPERATURE)));
        assert_eq!(
            parse_unit("m/s/s"),
            Ok((1.0, Dimension::new(1, 0, -2, 0, 0)))
        );
        assert_eq!(parse_unit("m/s^2"), parse_unit("m/s/s"));
        assert_eq!(parse_unit(""), Err(UnitError::Empty));
        let (factor, dimension) = parse_unit("F").expect("F is a unit");
        assert!(close(factor, 5.0 / 9.0, 1e-15));
        assert_eq!(dimension, Dimension::TEMPERATURE);
    }

    #[test]
    fn describe_and_display() {
        assert!(Dimension::PRESSURE.describe().contains("pressure"));
        assert_eq!(Dimension::LENGTH.describe(), "length");
        assert_eq!(Dimension::WAVEVECTOR.describe(), "wavevector (1/length)");
        assert_eq!(Dimension::new(1, 1, 0, 0, 0).describe(), "m·kg");
        assert_eq!(Dimension::new(-1, 1, -3, 0, 0).describe(), "m^-1·kg·s^-3");
        assert_eq!(Dimension::DIMENSIONLESS.formula(), "1");

        let message = parse_quantity("10 m", Dimension::PRESSURE)
            .expect_err("length is not pressure")
            .to_string();
        assert_eq!(
            message,
            "expected a pressure (e.g. \"10 MPa\"), but \"m\" is a length"
        );
        let message = parse_quantity("1 m^2", Dimension::VISCOSITY)
            .expect_err("area is not viscosity")
            .to_string();
        assert!(message.contains("is an area"), "{message}");
        let message = parse_quantity("1 m*kg", Dimension::PRESSURE)
            .expect_err("wrong dimension")
            .to_string();
        assert!(message.contains("has dimension m·kg"), "{message}");
        let message = UnitError::MissingUnit {
            expected: Dimension::VOLUME_FLOW,
        }
        .to_string();
        assert!(message.contains("1e-9 m^3/s"), "{message}");
    }

    #[test]
    fn the_units_a_fix_suggests_are_accepted() {
        for named in NAMED_DIMENSIONS {
            let d = named.dimension;
            for unit in d.engineering_units() {
                let text = format!("2.5 {unit}");
                let v = parse_quantity(&text, d).unwrap_or_else(|e| panic!("{text}: {e}"));
                assert!(v.is_finite() && v > 0.0, "{text}");
            }
            let fix = d.bare_number_fix(210.0);
            assert!(fix.contains("needs its unit"), "{fix}");
        }
        assert_eq!(
            Dimension::PRESSURE.bare_number_fix(210.0),
            "a pressure needs its unit: write \"210 bar\", \"210 MPa\" or \"210 psi\" (the one \
             you mean; a bare number is ambiguous)"
        );
    }

    #[test]
    fn named_dimensions_are_distinct_and_parse_their_examples() {
        for (i, a) in NAMED_DIMENSIONS.iter().enumerate() {
            for b in &NAMED_DIMENSIONS[i + 1..] {
                assert_ne!(a.dimension, b.dimension, "{} / {}", a.name, b.name);
            }
            assert!(
                parse_quantity(a.example, a.dimension).is_ok(),
                "example {:?} of {}",
                a.example,
                a.name
            );
        }
    }

    /// Units with factors to SI written out independently of the unit table.
    const KNOWN: &[(&str, f64, Dimension)] = &[
        ("Pa", 1.0, Dimension::PRESSURE),
        ("MPa", 1e6, Dimension::PRESSURE),
        ("kPa", 1e3, Dimension::PRESSURE),
        ("bar", 1e5, Dimension::PRESSURE),
        ("psi", 6894.757293168, Dimension::PRESSURE),
        ("m", 1.0, Dimension::LENGTH),
        ("um", 1e-6, Dimension::LENGTH),
        ("µm", 1e-6, Dimension::LENGTH),
        ("nm", 1e-9, Dimension::LENGTH),
        ("mm", 1e-3, Dimension::LENGTH),
        ("1/m", 1.0, Dimension::WAVEVECTOR),
        ("1/mm", 1e3, Dimension::WAVEVECTOR),
        ("mm^2", 1e-6, Dimension::AREA),
        ("h", 3600.0, Dimension::TIME),
        ("year", 31_557_600.0, Dimension::TIME),
        ("mPa*s", 1e-3, Dimension::VISCOSITY),
        ("cP", 1e-3, Dimension::VISCOSITY),
        ("cSt", 1e-6, Dimension::KINEMATIC_VISCOSITY),
        ("mm^2/s", 1e-6, Dimension::KINEMATIC_VISCOSITY),
        ("kg/m^3", 1.0, Dimension::DENSITY),
        ("m^3/s", 1.0, Dimension::VOLUME_FLOW),
        ("L/min", 1.0 / 60_000.0, Dimension::VOLUME_FLOW),
        ("kJ/mol", 1e3, Dimension::MOLAR_ENERGY),
        ("K", 1.0, Dimension::TEMPERATURE),
        ("C", 1.0, Dimension::TEMPERATURE),
        ("1/K", 1.0, Dimension::THERMAL_EXPANSION),
    ];

    proptest! {
        #[test]
        fn converts_known_units(
            mantissa in -10.0f64..10.0,
            exponent in -250i32..250,
            index in 0..KNOWN.len(),
        ) {
            let x = mantissa * 10f64.powi(exponent);
            let (unit, factor, dimension) = KNOWN[index];
            let expected = x * factor;
            let text = format!("{x:e} {unit}");
            let got = parse_quantity(&text, dimension);
            prop_assert!(
                matches!(got, Ok(v) if (v - expected).abs() <= 1e-15 * expected.abs()),
                "{} -> {:?}, expected {}", text, got, expected
            );
        }

        #[test]
        fn never_panics_on_arbitrary_text(text in ".*") {
            let _ = parse_quantity(&text, Dimension::PRESSURE);
            let _ = parse_quantity(&text, Dimension::DIMENSIONLESS);
            let _ = parse_temperature(&text);
            let _ = parse_unit(&text);
        }

        #[test]
        fn never_panics_on_any_string(text in any::<String>()) {
            let _ = parse_quantity(&text, Dimension::LENGTH);
            let _ = parse_temperature(&text);
            let _ = parse_unit(&text);
        }

        #[test]
        fn never_panics_on_unit_like_text(
            text in "[-+]?[0-9.eE]{0,5} ?[a-zA-Zµμ°/*·.^0-9⁻²³ +-]{0,14}",
        ) {
            for dimension in [Dimension::DIMENSIONLESS, Dimension::PRESSURE, Dimension::TEMPERATURE] {
                if let Ok(v) = parse_quantity(&text, dimension) {
                    prop_assert!(v.is_finite());
                }
            }
            if let Ok(k) = parse_temperature(&text) {
                prop_assert!(k.is_finite() && k >= 0.0);
            }
            if let Ok((factor, _)) = parse_unit(&text) {
                prop_assert!(factor.is_finite() && factor > 0.0);
            }
        }
    }
}
