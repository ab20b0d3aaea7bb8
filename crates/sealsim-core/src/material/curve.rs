//! The linear-viscoelastic response of a material at one temperature on a log time grid
//! (`sealsim materials curve`).
//!
//! The grid is uniform in log reduced time ξ over the Prony series' relaxation times widened
//! by [`MARGIN_DECADES`] on each side (1 s ± the margin for an elastic material). At a
//! temperature T with shift factor a_T the physical time of a grid point is `t = a_T ξ`, so the
//! curve always shows the whole relaxation, moved along the time axis by exactly a_T
//! (time–temperature superposition). Each point also carries the dynamic moduli at the
//! angular frequency `ω = 1/t`: `E′(ω; T) = E′(ω a_T) = E′(1/ξ)` at the reference temperature.
//!
//! A frozen WLF material (T ≤ T_ref − C2, a_T = ∞) does not relax at any finite time: the grid
//! is then taken as physical time, ξ = 0 everywhere, and the response is the instantaneous one
//! (E = E′ = E0, J = 1/E0, E″ = tan δ = 0).

use super::{Material, Prony, PronyTerm};
use std::fmt;

/// Decades added to the τ range on each side of the grid.
pub const MARGIN_DECADES: i32 = 2;

/// The response at one grid point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePoint {
    /// Physical time t \[s\] at the curve's temperature.
    pub time: f64,
    /// Reduced time ξ = t/a_T \[s\] (0 when frozen).
    pub reduced_time: f64,
    /// Relaxation modulus E(ξ) \[Pa\].
    pub relaxation: f64,
    /// Creep compliance J(ξ) \[1/Pa\].
    pub compliance: f64,
    /// Angular frequency ω = 1/t \[rad/s\].
    pub angular_frequency: f64,
    /// Storage modulus E′(ω a_T) \[Pa\].
    pub storage: f64,
    /// Loss modulus E″(ω a_T) \[Pa\].
    pub loss: f64,
    /// Loss factor tan δ = E″/E′.
    pub tan_delta: f64,
}

impl CurvePoint {
    /// All eight values, in the order of the fields (and of the curve CSV's columns).
    pub fn values(&self) -> [f64; 8] {
        [
            self.time,
            self.reduced_time,
            self.relaxation,
            self.compliance,
            self.angular_frequency,
            self.storage,
            self.loss,
            self.tan_delta,
        ]
    }
}

/// The response of a material at one temperature.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The temperature \[K\], or `None` for the reference temperature of the shift.
    pub temperature: Option<f64>,
    /// log10 a_T at that temperature (0 at the reference; +∞ when frozen).
    pub log10_shift: f64,
    /// Whether the material is frozen (WLF at or below T_ref − C2).
    pub frozen: bool,
    /// Whether the times are the reference grid rather than a_T times it: when frozen, or when
    /// a_T is so extreme that the shifted times are not representable (then ξ = t/a_T is 0 or
    /// ∞ to double precision: the instantaneous or the relaxed response).
    pub reference_grid: bool,
    pub points: Vec<CurvePoint>,
}

/// Why the curve cannot be computed in double precision (an extreme shift factor).
#[derive(Debug, Clone, PartialEq)]
pub struct CurveError(pub String);

impl fmt::Display for CurveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CurveError {}

/// The reduced-time grid: the relaxation times widened by [`MARGIN_DECADES`] each side, about
/// `points_per_decade` (≥ 1) points per decade, log-uniform, both ends included.
pub fn reduced_time_grid(prony: &Prony, points_per_decade: u32) -> Vec<f64> {
    let terms = prony.terms();
    let (lo, hi) = match (terms.first(), terms.last()) {
        (Some(first), Some(last)) => (first.tau, last.tau),
        _ => (1.0, 1.0),
    };
    // In log10: integer exponents stay exact, so that decades of seconds print as 1e-7, 1e-6, ...
    let margin = f64::from(MARGIN_DECADES);
    let (from, to) = (lo.log10() - margin, hi.log10() + margin);
    let steps = ((to - from) * f64::from(points_per_decade.max(1)))
        .round()
        .max(1.0);
    let n = steps as usize;
    (0..=n)
        .map(|k| 10f64.powf(from + (to - from) * k as f64 / steps))
        .collect()
}

