//! Drawing callouts (Ra, Rq, Rz with the cut-offs λc, λs) and the power spectra they imply.
//!
//! Physics only: the scenario boundary (`src/scenario/validate.rs`) reads the keys, checks them
//! and calls these functions with SI numbers. docs/model.md §2.1 states every relation below.
//!
//! * **The measured band.** A roughness parameter of ISO 21920-2 (formerly ISO 4287/4288) is
//!   evaluated on the profile filtered by the short-wave cut-off λs and the long-wave cut-off λc
//!   (the sampling length): wavevectors `q ∈ [2π/λc, 2π/λs]`. In the spectrum's convention
//!   (PY08 §2, `h_rms² = 2π ∫ q C dq`) the band's rms is `Rq = (2π ∫_{2π/λc}^{2π/λs} q C dq)^{1/2}`.
//!   This takes the profile's band rms as the isotropic surface's band rms (a line through an
//!   isotropic surface has the surface's height variance; the band-pass of a 1D profile mixes
//!   in some 2D wavevectors above its own — an approximation, docs/model.md §2.1).
//! * **Ra → Rq.** For Gaussian heights of standard deviation σ, `E|h| = σ √(2/π)`, so
//!   `Rq = √(π/2) Ra ≈ 1.2533 Ra` (the mean absolute deviation of a normal distribution; the
//!   "RMS ≈ 1.11 Ra" of conversion charts is a shop rule that assumes no distribution).
//! * **Rz → Rq.** Rz is the mean over the sampling lengths of the largest peak-to-valley height
//!   in one λc. For a Gaussian profile sampled at N = λc/λs independent points (λs is the
//!   shortest wavelength left), the expected peak-to-valley is `2 m(N) σ`, `m(N)` the expected
//!   largest of N independent standard normals: `Rz = 2 m(λc/λs) Rq`. With the defaults
//!   (N = 320) `Rz/Rq = 5.77`, `Rz/Ra = 7.23`; the conversion tables of practice give 7.2
//!   (Rz DIN) and 7.6 (Rz ISO) times Ra, and rules of thumb 4–7, up to 20 for surfaces with
//!   isolated deep scratches: a callout's Rz fixes Rq only to within a factor ≈ 2.
//! * **The spectrum of a callout.** Self-affine, `C ∝ q^{−2(1+H)}` from `q0 = 2π/λc` (flat
//!   below, if a longer `q0` is given: the waviness the λc filter removed is not known) to
//!   `q1`, scaled so that its rms over the measured band equals the callout's Rq.
//! * **Below λs** the profilometer saw nothing. [`ShortWavelengths::Extend`] (the default)
//!   continues the power law to [`EXTEND_TO_WAVELENGTH`] = 10 nm; [`ShortWavelengths::Stop`]
//!   ends the spectrum at 2π/λs; or `q1` is given.

use crate::math::special::erfc;
use crate::surface::{Spectrum, SpectrumError};
use std::f64::consts::PI;

/// Default long-wave cut-off λc = 0.8 mm \[m\]: the sampling length ISO 4288 (now ISO 21920-3)
/// prescribes for periodic or non-periodic profiles with 0.1 µm < Ra ≤ 2 µm — the range of
/// seal counterfaces.
pub const DEFAULT_CUTOFF: f64 = 0.8e-3;

/// Default short-wave cut-off λs = 2.5 µm \[m\]: the ISO 3274 / ISO 21920-3 pairing with
/// λc = 0.8 mm (λc/λs = 320, stylus tip radius 2 µm).
pub const DEFAULT_SHORT_CUTOFF: f64 = 2.5e-6;

/// Default Hurst exponent of a callout, H = 0.8 (fractal dimension 2.2): the value of PY08 §3
/// and of most surfaces Persson reports (recalled: B.N.J. Persson, *On the fractal dimension of
/// rough surfaces*, Tribol. Lett. 54 (2014) 99, finds most natural and machined surfaces with
/// 0.7 ≤ H ≤ 1, typically ≈ 0.8). Inside the 0.6–0.9 range of the validity check (§9.5).
pub const DEFAULT_HURST: f64 = 0.8;

