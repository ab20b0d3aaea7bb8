//! Particle clogging of the critical constrictions (docs/model.md §7, after PY08 §6).
//!
//! A particle of diameter d travels into the contact until the gap falls to d. Particles with
//! u_c < d ≤ d_reach reach the critical constriction, cannot pass it and block the channel
//! that carries them ("sieving", complete blocking, Hermia n = 2); d_reach = u1(ζc/2), the
//! constriction of the next-coarser octave of the channel path (docs/model.md §7). With the
//! particle number concentration n_p \[1/m³\], the cumulative size distribution F(d) and
//! N_ch = L_y/λ_c parallel critical channels, the open fraction f of the channels obeys
//!
//! ```text
//! df/dt = −n_p [F(d_reach) − F(u_c)] f Q̇_open / N_ch            (1)
//! ```
//!
//! (every sieved particle blocks one channel; the open channels carry f Q̇_open). Particles
//! with d > d_reach stop at the entry of the contact and form a filter cake there, in the wedge
//! the gap opens outside the contact, whose Kozeny–Carman resistance adds in series
//! ([`cake_resistance_in_wedge`]). This module holds
//! the validated inputs, the size distributions and these closed forms; the time integration
//! lives in the life loop (`simulate`, which uses this module).

use std::f64::consts::PI;

use statrs::distribution::{ContinuousCDF, LogNormal, Weibull};
use statrs::function::gamma::gamma;

/// Default relative tolerance of the open fraction (`[simulation] clogging_tolerance`).
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

/// Particle size distribution: the cumulative fraction F(d) of particles with diameter ≤ d.
///
/// The log-normal and Weibull CDFs are statrs' (`statrs` is built without its default
/// features, so it brings no second nalgebra).
#[derive(Debug, Clone, PartialEq)]
pub enum SizeDistribution {
    /// All particles of one diameter \[m\]: F(u) = 1 for u ≥ d, else 0.
    Monodisperse { diameter: f64 },
    /// Log-normal by number: ln d normal with mean ln(median) and standard deviation
    /// ln(geometric_std) (geometric_std > 1).
    LogNormal { median: f64, geometric_std: f64 },
    /// Weibull: F(d) = 1 − exp(−(d/scale)^shape).
    Weibull { scale: f64, shape: f64 },
    /// A tabulated CDF, linear between rows, from (0, 0) to the first row and 1 beyond the
    /// last: diameters \[m\] strictly increasing, F non-decreasing in \[0, 1\], ending at 1.
    Table { diameter: Vec<f64>, cdf: Vec<f64> },
}

impl SizeDistribution {
    /// F(u): the fraction of particles (by number) with diameter ≤ u \[m\].
    pub fn cdf(&self, u: f64) -> f64 {
        if u.is_nan() || u <= 0.0 {
            return 0.0;
        }
        match self {
            SizeDistribution::Monodisperse { diameter } => {
                if u >= *diameter {
                    1.0
                } else {
                    0.0
                }
            }
            SizeDistribution::LogNormal {
                median,
                geometric_std,
            } => LogNormal::new(median.ln(), geometric_std.ln())
                .map_or(0.0, |d| d.cdf(u).clamp(0.0, 1.0)),
            SizeDistribution::Weibull { scale, shape } => {
                Weibull::new(*shape, *scale).map_or(0.0, |d| d.cdf(u).clamp(0.0, 1.0))
            }
            SizeDistribution::Table { diameter, cdf } => {
                let k = diameter.partition_point(|&d| d < u);
                if k >= diameter.len() {
                    return 1.0;
                }
                let (d0, f0) = if k == 0 {
                    (0.0, 0.0)
                } else {
                    (diameter[k - 1], cdf[k - 1])
                };
                let (d1, f1) = (diameter[k], cdf[k]);
                (f0 + (f1 - f0) * (u - d0) / (d1 - d0)).clamp(0.0, 1.0)
            }
        }
    }

    /// E\[d³\] \[m³\]: monodisperse d³; log-normal median³ exp(4.5 ln²σg); Weibull
    /// λ³ Γ(1 + 3/k); a table exactly for its piecewise-linear CDF (uniform density in each
    /// interval: ΔF (d₁⁴ − d₀⁴)/(4 (d₁ − d₀))).
    pub fn mean_cube(&self) -> f64 {
        match self {
            SizeDistribution::Monodisperse { diameter } => diameter.powi(3),
            SizeDistribution::LogNormal {
                median,
                geometric_std,
            } => median.powi(3) * (4.5 * geometric_std.ln().powi(2)).exp(),
            SizeDistribution::Weibull { scale, shape } => scale.powi(3) * gamma(1.0 + 3.0 / shape),
            SizeDistribution::Table { diameter, cdf } => {
                let mut sum = 0.0;
                let (mut d0, mut f0) = (0.0, 0.0);
                for (&d1, &f1) in diameter.iter().zip(cdf) {
                    if d1 > d0 {
                        sum += (f1 - f0) * (d1.powi(4) - d0.powi(4)) / (4.0 * (d1 - d0));
                    }
                    (d0, f0) = (d1, f1);
                }
                sum
            }
        }
    }

