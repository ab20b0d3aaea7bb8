//! A study's summary of its cases (docs/model.md §14.2–14.3): counts, the Kaplan–Meier survival
//! curve, B1/B10/B50 lives with confidence bounds, a Weibull fit where it fits, and which input
//! drives the life.
//!
//! Everything here is a function of the per-case table's values only (life, failed or censored,
//! mode, inputs, warnings), so that a summary rebuilt from merged shard files is bit-identical
//! to the one of a single run.

use super::case::{CaseOutcome, Cell};
use super::sensitivity::{Column, ranking};
use super::survival::{BLife, KaplanMeier, Observation, Weibull};
use crate::simulate::FailureMode;

/// The B lives every summary gives: B1, B10, B50.
pub const B_LIVES: [f64; 3] = [0.01, 0.1, 0.5];

/// How an input's influence on the life is measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// Spearman's rank correlation ρ (signed: negative = more of the input, shorter life).
    Spearman,
    /// The correlation ratio η of the life's ranks over an input of words (unsigned).
    CorrelationRatio,
}

impl Measure {
    pub fn name(self) -> &'static str {
        match self {
            Measure::Spearman => "spearman_rho",
            Measure::CorrelationRatio => "correlation_ratio",
        }
    }
}

/// One input's influence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Influence {
    /// The input's index (study order).
    pub input: usize,
    pub measure: Measure,
    /// `None`: the input (or the life) was constant over the cases.
    pub value: Option<f64>,
}

/// A Weibull fit and whether it fits: the Kolmogorov–Smirnov distance
/// `D = sup_t |S_W(t) − S_KM(t)|` (over the Kaplan–Meier steps, on both sides of each) against
/// the 95 % critical value `1.36/√n` of a fully specified distribution [recalled: Massey 1951].
/// With the parameters estimated from the same data the test is conservative (it rejects less
/// than 5 % of true Weibull samples, measured in the tests); with censoring D only covers the
/// times up to the last failure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WeibullFit {
    pub weibull: Weibull,
    pub fits: bool,
    /// D.
    pub distance: f64,
    /// The critical value 1.36/√n.
    pub critical: f64,
}

impl WeibullFit {
    /// The fit of `observations` and its distance from their Kaplan–Meier curve `km`.
    pub fn new(observations: &[Observation], km: &KaplanMeier) -> Option<WeibullFit> {
        let w = Weibull::fit(observations)?;
        let mut before = 1.0;
        let mut distance: f64 = 0.0;
        for s in km.steps() {
            let sw = w.survival(s.time);
            distance = distance
                .max((sw - before).abs())
                .max((sw - s.survival).abs());
            before = s.survival;
        }
        let critical = 1.36 / (observations.len() as f64).sqrt();
        Some(WeibullFit {
            weibull: w,
            fits: distance <= critical,
            distance,
            critical,
        })
    }
}

/// The summary of a study's cases.
#[derive(Debug, Clone, PartialEq)]
pub struct StudySummary {
    pub cases: usize,
    /// Failures, the invalid cases included (failed at installation).
    pub failures: usize,
    /// Cases that are not valid scenarios (their inputs and reasons are in the case table).
    pub invalid: usize,
    /// Survivors: censored at the end of their run.
    pub censored: usize,
    /// Failures by mode, in the order of [`FailureMode`]'s names.
    pub modes: Vec<(FailureMode, usize)>,
    pub confidence: f64,
    pub kaplan_meier: KaplanMeier,
    /// (p, B_p life) for [`B_LIVES`].
    pub b_lives: Vec<(f64, BLife)>,
    pub weibull: Option<WeibullFit>,
    /// The inputs by influence, largest first.
    pub sensitivity: Vec<Influence>,
    /// Validity limits crossed: (id, number of cases), by id.
    pub warnings: Vec<(String, usize)>,
    /// The B10 life of each value of each word input (a size, a compound), in input order and
    /// the values' order of first appearance: a sweep over sizes reads its life per size.
    pub by_level: Vec<LevelLife>,
}

/// The life of the cases that share one value of a word input (`seal.size = "AS568-214"`):
/// Kaplan–Meier over those cases alone.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelLife {
    /// The input's index in the study's inputs.
    pub input: usize,
    /// The value (a word).
    pub level: String,
    pub cases: usize,
    /// Failures, invalid cases included.
    pub failures: usize,
    /// B10 with its bounds at the summary's confidence.
    pub b10: BLife,
}