/// Wavelength \[m\] to which [`ShortWavelengths::Extend`] continues the power law below λs:
/// 10 nm, q1 = 2π/(10 nm) = 6.28e8 1/m. A choice, not a measurement: AFM spectra of ground and
/// blasted steel stay self-affine well below the stylus' reach (recalled: Persson et al.,
/// J. Phys.: Condens. Matter 17 (2005) R1), and below ≈ 10 nm a rubber's network mesh and
/// the adsorbed layers make continuum contact questionable. For H = 0.8 the extension adds
/// < 0.01 % to h_rms but triples the rms slope of a ground surface (0.02 → 0.07 at Ra 0.4 µm):
/// it matters for the contact area, little for the leak's critical junction.
pub const EXTEND_TO_WAVELENGTH: f64 = 10e-9;

/// √(π/2): Rq/Ra for Gaussian heights.
pub const RQ_OVER_RA: f64 = 1.253_314_137_315_500_3;

/// Rq \[m\] of a Gaussian profile of arithmetic mean roughness `ra` \[m\]: `Rq = √(π/2) Ra`.
pub fn rq_from_ra(ra: f64) -> f64 {
    RQ_OVER_RA * ra
}

/// Ra \[m\] of a Gaussian profile of rms roughness `rq` \[m\]: `Ra = √(2/π) Rq`.
pub fn ra_from_rq(rq: f64) -> f64 {
    rq / RQ_OVER_RA
}

/// `m(N) = E[max of N independent standard normals] = ∫ x N φ(x) Φ(x)^{N−1} dx`
/// (dimensionless), by composite Simpson's rule on \[−12, 14\] (error < 1e-10 for 1 ≤ N ≤ 1e9).
/// `m(1) = 0`, `m(2) = 1/√π`.
pub fn expected_max_of_normals(n: f64) -> f64 {
    let steps = 20_000;
    let (lo, hi) = (-12.0_f64, 14.0_f64);
    let h = (hi - lo) / steps as f64;
    let f = |x: f64| {
        let phi = (-0.5 * x * x).exp() / (2.0 * PI).sqrt();
        let cdf = 0.5 * erfc(-x / std::f64::consts::SQRT_2);
        if cdf <= 0.0 {
            return 0.0;
        }
        x * n * phi * ((n - 1.0) * cdf.ln()).exp()
    };
    let mut sum = f(lo) + f(hi);
    for i in 1..steps {
        let w = if i % 2 == 1 { 4.0 } else { 2.0 };
        sum += w * f(lo + h * i as f64);
    }
    sum * h / 3.0
}

/// `Rz/Rq = 2 m(λc/λs)` (dimensionless) for a Gaussian profile: the expected peak-to-valley
/// height in one sampling length λc \[m\] with N = λc/λs independent samples (λs \[m\]). See the
/// module docs for how far the practice's ratios spread around it.
pub fn rz_over_rq(cutoff: f64, short_cutoff: f64) -> f64 {
    2.0 * expected_max_of_normals(cutoff / short_cutoff)
}

/// The measured band of a callout: wavelengths from `short_cutoff` λs to `cutoff` λc \[m\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Band {
    /// Long-wave cut-off λc \[m\].
    pub cutoff: f64,
    /// Short-wave cut-off λs \[m\].
    pub short_cutoff: f64,
}

impl Band {
    /// Lowest measured wavevector 2π/λc \[1/m\].
    pub fn q_lo(&self) -> f64 {
        2.0 * PI / self.cutoff
    }

    /// Highest measured wavevector 2π/λs \[1/m\].
    pub fn q_hi(&self) -> f64 {
        2.0 * PI / self.short_cutoff
    }

    /// The rms roughness of `spectrum` over the band \[m\]:
    /// `(2π ∫_{2π/λc}^{2π/λs} q C dq)^{1/2}` (the spectrum is zero outside its own range).
    pub fn rms(&self, spectrum: &Spectrum) -> f64 {
        (2.0 * PI * (spectrum.m1_to(self.q_hi()) - spectrum.m1_to(self.q_lo())))
            .max(0.0)
            .sqrt()
    }
}

/// The rule for the roughness below λs, which no callout measures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShortWavelengths {
    /// Continue the power law to q1 = 2π/[`EXTEND_TO_WAVELENGTH`] (the default).
    Extend,
    /// End the spectrum at q1 = 2π/λs: no roughness below the stylus' reach.
    Stop,
    /// End it at this q1 \[1/m\] (≥ 2π/λs).
    UpTo(f64),
}

