//! Tests of the key registry ([`super::keys`]): it names exactly the keys serde accepts, its
//! numeric keys carry the validator's own fields, its literal defaults are what the validator
//! assumes, and the committed reference is its rendering.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use super::Scenario;
use super::keys::{self, Fallback, Kind, TABLES};
use super::raw::*;
use serde::de::{self, Deserialize, Deserializer, Visitor};
use std::collections::BTreeSet;
use std::fmt;
use std::path::{Path, PathBuf};

/// What the recording deserializer returns: the fields serde asked for, or a refusal.
#[derive(Debug)]
enum Recorded {
    Fields(&'static [&'static str]),
    Other(String),
}

impl fmt::Display for Recorded {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Recorded::Fields(fields) => write!(f, "the fields {fields:?}"),
            Recorded::Other(message) => f.write_str(message),
        }
    }
}

impl std::error::Error for Recorded {}

impl de::Error for Recorded {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Recorded::Other(msg.to_string())
    }
}

/// A deserializer that only answers `deserialize_struct`, with the struct's field names: the
/// keys a `#[derive(Deserialize)]` struct accepts, from serde itself.
struct Recorder;

impl<'de> Deserializer<'de> for Recorder {
    type Error = Recorded;

    fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Recorded> {
        Err(Recorded::Other("not a struct".into()))
    }

    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _name: &'static str,
        fields: &'static [&'static str],
        _visitor: V,
    ) -> Result<V::Value, Recorded> {
        Err(Recorded::Fields(fields))
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
        option unit unit_struct newtype_struct seq tuple tuple_struct map enum identifier
        ignored_any
    }
}

/// The keys serde accepts for `T`.
fn accepted<'de, T: Deserialize<'de>>() -> BTreeSet<&'static str> {
    match T::deserialize(Recorder) {
        Err(Recorded::Fields(fields)) => fields.iter().copied().collect(),
        Err(other) => panic!("not a struct: {other}"),
        Ok(_) => panic!("the recorder gave a value"),
    }
}

/// Every raw table: the registry's path and the keys serde accepts there.
fn raw_tables() -> Vec<(&'static str, BTreeSet<&'static str>)> {
    vec![
        ("", accepted::<RawScenario>()),
        ("material", accepted::<RawMaterial>()),
        ("material.prony[i]", accepted::<RawPronyTerm>()),
        ("material.shift", accepted::<RawShift>()),
        ("material.ageing", accepted::<RawAgeing>()),
        (
            "material.compatibility.CLASS",
            accepted::<RawCompatibility>(),
        ),
        ("material.permeation.GAS", accepted::<RawPermeation>()),
        ("material.bands.KEY", accepted::<RawBand>()),
        ("surface", accepted::<RawSurface>()),
        ("fluid", accepted::<RawFluid>()),
        ("seal", accepted::<RawSeal>()),
        ("model", accepted::<RawModel>()),
        ("environment", accepted::<RawEnvironment>()),
        ("failure", accepted::<RawFailure>()),
        ("ageing", accepted::<RawScenarioAgeing>()),
        ("simulation", accepted::<RawSimulation>()),
        ("contamination", accepted::<RawContamination>()),
        (
            "contamination.size_distribution",
            accepted::<RawSizeDistribution>(),
        ),
        ("numerical", accepted::<RawNumerical>()),
        ("motion", accepted::<RawMotion>()),
    ]
}

#[test]
fn the_registry_names_exactly_the_keys_serde_accepts() {
    let raw = raw_tables();
    let raw_paths: BTreeSet<&str> = raw.iter().map(|(p, _)| *p).collect();
    let registry_paths: BTreeSet<&str> = TABLES.iter().map(|t| t.path).collect();
    assert_eq!(registry_paths, raw_paths, "the registry's tables");
    let mut problems = Vec::new();
    for (path, fields) in &raw {
        let table = keys::table(path).unwrap();
        let names: Vec<&str> = table.keys.iter().map(|k| k.name).collect();
        let registered: BTreeSet<&str> = names.iter().copied().collect();
        assert_eq!(
            names.len(),
            registered.len(),
            "[{path}]: a key listed twice"
        );
        let missing: Vec<_> = fields.difference(&registered).collect();
        let unknown: Vec<_> = registered.difference(fields).collect();
        if !(missing.is_empty() && unknown.is_empty()) {
            problems.push(format!(
                "[{path}]: keys without a registry entry {missing:?}; registry entries that are \
                 no key {unknown:?}"
            ));
        }
    }
    assert!(
        problems.is_empty(),
        "src/scenario/keys.rs does not list the keys serde accepts:\n{}",
        problems.join("\n")
    );
    // a study file
    let study: Vec<(&str, BTreeSet<&str>)> = vec![
        ("", accepted::<super::study::RawStudy>()),
        (
            "correlations[i]",
            accepted::<super::study::RawCorrelation>(),
        ),
    ];
    assert_eq!(keys::STUDY_TABLES.len(), study.len());
    for ((path, fields), table) in study.iter().zip(keys::STUDY_TABLES) {
        assert_eq!(table.path, *path);
        let registered: BTreeSet<&str> = table.keys.iter().map(|k| k.name).collect();
        assert_eq!(&registered, fields, "study file [{path}]");
    }
    // a material file is one [material] table
    assert_eq!(accepted::<RawMaterialFile>(), BTreeSet::from(["material"]));
    // the top level's tables are the tables `RawScenario::TABLES` reports as tables
    let top = keys::table("").unwrap();
    let tables: BTreeSet<&str> = top
        .keys
        .iter()
        .filter(|k| matches!(k.kind, Kind::Table))
        .map(|k| k.name)
        .collect();
    assert_eq!(tables, RawScenario::TABLES.iter().copied().collect());
    // every table key has its table in the registry (the two extra surfaces share [surface])
    for table in TABLES {
        for key in table.keys {
            let dotted = table.dotted(key);
            let path = match key.kind {
                Kind::Table => dotted,
                Kind::Tables => format!("{dotted}[i]"),
                _ => continue,
            };
            if path == "groove_surface" || path == "rubber_surface" {
                continue;
            }
            assert!(keys::table(&path).is_some(), "no registry table [{path}]");
        }
    }
}

