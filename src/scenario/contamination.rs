//! `[contamination]` → [`Contamination`] (docs/model.md §7), and `[simulation] clogging_tolerance`.
//!
//! Keys: `number_concentration` (1/m³) XOR `volume_fraction` (dimensionless; then
//! n_p = φ / E\[π d³/6\] from the size distribution), `size_distribution` (an inline table with
//! `kind` = `monodisperse` (`diameter`), `lognormal` (`median`, `geometric_std` > 1),
//! `weibull` (`scale`, `shape` > 0) or `table` (`file`, a CSV of d and cumulative F)),
//! `capture` (`"straining"`, the default, or `"sieving"`, its sharp limit) and `reroute`
//! (default true).

use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::raw::{Quantity, RawContamination, RawSimulation, RawSizeDistribution};
use crate::clogging::{CaptureLaw, Contamination, DEFAULT_TOLERANCE, SizeDistribution};
use crate::units::{self, Dimension, show};
use toml::Spanned;

pub(super) const NUMBER_CONCENTRATION: Field = field(
    "contamination.number_concentration",
    Dimension::NUMBER_DENSITY,
    "1/m^3",
    Bound::Range(0.0, 1e30),
);
pub(super) const VOLUME_FRACTION: Field = field(
    "contamination.volume_fraction",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(0.0, 1.0),
);
pub(super) const DIAMETER: Field = field(
    "contamination.size_distribution.diameter",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 1e-2),
);
pub(super) const MEDIAN: Field = field(
    "contamination.size_distribution.median",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 1e-2),
);
pub(super) const GEOMETRIC_STD: Field = field(
    "contamination.size_distribution.geometric_std",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(1e-3, 1e2),
);
pub(super) const SCALE: Field = field(
    "contamination.size_distribution.scale",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 1e-2),
);
pub(super) const SHAPE: Field = field(
    "contamination.size_distribution.shape",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(1e-2, 1e2),
);
pub(super) const CLOGGING_TOLERANCE: Field = field(
    "simulation.clogging_tolerance",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 0.1),
);
const SIZE_KEY: &str = "contamination.size_distribution";

