//! Mathematical building blocks that are not physics (quadrature, interpolation, least squares,
//! special functions, linear solvers), each documented with its method and reference.

pub mod fft;
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
