//! Surface roughness power spectra C(q) and their moments.
//!
//! Every spectrum sealsim handles is represented exactly as a *piecewise power law* in q:
//! on the segment `[q_k, q_{k+1}]`, `C(q) = C_k (q/q_k)^{s_k}`. A self-affine fractal is one
//! segment (PY08 §3: `C = C0 q^{-2(1+H)}`), a spectrum with a roll-off is two, and a tabulated
//! spectrum interpolated linearly in log C against log q (docs/model.md §2) is one segment per interval.
//! The moments `∫ q^n C(q) dq` that the contact theory needs are then closed forms, so no
//! quadrature error enters G(ζ), h_rms(ζ) or the critical magnification ζc.
//!
//! Conventions (PY08 §2): `C(q) = (2π)^-2 ∫ d²x <h(x)h(0)> e^{-iq·x}` \[m⁴\];
//! `h_rms² = 2π ∫ q C(q) dq`. All quantities in SI units.

use crate::units::show;
use std::fmt;

/// Why a spectrum could not be built. The input boundary adds file, line and key.
#[derive(Debug, Clone, PartialEq)]
pub enum SpectrumError {
    /// A parameter is outside its domain; the string says which and why.
    Invalid(String),
}

impl fmt::Display for SpectrumError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SpectrumError::Invalid(msg) => f.write_str(msg),
        }
    }
}

impl std::error::Error for SpectrumError {}

/// One power-law piece: on `[exp(ln_q), exp(ln_q_end)]`, `ln C = ln_c + slope (ln q − ln_q)`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment {
    ln_q: f64,
    ln_q_end: f64,
    ln_c: f64,
    slope: f64,
}

impl Segment {
    fn ln_c_at(&self, ln_q: f64) -> f64 {
        self.ln_c + self.slope * (ln_q - self.ln_q)
    }

    /// `∫_a^b q^n C dq` for `ln a`, `ln b` inside this segment, from `a` and `L = ln(b/a) ≥ 0`:
    /// `a^{n+1} C(a) · (e^{eL} − 1)/e` with `e = n + 1 + slope`. Exact; stable for small `L`
    /// and for `e → 0` (then it is `a^{n+1} C(a) L`).
    fn moment_from(&self, n: f64, ln_a: f64, big_l: f64) -> f64 {
        let e = n + 1.0 + self.slope;
        ((n + 1.0) * ln_a + self.ln_c_at(ln_a)).exp() * big_l * expm1_over_x(e * big_l)
    }
}

/// `(e^x − 1)/x`, continuous through x = 0.
pub(crate) fn expm1_over_x(x: f64) -> f64 {
    if x.abs() < 1e-8 {
        1.0 + 0.5 * x
    } else {
        x.exp_m1() / x
    }
}

/// A roughness power spectrum on `[q0, q1]`, piecewise power law (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum {
    segments: Vec<Segment>,
    /// `∫_{q0}^{q_k} q³ C dq` at the start of each segment (and one more at q1).
    cum_m3: Vec<f64>,
    /// `∫_{q0}^{q_k} q C dq` at the start of each segment (and one more at q1).
    cum_m1: Vec<f64>,
    /// The Hurst exponent of a spectrum given as a self-affine fractal (`None` for a tabulated
    /// one): only for the validity check of docs/model.md §9.5.
    hurst: Option<f64>,
}

