//! The result of `sealsim fit-prony` ([`crate::workflow::fit_prony`]): the material file's
//! text (a comment block on where the series comes from, then the `[material]` table of
//! [`super::material_toml`]) and the summary lines the command prints on standard error.

use super::material_toml::material_toml;
use crate::material::Shift;
use crate::material::csr::{Normalisation, TestPiece};
use crate::material::fit::{Fit, KK_TOLERANCE};
use crate::scenario::fit_data::FitKind;
use crate::units::show;
use crate::workflow::fit_prony::{Copied, FitOutcome, POOR_FIT, describe, regularisation_note};
use std::fmt::Write;

/// The material file (`fit-prony -o`): its comment block and the `[material]` table.
pub fn material_file(outcome: &FitOutcome) -> String {
    let source = &outcome.source;
    let head = match &outcome.master {
        Some(m) => format!(
            "# Prony series of the master curve fitted by sealsim fit-prony to relaxation data \
             at {} temperatures in {source} ({} points).\n\
             # E(t) = E∞ + Σ E_i exp(−ξ/τ_i) in reduced time ξ at the reference temperature of \
             [material.shift].\n",
            m.shifts.len(),
            m.reduced.len(),
        ),
        None => header(outcome),
    };
    format!(
        "{head}{}{}",
        like_header(outcome.copied.as_ref()),
        material_toml(&outcome.material)
    )
}

/// The summary lines (`fit-prony`'s standard error, each line ending in a newline): the master
/// curve, what was fitted and how well, how forces became moduli, what `--like` copied, and a
/// note when the data have no test temperature.
pub fn summary(outcome: &FitOutcome) -> String {
    let source = &outcome.source;
    let mut out = String::new();
    if let Some(m) = &outcome.master {
        out.push_str(&super::master_curve::text(source, m));
    }
    fit_lines(&mut out, source, &outcome.fit);
    if let Some((n, _)) = &outcome.normalisation {
        normalisation_lines(&mut out, source, n);
    }
    if let Some(copied) = &outcome.copied {
        like_lines(&mut out, source, copied);
    }
    if outcome.material.data_temperature.is_none() {
        let _ = writeln!(
            out,
            "note: {source}: no test temperature (a temperature column or --temperature): a run \
             at another temperature cannot be warned about"
        );
    }
    out
}

/// A comment block for the top of the file of a fit at one temperature.
fn header(outcome: &FitOutcome) -> String {
    let what = match outcome.kind {
        FitKind::Relaxation => "relaxation data",
        FitKind::Dma => "DMA data",
    };
    let shift = if outcome.material.shift == Shift::None {
        "at the temperature of the data (or of its master curve):\n\
         # add a [material.shift] table for temperature dependence."
    } else {
        "in reduced time at the reference temperature of [material.shift]."
    };
    format!(
        "# Prony series fitted by sealsim fit-prony to {what} in {} ({} points).\n\
         # E(t) = E∞ + Σ E_i exp(−t/τ_i), {shift}\n",
        outcome.source, outcome.fit.points
    )
}

/// The file's comment line on what `--like` copied.
fn like_header(copied: Option<&Copied>) -> String {
    copied.map_or(String::new(), |c| {
        format!(
            "# Poisson's ratio, thermal expansion, glass transition, temperature shift and ageing \
             copied from library compound {} ({} data): see [material.provenance].\n",
            c.id,
            c.status.as_str().to_uppercase()
        )
    })
}

/// What `--like` copied, and its notes.
fn like_lines(out: &mut String, source: &str, copied: &Copied) {
    let _ = writeln!(
        out,
        "fit-prony: {source}: copied from library compound {} ({}): {}",
        copied.id,
        copied.status.as_str(),
        copied.keys.join(", ")
    );
    for note in &copied.notes {
        let _ = writeln!(out, "note: {source}: {note}");
    }
}

