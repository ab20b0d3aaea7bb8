//! Seal geometry and loading: the nominal contact-pressure profile across the sealing width.
//!
//! One home per seal kind: [`SealGeometry`] names the kinds (its variants), and each kind's
//! behaviour — sealing length, squeeze or compression and its thermal strain, load variable,
//! pressure profile, swell, permeation section, shutdown contact, its names and its report
//! fragment — is the [`SealKind`] implementation in the kind's own file:
//!
//! * [`flat`]: a flat seal, uniform nominal pressure over `width × length` (PY08 Fig. 2), a
//!   bolted gasket under displacement loading.
//! * [`oring`]: an O-ring of cord diameter d and mean diameter D squeezed by ε between flat
//!   plates or in a groove — Lindley's relations (docs/model.md §6).
//!
//! `SealGeometry::kind` (private) is the one `match` that hands a geometry to its kind (ARCHITECTURE.md,
//! "A new seal kind": a new kind is its variant, one arm there, and its file).

use crate::fluid::FlowGeometry;
use std::f64::consts::PI;

pub mod flat;
pub mod oring;

pub use oring::{LINDLEY_RANGE, oring_contact_width, squeeze_from_load, squeeze_function};

/// A flat seal: uniform nominal pressure over a rectangle `width × length` (PY08 Fig. 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatSeal {
    /// Nominal squeezing pressure P0 \[Pa\].
    pub nominal_pressure: f64,
    /// L_x, the width along the flow \[m\].
    pub width: f64,
    /// L_y, the length across the flow \[m\].
    pub length: f64,
}

impl FlatSeal {
    /// The seal's extent along (L_x = `width`) and across (L_y = `length`) the flow.
    pub fn geometry(&self) -> FlowGeometry {
        FlowGeometry {
            along_flow: self.width,
            across_flow: self.length,
        }
    }
}

/// Where the nominal pressure comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SealGeometry {
    /// Uniform nominal pressure `nominal_pressure` right after installation over
    /// `width` (L_x, along the flow) × `length` (L_y, across it). Under displacement loading
    /// (a bolted gasket) the flanges hold its thickness at `1 − compression` of the free one,
    /// and the thermal strain changes that compression ([`SealGeometry::squeeze_at`]).
    Flat {
        nominal_pressure: f64,
        width: f64,
        length: f64,
        /// ε0, the installed compression of the free thickness, (t_free − t_c)/t_free, at the
        /// installation temperature (docs/model.md §6, "Thermal strain of a flat gasket").
        compression: f64,
        /// t_c, the compressed thickness \[m\] (`None`: not given; the shutdown check then
        /// tests the compression without the interference in metres, §8.2).
        thickness: Option<f64>,
    },
    /// O-ring: cord diameter d, mean diameter D (sealing length π D), squeeze ε0 at installation.
    ORing {
        cross_section: f64,
        mean_diameter: f64,
        squeeze: f64,
    },
}

impl SealGeometry {
    /// The geometry as its kind, the one place that matches on the variants: every method
    /// below calls the kind's [`SealKind`] implementation through it.
    fn kind<R>(&self, f: impl FnOnce(&dyn SealKind) -> R) -> R {
        match *self {
            SealGeometry::Flat {
                nominal_pressure,
                width,
                length,
                compression,
                thickness,
            } => f(&flat::Flat {
                nominal_pressure,
                width,
                length,
                compression,
                thickness,
            }),
            SealGeometry::ORing {
                cross_section,
                mean_diameter,
                squeeze,
            } => f(&oring::ORing {
                cross_section,
                mean_diameter,
                squeeze,
            }),
        }
    }

