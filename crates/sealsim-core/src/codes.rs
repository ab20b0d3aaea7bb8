//! The stable codes of sealsim's warnings and notes: one registry ([`ALL`]) of every validity
//! finding (the validity module's `Limit`, `W001`–`W029`), every input warning of a scenario
//! (`W030`–`W059`) and every input note (`N001`–…), each with its identifier, a short title (what
//! the one-line stderr message says), the long explanation `sealsim explain CODE` prints, and the
//! section of docs/model.md that defines it. The guide's warnings page
//! (`docs/src/reference/warnings.md`) is generated from it (`sealsim generate warnings`).
//!
//! A code is never reused for another meaning: a retired warning keeps its number out of use.

/// What a code reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// A validity limit of the model crossed by a computation (docs/model.md §9).
    Validity,
    /// A scenario input that is accepted but questionable (`FILE:LINE: key: …`).
    Input,
    /// How an input was read (information, not a problem): shown with `--verbose`.
    Note,
}

impl Kind {
    /// `validity`, `input` or `note`.
    pub fn as_str(self) -> &'static str {
        match self {
            Kind::Validity => "validity",
            Kind::Input => "input",
            Kind::Note => "note",
        }
    }
}

/// One registered code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Code {
    /// `W001` … (a warning) or `N001` … (a note).
    pub code: &'static str,
    /// The identifier (a validity finding's `id` in the JSON summaries).
    pub id: &'static str,
    pub kind: Kind,
    /// What the one-line message says (≤ 60 characters).
    pub title: &'static str,
    /// The long explanation: what it means for the result and what to do.
    pub explanation: &'static str,
    /// The section of docs/model.md that defines it (`§9.1`).
    pub section: &'static str,
}

macro_rules! codes {
    ($($name:ident = $code:literal, $id:literal, $kind:ident, $section:literal, $title:literal,
       $explanation:literal;)*) => {
        $(
            #[doc = concat!("`", $code, "` `", $id, "`: ", $title, " (docs/model.md ", $section, ").")]
            pub const $name: Code = Code {
                code: $code,
                id: $id,
                kind: Kind::$kind,
                title: $title,
                explanation: $explanation,
                section: $section,
            };
        )*
        /// Every code, in the order of its number.
        pub const ALL: &[Code] = &[$($name),*];
    };
}

