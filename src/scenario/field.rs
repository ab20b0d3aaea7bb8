//! A numeric key of the input and the one place where a written quantity becomes a checked SI
//! number: [`Field`] (key path, dimension, SI unit, allowed range) and
//! [`Source::quantity`]. Every table's module defines its keys as `Field`s; this module knows
//! none of them.

use super::error::{ScenarioError, Source};
use super::raw::{Quantity, RawQuantity};
use crate::units::{self, Dimension, show};
use std::ops::Range;

/// The values a key accepts (all of them also finite).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Bound {
    /// strictly inside (lo, hi)
    Open(f64, f64),
    /// inside \[lo, hi\]
    Closed(f64, f64),
    /// The plausible range \[lo, hi\] of a physical quantity (README "Ranges", docs/model.md §11.1): outside it
    /// the value is nonsense or overflows the model. A value ≤ 0 where `lo > 0` is reported as
    /// "must be positive", a negative one where `lo = 0` as "must not be negative"; anything
    /// else outside as "must lie in \[lo, hi\] unit".
    Range(f64, f64),
}

impl Bound {
    /// `None` if `v` is allowed, else what is wrong ("must …").
    fn violation(self, v: f64, unit: &str) -> Option<String> {
        let ok = v.is_finite()
            && match self {
                Bound::Open(lo, hi) => v > lo && v < hi,
                Bound::Closed(lo, hi) | Bound::Range(lo, hi) => (lo..=hi).contains(&v),
            };
        if ok {
            return None;
        }
        // the message only when there is one: validation runs per case in a study
        let got = if unit.is_empty() {
            show(v)
        } else {
            format!("{} {unit}", show(v))
        };
        Some(match self {
            _ if !v.is_finite() => format!("must be finite, got {got}"),
            // a fraction given as a percentage: say how to write one
            Bound::Open(lo, hi) if unit.is_empty() && hi == 1.0 && v > 1.0 && v < 100.0 => format!(
                "must lie strictly between {} and {}, got {got}: a fraction (write \"{got} %\" for \
                 a percentage)",
                show(lo),
                show(hi)
            ),
            Bound::Open(lo, hi) => format!(
                "must lie strictly between {} and {}, got {got}",
                show(lo),
                show(hi)
            ),
            Bound::Closed(lo, hi) => {
                format!("must lie between {} and {}, got {got}", show(lo), show(hi))
            }
            Bound::Range(lo, _) if lo > 0.0 && v <= 0.0 => format!("must be positive, got {got}"),
            Bound::Range(lo, _) if lo == 0.0 && v < 0.0 => {
                format!("must not be negative, got {got}")
            }
            Bound::Range(lo, hi) => {
                let unit = if unit.is_empty() {
                    String::new()
                } else {
                    format!(" {unit}")
                };
                format!("must lie in [{}, {}]{unit}, got {got}", show(lo), show(hi))
            }
        })
    }
}

/// One numeric key of the scenario file.
#[derive(Debug, Clone, Copy)]
pub(super) struct Field {
    /// Dotted key path, as printed in errors.
    pub(super) key: &'static str,
    dimension: Dimension,
    /// SI unit symbol, for messages ("" if dimensionless).
    unit: &'static str,
    bound: Bound,
}

impl Field {
    /// The quantity's dimension (what units it accepts).
    pub(super) fn dimension(&self) -> Dimension {
        self.dimension
    }

    /// SI unit symbol ("" if dimensionless).
    pub(super) fn unit(&self) -> &'static str {
        self.unit
    }

    /// The values it accepts.
    pub(super) fn bound(&self) -> Bound {
        self.bound
    }
}

pub(super) const fn field(
    key: &'static str,
    dimension: Dimension,
    unit: &'static str,
    bound: Bound,
) -> Field {
    Field {
        key,
        dimension,
        unit,
        bound,
    }
}

impl Source<'_> {
    /// A written quantity → a checked SI value: the unit must have the field's dimension and
    /// the value must lie in its range.
    pub(super) fn quantity(&self, raw: &Quantity, field: &Field) -> Result<f64, ScenarioError> {
        let value = match raw.get_ref() {
            // `210` for a pressure is 210 Pa to the parser and 210 bar to the engineer: a
            // dimensional key needs its unit (0 is 0 in every unit)
            RawQuantity::Number(v)
                if field.dimension != units::Dimension::DIMENSIONLESS && *v != 0.0 =>
            {
                return Err(self.error(raw.span(), field.key, field.dimension.bare_number_fix(*v)));
            }
            RawQuantity::Number(v) => *v,
            RawQuantity::Text(text) => units::parse_quantity(text, field.dimension)
                .map_err(|e| self.error(raw.span(), field.key, e.to_string()))?,
        };
        match field.bound.violation(value, field.unit) {
            Some(message) => Err(self.error(raw.span(), field.key, message)),
            None => Ok(value),
        }
    }

    /// [`Source::quantity`] for a key that must be present: when it is absent, an error at
    /// `table` (the span of its table) reading "missing key `name` {why}", `name` the key's last
    /// path component.
    pub(super) fn required(
        &self,
        raw: &Option<Quantity>,
        field: &Field,
        table: Range<usize>,
        why: &str,
    ) -> Result<f64, ScenarioError> {
        match raw {
            Some(q) => self.quantity(q, field),
            None => Err(self.error(
                table,
                field.key,
                format!(
                    "missing key `{}` {why}",
                    field.key.rsplit('.').next().unwrap_or(field.key)
                ),
            )),
        }
    }

    /// [`Source::quantity`] for a key that may be absent.
    pub(super) fn optional(
        &self,
        raw: Option<&Quantity>,
        field: &Field,
    ) -> Result<Option<f64>, ScenarioError> {
        raw.map(|q| self.quantity(q, field)).transpose()
    }
}
