//! The effective-medium level (docs/model.md §3.3): Bruggeman's 2-D effective conductance over the
//! distribution of interfacial separations.
//!
//! **Separation distribution** [recalled: Lorenz & Persson, Eur. Phys. J. E 31 (2010) 159;
//! Persson, J. Phys.: Condens. Matter 22 (2010) 265004], for u ≥ 0:
//!
//! `P(u) = (A(ζ1)/A0) δ(u) + ∫_1^{ζ1} dζ \[−A′(ζ)/A0\] (2π h²(ζ))^{−1/2}
//!         { e^{−(u−u1(ζ))²/2h²(ζ)} + e^{−(u+u1(ζ))²/2h²(ζ)} }`,
//!
//! with ζ1 = q1/q0, h(ζ) = h_rms(ζ) the roughness left above ζq0 (PY08 eq. 4) and u1(ζ) the
//! separation of the surfaces that come into contact at ζ (docs/model.md §2). It is kept as a contact
//! fraction `c = A(ζ1)/A0` plus a set of weighted *folded* Gaussians — one per Gauss–Legendre
//! node in ln M3(ζ), weight `w_i = ω_i [−dA/d ln M3]/A0` — so that the mass, the mean and the CDF
//! are closed forms. The weights integrate −A′ from 1 to ζ1, so `c + Σ w_i = A(1)/A0 = 1` up to
//! the quadrature error (a test).
//!
//! **Effective conductance**: the local conductance per unit width of a gap u is
//! `σ(u) = u³/(12η)` \[m³/(Pa·s)\]; the 2-D Bruggeman condition is
//! `∫ P(u) (σ_eff − σ(u))/(σ_eff + σ(u)) du = 0`. η cancels, so it is solved for
//! `g = 12 η σ_eff = u_eff³` \[m³\] by bisection in ln g. The left-hand side increases
//! monotonically from `2c − 1` (g → 0⁺) to 1 (g → ∞): a root exists only below the 2-D
//! threshold c < 1/2; at and above it the interface is sealed, g = 0 exactly. A gap no wider
//! than one molecule of the fluid ([`EffectiveMediumSettings::molecular_size`]; a rarefied gas's
//! diameter) conducts nothing (docs/model.md §8.1) and counts as contact: c is then
//! `P(u ≤ molecule)`, and the medium seals where that reaches ½.
//! The leak rate of a flat seal is `Q̇ = (L_y/L_x) σ_eff ΔP` (docs/model.md §3.3).

use super::PerssonContact;
use crate::math::quadrature::{composite, gauss_legendre};
use crate::math::special::erf;
use std::f64::consts::{FRAC_1_SQRT_2, PI, SQRT_2};

/// Half-width, in standard deviations, of the u-range integrated for each Gaussian (mass
/// outside ±8σ is 1.2e-15).
const SIGMAS: f64 = 8.0;

/// Quadrature settings of the effective-medium level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EffectiveMediumSettings {
    /// Largest Gauss–Legendre panel width in `ln M3(ζ)` for the ζ-integral of P(u).
    pub panel_width: f64,
    /// Gauss–Legendre points per ln ζ panel.
    pub order: usize,
    /// Uniform panels per sub-interval of the u-integral of each Gaussian (sub-intervals are
    /// cut at u = 0 and at ±u_eff·{½, 1, 2, 4}, where the Bruggeman kernel turns over).
    pub u_panels: usize,
    /// Gauss–Legendre points per u panel.
    pub u_order: usize,
    /// The size of one molecule of the fluid \[m\] ([`crate::fluid::Fluid::molecular_size`]): a
    /// local gap no wider conducts nothing in the Bruggeman average — it counts as contact
    /// ([`crate::fluid::passes_molecule`], docs/model.md §3.3, §8.1). 0 (the default): every open
    /// gap conducts; a contact path sets its fluid's
    /// (`leak::PathOptions::molecular_size`). A rarefied gas uses its own diameter.
    pub molecular_size: f64,
}

impl Default for EffectiveMediumSettings {
    fn default() -> Self {
        EffectiveMediumSettings {
            panel_width: 0.5,
            order: 8,
            u_panels: 4,
            u_order: 10,
            molecular_size: 0.0,
        }
    }
}

impl EffectiveMediumSettings {
    /// The same rules with `factor`× as many nodes in ln ζ and in u: for convergence checks.
    pub fn refined(self, factor: usize) -> Self {
        EffectiveMediumSettings {
            panel_width: self.panel_width / factor as f64,
            order: self.order,
            u_panels: self.u_panels * factor,
            u_order: self.u_order,
            molecular_size: self.molecular_size,
        }
    }
}

