//! Periodic random rough surfaces synthesised from a power spectrum (docs/model.md §3.5).
//!
//! The cell is the square of side `L = 2π/q0` (q0 = the spectrum's lower cut-off) sampled on
//! `n × n` pixels of size `a = L/n`. A height field periodic on the cell is a Fourier series
//! `h(x) = Σ_q h_q e^{iq·x}` over the lattice `q = (2π/L)(k_x, k_y)`, `k` integer, and with the
//! convention of Persson et al., J. Phys.: Condens. Matter 17 (2005) R1,
//! `C(q) = (2π)⁻² ∫ d²x ⟨h(x)h(0)⟩ e^{−iq·x}` \[m⁴\], a stationary field has
//! `⟨|h_q|²⟩ = (2π/L)² C(|q|)`: each lattice mode stands for one cell of area `(2π/L)²` of the
//! q-plane, and `Σ_q |h_q|² ≈ ∫ d²q C = 2π ∫ q C dq = h_rms²`.
//!
//! [`synthesize`] gives every mode in the band **the deterministic amplitude**
//! `|h_q| = (2π/L) √C(|q|)` and a uniformly random phase (the "random-phase" surface). Random
//! Gaussian amplitudes would add a χ²-scatter of the power of each mode; in the few lowest
//! shells, which carry most of h_rms for a fractal spectrum (the 4 modes at |q| = q0 alone hold
//! about 60 % of h_rms² for H = 0.8), that scatter makes the realised h_rms of one surface
//! differ from the spectrum's by tens of percent. With deterministic amplitudes the realised
//! mean square is exactly [`band_limited_rms`]² for every seed, so realisations differ only in
//! their phases (the arrangement of the asperities), which is what an average over realisations
//! of the numerical reference should sample.
//!
//! **Resolution.** The shortest wavelength `2π/q1` spans `2π/(q1 a) = n q0/q1` pixels, e.g. 8
//! for `q1/q0 = 64` at `n = 512`; modes above the Nyquist wavevector `π/a = n q0/2` cannot be
//! represented and are dropped (the band is cut at `min(q1, π/a)`).
//!
//! **Discrete versus continuous h_rms.** The lattice sum over the band is not the integral
//! `2π ∫_{q0}^{q1} q C dq` near the lower cut-off: the modes at `|q| = q0` sit on the edge of
//! the band but carry the full `C(q0)` for a whole lattice cell, half of which lies below q0. For
//! a pure power law starting at q0 the lattice sum exceeds the integral by the ratio of the
//! Epstein zeta function `Σ'_k |k|^{−2(1+H)}` to `2π/(2H)`: h_rms is about 30 % higher than the
//! spectrum's for H = 0.8 (see the tests). With a roll-off (C flat below some `q_r > q0`), the
//! lowest shells carry little weight and the two agree within a few percent. Comparisons of the
//! numerical reference with the analytic levels therefore use [`band_limited_rms`] or the
//! spectrum re-estimated from the map ([`super::psd`]), not the continuous h_rms.

use super::HeightMap;
use crate::math::fft::{Complex, Fft2, signed_index};
use crate::surface::Spectrum;
use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};
use std::f64::consts::PI;

/// Relative tolerance of the band edges, so that a mode exactly at `q1` (or at the Nyquist
/// wavevector) is inside although `q1 = exp(ln q1)` has been rounded.
const EDGE_TOLERANCE: f64 = 1e-9;

