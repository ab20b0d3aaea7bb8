//! Validity findings (docs/model.md §9) as text lines for stderr and as structured records for
//! JSON summaries.

use crate::scenario::InputWarning;
use crate::validity::{At, Finding, Findings};
use serde::Serialize;

/// A scenario's input message in full, as the report and `--verbose` show it:
/// `warning[W034]: FILE:LINE: key: …`, or `note[N001]: FILE:LINE: key: …` for a note (what was
/// read, how a callout became a spectrum — information, not a problem); `context` (e.g. a
/// compound's id) after the prefix when given.
pub fn input_line(context: Option<&str>, warning: &InputWarning) -> String {
    let lead = context.map(|c| format!("{c}: ")).unwrap_or_default();
    let (kind, text) = kind_and_text(warning);
    format!("{kind}[{}]: {lead}{text}", warning.code.code)
}

/// A scenario's input message as one stderr line of at most
/// [`MAX_LINE`](crate::validity::MAX_LINE) characters: `warning[W034]: NAME:LINE: key: TITLE —
/// sealsim explain W034` (the full text is in the report, the JSON summary and `--verbose`).
pub fn input_short(context: Option<&str>, warning: &InputWarning) -> String {
    let lead = context.map(|c| format!("{c}: ")).unwrap_or_default();
    let (kind, _) = kind_and_text(warning);
    crate::validity::one_line(
        kind,
        warning.code.code,
        &format!("{lead}{}", warning.place),
        warning.code.title,
    )
}

/// `note` and the text without its `note: ` for a note, `warning` and the text otherwise.
fn kind_and_text(warning: &InputWarning) -> (&'static str, String) {
    match warning.text.split_once(": note: ") {
        Some((place, text)) => ("note", format!("{place}: {text}")),
        None if warning.is_note() => ("note", warning.text.clone()),
        None => ("warning", warning.text.clone()),
    }
}

/// An input warning as a JSON record: its code and its full text.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputRecord {
    /// The registered code (`W034`; `N001` … for a note).
    pub code: &'static str,
    /// The code's identifier (`gland_overfill`).
    pub id: &'static str,
    /// `warning` or `note`.
    pub kind: &'static str,
    /// The message in full (`FILE:LINE: key: …`).
    pub message: String,
}

/// Every input warning and note of a scenario as records.
pub fn input_records(warnings: &[InputWarning]) -> Vec<InputRecord> {
    warnings
        .iter()
        .map(|w| InputRecord {
            code: w.code.code,
            id: w.code.id,
            kind: kind_and_text(w).0,
            message: w.text.clone(),
        })
        .collect()
}

/// One finding as a JSON record.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FindingRecord {
    /// The limit's registered code (`W001`; `sealsim explain W001`).
    pub code: &'static str,
    /// The limit's identifier (e.g. `pressure_ratio`).
    pub id: &'static str,
    /// The quantity the limit bounds (e.g. `ΔP/P0`); `null` for a limit without a value.
    pub quantity: Option<&'static str>,
    /// Its SI unit (empty when dimensionless).
    pub unit: Option<&'static str>,
    /// The worst value of the quantity.
    pub value: Option<f64>,
    /// The bound it crossed there.
    pub bound: Option<f64>,
    /// `setup`, `installation`, `pressure` (a static point) or `time` (a life step).
    pub at: &'static str,
    /// Where the worst value occurred: time since installation \[s\] (life runs).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub worst_time_s: Option<f64>,
    /// Where the limit was first crossed \[s\] (life runs).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first_time_s: Option<f64>,
    /// Where the worst value occurred: the nominal pressure \[Pa\] (static points).
    #[serde(
        rename = "worst_nominal_pressure_Pa",
        skip_serializing_if = "Option::is_none"
    )]
    pub worst_nominal_pressure_pa: Option<f64>,
    /// How many evaluations crossed the limit.
    pub evaluations: usize,
    /// The section of docs/model.md that explains the limit.
    pub section: String,
    /// The message as printed on stderr (without `warning: `).
    pub message: String,
}

impl FindingRecord {
    pub fn new(f: &Finding) -> Self {
        let quantity = f.limit.quantity();
        let has_value = quantity.is_some() && f.value.is_finite() && f.bound.is_finite();
        let time = |at: At| match at {
            At::Time(t) => Some(t),
            _ => None,
        };
        FindingRecord {
            code: f.limit.code().code,
            id: f.limit.id(),
            quantity: quantity.map(|(q, _)| q),
            unit: quantity.map(|(_, u)| u),
            value: has_value.then_some(f.value),
            bound: has_value.then_some(f.bound),
            at: match f.at {
                At::Setup => "setup",
                At::Installation => "installation",
                At::Pressure(_) => "pressure",
                At::Time(_) => "time",
            },
            worst_time_s: time(f.at),
            first_time_s: time(f.first),
            worst_nominal_pressure_pa: match f.at {
                At::Pressure(p) => Some(p),
                _ => None,
            },
            evaluations: f.count,
            section: format!("docs/model.md {}", f.limit.section()),
            message: f.to_string(),
        }
    }
}

/// Every finding as a record, in the order they were first crossed.
pub fn records(findings: &Findings) -> Vec<FindingRecord> {
    findings.iter().map(FindingRecord::new).collect()
}

/// One `warning[W0xx]: …` line per finding in full (the report, `--verbose`), `context` (e.g. a
/// compound's id) leading each.
pub fn warning_lines(context: Option<&str>, findings: &Findings) -> String {
    let lead = context.map(|c| format!("{c}: ")).unwrap_or_default();
    findings
        .iter()
        .map(|f| format!("warning[{}]: {lead}{f}\n", f.limit.code().code))
        .collect()
}

/// One short line per finding ([`Finding::line`]: at most 120 characters with its code).
pub fn short_lines(context: Option<&str>, findings: &Findings) -> String {
    findings.iter().map(|f| f.line(context) + "\n").collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::validity;

    #[test]
    fn a_life_finding_carries_its_worst_and_first_time() {
        let mut findings = Findings::default();
        validity::squeeze(0.32, At::Time(0.0), &mut findings);
        validity::squeeze(0.35, At::Time(100.0), &mut findings);
        let r = records(&findings);
        assert_eq!(r.len(), 1);
        assert_eq!(r[0].id, "squeeze");
        assert_eq!((r[0].value, r[0].bound), (Some(0.35), Some(0.3)));
        assert_eq!(
            (r[0].worst_time_s, r[0].first_time_s),
            (Some(100.0), Some(0.0))
        );
        assert_eq!(r[0].evaluations, 2);
        assert_eq!(r[0].section, "docs/model.md §9.6");
        let json = serde_json::to_string(&r[0]).unwrap_or_default();
        assert!(json.contains("\"worst_time_s\":100.0"), "{json}");
        assert!(!json.contains("worst_nominal_pressure_Pa"), "{json}");
    }

    #[test]
    fn a_limit_without_a_value_has_null_value_and_bound() {
        let mut findings = Findings::default();
        validity::no_failure_criterion(&mut findings);
        let r = records(&findings);
        assert_eq!((r[0].value, r[0].bound, r[0].quantity), (None, None, None));
        assert!(
            warning_lines(Some("nbr-70"), &findings)
                .starts_with("warning[W013]: nbr-70: the [failure]")
        );
    }
}
