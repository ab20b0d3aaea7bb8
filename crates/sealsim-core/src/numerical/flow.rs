//! Thin-film Reynolds flow through a gap field (docs/model.md §3.5): effective conductance of the
//! non-contact region of a periodic cell.
//!
//! # Model
//!
//! Laminar flow of a Newtonian fluid (viscosity η) in the gap `u(x, y)` between the rubber and
//! the countersurface. Flux per unit width `J = −σ(u) ∇p`, local conductance `σ(u) = u³/(12η)`
//! (m³/(Pa·s)); mass conservation `∇·(σ ∇p) = 0` (Reynolds equation).
//!
//! # Effective conductance of a periodic cell
//!
//! The cell is `L × L`, `L = n·pixel`, periodic in y (across the flow) and periodic in x *with a
//! jump*: `p(x + L, y) = p(x, y) − ΔP`. Writing `p = −ΔP x/L + φ` with φ periodic in both
//! directions, this is the standard homogenisation cell problem: the solution is the flow
//! through an infinite seal made of copies of the cell under the mean gradient `ΔP/L`. The
//! effective conductance σ_eff is defined by the mean flux per unit width across the flow:
//!
//! ```text
//! ⟨J_x⟩ = Q_cross / L_y = σ_eff ΔP / L_x,     i.e. σ_eff = Q_cross L_x / (L_y ΔP),
//! ```
//!
//! with `Q_cross` the volume flow (m³/s) through any cross-section x = const (the same for every
//! cross-section: conservation). For a seal of width `L_x` (along the flow) and length `L_y`
//! (across it) built from such cells, the leak rate is `Q̇ = (L_y/L_x) σ_eff ΔP` — the form of
//! docs/model.md §3.3 (effective medium) and §3.1 with `σ_eff = α u_c³/(12η)`. The *effective gap* is
//! `(12 η σ_eff)^{1/3}`, the uniform gap with the same conductance (compare with u_c).
//!
//! For a square cell σ_eff does not depend on the pixel size (a 2-D conductance is scale-free);
//! `pixel` is only checked. If nothing percolates along x, σ_eff = 0 exactly.
//!
//! Dynamic range (f64): σ_eff is accurate to ~1e-8 down to σ_eff ≈ 1e-18 of the largest cell
//! conductance u_max³/(12η) (a constriction gap 1e-6 of the widest), to ~1e-4 at 1e-21 (gap
//! 1e-7), and to ~1e-6 for a closed-form line of gap 1e-8 of the widest (σ 1e-24); measured on
//! a line of thin cells across the flow and just above the percolation threshold. Further down
//! the pressure in the wide channels is not known well enough and the result is an upper bound
//! set by round-off — the interface is then sealed for any practical purpose. Gaps below ~1e-51
//! of the widest are treated as contact.
//!
//! # Discretisation
//!
//! Finite volumes on the cells of the gap grid (row-major `gap[iy * n + ix]`, x along the flow,
//! the layout of [`super::HeightMap`]). The conductance of the face between two cells is the
//! harmonic mean of their σ, `2σ_aσ_b/(σ_a + σ_b)` — the exact series value of two half-cells, so
//! a step of the gap along the flow is reproduced exactly — and zero if either cell is in
//! contact (`gap = 0`: no flux into contact). Face flux `g (p_a − p_b)` (in 2-D the face length
//! and the centre distance are both `pixel` and cancel).
//!
//! Only the clusters of open cells that wind around x ([`super::percolation`]) can carry a net
//! flux; lakes, pockets and clusters winding in y only have constant pressure and are left out.
//! On each spanning cluster φ is defined up to a constant: one cell per cluster is pinned
//! (φ = 0), which makes the system symmetric positive definite without changing the fluxes.
//!
//! # Solver
//!
//! The system is a [`GridLaplacian`] (the five-point operator of the face conductances, the
//! pinned cells as sinks), solved by preconditioned conjugate gradients ([`crate::math::cg`],
//! flexible Polak–Ribière form), from φ = 0, stopped when
//! the relative residual `‖b − Aφ‖₂/‖b‖₂` (true residual, recomputed at the end) is below the
//! tolerance (default 1e-10) and — given a few more iterations if needed — the energy decrement
//! of the last step is below the tolerance times the current dissipation. σ_eff is evaluated
//! from the dissipation `Σ_faces g Δp²` (= `Q_cross ΔP`), which is variational: its error is quadratic in the error of φ. Near the
//! percolation threshold, where the flow is set by one constriction many decades narrower than
//! the wide channels, this keeps σ_eff accurate (the preconditioners agree to ~1e-10 with a
//! constriction 1e-12 of the largest conductance) although the residual, and with it the
//! balance of the cross-section fluxes, is dominated by the wide channels.
//!
//! Preconditioners ([`Preconditioner`]):
//! * `Jacobi` — diagonal; cheap per iteration, but the iteration count grows like `n` and with
//!   the conductance contrast;
//! * `IncompleteCholesky` — modified incomplete Cholesky MIC(0) (natural order, relaxation
//!   0.97; [`crate::math::cholesky`]); about 5× fewer iterations than Jacobi, sequential
//!   triangular solves;
//! * `Multigrid` (default) — aggregation algebraic multigrid with geometric guidance
//!   ([`crate::math::multigrid`]): aggregates
//!   are the strongly connected components of the nodes of 2 × 2 blocks (a face is strong when
//!   its conductance is at least 0.25 of the largest face of both its cells, so no aggregate
//!   straddles a constriction; a node left alone joins the neighbour it is most strongly tied
//!   to), Galerkin coarse operators (piecewise-constant prolongation: the coarse conductance
//!   between two aggregates is the sum of the fine faces between them), symmetric Gauss–Seidel
//!   smoothing, K-cycle on the coarse levels (Notay & Vassilevski 2008), dense Cholesky on the
//!   coarsest (≤ 400 unknowns). About 25–40 iterations independent of the grid size on rough
//!   gap fields with 20–30 % contact, and just above the percolation threshold.

