//! Particle clogging inside the life loop (docs/model.md §7): the constrictions a particle meets
//! on its way to the critical one and its survival to it (straining) or the reach (sieving), the
//! entry gap of a snapshot, the open fraction, the detours and the entry cake applied to a
//! snapshot, and the integration of the arrivals over one internal step.
// `!(x > 0.0)` is meant: it also rejects NaN
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use std::cell::RefCell;
use std::collections::HashMap;

use super::{Mechanics, SealState, Simulator, Snapshot, events};
use crate::clogging::{
    ArrivalDoses, CAKE_POROSITY, CAKE_WEDGE_SLOPE, CaptureLaw, Constrictions, Contamination,
    SIZE_NODES, SizeNode, cake_resistance_in_wedge, effective_threshold, survivals,
};
use crate::contact::{Junction, PerssonContact};

/// The largest number of octaves upstream of the critical constriction, ζc/2, ζc/4, … above 1
/// (q1/q0 below 2^63).
const MAX_LEVELS: usize = 63;

/// The step in ln s of the grid of reduced pressures at which the constrictions are computed
/// (and between which they are interpolated): 0.002. On the shipped dirty-oil gasket it moves the
/// 30-year volume by 1e-5 and the open fraction by 7e-5 from the values at every pressure itself
/// (a step of 0.02: 0.4 % and 1.1 %).
const LN_S_STEP: f64 = 0.002;

/// Below this blocked share the detours are not computed: with r ∈ \[0, 1\] the leak
/// `Q̇_open [f + (1 − f) r]` is within 1e-12 of Q̇_open whatever r is (r = 1 is taken).
const NEGLIGIBLE_BLOCKED_SHARE: f64 = 1e-12;

/// What the clogging path of a run needs beyond the problem: the exact contact path on a
/// coarser quadrature, the nodes of the size distribution, and the last constrictions computed
/// (a flat seal at a constant load keeps one peak pressure).
pub(super) struct CloggingSetup {
    contact: PerssonContact,
    nodes: Vec<SizeNode>,
    /// The constrictions at the points of the pressure grid met so far (`None`: sealed there).
    grid: RefCell<HashMap<i64, Option<Levels>>>,
}

impl CloggingSetup {
    pub(super) fn new(contact: PerssonContact, contamination: &Contamination) -> Self {
        let mut nodes = contamination.size_distribution.nodes();
        nodes.truncate(SIZE_NODES);
        CloggingSetup {
            contact,
            nodes,
            grid: RefCell::new(HashMap::new()),
        }
    }
}

/// The critical constrictions and those upstream of them, in units of the exact path's u_c =
/// u1(ζc) (docs/model.md §7): the octaves from ζc/2 outwards, then the entry.
#[derive(Debug, Clone, Copy)]
struct Levels {
    critical: Constrictions,
    octaves: [Constrictions; MAX_LEVELS],
    count: usize,
    entry: Constrictions,
    /// ū(1) \[m\], the entry gap the cake sits against.
    entry_gap: f64,
}

impl Levels {
    /// The constrictions a particle passes before the critical one (octaves and entry; their
    /// order does not matter to the product of the survivals).
    fn upstream(&self) -> ([Constrictions; MAX_LEVELS + 1], usize) {
        let mut all = [self.entry; MAX_LEVELS + 1];
        all[..self.count].copy_from_slice(&self.octaves[..self.count]);
        (all, self.count + 1)
    }
}

/// Under straining, what the state carries: the particles that have arrived at the critical
/// level, by relative size, and the critical constrictions last seen (the open fraction of a
/// snapshot whose junction is sealed is reported with them).
#[derive(Debug, Clone, Default)]
pub(super) struct Straining {
    doses: ArrivalDoses,
    critical: Option<Constrictions>,
}

/// Under straining, what a snapshot holds of the capture law: the critical constrictions in
/// units of the level's own u_c (centre 1, spread h_rms(ζc)/u1(ζc)), each size node's survival
/// S(d/u_c) to them, and the solid volume and surface deposited upstream (depth filtration and
/// the entry) per unit volume of fluid.
#[derive(Debug, Clone, Copy)]
pub(super) struct Capture {
    /// Set from a leaking junction (false: the defaults below).
    known: bool,
    critical: Constrictions,
    survival: [f64; SIZE_NODES],
    /// \[m³/m³\]
    deposit_volume: f64,
    /// π Σ d² per volume \[1/m\]
    deposit_surface: f64,
}

