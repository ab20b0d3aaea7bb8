//! Persson contact mechanics and the critical junction of a rough interface (PY08 §2).
//!
//! Everything here depends on the nominal pressure and the rubber only through the reduced
//! pressure `s = P0/E*`, `E* = E/(1−ν²)` (docs/model.md §2, "Scaling"). With the moments of the
//! spectrum `M3(ζ) = ∫_{q0}^{ζq0} q³C dq`:
//! * `G(ζ) = (π/4) E*² M3(ζ)` and `A(ζ)/A0 = erf(P0/(2√G)) = erf(s/√(π M3))`;
//! * `p(ζ) = P0 A0/A(ζ)`;
//! * `ū(ζ) = √π ∫_{ζq0}^{q1} q² C(q) w(q,ζ) F(w p(ζ)/E*) dq`, `w = (π ∫_{ζq0}^q q′³C dq′)^{−1/2}`;
//! * `u1(ζ) = ū(ζ) + ū′(ζ) A(ζ)/A′(ζ)`;
//! * ζc solves `A(ζc)/A0 = a_c` (percolation threshold, default 0.4): `M3(ζc) = s²/(π erfinv²(a_c))`,
//!   inverted in closed form. If that exceeds `M3(q1/q0)` no channel percolates: sealed.
//!
//! ū′ is computed analytically (differentiating under the integral: the boundary term vanishes
//! because F(∞) = 0), with the same quadrature nodes as ū, so u1 carries no finite-difference
//! error.

pub mod area;
pub mod effective_medium;
pub mod separation;
pub mod table;

pub use area::{AreaModel, ScaleMarch};
pub use effective_medium::{EffectiveMedium, EffectiveMediumSettings, SeparationDistribution};
pub use table::{ContactTable, EffectiveMediumTable, TableSettings};

use crate::math::quadrature::{composite, gauss_legendre};
use crate::math::special::{erf, erf_inv};
use crate::surface::Spectrum;
use std::f64::consts::PI;

/// Linear-elastic rubber against a rigid countersurface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elastic {
    /// Young's modulus E \[Pa\].
    pub youngs_modulus: f64,
    /// Poisson ratio ν ∈ \[0, 0.5\].
    pub poisson_ratio: f64,
}

impl Elastic {
    /// Plane-strain modulus of the rubber on a rigid substrate, `E* = E/(1−ν²)` \[Pa\] (PY08 §2).
    pub fn effective_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }
}

/// Quadrature of the ū integral: composite Gauss–Legendre in `v = ln t`, `q = ζq0 (1 + t)`,
/// with panels of at most `panel_width` in v, broken at the kinks of C(q).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadratureSettings {
    /// Largest panel width in `ln t`.
    pub panel_width: f64,
    /// Gauss–Legendre points per panel.
    pub order: usize,
}

impl Default for QuadratureSettings {
    fn default() -> Self {
        QuadratureSettings {
            panel_width: 1.0,
            order: 8,
        }
    }
}

/// Lowest `ln t` of the separation quadrature: `e^v` underflows to 0 below it.
const LN_T_FLOOR: f64 = -745.2;

impl QuadratureSettings {
    /// The same rule with `factor`× as many nodes (narrower panels): for convergence checks.
    pub fn refined(self, factor: f64) -> Self {
        QuadratureSettings {
            panel_width: self.panel_width / factor,
            order: self.order,
        }
    }
}

/// Model settings of the critical-junction theory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSettings {
    /// Relative contact area `A/A0 = 1 − p_c` at which the non-contact area percolates
    /// (PY08 §2: ≈ 0.4; Dapp et al., PRL 108 (2012) 244301: ≈ 0.42).
    pub percolation_threshold: f64,
    /// γ of the ū kernel (PY08 §2, ≈ 0.4).
    pub gamma: f64,
    /// The relation of the contact area A(ζ)/A0 ([`AreaModel`], docs/model.md §2).
    pub area: AreaModel,
    pub quadrature: QuadratureSettings,
}

impl Default for ContactSettings {
    fn default() -> Self {
        ContactSettings {
            percolation_threshold: 0.4,
            gamma: 0.4,
            area: AreaModel::Persson,
            quadrature: QuadratureSettings::default(),
        }
    }
}

