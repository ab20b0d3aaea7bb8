//! Thin-film Reynolds flow through a gap field (DESIGN §3.5): effective conductance of the
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
//! DESIGN §3.3 (effective medium) and §3.1 with `σ_eff = α u_c³/(12η)`. The *effective gap* is
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
//! Preconditioned conjugate gradients (flexible Polak–Ribière form), from φ = 0, stopped when
//! the relative residual `‖b − Aφ‖₂/‖b‖₂` (true residual, recomputed at the end) is below the
//! tolerance (default 1e-10) and — given a few more iterations if needed — the energy decrement
//! of the last step is below the tolerance times the current dissipation. σ_eff is evaluated from the dissipation `Σ_faces g Δp²`
//! (= `Q_cross ΔP`), which is variational: its error is quadratic in the error of φ. Near the
//! percolation threshold, where the flow is set by one constriction many decades narrower than
//! the wide channels, this keeps σ_eff accurate (the preconditioners agree to ~1e-10 with a
//! constriction 1e-12 of the largest conductance) although the residual, and with it the
//! balance of the cross-section fluxes, is dominated by the wide channels.
//!
//! Preconditioners ([`Preconditioner`]):
//! * `Jacobi` — diagonal; cheap per iteration, but the iteration count grows like `n` and with
//!   the conductance contrast;
//! * `IncompleteCholesky` — modified incomplete Cholesky MIC(0) (natural order, relaxation
//!   0.97); about 5× fewer iterations than Jacobi, sequential triangular solves;
//! * `Multigrid` (default) — aggregation algebraic multigrid with geometric guidance: aggregates
//!   are the strongly connected components of the nodes of 2 × 2 blocks (a face is strong when
//!   its conductance is at least 0.25 of the largest face of both its cells, so no aggregate
//!   straddles a constriction; a node left alone joins the neighbour it is most strongly tied
//!   to), Galerkin coarse operators (piecewise-constant prolongation: the coarse conductance
//!   between two aggregates is the sum of the fine faces between them), symmetric Gauss–Seidel
//!   smoothing, K-cycle on the coarse levels (Notay & Vassilevski 2008), dense Cholesky on the
//!   coarsest (≤ 400 unknowns). About 25–40 iterations independent of the grid size on rough
//!   gap fields with 20–30 % contact, and just above the percolation threshold.

use super::percolation;
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
}

