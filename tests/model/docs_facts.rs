//! The guide's and README's statements of fact about the model, checked against the code
//! (issue 42 item 9). The guide test (tests/guide.rs) runs the quoted commands and compares
//! their outputs; these tests read the prose around them, where three stale statements were
//! found by a new user (a tutorial said back-up rings are not modelled, another that a history
//! without a units row is read as seconds and kelvin, and gave silicone's calorimetric T_g where
//! the library's effective T_g stands):
//!
//! - [`library_figures_in_the_prose_are_the_librarys`]: every T10, T_g and thermal expansion
//!   written next to a library compound is that compound's figure, to the printed digits;
//! - [`nothing_modelled_is_said_to_be_unmodelled`]: no sentence says a feature the scenario
//!   keys model is not modelled;
//! - [`what_the_prose_says_of_units_rows_the_readers_do`]: every sentence about a data file's
//!   units row agrees with the readers, which refuse a file without one.
//!
//! Each check is also run on the stale sentence it would have caught (`*_catches_*`).

use regex::Regex;
use sealsim::scenario::library;
use std::path::{Path, PathBuf};

/// The Markdown the user reads: the guide's pages, the model reference and the README
/// (docs/src/model/ is generated from docs/model.md: read once, in the source).
fn pages() -> Vec<(PathBuf, String)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![root.join("README.md"), root.join("docs/model.md")];
    let mut stack = vec![root.join("docs/src")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                if !path.ends_with("docs/src/model") {
                    stack.push(path);
                }
            } else if path.extension().is_some_and(|e| e == "md") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .collect()
}

/// The prose paragraphs of a page with their first line (1-based): fenced code blocks (the
/// quoted outputs, checked by the guide test) and tables are left out; lines are joined so a
/// sentence broken over lines reads as one.
fn paragraphs(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut current = String::new();
    let mut start = 0;
    let mut fenced = false;
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("```") {
            fenced = !fenced;
        }
        let prose = !fenced && !trimmed.starts_with("```") && !trimmed.starts_with('|');
        if prose && !trimmed.is_empty() {
            if current.is_empty() {
                start = i + 1;
            }
            current.push(' ');
            current.push_str(trimmed);
        } else if !current.is_empty() {
            out.push((start, std::mem::take(&mut current)));
        }
    }
    if !current.is_empty() {
        out.push((start, current));
    }
    out
}

/// A number as written in the guide (a Unicode minus, or a hyphen) and the half-unit of its
/// last printed digit: the tolerance of a figure quoted to its printed precision.
fn number(s: &str) -> (f64, f64) {
    let ascii = s.replace('−', "-");
    let value: f64 = ascii.parse().unwrap();
    let mantissa = ascii.split(['e', 'E']).next().unwrap_or(&ascii);
    let decimals = mantissa.split('.').nth(1).map_or(0, str::len) as i32;
    let exponent: i32 = ascii
        .split(['e', 'E'])
        .nth(1)
        .map_or(0, |e| e.parse().unwrap());
    (value, 0.5 * 10f64.powi(exponent - decimals))
}

/// A library compound's figures the prose quotes: T10 and the (effective) T_g in °C, the
/// rubbery thermal expansion in 1/K.
struct Compound {
    id: &'static str,
    /// The class acronym its name starts with (`NBR`, `VMQ`, …), unique in the library.
    class: String,
    t10_c: Option<f64>,
    tg_c: Option<f64>,
    expansion: Option<f64>,
}

fn compounds() -> Vec<Compound> {
    library::ids()
        .map(|id| {
            let m = library::get(id).unwrap().load().unwrap();
            Compound {
                id,
                class: m.name.split_whitespace().next().unwrap().to_string(),
                t10_c: m.low_temperature_limit().map(|t| t - 273.15),
                tg_c: m.glass_transition.map(|t| t - 273.15),
                expansion: m.thermal_expansion,
            }
        })
        .collect()
}

