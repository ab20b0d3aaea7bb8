//! Reciprocating rod seals at working speed: inverse hydrodynamic lubrication (IHL;
//! docs/model.md §3.4.1).
//!
//! # The theory, derived here
//!
//! Blok's *inverse* problem [recalled: Blok; used for reciprocating rod seals in Müller & Nau,
//! *Fluid Sealing Technology*, Marcel Dekker 1998 — not read here, the derivation below is
//! sealsim's own]: the contact pressure p(x) under a soft seal is fixed by the seal's
//! deformation (its dry contact-pressure profile), and the film h(x) adjusts to it. The rod
//! slides at speed v, the rubber is at rest; x points along the rod's motion.
//!
//! * **Reynolds, 1-D, steady** (Couette + Poiseuille, per unit circumference):
//!   `q = v h/2 − h³/(12η) dp/dx` \[m²/s\], the same at every x.
//! * **At the pressure maximum** dp/dx = 0, so `q = v h*/2` with h* the film there: the
//!   Couette flow alone passes the peak.
//! * Hence everywhere `dp/dx = 6ηv (h − h*)/h³`. On the *inlet* side (before the peak, dp/dx > 0)
//!   this is largest over h at `h = 3h*/2`, where `(h − h*)/h³ = 4/(27 h*²)`, so the profile's
//!   steepest inlet gradient is `w = (8/9) η v/h*²`. The film that fits the given profile is
//!
//!   `h* = √(8 η v / (9 w))` \[m\] ([`film_thickness`]).
//!
//! * **Carried film.** The flux q leaves the contact as a film on the rod moving at v, so its
//!   thickness is `q/v = h*/2` ([`carried_film`]); one stroke of length S moves
//!   `V = L_y S h*/2` \[m³\] (L_y = π D the rod circumference) through the seal.
//!
//! **Strokes.** Out-stroke (rod leaving the cylinder, v0 > 0 in [`super`]'s convention): the
//! inlet is the pressurised side, `w_out` the steepest rise of p(x) on the fluid side, film
//! `h_out = √(8ηv_out/(9 w_out))`, volume out `V_out = L_y S h_out/2`. In-stroke: the inlet is
//! the air side, `w_in` the steepest rise of p seen from the air side, `h_in` likewise; the
//! in-stroke can return at most what the out-stroke left on the rod (**starvation**: the air
//! side is dry, the rod carries only the out-stroke's film back to the seal), so the return is
//! `V_back = min(L_y S h_in/2, V_out)`. Net per cycle, positive = leaked out:
//!
//! `V_net = V_out − V_back = L_y S (h_out − min(h_in, h_out))/2 = π D S max(h_out − h_in, 0)/2`
//! for equal stroke lengths (the issue's `π D·stroke·(h_out − h_in)/2` with the starvation
//! cap: a seal whose in-stroke film is the thicker one pumps back all it let out, net 0).
//!
//! **Regimes** ([`ihl_weight`]). The low-speed theory of [`super`] holds below the onset
//! `v_t = min(v_b, v_Λ)` of each stroke: `v_b` PY08's speed bound (second eq. 17: above it the
//! drag pressure opens the critical constriction), `v_Λ = 9 w σ²/(8η)` the speed at which that
//! stroke's IHL film reaches the rms roughness σ (above it the film, not the asperity contact,
//! carries the seal; a sealed static contact has `v_b = ∞` but still floats at speed). From
//! `v_t` to `TRANSITION_FACTOR · v_t` the stroke's volume is blended linearly in `log v` from
//! the low-speed to the IHL value (weight 0 → 1), so the volumes are continuous in the speed;
//! above, IHL alone. Onset and band are a **model choice**: nothing in PY08 or in the IHL
//! theory fixes them.
//!
//! **Film parameter** Λ = h*/σ with σ the rms roughness of the contact ([`FilmRegime`]):
//! Λ < 1 boundary, 1 ≤ Λ < 3 mixed, Λ ≥ 3 full film [recalled: the usual lubrication-regime
//! classification]. PY08 §8's premise (roughness on the rubber, the rod smooth) is kept in the
//! low-speed part; the IHL film is a smooth-surface result, so at Λ < 3 it is an estimate.