impl StudySummary {
    /// The summary of `outcomes` (in case order) at two-sided `confidence`: their
    /// [`CaseRecords`] summarised.
    pub fn new(outcomes: &[CaseOutcome], confidence: f64) -> Self {
        let mut records = CaseRecords::with_capacity(outcomes.len());
        for c in outcomes {
            records.push(c);
        }
        records.summary(confidence)
    }
}

/// What a study's summary reads of its cases, gathered one case at a time so that the cases
/// themselves need not be kept (a 10⁶-case study keeps ≈ 16 B a case plus 8 B per varied
/// input, against ≈ 1 KB for a [`CaseOutcome`]): each case's life and whether it failed, its
/// inputs' values (a word input as the index of its word), and the counts of failure modes,
/// invalid cases and validity warnings, counted as they come.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CaseRecords {
    observations: Vec<Observation>,
    /// Failures by mode, in order of first appearance.
    modes: Vec<(FailureMode, usize)>,
    invalid: usize,
    /// Cases per validity limit, in order of first appearance.
    warnings: Vec<(String, usize)>,
    /// The varied inputs' values, in input order (set by the first case).
    columns: Vec<InputRecord>,
}

/// One varied input over the cases so far.
#[derive(Debug, Clone, PartialEq)]
enum InputRecord {
    /// Every value so far a number.
    Numbers(Vec<f64>),
    /// Some value a word: each case's group, the index of its word (a number as its shortest
    /// text) in `words`, the words in order of first appearance.
    Words {
        groups: Vec<usize>,
        words: Vec<String>,
    },
}

impl InputRecord {
    fn push(&mut self, cell: &Cell) {
        match (&mut *self, cell) {
            (InputRecord::Numbers(v), Cell::Number(x)) => v.push(*x),
            (InputRecord::Numbers(v), Cell::Word(_)) => {
                // the first word: the numbers so far become words
                let mut words = InputRecord::Words {
                    groups: Vec::with_capacity(v.capacity()),
                    words: Vec::new(),
                };
                for x in v.iter() {
                    words.push(&Cell::Number(*x));
                }
                words.push(cell);
                *self = words;
            }
            (InputRecord::Words { groups, words }, cell) => {
                let word = match cell {
                    Cell::Word(w) => std::borrow::Cow::Borrowed(w.as_str()),
                    Cell::Number(x) => std::borrow::Cow::Owned(x.to_string()),
                };
                let group = match words.iter().position(|v| *v == word) {
                    Some(k) => k,
                    None => {
                        words.push(word.into_owned());
                        words.len() - 1
                    }
                };
                groups.push(group);
            }
        }
    }
}

impl CaseRecords {
    /// Records with room for `cases` cases.
    pub fn with_capacity(cases: usize) -> Self {
        CaseRecords {
            observations: Vec::with_capacity(cases),
            ..CaseRecords::default()
        }
    }

    /// The number of cases recorded.
    pub fn len(&self) -> usize {
        self.observations.len()
    }

    /// Whether no case is recorded.
    pub fn is_empty(&self) -> bool {
        self.observations.is_empty()
    }

    /// Records the next case (cases come in case order).
    pub fn push(&mut self, c: &CaseOutcome) {
        if self.observations.is_empty() {
            let room = self.observations.capacity();
            self.columns = (0..c.inputs.len())
                .map(|_| InputRecord::Numbers(Vec::with_capacity(room)))
                .collect();
        }
        self.observations.push(Observation {
            time: c.life,
            failed: c.failed(),
        });
        for (column, cell) in self.columns.iter_mut().zip(&c.inputs) {
            column.push(cell);
        }
        if let Some(m) = c.mode {
            count(&mut self.modes, m);
        }
        self.invalid += usize::from(c.invalid.is_some());
        for w in &c.warnings {
            match self.warnings.iter_mut().find(|(k, _)| k == w) {
                Some((_, n)) => *n += 1,
                None => self.warnings.push((w.clone(), 1)),
            }
        }
    }

