//! Particle clogging inside the life loop (docs/model.md §7): the open fraction of the critical
//! channels applied to a snapshot, the re-routing junctions, and the open-fraction ODE of one
//! internal step.

use super::{Mechanics, REROUTE_NODE_SPACING, SealState, Simulator, Snapshot, events};
use crate::clogging::{Contamination, effective_threshold};
use crate::contact::{CriticalJunction, Junction, PerssonContact};
use std::cell::RefCell;

impl Simulator<'_> {
    /// The leak rate of `open` (all channels open) with the state's open fraction f:
    /// * without re-routing the blocked channels carry nothing, the rest are unchanged:
    ///   `Q̇ = f Q̇_open`;
    /// * with re-routing the blocked channels count as contact, the effective threshold is
    ///   `a_eff = 1 − (1 − a_c)/f` and the next, narrower constriction takes over. The
    ///   strips-in-series open leak rate is scaled by the *peak strip's* ratio
    ///   `(u_c(s_peak, a_eff)/u_c(s_peak, a_c))³` (an approximation: the peak strip dominates
    ///   the series resistance), both junctions by the exact path; 0 when a_eff ≤ 0 or the
    ///   peak strip seals at a_eff.
    pub(super) fn clogged(&self, mut snap: Snapshot, state: &Mechanics) -> Snapshot {
        let f = if state.clogged_shut {
            0.0
        } else {
            state.log_open_fraction.exp().clamp(0.0, 1.0)
        };
        snap.open_fraction = f;
        if f >= 1.0 {
            return snap;
        }
        let (scale, u_c) = match &self.rerouting {
            None => (f, snap.u_c),
            Some(_) if state.clogged_shut => (0.0, None),
            Some(_) => {
                let (ratio, u_eff) = self.reroute_ratio(snap.peak_reduced_pressure, f);
                (ratio, u_eff)
            }
        };
        snap.u_c = u_c;
        snap.peak_junction = match (snap.peak_junction, u_c) {
            (Junction::Leaking(j), Some(u_c)) => Junction::Leaking(CriticalJunction { u_c, ..j }),
            _ => Junction::Sealed,
        };
        // The drag flows through the same channels: without re-routing the blocked ones carry
        // none of it (× f); with re-routing the film is taken to scale with the constriction
        // height, d = β u_c at fixed β (× the cube root of the u_c³ ratio).
        let drag_scale = if self.rerouting.is_some() {
            scale.cbrt()
        } else {
            scale
        };
        snap.leak_rate = match (snap.open_static_leak_rate, snap.motion) {
            (Some(static_rate), Some(m)) => {
                (static_rate * scale + m.drag_leak_rate * drag_scale).max(0.0)
            }
            _ => (snap.open_leak_rate * scale).max(0.0),
        };
        if !snap.leak_rate.is_finite() {
            snap.leak_rate = 0.0;
        }
        if let (Some((spec, _)), Some(m)) = (&self.drag, snap.motion) {
            let static_rate = match snap.open_static_leak_rate {
                Some(static_rate) => (static_rate * scale).max(0.0),
                None => snap.leak_rate,
            };
            snap.motion = Some(spec.rescale(m, static_rate, drag_scale));
        }
        if snap.state == SealState::Leaking && snap.leak_rate <= 0.0 {
            snap.state = SealState::Sealed;
        }
        snap
    }

    /// `((u_c(s, a_eff)/u_c(s, a_c))³, u_c(s, a_eff))` at the peak reduced pressure `s` and
    /// open fraction `f` (re-routing only; `(0, None)` when the junction seals).
    pub(super) fn reroute_ratio(&self, s: f64, f: f64) -> (f64, Option<f64>) {
        let Some(exact) = &self.rerouting else {
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
    /// `dy/dt = −n_p [1 − F(u)] Q̇ / (N_ch f)`, N_ch = L_y/λ_c (λ_c of the critical junction
    /// at the peak strip with all channels open: the channels that carry the flow), and
    /// * without re-routing `Q̇ = f Q̇_open`, u = u_c: `dy/dt = −n_p [1 − F(u_c)] Q̇_open/N_ch`;
    /// * with re-routing `Q̇ = Q̇_open (u_c(a_eff)/u_c(a_c))³` and u = u_c(a_eff) (see
    ///   [`Self::clogged`]); the right side vanishes where the seal closes.
    ///
    /// Inside the step u_c, Q̇_open, λ_c and the peak reduced pressure are interpolated as
    /// power laws in time between the step's ends ([`events::interpolate_power_law`]).
    /// Dopri5 (ode_solvers) with sparse output (only the end state is used; its dense output
    /// extrapolates the last point), rtol = atol = the clogging tolerance on ln f (an
    /// absolute error in ln f is a relative error in f). If the integration fails (a stiff
    /// closure under re-routing, which the explicit method cannot follow) the seal is taken
    /// as clogged shut from there on.
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
            simulator: self,
            contamination: c,
            a,
            b,
            before,
            after,
            length,
            ratios: RefCell::new(Vec::new()),
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
            _ => {
                if c.reroute {
                    state.clogged_shut = true;
                } else {
                    state.log_open_fraction = f64::NEG_INFINITY;
                }
            }
        }
    }
}