use super::percolation;
use crate::math::cg;
use crate::math::cholesky::ModifiedIncompleteCholesky;
use crate::math::dot;
use crate::math::laplacian::GridLaplacian;
use crate::math::multigrid::Multigrid;
use crate::units::show;

/// Direction of the mean pressure drop on the grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Direction {
    /// Along x (`ix`), the flow direction of [`super::HeightMap`].
    #[default]
    X,
    /// Along y (`iy`): the transposed problem.
    Y,
}

/// Preconditioner of the conjugate-gradient solve; see the module docs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Preconditioner {
    /// Diagonal scaling.
    Jacobi,
    /// Modified incomplete Cholesky, MIC(0).
    IncompleteCholesky,
    /// Aggregation multigrid (K-cycle).
    #[default]
    Multigrid,
}

/// Settings of [`solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowSettings {
    /// Relative residual `‖b − Aφ‖₂/‖b‖₂` at which the solve stops (default 1e-10); a few more
    /// iterations are spent, if needed, until the energy decrement of the last step is also below
    /// this fraction of the dissipation (see the module docs).
    pub tolerance: f64,
    /// Maximum number of conjugate-gradient iterations (default 100 000).
    pub max_iterations: usize,
    /// Preconditioner (default multigrid).
    pub preconditioner: Preconditioner,
    /// Direction of the mean pressure drop (default x).
    pub direction: Direction,
    /// A rarefied gas (docs/model.md §3.10): every cell's conductance u³/(12η) times the slit
    /// factor f(λ/u, pixel/u) at this mean free path, 0 for a gap no wider than a molecule
    /// (`None`: a liquid, the default).
    pub gas: Option<crate::gas::Rarefied>,
    /// The size of one molecule of the fluid \[m\] ([`crate::fluid::Fluid::molecular_size`]): a
    /// cell whose gap is no wider conducts nothing and counts as contact
    /// ([`crate::fluid::passes_molecule`], docs/model.md §8.1). 0 (the default): every open cell
    /// conducts; a contact path sets its fluid's (`leak::PathOptions::molecular_size`).
    pub molecular_size: f64,
}

impl Default for FlowSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            max_iterations: 100_000,
            preconditioner: Preconditioner::default(),
            direction: Direction::default(),
            gas: None,
            molecular_size: 0.0,
        }
    }
}

/// Effective conductance of a gap field; see the module docs for the definitions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowSolution {
    /// Effective conductance σ_eff (m³/(Pa·s)): mean flux per unit width across the flow
    /// `= σ_eff ΔP / L_x`. Exactly 0 when nothing percolates.
    pub conductance: f64,
    /// Effective gap `(12 η σ_eff)^{1/3}` (m).
    pub effective_gap: f64,
    /// Conjugate-gradient iterations.
    pub iterations: usize,
    /// Final relative residual `‖b − Aφ‖₂/‖b‖₂` (true residual; 0 when the right-hand side is 0,
    /// e.g. a gap that does not vary along the flow).
    pub residual: f64,
    /// Whether the open region percolates along the flow.
    pub percolates: bool,
    /// Fraction of cells in contact (`gap = 0`).
    pub contact_fraction: f64,
    /// Fraction of cells in a spanning cluster (the unknowns of the solve).
    pub spanning_fraction: f64,
}

impl FlowSolution {
    /// The interface as the leak law sees it: a uniform conductance per unit width σ_eff
    /// (m³/(Pa·s)); the leak rate is [`crate::fluid::Fluid::leak_rate`] over the seal's
    /// geometry, `Q̇ = (L_y/L_x) σ_eff ΔP` (docs/model.md §3.5).
    pub fn conduction(&self) -> crate::fluid::Conduction {
        crate::fluid::Conduction::Uniform {
            conductance: self.conductance,
        }
    }
}

/// A solution with its fields, for inspection and conservation checks ([`solve_field`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FlowField {
    /// The scalar results.
    pub solution: FlowSolution,
    /// Pressure (Pa) for a unit pressure drop ΔP = 1 Pa along the flow, `p = φ − x/L` with
    /// `x = (i + ½)·pixel` the cell centre along the flow, on the original grid layout;
    /// φ has an arbitrary constant per spanning cluster. NaN outside the spanning clusters.
    pub pressure: Vec<f64>,
    /// Volume flow (m³/s) for ΔP = 1 Pa through each of the `n` cross-sections between
    /// consecutive cells along the flow (entry `i`: between cells `i` and `i + 1 mod n`). Equal
    /// to σ_eff·(L_y/L_x)·1 Pa in every cross-section up to the residual: relative to σ_eff
    /// within about the tolerance when the conductance contrast is moderate, much less
    /// precisely just above the percolation threshold (see the module docs).
    pub cross_section_flux: Vec<f64>,
}

