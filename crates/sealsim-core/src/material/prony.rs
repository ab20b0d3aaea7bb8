//! Prony-series relaxation modulus in reduced time (docs/model.md §5).
//!
//! `E(ξ) = E∞ + Σ E_i e^{−ξ/τ_i}`, `E0 = E∞ + Σ E_i`. Storage and loss moduli
//! `E′(ω) = E∞ + Σ E_i ω²τ_i²/(1+ω²τ_i²)`, `E″(ω) = Σ E_i ωτ_i/(1+ω²τ_i²)`.
//! The creep compliance `J(ξ) = 1/E∞ − Σ_j B_j e^{−ξ/λ_j}` is the exact interconversion
//! (`s Ē(s) · s J̄(s) = 1`): the retardation times λ_j are the zeros of
//! `Ê(−1/λ) = E∞ + Σ E_i τ_i/(τ_i − λ)`, one in each interval `(τ_i, τ_{i+1})` and one above
//! τ_max (when E∞ > 0), and `B_j = 1/(λ_j Σ_i E_i τ_i/(λ_j − τ_i)²)` (Tschoegl, *The
//! Phenomenological Theory of Linear Viscoelastic Behavior*, Springer 1989, ch. 4).

use crate::math::special::exp_neg;
use crate::units::show;
use std::fmt;

/// One Maxwell branch: modulus E_i \[Pa\], relaxation time τ_i \[s, reduced time\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PronyTerm {
    pub modulus: f64,
    pub tau: f64,
}

/// Why a Prony series is invalid.
#[derive(Debug, Clone, PartialEq)]
pub struct PronyError(pub String);

impl fmt::Display for PronyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for PronyError {}

/// A Prony series with its terms sorted by τ (see the module docs).
#[derive(Debug, Clone)]
pub struct Prony {
    long_term: f64,
    terms: Vec<PronyTerm>,
    /// E_i and 1/τ_i as separate arrays: E(ξ) is a vectorisable multiply–exp–add loop.
    moduli: Vec<f64>,
    rates: Vec<f64>,
    /// The creep series, computed once and shared by clones (a study's cases share their
    /// compound's): not part of the series' identity.
    creep: std::sync::Arc<std::sync::OnceLock<Creep>>,
}

impl PartialEq for Prony {
    fn eq(&self, other: &Self) -> bool {
        self.long_term == other.long_term
            && self.terms == other.terms
            && self.moduli == other.moduli
            && self.rates == other.rates
    }
}

impl Prony {
    /// `E∞ ≥ 0`, every `E_i > 0` and `τ_i > 0`, all finite, at least one of E∞ and the terms
    /// positive. Terms are sorted by τ; equal τ are merged.
    pub fn new(long_term: f64, terms: &[PronyTerm]) -> Result<Self, PronyError> {
        if !(long_term.is_finite() && long_term >= 0.0) {
            return Err(PronyError(format!(
                "the long-term modulus must be finite and ≥ 0, got {} Pa",
                show(long_term)
            )));
        }
        for (i, t) in terms.iter().enumerate() {
            if !(t.modulus.is_finite() && t.modulus > 0.0) {
                return Err(PronyError(format!(
                    "term {}: the modulus must be positive and finite, got {} Pa",
                    i + 1,
                    show(t.modulus)
                )));
            }
            if !(t.tau.is_finite() && t.tau > 0.0) {
                return Err(PronyError(format!(
                    "term {}: the relaxation time must be positive and finite, got {} s",
                    i + 1,
                    show(t.tau)
                )));
            }
        }
        let mut sorted = terms.to_vec();
        sorted.sort_by(|a, b| a.tau.total_cmp(&b.tau));
        sorted.dedup_by(|b, a| {
            let same = a.tau == b.tau;
            if same {
                a.modulus += b.modulus;
            }
            same
        });
        if long_term == 0.0 && sorted.is_empty() {
            return Err(PronyError(
                "the modulus is zero: give a long-term modulus or Prony terms".into(),
            ));
        }
        let moduli = sorted.iter().map(|t| t.modulus).collect();
        let rates = sorted.iter().map(|t| 1.0 / t.tau).collect();
        Ok(Prony {
            long_term,
            terms: sorted,
            moduli,
            rates,
            creep: Default::default(),
        })
    }

