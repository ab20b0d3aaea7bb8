//! Leak rate of a static seal through its critical constriction (PY08 §2, eqs. 1–3).

use crate::contact::{
    ContactSettings, ContactTable, CriticalJunction, EffectiveMedium, EffectiveMediumSettings,
    Elastic, Junction, PerssonContact, TableSettings,
};
use crate::surface::Spectrum;
use std::fmt;

/// A Newtonian, incompressible fluid and the pressure it pushes across the seal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fluid {
    /// Dynamic viscosity η [Pa·s].
    pub viscosity: f64,
    /// ΔP = P_a − P_b across the seal [Pa] (≥ 0).
    pub pressure_difference: f64,
}

/// A flat seal: uniform nominal pressure over a rectangle `width × length` (PY08 Fig. 2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatSeal {
    /// Nominal squeezing pressure P0 [Pa].
    pub nominal_pressure: f64,
    /// L_x, the width along the flow [m].
    pub width: f64,
    /// L_y, the length across the flow [m].
    pub length: f64,
}

/// Which level of the fidelity ladder (DESIGN §4) evaluates the static leak.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Fidelity {
    /// Quadrature at every pressure.
    Exact,
    /// Interpolation in a [`ContactTable`] built once per surface (falls back to the exact
    /// path outside the table's range).
    #[default]
    Table,
    /// Bruggeman's 2-D effective medium over the separation distribution P(u) (DESIGN §3.3,
    /// [`crate::contact::effective_medium`]). Static leak ([`StaticSolver`]) only: wherever a
    /// critical junction is needed ([`ContactPath`], the life simulation) it uses the table.
    EffectiveMedium,
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

/// ΔP/P0 above which the fluid pressure is no longer small against the contact pressure
/// (PY08 §2 assumes P0 ≫ ΔP): a validity warning, for the static leak and the life run alike.
pub const MAX_PRESSURE_RATIO: f64 = 0.1;

/// Constriction height below which continuum flow is not a valid picture [m] (1 nm).
pub const MIN_CONTINUUM_GAP: f64 = 1e-9;

/// u_c/λ_c above which the thin-gap (lubrication) flow of PY08 eq. 1 fails.
pub const MAX_ASPECT_RATIO: f64 = 0.1;

/// One evaluated pressure point.
///
/// With [`Fidelity::EffectiveMedium`], `junction.u_c` is the effective gap
/// `u_eff = (12 η σ_eff)^{1/3}` and the other junction fields are those of the critical
/// junction at the same pressure (at the 2-D threshold 1/2 instead of a_c when the critical
/// junction is already sealed); `Sealed` exactly when the contact fraction `A(q1/q0)/A0` ≥ 1/2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LeakPoint {
    /// Nominal squeezing pressure P0 [Pa].
    pub nominal_pressure: f64,
    pub junction: Junction,
    /// Volume leak rate Q̇ [m³/s]; exactly 0 when sealed.
    pub leak_rate: f64,
}

/// A physics caveat about a result: the model was used outside the range where it holds.
#[derive(Debug, Clone, PartialEq)]
pub enum Warning {
    /// ΔP/P0 is not small: the fluid pressure deforms the contact (PY08 §2 assumes P0 ≫ ΔP).
    PressureRatio { nominal_pressure: f64, ratio: f64 },
    /// u_c/λ_c is not small: the lubrication (thin-gap) approximation behind eq. 1 fails.
    AspectRatio { nominal_pressure: f64, ratio: f64 },
    /// u_c is below a molecular size (1 nm): continuum flow is not a valid picture.
    MolecularGap { nominal_pressure: f64, u_c: f64 },
    /// ζc is within a factor 2 of q1/q0: the result depends on the (often uncertain) cut-off.
    NearCutoff {
        nominal_pressure: f64,
        zeta_c: f64,
        zeta_1: f64,
    },
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Warning::PressureRatio {
                nominal_pressure,
                ratio,
            } => write!(
                f,
                "at P0 = {nominal_pressure:.4e} Pa, ΔP/P0 = {ratio:.3}: the theory assumes P0 ≫ ΔP \
                 (the fluid pressure opens the interface; the leak rate is underestimated)"
            ),
            Warning::AspectRatio {
                nominal_pressure,
                ratio,
            } => write!(
                f,
                "at P0 = {nominal_pressure:.4e} Pa, u_c/λ_c = {ratio:.3}: the thin-gap flow assumption \
                 u_c ≪ λ_c does not hold"
            ),
            Warning::MolecularGap {
                nominal_pressure,
                u_c,
            } => write!(
                f,
                "at P0 = {nominal_pressure:.4e} Pa, u_c = {u_c:.3e} m is below 1 nm: continuum flow is \
                 not valid there; read the leak rate as 'effectively zero'"
            ),
            Warning::NearCutoff {
                nominal_pressure,
                zeta_c,
                zeta_1,
            } => write!(
                f,
                "at P0 = {nominal_pressure:.4e} Pa, ζc = {zeta_c:.4e} is within a factor 2 of q1/q0 = \
                 {zeta_1:.4e}: the result depends on the short-wavelength cut-off q1"
            ),
        }
    }
}

/// Leak rate through the critical constrictions of a flat seal (PY08 eqs. 1–3):
/// `Q̇ = (L_y/L_x) α u_c³ ΔP / (12 η)` [m³/s].
pub fn leak_rate(u_c: f64, fluid: &Fluid, width: f64, length: f64, shape_factor: f64) -> f64 {
    (length / width) * shape_factor * u_c.powi(3) * fluid.pressure_difference
        / (12.0 * fluid.viscosity)
}

