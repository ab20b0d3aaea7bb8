//! What every seal kind of the input gives (docs/model.md §6): [`SealSpec`], the `[seal]` table
//! validated before the thermal strain, the housing's expansion (`housing`,
//! `housing_expansion`), and the ring keys a groove-seated ring shares with a ring between
//! plates. The kinds themselves are read in `seal_kind` (and a groove-seated ring in `gland`).

use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::raw::RawSeal;
use crate::gland::{Gland, GlandDesign, Housing};
use crate::material::TemperatureHistory;
use crate::seal::SealGeometry;
use crate::simulate::Loading;
use crate::units::Dimension;

pub(super) const CROSS_SECTION: Field = field(
    "seal.cross_section",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 10.0),
);
pub(super) const SQUEEZE: Field = field(
    "seal.squeeze",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);
pub(super) const HOUSING_EXPANSION: Field = field(
    "seal.housing_expansion",
    Dimension::THERMAL_EXPANSION,
    "1/K",
    Bound::Range(0.0, 1e-2),
);
/// Default installation temperature of a groove-seated ring: 23 °C \[K\].
pub const DEFAULT_INSTALLATION_TEMPERATURE: f64 = 296.15;

/// `[seal]` validated, before the thermal strain (which needs the material and the
/// environment).
pub(super) struct SealSpec {
    pub geometry: SealGeometry,
    /// The groove of a groove-seated O-ring.
    pub gland: Option<Gland>,
    /// k_e (docs/model.md §6.3).
    pub energisation_factor: f64,
    pub loading: Loading,
    /// The housing's CTE and where it was set (`housing`, `housing_expansion`, or a gland's
    /// default).
    pub housing_expansion: Option<HousingExpansion>,
    /// `installation_temperature` \[K\], or a gland's default (23 °C): the thermal strain's
    /// reference.
    pub installation_temperature: Option<f64>,
    /// `installation_temperature` as given \[K\] (`None` when absent): the fitting
    /// temperature the installation ramp runs at (docs/model.md §5.2).
    pub fitting_temperature: Option<f64>,
    /// A groove-seated ring's ring and groove (docs/model.md §6.2).
    pub design: Option<GlandDesign>,
    /// Located warnings about the input (e.g. a gland fill above the guidance).
    pub warnings: Vec<super::InputWarning>,
    /// A flat gasket's compressed thickness \[m\] (`seal.thickness`; permeation, §13.3).
    pub thickness: Option<f64>,
}

impl SealSpec {
    /// The thermal strain's reference temperature \[K\]: `installation_temperature` (a gland's
    /// default 23 °C); otherwise T(0) for an O-ring between plates, and for a flat gasket the
    /// hotter of 23 °C (bolted at room temperature) and T(0) (re-tightened hot) — the
    /// conservative end: the compression falls from it at every colder temperature, and P0
    /// stays the stress the run starts from in a hot service (docs/model.md §6).
    pub fn thermal_reference(&self, environment: &TemperatureHistory) -> f64 {
        match self.installation_temperature {
            Some(t) => t,
            None if self.geometry.bolted() => {
                environment.at(0.0).max(DEFAULT_INSTALLATION_TEMPERATURE)
            }
            None => environment.at(0.0),
        }
    }
}

/// The housing's linear CTE α_h and the key that set it.
pub(super) struct HousingExpansion {
    /// α_h \[1/K\].
    pub value: f64,
    /// The span of the key's value (of `gland` for the default).
    pub span: std::ops::Range<usize>,
    /// `seal.housing`, `seal.housing_expansion` or `seal.gland`.
    pub key: &'static str,
    /// Set by default (a groove-seated ring without `housing` or `housing_expansion`).
    pub by_default: bool,
}

impl Source<'_> {
    /// `housing = "steel"` (a CTE of [`Housing`]) or `housing_expansion` (a CTE), mutually
    /// exclusive; `None` when neither is given.
    pub(super) fn housing_expansion(
        &self,
        raw: &RawSeal,
    ) -> Result<Option<HousingExpansion>, ScenarioError> {
        match (&raw.housing, &raw.housing_expansion) {
            (Some(_), Some(q)) => Err(self.error(
                q.span(),
                HOUSING_EXPANSION.key,
                "housing and housing_expansion both give the housing's expansion: name the \
                 material (housing) or give its CTE (housing_expansion), not both",
            )),
            (Some(name), None) => match Housing::from_name(name.get_ref()) {
                Some(h) => Ok(Some(HousingExpansion {
                    value: h.expansion(),
                    span: name.span(),
                    key: "seal.housing",
                    by_default: false,
                })),
                None => Err(self.error(
                    name.span(),
                    "seal.housing",
                    format!(
                        "must be one of {} (or give housing_expansion, a CTE such as \
                         \"12e-6 1/K\"), got {:?}",
                        Housing::ALL
                            .iter()
                            .map(|h| format!("{:?}", h.name()))
                            .collect::<Vec<_>>()
                            .join(", "),
                        name.get_ref()
                    ),
                )),
            },
            (None, Some(q)) => Ok(Some(HousingExpansion {
                value: self.quantity(q, &HOUSING_EXPANSION)?,
                span: q.span(),
                key: HOUSING_EXPANSION.key,
                by_default: false,
            })),
            (None, None) => Ok(None),
        }
    }
}
