//! A compound from a supplier datasheet (docs/model.md §5.4): the figures an engineer has —
//! hardness, the low-temperature limit (TR-10 or T_g), compression set at one to three
//! (time, temperature) points — turned into a compound on its class's master curve.
//!
//! 1. **Low temperature.** The class compound's viscoelastic response moved by ΔT along the
//!    temperature axis, `E_new(t, T) = E_class(t, T − ΔT)` (its shift's reference temperature
//!    and T_g move by ΔT), with ΔT found so that the compound's T10
//!    ([`Material::low_temperature_limit`]) is the datasheet's, or ΔT = T_g − T_g,class.
//! 2. **Hardness.** Every modulus scaled by one factor so that `E(3 s, 23 °C)` is Gent's modulus
//!    of the Shore A grade (A.N. Gent, Trans. IRI 34 (1958) 46, in the form commonly quoted:
//!    `E [MPa] = 0.0981 (56 + 7.62336 S)/(0.137505 (254 − 2.54 S))`, [`gent_modulus`]); a
//!    uniform scale leaves T10 (a ratio of moduli) where step 1 put it.
//! 3. **Ageing.** A compression-set reading (ASTM D395 method B, ISO 815-1: compressed for t at
//!    T, released and read after 30 min at 23 °C) holds the chemical set — the two-network
//!    model's `CS_chem = 1 − e^{−k(T) t}` at constant squeeze (§6.5, ISO 11346) — and the part
//!    of the viscoelastic strain not yet recovered at the reading, which the master curve gives
//!    ([`viscoelastic_set`]). Combined as `CS = CS_chem + (1 − CS_chem)·CS_ve` (the
//!    unrecovered viscoelastic strain acts on the part of the squeeze the networks have not
//!    set), so `k(T) = −ln(1 − CS_chem)/t` with `CS_chem = (CS − CS_ve)/(1 − CS_ve)`. Two
//!    temperatures give Ea (the Arrhenius line through the largest k at the coolest and the
//!    hottest); one gives k there and takes the low end of the class's Ea band. At one
//!    temperature the largest k is kept (the faster ageing: less life). The law is anchored
//!    where the readings pin k (their mean 1/T), so Ea's band pivots about the data.
//!
//! The band of each derived figure (what the datasheet does not pin down) is returned with it
//! ([`Bands`]): the datasheet's own rounding of a compression set (±½ of its last digit) carried
//! through to k and Ea, and, for an Ea taken from the class, the class's band.

use super::compound::{GEHMAN_ROOM_TEMPERATURE, Material, Status};
use super::shift::GAS_CONSTANT;
use super::{Ageing, Shift};

/// The time scale of a Shore A reading \[s\] (the 3 s reading of ISO 48-4 / ASTM D2240).
pub const HARDNESS_READING_TIME: f64 = 3.0;
/// Steps per decade of recovery time in [`viscoelastic_set`].
const STEPS_PER_DECADE: f64 = 80.0;

/// Recovery before a compression set is read \[s\] (ASTM D395 B, ISO 815-1: 30 min).
pub const SET_RECOVERY_TIME: f64 = 1800.0;
/// Temperature of that recovery \[K\] (23 °C, the standard laboratory temperature).
pub const SET_RECOVERY_TEMPERATURE: f64 = GEHMAN_ROOM_TEMPERATURE;

/// Young's modulus \[Pa\] of a rubber of Shore A hardness `shore` by Gent's relation (module
/// docs); the form the library's compounds were calibrated with (`materials/derive_illustrative.py`).
pub fn gent_modulus(shore: f64) -> f64 {
    0.0981e6 * (56.0 + 7.62336 * shore) / (0.137505 * (254.0 - 2.54 * shore))
}

/// The modulus a Shore A reading sees: `E(3 s, 23 °C)` \[Pa\] of `m` (the relaxation modulus
/// at the reduced time of the reading).
pub fn hardness_modulus(m: &Material) -> f64 {
    m.prony
        .relaxation(HARDNESS_READING_TIME * m.shift.ln_rate(GEHMAN_ROOM_TEMPERATURE).exp())
}

/// The low-temperature figure of a datasheet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LowTemperature {
    /// TR-10 (ASTM D1329, ISO 2921) or a Gehman T10 \[K\], matched as the model's T10.
    T10(f64),
    /// The glass transition \[K\] (DSC).
    GlassTransition(f64),
}

