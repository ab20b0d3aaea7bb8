//! Gauss–Legendre quadrature.

/// Nodes and weights of the n-point Gauss–Legendre rule on \[−1, 1\], by Newton iteration on
/// the Legendre polynomial from Tricomi's initial guesses (Golub & Welsch give the same
/// rule; Newton is simpler and exact to rounding for the n ≤ 64 used here).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    assert!(n >= 1, "Gauss-Legendre needs at least one node");
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    let nf = n as f64;
    for i in 0..n.div_ceil(2) {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            if n == 1 {
                p1 = z;
                p0 = 1.0;
            } else {
                for k in 2..=n {
                    let kf = k as f64;
                    let p2 = ((2.0 * kf - 1.0) * z * p1 - (kf - 1.0) * p0) / kf;
                    p0 = p1;
                    p1 = p2;
                }
            }
            // p1 = P_n(z), p0 = P_{n−1}(z)
            dp = nf * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        let wi = 2.0 / ((1.0 - z * z) * dp * dp);
        w[i] = wi;
        w[n - 1 - i] = wi;
    }
    (x, w)
}

/// Most nodes of a rule [`rule`] keeps.
pub const CACHED_ORDERS: usize = 64;

/// The n-point rule of [`gauss_legendre`] (1 ≤ n ≤ [`CACHED_ORDERS`]), computed once per order
/// and shared: for the inner loops that integrate many short intervals with the same rule.
pub fn rule(n: usize) -> &'static (Vec<f64>, Vec<f64>) {
    static RULES: [std::sync::OnceLock<(Vec<f64>, Vec<f64>)>; CACHED_ORDERS] =
        [const { std::sync::OnceLock::new() }; CACHED_ORDERS];
    assert!(
        (1..=CACHED_ORDERS).contains(&n),
        "cached Gauss-Legendre rules have 1 to {CACHED_ORDERS} nodes, not {n}"
    );
    RULES[n - 1].get_or_init(|| gauss_legendre(n))
}

/// `∫_a^b f(x) dx` by the n-point Gauss–Legendre rule on the one panel \[a, b\] ([`rule`]):
/// `½(b − a) Σ w_i f(m + ½(b − a) x_i)`, m the midpoint; exact for polynomials of degree
/// 2n − 1.
pub fn gauss_integral(f: impl Fn(f64) -> f64, n: usize, a: f64, b: f64) -> f64 {
    let (nodes, weights) = rule(n);
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    nodes
        .iter()
        .zip(weights)
        .map(|(x, w)| w * f(mid + half * x))
        .sum::<f64>()
        * half
}

/// Most panels [`composite`] cuts one interval into: a bound on the cost of one integral (an
/// interval wider than `MAX_PANELS × max_width` gets wider panels, a coarser rule, rather than
/// an unbounded loop).
pub const MAX_PANELS: f64 = 1_048_576.0;

/// The composite rule built from the n-point rule (`nodes`, `weights` of [`gauss_legendre`]) on
/// the intervals between consecutive `breaks` (increasing), each cut into equal panels no wider
/// than `max_width`: `(abscissa, weight)` pairs in increasing abscissa, weight `½ h w_i` for a
/// panel of width h. An interval of non-finite length contributes no pairs; an interval is cut
/// into at most [`MAX_PANELS`] panels.
pub fn composite<'a>(
    breaks: &'a [f64],
    max_width: f64,
    nodes: &'a [f64],
    weights: &'a [f64],
) -> impl Iterator<Item = (f64, f64)> + 'a {
    breaks.windows(2).flat_map(move |pair| {
        let (lo, hi) = (pair[0], pair[1]);
        // an interval of non-finite length has no panels; at most MAX_PANELS per interval
        let panels = if (hi - lo).is_finite() {
            ((hi - lo) / max_width).ceil().clamp(1.0, MAX_PANELS)
        } else {
            0.0
        } as usize;
        let h = (hi - lo) / panels as f64;
        (0..panels).flat_map(move |p| {
            let mid = lo + (p as f64 + 0.5) * h;
            nodes
                .iter()
                .zip(weights)
                .map(move |(x, w)| (mid + 0.5 * h * x, 0.5 * h * w))
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cached_rule_is_the_rule_and_integrates_a_cubic_on_any_interval() {
        for n in [1, 2, 8, 64] {
            assert_eq!(rule(n), &gauss_legendre(n));
        }
        // ∫_1^3 x³ dx = (81 − 1)/4 = 20, exact from two nodes on
        for n in [2, 4, 8] {
            assert!(
                (gauss_integral(|x| x.powi(3), n, 1.0, 3.0) - 20.0).abs() < 1e-13,
                "{n}"
            );
        }
    }

    #[test]
    fn integrates_polynomials_exactly_to_degree_2n_minus_1() {
        for n in [2, 5, 8, 16] {
            let (x, w) = gauss_legendre(n);
            assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
            for deg in 0..(2 * n) {
                let got: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(deg as i32)).sum();
                let exact = if deg % 2 == 1 {
                    0.0
                } else {
                    2.0 / (deg as f64 + 1.0)
                };
                assert!((got - exact).abs() < 1e-13, "n={n} deg={deg}");
            }
        }
    }
}
