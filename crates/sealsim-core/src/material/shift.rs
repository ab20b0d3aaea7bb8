//! Time–temperature superposition: shift factors a_T and reduced time ξ(t) = ∫ dt / a_T(T(t))
//! over a temperature history (docs/model.md §5).
//!
//! * WLF (Williams, Landel & Ferry, J. Am. Chem. Soc. 77 (1955) 3701):
//!   `log10 a_T = −C1 (T − Tref)/(C2 + T − Tref)`; a_T < 1 above Tref (faster relaxation).
//!   At `T ≤ Tref − C2` the formula diverges and then flips sign; sealsim treats the material
//!   as frozen there (a_T = ∞: no relaxation progresses, the response is instantaneous) and
//!   reports it, never a NaN or a sign flip.
//! * Arrhenius: `ln a_T = (Ea/R)(1/T − 1/Tref)`.
//!
//! Everything is carried as the *rate* `r(T) = 1/a_T`, through its natural log, so that shift
//! factors of hundreds of decades neither overflow nor lose precision.

use crate::math::quadrature::gauss_integral;

/// Molar gas constant R \[J/(mol·K)\] (CODATA 2018, exact).
pub const GAS_CONSTANT: f64 = 8.314_462_618;

/// Seconds in a day and in a Julian year (365.25 d).
pub const DAY: f64 = 86_400.0;
pub const YEAR: f64 = 365.25 * DAY;

/// A time–temperature shift function.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shift {
    /// No temperature dependence (a_T = 1).
    None,
    /// WLF with reference temperature \[K\], C1 (dimensionless) and C2 \[K\], C2 > 0.
    Wlf { reference: f64, c1: f64, c2: f64 },
    /// Arrhenius with reference temperature \[K\] and activation energy \[J/mol\].
    Arrhenius {
        reference: f64,
        activation_energy: f64,
    },
}

impl Shift {
    /// `ln(1/a_T)` at temperature `t` \[K\]: +∞-safe; `−∞` when frozen (WLF at or below
    /// Tref − C2).
    pub fn ln_rate(&self, t: f64) -> f64 {
        match *self {
            Shift::None => 0.0,
            Shift::Wlf { reference, c1, c2 } => {
                let dt = t - reference;
                if t <= reference - c2 || c2 + dt <= 0.0 {
                    f64::NEG_INFINITY
                } else {
                    std::f64::consts::LN_10 * c1 * dt / (c2 + dt)
                }
            }
            Shift::Arrhenius {
                reference,
                activation_energy,
            } => -(activation_energy / GAS_CONSTANT) * (1.0 / t - 1.0 / reference),
        }
    }

    /// `log10 a_T` (+∞ when frozen).
    pub fn log10_factor(&self, t: f64) -> f64 {
        -self.ln_rate(t) / std::f64::consts::LN_10
    }

    /// The shift factor a_T (+∞ when frozen).
    pub fn factor(&self, t: f64) -> f64 {
        (-self.ln_rate(t)).exp()
    }

    /// Whether the material is frozen (glassy, no relaxation) at `t` \[K\].
    pub fn is_frozen(&self, t: f64) -> bool {
        self.ln_rate(t) == f64::NEG_INFINITY
    }

    /// The temperature at and below which a WLF material is frozen, `Tref − C2` \[K\].
    pub fn frozen_below(&self) -> Option<f64> {
        match *self {
            Shift::Wlf { reference, c2, .. } => Some(reference - c2),
            _ => None,
        }
    }
}

/// A sinusoidal temperature cycle `A sin(2π (t − t0)/P)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cycle {
    /// Amplitude \[K\].
    pub amplitude: f64,
    /// Period P \[s\].
    pub period: f64,
    /// Time of the upward zero crossing t0 \[s\].
    pub phase: f64,
}

impl Cycle {
    /// `A sin(2π (t − t0)/P)` \[K\], its phase taken from [`Self::offset`].
    fn at(&self, t: f64) -> f64 {
        self.at_offset(self.offset(t))
    }

    /// `A sin(2π x/P)` \[K\] at `x` = t − t0 reduced by whole periods.
    fn at_offset(&self, x: f64) -> f64 {
        self.amplitude * (std::f64::consts::TAU * x / self.period).sin()
    }

    /// `t − t0` less a whole number of periods \[s\] (in (−P, P] up to rounding): `t − t0`
    /// is carried with its rounding error (Knuth's two-sum) and reduced by `fmod`, which is
    /// exact, so the phase is good to ~1e-16 of a period at any t. Taken as `(t − t0)/P` it
    /// would be good to ~1e-16 of t only: 130 years into a run, 1e-11 of a day, which the
    /// 1e-12 quadrature of [`reduced_time`] cannot converge below.
    fn offset(&self, t: f64) -> f64 {
        let d = t - self.phase;
        let back = d - t;
        let error = (t - (d - back)) + (-self.phase - back);
        d % self.period + error
    }
}

