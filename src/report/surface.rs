//! The result of `sealsim surface` ([`crate::workflow::surface`]): what a roughness source says
//! about the contact's input spectrum — profile parameters (Ra, Rq, Rz), h_rms and rms slope,
//! the Hurst exponent with its interval, the cut-offs and roll-off — as text, JSON and a C(q)
//! chart.

pub use crate::workflow::surface::SurfaceReport;

use super::ReportError;
use super::plot::{LogLogChart, Series};
use crate::units::show;
use serde_json::json;
use std::fmt::Write;

impl SurfaceReport {
    /// The human-readable summary.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let um = |v: f64| format!("{:.4} µm", v * 1e6);
        let _ = writeln!(out, "surface: {} ({})", self.source, self.kind);
        let _ = writeln!(
            out,
            "Ra {}  Rq {}  Rz {}  ({})",
            um(self.ra),
            um(self.rq),
            self.rz.map_or("–".to_string(), um),
            self.parameters_basis
        );
        let _ = writeln!(
            out,
            "band q = {} … {} 1/m (wavelengths {} … {} µm): h_rms {}, rms slope {:.4}",
            show(self.band.0),
            show(self.band.1),
            show(2e6 * std::f64::consts::PI / self.band.1),
            show(2e6 * std::f64::consts::PI / self.band.0),
            um(self.h_rms),
            self.rms_slope
        );
        if let Some((h_rms, slope)) = self.map_figures {
            let _ = writeln!(
                out,
                "on the map itself: h_rms {}, rms slope {slope:.4} (finite differences)",
                um(h_rms)
            );
        }
        let fitted_over = self.fit_band.map_or(String::new(), |(a, b)| {
            format!(", fitted over q = {} … {} 1/m", show(a), show(b))
        });
        match self.hurst {
            Some((h, Some((lo, hi)))) => {
                let _ = writeln!(
                    out,
                    "Hurst exponent {h:.3} (95 % interval {lo:.3} – {hi:.3}{fitted_over})"
                );
            }
            Some((h, None)) => {
                let _ = writeln!(out, "Hurst exponent {h:.3} (given)");
            }
            None => {
                let _ = writeln!(out, "Hurst exponent: none (not a single power law)");
            }
        }
        let _ = writeln!(
            out,
            "q0 {} 1/m, q1 {} 1/m, roll-off {}",
            show(self.q0),
            show(self.q1),
            self.rolloff
                .map_or("none".to_string(), |q| format!("{} 1/m", show(q)))
        );
        for w in &self.warnings {
            let _ = writeln!(out, "warning: {w}");
        }
        out
    }

    /// The JSON object (keys named with their units).
    ///
    /// # Errors
    /// [`ReportError::NonFinite`] for a NaN or infinite figure: serde_json would print it as
    /// `null`, which reads as "absent" (the readers refuse what would give one).
    pub fn json(&self) -> Result<String, ReportError> {
        let mut numbers: Vec<(&'static str, f64)> = vec![
            ("ra_m", self.ra),
            ("rq_m", self.rq),
            ("h_rms_m", self.h_rms),
            ("rms_slope", self.rms_slope),
            ("band_per_m", self.band.0),
            ("band_per_m", self.band.1),
            ("q0_per_m", self.q0),
            ("q1_per_m", self.q1),
        ];
        numbers.extend(self.rz.map(|v| ("rz_m", v)));
        numbers.extend(self.rolloff.map(|v| ("rolloff_per_m", v)));
        if let Some((h, interval)) = self.hurst {
            numbers.push(("hurst_exponent", h));
            numbers.extend(interval.into_iter().flat_map(|(a, b)| {
                [
                    ("hurst_exponent_interval", a),
                    ("hurst_exponent_interval", b),
                ]
            }));
        }
        numbers.extend(
            self.fit_band
                .into_iter()
                .flat_map(|(a, b)| [("hurst_fit_band_per_m", a), ("hurst_fit_band_per_m", b)]),
        );
        numbers.extend(
            self.map_figures
                .into_iter()
                .flat_map(|(a, b)| [("map_h_rms_m", a), ("map_rms_slope", b)]),
        );
        if let Some(&(column, value)) = numbers.iter().find(|(_, v)| !v.is_finite()) {
            return Err(ReportError::NonFinite {
                row: 1,
                column,
                value,
            });
        }
        let (hurst, interval) = match self.hurst {
            Some((h, i)) => (Some(h), i.map(|(a, b)| vec![a, b])),
            None => (None, None),
        };
        let value = json!({
            "source": self.source,
            "kind": self.kind,
            "ra_m": self.ra,
            "rq_m": self.rq,
            "rz_m": self.rz,
            "parameters_basis": self.parameters_basis,
            "h_rms_m": self.h_rms,
            "rms_slope": self.rms_slope,
            "band_per_m": [self.band.0, self.band.1],
            "hurst_exponent": hurst,
            "hurst_exponent_interval": interval,
            "hurst_fit_band_per_m": self.fit_band.map(|(a, b)| vec![a, b]),
            "map_h_rms_m": self.map_figures.map(|f| f.0),
            "map_rms_slope": self.map_figures.map(|f| f.1),
            "q0_per_m": self.q0,
            "q1_per_m": self.q1,
            "rolloff_per_m": self.rolloff,
            "warnings": self.warnings,
        });
        serde_json::to_string_pretty(&value)
            .map(|s| s + "\n")
            .map_err(|e| ReportError::Csv(e.to_string()))
    }

    /// C(q) on log axes: the spectrum, the law, and the band's ends as vertical markers.
    pub fn chart(&self) -> LogLogChart {
        let c_lo = self
            .spectrum_points
            .iter()
            .chain(&self.law_points)
            .map(|p| p.1)
            .filter(|c| *c > 0.0)
            .fold(f64::INFINITY, f64::min);
        let c_hi = self
            .spectrum_points
            .iter()
            .chain(&self.law_points)
            .map(|p| p.1)
            .fold(0.0, f64::max);
        let mut series = vec![
            Series {
                label: "C(q)".into(),
                points: self.spectrum_points.clone(),
            },
            Series {
                label: "fitted or given law".into(),
                points: self.law_points.clone(),
            },
        ];
        if c_hi > 0.0 && c_lo.is_finite() {
            for (q, label) in [(self.band.0, "band start"), (self.band.1, "band end")] {
                series.push(Series {
                    label: label.into(),
                    points: vec![(q, c_lo), (q, c_hi)],
                });
            }
        }
        LogLogChart {
            title: format!("Power spectrum: {}", self.source),
            x_label: "wavevector q [1/m]".into(),
            y_label: "C(q) [m^4]".into(),
            series,
        }
    }
}
