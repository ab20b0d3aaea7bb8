//! `[motion]` → [`MotionSpec`]: a reciprocating (dynamic) seal, PY08 §8 ([`crate::dynamic`]).
//!
//! Keys: `sliding_speed` (constant sliding, ≥ 0) XOR `stroke` (a stroke cycle, > 0); a stroke
//! cycle takes `frequency` (> 0; then `out_speed = in_speed = 2 · stroke · frequency`) XOR both
//! `out_speed` and `in_speed` (> 0); `junction_position` (strictly between 0 and 1, default
//! ½) in either case. Every combination that does not fit is an error naming the key.
//!
//! A rod seal's inverse-hydrodynamic films ([`crate::dynamic::ihl`]) take the steepest inlet
//! gradients of its contact-pressure profile: `inlet_gradient_out` and `inlet_gradient_in`
//! (a pressure per length, > 0, e.g. "5 MPa/mm"; both or neither) XOR `contact_profile` (a CSV
//! of x, p with a units row, [`parse_contact_profile`]); neither: an O-ring's are estimated
//! from its Hertz profile, a flat seal has none.

use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::raw::RawMotion;
use crate::dynamic::ihl::{ContactProfile, GradientSource, InletGradients};
use crate::dynamic::{Motion, MotionSpec};
use crate::units::{self, Dimension, show};
use toml::Spanned;

/// Pressure per length \[Pa/m\].
const PRESSURE_GRADIENT: Dimension = Dimension::new(-2, 1, -2, 0, 0);
pub(super) const INLET_GRADIENT_OUT: Field = field(
    "motion.inlet_gradient_out",
    PRESSURE_GRADIENT,
    "Pa/m",
    Bound::Range(1.0, 1e15),
);
pub(super) const INLET_GRADIENT_IN: Field = field(
    "motion.inlet_gradient_in",
    PRESSURE_GRADIENT,
    "Pa/m",
    Bound::Range(1.0, 1e15),
);
const CONTACT_PROFILE: &str = "motion.contact_profile";

pub(super) const SLIDING_SPEED: Field = field(
    "motion.sliding_speed",
    Dimension::VELOCITY,
    "m/s",
    Bound::Range(0.0, 100.0),
);
pub(super) const STROKE: Field = field(
    "motion.stroke",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 10.0),
);
pub(super) const FREQUENCY: Field = field(
    "motion.frequency",
    Dimension::FREQUENCY,
    "Hz",
    Bound::Range(1e-9, 1e6),
);
pub(super) const OUT_SPEED: Field = field(
    "motion.out_speed",
    Dimension::VELOCITY,
    "m/s",
    Bound::Range(1e-9, 100.0),
);
pub(super) const IN_SPEED: Field = field(
    "motion.in_speed",
    Dimension::VELOCITY,
    "m/s",
    Bound::Range(1e-9, 100.0),
);
pub(super) const JUNCTION_POSITION: Field = field(
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
        let gradients = self.inlet_gradients(raw, table)?;
        Ok(Some(MotionSpec {
            motion,
            junction_position,
            gradients,
        }))
    }

    /// `inlet_gradient_out`/`_in` or `contact_profile` (module docs).
    fn inlet_gradients(
        &self,
        raw: &RawMotion,
        table: &Spanned<RawMotion>,
    ) -> Result<Option<(InletGradients, GradientSource)>, ScenarioError> {
        let out = self.optional(raw.inlet_gradient_out.as_ref(), &INLET_GRADIENT_OUT)?;
        let back = self.optional(raw.inlet_gradient_in.as_ref(), &INLET_GRADIENT_IN)?;
        if let (Some(_), Some(q)) = (
            &raw.contact_profile,
            raw.inlet_gradient_out
                .as_ref()
                .or(raw.inlet_gradient_in.as_ref()),
        ) {
            return Err(self.error(
                q.span(),
                if raw.inlet_gradient_out.is_some() {
                    INLET_GRADIENT_OUT.key
                } else {
                    INLET_GRADIENT_IN.key
                },
                "contact_profile gives the gradients; remove inlet_gradient_out/inlet_gradient_in \
                 (or remove contact_profile)",
            ));
        }
        match (out, back) {
            (Some(out_stroke), Some(in_stroke)) => {
                return Ok(Some((
                    InletGradients {
                        out_stroke,
                        in_stroke,
                    },
                    GradientSource::Given,
                )));
            }
            (Some(_), None) | (None, Some(_)) => {
                let (span, missing) = match &raw.inlet_gradient_out {
                    Some(q) => (q.span(), INLET_GRADIENT_IN.key),
                    None => (
                        raw.inlet_gradient_in
                            .as_ref()
                            .map_or(table.span(), Spanned::span),
                        INLET_GRADIENT_OUT.key,
                    ),
                };
                return Err(self.error(
                    span,
                    missing,
                    "missing key: the inlet gradients go in pairs (inlet_gradient_out for the \
                     pressurised side, inlet_gradient_in for the air side, e.g. \"5 MPa/mm\")",
                ));
            }
            (None, None) => {}
        }
        let Some(file) = &raw.contact_profile else {
            return Ok(None);
        };
        let path = self.relative_path(file.get_ref());
        let text = std::fs::read_to_string(&path).map_err(|e| {
            self.error(
                file.span(),
                CONTACT_PROFILE,
                format!(
                    "cannot read the contact-pressure profile {}: {e}",
                    path.display()
                ),
            )
        })?;
        let profile = parse_contact_profile(&text).map_err(|(line, message)| {
            let at = line.map_or(String::new(), |l| format!(":{l}"));
            self.error(
                file.span(),
                CONTACT_PROFILE,
                format!("{}{at}: {message}", path.display()),
            )
        })?;
        Ok(Some((profile.inlet_gradients(), GradientSource::Profile)))
    }
}

