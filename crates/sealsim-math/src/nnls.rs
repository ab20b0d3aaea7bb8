//! Non-negative least squares: `min ‖A x − b‖₂ subject to x ≥ 0`.
//!
//! The active-set algorithm NNLS of C.L. Lawson & R.J. Hanson, *Solving Least Squares
//! Problems*, Prentice-Hall 1974, ch. 23 (republished by SIAM, 1995). Every column `j` is
//! either *passive* (`j ∈ P`, `x_j > 0`, its bound inactive) or *active* (`j ∈ Z`,
//! `x_j = 0`). Starting from `x = 0`, `P = ∅`:
//!
//! 1. dual vector `w = Aᵀ(b − A x)`; stop when every `w_j ≤ tol` on `Z` (the Karush–Kuhn–Tucker
//!    conditions: then also `w_j = 0` on `P` up to rounding);
//! 2. move the active `t` with the largest `w_t` to `P`;
//! 3. solve the unconstrained least-squares problem on the passive columns, `z_P = argmin
//!    ‖A_P z − b‖`, `z_Z = 0`; if every `z_j > 0` on `P`, take `x = z` and go to 1;
//! 4. otherwise step from `x` towards `z` as far as feasibility allows,
//!    `α = min_{j∈P, z_j ≤ 0} x_j/(x_j − z_j)`, `x ← x + α (z − x)`, move the columns that
//!    reached zero back to `Z`, and go to 3.
//!
//! The passive subproblems are solved by Householder QR of `A_P` (nalgebra's [`QR`]),
//! never by the normal equations, so their error grows with cond(A_P), not its square.
//! As in Lawson & Hanson's program, a candidate column is refused (and the next largest
//! `w_j` tried) when it is numerically dependent on the passive columns
//! (`|R_kk| ≤ 100 ε ‖a_t‖`) or when its coefficient in the new solution is not positive;
//! this keeps `A_P` of full rank and rules out cycling through rounding errors.
//!
//! Tolerance (documented default, [`NnlsOptions::tolerance`]):
//! `tol = 10 ε max(m, n) · max_j ‖a_j‖₂ · ‖b‖₂`, the size of the rounding error of a
//! computed `w_j = a_jᵀ r` with `‖r‖ ≤ ‖b‖` (ε = 2.2e-16, `f64::EPSILON`).
//! Every iteration of step 3 counts against [`NnlsOptions::max_iterations`]; reaching the cap
//! is an error ([`NnlsError::IterationLimit`]), never an endless loop.

use nalgebra::{DMatrix, DVector, QR};
use std::fmt;

/// Settings of [`nnls_with`]; [`nnls`] uses the defaults.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct NnlsOptions {
    /// Largest dual value `w_j` on an active column that still counts as zero, in the units of
    /// `Aᵀb`; `None` for the default `10 ε max(m, n) max_j ‖a_j‖ ‖b‖` (module docs).
    pub tolerance: Option<f64>,
    /// Cap on the number of least-squares solves (step 3 of the module docs); `None` for
    /// `10 n + 10`, well above Lawson & Hanson's usual `3 n`.
    pub max_iterations: Option<usize>,
}

/// The solution of a non-negative least-squares problem.
#[derive(Debug, Clone, PartialEq)]
pub struct NnlsSolution {
    /// The minimiser `x ≥ 0` (exact zeros on the active set).
    pub x: DVector<f64>,
    /// The dual vector `w = Aᵀ(b − A x)` at the solution: `≤ tolerance` where `x_j = 0`,
    /// ≈ 0 where `x_j > 0`.
    pub dual: DVector<f64>,
    /// `‖A x − b‖₂`.
    pub residual_norm: f64,
    /// Least-squares solves performed.
    pub iterations: usize,
    /// The tolerance that was used on the dual vector.
    pub tolerance: f64,
}

/// Why [`nnls`] gave no solution.
#[derive(Debug, Clone, PartialEq)]
pub enum NnlsError {
    /// `A` has `rows` rows but `b` has `rhs` entries.
    DimensionMismatch { rows: usize, rhs: usize },
    /// `A` or `b` holds a NaN or an infinity.
    NonFinite,
    /// The iteration cap was reached before the KKT conditions held.
    IterationLimit { iterations: usize },
}