impl Spectrum {
    /// Self-affine fractal with rms roughness `h_rms` \[m\], Hurst exponent `hurst` ∈ (0, 1),
    /// cut-offs `q0 < q1` \[1/m\] and an optional roll-off `q_r` ∈ (q0, q1) below which C is
    /// flat at `C(q_r)` (docs/model.md §2).
    ///
    /// Normalised exactly so that `2π ∫_{q0}^{q1} q C dq = h_rms²`. Without roll-off this is
    /// PY08 §3's `C0 = (H/π) h_rms² [q0^{-2H} − q1^{-2H}]^{-1}` (the paper's approximate form
    /// `≈ (H/π) h² q0^{-2H}` is not used).
    pub fn self_affine(
        h_rms: f64,
        hurst: f64,
        q0: f64,
        q1: f64,
        rolloff: Option<f64>,
    ) -> Result<Self, SpectrumError> {
        positive_finite("rms roughness", h_rms)?;
        positive_finite("q0", q0)?;
        positive_finite("q1", q1)?;
        if !(hurst > 0.0 && hurst < 1.0) {
            return Err(SpectrumError::Invalid(format!(
                "Hurst exponent must lie strictly between 0 and 1, got {}",
                show(hurst)
            )));
        }
        if q0 >= q1 {
            return Err(SpectrumError::Invalid(format!(
                "q0 must be smaller than q1, got q0 = {} 1/m and q1 = {} 1/m",
                show(q0),
                show(q1)
            )));
        }
        let slope = -2.0 * (1.0 + hurst);
        let (ln_q0, ln_q1) = (q0.ln(), q1.ln());
        let segments = match rolloff {
            None => vec![Segment {
                ln_q: ln_q0,
                ln_q_end: ln_q1,
                ln_c: 0.0,
                slope,
            }],
            Some(qr) => {
                positive_finite("roll-off wavevector", qr)?;
                if !(qr > q0 && qr < q1) {
                    return Err(SpectrumError::Invalid(format!(
                        "the roll-off wavevector must lie between q0 and q1, got {} 1/m",
                        show(qr)
                    )));
                }
                let ln_qr = qr.ln();
                vec![
                    Segment {
                        ln_q: ln_q0,
                        ln_q_end: ln_qr,
                        ln_c: 0.0,
                        slope: 0.0,
                    },
                    Segment {
                        ln_q: ln_qr,
                        ln_q_end: ln_q1,
                        ln_c: 0.0,
                        slope,
                    },
                ]
            }
        };
        // Built with C = 1 at every segment start, then shifted: normalise in log space.
        let mut s = Spectrum::from_segments(segments);
        s.rescale_to(h_rms);
        s.hurst = Some(hurst);
        Ok(s)
    }

    /// Tabulated spectrum: strictly increasing `q` \[1/m\] with `C > 0` \[m⁴\], interpolated
    /// linearly in `ln C` against `ln q` (docs/model.md §2). At least two points.
    pub fn tabulated(q: &[f64], c: &[f64]) -> Result<Self, SpectrumError> {
        if q.len() != c.len() {
            return Err(SpectrumError::Invalid(
                "q and C columns differ in length".into(),
            ));
        }
        if q.len() < 2 {
            return Err(SpectrumError::Invalid(format!(
                "a tabulated spectrum needs at least two points, got {}",
                q.len()
            )));
        }
        for (i, (&qi, &ci)) in q.iter().zip(c).enumerate() {
            if !(qi.is_finite() && qi > 0.0 && ci.is_finite() && ci > 0.0) {
                return Err(SpectrumError::Invalid(format!(
                    "point {} (q = {qi}, C = {ci}): q and C must be positive and finite",
                    i + 1
                )));
            }
            if i > 0 && qi <= q[i - 1] {
                return Err(SpectrumError::Invalid(format!(
                    "point {}: q must increase strictly (q = {qi} after {})",
                    i + 1,
                    q[i - 1]
                )));
            }
        }
        let segments = q
            .windows(2)
            .zip(c.windows(2))
            .map(|(qw, cw)| {
                let (l0, l1) = (qw[0].ln(), qw[1].ln());
                Segment {
                    ln_q: l0,
                    ln_q_end: l1,
                    ln_c: cw[0].ln(),
                    slope: (cw[1].ln() - cw[0].ln()) / (l1 - l0),
                }
            })
            .collect();
        Ok(Spectrum::from_segments(segments))
    }