    /// Mean particle volume E\[π d³/6\] \[m³\].
    pub fn mean_volume(&self) -> f64 {
        PI / 6.0 * self.mean_cube()
    }

    /// The partial moment E\[d^k; d > x\] \[m^k\] (k = 2, 3: the cake's surface and volume):
    /// monodisperse d^k if d > x; log-normal (ln d ~ N(μ, s²))
    /// `e^{kμ + k²s²/2} Φ((μ + k s² − ln x)/s)`; Weibull `λ^k Γ(1 + k/m) Q(1 + k/m, (x/λ)^m)`
    /// (Q the regularised upper incomplete gamma); a table exactly for its piecewise-linear CDF
    /// (uniform density in each interval, truncated at x) \[derived\].
    pub fn partial_moment(&self, k: i32, x: f64) -> f64 {
        let x = if x.is_nan() { 0.0 } else { x.max(0.0) };
        let kf = f64::from(k);
        match self {
            SizeDistribution::Monodisperse { diameter } => {
                if *diameter > x {
                    diameter.powi(k)
                } else {
                    0.0
                }
            }
            SizeDistribution::LogNormal {
                median,
                geometric_std,
            } => {
                let (mu, s) = (median.ln(), geometric_std.ln());
                let full = (kf * mu + 0.5 * kf * kf * s * s).exp();
                if x <= 0.0 {
                    return full;
                }
                let z = (mu + kf * s * s - x.ln()) / s;
                full * 0.5 * statrs::function::erf::erfc(-z / std::f64::consts::SQRT_2)
            }
            SizeDistribution::Weibull { scale, shape } => {
                let a = 1.0 + kf / shape;
                let upper = if x <= 0.0 {
                    1.0
                } else {
                    statrs::function::gamma::gamma_ur(a, (x / scale).powf(*shape))
                };
                scale.powi(k) * gamma(a) * upper
            }
            SizeDistribution::Table { diameter, cdf } => {
                let mut sum = 0.0;
                let (mut d0, mut f0) = (0.0, 0.0);
                for (&d1, &f1) in diameter.iter().zip(cdf) {
                    if d1 > d0 && d1 > x {
                        let lo = d0.max(x);
                        let density = (f1 - f0) / (d1 - d0);
                        sum += density * (d1.powi(k + 1) - lo.powi(k + 1)) / (kf + 1.0);
                    }
                    (d0, f0) = (d1, f1);
                }
                sum
            }
        }
    }
}

/// Default porosity φ of the filter cake at the contact's entry: 0.4, random packing of
/// equal spheres (≈ 0.36–0.40 \[recalled\]); a looser cake (larger φ) is more permeable, so
/// 0.4 leans towards the larger cake resistance.
pub const CAKE_POROSITY: f64 = 0.4;

/// Kozeny–Carman permeability of a packed bed of spheres of diameter `d` \[m\] and porosity
/// `phi`: `k = d² φ³ / (180 (1 − φ)²)` \[m²\] (the Kozeny–Carman equation with the constant
/// 180 for random packing of spheres; for a mixture of sizes d is the Sauter mean diameter
/// d₃₂ = E\[d³\]/E\[d²\], Kozeny constant 5 ≙ 180 — en.wikipedia "Kozeny–Carman equation"
/// via grokipedia.com/page/Kozeny–Carman_equation and particles.org.uk/particle_support/
/// permeability.htm).
pub fn kozeny_carman_permeability(d: f64, phi: f64) -> f64 {
    d * d * phi.powi(3) / (180.0 * (1.0 - phi).powi(2))
}

/// Hydraulic resistance of the cake \[Pa·s/m³\]: Darcy's law through a plug of cross-section
/// `area` \[m²\] and length V_bulk/area, `R = μ V_solid / ((1 − φ) k area²)`, with the solid
/// volume `solid_volume` \[m³\] of the deposited particles, the viscosity `viscosity` \[Pa·s\],
/// the Sauter mean diameter `d32` \[m\] and porosity `phi` \[derived from Darcy's law\].
pub fn cake_resistance(viscosity: f64, solid_volume: f64, d32: f64, phi: f64, area: f64) -> f64 {
    let k = kozeny_carman_permeability(d32, phi);
    if !(solid_volume > 0.0 && k > 0.0 && area > 0.0) {
        return 0.0;
    }
    viscosity * solid_volume / ((1.0 - phi) * k * area * area)
}

