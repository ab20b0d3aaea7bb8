//! The master curve of `sealsim fit-prony` on data at several temperatures
//! ([`crate::material::tts`]): a text summary (shift factors with standard errors, the shift
//! law with its intervals) and two charts (the shifted data on the master curve; a_T against
//! T with the fitted law).

use super::plot::{LogLogChart, Series};
use crate::material::tts::{FittedLaw, MasterCurve};
use crate::units::show;
use crate::workflow::fit_prony::law_text;
use std::fmt::Write;

/// The human-readable summary (stderr of `fit-prony`).
pub fn text(source: &str, m: &MasterCurve) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "fit-prony: {source}: master curve from {} temperatures ({} points), reference {:.2} K \
         ({:.2} C); {} iterations{}",
        m.shifts.len(),
        m.reduced.len(),
        m.reference,
        m.reference - 273.15,
        m.iterations,
        if m.converged {
            ""
        } else {
            " (NOT converged: the shifts still moved)"
        }
    );
    let _ = writeln!(
        out,
        "{:>10}  {:>9}  {:>12}  {:>10}  {:>12}",
        "T [K]", "T [C]", "log10 a_T", "std error", "law"
    );
    for s in &m.shifts {
        let _ = writeln!(
            out,
            "{:>10.2}  {:>9.2}  {:>12.4}  {:>10.4}  {:>12.4}",
            s.temperature,
            s.temperature - 273.15,
            s.log10_shift,
            s.std_error,
            m.shift.log10_factor(s.temperature)
        );
    }
    let _ = writeln!(out, "{}", law_text(m));
    let _ = writeln!(
        out,
        "law fit: {} points, {} degrees of freedom, rms residual {:.2e} decades, Birge ratio {:.2}{}",
        m.law.points,
        m.law.degrees_of_freedom,
        m.law.rms_residual,
        m.law.birge_ratio,
        m.law
            .note
            .as_deref()
            .map_or(String::new(), |n| format!(" ({n})"))
    );
    let _ = writeln!(
        out,
        "master curve at {:.2} K backed by data from {} s to {} s of reduced time",
        m.reference,
        show(m.window.0),
        show(m.window.1)
    );
    out
}

/// The shifted data (one series per temperature) on the fitted master curve, E against
/// reduced time at the reference temperature.
pub fn master_chart(source: &str, m: &MasterCurve) -> LogLogChart {
    let mut series: Vec<Series> = m
        .shifts
        .iter()
        .enumerate()
        .map(|(i, s)| Series {
            label: format!("{:.1} C", s.temperature - 273.15),
            points: m
                .reduced
                .iter()
                .filter(|p| p.isotherm == i)
                .map(|p| (p.reduced_time, p.modulus))
                .collect(),
        })
        .collect();
    let (lo, hi) = m.window;
    series.push(Series {
        label: "master curve (Prony)".into(),
        points: (0..=200)
            .map(|k| {
                let t = lo * (hi / lo).powf(f64::from(k) / 200.0);
                (t, m.fit.prony.relaxation(t))
            })
            .collect(),
    });
    LogLogChart {
        title: format!("Master curve at {:.1} C: {source}", m.reference - 273.15),
        x_label: "reduced time t/a_T [s]".into(),
        y_label: "relaxation modulus E [Pa]".into(),
        series,
    }
}

/// The measured shift factors and the fitted law, a_T against T (both on log axes).
pub fn shift_chart(source: &str, m: &MasterCurve) -> LogLogChart {
    let (lo, hi) = m.temperature_range;
    let points: Vec<(f64, f64)> = m
        .shifts
        .iter()
        .map(|s| (s.temperature, 10f64.powf(s.log10_shift)))
        .collect();
    let law: Vec<(f64, f64)> = (0..=60)
        .map(|k| {
            let t = lo + (hi - lo) * f64::from(k) / 60.0;
            (t, m.shift.factor(t))
        })
        .collect();
    let name = match m.law.law {
        FittedLaw::Wlf { .. } => "WLF fit",
        FittedLaw::Arrhenius { .. } => "Arrhenius fit",
    };
    LogLogChart {
        title: format!("Shift factors: {source}"),
        x_label: "temperature T [K]".into(),
        y_label: format!("shift factor a_T (reference {:.1} C)", m.reference - 273.15),
        series: vec![
            Series {
                label: "measured".into(),
                points,
            },
            Series {
                label: name.into(),
                points: law,
            },
        ],
    }
}