    /// A purely elastic material (no terms): `E(t) = E`.
    pub fn elastic(modulus: f64) -> Result<Self, PronyError> {
        Prony::new(modulus, &[])
    }

    /// The series with every modulus (E∞ and each E_i) multiplied by `factor` (> 0) and the
    /// relaxation times kept: a uniformly softened or stiffened network (e.g. a swollen one,
    /// [`crate::seal::VolumeSwell::modulus_factor`]).
    pub fn scaled(&self, factor: f64) -> Prony {
        let terms: Vec<PronyTerm> = self
            .terms
            .iter()
            .map(|t| PronyTerm {
                modulus: t.modulus * factor,
                tau: t.tau,
            })
            .collect();
        Prony {
            long_term: self.long_term * factor,
            moduli: terms.iter().map(|t| t.modulus).collect(),
            rates: self.rates.clone(),
            terms,
            creep: Default::default(),
        }
    }

    /// Long-term (relaxed) modulus E∞ \[Pa\].
    pub fn long_term(&self) -> f64 {
        self.long_term
    }

    /// Instantaneous (glassy-side) modulus E0 = E∞ + Σ E_i \[Pa\].
    pub fn instantaneous(&self) -> f64 {
        self.long_term + self.terms.iter().map(|t| t.modulus).sum::<f64>()
    }

    /// The branches, sorted by τ.
    pub fn terms(&self) -> &[PronyTerm] {
        &self.terms
    }

    /// Relaxation modulus E(ξ) \[Pa\] at reduced time ξ ≥ 0 \[s\] (with the table-driven
    /// [`exp_neg`]: E(ξ) sits in every time step and fit residual).
    pub fn relaxation(&self, xi: f64) -> f64 {
        // 1/τ stored (a multiply, not a divide, per term) and four independent partial sums
        let mut acc = [0.0; 4];
        let (m4, m_rest) = self.moduli.as_chunks::<4>();
        let (r4, r_rest) = self.rates.as_chunks::<4>();
        for (m, r) in m4.iter().zip(r4) {
            for k in 0..4 {
                acc[k] += m[k] * exp_neg(xi * r[k]);
            }
        }
        let rest: f64 = m_rest
            .iter()
            .zip(r_rest)
            .map(|(m, r)| m * (-xi * r).exp())
            .sum();
        self.long_term + (acc[0] + acc[1]) + (acc[2] + acc[3]) + rest
    }

    /// Storage modulus E′(ω) \[Pa\], ω \[rad/s\].
    pub fn storage(&self, omega: f64) -> f64 {
        self.long_term
            + self
                .terms
                .iter()
                // ω²τ²/(1 + ω²τ²) written as 1/(1 + (ωτ)^−2): no overflow for ωτ > 1e154
                .map(|t| t.modulus / (1.0 + (omega * t.tau).powi(-2)))
                .sum::<f64>()
    }

    /// Loss modulus E″(ω) \[Pa\], ω \[rad/s\].
    pub fn loss(&self, omega: f64) -> f64 {
        self.terms
            .iter()
            // ωτ/(1 + ω²τ²) written as 1/(ωτ + 1/(ωτ)): no overflow at either end
            .map(|t| {
                let w = omega * t.tau;
                t.modulus / (w + w.recip())
            })
            .sum()
    }

    /// Loss factor tan δ = E″/E′.
    pub fn tan_delta(&self, omega: f64) -> f64 {
        self.loss(omega) / self.storage(omega)
    }

    /// The creep compliance as a retardation series (see the module docs); computed on the
    /// first call and kept.
    pub fn creep(&self) -> Creep {
        self.creep.get_or_init(|| self.compute_creep()).clone()
    }

