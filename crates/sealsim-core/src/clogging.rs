//! Particle clogging of the critical constrictions (docs/model.md §7, after PY08 §6).
//!
//! **Straining** (the default, [`CaptureLaw::Straining`]): a particle of diameter d follows the
//! flow from the entry of the contact through one constriction per octave of the channel
//! hierarchy, ζ = 1 (the entry), …, ζc/4, ζc/2, to the critical one at ζc. The heights of the
//! constrictions met at one magnification are that magnification's component of Persson's
//! separation distribution P(u) (docs/model.md §3.3): a folded normal centred at u1(ζ) with the
//! width of the roughness left, h_rms(ζ) ([`Constrictions`]). The flow through a constriction of
//! height u scales as u³, so the particle meets a constriction narrower than itself with the
//! probability η(d) = E\[u³; u < d\]/E\[u³\] (size exclusion with the particles carried by the flow,
//! [`Constrictions::flux_split`]), and it reaches the critical level with the probability
//! S(d) = Π (1 − η_k(d)) over the upstream constrictions ([`survival`]: deep-bed filtration's
//! constant fractional removal per constriction passed, one constriction per octave). Those
//! captured upstream (depth filtration) and at the entry deposit; their solid volume forms the
//! entry cake. At the critical level a particle that meets an open channel whose constriction
//! is narrower than itself blocks it (complete blocking); the channels of each relative height
//! x = u/u_c keep their own open fraction, so the open share of the flow is
//!
//! ```text
//! f = ∫ W(x) exp(−x³ Λ(x)) dx,  W(x) = x³ g(x)/E[x³],  Λ(x) = Σ_{arrivals with d/u_c > x} m   (1)
//! ```
//!
//! (g the critical level's folded normal, m the dose of arriving particles per unit x³ of
//! channel flow, [`ArrivalDoses`]). **Sieving** ([`CaptureLaw::Sieving`]) is the limit of zero
//! spread: every critical constriction is u_c high, particles with u_c < d ≤ d_reach = u1(ζc/2)
//! block, and with N_ch = L_y/λ_c parallel channels
//!
//! ```text
//! df/dt = −n_p [F(d_reach) − F(u_c)] f Q̇_open / N_ch                                          (2)
//! ```
//!
//! Particles that stop upstream of the critical level cake at the entry of the contact, in the
//! wedge the gap opens outside it, whose Kozeny–Carman resistance adds in series
//! ([`cake_resistance_in_wedge`]). This module holds the validated inputs, the size
//! distributions and these closed forms; the time integration lives in the life loop
//! (`simulate`, which uses this module).
// `!(x > 0.0)` is meant: it also rejects NaN
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use std::f64::consts::PI;

use statrs::distribution::{ContinuousCDF, LogNormal, Weibull};
use statrs::function::gamma::gamma;

use crate::math::quadrature::{gauss_integral, rule};
use crate::math::special::erfc;

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
    /// How particles are captured (`[contamination] capture`): straining (the default) or the
    /// sharp sieve.
    pub capture: CaptureLaw,
    /// A blocked critical channel detours through the next-narrowest constriction,
    /// `Q̇ = Q̇_open [f + (1 − f) r]` (docs/model.md §7); false: the parallel-channel limit
    /// `Q̇ = f Q̇_open`.
    pub reroute: bool,
    /// Relative tolerance of the open fraction f (`[simulation] clogging_tolerance`).
    pub tolerance: f64,
}

impl Contamination {
    /// Sieving: fraction of the arriving particles that reach the critical constriction of
    /// height `u_c` \[m\] and are sieved there: `F(d_reach) − F(u_c)` (u_c < d ≤ d_reach;
    /// `reach` \[m\] is d_reach ≥ u_c).
    pub fn captured_fraction(&self, u_c: f64, reach: f64) -> f64 {
        let f = &self.size_distribution;
        (f.cdf(reach.max(u_c)) - f.cdf(u_c)).clamp(0.0, 1.0)
    }

    /// Sieving: solid volume per unit volume of fluid of the particles that stop at the entry
    /// (d > d_reach): `n_p E[π d³/6; d > d_reach]` \[m³/m³\].
    pub fn cake_volume_fraction(&self, reach: f64) -> f64 {
        self.number_concentration * PI / 6.0 * self.size_distribution.partial_moment(3, reach)
    }