/// The figures of one paragraph that contradict the library: each T10/T_g/expansion is
/// attributed to the compound named nearest to it in the paragraph (by id or class acronym).
fn wrong_library_figures(paragraph: &str, compounds: &[Compound]) -> Vec<String> {
    let names: Vec<(usize, &Compound)> = compounds
        .iter()
        .flat_map(|c| {
            let pattern = format!(r"\b(?:{}|{})\b", regex::escape(c.id), c.class);
            let re = Regex::new(&pattern).unwrap();
            re.find_iter(paragraph)
                .map(|m| (m.start(), c))
                .collect::<Vec<_>>()
        })
        .collect();
    if names.is_empty() {
        return Vec::new();
    }
    let nearest = |at: usize| {
        names
            .iter()
            .min_by_key(|(pos, _)| pos.abs_diff(at))
            .map(|&(_, c)| c)
    };
    let num = r"([−-]?\d+(?:\.\d+)?)";
    let checks: [(&str, Regex); 4] = [
        (
            "T10",
            Regex::new(&format!(r"T10\s*(?:=|of|is)\s*{num}\s*°C")).unwrap(),
        ),
        (
            "low-temperature limit",
            Regex::new(&format!(r"low-temperature limit(?: is| of)?\s*{num}\s*°C")).unwrap(),
        ),
        (
            "T_g",
            Regex::new(&format!(
                r"(calorimetric\s+)?T_g\s*(?:=|of|is)\s*{num}\s*°C"
            ))
            .unwrap(),
        ),
        (
            "expansion",
            Regex::new(r"([a-z]+-\d+):\s*(\d+(?:\.\d+)?e[−-]?\d+)\s*1/K").unwrap(),
        ),
    ];
    let mut wrong = Vec::new();
    for (what, re) in &checks {
        for cap in re.captures_iter(paragraph) {
            let whole = cap.get(0).unwrap();
            let (compound, written, library) = match *what {
                "expansion" => {
                    let Some(c) = compounds.iter().find(|c| c.id == &cap[1]) else {
                        continue;
                    };
                    (c, &cap[2], c.expansion)
                }
                "T_g" => {
                    if cap.get(1).is_some() {
                        // a calorimetric T_g is the polymer's, not the model's figure
                        continue;
                    }
                    let c = nearest(whole.start()).unwrap();
                    (c, &cap[2], c.tg_c)
                }
                _ => {
                    let c = nearest(whole.start()).unwrap();
                    (c, &cap[1], c.t10_c)
                }
            };
            let (value, half_digit) = number(written);
            let ok = library.is_some_and(|l| (l - value).abs() <= half_digit * (1.0 + 1e-9));
            if !ok {
                wrong.push(format!(
                    "{what} of {} written {written}, the library has {library:?} (\"{}\")",
                    compound.id,
                    whole.as_str()
                ));
            }
        }
    }
    wrong
}