impl Default for FlowSettings {
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            max_iterations: 100_000,
            preconditioner: Preconditioner::default(),
            direction: Direction::default(),
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
    /// Leak rate `Q̇ = (L_y/L_x) σ_eff ΔP` (m³/s) of a seal of `length` across the flow (L_y, m),
    /// `width` along it (L_x, m) under the pressure difference `pressure_difference` (Pa),
    /// DESIGN §3.3.
    pub fn leak_rate(&self, length: f64, width: f64, pressure_difference: f64) -> f64 {
        length / width * self.conductance * pressure_difference
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
    let mut field = solve_x(gap, n, viscosity, settings)?;
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
    viscosity: f64,
    settings: &FlowSettings,
) -> Result<FlowField, FlowError> {
    let cells = n * n;
    // Cell conductances u³/(12η), scaled by their maximum. A gap so thin that its scaled
    // conductance is below √(f64::MIN_POSITIVE) ≈ 1.5e-154 (u below ~1e-51 of the widest gap)
    // counts as contact, so that no face conductance underflows to zero inside a cluster.
    let sigma_of = |u: f64| u * u * u / (12.0 * viscosity);
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
    let grid = Grid::new(n, &face_e, &face_n, &active);
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
// The linear system on a periodic grid: a weighted graph Laplacian with Dirichlet sinks.

/// Symmetric positive (semi)definite 5-point operator on a periodic `n × n` grid:
/// `(A x)_i = d_i x_i − Σ_faces g x_neighbour`. Inactive cells have no faces and `d = 0`; their
/// entries in every vector stay 0.
#[derive(Debug, Clone)]
struct Grid {
    n: usize,
    /// Conductance of the face to the east neighbour (0 if either cell is inactive).
    ge: Vec<f64>,
    /// Conductance of the face to the north neighbour.
    gn: Vec<f64>,
    /// Diagonal: sum of the faces plus the sinks to pinned cells.
    diag: Vec<f64>,
    /// 1/diag, 0 for inactive cells.
    inv_diag: Vec<f64>,
    /// Sinks: diagonal excess over the faces (connections to pinned cells).
    extra: Vec<f64>,
}

impl Grid {
    /// The operator of the active cells, from the physical faces; faces to inactive cells that
    /// are part of the physical network (pinned cells) become sinks.
    fn new(n: usize, face_e: &[f64], face_n: &[f64], active: &[bool]) -> Self {
        let cells = n * n;
        let mut ge = vec![0.0; cells];
        let mut gn = vec![0.0; cells];
        let mut extra = vec![0.0; cells];
        for iy in 0..n {
            for ix in 0..n {
                let i = iy * n + ix;
                for (j, g, slot) in [
                    (iy * n + (ix + 1) % n, face_e[i], &mut ge),
                    (((iy + 1) % n) * n + ix, face_n[i], &mut gn),
                ] {
                    match (active[i], active[j]) {
                        (true, true) => slot[i] = g,
                        (true, false) => extra[i] += g,
                        (false, true) => extra[j] += g,
                        (false, false) => {}
                    }
                }
            }
        }
        Self::assemble(n, ge, gn, extra)
    }

    fn assemble(n: usize, ge: Vec<f64>, gn: Vec<f64>, extra: Vec<f64>) -> Self {
        let cells = n * n;
        let mut diag = extra.clone();
        for iy in 0..n {
            for ix in 0..n {
                let i = iy * n + ix;
                diag[i] +=
                    ge[i] + ge[iy * n + (ix + n - 1) % n] + gn[i] + gn[((iy + n - 1) % n) * n + ix];
            }
        }
        let inv_diag = diag
            .iter()
            .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
            .collect();
        debug_assert_eq!(diag.len(), cells);
        Self {
            n,
            ge,
            gn,
            diag,
            inv_diag,
            extra,
        }
    }

    fn cells(&self) -> usize {
        self.n * self.n
    }

    /// y = A x.
    fn apply(&self, x: &[f64], y: &mut [f64]) {
        self.apply_dot(x, y);
    }

    /// y = A x; returns x·y (computed row by row while the row is in cache).
    fn apply_dot(&self, x: &[f64], y: &mut [f64]) -> f64 {
        let n = self.n;
        let mut xy = 0.0;
        for iy in 0..n {
            let row = iy * n;
            let south = ((iy + n - 1) % n) * n;
            let north = ((iy + 1) % n) * n;
            let xr = &x[row..row + n];
            let xs = &x[south..south + n];
            let xn = &x[north..north + n];
            let ge = &self.ge[row..row + n];
            let gn = &self.gn[row..row + n];
            let gs = &self.gn[south..south + n];
            let d = &self.diag[row..row + n];
            let yr = &mut y[row..row + n];
            let edge = |ix: usize, w: usize, e: usize| {
                d[ix] * xr[ix] - ge[ix] * xr[e] - ge[w] * xr[w] - gn[ix] * xn[ix] - gs[ix] * xs[ix]
            };
            yr[0] = edge(0, n - 1, 1 % n);
            for ix in 1..n - 1 {
                yr[ix] = d[ix] * xr[ix]
                    - ge[ix] * xr[ix + 1]
                    - ge[ix - 1] * xr[ix - 1]
                    - gn[ix] * xn[ix]
                    - gs[ix] * xs[ix];
            }
            yr[n - 1] = edge(n - 1, n - 2, 0);
            xy += dot(xr, yr);
        }
        xy
    }

    /// One Gauss–Seidel sweep on A x = rhs, forward (lexicographic) or backward. Row by row: the
    /// terms from the rows above and below and the right-hand side first (vectorised), then the
    /// recurrence along the row.
    fn gauss_seidel(&self, rhs: &[f64], x: &mut [f64], forward: bool, scratch: &mut Vec<f64>) {
        let n = self.n;
        scratch.resize(n, 0.0);
        let t = &mut scratch[..];
        let mut row_sweep = |iy: usize| {
            let row = iy * n;
            let south = ((iy + n - 1) % n) * n;
            let (cur, xs, xn) = rows_mut(x, n, iy);
            let ge = &self.ge[row..row + n];
            let gn = &self.gn[row..row + n];
            let gs = &self.gn[south..south + n];
            let inv = &self.inv_diag[row..row + n];
            let b = &rhs[row..row + n];
            if forward {
                // t = (b + vertical + east (old)) / d; then x_i = t_i + g_w x_{i−1} / d.
                for ix in 0..n - 1 {
                    t[ix] = (b[ix] + gn[ix] * xn[ix] + gs[ix] * xs[ix] + ge[ix] * cur[ix + 1])
                        * inv[ix];
                }
                cur[0] = t[0] + ge[n - 1] * cur[n - 1] * inv[0];
                let mut west = cur[0];
                for ix in 1..n - 1 {
                    west = t[ix] + ge[ix - 1] * inv[ix] * west;
                    cur[ix] = west;
                }
                let last = n - 1;
                cur[last] = (b[last]
                    + gn[last] * xn[last]
                    + gs[last] * xs[last]
                    + ge[last] * cur[0]
                    + ge[last - 1] * west)
                    * inv[last];
            } else {
                // t = (b + vertical + west (old)) / d; then x_i = t_i + g_e x_{i+1} / d.
                for ix in 1..n {
                    t[ix] = (b[ix] + gn[ix] * xn[ix] + gs[ix] * xs[ix] + ge[ix - 1] * cur[ix - 1])
                        * inv[ix];
                }
                let last = n - 1;
                cur[last] = t[last] + ge[last] * cur[0] * inv[last];
                let mut east = cur[last];
                for ix in (1..n - 1).rev() {
                    east = t[ix] + ge[ix] * inv[ix] * east;
                    cur[ix] = east;
                }
                cur[0] =
                    (b[0] + gn[0] * xn[0] + gs[0] * xs[0] + ge[0] * east + ge[last] * cur[last])
                        * inv[0];
            }
        };
        if forward {
            (0..n).for_each(&mut row_sweep);
        } else {
            (0..n).rev().for_each(&mut row_sweep);
        }
    }
}

/// Row `iy` of an `n × n` field (mutable) with its periodic neighbours below and above.
fn rows_mut(x: &mut [f64], n: usize, iy: usize) -> (&mut [f64], &[f64], &[f64]) {
    let (before, rest) = x.split_at_mut(iy * n);
    let (cur, after) = rest.split_at_mut(n);
    let south: &[f64] = if iy > 0 {
        &before[(iy - 1) * n..]
    } else {
        &after[after.len() - n..]
    };
    let north: &[f64] = if iy + 1 < n {
        &after[..n]
    } else {
        &before[..n]
    };
    (cur, south, north)
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    // Four partial sums: vectorisable and a little more accurate.
    let mut s = [0.0; 4];
    let (ca, ra) = a.as_chunks::<4>();
    let (cb, rb) = b.as_chunks::<4>();
    for (x, y) in ca.iter().zip(cb) {
        for k in 0..4 {
            s[k] += x[k] * y[k];
        }
    }
    let tail: f64 = ra.iter().zip(rb).map(|(x, y)| x * y).sum();
    (s[0] + s[1]) + (s[2] + s[3]) + tail
}

// ---------------------------------------------------------------------------------------------
// Preconditioners.

enum Precond {
    Jacobi,
    Mic(Mic),
    Multigrid(Box<Multigrid>),
}

impl Precond {
    fn new(kind: Preconditioner, grid: &Grid) -> Self {
        match kind {
            Preconditioner::Jacobi => Self::Jacobi,
            Preconditioner::IncompleteCholesky => Self::Mic(Mic::new(grid, MIC_RELAXATION)),
            Preconditioner::Multigrid => Self::Multigrid(Box::new(Multigrid::new(grid.clone()))),
        }
    }

    /// z = M⁻¹ r.
    fn apply(&mut self, grid: &Grid, r: &[f64], z: &mut [f64]) {
        match self {
            Self::Jacobi => {
                for ((z, r), d) in z.iter_mut().zip(r).zip(&grid.inv_diag) {
                    *z = r * d;
                }
            }
            Self::Mic(m) => m.apply(grid, r, z),
            Self::Multigrid(m) => m.apply(r, z),
        }
    }
}

/// Relaxation of the modified incomplete Cholesky (1 = row sums preserved exactly, 0 = IC(0)).
const MIC_RELAXATION: f64 = 0.97;

/// Modified incomplete Cholesky `M = (D − E) D⁻¹ (D − Eᵀ)`, E the strictly lower part of −A,
/// natural (row-major) order, no fill; the dropped fill is added to the diagonal with weight ω.
struct Mic {
    /// Pivots D.
    pivot: Vec<f64>,
    inv_pivot: Vec<f64>,
}

/// The four neighbours of cell `i` with the conductances of the faces to them.
fn neighbours(grid: &Grid, i: usize) -> [(usize, f64); 4] {
    let n = grid.n;
    let (ix, iy) = (i % n, i / n);
    let e = iy * n + (ix + 1) % n;
    let w = iy * n + (ix + n - 1) % n;
    let no = ((iy + 1) % n) * n + ix;
    let so = ((iy + n - 1) % n) * n + ix;
    [
        (e, grid.ge[i]),
        (w, grid.ge[w]),
        (no, grid.gn[i]),
        (so, grid.gn[so]),
    ]
}

impl Mic {
    fn new(grid: &Grid, omega: f64) -> Self {
        let cells = grid.cells();
        let mut pivot = vec![0.0; cells];
        for i in 0..cells {
            if grid.diag[i] <= 0.0 {
                continue;
            }
            let mut d = grid.diag[i];
            for (j, g) in neighbours(grid, i) {
                if j >= i || g == 0.0 || pivot[j] <= 0.0 {
                    continue;
                }
                // Fill that elimination of j would put in row i, towards j's other upper
                // neighbours k (dropped, and added to the diagonal with weight ω).
                let fill: f64 = neighbours(grid, j)
                    .iter()
                    .filter(|&&(k, _)| k > j && k != i)
                    .map(|&(_, gk)| gk)
                    .sum();
                d -= g * (g + omega * fill) / pivot[j];
            }
            // Guard against breakdown (near-singular clusters, round-off).
            pivot[i] = if d > 1e-12 * grid.diag[i] {
                d
            } else {
                grid.diag[i]
            };
        }
        let inv_pivot = pivot
            .iter()
            .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
            .collect();
        Self { pivot, inv_pivot }
    }

    fn apply(&self, grid: &Grid, r: &[f64], z: &mut [f64]) {
        let n = grid.n;
        let (ge, gn, inv) = (&grid.ge, &grid.gn, &self.inv_pivot);
        let last_row = (n - 1) * n;
        // Forward: (D − E) w = r, w_i = (r_i + Σ_{j<i} g_ij w_j)/D_i. The neighbours before a
        // cell: west, south, and through the periodic boundary the first cell of the row (for the
        // last cell of a row) and the cell of the first row (for the last row).
        for iy in 0..n {
            let row = iy * n;
            for ix in 0..n {
                let i = row + ix;
                let mut s = r[i];
                if ix > 0 {
                    s += ge[i - 1] * z[i - 1];
                }
                if iy > 0 {
                    s += gn[i - n] * z[i - n];
                }
                if ix == n - 1 {
                    s += ge[i] * z[row];
                }
                if iy == n - 1 {
                    s += gn[i] * z[ix];
                }
                z[i] = s * inv[i];
            }
        }
        // Backward: (D − Eᵀ) z = D w, z_i = w_i + (Σ_{j>i} g_ij z_j)/D_i.
        for iy in (0..n).rev() {
            let row = iy * n;
            for ix in (0..n).rev() {
                let i = row + ix;
                let mut s = 0.0;
                if ix < n - 1 {
                    s += ge[i] * z[i + 1];
                }
                if iy < n - 1 {
                    s += gn[i] * z[i + n];
                }
                if ix == 0 {
                    s += ge[row + n - 1] * z[row + n - 1];
                }
                if iy == 0 {
                    s += gn[last_row + ix] * z[last_row + ix];
                }
                z[i] += s * inv[i];
            }
        }
        debug_assert_eq!(self.pivot.len(), grid.cells());
    }
}

/// Aggregation strength threshold: a face joins two nodes into one aggregate only if its
/// conductance is at least this fraction of the largest face of *both* nodes, so aggregates do
/// not straddle constrictions (weak links would otherwise be short-circuited on the coarse grids).
const STRENGTH: f64 = 0.25;
/// The hierarchy stops at a level with at most this many unknowns (dense Cholesky).
const COARSEST_NODES: usize = 400;
/// The K-cycle skips its second step when the first reduced the residual below this fraction.
const KRYLOV_SKIP: f64 = 0.25;
/// Symmetric Gauss–Seidel sweeps before and after the coarse correction.
const SWEEPS: usize = 1;

const NONE: u32 = u32::MAX;

/// A coarse level: graph Laplacian with sinks in compressed rows,
/// `(A x)_i = d_i x_i − Σ_e w_e x_col(e)`, `d_i = Σ_e w_e + sink_i`. Its nodes belong to the
/// blocks of a `side × side` periodic grid of cell blocks and are sorted by block.
struct Sparse {
    side: usize,
    /// First node of every block (`side² + 1` entries).
    block_start: Vec<u32>,
    /// First edge of every node (`nodes + 1` entries).
    start: Vec<u32>,
    col: Vec<u32>,
    weight: Vec<f64>,
    sink: Vec<f64>,
    diag: Vec<f64>,
    inv_diag: Vec<f64>,
}

impl Sparse {
    fn nodes(&self) -> usize {
        self.start.len() - 1
    }

    fn finish(
        side: usize,
        block_start: Vec<u32>,
        start: Vec<u32>,
        col: Vec<u32>,
        weight: Vec<f64>,
        sink: Vec<f64>,
    ) -> Self {
        let diag: Vec<f64> = (0..start.len() - 1)
            .map(|i| {
                weight[start[i] as usize..start[i + 1] as usize]
                    .iter()
                    .sum::<f64>()
                    + sink[i]
            })
            .collect();
        let inv_diag = diag
            .iter()
            .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
            .collect();
        Self {
            side,
            block_start,
            start,
            col,
            weight,
            sink,
            diag,
            inv_diag,
        }
    }

    /// The fine grid as a graph (one node per cell with a non-zero diagonal, in cell order),
    /// with the node of every cell (`NONE` for cells out of the system).
    fn from_grid(grid: &Grid) -> (Self, Vec<u32>) {
        let cells = grid.cells();
        let mut node = vec![NONE; cells];
        let mut block_start = Vec::with_capacity(cells + 1);
        let mut count = 0u32;
        for (i, slot) in node.iter_mut().enumerate() {
            block_start.push(count);
            if grid.diag[i] > 0.0 {
                *slot = count;
                count += 1;
            }
        }
        block_start.push(count);
        let mut start = Vec::with_capacity(count as usize + 1);
        start.push(0u32);
        let mut col = Vec::with_capacity(4 * count as usize);
        let mut weight = Vec::with_capacity(4 * count as usize);
        let mut sink = Vec::with_capacity(count as usize);
        for i in 0..cells {
            if node[i] == NONE {
                continue;
            }
            for (j, g) in neighbours(grid, i) {
                if g > 0.0 {
                    col.push(node[j]);
                    weight.push(g);
                }
            }
            sink.push(grid.extra[i]);
            start.push(col.len() as u32);
        }
        (
            Self::finish(grid.n, block_start, start, col, weight, sink),
            node,
        )
    }

    fn edges(&self, i: usize) -> impl Iterator<Item = (usize, f64)> + '_ {
        let range = self.start[i] as usize..self.start[i + 1] as usize;
        self.col[range.clone()]
            .iter()
            .zip(&self.weight[range])
            .map(|(&j, &w)| (j as usize, w))
    }

    /// Aggregates: within every 2 × 2 super-block of blocks, the connected components of the
    /// nodes under the strong edges (`w ≥ θ · max(largest edge of either end)`). Returns the
    /// aggregate of every node, the first aggregate of every super-block and their count.
    fn aggregate(&self, theta: f64) -> (Vec<u32>, Vec<u32>, usize) {
        let nodes = self.nodes();
        let largest: Vec<f64> = (0..nodes)
            .map(|i| self.edges(i).map(|(_, w)| w).fold(0.0, f64::max))
            .collect();
        let side = self.side;
        let cs = side.div_ceil(2);
        let mut agg = vec![NONE; nodes];
        let mut stamp = vec![NONE; nodes];
        let mut coarse_start = Vec::with_capacity(cs * cs + 1);
        let mut members: Vec<usize> = Vec::new();
        let mut stack: Vec<usize> = Vec::new();
        let mut sizes: Vec<u32> = Vec::new();
        let mut renumber: Vec<u32> = Vec::new();
        let mut count = 0u32;
        for by in 0..cs {
            for bx in 0..cs {
                coarse_start.push(count);
                let s = (by * cs + bx) as u32;
                members.clear();
                for (cx, cy) in [
                    (2 * bx, 2 * by),
                    (2 * bx + 1, 2 * by),
                    (2 * bx, 2 * by + 1),
                    (2 * bx + 1, 2 * by + 1),
                ] {
                    if cx < side && cy < side {
                        let b = cy * side + cx;
                        let range = self.block_start[b]..self.block_start[b + 1];
                        members.extend(range.map(|i| i as usize));
                    }
                }
                for &i in &members {
                    stamp[i] = s;
                }
                // Phase 1: components under the strong edges, local ids from `first`.
                let first = count;
                sizes.clear();
                for &i in &members {
                    if agg[i] != NONE {
                        continue;
                    }
                    let id = count;
                    agg[i] = id;
                    let mut size = 1u32;
                    stack.push(i);
                    while let Some(k) = stack.pop() {
                        for (j, w) in self.edges(k) {
                            if stamp[j] == s
                                && agg[j] == NONE
                                && w >= theta * largest[k].max(largest[j])
                            {
                                agg[j] = id;
                                size += 1;
                                stack.push(j);
                            }
                        }
                    }
                    sizes.push(size);
                    count += 1;
                }
                // Phase 2: a node left alone joins the neighbouring aggregate of the super-block
                // it is most strongly tied to, if that tie is strong from its own side.
                let mut merged = false;
                for &i in &members {
                    if sizes[(agg[i] - first) as usize] != 1 {
                        continue;
                    }
                    let best = self
                        .edges(i)
                        .filter(|&(j, _)| stamp[j] == s && agg[j] != agg[i])
                        .max_by(|a, b| a.1.total_cmp(&b.1));
                    if let Some((j, w)) = best
                        && w >= theta * largest[i]
                    {
                        sizes[(agg[i] - first) as usize] = 0;
                        agg[i] = agg[j];
                        sizes[(agg[j] - first) as usize] += 1;
                        merged = true;
                    }
                }
                if merged {
                    // Renumber the aggregates of this super-block without the emptied ones.
                    renumber.clear();
                    let mut next = first;
                    for &size in &sizes {
                        renumber.push(next);
                        if size > 0 {
                            next += 1;
                        }
                    }
                    for &i in &members {
                        agg[i] = renumber[(agg[i] - first) as usize];
                    }
                    count = next;
                }
            }
        }
        coarse_start.push(count);
        (agg, coarse_start, count as usize)
    }

    /// Galerkin operator `Pᵀ A P` for the piecewise-constant prolongation of `agg`.
    fn galerkin(&self, agg: &[u32], coarse_start: Vec<u32>, count: usize) -> Sparse {
        // Members of every aggregate (counting sort).
        let mut first = vec![0u32; count + 1];
        for &a in agg {
            first[a as usize + 1] += 1;
        }
        for k in 0..count {
            first[k + 1] += first[k];
        }
        let mut fill = first.clone();
        let mut members = vec![0u32; agg.len()];
        for (i, &a) in agg.iter().enumerate() {
            members[fill[a as usize] as usize] = i as u32;
            fill[a as usize] += 1;
        }
        let mut position = vec![NONE; count];
        let mut start = Vec::with_capacity(count + 1);
        start.push(0u32);
        let mut col: Vec<u32> = Vec::new();
        let mut weight: Vec<f64> = Vec::new();
        let mut sink = Vec::with_capacity(count);
        for a in 0..count {
            let row = col.len();
            let mut s = 0.0;
            for &i in &members[first[a] as usize..first[a + 1] as usize] {
                s += self.sink[i as usize];
                for (j, w) in self.edges(i as usize) {
                    let b = agg[j];
                    if b as usize == a {
                        continue;
                    }
                    match position[b as usize] {
                        NONE => {
                            position[b as usize] = col.len() as u32;
                            col.push(b);
                            weight.push(w);
                        }
                        p => weight[p as usize] += w,
                    }
                }
            }
            for &b in &col[row..] {
                position[b as usize] = NONE;
            }
            sink.push(s);
            start.push(col.len() as u32);
        }
        Sparse::finish(
            self.side.div_ceil(2),
            coarse_start,
            start,
            col,
            weight,
            sink,
        )
    }

    /// y = A x.
    fn apply(&self, x: &[f64], y: &mut [f64]) {
        for i in 0..self.nodes() {
            let mut s = self.diag[i] * x[i];
            for (j, w) in self.edges(i) {
                s -= w * x[j];
            }
            y[i] = s;
        }
    }

    /// r = b − A x.
    fn residual(&self, b: &[f64], x: &[f64], r: &mut [f64]) {
        for i in 0..self.nodes() {
            let mut s = b[i] - self.diag[i] * x[i];
            for (j, w) in self.edges(i) {
                s += w * x[j];
            }
            r[i] = s;
        }
    }

    fn gauss_seidel(&self, b: &[f64], x: &mut [f64], forward: bool) {
        let mut relax = |i: usize| {
            let mut s = b[i];
            for (j, w) in self.edges(i) {
                s += w * x[j];
            }
            x[i] = s * self.inv_diag[i];
        };
        if forward {
            (0..self.nodes()).for_each(&mut relax);
        } else {
            (0..self.nodes()).rev().for_each(&mut relax);
        }
    }
}

/// Builds the coarse levels below a graph until one is small enough for the dense solve.
/// Returns the aggregate map of `fine` and the levels with the maps between them.
fn hierarchy(fine: &Sparse, theta: f64) -> (Vec<u32>, Vec<Sparse>, Vec<Vec<u32>>) {
    let mut levels: Vec<Sparse> = Vec::new();
    let mut maps: Vec<Vec<u32>> = Vec::new();
    let mut first_map = Vec::new();
    loop {
        let current = levels.last().unwrap_or(fine);
        if current.nodes() <= COARSEST_NODES || (current.side == 1 && !levels.is_empty()) {
            break;
        }
        let (mut agg, mut starts, mut count) = current.aggregate(theta);
        if count as f64 > 0.9 * current.nodes() as f64 {
            // Too little coarsening (many weak links): aggregate on the geometry alone.
            (agg, starts, count) = current.aggregate(0.0);
        }
        if count == current.nodes() && current.side == 1 {
            break;
        }
        let next = current.galerkin(&agg, starts, count);
        if levels.is_empty() {
            first_map = agg;
        } else {
            maps.push(agg);
        }
        levels.push(next);
    }
    (first_map, levels, maps)
}

struct Multigrid {
    fine: Grid,
    /// Level-1 node of every fine cell (`NONE` outside the system), or, without coarse levels,
    /// the unknown of the dense solve.
    fine_map: Vec<u32>,
    /// Coarse levels 1, 2, … (the last one is solved directly).
    levels: Vec<Sparse>,
    /// `maps[k]`: node of `levels[k + 1]` for every node of `levels[k]`.
    maps: Vec<Vec<u32>>,
    dense: DenseCholesky,
    fine_res: Vec<f64>,
    scratch: Vec<f64>,
    /// Per coarse level, work vectors of the K-cycle: rhs copy, v1, A v1, A v2.
    krylov: Vec<[Vec<f64>; 4]>,
    /// Per coarse level: iterate, right-hand side, residual.
    x: Vec<Vec<f64>>,
    rhs: Vec<Vec<f64>>,
    res: Vec<Vec<f64>>,
}

impl Multigrid {
    fn new(fine: Grid) -> Self {
        let (graph, node) = Sparse::from_grid(&fine);
        let (first_map, levels, maps) = hierarchy(&graph, STRENGTH);
        let (fine_map, dense) = if levels.is_empty() {
            (node, DenseCholesky::new(&graph))
        } else {
            let map = node
                .iter()
                .map(|&k| {
                    if k == NONE {
                        NONE
                    } else {
                        first_map[k as usize]
                    }
                })
                .collect();
            let dense = DenseCholesky::new(levels.last().expect("non-empty"));
            (map, dense)
        };
        drop(graph);
        let x = levels.iter().map(|g| vec![0.0; g.nodes()]).collect();
        let rhs = levels.iter().map(|g| vec![0.0; g.nodes()]).collect();
        let res = levels.iter().map(|g| vec![0.0; g.nodes()]).collect();
        Self {
            fine_res: vec![0.0; fine.cells()],
            scratch: Vec::new(),
            krylov: levels
                .iter()
                .map(|g| std::array::from_fn(|_| vec![0.0; g.nodes()]))
                .collect(),
            fine,
            fine_map,
            levels,
            maps,
            dense,
            x,
            rhs,
            res,
        }
    }

