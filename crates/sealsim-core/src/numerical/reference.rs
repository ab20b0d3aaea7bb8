//! The numerical level (docs/model.md §3.5, §4): an ensemble of contact-and-flow solutions at one
//! nominal pressure.
//!
//! Per realisation: a periodic random-phase surface from the spectrum ([`super::surface`], or a
//! measured height map as the single realisation), frictionless elastic contact by FFT boundary
//! elements at the mean pressure P0 ([`super::bem`], Polonsky & Keer 1999), non-contact
//! percolation along the flow ([`super::percolation`]) and thin-film Reynolds flow through the
//! gap field ([`super::flow`]) → effective conductance σ_eff. The ensemble gives the mean and
//! the spread of σ_eff, of the contact fraction and of the mean gap; the leak rate of a flat
//! seal is `Q̇ = (L_y/L_x) σ_eff ΔP` (docs/model.md §3.3, as for the effective medium).
//!
//! The grid resolves only a band of wavevectors: the synthetic surfaces keep the spectrum on
//! `[q0, band · q0]` ([`band_limited`]); comparisons with the analytic levels are made on that
//! same band-limited spectrum.

use super::HeightMap;
use super::bem::{self, BemError, BemSettings, Boundary, Load};
use super::flow::{self, FlowError, FlowSettings};
use super::surface::synthesize;
use crate::surface::{Spectrum, SpectrumError};
use std::fmt;

/// Settings of the numerical level.
#[derive(Debug, Clone, PartialEq)]
pub struct NumericalSettings {
    /// Wavevector band `q1/q0` the synthetic surfaces resolve (default 32).
    pub band: f64,
    /// Pixels per shortest wavelength `2π/(q1 a)` (default 8); the grid has
    /// `n = band · pixels_per_wavelength` points per side.
    pub pixels_per_wavelength: usize,
    /// Number of surface realisations (default 8).
    pub realisations: usize,
    /// Seed of the first realisation; realisation `k` uses `seed + k`.
    pub seed: u64,
    pub bem: BemSettings,
    pub flow: FlowSettings,
}

impl Default for NumericalSettings {
    fn default() -> Self {
        NumericalSettings {
            band: 32.0,
            pixels_per_wavelength: 8,
            realisations: 8,
            seed: 1,
            bem: BemSettings::default(),
            flow: FlowSettings::default(),
        }
    }
}

/// Largest grid the numerical level solves, in pixels: 8192² (2²⁶), the height-map readers'
/// bound too. An engineering bound (assumed), not a property of the model: the contact and
/// flow solvers hold about [`BYTES_PER_PIXEL`] a pixel, so 8192² needs ≈ 4.8 GB; one pixel
/// more per side than this can exhaust the memory of a workstation, and an allocation failure
/// aborts the process (a Python interpreter with it) rather than failing cleanly.
pub const MAX_GRID_PIXELS: usize = 1 << 26;

/// Memory the numerical level holds per grid pixel while it solves one realisation \[B\]:
/// 1.17 GB at 4096² and 4.69 GB at 8192² (peak RSS of `benches/bem-peers.sh`'s solve on the
/// 2-core benchmark machine, 2026-11-29; ≈ 70 B), rounded up.
pub const BYTES_PER_PIXEL: f64 = 72.0;

impl NumericalSettings {
    /// The memory one realisation needs, estimated from its pixel count \[B\]
    /// (`BYTES_PER_PIXEL · n²`).
    pub fn estimated_memory(&self) -> f64 {
        let n = self.grid_size() as f64;
        BYTES_PER_PIXEL * n * n
    }

    /// Points per side of the synthetic surfaces, `band · pixels_per_wavelength` rounded up to
    /// an even number (at least 8).
    pub fn grid_size(&self) -> usize {
        let n = (self.band * self.pixels_per_wavelength as f64)
            .ceil()
            .max(8.0) as usize;
        n + n % 2
    }
}

/// The part of `spectrum` the numerical level resolves: `[q0, min(q1, band · q0)]`.
pub fn band_limited(spectrum: &Spectrum, band: f64) -> Result<Spectrum, SpectrumError> {
    let q0 = spectrum.q0();
    spectrum.restricted(q0, spectrum.q1().min(band * q0))
}

/// Mean, sample standard deviation, minimum and maximum of one quantity over the ensemble.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spread {
    pub mean: f64,
    /// Sample standard deviation (0 for a single realisation).
    pub std_dev: f64,
    pub min: f64,
    pub max: f64,
}

impl Spread {
    /// The statistics of `values` (not empty).
    pub fn of(values: &[f64]) -> Spread {
        let n = values.len() as f64;
        let mean = values.iter().sum::<f64>() / n;
        let var = if values.len() > 1 {
            values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)
        } else {
            0.0
        };
        Spread {
            mean,
            std_dev: var.sqrt(),
            min: values.iter().copied().fold(f64::INFINITY, f64::min),
            max: values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        }
    }

    /// Standard error of the mean, `std_dev/√count`.
    pub fn standard_error(&self, count: usize) -> f64 {
        self.std_dev / (count.max(1) as f64).sqrt()
    }
}

