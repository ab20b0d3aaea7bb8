//! The O-ring: a cord of diameter d on a mean diameter D squeezed by ε (compression/d) between
//! flat plates or in a groove — Lindley's empirical relations for a laterally unrestrained
//! O-ring (P.B. Lindley, "Compression characteristics of laterally-unrestrained rubber
//! O-rings", J. Inst. Rubber Ind. 1 (1967) 209), as written in docs/model.md §6:
//! force per unit length `f = E d (1.25 ε^{3/2} + 50 ε⁶)` \[N/m\], contact width
//! `b = d √(6ε/π)` \[m\], and a Hertz-shaped profile `p(x) = p_max √(1 − (2x/b)²)`,
//! `p_max = 4 f/(π b)`. The constants could not be checked word for word against the
//! original here (docs/model.md marks them "recalled"); what is tested is their own consistency
//! (∫p dx = f) and the stated range: the relations are meant for squeeze up to ≈ 30 %, and
//! sealsim warns beyond (and below 5 %, where the ε⁶ term is irrelevant but the contact is
//! too narrow for a Hertz picture of a real groove).
//!
//! Viscoelasticity enters through the *squeeze function* `g(ε) = 1.25 ε^{3/2} + 50 ε⁶`: the
//! sealing force is `f(t) = d ∫ E(ξ(t) − ξ(s)) dg(ε(s))` (quasi-linear viscoelasticity), so
//! the Prony recursion runs on g rather than on ε.

use super::{
    FlatSeal, PermeationSection, Profile, SealGeometry, SealKind, SetContact, SetInput,
    ThermalStrain, VolumeSwell,
};
use crate::units::human;
use std::f64::consts::PI;

/// Lower and upper squeeze of the range in which Lindley's relations are used without warning.
pub const LINDLEY_RANGE: (f64, f64) = (0.05, 0.30);

/// Lindley's squeeze function `g(ε) = 1.25 ε^{3/2} + 50 ε⁶` (dimensionless); `f = E d g(ε)`.
pub fn squeeze_function(eps: f64) -> f64 {
    let e = eps.max(0.0);
    1.25 * e.powf(1.5) + 50.0 * e.powi(6)
}

/// The squeeze whose [`squeeze_function`] is `load` (≥ 0): g is increasing, so bisection on
/// [0, 1] to the last bit (g(1) = 51.25; larger loads give 1).
pub fn squeeze_from_load(load: f64) -> f64 {
    if load <= 0.0 {
        return 0.0;
    }
    let (lo, hi) =
        sealsim_math::roots::bisect(0.0, 1.0, 64, sealsim_math::roots::to_the_last_bit, |x| {
            squeeze_function(x) < load
        });
    0.5 * (lo + hi)
}

/// O-ring contact width `b = d √(6ε/π)` \[m\].
pub fn oring_contact_width(cross_section: f64, eps: f64) -> f64 {
    cross_section * (6.0 * eps.max(0.0) / PI).sqrt()
}

/// An O-ring ([`SealGeometry::ORing`]): cord diameter d \[m\], mean diameter D \[m\] (sealing
/// length π D), squeeze ε0 at installation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ORing {
    pub cross_section: f64,
    pub mean_diameter: f64,
    pub squeeze: f64,
}

