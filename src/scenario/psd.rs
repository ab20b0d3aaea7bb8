//! Tabulated power spectra: a CSV file of `q [1/m], C [m⁴]` rows.
//!
//! Format: two comma-separated columns per row; blank lines and lines starting with `#` are
//! ignored; the first row is a header that names the units (`q [1/m],C [m^4]`, parentheses or
//! the suffixes `q_per_m,C_m4` too) or is followed by a units row (`1/m,m^4`) — a file without
//! units is refused at its line; at least two data rows; `q` strictly increasing and positive;
//! `C` positive. Parsed by hand (the format is
//! tiny) so that every error names the real line of the file.

use crate::units::show;

/// A malformed PSD file: what is wrong and, when it is on one row, the 1-based line.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct PsdError {
    pub line: Option<usize>,
    pub message: String,
}

impl PsdError {
    fn at(line: usize, message: String) -> Self {
        PsdError {
            line: Some(line),
            message,
        }
    }
}

/// The unit a PSD header cell names: `q [1/m]` (in brackets or parentheses), or the suffix
/// forms `q_per_m`, `C_m4`.
fn header_unit(cell: &str) -> Option<String> {
    let cell = cell.trim();
    for (open, close) in [('[', ']'), ('(', ')')] {
        if let (Some(a), Some(b)) = (cell.find(open), cell.rfind(close))
            && b > a
        {
            return Some(cell[a + 1..b].trim().to_owned());
        }
    }
    let lower = cell.to_ascii_lowercase();
    if lower.ends_with("_per_m") {
        return Some("1/m".into());
    }
    if lower.ends_with("_m4") {
        return Some("m^4".into());
    }
    None
}

/// The SI factors of the q and C columns from their units (`1/m`-like and `m^4`-like).
fn column_factors(units: [&str; 2], line: usize) -> Result<(f64, f64), PsdError> {
    let factor = |unit: &str, want: crate::units::Dimension, name: &str| {
        match crate::units::parse_unit(unit) {
            Ok((f, d)) if d == want => Ok(f),
            Ok((_, d)) => Err(PsdError::at(
                line,
                format!(
                    "{name}: unit {unit:?} is {}, expected {}",
                    d.describe(),
                    want.describe()
                ),
            )),
            Err(e) => Err(PsdError::at(line, format!("{name}: unit {unit:?}: {e}"))),
        }
    };
    Ok((
        factor(units[0], crate::units::Dimension::WAVEVECTOR, "q")?,
        factor(units[1], crate::units::Dimension::SPECTRUM, "C")?,
    ))
}

/// The `(q, C)` columns of a PSD file's text, checked as described in the module docs.
pub(super) fn parse(text: &str) -> Result<(Vec<f64>, Vec<f64>), PsdError> {
    let mut q: Vec<f64> = Vec::new();
    let mut c: Vec<f64> = Vec::new();
    let mut rows = super::text::data_lines(text).peekable();
    // the header (and a units row, unless the header names them): a bare q could be 1/m or
    // 1/µm, a bare C m⁴ or µm⁴
    let Some((line, header)) = rows.next() else {
        return Err(PsdError {
            line: None,
            message: "empty file: expected a header `q [1/m],C [m^4]` and data rows".into(),
        });
    };
    let cells: Vec<&str> = header.split(',').map(str::trim).collect();
    if cells.iter().any(|cell| cell.parse::<f64>().is_ok()) || cells.len() != 2 {
        return Err(PsdError::at(
            line,
            "no header with units: the first row must be `q [1/m],C [m^4]` (or `q,C` then a \
             units row `1/m,m^4`)"
                .into(),
        ));
    }
    let (fq, fc) = match (header_unit(cells[0]), header_unit(cells[1])) {
        (Some(uq), Some(uc)) => column_factors([&uq, &uc], line)?,
        _ => match rows.next() {
            Some((units_line, row)) => {
                let units: Vec<&str> = row.split(',').map(str::trim).collect();
                match units[..] {
                    [uq, uc] if uq.parse::<f64>().is_err() => column_factors([uq, uc], units_line)?,
                    _ => {
                        return Err(PsdError::at(
                            units_line,
                            "no units: name them in the header, `q [1/m],C [m^4]`, or in a \
                             units row after it, `1/m,m^4`"
                                .into(),
                        ));
                    }
                }
            }
            None => {
                return Err(PsdError::at(
                    line,
                    "no units row and no data after the header".into(),
                ));
            }
        },
    };
    for (line, row) in rows {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        let [q_cell, c_cell] = cells[..] else {
            return Err(PsdError::at(
                line,
                format!(
                    "expected 2 comma-separated columns (q [1/m], C [m^4]), found {}",
                    cells.len()
                ),
            ));
        };
        let qi = number(q_cell, "q", line)? * fq;
        let ci = number(c_cell, "C", line)? * fc;
        if qi <= 0.0 {
            return Err(PsdError::at(
                line,
                format!("q must be positive, got {}", show(qi)),
            ));
        }
        if ci <= 0.0 {
            return Err(PsdError::at(
                line,
                format!("C must be positive, got {}", show(ci)),
            ));
        }
        if let Some(&prev) = q.last()
            && qi <= prev
        {
            return Err(PsdError::at(
                line,
                format!(
                    "q must increase strictly from row to row, got {} after {}",
                    show(qi),
                    show(prev)
                ),
            ));
        }
        q.push(qi);
        c.push(ci);
    }
    if q.len() < 2 {
        return Err(PsdError {
            line: None,
            message: format!("a PSD needs at least 2 data rows (q, C), found {}", q.len()),
        });
    }
    Ok((q, c))
}

