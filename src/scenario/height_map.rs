//! Height maps: a CSV file of a rectangular grid of heights (`surface.height_map`; a `.gsf`
//! file is read by the `gsf` module).
//!
//! Format: one grid row per line (row `iy`, increasing y), comma-separated heights (column `ix`,
//! increasing x, the flow direction), in metres unless the scenario's `height_unit` says
//! otherwise. Blank lines and lines starting with `#` are ignored; no header row. The grid is
//! `nx × ny` (every row the same length), each side at least [`MIN_SIZE`], any parity: the PSD
//! estimate takes any size, and the numerical level runs on the largest centred even square
//! ([`crate::numerical::Topography::square_crop`]). Every cell a finite number. Parsed by hand
//! so that every error names the real line of the file.

use crate::units::show;

/// Smallest accepted grid side.
pub const MIN_SIZE: usize = 8;

/// Largest accepted grid, in pixels: 8192 × 8192 (2²⁶). A 4096² map takes about 55 bytes a
/// pixel (0.9 GB) and 3–4 s in `sealsim surface` (measured on a 2-core machine); this bound
/// keeps a map within a few GB and a corrupt header (`XRes · YRes` past any memory) from
/// allocating at all. An engineering bound (assumed), not a property of the theory.
pub const MAX_PIXELS: usize = 1 << 26;

/// Largest accepted height magnitude \[m\]: 10 mm. A seal face's roughness (µm) with its
/// form and tilt over a profilometer's field (mm) stays far below it; a height beyond it is a
/// unit slip (a map in µm read as metres) or a no-data marker, and an absurd height makes the
/// spectrum's moments, and the run time, explode (a 3.4e38 µm cell: 105 s and a leak of
/// 1e107 m³/s before this bound). Assumed, chosen wide (band: roughness 1e-9–1e-4 m).
pub const MAX_HEIGHT: f64 = 0.01;

/// A value at or beyond this magnitude, in the file's own unit, is read as an instrument's
/// no-data marker (single-precision FLT_MAX = 3.4028235e38, the common one, or 1e38).
pub const NO_DATA: f64 = 1e38;

/// Why a height `v` (in the file's unit, `unit` its SI factor) is refused, or `None`.
pub fn implausible_height(v: f64, unit: f64) -> Option<String> {
    if !v.is_finite() || !(v * unit).is_finite() {
        return Some(format!("the height must be finite, got {}", show(v)));
    }
    if v.abs() >= NO_DATA {
        return Some(format!(
            "height {} looks like an instrument's no-data marker (FLT_MAX = 3.4e38): fill or \
             crop the missing cells before using the map",
            show(v)
        ));
    }
    if (v * unit).abs() > MAX_HEIGHT {
        return Some(format!(
            "height {} = {} m is beyond ±{} m, not a seal surface's height: the likely slip \
             is the height unit (a map in µm or nm read as metres: set height_unit) or a \
             no-data marker",
            show(v),
            show(v * unit),
            show(MAX_HEIGHT)
        ));
    }
    None
}

/// A malformed height map: what is wrong and, when it is on one row, the 1-based line.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct HeightMapError {
    pub line: Option<usize>,
    pub message: String,
}

fn at(line: usize, message: String) -> HeightMapError {
    HeightMapError {
        line: Some(line),
        message,
    }
}