/// One compression-set reading of a datasheet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SetPoint {
    /// Time under compression \[s\].
    pub time: f64,
    /// Temperature of the compression \[K\].
    pub temperature: f64,
    /// The set, a fraction (0.25 for 25 %).
    pub set: f64,
    /// Half the last printed digit of the set, a fraction (0.005 for "25 %"): the datasheet's
    /// own resolution.
    pub resolution: f64,
}

/// A supplier datasheet, validated (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Datasheet {
    /// The compound's trade name.
    pub name: String,
    /// Where the figures come from (the datasheet, its revision).
    pub source: String,
    /// Shore A hardness.
    pub hardness: f64,
    pub low_temperature: LowTemperature,
    /// One to three readings.
    pub compression_set: Vec<SetPoint>,
}

/// The band of a derived figure: its value and the lowest and highest values the datasheet
/// allows, with why.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    pub value: f64,
    pub low: f64,
    pub high: f64,
    pub basis: String,
}

/// The bands of a datasheet compound's derived figures.
#[derive(Debug, Clone, PartialEq)]
pub struct Bands {
    /// Ea of the chemical ageing \[J/mol\].
    pub activation_energy: Band,
    /// k at the ageing reference temperature \[1/s\] (the readings' mean 1/T).
    pub rate: Band,
}

/// What the conversion did, for the summary and the provenance.
#[derive(Debug, Clone, PartialEq)]
pub struct Conversion {
    /// The temperature shift of the class curve \[K\].
    pub shift: f64,
    /// The modulus scale.
    pub scale: f64,
    /// Per reading: the viscoelastic part of the set, the chemical set and k \[1/s\].
    pub points: Vec<(SetPoint, f64, f64, f64)>,
    pub bands: Bands,
}

/// Why a datasheet cannot be turned into a compound.
#[derive(Debug, Clone, PartialEq)]
pub enum DatasheetError {
    /// The class compound has no temperature shift or no T10 to move.
    NoLowTemperatureLimit,
    /// No temperature shift within ±150 K reaches the datasheet's T10 \[K\].
    T10OutOfReach(f64),
    /// A reading no larger than the viscoelastic set the master curve leaves: the chemical part
    /// cannot be resolved. (index, the reading, the viscoelastic part)
    SetBelowViscoelastic(usize, f64, f64),
    /// Two temperatures whose k fall with temperature: no Arrhenius ageing.
    RateFallsWithTemperature,
    /// The class compound has no ageing law to take Ea from (one temperature only).
    NoClassActivationEnergy,
    /// No compression-set reading.
    NoReadings,
}

impl std::fmt::Display for DatasheetError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DatasheetError::NoLowTemperatureLimit => {
                write!(
                    f,
                    "the class compound has no T10 to move (no temperature shift)"
                )
            }
            DatasheetError::T10OutOfReach(t) => write!(
                f,
                "no shift of the class's master curve within ±150 K gives T10 = {:.1} °C",
                t - 273.15
            ),
            DatasheetError::SetBelowViscoelastic(i, set, ve) => write!(
                f,
                "compression set {} ({:.1} %) is no larger than the {:.1} % the master curve's \
                 viscoelasticity alone leaves 30 min after release: the chemical set cannot be \
                 resolved — check the figure, or give a longer or hotter reading",
                i + 1,
                set * 100.0,
                ve * 100.0
            ),
            DatasheetError::RateFallsWithTemperature => write!(
                f,
                "the chemical set rate falls as the temperature rises between the readings: \
                 no Arrhenius ageing fits them — check the readings' temperatures"
            ),
            DatasheetError::NoReadings => {
                write!(f, "a datasheet needs at least one compression-set reading")
            }
            DatasheetError::NoClassActivationEnergy => write!(
                f,
                "readings at one temperature need the class's activation energy, and the class \
                 compound has no ageing law: give readings at two temperatures"
            ),
        }
    }
}

