//! The validity limits of the model, each defined once (docs/model.md §9).
//!
//! Every command evaluates them through the same functions: [`contact`] for a contact state
//! (a static leak point, or the peak strip of a life step), [`surface`] for the roughness,
//! [`temperature`] and [`squeeze`] for the rubber's state, [`speed`] for a sliding seal, and
//! [`Findings::record`] to collect them. A [`Finding`] keeps, per limit, the worst value seen
//! (how far outside the range) and where it occurred — the nominal pressure of a static point or
//! the time of a life step — and where it first occurred. The result is still computed; the
//! finding says how far to trust it.

use crate::codes::{self, Code};
use crate::contact::Junction;
use crate::seal::LINDLEY_RANGE;
use crate::surface::Spectrum;
use crate::units::human;
use std::fmt;

/// ΔP over the peak contact pressure above which the fluid's load on the rubber body, not
/// modelled, is comparable to the contact load (docs/model.md §9.1).
pub const MAX_PRESSURE_RATIO: f64 = 0.5;

/// Clearance over the extrusion chart's limit above which sealsim warns that the ring is close
/// to extruding (docs/model.md §9.12).
pub const EXTRUSION_WARNING: f64 = 0.8;

/// u_c/λ_c above which the thin-gap (lubrication) flow of the critical constriction fails
/// (docs/model.md §9.2).
pub const MAX_ASPECT_RATIO: f64 = 0.1;

/// Constriction height below which continuum flow is not a valid picture \[m\] (1 nm;
/// docs/model.md §9.3).
pub const MIN_CONTINUUM_GAP: f64 = 1e-9;

/// ζc above this fraction of q1/q0 puts the critical junction near the cut-off (docs/model.md
/// §9.4).
pub const NEAR_CUTOFF_FRACTION: f64 = 0.5;

/// Hurst exponents of a self-affine spectrum within which sealsim's analytic contact levels have
/// been checked (docs/model.md §9.5).
pub const HURST_RANGE: (f64, f64) = (0.6, 0.9);

/// rms slope above which the small-slope contact theory is stretched (docs/model.md §9.8).
pub const MAX_RMS_SLOPE: f64 = 0.5;

/// One limit of the model's validity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Limit {
    /// ΔP/P0 not small (docs/model.md §9.1).
    PressureRatio,
    /// u_c/λ_c not small (§9.2).
    AspectRatio,
    /// u_c below 1 nm (§9.3).
    MolecularGap,
    /// ζc within a factor 2 of the cut-off q1/q0 (§9.4).
    NearCutoff,
    /// Hurst exponent outside [`HURST_RANGE`] (§9.5).
    HurstExponent,
    /// O-ring squeeze outside Lindley's range (§9.6).
    Squeeze,
    /// Temperature below the glass transition (§9.7).
    GlassTransition,
    /// Temperature at or below the WLF singularity: the rubber is frozen (§9.7).
    Frozen,
    /// rms slope of the surface above [`MAX_RMS_SLOPE`] (§9.8).
    RmsSlope,
    /// Sliding speed above the PY08 §8 bound (§9.9).
    SpeedBound,
    /// The numerical level resolves only a band of the spectrum (§9.10).
    BandLimited,
    /// A node of the numerical level's table failed and was left out (§9.10).
    NumericalFailure,
    /// No failure criterion: a life run can only survive (§8).
    NoFailureCriterion,
    /// Clearance close to (or beyond) the extrusion chart's limit (§9.12).
    Extrusion,
    /// Pressure or hardness outside the extrusion chart: its nearest row or band was used
    /// (§9.12).
    ExtrusionChart,
    /// Reduced time beyond the window of the data the series was fitted to (§9.13).
    DataTime,
    /// Temperature outside the window of the material's data (§9.13).
    DataTemperature,
    /// A stroke speed between PY08's speed bound and the inverse-hydrodynamic regime: the
    /// stroke volumes are blended (§9.9).
    IhlTransition,
    /// An O-ring's inlet pressure gradients estimated from its Hertz profile (§9.9).
    GradientEstimate,
    /// A gas at the critical constriction in the slip regime, [`KNUDSEN_SLIP`] < Kn ≤
    /// [`KNUDSEN_TRANSITION`] (§9.14).
    KnudsenSlip,
    /// The transition regime, [`KNUDSEN_TRANSITION`] < Kn ≤ [`KNUDSEN_FREE_MOLECULAR`] (§9.14).
    KnudsenTransition,
    /// The free-molecular regime, Kn > [`KNUDSEN_FREE_MOLECULAR`] (§9.14).
    KnudsenFreeMolecular,
    /// Kn > [`KNUDSEN_SLIP`] under the continuum law (`rarefaction = false`, §9.14).
    KnudsenContinuumLaw,
    /// Fewer than [`MIN_WAVELENGTHS_ACROSS`] of the longest roughness wavelengths 2π/q0 across
    /// the contact width (§9.16).
    NarrowContact,
}

/// The longest roughness wavelengths 2π/q0 that must fit across the contact for its strips in
/// series to be statistical samples of the roughness (docs/model.md §9.16; PY08 §3 asks for a
/// contact much wider than 2π/q0).
pub const MIN_WAVELENGTHS_ACROSS: f64 = 2.0;