    /// z = B r: one cycle from z = 0 (symmetric Gauss–Seidel around the coarse correction).
    fn apply(&mut self, r: &[f64], z: &mut [f64]) {
        if self.levels.is_empty() {
            // Small system: exact solve.
            let rhs: Vec<f64> = self.dense_gather(r);
            let mut y = vec![0.0; rhs.len()];
            self.dense.solve(&rhs, &mut y);
            z.fill(0.0);
            for (zi, &k) in z.iter_mut().zip(&self.fine_map) {
                if k != NONE {
                    *zi = y[k as usize];
                }
            }
            return;
        }
        // Fine level: smooth, restrict, coarse cycle, prolong, smooth.
        z.fill(0.0);
        for _ in 0..SWEEPS {
            self.fine.gauss_seidel(r, z, true, &mut self.scratch);
        }
        self.fine.apply(z, &mut self.fine_res);
        let rhs1 = &mut self.rhs[0];
        rhs1.fill(0.0);
        for ((&k, q), b) in self.fine_map.iter().zip(&self.fine_res).zip(r) {
            if k != NONE {
                rhs1[k as usize] += b - q;
            }
        }
        self.coarse_cycle(0);
        let x1 = &self.x[0];
        for (zi, &k) in z.iter_mut().zip(&self.fine_map) {
            if k != NONE {
                *zi += x1[k as usize];
            }
        }
        for _ in 0..SWEEPS {
            self.fine.gauss_seidel(r, z, false, &mut self.scratch);
        }
    }

