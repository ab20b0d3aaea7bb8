//! sealsim — leak rate and life of rubber seals from rough-surface contact mechanics.
//!
//! The physics follows B.N.J. Persson and C. Yang, *Theory of the leak-rate of seals*,
//! J. Phys.: Condens. Matter 20 (2008) 315011 (cited below as "PY08 §n"); every formula, its
//! source and its validity limits are written out in the model reference, `docs/model.md`
//! (cited as "docs/model.md §n").
//!
//! Architecture: dependencies point inwards.
//! * input boundary: [`units`] (unit strings → SI), [`scenario`] (TOML → validated model types);
//! * physics: [`surface`] (roughness spectra), [`contact`] (Persson contact mechanics, critical
//!   junction, effective medium, contact tables), [`fluid`] (the leak law), [`leak`] (the
//!   fidelity ladder of a flat seal), [`material`] (Prony series, shift, fits), [`seal`]
//!   (pressure profiles), [`dynamic`] (reciprocating seals), [`clogging`], [`numerical`] (the
//!   numerical reference), [`permeation`] (gas permeation through the rubber), [`validity`]
//!   (the model's limits), on [`math`] (quadrature, solvers);
//! * [`simulate`] (the life loop) and [`workflow`] (what each command does: leak, life,
//!   compare, figures, trade-off);
//! * output boundary: [`report`] (CSV, JSON, charts, atomic files) and, with the default `cli`
//!   feature, the command line (`cli`), which only parses, calls, renders and writes.
//!
//! The physics modules know nothing of files, units, TOML or the command line.
//!
//! # Example: a seal's life from a scenario
//!
//! ```
//! use sealsim::scenario::Scenario;
//! use sealsim::workflow;
//! use std::path::Path;
//!
//! let text = r#"
//!     name = "NBR O-ring, water at 80 °C"
//!     [material]
//!     library = "nbr-70"
//!     [surface]
//!     rms_roughness = "0.8 um"
//!     hurst_exponent = 0.8
//!     q0 = "3e5 1/m"
//!     q1 = "1e8 1/m"
//!     [fluid]
//!     viscosity = "0.35 mPa*s"
//!     pressure_difference = "0.5 bar"
//!     [seal]
//!     kind = "o-ring"
//!     cross_section = "3.53 mm"
//!     mean_diameter = "50 mm"
//!     squeeze = 0.25
//!     [environment]
//!     temperature = "80 C"
//!     [failure]
//!     max_leaked_volume = "0.5 L"
//!     [simulation]
//!     duration = "10 year"
//! "#;
//! // units are parsed and every value is checked once, here; errors name the line and key
//! let scenario = Scenario::from_str(text, Path::new("example.toml"))?;
//! let result = workflow::life::run(&scenario, &mut |_, _| {});
//!
//! let first = &result.rows[0];
//! let last = result.rows.last().expect("a history has rows");
//! assert_eq!(first.time, 0.0);
//! assert!((last.time - 10.0 * 365.25 * 86400.0).abs() < 1.0); // s
//! // the rubber relaxes: the sealing force falls, and the leak rate rises
//! assert!(last.sealing_force < first.sealing_force); // N/m
//! assert!(result.final_leak_rate() > result.initial_leak_rate()); // m³/s
//! // each validity limit crossed is reported once, with its worst value and when
//! for finding in result.findings.iter() {
//!     println!("warning: {finding}");
//! }
//! # Ok::<(), sealsim::scenario::ScenarioError>(())
//! ```
//!
//! # Example: the paper's §3 case, one static state
//!
//! ```
//! use sealsim::contact::{ContactSettings, Elastic};
//! use sealsim::fluid::{Fluid, ViscosityLaw};
//! use sealsim::leak::{Fidelity, FlatSeal, StaticProblem, StaticSolver};
//! use sealsim::surface::Spectrum;
//!
//! let problem = StaticProblem {
//!     material: Elastic { youngs_modulus: 10e6, poisson_ratio: 0.5 },
//!     // h_rms = 2 µm, H = 0.8, q0 = 1e4 1/m, q1 = 7.8e9 1/m
//!     spectrum: Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None)?,
//!     fluid: Fluid { viscosity: 1e-3, pressure_difference: 0.01e6, law: ViscosityLaw::Constant, gas: None },
//!     seal: FlatSeal { nominal_pressure: 0.2e6, width: 1e-3, length: 1e-3 },
//!     contact: ContactSettings::default(),
//!     shape_factor: 1.0,
//! };
//! let solver = StaticSolver::new(problem, Fidelity::Exact);
//! let point = solver.evaluate(0.2e6);
//! let junction = point.junction.leaking().expect("a channel percolates at 0.2 MPa");
//! assert!((junction.zeta_c - 16.19).abs() < 0.01);
//! assert!((junction.u_c - 0.1236e-6).abs() < 0.0001e-6);
//! // with the fluid pressure inside the interface (docs/model.md §3.6): 2.0e-15 m³/s, 27 % above
//! // the 1.57e-15 of σ(P0) alone — ΔP/P0 = 0.05, but σ falls steeply with the asperity pressure
//! assert!(point.leak_rate > 1.95e-15 && point.leak_rate < 2.05e-15); // m³/s
//! # Ok::<(), sealsim::surface::SpectrumError>(())
//! ```

#[cfg(feature = "cli")]
pub mod cli;
pub mod report;
pub mod scenario;
pub mod workflow;
// The physics (crates/sealsim-core) and the numerics (crates/sealsim-math), under the paths
// they had before the split.
pub use sealsim_core::{
    clogging, codes, contact, dynamic, extrusion, fits, fluid, gas, gland, gland_design, interface,
    leak, material, math, numerical, permeation, plausibility, pressure, profile, roughness, seal,
    simulate, study, surface, units, validity,
};
