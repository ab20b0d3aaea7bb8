//! `[motion]` → [`MotionSpec`]: a reciprocating (dynamic) seal, PY08 §8 ([`crate::dynamic`]).
//!
//! Keys: `sliding_speed` (constant sliding, ≥ 0) XOR `stroke` (a stroke cycle, > 0); a stroke
//! cycle takes `frequency` (> 0; then `out_speed = in_speed = 2 · stroke · frequency`) XOR both
//! `out_speed` and `in_speed` (> 0); `junction_position` (strictly between 0 and 1, default
//! ½) in either case. Every combination that does not fit is an error naming the key.

use super::error::{ScenarioError, Source};
use super::raw::RawMotion;
use super::validate::{Bound, Field, field};
use crate::dynamic::{Motion, MotionSpec};
use crate::units::{Dimension, show};
use toml::Spanned;

const SLIDING_SPEED: Field = field(
    "motion.sliding_speed",
    Dimension::VELOCITY,
    "m/s",
    Bound::Range(0.0, 100.0),
);
const STROKE: Field = field(
    "motion.stroke",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 10.0),
);
const FREQUENCY: Field = field(
    "motion.frequency",
    Dimension::FREQUENCY,
    "Hz",
    Bound::Range(1e-9, 1e6),
);
const OUT_SPEED: Field = field(
    "motion.out_speed",
    Dimension::VELOCITY,
    "m/s",
    Bound::Range(1e-9, 100.0),
);
const IN_SPEED: Field = field(
    "motion.in_speed",
    Dimension::VELOCITY,
    "m/s",
    Bound::Range(1e-9, 100.0),
);
const JUNCTION_POSITION: Field = field(
    "motion.junction_position",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);

/// Default of `motion.junction_position`: the critical junction in the middle of the width.
const DEFAULT_JUNCTION_POSITION: f64 = 0.5;