impl Default for Capture {
    /// Nothing reaches the critical level (no leaking junction), nothing deposits.
    fn default() -> Self {
        Capture {
            known: false,
            critical: Constrictions {
                centre: 1.0,
                spread: 0.0,
            },
            survival: [0.0; SIZE_NODES],
            deposit_volume: 0.0,
            deposit_surface: 0.0,
        }
    }
}

impl Simulator<'_> {
    fn capture_law(&self) -> CaptureLaw {
        self.problem
            .contamination
            .as_ref()
            .map_or(CaptureLaw::Straining, |c| c.capture)
    }

    /// Sets what the capture law needs at the snapshot's peak strip (docs/model.md §7), all
    /// ratios on the clogging contact path scaled to the fidelity's own u_c:
    /// * sieving: the reach `d_reach = u_c · u1(ζ_r)/u1(ζc)`, ζ_r = max(ζc/2, 1), at least u_c;
    /// * straining: the critical constrictions (spread h_rms(ζc)/u1(ζc)), the constrictions
    ///   upstream — the octaves ζc/2^k > 1, centred at u1(ζ)/u1(ζc) with spread
    ///   h_rms(ζ)/u1(ζc), and the entry, centred at ū(1)/u1(ζc) with the whole roughness (on a
    ///   grid in ln s, [`Self::levels`]) — each size node's survival through them and the
    ///   volume deposited upstream;
    /// * both: the entry gap ū(1) the cake sits against.
    pub(super) fn with_reach(&self, mut snap: Snapshot) -> Snapshot {
        let (Some(setup), Junction::Leaking(j)) = (&self.clogging, snap.peak_junction) else {
            return snap;
        };
        let exact = &setup.contact;
        let s = snap.peak_reduced_pressure;
        let gap = |entry: f64| {
            if entry.is_finite() {
                entry.max(0.0)
            } else {
                0.0
            }
        };
        match self.capture_law() {
            CaptureLaw::Sieving => {
                snap.entry_gap = gap(exact.separation(1.0, s).mean);
                let u1c = exact.separation(j.zeta_c, s).u1();
                let u1r = exact.separation((0.5 * j.zeta_c).max(1.0), s).u1();
                let ratio = u1r / u1c;
                let ratio = if ratio.is_finite() {
                    ratio.max(1.0)
                } else {
                    1.0
                };
                snap.reach = snap.open_u_c * ratio;
            }
            CaptureLaw::Straining => {
                if let Some(levels) = self.levels(setup, s) {
                    snap.entry_gap = gap(levels.entry_gap);
                    snap.capture = self.capture(setup, &levels, snap.open_u_c);
                }
            }
        }
        snap
    }

    /// The constrictions at the peak reduced pressure `s`, interpolated linearly in ln s between
    /// the two neighbouring points of a grid of step [`LN_S_STEP`], each computed once at its own
    /// pressure ([`Self::levels_at`]; a level present at one end only is left out — it lies at
    /// ζ ≈ 1, where u1 diverges and nothing is caught). `None` where neither point leaks.
    fn levels(&self, setup: &CloggingSetup, s: f64) -> Option<Levels> {
        if !(s > 0.0 && s.is_finite()) {
            return None;
        }
        let x = s.ln() / LN_S_STEP;
        let k = x.floor();
        let t = x - k;
        let k = k as i64;
        let (a, b) = (self.levels_at(setup, k), self.levels_at(setup, k + 1));
        let (a, b) = match (a, b) {
            (Some(a), Some(b)) => (a, b),
            (Some(one), None) | (None, Some(one)) => return Some(one),
            (None, None) => return None,
        };
        let mix = |p: &Constrictions, q: &Constrictions| Constrictions {
            centre: p.centre + t * (q.centre - p.centre),
            spread: p.spread + t * (q.spread - p.spread),
        };
        let mut levels = Levels {
            critical: mix(&a.critical, &b.critical),
            entry: mix(&a.entry, &b.entry),
            entry_gap: a.entry_gap + t * (b.entry_gap - a.entry_gap),
            ..a
        };
        levels.count = a.count.min(b.count);
        for i in 0..levels.count {
            levels.octaves[i] = mix(&a.octaves[i], &b.octaves[i]);
        }
        Some(levels)
    }

    /// The constrictions at the grid's reduced pressure s = e^{k · LN_S_STEP} (computed once,
    /// then remembered): the critical magnification and u1(ζc) of the clogging path, the
    /// octaves ζc/2^k > 1 and the entry (docs/model.md §7).
    fn levels_at(&self, setup: &CloggingSetup, k: i64) -> Option<Levels> {
        if let Some(known) = setup.grid.borrow().get(&k) {
            return *known;
        }
        let s = (k as f64 * LN_S_STEP).exp();
        let exact = &setup.contact;
        let levels = exact.critical_magnification(s).and_then(|zeta_c| {
            let spectrum = exact.spectrum();
            let q0 = spectrum.q0();
            let u1c = exact.separation(zeta_c, s).u1();
            if !(u1c > 0.0 && u1c.is_finite()) {
                return None;
            }
            let relative = |x: f64| if x.is_finite() { x / u1c } else { f64::NAN };
            let critical = Constrictions {
                centre: 1.0,
                spread: relative(spectrum.rms_roughness_above(zeta_c * q0)).max(0.0),
            };
            // a level whose centre or spread is not a number captures nothing (u1 diverges as
            // ζ → 1, where no area comes out of contact)
            let usable =
                |c: &Constrictions| c.centre.is_finite() && c.spread.is_finite() && c.centre >= 0.0;
            let entry_gap = exact.separation(1.0, s).mean;
            let mut levels = Levels {
                critical,
                octaves: [critical; MAX_LEVELS],
                count: 0,
                entry: Constrictions {
                    centre: relative(entry_gap),
                    spread: relative(spectrum.rms_roughness()),
                },
                entry_gap,
            };
            let mut zeta = 0.5 * zeta_c;
            while zeta > 1.0 && levels.count < MAX_LEVELS {
                let level = Constrictions {
                    centre: relative(exact.separation(zeta, s).u1()),
                    spread: relative(spectrum.rms_roughness_above(zeta * q0)),
                };
                if !usable(&level) {
                    break;
                }
                levels.octaves[levels.count] = level;
                levels.count += 1;
                zeta *= 0.5;
            }
            usable(&levels.entry).then_some(levels)
        });
        setup.grid.borrow_mut().insert(k, levels);
        levels
    }

    /// Each size node's survival to the critical constrictions, S(d/u_c) with d the node's
    /// diameter and `u_c` the level's own critical gap, and the volume and surface of the
    /// particles that stop upstream, `n_p Σ (π/6 E[d³; node], π E[d²; node]) (1 − S)`.
    fn capture(&self, setup: &CloggingSetup, levels: &Levels, u_c: f64) -> Capture {
        let mut capture = Capture {
            known: true,
            critical: levels.critical,
            ..Capture::default()
        };
        let Some(c) = &self.problem.contamination else {
            return capture;
        };
        if !(u_c > 0.0) {
            return capture;
        }
        let (all, count) = levels.upstream();
        let upstream = &all[..count];
        let n = setup.nodes.len();
        let mut sizes = [0.0; SIZE_NODES];
        for (y, node) in sizes.iter_mut().zip(&setup.nodes) {
            *y = node.diameter / u_c;
        }
        survivals(upstream, &sizes[..n], &mut capture.survival[..n]);
        let (mut volume, mut surface) = (0.0, 0.0);
        for (node, s) in setup.nodes.iter().zip(&capture.survival) {
            volume += node.m3 * (1.0 - s);
            surface += node.m2 * (1.0 - s);
        }
        let n_p = c.number_concentration;
        capture.deposit_volume = n_p * std::f64::consts::PI / 6.0 * volume;
        capture.deposit_surface = n_p * std::f64::consts::PI * surface;
        capture
    }

    /// The open fraction f the state gives at the snapshot: the open share of the critical
    /// channels' flow (straining, [`ArrivalDoses::open_share`]) or e^{ln f} (sieving).
    fn open_fraction(&self, snap: &Snapshot, state: &Mechanics) -> f64 {
        match self.capture_law() {
            CaptureLaw::Sieving => {
                if state.clogged_shut {
                    0.0
                } else {
                    state.log_open_fraction.exp().clamp(0.0, 1.0)
                }
            }
            CaptureLaw::Straining => {
                let critical = match (snap.capture.known, state.straining.critical) {
                    (false, Some(last)) => last,
                    _ => snap.capture.critical,
                };
                state.straining.doses.open_share(&critical)
            }
        }
    }

    /// The leak rate of `open` (all channels open) with the state's open fraction f and cake:
    /// * the seal: without re-routing the blocked channels carry nothing and the rest are
    ///   unchanged, `Q̇_s = f Q̇_open`; with re-routing each blocked channel detours through
    ///   the next-narrowest constriction u_c(a_eff) ≤ u_c, `Q̇_s = Q̇_open [f + (1 − f) r]`,
    ///   `r = (u_c(s_peak, a_eff)/u_c(s_peak, a_c))³ ∈ [0, 1]` ([`effective_threshold`]), so
    ///   `f Q̇_open ≤ Q̇_s ≤ Q̇_open` by construction;
    /// * the cake in series: `Q̇ = Q̇_s/(1 + ε)`, `ε = R_cake Q̇_s/ΔP`
    ///   ([`cake_resistance_in_wedge`] from the entry gap ū(1) outwards), on the pressure-driven
    ///   part.
    ///
    /// The drag flows through the same channels: × f without re-routing, × f + (1 − f) r^{1/3}
    /// with it (the film scaling with the constriction height, d = β u_c).
    pub(super) fn clogged(&self, mut snap: Snapshot, state: &Mechanics) -> Snapshot {
        let f = self.open_fraction(&snap, state);
        snap.open_fraction = f;
        if f >= 1.0 && state.cake_volume <= 0.0 {
            return snap;
        }
        let reroute = self
            .problem
            .contamination
            .as_ref()
            .is_some_and(|c| c.reroute);
        let (scale, drag_scale) = if f >= 1.0 || (reroute && 1.0 - f <= NEGLIGIBLE_BLOCKED_SHARE) {
            (1.0, 1.0)
        } else if reroute {
            let (r, _) = self.reroute_ratio(snap.peak_reduced_pressure, f);
            let r = if r.is_finite() {
                r.clamp(0.0, 1.0)
            } else {
                0.0
            };
            (f + (1.0 - f) * r, f + (1.0 - f) * r.cbrt())
        } else {
            (f, f)
        };
        if scale <= 0.0 {
            snap.u_c = None;
            snap.peak_junction = Junction::Sealed;
        }
        let open_static = snap.open_static_leak_rate.unwrap_or(snap.open_leak_rate);
        let seal_static = (open_static * scale).max(0.0);
        snap.cake_factor = 1.0 + self.cake_ratio(&snap, state, seal_static);
        let static_rate = seal_static / snap.cake_factor;
        // The drag of constant sliding flows through the channels and scales with them; a
        // stroke cycle's film rides over the contact and does not (docs/model.md §7).
        let motion = match (&self.drag, snap.motion) {
            (Some((spec, _)), Some(m)) => {
                Some((spec.is_stroke(), spec.rescale(m, static_rate, drag_scale)))
            }
            _ => None,
        };
        snap.leak_rate = match motion {
            None => static_rate,
            Some((true, m)) => m.cycle_mean_leak_rate().unwrap_or(static_rate),
            Some((false, m)) => static_rate + m.drag_leak_rate,
        }
        .max(0.0);
        if !snap.leak_rate.is_finite() {
            snap.leak_rate = 0.0;
        }
        snap.motion = motion.map(|(_, m)| m);
        if snap.state == SealState::Leaking && snap.leak_rate <= 0.0 {
            snap.state = SealState::Sealed;
        }
        snap
    }

    /// ε = R_cake/R_seal = R_cake Q̇_s/ΔP for the seal's pressure-driven leak `seal_static`
    /// (0 without a cake, a pressure difference or an entry gap), the cake's Sauter diameter
    /// 6 V/A from the solid volume and surface deposited so far.
    fn cake_ratio(&self, snap: &Snapshot, state: &Mechanics, seal_static: f64) -> f64 {
        let p = self.problem;
        let (Some(_), dp) = (&p.contamination, snap.pressure_difference) else {
            return 0.0;
        };
        if !(state.cake_volume > 0.0
            && state.cake_surface > 0.0
            && dp > 0.0
            && snap.entry_gap > 0.0
            && seal_static > 0.0)
        {
            return 0.0;
        }
        let viscosity = p.fluid.viscosity_at(snap.temperature);
        let r = cake_resistance_in_wedge(
            viscosity,
            state.cake_volume,
            6.0 * state.cake_volume / state.cake_surface,
            CAKE_POROSITY,
            p.geometry.sealing_length(),
            snap.entry_gap,
            CAKE_WEDGE_SLOPE,
        );
        let eps = r * seal_static / dp;
        if eps.is_finite() { eps.max(0.0) } else { 0.0 }
    }

    /// The entry cake grows by what the fluid volume `volume` \[m³\] leaked over the step
    /// carried and lost upstream of the critical constrictions, at the step's end snapshot
    /// `after`: the particles that stopped in depth or at the entry (straining) or those larger
    /// than the reach (sieving).
    pub(super) fn deposit(
        &self,
        c: &Contamination,
        state: &mut Mechanics,
        after: &Snapshot,
        volume: f64,
    ) {
        let (v, a) = match c.capture {
            CaptureLaw::Sieving => (
                c.cake_volume_fraction(after.reach),
                c.cake_surface_fraction(after.reach),
            ),
            CaptureLaw::Straining => (after.capture.deposit_volume, after.capture.deposit_surface),
        };
        if v > 0.0 && a > 0.0 && volume > 0.0 {
            state.cake_volume += v * volume;
            state.cake_surface += a * volume;
        }
    }

    /// `((u_c(s, a_eff)/u_c(s, a_c))³, u_c(s, a_eff))` at the peak reduced pressure `s` and
    /// open fraction `f` (re-routing only; `(0, None)` when the junction seals).
    pub(super) fn reroute_ratio(&self, s: f64, f: f64) -> (f64, Option<f64>) {
        let Some(setup) = &self.clogging else {
            return (f, None);
        };
        let exact = &setup.contact;
        let a_c = self.problem.contact.percolation_threshold;
        let a_eff = effective_threshold(a_c, f);
        if a_eff.is_nan() || a_eff <= 0.0 {
            return (0.0, None);
        }
        let reference = self.reference_junction(exact, s);
        Self::ratio_against(exact, s, a_eff, reference)
    }

    /// `u_c(s, a_c)` on the re-routing quadrature, remembered for the last `s`.
    pub(super) fn reference_junction(&self, exact: &PerssonContact, s: f64) -> Option<f64> {
        if let Some((last, u)) = self.reference_memo.get()
            && last == s
        {
            return u;
        }
        let a_c = self.problem.contact.percolation_threshold;
        let u = exact
            .critical_junction_at_threshold(s, a_c)
            .leaking()
            .map(|j| j.u_c);
        self.reference_memo.set(Some((s, u)));
        u
    }

    /// `((u_c(s, a_eff)/u_ref)³, u_c(s, a_eff))` for a given reference `u_ref = u_c(s, a_c)`.
    pub(super) fn ratio_against(
        exact: &PerssonContact,
        s: f64,
        a_eff: f64,
        reference: Option<f64>,
    ) -> (f64, Option<f64>) {
        match (reference, exact.critical_junction_at_threshold(s, a_eff)) {
            (Some(r), Junction::Leaking(n)) if r > 0.0 => {
                ((n.u_c / r).powi(3).min(1.0), Some(n.u_c))
            }
            _ => (0.0, None),
        }
    }

    /// Integrates the clogging state over one internal step `[before, open]` (docs/model.md §7):
    /// the arrivals at the critical level (straining, [`Self::integrate_straining`]) or the
    /// open fraction's ODE (sieving, [`Self::integrate_sieving`]).
    pub(super) fn integrate_clogging(
        &self,
        c: &Contamination,
        state: &mut Mechanics,
        b: f64,
        before: &Snapshot,
        after: &Snapshot,
    ) {
        match c.capture {
            CaptureLaw::Sieving => self.integrate_sieving(c, state, b, before, after),
            CaptureLaw::Straining => self.integrate_straining(c, state, b, before, after),
        }
    }

    /// Straining over one internal step `[a, b]`: the arrivals of each size node at the
    /// critical level, `m = w ∫ n_p κ(t) S(t)/(1 + ε) dt`, with the channel flow per unit x³
    /// `κ = Q̇_open λ_c/(L_y E[x³])` (N_ch = L_y/λ_c channels carry Q̇_open, a channel of
    /// relative height x carries κ x³) interpolated as a power law in time between the step's
    /// ends ([`events::interpolate_power_law`]), the node's survival S linear in time between
    /// them and ε the cake's series ratio at the step's start. The integrals of a power law and
    /// of t times it are closed forms ([`events::integrate_power_law`]), so the step's dose is
    /// exact for that interpolation. It is recorded at the node's size relative to u_c at the
    /// step's middle (geometric), spread over the node's interval in ln d.
    fn integrate_straining(
        &self,
        c: &Contamination,
        state: &mut Mechanics,
        b: f64,
        before: &Snapshot,
        after: &Snapshot,
    ) {
        let a = state.time;
        let Some(setup) = &self.clogging else {
            return;
        };
        if !(b > a && c.number_concentration > 0.0) {
            return;
        }
        let length = self.problem.geometry.sealing_length();
        let kappa = |snap: &Snapshot| {
            let m3 = snap.capture.critical.mean_cube();
            let k = c.number_concentration * snap.open_leak_rate * snap.lambda_c
                / (length * m3 * before.cake_factor.max(1.0));
            if k.is_finite() { k.max(0.0) } else { 0.0 }
        };
        let (ka, kb) = (kappa(before), kappa(after));
        if ka <= 0.0 && kb <= 0.0 {
            return;
        }
        let total = events::integrate_power_law(a, ka, b, kb);
        // ∫ κ (t − a)/(b − a) dt, the weight of the step's end
        let moment = events::integrate_power_law(a, a * ka, b, b * kb);
        let late = ((moment - a * total) / (b - a)).clamp(0.0, total);
        let early = total - late;
        if !(total > 0.0 && total.is_finite()) {
            return;
        }
        let middle = if a > 0.0 { (a * b).sqrt() } else { 0.5 * b };
        let u_c = events::interpolate_power_law(a, before.open_u_c, b, after.open_u_c, middle);
        if !(u_c > 0.0) {
            return;
        }
        let ln_u = u_c.ln();
        let doses = &mut state.straining.doses;
        for (k, node) in setup.nodes.iter().enumerate() {
            let mass = node.weight
                * (before.capture.survival[k] * early + after.capture.survival[k] * late);
            if node.hi > node.lo {
                doses.add_spread(node.lo.ln() - ln_u, node.hi.ln() - ln_u, mass);
            } else {
                doses.add_point(node.diameter.ln() - ln_u, mass);
            }
        }
        if after.capture.known {
            state.straining.critical = Some(after.capture.critical);
        }
    }

    /// Sieving over one internal step `[before, open]`.
    ///
    /// The state is `y = ln f` (so f = e^y can never overshoot below 0, and a huge
    /// concentration drives y to −∞, f to 0, within the step), with
    /// `dy/dt = −n_p [F(d_reach) − F(u_c)] Q̇_open / (N_ch (1 + ε))`: the sieved particles
    /// arrive with the flow of the open critical channels, f Q̇_open/(1 + ε) (detours carry
    /// their own particles past the critical constrictions, not into them), N_ch = L_y/λ_c
    /// (λ_c of the critical junction at the peak strip with all channels open), ε the cake's
    /// series ratio at the step's start. The right side does not depend on f, with or without
    /// re-routing.
    ///
    /// Inside the step u_c, d_reach, Q̇_open and λ_c are interpolated as power laws in time
    /// between the step's ends ([`events::interpolate_power_law`]). Dopri5 (ode_solvers) with
    /// sparse output (only the end state is used), rtol = atol = the clogging tolerance on
    /// ln f (an absolute error in ln f is a relative error in f). If the integration fails
    /// every channel is taken as blocked from there on.
    fn integrate_sieving(
        &self,
        c: &Contamination,
        state: &mut Mechanics,
        b: f64,
        before: &Snapshot,
        after: &Snapshot,
    ) {
        let a = state.time;
        if state.clogged_shut || state.log_open_fraction == f64::NEG_INFINITY || b <= a {
            return;
        }
        let length = self.problem.geometry.sealing_length();
        let system = CloggingOde {
            contamination: c,
            a,
            b,
            before,
            after,
            length,
        };
        // Nothing captured at the ends: nothing in between either (u_c(t) is a power law,
        // hence monotone, and so is F(u_c(t))), the clean case costs no integration; the
        // midpoint is probed as well for safety.
        let probes = [a, 0.5 * (a + b), b];
        if probes
            .iter()
            .all(|&t| system.rate(t, state.log_open_fraction) == 0.0)
        {
            return;
        }
        let y0 = ode_solvers::Vector1::new(state.log_open_fraction);
        let tol = c.tolerance;
        let mut stepper = ode_solvers::Dopri5::new(system, a, b, b - a, y0, tol, tol);
        stepper.set_output(ode_solvers::OutputType::Sparse);
        let y = match stepper.integrate() {
            Ok(_) => stepper.y_out().last().map(|v| v[0]),
            Err(_) => None,
        };
        match y {
            Some(y) if y.is_finite() => {
                // below e^-745 f underflows: every channel is blocked
                state.log_open_fraction = if y < f64::MIN_POSITIVE.ln() {
                    f64::NEG_INFINITY
                } else {
                    y.min(0.0)
                };
            }
            Some(y) if y == f64::NEG_INFINITY => state.log_open_fraction = y,
            _ => state.clogged_shut = true,
        }
    }
}