impl fmt::Display for NnlsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NnlsError::DimensionMismatch { rows, rhs } => write!(
                f,
                "non-negative least squares: the matrix has {rows} rows but the right-hand side has {rhs} entries"
            ),
            NnlsError::NonFinite => f.write_str(
                "non-negative least squares: the matrix or the right-hand side is not finite",
            ),
            NnlsError::IterationLimit { iterations } => write!(
                f,
                "non-negative least squares did not converge in {iterations} iterations"
            ),
        }
    }
}

impl std::error::Error for NnlsError {}

/// `argmin ‖A x − b‖₂` subject to `x ≥ 0`, with the default [`NnlsOptions`].
pub fn nnls(a: &DMatrix<f64>, b: &DVector<f64>) -> Result<NnlsSolution, NnlsError> {
    nnls_with(a, b, &NnlsOptions::default())
}

/// `argmin ‖A x − b‖₂` subject to `x ≥ 0` by Lawson & Hanson's algorithm (module docs).
pub fn nnls_with(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
    options: &NnlsOptions,
) -> Result<NnlsSolution, NnlsError> {
    let (m, n) = a.shape();
    if b.len() != m {
        return Err(NnlsError::DimensionMismatch {
            rows: m,
            rhs: b.len(),
        });
    }
    if !(a.iter().all(|v| v.is_finite()) && b.iter().all(|v| v.is_finite())) {
        return Err(NnlsError::NonFinite);
    }
    let column_norms: Vec<f64> = a.column_iter().map(|c| c.norm()).collect();
    let largest_column = column_norms.iter().copied().fold(0.0, f64::max);
    let tol = options
        .tolerance
        .unwrap_or(10.0 * f64::EPSILON * m.max(n) as f64 * largest_column * b.norm());
    let max_iterations = options.max_iterations.unwrap_or(10 * n + 10);

    let mut x = DVector::<f64>::zeros(n);
    let mut passive = vec![false; n];
    let mut iterations = 0;
    let mut w = dual(a, b, &x);
    // Columns refused since `x` last changed (dependent, or a non-positive coefficient).
    let mut refused = vec![false; n];
    loop {
        let candidate = (0..n)
            .filter(|&j| !passive[j] && !refused[j] && w[j] > tol)
            .max_by(|&i, &j| w[i].total_cmp(&w[j]));
        let Some(t) = candidate else { break };
        passive[t] = true;
        // Step 3–4: least squares on the passive set, stepping back while infeasible.
        let mut first = true;
        loop {
            if iterations >= max_iterations {
                return Err(NnlsError::IterationLimit { iterations });
            }
            iterations += 1;
            // The new column goes last, so that its R_kk measures its distance from the
            // span of the others.
            let mut columns: Vec<usize> = (0..n).filter(|&j| passive[j] && j != t).collect();
            if passive[t] {
                columns.push(t);
            }
            let solve = passive_least_squares(a, b, &columns, &column_norms);
            let z = match solve {
                Some(z) if !first || z[columns.len() - 1] > 0.0 => z,
                _ if first => {
                    // Lawson & Hanson's safeguard: refuse `t`, keep `x`, try the next column.
                    passive[t] = false;
                    refused[t] = true;
                    break;
                }
                // A subset of independent columns is independent: unreachable in exact
                // arithmetic; keep the feasible `x` and let the dual decide.
                _ => break,
            };
            first = false;
            if z.iter().all(|&v| v > 0.0) {
                x.fill(0.0);
                for (&j, &v) in columns.iter().zip(z.iter()) {
                    x[j] = v;
                }
                refused.fill(false);
                break;
            }
            // Feasible step towards z; the column that limits it is set to exactly zero.
            let mut alpha = f64::INFINITY;
            let mut limiting = columns[0];
            for (&j, &zj) in columns.iter().zip(z.iter()) {
                if zj <= 0.0 {
                    let ratio = x[j] / (x[j] - zj);
                    if ratio < alpha {
                        alpha = ratio;
                        limiting = j;
                    }
                }
            }
            for (&j, &zj) in columns.iter().zip(z.iter()) {
                x[j] += alpha * (zj - x[j]);
                if j == limiting || x[j] <= 0.0 {
                    x[j] = 0.0;
                    passive[j] = false;
                }
            }
            refused.fill(false);
            if !passive.iter().any(|&p| p) {
                break;
            }
        }
        w = dual(a, b, &x);
    }
    let residual_norm = (a * &x - b).norm();
    Ok(NnlsSolution {
        x,
        dual: w,
        residual_norm,
        iterations,
        tolerance: tol,
    })
}