/// Knudsen number above which a gas slips at the walls (docs/model.md §9.14).
pub const KNUDSEN_SLIP: f64 = 0.01;
/// Knudsen number above which a gas is in the transition regime (docs/model.md §9.14).
pub const KNUDSEN_TRANSITION: f64 = 0.1;
/// Knudsen number above which a gas flows free-molecularly (docs/model.md §9.14).
pub const KNUDSEN_FREE_MOLECULAR: f64 = 10.0;

impl Limit {
    /// Every limit, in the order of docs/model.md.
    pub const ALL: [Limit; 24] = [
        Limit::PressureRatio,
        Limit::AspectRatio,
        Limit::MolecularGap,
        Limit::NearCutoff,
        Limit::HurstExponent,
        Limit::Squeeze,
        Limit::GlassTransition,
        Limit::Frozen,
        Limit::RmsSlope,
        Limit::SpeedBound,
        Limit::BandLimited,
        Limit::NumericalFailure,
        Limit::NoFailureCriterion,
        Limit::Extrusion,
        Limit::ExtrusionChart,
        Limit::DataTime,
        Limit::DataTemperature,
        Limit::IhlTransition,
        Limit::GradientEstimate,
        Limit::KnudsenSlip,
        Limit::KnudsenTransition,
        Limit::KnudsenFreeMolecular,
        Limit::KnudsenContinuumLaw,
        Limit::NarrowContact,
    ];