use std::fmt;

/// Upper end of the blend band over PY08's speed bound: IHL alone above
/// `TRANSITION_FACTOR · v_b` (module docs; a model choice).
pub const TRANSITION_FACTOR: f64 = 10.0;

/// Slope of the Hertz quarter-ellipse `p = Δp √(1 − (ξ/a)²)` at half its rise, in units of
/// `Δp/a`: `√3` (at `p = Δp/2`, `ξ/a = √3/2`, `|dp/dξ| = (Δp/a)(ξ/a)/√(1 − (ξ/a)²)`).
/// The O-ring's finite-gradient estimate ([`InletGradients::oring_estimate`]).
pub const HERTZ_HALF_RISE_SLOPE: f64 = 1.732_050_807_568_877_2;

/// `h* = √(8 η v / (9 w))` \[m\]: the film under the pressure maximum for viscosity η \[Pa·s\],
/// speed v \[m/s\] and the steepest inlet pressure gradient w \[Pa/m\] (module docs; derived).
/// 0 unless all three are positive and finite.
pub fn film_thickness(viscosity: f64, speed: f64, gradient: f64) -> f64 {
    let ok = |x: f64| x > 0.0 && x.is_finite();
    if !(ok(viscosity) && ok(speed) && ok(gradient)) {
        return 0.0;
    }
    (8.0 * viscosity * speed / (9.0 * gradient)).sqrt()
}

/// The film the rod carries out of the contact, `h*/2` \[m\]: the flux `q = v h*/2` at the
/// pressure maximum spread over a film moving at v.
pub fn carried_film(film: f64) -> f64 {
    0.5 * film
}

/// The steepest inlet gradients of a contact-pressure profile \[Pa/m\], both > 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InletGradients {
    /// Out-stroke inlet: the steepest rise of p(x) on the pressurised side \[Pa/m\].
    pub out_stroke: f64,
    /// In-stroke inlet: the steepest rise of p(x) seen from the air side \[Pa/m\].
    pub in_stroke: f64,
}

impl InletGradients {
    /// The estimate for an O-ring without a given profile (a **model choice**, warned): the
    /// Hertz profile has infinite slope at its edges (h* = 0), so each flank is taken as a
    /// Hertz quarter-ellipse over the half width `b/2` from its edge pressure to the peak, and
    /// its gradient read at half its rise: `w = √3 · rise/(b/2)`. The rises include the fluid
    /// pressure: with the energised peak `p_peak` (squeeze + k_e ΔP), the pressurised side rises
    /// from ΔP to p_peak, the air side from 0: `w_out = 2√3 (p_peak − ΔP)/b`,
    /// `w_in = 2√3 p_peak/b` \[Pa/m\]. `None` unless the peak exceeds ΔP and the width is
    /// positive.
    pub fn oring_estimate(peak: f64, width: f64, pressure_difference: f64) -> Option<Self> {
        let dp = pressure_difference.max(0.0);
        let ok = |x: f64| x > 0.0 && x.is_finite();
        if !(ok(width) && ok(peak) && peak > dp) {
            return None;
        }
        let k = 2.0 * HERTZ_HALF_RISE_SLOPE / width;
        Some(InletGradients {
            out_stroke: k * (peak - dp),
            in_stroke: k * peak,
        })
    }
}

/// Where a scenario's inlet gradients come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GradientSource {
    /// `[motion] inlet_gradient_out` / `inlet_gradient_in`.
    Given,
    /// `[motion] contact_profile`: a tabulated p(x) ([`ContactProfile`]).
    Profile,
    /// The O-ring's Hertz profile ([`InletGradients::oring_estimate`], warned).
    ORingEstimate,
}

impl GradientSource {
    /// The identifier in outputs.
    pub fn id(self) -> &'static str {
        match self {
            GradientSource::Given => "given",
            GradientSource::Profile => "profile",
            GradientSource::ORingEstimate => "oring_estimate",
        }
    }
}

