//! Line traces (stylus or optical profiles, `x, z`) → the isotropic 2-D roughness spectrum C(q)
//! of the contact theory, and the ISO profile parameters Ra, Rq, Rz of the traces.
//!
//! Physics only: heights and spacings in metres, no files (the CSV reader is
//! `scenario::profile`, at the input boundary).
//!
//! # Conventions
//!
//! * 2-D (PY08 §2, as [`crate::surface`]): `C(q) = (2π)⁻² ∫ d²x ⟨h(x)h(0)⟩ e^{−iq·x}` \[m⁴\],
//!   `h_rms² = 2π ∫_0^∞ q C(q) dq`, mean-square gradient `⟨|∇h|²⟩ = 2π ∫ q³ C dq`.
//! * 1-D (this module): `C1D(q) = (2π)⁻¹ ∫ dx ⟨h(x)h(0)⟩ e^{−iqx}` \[m³\], the two-sided density
//!   reported for `q > 0`, so that `h_rms² = ∫_{−∞}^{∞} C1D dq = 2 ∫_0^∞ C1D(q) dq` (Parseval;
//!   tested) and the mean-square slope along the line is `⟨h'²⟩ = 2 ∫_0^∞ q² C1D dq`.
//!
//! # Per trace (module function [`periodogram`])
//! 1. remove the least-squares line (form removal of a flat specimen; curved form must be
//!    removed before export, as instrument software does);
//! 2. multiply by the periodic Hann window `w_j = sin²(πj/N)` (a measured trace is not
//!    periodic: its end step would leak power ∝ q⁻² over the whole spectrum);
//! 3. FFT `Z_k = Σ_j w_j z_j e^{−2πi jk/N}` ([`crate::math::fft::Fft1`]) and
//!    `C1D(q_k) = |Z_k|² Δx / (2π N ⟨w²⟩)` at `q_k = 2πk/L`, `L = NΔx`, `k = 1..=N/2`, with
//!    `⟨w²⟩ = N⁻¹ Σ w_j² = 3/8` (Hann) correcting the expected power for the window. Derivation:
//!    a field periodic on L has `h(x) = Σ h_q e^{iqx}` with `⟨|h_q|²⟩ = (2π/L) C1D(q)` and
//!    `h_q = Z_k/N`; the window multiplies the expected periodogram of a stationary signal by
//!    `⟨w²⟩` (as in the numerical reference's `psd` module).
//!
//! # Averaging (traces of any lengths and spacings)
//! Each trace contributes only its *trusted* ordinates, `q_lo,i ≤ q_k ≤ q_hi,i` (below). They
//! are pooled in log-spaced bins of a common grid, edges `10^{b/B}` 1/m (B =
//! [`ProfileOptions::bins_per_decade`], default 10), so traces of different lengths and
//! spacings share bins. A bin gives the mean of its ordinates at the geometric mean `q̄` of their
//! q. For a local power law `C1D ∝ q^s` that mean exceeds `C1D(q̄)` by `⟨(q/q̄)^s⟩ ≈
//! exp(s² var(ln q)/2)` (≈ 1.5 % for s = −2.6 at 10 bins per decade); each bin is divided by that
//! factor, with s from its neighbours.
//!
//! # 1-D → 2-D (isotropic surface)
//! The correlation along a line is the 2-D one on the axis, so with the conventions above
//! `C1D(q) = ∫_{−∞}^{∞} C(√(q² + q_y²)) dq_y = 2 ∫_q^∞ C(r) r dr / √(r² − q²)`, an Abel
//! transform, inverted by `C(q) = −(1/π) ∫_q^∞ C1D'(q′) dq′ / √(q′² − q²)` (the standard Abel
//! pair; for isotropic roughness: Jacobs, Junge & Pastewka, *Quantitative characterization of
//! surface topography using spectral analysis*, Surf. Topogr.: Metrol. Prop. 5 (2017) 013001,
//! §2 — recalled; their 1-D PSD carries a different constant (their `C1D = π ×` ours, with
//! `h_rms² = π⁻¹ ∫_0^∞ C1D dq` as quoted by the SurfaceTopography documentation), so the
//! constants here were derived for the conventions above and are tested).
//! For a power law `C = A q^{−2(1+H)}` the transform is closed:
//! `C1D(q) = q C(q) √π Γ(H+½)/Γ(1+H)` (substitute r = q t, then the Beta integral
//! `∫_1^∞ t^{−1−2H} (t²−1)^{−1/2} dt = ½ B(H+½, ½)`), i.e.
//! `C(q) = C1D(q)/q · Γ(1+H)/(√π Γ(H+½))` ([`power_law_factor`]; 0.5855 at H = 0.8).
//! Numerically ([`abel_inverse`]): the binned C1D is interpolated as a piecewise power law
//! (linear in log–log) between bin points and continued above the last bin by the power law of
//! the last 5 bins (slope capped at −1 so that the integral converges); substituting
//! `q′ = q cosh u` removes the singularity, `C(q) = −(1/π) ∫_0^∞ C1D'(q cosh u) du`, integrated
//! by 16-point Gauss–Legendre between the knots: exact to ~1e-10 for a piecewise power law
//! (tested against the closed form). The kernel is local (for C1D ∝ q^{−2.6}, 90 % of the
//! integral comes from `q′ < 1.6 q`), so errors of C1D stay local.
//!
//! # Trusted band
//! * `q_lo = n_lo · 2π/L` ([`ProfileOptions::low_periods`], default 8): the lowest ordinates
//!   are biased by the line removal (k ≤ 3) and by the window (which mixes neighbouring
//!   ordinates, relative bias ∝ s²/k²), and are the noisiest (one ordinate per trace per bin);
//! * `q_hi = f · π/Δx` ([`ProfileOptions::nyquist_fraction`], default 1/4): a trace without an
//!   anti-aliasing filter folds the power above the Nyquist wavevector π/Δx back into the band;
//!   for a power law continuing beyond Nyquist with C1D ∝ q^{−2.6} (H = 0.8), the folded power at
//!   π/(4Δx) is ≈ 1.2 % (images at 7/4, 9/4, … of the Nyquist wavevector), ≈ 8 % at π/(2Δx);
//! * with a stylus tip radius R ([`ProfileOptions::tip_radius`]): `q_hi ≤ 1/√(R Rq)`, Rq the
//!   trace's rms. A stated engineering choice, not a standard: a sinusoid of amplitude a and
//!   wavevector q is followed by a tip of radius R as long as its curvature `a q² ≤ 1/R`; the
//!   rule takes a = Rq (the trace's whole roughness), which is conservative.
//!
//! The reported band is from the first to the last non-empty bin point; the 2-D spectrum is
//! tabulated at the bin points inside it ([`Spectrum::tabulated`]; plus q_r when the model is
//! reported, so that the integrals follow its corner).
//!
//! # Parametric model (forward transform) and which spectrum is reported
//! Below a roll-off C1D is nearly flat and the inversion, a derivative, amplifies the 1-D
//! scatter about tenfold (see "Measured accuracy"). The forward transform is well conditioned,
//! so a model is also fitted *through* it: the 2-D spectrum "flat below q_r, power law above",
//! `C(q) = A min(q, q_r)^{−2(1+H)}` ([`RollOffModel`]), whose 1-D transform is closed up to a
//! finite integral ([`rolloff_one_d`]: `q ≥ q_r` the power-law form above; `q < q_r`
//! `2 A q_r^{−2(1+H)} √(q_r² − q²) + 2 A q^{−1−2H} (G − ∫_0^{u_r} cosh^{−1−2H} u du)`,
//! `u_r = acosh(q_r/q)`, `G = ½ B(H+½, ½)`; tested against [`one_d_from_two_d`]). It is
//! fitted by weighted least squares in ln C1D over the bins (weights: each bin's count of
//! ordinates; ln A eliminated exactly; H ∈ [0.02, 1.2] and ln q_r continuous between the band's
//! first point and the point with 4 points above, by a 25 × 25 grid refined six times), and
//! also with q_r at the first point (a pure power law, 2 parameters); the roll-off is kept when
//! it lowers Akaike's criterion `m ln(SSE/m) + 2k` (weighted SSE, k = 3 or 2).
//!
//! **The model is reported** (`spectrum` = the model tabulated at the bin points plus q_r,
//! `hurst` and `q0` the model's, [`TraceSpectrum::from_model`]) when it describes the 1-D data
//! as well as the non-parametric curve does: its criterion `m ln(SSE/m) + 2k` is not above that
//! of the smoothed ln C1D (local quadratic over 5 bins, the curve the inversion uses) with
//! k = the smoother's effective number of parameters (trace of its hat matrix, ≈ 0.6 m). A
//! spectrum that is not "flat + power law" (two slopes, a bump) leaves a systematic misfit and
//! **the non-parametric inversion is reported** instead, with the fit below; the inversion is
//! always available as [`TraceSpectrum::inversion`]. H's 95 % interval from the model is
//! `H ± t_{0.975,m−k} σ_H`, σ_H² the H entry of `σ² (JᵀWJ)⁻¹`, `σ² = SSE/(m − k)`, J the
//! numerical Jacobian of ln C1D in (ln A, H, ln q_r): bins are correlated (window, the surface's
//! realisation shared by traces), so it is indicative.
//!
//! # Fit of the inversion (when the model is not reported)
//! Least squares in log–log over the 2-D points: a single power law, and a power law with a
//! flat roll-off below a bin point q_r (C constant for q ≤ q_r, at least 2 points below and 4
//! above); the roll-off is kept when it lowers Akaike's criterion `m ln(SSE/m) + 2k` (k = 2 or
//! 3). H follows from the slope `s = −2(1+H)` of the least-squares line over the points from q_r
//! (or all points), with a 95 % interval `H ± t_{0.975,m−2} σ_s/2` (Student t). Neighbouring
//! points are correlated (binning, window, the inversion), so the interval is indicative.
//!
//! # Profile parameters ([`profile_parameters`])
//! Ra (mean |z|), Rq (rms) and Rz (mean over the sampling lengths of the largest peak-to-valley
//! height `max z − min z` within each; ISO 4287 / ISO 21920-2 "Rz", 5 sampling lengths by
//! default) of the roughness profile, i.e. of z minus a mean line:
//! * with a cut-off λc ([`ProfileOptions::cutoff`]): the Gaussian filter of ISO 16610-21,
//!   weighting `s(x) = (α λc)⁻¹ exp(−π (x/(α λc))²)`, `α = √(ln 2/π)`, truncated at `±λc/2` and
//!   renormalised to unit sum; the evaluation length is the trace minus λc/2 at each end (run-in
//!   and run-out, ISO 4288), the sampling length is λc, and Rz averages over
//!   `min(5, ⌊evaluation length/λc⌋)` sampling lengths (`None` when not even one fits). A trace
//!   shorter than 2λc falls back to the least-squares line;
//! * without a cut-off: the least-squares line over the whole trace, and the trace divided into
//!   5 equal sampling lengths for Rz.
//!
//! # Measured accuracy (tests/model/profile.rs)
//! Eight Gaussian random isotropic 2048² surfaces ([`synthesize_gaussian`], pixel 0.5 µm,
//! H = 0.8, flat roll-off below q_r = 32 · 2π/L), 32 rows each cut into two non-periodic
//! halves of 1024 points (512 traces), default options (band 9.8e4–1.41e6 1/m, 1.16 decades,
//! 13 bins). The model is reported:
//! * C(q) within 1.7 % of the known spectrum over the whole band (1.1 % below q_r, 1.4–1.7 %
//!   above: the fitted H, 0.799, tilts the law slightly). The non-parametric inversion of the
//!   same data is within 1.5 % only for q ≥ 2 q_r: 4 % at 1.2–1.8 q_r, 1–19 % across the
//!   roll-off and 74 % at the band's lowest point (q = q_r/2), because where C1D is nearly flat
//!   the inversion amplifies the 1-D noise (3–10 % per bin there, dominated by the realisation of
//!   the surface, not the number of traces) roughly tenfold. The noise-free inversion of the
//!   exact C1D of this spectrum is within 0.5 % except at the kink itself (−5.7 % at the bin
//!   next to q_r, where the tabulation cannot follow the corner);
//! * H = 0.799 (95 % interval 0.790–0.808); roll-off at 1.960e5 1/m (true 1.963e5);
//! * band h_rms −0.7 %, band rms gradient −0.8 %;
//! * 2.3–3.5 s in release on 2 cores (synthesis of the surfaces included).
//!
//! A spectrum with two power laws (H = 0.8 below 4e5 1/m, 0.3 above; 128 traces): the model's
//! misfit reaches 53 % and its criterion loses, so the inversion is reported (test
//! `a_bent_spectrum_is_reported_by_the_inversion`).
//!
//! The 1-D ↔ 2-D pair matches the power-law closed form to 1e-8 (inverse) and 1e-6 (forward)
//! for H = 0.3…0.95.