/// The grid of a height map file's text: `(nx, ny, heights)` with `heights[iy * nx + ix]` in
/// metres (each cell multiplied by `unit`, the SI factor of the file's height unit).
pub(super) fn parse(text: &str, unit: f64) -> Result<(usize, usize, Vec<f64>), HeightMapError> {
    let mut heights = Vec::new();
    // (line, column count) of the first row, and the line of every row.
    let mut first: Option<(usize, usize)> = None;
    let mut lines = Vec::new();
    for (line, row) in super::text::data_lines(text) {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        match first {
            None => first = Some((line, cells.len())),
            Some((first_line, columns)) if cells.len() != columns => {
                return Err(at(
                    line,
                    format!(
                        "ragged row: {} values, but the first row (line {first_line}) has \
                         {columns}; every row of the grid must have the same length",
                        cells.len()
                    ),
                ));
            }
            Some(_) => {}
        }
        if heights.len() + cells.len() > MAX_PIXELS {
            return Err(at(
                line,
                format!(
                    "the grid passes {MAX_PIXELS} values (8192 × 8192), the largest height map \
                     read: crop or resample it"
                ),
            ));
        }
        for (column, cell) in cells.iter().enumerate() {
            heights.push(height(cell, column + 1, line, unit)?);
        }
        lines.push(line);
    }
    let Some((first_line, columns)) = first else {
        return Err(HeightMapError {
            line: None,
            message: "no data rows: expected a grid of comma-separated heights".into(),
        });
    };
    let rows = lines.len();
    if columns < MIN_SIZE {
        return Err(at(
            first_line,
            format!(
                "{columns} value(s) per row: a height map needs at least {MIN_SIZE} × {MIN_SIZE}"
            ),
        ));
    }
    if rows < MIN_SIZE {
        return Err(at(
            lines[rows - 1],
            format!(
                "the grid ends after {rows} row(s): a height map needs at least {MIN_SIZE} rows \
                 of at least {MIN_SIZE} values"
            ),
        ));
    }
    Ok((columns, rows, heights))
}

/// A finite height (m) from one cell, within [`MAX_HEIGHT`].
fn height(cell: &str, column: usize, line: usize, unit: f64) -> Result<f64, HeightMapError> {
    match cell.parse::<f64>() {
        Ok(v) => match implausible_height(v, unit) {
            None => Ok(v * unit),
            Some(why) => Err(at(line, format!("column {column}: {why}"))),
        },
        Err(_) => Err(at(line, format!("column {column}: not a number: {cell:?}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n: usize) -> String {
        (0..n)
            .map(|iy| {
                (0..n)
                    .map(|ix| format!("{}e-7", ix + 2 * iy))
                    .collect::<Vec<_>>()
                    .join(", ")
                    + "\n"
            })
            .collect()
    }

    fn rect(nx: usize, ny: usize) -> String {
        (0..ny)
            .map(|iy| {
                (0..nx)
                    .map(|ix| format!("{}e-7", ix + 2 * iy))
                    .collect::<Vec<_>>()
                    .join(", ")
                    + "\n"
            })
            .collect()
    }

    #[test]
    fn rows_are_read_in_order_with_comments_and_units() {
        let text = format!("# a map\n\n{}", grid(8));
        let (nx, ny, h) = parse(&text, 1.0).unwrap();
        assert_eq!((nx, ny), (8, 8));
        assert_eq!(h[8 + 3], 5e-7);
        let (_, _, um) = parse(&text, 1e-6).unwrap();
        assert!((um[8 + 3] - 5e-13).abs() < 1e-25);
        // rectangular and odd sides are accepted
        let (nx, ny, h) = parse(&rect(12, 9), 1.0).unwrap();
        assert_eq!((nx, ny, h.len()), (12, 9, 108));
        assert_eq!(h[12 + 3], 5e-7);
    }

    #[test]
    fn errors_name_the_real_line() {
        let err = |text: &str| parse(text, 1.0).unwrap_err();
        let good = grid(8);
        let mut rows: Vec<String> = good.lines().map(str::to_owned).collect();
        rows[2] = rows[2].replacen("5e-7", "abc", 1);
        let e = err(&format!("# header\n{}", rows.join("\n")));
        assert_eq!(e.line, Some(4), "{e:?}");
        assert!(e.message.contains("not a number: \"abc\""), "{e:?}");

        let mut rows: Vec<String> = good.lines().map(str::to_owned).collect();
        rows[5].push_str(", 1");
        let e = err(&rows.join("\n"));
        assert_eq!(e.line, Some(6));
        assert!(e.message.contains("ragged row: 9 values"), "{e:?}");

        let e = err(&good.lines().take(7).collect::<Vec<_>>().join("\n"));
        assert_eq!(e.line, Some(7));
        assert!(e.message.contains("at least 8 rows"), "{e:?}");

        let e = err(&grid(6));
        assert_eq!(e.line, Some(1));
        assert!(e.message.contains("at least 8 × 8"), "{e:?}");

        let e = err(&good.replacen("0e-7,", "inf,", 1));
        assert_eq!(e.line, Some(1));
        assert!(e.message.contains("must be finite"), "{e:?}");
        assert_eq!(err("# only a comment\n").line, None);
    }
}