/// A tabulated contact-pressure profile p(x): x \[m\] strictly increasing from the pressurised
/// side to the air side, p \[Pa\] ≥ 0, at least 3 points, its maximum strictly inside.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactProfile {
    x: Vec<f64>,
    p: Vec<f64>,
}

/// Why a profile is refused: the 0-based index of the offending point, and what is wrong.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileError {
    pub index: Option<usize>,
    pub message: String,
}

impl fmt::Display for ProfileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl ContactProfile {
    /// Checks and keeps the table (see the type's docs).
    pub fn new(x: Vec<f64>, p: Vec<f64>) -> Result<Self, ProfileError> {
        let err = |index: Option<usize>, message: String| ProfileError { index, message };
        if x.len() != p.len() {
            return Err(err(None, format!("{} x but {} p values", x.len(), p.len())));
        }
        if x.len() < 3 {
            return Err(err(
                None,
                format!("a profile needs at least 3 points, found {}", x.len()),
            ));
        }
        for i in 0..x.len() {
            if !(x[i].is_finite() && p[i].is_finite()) {
                return Err(err(Some(i), "x and p must be finite".into()));
            }
            if p[i] < 0.0 {
                return Err(err(
                    Some(i),
                    format!("the contact pressure must not be negative, got {} Pa", p[i]),
                ));
            }
            if i > 0 && x[i] <= x[i - 1] {
                return Err(err(
                    Some(i),
                    format!(
                        "x must increase strictly from row to row (sorted from the pressurised \
                         side to the air side), got {} m after {} m",
                        x[i],
                        x[i - 1]
                    ),
                ));
            }
        }
        let profile = ContactProfile { x, p };
        let k = profile.peak_index();
        if k == 0 || k == profile.x.len() - 1 {
            return Err(err(
                Some(k),
                "the pressure maximum must lie strictly inside the table (a rise on both sides)"
                    .into(),
            ));
        }
        Ok(profile)
    }

    /// Index of the (first) maximum of p.
    pub fn peak_index(&self) -> usize {
        let mut k = 0;
        for i in 1..self.p.len() {
            if self.p[i] > self.p[k] {
                k = i;
            }
        }
        k
    }

    /// The peak pressure \[Pa\].
    pub fn peak(&self) -> f64 {
        self.p[self.peak_index()]
    }

    /// The steepest inlet gradients of the piecewise-linear table: the largest segment slope
    /// `(p_{i+1} − p_i)/(x_{i+1} − x_i)` before the peak (out-stroke) and the largest
    /// `−slope` after it (in-stroke) \[Pa/m\]. Exact for straight flanks; a sampled smooth
    /// flank converges as the table is refined.
    pub fn inlet_gradients(&self) -> InletGradients {
        let k = self.peak_index();
        let slope = |i: usize| (self.p[i + 1] - self.p[i]) / (self.x[i + 1] - self.x[i]);
        let out_stroke = (0..k).map(slope).fold(0.0_f64, f64::max);
        let in_stroke = (k..self.x.len() - 1)
            .map(|i| -slope(i))
            .fold(0.0_f64, f64::max);
        InletGradients {
            out_stroke,
            in_stroke,
        }
    }
}

/// The speed at which the IHL film reaches the rms roughness σ (Λ = 1):
/// `v_Λ = 9 w σ²/(8η)` \[m/s\] (the inverse of [`film_thickness`]). +∞ when it is undefined
/// (no gradient, no viscosity), 0 for a smooth surface.
pub fn film_onset_speed(viscosity: f64, gradient: f64, roughness: f64) -> f64 {
    if !(viscosity > 0.0 && gradient > 0.0 && gradient.is_finite()) {
        return f64::INFINITY;
    }
    9.0 * gradient * roughness.max(0.0).powi(2) / (8.0 * viscosity)
}

