//! Gwyddion Simple Field (`.gsf`) height maps: `surface.height_map = "map.gsf"` and
//! `sealsim surface map.gsf`.
//!
//! Format, as described in the Gwyddion user guide, "Simple Field Files"
//! (<http://gwyddion.net/documentation/user-guide-en/gsf.html>, read for this reader):
//! 1. the magic line `Gwyddion Simple Field 1.0` ended by a line feed;
//! 2. a text header of `name = value` lines (line feeds; whitespace around the name, the `=` and
//!    at the end of the value ignored; names case-sensitive; UTF-8, no NUL);
//! 3. one to four NUL bytes, so that the data start at a multiple of 4 bytes;
//! 4. the data, 32-bit floating-point values.
//!
//! Header fields used here: `XRes`, `YRes` (pixels per row and rows, mandatory), `XReal`,
//! `YReal` (physical width and height), `XYUnits`, `ZUnits` (unit strings of the lateral sizes
//! and of the values). The guide's field table was not fully visible where it was read; the
//! following is **recalled** from Gwyddion practice, not from the page: the values are
//! little-endian IEEE single precision, stored row by row (`XRes` values per row, `YRes` rows);
//! `XReal`/`YReal` default to 1 and the units to none (base SI). This reader is stricter than
//! the format:
//! * `XReal` and `YReal` are required (a pixel size of an unstated "1" would be a guess);
//! * the units default to metres and must be lengths (`m`, `um`, `µm`, `nm`, …);
//! * the pixels must be square (`XReal/XRes = YReal/YRes` within 1e-6, relative): the
//!   spectrum estimate and the numerical level assume one spacing;
//! * each side at least 8 pixels, at most `MAX_PIXELS` (8192²) in all, every value finite
//!   and within ±10 mm (`MAX_HEIGHT`; FLT_MAX is a no-data marker), and exactly
//!   `XRes · YRes` values after the padding (a short file is truncated, a longer one is
//!   refused too: it is not what the header says).
//!
//! The file gives the pixel size and the height unit, so a scenario's `pixel_size` and
//! `height_unit` are refused next to a `.gsf` map.

use super::height_map::{HeightMapError, MAX_PIXELS, MIN_SIZE, implausible_height};
use crate::numerical::Topography;
use crate::units::{Dimension, parse_unit, show};

/// The magic line (without its line feed).
pub const MAGIC: &str = "Gwyddion Simple Field 1.0";

fn whole(message: String) -> HeightMapError {
    HeightMapError {
        line: None,
        message,
    }
}