    /// The limit's identifier in JSON summaries.
    pub fn id(self) -> &'static str {
        match self {
            Limit::PressureRatio => "pressure_ratio",
            Limit::AspectRatio => "aspect_ratio",
            Limit::MolecularGap => "molecular_gap",
            Limit::NearCutoff => "near_cutoff",
            Limit::HurstExponent => "hurst_exponent",
            Limit::Squeeze => "squeeze",
            Limit::GlassTransition => "below_glass_transition",
            Limit::Frozen => "frozen",
            Limit::RmsSlope => "rms_slope",
            Limit::SpeedBound => "speed_above_bound",
            Limit::BandLimited => "band_limited",
            Limit::NumericalFailure => "numerical_failure",
            Limit::NoFailureCriterion => "no_failure_criterion",
            Limit::Extrusion => "extrusion",
            Limit::ExtrusionChart => "extrusion_chart",
            Limit::DataTime => "beyond_data_time",
            Limit::DataTemperature => "beyond_data_temperature",
            Limit::IhlTransition => "speed_in_ihl_transition",
            Limit::GradientEstimate => "estimated_pressure_gradients",
            Limit::KnudsenSlip => "knudsen_slip",
            Limit::KnudsenTransition => "knudsen_transition",
            Limit::KnudsenFreeMolecular => "knudsen_free_molecular",
            Limit::KnudsenContinuumLaw => "knudsen_continuum_law",
            Limit::NarrowContact => "narrow_contact",
        }
    }

    /// The section of docs/model.md that explains the limit.
    pub fn section(self) -> &'static str {
        match self {
            Limit::PressureRatio => "§9.1",
            Limit::AspectRatio => "§9.2",
            Limit::MolecularGap => "§9.3",
            Limit::NearCutoff => "§9.4",
            Limit::HurstExponent => "§9.5",
            Limit::Squeeze => "§9.6",
            Limit::GlassTransition | Limit::Frozen => "§9.7",
            Limit::RmsSlope => "§9.8",
            Limit::SpeedBound | Limit::IhlTransition | Limit::GradientEstimate => "§9.9",
            Limit::BandLimited | Limit::NumericalFailure => "§9.10",
            Limit::NoFailureCriterion => "§8",
            Limit::Extrusion | Limit::ExtrusionChart => "§9.12",
            Limit::DataTime | Limit::DataTemperature => "§9.13",
            Limit::KnudsenSlip
            | Limit::KnudsenTransition
            | Limit::KnudsenFreeMolecular
            | Limit::KnudsenContinuumLaw => "§9.14",
            Limit::NarrowContact => "§9.16",
        }
    }

    /// The quantity the limit bounds and its SI unit (`None` for a limit without a value).
    pub fn quantity(self) -> Option<(&'static str, &'static str)> {
        match self {
            Limit::PressureRatio => Some(("ΔP/P0", "")),
            Limit::AspectRatio => Some(("u_c/λ_c", "")),
            Limit::MolecularGap => Some(("u_c", "m")),
            Limit::NearCutoff => Some(("ζc", "")),
            Limit::HurstExponent => Some(("H", "")),
            Limit::Squeeze => Some(("squeeze", "")),
            Limit::GlassTransition | Limit::Frozen => Some(("T", "K")),
            Limit::RmsSlope => Some(("rms slope", "")),
            Limit::SpeedBound | Limit::IhlTransition => Some(("sliding speed", "m/s")),
            Limit::GradientEstimate => None,
            Limit::BandLimited => Some(("q1/q0", "")),
            Limit::NumericalFailure => Some(("P0/E*", "")),
            Limit::NoFailureCriterion | Limit::ExtrusionChart => None,
            Limit::Extrusion => Some(("clearance/limit", "")),
            Limit::DataTime => Some(("reduced time", "s")),
            Limit::DataTemperature => Some(("T", "K")),
            Limit::KnudsenSlip
            | Limit::KnudsenTransition
            | Limit::KnudsenFreeMolecular
            | Limit::KnudsenContinuumLaw => Some(("Kn = λ(p̄)/u_c", "")),
            Limit::NarrowContact => Some(("contact width × q0/2π", "")),
        }
    }

    /// The limit's registered code (`W001` …, [`crate::codes`]).
    pub fn code(self) -> &'static Code {
        match self {
            Limit::PressureRatio => &codes::PRESSURE_RATIO,
            Limit::AspectRatio => &codes::ASPECT_RATIO,
            Limit::MolecularGap => &codes::MOLECULAR_GAP,
            Limit::NearCutoff => &codes::NEAR_CUTOFF,
            Limit::HurstExponent => &codes::HURST_EXPONENT,
            Limit::Squeeze => &codes::SQUEEZE,
            Limit::GlassTransition => &codes::GLASS_TRANSITION,
            Limit::Frozen => &codes::FROZEN,
            Limit::RmsSlope => &codes::RMS_SLOPE,
            Limit::SpeedBound => &codes::SPEED_BOUND,
            Limit::BandLimited => &codes::BAND_LIMITED,
            Limit::NumericalFailure => &codes::NUMERICAL_FAILURE,
            Limit::NoFailureCriterion => &codes::NO_FAILURE_CRITERION,
            Limit::Extrusion => &codes::EXTRUSION,
            Limit::ExtrusionChart => &codes::EXTRUSION_CHART,
            Limit::DataTime => &codes::DATA_TIME,
            Limit::DataTemperature => &codes::DATA_TEMPERATURE,
            Limit::IhlTransition => &codes::IHL_TRANSITION,
            Limit::GradientEstimate => &codes::GRADIENT_ESTIMATE,
            Limit::KnudsenSlip => &codes::KNUDSEN_SLIP,
            Limit::KnudsenTransition => &codes::KNUDSEN_TRANSITION,
            Limit::KnudsenFreeMolecular => &codes::KNUDSEN_FREE_MOLECULAR,
            Limit::KnudsenContinuumLaw => &codes::KNUDSEN_CONTINUUM_LAW,
            Limit::NarrowContact => &codes::NARROW_CONTACT,
        }
    }

    /// What the limit means for the result.
    pub fn consequence(self) -> &'static str {
        match self {
            Limit::PressureRatio => {
                "the fluid pressure is comparable to the contact pressure: in the interface it is \
                 modelled on the asperities, but its load on the rubber body, which reshapes the \
                 contact, is not"
            }
            Limit::AspectRatio => {
                "the critical constriction is not a thin gap: the lubrication flow u³/12η \
                 overstates its conductance"
            }
            Limit::MolecularGap => {
                "continuum flow is not valid within a few molecular sizes; a gap narrower than one \
                 molecule of the fluid is reported as sealed"
            }
            Limit::NearCutoff => {
                "the critical junction lies near the short-wavelength cut-off q1: the result \
                 depends on the (often uncertain) cut-off"
            }
            Limit::HurstExponent => {
                "outside the Hurst exponents for which sealsim's contact levels were checked \
                 against independent references"
            }
            Limit::Squeeze => "outside the squeeze for which Lindley's O-ring relations are used",
            Limit::GlassTransition => {
                "below the glass transition: the rubber turns glassy; WLF is extrapolated below its \
                 range, and a series that stops at the rubbery plateau is far too soft here"
            }
            Limit::Frozen => {
                "at or below the WLF singularity: the rubber is treated as frozen (no relaxation)"
            }
            Limit::RmsSlope => {
                "the surface is steep: the small-slope contact theory is stretched (contact area \
                 and separation less reliable)"
            }
            Limit::SpeedBound => {
                "the drag pressure opens the critical constriction; hydrodynamic lift-off is not \
                 modelled (the drag leak rate is likely underestimated)"
            }
            Limit::IhlTransition => {
                "between the end of the low-speed theory (the lower of PY08's speed bound and the \
                 speed at which the inverse-hydrodynamic film reaches the rms roughness) and the \
                 inverse-hydrodynamic regime (10× that speed): the stroke volumes are a log-speed blend of the low-speed and the \
                 inverse-hydrodynamic values"
            }
            Limit::GradientEstimate => {
                "no contact-pressure profile given: the O-ring's inlet pressure gradients are \
                 estimated from its Hertz profile (slope at half rise), so the \
                 inverse-hydrodynamic films are estimates; give [motion] contact_profile or \
                 inlet_gradient_out/inlet_gradient_in"
            }
            Limit::BandLimited => {
                "the numerical level resolved only part of the spectrum; its answer is for the \
                 band-limited surface"
            }
            Limit::NumericalFailure => {
                "a node of the numerical level's table failed and was left out"
            }
            Limit::NoFailureCriterion => {
                "the [failure] block sets no criterion: the seal can only survive"
            }
            Limit::Extrusion => {
                "the clearance gap is close to the extrusion chart's limit for this pressure and \
                 hardness (above 1: the ring extrudes)"
            }
            Limit::ExtrusionChart => {
                "outside the extrusion chart (70–90 Shore A ± 2, up to 3000 psi)"
            }
            Limit::DataTime => {
                "beyond the reduced times of the data the material's series was fitted to: the \
                 relaxation there is an extrapolation"
            }
            Limit::DataTemperature => {
                "outside the temperatures of the material's data: the shift (or, without one, the \
                 series itself) is extrapolated"
            }
            Limit::KnudsenSlip => {
                "slip regime (0.01 < Kn ≤ 0.1) at the critical constriction: the rarefied slit \
                 law adds first-order slip (flow × ≈ 1 + 6 Kn), accurate to a few % here"
            }
            Limit::KnudsenTransition => {
                "transition regime (0.1 < Kn ≤ 10) at the critical constriction: the rarefied \
                 slit law interpolates between slip and free-molecular flow (Beskok–Karniadakis \
                 form); its error against kinetic theory is not quantified here (tens of % \
                 possible)"
            }
            Limit::KnudsenFreeMolecular => {
                "free-molecular regime (Kn > 10) at the critical constriction: the slit law's \
                 free-molecular limit applies (Smoluchowski's slit conductance of a constriction \
                 λc wide; its logarithm of λc/u_c makes it uncertain by tens of %)"
            }
            Limit::KnudsenContinuumLaw => {
                "the gas is rarefied at the critical constriction but `rarefaction = false`: the \
                 continuum law is used and underestimates the flow (slip alone adds ≈ 6 Kn; \
                 free-molecular flow can be orders of magnitude above the continuum law)"
            }
            Limit::NarrowContact => {
                "fewer than two of the surface's longest wavelengths 2π/q0 fit across the \
                 contact: its strips, each a statistical sample of the roughness, are not; the \
                 leak of so narrow a contact depends on where its few long waves sit (the model \
                 gives their average)"
            }
        }
    }
}

