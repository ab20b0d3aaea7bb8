//! The contact table: u_c and ū_c against the reduced pressure P0/E*, built once per surface.
//!
//! For a given spectrum and settings, the critical junction depends on the nominal pressure
//! and the rubber only through `s = P0/E*` (docs/model.md §2). ζc, λc and h_rms(ζc) are closed forms
//! and are always computed exactly; only the quadrature results u_c and ū_c are tabulated, as
//! `ln(u/h_rms)` on a uniform grid in `v = logit(s/s_seal) = ln(r/(1−r))`, `r = s/s_seal`,
//! with 4-point cubic interpolation. `v` is log-uniform at low pressure, where u_c varies like
//! ln(1/P0), and stretches the approach to the sealing pressure s_seal, where u_c vanishes
//! like exp(−c/(1−r)) and a grid uniform in ln s loses all accuracy (measured: errors of 200 %
//! at 12 points per decade). Outside the tabulated range the exact path answers, so a lookup
//! is never less accurate than the table's stated tolerance.

use super::{EffectiveMedium, EffectiveMediumSettings, Junction, PerssonContact};
use crate::math::interp::UniformCubic;
use std::sync::{Arc, OnceLock};

/// How the table is laid out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableSettings {
    /// Grid points per unit `log10` of `r/(1−r)` (≈ per decade of P0/E* at low pressure).
    pub points_per_decade: f64,
    /// The table starts at `r = 10^-decades` below the sealing pressure.
    pub decades: f64,
    /// Further decades below `decades`, tabulated with the same spacing on the first lookup
    /// there (0: none). A glassy ring at lift-off reaches far below the rubbery range
    /// (docs/model.md §2); most runs never go there and do not pay for it.
    pub extension: f64,
    /// The table ends at `r = 1 − upper_gap`; closer to sealing the exact path answers.
    pub upper_gap: f64,
}

impl TableSettings {
    /// The uniform grid in `logit(s/s_seal)` these settings describe: `(first node, spacing,
    /// number of nodes ≥ 4)`.
    fn logit_grid(&self) -> (f64, f64, usize) {
        let hi = logit(1.0 - self.upper_gap);
        let lo = logit(10f64.powf(-self.decades));
        let n = ((hi - lo) / std::f64::consts::LN_10 * self.points_per_decade)
            .ceil()
            .max(4.0) as usize;
        (lo, (hi - lo) / (n - 1) as f64, n)
    }

    /// The effective-medium table's default: 8 points per decade from 1e-16 of the threshold to
    /// 2e-9 short of it, built lazily (each node costs a Bruggeman solve; measured worst error vs
    /// the direct solve in tests/model/effective_medium.rs).
    pub fn effective_medium() -> Self {
        TableSettings {
            points_per_decade: 8.0,
            decades: 16.0,
            upper_gap: 2e-9,
            extension: 0.0,
        }
    }
}

impl TableSettings {
    /// The exact level's cache of quadrature nodes (docs/model.md §4): 96 points per decade over
    /// the default range (8 decades, 8 more on first use below), so that its interpolation error
    /// stays far below the critical-junction table's (measured in tests/model/contact_table.rs);
    /// ≈ 770 quadratures (≈ 15 ms) to build.
    pub fn exact_cache() -> Self {
        TableSettings {
            points_per_decade: 96.0,
            ..TableSettings::default()
        }
    }
}

impl Default for TableSettings {
    fn default() -> Self {
        TableSettings {
            points_per_decade: 12.0,
            decades: 8.0,
            upper_gap: 0.03,
            extension: 8.0,
        }
    }
}

/// u_c(P0/E*) and ū_c(P0/E*) for one surface (see the module docs).
///
/// The tabulated `ln(u/h_rms)` against `logit(s/s_seal)` is the same function for every
/// spectrum of one *shape* (C(q) up to a constant factor k²): by Persson's scaling
/// (docs/model.md §2) the contact of `k² C` at `P0/E*` is that of `C` at `P0/(k E*)` with every
/// length times k, so `s_seal` and `h_rms` scale by k and the tabulated quotients do not move.
/// So the nodes are computed once per shape, on [`Spectrum::unit_shape`](crate::surface::Spectrum::unit_shape),
/// and shared (a process-wide cache of [`SHAPE_CACHE_SIZE`] shapes): the cases of a study that
/// varies the roughness amplitude (Ra, rms) at a fixed shape build one table between them. The
/// nodes are a function of the shape alone, never of which surface asked first, so every run
/// gets the same bits whatever the order, the threads or the other runs of the process.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactTable {
    /// This surface's exact path (ζc, λc, h_rms(ζc), and every look-up outside the grid).
    exact: PerssonContact,
    s_seal: f64,
    ln_h: f64,
    shape: Arc<TableShape>,
}

