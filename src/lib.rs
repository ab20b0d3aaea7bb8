//! sealsim — leak rate and life of rubber seals from rough-surface contact mechanics.
//!
//! The physics follows B.N.J. Persson and C. Yang, *Theory of the leak-rate of seals*,
//! J. Phys.: Condens. Matter 20 (2008) 315011 (cited below as "PY08 §n").
//!
//! Architecture: dependencies point inwards.
//! * input boundary: [`units`] (unit strings → SI), [`scenario`] (TOML → validated model types);
//! * physics: [`numerics`], [`surface`] (roughness spectra), [`contact`] (Persson contact
//!   mechanics, critical junction, contact table), [`leak`] (leak rate of a flat seal);
//! * output boundary: [`report`] (CSV, plots, atomic files), [`cli`].
//!
//! The physics modules know nothing of files, units, TOML or the command line.

pub mod cli;
pub mod contact;
pub mod leak;
pub mod numerics;
pub mod report;
pub mod scenario;
pub mod surface;
pub mod units;
