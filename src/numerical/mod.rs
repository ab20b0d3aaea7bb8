//! Numerical reference (docs/model.md §3.5): a periodic random surface from the spectrum, FFT boundary
//! elements for the frictionless contact of an elastic half-space on it, percolation of the
//! non-contact region and thin-film Reynolds flow through the gap field.
//!
//! It resolves only a band q1/q0 of a few hundred, so the analytic levels are compared with it on
//! the same band-limited spectrum.

pub mod bem;
pub mod flow;
pub mod percolation;
pub mod psd;
pub mod reference;
pub mod surface;
pub mod table;

/// A square periodic grid of heights: `n × n` samples `pixel` apart (m), row-major
/// (`heights[iy * n + ix]`, x along the flow). Heights in m.
#[derive(Debug, Clone, PartialEq)]
pub struct HeightMap {
    /// Samples per side.
    pub n: usize,
    /// Sample spacing (m).
    pub pixel: f64,
    /// Heights (m), `n²` values.
    pub heights: Vec<f64>,
}

impl HeightMap {
    /// Side length of the periodic cell, `n · pixel` (m).
    pub fn side(&self) -> f64 {
        self.n as f64 * self.pixel
    }

    /// Root-mean-square slope by periodic forward differences,
    /// `(⟨(∂h/∂x)² + (∂h/∂y)²⟩)^{1/2}` (dimensionless).
    pub fn rms_slope(&self) -> f64 {
        let n = self.n;
        let mut sum = 0.0;
        for iy in 0..n {
            for ix in 0..n {
                let h = self.heights[iy * n + ix];
                let dx = self.heights[iy * n + (ix + 1) % n] - h;
                let dy = self.heights[((iy + 1) % n) * n + ix] - h;
                sum += dx * dx + dy * dy;
            }
        }
        (sum / (n * n) as f64).sqrt() / self.pixel
    }

    /// Root-mean-square height about the mean (m).
    pub fn rms(&self) -> f64 {
        let count = self.heights.len() as f64;
        let mean = self.heights.iter().sum::<f64>() / count;
        (self.heights.iter().map(|h| (h - mean).powi(2)).sum::<f64>() / count).sqrt()
    }
}