use crate::math::fft::{Complex, Fft1, Fft2, signed_index};
use crate::math::quadrature::gauss_legendre;
use crate::math::rng::SplitMix64;
use crate::surface::{Spectrum, SpectrumError};
use statrs::distribution::{ContinuousCDF, StudentsT};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::fmt;

/// Smallest number of points of a trace the analysis accepts: with the default band
/// `[8 · 2π/L, π/(4Δx)]` a trace of N points spans a factor N/64, so fewer points leave less
/// than ~0.6 decade (6 bins).
pub const MIN_POINTS: usize = 256;

/// One uniformly sampled line trace.
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    /// Sampling interval Δx \[m\], > 0.
    pub spacing: f64,
    /// Heights z_j \[m\] at x_j = j Δx.
    pub heights: Vec<f64>,
}

impl Trace {
    /// Length `L = N Δx` \[m\] (the period of the discrete Fourier transform).
    pub fn length(&self) -> f64 {
        self.heights.len() as f64 * self.spacing
    }

    fn check(&self, index: usize) -> Result<(), ProfileError> {
        if !(self.spacing.is_finite() && self.spacing > 0.0) {
            return Err(ProfileError(format!(
                "trace {}: the spacing must be positive and finite, got {}",
                index + 1,
                self.spacing
            )));
        }
        if self.heights.len() < MIN_POINTS {
            return Err(ProfileError(format!(
                "trace {}: {} points; at least {MIN_POINTS} are needed",
                index + 1,
                self.heights.len()
            )));
        }
        if let Some(j) = self.heights.iter().position(|z| !z.is_finite()) {
            return Err(ProfileError(format!(
                "trace {}: height {} is not finite",
                index + 1,
                j + 1
            )));
        }
        Ok(())
    }
}

/// Why traces could not be analysed.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileError(pub String);

impl fmt::Display for ProfileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ProfileError {}

impl From<SpectrumError> for ProfileError {
    fn from(e: SpectrumError) -> Self {
        ProfileError(e.to_string())
    }
}

/// The taper of a trace before its FFT.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TraceWindow {
    /// Periodic Hann `w_j = sin²(πj/N)`, `⟨w²⟩ = 3/8`: for measured (non-periodic) traces.
    #[default]
    Hann,
    /// No window: exact for periodic traces only.
    Rectangular,
}

