//! A study's outputs (docs/model.md §14): the per-case table (CSV, SI units in the column
//! names) and its reading back for `study merge`, the summary as JSON and as a terminal table,
//! and (with the `cli` feature) the survival-curve and tornado charts.
//!
//! Numbers are written in Rust's shortest round-trip form, so a table read back gives the same
//! bits: a summary rebuilt from merged shard files equals the single run's.

use crate::report::life::human_time;
use crate::scenario::ScenarioError;
use crate::scenario::study::{InputKind, Study};
use crate::simulate::FailureMode;
use crate::study::design::Sampler;
use crate::study::summary::{B_LIVES, LevelLife, StudySummary};
use crate::study::{CaseOutcome, Cell};
use crate::units::{exact as num, human};
use serde_json::{Value, json};
use std::path::Path;

/// The first line of a shard's part file: `# sealsim study FINGERPRINT part K/N cases A..B of
/// TOTAL`.
const PART_PREFIX: &str = "# sealsim study ";

/// The per-case table's header.
pub fn columns(study: &Study) -> Vec<String> {
    let mut c = vec!["case".to_owned()];
    c.extend(study.inputs.iter().map(|i| i.column()));
    c.extend(["life_s", "status", "mode"].iter().map(|s| (*s).to_owned()));
    c.extend(
        study
            .report_times
            .iter()
            .map(|t| format!("leak_rate_at_{}_s_m3_per_s", num(*t))),
    );
    c.extend(
        [
            "sealing_force_end_N_per_m",
            "retained_force_end",
            "leaked_volume_end_m3",
            "compression_set_end",
            "state_end",
            "warnings",
            "invalid_reason",
        ]
        .iter()
        .map(|s| (*s).to_owned()),
    );
    c
}

fn opt(v: Option<f64>) -> String {
    v.map_or_else(String::new, num)
}

/// The per-case table (CSV) of `outcomes`: the header, then [`case_rows`].
pub fn cases_csv(
    study: &Study,
    outcomes: &[CaseOutcome],
) -> Result<String, crate::report::ReportError> {
    let mut bytes = header_row(study)?;
    bytes.extend(case_rows(study, outcomes)?);
    String::from_utf8(bytes).map_err(|e| crate::report::ReportError::Csv(e.to_string()))
}

/// The per-case table's header line (CSV).
pub fn header_row(study: &Study) -> Result<Vec<u8>, crate::report::ReportError> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let err = |e: csv::Error| crate::report::ReportError::Csv(e.to_string());
    w.write_record(columns(study)).map_err(err)?;
    w.into_inner()
        .map_err(|e| crate::report::ReportError::Csv(e.to_string()))
}

/// The per-case table's rows of `outcomes` (CSV, no header): a study's table is its header
/// followed by the rows of its blocks of cases in case order, so it can be written as the
/// blocks come.
pub fn case_rows(
    study: &Study,
    outcomes: &[CaseOutcome],
) -> Result<Vec<u8>, crate::report::ReportError> {
    let mut w = csv::Writer::from_writer(Vec::new());
    let err = |e: csv::Error| crate::report::ReportError::Csv(e.to_string());
    let width = columns(study).len();
    let mut row: Vec<String> = Vec::with_capacity(width);
    for c in outcomes {
        row.clear();
        row.push(c.index.to_string());
        row.extend(c.inputs.iter().map(|cell| match cell {
            Cell::Number(x) => num(*x),
            Cell::Word(s) => s.clone(),
        }));
        row.push(num(c.life));
        row.push(
            if c.invalid.is_some() {
                "invalid"
            } else if c.failed() {
                "failed"
            } else {
                "censored"
            }
            .to_owned(),
        );
        row.push(c.mode.map_or("", FailureMode::as_str).to_owned());
        row.extend(c.leak_rates.iter().map(|r| opt(*r)));
        row.push(num(c.final_force));
        row.push(num(c.retained_force));
        row.push(num(c.leaked_volume));
        row.push(opt(c.compression_set));
        row.push(c.final_state.clone());
        row.push(c.warnings.join(";"));
        row.push(c.invalid.clone().unwrap_or_default());
        w.write_record(&row).map_err(err)?;
    }
    w.into_inner()
        .map_err(|e| crate::report::ReportError::Csv(e.to_string()))
}

/// A shard's part file: [`part_head`], then the rows of its cases.
pub fn part_csv(
    study: &Study,
    shard: (usize, usize),
    range: std::ops::Range<usize>,
    outcomes: &[CaseOutcome],
) -> Result<String, crate::report::ReportError> {
    let mut bytes = part_head(study, shard, range)?;
    bytes.extend(case_rows(study, outcomes)?);
    String::from_utf8(bytes).map_err(|e| crate::report::ReportError::Csv(e.to_string()))
}

/// The start of shard `shard`'s part file (cases `range`): its identifying first line,
/// `# sealsim study FINGERPRINT part K/N cases A..B of TOTAL`, then the table's header.
pub fn part_head(
    study: &Study,
    shard: (usize, usize),
    range: std::ops::Range<usize>,
) -> Result<Vec<u8>, crate::report::ReportError> {
    let mut bytes = format!(
        "{PART_PREFIX}{} part {}/{} cases {}..{} of {}\n",
        study.fingerprint,
        shard.0,
        shard.1,
        range.start,
        range.end,
        study.cases(),
    )
    .into_bytes();
    bytes.extend(header_row(study)?);
    Ok(bytes)
}

