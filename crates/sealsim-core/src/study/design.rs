//! Sampling designs of a study (docs/model.md §14.1): which values each varied input takes in
//! each case.
//!
//! Every input has a [`Distribution`] given by its quantile function `x(u)`, u ∈ (0, 1), so
//! that every design is a rule for the uniforms u:
//! * **Monte Carlo**: u drawn independently per case and input;
//! * **Latin hypercube** (McKay, Beckman & Conover 1979 \[recalled\]): for each input the n
//!   cases fall one into each of the n equal-probability strata, `u_ij = (π_j(i) + U_ij)/n`
//!   with a random permutation π_j per input;
//! * **grid**: the full factorial of each input's levels (its listed values, or `levels`
//!   quantiles at the stratum midpoints `(k + ½)/m`), the first input varying slowest.
//!
//! **Correlated inputs** (Monte Carlo only) through a Gaussian copula: the uniforms become
//! normal scores ε = Φ⁻¹(u), correlated as z = Lε (L the Cholesky factor of the normal-scores
//! correlation matrix R), and back to uniforms Φ(z); every marginal stays as given. A target
//! Spearman ρ_s between two inputs is R = 2 sin(πρ_s/6), exact for the copula (the rank
//! correlation is invariant under the marginals' monotone quantile maps) [recalled: Kruskal 1958
//! for ρ_s of a bivariate normal].
//!
//! Determinism: case i's uniforms come from ChaCha8 seeded with the study's seed on stream i,
//! and the permutations from streams above 2⁴⁸; so a case's values depend only on the seed,
//! its index and the design — never on the order cases run in, the thread count or the shard.

use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use statrs::distribution::{ContinuousCDF, Normal};

/// The distribution of one varied input, in the input's own unit (a level index for a list of
/// words such as compound ids).
#[derive(Debug, Clone, PartialEq)]
pub enum Distribution {
    /// Uniform on [min, max].
    Uniform { min: f64, max: f64 },
    /// Triangular on [min, max] with its peak at `mode`.
    Triangular { min: f64, mode: f64, max: f64 },
    /// Normal N(mean, std²), truncated to [lo, hi] (±∞ for none).
    Normal {
        mean: f64,
        std: f64,
        lo: f64,
        hi: f64,
    },
    /// Log-normal: ln x ~ N(ln median, (ln geometric_std)²), truncated to [lo, hi].
    LogNormal {
        median: f64,
        geometric_std: f64,
        lo: f64,
        hi: f64,
    },
    /// Log-uniform on [min, max] (min > 0).
    LogUniform { min: f64, max: f64 },
    /// Equally likely discrete values (a list, a linear or log-spaced range).
    Levels(Vec<f64>),
}

impl Distribution {
    /// Why the parameters are not a distribution, or `Ok`.
    pub fn check(&self) -> Result<(), String> {
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        match *self {
            Distribution::Uniform { min, max } | Distribution::LogUniform { min, max } => {
                if !finite(&[min, max]) || min >= max {
                    return Err(format!(
                        "needs min < max, got min {} and max {}",
                        crate::units::show(min),
                        crate::units::show(max)
                    ));
                }
                if matches!(self, Distribution::LogUniform { .. }) && min <= 0.0 {
                    return Err("a log-spaced distribution needs min > 0".into());
                }
            }
            Distribution::Triangular { min, mode, max } => {
                if !finite(&[min, mode, max]) || min >= max || mode < min || mode > max {
                    return Err("needs min ≤ mode ≤ max with min < max".into());
                }
            }
            Distribution::Normal { mean, std, lo, hi } => {
                if !(mean.is_finite() && std > 0.0 && std.is_finite()) {
                    return Err(format!(
                        "needs a finite mean and std > 0, got std {}",
                        crate::units::show(std)
                    ));
                }
                check_truncation(mean, std, lo, hi)?;
            }
            Distribution::LogNormal {
                median,
                geometric_std,
                lo,
                hi,
            } => {
                if !(median > 0.0 && median.is_finite()) {
                    return Err("needs median > 0".into());
                }
                if !(geometric_std > 1.0 && geometric_std.is_finite()) {
                    return Err(format!(
                        "needs geometric_std > 1 (a factor), got {}",
                        crate::units::show(geometric_std)
                    ));
                }
                check_truncation(median.ln(), geometric_std.ln(), log_or(lo), log_or(hi))?;
            }
            Distribution::Levels(ref v) => {
                if v.is_empty() || !finite(v) {
                    return Err("needs at least one finite value".into());
                }
            }
        }
        Ok(())
    }