/// The opening of the gap outside the contact where the entry cake sits, dh/dx (docs/model.md
/// §7): 1, a 45° wedge. Particles larger than the reach stop where the gap has narrowed to
/// them, *outside* the contact, and the cake grows outwards where the gap widens: its
/// cross-section grows with its length, so its resistance grows only logarithmically with
/// its volume ([`cake_resistance_in_wedge`]). The band: from no resistance at all (the cake in
/// the open fluid beyond a gasket's edge, slope → ∞) to the slit plug of [`cake_resistance`]
/// (slope → 0, the bound the model used before). A slope of 1 sits at the end that predicts
/// more leak: the free surface of a squeezed O-ring leaves the counterface more gently close
/// to the contact, a cut gasket's edge more steeply.
pub const CAKE_WEDGE_SLOPE: f64 = 1.0;

/// Hydraulic resistance \[Pa·s/m³\] of a cake of solid volume `solid_volume` \[m³\] (porosity
/// `phi`, Sauter diameter `d32` \[m\], Kozeny–Carman permeability k) filling a wedge of length
/// `length` L_y \[m\] across the flow that opens from the entry gap `entry_gap` h0 \[m\] with
/// slope θ = `slope` (h = h0 + θ x): the bulk volume V_b = V_solid/(1 − φ) fills it to x_c with
/// `V_b = L_y (h0 x_c + θ x_c²/2)`, and Darcy's law in series over the growing section gives
/// `R = ∫_0^{x_c} μ dx/(k L_y h) = μ/(2 k L_y θ) · ln(1 + 2 θ V_b/(L_y h0²))` \[derived\]. It tends
/// to the slit plug [`cake_resistance`] (area L_y h0) as θ → 0 and grows like ln V_b, not V_b.
pub fn cake_resistance_in_wedge(
    viscosity: f64,
    solid_volume: f64,
    d32: f64,
    phi: f64,
    length: f64,
    entry_gap: f64,
    slope: f64,
) -> f64 {
    let k = kozeny_carman_permeability(d32, phi);
    if !(solid_volume > 0.0 && k > 0.0 && length > 0.0 && entry_gap > 0.0) {
        return 0.0;
    }
    let bulk = solid_volume / (1.0 - phi);
    let x = 2.0 * slope * bulk / (length * entry_gap * entry_gap);
    if slope <= 0.0 || x < 1e-8 {
        // the slit limit (and its first term, without cancellation)
        return viscosity * bulk / (k * length * length * entry_gap * entry_gap);
    }
    viscosity / (2.0 * k * length * slope) * x.ln_1p()
}

/// The `[contamination]` block, validated (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Contamination {
    /// n_p \[1/m³\] (from `number_concentration`, or `volume_fraction / E[π d³/6]`).
    pub number_concentration: f64,
    pub size_distribution: SizeDistribution,
    /// A blocked critical channel detours through the next-narrowest constriction,
    /// `Q̇ = Q̇_open [f + (1 − f) r]` (docs/model.md §7); false: the parallel-channel limit
    /// `Q̇ = f Q̇_open`.
    pub reroute: bool,
    /// Relative tolerance of the open fraction f (`[simulation] clogging_tolerance`).
    pub tolerance: f64,
}

impl Contamination {
    /// Fraction of the arriving particles that reach the critical constriction of height `u_c`
    /// \[m\] and are sieved there: `F(d_reach) − F(u_c)` (u_c < d ≤ d_reach; `reach` \[m\]
    /// is d_reach ≥ u_c).
    pub fn captured_fraction(&self, u_c: f64, reach: f64) -> f64 {
        let f = &self.size_distribution;
        (f.cdf(reach.max(u_c)) - f.cdf(u_c)).clamp(0.0, 1.0)
    }

    /// Solid volume per unit volume of fluid of the particles that stop at the entry
    /// (d > d_reach): `n_p E[π d³/6; d > d_reach]` \[m³/m³\].
    pub fn cake_volume_fraction(&self, reach: f64) -> f64 {
        self.number_concentration * PI / 6.0 * self.size_distribution.partial_moment(3, reach)
    }