/// A contact-pressure profile CSV: a header row `x,p` (case-insensitive; `x,pressure` or
/// `x,contact_pressure` accepted), a units row (a length and a pressure unit, e.g. `mm,MPa`),
/// then rows of x (from the pressurised side to the air side, strictly increasing) and the
/// contact pressure p (≥ 0). `#` lines and blank lines are skipped. Errors carry the 1-based
/// line.
pub fn parse_contact_profile(text: &str) -> Result<ContactProfile, (Option<usize>, String)> {
    let cells =
        |row: &str| -> Vec<String> { row.split(',').map(|c| c.trim().to_owned()).collect() };
    let mut rows = super::text::data_lines(text);
    let Some((header_line, header)) = rows.next() else {
        return Err((None, "no data: expected a header row x,p".into()));
    };
    let names: Vec<String> = cells(header).iter().map(|c| c.to_lowercase()).collect();
    if names.len() != 2
        || names[0] != "x"
        || !["p", "pressure", "contact_pressure"].contains(&names[1].as_str())
    {
        return Err((
            Some(header_line),
            format!("expected the header row x,p, found {header:?}"),
        ));
    }
    let Some((units_line, units_row)) = rows.next() else {
        return Err((
            Some(header_line),
            "no units row: expected e.g. mm,MPa after the header".into(),
        ));
    };
    let units_cells = cells(units_row);
    let unit =
        |k: usize, dimension: Dimension, what: &str| -> Result<f64, (Option<usize>, String)> {
            let u = units_cells.get(k).map_or("", String::as_str);
            match units::parse_unit(u) {
                Ok((factor, d)) if d == dimension => Ok(factor),
                Ok((_, d)) => Err((
                    Some(units_line),
                    format!("unit {u:?} is {d}, expected {what}"),
                )),
                Err(e) => Err((Some(units_line), format!("{what}: {e}"))),
            }
        };
    if units_cells.len() != 2 {
        return Err((
            Some(units_line),
            format!(
                "the units row has {} cells, expected 2 (e.g. mm,MPa)",
                units_cells.len()
            ),
        ));
    }
    let x_factor = unit(0, Dimension::LENGTH, "a length (e.g. mm)")?;
    let p_factor = unit(1, Dimension::PRESSURE, "a pressure (e.g. MPa)")?;
    let (mut x, mut p, mut lines) = (Vec::new(), Vec::new(), Vec::new());
    for (line, row) in rows {
        let c = cells(row);
        if c.len() != 2 {
            return Err((
                Some(line),
                format!(
                    "expected 2 comma-separated columns (x, p), found {}",
                    c.len()
                ),
            ));
        }
        let number = |k: usize, name: &str| match c[k].parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err((
                Some(line),
                format!("{name}: not a finite number: {:?}", c[k]),
            )),
        };
        x.push(number(0, "x")? * x_factor);
        p.push(number(1, "p")? * p_factor);
        lines.push(line);
    }
    ContactProfile::new(x, p).map_err(|e| (e.index.and_then(|i| lines.get(i).copied()), e.message))
}

