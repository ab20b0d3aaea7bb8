//! Studies over many life runs (issue 19; docs/model.md §14): the statistics of a set of times to
//! failure with censoring. The study files, designs and runners build on this.

pub mod sensitivity;
pub mod survival;