/// Why a flow solve failed.
#[derive(Debug, Clone, PartialEq)]
pub enum FlowError {
    /// `gap.len()` is not `n²`, or `n < 2`.
    Size {
        /// Length of the gap field.
        len: usize,
        /// Requested side.
        n: usize,
    },
    /// A gap value is negative or not finite.
    InvalidGap {
        /// Cell index.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A parameter (pixel, viscosity, tolerance) is not positive and finite.
    InvalidParameter(&'static str),
    /// The conjugate-gradient solve did not reach the tolerance.
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// Relative residual reached.
        residual: f64,
    },
}

impl std::fmt::Display for FlowError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Size { len, n } => write!(
                f,
                "gap field of {len} values is not an n × n grid with n = {n} ≥ 2"
            ),
            Self::InvalidGap { index, value } => {
                write!(
                    f,
                    "gap value {} at cell {index} is negative or not finite",
                    show(*value)
                )
            }
            Self::InvalidParameter(what) => write!(f, "{what} must be positive and finite"),
            Self::NotConverged {
                iterations,
                residual,
            } => write!(
                f,
                "Reynolds solve did not converge: relative residual {} after {iterations} \
                 iterations",
                show(*residual)
            ),
        }
    }
}

impl std::error::Error for FlowError {}

/// Effective conductance of the gap field `gap` (m, `n × n` row-major, exactly 0 in contact)
/// of a periodic cell with `pixel` spacing (m), for a fluid of `viscosity` η (Pa·s).
pub fn solve(
    gap: &[f64],
    n: usize,
    pixel: f64,
    viscosity: f64,
    settings: &FlowSettings,
) -> Result<FlowSolution, FlowError> {
    solve_field(gap, n, pixel, viscosity, settings).map(|f| f.solution)
}

/// As [`solve`], with the pressure field and the flux through every cross-section.
pub fn solve_field(
    gap: &[f64],
    n: usize,
    pixel: f64,
    viscosity: f64,
    settings: &FlowSettings,
) -> Result<FlowField, FlowError> {
    if n < 2 || gap.len() != n * n {
        return Err(FlowError::Size { len: gap.len(), n });
    }
    if let Some((index, &value)) = gap
        .iter()
        .enumerate()
        .find(|&(_, u)| !(u.is_finite() && *u >= 0.0))
    {
        return Err(FlowError::InvalidGap { index, value });
    }
    if !(pixel.is_finite() && pixel > 0.0) {
        return Err(FlowError::InvalidParameter("pixel size"));
    }
    if !(viscosity.is_finite() && viscosity > 0.0) {
        return Err(FlowError::InvalidParameter("viscosity"));
    }
    if !(settings.tolerance.is_finite() && settings.tolerance > 0.0) {
        return Err(FlowError::InvalidParameter("tolerance"));
    }
    let transposed;
    let gap = match settings.direction {
        Direction::X => gap,
        Direction::Y => {
            transposed = transpose(gap, n);
            &transposed[..]
        }
    };
    let mut field = solve_x(gap, n, pixel, viscosity, settings)?;
    if settings.direction == Direction::Y {
        field.pressure = transpose(&field.pressure, n);
    }
    Ok(field)
}

fn transpose(a: &[f64], n: usize) -> Vec<f64> {
    let mut t = vec![0.0; n * n];
    for iy in 0..n {
        for ix in 0..n {
            t[ix * n + iy] = a[iy * n + ix];
        }
    }
    t
}