    /// Sieving: the surface π d² of the particles that stop at the entry per unit volume of
    /// fluid, `n_p π E[d²; d > d_reach]` \[1/m\] (with [`Self::cake_volume_fraction`], the
    /// cake's Sauter diameter d₃₂ = 6 V/A).
    pub fn cake_surface_fraction(&self, reach: f64) -> f64 {
        self.number_concentration * PI * self.size_distribution.partial_moment(2, reach)
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

/// How particles are captured in the contact (`[contamination] capture`, docs/model.md §7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CaptureLaw {
    /// Continuous in particle size (the default): straining through the constrictions of every
    /// octave from the entry to the critical one, whose heights are spread like P(u)'s component
    /// at their magnification; particles stopped upstream deposit (depth filtration, the entry
    /// cake), those that meet a critical constriction narrower than themselves block its
    /// channel (equation (1) of the module).
    #[default]
    Straining,
    /// The limit of zero spread: particles with u_c < d ≤ d_reach = u1(ζc/2) block a critical
    /// channel, larger ones cake at the entry, smaller ones pass (equation (2)). Five decades of
    /// leaked volume can lie between two sizes 10 % apart (docs/model.md §7); kept for
    /// comparison.
    Sieving,
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

/// √(2π).
const SQRT_2PI: f64 = 2.506_628_274_631_000_5;

/// The standard normal density φ(z) (0 at ±∞).
fn std_normal_density(z: f64) -> f64 {
    if z.is_finite() {
        (-0.5 * z * z).exp() / SQRT_2PI
    } else {
        0.0
    }
}

/// Φ(β) − Φ(α) for α ≤ β, from the upper tails when both are positive (accurate far out).
fn std_normal_mass(alpha: f64, beta: f64) -> f64 {
    let upper = |z: f64| {
        if z == f64::INFINITY {
            0.0
        } else {
            0.5 * erfc(z / std::f64::consts::SQRT_2)
        }
    };
    let lower = |z: f64| 0.5 * erfc(-z / std::f64::consts::SQRT_2);
    if alpha >= 0.0 {
        upper(alpha) - upper(beta)
    } else if beta <= 0.0 {
        lower(beta) - lower(alpha)
    } else {
        1.0 - upper(beta) - lower(alpha)
    }
}

/// E\[X^k; a < X < b\] for X ~ N(μ, σ²), σ > 0, k ≤ 3, a finite, b finite or +∞:
/// `Σ_i C(k, i) μ^{k−i} σ^i J_i` with `J_i = ∫_α^β z^i φ(z) dz` (α, β the standardised limits):
/// J₀ = Φ(β) − Φ(α), J₁ = φ(α) − φ(β), J₂ = J₀ + αφ(α) − βφ(β), J₃ = (α² + 2)φ(α) − (β² + 2)φ(β)
/// \[derived: repeated integration by parts\].
fn normal_partial_moment(mu: f64, sigma: f64, k: usize, a: f64, b: f64) -> f64 {
    let alpha = (a - mu) / sigma;
    let beta = (b - mu) / sigma;
    let (pa, pb) = (std_normal_density(alpha), std_normal_density(beta));
    let times = |z: f64, p: f64| if z.is_finite() { z * p } else { 0.0 };
    let j0 = std_normal_mass(alpha, beta);
    let j = [
        j0,
        pa - pb,
        j0 + times(alpha, pa) - times(beta, pb),
        (alpha * alpha + 2.0) * pa - times(beta, times(beta, pb)) - 2.0 * pb,
    ];
    const BINOMIAL: [[f64; 4]; 4] = [
        [1.0, 0.0, 0.0, 0.0],
        [1.0, 1.0, 0.0, 0.0],
        [1.0, 2.0, 1.0, 0.0],
        [1.0, 3.0, 3.0, 1.0],
    ];
    (0..=k)
        .map(|i| BINOMIAL[k][i] * mu.powi((k - i) as i32) * sigma.powi(i as i32) * j[i])
        .sum()
}

/// The heights of the constrictions a particle meets at one magnification ζ, in units of the
/// critical gap u_c: u = |X|, X ~ N(`centre`, `spread`²), the component of Persson's
/// separation distribution P(u) of that magnification — a normal centred at u1(ζ) with the
/// width of the roughness left, h_rms(ζ), folded at the contact (docs/model.md §3.3, §7).
/// `spread` = 0 is one height (the sieve).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Constrictions {
    /// μ = u1(ζ)/u_c (dimensionless, ≥ 0).
    pub centre: f64,
    /// σ = h_rms(ζ)/u_c (dimensionless, ≥ 0).
    pub spread: f64,
}

impl Constrictions {
    /// The probability density of the height, `[φ((x − μ)/σ) + φ((x + μ)/σ)]/σ` for x ≥ 0.
    pub fn density(&self, x: f64) -> f64 {
        let (mu, sigma) = (self.centre, self.spread);
        if !(sigma > 0.0) || x < 0.0 {
            return 0.0;
        }
        (std_normal_density((x - mu) / sigma) + std_normal_density((x + mu) / sigma)) / sigma
    }

