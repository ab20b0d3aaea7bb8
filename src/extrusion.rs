//! Extrusion of a groove-seated O-ring into the clearance gap (docs/model.md §6.3).
//!
//! Under pressure the ring is pushed against the low-pressure side of its groove; where the
//! clearance gap between the parts is too wide for the rubber's hardness, it flows into the gap
//! and is nibbled away. The design limit engineers use is an empirical chart of the largest
//! diametral clearance against the pressure, by hardness, going back to the Parker O-Ring
//! Handbook's "limits for extrusion" figure. sealsim uses the condensed table published by
//! Seal & Design Inc., "Limits of Diametral Clearance Against Fluid Pressure"
//! (<http://www.sealanddesign.com/category/Extrusion-Limits/611.html>, read 2026-11-24), for
//! 70 and 90 Shore A in five pressure bands up to 3000 psi ([`CHART`]). Between 70 and 90
//! Shore A the limit is interpolated linearly in hardness (sealsim's choice: the chart gives no
//! 80 Shore A row; the Apple Rubber seal design guide's worked example — 1000 psi, 0.016 in:
//! not acceptable at 70, acceptable at 80 Shore A — is consistent with it). Softer than 70 the
//! 70 row is used and harder than 90 the 90 row: both are flagged, as is a pressure above the
//! chart's 3000 psi.
//!
//! The hardness is not a model parameter: sealsim takes the rubber's Shore A from its
//! relaxation modulus at the hardness test's time scale (3 s) at the current temperature, by
//! inverting Gent's relation `E [MPa] = 0.0981 (56 + 7.62336 S)/(0.137505 (254 − 2.54 S))`
//! (A.N. Gent 1958, in the form commonly quoted — the relation the library's illustrative
//! compounds were derived from, so they give back their nominal grade at 23 °C). A hot ring is
//! softer and extrudes at a smaller gap.

/// Pressure bands of the chart: their upper ends \[psi\].
const BAND_ENDS_PSI: [f64; 5] = [500.0, 1000.0, 1500.0, 2000.0, 3000.0];

/// The chart: (Shore A, largest diametral clearance \[in\] in each pressure band).
pub const CHART: [(f64, [f64; 5]); 2] = [
    (70.0, [0.016, 0.010, 0.006, 0.004, 0.002]),
    (90.0, [0.028, 0.024, 0.020, 0.016, 0.010]),
];

const PSI: f64 = 6_894.757_293_168_361;
const INCH: f64 = 0.0254;

/// What the chart allows at one pressure and hardness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExtrusionLimit {
    /// Largest diametral clearance \[m\].
    pub diametral_clearance: f64,
    /// The pressure is above the chart's last band (3000 psi): its last band was used.
    pub beyond_pressure: bool,
    /// The hardness is outside 70–90 Shore A by more than [`HARDNESS_RESOLUTION`]: the nearest
    /// row was used.
    pub beyond_hardness: bool,
    /// The hardness the limit is for \[Shore A\].
    pub hardness: f64,
}

/// Shore A points within which a hardness counts as on the chart's 70 or 90 row: the reading of
/// a durometer resolves about 1 point and a compound's grade is specified ± 5; 2 points keeps a
/// nominal 70 Shore A compound (69.97 here) on its row without hiding a softened one.
pub const HARDNESS_RESOLUTION: f64 = 2.0;

/// The chart's limit at pressure difference `pressure` \[Pa\] and hardness `shore_a`.
pub fn limit(pressure: f64, shore_a: f64) -> ExtrusionLimit {
    let psi = pressure.max(0.0) / PSI;
    let band = BAND_ENDS_PSI
        .iter()
        .position(|&end| psi <= end)
        .unwrap_or(BAND_ENDS_PSI.len() - 1);
    let (soft, hard) = (CHART[0], CHART[1]);
    let w = ((shore_a - soft.0) / (hard.0 - soft.0)).clamp(0.0, 1.0);
    let inches = soft.1[band] + w * (hard.1[band] - soft.1[band]);
    ExtrusionLimit {
        diametral_clearance: inches * INCH,
        beyond_pressure: psi > BAND_ENDS_PSI[BAND_ENDS_PSI.len() - 1],
        beyond_hardness: !(soft.0 - HARDNESS_RESOLUTION..=hard.0 + HARDNESS_RESOLUTION)
            .contains(&shore_a),
        hardness: shore_a,
    }
}

/// Shore A from Young's modulus `e` \[Pa\] by inverting Gent's relation (module docs):
/// `S = (254 E′ − 5.4936)/(0.747846 + 2.54 E′)`, `E′ = 0.137505 E/MPa`; clamped to 0–100.
pub fn shore_a_from_modulus(e: f64) -> f64 {
    let ep = 0.137_505 * e / 1e6;
    ((254.0 * ep - 0.0981 * 56.0) / (0.0981 * 7.623_36 + 2.54 * ep)).clamp(0.0, 100.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gent(shore: f64) -> f64 {
        0.0981 * (56.0 + 7.62336 * shore) / (0.137505 * (254.0 - 2.54 * shore)) * 1e6
    }

    #[test]
    fn gent_inverse_returns_the_grade() {
        for s in [40.0, 55.5, 70.0, 75.0, 90.0] {
            assert!((shore_a_from_modulus(gent(s)) - s).abs() < 1e-9, "{s}");
        }
        // the library's NBR 70: E(3 s, 23 °C) = 5.5205 MPa (materials/nbr-70.toml provenance)
        assert!((shore_a_from_modulus(5.5205e6) - 70.0).abs() < 1e-3);
    }

    #[test]
    fn chart_rows_and_interpolation() {
        // 70 Shore A at 100 bar (1450 psi): 1000–1500 psi band, 0.006 in
        let l = limit(100e5, 70.0);
        assert!((l.diametral_clearance - 0.006 * 0.0254).abs() < 1e-15);
        assert!(!l.beyond_pressure && !l.beyond_hardness);
        // 90 Shore A below 500 psi: 0.028 in
        assert!((limit(20e5, 90.0).diametral_clearance - 0.028 * 0.0254).abs() < 1e-15);
        // 80 Shore A at 1000 psi: halfway between 0.010 and 0.024 → 0.017 in ≥ 0.016 in
        // (Apple Rubber: 0.016 in acceptable at 80, not at 70 Shore A)
        let l = limit(1000.0 * PSI, 80.0);
        assert!((l.diametral_clearance / 0.0254 - 0.017).abs() < 1e-12);
        assert!(limit(1000.0 * PSI, 70.0).diametral_clearance < 0.016 * 0.0254);
        // outside the chart: flagged, nearest row/band; within 2 points of a row: on it
        let l = limit(400e5, 60.0);
        assert!(l.beyond_pressure && l.beyond_hardness);
        assert!(!limit(100e5, 68.5).beyond_hardness && limit(100e5, 67.9).beyond_hardness);
        assert!((l.diametral_clearance - 0.002 * 0.0254).abs() < 1e-15);
        // monotone: more pressure, less clearance; harder, more clearance
        let mut last = f64::INFINITY;
        for bar in [1.0, 40.0, 60.0, 90.0, 120.0, 180.0, 300.0] {
            let c = limit(bar * 1e5, 75.0).diametral_clearance;
            assert!(c <= last);
            last = c;
        }
        assert!(limit(100e5, 85.0).diametral_clearance > limit(100e5, 75.0).diametral_clearance);
    }
}
