//! The fluid pressure inside the interface (docs/model.md §3.6).
//!
//! Across the contact width the fluid pressure p_f(x) falls from ΔP at the inlet to 0 at the
//! outlet (gauge pressures over the outlet). The asperities at x carry the contact pressure minus
//! the fluid pressure, `e(x) = p_c(x) − p_f(x)`, so the local conductance per unit width is
//! σ(e(x)), not σ(p_c(x)) (Lorenz & Persson, EPJE 32 (2010) 281, recalled). The flux per unit
//! length across the flow, q \[m²/s\], is the same through every strip:
//!
//! `q = −σ(p_c(x) − p_f(x)) dp_f/dx`,  p_f(0) = ΔP, p_f(L_x) = 0.
//!
//! * Uniform contact pressure P0: separable, `q L_x = ∫_0^{ΔP} σ(P0 − p) dp = ∫_{P0−ΔP}^{P0} σ(e) de`
//!   ([`uniform`], a quadrature in ln e).
//! * A profile (Hertz): the fluid enters the contact freely (an open gap, e ≤ 0, carries no
//!   pressure drop) up to where p_c = ΔP, then follows the ODE; q is found by shooting
//!   ([`hertz`]: RK4 in a stretched angle, Illinois iteration on ln q).
//!
//! Either way the result is handed to the one leak law as a [`Conduction`]: a uniform effective
//! conductance `σ_eff = q L_x/ΔP`, or a series resistance `R = ΔP/q`, so that
//! [`crate::fluid::Fluid::leak_rate`] gives `Q̇ = L_y q`. As ΔP/P0 → 0 both reduce to the
//! strips in series at the contact pressure (docs/model.md §3.2). Where the fluid pressure reaches
//! the contact pressure everywhere (ΔP ≥ the peak contact pressure) the seal opens: lift-off, an
//! outcome of the model.

use crate::fluid::Conduction;
use crate::math::quadrature::{composite, gauss_legendre};
use std::f64::consts::FRAC_PI_2;

/// What the interface does under the fluid pressure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InterfaceFlow {
    /// It conducts: the leak law's input.
    Conducting(Conduction),
    /// No channel percolates anywhere the fluid pressure leaves the contact pressure high
    /// enough: no flow.
    Sealed,
    /// The fluid pressure reaches the contact pressure across the whole width: the seal opens.
    LiftOff,
}

/// Accuracy settings of the interface-pressure solutions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InterfaceSettings {
    /// Uniform pressure: Gauss–Legendre panels per unit of ln e (8 points each).
    pub panels_per_log_unit: f64,
    /// Profile: RK4 steps across the width.
    pub steps: usize,
    /// Profile: relative tolerance of the flux.
    pub tolerance: f64,
    /// Uniform pressure: extra breaks of the e-quadrature at `P0 − ΔP·4^{−k}`, k = 1…n,
    /// towards the outlet end e = P0 — for a rarefied gas against a vacuum, whose σ(e)·p goes
    /// like const − c p^0.4 there (docs/model.md §3.10); 0 otherwise.
    pub outlet_breaks: usize,
    /// Uniform pressure: the asperity pressure \[Pa\] at and above which σ is 0 — the strips
    /// whose critical gap is no wider than a molecule of the fluid (docs/model.md §3.6, §8.1;
    /// `ContactPath::molecular_cut` times E*). σ jumps to 0 there, and the quadrature ends at
    /// it, so that it integrates the smooth part only. ∞ (the default): none.
    pub ceiling: f64,
}

impl Default for InterfaceSettings {
    fn default() -> Self {
        InterfaceSettings {
            panels_per_log_unit: 4.0,
            steps: 3200,
            tolerance: 1e-13,
            outlet_breaks: 0,
            ceiling: f64::INFINITY,
        }
    }
}