    fn compute_creep(&self) -> Creep {
        let n = self.terms.len();
        let mut retardation = Vec::with_capacity(n);
        for j in 0..n {
            let lo = self.terms[j].tau;
            let hi = if j + 1 < n {
                Some(self.terms[j + 1].tau)
            } else {
                None
            };
            let Some(lambda) = self.retardation_time(lo, hi) else {
                continue;
            };
            let sum: f64 = self
                .terms
                .iter()
                .map(|t| t.modulus * t.tau / (lambda - t.tau).powi(2))
                .sum();
            retardation.push(PronyTerm {
                modulus: 1.0 / (lambda * sum),
                tau: lambda,
            });
        }
        // With E∞ = 0 the material flows: J gains a steady-flow term ξ/η0, η0 = Σ E_i τ_i.
        let fluidity = if self.long_term > 0.0 {
            0.0
        } else {
            1.0 / self.terms.iter().map(|t| t.modulus * t.tau).sum::<f64>()
        };
        Creep {
            instantaneous: 1.0 / self.instantaneous(),
            fluidity,
            retardation,
        }
    }

    /// The zero of `Ê(−1/λ) = E∞ + Σ E_i τ_i/(τ_i − λ)` in `(lo, hi)` (`hi = None`: above the
    /// last τ, which exists only when E∞ > 0). Bisection in ln λ: the function rises
    /// monotonically from −∞ to +∞ (or to E∞) across the interval, so it is bracketed.
    fn retardation_time(&self, lo: f64, hi: Option<f64>) -> Option<f64> {
        let g = |lambda: f64| -> f64 {
            self.long_term
                + self
                    .terms
                    .iter()
                    .map(|t| t.modulus * t.tau / (t.tau - lambda))
                    .sum::<f64>()
        };
        let (mut a, mut b) = match hi {
            Some(hi) => (lo.ln(), hi.ln()),
            None => {
                if self.long_term <= 0.0 {
                    return None;
                }
                // g(λ) → E∞ from below; above λ = τ_max (1 + E_max-ish/E∞ ...) it is positive.
                let mut b = lo.ln() + 1.0;
                while g(b.exp()) <= 0.0 {
                    b += 1.0;
                    if b > 745.0 {
                        return None;
                    }
                }
                (lo.ln(), b)
            }
        };
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if m <= a || m >= b {
                break;
            }
            if g(m.exp()) < 0.0 {
                a = m;
            } else {
                b = m;
            }
        }
        Some((0.5 * (a + b)).exp())
    }
}

/// Creep compliance `J(ξ) = 1/E0 + ξ/η0 + Σ_j B_j (1 − e^{−ξ/λ_j})` \[1/Pa\]; the flow term
/// ξ/η0 is present only when E∞ = 0 (then `1/Ê(s)` has a pole at s = 0), otherwise
/// `J(∞) = 1/E∞`.
#[derive(Debug, Clone, PartialEq)]
pub struct Creep {
    instantaneous: f64,
    /// 1/η0 \[1/(Pa·s)\], zero for a solid (E∞ > 0).
    fluidity: f64,
    /// B_j \[1/Pa\] in `modulus`, λ_j in `tau`.
    retardation: Vec<PronyTerm>,
}

impl Creep {
    /// J(ξ) \[1/Pa\].
    pub fn compliance(&self, xi: f64) -> f64 {
        let delayed: f64 = self
            .retardation
            .iter()
            .map(|r| r.modulus * (-(-xi / r.tau).exp_m1()))
            .sum();
        self.instantaneous + self.fluidity * xi + delayed
    }

    /// The strain at ξ after a stress ramped linearly to 1 Pa over the reduced time `ramp` and
    /// held since, per pascal: the mean of J over [ξ, ξ + ramp] \[1/Pa\]
    /// (`1/E0 + (ξ + ramp/2)/η0 + Σ B_j (1 − λ_j e^{−ξ/λ_j} (1 − e^{−ramp/λ_j})/ramp)`); J(ξ) at
    /// ramp = 0.
    pub fn ramp_compliance(&self, xi: f64, ramp: f64) -> f64 {
        if ramp <= 0.0 {
            return self.compliance(xi);
        }
        self.ramp_compliance_with(xi, ramp, &self.ramp_weights(ramp))
    }

