//! Leak rate of a static seal through its critical constriction (PY08 §2, eqs. 1–3).

use crate::contact::{
    ContactSettings, ContactTable, CriticalJunction, EffectiveMediumSettings, EffectiveMediumTable,
    Elastic, FullContact, Junction, PerssonContact, TableSettings,
};
use crate::fluid::{Fluid, junction_conductance, passes_molecule};
use crate::interface::{self, InterfaceFlow, InterfaceSettings};
use crate::numerical::HeightMap;
use crate::numerical::reference::NumericalSettings;
use crate::numerical::table::NumericalTable;
use crate::surface::Spectrum;
use crate::validity::{self, At, ContactState, Findings};

/// The flat seal of the leak problem lives with the other seal geometries.
pub use crate::seal::FlatSeal;

/// Which level of the fidelity ladder (docs/model.md §4) evaluates the contact and the leak.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Fidelity {
    /// `u_c ≈ h_rms(ζc)` (PY08 §3, Fig. 12): closed forms only, no separation quadrature.
    RuleOfThumb,
    /// Critical junction `u_c = u1(ζc)` by quadrature at every pressure.
    Exact,
    /// Critical junction by interpolation in a [`ContactTable`] built once per surface (falls
    /// back to the exact path outside the table's range).
    #[default]
    Table,
    /// Bruggeman's 2-D effective medium over the separation distribution P(u) (docs/model.md §3.3,
    /// [`crate::contact::effective_medium`]), tabulated once per surface
    /// ([`EffectiveMediumTable`]).
    EffectiveMedium,
    /// The numerical reference (docs/model.md §3.5, [`crate::numerical`]): BEM contact, percolation
    /// and Reynolds flow on realisations of the surface (or on a measured height map),
    /// tabulated against P0/E* at a few nodes ([`NumericalTable`]); seconds to minutes to build.
    Numerical,
}

impl Fidelity {
    /// Every level, cheapest first.
    pub const ALL: [Fidelity; 5] = [
        Fidelity::RuleOfThumb,
        Fidelity::Table,
        Fidelity::Exact,
        Fidelity::EffectiveMedium,
        Fidelity::Numerical,
    ];

    /// The level's name in scenario files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Fidelity::RuleOfThumb => "rule-of-thumb",
            Fidelity::Exact => "exact",
            Fidelity::Table => "critical-junction",
            Fidelity::EffectiveMedium => "effective-medium",
            Fidelity::Numerical => "numerical",
        }
    }

    /// The neighbouring level a life summary sets its figures beside (docs/model.md §4.1): the
    /// nearest level that computes the gap by *another model* — the critical junction and the
    /// effective medium are each other's (the `exact` level is the critical junction by
    /// quadrature: its neighbour is the effective medium too); the rule of thumb's is the critical
    /// junction it approximates; the numerical reference's the effective medium.
    pub fn neighbour(self) -> Fidelity {
        match self {
            Fidelity::RuleOfThumb | Fidelity::EffectiveMedium => Fidelity::Table,
            Fidelity::Table | Fidelity::Exact | Fidelity::Numerical => Fidelity::EffectiveMedium,
        }
    }

    /// Other names of the level (scenario files and command line alike).
    pub fn aliases(self) -> &'static [&'static str] {
        match self {
            Fidelity::Table => &["table"],
            _ => &[],
        }
    }

    /// What the level computes, in a few words (command-line help).
    pub fn description(self) -> &'static str {
        match self {
            Fidelity::RuleOfThumb => "u_c ≈ h_rms(ζc), closed forms only",
            Fidelity::Table => "critical junction from a contact table built once per surface",
            Fidelity::Exact => "critical junction by quadrature at every pressure",
            Fidelity::EffectiveMedium => "Bruggeman effective medium over the separation P(u)",
            Fidelity::Numerical => {
                "numerical reference: BEM contact and Reynolds flow on surface realisations \
                 (seconds to minutes)"
            }
        }
    }

    /// The level's measured error, as the user guide's fidelity ladder (docs/src/reference/fidelity.md) states it (reports).
    pub fn measured_error(self) -> &'static str {
        match self {
            Fidelity::RuleOfThumb => {
                "u_c within a factor 2 of the critical junction's on the paper's surface \
                 (h_rms(ζc)/u1(ζc) = 0.57–2.35 over 0.01–1 MPa), up to 10× in the leak rate"
            }
            Fidelity::Table => {
                "contact table against quadrature < 3.2e-4; the model itself (the critical \
                 junction) against the effective medium: a factor 0.6–37 in the leak rate on the \
                 paper's case"
            }
            Fidelity::Exact => {
                "the reference the contact table is checked against (< 3.2e-4); the \
                 critical-junction model itself as for critical-junction"
            }
            Fidelity::EffectiveMedium => "table against direct solve < 2.6e-4",
            Fidelity::Numerical => {
                "resolves a band q1/q0 of a few tens only; its statistical error is in the run's \
                 warnings"
            }
        }
    }

    /// The level named `name` (its [`name`](Self::name) or one of its
    /// [`aliases`](Self::aliases)).
    pub fn from_name(name: &str) -> Option<Fidelity> {
        Fidelity::ALL
            .into_iter()
            .find(|f| f.name() == name || f.aliases().contains(&name))
    }
}