/// The fields of a key (empty for a key that is no quantity).
fn fields(kind: &Kind) -> Vec<super::field::Field> {
    match kind {
        Kind::Quantity(f) | Kind::QuantityPair(f) | Kind::ChoiceOrQuantity(_, f) => vec![*f],
        Kind::Quantities(fs) => fs.iter().map(|(_, f)| *f).collect(),
        _ => Vec::new(),
    }
}

#[test]
fn every_numeric_key_carries_the_field_of_its_own_name() {
    let mut n = 0;
    for table in TABLES {
        for key in table.keys {
            for field in fields(&key.kind) {
                // errors index a list's entries: `material.prony[2].tau`
                assert_eq!(field.key, table.dotted(key).replace("[i]", ""));
                n += 1;
            }
        }
    }
    assert!(n > 90, "{n} fields");
}

#[test]
fn the_listed_words_are_the_codes() {
    let code: Vec<&str> = crate::fluid::library_ids();
    assert_eq!(keys::FLUIDS, code.as_slice());
    let mut gases = crate::gas::library_ids();
    gases.push("custom");
    assert_eq!(keys::GASES, gases.as_slice());
    let mut housings: Vec<&str> = crate::gland::Housing::ALL.map(|h| h.name()).to_vec();
    housings.insert(3, "aluminum");
    assert_eq!(keys::HOUSINGS, housings.as_slice());
    let fidelities: Vec<&str> = crate::leak::Fidelity::ALL
        .iter()
        .flat_map(|f| std::iter::once(f.name()).chain(f.aliases().iter().copied()))
        .collect();
    assert_eq!(keys::FIDELITIES, fidelities.as_slice());
    let media: Vec<&str> = crate::material::AgeingMedium::ALL
        .map(|m| m.as_str())
        .to_vec();
    assert_eq!(keys::MEDIA, media.as_slice());
    assert_eq!(keys::CLASSES, crate::permeation::FAMILIES.as_slice());
    let designs = crate::study::design::Design::ALL.map(|d| d.name());
    assert_eq!(keys::DESIGNS, designs.as_slice());
    let ratings: Vec<String> = crate::material::compatibility::Rating::ALL
        .map(|r| r.letter().to_string())
        .to_vec();
    assert_eq!(
        keys::RATINGS,
        ratings.iter().map(String::as_str).collect::<Vec<_>>()
    );
    // the provenance parameters named in [material] provenance's meaning
    let provenance = keys::table("material")
        .unwrap()
        .keys
        .iter()
        .find(|k| k.name == "provenance")
        .unwrap();
    for p in super::PARAMETERS {
        assert!(provenance.doc.contains(&format!("`{p}`")), "{p}");
    }
}