    /// Approximate solve of coarse level `l` (`x[l]` from `rhs[l]`, starting from 0):
    /// symmetric Gauss–Seidel around a correction from level `l + 1`, exact on the coarsest
    /// level. Above it the correction is the K-cycle of Notay & Vassilevski (Numer. Linear
    /// Algebra Appl. 15 (2008) 473): two recursive cycles combined by two steps of flexible
    /// conjugate gradients on level `l + 1`, which keeps the rate of unsmoothed aggregation
    /// independent of the number of levels without a tuned over-correction.
    fn coarse_cycle(&mut self, l: usize) {
        let last = self.levels.len() - 1;
        if l == last {
            self.dense.solve(&self.rhs[l], &mut self.x[l]);
            return;
        }
        self.x[l].fill(0.0);
        for _ in 0..SWEEPS {
            self.levels[l].gauss_seidel(&self.rhs[l], &mut self.x[l], true);
        }
        self.levels[l].residual(&self.rhs[l], &self.x[l], &mut self.res[l]);
        let next = l + 1;
        {
            let coarse = &mut self.rhs[next];
            coarse.fill(0.0);
            for (&k, q) in self.maps[l].iter().zip(&self.res[l]) {
                coarse[k as usize] += q;
            }
        }
        if next < last {
            self.krylov_correction(next);
        } else {
            self.coarse_cycle(next);
        }
        let (head, tail) = self.x.split_at_mut(next);
        for (xi, &k) in head[l].iter_mut().zip(&self.maps[l]) {
            *xi += tail[0][k as usize];
        }
        for _ in 0..SWEEPS {
            self.levels[l].gauss_seidel(&self.rhs[l], &mut self.x[l], false);
        }
    }