impl Source<'_> {
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
        let m = motion("stroke = \"5 cm\"\nout_speed = \"0.2 m/s\"\nin_speed = \"0.05 m/s\"\n")
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
        let m = motion(
            "stroke = \"0.1 m\"\nfrequency = \"1 Hz\"\ninlet_gradient_out = \"2 MPa/mm\"\n\
             inlet_gradient_in = \"3e9 Pa/m\"\n",
        )
        .unwrap()
        .unwrap();
        let (g, source) = m.gradients.unwrap();
        assert_eq!(source, crate::dynamic::ihl::GradientSource::Given);
        assert!((g.out_stroke / 2e9 - 1.0).abs() < 1e-12 && g.in_stroke == 3e9);
        assert_eq!(
            motion("sliding_speed = 0\n").unwrap().unwrap().gradients,
            None
        );
        let none = Scenario::from_str(PAPER, Path::new("x.toml")).unwrap();
        assert_eq!(none.life.motion, None);
        assert_eq!(none.life.motion, None);
    }

    #[test]
    fn contact_profiles_are_read_in_si_and_errors_name_their_line() {
        let ok = super::parse_contact_profile("# c\nx,p\nmm,MPa\n0,0.2\n0.5,1.2\n1.5,0\n").unwrap();
        let g = ok.inlet_gradients();
        // 1 MPa over 0.5 mm and 1.2 MPa over 1 mm
        assert!((g.out_stroke / 2e9 - 1.0).abs() < 1e-12, "{g:?}");
        assert!((g.in_stroke / 1.2e9 - 1.0).abs() < 1e-12, "{g:?}");
        let line = |text: &str| super::parse_contact_profile(text).unwrap_err().0;
        assert_eq!(line("x,q\nmm,MPa\n0,0\n1,1\n2,0\n"), Some(1));
        assert_eq!(line("x,p\nMPa,MPa\n0,0\n1,1\n2,0\n"), Some(2));
        assert_eq!(line("x,p\nmm,mm\n0,0\n1,1\n2,0\n"), Some(2));
        assert_eq!(line("x,p\nmm,MPa\n0,0\n1,abc\n2,0\n"), Some(4));
        assert_eq!(line("x,p\nmm,MPa\n\n0,0\n# c\n1,1\n1,0\n"), Some(7));
        assert_eq!(line("x,p\nmm,MPa\n0,0\n1,1\n"), None);
        // the maximum on an edge: no rise on one side
        assert_eq!(line("x,p\nmm,MPa\n0,0\n1,1\n2,2\n"), Some(5));
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
                "stroke = 0\nfrequency = \"1 Hz\"\n",
                "x.toml:18: motion.stroke: must be positive, got 0 m",
            ),
            (
                "sliding_speed = \"1 cm/s\"\nstroke = \"0.1 m\"\n",
                "x.toml:19: motion.stroke: sliding_speed (constant sliding) and stroke",
            ),
            (
                "stroke = \"0.1 m\"\nfrequency = \"1 Hz\"\nout_speed = \"1 m/s\"\n",
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
                "stroke = \"0.1 m\"\nout_speed = \"0 m/s\"\nin_speed = \"1 m/s\"\n",
                "x.toml:19: motion.out_speed: must be positive",
            ),
            (
                "sliding_speed = \"1 cm/s\"\nfrequency = \"1 Hz\"\n",
                "x.toml:19: motion.frequency: only applies to a stroke cycle",
            ),
            (
                "out_speed = \"1 m/s\"\nin_speed = \"1 m/s\"\n",
                "x.toml:18: motion.out_speed: belongs to a stroke cycle",
            ),
            ("", "x.toml:17: motion.sliding_speed: missing key"),
            (
                "sliding_speed = \"1 m/s\"\njunction_position = 1\n",
                "x.toml:19: motion.junction_position: must lie strictly between 0 and 1",
            ),
            (
                "sliding_speed = \"1 m/s\"\nspeed = 1\n",
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
