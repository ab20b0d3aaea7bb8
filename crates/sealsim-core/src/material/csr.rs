//! From a compression-stress-relaxation test (ISO 3384) to the relaxation modulus E(t)
//! (docs/model.md §5, "Fitting").
//!
//! A CSR rig holds a test piece at a fixed compression and records the counterforce F(t).
//! In quasi-linear viscoelasticity (the same assumption the life run makes, §6) the force
//! at a fixed deformation is the relaxation modulus times a function of the deformation
//! alone, `F(t) = E(t) · k(ε)`, so `E(t) = F(t)/k(ε)` with `k` from the test piece:
//!
//! * **Ring** (ISO 3384 ring test piece, or an O-ring of cord diameter d and mean diameter D
//!   compressed between plates): `k = π D · d · g(ε)` with Lindley's squeeze function
//!   `g(ε) = 1.25 ε^{3/2} + 50 ε⁶` ([`crate::seal::squeeze_function`]) — exactly the force law
//!   the life run uses for an O-ring, so a ring fitted here gives back its measured force.
//! * **Disc** (ISO 3384 cylindrical test piece of diameter D) between lubricated
//!   (frictionless) plates: homogeneous uniaxial compression of an incompressible neo-Hookean
//!   solid, nominal stress `σ = (E/3)(λ⁻² − λ)` with `λ = 1 − ε` (L.R.G. Treloar, *The
//!   Physics of Rubber Elasticity*, 3rd ed., Oxford 1975, ch. 5 — recalled), so
//!   `k = (π D²/4) (λ⁻² − λ)/3`. Plates that grip the rubber raise the force: for a fully
//!   bonded disc of shape factor S = D/(4h) the small-strain stiffness rises by about
//!   `1 + 2S²` (A.N. Gent & P.B. Lindley, Proc. Inst. Mech. Eng. 173 (1959) 111 —
//!   recalled); [`TestPiece::friction_bound`] gives that factor so that a report can say how much a
//!   modulus from unlubricated plates may be overstated.
//! * **A stated normalisation**: the modulus at the force's reference point (the first
//!   reading, or F/F0 = 1 for retained-force data), `E(t) = E_ref · F(t)/F_ref`.
//!
//! The readings should start well after the compression was applied (ISO 3384 takes its
//! initial reading 30 min after compression — recalled): earlier points still carry the
//! loading ramp, which a step-strain relaxation modulus does not describe.

use crate::seal::squeeze_function;
use std::f64::consts::PI;
use std::fmt;

/// A CSR test piece and its compression.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TestPiece {
    /// A ring (or O-ring) of cord diameter `cross_section` \[m\] and mean diameter
    /// `mean_diameter` \[m\], compressed by `squeeze` (fraction of the cord diameter).
    Ring {
        cross_section: f64,
        mean_diameter: f64,
        squeeze: f64,
    },
    /// A cylindrical disc of `diameter` \[m\] (and `height` \[m\], used only for the friction
    /// bound) compressed by `squeeze` (fraction of the height) between lubricated plates.
    Disc {
        diameter: f64,
        height: Option<f64>,
        squeeze: f64,
    },
}

/// Why a test piece cannot be used.
#[derive(Debug, Clone, PartialEq)]
pub enum CsrError {
    /// A dimension is not positive and finite.
    Dimension { what: &'static str, value: f64 },
    /// The squeeze is outside (0, 0.6).
    Squeeze(f64),
}

impl fmt::Display for CsrError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CsrError::Dimension { what, value } => {
                write!(f, "the test piece's {what} must be positive, got {value} m")
            }
            CsrError::Squeeze(s) => write!(
                f,
                "the test's squeeze must be between 0 and 60 %, got {:.4} %",
                100.0 * s
            ),
        }
    }
}

impl std::error::Error for CsrError {}

/// Largest squeeze accepted (CSR tests run at 15–40 %; 60 % is far beyond any of them).
pub const MAX_SQUEEZE: f64 = 0.6;