    /// K-cycle correction on level `m`: `x[m]` ≈ A⁻¹ `rhs[m]` from two preconditioned steps.
    fn krylov_correction(&mut self, m: usize) {
        // The work vectors of level m are not touched by the cycles below it.
        let mut work = std::mem::take(&mut self.krylov[m]);
        self.krylov_steps(m, &mut work);
        self.krylov[m] = work;
    }

    fn krylov_steps(&mut self, m: usize, [rc, v1, w1, w2]: &mut [Vec<f64>; 4]) {
        rc.copy_from_slice(&self.rhs[m]);
        self.coarse_cycle(m);
        v1.copy_from_slice(&self.x[m]);
        self.levels[m].apply(v1, w1);
        let rho1 = dot(v1, w1);
        if rho1.is_nan() || rho1 <= 0.0 {
            self.rhs[m].copy_from_slice(rc);
            return;
        }
        let alpha1 = dot(v1, rc) / rho1;
        // Second step on r2 = rc − α1 A v1, unless the first one left little residual.
        let r2 = &mut self.rhs[m];
        for ((r, c), w) in r2.iter_mut().zip(rc.iter()).zip(w1.iter()) {
            *r = c - alpha1 * w;
        }
        if dot(r2, r2) <= KRYLOV_SKIP * KRYLOV_SKIP * dot(rc, rc) {
            for (x, v) in self.x[m].iter_mut().zip(v1.iter()) {
                *x = alpha1 * v;
            }
            self.rhs[m].copy_from_slice(rc);
            return;
        }
        self.coarse_cycle(m);
        let v2 = &self.x[m];
        self.levels[m].apply(v2, w2);
        let gamma = dot(v2, w1);
        let beta = dot(v2, w2);
        let alpha2 = dot(v2, &self.rhs[m]);
        let rho2 = beta - gamma * gamma / rho1;
        let (c1, c2) = if rho2 > 0.0 {
            (alpha1 - gamma * alpha2 / (rho1 * rho2), alpha2 / rho2)
        } else {
            (alpha1, 0.0)
        };
        for (x, v) in self.x[m].iter_mut().zip(v1.iter()) {
            *x = c1 * v + c2 * *x;
        }
        self.rhs[m].copy_from_slice(rc);
    }