/// The nodes of a [`ContactTable`], computed on the unit-shape spectrum.
#[derive(Debug, PartialEq)]
struct TableShape {
    /// The unit-shape path the nodes are computed on.
    exact: PerssonContact,
    s_seal: f64,
    ln_h: f64,
    /// `None` if the surface left fewer than four tabulable nodes: every lookup is exact.
    grid: Option<Grid>,
    /// The lazily built extension below `grid` (same spacing, ending at its first node), and
    /// the grid variable where it starts (`+∞`: no extension).
    low: OnceLock<Option<Grid>>,
    low_start: f64,
}

/// How many table shapes the process keeps (each a few kB): a study or sweep rarely has more
/// surface shapes than this, and the least recently built goes first.
pub const SHAPE_CACHE_SIZE: usize = 64;

/// The process's table shapes (see [`ContactTable`]), by the exact bits of the unit-shape
/// spectrum, the model settings and the table's layout.
static SHAPES: crate::math::memo::Memo<(String, TableSettings), Arc<TableShape>> =
    crate::math::memo::Memo::new(SHAPE_CACHE_SIZE);

#[derive(Debug, Clone, PartialEq)]
struct Grid {
    /// `ln(u_c/h_rms)` against `logit(s/s_seal)`.
    u_c: UniformCubic,
    /// `ln(ū_c/h_rms)` against `logit(s/s_seal)`.
    ubar_c: UniformCubic,
}

impl TableShape {
    /// The nodes, by evaluating the exact path of the unit shape at every one.
    fn build(exact: PerssonContact, settings: TableSettings) -> Self {
        let s_seal = exact.sealing_reduced_pressure();
        let (lo, h, n) = settings.logit_grid();
        let ln_h = exact.spectrum().rms_roughness().ln();
        let mut u = Vec::with_capacity(n);
        let mut ub = Vec::with_capacity(n);
        for i in 0..n {
            let s = s_seal * logistic(lo + h * i as f64);
            match exact.critical_junction(s) {
                Junction::Leaking(j) => {
                    u.push(j.u_c.ln() - ln_h);
                    ub.push(j.ubar_c.ln() - ln_h);
                }
                // Not expected below 97 % of the sealing pressure; if a surface gets there,
                // the table simply ends and the exact path answers above.
                Junction::Sealed => break,
            }
        }
        let grid = (u.len() >= 4).then(|| Grid {
            u_c: UniformCubic::new(lo, h, u),
            ubar_c: UniformCubic::new(lo, h, ub),
        });
        // the extension: whole steps of h below lo, at least four nodes
        let steps = (settings.extension * std::f64::consts::LN_10 / h).ceil();
        let low_start = if grid.is_some() && steps >= 3.0 {
            lo - h * steps
        } else {
            f64::INFINITY
        };
        TableShape {
            exact,
            s_seal,
            ln_h,
            grid,
            low: OnceLock::new(),
            low_start,
        }
    }

    /// The extension grid from `low_start` to the main grid's first node (built on first use).
    fn low_grid(&self) -> Option<&Grid> {
        self.low
            .get_or_init(|| {
                let main = self.grid.as_ref()?;
                let (lo, _) = main.u_c.range();
                let h = main.u_c.spacing();
                let n = ((lo - self.low_start) / h).round() as usize + 1;
                let mut u = Vec::with_capacity(n);
                let mut ub = Vec::with_capacity(n);
                for i in 0..n {
                    let s = self.s_seal * logistic(self.low_start + h * i as f64);
                    let Junction::Leaking(j) = self.exact.critical_junction(s) else {
                        return None;
                    };
                    u.push(j.u_c.ln() - self.ln_h);
                    ub.push(j.ubar_c.ln() - self.ln_h);
                }
                Some(Grid {
                    u_c: UniformCubic::new(self.low_start, h, u),
                    ubar_c: UniformCubic::new(self.low_start, h, ub),
                })
            })
            .as_ref()
    }