/// The height map of a `.gsf` file's bytes, heights and pixel in metres. Errors name the
/// header line (1-based, the magic line is line 1) when the fault is on one.
pub(super) fn parse(bytes: &[u8]) -> Result<Topography, HeightMapError> {
    let magic = format!("{MAGIC}\n");
    if !bytes.starts_with(magic.as_bytes()) {
        return Err(HeightMapError {
            line: Some(1),
            message: format!(
                "not a Gwyddion Simple Field file: the first line must be {MAGIC:?} followed \
                 by a line feed"
            ),
        });
    }
    let Some(nul) = bytes.iter().position(|&b| b == 0) else {
        return Err(whole(
            "no NUL padding after the header: the file is truncated or not a .gsf".into(),
        ));
    };
    let header = std::str::from_utf8(&bytes[magic.len()..nul])
        .map_err(|_| whole("the header is not UTF-8 text".into()))?;
    let mut fields: Vec<(usize, &str, &str)> = Vec::new();
    for (i, line) in header.split('\n').enumerate() {
        let number = i + 2;
        if line.trim().is_empty() {
            continue;
        }
        let Some((name, value)) = line.split_once('=') else {
            return Err(HeightMapError {
                line: Some(number),
                message: format!("header line {line:?} is not of the form name = value"),
            });
        };
        fields.push((number, name.trim(), value.trim()));
    }
    let get = |name: &str| fields.iter().find(|f| f.1 == name).copied();
    let count = |name: &str| -> Result<usize, HeightMapError> {
        let Some((line, _, value)) = get(name) else {
            return Err(whole(format!(
                "missing header field {name} (the number of {})",
                if name == "XRes" {
                    "pixels per row"
                } else {
                    "rows"
                }
            )));
        };
        match value.parse::<usize>() {
            Ok(v) if v >= MIN_SIZE => Ok(v),
            Ok(v) => Err(HeightMapError {
                line: Some(line),
                message: format!(
                    "{name} = {v}: a height map needs at least {MIN_SIZE} × {MIN_SIZE}"
                ),
            }),
            Err(_) => Err(HeightMapError {
                line: Some(line),
                message: format!("{name} must be a positive integer, got {value:?}"),
            }),
        }
    };
    let (nx, ny) = (count("XRes")?, count("YRes")?);
    // checked: a header whose XRes · YRes wraps once passed the size check and panicked
    let pixels = nx
        .checked_mul(ny)
        .filter(|&n| n <= MAX_PIXELS)
        .ok_or_else(|| {
            whole(format!(
                "XRes × YRes = {nx} × {ny} is more than {MAX_PIXELS} pixels (8192 × 8192), the \
             largest height map read: the header is corrupt, or crop or resample the map"
            ))
        })?;
    let unit = |name: &str| -> Result<f64, HeightMapError> {
        let Some((line, _, value)) = get(name) else {
            return Ok(1.0);
        };
        match parse_unit(value) {
            Ok((factor, dimension)) if dimension == Dimension::LENGTH => Ok(factor),
            _ => Err(HeightMapError {
                line: Some(line),
                message: format!("{name} must be a length unit such as m, um or nm, got {value:?}"),
            }),
        }
    };
    let (lateral, vertical) = (unit("XYUnits")?, unit("ZUnits")?);
    let real = |name: &str| -> Result<f64, HeightMapError> {
        let Some((line, _, value)) = get(name) else {
            return Err(whole(format!(
                "missing header field {name}: the physical size of the map is needed for its \
                 pixel size"
            )));
        };
        match value.parse::<f64>() {
            Ok(v) if v.is_finite() && v > 0.0 && (v * lateral).is_finite() => Ok(v * lateral),
            _ => Err(HeightMapError {
                line: Some(line),
                message: format!("{name} must be a positive number, got {value:?}"),
            }),
        }
    };
    let (x_real, y_real) = (real("XReal")?, real("YReal")?);
    let (px, py) = (x_real / nx as f64, y_real / ny as f64);
    if ((px - py) / px).abs() > 1e-6 {
        return Err(whole(format!(
            "non-square pixels: XReal/XRes = {} m but YReal/YRes = {} m; resample the map to \
             square pixels (e.g. in Gwyddion) before using it",
            show(px),
            show(py)
        )));
    }
    let start = (nul / 4 + 1) * 4;
    if bytes.len() < start || bytes[nul..start].iter().any(|&b| b != 0) {
        return Err(whole(format!(
            "the header must end with 1 to 4 NUL bytes up to byte {start} (a multiple of 4): \
             the file is truncated or corrupt"
        )));
    }
    let data = &bytes[start..];
    let expected = pixels * 4;
    if data.len() != expected {
        return Err(whole(format!(
            "XRes × YRes = {nx} × {ny} needs {expected} bytes of data after the header, found \
             {}: the file is {}",
            data.len(),
            if data.len() < expected {
                "truncated"
            } else {
                "longer than its header says"
            }
        )));
    }
    let mut heights = Vec::with_capacity(pixels);
    for (i, chunk) in data.chunks_exact(4).enumerate() {
        let v = f64::from(f32::from_le_bytes([chunk[0], chunk[1], chunk[2], chunk[3]]));
        if let Some(why) = implausible_height(v, vertical) {
            return Err(whole(format!(
                "value {} (row {}, column {}): {why}",
                i + 1,
                i / nx + 1,
                i % nx + 1
            )));
        }
        heights.push(v * vertical);
    }
    Ok(Topography {
        nx,
        ny,
        pixel: px,
        heights,
    })
}

