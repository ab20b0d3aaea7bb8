//! Two-dimensional real FFT on a square periodic grid (rustfft + realfft).
//!
//! Layout: a real field is `n × n`, row-major (`field[iy * n + ix]`). Its spectrum is the
//! half-plane `n × (n/2 + 1)`, row-major (`spectrum[ky * h + kx]`, `h = n/2 + 1`), with
//! `kx = 0..=n/2` and `ky = 0..n` (signed frequency [`signed_index`]). The forward transform is
//! unnormalised, ĥ(k) = Σ_x h(x) e^{−2πi k·x/n}; the inverse divides by n², so
//! `inverse(forward(h)) = h`.
//!
//! [`Convolver`] applies a Fourier multiplier (a convolution) with the same transforms, without
//! full transposes and on several threads, bit-identical for any thread count.

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
            #[expect(
                clippy::expect_used,
                reason = "row lengths are those of the plan (asserted above), the only error \
                          realfft's forward transform reports"
            )]
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
            #[expect(
                clippy::expect_used,
                reason = "row lengths are those of the plan (asserted above) and the DC and \
                          Nyquist bins were just made real: realfft's only errors"
            )]
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

/// Columns per tile of the half spectrum in [`Convolver`]: the column pass transforms one tile
/// (`m × 8` complex values, contiguous) at a time.
const TILE: usize = 8;

/// `dst.copy_from_slice(src)` for at most [`TILE`] values, inlined for a full tile (a library
/// `memmove` call per 128 bytes costs more than the copy).
#[inline(always)]
fn copy_short(dst: &mut [Complex<f64>], src: &[Complex<f64>]) {
    match (
        <&mut [Complex<f64>; TILE]>::try_from(&mut *dst),
        <&[Complex<f64>; TILE]>::try_from(src),
    ) {
        (Ok(d), Ok(s)) => *d = *s,
        _ => {
            for (d, s) in dst.iter_mut().zip(src) {
                *d = *s;
            }
        }
    }
}

/// Per-thread buffers of [`Convolver`].
struct Worker {
    row: Vec<f64>,
    half: Vec<Complex<f64>>,
    real_scratch: Vec<Complex<f64>>,
    block: Vec<Complex<f64>>,
    column_scratch: Vec<Complex<f64>>,
}

/// `output = F⁻¹[M · F[input]]` for a real multiplier `M` on the half spectrum of an `m × m`
/// grid, the input being the top-left `n × n` block (zero elsewhere) and the output read from
/// the same block; the transforms are those of [`Fft2`] (inverse normalised by `1/m²`). With
/// `m = n` this is the periodic (circular) convolution with the kernel whose spectrum is `M`; with
/// `m = 2n` the input is zero-padded and the result is the linear (non-periodic) convolution (the
/// DC-FFT method, Liu, Wang & Liu, Wear 243 (2000) 101).
///
/// Real FFTs along the rows, then the columns tile by tile (transpose in cache, forward
/// transform, multiply, inverse transform, transpose back), then inverse real FFTs along the
/// rows. The half spectrum is stored in tiles of `TILE` = 8 columns, each tile contiguous
/// (`tile[ky * width + j]`), so the column pass streams memory; the tiles are dealt out in
/// `threads` contiguous bands so that the threads of the column pass own disjoint memory, and
/// the rows likewise in the row passes. Every 1-D transform is the same whatever the thread
/// count, so the result is bit-identical for any `threads`.
pub struct Convolver {
    n: usize,
    m: usize,
    threads: usize,
    forward_rows: Arc<dyn RealToComplex<f64>>,
    inverse_rows: Arc<dyn ComplexToReal<f64>>,
    forward_columns: Arc<dyn Fft<f64>>,
    inverse_columns: Arc<dyn Fft<f64>>,
    /// First tile of each band, and the number of tiles at the end.
    band_tiles: Vec<usize>,
    /// Bands of tiles of the half spectrum.
    bands: Vec<Vec<Complex<f64>>>,
    workers: Vec<Worker>,
}

