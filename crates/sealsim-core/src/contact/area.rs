//! Which relation gives the relative contact area A(ζ)/A0 (docs/model.md §2, "The contact area").
//!
//! Persson's theory (J. Chem. Phys. 115 (2001) 3840) lets the pressure distribution diffuse with
//! magnification at the full-contact rate: its variance is `V_p(ζ) = V_pc(ζ) ∝ M3(ζ)`,
//! `M3(ζ) = ∫_{q0}^{ζq0} q³C dq`, and `A/A0 = erf(s/√(π M3))`, `s = P0/E*`. That under-predicts
//! the area of boundary-element and Green's-function simulations by 25–40 % at small load
//! (κ = √(8/π) ≈ 1.60 against ≈ 2.1–2.4; docs/src/validation.md). The published corrections slow
//! the diffusion where part of the interface has lost contact, marching the variance over scales:
//!
//! `dV_p = f(A) dV_pc`, `A = erf(P0/√(2 V_p))`,
//! * Yang & Persson, J. Phys.: Condens. Matter 20 (2008) 215214: `f = γ + (1 − γ)A²`;
//! * Wang & Müser, Tribol. Lett. 65 (2017), "Gauging Persson theory on adhesion":
//!   `f = γ − (2/9)A² + (11/9 − γ)A⁴`, γ = 5/9.
//!
//! Both have f(1) = 1 (full contact is Persson's) and f → γ as A → 0, so the small-load slope
//! becomes κ = √(8/π)/√γ. With `V ∝ M3`, the march is a function of one variable: in
//! `x = M3/s²` and `Φ = M3_eff/s²` (`M3_eff` the corrected moment, `A = erf(1/√(πΦ))`),
//! `dΦ/dx = f(erf(1/√(πΦ)))`, `Φ(0) = 0`, whatever the spectrum or the pressure. [`ScaleMarch`]
//! integrates that ODE once (RK4 in ln x, tabulated with cubic Hermite interpolation, ≈ 1e-9
//! relative) and closes it analytically beyond the table, so that every quantity that depends on
//! the area (ζc, p(ζ) = P0 A0/A(ζ), A′ in u1 and in P(u)) follows from
//! `M3_eff = s² Φ(M3/s²)` in place of `M3`.

use crate::math::special::erf;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// The relation of the contact area (`[model] area`, docs/model.md §2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum AreaModel {
    /// Persson 2001: `A/A0 = erf(s/√(π M3))` (κ = √(8/π)). The default: it predicts the smaller
    /// area, so the larger open area and leak (the conservative side, docs/src/validation.md).
    #[default]
    Persson,
    /// Wang & Müser 2017's scale march (γ = 5/9, κ = 2.14), the published correction closest to
    /// the numerical level's boundary elements (docs/src/validation.md).
    Corrected,
}

impl AreaModel {
    /// The scenario's spelling (`"persson"`, `"corrected"`).
    pub fn name(self) -> &'static str {
        match self {
            AreaModel::Persson => "persson",
            AreaModel::Corrected => "corrected",
        }
    }

    /// The scale march of the corrected relation (`None`: Persson's closed form).
    pub fn march(self) -> Option<&'static ScaleMarch> {
        match self {
            AreaModel::Persson => None,
            AreaModel::Corrected => Some(ScaleMarch::wang_muser()),
        }
    }
}

/// Lowest tabulated `ln x`: below it `A = erf(1/√(πx)) = 1` in double precision
/// (erf(17.8)), so `f = 1` and `Φ = x` exactly.
const LN_X_LO: f64 = -6.907_755_278_982_137; // ln 1e-3
/// Highest tabulated `ln x`; above it the analytic tail (see [`ScaleMarch::scaled`]).
const LN_X_HI: f64 = 18.420_680_743_952_367; // ln 1e8
/// Table nodes per unit of ln x.
const NODES_PER_UNIT: f64 = 128.0;
/// RK4 steps between two nodes.
const SUBSTEPS: usize = 4;