/// The longest first line of a part file read (its fingerprint and cases take < 200 bytes).
const PART_LINE: u64 = 4096;

/// The cases a part file of `study` holds, from its first line (read from `reader`, which is
/// left at the second): the file must be a part file and carry the study's fingerprint.
pub fn part_cases(
    study: &Study,
    path: &Path,
    reader: &mut impl std::io::BufRead,
) -> Result<std::ops::Range<usize>, ScenarioError> {
    use std::io::{BufRead as _, Read};
    let mut first = String::new();
    Read::take(&mut *reader, PART_LINE)
        .read_line(&mut first)
        .map_err(|e| part_error(path, None, None, format!("cannot read the part file: {e}")))?;
    let header = part_header(study, path, first.trim_end_matches(['\n', '\r']))?;
    // `… part K/N cases A..B of TOTAL`
    let words: Vec<&str> = header.split_whitespace().collect();
    let range = match words.as_slice() {
        [_, "part", _, "cases", range, "of", total] => range
            .split_once("..")
            .and_then(|(a, b)| Some((a.parse::<usize>().ok()?, b.parse::<usize>().ok()?)))
            .filter(|(a, b)| {
                a <= b && *b <= study.cases() && total.parse::<usize>() == Ok(study.cases())
            }),
        _ => None,
    };
    let Some((a, b)) = range else {
        return Err(part_error(
            path,
            Some(1),
            None,
            format!(
                "the first line does not say which of the study's {} cases the part holds \
                 (`… cases A..B of {}`): the part file was edited",
                study.cases(),
                study.cases()
            ),
        ));
    };
    Ok(a..b)
}

/// The cases of one part file of `study` (`reader` at its second line, after
/// [`part_cases`]: `range`), checked and handed to `each_block` in blocks of `block` cases in
/// case order: the file must carry the study's columns, its rows the cases `range` in order,
/// and every case the inputs the study's design gives it (`design`).
pub fn read_part<E: From<ScenarioError>>(
    study: &Study,
    design: &Sampler<'_>,
    path: &Path,
    reader: impl std::io::Read,
    (range, block): (std::ops::Range<usize>, usize),
    mut each_block: impl FnMut(Vec<CaseOutcome>) -> Result<(), E>,
) -> Result<(), E> {
    let mut reader = csv::ReaderBuilder::new().from_reader(reader);
    let expected = columns(study);
    let found: Vec<String> = reader
        .headers()
        .map_err(|e| part_error(path, Some(2), None, e.to_string()))?
        .iter()
        .map(str::to_owned)
        .collect();
    if found != expected {
        return Err(part_error(
            path,
            Some(2),
            None,
            "the columns are not this study's".into(),
        )
        .into());
    }
    let mut cases = Vec::new();
    let mut values = Vec::new();
    let mut record = csv::StringRecord::new();
    let mut r = 0;
    loop {
        let line = r + 3;
        let more = reader
            .read_record(&mut record)
            .map_err(|e| part_error(path, Some(line), None, e.to_string()))?;
        let next = range.start + r;
        if !more {
            break;
        }
        if r % block == 0 {
            values = design.values(next..(next + block).min(range.end));
        }
        let row = PartRow {
            study,
            path,
            line,
            record: &record,
            expected: &expected,
        };
        cases.push(row.case(next, &range, values.get(r % block).map(Vec::as_slice))?);
        r += 1;
        if cases.len() == block {
            each_block(std::mem::take(&mut cases))?;
        }
    }
    if range.start + r < range.end {
        return Err(part_error(
            path,
            Some(r + 3),
            None,
            format!(
                "the part ends after case {}; its first line says cases {}..{} (a truncated \
                 part file?)",
                (range.start + r).wrapping_sub(1),
                range.start,
                range.end
            ),
        )
        .into());
    }
    if !cases.is_empty() {
        each_block(cases)?;
    }
    Ok(())
}

/// An error in the part file at `path`.
fn part_error(
    path: &Path,
    line: Option<usize>,
    key: Option<&str>,
    message: String,
) -> ScenarioError {
    ScenarioError::Invalid {
        path: path.to_path_buf(),
        line,
        key: key.map(str::to_owned),
        message,
    }
}

/// A part file's first line after its prefix, which must name `study` by its fingerprint.
fn part_header<'t>(study: &Study, path: &Path, first: &'t str) -> Result<&'t str, ScenarioError> {
    let Some(header) = first.strip_prefix(PART_PREFIX) else {
        return Err(part_error(
            path,
            Some(1),
            None,
            "not a part file of `sealsim study --shard` (its first line names the study)".into(),
        ));
    };
    let fingerprint = header.split_whitespace().next().unwrap_or("");
    if fingerprint != study.fingerprint {
        return Err(part_error(
            path,
            Some(1),
            None,
            format!(
                "a part of another study (fingerprint {fingerprint}; {} has {}): the study file, \
                 its base scenario or sealsim's version differ",
                study.path.display(),
                study.fingerprint
            ),
        ));
    }
    Ok(header)
}

