//! Plausibility of measured heights against their sample spacing (docs/model.md §2.4): a height
//! map or a line trace whose heights are in µm but were read as m (or whose pixel is a thousand
//! times too small) still makes a valid spectrum, and the contact then gives gaps of metres.
//! Two numbers of the raw samples catch it, independently of the spectrum estimate:
//!
//! * the rms slope at the sample spacing, `h′_rms = ⟨|∇h|²⟩^{1/2}` from first differences (a
//!   trace: `⟨(Δz/Δx)²⟩^{1/2}`). A stylus with the standard 60° cone (ISO 25178-601, formerly
//!   ISO 3274: cone angle 60° or 90°) follows flanks up to 60° from the plane, slope
//!   tan 60° ≈ 1.7, so no stylus record has an rms slope above that; [`MAX_RMS_SLOPE`] = 10
//!   leaves a factor of about 6 for optical instruments and steep features (an assumed margin,
//!   not a measured limit);
//! * the rms height about the best-fit plane (a trace: line). The roughest grade of ISO 1302's
//!   table, N12, is Ra = 50 µm (Rq ≈ 63 µm for Gaussian heights); [`MAX_RMS_HEIGHT`] = 1 mm is
//!   16 times that: not a roughness.
//!
//! A slip of the height unit by 10³ (mm as m), 10⁶ (µm as m) or 10⁹ (nm as m) multiplies both
//! by that factor, so it crosses at least one bound for any real surface; the likely slip is the
//! smallest of these factors that brings both back within bounds.

/// rms slope at the sample spacing above which heights are implausible for their spacing
/// (dimensionless; assumed: about 6 × the steepest flank a 60° stylus cone follows).
pub const MAX_RMS_SLOPE: f64 = 10.0;

/// rms height above which heights are not a roughness \[m\] (16 × ISO 1302's roughest grade,
/// N12, Ra 50 µm ≈ Rq 63 µm).
pub const MAX_RMS_HEIGHT: f64 = 1e-3;

/// The two statistics of measured heights the check reads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeightStatistics {
    /// rms height about the best-fit plane (line) \[m\].
    pub rms_height: f64,
    /// rms slope from first differences at the sample spacing (dimensionless).
    pub rms_slope: f64,
    /// The sample spacing \[m\].
    pub spacing: f64,
}

impl HeightStatistics {
    /// Of a grid of `nx × ny` heights \[m\] (row-major, rows along y) at spacing `pixel` \[m\]:
    /// the rms about the least-squares plane, and `⟨(∂h/∂x)²⟩ + ⟨(∂h/∂y)²⟩` from forward
    /// differences (not wrapped: a measured map is not periodic).
    pub fn of_map(nx: usize, ny: usize, pixel: f64, heights: &[f64]) -> Self {
        let n = (nx * ny) as f64;
        let at = |ix: usize, iy: usize| heights[iy * nx + ix];
        // the plane z = a + b (x − x̄) + c (y − ȳ): on a full grid x and y are uncorrelated
        let (xm, ym) = ((nx as f64 - 1.0) / 2.0, (ny as f64 - 1.0) / 2.0);
        let mean = heights.iter().sum::<f64>() / n;
        let (mut sxz, mut sxx, mut syz, mut syy) = (0.0, 0.0, 0.0, 0.0);
        for iy in 0..ny {
            for ix in 0..nx {
                let (dx, dy, z) = (ix as f64 - xm, iy as f64 - ym, at(ix, iy) - mean);
                sxz += dx * z;
                sxx += dx * dx;
                syz += dy * z;
                syy += dy * dy;
            }
        }
        let b = if sxx > 0.0 { sxz / sxx } else { 0.0 };
        let c = if syy > 0.0 { syz / syy } else { 0.0 };
        let mut square = 0.0;
        for iy in 0..ny {
            for ix in 0..nx {
                let r = at(ix, iy) - mean - b * (ix as f64 - xm) - c * (iy as f64 - ym);
                square += r * r;
            }
        }
        let mean_square = |pairs: usize, sum: f64| if pairs > 0 { sum / pairs as f64 } else { 0.0 };
        let (mut gx, mut gy) = (0.0, 0.0);
        for iy in 0..ny {
            for ix in 0..nx {
                if ix + 1 < nx {
                    gx += ((at(ix + 1, iy) - at(ix, iy)) / pixel).powi(2);
                }
                if iy + 1 < ny {
                    gy += ((at(ix, iy + 1) - at(ix, iy)) / pixel).powi(2);
                }
            }
        }
        HeightStatistics {
            rms_height: (square / n).sqrt(),
            rms_slope: (mean_square((nx - 1) * ny, gx) + mean_square(nx * (ny - 1), gy)).sqrt(),
            spacing: pixel,
        }
    }