    fn dense_gather(&self, r: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.dense.size()];
        for (&k, &v) in self.fine_map.iter().zip(r) {
            if k != NONE {
                out[k as usize] = v;
            }
        }
        out
    }
}

/// Dense Cholesky factor of a small graph operator.
struct DenseCholesky {
    m: usize,
    /// Lower factor, row-major `m × m` (with the pivots on the diagonal).
    l: Vec<f64>,
    /// Its transpose without the diagonal, row-major.
    u: Vec<f64>,
}

impl DenseCholesky {
    fn new(graph: &Sparse) -> Self {
        let m = graph.nodes();
        let mut a = vec![0.0; m * m];
        for i in 0..m {
            a[i * m + i] += graph.diag[i];
            for (j, w) in graph.edges(i) {
                a[i * m + j] -= w;
            }
        }
        // In-place Cholesky, lower triangle.
        for j in 0..m {
            let mut d = a[j * m + j];
            for k in 0..j {
                d -= a[j * m + k] * a[j * m + k];
            }
            let floor = 1e-14 * graph.diag[j];
            let d = if d > floor { d.sqrt() } else { floor.sqrt() };
            a[j * m + j] = d;
            for i in j + 1..m {
                let mut s = a[i * m + j];
                for k in 0..j {
                    s -= a[i * m + k] * a[j * m + k];
                }
                a[i * m + j] = if d > 0.0 { s / d } else { 0.0 };
            }
        }
        let mut u = vec![0.0; m * m];
        for i in 0..m {
            for k in 0..i {
                u[k * m + i] = a[i * m + k];
            }
        }
        Self { m, l: a, u }
    }

