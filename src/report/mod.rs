//! placeholder
pub mod plot;
