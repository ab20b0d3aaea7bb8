//! The result of `sealsim ageing-fit` (ISO 11346, [`crate::material::ageing_fit`]): a text
//! table, a JSON object and an Arrhenius chart (ln t against 1/T).

use super::ReportError;
use super::life::human_time;
use super::plot::{LogLogChart, Series};
use crate::material::ageing_fit::{AgeingKind, ArrheniusFit, Crossing};
use crate::units::show;
use serde_json::json;
use std::fmt::Write;

/// Everything reported by `sealsim ageing-fit`; SI units (K, s, J/mol).
#[derive(Debug, Clone, PartialEq)]
pub struct AgeingFitReport {
    pub source: String,
    pub kind: AgeingKind,
    /// Whether the kind was inferred from the data's direction.
    pub kind_inferred: bool,
    pub criterion: f64,
    /// Every temperature \[K\] and its crossing, in file order.
    pub crossings: Vec<(f64, Crossing)>,
    pub fit: ArrheniusFit,
    /// Service temperature \[K\], when given.
    pub service_temperature: Option<f64>,
}

/// (life \[s\], 95 % confidence interval, 95 % prediction interval).
type Life = (f64, (f64, f64), (f64, f64));

const INTERVAL_NOTE: &str = "95 % confidence interval of the regression line (ISO 11346); \
    the 95 % prediction interval of one new determination is wider";

impl AgeingFitReport {
    /// (life \[s\], confidence interval, prediction interval) at the service temperature.
    fn life(&self) -> Option<Life> {
        self.service_temperature.map(|t| {
            (
                self.fit.time_at(t),
                self.fit.interval_at(t, false),
                self.fit.interval_at(t, true),
            )
        })
    }

    /// The human-readable summary.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "ageing-fit: {}: {} ({}), criterion {}",
            self.source,
            self.kind.as_str(),
            if self.kind_inferred {
                "inferred from the direction of every series"
            } else {
                "given"
            },
            show(self.criterion)
        );
        let _ = writeln!(
            out,
            "time to criterion: linear interpolation in ln t between the bracketing points"
        );
        let _ = writeln!(out, "{:>10}  {:>10}  time to criterion", "T [K]", "T [C]");
        for (t, c) in &self.crossings {
            let what = match c {
                Crossing::Reached(s) => format!("{} s ({})", show(*s), human_time(*s)),
                Crossing::AtFirstTime => {
                    "passed at the first ageing time: shorter times needed (not fitted)".into()
                }
                Crossing::NotReached => "not reached: longer ageing needed (not fitted)".into(),
            };
            let _ = writeln!(out, "{:>10.2}  {:>10.2}  {what}", t, t - 273.15);
        }
        let (lo, hi) = self.fit.activation_energy_interval;
        let _ = writeln!(
            out,
            "Arrhenius fit ln t = ln A + Ea/(R T) over {} temperatures: Ea = {:.1} kJ/mol \
             (95 % confidence interval {:.1} – {:.1} kJ/mol), r² = {:.4}",
            self.fit.points.len(),
            self.fit.activation_energy / 1e3,
            lo / 1e3,
            hi / 1e3,
            self.fit.r_squared
        );
        if let (Some(ts), Some((life, (clo, chi), (plo, phi)))) =
            (self.service_temperature, self.life())
        {
            let _ = writeln!(
                out,
                "life at {:.2} K ({:.2} C): {} s ({}); 95 % confidence interval {} – {}; \
                 95 % prediction interval {} – {}",
                ts,
                ts - 273.15,
                show(life),
                human_time(life),
                human_time(clo),
                human_time(chi),
                human_time(plo),
                human_time(phi)
            );
        }
        out
    }

    /// The JSON object (fields named with their units).
    pub fn json(&self) -> Result<String, ReportError> {
        let life = self.life();
        let (lo, hi) = self.fit.activation_energy_interval;
        let value = json!({
            "source": self.source,
            "kind": self.kind.as_str(),
            "kind_inferred": self.kind_inferred,
            "criterion": self.criterion,
            "interpolation": "linear in ln t between the bracketing points",
            "times_to_criterion": self.crossings.iter().map(|(t, c)| match c {
                Crossing::Reached(s) => json!({"temperature_K": t, "time_s": s}),
                Crossing::AtFirstTime => json!({"temperature_K": t, "time_s": null,
                    "note": "passed at the first ageing time"}),
                Crossing::NotReached => json!({"temperature_K": t, "time_s": null,
                    "note": "not reached"}),
            }).collect::<Vec<_>>(),
            "activation_energy_J_per_mol": self.fit.activation_energy,
            "activation_energy_interval_J_per_mol": [lo, hi],
            "ln_A_ln_s": self.fit.intercept,
            "r_squared": self.fit.r_squared,
            "service_temperature_K": self.service_temperature,
            "life_at_service_s": life.map(|l| l.0),
            "life_interval_s": life.map(|l| [l.1.0, l.1.1]),
            "life_interval_kind": INTERVAL_NOTE,
            "life_prediction_interval_s": life.map(|l| [l.2.0, l.2.1]),
        });
        serde_json::to_string_pretty(&value)
            .map(|s| s + "\n")
            .map_err(|e| ReportError::Csv(e.to_string()))
    }

    /// The Arrhenius chart: time to criterion (log axis, i.e. ln t) against 1/T, the points
    /// and the fitted line (extended to the service temperature).
    pub fn chart(&self) -> LogLogChart {
        let xs: Vec<f64> = self
            .fit
            .points
            .iter()
            .map(|p| 1.0 / p.0)
            .chain(self.service_temperature.map(|t| 1.0 / t))
            .collect();
        let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = xs.iter().copied().fold(0.0, f64::max);
        let line: Vec<(f64, f64)> = (0..=60)
            .map(|i| {
                let x = lo + (hi - lo) * f64::from(i) / 60.0;
                (x, self.fit.time_at(1.0 / x))
            })
            .collect();
        LogLogChart {
            title: format!("Arrhenius plot (ISO 11346): {}", self.source),
            x_label: "1/T [1/K]".into(),
            y_label: "time to criterion [s]".into(),
            series: vec![
                Series {
                    label: "times to criterion".into(),
                    points: self.fit.points.iter().map(|p| (1.0 / p.0, p.1)).collect(),
                },
                Series {
                    label: format!("fit: Ea = {:.1} kJ/mol", self.fit.activation_energy / 1e3),
                    points: line,
                },
            ],
        }
    }
}
