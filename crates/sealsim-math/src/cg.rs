//! Preconditioned conjugate gradients for a symmetric positive definite system `A x = b`, in the
//! flexible (Polak–Ribière) form, so that the preconditioner may itself be an iteration (e.g. the
//! K-cycle of [`super::multigrid`]).
//!
//! The problem (the operator, [`LinearOperator`]) and the preconditioner ([`Preconditioner`]) are
//! supplied by the caller; [`solve`] only runs the iteration.

use super::dot;

/// A symmetric positive (semi)definite linear operator `y = A x` on vectors of a fixed length.
pub trait LinearOperator {
    /// `y = A x`.
    fn apply(&self, x: &[f64], y: &mut [f64]);

    /// `y = A x`; returns `x · y`. Implementations may fuse the dot product into the product
    /// (the default computes it afterwards with [`dot`]).
    fn apply_dot(&self, x: &[f64], y: &mut [f64]) -> f64 {
        self.apply(x, y);
        dot(x, y)
    }
}

/// An approximate inverse `z = M⁻¹ r` of the operator; it may keep work space between calls
/// (hence `&mut self`) and need not be a fixed linear map (flexible CG).
pub trait Preconditioner {
    /// `z = M⁻¹ r`.
    fn apply(&mut self, r: &[f64], z: &mut [f64]);
}

/// Diagonal (Jacobi) preconditioner `z_i = r_i / a_ii`, from the inverse diagonal (0 for
/// unknowns out of the system).
#[derive(Debug, Clone, Copy)]
pub struct Jacobi<'a> {
    /// `1/a_ii`.
    pub inverse_diagonal: &'a [f64],
}

impl Preconditioner for Jacobi<'_> {
    fn apply(&mut self, r: &[f64], z: &mut [f64]) {
        for ((z, r), d) in z.iter_mut().zip(r).zip(self.inverse_diagonal) {
            *z = r * d;
        }
    }
}

/// A scale of the energy of the solution, evaluated on the iterate (see [`solve`]).
pub type Energy<'a> = &'a dyn Fn(&[f64]) -> f64;

/// Stopping rule of [`solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Relative residual `‖b − A x‖₂/‖b‖₂` at which the iteration stops.
    pub tolerance: f64,
    /// Maximum number of iterations.
    pub max_iterations: usize,
}

/// Result of a converged [`solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Convergence {
    /// Iterations done.
    pub iterations: usize,
    /// True relative residual `‖b − A x‖₂/‖b‖₂` (recomputed at the end; 0 when `b = 0`).
    pub residual: f64,
}

/// [`solve`] did not reach the tolerance within the iteration limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NotConverged {
    /// Iterations done.
    pub iterations: usize,
    /// True relative residual reached.
    pub residual: f64,
}