/// One folded normal component of P(u): density
/// `weight · [N(u; center, width) + N(u; −center, width)]` on u ≥ 0, of total mass `weight`.
/// `width = 0` is a point mass at `center`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoldedGaussian {
    /// Probability carried by this component (≥ 0).
    pub weight: f64,
    /// Centre u1(ζ) \[m\] (≥ 0).
    pub center: f64,
    /// Standard deviation h_rms(ζ) \[m\] (≥ 0).
    pub width: f64,
}

impl FoldedGaussian {
    /// The sub-intervals of the component's range μ ± [`SIGMAS`]σ cut at the `breaks` inside
    /// it, as sorted cut points in `cuts`.
    fn cuts(&self, breaks: &[f64], cuts: &mut Vec<f64>) {
        let (a, b) = (
            self.center - SIGMAS * self.width,
            self.center + SIGMAS * self.width,
        );
        cuts.clear();
        cuts.push(a);
        cuts.extend(breaks.iter().copied().filter(|&v| v > a && v < b));
        cuts.push(b);
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
    }

    /// Each node u of `rule` over the sub-intervals `cuts` with its weight `½h·w_k·e^{−z²/2}`,
    /// z = (u − μ)/σ (the normal density up to 1/(σ√(2π)), applied by the caller).
    fn for_each_node(&self, cuts: &[f64], rule: &URule<'_>, mut f: impl FnMut(f64, f64)) {
        let inv = 1.0 / self.width;
        for pair in cuts.windows(2) {
            let h = (pair[1] - pair[0]) / rule.panels as f64;
            for p in 0..rule.panels {
                let mid = pair[0] + (p as f64 + 0.5) * h;
                for (x, w) in rule.nodes.iter().zip(rule.weights) {
                    let u = mid + 0.5 * h * x;
                    let z = (u - self.center) * inv;
                    f(u, 0.5 * h * w * (-0.5 * z * z).exp());
                }
            }
        }
    }

    /// `P(U ≤ u)` of the folded normal (without the weight):
    /// `½[erf((u+μ)/(σ√2)) + erf((u−μ)/(σ√2))]` for u ≥ 0.
    pub fn cdf(&self, u: f64) -> f64 {
        if u < 0.0 {
            return 0.0;
        }
        if self.width <= 0.0 {
            return if u >= self.center { 1.0 } else { 0.0 };
        }
        let k = FRAC_1_SQRT_2 / self.width;
        0.5 * (erf((u + self.center) * k) + erf((u - self.center) * k))
    }

    /// Mean of the folded normal (without the weight):
    /// `σ√(2/π) e^{−μ²/2σ²} + μ erf(μ/(σ√2))` \[m\].
    pub fn mean(&self) -> f64 {
        if self.width <= 0.0 {
            return self.center;
        }
        let (m, s) = (self.center, self.width);
        s * (2.0 / PI).sqrt() * (-0.5 * (m / s).powi(2)).exp() + m * erf(m / (s * SQRT_2))
    }
}

/// The distribution of interfacial separations: a contact fraction (u = 0) plus folded
/// Gaussians (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SeparationDistribution {
    contact: f64,
    components: Vec<FoldedGaussian>,
}

impl SeparationDistribution {
    /// A distribution from its parts (e.g. synthetic ones for tests). Negative or non-finite
    /// weights, centres and widths are clamped to 0.
    pub fn new(contact: f64, components: Vec<FoldedGaussian>) -> Self {
        let clean = |x: f64| if x.is_finite() { x.max(0.0) } else { 0.0 };
        SeparationDistribution {
            contact: clean(contact),
            components: components
                .into_iter()
                .map(|g| FoldedGaussian {
                    weight: clean(g.weight),
                    center: clean(g.center),
                    width: clean(g.width),
                })
                .collect(),
        }
    }

