//! The internal time steps of a life run (docs/model.md §10.1): chosen by the physics and an
//! error control, never by the output grid.
//!
//! * **Base steps**: log-uniform at [`BASE_POINTS_PER_DECADE`] from `min(start, 1 s)` to the
//!   duration, with every knot of the temperature history, eight sub-steps per shortest cycle
//!   and the thermal splitting of [`Simulator::substeps`]. They do not depend on
//!   `points_per_decade`.
//! * **Error control**: each pair of base steps `[a, b, c]` is step-doubled: the leaked volume of
//!   the one power-law step `a → c` against the two `a → b → c`. The pair is accepted when they
//!   differ by at most `tol · (V_ac + V(a) ln(c/a)/ln(T/t0))` (the second term spreads an
//!   absolute allowance of `tol · V(T)` over log time, so the global error stays of the order of
//!   `tol` of the final volume), when no state changes inside it and when the middle leak rate is
//!   no extremum beyond `tol`; otherwise each step is bisected (geometric midpoint) and checked
//!   the same way, to [`MAX_DEPTH`] levels.
//! * **State changes** (sealed, leaking, below a molecule, lift-off, pressure-held) are located
//!   by bisection on the exact state update to [`STATE_CHANGE_RTOL`] of the time, and a step is
//!   placed on each side, so that the leak rate, which jumps there, is integrated on each side
//!   and never across the jump.
//! * **Outputs only sample**: a history row at an output time that is not an internal step is
//!   the state advanced from the internal step before it, on a copy; the run goes on from the
//!   internal step. The leaked volume, the states with their times, the extremes and every
//!   failure time are the internal steps', so they do not move with `points_per_decade`.

use super::problem::CoursePoint;
use super::{Course, Mechanics, Simulator, Snapshot};

/// Base internal steps per decade of time (before the error control refines them). Equal to
/// the default output grid, so that with the default grid every history row is an internal
/// step and costs nothing extra.
pub(super) const BASE_POINTS_PER_DECADE: f64 = 20.0;
/// The earliest base step \[s\] (or the output grid's `start`, if earlier).
pub(super) const BASE_START: f64 = 1.0;
/// Deepest bisection of one base step by the error control.
const MAX_DEPTH: u32 = 24;
/// Most evaluations the error control may spend on one pair of base steps; past it the pair
/// is taken as it is (a guard against a state that flips on every bisection).
const MAX_EVALUATIONS_PER_PAIR: usize = 4096;
/// The error control of the leaked volume and the extremes does not split a step shorter than
/// this multiple of the tolerance, as a fraction of its time (1e-4 at the default: a leak rate
/// that still varies by more than the tolerance across 1e-4 of the time is numerical noise of
/// the contact model near its sealing threshold, seen at rates of 1e-19 m³/s and below).
const MIN_ERROR_STEP: f64 = 0.1;
/// A step no longer than this fraction of its time (next to a state change) is accepted
/// without its midpoint when its monotone bound meets the tolerance ([`Stepper::bounded`]).
const SHORT_STEP: f64 = 1e-3;
/// State changes are located to this multiple of the tolerance, as a fraction of their time
/// (1e-5 at the default): the leak's jump there then adds at most that fraction of a step's
/// volume, and the time is stated to five figures.
const STATE_CHANGE_RTOL: f64 = 1e-2;

/// A state of the run at one internal time: the mechanics and what is evaluated from them.
#[derive(Debug, Clone)]
pub(super) struct Point {
    pub(super) state: Mechanics,
    pub(super) snap: Snapshot,
}

impl Point {
    fn time(&self) -> f64 {
        self.state.time
    }
}

/// The error control of one run.
pub(super) struct Stepper<'s, 'a> {
    simulator: &'s Simulator<'a>,
    /// Relative tolerance of the integrated quantities (`[simulation] tolerance`).
    tolerance: f64,
    /// ln(T/t0) of the base grid: the log-time over which the absolute allowance is spread.
    log_span: f64,
    /// Evaluations left for the current pair.
    budget: std::cell::Cell<usize>,
    /// Evaluations made (for the cost figures).
    pub(super) evaluations: std::cell::Cell<usize>,
    /// The highest leak rate evaluated so far \[m³/s\]: an extremum of the leak rate is resolved
    /// only where it can be the run's highest.
    highest: std::cell::Cell<f64>,
}