/// One case's row of a part file being read: its `line`, and the study's columns
/// (`expected`) for the messages.
struct PartRow<'a> {
    study: &'a Study,
    path: &'a Path,
    line: usize,
    record: &'a csv::StringRecord,
    expected: &'a [String],
}

impl PartRow<'_> {
    /// An error on this row at `key`.
    fn error(&self, key: &str, message: String) -> ScenarioError {
        part_error(self.path, Some(self.line), Some(key), message)
    }

    /// The cell of column `k` (empty when the row is short).
    fn field(&self, k: usize) -> &str {
        self.record.get(k).unwrap_or("")
    }

    /// The finite number in column `k`.
    fn number(&self, k: usize) -> Result<f64, ScenarioError> {
        self.field(k)
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| {
                self.error(
                    &self.expected[k],
                    format!("\"{}\" is not a number", self.field(k)),
                )
            })
    }

    /// The number in column `k`, if the cell is not empty.
    fn optional(&self, k: usize) -> Result<Option<f64>, ScenarioError> {
        if self.field(k).is_empty() {
            Ok(None)
        } else {
            self.number(k).map(Some)
        }
    }

    /// The case, which must be case `next` of the part's cases `range`, checked against the
    /// design's `values` of it (`None`: beyond the part's cases).
    fn case(
        &self,
        next: usize,
        range: &std::ops::Range<usize>,
        values: Option<&[f64]>,
    ) -> Result<CaseOutcome, ScenarioError> {
        let index = self.index(next, range)?;
        let values = values.ok_or_else(|| {
            self.error(
                "case",
                format!(
                    "case {index} is beyond the part's cases {}..{} (its first line)",
                    range.start, range.end
                ),
            )
        })?;
        let inputs = self.inputs(index, values)?;
        let k = 1 + self.study.inputs.len();
        let status = self.field(k + 1);
        let mode = self.mode(status, self.field(k + 2))?;
        let times = self.study.report_times.len();
        let leak_rates = (0..times)
            .map(|t| self.optional(k + 3 + t))
            .collect::<Result<_, _>>()?;
        let e = k + 3 + times;
        let final_state = self.final_state(self.field(e + 4))?;
        let invalid = (status == "invalid").then(|| self.field(e + 6).to_owned());
        if status == "invalid" && self.field(e + 6).is_empty() {
            return Err(self.error("invalid_reason", "an invalid case needs its reason".into()));
        }
        Ok(CaseOutcome {
            index,
            inputs,
            life: self.number(k)?,
            mode,
            leak_rates,
            final_force: self.number(e)?,
            retained_force: self.number(e + 1)?,
            leaked_volume: self.number(e + 2)?,
            compression_set: self.optional(e + 3)?,
            final_state: final_state.to_owned(),
            warnings: self.warnings(e + 5)?,
            invalid,
        })
    }

    /// The `;`-separated validity limits of column `k`: each a limit's id (docs/model.md §9) or
    /// the permeation bound's flag, as the study writes them (an edited `bogus-id` or `inf`
    /// was merged into the table and counted in the summary).
    fn warnings(&self, k: usize) -> Result<Vec<String>, ScenarioError> {
        use crate::study::case::PERMEATION_BOUND;
        use crate::validity::Limit;
        let cell = self.field(k);
        if cell.is_empty() {
            return Ok(Vec::new());
        }
        cell.split(';')
            .map(|id| {
                if id == PERMEATION_BOUND || Limit::ALL.iter().any(|l| l.id() == id) {
                    Ok(id.to_owned())
                } else {
                    Err(self.error(
                        &self.expected[k],
                        format!(
                            "\"{id}\" is not a validity limit's id (docs/model.md §9: {}, or \
                             {PERMEATION_BOUND}); the part file was edited or is not a part file",
                            Limit::ALL.map(Limit::id).join(", ")
                        ),
                    ))
                }
            })
            .collect()
    }

    /// The case index: a case of the study, and `next`, the part's rows running through its
    /// cases `range` in order.
    fn index(&self, next: usize, range: &std::ops::Range<usize>) -> Result<usize, ScenarioError> {
        let index: usize = self.field(0).parse().map_err(|_| {
            self.error("case", format!("\"{}\" is not a case index", self.field(0)))
        })?;
        if index >= self.study.cases() {
            return Err(self.error(
                "case",
                format!(
                    "case {index} is beyond the study's {} cases",
                    self.study.cases()
                ),
            ));
        }
        if index != next {
            return Err(self.error(
                "case",
                format!(
                    "case {index} where case {next} belongs: a part holds the cases of its first \
                     line ({}..{}) in order; the part file was edited",
                    range.start, range.end
                ),
            ));
        }
        Ok(index)
    }

    /// The case's inputs, each the one the study's design gives it (`values`).
    fn inputs(&self, index: usize, values: &[f64]) -> Result<Vec<Cell>, ScenarioError> {
        let mut inputs = Vec::with_capacity(self.study.inputs.len());
        for (j, input) in self.study.inputs.iter().enumerate() {
            let cell = match input.kind {
                InputKind::Words(_) => Cell::Word(self.field(1 + j).to_owned()),
                InputKind::Quantity { .. } | InputKind::SizeTolerance | InputKind::FitTolerance => {
                    Cell::Number(self.number(1 + j)?)
                }
            };
            if input.cell(values[j]) != cell {
                return Err(self.error(
                    &self.expected[1 + j],
                    format!("case {index}'s input is not the one the study's design gives it"),
                ));
            }
            inputs.push(cell);
        }
        Ok(inputs)
    }

    /// The failure mode of a failed case (`status`, `mode`); none for a censored or invalid
    /// one.
    fn mode(&self, status: &str, mode: &str) -> Result<Option<FailureMode>, ScenarioError> {
        match (status, mode) {
            ("censored" | "invalid", "") => Ok(None),
            ("failed", m) => Ok(Some(FailureMode::from_name(m).ok_or_else(|| {
                self.error("mode", format!("unknown failure mode \"{m}\""))
            })?)),
            (s, _) => Err(self.error(
                "status",
                format!("\"{s}\": failed (with a mode), censored or invalid"),
            )),
        }
    }

    /// The state at the end: a seal state, or an invalid case's.
    fn final_state<'s>(&self, state: &'s str) -> Result<&'s str, ScenarioError> {
        if state != crate::study::case::INVALID_STATE
            && !crate::leak::SealState::ALL
                .iter()
                .any(|s| s.as_str() == state)
        {
            return Err(self.error("state_end", format!("unknown state \"{state}\"")));
        }
        Ok(state)
    }
}