/// Where a finding was evaluated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum At {
    /// Of the set-up as a whole (the surface, the numerical level's band).
    Setup,
    /// The installation state of a seal evaluated statically (`sealsim leak`).
    Installation,
    /// A static leak point at nominal pressure P0 \[Pa\].
    Pressure(f64),
    /// A life step at time t \[s\] since installation.
    Time(f64),
}

impl fmt::Display for At {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            At::Setup => Ok(()),
            At::Installation => f.write_str("at installation"),
            At::Pressure(p0) => write!(f, "at P0 = {}", with_unit(p0, "Pa")),
            At::Time(t) => write!(f, "at t = {}", duration(t)),
        }
    }
}

/// One limit crossed: its worst value and where.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    pub limit: Limit,
    /// The quantity of [`Limit::quantity`] at its worst (0 for a limit without a value).
    pub value: f64,
    /// The bound it crossed there (the threshold, or the case's own bound: q1/q0 / 2, T_g, the
    /// speed bound …).
    pub bound: f64,
    /// Where the worst value occurred.
    pub at: At,
    /// Where the limit was first crossed.
    pub first: At,
    /// How many evaluations crossed it.
    pub count: usize,
    /// Extra text (the solver's message of a numerical failure).
    pub detail: Option<String>,
}

impl Finding {
    fn new(limit: Limit, value: f64, bound: f64, at: At) -> Self {
        Finding {
            limit,
            value,
            bound,
            at,
            first: at,
            count: 1,
            detail: None,
        }
    }

    /// How far outside the range: `max(value/bound, bound/value)` (≥ 1 for a crossed limit;
    /// 1 for a limit without a value).
    pub fn severity(&self) -> f64 {
        if self.limit.quantity().is_none() || self.value <= 0.0 || self.bound <= 0.0 {
            return 1.0;
        }
        (self.value / self.bound).max(self.bound / self.value)
    }
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some((name, unit)) = self.limit.quantity() {
            let relation = if self.value > self.bound {
                "above"
            } else {
                "below"
            };
            write!(
                f,
                "{name} = {} is {relation} {}",
                with_unit(self.value, unit),
                with_unit(self.bound, unit)
            )?;
            match (self.at, self.count) {
                (At::Setup, _) => {}
                (at, 1) => write!(f, " {at}")?,
                (at, n) if self.first == at => write!(f, ", worst {at} ({n} evaluations)")?,
                (at, n) => write!(f, ", worst {at}; first {}, {n} evaluations", self.first)?,
            }
            f.write_str(": ")?;
        }
        f.write_str(self.limit.consequence())?;
        if let Some(detail) = &self.detail {
            write!(f, " ({detail})")?;
        }
        write!(f, " [docs/model.md {}]", self.limit.section())
    }
}

/// The longest one-line message on stderr, in characters (`warning[W001]: …` included).
pub const MAX_LINE: usize = 120;

impl Finding {
    /// The finding in one short phrase: `ΔP/P0 = 1 > 0.5 from 350 d (worst 10 y)`, the value
    /// against its bound and where (the first and the worst place when it was crossed more than
    /// once); the limit's title for a limit without a value.
    pub fn short(&self) -> String {
        let Some((name, unit)) = self.limit.quantity() else {
            return self.limit.code().title.to_owned();
        };
        let relation = if self.value > self.bound { ">" } else { "<" };
        let mut text = format!(
            "{name} = {} {relation} {}",
            with_unit(self.value, unit),
            with_unit(self.bound, unit)
        );
        match (self.at, self.first == self.at || self.count == 1) {
            (At::Setup, _) => {}
            (at, true) => text += &format!(" at {}", compact(at)),
            (at, false) => {
                text += &format!(" from {} (worst {})", compact(self.first), compact(at));
            }
        }
        text
    }

    /// The one stderr line of the finding, at most [`MAX_LINE`] characters:
    /// `warning[W001]: CONTEXT: ΔP/P0 = 1 > 0.5 from 350 d (worst 10 y): TITLE — sealsim explain
    /// W001`; the title is shortened (or left out) to fit. The full text is [`Finding`]'s
    /// `Display`.
    pub fn line(&self, context: Option<&str>) -> String {
        let code = self.limit.code();
        let lead = context.map(|c| format!("{c}: ")).unwrap_or_default();
        let short = self.short();
        let title = if self.limit.quantity().is_some() {
            code.title
        } else {
            ""
        };
        one_line("warning", code.code, &format!("{lead}{short}"), title)
    }
}