    /// Of a line trace of `heights` \[m\] at spacing `spacing` \[m\]: the rms about the
    /// least-squares line, and `⟨(Δz/Δx)²⟩^{1/2}`.
    pub fn of_trace(spacing: f64, heights: &[f64]) -> Self {
        let mut stats = Self::of_map(heights.len(), 1, spacing, heights);
        stats.spacing = spacing;
        stats
    }

    /// Whether the heights are implausible for their spacing: rms slope above
    /// [`MAX_RMS_SLOPE`] or rms height at or above [`MAX_RMS_HEIGHT`].
    pub fn implausible(&self) -> bool {
        self.rms_slope > MAX_RMS_SLOPE || self.rms_height >= MAX_RMS_HEIGHT
    }

    /// The likely unit slip of implausible heights: the smallest factor of 10⁻³, 10⁻⁶ and 10⁻⁹
    /// that makes them plausible (heights in mm, µm or nm read as m); `None` when they are
    /// plausible, or when no factor does (then the pixel is the likelier slip).
    pub fn likely_factor(&self) -> Option<f64> {
        if !self.implausible() {
            return None;
        }
        [1e-3, 1e-6, 1e-9].into_iter().find(|f| {
            let scaled = HeightStatistics {
                rms_height: self.rms_height * f,
                rms_slope: self.rms_slope * f,
                spacing: self.spacing,
            };
            !scaled.implausible()
        })
    }

    /// The warning for implausible heights given in the unit `given` (m per unit of the
    /// heights as read: 1 for m, 1e-6 for µm; `None`: not known here, e.g. a trace's units
    /// row), without the fix's key: `heights look like µm read as m: rms 5.0e-1 m over 5.0e-7 m
    /// samples (rms slope …)`, and the unit the heights likely are in (`"um"`), `None` where no
    /// unit slip explains them. `None` altogether for plausible heights.
    pub fn warning(&self, given: Option<f64>) -> Option<(String, Option<&'static str>)> {
        if !self.implausible() {
            return None;
        }
        let what = format!(
            "rms {} m over {} m samples (rms slope {} at the sample spacing; plausible: below {} \
             and below {} m rms)",
            short(self.rms_height),
            short(self.spacing),
            short(self.rms_slope),
            short(MAX_RMS_SLOPE),
            short(MAX_RMS_HEIGHT),
        );
        let factor = self.likely_factor();
        let likely = factor.zip(given).and_then(|(f, g)| unit_name(g * f));
        Some(match (likely, given.and_then(unit_name), factor) {
            (None, None, Some(f)) if given.is_none() => (
                format!(
                    "heights look {} times too large for their unit (e.g. µm values under a unit \
                     of m): {what}",
                    short(1.0 / f)
                ),
                None,
            ),
            (Some(unit), Some(read), _) => (
                format!(
                    "heights look like {} read as {}: {what}",
                    pretty(unit),
                    pretty(read)
                ),
                Some(unit),
            ),
            _ => (
                format!(
                    "heights implausible for their spacing: {what}; check the height unit and \
                     the pixel size (a pixel too small by 10³ or more gives the same slopes)"
                ),
                None,
            ),
        })
    }
}

/// The unit string of a length `factor` \[m\] (`1e-6` → `"um"`), for the units the check names.
fn unit_name(factor: f64) -> Option<&'static str> {
    [
        (1.0, "m"),
        (1e-3, "mm"),
        (1e-6, "um"),
        (1e-9, "nm"),
        (1e-12, "pm"),
    ]
    .into_iter()
    .find(|(f, _)| (factor / f - 1.0).abs() < 1e-9)
    .map(|(_, name)| name)
}

/// `um` as the reader writes it.
fn pretty(unit: &str) -> &str {
    if unit == "um" { "µm" } else { unit }
}