/// What was fitted and how well, with the regularisation and the widest half-width of the
/// simultaneous 95 % band over the data window; a warning when the fit is poor.
fn fit_lines(out: &mut String, source: &str, fit: &Fit) {
    let (widest, at) = fit.widest_relative_band();
    let band = if widest.is_finite() {
        format!(
            "simultaneous 95 % band of E(t) over the data window: ±{:.2} % at most (at t = {} s)",
            100.0 * widest,
            show(at)
        )
    } else {
        "no uncertainty band: the fit leaves no residual degree of freedom to estimate the \
         scatter from (give more points)"
            .to_string()
    };
    let _ = writeln!(
        out,
        "fit-prony: {source}: {} points, {} of {} grid terms kept + E∞; \
         rms relative residual {:.2e}, max {:.2e}\n\
         fit-prony: {}; {band}",
        fit.points,
        fit.prony.terms().len(),
        fit.grid_terms,
        fit.rms_relative_residual,
        fit.max_relative_residual,
        regularisation_note(fit),
    );
    let inconsistent = consistency_lines(out, source, fit);
    if fit.rms_relative_residual > POOR_FIT {
        let advice = if inconsistent {
            "E′ and E″ disagree (above): --honour storage fits E′ where E″ is inconsistent; \
             more terms per decade will not help"
        } else {
            "check the data, or raise --terms-per-decade"
        };
        let _ = writeln!(
            out,
            "warning: {source}: the series misses the data by {:.1} % rms: {advice}",
            100.0 * fit.rms_relative_residual
        );
    }
}

/// The Kramers–Kronig check of DMA data (`material::fit`, "Kramers–Kronig check"): a line
/// when E′ and E″ agree, a warning naming the inconsistent frequency bands (f = ω/2π, in Hz)
/// and both long-term moduli when they do not. Returns whether an inconsistency is left in
/// the fit (so that `--honour storage` is the advice).
fn consistency_lines(out: &mut String, source: &str, fit: &Fit) -> bool {
    let Some(c) = &fit.consistency else {
        return false;
    };
    let hz = |w: f64| show_rounded(w / std::f64::consts::TAU);
    let long_term = |e: f64| format!("{} MPa", show_rounded(e / 1e6));
    let bands: Vec<String> = c
        .inconsistent()
        .map(|d| {
            format!(
                "{} at f = {}–{} Hz",
                show_rounded(d.ratio),
                hz(d.omegas.0),
                hz(d.omegas.1)
            )
        })
        .collect();
    if bands.is_empty() {
        let worst = c
            .decades
            .iter()
            .map(|d| d.ratio)
            .max_by(|a, b| a.ln().abs().total_cmp(&b.ln().abs()))
            .unwrap_or(1.0);
        let _ = writeln!(
            out,
            "fit-prony: {source}: Kramers–Kronig check: E″ agrees with the E″ that E′ implies \
             within a factor {} in every decade (worst ratio {}){}",
            show(KK_TOLERANCE),
            show_rounded(worst),
            if fit.refined {
                "; relaxation times refined off the grid"
            } else {
                ""
            }
        );
        return false;
    }
    let _ = writeln!(
        out,
        "warning: {source}: E″ disagrees with E′ (Kramers–Kronig): measured E″ over the E″ \
         that E′ implies, {} (tolerance: a factor {})",
        bands.join(", "),
        show(KK_TOLERANCE)
    );
    let (fitted, alone) = (fit.prony.long_term(), c.storage_long_term);
    if c.replaced_loss > 0 {
        let _ = writeln!(
            out,
            "fit-prony: {source}: --honour storage: {} E″ values of those decades replaced by \
             the E″ that E′ implies; E∞ = {} (E′ alone: {})",
            c.replaced_loss,
            long_term(fitted),
            long_term(alone)
        );
        false
    } else {
        let _ = writeln!(
            out,
            "warning: {source}: this fit's long-term modulus E∞ = {} is the lower one (E′ \
             alone gives {}): the default keeps it, which predicts less late sealing force and \
             more leak; if the storage data are the trusted ones, --honour storage fits E′ and \
             replaces the inconsistent E″ by the E″ that E′ implies",
            long_term(fitted),
            long_term(alone)
        );
        true
    }
}

/// Four significant digits, for messages.
fn show_rounded(x: f64) -> String {
    show(format!("{x:.3e}").parse().unwrap_or(x))
}

/// How forces were turned into moduli, and the plate-friction caveat for discs.
fn normalisation_lines(out: &mut String, source: &str, n: &Normalisation) {
    let _ = writeln!(
        out,
        "fit-prony: {source}: moduli = {} × the measured value, from {}",
        show(n.factor()),
        describe(n)
    );
    let piece = match n {
        Normalisation::Piece(p) | Normalisation::RetainedOf { piece: p, .. } => Some(p),
        Normalisation::Modulus { .. } => None,
    };
    if let Some(bound) = piece.and_then(TestPiece::friction_bound) {
        let _ = writeln!(
            out,
            "note: {source}: if the plates were not lubricated, friction raises the force of \
             this disc by up to ×{bound:.2} (fully bonded, 1 + 2S²): the moduli would be \
             overstated by up to that factor"
        );
    }
}