    /// The grid that covers the grid variable `v`, if any.
    fn grid_at(&self, v: f64) -> Option<&Grid> {
        let g = self.grid.as_ref()?;
        let (lo, hi) = g.u_c.range();
        if v >= lo && v <= hi {
            Some(g)
        } else if v < lo && v >= self.low_start {
            self.low_grid()
        } else {
            None
        }
    }
}

impl ContactTable {
    /// Builds the table: the nodes of the surface's shape (computed on the unit-shape spectrum
    /// by evaluating its exact path at every node, or taken from the process's cache of shapes),
    /// bound to this surface's exact path.
    pub fn build(exact: PerssonContact, settings: TableSettings) -> Self {
        let unit = exact.spectrum().unit_shape();
        // exact bits of the shape and the model settings: equal keys, equal nodes
        let key = (format!("{unit:?}{:?}", exact.settings()), settings);
        let shape = SHAPES.get_or_insert_with(key, || {
            Arc::new(TableShape::build(
                PerssonContact::new(unit, *exact.settings()),
                settings,
            ))
        });
        ContactTable {
            s_seal: exact.sealing_reduced_pressure(),
            ln_h: exact.spectrum().rms_roughness().ln(),
            exact,
            shape,
        }
    }

    /// The grid that covers the grid variable `v`, if any.
    fn grid_at(&self, v: f64) -> Option<&Grid> {
        self.shape.grid_at(v)
    }

    /// The exact path the table was built from.
    pub fn exact(&self) -> &PerssonContact {
        &self.exact
    }

    /// Range of `P0/E*` the table covers, its extension included (`None`: no table); outside
    /// it lookups are exact.
    pub fn range(&self) -> Option<(f64, f64)> {
        let shape = &*self.shape;
        let (a, b) = shape.grid.as_ref()?.u_c.range();
        Some((
            self.s_seal * logistic(a.min(shape.low_start)),
            self.s_seal * logistic(b),
        ))
    }

    /// u_c at `s = P0/E*` \[m\] (`None` when sealed): the same number as
    /// [`Self::critical_junction`]'s, without assembling the junction (ζc, λc, h_rms(ζc)) — the
    /// conductance needs u_c alone, and the interface-pressure solutions ask for it thousands of
    /// times per state.
    pub fn critical_gap(&self, s: f64) -> Option<f64> {
        // inside a grid r ≤ 1 − upper_gap < 1: below the sealing pressure, leaking
        match self.grid_at(logit(s / self.s_seal)) {
            Some(g) => Some((g.u_c.eval(logit(s / self.s_seal)) + self.ln_h).exp()),
            None => self.exact.critical_junction(s).leaking().map(|j| j.u_c),
        }
    }

    /// The critical junction at `s = P0/E*`: ζc exact, u_c and ū_c interpolated.
    pub fn critical_junction(&self, s: f64) -> Junction {
        let v = logit(s / self.s_seal);
        let Some(grid) = self.grid_at(v) else {
            return self.exact.critical_junction(s);
        };
        let Some(ln_a) = self.exact.critical_ln_q(s) else {
            return Junction::Sealed;
        };
        let u_c = (grid.u_c.eval(v) + self.ln_h).exp();
        let ubar_c = (grid.ubar_c.eval(v) + self.ln_h).exp();
        Junction::Leaking(self.exact.junction_from(ln_a, u_c, ubar_c))
    }
}

