//! One-dimensional root finding and minimisation on a bracket: bisection (for roots of
//! monotone functions, and thresholds of monotone predicates) and golden-section search (for a
//! minimum of a unimodal function). Each call site states which quantity is monotone or
//! unimodal and why.
//!
//! Brent's method is not here: no search in sealsim needs it. The life run's failure times are
//! located by a geometric-midpoint bisection (its own, in `simulate`, because times span
//! decades), and the effective-medium gap by a safeguarded secant (`contact::effective_medium`),
//! both kept beside their models.

use std::convert::Infallible;

/// Bisection of the bracket `[lo, hi]` on a predicate that is `true` below a threshold and
/// `false` above it (`below(x)` = "the root lies above x"), e.g. `f(x) < 0` for an increasing
/// `f`. Returns the final bracket `(lo, hi)`; the threshold lies in it.
///
/// Each iteration halves the bracket at its midpoint m = (lo + hi)/2: `lo = m` if `below(m)`,
/// else `hi = m`. It stops before an iteration when `converged(lo, hi)`, when the midpoint no
/// longer lies strictly inside the bracket (the bracket is two adjacent floating-point numbers:
/// "to the last bit"), or after `max_iterations` halvings. The bracket shrinks by 2⁻ᵏ after k
/// iterations, so the error is bounded without any smoothness of the function (Burden & Faires,
/// *Numerical Analysis*, §2.1, the bisection method; convergence is linear with ratio 1/2).
pub fn bisect(
    lo: f64,
    hi: f64,
    max_iterations: usize,
    converged: impl Fn(f64, f64) -> bool,
    mut below: impl FnMut(f64) -> bool,
) -> (f64, f64) {
    let result: Result<(f64, f64), Infallible> =
        try_bisect(lo, hi, max_iterations, converged, |x| Ok(below(x)));
    match result {
        Ok(bracket) => bracket,
    }
}