    /// The per-term factors `(1 − e^{−ramp/λ_j})/(ramp/λ_j)` of [`Self::ramp_compliance`]: a
    /// run evaluates the compliance at every state after one installation ramp, so it computes
    /// them once.
    pub fn ramp_weights(&self, ramp: f64) -> Vec<f64> {
        self.retardation
            .iter()
            .map(|r| {
                let x = ramp / r.tau;
                // (1 − e^{−x})/x, accurate for small x
                if x < 1e-8 {
                    1.0 - 0.5 * x
                } else {
                    -(-x).exp_m1() / x
                }
            })
            .collect()
    }

    /// [`Self::ramp_compliance`] with the weights of [`Self::ramp_weights`]`(ramp)` (the same
    /// bits); `ramp > 0`.
    pub fn ramp_compliance_with(&self, xi: f64, ramp: f64, weights: &[f64]) -> f64 {
        let delayed: f64 = self
            .retardation
            .iter()
            .zip(weights)
            .map(|(r, phi)| r.modulus * (1.0 - (-xi / r.tau).exp() * phi))
            .sum();
        self.instantaneous + self.fluidity * (xi + 0.5 * ramp) + delayed
    }

    /// 1/η0 \[1/(Pa·s)\] of the steady-flow term (zero when E∞ > 0).
    pub fn fluidity(&self) -> f64 {
        self.fluidity
    }

    /// The retardation terms (B_j in `modulus` \[1/Pa\], λ_j in `tau` \[s\]).
    pub fn retardation(&self) -> &[PronyTerm] {
        &self.retardation
    }

    /// J(0) = 1/E0 \[1/Pa\].
    pub fn instantaneous(&self) -> f64 {
        self.instantaneous
    }
}

/// The branch stresses of a Prony material under a strain history, advanced by the exact
/// exponential update for strain linear in reduced time within a step (Taylor, Pister &
/// Goudreau, Int. J. Numer. Meth. Eng. 2 (1970) 45; Simo & Hughes, *Computational
/// Inelasticity*, Springer 1998, §10.3):
/// `h_i ← e^{−x} h_i + E_i φ(x) Δε`, `x = Δξ/τ_i`, `φ(x) = −expm1(−x)/x`;
/// `σ = E∞ ε + Σ h_i`. Unconditionally stable and exact for piecewise-linear strain.
///
/// With chemical ageing ([`Self::step_aged`]) the state is that of the two-network model
/// (docs/model.md §6.5): the original network breaks at the scission rate k_s, a new network
/// forms at `r·k_s` in the state the rubber is in when it forms and carries stress only for
/// strain changes after its formation. With K = ∫k_s dt, the crosslink fraction
/// c (`c' = k_s (r − c)`, c(0) = 1) and the set reference y (`y' = k_s (r ε − y)`, y(0) = 0):
/// `σ = E∞ (c ε − y) + Σ h_i`, and every branch decays with the network,
/// `h_i ← e^{−x − ΔK} h_i + E_i c φ(x + ΔK) Δε`. The equilibrium strain z = c ε − y obeys
/// `dz/dK = −z + c dε/dK` — a branch with τ = ∞ — and is carried besides y: the stress from z
/// keeps its relative precision however far it has decayed (z → ε e^{−K}), the set from y
/// however little has formed (y → r ε K).
#[derive(Debug, Clone, PartialEq)]
pub struct RelaxationState {
    strain: f64,
    branches: Vec<f64>,
    /// c, the crosslink density relative to the original network's.
    network: f64,
    /// z = c ε − y, the strain the equilibrium spring E∞ carries (ε unaged).
    equilibrium: f64,
    /// y, the strain the later networks hold at rest, times their fraction (0 unaged).
    set_reference: f64,
}

/// One step of chemical ageing for [`RelaxationState::step_aged`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChemicalStep {
    /// ΔK = ∫ k_s dt over the step (scission of the network, ≥ 0).
    pub scission: f64,
    /// r = k_x/k_s, the rate at which a new network forms in the deformed state relative to
    /// the scission rate (1: balanced, compression set = 1 − F/F0; 0: scission only).
    pub crosslinking: f64,
}

