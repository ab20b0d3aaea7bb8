//! Reciprocating (dynamic) seals at low sliding speed (PY08 §8, eqs. 7–17; docs/model.md §3.4).
//!
//! # The model, derived from the paper's text
//!
//! **Frame and signs (PY08 §8).** The rubber is at rest; the hard, flat countersurface (a rod,
//! a windscreen) slides past it with velocity `v0` along +x. The high-pressure fluid (P_a) is at
//! `x < 0`, the low-pressure fluid (P_b) at `x > L`, `ΔP = P_a − P_b`. So **`v0 > 0` drags fluid
//! from the high-pressure side a towards the low-pressure side b** (the leak direction; the
//! *out-stroke* of a rod seal, the rod leaving the pressurised cylinder) and **`v0 < 0` drags it
//! back** (the *in-stroke*). Every volume rate here counts flow from a to b as positive.
//!
//! **Flow in a channel.** In a thin channel of height `u(s)` and width `λ(s)` along the path
//! coordinate s, the Poiseuille + Couette profile gives the volume rate
//! `Q̇ = λ (−u³/(12η) dp/ds + v0 (x̂·ŝ) u/2)`, i.e.
//! `dp/ds = 6η v0 (x̂·ŝ)/u² − 12η Q̇/(λ u³)`. Integrated from the inlet to the critical
//! junction, with the distribution `P̃(u)` of heights along the channel (eqs. 7–8):
//! `P′_a = P_a + B_a v0 − C_a Q̇` (eq. 9), and from the junction to the outlet
//! `P′_b = P_b − B_b v0 ∓ C_b Q̇` (eq. 12), where
//!
//! * `B_a = 6 L_a η ∫_{u_c}^∞ P̃(u)/u² du` (**eq. 10**) \[Pa·s/m\], `B_b` the same with `L_b`;
//! * `L_a` is "the length of the percolation path projected on the x-axis" from the
//!   high-pressure edge to the critical junction, `L_b` from the junction to the low-pressure
//!   edge, so `L_a + L_b = L = L_x`, the seal width along the flow. The paper does not say where
//!   the junction sits: it is a parameter here ([`ReciprocatingSeal::junction_position`],
//!   `L_a = f L_x`; ½ for a symmetric seal). Only `B_a + B_b = 6 L_x η J` enters the leak rate,
//!   so the choice changes the split, never Q̇;
//! * `P̃(u) = P(u)/∫_{u_c}^∞ P(u′) du′` on `u > u_c` (the paper's approximation, after eq. 8),
//!   with P(u) the separation distribution of the whole interface
//!   ([`SeparationDistribution::persson`], docs/model.md §3.3);
//! * `C_a = 12 l_a η ∫ P̃/(λ(u) u³) du` (eq. 11) needs the unknown channel widths λ(u). The
//!   paper drops the factor `M(C_a − C_b)` in the denominator of eq. 13 ("negligible compared
//!   to unity"); so does sealsim. (Integrating dp/ds from the junction to the outlet actually
//!   gives `+C_b Q̇` in eq. 12 and a denominator `1 + M(C_a + C_b)` in eq. 13; the paper prints
//!   `−C_b Q̇` and `1 − M(C_a − C_b)`. Irrelevant once the term is dropped.)
//!
//! **Leak rate.** The junction passes `M (P′_a − P′_b)` with `M = α u_c³/(12η)` (eq. 2,
//! [m³/(Pa·s)], the conductance of *one* constriction, one square unit cell `L_x × L_x` of the
//! seal). The seal has `L_y/L_x` such cells side by side (eq. 3, and eq. 15's "extra factor
//! L_y/L_x"), so
//!
//! `Q̇ = (L_y/L_x) M [ΔP + (B_a + B_b) v0]`  (**eq. 13**, with eq. 3's factor) \[m³/s\].
//!
//! At `v0 = 0` this is exactly sealsim's static leak [`crate::fluid::Fluid::leak_rate`],
//! `(L_y/L_x) α u_c³ ΔP/(12η)` (eq. 3). docs/model.md §3.4 writes `Q̇ = M[ΔP + (B_a+B_b)v0]` without
//! the cell count and a single `B = 6 L η ∫…`; that B is `B_a + B_b` with `L = L_x`.
//!
//! **Wiper film (eqs. 14–17).** With `ΔP = 0`, `Q̇ = (L_y/L_x) M (B_a+B_b) v0
//! = L_y u_c³ v0 (α/2) J` (eq. 15), `J = ∫_{u_c}^∞ P̃(u)/u² du`. The film left on the
//! countersurface, `d = Q̇/(L_y v0)`, is `d = β u_c` (eq. 16) with
//! `β = (α/2) I`, `I = ∫_{u_c}^∞ u_c² P̃(u)/u² du` (the paper's *first* eq. 17 — the paper
//! numbers two equations 17). Since `u_c²/u² ≤ 1` on `u > u_c` and P̃ is normalised,
//! `0 ≤ I ≤ 1`, so `d ≤ (α/2) u_c`. The paper finds `I ≈ 0.1–0.2` and "expects β ≈ 0.1";
//! by its own eq. 17 that is `β = 0.05–0.1` for α = 1.
//!
//! **Stroke cycle** ([`stroke_cycle`]): out-stroke at `v0 = +v_out`, in-stroke at
//! `v0 = −v_in`, each over the stroke length S. The drag carries `L_y d S` out and the same
//! back, so in this linear theory the net volume per cycle is the static leak over the cycle
//! time.
//!
//! **Validity (the paper's *second* eq. 17).** The drag pressure at the critical constriction,
//! `p_c ≈ 6 L η v0 J = (B_a + B_b) v0`, opens it by `Δu ≈ λ_c p_c/E`; the contact is speed
//! independent only while `Δu ≪ u_c`:
//! `v0 ≪ E u_c³/(6 L η λ_c I) = E u_c/(λ_c (B_a + B_b))` (≈ `E u_c³/(L η λ_c)` for I ≈ 0.15).
//! Conventions: as in the paper, `E` is Young's modulus (not E*) and `L = L_x` is the full seal
//! width (the paper's L; the pressure built over `L_a` alone would allow a larger speed, so this
//! is the conservative reading); `λ_c` is sealsim's `2π/(ζc q0)`
//! ([`CriticalJunction::lambda_c`]). For its wiper example the paper reads "λ_c ≈ 10 µm" off
//! its Fig. 6; sealsim's convention gives ≈ 39 µm for the same case, so the bound here is ≈ 4×
//! below what the paper's λ_c would give. [`DragCoefficients::speed_bound`] is the
//! un-approximated first form (with the computed I), not the `≈` form.
//!
//! **Sealed.** Without a percolating channel every coefficient is exactly 0 (and the speed
//! bound is +∞: no constriction to open) — never NaN.
//!
//! **Not modelled here** (also absent from PY08 §8): speed-dependent or viscoelastic contact,
//! the `C` terms of eq. 13. Hydrodynamic lift of a rod seal above the speed bound, with the
//! starvation of the in-stroke, is [`ihl`] (docs/model.md §3.4.1): a stroke cycle with inlet
//! pressure gradients blends this theory's volumes into the inverse-hydrodynamic ones above the
//! onset `min(v_b, v_Λ)`.
//!
//! **In scenarios** (`[motion]`, [`MotionSpec`]): constant sliding ([`Motion::Steady`], the
//! out-stroke direction) or a stroke cycle ([`Motion::Stroke`]). [`MotionSpec::evaluate`]
//! turns a state's coefficients and static leak rate into the reported [`MotionPoint`]: the
//! drag at the sliding speed (a cycle: at the out-stroke speed), the film, the speed bound and
//! whether the fastest speed exceeds it, and a cycle's volumes ([`stroke_cycle_from`], on the
//! static leak rate of the caller: the fidelity level's for `sealsim leak`, the O-ring's
//! strips in series for `sealsim run`). Constant sliding adds its drag to the leak rate; a
//! stroke cycle does not (its drag volumes cancel). `sealsim leak` evaluates
//! [`DragCoefficients::compute`] at every pressure; the life run looks I up in a
//! [`DragTable`] built once per run.