    /// The quantile x(u) for u ∈ (0, 1).
    pub fn quantile(&self, u: f64) -> f64 {
        match *self {
            Distribution::Uniform { min, max } => min + u * (max - min),
            Distribution::Triangular { min, mode, max } => {
                let f = (mode - min) / (max - min);
                if u < f {
                    min + ((max - min) * (mode - min) * u).sqrt()
                } else {
                    max - ((max - min) * (max - mode) * (1.0 - u)).sqrt()
                }
            }
            Distribution::Normal { mean, std, lo, hi } => truncated_normal(mean, std, lo, hi, u),
            Distribution::LogNormal {
                median,
                geometric_std,
                lo,
                hi,
            } => truncated_normal(median.ln(), geometric_std.ln(), log_or(lo), log_or(hi), u).exp(),
            Distribution::LogUniform { min, max } => (min.ln() + u * (max / min).ln()).exp(),
            Distribution::Levels(ref v) => {
                let k = ((u * v.len() as f64) as usize).min(v.len() - 1);
                v[k]
            }
        }
    }

    /// A grid's levels: a list's own values, otherwise `m` quantiles at the stratum midpoints
    /// `(k + ½)/m`.
    pub fn levels(&self, m: usize) -> Vec<f64> {
        match self {
            Distribution::Levels(v) => v.clone(),
            _ => (0..m)
                .map(|k| self.quantile((k as f64 + 0.5) / m as f64))
                .collect(),
        }
    }
}

/// ln x, or ±∞ kept (a truncation bound of a log-normal).
fn log_or(x: f64) -> f64 {
    if x <= 0.0 { f64::NEG_INFINITY } else { x.ln() }
}

fn check_truncation(mean: f64, std: f64, lo: f64, hi: f64) -> Result<(), String> {
    if lo.is_nan() || hi.is_nan() || lo >= hi {
        return Err("needs truncation bounds min < max".into());
    }
    // A window far in a tail leaves no probability to sample from in double precision.
    let n = standard();
    if n.cdf((hi - mean) / std) - n.cdf((lo - mean) / std) < 1e-12 {
        return Err("the truncation bounds leave no probability (they lie far in a tail)".into());
    }
    Ok(())
}

fn standard() -> Normal {
    // N(0, 1): statrs builds it without a fallible check
    Normal::standard()
}

/// The quantile of N(mean, std²) restricted to [lo, hi]: x = mean + std Φ⁻¹(Φ(a) + u(Φ(b) − Φ(a))),
/// a, b the standardised bounds.
fn truncated_normal(mean: f64, std: f64, lo: f64, hi: f64, u: f64) -> f64 {
    let n = standard();
    let (a, b) = (n.cdf((lo - mean) / std), n.cdf((hi - mean) / std));
    let p = (a + u * (b - a)).clamp(f64::MIN_POSITIVE, 1.0 - f64::EPSILON / 2.0);
    (mean + std * normal_quantile(&n, p)).clamp(lo, hi)
}

/// Φ⁻¹(p) to rounding: statrs's inverse (good to ≈ 5e-11 in p) polished by one Newton step on
/// Φ(x) = p.
fn normal_quantile(n: &Normal, p: f64) -> f64 {
    use statrs::distribution::Continuous;
    let x = n.inverse_cdf(p);
    let density = n.pdf(x);
    if density > 0.0 && x.is_finite() {
        x - (n.cdf(x) - p) / density
    } else {
        x
    }
}