/// Everything the static leak calculation needs, in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticProblem {
    pub material: Elastic,
    pub spectrum: Spectrum,
    pub fluid: Fluid,
    pub seal: FlatSeal,
    pub contact: ContactSettings,
    /// Shape factor α of the critical constriction (PY08 eq. 2), ≈ 1.
    pub shape_factor: f64,
}

/// One evaluated pressure point.
///
/// `junction` is the conducting channel of the level ([`ContactPath::critical_junction`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeakPoint {
    /// Nominal squeezing pressure P0 \[Pa\].
    pub nominal_pressure: f64,
    /// The critical junction where the asperities carry most (docs/model.md §3.6).
    pub junction: Junction,
    /// Volume leak rate Q̇ \[m³/s\]; exactly 0 when sealed.
    pub leak_rate: f64,
    pub state: SealState,
}

/// State of the interface (docs/model.md §8.1, which names the tolerances that decide it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SealState {
    /// A channel percolates and its critical gap is wider than a molecule of the fluid.
    Leaking,
    /// No channel percolates (somewhere across the width).
    Sealed,
    /// A channel percolates, but its critical gap is narrower than a molecule of the fluid
    /// ([`crate::fluid::Fluid::molecular_size`]): nothing passes, the leak is 0 (the computed
    /// u_c stays in the history).
    BelowMolecule,
    /// The fluid pressure reaches the contact pressure across the whole width: the seal is
    /// open (docs/model.md §3.6). The leak rate shown is the model's at the threshold of
    /// lift-off, a lower bound ([`lift_off_threshold`]).
    LiftOff,
    /// Energised (k_e > 1 − τ) while the squeeze's part of the contact pressure has fallen
    /// below τ ΔP ([`SQUEEZE_SHARE_TOLERANCE`]): the seal is held by the fluid pressure alone,
    /// within the uncertainty of k_e — it would open on any fall of the pressure.
    PressureHeld,
}

impl SealState {
    /// Every state, in the order a seal passes through them.
    pub const ALL: [SealState; 5] = [
        SealState::Sealed,
        SealState::BelowMolecule,
        SealState::Leaking,
        SealState::PressureHeld,
        SealState::LiftOff,
    ];

    /// The state's name in the CSV and JSON outputs.
    pub fn as_str(self) -> &'static str {
        match self {
            SealState::Leaking => "leaking",
            SealState::Sealed => "sealed",
            SealState::BelowMolecule => "sealed",
            SealState::LiftOff => "lift_off",
            SealState::PressureHeld => "pressure_held",
        }
    }

    /// The state for a reader, short: `"sealed (no percolating channel)"`, `"OPEN (lift-off)"`.
    pub fn label(self) -> &'static str {
        match self {
            SealState::Leaking => "leaking",
            SealState::Sealed => "sealed (no percolating channel)",
            SealState::BelowMolecule => "sealed (critical gap below a molecule)",
            SealState::LiftOff => "OPEN (lift-off)",
            SealState::PressureHeld => "held by the fluid pressure alone",
        }
    }

    /// What the state means, for a reader.
    pub fn meaning(self) -> &'static str {
        match self {
            SealState::Leaking => "a channel percolates through the contact",
            SealState::Sealed => "no channel percolates through the contact",
            SealState::BelowMolecule => {
                "a channel percolates, but its critical gap is narrower than a molecule of the \
                 fluid"
            }
            SealState::LiftOff => "the fluid pressure exceeds the contact pressure",
            SealState::PressureHeld => {
                "the squeeze's contact pressure is below 0.1 % of ΔP: any fall of the pressure \
                 opens the seal"
            }
        }
    }

    /// Why a sealed state is sealed (`None` for the others).
    pub fn reason(self) -> Option<&'static str> {
        match self {
            SealState::Sealed => Some("no_percolating_channel"),
            SealState::BelowMolecule => Some("critical_gap_below_a_molecule"),
            _ => None,
        }
    }

    /// Whether the interface holds the fluid back (sealed, or below a molecule).
    pub fn is_sealed(self) -> bool {
        matches!(self, SealState::Sealed | SealState::BelowMolecule)
    }

    /// Whether the seal is open, or would open on any fall of the pressure (what the
    /// `lift_off` criterion fails on).
    pub fn is_open(self) -> bool {
        matches!(self, SealState::LiftOff | SealState::PressureHeld)
    }
}