pub mod ihl;

use crate::contact::table::{logistic, logit};
use crate::contact::{
    CriticalJunction, EffectiveMediumSettings, Elastic, Junction, PerssonContact,
    SeparationDistribution,
};
use crate::fluid::{Conduction, FlowGeometry, Fluid};
use crate::math::interp::UniformCubic;
use crate::math::quadrature::gauss_legendre;
use crate::math::special::erfc;
use crate::seal::FlatSeal;
use ihl::{GradientSource, IhlCycle, InletGradients, SpeedRegime, ihl_weight, transition_onset};
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// Half-width, in standard deviations, of the u-range kept for each Gaussian component of
/// P(u) (mass beyond: 1.2e-15).
const SIGMAS: f64 = 8.0;

/// A seal under reciprocating motion: the rubber, the flat contact, the fluid's viscosity and
/// where along the width the critical junction sits. All SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReciprocatingSeal {
    /// The rubber (E also enters the speed bound, PY08 eq. 17).
    pub material: Elastic,
    /// Nominal pressure P0 \[Pa\], width `L_x = L` along the flow \[m\] and length `L_y` across it
    /// \[m\] (e.g. the rod circumference).
    pub seal: FlatSeal,
    /// Dynamic viscosity η \[Pa·s\].
    pub viscosity: f64,
    /// Shape factor α of the critical constriction (PY08 eq. 2), ≈ 1.
    pub shape_factor: f64,
    /// `L_a/L_x` ∈ \[0, 1\]: the projected distance from the high-pressure edge to the critical
    /// junction over the width (clamped). ½ for a symmetric seal. Changes only the split of
    /// `B_a + B_b`, not the leak rate (module docs).
    pub junction_position: f64,
}

impl ReciprocatingSeal {
    /// `s = P0/E*`, the reduced pressure the contact theory depends on.
    pub fn reduced_pressure(&self) -> f64 {
        self.seal.nominal_pressure / self.material.effective_modulus()
    }

    /// `(L_a, L_b)` \[m\], the projected lengths of the percolation path on either side of the
    /// junction (`L_a + L_b = L_x`).
    pub fn side_widths(&self) -> (f64, f64) {
        let f = if self.junction_position.is_nan() {
            0.5
        } else {
            self.junction_position.clamp(0.0, 1.0)
        };
        let l_a = f * self.seal.width;
        (l_a, self.seal.width - l_a)
    }
}

/// Numerical settings of the drag coefficients.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DragSettings {
    /// How P(u) is built ([`SeparationDistribution::persson`]).
    pub distribution: EffectiveMediumSettings,
    /// Largest Gauss–Legendre panel width in `ln(u/u_c)` for the integral I.
    pub panel_width: f64,
    /// Gauss–Legendre points per panel.
    pub order: usize,
}

impl Default for DragSettings {
    fn default() -> Self {
        DragSettings {
            distribution: EffectiveMediumSettings::default(),
            panel_width: 0.05,
            order: 8,
        }
    }
}