/// [`bisect`] with a predicate that can fail: the first error ends the search and is returned.
pub fn try_bisect<E>(
    mut lo: f64,
    mut hi: f64,
    max_iterations: usize,
    converged: impl Fn(f64, f64) -> bool,
    mut below: impl FnMut(f64) -> Result<bool, E>,
) -> Result<(f64, f64), E> {
    for _ in 0..max_iterations {
        if converged(lo, hi) {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if below(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok((lo, hi))
}

/// The root of a continuous `f` with `f(lo) < 0 ≤ f(hi)` by the Illinois variant of regula
/// falsi, to a bracket no wider than `tol` (at most 200 steps). The ends come with their values
/// `(lo, f(lo))`, `(hi, f(hi))`, which a caller has usually computed to decide that there is a
/// root to find. Returns the final bracket `(lo, hi)` with `f(lo) < 0 ≤ f(hi)`; an input that
/// is not such a bracket is returned as it is.
///
/// Each step takes the secant point of the bracket (the midpoint where round-off would put it
/// on an end); when the same end is kept twice its function value is halved, which makes the
/// convergence superlinear (order ≈ 1.44) on smooth functions where plain regula falsi stalls
/// (Dowell & Jarratt, "A modified regula falsi method for computing the root of an equation",
/// BIT 11 (1971) 168–174).
pub fn illinois(
    mut f: impl FnMut(f64) -> f64,
    (lo, f_lo): (f64, f64),
    (hi, f_hi): (f64, f64),
    tol: f64,
) -> (f64, f64) {
    let (mut a, mut b) = (lo, hi);
    let (mut fa, mut fb) = (f_lo, f_hi);
    // which end the last step replaced: +1 the upper, −1 the lower
    let mut side = 0i8;
    for _ in 0..200 {
        if b - a <= tol || !(fa < 0.0 && fb >= 0.0) {
            break;
        }
        let x = (a * fb - b * fa) / (fb - fa);
        let x = if x > a && x < b { x } else { 0.5 * (a + b) };
        if x <= a || x >= b {
            break;
        }
        let fx = f(x);
        if fx >= 0.0 {
            (b, fb) = (x, fx);
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            (a, fa) = (x, fx);
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
    }
    (a, b)
}

/// No convergence test: [`bisect`] runs to the last bit (or `max_iterations`).
pub fn to_the_last_bit(_lo: f64, _hi: f64) -> bool {
    false
}

/// Golden-section search for a minimum of a unimodal `f` on `[a, b]`, to a bracket width
/// `tol` (at most 200 reductions); returns the midpoint of the final bracket.
///
/// Two interior points at the golden ratio g = (√5 − 1)/2 of the bracket; the one with the
/// larger value and the end beyond it are dropped, and the kept interior point is reused, so
/// each step costs one evaluation and shrinks the bracket by g ≈ 0.618 (J. Kiefer, "Sequential
/// minimax search for a maximum", Proc. Amer. Math. Soc. 4 (1953) 502–506).
pub fn golden_section(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64, tol: f64) -> f64 {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - g * (b - a);
    let mut d = a + g * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if b - a <= tol {
            break;
        }
        if fc <= fd {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// √2 as the root of x² − 2 on [1, 2], to the last bit: the bracket ends as two adjacent
    /// doubles around the correctly rounded √2.
    #[test]
    fn bisection_finds_a_square_root_to_the_last_bit() {
        let (lo, hi) = bisect(1.0, 2.0, 200, to_the_last_bit, |x| x * x < 2.0);
        let root = 2f64.sqrt();
        assert!(lo <= root && root <= hi, "{lo} {root} {hi}");
        assert_eq!(lo.next_up(), hi, "not to the last bit: [{lo}, {hi}]");
    }

    /// The convergence test and the iteration cap each end the search where they should: k
    /// halvings of [0, 1] leave a bracket of 2⁻ᵏ.
    #[test]
    fn bisection_stops_at_the_tolerance_or_the_cap() {
        let (lo, hi) = bisect(0.0, 1.0, 10, to_the_last_bit, |x| x < 0.3);
        assert_eq!(hi - lo, 2f64.powi(-10));
        assert!(lo < 0.3 && 0.3 < hi);
        let (lo, hi) = bisect(0.0, 1.0, 200, |lo, hi| hi - lo < 1e-6, |x| x < 0.3);
        assert!(hi - lo < 1e-6 && hi - lo > 0.5e-6);
        let mut calls = 0;
        let _ = bisect(
            0.0,
            1.0,
            200,
            |_, _| true,
            |_| {
                calls += 1;
                true
            },
        );
        assert_eq!(calls, 0, "a converged bracket needs no evaluation");
    }

    /// The first error of a fallible predicate ends the search and is returned.
    #[test]
    fn a_failing_predicate_ends_the_search() {
        let mut calls = 0;
        let result = try_bisect(0.0, 1.0, 200, to_the_last_bit, |x| {
            calls += 1;
            if x < 0.2 { Err("stop") } else { Ok(false) }
        });
        assert_eq!(result, Err("stop"));
        // 0.5, 0.25, 0.125: the third midpoint is below 0.2
        assert_eq!(calls, 3);
    }

    /// The cube root of 2 as the root of x³ − 2 on [0, 2] to 1e-12, in far fewer evaluations than
    /// bisection's 41; and on a root where plain regula falsi keeps one end for ever (a convex
    /// exponential, e^{10x} − 2 on [0, 1]) the halving of the kept end still converges.
    #[test]
    fn illinois_finds_roots_faster_than_bisection() {
        let count = std::cell::Cell::new(0);
        let f = |x: f64| {
            count.set(count.get() + 1);
            x.powi(3) - 2.0
        };
        let (lo, hi) = illinois(f, (0.0, -2.0), (2.0, 6.0), 1e-12);
        let root = 2f64.cbrt();
        assert!(lo <= root && root <= hi && hi - lo <= 1e-12, "[{lo}, {hi}]");
        assert!(count.get() < 30, "{} evaluations", count.get());
        let g = |x: f64| (10.0 * x).exp() - 2.0;
        let (lo, hi) = illinois(g, (0.0, g(0.0)), (1.0, g(1.0)), 1e-12);
        let root = 2f64.ln() / 10.0;
        assert!(lo <= root && root <= hi && hi - lo <= 1e-12, "[{lo}, {hi}]");
        // not a bracket: returned as it is, with no evaluation
        count.set(0);
        let f = |x: f64| {
            count.set(count.get() + 1);
            x
        };
        assert_eq!(illinois(f, (1.0, 1.0), (2.0, 2.0), 1e-12), (1.0, 2.0));
        assert_eq!(count.get(), 0);
    }

    #[test]
    fn golden_section_finds_a_parabola_minimum() {
        let x = golden_section(|x| (x - 0.3).powi(2), -1.0, 1.0, 1e-10);
        assert!((x - 0.3).abs() < 1e-9, "{x}");
        // a minimum at the end of the bracket is approached, not missed
        let x = golden_section(|x| x, 0.0, 1.0, 1e-10);
        assert!(x < 1e-9, "{x}");
    }
}