/// The effective gap `u_eff(P0/E*) = (12 η σ_eff)^{1/3}` of the effective-medium level
/// (docs/model.md §3.3), tabulated per surface like [`ContactTable`]: `ln(u_eff/h_rms)` at nodes
/// uniform in `v = logit(s/s_half)`, where `s_half = erfinv(½) √(π M3(q1))` (with the corrected
/// area [`PerssonContact::reduced_pressure_at_area`]) is the pressure at which the contact
/// fraction reaches the 2-D threshold ½ and σ_eff vanishes. Each node is one Bruggeman solve,
/// made on the first lookup that needs it (a life run visits a narrow band of P0/E*), and is a
/// function of its index alone, so the table gives the same bits whatever the order or the
/// threads of the calls. The nodes reach from `s = 10^-decades s_half` to `1 − upper_gap` of the
/// threshold ([`TableSettings::effective_medium`]: 1e-16 and 2e-9): ln u_eff is smooth in v
/// all the way, since u_eff vanishes as a power of the distance to the threshold — measured
/// `u_eff ∝ (1 − s/s_half)^1` (d ln u_eff/dv = −1.0000 from v = 12 to 24 on the paper's surface,
/// tests/model/effective_medium.rs), which the table continues beyond its last node; below its
/// first node it answers the first node's value (the integrand e·σ(e) of every interface
/// integral vanishes there). It also carries the critical-junction table of the same surface,
/// whose ζc and λc describe the channels (clogging, validity warnings).
#[derive(Debug, Clone, PartialEq)]
pub struct EffectiveMediumTable {
    junctions: ContactTable,
    settings: EffectiveMediumSettings,
    s_half: f64,
    ln_h: f64,
    /// `ln(u_eff/h_rms)` against `logit(s/s_half)`, built on first use.
    nodes: LazyNodes,
    /// A rarefied gas: `12 η σ_eff` against s, one column per node of ln λ (built on first use).
    gas: GasColumns,
}

/// The exponent of `1 − s/s_half` with which a tabulated `u_eff` vanishes at the threshold
/// (measured, see [`EffectiveMediumTable`]): beyond the last node `ln u_eff` continues with
/// slope −this in `ln(1 − s/s_half)`, and `ln(12ησ_eff)` with three times it.
const THRESHOLD_EXPONENT: f64 = 1.0;

/// Values at the nodes `v_i = i h` (`first ≤ i ≤ last`) of a grid variable, each computed on first
/// use (`None`: the node does not conduct), and 4-point cubic Lagrange interpolation between
/// them (shifted stencil at the ends). A node's value is a function of its abscissa alone,
/// never of which call built it: a lazily filled grid gives the bits an eagerly built one would,
/// for any order of calls and any number of threads.
#[derive(Debug)]
struct LazyNodes {
    first: i64,
    h: f64,
    values: Vec<OnceLock<Option<f64>>>,
    /// The lowest index found not to conduct so far (`i64::MAX`: none): the conductance falls
    /// with the pressure, so every node above it is sealed too and is never built.
    sealed_from: std::sync::atomic::AtomicI64,
}

impl Clone for LazyNodes {
    fn clone(&self) -> Self {
        LazyNodes {
            first: self.first,
            h: self.h,
            values: self.values.clone(),
            sealed_from: std::sync::atomic::AtomicI64::new(self.sealed()),
        }
    }
}

impl PartialEq for LazyNodes {
    /// The grid, not which of its nodes happen to be built yet.
    fn eq(&self, other: &Self) -> bool {
        (self.first, self.h, self.values.len()) == (other.first, other.h, other.values.len())
    }
}

impl LazyNodes {
    /// Nodes `h` apart covering `[lo, hi]` (at least four).
    fn new(lo: f64, hi: f64, h: f64) -> Self {
        let first = (lo / h).floor() as i64;
        let last = ((hi / h).ceil() as i64).max(first + 3);
        LazyNodes {
            first,
            h,
            values: (first..=last).map(|_| OnceLock::new()).collect(),
            sealed_from: std::sync::atomic::AtomicI64::new(i64::MAX),
        }
    }

    /// The same grid with no node built.
    fn empty_like(&self) -> Self {
        LazyNodes {
            first: self.first,
            h: self.h,
            values: self.values.iter().map(|_| OnceLock::new()).collect(),
            sealed_from: std::sync::atomic::AtomicI64::new(i64::MAX),
        }
    }

    /// The lowest node index known not to conduct (`i64::MAX`: none yet).
    fn sealed(&self) -> i64 {
        self.sealed_from.load(std::sync::atomic::Ordering::Relaxed)
    }

    fn last(&self) -> i64 {
        self.first + self.values.len() as i64 - 1
    }

    fn abscissa(&self, i: i64) -> f64 {
        i as f64 * self.h
    }