impl DragSettings {
    /// The same rules with `factor`× as many u-panels for I (P(u) unchanged): for convergence
    /// checks of the integral.
    pub fn refined(self, factor: usize) -> Self {
        DragSettings {
            panel_width: self.panel_width / factor.max(1) as f64,
            ..self
        }
    }
}

/// The speed-independent coefficients of PY08 §8 for one seal state.
///
/// With them `Q̇(ΔP, v0) = (L_y/L_x) · m · [ΔP + (b_a + b_b) v0]` ([`leak_rate`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DragCoefficients {
    /// The critical junction the coefficients belong to.
    pub junction: Junction,
    /// The seal's extent along (L_x) and across (L_y) the flow; `L_y/L_x` square cells
    /// (constrictions) side by side (PY08 eq. 3).
    pub geometry: FlowGeometry,
    /// Viscosity η of the fluid \[Pa·s\].
    pub viscosity: f64,
    /// `M = α u_c³/(12η)` \[m³/(Pa·s)\]: conductance of one constriction (PY08 eq. 2).
    pub m: f64,
    /// `B_a = 6 L_a η J` \[Pa·s/m\] (PY08 eq. 10), `J = ∫_{u_c}^∞ P̃(u)/u² du`.
    pub b_a: f64,
    /// `B_b = 6 L_b η J` \[Pa·s/m\] (PY08 eq. 12's counterpart of eq. 10).
    pub b_b: f64,
    /// `I = ∫_{u_c}^∞ u_c² P̃(u)/u² du` ∈ \[0, 1\] (dimensionless; PY08 first eq. 17).
    pub integral_i: f64,
    /// `β = α I/2` (PY08 first eq. 17; paper: ≈ 0.1).
    pub beta: f64,
    /// Wiper film `d = β u_c` \[m\] (PY08 eq. 16): volume dragged out per swept area.
    pub film_thickness: f64,
    /// `v_max = E u_c³/(6 L η λ_c I) = E u_c/(λ_c (B_a + B_b))` \[m/s\] (PY08 second eq. 17,
    /// un-approximated; E Young's modulus, L = L_x): the theory needs `|v0| ≪ v_max`.
    /// +∞ when sealed or when P(u) has no mass above u_c.
    pub speed_bound: f64,
}

impl DragCoefficients {
    /// The coefficients of `seal` on the surface of `contact` (critical junction at
    /// `s = P0/E*`, P(u) by [`SeparationDistribution::persson`]). Sealed: all zero.
    pub fn compute(
        contact: &PerssonContact,
        seal: &ReciprocatingSeal,
        settings: &DragSettings,
    ) -> Self {
        let s = seal.reduced_pressure();
        let junction = contact.critical_junction(s);
        match junction {
            Junction::Sealed => Self::sealed(seal),
            Junction::Leaking(_) => {
                let p = SeparationDistribution::persson(contact, s, settings.distribution);
                Self::from_parts(&junction, &p, seal, settings)
            }
        }
    }

    /// The coefficients from a junction and a separation distribution computed elsewhere
    /// (e.g. from a table, or a synthetic P(u)). `seal.seal.nominal_pressure` is not used.
    pub fn from_parts(
        junction: &Junction,
        distribution: &SeparationDistribution,
        seal: &ReciprocatingSeal,
        settings: &DragSettings,
    ) -> Self {
        let Junction::Leaking(j) = junction else {
            return Self::sealed(seal);
        };
        let i = separation_integral(distribution, j.u_c, settings);
        Self::from_integral(j, i, seal)
    }

    /// The coefficients from the junction and a given `I` (module docs for the formulas).
    pub fn from_integral(j: &CriticalJunction, integral_i: f64, seal: &ReciprocatingSeal) -> Self {
        let eta = seal.viscosity;
        let alpha = seal.shape_factor;
        let u_c = j.u_c;
        let (l_a, l_b) = seal.side_widths();
        let m = crate::fluid::junction_conductance(u_c, alpha, eta);
        // J = I/u_c². For u_c ≲ 1e-154 m (a junction within rounding of sealing) J overflows
        // while M underflows to 0; B saturates at f64::MAX so that M·B stays 0, not NaN.
        let j_int = integral_i / (u_c * u_c);
        let saturate = |b: f64| if b.is_nan() { 0.0 } else { b.min(f64::MAX) };
        let (b_a, b_b) = (
            saturate(6.0 * l_a * eta * j_int),
            saturate(6.0 * l_b * eta * j_int),
        );
        let beta = 0.5 * alpha * integral_i;
        // E u_c³/(6 L η λ_c I), in the form that underflows gracefully for tiny u_c
        let denominator = 6.0 * seal.seal.width * eta * j.lambda_c * integral_i;
        let speed_bound = if denominator > 0.0 {
            seal.material.youngs_modulus * u_c.powi(3) / denominator
        } else {
            f64::INFINITY
        };
        DragCoefficients {
            junction: Junction::Leaking(*j),
            geometry: seal.seal.geometry(),
            viscosity: eta,
            m,
            b_a,
            b_b,
            integral_i,
            beta,
            film_thickness: beta * u_c,
            speed_bound,
        }
    }

    /// No percolating channel: no leak, no drag (speed bound +∞).
    pub fn sealed(seal: &ReciprocatingSeal) -> Self {
        DragCoefficients {
            junction: Junction::Sealed,
            geometry: seal.seal.geometry(),
            viscosity: seal.viscosity,
            m: 0.0,
            b_a: 0.0,
            b_b: 0.0,
            integral_i: 0.0,
            beta: 0.0,
            film_thickness: 0.0,
            speed_bound: f64::INFINITY,
        }
    }

