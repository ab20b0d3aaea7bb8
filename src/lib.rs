//! sealsim — leak rate and life of rubber seals from rough-surface contact mechanics.
//!
//! The physics follows B.N.J. Persson and C. Yang, *Theory of the leak-rate of seals*,
//! J. Phys.: Condens. Matter 20 (2008) 315011 (cited below as "PY08 §n").
//!
//! Architecture: dependencies point inwards.
//! * input boundary: [`units`] (unit strings → SI), [`scenario`] (TOML → validated model types);
//! * physics: [`math`], [`surface`] (roughness spectra), [`contact`] (Persson contact
//!   mechanics, critical junction, contact table), [`leak`] (leak rate of a flat seal);
//! * output boundary: [`report`] (CSV, plots, atomic files), [`cli`].
//!
//! The physics modules know nothing of files, units, TOML or the command line.
//!
//! # Example: the paper's §3 case
//!
//! ```
//! use sealsim::contact::{ContactSettings, Elastic};
//! use sealsim::fluid::Fluid;
//! use sealsim::leak::{Fidelity, FlatSeal, StaticProblem, StaticSolver};
//! use sealsim::surface::Spectrum;
//!
//! let problem = StaticProblem {
//!     material: Elastic { youngs_modulus: 10e6, poisson_ratio: 0.5 },
//!     // h_rms = 2 µm, H = 0.8, q0 = 1e4 1/m, q1 = 7.8e9 1/m
//!     spectrum: Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None)?,
//!     fluid: Fluid { viscosity: 1e-3, pressure_difference: 0.01e6 },
//!     seal: FlatSeal { nominal_pressure: 0.2e6, width: 1e-3, length: 1e-3 },
//!     contact: ContactSettings::default(),
//!     shape_factor: 1.0,
//! };
//! let solver = StaticSolver::new(problem, Fidelity::Exact);
//! let point = solver.evaluate(0.2e6);
//! let junction = point.junction.leaking().expect("a channel percolates at 0.2 MPa");
//! assert!((junction.zeta_c - 16.19).abs() < 0.01);
//! assert!((junction.u_c - 0.1236e-6).abs() < 0.0001e-6);
//! assert!(point.leak_rate > 1.5e-15 && point.leak_rate < 1.6e-15); // m³/s
//! # Ok::<(), sealsim::surface::SpectrumError>(())
//! ```

#[cfg(feature = "cli")]
pub mod cli;
pub mod clogging;
pub mod contact;
pub mod dynamic;
pub mod fluid;
pub mod leak;
pub mod material;
pub mod math;
pub mod numerical;
pub mod report;
pub mod scenario;
pub mod seal;
pub mod simulate;
pub mod surface;
pub mod units;
pub mod validity;
pub mod workflow;