    /// E\[u^k; a < u < b\] (k ≤ 3, 0 ≤ a ≤ b ≤ ∞): the two branches of the fold in closed form
    /// (`normal_partial_moment`), or by Gauss–Legendre (order 8) on an interval narrower than
    /// σ/2, where the closed form would lose its digits to cancellation, or from 0 to below σ/20
    /// by the density's Taylor series at 0 (three terms).
    pub fn moment_between(&self, k: usize, a: f64, b: f64) -> f64 {
        let (mu, sigma) = (self.centre.abs(), self.spread);
        let a = a.max(0.0);
        if !(b > a) {
            return 0.0;
        }
        if !(sigma > 0.0) {
            return if mu > a && mu < b {
                mu.powi(k as i32)
            } else {
                0.0
            };
        }
        if a == 0.0 && b < 0.05 * sigma {
            // the density is even at 0: g(x) = g0 + g2 x²/2 + g4 x⁴/24 + …, with
            // g^(2n)(0) = 2 He_2n(μ/σ) φ(μ/σ)/σ^(2n+1) (He the Hermite polynomials); three terms
            // leave a relative error below (b/σ)⁶ ≈ 2e-8
            let t = mu / sigma;
            let g = 2.0 * std_normal_density(t) / sigma;
            let (h2, h4) = (t * t - 1.0, t.powi(4) - 6.0 * t * t + 3.0);
            let (s2, s4) = (h2 / (sigma * sigma), h4 / sigma.powi(4));
            let k = k as i32;
            let term = |n: i32| b.powi(k + n + 1) / f64::from(k + n + 1);
            return g * (term(0) + 0.5 * s2 * term(2) + s4 / 24.0 * term(4));
        }
        if b - a < 0.5 * sigma {
            return gauss_integral(|x| x.powi(k as i32) * self.density(x), 8, a, b);
        }
        let m =
            normal_partial_moment(mu, sigma, k, a, b) + normal_partial_moment(-mu, sigma, k, a, b);
        m.max(0.0)
    }

    /// E\[u³\], the mean cube of the heights (|μ|³ for one height).
    pub fn mean_cube(&self) -> f64 {
        self.moment_between(3, 0.0, f64::INFINITY)
    }

    /// The shares of the flow through constrictions narrower and wider than `y` (in units of
    /// u_c): `(E[u³; u < y], E[u³; u > y])/E[u³]` — the flow through a constriction of height
    /// u scales as u³ (σ(u) = u³/12η, docs/model.md §3.3), and the particles go with the flow.
    /// The smaller share is computed directly and the other as its complement, so both keep
    /// their digits far in the tails. For one height: (0, 1) up to it, (1, 0) beyond.
    pub fn flux_split(&self, y: f64) -> (f64, f64) {
        self.flux_split_of(self.mean_cube(), y)
    }

    /// [`Self::flux_split`] with the mean cube `total` = E\[u³\] given.
    fn flux_split_of(&self, total: f64, y: f64) -> (f64, f64) {
        if !(total > 0.0) || y.is_nan() || y <= 0.0 {
            return (0.0, 1.0);
        }
        if y >= self.centre.abs() {
            let above = (self.moment_between(3, y, f64::INFINITY) / total).clamp(0.0, 1.0);
            (1.0 - above, above)
        } else {
            let below = (self.moment_between(3, 0.0, y) / total).clamp(0.0, 1.0);
            (below, 1.0 - below)
        }
    }
}

/// The probability that a particle `y` = d/u_c across reaches the critical level through the
/// `upstream` constrictions, one met at each: `S = Π (1 − η_k(y))`, η_k the flow share of level
/// k narrower than y ([`Constrictions::flux_split`]) — deep-bed filtration's constant
/// fractional removal per collector passed, per constriction here (docs/model.md §7).
pub fn survival(upstream: &[Constrictions], y: f64) -> f64 {
    let mut s = [1.0];
    survivals(upstream, &[y], &mut s);
    s[0]
}

/// [`survival`] of each of `ys` into `out` (each level's mean cube computed once).
pub fn survivals(upstream: &[Constrictions], ys: &[f64], out: &mut [f64]) {
    for s in out.iter_mut() {
        *s = 1.0;
    }
    for level in upstream {
        let total = level.mean_cube();
        for (s, &y) in out.iter_mut().zip(ys) {
            if *s > 0.0 {
                *s *= level.flux_split_of(total, y).1;
            }
        }
    }
}

/// One node of a size distribution: the particles with diameters between `lo` and `hi` \[m\]
/// (one diameter when equal), their number fraction and their partial moments.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SizeNode {
    /// Lower and upper diameter of the interval \[m\] (the distribution's tails beyond
    /// ±`NODE_SCORE` standard scores are counted in the first and last node's weight and
    /// moments, not in their interval).
    pub lo: f64,
    pub hi: f64,
    /// The diameter that represents it: the median of the interval \[m\].
    pub diameter: f64,
    /// Number fraction (the nodes' weights sum to 1).
    pub weight: f64,
    /// E\[d²; node\] \[m²\] and E\[d³; node\] \[m³\] (number-weighted partial moments).
    pub m2: f64,
    pub m3: f64,
}