    /// P(u) of Persson's theory at reduced pressure `s = P0/E*` (module docs).
    ///
    /// The ζ-integral is done in `x = ln M3(ζ)`, `M3(ζ) = ∫_{q0}^{ζq0} q³C dq`, where
    /// `A/A0 = erf(y)`, `y = s/√(π M3)`, is smooth (`−dA/dx = y e^{−y²}/√π`) however sharply
    /// it drops in ζ at low pressure: Gauss–Legendre panels of `panel_width` in x, broken at
    /// the kinks of C(q), from `y = 6` (A/A0 = 1 − 2e-17) to ζ1. With the corrected area
    /// (docs/model.md §2) `y = s/√(π M3_eff)` and `−dA/dx = g y e^{−y²}/√π`,
    /// `g = d ln M3_eff/d ln M3`; at y = 6 the two areas are the same (full contact).
    pub fn persson(contact: &PerssonContact, s: f64, settings: EffectiveMediumSettings) -> Self {
        let sp = contact.spectrum();
        let (q0, q1) = (sp.q0(), sp.q1());
        let zeta1 = q1 / q0;
        let c = contact.area_fraction(zeta1, s);
        let x_hi = sp.total_m3().ln();
        let x_lo = (s * s / (36.0 * PI)).ln();
        if !(s > 0.0 && x_lo < x_hi) {
            return SeparationDistribution::new(c, Vec::new());
        }
        let mut breaks = vec![x_lo];
        breaks.extend(
            sp.interior_knots()
                .map(|k| sp.m3_to(k.exp()).ln())
                .filter(|&x| x > x_lo && x < x_hi),
        );
        breaks.push(x_hi);
        let (nodes, weights) = gauss_legendre(settings.order.max(1));
        let width = if settings.panel_width > 0.0 {
            settings.panel_width
        } else {
            0.5
        };
        let mut components = Vec::new();
        for (x, weight) in composite(&breaks, width, &nodes, &weights) {
            let Some(ln_q) = sp.invert_m3(x.exp()) else {
                continue;
            };
            // the corrected area: M3_eff = r·M3 and −dA/dx gains g = d ln M3_eff/d ln M3
            let (ratio, growth) = contact.area_scaling(x.exp(), s);
            let y = s / (PI * x.exp() * ratio).sqrt();
            let zeta = (ln_q - q0.ln()).exp().max(1.0);
            let sep = contact.separation(zeta, s);
            components.push(FoldedGaussian {
                weight: weight * y * (-y * y).exp() / PI.sqrt() * growth,
                center: sep.u1(),
                width: sp.rms_roughness_above(ln_q.exp()),
            });
        }
        SeparationDistribution::new(c, components)
    }

    /// The contact fraction `A(ζ1)/A0` (the weight of δ(u)).
    pub fn contact_fraction(&self) -> f64 {
        self.contact
    }

    /// The folded Gaussian components.
    pub fn components(&self) -> &[FoldedGaussian] {
        &self.components
    }

    /// `∫ P(u) du` over u ≥ 0 (1 in theory).
    pub fn total_probability(&self) -> f64 {
        self.contact + self.components.iter().map(|g| g.weight).sum::<f64>()
    }

    /// `P(U ≤ u)`, including the contact fraction for u ≥ 0.
    pub fn cdf(&self, u: f64) -> f64 {
        if u < 0.0 {
            return 0.0;
        }
        self.contact
            + self
                .components
                .iter()
                .map(|g| g.weight * g.cdf(u))
                .sum::<f64>()
    }

    /// The continuous part of P(u) \[1/m\] at u ≥ 0 (point-mass components are left out).
    pub fn density(&self, u: f64) -> f64 {
        if u < 0.0 {
            return 0.0;
        }
        let norm = 1.0 / (2.0 * PI).sqrt();
        self.components
            .iter()
            .filter(|g| g.width > 0.0)
            .map(|g| {
                let (a, b) = ((u - g.center) / g.width, (u + g.center) / g.width);
                g.weight * norm / g.width * ((-0.5 * a * a).exp() + (-0.5 * b * b).exp())
            })
            .sum()
    }

    /// The mean separation `∫ u P(u) du` \[m\].
    pub fn mean(&self) -> f64 {
        self.components.iter().map(|g| g.weight * g.mean()).sum()
    }

    /// `12 η σ_eff` \[m³\] of the 2-D Bruggeman medium with local conductance `u³/(12η)`
    /// (module docs), 0 for a gap no wider than `settings.molecular_size` m; exactly 0 at and
    /// above the threshold — `P(u ≤ molecular size) ≥ 1/2`, the contact fraction alone when the
    /// molecular size is 0 — or when no component has a positive gap.
    pub fn bruggeman_cubed_gap(&self, settings: EffectiveMediumSettings) -> f64 {
        self.bruggeman(settings, None)
    }

