//! Failure criteria (docs/model.md §8) and the power-law interpolation used between time steps.

use crate::surface::expm1_over_x;

/// Two failure events within this fraction of their time count as simultaneous: the run
/// reports the earlier time and the mode that comes first in the tie order (the damage first;
/// docs/model.md §8). A thousandth is the precision a summary states a time with (three
/// figures), far above the location's 1e-12, and far below any physical separation of causes.
pub const SIMULTANEOUS_EVENTS: f64 = 1e-3;

/// Which criterion ended the seal's life.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FailureMode {
    LeakRate,
    LeakedVolume,
    RetainedForce,
    /// Compression set above its limit (ageing).
    CompressionSet,
    LiftOff,
    /// The ring extrudes into the clearance gap (docs/model.md §6.3).
    Extrusion,
    /// At the shutdown condition (docs/model.md §8.2) the set, cooled ring no longer closes
    /// the roughness, or cannot hold the minimum pressure difference at a restart.
    LostInterference,
    /// The sealing force per unit length below an absolute minimum (docs/model.md §8).
    SealingForce,
    /// The installed contact pressure below an absolute minimum, or below m·ΔP (§8).
    ContactPressure,
    /// The rubber colder than its low-temperature limit T10 by more than the margin of
    /// practice (docs/model.md §8.3).
    LowTemperature,
}

impl FailureMode {
    pub const ALL: [FailureMode; 10] = [
        FailureMode::LeakRate,
        FailureMode::LeakedVolume,
        FailureMode::RetainedForce,
        FailureMode::CompressionSet,
        FailureMode::LiftOff,
        FailureMode::Extrusion,
        FailureMode::LostInterference,
        FailureMode::SealingForce,
        FailureMode::ContactPressure,
        FailureMode::LowTemperature,
    ];

    /// The mode of its [`FailureMode::as_str`] name.
    pub fn from_name(name: &str) -> Option<FailureMode> {
        FailureMode::ALL.into_iter().find(|m| m.as_str() == name)
    }

    pub fn as_str(self) -> &'static str {
        match self {
            FailureMode::LeakRate => "leak_rate",
            FailureMode::LeakedVolume => "leaked_volume",
            FailureMode::RetainedForce => "retained_force",
            FailureMode::CompressionSet => "compression_set",
            FailureMode::LiftOff => "lift_off",
            FailureMode::Extrusion => "extrusion",
            FailureMode::LostInterference => "lost_interference",
            FailureMode::SealingForce => "sealing_force",
            FailureMode::ContactPressure => "contact_pressure",
            FailureMode::LowTemperature => "low_temperature",
        }
    }
}

/// When and how the seal failed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FailureEvent {
    /// Time to failure \[s\].
    pub time: f64,
    pub mode: FailureMode,
}

/// The scenario's failure criteria; any subset, the first event wins.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FailureCriteria {
    /// Leak rate above this \[m³/s\].
    pub max_leak_rate: Option<f64>,
    /// Cumulative leaked volume above this \[m³\].
    pub max_leaked_volume: Option<f64>,
    /// Sealing force below this fraction of its value at `retained_force_reference`.
    pub min_retained_force: Option<f64>,
    /// The time after installation the retained force is referred to \[s\] (ISO 3384 practice:
    /// 30 min; 0: right after installation).
    pub retained_force_reference: f64,
    /// Compression set (ASTM D395 definition) above this fraction.
    pub max_compression_set: Option<f64>,
    /// The sealing force per unit length `∫ p_sq dx` below this \[N/m\] (absolute: a
    /// tolerance that lowers the squeeze lowers the life).
    pub min_sealing_force: Option<f64>,
    /// The installed (squeeze) peak contact pressure below this \[Pa\].
    pub min_contact_pressure: Option<f64>,
    /// The gasket factor m: the installed mean contact pressure below m·ΔP (the gasket
    /// practice of ASME VIII Div. 1 Appendix 2, whose operating load keeps a contact stress m·P
    /// on the gasket; docs/model.md §8).
    pub gasket_factor: Option<f64>,
    /// The fluid pressure opens the contact across the whole width (docs/model.md §3.6).
    pub lift_off: bool,
    /// A groove-seated ring's clearance gap beyond the extrusion chart's limit (§6.3).
    pub extrusion: bool,
    /// The shutdown check of an O-ring under displacement loading (§8.2): `None` when waived
    /// (`[failure] lost_interference = false`).
    pub shutdown: Option<Shutdown>,
    /// The cold limit of practice (docs/model.md §8.3): `None` when waived
    /// (`[failure] low_temperature = false`) or when the compound has no T10.
    pub low_temperature: Option<ColdLimit>,
    /// End the run at the step that finds the failure (a study's cases: what follows a failure
    /// is not the life's); `false`: run the whole duration.
    pub stop_at_failure: bool,
}