impl SealKind for ORing {
    fn name(&self) -> &'static str {
        "o-ring"
    }

    fn set_quantity(&self) -> &'static str {
        "squeeze of the set ring"
    }

    /// `"O-ring d = 3.53 mm, D = 50 mm, squeeze 20 %"`.
    fn describe(&self, _thermal: bool) -> String {
        format!(
            "O-ring d = {} mm, D = {} mm, squeeze {} %",
            human(self.cross_section * 1e3, 4),
            human(self.mean_diameter * 1e3, 4),
            human(self.squeeze * 100.0, 3)
        )
    }

    /// π D.
    fn sealing_length(&self) -> f64 {
        PI * self.mean_diameter
    }

    /// The squeeze at temperature `t` \[K\] with the thermal strain `thermal`. With gland depth
    /// h and cord d, ε = 1 − h/d; heating by ΔT expands the housing with α_h and the cord by its
    /// free strain e_r(T) ([`ThermalStrain::rubber_strain`]: α_r ΔT above T_g), so
    /// `ε(T) = 1 − (1 − ε0)(1 + α_h ΔT)/(1 + e_r(T)) ≈ ε0 + (1 − ε0)(α_r − α_h) ΔT`
    /// (docs/model.md §6): the compression is referred to the current cord.
    fn squeeze_at(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        match thermal {
            Some(th) => {
                let dt = t - th.installation_temperature;
                1.0 - (1.0 - self.squeeze) * (1.0 + th.housing_expansion * dt)
                    / (1.0 + th.rubber_strain(t))
            }
            None => self.squeeze,
        }
    }

    /// The squeeze ε (the ring's displacement field superposes linearly).
    fn deformation(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        self.squeeze_at(thermal, t)
    }

    /// Lindley's g(ε).
    fn load_variable(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        squeeze_function(self.squeeze_at(thermal, t))
    }

    /// The Hertz profile of force `d · stress` over Lindley's width at the current squeeze.
    fn profile(
        &self,
        stress: f64,
        _instantaneous_modulus: f64,
        thermal: Option<&ThermalStrain>,
        t: f64,
    ) -> Profile {
        let eps = self.squeeze_at(thermal, t);
        let width = oring_contact_width(self.cross_section, eps).max(f64::MIN_POSITIVE);
        Profile::hertz((self.cross_section * stress).max(0.0), width)
    }

    fn squeeze_out_of_range(&self, eps: f64) -> bool {
        !(LINDLEY_RANGE.0..=LINDLEY_RANGE.1).contains(&eps)
    }

    /// Cord λ_s d, squeeze [`VolumeSwell::squeeze`]; the mean diameter (where the ring sits)
    /// is kept.
    fn swollen(&self, swell: &VolumeSwell) -> SealGeometry {
        SealGeometry::ORing {
            cross_section: self.cross_section * swell.linear_stretch(),
            mean_diameter: self.mean_diameter,
            squeeze: swell.squeeze(self.squeeze),
        }
    }

    fn given_pressure(&self) -> Option<f64> {
        None
    }

    fn ring_squeeze(&self) -> Option<f64> {
        Some(self.squeeze)
    }

    fn cooling_length(&self) -> Option<f64> {
        Some(self.cross_section)
    }

    fn fitted(&self) -> bool {
        true
    }

    fn bolted(&self) -> bool {
        false
    }

    fn permeation_section(&self, _thickness: Option<f64>) -> Option<PermeationSection> {
        Some(PermeationSection::Ring {
            cross_section: self.cross_section,
            mean_diameter: self.mean_diameter,
            squeeze: self.squeeze,
        })
    }

    /// The ring set by `s` (clamped below 1) at the shutdown squeeze ε: interference
    /// `(ε − s) d`, remaining squeeze `(ε − s)/(1 − s)` over the recovered cord `d (1 − s)`,
    /// and Lindley's Hertz profile there with the relaxed modulus `E∞ c` (docs/model.md §8.2).
    fn set_contact(&self, set: &SetInput) -> SetContact {
        let squeeze = set.squeeze;
        let s = set.set_strain.clamp(0.0, 1.0 - f64::EPSILON);
        let interference = (squeeze - s) * self.cross_section;
        let remaining = ((squeeze - s) / (1.0 - s)).max(0.0);
        let cord = self.cross_section * (1.0 - s);
        let modulus = set.long_term * set.network;
        let profile = Profile::hertz(
            modulus * cord * squeeze_function(remaining),
            oring_contact_width(cord, remaining).max(f64::MIN_POSITIVE),
        );
        SetContact {
            remaining,
            peak_pressure: profile.peak(),
            touches: interference > set.roughness,
        }
    }

    /// The uniform equivalent of the central strip right after installation: the Hertz peak
    /// as P0, Lindley's contact width as L_x, the circumference π D as L_y.
    fn static_seal(&self, _load: f64, initial: &dyn Fn() -> Profile) -> FlatSeal {
        let profile = initial();
        FlatSeal {
            nominal_pressure: profile.peak(),
            width: profile.width(),
            length: self.sealing_length(),
        }
    }
}