    /// [`Self::bruggeman_cubed_gap`] of a gas whose every gap u conducts
    /// `u³ f(λ/u, width/u)/(12η)` (channels `width` \[m\] wide), f the slit rarefaction factor ([`crate::gas::slit_rarefaction`]) at
    /// the gas's mean free path λ (docs/model.md §3.10): each separation carries its own
    /// Knudsen number, and a gap no wider than a molecule conducts nothing. Returns `12 η σ_eff` \[m³\] (0 when sealed).
    pub fn rarefied_bruggeman_cubed_gap(
        &self,
        settings: EffectiveMediumSettings,
        free_path: crate::gas::Rarefied,
        width: f64,
    ) -> f64 {
        self.bruggeman(settings, Some((free_path, width)))
    }

    fn bruggeman(
        &self,
        settings: EffectiveMediumSettings,
        free_path: Option<(crate::gas::Rarefied, f64)>,
    ) -> f64 {
        // the gaps no wider than a molecule count as contact (docs/model.md §8.1): as g → 0⁺
        // the residual tends to 2 P(u ≤ molecule) − 1, so the medium conducts only below ½
        let molecule = match free_path {
            Some((l, _)) => l.molecular_diameter,
            None => settings.molecular_size,
        };
        if self.contact >= 0.5 || (molecule > 0.0 && self.cdf(molecule) >= 0.5) {
            return 0.0;
        }
        // Wiener's upper bound: the arithmetic mean of the local conductance (where the
        // residual is ≥ 0); for a gas the continuum mean times the factor at the mean gap, and
        // the bracket is widened upwards until the residual is ≥ 0.
        let mut upper = self.mean_cubed();
        if !(upper > 0.0 && upper.is_finite()) {
            return 0.0;
        }
        let (nodes, weights) = gauss_legendre(settings.u_order.max(1));
        let gas = free_path.map(|(l, width)| {
            let u_max = self
                .components
                .iter()
                .map(|c| c.center.abs() + SIGMAS * c.width)
                .fold(0.0, f64::max);
            GasConductance::new(l, width, u_max)
        });
        if let Some(gas) = &gas {
            // Wiener's bound for the gas: the arithmetic mean of u³ f(λ/u) (0 below a molecule)
            upper = self.mean_local(settings.u_panels.max(1), &nodes, &weights, &|u| gas.at(u));
            if !(upper > 0.0 && upper.is_finite()) {
                return 0.0;
            }
        }
        let cache = std::cell::RefCell::new(NodeCache::default());
        let residual = |g: f64| {
            self.bruggeman_residual(
                g,
                &URule {
                    panels: settings.u_panels.max(1),
                    nodes: &nodes,
                    weights: &weights,
                },
                gas.as_ref(),
                settings.molecular_size,
                &cache,
            )
        };
        // the residuals at the bracket's ends as the search below finds them (each solve costs
        // ~10 residuals of a few hundred components; none is evaluated twice)
        let mut hi = upper.ln();
        let mut f_hi = None;
        if let Some((l, width)) = free_path {
            // Wiener's bound is loose by many decades when far-out components of P(u) carry a
            // tiny weight at huge u: start at the mean gap's conductance instead and climb by
            // decades to a positive residual (at the bound it is ≥ 0)
            let mean = self.mean();
            let start = mean * mean * mean * l.factor(mean, width);
            if start > 0.0 && start < upper {
                hi = start.ln();
                while hi < upper.ln() {
                    let r = residual(hi.exp());
                    if r.is_nan() || r >= 0.0 {
                        f_hi = Some(r);
                        break;
                    }
                    hi = (hi + 10.0_f64.ln()).min(upper.ln());
                }
            }
        } else {
            let r = residual(hi.exp());
            if r < 0.0 {
                // rounding only: the bound holds exactly
                return upper;
            }
            f_hi = Some(r);
        }
        let mut lo = hi - 10.0_f64.ln();
        let mut f_lo;
        loop {
            let g = lo.exp();
            if g <= 0.0 || !g.is_finite() {
                return 0.0;
            }
            f_lo = residual(g);
            if f_lo < 0.0 {
                break;
            }
            (hi, f_hi) = (lo, Some(f_lo));
            lo -= 10.0_f64.ln();
        }
        // Illinois (modified regula falsi) in ln g: the residual is smooth and monotone, so it
        // converges superlinearly — ≈ 10 evaluations instead of bisection's 40.
        let mut f_hi = f_hi.unwrap_or_else(|| residual(hi.exp()));
        let mut side = 0i8;
        let mut last = f64::NAN;
        for _ in 0..200 {
            let mut x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
            if !(x > lo && x < hi) {
                x = 0.5 * (lo + hi);
            }
            // successive estimates agree to 1e-12 in ln g (relative in g), or the bracket is
            // that narrow
            if (x - last).abs() <= 1e-12 || hi - lo <= 1e-12 {
                return x.exp();
            }
            last = x;
            let fx = residual(x.exp());
            if fx == 0.0 {
                return x.exp();
            }
            if fx < 0.0 {
                (lo, f_lo) = (x, fx);
                if side == -1 {
                    f_hi *= 0.5;
                }
                side = -1;
            } else {
                (hi, f_hi) = (x, fx);
                if side == 1 {
                    f_lo *= 0.5;
                }
                side = 1;
            }
        }
        (0.5 * (lo + hi)).exp()
    }