/// Solves `A x = b` from `x = 0` by preconditioned conjugate gradients; `x` holds the iterate on
/// return (also on error).
///
/// The step length is the usual `α = r·z / p·Ap`; the direction update uses the flexible
/// (Polak–Ribière) `β = z·(r − r_old)/(z_old·r_old) = −α z·Ap/(z_old·r_old)`, the same as
/// Fletcher–Reeves for a fixed preconditioner and robust for a variable one. The iteration stops
/// when the recursive residual is below `tolerance · ‖b‖₂`, and is accepted when the true residual
/// `b − A x`, recomputed then, is too; otherwise it restarts from the true residual (at most five
/// times in all).
///
/// With `energy = Some(E)`, once the residual criterion holds the energy decrement of the last
/// step, `α r·z = ‖x_{k+1} − x_k‖²_A`, must also be below `tolerance × E(x)` (`E(x)` a scale of
/// the energy of the solution, evaluated by the caller on the iterate): where the residual is
/// dominated by a part of the system that does not set the quantity of interest, this keeps
/// iterating until the energy has converged. This second test gets at most
/// `10 + iterations/4` extra iterations, since it can fall below round-off; the residual test
/// alone decides convergence.
///
/// A non-positive or non-finite curvature `p·Ap` ends the current pass (then the restart logic
/// decides, from the true residual).
pub fn solve<A, M>(
    operator: &A,
    preconditioner: &mut M,
    b: &[f64],
    x: &mut [f64],
    energy: Option<Energy<'_>>,
    settings: &Settings,
) -> Result<Convergence, NotConverged>
where
    A: LinearOperator + ?Sized,
    M: Preconditioner + ?Sized,
{
    let len = b.len();
    let b_norm = dot(b, b).sqrt();
    x.fill(0.0);
    if b_norm == 0.0 {
        return Ok(Convergence {
            iterations: 0,
            residual: 0.0,
        });
    }
    let mut r = b.to_vec();
    let mut z = vec![0.0; len];
    let mut p = vec![0.0; len];
    let mut q = vec![0.0; len];
    let mut iterations = 0;
    let target = settings.tolerance * b_norm;
    let mut extra = 0;
    let mut true_norm = f64::INFINITY;
    // Restarts from the true residual if the recursive one drifted below it.
    for _restart in 0..5 {
        preconditioner.apply(&r, &mut z);
        p.copy_from_slice(&z);
        let mut rz = dot(&r, &z);
        while iterations < settings.max_iterations {
            let pq = operator.apply_dot(&p, &mut q);
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
                let energy_converged =
                    energy.is_none_or(|energy| alpha * rz <= settings.tolerance * energy(x));
                if energy_converged || extra >= 10 + iterations / 4 {
                    break;
                }
                extra += 1;
            }
            preconditioner.apply(&r, &mut z);
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
        operator.apply(x, &mut q);
        for ((ri, bi), qi) in r.iter_mut().zip(b).zip(&q) {
            *ri = bi - qi;
        }
        true_norm = dot(&r, &r).sqrt();
        if true_norm <= target {
            return Ok(Convergence {
                iterations,
                residual: true_norm / b_norm,
            });
        }
        if iterations >= settings.max_iterations {
            break;
        }
    }
    Err(NotConverged {
        iterations,
        residual: true_norm / b_norm,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cholesky::{DenseCholesky, ModifiedIncompleteCholesky};
    use crate::laplacian::GridLaplacian;
    use crate::multigrid::Multigrid;

    /// A 24 × 24 periodic grid with conductances over four decades, one cell held at 0.
    fn problem() -> (GridLaplacian, Vec<f64>) {
        let n = 24;
        let g =
            |i: usize, k: usize| 10f64.powf(4.0 * (((i * 7 + k * 13) * 37 % 101) as f64) / 101.0);
        let face_e: Vec<f64> = (0..n * n).map(|i| g(i, 1)).collect();
        let face_n: Vec<f64> = (0..n * n).map(|i| g(i, 2)).collect();
        let mut active = vec![true; n * n];
        active[0] = false;
        let grid = GridLaplacian::new(n, &face_e, &face_n, &active);
        let b = (0..n * n)
            .map(|i| {
                if i == 0 {
                    0.0
                } else {
                    ((i * 29 % 17) as f64) - 8.0
                }
            })
            .collect();
        (grid, b)
    }

    #[test]
    fn every_preconditioner_reaches_the_direct_solution() {
        let (grid, b) = problem();
        let cells = grid.cells();
        // Direct solution of the active cells.
        let mut dense = vec![0.0; cells * cells];
        let mut column = vec![0.0; cells];
        let mut unit = vec![0.0; cells];
        for j in 0..cells {
            unit.fill(0.0);
            unit[j] = 1.0;
            grid.apply(&unit, &mut column);
            for i in 0..cells {
                dense[i * cells + j] = column[i];
            }
        }
        dense[0] = 1.0; // the cell out of the system: x_0 = b_0 = 0
        let mut direct = vec![0.0; cells];
        DenseCholesky::new(cells, dense).solve(&b, &mut direct);
        let settings = Settings {
            tolerance: 1e-12,
            max_iterations: 10_000,
        };
        let check = |x: &[f64], c: Convergence| {
            assert!(c.residual <= 1e-12 && c.iterations > 0, "{c:?}");
            let scale = direct.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (x, d) in x.iter().zip(&direct) {
                assert!((x - d).abs() <= 1e-8 * scale, "{x} vs {d}");
            }
        };
        let mut x = vec![0.0; cells];
        let mut jacobi = Jacobi {
            inverse_diagonal: grid.inverse_diagonal(),
        };
        let c = solve(&grid, &mut jacobi, &b, &mut x, None, &settings).unwrap();
        check(&x, c);
        let mut mic = ModifiedIncompleteCholesky::new(&grid, 0.97);
        let c = solve(&grid, &mut mic, &b, &mut x, None, &settings).unwrap();
        check(&x, c);
        let mut multigrid = Multigrid::new(grid.clone());
        let energy = |x: &[f64]| dot(x, &b);
        let c = solve(&grid, &mut multigrid, &b, &mut x, Some(&energy), &settings).unwrap();
        check(&x, c);
        // Too few iterations: an error with the iterate so far.
        let few = Settings {
            max_iterations: 3,
            ..settings
        };
        let e = solve(&grid, &mut jacobi, &b, &mut x, None, &few).unwrap_err();
        assert_eq!(e.iterations, 3);
        assert!(e.residual > 1e-12);
    }
}