/// The condition an O-ring is checked at besides its service (docs/model.md §8.2): a shutdown
/// or cold restart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shutdown {
    /// T_sd \[K\] (default: the lower of 23 °C and the run's coldest temperature).
    pub temperature: f64,
    /// ΔP_min \[Pa\], the lowest pressure difference the seal must hold (default 0).
    pub pressure_difference: f64,
    /// The time over which the ring cools from its service temperature to T_sd in the check's
    /// glassy branch \[s\]: the cord's thermal settling time d²/a (docs/model.md §5.2, §8.2),
    /// the fastest the ring can follow its surroundings, so the least relaxation on the way.
    pub cooling_time: f64,
}

/// The low-temperature limit of practice (docs/model.md §8.3): the seal fails when the rubber
/// is colder than `limit − margin`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ColdLimit {
    /// The compound's T10 \[K\] ([`crate::material::Material::low_temperature_limit`]).
    pub limit: f64,
    /// How far below T10 the seal is still taken to hold \[K\] (≥ 0).
    pub margin: f64,
}

impl ColdLimit {
    /// The coldest temperature the seal holds at, `T10 − margin` \[K\].
    pub fn threshold(&self) -> f64 {
        self.limit - self.margin
    }
}

/// What the criteria look at, at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EventInput {
    pub leak_rate: f64,
    pub leaked_volume: f64,
    /// Sealing force / sealing force at the reference time.
    pub retained_force: f64,
    /// Compression set (0 without ageing).
    pub compression_set: f64,
    /// Whether the fluid pressure opens the contact.
    pub lifted: bool,
    /// Whether the clearance is beyond the extrusion chart's limit.
    pub extruded: bool,
    /// Whether the shutdown check finds the interference lost.
    pub lost_interference: bool,
    /// Sealing force per unit length of the installed (squeeze) profile \[N/m\].
    pub sealing_force: f64,
    /// Peak of the installed (squeeze) profile \[Pa\].
    pub contact_peak: f64,
    /// Mean of the installed profile over its width \[Pa\].
    pub contact_mean: f64,
    /// The pressure difference ΔP \[Pa\].
    pub pressure_difference: f64,
    /// The rubber's temperature \[K\].
    pub temperature: f64,
}

impl FailureCriteria {
    /// No criterion that can end a life over time (the extrusion check, a property of the
    /// gland at the service pressure and temperature, does not count; nor does the cold limit,
    /// a property of the temperature history: [`crate::simulate::LifeProblem::can_fail`] counts
    /// it where the history reaches it).
    pub fn is_empty(&self) -> bool {
        self.max_leak_rate.is_none()
            && self.max_leaked_volume.is_none()
            && self.min_retained_force.is_none()
            && self.max_compression_set.is_none()
            && self.min_sealing_force.is_none()
            && self.min_contact_pressure.is_none()
            && self.gasket_factor.is_none()
            && !self.lift_off
    }

    /// The criteria in the order a tie is broken (several crossed at once, e.g. at
    /// installation, or within [`SIMULTANEOUS_EVENTS`] of each other): the damage first — the
    /// states the model computes (extrusion, an open seal, the shutdown), then the cold limit of
    /// practice, which names the cause of a cold leak or force criterion crossed with it, then
    /// those.
    pub const MODES: [FailureMode; 10] = [
        FailureMode::Extrusion,
        FailureMode::LiftOff,
        FailureMode::LostInterference,
        FailureMode::LowTemperature,
        FailureMode::LeakRate,
        FailureMode::LeakedVolume,
        FailureMode::ContactPressure,
        FailureMode::SealingForce,
        FailureMode::RetainedForce,
        FailureMode::CompressionSet,
    ];

    /// The rank of `mode` in the tie order [`Self::MODES`] (0 first).
    pub fn precedence(&self, mode: FailureMode) -> usize {
        Self::MODES
            .iter()
            .position(|&m| m == mode)
            .unwrap_or(Self::MODES.len())
    }