    /// The kind's name in the outputs (`"flat"`, `"o-ring"`; the JSON summary's `seal_kind`).
    pub fn name(&self) -> &'static str {
        self.kind(|k| k.name())
    }

    /// What the shutdown check keeps of the set seal, for the report: `"squeeze of the set
    /// ring"`, `"compression of the set gasket"` (docs/model.md §8.2).
    pub fn set_quantity(&self) -> &'static str {
        self.kind(|k| k.set_quantity())
    }

    /// The report's description of the geometry, e.g. `"O-ring d = 3.53 mm, D = 50 mm,
    /// squeeze 20 %"`; `thermal`: the run has a thermal strain (a flat gasket then shows its
    /// compression, which the strain changes).
    pub fn describe(&self, thermal: bool) -> String {
        self.kind(|k| k.describe(thermal))
    }

    /// L_y, the sealing length across the flow \[m\] (O-ring: π D).
    pub fn sealing_length(&self) -> f64 {
        self.kind(|k| k.sealing_length())
    }

    /// The squeeze (O-ring) or compression (flat gasket) at temperature `t` \[K\] with the
    /// thermal strain `thermal` (docs/model.md §6): [`oring::ORing::squeeze_at`],
    /// [`flat::Flat::squeeze_at`]; without thermal strain the installed one.
    pub fn squeeze_at(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        self.kind(|k| k.squeeze_at(thermal, t))
    }

    /// The material strain at temperature `t` \[K\] that the chemical networks are stepped with
    /// (docs/model.md §6.5): the squeeze ε for an O-ring (its displacement field superposes
    /// linearly), for a flat seal its compression over the installed one, ε(T)/ε0 (its unit
    /// load at the installation temperature; 1 without thermal strain).
    pub fn deformation(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        self.kind(|k| k.deformation(thermal, t))
    }

    /// The variable the Prony recursion runs on at temperature `t` \[K\]: Lindley's g(ε) for an
    /// O-ring; for a flat seal, linear in its compression, ε(T)/ε0 (1 at the installation
    /// temperature and without thermal strain), so that its pressure is
    /// `P0 σ/E_install` with σ the hereditary stress on it (docs/model.md §6).
    pub fn load_variable(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64 {
        self.kind(|k| k.load_variable(thermal, t))
    }

    /// The nominal profile for the hereditary `stress` \[Pa\] on the load variable, with
    /// `instantaneous_modulus` E0 \[Pa\], at temperature `t` \[K\]: a flat seal's P0 scaled by
    /// stress/E0 over its width; an O-ring's Hertz profile of force `d · stress` over Lindley's
    /// width at the current squeeze (docs/model.md §6).
    pub fn profile(
        &self,
        stress: f64,
        instantaneous_modulus: f64,
        thermal: Option<&ThermalStrain>,
        t: f64,
    ) -> Profile {
        self.kind(|k| k.profile(stress, instantaneous_modulus, thermal, t))
    }

    /// Whether Lindley's relations are used outside their range at squeeze `eps` (an O-ring
    /// only; docs/model.md §9.6).
    pub fn squeeze_out_of_range(&self, eps: f64) -> bool {
        self.kind(|k| k.squeeze_out_of_range(eps))
    }

    /// The seal swollen by `swell` (docs/model.md §3.8; [`VolumeSwell::geometry`]).
    pub fn swollen(&self, swell: &VolumeSwell) -> SealGeometry {
        self.kind(|k| k.swollen(swell))
    }

    /// The nominal pressure P0 \[Pa\] the input gives (a flat seal), `None` where the pressure
    /// follows from the squeeze (an O-ring: `leak` evaluates its installed state, and a moving
    /// ring's inlet gradients come from its Hertz profile).
    pub fn given_pressure(&self) -> Option<f64> {
        self.kind(|k| k.given_pressure())
    }

    /// Whether the contact pressure follows from the squeeze, not a given P0: `given_pressure`
    /// is `None`.
    pub fn pressure_from_squeeze(&self) -> bool {
        self.given_pressure().is_none()
    }

    /// A ring's installed squeeze ε0 (the gland summary's), `None` for a kind without one.
    pub fn ring_squeeze(&self) -> Option<f64> {
        self.kind(|k| k.ring_squeeze())
    }

    /// The length \[m\] heat crosses to reach the seal's middle, for its thermal settling time
    /// d²/a (docs/model.md §5.2): an O-ring's cord, a gasket's compressed thickness (`None`
    /// when not given: cooled at once, the least relaxation on the way, §8.2).
    pub fn cooling_length(&self) -> Option<f64> {
        self.kind(|k| k.cooling_length())
    }

    /// Whether the seal is fitted by squeezing it at its fitting temperature (an O-ring): its
    /// temperature then settles from the fitting one, and a fit below T10 is flagged
    /// (docs/model.md §5.2). A bolted gasket's installation ramp runs at T(0).
    pub fn fitted(&self) -> bool {
        self.kind(|k| k.fitted())
    }

    /// Whether the seal is a gasket held by bolted flanges (a flat seal): bolted at room
    /// temperature at the coldest, and its thermal strain defaults to steel flanges without
    /// needing the rubber's expansion until the temperature departs from the bolting's
    /// (docs/model.md §6).
    pub fn bolted(&self) -> bool {
        self.kind(|k| k.bolted())
    }

    /// The cross-section permeation runs through (docs/model.md §13.3), with a gasket's
    /// compressed `thickness` \[m\] as the caller has it; `None` where it is not known (a
    /// gasket without its thickness).
    pub fn permeation_section(&self, thickness: Option<f64>) -> Option<PermeationSection> {
        self.kind(|k| k.permeation_section(thickness))
    }

    /// The set seal at shutdown (docs/model.md §8.2), see [`SetContact`]: `squeeze` is
    /// [`Self::squeeze_at`] the shutdown temperature, `set_strain` the networks' set on the
    /// load variable, `network` the network factor, `long_term` E∞ \[Pa\],
    /// `installed_modulus` E_install \[Pa\], `roughness` the counterface's rms height \[m\].
    pub fn set_contact(&self, set: &SetInput) -> SetContact {
        self.kind(|k| k.set_contact(set))
    }

    /// The flat seal of the static leak problem (`sealsim leak`): a flat seal's own, with its
    /// pressure P0 × `load` (the load variable at the installation's temperature, exactly 1
    /// without thermal strain); an O-ring's uniform equivalent of its central strip, the peak
    /// and width of the `initial` profile over its circumference π D.
    pub fn static_seal(&self, load: f64, initial: &dyn Fn() -> Profile) -> FlatSeal {
        self.kind(|k| k.static_seal(load, initial))
    }
}