    fn from_segments(mut segments: Vec<Segment>) -> Self {
        // Make C continuous: each segment starts where the previous one ended.
        for k in 1..segments.len() {
            let prev = segments[k - 1];
            segments[k].ln_c = prev.ln_c_at(prev.ln_q_end);
        }
        let mut s = Spectrum {
            segments,
            cum_m3: Vec::new(),
            cum_m1: Vec::new(),
            hurst: None,
        };
        s.recompute_cumulative();
        s
    }

    fn recompute_cumulative(&mut self) {
        let mut m3 = vec![0.0];
        let mut m1 = vec![0.0];
        for seg in &self.segments {
            let l = seg.ln_q_end - seg.ln_q;
            m3.push(m3[m3.len() - 1] + seg.moment_from(3.0, seg.ln_q, l));
            m1.push(m1[m1.len() - 1] + seg.moment_from(1.0, seg.ln_q, l));
        }
        self.cum_m3 = m3;
        self.cum_m1 = m1;
    }

    /// Returns a copy with `C` multiplied by a constant so that the rms roughness is `h_rms`.
    /// Every contact quantity of the copy follows from the scaling law of docs/model.md §2.
    pub fn with_rms_roughness(&self, h_rms: f64) -> Self {
        let mut s = self.clone();
        s.rescale_to(h_rms);
        s
    }

    /// The spectrum's shape: C divided by C(q0), then scaled to an rms roughness of 1 µm. Two
    /// spectra that differ by a constant factor only (a self-affine surface at another Ra or
    /// rms) have the same bits here whenever the factor sits in one shift of ln C, as it does
    /// for every [`Self::self_affine`] spectrum, so the scale-free contact tables
    /// (the contact table of `contact::table`) computed on it are shared between them.
    pub fn unit_shape(&self) -> Self {
        let mut s = self.clone();
        let ln_c0 = s.segments.first().map_or(0.0, |seg| seg.ln_c);
        for seg in &mut s.segments {
            seg.ln_c -= ln_c0;
        }
        s.recompute_cumulative();
        s.rescale_to(1e-6);
        s
    }

    fn rescale_to(&mut self, h_rms: f64) {
        let shift = (h_rms * h_rms).ln() - (2.0 * std::f64::consts::PI * self.total_m1()).ln();
        for seg in &mut self.segments {
            seg.ln_c += shift;
        }
        self.recompute_cumulative();
    }

    /// Returns a copy restricted to `[q_lo, q_hi]` (inside the current range).
    pub fn restricted(&self, q_lo: f64, q_hi: f64) -> Result<Self, SpectrumError> {
        let (lo, hi) = (q_lo.ln(), q_hi.ln());
        if !(q_lo > 0.0 && q_lo < q_hi && lo >= self.ln_q0() - 1e-12 && hi <= self.ln_q1() + 1e-12)
        {
            return Err(SpectrumError::Invalid(format!(
                "the band [{q_lo}, {q_hi}] 1/m must lie inside the spectrum's [{}, {}] 1/m",
                self.q0(),
                self.q1()
            )));
        }
        let segments = self
            .segments
            .iter()
            .filter(|s| s.ln_q_end > lo && s.ln_q < hi)
            .map(|s| {
                let start = s.ln_q.max(lo);
                Segment {
                    ln_q: start,
                    ln_q_end: s.ln_q_end.min(hi),
                    ln_c: s.ln_c_at(start),
                    slope: s.slope,
                }
            })
            .collect();
        Ok(Spectrum {
            hurst: self.hurst,
            ..Spectrum::from_segments(segments)
        })
    }

