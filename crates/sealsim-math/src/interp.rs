//! Interpolation on uniform grids.

/// Values on a uniform grid `x_i = x0 + i h`, interpolated by the cubic Lagrange polynomial
/// through the four nearest nodes (shifted stencil at the ends). Error O(h⁴ f''''); exact for
/// cubics. O(1) lookup, no global solve.
#[derive(Debug, Clone, PartialEq)]
pub struct UniformCubic {
    x0: f64,
    h: f64,
    y: Vec<f64>,
}

impl UniformCubic {
    /// `y` sampled at `x0 + i h`; needs at least four samples and `h > 0`.
    pub fn new(x0: f64, h: f64, y: Vec<f64>) -> Self {
        assert!(
            y.len() >= 4 && h > 0.0,
            "cubic interpolation needs ≥ 4 nodes and h > 0"
        );
        UniformCubic { x0, h, y }
    }

    /// The grid spacing h.
    pub fn spacing(&self) -> f64 {
        self.h
    }

    /// First and last abscissa.
    pub fn range(&self) -> (f64, f64) {
        (self.x0, self.x0 + self.h * (self.y.len() - 1) as f64)
    }

    /// Interpolated value at `x` (extrapolates the end cubic outside the range).
    #[inline]
    pub fn eval(&self, x: f64) -> f64 {
        let n = self.y.len();
        let t = (x - self.x0) / self.h;
        // stencil start j: nodes j..j+3 with t in [j+1, j+2] in the interior
        let j = (t.floor() as isize - 1).clamp(0, n as isize - 4) as usize;
        let s = t - j as f64; // position relative to node j, in [0, 3] inside
        let (y0, y1, y2, y3) = (self.y[j], self.y[j + 1], self.y[j + 2], self.y[j + 3]);
        let (a, b, c, d) = (s, s - 1.0, s - 2.0, s - 3.0);
        -y0 * b * c * d / 6.0 + y1 * a * c * d / 2.0 - y2 * a * b * d / 2.0 + y3 * a * b * c / 6.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_cubics_exactly() {
        let f = |x: f64| 2.0 - 3.0 * x + 0.5 * x * x - 0.25 * x * x * x;
        let y: Vec<f64> = (0..10).map(|i| f(-1.0 + 0.3 * i as f64)).collect();
        let c = UniformCubic::new(-1.0, 0.3, y);
        for x in [-1.0, -0.93, 0.0, 0.41, 1.2, 1.7] {
            assert!((c.eval(x) - f(x)).abs() < 1e-12, "x={x}");
        }
    }

    #[test]
    fn fourth_order_convergence() {
        let err = |n: usize| {
            let h = 1.0 / n as f64;
            let y = (0..=n).map(|i| (i as f64 * h).sin()).collect();
            let c = UniformCubic::new(0.0, h, y);
            (0..1000)
                .map(|k| (c.eval(k as f64 / 1000.0) - (k as f64 / 1000.0).sin()).abs())
                .fold(0.0, f64::max)
        };
        let ratio = err(10) / err(20);
        assert!(ratio > 12.0 && ratio < 20.0, "ratio {ratio}");
    }
}
