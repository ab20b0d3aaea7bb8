//! The fluid pressure against time (docs/model.md §8.4): a table of `(t, P)` points, a daily
//! cycle down to a lower pressure, and a proof-pressure step before service.
//!
//! `P` is what the fluid's own pressure key states: the pressure difference ΔP across the seal
//! for a liquid, the **absolute inlet pressure** P_a for a gas (its outlet P_b stays fixed), so
//! that `ΔP(t) = P(t) − P_b`. The history is continuous and piecewise linear in time between its
//! knots ([`PressureHistory::knots`]): a change of pressure takes [`PRESSURE_RAMP`] in a cycle
//! and after the proof, and a table's rows are joined by straight lines, as a temperature table's
//! are. The life loop places an internal step on every knot, so no verdict depends on the output
//! grid; between knots it locates events by bisection on the exact state update, as for the
//! temperature.

use crate::material::shift::DAY;

/// How long a pressure change of a cycle or the end of the proof takes \[s\]: 60 s
/// (illustrative — a valve closing or a pump starting, stated rather than sourced). The figures
/// of a run do not depend on it beyond the volume leaked during the change itself; it makes the
/// history continuous, so that every state the run evaluates has one pressure.
pub const PRESSURE_RAMP: f64 = 60.0;
/// The start of the low phase of a daily pressure cycle \[s after midnight\]: 21:00. With the
/// daily temperature cycle (warmest at 15:00, coldest at 03:00, docs/model.md §8) the plant
/// is at its low pressure through the cold of the night — a depressurised shutdown at the cold,
/// the case the restart check is about (§8.2).
pub const DAILY_LOW_START: f64 = 21.0 * 3600.0;
/// The end of the low phase of a daily pressure cycle \[s after midnight\]: 09:00 (the
/// pressure is back at its service value at 09:01).
pub const DAILY_LOW_END: f64 = 9.0 * 3600.0;

/// A proof (pressure test) before service: `pressure` held from the installation (t = 0) to
/// `duration`, then back to the service pressure over [`PRESSURE_RAMP`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Proof {
    /// The proof pressure, in the fluid's terms (ΔP, or a gas's absolute inlet pressure) \[Pa\].
    pub pressure: f64,
    /// How long it is held \[s\] (> 0).
    pub duration: f64,
}

/// The fluid pressure of a life run against time (see the module documentation).
#[derive(Debug, Clone, PartialEq)]
pub struct PressureHistory {
    /// `(t [s], P [Pa])`, strictly increasing in t, at least one point; constant before the
    /// first and after the last.
    points: Vec<(f64, f64)>,
    /// The pressure of the low phase of a daily cycle (21:00–09:00) \[Pa\].
    daily_low: Option<f64>,
    proof: Option<Proof>,
    /// What P is measured from: the outlet pressure P_b of a gas, 0 for a liquid \[Pa\].
    datum: f64,
}

impl PressureHistory {
    /// A constant pressure `pressure` \[Pa\] above `datum` (P_b of a gas, 0 for a liquid).
    pub fn constant(pressure: f64, datum: f64) -> Self {
        Self::table(vec![(0.0, pressure)], datum)
    }

    /// A table of `(t [s], P [Pa])` points (strictly increasing t, at least one point).
    pub fn table(points: Vec<(f64, f64)>, datum: f64) -> Self {
        PressureHistory {
            points,
            daily_low: None,
            proof: None,
            datum,
        }
    }

    /// With a daily cycle: the pressure `low` \[Pa\] from 21:00 to 09:00 each day
    /// ([`DAILY_LOW_START`], [`DAILY_LOW_END`]), the table's value the rest of the day, each
    /// change over [`PRESSURE_RAMP`].
    pub fn with_daily_low(mut self, low: f64) -> Self {
        self.daily_low = Some(low);
        self
    }

    /// With a proof before service.
    pub fn with_proof(mut self, proof: Proof) -> Self {
        self.proof = Some(proof);
        self
    }

    /// The proof, if any.
    pub fn proof(&self) -> Option<Proof> {
        self.proof
    }