    /// `B_a + B_b = 6 L_x η J` \[Pa·s/m\] (docs/model.md §3.4's B).
    pub fn b(&self) -> f64 {
        self.b_a + self.b_b
    }

    /// `(L_y/L_x) M` \[m³/(Pa·s)\]: the static conductance of the whole seal.
    pub fn conductance(&self) -> f64 {
        self.geometry.cells() * self.m
    }

    /// The pressure-driven part `(L_y/L_x) M ΔP` \[m³/s\] at `pressure_difference` ΔP \[Pa\]:
    /// the static leak law ([`Fluid::leak_rate`]) through the junction's conductance M.
    pub fn static_leak_rate(&self, pressure_difference: f64) -> f64 {
        let fluid = Fluid {
            viscosity: self.viscosity,
            pressure_difference,
            law: crate::fluid::ViscosityLaw::Constant,
            gas: None,
        };
        fluid.leak_rate(
            self.geometry,
            Conduction::Uniform {
                conductance: self.m,
            },
        )
    }
}

/// `Q̇ = (L_y/L_x) M [ΔP + (B_a + B_b) v0]` \[m³/s\] (PY08 eq. 13 with eq. 3's cell count, the
/// `M(C_a − C_b)` term dropped as in the paper). `pressure_difference = P_a − P_b` \[Pa\];
/// `speed = v0` \[m/s\], positive when the countersurface moves from the high-pressure side
/// towards the low-pressure side (out-stroke). Positive Q̇ flows from a to b.
pub fn leak_rate(coeffs: &DragCoefficients, pressure_difference: f64, speed: f64) -> f64 {
    coeffs.static_leak_rate(pressure_difference) + drag_leak_rate(coeffs, speed)
}

/// The drag term alone, `(L_y/L_x) M (B_a + B_b) v0 = L_y d v0` \[m³/s\] (PY08 eqs. 14–15):
/// the leak of a wiper (ΔP = 0). Sign convention as [`leak_rate`].
pub fn drag_leak_rate(coeffs: &DragCoefficients, speed: f64) -> f64 {
    let g = coeffs.conductance();
    if g == 0.0 {
        return 0.0;
    }
    g * coeffs.b() * speed
}

/// Volumes of one reciprocating cycle (out-stroke then in-stroke), all in m³, counted positive
/// from the high-pressure side a to the low-pressure side b.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StrokeCycle {
    /// Cycle time `S/v_out + S/v_in` \[s\].
    pub period: f64,
    /// Passed a → b during the out-stroke (v0 = +v_out, duration S/v_out):
    /// `(L_y/L_x) M [ΔP S/v_out + B S]`.
    pub out_volume: f64,
    /// Passed a → b during the in-stroke (v0 = −v_in, duration S/v_in):
    /// `(L_y/L_x) M [ΔP S/v_in − B S]` — negative when the drag carries more back than ΔP
    /// pushes out.
    pub in_volume: f64,
    /// `out_volume + in_volume`: the net leak per cycle.
    pub net_volume: f64,
    /// The static leak over the same time, `(L_y/L_x) M ΔP · period`.
    pub static_volume: f64,
    /// The drag volume of one stroke, `(L_y/L_x) M B S = L_y d S` (carried out on the
    /// out-stroke, back on the in-stroke).
    pub drag_volume: f64,
    /// Both speeds are below [`DragCoefficients::speed_bound`] (necessary, not sufficient:
    /// the theory needs them *much* smaller).
    pub within_speed_bound: bool,
}

/// One stroke cycle of length `stroke` S \[m\] at out-stroke speed `out_speed` and in-stroke
/// speed `in_speed` (magnitudes, > 0) \[m/s\] against `pressure_difference` ΔP \[Pa\].
///
/// In the linear theory of PY08 §8 the drag volumes of the two strokes are equal and opposite
/// (`±L_y d S`, independent of speed), so `net_volume = static_volume` exactly: the
/// reciprocating motion carries fluid out and back but pumps none on balance. A net
/// (in- or out-) pumping needs what the paper leaves out (speed-dependent contact, different
/// pressure profiles on the two strokes, starvation of the in-stroke). `None` unless the
/// speeds are positive and finite and the stroke is non-negative and finite.
pub fn stroke_cycle(
    coeffs: &DragCoefficients,
    pressure_difference: f64,
    out_speed: f64,
    in_speed: f64,
    stroke: f64,
) -> Option<StrokeCycle> {
    // the static part of Q̇ = (L_y/L_x) M [ΔP + B v0] over the cycle, plus the drag film
    stroke_cycle_from(
        coeffs.static_leak_rate(pressure_difference),
        coeffs,
        out_speed,
        in_speed,
        stroke,
    )
}

/// `∫_{u_c}^∞ P(u) du`: the probability of a separation above `u_c` (closed form per folded
/// Gaussian, `½[erfc((u_c−μ)/σ√2) + erfc((u_c+μ)/σ√2)]`; point masses count when
/// `center > u_c`). The normalisation of P̃.
pub fn probability_above(distribution: &SeparationDistribution, u_c: f64) -> f64 {
    distribution
        .components()
        .iter()
        .map(|g| {
            let tail = if g.width > 0.0 {
                let k = FRAC_1_SQRT_2 / g.width;
                0.5 * (erfc((u_c - g.center) * k) + erfc((u_c + g.center) * k))
            } else if g.center > u_c {
                1.0
            } else {
                0.0
            };
            g.weight * tail
        })
        .sum()
}