/// How the cases are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Design {
    Grid,
    MonteCarlo,
    LatinHypercube,
}

impl Design {
    pub const ALL: [Design; 3] = [Design::Grid, Design::MonteCarlo, Design::LatinHypercube];

    /// The study file's name of the design.
    pub fn name(self) -> &'static str {
        match self {
            Design::Grid => "grid",
            Design::MonteCarlo => "monte-carlo",
            Design::LatinHypercube => "latin-hypercube",
        }
    }

    /// Whether the cases are a random sample of the input distributions (so that the survival
    /// curve and B lives estimate a population's), rather than a sweep.
    pub fn is_sample(self) -> bool {
        !matches!(self, Design::Grid)
    }
}

/// A study's design: the inputs' distributions, how many cases and the seed.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    pub design: Design,
    pub inputs: Vec<Distribution>,
    /// Monte Carlo and Latin hypercube: the number of cases.
    pub samples: usize,
    /// Grid: the number of levels of each continuous input (a list keeps its own).
    pub levels: usize,
    pub seed: u64,
    /// Monte Carlo: the lower Cholesky factor of the inputs' normal-scores correlation matrix
    /// (row-major, inputs × inputs), see [`correlation_factor`]; `None`: independent inputs.
    pub correlation: Option<Vec<f64>>,
}

/// The lower Cholesky factor (row-major) of the normal-scores correlation matrix of `k` inputs
/// with the target Spearman rank correlations `pairs` (i, j, ρ_s): `R_ij = 2 sin(πρ_s/6)`, 1 on
/// the diagonal, 0 elsewhere. `Err` when R is not positive definite (the correlations
/// contradict each other).
pub fn correlation_factor(k: usize, pairs: &[(usize, usize, f64)]) -> Result<Vec<f64>, String> {
    let mut r = nalgebra::DMatrix::<f64>::identity(k, k);
    for &(i, j, rho) in pairs {
        let normal = 2.0 * (std::f64::consts::PI * rho / 6.0).sin();
        r[(i, j)] = normal;
        r[(j, i)] = normal;
    }
    let l = r
        .cholesky()
        .ok_or("the correlations contradict each other (their matrix is not positive definite)")?
        .l();
    Ok((0..k)
        .flat_map(|i| (0..k).map(move |j| (i, j)))
        .map(|(i, j)| l[(i, j)])
        .collect())
}

impl Plan {
    /// The number of cases.
    pub fn cases(&self) -> usize {
        match self.design {
            Design::Grid => self
                .inputs
                .iter()
                .map(|d| d.levels(self.levels).len())
                .product(),
            _ => self.samples,
        }
    }

    /// The input values of cases `range` (each a vector in input order). Any sub-range gives
    /// the same values as the whole. For many calls over one study use [`Plan::sampler`]: a
    /// Latin hypercube's permutations are drawn on each call here.
    pub fn values(&self, range: std::ops::Range<usize>) -> Vec<Vec<f64>> {
        self.sampler().values(range)
    }

    /// The design ready to give any cases' values ([`Sampler::values`]): a Latin hypercube's
    /// stratum permutations drawn once (8 B per case and input: 24 MB for 10⁶ cases of three
    /// inputs), nothing for the other designs.
    pub fn sampler(&self) -> Sampler<'_> {
        let permutations = match self.design {
            Design::LatinHypercube => (0..self.inputs.len())
                .map(|j| self.permutation(j))
                .collect(),
            Design::Grid | Design::MonteCarlo => Vec::new(),
        };
        Sampler {
            plan: self,
            permutations,
        }
    }

    fn case_stream(&self, i: usize) -> ChaCha8Rng {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        rng.set_stream(i as u64);
        rng
    }

    /// Input j's stratum permutation (Fisher–Yates on its own stream).
    fn permutation(&self, j: usize) -> Vec<usize> {
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed);
        rng.set_stream((1u64 << 48) + j as u64);
        let mut p: Vec<usize> = (0..self.samples).collect();
        for k in (1..p.len()).rev() {
            let r = (rng.next_u64() % (k as u64 + 1)) as usize;
            p.swap(k, r);
        }
        p
    }
}

