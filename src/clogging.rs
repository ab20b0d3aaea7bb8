//! Particle clogging of the critical constrictions (docs/model.md §7, after PY08 §6).
//!
//! Particles of diameter d larger than the height u_c of the critical constriction cannot
//! pass it and block the channel that carries them ("sieving", complete blocking, Hermia
//! n = 2). With the particle number concentration n_p \[1/m³\], the cumulative size
//! distribution F(d) and N_ch = L_y/λ_c parallel critical channels, the open fraction f of
//! the channels obeys
//!
//! ```text
//! df/dt = −n_p [1 − F(u_c(t))] Q̇(t) / N_ch            (1)
//! ```
//!
//! (every captured particle blocks one channel; Q̇ n_p \[1 − F\] is the rate at which captured
//! particles arrive). This module holds the validated inputs and the size distributions; the
//! time integration lives in [`crate::simulate`].

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
}

/// The `[contamination]` block, validated (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Contamination {
    /// n_p \[1/m³\] (from `number_concentration`, or `volume_fraction / E[π d³/6]`).
    pub number_concentration: f64,
    pub size_distribution: SizeDistribution,
    /// Blocked channels count as extra contact for the percolation (the next, narrower
    /// constriction takes over) rather than scaling the leak rate by f.
    pub reroute: bool,
    /// Relative tolerance of the open fraction f (`[simulation] clogging_tolerance`).
    pub tolerance: f64,
}

impl Contamination {
    /// Fraction of the arriving particles that are captured at a constriction of height
    /// `u_c` \[m\] (None: sealed, nothing arrives): `1 − F(u_c)`.
    pub fn captured_fraction(&self, u_c: f64) -> f64 {
        (1.0 - self.size_distribution.cdf(u_c)).clamp(0.0, 1.0)
    }
}

/// The effective percolation threshold when a fraction `1 − f` of the critical channels is
/// blocked and counted as contact: `a_eff = 1 − (1 − a_c)/f` (a_c the clean threshold).
/// At f = 1 exactly a_c; ≤ 0 (the seal closes) for f ≤ 1 − a_c.
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
    fn threshold_closes_at_one_minus_ac() {
        assert_eq!(effective_threshold(0.4, 1.0), 0.4);
        assert!((effective_threshold(0.4, 0.6)).abs() < 1e-15);
        assert!(effective_threshold(0.4, 0.5) < 0.0);
        assert!((effective_threshold(0.4, 0.8) - 0.25).abs() < 1e-15);
    }
}