/// `I = ∫_{u_c}^∞ u_c² P̃(u)/u² du`, `P̃ = P/∫_{u_c}^∞ P` (PY08 eqs. 10 and 17), ∈ \[0, 1\].
///
/// The numerator is integrated in `x = ln(u/u_c)` (integrand `u_c ρ(u) e^{−x}`, ρ the
/// continuous density), from 0 to the largest `center + 8·width` of the components that reach
/// above u_c, with Gauss–Legendre panels of at most `settings.panel_width` and
/// `settings.order` points — fine panels where the integrand is largest, at u_c, and the
/// Gaussians of P(u) have widths `h_rms(ζ) ≳ u_c` there, so the rule is smooth-integrand
/// accurate (convergence is tested by refinement). Point masses above u_c add
/// `w u_c²/center²` exactly. The denominator is [`probability_above`]. Returns 0 when
/// `u_c ≤ 0` or no probability lies above u_c.
pub fn separation_integral(
    distribution: &SeparationDistribution,
    u_c: f64,
    settings: &DragSettings,
) -> f64 {
    if !(u_c > 0.0 && u_c.is_finite()) {
        return 0.0;
    }
    let norm = probability_above(distribution, u_c);
    if !(norm > 0.0 && norm.is_finite()) {
        return 0.0;
    }
    let mut point_part = 0.0;
    // (component, lowest and highest x = ln(u/u_c) where it is above e^{−32} of its peak)
    let mut active = Vec::new();
    let mut u_max = u_c;
    for g in distribution.components() {
        if g.weight <= 0.0 {
            continue;
        }
        if g.width <= 0.0 {
            if g.center > u_c {
                point_part += g.weight * (u_c / g.center).powi(2);
            }
            continue;
        }
        let top = g.center + SIGMAS * g.width;
        if top > u_c {
            u_max = u_max.max(top);
            let bottom = (g.center - SIGMAS * g.width).max(u_c);
            active.push((*g, (bottom / u_c).ln(), (top / u_c).ln()));
        }
    }
    let mut continuous = 0.0;
    let x_max = (u_max / u_c).ln();
    if x_max > 0.0 && !active.is_empty() {
        let (nodes, weights) = gauss_legendre(settings.order.max(1));
        let width = if settings.panel_width > 0.0 {
            settings.panel_width
        } else {
            DragSettings::default().panel_width
        };
        let panels = (x_max / width).ceil().max(1.0) as usize;
        let h = x_max / panels as f64;
        let inv_sqrt_2pi = 1.0 / (2.0 * PI).sqrt();
        let mut window = Vec::with_capacity(active.len());
        for p in 0..panels {
            let mid = (p as f64 + 0.5) * h;
            // Only the components within 8 widths of the panel contribute (the others are
            // below e^{−32} of their peak there, and so is their folded image: u + center ≥
            // |u − center|).
            let (x_a, x_b) = (mid - 0.5 * h, mid + 0.5 * h);
            window.clear();
            window.extend(
                active
                    .iter()
                    .filter(|(_, lo, hi)| *lo <= x_b && *hi >= x_a)
                    .map(|(g, _, _)| {
                        let inv = 1.0 / g.width;
                        (g.weight * inv, inv, g.center)
                    }),
            );
            if window.is_empty() {
                continue;
            }
            for (node, w) in nodes.iter().zip(&weights) {
                let x = mid + 0.5 * h * node;
                let u = u_c * x.exp();
                let rho: f64 = window
                    .iter()
                    .map(|&(weight_over_width, inv, center)| {
                        let (a, b) = ((u - center) * inv, (u + center) * inv);
                        weight_over_width * ((-0.5 * a * a).exp() + (-0.5 * b * b).exp())
                    })
                    .sum::<f64>()
                    * inv_sqrt_2pi;
                // u_c² ρ(u)/u² du = u_c² ρ(u)/u dx = u_c ρ(u) e^{−x} dx
                continuous += 0.5 * h * w * u_c * rho * (-x).exp();
            }
        }
    }
    (continuous + point_part) / norm
}

/// The motion of the countersurface in a scenario (`[motion]`): constant sliding or a stroke
/// cycle. Speeds are magnitudes \[m/s\], lengths in m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Motion {
    /// Constant sliding at `speed` ≥ 0 in the out-stroke direction (`v0 = +speed`: the
    /// countersurface drags fluid from the high-pressure side to the low-pressure side).
    Steady { speed: f64 },
    /// A reciprocating cycle: the out-stroke over `stroke` at `v0 = +out_speed`, then the
    /// in-stroke back at `v0 = −in_speed` (all > 0).
    Stroke {
        stroke: f64,
        out_speed: f64,
        in_speed: f64,
    },
}

/// A scenario's `[motion]`: the motion, where along the width the critical junction sits
/// ([`ReciprocatingSeal::junction_position`]) and the inlet pressure gradients of a rod seal
/// ([`ihl`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionSpec {
    pub motion: Motion,
    /// `L_a/L_x` ∈ (0, 1) (½ for a symmetric seal); changes only the split `B_a`/`B_b`.
    pub junction_position: f64,
    /// The inlet gradients given in the scenario (`inlet_gradient_out`/`_in`, or the steepest
    /// flanks of `contact_profile`); `None`: an O-ring's are estimated at each state
    /// ([`InletGradients::oring_estimate`]), a flat seal has none (low-speed theory only).
    pub gradients: Option<(InletGradients, GradientSource)>,
}

/// What the inverse-hydrodynamic part of [`MotionSpec::evaluate`] needs of a state, all SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IhlInput {
    /// The inlet gradients and their source (`None`: no IHL, the low-speed theory at any
    /// speed). [`MotionSpec::gradients_for`] picks them.
    pub gradients: Option<(InletGradients, GradientSource)>,
    /// Viscosity η \[Pa·s\].
    pub viscosity: f64,
    /// Sealing length L_y = π D \[m\].
    pub sealing_length: f64,
    /// rms roughness σ of the contact \[m\] (film parameter Λ = h*/σ).
    pub roughness: f64,
}