/// A periodic random-phase surface of the spectrum `spectrum` on an `n × n` grid.
///
/// Cell side `L = 2π/q0` with `q0 = spectrum.q0()`, pixel `a = L/n` (both in m). Every Fourier
/// mode whose wavevector lies in the band `q0 ≤ |q| ≤ min(q1, π/a)` gets the amplitude
/// `|h_q| = (2π/L) √C(|q|)` (m) and a uniformly random phase; every other mode, the mean
/// (`q = 0`) included, is zero, so the map's mean is zero to rounding and its rms is
/// [`band_limited_rms`]`(spectrum, n)`. The two self-conjugate modes on the Nyquist lines
/// (`|k_x| = n/2` or `|k_y| = n/2`), which can carry no phase, are left out; inside the disc
/// `|q| ≤ π/a` these are only `(n/2, 0)` and `(0, n/2)`.
///
/// **Reproducibility.** The phase of the mode with signed indices `(kx, ky)` (its
/// representative in the half plane `kx > 0`, or `kx = 0, ky > 0`) is `φ = 2π u` with
/// `u = (next_u64() >> 11) · 2⁻⁵³` ∈ [0, 1) drawn from `ChaCha8Rng::seed_from_u64(seed)` on the
/// stream `kx · 2³² + (ky mod 2³²)` at word 0: it depends on the seed and the wavevector only.
/// So the same seed gives the *same surface* sampled on any grid that resolves its band (the
/// refinement study of the numerical level relies on this), and nested bands give nested
/// surfaces. The phase stream and `cos`/`sin` (libm's portable implementation) are identical
/// on every machine; a seed gives the same map bit for bit on a given build and CPU. Between
/// CPUs the last bits may differ, because rustfft chooses its SIMD kernels at run time and
/// `C(q)` uses the platform's `exp`.
///
/// # Panics
/// If `n` is odd or smaller than 4.
pub fn synthesize(spectrum: &Spectrum, n: usize, seed: u64) -> HeightMap {
    assert!(
        n >= 4 && n.is_multiple_of(2),
        "grid size must be even and ≥ 4"
    );
    let band = Band::new(spectrum, n);
    let mut fft = Fft2::new(n);
    let h = fft.half();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let scale = (n * n) as f64; // Fft2::inverse divides by n²
    let mut half = vec![Complex::new(0.0, 0.0); n * h];
    for ky in 0..n {
        for kx in 0..h {
            let independent = if kx == 0 {
                ky >= 1 && ky < n / 2
            } else {
                kx < n / 2
            };
            if !independent {
                continue;
            }
            let ky_signed = signed_index(ky, n);
            if let Some(amplitude) = band.amplitude(kx as i64, ky_signed) {
                rng.set_stream(((kx as u64) << 32) | u64::from(ky_signed as i32 as u32));
                rng.set_word_pos(0);
                let u = (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
                let phase = 2.0 * PI * u;
                half[ky * h + kx] =
                    Complex::new(libm::cos(phase), libm::sin(phase)) * (scale * amplitude);
            }
        }
    }
    // Hermitian symmetry of the kx = 0 column: ĥ(0, −ky) = conj ĥ(0, ky).
    for ky in 1..n / 2 {
        half[(n - ky) * h] = half[ky * h].conj();
    }
    let mut heights = vec![0.0; n * n];
    fft.inverse(&mut half, &mut heights);
    HeightMap {
        n,
        pixel: band.side / n as f64,
        heights,
    }
}

/// The rms height (m) that [`synthesize`]`(spectrum, n, _)` realises for every seed: the
/// square root of the sum over the modes in its band (all of them, the full q-plane) of
/// `|h_q|² = (2π/L)² C(|q|)`. It approaches the spectrum's `h_rms = (2π ∫ q C dq)^{1/2}` when the
/// lowest shells carry little of the power and `q1 ≤ π/a` (see the module docs).
///
/// # Panics
/// If `n` is odd or smaller than 4.
pub fn band_limited_rms(spectrum: &Spectrum, n: usize) -> f64 {
    assert!(
        n >= 4 && n.is_multiple_of(2),
        "grid size must be even and ≥ 4"
    );
    let band = Band::new(spectrum, n);
    let half = (n / 2) as i64;
    let mut sum = 0.0;
    for ky in -half + 1..half {
        for kx in -half + 1..half {
            if let Some(amplitude) = band.amplitude(kx, ky) {
                sum += amplitude * amplitude;
            }
        }
    }
    sum.sqrt()
}

/// The band of lattice modes that a synthesis on `n × n` pixels fills.
struct Band<'a> {
    spectrum: &'a Spectrum,
    n: usize,
    /// Cell side L = 2π/q0 (m).
    side: f64,
    /// Lattice spacing 2π/L = q0 (1/m).
    dq: f64,
    /// Largest |k|² in the band, `min(q1/q0, n/2)²` with the edge tolerance.
    k2_max: f64,
}

