//! `sealsim advise`'s outputs (docs/model.md §16): the verdict and the target, the verified
//! changes (each as the TOML keys it sets, its life and margin, the runs it took), the
//! sensitivity table; the same as JSON (SI); each proposal as a runnable scenario.

use crate::report::life::{human_time, verdict};
use crate::units::human;
use crate::workflow::advise::{Advice, Domain, Margin, Measure, Proposal};
use serde::Serialize;

/// The life or margin of a measure in words: "survives 10 years; retained_force 44 % (limit
/// 10 %): margin +340 %", "FAILS after 407 days by retained_force (−89 % of the target)".
pub fn measure_text(m: &Measure, target: f64) -> String {
    match (m.life, m.mode) {
        (Some(t), mode) => {
            let when = if t == 0.0 {
                "at installation".to_owned()
            } else {
                format!("after {}", human_time(t))
            };
            format!(
                "{} {when} by {} ({}% of the target)",
                if mode == Some("open") {
                    "OPEN"
                } else {
                    "FAILS"
                },
                mode.unwrap_or("?"),
                signed(100.0 * (t / target - 1.0))
            )
        }
        (None, _) if m.undecided => format!(
            "survives {} here, but the neighbouring level does not: UNDECIDED",
            human_time(target)
        ),
        (None, _) => match &m.margin {
            Some(margin) => format!(
                "survives {}; {}: margin {}%",
                human_time(target),
                margin_text(margin),
                signed(100.0 * margin.margin)
            ),
            None => format!(
                "survives {} (no criterion with a margin)",
                human_time(target)
            ),
        },
    }
}

fn signed(x: f64) -> String {
    let h = human(x, 2);
    if x > 0.0 { format!("+{h}") } else { h }
}

/// The limiting quantity's worst value against its criterion.
fn margin_text(m: &Margin) -> String {
    match m.quantity {
        "retained_force" | "compression_set" => format!(
            "{} {} % (limit {} %)",
            m.quantity,
            human(100.0 * m.value, 3),
            human(100.0 * m.limit, 3)
        ),
        _ => format!(
            "{} {} (limit {}, SI)",
            m.quantity,
            human(m.value, 3),
            human(m.limit, 3)
        ),
    }
}

/// The changes of a proposal as `key = value` (TOML), with their notes.
pub fn changes_text(p: &Proposal) -> String {
    let mut parts = Vec::new();
    for (k, v) in &p.setting.values {
        parts.push(format!("{k} = {v}"));
    }
    let notes: Vec<&str> = p
        .setting
        .notes
        .iter()
        .map(String::as_str)
        .filter(|n| !n.is_empty())
        .collect();
    let mut out = parts.join(", ");
    if !notes.is_empty() {
        out += &format!(" ({})", notes.join("; "));
    }
    out
}

/// The terminal text: the verdict first, then the changes, the sensitivity, what was skipped.
pub fn text(a: &Advice, file: &str) -> String {
    let target = human_time(a.target);
    let mut out = format!("{} ({file})\n", a.base.name);
    let v = verdict(&a.base.life, &a.base_result);
    let passing: Vec<&Proposal> = a.proposals.iter().filter(|p| p.measure.passes).collect();
    if a.base_measure.passes {
        out += &format!(
            "{}; target {target}: it already passes — {}. No change is needed.\n",
            v.text,
            measure_text(&a.base_measure, a.target)
        );
    } else if passing.is_empty() {
        out += &format!(
            "{}; target {target}. No change within the bounds passes; the best found:\n",
            v.text
        );
    } else {
        out += &format!(
            "{}; target {target}. {} change{} pass{}:\n",
            v.text,
            passing.len(),
            if passing.len() == 1 { "" } else { "s" },
            if passing.len() == 1 { "es" } else { "" }
        );
    }
    for (i, p) in a.proposals.iter().enumerate() {
        out += &format!(
            "{:>3}. {}\n     {} [{} run{}]\n",
            i + 1,
            changes_text(p),
            measure_text(&p.measure, a.target),
            p.runs,
            if p.runs == 1 { "" } else { "s" }
        );
    }
    out += "\nsensitivity (each variable ±5 % within its admissible range; the change of \
            life/target − 1, or of the limiting margin once the target is met):\n";
    let rows: Vec<Vec<String>> = a
        .sensitivity
        .iter()
        .map(|r| {
            let cell = |s: &Option<(String, Measure)>| match s {
                Some((value, m)) => format!("{value}: {}", short(m, a.target)),
                None => "—".to_owned(),
            };
            vec![
                r.key.clone(),
                r.base.clone(),
                cell(&r.down),
                cell(&r.up),
                format!(
                    "{}{}",
                    human(r.effect, 2),
                    if r.domain == Domain::Service {
                        " (the service: information only)"
                    } else {
                        ""
                    }
                ),
            ]
        })
        .collect();
    out += &columns(&["key", "base", "down", "up", "effect"], &rows);
    out += &format!("the base: {}\n", short(&a.base_measure, a.target));
    for s in &a.skipped {
        out += &format!("not varied: {}: {}\n", s.what, s.why);
    }
    out += &format!(
        "{} life runs of at most {}{}; every listed change verified by a full run (docs/model.md \
         §16)\n",
        a.runs,
        a.max_runs,
        if a.exhausted {
            " (the bound stopped the search: raise --max-runs for more)"
        } else {
            ""
        }
    );
    out
}

