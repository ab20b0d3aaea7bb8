//! The measured speed/accuracy trade of the fidelity ladder (docs/model.md §4): one scenario's static
//! state and life run at every level and at a ladder of numerical settings, each with its wall
//! time and its error against the most accurate setting run.
//!
//! Two sections:
//! * **full spectrum** — the analytic levels (rule of thumb, critical junction by table and by
//!   quadrature, effective medium) on the scenario's own spectrum, static and life. Reference:
//!   the critical junction by quadrature with 4× the quadrature nodes and 4× the time grid
//!   (and the clogging tolerance ×0.01, with `[contamination]`) — the paper's model,
//!   converged. The errors of the table and of the quadrature settings
//!   are numerical; those of the rule of thumb and of the effective medium are model
//!   differences.
//! * **band-limited** — the numerical reference resolves only a band q1/q0 of a few tens, so
//!   it is compared with the analytic levels on the same band: the spectrum of the synthetic
//!   surfaces as the lattice carries it (re-estimated from one realisation, which is the same
//!   for every seed because the amplitudes are deterministic, [`crate::numerical::surface`]),
//!   at the nominal pressure where Persson's contact fraction is 0.2 (the scenario's own
//!   pressure usually seals the band-limited surface). Static only. Reference: the finest
//!   numerical setting.
//!
//! Timing is wall-clock on the calling thread (repeated until ≥ 50 ms for fast settings, the
//! mean reported); the numerical level's contact solver uses two threads for its FFTs.

use crate::contact::{QuadratureSettings, TableSettings};
use crate::fluid::Conduction;
use crate::leak::{ContactPath, Fidelity, PathOptions, StaticProblem, StaticSolver};
use crate::math::special::erf_inv;
use crate::numerical::psd::{self, PsdOptions, Window};
use crate::numerical::reference::{NumericalSettings, Surfaces, band_limited, evaluate};
use crate::numerical::surface::synthesize;
use crate::simulate::{LifeProblem, Simulator};
use std::f64::consts::PI;
use std::time::Instant;

/// Which comparison a row belongs to (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Section {
    FullSpectrum,
    BandLimited,
}

impl Section {
    pub fn name(self) -> &'static str {
        match self {
            Section::FullSpectrum => "full-spectrum",
            Section::BandLimited => "band-limited",
        }
    }
}

/// What a life run is judged by: the time to failure when the reference fails, else the
/// volume leaked over the whole run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LifeOutcome {
    /// Wall time of the run, path (table) build included (s).
    pub seconds: f64,
    pub time_to_failure: Option<f64>,
    pub leaked_volume: f64,
    /// Relative error of the judged quantity against the reference; `None` when undefined
    /// (one fails and the other does not).
    pub error: Option<f64>,
}

/// One setting of one level.
#[derive(Debug, Clone, PartialEq)]
pub struct TradeoffRow {
    pub section: Section,
    pub level: Fidelity,
    /// The setting, e.g. `table 12 pts/decade`, `quadrature ×2, time grid ×1`.
    pub setting: String,
    /// Nominal pressure of the static state (Pa).
    pub nominal_pressure: f64,
    /// Wall time of the static state: path (table) build plus one evaluation (s).
    pub static_seconds: f64,
    /// Static leak rate (m³/s).
    pub leak_rate: f64,
    /// |Q̇/Q̇_ref − 1|; `None` when the reference is sealed and this is not (or vice versa).
    pub static_error: Option<f64>,
    /// The life run (full-spectrum section only).
    pub life: Option<LifeOutcome>,
    /// For the numerical level: the standard deviation of the leak rate over realisations.
    pub leak_rate_spread: Option<f64>,
}

/// Options of a trade-off study.
#[derive(Debug, Clone, PartialEq)]
pub struct TradeoffOptions {
    /// Band q1/q0 of the numerical comparison (default 32).
    pub band: f64,
    /// (pixels per shortest wavelength, realisations) of the numerical ladder; the last is the
    /// band-limited reference.
    pub numerical_ladder: Vec<(usize, usize)>,
    /// Seed of the synthetic surfaces.
    pub seed: u64,
    /// Skip the band-limited section (no numerical level).
    pub skip_numerical: bool,
}

impl Default for TradeoffOptions {
    fn default() -> Self {
        TradeoffOptions {
            band: 32.0,
            numerical_ladder: vec![(4, 8), (8, 8), (16, 8), (16, 32)],
            seed: 1,
            skip_numerical: false,
        }
    }
}

/// Mean wall time of `f` in seconds, repeated until 50 ms have passed (at most 1000 times);
/// returns the last result.
fn timed<T>(mut f: impl FnMut() -> T) -> (f64, T) {
    let start = Instant::now();
    let mut runs = 0u32;
    loop {
        let value = f();
        runs += 1;
        let elapsed = start.elapsed().as_secs_f64();
        if elapsed >= 0.05 || runs >= 1000 {
            return (elapsed / f64::from(runs), value);
        }
    }
}