/// Settings of [`analyse`] (module docs, "Trusted band" and "Profile parameters").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileOptions {
    /// Log-spaced bins per decade of q (default 10).
    pub bins_per_decade: usize,
    /// `q_lo = low_periods · 2π/L` (default 8).
    pub low_periods: f64,
    /// `q_hi = nyquist_fraction · π/Δx` (default 0.25).
    pub nyquist_fraction: f64,
    /// Stylus tip radius R \[m\]: `q_hi ≤ 1/√(R Rq)` (default none).
    pub tip_radius: Option<f64>,
    /// Window (default Hann).
    pub window: TraceWindow,
    /// Gaussian-filter cut-off λc \[m\] for Ra, Rq, Rz (default none: least-squares line).
    pub cutoff: Option<f64>,
}

impl Default for ProfileOptions {
    fn default() -> Self {
        ProfileOptions {
            bins_per_decade: 10,
            low_periods: 8.0,
            nyquist_fraction: 0.25,
            tip_radius: None,
            window: TraceWindow::Hann,
            cutoff: None,
        }
    }
}

/// The mean line removed before Ra, Rq, Rz.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MeanLine {
    /// Least-squares straight line over the whole trace.
    LeastSquaresLine,
    /// ISO 16610-21 Gaussian filter of cut-off λc \[m\] (module docs).
    Gaussian {
        /// λc \[m\].
        cutoff: f64,
    },
}

/// ISO 4287 / ISO 21920-2 profile parameters of one trace (module docs), all in m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileParameters {
    /// Arithmetic mean deviation `Ra = ⟨|z − m|⟩` over the evaluation length.
    pub ra: f64,
    /// Root-mean-square deviation `Rq = ⟨(z − m)²⟩^{1/2}`.
    pub rq: f64,
    /// Mean over the sampling lengths of `max − min` in each; `None` if none fits.
    pub rz: Option<f64>,
    /// Number of sampling lengths behind `rz`.
    pub sampling_lengths: usize,
    /// Evaluation length \[m\].
    pub evaluation_length: f64,
    /// The mean line m that was removed.
    pub mean_line: MeanLine,
}

/// The binned, averaged 1-D spectrum of a set of traces.
#[derive(Debug, Clone, PartialEq)]
pub struct Psd1d {
    /// Geometric-mean q of each non-empty bin \[1/m\], increasing.
    pub q: Vec<f64>,
    /// C1D at `q` \[m³\] (mean of the bin, corrected for the bin's curvature).
    pub c: Vec<f64>,
    /// Number of periodogram ordinates (over all traces) in each bin.
    pub count: Vec<usize>,
}

/// The result of [`analyse`].
#[derive(Debug, Clone, PartialEq)]
pub struct TraceSpectrum {
    /// The isotropic 2-D spectrum C(q) \[m⁴\] (PY08 convention), tabulated at the bin points of
    /// the band.
    pub spectrum: Spectrum,
    /// The trusted band `(q_lo, q_hi)` \[1/m\]: first and last bin point.
    pub band: (f64, f64),
    /// Hurst exponent of the fit and its 95 % interval.
    pub hurst: (f64, (f64, f64)),
    /// Roll-off wavevector \[1/m\] when the fit found a flat segment below it.
    pub q0: Option<f64>,
    /// rms roughness of the band from the 2-D spectrum, `(2π ∫ q C dq)^{1/2}` \[m\].
    pub h_rms: f64,
    /// rms gradient of the band from the 2-D spectrum, `(2π ∫ q³ C dq)^{1/2}`.
    pub rms_slope: f64,
    /// rms of the traces (all wavelengths, after the least-squares line), pooled \[m\]: equals the
    /// 2-D h_rms of the whole surface for an isotropic surface, not the band's.
    pub trace_rms: f64,
    /// `√2 ×` the pooled rms of the finite-difference slope `(z_{j+1} − z_j)/Δx` of the traces:
    /// the 2-D rms gradient of an isotropic surface (`⟨|∇h|²⟩ = 2 ⟨h_x²⟩`), all wavelengths the
    /// sampling resolves.
    pub trace_rms_slope: f64,
    /// Number of traces.
    pub traces: usize,
    /// The averaged 1-D spectrum (band only).
    pub psd_1d: Psd1d,
    /// 2-D points of the band whose Abel inversion came out ≤ 0 (noise: C1D rising locally) and
    /// were replaced by the local power-law closed form.
    pub replaced_points: usize,
    /// The non-parametric Abel inversion of the smoothed 1-D spectrum at `psd_1d.q` \[m⁴\]
    /// (reported as `spectrum` unless `from_model`; module docs, "Which is reported").
    pub inversion: Vec<f64>,
    /// The parametric roll-off model fitted to the 1-D spectrum (a pure power law, q_r at the
    /// band's first point, when no roll-off is found).
    pub model: RollOffModel,
    /// Whether `spectrum`, `hurst` and `q0` are the model's (it fits the 1-D data as well as the
    /// non-parametric curve by Akaike's criterion) rather than the inversion's.
    pub from_model: bool,
    /// Ra, Rq, Rz of each trace.
    pub parameters: Vec<ProfileParameters>,
}

/// Least-squares line removed: `z_j − (a + b j)`.
pub fn detrend(heights: &[f64]) -> Vec<f64> {
    let n = heights.len();
    if n == 0 {
        return Vec::new();
    }
    let nf = n as f64;
    let centre = (nf - 1.0) / 2.0;
    let mean = heights.iter().sum::<f64>() / nf;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (j, z) in heights.iter().enumerate() {
        let x = j as f64 - centre;
        sxy += x * (z - mean);
        sxx += x * x;
    }
    let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    heights
        .iter()
        .enumerate()
        .map(|(j, z)| z - mean - slope * (j as f64 - centre))
        .collect()
}

/// The one-trace periodogram of the module docs: `(q_k, C1D(q_k))` for `k = 1..=N/2`
/// (\[1/m\], \[m³\]) after removing the least-squares line and applying `window`.
pub fn periodogram(trace: &Trace, window: TraceWindow, fft: &mut Fft1) -> (Vec<f64>, Vec<f64>) {
    let n = trace.heights.len();
    let mut z = detrend(&trace.heights);
    let mut w2 = 1.0;
    if window == TraceWindow::Hann && n > 1 {
        let mut sum = 0.0;
        for (j, v) in z.iter_mut().enumerate() {
            let w = (PI * j as f64 / n as f64).sin().powi(2);
            *v *= w;
            sum += w * w;
        }
        w2 = sum / n as f64;
    }
    if n < 2 {
        return (Vec::new(), Vec::new());
    }
    let spectrum: Vec<Complex<f64>> = fft.forward(&mut z);
    let scale = trace.spacing / (2.0 * PI * n as f64 * w2);
    let length = trace.length();
    (1..=n / 2)
        .map(|k| (2.0 * PI * k as f64 / length, spectrum[k].norm_sqr() * scale))
        .unzip()
}

/// `Γ(1+H) / (√π Γ(H+½))`: `C(q) = C1D(q)/q ×` this for a power law `C ∝ q^{−2(1+H)}`
/// (module docs). Defined for H > −½.
pub fn power_law_factor(hurst: f64) -> f64 {
    libm::tgamma(1.0 + hurst) / (PI.sqrt() * libm::tgamma(hurst + 0.5))
}

/// Half-width (in bins) of the local quadratic smoothing of ln C1D before the inversion.
pub const SMOOTH_HALF_WIDTH: usize = 2;

/// Gauss–Legendre nodes/weights used by the transforms.
const GL_POINTS: usize = 16;