    /// Whether criterion `mode` (if set) has failed in state `x`.
    pub fn crossed(&self, mode: FailureMode, x: &EventInput) -> bool {
        match mode {
            FailureMode::LeakRate => self.max_leak_rate.is_some_and(|m| x.leak_rate > m),
            FailureMode::LeakedVolume => {
                self.max_leaked_volume.is_some_and(|m| x.leaked_volume > m)
            }
            FailureMode::RetainedForce => self
                .min_retained_force
                .is_some_and(|m| x.retained_force < m),
            FailureMode::CompressionSet => self
                .max_compression_set
                .is_some_and(|m| x.compression_set > m),
            FailureMode::LiftOff => self.lift_off && x.lifted,
            FailureMode::Extrusion => self.extrusion && x.extruded,
            FailureMode::LostInterference => self.shutdown.is_some() && x.lost_interference,
            FailureMode::SealingForce => {
                self.min_sealing_force.is_some_and(|m| x.sealing_force < m)
            }
            FailureMode::ContactPressure => {
                self.min_contact_pressure
                    .is_some_and(|m| x.contact_peak < m)
                    || self
                        .gasket_factor
                        .is_some_and(|m| x.contact_mean < m * x.pressure_difference)
            }
            FailureMode::LowTemperature => self
                .low_temperature
                .is_some_and(|c| x.temperature < c.threshold()),
        }
    }

    /// The criteria that hold in `after` but not in `before`.
    pub fn newly_crossed(&self, before: &EventInput, after: &EventInput) -> Vec<FailureMode> {
        Self::MODES
            .into_iter()
            .filter(|&m| !self.crossed(m, before) && self.crossed(m, after))
            .collect()
    }

    /// A criterion that already holds right after installation (time 0).
    pub fn at_start(&self, x: &EventInput) -> Option<FailureEvent> {
        Self::MODES
            .into_iter()
            .find(|&m| self.crossed(m, x))
            .map(|mode| FailureEvent { time: 0.0, mode })
    }
}

/// `q(t)` between `(a, qa)` and `(b, qb)` as a power law in t when both values and `a` are
/// positive, linearly otherwise.
pub fn interpolate_power_law(a: f64, qa: f64, b: f64, qb: f64, t: f64) -> f64 {
    if a > 0.0 && qa > 0.0 && qb > 0.0 {
        let k = (qb / qa).ln() / (b / a).ln();
        qa * (t / a).powf(k)
    } else {
        qa + (qb - qa) * (t - a) / (b - a)
    }
}