/// The motion quantities of one seal state (one pressure of `sealsim leak`, one time of
/// `sealsim run`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionPoint {
    /// The drag term `L_y d v` \[m³/s\] at [`MotionSpec::drag_speed`] (the sliding speed, or the
    /// out-stroke speed of a cycle). 0 when sealed.
    pub drag_leak_rate: f64,
    /// The film `d = β u_c` \[m\] the countersurface carries out (PY08 eq. 16). 0 when sealed.
    pub film_thickness: f64,
    /// The speed bound of PY08's second eq. 17 \[m/s\] (+∞ when sealed).
    pub speed_bound: f64,
    /// [`MotionSpec::fastest_speed`] exceeds [`Self::speed_bound`]: the drag pressure would open
    /// the critical constriction (hydrodynamic lift-off), which is not modelled.
    pub above_bound: bool,
    /// A stroke cycle's volumes (blended between the low-speed and IHL values, [`ihl`]);
    /// `None` for constant sliding.
    pub cycle: Option<StrokeCycle>,
    /// A stroke cycle with inlet gradients: the inverse-hydrodynamic films and volumes.
    pub ihl: Option<IhlCycle>,
    /// The IHL weights of the out- and in-stroke ([`ihl_weight`] at the onset
    /// `min(v_b, v_Λ)`; 0 without `ihl`).
    pub ihl_weights: (f64, f64),
    /// The speed regime (constant sliding: [`SpeedRegime::NoProfile`], the low-speed theory).
    pub regime: SpeedRegime,
}

impl MotionPoint {
    /// The cycle-averaged leak rate `net_volume/period` \[m³/s\] of a stroke cycle in which the
    /// IHL has weight; `None` otherwise (constant sliding, or the low-speed regime, where it
    /// is the static leak rate).
    pub fn cycle_mean_leak_rate(&self) -> Option<f64> {
        let c = self.cycle?;
        let (a, b) = self.ihl_weights;
        (self.ihl.is_some() && (a > 0.0 || b > 0.0) && c.period > 0.0)
            .then(|| c.net_volume / c.period)
    }
}

/// The low-speed cycle `low` blended with the IHL cycle: per stroke
/// `V = (1 − w) V_low + w V_ihl` (out: `V_ihl = out_volume`; in: `−back_volume`), then the
/// starvation cap `in ≥ −out` (the in-stroke cannot return more than the out-stroke carried;
/// never active in the low-speed cycle, where `out + in = Q̇_s · period ≥ 0`).
fn blend(low: StrokeCycle, ihl: Option<&IhlCycle>, weights: (f64, f64)) -> StrokeCycle {
    let Some(ihl) = ihl else {
        return low;
    };
    let (w_out, w_in) = weights;
    if w_out == 0.0 && w_in == 0.0 {
        return low;
    }
    let out_volume = (1.0 - w_out) * low.out_volume + w_out * ihl.out_volume;
    let in_volume = ((1.0 - w_in) * low.in_volume - w_in * ihl.back_volume).max(-out_volume);
    StrokeCycle {
        out_volume,
        in_volume,
        net_volume: out_volume + in_volume,
        ..low
    }
}

impl MotionSpec {
    /// Constant sliding at `speed` with the junction at the centre.
    pub fn steady(speed: f64) -> Self {
        MotionSpec {
            motion: Motion::Steady { speed },
            junction_position: 0.5,
            gradients: None,
        }
    }

    /// The inlet gradients of a state: the scenario's, else an O-ring's estimate from its
    /// energised peak `peak` \[Pa\], contact width \[m\] and ΔP \[Pa\] (`oring`), else none.
    pub fn gradients_for(
        &self,
        oring: Option<(f64, f64, f64)>,
    ) -> Option<(InletGradients, GradientSource)> {
        self.gradients.or_else(|| {
            let (peak, width, dp) = oring?;
            InletGradients::oring_estimate(peak, width, dp)
                .map(|g| (g, GradientSource::ORingEstimate))
        })
    }

    /// The speed the drag term is evaluated at \[m/s\]: the sliding speed, or a cycle's
    /// out-stroke speed (the direction that carries fluid out).
    pub fn drag_speed(&self) -> f64 {
        match self.motion {
            Motion::Steady { speed } => speed,
            Motion::Stroke { out_speed, .. } => out_speed,
        }
    }

    /// The largest speed of the motion \[m/s\], the one checked against the speed bound.
    pub fn fastest_speed(&self) -> f64 {
        match self.motion {
            Motion::Steady { speed } => speed,
            Motion::Stroke {
                out_speed,
                in_speed,
                ..
            } => out_speed.max(in_speed),
        }
    }

    /// The cycle time `S/v_out + S/v_in` \[s\] of a stroke cycle; `None` for constant sliding.
    pub fn period(&self) -> Option<f64> {
        match self.motion {
            Motion::Steady { .. } => None,
            Motion::Stroke {
                stroke,
                out_speed,
                in_speed,
            } => Some(stroke / out_speed + stroke / in_speed),
        }
    }

    /// Whether the motion is a stroke cycle.
    pub fn is_stroke(&self) -> bool {
        matches!(self.motion, Motion::Stroke { .. })
    }

