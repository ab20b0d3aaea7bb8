//! The physics of sealsim (docs/model.md): rough surfaces and contact, fluids and flow, rubber,
//! seals and glands, clogging, the leak model at every fidelity and its numerical reference,
//! moving seals, validity findings, the life loop and the statistics of studies.
//!
//! Everything here is SI and knows no file, unit string, TOML, CSV or command line: those are
//! the input layer's (`sealsim::scenario`) and the outer layers'. The crate depends on
//! `sealsim-math` and numerical crates only (ARCHITECTURE.md); the layering of its modules is
//! checked by `tests/model/architecture.rs` in the root package.

pub use sealsim_math as math;

pub mod clogging;
pub mod codes;
pub mod contact;
pub mod dynamic;
pub mod extrusion;
pub mod fits;
pub mod fluid;
pub mod gas;
pub mod gland;
pub mod gland_design;
pub mod interface;
pub mod leak;
pub mod material;
pub mod numerical;
pub mod permeation;
pub mod plausibility;
pub mod pressure;
pub mod profile;
pub mod roughness;
pub mod seal;
pub mod simulate;
pub mod study;
pub mod surface;
pub mod units;
pub mod validity;