/// τ, the share of ΔP below which the squeeze's part of the contact pressure no longer counts
/// as holding an energised seal (docs/model.md §8.1). The peak contact pressure is
/// `p_sq + k_e ΔP`; when the squeeze's part has decayed below 0.1 % of ΔP the seal is held by the
/// fluid pressure alone — k_e is not known to 0.1 % (§6.3), and a ring so relaxed opens at the
/// first fall of the pressure. τ sits 13 decades above the rounding of `p_sq + ΔP` (ΔP·1e-16),
/// where the verdict used to be decided, and far below the squeeze stress of a working ring
/// at any service pressure (1.5 MPa against 0.1 % of 1000 bar = 0.1 MPa). It also makes the
/// verdict continuous in k_e: the seal opens at `p_sq ≤ max(1 − k_e, τ) ΔP`.
pub const SQUEEZE_SHARE_TOLERANCE: f64 = 1e-3;

/// The state the stresses alone decide (docs/model.md §8.1): with the squeeze's peak contact
/// pressure `squeeze_peak` \[Pa\], the energisation factor k_e and the pressure difference ΔP
/// \[Pa\], the seal is open when `p_sq ≤ max(1 − k_e, τ) ΔP` — lifted off when 1 − k_e ≥ τ (the
/// fluid pressure reaches the contact pressure), held by the pressure alone otherwise;
/// `None` when the squeeze holds it (the leak then decides between sealed and leaking).
pub fn opening(
    squeeze_peak: f64,
    energisation: f64,
    pressure_difference: f64,
) -> Option<SealState> {
    if pressure_difference <= 0.0 {
        return None;
    }
    let share = (1.0 - energisation).max(SQUEEZE_SHARE_TOLERANCE);
    (squeeze_peak <= share * pressure_difference).then_some(
        if 1.0 - energisation >= SQUEEZE_SHARE_TOLERANCE {
            SealState::LiftOff
        } else {
            SealState::PressureHeld
        },
    )
}

/// The squeeze's peak contact pressure at the threshold of lift-off, `(1 − k_e) ΔP` \[Pa\]
/// (k_e < 1): a lifted-off seal's leak is reported as the leak of the same seal loaded just to
/// this threshold — what it leaks as it opens, a lower bound of an open seal's leak that does
/// not depend on how far below the threshold the load is, so less load never leaks less.
pub fn lift_off_threshold(energisation: f64, pressure_difference: f64) -> f64 {
    (1.0 - energisation).max(0.0) * pressure_difference
}

/// Evaluates the leak of one surface at many pressures through one [`ContactPath`].
#[derive(Debug, Clone)]
pub struct StaticSolver {
    problem: StaticProblem,
    path: ContactPath,
    /// [`ContactPath::molecular_cut`] for the problem's fluid.
    cut: f64,
}

/// The contact-and-gap model of one surface at the chosen [`Fidelity`], prepared once (a table
/// where the level has one) and re-used for every pressure and time step.
#[derive(Debug, Clone)]
pub enum ContactPath {
    RuleOfThumb(PerssonContact),
    /// The exact path, and a cache of its nodes for the interface integrals (which ask for the
    /// conductance thousands of times per state): [`TableSettings::exact_cache`].
    Exact(ContactTable),
    Table(ContactTable),
    EffectiveMedium(Box<EffectiveMediumTable>),
    Numerical {
        table: NumericalTable,
        /// The critical-junction table of the same spectrum (ζc, λc of the channels).
        junctions: Box<ContactTable>,
        /// A rarefied gas: the mean free path the table's cells were rarefied at (p̄ and the
        /// installation temperature; `None`: a liquid, or built without the gas).
        gas: Option<crate::gas::Rarefied>,
    },
}

/// How the levels that have one build their table, where the numerical level gets its
/// surfaces, and the fluid's molecule the averaging levels build with.
#[derive(Debug, Clone)]
pub struct PathOptions<'a> {
    /// Spacing of the critical-junction table (the effective-medium table uses ⅔ of its
    /// points per decade, over [`TableSettings::effective_medium`]'s range).
    pub table: TableSettings,
    /// Grid, band, realisations and seed of the numerical level.
    pub numerical: NumericalSettings,
    /// A measured surface: the numerical level's single realisation (the analytic levels use
    /// its estimated spectrum).
    pub height_map: Option<&'a HeightMap>,
    /// Reduced pressures P0/E* at which the numerical level solves (a pressure sweep: exactly
    /// the pressures asked for); `None`: its default nodes, for a life run.
    pub numerical_nodes: Option<Vec<f64>>,
    /// The size of one molecule of the fluid \[m\] ([`Fluid::molecular_size`]; default a
    /// liquid's, [`crate::fluid::liquid_molecular_size`]): the effective-medium and numerical
    /// levels tabulate with every local gap no wider conducting nothing (docs/model.md §3.3,
    /// §3.5, §8.1). The critical-junction levels apply the same rule when evaluated
    /// ([`ContactPath::conductance`]), whatever this is.
    pub molecular_size: f64,
}

