//! Tabulated power spectra: a CSV file of `q [1/m], C [m⁴]` rows.
//!
//! Format: two comma-separated columns per row; blank lines and lines starting with `#` are
//! ignored; the first row may be a header (a row without any number in it); at least two data
//! rows; `q` strictly increasing and positive; `C` positive. Parsed by hand (the format is
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

/// The `(q, C)` columns of a PSD file's text, checked as described in the module docs.
pub(super) fn parse(text: &str) -> Result<(Vec<f64>, Vec<f64>), PsdError> {
    let mut q: Vec<f64> = Vec::new();
    let mut c: Vec<f64> = Vec::new();
    let mut first_row = true;
    for (line, row) in super::data_lines(text) {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        let is_header = first_row && cells.iter().all(|cell| cell.parse::<f64>().is_err());
        first_row = false;
        if is_header {
            continue;
        }
        let [q_cell, c_cell] = cells[..] else {
            return Err(PsdError::at(
                line,
                format!(
                    "expected 2 comma-separated columns (q [1/m], C [m^4]), found {}",
                    cells.len()
                ),
            ));
        };
        let qi = number(q_cell, "q", line)?;
        let ci = number(c_cell, "C", line)?;
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
    fn errors_name_the_real_line() {
        let err = |text: &str| parse(text).unwrap_err();
        assert_eq!(err("# c\n1e4,1e-20\n2e4,abc\n").line, Some(3));
        assert_eq!(err("1e4,1e-20\n# c\n\n1e3,1e-21\n").line, Some(4));
        assert_eq!(err("1e4,1e-20\n2e4,-1\n").line, Some(2));
        assert_eq!(err("1e4,1e-20\n2e4,1,3\n").line, Some(2));
        assert_eq!(err("0,1e-20\n2e4,1\n").line, Some(1));
        assert_eq!(err("1e4,1e-20\n2e4,inf\n").line, Some(2));
        assert_eq!(err("q,C\n1e4,1e-20\n").line, None);
        // a non-numeric row after the first is an error, not a header
        assert_eq!(err("1e4,1e-20\nq,C\n").line, Some(2));
    }
}