/// The variance march `dV_p = (c0 + c2 A² + c4 A⁴) dV_pc` in scaled form (module docs):
/// `Φ(x)`, `x = M3/s²`, tabulated as `L = ln Φ` against `t = ln x`.
#[derive(Debug, Clone, PartialEq)]
pub struct ScaleMarch {
    /// `[c0, c2, c4]`: f(A) = c0 + c2 A² + c4 A⁴ (c0 = γ, f(1) = 1).
    coefficients: [f64; 3],
    /// ln Φ at `t = LN_X_LO + i/NODES_PER_UNIT`.
    ln_phi: Vec<f64>,
    /// dL/dt there.
    slope: Vec<f64>,
}

impl ScaleMarch {
    /// Wang & Müser 2017: `f = γ − (2/9)A² + (11/9 − γ)A⁴`, γ = 5/9 (built once per process).
    pub fn wang_muser() -> &'static ScaleMarch {
        static MARCH: OnceLock<ScaleMarch> = OnceLock::new();
        MARCH.get_or_init(|| {
            let gamma = 5.0 / 9.0;
            ScaleMarch::new([gamma, -2.0 / 9.0, 11.0 / 9.0 - gamma])
        })
    }

    /// Yang & Persson 2008: `f = γ + (1 − γ)A²` (γ ≈ 0.42–0.45 in the literature; used by the
    /// tests as a second published relation).
    pub fn yang_persson(gamma: f64) -> ScaleMarch {
        ScaleMarch::new([gamma, 1.0 - gamma, 0.0])
    }

    /// Integrates `dΦ/dx = f(erf(1/√(πΦ)))` from `Φ = x` at x = 1e-3 (where A = 1) to x = 1e8.
    /// `f` must be positive on \[0, 1\] (both published relations are: min 0.54 and 0.42).
    pub fn new(coefficients: [f64; 3]) -> ScaleMarch {
        let mut march = ScaleMarch {
            coefficients,
            ln_phi: Vec::new(),
            slope: Vec::new(),
        };
        let n = ((LN_X_HI - LN_X_LO) * NODES_PER_UNIT).round() as usize;
        let h = 1.0 / NODES_PER_UNIT;
        // dL/dt = (x/Φ) f(A) = e^{t − L} f(A(L))
        let rhs = |t: f64, l: f64| (t - l).exp() * march.rate(area_of(l.exp()));
        let (mut t, mut l) = (LN_X_LO, LN_X_LO);
        let mut ln_phi = Vec::with_capacity(n + 1);
        let mut slope = Vec::with_capacity(n + 1);
        ln_phi.push(l);
        slope.push(rhs(t, l));
        let k = h / SUBSTEPS as f64;
        for i in 1..=n {
            for _ in 0..SUBSTEPS {
                let k1 = rhs(t, l);
                let k2 = rhs(t + 0.5 * k, l + 0.5 * k * k1);
                let k3 = rhs(t + 0.5 * k, l + 0.5 * k * k2);
                let k4 = rhs(t + k, l + k * k3);
                l += k / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
                t += k;
            }
            // re-anchor t on the grid (no drift of the sum of substeps)
            t = LN_X_LO + i as f64 * h;
            ln_phi.push(l);
            slope.push(rhs(t, l));
        }
        march.ln_phi = ln_phi;
        march.slope = slope;
        march
    }

    /// `f(A) = c0 + c2 A² + c4 A⁴`, the factor on the full-contact variance growth.
    pub fn rate(&self, area: f64) -> f64 {
        let [c0, c2, c4] = self.coefficients;
        let a2 = area * area;
        c0 + a2 * (c2 + c4 * a2)
    }

    /// γ = f(0): the small-load limit, where `κ = √(8/π)/√γ`.
    pub fn gamma(&self) -> f64 {
        self.coefficients[0]
    }

    /// `(Φ(x)/x, d ln Φ/d ln x)` at `x = M3/s² ≥ 0` (both 1 in full contact, → γ and 1 at
    /// small load). `x = ∞` (s² underflowed) gives the limit `(γ, 1)`.
    pub fn scaled(&self, x: f64) -> (f64, f64) {
        if x.is_nan() || x <= 0.0 || x.ln() <= LN_X_LO {
            return (1.0, 1.0);
        }
        let t = x.ln();
        let t1 = self.t_end();
        if t < t1 {
            let (l, dl) = self.hermite(t);
            return ((l - t).exp(), dl);
        }
        // Beyond the table A ≈ 2/(π√Φ) is small: dΦ/dx = c0 + b/Φ, b = c2·4/π², whose
        // solution from (x1, Φ1) is x − x1 = (Φ − Φ1)/c0 − (b/c0²) ln((c0Φ + b)/(c0Φ1 + b));
        // one fixed-point step from Φ̃ = Φ1 + c0(x − x1) leaves an error O(b²/(c0²Φ)) < 1e-15.
        let c0 = self.coefficients[0];
        let b = self.coefficients[1] * 4.0 / (PI * PI);
        let x1 = t1.exp();
        let phi1 = self.ln_phi[self.ln_phi.len() - 1].exp();
        if !x.is_finite() {
            return (c0, 1.0);
        }
        let guess = phi1 + c0 * (x - x1);
        let phi = guess + (b / c0) * ((c0 * guess + b) / (c0 * phi1 + b)).ln();
        let dl = x * self.rate(area_of(phi)) / phi;
        (phi / x, dl)
    }

    /// `Φ(x)`, the corrected moment over s² at `x = M3/s²`.
    pub fn phi(&self, x: f64) -> f64 {
        self.scaled(x).0 * x
    }

    /// `A/A0 = erf(1/√(π Φ(x)))` at `x = M3/s²`.
    pub fn area(&self, x: f64) -> f64 {
        if x.is_nan() || x <= 0.0 {
            return 1.0;
        }
        area_of(self.phi(x))
    }

    /// The `x` at which `Φ(x) = phi` (Φ increases strictly: dΦ/dx = f > 0).
    pub fn inverse(&self, phi: f64) -> f64 {
        if phi.is_nan() || phi <= 0.0 {
            return 0.0;
        }
        let lp = phi.ln();
        if lp <= LN_X_LO {
            return phi;
        }
        let last = self.ln_phi.len() - 1;
        if lp >= self.ln_phi[last] {
            let c0 = self.coefficients[0];
            let b = self.coefficients[1] * 4.0 / (PI * PI);
            let phi1 = self.ln_phi[last].exp();
            return self.t_end().exp()
                + ((phi - phi1) - (b / c0) * ((c0 * phi + b) / (c0 * phi1 + b)).ln()) / c0;
        }
        // the node interval, then bisection on the Hermite cubic (monotone in it)
        let i = self.ln_phi.partition_point(|&l| l <= lp).saturating_sub(1);
        let h = 1.0 / NODES_PER_UNIT;
        let (mut lo, mut hi) = (LN_X_LO + i as f64 * h, LN_X_LO + (i + 1) as f64 * h);
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if self.hermite(mid).0 < lp {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        (0.5 * (lo + hi)).exp()
    }

    /// The last node's `t = ln x` (≈ [`LN_X_HI`]): the tail takes over above it.
    fn t_end(&self) -> f64 {
        LN_X_LO + (self.ln_phi.len() - 1) as f64 / NODES_PER_UNIT
    }

    /// `(L, dL/dt)` at `t` inside the table: cubic Hermite on the nodes' values and slopes.
    fn hermite(&self, t: f64) -> (f64, f64) {
        let h = 1.0 / NODES_PER_UNIT;
        let u = (t - LN_X_LO) / h;
        let i = (u.floor() as usize).min(self.ln_phi.len() - 2);
        let r = u - i as f64;
        let (y0, y1) = (self.ln_phi[i], self.ln_phi[i + 1]);
        let (m0, m1) = (self.slope[i] * h, self.slope[i + 1] * h);
        let (r2, r3) = (r * r, r * r * r);
        let y = (2.0 * r3 - 3.0 * r2 + 1.0) * y0
            + (r3 - 2.0 * r2 + r) * m0
            + (-2.0 * r3 + 3.0 * r2) * y1
            + (r3 - r2) * m1;
        let dy = (6.0 * r2 - 6.0 * r) * y0
            + (3.0 * r2 - 4.0 * r + 1.0) * m0
            + (-6.0 * r2 + 6.0 * r) * y1
            + (3.0 * r2 - 2.0 * r) * m1;
        (y, dy / h)
    }
}