/// The critical constriction of the first percolating non-contact channel (PY08 §2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalJunction {
    /// Critical magnification ζc (dimensionless, ≥ 1).
    pub zeta_c: f64,
    /// Lateral size `λc = 2π/(ζc q0)` \[m\] (the convention L = 2π/q0).
    pub lambda_c: f64,
    /// Height of the critical constriction `u_c = u1(ζc)` \[m\].
    pub u_c: f64,
    /// Mean separation in the apparent contact at ζc, `ū(ζc)` \[m\].
    pub ubar_c: f64,
    /// rms roughness left at ζc, `h_rms(ζc)` \[m\] (PY08 eq. 4).
    pub hrms_c: f64,
}

/// Whether a non-contact channel percolates before the roughness runs out at q1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Junction {
    Leaking(CriticalJunction),
    /// `A(q1/q0)/A0` is still above the threshold, so no non-contact channel percolates; or
    /// (within ≈3 % of the sealing pressure) the constriction height underflows double
    /// precision. No leak.
    Sealed,
}

impl Junction {
    pub fn leaking(&self) -> Option<&CriticalJunction> {
        match self {
            Junction::Leaking(j) => Some(j),
            Junction::Sealed => None,
        }
    }
}

/// ū and its derivative with respect to ln ζ at one magnification.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Separation {
    /// Mean separation ū(ζ) \[m\].
    pub mean: f64,
    /// dū/d ln ζ \[m\] (≤ 0).
    pub mean_dlnzeta: f64,
    /// A(ζ)/A0.
    pub area: f64,
    /// dA/d ln ζ / A0 (≤ 0).
    pub area_dlnzeta: f64,
}

impl Separation {
    /// `u1 = ū + ū′ A/A′` (PY08 §2, after Yang & Persson 2008).
    pub fn u1(&self) -> f64 {
        if self.area_dlnzeta == 0.0 {
            return self.mean;
        }
        self.mean + self.mean_dlnzeta * self.area / self.area_dlnzeta
    }
}

/// Where the integrand is cut off: beyond `x = w p/E* = X_CUT` the kernel is below e^{−64}.
const X_CUT: f64 = 8.0;

/// The interface at full magnification (PY08 §2): what a contact study reports at one
/// nominal pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FullContact {
    /// Relative contact area A(ζ1)/A0 at full magnification ζ1 = q1/q0 (1).
    pub area_fraction: f64,
    /// Mean interfacial separation ū of the whole interface (m): ū(ζ = 1) in Persson's theory,
    /// the mean of the gap field in the numerical level.
    pub mean_gap: f64,
}

