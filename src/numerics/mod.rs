//! Numerical building blocks, each documented with its method and reference.

pub mod interp;
pub mod nnls;
pub mod quadrature;
pub mod special;

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
