//! Raw scenario → SI model types, checking every value once, each error located.
//!
//! Every numeric key is described by a [`Field`] (key path, dimension, SI unit, allowed
//! range); [`Source::quantity`] is the one place where a written quantity becomes a checked SI
//! number.

use super::Scenario;
use super::error::{ScenarioError, Source};
use super::field::{Bound, Field, field};
use super::psd;
use super::raw::{Quantity, RawFluid, RawModel, RawNumerical, RawScenario, RawSurface};
use crate::contact::{AreaModel, ContactSettings};
use crate::fluid::{Fluid, GasService, LibraryFluid, MINERAL_OIL_EXPANSION, ViscosityLaw, Walther};
use crate::leak::{FlatSeal, StaticProblem};
use crate::material::Material;
use crate::numerical::reference::NumericalSettings;
use crate::numerical::{HeightMap, psd as map_psd};
use crate::roughness::{self, Band, Callout, ShortWavelengths};
use crate::seal::VolumeSwell;
use crate::simulate::LifeProblem;
use crate::simulate::{AsperityModulus, GrooveInterface};
use crate::surface::Spectrum;
use crate::units::{self, Dimension, show, show_temperature};
use std::ops::Range;
use toml::Spanned;

/// Gauss–Legendre points across an O-ring's Hertz profile (strips in series) in a life run.
pub const STRIPS: usize = 16;

pub(super) const RMS_ROUGHNESS: Field = field(
    "surface.rms_roughness",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-10, 1e-3),
);
pub(super) const HURST_EXPONENT: Field = field(
    "surface.hurst_exponent",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);
pub(super) const Q0: Field = field(
    "surface.q0",
    Dimension::WAVEVECTOR,
    "1/m",
    Bound::Range(1.0, 1e12),
);
pub(super) const Q1: Field = field(
    "surface.q1",
    Dimension::WAVEVECTOR,
    "1/m",
    Bound::Range(1.0, 1e12),
);
pub(super) const ROLLOFF: Field = field(
    "surface.rolloff",
    Dimension::WAVEVECTOR,
    "1/m",
    Bound::Range(1.0, 1e12),
);
pub(super) const PIXEL_SIZE: Field = field(
    "surface.pixel_size",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-10, 1e-2),
);
pub(super) const RA: Field = field(
    "surface.ra",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 1e-4),
);
pub(super) const RQ: Field = field(
    "surface.rq",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-9, 1.25e-4),
);
pub(super) const RZ: Field = field(
    "surface.rz",
    Dimension::LENGTH,
    "m",
    Bound::Range(5e-9, 1e-3),
);
/// λc: ISO 21920-3's sampling lengths run 0.08–8 mm; 10 µm – 100 mm is accepted.
pub(super) const CUTOFF: Field = field(
    "surface.cutoff",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-5, 0.1),
);
/// λs: ISO 3274's 0.8–25 µm; 10 nm (an AFM's reach) – 1 mm is accepted.
pub(super) const SHORT_CUTOFF: Field = field(
    "surface.short_cutoff",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-8, 1e-3),
);
/// Key of the rule below λs, in messages.
const SHORT_WAVELENGTH: &str = "surface.short_wavelength";
/// Key of the height map file, in messages.
const HEIGHT_MAP: &str = "surface.height_map";
/// Key of the height map's unit, in messages.
const HEIGHT_UNIT: &str = "surface.height_unit";
pub(super) const VISCOSITY: Field = field(
    "fluid.viscosity",
    Dimension::VISCOSITY,
    "Pa·s",
    Bound::Range(1e-7, 1e6),
);
pub(super) const VISCOSITY_40C: Field = field(
    "fluid.viscosity_40c",
    Dimension::KINEMATIC_VISCOSITY,
    "m²/s",
    Bound::Range(1e-7, 1e-1),
);
pub(super) const VISCOSITY_100C: Field = field(
    "fluid.viscosity_100c",
    Dimension::KINEMATIC_VISCOSITY,
    "m²/s",
    Bound::Range(1e-7, 1e-1),
);
pub(super) const DENSITY: Field = field(
    "fluid.density",
    Dimension::DENSITY,
    "kg/m³",
    Bound::Range(100.0, 3e4),
);
pub(super) const FLUID_EXPANSION: Field = field(
    "fluid.thermal_expansion",
    Dimension::THERMAL_EXPANSION,
    "1/K",
    Bound::Range(0.0, 1e-2),
);
pub(super) const VOLUME_SWELL: Field = field(
    "fluid.volume_swell",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(-0.5, 2.0),
);
/// ΔV/V0 above which a swell is out of seal practice (a warning): ≈ +30 %.
const SWELL_PRACTICE: f64 = 0.30;
pub(super) const PRESSURE_DIFFERENCE: Field = field(
    "fluid.pressure_difference",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(0.0, 1e10),
);
pub(super) const INLET_PRESSURE: Field = field(
    "fluid.inlet_pressure",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(0.0, 1e10),
);
pub(super) const OUTLET_PRESSURE: Field = field(
    "fluid.outlet_pressure",
    Dimension::PRESSURE,
    "Pa",
    Bound::Range(0.0, 1e10),
);
pub(super) const MOLAR_MASS: Field = field(
    "fluid.molar_mass",
    Dimension::new(0, 1, 0, 0, -1),
    "kg/mol",
    Bound::Range(1e-3, 1.0),
);
pub(super) const MOLECULAR_DIAMETER: Field = field(
    "fluid.molecular_diameter",
    Dimension::LENGTH,
    "m",
    Bound::Range(1e-11, 1e-8),
);
pub(super) const GAS_VISCOSITY: Field = field(
    "fluid.viscosity",
    Dimension::VISCOSITY,
    "Pa·s",
    Bound::Range(1e-7, 1e-3),
);
pub(super) const SUTHERLAND_VISCOSITY: Field = field(
    "fluid.sutherland_viscosity",
    Dimension::VISCOSITY,
    "Pa·s",
    Bound::Range(1e-7, 1e-3),
);
pub(super) const SUTHERLAND_CONSTANT: Field = field(
    "fluid.sutherland_constant",
    Dimension::TEMPERATURE,
    "K",
    Bound::Range(0.0, 5000.0),
);
/// Outlet pressure of a gas given only `pressure_difference`: 1 atm \[Pa\].
const ATMOSPHERE: f64 = 101_325.0;
pub(super) const PERCOLATION_THRESHOLD: Field = field(
    "model.percolation_threshold",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Open(0.0, 1.0),
);
pub(super) const SHAPE_FACTOR: Field = field(
    "model.shape_factor",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Range(1e-2, 1e2),
);
pub(super) const GAMMA: Field = field(
    "model.gamma",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(0.0, 1.0),
);

pub(super) const NUMERICAL_BAND: Field = field(
    "numerical.band",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(4.0, 512.0),
);
pub(super) const NUMERICAL_PIXELS: Field = field(
    "numerical.pixels_per_wavelength",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(2.0, 64.0),
);
pub(super) const NUMERICAL_REALISATIONS: Field = field(
    "numerical.realisations",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(1.0, 1000.0),
);
pub(super) const NUMERICAL_SEED: Field = field(
    "numerical.seed",
    Dimension::DIMENSIONLESS,
    "",
    Bound::Closed(0.0, 9_007_199_254_740_992.0),
);

/// The compound swollen by `swell` (docs/model.md §3.9): every Prony modulus, and a fixed
/// asperity modulus, × [`VolumeSwell::modulus_factor`].
fn swollen_material(
    mut material: Material,
    asperity: AsperityModulus,
    swell: &VolumeSwell,
) -> (Material, AsperityModulus) {
    let factor = swell.modulus_factor();
    if factor == 1.0 {
        return (material, asperity);
    }
    material.prony = material.prony.scaled(factor);
    material.provenance.push((
        "prony".to_owned(),
        format!(
            "× {} for the fluid's {} % volume swell (G ∝ v2^(1/3), Treloar)",
            show(factor),
            show(100.0 * swell.volume_change)
        ),
    ));
    let asperity = match asperity {
        AsperityModulus::Fixed(e) => AsperityModulus::Fixed(e * factor),
        other => other,
    };
    (material, asperity)
}

/// 20 °C \[K\]: where a law's viscosity is first evaluated (the installation temperature
/// replaces it once the environment is known).
const ROOM_TEMPERATURE: f64 = 293.15;

/// Default of `model.shape_factor` (α ≈ 1, PY08 eq. 2).
const DEFAULT_SHAPE_FACTOR: f64 = 1.0;