/// `KIND[CODE]: HEAD: TAIL — sealsim explain CODE` in at most [`MAX_LINE`] characters: `tail`
/// (a title) is left out when it does not fit whole, and `head` is shortened with `…` if it
/// must.
pub fn one_line(kind: &str, code: &str, head: &str, tail: &str) -> String {
    let open = format!("{kind}[{code}]: ");
    let close = format!(" — sealsim explain {code}");
    let room = MAX_LINE.saturating_sub(open.chars().count() + close.chars().count());
    let whole = head.chars().count() + 2 + tail.chars().count();
    let body = if tail.is_empty() || whole > room {
        clip(head, room)
    } else {
        format!("{head}: {tail}")
    };
    format!("{open}{body}{close}")
}

/// `text` cut to `room` characters, the last one `…` when cut.
fn clip(text: &str, room: usize) -> String {
    if text.chars().count() <= room {
        return text.to_owned();
    }
    let mut cut: String = text.chars().take(room.saturating_sub(1)).collect();
    cut.push('…');
    cut
}

/// Where, compactly: `P0 = 1e6 Pa`, `350 d`, `10.5 y`, `3 h`, `installation`.
fn compact(at: At) -> String {
    const HOUR: f64 = 3600.0;
    const DAY: f64 = 86_400.0;
    const YEAR: f64 = 365.25 * DAY;
    match at {
        At::Time(t) if t >= 2.0 * YEAR => format!("{} y", human(t / YEAR, 3)),
        At::Time(t) if t >= DAY => format!("{} d", human(t / DAY, 3)),
        At::Time(t) if t >= HOUR => format!("{} h", human(t / HOUR, 3)),
        At::Time(t) => format!("{} s", human(t, 3)),
        At::Pressure(p0) => format!("P0 = {}", with_unit(p0, "Pa")),
        At::Installation => "installation".to_owned(),
        At::Setup => String::new(),
    }
}

/// `value unit` with four significant digits ([`human`]).
fn with_unit(value: f64, unit: &str) -> String {
    if unit == "K" {
        // an absolute temperature: in °C first, as the inputs are usually written
        return crate::units::show_temperature(value, 4);
    }
    let number = human(value, 4);
    if unit.is_empty() {
        number
    } else {
        format!("{number} {unit}")
    }
}

/// `3.156e7 s (1 years)`: seconds, with days or years for long times.
fn duration(t: f64) -> String {
    const DAY: f64 = 86_400.0;
    const YEAR: f64 = 365.25 * DAY;
    let seconds = with_unit(t, "s");
    if t >= YEAR {
        format!("{seconds} ({} years)", human(t / YEAR, 4))
    } else if t >= DAY {
        format!("{seconds} ({} days)", human(t / DAY, 4))
    } else {
        seconds
    }
}

/// The findings of one evaluation (a sweep, a life run): one per limit, the worst.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Findings {
    items: Vec<Finding>,
}

impl Findings {
    /// Records `finding`: the first of its limit is kept as is; a later one replaces the worst
    /// value and its place when it is further outside the range ([`Finding::severity`]), and is
    /// counted.
    pub fn record(&mut self, finding: Finding) {
        match self.items.iter_mut().find(|f| f.limit == finding.limit) {
            None => self.items.push(finding),
            Some(kept) => {
                kept.count += finding.count;
                if finding.severity() > kept.severity() {
                    kept.value = finding.value;
                    kept.bound = finding.bound;
                    kept.at = finding.at;
                    kept.detail = finding.detail;
                }
            }
        }
    }

    /// Records every finding of `other`.
    pub fn extend(&mut self, other: Findings) {
        for f in other.items {
            self.record(f);
        }
    }

    /// The findings, in the order their limits were first crossed.
    pub fn iter(&self) -> impl Iterator<Item = &Finding> {
        self.items.iter()
    }

    /// The finding of `limit`, if it was crossed.
    pub fn get(&self, limit: Limit) -> Option<&Finding> {
        self.items.iter().find(|f| f.limit == limit)
    }

    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    pub fn len(&self) -> usize {
        self.items.len()
    }

    fn check(&mut self, limit: Limit, crossed: bool, value: f64, bound: f64, at: At) {
        if crossed {
            self.record(Finding::new(limit, value, bound, at));
        }
    }
}

/// The contact state behind one leak evaluation: the nominal pressure that holds the critical
/// junction (P0 of a flat seal, the peak of a profile), the fluid's ΔP, the junction, and the
/// spectrum's q1/q0.
#[derive(Debug, Clone, Copy)]
pub struct ContactState<'a> {
    /// Nominal contact pressure \[Pa\].
    pub nominal_pressure: f64,
    /// ΔP across the seal \[Pa\].
    pub pressure_difference: f64,
    pub junction: &'a Junction,
    /// q1/q0 of the spectrum.
    pub cutoff: f64,
    /// Whether the fluid pressure has lifted the seal off (state `lift_off`): the contact is
    /// open, P0 no longer holds a junction, and the verdict (not a pressure ratio) reports it.
    pub lifted_off: bool,
}