    /// The spectrum of two uncorrelated rough surfaces in contact, `C = C_self + C_other`
    /// \[m⁴\], on the union of the two bands (where only one spectrum is defined, it alone).
    ///
    /// The height difference `h = h_1 − h_2` of two independent random surfaces has the
    /// autocorrelation `<h_1 h_1> + <h_2 h_2>`, so its spectrum is the sum (docs/model.md §2.2;
    /// Persson & Scaraggi, *General contact mechanics theory for randomly rough surfaces with
    /// application to rubber friction*, J. Chem. Phys. 143 (2015) 224111, arXiv:1506.06955 —
    /// both surfaces rough; the sum itself is recalled from Persson, Surf. Sci. Rep. 61 (2006)).
    ///
    /// Exactness: the breakpoints of both are merged; where one spectrum covers an interval the
    /// piece is copied, where both do and their slopes agree the sum is again one power law
    /// (exact). Where the slopes differ by Δs, `ln C` (a log-sum-exp of two lines, convex with
    /// `(ln C)'' ≤ Δs²/4`) is tabulated on equal steps h in `ln q` with `Δs² h²/32 ≤`
    /// [`SUM_TOLERANCE`]: the tabulated C lies above the exact sum by a factor in
    /// `[1, e^SUM_TOLERANCE]` everywhere, hence so does every moment `∫ q^n C dq`.
    ///
    /// Errors if the bands neither overlap nor touch (C would be zero on the gap between).
    pub fn sum(&self, other: &Spectrum) -> Result<Spectrum, SpectrumError> {
        let (a, b) = (self, other);
        if a.ln_q1() < b.ln_q0() || b.ln_q1() < a.ln_q0() {
            return Err(SpectrumError::Invalid(format!(
                "the two spectra's bands [{}, {}] and [{}, {}] 1/m do not overlap: the combined \
                 spectrum would be zero in between",
                show(a.q0()),
                show(a.q1()),
                show(b.q0()),
                show(b.q1())
            )));
        }
        let mut knots: Vec<f64> = [a, b]
            .iter()
            .flat_map(|s| {
                s.segments
                    .iter()
                    .map(|g| g.ln_q)
                    .chain(std::iter::once(s.ln_q1()))
            })
            .collect();
        knots.sort_by(f64::total_cmp);
        knots.dedup_by(|x, y| (*x - *y).abs() <= 1e-12 * y.abs().max(1.0));
        // the segment of `s` covering the open interval (x0, x1), if any
        let piece = |s: &Spectrum, x0: f64, x1: f64| -> Option<Segment> {
            let mid = 0.5 * (x0 + x1);
            (mid > s.ln_q0() && mid < s.ln_q1()).then(|| s.segments[s.segment_index(mid)])
        };
        let step = (32.0 * SUM_TOLERANCE).sqrt();
        let mut segments = Vec::new();
        for w in knots.windows(2) {
            let (x0, x1) = (w[0], w[1]);
            let pieces = (piece(a, x0, x1), piece(b, x0, x1));
            let (p, q) = match pieces {
                (None, None) => continue,
                (Some(p), None) | (None, Some(p)) => {
                    segments.push(Segment {
                        ln_q: x0,
                        ln_q_end: x1,
                        ln_c: p.ln_c_at(x0),
                        slope: p.slope,
                    });
                    continue;
                }
                (Some(p), Some(q)) => (p, q),
            };
            let ln_sum = |x: f64| log_add_exp(p.ln_c_at(x), q.ln_c_at(x));
            let ds = (p.slope - q.slope).abs();
            let n = ((x1 - x0) * ds / step).ceil().max(1.0) as usize;
            let node = |i: usize| {
                if i == n {
                    x1
                } else {
                    x0 + (x1 - x0) * i as f64 / n as f64
                }
            };
            for i in 0..n {
                let (s0, s1) = (node(i), node(i + 1));
                let (c0, c1) = (ln_sum(s0), ln_sum(s1));
                segments.push(Segment {
                    ln_q: s0,
                    ln_q_end: s1,
                    ln_c: c0,
                    slope: if p.slope == q.slope {
                        p.slope
                    } else {
                        (c1 - c0) / (s1 - s0)
                    },
                });
            }
        }
        let mut s = Spectrum {
            segments,
            cum_m3: Vec::new(),
            cum_m1: Vec::new(),
            hurst: match (a.hurst, b.hurst) {
                (Some(x), Some(y)) if x == y => Some(x),
                _ => None,
            },
        };
        s.recompute_cumulative();
        Ok(s)
    }