/// What the shutdown check of a set seal needs besides its geometry (docs/model.md §8.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SetInput {
    /// The squeeze or compression at the shutdown temperature.
    pub squeeze: f64,
    /// The networks' set on the load variable.
    pub set_strain: f64,
    /// The network factor c (the fraction of the original network left).
    pub network: f64,
    /// E∞ \[Pa\].
    pub long_term: f64,
    /// The installed modulus E_install \[Pa\].
    pub installed_modulus: f64,
    /// The counterface's rms roughness \[m\].
    pub roughness: f64,
}

/// The set seal at shutdown: what the check of docs/model.md §8.2 compares.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SetContact {
    /// The squeeze (compression) left over the recovered cord (thickness), ε_r.
    pub remaining: f64,
    /// The fully relaxed peak contact pressure \[Pa\].
    pub peak_pressure: f64,
    /// Whether the interference still exceeds the roughness.
    pub touches: bool,
}

/// The cross-section a gas permeates through (docs/model.md §13.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PermeationSection {
    /// A squeezed cord: d, D \[m\] and the squeeze.
    Ring {
        cross_section: f64,
        mean_diameter: f64,
        squeeze: f64,
    },
    /// A gasket's edge: its compressed thickness, the land width along the flow and the
    /// circumference across it \[m\].
    Gasket {
        thickness: f64,
        land_width: f64,
        circumference: f64,
    },
}