/// `A = erf(1/√(π Φ))` (1 at Φ = 0).
fn area_of(phi: f64) -> f64 {
    if phi.is_nan() || phi <= 0.0 {
        return 1.0;
    }
    erf(1.0 / (PI * phi).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ODE dΦ/dx = f(A(Φ)) integrated directly in x by RK4 with small steps: an
    /// independent path to Φ (no logarithms, no table).
    fn direct(march: &ScaleMarch, x_end: f64) -> f64 {
        let n = 200_000;
        let h = x_end / n as f64;
        let f = |phi: f64| march.rate(area_of(phi));
        let mut phi = 0.0;
        for _ in 0..n {
            let k1 = f(phi);
            let k2 = f(phi + 0.5 * h * k1);
            let k3 = f(phi + 0.5 * h * k2);
            let k4 = f(phi + h * k3);
            phi += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        }
        phi
    }

    #[test]
    fn the_table_agrees_with_a_direct_integration_in_x() {
        for march in [ScaleMarch::wang_muser(), &ScaleMarch::yang_persson(0.42)] {
            for x in [0.05, 0.3, 1.0, 4.0, 30.0] {
                let (a, b) = (march.phi(x), direct(march, x));
                assert!((a / b - 1.0).abs() < 1e-8, "x = {x}: {a} vs {b}");
            }
        }
    }

    #[test]
    fn limits_full_contact_and_small_load() {
        let m = ScaleMarch::wang_muser();
        // full contact: Φ = x
        assert_eq!(m.scaled(1e-4), (1.0, 1.0));
        // small load: Φ/x → γ, and across the table's end the tail is continuous
        let below = m.scaled(m.t_end().exp() * (1.0 - 1e-9));
        let above = m.scaled(m.t_end().exp() * (1.0 + 1e-9));
        assert!(
            (below.0 / above.0 - 1.0).abs() < 1e-9,
            "{below:?} {above:?}"
        );
        assert!((below.1 - above.1).abs() < 1e-8, "{below:?} {above:?}");
        let (r, _) = m.scaled(1e30);
        assert!((r / (5.0 / 9.0) - 1.0).abs() < 1e-12);
        assert_eq!(m.scaled(f64::INFINITY), (5.0 / 9.0, 1.0));
    }

    #[test]
    fn inverse_round_trips() {
        let m = ScaleMarch::wang_muser();
        for x in [1e-5, 0.01, 0.2, 1.0, 7.0, 1e3, 1e7, 1e9, 1e14] {
            let back = m.inverse(m.phi(x));
            assert!((back / x - 1.0).abs() < 1e-10, "{x}: {back}");
        }
    }

    #[test]
    fn derivative_is_the_derivative_of_the_value() {
        let m = ScaleMarch::wang_muser();
        for x in [0.02, 0.3, 2.0, 50.0, 1e6, 1e9] {
            let e = 1e-5_f64;
            let fd = (m.phi(x * e.exp()).ln() - m.phi(x * (-e).exp()).ln()) / (2.0 * e);
            let (_, d) = m.scaled(x);
            assert!((fd - d).abs() < 1e-7, "x = {x}: {fd} vs {d}");
        }
    }
}