    /// Sauter mean diameter of the cake's particles, `E[d³; d > x]/E[d²; d > x]` \[m\] (0 when
    /// no particle exceeds x).
    pub fn cake_diameter(&self, reach: f64) -> f64 {
        let f = &self.size_distribution;
        let (m3, m2) = (f.partial_moment(3, reach), f.partial_moment(2, reach));
        if m2 > 0.0 && m3.is_finite() {
            m3 / m2
        } else {
            0.0
        }
    }
}

/// The percolation threshold of the detours when a fraction `1 − f` of the critical channels
/// is blocked: the blocked channels' share of the non-contact area is taken away,
/// `a_eff = 1 − (1 − a_c)/f` (a_c the clean threshold), and the critical-junction
/// construction at a_eff gives the next-narrowest constriction u_c(a_eff) ≤ u_c (docs/model.md
/// §7). At f = 1 exactly a_c; ≤ 0 (no detour percolates) for f ≤ 1 − a_c.
pub fn effective_threshold(threshold: f64, open_fraction: f64) -> f64 {
    if open_fraction >= 1.0 {
        threshold
    } else if open_fraction <= 0.0 {
        f64::NEG_INFINITY
    } else {
        1.0 - (1.0 - threshold) / open_fraction
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cdfs_and_moments() {
        let ln = SizeDistribution::LogNormal {
            median: 1e-6,
            geometric_std: 2.0,
        };
        assert!((ln.cdf(1e-6) - 0.5).abs() < 1e-12);
        assert!((ln.mean_cube() / (1e-18 * (4.5 * 2f64.ln().powi(2)).exp()) - 1.0).abs() < 1e-14);
        let w = SizeDistribution::Weibull {
            scale: 1e-6,
            shape: 2.0,
        };
        assert!((w.cdf(1e-6) - (1.0 - (-1f64).exp())).abs() < 1e-12);
        // Γ(2.5) = 3√π/4
        assert!((w.mean_cube() / (1e-18 * 0.75 * PI.sqrt()) - 1.0).abs() < 1e-12);
        let m = SizeDistribution::Monodisperse { diameter: 2e-6 };
        assert_eq!((m.cdf(1.999e-6), m.cdf(2e-6)), (0.0, 1.0));
        // a table that is uniform on [1, 3] µm: E[d³] = (3⁴ − 1⁴)/(4·2) µm³ = 10 µm³
        let t = SizeDistribution::Table {
            diameter: vec![1e-6, 3e-6],
            cdf: vec![0.0, 1.0],
        };
        assert!((t.mean_cube() / 10e-18 - 1.0).abs() < 1e-12);
        assert_eq!(t.cdf(0.5e-6), 0.0);
        assert!((t.cdf(2e-6) - 0.5).abs() < 1e-12);
        assert_eq!(t.cdf(4e-6), 1.0);
        assert_eq!(ln.cdf(f64::NAN), 0.0);
    }

    #[test]
    fn partial_moments_from_zero_are_the_full_moments() {
        let all = [
            SizeDistribution::Monodisperse { diameter: 2e-6 },
            SizeDistribution::LogNormal {
                median: 1e-6,
                geometric_std: 2.0,
            },
            SizeDistribution::Weibull {
                scale: 1e-6,
                shape: 2.0,
            },
            SizeDistribution::Table {
                diameter: vec![1e-6, 3e-6],
                cdf: vec![0.0, 1.0],
            },
        ];
        for d in &all {
            assert!(
                (d.partial_moment(3, 0.0) / d.mean_cube() - 1.0).abs() < 1e-10,
                "{d:?}"
            );
        }
        // log-normal: above x = median e^{3 s²} exactly half of E[d³] (Φ(0) = ½)
        let s2 = 2f64.ln().powi(2);
        let x = 1e-6 * (3.0 * s2).exp();
        assert!((all[1].partial_moment(3, x) / all[1].mean_cube() - 0.5).abs() < 1e-12);
        // uniform on [1, 3] µm above 2 µm: ½ (3⁴ − 2⁴)/(4·1) µm³ … with density ½ per µm
        let t = &all[3];
        assert!(
            (t.partial_moment(3, 2e-6) / (0.5 * (81.0 - 16.0) / 4.0 * 1e-18) - 1.0).abs() < 1e-12
        );
        assert_eq!(all[0].partial_moment(3, 2e-6), 0.0);
    }

    #[test]
    fn threshold_closes_at_one_minus_ac() {
        assert_eq!(effective_threshold(0.4, 1.0), 0.4);
        assert!((effective_threshold(0.4, 0.6)).abs() < 1e-15);
        assert!(effective_threshold(0.4, 0.5) < 0.0);
        assert!((effective_threshold(0.4, 0.8) - 0.25).abs() < 1e-15);
    }
}