/// 1-D spectrum of an isotropic 2-D spectrum (the forward Abel transform of the module docs):
/// `C1D(q) = 2 ∫_0^∞ C(q cosh u) q cosh u du` over the spectrum's band (C = 0 outside)
/// \[m³\], for `q > 0`.
pub fn one_d_from_two_d(spectrum: &Spectrum, q: f64) -> f64 {
    if !(q > 0.0 && q < spectrum.q1()) {
        return 0.0;
    }
    let (nodes, weights) = gauss_legendre(GL_POINTS);
    // knots of C in u: the band edges and every interior knot above q
    let start = q.max(spectrum.q0());
    let mut knots_q: Vec<f64> = vec![start];
    knots_q.extend(
        spectrum
            .interior_knots()
            .map(f64::exp)
            .filter(|&k| k > start),
    );
    knots_q.push(spectrum.q1());
    let mut total = 0.0;
    for pair in knots_q.windows(2) {
        let (u0, u1) = ((pair[0] / q).acosh(), (pair[1] / q).acosh());
        // split each piece in 8 for the curvature of cosh
        let pieces = 8;
        for p in 0..pieces {
            let a = u0 + (u1 - u0) * p as f64 / pieces as f64;
            let b = u0 + (u1 - u0) * (p + 1) as f64 / pieces as f64;
            let (mid, half) = ((a + b) / 2.0, (b - a) / 2.0);
            for (x, w) in nodes.iter().zip(&weights) {
                let qq = q * (mid + half * x).cosh();
                total += half * w * spectrum.c(qq.min(spectrum.q1())) * qq;
            }
        }
    }
    2.0 * total
}

/// The inverse Abel transform of the module docs: the isotropic 2-D C at each `q[j]` from a
/// 1-D spectrum given at points `(q, c1d)` (increasing q, c1d > 0), interpolated by a cubic
/// Hermite spline in `(ln q, ln C1D)` (node slopes from the parabola through each point and its
/// neighbours, so that the curvature of C1D at a roll-off is followed) and continued above the
/// last point by `C1D ∝ q^{tail_slope}` (`tail_slope` capped at −1). Values may come out ≤ 0
/// where the data rise with q.
pub fn abel_inverse(q: &[f64], c1d: &[f64], tail_slope: f64) -> Vec<f64> {
    let m = q.len().min(c1d.len());
    if m == 0 {
        return Vec::new();
    }
    let (nodes, weights) = gauss_legendre(GL_POINTS);
    let x: Vec<f64> = q[..m].iter().map(|v| v.ln()).collect();
    let y: Vec<f64> = c1d[..m].iter().map(|v| v.ln()).collect();
    let tail = tail_slope.min(-1.0);
    let d = node_slopes(&x, &y);
    // dC1D/dq at q on segment i (q in [q_i, q_{i+1}]); i = m−1 the tail
    let derivative = |i: usize, qq: f64| {
        let xx = qq.ln();
        if i + 1 >= m {
            return tail * (y[m - 1] + tail * (xx - x[m - 1])).exp() / qq;
        }
        let h = x[i + 1] - x[i];
        let t = (xx - x[i]) / h;
        let (t2, t3) = (t * t, t * t * t);
        let p = (2.0 * t3 - 3.0 * t2 + 1.0) * y[i]
            + (t3 - 2.0 * t2 + t) * h * d[i]
            + (-2.0 * t3 + 3.0 * t2) * y[i + 1]
            + (t3 - t2) * h * d[i + 1];
        let dp = ((6.0 * t2 - 6.0 * t) * y[i]
            + (3.0 * t2 - 4.0 * t + 1.0) * h * d[i]
            + (-6.0 * t2 + 6.0 * t) * y[i + 1]
            + (3.0 * t2 - 2.0 * t) * h * d[i + 1])
            / h;
        p.exp() * dp / qq
    };
    let gauss = |a: f64, b: f64, qj: f64, i: usize| {
        let (mid, half) = ((a + b) / 2.0, (b - a) / 2.0);
        nodes
            .iter()
            .zip(&weights)
            .map(|(u, w)| half * w * derivative(i, qj * (mid + half * u).cosh()))
            .sum::<f64>()
    };
    (0..m)
        .map(|j| {
            let qj = q[j];
            let mut total = 0.0;
            for i in j..m - 1 {
                let (u0, u1) = ((q[i] / qj).acosh(), (q[i + 1] / qj).acosh());
                // from u = 0 the map q = q_j cosh u is flat: split the first segment
                let pieces = if i == j { 4 } else { 1 };
                for p in 0..pieces {
                    let a = u0 + (u1 - u0) * p as f64 / pieces as f64;
                    let b = u0 + (u1 - u0) * (p + 1) as f64 / pieces as f64;
                    total += gauss(a, b, qj, i);
                }
            }
            // tail: integrand ∝ e^{(tail − 1)u}; integrate 60 e-folds in 12 panels
            let u_start = (q[m - 1] / qj).acosh();
            let span = 60.0 / (1.0 - tail);
            for p in 0..12 {
                let a = u_start + span * p as f64 / 12.0;
                let b = u_start + span * (p + 1) as f64 / 12.0;
                total += gauss(a, b, qj, m - 1);
            }
            -total / PI
        })
        .collect()
}

/// Slopes dy/dx at the nodes: the derivative of the parabola through each node and its two
/// neighbours (the nearest three at the ends); the secant for two nodes.
fn node_slopes(x: &[f64], y: &[f64]) -> Vec<f64> {
    let m = x.len();
    if m < 2 {
        return vec![0.0; m];
    }
    if m == 2 {
        let s = (y[1] - y[0]) / (x[1] - x[0]);
        return vec![s, s];
    }
    (0..m)
        .map(|i| {
            let c = i.clamp(1, m - 2);
            let (x0, x1, x2) = (x[c - 1], x[c], x[c + 1]);
            let (y0, y1, y2) = (y[c - 1], y[c], y[c + 1]);
            // derivative at x[i] of the Lagrange parabola through the three points
            let xi = x[i];
            y0 * ((xi - x1) + (xi - x2)) / ((x0 - x1) * (x0 - x2))
                + y1 * ((xi - x0) + (xi - x2)) / ((x1 - x0) * (x1 - x2))
                + y2 * ((xi - x0) + (xi - x1)) / ((x2 - x0) * (x2 - x1))
        })
        .collect()
}

/// Weighted local quadratic regression of `y(x)` (LOESS-like, no tricube): at each node the
/// quadratic least-squares fit over the `2w + 1` nearest nodes (window shifted at the ends),
/// weights `weight`, evaluated at the node. Exact for a quadratic (a power law in log–log).
fn smooth(x: &[f64], y: &[f64], weight: &[f64], w: usize) -> Vec<f64> {
    let m = x.len();
    let width = (2 * w + 1).min(m);
    if width < 3 {
        return y.to_vec();
    }
    (0..m)
        .map(|i| {
            let lo = i.saturating_sub(w).min(m - width);
            let xs = &x[lo..lo + width];
            // normal equations in t = x − x_i
            let mut a = [[0.0f64; 3]; 3];
            let mut b = [0.0f64; 3];
            for (k, &xk) in xs.iter().enumerate() {
                let t = xk - x[i];
                let basis = [1.0, t, t * t];
                let wk = weight[lo + k];
                for r in 0..3 {
                    b[r] += wk * basis[r] * y[lo + k];
                    for c in 0..3 {
                        a[r][c] += wk * basis[r] * basis[c];
                    }
                }
            }
            solve3(a, b).map_or(y[i], |coef| coef[0])
        })
        .collect()
}