/// T(lo + s) \[K\] on a piece `[lo, hi]` of a history with no kink inside, as a function of the
/// offset `s` \[s\] from its start: the table's segment and each cycle's phase are taken once at
/// `lo` (exactly, [`Cycle::offset`]), so that the integrand of [`reduced_time`] carries no
/// rounding of the absolute time (1e-7 s late in a long run) and its quadrature converges to
/// 1e-12 at any t.
struct Local {
    /// T of the table at `lo`'s segment start, its rise over the segment \[K\], `lo` less the
    /// segment start and the segment's width \[s\] (rise 0 and width 1 where T is constant).
    start: f64,
    rise: f64,
    from: f64,
    width: f64,
    /// Each cycle with its [`Cycle::offset`] at `lo`.
    cycles: Vec<(Cycle, f64)>,
}

impl Local {
    /// T(lo + s) \[K\], the formula of [`TemperatureHistory::at`] (bit for bit at s = 0).
    fn at(&self, s: f64) -> f64 {
        let base = self.start + self.rise * (self.from + s) / self.width;
        base + self
            .cycles
            .iter()
            .map(|(c, x)| c.at_offset(x + s))
            .sum::<f64>()
    }
}

/// Temperature against time: a piecewise-linear table (constant beyond its ends) or a constant,
/// plus optional sinusoidal cycles (daily, yearly).
#[derive(Debug, Clone, PartialEq)]
pub struct TemperatureHistory {
    /// (time \[s\], temperature \[K\]) with strictly increasing times; one point = constant.
    points: Vec<(f64, f64)>,
    cycles: Vec<Cycle>,
}

impl TemperatureHistory {
    /// Constant temperature \[K\].
    pub fn constant(t: f64) -> Self {
        TemperatureHistory {
            points: vec![(0.0, t)],
            cycles: Vec::new(),
        }
    }

    /// Piecewise-linear table of (time \[s\], temperature \[K\]); times strictly increasing, at
    /// least one point. Validated by the caller (the scenario boundary).
    pub fn table(points: Vec<(f64, f64)>) -> Self {
        TemperatureHistory {
            points,
            cycles: Vec::new(),
        }
    }

    /// Adds a sinusoidal cycle.
    pub fn with_cycle(mut self, cycle: Cycle) -> Self {
        self.cycles.push(cycle);
        self
    }

    /// The history with its first `duration` \[s\] replaced by a linear change from `start`
    /// \[K\] at t = 0 to the history's own temperature at `duration`: a seal fitted at `start`
    /// that settles to the environment (docs/model.md §5.2). Table points inside the lead-in
    /// are replaced by it; the cycles run on.
    pub fn with_lead_in(self, start: f64, duration: f64) -> Self {
        let cycles_at = |t: f64| self.cycles.iter().map(|c| c.at(t)).sum::<f64>();
        let mut points = vec![
            (0.0, start - cycles_at(0.0)),
            (duration, self.base(duration)),
        ];
        points.extend(self.points.iter().copied().filter(|p| p.0 > duration));
        TemperatureHistory {
            points,
            cycles: self.cycles,
        }
    }

    /// Whether the temperature never changes.
    pub fn is_constant(&self) -> bool {
        self.points.len() == 1 && self.cycles.iter().all(|c| c.amplitude == 0.0)
    }

    /// The temperature \[K\] if it is constant on `[a, b]` (no cycle, and the table flat
    /// there: after a lead-in, say), else `None`. Over such a piece the reduced time is exact
    /// and a strain that follows the temperature does not change.
    pub fn constant_on(&self, a: f64, b: f64) -> Option<f64> {
        if self.cycles.iter().any(|c| c.amplitude != 0.0) {
            return None;
        }
        let t = self.base(a);
        let flat = self.base(b) == t && self.inside(a, b).iter().all(|p| p.1 == t);
        flat.then_some(t)
    }

    /// The table's points with a time strictly inside `(a, b)` (binary search: O(log n)).
    fn inside(&self, a: f64, b: f64) -> &[(f64, f64)] {
        let p = &self.points;
        let from = p.partition_point(|q| q.0 <= a);
        let to = p.partition_point(|q| q.0 < b).max(from);
        &p[from..to]
    }

    /// [`Self::at`] from `lo` on, in the offset from `lo` ([`Local`]): for a piece `[lo, hi]`
    /// with no table point strictly inside.
    fn local(&self, lo: f64) -> Local {
        let p = &self.points;
        let k = p.partition_point(|&(ti, _)| ti <= lo);
        let (start, rise, from, width) = if k == 0 || k == p.len() {
            (p[k.saturating_sub(1)].1, 0.0, 0.0, 1.0)
        } else {
            let ((t0, y0), (t1, y1)) = (p[k - 1], p[k]);
            (y0, y1 - y0, lo - t0, t1 - t0)
        };
        let cycles = self
            .cycles
            .iter()
            .filter(|c| c.amplitude != 0.0)
            .map(|c| (*c, c.offset(lo)))
            .collect();
        Local {
            start,
            rise,
            from,
            width,
            cycles,
        }
    }

    /// T(t) \[K\].
    pub fn at(&self, t: f64) -> f64 {
        self.base(t) + self.cycles.iter().map(|c| c.at(t)).sum::<f64>()
    }

    fn base(&self, t: f64) -> f64 {
        let p = &self.points;
        let k = p.partition_point(|&(ti, _)| ti <= t);
        if k == 0 {
            return p[0].1;
        }
        if k == p.len() {
            return p[p.len() - 1].1;
        }
        let ((t0, y0), (t1, y1)) = (p[k - 1], p[k]);
        y0 + (y1 - y0) * (t - t0) / (t1 - t0)
    }