impl<'s, 'a> Stepper<'s, 'a> {
    pub(super) fn new(simulator: &'s Simulator<'a>) -> Self {
        let grid = &simulator.problem.time;
        let start = grid.start.min(BASE_START);
        Stepper {
            simulator,
            tolerance: grid.tolerance,
            log_span: (grid.duration / start).ln().max(1.0),
            budget: std::cell::Cell::new(MAX_EVALUATIONS_PER_PAIR),
            evaluations: std::cell::Cell::new(0),
            highest: std::cell::Cell::new(0.0),
        }
    }

    /// The state advanced from `from` to `t` (a copy; the exact update of
    /// [`Simulator::advance`]).
    fn step(&self, from: &Point, t: f64) -> Point {
        self.evaluations.set(self.evaluations.get() + 1);
        self.budget.set(self.budget.get().saturating_sub(1));
        let mut state = from.state.clone();
        let snap = self.simulator.advance(&mut state, t, &from.snap);
        self.highest.set(self.highest.get().max(snap.leak_rate));
        Point { state, snap }
    }

    fn exhausted(&self) -> bool {
        self.budget.get() == 0
    }

    /// The accepted internal steps from `from` through the base steps `ends` (one or two, in
    /// increasing order), refined until the error control is met.
    pub(super) fn window(&self, from: &Point, ends: &[f64]) -> Vec<Point> {
        self.budget.set(MAX_EVALUATIONS_PER_PAIR);
        match *ends {
            [b, c] => {
                let pb = self.step(from, b);
                let pc = self.step(&pb, c);
                if same_state(from, &pb) && same_state(&pb, &pc) && self.converged(from, &pb, &pc) {
                    return vec![pb, pc];
                }
                self.halves(from, pb, Some(pc), c, 1)
            }
            [b] => {
                let pb = self.step(from, b);
                self.refine(from, pb, 1)
            }
            _ => Vec::new(),
        }
    }

    /// The accepted steps from `from` to `to` (evaluated from `from` in one step): bisected
    /// while the state changes across it (down to [`STATE_CHANGE_RTOL`] × tolerance of its time, so that a
    /// change is located on the steps themselves and the leak, which jumps there, is integrated
    /// on each side of it), or while the leaked volume or an extreme misses the tolerance.
    fn refine(&self, from: &Point, to: Point, depth: u32) -> Vec<Point> {
        let (a, b) = (from.time(), to.time());
        let m = midpoint(a, b);
        let changed = !same_state(from, &to);
        // a state change is located to STATE_CHANGE_RTOL, the volume and extremes to
        // MIN_ERROR_STEP (below it a leak rate is as good as constant, or numerical noise)
        let shortest = self.tolerance
            * if changed {
                STATE_CHANGE_RTOL
            } else {
                MIN_ERROR_STEP
            };
        if depth >= MAX_DEPTH || self.exhausted() || !(m > a && m < b) || b - a <= shortest * b {
            return vec![to];
        }
        if !changed && b - a <= SHORT_STEP * b && self.bounded(from, &to) {
            return vec![to];
        }
        let pm = self.step(from, m);
        let pb = if changed {
            None
        } else {
            let pb = self.step(&pm, b);
            if same_state(from, &pm) && same_state(&pm, &pb) && self.converged(from, &pm, &pb) {
                return vec![pm, pb];
            }
            Some(pb)
        };
        self.halves(from, pm, pb, b, depth + 1)
    }

    /// `from → mid → b` refined half by half: the first half ends at `mid` (evaluated); the
    /// second starts where the first's refinement ended, reusing `end` (evaluated from `mid`)
    /// when that is `mid` itself.
    fn halves(
        &self,
        from: &Point,
        mid: Point,
        end: Option<Point>,
        b: f64,
        depth: u32,
    ) -> Vec<Point> {
        let mut out = self.refine(from, mid, depth);
        let Some(last) = out.last().cloned() else {
            return out;
        };
        let end = match end {
            Some(end) if out.len() == 1 => end,
            _ => self.step(&last, b),
        };
        out.extend(self.refine(&last, end, depth));
        out
    }