/// Solve a 3 × 3 system by Gaussian elimination with partial pivoting; `None` if singular.
fn solve3(mut a: [[f64; 3]; 3], mut b: [f64; 3]) -> Option<[f64; 3]> {
    for col in 0..3 {
        let pivot = (col..3).max_by(|&r, &s| a[r][col].abs().total_cmp(&a[s][col].abs()))?;
        if a[pivot][col].abs() < 1e-300 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        for r in col + 1..3 {
            let f = a[r][col] / a[col][col];
            let pivot_row = a[col];
            for (entry, p) in a[r].iter_mut().zip(pivot_row).skip(col) {
                *entry -= f * p;
            }
            b[r] -= f * b[col];
        }
    }
    let mut out = [0.0; 3];
    for r in (0..3).rev() {
        let s: f64 = (r + 1..3).map(|c| a[r][c] * out[c]).sum();
        out[r] = (b[r] - s) / a[r][r];
    }
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// The 2-D model of the fit ("Parametric model" in the module docs): `C(q) = A q_r^{−2(1+H)}`
/// for `q < q_r`, `A q^{−2(1+H)}` above \[m⁴ with A in m⁴·m^{−2(1+H)}\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollOffModel {
    /// Prefactor A of the power law (`C = A q^{−2(1+H)}` above q_r).
    pub prefactor: f64,
    /// Hurst exponent H.
    pub hurst: f64,
    /// Roll-off wavevector q_r \[1/m\] (at or below the band's first point: no roll-off in the
    /// band).
    pub rolloff: f64,
}

impl RollOffModel {
    /// The 2-D spectrum `C(q)` \[m⁴\].
    pub fn c(&self, q: f64) -> f64 {
        self.prefactor * q.max(self.rolloff).powf(-2.0 * (1.0 + self.hurst))
    }

    /// Its 1-D spectrum (forward Abel transform, module docs) \[m³\]:
    /// `A · rolloff_one_d(H, q_r, q)`.
    pub fn c1d(&self, q: f64) -> f64 {
        self.prefactor * rolloff_one_d(self.hurst, self.rolloff, q)
    }
}

/// 1-D spectrum of the unit roll-off model `C = min(q, q_r)^{−2(1+H)}` (A = 1), extending to
/// q = ∞: with `q′ = q cosh u` (module docs) and `p = 1 + 2H`,
/// * `q ≥ q_r`: `q^{−p} Γ(½)Γ(H+½)/Γ(1+H)` (the power-law closed form);
/// * `q < q_r`: `2 q_r^{−2(1+H)} √(q_r² − q²) + 2 q^{−p} (G − ∫_0^{u_r} cosh^{−p} u du)`,
///   `u_r = acosh(q_r/q)`, `G = ∫_0^∞ cosh^{−p} u du = ½ B(H+½, ½)` (the flat part integrated
///   exactly, the finite integral by 2 × 16-point Gauss–Legendre).
pub fn rolloff_one_d(hurst: f64, rolloff: f64, q: f64) -> f64 {
    let p = 1.0 + 2.0 * hurst;
    let g = 0.5 / power_law_factor(hurst);
    if q >= rolloff {
        return 2.0 * g * q.powf(-p);
    }
    let u_r = (rolloff / q).acosh();
    let (nodes, weights) = gauss_legendre(GL_POINTS);
    let mut head = 0.0;
    for panel in 0..2 {
        let (a, b) = (u_r * panel as f64 / 2.0, u_r * (panel + 1) as f64 / 2.0);
        let (mid, half) = ((a + b) / 2.0, (b - a) / 2.0);
        head += nodes
            .iter()
            .zip(&weights)
            .map(|(x, w)| half * w * (mid + half * x).cosh().powf(-p))
            .sum::<f64>();
    }
    2.0 * rolloff.powf(-1.0 - p) * (rolloff * rolloff - q * q).sqrt()
        + 2.0 * q.powf(-p) * (g - head).max(0.0)
}

/// Weighted least-squares fit of the roll-off model to `(ln q, ln C1D)` with weights `w`,
/// ln A eliminated (weighted mean of the residual): `(model, weighted SSE)`. H ∈ [0.02, 1.2],
/// `ln q_r` from the band's first point to the point with 4 points above (`allow_rolloff`
/// false: q_r at the first point, a pure power law); a 25 × 25 grid refined 5 times.
fn fit_model(ln_q: &[f64], y: &[f64], w: &[f64], allow_rolloff: bool) -> (RollOffModel, f64) {
    let m = ln_q.len();
    let sw: f64 = w.iter().sum();
    let eval = |h: f64, lr: f64| {
        let f: Vec<f64> = ln_q
            .iter()
            .map(|x| rolloff_one_d(h, lr.exp(), x.exp()).max(1e-300).ln())
            .collect();
        let ln_a = y
            .iter()
            .zip(&f)
            .zip(w)
            .map(|((a, b), c)| c * (a - b))
            .sum::<f64>()
            / sw;
        let sse: f64 = y
            .iter()
            .zip(&f)
            .zip(w)
            .map(|((a, b), c)| c * (a - b - ln_a).powi(2))
            .sum();
        (sse, ln_a)
    };
    let (h_lo, h_hi) = (0.02, 1.2);
    let lr_lo = ln_q[0];
    let lr_hi = if allow_rolloff && m >= 6 {
        ln_q[m - 5]
    } else {
        ln_q[0]
    };
    let (mut hc, mut lc) = ((h_lo + h_hi) / 2.0, (lr_lo + lr_hi) / 2.0);
    let (mut hw, mut lw) = ((h_hi - h_lo) / 2.0, (lr_hi - lr_lo) / 2.0);
    let mut best = (f64::INFINITY, hc, lc, 0.0);
    let n = 24;
    for _ in 0..6 {
        for i in 0..=n {
            let h = (hc - hw + 2.0 * hw * i as f64 / n as f64).clamp(h_lo, h_hi);
            for j in 0..=n {
                let lr = (lc - lw + 2.0 * lw * j as f64 / n as f64).clamp(lr_lo, lr_hi);
                let (sse, ln_a) = eval(h, lr);
                if sse < best.0 {
                    best = (sse, h, lr, ln_a);
                }
            }
        }
        (hc, lc) = (best.1, best.2);
        (hw, lw) = (hw / 4.0, lw / 4.0);
    }
    (
        RollOffModel {
            prefactor: best.3.exp(),
            hurst: best.1,
            rolloff: best.2.exp(),
        },
        best.0,
    )
}

/// Standard error of H of the weighted fit (`σ² = SSE/(m − k)`, covariance
/// `σ² (JᵀWJ)⁻¹` with J the numerical Jacobian of ln C1D in (ln A, H, ln q_r), or (ln A, H)
/// without roll-off).
fn model_hurst_se(model: &RollOffModel, ln_q: &[f64], w: &[f64], sse: f64, rolloff: bool) -> f64 {
    let m = ln_q.len();
    let k = if rolloff { 3 } else { 2 };
    if m <= k {
        return f64::INFINITY;
    }
    let f = |h: f64, lr: f64, x: f64| rolloff_one_d(h, lr.exp(), x.exp()).max(1e-300).ln();
    let (h, lr) = (model.hurst, model.rolloff.ln());
    let mut a = [[0.0f64; 3]; 3];
    for (x, wi) in ln_q.iter().zip(w) {
        let dh = (f(h + 1e-5, lr, *x) - f(h - 1e-5, lr, *x)) / 2e-5;
        let dl = if rolloff {
            (f(h, lr + 1e-5, *x) - f(h, lr - 1e-5, *x)) / 2e-5
        } else {
            0.0
        };
        let j = [1.0, dh, dl];
        for r in 0..3 {
            for c in 0..3 {
                a[r][c] += wi * j[r] * j[c];
            }
        }
    }
    if !rolloff {
        a[2][2] = 1.0;
    }
    let sigma2 = sse / (m - k) as f64;
    solve3(a, [0.0, 1.0, 0.0]).map_or(f64::INFINITY, |col| (sigma2 * col[1]).max(0.0).sqrt())
}

