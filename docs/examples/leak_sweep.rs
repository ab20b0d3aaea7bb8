//! A leak-rate sweep over the squeezing pressure, on the contact model alone: the flat seal of
//! Persson & Yang (2008) §3, at the critical-junction level.
//!
//!     cargo run --release --example leak_sweep
//!
//! Prints P0, the critical gap u_c and the leak rate: the leak falls steeply with P0 and stops
//! when no channel percolates any more.

use sealsim::contact::{ContactSettings, Elastic};
use sealsim::fluid::{Fluid, ViscosityLaw};
use sealsim::leak::{Fidelity, FlatSeal, StaticProblem, StaticSolver};
use sealsim::surface::Spectrum;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let problem = StaticProblem {
        material: Elastic {
            youngs_modulus: 10e6, // Pa
            poisson_ratio: 0.5,
        },
        // h_rms = 2 µm, H = 0.8, q0 = 1e4 1/m, q1 = 7.8e9 1/m (the paper's surface)
        spectrum: Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None)?,
        fluid: Fluid {
            viscosity: 1e-3, // Pa·s
            pressure_difference: 0.01e6,
            law: ViscosityLaw::Constant,
            gas: None,
        },
        seal: FlatSeal {
            nominal_pressure: 0.2e6,
            width: 1e-3,
            length: 1e-3,
        },
        contact: ContactSettings::default(),
        shape_factor: 1.0,
    };
    let solver = StaticSolver::new(problem, Fidelity::Exact);
    println!("{:>10}  {:>12}  {:>12}", "P0 [MPa]", "u_c [m]", "Q [m³/s]");
    for p0 in [0.05e6, 0.1e6, 0.2e6, 0.5e6, 1e6, 2e6] {
        let point = solver.evaluate(p0);
        let u_c = point
            .junction
            .leaking()
            .map_or("sealed".to_string(), |j| format!("{:.3e}", j.u_c));
        println!(
            "{:>10.2}  {:>12}  {:>12.3e}",
            p0 / 1e6,
            u_c,
            point.leak_rate
        );
    }
    Ok(())
}