/// Scenarios to insert defaults into, besides the shipped ones: (name, text).
const BASES: &[(&str, &str)] = &[
    (
        "astm-law.toml",
        r#"
[material]
youngs_modulus = "10 MPa"
poisson_ratio = 0.5
# a bolted gasket at 60 °C follows the temperature (docs/model.md §6): it needs the rubber's CTE
thermal_expansion = "1.6e-4 1/K"
[surface]
ra = "0.8 um"
[fluid]
viscosity_40c = "46 cSt"
viscosity_100c = "6.8 cSt"
density = "870 kg/m^3"
pressure_difference = "2 bar"
[seal]
nominal_pressure = "0.5 MPa"
width = "2 mm"
length = "50 mm"
[environment]
temperature = "60 C"
[contamination]
number_concentration = "5e10 1/m^3"
size_distribution = { kind = "lognormal", median = "150 nm", geometric_std = 2.5 }
"#,
    ),
    (
        "inline-shift.toml",
        r#"
name = "inline viscoelastic"
[material]
poisson_ratio = 0.5
long_term_modulus = "4 MPa"
prony = [{ modulus = "6 MPa", tau = "1000 s" }]
thermal_expansion = "1.6e-4 1/K"
[material.shift]
kind = "wlf"
reference_temperature = "40 C"
c1 = 8.86
c2 = "101.6 K"
[surface]
ra = "0.4 um"
[fluid]
viscosity = "1e-3 Pa*s"
pressure_difference = "1 bar"
[seal]
nominal_pressure = "0.5 MPa"
width = "2 mm"
length = "50 mm"
"#,
    ),
    (
        "inline-ageing.toml",
        r#"
[material]
poisson_ratio = 0.5
long_term_modulus = "4 MPa"
prony = [{ modulus = "6 MPa", tau = "1000 s" }]
thermal_expansion = "1.6e-4 1/K"
[material.shift]
kind = "arrhenius"
reference_temperature = "23 C"
activation_energy = "90 kJ/mol"
[material.ageing]
activation_energy = "90 kJ/mol"
rate = "1e-9 1/s"
reference_temperature = "23 C"
[surface]
ra = "0.4 um"
[fluid]
viscosity = "1e-3 Pa*s"
pressure_difference = "1 bar"
[seal]
kind = "o-ring"
cross_section = "3.53 mm"
mean_diameter = "40 mm"
squeeze = "20 %"
[environment]
temperature = "60 C"
[failure]
max_leak_rate = "1 mL/h"
"#,
    ),
];

/// Every base scenario: (path it is validated as, text).
fn bases() -> Vec<(PathBuf, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let mut out: Vec<(PathBuf, String)> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .collect();
    out.sort();
    out.extend(
        BASES
            .iter()
            .map(|(name, text)| (dir.join(name), (*text).to_owned())),
    );
    out
}

/// `text` with `key = value` in table `path` ("" the top level), and the same text without
/// it but with the same tables: `None` when the key is already given, or the table cannot be
/// added (a sub-table the base lacks).
fn with_and_without(text: &str, path: &str, key: &str, value: &str) -> Option<(String, String)> {
    let parsed: toml::Table = text.parse().ok()?;
    let mut node = &parsed;
    let mut present = true;
    for part in path.split('.').filter(|p| !p.is_empty()) {
        match node.get(part).and_then(toml::Value::as_table) {
            Some(t) => node = t,
            None => {
                present = false;
                break;
            }
        }
    }
    let line = format!("{key} = {value}\n");
    if path.is_empty() {
        if parsed.contains_key(key) {
            return None;
        }
        return Some((format!("{line}{text}"), text.to_owned()));
    }
    if !present {
        // a top-level table the base lacks: add it, empty and with the key
        if path.contains('.') {
            return None;
        }
        return Some((
            format!("{text}\n[{path}]\n{line}"),
            format!("{text}\n[{path}]\n"),
        ));
    }
    if node.contains_key(key) {
        return None;
    }
    let header = format!("[{path}]");
    let mut out = String::new();
    let mut found = false;
    for l in text.split_inclusive('\n') {
        out.push_str(l);
        let bare = l.split('#').next().unwrap_or("").trim();
        if !found && bare == header {
            if !l.ends_with('\n') {
                out.push('\n');
            }
            out.push_str(&line);
            found = true;
        }
    }
    // a table written inline or by dotted keys: not this test's business
    found.then(|| (out, text.to_owned()))
}

/// The scenario with its warnings' line numbers removed (inserting a line moves them), and
/// the words by which a note says that a value it prints is a default (a callout's `H = 0.8
/// (default)`, `short_wavelength = "extend", the default`).
fn unlined(mut s: Scenario) -> Scenario {
    for w in &mut s.warnings {
        let text = w
            .text
            .replace(" (default)", "")
            .replace(", the default", "");
        let mut out = String::new();
        let mut rest = text.as_str();
        while let Some(i) = rest.find(".toml:") {
            out.push_str(&rest[..i + 6]);
            rest = rest[i + 6..].trim_start_matches(|c: char| c.is_ascii_digit());
            out.push('N');
        }
        out.push_str(rest);
        w.text = out;
        w.place = String::new();
    }
    s
}

/// The value at dotted `path` of `table`.
fn lookup<'a>(table: &'a toml::Table, path: &str) -> Option<&'a toml::Value> {
    let mut parts = path.split('.');
    let mut value = table.get(parts.next()?)?;
    for part in parts {
        value = value.as_table()?.get(part)?;
    }
    Some(value)
}