/// Uniform contact pressure `contact_pressure` P0 \[Pa\] under `pressure_difference` ΔP \[Pa\],
/// local conductance per unit width `sigma(e)` \[m³/(Pa·s)\] at asperity pressure e \[Pa\]:
/// `σ_eff = (1/ΔP) ∫_{P0−ΔP}^{P0} σ(e) de` (σ(P0) at ΔP = 0); lift-off when ΔP ≥ P0. With a
/// [`InterfaceSettings::ceiling`] e_m below P0 the integral ends there (σ = 0 above it):
/// `(1/ΔP) ∫_{P0−ΔP}^{min(P0, e_m)} σ(e) de`, sealed when e_m ≤ P0 − ΔP.
pub fn uniform(
    sigma: &dyn Fn(f64) -> f64,
    contact_pressure: f64,
    pressure_difference: f64,
    settings: &InterfaceSettings,
) -> InterfaceFlow {
    let (p0, dp) = (contact_pressure, pressure_difference);
    if dp >= p0 {
        return InterfaceFlow::LiftOff;
    }
    let lo = p0 - dp;
    // the strips at and above the ceiling conduct nothing
    let top = p0.min(settings.ceiling);
    // (at ΔP = 0, lo = top = P0 below the ceiling: σ(P0), not sealed)
    if settings.ceiling <= lo {
        return InterfaceFlow::Sealed;
    }
    // below ΔP/P0 ≈ 1e-8 the mean over [P0 − ΔP, P0] is σ(P0) to rounding
    let conductance = if dp <= 1e-8 * p0 && top >= p0 {
        sigma(p0 - 0.5 * dp)
    } else if settings.outlet_breaks > 0 {
        // graded towards e = P0: the integral as a sum over [lo, b1], [b1, b2], …, [bn, P0]
        let mut edges = vec![lo];
        edges.extend(
            (1..=settings.outlet_breaks)
                .map(|k| p0 - dp * 0.25f64.powi(k as i32))
                .filter(|&b| b < top),
        );
        edges.push(top);
        edges
            .windows(2)
            .filter(|w| w[1] > w[0])
            .map(|w| mean_over(sigma, w[0], w[1], settings) * (w[1] - w[0]))
            .sum::<f64>()
            / dp
    } else if top < p0 {
        mean_over(sigma, lo, top, settings) * (top - lo) / dp
    } else {
        mean_over(sigma, lo, p0, settings)
    };
    if conductance > 0.0 && conductance.is_finite() {
        InterfaceFlow::Conducting(Conduction::Uniform { conductance })
    } else {
        InterfaceFlow::Sealed
    }
}

/// The uniform contact at the onset of lift-off, as the conduction the leak law takes at the
/// actual ΔP \[Pa\]: the flux with the fluid pressure in the interface at its largest, P0,
/// `q L_x = ∫_0^{P0} σ(e) de` (up to the [`InterfaceSettings::ceiling`] if that is lower), so
/// `σ_eff = (1/ΔP) ∫_0^{P0} σ(e) de`. Once lifted off the seal is
/// open and its leak is not the interface's any more: this is the last value the model gives, a
/// lower bound (docs/model.md §3.6).
pub fn uniform_onset(
    sigma: &dyn Fn(f64) -> f64,
    contact_pressure: f64,
    pressure_difference: f64,
    settings: &InterfaceSettings,
) -> Conduction {
    let p0 = contact_pressure;
    // ∫_0^{P0}: the integrand σ(e)·e of the log rule vanishes as e → 0; start 1e-12 P0 below;
    // end at the ceiling (σ = 0 above it)
    let floor = 1e-12 * p0;
    let top = p0.min(settings.ceiling);
    let integral = if top > floor {
        mean_over(sigma, floor, top, settings) * (top - floor)
    } else {
        0.0
    };
    Conduction::Uniform {
        conductance: integral / pressure_difference,
    }
}

/// `(1/(b − a)) ∫_a^b σ(e) de` for 0 < a < b, composite Gauss–Legendre in ln e (the integrand
/// σ(e)·e is smooth in ln e down to e → 0, where σ grows like ln³(1/e)).
fn mean_over(sigma: &dyn Fn(f64) -> f64, a: f64, b: f64, settings: &InterfaceSettings) -> f64 {
    let (nodes, weights) = gauss_legendre(8);
    let breaks = [a.ln(), b.ln()];
    let width = 1.0 / settings.panels_per_log_unit;
    let total: f64 = composite(&breaks, width, &nodes, &weights)
        .map(|(l, w)| {
            let e = l.exp();
            w * e * sigma(e)
        })
        .sum();
    total / (b - a)
}

/// A Hertz-shaped contact-pressure profile lifted by a uniform energisation:
/// `p_c(x) = offset + peak √(1 − (2x/b)²)` over `width` b \[m\] (pressures in Pa, gauge over
/// the outlet). `offset = k_e ΔP` for a pressure-energised O-ring (docs/model.md §6.3), 0
/// otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzContact {
    /// The ring's own (squeeze) peak \[Pa\].
    pub peak: f64,
    /// The uniform energisation added to it \[Pa\].
    pub offset: f64,
    /// Contact width b \[m\].
    pub width: f64,
}

/// A solved Hertz interface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzSolution {
    /// What the interface does.
    pub flow: InterfaceFlow,
    /// The fluid pressure at the profile's peak (x = 0) \[Pa\]: the asperities there carry
    /// `offset + peak − centre_fluid_pressure`. ΔP when lifted off or sealed (no flow lowers
    /// the inlet pressure before the sealing strip).
    pub centre_fluid_pressure: f64,
    /// `κ = q R0/ΔP` (≥ 1), the flux over its no-fluid-pressure value: a start for the next
    /// solve of a nearby state (`None` when there is no flow).
    pub flux_ratio: Option<f64>,
}