    /// `∫ u³ P(u) du` \[m³\], in closed form per component
    /// (`E|X|³` of a folded normal: `(μ³ + 3μσ²) erf(μ/σ√2) + √(2/π) σ (μ² + 2σ²) e^{−μ²/2σ²}`).
    pub fn mean_cubed(&self) -> f64 {
        self.components
            .iter()
            .map(|g| {
                let (m, s) = (g.center, g.width);
                let m3 = if s <= 0.0 {
                    m * m * m
                } else {
                    (m * m * m + 3.0 * m * s * s) * erf(m / (s * SQRT_2))
                        + (2.0 / PI).sqrt()
                            * s
                            * (m * m + 2.0 * s * s)
                            * (-0.5 * (m / s).powi(2)).exp()
                };
                g.weight * m3
            })
            .sum()
    }

    /// `∫ P(u) c(|u|) du` over the open gaps (the contact carries c = 0), by the residual's
    /// quadrature (cut at u = 0): the arithmetic mean of a local conductance `c` (Wiener's
    /// upper bound of the medium's).
    fn mean_local(
        &self,
        panels: usize,
        nodes: &[f64],
        weights: &[f64],
        c: &dyn Fn(f64) -> f64,
    ) -> f64 {
        self.expectation(0.0, &[0.0], panels, nodes, weights, &|u| c(u.abs()))
    }

    /// `start + Σ_i w_i ∫ N(u; μ_i, σ_i) φ(u) du` over the components (a point mass at its
    /// centre when σ_i = 0), each over μ_i ± 8σ_i by `panels` Gauss–Legendre panels per
    /// sub-interval, cut at those of `breaks` that fall inside: φ(|u|) of the folded Gaussian
    /// is φ of the signed u here, `∫_0^∞ [N(u;μ,σ) + N(u;−μ,σ)] φ(u) du = ∫ N(u;μ,σ) φ(|u|) du`.
    fn expectation(
        &self,
        start: f64,
        breaks: &[f64],
        panels: usize,
        nodes: &[f64],
        weights: &[f64],
        phi: &dyn Fn(f64) -> f64,
    ) -> f64 {
        let norm = 1.0 / (2.0 * PI).sqrt();
        let mut total = start;
        let mut cuts: Vec<f64> = Vec::with_capacity(breaks.len() + 2);
        for comp in &self.components {
            if comp.weight == 0.0 {
                continue;
            }
            if comp.width <= 0.0 {
                total += comp.weight * phi(comp.center);
                continue;
            }
            comp.cuts(breaks, &mut cuts);
            let inv = 1.0 / comp.width;
            let rule = URule {
                panels,
                nodes,
                weights,
            };
            let mut sum = 0.0;
            comp.for_each_node(&cuts, &rule, |u, weight| sum += weight * phi(u));
            total += comp.weight * norm * inv * sum;
        }
        total
    }

    /// `∫ P(u) (g − c(u))/(g + c(u)) du` with the local `c(u) = |u|³` (0 for |u| no wider than
    /// `molecule` \[m\]), or `|u|³ f(λ/|u|)` for a gas with mean free path `free_path` λ (0 below
    /// its own molecular diameter); monotonically increasing in g > 0.
    fn bruggeman_residual(
        &self,
        g: f64,
        rule: &URule<'_>,
        gas: Option<&GasConductance>,
        molecule: f64,
        cache: &std::cell::RefCell<NodeCache>,
    ) -> f64 {
        let local = |u: f64| {
            let a = u.abs();
            match gas {
                Some(gas) => gas.at(a),
                None if !crate::fluid::passes_molecule(a, molecule) => 0.0,
                None => a * a * a,
            }
        };
        // the gap where the kernel turns over, c(u*) = g: u* = g^{1/3} for a liquid; for a
        // gas by bisection in ln u (c is increasing in u)
        let u_eff = match gas {
            None => g.cbrt(),
            Some(_) => {
                let (mut lo, mut hi) = (g.cbrt().ln() - 60.0, g.cbrt().ln());
                for _ in 0..60 {
                    let m = 0.5 * (lo + hi);
                    if local(m.exp()) < g {
                        lo = m;
                    } else {
                        hi = m;
                    }
                }
                (0.5 * (lo + hi)).exp()
            }
        };
        // the kernel turns over at u*; the local conductance jumps at the molecular size
        let mut breaks = vec![0.0];
        for x in [0.5, 1.0, 2.0, 4.0] {
            breaks.extend([x * u_eff, -x * u_eff]);
        }
        match gas {
            Some(gas) => breaks.extend([gas.diameter, -gas.diameter]),
            None if molecule > 0.0 => breaks.extend([molecule, -molecule]),
            None => {}
        }
        self.kernel_expectation(&breaks, rule, &local, g, &mut cache.borrow_mut())
    }

