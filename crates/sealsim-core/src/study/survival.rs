//! Survival statistics of times to failure with right censoring (docs/model.md §14).
//!
//! * **Kaplan–Meier** product-limit estimate: at each distinct failure time t_i with n_i cases
//!   at risk (time ≥ t_i) and d_i failures, `S(t) = Π_{t_i ≤ t} (1 − d_i/n_i)`. A censored case
//!   (a seal that survived its run, or failed by nothing before its duration) is at risk up to
//!   its censoring time and never counts as a failure; at a tie, failures come first (a case
//!   censored at t_i is still at risk at t_i).
//! * **Greenwood's variance** `Var S(t) = S(t)² Σ_{t_i ≤ t} d_i/(n_i (n_i − d_i))`, and the
//!   pointwise confidence band on the log-log scale (Kalbfleisch & Prentice), which stays
//!   inside (0, 1): with `θ = ln(−ln S)` and `se(θ) = √(Σ d_i/(n_i(n_i − d_i)))/|ln S|`,
//!   `S^{exp(±z se)}`, z the two-sided normal quantile.
//! * **B_p life**: the first failure time at which S falls to 1 − p or below; its confidence
//!   bounds are the first times the band's lower and upper edges do (earlier and later). `None`
//!   where the estimate (or an edge) never reaches 1 − p — too few failures, censored before.
//!
//! [recalled: Kaplan & Meier, JASA 53 (1958) 457; Greenwood 1926; Kalbfleisch & Prentice, *The
//! Statistical Analysis of Failure Time Data* (1980) — the formulas are the textbook ones; their
//! coverage is checked by simulation in the tests.]

use statrs::distribution::{ContinuousCDF, Normal};

/// One case: its time \[s\] and whether it failed then (`false`: censored, still sealing at
/// `time`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Observation {
    pub time: f64,
    pub failed: bool,
}

/// One failure time of the product-limit estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    /// The failure time t_i \[s\].
    pub time: f64,
    /// n_i: cases with time ≥ t_i.
    pub at_risk: usize,
    /// d_i: failures at t_i.
    pub failures: usize,
    /// S(t_i), after the step.
    pub survival: f64,
    /// Greenwood's sum Σ_{t_j ≤ t_i} d_j/(n_j (n_j − d_j)) (∞ once S = 0).
    pub greenwood: f64,
}

/// The Kaplan–Meier estimate of a set of observations.
#[derive(Debug, Clone, PartialEq)]
pub struct KaplanMeier {
    steps: Vec<Step>,
    cases: usize,
    failures: usize,
}

/// A B_p life with its confidence bounds \[s\] (`None`: not reached within the data).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BLife {
    pub estimate: Option<f64>,
    /// The earlier bound (the band's lower edge reaches 1 − p).
    pub lower: Option<f64>,
    /// The later bound (the band's upper edge reaches 1 − p).
    pub upper: Option<f64>,
}

impl KaplanMeier {
    /// The estimate of `observations` (non-finite or negative times are left out).
    pub fn new(observations: &[Observation]) -> Self {
        let mut obs: Vec<Observation> = observations
            .iter()
            .copied()
            .filter(|o| o.time.is_finite() && o.time >= 0.0)
            .collect();
        // by time; at a tie failures first, so that a case censored then is still at risk
        obs.sort_by(|a, b| a.time.total_cmp(&b.time).then(b.failed.cmp(&a.failed)));
        let cases = obs.len();
        let mut steps = Vec::new();
        let (mut survival, mut greenwood) = (1.0, 0.0);
        let mut i = 0;
        while i < obs.len() {
            let t = obs[i].time;
            let at_risk = obs.len() - i;
            let mut failures = 0;
            let mut j = i;
            while j < obs.len() && obs[j].time == t {
                failures += usize::from(obs[j].failed);
                j += 1;
            }
            if failures > 0 {
                let (n, d) = (at_risk as f64, failures as f64);
                survival *= 1.0 - d / n;
                greenwood += if failures < at_risk {
                    d / (n * (n - d))
                } else {
                    f64::INFINITY
                };
                steps.push(Step {
                    time: t,
                    at_risk,
                    failures,
                    survival,
                    greenwood,
                });
            }
            i = j;
        }
        let failures = obs.iter().filter(|o| o.failed).count();
        KaplanMeier {
            steps,
            cases,
            failures,
        }
    }