impl RelaxationState {
    /// Unstrained, relaxed state.
    pub fn new(prony: &Prony) -> Self {
        RelaxationState {
            strain: 0.0,
            branches: vec![0.0; prony.terms().len()],
            network: 1.0,
            equilibrium: 0.0,
            set_reference: 0.0,
        }
    }

    /// The chemical networks of the two-network model alone, without the Prony branches
    /// (step it with any series: no branch is updated): its [`Self::set_strain`] y/c is the
    /// strain the aged networks hold at rest, on whatever strain it is stepped with
    /// (docs/model.md §6.5: the compression set on the material strain).
    pub fn networks_only() -> Self {
        RelaxationState {
            strain: 0.0,
            branches: Vec::new(),
            network: 1.0,
            equilibrium: 0.0,
            set_reference: 0.0,
        }
    }

    /// Advances by reduced time `d_xi ≥ 0` while the strain changes linearly by `d_strain`.
    /// `d_xi = 0` is an instantaneous jump (φ(0) = 1).
    pub fn step(&mut self, prony: &Prony, d_xi: f64, d_strain: f64) {
        self.step_aged(
            prony,
            d_xi,
            d_strain,
            ChemicalStep {
                scission: 0.0,
                crosslinking: 0.0,
            },
        );
    }

    /// [`Self::step`] with chemical ageing over the step (two-network model; Andrews,
    /// Tobolsky & Hanson, J. Appl. Phys. 17 (1946) 352): the branches and z as in the type's doc
    /// with c at the step's middle (`z ← e^{−ΔK} z + c φ(ΔK) Δε`); c and y exactly for the
    /// strain linear in K within the step: `c ← e^{−ΔK} c + r (1 − e^{−ΔK})`,
    /// `y ← e^{−ΔK} y + r [ε_a (1 − e^{−ΔK}) + Δε (1 − φ(ΔK))]`. Exact at constant strain for
    /// any step; with ΔK = 0 it is [`Self::step`] bit for bit.
    pub fn step_aged(&mut self, prony: &Prony, d_xi: f64, d_strain: f64, chem: ChemicalStep) {
        let d_k = chem.scission;
        let r = chem.crosslinking;
        let decay = exp_neg(d_k);
        // 1 − e^{−ΔK} without cancellation: ΔK of a step is often 1e-12 or less
        let formed = -(-d_k).exp_m1();
        let network_end = decay * self.network + r * formed;
        let network_mid = if d_k > 0.0 {
            let half = -(-0.5 * d_k).exp_m1();
            (1.0 - half) * self.network + r * half
        } else {
            self.network
        };
        if d_strain == 0.0 {
            // at constant strain (most steps of a life at a steady temperature) the branches
            // only decay: the same bits as below, whose second term is then +0, without φ
            for (h, t) in self.branches.iter_mut().zip(prony.terms()) {
                *h = exp_neg(d_xi / t.tau + d_k) * *h + 0.0;
            }
        } else {
            for (h, t) in self.branches.iter_mut().zip(prony.terms()) {
                let x = d_xi / t.tau + d_k;
                *h = exp_neg(x) * *h + t.modulus * network_mid * phi(x) * d_strain;
            }
        }
        self.equilibrium = decay * self.equilibrium + network_mid * phi(d_k) * d_strain;
        if d_k > 0.0 {
            self.set_reference = decay * self.set_reference
                + r * (self.strain * formed + d_strain * (1.0 - phi(d_k)));
        }
        self.network = network_end;
        self.strain += d_strain;
    }

    /// Current stress σ = E∞ z + Σ h_i \[Pa\] (z = ε unaged).
    pub fn stress(&self, prony: &Prony) -> f64 {
        prony.long_term() * self.equilibrium + self.branches.iter().sum::<f64>()
    }

    /// Current strain.
    pub fn strain(&self) -> f64 {
        self.strain
    }

