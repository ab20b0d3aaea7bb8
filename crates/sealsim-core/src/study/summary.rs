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
    /// The summary of `outcomes` (in case order) at two-sided `confidence`.
    pub fn new(outcomes: &[CaseOutcome], confidence: f64) -> Self {
        let observations: Vec<Observation> = outcomes
            .iter()
            .map(|c| Observation {
                time: c.life,
                failed: c.failed(),
            })
            .collect();
        let km = KaplanMeier::new(&observations);
        let failures = outcomes.iter().filter(|c| c.failed()).count();
        let mut modes: Vec<(FailureMode, usize)> = Vec::new();
        for m in outcomes.iter().filter_map(|c| c.mode) {
            match modes.iter_mut().find(|(k, _)| *k == m) {
                Some((_, n)) => *n += 1,
                None => modes.push((m, 1)),
            }
        }
        modes.sort_by_key(|(m, _)| m.as_str());
        let invalid = outcomes.iter().filter(|c| c.invalid.is_some()).count();
        // failures at installation (life 0) are not a Weibull population: no fit with them
        let weibull = if invalid == 0 {
            WeibullFit::new(&observations, &km)
        } else {
            None
        };
        let life: Vec<f64> = observations.iter().map(|o| o.time).collect();
        let inputs = outcomes.first().map_or(0, |c| c.inputs.len());
        let columns: Vec<Column> = (0..inputs).map(|j| column(outcomes, j)).collect();
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
        let mut warnings: Vec<(String, usize)> = Vec::new();
        for w in outcomes.iter().flat_map(|c| &c.warnings) {
            match warnings.iter_mut().find(|(k, _)| k == w) {
                Some((_, n)) => *n += 1,
                None => warnings.push((w.clone(), 1)),
            }
        }
        warnings.sort();
        let by_level = columns
            .iter()
            .enumerate()
            .filter_map(|(j, c)| match c {
                Column::Categorical(groups) => Some((j, groups)),
                Column::Numeric(_) => None,
            })
            .flat_map(|(j, groups)| {
                let levels = groups.iter().copied().max().map_or(0, |m| m + 1);
                let observations = &observations;
                (0..levels).map(move |g| {
                    let members: Vec<usize> =
                        (0..groups.len()).filter(|&i| groups[i] == g).collect();
                    let subset: Vec<Observation> =
                        members.iter().map(|&i| observations[i]).collect();
                    let level = match &outcomes[members[0]].inputs[j] {
                        Cell::Word(w) => w.clone(),
                        Cell::Number(x) => x.to_string(),
                    };
                    LevelLife {
                        input: j,
                        level,
                        cases: subset.len(),
                        failures: subset.iter().filter(|o| o.failed).count(),
                        b10: KaplanMeier::new(&subset).b_life(0.1, confidence),
                    }
                })
            })
            .collect();
        StudySummary {
            by_level,
            cases: outcomes.len(),
            failures,
            invalid,
            censored: outcomes.len() - failures,
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

/// Input `j` over the cases: numbers, or words as group indices (in order of first appearance).
fn column(outcomes: &[CaseOutcome], j: usize) -> Column {
    let cells: Vec<&Cell> = outcomes.iter().map(|c| &c.inputs[j]).collect();
    if cells.iter().all(|c| matches!(c, Cell::Number(_))) {
        return Column::Numeric(
            cells
                .iter()
                .map(|c| match c {
                    Cell::Number(x) => *x,
                    Cell::Word(_) => f64::NAN,
                })
                .collect(),
        );
    }
    let mut words: Vec<String> = Vec::new();
    Column::Categorical(
        cells
            .iter()
            .map(|c| {
                let w = match c {
                    Cell::Word(w) => w.clone(),
                    Cell::Number(x) => x.to_string(),
                };
                match words.iter().position(|v| *v == w) {
                    Some(k) => k,
                    None => {
                        words.push(w);
                        words.len() - 1
                    }
                }
            })
            .collect(),
    )
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