impl Convolver {
    /// Plans and buffers for an `n × n` field on an `m × m` FFT grid (`m ≥ n`, even), on
    /// `threads` threads (at least 1, at most the number of tiles; the calling thread is one of
    /// them).
    pub fn new(n: usize, m: usize, threads: usize) -> Self {
        let half = m / 2 + 1;
        let tiles = half.div_ceil(TILE);
        let threads = threads.clamp(1, tiles);
        let mut real = RealFftPlanner::<f64>::new();
        let mut complex = FftPlanner::<f64>::new();
        let forward_rows = real.plan_fft_forward(m);
        let inverse_rows = real.plan_fft_inverse(m);
        let forward_columns = complex.plan_fft_forward(m);
        let inverse_columns = complex.plan_fft_inverse(m);
        let band_tiles: Vec<usize> = (0..=threads).map(|k| k * tiles / threads).collect();
        let bands = band_tiles
            .windows(2)
            .map(|w| {
                let columns = (w[1] * TILE).min(half) - w[0] * TILE;
                vec![Complex::new(0.0, 0.0); columns * m]
            })
            .collect();
        let real_scratch = forward_rows
            .get_scratch_len()
            .max(inverse_rows.get_scratch_len());
        let column_scratch = forward_columns
            .get_inplace_scratch_len()
            .max(inverse_columns.get_inplace_scratch_len());
        let workers = (0..threads)
            .map(|_| Worker {
                row: vec![0.0; m],
                half: vec![Complex::new(0.0, 0.0); half],
                real_scratch: vec![Complex::new(0.0, 0.0); real_scratch],
                block: vec![Complex::new(0.0, 0.0); TILE * m],
                column_scratch: vec![Complex::new(0.0, 0.0); column_scratch],
            })
            .collect();
        Self {
            n,
            m,
            threads,
            forward_rows,
            inverse_rows,
            forward_columns,
            inverse_columns,
            band_tiles,
            bands,
            workers,
        }
    }

    /// A multiplier in the half-spectrum layout of [`Fft2`] (`[ky * (m/2+1) + kx]`) rearranged
    /// column by column (`[kx * m + ky]`), as [`Convolver::apply`] takes it.
    pub fn columns_first(m: usize, multiplier: &[f64]) -> Vec<f64> {
        let half = m / 2 + 1;
        let mut out = vec![0.0; m * half];
        for ky in 0..m {
            for kx in 0..half {
                out[kx * m + ky] = multiplier[ky * half + kx];
            }
        }
        out
    }

    /// Columns `[start, end)` of tile `tile`, clipped to the half spectrum.
    fn tile_columns(&self, tile: usize) -> (usize, usize) {
        let half = self.m / 2 + 1;
        (tile * TILE, ((tile + 1) * TILE).min(half))
    }