/// A measure in a few words for the table.
fn short(m: &Measure, target: f64) -> String {
    match (m.life, &m.margin) {
        (Some(t), _) => {
            format!("{} by {}", human_time(t), m.mode.unwrap_or("?"))
                + &format!(" ({}%)", signed(100.0 * (t / target - 1.0)))
        }
        (None, Some(margin)) => format!(
            "passes, {} margin {}%",
            margin.quantity,
            signed(100.0 * margin.margin)
        ),
        (None, None) => "passes".to_owned(),
    }
}

/// Left-aligned columns, two spaces apart.
fn columns(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut width: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for r in rows {
        for (w, c) in width.iter_mut().zip(r) {
            *w = (*w).max(c.chars().count());
        }
    }
    let line = |cells: Vec<&str>| -> String {
        let mut s = String::new();
        for (i, (c, w)) in cells.iter().zip(&width).enumerate() {
            if i + 1 == cells.len() {
                s += c;
            } else {
                s += &format!("{c}{}  ", " ".repeat(w - c.chars().count()));
            }
        }
        s.trim_end().to_owned() + "\n"
    };
    let mut out = line(header.to_vec());
    for r in rows {
        out += &line(r.iter().map(String::as_str).collect());
    }
    out
}

#[derive(Serialize)]
struct JsonMargin<'a> {
    quantity: &'a str,
    value: f64,
    limit: f64,
    margin: f64,
}

#[derive(Serialize)]
struct JsonMeasure<'a> {
    passes: bool,
    /// When it failed or opened within the target \[s\]; null: it did neither.
    life_s: Option<f64>,
    mode: Option<&'a str>,
    undecided: bool,
    margin: Option<JsonMargin<'a>>,
    score: f64,
}

impl<'a> JsonMeasure<'a> {
    fn of(m: &'a Measure) -> Self {
        JsonMeasure {
            passes: m.passes,
            life_s: m.life,
            mode: m.mode,
            undecided: m.undecided,
            margin: m.margin.as_ref().map(|g| JsonMargin {
                quantity: g.quantity,
                value: g.value,
                limit: g.limit,
                margin: g.margin,
            }),
            score: m.score,
        }
    }
}

#[derive(Serialize)]
struct JsonChange {
    key: String,
    /// The TOML value as the scenario would read it (a unit string).
    value: String,
}

#[derive(Serialize)]
struct JsonProposal<'a> {
    changes: Vec<JsonChange>,
    notes: Vec<&'a str>,
    variables: &'a [String],
    #[serde(flatten)]
    measure: JsonMeasure<'a>,
    runs: usize,
}

#[derive(Serialize)]
struct JsonStep<'a> {
    value: &'a str,
    #[serde(flatten)]
    measure: JsonMeasure<'a>,
}

#[derive(Serialize)]
struct JsonSensitivity<'a> {
    key: &'a str,
    label: &'a str,
    service: bool,
    base: &'a str,
    down: Option<JsonStep<'a>>,
    up: Option<JsonStep<'a>>,
    effect: f64,
}

#[derive(Serialize)]
struct JsonAdvice<'a> {
    scenario: &'a str,
    name: &'a str,
    target_s: f64,
    verdict: String,
    base: JsonMeasure<'a>,
    proposals: Vec<JsonProposal<'a>>,
    sensitivity: Vec<JsonSensitivity<'a>>,
    runs: usize,
    max_runs: usize,
    exhausted: bool,
}

/// The advice as JSON (SI: times in s, margins as fractions).
pub fn json(a: &Advice, file: &str) -> Result<String, String> {
    fn step(s: &Option<(String, Measure)>) -> Option<JsonStep<'_>> {
        s.as_ref().map(|(v, m)| JsonStep {
            value: v,
            measure: JsonMeasure::of(m),
        })
    }
    let doc = JsonAdvice {
        scenario: file,
        name: &a.base.name,
        target_s: a.target,
        verdict: verdict(&a.base.life, &a.base_result).text,
        base: JsonMeasure::of(&a.base_measure),
        proposals: a
            .proposals
            .iter()
            .map(|p| JsonProposal {
                changes: p
                    .setting
                    .values
                    .iter()
                    .map(|(k, v)| JsonChange {
                        key: k.clone(),
                        value: v.to_string(),
                    })
                    .collect(),
                notes: p
                    .setting
                    .notes
                    .iter()
                    .map(String::as_str)
                    .filter(|n| !n.is_empty())
                    .collect(),
                variables: &p.variables,
                measure: JsonMeasure::of(&p.measure),
                runs: p.runs,
            })
            .collect(),
        sensitivity: a
            .sensitivity
            .iter()
            .map(|r| JsonSensitivity {
                key: &r.key,
                label: &r.label,
                service: r.domain == Domain::Service,
                base: &r.base,
                down: step(&r.down),
                up: step(&r.up),
                effect: r.effect,
            })
            .collect(),
        runs: a.runs,
        max_runs: a.max_runs,
        exhausted: a.exhausted,
    };
    let mut text = serde_json::to_string_pretty(&doc).map_err(|e| e.to_string())?;
    text.push('\n');
    Ok(text)
}

/// A proposal as a runnable scenario: a header naming the base and the change, then the
/// scenario's TOML with it.
pub fn scenario_file(a: &Advice, p: &Proposal, file: &str) -> String {
    format!(
        "# sealsim advise: {file} with {}\n# verified: {}\n{}",
        changes_text(p).replace('\n', " "),
        measure_text(&p.measure, a.target),
        p.text
    )
}