/// The response of `material` at `temperature` \[K\] (`None`: the reference temperature).
pub fn response_curve(
    material: &Material,
    temperature: Option<f64>,
    points_per_decade: u32,
) -> Result<Curve, CurveError> {
    let prony = &material.prony;
    let grid = reduced_time_grid(prony, points_per_decade);
    let ln_rate = match (temperature, material.shift) {
        (Some(t), shift) => shift.ln_rate(t),
        (None, _) => 0.0,
    };
    let frozen = ln_rate == f64::NEG_INFINITY;
    let log10_shift = -ln_rate / std::f64::consts::LN_10;
    // The shifted grid t = a_T ξ, unless the material is frozen or a_T moves it outside the
    // normal doubles; then the reference grid is taken as physical time and ξ = t/a_T
    // (0 when frozen or underflowing: the instantaneous response; ∞ when overflowing: the
    // relaxed one).
    let shift_factor = (-ln_rate).exp();
    let shifted: Option<Vec<f64>> = (!frozen)
        .then(|| {
            grid.iter()
                .map(|&xi| {
                    if shift_factor.is_finite() && shift_factor > 0.0 {
                        xi * shift_factor
                    } else {
                        (xi.ln() - ln_rate).exp()
                    }
                })
                .collect::<Vec<f64>>()
        })
        .filter(|times| times.iter().all(|t| t.is_normal()));
    let reference_grid = shifted.is_none();
    let pairs: Vec<(f64, f64)> = match shifted {
        Some(times) => times.into_iter().zip(grid).collect(),
        None => grid
            .into_iter()
            .map(|t| (t, (t.ln() + ln_rate).exp()))
            .collect(),
    };
    let creep = prony.creep();
    let points = pairs
        .into_iter()
        .map(|(time, xi)| {
            let (storage, loss) = dynamic_moduli(prony, xi);
            CurvePoint {
                time,
                reduced_time: xi,
                relaxation: prony.relaxation(xi),
                // J(∞) of a solid is its limit 1/E∞ (avoids 0·∞ in the flow term)
                compliance: creep.compliance(xi.min(f64::MAX)),
                angular_frequency: 1.0 / time,
                storage,
                loss,
                tan_delta: loss / storage,
            }
        })
        .collect();
    let curve = Curve {
        temperature,
        log10_shift,
        frozen,
        reference_grid,
        points,
    };
    check_finite(&curve)?;
    Ok(curve)
}

/// E′ and E″ at the reduced angular frequency 1/ξ, written so that no ratio ξ/τ, however
/// extreme, gives a NaN: `E_i/(1 + (ξ/τ)²)` and `E_i/(ξ/τ + τ/ξ)`.
fn dynamic_moduli(prony: &Prony, xi: f64) -> (f64, f64) {
    let ratio = |t: &PronyTerm| xi / t.tau;
    let storage = prony.long_term()
        + prony
            .terms()
            .iter()
            .map(|t| t.modulus / (1.0 + ratio(t).powi(2)))
            .sum::<f64>();
    let loss = prony
        .terms()
        .iter()
        .map(|t| t.modulus / (ratio(t) + 1.0 / ratio(t)))
        .sum::<f64>();
    (storage, loss)
}