    /// The values at nodes `from..from + N` (inside the grid); the missing ones computed by
    /// `f(v_i)`, on two threads when more than one is missing. No allocation when all are
    /// built (the common case: a look-up per strip and state evaluation).
    fn values<const N: usize>(
        &self,
        from: i64,
        f: &(dyn Fn(f64) -> Option<f64> + Sync),
    ) -> [Option<f64>; N] {
        let slot = |i: i64| &self.values[(i - self.first) as usize];
        let range = from..from + N as i64;
        if range.clone().any(|i| slot(i).get().is_none()) {
            self.build_missing(from, N, f);
        }
        let values: [Option<f64>; N] = std::array::from_fn(|k| {
            *slot(from + k as i64).get_or_init(|| f(self.abscissa(from + k as i64)))
        });
        for (i, v) in (from..).zip(&values) {
            if v.is_none() {
                self.sealed_from
                    .fetch_min(i, std::sync::atomic::Ordering::Relaxed);
            }
        }
        values
    }

    /// Builds the missing nodes of `from..from + n`, with the next node along when a look-up
    /// moving along the grid misses one at an end of its stencil (on the second thread: a
    /// node's value does not depend on when it is built).
    fn build_missing(&self, from: i64, n: usize, f: &(dyn Fn(f64) -> Option<f64> + Sync)) {
        let slot = |i: i64| &self.values[(i - self.first) as usize];
        let range = from..from + n as i64;
        let mut missing: Vec<i64> = range.filter(|&i| slot(i).get().is_none()).collect();
        if let [i] = missing[..] {
            let next = if i == from + n as i64 - 1 {
                i + 1
            } else {
                i - 1
            };
            if n > 1
                && (i == from || i == from + n as i64 - 1)
                && (self.first..=self.last()).contains(&next)
                && next < self.sealed()
                && slot(next).get().is_none()
            {
                missing.push(next);
            }
        }
        if missing.len() > 1 {
            let computed =
                crate::math::map_on_two_threads(missing.len(), |k| f(self.abscissa(missing[k])));
            for (&i, value) in missing.iter().zip(computed) {
                // set by another thread meanwhile: the same value
                let _ = slot(i).set(value);
            }
        }
    }

    /// The tabulated `y(v)` (a logarithm; −∞ where sealed):
    /// * inside the nodes, the cubic through the four nearest; where one of them does not
    ///   conduct, linear between the two around v, and in the cell before the first sealed node
    ///   `e^y` linear down to 0 there (the threshold lies in that cell; sealed beyond);
    /// * below the first node, its value;
    /// * beyond the last, `y_last + power·[ln(1 − r) − ln(1 − r_last)]`, r = logistic(v): the
    ///   measured power law at the threshold ([`THRESHOLD_EXPONENT`]).
    fn look_up(&self, v: f64, power: f64, f: &(dyn Fn(f64) -> Option<f64> + Sync)) -> f64 {
        let hi = self.abscissa(self.last());
        // at or beyond a node known to be sealed: sealed, nothing to build
        if (v / self.h).floor() >= self.sealed() as f64 {
            return f64::NEG_INFINITY;
        }
        if v > hi {
            return match self.values::<1>(self.last(), f)[0] {
                Some(y) => y + power * (softplus(hi) - softplus(v)),
                None => f64::NEG_INFINITY,
            };
        }
        let t = (v / self.h).max(self.first as f64);
        let j = (t.floor() as i64 - 1).clamp(self.first, self.last() - 3);
        let s = t - j as f64;
        let y = self.values::<4>(j, f);
        if let [Some(y0), Some(y1), Some(y2), Some(y3)] = y[..] {
            let (a, b, c, d) = (s, s - 1.0, s - 2.0, s - 3.0);
            return -y0 * b * c * d / 6.0 + y1 * a * c * d / 2.0 - y2 * a * b * d / 2.0
                + y3 * a * b * c / 6.0;
        }
        // the cell [k, k + 1] of the stencil that holds v
        let k = (s.floor() as usize).min(2);
        let x = s - k as f64;
        match (y[k], y[k + 1]) {
            (Some(a), Some(b)) => a + (b - a) * x,
            (Some(a), None) => a + (1.0 - x).ln(),
            (None, _) => f64::NEG_INFINITY,
        }
    }
}

/// `ln(1 + e^v)` = −ln(1 − logistic(v)), without overflow.
fn softplus(v: f64) -> f64 {
    v.max(0.0) + (-v.abs()).exp().ln_1p()
}