#[test]
fn library_figures_in_the_prose_are_the_librarys() {
    let compounds = compounds();
    let mut wrong = Vec::new();
    let mut checked = 0;
    for (path, text) in pages() {
        for (line, paragraph) in paragraphs(&text) {
            if paragraph.contains("T10") || paragraph.contains("T_g") || paragraph.contains("1/K") {
                checked += 1;
            }
            for w in wrong_library_figures(&paragraph, &compounds) {
                wrong.push(format!("{}:{line}: {w}", path.display()));
            }
        }
    }
    assert!(checked > 5, "the scan found only {checked} paragraphs");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_library_figure_check_catches_the_stale_silicone_tg() {
    let compounds = compounds();
    // docs/src/tutorials/cold-start.md before 2026-11-29
    let stale = "`scenarios/cold-night-vmq.toml` is the same gland, fluid and night with a \
                 silicone ring (`library = \"vmq-70\"`, T_g = −127 °C):";
    assert_eq!(wrong_library_figures(stale, &compounds).len(), 1);
    let fixed = "(`library = \"vmq-70\"`; its low-temperature limit −55 °C, with an effective \
                 T_g of −63.5 °C that stands in for the crystallisation the model does not have \
                 — silicone's calorimetric T_g is −127 °C)";
    assert_eq!(
        wrong_library_figures(fixed, &compounds),
        Vec::<String>::new()
    );
    // and a T10 or an expansion off by one printed digit
    assert_eq!(
        wrong_library_figures("T10 = −54.83 °C for the VMQ", &compounds).len(),
        1
    );
    assert_eq!(
        wrong_library_figures("(nbr-70: 1.75e-4 1/K; steel: 1.17e-5 1/K)", &compounds).len(),
        1
    );
}

/// Features the scenario keys model, each with the phrases a sentence would name it by and
/// the registry key that models it (checked to exist, so the table cannot outlive the model).
const MODELLED: &[(&[&str], &str)] = &[
    (
        &["back-up ring", "backup ring", "anti-extrusion ring"],
        "seal.backup_rings",
    ),
    (
        &["chemical ageing", "heat ageing", "thermo-oxidative ageing"],
        "material.ageing.rate",
    ),
    (
        &["chemical compression set", "compression set of the ring"],
        "material.ageing.crosslinking",
    ),
    (
        &["thermal expansion", "housing expansion"],
        "seal.housing_expansion",
    ),
    (
        &["volume swell", "swelling in the fluid"],
        "fluid.volume_swell",
    ),
    (&["particle", "clogging"], "contamination.volume_fraction"),
    (&["permeation"], "fluid.gas"),
    (
        &["reciprocating motion", "sliding motion", "stroke cycle"],
        "motion.sliding_speed",
    ),
    (
        &["pressure history", "temperature history"],
        "environment.history",
    ),
];

/// A sentence of `paragraph` that says a modelled feature is not modelled, with the feature.
fn unmodelled_claims(paragraph: &str) -> Vec<(String, &'static str)> {
    let negation =
        Regex::new(r"(?i)(?:is|are) not modell?ed|does not model|do not model|not modell?ed")
            .unwrap();
    paragraph
        .split_inclusive(['.', ';', ')'])
        .filter(|s| negation.is_match(s))
        .flat_map(|s| {
            let lower = s.to_lowercase();
            // "ageing specific to the medium … is not modelled": the qualifier is what is not
            // modelled, said as such
            let qualified = ["specific to", "beyond", "other than", "except"]
                .iter()
                .any(|q| lower.contains(q));
            MODELLED
                .iter()
                .filter(|(phrases, _)| !qualified && phrases.iter().any(|p| lower.contains(p)))
                .map(|&(_, key)| (s.trim().to_string(), key))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// The scenario keys as dotted paths, from the generated reference (docs/src/reference/keys.md,
/// kept current by the keys staleness test): `## `[seal]`` heads a table, `| `name` |` a key.
fn scenario_keys() -> Vec<String> {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/reference/keys.md"),
    )
    .unwrap();
    let mut table = String::new();
    let mut keys = Vec::new();
    for line in text.lines() {
        if let Some(head) = line.strip_prefix("## ") {
            table = head
                .trim_matches(|c| c == '`' || c == '[' || c == ']')
                .to_string();
        } else if let Some(row) = line.strip_prefix("| `") {
            let name = row.split('`').next().unwrap_or_default();
            keys.push(format!("{table}.{name}"));
        }
    }
    keys
}

#[test]
fn nothing_modelled_is_said_to_be_unmodelled() {
    let keys = scenario_keys();
    for (_, key) in MODELLED {
        assert!(
            keys.iter().any(|k| k == key),
            "{key}: no longer a scenario key; update MODELLED"
        );
    }
    let mut wrong = Vec::new();
    for (path, text) in pages() {
        for (line, paragraph) in paragraphs(&text) {
            for (sentence, key) in unmodelled_claims(&paragraph) {
                wrong.push(format!(
                    "{}:{line}: says it is not modelled, but `{key}` models it: \"{sentence}\"",
                    path.display()
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn the_unmodelled_check_catches_the_stale_back_up_ring_sentence() {
    // docs/src/tutorials/piston-gland.md before 2026-11-29
    let stale = "At 160 bar this gland needs a smaller clearance, a harder compound or a back-up \
                 ring (sealsim does not model back-up rings).";
    assert_eq!(unmodelled_claims(stale).len(), 1);
    let medium = "ageing specific to the medium (hydrolysis in water) is not modelled";
    assert!(unmodelled_claims(medium).is_empty());
}

/// A sentence that says what happens to a data file WITHOUT a units row (read with default
/// units, optional): the readers refuse such a file, so any such sentence is stale.
fn units_row_optional_claims(paragraph: &str) -> Vec<String> {
    let optional = Regex::new(
        r"(?i)(optional units row|units row[^.;]*optional|without (it|a units row|one)[^.;]*read as|units row[^.;]*default)",
    )
    .unwrap();
    paragraph
        .split_inclusive(['.', ';'])
        .filter(|s| s.contains("units row") && optional.is_match(s))
        .filter(|s| !s.contains("refused"))
        .map(|s| s.trim().to_string())
        .collect()
}

#[test]
fn what_the_prose_says_of_units_rows_the_readers_do() {
    // the fact: a history and a line trace without a units row are refused, naming the line
    let dir = tempfile::tempdir().unwrap();
    let history = dir.path().join("h.csv");
    std::fs::write(&history, "time,temperature\n0,300\n10,320\n").unwrap();
    let scenario = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios/cold-night-nbr.toml"),
    )
    .unwrap();
    let toml = Regex::new(r#"history = "[^"]*""#)
        .unwrap()
        .replace(
            &scenario,
            format!("history = {:?}", history.display().to_string()).as_str(),
        )
        .into_owned();
    let file = dir.path().join("s.toml");
    std::fs::write(&file, toml).unwrap();
    let Err(err) = sealsim::scenario::Scenario::load(&file) else {
        panic!("a history without a units row was read");
    };
    assert!(err.to_string().contains("h.csv:2"), "{err}");
    // and the prose agrees
    let mut wrong = Vec::new();
    for (path, text) in pages() {
        for (line, paragraph) in paragraphs(&text) {
            for sentence in units_row_optional_claims(&paragraph) {
                wrong.push(format!("{}:{line}: \"{sentence}\"", path.display()));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "these say a units row is optional; the readers refuse a file without one:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_units_row_check_catches_the_stale_history_sentence() {
    // docs/src/tutorials/cold-start.md before 2026-11-29, and `surface --help` before it
    let stale = "A header row, a units row (without it the numbers are read as seconds and \
                 kelvin), then `time,temperature` points joined by straight lines.";
    assert_eq!(units_row_optional_claims(stale).len(), 1);
    let help = "one or more line traces (CSV with header x,z and an optional units row such as \
                mm,um; several files are averaged)";
    assert_eq!(units_row_optional_claims(help).len(), 1);
    let fixed = "A header row, a units row (required: a file without one is refused, naming the \
                 line, so a temperature in °C is never read as kelvin), then points.";
    assert!(units_row_optional_claims(fixed).is_empty());
}