/// One realisation's contact and flow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Realisation {
    /// Seed of the synthetic surface (`None` for a measured map).
    pub seed: Option<u64>,
    /// A/A0 of the BEM solution.
    pub contact_fraction: f64,
    /// Mean interfacial separation ū (m).
    pub mean_gap: f64,
    /// Effective conductance σ_eff (m³/(Pa·s)); 0 when nothing percolates.
    pub conductance: f64,
    pub percolates: bool,
    /// Iterations of the contact and of the flow solve.
    pub bem_iterations: usize,
    pub flow_iterations: usize,
}

/// The ensemble at one nominal pressure.
#[derive(Debug, Clone, PartialEq)]
pub struct NumericalState {
    /// Nominal pressure P0 (Pa).
    pub nominal_pressure: f64,
    pub realisations: Vec<Realisation>,
    pub contact_fraction: Spread,
    pub mean_gap: Spread,
    /// σ_eff (m³/(Pa·s)) over the realisations (the ensemble estimate is the mean).
    pub conductance: Spread,
    /// Fraction of realisations whose non-contact region percolates along the flow.
    pub percolating_fraction: f64,
}

impl NumericalState {
    /// The effective gap of the mean conductance, `(12 η σ̄_eff)^{1/3}` (m).
    pub fn effective_gap(&self, viscosity: f64) -> f64 {
        (12.0 * viscosity * self.conductance.mean).cbrt()
    }
}

/// Where the surfaces come from.
#[derive(Debug, Clone, Copy)]
pub enum Surfaces<'a> {
    /// Random-phase realisations of the spectrum's band `[q0, band·q0]` (see
    /// [`NumericalSettings`]).
    Synthetic(&'a Spectrum),
    /// A measured map: the single realisation.
    Map(&'a HeightMap),
}

/// Why the numerical level failed.
#[derive(Debug, Clone, PartialEq)]
pub enum NumericalError {
    Spectrum(SpectrumError),
    Contact(BemError),
    Flow(FlowError),
    /// No realisation was asked for.
    NoRealisations,
}

impl fmt::Display for NumericalError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NumericalError::Spectrum(e) => write!(f, "band-limited spectrum: {e}"),
            NumericalError::Contact(e) => write!(f, "contact solve: {e}"),
            NumericalError::Flow(e) => write!(f, "flow solve: {e}"),
            NumericalError::NoRealisations => write!(f, "at least one realisation is needed"),
        }
    }
}

impl std::error::Error for NumericalError {}