    /// The shortest period among the cycles with a non-zero amplitude \[s\].
    pub fn shortest_period(&self) -> Option<f64> {
        self.cycles
            .iter()
            .filter(|c| c.amplitude != 0.0)
            .map(|c| c.period)
            .min_by(f64::total_cmp)
    }

    /// The times of the table's points \[s\] (kinks of T(t)).
    pub fn knots(&self) -> impl Iterator<Item = f64> + '_ {
        self.points.iter().map(|p| p.0)
    }

    /// The times of the table's points strictly inside `(a, b)` \[s\], found by binary search
    /// (O(log n) and the points returned, not a pass over the table).
    pub fn knots_between(&self, a: f64, b: f64) -> impl Iterator<Item = f64> + '_ {
        self.inside(a, b).iter().map(|p| p.0)
    }

    /// The coldest temperature over `[a, b]` \[K\] and its first time \[s\]: the table's
    /// points and the ends exactly; with cycles, each cycle's period split into eighths (where
    /// the sum is smooth) and the coldest of those points refined by golden-section search on
    /// its two neighbouring pieces.
    pub fn coldest(&self, a: f64, b: f64) -> (f64, f64) {
        let points = self.breakpoints(a, b.max(a));
        let mut best = (self.at(a), a);
        for &t in &points {
            let y = self.at(t);
            if y < best.0 {
                best = (y, t);
            }
        }
        if self.shortest_period().is_some() {
            let k = points.partition_point(|&t| t < best.1);
            let lo = points[k.saturating_sub(1)];
            let hi = points[(k + 1).min(points.len() - 1)];
            if hi > lo {
                let t =
                    sealsim_math::roots::golden_section(|t| self.at(t), lo, hi, 1e-9 * (hi - lo));
                let y = self.at(t);
                if y < best.0 {
                    best = (y, t);
                }
            }
        }
        best
    }

    /// The first time in `[a, b]` at which T(t) < `threshold` \[s\] (`None`: never), by
    /// bisection on T(t) within the first piece between breakpoints that goes below it (a
    /// table's piece is linear: its end decides; with cycles its coldest point, found by
    /// golden-section search, does).
    pub fn first_below(&self, threshold: f64, a: f64, b: f64) -> Option<f64> {
        if self.at(a) < threshold {
            return Some(a);
        }
        let cycles = self.shortest_period().is_some();
        // a bound on the slope of the cycles' sum, Σ A 2π/P: with the table's own (linear
        // within a piece) it keeps a piece whose ends are far enough above the threshold above
        // it throughout, and spares its search
        let cycle_slope: f64 = self
            .cycles
            .iter()
            .map(|c| c.amplitude.abs() * std::f64::consts::TAU / c.period)
            .sum();
        let points = self.breakpoints(a, b.max(a));
        points.windows(2).find_map(|w| {
            let (lo, hi) = (w[0], w[1]);
            let (y_lo, y_hi) = (self.at(lo), self.at(hi));
            let slope = cycle_slope + ((self.base(hi) - self.base(lo)) / (hi - lo)).abs();
            if cycles && 0.5 * (y_lo + y_hi) - 0.5 * slope * (hi - lo) >= threshold {
                return None;
            }
            let cold = if cycles {
                sealsim_math::roots::golden_section(|t| self.at(t), lo, hi, 1e-9 * (hi - lo))
            } else {
                hi
            };
            let end = if self.at(hi) < threshold { hi } else { cold };
            (self.at(end) < threshold).then(|| {
                // invariant: T(lo) ≥ threshold > T(end)
                let (_, t) = sealsim_math::roots::bisect(
                    lo,
                    end,
                    200,
                    sealsim_math::roots::to_the_last_bit,
                    |t| self.at(t) >= threshold,
                );
                t
            })
        })
    }

    /// Lowest and highest temperature the history can reach \[K\] (bounds, for warnings).
    pub fn range(&self) -> (f64, f64) {
        let amp: f64 = self.cycles.iter().map(|c| c.amplitude.abs()).sum();
        let (lo, hi) = self
            .points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.1), hi.max(p.1))
            });
        (lo - amp, hi + amp)
    }

    /// Points where T(t) has a kink or a fast change inside `(a, b)`: table knots, and each
    /// cycle's period split into eight (so that every piece is smooth and short); with `a`
    /// and `b`, sorted. O(log n) in the table's length plus the points returned.
    fn breakpoints(&self, a: f64, b: f64) -> Vec<f64> {
        let mut v = vec![a, b];
        v.extend(self.knots_between(a, b));
        for c in &self.cycles {
            if c.amplitude == 0.0 {
                continue;
            }
            let h = c.period / 8.0;
            let first = ((a - c.phase) / h).floor() + 1.0;
            let last = ((b - c.phase) / h).ceil() - 1.0;
            let mut k = first;
            while k <= last {
                v.push(c.phase + k * h);
                k += 1.0;
            }
        }
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    }
}