impl Source<'_> {
    /// `[simulation] clogging_tolerance` (default [`DEFAULT_TOLERANCE`]).
    pub(super) fn clogging_tolerance(
        &self,
        table: Option<&Spanned<RawSimulation>>,
    ) -> Result<f64, ScenarioError> {
        let raw = table.and_then(|t| t.get_ref().clogging_tolerance.as_ref());
        Ok(self
            .optional(raw, &CLOGGING_TOLERANCE)?
            .unwrap_or(DEFAULT_TOLERANCE))
    }

    /// `[contamination]` (absent: clean fluid, no clogging).
    pub(super) fn contamination(
        &self,
        table: Option<&Spanned<RawContamination>>,
        tolerance: f64,
    ) -> Result<Option<Contamination>, ScenarioError> {
        let Some(table) = table else {
            return Ok(None);
        };
        let raw = table.get_ref();
        let capture = match raw.capture.as_ref().map(|c| c.get_ref().as_str()) {
            None | Some("straining") => CaptureLaw::Straining,
            Some("sieving") => CaptureLaw::Sieving,
            Some(other) => {
                let span = raw.capture.as_ref().map_or(table.span(), |c| c.span());
                return Err(self.error(
                    span,
                    "contamination.capture",
                    format!(
                        "must be \"straining\" (the default: capture continuous in particle \
                         size, through the constrictions of every octave) or \"sieving\" (its \
                         sharp limit: u_c < d ≤ d_reach block), got {other:?}"
                    ),
                ));
            }
        };
        let Some(sizes) = &raw.size_distribution else {
            return Err(self.error(
                table.span(),
                SIZE_KEY,
                concat!(
                    "missing key `size_distribution` in [contamination], e.g. ",
                    "{ kind = \"lognormal\", median = \"1 um\", geometric_std = 1.8 }",
                ),
            ));
        };
        let size_distribution = self.size_distribution(sizes)?;
        let number_concentration = match (&raw.number_concentration, &raw.volume_fraction) {
            (Some(n), None) => self.quantity(n, &NUMBER_CONCENTRATION)?,
            (None, Some(phi)) => {
                let phi = self.quantity(phi, &VOLUME_FRACTION)?;
                phi / size_distribution.mean_volume()
            }
            (Some(_), Some(phi)) => {
                return Err(self.error(
                    phi.span(),
                    VOLUME_FRACTION.key,
                    "number_concentration and volume_fraction are mutually exclusive; give one",
                ));
            }
            (None, None) => {
                return Err(self.error(
                    table.span(),
                    NUMBER_CONCENTRATION.key,
                    "missing key: [contamination] needs number_concentration (e.g. \"1e12 \
                     1/m^3\") or volume_fraction (e.g. 1e-6)",
                ));
            }
        };
        if !number_concentration.is_finite() {
            return Err(self.error(
                table.span(),
                NUMBER_CONCENTRATION.key,
                format!(
                    "the number concentration is not finite ({})",
                    show(number_concentration)
                ),
            ));
        }
        Ok(Some(Contamination {
            number_concentration,
            size_distribution,
            capture,
            reroute: raw.reroute.as_ref().is_none_or(|r| *r.get_ref()),
            tolerance,
        }))
    }

    fn size_distribution(
        &self,
        table: &Spanned<RawSizeDistribution>,
    ) -> Result<SizeDistribution, ScenarioError> {
        let raw = table.get_ref();
        let kind = raw.kind.get_ref().as_str();
        let keys: [(&Option<Quantity>, &str); 5] = [
            (&raw.diameter, "diameter"),
            (&raw.median, "median"),
            (&raw.geometric_std, "geometric_std"),
            (&raw.scale, "scale"),
            (&raw.shape, "shape"),
        ];
        let takes = |allowed: &[&str], description: &str| {
            for (present, key) in &keys {
                if let Some(q) = present
                    && !allowed.contains(key)
                {
                    return Err(self.error(
                        q.span(),
                        &format!("{SIZE_KEY}.{key}"),
                        format!("not a key of a {kind} distribution, which takes {description}"),
                    ));
                }
            }
            if let Some(file) = &raw.file
                && !allowed.contains(&"file")
            {
                return Err(self.error(
                    file.span(),
                    &format!("{SIZE_KEY}.file"),
                    format!("not a key of a {kind} distribution, which takes {description}"),
                ));
            }
            Ok(())
        };
        let why = format!("of a {kind} size distribution");
        let required = |q: &Option<Quantity>, f: &Field| self.required(q, f, table.span(), &why);
        match kind {
            "monodisperse" => {
                takes(&["diameter"], "diameter")?;
                Ok(SizeDistribution::Monodisperse {
                    diameter: required(&raw.diameter, &DIAMETER)?,
                })
            }
            "lognormal" => {
                takes(&["median", "geometric_std"], "median and geometric_std")?;
                let median = required(&raw.median, &MEDIAN)?;
                let geometric_std = required(&raw.geometric_std, &GEOMETRIC_STD)?;
                if geometric_std <= 1.0 {
                    let span = raw.geometric_std.as_ref().map_or(table.span(), |q| q.span());
                    return Err(self.error(
                        span,
                        GEOMETRIC_STD.key,
                        format!(
                            "must exceed 1 (σg = 1 is one size: use kind = \"monodisperse\"), got {}",
                            show(geometric_std)
                        ),
                    ));
                }
                Ok(SizeDistribution::LogNormal {
                    median,
                    geometric_std,
                })
            }
            "weibull" => {
                takes(&["scale", "shape"], "scale and shape")?;
                Ok(SizeDistribution::Weibull {
                    scale: required(&raw.scale, &SCALE)?,
                    shape: required(&raw.shape, &SHAPE)?,
                })
            }
            "table" => {
                takes(&["file"], "file")?;
                self.size_table(table)
            }
            other => Err(self.error(
                raw.kind.span(),
                &format!("{SIZE_KEY}.kind"),
                format!(
                    "must be \"monodisperse\", \"lognormal\", \"weibull\" or \"table\", got {other:?}"
                ),
            )),
        }
    }
    /// A table size distribution: `file`, a CSV of d, F (relative to the scenario's directory).
    fn size_table(
        &self,
        table: &Spanned<RawSizeDistribution>,
    ) -> Result<SizeDistribution, ScenarioError> {
        let raw = table.get_ref();
        let Some(file) = &raw.file else {
            return Err(self.error(
                table.span(),
                &format!("{SIZE_KEY}.file"),
                "missing key `file` of a table size distribution (a CSV of d, F)",
            ));
        };
        let path = self.relative_path(file.get_ref());
        let key = format!("{SIZE_KEY}.file");
        let text = std::fs::read_to_string(&path).map_err(|e| {
            self.error(
                file.span(),
                &key,
                format!("cannot read size table {}: {e}", path.display()),
            )
        })?;
        let (diameter, cdf) = parse_size_table(&text).map_err(|(line, message)| {
            let at = line.map_or(String::new(), |l| format!(":{l}"));
            self.error(
                file.span(),
                &key,
                format!("{}{at}: {message}", path.display()),
            )
        })?;
        Ok(SizeDistribution::Table { diameter, cdf })
    }
}

/// A malformed size table: the 1-based line (when the problem is on one row) and what is
/// wrong.
type TableError = (Option<usize>, String);