impl<'a> Band<'a> {
    fn new(spectrum: &'a Spectrum, n: usize) -> Self {
        let q0 = spectrum.q0();
        let k_max = (spectrum.q1() / q0).min(n as f64 / 2.0) * (1.0 + EDGE_TOLERANCE);
        Band {
            spectrum,
            n,
            side: 2.0 * PI / q0,
            dq: q0,
            k2_max: k_max * k_max,
        }
    }

    /// `|h_q| = (2π/L) √C(|q|)` (m) of the mode with signed indices `(kx, ky)`, or `None`
    /// outside the band (the mean, beyond `min(q1, π/a)`, or a Nyquist line).
    fn amplitude(&self, kx: i64, ky: i64) -> Option<f64> {
        let nyquist = (self.n / 2) as i64;
        let k2 = (kx * kx + ky * ky) as f64;
        if k2 < 1.0 || k2 > self.k2_max || kx.abs() >= nyquist || ky.abs() >= nyquist {
            return None;
        }
        // |k| ≥ 1 is the lower edge q0 exactly; clamp so that rounding of ln q at the edges
        // cannot fall outside the spectrum's range.
        let ln_q = (self.dq * k2.sqrt()).ln();
        let ln_q = ln_q.clamp(self.spectrum.ln_q0(), self.spectrum.ln_q1());
        Some(self.dq * (0.5 * self.spectrum.ln_c(ln_q)).exp())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    fn self_affine(ratio: f64, rolloff: Option<f64>) -> Spectrum {
        let q0 = 1e4;
        Spectrum::self_affine(1e-6, 0.8, q0, ratio * q0, rolloff.map(|r| r * q0)).unwrap()
    }

    #[test]
    fn realised_rms_is_the_band_limited_rms() {
        let spectrum = self_affine(64.0, None);
        let n = 512;
        let target = band_limited_rms(&spectrum, n);
        for seed in [1, 2, 3] {
            let map = synthesize(&spectrum, n, seed);
            assert_eq!(map.n, n);
            assert!(rel(map.side(), 2.0 * PI / 1e4) < 1e-12);
            assert!(rel(map.rms(), target) < 1e-12, "seed {seed}");
            let mean = map.heights.iter().sum::<f64>() / (n * n) as f64;
            assert!(mean.abs() < 1e-12 * target, "mean {mean}");
        }
    }

    #[test]
    fn discrete_and_continuous_rms() {
        let n = 512;
        // With a roll-off at 8 q0 the lowest shells carry little of the power: the lattice sum
        // is the integral within a few percent (measured: 0.3 %).
        let rolled = self_affine(64.0, Some(8.0));
        let ratio = band_limited_rms(&rolled, n) / rolled.rms_roughness();
        assert!((ratio - 1.0).abs() < 0.03, "ratio {ratio}");
        // A pure power law from q0: the 4 modes at |q| = q0 carry a whole lattice cell of
        // C(q0) each; h_rms² exceeds the integral by Z(3.6)/(2π/1.6) ≈ 6.6/3.93 (Epstein zeta),
        // h_rms by ≈ 30 % (measured: 1.3125).
        let pure = self_affine(64.0, None);
        let ratio = band_limited_rms(&pure, n) / pure.rms_roughness();
        assert!((1.25..1.35).contains(&ratio), "ratio {ratio}");
    }

    #[test]
    fn seeds_reproduce_and_differ() {
        let spectrum = self_affine(16.0, None);
        let a = synthesize(&spectrum, 64, 7);
        let b = synthesize(&spectrum, 64, 7);
        let c = synthesize(&spectrum, 64, 8);
        assert!(
            a.heights
                .iter()
                .zip(&b.heights)
                .all(|(x, y)| x.to_bits() == y.to_bits())
        );
        let differing = a
            .heights
            .iter()
            .zip(&c.heights)
            .filter(|(x, y)| (*x - *y).abs() > 1e-3 * a.rms())
            .count();
        assert!(differing > 64 * 64 / 2, "{differing}");
    }

    #[test]
    fn the_same_seed_gives_the_same_surface_on_finer_grids() {
        // A band resolved on 64² and on 256²: every fourth sample of the fine map is the
        // coarse map (the same Fourier series sampled at the same points).
        let spectrum = self_affine(16.0, Some(2.0));
        let (coarse, fine) = (synthesize(&spectrum, 64, 5), synthesize(&spectrum, 256, 5));
        let rms = coarse.rms();
        for iy in 0..64 {
            for ix in 0..64 {
                let (a, b) = (
                    coarse.heights[iy * 64 + ix],
                    fine.heights[4 * iy * 256 + 4 * ix],
                );
                assert!((a - b).abs() < 1e-12 * rms, "({ix}, {iy}): {a} vs {b}");
            }
        }
    }

    #[test]
    fn nested_bands_share_their_phases() {
        // Same n and seed, a narrower band: the common modes are identical.
        let wide = self_affine(16.0, None);
        let narrow = wide.restricted(1e4, 4e4).unwrap();
        let n = 32;
        let transform = |map: &HeightMap| {
            let mut fft = Fft2::new(n);
            let mut field = map.heights.clone();
            let mut spectrum = vec![Complex::new(0.0, 0.0); n * fft.half()];
            fft.forward(&mut field, &mut spectrum);
            spectrum
        };
        let (a, b) = (
            transform(&synthesize(&wide, n, 3)),
            transform(&synthesize(&narrow, n, 3)),
        );
        // Mode (1, 2): |k| = √5 < 4, in both bands; the amplitudes differ by the
        // normalisation of the narrower spectrum, the phases agree.
        let h = n / 2 + 1;
        let (x, y) = (a[2 * h + 1], b[2 * h + 1]);
        assert!((x.arg() - y.arg()).abs() < 1e-9, "{x} vs {y}");
    }

    #[test]
    fn a_narrow_annulus_puts_its_power_at_its_wavevector() {
        // C only on 20 q0 ≤ |q| ≤ 21 q0: every mode with power must lie there, and each one
        // must carry exactly (2π/L)² C(|q|).
        let q0 = 1e4;
        let spectrum = Spectrum::self_affine(1e-6, 0.8, q0, 64.0 * q0, None)
            .unwrap()
            .restricted(20.0 * q0, 21.0 * q0)
            .unwrap();
        let n = 128;
        let map = synthesize(&spectrum, n, 11);
        // The cell follows the spectrum's q0 (= 20 q0 here): re-express in the lattice of that
        // cell, where the annulus is 1 ≤ |k| ≤ 1.05.
        let dq = spectrum.q0();
        assert!(rel(map.side(), 2.0 * PI / dq) < 1e-12);
        let mut fft = Fft2::new(n);
        let h = fft.half();
        let mut field = map.heights.clone();
        let mut transformed = vec![Complex::new(0.0, 0.0); n * h];
        fft.forward(&mut field, &mut transformed);
        let mut power_in = 0.0;
        let mut power_out = 0.0;
        for ky in 0..n {
            for kx in 0..h {
                let k = ((kx * kx) as f64 + (signed_index(ky, n).pow(2)) as f64).sqrt();
                let amp = transformed[ky * h + kx].norm() / (n * n) as f64;
                let q = k * dq;
                if (dq..=spectrum.q1()).contains(&q) {
                    let expected = dq * spectrum.c(q).sqrt();
                    assert!(rel(amp, expected) < 1e-9, "k = {k}: {amp} vs {expected}");
                    power_in += amp * amp;
                } else {
                    power_out += amp * amp;
                }
            }
        }
        assert!(
            power_in > 0.0 && power_out < 1e-24 * power_in,
            "{power_out}"
        );

        // The same annulus inside a wider cell: q0 of the cell from a spectrum starting at q0,
        // power only at 20 ≤ |k| ≤ 21.
        let wide = Spectrum::tabulated(
            &[q0, 19.9 * q0, 20.0 * q0, 21.0 * q0, 21.1 * q0, 64.0 * q0],
            &[1e-40, 1e-40, 1e-30, 1e-30, 1e-40, 1e-40],
        )
        .unwrap();
        let map = synthesize(&wide, n, 5);
        let mut field = map.heights.clone();
        fft.forward(&mut field, &mut transformed);
        let (mut inside, mut total) = (0.0, 0.0);
        for ky in 0..n {
            for kx in 0..h {
                let k = ((kx * kx) as f64 + (signed_index(ky, n).pow(2)) as f64).sqrt();
                let p = transformed[ky * h + kx].norm_sqr();
                total += p;
                if (20.0..=21.0).contains(&k) {
                    inside += p;
                }
            }
        }
        assert!(inside / total > 0.999, "{}", inside / total);
    }
}