/// The Hertz contact `contact` under ΔP = `pressure_difference` \[Pa\]: the flux q by shooting;
/// the result as the series resistance `R = ΔP/q` \[Pa·s/m²\]. Lift-off when ΔP ≥ offset + peak;
/// sealed when σ(offset + peak − ΔP) = 0 (the centre seals even with the whole fluid pressure
/// relieving it). `start`: a flux ratio κ from a nearby state ([`HertzSolution::flux_ratio`]),
/// which the secant iteration starts from (the result does not depend on it beyond the
/// tolerance).
pub fn hertz(
    sigma: &dyn Fn(f64) -> f64,
    contact: HertzContact,
    pressure_difference: f64,
    settings: &InterfaceSettings,
    start: Option<f64>,
) -> HertzSolution {
    hertz_warm(
        &|e, _| sigma(e),
        contact,
        pressure_difference,
        settings,
        start.map(|k| Start::Ratio(k, 1.0)),
    )
    .0
}

/// [`hertz`] for a local conductance that also depends on the local fluid pressure:
/// `sigma(e, p_f)` \[m³/(Pa·s)\] at asperity pressure e and gauge fluid pressure p_f \[Pa\]. A
/// gas (docs/model.md §3.9–§3.10) passes its conductance weighed by the local density,
/// `σ(e, λ(P_b + p_f)) (P_b + p_f)/p̄`, each constriction rarefied at the local pressure: the
/// flux q is then the volume flux at the mean pressure p̄, conserved along the profile (the
/// mass flux over ρ(p̄)), and the series resistance ΔP/q goes to the gas law as it is. Needs σ
/// finite where p_f → 0 (a rarefied gas is; the continuum law against a vacuum is not, and is
/// then resolved only as well as the steps near the outlet allow).
pub fn hertz_local(
    sigma: &dyn Fn(f64, f64) -> f64,
    contact: HertzContact,
    pressure_difference: f64,
    settings: &InterfaceSettings,
) -> HertzSolution {
    hertz_warm(sigma, contact, pressure_difference, settings, None).0
}

/// Where the shooting of [`hertz_warm`] starts.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Start {
    /// The flux ratio κ of a nearby solve, and the secant slope of g in ln q it ended with.
    Ratio(f64, f64),
    /// A predicted flux q \[m²/s\], and a slope.
    Flux(f64, f64),
}

/// [`hertz`] from a [`Start`]; also returns the slope the secant ended with and the flux (the
/// next nearby solve's start).
fn hertz_warm(
    sigma: &dyn Fn(f64, f64) -> f64,
    contact: HertzContact,
    pressure_difference: f64,
    settings: &InterfaceSettings,
    start: Option<Start>,
) -> (HertzSolution, Option<(f64, f64)>) {
    let dp = pressure_difference;
    let HertzContact {
        peak,
        offset,
        width,
    } = contact;
    let unsolved = |flow| HertzSolution {
        flow,
        centre_fluid_pressure: dp,
        flux_ratio: None,
    };
    if dp >= peak + offset {
        return (unsolved(InterfaceFlow::LiftOff), None);
    }
    if sigma(peak + offset - dp, dp) <= 0.0 {
        return (unsolved(InterfaceFlow::Sealed), None);
    }
    // the outlet edge: an energised profile ends on a step from k_e ΔP to 0; across it the fluid
    // pressure can fall without resistance down to where the asperities seal (as the uniform
    // contact's separable solution does), so the outlet condition is p_f = max(0, k_e ΔP − e_s)
    // (the sealing asperity pressure taken at the outlet's fluid pressure, 0)
    let outlet = if offset > 0.0 && sigma(offset, 0.0) <= 0.0 {
        offset - sealing_pressure(&|e| sigma(e, 0.0), peak + offset - dp, offset)
    } else {
        0.0
    };
    // x = (b/2) sin θ; the contact is open (p_c ≤ ΔP) for θ < θ_a
    let theta_a = -((dp - offset) / peak).clamp(0.0, 1.0).acos();
    let shot = Shot {
        sigma,
        peak,
        offset,
        half_width: 0.5 * width,
        dp,
        outlet,
        theta_a,
        // even: the reference resistances use Simpson's rule on the same steps
        steps: settings.steps.max(8).next_multiple_of(2),
    };
    // the no-fluid-pressure resistance R0 (the ΔP → 0 limit), or — where the dry contact seals
    // (an outlet step above e_s) — the resistance with the whole ΔP relieving every strip, a
    // lower bound: the flux's reference and the start of the iteration
    let r0 = shot.reference_resistance(0.0);
    if dp <= 0.0 {
        let solution = if r0.is_finite() && r0 > 0.0 {
            HertzSolution {
                flow: InterfaceFlow::Conducting(Conduction::Series { resistance: r0 }),
                centre_fluid_pressure: 0.0,
                flux_ratio: Some(1.0),
            }
        } else {
            unsolved(InterfaceFlow::Sealed)
        };
        return (solution, None);
    }
    let reference = if r0.is_finite() {
        r0
    } else {
        shot.reference_resistance(dp)
    };
    if !(reference.is_finite() && reference > 0.0) {
        return (unsolved(InterfaceFlow::Sealed), None);
    }
    match shot
        .flux(reference, start, settings.tolerance)
        .filter(|(q, _)| *q > 0.0 && q.is_finite())
    {
        Some((q, slope)) => (
            HertzSolution {
                flow: InterfaceFlow::Conducting(Conduction::Series { resistance: dp / q }),
                centre_fluid_pressure: shot.centre_pressure(q),
                flux_ratio: Some(q * reference / (dp - outlet)),
            },
            Some((q, slope)),
        ),
        None => (unsolved(InterfaceFlow::Sealed), None),
    }
}