    /// Lower cut-off q0 \[1/m\]; magnification ζ = q/q0.
    pub fn q0(&self) -> f64 {
        self.ln_q0().exp()
    }

    /// Upper cut-off q1 \[1/m\].
    pub fn q1(&self) -> f64 {
        self.ln_q1().exp()
    }

    pub(crate) fn ln_q0(&self) -> f64 {
        self.segments[0].ln_q
    }

    pub(crate) fn ln_q1(&self) -> f64 {
        self.segments[self.segments.len() - 1].ln_q_end
    }

    /// Natural logs of the segment boundaries strictly inside (q0, q1): kinks of C(q).
    pub(crate) fn interior_knots(&self) -> impl Iterator<Item = f64> + '_ {
        self.segments[1..].iter().map(|s| s.ln_q)
    }

    fn segment_index(&self, ln_q: f64) -> usize {
        // partition_point: first segment whose end is ≥ ln_q
        self.segments
            .partition_point(|s| s.ln_q_end < ln_q)
            .min(self.segments.len() - 1)
    }

    /// `ln C(q)` at `ln q` (clamped to the band).
    pub(crate) fn ln_c(&self, ln_q: f64) -> f64 {
        self.segments[self.segment_index(ln_q)].ln_c_at(ln_q)
    }

    /// C(q) \[m⁴\]; zero outside `[q0, q1]`.
    pub fn c(&self, q: f64) -> f64 {
        let l = q.ln();
        if !(l >= self.ln_q0() && l <= self.ln_q1()) {
            return 0.0;
        }
        self.ln_c(l).exp()
    }

    /// `∫_{q_a}^{q_b} q^n C(q) dq` for `ln q_a = ln_a` and `q_b = q_a e^{big_l}`, both in the
    /// band. Exact; accurate even when `big_l` is far below machine epsilon relative to `ln_a`.
    pub(crate) fn moment_span(&self, n: f64, ln_a: f64, big_l: f64) -> f64 {
        let mut k = self.segment_index(ln_a);
        let ln_b = ln_a + big_l;
        let mut total = 0.0;
        let mut start = ln_a;
        let mut span = big_l;
        loop {
            let seg = &self.segments[k];
            let room = seg.ln_q_end - start;
            if span <= room || k + 1 == self.segments.len() {
                return total + seg.moment_from(n, start, span.min(room.max(0.0)).max(0.0));
            }
            total += seg.moment_from(n, start, room.max(0.0));
            k += 1;
            start = self.segments[k].ln_q;
            span = ln_b - start;
        }
    }

    /// `∫_{q0}^{q} q'³ C dq'` \[m⁰… m⁴·m⁻⁴·…\]: the moment behind G(ζ) (PY08 §2), exact.
    pub fn m3_to(&self, q: f64) -> f64 {
        self.cumulative(q.ln(), 3.0, &self.cum_m3)
    }

    /// `∫_{q0}^{q} q' C dq'`; `h_rms²(ζ) = 2π (total − m1_to(ζ q0))` (PY08 eq. 4).
    pub fn m1_to(&self, q: f64) -> f64 {
        self.cumulative(q.ln(), 1.0, &self.cum_m1)
    }

    fn cumulative(&self, ln_q: f64, n: f64, cum: &[f64]) -> f64 {
        if ln_q <= self.ln_q0() {
            return 0.0;
        }
        if ln_q >= self.ln_q1() {
            return cum[cum.len() - 1];
        }
        let k = self.segment_index(ln_q);
        let seg = &self.segments[k];
        cum[k] + seg.moment_from(n, seg.ln_q, ln_q - seg.ln_q)
    }

    /// `∫_{q0}^{q1} q³ C dq` = h'_rms²/(2π), the mean-square slope over 2π.
    pub fn total_m3(&self) -> f64 {
        self.cum_m3[self.cum_m3.len() - 1]
    }

    /// `∫_{q0}^{q1} q C dq` = h_rms²/(2π).
    pub fn total_m1(&self) -> f64 {
        self.cum_m1[self.cum_m1.len() - 1]
    }

    /// rms roughness `h_rms = (2π ∫ q C dq)^{1/2}` \[m\].
    pub fn rms_roughness(&self) -> f64 {
        (2.0 * std::f64::consts::PI * self.total_m1()).sqrt()
    }

    /// The Hurst exponent H of a self-affine spectrum (`C ∝ q^{−2(1+H)}`); `None` for a
    /// tabulated spectrum.
    pub fn hurst_exponent(&self) -> Option<f64> {
        self.hurst
    }

    /// rms slope `h'_rms = (2π ∫ q³ C dq)^{1/2}` (dimensionless).
    pub fn rms_slope(&self) -> f64 {
        (2.0 * std::f64::consts::PI * self.total_m3()).sqrt()
    }

    /// Roughness left at magnification ζ: `h_rms(ζ) = (2π ∫_{ζq0}^{q1} q C dq)^{1/2}` (PY08 eq. 4).
    pub fn rms_roughness_above(&self, q: f64) -> f64 {
        let ln_q = q.ln().max(self.ln_q0());
        let rest = if ln_q >= self.ln_q1() {
            0.0
        } else {
            self.moment_span(1.0, ln_q, self.ln_q1() - ln_q)
        };
        (2.0 * std::f64::consts::PI * rest).sqrt()
    }

    /// The `ln q` at which `∫_{q0}^{q} q'³ C dq' = target`, or `None` if `target` exceeds the
    /// total over the band. Exact inversion of the piecewise power law.
    pub fn invert_m3(&self, target: f64) -> Option<f64> {
        if target.is_nan() || target < 0.0 || target > self.total_m3() {
            return None;
        }
        let k = self
            .cum_m3
            .partition_point(|&m| m <= target)
            .saturating_sub(1);
        let k = k.min(self.segments.len() - 1);
        let seg = &self.segments[k];
        let rest = target - self.cum_m3[k];
        // rest = a⁴ C(a) (e^{eL} − 1)/e  ⇒  L = ln(1 + e·rest/(a⁴C(a)))/e
        let base = (4.0 * seg.ln_q + seg.ln_c).exp();
        let e = 4.0 + seg.slope;
        let r = rest / base;
        let l = if (e * r).abs() < 1e-12 {
            r * (1.0 - 0.5 * e * r)
        } else {
            (e * r).ln_1p() / e
        };
        Some((seg.ln_q + l).min(seg.ln_q_end))
    }
}