/// Pressure ratio, aspect ratio, molecular gap and nearness of the cut-off of one contact state
/// (docs/model.md §9.1–§9.4).
///
/// ΔP/P0 is evaluated only where P0 holds the junction: in contact (not lifted off) with a
/// positive P0. A seal the fluid pressure has opened is the verdict's business (state
/// `lift_off`); its ΔP/P0 (up to 1e13 on a relaxed gasket) would say nothing true about the
/// contact model.
pub fn contact(state: &ContactState<'_>, at: At, out: &mut Findings) {
    if !state.lifted_off && state.nominal_pressure > 0.0 {
        let ratio = state.pressure_difference / state.nominal_pressure;
        out.check(
            Limit::PressureRatio,
            ratio > MAX_PRESSURE_RATIO,
            ratio,
            MAX_PRESSURE_RATIO,
            at,
        );
    }
    if let Junction::Leaking(j) = state.junction {
        let aspect = j.u_c / j.lambda_c;
        out.check(
            Limit::AspectRatio,
            aspect > MAX_ASPECT_RATIO,
            aspect,
            MAX_ASPECT_RATIO,
            at,
        );
        out.check(
            Limit::MolecularGap,
            j.u_c < MIN_CONTINUUM_GAP,
            j.u_c,
            MIN_CONTINUUM_GAP,
            at,
        );
        let near = NEAR_CUTOFF_FRACTION * state.cutoff;
        out.check(Limit::NearCutoff, j.zeta_c > near, j.zeta_c, near, at);
    }
}

/// The contact width `width` \[m\] against the longest roughness wavelength 2π/`q0` (docs/model.md
/// §9.16): fewer than [`MIN_WAVELENGTHS_ACROSS`] across is a finding.
pub fn contact_width(width: f64, q0: f64, at: At, out: &mut Findings) {
    let across = width * q0 / (2.0 * std::f64::consts::PI);
    out.check(
        Limit::NarrowContact,
        across < MIN_WAVELENGTHS_ACROSS,
        across,
        MIN_WAVELENGTHS_ACROSS,
        at,
    );
}

/// The Knudsen number `kn` of a gas at the critical constriction (docs/model.md §9.14): the
/// regime it is in — slip, transition or free molecular, each over its own band — when the
/// rarefied law is used (`rarefied`); past the slip threshold at all under the continuum law.
pub fn knudsen(kn: f64, rarefied: bool, at: At, out: &mut Findings) {
    if !rarefied {
        out.check(
            Limit::KnudsenContinuumLaw,
            kn > KNUDSEN_SLIP,
            kn,
            KNUDSEN_SLIP,
            at,
        );
        return;
    }
    for (limit, lo, hi) in [
        (Limit::KnudsenSlip, KNUDSEN_SLIP, KNUDSEN_TRANSITION),
        (
            Limit::KnudsenTransition,
            KNUDSEN_TRANSITION,
            KNUDSEN_FREE_MOLECULAR,
        ),
        (
            Limit::KnudsenFreeMolecular,
            KNUDSEN_FREE_MOLECULAR,
            f64::INFINITY,
        ),
    ] {
        out.check(limit, kn > lo && kn <= hi, kn, lo, at);
    }
}

/// Hurst exponent (self-affine spectra) and rms slope of the surface (docs/model.md §9.5,
/// §9.8).
pub fn surface(spectrum: &Spectrum, out: &mut Findings) {
    if let Some(h) = spectrum.hurst_exponent() {
        let (lo, hi) = HURST_RANGE;
        let bound = if h < lo { lo } else { hi };
        out.check(
            Limit::HurstExponent,
            !(lo..=hi).contains(&h),
            h,
            bound,
            At::Setup,
        );
    }
    let slope = spectrum.rms_slope();
    out.check(
        Limit::RmsSlope,
        slope > MAX_RMS_SLOPE,
        slope,
        MAX_RMS_SLOPE,
        At::Setup,
    );
}

/// Temperature `t` \[K\] against the glass transition `glass_transition` \[K\] and the WLF frozen
/// limit `frozen_below` \[K\] (docs/model.md §9.7).
pub fn temperature(
    t: f64,
    glass_transition: Option<f64>,
    frozen_below: Option<f64>,
    at: At,
    out: &mut Findings,
) {
    if let Some(limit) = frozen_below {
        out.check(Limit::Frozen, t <= limit, t, limit, at);
    }
    if let Some(tg) = glass_transition {
        out.check(Limit::GlassTransition, t < tg, t, tg, at);
    }
}

/// A life state's reduced time `xi` \[s\] and temperature `t` \[K\] against the windows of the
/// material's data, when it gives them (docs/model.md §9.13).
pub fn data_window(
    xi: f64,
    t: f64,
    reduced_time: Option<(f64, f64)>,
    temperature: Option<(f64, f64)>,
    at: At,
    out: &mut Findings,
) {
    if let Some((_, hi)) = reduced_time {
        out.check(Limit::DataTime, xi > hi, xi, hi, at);
    }
    if let Some((lo, hi)) = temperature {
        let bound = if t < lo { lo } else { hi };
        out.check(
            Limit::DataTemperature,
            !(lo..=hi).contains(&t),
            t,
            bound,
            at,
        );
    }
}

/// An O-ring's squeeze `eps` against Lindley's range (docs/model.md §9.6).
pub fn squeeze(eps: f64, at: At, out: &mut Findings) {
    let (lo, hi) = LINDLEY_RANGE;
    let bound = if eps < lo { lo } else { hi };
    out.check(Limit::Squeeze, !(lo..=hi).contains(&eps), eps, bound, at);
}

/// A sliding `speed` \[m/s\] against the PY08 §8 bound `bound` \[m/s\] (docs/model.md §9.9).
pub fn speed(speed: f64, bound: f64, at: At, out: &mut Findings) {
    out.check(Limit::SpeedBound, speed > bound, speed, bound, at);
}