    /// The failure steps, in time order.
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// Number of cases, and of failures among them (the rest are censored).
    pub fn counts(&self) -> (usize, usize) {
        (self.cases, self.failures)
    }

    /// S(t): 1 before the first failure.
    pub fn survival(&self, t: f64) -> f64 {
        self.step_at(t).map_or(1.0, |s| s.survival)
    }

    /// The pointwise band of S(t) at `confidence` (e.g. 0.95), on the log-log scale; (1, 1)
    /// before the first failure, (0, 0) once S = 0.
    pub fn band(&self, t: f64, confidence: f64) -> (f64, f64) {
        match self.step_at(t) {
            None => (1.0, 1.0),
            Some(s) => band_of(s, z_of(confidence)),
        }
    }

    /// The B_p life (p in (0, 1): B10 is p = 0.1) with its bounds at `confidence`.
    pub fn b_life(&self, p: f64, confidence: f64) -> BLife {
        let target = 1.0 - p;
        let z = z_of(confidence);
        let first = |value: &dyn Fn(&Step) -> f64| {
            self.steps
                .iter()
                .find(|s| value(s) <= target)
                .map(|s| s.time)
        };
        BLife {
            estimate: first(&|s| s.survival),
            lower: first(&|s| band_of(s, z).0),
            upper: first(&|s| band_of(s, z).1),
        }
    }

    /// The last step at or before `t`.
    fn step_at(&self, t: f64) -> Option<&Step> {
        let k = self.steps.partition_point(|s| s.time <= t);
        k.checked_sub(1).map(|k| &self.steps[k])
    }
}

/// A two-parameter Weibull life distribution, `S(t) = exp(−(t/η)^β)`, fitted by maximum
/// likelihood with right censoring (docs/model.md §14).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Weibull {
    /// Shape β.
    pub shape: f64,
    /// Scale η \[s\].
    pub scale: f64,
}

impl Weibull {
    /// The maximum-likelihood fit of `observations` (failures and censored cases): with r
    /// failures, the likelihood `Π_fail f(t_i) Π_cens S(t_j)` is maximal where
    /// `η^β = Σ_all t^β / r` and `g(β) = Σ_all t^β ln t/Σ_all t^β − 1/β − (1/r) Σ_fail ln t_i = 0`
    /// (g increases in β), solved by bisection in ln β. `None` with fewer than two failures at
    /// distinct times (no shape to fit).
    pub fn fit(observations: &[Observation]) -> Option<Weibull> {
        let all: Vec<(f64, bool)> = observations
            .iter()
            .filter(|o| o.time.is_finite() && o.time > 0.0)
            .map(|o| (o.time, o.failed))
            .collect();
        let fails: Vec<f64> = all.iter().filter(|(_, f)| *f).map(|(t, _)| *t).collect();
        let r = fails.len() as f64;
        let distinct = fails.iter().any(|&t| t != fails[0]);
        if fails.len() < 2 || !distinct {
            return None;
        }
        // times scaled by the largest, so that t^β neither overflows nor underflows
        let t_max = all.iter().map(|(t, _)| *t).fold(0.0, f64::max);
        let mean_ln_fail = fails.iter().map(|t| (t / t_max).ln()).sum::<f64>() / r;
        let g = |beta: f64| {
            let (mut num, mut den) = (0.0, 0.0);
            for (t, _) in &all {
                let x = t / t_max;
                let w = x.powf(beta);
                num += w * x.ln();
                den += w;
            }
            num / den - 1.0 / beta - mean_ln_fail
        };
        let (lo, hi) = ((1e-3_f64).ln(), (1e3_f64).ln());
        if g(lo.exp()) > 0.0 || g(hi.exp()) < 0.0 {
            return None;
        }
        let (lo, hi) = sealsim_math::roots::bisect(
            lo,
            hi,
            200,
            |lo, hi| hi - lo < 1e-14,
            |ln_beta| g(ln_beta.exp()) < 0.0,
        );
        let shape = (0.5 * (lo + hi)).exp();
        let sum: f64 = all.iter().map(|(t, _)| (t / t_max).powf(shape)).sum();
        let scale = t_max * (sum / r).powf(1.0 / shape);
        Some(Weibull { shape, scale })
    }

