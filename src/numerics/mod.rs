//! Numerical building blocks, each documented with its method and reference.

pub mod interp;
pub mod quadrature;
pub mod special;