/// The asperity pressure at which `sigma` stops conducting, between `conducting` (σ > 0) and
/// `sealed` (σ = 0) \[Pa\]: bisection to 1e-13 relative (σ decreases with e).
fn sealing_pressure(sigma: &dyn Fn(f64) -> f64, conducting: f64, sealed: f64) -> f64 {
    // the cap is never reached: the bracket reaches its last bit within ~2100 halvings
    let (_, hi) = sealsim_math::roots::bisect(
        conducting,
        sealed,
        usize::MAX,
        |lo, hi| hi - lo <= 1e-13 * hi,
        |e| sigma(e) > 0.0,
    );
    hi
}

/// Hertz solutions of one run, interpolated in the reduced peak and pressure difference.
///
/// The local conductance of the asperity contact depends on the asperity pressure only through
/// e/E* (Persson's theory scales with P/E*): `σ(e) = σ̂(e/E*)`. With every pressure scaled by E*
/// the profile's ODE keeps its form and `q = E* q̂`, so the series resistance ΔP/q and the fluid
/// pressure at the peak over ΔP depend only on the reduced peak p̂ = p_max/E*, the reduced
/// ΔP̂ = ΔP/E* (the energisation k_e ΔP̂ follows from it) and — in ξ = x/b — not on b: `q b = ΔP
/// F(p̂, ΔP̂)`; with σ ∝ 1/η, `q b η` does not depend on the viscosity either. `ln(q b η)` and the
/// centre's fluid-pressure ratio are smooth in ln p̂ and ln ΔP̂ away from lift-off and sealing,
/// and a life run visits a narrow band of them thousands of times (temperature cycles,
/// bisection of failure times): this memo solves [`hertz`] at nodes `(ln p̂, ln ΔP̂) = (i h, j
/// h_ΔP)` as they are needed and interpolates with 4-point cubics in each (Lagrange on the
/// uniform grid). When E* stays the same over the run (every asperity modulus but `follow`) ΔP̂ is
/// one value and the ΔP axis is not interpolated ([`Self::new`]). Where a node does not conduct
/// (near lift-off or sealing) it answers with the direct solve. While every call shares one p̂
/// (a fixed squeeze under `follow`: only ΔP̂ moves) the nodes form one column at that p̂, and a
/// new node's shooting starts from the flux extrapolated from the two nodes below it (and their
/// secant slope): 7 shots a node instead of 16. Otherwise it starts from the flux ratio of the
/// node solved before it. To the root tolerance the value does not depend on the start; bit for
/// bit it follows the run's own, deterministic order.
#[derive(Debug)]
pub struct HertzMemo {
    /// Node spacing h in ln p̂.
    spacing: f64,
    /// Node spacing in ln ΔP̂ (`None`: ΔP̂ is the same in every call, one node row).
    pressure_spacing: Option<f64>,
    /// `(i, j) → (ln(q b η), p_f(centre)/ΔP)` (`None`: not conducting there).
    nodes: std::cell::RefCell<std::collections::HashMap<(i64, i64), Option<Node>>>,
    /// The node solved last (the start of the next, a neighbour usually) and the one before.
    previous: std::cell::Cell<Option<Solved>>,
    warm: std::cell::Cell<Option<Solved>>,
    /// With an interpolated ΔP axis: `None` before the first call, `Some(Some(p̂))` while every
    /// call had that p̂ (nodes in one column, key [`COLUMN`]), `Some(None)` once one did not.
    column: std::cell::Cell<Option<Option<f64>>>,
}

/// A memoised node: `(ln(q b η), p_f(centre)/ΔP)`.
type Node = (f64, f64);

/// A node solution as the start of the next node's shooting.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Solved {
    /// Its row j (ΔP̂ axis).
    row: i64,
    /// ln q̂ \[ln(m²/s)\].
    ln_flux: f64,
    /// The flux ratio κ.
    kappa: f64,
    /// The secant slope its shooting ended with.
    slope: f64,
}

/// The key of the single column of nodes at a shared p̂ ([`HertzMemo::solve`]).
const COLUMN: i64 = i64::MIN;

