//! Two-dimensional real FFT on a square periodic grid (rustfft + realfft).
//!
//! Layout: a real field is `n × n`, row-major (`field[iy * n + ix]`). Its spectrum is the
//! half-plane `n × (n/2 + 1)`, row-major (`spectrum[ky * h + kx]`, `h = n/2 + 1`), with
//! `kx = 0..=n/2` and `ky = 0..n` (signed frequency [`signed_index`]). The forward transform is
//! unnormalised, ĥ(k) = Σ_x h(x) e^{−2πi k·x/n}; the inverse divides by n², so
//! `inverse(forward(h)) = h`.

use std::sync::Arc;

use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
pub use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

/// Signed frequency index of position `i` on an `n`-point periodic axis: `i` for `i ≤ n/2`,
/// else `i − n`.
pub fn signed_index(i: usize, n: usize) -> i64 {
    if i <= n / 2 {
        i as i64
    } else {
        i as i64 - n as i64
    }
}

/// Plans and scratch space for 2-D real transforms of one grid size.
pub struct Fft2 {
    n: usize,
    row_forward: Arc<dyn RealToComplex<f64>>,
    row_inverse: Arc<dyn ComplexToReal<f64>>,
    column_forward: Arc<dyn Fft<f64>>,
    column_inverse: Arc<dyn Fft<f64>>,
    /// Column-major copy of the half spectrum (`h` columns of length `n`).
    columns: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl Fft2 {
    /// Plans for an `n × n` grid (`n ≥ 2`, even; powers of two are fastest).
    pub fn new(n: usize) -> Self {
        assert!(
            n >= 2 && n.is_multiple_of(2),
            "grid size must be even and ≥ 2"
        );
        let mut real = RealFftPlanner::<f64>::new();
        let mut complex = FftPlanner::<f64>::new();
        let h = n / 2 + 1;
        let column_forward = complex.plan_fft_forward(n);
        let column_inverse = complex.plan_fft_inverse(n);
        let scratch_len = column_forward
            .get_inplace_scratch_len()
            .max(column_inverse.get_inplace_scratch_len());
        Self {
            n,
            row_forward: real.plan_fft_forward(n),
            row_inverse: real.plan_fft_inverse(n),
            column_forward,
            column_inverse,
            columns: vec![Complex::new(0.0, 0.0); h * n],
            scratch: vec![Complex::new(0.0, 0.0); scratch_len],
        }
    }

    /// Grid size `n`.
    pub fn size(&self) -> usize {
        self.n
    }

    /// Number of stored columns of the half spectrum, `n/2 + 1`.
    pub fn half(&self) -> usize {
        self.n / 2 + 1
    }

    /// Forward transform of `field` (`n²`, used as scratch: its contents are destroyed) into
    /// `spectrum` (`n (n/2 + 1)`).
    pub fn forward(&mut self, field: &mut [f64], spectrum: &mut [Complex<f64>]) {
        let (n, h) = (self.n, self.half());
        assert_eq!(field.len(), n * n);
        assert_eq!(spectrum.len(), n * h);
        for (row, out) in field.chunks_exact_mut(n).zip(spectrum.chunks_exact_mut(h)) {
            // Lengths are fixed by construction, so the only error realfft reports cannot occur.
            self.row_forward
                .process(row, out)
                .expect("row lengths match the plan");
        }
        self.transpose_in(spectrum);
        self.column_forward
            .process_with_scratch(&mut self.columns, &mut self.scratch);
        self.transpose_out(spectrum);
    }

    /// Inverse transform of `spectrum` (destroyed) into `field`, normalised so that
    /// `inverse ∘ forward` is the identity. The imaginary parts of the `kx = 0` and `kx = n/2`
    /// columns' self-conjugate entries are ignored.
    pub fn inverse(&mut self, spectrum: &mut [Complex<f64>], field: &mut [f64]) {
        let (n, h) = (self.n, self.half());
        assert_eq!(field.len(), n * n);
        assert_eq!(spectrum.len(), n * h);
        self.transpose_in(spectrum);
        self.column_inverse
            .process_with_scratch(&mut self.columns, &mut self.scratch);
        self.transpose_out(spectrum);
        let scale = 1.0 / (n * n) as f64;
        for (row, out) in spectrum.chunks_exact_mut(h).zip(field.chunks_exact_mut(n)) {
            // realfft insists on exactly real DC and Nyquist bins; rounding leaves ~1e-17.
            row[0].im = 0.0;
            row[h - 1].im = 0.0;
            self.row_inverse
                .process(row, out)
                .expect("row lengths match the plan");
            for value in out.iter_mut() {
                *value *= scale;
            }
        }
    }

    fn transpose_in(&mut self, spectrum: &[Complex<f64>]) {
        let (n, h) = (self.n, self.half());
        for ky in 0..n {
            for kx in 0..h {
                self.columns[kx * n + ky] = spectrum[ky * h + kx];
            }
        }
    }

    fn transpose_out(&mut self, spectrum: &mut [Complex<f64>]) {
        let (n, h) = (self.n, self.half());
        for kx in 0..h {
            for ky in 0..n {
                spectrum[ky * h + kx] = self.columns[kx * n + ky];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_identity() {
        let n = 16;
        let field: Vec<f64> = (0..n * n).map(|i| ((i * 37 % 101) as f64).sin()).collect();
        let mut fft = Fft2::new(n);
        let mut work = field.clone();
        let mut spectrum = vec![Complex::new(0.0, 0.0); n * fft.half()];
        fft.forward(&mut work, &mut spectrum);
        let mut back = vec![0.0; n * n];
        fft.inverse(&mut spectrum, &mut back);
        for (a, b) in field.iter().zip(&back) {
            assert!((a - b).abs() < 1e-13);
        }
    }

    #[test]
    fn single_mode_lands_on_its_wavevector() {
        // h = cos(2π (3x + 5y)/n) → ĥ(kx = 3, ky = 5) = n²/2.
        let n = 32;
        let mut field: Vec<f64> = (0..n * n)
            .map(|i| {
                let (x, y) = ((i % n) as f64, (i / n) as f64);
                (2.0 * std::f64::consts::PI * (3.0 * x + 5.0 * y) / n as f64).cos()
            })
            .collect();
        let mut fft = Fft2::new(n);
        let h = fft.half();
        let mut spectrum = vec![Complex::new(0.0, 0.0); n * h];
        fft.forward(&mut field, &mut spectrum);
        let peak = spectrum[5 * h + 3];
        assert!((peak.re - (n * n) as f64 / 2.0).abs() < 1e-9 && peak.im.abs() < 1e-9);
        let total: f64 = spectrum.iter().map(|c| c.norm()).sum();
        assert!((total - peak.norm()).abs() < 1e-8);
        assert_eq!(signed_index(n - 1, n), -1);
        assert_eq!(signed_index(n / 2, n), (n / 2) as i64);
    }
}