/// The summary as JSON ([`write_summary_json`] into a string).
pub fn summary_json(study: &Study, s: &StudySummary) -> Result<String, serde_json::Error> {
    let mut bytes = Vec::new();
    write_summary_json(study, s, &mut bytes)?;
    String::from_utf8(bytes).map_err(|e| serde::ser::Error::custom(e.to_string()))
}

/// Writes the summary as JSON (pretty, keys in order, a final newline) to `w`. The survival
/// curve — a step per distinct failure time, ≈ 200 B each, up to one per case — is rendered
/// step by step as it is written, never as a document tree (≈ 1 KB a step: 1 GB for 10⁶
/// cases).
pub fn write_summary_json(
    study: &Study,
    s: &StudySummary,
    mut w: impl std::io::Write,
) -> Result<(), serde_json::Error> {
    let doc = SummaryDoc {
        doc: summary_doc(study, s),
        km: &s.kaplan_meier,
        confidence: s.confidence,
    };
    serde_json::to_writer_pretty(&mut w, &doc)?;
    w.write_all(b"\n").map_err(serde_json::Error::io)
}

/// The summary's JSON document; its `survival` member is a placeholder for the steps.
struct SummaryDoc<'a> {
    doc: serde_json::Map<String, Value>,
    km: &'a crate::study::survival::KaplanMeier,
    confidence: f64,
}

impl serde::Serialize for SummaryDoc<'_> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut map = serializer.serialize_map(Some(self.doc.len()))?;
        for (key, value) in &self.doc {
            if key == "survival" {
                map.serialize_entry(key, &SurvivalSteps(self))?;
            } else {
                map.serialize_entry(key, value)?;
            }
        }
        map.end()
    }
}

/// The Kaplan–Meier steps with their band, each a JSON object made as it is written.
struct SurvivalSteps<'a>(&'a SummaryDoc<'a>);

impl serde::Serialize for SurvivalSteps<'_> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeSeq;
        let (km, confidence) = (self.0.km, self.0.confidence);
        let mut seq = serializer.serialize_seq(Some(km.steps().len()))?;
        for st in km.steps() {
            let (lo, hi) = km.band(st.time, confidence);
            seq.serialize_element(&json!({
                "time_s": st.time,
                "at_risk": st.at_risk,
                "failures": st.failures,
                "survival": st.survival,
                "lower": lo,
                "upper": hi,
            }))?;
        }
        seq.end()
    }
}