/// Trace of the hat matrix of [`smooth`] (its effective number of parameters): at node i the
/// weight of y_i in its own fit, `w_i [(XᵀWX)⁻¹]₀₀`.
fn smooth_dof(x: &[f64], weight: &[f64], w: usize) -> f64 {
    let m = x.len();
    let width = (2 * w + 1).min(m);
    if width < 3 {
        return m as f64;
    }
    (0..m)
        .map(|i| {
            let lo = i.saturating_sub(w).min(m - width);
            let mut a = [[0.0f64; 3]; 3];
            for (k, &xk) in x[lo..lo + width].iter().enumerate() {
                let t = xk - x[i];
                let basis = [1.0, t, t * t];
                for r in 0..3 {
                    for c in 0..3 {
                        a[r][c] += weight[lo + k] * basis[r] * basis[c];
                    }
                }
            }
            solve3(a, [1.0, 0.0, 0.0]).map_or(1.0, |col| weight[i] * col[0])
        })
        .sum()
}

/// Least-squares line `y = a + b x`: `(a, b, standard error of b, SSE)`.
fn line_fit(x: &[f64], y: &[f64]) -> (f64, f64, f64, f64) {
    let n = x.len() as f64;
    let mx = x.iter().sum::<f64>() / n;
    let my = y.iter().sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for (a, b) in x.iter().zip(y) {
        sxy += (a - mx) * (b - my);
        sxx += (a - mx).powi(2);
    }
    let b = if sxx > 0.0 { sxy / sxx } else { 0.0 };
    let a = my - b * mx;
    let sse: f64 = x
        .iter()
        .zip(y)
        .map(|(xi, yi)| (yi - a - b * xi).powi(2))
        .sum();
    let se = if x.len() > 2 && sxx > 0.0 {
        (sse / (n - 2.0) / sxx).sqrt()
    } else {
        f64::INFINITY
    };
    (a, b, se, sse)
}

/// Student t quantile t_{0.975,ν}, or ∞ when undefined.
pub(crate) fn t975(dof: usize) -> f64 {
    StudentsT::new(0.0, 1.0, dof as f64)
        .map(|t| t.inverse_cdf(0.975))
        .ok()
        .filter(|v| v.is_finite())
        .unwrap_or(f64::INFINITY)
}

#[derive(Default, Clone, Copy)]
struct Bin {
    count: usize,
    sum_c: f64,
    sum_ln_q: f64,
    sum_ln_q2: f64,
}

/// The trusted `(q_lo, q_hi)` of one trace (module docs).
fn trace_band(trace: &Trace, options: &ProfileOptions, rms: f64) -> (f64, f64) {
    let q_lo = options.low_periods * 2.0 * PI / trace.length();
    let mut q_hi = options.nyquist_fraction * PI / trace.spacing;
    if let Some(r) = options.tip_radius
        && r > 0.0
        && rms > 0.0
    {
        q_hi = q_hi.min(1.0 / (r * rms).sqrt());
    }
    (q_lo, q_hi)
}

/// The binned, averaged 1-D spectrum of `traces` over their trusted ordinates (module docs,
/// "Averaging").
///
/// # Errors
/// If a trace is invalid (spacing, fewer than [`MIN_POINTS`] points, a non-finite height), the
/// options are out of range, or fewer than 4 bins hold ordinates.
pub fn psd_1d(traces: &[Trace], options: &ProfileOptions) -> Result<Psd1d, ProfileError> {
    check_options(options)?;
    if traces.is_empty() {
        return Err(ProfileError("no traces".into()));
    }
    let per_decade = options.bins_per_decade as f64;
    let mut bins: BTreeMap<i64, Bin> = BTreeMap::new();
    let mut fft = Fft1::new();
    for (i, trace) in traces.iter().enumerate() {
        trace.check(i)?;
        let rms = rms(&detrend(&trace.heights));
        let (q_lo, q_hi) = trace_band(trace, options, rms);
        let (q, c) = periodogram(trace, options.window, &mut fft);
        for (qk, ck) in q.into_iter().zip(c) {
            if qk < q_lo * (1.0 - 1e-12) || qk > q_hi * (1.0 + 1e-12) {
                continue;
            }
            let ln_q = qk.ln();
            let b = (ln_q / std::f64::consts::LN_10 * per_decade).floor() as i64;
            let bin = bins.entry(b).or_default();
            bin.count += 1;
            bin.sum_c += ck;
            bin.sum_ln_q += ln_q;
            bin.sum_ln_q2 += ln_q * ln_q;
        }
    }
    let rows: Vec<(f64, f64, f64, usize)> = bins
        .values()
        .filter(|b| b.count > 0 && b.sum_c > 0.0)
        .map(|b| {
            let n = b.count as f64;
            let mean = b.sum_ln_q / n;
            let var = (b.sum_ln_q2 / n - mean * mean).max(0.0);
            (mean, (b.sum_c / n).ln(), var, b.count)
        })
        .collect();
    if rows.len() < 4 {
        return Err(ProfileError(format!(
            "the traces' trusted band holds {} bin(s) of the 1-D spectrum; at least 4 are \
             needed (longer or more finely sampled traces)",
            rows.len()
        )));
    }
    // curvature correction with the local slope from the neighbours
    let m = rows.len();
    let mut out = Psd1d {
        q: Vec::with_capacity(m),
        c: Vec::with_capacity(m),
        count: Vec::with_capacity(m),
    };
    for i in 0..m {
        let (a, b) = (i.saturating_sub(1), (i + 1).min(m - 1));
        let s = (rows[b].1 - rows[a].1) / (rows[b].0 - rows[a].0);
        let (ln_q, ln_c, var, count) = rows[i];
        out.q.push(ln_q.exp());
        out.c.push((ln_c - s * s * var / 2.0).exp());
        out.count.push(count);
    }
    Ok(out)
}

fn check_options(options: &ProfileOptions) -> Result<(), ProfileError> {
    if options.bins_per_decade == 0 {
        return Err(ProfileError("bins_per_decade must be at least 1".into()));
    }
    if !(options.low_periods.is_finite() && options.low_periods >= 1.0) {
        return Err(ProfileError(format!(
            "low_periods must be at least 1, got {}",
            options.low_periods
        )));
    }
    if !(options.nyquist_fraction > 0.0 && options.nyquist_fraction <= 1.0) {
        return Err(ProfileError(format!(
            "nyquist_fraction must lie in (0, 1], got {}",
            options.nyquist_fraction
        )));
    }
    if let Some(r) = options.tip_radius
        && !(r.is_finite() && r > 0.0)
    {
        return Err(ProfileError(format!(
            "the tip radius must be positive and finite, got {r}"
        )));
    }
    if let Some(l) = options.cutoff
        && !(l.is_finite() && l > 0.0)
    {
        return Err(ProfileError(format!(
            "the cut-off λc must be positive and finite, got {l}"
        )));
    }
    Ok(())
}

fn rms(z: &[f64]) -> f64 {
    if z.is_empty() {
        return 0.0;
    }
    (z.iter().map(|v| v * v).sum::<f64>() / z.len() as f64).sqrt()
}