    /// S(t) = exp(−(t/η)^β).
    pub fn survival(&self, t: f64) -> f64 {
        (-(t / self.scale).powf(self.shape)).exp()
    }

    /// The B_p life `η (−ln(1 − p))^{1/β}` \[s\].
    pub fn b_life(&self, p: f64) -> f64 {
        self.scale * (-(-p).ln_1p()).powf(1.0 / self.shape)
    }
}

/// The two-sided standard-normal quantile of `confidence` (0.95 → 1.95996).
fn z_of(confidence: f64) -> f64 {
    let c = confidence.clamp(1e-9, 1.0 - 1e-15);
    Normal::standard().inverse_cdf(0.5 + 0.5 * c)
}

/// The log-log band of one step at quantile `z`.
fn band_of(s: &Step, z: f64) -> (f64, f64) {
    let surv = s.survival;
    if surv <= 0.0 || !s.greenwood.is_finite() {
        return (0.0, 0.0);
    }
    if surv >= 1.0 {
        return (1.0, 1.0);
    }
    let se = s.greenwood.sqrt() / surv.ln().abs();
    // S^{exp(+z se)} is the lower edge (a power above 1 of a number below 1)
    (surv.powf((z * se).exp()), surv.powf((-z * se).exp()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::rng::SplitMix64;

    fn failed(times: &[f64]) -> Vec<Observation> {
        times
            .iter()
            .map(|&time| Observation { time, failed: true })
            .collect()
    }

    #[test]
    fn without_censoring_it_is_the_empirical_survival() {
        let km = KaplanMeier::new(&failed(&[5.0, 1.0, 3.0, 2.0, 4.0]));
        for (t, s) in [(0.5, 1.0), (1.0, 0.8), (2.5, 0.6), (4.0, 0.2), (9.0, 0.0)] {
            assert!((km.survival(t) - s).abs() < 1e-15, "{t}");
        }
        assert_eq!(km.counts(), (5, 5));
        // B20 = the first time S ≤ 0.8
        assert_eq!(km.b_life(0.2, 0.95).estimate, Some(1.0));
    }

    #[test]
    fn survivors_never_count_as_failures() {
        // censored cases: at risk until their time, never a step
        let all_survive: Vec<Observation> = (1..=10)
            .map(|k| Observation {
                time: k as f64,
                failed: false,
            })
            .collect();
        let km = KaplanMeier::new(&all_survive);
        assert!(km.steps().is_empty());
        assert_eq!(km.survival(100.0), 1.0);
        assert_eq!(km.b_life(0.1, 0.95).estimate, None);
        // a textbook case by hand: failures at 1, 3; censored at 2, 4; one failure at 5
        // n: 5 at t=1 → S = 4/5; at t=3 three at risk → S = 4/5 · 2/3; at t=5 one → 0
        let obs = [
            (1.0, true),
            (2.0, false),
            (3.0, true),
            (4.0, false),
            (5.0, true),
        ]
        .map(|(time, failed)| Observation { time, failed });
        let km = KaplanMeier::new(&obs);
        assert!((km.survival(3.5) - 8.0 / 15.0).abs() < 1e-15);
        assert_eq!(km.counts(), (5, 3));
        // Greenwood after t=3: 1/(5·4) + 1/(3·2)
        let g = km.steps()[1].greenwood;
        assert!((g - (1.0 / 20.0 + 1.0 / 6.0)).abs() < 1e-15);
        // a tie: the case censored at a failure time is still at risk then
        let tie = [(2.0, true), (2.0, false), (3.0, true)]
            .map(|(time, failed)| Observation { time, failed });
        assert!((KaplanMeier::new(&tie).survival(2.0) - 2.0 / 3.0).abs() < 1e-15);
    }

    #[test]
    fn weibull_fit_recovers_a_known_distribution_with_censoring() {
        // lives Weibull(β = 2.5, η = 10) by inversion, censored at 12 (≈ 20 % survive): the
        // fit must recover β and η, and its B10 the true η (−ln 0.9)^{1/β} = 4.07
        let mut rng = SplitMix64(42);
        let obs: Vec<Observation> = (0..4000)
            .map(|_| {
                let life = 10.0 * (-rng.uniform().ln()).powf(1.0 / 2.5);
                Observation {
                    time: life.min(12.0),
                    failed: life <= 12.0,
                }
            })
            .collect();
        let fit = Weibull::fit(&obs).unwrap();
        eprintln!("Weibull fit {fit:?}, B10 {}", fit.b_life(0.1));
        assert!((fit.shape / 2.5 - 1.0).abs() < 0.05, "{fit:?}");
        assert!((fit.scale / 10.0 - 1.0).abs() < 0.03, "{fit:?}");
        let truth = Weibull {
            shape: 2.5,
            scale: 10.0,
        };
        assert!((fit.b_life(0.1) / truth.b_life(0.1) - 1.0).abs() < 0.05);
        assert!((truth.survival(truth.b_life(0.1)) - 0.9).abs() < 1e-14);
        // the censored cases count only as survivors: fitting the failures alone, as if
        // every case had failed, gives a smaller scale
        let failures_only: Vec<Observation> = obs.iter().copied().filter(|o| o.failed).collect();
        assert!(Weibull::fit(&failures_only).unwrap().scale < fit.scale);
        // no shape without two distinct failures
        assert_eq!(Weibull::fit(&failed(&[3.0, 3.0])), None);
    }

    #[test]
    fn the_band_and_the_b10_bounds_cover_a_known_life_distribution() {
        // lives N(10, 2²) censored at 11 (a study's duration): the true S(8) = Φ(1) and the
        // true B10 = 10 + 2 Φ⁻¹(0.1) = 7.4369; over 400 seeded studies of 300 cases the 95 %
        // band must cover S(8) and the B10 bounds the true B10 about 95 % of the time
        let normal = Normal::standard();
        let true_s8 = normal.cdf(1.0);
        let true_b10 = 10.0 + 2.0 * normal.inverse_cdf(0.1);
        let (mut band_hits, mut b10_hits, mut b10_found) = (0, 0, 0);
        let studies = 400;
        for seed in 0..studies {
            let mut rng = SplitMix64(0x5eed_0000 + seed);
            let obs: Vec<Observation> = (0..150)
                .flat_map(|_| {
                    let (a, b) = rng.normal_pair();
                    [a, b]
                })
                .map(|z| {
                    let life = 10.0 + 2.0 * z;
                    if life <= 11.0 {
                        Observation {
                            time: life,
                            failed: true,
                        }
                    } else {
                        Observation {
                            time: 11.0,
                            failed: false,
                        }
                    }
                })
                .collect();
            let km = KaplanMeier::new(&obs);
            let (lo, hi) = km.band(8.0, 0.95);
            band_hits += usize::from(lo <= true_s8 && true_s8 <= hi);
            let b10 = km.b_life(0.1, 0.95);
            if let (Some(l), Some(u)) = (b10.lower, b10.upper) {
                b10_found += 1;
                b10_hits += usize::from(l <= true_b10 && true_b10 <= u);
            }
            // censored cases never became failures
            let (cases, failures) = km.counts();
            assert_eq!(cases, 300);
            assert!(failures < cases);
        }
        let band = band_hits as f64 / studies as f64;
        let b10 = b10_hits as f64 / b10_found as f64;
        eprintln!("coverage: band at t = 8 {band}, B10 bounds {b10}");
        assert!((0.91..=0.99).contains(&band), "band coverage {band}");
        assert!(b10_found == studies as usize);
        assert!((0.90..=0.99).contains(&b10), "B10 coverage {b10}");
    }
}
