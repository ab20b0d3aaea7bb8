//! Commented, runnable starting points for a user's own files (`sealsim new TEMPLATE`): one
//! scenario per common seal arrangement and a study. The texts are the files in
//! `scenarios/templates/`, which the tests run unchanged; every key carries a comment with its
//! SI unit, accepted range and default (docs/src/reference/keys.md is the full reference).

/// What a template is a starting point for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TemplateKind {
    /// A scenario file, for `sealsim run`, `leak`, `compare`, `tradeoff`.
    Scenario,
    /// A study file, for `sealsim study`; it names a base scenario by `base = "…"`.
    Study,
}

/// One template: its name on the command line, a one-line description and its text.
#[derive(Debug, Clone, Copy)]
pub struct Template {
    /// Name as given to `sealsim new`, e.g. `o-ring-face`.
    pub name: &'static str,
    /// One line: the arrangement it models, as written.
    pub summary: &'static str,
    /// Scenario or study.
    pub kind: TemplateKind,
    /// The file's text (TOML with comments).
    pub text: &'static str,
}

/// Every template, in the order `sealsim new --list` prints them.
pub const TEMPLATES: &[Template] = &[
    Template {
        name: "o-ring-face",
        summary: "O-ring in a face (axial) gland: AS568-225 NBR, water at 2 bar and 80 °C",
        kind: TemplateKind::Scenario,
        text: include_str!("../../scenarios/templates/o-ring-face.toml"),
    },
    Template {
        name: "o-ring-piston",
        summary: "O-ring in a piston gland at hydraulic pressure: AS568-224 NBR, ISO VG 46 at 20 bar",
        kind: TemplateKind::Scenario,
        text: include_str!("../../scenarios/templates/o-ring-piston.toml"),
    },
    Template {
        name: "o-ring-rod",
        summary: "O-ring in a rod gland, static or stroking: AS568-224 NBR on a 45 mm rod",
        kind: TemplateKind::Scenario,
        text: include_str!("../../scenarios/templates/o-ring-rod.toml"),
    },
    Template {
        name: "flat-gasket",
        summary: "flat gasket under a bolt or spring load: NBR sheet, oil at 2 bar",
        kind: TemplateKind::Scenario,
        text: include_str!("../../scenarios/templates/flat-gasket.toml"),
    },
    Template {
        name: "gas-flange",
        summary: "gas seal: FKM O-ring in a vacuum flange under a helium leak test",
        kind: TemplateKind::Scenario,
        text: include_str!("../../scenarios/templates/gas-flange.toml"),
    },
    Template {
        name: "study",
        summary: "tolerance study (Latin hypercube) of a base scenario to a B10 life",
        kind: TemplateKind::Study,
        text: include_str!("../../scenarios/templates/study.toml"),
    },
];

/// The line of the study template that names its base scenario.
const STUDY_BASE_LINE: &str = "base = \"o-ring-face.toml\"";

/// The template called `name`, if there is one.
pub fn template(name: &str) -> Option<&'static Template> {
    TEMPLATES.iter().find(|t| t.name == name)
}

/// The study template's text with its `base = "…"` line naming `base` (a path relative to the
/// study file's folder, or absolute), written as a TOML basic string.
pub fn study_with_base(template: &Template, base: &str) -> String {
    let quoted = toml::Value::String(base.to_owned()).to_string();
    template
        .text
        .replacen(STUDY_BASE_LINE, &format!("base = {quoted}"), 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every template parses as TOML and the study's base line is there to be replaced (a
    /// template edited so that the substitution silently did nothing would fail here).
    #[test]
    fn templates_parse_and_the_study_base_is_replaceable() {
        for t in TEMPLATES {
            assert!(
                t.text.parse::<toml::Table>().is_ok(),
                "template {} is not TOML",
                t.name
            );
        }
        let study = template("study").map(|t| (t, t.kind));
        assert!(matches!(study, Some((_, TemplateKind::Study))));
        if let Some((t, _)) = study {
            assert!(t.text.contains(STUDY_BASE_LINE));
            let replaced = study_with_base(t, "dir with \"quote\"/base.toml");
            let table: toml::Table = replaced.parse().unwrap_or_default();
            assert_eq!(
                table.get("base").and_then(|v| v.as_str()),
                Some("dir with \"quote\"/base.toml")
            );
        }
        let mut names: Vec<&str> = TEMPLATES.iter().map(|t| t.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), TEMPLATES.len(), "template names are unique");
    }

    /// Every key a scenario template writes is a registry key of its table, its comment
    /// names the key's SI unit (a quantity) and, where the registry has a literal default,
    /// states that default as the registry writes it; a "default X" the comment states is the
    /// registry's. So the templates' comments cannot drift from the code's units and defaults.
    #[test]
    fn template_comments_agree_with_the_key_registry() {
        use super::super::keys::{self, Fallback, Kind};
        let mut checked = 0;
        let mut wrong = Vec::new();
        for t in TEMPLATES
            .iter()
            .filter(|t| t.kind == TemplateKind::Scenario)
        {
            let mut table = String::new();
            for (number, line) in t.text.lines().enumerate() {
                let line = line.trim_start_matches("# ");
                let (code, comment) = line.split_once('#').unwrap_or((line, ""));
                let code = code.trim();
                if let Some(header) = code.strip_prefix('[').and_then(|c| c.strip_suffix(']')) {
                    table = header.to_owned();
                    continue;
                }
                let Some((name, _)) = code.split_once(" = ") else {
                    continue;
                };
                let at = format!("{}:{}: {table}.{name}", t.name, number + 1);
                // the interface surfaces take the keys of [surface]
                let registry_table = match table.as_str() {
                    "groove_surface" | "rubber_surface" => "surface",
                    other => other,
                };
                let Some(key) = keys::table(registry_table)
                    .and_then(|tab| tab.keys.iter().find(|k| k.name == name.trim()))
                else {
                    wrong.push(format!("{at}: not a key of the registry"));
                    continue;
                };
                if let Kind::Quantity(field) = key.kind {
                    let unit = field.unit();
                    if !unit.is_empty()
                        && !comment.is_empty()
                        && key.name != "size"
                        && !comment.contains(unit)
                    {
                        wrong.push(format!("{at}: the comment does not name {unit}"));
                    }
                }
                let literal = match key.default {
                    Fallback::Literal(value, _) | Fallback::LiteralWhere(value, _, _) => {
                        Some(value)
                    }
                    _ => None,
                };
                if let Some((_, stated)) = comment.split_once("default ") {
                    let stated = stated.split([';', '(']).next().unwrap_or("").trim();
                    let literal_text = stated.starts_with('"')
                        || stated.chars().next().is_some_and(|c| c.is_ascii_digit());
                    if literal_text && Some(stated) != literal {
                        wrong.push(format!(
                            "{at}: states default {stated}, the registry {literal:?}"
                        ));
                    }
                    checked += 1;
                }
            }
        }
        assert!(wrong.is_empty(), "{}", wrong.join("\n"));
        assert!(
            checked >= 20,
            "only {checked} defaults stated in the templates"
        );
    }
}