impl Source<'_> {
    /// Checks the whole file; with `replacement`, that compound stands in for the one the
    /// `[material]` table gives (`sealsim compare`).
    pub fn scenario(
        &self,
        raw: &RawScenario,
        replacement: Option<&Material>,
    ) -> Result<Scenario, ScenarioError> {
        let name = raw
            .name
            .as_ref()
            .map_or_else(|| self.file_stem(), |n| n.get_ref().clone());
        // An inline material without a name is called after the scenario.
        let (material, elastic, asperity_modulus) =
            self.scenario_material(&raw.material, &name, replacement)?;
        let swell = self.volume_swell(&raw.fluid)?;
        let (material, asperity_modulus) = match &swell {
            Some((s, _)) => swollen_material(material, asperity_modulus, s),
            None => (material, asperity_modulus),
        };
        let (spectrum, height_map, mut notes) = self.surface(&raw.surface)?;
        let fluid = self.fluid(&raw.fluid)?;
        let seal = self.seal(&raw.seal, swell.as_ref().map(|s| &s.0))?;
        let installation_time = self.installation_time(&raw.seal)?;
        let (spectrum, groove) = self.interface_surfaces(
            raw,
            spectrum,
            seal.gland.is_some(),
            height_map.is_some(),
            &mut notes,
        )?;
        let (contact, shape_factor) = match &raw.model {
            Some(model) => self.model(model.get_ref())?,
            None => (ContactSettings::default(), DEFAULT_SHAPE_FACTOR),
        };
        let environment = self.environment(raw.environment.as_ref(), &material)?;
        let cold_fitting = self.fitting_temperature(raw, &seal, &material, &environment)?;
        let environment = settling_environment(environment, &seal);
        // the static problem's viscosity is the law's at the installation (fitting) temperature,
        // the first row's of a run
        let fluid = fluid.at(environment.at(0.0));
        let cte_fix = self.material_key_fix(
            raw.material.get_ref(),
            replacement.is_some(),
            "thermal_expansion",
        );
        let thermal_strain = self.thermal_strain(&seal, &material, &environment, &cte_fix)?;
        let pressure = self.pressure_history(raw.environment.as_ref(), &fluid)?;
        let service = self.service(
            raw,
            &material,
            replacement.is_some(),
            &fluid,
            (&environment, pressure.as_ref()),
            &seal,
        )?;
        if thermal_strain.is_none() {
            self.flat_without_expansion(
                &raw.seal,
                &seal,
                &material,
                &environment,
                &service.failure,
                &cte_fix,
            )?;
        }
        let (permeation, permeation_note) =
            self.permeation(raw, &material, &fluid, &seal, replacement.is_some())?;
        let life = LifeProblem {
            material: material.clone(),
            asperity_modulus,
            spectrum: spectrum.clone(),
            contact,
            shape_factor,
            fluid,
            geometry: seal.geometry,
            gland: seal.gland,
            groove,
            energisation_factor: seal.energisation_factor,
            loading: seal.loading,
            installation_time,
            environment,
            thermal_strain,
            ageing: service.ageing,
            ageing_source: service.ageing_source,
            failure: service.failure,
            time: service.time,
            fidelity: service.fidelity,
            strips: STRIPS,
            contamination: service.contamination,
            motion: service.motion,
            permeation,
            pressure,
        };
        let mut warnings = seal.warnings;
        warnings.extend(self.service_warnings(raw, seal.design.as_ref(), &life, permeation_note));
        // the surface's readings are notes; a unit slip (§2.4) is a warning to be seen
        warnings.extend(notes.into_iter().map(|n| {
            if n.to_string().ends_with("[docs/model.md §2.4]") {
                n.warning(&crate::codes::HEIGHT_SLIP)
            } else {
                n.warning(&crate::codes::SURFACE_NOTE)
            }
        }));
        if let Some(w) = self.lay(&raw.surface, life.fluid.gas.is_some())? {
            warnings.push(w.warning(&crate::codes::SURFACE_LAY));
        }
        warnings.extend(cold_fitting.map(|w| w.warning(&crate::codes::COLD_FITTING)));
        let run = Run {
            raw,
            material: &material,
            life: &life,
            swell: swell.as_ref(),
            known_fluid: raw
                .fluid
                .get_ref()
                .library
                .as_ref()
                .and_then(|l| crate::fluid::library(l.get_ref()).map(|f| (l, f))),
        };
        let compatibility = self.run_warnings(&run, &mut warnings)?;
        let fluid_class = run.known_fluid.and_then(|(_, fluid)| {
            super::compatibility::FluidClass::of(fluid.id, life.environment.range().1)
        });
        let static_seal = static_seal(&life);
        // the static problem sees the asperity modulus of the installed state, as the first row
        // of a life run does
        let elastic = crate::contact::Elastic {
            youngs_modulus: life.installed_asperity_modulus(),
            ..elastic
        };
        Ok(Scenario {
            name,
            path: self.path.to_path_buf(),
            material,
            problem: StaticProblem {
                material: elastic,
                spectrum,
                fluid,
                seal: static_seal,
                contact,
                shape_factor,
            },
            life,
            height_map,
            numerical: service.numerical,
            gland: seal.design,
            warnings,
            compatibility,
            fluid_class,
            inputs: self.data_files(raw),
        })
    }

    /// The warnings that need the service: the gland's ([motion]: the dynamic squeeze range; a
    /// vacuum outlet), then the permeation figure's note.
    fn service_warnings(
        &self,
        raw: &RawScenario,
        design: Option<&crate::gland::GlandDesign>,
        life: &LifeProblem,
        permeation_note: Option<String>,
    ) -> Vec<super::InputWarning> {
        let mut warnings = self.gland_service_warnings(
            &raw.seal,
            design,
            raw.motion.is_some(),
            life.fluid
                .gas
                .is_some_and(|g| g.outlet_pressure < crate::permeation::STP_PRESSURE),
        );
        if let Some(note) = permeation_note {
            warnings.push(
                self.error(raw.fluid.span(), "fluid.gas", format!("note: {note}"))
                    .warning(&crate::codes::PERMEATION_NOTE),
            );
        }
        warnings
    }

    /// Permeation through the rubber for a gas (docs/model.md §13.7), with its note. The
    /// figure is the compound's own (`[material.permeation]`) or its class's (sourced, or a
    /// stated NOT SOURCED bound, every output says which). Missing data never read as zero: a
    /// compound without class or figure, a gas the table lacks, a flat seal without its
    /// thickness are refused at the key that supplies them.
    fn permeation(
        &self,
        raw: &RawScenario,
        material: &Material,
        fluid: &Fluid,
        seal: &super::seal_spec::SealSpec,
        replaced: bool,
    ) -> Result<(Option<crate::permeation::SealPermeation>, Option<String>), ScenarioError> {
        use crate::permeation::{Missing, SealPermeation, figure};
        let Some(gas) = fluid.gas else {
            return Ok((None, None));
        };
        let id = gas.gas.id;
        let refuse = |missing: Missing| -> ScenarioError {
            let own = format!(
                "[material.permeation] {id} = {{ permeability = \"5 barrer\", diffusivity = \
                 \"3e-10 m^2/s\", source = \"<where the figure comes from>\" }}"
            );
            let material_span = raw.material.span();
            match missing {
                Missing::NoClass => self.error(
                    material_span,
                    "material.class",
                    format!(
                        "no permeation figure for {id} through the rubber: the material ({}) \
                         names no compound class and gives no figure of its own, and a gas run \
                         never takes a missing figure as zero (docs/model.md §13.4). {}: \
                         `class = \"nbr\"` (one of {}; its figure is sourced or a stated NOT \
                         SOURCED bound, `sealsim materials show ID` prints it), or the \
                         compound's own figure `{own}`",
                        material.name,
                        if replaced {
                            "Add to [material] in the compared compound's material file"
                        } else if raw.material.get_ref().file.is_some() {
                            "Add to [material] in the material file itself"
                        } else {
                            "Add to [material]"
                        },
                        crate::permeation::FAMILIES.join(", "),
                    ),
                ),
                Missing::NoRow { family } => self.error(
                    raw.fluid.span(),
                    "fluid.gas",
                    format!(
                        "no permeation figure for {id} in {family}: sealsim's table has {} \
                         (docs/model.md §13.4), and a gas run never takes a missing figure as \
                         zero; give the compound's own figure in the scenario: `{own}`",
                        crate::permeation::GASES.join(", "),
                    ),
                ),
                Missing::NoThickness => self.error(
                    raw.seal.span(),
                    "seal.thickness",
                    format!(
                        "missing key `thickness` in [seal]: {id} permeates through the flat \
                         gasket's exposed edge, whose compressed thickness sets its area \
                         (docs/model.md §13.3), and a gas run never takes the unknown \
                         permeation as zero; give e.g. thickness = \"2.8 mm\""
                    ),
                ),
                Missing::Path(e) => self.error(
                    raw.seal.span(),
                    "seal",
                    format!("the permeation path: {e} [docs/model.md §13.3]"),
                ),
            }
        };
        let data = figure(material.class.as_deref(), &material.permeation, id).map_err(refuse)?;
        let (permeation, note) = SealPermeation::for_seal(
            data,
            &seal.geometry,
            seal.thickness,
            gas.outlet_pressure + fluid.pressure_difference,
            gas.outlet_pressure,
        )
        .map_err(refuse)?;
        Ok((Some(permeation), note))
    }

    /// `[groove_surface]` (the gland's own interface) and `[rubber_surface]` (the rubber's
    /// roughness, summed into the counterface's `spectrum` and the groove's), their notes
    /// added to `notes`.
    fn interface_surfaces(
        &self,
        raw: &RawScenario,
        spectrum: Spectrum,
        in_gland: bool,
        counterface_map: bool,
        notes: &mut Vec<ScenarioError>,
    ) -> Result<(Spectrum, GrooveInterface), ScenarioError> {
        let (groove, groove_notes) = self.groove_surface(raw.groove_surface.as_ref(), in_gland)?;
        notes.extend(groove_notes);
        let Some(table) = &raw.rubber_surface else {
            return Ok((spectrum, groove));
        };
        let (rubber, rubber_notes) = self.rubber_surface(table, counterface_map)?;
        notes.extend(rubber_notes);
        let sum = |s: &Spectrum| {
            s.sum(&rubber)
                .map_err(|e| self.error(table.span(), "rubber_surface", e.to_string()))
        };
        let groove = match groove {
            GrooveInterface::Own(g) => GrooveInterface::Own(sum(&g)?),
            other => other,
        };
        Ok((sum(&spectrum)?, groove))
    }

    /// The run's own tables: `[ageing]`, `[failure]`, `[simulation]` (with its cycle budget
    /// and clogging tolerance), `[contamination]`, `[numerical]` and `[motion]`; the last two
    /// of a liquid's only.
    fn service(
        &self,
        raw: &RawScenario,
        material: &Material,
        replaced: bool,
        fluid: &Fluid,
        (environment, pressure): (
            &crate::material::TemperatureHistory,
            Option<&crate::pressure::PressureHistory>,
        ),
        seal: &super::seal_spec::SealSpec,
    ) -> Result<Service, ScenarioError> {
        let (geometry, loading) = (&seal.geometry, seal.loading);
        let (ageing, ageing_source) =
            self.scenario_ageing(raw.ageing.as_ref(), material, replaced)?;
        let motion = self.motion(raw.motion.as_ref())?;
        let failure = self.failure(
            raw.failure.as_ref(),
            fluid,
            environment,
            &super::life::FailureContext {
                low_temperature_limit: material.low_temperature_limit(),
                moving: motion.is_some(),
                // a ring's cord, a gasket's compressed thickness; unknown: cooled at once,
                // the least relaxation on the way (docs/model.md §8.2)
                cooling_time: geometry.cooling_length().map_or(0.0, thermal_settling_time),
                no_shutdown: (loading == crate::simulate::Loading::Force).then_some(
                    "under loading = \"force\" the bolts or springs keep the seal's load at rest \
                     too; the check is of a seal held at a fixed compression (loading = \
                     \"displacement\")",
                ),
                highest_pressure: pressure
                    .map(crate::pressure::PressureHistory::highest_difference),
            },
        )?;
        let (time, fidelity) = self.simulation(raw.simulation.as_ref())?;
        self.cycle_budget(
            raw.simulation.as_ref(),
            raw.environment.as_ref(),
            (environment, pressure),
            &time,
        )?;
        let clogging_tolerance = self.clogging_tolerance(raw.simulation.as_ref())?;
        let contamination = self.contamination(raw.contamination.as_ref(), clogging_tolerance)?;
        let numerical = self.numerical(raw.numerical.as_ref())?;
        if fluid.gas.is_some() {
            self.liquid_only_tables(raw)?;
        }
        Ok(Service {
            ageing,
            ageing_source,
            failure,
            time,
            fidelity,
            contamination,
            numerical,
            motion,
        })
    }

    /// A gas's interface flow is modelled for a static seal only (docs/model.md §3.9): no
    /// `[motion]`, no `[contamination]`.
    fn liquid_only_tables(&self, raw: &RawScenario) -> Result<(), ScenarioError> {
        let stray = [
            raw.motion.as_ref().map(|m| (m.span(), "motion")),
            raw.contamination
                .as_ref()
                .map(|c| (c.span(), "contamination")),
        ];
        if let Some((span, key)) = stray.into_iter().flatten().next() {
            return Err(self.error(
                span,
                key,
                format!(
                    "[{key}] is modelled for a liquid only, but [fluid] is a gas (the \
                     drag films of a reciprocating seal and particle clogging are liquid \
                     models): remove [{key}] or give a liquid"
                ),
            ));
        }
        Ok(())
    }

    /// The warnings on the whole run, added to `warnings` in order (the fluid's compatibility
    /// with the compound, the ageing's medium, the fluid's liquid range, the class's rated
    /// temperature, the swell, an unshifted relaxation), or the error of a gas that
    /// condenses; the compound's compatibility rating with the fluid.
    fn run_warnings(
        &self,
        run: &Run,
        warnings: &mut Vec<super::InputWarning>,
    ) -> Result<Option<super::compatibility::Compatibility>, ScenarioError> {
        let compatibility = self.fluid_compatibility(run);
        if let Some((c, span)) = &compatibility {
            let not = c.rating == super::compatibility::Rating::NotRecommended;
            let message = format!(
                "{}{} is rated {c} [docs/model.md §6.8]",
                if not { "" } else { "note: " },
                run.material.library_id.as_deref().unwrap_or("the compound"),
            );
            let code = if not {
                &crate::codes::FLUID_NOT_RECOMMENDED
            } else {
                &crate::codes::COMPATIBILITY_NOTE
            };
            warnings.push(
                self.error(span.clone(), "fluid.library", message)
                    .warning(code),
            );
        }
        warnings.extend(self.ageing_medium_warning(run));
        self.liquid_range_check(run)?;
        warnings.extend(self.rated_temperature_warning(run));
        self.gas_condensation(run)?;
        warnings.extend(self.swell_warning(run));
        warnings.extend(self.unshifted_warning(run));
        Ok(compatibility.map(|(c, _)| c))
    }

    /// The compound's fluid compatibility (docs/model.md §6.8), with the span of
    /// `fluid.library`.
    fn fluid_compatibility(
        &self,
        run: &Run,
    ) -> Option<(super::compatibility::Compatibility, Range<usize>)> {
        run.known_fluid.and_then(|(library, fluid)| {
            let (_, hi) = run.life.environment.range();
            super::compatibility::FluidClass::of(fluid.id, hi)
                .and_then(|class| super::compatibility::rating(&run.material.compatibility, class))
                .map(|c| (c.clone(), library.span()))
        })
    }

    /// Ageing constants measured in another medium than the run's fluid (docs/model.md §6.8).
    fn ageing_medium_warning(&self, run: &Run) -> Option<super::InputWarning> {
        use crate::material::AgeingMedium;
        let (Some(basis), true) = (&run.material.ageing_basis, run.life.ageing.is_some()) else {
            return None;
        };
        let run_medium = match (run.known_fluid, &run.life.fluid.gas) {
            (Some((_, fluid)), _) => match fluid.id {
                "water" => Some(AgeingMedium::Water),
                "ethylene-glycol-water-50" => Some(AgeingMedium::WaterGlycol),
                id if id.starts_with("iso-vg-") => Some(AgeingMedium::MineralOil),
                _ => None,
            },
            (None, Some(g)) if g.gas.id == "air" || g.gas.id == "oxygen" => Some(AgeingMedium::Air),
            _ => None,
        };
        let (Some(measured), Some(medium)) = (basis.medium, run_medium) else {
            return None;
        };
        (measured != medium).then(|| {
            self.error(
                run.raw.fluid.span(),
                "fluid",
                format!(
                    "the compound's ageing constants were measured in {}, this run's \
                     fluid is {}: ageing specific to the medium (hydrolysis in water, \
                     oxidation in air, swelling and extraction in oil) is not modelled, \
                     so the ageing rate is the measured medium's [docs/model.md §6.8]",
                    measured.as_str(),
                    medium.as_str()
                ),
            )
            .warning(&crate::codes::AGEING_MEDIUM)
        })
    }

    /// A library liquid taken outside the range where it is a liquid is refused (docs/model.md
    /// §3.7): below its freezing or pour point, or above its boiling point at the run's
    /// absolute pressure — the fluid's ΔP over the 1 atm outlet ([`LibraryFluid::boiling_point`]:
    /// water on the IAPWS-IF97 saturation line, so 7 bar absolute boils at ≈ 165 °C, not
    /// 100 °C). The viscosity law there would be evaluated past a phase change (an oil at 80 K
    /// gave 5.97e251 Pa·s): most often a unit slip ("80 K" for "80 C").
    fn liquid_range_check(&self, run: &Run) -> Result<(), ScenarioError> {
        let Some((library, fluid)) = run.known_fluid else {
            return Ok(());
        };
        let Some((melting, _)) = fluid.liquid_range else {
            return Ok(());
        };
        let absolute = run.life.fluid.pressure_difference.max(0.0) + crate::fluid::ATMOSPHERE;
        let boiling = fluid.boiling_point(absolute);
        let (lo, hi) = run.life.environment.range();
        if lo >= melting && hi <= boiling {
            return Ok(());
        }
        let id = fluid.id;
        let range = if boiling.is_finite() {
            format!(
                "{id} is a liquid from {} to {} (its boiling point at {} bar absolute, the \
                 fluid's ΔP over 1 atm)",
                show_temperature(melting, 5),
                show_temperature(boiling, 5),
                show((absolute / 1e5 * 1e3).round() / 1e3),
            )
        } else {
            format!(
                "{id} flows only above its pour point {} (illustrative, a VG 46 mineral oil's; \
                 a product's data sheet governs)",
                show_temperature(melting, 5)
            )
        };
        let (what, fix) = if lo < melting {
            (
                format!("falls to {}", show_temperature(lo, 6)),
                "is the unit right (\"80 C\", not \"80 K\")? give a temperature in the range, or \
                 the fluid inline with its own data (viscosity_40c, viscosity_100c, density)",
            )
        } else {
            (
                format!("reaches {}", show_temperature(hi, 6)),
                "is the unit or the pressure right? give a temperature in the range, or the \
                 pressure that keeps the liquid from boiling",
            )
        };
        let key = match run.raw.environment.as_ref() {
            Some(e) if e.get_ref().temperature.is_some() => "environment.temperature",
            Some(_) => "environment",
            None => "fluid.library",
        };
        let span = match key {
            "fluid.library" => library.span(),
            _ => temperature_span(run.raw),
        };
        Err(self.error(
            span,
            key,
            format!(
                "the temperature {what}, but {range}: outside it the fluid is not a liquid and \
                 its viscosity law is meaningless; {fix} [docs/model.md §3.7]"
            ),
        ))
    }

    /// A library compound above its class's rated temperature (docs/model.md §6.7): its life
    /// there is the Arrhenius extrapolation beyond "1,000 hours continuous service".
    fn rated_temperature_warning(&self, run: &Run) -> Option<super::InputWarning> {
        let published = run
            .material
            .library_id
            .as_deref()
            .and_then(super::library_check::published)?;
        let (_, hi) = run.life.environment.range();
        (hi > published.rated).then(|| {
            self.error(
                temperature_span(run.raw),
                "environment.temperature",
                format!(
                    "the temperature reaches {}, {} K above the rated {} of the compound's \
                     class ({}): a seal there is expected to lose 30-50 % of its \
                     properties within 1,000 h, and beyond the rating the compound may \
                     decompose; the ageing constants are extrapolated \
                     [docs/model.md §6.7]",
                    show_temperature(hi, 4),
                    show(((hi - published.rated) * 10.0).round() / 10.0),
                    show_temperature(published.rated, 4),
                    published.source
                ),
            )
            .warning(&crate::codes::RATED_TEMPERATURE)
        })
    }

    /// A gas taken down to where it condenses at 1 atm is refused (docs/model.md §3.9).
    fn gas_condensation(&self, run: &Run) -> Result<(), ScenarioError> {
        if let Some(service) = &run.life.fluid.gas
            && let Some(condenses) = crate::gas::condensation_point(service.gas.id)
        {
            let (lo, _) = run.life.environment.range();
            if lo <= condenses {
                return Err(self.error(
                    temperature_span(run.raw),
                    "environment.temperature",
                    format!(
                        "the temperature reaches {}, but {} is a gas at 1 atm only above {} \
                         (below it condenses, and the gas laws do not apply): give a \
                         temperature above it, e.g. \"{} K\" [docs/model.md §3.9]",
                        show_temperature(lo, 6),
                        service.gas.id,
                        show_temperature(condenses, 6),
                        show((condenses + 10.0).ceil())
                    ),
                ));
            }
        }
        Ok(())
    }

    /// A volume swell beyond seal practice (docs/model.md §3.9).
    fn swell_warning(&self, run: &Run) -> Option<super::InputWarning> {
        let (swell, span) = run.swell?;
        (swell.volume_change > SWELL_PRACTICE).then(|| {
            self.error(
                span.clone(),
                VOLUME_SWELL.key,
                format!(
                    "{} % volume swell is beyond seal practice (≈ {} %: the compound is \
                         not compatible with this fluid); the swell relations are applied \
                         as given [docs/model.md §3.9]",
                    show(100.0 * swell.volume_change),
                    show(100.0 * SWELL_PRACTICE)
                ),
            )
            .warning(&crate::codes::SWELL)
        })
    }

    /// A relaxation series without a temperature shift or a data temperature: the series was
    /// measured at some temperature; without a shift or that temperature the run cannot tell
    /// how far from it it goes, so say so once (docs/model.md §9.13).
    fn unshifted_warning(&self, run: &Run) -> Option<super::InputWarning> {
        let material = run.material;
        let unshifted = material.shift == crate::material::Shift::None
            && material.data_temperature.is_none()
            && !material.prony.terms().is_empty();
        unshifted.then(|| {
            let (lo, hi) = run.life.environment.range();
            self.error(
                run.raw.material.span(),
                "material",
                format!(
                    "{} has no temperature shift and no data temperature: its relaxation is \
                     taken as measured, at every temperature of this run ({}–{} K); give \
                     `data_temperature` (fit-prony --temperature) so that a run away from it \
                     is warned about, or a [material.shift] (a master curve from data at \
                     several temperatures, or a library compound's shift copied by \
                     fit-prony --like) [docs/model.md §9.13]",
                    material.name,
                    show(lo),
                    show(hi)
                ),
            )
            .warning(&crate::codes::UNSHIFTED)
        })
    }

    /// The data files `raw` names, resolved from the scenario's directory.
    fn data_files(&self, raw: &RawScenario) -> Vec<std::path::PathBuf> {
        let surfaces = [
            Some(&raw.surface),
            raw.groove_surface.as_ref(),
            raw.rubber_surface.as_ref(),
        ];
        let mut names: Vec<&str> = [
            raw.material.get_ref().file.as_ref(),
            raw.environment
                .as_ref()
                .and_then(|e| e.get_ref().history.as_ref()),
            raw.motion
                .as_ref()
                .and_then(|m| m.get_ref().contact_profile.as_ref()),
            raw.contamination
                .as_ref()
                .and_then(|c| c.get_ref().size_distribution.as_ref())
                .and_then(|d| d.get_ref().file.as_ref()),
        ]
        .into_iter()
        .flatten()
        .map(|n| n.get_ref().as_str())
        .collect();
        for s in surfaces.into_iter().flatten().map(Spanned::get_ref) {
            names.extend(
                [s.psd_file.as_ref(), s.height_map.as_ref()]
                    .into_iter()
                    .flatten()
                    .map(|n| n.get_ref().as_str()),
            );
            if let Some(files) = &s.profile {
                names.extend(files.get_ref().names());
            }
        }
        names.into_iter().map(|n| self.relative_path(n)).collect()
    }

    /// `[numerical]`: band (4–512), pixels per shortest wavelength (integer 2–64),
    /// realisations (integer 1–1000), seed (integer 0–2⁵³); each optional.
    fn numerical(
        &self,
        table: Option<&Spanned<RawNumerical>>,
    ) -> Result<NumericalSettings, ScenarioError> {
        let mut settings = NumericalSettings::default();
        let Some(table) = table else {
            return Ok(settings);
        };
        let raw = table.get_ref();
        if let Some(band) = self.optional(raw.band.as_ref(), &NUMERICAL_BAND)? {
            settings.band = band;
        }
        let integer = |q: Option<&Quantity>, f: &Field| -> Result<Option<u64>, ScenarioError> {
            let Some(q) = q else { return Ok(None) };
            let v = self.quantity(q, f)?;
            if v.fract() != 0.0 {
                return Err(self.error(
                    q.span(),
                    f.key,
                    format!("must be a whole number, got {}", show(v)),
                ));
            }
            Ok(Some(v as u64))
        };
        if let Some(p) = integer(raw.pixels_per_wavelength.as_ref(), &NUMERICAL_PIXELS)? {
            settings.pixels_per_wavelength = p as usize;
        }
        if let Some(r) = integer(raw.realisations.as_ref(), &NUMERICAL_REALISATIONS)? {
            settings.realisations = r as usize;
        }
        if let Some(seed) = integer(raw.seed.as_ref(), &NUMERICAL_SEED)? {
            settings.seed = seed;
        }
        self.numerical_grid(table, &settings)?;
        Ok(settings)
    }

    /// The grid `band · pixels_per_wavelength` per side, each in range, must fit
    /// [`MAX_GRID_PIXELS`]: 512 × 64 asks for 32768² pixels, ≈ 77 GB, which aborted on the
    /// allocation (a Python interpreter with it) instead of being refused.
    fn numerical_grid(
        &self,
        table: &Spanned<RawNumerical>,
        settings: &NumericalSettings,
    ) -> Result<(), ScenarioError> {
        let raw = table.get_ref();
        use crate::numerical::reference::{BYTES_PER_PIXEL, MAX_GRID_PIXELS};
        let n = settings.grid_size();
        if n.saturating_mul(n) <= MAX_GRID_PIXELS {
            return Ok(());
        }
        let (span, key) = match (&raw.band, &raw.pixels_per_wavelength) {
            (Some(b), _) => (b.span(), NUMERICAL_BAND.key),
            (None, Some(p)) => (p.span(), NUMERICAL_PIXELS.key),
            (None, None) => (table.span(), NUMERICAL_BAND.key),
        };
        let side = (MAX_GRID_PIXELS as f64).sqrt();
        Err(self.error(
            span,
            key,
            format!(
                "band {} × pixels_per_wavelength {} asks for a {n} × {n} grid, which needs about \
                 {:.1} GB (≈ {BYTES_PER_PIXEL} bytes a pixel); the numerical level solves at most \
                 {side} × {side} (≈ {:.1} GB): lower band or pixels_per_wavelength so that their \
                 product is at most {side}",
                show(settings.band),
                settings.pixels_per_wavelength,
                settings.estimated_memory() / 1e9,
                BYTES_PER_PIXEL * MAX_GRID_PIXELS as f64 / 1e9,
            ),
        ))
    }

    /// A ring fitted at or below its compound's low-temperature limit T10 (docs/model.md §5.2):
    /// below it the rubber is leathery to glassy, it cannot be stretched and seated without
    /// damage, and a fitter warms it first. A stated `installation_temperature` there is refused;
    /// without one the ring is taken as fitted at 23 °C in a gland, else at the environment's first
    /// temperature, and that
    /// is flagged (the returned warning): its squeeze is applied to a glassy ring.
    fn fitting_temperature(
        &self,
        raw: &RawScenario,
        seal: &super::seal_spec::SealSpec,
        material: &Material,
        environment: &crate::material::TemperatureHistory,
    ) -> Result<Option<ScenarioError>, ScenarioError> {
        if !seal.geometry.fitted() {
            return Ok(None);
        }
        let Some(limit) = material.low_temperature_limit() else {
            return Ok(None);
        };
        let fitted = seal
            .fitting_temperature
            .unwrap_or_else(|| environment.at(0.0));
        if fitted > limit {
            return Ok(None);
        }
        let given = raw.seal.get_ref().installation_temperature.as_ref();
        let (span, key, unit) = match (given, raw.environment.as_ref()) {
            (Some(q), _) => (q.span(), "seal.installation_temperature", unit_of(q)),
            (None, Some(env)) => match &env.get_ref().temperature {
                Some(q) => (q.span(), "environment.temperature", unit_of(q)),
                None => (env.span(), "environment", Default::default()),
            },
            (None, None) => (raw.seal.span(), "seal", Default::default()),
        };
        let warm = unit.input(296.15_f64.max(limit + 10.0));
        if given.is_some() {
            return Err(self.error(
                span,
                key,
                format!(
                    "a ring fitted at {} is at or below its compound's low-temperature limit T10 = \
                     {}: there the rubber is leathery to glassy and cannot be stretched and seated \
                     without damage; fit it warmer, e.g. installation_temperature = \"{warm}\" \
                     [docs/model.md §5.2]",
                    unit.show(fitted),
                    unit.show(limit),
                ),
            ));
        }
        let taken = if seal.gland.is_some() {
            "the gland's default fitting temperature"
        } else {
            "the environment's first temperature"
        };
        Ok(Some(self.error(
            span,
            key,
            format!(
                "the ring is taken as fitted at {taken}, {}, at or \
                 below its compound's low-temperature limit T10 = {}: its squeeze is applied to a \
                 leathery to glassy ring (a far higher force than a ring fitted warm and cooled); \
                 a ring fitted warm: installation_temperature = \"{warm}\" in [seal] (the \
                 environment's history then starts after it) [docs/model.md §5.2]",
                unit.show(fitted),
                unit.show(limit),
            ),
        )))
    }

    /// `[surface] lay` (docs/model.md §9.15): `"isotropic"` (the default, what the contact
    /// model assumes) passes; `"spiral"` (a turned face) and `"radial"` are accepted with a
    /// warning that the channel along the lay is not modelled — for a gas, where a single turning
    /// groove across the seal is a classic leak path, the interface leak may be far too low.
    fn lay(
        &self,
        table: &Spanned<RawSurface>,
        gas: bool,
    ) -> Result<Option<ScenarioError>, ScenarioError> {
        let Some(lay) = &table.get_ref().lay else {
            return Ok(None);
        };
        let what = match lay.get_ref().as_str() {
            "isotropic" => return Ok(None),
            "spiral" => {
                "a spiral (turned) lay: a continuous groove can carry the fluid along the \
                         marks across the contact"
            }
            "radial" => {
                "a radial lay: the marks run across the contact, in the direction of the \
                         flow"
            }
            other => {
                return Err(self.error(
                    lay.span(),
                    "surface.lay",
                    format!(
                        "must be \"isotropic\" (no direction, the default), \"spiral\" (a \
                         turned face) or \"radial\" (marks across the seal), got {other:?}"
                    ),
                ));
            }
        };
        let consequence = if gas {
            "on a gas seal such a channel usually decides the leak, and this model of an \
             isotropic surface does not see it: the interface leak may be far too low; lap or \
             face-turn the surface with a circular lay, or measure the seal"
        } else {
            "the model treats the surface as isotropic and does not see a channel along the \
             lay: the leak may be too low"
        };
        Ok(Some(self.error(
            lay.span(),
            "surface.lay",
            format!("{what}; {consequence} [docs/model.md §9.15]"),
        )))
    }

    /// `[fluid] gas = "…"` (docs/model.md §3.9): a library gas or `"custom"` (with
    /// `molar_mass`, `molecular_diameter` and either a constant `viscosity` or the Sutherland
    /// constants `sutherland_viscosity`, `sutherland_temperature`, `sutherland_constant`); the
    /// absolute `inlet_pressure` and `outlet_pressure`, or `pressure_difference` with the
    /// outlet at `outlet_pressure` (default 1 atm). Liquid keys are refused.
    fn gas(&self, table: &Spanned<RawFluid>, id: &Spanned<String>) -> Result<Fluid, ScenarioError> {
        let raw = table.get_ref();
        let liquid = [
            (raw.library.as_ref().map(|l| l.span()), "fluid.library"),
            (
                raw.viscosity_40c.as_ref().map(|q| q.span()),
                VISCOSITY_40C.key,
            ),
            (
                raw.viscosity_100c.as_ref().map(|q| q.span()),
                VISCOSITY_100C.key,
            ),
            (raw.density.as_ref().map(|q| q.span()), DENSITY.key),
            (
                raw.thermal_expansion.as_ref().map(|q| q.span()),
                FLUID_EXPANSION.key,
            ),
        ];
        if let Some((Some(span), key)) = liquid.into_iter().find(|(s, _)| s.is_some()) {
            return Err(self.error(
                span,
                key,
                format!(
                    "a liquid's viscosity key, but [fluid] is the gas \"{}\": a gas takes its \
                     viscosity from the gas library, or (gas = \"custom\") a constant \
                     `viscosity` or the Sutherland constants",
                    id.get_ref()
                ),
            ));
        }
        let custom_keys = [
            (&raw.viscosity, "fluid.viscosity"),
            (&raw.molar_mass, MOLAR_MASS.key),
            (&raw.molecular_diameter, MOLECULAR_DIAMETER.key),
            (&raw.sutherland_viscosity, SUTHERLAND_VISCOSITY.key),
            (&raw.sutherland_temperature, "fluid.sutherland_temperature"),
            (&raw.sutherland_constant, SUTHERLAND_CONSTANT.key),
        ];
        let gas = if id.get_ref() == "custom" {
            self.custom_gas(table)?
        } else {
            let Some(known) = crate::gas::library(id.get_ref()) else {
                return Err(self.error(
                    id.span(),
                    "fluid.gas",
                    format!(
                        "unknown gas \"{}\"; known: {}, or \"custom\"",
                        id.get_ref(),
                        crate::gas::library_ids().join(", ")
                    ),
                ));
            };
            if let Some((Some(q), key)) = custom_keys.into_iter().find(|(q, _)| q.is_some()) {
                return Err(self.error(
                    q.span(),
                    key,
                    format!(
                        "only goes with gas = \"custom\": the library gas \"{}\" has its own",
                        id.get_ref()
                    ),
                ));
            }
            known
        };
        // a gauge unit on an absolute pressure is a mistake, not a conversion
        for (q, key) in [
            (&raw.inlet_pressure, INLET_PRESSURE.key),
            (&raw.outlet_pressure, OUTLET_PRESSURE.key),
        ] {
            if let Some(q) = q
                && let super::raw::RawQuantity::Text(t) = q.get_ref()
                && (t.contains("barg") || t.contains("psig"))
            {
                return Err(self.error(
                    q.span(),
                    key,
                    format!(
                        "\"{t}\" is a gauge pressure, but {key} is absolute: write it in bar, Pa \
                         or psi (absolute), or give pressure_difference"
                    ),
                ));
            }
        }
        let outlet = self.optional(raw.outlet_pressure.as_ref(), &OUTLET_PRESSURE)?;
        let pressure_difference = match (&raw.inlet_pressure, &raw.pressure_difference) {
            (Some(_), Some(dp)) => {
                return Err(self.error(
                    dp.span(),
                    PRESSURE_DIFFERENCE.key,
                    "inlet_pressure and pressure_difference are mutually exclusive: give the \
                     absolute inlet_pressure and outlet_pressure, or pressure_difference (with \
                     the outlet at outlet_pressure, default 1 atm)",
                ));
            }
            (Some(inlet), None) => {
                let Some(outlet) = outlet else {
                    return Err(self.error(
                        inlet.span(),
                        OUTLET_PRESSURE.key,
                        "missing key `outlet_pressure` in [fluid]: an absolute inlet_pressure \
                         needs the absolute outlet pressure (0 for vacuum)",
                    ));
                };
                let pa = self.quantity(inlet, &INLET_PRESSURE)?;
                if outlet > pa {
                    let span = raw
                        .outlet_pressure
                        .as_ref()
                        .map_or(inlet.span(), |q| q.span());
                    return Err(self.error(
                        span,
                        OUTLET_PRESSURE.key,
                        format!(
                            "the outlet pressure {} Pa is above the inlet pressure {} Pa: the \
                             inlet is the pressurised side",
                            show(outlet),
                            show(pa)
                        ),
                    ));
                }
                pa - outlet
            }
            (None, Some(dp)) => self.quantity(dp, &PRESSURE_DIFFERENCE)?,
            (None, None) => {
                return Err(self.error(
                    table.span(),
                    INLET_PRESSURE.key,
                    "missing key `inlet_pressure` in [fluid] (a gas takes the absolute \
                     inlet_pressure and outlet_pressure, or pressure_difference)",
                ));
            }
        };
        let law = ViscosityLaw::Gas(gas);
        Ok(Fluid {
            viscosity: 0.0,
            pressure_difference,
            law,
            gas: Some(GasService {
                gas,
                outlet_pressure: outlet.unwrap_or(ATMOSPHERE),
                temperature: ROOM_TEMPERATURE,
                flow_law: match raw.rarefaction.as_ref().map(|b| *b.get_ref()) {
                    Some(false) => crate::gas::FlowLaw::Continuum,
                    _ => crate::gas::FlowLaw::Rarefied,
                },
            }),
        }
        .at(ROOM_TEMPERATURE))
    }

    /// `gas = "custom"`: its molar mass, molecular diameter and viscosity (a constant, or the
    /// three Sutherland constants together).
    fn custom_gas(&self, table: &Spanned<RawFluid>) -> Result<crate::gas::Gas, ScenarioError> {
        let raw = table.get_ref();
        let required = |q: &Option<Quantity>, f: &Field| {
            self.required(q, f, table.span(), "in [fluid] for gas = \"custom\"")
        };
        let molar_mass = required(&raw.molar_mass, &MOLAR_MASS)?;
        let molecular_diameter = required(&raw.molecular_diameter, &MOLECULAR_DIAMETER)?;
        let sutherland = [
            &raw.sutherland_viscosity,
            &raw.sutherland_temperature,
            &raw.sutherland_constant,
        ];
        let viscosity = match (&raw.viscosity, sutherland.iter().find_map(|q| q.as_ref())) {
            (Some(_), Some(q)) => {
                return Err(self.error(
                    q.span(),
                    "fluid.viscosity",
                    "a constant `viscosity` and the Sutherland constants are mutually exclusive",
                ));
            }
            (Some(q), None) => {
                crate::gas::GasViscosity::Constant(self.quantity(q, &GAS_VISCOSITY)?)
            }
            (None, Some(_)) => {
                let mu0 = required(&raw.sutherland_viscosity, &SUTHERLAND_VISCOSITY)?;
                let Some(t0) = &raw.sutherland_temperature else {
                    return Err(self.error(
                        table.span(),
                        "fluid.sutherland_temperature",
                        "missing key `sutherland_temperature` in [fluid]: μ0 and S belong to \
                         their own reference temperature T0",
                    ));
                };
                let t0 = self.absolute_temperature(t0, "fluid.sutherland_temperature")?;
                let s = required(&raw.sutherland_constant, &SUTHERLAND_CONSTANT)?;
                crate::gas::GasViscosity::Sutherland(crate::gas::Sutherland { mu0, t0, s })
            }
            (None, None) => {
                return Err(self.error(
                    table.span(),
                    "fluid.viscosity",
                    "missing key `viscosity` in [fluid] for gas = \"custom\" (or the Sutherland \
                     constants sutherland_viscosity, sutherland_temperature, \
                     sutherland_constant)",
                ));
            }
        };
        Ok(crate::gas::Gas {
            id: "custom",
            molar_mass,
            viscosity,
            molecular_diameter,
            source: "custom gas (scenario)",
        })
    }

    /// `[fluid] volume_swell`: the compound's ASTM D471 ΔV/V0 in this fluid (−50 % < ΔV/V0 <
    /// 200 %), `None` when absent or zero (a zero swell changes nothing).
    fn volume_swell(
        &self,
        table: &Spanned<RawFluid>,
    ) -> Result<Option<(VolumeSwell, std::ops::Range<usize>)>, ScenarioError> {
        let Some(q) = &table.get_ref().volume_swell else {
            return Ok(None);
        };
        let volume_change = self.quantity(q, &VOLUME_SWELL)?;
        Ok((volume_change != 0.0).then(|| (VolumeSwell { volume_change }, q.span())))
    }

    /// `[fluid]`: the pressure difference and the viscosity, one of `viscosity` (constant),
    /// `library` (water, ISO VG grades) or the inline ASTM D341 law (`viscosity_40c`,
    /// `viscosity_100c`, `density`, optional `thermal_expansion`); docs/model.md §3.7. The
    /// viscosity returned is the constant's (or, for a law, the one at 20 °C: the caller
    /// evaluates it at the installation temperature).
    fn fluid(&self, table: &Spanned<RawFluid>) -> Result<Fluid, ScenarioError> {
        let raw = table.get_ref();
        if let Some(id) = &raw.gas {
            return self.gas(table, id);
        }
        self.refuse_gas_keys(raw)?;
        let Some(dp) = &raw.pressure_difference else {
            return Err(self.error(
                table.span(),
                PRESSURE_DIFFERENCE.key,
                "missing key `pressure_difference` in [fluid]",
            ));
        };
        let pressure_difference = self.quantity(dp, &PRESSURE_DIFFERENCE)?;
        let inline = raw.viscosity_40c.as_ref().or(raw.viscosity_100c.as_ref());
        self.one_viscosity_source(raw, inline)?;
        let with_law = |law: ViscosityLaw| {
            let fluid = Fluid {
                viscosity: 0.0,
                pressure_difference,
                law,
                gas: None,
            };
            fluid.at(ROOM_TEMPERATURE)
        };
        if let Some(q) = &raw.viscosity {
            return Ok(Fluid {
                viscosity: self.quantity(q, &VISCOSITY)?,
                pressure_difference,
                law: ViscosityLaw::Constant,
                gas: None,
            });
        }
        if let Some(id) = &raw.library {
            return match crate::fluid::library(id.get_ref()) {
                Some(known) => Ok(with_law(known.law)),
                None => Err(self.error(
                    id.span(),
                    "fluid.library",
                    format!(
                        "unknown fluid \"{}\"; known: {}",
                        id.get_ref(),
                        crate::fluid::library_ids().join(", ")
                    ),
                )),
            };
        }
        let Some(first) = inline else {
            return Err(self.error(
                table.span(),
                VISCOSITY.key,
                "missing key `viscosity` in [fluid] (or `library`, or `viscosity_40c` and \
                 `viscosity_100c` with `density`)",
            ));
        };
        Ok(with_law(self.inline_viscosity_law(raw, first)?))
    }

    /// A liquid's `[fluid]` refuses the keys of a gas (`rarefaction`, absolute pressures, molar
    /// mass, molecular diameter, Sutherland constants).
    fn refuse_gas_keys(&self, raw: &RawFluid) -> Result<(), ScenarioError> {
        if let Some(b) = &raw.rarefaction {
            return Err(self.error(
                b.span(),
                "fluid.rarefaction",
                "rarefaction is the flow law of a gas: add `gas = \"…\"` to [fluid], or remove \
                 the key (a liquid does not rarefy)",
            ));
        }
        if let Some(q) = [&raw.inlet_pressure, &raw.outlet_pressure]
            .into_iter()
            .chain([&raw.molar_mass, &raw.molecular_diameter])
            .chain([
                &raw.sutherland_viscosity,
                &raw.sutherland_temperature,
                &raw.sutherland_constant,
            ])
            .flatten()
            .next()
        {
            return Err(self.error(
                q.span(),
                "fluid.gas",
                "absolute pressures, molar mass, molecular diameter and Sutherland constants \
                 belong to a gas: add `gas = \"…\"` to [fluid] (a liquid takes \
                 `pressure_difference`)",
            ));
        }
        Ok(())
    }

    /// At most one of a constant `viscosity`, a `library` fluid and the inline law
    /// (`inline`: `viscosity_40c` or `viscosity_100c`); `density` and `thermal_expansion`
    /// only with the inline law.
    fn one_viscosity_source(
        &self,
        raw: &RawFluid,
        inline: Option<&Quantity>,
    ) -> Result<(), ScenarioError> {
        let given: Vec<(&str, std::ops::Range<usize>)> = [
            raw.viscosity.as_ref().map(|q| ("viscosity", q.span())),
            raw.library.as_ref().map(|l| ("library", l.span())),
            inline.map(|q| ("viscosity_40c/viscosity_100c", q.span())),
        ]
        .into_iter()
        .flatten()
        .collect();
        if given.len() > 1 {
            let (key, span) = given[1].clone();
            return Err(self.error(
                span,
                &format!("fluid.{}", key.split('/').next().unwrap_or(key)),
                format!(
                    "{} and {key} are mutually exclusive: give a constant `viscosity`, a \
                     `library` fluid, or the inline law `viscosity_40c`, `viscosity_100c` with \
                     `density`",
                    given[0].0
                ),
            ));
        }
        if inline.is_none() {
            let stray = [
                (&raw.density, DENSITY.key),
                (&raw.thermal_expansion, FLUID_EXPANSION.key),
            ];
            if let Some((Some(q), key)) = stray.into_iter().find(|(q, _)| q.is_some()) {
                return Err(self.error(
                    q.span(),
                    key,
                    "only goes with the inline law `viscosity_40c`, `viscosity_100c` (a \
                     constant `viscosity` is dynamic; a `library` fluid has its own density)",
                ));
            }
        }
        Ok(())
    }

    /// The inline ASTM D341 law through `viscosity_40c` and `viscosity_100c` with `density` and
    /// the optional `thermal_expansion` (`first`: the first of the two viscosities given).
    fn inline_viscosity_law(
        &self,
        raw: &RawFluid,
        first: &Quantity,
    ) -> Result<ViscosityLaw, ScenarioError> {
        let required = |q: &Option<Quantity>, f: &Field, why: &str| {
            self.required(q, f, first.span(), &format!("in [fluid]: {why}"))
        };
        let both = "the ASTM D341 law needs the kinematic viscosities at 40 °C and 100 °C";
        let nu40 = required(&raw.viscosity_40c, &VISCOSITY_40C, both)?;
        let nu100 = required(&raw.viscosity_100c, &VISCOSITY_100C, both)?;
        let density = required(
            &raw.density,
            &DENSITY,
            "a kinematic viscosity (cSt) needs the density at 15 °C to give η = ρ ν",
        )?;
        let expansion = self
            .optional(raw.thermal_expansion.as_ref(), &FLUID_EXPANSION)?
            .unwrap_or(MINERAL_OIL_EXPANSION);
        match Walther::through(
            nu40,
            nu100,
            density,
            expansion,
            "inline ASTM D341 through ν40, ν100",
        ) {
            Some(w) => Ok(ViscosityLaw::Walther(w)),
            None => Err(self.error(
                raw.viscosity_100c
                    .as_ref()
                    .map_or(first.span(), |q| q.span()),
                VISCOSITY_100C.key,
                format!(
                    "must be below viscosity_40c ({} m²/s): an oil thins when heated, got {} m²/s",
                    show(nu40),
                    show(nu100)
                ),
            )),
        }
    }

    fn model(&self, raw: &RawModel) -> Result<(ContactSettings, f64), ScenarioError> {
        let defaults = ContactSettings::default();
        let contact = ContactSettings {
            percolation_threshold: self
                .optional(raw.percolation_threshold.as_ref(), &PERCOLATION_THRESHOLD)?
                .unwrap_or(defaults.percolation_threshold),
            gamma: self
                .optional(raw.gamma.as_ref(), &GAMMA)?
                .unwrap_or(defaults.gamma),
            area: self.area_model(raw.area.as_ref())?,
            quadrature: Default::default(),
        };
        let shape_factor = self
            .optional(raw.shape_factor.as_ref(), &SHAPE_FACTOR)?
            .unwrap_or(DEFAULT_SHAPE_FACTOR);
        Ok((contact, shape_factor))
    }

    /// `[model] area` (docs/model.md §2): `"persson"` (the default) or `"corrected"`.
    fn area_model(&self, raw: Option<&Spanned<String>>) -> Result<AreaModel, ScenarioError> {
        let Some(area) = raw else {
            return Ok(AreaModel::default());
        };
        match area.get_ref().as_str() {
            "persson" => Ok(AreaModel::Persson),
            "corrected" => Ok(AreaModel::Corrected),
            other => Err(self.error(
                area.span(),
                "model.area",
                format!(
                    "must be \"persson\" (Persson 2001, the default: the smaller contact area, \
                     so the larger leak) or \"corrected\" (Wang & Müser 2017's scale march, \
                     closer to boundary-element contact areas), got {other:?}"
                ),
            )),
        }
    }

    /// `[groove_surface]`: the groove bottom's surface of a groove-seated ring, in the keys of
    /// `[surface]` but without a height map (absent: the counterface's surface); refused without a
    /// gland. Messages name `groove_surface.…`. Also returns the notes of a callout.
    fn groove_surface(
        &self,
        table: Option<&Spanned<RawSurface>>,
        in_gland: bool,
    ) -> Result<(GrooveInterface, Vec<ScenarioError>), ScenarioError> {
        let Some(table) = table else {
            let groove = if in_gland {
                GrooveInterface::Counterface
            } else {
                GrooveInterface::None
            };
            return Ok((groove, Vec::new()));
        };
        if !in_gland {
            return Err(self.error(
                table.span(),
                "groove_surface",
                "the groove bottom is the second sealing interface of a groove-seated O-ring: set \
                 [seal] gland (face, piston or rod) or remove [groove_surface]",
            ));
        }
        if let Some(map) = &table.get_ref().height_map {
            return Err(self.error(
                map.span(),
                "groove_surface.height_map",
                "a height map describes the counterface for the numerical level; give the groove \
                 bottom as a spectrum (self-affine keys, a callout or psd_file)",
            ));
        }
        match self.surface(table) {
            Ok((spectrum, _, notes)) => Ok((
                GrooveInterface::Own(spectrum),
                notes
                    .into_iter()
                    .map(|n| renamed(n, "groove_surface"))
                    .collect(),
            )),
            Err(e) => Err(renamed(e, "groove_surface")),
        }
    }

    /// `[rubber_surface]`: the rubber's own roughness, in the keys of `[surface]` but without a
    /// height map; refused when the counterface is a height map (the numerical level would see
    /// the map alone). The contact sees `C_counterface + C_rubber` ([`Spectrum::sum`],
    /// docs/model.md §2.2). Messages name `rubber_surface.…`.
    fn rubber_surface(
        &self,
        table: &Spanned<RawSurface>,
        counterface_map: bool,
    ) -> Result<(Spectrum, Vec<ScenarioError>), ScenarioError> {
        if let Some(map) = &table.get_ref().height_map {
            return Err(self.error(
                map.span(),
                "rubber_surface.height_map",
                "a height map describes the counterface for the numerical level; give the \
                 rubber's roughness as a spectrum (self-affine keys, a callout or psd_file)",
            ));
        }
        if counterface_map {
            return Err(self.error(
                table.span(),
                "rubber_surface",
                "the counterface is a height map, which the numerical level uses as the whole \
                 surface, without the rubber's roughness: give [surface] as a spectrum \
                 (psd_file, a callout or self-affine keys) or remove [rubber_surface]",
            ));
        }
        match self.surface(table) {
            Ok((spectrum, _, notes)) => Ok((
                spectrum,
                notes
                    .into_iter()
                    .map(|n| renamed(n, "rubber_surface"))
                    .collect(),
            )),
            Err(e) => Err(renamed(e, "rubber_surface")),
        }
    }

    /// `[surface]`: a self-affine spectrum, a tabulated one from `psd_file`, or the spectrum
    /// estimated from `height_map` (which is also returned, for the numerical level).
    /// The notes returned say how a callout became a spectrum (printed with the warnings).
    fn surface(
        &self,
        table: &Spanned<RawSurface>,
    ) -> Result<(Spectrum, Option<HeightMap>, Vec<ScenarioError>), ScenarioError> {
        let raw = table.get_ref();
        let callout: Vec<(&Quantity, &Field)> = [(&raw.ra, &RA), (&raw.rq, &RQ), (&raw.rz, &RZ)]
            .into_iter()
            .filter_map(|(q, f)| q.as_ref().map(|q| (q, f)))
            .collect();
        if let Some(&(value, field)) = callout.first() {
            let name = field.key.trim_start_matches("surface.");
            if let Some(&(other, other_field)) = callout.get(1) {
                return Err(self.error(
                    other.span(),
                    other_field.key,
                    format!(
                        "{name} and {} are mutually exclusive: a drawing callout gives one of \
                         ra, rq or rz",
                        other_field.key.trim_start_matches("surface.")
                    ),
                ));
            }
            for (present, key) in [
                (
                    raw.rms_roughness.as_ref().map(Spanned::span),
                    RMS_ROUGHNESS.key,
                ),
                (raw.psd_file.as_ref().map(Spanned::span), "surface.psd_file"),
                (raw.height_map.as_ref().map(Spanned::span), HEIGHT_MAP),
                (raw.pixel_size.as_ref().map(Spanned::span), PIXEL_SIZE.key),
                (raw.height_unit.as_ref().map(Spanned::span), HEIGHT_UNIT),
                (raw.rolloff.as_ref().map(Spanned::span), ROLLOFF.key),
                (raw.profile.as_ref().map(Spanned::span), "surface.profile"),
            ] {
                if let Some(span) = present {
                    let short = key.trim_start_matches("surface.");
                    let why = if key == ROLLOFF.key {
                        "the callout's spectrum rolls off at 2π/cutoff".to_owned()
                    } else {
                        format!("the callout gives the spectrum; remove {short} or {name}")
                    };
                    return Err(self.error(
                        span,
                        key,
                        format!("{short} and {name} are mutually exclusive: {why}"),
                    ));
                }
            }
            let (spectrum, note) = self.callout_surface(table, value, field)?;
            return Ok((spectrum, None, vec![note]));
        }
        for (present, key) in [
            (raw.cutoff.as_ref().map(Spanned::span), CUTOFF.key),
            (
                raw.short_cutoff.as_ref().map(Spanned::span),
                SHORT_CUTOFF.key,
            ),
            (
                raw.short_wavelength.as_ref().map(Spanned::span),
                SHORT_WAVELENGTH,
            ),
        ] {
            if let Some(span) = present {
                return Err(self.error(
                    span,
                    key,
                    "only applies to a drawing callout: give ra, rq or rz with it, or remove \
                     this key",
                ));
            }
        }
        if let Some(files) = &raw.profile {
            let (spectrum, notes) = self.profile_surface(raw, files)?;
            return Ok((spectrum, None, notes));
        }
        if let Some(file) = &raw.height_map {
            let (spectrum, map, notes) = self.height_map_surface(raw, file)?;
            return Ok((spectrum, Some(map), notes));
        }
        for (present, key) in [
            (raw.pixel_size.as_ref().map(Spanned::span), PIXEL_SIZE.key),
            (raw.height_unit.as_ref().map(Spanned::span), HEIGHT_UNIT),
        ] {
            if let Some(span) = present {
                return Err(self.error(
                    span,
                    key,
                    "only applies to a height map: set height_map (a CSV grid of heights) or \
                     remove this key",
                ));
            }
        }
        let spectrum = match &raw.psd_file {
            Some(file) => self.tabulated_surface(raw, file)?,
            None if raw.rms_roughness.is_none() && raw.hurst_exponent.is_none() => {
                return Err(self.error(
                    table.span(),
                    "surface",
                    "no spectrum given: set either a drawing callout (ra, rq or rz), line \
                     traces (profile), the self-affine parameters (rms_roughness, \
                     hurst_exponent, q0, q1, optional rolloff), psd_file (a CSV of q, C) or \
                     height_map (a CSV grid of heights with pixel_size, or a .gsf file)",
                ));
            }
            None => self.self_affine_surface(table)?,
        };
        Ok((spectrum, None, Vec::new()))
    }

    /// `profile`: line traces (CSV `x,z`, relative to the scenario's directory) → the isotropic
    /// 2-D spectrum over the band the traces can be trusted in ([`crate::profile::analyse`]),
    /// continued above the band by the fitted power law up to `q1` (default 2π/10 nm, the rule
    /// of the callouts, docs/model.md §2.1) and stopped below it (longer waves than the traces
    /// see are left out); with a note saying how it was built (docs/model.md §2.3).
    fn profile_surface(
        &self,
        raw: &RawSurface,
        files: &Spanned<crate::scenario::raw::Files>,
    ) -> Result<(Spectrum, Vec<ScenarioError>), ScenarioError> {
        for (present, key) in [
            (
                raw.rms_roughness.as_ref().map(Spanned::span),
                RMS_ROUGHNESS.key,
            ),
            (
                raw.hurst_exponent.as_ref().map(Spanned::span),
                HURST_EXPONENT.key,
            ),
            (raw.q0.as_ref().map(Spanned::span), "surface.q0"),
            (raw.rolloff.as_ref().map(Spanned::span), ROLLOFF.key),
            (raw.psd_file.as_ref().map(Spanned::span), "surface.psd_file"),
            (raw.height_map.as_ref().map(Spanned::span), HEIGHT_MAP),
            (raw.pixel_size.as_ref().map(Spanned::span), PIXEL_SIZE.key),
            (raw.height_unit.as_ref().map(Spanned::span), HEIGHT_UNIT),
        ] {
            if let Some(span) = present {
                let short = key.trim_start_matches("surface.");
                return Err(self.error(
                    span,
                    key,
                    format!(
                        "{short} and profile are mutually exclusive: the traces give the spectrum \
                         (and its Hurst exponent); only q1, where the fitted power law ends, may \
                         go with them"
                    ),
                ));
            }
        }
        let line = self.line(files.span().start);
        let names = files.get_ref().names();
        if names.is_empty() {
            return Err(self.error(files.span(), "surface.profile", "names no trace file"));
        }
        let mut traces = Vec::with_capacity(names.len());
        let mut slips = Vec::new();
        for name in &names {
            let path = self.relative_path(name);
            let trace = crate::scenario::profile::read_trace(&path).map_err(|e| {
                ScenarioError::TraceFormat {
                    trace: path.clone(),
                    trace_line: e.line,
                    scenario: self.path.to_path_buf(),
                    line,
                    message: e.message,
                }
            })?;
            // heights in µm under a units row of m still make a spectrum (§2.4)
            if let Some((text, _)) =
                crate::plausibility::HeightStatistics::of_trace(trace.spacing, &trace.heights)
                    .warning(None)
            {
                slips.push(self.error(
                    files.span(),
                    "surface.profile",
                    format!(
                        "{}: {text}; check the z unit of its units row [docs/model.md §2.4]",
                        path.display()
                    ),
                ));
            }
            traces.push(trace);
        }
        let first = self.relative_path(names[0]);
        let error = |message: String| ScenarioError::TraceFormat {
            trace: first.clone(),
            trace_line: None,
            scenario: self.path.to_path_buf(),
            line,
            message,
        };
        let result = crate::profile::analyse(&traces, &crate::profile::ProfileOptions::default())
            .map_err(|e| error(e.to_string()))?;
        let (q_lo, q_hi) = result.band;
        let hurst = result.hurst.0;
        let q1 = match &raw.q1 {
            Some(q) => {
                let q1 = self.quantity(q, &Q1)?;
                if q1 < q_hi {
                    return Err(self.error(
                        q.span(),
                        Q1.key,
                        format!(
                            "below the traces' band (which ends at {} 1/m): q1 continues the \
                             fitted power law beyond it",
                            show(q_hi)
                        ),
                    ));
                }
                q1
            }
            None => 2.0 * std::f64::consts::PI / roughness::EXTEND_TO_WAVELENGTH,
        };
        // the knots of the traces' spectrum: the bin points and, when a roll-off was fitted,
        // its corner
        let mut q: Vec<f64> = result
            .psd_1d
            .q
            .iter()
            .copied()
            .chain(result.q0)
            .filter(|&x| x >= q_lo && x <= q_hi)
            .collect();
        q.sort_by(f64::total_cmp);
        q.dedup_by(|a, b| (*a / *b - 1.0).abs() < 1e-12);
        let mut c: Vec<f64> = q.iter().map(|&x| result.spectrum.c(x)).collect();
        if q1 > q_hi * (1.0 + 1e-9) {
            let c_hi = result.spectrum.c(q_hi);
            if q.last().is_some_and(|&last| last < q_hi) {
                q.push(q_hi);
                c.push(c_hi);
            }
            q.push(q1);
            c.push(c_hi * (q1 / q_hi).powf(-2.0 * (1.0 + hurst)));
        }
        let spectrum = Spectrum::tabulated(&q, &c).map_err(|e| error(e.to_string()))?;
        let note = self.error(
            files.span(),
            "surface.profile",
            format!(
                "note: {} trace(s): band {} … {} 1/m (h_rms {} µm, rms slope {:.3}), fitted H = \
                 {:.3} ({:.3} – {:.3}), continued as a power law to q1 = {} 1/m: h_rms {} µm, \
                 rms slope {:.3} [docs/model.md §2.3]",
                traces.len(),
                show(q_lo),
                show(q_hi),
                show(result.h_rms * 1e6),
                result.rms_slope,
                hurst,
                result.hurst.1.0,
                result.hurst.1.1,
                show(q1),
                show(spectrum.rms_roughness() * 1e6),
                spectrum.rms_slope()
            ),
        );
        slips.insert(0, note);
        Ok((spectrum, slips))
    }

    /// A drawing callout (`ra`, `rq` or `rz`, given as `value` of `field`) with `cutoff` λc
    /// (default 0.8 mm), `short_cutoff` λs (default 2.5 µm), `hurst_exponent` (default 0.8),
    /// optional `q0` (< 2π/λc: a flat part) and the rule below λs (`short_wavelength =
    /// "extend"` (default) or `"stop"`, or `q1`): the spectrum of [`Callout::spectrum`] and a
    /// note saying how it was built (docs/model.md §2.1).
    fn callout_surface(
        &self,
        table: &Spanned<RawSurface>,
        value: &Quantity,
        field: &Field,
    ) -> Result<(Spectrum, ScenarioError), ScenarioError> {
        let raw = table.get_ref();
        let given = self.quantity(value, field)?;
        let hurst = self.optional(raw.hurst_exponent.as_ref(), &HURST_EXPONENT)?;
        let band = self.callout_band(table)?;
        let short = self.short_wavelengths(table, &band)?;
        let q0 = self.optional(raw.q0.as_ref(), &Q0)?;
        if let (Some(q0), Some(raw_q0)) = (q0, &raw.q0)
            && q0 > band.q_lo()
        {
            return Err(self.error(
                raw_q0.span(),
                Q0.key,
                format!(
                    "must not exceed 2π/cutoff = {} 1/m (it would cut the measured band), got \
                     {} 1/m",
                    show(band.q_lo()),
                    show(q0)
                ),
            ));
        }
        let (rq, how) = self.callout_rq(value, field, given, &band)?;
        let callout = Callout {
            rq,
            hurst: hurst.unwrap_or(roughness::DEFAULT_HURST),
            band,
            q0,
            short,
        };
        let spectrum = callout
            .spectrum()
            .map_err(|e| self.error(value.span(), field.key, e.to_string()))?;
        let name = field.key.trim_start_matches("surface.");
        let rule = Self::short_rule(short, &spectrum);
        let note = self.error(
            value.span(),
            field.key,
            format!(
                "note: callout {name} = {} m over λs = {} m … λc = {} m read as Rq = {} m ({how}), \
                 H = {}{}; roughness below λs: {rule}; the spectrum: q0 = {} 1/m, h_rms = {} m, \
                 rms slope = {} [docs/model.md §2.1]",
                show(given),
                show(callout.band.short_cutoff),
                show(callout.band.cutoff),
                show(rq),
                show(callout.hurst),
                if hurst.is_none() { " (default)" } else { "" },
                show(spectrum.q0()),
                show(spectrum.rms_roughness()),
                show(spectrum.rms_slope()),
            ),
        );
        Ok((spectrum, note))
    }

    /// A callout's band: `cutoff` λc (default 0.8 mm) longer than `short_cutoff` λs (default
    /// 2.5 µm).
    fn callout_band(&self, table: &Spanned<RawSurface>) -> Result<Band, ScenarioError> {
        let raw = table.get_ref();
        let cutoff = self
            .optional(raw.cutoff.as_ref(), &CUTOFF)?
            .unwrap_or(roughness::DEFAULT_CUTOFF);
        let short_cutoff = self
            .optional(raw.short_cutoff.as_ref(), &SHORT_CUTOFF)?
            .unwrap_or(roughness::DEFAULT_SHORT_CUTOFF);
        if cutoff <= short_cutoff {
            let (span, key) = match (&raw.cutoff, &raw.short_cutoff) {
                (Some(q), _) => (q.span(), CUTOFF.key),
                (None, Some(q)) => (q.span(), SHORT_CUTOFF.key),
                (None, None) => (table.span(), CUTOFF.key),
            };
            return Err(self.error(
                span,
                key,
                format!(
                    "the cut-off λc (cutoff = {} m) must be longer than the short cut-off λs \
                     (short_cutoff = {} m): the measured band is λs … λc",
                    show(cutoff),
                    show(short_cutoff)
                ),
            ));
        }
        Ok(Band {
            cutoff,
            short_cutoff,
        })
    }

    /// The roughness below λs: `short_wavelength = "extend"` (default) or `"stop"`, or `q1`
    /// (at least the band's end).
    fn short_wavelengths(
        &self,
        table: &Spanned<RawSurface>,
        band: &Band,
    ) -> Result<ShortWavelengths, ScenarioError> {
        let raw = table.get_ref();
        let q1 = self.optional(raw.q1.as_ref(), &Q1)?;
        Ok(match (&raw.short_wavelength, q1) {
            (Some(rule), Some(_)) => {
                return Err(self.error(
                    rule.span(),
                    SHORT_WAVELENGTH,
                    "short_wavelength and q1 are mutually exclusive: q1 already says where the \
                     roughness below λs ends",
                ));
            }
            (None, Some(q1)) => {
                if q1 < band.q_hi() {
                    return Err(self.error(
                        raw.q1.as_ref().map_or(table.span(), Spanned::span),
                        Q1.key,
                        format!(
                            "must be at least 2π/short_cutoff = {} 1/m (the measured band ends \
                             there), got {} 1/m",
                            show(band.q_hi()),
                            show(q1)
                        ),
                    ));
                }
                ShortWavelengths::UpTo(q1)
            }
            (Some(rule), None) => match rule.get_ref().trim() {
                "extend" => ShortWavelengths::Extend,
                "stop" => ShortWavelengths::Stop,
                other => {
                    return Err(self.error(
                        rule.span(),
                        SHORT_WAVELENGTH,
                        format!(
                            "expected \"extend\" (the power law continues to 10 nm) or \"stop\" \
                             (no roughness below short_cutoff), got {other:?}"
                        ),
                    ));
                }
            },
            (None, None) => ShortWavelengths::Extend,
        })
    }

    /// The Rq a callout's `given` value of `field` means (Ra and Rz converted for Gaussian
    /// heights), and how it was read.
    fn callout_rq(
        &self,
        value: &Quantity,
        field: &Field,
        given: f64,
        band: &Band,
    ) -> Result<(f64, String), ScenarioError> {
        let (cutoff, short_cutoff) = (band.cutoff, band.short_cutoff);
        Ok(if field.key == RA.key {
            (
                roughness::rq_from_ra(given),
                "Gaussian heights: Rq = √(π/2) Ra".to_owned(),
            )
        } else if field.key == RZ.key {
            let n = cutoff / short_cutoff;
            if n < 2.0 {
                return Err(self.error(
                    value.span(),
                    RZ.key,
                    format!(
                        "needs cutoff/short_cutoff ≥ 2 (Rz is a peak-to-valley height over \
                         cutoff/short_cutoff independent samples), got {}",
                        show(n)
                    ),
                ));
            }
            let ratio = roughness::rz_over_rq(cutoff, short_cutoff);
            (
                given / ratio,
                format!(
                    "Gaussian heights, N = λc/λs = {} independent samples per λc: Rz = 2 m(N) Rq \
                     = {} Rq; practice's Rz/Ra ratios spread 4–7 and more, so Rq is uncertain \
                     by up to ≈ ×2",
                    show(n),
                    show(ratio)
                ),
            )
        } else {
            (given, "Rq given".to_owned())
        })
    }

    /// What a callout's spectrum holds below λs, for its note.
    fn short_rule(short: ShortWavelengths, spectrum: &Spectrum) -> String {
        match short {
            ShortWavelengths::Extend => format!(
                "extended as the power law to {} m (q1 = {} 1/m; short_wavelength = \"extend\", \
                 the default; \"stop\" ends it at λs)",
                show(roughness::EXTEND_TO_WAVELENGTH),
                show(spectrum.q1())
            ),
            ShortWavelengths::Stop => {
                "none: the spectrum stops at λs (short_wavelength = \"stop\")".to_owned()
            }
            ShortWavelengths::UpTo(q1) => {
                format!(
                    "extended as the power law to the given q1 = {} 1/m",
                    show(q1)
                )
            }
        }
    }

    /// `height_map` (relative to the scenario's directory): a CSV grid with `pixel_size` and the
    /// optional `height_unit`, or a `.gsf` file that states both (the keys are then refused);
    /// rectangular grids accepted. The grid in SI units and its PSD estimate over the whole map
    /// ([`map_psd::estimate_topography`], q0 from the shorter side) (default options: Hann window
    /// unless the map is periodic, 10 bins per decade, h_rms equal to the detrended map's rms,
    /// band `2π/(L√π)` … `π/pixel_size`; [`crate::numerical::psd`]), restricted to the optional
    /// `q0`, `q1`. The map returned for the numerical level is the largest centred even square
    /// ([`crate::numerical::Topography::square_crop`]), with a note when that is not the whole
    /// map.
    /// Heights in µm read as m still make a spectrum: the likely unit slip (§2.4) as a warning
    /// at the height_unit line (or the map's, for the file's own units).
    fn height_slip(
        &self,
        raw: &RawSurface,
        file: &Spanned<String>,
        topography: &crate::numerical::Topography,
        unit: f64,
    ) -> Option<ScenarioError> {
        crate::plausibility::HeightStatistics::of_map(
            topography.nx,
            topography.ny,
            topography.pixel,
            &topography.heights,
        )
        .warning(Some(unit))
        .map(|(text, likely)| match (&raw.height_unit, likely) {
            (Some(given), Some(likely)) => self.error(
                given.span(),
                HEIGHT_UNIT,
                format!("{text}; write height_unit = \"{likely}\" [docs/model.md §2.4]"),
            ),
            _ => self.error(
                file.span(),
                HEIGHT_MAP,
                format!("{text} (the file's own units) [docs/model.md §2.4]"),
            ),
        })
    }

    fn height_map_surface(
        &self,
        raw: &RawSurface,
        file: &Spanned<String>,
    ) -> Result<(Spectrum, HeightMap, Vec<ScenarioError>), ScenarioError> {
        for (present, key) in [
            (
                raw.rms_roughness.as_ref().map(Spanned::span),
                RMS_ROUGHNESS.key,
            ),
            (
                raw.hurst_exponent.as_ref().map(Spanned::span),
                HURST_EXPONENT.key,
            ),
            (raw.rolloff.as_ref().map(Spanned::span), ROLLOFF.key),
            (raw.psd_file.as_ref().map(Spanned::span), "surface.psd_file"),
        ] {
            if let Some(span) = present {
                return Err(self.error(
                    span,
                    key,
                    format!(
                        "height_map gives the whole surface; remove {key} (or remove height_map)"
                    ),
                ));
            }
        }
        let path = self.relative_path(file.get_ref());
        let gsf = super::surface_files::is_gsf(&path);
        let (pixel, unit) = if gsf {
            // the file states its pixel size and units (scenario/gsf.rs)
            for (present, key) in [
                (raw.pixel_size.as_ref().map(Spanned::span), PIXEL_SIZE.key),
                (raw.height_unit.as_ref().map(Spanned::span), HEIGHT_UNIT),
            ] {
                if let Some(span) = present {
                    return Err(self.error(
                        span,
                        key,
                        "a .gsf height map states its pixel size (XReal/XRes) and height unit \
                         (ZUnits) itself: remove this key",
                    ));
                }
            }
            (None, 1.0)
        } else {
            let Some(pixel_size) = &raw.pixel_size else {
                return Err(self.error(
                    file.span(),
                    HEIGHT_MAP,
                    "needs pixel_size, the spacing of the grid's samples (e.g. pixel_size = \
                     \"0.5 um\")",
                ));
            };
            let pixel = self.quantity(pixel_size, &PIXEL_SIZE)?;
            let unit = match &raw.height_unit {
                // a CSV grid of bare heights could be in m or µm: the unit must be stated
                None => {
                    return Err(self.error(
                        file.span(),
                        HEIGHT_MAP,
                        "needs height_unit, the unit of the grid's heights (e.g. height_unit = \
                         \"um\"): a bare height could be metres or micrometres",
                    ));
                }
                Some(text) => match units::parse_unit(text.get_ref().trim()) {
                    Ok((factor, dimension)) if dimension == Dimension::LENGTH => factor,
                    Ok(_) | Err(_) => {
                        return Err(self.error(
                            text.span(),
                            HEIGHT_UNIT,
                            format!(
                                "expected a length unit for the heights, such as \"m\", \"um\" \
                                 or \"nm\", got {:?}",
                                text.get_ref()
                            ),
                        ));
                    }
                },
            };
            (Some(pixel), unit)
        };
        let line = self.line(file.span().start);
        if !path.is_file() {
            return Err(self.error(
                file.span(),
                HEIGHT_MAP,
                format!("cannot read height map {}: no such file", path.display()),
            ));
        }
        let format_error =
            |map_line: Option<usize>, message: String| ScenarioError::HeightMapFormat {
                map: path.clone(),
                map_line,
                scenario: self.path.to_path_buf(),
                line,
                message,
            };
        let topography = super::surface_files::read_height_map(&path, pixel, unit)
            .map_err(|e| format_error(e.line, e.message))?;
        let slip = self.height_slip(raw, file, &topography, unit);
        let spectrum = map_psd::estimate_topography(&topography, &map_psd::PsdOptions::default())
            .map_err(|e| format_error(None, e.to_string()))?;
        // the numerical level needs a square periodic grid of even side: the centred crop
        let (map, (x0, y0)) = topography.square_crop();
        let note = (!topography.is_square_even()).then(|| {
            self.error(
                file.span(),
                HEIGHT_MAP,
                format!(
                    "the map is {} × {} pixels: its spectrum uses the whole map (q0 from the \
                     shorter side); the numerical level (fidelity = \"numerical\") runs on its \
                     centred {} × {} crop (columns {}–{}, rows {}–{})",
                    topography.nx,
                    topography.ny,
                    map.n,
                    map.n,
                    x0 + 1,
                    x0 + map.n,
                    y0 + 1,
                    y0 + map.n
                ),
            )
        });
        let short_side = topography.nx.min(topography.ny) as f64 * topography.pixel;

        let q0 = self.optional(raw.q0.as_ref(), &Q0)?;
        let q1 = self.optional(raw.q1.as_ref(), &Q1)?;
        let (span, key) = match (&raw.q0, &raw.q1) {
            (Some(q), _) => (q.span(), Q0.key),
            (None, Some(q)) => (q.span(), Q1.key),
            (None, None) => return Ok((spectrum, map, note.into_iter().chain(slip).collect())),
        };
        let (lo, hi) = (q0.unwrap_or(spectrum.q0()), q1.unwrap_or(spectrum.q1()));
        let spectrum = spectrum.restricted(lo, hi).map_err(|e| {
            self.error(
                span,
                key,
                format!(
                    "{e} (the height map's spectrum covers 2π/(L√π) … π/pixel_size, \
                     L = {} m its shorter side)",
                    show(short_side)
                ),
            )
        })?;
        Ok((spectrum, map, note.into_iter().chain(slip).collect()))
    }

    fn self_affine_surface(&self, table: &Spanned<RawSurface>) -> Result<Spectrum, ScenarioError> {
        let raw = table.get_ref();
        let required = |q: Option<&Quantity>, field: &Field| {
            match q {
            Some(q) => self.quantity(q, field),
            None => Err(self.error(
                table.span(),
                field.key,
                "missing key: a self-affine spectrum needs rms_roughness, hurst_exponent, q0 and q1 \
                 (or give psd_file instead)",
            )),
        }
        };
        let h_rms = required(raw.rms_roughness.as_ref(), &RMS_ROUGHNESS)?;
        let hurst = required(raw.hurst_exponent.as_ref(), &HURST_EXPONENT)?;
        let q0 = required(raw.q0.as_ref(), &Q0)?;
        let q1 = required(raw.q1.as_ref(), &Q1)?;
        if q0 >= q1 {
            return Err(self.error(
                raw.q0.as_ref().map_or(table.span(), Spanned::span),
                Q0.key,
                format!(
                    "must be smaller than surface.q1, got q0 = {} 1/m and q1 = {} 1/m",
                    show(q0),
                    show(q1)
                ),
            ));
        }
        let rolloff = self.optional(raw.rolloff.as_ref(), &ROLLOFF)?;
        if let (Some(qr), Some(qr_raw)) = (rolloff, &raw.rolloff)
            && !(qr > q0 && qr < q1)
        {
            return Err(self.error(
                qr_raw.span(),
                ROLLOFF.key,
                format!(
                    "must lie strictly between q0 = {} 1/m and q1 = {} 1/m, got {} 1/m",
                    show(q0),
                    show(q1),
                    show(qr)
                ),
            ));
        }
        Spectrum::self_affine(h_rms, hurst, q0, q1, rolloff)
            .map_err(|e| self.error(table.span(), "surface", e.to_string()))
    }

    fn tabulated_surface(
        &self,
        raw: &RawSurface,
        file: &Spanned<String>,
    ) -> Result<Spectrum, ScenarioError> {
        for (present, key) in [
            (&raw.rms_roughness, RMS_ROUGHNESS.key),
            (&raw.hurst_exponent, HURST_EXPONENT.key),
            (&raw.rolloff, ROLLOFF.key),
        ] {
            if let Some(q) = present {
                return Err(self.error(
                    q.span(),
                    key,
                    format!("psd_file gives the whole spectrum; remove {key} (or remove psd_file)"),
                ));
            }
        }
        let line = self.line(file.span().start);
        let psd_path = self.relative_path(file.get_ref());
        let text = std::fs::read_to_string(&psd_path).map_err(|source| ScenarioError::PsdRead {
            psd: psd_path.clone(),
            scenario: self.path.to_path_buf(),
            line,
            source,
        })?;
        let format_error = |psd_line: Option<usize>, message: String| ScenarioError::PsdFormat {
            psd: psd_path.clone(),
            psd_line,
            scenario: self.path.to_path_buf(),
            line,
            message,
        };
        let (q, c) = psd::parse(&text).map_err(|e| format_error(e.line, e.message))?;
        let spectrum =
            Spectrum::tabulated(&q, &c).map_err(|e| format_error(None, e.to_string()))?;
        // moments that overflow (C(q) of 1e308 …) make every later number meaningless
        if let Some(why) = super::surface_files::implausible_spectrum(
            spectrum.rms_roughness(),
            spectrum.rms_slope(),
        ) {
            return Err(format_error(None, why));
        }

        let q0 = self.optional(raw.q0.as_ref(), &Q0)?;
        let q1 = self.optional(raw.q1.as_ref(), &Q1)?;
        // A band error is reported at q0 if it is given, else at q1.
        let (span, key) = match (&raw.q0, &raw.q1) {
            (Some(q), _) => (q.span(), Q0.key),
            (None, Some(q)) => (q.span(), Q1.key),
            (None, None) => return Ok(spectrum),
        };
        let (lo, hi) = (q0.unwrap_or(spectrum.q0()), q1.unwrap_or(spectrum.q1()));
        spectrum
            .restricted(lo, hi)
            .map_err(|e| self.error(span, key, e.to_string()))
    }
}