impl Default for PathOptions<'_> {
    fn default() -> Self {
        PathOptions {
            table: TableSettings::default(),
            numerical: NumericalSettings::default(),
            height_map: None,
            numerical_nodes: None,
            molecular_size: crate::fluid::liquid_molecular_size(),
        }
    }
}

impl ContactPath {
    /// Builds the path for `spectrum` with the default options (critical-junction table ≈ 3 ms;
    /// effective-medium table ≈ 0.5 s; the numerical level: an ensemble at 10 pressures,
    /// ≈ 10–30 s), for a liquid. See [`Self::build`].
    pub fn new(spectrum: &Spectrum, settings: ContactSettings, fidelity: Fidelity) -> Self {
        Self::build(
            spectrum,
            settings,
            fidelity,
            &PathOptions::default(),
            &mut |_, _| {},
        )
    }

    /// [`Self::new`] for `fluid`: the averaging levels tabulate with its molecule
    /// ([`PathOptions::molecular_size`]).
    pub fn for_fluid(
        spectrum: &Spectrum,
        settings: ContactSettings,
        fidelity: Fidelity,
        fluid: &Fluid,
    ) -> Self {
        let options = PathOptions {
            molecular_size: fluid.molecular_size(),
            ..PathOptions::default()
        };
        Self::build(spectrum, settings, fidelity, &options, &mut |_, _| {})
    }

    /// Builds the path; `progress(done, total)` reports the numerical level's realisations.
    ///
    /// The numerical level cannot fail on validated input except by a solver not converging
    /// within its (generous) iteration limit; should a node fail, it is left out of the table
    /// and reported by [`Self::assess`] (a warning for the caller to print), never
    /// silently.
    pub fn build(
        spectrum: &Spectrum,
        settings: ContactSettings,
        fidelity: Fidelity,
        options: &PathOptions<'_>,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Self {
        let exact = PerssonContact::new(spectrum.clone(), settings);
        let table = options.table;
        match fidelity {
            Fidelity::RuleOfThumb => ContactPath::RuleOfThumb(exact),
            Fidelity::Exact => {
                ContactPath::Exact(ContactTable::build(exact, TableSettings::exact_cache()))
            }
            Fidelity::Table => ContactPath::Table(ContactTable::build(exact, table)),
            Fidelity::EffectiveMedium => {
                let em_table = TableSettings {
                    points_per_decade: table.points_per_decade * (2.0 / 3.0),
                    ..TableSettings::effective_medium()
                };
                ContactPath::EffectiveMedium(Box::new(EffectiveMediumTable::build(
                    exact,
                    em_table,
                    EffectiveMediumSettings {
                        molecular_size: options.molecular_size,
                        ..EffectiveMediumSettings::default()
                    },
                )))
            }
            Fidelity::Numerical => {
                let s_seal = exact.sealing_reduced_pressure();
                let mut settings = options.numerical.clone();
                settings.flow.molecular_size = options.molecular_size;
                let numerical = NumericalTable::for_surface(
                    spectrum,
                    options.height_map,
                    options.numerical_nodes.as_deref(),
                    s_seal,
                    &settings,
                    progress,
                );
                ContactPath::Numerical {
                    table: numerical,
                    junctions: Box::new(ContactTable::build(exact, table)),
                    gas: options.numerical.flow.gas,
                }
            }
        }
    }

    /// Caveats of the path itself (not of one pressure), recorded into `out`: the numerical
    /// level resolves only a band of a synthetic spectrum, or a node of its table failed
    /// (docs/model.md §9.10).
    pub fn assess(&self, options: &PathOptions<'_>, out: &mut Findings) {
        let ContactPath::Numerical {
            table, junctions, ..
        } = self
        else {
            return;
        };
        let sp = junctions.exact().spectrum();
        if options.height_map.is_none() {
            validity::band_limited(options.numerical.band, sp.q1() / sp.q0(), out);
        }
        for (s, e) in table.failures() {
            validity::numerical_failure(*s, e.to_string(), out);
        }
    }

    /// The level this path evaluates.
    pub fn fidelity(&self) -> Fidelity {
        match self {
            ContactPath::RuleOfThumb(_) => Fidelity::RuleOfThumb,
            ContactPath::Exact(_) => Fidelity::Exact,
            ContactPath::Table(_) => Fidelity::Table,
            ContactPath::EffectiveMedium(_) => Fidelity::EffectiveMedium,
            ContactPath::Numerical { .. } => Fidelity::Numerical,
        }
    }

    /// The exact contact theory behind the path.
    pub fn exact(&self) -> &PerssonContact {
        match self {
            ContactPath::RuleOfThumb(c) => c,
            ContactPath::Table(t) | ContactPath::Exact(t) => t.exact(),
            ContactPath::EffectiveMedium(t) => t.junctions().exact(),
            ContactPath::Numerical { junctions, .. } => junctions.exact(),
        }
    }