    /// `c + Σ_i w_i ∫ N(u; μ_i, σ_i) (g − c(u))/(g + c(u)) du` by [`Self::expectation`]'s
    /// rule, each component's node weights `½h·w_k·e^{−z²/2}` and conductances `c(u_k)` kept
    /// in `cache` while its cut points stay: only the components a moving break of the kernel
    /// cuts are evaluated again. The same products in the same order, so the same bits as
    /// [`Self::expectation`] with the kernel (a test).
    fn kernel_expectation(
        &self,
        breaks: &[f64],
        rule: &URule<'_>,
        local: &dyn Fn(f64) -> f64,
        g: f64,
        cache: &mut NodeCache,
    ) -> f64 {
        let norm = 1.0 / (2.0 * PI).sqrt();
        let kernel = |c: f64| (g - c) / (g + c);
        let mut total = self.contact;
        cache
            .components
            .resize_with(self.components.len(), CachedNodes::default);
        let mut cuts = std::mem::take(&mut cache.scratch);
        for (comp, kept) in self.components.iter().zip(&mut cache.components) {
            if comp.weight == 0.0 {
                continue;
            }
            if comp.width <= 0.0 {
                total += comp.weight * kernel(local(comp.center));
                continue;
            }
            comp.cuts(breaks, &mut cuts);
            let inv = 1.0 / comp.width;
            if kept.cuts != cuts {
                kept.nodes.clear();
                comp.for_each_node(&cuts, rule, |u, weight| kept.nodes.push((weight, local(u))));
                std::mem::swap(&mut kept.cuts, &mut cuts);
            }
            let sum: f64 = kept
                .nodes
                .iter()
                .fold(0.0, |sum, &(weight, c)| sum + weight * kernel(c));
            total += comp.weight * norm * inv * sum;
        }
        cache.scratch = cuts;
        total
    }
}

/// The u-rule of [`SeparationDistribution::expectation`]: `panels` Gauss–Legendre panels
/// (`nodes`, `weights` on \[−1, 1\]) in each sub-interval of a component's range.
struct URule<'a> {
    panels: usize,
    nodes: &'a [f64],
    weights: &'a [f64],
}

/// The nodes of one Bruggeman solve's residuals, per component ([`SeparationDistribution::kernel_expectation`]).
#[derive(Default)]
struct NodeCache {
    components: Vec<CachedNodes>,
    scratch: Vec<f64>,
}

/// One component's cut points and, at each node, `(½h·w_k·e^{−z²/2}, c(u_k))`.
#[derive(Default)]
struct CachedNodes {
    cuts: Vec<f64>,
    nodes: Vec<(f64, f64)>,
}

/// The local conductance `c(u) = u³ f(λ/u, w/u)` \[m³\] of a gas's gap u (docs/model.md §3.10;
/// 0 at and below the molecular diameter), tabulated once per Bruggeman solve at
/// [`GAS_OCTAVE_POINTS`] points per octave of u from the molecular diameter to the widest gap
/// of P(u) and interpolated by 4-point Lagrange cubics within each octave: the solve evaluates
/// it ~10⁶ times and the slit factor's logarithms and powers cost ~15× a cube. The octave and
/// the position in it are read off the float's exponent and mantissa, so a look-up costs no
/// logarithm and no exponential (interpolation error ≤ 1e-7 of c, a test).
struct GasConductance {
    gas: crate::gas::Rarefied,
    width: f64,
    /// The molecular diameter d \[m\].
    diameter: f64,
    table: Option<OctaveTable>,
}

/// Points per octave of [`GasConductance`]'s table.
const GAS_OCTAVE_POINTS: usize = 64;