/// Two significant figures in scientific form (`3.9e-1`).
fn short(value: f64) -> String {
    format!("{value:.1e}")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid `amplitude cos(2π (x − x̄) / wavelength)` along x, even about the centre x̄ (so
    /// the best-fit plane is flat: on whole periods its mean and tilt vanish): rms
    /// amplitude/√2, rms slope 2π amplitude/(wavelength √2) (continuous values; first
    /// differences are within 0.1 % at 64 samples a wavelength).
    fn sine(n: usize, pixel: f64, amplitude: f64, wavelength: f64) -> Vec<f64> {
        let centre = (n as f64 - 1.0) / 2.0;
        (0..n * n)
            .map(|i| {
                let x = ((i % n) as f64 - centre) * pixel;
                amplitude * (2.0 * std::f64::consts::PI * x / wavelength).cos()
            })
            .collect()
    }

    #[test]
    fn statistics_of_a_sine_are_its_closed_forms() {
        let (n, pixel, a, w) = (256, 1e-6, 1e-6, 64e-6);
        let s = HeightStatistics::of_map(n, n, pixel, &sine(n, pixel, a, w));
        let rms = a / 2f64.sqrt();
        let slope = 2.0 * std::f64::consts::PI * a / (w * 2f64.sqrt());
        // four whole periods: the plane fit removes (almost) nothing
        assert!((s.rms_height / rms - 1.0).abs() < 0.01, "{s:?}");
        assert!((s.rms_slope / slope - 1.0).abs() < 0.01, "{s:?}");
        assert!(!s.implausible());
        assert_eq!(s.warning(Some(1.0)), None);
    }

    #[test]
    fn a_tilt_is_not_roughness_but_its_slope_counts() {
        // a plane tilted 1e-3: rms height about the plane 0, slope 1e-3
        let n = 32;
        let heights: Vec<f64> = (0..n * n).map(|i| 1e-3 * (i % n) as f64 * 1e-5).collect();
        let s = HeightStatistics::of_map(n, n, 1e-5, &heights);
        assert!(s.rms_height < 1e-15, "{s:?}");
        assert!((s.rms_slope - 1e-3).abs() < 1e-12, "{s:?}");
    }

    #[test]
    fn micrometres_read_as_metres_are_named() {
        // the review's repro: a 0.5 µm rms map at 0.5 µm pixels, its heights written in µm
        let (n, pixel) = (128, 0.5e-6);
        let metres = sine(n, pixel, 0.5e-6 * 2f64.sqrt(), 32e-6);
        let good = HeightStatistics::of_map(n, n, pixel, &metres);
        assert!(!good.implausible(), "{good:?}");
        let as_um: Vec<f64> = metres.iter().map(|z| z * 1e6).collect();
        let slipped = HeightStatistics::of_map(n, n, pixel, &as_um);
        assert!(slipped.implausible());
        assert_eq!(slipped.likely_factor(), Some(1e-6));
        let (text, unit) = slipped.warning(Some(1.0)).unwrap();
        assert!(
            text.starts_with("heights look like µm read as m: rms 5.0e-1 m"),
            "{text}"
        );
        assert_eq!(unit, Some("um"));
        // the unit named is relative to the one read: a file in mm whose heights are nm
        let as_mm = HeightStatistics::of_map(n, n, pixel, &as_um);
        let (text, unit) = as_mm.warning(Some(1e-3)).unwrap();
        assert!(
            text.starts_with("heights look like nm read as mm"),
            "{text}"
        );
        assert_eq!(unit, Some("nm"));
    }

    #[test]
    fn millimetres_read_as_metres_and_the_bounds() {
        // 1 µm rms, slope 0.1: ×1e3 gives 1 mm rms (at the bound) and slope 100
        let (n, pixel) = (64, 1e-6);
        let amplitude = 1e-6 * 2f64.sqrt();
        let wavelength = 2.0 * std::f64::consts::PI * amplitude / (0.1 * 2f64.sqrt());
        let z: Vec<f64> = sine(n, pixel, amplitude * 1e3, wavelength);
        let s = HeightStatistics::of_map(n, n, pixel, &z);
        assert_eq!(s.likely_factor(), Some(1e-3), "{s:?}");
        // just inside both bounds: plausible
        let inside = HeightStatistics {
            rms_height: 0.99e-3,
            rms_slope: 9.9,
            spacing: 1e-6,
        };
        assert!(!inside.implausible());
        assert!(
            HeightStatistics {
                rms_slope: 10.1,
                ..inside
            }
            .implausible()
        );
        assert!(
            HeightStatistics {
                rms_height: 1e-3,
                ..inside
            }
            .implausible()
        );
    }

    #[test]
    fn a_pixel_slip_is_not_blamed_on_the_heights() {
        // plausible heights, slope 1e12 (a pixel 1e12 too small): no unit of the heights fits
        let s = HeightStatistics {
            rms_height: 1e-6,
            rms_slope: 1e12,
            spacing: 1e-18,
        };
        assert_eq!(s.likely_factor(), None);
        let (text, unit) = s.warning(Some(1.0)).unwrap();
        assert!(
            text.starts_with("heights implausible for their spacing"),
            "{text}"
        );
        assert!(text.contains("pixel size"), "{text}");
        assert_eq!(unit, None);
    }

    #[test]
    fn an_unknown_unit_is_named_by_its_factor() {
        let s = HeightStatistics {
            rms_height: 0.5,
            rms_slope: 3e5,
            spacing: 1e-6,
        };
        let (text, unit) = s.warning(None).unwrap();
        assert!(
            text.starts_with("heights look 1.0e6 times too large"),
            "{text}"
        );
        assert_eq!(unit, None);
    }

    #[test]
    fn a_trace_is_a_one_row_map() {
        let z: Vec<f64> = (0..1000)
            .map(|i| if i % 2 == 0 { 1e-6 } else { -1e-6 })
            .collect();
        let s = HeightStatistics::of_trace(1e-6, &z);
        assert!((s.rms_height - 1e-6).abs() < 1e-9, "{s:?}");
        assert!((s.rms_slope - 2.0).abs() < 1e-12, "{s:?}");
        assert_eq!(s.spacing, 1e-6);
    }
}