    /// The interface at full magnification at reduced pressure `s = P0/E*`: the relative
    /// contact area A/A0 and the mean gap ū. The analytic levels all give Persson's theory by
    /// quadrature ([`PerssonContact::full_contact`]: A(q1/q0)/A0 and ū(ζ = 1)); the numerical
    /// level the ensemble means of the boundary-element solutions at a node of its table
    /// ([`NumericalTable::full_contact`]: a pressure sweep solves at exactly its pressures),
    /// `None` between nodes.
    pub fn full_contact(&self, s: f64) -> Option<FullContact> {
        match self {
            ContactPath::Numerical { table, .. } => table.full_contact(s),
            _ => Some(self.exact().full_contact(s)),
        }
    }

    /// The conducting channel at reduced pressure `s = P0/E*`:
    /// * critical junction (exact or table): u_c = u1(ζc) (PY08 §2);
    /// * rule of thumb: the same ζc, λc with u_c = ū_c = h_rms(ζc);
    /// * effective medium: `u_c` is the effective gap `u_eff = (12 η σ_eff)^{1/3}` and the other
    ///   fields are the critical junction's at the same pressure (at the 2-D threshold ½ when
    ///   the critical junction is already sealed); `Sealed` exactly when the contact fraction
    ///   `A(q1/q0)/A0` ≥ ½.
    pub fn critical_junction(&self, s: f64) -> Junction {
        match self {
            ContactPath::RuleOfThumb(c) => c.rule_of_thumb_junction(s),
            ContactPath::Exact(t) => t.exact().critical_junction(s),
            ContactPath::Table(t) => t.critical_junction(s),
            ContactPath::EffectiveMedium(t) => {
                Self::gap_channel(t.effective_gap(s), t.junctions(), s, 0.5)
            }
            ContactPath::Numerical {
                table, junctions, ..
            } => {
                let a_c = junctions.exact().settings().percolation_threshold;
                Self::gap_channel(table.effective_gap(s), junctions, s, a_c.max(0.5))
            }
        }
    }

    /// The critical junction of Persson's theory (`u_c = u1(ζc)`, PY08 §2) at `s`, whatever
    /// the level: the level's own for the critical-junction levels (table or exact), the
    /// critical-junction table the effective-medium and numerical levels carry, the exact path
    /// for the rule of thumb (whose own u_c is h_rms(ζc)). The reciprocating-seal theory
    /// (PY08 §8, the `dynamic` module) is built on this junction.
    pub fn persson_junction(&self, s: f64) -> Junction {
        match self {
            ContactPath::RuleOfThumb(c) => c.critical_junction(s),
            ContactPath::Exact(t) => t.exact().critical_junction(s),
            ContactPath::Table(t) => t.critical_junction(s),
            ContactPath::EffectiveMedium(t) => t.junctions().critical_junction(s),
            ContactPath::Numerical { junctions, .. } => junctions.critical_junction(s),
        }
    }

    /// A channel of effective gap `u_eff` with the critical junction's ζc and λc at `s` (at the
    /// percolation `threshold` when the critical junction is already sealed there).
    fn gap_channel(u_eff: f64, junctions: &ContactTable, s: f64, threshold: f64) -> Junction {
        if u_eff.is_nan() || u_eff <= 0.0 {
            return Junction::Sealed;
        }
        let reference = match junctions.critical_junction(s) {
            Junction::Leaking(j) => Some(j),
            Junction::Sealed => junctions
                .exact()
                .critical_junction_at_threshold(s, threshold)
                .leaking()
                .copied(),
        };
        match reference {
            Some(j) => Junction::Leaking(CriticalJunction { u_c: u_eff, ..j }),
            // within rounding of the threshold (or beyond every threshold): ζc and λc are
            // not defined; the gap itself is reported through the conductance only
            None => Junction::Leaking(CriticalJunction {
                u_c: u_eff,
                ..Self::last_channel(junctions)
            }),
        }
    }

    /// The channel at the shortest wavelength of the spectrum (ζc = q1/q0), for an effective
    /// gap that outlives every critical junction.
    fn last_channel(junctions: &ContactTable) -> CriticalJunction {
        let sp = junctions.exact().spectrum();
        CriticalJunction {
            zeta_c: sp.q1() / sp.q0(),
            lambda_c: 2.0 * std::f64::consts::PI / sp.q1(),
            u_c: 0.0,
            ubar_c: 0.0,
            hrms_c: 0.0,
        }
    }