/// `c(u)` at `u = 2^e (1 + j/N)`, j = −1 … N + 1 (N = [`GAS_OCTAVE_POINTS`]), for the octaves
/// e = `first` … `first + octaves − 1`, octave by octave.
struct OctaveTable {
    first: i64,
    octaves: usize,
    values: Vec<f64>,
}

impl OctaveTable {
    /// The octave of a positive normal `u` and its mantissa in \[1, 2).
    fn split(u: f64) -> (i64, f64) {
        let bits = u.to_bits();
        let exponent = ((bits >> 52) & 0x7ff) as i64 - 1023;
        let mantissa = f64::from_bits((bits & ((1u64 << 52) - 1)) | (1023u64 << 52));
        (exponent, mantissa)
    }

    fn new(lo: f64, hi: f64, c: impl Fn(f64) -> f64) -> Option<Self> {
        if !(lo > f64::MIN_POSITIVE && hi > lo && hi.is_finite()) {
            return None;
        }
        let (first, _) = Self::split(lo);
        let (last, _) = Self::split(hi);
        let octaves = (last - first + 1) as usize;
        let n = GAS_OCTAVE_POINTS as f64;
        let mut values = Vec::with_capacity(octaves * (GAS_OCTAVE_POINTS + 3));
        for e in first..=last {
            let base = 2f64.powi(e as i32);
            values
                .extend((0..GAS_OCTAVE_POINTS + 3).map(|j| c(base * (1.0 + (j as f64 - 1.0) / n))));
        }
        Some(OctaveTable {
            first,
            octaves,
            values,
        })
    }

    /// The interpolated `c(u)`, `None` outside the table.
    fn at(&self, u: f64) -> Option<f64> {
        let (exponent, mantissa) = Self::split(u);
        let octave = usize::try_from(exponent - self.first)
            .ok()
            .filter(|&o| o < self.octaves)?;
        let x = (mantissa - 1.0) * GAS_OCTAVE_POINTS as f64;
        let j = (x as usize).min(GAS_OCTAVE_POINTS - 1);
        let t = x - j as f64;
        let y = &self.values[octave * (GAS_OCTAVE_POINTS + 3) + j..][..4];
        // Lagrange through the nodes −1, 0, 1, 2 at t ∈ [0, 1]
        Some(
            -t * (t - 1.0) * (t - 2.0) / 6.0 * y[0]
                + (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0 * y[1]
                - (t + 1.0) * t * (t - 2.0) / 2.0 * y[2]
                + (t + 1.0) * t * (t - 1.0) / 6.0 * y[3],
        )
    }
}

impl GasConductance {
    fn new(gas: crate::gas::Rarefied, width: f64, u_max: f64) -> Self {
        let d = gas.molecular_diameter;
        // the smooth law on both sides of d (the cut is applied at look-up)
        let table = OctaveTable::new(d, u_max, |u| {
            u * u * u * crate::gas::slit_rarefaction(gas.free_path / u, width / u)
        });
        GasConductance {
            gas,
            width,
            diameter: d,
            table,
        }
    }

    /// `u³ f(λ/u, w/u)` at `u` ≥ 0.
    fn at(&self, u: f64) -> f64 {
        if !crate::fluid::passes_molecule(u, self.diameter) {
            return 0.0;
        }
        match self.table.as_ref().and_then(|t| t.at(u)) {
            Some(c) => c,
            None => u * u * u * self.gas.factor(u, self.width),
        }
    }
}

/// The effective-medium result at one pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EffectiveMedium {
    /// Contact fraction `A(ζ1)/A0` (sealed at ≥ 1/2).
    pub contact_fraction: f64,
    /// `12 η σ_eff` \[m³\]; 0 when sealed.
    pub cubed_gap: f64,
}

impl EffectiveMedium {
    /// Bruggeman over Persson's P(u) at reduced pressure `s = P0/E*`.
    pub fn persson(contact: &PerssonContact, s: f64, settings: EffectiveMediumSettings) -> Self {
        Self::solve(contact, s, settings, None)
    }

    /// [`Self::persson`] for a gas with mean free path `free_path` λ \[m\] through channels
    /// `width` \[m\] wide: every separation conducts with its own Knudsen number λ/u
    /// ([`SeparationDistribution::rarefied_bruggeman_cubed_gap`]).
    pub fn persson_rarefied(
        contact: &PerssonContact,
        s: f64,
        settings: EffectiveMediumSettings,
        free_path: crate::gas::Rarefied,
        width: f64,
    ) -> Self {
        Self::solve(contact, s, settings, Some((free_path, width)))
    }