fn relative_error(value: f64, reference: f64) -> Option<f64> {
    if reference == 0.0 {
        (value == 0.0).then_some(0.0)
    } else if value == 0.0 {
        None
    } else {
        Some((value / reference - 1.0).abs())
    }
}

/// The relative error of a leak rate or leaked volume with both raised to `floor` first
/// (docs/model.md §15.4): `|max(v, f)/max(r, f) − 1|`. Below the floor nothing flows but single
/// molecules, so two rates under it agree (0) and a difference there is never an error; a
/// setting that leaks where the reference is sealed in practice has the error of its excess
/// over the floor.
fn floored_error(value: f64, reference: f64, floor: f64) -> Option<f64> {
    if floor > 0.0 {
        Some((value.max(floor) / reference.max(floor) - 1.0).abs())
    } else {
        relative_error(value, reference)
    }
}

/// One analytic setting of the full-spectrum section.
struct Setting {
    level: Fidelity,
    label: String,
    table: TableSettings,
    quadrature: f64,
    time_grid: f64,
    /// Factor on the clogging ODE tolerance (only with `[contamination]`).
    clogging_tolerance: f64,
}

fn full_spectrum_ladder(clogging: bool) -> Vec<Setting> {
    let base = |level, label: &str| Setting {
        level,
        label: label.to_owned(),
        table: TableSettings::default(),
        quadrature: 1.0,
        time_grid: 1.0,
        clogging_tolerance: 1.0,
    };
    let mut ladder = vec![base(Fidelity::RuleOfThumb, "closed form")];
    for ppd in [3.0, 6.0, 12.0, 24.0] {
        ladder.push(Setting {
            table: TableSettings {
                points_per_decade: ppd,
                ..TableSettings::default()
            },
            ..base(Fidelity::Table, &format!("table {ppd} pts/decade"))
        });
    }
    for q in [0.5, 1.0, 2.0] {
        ladder.push(Setting {
            quadrature: q,
            ..base(Fidelity::Exact, &format!("quadrature ×{q}"))
        });
    }
    for g in [0.25, 0.5, 2.0] {
        ladder.push(Setting {
            time_grid: g,
            ..base(Fidelity::Table, &format!("table, time grid ×{g}"))
        });
    }
    if clogging {
        for f in [100.0, 0.01] {
            ladder.push(Setting {
                clogging_tolerance: f,
                ..base(Fidelity::Table, &format!("table, clogging tolerance ×{f}"))
            });
        }
    }
    ladder.push(base(Fidelity::EffectiveMedium, "table 8 pts/decade"));
    ladder.push(Setting {
        table: TableSettings {
            points_per_decade: 24.0,
            ..TableSettings::default()
        },
        ..base(Fidelity::EffectiveMedium, "table 16 pts/decade")
    });
    ladder
}

fn with_settings(problem: &LifeProblem, setting: &Setting) -> LifeProblem {
    let mut p = problem.clone();
    p.contact.quadrature = QuadratureSettings::default().refined(setting.quadrature);
    p.time.points_per_decade *= setting.time_grid;
    if let Some(c) = &mut p.contamination {
        c.tolerance *= setting.clogging_tolerance;
    }
    p.fidelity = setting.level;
    p
}

/// The analytic path of `life` (its spectrum, contact settings and fidelity) with the setting's
/// table spacing — built inside the timed region, since a user pays for it on every new surface.
fn analytic_path(life: &LifeProblem, setting: &Setting) -> ContactPath {
    let options = PathOptions {
        table: setting.table,
        molecular_size: life.fluid.molecular_size(),
        ..PathOptions::default()
    };
    ContactPath::build(
        &life.spectrum,
        life.contact,
        life.fidelity,
        &options,
        &mut |_, _| {},
    )
}

/// The static state `sealsim leak` evaluates — a flat seal at its nominal pressure, an O-ring
/// installed ([`super::leak::installed_oring`]) — timed with the path's build: (seconds, leak
/// rate \[m³/s\], its pressure \[Pa\]).
fn static_state(
    problem: &StaticProblem,
    life: &LifeProblem,
    setting: &Setting,
) -> (f64, (f64, f64)) {
    let mut pb = problem.clone();
    pb.contact = life.contact;
    timed(|| {
        let path = analytic_path(life, setting);
        let point = if life.geometry.pressure_from_squeeze() {
            super::leak::installed_oring(life, &path, None)
                .into_iter()
                .next()
        } else {
            Some(StaticSolver::with_path(pb.clone(), path).evaluate(pb.seal.nominal_pressure))
        };
        point.map_or((0.0, pb.seal.nominal_pressure), |p| {
            (p.leak_rate, p.nominal_pressure)
        })
    })
}