/// Reduced time accumulated over `[a, b]`: `ξ(b) − ξ(a) = ∫_a^b dt / a_T(T(t))` \[s\].
///
/// Exact for a constant temperature; otherwise the interval is split at the history's kinks
/// and into eighths of each cycle, and each piece is integrated by globally adaptive
/// Gauss–Legendre to 1e-12 relative, so a_T may change by decades within a step. Frozen
/// stretches contribute nothing. Each piece is integrated in the offset from its start, its
/// table segment and cycle phases taken there exactly (`Local`): the integrand carries no
/// rounding of the absolute time, so the quadrature converges alike 130 years into a run as at
/// its start, at the same cost. The pieces are found by binary search in the table: the cost
/// does not grow with the table's length.
pub fn reduced_time(history: &TemperatureHistory, shift: &Shift, a: f64, b: f64) -> f64 {
    if b <= a {
        return 0.0;
    }
    if matches!(shift, Shift::None) {
        return (b - a) / shift.factor(history.at(a));
    }
    // exact where T is constant: the whole history, or the piece after a lead-in
    if let Some(t) = history.constant_on(a, b) {
        return (b - a) / shift.factor(t);
    }
    history
        .breakpoints(a, b)
        .windows(2)
        .map(|w| piece(history, shift, w[0], w[1]))
        .sum()
}

/// `∫_lo^hi dt / a_T(T(t))` \[s\] over a piece with no kink of T inside, integrated in the
/// offset from `lo` ([`TemperatureHistory::local`]).
fn piece(history: &TemperatureHistory, shift: &Shift, lo: f64, hi: f64) -> f64 {
    piece_parts(history, shift, lo, hi).0
}

/// [`piece`] and the sub-intervals its quadrature used (its cost: 24 evaluations each).
fn piece_parts(history: &TemperatureHistory, shift: &Shift, lo: f64, hi: f64) -> (f64, usize) {
    let local = history.local(lo);
    adaptive(&|s: f64| shift.ln_rate(local.at(s)).exp(), 0.0, hi - lo)
}

/// Reduced time of a two-sided Arrhenius law anchored at `reference` T_a \[K\]:
/// `∫_a^b exp(−E(T)/R (1/T − 1/T_a)) dt` \[s\], with `E(T) = below` for T ≤ T_a and
/// `E(T) = above` for T > T_a \[J/mol\] (a band of activation energies about an anchor,
/// docs/model.md §6.5). The rate is continuous at T_a (1 there on both sides); only its slope
/// in 1/T jumps.
///
/// Exact for a constant temperature. Otherwise each smooth piece of [`reduced_time`] (between
/// the history's kinks and eighths of its cycles) is split again where T(t) crosses T_a (sign
/// changes of T − T_a on 16 sub-steps, each bisected to the last bit), so every piece sees one
/// Arrhenius law and is integrated like [`reduced_time`] to 1e-12 relative. With
/// `below == above` it is [`reduced_time`] of that one law.
pub fn reduced_time_two_sided(
    history: &TemperatureHistory,
    reference: f64,
    below: f64,
    above: f64,
    a: f64,
    b: f64,
) -> f64 {
    let law = |activation_energy: f64| Shift::Arrhenius {
        reference,
        activation_energy,
    };
    let side = |t: f64| if t > reference { above } else { below };
    if below == above {
        return reduced_time(history, &law(below), a, b);
    }
    if b <= a {
        return 0.0;
    }
    if let Some(t) = history.constant_on(a, b) {
        return reduced_time(history, &law(side(t)), a, b);
    }
    // a history that never reaches the anchor (or never leaves the side below it) sees one law
    let (coldest, hottest) = history.range();
    if hottest <= reference {
        return reduced_time(history, &law(below), a, b);
    }
    if coldest > reference {
        return reduced_time(history, &law(above), a, b);
    }
    let mut total = 0.0;
    for w in history.breakpoints(a, b).windows(2) {
        let mut cuts = vec![w[0]];
        cuts.extend(crossings(history, reference, w[0], w[1]));
        cuts.push(w[1]);
        for c in cuts.windows(2) {
            if c[1] <= c[0] {
                continue;
            }
            let shift = law(side(history.at(0.5 * (c[0] + c[1]))));
            total += piece(history, &shift, c[0], c[1]);
        }
    }
    total
}