/// The viscoelastic part of a compression-set reading of `m`: the fraction of the imposed
/// strain not yet recovered `recovery` s after release at `recovery_temperature`, after a hold
/// of `time` s at `temperature` (no ageing).
///
/// Generalised Maxwell model in reduced time ξ: `σ = E∞ ε + Σ E_i (ε − q_i)`,
/// `dq_i/dξ = (ε − q_i)/τ_i`. Held at ε0 = 1: `q_i = 1 − e^{−ξ_h/τ_i}`. Released (σ = 0):
/// `ε = Σ w_i q_i`, `w_i = E_i/E0`, and the q_i relax towards ε — integrated exactly per step
/// for ε linear over the step (exponential time differencing, second order, stable for
/// every τ_i) on 40 steps per decade of recovery time. Standard linear solid: `ε(r) = w q0
/// e^{−(1−w) r/τ}` (a test).
pub fn viscoelastic_set(
    m: &Material,
    time: f64,
    temperature: f64,
    recovery: f64,
    recovery_temperature: f64,
) -> f64 {
    let terms = m.prony.terms();
    let e0 = m.prony.instantaneous();
    if terms.is_empty() || e0.is_nan() || e0 <= 0.0 {
        return 0.0;
    }
    let hold = time * m.shift.ln_rate(temperature).exp();
    let rest = recovery * m.shift.ln_rate(recovery_temperature).exp();
    let w: Vec<f64> = terms.iter().map(|t| t.modulus / e0).collect();
    let q: Vec<f64> = terms.iter().map(|t| -(-hold / t.tau).exp_m1()).collect();
    let strain = |q: &[f64]| w.iter().zip(q).map(|(w, q)| w * q).sum::<f64>();
    let eps = strain(&q);
    if rest.is_nan() || rest <= 0.0 {
        return eps;
    }
    // steps from 1e-6 of the shortest τ (the fastest mode settles within the first) to `rest`;
    // the scheme is second order: Richardson's extrapolation of N and 2N steps per decade
    let first = (terms.iter().map(|t| t.tau).fold(f64::INFINITY, f64::min) * 1e-6).min(rest);
    let coarse = recover(terms, &w, &q, eps, first, rest, STEPS_PER_DECADE);
    let fine = recover(terms, &w, &q, eps, first, rest, 2.0 * STEPS_PER_DECADE);
    (4.0 * fine - coarse) / 3.0
}

/// The strain after `rest` of recovery from the dashpot strains `q` and strain `eps` at
/// release, on `per_decade` geometric steps per decade from `first`.
fn recover(
    terms: &[super::PronyTerm],
    w: &[f64],
    q: &[f64],
    mut eps: f64,
    first: f64,
    rest: f64,
    per_decade: f64,
) -> f64 {
    let mut q = q.to_vec();
    let decades = (rest / first).log10().max(0.0);
    let steps = (per_decade * decades).ceil().max(1.0) as usize;
    let mut r = 0.0;
    for k in 0..=steps {
        let next = if k == steps {
            rest
        } else {
            first * 10f64.powf(decades * k as f64 / steps as f64)
        };
        let h = next - r;
        if h <= 0.0 {
            continue;
        }
        // q_i(r + h) = q_i e_i + ε_n a_i + ε_{n+1} b_i for ε linear over the step, with
        // e = e^{−h/τ}, b = 1 − (1 − e)τ/h, a = 1 − e − b
        let mut known = 0.0;
        let mut implicit = 0.0;
        let coefficients: Vec<(f64, f64, f64)> = terms
            .iter()
            .map(|t| {
                let x = h / t.tau;
                let e = (-x).exp();
                let one_minus_e = -(-x).exp_m1();
                let b = if x < 1e-8 {
                    0.5 * x
                } else {
                    1.0 - one_minus_e / x
                };
                (e, one_minus_e - b, b)
            })
            .collect();
        for ((wi, qi), (e, a, b)) in w.iter().zip(&q).zip(&coefficients) {
            known += wi * (qi * e + eps * a);
            implicit += wi * b;
        }
        let eps_next = known / (1.0 - implicit);
        for (qi, (e, a, b)) in q.iter_mut().zip(&coefficients) {
            *qi = *qi * e + eps * a + eps_next * b;
        }
        eps = eps_next;
        r = next;
    }
    eps
}

/// The compression set of a D395 B / ISO 815-1 reading the model predicts for `m`: the
/// chemical set `1 − e^{−k(T) t}` (0 without ageing) and the viscoelastic part
/// ([`viscoelastic_set`], 30 min at 23 °C), combined as in the module docs.
pub fn compression_set(m: &Material, time: f64, temperature: f64) -> f64 {
    let chemical = m
        .ageing
        .map_or(0.0, |a| -(-a.rate_at(temperature) * time).exp_m1());
    let ve = viscoelastic_set(
        m,
        time,
        temperature,
        SET_RECOVERY_TIME,
        SET_RECOVERY_TEMPERATURE,
    );
    chemical + (1.0 - chemical) * ve
}