/// A [`Plan`] with what its cases' values share: a Latin hypercube's permutations.
#[derive(Debug, Clone)]
pub struct Sampler<'a> {
    plan: &'a Plan,
    /// Input j's stratum permutation over all cases (Latin hypercube only).
    permutations: Vec<Vec<usize>>,
}

impl Sampler<'_> {
    /// The input values of cases `range` (each a vector in input order), as
    /// [`Plan::values`]: any sub-range gives the same values as the whole.
    pub fn values(&self, range: std::ops::Range<usize>) -> Vec<Vec<f64>> {
        let plan = self.plan;
        match plan.design {
            Design::Grid => {
                let levels: Vec<Vec<f64>> =
                    plan.inputs.iter().map(|d| d.levels(plan.levels)).collect();
                range
                    .map(|mut i| {
                        // mixed radix, the last input fastest
                        let mut v = vec![0.0; levels.len()];
                        for (j, l) in levels.iter().enumerate().rev() {
                            v[j] = l[i % l.len()];
                            i /= l.len();
                        }
                        v
                    })
                    .collect()
            }
            Design::MonteCarlo => range
                .map(|i| {
                    let mut rng = plan.case_stream(i);
                    let mut u: Vec<f64> =
                        plan.inputs.iter().map(|_| open_uniform(&mut rng)).collect();
                    if let Some(l) = &plan.correlation {
                        u = correlated(l, &u);
                    }
                    plan.inputs
                        .iter()
                        .zip(u)
                        .map(|(d, u)| d.quantile(u))
                        .collect()
                })
                .collect(),
            Design::LatinHypercube => {
                let n = plan.samples as f64;
                range
                    .map(|i| {
                        let mut rng = plan.case_stream(i);
                        plan.inputs
                            .iter()
                            .zip(&self.permutations)
                            .map(|(d, p)| d.quantile((p[i] as f64 + open_uniform(&mut rng)) / n))
                            .collect()
                    })
                    .collect()
            }
        }
    }
}

/// Independent uniforms `u` → correlated ones through the Gaussian copula with Cholesky factor
/// `l` (row-major): Φ(L Φ⁻¹(u)), kept inside (0, 1).
fn correlated(l: &[f64], u: &[f64]) -> Vec<f64> {
    let n = standard();
    let k = u.len();
    let eps: Vec<f64> = u.iter().map(|&p| normal_quantile(&n, p)).collect();
    (0..k)
        .map(|i| {
            let z: f64 = (0..=i).map(|j| l[i * k + j] * eps[j]).sum();
            n.cdf(z).clamp(f64::MIN_POSITIVE, 1.0 - f64::EPSILON / 2.0)
        })
        .collect()
}

/// A uniform in (0, 1): 53 random bits, centred in their cell.
fn open_uniform(rng: &mut ChaCha8Rng) -> f64 {
    ((rng.next_u64() >> 11) as f64 + 0.5) * (1.0 / (1u64 << 53) as f64)
}