/// The 1-D spectrum of `traces` → the isotropic 2-D spectrum over the trusted band, its fit and
/// the profile parameters (module docs).
///
/// # Errors
/// As [`psd_1d`]; also if the traces are flat.
pub fn analyse(traces: &[Trace], options: &ProfileOptions) -> Result<TraceSpectrum, ProfileError> {
    let psd = psd_1d(traces, options)?;
    let m = psd.q.len();
    let ln_q: Vec<f64> = psd.q.iter().map(|v| v.ln()).collect();
    let raw: Vec<f64> = psd.c.iter().map(|v| v.ln()).collect();
    let weight: Vec<f64> = psd.count.iter().map(|&n| n as f64).collect();
    let ln_c = smooth(&ln_q, &raw, &weight, SMOOTH_HALF_WIDTH);
    let c1: Vec<f64> = ln_c.iter().map(|v| v.exp()).collect();
    let top = m.saturating_sub(5);
    let (_, tail, _, _) = line_fit(&ln_q[top..], &ln_c[top..]);
    let mut c2 = abel_inverse(&psd.q, &c1, tail);
    // local power-law closed form where the inversion is not positive
    let mut replaced = 0;
    for j in 0..m {
        if !(c2[j].is_finite() && c2[j] > 0.0) {
            let (a, b) = (j.saturating_sub(1), (j + 1).min(m - 1));
            let s = (ln_c[b] - ln_c[a]) / (ln_q[b] - ln_q[a]);
            let h = (-(s + 1.0) / 2.0).clamp(0.05, 0.95);
            c2[j] = c1[j] / psd.q[j] * power_law_factor(h);
            replaced += 1;
        }
    }
    // the parametric model, fitted through the forward transform (module docs)
    let (law, sse_law) = fit_model(&ln_q, &raw, &weight, false);
    let (roll, sse_roll) = fit_model(&ln_q, &raw, &weight, true);
    let aic = |sse: f64, k: f64| m as f64 * (sse / m as f64).max(1e-300).ln() + 2.0 * k;
    let has_rolloff =
        roll.rolloff > psd.q[0] * (1.0 + 1e-9) && aic(sse_roll, 3.0) < aic(sse_law, 2.0);
    let (model, sse_model, k_model) = if has_rolloff {
        (roll, sse_roll, 3.0)
    } else {
        (law, sse_law, 2.0)
    };
    let sse_smooth: f64 = raw
        .iter()
        .zip(&ln_c)
        .zip(&weight)
        .map(|((a, b), w)| w * (a - b).powi(2))
        .sum();
    let dof_smooth = smooth_dof(&ln_q, &weight, SMOOTH_HALF_WIDTH);
    let from_model = aic(sse_model, k_model) <= aic(sse_smooth, dof_smooth);
    let inversion = c2.clone();
    let (spectrum, hurst, q0) = if from_model {
        let mut q_tab = psd.q.clone();
        if has_rolloff
            && let Some(i) = q_tab.iter().position(|&q| q > model.rolloff)
            && i > 0
            && model.rolloff > q_tab[i - 1] * (1.0 + 1e-6)
            && model.rolloff < q_tab[i] * (1.0 - 1e-6)
        {
            q_tab.insert(i, model.rolloff);
        }
        let c_tab: Vec<f64> = q_tab.iter().map(|&q| model.c(q)).collect();
        let se = model_hurst_se(&model, &ln_q, &weight, sse_model, has_rolloff);
        let half = t975((m as f64 - k_model) as usize) * se;
        let h = model.hurst;
        (
            Spectrum::tabulated(&q_tab, &c_tab)?,
            (h, (h - half, h + half)),
            has_rolloff.then_some(model.rolloff),
        )
    } else {
        let ln_c2: Vec<f64> = c2.iter().map(|v| v.ln()).collect();
        let (hurst, q0) = fit_hurst(&ln_q, &ln_c2);
        (Spectrum::tabulated(&psd.q, &c2)?, hurst, q0)
    };

    let mut sum_z2 = 0.0;
    let mut sum_s2 = 0.0;
    let (mut nz, mut ns) = (0usize, 0usize);
    let mut parameters = Vec::with_capacity(traces.len());
    for trace in traces {
        let z = detrend(&trace.heights);
        sum_z2 += z.iter().map(|v| v * v).sum::<f64>();
        nz += z.len();
        for w in z.windows(2) {
            sum_s2 += ((w[1] - w[0]) / trace.spacing).powi(2);
            ns += 1;
        }
        parameters.push(profile_parameters(trace, options.cutoff)?);
    }
    let trace_rms = (sum_z2 / nz.max(1) as f64).sqrt();
    if trace_rms <= 0.0 {
        return Err(ProfileError("the traces are flat".into()));
    }
    Ok(TraceSpectrum {
        band: (psd.q[0], psd.q[m - 1]),
        h_rms: spectrum.rms_roughness(),
        rms_slope: spectrum.rms_slope(),
        spectrum,
        hurst,
        q0,
        trace_rms,
        trace_rms_slope: (2.0 * sum_s2 / ns.max(1) as f64).sqrt(),
        traces: traces.len(),
        psd_1d: psd,
        replaced_points: if from_model { 0 } else { replaced },
        inversion,
        model,
        from_model,
        parameters,
    })
}

/// The fit of the module docs on 2-D points `(ln q, ln C)`: `((H, (lo, hi)), roll-off)`.
fn fit_hurst(ln_q: &[f64], ln_c: &[f64]) -> ((f64, (f64, f64)), Option<f64>) {
    let m = ln_q.len();
    let (_, _, _, sse_line) = line_fit(ln_q, ln_c);
    let aic = |sse: f64, k: f64| m as f64 * (sse / m as f64).max(1e-300).ln() + 2.0 * k;
    let mut best: Option<(f64, usize)> = None;
    for b in 1..m {
        if m - 1 - b < 4 {
            break;
        }
        // C flat up to point b, then a power law: y = c0 + s max(0, x − x_b)
        let x: Vec<f64> = ln_q.iter().map(|v| (v - ln_q[b]).max(0.0)).collect();
        let (_, _, _, sse) = line_fit(&x, ln_c);
        let score = aic(sse, 3.0);
        if best.is_none_or(|(s, _)| score < s) {
            best = Some((score, b));
        }
    }
    let from = match best {
        Some((score, b)) if score < aic(sse_line, 2.0) => Some(b),
        _ => None,
    };
    let start = from.unwrap_or(0);
    let (_, slope, se, _) = line_fit(&ln_q[start..], &ln_c[start..]);
    let h = -slope / 2.0 - 1.0;
    let half = t975(m - start - 2) * se / 2.0;
    ((h, (h - half, h + half)), from.map(|b| ln_q[b].exp()))
}

/// Ra, Rq, Rz of one trace (module docs, "Profile parameters"), with the Gaussian mean line of
/// cut-off `cutoff` \[m\] or, for `None` (or a trace shorter than 2λc), the least-squares line.
///
/// # Errors
/// If the trace has fewer than 10 points, a bad spacing or a non-finite height, or the cut-off
/// is not positive.
pub fn profile_parameters(
    trace: &Trace,
    cutoff: Option<f64>,
) -> Result<ProfileParameters, ProfileError> {
    let n = trace.heights.len();
    let dx = trace.spacing;
    if !(dx.is_finite() && dx > 0.0) || n < 10 || trace.heights.iter().any(|z| !z.is_finite()) {
        return Err(ProfileError(
            "profile parameters need at least 10 finite heights and a positive spacing".into(),
        ));
    }
    let gaussian = match cutoff {
        Some(lc) if !(lc.is_finite() && lc > 0.0) => {
            return Err(ProfileError(format!(
                "the cut-off λc must be positive and finite, got {lc}"
            )));
        }
        Some(lc) if (n as f64 - 1.0) * dx >= 2.0 * lc => Some(lc),
        _ => None,
    };
    let (roughness, sampling, mean_line) = match gaussian {
        Some(lc) => {
            let half = ((lc / 2.0) / dx).floor() as usize;
            let alpha = (std::f64::consts::LN_2 / PI).sqrt();
            let kernel: Vec<f64> = (0..=2 * half)
                .map(|i| {
                    let x = (i as f64 - half as f64) * dx;
                    (-PI * (x / (alpha * lc)).powi(2)).exp()
                })
                .collect();
            let norm: f64 = kernel.iter().sum();
            let r: Vec<f64> = (half..n - half)
                .map(|j| {
                    let mean: f64 = kernel
                        .iter()
                        .enumerate()
                        .map(|(i, w)| w * trace.heights[j + i - half])
                        .sum::<f64>()
                        / norm;
                    trace.heights[j] - mean
                })
                .collect();
            let per = ((lc / dx).round() as usize).max(1);
            let count = (r.len() / per).min(5);
            (r, (count, per), MeanLine::Gaussian { cutoff: lc })
        }
        None => {
            let r = detrend(&trace.heights);
            let per = n / 5;
            (r, (5, per), MeanLine::LeastSquaresLine)
        }
    };
    let len = roughness.len() as f64;
    let ra = roughness.iter().map(|v| v.abs()).sum::<f64>() / len;
    let rq = rms(&roughness);
    let (count, per) = sampling;
    let rz = (count > 0 && per >= 2).then(|| {
        roughness
            .chunks_exact(per)
            .take(count)
            .map(|chunk| {
                let (lo, hi) = chunk
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
                        (lo.min(v), hi.max(v))
                    });
                hi - lo
            })
            .sum::<f64>()
            / count as f64
    });
    Ok(ProfileParameters {
        ra,
        rq,
        rz,
        sampling_lengths: if rz.is_some() { count } else { 0 },
        evaluation_length: len * dx,
        mean_line,
    })
}