/// The standard scores the nodes of a continuous size distribution span (Φ(−8) ≈ 6e-16).
const NODE_SCORE: f64 = 8.0;
/// The number of nodes of a continuous size distribution: equal steps of 0.25 in the standard
/// score z = Φ⁻¹(F(d)) (for a log-normal, 0.25 ln σg in ln d).
pub const SIZE_NODES: usize = 64;

impl SizeDistribution {
    /// The diameter at the standard score `z`, `F⁻¹(Φ(z))` \[m\]: exact for the log-normal
    /// (median σg^z) and the Weibull (λ (−ln(1 − Φ(z)))^{1/k}, the upper tail from erfc), the
    /// piecewise-linear inverse of a table, the diameter of a monodisperse distribution.
    pub fn at_score(&self, z: f64) -> f64 {
        let lower = 0.5 * erfc(-z / std::f64::consts::SQRT_2);
        let upper = 0.5 * erfc(z / std::f64::consts::SQRT_2);
        match self {
            SizeDistribution::Monodisperse { diameter } => *diameter,
            SizeDistribution::LogNormal {
                median,
                geometric_std,
            } => median * geometric_std.powf(z),
            SizeDistribution::Weibull { scale, shape } => {
                // −ln(1 − Φ) = −ln Q(z), or −ln_1p(−Φ(z)) where Φ is small
                let h = if z < 0.0 {
                    -(-lower).ln_1p()
                } else {
                    -upper.ln()
                };
                scale * h.powf(1.0 / shape)
            }
            SizeDistribution::Table { diameter, cdf } => {
                let p = lower;
                let k = cdf.partition_point(|&f| f < p);
                if k >= cdf.len() {
                    return diameter.last().copied().unwrap_or(0.0);
                }
                let (d0, f0) = if k == 0 {
                    (0.0, 0.0)
                } else {
                    (diameter[k - 1], cdf[k - 1])
                };
                let (d1, f1) = (diameter[k], cdf[k]);
                if f1 > f0 {
                    d0 + (d1 - d0) * (p - f0) / (f1 - f0)
                } else {
                    d1
                }
            }
        }
    }

    /// The nodes the capture law integrates over: one for a monodisperse distribution,
    /// otherwise [`SIZE_NODES`] intervals of equal steps in the standard score from −8 to 8,
    /// each with its exact number fraction (Φ differences) and partial moments
    /// ([`Self::partial_moment`]); the tails beyond ±8 join the end nodes. Nodes of no weight
    /// (a flat stretch of a table) are left out.
    pub fn nodes(&self) -> Vec<SizeNode> {
        if let SizeDistribution::Monodisperse { diameter } = self {
            let d = *diameter;
            return vec![SizeNode {
                lo: d,
                hi: d,
                diameter: d,
                weight: 1.0,
                m2: d * d,
                m3: d.powi(3),
            }];
        }
        let n = SIZE_NODES;
        let step = 2.0 * NODE_SCORE / n as f64;
        let score = |i: usize| -NODE_SCORE + step * i as f64;
        let mut nodes = Vec::with_capacity(n);
        for i in 0..n {
            let (za, zb) = (score(i), score(i + 1));
            // the tails join the end nodes: from 0, to ∞
            let lo_all = if i == 0 { 0.0 } else { self.at_score(za) };
            let hi_all = if i + 1 == n {
                f64::INFINITY
            } else {
                self.at_score(zb)
            };
            let weight = if i == 0 {
                0.5 * erfc(-zb / std::f64::consts::SQRT_2)
            } else if i + 1 == n {
                0.5 * erfc(za / std::f64::consts::SQRT_2)
            } else {
                std_normal_mass(za, zb)
            };
            let moment = |k: i32| {
                let upper = if hi_all == f64::INFINITY {
                    0.0
                } else {
                    self.partial_moment(k, hi_all)
                };
                (self.partial_moment(k, lo_all) - upper).max(0.0)
            };
            if !(weight > 0.0) {
                continue;
            }
            let (lo, hi) = (self.at_score(za), self.at_score(zb));
            if !(hi > 0.0 && hi.is_finite()) {
                continue;
            }
            nodes.push(SizeNode {
                lo: lo.max(0.0),
                hi,
                diameter: self.at_score(0.5 * (za + zb)),
                weight,
                m2: moment(2),
                m3: moment(3),
            });
        }
        nodes
    }
}