/// The behaviour of one seal kind (`SealGeometry::kind` (private) hands a geometry to it); the
/// methods are documented on [`SealGeometry`]'s of the same name.
pub trait SealKind {
    /// See [`SealGeometry::name`].
    fn name(&self) -> &'static str;
    /// See [`SealGeometry::set_quantity`].
    fn set_quantity(&self) -> &'static str;
    /// See [`SealGeometry::describe`].
    fn describe(&self, thermal: bool) -> String;
    /// See [`SealGeometry::sealing_length`].
    fn sealing_length(&self) -> f64;
    /// See [`SealGeometry::squeeze_at`].
    fn squeeze_at(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64;
    /// See [`SealGeometry::deformation`].
    fn deformation(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64;
    /// See [`SealGeometry::load_variable`].
    fn load_variable(&self, thermal: Option<&ThermalStrain>, t: f64) -> f64;
    /// See [`SealGeometry::profile`].
    fn profile(
        &self,
        stress: f64,
        instantaneous_modulus: f64,
        thermal: Option<&ThermalStrain>,
        t: f64,
    ) -> Profile;
    /// See [`SealGeometry::squeeze_out_of_range`].
    fn squeeze_out_of_range(&self, eps: f64) -> bool;
    /// See [`SealGeometry::swollen`].
    fn swollen(&self, swell: &VolumeSwell) -> SealGeometry;
    /// See [`SealGeometry::given_pressure`].
    fn given_pressure(&self) -> Option<f64>;
    /// See [`SealGeometry::ring_squeeze`].
    fn ring_squeeze(&self) -> Option<f64>;
    /// See [`SealGeometry::cooling_length`].
    fn cooling_length(&self) -> Option<f64>;
    /// See [`SealGeometry::fitted`].
    fn fitted(&self) -> bool;
    /// See [`SealGeometry::bolted`].
    fn bolted(&self) -> bool;
    /// See [`SealGeometry::permeation_section`].
    fn permeation_section(&self, thickness: Option<f64>) -> Option<PermeationSection>;
    /// See [`SealGeometry::set_contact`].
    fn set_contact(&self, set: &SetInput) -> SetContact;
    /// See [`SealGeometry::static_seal`].
    fn static_seal(&self, load: f64, initial: &dyn Fn() -> Profile) -> FlatSeal;
}

/// The rubber's equilibrium volume swell in the fluid: ΔV/V0 of ASTM D471 (the volume change of
/// a specimen immersed in the fluid to equilibrium), −0.5 < ΔV/V0 (docs/model.md §3.8).
///
/// * Dimensions: the swell is isotropic, so every free length of the rubber is stretched by
///   `λ_s = (1 + ΔV/V0)^{1/3}` — a free linear strain `λ_s − 1` like the thermal one
///   ([`ThermalStrain`]): the cord d → λ_s d (and a groove-seated ring's inside diameter
///   with it), and the squeeze at a fixed gland depth h = (1 − ε0) d becomes
///   `ε_s = 1 − (1 − ε0)/λ_s` ([`VolumeSwell::squeeze`]).
/// * Modulus: the shear modulus of a swollen network, referred to the swollen dimensions, is
///   `G = G_dry v2^{1/3}`, `v2 = 1/(1 + ΔV/V0)` the polymer's volume fraction (Treloar, *The
///   Physics of Rubber Elasticity*, 3rd ed., Oxford 1975, ch. 7: the swollen network's
///   stress–strain relation; Flory, *Principles of Polymer Chemistry*, 1953, ch. XIII), so
///   every Prony modulus is scaled by `(1 + ΔV/V0)^{−1/3} = 1/λ_s` ([`VolumeSwell::modulus_factor`]).
///   For shrinkage (ΔV/V0 < 0: plasticiser extracted by the fluid) that relation does not
///   apply — the lost volume is plasticiser, not a swelling liquid, and such a compound
///   usually hardens by an amount the volume change does not fix — so only the dimensional
///   change is applied and the modulus is left as it is (factor 1).
///
/// Applied from t = 0 (the equilibrium swell); real swell develops over hours to days.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VolumeSwell {
    /// ΔV/V0 (dimensionless; > −0.5).
    pub volume_change: f64,
}

impl VolumeSwell {
    /// The linear stretch `λ_s = (1 + ΔV/V0)^{1/3}`.
    pub fn linear_stretch(&self) -> f64 {
        (1.0 + self.volume_change).cbrt()
    }

    /// The factor on the moduli: `(1 + ΔV/V0)^{−1/3}` for a swell, 1 for a shrinkage.
    pub fn modulus_factor(&self) -> f64 {
        if self.volume_change > 0.0 {
            1.0 / self.linear_stretch()
        } else {
            1.0
        }
    }

    /// The squeeze of the swollen cord in the gland that squeezed the dry one by `squeeze`:
    /// `ε_s = 1 − (1 − ε0)/λ_s`.
    pub fn squeeze(&self, squeeze: f64) -> f64 {
        1.0 - (1.0 - squeeze) / self.linear_stretch()
    }