/// The summary's JSON members but the survival steps (a placeholder).
fn summary_doc(study: &Study, s: &StudySummary) -> serde_json::Map<String, Value> {
    let mut doc = serde_json::Map::new();
    doc.insert("study".into(), json!(study.name));
    doc.insert("file".into(), json!(study.path.display().to_string()));
    doc.insert("base".into(), json!(study.base_path.display().to_string()));
    doc.insert("fingerprint".into(), json!(study.fingerprint));
    doc.insert("design".into(), json!(study.plan.design.name()));
    doc.insert("is_sample".into(), json!(study.plan.design.is_sample()));
    doc.insert("seed".into(), json!(study.plan.seed));
    doc.insert("cases".into(), json!(s.cases));
    doc.insert("failures".into(), json!(s.failures));
    doc.insert("invalid_cases".into(), json!(s.invalid));
    doc.insert("censored".into(), json!(s.censored));
    doc.insert("confidence".into(), json!(s.confidence));
    for (p, b) in &s.b_lives {
        let name = format!("b{}", (p * 100.0).round());
        doc.insert(format!("{name}_s"), json!(b.estimate));
        doc.insert(format!("{name}_lower_s"), json!(b.lower));
        doc.insert(format!("{name}_upper_s"), json!(b.upper));
    }
    doc.insert(
        "by_level".into(),
        Value::Array(
            levels(study, s)
                .into_iter()
                .map(|l| {
                    json!({
                        "input": study.inputs[l.input].key,
                        "level": l.level,
                        "cases": l.cases,
                        "failures": l.failures,
                        "b10_s": l.b10.estimate,
                        "b10_lower_s": l.b10.lower,
                        "b10_upper_s": l.b10.upper,
                    })
                })
                .collect(),
        ),
    );
    doc.insert(
        "modes".into(),
        Value::Object(
            s.modes
                .iter()
                .map(|(m, n)| (m.as_str().to_owned(), json!(n)))
                .collect(),
        ),
    );
    doc.insert(
        "weibull".into(),
        match &s.weibull {
            None => Value::Null,
            Some(w) => {
                let mut o = serde_json::Map::new();
                o.insert("shape".into(), json!(w.weibull.shape));
                o.insert("scale_s".into(), json!(w.weibull.scale));
                o.insert("fits".into(), json!(w.fits));
                o.insert("ks_distance".into(), json!(w.distance));
                o.insert("ks_critical".into(), json!(w.critical));
                for p in B_LIVES {
                    o.insert(
                        format!("b{}_s", (p * 100.0).round()),
                        json!(w.weibull.b_life(p)),
                    );
                }
                Value::Object(o)
            }
        },
    );
    doc.insert(
        "sensitivity".into(),
        Value::Array(
            s.sensitivity
                .iter()
                .map(|i| {
                    json!({
                        "input": study.inputs[i.input].key,
                        "measure": i.measure.name(),
                        "value": i.value,
                    })
                })
                .collect(),
        ),
    );
    // the steps are written one by one (`SurvivalSteps`)
    doc.insert("survival".into(), Value::Null);
    doc.insert(
        "warnings".into(),
        Value::Object(
            s.warnings
                .iter()
                .map(|(id, n)| (id.clone(), json!(n)))
                .collect(),
        ),
    );
    doc
}

/// A life for people, or why there is none.
fn life_text(t: Option<f64>, why: &str) -> String {
    t.map_or_else(|| why.to_owned(), human_time)
}

/// The summary's per-value lives in input order and, within an input, in the order the study
/// lists its values.
fn levels<'s>(study: &Study, s: &'s StudySummary) -> Vec<&'s LevelLife> {
    let rank = |l: &LevelLife| match &study.inputs[l.input].kind {
        InputKind::Words(words) => words.iter().position(|w| *w == l.level),
        InputKind::Quantity { .. } | InputKind::SizeTolerance | InputKind::FitTolerance => None,
    };
    let mut out: Vec<&LevelLife> = s.by_level.iter().collect();
    out.sort_by_key(|l| (l.input, rank(l)));
    out
}

/// B10 per value of each word input (`seal.size`, `material.library`): one line per value with
/// its cases, failures and bounds; empty without a word input.
fn by_level_table(study: &Study, s: &StudySummary) -> String {
    let mut out = String::new();
    let mut last = None;
    let width = s
        .by_level
        .iter()
        .map(|l| l.level.chars().count())
        .max()
        .unwrap_or(0);
    for l in levels(study, s) {
        if last != Some(l.input) {
            out += &format!(
                "\nB10 by {} (Kaplan–Meier over its cases, {} % bounds)\n",
                study.inputs[l.input].key,
                human(100.0 * s.confidence, 3)
            );
            last = Some(l.input);
        }
        let never = "not reached: fewer than 10 % failed";
        out += &format!(
            "  {:<width$}  {:<22} [{}, {}]   {} of {} failed\n",
            l.level,
            life_text(l.b10.estimate, never),
            life_text(l.b10.lower, "—"),
            life_text(l.b10.upper, "beyond the data"),
            l.failures,
            l.cases
        );
    }
    out
}