/// `error` (or note) of a `[surface]`-keyed table re-addressed to `[table]` (`groove_surface`,
/// `rubber_surface`): its key and the `surface.` keys its message names.
fn renamed(error: ScenarioError, table: &str) -> ScenarioError {
    match error {
        ScenarioError::Invalid {
            path,
            line,
            key,
            message,
        } => ScenarioError::Invalid {
            path,
            line,
            key: key.map(|k| match k.strip_prefix("surface") {
                Some(rest) => format!("{table}{rest}"),
                None => k,
            }),
            message: message.replace("surface.", &format!("{table}.")),
        },
        other => other,
    }
}

/// The run's own tables, read by [`Source::service`].
struct Service {
    ageing: Option<crate::material::Ageing>,
    ageing_source: crate::simulate::AgeingSource,
    failure: crate::simulate::FailureCriteria,
    time: crate::simulate::TimeGrid,
    fidelity: crate::leak::Fidelity,
    contamination: Option<crate::clogging::Contamination>,
    numerical: NumericalSettings,
    motion: Option<crate::dynamic::MotionSpec>,
}

/// A checked run and what its closing warnings look at: the file, the compound, the life
/// problem, the fluid's volume swell (with its span) and the library fluid `fluid.library`
/// names (with that key).
struct Run<'r> {
    raw: &'r RawScenario,
    material: &'r Material,
    life: &'r LifeProblem,
    swell: Option<&'r (VolumeSwell, Range<usize>)>,
    known_fluid: Option<(&'r Spanned<String>, LibraryFluid)>,
}