    /// `output = F⁻¹[M F[input]]`, `multiplier` as from [`Convolver::columns_first`].
    pub fn apply(&mut self, multiplier: &[f64], input: &[f64], output: &mut [f64]) {
        let (n, m, threads) = (self.n, self.m, self.threads);
        let half = m / 2 + 1;
        let rows: Vec<usize> = (0..=threads).map(|k| k * n / threads).collect();
        // Tile extents (first column, width) in every band, and each band's offset in a row.
        let layout: Vec<Vec<(usize, usize)>> = self
            .band_tiles
            .windows(2)
            .map(|w| {
                (w[0]..w[1])
                    .map(|tile| {
                        let (a, b) = self.tile_columns(tile);
                        (a, b - a)
                    })
                    .collect()
            })
            .collect();
        let layout = &layout;

        // Row pass, forward: thread k transforms data rows [rows[k], rows[k+1]) into every
        // tile; rows n..m of the padded grid are zero.
        {
            let plan = &self.forward_rows;
            let rows = &rows;
            let bands: Vec<&mut Vec<Complex<f64>>> = self.bands.iter_mut().collect();
            // Each thread needs all bands; split every tile's rows instead of the bands.
            let mut per_thread: Vec<Vec<Vec<&mut [Complex<f64>]>>> =
                (0..threads).map(|_| Vec::new()).collect();
            for (band, tiles) in bands.into_iter().zip(layout) {
                let mut rest: &mut [Complex<f64>] = band;
                let mut tile_slices: Vec<Vec<&mut [Complex<f64>]>> =
                    (0..threads).map(|_| Vec::new()).collect();
                for &(_, w) in tiles {
                    let (tile, tail) = rest.split_at_mut(m * w);
                    rest = tail;
                    let (data, padding) = tile.split_at_mut(n * w);
                    padding.fill(Complex::new(0.0, 0.0));
                    let mut data_rest = data;
                    for (k, slot) in tile_slices.iter_mut().enumerate() {
                        let (chunk, tail) = data_rest.split_at_mut((rows[k + 1] - rows[k]) * w);
                        slot.push(chunk);
                        data_rest = tail;
                    }
                }
                for (k, slices) in tile_slices.into_iter().enumerate() {
                    per_thread[k].push(slices);
                }
            }
            let job = |worker: &mut Worker, mut slices: Vec<Vec<&mut [Complex<f64>]>>, k: usize| {
                for r in 0..rows[k + 1] - rows[k] {
                    let iy = rows[k] + r;
                    worker.row[..n].copy_from_slice(&input[iy * n..(iy + 1) * n]);
                    worker.row[n..].fill(0.0);
                    let result = plan.process_with_scratch(
                        &mut worker.row,
                        &mut worker.half,
                        &mut worker.real_scratch,
                    );
                    debug_assert!(result.is_ok());
                    for (band, tiles) in slices.iter_mut().zip(layout) {
                        for (tile, &(start, w)) in band.iter_mut().zip(tiles) {
                            copy_short(
                                &mut tile[r * w..(r + 1) * w],
                                &worker.half[start..start + w],
                            );
                        }
                    }
                }
            };
            run_parallel(&mut self.workers, per_thread, &job);
        }
        // Column pass: thread k owns band k.
        {
            let plans = (&self.forward_columns, &self.inverse_columns);
            let job = |worker: &mut Worker, band: &mut Vec<Complex<f64>>, k: usize| {
                let mut offset = 0;
                for &(start, w) in &layout[k] {
                    let tile = &mut band[offset..offset + m * w];
                    offset += m * w;
                    let block = &mut worker.block[..m * w];
                    for ky in 0..m {
                        for j in 0..w {
                            block[j * m + ky] = tile[ky * w + j];
                        }
                    }
                    plans
                        .0
                        .process_with_scratch(block, &mut worker.column_scratch);
                    for (j, column) in block.chunks_exact_mut(m).enumerate() {
                        let factors = &multiplier[(start + j) * m..(start + j + 1) * m];
                        for (c, f) in column.iter_mut().zip(factors) {
                            *c *= *f;
                        }
                    }
                    plans
                        .1
                        .process_with_scratch(block, &mut worker.column_scratch);
                    for ky in 0..m {
                        for j in 0..w {
                            tile[ky * w + j] = block[j * m + ky];
                        }
                    }
                }
            };
            let bands: Vec<&mut Vec<Complex<f64>>> = self.bands.iter_mut().collect();
            run_parallel(&mut self.workers, bands, &job);
        }
        // Row pass, inverse: thread k rebuilds its output rows from every tile.
        {
            let scale = 1.0 / (m * m) as f64;
            let bands = &self.bands;
            let plan = &self.inverse_rows;
            let mut outputs: Vec<&mut [f64]> = Vec::new();
            let mut rest = output;
            for k in 0..threads {
                let (chunk, tail) = rest.split_at_mut((rows[k + 1] - rows[k]) * n);
                outputs.push(chunk);
                rest = tail;
            }
            let job = |worker: &mut Worker, out: &mut [f64], k: usize| {
                for (r, out_row) in out.chunks_exact_mut(n).enumerate() {
                    let iy = rows[k] + r;
                    for (band, tiles) in bands.iter().zip(layout) {
                        let mut offset = 0;
                        for &(start, w) in tiles {
                            let base = offset + iy * w;
                            copy_short(&mut worker.half[start..start + w], &band[base..base + w]);
                            offset += m * w;
                        }
                    }
                    // Exactly real DC and Nyquist bins (rounding leaves ~1e-17).
                    worker.half[0].im = 0.0;
                    worker.half[half - 1].im = 0.0;
                    let result = plan.process_with_scratch(
                        &mut worker.half,
                        &mut worker.row,
                        &mut worker.real_scratch,
                    );
                    debug_assert!(result.is_ok());
                    for (o, v) in out_row.iter_mut().zip(&worker.row[..n]) {
                        *o = v * scale;
                    }
                }
            };
            run_parallel(&mut self.workers, outputs, &job);
        }
    }
}