/// The terminal table of the summary.
pub fn summary_table(study: &Study, s: &StudySummary) -> String {
    let mut out = String::new();
    let pct = |p: f64| format!("{} %", human(100.0 * p, 3));
    out += &format!("study          {} ({})\n", study.name, study.path.display());
    out += &format!(
        "design         {}: {} cases, seed {}, base {}\n",
        study.plan.design.name(),
        s.cases,
        study.plan.seed,
        study.base_path.display()
    );
    let mut modes: Vec<String> = s
        .modes
        .iter()
        .map(|(m, n)| format!("{n} by {}", m.as_str()))
        .collect();
    if s.invalid > 0 {
        modes.push(format!(
            "{} invalid (not a valid seal: failed at installation; reasons in the case table)",
            s.invalid
        ));
    }
    out += &format!(
        "failures       {} of {} ({}){}\n",
        s.failures,
        s.cases,
        pct(s.failures as f64 / s.cases.max(1) as f64),
        if modes.is_empty() {
            String::new()
        } else {
            format!(": {}", modes.join(", "))
        }
    );
    out += &format!(
        "survivors      {} (censored at the end of their run; never counted as failures)\n",
        s.censored
    );
    if !study.plan.design.is_sample() {
        out += "note           a grid is a sweep, not a sample: the survival curve and B lives \
                weight every grid point equally\n";
    }
    out += &format!("\nlife (Kaplan–Meier, {} bounds)\n", pct(s.confidence));
    for (p, b) in &s.b_lives {
        let name = format!("B{}", (p * 100.0).round());
        let never = format!("not reached: fewer than {} failed", pct(*p));
        out += &format!(
            "  {name:<5} {:<22} [{}, {}]\n",
            life_text(b.estimate, &never),
            life_text(b.lower, "—"),
            life_text(b.upper, "beyond the data")
        );
    }
    match &s.weibull {
        None if s.invalid > 0 => {
            out += "Weibull        no fit (invalid cases fail at installation, life 0)\n";
        }
        None => out += "Weibull        no fit (fewer than two failures at distinct times)\n",
        Some(w) => {
            out += &format!(
                "Weibull        β {}, η {}: {}\n",
                human(w.weibull.shape, 3),
                human_time(w.weibull.scale),
                if w.fits {
                    format!(
                        "fits (Kolmogorov–Smirnov D {} ≤ {}); B10 {}",
                        human(w.distance, 2),
                        human(w.critical, 2),
                        human_time(w.weibull.b_life(0.1))
                    )
                } else {
                    format!(
                        "does not fit (Kolmogorov–Smirnov D {} > {})",
                        human(w.distance, 2),
                        human(w.critical, 2)
                    )
                }
            )
        }
    }
    out += &by_level_table(study, s);
    out += "\nwhat drives the life (Spearman ρ of input and life; η for words)\n";
    let width = study.inputs.iter().map(|i| i.key.len()).max().unwrap_or(0);
    for inf in &s.sensitivity {
        let key = &study.inputs[inf.input].key;
        let (symbol, text, bar) = match inf.value {
            None => ("", "constant".to_owned(), String::new()),
            Some(v) => (
                if inf.measure.name() == "spearman_rho" {
                    "ρ"
                } else {
                    "η"
                },
                format!("{v:+.2}"),
                "█".repeat((v.abs() * 20.0).round() as usize),
            ),
        };
        out += &format!("  {key:<width$}  {symbol} {text:>6}  {bar}\n");
    }
    if !s.warnings.is_empty() {
        out += "\nvalidity warnings (cases)\n";
        for (id, n) in &s.warnings {
            out += &format!("  {id}: {n}\n");
        }
    }
    out
}

/// The survival-curve and tornado charts (SVG).
#[cfg(feature = "cli")]
pub mod charts {
    use super::*;
    use crate::report::plot::PlotError;
    use plotters::prelude::*;

    const YEAR: f64 = 365.25 * 86_400.0;

    fn err<E: std::fmt::Display>(e: E) -> PlotError {
        PlotError(e.to_string())
    }