/// The width of the dose bins in ln(d/u_c): 0.05, a 5 % step in relative particle size.
pub const DOSE_BIN: f64 = 0.05;
/// A dose that gives no channel more than this is not kept (`x³ m` for the widest channel it
/// can block, x = y).
const NEGLIGIBLE_DOSE: f64 = 1e-20;
/// Arrivals narrower than 1e-3 u_c are not kept: the channels they could block carry a share
/// of the flow below 1e-12 for any spread above 0.1 (∝ y⁴).
const LN_SMALLEST_DOSE: f64 = -6.907_755_278_982_137;

/// The particles that have arrived at the critical level, by their size relative to the
/// critical gap at arrival, y = d/u_c: the dose m of each bin is `∫ n_p κ S w dt` with
/// κ = Q̇_open/(N_ch E\[x³\]) the flow of a channel per unit x³ \[m³/s\] (a channel of relative
/// height x carries κ x³), so a channel of relative height x has received x³ Λ(x) particles
/// per open channel, Λ(x) the dose of the arrivals larger than x (docs/model.md §7). Each bin
/// keeps its dose and the dose-weighted mean of ln y (one size at a constant u_c stays at its
/// exact position).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ArrivalDoses {
    /// Index of the first bin (bin i covers ln y ∈ \[i, i + 1) · [`DOSE_BIN`]).
    first: i64,
    /// (dose, dose-weighted mean ln y) of each bin.
    bins: Vec<(f64, f64)>,
}

impl ArrivalDoses {
    /// True before any particle has arrived.
    pub fn is_empty(&self) -> bool {
        self.bins.iter().all(|b| b.0 <= 0.0)
    }

    /// The total dose (every arrival) \[1\].
    pub fn total(&self) -> f64 {
        self.bins.iter().map(|b| b.0).sum()
    }

    fn bin_mut(&mut self, index: i64) -> &mut (f64, f64) {
        if self.bins.is_empty() {
            self.first = index;
        }
        if index < self.first {
            let grow = (self.first - index) as usize;
            self.bins
                .splice(0..0, std::iter::repeat_n((0.0, 0.0), grow));
            self.first = index;
        }
        let k = (index - self.first) as usize;
        if k >= self.bins.len() {
            self.bins.resize(k + 1, (0.0, 0.0));
        }
        &mut self.bins[k]
    }

    /// Adds a dose `mass` of particles of one relative size e^`ln_y`. A dose that cannot give
    /// any channel (x < y) a dose x³m above 1e-20 is left out (it would block a share of the
    /// flow below that).
    pub fn add_point(&mut self, ln_y: f64, mass: f64) {
        if !(mass > 0.0 && mass.is_finite() && ln_y.is_finite())
            || ln_y < LN_SMALLEST_DOSE
            || mass * (3.0 * ln_y).exp() < NEGLIGIBLE_DOSE
        {
            return;
        }
        let bin = self.bin_mut((ln_y / DOSE_BIN).floor() as i64);
        // the running dose-weighted mean stays inside the bin, however small the doses
        bin.0 += mass;
        bin.1 += (ln_y - bin.1) * (mass / bin.0);
    }

