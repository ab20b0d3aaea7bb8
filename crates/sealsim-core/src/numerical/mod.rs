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

/// A rectangular grid of heights as measured: `nx × ny` samples `pixel` apart in both
/// directions (m, square pixels), row-major (`heights[iy * nx + ix]`, x along the flow),
/// heights in m. The power-spectrum estimate ([`psd::radial_psd_topography`]) works on any
/// such grid; the numerical solvers need a square periodic [`HeightMap`]
/// ([`Topography::square_crop`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Topography {
    /// Samples along x (per row).
    pub nx: usize,
    /// Samples along y (rows).
    pub ny: usize,
    /// Sample spacing in x and y (m).
    pub pixel: f64,
    /// Heights (m), `nx · ny` values.
    pub heights: Vec<f64>,
}

impl From<HeightMap> for Topography {
    fn from(map: HeightMap) -> Self {
        Topography {
            nx: map.n,
            ny: map.n,
            pixel: map.pixel,
            heights: map.heights,
        }
    }
}

impl Topography {
    /// Side lengths `(Lx, Ly) = (nx · pixel, ny · pixel)` (m).
    pub fn sides(&self) -> (f64, f64) {
        (self.nx as f64 * self.pixel, self.ny as f64 * self.pixel)
    }

    /// The largest centred square with an even side, `m = 2 ⌊min(nx, ny)/2⌋`, starting at
    /// `((nx − m)/2, (ny − m)/2)` (integer division): the grid the numerical level (square,
    /// periodic, even FFT size) runs on. The whole grid when it is already square and even.
    /// Returns the map and its offset `(ix0, iy0)`.
    pub fn square_crop(&self) -> (HeightMap, (usize, usize)) {
        let m = 2 * (self.nx.min(self.ny) / 2);
        let (x0, y0) = ((self.nx - m) / 2, (self.ny - m) / 2);
        let heights = (0..m)
            .flat_map(|iy| {
                let start = (y0 + iy) * self.nx + x0;
                self.heights[start..start + m].iter().copied()
            })
            .collect();
        (
            HeightMap {
                n: m,
                pixel: self.pixel,
                heights,
            },
            (x0, y0),
        )
    }

    /// Whether [`Topography::square_crop`] is the whole grid.
    pub fn is_square_even(&self) -> bool {
        self.nx == self.ny && self.nx.is_multiple_of(2)
    }

    /// Root-mean-square height about the mean (m).
    pub fn rms(&self) -> f64 {
        let count = self.heights.len() as f64;
        let mean = self.heights.iter().sum::<f64>() / count;
        (self.heights.iter().map(|h| (h - mean).powi(2)).sum::<f64>() / count).sqrt()
    }

    /// Root-mean-square slope from forward differences inside the grid (not across its
    /// edges: a measured map is not periodic),
    /// `(⟨(Δh/Δx)²⟩ + ⟨(Δh/Δy)²⟩)^{1/2}`, each mean over its `(nx−1) ny` or `nx (ny−1)`
    /// differences (dimensionless). For a periodic map it differs from
    /// [`HeightMap::rms_slope`] only by the edge pairs left out.
    pub fn rms_slope(&self) -> f64 {
        let (nx, ny) = (self.nx, self.ny);
        let h = |ix: usize, iy: usize| self.heights[iy * nx + ix];
        let (mut sx, mut sy) = (0.0, 0.0);
        for iy in 0..ny {
            for ix in 0..nx {
                if ix + 1 < nx {
                    sx += (h(ix + 1, iy) - h(ix, iy)).powi(2);
                }
                if iy + 1 < ny {
                    sy += (h(ix, iy + 1) - h(ix, iy)).powi(2);
                }
            }
        }
        let mx = sx / ((nx - 1) * ny).max(1) as f64;
        let my = sy / (nx * (ny - 1)).max(1) as f64;
        (mx + my).sqrt() / self.pixel
    }
}