/// `w = Aᵀ(b − A x)`.
fn dual(a: &DMatrix<f64>, b: &DVector<f64>, x: &DVector<f64>) -> DVector<f64> {
    a.tr_mul(&(b - a * x))
}

/// Least-squares solution on the columns `columns` of `a` (in that order) by Householder
/// QR. `None` when a column is numerically dependent on the ones before it,
/// `|R_kk| ≤ 100 ε ‖a_k‖` (Lawson & Hanson's test for the column entering the passive set).
fn passive_least_squares(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
    columns: &[usize],
    column_norms: &[f64],
) -> Option<DVector<f64>> {
    let k = columns.len();
    if k == 0 || k > a.nrows() {
        return None;
    }
    let sub = a.select_columns(columns);
    let qr = QR::new(sub);
    let mut rhs = b.clone();
    qr.q_tr_mul(&mut rhs);
    let r = qr.unpack_r();
    for (i, &j) in columns.iter().enumerate() {
        let diagonal = r[(i, i)].abs();
        if diagonal <= 100.0 * f64::EPSILON * column_norms[j] || diagonal == 0.0 {
            return None;
        }
    }
    r.solve_upper_triangular(&rhs.rows(0, k))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clamps_a_component_to_zero_by_hand() {
        // A = I₂, b = (1, −1): the unconstrained optimum (1, −1) is infeasible; the NNLS
        // optimum clamps x₂ = 0, and w₂ = −1 < 0 certifies it.
        let a = DMatrix::identity(2, 2);
        let b = DVector::from_vec(vec![1.0, -1.0]);
        let s = nnls(&a, &b).unwrap();
        assert_eq!(s.x.as_slice(), &[1.0, 0.0]);
        assert!((s.dual[1] + 1.0).abs() < 1e-15);
        assert!((s.residual_norm - 1.0).abs() < 1e-15);
    }

    #[test]
    fn degenerate_inputs() {
        let a = DMatrix::<f64>::zeros(3, 2);
        let b = DVector::from_vec(vec![1.0, 2.0, 3.0]);
        let s = nnls(&a, &b).unwrap();
        assert_eq!(s.x.as_slice(), &[0.0, 0.0]);
        assert_eq!(
            nnls(&a, &DVector::zeros(2)),
            Err(NnlsError::DimensionMismatch { rows: 3, rhs: 2 })
        );
        let mut bad = DMatrix::identity(2, 2);
        bad[(0, 1)] = f64::NAN;
        assert_eq!(nnls(&bad, &DVector::zeros(2)), Err(NnlsError::NonFinite));
        // duplicated columns: the second copy is dependent and must be refused, not cycled on
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 1.0, 2.0, 2.0, 3.0, 3.0]);
        let s = nnls(&a, &b).unwrap();
        assert!((s.x.sum() - 1.0).abs() < 1e-14, "{}", s.x);
        assert!(s.x.iter().filter(|&&v| v > 0.0).count() == 1);
    }

    #[test]
    fn iteration_cap_is_an_error() {
        let a = DMatrix::identity(3, 3);
        let b = DVector::from_vec(vec![1.0, 2.0, 3.0]);
        let options = NnlsOptions {
            max_iterations: Some(1),
            ..NnlsOptions::default()
        };
        assert_eq!(
            nnls_with(&a, &b, &options),
            Err(NnlsError::IterationLimit { iterations: 1 })
        );
    }
}