    /// The Kaplan–Meier curve (steps) with its band, the Weibull fit, against time in years on
    /// a log axis.
    pub fn survival_chart(study: &Study, s: &StudySummary) -> Result<String, PlotError> {
        let km = &s.kaplan_meier;
        let steps = km.steps();
        let lives: Vec<f64> = steps
            .iter()
            .map(|st| st.time / YEAR)
            .filter(|t| *t > 0.0)
            .collect();
        if lives.is_empty() {
            return Err(PlotError("no failures: no survival curve to draw".into()));
        }
        let lo = lives.iter().copied().fold(f64::INFINITY, f64::min) / 2.0;
        let end = study
            .base_scenario
            .life
            .time
            .duration
            .max(steps.last().map_or(0.0, |st| st.time))
            / YEAR;
        let hi = (end * 1.5).max(lo * 10.0);
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (800, 520)).into_drawing_area();
            root.fill(&WHITE).map_err(err)?;
            let mut chart = ChartBuilder::on(&root)
                .caption(format!("{}: survival", study.name), ("sans-serif", 20))
                .margin(16)
                .x_label_area_size(48)
                .y_label_area_size(60)
                .build_cartesian_2d((lo..hi).log_scale(), 0.0..1.02)
                .map_err(err)?;
            chart
                .configure_mesh()
                .x_desc("time (years)")
                .y_desc("fraction still sealing")
                .draw()
                .map_err(err)?;
            // the curve and its band as steps: flat until each failure time, then down
            let step_points = |value: &dyn Fn(f64, usize) -> f64| {
                let mut pts = vec![(lo, 1.0)];
                let mut prev = 1.0;
                for (k, st) in steps.iter().enumerate() {
                    let t = (st.time / YEAR).max(lo);
                    pts.push((t, prev));
                    prev = value(st.time, k);
                    pts.push((t, prev));
                }
                pts.push((hi.min(end.max(lo)), prev));
                pts
            };
            let blue = RGBColor(0, 114, 178);
            let band_colour = RGBColor(86, 180, 233);
            let lower = step_points(&|t, _| km.band(t, s.confidence).0);
            let upper = step_points(&|t, _| km.band(t, s.confidence).1);
            for (pts, label) in [(&lower, "band"), (&upper, "")] {
                let series = chart
                    .draw_series(LineSeries::new(pts.clone(), band_colour.stroke_width(1)))
                    .map_err(err)?;
                if !label.is_empty() {
                    series
                        .label(format!(
                            "{} % confidence band",
                            human(100.0 * s.confidence, 3)
                        ))
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 20, y)], band_colour.stroke_width(1))
                        });
                }
            }
            chart
                .draw_series(LineSeries::new(
                    step_points(&|_, k| steps[k].survival),
                    blue.stroke_width(3),
                ))
                .map_err(err)?
                .label("Kaplan–Meier")
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], blue.stroke_width(3))
                });
            if let Some(w) = &s.weibull {
                let orange = RGBColor(230, 159, 0);
                let n = 200;
                let pts: Vec<(f64, f64)> = (0..=n)
                    .map(|i| {
                        let t = lo * (hi / lo).powf(i as f64 / n as f64);
                        (t, w.weibull.survival(t * YEAR))
                    })
                    .collect();
                chart
                    .draw_series(LineSeries::new(pts, orange.stroke_width(2)))
                    .map_err(err)?
                    .label(format!(
                        "Weibull β {}, η {}{}",
                        human(w.weibull.shape, 3),
                        human_time(w.weibull.scale),
                        if w.fits { "" } else { " (does not fit)" }
                    ))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], orange.stroke_width(2))
                    });
            }
            // B10 as a marker line
            if let Some(b10) = s
                .b_lives
                .iter()
                .find(|(p, _)| *p == 0.1)
                .and_then(|(_, b)| b.estimate)
            {
                let grey = RGBColor(100, 100, 100);
                chart
                    .draw_series(LineSeries::new(
                        vec![
                            (lo, 0.9),
                            ((b10 / YEAR).max(lo), 0.9),
                            ((b10 / YEAR).max(lo), 0.0),
                        ],
                        grey.stroke_width(1),
                    ))
                    .map_err(err)?
                    .label(format!("B10 {}", human_time(b10)))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], grey.stroke_width(1))
                    });
            }
            crate::report::life_chart::legend(&mut chart, SeriesLabelPosition::UpperRight)?;
            root.present().map_err(err)?;
        }
        Ok(svg)
    }

    /// The inputs' influence on the life as horizontal bars, largest at the top.
    pub fn tornado_chart(study: &Study, s: &StudySummary) -> Result<String, PlotError> {
        let bars: Vec<(String, f64)> = s
            .sensitivity
            .iter()
            .filter_map(|i| i.value.map(|v| (study.inputs[i.input].key.clone(), v)))
            .collect();
        if bars.is_empty() {
            return Err(PlotError("no input varied the life".into()));
        }
        let n = bars.len();
        let height = 120 + 48 * n as u32;
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, (800, height)).into_drawing_area();
            root.fill(&WHITE).map_err(err)?;
            let labels = bars.clone();
            let mut chart = ChartBuilder::on(&root)
                .caption(
                    format!("{}: what drives the life", study.name),
                    ("sans-serif", 20),
                )
                .margin(16)
                .x_label_area_size(48)
                .y_label_area_size(220)
                .build_cartesian_2d(-1.0..1.0, (0..n as i32 - 1).into_segmented())
                .map_err(err)?;
            chart
                .configure_mesh()
                .x_desc("rank correlation with the life (ρ; η ≥ 0 for words)")
                .y_labels(n)
                .y_label_formatter(&|y| match y {
                    SegmentValue::CenterOf(k) if *k >= 0 && (*k as usize) < n => {
                        labels[n - 1 - *k as usize].0.clone()
                    }
                    _ => String::new(),
                })
                .disable_y_mesh()
                .light_line_style(WHITE)
                .draw()
                .map_err(err)?;
            // vermillion: more of the input shortens the life; blue: lengthens (Okabe–Ito)
            let shorter = RGBColor(213, 94, 0);
            let longer = RGBColor(0, 114, 178);
            chart
                .draw_series(bars.iter().enumerate().map(|(k, (_, v))| {
                    let y = (n - 1 - k) as i32;
                    let colour = if *v < 0.0 { shorter } else { longer };
                    let mut r = Rectangle::new(
                        [
                            (0.0, SegmentValue::Exact(y)),
                            (*v, SegmentValue::Exact(y + 1)),
                        ],
                        colour.filled(),
                    );
                    r.set_margin(8, 8, 0, 0);
                    r
                }))
                .map_err(err)?;
            root.present().map_err(err)?;
        }
        Ok(svg)
    }
}