    /// Adds a dose `mass` spread evenly in ln y over \[`ln_lo`, `ln_hi`\].
    pub fn add_spread(&mut self, ln_lo: f64, ln_hi: f64, mass: f64) {
        if !(mass > 0.0 && mass.is_finite()) {
            return;
        }
        if !(ln_hi - ln_lo > 1e-12) || !ln_lo.is_finite() || !ln_hi.is_finite() {
            self.add_point(0.5 * (ln_lo + ln_hi), mass);
            return;
        }
        let density = mass / (ln_hi - ln_lo);
        let mut from = ln_lo.max(LN_SMALLEST_DOSE);
        while from < ln_hi {
            let index = (from / DOSE_BIN).floor() as i64;
            let to = (((index + 1) as f64) * DOSE_BIN).min(ln_hi);
            // rounding can leave `to` at `from`: step to the next bin
            let to = if to > from {
                to
            } else {
                from + 1e-9 * DOSE_BIN
            };
            let part = density * (to - from);
            let at = 0.5 * (from + to);
            if part * (3.0 * at).exp() >= NEGLIGIBLE_DOSE {
                let bin = self.bin_mut(index);
                bin.0 += part;
                bin.1 += (at - bin.1) * (part / bin.0);
            }
            from = to;
        }
    }

    /// The open share of the critical channels' flow, equation (1) of the module:
    /// `f = ∫ W(x) exp(−x³ Λ(x)) dx` over the relative heights x of the critical constrictions
    /// (`critical`, in units of u_c), W the flow share, Λ(x) the dose of the arrivals larger
    /// than x. Between two bins Λ is constant and the integral is taken by Gauss–Legendre
    /// (order 4; order 2 on slivers no wider than σ/16 and 0.05 in x³Λ) on panels no wider than
    /// σ/4 in x nor ½ in x³Λ; beyond the largest arrival no channel is
    /// blocked (the flow share above it, in closed form). One height (σ = 0): `exp(−μ³ Λ(μ))`.
    pub fn open_share(&self, critical: &Constrictions) -> f64 {
        let Some(last) = self.bins.iter().rev().find(|b| b.0 > 0.0) else {
            return 1.0;
        };
        let (mu, sigma) = (critical.centre.abs(), critical.spread);
        if !(sigma > 0.0) {
            let dose: f64 = self
                .bins
                .iter()
                .filter(|b| b.0 > 0.0 && b.1.exp() > mu)
                .map(|b| b.0)
                .sum();
            return (-mu.powi(3) * dose).exp().clamp(0.0, 1.0);
        }
        let total = critical.mean_cube();
        if !(total > 0.0) {
            return 1.0;
        }
        // beyond the largest arrival nothing is blocked
        let mut share = critical.flux_split(last.1.exp()).1 * total;
        // downwards from it: on (x_{i−1}, x_i) Λ is the dose of the points i, i + 1, …; the
        // heights above μ + 10σ carry no flow worth counting
        let support_hi = mu + 10.0 * sigma;
        let (nodes, weights) = rule(4);
        let mut dose = 0.0;
        let mut upper = f64::NAN;
        for bin in self.bins.iter().rev().filter(|b| b.0 > 0.0) {
            let x = bin.1.exp();
            if upper.is_finite() {
                share += Self::blocked_interval(
                    critical,
                    x,
                    upper.min(support_hi),
                    dose,
                    nodes,
                    weights,
                );
            }
            dose += bin.0;
            upper = x;
        }
        share += Self::blocked_interval(critical, 0.0, upper.min(support_hi), dose, nodes, weights);
        (share / total).clamp(0.0, 1.0)
    }

