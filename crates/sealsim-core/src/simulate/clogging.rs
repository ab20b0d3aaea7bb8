//! Particle clogging inside the life loop (docs/model.md §7): the reach of the particles and
//! the entry gap of a snapshot, the open fraction, the detours and the entry cake applied to a
//! snapshot, and the open-fraction ODE of one internal step.

use super::{Mechanics, SealState, Simulator, Snapshot, events};
use crate::clogging::{
    CAKE_POROSITY, CAKE_WEDGE_SLOPE, Contamination, cake_resistance_in_wedge, effective_threshold,
};
use crate::contact::{Junction, PerssonContact};

impl Simulator<'_> {
    /// Sets the reach `d_reach = u_c · u1(ζ_r)/u1(ζc)` with ζ_r = max(ζc/2, 1) (the constriction
    /// of the next-coarser octave of the path, which every particle must pass before it meets
    /// the critical one; at least u_c) and the entry gap ū(1), both at the peak strip's reduced
    /// pressure on the clogging contact path (docs/model.md §7). The ratio keeps d_reach on the
    /// fidelity's own u_c.
    pub(super) fn with_reach(&self, mut snap: Snapshot) -> Snapshot {
        let (Some(exact), Junction::Leaking(j)) = (&self.clogging_contact, snap.peak_junction)
        else {
            return snap;
        };
        let s = snap.peak_reduced_pressure;
        let u1c = exact.separation(j.zeta_c, s).u1();
        let u1r = exact.separation((0.5 * j.zeta_c).max(1.0), s).u1();
        let ratio = u1r / u1c;
        let ratio = if ratio.is_finite() {
            ratio.max(1.0)
        } else {
            1.0
        };
        snap.reach = snap.open_u_c * ratio;
        let entry = exact.separation(1.0, s).mean;
        snap.entry_gap = if entry.is_finite() {
            entry.max(0.0)
        } else {
            0.0
        };
        snap
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
        let f = if state.clogged_shut {
            0.0
        } else {
            state.log_open_fraction.exp().clamp(0.0, 1.0)
        };
        snap.open_fraction = f;
        if f >= 1.0 && state.cake_volume <= 0.0 {
            return snap;
        }
        let reroute = self
            .problem
            .contamination
            .as_ref()
            .is_some_and(|c| c.reroute);
        let (scale, drag_scale) = if f >= 1.0 {
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
    /// (0 without a cake, a pressure difference or an entry gap).
    fn cake_ratio(&self, snap: &Snapshot, state: &Mechanics, seal_static: f64) -> f64 {
        let p = self.problem;
        let (Some(c), dp) = (&p.contamination, p.fluid.pressure_difference) else {
            return 0.0;
        };
        if !(state.cake_volume > 0.0 && dp > 0.0 && snap.entry_gap > 0.0 && seal_static > 0.0) {
            return 0.0;
        }
        let viscosity = p.fluid.viscosity_at(snap.temperature);
        let r = cake_resistance_in_wedge(
            viscosity,
            state.cake_volume,
            c.cake_diameter(snap.reach),
            CAKE_POROSITY,
            p.geometry.sealing_length(),
            snap.entry_gap,
            CAKE_WEDGE_SLOPE,
        );
        let eps = r * seal_static / dp;
        if eps.is_finite() { eps.max(0.0) } else { 0.0 }
    }

    /// `((u_c(s, a_eff)/u_c(s, a_c))³, u_c(s, a_eff))` at the peak reduced pressure `s` and
    /// open fraction `f` (re-routing only; `(0, None)` when the junction seals).
    pub(super) fn reroute_ratio(&self, s: f64, f: f64) -> (f64, Option<f64>) {
        let Some(exact) = &self.clogging_contact else {
            return (f, None);
        };
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

    /// Integrates the open fraction over one internal step `[before, open]` (docs/model.md §7).
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
    pub(super) fn integrate_clogging(
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

/// The clogging ODE of one internal step, `d(ln f)/dt` (see
/// [`Simulator::integrate_clogging`]).
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