/// The bytes of a `.gsf` file of `heights` (row-major, `nx` per row; written as f32 in the
/// unit `z_unit`, i.e. `h / factor(z_unit)`) over `x_real × y_real` metres: for tests and
/// examples.
pub fn write(nx: usize, ny: usize, x_real: f64, y_real: f64, heights: &[f64]) -> Vec<u8> {
    let mut out =
        format!("{MAGIC}\nXRes = {nx}\nYRes = {ny}\nXReal = {x_real:e}\nYReal = {y_real:e}\nXYUnits = m\nZUnits = m\n")
            .into_bytes();
    let pad = 4 - out.len() % 4;
    out.extend(std::iter::repeat_n(0u8, pad));
    for h in heights {
        #[expect(clippy::cast_possible_truncation, reason = "the format stores f32")]
        out.extend_from_slice(&(*h as f32).to_le_bytes());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn heights(nx: usize, ny: usize) -> Vec<f64> {
        (0..nx * ny)
            .map(|i| f64::from(f32::from_bits(0x3400_0000 + (i as u32 * 7919) % 100_000)))
            .collect()
    }

    /// The reliability review's D4 headers: `XRes · YRes · 4` wrapped to 0 and passed the size
    /// check, then panicked ("capacity overflow"; an index out of bounds in the PSD estimate).
    #[test]
    fn a_header_whose_size_wraps_is_refused_not_a_panic() {
        for (x, y, xr, yr) in [
            ("4294967296", "1073741824", "1e-3", "0.00025"),
            ("9223372036854775808", "9223372036854775808", "1", "1"),
        ] {
            let mut bytes =
                format!("{MAGIC}\nXRes = {x}\nYRes = {y}\nXReal = {xr}\nYReal = {yr}\n")
                    .into_bytes();
            let pad = 4 - bytes.len() % 4;
            bytes.extend(std::iter::repeat_n(0u8, pad));
            let e = parse(&bytes).expect_err("refused");
            assert!(e.message.contains("more than 67108864 pixels"), "{e:?}");
        }
    }

    /// FLT_MAX, a profilometer's no-data marker, and a height beyond 10 mm are refused (one
    /// 3.4e38 µm cell once made a life run take 105 s and leak 7.75e106 m³/s).
    #[test]
    fn a_no_data_cell_and_an_absurd_height_are_refused() {
        let mut h = heights(8, 8);
        h[9] = f64::from(f32::MAX);
        let e = parse(&write(8, 8, 8e-6, 8e-6, &h)).expect_err("refused");
        assert!(
            e.message.contains("row 2, column 2") && e.message.contains("no-data"),
            "{e:?}"
        );
        h[9] = 0.02; // 20 mm
        let e = parse(&write(8, 8, 8e-6, 8e-6, &h)).expect_err("refused");
        assert!(e.message.contains("height unit"), "{e:?}");
        h[9] = 0.009; // 9 mm: within the bound
        assert!(parse(&write(8, 8, 8e-6, 8e-6, &h)).is_ok());
    }

    #[test]
    fn round_trip_is_exact() {
        let h = heights(12, 10);
        let bytes = write(12, 10, 12e-6, 10e-6, &h);
        let map = parse(&bytes).unwrap();
        assert_eq!((map.nx, map.ny), (12, 10));
        assert!((map.pixel - 1e-6).abs() < 1e-18);
        assert_eq!(map.heights, h, "f32 values come back bit for bit");
    }

    #[test]
    fn units_and_padding() {
        // header length ≡ 0 (mod 4) needs four NULs; units scale sizes and heights
        let mut text = format!(
            "{MAGIC}\nXRes = 8\nYRes = 8\nXReal = 4\nYReal = 4\nXYUnits = um\nZUnits = nm\n"
        );
        while !text.len().is_multiple_of(4) {
            text.insert(text.len() - 1, ' ');
        }
        let mut bytes = text.into_bytes();
        bytes.extend([0u8; 4]);
        for _ in 0..64 {
            bytes.extend(2.0f32.to_le_bytes());
        }
        let map = parse(&bytes).unwrap();
        assert!((map.pixel - 0.5e-6).abs() < 1e-18);
        assert!((map.heights[5] - 2e-9).abs() < 1e-21);
    }

    #[test]
    fn bad_files_are_refused_with_the_reason() {
        let good = write(8, 8, 8e-6, 8e-6, &heights(8, 8));
        let msg = |b: &[u8]| parse(b).unwrap_err().message;
        assert!(msg(&good[..good.len() - 3]).contains("truncated"));
        let mut longer = good.clone();
        longer.extend([0u8; 4]);
        assert!(msg(&longer).contains("longer than its header"));
        let mut wrong = good.clone();
        wrong[0] = b'g';
        let e = parse(&wrong).unwrap_err();
        assert_eq!(e.line, Some(1));
        assert!(e.message.contains("not a Gwyddion Simple Field"));
        let text = String::from_utf8_lossy(&good).replace("XRes = 8\n", "");
        assert!(msg(text.as_bytes()).contains("missing header field XRes"));
        let text = String::from_utf8_lossy(&good).replace("YReal = 8e-6", "YReal = 9e-6");
        assert!(msg(text.as_bytes()).contains("non-square pixels"));
        let text = String::from_utf8_lossy(&good).replace("XRes = 8", "XRes = 4");
        let e = parse(text.as_bytes()).unwrap_err();
        assert_eq!(e.line, Some(2));
        assert!(e.message.contains("at least 8"));
        let text = String::from_utf8_lossy(&good).replace("ZUnits = m", "ZUnits = s");
        assert!(msg(text.as_bytes()).contains("ZUnits must be a length"));
        let text = String::from_utf8_lossy(&good).replace("XYUnits = m", "XYUnits m");
        assert!(msg(text.as_bytes()).contains("name = value"));
        let text = String::from_utf8_lossy(&good).replace("XReal = 8e-6\n", "");
        assert!(msg(text.as_bytes()).contains("missing header field XReal"));
    }
}