    /// Sealed at and above the threshold ½ without building P(u); else its Bruggeman medium.
    fn solve(
        contact: &PerssonContact,
        s: f64,
        settings: EffectiveMediumSettings,
        gas: Option<(crate::gas::Rarefied, f64)>,
    ) -> Self {
        let zeta1 = contact.spectrum().q1() / contact.spectrum().q0();
        let c = contact.area_fraction(zeta1, s);
        if c >= 0.5 {
            return EffectiveMedium {
                contact_fraction: c,
                cubed_gap: 0.0,
            };
        }
        let p = SeparationDistribution::persson(contact, s, settings);
        EffectiveMedium {
            contact_fraction: p.contact_fraction(),
            cubed_gap: p.bruggeman(settings, gas),
        }
    }

    /// Whether the interface is sealed (no percolating conductance).
    pub fn sealed(&self) -> bool {
        self.cubed_gap <= 0.0
    }

    /// The effective gap `u_eff = (12 η σ_eff)^{1/3}` \[m\].
    pub fn effective_gap(&self) -> f64 {
        self.cubed_gap.cbrt()
    }

    /// Effective conductance per unit width `σ_eff` \[m³/(Pa·s)\] for viscosity η \[Pa·s\].
    pub fn conductance(&self, viscosity: f64) -> f64 {
        self.cubed_gap / (12.0 * viscosity)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The octave table against the slit law itself, air at 1 bar (λ ≈ 68 nm, d = 0.366 nm)
    /// and at 100 bar, across 4 decades of gap and through the transition and free-molecular
    /// regimes: within 1e-7 everywhere, 0 at and below a molecule.
    #[test]
    fn the_gas_conductance_table_is_the_slit_law_within_1e_7() {
        for free_path in [68e-9, 0.68e-9] {
            let gas = crate::gas::Rarefied {
                free_path,
                molecular_diameter: 3.66e-10,
            };
            let width = 2e-6;
            let c = GasConductance::new(gas, width, 4e-6);
            assert!(c.table.is_some());
            assert_eq!(c.at(3.66e-10), 0.0);
            assert_eq!(c.at(1e-10), 0.0);
            let mut worst = 0.0_f64;
            for i in 0..4000 {
                let u = 3.7e-10 * 10f64.powf(4.0 * i as f64 / 4000.0);
                let want = u * u * u * gas.factor(u, width);
                worst = worst.max((c.at(u) / want - 1.0).abs());
            }
            assert!(
                worst < 1e-7,
                "λ = {free_path}: worst relative error {worst:e}"
            );
        }
    }

    /// The cached residual is the plain one to the bit, at a first g and after the cache has
    /// been filled at others (a liquid's u³ with a molecular cut, three components of which two
    /// are cut by the kernel's moving breaks and one is not).
    #[test]
    fn the_cached_kernel_expectation_is_the_plain_one_bit_for_bit() {
        let p = SeparationDistribution::new(
            0.2,
            vec![
                FoldedGaussian {
                    weight: 0.3,
                    center: 1e-6,
                    width: 0.5e-6,
                },
                FoldedGaussian {
                    weight: 0.4,
                    center: 2e-9,
                    width: 0.5e-9,
                },
                FoldedGaussian {
                    weight: 0.1,
                    center: 3e-7,
                    width: 0.0,
                },
            ],
        );
        let (nodes, weights) = gauss_legendre(10);
        let molecule = 0.3e-9;
        let local = |u: f64| {
            let a = u.abs();
            if crate::fluid::passes_molecule(a, molecule) {
                a * a * a
            } else {
                0.0
            }
        };
        let cache = std::cell::RefCell::new(NodeCache::default());
        for g in [1e-20, 1e-19, 3e-20, 1e-19, 1e-18] {
            let u = f64::cbrt(g);
            let mut breaks = vec![0.0, molecule, -molecule];
            for x in [0.5, 1.0, 2.0, 4.0] {
                breaks.extend([x * u, -x * u]);
            }
            let plain = p.expectation(p.contact, &breaks, 4, &nodes, &weights, &|u| {
                let c = local(u);
                (g - c) / (g + c)
            });
            let rule = URule {
                panels: 4,
                nodes: &nodes,
                weights: &weights,
            };
            let cached = p.bruggeman_residual(g, &rule, None, molecule, &cache);
            assert_eq!(plain.to_bits(), cached.to_bits(), "g = {g:e}");
        }
    }
}