/// The sieving ODE of one internal step, `d(ln f)/dt` (see
/// [`Simulator::integrate_sieving`]).
struct CloggingOde<'s> {
    contamination: &'s Contamination,
    a: f64,
    b: f64,
    before: &'s Snapshot,
    after: &'s Snapshot,
    /// L_y \[m\].
    length: f64,
}

impl CloggingOde<'_> {
    /// `−d(ln f)/dt` \[1/s\] at time `t` (≥ 0, finite; independent of f).
    fn rate(&self, t: f64, _y: f64) -> f64 {
        let (a, b) = (self.a, self.b);
        let t = t.clamp(a, b);
        let at = |qa: f64, qb: f64| events::interpolate_power_law(a, qa, b, qb, t).max(0.0);
        let q_open = at(self.before.open_leak_rate, self.after.open_leak_rate);
        let lambda_c = at(self.before.lambda_c, self.after.lambda_c);
        if !(q_open > 0.0 && lambda_c > 0.0) {
            return 0.0;
        }
        let channels = self.length / lambda_c;
        let n_p = self.contamination.number_concentration;
        let u_c = at(self.before.open_u_c, self.after.open_u_c);
        let reach = at(self.before.reach, self.after.reach);
        let cake = self.before.cake_factor.max(1.0);
        let rate =
            n_p * self.contamination.captured_fraction(u_c, reach) * q_open / (channels * cake);
        if rate.is_nan() {
            0.0
        } else {
            rate.min(f64::MAX)
        }
    }
}

impl ode_solvers::System<f64, ode_solvers::Vector1<f64>> for CloggingOde<'_> {
    fn system(&self, t: f64, y: &ode_solvers::Vector1<f64>, dy: &mut ode_solvers::Vector1<f64>) {
        dy[0] = -self.rate(t, y[0]);
    }
}