/// Runs `job(worker_k, item_k, k)` for every thread `k` on scoped threads (the first on the
/// calling thread).
fn run_parallel<I: Send, F>(workers: &mut [Worker], items: Vec<I>, job: &F)
where
    F: Fn(&mut Worker, I, usize) + Sync,
{
    let mut pairs = workers.iter_mut().zip(items).enumerate();
    let Some((_, (first_worker, first_item))) = pairs.next() else {
        return;
    };
    std::thread::scope(|scope| {
        for (k, (worker, item)) in pairs {
            scope.spawn(move || job(worker, item, k));
        }
        job(first_worker, first_item, 0);
    });
}

/// Plans for 1-D forward real transforms of any length (line traces), cached by length.
///
/// `forward` returns `Ẑ(k) = Σ_j z_j e^{−2πi jk/N}` for `k = 0..=N/2` (unnormalised, as
/// [`Fft2::forward`]).
pub struct Fft1 {
    planner: RealFftPlanner<f64>,
}

impl Default for Fft1 {
    fn default() -> Self {
        Self::new()
    }
}

impl Fft1 {
    /// An empty planner.
    pub fn new() -> Self {
        Fft1 {
            planner: RealFftPlanner::<f64>::new(),
        }
    }

    /// Forward transform of `signal` (`N ≥ 1` points; used as scratch: its contents are
    /// destroyed): the `N/2 + 1` coefficients `k = 0..=N/2`.
    pub fn forward(&mut self, signal: &mut [f64]) -> Vec<Complex<f64>> {
        let plan = self.planner.plan_fft_forward(signal.len());
        let mut out = plan.make_output_vec();
        #[expect(
            clippy::expect_used,
            reason = "the output comes from the plan itself and the input has the plan's length: \
                      realfft's only errors"
        )]
        plan.process(signal, &mut out)
            .expect("lengths match the plan");
        out
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

    #[test]
    fn convolver_matches_plain_fft_and_ignores_thread_count() {
        for (n, m) in [(16usize, 16usize), (16, 32), (24, 24)] {
            let half = m / 2 + 1;
            let multiplier: Vec<f64> = (0..m * half)
                .map(|i| 1.0 + ((i * 7919) % 13) as f64)
                .collect();
            let input: Vec<f64> = (0..n * n).map(|i| ((i * 31 % 17) as f64).sin()).collect();
            // Reference with Fft2 on the zero-padded field.
            let mut field = vec![0.0; m * m];
            for iy in 0..n {
                field[iy * m..iy * m + n].copy_from_slice(&input[iy * n..(iy + 1) * n]);
            }
            let mut fft = Fft2::new(m);
            let mut spectrum = vec![Complex::new(0.0, 0.0); m * half];
            fft.forward(&mut field, &mut spectrum);
            for (c, k) in spectrum.iter_mut().zip(&multiplier) {
                *c *= *k;
            }
            fft.inverse(&mut spectrum, &mut field);
            let mut outputs = Vec::new();
            for threads in [1, 2, 3] {
                let mut out = vec![0.0; n * n];
                Convolver::new(n, m, threads).apply(
                    &Convolver::columns_first(m, &multiplier),
                    &input,
                    &mut out,
                );
                for iy in 0..n {
                    for ix in 0..n {
                        assert!((out[iy * n + ix] - field[iy * m + ix]).abs() < 1e-12);
                    }
                }
                outputs.push(out);
            }
            assert!(outputs.windows(2).all(|w| w[0] == w[1]));
        }
    }
}