    /// The volume allowance of a step `a → c` whose leaked volume is `volume` (see the module
    /// documentation).
    fn allowance(&self, a: &Point, c: f64, volume: f64) -> f64 {
        let ta = a.time();
        let spread = if ta > 0.0 {
            (c / ta).ln() / self.log_span
        } else {
            1.0
        };
        self.tolerance * (volume + a.state.leaked_volume * spread)
    }

    /// Whether a short step's leaked volume is within the allowance whatever the leak rate does
    /// in it, as long as it is monotone: `(b − a)|q_b − q_a|` bounds the error of any estimate
    /// between the two ends' rates. Used only for steps no longer than [`SHORT_STEP`] of their
    /// time (next to a located state change), where a turning leak rate inside is not to be
    /// feared; it spares their midpoint evaluations.
    fn bounded(&self, a: &Point, b: &Point) -> bool {
        let (ta, tb) = (a.time(), b.time());
        let (qa, qb) = (a.snap.leak_rate, b.snap.leak_rate);
        let volume = super::events::integrate_power_law(ta, qa, tb, qb);
        (tb - ta) * (qb - qa).abs() <= self.allowance(a, tb, volume)
    }

    /// Whether the step pair `a → b → c` (one state throughout) meets the tolerance: the
    /// leaked volume of one power-law step `a → c` within the allowance of the two, and the
    /// middle leak rate no extremum beyond the tolerance (a peak or trough inside is resolved).
    fn converged(&self, a: &Point, b: &Point, c: &Point) -> bool {
        let (ta, tb, tc) = (a.time(), b.time(), c.time());
        let (qa, qb, qc) = (a.snap.leak_rate, b.snap.leak_rate, c.snap.leak_rate);
        let fine = super::events::integrate_power_law(ta, qa, tb, qb)
            + super::events::integrate_power_law(tb, qb, tc, qc);
        let coarse = super::events::integrate_power_law(ta, qa, tc, qc);
        let allowance = self.allowance(a, tc, fine);
        let tol = self.tolerance;
        let peak = qb > (1.0 + tol) * qa.max(qc) && qb >= (1.0 - tol) * self.highest.get();
        let trough = qb < (1.0 - tol) * qa.min(qc);
        let extremum = peak || trough;
        (coarse - fine).abs() <= allowance && !extremum
    }
}

/// Whether two points are in the same state (the state a report names).
fn same_state(a: &Point, b: &Point) -> bool {
    a.snap.state == b.snap.state
}

/// The geometric midpoint of `(a, b)` (arithmetic from 0), as the time steps are log-spaced.
pub(super) fn midpoint(a: f64, b: f64) -> f64 {
    let geometric = if a > 0.0 { (a * b).sqrt() } else { 0.5 * b };
    if geometric > a && geometric < b {
        geometric
    } else {
        0.5 * (a + b)
    }
}

impl Course {
    /// The course of a run that starts at `first` (t = 0).
    pub(super) fn start(first: &Snapshot, peak_pressure: f64) -> Self {
        let mut course = Course::empty(1);
        course.observe(&point(0.0, first, peak_pressure, 0.0), None);
        course
    }

    /// Takes in the accepted internal step `from → to`.
    pub(super) fn record(&mut self, from: &Point, to: &Point, peak_pressure: f64) {
        let at = point(to.time(), &to.snap, peak_pressure, to.state.leaked_volume);
        self.observe(&at, Some((from.time(), from.state.leaked_volume)));
    }
}

/// The course's view of the state `snap` at `time` with `leaked_volume` so far.
fn point(time: f64, snap: &Snapshot, peak_pressure: f64, leaked_volume: f64) -> CoursePoint {
    CoursePoint {
        time,
        state: snap.state,
        leak_rate: snap.leak_rate,
        force: snap.profile.force_per_length(),
        peak_pressure,
        leaked_volume,
        interference_lost: snap.shutdown.is_some_and(|s| !s.holds),
    }
}

#[cfg(test)]
mod tests {
    use super::midpoint;

    #[test]
    fn midpoints_are_geometric_and_inside() {
        assert_eq!(midpoint(1.0, 100.0), 10.0);
        assert_eq!(midpoint(0.0, 4.0), 2.0);
        let (a, b) = (1.0, 1.0 + f64::EPSILON);
        let m = midpoint(a, b);
        assert!(
            !(m > a && m < b),
            "no double strictly between: the caller stops"
        );
    }
}