/// Relative difference of p̂ under which a call shares the column's p̂: the flux changes by
/// at most this times d ln F/d ln p̂ (≈ 10), far below the shooting's error.
const COLUMN_TOLERANCE: f64 = 1e-12;

/// Node spacing of [`HertzMemo`] in ln p̂ (0.8 %): measured ≤ 4.7e-7 relative difference of
/// the flux from the direct solves (tests/model/interface.rs; 2.9e-7 over a 30-year EPDM cycle
/// run, 2.7e-8 at 1/512 with 4× the nodes — slower than h⁴ because σ from the contact table is
/// only continuous at its own nodes), below the 8.4e-7 of the 128-step shooting itself.
pub const MEMO_SPACING: f64 = 1.0 / 128.0;

/// Node spacing of [`HertzMemo`] in ln ΔP̂ when E* changes over the run (`follow`): measured
/// 4.7e-7 against direct solves with E* over a factor 20 (tests/model/interface.rs), 1.6e-6 at
/// 1/16 — the flux is nearly proportional to ΔP̂, so four times the ln p̂ spacing suffices.
pub const MEMO_PRESSURE_SPACING: f64 = 1.0 / 24.0;

/// Lagrange weights on the nodes −1, 0, 1, 2 at `t ∈ [0, 1)`.
fn cubic_weights(t: f64) -> [f64; 4] {
    [
        -t * (t - 1.0) * (t - 2.0) / 6.0,
        (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0,
        -(t + 1.0) * t * (t - 2.0) / 2.0,
        (t + 1.0) * t * (t - 1.0) / 6.0,
    ]
}

impl HertzMemo {
    /// A memo with nodes `spacing` apart in ln p̂, and `pressure_spacing` apart in ln ΔP̂ when
    /// E* (hence ΔP̂) changes between calls (`None`: it does not).
    pub fn new(spacing: f64, pressure_spacing: Option<f64>) -> Self {
        HertzMemo {
            spacing,
            pressure_spacing,
            nodes: Default::default(),
            previous: Default::default(),
            warm: Default::default(),
            column: Default::default(),
        }
    }

    /// [`hertz`] at peak `peak` \[Pa\], offset, `width` \[m\], ΔP, with the local conductance
    /// `sigma_hat(e/E*)` at viscosity `viscosity` \[Pa·s\] and the asperity contact's `e_star`
    /// \[Pa\] (`sigma_hat` must not change between calls except by the viscosity; without a
    /// pressure spacing neither may ΔP/E*): interpolated between memoised nodes, or solved
    /// directly.
    #[allow(clippy::too_many_arguments)]
    pub fn solve(
        &self,
        sigma_hat: &dyn Fn(f64) -> f64,
        e_star: f64,
        contact: HertzContact,
        viscosity: f64,
        pressure_difference: f64,
        settings: &InterfaceSettings,
    ) -> HertzSolution {
        let sigma = |e: f64| sigma_hat(e / e_star);
        let direct = || hertz(&sigma, contact, pressure_difference, settings, None);
        if !(contact.peak > 0.0 && contact.width > 0.0 && pressure_difference > 0.0 && e_star > 0.0)
        {
            return direct();
        }
        let dp_hat = pressure_difference / e_star;
        let peak_hat = contact.peak / e_star;
        // the p̂ axis: the one column of a p̂ every call so far shared (to 1e-12: a fixed squeeze
        // under `follow`, where only ΔP̂ moves), else four interpolated columns
        let column = match self.column.get() {
            None if self.pressure_spacing.is_some() => {
                self.column.set(Some(Some(peak_hat)));
                Some(peak_hat)
            }
            Some(Some(c)) if (peak_hat / c - 1.0).abs() <= COLUMN_TOLERANCE => Some(c),
            Some(Some(_)) => {
                self.column.set(Some(None));
                None
            }
            _ => None,
        };
        let (i0, wx, columns) = match column {
            Some(_) => (COLUMN, [1.0, 0.0, 0.0, 0.0], 1),
            None => {
                let x = peak_hat.ln() / self.spacing;
                let i0 = x.floor() as i64 - 1;
                (i0, cubic_weights(x - (i0 + 1) as f64), 4)
            }
        };
        // the ΔP axis: four interpolated rows, or the one row of a constant ΔP̂
        let (j0, wy, rows) = match self.pressure_spacing {
            Some(h) => {
                let y = dp_hat.ln() / h;
                let j0 = y.floor() as i64 - 1;
                (j0, cubic_weights(y - (j0 + 1) as f64), 4)
            }
            None => (0, [1.0, 0.0, 0.0, 0.0], 1),
        };
        let offset_ratio = contact.offset / pressure_difference;
        let mut ln_flux = 0.0;
        let mut centre = 0.0;
        for (dj, wj) in wy.iter().enumerate().take(rows) {
            let j = j0 + dj as i64;
            let node_dp = match self.pressure_spacing {
                Some(h) => (j as f64 * h).exp(),
                None => dp_hat,
            };
            for (di, wi) in wx.iter().enumerate().take(columns) {
                let i = i0 + di as i64;
                let node = *self.nodes.borrow_mut().entry((i, j)).or_insert_with(|| {
                    let at = HertzContact {
                        peak: match column {
                            Some(c) => c,
                            None => (i as f64 * self.spacing).exp(),
                        },
                        offset: offset_ratio * node_dp,
                        width: 1.0,
                    };
                    // in one column, the flux extrapolated from the two nodes below; else the
                    // flux ratio of the node solved last
                    let start = match (column, self.warm.get(), self.previous.get()) {
                        (Some(_), Some(w), Some(p))
                            if (p.row - w.row).abs() == 1 && j - p.row == p.row - w.row =>
                        {
                            let step = p.ln_flux - w.ln_flux;
                            Some(Start::Flux((p.ln_flux + step).exp(), p.slope))
                        }
                        (_, _, Some(p)) => Some(Start::Ratio(p.kappa, p.slope)),
                        _ => None,
                    };
                    let (solved, end) =
                        hertz_warm(&|e, _| sigma_hat(e), at, node_dp, settings, start);
                    if let (Some(kappa), Some((q, slope))) = (solved.flux_ratio, end) {
                        self.warm.set(self.previous.get());
                        self.previous.set(Some(Solved {
                            row: j,
                            ln_flux: q.ln(),
                            kappa,
                            slope,
                        }));
                    }
                    match solved.flow {
                        InterfaceFlow::Conducting(Conduction::Series { resistance })
                            if resistance.is_finite() && resistance > 0.0 =>
                        {
                            // q̂ b η with q̂ = ΔP̂/R̂: the flux of the scaled problem; ln q b η =
                            // ln q̂ b η + ln E*, added below
                            Some((
                                (node_dp / resistance * viscosity).ln(),
                                solved.centre_fluid_pressure / node_dp,
                            ))
                        }
                        _ => None,
                    }
                });
                let Some((flux, ratio)) = node else {
                    return direct();
                };
                ln_flux += wi * wj * flux;
                centre += wi * wj * ratio;
            }
        }
        let q = (ln_flux + e_star.ln()).exp() / (viscosity * contact.width);
        HertzSolution {
            flow: InterfaceFlow::Conducting(Conduction::Series {
                resistance: pressure_difference / q,
            }),
            centre_fluid_pressure: (centre * pressure_difference).clamp(0.0, pressure_difference),
            flux_ratio: None,
        }
    }
}

/// One shooting problem across a Hertz profile.
struct Shot<'a> {
    /// σ(e, p_f): the local conductance at asperity pressure e and fluid pressure p_f.
    sigma: &'a dyn Fn(f64, f64) -> f64,
    peak: f64,
    offset: f64,
    half_width: f64,
    dp: f64,
    /// The fluid pressure the integration must reach at the outlet (0, or the pressure above
    /// which an energised profile's outlet step lets the fluid out).
    outlet: f64,
    theta_a: f64,
    steps: usize,
}