/// The clogging ODE of one internal step, `d(ln f)/dt` (see
/// [`Simulator::integrate_clogging`]).
struct CloggingOde<'s, 'a> {
    simulator: &'s Simulator<'a>,
    contamination: &'s Contamination,
    a: f64,
    b: f64,
    before: &'s Snapshot,
    after: &'s Snapshot,
    /// L_y \[m\].
    length: f64,
    /// Re-routing ratios `(k, ratio, u_eff)` at `ln f = k h` ([`REROUTE_NODE_SPACING`]) and the
    /// step's end peak pressure, computed on demand and interpolated linearly in
    /// ln f: the right side is then a fixed, smooth function of f within the step (independent
    /// of where the solver samples it), at a few exact junctions per step instead of two per
    /// evaluation.
    ratios: RefCell<Vec<(i64, f64, Option<f64>)>>,
}

impl CloggingOde<'_, '_> {
    /// `−d(ln f)/dt` \[1/s\] at time `t` and `y = ln f` (≥ 0, finite).
    fn rate(&self, t: f64, y: f64) -> f64 {
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
        let rate = match &self.simulator.rerouting {
            None => {
                let u_c = at(self.before.open_u_c, self.after.open_u_c);
                n_p * self.contamination.captured_fraction(u_c) * q_open / channels
            }
            Some(_) => {
                let f = y.exp().min(1.0);
                if f <= 0.0 {
                    return 0.0;
                }
                let (ratio, u_eff) = if f >= 1.0 {
                    (1.0, Some(at(self.before.open_u_c, self.after.open_u_c)))
                } else {
                    self.interpolated_ratio(y)
                };
                let Some(u_eff) = u_eff else {
                    return 0.0;
                };
                n_p * self.contamination.captured_fraction(u_eff) * q_open * ratio / (channels * f)
            }
        };
        if rate.is_nan() {
            0.0
        } else {
            rate.min(f64::MAX)
        }
    }
}

impl CloggingOde<'_, '_> {
    /// The step's peak reduced pressure for the re-routing ratio: the end's, the pressure its
    /// end snapshot uses, so the ratio integrated and the ratio reported agree at the end.
    fn step_pressure(&self) -> f64 {
        self.after.peak_reduced_pressure
    }

    /// The re-routing ratio at node `k` (`ln f = k h`), cached.
    fn node(&self, k: i64) -> (f64, Option<f64>) {
        if let Some(&(_, r, u)) = self.ratios.borrow().iter().find(|n| n.0 == k) {
            return (r, u);
        }
        let f = (k as f64 * REROUTE_NODE_SPACING).exp().min(1.0);
        let (r, u) = match &self.simulator.rerouting {
            Some(exact) => {
                let s = self.step_pressure();
                let a_c = self.simulator.problem.contact.percolation_threshold;
                let reference = self.simulator.reference_junction(exact, s);
                let a_eff = effective_threshold(a_c, f);
                if f >= 1.0 {
                    (1.0, reference)
                } else if a_eff.is_nan() || a_eff <= 0.0 {
                    (0.0, None)
                } else {
                    Simulator::ratio_against(exact, s, a_eff, reference)
                }
            }
            None => (f, None),
        };
        self.ratios.borrow_mut().push((k, r, u));
        (r, u)
    }

    /// `(ratio, u_eff)` at `y = ln f`, linear in ln f between the two nearest nodes.
    fn interpolated_ratio(&self, y: f64) -> (f64, Option<f64>) {
        let x = y / REROUTE_NODE_SPACING;
        let k = x.floor();
        let w = x - k;
        let (k, w) = if k.is_finite() {
            (k as i64, w)
        } else {
            return (0.0, None);
        };
        let (r0, u0) = self.node(k);
        let (r1, u1) = self.node(k + 1);
        match (u0, u1) {
            (Some(u0), Some(u1)) => (r0 + w * (r1 - r0), Some(u0 + w * (u1 - u0))),
            // one node sealed: take the nearer one
            _ if w < 0.5 => (r0, u0),
            _ => (r1, u1),
        }
    }
}

impl ode_solvers::System<f64, ode_solvers::Vector1<f64>> for CloggingOde<'_, '_> {
    fn system(&self, t: f64, y: &ode_solvers::Vector1<f64>, dy: &mut ode_solvers::Vector1<f64>) {
        dy[0] = -self.rate(t, y[0]);
    }
}
