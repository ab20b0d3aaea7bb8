//! Weighted graph Laplacian of a periodic square grid: the symmetric five-point operator
//!
//! ```text
//! (A x)_i = d_i x_i − Σ_faces g_f x_neighbour,     d_i = Σ_faces g_f + s_i,
//! ```
//!
//! on an `n × n` grid with periodic wrap in both directions (row-major, `x[iy * n + ix]`), face
//! conductances `g_f ≥ 0` and sinks `s_i ≥ 0` (connections to cells held at zero). Symmetric
//! positive semidefinite; definite on every connected component with a sink. Cells with no faces
//! and no sink (`d = 0`) are out of the system: their entries in every vector stay 0.
//!
//! The kernels are the product ([`GridLaplacian::apply`], [`GridLaplacian::apply_dot`]) and a
//! Gauss–Seidel sweep ([`GridLaplacian::gauss_seidel`]), both row by row for the cache; the
//! operator is the fine level of [`super::multigrid`] and of
//! [`super::cholesky::ModifiedIncompleteCholesky`].

use super::cg::LinearOperator;
use super::dot;

/// Symmetric positive (semi)definite 5-point operator on a periodic `n × n` grid; see the module
/// docs.
#[derive(Debug, Clone)]
pub struct GridLaplacian {
    n: usize,
    /// Conductance of the face to the east neighbour (0 if either cell is inactive).
    ge: Vec<f64>,
    /// Conductance of the face to the north neighbour.
    gn: Vec<f64>,
    /// Diagonal: sum of the faces plus the sinks.
    diag: Vec<f64>,
    /// 1/diag, 0 for inactive cells.
    inv_diag: Vec<f64>,
    /// Sinks: diagonal excess over the faces (connections to cells held at 0).
    extra: Vec<f64>,
}

impl GridLaplacian {
    /// The operator of the active cells of a network with conductance `face_e[i]` on the face
    /// between cell `i` and its east neighbour and `face_n[i]` to its north neighbour. Faces
    /// between two active cells are kept; a face between an active and an inactive cell becomes
    /// a sink of the active one (the inactive cell held at 0, a Dirichlet condition); faces
    /// between inactive cells are dropped.
    pub fn new(n: usize, face_e: &[f64], face_n: &[f64], active: &[bool]) -> Self {
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

    /// Grid side `n`.
    pub fn side(&self) -> usize {
        self.n
    }

    /// Number of cells `n²` (the length of every vector).
    pub fn cells(&self) -> usize {
        self.n * self.n
    }

    /// Diagonal `d_i` (faces plus sink).
    pub fn diagonal(&self) -> &[f64] {
        &self.diag
    }

    /// `1/d_i`, 0 for cells out of the system.
    pub fn inverse_diagonal(&self) -> &[f64] {
        &self.inv_diag
    }

    /// Sink of every cell: the diagonal in excess of its faces.
    pub fn sinks(&self) -> &[f64] {
        &self.extra
    }

    /// Conductance of the face to the east neighbour of every cell.
    pub fn east(&self) -> &[f64] {
        &self.ge
    }

    /// Conductance of the face to the north neighbour of every cell.
    pub fn north(&self) -> &[f64] {
        &self.gn
    }

    /// The four neighbours of cell `i` (east, west, north, south) with the conductances of the
    /// faces to them.
    pub fn neighbours(&self, i: usize) -> [(usize, f64); 4] {
        let n = self.n;
        let (ix, iy) = (i % n, i / n);
        let e = iy * n + (ix + 1) % n;
        let w = iy * n + (ix + n - 1) % n;
        let no = ((iy + 1) % n) * n + ix;
        let so = ((iy + n - 1) % n) * n + ix;
        [
            (e, self.ge[i]),
            (w, self.ge[w]),
            (no, self.gn[i]),
            (so, self.gn[so]),
        ]
    }

    /// y = A x.
    pub fn apply(&self, x: &[f64], y: &mut [f64]) {
        self.apply_dot(x, y);
    }

    /// y = A x; returns x·y (computed row by row while the row is in cache).
    pub fn apply_dot(&self, x: &[f64], y: &mut [f64]) -> f64 {
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
    pub fn gauss_seidel(&self, rhs: &[f64], x: &mut [f64], forward: bool, scratch: &mut Vec<f64>) {
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

impl LinearOperator for GridLaplacian {
    fn apply(&self, x: &[f64], y: &mut [f64]) {
        GridLaplacian::apply(self, x, y);
    }

    fn apply_dot(&self, x: &[f64], y: &mut [f64]) -> f64 {
        GridLaplacian::apply_dot(self, x, y)
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