/// `m` moved by `dt` K along the temperature axis: `E_new(t, T) = E(t, T − dt)`.
fn moved(m: &Material, dt: f64) -> Material {
    let shift = match m.shift {
        Shift::None => Shift::None,
        Shift::Wlf { reference, c1, c2 } => Shift::Wlf {
            reference: reference + dt,
            c1,
            c2,
        },
        Shift::Arrhenius {
            reference,
            activation_energy,
        } => Shift::Arrhenius {
            reference: reference + dt,
            activation_energy,
        },
    };
    Material {
        shift,
        glass_transition: m.glass_transition.map(|t| t + dt),
        data_temperature: m.data_temperature.map(|(a, b)| (a + dt, b + dt)),
        ..m.clone()
    }
}

/// The temperature shift of `class` that gives `low` (module docs, step 1).
fn temperature_shift(class: &Material, low: LowTemperature) -> Result<f64, DatasheetError> {
    match low {
        LowTemperature::GlassTransition(tg) => class
            .glass_transition
            .map(|own| tg - own)
            .ok_or(DatasheetError::NoLowTemperatureLimit),
        LowTemperature::T10(target) => {
            let t10 = |dt: f64| moved(class, dt).low_temperature_limit();
            let own = t10(0.0).ok_or(DatasheetError::NoLowTemperatureLimit)?;
            // T10 moves by about dt: bracket around the difference, then bisect
            let guess = target - own;
            let (lo, hi) = (guess - 30.0, guess + 30.0);
            let below = |dt: f64| t10(dt).is_some_and(|t| t < target);
            if !below(lo) || below(hi) || lo < -150.0 || hi > 150.0 {
                return Err(DatasheetError::T10OutOfReach(target));
            }
            let (a, b) = sealsim_math::roots::bisect(lo, hi, 80, |a, b| b - a < 1e-9, below);
            Ok(0.5 * (a + b))
        }
    }
}

/// k(T) \[1/s\] of a reading of `m` (no ageing in `m`) with set `set`: the viscoelastic part
/// and the chemical set (module docs, step 3).
fn rate_of(m: &Material, p: &SetPoint, set: f64) -> (f64, f64, f64) {
    let ve = viscoelastic_set(
        m,
        p.time,
        p.temperature,
        SET_RECOVERY_TIME,
        SET_RECOVERY_TEMPERATURE,
    );
    let chemical = (set - ve) / (1.0 - ve);
    (ve, chemical, -(-chemical).ln_1p() / p.time)
}