    /// An O-ring squeezed between plates, swollen: cord λ_s d, squeeze [`VolumeSwell::squeeze`];
    /// the mean diameter (where the ring sits) is kept. A flat seal is unchanged (its nominal
    /// pressure is given).
    pub fn geometry(&self, geometry: SealGeometry) -> SealGeometry {
        geometry.swollen(self)
    }
}

/// Thermal strain of an O-ring: the cord expands with the rubber's free strain e_r(T), the
/// groove depth with the housing's CTE: `ε(T) = 1 − (1 − ε0)(1 + α_h ΔT)/(1 + e_r(T))`,
/// ΔT = T − T_install ([`SealGeometry::squeeze_at`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalStrain {
    /// Rubber linear CTE α_r \[1/K\] (rubbery: above the glass transition).
    pub rubber_expansion: f64,
    /// Housing linear CTE α_h \[1/K\].
    pub housing_expansion: f64,
    /// Installation temperature \[K\].
    pub installation_temperature: f64,
    /// Rubber linear CTE below the glass transition α_g \[1/K\] (`None`: α_r throughout).
    pub glassy_expansion: Option<f64>,
    /// Glass transition temperature T_g \[K\] at which the CTE changes from α_r to α_g.
    pub glass_transition: Option<f64>,
}

impl ThermalStrain {
    /// The rubber's free linear thermal strain from the installation temperature T_i to `t`
    /// \[K\], `e_r(T) = ∫_{T_i}^{T} α(T') dT'` with α = α_r above T_g and α_g below
    /// (a bilinear length–temperature curve with its kink at T_g, the dilatometric picture of
    /// the glass transition). With the primitive `F(T) = α_r (T − T_g)` for T ≥ T_g and
    /// `α_g (T − T_g)` below, `e_r(T) = F(T) − F(T_i)`, whichever side of T_g T and T_i are.
    /// Without both α_g and T_g it is `α_r (T − T_i)`.
    pub fn rubber_strain(&self, t: f64) -> f64 {
        match (self.glassy_expansion, self.glass_transition) {
            (Some(glassy), Some(tg)) => {
                let primitive = |temp: f64| {
                    let alpha = if temp >= tg {
                        self.rubber_expansion
                    } else {
                        glassy
                    };
                    alpha * (temp - tg)
                };
                primitive(t) - primitive(self.installation_temperature)
            }
            _ => self.rubber_expansion * (t - self.installation_temperature),
        }
    }
}

/// The nominal pressure across the sealing width at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Profile {
    /// Uniform `pressure` \[Pa\] over `width` \[m\].
    Uniform { pressure: f64, width: f64 },
    /// `p(x) = peak √(1 − (2x/b)²)` over `width` b \[m\].
    Hertz { peak: f64, width: f64 },
}

impl Profile {
    /// Sealing force per unit length `∫ p dx` \[N/m\].
    pub fn force_per_length(&self) -> f64 {
        match *self {
            Profile::Uniform { pressure, width } => pressure * width,
            Profile::Hertz { peak, width } => PI / 4.0 * peak * width,
        }
    }

    /// Peak nominal pressure \[Pa\].
    pub fn peak(&self) -> f64 {
        match *self {
            Profile::Uniform { pressure, .. } => pressure,
            Profile::Hertz { peak, .. } => peak,
        }
    }

    /// Mean nominal pressure over the width \[Pa\].
    pub fn mean(&self) -> f64 {
        self.force_per_length() / self.width()
    }

    /// Contact width L_x \[m\].
    pub fn width(&self) -> f64 {
        match *self {
            Profile::Uniform { width, .. } | Profile::Hertz { width, .. } => width,
        }
    }

    /// The profile with the force scaled by `factor` and the width unchanged.
    pub fn scaled(&self, factor: f64) -> Profile {
        match *self {
            Profile::Uniform { pressure, width } => Profile::Uniform {
                pressure: pressure * factor,
                width,
            },
            Profile::Hertz { peak, width } => Profile::Hertz {
                peak: peak * factor,
                width,
            },
        }
    }

    /// The profile with its peak `peak` \[Pa\] and the width unchanged.
    pub fn with_peak(&self, peak: f64) -> Profile {
        match *self {
            Profile::Uniform { width, .. } => Profile::Uniform {
                pressure: peak,
                width,
            },
            Profile::Hertz { width, .. } => Profile::Hertz { peak, width },
        }
    }