    /// The summary of the recorded cases at two-sided `confidence`.
    pub fn summary(self, confidence: f64) -> StudySummary {
        let CaseRecords {
            observations,
            mut modes,
            invalid,
            mut warnings,
            columns,
        } = self;
        let km = KaplanMeier::new(&observations);
        let failures = observations.iter().filter(|o| o.failed).count();
        modes.sort_by_key(|(m, _)| m.as_str());
        warnings.sort();
        // failures at installation (life 0) are not a Weibull population: no fit with them
        let weibull = if invalid == 0 {
            WeibullFit::new(&observations, &km)
        } else {
            None
        };
        let mut level_words: Vec<Vec<String>> = Vec::with_capacity(columns.len());
        let columns: Vec<Column> = columns
            .into_iter()
            .map(|c| match c {
                InputRecord::Numbers(v) => {
                    level_words.push(Vec::new());
                    Column::Numeric(v)
                }
                InputRecord::Words { groups, words } => {
                    level_words.push(words);
                    Column::Categorical(groups)
                }
            })
            .collect();
        let life: Vec<f64> = observations.iter().map(|o| o.time).collect();
        let sensitivity = ranking(&columns, &life)
            .into_iter()
            .map(|(input, value)| Influence {
                input,
                measure: match columns[input] {
                    Column::Numeric(_) => Measure::Spearman,
                    Column::Categorical(_) => Measure::CorrelationRatio,
                },
                value,
            })
            .collect();
        drop(life);
        let by_level = by_level(&columns, &level_words, &observations, confidence);
        StudySummary {
            by_level,
            cases: observations.len(),
            failures,
            invalid,
            censored: observations.len() - failures,
            modes,
            confidence,
            b_lives: B_LIVES
                .iter()
                .map(|&p| (p, km.b_life(p, confidence)))
                .collect(),
            kaplan_meier: km,
            weibull,
            sensitivity,
            warnings,
        }
    }
}

/// One more of `mode` in the counts `modes`.
fn count(modes: &mut Vec<(FailureMode, usize)>, mode: FailureMode) {
    match modes.iter_mut().find(|(k, _)| *k == mode) {
        Some((_, n)) => *n += 1,
        None => modes.push((mode, 1)),
    }
}

