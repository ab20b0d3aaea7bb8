//! Mathematical building blocks that are not physics (quadrature, interpolation, least squares,
//! special functions, FFTs, linear solvers, [`roots`]: bisection and golden-section search), each documented with its method and reference.
//!
//! Linear solvers: [`cg`] (preconditioned conjugate gradients, generic over the operator and the
//! preconditioner), [`laplacian`] (the periodic five-point operator), [`multigrid`] (aggregation
//! multigrid K-cycle preconditioner), [`cholesky`] (dense and modified incomplete Cholesky).

pub mod cg;
pub mod cholesky;
pub mod fft;
pub mod fnv;
pub mod interp;
pub mod laplacian;
pub mod memo;
pub mod multigrid;
pub mod nnls;
pub mod quadrature;
pub mod rng;
pub mod roots;
pub mod special;

/// Dot product `a · b` of two slices of equal length, with four partial sums: vectorisable and
/// a little more accurate than one running sum; the summation order is fixed.
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
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

/// `n ≥ 2` log-spaced values from `from` to `to` (both > 0), both ends exact.
pub fn log_spaced(from: f64, to: f64, n: usize) -> Vec<f64> {
    let n = n.max(2);
    let ratio = (to / from).ln();
    (0..n)
        .map(|i| match i {
            0 => from,
            _ if i == n - 1 => to,
            _ => from * (ratio * i as f64 / (n - 1) as f64).exp(),
        })
        .collect()
}

/// `[f(0), f(1), …, f(n−1)]` computed on two threads (the caller's and one scoped worker taking
/// the odd indices). For tables whose nodes are independent solves of a few ms each; the result
/// does not depend on the split. A panic in `f` propagates.
pub fn map_on_two_threads<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    let f = &f;
    std::thread::scope(|scope| {
        let odd = scope.spawn(move || (1..n).step_by(2).map(f).collect::<Vec<T>>());
        let even: Vec<T> = (0..n).step_by(2).map(f).collect();
        // a panic in the worker is a bug, not an input error: propagate it
        let odd = odd.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
        let mut out = Vec::with_capacity(n);
        let mut odd = odd.into_iter();
        for e in even {
            out.push(e);
            if let Some(o) = odd.next() {
                out.push(o);
            }
        }
        out
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_thread_map_keeps_the_order() {
        for n in [0, 1, 2, 7, 10] {
            assert_eq!(
                map_on_two_threads(n, |i| i * i),
                (0..n).map(|i| i * i).collect::<Vec<_>>()
            );
        }
    }
}