    /// Hertz profile of force per length `f` over width `b`: `p_max = 4 f/(π b)`.
    pub fn hertz(force_per_length: f64, width: f64) -> Profile {
        Profile::Hertz {
            peak: 4.0 * force_per_length / (PI * width),
            width,
        }
    }

    /// The profile's extent along the flow (its width L_x) with `sealing_length` L_y across it.
    pub fn geometry(&self, sealing_length: f64) -> FlowGeometry {
        FlowGeometry {
            along_flow: self.width(),
            across_flow: sealing_length,
        }
    }

    /// Resistance per unit width of the profile's strips in series (docs/model.md §3.2),
    /// `R = ∫ dx / σ(p(x))` \[Pa·s/m²\], with the local conductance per unit width `σ(p)`
    /// [m³/(Pa·s)] supplied by the caller (`σ = α u_c(p)³/(12η)`; `0` where sealed); the leak
    /// rate is then `Q̇ = L_y ΔP / R` ([`crate::fluid::Fluid::leak_rate`] with
    /// [`crate::fluid::Conduction::Series`]).
    ///
    /// For the Hertz profile `x = (b/2) sin θ` gives `∫ dx/σ = (b/2) ∫ cos θ / σ(p_max cos θ) dθ`,
    /// a smooth integrand, integrated with `nodes` Gauss–Legendre points over (−π/2, π/2)
    /// (symmetric, so half the points are evaluated). A sealed strip anywhere seals the seal:
    /// `R = ∞`.
    pub fn series_resistance(
        &self,
        rule: &(Vec<f64>, Vec<f64>),
        conductance: impl Fn(f64) -> f64,
    ) -> f64 {
        match *self {
            Profile::Uniform { pressure, width } => {
                let c = conductance(pressure);
                if c <= 0.0 {
                    return f64::INFINITY;
                }
                width / c
            }
            Profile::Hertz { peak, width } => {
                let (x, w) = rule;
                let mut total = 0.0;
                for (xi, wi) in x.iter().zip(w) {
                    if *xi < 0.0 {
                        continue; // symmetric: count each positive node twice
                    }
                    let factor = if *xi == 0.0 { 1.0 } else { 2.0 };
                    let theta = 0.5 * PI * xi;
                    let c = conductance(peak * theta.cos());
                    if c <= 0.0 {
                        return f64::INFINITY;
                    }
                    total += factor * wi * theta.cos() / c;
                }
                0.5 * width * 0.5 * PI * total
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::{Conduction, Fluid};
    use crate::math::quadrature::gauss_legendre;

    /// `Q̇` of `profile` by the leak law, strips in series.
    fn series_leak_rate(
        profile: &Profile,
        sealing_length: f64,
        pressure_difference: f64,
        rule: &(Vec<f64>, Vec<f64>),
        conductance: impl Fn(f64) -> f64,
    ) -> f64 {
        let fluid = Fluid {
            viscosity: 1e-3,
            pressure_difference,
            law: crate::fluid::ViscosityLaw::Constant,
            gas: None,
        };
        let resistance = profile.series_resistance(rule, conductance);
        fluid.leak_rate(
            profile.geometry(sealing_length),
            Conduction::Series { resistance },
        )
    }

    #[test]
    fn hertz_profile_carries_its_force() {
        let p = Profile::hertz(1000.0, 2e-3);
        assert!((p.force_per_length() - 1000.0).abs() < 1e-9);
        assert!((p.peak() - 4.0 * 1000.0 / (PI * 2e-3)).abs() < 1e-6);
        assert!((p.mean() * 4.0 / PI - p.peak()).abs() < 1e-6);
    }

    #[test]
    fn uniform_conductance_gives_the_flat_formula() {
        // σ constant → Q̇ = L_y ΔP σ / b, for both profile kinds
        let rule = gauss_legendre(16);
        let flat = Profile::Uniform {
            pressure: 1e5,
            width: 1e-3,
        };
        let q = series_leak_rate(&flat, 0.1, 1e4, &rule, |_| 2e-12);
        assert!((q / (0.1 * 1e4 * 2e-12 / 1e-3) - 1.0).abs() < 1e-14);
        let hertz = Profile::hertz(100.0, 1e-3);
        let qh = series_leak_rate(&hertz, 0.1, 1e4, &rule, |_| 2e-12);
        assert!(
            (qh / q - 1.0).abs() < 1e-12,
            "∫cos θ dθ over (−π/2, π/2) = 2"
        );
    }

    #[test]
    fn series_resistance_matches_closed_form_for_linear_conductance_law() {
        // σ(p) = c/p ⇒ ∫ dx p(x)/c = f/c exactly
        let rule = gauss_legendre(32);
        let hertz = Profile::hertz(250.0, 1.5e-3);
        let c = 3e-7;
        let q = series_leak_rate(&hertz, 1.0, 1.0, &rule, |p| c / p);
        assert!((q / (c / 250.0) - 1.0).abs() < 1e-12, "{q}");
    }

    #[test]
    fn a_sealed_strip_seals_the_seal() {
        let rule = gauss_legendre(16);
        let hertz = Profile::hertz(250.0, 1.5e-3);
        let q = series_leak_rate(&hertz, 1.0, 1.0, &rule, |p| {
            if p > 0.9 * hertz.peak() { 0.0 } else { 1e-12 }
        });
        assert_eq!(q, 0.0);
    }

    #[test]
    fn thermal_strain_refers_the_compression_to_the_current_cord() {
        // NBR cord (α_r = 2.3e-4 1/K) in a steel gland (α_h = 1.2e-5 1/K), 25 % squeeze at 23 °C,
        // cooled to −42 °C (ΔT = −65 K). By hand: h/d = 0.75; h' = h (1 − 7.8e-4),
        // d' = d (1 − 0.01495): ε' = 1 − 0.75 × 0.99922/0.98505 = 0.2392111…
        let ring = SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze: 0.25,
        };
        let th = ThermalStrain {
            rubber_expansion: 2.3e-4,
            housing_expansion: 1.2e-5,
            installation_temperature: 296.15,
            glassy_expansion: None,
            glass_transition: None,
        };
        let eps = ring.squeeze_at(Some(&th), 296.15 - 65.0);
        let by_hand = 1.0 - 0.75 * (1.0 - 65.0 * 1.2e-5) / (1.0 - 65.0 * 2.3e-4);
        assert!((eps - by_hand).abs() < 1e-15, "{eps}");
        assert!((eps - 0.239_211).abs() < 1e-6, "{eps}");
        // first order: Δε = (1 − ε0)(α_r − α_h) ΔT = −0.0106275; the old form
        // (α_r − α_h (1 − ε0)) ΔT = −0.014365 overstated it by 35 %
        assert!(((eps - 0.25) / -0.010_627_5 - 1.0).abs() < 0.02);
        assert_eq!(ring.squeeze_at(Some(&th), 296.15), 0.25);
        assert_eq!(ring.squeeze_at(None, 200.0), 0.25);
    }

    /// A cord with α_r = 1.65e-4, α_g = 5.5e-5 1/K and T_g = −34 °C, installed at `install` \[K\].
    fn glassy(install: f64) -> ThermalStrain {
        ThermalStrain {
            rubber_expansion: 1.65e-4,
            housing_expansion: 1.2e-5,
            installation_temperature: install,
            glassy_expansion: Some(5.5e-5),
            glass_transition: Some(239.15),
        }
    }

    #[test]
    fn rubber_strain_is_the_integral_of_the_piecewise_cte() {
        let (ar, ag, tg) = (1.65e-4, 5.5e-5, 239.15);
        // installed at 23 °C, cooled to −60 °C: 57 K rubbery, then 26 K glassy
        let th = glassy(296.15);
        let by_hand = -ar * 57.0 - ag * 26.0;
        assert!((th.rubber_strain(213.15) - by_hand).abs() < 1e-15);
        // installed in the glass at −60 °C, heated to 23 °C: the same path backwards
        let cold = glassy(213.15);
        assert!((cold.rubber_strain(296.15) + by_hand).abs() < 1e-15);
        // both temperatures below T_g: α_g only; both above: α_r only
        assert!((cold.rubber_strain(223.15) - ag * 10.0).abs() < 1e-15);
        assert!((th.rubber_strain(306.15) - ar * 10.0).abs() < 1e-15);
        // continuous at T_g (and its slope drops from α_r to α_g there)
        let at = th.rubber_strain(tg);
        for h in [1e-6, 1e-3] {
            assert!((th.rubber_strain(tg + h) - at - ar * h).abs() < 1e-15);
            assert!((th.rubber_strain(tg - h) - at + ag * h).abs() < 1e-15);
        }
        // a glassy cord contracts less than a rubbery one would: the squeeze is kept better
        let ring = SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze: 0.25,
        };
        let rubbery = ThermalStrain {
            glassy_expansion: None,
            ..th
        };
        let eps = ring.squeeze_at(Some(&th), 213.15);
        let by_hand = 1.0 - 0.75 * (1.0 - 83.0 * 1.2e-5) / (1.0 + by_hand);
        assert!((eps - by_hand).abs() < 1e-15, "{eps}");
        assert!(eps > ring.squeeze_at(Some(&rubbery), 213.15));
    }

    #[test]
    fn above_the_glass_transition_the_squeeze_is_the_rubbery_one() {
        // identical (to rounding) to α_r ΔT when the temperature stays above T_g
        let ring = SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze: 0.25,
        };
        let th = glassy(296.15);
        let plain = ThermalStrain {
            glassy_expansion: None,
            glass_transition: None,
            ..th
        };
        for t in [240.0, 260.0, 296.15, 350.0, 420.0] {
            let dt = t - 296.15;
            let today = 1.0 - 0.75 * (1.0 + 1.2e-5 * dt) / (1.0 + 1.65e-4 * dt);
            assert!((ring.squeeze_at(Some(&th), t) - today).abs() < 1e-15, "{t}");
            assert_eq!(ring.squeeze_at(Some(&plain), t), today, "{t}");
        }
    }