codes! {
    PRESSURE_RATIO = "W001", "pressure_ratio", Validity, "§9.1",
        "fluid's load on the rubber not modelled",
        "ΔP/P0 > 0.5, with P0 the peak contact pressure that holds the critical junction. The \
         fluid pressure is modelled on the asperities of the interface, but its load on the \
         rubber body, which reshapes the nominal contact, is not: the contact picture is \
         stretched. It is evaluated only while the seal is in contact; a seal whose fluid \
         pressure has lifted it off is reported by the verdict (state lift_off), not here. \
         What to do: raise the squeeze or the gasket stress, or treat the life near the end of \
         the run as the point where the seal is held by the fluid pressure alone.";
    ASPECT_RATIO = "W002", "aspect_ratio", Validity, "§9.2",
        "critical constriction not a thin gap",
        "u_c/λ_c > 0.1 at the critical constriction: the lubrication (thin-gap) flow u³/12η \
         overstates its conductance, so the leak rate is an upper estimate. It happens for very \
         rough or lightly loaded surfaces.";
    MOLECULAR_GAP = "W003", "molecular_gap", Validity, "§9.3",
        "constriction below 1 nm: continuum flow not valid",
        "The critical constriction u_c is below 1 nm: continuum flow is not valid within a few \
         molecular sizes; a gap narrower than one molecule of the fluid is reported as sealed. \
         The leak rate there is a continuum extrapolation.";
    NEAR_CUTOFF = "W004", "near_cutoff", Validity, "§9.4",
        "critical junction near the short-wavelength cut-off",
        "ζc > (q1/q0)/2: the critical junction lies near the short-wavelength cut-off q1, so the \
         result depends on the cut-off, which is often uncertain. Check the surface's q1 (or the \
         callout's λs) and run a case with another cut-off.";
    HURST_EXPONENT = "W005", "hurst_exponent", Validity, "§9.5",
        "Hurst exponent outside the checked 0.6–0.9",
        "The self-affine spectrum's Hurst exponent is outside 0.6–0.9, the range for which \
         sealsim's analytic contact levels were checked against independent references.";
    SQUEEZE = "W006", "squeeze", Validity, "§9.6",
        "O-ring squeeze outside Lindley's 5–30 %",
        "The O-ring's squeeze (with its thermal strain) is outside the 5–30 % for which \
         Lindley's relations between squeeze, contact width and force are used; the force and \
         the contact width are extrapolated.";
    GLASS_TRANSITION = "W007", "below_glass_transition", Validity, "§9.7",
        "below the glass transition: rubber turns glassy",
        "The temperature is below the compound's glass transition T_g: the rubber turns glassy. \
         WLF is extrapolated below its range, and a Prony series that stops at the rubbery \
         plateau is far too soft here. A seal this cold usually leaks until it warms up; the \
         cold limit (docs/model.md §8.3) is the failure criterion for it.";
    FROZEN = "W008", "frozen", Validity, "§9.7",
        "at or below the WLF singularity: rubber frozen",
        "The temperature is at or below the WLF singularity (T_ref − C2): the rubber is treated \
         as frozen (no relaxation). The result there is not a prediction.";
    RMS_SLOPE = "W009", "rms_slope", Validity, "§9.8",
        "rms slope above 0.5: small-slope theory stretched",
        "The surface's rms slope is above 0.5: the small-slope contact theory is stretched, so \
         the contact area and the separation are less reliable. A callout's short-wavelength \
         filter λs (or q1) sets the slope: check it.";
    SPEED_BOUND = "W010", "speed_above_bound", Validity, "§9.9",
        "sliding speed above the low-speed bound",
        "The sliding speed is above PY08's bound: the drag pressure opens the critical \
         constriction and hydrodynamic lift-off is not modelled, so the drag leak rate is likely \
         underestimated. Give the inlet pressure gradients (contact_profile) to use the \
         inverse-hydrodynamic films.";
    BAND_LIMITED = "W011", "band_limited", Validity, "§9.10",
        "numerical level resolved only part of the spectrum",
        "The numerical level resolved only a band of the spectrum: its answer is for the \
         band-limited surface, not the whole one.";
    NUMERICAL_FAILURE = "W012", "numerical_failure", Validity, "§9.10",
        "a node of the numerical table failed",
        "A node of the numerical level's contact table failed and was left out; the table \
         interpolates across it. The message names the solver's error.";
    NO_FAILURE_CRITERION = "W013", "no_failure_criterion", Validity, "§8",
        "no failure criterion: the seal can only survive",
        "The [failure] block sets no criterion, so a life run can only survive. Give \
         max_leak_rate, max_leaked_volume or min_retained_force.";
    EXTRUSION = "W014", "extrusion", Validity, "§9.12",
        "clearance close to the extrusion limit",
        "The groove-seated ring's diametral clearance is above 0.8 of the extrusion chart's \
         limit for this pressure and the rubber's hardness (above 1 the ring fails by \
         extrusion). Tighten the clearance or add back-up rings.";
    EXTRUSION_CHART = "W015", "extrusion_chart", Validity, "§9.12",
        "outside the extrusion chart: nearest row used",
        "The pressure or the hardness is outside the extrusion chart (70–90 Shore A ± 2, up to \
         3000 psi): its nearest row or band, or its trend, is used, and the message says which.";
    DATA_TIME = "W016", "beyond_data_time", Validity, "§9.13",
        "beyond the reduced times of the material's data",
        "The reduced time is beyond the window of the data the material's series was fitted to: \
         the relaxation there is an extrapolation of the series.";
    DATA_TEMPERATURE = "W017", "beyond_data_temperature", Validity, "§9.13",
        "outside the temperatures of the material's data",
        "The temperature is outside the window of the material's data: the temperature shift \
         (or, without one, the series itself) is extrapolated.";
    IHL_TRANSITION = "W018", "speed_in_ihl_transition", Validity, "§9.9",
        "stroke speed in the blend band: volumes blended",
        "The stroke speed is between the end of the low-speed theory and the \
         inverse-hydrodynamic regime (10× that speed): the stroke volumes are a log-speed blend \
         of the two.";
    GRADIENT_ESTIMATE = "W019", "estimated_pressure_gradients", Validity, "§9.9",
        "inlet pressure gradients estimated (Hertz)",
        "No contact-pressure profile was given: the O-ring's inlet pressure gradients are \
         estimated from its Hertz profile, so the inverse-hydrodynamic films are estimates. \
         Give [motion] contact_profile or inlet_gradient_out/inlet_gradient_in.";
    KNUDSEN_SLIP = "W020", "knudsen_slip", Validity, "§9.14",
        "gas in the slip regime (0.01 < Kn ≤ 0.1)",
        "The gas at the critical constriction is in the slip regime: the rarefied slit law adds \
         first-order slip (flow × ≈ 1 + 6 Kn), accurate to a few % here.";
    KNUDSEN_TRANSITION = "W021", "knudsen_transition", Validity, "§9.14",
        "gas in the transition regime (0.1 < Kn ≤ 10)",
        "The gas at the critical constriction is in the transition regime: the rarefied slit \
         law interpolates between slip and free-molecular flow; its error against kinetic \
         theory is not quantified here (tens of % possible).";
    KNUDSEN_FREE_MOLECULAR = "W022", "knudsen_free_molecular", Validity, "§9.14",
        "gas free-molecular (Kn > 10)",
        "The gas at the critical constriction flows free-molecularly: Smoluchowski's slit \
         conductance applies; its logarithm of λc/u_c makes it uncertain by tens of %.";
    KNUDSEN_CONTINUUM_LAW = "W023", "knudsen_continuum_law", Validity, "§9.14",
        "rarefied gas under the continuum law",
        "The gas is rarefied at the critical constriction but `rarefaction = false`: the \
         continuum law underestimates the flow (slip alone adds ≈ 6 Kn). Remove the key.";
    NARROW_CONTACT = "W024", "narrow_contact", Validity, "§9.16",
        "contact narrower than two long wavelengths",
        "Fewer than two of the surface's longest wavelengths 2π/q0 fit across the contact: its \
         strips are not statistical samples of the roughness, and the leak of so narrow a \
         contact depends on where its few long waves sit (the model gives their average).";
    GLAND_SQUEEZE_RANGE = "W030", "gland_squeeze_range", Input, "§6.2",
        "squeeze over the tolerances outside the gland's range",
        "The squeeze at the tolerance limits leaves the handbook range of the gland (10–30 % \
         static, 10–16 % dynamic): below it the seal may leak at low pressure, above it \
         friction, wear and compression set rise. Change the groove depth.";
    VACUUM_OUTER_SEAT = "W031", "vacuum_outer_seat", Input, "§6.2",
        "vacuum service: ring seated on the outer wall",
        "The ring bears on the groove's outer wall (pressure inside) but the gas outlet is \
         below 1 atm: a vacuum flange has its vacuum inside and pushes the ring onto the inner \
         wall. Give groove_inner_diameter, or pressure_side = \"inside\".";
    CIRCUMFERENTIAL_COMPRESSION = "W032", "circumferential_compression", Input, "§6.2",
        "ring compressed circumferentially above 3 %",
        "The ring is compressed circumferentially onto the wall that holds it above the 3 % \
         recommended: it may buckle or be pinched on assembly. Choose another size (the message \
         suggests some).";
    SQUEEZE_AT_TOLERANCE = "W033", "squeeze_at_tolerance", Input, "§6.2",
        "squeeze reaches 0 at the tolerance limits",
        "At the tolerance limits the squeeze falls to zero or below: the cord may not touch \
         both walls. Tighten the groove-depth tolerance or deepen the squeeze.";
    GLAND_OVERFILL = "W034", "gland_overfill", Input, "§6.2",
        "gland fill above the 85 %/90 % guidance",
        "The gland fill is above 85 % nominal or 90 % at maximum material condition: little \
         room for thermal expansion or swell. Widen the groove.";
    GLAND_UNDERFILL = "W035", "gland_underfill", Input, "§6.2",
        "gland fill below half the groove",
        "The ring fills less than half its groove (the usual range is 65–85 %): it can shift \
         and roll. Is the groove width or depth in the intended unit?";
    STRETCH = "W036", "stretch", Input, "§6.2",
        "ring stretched above 5 % onto its seat",
        "The ring is stretched above the 5 % recommended onto its seat: it ages faster and its \
         cord thins. Choose a ring with a larger inside diameter.";
    FLUID_NOT_RECOMMENDED = "W037", "fluid_not_recommended", Input, "§6.8",
        "compound rated not recommended for the fluid",
        "The compound is rated X (not recommended) for the fluid in the compatibility table: \
         the model does not model chemical attack, so its life is not a prediction. Choose a \
         compound rated A or B.";
    AGEING_MEDIUM = "W038", "ageing_medium", Input, "§6.8",
        "ageing constants measured in another medium",
        "The compound's ageing constants were measured in another medium than the run's fluid: \
         ageing specific to the medium (hydrolysis in water, oxidation in air, swelling and \
         extraction in oil) is not modelled, so the ageing rate is the measured medium's.";
    RATED_TEMPERATURE = "W039", "rated_temperature", Input, "§6.7",
        "above the compound class's rated temperature",
        "The temperature reaches above the rated temperature of the compound's class: a seal \
         there is expected to lose 30–50 % of its properties within 1,000 h and may decompose; \
         the ageing constants are extrapolated.";
    SWELL = "W040", "swell", Input, "§3.8",
        "volume swell beyond seal practice (≈ 30 %)",
        "The volume swell is beyond seal practice (≈ 30 %): the compound is not compatible with \
         this fluid; the swell relations are applied as given.";
    UNSHIFTED = "W041", "unshifted_relaxation", Input, "§9.13",
        "no temperature shift and no data temperature",
        "The material has neither a temperature shift nor a data temperature: its relaxation is \
         taken as measured at every temperature of the run. Give data_temperature or a \
         [material.shift].";
    SURFACE_LAY = "W042", "surface_lay", Input, "§9.15",
        "directional lay: a channel along it not modelled",
        "A spiral or radial lay: a continuous groove can carry the fluid along the marks across \
         the contact, and the isotropic contact model does not see it, so the leak may be far \
         too low (on a gas seal such a channel usually decides the leak).";
    COLD_FITTING = "W043", "cold_fitting", Input, "§5.2",
        "ring taken as fitted at or below its T10",
        "The ring is taken as fitted at or below its compound's low-temperature limit T10: its \
         squeeze is applied to a leathery to glassy ring (a far higher force than a ring fitted \
         warm and cooled). Give installation_temperature in [seal].";
    HEIGHT_SLIP = "W044", "height_unit_slip", Input, "§2.4",
        "heights implausible for their spacing: a unit slip?",
        "A height map's or trace's heights are implausible for their sample spacing (rms slope \
         above 10 at the spacing, or rms height of 1 mm or more): most often heights in µm read \
         as metres. The message names the likely unit; fix height_unit or the units row.";
    SURFACE_NOTE = "N001", "surface_reading", Note, "§2.1",
        "how the roughness input became a spectrum",
        "How a roughness callout (Ra, Rq, Rz with λs and λc) or a set of traces was read into \
         the spectrum the contact model uses: its q0, q1, h_rms, Hurst exponent and rms slope.";
    COMPATIBILITY_NOTE = "N002", "compatibility_rating", Note, "§6.8",
        "the compound's rating for the fluid",
        "The compound's compatibility rating (A, B or C) for the fluid, with its source.";
    PERMEATION_NOTE = "N003", "permeation_figure", Note, "§13.7",
        "where the gas permeation figure comes from",
        "Which permeation coefficient the run uses for the gas through the rubber (the \
         compound's own, its class's sourced figure, or a stated bound) and why.";
}

/// The registered code `code` (`W001`, case-insensitive), if any.
pub fn lookup(code: &str) -> Option<&'static Code> {
    ALL.iter()
        .find(|c| c.code.eq_ignore_ascii_case(code.trim()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_and_ids_are_unique_titles_short_and_sections_named() {
        let mut codes: Vec<&str> = ALL.iter().map(|c| c.code).collect();
        codes.sort_unstable();
        codes.dedup();
        assert_eq!(codes.len(), ALL.len());
        let mut ids: Vec<&str> = ALL.iter().map(|c| c.id).collect();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), ALL.len());
        for c in ALL {
            assert!(c.title.chars().count() <= 60, "{}: {}", c.code, c.title);
            assert!(c.section.starts_with('§'), "{}", c.code);
            let prefix = if c.kind == Kind::Note { 'N' } else { 'W' };
            assert!(
                c.code.starts_with(prefix) && c.code.len() == 4,
                "{}",
                c.code
            );
        }
        assert_eq!(lookup("w001"), Some(&PRESSURE_RATIO));
        assert_eq!(lookup("W999"), None);
    }
}