/// The findings of a stroke cycle or sliding motion at one state (docs/model.md §9.9): with
/// inverse-hydrodynamic films (`point.ihl`) a speed inside the blend band and an estimated
/// gradient; without, the PY08 speed bound as [`speed`].
pub fn motion(fastest: f64, point: &crate::dynamic::MotionPoint, at: At, out: &mut Findings) {
    use crate::dynamic::ihl::{GradientSource, SpeedRegime};
    match point.ihl {
        None => speed(fastest, point.speed_bound, at, out),
        Some(ihl) => {
            if point.regime == SpeedRegime::Transition {
                let onset = point
                    .speed_bound
                    .min(ihl.film_onset_speeds.0)
                    .min(ihl.film_onset_speeds.1);
                out.check(Limit::IhlTransition, true, fastest, onset, at);
            }
            if ihl.source == GradientSource::ORingEstimate {
                out.record(Finding::new(Limit::GradientEstimate, 0.0, 0.0, at));
            }
        }
    }
}

/// The extrusion check of a groove-seated ring (docs/model.md §9.12): the diametral clearance
/// over the chart's limit, and whether the chart had to be extended.
pub fn extrusion(ratio: f64, limit: &crate::extrusion::ExtrusionLimit, at: At, out: &mut Findings) {
    out.check(
        Limit::Extrusion,
        ratio > EXTRUSION_WARNING,
        ratio,
        EXTRUSION_WARNING,
        at,
    );
    if limit.beyond_pressure || limit.beyond_hardness {
        // the chart finding has no magnitude (0 of 0): the first one's text is the one kept,
        // so a run that stays beyond the chart only counts it (not formatted at every step)
        if let Some(kept) = out
            .items
            .iter_mut()
            .find(|f| f.limit == Limit::ExtrusionChart)
        {
            kept.count += 1;
            return;
        }
        let mut f = Finding::new(Limit::ExtrusionChart, 0.0, 0.0, at);
        let hardness = if limit.backup_rings > 0 {
            String::new()
        } else if limit.hardness < 70.0 {
            format!(
                "hardness {} Shore A, below the chart: its 70-to-90 trend continued",
                human(limit.hardness, 3)
            )
        } else {
            format!(
                "hardness {} Shore A, above the chart: the 90 row used",
                human(limit.hardness, 3)
            )
        };
        let pressure = match (limit.beyond_pressure, limit.backup_rings, limit.over_rated) {
            (false, _, _) => String::new(),
            (true, 0, _) => "pressure above the chart's 3000 psi without back-up rings: the \
                             ring extrudes (declare backup_rings, rated to 40 MPa)"
                .to_owned(),
            (true, _, false) => "pressure above the chart's 3000 psi: the back-up rings' 90 \
                                 row continued by its last step"
                .to_owned(),
            (true, _, true) => "pressure above the 40 MPa back-up rings are rated for (ERIKS): \
                                the ring extrudes (special construction needed)"
                .to_owned(),
        };
        f.detail = Some(
            [pressure, hardness]
                .into_iter()
                .filter(|s| !s.is_empty())
                .collect::<Vec<_>>()
                .join("; "),
        );
        out.record(f);
    }
}

/// The numerical level resolved the band `band` of a spectrum spanning `spectrum_band` = q1/q0
/// (docs/model.md §9.10).
pub fn band_limited(band: f64, spectrum_band: f64, out: &mut Findings) {
    out.check(
        Limit::BandLimited,
        spectrum_band > band * (1.0 + 1e-9),
        spectrum_band,
        band,
        At::Setup,
    );
}

/// A node of the numerical level's table at reduced pressure `reduced_pressure` failed with
/// `message` (docs/model.md §9.10).
pub fn numerical_failure(reduced_pressure: f64, message: String, out: &mut Findings) {
    let mut f = Finding::new(
        Limit::NumericalFailure,
        reduced_pressure,
        reduced_pressure,
        At::Setup,
    );
    f.detail = Some(message);
    out.record(f);
}

