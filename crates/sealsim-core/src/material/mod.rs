//! Viscoelastic rubber: Prony series in reduced time, time–temperature shift, fitting, and
//! the material library's model types (docs/model.md §5).

pub mod ageing_fit;
pub mod compatibility;
pub mod compound;
pub mod csr;
pub mod curve;
pub mod datasheet;
pub mod fit;
pub mod prony;
pub mod shift;
pub mod tts;

pub use compound::{
    Ageing, AgeingBasis, AgeingMedium, BALANCED_CROSSLINKING, FigureBand, Material, Status,
};
pub use prony::{ChemicalStep, Creep, Prony, PronyError, PronyTerm, RelaxationState};
pub use shift::{Shift, TemperatureHistory};
