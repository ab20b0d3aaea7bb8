//! The validated scenario: the type that `validate` builds from the raw tables and every
//! command reads. Its entry points (`Scenario::load`, …) are in the module root.

use super::compatibility;
use crate::gland::GlandDesign;
use crate::leak::StaticProblem;
use crate::material::Material;
use crate::numerical::HeightMap;
use crate::numerical::reference::NumericalSettings;
use crate::simulate::LifeProblem;
use std::path::PathBuf;

/// A validated scenario: everything in SI units, ready for the solvers.
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    /// The `name` key, or the file stem when it is absent.
    pub name: String,
    /// The file the scenario was read from (as given).
    pub path: PathBuf,
    /// The rubber (`[material]`: inline, or a library compound).
    pub material: Material,
    /// The static leak problem of the seal; its elastic constants are the material's relaxed
    /// modulus E∞ and ν. For an O-ring its flat seal is the central strip right after
    /// installation (Hertz peak pressure of Lindley's force with E0, Lindley's contact width,
    /// sealing length π D).
    pub problem: StaticProblem,
    /// The seal-life problem (`sealsim run`): O-ring or flat seal, loading, environment,
    /// ageing, failure criteria and time grid; 16 strips across an O-ring's profile.
    pub life: LifeProblem,
    /// The measured surface of `surface.height_map` (heights and pixel in m) for the numerical
    /// level: the map itself, or for a map that is not square with an even side its largest
    /// centred even square crop ([`crate::numerical::Topography::square_crop`]); `None` for a
    /// spectrum given by parameters or `psd_file`. When present, `problem.spectrum` and
    /// `life.spectrum` are the PSD estimate of the whole map
    /// ([`crate::numerical::psd::estimate_topography`], restricted to `q0`, `q1` if given).
    pub height_map: Option<HeightMap>,
    /// `[numerical]`: grid, band, realisations and seed of the numerical level (defaults:
    /// [`NumericalSettings::default`]).
    pub numerical: NumericalSettings,
    /// A groove-seated O-ring's ring and groove (`[seal] gland = …`, docs/model.md §6.2): its
    /// installed state, squeeze range over the tolerances and gland fill
    /// ([`GlandDesign::installed`], [`GlandDesign::squeeze_range`],
    /// [`GlandDesign::max_material_fill`]); `life.geometry` is its nominal installed state.
    pub gland: Option<GlandDesign>,
    /// Warnings about the input, each located like an error (`FILE:LINE: KEY: …`), e.g. a gland
    /// fill above the guidance; the commands print them as `warning:` lines.
    pub warnings: Vec<super::InputWarning>,
    /// The library compound's rating in the library fluid's class (docs/model.md §6.8); `None`
    /// when the fluid is not a rated class or no source rated the pair.
    pub compatibility: Option<compatibility::Compatibility>,
    /// The library fluid's class on the rating scale at the run's highest temperature
    /// ([`compatibility::FluidClass::of`]); `None` for a fluid the ratings do not cover (a
    /// gas, an inline fluid). `sealsim compare` ranks by it.
    pub fluid_class: Option<compatibility::FluidClass>,
    /// The files the scenario reads besides itself (a material file, a temperature history,
    /// PSD files, height maps, traces, a contact profile, a size distribution), as resolved
    /// from the scenario's directory: no output may be written over them.
    pub inputs: Vec<PathBuf>,
}