/// Largest relative error of C in [`Spectrum::sum`] where two power laws of different slope
/// overlap: the tabulated sum lies within a factor `e^{1e-4}` (0.01 %) above the exact one.
pub const SUM_TOLERANCE: f64 = 1e-4;

/// `ln(e^a + e^b)`, symmetric in a and b (so that a sum of spectra does not depend on order).
fn log_add_exp(a: f64, b: f64) -> f64 {
    let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
    hi + (lo - hi).exp().ln_1p()
}

fn positive_finite(what: &str, v: f64) -> Result<(), SpectrumError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(SpectrumError::Invalid(format!(
            "{what} must be positive and finite, got {}",
            show(v)
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn paper() -> Spectrum {
        Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None).unwrap()
    }

    #[test]
    fn self_affine_matches_paper_c0_exactly() {
        let s = paper();
        let (h, q0, q1) = (0.8, 1e4_f64, 7.8e9_f64);
        let c0 = h / PI * 4e-12 / (q0.powf(-2.0 * h) - q1.powf(-2.0 * h));
        for q in [1e4_f64, 3.3e6, 7.8e9] {
            let expect = c0 * q.powf(-2.0 * (1.0 + h));
            assert!((s.c(q) / expect - 1.0).abs() < 1e-12, "q={q}");
        }
        assert!((s.rms_roughness() / 2e-6 - 1.0).abs() < 1e-13);
    }

    #[test]
    fn moments_match_closed_forms() {
        let s = paper();
        let (h, q0, q1) = (0.8_f64, 1e4_f64, 7.8e9_f64);
        let c0 = h / PI * 4e-12 / (q0.powf(-2.0 * h) - q1.powf(-2.0 * h));
        let q = 2.5e7_f64;
        // ∫ q³ C = C0 (q^{2-2H} − q0^{2-2H})/(2−2H)
        let m3 = c0 * (q.powf(2.0 - 2.0 * h) - q0.powf(2.0 - 2.0 * h)) / (2.0 - 2.0 * h);
        assert!((s.m3_to(q) / m3 - 1.0).abs() < 1e-12);
        let m1 = c0 * (q0.powf(-2.0 * h) - q.powf(-2.0 * h)) / (2.0 * h);
        assert!((s.m1_to(q) / m1 - 1.0).abs() < 1e-12);
        let above = (2.0 * PI * c0 * (q.powf(-2.0 * h) - q1.powf(-2.0 * h)) / (2.0 * h)).sqrt();
        assert!((s.rms_roughness_above(q) / above - 1.0).abs() < 1e-12);
    }

    #[test]
    fn tiny_spans_do_not_cancel() {
        let s = paper();
        let ln_a = (1.6e5_f64).ln();
        let l = 1e-20;
        let expect = (4.0 * ln_a).exp() * s.c(1.6e5) * l;
        assert!((s.moment_span(3.0, ln_a, l) / expect - 1.0).abs() < 1e-12);
    }

    #[test]
    fn invert_m3_round_trips_across_segments() {
        let s = Spectrum::self_affine(1e-6, 0.7, 1e3, 1e9, Some(1e5)).unwrap();
        for q in [1.5e3, 9.9e4, 1e5, 1.01e5, 3e7, 9.99e8] {
            let lq = s.invert_m3(s.m3_to(q)).unwrap();
            assert!((lq - q.ln()).abs() < 1e-10, "q={q} back={}", lq.exp());
        }
        assert!(s.invert_m3(s.total_m3() * 1.0001).is_none());
    }

    #[test]
    fn rolloff_is_flat_below_qr_and_normalised() {
        let s = Spectrum::self_affine(3e-6, 0.8, 1e3, 1e8, Some(1e4)).unwrap();
        assert!((s.c(2e3) / s.c(9e3) - 1.0).abs() < 1e-12);
        assert!((s.c(1e4) / s.c(2e4) - 2f64.powf(3.6)).abs() < 1e-9);
        assert!((s.rms_roughness() / 3e-6 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn tabulated_power_law_equals_self_affine() {
        let a = Spectrum::self_affine(2e-6, 0.8, 1e4, 1e8, None).unwrap();
        let q: Vec<f64> = (0..=8).map(|i| 1e4 * 10f64.powf(i as f64 * 0.5)).collect();
        let c: Vec<f64> = q.iter().map(|&q| a.c(q)).collect();
        let t = Spectrum::tabulated(&q, &c).unwrap();
        for qq in [1.3e4, 7.7e5, 9.9e7] {
            assert!((t.c(qq) / a.c(qq) - 1.0).abs() < 1e-12);
            assert!((t.m3_to(qq) / a.m3_to(qq) - 1.0).abs() < 1e-12);
        }
        assert!((t.rms_roughness() / 2e-6 - 1.0).abs() < 1e-12);
    }

    #[test]
    fn sum_of_equal_slopes_is_exact() {
        let a = Spectrum::self_affine(1e-6, 0.8, 1e4, 1e9, None).unwrap();
        let b = Spectrum::self_affine(2e-6, 0.8, 1e4, 1e9, None).unwrap();
        let s = a.sum(&b).unwrap();
        assert_eq!(s.segments.len(), 1);
        let rss = (1e-12_f64 + 4e-12).sqrt();
        assert!((s.rms_roughness() / rss - 1.0).abs() < 1e-12);
        let slope = (a.rms_slope().powi(2) + b.rms_slope().powi(2)).sqrt();
        assert!((s.rms_slope() / slope - 1.0).abs() < 1e-12);
        assert_eq!(s.hurst_exponent(), Some(0.8));
    }

    #[test]
    fn sum_of_different_spectra_is_within_the_stated_tolerance() {
        // different H, different bands, one with a roll-off: every moment within e^{1e-4}
        let a = Spectrum::self_affine(1e-6, 0.8, 1e4, 1e9, Some(1e5)).unwrap();
        let b = Spectrum::self_affine(0.5e-6, 0.6, 3e4, 3e9, None).unwrap();
        let s = a.sum(&b).unwrap();
        let ba = b.sum(&a).unwrap();
        assert_eq!(s, ba, "the sum does not depend on the order");
        assert!((s.q0() - 1e4).abs() < 1e-6 && (s.q1() / 3e9 - 1.0).abs() < 1e-12);
        let rss = (a.rms_roughness().powi(2) + b.rms_roughness().powi(2)).sqrt();
        let r = s.rms_roughness() / rss;
        assert!((1.0..1.0 + 0.5 * SUM_TOLERANCE + 1e-12).contains(&r), "{r}");
        let slope = (a.rms_slope().powi(2) + b.rms_slope().powi(2)).sqrt();
        let r = s.rms_slope() / slope;
        assert!((1.0..1.0 + 0.5 * SUM_TOLERANCE + 1e-12).contains(&r), "{r}");
        // pointwise: C within [1, e^tol] of the exact sum, also where only one is defined
        for q in [1.2e4, 5e4, 9.9e4, 1.1e5, 3.3e6, 7e8, 2e9] {
            let r = s.c(q) / (a.c(q) + b.c(q));
            assert!(
                (1.0 - 1e-12..=SUM_TOLERANCE.exp() + 1e-12).contains(&r),
                "q = {q}: {r}"
            );
        }
        assert_eq!(s.hurst_exponent(), None);
        // the cumulative moments agree with a fine quadrature of the exact sum to the tolerance
        let m3 = |sp: &Spectrum| sp.m3_to(1e8);
        let r = m3(&s) / (m3(&a) + m3(&b));
        assert!((1.0..1.0 + 1.01 * SUM_TOLERANCE).contains(&r), "{r}");
    }

    #[test]
    fn sum_of_disjoint_bands_is_refused() {
        let a = Spectrum::self_affine(1e-6, 0.8, 1e4, 1e5, None).unwrap();
        let b = Spectrum::self_affine(1e-6, 0.8, 1e6, 1e7, None).unwrap();
        assert!(a.sum(&b).is_err());
    }

    #[test]
    fn invalid_parameters_are_rejected() {
        assert!(Spectrum::self_affine(2e-6, 1.0, 1e4, 1e9, None).is_err());
        assert!(Spectrum::self_affine(2e-6, 0.0, 1e4, 1e9, None).is_err());
        assert!(Spectrum::self_affine(2e-6, 0.8, 1e9, 1e4, None).is_err());
        assert!(Spectrum::self_affine(-1.0, 0.8, 1e4, 1e9, None).is_err());
        assert!(Spectrum::self_affine(1e-6, 0.8, 1e4, 1e9, Some(1e3)).is_err());
        assert!(Spectrum::tabulated(&[1.0, 1.0], &[1.0, 1.0]).is_err());
        assert!(Spectrum::tabulated(&[1.0, 2.0], &[1.0, -1.0]).is_err());
        assert!(Spectrum::tabulated(&[1.0], &[1.0]).is_err());
    }
}