/// Spacing of the rarefied columns in ln λ (docs/model.md §3.10): ln(12ησ_eff) is smooth in
/// ln λ (it goes from ln u³ to ln λ + const), so cubic interpolation over e-fold steps is
/// accurate to ≈ 1e-4 (measured in tests/model/effective_medium.rs).
const GAS_COLUMN_SPACING: f64 = 1.0;

/// Above this Knudsen number over the surface's rms height, the rarefied effective medium is
/// taken as free molecular: every local conductance proportional to λ, so σ_eff ∝ λ (Bruggeman
/// is homogeneous of degree one in the conductances).
const GAS_FREE_MOLECULAR_KN: f64 = 1e5;

/// The rarefied columns start at this many decades below the threshold (the liquid's nodes
/// reach further): a gas's Hertz profile is solved from its open inlet, where the asperity
/// pressure rises from 0 and the resistance is least, and would otherwise build every node
/// down there; below it a column answers its first node's value.
const GAS_COLUMN_DECADES: f64 = 6.0;

/// The rarefied columns of an [`EffectiveMediumTable`], keyed by the node index k of
/// ln λ = k·[`GAS_COLUMN_SPACING`] and the molecular diameter's bits: each column
/// `ln(12ησ_eff) − 3 ln h_rms` on the table's nodes in `logit(s/s_half)`, its nodes built on first
/// use (and shared by clones made afterwards).
#[derive(Default)]
struct GasColumns(std::sync::Mutex<ColumnMap>);

/// `(k, molecular diameter bits) → column`.
type ColumnMap = std::collections::BTreeMap<(i64, u64), std::sync::Arc<LazyNodes>>;

impl Clone for GasColumns {
    fn clone(&self) -> Self {
        let map = self.0.lock().map(|m| m.clone()).unwrap_or_default();
        GasColumns(std::sync::Mutex::new(map))
    }
}

impl PartialEq for GasColumns {
    /// A cache: never part of a table's value.
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for GasColumns {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let n = self.0.lock().map(|m| m.len()).unwrap_or(0);
        write!(f, "GasColumns({n} begun)")
    }
}

impl EffectiveMediumTable {
    /// Lays out the table with `table`'s spacing and range (no Bruggeman solve yet: each node,
    /// ≈ 10 ms, is solved on first use) and builds the critical-junction table with the default
    /// spacing.
    pub fn build(
        exact: PerssonContact,
        table: TableSettings,
        settings: EffectiveMediumSettings,
    ) -> Self {
        let s_contact = exact.reduced_pressure_at_area(0.5);
        let s_half = molecular_threshold(&exact, settings, s_contact, table.upper_gap);
        let ln_h = exact.spectrum().rms_roughness().ln();
        EffectiveMediumTable {
            junctions: ContactTable::build(exact, TableSettings::default()),
            settings,
            s_half,
            ln_h,
            nodes: Self::layout(table),
            gas: GasColumns::default(),
        }
    }

    /// The nodes `table` describes: `ln 10/points_per_decade` apart in `logit(s/s_half)`, from
    /// `10^-decades` of the threshold to `1 − upper_gap`.
    fn layout(table: TableSettings) -> LazyNodes {
        LazyNodes::new(
            logit(10f64.powf(-table.decades)),
            logit(1.0 - table.upper_gap),
            std::f64::consts::LN_10 / table.points_per_decade,
        )
    }

    /// The number of Bruggeman nodes built so far (liquid and gas columns): what a run paid.
    pub fn nodes_built(&self) -> usize {
        let count = |n: &LazyNodes| n.values.iter().filter(|v| v.get().is_some()).count();
        let gas = self
            .gas
            .0
            .lock()
            .map(|m| m.values().map(|c| count(c)).sum())
            .unwrap_or(0);
        count(&self.nodes) + gas
    }