    /// `∫_a^b x³ g(x) exp(−x³ Λ) dx` (unnormalised) on panels no wider than σ/4 and no
    /// wider than a step of ½ in x³Λ, Gauss–Legendre nodes on each; past x³Λ = 40 nothing
    /// is left.
    fn blocked_interval(
        critical: &Constrictions,
        a: f64,
        b: f64,
        dose: f64,
        nodes: &[f64],
        weights: &[f64],
    ) -> f64 {
        if !(b > a) || a.powi(3) * dose > 40.0 {
            return 0.0;
        }
        let b = if b.powi(3) * dose > 40.0 {
            (40.0 / dose).cbrt()
        } else {
            b
        };
        let width_x = 0.25 * critical.spread;
        // a sliver between two neighbouring bins (≤ σ/16, ≤ 0.05 in x³Λ) takes two nodes
        let (nodes, weights) = if b - a <= 0.25 * width_x && (b.powi(3) - a.powi(3)) * dose <= 0.05
        {
            let (n, w) = rule(2);
            (n.as_slice(), w.as_slice())
        } else {
            (nodes, weights)
        };
        let mut sum = 0.0;
        let mut x0 = a;
        if b - a <= width_x && (b.powi(3) - a.powi(3)) * dose <= 0.5 {
            // one panel
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            for (z, w) in nodes.iter().zip(weights) {
                let x = mid + half * z;
                let c = x.powi(3);
                sum += w * half * c * critical.density(x) * (-c * dose).exp();
            }
            return sum;
        }
        while x0 < b {
            // the next panel: σ/4 in x, and half a unit of x³Λ
            let by_dose = if dose > 0.0 {
                ((x0.powi(3) * dose + 0.5) / dose).cbrt() - x0
            } else {
                f64::INFINITY
            };
            let x1 = (x0 + width_x.min(by_dose).max(1e-6 * (b - a))).min(b);
            let (mid, half) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
            for (z, w) in nodes.iter().zip(weights) {
                let x = mid + half * z;
                let c = x.powi(3);
                sum += w * half * c * critical.density(x) * (-c * dose).exp();
            }
            x0 = x1;
        }
        sum
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

    /// `∫_a^b f` by the composite Simpson rule on `n` (even) panels.
    fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
        let h = (b - a) / n as f64;
        let mut sum = f(a) + f(b);
        for i in 1..n {
            sum += f(a + h * i as f64) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        sum * h / 3.0
    }

    #[test]
    fn folded_normal_moments_against_quadrature() {
        for (mu, sigma) in [
            (1.0, 1.31),
            (1.0, 0.2),
            (4.0, 3.7),
            (0.0, 1.0),
            (1.85, 4.31),
        ] {
            let c = Constrictions {
                centre: mu,
                spread: sigma,
            };
            let top = mu + 14.0 * sigma;
            for k in 0..=3usize {
                for (a, b) in [
                    (0.0, f64::INFINITY),
                    (0.0, 0.3 * sigma),
                    (0.0, mu + 0.7 * sigma),
                    (0.5 * mu, mu + 2.0 * sigma),
                    (mu + 3.0 * sigma, f64::INFINITY),
                ] {
                    let got = c.moment_between(k, a, b);
                    let want = simpson(|x| x.powi(k as i32) * c.density(x), a, b.min(top), 40_000);
                    assert!(
                        (got - want).abs() <= 1e-9 * want.abs().max(1e-6 * sigma.powi(k as i32)),
                        "μ {mu} σ {sigma} k {k} [{a}, {b}]: {got} vs {want}"
                    );
                }
            }
            // the density integrates to 1
            assert!((c.moment_between(0, 0.0, f64::INFINITY) - 1.0).abs() < 1e-14);
        }
        // closed forms: one height |μ|³; the half-normal E[u³] = 2√(2/π) σ³
        let one = Constrictions {
            centre: 1.5,
            spread: 0.0,
        };
        assert_eq!(one.mean_cube(), 1.5f64.powi(3));
        let half = Constrictions {
            centre: 0.0,
            spread: 2.0,
        };
        let want = 2.0 * (2.0 / PI).sqrt() * 8.0;
        assert!((half.mean_cube() / want - 1.0).abs() < 1e-14);
    }

    #[test]
    fn flux_shares_limits() {
        let c = Constrictions {
            centre: 1.0,
            spread: 1.31,
        };
        for y in [1e-3, 0.5, 1.0, 2.0, 5.0, 20.0] {
            let (below, above) = c.flux_split(y);
            assert!((below + above - 1.0).abs() < 1e-15, "{y}");
        }
        // d → 0: the share narrower than y vanishes as y⁴ (the density is even at 0)
        let (a, b) = (c.flux_split(1e-3).0, c.flux_split(2e-3).0);
        assert!((b / a - 16.0).abs() < 1e-3, "{}", b / a);
        // far in the tail the wider share is still a positive, falling number (no
        // cancellation): at μ + 10σ it is of the order of the Gaussian tail
        let far = c.flux_split(1.0 + 10.0 * 1.31).1;
        let farther = c.flux_split(1.0 + 12.0 * 1.31).1;
        assert!(
            far > 0.0 && far < 1e-18 && farther < 1e-3 * far,
            "{far} {farther}"
        );
        // one height: all of it below or above
        let sieve = Constrictions {
            centre: 1.0,
            spread: 0.0,
        };
        assert_eq!(sieve.flux_split(0.99), (0.0, 1.0));
        assert_eq!(sieve.flux_split(1.01), (1.0, 0.0));
        // survival: 1 through nothing, falling with size, 0 far beyond every level
        let levels = [
            Constrictions {
                centre: 1.9,
                spread: 2.2,
            },
            Constrictions {
                centre: 1.85,
                spread: 4.3,
            },
        ];
        assert_eq!(survival(&[], 7.0), 1.0);
        let mut last = 1.0;
        for y in [0.1, 1.0, 2.0, 5.0, 10.0, 20.0] {
            let s = survival(&levels, y);
            assert!(s < last && s > 0.0, "{y}: {s}");
            last = s;
        }
        assert_eq!(survival(&levels, 200.0), 0.0);
    }

    #[test]
    fn size_nodes_partition_the_distribution() {
        let all = [
            SizeDistribution::LogNormal {
                median: 150e-9,
                geometric_std: 2.5,
            },
            SizeDistribution::Weibull {
                scale: 1e-6,
                shape: 2.0,
            },
            SizeDistribution::Table {
                diameter: vec![1e-6, 3e-6],
                cdf: vec![0.2, 1.0],
            },
        ];
        for d in &all {
            let nodes = d.nodes();
            assert!(nodes.len() <= SIZE_NODES && nodes.len() > 10, "{d:?}");
            let w: f64 = nodes.iter().map(|n| n.weight).sum();
            assert!((w - 1.0).abs() < 1e-12, "{d:?}: {w}");
            for k in [2, 3] {
                let sum: f64 = nodes.iter().map(|n| if k == 2 { n.m2 } else { n.m3 }).sum();
                let full = d.partial_moment(k, 0.0);
                assert!(
                    (sum / full - 1.0).abs() < 1e-10,
                    "{d:?} k {k}: {sum} vs {full}"
                );
            }
            for n in &nodes {
                assert!(n.lo <= n.diameter && n.diameter <= n.hi, "{n:?}");
            }
            // the diameter at a score has that score's cumulative fraction
            for z in [-3.0, -0.5, 0.0, 1.0, 4.0] {
                let p = 0.5 * erfc(-z / std::f64::consts::SQRT_2);
                let f = d.cdf(d.at_score(z));
                assert!((f - p).abs() < 1e-9, "{d:?} z {z}: {f} vs {p}");
            }
        }
        let m = SizeDistribution::Monodisperse { diameter: 2e-6 };
        assert_eq!(m.nodes().len(), 1);
        assert!((m.nodes()[0].m3 / 8e-18 - 1.0).abs() < 1e-15);
    }

    #[test]
    fn open_share_against_quadrature() {
        let c = Constrictions {
            centre: 1.0,
            spread: 1.31,
        };
        let total = c.mean_cube();
        assert_eq!(ArrivalDoses::default().open_share(&c), 1.0);
        // one size y, dose m: ∫_0^y W e^{−x³ m} dx + the flow share above y
        for (y, m) in [(0.7f64, 3.0), (1.5, 0.2), (3.0, 50.0), (6.0, 1e-3)] {
            let mut doses = ArrivalDoses::default();
            doses.add_point(y.ln(), m);
            let blocked = simpson(
                |x| x.powi(3) * c.density(x) * (-x.powi(3) * m).exp(),
                0.0,
                y,
                40_000,
            ) / total;
            let want = blocked + c.flux_split(y).1;
            let got = doses.open_share(&c);
            assert!((got - want).abs() < 1e-9, "y {y} m {m}: {got} vs {want}");
            // more dose, less open; a dose far below every channel changes nothing
            doses.add_point(y.ln(), m);
            assert!(doses.open_share(&c) < got);
        }
        // one height: exp(−μ³ Λ(μ)), counting only the arrivals wider than μ
        let mut doses = ArrivalDoses::default();
        doses.add_point(0.9f64.ln(), 5.0);
        doses.add_point(1.2f64.ln(), 0.3);
        let sieve = Constrictions {
            centre: 1.0,
            spread: 0.0,
        };
        assert!((doses.open_share(&sieve) - (-0.3f64).exp()).abs() < 1e-15);
        // a dose spread over an interval equals many points across it
        let (mut spread, mut points) = (ArrivalDoses::default(), ArrivalDoses::default());
        spread.add_spread(0.0, 1.0, 2.0);
        for i in 0..1000 {
            points.add_point((i as f64 + 0.5) / 1000.0, 2.0 / 1000.0);
        }
        assert!((spread.open_share(&c) - points.open_share(&c)).abs() < 1e-6);
        // doses too small to matter (down to denormals) are left out and cannot disorder the
        // bins (a denormal dose once gave its bin a mean position of 0, y = 1)
        let mut tiny = ArrivalDoses::default();
        tiny.add_point(5.0, 5e-324);
        tiny.add_point(5.2, 1e-300);
        tiny.add_point(1.0, 0.1);
        let mut plain = ArrivalDoses::default();
        plain.add_point(1.0, 0.1);
        assert_eq!(tiny.open_share(&c), plain.open_share(&c));
    }
}