/// The contiguous block of cases of shard `k` (1-based) of `n` over `cases`:
/// `[⌊(k−1)·cases/n⌋, ⌊k·cases/n⌋)`.
pub fn shard_range(k: usize, n: usize, cases: usize) -> std::ops::Range<usize> {
    let edge = |k: usize| (k as u128 * cases as u128 / n.max(1) as u128) as usize;
    edge(k - 1)..edge(k)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan(design: Design, inputs: Vec<Distribution>, samples: usize) -> Plan {
        Plan {
            design,
            inputs,
            samples,
            levels: 3,
            seed: 7,
            correlation: None,
        }
    }

    #[test]
    fn quantiles_invert_the_closed_form_cdfs() {
        let n = standard();
        for &u in &[1e-6, 0.1, 0.37, 0.5, 0.9, 1.0 - 1e-6] {
            let x = Distribution::Normal {
                mean: 2.0,
                std: 0.5,
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            }
            .quantile(u);
            assert!(
                (n.cdf((x - 2.0) / 0.5) - u).abs() < 1e-12,
                "normal at {u}: {}",
                n.cdf((x - 2.0) / 0.5) - u
            );
            let x = Distribution::LogNormal {
                median: 0.8,
                geometric_std: 1.2,
                lo: 0.0,
                hi: f64::INFINITY,
            }
            .quantile(u);
            assert!((n.cdf((x / 0.8).ln() / 1.2f64.ln()) - u).abs() < 1e-12);
            // triangular CDF: (x−a)²/((b−a)(c−a)) below the mode, 1 − (b−x)²/((b−a)(b−c)) above
            let (a, c, b) = (1.0, 1.5, 4.0);
            let x = Distribution::Triangular {
                min: a,
                mode: c,
                max: b,
            }
            .quantile(u);
            let cdf = if x < c {
                (x - a).powi(2) / ((b - a) * (c - a))
            } else {
                1.0 - (b - x).powi(2) / ((b - a) * (b - c))
            };
            assert!((cdf - u).abs() < 1e-12, "triangular at {u}");
        }
        // truncated: the CDF restricted and renormalised
        let (lo, hi) = (-0.5, 2.0);
        let d = Distribution::Normal {
            mean: 0.0,
            std: 1.0,
            lo,
            hi,
        };
        for &u in &[0.01, 0.5, 0.99] {
            let x = d.quantile(u);
            assert!((lo..=hi).contains(&x));
            let cdf = (n.cdf(x) - n.cdf(lo)) / (n.cdf(hi) - n.cdf(lo));
            assert!((cdf - u).abs() < 1e-12);
        }
    }

    #[test]
    fn invalid_parameters_are_refused() {
        let inf = f64::INFINITY;
        for d in [
            Distribution::Uniform { min: 2.0, max: 1.0 },
            Distribution::Normal {
                mean: 0.0,
                std: -1.0,
                lo: -inf,
                hi: inf,
            },
            Distribution::Normal {
                mean: 0.0,
                std: 1.0,
                lo: 50.0,
                hi: 60.0,
            },
            Distribution::LogNormal {
                median: 1.0,
                geometric_std: 0.9,
                lo: 0.0,
                hi: inf,
            },
            Distribution::LogUniform { min: 0.0, max: 1.0 },
            Distribution::Triangular {
                min: 0.0,
                mode: 2.0,
                max: 1.0,
            },
            Distribution::Levels(vec![]),
        ] {
            assert!(d.check().is_err(), "{d:?} accepted");
        }
    }

    #[test]
    fn latin_hypercube_puts_one_case_in_every_stratum() {
        let n = 50;
        let p = plan(
            Design::LatinHypercube,
            vec![
                Distribution::Uniform { min: 0.0, max: 1.0 },
                Distribution::Uniform {
                    min: 10.0,
                    max: 20.0,
                },
            ],
            n,
        );
        let values = p.values(0..n);
        for (j, (lo, w)) in [(0.0, 1.0), (10.0, 10.0)].into_iter().enumerate() {
            let mut strata: Vec<usize> = values
                .iter()
                .map(|v| ((v[j] - lo) / w * n as f64) as usize)
                .collect();
            strata.sort_unstable();
            assert_eq!(strata, (0..n).collect::<Vec<_>>(), "input {j}");
        }
    }

    #[test]
    fn any_slice_of_cases_equals_the_same_slice_of_the_whole() {
        let inputs = vec![
            Distribution::Normal {
                mean: 1.0,
                std: 0.1,
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            },
            Distribution::Levels(vec![0.0, 1.0, 2.0]),
        ];
        for design in Design::ALL {
            let p = plan(design, inputs.clone(), 23);
            let n = p.cases();
            let whole = p.values(0..n);
            for shards in [1, 4, 7] {
                let parts: Vec<Vec<f64>> = (1..=shards)
                    .flat_map(|k| p.values(shard_range(k, shards, n)))
                    .collect();
                assert_eq!(parts, whole, "{design:?} in {shards} shards");
            }
            // one sampler (the permutations drawn once) over blocks of 5: the same values
            let sampler = p.sampler();
            let blocks: Vec<Vec<f64>> = (0..n)
                .step_by(5)
                .flat_map(|a| sampler.values(a..(a + 5).min(n)))
                .collect();
            assert_eq!(blocks, whole, "{design:?} in blocks");
        }
    }

    #[test]
    fn a_grid_is_the_full_factorial_with_the_first_input_slowest() {
        let p = plan(
            Design::Grid,
            vec![
                Distribution::Levels(vec![1.0, 2.0]),
                Distribution::Uniform { min: 0.0, max: 3.0 },
            ],
            0,
        );
        assert_eq!(p.cases(), 6);
        let v = p.values(0..6);
        assert_eq!(v[0], vec![1.0, 0.5]);
        assert_eq!(v[2], vec![1.0, 2.5]);
        assert_eq!(v[3], vec![2.0, 0.5]);
    }

    #[test]
    fn monte_carlo_moments_converge_to_the_distribution() {
        let p = plan(
            Design::MonteCarlo,
            vec![Distribution::Normal {
                mean: 0.25,
                std: 0.02,
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            }],
            20_000,
        );
        let x: Vec<f64> = p.values(0..20_000).into_iter().map(|v| v[0]).collect();
        let mean = x.iter().sum::<f64>() / x.len() as f64;
        let var = x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (x.len() - 1) as f64;
        // 4 standard errors
        assert!((mean - 0.25).abs() < 4.0 * 0.02 / (20_000f64).sqrt());
        assert!((var.sqrt() / 0.02 - 1.0).abs() < 4.0 / (2.0 * 20_000f64).sqrt());
    }

    #[test]
    fn correlated_inputs_have_the_asked_rank_correlation_and_keep_their_marginals() {
        let n = 20_000;
        let mut p = plan(
            Design::MonteCarlo,
            vec![
                Distribution::Uniform { min: 0.0, max: 1.0 },
                Distribution::LogNormal {
                    median: 1.0,
                    geometric_std: 2.0,
                    lo: 0.0,
                    hi: f64::INFINITY,
                },
                Distribution::Uniform { min: 0.0, max: 1.0 },
            ],
            n,
        );
        p.correlation = Some(correlation_factor(3, &[(0, 1, 0.8), (1, 2, -0.3)]).unwrap());
        let v = p.values(0..n);
        let col = |j: usize| v.iter().map(|c| c[j]).collect::<Vec<f64>>();
        let rho =
            |a: usize, b: usize| crate::study::sensitivity::spearman(&col(a), &col(b)).unwrap();
        // the sample ρ_s has a standard error ≈ 1/√n ≈ 0.007
        assert!((rho(0, 1) - 0.8).abs() < 0.02, "{}", rho(0, 1));
        assert!((rho(1, 2) + 0.3).abs() < 0.02, "{}", rho(1, 2));
        // the marginals: the uniform's mean ½ and the log-normal's median 1
        let mean = col(0).iter().sum::<f64>() / n as f64;
        assert!((mean - 0.5).abs() < 0.01);
        let mut x = col(1);
        x.sort_by(f64::total_cmp);
        assert!((x[n / 2] - 1.0).abs() < 0.05, "{}", x[n / 2]);
        // contradicting correlations are refused
        assert!(correlation_factor(3, &[(0, 1, 0.9), (1, 2, 0.9), (0, 2, -0.9)]).is_err());
    }

    #[test]
    fn shards_cover_every_case_once() {
        for cases in [0, 1, 5, 100, 101] {
            for n in 1..=9 {
                let mut next = 0;
                for k in 1..=n {
                    let r = shard_range(k, n, cases);
                    assert_eq!(r.start, next);
                    next = r.end;
                }
                assert_eq!(next, cases);
            }
        }
    }
}