/// The B10 life of each word (`words[j]`, in order of first appearance) of each word input
/// (`columns[j]` categorical): Kaplan–Meier over that word's cases alone.
fn by_level(
    columns: &[Column],
    words: &[Vec<String>],
    observations: &[Observation],
    confidence: f64,
) -> Vec<LevelLife> {
    let mut out = Vec::new();
    for (j, column) in columns.iter().enumerate() {
        let Column::Categorical(groups) = column else {
            continue;
        };
        for (g, level) in words[j].iter().enumerate() {
            let subset: Vec<Observation> = groups
                .iter()
                .zip(observations)
                .filter(|(k, _)| **k == g)
                .map(|(_, o)| *o)
                .collect();
            out.push(LevelLife {
                input: j,
                level: level.clone(),
                cases: subset.len(),
                failures: subset.iter().filter(|o| o.failed).count(),
                b10: KaplanMeier::new(&subset).b_life(0.1, confidence),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::SplitMix64;

    /// A Weibull(β, η) life by inversion, censored at `cut`.
    fn weibull_life(rng: &mut SplitMix64, beta: f64, eta: f64, cut: f64) -> Observation {
        let t = eta * (-rng.uniform().ln()).powf(1.0 / beta);
        Observation {
            time: t.min(cut),
            failed: t <= cut,
        }
    }

    #[test]
    fn the_weibull_check_accepts_weibull_samples_and_rejects_a_mixture() {
        let mut rng = SplitMix64(3);
        let studies = 300;
        let accepted = (0..studies)
            .filter(|_| {
                let obs: Vec<Observation> = (0..200)
                    .map(|_| weibull_life(&mut rng, 2.5, 10.0, 12.0))
                    .collect();
                let km = KaplanMeier::new(&obs);
                WeibullFit::new(&obs, &km).is_some_and(|w| w.fits)
            })
            .count();
        // the test's level is 5 % for a fully specified law; with fitted parameters it rejects
        // less often
        assert!(
            accepted as f64 >= 0.95 * studies as f64,
            "{accepted}/{studies}"
        );
        // two populations a decade apart (a bimodal life): rejected
        let rejected = (0..100)
            .filter(|_| {
                let obs: Vec<Observation> = (0..200)
                    .map(|i| weibull_life(&mut rng, 5.0, if i % 2 == 0 { 1.0 } else { 10.0 }, 20.0))
                    .collect();
                let km = KaplanMeier::new(&obs);
                WeibullFit::new(&obs, &km).is_some_and(|w| !w.fits)
            })
            .count();
        eprintln!(
            "Weibull check: {accepted}/{studies} Weibull samples accepted, {rejected}/100 mixtures rejected"
        );
        assert!(rejected >= 95, "{rejected}/100");
    }

    /// The records count as the cases come: modes, invalid cases and warnings; a word input
    /// (here one whose first value is a number, as a list of mixed values reads) gets one
    /// level per value in order of first appearance, each with the Kaplan–Meier B10 of its own
    /// cases; an input equal to the life has ρ = 1, the words their η in closed form.
    #[test]
    fn records_count_as_they_come_and_give_each_word_its_own_life() {
        let case = |life: f64, word: Cell, failed: bool, warnings: &[&str]| CaseOutcome {
            index: 0,
            inputs: vec![Cell::Number(life), word],
            life,
            mode: failed.then_some(FailureMode::LeakRate),
            leak_rates: vec![],
            final_force: 1.0,
            retained_force: 1.0,
            leaked_volume: 0.0,
            compression_set: None,
            final_state: "sealed".into(),
            warnings: warnings.iter().map(|w| (*w).to_owned()).collect(),
            invalid: None,
        };
        let mut invalid = case(0.0, Cell::Number(7.0), false, &[]);
        invalid.invalid = Some("overfills the groove".into());
        let mut records = CaseRecords::default();
        records.push(&invalid);
        for i in 0..10 {
            let a = Cell::Word("a".into());
            records.push(&case(1.0 + f64::from(i), a, true, &["w1"]));
            let b = Cell::Word("b".into());
            records.push(&case(100.0 + f64::from(i), b, false, &["w1", "w2"]));
        }
        assert_eq!(records.len(), 21);
        let s = records.summary(0.95);
        assert_eq!(
            (s.cases, s.failures, s.invalid, s.censored),
            (21, 11, 1, 10)
        );
        assert_eq!(s.modes, vec![(FailureMode::LeakRate, 10)]);
        let w = |id: &str, n| (id.to_owned(), n);
        assert_eq!(s.warnings, vec![w("w1", 20), w("w2", 10)]);
        // no Weibull fit with a failure at installation
        assert!(s.weibull.is_none());
        let levels: Vec<(&str, usize, usize)> = s
            .by_level
            .iter()
            .map(|l| (l.level.as_str(), l.cases, l.failures))
            .collect();
        assert_eq!(levels, [("7", 1, 1), ("a", 10, 10), ("b", 10, 0)]);
        // "a": S falls to 9/10 at its first failure, t = 1; "b" never fails; "7" at t = 0
        let b10: Vec<Option<f64>> = s.by_level.iter().map(|l| l.b10.estimate).collect();
        assert_eq!(b10, [Some(0.0), Some(1.0), None]);
        // ranks: "7" 1, "a" 2…11 (mean 6.5), "b" 12…21 (mean 16.5), all 11 on average:
        // η² = (10² + 10·4.5² + 10·5.5²)/(21·(21² − 1)/12) = 605/770
        let influence: Vec<(usize, Measure)> =
            s.sensitivity.iter().map(|i| (i.input, i.measure)).collect();
        assert_eq!(
            influence,
            [(0, Measure::Spearman), (1, Measure::CorrelationRatio)]
        );
        assert_eq!(s.sensitivity[0].value, Some(1.0));
        let eta = s.sensitivity[1].value.unwrap();
        assert!((eta - (605.0f64 / 770.0).sqrt()).abs() < 1e-15, "{eta}");
    }

    #[test]
    fn survivors_are_censored_not_failures() {
        let outcome = |life: f64, mode: Option<FailureMode>, x: f64| CaseOutcome {
            index: 0,
            inputs: vec![Cell::Number(x)],
            life,
            mode,
            leak_rates: vec![],
            final_force: 1.0,
            retained_force: 1.0,
            leaked_volume: 0.0,
            compression_set: None,
            final_state: "sealed".into(),
            warnings: vec!["x".into()],
            invalid: None,
        };
        let cases = vec![
            outcome(5.0, Some(FailureMode::LeakRate), 3.0),
            outcome(10.0, None, 1.0),
            outcome(10.0, None, 2.0),
            outcome(2.0, Some(FailureMode::LiftOff), 4.0),
        ];
        let s = StudySummary::new(&cases, 0.95);
        assert_eq!((s.cases, s.failures, s.censored), (4, 2, 2));
        // S after the two failures: (1 − 1/4)(1 − 1/3) = 1/2, the survivors still at risk
        let last = s.kaplan_meier.steps().last().copied().unwrap();
        assert!((last.survival - 0.5).abs() < 1e-15);
        assert_eq!(last.at_risk, 3);
        assert_eq!(s.b_lives[2].1.estimate, Some(5.0));
        assert_eq!(s.warnings, vec![("x".to_owned(), 4)]);
        // the input rises as the life falls: ρ = −1 with the survivors' tie → −0.95
        assert!(s.sensitivity[0].value.unwrap() < -0.9);
    }
}