    /// Conductance per unit width of the interface at `s` \[m³/(Pa·s)\]: `α u_c³/(12η)` for the
    /// critical-junction levels (PY08 eq. 1), `σ_eff = u_eff³/(12η)` for the effective medium
    /// (α does not enter); 0 when sealed, and 0 where the level's gap (u_c, u_eff) is no wider
    /// than `molecular_size` \[m\], one molecule of the fluid ([`Fluid::molecular_size`],
    /// [`crate::fluid::passes_molecule`]; docs/model.md §3.6, §8.1). Since the gap is a function
    /// of `s` alone, the cut is one reduced pressure for a surface and a fluid, and every strip of
    /// the interface (§3.6) meets it where the outlet's junction does.
    pub fn conductance(
        &self,
        s: f64,
        shape_factor: f64,
        viscosity: f64,
        molecular_size: f64,
    ) -> f64 {
        // the exact level through its cache of nodes (interpolation error < 1e-7, far below the
        // table's 3.2e-4; docs/model.md §4)
        if let ContactPath::Table(t) | ContactPath::Exact(t) = self {
            return t
                .critical_gap(s)
                .filter(|&u_c| passes_molecule(u_c, molecular_size))
                .map_or(0.0, |u_c| {
                    junction_conductance(u_c, shape_factor, viscosity)
                });
        }
        if let ContactPath::EffectiveMedium(t) = self {
            // u_eff alone: what `channel_conductance` of its junction gives, bit for bit, without
            // the reported junction's ζc and λc (a table look-up of the critical junction level
            // per call, most of an interface solve's cost)
            let u = t.effective_gap(s);
            return if u > 0.0 && passes_molecule(u, molecular_size) {
                junction_conductance(u, 1.0, viscosity)
            } else {
                0.0
            };
        }
        self.channel_conductance(
            &self.critical_junction(s),
            shape_factor,
            viscosity,
            molecular_size,
        )
    }

    /// [`Self::conductance`] of a gas with the mean free path of the local pressure (`gas`;
    /// `None`: a liquid, or the continuum law), docs/model.md §3.10 — a gap no wider than a
    /// molecule (`molecular_size`, the gas's diameter) conducts nothing, at every level as in
    /// [`Self::conductance`]:
    /// * critical-junction levels: `α u_c³ f(λ/u_c, λc/u_c)/(12η)`, f the slit rarefaction
    ///   factor ([`crate::gas::slit_rarefaction`]) at the critical constriction's own Knudsen
    ///   number, the constriction λc wide;
    /// * effective medium: Bruggeman over the separations, each gap u conducting
    ///   `u³ f(λ/u)/(12η)` ([`EffectiveMediumTable::rarefied_cubed_gap`]);
    /// * numerical: built for the gas (`PathOptions::numerical.flow.gas`), every cell rarefied
    ///   at the table's λ̄ (p̄, installation temperature), times `f(λ/u_c)/f(λ̄/u_c)` of the
    ///   critical constriction for the local pressure; built without it, the effective channel
    ///   `f(λ/u_eff, λc/u_eff)`.
    pub fn gas_conductance(
        &self,
        s: f64,
        shape_factor: f64,
        viscosity: f64,
        gas: Option<crate::gas::Rarefied>,
        molecular_size: f64,
    ) -> f64 {
        let Some(l) = gas else {
            return self.conductance(s, shape_factor, viscosity, molecular_size);
        };
        let alpha = match self {
            ContactPath::EffectiveMedium(t) => {
                // the level's gap (the reported u_eff) below a molecule: as every level
                if !passes_molecule(t.effective_gap(s), molecular_size) {
                    return 0.0;
                }
                return t.rarefied_cubed_gap(s, l) / (12.0 * viscosity);
            }
            ContactPath::Numerical {
                table,
                junctions,
                gas: Some(built),
            } => {
                // cell by cell at the table's mean free path; the local pressure's change of it
                // carried by the critical constriction's own factor
                let u = table.effective_gap(s);
                if !passes_molecule(u, molecular_size) {
                    return 0.0;
                }
                let ratio = match junctions.critical_junction(s) {
                    Junction::Leaking(j) if j.u_c > l.molecular_diameter => {
                        l.factor(j.u_c, j.lambda_c) / built.factor(j.u_c, j.lambda_c)
                    }
                    _ => 1.0,
                };
                return junction_conductance(u, 1.0, viscosity) * ratio;
            }
            ContactPath::Numerical { .. } => 1.0,
            _ => shape_factor,
        };
        // the channel: u_c (u_eff for the numerical level) and its lateral extent λc; the exact
        // level's u_c from its cache of nodes (ζc and λc exact)
        let junction = match self {
            ContactPath::Exact(t) => t.critical_junction(s),
            _ => self.critical_junction(s),
        };
        match junction {
            Junction::Leaking(j) if j.u_c > 0.0 && passes_molecule(j.u_c, molecular_size) => {
                junction_conductance(j.u_c, alpha, viscosity) * l.factor(j.u_c, j.lambda_c)
            }
            _ => 0.0,
        }
    }

    /// [`Self::conductance`] of a channel this path has already evaluated.
    pub fn channel_conductance(
        &self,
        junction: &Junction,
        shape_factor: f64,
        viscosity: f64,
        molecular_size: f64,
    ) -> f64 {
        let alpha = match self {
            ContactPath::EffectiveMedium(_) | ContactPath::Numerical { .. } => 1.0,
            _ => shape_factor,
        };
        match junction {
            Junction::Leaking(j) if passes_molecule(j.u_c, molecular_size) => {
                junction_conductance(j.u_c, alpha, viscosity)
            }
            _ => 0.0,
        }
    }

