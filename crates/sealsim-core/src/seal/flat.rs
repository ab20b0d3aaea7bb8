//! The flat seal: uniform nominal pressure P0 over `width × length` (PY08 Fig. 2); under
//! displacement loading a gasket bolted between flanges that hold its thickness at
//! `1 − compression` of the free one, so the thermal strain changes its compression and with
//! it the load (docs/model.md §6, "Thermal strain of a flat gasket").

use super::{
    FlatSeal, PermeationSection, Profile, SealGeometry, SealKind, SetContact, SetInput,
    ThermalStrain, VolumeSwell,
};
use crate::units::human;

/// A flat seal ([`SealGeometry::Flat`]): P0 \[Pa\] right after installation over `width`
/// (L_x) × `length` (L_y) \[m\]; ε0, the installed compression of the free thickness; t_c, the
/// compressed thickness \[m\] when given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Flat {
    pub nominal_pressure: f64,
    pub width: f64,
    pub length: f64,
    pub compression: f64,
    pub thickness: Option<f64>,
}

impl Flat {
    /// The compression at `t` \[K\] over the installed one, ε(T)/ε0, no less than 0 (a gasket
    /// the flanges no longer touch carries no load): 1 at the installation temperature and
    /// without thermal strain.
    fn load(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        self.squeeze_at(thermal, t).max(0.0) / self.compression
    }
}

impl SealKind for Flat {
    fn name(&self) -> &'static str {
        "flat"
    }

    fn set_quantity(&self) -> &'static str {
        "compression of the set gasket"
    }

    /// `"flat, P0 = 2 MPa over 1 mm × 100 mm"`, with `", compression 25 %"` where the thermal
    /// strain changes it.
    fn describe(&self, thermal: bool) -> String {
        format!(
            "flat, P0 = {} MPa over {} mm × {} mm{}",
            human(self.nominal_pressure / 1e6, 4),
            human(self.width * 1e3, 4),
            human(self.length * 1e3, 4),
            // the compression matters where the thermal strain changes it (docs/model.md §6)
            if thermal {
                format!(", compression {} %", human(self.compression * 100.0, 3))
            } else {
                String::new()
            }
        )
    }

    fn sealing_length(&self) -> f64 {
        self.length
    }

    /// The O-ring's relation ([`super::oring::ORing`]) with the free thickness for d and the
    /// flange gap for h, written `ε0 + (1 − ε0)(e_r(T) − α_h ΔT)/(1 + e_r(T))` (the same
    /// number, exactly ε0 at ΔT = 0); without thermal strain it stays ε0.
    fn squeeze_at(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        let compression = self.compression;
        match thermal {
            Some(th) => {
                let dt = t - th.installation_temperature;
                let free = th.rubber_strain(t);
                compression
                    + (1.0 - compression) * (free - th.housing_expansion * dt) / (1.0 + free)
            }
            None => compression,
        }
    }

    /// ε(T)/ε0.
    fn deformation(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        self.load(thermal, t)
    }

    /// ε(T)/ε0, linear in the compression.
    fn load_variable(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        self.load(thermal, t)
    }

    /// P0 × stress/E0, uniform over the width.
    fn profile(
        &self,
        stress: f64,
        instantaneous_modulus: f64,
        _thermal: Option<&ThermalStrain>,
        _t: f64,
    ) -> Profile {
        Profile::Uniform {
            // a gasket the cold has pulled off its flanges presses with nothing, not a tension
            pressure: (self.nominal_pressure * stress / instantaneous_modulus).max(0.0),
            width: self.width,
        }
    }

    /// Lindley's range is an O-ring's.
    fn squeeze_out_of_range(&self, _eps: f64) -> bool {
        false
    }

    /// Unchanged: its nominal pressure is given.
    fn swollen(&self, _swell: &VolumeSwell) -> SealGeometry {
        SealGeometry::Flat {
            nominal_pressure: self.nominal_pressure,
            width: self.width,
            length: self.length,
            compression: self.compression,
            thickness: self.thickness,
        }
    }

    fn given_pressure(&self) -> Option<f64> {
        Some(self.nominal_pressure)
    }

    fn ring_squeeze(&self) -> Option<f64> {
        None
    }

    /// Through its compressed thickness.
    fn cooling_length(&self) -> Option<f64> {
        self.thickness
    }

    fn fitted(&self) -> bool {
        false
    }

    fn bolted(&self) -> bool {
        true
    }

    /// Through the edge of thickness t_c over the land width, around the length.
    fn permeation_section(&self, thickness: Option<f64>) -> Option<PermeationSection> {
        thickness.map(|thickness| PermeationSection::Gasket {
            thickness,
            land_width: self.width,
            circumference: self.length,
        })
    }

    /// With the networks' set `s_λ = y/c` on the load ε/ε0, the set in compression is
    /// `s = s_λ ε0`; the remaining compression over the recovered thickness is
    /// `ε_r = (ε(T_sd) − s)/(1 − s)`, the interference `(ε(T_sd) − s) t_free`
    /// (t_free = t_c/(1 − ε0); without the thickness, the compression `ε(T_sd) − s` itself must
    /// stay positive), and the fully relaxed pressure, linear in the compression like the
    /// gasket's stress, `p = P0 c E∞ (ε(T_sd) − s)/(ε0 E_install)` (docs/model.md §8.2).
    fn set_contact(&self, set: &SetInput) -> SetContact {
        let (squeeze, compression) = (set.squeeze, self.compression);
        let s = (set.set_strain * compression).clamp(0.0, 1.0 - f64::EPSILON);
        let remaining = ((squeeze - s) / (1.0 - s)).max(0.0);
        let touches = match self.thickness {
            Some(t) => (squeeze - s) * t / (1.0 - compression) > set.roughness,
            None => squeeze - s > 0.0,
        };
        let peak = (self.nominal_pressure * set.network * set.long_term * (squeeze - s)
            / (compression * set.installed_modulus))
            .max(0.0);
        SetContact {
            remaining,
            peak_pressure: peak,
            touches,
        }
    }

    /// Its own, at the installation's temperature: the bolted stress with its thermal strain
    /// there, P0 × `load`, as the first state of a life run (exactly P0 without thermal strain).
    fn static_seal(&self, load: f64, _initial: &dyn Fn() -> Profile) -> FlatSeal {
        FlatSeal {
            nominal_pressure: self.nominal_pressure * load,
            width: self.width,
            length: self.length,
        }
    }
}