/// The span of `environment.temperature` (or of its table, or of `[fluid]` without one).
fn temperature_span(raw: &RawScenario) -> Range<usize> {
    raw.environment.as_ref().map_or(raw.fluid.span(), |e| {
        e.get_ref()
            .temperature
            .as_ref()
            .map_or(e.span(), |t| t.span())
    })
}

/// Two temperatures closer than this \[K\] are the same for the fitting lead-in (1 µK: far below
/// any measurement, far above the rounding of a unit round trip, ~1e-13 K).
const SAME_TEMPERATURE: f64 = 1e-6;

/// A ring fitted at another temperature than the environment's first: its temperature settles
/// to the environment's over its thermal time (docs/model.md §5.2).
fn settling_environment(
    environment: crate::material::TemperatureHistory,
    seal: &super::seal_spec::SealSpec,
) -> crate::material::TemperatureHistory {
    match (seal.fitting_temperature, seal.geometry.fitted()) {
        // a difference in the last bits (a history read back from °F: 296.15 K → 73.4 °F →
        // 296.14999999999996 K) is no difference: no thermometer resolves a µK, and the lead-in
        // would replace the history's first seconds with its ramp
        (Some(fitted), true) if (fitted - environment.at(0.0)).abs() > SAME_TEMPERATURE => {
            let length = seal.geometry.cooling_length().unwrap_or(0.0);
            environment.with_lead_in(fitted, thermal_settling_time(length))
        }
        _ => environment,
    }
}