impl TestPiece {
    /// Checks the dimensions and the squeeze.
    pub fn check(&self) -> Result<(), CsrError> {
        let positive = |what: &'static str, value: f64| {
            if value.is_finite() && value > 0.0 {
                Ok(())
            } else {
                Err(CsrError::Dimension { what, value })
            }
        };
        let squeeze = match *self {
            TestPiece::Ring {
                cross_section,
                mean_diameter,
                squeeze,
            } => {
                positive("cross-section", cross_section)?;
                positive("mean diameter", mean_diameter)?;
                squeeze
            }
            TestPiece::Disc {
                diameter,
                height,
                squeeze,
            } => {
                positive("diameter", diameter)?;
                if let Some(h) = height {
                    positive("height", h)?;
                }
                squeeze
            }
        };
        if squeeze.is_finite() && squeeze > 0.0 && squeeze < MAX_SQUEEZE {
            Ok(())
        } else {
            Err(CsrError::Squeeze(squeeze))
        }
    }

    /// `k(ε)` \[m²\]: the force per unit modulus, `F = E k` (module docs).
    pub fn force_per_modulus(&self) -> f64 {
        match *self {
            TestPiece::Ring {
                cross_section,
                mean_diameter,
                squeeze,
            } => PI * mean_diameter * cross_section * squeeze_function(squeeze),
            TestPiece::Disc {
                diameter, squeeze, ..
            } => {
                let stretch = 1.0 - squeeze;
                0.25 * PI * diameter * diameter * (stretch.powi(-2) - stretch) / 3.0
            }
        }
    }

    /// For a disc of known height, `1 + 2S²` with `S = D/(4h)`: about how much plates that
    /// grip the rubber raise the force over the lubricated case (module docs); `None` for a
    /// ring or a disc without height.
    pub fn friction_bound(&self) -> Option<f64> {
        match *self {
            TestPiece::Disc {
                diameter,
                height: Some(h),
                ..
            } => {
                let s = diameter / (4.0 * h);
                Some(1.0 + 2.0 * s * s)
            }
            _ => None,
        }
    }
}

/// How measured forces become moduli.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Normalisation {
    /// Forces \[N\] of a test piece: `E = F / k`.
    Piece(TestPiece),
    /// Forces of a test piece given as retained fractions of `initial_force` \[N\]:
    /// `E = r F0 / k`.
    RetainedOf {
        piece: TestPiece,
        initial_force: f64,
    },
    /// A stated modulus \[Pa\] at the reference reading (a force's first point, or a
    /// retention of 1): `E = E_ref · value / reference_value`.
    Modulus { modulus: f64, reference_value: f64 },
}

impl Normalisation {
    /// The factor `E/value` \[Pa per unit of the measured value\].
    pub fn factor(&self) -> f64 {
        match *self {
            Normalisation::Piece(piece) => 1.0 / piece.force_per_modulus(),
            Normalisation::RetainedOf {
                piece,
                initial_force,
            } => initial_force / piece.force_per_modulus(),
            Normalisation::Modulus {
                modulus,
                reference_value,
            } => modulus / reference_value,
        }
    }

    /// The moduli \[Pa\] of measured `values`.
    pub fn moduli(&self, values: &[f64]) -> Vec<f64> {
        let factor = self.factor();
        values.iter().map(|v| v * factor).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn disc_small_strain_limit_is_hookean() {
        // λ⁻² − λ = 3ε + O(ε²): F → E A ε
        let piece = TestPiece::Disc {
            diameter: 0.013,
            height: Some(0.0063),
            squeeze: 1e-6,
        };
        let area = 0.25 * PI * 0.013 * 0.013;
        let k = piece.force_per_modulus();
        assert!((k / (area * 1e-6) - 1.0).abs() < 1e-5, "{k}");
        // ISO 3384 type B: S = 13/(4·6.3) = 0.516, 1 + 2S² = 1.532
        let bound = piece.friction_bound().unwrap();
        assert!((bound - 1.532).abs() < 1e-3, "{bound}");
    }

    #[test]
    fn ring_uses_the_life_runs_force_law() {
        let piece = TestPiece::Ring {
            cross_section: 3.53e-3,
            mean_diameter: 0.03,
            squeeze: 0.25,
        };
        let g = 1.25 * 0.25f64.powf(1.5) + 50.0 * 0.25f64.powi(6);
        let k = piece.force_per_modulus();
        assert!((k / (PI * 0.03 * 3.53e-3 * g) - 1.0).abs() < 1e-14);
        assert!(piece.check().is_ok());
        let bad = TestPiece::Ring {
            cross_section: 3.53e-3,
            mean_diameter: 0.03,
            squeeze: 0.7,
        };
        assert_eq!(bad.check(), Err(CsrError::Squeeze(0.7)));
    }

    #[test]
    fn stated_modulus_scales_by_the_reference() {
        let n = Normalisation::Modulus {
            modulus: 6e6,
            reference_value: 200.0,
        };
        assert_eq!(n.moduli(&[200.0, 100.0]), [6e6, 3e6]);
    }
}