/// The HTML report of a study: the summary table, the survival curve, the sensitivities, the
/// warnings, the study file and its base scenario.
pub fn report_page(
    study: &Study,
    summary: &StudySummary,
    table: &str,
    survival: Option<&str>,
    tornado: Option<&str>,
) -> String {
    use crate::report::html;
    let mut body = format!("<h1>{}</h1>\n", html::escape(&study.name));
    body += &format!(
        "<p class=\"meta\">study file {} · base {} · sealsim study</p>\n",
        html::escape(&study.path.display().to_string()),
        html::escape(&study.base_path.display().to_string())
    );
    let b10 = summary
        .b_lives
        .iter()
        .find(|(p, _)| *p == 0.1)
        .map(|(_, b)| b);
    let verdict = match b10.and_then(|b| b.estimate) {
        Some(t) => format!(
            "B10 life {} ({} of {} cases failed within their run)",
            human_time(t),
            summary.failures,
            summary.cases
        ),
        None => format!(
            "B10 not reached: {} of {} cases failed within their run",
            summary.failures, summary.cases
        ),
    };
    body += &html::verdict("info", &verdict);
    let inputs: Vec<&std::path::Path> = [study.path.as_path(), study.base_path.as_path()]
        .into_iter()
        .chain(
            study
                .base_scenario
                .inputs
                .iter()
                .map(std::path::PathBuf::as_path),
        )
        .collect();
    body += &html::record("sealsim study", &inputs);
    body += &html::heading("Summary");
    body += &html::pre(table);
    if let Some(svg) = survival {
        body += &html::heading("Survival");
        body += &html::figure(
            svg,
            "Kaplan–Meier survival with its 95 % band, the Weibull fit and the B10 life.",
        );
    }
    if let Some(svg) = tornado {
        body += &html::heading("What drives the life");
        body += &html::figure(
            svg,
            "Rank correlation of each input with the life (ρ; η for words), largest first.",
        );
    }
    body += &html::file("Study file", study.text());
    body += &html::file(
        "Base scenario (inputs with units and provenance)",
        study.base_text(),
    );
    html::document(&study.name, &body)
}

/// What `study slurm` submits.
#[derive(Debug, Clone, Copy)]
pub struct SlurmJob<'a> {
    pub study: &'a Study,
    /// Absolute paths, as the jobs see them (a shared file system).
    pub study_path: &'a Path,
    pub sealsim: &'a Path,
    pub results: &'a Path,
    pub shards: usize,
    pub cpus_per_task: usize,
    pub partition: Option<&'a str>,
    pub time: Option<&'a str>,
}

/// A word for the shell, single-quoted.
fn shell_quote(text: &str) -> String {
    format!("'{}'", text.replace('\'', r"'\''"))
}

/// The submission script of a study on Slurm: a job array with one task per shard, each
/// running `sealsim study FILE --shard K/N` into `part-K.csv`, and the merge as a job that
/// starts only after every task succeeded (`--dependency=afterok`). Run with bash on a node
/// that can submit.
pub fn slurm_script(job: &SlurmJob<'_>) -> String {
    let study = job.study;
    let name: String = study
        .name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect();
    let mut common = format!("--job-name={}", shell_quote(&format!("sealsim-{name}")));
    if let Some(p) = job.partition {
        common += &format!(" --partition={}", shell_quote(p));
    }
    if let Some(t) = job.time {
        common += &format!(" --time={}", shell_quote(t));
    }
    let n = job.shards;
    let c = job.cpus_per_task;
    format!(
        r#"#!/bin/bash
# sealsim study "{title}": {cases} cases in {n} shards as a Slurm job array, then their merge.
# Generated by `sealsim study slurm` (study fingerprint {fp}).
# Submit from a node that can run sbatch:   bash THIS_FILE
# The jobs need this binary, the study and its base scenario at the same paths (a shared file
# system). Results: $RESULTS/cases.csv, summary.json, survival.svg, tornado.svg; logs there too.
set -euo pipefail
SEALSIM={sealsim}
STUDY={study_path}
RESULTS={results}
mkdir -p "$RESULTS"

array=$(sbatch --parsable {common} --array=1-{n} --cpus-per-task={c} \
  --output="$RESULTS/shard-%a.log" <<EOF
#!/bin/bash
exec "$SEALSIM" study "$STUDY" --shard "\$SLURM_ARRAY_TASK_ID/{n}" --threads {c} \
  -o "$RESULTS/part-\$SLURM_ARRAY_TASK_ID.csv"
EOF
)
array=${{array%%;*}}

merge=$(sbatch --parsable {common} --dependency=afterok:"$array" \
  --output="$RESULTS/merge.log" <<EOF
#!/bin/bash
exec "$SEALSIM" study merge "$STUDY" "$RESULTS"/part-*.csv -o "$RESULTS/cases.csv" \
  --summary "$RESULTS/summary.json" --survival-plot "$RESULTS/survival.svg" \
  --tornado-plot "$RESULTS/tornado.svg"
EOF
)
merge=${{merge%%;*}}

echo "submitted: shards as job array $array (tasks 1-{n}), merge as job $merge (after all succeed)"
echo "results: $RESULTS"
"#,
        title = study.name.replace(['\n', '"'], " "),
        cases = study.cases(),
        fp = study.fingerprint,
        sealsim = shell_quote(&job.sealsim.display().to_string()),
        study_path = shell_quote(&job.study_path.display().to_string()),
        results = shell_quote(&job.results.display().to_string()),
    )
}