    #[test]
    fn volume_swell_stretches_the_cord_and_softens_the_network() {
        // 20 % swell: λ_s = 1.2^{1/3} = 1.062659, moduli × 1/λ_s = 0.941036
        let s = VolumeSwell { volume_change: 0.2 };
        assert!((s.linear_stretch() - 1.062_659).abs() < 1e-6);
        assert!((s.modulus_factor() - 0.941_036).abs() < 1e-6);
        // a 20 % squeeze: h/d = 0.8 → ε = 1 − 0.8/1.062659 = 0.247172
        let ring = SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze: 0.2,
        };
        let SealGeometry::ORing {
            cross_section,
            mean_diameter,
            squeeze,
        } = s.geometry(ring)
        else {
            panic!()
        };
        assert!((squeeze - 0.247_172).abs() < 1e-6, "{squeeze}");
        assert!((cross_section / 3.53e-3 - 1.062_659).abs() < 1e-6);
        assert_eq!(mean_diameter, 0.05);
        // the gland depth is kept: (1 − ε) d is the dry one's
        assert!(((1.0 - squeeze) * cross_section - 0.8 * 3.53e-3).abs() < 1e-15);
        // shrinkage: the dimensions only
        let shrink = VolumeSwell {
            volume_change: -0.1,
        };
        assert_eq!(shrink.modulus_factor(), 1.0);
        assert!(shrink.squeeze(0.2) < 0.2);
        // a flat seal is unchanged
        let flat = SealGeometry::Flat {
            nominal_pressure: 1e6,
            width: 1e-3,
            length: 0.1,
            compression: 0.25,
            thickness: None,
        };
        assert_eq!(s.geometry(flat), flat);
    }

    #[test]
    fn lindley_relations() {
        assert_eq!(squeeze_function(0.0), 0.0);
        let e: f64 = 0.2;
        assert!((squeeze_function(e) - (1.25 * e.powf(1.5) + 50.0 * e.powi(6))).abs() < 1e-15);
        assert!((oring_contact_width(3.53e-3, 0.2) - 3.53e-3 * (1.2 / PI).sqrt()).abs() < 1e-15);
        let g = SealGeometry::ORing {
            cross_section: 3.53e-3,
            mean_diameter: 0.05,
            squeeze: 0.2,
        };
        assert!((g.sealing_length() - PI * 0.05).abs() < 1e-15);
        assert!(
            !g.squeeze_out_of_range(0.2)
                && g.squeeze_out_of_range(0.35)
                && g.squeeze_out_of_range(0.02)
        );
    }
}