    /// The drag speed that adds to the time-averaged leak rate: the sliding speed for
    /// constant sliding; 0 for a stroke cycle, whose drag volumes cancel over a cycle in the
    /// linear theory ([`stroke_cycle`]).
    pub fn mean_drag_speed(&self) -> f64 {
        match self.motion {
            Motion::Steady { speed } => speed,
            Motion::Stroke { .. } => 0.0,
        }
    }

    /// The [`ReciprocatingSeal`] of a flat contact under this motion.
    pub fn seal(
        &self,
        material: Elastic,
        seal: FlatSeal,
        viscosity: f64,
        shape_factor: f64,
    ) -> ReciprocatingSeal {
        ReciprocatingSeal {
            material,
            seal,
            viscosity,
            shape_factor,
            junction_position: self.junction_position,
        }
    }

    /// The motion quantities of a state with drag coefficients `coeffs` and static
    /// (pressure-driven) leak rate `static_leak_rate` \[m³/s\]. The stroke volumes take the
    /// given static leak rate (the level's, or an O-ring's strips in series) and the drag of
    /// `coeffs` ([`stroke_cycle_from`]).
    ///
    /// A stroke cycle with inlet gradients (`ihl.gradients`) also gets the IHL cycle
    /// ([`IhlCycle`]) and its volumes blended with the low-speed ones by the weights
    /// [`ihl_weight`] of each stroke's speed against the speed bound (docs/model.md §3.4.1).
    /// Constant sliding stays with the low-speed theory.
    pub fn evaluate(
        &self,
        coeffs: &DragCoefficients,
        static_leak_rate: f64,
        ihl: &IhlInput,
    ) -> MotionPoint {
        let (cycle, ihl_cycle, weights, regime) = match self.motion {
            Motion::Steady { .. } => (None, None, (0.0, 0.0), SpeedRegime::NoProfile),
            Motion::Stroke {
                stroke,
                out_speed,
                in_speed,
            } => {
                let low = stroke_cycle_from(static_leak_rate, coeffs, out_speed, in_speed, stroke);
                match ihl.gradients {
                    None => (low, None, (0.0, 0.0), SpeedRegime::NoProfile),
                    Some((gradients, source)) => {
                        let cycle = IhlCycle::new(
                            gradients,
                            source,
                            ihl.viscosity,
                            ihl.sealing_length,
                            stroke,
                            out_speed,
                            in_speed,
                            ihl.roughness,
                        );
                        let (v_out, v_in) = cycle.film_onset_speeds;
                        let weights = (
                            ihl_weight(out_speed, transition_onset(coeffs.speed_bound, v_out)),
                            ihl_weight(in_speed, transition_onset(coeffs.speed_bound, v_in)),
                        );
                        let regime = match weights {
                            (a, b) if a == 0.0 && b == 0.0 => SpeedRegime::LowSpeed,
                            (a, b) if a == 1.0 && b == 1.0 => SpeedRegime::Ihl,
                            _ => SpeedRegime::Transition,
                        };
                        (
                            low.map(|c| blend(c, Some(&cycle), weights)),
                            Some(cycle),
                            weights,
                            regime,
                        )
                    }
                }
            }
        };
        MotionPoint {
            drag_leak_rate: drag_leak_rate(coeffs, self.drag_speed()),
            film_thickness: coeffs.film_thickness,
            speed_bound: coeffs.speed_bound,
            above_bound: self.fastest_speed() > coeffs.speed_bound,
            cycle,
            ihl: ihl_cycle,
            ihl_weights: weights,
            regime,
        }
    }

    /// `point` with only a fraction of its channels carrying flow: the drag (rate, film,
    /// stroke volume) scaled by `drag_scale` and the stroke volumes rebuilt on the static leak
    /// rate `static_leak_rate` (used by the life loop under particle clogging). The speed
    /// bound, the IHL films (which do not flow through the channels) and the weights are
    /// unchanged; the volumes are blended again.
    pub fn rescale(
        &self,
        point: MotionPoint,
        static_leak_rate: f64,
        drag_scale: f64,
    ) -> MotionPoint {
        let cycle = match (self.motion, point.cycle) {
            (
                Motion::Stroke {
                    stroke,
                    out_speed,
                    in_speed,
                },
                Some(c),
            ) => Some(blend(
                assemble_cycle(
                    static_leak_rate,
                    c.drag_volume * drag_scale,
                    stroke / out_speed,
                    stroke / in_speed,
                    c.within_speed_bound,
                ),
                point.ihl.as_ref(),
                point.ihl_weights,
            )),
            _ => None,
        };
        MotionPoint {
            drag_leak_rate: point.drag_leak_rate * drag_scale,
            film_thickness: point.film_thickness * drag_scale,
            cycle,
            ..point
        }
    }
}

/// [`stroke_cycle`] with the static part given as a leak rate `static_leak_rate` [m³/s]
/// instead of `conductance · ΔP` (for a static leak computed elsewhere: another fidelity level,
/// or an O-ring's strips in series), the drag from `coeffs`:
/// `out = Q̇_s S/v_out + L_y d S`, `in = Q̇_s S/v_in − L_y d S`, `net = Q̇_s · period`.
/// For a flat seal at the critical-junction level, `Q̇_s = (L_y/L_x) M ΔP` and this is
/// [`stroke_cycle`]. `None` on the same invalid input.
pub fn stroke_cycle_from(
    static_leak_rate: f64,
    coeffs: &DragCoefficients,
    out_speed: f64,
    in_speed: f64,
    stroke: f64,
) -> Option<StrokeCycle> {
    let ok = |v: f64| v > 0.0 && v.is_finite();
    if !(ok(out_speed) && ok(in_speed) && stroke >= 0.0 && stroke.is_finite()) {
        return None;
    }
    Some(assemble_cycle(
        static_leak_rate,
        drag_leak_rate(coeffs, 1.0) * stroke,
        stroke / out_speed,
        stroke / in_speed,
        out_speed < coeffs.speed_bound && in_speed < coeffs.speed_bound,
    ))
}