    /// `12 η σ_eff` \[m³\] of a rarefied gas at `s` (docs/model.md §3.10): every separation u
    /// conducts `u³ f(λ/u)` (0 below a molecule). Cubic interpolation in ln λ between columns
    /// tabulated against s on this table's nodes (each node a Bruggeman solve, built on first
    /// use); free molecular (σ_eff ∝ λ) above λ = 1e5 h_rms. Each column is sealed from its first
    /// sealed node on, falls linearly to 0 in the cell before it, answers its first node's value
    /// below its range and continues with `(1 − s/s_half)^3` beyond it (`LazyNodes::look_up`).
    pub fn rarefied_cubed_gap(&self, s: f64, gas: crate::gas::Rarefied) -> f64 {
        let direct = |gas: crate::gas::Rarefied| {
            EffectiveMedium::persson_rarefied(
                self.junctions.exact(),
                s,
                self.settings,
                gas,
                self.channel_width(s),
            )
            .cubed_gap
        };
        let top = GAS_FREE_MOLECULAR_KN * self.ln_h.exp();
        if gas.free_path > top {
            let at_top = crate::gas::Rarefied {
                free_path: top,
                ..gas
            };
            return self.rarefied_cubed_gap(s, at_top) * (gas.free_path / top);
        }
        let r = s / self.s_half;
        if gas.free_path.is_nan() || gas.free_path <= 0.0 || !(r > 0.0 && r < 1.0) {
            // at and above the threshold the solve returns 0 before building P(u)
            return direct(gas);
        }
        let v = logit(r);
        let x = gas.free_path.ln() / GAS_COLUMN_SPACING;
        let k0 = x.floor() as i64 - 1;
        let t = x - (k0 + 1) as f64;
        let weights = [
            -t * (t - 1.0) * (t - 2.0) / 6.0,
            (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0,
            -(t + 1.0) * t * (t - 2.0) / 2.0,
            (t + 1.0) * t * (t - 1.0) / 6.0,
        ];
        let mut g = [0.0; 4];
        for (i, gi) in g.iter_mut().enumerate() {
            let Some(column) = self.gas_column(k0 + i as i64, gas.molecular_diameter) else {
                return direct(gas);
            };
            let free_path = ((k0 + i as i64) as f64 * GAS_COLUMN_SPACING).exp();
            let node = |v: f64| {
                let s = self.s_half * logistic(v);
                let em = EffectiveMedium::persson_rarefied(
                    self.junctions.exact(),
                    s,
                    self.settings,
                    crate::gas::Rarefied {
                        free_path,
                        molecular_diameter: gas.molecular_diameter,
                    },
                    self.channel_width(s),
                );
                (!em.sealed()).then(|| em.cubed_gap.ln() - 3.0 * self.ln_h)
            };
            let y = column.look_up(v, 3.0 * THRESHOLD_EXPONENT, &node);
            *gi = (y + 3.0 * self.ln_h).exp();
        }
        if g.iter().all(|&x| x > 0.0) {
            weights
                .iter()
                .zip(g)
                .map(|(w, x)| w * x.ln())
                .sum::<f64>()
                .exp()
        } else {
            weights
                .iter()
                .zip(g)
                .map(|(w, x)| w * x)
                .sum::<f64>()
                .max(0.0)
        }
    }

    /// The lateral extent of the channels at `s` \[m\]: λc of the critical junction there (at
    /// the 2-D threshold ½ once it is sealed; the shortest wavelength beyond every threshold).
    pub fn channel_width(&self, s: f64) -> f64 {
        let exact = self.junctions.exact();
        match self.junctions.critical_junction(s) {
            Junction::Leaking(j) => j.lambda_c,
            Junction::Sealed => exact
                .critical_junction_at_threshold(s, 0.5)
                .leaking()
                .map_or(2.0 * std::f64::consts::PI / exact.spectrum().q1(), |j| {
                    j.lambda_c
                }),
        }
    }

    /// The rarefied column k (ln λ = k·[`GAS_COLUMN_SPACING`]) for molecular diameter `d`: its
    /// (lazy) nodes, the liquid's from [`GAS_COLUMN_DECADES`] below the threshold on.
    fn gas_column(&self, k: i64, d: f64) -> Option<std::sync::Arc<LazyNodes>> {
        let mut map = self.gas.0.lock().ok()?;
        let column = map.entry((k, d.to_bits())).or_insert_with(|| {
            let mut column = self.nodes.empty_like();
            // the same nodes from GAS_COLUMN_DECADES below the threshold on
            let start = ((logit(10f64.powf(-GAS_COLUMN_DECADES)) / column.h).floor() as i64)
                .clamp(column.first, column.last() - 3);
            column.values.drain(..(start - column.first) as usize);
            column.first = start;
            std::sync::Arc::new(column)
        });
        Some(column.clone())
    }

    /// The critical-junction table of the same surface.
    pub fn junctions(&self) -> &ContactTable {
        &self.junctions
    }

    /// The quadrature settings of its Bruggeman solves.
    pub fn settings(&self) -> EffectiveMediumSettings {
        self.settings
    }

    /// The reduced pressure the table is laid against, at and above which the medium is sealed:
    /// where the contact fraction reaches ½, or — with a molecular size whose threshold lies
    /// below the table's last node — where `P(u ≤ molecule)` does (`molecular_threshold`).
    pub fn sealing_reduced_pressure(&self) -> f64 {
        self.s_half
    }

    /// `u_eff` \[m\] at `s = P0/E*`: interpolated in the table (see the type's docs); 0 when
    /// sealed (at and above the threshold).
    pub fn effective_gap(&self, s: f64) -> f64 {
        let r = s / self.s_half;
        if r >= 1.0 {
            // sealed at and above the threshold, which is the molecule's where one is set
            // (`molecular_threshold`): no solve, since proving a molecular seal needs the whole
            // separation distribution and a life run spends many states there
            return 0.0;
        }
        if r.is_nan() || r <= 0.0 {
            return EffectiveMedium::persson(self.junctions.exact(), s, self.settings)
                .effective_gap();
        }
        let node = |v: f64| {
            let em = EffectiveMedium::persson(
                self.junctions.exact(),
                self.s_half * logistic(v),
                self.settings,
            );
            (!em.sealed()).then(|| em.effective_gap().ln() - self.ln_h)
        };
        (self.nodes.look_up(logit(r), THRESHOLD_EXPONENT, &node) + self.ln_h).exp()
    }
}

/// The reduced pressure the effective medium of `settings` is tabulated against, at and above
/// which it is sealed (docs/model.md §3.3): `s_contact`, where the contact fraction alone reaches
/// ½, when every open gap conducts. With a molecular size m the gaps no wider than m count as
/// contact and the medium seals where `P(u ≤ m)` reaches ½ ([`super::SeparationDistribution::cdf`],
/// which rises with the pressure: more contact, narrower gaps). Where that happens above the
/// table's last node, `(1 − upper_gap) s_contact`, the table is unchanged and the direct solves
/// beyond its last node find the threshold (one distribution built to check); below it, the
/// threshold is found by Illinois in ln s (to 1e-10, over 15 decades) and the grid is laid
/// against it, so that the approach to the medium's own threshold is tabulated.
fn molecular_threshold(
    exact: &PerssonContact,
    settings: EffectiveMediumSettings,
    s_contact: f64,
    upper_gap: f64,
) -> f64 {
    let m = settings.molecular_size;
    // no molecule (0, or NaN from a bad size): the threshold is the contact's own
    if m.is_nan() || m <= 0.0 {
        return s_contact;
    }
    // P(u ≤ m) − ½ (≥ 0: sealed) is smooth in ln s: Illinois brackets its root in ~10
    // distributions where bisection to 1e-10 took ~40 (each a whole separation distribution);
    // the bracket's upper end is the threshold
    let g = |x: f64| super::SeparationDistribution::persson(exact, x.exp(), settings).cdf(m) - 0.5;
    let last = (s_contact * (1.0 - upper_gap)).ln();
    let g_last = g(last);
    if g_last < 0.0 {
        return s_contact;
    }
    let floor = (s_contact * 1e-15).ln();
    let g_floor = g(floor);
    if g_floor >= 0.0 {
        return floor.exp();
    }
    let (_, b) = crate::math::roots::illinois(g, (floor, g_floor), (last, g_last), 1e-10);
    b.exp()
}

/// `ln(r/(1−r))`: log-uniform for r → 0, stretched towards the sealing end r → 1 (the grid
/// variable of every table against P0/E*).
pub(crate) fn logit(r: f64) -> f64 {
    r.ln() - (-r).ln_1p()
}

/// Inverse of [`logit`].
pub(crate) fn logistic(v: f64) -> f64 {
    1.0 / (1.0 + (-v).exp())
}