impl Source<'_> {
    /// `[motion]` (absent: a static seal).
    pub(super) fn motion(
        &self,
        table: Option<&Spanned<RawMotion>>,
    ) -> Result<Option<MotionSpec>, ScenarioError> {
        let Some(table) = table else {
            return Ok(None);
        };
        let raw = table.get_ref();
        // every value first, so that a wrong unit or range is reported at its own key
        let sliding_speed = self.optional(raw.sliding_speed.as_ref(), &SLIDING_SPEED)?;
        let stroke = self.optional(raw.stroke.as_ref(), &STROKE)?;
        let frequency = self.optional(raw.frequency.as_ref(), &FREQUENCY)?;
        let out_speed = self.optional(raw.out_speed.as_ref(), &OUT_SPEED)?;
        let in_speed = self.optional(raw.in_speed.as_ref(), &IN_SPEED)?;
        let junction_position = self
            .optional(raw.junction_position.as_ref(), &JUNCTION_POSITION)?
            .unwrap_or(DEFAULT_JUNCTION_POSITION);
        // the stroke-cycle keys that are present, in file order of the schema
        let cycle_keys = [
            (&raw.frequency, FREQUENCY.key),
            (&raw.out_speed, OUT_SPEED.key),
            (&raw.in_speed, IN_SPEED.key),
        ];
        let first_cycle_key = cycle_keys
            .iter()
            .find_map(|(q, key)| q.as_ref().map(|q| (q.span(), *key)));

        let motion = match (sliding_speed, stroke) {
            (Some(_), Some(_)) => {
                let span = raw.stroke.as_ref().map_or(table.span(), Spanned::span);
                return Err(self.error(
                    span,
                    STROKE.key,
                    "sliding_speed (constant sliding) and stroke (a stroke cycle) are mutually \
                     exclusive; give one",
                ));
            }
            (Some(speed), None) => {
                if let Some((span, key)) = first_cycle_key {
                    return Err(self.error(
                        span,
                        key,
                        "only applies to a stroke cycle (with stroke); sliding_speed is constant \
                         sliding: remove this key, or replace sliding_speed by stroke",
                    ));
                }
                Motion::Steady { speed }
            }
            (None, None) => {
                return Err(match first_cycle_key {
                    Some((span, key)) => self.error(
                        span,
                        key,
                        "belongs to a stroke cycle, which needs stroke (the stroke length, e.g. \
                         stroke = \"100 mm\")",
                    ),
                    None => self.error(
                        table.span(),
                        SLIDING_SPEED.key,
                        "missing key: [motion] needs sliding_speed (constant sliding, e.g. \
                         \"1 cm/s\") or stroke (a stroke cycle, e.g. stroke = \"100 mm\" with \
                         frequency = \"0.5 Hz\", or with out_speed and in_speed); remove [motion] \
                         for a static seal",
                    ),
                });
            }
            (None, Some(stroke)) => {
                self.stroke_cycle(raw, stroke, frequency, out_speed, in_speed)?
            }
        };
        Ok(Some(MotionSpec {
            motion,
            junction_position,
        }))
    }

    /// The speeds of a stroke cycle of length `stroke`: from `frequency`, or `out_speed` and
    /// `in_speed`.
    fn stroke_cycle(
        &self,
        raw: &RawMotion,
        stroke: f64,
        frequency: Option<f64>,
        out_speed: Option<f64>,
        in_speed: Option<f64>,
    ) -> Result<Motion, ScenarioError> {
        let span_of = |q: &Option<super::raw::Quantity>| q.as_ref().map(Spanned::span);
        let stroke_span = span_of(&raw.stroke).unwrap_or_default();
        match (frequency, out_speed, in_speed) {
            (Some(f), None, None) => {
                let speed = 2.0 * stroke * f;
                if !(speed.is_finite() && speed > 0.0) {
                    return Err(self.error(
                        span_of(&raw.frequency).unwrap_or(stroke_span),
                        FREQUENCY.key,
                        format!(
                            "gives the speed 2 · stroke · frequency = {} m/s, which is not a \
                             positive finite number",
                            show(speed)
                        ),
                    ));
                }
                Ok(Motion::Stroke {
                    stroke,
                    out_speed: speed,
                    in_speed: speed,
                })
            }
            (Some(_), _, _) => Err(self.error(
                span_of(&raw.frequency).unwrap_or(stroke_span),
                FREQUENCY.key,
                "frequency (which sets out_speed = in_speed = 2 · stroke · frequency) and \
                 out_speed/in_speed are mutually exclusive; give frequency alone or both speeds",
            )),
            (None, Some(out_speed), Some(in_speed)) => Ok(Motion::Stroke {
                stroke,
                out_speed,
                in_speed,
            }),
            (None, Some(_), None) => Err(self.error(
                span_of(&raw.out_speed).unwrap_or(stroke_span),
                IN_SPEED.key,
                "missing key: a stroke cycle with out_speed needs in_speed too (or give \
                 frequency alone)",
            )),
            (None, None, Some(_)) => Err(self.error(
                span_of(&raw.in_speed).unwrap_or(stroke_span),
                OUT_SPEED.key,
                "missing key: a stroke cycle with in_speed needs out_speed too (or give \
                 frequency alone)",
            )),
            (None, None, None) => Err(self.error(
                stroke_span,
                STROKE.key,
                "a stroke cycle needs frequency (e.g. \"0.5 Hz\": out_speed = in_speed = 2 · \
                 stroke · frequency) or both out_speed and in_speed (e.g. \"0.1 m/s\")",
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::dynamic::{Motion, MotionSpec};
    use crate::scenario::Scenario;
    use std::path::Path;

    const PAPER: &str = include_str!("../../scenarios/persson-yang-2008.toml");

    fn motion(table: &str) -> Result<Option<MotionSpec>, String> {
        Scenario::from_str(&format!("{PAPER}[motion]\n{table}"), Path::new("x.toml"))
            .map(|s| s.life.motion)
            .map_err(|e| e.to_string())
    }

    /// The line of `[motion]` in the test scenario is 17; its first key 18.
    fn error(table: &str) -> String {
        motion(table).expect_err("should be rejected")
    }

    #[test]
    fn steady_and_stroke_in_si_units() {
        let m = motion("sliding_speed = \"1 cm/s\"\n").unwrap().unwrap();
        assert_eq!(m.motion, Motion::Steady { speed: 0.01 });
        assert_eq!(m.junction_position, 0.5);
        let m = motion("sliding_speed = \"2 mm/s\"\njunction_position = 0.25\n")
            .unwrap()
            .unwrap();
        assert_eq!(m.motion, Motion::Steady { speed: 2e-3 });
        assert_eq!(m.junction_position, 0.25);
        let m = motion("stroke = \"100 mm\"\nfrequency = \"0.5 Hz\"\n")
            .unwrap()
            .unwrap();
        assert_eq!(
            m.motion,
            Motion::Stroke {
                stroke: 0.1,
                out_speed: 0.1,
                in_speed: 0.1
            }
        );
        assert_eq!(m.period(), Some(2.0));
        let m = motion("stroke = \"5 cm\"\nout_speed = \"0.2 m/s\"\nin_speed = 0.05\n")
            .unwrap()
            .unwrap();
        assert_eq!(
            m.motion,
            Motion::Stroke {
                stroke: 0.05,
                out_speed: 0.2,
                in_speed: 0.05
            }
        );
        assert_eq!(m.drag_speed(), 0.2);
        assert_eq!(m.fastest_speed(), 0.2);
        assert!(motion("sliding_speed = 0\n").unwrap().is_some());
        let none = Scenario::from_str(PAPER, Path::new("x.toml")).unwrap();
        assert_eq!(none.life.motion, None);
        assert_eq!(none.life.motion, None);
    }

    #[test]
    fn every_bad_combination_names_its_key() {
        let cases = [
            (
                "sliding_speed = \"-1 cm/s\"\n",
                "x.toml:18: motion.sliding_speed: must not be negative, got -0.01 m/s",
            ),
            (
                "sliding_speed = \"1 MPa\"\n",
                "x.toml:18: motion.sliding_speed: expected a velocity",
            ),
            (
                "stroke = \"0.1 m\"\nfrequency = \"0 Hz\"\n",
                "x.toml:19: motion.frequency: must be positive, got 0 Hz",
            ),
            (
                "stroke = \"0.1 m\"\n",
                "x.toml:18: motion.stroke: a stroke cycle needs frequency",
            ),
            (
                "stroke = 0\nfrequency = 1\n",
                "x.toml:18: motion.stroke: must be positive, got 0 m",
            ),
            (
                "sliding_speed = \"1 cm/s\"\nstroke = \"0.1 m\"\n",
                "x.toml:19: motion.stroke: sliding_speed (constant sliding) and stroke",
            ),
            (
                "stroke = \"0.1 m\"\nfrequency = 1\nout_speed = \"1 m/s\"\n",
                "x.toml:19: motion.frequency: frequency (which sets",
            ),
            (
                "stroke = \"0.1 m\"\nout_speed = \"1 m/s\"\n",
                "x.toml:19: motion.in_speed: missing key",
            ),
            (
                "stroke = \"0.1 m\"\nin_speed = \"1 m/s\"\n",
                "x.toml:19: motion.out_speed: missing key",
            ),
            (
                "stroke = \"0.1 m\"\nout_speed = \"0 m/s\"\nin_speed = 1\n",
                "x.toml:19: motion.out_speed: must be positive",
            ),
            (
                "sliding_speed = \"1 cm/s\"\nfrequency = 1\n",
                "x.toml:19: motion.frequency: only applies to a stroke cycle",
            ),
            (
                "out_speed = \"1 m/s\"\nin_speed = 1\n",
                "x.toml:18: motion.out_speed: belongs to a stroke cycle",
            ),
            ("", "x.toml:17: motion.sliding_speed: missing key"),
            (
                "sliding_speed = 1\njunction_position = 1\n",
                "x.toml:19: motion.junction_position: must lie strictly between 0 and 1",
            ),
            (
                "sliding_speed = 1\nspeed = 1\n",
                "x.toml:19: motion.speed: unknown key",
            ),
        ];
        for (table, expected) in cases {
            let e = error(table);
            assert!(
                e.starts_with(expected),
                "{table:?}:\n{e}\nexpected {expected}"
            );
        }
    }
}
