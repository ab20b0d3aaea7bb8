//! Line-trace CSV files (`x, z`) → a [`Trace`] for [`crate::profile::analyse`].
//!
//! Format: a header row `x,z` (case-insensitive); a units row right after it, e.g. `mm,um`,
//! each cell a length unit of [`crate::units::parse_unit`] (required: a file without one is
//! refused at its line); then one `x, z` pair per line. Blank lines and lines starting with `#` are
//! ignored. Every error names `file:line`.
//!
//! Checks: every value finite; x strictly increasing; **uniform spacing**: every step
//! `x_{i+1} − x_i` must lie within [`SPACING_TOLERANCE`] (1 %) of the median step, else the file
//! is refused at the line where the step breaks (resampling is left to the instrument software:
//! a gap or a jump in x would otherwise be silently treated as uniform). A sampling jitter δ of
//! 1 % of the spacing changes the periodogram by the factor `exp(−(qδ)²)` ≥ 0.999 up to the
//! Nyquist wavevector, and the tolerance accepts x printed with ~4 significant digits per
//! spacing. At least [`crate::profile::MIN_POINTS`] (256) points: the default trusted band
//! `[8 · 2π/L, π/(4Δx)]` spans N/64, less than 0.6 decade below 256 points.

use crate::profile::{MIN_POINTS, Trace};
use crate::units::{Dimension, parse_unit};
use std::path::Path;

/// Largest relative deviation of a step from the median step.
pub const SPACING_TOLERANCE: f64 = 1e-2;

/// A malformed trace file: the one data-file error, [`DataFileError`](crate::scenario::DataFileError)
/// (`path:line: message`), under the name this module's callers know.
pub type TraceFileError = super::text::DataFileError;

/// Reads a trace file (module docs).
///
/// # Errors
/// If the file cannot be read or is malformed.
pub fn read_trace(path: &Path) -> Result<Trace, TraceFileError> {
    let text = std::fs::read_to_string(path).map_err(|e| TraceFileError {
        path: path.to_path_buf(),
        line: None,
        message: format!("cannot read: {e}"),
    })?;
    parse_trace(&text, path)
}

/// Parses a trace file's text (module docs); `path` only names the file in errors.
///
/// # Errors
/// If the text is malformed.
pub fn parse_trace(text: &str, path: &Path) -> Result<Trace, TraceFileError> {
    let err = |line: Option<usize>, message: String| TraceFileError {
        path: path.to_path_buf(),
        line,
        message,
    };
    let mut lines = super::text::data_lines(text).peekable();
    let Some((header_line, header)) = lines.next() else {
        return Err(err(None, "empty file: expected a header row `x,z`".into()));
    };
    let names: Vec<String> = header
        .split(',')
        .map(|c| c.trim().to_ascii_lowercase())
        .collect();
    if names != ["x", "z"] {
        return Err(err(
            Some(header_line),
            format!("expected the header row `x,z`, found {header:?}"),
        ));
    }
    let (mut fx, mut fz) = (1.0, 1.0);
    // the units row is required: a bare `0.8` height could be metres or micrometres
    let mut have_units = false;
    if let Some(&(line, row)) = lines.peek() {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        if cells.iter().any(|c| c.parse::<f64>().is_err()) {
            have_units = true;
            if cells.len() != 2 {
                return Err(err(
                    Some(line),
                    format!("units row: expected 2 units (x, z), found {}", cells.len()),
                ));
            }
            let mut factors = [0.0; 2];
            for (k, cell) in cells.iter().enumerate() {
                match parse_unit(cell) {
                    Ok((f, Dimension::LENGTH)) => factors[k] = f,
                    Ok((_, d)) => {
                        return Err(err(
                            Some(line),
                            format!(
                                "unit {cell:?} is a {}: x and z must be lengths",
                                d.describe()
                            ),
                        ));
                    }
                    Err(e) => {
                        return Err(err(Some(line), format!("unit {cell:?}: {e}")));
                    }
                }
            }
            (fx, fz) = (factors[0], factors[1]);
            lines.next();
        }
    }
    if !have_units {
        let line = lines.peek().map_or(header_line, |&(l, _)| l);
        return Err(err(
            Some(line),
            "no units row: add one after the header, e.g. `mm,um` (x in mm, z in µm) — without \
             it a height of 0.8 could be metres or micrometres"
                .into(),
        ));
    }
    let mut x = Vec::new();
    let mut z = Vec::new();
    let mut at = Vec::new();
    for (line, row) in lines {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        let [xc, zc] = cells[..] else {
            return Err(err(
                Some(line),
                format!("expected 2 columns (x, z), found {}", cells.len()),
            ));
        };
        let value = |cell: &str, name: &str, factor: f64| match cell.parse::<f64>() {
            Ok(v) if v.is_finite() && (v * factor).is_finite() => Ok(v * factor),
            Ok(v) => Err(err(Some(line), format!("{name} must be finite, got {v}"))),
            Err(_) => Err(err(Some(line), format!("{name} is not a number: {cell:?}"))),
        };
        let xi = value(xc, "x", fx)?;
        let zi = value(zc, "z", fz)?;
        if let Some(&prev) = x.last()
            && xi <= prev
        {
            return Err(err(
                Some(line),
                format!("x must increase strictly, got {xi} m after {prev} m"),
            ));
        }
        x.push(xi);
        z.push(zi);
        at.push(line);
    }
    if x.len() < MIN_POINTS {
        return Err(err(
            None,
            format!(
                "{} points; a trace needs at least {MIN_POINTS} (module docs)",
                x.len()
            ),
        ));
    }
    let mut steps: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let first_bad = steps.clone();
    steps.sort_by(f64::total_cmp);
    let median = steps[steps.len() / 2];
    if let Some(i) = first_bad
        .iter()
        .position(|s| (s / median - 1.0).abs() > SPACING_TOLERANCE)
    {
        return Err(err(
            Some(at[i + 1]),
            format!(
                "non-uniform spacing: the step to this point is {} m, the median step {} m \
                 (tolerance {} %); resample the trace uniformly",
                first_bad[i],
                median,
                SPACING_TOLERANCE * 100.0
            ),
        ));
    }
    let spacing = (x[x.len() - 1] - x[0]) / (x.len() - 1) as f64;
    Ok(Trace {
        spacing,
        heights: z,
    })
}
