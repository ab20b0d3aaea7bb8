//! The surface data files a scenario or `sealsim surface` reads: PSD files and height maps
//! (CSV grids and Gwyddion `.gsf` files), each read into SI model types.

use super::text::{DataFileError, read};
use super::{gsf, height_map, psd};
use std::path::Path;

/// The spectrum of a PSD file (CSV of `q [1/m], C [m⁴]`, the format of `[surface] psd_file`),
/// interpolated as a piecewise power law.
pub fn read_psd_file(path: &Path) -> Result<crate::surface::Spectrum, DataFileError> {
    let error = |line: Option<usize>, message: String| DataFileError {
        path: path.to_path_buf(),
        line,
        message,
    };
    let text = read(path).map_err(|e| error(None, e.to_string()))?;
    let (q, c) = psd::parse(&text).map_err(|e| error(e.line, e.message))?;
    let spectrum =
        crate::surface::Spectrum::tabulated(&q, &c).map_err(|e| error(None, e.to_string()))?;
    // moments that overflow (a C(q) of 1e308 …) make every later number infinite, as a
    // scenario's psd_file refuses them (`sealsim surface` once printed "Ra inf µm")
    match implausible_spectrum(spectrum.rms_roughness(), spectrum.rms_slope()) {
        Some(why) => Err(error(None, why)),
        None => Ok(spectrum),
    }
}

/// Largest rms slope a PSD file may give: 100 (a surface at 89.4°). The small-slope contact
/// theory is stretched above 0.5 (a warning); a slope of 1e11 is a C(q) in the wrong unit, and
/// was accepted. An engineering bound (assumed), chosen wide.
pub const MAX_RMS_SLOPE: f64 = 100.0;

/// Why a tabulated spectrum's moments are refused (`None`: they are not): not finite (a C(q)
/// of 1e308 …), an h_rms beyond [`super::MAX_HEIGHT`] (10 mm, the height maps' bound) or an rms
/// slope beyond [`MAX_RMS_SLOPE`]; each the likely unit slip of C(q).
pub(crate) fn implausible_spectrum(h_rms: f64, slope: f64) -> Option<String> {
    let (h, s) = (crate::units::show(h_rms), crate::units::show(slope));
    if !(h_rms.is_finite() && slope.is_finite()) {
        return Some(format!(
            "the spectrum's moments overflow (h_rms = {h} m, rms slope = {s}): check the values \
             and the units of C(q)"
        ));
    }
    if h_rms > super::MAX_HEIGHT || slope > MAX_RMS_SLOPE {
        return Some(format!(
            "the spectrum gives h_rms = {h} m and rms slope = {s}, beyond a seal surface's \
             (h_rms ≤ {} m, slope ≤ {}): check the units of q and C(q) (C in m⁴, q in 1/m)",
            crate::units::show(super::MAX_HEIGHT),
            crate::units::show(MAX_RMS_SLOPE)
        ));
    }
    None
}

/// Whether `path` names a Gwyddion Simple Field file (extension `.gsf`, any case).
pub fn is_gsf(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("gsf"))
}

/// A height map file as a [`crate::numerical::Topography`] (SI units): a `.gsf` file
/// ([`gsf`], self-describing; `pixel` must then be `None` and `unit` 1) or a CSV grid
/// (`height_map` format, heights times `unit`, spacing `pixel`, which is then required).
pub fn read_height_map(
    path: &Path,
    pixel: Option<f64>,
    unit: f64,
) -> Result<crate::numerical::Topography, DataFileError> {
    let error = |line: Option<usize>, message: String| DataFileError {
        path: path.to_path_buf(),
        line,
        message,
    };
    if is_gsf(path) {
        let bytes =
            std::fs::read(path).map_err(|e| error(None, format!("cannot read the file: {e}")))?;
        return gsf::parse(&bytes).map_err(|e| error(e.line, e.message));
    }
    let Some(pixel) = pixel else {
        return Err(error(
            None,
            "a CSV height grid needs its pixel size (the spacing of the samples)".into(),
        ));
    };
    let text = read(path).map_err(|e| error(None, e.to_string()))?;
    parse_height_map(&text, path, pixel, unit)
}

/// A CSV height grid's `text` (`height_map` format: one row of heights per line, times
/// `unit`) as a [`crate::numerical::Topography`] of spacing `pixel` \[m\]; `path` only
/// names the grid in errors.
pub fn parse_height_map(
    text: &str,
    path: &Path,
    pixel: f64,
    unit: f64,
) -> Result<crate::numerical::Topography, DataFileError> {
    let (nx, ny, heights) = height_map::parse(text, unit).map_err(|e| DataFileError {
        path: path.to_path_buf(),
        line: e.line,
        message: e.message,
    })?;
    Ok(crate::numerical::Topography {
        nx,
        ny,
        pixel,
        heights,
    })
}
