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
use std::sync::OnceLock;

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

    /// The effective-medium table's default: 8 points per decade over 6 decades below the
    /// threshold (each node costs a Bruggeman solve; measured worst error vs the direct solve in
    /// tests/model/effective_medium.rs).
    pub fn effective_medium() -> Self {
        TableSettings {
            points_per_decade: 8.0,
            decades: 6.0,
            upper_gap: 0.03,
            extension: 0.0,
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
#[derive(Debug, Clone, PartialEq)]
pub struct ContactTable {
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

#[derive(Debug, Clone, PartialEq)]
struct Grid {
    /// `ln(u_c/h_rms)` against `logit(s/s_seal)`.
    u_c: UniformCubic,
    /// `ln(ū_c/h_rms)` against `logit(s/s_seal)`.
    ubar_c: UniformCubic,
}

impl ContactTable {
    /// Builds the table by evaluating the exact path at every node.
    pub fn build(exact: PerssonContact, settings: TableSettings) -> Self {
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
        ContactTable {
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

    /// The exact path the table was built from.
    pub fn exact(&self) -> &PerssonContact {
        &self.exact
    }

    /// Range of `P0/E*` the table covers, its extension included (`None`: no table); outside
    /// it lookups are exact.
    pub fn range(&self) -> Option<(f64, f64)> {
        let (a, b) = self.grid.as_ref()?.u_c.range();
        Some((
            self.s_seal * logistic(a.min(self.low_start)),
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
/// (docs/model.md §3.3), built once per surface like [`ContactTable`]: `ln(u_eff/h_rms)` on a uniform
/// grid in `logit(s/s_half)`, where `s_half = erfinv(½) √(π M3(q1))` (with the corrected area
/// [`PerssonContact::reduced_pressure_at_area`]) is the pressure at which
/// the contact fraction reaches the 2-D threshold ½ and σ_eff vanishes (linearly in u_eff).
/// Outside the tabulated range (and within `upper_gap` of `s_half`) the Bruggeman solve
/// answers directly. It also carries the critical-junction table of the same surface, whose
/// ζc and λc describe the channels (clogging, validity warnings).
#[derive(Debug, Clone, PartialEq)]
pub struct EffectiveMediumTable {
    junctions: ContactTable,
    settings: EffectiveMediumSettings,
    s_half: f64,
    ln_h: f64,
    grid: Option<UniformCubic>,
    /// The logit grid of `grid` (start, spacing, nodes): the gas columns share it.
    layout: (f64, f64, usize),
    /// A rarefied gas: `12 η σ_eff` against s, one column per node of ln λ (built on first use).
    gas: GasColumns,
}

/// Spacing of the rarefied columns in ln λ (docs/model.md §3.10): ln(12ησ_eff) is smooth in
/// ln λ (it goes from ln u³ to ln λ + const), so cubic interpolation over e-fold steps is
/// accurate to ≈ 1e-4 (measured in tests/model/effective_medium.rs).
const GAS_COLUMN_SPACING: f64 = 1.0;

/// Above this Knudsen number over the surface's rms height, the rarefied effective medium is
/// taken as free molecular: every local conductance proportional to λ, so σ_eff ∝ λ (Bruggeman
/// is homogeneous of degree one in the conductances).
const GAS_FREE_MOLECULAR_KN: f64 = 1e5;

/// The rarefied columns of an [`EffectiveMediumTable`], keyed by the node index k of
/// ln λ = k·[`GAS_COLUMN_SPACING`] and the molecular diameter's bits; built once each, on two
/// threads, and shared by clones made afterwards. `None` for a column the solve could not
/// tabulate (fewer than four open nodes): lookups then solve directly.
#[derive(Default)]
struct GasColumns(std::sync::Mutex<ColumnMap>);

/// `(k, molecular diameter bits) → column` (`None`: not tabulable).
type ColumnMap = std::collections::BTreeMap<(i64, u64), Option<std::sync::Arc<GasColumn>>>;

/// One rarefied column: `ln(12ησ_eff) − 3 ln h_rms` on the table's logit grid up to its last
/// open node, and the logit of the first sealed node (`None`: open to the grid's end).
#[derive(Debug, Clone)]
struct GasColumn {
    cubic: UniformCubic,
    sealed_from: Option<f64>,
}

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
        write!(f, "GasColumns({n} built)")
    }
}

impl EffectiveMediumTable {
    /// Tabulates u_eff with `table` spacing (each node one Bruggeman solve, ≈ 5 ms) and builds
    /// the critical-junction table with the default spacing.
    pub fn build(
        exact: PerssonContact,
        table: TableSettings,
        settings: EffectiveMediumSettings,
    ) -> Self {
        let s_contact = exact.reduced_pressure_at_area(0.5);
        let s_half = molecular_threshold(&exact, settings, s_contact, table.upper_gap);
        let ln_h = exact.spectrum().rms_roughness().ln();
        let (lo, h, n) = table.logit_grid();
        // Each node is an independent Bruggeman solve of a few ms: two threads take alternate
        // nodes (the result does not depend on the split).
        let node = |i: usize| {
            let em =
                EffectiveMedium::persson(&exact, s_half * logistic(lo + h * i as f64), settings);
            (!em.sealed()).then(|| em.effective_gap().ln() - ln_h)
        };
        let values: Vec<f64> = crate::math::map_on_two_threads(n, node)
            .into_iter()
            .map_while(|v| v)
            .collect();
        let grid = (values.len() >= 4).then(|| UniformCubic::new(lo, h, values));
        EffectiveMediumTable {
            junctions: ContactTable::build(exact, TableSettings::default()),
            settings,
            s_half,
            ln_h,
            grid,
            layout: (lo, h, n),
            gas: GasColumns::default(),
        }
    }

    /// `12 η σ_eff` \[m³\] of a rarefied gas at `s` (docs/model.md §3.10): every separation u
    /// conducts `u³ f(λ/u)` (0 below a molecule). Cubic interpolation in ln λ between columns
    /// tabulated against s on this table's grid (each column ≈ 0.25 s, built on first use);
    /// free molecular (σ_eff ∝ λ) above λ = 1e5 h_rms; below the columns' range in s (1e-6 of
    /// the threshold) the value at its start; solved directly above it, next to the threshold.
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
        if gas.free_path.is_nan() || gas.free_path <= 0.0 {
            return direct(gas);
        }
        let v = logit(s / self.s_half);
        let x = gas.free_path.ln() / GAS_COLUMN_SPACING;
        let k0 = x.floor() as i64 - 1;
        let t = x - (k0 + 1) as f64;
        let weights = [
            -t * (t - 1.0) * (t - 2.0) / 6.0,
            (t + 1.0) * (t - 1.0) * (t - 2.0) / 2.0,
            -(t + 1.0) * t * (t - 2.0) / 2.0,
            (t + 1.0) * t * (t - 1.0) / 6.0,
        ];
        if v.is_nan() {
            return direct(gas);
        }
        let mut g = [0.0; 4];
        for (i, gi) in g.iter_mut().enumerate() {
            let Some(column) = self.gas_column(k0 + i as i64, gas.molecular_diameter) else {
                return direct(gas);
            };
            let (a, b) = column.cubic.range();
            let at = |v: f64| (column.cubic.eval(v) + 3.0 * self.ln_h).exp();
            *gi = if v <= b {
                // below the range (s < 1e-6 of the threshold: the open inlet of a profile,
                // where the resistance is least) the range's first value, not a solve per call
                at(v.max(a))
            } else {
                match column.sealed_from {
                    // sealed at and beyond the first sealed node; in the one grid cell before
                    // it, linear in v down to 0 there (the gas's threshold lies in that cell)
                    Some(sealed) if v >= sealed => 0.0,
                    Some(sealed) => at(b) * (sealed - v) / (sealed - b),
                    None => return direct(gas),
                }
            };
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

    /// The rarefied column k (ln λ = k·[`GAS_COLUMN_SPACING`]) for molecular diameter `d`.
    fn gas_column(&self, k: i64, d: f64) -> Option<std::sync::Arc<GasColumn>> {
        let key = (k, d.to_bits());
        if let Some(c) = self.gas.0.lock().ok()?.get(&key) {
            return c.clone();
        }
        let gas = crate::gas::Rarefied {
            free_path: (k as f64 * GAS_COLUMN_SPACING).exp(),
            molecular_diameter: d,
        };
        let (lo, h, n) = self.layout;
        let node = |i: usize| {
            let s = self.s_half * logistic(lo + h * i as f64);
            let em = EffectiveMedium::persson_rarefied(
                self.junctions.exact(),
                s,
                self.settings,
                gas,
                self.channel_width(s),
            );
            (!em.sealed()).then(|| em.cubed_gap.ln() - 3.0 * self.ln_h)
        };
        let values: Vec<f64> = crate::math::map_on_two_threads(n, node)
            .into_iter()
            .map_while(|v| v)
            .collect();
        let sealed_from = (values.len() < n).then_some(lo + h * values.len() as f64);
        let column = (values.len() >= 4).then(|| {
            std::sync::Arc::new(GasColumn {
                cubic: UniformCubic::new(lo, h, values),
                sealed_from,
            })
        });
        self.gas.0.lock().ok()?.insert(key, column.clone());
        column
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
    /// below the table's last node — where `P(u ≤ molecule)` does ([`molecular_threshold`]).
    pub fn sealing_reduced_pressure(&self) -> f64 {
        self.s_half
    }

    /// `u_eff` \[m\] at `s = P0/E*`: interpolated inside the table, solved outside; 0 when
    /// sealed (at and above [`Self::sealing_reduced_pressure`]).
    pub fn effective_gap(&self, s: f64) -> f64 {
        if s >= self.s_half {
            return 0.0;
        }
        let v = logit(s / self.s_half);
        match &self.grid {
            Some(g) if v >= g.range().0 && v <= g.range().1 => (g.eval(v) + self.ln_h).exp(),
            _ => EffectiveMedium::persson(self.junctions.exact(), s, self.settings).effective_gap(),
        }
    }
}

/// The reduced pressure the effective medium of `settings` is tabulated against, at and above
/// which it is sealed (docs/model.md §3.3): `s_contact`, where the contact fraction alone reaches
/// ½, when every open gap conducts. With a molecular size m the gaps no wider than m count as
/// contact and the medium seals where `P(u ≤ m)` reaches ½ ([`super::SeparationDistribution::cdf`],
/// which rises with the pressure: more contact, narrower gaps). Where that happens above the
/// table's last node, `(1 − upper_gap) s_contact`, the table is unchanged and the direct solves
/// beyond its last node find the threshold (one distribution built to check); below it, the
/// threshold is found by bisection in ln s (to 1e-10, over 15 decades) and the grid is laid
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
    let sealed = |s: f64| super::SeparationDistribution::persson(exact, s, settings).cdf(m) >= 0.5;
    let last = s_contact * (1.0 - upper_gap);
    if !sealed(last) {
        return s_contact;
    }
    let floor = s_contact * 1e-15;
    if sealed(floor) {
        return floor;
    }
    let (_, hi) = crate::math::roots::bisect(
        floor.ln(),
        last.ln(),
        200,
        |lo, hi| hi - lo <= 1e-10,
        |x| !sealed(x.exp()),
    );
    hi.exp()
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