/// The compound of `sheet` on the master curve of `class` (module docs). The result is a
/// user compound (no claim is made); `class_band` is the class's Ea band \[J/mol\]: with
/// readings at one temperature Ea is its low end (the faster ageing at the service
/// temperatures below a hot reading: less life) and the band is carried in [`Bands`]. The
/// caller names the provenance.
pub fn from_datasheet(
    class: &Material,
    class_band: (f64, f64),
    sheet: &Datasheet,
) -> Result<(Material, Conversion), DatasheetError> {
    let dt = temperature_shift(class, sheet.low_temperature)?;
    let shifted = moved(class, dt);
    let room = GEHMAN_ROOM_TEMPERATURE;
    let scale = gent_modulus(sheet.hardness) / hardness_modulus(&shifted);
    let viscoelastic = Material {
        prony: shifted.prony.scaled(scale),
        ageing: None,
        ..shifted
    };
    let mut points = Vec::new();
    for (i, p) in sheet.compression_set.iter().enumerate() {
        let (ve, chemical, k) = rate_of(&viscoelastic, p, p.set);
        if !(chemical > 0.0 && k.is_finite()) {
            return Err(DatasheetError::SetBelowViscoelastic(i, p.set, ve));
        }
        points.push((*p, ve, chemical, k));
    }
    // the largest k at each temperature (the faster ageing)
    let mut by_temperature: Vec<(f64, f64, usize)> = Vec::new();
    for (i, (p, _, _, k)) in points.iter().enumerate() {
        match by_temperature
            .iter_mut()
            .find(|(t, _, _)| (t - p.temperature).abs() < 1e-6)
        {
            Some(entry) if *k > entry.1 => *entry = (p.temperature, *k, i),
            Some(_) => {}
            None => by_temperature.push((p.temperature, *k, i)),
        }
    }
    by_temperature.sort_by(|a, b| a.0.total_cmp(&b.0));
    // the ageing law's anchor: where the readings pin k — the reading temperature, or between
    // two the mean of 1/T, about which Ea and k_ref are uncorrelated — so that Ea's band pivots
    // about the data (a study varying Ea alone stays true to the readings)
    let reference = match (by_temperature.first(), by_temperature.last()) {
        (Some(&(t1, _, _)), Some(&(t2, _, _))) => 2.0 / (1.0 / t1 + 1.0 / t2),
        _ => room,
    };
    // Ea and k at `reference` from the (T, k) of the coolest and hottest readings
    let arrhenius = |cool: (f64, f64), hot: (f64, f64)| {
        let ea = GAS_CONSTANT * (hot.1 / cool.1).ln() / (1.0 / cool.0 - 1.0 / hot.0);
        (
            ea,
            hot.1 * (ea / GAS_CONSTANT * (1.0 / hot.0 - 1.0 / reference)).exp(),
        )
    };
    let at_reference =
        |ea: f64, t: f64, k: f64| k * (ea / GAS_CONSTANT * (1.0 / t - 1.0 / reference)).exp();
    let (ea, rate, bands) = match (by_temperature.first(), by_temperature.last()) {
        (Some(&(t1, k1, i1)), Some(&(t2, k2, i2))) if t2 > t1 => {
            if k2 <= k1 {
                return Err(DatasheetError::RateFallsWithTemperature);
            }
            let (ea, rate) = arrhenius((t1, k1), (t2, k2));
            // the datasheet's rounding: each reading anywhere within ± its resolution
            let k_at = |i: usize, sign: f64| {
                let p = &points[i].0;
                rate_of(&viscoelastic, p, p.set + sign * p.resolution).2
            };
            let mut eas = Vec::new();
            let mut rates = Vec::new();
            for (s1, s2) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
                let (a, b) = (k_at(i1, s1), k_at(i2, s2));
                if a > 0.0 && b > a && a.is_finite() && b.is_finite() {
                    let (e, r) = arrhenius((t1, a), (t2, b));
                    eas.push(e);
                    rates.push(r);
                }
            }
            let band = |v: f64, all: &[f64], basis: &str| Band {
                value: v,
                low: all.iter().copied().fold(v, f64::min),
                high: all.iter().copied().fold(v, f64::max),
                basis: basis.to_owned(),
            };
            let basis = "the datasheet's rounding of the two readings (± half their last digit)";
            (
                ea,
                rate,
                Bands {
                    activation_energy: band(ea, &eas, basis),
                    rate: band(rate, &rates, basis),
                },
            )
        }
        (Some(&(t, k, _)), _) => {
            if class.ageing.is_none() {
                return Err(DatasheetError::NoClassActivationEnergy);
            }
            // the band's low end: the faster ageing below the reading's temperature
            let (lo, hi) = class_band;
            let ea = lo;
            let rate = at_reference(ea, t, k);
            let (r_lo, r_hi) = (at_reference(hi, t, k), at_reference(lo, t, k));
            let basis = "the class's activation-energy band (one reading temperature)";
            (
                ea,
                rate,
                Bands {
                    activation_energy: Band {
                        value: ea,
                        low: lo.min(ea),
                        high: hi.max(ea),
                        basis: basis.to_owned(),
                    },
                    rate: Band {
                        value: rate,
                        low: r_lo.min(r_hi).min(rate),
                        high: r_lo.max(r_hi).max(rate),
                        basis: basis.to_owned(),
                    },
                },
            )
        }
        _ => return Err(DatasheetError::NoReadings),
    };
    let crosslinking = class
        .ageing
        .map_or(super::BALANCED_CROSSLINKING, |a| a.crosslinking);
    let material = Material {
        name: sheet.name.clone(),
        status: Status::User,
        ageing: Some(Ageing::arrhenius(ea, rate, reference, crosslinking)),
        library_id: None,
        provenance: Vec::new(),
        // what a study draws Ea from with "band" (docs/model.md §5.4)
        bands: vec![super::FigureBand {
            key: "ageing.activation_energy".into(),
            min: bands.activation_energy.low,
            max: bands.activation_energy.high,
            source: bands.activation_energy.basis.clone(),
        }],
        ..viscoelastic
    };
    Ok((
        material,
        Conversion {
            shift: dt,
            scale,
            points,
            bands,
        },
    ))
}