/// The TOML text an absent key is taken as in the base scenario `parsed` (`None`: the default
/// does not apply there, or is not a value to write).
fn default_text(default: &Fallback, parsed: &toml::Table) -> Option<String> {
    match default {
        Fallback::Literal(value, _) => Some((*value).to_owned()),
        Fallback::LiteralWhere(value, _, given) => {
            lookup(parsed, given).map(|_| (*value).to_owned())
        }
        Fallback::SameAs(from, _) => lookup(parsed, from).map(toml::Value::to_string),
        Fallback::Required(_) | Fallback::Absent(_) | Fallback::Derived(_) => None,
    }
}

#[test]
fn every_literal_default_is_what_an_absent_key_means() {
    let bases: Vec<(PathBuf, String, toml::Table)> = bases()
        .into_iter()
        .map(|(path, text)| {
            let parsed = text.parse().unwrap();
            (path, text, parsed)
        })
        .collect();
    let (mut defaults, mut checked) = (0, 0);
    let (mut unchecked, mut wrong) = (Vec::new(), Vec::new());
    for table in TABLES {
        for key in table.keys {
            match key.default {
                Fallback::Required(_) | Fallback::Absent(_) => continue,
                Fallback::Derived(_) => {
                    defaults += 1;
                    continue;
                }
                _ => defaults += 1,
            }
            let dotted = table.dotted(key);
            let mut compared = 0;
            for (path, text, parsed) in &bases {
                let Some(value) = default_text(&key.default, parsed) else {
                    continue;
                };
                let Some((with, without)) = with_and_without(text, table.path, key.name, &value)
                else {
                    continue;
                };
                let (Ok(a), Ok(b)) = (
                    Scenario::from_str(&without, path),
                    Scenario::from_str(&with, path),
                ) else {
                    // the base is not a place for the key (e.g. a gas key with a liquid)
                    continue;
                };
                let (a, b) = (unlined(a), unlined(b));
                if a != b {
                    let how = if a.warnings == b.warnings {
                        "the validated scenarios differ".to_owned()
                    } else {
                        let (x, y) = a
                            .warnings
                            .iter()
                            .zip(&b.warnings)
                            .find(|(x, y)| x != y)
                            .map_or((None, None), |(x, y)| (Some(x), Some(y)));
                        format!("the warnings differ: {x:?} against {y:?}")
                    };
                    wrong.push(format!(
                        "{dotted}: absent is not `{} = {value}` in {}: {how}",
                        key.name,
                        path.display()
                    ));
                }
                compared += 1;
            }
            if compared == 0 {
                unchecked.push(dotted);
            } else {
                checked += 1;
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert!(
        unchecked.is_empty(),
        "defaults no base scenario could check: {unchecked:?}"
    );
    eprintln!(
        "{checked} of {defaults} defaults checked; the others depend on other keys or the \
         compound"
    );
    // the derived defaults are the exception
    assert!(
        checked * 4 >= defaults * 3,
        "{checked} of {defaults} defaults checked"
    );
}

#[test]
fn every_literal_default_of_a_study_file_is_what_an_absent_key_means() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/studies");
    let bases: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.to_string_lossy().ends_with(".study.toml"))
        .collect();
    assert!(!bases.is_empty());
    // a study as validated, but for its text, the fingerprint of the text and its inputs'
    // lines (inserting a line moves them)
    let load = |text: &str, path: &Path| {
        super::study::Study::from_str(text, path).ok().map(|mut s| {
            s.fingerprint.clear();
            for input in &mut s.inputs {
                input.line = 0;
            }
            format!("{s:?}").replace(&format!("{text:?}"), "TEXT")
        })
    };
    let mut checked = 0;
    for table in keys::STUDY_TABLES {
        for key in table.keys {
            let Fallback::Literal(value, _) = key.default else {
                continue;
            };
            let mut compared = 0;
            for path in &bases {
                let text = std::fs::read_to_string(path).unwrap();
                let Some((with, without)) = with_and_without(&text, table.path, key.name, value)
                else {
                    continue;
                };
                let (Some(a), Some(b)) = (load(&without, path), load(&with, path)) else {
                    continue;
                };
                assert!(a == b, "study {}: absent is not `{value}`", key.name);
                compared += 1;
            }
            assert!(compared > 0, "study {}: no base could check it", key.name);
            checked += 1;
        }
    }
    assert_eq!(checked, 5);
}

/// The committed reference.
const REFERENCE: &str = "docs/src/reference/keys.md";

#[test]
fn the_committed_key_reference_is_the_registry_rendered() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(REFERENCE);
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == keys::markdown(),
        "{REFERENCE} is not what the key registry (src/scenario/keys.rs) renders: regenerate it \
         with `cargo run --release -- generate keys -o {REFERENCE}`"
    );
}