    /// The pressure of the daily cycle's low phase, if any \[Pa\].
    pub fn daily_low(&self) -> Option<f64> {
        self.daily_low
    }

    /// P(t) in the fluid's terms \[Pa\].
    pub fn at(&self, t: f64) -> f64 {
        let service = self.service(t);
        match self.proof {
            Some(proof) if t <= proof.duration => proof.pressure,
            Some(proof) if t < proof.duration + PRESSURE_RAMP => {
                let w = (t - proof.duration) / PRESSURE_RAMP;
                proof.pressure + w * (service - proof.pressure)
            }
            _ => service,
        }
    }

    /// ΔP(t) = P(t) − P_b \[Pa\] (≥ 0: the scenario refuses a pressure below the datum).
    pub fn difference_at(&self, t: f64) -> f64 {
        (self.at(t) - self.datum).max(0.0)
    }

    /// The table with the daily cycle, without the proof.
    fn service(&self, t: f64) -> f64 {
        let base = self.base(t);
        match self.daily_low {
            Some(low) => {
                let w = daily_weight(t);
                if w == 0.0 {
                    base
                } else {
                    base + w * (low - base)
                }
            }
            None => base,
        }
    }

    fn base(&self, t: f64) -> f64 {
        let p = &self.points;
        let k = p.partition_point(|&(ti, _)| ti <= t);
        if k == 0 {
            return p.first().map_or(0.0, |q| q.1);
        }
        if k == p.len() {
            return p[k - 1].1;
        }
        let (t0, y0) = p[k - 1];
        let (t1, y1) = p[k];
        y0 + (y1 - y0) * (t - t0) / (t1 - t0)
    }

    /// Whether P(t) is the same at every time.
    pub fn is_constant(&self) -> bool {
        let first = self.points.first().map_or(0.0, |p| p.1);
        self.points.iter().all(|p| p.1 == first)
            && self.daily_low.is_none_or(|low| low == first)
            && self.proof.is_none_or(|p| p.pressure == first)
    }

    /// The lowest and highest P over all time \[Pa\].
    pub fn range(&self) -> (f64, f64) {
        let values = self
            .points
            .iter()
            .map(|p| p.1)
            .chain(self.daily_low)
            .chain(self.proof.map(|p| p.pressure));
        values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        })
    }

    /// The highest ΔP over all time \[Pa\].
    pub fn highest_difference(&self) -> f64 {
        (self.range().1 - self.datum).max(0.0)
    }

    /// The knots of P(t) strictly inside `(a, b)` \[s\], increasing: the table's kinks, the
    /// ends of the proof's hold and ramp, and the four corners of each day of a cycle. P is
    /// linear (a table under no cycle) or smooth between them.
    pub fn knots(&self, a: f64, b: f64) -> Vec<f64> {
        // a table's row is a knot only where P(t) has a kink there (a row on a straight line,
        // or a constant table's rows, change nothing: no step, the run as without them)
        let slope = |i: usize| -> f64 {
            match (i.checked_sub(1).map(|j| self.points[j]), self.points.get(i)) {
                (Some((t0, y0)), Some(&(t1, y1))) => (y1 - y0) / (t1 - t0),
                _ => 0.0,
            }
        };
        // the rows strictly inside (a, b) by binary search: a long table costs O(log n) a call
        let first = self.points.partition_point(|p| p.0 <= a);
        let last = self.points.partition_point(|p| p.0 < b).max(first);
        let mut out: Vec<f64> = (first..last)
            .filter(|&i| slope(i) != slope(i + 1))
            .map(|i| self.points[i].0)
            .collect();
        if let Some(proof) = self.proof {
            out.extend(
                [proof.duration, proof.duration + PRESSURE_RAMP]
                    .into_iter()
                    .filter(|&k| k > a && k < b),
            );
        }
        if self.daily_low.is_some() && b > a {
            let first = (a / DAY).floor().max(0.0);
            let mut day = first;
            while day * DAY < b {
                for corner in [
                    DAILY_LOW_END,
                    DAILY_LOW_END + PRESSURE_RAMP,
                    DAILY_LOW_START,
                    DAILY_LOW_START + PRESSURE_RAMP,
                ] {
                    let k = day * DAY + corner;
                    if k > a && k < b {
                        out.push(k);
                    }
                }
                day += 1.0;
            }
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }

    /// The period of the daily cycle \[s\], if any (the run's cost: four knots a day).
    pub fn period(&self) -> Option<f64> {
        self.daily_low.map(|_| DAY)
    }
}