/// The cycle of a static leak rate \[m³/s\] and a drag volume per stroke \[m³\], with the
/// durations of the two strokes \[s\].
fn assemble_cycle(
    static_leak_rate: f64,
    drag_volume: f64,
    t_out: f64,
    t_in: f64,
    within_speed_bound: bool,
) -> StrokeCycle {
    let out_volume = static_leak_rate * t_out + drag_volume;
    let in_volume = static_leak_rate * t_in - drag_volume;
    let period = t_out + t_in;
    StrokeCycle {
        period,
        out_volume,
        in_volume,
        net_volume: out_volume + in_volume,
        static_volume: static_leak_rate * period,
        drag_volume,
        within_speed_bound,
    }
}

/// Nodes of [`DragTable`].
const DRAG_TABLE_NODES: usize = 40;
/// [`DragTable`] starts at `s = 1e-4 s_seal`.
const DRAG_TABLE_LOW: f64 = 1e-4;
/// [`DragTable`] ends at `s = (1 − 0.03) s_seal`, like the contact table.
const DRAG_TABLE_UPPER_GAP: f64 = 0.03;

/// The integral I of a surface against the reduced pressure, tabulated once (for the life
/// run, which needs it at every time step; P(u) costs ≈ 3–4 ms per pressure).
///
/// Near the sealing pressure I is not smooth in ln s: it falls from ≈ 0.06 at 0.7 s_seal to
/// 5e-6 at 0.96 s_seal, like u_c itself (for u_c much below the widths of P(u),
/// `I ≈ u_c ρ(0)/∫_{u_c}^∞ P`). What is smooth is `ln(I/u_c)`, so that is tabulated, on the
/// contact table's grid variable `logit(s/s_seal)` ([`crate::contact::ContactTable`]), with
/// 40 nodes from `1e-4 s_seal` to `0.97 s_seal` and 4-point cubic
/// interpolation; a lookup multiplies by the u_c of the junction it is given. Below the table
/// the direct evaluation answers; above it (within 3 % of sealing, where the film
/// `d = (α/2) I u_c` is below 1e-20 m) `I/u_c` is held at its last value. The interpolation
/// error against the direct evaluation is measured in tests/model/motion.rs.
#[derive(Debug, Clone)]
pub struct DragTable {
    contact: PerssonContact,
    settings: DragSettings,
    s_seal: f64,
    /// `ln(I/u_c [1/m])` against `logit(s/s_seal)`; `None` when fewer than 4 nodes leak.
    grid: Option<UniformCubic>,
}

impl DragTable {
    /// Tabulates I for the surface of `contact` (two threads take alternate nodes; each node
    /// is one exact junction, one P(u) and one I).
    pub fn build(contact: &PerssonContact, settings: DragSettings) -> Self {
        let s_seal = contact.sealing_reduced_pressure();
        let lo = logit(DRAG_TABLE_LOW);
        let hi = logit(1.0 - DRAG_TABLE_UPPER_GAP);
        let n = DRAG_TABLE_NODES;
        let h = (hi - lo) / (n - 1) as f64;
        let node = |i: usize| -> Option<f64> {
            let s = s_seal * logistic(lo + h * i as f64);
            let j = *contact.critical_junction(s).leaking()?;
            let p = SeparationDistribution::persson(contact, s, settings.distribution);
            let i = separation_integral(&p, j.u_c, &settings);
            let v = (i / j.u_c).ln();
            v.is_finite().then_some(v)
        };
        let values: Vec<f64> = crate::math::map_on_two_threads(n, node)
            .into_iter()
            .map_while(|v| v)
            .collect();
        let grid = (values.len() >= 4).then(|| UniformCubic::new(lo, h, values));
        DragTable {
            contact: contact.clone(),
            settings,
            s_seal,
            grid,
        }
    }

    /// The range of `s = P0/E*` the table covers (`None`: no table, every lookup is direct).
    pub fn range(&self) -> Option<(f64, f64)> {
        let (a, b) = self.grid.as_ref()?.range();
        Some((self.s_seal * logistic(a), self.s_seal * logistic(b)))
    }

    /// I at reduced pressure `s`, for the critical junction `junction` there (module docs of
    /// [`DragTable`]); in [0, 1].
    pub fn integral(&self, s: f64, junction: &CriticalJunction) -> f64 {
        let v = logit(s / self.s_seal);
        let ln_ratio = match &self.grid {
            Some(g) if v >= g.range().0 => g.eval(v.min(g.range().1)),
            _ => {
                let p =
                    SeparationDistribution::persson(&self.contact, s, self.settings.distribution);
                return separation_integral(&p, junction.u_c, &self.settings);
            }
        };
        let i = junction.u_c * ln_ratio.exp();
        if i.is_nan() { 0.0 } else { i.clamp(0.0, 1.0) }
    }

    /// The drag coefficients of `seal` at reduced pressure `s` with the critical junction
    /// `junction` there (e.g. from a contact table): [`DragCoefficients::from_integral`] with
    /// the tabulated I.
    pub fn coefficients(
        &self,
        s: f64,
        junction: &Junction,
        seal: &ReciprocatingSeal,
    ) -> DragCoefficients {
        match junction {
            Junction::Leaking(j) => DragCoefficients::from_integral(j, self.integral(s, j), seal),
            Junction::Sealed => DragCoefficients::sealed(seal),
        }
    }
}