/// A periodic Gaussian random isotropic surface of the 2-D spectrum `spectrum` on `n × n`
/// pixels of side `pixel` \[m\] (cell side `L = n · pixel`), row-major `h[iy * n + ix]` \[m\]:
/// for testing and for example traces.
///
/// Each Fourier mode `q = (2π/L) k` with `0 < |k|`, `|k_x|, |k_y| < n/2`, gets
/// `h_q = σ (g₁ + i g₂)/√2` with `σ² = (2π/L)² C(|q|)` (C = 0 outside the spectrum's band) and
/// independent standard normals g from a SplitMix64 seeded with `seed` (Box–Muller, libm's
/// cos/sin), Hermitian symmetry making h real; so `⟨|h_q|²⟩ = (2π/L)² C`, the PY08
/// normalisation (see the numerical reference's `surface` module). Unlike that module's random-phase surface
/// the power of each mode scatters (χ² with 2 degrees of freedom), as on a real surface.
///
/// # Panics
/// If `n` is odd or smaller than 4.
pub fn synthesize_gaussian(spectrum: &Spectrum, n: usize, pixel: f64, seed: u64) -> Vec<f64> {
    assert!(
        n >= 4 && n.is_multiple_of(2),
        "grid size must be even and ≥ 4"
    );
    let mut fft = Fft2::new(n);
    let h = fft.half();
    let dq = 2.0 * PI / (n as f64 * pixel);
    let scale = (n * n) as f64; // Fft2::inverse divides by n²
    let mut rng = SplitMix64(seed);
    let mut half = vec![Complex::new(0.0, 0.0); n * h];
    for ky in 0..n {
        let ky_s = signed_index(ky, n);
        for kx in 0..n / 2 {
            // independent half plane: kx > 0, or kx = 0 and ky > 0; Nyquist rows/columns empty
            if (kx == 0 && ky_s <= 0) || ky_s.unsigned_abs() as usize == n / 2 {
                continue;
            }
            let q = dq * ((kx * kx) as f64 + (ky_s * ky_s) as f64).sqrt();
            let sigma = dq * spectrum.c(q).sqrt();
            let (g1, g2) = rng.normal_pair();
            half[ky * h + kx] =
                Complex::new(g1, g2) * (scale * sigma * std::f64::consts::FRAC_1_SQRT_2);
        }
    }
    for ky in 1..n / 2 {
        half[(n - ky) * h] = half[ky * h].conj();
    }
    let mut heights = vec![0.0; n * n];
    fft.inverse(&mut half, &mut heights);
    heights
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    #[test]
    fn parseval_rectangular_is_exact() {
        let mut rng = SplitMix64(7);
        let n = 512;
        let heights: Vec<f64> = (0..n).map(|_| rng.normal_pair().0 * 1e-6).collect();
        let trace = Trace {
            spacing: 2e-6,
            heights,
        };
        let z = detrend(&trace.heights);
        let ms = z.iter().map(|v| v * v).sum::<f64>() / n as f64;
        let (q, c) = periodogram(&trace, TraceWindow::Rectangular, &mut Fft1::new());
        let dq = q[0];
        // h_rms² = 2 ∫_0^∞ C1D dq; the Nyquist ordinate (k = N/2) is its own mirror image
        let sum: f64 = c[..c.len() - 1].iter().sum::<f64>() * 2.0 * dq + c[c.len() - 1] * dq;
        assert!(rel(sum, ms) < 1e-12, "{sum} vs {ms}");
    }

    #[test]
    fn hann_keeps_the_power_of_white_noise() {
        // white noise of unit variance: C1D = Δx/(2π) at every q; 64 traces of 4096 points
        let mut rng = SplitMix64(11);
        let n = 4096;
        let mut fft = Fft1::new();
        let mut mean = 0.0;
        for _ in 0..64 {
            let heights: Vec<f64> = (0..n).map(|_| rng.normal_pair().0).collect();
            let trace = Trace {
                spacing: 1.0,
                heights,
            };
            let (q, c) = periodogram(&trace, TraceWindow::Hann, &mut fft);
            assert_eq!(q.len(), n / 2);
            mean += c.iter().sum::<f64>() / c.len() as f64 / 64.0;
        }
        assert!(rel(mean, 1.0 / (2.0 * PI)) < 0.01, "{mean}");
    }

    #[test]
    fn power_law_factor_constant() {
        // H = 0.5: Γ(1.5)/(√π Γ(1)) = ½
        assert!((power_law_factor(0.5) - 0.5).abs() < 1e-14);
        assert!((power_law_factor(0.8) - 0.585_5).abs() < 1e-3);
    }

    #[test]
    fn profile_parameters_of_a_sine() {
        let a = 1e-6;
        // a cosine even about the trace's centre (no least-squares tilt), with samples on every
        // crest and trough: Rz = 2a exactly, Rq = a/√2, Ra = 2a/π
        let period = 100;
        let n = 100 * period + 1;
        let centre = (n / 2) as f64;
        let heights: Vec<f64> = (0..n)
            .map(|j| a * (2.0 * PI * (j as f64 - centre) / period as f64).cos())
            .collect();
        let trace = Trace {
            spacing: 1e-6,
            heights,
        };
        let p = profile_parameters(&trace, None).unwrap();
        assert!(rel(p.rz.unwrap(), 2.0 * a) < 1e-6, "{p:?}");
        assert!(rel(p.rq, a / 2f64.sqrt()) < 1e-3);
        assert!(rel(p.ra, 2.0 * a / PI) < 1e-3);
    }

    #[test]
    fn rolloff_one_d_matches_the_numerical_transform() {
        for h in [0.3, 0.8] {
            let q_r = 1e5;
            let spectrum = Spectrum::self_affine(1e-6, h, 1.0, 1e12, Some(q_r)).unwrap();
            let a = spectrum.c(2.0 * q_r) * (2.0 * q_r).powf(2.0 * (1.0 + h));
            for q in [1e4, 3e4, 6e4, 9.9e4, 1e5, 1.5e5, 4e5] {
                let closed = a * rolloff_one_d(h, q_r, q);
                let numerical = one_d_from_two_d(&spectrum, q);
                assert!(
                    rel(closed, numerical) < 1e-6,
                    "H {h} q {q}: {closed} {numerical}"
                );
            }
        }
    }

    #[test]
    fn bad_options_are_errors() {
        let trace = Trace {
            spacing: 1e-6,
            heights: vec![0.0; 100],
        };
        assert!(analyse(std::slice::from_ref(&trace), &ProfileOptions::default()).is_err());
        let opts = ProfileOptions {
            bins_per_decade: 0,
            ..ProfileOptions::default()
        };
        assert!(psd_1d(&[trace], &opts).is_err());
    }
}