impl ShortWavelengths {
    /// The upper cut-off q1 \[1/m\] for `band`.
    pub fn q1(&self, band: &Band) -> f64 {
        match *self {
            ShortWavelengths::Extend => (2.0 * PI / EXTEND_TO_WAVELENGTH).max(band.q_hi()),
            ShortWavelengths::Stop => band.q_hi(),
            ShortWavelengths::UpTo(q1) => q1,
        }
    }
}

/// A drawing callout turned into what the spectrum needs: Rq over the band, H, the band, an
/// optional lower cut-off below 2π/λc and the rule below λs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Callout {
    /// Rq over the band \[m\] (from Ra or Rz by the relations above).
    pub rq: f64,
    /// Hurst exponent H ∈ (0, 1).
    pub hurst: f64,
    /// The measured band.
    pub band: Band,
    /// Lower cut-off q0 \[1/m\] below 2π/λc (C flat from q0 to 2π/λc); `None`: q0 = 2π/λc.
    pub q0: Option<f64>,
    /// The rule below λs.
    pub short: ShortWavelengths,
}

impl Callout {
    /// The self-affine spectrum whose rms over the band is `rq`: `C ∝ q^{−2(1+H)}` on
    /// `[2π/λc, q1]`, flat on `[q0, 2π/λc]` if `q0` is given (a roll-off at 2π/λc).
    pub fn spectrum(&self) -> Result<Spectrum, SpectrumError> {
        let (qc, qs) = (self.band.q_lo(), self.band.q_hi());
        if self.band.cutoff.partial_cmp(&self.band.short_cutoff)
            != Some(std::cmp::Ordering::Greater)
        {
            return Err(SpectrumError::Invalid(format!(
                "the cut-off λc = {} m must be longer than the short cut-off λs = {} m",
                self.band.cutoff, self.band.short_cutoff
            )));
        }
        let q1 = self.short.q1(&self.band);
        if q1 < qs * (1.0 - 1e-12) {
            return Err(SpectrumError::Invalid(format!(
                "q1 = {q1} 1/m ends the spectrum inside the measured band (below 2π/λs = {qs} \
                 1/m)"
            )));
        }
        let q1 = q1.max(qs);
        let (q0, rolloff) = match self.q0 {
            Some(q0) if q0 < qc => (q0, Some(qc)),
            Some(q0) if q0 > qc * (1.0 + 1e-12) => {
                return Err(SpectrumError::Invalid(format!(
                    "q0 = {q0} 1/m is above 2π/λc = {qc} 1/m: it would cut the measured band"
                )));
            }
            _ => (qc, None),
        };
        let unit = Spectrum::self_affine(1.0, self.hurst, q0, q1, rolloff)?;
        let in_band = self.band.rms(&unit);
        Ok(unit.with_rms_roughness(self.rq / in_band))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn default_band() -> Band {
        Band {
            cutoff: DEFAULT_CUTOFF,
            short_cutoff: DEFAULT_SHORT_CUTOFF,
        }
    }

    #[test]
    fn ra_to_rq_is_root_half_pi() {
        assert!((rq_from_ra(1.0) - (PI / 2.0).sqrt()).abs() < 1e-15);
        assert!((ra_from_rq(rq_from_ra(0.4e-6)) / 0.4e-6 - 1.0).abs() < 1e-15);
    }

    #[test]
    fn gaussian_mean_absolute_deviation_matches_the_factor() {
        // E|x| for a standard normal by quadrature: √(2/π)
        let n = 200_000;
        let h = 20.0 / n as f64;
        let e_abs: f64 = (0..n)
            .map(|i| {
                let x = -10.0 + (i as f64 + 0.5) * h;
                x.abs() * (-0.5 * x * x).exp() / (2.0 * PI).sqrt() * h
            })
            .sum();
        assert!((1.0 / e_abs / RQ_OVER_RA - 1.0).abs() < 1e-8, "{e_abs}");
    }

    #[test]
    fn expected_maximum_of_normals_has_its_known_values() {
        assert!(expected_max_of_normals(1.0).abs() < 1e-10);
        // m(2) = 1/√π, m(3) = 3/(2√π) (closed forms)
        assert!((expected_max_of_normals(2.0) - 1.0 / PI.sqrt()).abs() < 1e-10);
        assert!((expected_max_of_normals(3.0) - 1.5 / PI.sqrt()).abs() < 1e-10);
        // m(5) = 1.162964 (tabulated order statistics of the normal)
        assert!((expected_max_of_normals(5.0) - 1.162_964).abs() < 1e-6);
    }

    #[test]
    fn rz_relation_is_twice_the_expected_maximum() {
        let r = rz_over_rq(DEFAULT_CUTOFF, DEFAULT_SHORT_CUTOFF);
        assert!((r - 2.0 * expected_max_of_normals(320.0)).abs() < 1e-12);
        // at the defaults: Rz/Ra ≈ 7.2, the conversion tables' Rz DIN factor (module docs)
        let rz_over_ra = r * RQ_OVER_RA;
        assert!((7.1..7.35).contains(&rz_over_ra), "{rz_over_ra}");
        // by Monte Carlo with a fixed LCG: the mean range of 320 normals over 4000 draws
        let mut state: u64 = 12345;
        let mut uniform = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        let draws = 4000;
        let mut mean_range = 0.0;
        for _ in 0..draws {
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for _ in 0..160 {
                let (u1, u2) = (uniform(), uniform());
                let r = (-2.0 * u1.ln()).sqrt();
                for z in [r * (2.0 * PI * u2).cos(), r * (2.0 * PI * u2).sin()] {
                    lo = lo.min(z);
                    hi = hi.max(z);
                }
            }
            mean_range += (hi - lo) / draws as f64;
        }
        // the standard error of the mean range is ≈ 0.55/√4000 ≈ 0.009
        assert!((mean_range - r).abs() < 0.04, "{mean_range} vs {r}");
    }

    #[test]
    fn callout_band_rms_matches_the_closed_form() {
        let h = 0.8_f64;
        let rq = rq_from_ra(0.4e-6);
        let callout = Callout {
            rq,
            hurst: h,
            band: default_band(),
            q0: None,
            short: ShortWavelengths::Extend,
        };
        let s = callout.spectrum().unwrap();
        let (qc, qs, q1) = (2.0 * PI / 0.8e-3, 2.0 * PI / 2.5e-6, 2.0 * PI / 10e-9);
        assert!((s.q0() / qc - 1.0).abs() < 1e-12 && (s.q1() / q1 - 1.0).abs() < 1e-12);
        // C = C0 q^{−2(1+H)}: ∫ q C dq = C0 (a^{−2H} − b^{−2H})/(2H); choose C0 from the band
        let m1 = |a: f64, b: f64| (a.powf(-2.0 * h) - b.powf(-2.0 * h)) / (2.0 * h);
        let c0 = rq * rq / (2.0 * PI * m1(qc, qs));
        for q in [qc, 1e5, qs, 1e8] {
            let expect = c0 * q.powf(-2.0 * (1.0 + h));
            assert!((s.c(q) / expect - 1.0).abs() < 1e-11, "q = {q}");
        }
        assert!((default_band().rms(&s) / rq - 1.0).abs() < 1e-12);
        let total = (2.0 * PI * c0 * m1(qc, q1)).sqrt();
        assert!((s.rms_roughness() / total - 1.0).abs() < 1e-12);
        // ∫ q³ C dq = C0 (b^{2−2H} − a^{2−2H})/(2−2H)
        let slope = (2.0 * PI * c0 * (q1.powf(2.0 - 2.0 * h) - qc.powf(2.0 - 2.0 * h))
            / (2.0 - 2.0 * h))
            .sqrt();
        assert!((s.rms_slope() / slope - 1.0).abs() < 1e-12);
    }

    #[test]
    fn stop_ends_at_the_short_cutoff_and_q0_adds_a_flat_part() {
        let mut callout = Callout {
            rq: 1e-6,
            hurst: 0.7,
            band: default_band(),
            q0: None,
            short: ShortWavelengths::Stop,
        };
        let s = callout.spectrum().unwrap();
        assert!((s.q1() / (2.0 * PI / 2.5e-6) - 1.0).abs() < 1e-12);
        assert!((s.rms_roughness() / 1e-6 - 1.0).abs() < 1e-12);
        callout.q0 = Some(1e3);
        let f = callout.spectrum().unwrap();
        assert!((f.c(1.5e3) / f.c(7e3) - 1.0).abs() < 1e-12);
        assert!((default_band().rms(&f) / 1e-6 - 1.0).abs() < 1e-12);
        assert!(f.rms_roughness() > 1e-6);
        callout.short = ShortWavelengths::UpTo(1e5);
        assert!(callout.spectrum().is_err());
        callout.short = ShortWavelengths::Stop;
        callout.band.short_cutoff = callout.band.cutoff;
        assert!(callout.spectrum().is_err());
    }
}