impl Shot<'_> {
    /// Resistance density 1/σ(e, p_f) \[Pa·s/m³\] at fluid pressure `p`: 0 where the contact is
    /// open (e ≤ 0), ∞ where sealed.
    fn resistivity(&self, e: f64, p: f64) -> f64 {
        if e <= 0.0 {
            return 0.0;
        }
        let s = (self.sigma)(e, p.max(0.0));
        if s > 0.0 { 1.0 / s } else { f64::INFINITY }
    }

    /// θ(t) = θ_a + (π/2 − θ_a) t², clustering steps at the inlet end of the contact, where the
    /// asperity pressure rises from 0; and dθ/dt.
    fn angle(&self, t: f64) -> (f64, f64) {
        let span = FRAC_PI_2 - self.theta_a;
        (self.theta_a + span * t * t, 2.0 * span * t)
    }

    /// dp_f/dt at `t` for flux `q`.
    fn slope(&self, t: f64, p: f64, q: f64) -> f64 {
        let (theta, dtheta) = self.angle(t);
        let c = theta.cos().max(0.0);
        let r = self.resistivity(self.offset + self.peak * c - p, p);
        if r == 0.0 {
            return 0.0;
        }
        -q * r * self.half_width * c * dtheta
    }

    /// p_f at `t_end` for flux `q` (RK4 in t on the grid of `steps` over [0, 1], the last step
    /// partial); −∞ once a strip seals.
    fn pressure_at(&self, q: f64, t_end: f64) -> f64 {
        let h = 1.0 / self.steps as f64;
        let mut p = self.dp;
        let mut t = 0.0;
        while t < t_end {
            let step = h.min(t_end - t);
            let k1 = self.slope(t, p, q);
            let k2 = self.slope(t + 0.5 * step, p + 0.5 * step * k1, q);
            let k3 = self.slope(t + 0.5 * step, p + 0.5 * step * k2, q);
            let k4 = self.slope(t + step, p + step * k3, q);
            p += step / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            if !p.is_finite() {
                return f64::NEG_INFINITY;
            }
            // whole steps land on k·h exactly (no drift over thousands of steps)
            t = if step == h {
                ((t / h).round() + 1.0) * h
            } else {
                t_end
            };
        }
        p
    }

    /// p_f at the outlet for flux `q`.
    fn outlet_pressure(&self, q: f64) -> f64 {
        self.pressure_at(q, 1.0)
    }

    /// p_f at the profile's peak (θ = 0) for flux `q`.
    fn centre_pressure(&self, q: f64) -> f64 {
        let t_centre = (-self.theta_a / (FRAC_PI_2 - self.theta_a)).sqrt();
        self.pressure_at(q, t_centre).max(0.0)
    }

    /// `∫ dx/σ(p_c(x) − relief)` over the part of the width beyond θ_a, by Simpson's rule on
    /// the same steps: with `relief` = 0 the no-fluid-pressure resistance R0 (the ΔP → 0
    /// resistance), with ΔP a lower bound of the resistance.
    fn reference_resistance(&self, relief: f64) -> f64 {
        let h = 1.0 / self.steps as f64;
        // Simpson on the stretched variable (the integrand vanishes at t = 0 with dθ/dt)
        let f = |t: f64| {
            let (theta, dtheta) = self.angle(t);
            let c = theta.cos().max(0.0);
            self.resistivity(self.offset + self.peak * c - relief, relief)
                * self.half_width
                * c
                * dtheta
        };
        let mut total = f(0.0) + f(1.0);
        for k in 1..self.steps {
            total += if k % 2 == 1 { 4.0 } else { 2.0 } * f(k as f64 * h);
        }
        total * h / 3.0
    }

    /// The flux with p_f(outlet) = the outlet condition P_out (0 unless an energised outlet step),
    /// to relative `tolerance` in q.
    ///
    /// The unknown is x = ln q and the function `g(x) = ln(ΔP − p_f(outlet)) − ln(ΔP − P_out)`,
    /// the log of the pressure drop the flux q needs over the one available: increasing in x, with slope 1 where the
    /// fluid pressure hardly changes the asperity pressure (drop ≈ q R0), steeper as it does, and
    /// +∞ beyond the flux at which a strip seals. The root is found by secant steps, the first
    /// with slope 1, kept inside the bracket the signs of g establish (bisection when a step
    /// leaves it or g is infinite): from a nearby state's κ (`start`) two or three evaluations.
    /// The flux q and the final secant slope, from `start`.
    fn flux(&self, reference: f64, start: Option<Start>, tolerance: f64) -> Option<(f64, f64)> {
        let available = self.dp - self.outlet;
        let g = |x: f64| {
            let drop = self.dp - self.outlet_pressure(x.exp());
            if drop.is_nan() {
                f64::INFINITY
            } else {
                (drop / available).ln()
            }
        };
        let (x0, slope) = match start {
            None => ((available / reference).ln(), 1.0),
            Some(Start::Ratio(kappa, slope)) => ((available / reference).ln() + kappa.ln(), slope),
            Some(Start::Flux(q, slope)) if q > 0.0 && q.is_finite() => (q.ln(), slope),
            Some(Start::Flux(_, slope)) => ((available / reference).ln(), slope),
        };
        Self::bracketed_secant(&g, x0, slope, tolerance).map(|(x, s)| (x.exp(), s))
    }

    /// The root of an increasing `g` from `x0`: secant steps (the first with slope `slope0`, 1
    /// from a cold start), each kept inside the bracket [lo, hi] of the points where g < 0 and
    /// g > 0 (or +∞) seen so far, and bisection of the bracket when a step would leave it;
    /// `None` if no root in 200 steps. Returns the root and the last secant slope.
    fn bracketed_secant(
        g: &dyn Fn(f64) -> f64,
        x0: f64,
        slope0: f64,
        tolerance: f64,
    ) -> Option<(f64, f64)> {
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let (mut x, mut gx) = (x0, g(x0));
        let mut slope = if slope0 > 0.0 && slope0.is_finite() {
            slope0
        } else {
            1.0
        };
        for _ in 0..200 {
            if gx == 0.0 {
                return Some((x, slope));
            }
            if gx < 0.0 {
                lo = lo.max(x);
            } else {
                hi = hi.min(x);
            }
            if hi - lo <= tolerance {
                return Some((0.5 * (lo + hi), slope));
            }
            let mut next = if gx.is_finite() {
                x - gx / slope
            } else {
                f64::NAN
            };
            if !(next > lo && next < hi) {
                // outside the bracket (or no finite secant): bisect it, or march out of a
                // one-sided one by factors of e
                next = match (lo.is_finite(), hi.is_finite()) {
                    (true, true) => 0.5 * (lo + hi),
                    (true, false) => lo + 1.0,
                    (false, true) => hi - 1.0,
                    (false, false) => return None,
                };
            }
            let g_next = g(next);
            if (next - x).abs() <= tolerance && g_next.is_finite() {
                return Some((next, slope));
            }
            if gx.is_finite() && g_next.is_finite() && g_next != gx {
                let s = (g_next - gx) / (next - x);
                slope = if s > 0.0 && s.is_finite() { s } else { 1.0 };
            }
            (x, gx) = (next, g_next);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// σ(e) = c (e_s − e)² for e < e_s: seals at e_s, smooth; ∫ closed form.
    fn quadratic(e: f64) -> f64 {
        let (c, e_s) = (1e-30, 2e6);
        if e < e_s { c * (e_s - e).powi(2) } else { 0.0 }
    }

    fn uniform_sigma(flow: InterfaceFlow) -> f64 {
        match flow {
            InterfaceFlow::Conducting(Conduction::Uniform { conductance }) => conductance,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn uniform_integral_matches_its_closed_form() {
        // (1/ΔP) ∫_{P0−ΔP}^{P0} c (e_s − e)² de = c [(e_s − P0 + ΔP)³ − (e_s − P0)³]/(3 ΔP)
        let (p0, dp) = (1e6, 4e5);
        let s = uniform_sigma(uniform(&quadratic, p0, dp, &InterfaceSettings::default()));
        let exact = 1e-30 * ((2e6 - p0 + dp).powi(3) - (2e6 - p0).powi(3)) / (3.0 * dp);
        assert!((s / exact - 1.0).abs() < 1e-12, "{s} {exact}");
    }

    #[test]
    fn uniform_limits_lift_off_and_sealing() {
        let set = InterfaceSettings::default();
        let p0 = 1e6;
        let s = uniform_sigma(uniform(&quadratic, p0, 1e-3, &set));
        assert!((s / quadratic(p0) - 1.0).abs() < 1e-9);
        assert!(matches!(
            uniform(&quadratic, p0, p0 * (1.0 - 1e-12), &set),
            InterfaceFlow::Conducting(_)
        ));
        assert_eq!(uniform(&quadratic, p0, p0, &set), InterfaceFlow::LiftOff);
        assert_eq!(uniform(&quadratic, 3e6, 0.5e6, &set), InterfaceFlow::Sealed);
    }

    /// Flux of the Hertz solution (Q̇ per unit length = ΔP/R).
    fn hertz_flux(peak: f64, dp: f64, steps: usize) -> f64 {
        let set = InterfaceSettings {
            steps,
            ..InterfaceSettings::default()
        };
        let contact = HertzContact {
            peak,
            offset: 0.0,
            width: 1e-3,
        };
        match hertz(&quadratic, contact, dp, &set, None).flow {
            InterfaceFlow::Conducting(Conduction::Series { resistance }) => dp / resistance,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn hertz_shooting_converges_and_is_monotone_in_the_pressure() {
        let peak = 1.5e6;
        let mut last = 0.0;
        for dp in [1e3, 1e4, 1e5, 3e5, 6e5, 1e6, 1.4e6] {
            let q = hertz_flux(peak, dp, 800);
            let q2 = hertz_flux(peak, dp, 1600);
            assert!((q2 / q - 1.0).abs() < 1e-9, "ΔP = {dp}: {q} vs {q2}");
            assert!(q > last, "flux must rise with ΔP");
            last = q;
        }
        let set = InterfaceSettings::default();
        assert_eq!(
            hertz(
                &quadratic,
                HertzContact {
                    peak,
                    offset: 0.0,
                    width: 1e-3
                },
                peak,
                &set,
                None
            )
            .flow,
            InterfaceFlow::LiftOff
        );
    }

    #[test]
    fn hertz_at_small_pressure_is_the_series_resistance() {
        // ΔP → 0: R → ∫ dx/σ(p_c(x)) = (b/2) ∫ cos θ dθ / σ(peak cos θ), here by a fine
        // Gauss–Legendre rule in θ (independent of the shooting's RK4 and stretching)
        let (peak, b) = (1.5e6, 1e-3);
        let (x, w) = gauss_legendre(64);
        let series: f64 = x
            .iter()
            .zip(&w)
            .map(|(xi, wi)| {
                let theta = FRAC_PI_2 * xi;
                wi * FRAC_PI_2 * theta.cos() / quadratic(peak * theta.cos())
            })
            .sum::<f64>()
            * 0.5
            * b;
        let dp = 1e-4;
        let q = hertz_flux(peak, dp, 1600);
        assert!(
            (dp / q / series - 1.0).abs() < 1e-8,
            "{} vs {series}",
            dp / q
        );
    }
}