/// A life run without failure criteria (docs/model.md §8).
pub fn no_failure_criterion(out: &mut Findings) {
    out.record(Finding::new(Limit::NoFailureCriterion, 0.0, 0.0, At::Setup));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every limit has its own code (in the registry, `crate::codes`: kept here so that the
    /// registry does not name this module), with the limit's id and section.
    #[test]
    fn every_validity_limit_has_its_own_code_with_its_id_and_section() {
        use crate::codes::{ALL, Kind};
        for l in Limit::ALL {
            let c = l.code();
            assert_eq!(
                (c.id, c.section, c.kind),
                (l.id(), l.section(), Kind::Validity)
            );
        }
        let validity = ALL.iter().filter(|c| c.kind == Kind::Validity).count();
        assert_eq!(validity, Limit::ALL.len());
    }
    use crate::contact::CriticalJunction;

    fn junction(u_c: f64, lambda_c: f64, zeta_c: f64) -> Junction {
        Junction::Leaking(CriticalJunction {
            zeta_c,
            lambda_c,
            u_c,
            ubar_c: 0.5 * u_c,
            hrms_c: u_c,
        })
    }

    #[test]
    fn each_contact_limit_fires_exactly_past_its_threshold() {
        let j = junction(1e-7, 1e-5, 10.0);
        let state = |p0: f64, j: &Junction| {
            let mut out = Findings::default();
            contact(
                &ContactState {
                    nominal_pressure: p0,
                    pressure_difference: 1e4,
                    junction: j,
                    cutoff: 100.0,
                    lifted_off: false,
                },
                At::Pressure(p0),
                &mut out,
            );
            out
        };
        assert!(state(2e4, &j).is_empty(), "ΔP/P0 = 0.5 exactly is inside");
        assert!(state(1.99e4, &j).get(Limit::PressureRatio).is_some());
        let steep = junction(2e-6, 1e-5, 10.0);
        assert!(state(1e6, &steep).get(Limit::AspectRatio).is_some());
        let thin = junction(0.5e-9, 1e-5, 10.0);
        let f = state(1e6, &thin);
        let m = f.get(Limit::MolecularGap).map(|f| (f.value, f.bound));
        assert_eq!(m, Some((0.5e-9, 1e-9)));
        let late = junction(1e-7, 1e-5, 51.0);
        assert!(state(1e6, &late).get(Limit::NearCutoff).is_some());
        assert!(state(1e6, &Junction::Sealed).is_empty());
    }

    #[test]
    fn the_pressure_ratio_is_not_evaluated_where_p0_holds_no_junction() {
        // the review's relaxed gasket: P0 → 0 gave "ΔP/P0 = 9.863e12"; lifted off, or with no
        // contact pressure, the seal is open and the verdict says so
        let j = Junction::Sealed;
        for (p0, lifted_off) in [(6e5 / 9.863e12, true), (0.0, false), (1e5, true)] {
            let mut out = Findings::default();
            contact(
                &ContactState {
                    nominal_pressure: p0,
                    pressure_difference: 6e5,
                    junction: &j,
                    cutoff: 100.0,
                    lifted_off,
                },
                At::Time(1.0),
                &mut out,
            );
            assert!(
                out.is_empty(),
                "P0 = {p0}, lifted off {lifted_off}: {out:?}"
            );
        }
    }

    #[test]
    fn every_finding_fits_one_line_with_its_code_even_with_a_long_context() {
        for limit in Limit::ALL {
            for (value, bound) in [(9.863e12, 0.5), (1.0e-300, 3.3e-9), (0.98, 0.5)] {
                let mut f = Finding::new(limit, value, bound, At::Time(3.156e8));
                f.first = At::Time(3.0e7);
                f.count = 55;
                f.detail = Some("x".repeat(300));
                for context in [None, Some("nbr-70, fkm-75, epdm-70, vmq-70, ffkm-75")] {
                    let line = f.line(context);
                    assert!(line.chars().count() <= MAX_LINE, "{line}");
                    let code = limit.code().code;
                    assert!(line.starts_with(&format!("warning[{code}]: ")), "{line}");
                    assert!(line.ends_with(&format!("sealsim explain {code}")), "{line}");
                }
            }
        }
        let mut f = Finding::new(Limit::PressureRatio, 1.0, 0.5, At::Time(3.156e8));
        f.first = At::Time(350.0 * 86_400.0);
        f.count = 31;
        assert_eq!(f.short(), "ΔP/P0 = 1 > 0.5 from 350 d (worst 10 y)");
    }

    #[test]
    fn findings_keep_the_worst_and_the_first() {
        let mut out = Findings::default();
        for (t, ratio) in [(1.0, 0.12), (10.0, 0.16), (100.0, 0.14)] {
            out.check(Limit::PressureRatio, true, ratio, 0.1, At::Time(t));
        }
        let f = out.get(Limit::PressureRatio).cloned();
        let f = f.as_ref();
        assert_eq!(f.map(|f| f.value), Some(0.16));
        assert_eq!(f.map(|f| f.at), Some(At::Time(10.0)));
        assert_eq!(f.map(|f| f.first), Some(At::Time(1.0)));
        assert_eq!(f.map(|f| f.count), Some(3));
        assert_eq!(out.len(), 1);
    }

    #[test]
    fn severity_measures_both_sides_of_a_range() {
        let mut out = Findings::default();
        squeeze(0.04, At::Time(0.0), &mut out); // 1.25× below 5 %
        squeeze(0.45, At::Time(1.0), &mut out); // 1.5× above 30 %
        squeeze(0.2, At::Time(2.0), &mut out); // inside
        let f = out.get(Limit::Squeeze).cloned();
        assert_eq!(f.as_ref().map(|f| (f.value, f.bound)), Some((0.45, 0.3)));
        assert_eq!(f.map(|f| f.count), Some(2));
    }

    #[test]
    fn messages_name_value_bound_place_and_section() {
        let mut out = Findings::default();
        for (t, ratio) in [(0.0, 0.13), (3.156e8, 0.16)] {
            out.check(Limit::PressureRatio, true, ratio, 0.1, At::Time(t));
        }
        let text = out.iter().map(ToString::to_string).collect::<String>();
        assert!(text.contains("ΔP/P0 = 0.16 is above 0.1"), "{text}");
        assert!(text.contains("worst at t = 3.156e8 s (10 years)"), "{text}");
        assert!(text.contains("first at t = 0 s, 2 evaluations"), "{text}");
        assert!(text.contains("docs/model.md §9.1"), "{text}");
    }

    #[test]
    fn every_limit_has_a_unique_id_and_a_section() {
        let mut ids: Vec<&str> = Limit::ALL.iter().map(|l| l.id()).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), Limit::ALL.len());
        assert!(Limit::ALL.iter().all(|l| l.section().starts_with('§')));
    }
}