    fn size(&self) -> usize {
        self.m
    }

    fn solve(&self, rhs: &[f64], x: &mut [f64]) {
        let m = self.m;
        let pivot = |i: usize, s: f64| {
            let d = self.l[i * m + i];
            if d > 0.0 { s / d } else { 0.0 }
        };
        x.copy_from_slice(&rhs[..m]);
        for i in 0..m {
            let (done, rest) = x.split_at_mut(i);
            rest[0] = pivot(i, rest[0] - dot(&self.l[i * m..i * m + i], done));
        }
        for i in (0..m).rev() {
            let (head, done) = x.split_at_mut(i + 1);
            head[i] = pivot(i, head[i] - dot(&self.u[i * m + i + 1..(i + 1) * m], done));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Conjugate gradients.

/// Solves A x = b from x = 0; returns (iterations, true relative residual).
/// Once the residual criterion holds, also asks the energy decrement of the last step,
/// `α r·z = ‖x_{k+1} − x_k‖²_A`, to be below `tolerance × D(x)` (the dissipation of the iterate,
/// evaluated directly): near the percolation threshold the residual is dominated by the wide
/// channels while the flow is set by a constriction. This second test gets at most
/// `10 + iterations/4` extra iterations, since at extreme contrast (beyond ~1e-15) it is below
/// the round-off of the wide channels; the residual test alone decides convergence.
fn pcg(
    grid: &Grid,
    b: &[f64],
    x: &mut [f64],
    dissipation: &dyn Fn(&[f64]) -> f64,
    settings: &FlowSettings,
) -> Result<(usize, f64), FlowError> {
    let cells = grid.cells();
    let b_norm = dot(b, b).sqrt();
    x.fill(0.0);
    if b_norm == 0.0 {
        return Ok((0, 0.0));
    }
    let mut precond = Precond::new(settings.preconditioner, grid);
    let mut r = b.to_vec();
    let mut z = vec![0.0; cells];
    let mut p = vec![0.0; cells];
    let mut q = vec![0.0; cells];
    let mut iterations = 0;
    let target = settings.tolerance * b_norm;
    let mut extra = 0;
    let mut true_norm = f64::INFINITY;
    // Restarts from the true residual if the recursive one drifted below it.
    for _restart in 0..5 {
        precond.apply(grid, &r, &mut z);
        p.copy_from_slice(&z);
        let mut rz = dot(&r, &z);
        while iterations < settings.max_iterations {
            let pq = grid.apply_dot(&p, &mut q);
            if pq.is_nan() || pq <= 0.0 || pq.is_infinite() {
                break;
            }
            let alpha = rz / pq;
            let mut rr = 0.0;
            for ((xi, pi), (ri, qi)) in x.iter_mut().zip(&p).zip(r.iter_mut().zip(&q)) {
                *xi += alpha * pi;
                *ri -= alpha * qi;
                rr += *ri * *ri;
            }
            iterations += 1;
            if rr.sqrt() <= target {
                let energy_converged = alpha * rz <= settings.tolerance * dissipation(x);
                if energy_converged || extra >= 10 + iterations / 4 {
                    break;
                }
                extra += 1;
            }
            precond.apply(grid, &r, &mut z);
            // Flexible (Polak–Ribière) β = z·(r − r_old)/(z_old·r_old) = −α z·q/(z_old·r_old):
            // the same as Fletcher–Reeves for a fixed preconditioner, robust for the K-cycle.
            let (mut rz_new, mut qz) = (0.0, 0.0);
            for ((ri, qi), zi) in r.iter().zip(&q).zip(&z) {
                rz_new += ri * zi;
                qz += qi * zi;
            }
            let beta = -alpha * qz / rz;
            rz = rz_new;
            for (pi, zi) in p.iter_mut().zip(&z) {
                *pi = zi + beta * *pi;
            }
        }
        // True residual.
        grid.apply(x, &mut q);
        for ((ri, bi), qi) in r.iter_mut().zip(b).zip(&q) {
            *ri = bi - qi;
        }
        true_norm = dot(&r, &r).sqrt();
        if true_norm <= target {
            return Ok((iterations, true_norm / b_norm));
        }
        if iterations >= settings.max_iterations {
            break;
        }
    }
    Err(FlowError::NotConverged {
        iterations,
        residual: true_norm / b_norm,
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
        let q = s.leak_rate(10e-3, 1e-3, 1e6);
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