    /// The strain at which the equilibrium stress of the aged networks vanishes, `y/c`: where
    /// the rubber returns to when released and fully recovered (0 unaged).
    pub fn set_strain(&self) -> f64 {
        if self.network > 0.0 {
            self.set_reference / self.network
        } else {
            self.strain
        }
    }

    /// The crosslink density relative to the original network's, c.
    pub fn network(&self) -> f64 {
        self.network
    }
}

/// `φ(x) = (1 − e^{−x})/x`, → 1 at x = 0, accurate for small x.
#[inline]
fn phi(x: f64) -> f64 {
    if x < 1e-8 {
        1.0 - 0.5 * x
    } else {
        -(-x).exp_m1() / x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wide() -> Prony {
        // one term per decade, τ from 1e-2 s to 1e28 s
        let terms: Vec<PronyTerm> = (-2..=28)
            .map(|k| PronyTerm {
                modulus: 1e6 * (1.0 + 0.3 * (k as f64).sin()),
                tau: 10f64.powi(k),
            })
            .collect();
        Prony::new(2e6, &terms).unwrap()
    }

    #[test]
    fn recursive_update_equals_closed_form_at_constant_strain() {
        let p = wide();
        let mut s = RelaxationState::new(&p);
        let eps = 0.1;
        s.step(&p, 0.0, eps);
        let mut t = 0.0;
        let mut worst: f64 = 0.0;
        // 10 steps per decade from 1e-3 s to 1e30 s
        for k in 0..=330 {
            let next = 10f64.powf(-3.0 + k as f64 / 10.0);
            s.step(&p, next - t, 0.0);
            t = next;
            let exact = eps * p.relaxation(t);
            worst = worst.max((s.stress(&p) / exact - 1.0).abs());
        }
        eprintln!("recursive update: worst relative error {worst:e}");
        assert!(worst <= 1e-12, "worst relative error {worst:e}");
    }

    #[test]
    fn storage_and_loss_limits() {
        let p = wide();
        assert!((p.storage(1e-40) / p.long_term() - 1.0).abs() < 1e-12);
        assert!((p.storage(1e40) / p.instantaneous() - 1.0).abs() < 1e-12);
        assert!(p.loss(1e-45) < 1e-15 * p.long_term());
        // no overflow far outside the spectrum
        for omega in [0.0, 1e-300, 1e300, f64::MAX] {
            assert!(
                p.storage(omega).is_finite() && p.loss(omega).is_finite(),
                "ω = {omega}"
            );
        }
        // a single term peaks in loss at ωτ = 1 with E''/E_1 = 1/2
        let one = Prony::new(
            1e6,
            &[PronyTerm {
                modulus: 4e6,
                tau: 10.0,
            }],
        )
        .unwrap();
        assert!((one.loss(0.1) - 2e6).abs() < 1e-6);
        assert!((one.tan_delta(0.1) - 2e6 / 3e6).abs() < 1e-12);
    }

    #[test]
    fn invalid_series_are_rejected() {
        assert!(Prony::new(-1.0, &[]).is_err());
        assert!(Prony::new(0.0, &[]).is_err());
        assert!(
            Prony::new(
                1.0,
                &[PronyTerm {
                    modulus: -1.0,
                    tau: 1.0
                }]
            )
            .is_err()
        );
        assert!(
            Prony::new(
                1.0,
                &[PronyTerm {
                    modulus: 1.0,
                    tau: 0.0
                }]
            )
            .is_err()
        );
        assert!(
            Prony::new(
                1.0,
                &[PronyTerm {
                    modulus: 1.0,
                    tau: f64::NAN
                }]
            )
            .is_err()
        );
    }

    #[test]
    fn two_networks_at_constant_strain_match_their_closed_forms() {
        // constant scission rate k, strain x0 from t = 0: for any r, σ = x0 E(t) e^{−kt} and
        // c = e^{−K} + r(1 − e^{−K}), set y/c = x0 r(1 − e^{−K})/c, K = kt
        let p = wide();
        let (x0, k) = (0.1, 3e-9);
        for r in [0.0, 0.5, 1.0, 2.0] {
            let mut s = RelaxationState::new(&p);
            s.step(&p, 0.0, x0);
            let mut t = 0.0;
            let mut worst: f64 = 0.0;
            for n in 0..=220 {
                let next = 10f64.powf(-2.0 + n as f64 / 20.0);
                let chem = ChemicalStep {
                    scission: k * (next - t),
                    crosslinking: r,
                };
                s.step_aged(&p, next - t, 0.0, chem);
                t = next;
                let big_k = k * t;
                let stress = x0 * p.relaxation(t) * (-big_k).exp();
                let c = (-big_k).exp() + r * -(-big_k).exp_m1();
                let set = x0 * r * -(-big_k).exp_m1() / c;
                worst = worst
                    .max((s.stress(&p) / stress - 1.0).abs())
                    .max((s.network() / c - 1.0).abs());
                if set > 0.0 {
                    worst = worst.max((s.set_strain() / set - 1.0).abs());
                } else {
                    assert_eq!(s.set_strain(), 0.0);
                }
            }
            assert!(worst <= 1e-9, "r = {r}: worst relative error {worst:e}");
        }
    }

    #[test]
    fn a_strain_change_after_ageing_meets_the_whole_network() {
        // after K = 1 at x0: an instantaneous Δx changes the stress by c E0 Δx — E0 Δx for r = 1,
        // e^{−K} E0 Δx for scission alone (r = 0), which is the plain multiplier's
        let p = wide();
        let (x0, dx) = (0.1, -0.02);
        for (r, factor) in [(1.0, 1.0), (0.0, (-1.0f64).exp())] {
            let mut s = RelaxationState::new(&p);
            s.step(&p, 0.0, x0);
            for _ in 0..10 {
                let chem = ChemicalStep {
                    scission: 0.1,
                    crosslinking: r,
                };
                s.step_aged(&p, 1e3, 0.0, chem);
            }
            let before = s.stress(&p);
            s.step(&p, 0.0, dx);
            let change = s.stress(&p) - before;
            let hand = factor * p.instantaneous() * dx;
            assert!(
                (change / hand - 1.0).abs() < 1e-12,
                "r = {r}: {change} vs {hand}"
            );
        }
    }

    #[test]
    fn ramp_compliance_is_the_mean_of_j_over_the_ramp() {
        let p = wide();
        let c = p.creep();
        for (xi, ramp) in [(0.0, 1.0), (10.0, 1e-3), (1e3, 1e6), (1e20, 5.0)] {
            // midpoint rule with 200 000 panels on [ξ, ξ + ramp]
            let n = 200_000;
            let h = ramp / n as f64;
            let mean: f64 = (0..n)
                .map(|k| c.compliance(xi + (k as f64 + 0.5) * h))
                .sum::<f64>()
                / n as f64;
            let rel = (c.ramp_compliance(xi, ramp) / mean - 1.0).abs();
            assert!(rel < 1e-8, "ξ = {xi}, ramp = {ramp}: {rel:e}");
        }
        assert_eq!(c.ramp_compliance(3.0, 0.0), c.compliance(3.0));
    }

    #[test]
    fn creep_single_term_closed_form() {
        // standard linear solid: λ = τ E0/E∞, J(t) = 1/E∞ − (1/E∞ − 1/E0) e^{−t/λ}
        let (einf, e1, tau) = (1e6, 4e6, 10.0);
        let p = Prony::new(einf, &[PronyTerm { modulus: e1, tau }]).unwrap();
        let c = p.creep();
        let lambda = tau * (einf + e1) / einf;
        assert_eq!(c.retardation().len(), 1);
        assert!((c.retardation()[0].tau / lambda - 1.0).abs() < 1e-12);
        for t in [0.0, 1.0, 50.0, 1e4] {
            let exact = 1.0 / einf - (1.0 / einf - 1.0 / (einf + e1)) * (-t / lambda).exp();
            assert!((c.compliance(t) / exact - 1.0).abs() < 1e-12, "t={t}");
        }
    }
}