/// A finite number from one cell.
fn number(cell: &str, column: &str, line: usize) -> Result<f64, PsdError> {
    match cell.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) => Err(PsdError::at(
            line,
            format!("{column} must be finite, got {}", show(v)),
        )),
        Err(_) => Err(PsdError::at(
            line,
            format!("{column} is not a number: {cell:?}"),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_comments_and_blank_lines_are_skipped() {
        let (q, c) =
            parse("# synthetic\nq [1/m], C [m^4]\n\n1e4, 1e-20\n# mid\n1e5,1e-23\n").unwrap();
        assert_eq!(q, [1e4, 1e5]);
        assert_eq!(c, [1e-20, 1e-23]);
    }

    #[test]
    fn units_come_from_the_header_or_a_units_row() {
        // µm⁻¹ and µm⁴: 1e4 1/µm = 1e10 1/m, 1e6 µm⁴ = 1e-18 m⁴
        let (q, c) = parse("q,C\n1/um,um^4\n1,1e6\n2,1e5\n").unwrap();
        assert_eq!(q, [1e6, 2e6]);
        assert!((c[0] - 1e-18).abs() < 1e-30 && (c[1] - 1e-19).abs() < 1e-31);
        let (q, _) = parse("q_per_m,C_m4\n1e4,1e-20\n1e5,1e-23\n").unwrap();
        assert_eq!(q, [1e4, 1e5]);
        // none: refused at the header, with a fix that is accepted
        let e = parse("1e4,1e-20\n1e5,1e-23\n").unwrap_err();
        assert_eq!(e.line, Some(1));
        assert!(e.message.contains("q [1/m],C [m^4]"), "{e:?}");
        assert!(parse("q [1/m],C [m^4]\n1e4,1e-20\n1e5,1e-23\n").is_ok());
        // a unit of the wrong dimension
        let e = parse("q [m],C [m^4]\n1e4,1e-20\n1e5,1e-23\n").unwrap_err();
        assert!(e.message.contains("expected wavevector"), "{e:?}");
    }

    #[test]
    fn errors_name_the_real_line() {
        let h = "q [1/m],C [m^4]\n";
        let err = |text: &str| parse(&format!("{h}{text}")).unwrap_err();
        assert_eq!(err("# c\n1e4,1e-20\n2e4,abc\n").line, Some(4));
        assert_eq!(err("1e4,1e-20\n# c\n\n1e3,1e-21\n").line, Some(5));
        assert_eq!(err("1e4,1e-20\n2e4,-1\n").line, Some(3));
        assert_eq!(err("1e4,1e-20\n2e4,1,3\n").line, Some(3));
        assert_eq!(err("0,1e-20\n2e4,1\n").line, Some(2));
        assert_eq!(err("1e4,1e-20\n2e4,inf\n").line, Some(3));
        assert_eq!(err("1e4,1e-20\n").line, None);
        // a non-numeric row after the header is an error
        assert_eq!(err("1e4,1e-20\nq,C\n").line, Some(3));
    }
}