/// Evaluates the critical junction of one surface at many pressures, by the exact path or a
/// contact table built once (and re-used for every pressure).
#[derive(Debug, Clone)]
pub struct StaticSolver {
    problem: StaticProblem,
    path: ContactPath,
    fidelity: Fidelity,
}

/// The critical junction of one surface by the chosen [`Fidelity`]: the exact path, or a
/// contact table built once and re-used for every pressure and time step.
#[derive(Debug, Clone)]
pub enum ContactPath {
    Exact(PerssonContact),
    Table(ContactTable),
}

impl ContactPath {
    /// Builds the path for `spectrum` (with the table: ≈ 3 ms).
    pub fn new(spectrum: &Spectrum, settings: ContactSettings, fidelity: Fidelity) -> Self {
        let exact = PerssonContact::new(spectrum.clone(), settings);
        match fidelity {
            Fidelity::Exact => ContactPath::Exact(exact),
            // the effective medium has no critical junction of its own: use the table
            Fidelity::Table | Fidelity::EffectiveMedium => {
                ContactPath::Table(ContactTable::build(exact, TableSettings::default()))
            }
        }
    }

    /// The exact contact theory behind the path.
    pub fn exact(&self) -> &PerssonContact {
        match self {
            ContactPath::Exact(c) => c,
            ContactPath::Table(t) => t.exact(),
        }
    }

    /// The critical junction at reduced pressure `s = P0/E*`.
    pub fn critical_junction(&self, s: f64) -> Junction {
        match self {
            ContactPath::Exact(c) => c.critical_junction(s),
            ContactPath::Table(t) => t.critical_junction(s),
        }
    }
}

impl StaticSolver {
    /// Prepares the solver; with [`Fidelity::Table`] this builds the contact table.
    pub fn new(problem: StaticProblem, fidelity: Fidelity) -> Self {
        let path = ContactPath::new(&problem.spectrum, problem.contact, fidelity);
        StaticSolver {
            problem,
            path,
            fidelity,
        }
    }

    pub fn problem(&self) -> &StaticProblem {
        &self.problem
    }

    /// The junction and leak rate at nominal pressure `p0` [Pa] (> 0).
    pub fn evaluate(&self, p0: f64) -> LeakPoint {
        let s = p0 / self.problem.material.effective_modulus();
        if self.fidelity == Fidelity::EffectiveMedium {
            return self.evaluate_effective_medium(p0, s);
        }
        let junction = self.path.critical_junction(s);
        let pb = &self.problem;
        let leak_rate = match junction {
            Junction::Leaking(j) => leak_rate(
                j.u_c,
                &pb.fluid,
                pb.seal.width,
                pb.seal.length,
                pb.shape_factor,
            ),
            Junction::Sealed => 0.0,
        };
        LeakPoint {
            nominal_pressure: p0,
            junction,
            leak_rate,
        }
    }

    /// The effective-medium point (DESIGN §3.3): `Q̇ = (L_y/L_x) σ_eff ΔP`, σ_eff by Bruggeman
    /// over P(u) (the shape factor α of the critical junction does not enter).
    fn evaluate_effective_medium(&self, p0: f64, s: f64) -> LeakPoint {
        let pb = &self.problem;
        let em = EffectiveMedium::persson(self.path.exact(), s, EffectiveMediumSettings::default());
        let sealed = LeakPoint {
            nominal_pressure: p0,
            junction: Junction::Sealed,
            leak_rate: 0.0,
        };
        if em.sealed() {
            return sealed;
        }
        let u_eff = em.effective_gap();
        let reference = match self.path.critical_junction(s) {
            Junction::Leaking(j) => Some(j),
            Junction::Sealed => self
                .path
                .exact()
                .critical_junction_at_threshold(s, 0.5)
                .leaking()
                .copied(),
        };
        let junction = match reference {
            Some(j) => CriticalJunction { u_c: u_eff, ..j },
            // within rounding of the threshold: the channel has no height in double precision
            None => return sealed,
        };
        let leak_rate = (pb.seal.length / pb.seal.width)
            * em.conductance(pb.fluid.viscosity)
            * pb.fluid.pressure_difference;
        LeakPoint {
            nominal_pressure: p0,
            junction: Junction::Leaking(junction),
            leak_rate,
        }
    }

    /// The validity caveats of one result (empty when the model holds).
    pub fn warnings(&self, point: &LeakPoint) -> Vec<Warning> {
        let p0 = point.nominal_pressure;
        let mut w = Vec::new();
        let ratio = self.problem.fluid.pressure_difference / p0;
        if ratio > MAX_PRESSURE_RATIO {
            w.push(Warning::PressureRatio {
                nominal_pressure: p0,
                ratio,
            });
        }
        if let Junction::Leaking(j) = point.junction {
            let aspect = j.u_c / j.lambda_c;
            if aspect > MAX_ASPECT_RATIO {
                w.push(Warning::AspectRatio {
                    nominal_pressure: p0,
                    ratio: aspect,
                });
            }
            if j.u_c < MIN_CONTINUUM_GAP {
                w.push(Warning::MolecularGap {
                    nominal_pressure: p0,
                    u_c: j.u_c,
                });
            }
            let zeta_1 = self.problem.spectrum.q1() / self.problem.spectrum.q0();
            if j.zeta_c > 0.5 * zeta_1 {
                w.push(Warning::NearCutoff {
                    nominal_pressure: p0,
                    zeta_c: j.zeta_c,
                    zeta_1,
                });
            }
        }
        w
    }
}