fn check_finite(curve: &Curve) -> Result<(), CurveError> {
    let bad = curve
        .points
        .iter()
        .find(|p| p.values().iter().any(|v| !v.is_finite()) || p.time <= 0.0);
    match bad {
        None => Ok(()),
        Some(_) => Err(CurveError(format!(
            "the shift factor a_T = 10^{:.1} puts the curve outside the range of double precision",
            curve.log10_shift
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::{Shift, Status};

    /// The single-term test rubber: E∞ 4 MPa, 6 MPa at 1000 h, WLF at 23 °C.
    fn test_rubber() -> Material {
        Material {
            name: "single-term test rubber".into(),
            status: Status::User,
            prony: Prony::new(
                4e6,
                &[PronyTerm {
                    modulus: 6e6,
                    tau: 3.6e6,
                }],
            )
            .unwrap(),
            poisson_ratio: 0.5,
            shift: Shift::Wlf {
                reference: 296.15,
                c1: 8.86,
                c2: 101.6,
            },
            glass_transition: None,
            thermal_expansion: None,
            glassy_thermal_expansion: None,
            ageing: None,
            ageing_basis: None,
            data_reduced_time: None,
            data_temperature: None,
            provenance: Vec::new(),
            compatibility: Vec::new(),
            library_id: None,
            class: None,
            permeation: Vec::new(),
            bands: Vec::new(),
        }
    }

    #[test]
    fn grid_spans_tau_range_plus_two_decades() {
        let m = test_rubber();
        let g = reduced_time_grid(&m.prony, 10);
        assert_eq!(g.len(), 41);
        assert!((g[0] / 3.6e4 - 1.0).abs() < 1e-12);
        assert!((g[40] / 3.6e8 - 1.0).abs() < 1e-12);
        assert!(
            g.windows(2)
                .all(|w| (w[1] / w[0] / 10f64.powf(0.1) - 1.0).abs() < 1e-12)
        );
        let decades = reduced_time_grid(
            &Prony::new(
                1.0,
                &[
                    PronyTerm {
                        modulus: 1.0,
                        tau: 1e-6,
                    },
                    PronyTerm {
                        modulus: 1.0,
                        tau: 1e13,
                    },
                ],
            )
            .unwrap(),
            10,
        );
        assert_eq!(decades.len(), 231);
        assert_eq!((decades[0], decades[10], decades[230]), (1e-8, 1e-7, 1e15));
    }

    #[test]
    fn reference_curve_is_the_series_and_warmer_is_shifted() {
        let m = test_rubber();
        let reference = response_curve(&m, None, 5).unwrap();
        for p in &reference.points {
            assert_eq!(p.time, p.reduced_time);
            assert_eq!(p.relaxation, m.prony.relaxation(p.time));
            assert!((p.storage / m.prony.storage(p.angular_frequency) - 1.0).abs() < 1e-14);
            assert!((p.loss / m.prony.loss(p.angular_frequency) - 1.0).abs() < 1e-14);
        }
        let warm = response_curve(&m, Some(353.15), 5).unwrap();
        let a_t = m.shift.factor(353.15);
        assert!(a_t < 1.0);
        for (w, r) in warm.points.iter().zip(&reference.points) {
            assert!((w.time / (a_t * r.time) - 1.0).abs() < 1e-14);
            assert_eq!(w.relaxation, r.relaxation);
            assert_eq!(w.storage, r.storage);
        }
    }

    #[test]
    fn frozen_is_instantaneous_and_extremes_stay_finite() {
        let m = test_rubber();
        let cold = response_curve(&m, Some(150.0), 3).unwrap();
        assert!(cold.frozen && cold.log10_shift == f64::INFINITY);
        assert!(
            cold.points
                .iter()
                .all(|p| p.relaxation == 1e7 && p.loss == 0.0)
        );
        // just above the frozen limit a_T overflows: the reference grid, instantaneous response
        let edge = m.shift.frozen_below().unwrap() + 1e-9;
        let c = response_curve(&m, Some(edge), 3).unwrap();
        assert!(!c.frozen && c.reference_grid && c.log10_shift > 1e9);
        assert!(
            c.points
                .iter()
                .all(|p| p.relaxation == 1e7 && p.reduced_time == 0.0)
        );
        // a_T ≈ 1e-1500 (far above T_ref, Arrhenius): ξ = t/a_T overflows, a clear error
        let hot = Material {
            shift: Shift::Arrhenius {
                reference: 296.15,
                activation_energy: 1e7,
            },
            ..test_rubber()
        };
        let e = response_curve(&hot, Some(2000.0), 3).unwrap_err();
        assert!(e.to_string().contains("10^-1502.6"), "{e}");
        let (e1, e2) = dynamic_moduli(&m.prony, 1e-300);
        assert!((e1 - 1e7).abs() < 1e-6 && e2 >= 0.0);
        let (e1, e2) = dynamic_moduli(&m.prony, 1e300);
        assert!((e1 - 4e6).abs() < 1e-6 && e2 >= 0.0);
    }
}