/// The flat seal of the static leak problem (`sealsim leak`, `figures`). A flat scenario's
/// own seal; for an O-ring, the uniform equivalent of its central strip right after
/// installation: the Hertz peak pressure of Lindley's force with the instantaneous modulus E0
/// as P0, Lindley's contact width as L_x and the circumference π D as L_y (`sealsim run`
/// integrates the whole profile as strips in series).
fn static_seal(life: &LifeProblem) -> FlatSeal {
    let load = life
        .geometry
        .load_variable(life.thermal_strain.as_ref(), life.installed_temperature());
    life.geometry.static_seal(load, &|| life.initial_profile())
}

/// The temperature scale a quantity was written in (°C for a bare number).
fn unit_of(q: &Quantity) -> crate::units::TemperatureUnit {
    match q.get_ref() {
        super::raw::RawQuantity::Text(text) => crate::units::TemperatureUnit::of(text),
        super::raw::RawQuantity::Number(_) => Default::default(),
    }
}

/// The thermal diffusivity of rubber a \[m²/s\]: k/(ρ c_p) with k ≈ 0.2 W/(m K),
/// ρ ≈ 1.2e3 kg/m³, c_p ≈ 1.7e3 J/(kg K) for filled NBR-like compounds, ≈ 1e-7 m²/s
/// (docs/model.md §5.2).
pub const RUBBER_THERMAL_DIFFUSIVITY: f64 = 1e-7;

/// The time a cord of diameter `cross_section` \[m\] takes to follow a change of its
/// surroundings' temperature, `d²/a` \[s\] (125 s for 3.53 mm): three time constants
/// `d²/(23.1 a)` of a cylinder's slowest conduction mode (2.405 the first zero of J0) and more.
pub fn thermal_settling_time(cross_section: f64) -> f64 {
    cross_section * cross_section / RUBBER_THERMAL_DIFFUSIVITY
}