fn life_run(problem: &LifeProblem, setting: &Setting) -> (f64, Option<f64>, f64) {
    let (seconds, result) =
        timed(|| Simulator::with_path(problem, analytic_path(problem, setting)).run());
    (
        seconds,
        result.failure.map(|f| f.time),
        result.leaked_volume(),
    )
}

/// Runs the study; `progress(done, total)` after every setting.
pub fn run(
    problem: &StaticProblem,
    life: &LifeProblem,
    options: &TradeoffOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> Vec<TradeoffRow> {
    let ladder = full_spectrum_ladder(life.contamination.is_some());
    let numerical = if options.skip_numerical {
        0
    } else {
        options.numerical_ladder.len() + 3
    };
    let total = ladder.len() + 1 + numerical;
    let mut done = 0;
    let mut step = |progress: &mut dyn FnMut(usize, usize)| {
        done += 1;
        progress(done, total);
    };

    // the full-spectrum reference: quadrature ×4, time grid ×4
    let reference = Setting {
        level: Fidelity::Exact,
        label: "quadrature ×4, time grid ×4 (reference)".to_owned(),
        table: TableSettings::default(),
        quadrature: 4.0,
        time_grid: 4.0,
        clogging_tolerance: 0.01,
    };
    let ref_life = with_settings(life, &reference);
    let (ref_static_s, (ref_q, pressure)) = static_state(problem, &ref_life, &reference);
    let (ref_life_s, ref_ttf, ref_volume) = life_run(&ref_life, &reference);
    step(progress);
    // a surviving seal is judged on its leaked volume, floored at one molecule a second over
    // the run: differences below that are not errors (docs/model.md §15.4)
    let rate_floor = life.fluid.one_molecule_per_second();
    let volume_floor = rate_floor * life.time.duration;
    let judge = |ttf: Option<f64>, volume: f64| match ref_ttf {
        Some(r) => ttf.and_then(|t| relative_error(t, r)),
        None => match ttf {
            Some(_) => None,
            None => floored_error(volume, ref_volume, volume_floor),
        },
    };
    let mut rows = vec![TradeoffRow {
        section: Section::FullSpectrum,
        level: Fidelity::Exact,
        setting: reference.label.clone(),
        nominal_pressure: pressure,
        static_seconds: ref_static_s,
        leak_rate: ref_q,
        static_error: Some(0.0),
        life: Some(LifeOutcome {
            seconds: ref_life_s,
            time_to_failure: ref_ttf,
            leaked_volume: ref_volume,
            error: Some(0.0),
        }),
        leak_rate_spread: None,
    }];
    for setting in &ladder {
        let lp = with_settings(life, setting);
        let (static_seconds, (q, pressure)) = static_state(problem, &lp, setting);
        let (life_seconds, ttf, volume) = life_run(&lp, setting);
        rows.push(TradeoffRow {
            section: Section::FullSpectrum,
            level: setting.level,
            setting: setting.label.clone(),
            nominal_pressure: pressure,
            static_seconds,
            leak_rate: q,
            static_error: floored_error(q, ref_q, rate_floor),
            life: Some(LifeOutcome {
                seconds: life_seconds,
                time_to_failure: ttf,
                leaked_volume: volume,
                error: judge(ttf, volume),
            }),
            leak_rate_spread: None,
        });
        step(progress);
    }
    if !options.skip_numerical {
        rows.extend(band_limited_section(problem, options, &mut || {
            step(progress)
        }));
    }
    rows
}

/// The band-limited section (module docs).
fn band_limited_section(
    problem: &StaticProblem,
    options: &TradeoffOptions,
    step: &mut dyn FnMut(),
) -> Vec<TradeoffRow> {
    let Ok(band) = band_limited(&problem.spectrum, options.band) else {
        return Vec::new();
    };
    // the spectrum the lattice carries: the periodic map's own estimate (no window)
    let finest = options
        .numerical_ladder
        .iter()
        .map(|&(ppw, _)| ppw)
        .max()
        .unwrap_or(8);
    let settings_for = |ppw: usize, realisations: usize| NumericalSettings {
        band: options.band,
        pixels_per_wavelength: ppw,
        realisations,
        seed: options.seed,
        ..NumericalSettings::default()
    };
    let map = synthesize(&band, settings_for(finest, 1).grid_size(), options.seed);
    let estimate = psd::estimate(
        &map,
        &PsdOptions {
            window: Window::Rectangular,
            ..PsdOptions::default()
        },
    )
    .unwrap_or_else(|_| band.clone());
    let mut pb = problem.clone();
    pb.spectrum = estimate;
    let e_star = pb.material.effective_modulus();
    // Persson's contact fraction A(ζ1)/A0 = erf(s/√(π M3(q1))) = 0.2
    let s = erf_inv(0.2) * (PI * pb.spectrum.total_m3()).sqrt();
    let p0 = s * e_star;
    pb.seal.nominal_pressure = p0;
    // the leak law is linear in σ: the mean and the spread of σ map to leak rates alike. Like
    // for like: the numerical level gives σ(P0), the local conductance at one pressure, so the
    // analytic rows below use theirs too — the fluid pressure inside the interface
    // (docs/model.md §3.6) is the same integral over either σ and is left out of this section
    let leak_rate_of = |conductance: f64| {
        pb.fluid
            .leak_rate(pb.seal.geometry(), Conduction::Uniform { conductance })
    };

    let mut rows = Vec::new();
    let mut numerical = Vec::new();
    for &(ppw, realisations) in &options.numerical_ladder {
        let settings = settings_for(ppw, realisations);
        let start = Instant::now();
        let state = evaluate(
            Surfaces::Synthetic(&band),
            e_star,
            p0,
            pb.fluid.viscosity,
            &settings,
            &mut |_, _| {},
        );
        let seconds = start.elapsed().as_secs_f64();
        step();
        let Ok(state) = state else { continue };
        numerical.push(TradeoffRow {
            section: Section::BandLimited,
            level: Fidelity::Numerical,
            setting: format!(
                "{n}², {ppw} px/wavelength, {realisations} realisations",
                n = settings.grid_size()
            ),
            nominal_pressure: p0,
            static_seconds: seconds,
            leak_rate: leak_rate_of(state.conductance.mean),
            static_error: None,
            life: None,
            leak_rate_spread: Some(leak_rate_of(state.conductance.std_dev)),
        });
    }
    let reference = numerical.last().map_or(0.0, |r| r.leak_rate);
    for level in [
        Fidelity::RuleOfThumb,
        Fidelity::Exact,
        Fidelity::EffectiveMedium,
    ] {
        let (seconds, conductance) = timed(|| {
            StaticSolver::new(pb.clone(), level).path().conductance(
                p0 / e_star,
                pb.shape_factor,
                pb.fluid.viscosity,
                pb.fluid.molecular_size(),
            )
        });
        let leak_rate = leak_rate_of(conductance);
        rows.push(TradeoffRow {
            section: Section::BandLimited,
            level,
            setting: "band-limited spectrum".to_owned(),
            nominal_pressure: p0,
            static_seconds: seconds,
            leak_rate,
            static_error: floored_error(leak_rate, reference, pb.fluid.one_molecule_per_second()),
            life: None,
            leak_rate_spread: None,
        });
        step();
    }
    for row in &mut numerical {
        row.static_error =
            floored_error(row.leak_rate, reference, pb.fluid.one_molecule_per_second());
    }
    rows.extend(numerical);
    rows
}

/// The trade-off of a scenario with the validity findings of the scenario itself (its static
/// state and its life at the critical-junction table level, docs/model.md §9): the levels'
/// rows say how fast and how far from the reference each level is; the findings say how far
/// the model holds for this seal at all.
#[derive(Debug, Clone)]
pub struct ScenarioTradeoff {
    pub rows: Vec<TradeoffRow>,
    pub findings: crate::validity::Findings,
}

/// [`run`] on a validated scenario, with its findings.
pub fn for_scenario(
    scenario: &crate::scenario::Scenario,
    options: &TradeoffOptions,
    progress: &mut dyn FnMut(usize, usize),
) -> ScenarioTradeoff {
    let rows = run(&scenario.problem, &scenario.life, options, progress);
    let mut table_level = scenario.clone();
    table_level.life.fidelity = Fidelity::Table;
    // one contact table for the static state and the life
    let (path, findings) =
        super::scenario_path(&table_level, Fidelity::Table, None, &mut |_, _| {});
    let mut findings =
        super::leak::evaluate_on(&table_level, path.clone(), findings, None).findings;
    findings.extend(super::life_on(&table_level.life, path, Default::default()).findings);
    ScenarioTradeoff { rows, findings }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differences_below_the_floor_are_not_errors() {
        let floor = 3e-29;
        // two sealed-in-practice rates nine decades apart: no error (the plain relative error
        // would be 1e9)
        assert!((relative_error(1e-31, 1e-40).unwrap() / 1e9 - 1.0).abs() < 1e-6);
        assert_eq!(floored_error(1e-31, 1e-40, floor), Some(0.0));
        assert_eq!(floored_error(0.0, 1e-35, floor), Some(0.0));
        // above the floor the plain relative error
        assert_eq!(floored_error(2e-12, 1e-12, floor), Some(1.0));
        // a setting that leaks where the reference is sealed: its excess over the floor
        assert!((floored_error(6e-29, 0.0, floor).unwrap() - 1.0).abs() < 1e-12);
    }
}