    /// The reduced pressure `s_m = e/E*` at and above which the level's gap (u_c; u_eff) is no
    /// wider than `molecular_size` \[m\], so that [`Self::conductance`] is 0 (docs/model.md
    /// §3.6, §8.1). The gap falls with the pressure, so the cut is one reduced pressure for a
    /// surface and a fluid: found once, to 1e-10, by Illinois in logit(s/s_half) between 1e-6
    /// of the effective medium's threshold s_half and 1e-12 short of it, otherwise by bisection
    /// in ln s between 1e-30 and 1e3 — and handed to the uniform interface's quadrature as its
    /// ceiling
    /// ([`crate::interface::InterfaceSettings::ceiling`]), which then integrates the smooth
    /// part of σ(e) only. `∞` if the gap is wider at 1e3 (no surface seals that late); 1e-30 if
    /// it is no wider even there.
    pub fn molecular_cut(&self, molecular_size: f64) -> f64 {
        let passes = |s: f64| {
            let gap = match self {
                ContactPath::Table(t) => t.critical_gap(s),
                ContactPath::EffectiveMedium(t) => Some(t.effective_gap(s)),
                ContactPath::Numerical { table, .. } => Some(table.effective_gap(s)),
                _ => self.critical_junction(s).leaking().map(|j| j.u_c),
            };
            gap.is_some_and(|u| passes_molecule(u, molecular_size))
        };
        // the effective medium: ln u_eff is smooth and nearly linear in logit(s/s_half) (slope
        // → −1 at the threshold, docs/model.md §4), so Illinois finds u_eff = m in a few lazy
        // table nodes where bisection in ln s built dozens; the cut is the bracket's upper end,
        // where the gap no longer passes. u_eff is 0 at and above s_half and the power law keeps
        // it positive below, so f is finite on the bracket.
        if let ContactPath::EffectiveMedium(t) = self {
            use crate::contact::table::{logistic, logit};
            let s_half = t.sealing_reduced_pressure();
            let ln_m = molecular_size.ln();
            let f = |v: f64| {
                ln_m - t
                    .effective_gap(s_half * logistic(v))
                    .max(f64::MIN_POSITIVE)
                    .ln()
            };
            let (lo, hi) = (logit(1e-6), logit(1.0 - 1e-12));
            let (f_lo, f_hi) = (f(lo), f(hi));
            if f_lo < 0.0 {
                if f_hi < 0.0 {
                    // wider than a molecule to within 1e-12 of its threshold
                    return s_half;
                }
                let (_, hi) = crate::math::roots::illinois(f, (lo, f_lo), (hi, f_hi), 1e-10);
                return s_half * logistic(hi);
            }
        }
        let (lo, hi) = (1e-30f64.ln(), 1e3f64.ln());
        if passes(hi.exp()) {
            return f64::INFINITY;
        }
        if !passes(lo.exp()) {
            return lo.exp();
        }
        let (_, hi) = crate::math::roots::bisect(
            lo,
            hi,
            usize::MAX,
            // 1e-10 of s: the integral misses or adds σ(e_m) e_m 1e-10 at most
            |a, b| b - a <= 1e-10,
            |x| passes(x.exp()),
        );
        hi.exp()
    }

    /// The state of an interface that conducts nothing under the fluid pressure (docs/model.md
    /// §3.6, §8.1), from its least-loaded strip — the one the fluid pressure relieves most, at
    /// reduced asperity pressure `s_least` (`(P0 − ΔP)/E*` for a uniform contact, the peak less
    /// the whole ΔP for a profile): [`SealState::BelowMolecule`] when a channel percolates there
    /// (every percolating strip's gap is then no wider than a molecule: the molecule is what
    /// seals), [`SealState::Sealed`] when none does (percolation falls with the pressure, so
    /// no strip percolates). The effective medium counts its sub-molecular gaps as contact, so
    /// its channel percolates where the contact fraction alone is below the threshold ½; the
    /// numerical level's cells are cut when its table is built, and it reads `Sealed` unless its
    /// effective gap is positive.
    pub fn sealed_state(&self, s_least: f64) -> SealState {
        let s = s_least.max(f64::MIN_POSITIVE);
        let percolates = match self {
            ContactPath::EffectiveMedium(t) => {
                let exact = t.junctions().exact();
                let sp = exact.spectrum();
                exact.area_fraction(sp.q1() / sp.q0(), s) < 0.5
            }
            _ => self.critical_junction(s).leaking().is_some(),
        };
        if percolates {
            SealState::BelowMolecule
        } else {
            SealState::Sealed
        }
    }
}

impl StaticSolver {
    /// Prepares the solver (builds the level's table, if it has one).
    pub fn new(problem: StaticProblem, fidelity: Fidelity) -> Self {
        let path =
            ContactPath::for_fluid(&problem.spectrum, problem.contact, fidelity, &problem.fluid);
        Self::with_path(problem, path)
    }

