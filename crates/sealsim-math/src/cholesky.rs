//! Cholesky factorisations: a dense one for small systems (the coarsest level of
//! [`super::multigrid`]) and the modified incomplete one, MIC(0), of the periodic five-point
//! operator [`GridLaplacian`] (a preconditioner for [`super::cg`]).

use super::cg::Preconditioner;
use super::dot;
use super::laplacian::GridLaplacian;

/// Dense Cholesky factor `L Lᵀ` of a small symmetric positive (semi)definite matrix.
///
/// In place, column by column. Semidefinite or near-singular blocks do not break down: a pivot
/// `d` (before the square root) not above `1e-14 ×` the original diagonal entry is replaced by
/// that floor.
#[derive(Debug, Clone)]
pub struct DenseCholesky {
    m: usize,
    /// Lower factor, row-major `m × m` (with the pivots on the diagonal).
    l: Vec<f64>,
    /// Its transpose without the diagonal, row-major.
    u: Vec<f64>,
}

impl DenseCholesky {
    /// Factorises the symmetric `m × m` matrix `a` (row-major; only the lower triangle and the
    /// diagonal are read).
    pub fn new(m: usize, mut a: Vec<f64>) -> Self {
        assert_eq!(a.len(), m * m, "the matrix is m × m");
        // In-place Cholesky, lower triangle.
        for j in 0..m {
            // The diagonal entry is still the original one here.
            let diagonal = a[j * m + j];
            let mut d = diagonal;
            for k in 0..j {
                d -= a[j * m + k] * a[j * m + k];
            }
            let floor = 1e-14 * diagonal;
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

    /// Order `m` of the matrix.
    pub fn size(&self) -> usize {
        self.m
    }

    /// Solves `L Lᵀ x = rhs` (the first `m` entries of `rhs`; a zero pivot gives 0).
    pub fn solve(&self, rhs: &[f64], x: &mut [f64]) {
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

/// Modified incomplete Cholesky MIC(0) of a [`GridLaplacian`]:
/// `M = (D − E) D⁻¹ (D − Eᵀ)`, `E` the strictly lower part of `−A`, natural (row-major) order,
/// no fill; the dropped fill is added to the diagonal with weight ω (the relaxation). A pivot not
/// above `1e-12 ×` the diagonal (breakdown on near-singular clusters, round-off) is replaced by
/// the diagonal.
#[derive(Debug, Clone)]
pub struct ModifiedIncompleteCholesky<'a> {
    grid: &'a GridLaplacian,
    /// Pivots D.
    pivot: Vec<f64>,
    inv_pivot: Vec<f64>,
}

impl<'a> ModifiedIncompleteCholesky<'a> {
    /// The factorisation of `grid` with relaxation `omega` (1 = row sums preserved exactly,
    /// 0 = IC(0)).
    pub fn new(grid: &'a GridLaplacian, omega: f64) -> Self {
        let cells = grid.cells();
        let diag = grid.diagonal();
        let mut pivot = vec![0.0; cells];
        for i in 0..cells {
            if diag[i] <= 0.0 {
                continue;
            }
            let mut d = diag[i];
            for (j, g) in grid.neighbours(i) {
                if j >= i || g == 0.0 || pivot[j] <= 0.0 {
                    continue;
                }
                // Fill that elimination of j would put in row i, towards j's other upper
                // neighbours k (dropped, and added to the diagonal with weight ω).
                let fill: f64 = grid
                    .neighbours(j)
                    .iter()
                    .filter(|&&(k, _)| k > j && k != i)
                    .map(|&(_, gk)| gk)
                    .sum();
                d -= g * (g + omega * fill) / pivot[j];
            }
            // Guard against breakdown (near-singular clusters, round-off).
            pivot[i] = if d > 1e-12 * diag[i] { d } else { diag[i] };
        }
        let inv_pivot = pivot
            .iter()
            .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
            .collect();
        Self {
            grid,
            pivot,
            inv_pivot,
        }
    }

    /// `z = M⁻¹ r`: forward and backward triangular solves in the natural order.
    pub fn solve(&self, r: &[f64], z: &mut [f64]) {
        let grid = self.grid;
        let n = grid.side();
        let (ge, gn, inv) = (grid.east(), grid.north(), &self.inv_pivot);
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

impl Preconditioner for ModifiedIncompleteCholesky<'_> {
    fn apply(&mut self, r: &[f64], z: &mut [f64]) {
        self.solve(r, z);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dense_factor_solves_a_small_spd_system() {
        // A = [[4, 2, 0], [2, 5, 1], [0, 1, 3]], x = (1, −2, 3).
        let a = vec![4.0, 2.0, 0.0, 2.0, 5.0, 1.0, 0.0, 1.0, 3.0];
        let x_true = [1.0, -2.0, 3.0];
        let b: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[i * 3 + j] * x_true[j]).sum())
            .collect();
        let chol = DenseCholesky::new(3, a);
        assert_eq!(chol.size(), 3);
        let mut x = [0.0; 3];
        chol.solve(&b, &mut x);
        for (x, t) in x.iter().zip(x_true) {
            assert!((x - t).abs() < 1e-14, "{x} vs {t}");
        }
    }
}
