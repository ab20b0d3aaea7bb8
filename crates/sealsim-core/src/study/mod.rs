//! Studies over many life runs (issue 19; docs/model.md §14): the sampling designs of the varied
//! inputs ([`design`]), what a study keeps of each case ([`case`]), the statistics of a set of
//! times to failure with censoring ([`survival`]), which input drives the life
//! ([`sensitivity`]), and a study's summary of its cases ([`summary`]). Running the cases is
//! the study workflow's (`workflow::study`); reading study files the input boundary's
//! (`scenario::study`): both use this module, not the other way round.

pub mod case;
pub mod design;
pub mod sensitivity;
pub mod summary;
pub mod survival;

pub use case::{CaseOutcome, Cell};