/// The weight of the low phase of the daily cycle at `t` \[s\] (t = 0 is midnight): 1 from
/// 21:01 to 09:00, 0 from 09:01 to 21:00, linear over the minute between.
fn daily_weight(t: f64) -> f64 {
    let s = t.rem_euclid(DAY);
    if s < DAILY_LOW_END {
        1.0
    } else if s < DAILY_LOW_END + PRESSURE_RAMP {
        1.0 - (s - DAILY_LOW_END) / PRESSURE_RAMP
    } else if s < DAILY_LOW_START {
        0.0
    } else if s < DAILY_LOW_START + PRESSURE_RAMP {
        (s - DAILY_LOW_START) / PRESSURE_RAMP
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_table_is_linear_between_rows_and_constant_outside() {
        let h = PressureHistory::table(vec![(10.0, 1e6), (20.0, 3e6)], 0.0);
        assert_eq!(h.at(0.0), 1e6);
        assert_eq!(h.at(15.0), 2e6);
        assert_eq!(h.at(1e9), 3e6);
        assert_eq!(h.knots(0.0, 100.0), [10.0, 20.0]);
        assert_eq!(h.knots(10.0, 20.0), Vec::<f64>::new());
        assert!(!h.is_constant());
        assert!(PressureHistory::constant(5e6, 0.0).is_constant());
        // rows without a kink are no knots: a constant table, a row on a straight line
        let flat = PressureHistory::table(vec![(0.0, 1e6), (5.0, 1e6), (9.0, 1e6)], 0.0);
        assert!(flat.knots(-1.0, 100.0).is_empty());
        let line = PressureHistory::table(vec![(0.0, 0.0), (5.0, 5.0), (9.0, 9.0)], 0.0);
        assert_eq!(line.knots(-1.0, 100.0), [0.0, 9.0]);
    }

    #[test]
    fn the_proof_holds_then_ramps_to_service() {
        let h = PressureHistory::constant(2e7, 0.0).with_proof(Proof {
            pressure: 3e7,
            duration: 600.0,
        });
        assert_eq!(h.at(0.0), 3e7);
        assert_eq!(h.at(600.0), 3e7);
        assert_eq!(h.at(600.0 + 0.5 * PRESSURE_RAMP), 2.5e7);
        assert_eq!(h.at(600.0 + PRESSURE_RAMP), 2e7);
        assert_eq!(h.knots(0.0, 1e4), [600.0, 660.0]);
        assert_eq!(h.range(), (2e7, 3e7));
    }

    #[test]
    fn a_daily_cycle_is_low_through_the_night_and_a_gas_is_measured_from_its_outlet() {
        let h = PressureHistory::constant(8e5, 1e5).with_daily_low(1e5);
        // 03:00 low, 15:00 service; ΔP from the outlet
        assert_eq!(h.difference_at(3.0 * 3600.0), 0.0);
        assert_eq!(h.difference_at(15.0 * 3600.0), 7e5);
        assert_eq!(h.difference_at(DAY + 15.0 * 3600.0), 7e5);
        // halfway down the ramp at 21:00:30
        assert!((h.at(DAILY_LOW_START + 30.0) - 4.5e5).abs() < 1e-6);
        let k = h.knots(0.0, DAY);
        assert_eq!(
            k,
            [
                DAILY_LOW_END,
                DAILY_LOW_END + 60.0,
                DAILY_LOW_START,
                DAILY_LOW_START + 60.0
            ]
        );
        assert_eq!(h.period(), Some(DAY));
        assert_eq!(h.highest_difference(), 7e5);
    }
}