/// Where the low-speed theory is left (a **model choice**, module docs): the lower of PY08's
/// speed bound and the speed at which the IHL film reaches the roughness,
/// `min(v_b, v_Λ)` \[m/s\].
pub fn transition_onset(speed_bound: f64, film_onset: f64) -> f64 {
    speed_bound.min(film_onset)
}

/// The weight of the IHL result at `speed` for the onset `onset` \[m/s\]
/// ([`transition_onset`]): 0 at and below the onset, 1 at and above `TRANSITION_FACTOR ×` the
/// onset, linear in `log v` between (continuous in v). An infinite onset gives 0, a zero onset
/// 1 (for v > 0).
pub fn ihl_weight(speed: f64, onset: f64) -> f64 {
    if speed.is_nan() || speed <= 0.0 || onset.is_nan() || onset == f64::INFINITY {
        return 0.0;
    }
    if onset <= 0.0 {
        return 1.0;
    }
    if speed <= onset {
        return 0.0;
    }
    ((speed / onset).ln() / TRANSITION_FACTOR.ln()).clamp(0.0, 1.0)
}

/// The lubrication regime of a film against the contact's rms roughness (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FilmRegime {
    /// Λ < 1.
    Boundary,
    /// 1 ≤ Λ < 3.
    Mixed,
    /// Λ ≥ 3.
    FullFilm,
}

impl FilmRegime {
    /// The regime of film parameter `lambda` = h*/σ.
    pub fn of(lambda: f64) -> Self {
        if lambda >= 3.0 {
            FilmRegime::FullFilm
        } else if lambda >= 1.0 {
            FilmRegime::Mixed
        } else {
            FilmRegime::Boundary
        }
    }

    /// The identifier in outputs.
    pub fn id(self) -> &'static str {
        match self {
            FilmRegime::Boundary => "boundary",
            FilmRegime::Mixed => "mixed",
            FilmRegime::FullFilm => "full_film",
        }
    }
}

/// The speed regime of a stroke cycle (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpeedRegime {
    /// Both strokes at or below PY08's speed bound: the low-speed theory (weight 0).
    LowSpeed,
    /// A stroke within the blend band.
    Transition,
    /// Both strokes above the band: IHL alone (weight 1).
    Ihl,
    /// No inlet gradients (a flat seal without a profile), or constant sliding (which stays
    /// with the low-speed theory): the low-speed theory at any speed.
    NoProfile,
}

impl SpeedRegime {
    /// The identifier in outputs.
    pub fn id(self) -> &'static str {
        match self {
            SpeedRegime::LowSpeed => "low_speed",
            SpeedRegime::Transition => "transition",
            SpeedRegime::Ihl => "inverse_hydrodynamic",
            SpeedRegime::NoProfile => "low_speed_no_profile",
        }
    }
}

/// The IHL films and volumes of one stroke cycle (module docs), all SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IhlCycle {
    /// The inlet gradients used \[Pa/m\].
    pub gradients: InletGradients,
    /// Where they came from.
    pub source: GradientSource,
    /// Out-stroke film under the pressure maximum `h_out = √(8ηv_out/(9 w_out))` \[m\].
    pub out_film: f64,
    /// In-stroke film `h_in = √(8ηv_in/(9 w_in))` \[m\].
    pub in_film: f64,
    /// Carried out on the out-stroke, `L_y S h_out/2` \[m³\].
    pub out_volume: f64,
    /// Returned on the in-stroke, `min(L_y S h_in/2, out_volume)` \[m³\] (≥ 0; starvation cap).
    pub back_volume: f64,
    /// Whether the starvation cap acted (`h_in > h_out`: the seal pumps back all it let out).
    pub starved: bool,
    /// Film parameter `min(h_out, h_in)/σ` (σ the contact's rms roughness).
    pub film_parameter: f64,
    /// The speeds at which each stroke's film reaches σ, `(v_Λ,out, v_Λ,in)` \[m/s\]
    /// ([`film_onset_speed`]).
    pub film_onset_speeds: (f64, f64),
}