/// Persson's contact theory on one spectrum: the exact (quadrature) path.
#[derive(Debug, Clone, PartialEq)]
pub struct PerssonContact {
    spectrum: Spectrum,
    settings: ContactSettings,
    /// erfinv(a_c)², fixed by the threshold.
    erfinv2: f64,
    /// The corrected area's scale march (`None`: Persson's area).
    march: Option<&'static ScaleMarch>,
    /// With a march: `x_c = Φ⁻¹(1/(π erfinv²(a_c)))`, so that `M3(ζc) = s² x_c`.
    critical_x: f64,
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl PerssonContact {
    /// Binds a spectrum to model settings. `percolation_threshold` must lie in (0, 1).
    pub fn new(spectrum: Spectrum, settings: ContactSettings) -> Self {
        let (nodes, weights) = gauss_legendre(settings.quadrature.order.max(1));
        let e = erf_inv(settings.percolation_threshold);
        let march = settings.area.march();
        let critical_x = march.map_or(0.0, |m| m.inverse(1.0 / (PI * e * e)));
        PerssonContact {
            spectrum,
            settings,
            erfinv2: e * e,
            march,
            critical_x,
            nodes,
            weights,
        }
    }

    pub fn spectrum(&self) -> &Spectrum {
        &self.spectrum
    }

    pub fn settings(&self) -> &ContactSettings {
        &self.settings
    }

    /// Relative apparent contact area `A(ζ)/A0 = erf(s/√(π M3(ζ)))` at reduced pressure s;
    /// with the corrected area `M3_eff = s² Φ(M3/s²)` in place of `M3` ([`area`]).
    pub fn area_fraction(&self, zeta: f64, s: f64) -> f64 {
        let m3 = self.spectrum.m3_to(zeta * self.spectrum.q0());
        if m3 <= 0.0 {
            return 1.0;
        }
        let (ratio, _) = self.area_scaling(m3, s);
        erf(s / (PI * m3 * ratio).sqrt())
    }

    /// `(M3_eff/M3, d ln M3_eff/d ln M3)` at the moment `m3` and reduced pressure `s`: `(1, 1)`
    /// for Persson's area (multiplying by 1 changes no bit), the scale march's otherwise.
    pub(crate) fn area_scaling(&self, m3: f64, s: f64) -> (f64, f64) {
        match self.march {
            None => (1.0, 1.0),
            Some(m) => m.scaled(m3 / (s * s)),
        }
    }

    /// The reduced pressure at which the area at full magnification is `A(q1/q0)/A0 = a`,
    /// a ∈ (0, 1): `erfinv(a) √(π M3(q1))` for Persson's area, `√(M3(q1)/Φ⁻¹(1/(π erfinv²a)))`
    /// for the corrected one.
    pub fn reduced_pressure_at_area(&self, a: f64) -> f64 {
        let e = erf_inv(a);
        match self.march {
            None => e * (PI * self.spectrum.total_m3()).sqrt(),
            Some(m) => (self.spectrum.total_m3() / m.inverse(1.0 / (PI * e * e))).sqrt(),
        }
    }

    /// The interface at full magnification at reduced pressure `s = P0/E*`:
    /// `A(q1/q0)/A0 = erf(s/√(π M3(q1)))` (or the corrected area, [`area`]) and the mean separation ū(ζ = 1) (PY08 §2; the
    /// quadrature of [`Self::separation`]). `sealsim leak`'s `area_fraction` and `mean_gap_m` at
    /// every analytic level, and the Python package's `sealsim.contact`.
    pub fn full_contact(&self, s: f64) -> FullContact {
        let zeta1 = self.spectrum.q1() / self.spectrum.q0();
        FullContact {
            area_fraction: self.area_fraction(zeta1, s),
            mean_gap: self.separation(1.0, s).mean,
        }
    }

    /// The reduced pressure `P0/E*` above which no channel percolates below q1:
    /// `s_seal = erfinv(a_c) √(π M3(q1))`; with the corrected area `√(M3(q1)/x_c)`,
    /// `x_c = Φ⁻¹(1/(π erfinv²(a_c)))`.
    pub fn sealing_reduced_pressure(&self) -> f64 {
        match self.march {
            None => (self.erfinv2 * PI * self.spectrum.total_m3()).sqrt(),
            Some(_) => (self.spectrum.total_m3() / self.critical_x).sqrt(),
        }
    }

    /// `M3(ζc) = s²/(π erfinv²(a_c))`: the moment at the critical magnification (`s² x_c` with
    /// the corrected area).
    fn critical_m3(&self, s: f64) -> f64 {
        match self.march {
            None => s * s / (PI * self.erfinv2),
            Some(_) => s * s * self.critical_x,
        }
    }

    /// Critical magnification ζc at reduced pressure s, or `None` when sealed.
    pub fn critical_magnification(&self, s: f64) -> Option<f64> {
        self.spectrum
            .invert_m3(self.critical_m3(s))
            .map(|ln_q| (ln_q - self.spectrum.ln_q0()).exp())
    }

    /// ū(ζ) and its ln ζ derivatives at reduced pressure s (PY08 §2).
    pub fn separation(&self, zeta: f64, s: f64) -> Separation {
        let ln_a = self.spectrum.ln_q0() + zeta.ln().max(0.0);
        let m3 = self.spectrum.m3_to(ln_a.exp());
        self.separation_at(ln_a, m3, s)
    }

    /// ū and derivatives at `a = ζq0` given `M3(ζ)` directly (so that ζ → 1 loses nothing to
    /// rounding of ζq0).
    fn separation_at(&self, ln_a: f64, m3: f64, s: f64) -> Separation {
        let sp = &self.spectrum;
        let gamma = self.settings.gamma;
        // dM3/d ln ζ = a⁴ C(a)
        let dm3 = (4.0 * ln_a + sp.ln_c(ln_a)).exp();
        // the area (and A′) from the corrected moment M3_eff = r·M3, d ln M3_eff = g d ln M3;
        // the kernel below keeps the spectrum's own M3 (docs/model.md §2)
        let (ratio, growth) = self.area_scaling(m3, s);
        let y = s / (PI * m3 * ratio).sqrt();
        let area = erf(y);
        let area_d = if m3 > 0.0 {
            -(y / PI.sqrt()) * (-y * y).exp() * dm3 / m3 * growth
        } else {
            0.0
        };
        let pr = s / area; // p(ζ)/E*
        let pr_d = -s * area_d / (area * area);

        let ln_t_max = (sp.ln_q1() - ln_a).exp_m1().ln();
        if !(ln_t_max.is_finite()) {
            return Separation {
                mean: 0.0,
                mean_dlnzeta: 0.0,
                area,
                area_dlnzeta: area_d,
            };
        }
        // Lower cut: w(q) pr = X_CUT ⇔ π M3(a, q) = (pr/X_CUT)², to leading order in t.
        let m_cut = (pr / X_CUT).powi(2) / PI;
        let t_lin = m_cut / dm3;
        let ln_t_min = if t_lin < 1e-3 {
            t_lin.ln()
        } else {
            match sp.invert_m3(m3 + m_cut) {
                Some(lq) => (lq - ln_a).exp_m1().ln(),
                None => ln_t_max,
            }
        }
        // below ln t = −745, t = e^v is 0 in f64 and the integrand (∝ t) contributes nothing;
        // the floor keeps the panel count finite when t_lin underflows (an extreme roughness
        // made ln t_min = −∞ and the quadrature never ended)
        .max(LN_T_FLOOR);
        if ln_t_min >= ln_t_max {
            return Separation {
                mean: 0.0,
                mean_dlnzeta: 0.0,
                area,
                area_dlnzeta: area_d,
            };
        }

        // Panel breakpoints: ends plus the spectrum's kinks above a.
        let mut breaks = vec![ln_t_min];
        for k in sp.interior_knots() {
            if k > ln_a {
                let v = (k - ln_a).exp_m1().ln();
                if v > ln_t_min && v < ln_t_max {
                    breaks.push(v);
                }
            }
        }
        breaks.push(ln_t_max);

        let mut mean = 0.0;
        let mut mean_d = 0.0;
        let width = self.settings.quadrature.panel_width;
        for (v, weight) in composite(&breaks, width, &self.nodes, &self.weights) {
            let t = v.exp();
            let big_l = t.ln_1p();
            let ln_q = ln_a + big_l;
            // q² C(q) · dq/dv, dq/dv = a t
            let jac = (2.0 * ln_q + sp.ln_c(ln_q) + ln_a).exp() * t;
            let m = sp.moment_span(3.0, ln_a, big_l);
            let w = 1.0 / (PI * m).sqrt();
            let x = w * pr;
            let f = separation::f(x, gamma);
            // F′(x)·x = −g e^{−x²}
            let ex = (-x * x).exp();
            let erfx = erf(x);
            let g = gamma + 3.0 * (1.0 - gamma) * erfx * erfx;
            let xfp = -g * ex;
            let dw = 0.5 * PI * w * w * w * dm3;
            // d[w F(w p/E*)]/d ln ζ = w′ (F + x F′) + w² (p/E*)′ F′, and w² F′ = w (x F′)/pr
            let d = dw * (f + xfp) + w * pr_d * xfp / pr;
            let scale = weight * jac;
            mean += scale * w * f;
            mean_d += scale * d;
        }
        let sqrt_pi = PI.sqrt();
        Separation {
            mean: sqrt_pi * mean,
            mean_dlnzeta: sqrt_pi * mean_d,
            area,
            area_dlnzeta: area_d,
        }
    }

    /// The critical junction at reduced pressure `s = P0/E*` by quadrature (the exact path).
    pub fn critical_junction(&self, s: f64) -> Junction {
        self.junction_at_m3(s, self.critical_m3(s))
    }

    /// The junction at reduced pressure `s` whose critical magnification has `M3(ζc) = m3`.
    fn junction_at_m3(&self, s: f64, m3: f64) -> Junction {
        let Some(ln_a) = self.spectrum.invert_m3(m3) else {
            return Junction::Sealed;
        };
        let sep = self.separation_at(ln_a, m3, s);
        let (u_c, ubar_c) = (sep.u1(), sep.mean);
        // So close to the sealing pressure that the gap integrand is below e^{-64} everywhere:
        // the channel exists in principle but has no height in double precision.
        if !(ubar_c > 0.0 && u_c > ubar_c) {
            return Junction::Sealed;
        }
        Junction::Leaking(self.junction_from(ln_a, u_c, ubar_c))
    }

    /// The rule-of-thumb junction (docs/model.md §4, PY08 §3 (Fig. 12) notes that u1(ζc) and h_rms(ζc) are
    /// close): ζc and λc as in [`Self::critical_junction`], and `u_c ≈ h_rms(ζc)` (PY08 eq. 4),
    /// all closed forms — no separation quadrature. This level does not compute ū(ζc) either:
    /// `ubar_c` carries the same h_rms(ζc).
    pub fn rule_of_thumb_junction(&self, s: f64) -> Junction {
        let Some(ln_a) = self.critical_ln_q(s) else {
            return Junction::Sealed;
        };
        let h = self.spectrum.rms_roughness_above(ln_a.exp());
        if h.is_nan() || h <= 0.0 {
            return Junction::Sealed;
        }
        Junction::Leaking(self.junction_from(ln_a, h, h))
    }

    /// The critical junction at reduced pressure `s` for an arbitrary percolation threshold
    /// `threshold` ∈ (0, 1) instead of the settings' a_c (used by clogging with re-routing,
    /// docs/model.md §7: blocked channels count as contact, so the flow percolates at the smaller
    /// threshold `a_eff`). Same quadrature as [`Self::critical_junction`], with
    /// `M3(ζc) = s²/(π erfinv²(threshold))`; erfinv² is computed per call. Sealed for a
    /// threshold outside (0, 1).
    pub fn critical_junction_at_threshold(&self, s: f64, threshold: f64) -> Junction {
        if !(threshold > 0.0 && threshold < 1.0) {
            return Junction::Sealed;
        }
        let e = erf_inv(threshold);
        let m3 = match self.march {
            None => s * s / (PI * e * e),
            Some(m) => s * s * m.inverse(1.0 / (PI * e * e)),
        };
        if !m3.is_finite() {
            return Junction::Sealed;
        }
        self.junction_at_m3(s, m3)
    }

    /// Assembles the junction at `ln(ζc q0) = ln_a` from u_c and ū_c (used by the table).
    pub(crate) fn junction_from(&self, ln_a: f64, u_c: f64, ubar_c: f64) -> CriticalJunction {
        let zeta_c = (ln_a - self.spectrum.ln_q0()).exp().max(1.0);
        CriticalJunction {
            zeta_c,
            lambda_c: 2.0 * PI / ln_a.exp(),
            u_c,
            ubar_c,
            hrms_c: self.spectrum.rms_roughness_above(ln_a.exp()),
        }
    }

    /// `ln(ζc q0)` at reduced pressure s, `None` when sealed.
    pub(crate) fn critical_ln_q(&self, s: f64) -> Option<f64> {
        self.spectrum.invert_m3(self.critical_m3(s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paper_contact() -> PerssonContact {
        let sp = Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None).unwrap();
        PerssonContact::new(sp, ContactSettings::default())
    }

    #[test]
    fn analytic_derivatives_match_finite_differences() {
        let c = paper_contact();
        let s = 0.2e6 / (10e6 / 0.75);
        for zeta in [3.0, 16.0, 500.0] {
            let h = 1e-5_f64;
            let a = c.separation(zeta * (-h).exp(), s);
            let b = c.separation(zeta * h.exp(), s);
            let m = c.separation(zeta, s);
            let fd_u = (b.mean - a.mean) / (2.0 * h);
            let fd_a = (b.area - a.area) / (2.0 * h);
            assert!(
                (fd_u / m.mean_dlnzeta - 1.0).abs() < 1e-6,
                "zeta={zeta}: {fd_u} vs {}",
                m.mean_dlnzeta
            );
            assert!((fd_a / m.area_dlnzeta - 1.0).abs() < 1e-6);
        }
    }

    #[test]
    fn junction_at_the_own_threshold_is_the_junction() {
        let c = paper_contact();
        let s = 0.2e6 / (10e6 / 0.75);
        assert_eq!(
            c.critical_junction_at_threshold(s, 0.4),
            c.critical_junction(s)
        );
        // a smaller threshold: a narrower constriction at a higher magnification
        let (a, b) = (
            c.critical_junction(s).leaking().copied().unwrap(),
            c.critical_junction_at_threshold(s, 0.3)
                .leaking()
                .copied()
                .unwrap(),
        );
        assert!(b.u_c < a.u_c && b.zeta_c > a.zeta_c);
        assert_eq!(c.critical_junction_at_threshold(s, 0.0), Junction::Sealed);
    }
}