/// The solve along x on a validated field.
fn solve_x(
    gap: &[f64],
    n: usize,
    pixel: f64,
    viscosity: f64,
    settings: &FlowSettings,
) -> Result<FlowField, FlowError> {
    let cells = n * n;
    // Cell conductances u³/(12η) (a gas: times its slit factor, a cell as wide as a pixel),
    // scaled by their maximum. A gap so thin that its scaled conductance is below
    // √(f64::MIN_POSITIVE) ≈ 1.5e-154 (u below ~1e-51 of the widest gap) counts as contact, so
    // that no face conductance underflows to zero inside a cluster; so does a gap no wider than
    // a molecule of the fluid (it passes nothing, docs/model.md §8.1).
    let sigma_of = |u: f64| {
        if !crate::fluid::passes_molecule(u, settings.molecular_size) {
            return 0.0;
        }
        let liquid = u * u * u / (12.0 * viscosity);
        match settings.gas {
            Some(g) if u > 0.0 => liquid * g.factor(u, pixel),
            _ => liquid,
        }
    };
    let scale = gap.iter().map(|&u| sigma_of(u)).fold(0.0, f64::max);
    let floor = f64::MIN_POSITIVE.sqrt();
    let open: Vec<bool> = gap
        .iter()
        .map(|&u| scale > 0.0 && sigma_of(u) / scale >= floor)
        .collect();
    let perc = percolation::analyse(&open, n);
    let empty = || FlowField {
        solution: FlowSolution {
            conductance: 0.0,
            effective_gap: 0.0,
            iterations: 0,
            residual: 0.0,
            percolates: false,
            contact_fraction: perc.contact_fraction,
            spanning_fraction: perc.spanning_fraction,
        },
        pressure: vec![f64::NAN; cells],
        cross_section_flux: vec![0.0; n],
    };
    if !perc.percolates() {
        return Ok(empty());
    }
    // Rescaled by the largest conductance of the spanning cells (what is left out does not
    // change the numbers).
    let scale = perc
        .labels
        .iter()
        .zip(gap)
        .filter(|(l, _)| l.is_some())
        .map(|(_, &u)| sigma_of(u))
        .fold(0.0, f64::max);
    let sigma: Vec<f64> = perc
        .labels
        .iter()
        .zip(gap)
        .map(|(l, &u)| {
            if l.is_some() {
                sigma_of(u) / scale
            } else {
                0.0
            }
        })
        .collect();
    let harmonic = |a: f64, b: f64| {
        if a > 0.0 && b > 0.0 {
            2.0 * a * b / (a + b)
        } else {
            0.0
        }
    };
    // Physical face conductances (east and north faces of every cell).
    let mut face_e = vec![0.0; cells];
    let mut face_n = vec![0.0; cells];
    for iy in 0..n {
        for ix in 0..n {
            let i = iy * n + ix;
            face_e[i] = harmonic(sigma[i], sigma[iy * n + (ix + 1) % n]);
            face_n[i] = harmonic(sigma[i], sigma[((iy + 1) % n) * n + ix]);
        }
    }
    // Pin the cell of largest diagonal in every spanning cluster.
    let degree = |i: usize| {
        let (ix, iy) = (i % n, i / n);
        face_e[i]
            + face_e[iy * n + (ix + n - 1) % n]
            + face_n[i]
            + face_n[((iy + n - 1) % n) * n + ix]
    };
    let mut pin: Vec<Option<(usize, f64)>> = vec![None; perc.spanning_clusters];
    for (i, l) in perc.labels.iter().enumerate() {
        if let Some(k) = l {
            let d = degree(i);
            let slot = &mut pin[*k as usize];
            if slot.is_none_or(|(_, best)| d > best) {
                *slot = Some((i, d));
            }
        }
    }
    let mut active: Vec<bool> = perc.labels.iter().map(Option::is_some).collect();
    for (i, _) in pin.iter().flatten() {
        active[*i] = false;
    }
    let grid = GridLaplacian::new(n, &face_e, &face_n, &active);
    // Right-hand side for ΔP = 1 (a drop of 1/n per cell): b_i = (g_west − g_east)/n.
    let h = 1.0 / n as f64;
    let mut b = vec![0.0; cells];
    for iy in 0..n {
        for ix in 0..n {
            let i = iy * n + ix;
            if active[i] {
                b[i] = (face_e[iy * n + (ix + n - 1) % n] - face_e[i]) * h;
            }
        }
    }
    let mut phi = vec![0.0; cells];
    // Dissipation Σ_faces g Δp² of p = φ − x/L (= Q_cross ΔP for ΔP = 1).
    let dissipation = |phi: &[f64]| {
        let mut d = 0.0;
        for iy in 0..n {
            let north = ((iy + 1) % n) * n;
            for ix in 0..n {
                let i = iy * n + ix;
                let dx = phi[i] - phi[iy * n + (ix + 1) % n] + h;
                let dy = phi[i] - phi[north + ix];
                d += face_e[i] * dx * dx + face_n[i] * dy * dy;
            }
        }
        d
    };
    let (iterations, residual) = pcg(&grid, &b, &mut phi, &dissipation, settings)?;
    // Flux through every cross-section (between column c and c + 1), ΔP = 1.
    let mut flux = vec![0.0; n];
    for iy in 0..n {
        for (ix, q) in flux.iter_mut().enumerate() {
            let i = iy * n + ix;
            let e = iy * n + (ix + 1) % n;
            *q += face_e[i] * (phi[i] - phi[e] + h);
        }
    }
    for q in &mut flux {
        *q *= scale;
    }
    // σ_eff from the dissipation Σ g Δp² (= Q_cross ΔP for ΔP = 1): a sum of positive terms,
    // exact to O(‖error‖²_A) (variational), where the cross-section fluxes are only first order.
    let conductance = dissipation(&phi) * scale;
    let pressure = (0..cells)
        .map(|i| {
            if perc.labels[i].is_some() {
                phi[i] - ((i % n) as f64 + 0.5) * h
            } else {
                f64::NAN
            }
        })
        .collect();
    Ok(FlowField {
        solution: FlowSolution {
            conductance,
            effective_gap: (12.0 * viscosity * conductance).cbrt(),
            iterations,
            residual,
            percolates: true,
            contact_fraction: perc.contact_fraction,
            spanning_fraction: perc.spanning_fraction,
        },
        pressure,
        cross_section_flux: flux,
    })
}

// ---------------------------------------------------------------------------------------------
// The solver: conjugate gradients (crate::math::cg) with the chosen preconditioner.

/// Relaxation of the modified incomplete Cholesky (1 = row sums preserved exactly, 0 = IC(0)).
const MIC_RELAXATION: f64 = 0.97;