    /// The path the solver evaluates.
    pub fn path(&self) -> &ContactPath {
        &self.path
    }

    /// A solver on an already prepared path (built for the same spectrum and contact settings).
    pub fn with_path(problem: StaticProblem, path: ContactPath) -> Self {
        let cut = path.molecular_cut(problem.fluid.molecular_size());
        StaticSolver { problem, path, cut }
    }

    pub fn problem(&self) -> &StaticProblem {
        &self.problem
    }

    /// The junction and leak rate at nominal pressure `p0` \[Pa\] (> 0) with the fluid pressure
    /// inside the interface (docs/model.md §3.6): `Q̇ = (L_y/L_x) σ_eff ΔP`
    /// ([`Fluid::leak_rate`]), `σ_eff = (1/ΔP) ∫_{P0−ΔP}^{P0} σ(e) de` with σ the path's
    /// [`ContactPath::conductance`] ([`interface::uniform`]). Lifted off when P0 ≤ ΔP
    /// ([`opening`] with k_e = 0), with the leak at the threshold of lift-off, P0 = ΔP
    /// ([`interface::uniform_onset`], a lower bound that does not grow with P0). The junction is
    /// the outlet's (asperity pressure P0), where the asperities carry most. Every strip whose
    /// critical gap is no wider than a molecule of the fluid conducts nothing
    /// ([`ContactPath::conductance`]); an interface that conducts nowhere is sealed, by the
    /// molecule ([`SealState::BelowMolecule`]) when a channel percolates in its least-loaded
    /// strip ([`ContactPath::sealed_state`]).
    pub fn evaluate(&self, p0: f64) -> LeakPoint {
        let pb = &self.problem;
        let dp = pb.fluid.pressure_difference;
        let e_star = pb.material.effective_modulus();
        let junction = self.path.critical_junction(p0 / e_star);
        let molecule = pb.fluid.molecular_size();
        // a gas: σ(e) weighed by the local density (P_b + p_f)/p̄, p_f = top − e, each
        // constriction rarefied at the local pressure (docs/model.md §3.9, §3.10); 1 for a liquid
        let sigma = |top: f64| {
            move |e: f64| {
                self.path.gas_conductance(
                    e / e_star,
                    pb.shape_factor,
                    pb.fluid.viscosity,
                    pb.fluid.free_path_at(top - e),
                    molecule,
                ) * pb.fluid.density_weight(top - e)
            }
        };
        // σ is 0 at and above the molecular cut: the quadratures end there
        let ceiling = self.cut * e_star;
        let (leak_rate, state) = if opening(p0, 0.0, dp).is_some() {
            let top = dp;
            let conduction = interface::uniform_onset(
                &sigma(top),
                top,
                dp,
                &InterfaceSettings {
                    ceiling,
                    ..InterfaceSettings::default()
                },
            );
            (
                pb.fluid.leak_rate(pb.seal.geometry(), conduction),
                SealState::LiftOff,
            )
        } else {
            match interface::uniform(
                &sigma(p0),
                p0,
                dp,
                &InterfaceSettings {
                    outlet_breaks: pb.fluid.outlet_breaks(),
                    ceiling,
                    ..InterfaceSettings::default()
                },
            ) {
                InterfaceFlow::Conducting(conduction) => (
                    pb.fluid.leak_rate(pb.seal.geometry(), conduction),
                    SealState::Leaking,
                ),
                InterfaceFlow::Sealed => (0.0, self.path.sealed_state((p0 - dp) / e_star)),
                InterfaceFlow::LiftOff => (0.0, SealState::LiftOff),
            }
        };
        LeakPoint {
            nominal_pressure: p0,
            junction,
            leak_rate,
            state,
        }
    }

    /// Records the validity findings of one result into `out` (docs/model.md §9.1–§9.4).
    pub fn assess(&self, point: &LeakPoint, out: &mut Findings) {
        let sp = &self.problem.spectrum;
        validity::contact(
            &ContactState {
                nominal_pressure: point.nominal_pressure,
                pressure_difference: self.problem.fluid.pressure_difference,
                // lifted off, the contact is open: no contact limit applies (the verdict says lift_off)
                junction: if point.state == SealState::LiftOff {
                    &Junction::Sealed
                } else {
                    &point.junction
                },
                cutoff: sp.q1() / sp.q0(),
                lifted_off: point.state == SealState::LiftOff,
            },
            At::Pressure(point.nominal_pressure),
            out,
        );
        if let (Junction::Leaking(j), false) = (&point.junction, point.state == SealState::LiftOff)
            && let Some(kn) = self.problem.fluid.knudsen(j.u_c)
        {
            validity::knudsen(
                kn,
                self.problem.fluid.mean_free_path().is_some(),
                At::Pressure(point.nominal_pressure),
                out,
            );
        }
    }
}