/// `∫_a^b q dt` for the interpolation of [`interpolate_power_law`]: exact for power-law
/// segments, `qa a ln(b/a) φ((k+1) ln(b/a))` with `φ(x) = (e^x − 1)/x`; the trapezoid rule
/// when the power law does not apply (a = 0 or a zero end).
pub fn integrate_power_law(a: f64, qa: f64, b: f64, qb: f64) -> f64 {
    if b <= a {
        return 0.0;
    }
    if a > 0.0 && qa > 0.0 && qb > 0.0 {
        let l = (b / a).ln();
        let k = (qb / qa).ln() / l;
        qa * a * l * expm1_over_x((k + 1.0) * l)
    } else {
        0.5 * (b - a) * (qa + qb)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_law_integral_is_exact() {
        // q = 3 t^-0.5 on [2, 50]: ∫ = 6 (√50 − √2)
        let q = |t: f64| 3.0 * t.powf(-0.5);
        let got = integrate_power_law(2.0, q(2.0), 50.0, q(50.0));
        assert!((got / (6.0 * (50f64.sqrt() - 2f64.sqrt())) - 1.0).abs() < 1e-13);
        // k = −1: ∫ 4/t = 4 ln(b/a)
        let got = integrate_power_law(1.0, 4.0, 1e3, 4e-3);
        assert!((got / (4.0 * 1e3f64.ln()) - 1.0).abs() < 1e-12);
        // constant, and a zero end (trapezoid)
        assert!((integrate_power_law(1.0, 2.0, 3.0, 2.0) - 4.0).abs() < 1e-14);
        assert_eq!(integrate_power_law(1.0, 0.0, 3.0, 2.0), 2.0);
        assert!((interpolate_power_law(2.0, q(2.0), 50.0, q(50.0), 8.0) - q(8.0)).abs() < 1e-14);
    }

    #[test]
    fn absolute_criteria_compare_the_installed_contact() {
        let c = FailureCriteria {
            min_sealing_force: Some(1500.0),
            min_contact_pressure: Some(1e6),
            gasket_factor: Some(2.0),
            ..Default::default()
        };
        assert!(!c.is_empty());
        let ok = EventInput {
            leak_rate: 0.0,
            leaked_volume: 0.0,
            retained_force: 1.0,
            compression_set: 0.0,
            lifted: false,
            extruded: false,
            lost_interference: false,
            sealing_force: 2000.0,
            contact_peak: 2e6,
            contact_mean: 1.5e6,
            pressure_difference: 5e5,
            temperature: 296.15,
        };
        assert!(c.at_start(&ok).is_none());
        // the force below its floor; the peak below its floor; the mean below m·ΔP = 1e6 Pa
        let weak = EventInput {
            sealing_force: 1000.0,
            ..ok
        };
        assert_eq!(c.newly_crossed(&ok, &weak), vec![FailureMode::SealingForce]);
        let low_peak = EventInput {
            contact_peak: 0.9e6,
            ..ok
        };
        assert_eq!(
            c.newly_crossed(&ok, &low_peak),
            vec![FailureMode::ContactPressure]
        );
        let low_mean = EventInput {
            contact_mean: 0.99e6,
            ..ok
        };
        assert_eq!(
            c.newly_crossed(&ok, &low_mean),
            vec![FailureMode::ContactPressure]
        );
        for m in FailureMode::ALL {
            assert_eq!(FailureMode::from_name(m.as_str()), Some(m));
        }
    }

    #[test]
    fn the_cold_limit_is_a_strict_threshold_and_breaks_a_tie_after_the_open_states() {
        let c = FailureCriteria {
            max_leak_rate: Some(1.0),
            lift_off: true,
            low_temperature: Some(ColdLimit {
                limit: 250.0,
                margin: 5.0,
            }),
            ..Default::default()
        };
        assert_eq!(c.low_temperature.map(|l| l.threshold()), Some(245.0));
        let warm = EventInput {
            leak_rate: 0.0,
            leaked_volume: 0.0,
            retained_force: 1.0,
            compression_set: 0.0,
            lifted: false,
            extruded: false,
            lost_interference: false,
            sealing_force: 1.0,
            contact_peak: 1.0,
            contact_mean: 1.0,
            pressure_difference: 0.0,
            temperature: 245.0,
        };
        // at the threshold it holds; a millikelvin colder it fails
        assert!(!c.crossed(FailureMode::LowTemperature, &warm));
        let cold = EventInput {
            temperature: 244.999,
            ..warm
        };
        assert_eq!(
            c.newly_crossed(&warm, &cold),
            vec![FailureMode::LowTemperature]
        );
        // crossed with a leak: the cold names the cause; with an open seal the state comes first
        let leaking = EventInput {
            leak_rate: 2.0,
            ..cold
        };
        assert_eq!(
            c.at_start(&leaking).map(|e| e.mode),
            Some(FailureMode::LowTemperature)
        );
        let open = EventInput {
            lifted: true,
            ..leaking
        };
        assert_eq!(
            c.at_start(&open).map(|e| e.mode),
            Some(FailureMode::LiftOff)
        );
        // waived: nothing
        let waived = FailureCriteria {
            low_temperature: None,
            ..c
        };
        assert!(!waived.crossed(FailureMode::LowTemperature, &cold));
        assert_eq!(
            FailureMode::from_name("low_temperature"),
            Some(FailureMode::LowTemperature)
        );
    }

    #[test]
    fn criteria() {
        let c = FailureCriteria {
            max_leak_rate: Some(1.0),
            min_retained_force: Some(0.5),
            ..Default::default()
        };
        let ok = EventInput {
            leak_rate: 0.5,
            leaked_volume: 0.0,
            retained_force: 0.9,
            compression_set: 0.0,
            lifted: false,
            extruded: false,
            lost_interference: false,
            sealing_force: 1.0,
            contact_peak: 1.0,
            contact_mean: 1.0,
            pressure_difference: 0.0,
            temperature: 296.15,
        };
        let bad = EventInput {
            leak_rate: 2.0,
            retained_force: 0.4,
            ..ok
        };
        assert_eq!(
            c.newly_crossed(&ok, &bad),
            vec![FailureMode::LeakRate, FailureMode::RetainedForce]
        );
        assert!(c.at_start(&ok).is_none());
        assert!(FailureCriteria::default().is_empty());
        // the extrusion check alone cannot end a life over time
        let gland_only = FailureCriteria {
            extrusion: true,
            ..Default::default()
        };
        assert!(gland_only.is_empty());
        let extruded = EventInput {
            extruded: true,
            ..ok
        };
        assert_eq!(
            gland_only.at_start(&extruded).map(|e| e.mode),
            Some(FailureMode::Extrusion)
        );
        assert!(
            !FailureCriteria {
                lift_off: true,
                ..Default::default()
            }
            .is_empty()
        );
    }
}