/// The preconditioner selected by [`Preconditioner`].
enum Precond<'a> {
    Jacobi(cg::Jacobi<'a>),
    Mic(ModifiedIncompleteCholesky<'a>),
    Multigrid(Box<Multigrid>),
}

impl<'a> Precond<'a> {
    fn new(kind: Preconditioner, grid: &'a GridLaplacian) -> Self {
        match kind {
            Preconditioner::Jacobi => Self::Jacobi(cg::Jacobi {
                inverse_diagonal: grid.inverse_diagonal(),
            }),
            Preconditioner::IncompleteCholesky => {
                Self::Mic(ModifiedIncompleteCholesky::new(grid, MIC_RELAXATION))
            }
            Preconditioner::Multigrid => Self::Multigrid(Box::new(Multigrid::new(grid.clone()))),
        }
    }
}

impl cg::Preconditioner for Precond<'_> {
    fn apply(&mut self, r: &[f64], z: &mut [f64]) {
        match self {
            Self::Jacobi(m) => m.apply(r, z),
            Self::Mic(m) => m.solve(r, z),
            Self::Multigrid(m) => m.apply(r, z),
        }
    }
}

/// Solves A φ = b from φ = 0 by preconditioned conjugate gradients ([`cg::solve`]); returns
/// (iterations, true relative residual). Once the residual criterion holds, the energy decrement
/// of the last step must also be below `tolerance ×` the dissipation D(φ) (see the module docs):
/// near the percolation threshold the residual is dominated by the wide channels while the flow
/// is set by a constriction. The preconditioner is built only for a non-zero right-hand side.
fn pcg(
    grid: &GridLaplacian,
    b: &[f64],
    x: &mut [f64],
    dissipation: &dyn Fn(&[f64]) -> f64,
    settings: &FlowSettings,
) -> Result<(usize, f64), FlowError> {
    if dot(b, b) == 0.0 {
        x.fill(0.0);
        return Ok((0, 0.0));
    }
    let mut precond = Precond::new(settings.preconditioner, grid);
    let cg_settings = cg::Settings {
        tolerance: settings.tolerance,
        max_iterations: settings.max_iterations,
    };
    cg::solve(grid, &mut precond, b, x, Some(dissipation), &cg_settings)
        .map(|c| (c.iterations, c.residual))
        .map_err(|e| FlowError::NotConverged {
            iterations: e.iterations,
            residual: e.residual,
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use rand_chacha::ChaCha8Rng;
    use rand_core::{RngCore, SeedableRng};

    const ETA: f64 = 1e-3;
    const PIXEL: f64 = 1e-7;
    const ALL: [Preconditioner; 3] = [
        Preconditioner::Jacobi,
        Preconditioner::IncompleteCholesky,
        Preconditioner::Multigrid,
    ];

    fn settings(preconditioner: Preconditioner) -> FlowSettings {
        FlowSettings {
            preconditioner,
            ..FlowSettings::default()
        }
    }

    fn sigma(u: f64) -> f64 {
        u * u * u / (12.0 * ETA)
    }

    fn grid(n: usize, gap: impl Fn(usize, usize) -> f64) -> Vec<f64> {
        (0..n * n).map(|i| gap(i % n, i / n)).collect()
    }

    fn uniform01(rng: &mut ChaCha8Rng) -> f64 {
        (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A smooth periodic random gap field: `max(0, d − h)` with `h` a sum of random cosines of
    /// power-law amplitude (H = 0.8) and `d` the height below which `1 − contact` of the cells
    /// lie.
    fn rough_gap(n: usize, modes: usize, contact: f64, seed: u64) -> Vec<f64> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let kmax = (n / 4).max(2) as f64;
        let table: Vec<(f64, f64)> = (0..n)
            .map(|j| {
                let a = 2.0 * std::f64::consts::PI * j as f64 / n as f64;
                (a.cos(), a.sin())
            })
            .collect();
        let mut h = vec![0.0; n * n];
        for _ in 0..modes {
            let (kx, ky) = loop {
                let kx = (uniform01(&mut rng) * (2.0 * kmax + 1.0)) as i64 - kmax as i64;
                let ky = (uniform01(&mut rng) * (2.0 * kmax + 1.0)) as i64 - kmax as i64;
                let k = ((kx * kx + ky * ky) as f64).sqrt();
                if k >= 1.0 && k <= kmax {
                    break (kx, ky);
                }
            };
            let k = ((kx * kx + ky * ky) as f64).sqrt();
            let amp = k.powf(-1.8);
            let phase = 2.0 * std::f64::consts::PI * uniform01(&mut rng);
            let kxu = kx.rem_euclid(n as i64) as usize;
            let kyu = ky.rem_euclid(n as i64) as usize;
            for iy in 0..n {
                let (cb, sb) = table[(kyu * iy) % n];
                let (cp, sp) = (phase.cos(), phase.sin());
                let (c, s) = (amp * (cb * cp - sb * sp), amp * (sb * cp + cb * sp));
                let row = &mut h[iy * n..(iy + 1) * n];
                for (ix, v) in row.iter_mut().enumerate() {
                    let (ca, sa) = table[(kxu * ix) % n];
                    *v += c * ca - s * sa;
                }
            }
        }
        let mut sorted = h.clone();
        sorted.sort_by(f64::total_cmp);
        let d = sorted[((1.0 - contact) * (n * n) as f64) as usize];
        let rms = (h.iter().map(|v| v * v).sum::<f64>() / (n * n) as f64).sqrt();
        h.iter().map(|&v| 1e-6 * (d - v).max(0.0) / rms).collect()
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    #[test]
    fn uniform_gap_is_exact() {
        let u = 0.3e-6;
        for p in ALL {
            let s = solve(&vec![u; 64 * 64], 64, PIXEL, ETA, &settings(p)).unwrap();
            assert!(rel(s.conductance, sigma(u)) <= 1e-14, "{p:?}: {s:?}");
            assert!(rel(s.effective_gap, u) <= 1e-14);
            assert!(s.percolates);
            assert_eq!(s.contact_fraction, 0.0);
        }
    }

    #[test]
    fn step_along_the_flow_gives_the_series_value() {
        let (u1, u2) = (0.2e-6, 1.0e-6);
        for n in [8, 64] {
            let gap = grid(n, |ix, _| if ix < n / 2 { u1 } else { u2 });
            let series = 2.0 / (1.0 / sigma(u1) + 1.0 / sigma(u2));
            for p in ALL {
                let f = solve_field(&gap, n, PIXEL, ETA, &settings(p)).unwrap();
                let s = f.solution;
                assert!(s.residual <= 1e-10, "{p:?} n = {n}: {s:?}");
                assert!(rel(s.conductance, series) <= 1e-8, "{p:?} n = {n}: {s:?}");
                for q in &f.cross_section_flux {
                    assert!(rel(*q, series) <= 1e-8);
                }
            }
        }
    }

    #[test]
    fn step_across_the_flow_gives_the_parallel_value() {
        let (u1, u2) = (0.2e-6, 1.0e-6);
        let n = 32;
        let gap = grid(n, |_, iy| if iy < n / 2 { u1 } else { u2 });
        let parallel = 0.5 * (sigma(u1) + sigma(u2));
        for p in ALL {
            let s = solve(&gap, n, PIXEL, ETA, &settings(p)).unwrap();
            assert!(rel(s.conductance, parallel) <= 1e-8, "{p:?}: {s:?}");
        }
    }

    #[test]
    fn a_rarefied_gas_conducts_cell_by_cell() {
        // helium near 1 bar: every cell's conductance u³ f(λ/u, pixel/u)/(12η), so the series
        // and parallel steps give the harmonic and arithmetic means of the rarefied cells, and
        // a strip of sub-molecular gaps across the flow seals
        let gas = crate::gas::Rarefied {
            free_path: 0.2e-6,
            molecular_diameter: 0.215e-9,
        };
        let rarefied = |u: f64| sigma(u) * crate::gas::slit_rarefaction(0.2e-6 / u, PIXEL / u);
        let set = FlowSettings {
            gas: Some(gas),
            ..FlowSettings::default()
        };
        let (u1, u2) = (0.2e-6, 1.0e-6);
        let n = 32;
        let along = grid(n, |ix, _| if ix < n / 2 { u1 } else { u2 });
        let across = grid(n, |_, iy| if iy < n / 2 { u1 } else { u2 });
        let series = 2.0 / (1.0 / rarefied(u1) + 1.0 / rarefied(u2));
        let parallel = 0.5 * (rarefied(u1) + rarefied(u2));
        let s = solve(&along, n, PIXEL, ETA, &set).unwrap();
        assert!(rel(s.conductance, series) <= 1e-8, "{s:?}");
        let s = solve(&across, n, PIXEL, ETA, &set).unwrap();
        assert!(rel(s.conductance, parallel) <= 1e-8, "{s:?}");
        // above the liquid's by the factors (> 1)
        assert!(s.conductance > 0.5 * (sigma(u1) + sigma(u2)));
        let blocked = grid(n, |ix, _| if ix == n / 2 { 0.1e-9 } else { u2 });
        let s = solve(&blocked, n, PIXEL, ETA, &set).unwrap();
        assert_eq!(s.conductance, 0.0);
        assert!(!s.percolates);
    }

    #[test]
    fn a_liquid_s_gap_below_a_molecule_conducts_nothing() {
        // a strip of 0.2 nm gaps across the flow (below a water molecule, 0.31 nm): with the
        // liquid's molecular size it is contact and nothing percolates; without it the cells
        // conduct u³/(12η) in series (the defect of docs/model.md §8.1: a flow through gaps
        // no wider than one molecule); a strip of 0.5 nm gaps still conducts, in series
        let n = 32;
        let molecule = crate::fluid::liquid_molecular_size();
        let set = FlowSettings {
            molecular_size: molecule,
            ..FlowSettings::default()
        };
        let u2 = 5.0e-9;
        let strip = |u: f64| grid(n, move |ix, _| if ix == n / 2 { u } else { u2 });
        let s = solve(&strip(0.2e-9), n, PIXEL, ETA, &set).unwrap();
        assert_eq!(s.conductance, 0.0);
        assert!(!s.percolates);
        let s = solve(&strip(0.2e-9), n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert!(s.percolates && s.conductance > 0.0, "{s:?}");
        // wider than a molecule: the harmonic mean of the faces along x, as without it
        let u1 = 0.5e-9;
        // faces: n − 2 between open cells, 2 harmonic means 2σ1σ2/(σ1 + σ2) beside the strip
        let series = n as f64 / ((n - 2) as f64 / sigma(u2) + 1.0 / sigma(u1) + 1.0 / sigma(u2));
        let s = solve(&strip(u1), n, PIXEL, ETA, &set).unwrap();
        assert!(rel(s.conductance, series) <= 1e-8, "{s:?} vs {series}");
        let plain = solve(&strip(u1), n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert_eq!(s.conductance, plain.conductance);
    }

    #[test]
    fn a_contact_line_across_the_flow_seals_exactly() {
        let n = 32;
        let gap = grid(n, |ix, iy| {
            if ix == 11 {
                0.0
            } else {
                1e-6 * (1.0 + iy as f64)
            }
        });
        for p in ALL {
            let s = solve(&gap, n, PIXEL, ETA, &settings(p)).unwrap();
            assert_eq!(s.conductance, 0.0);
            assert_eq!(s.effective_gap, 0.0);
            assert!(!s.percolates);
            assert_eq!(s.iterations, 0);
            assert!((s.contact_fraction - 1.0 / 32.0).abs() < 1e-15);
        }
        // Gaps below ~1e-51 of the widest count as contact (their u³ would underflow).
        let hairline = grid(n, |ix, _| if ix == 11 { 1e-60 } else { 1e-6 });
        let s = solve(&hairline, n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert_eq!(s.conductance, 0.0);
        // A line of thin gap across the flow: a series of the rows' faces, resolved down to a
        // constriction of 1e-12 of the widest conductance.
        for thin_gap in [1e-8, 1e-10] {
            let thin = grid(n, |ix, _| if ix == 11 { thin_gap } else { 1e-6 });
            for p in ALL {
                let s = solve(&thin, n, PIXEL, ETA, &settings(p)).unwrap();
                let (st, sw) = (sigma(thin_gap), sigma(1e-6));
                let neck = 2.0 * st * sw / (st + sw);
                let series = n as f64 / (2.0 / neck + (n - 2) as f64 / sw);
                assert!(
                    s.percolates && rel(s.conductance, series) <= 1e-8,
                    "{p:?}: {s:?}"
                );
            }
        }
        // The same line along the flow is two parallel plates (minus the closed row).
        let along = grid(n, |_, iy| if iy == 11 { 0.0 } else { 1e-6 });
        let s = solve(&along, n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert!(rel(s.conductance, sigma(1e-6) * 31.0 / 32.0) <= 1e-12);
    }

    #[test]
    fn flux_is_conserved_through_every_cross_section() {
        let n = 64;
        let gap = rough_gap(n, 200, 0.25, 3);
        for p in ALL {
            let f = solve_field(&gap, n, PIXEL, ETA, &settings(p)).unwrap();
            let s = f.solution;
            assert!(s.percolates && s.conductance > 0.0);
            assert!((s.contact_fraction - 0.25).abs() < 0.01);
            let spread = f
                .cross_section_flux
                .iter()
                .map(|q| rel(*q, s.conductance))
                .fold(0.0, f64::max);
            assert!(spread <= 1e-8, "{p:?}: spread {spread:e}, {s:?}");
        }
    }

    #[test]
    fn preconditioners_agree_on_a_rough_gap() {
        let n = 128;
        let gap = rough_gap(n, 300, 0.25, 11);
        let reference = solve(&gap, n, PIXEL, ETA, &settings(Preconditioner::Multigrid)).unwrap();
        for p in ALL {
            let s = solve(&gap, n, PIXEL, ETA, &settings(p)).unwrap();
            assert!(
                rel(s.conductance, reference.conductance) <= 1e-9,
                "{p:?}: {s:?} vs {reference:?}"
            );
        }
        // Wiener bounds over the cells.
        let sig: Vec<f64> = gap.iter().map(|&u| sigma(u)).collect();
        let mean = sig.iter().sum::<f64>() / sig.len() as f64;
        assert!(reference.conductance < mean && reference.conductance > 0.0);
    }

    #[test]
    fn isolated_lakes_and_dead_ends_change_nothing() {
        let n = 32;
        // Channels along x of varying gap, separated by contact bands three cells thick.
        let base = |ix: usize, iy: usize| {
            if iy % 8 < 3 {
                0.0
            } else {
                1e-6 * (1.0 + 0.5 * ((ix as f64) * 0.7 + iy as f64).sin())
            }
        };
        let reference = solve(&grid(n, base), n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert!(reference.conductance > 0.0);
        // A lake inside a contact band: excluded, so the result is bit for bit the same.
        let lake = grid(n, |ix, iy| {
            if iy == 17 && (5..=9).contains(&ix) {
                3e-6
            } else {
                base(ix, iy)
            }
        });
        let a = solve(&lake, n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert_eq!(a.conductance, reference.conductance);
        assert!(a.contact_fraction < reference.contact_fraction);
        // A dead-end pocket opening into the channel at iy = 3 through one face: it joins the
        // spanning cluster but carries no flux.
        let dead_end = grid(n, |ix, iy| {
            if (iy == 1 && (20..=22).contains(&ix)) || (iy == 2 && ix == 21) {
                2e-6
            } else {
                base(ix, iy)
            }
        });
        for p in ALL {
            let d = solve(&dead_end, n, PIXEL, ETA, &settings(p)).unwrap();
            assert!(d.spanning_fraction > reference.spanning_fraction);
            assert!(
                rel(d.conductance, reference.conductance) <= 1e-9,
                "{p:?}: {d:?} vs {reference:?}"
            );
        }
        // One bridge through a band between two channels is a dead end too (no return path);
        // two bridges do change the conductance.
        let bridge = grid(n, |ix, iy| {
            if iy % 8 < 3 && iy < 8 && ix == 20 {
                2e-6
            } else {
                base(ix, iy)
            }
        });
        let c = solve(&bridge, n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert!(rel(c.conductance, reference.conductance) <= 1e-9);
        let bridge = grid(n, |ix, iy| {
            if iy % 8 < 3 && iy < 8 && (ix == 20 || ix == 5) {
                2e-6
            } else {
                base(ix, iy)
            }
        });
        let c = solve(&bridge, n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert!(
            c.conductance > reference.conductance * (1.0 + 1e-6),
            "{c:?} vs {reference:?}"
        );
    }

    #[test]
    fn flow_along_y_is_the_transposed_problem() {
        let n = 48;
        let gap = rough_gap(n, 100, 0.2, 5);
        let t = transpose(&gap, n);
        let x = solve_field(&gap, n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        let y = solve_field(
            &t,
            n,
            PIXEL,
            ETA,
            &FlowSettings {
                direction: Direction::Y,
                ..FlowSettings::default()
            },
        )
        .unwrap();
        assert_eq!(x.solution.conductance, y.solution.conductance);
        assert_eq!(transpose(&x.pressure, n).len(), y.pressure.len());
        for (a, b) in transpose(&x.pressure, n).iter().zip(&y.pressure) {
            assert!(a == b || (a.is_nan() && b.is_nan()));
        }
    }

    #[test]
    fn open_but_not_percolating_is_zero() {
        let n = 16;
        // Channels along y only.
        let gap = grid(n, |ix, _| if ix % 4 == 0 { 1e-6 } else { 0.0 });
        let s = solve(&gap, n, PIXEL, ETA, &FlowSettings::default()).unwrap();
        assert_eq!(s.conductance, 0.0);
        assert!(!s.percolates);
        // But along y they conduct: a quarter of the cells at σ(1 µm).
        let along_y = FlowSettings {
            direction: Direction::Y,
            ..FlowSettings::default()
        };
        let s = solve(&gap, n, PIXEL, ETA, &along_y).unwrap();
        assert!(rel(s.conductance, 0.25 * sigma(1e-6)) <= 1e-12);
    }

    #[test]
    fn leak_rate_follows_the_seal_geometry() {
        let u = 0.1e-6;
        let s = solve(&[u; 16], 4, PIXEL, ETA, &FlowSettings::default()).unwrap();
        // L_y = 10 mm, L_x = 1 mm, ΔP = 1 MPa
        let fluid = crate::fluid::Fluid {
            viscosity: ETA,
            pressure_difference: 1e6,
            law: crate::fluid::ViscosityLaw::Constant,
            gas: None,
        };
        let geometry = crate::fluid::FlowGeometry {
            along_flow: 1e-3,
            across_flow: 10e-3,
        };
        let q = fluid.leak_rate(geometry, s.conduction());
        assert!(rel(q, 10.0 * sigma(u) * 1e6) <= 1e-14);
    }

    #[test]
    fn invalid_input_is_an_error() {
        let ok = FlowSettings::default();
        assert!(matches!(
            solve(&[1e-6; 5], 2, PIXEL, ETA, &ok),
            Err(FlowError::Size { .. })
        ));
        assert!(matches!(
            solve(&[1e-6], 1, PIXEL, ETA, &ok),
            Err(FlowError::Size { .. })
        ));
        assert!(matches!(
            solve(&[1e-6, -1e-9, 0.0, 1e-6], 2, PIXEL, ETA, &ok),
            Err(FlowError::InvalidGap { index: 1, .. })
        ));
        assert!(matches!(
            solve(&[1e-6, f64::NAN, 0.0, 1e-6], 2, PIXEL, ETA, &ok),
            Err(FlowError::InvalidGap { index: 1, .. })
        ));
        assert!(matches!(
            solve(&[1e-6; 4], 2, 0.0, ETA, &ok),
            Err(FlowError::InvalidParameter(_))
        ));
        assert!(matches!(
            solve(&[1e-6; 4], 2, PIXEL, -1.0, &ok),
            Err(FlowError::InvalidParameter(_))
        ));
        let few = FlowSettings {
            max_iterations: 2,
            preconditioner: Preconditioner::Jacobi,
            ..ok
        };
        let gap = rough_gap(32, 50, 0.2, 1);
        assert!(matches!(
            solve(&gap, 32, PIXEL, ETA, &few),
            Err(FlowError::NotConverged { iterations: 2, .. })
        ));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Wiener bounds: σ_eff lies between the harmonic and the arithmetic mean of the cell
        /// conductances (both bounds hold exactly for the discrete problem).
        #[test]
        fn conductance_lies_within_the_wiener_bounds(
            n in 2usize..12,
            raw in proptest::collection::vec(0.05f64..5.0, 144),
            pre in 0usize..3,
        ) {
            let gap: Vec<f64> = raw[..n * n].iter().map(|v| v * 1e-6).collect();
            let s = solve(&gap, n, PIXEL, ETA, &settings(ALL[pre])).unwrap();
            let sig: Vec<f64> = gap.iter().map(|&u| sigma(u)).collect();
            let cells = sig.len() as f64;
            let arithmetic = sig.iter().sum::<f64>() / cells;
            let harmonic = cells / sig.iter().map(|s| 1.0 / s).sum::<f64>();
            prop_assert!(s.conductance <= arithmetic * (1.0 + 1e-9), "{s:?} > {arithmetic}");
            prop_assert!(s.conductance >= harmonic * (1.0 - 1e-9), "{s:?} < {harmonic}");
        }
    }
}
