//! The fluid and the leak law: how a fluid driven by the pressures at the seal's two ends flows
//! through the interface's conductance (docs/model.md §3.1–§3.2).
//!
//! This is the one place where a conductance becomes a leak rate. Every path of the simulator —
//! the static leak of a flat seal, the strips in series of a life run, the numerical reference,
//! the reciprocating seal's pressure-driven part and the clogged interface — hands the fluid a
//! [`FlowGeometry`] and a [`Conduction`] and gets the leak rate back from [`Fluid::leak_rate`].
//! A compressible gas will plug in here: it is the fluid that decides how the boundary
//! pressures drive the flow (for an incompressible liquid, linearly in ΔP).

/// A Newtonian, incompressible fluid and the pressure it pushes across the seal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fluid {
    /// Dynamic viscosity η \[Pa·s\].
    pub viscosity: f64,
    /// ΔP = P_a − P_b across the seal \[Pa\] (≥ 0).
    pub pressure_difference: f64,
}

/// The seal's extent along and across the flow. Built with named fields only, so that the two
/// lengths cannot be swapped silently.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowGeometry {
    /// L_x: the extent along the flow, from the pressurised side to the outlet \[m\] (the contact
    /// width).
    pub along_flow: f64,
    /// L_y: the extent across the flow \[m\] (the sealing length; an O-ring's mean circumference
    /// π D).
    pub across_flow: f64,
}

impl FlowGeometry {
    /// `L_y/L_x`: the number of square cells of side L_x side by side across the flow, each with
    /// one critical constriction (PY08 eq. 3; docs/model.md §3.1).
    pub fn cells(&self) -> f64 {
        self.across_flow / self.along_flow
    }
}

/// How the interface conducts between the two ends of the seal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Conduction {
    /// One conductance per unit width σ \[m³/(Pa·s)\] over the whole extent along the flow
    /// (a flat seal; `σ = α u_c³/(12η)` for the critical junction, σ_eff for an effective
    /// medium or the numerical reference).
    Uniform { conductance: f64 },
    /// Strips in series along the flow: the resistance per unit width `R = ∫ dx/σ(x)`
    /// [Pa·s/m²] over the extent along the flow (docs/model.md §3.2).
    Series { resistance: f64 },
}

impl Fluid {
    /// The leak rate Q̇ \[m³/s\] through `conduction` over `geometry` (docs/model.md §3.1–§3.2):
    /// * uniform: `Q̇ = (L_y/L_x) σ ΔP` (PY08 eq. 3 with the conductance of eq. 2);
    /// * series: `Q̇ = L_y ΔP / ∫ dx/σ(x)` (the flux per unit width is the same through every
    ///   strip; with σ uniform it is the uniform law).
    ///
    /// An incompressible fluid's volume flow is linear in ΔP. A sealed interface (σ = 0 or
    /// R = ∞) gives 0.
    pub fn leak_rate(&self, geometry: FlowGeometry, conduction: Conduction) -> f64 {
        match conduction {
            Conduction::Uniform { conductance } => {
                geometry.cells() * conductance * self.pressure_difference
            }
            Conduction::Series { resistance } => {
                geometry.across_flow * self.pressure_difference / resistance
            }
        }
    }
}

/// Conductance per unit width of one critical constriction of height `u_c` \[m\] (PY08 eqs.
/// 1–2; docs/model.md §3.1): `σ = α u_c³/(12 η)` \[m³/(Pa·s)\], α the shape factor, η the
/// viscosity \[Pa·s\]. The flow through a thin gap between parallel walls (plane Poiseuille).
pub fn junction_conductance(u_c: f64, shape_factor: f64, viscosity: f64) -> f64 {
    shape_factor * u_c.powi(3) / (12.0 * viscosity)
}

#[cfg(test)]
mod tests {
    use super::*;

    const WATER: Fluid = Fluid {
        viscosity: 1e-3,
        pressure_difference: 1e5,
    };

    #[test]
    fn uniform_law_counts_cells_across_the_flow() {
        let g = FlowGeometry {
            along_flow: 1e-3,
            across_flow: 0.1,
        };
        let q = WATER.leak_rate(g, Conduction::Uniform { conductance: 2e-18 });
        assert!((q / (100.0 * 2e-18 * 1e5) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn series_of_equal_strips_is_the_uniform_law() {
        let g = FlowGeometry {
            along_flow: 2e-3,
            across_flow: 0.05,
        };
        let sigma = 3e-19;
        let uniform = WATER.leak_rate(g, Conduction::Uniform { conductance: sigma });
        let series = WATER.leak_rate(
            g,
            Conduction::Series {
                resistance: g.along_flow / sigma,
            },
        );
        assert!((series / uniform - 1.0).abs() < 1e-14);
    }

    #[test]
    fn a_sealed_interface_leaks_nothing() {
        let g = FlowGeometry {
            along_flow: 1e-3,
            across_flow: 1e-2,
        };
        assert_eq!(
            WATER.leak_rate(g, Conduction::Uniform { conductance: 0.0 }),
            0.0
        );
        assert_eq!(
            WATER.leak_rate(
                g,
                Conduction::Series {
                    resistance: f64::INFINITY
                }
            ),
            0.0
        );
    }

    #[test]
    fn plane_poiseuille_conductance() {
        // a 1 µm slit, water: u³/(12η) = 1e-18/1.2e-2
        let s = junction_conductance(1e-6, 1.0, 1e-3);
        assert!((s / (1e-18 / 1.2e-2) - 1.0).abs() < 1e-15);
        assert!((junction_conductance(1e-6, 0.5, 1e-3) / s - 0.5).abs() < 1e-15);
    }
}