/// A size table: rows `d, F` (comma-separated; `#` comments and blank lines ignored) after a
/// header row (no number in it) and a units row whose first cell is the length unit of d
/// (`um`): required, as for every data file, since a bare `10` could be metres or micrometres. d strictly increasing and positive, F non-decreasing
/// within \[0, 1\] and reaching 1 at the last row ("not a CDF" otherwise).
fn parse_size_table(text: &str) -> Result<(Vec<f64>, Vec<f64>), TableError> {
    let mut d: Vec<f64> = Vec::new();
    let mut f: Vec<f64> = Vec::new();
    let mut scale = 1.0;
    let mut text_rows = 0;
    for (line, row) in super::text::data_lines(text) {
        let cells: Vec<&str> = row.split(',').map(str::trim).collect();
        if d.is_empty() && cells.iter().all(|c| c.parse::<f64>().is_err()) {
            text_rows += 1;
            if text_rows == 2 {
                // units row: the first cell is the diameter's length unit
                let unit = cells.first().copied().unwrap_or("");
                scale = units::parse_quantity(&format!("1 {unit}"), Dimension::LENGTH)
                    .map_err(|e| (Some(line), format!("diameter unit {unit:?}: {e}")))?;
            } else if text_rows > 2 {
                return Err((Some(line), "expected a data row (d, F)".into()));
            }
            continue;
        }
        if d.is_empty() && text_rows < 2 {
            return Err((
                Some(line),
                "no units row: start the table with a header and a units row, e.g. `d,F` then \
                 `um,` — without it a diameter of 10 could be metres or micrometres"
                    .into(),
            ));
        }
        let [dc, fc] = cells[..] else {
            return Err((
                Some(line),
                format!(
                    "expected 2 comma-separated columns (d, cumulative F), found {}",
                    cells.len()
                ),
            ));
        };
        let number = |cell: &str, name: &str| {
            cell.parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| (Some(line), format!("{name} is not a number: {cell:?}")))
        };
        let di = number(dc, "d")? * scale;
        let fi = number(fc, "F")?;
        if di <= 0.0 {
            return Err((Some(line), format!("d must be positive, got {}", show(di))));
        }
        if let Some(&prev) = d.last()
            && di <= prev
        {
            return Err((
                Some(line),
                format!(
                    "d must increase strictly from row to row, got {} after {}",
                    show(di),
                    show(prev)
                ),
            ));
        }
        if !(0.0..=1.0).contains(&fi) {
            return Err((
                Some(line),
                format!("not a CDF: F must lie between 0 and 1, got {}", show(fi)),
            ));
        }
        if let Some(&prev) = f.last()
            && fi < prev
        {
            return Err((
                Some(line),
                format!(
                    "not a CDF: F must not decrease, got {} after {}",
                    show(fi),
                    show(prev)
                ),
            ));
        }
        d.push(di);
        f.push(fi);
    }
    match f.last() {
        None => Err((None, "no data rows".into())),
        Some(&last) if last != 1.0 => Err((
            None,
            format!(
                "not a CDF: F must reach 1 at the last row, got {}",
                show(last)
            ),
        )),
        Some(_) => Ok((d, f)),
    }
}

#[cfg(test)]
mod tests {
    use super::parse_size_table;

    #[test]
    fn size_tables() {
        let (d, f) = parse_size_table("d,F\num,\n0.5,0\n1,0.5\n2,1\n").unwrap();
        assert_eq!(f, vec![0.0, 0.5, 1.0]);
        assert!((d[1] - 1e-6).abs() < 1e-18);
        let (d, _) = parse_size_table("# sizes\nd,F\nm,\n1e-6,0.2\n2e-6,1\n").unwrap();
        assert_eq!(d, vec![1e-6, 2e-6]);
        let e = parse_size_table("d,F\nm,\n1e-6,0.5\n2e-6,0.4\n3e-6,1\n").unwrap_err();
        assert_eq!(e.0, Some(4));
        assert!(e.1.contains("not a CDF"), "{}", e.1);
        let e = parse_size_table("d,F\nm,\n1e-6,0.5\n2e-6,0.9\n").unwrap_err();
        assert!(e.1.contains("must reach 1"), "{}", e.1);
        let e = parse_size_table("d,F\nm,\n1e-6,1.5\n").unwrap_err();
        assert!(e.1.contains("not a CDF"), "{}", e.1);
    }

    /// A table without its units row is refused at its first number (a size in µm read as
    /// metres would be a 10⁶× slip); an empty unit cell too.
    #[test]
    fn a_size_table_without_units_is_refused() {
        let e = parse_size_table("# sizes\n1e-6,0.2\n2e-6,1\n").unwrap_err();
        assert_eq!(e.0, Some(2));
        assert!(e.1.contains("no units row"), "{}", e.1);
        let e = parse_size_table("d,F\n1,0.2\n2,1\n").unwrap_err();
        assert!(e.1.contains("no units row"), "{}", e.1);
        let e = parse_size_table("d,F\n,\n1,0.2\n2,1\n").unwrap_err();
        assert_eq!(e.0, Some(2));
    }
}