impl IhlCycle {
    /// The IHL cycle of a seal of sealing length `sealing_length` L_y \[m\] (π D), stroke S
    /// \[m\], speeds \[m/s\], viscosity η \[Pa·s\], inlet gradients and rms roughness σ \[m\].
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        gradients: InletGradients,
        source: GradientSource,
        viscosity: f64,
        sealing_length: f64,
        stroke: f64,
        out_speed: f64,
        in_speed: f64,
        roughness: f64,
    ) -> Self {
        let out_film = film_thickness(viscosity, out_speed, gradients.out_stroke);
        let in_film = film_thickness(viscosity, in_speed, gradients.in_stroke);
        let swept = sealing_length * stroke;
        let out_volume = swept * carried_film(out_film);
        let capacity = swept * carried_film(in_film);
        let film_parameter = if roughness > 0.0 {
            out_film.min(in_film) / roughness
        } else {
            f64::INFINITY
        };
        IhlCycle {
            gradients,
            source,
            out_film,
            in_film,
            out_volume,
            back_volume: capacity.min(out_volume),
            starved: capacity > out_volume,
            film_parameter,
            film_onset_speeds: (
                film_onset_speed(viscosity, gradients.out_stroke, roughness),
                film_onset_speed(viscosity, gradients.in_stroke, roughness),
            ),
        }
    }

    /// `out_volume − back_volume` \[m³\] ≥ 0: leaked per cycle.
    pub fn net_volume(&self) -> f64 {
        self.out_volume - self.back_volume
    }

    /// The lubrication regime of the thinner film.
    pub fn film_regime(&self) -> FilmRegime {
        FilmRegime::of(self.film_parameter)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_rise_slope_is_root_three() {
        assert!((HERTZ_HALF_RISE_SLOPE - 3f64.sqrt()).abs() < 1e-15);
        // the Hertz quarter-ellipse's slope at half rise, from its derivative
        let xi = 3f64.sqrt() / 2.0;
        assert!((xi / (1.0 - xi * xi).sqrt() - HERTZ_HALF_RISE_SLOPE).abs() < 1e-12);
    }

    #[test]
    fn weight_is_continuous_and_monotone() {
        let b = 1e-6;
        assert_eq!(ihl_weight(b, b), 0.0);
        assert_eq!(ihl_weight(0.5 * b, b), 0.0);
        assert_eq!(ihl_weight(TRANSITION_FACTOR * b, b), 1.0);
        assert!((ihl_weight(TRANSITION_FACTOR.sqrt() * b, b) - 0.5).abs() < 1e-12);
        assert_eq!(ihl_weight(1.0, f64::INFINITY), 0.0);
        assert_eq!(ihl_weight(1.0, 0.0), 1.0);
        assert_eq!(ihl_weight(0.0, 0.0), 0.0);
        // the onset speed is the inverse of the film: h*(v_Λ) = σ
        let (eta, w, sigma) = (0.03, 4e9, 2.5e-7);
        let v = film_onset_speed(eta, w, sigma);
        assert!((film_thickness(eta, v, w) / sigma - 1.0).abs() < 1e-12);
        let mut last = 0.0;
        for k in 0..200 {
            let w = ihl_weight(b * 10f64.powf(-0.5 + 2.0 * k as f64 / 199.0), b);
            assert!(w >= last);
            last = w;
        }
    }

    #[test]
    fn profiles_are_checked() {
        let bad = |x: Vec<f64>, p: Vec<f64>| ContactProfile::new(x, p).unwrap_err();
        assert_eq!(bad(vec![0.0, 2.0, 1.0], vec![0.0, 1.0, 0.0]).index, Some(2));
        assert_eq!(
            bad(vec![0.0, 1.0, 2.0], vec![0.0, -1.0, 0.0]).index,
            Some(1)
        );
        assert_eq!(bad(vec![0.0, 1.0, 2.0], vec![0.0, 1.0, 2.0]).index, Some(2));
        assert_eq!(bad(vec![0.0, 1.0], vec![0.0, 1.0]).index, None);
    }
}