/// The numerical level at nominal pressure `p0` (Pa) for a half-space of effective modulus
/// `e_star` (Pa) and a fluid of `viscosity` (Pa·s). `progress(done, total)` is called after each
/// realisation (for a progress bar; the physics does not print).
pub fn evaluate(
    surfaces: Surfaces<'_>,
    e_star: f64,
    p0: f64,
    viscosity: f64,
    settings: &NumericalSettings,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<NumericalState, NumericalError> {
    evaluate_loaded(
        surfaces,
        e_star,
        Load::MeanPressure(p0),
        viscosity,
        settings,
        progress,
        &mut |_, _, _| {},
    )
}

/// [`evaluate`] under load or displacement control, handing each realisation's fields to
/// `observe(map, contact, realisation)` as it is solved: the surface (heights in m), the
/// boundary-element solution (contact pressure in Pa and gap in m on the map's grid,
/// [`bem::ContactSolution`]) and its scalars. Each realisation's contact is at the mean pressure
/// or at the rigid-body approach `load` ([`bem::solve_load`], periodic cell); under
/// `Load::MeanPressure` the same solves as [`evaluate`], number for number (the Python
/// package's `sealsim.contact` at the numerical level).
/// Under displacement control the state's `nominal_pressure` is the ensemble mean of the
/// realisations' mean pressures (each in its solution, [`bem::ContactSolution::mean_pressure`]);
/// an approach at which no realisation touches gives zero pressure and no contact (the gap field
/// still carries the flow).
pub fn evaluate_loaded(
    surfaces: Surfaces<'_>,
    e_star: f64,
    load: Load,
    viscosity: f64,
    settings: &NumericalSettings,
    progress: &mut dyn FnMut(usize, usize),
    observe: &mut dyn FnMut(&HeightMap, &bem::ContactSolution, &Realisation),
) -> Result<NumericalState, NumericalError> {
    let mut realisations = Vec::new();
    let mut pressures = Vec::new();
    for_each_surface(surfaces, settings, &mut |map, seed, done, total| {
        let (r, p) = realise(map, seed, e_star, load, viscosity, settings, observe)?;
        realisations.push(r);
        pressures.push(p);
        progress(done, total);
        Ok(())
    })?;
    let p0 = match load {
        Load::MeanPressure(p0) => p0,
        Load::Approach(_) => pressures.iter().sum::<f64>() / pressures.len().max(1) as f64,
    };
    Ok(summarise(p0, realisations))
}

/// What [`for_each_surface`] calls on each surface: `(map, seed, done, total)`.
pub type EachSurface<'a> =
    dyn FnMut(&HeightMap, Option<u64>, usize, usize) -> Result<(), NumericalError> + 'a;

/// Calls `each(map, seed, done, total)` on every surface of the numerical level in order: the
/// measured map (seed `None`, one of one) or the synthetic realisations of the band-limited
/// spectrum (seeds `seed + k`, [`NumericalSettings`]).
pub fn for_each_surface(
    surfaces: Surfaces<'_>,
    settings: &NumericalSettings,
    each: &mut EachSurface<'_>,
) -> Result<(), NumericalError> {
    match surfaces {
        Surfaces::Map(map) => each(map, None, 1, 1),
        Surfaces::Synthetic(spectrum) => {
            if settings.realisations == 0 {
                return Err(NumericalError::NoRealisations);
            }
            let band = band_limited(spectrum, settings.band).map_err(NumericalError::Spectrum)?;
            let n = settings.grid_size();
            let total = settings.realisations;
            for k in 0..total {
                let seed = settings.seed.wrapping_add(k as u64);
                each(&synthesize(&band, n, seed), Some(seed), k + 1, total)?;
            }
            Ok(())
        }
    }
}

/// One realisation's contact, flow and mean pressure (Pa).
fn realise(
    map: &HeightMap,
    seed: Option<u64>,
    e_star: f64,
    load: Load,
    viscosity: f64,
    settings: &NumericalSettings,
    observe: &mut dyn FnMut(&HeightMap, &bem::ContactSolution, &Realisation),
) -> Result<(Realisation, f64), NumericalError> {
    let contact = bem::solve_load(map, e_star, load, Boundary::Periodic, &settings.bem)
        .map_err(NumericalError::Contact)?;
    let flow = flow::solve(&contact.gap, map.n, map.pixel, viscosity, &settings.flow)
        .map_err(NumericalError::Flow)?;
    let realisation = Realisation {
        seed,
        contact_fraction: contact.contact_fraction,
        mean_gap: contact.mean_gap,
        conductance: flow.conductance,
        percolates: flow.percolates,
        bem_iterations: contact.iterations,
        flow_iterations: flow.iterations,
    };
    observe(map, &contact, &realisation);
    Ok((realisation, contact.mean_pressure))
}

fn summarise(p0: f64, realisations: Vec<Realisation>) -> NumericalState {
    let of =
        |f: fn(&Realisation) -> f64| Spread::of(&realisations.iter().map(f).collect::<Vec<_>>());
    let percolating = realisations.iter().filter(|r| r.percolates).count();
    NumericalState {
        nominal_pressure: p0,
        contact_fraction: of(|r| r.contact_fraction),
        mean_gap: of(|r| r.mean_gap),
        conductance: of(|r| r.conductance),
        percolating_fraction: percolating as f64 / realisations.len() as f64,
        realisations,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_of_known_values() {
        let s = Spread::of(&[1.0, 2.0, 3.0, 4.0]);
        assert_eq!((s.mean, s.min, s.max), (2.5, 1.0, 4.0));
        assert!((s.std_dev - (5.0f64 / 3.0).sqrt()).abs() < 1e-15);
        assert_eq!(Spread::of(&[7.0]).std_dev, 0.0);
    }

    #[test]
    fn observed_fields_are_the_ensemble_s_solves() {
        // 3 realisations of a 32² grid (band 8, 4 pixels per wavelength) at P0/E* = 0.02
        let spectrum = Spectrum::self_affine(1e-6, 0.8, 1e5, 1e7, None).unwrap();
        let settings = NumericalSettings {
            band: 8.0,
            pixels_per_wavelength: 4,
            realisations: 3,
            ..NumericalSettings::default()
        };
        let surfaces = Surfaces::Synthetic(&spectrum);
        let plain = evaluate(surfaces, 1.0, 0.02, 1.0, &settings, &mut |_, _| {}).unwrap();
        let mut seen = Vec::new();
        let observed = evaluate_loaded(
            surfaces,
            1.0,
            Load::MeanPressure(0.02),
            1.0,
            &settings,
            &mut |_, _| {},
            &mut |map, contact, r| {
                // the fields behind the scalars: contact is a positive pressure, ū the mean gap
                let n2 = (map.n * map.n) as f64;
                let touching = contact.pressure.iter().filter(|p| **p > 0.0).count();
                assert_eq!(touching as f64 / n2, r.contact_fraction);
                let mean = contact.gap.iter().sum::<f64>() / n2;
                assert!((mean - r.mean_gap).abs() <= 1e-12 * r.mean_gap);
                assert_eq!((map.n, contact.gap.len()), (32, 32 * 32));
                seen.push(*r);
            },
        )
        .unwrap();
        assert_eq!(observed, plain, "observing changes no number");
        assert_eq!(seen, plain.realisations);
    }

    #[test]
    fn grid_size_follows_band_and_resolution() {
        let mut s = NumericalSettings::default();
        assert_eq!(s.grid_size(), 256);
        s.pixels_per_wavelength = 4;
        s.band = 31.0;
        assert_eq!(s.grid_size(), 124);
    }
}