/// Times in `(a, b)` where `history` crosses `level` \[K\]: sign changes of T − level on 16
/// equal sub-steps, each bisected until the bracket stops shrinking.
fn crossings(history: &TemperatureHistory, level: f64, a: f64, b: f64) -> Vec<f64> {
    const STEPS: usize = 16;
    let above = |t: f64| history.at(t) > level;
    let mut out = Vec::new();
    let mut t0 = a;
    for k in 1..=STEPS {
        let t1 = if k == STEPS {
            b
        } else {
            a + (b - a) * k as f64 / STEPS as f64
        };
        if above(t0) != above(t1) {
            let (mut lo, mut hi) = (t0, t1);
            let side = above(lo);
            loop {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if above(mid) == side {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            out.push(0.5 * (lo + hi));
        }
        t0 = t1;
    }
    out
}

/// Globally adaptive Gauss–Legendre: 16-node estimates, error from the 8-node rule; the
/// sub-interval with the largest error is bisected until the summed error is below 1e-12 of the
/// summed integral, or 256 sub-intervals are in use (a bounded cost: near the WLF frozen limit
/// the integrand falls by hundreds of decades within a step, where local tests can recurse
/// without end). Returns the integral and the sub-intervals used (the cost: 24 evaluations
/// each).
fn adaptive(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, usize) {
    let piece = |a: f64, b: f64| {
        let hi = gauss_integral(f, 16, a, b);
        (a, b, hi, (hi - gauss_integral(f, 8, a, b)).abs())
    };
    let mut parts = vec![piece(a, b)];
    loop {
        let total: f64 = parts.iter().map(|p| p.2).sum();
        let error: f64 = parts.iter().map(|p| p.3).sum();
        if error <= 1e-12 * total.abs() || parts.len() >= 256 {
            return (total, parts.len());
        }
        let worst = parts
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.3.total_cmp(&y.1.3))
            .map_or(0, |(i, _)| i);
        let (pa, pb, _, _) = parts.swap_remove(worst);
        let m = 0.5 * (pa + pb);
        parts.push(piece(pa, m));
        parts.push(piece(m, pb));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// 128 years: 32 common periods of a daily and a yearly cycle (4 Julian years are exactly
    /// 1461 days), so a history of such cycles repeats after it \[s\].
    const LATE: f64 = 128.0 * YEAR;
    /// 1/1024 s: times on this grid below 2^42 s add exactly, so `a + LATE` is `a` moved by
    /// exactly 128 years.
    const GRID: f64 = 1.0 / 1024.0;

    /// The EPDM WLF law of `materials/epdm-70.toml` (Tref 23 °C, C1 6.9437, C2 129.6 K).
    const EPDM: Shift = Shift::Wlf {
        reference: 296.15,
        c1: 6.9437,
        c2: 129.6,
    };

    /// The outdoor climate of `scenarios/oring-epdm-outdoor-cycles.toml`: 10 °C ± 8 K a day
    /// (maximum at 15:00) ± 12 K a year (maximum on 21 July).
    fn outdoor() -> TemperatureHistory {
        TemperatureHistory::constant(283.15)
            .with_cycle(Cycle {
                amplitude: 8.0,
                period: DAY,
                phase: 9.0 * 3600.0,
            })
            .with_cycle(Cycle {
                amplitude: 12.0,
                period: YEAR,
                phase: 110.25 * DAY,
            })
    }

    /// A table of 100 001 rows 40 000 s apart (to 4e9 s, 127 years), zigzagging between
    /// 0 °C and 40 °C: T repeats every 80 000 s along it.
    fn zigzag() -> TemperatureHistory {
        TemperatureHistory::table(
            (0..=100_000u32)
                .map(|k| (40_000.0 * f64::from(k), 273.15 + 40.0 * f64::from(k % 2)))
                .collect(),
        )
    }

    /// `x` in 2^-56 s as an integer: exact for every double that is a multiple of 2^-56 s
    /// (all the times and phases of the test below).
    fn fixed(x: f64) -> i128 {
        let bits = x.to_bits();
        let exponent = ((bits >> 52) & 0x7ff) as i32 - 1075;
        let mantissa = i128::from(bits & ((1 << 52) - 1) | (1 << 52));
        let scaled = mantissa << (exponent + 56);
        if x < 0.0 { -scaled } else { scaled }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// A cycle's phase is `(t − t0) mod P` to the rounding of one period (< 1e-10 s of a
        /// day) at any time up to 130 years, checked against the exact remainder in integer
        /// arithmetic; `(t − t0)/P` in floating point would be off by up to ulp(t) = 4.8e-7 s.
        #[test]
        fn a_cycle_phase_is_exact_at_any_time(
            t in 0.0..(130.0 * YEAR),
            phase in 0.0..DAY,
        ) {
            // times and phases on a 2^-20 s grid: exactly representable in 2^-56 s units
            let (t, phase) = ((t * 1048576.0).round() / 1048576.0, (phase * 1048576.0).round() / 1048576.0);
            let cycle = Cycle { amplitude: 1.0, period: DAY, phase };
            let period = fixed(DAY);
            let exact = (fixed(t) - fixed(phase)).rem_euclid(period) as f64 / 2f64.powi(56);
            let mut error = cycle.offset(t) - exact;
            error -= DAY * (error / DAY).round();
            prop_assert!(error.abs() < 1e-10, "t {t}: {} vs {exact}", cycle.offset(t));
        }

        /// Daily and yearly cycles repeat after 128 years, so must the reduced time of the
        /// WLF law and the scission integral of a two-sided Arrhenius law whose anchor the
        /// cycles cross: any interval (from 1 ms to 10 days) late in a 130-year run gives the
        /// same integral as the same interval at the start, to 1e-12 relative — the quadrature
        /// in the piece's own offset ([`Local`]) converges to its 1e-12 at any t.
        #[test]
        fn cycles_give_the_same_reduced_time_128_years_later(
            a in 0.0..(4.0 * YEAR),
            log_length in -3.0..6.0f64,
        ) {
            let h = outdoor();
            let a = (a / GRID).round() * GRID;
            let b = ((a + 10f64.powf(log_length)) / GRID).round() * GRID;
            let early = reduced_time(&h, &EPDM, a, b);
            let late = reduced_time(&h, &EPDM, a + LATE, b + LATE);
            prop_assert!((late / early - 1.0).abs() <= 1e-12, "[{a}, {b}]: {early} vs {late}");
            // anchored at the mean, 10 °C: every day crosses it
            let k = |a: f64, b: f64| reduced_time_two_sided(&h, 283.15, 50e3, 105e3, a, b);
            let (early, late) = (k(a, b), k(a + LATE, b + LATE));
            prop_assert!((late / early - 1.0).abs() <= 1e-12, "[{a}, {b}]: {early} vs {late}");
        }

        /// The zigzag table repeats every 80 000 s: an interval near its end (~126 years in)
        /// gives the reduced time and the two-sided scission (anchored at 20 °C, crossed on
        /// every row) of the same interval near its start, to 1e-12 relative.
        #[test]
        fn a_long_table_gives_the_same_reduced_time_at_its_end(
            a in 0.0..800_000.0f64,
            log_length in -3.0..5.5f64,
        ) {
            let h = zigzag();
            let shift = 49_000.0 * 80_000.0;
            let a = (a / GRID).round() * GRID;
            let b = ((a + 10f64.powf(log_length)) / GRID).round() * GRID;
            let early = reduced_time(&h, &WLF, a, b);
            let late = reduced_time(&h, &WLF, a + shift, b + shift);
            prop_assert!((late / early - 1.0).abs() <= 1e-12, "[{a}, {b}]: {early} vs {late}");
            let k = |a: f64, b: f64| reduced_time_two_sided(&h, 293.15, 50e3, 105e3, a, b);
            let (early, late) = (k(a, b), k(a + shift, b + shift));
            prop_assert!((late / early - 1.0).abs() <= 1e-12, "[{a}, {b}]: {early} vs {late}");
        }

        /// The binary-searched look-ups are the linear scans they replace: the table's points
        /// strictly inside (a, b) and the constant pieces.
        #[test]
        fn look_ups_by_binary_search_are_the_scans(
            steps in proptest::collection::vec((1u8..4, 0u8..3), 1..40),
            a in -2.0..60.0f64,
            length in 0.0..30.0f64,
        ) {
            let mut t = 0.0;
            let points: Vec<(f64, f64)> = steps
                .iter()
                .map(|&(dt, y)| {
                    t += f64::from(dt);
                    (t, 280.0 + f64::from(y))
                })
                .collect();
            let h = TemperatureHistory::table(points.clone());
            let (a, b) = (a.round(), (a + length).round());
            let scan: Vec<f64> = points.iter().map(|p| p.0).filter(|&k| k > a && k < b).collect();
            prop_assert_eq!(h.knots_between(a, b).collect::<Vec<_>>(), scan);
            let flat = points
                .iter()
                .filter(|p| p.0 > a && p.0 < b)
                .all(|p| p.1 == h.base(a))
                && h.base(b) == h.base(a);
            prop_assert_eq!(h.constant_on(a, b), flat.then_some(h.base(a)));
        }
    }

    /// Bounded work per step: an eighth of a day's cycle (an internal step of a cycled run) and
    /// a row of the zigzag table cost the same quadrature 128 years in as at the start, at
    /// most two sub-intervals (48 evaluations). (In absolute time the integrand carries the
    /// rounding of t, ~1e-11 of the rate that late, and the 1e-12 quadrature split it up to its
    /// cap of 256 sub-intervals: the run's cost grew faster than its length.)
    #[test]
    fn a_late_step_costs_what_an_early_one_does() {
        let (cycles, table) = (outdoor(), zigzag());
        for k in 0..8 {
            let lo = f64::from(k) * DAY / 8.0 + 9.0 * 3600.0;
            let parts = |lo: f64| piece_parts(&cycles, &EPDM, lo, lo + DAY / 8.0).1;
            let (early, late) = (parts(lo), parts(lo + LATE));
            assert_eq!(early, late, "eighth {k}");
            assert!(late <= 2, "eighth {k}: {late}");
            let lo = 40_000.0 * f64::from(k);
            let parts = |lo: f64| piece_parts(&table, &WLF, lo, lo + 40_000.0).1;
            let (early, late) = (parts(lo), parts(lo + 49_000.0 * 80_000.0));
            assert_eq!(early, late, "row {k}");
            assert!(late <= 2, "row {k}: {late}");
        }
    }

    /// [`Local`] is [`TemperatureHistory::at`] in the offset from its start: the same bits at
    /// the start, and along the piece the same temperature up to rounding.
    #[test]
    fn local_temperatures_are_the_history() {
        for h in [outdoor(), zigzag(), outdoor().with_lead_in(296.15, 3600.0)] {
            for lo in [0.0, 1800.0, 40_000.0, 1e6 + 0.5, 3.9e9] {
                let local = h.local(lo);
                assert_eq!(local.at(0.0), h.at(lo));
                // within the piece from `lo`: no table point inside
                for s in [1e-3, 1.0, 1000.0, 9999.0] {
                    if h.knots_between(lo, lo + s).next().is_some() {
                        continue;
                    }
                    assert!((local.at(s) - h.at(lo + s)).abs() < 1e-9, "{lo} + {s}");
                }
            }
        }
    }

    const WLF: Shift = Shift::Wlf {
        reference: 296.15,
        c1: 8.86,
        c2: 101.6,
    };

    /// A fitted ring settling from 23 °C to 80 °C over an hour: the temperature is constant
    /// after the lead-in and nowhere before; a cycle makes it vary everywhere; and the reduced
    /// time over a constant piece is the closed form (b − a)/a_T, which the adaptive quadrature
    /// gives to its 1e-12.
    #[test]
    fn constant_pieces_after_a_lead_in_are_exact() {
        let h = TemperatureHistory::constant(353.15).with_lead_in(296.15, 3600.0);
        assert!(!h.is_constant());
        assert_eq!(h.constant_on(3600.0, 1e9), Some(353.15));
        assert_eq!(h.constant_on(7200.0, 9000.0), Some(353.15));
        assert_eq!(h.constant_on(0.0, 3600.0), None);
        assert_eq!(h.constant_on(3599.0, 4000.0), None);
        let closed = (1e9 - 4000.0) / WLF.factor(353.15);
        assert_eq!(reduced_time(&h, &WLF, 4000.0, 1e9), closed);
        let rate = |t: f64| WLF.ln_rate(h.at(t)).exp();
        assert!((adaptive(&rate, 4000.0, 1e9).0 / closed - 1.0).abs() < 1e-11);
        let cycled = h.clone().with_cycle(Cycle {
            amplitude: 5.0,
            period: 86_400.0,
            phase: 0.0,
        });
        assert_eq!(cycled.constant_on(4000.0, 5000.0), None);
        assert_eq!(
            TemperatureHistory::constant(300.0).constant_on(0.0, 1.0),
            Some(300.0)
        );
    }

    #[test]
    fn coldest_point_and_first_crossing_are_the_closed_forms() {
        // a table: 25 °C, down to −40 °C over 4 h from 30 h, held, back up
        let night = TemperatureHistory::table(vec![
            (0.0, 298.15),
            (108_000.0, 298.15),
            (122_400.0, 233.15),
            (151_200.0, 233.15),
            (165_600.0, 298.15),
        ]);
        assert_eq!(night.coldest(0.0, 432_000.0), (233.15, 122_400.0));
        // before the cold: the end of the window
        assert_eq!(night.coldest(0.0, 115_200.0).1, 115_200.0);
        // T(t) < 243 K first at 108000 + 14400 (298.15 − 243)/65 s on the ramp
        let t = night.first_below(243.0, 0.0, 432_000.0).unwrap();
        let exact = 108_000.0 + 14_400.0 * (298.15 - 243.0) / 65.0;
        assert!((t - exact).abs() < 1e-9 * exact, "{t} vs {exact}");
        assert_eq!(night.first_below(233.0, 0.0, 432_000.0), None);
        assert_eq!(night.first_below(300.0, 0.0, 432_000.0), Some(0.0));
        // a daily cycle of 10 K around 0 °C, zero crossing upwards at 6 h: coldest at 0 h and
        // 24 h, −10 °C; from 7 h (warm) below −5 °C first where the sine falls below −1/2
        let day = 86_400.0;
        let cycled = TemperatureHistory::constant(273.15).with_cycle(Cycle {
            amplitude: 10.0,
            period: day,
            phase: 6.0 * 3600.0,
        });
        let (cold, when) = cycled.coldest(3600.0, 2.0 * day);
        assert!((cold - 263.15).abs() < 1e-9, "{cold}");
        assert!((when - day).abs() < 1.0, "{when}");
        // sin(2π(t − 6 h)/P) < −1/2 first at t − 6 h = 7P/12, t = 20 h
        let t = cycled.first_below(268.15, 7.0 * 3600.0, 2.0 * day).unwrap();
        assert!((t - 20.0 * 3600.0).abs() < 1e-6, "{t}");
        assert_eq!(cycled.first_below(263.0, 7.0 * 3600.0, 2.0 * day), None);
    }

    #[test]
    fn wlf_sign_reference_and_frozen_limit() {
        assert_eq!(WLF.factor(296.15), 1.0);
        assert!(WLF.factor(353.15) < 1.0, "faster above Tref");
        assert!(WLF.factor(273.15) > 1.0, "slower below Tref");
        // hand value: T − Tref = 57 K: log10 a_T = −8.86·57/158.6 = −3.18426...
        assert!((WLF.log10_factor(353.15) + 8.86 * 57.0 / 158.6).abs() < 1e-12);
        // frozen at and below Tref − C2 = 194.55 K: a_T = ∞, rate 0, never NaN or negative
        let edge = WLF.frozen_below().unwrap();
        assert!((edge - 194.55).abs() < 1e-9);
        for t in [edge, 194.0, 150.0, 1.0] {
            assert!(WLF.is_frozen(t));
            assert_eq!(WLF.factor(t), f64::INFINITY);
        }
        assert!(!WLF.is_frozen(194.56));
        assert!(WLF.factor(194.56) > 1e100);
    }

    #[test]
    fn arrhenius_hand_values() {
        let s = Shift::Arrhenius {
            reference: 296.15,
            activation_energy: 90e3,
        };
        assert_eq!(s.factor(296.15), 1.0);
        // ln a_T(353.15 K) = (90000/8.314462618)(1/353.15 − 1/296.15) = −5.899459...
        let expect = (90e3 / 8.314_462_618) * (1.0 / 353.15 - 1.0 / 296.15);
        assert!((s.factor(353.15).ln() - expect).abs() < 1e-12);
        assert!((expect + 5.899_459_6).abs() < 1e-6, "{expect}");
        // ln a_T(273.15 K) = +3.0776...
        let cold = (90e3 / 8.314_462_618) * (1.0 / 273.15 - 1.0 / 296.15);
        assert!((s.factor(273.15).ln() - cold).abs() < 1e-12 && (cold - 3.0776).abs() < 1e-3);
    }

    #[test]
    fn constant_history_gives_t_over_a_t_exactly() {
        let h = TemperatureHistory::constant(353.15);
        let xi = reduced_time(&h, &WLF, 0.0, 3.0e7);
        assert_eq!(xi, 3.0e7 / WLF.factor(353.15));
    }

    #[test]
    fn linear_ramp_matches_closed_form_arrhenius_integral() {
        // For Arrhenius on a linear ramp T = T0 + k t there is no elementary closed form, so
        // compare a steep WLF ramp against a 1e6-point midpoint rule instead.
        let h = TemperatureHistory::table(vec![(0.0, 200.0), (1000.0, 400.0)]);
        let xi = reduced_time(&h, &WLF, 0.0, 1000.0);
        let n = 1_000_000;
        let dt = 1000.0 / n as f64;
        let reference: f64 = (0..n)
            .map(|i| dt / WLF.factor(h.at((i as f64 + 0.5) * dt)))
            .sum();
        // a_T spans 12 decades along the ramp
        assert!((xi / reference - 1.0).abs() < 1e-9, "{xi} vs {reference}");
    }

    #[test]
    fn daily_cycle_is_additive_over_whole_periods() {
        let s = Shift::Arrhenius {
            reference: 296.15,
            activation_energy: 90e3,
        };
        let h = TemperatureHistory::constant(320.0).with_cycle(Cycle {
            amplitude: 15.0,
            period: DAY,
            phase: 0.0,
        });
        let one = reduced_time(&h, &s, 0.0, DAY);
        let ten = reduced_time(&h, &s, 0.0, 10.0 * DAY);
        assert!((ten / (10.0 * one) - 1.0).abs() < 1e-11);
        // hotter half-days dominate: more than the mean-temperature value
        assert!(one > DAY / s.factor(320.0));
    }

    /// The two-sided law: closed forms at constant temperature on both sides of the anchor, a
    /// ramp through the anchor against the one-sided integrals split at the known crossing
    /// time t* = (T_a − T0)/slope and against a 1e6-point midpoint rule, a daily cycle that
    /// crosses the anchor twice a day against the midpoint rule.
    #[test]
    fn two_sided_arrhenius_is_exact_on_each_side() {
        let (ta, lo, hi) = (373.15, 50e3, 105e3);
        let one = |e: f64| Shift::Arrhenius {
            reference: ta,
            activation_energy: e,
        };
        for (t, e) in [(300.0, lo), (373.15, lo), (420.0, hi)] {
            let h = TemperatureHistory::constant(t);
            let xi = reduced_time_two_sided(&h, ta, lo, hi, 0.0, 1e6);
            let closed = 1e6 * (-(e / GAS_CONSTANT) * (1.0 / t - 1.0 / ta)).exp();
            assert!((xi / closed - 1.0).abs() < 1e-14, "{t}: {xi} vs {closed}");
        }
        // 353.15 → 393.15 K over 1000 s: crosses T_a at t* = 500 s
        let ramp = TemperatureHistory::table(vec![(0.0, 353.15), (1000.0, 393.15)]);
        let xi = reduced_time_two_sided(&ramp, ta, lo, hi, 0.0, 1000.0);
        let split = reduced_time(&ramp, &one(lo), 0.0, 500.0)
            + reduced_time(&ramp, &one(hi), 500.0, 1000.0);
        assert!((xi / split - 1.0).abs() < 1e-12, "{xi} vs {split}");
        let midpoint = |h: &TemperatureHistory, span: f64| {
            let n = 1_000_000;
            let dt = span / n as f64;
            (0..n)
                .map(|i| {
                    let t = h.at((i as f64 + 0.5) * dt);
                    let e = if t > ta { hi } else { lo };
                    dt / one(e).factor(t)
                })
                .sum::<f64>()
        };
        assert!((xi / midpoint(&ramp, 1000.0) - 1.0).abs() < 1e-9);
        // a single law over the same ramp differs: the split matters
        let single = reduced_time(&ramp, &one(lo), 0.0, 1000.0);
        assert!(xi / single > 1.05, "{xi} vs {single}");
        // a daily cycle of ±20 K about T_a + 5 K
        let cycle = TemperatureHistory::constant(ta + 5.0).with_cycle(Cycle {
            amplitude: 20.0,
            period: DAY,
            phase: 0.0,
        });
        let day = reduced_time_two_sided(&cycle, ta, lo, hi, 0.0, DAY);
        assert!((day / midpoint(&cycle, DAY) - 1.0).abs() < 1e-9);
        // equal energies: the one-sided reduced time itself
        assert_eq!(
            reduced_time_two_sided(&ramp, ta, lo, lo, 0.0, 1000.0),
            reduced_time(&ramp, &one(lo), 0.0, 1000.0)
        );
    }

    #[test]
    fn frozen_stretches_add_no_reduced_time() {
        let h = TemperatureHistory::table(vec![(0.0, 150.0), (100.0, 150.0), (200.0, 296.15)]);
        assert_eq!(reduced_time(&h, &WLF, 0.0, 100.0), 0.0);
        assert!(reduced_time(&h, &WLF, 0.0, 200.0).is_finite());
    }
}
