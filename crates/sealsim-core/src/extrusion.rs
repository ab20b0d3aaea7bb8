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
//! not acceptable at 70, acceptable at 80 Shore A — is consistent with it). Harder than 90 the
//! 90 row is used (the conservative side). Softer than 70 the chart's own trend is continued:
//! the clearance is extrapolated geometrically in hardness with the 70-to-90 ratio of each band
//! (at 50 Shore A 57 % of the 70 row's below 500 psi, consistent with the Machinery's Handbook's
//! advice to halve the standard gap for soft silicone rings, 31st ed., p. 2679), and flagged.
//!
//! **Beyond the chart's pressures.** The chart stops at 3000 psi. Without back-up rings a
//! groove-seated ring above it extrudes ([`ExtrusionLimit::over_rated`]): the chart gives no
//! clearance there, and ERIKS' O-ring technical handbook (§12F) rates a static O-ring without a
//! back-up ring to 1000 psi (7 MPa) only. With back-up rings (`backup_rings = 1` or `2`) the
//! ring is protected by a harder ring: Parker's O-Ring Handbook (ORD 5700, §6.1) reads the
//! clearance off the 90 Shore A curve when standard 90-durometer back-up rings are used, and
//! ERIKS rates a static O-ring with back-up rings to 6000 psi (40 MPa), "up to 30000 psi …
//! with special construction" beyond. So with back-up rings the limit is the 90 row up to
//! 3000 psi, its last band's step continued geometrically per 1000 psi above (×0.625 per
//! 1000 psi: the conservative reading), and over-rated above 40 MPa. One and two back-up rings
//! get the same limit (ERIKS does not distinguish; Parker recommends two even for one-way
//! pressure, "cheap insurance", for a pressure that may reverse).
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
    /// The pressure is above the chart's last band (3000 psi): with back-up rings its 90 row's
    /// last step was continued; without, [`Self::over_rated`].
    pub beyond_pressure: bool,
    /// The hardness is outside 70–90 Shore A by more than [`HARDNESS_RESOLUTION`]: below, the
    /// chart's trend was continued; above, the 90 row was used.
    pub beyond_hardness: bool,
    /// The hardness the limit is for \[Shore A\].
    pub hardness: f64,
    /// The back-up rings on the low-pressure side (0, 1 or 2).
    pub backup_rings: u8,
    /// The pressure is above what the arrangement is rated for — the chart's 3000 psi without
    /// back-up rings, 40 MPa with them: the ring extrudes whatever the clearance.
    pub over_rated: bool,
    /// The highest pressure the arrangement is rated for \[Pa\].
    pub rated_pressure: f64,
}

impl ExtrusionLimit {
    /// Whether a diametral clearance `clearance` \[m\] extrudes the ring: over the chart's
    /// limit, or any clearance above the arrangement's rated pressure.
    pub fn extrudes(&self, clearance: f64) -> bool {
        self.over_rated || clearance > self.diametral_clearance
    }
}

/// Shore A points within which a hardness counts as on the chart's 70 or 90 row: the reading of
/// a durometer resolves about 1 point and a compound's grade is specified ± 5; 2 points keeps a
/// nominal 70 Shore A compound (69.97 here) on its row without hiding a softened one.
pub const HARDNESS_RESOLUTION: f64 = 2.0;

/// The pressure the chart covers, its last band's end \[Pa\] (3000 psi).
pub const CHART_PRESSURE: f64 = 3000.0 * PSI;
/// The pressure back-up rings rate a static O-ring to \[Pa\]: 6000 psi, 40 MPa (ERIKS O-ring
/// technical handbook, §12F: "up to 6000 psi (400 bar, 40 MPa) with back-up ring").
pub const BACKUP_RATED_PRESSURE: f64 = 40e6;
/// The factor per 1000 psi that continues the 90 row beyond 3000 psi with back-up rings: its
/// last step, 0.010/0.016 in.
const BACKUP_STEP_PER_1000_PSI: f64 = 0.010 / 0.016;

/// The chart's limit at pressure difference `pressure` \[Pa\] and hardness `shore_a` with
/// `backup_rings` back-up rings (module docs).
pub fn limit(pressure: f64, shore_a: f64, backup_rings: u8) -> ExtrusionLimit {
    let psi = pressure.max(0.0) / PSI;
    let band = BAND_ENDS_PSI
        .iter()
        .position(|&end| psi <= end)
        .unwrap_or(BAND_ENDS_PSI.len() - 1);
    let (soft, hard) = (CHART[0], CHART[1]);
    let beyond_pressure = psi > BAND_ENDS_PSI[BAND_ENDS_PSI.len() - 1];
    let inches = if backup_rings > 0 {
        // the back-up ring's 90 Shore A row, continued beyond the chart by its last step
        let excess = (psi - BAND_ENDS_PSI[BAND_ENDS_PSI.len() - 1]).max(0.0) / 1000.0;
        hard.1[band] * BACKUP_STEP_PER_1000_PSI.powf(excess)
    } else if shore_a < soft.0 {
        // softer than the chart: its 70-to-90 trend continued geometrically
        let ratio = hard.1[band] / soft.1[band];
        soft.1[band] * ratio.powf((shore_a - soft.0) / (hard.0 - soft.0))
    } else {
        let w = ((shore_a - soft.0) / (hard.0 - soft.0)).min(1.0);
        soft.1[band] + w * (hard.1[band] - soft.1[band])
    };
    let rated_pressure = if backup_rings > 0 {
        BACKUP_RATED_PRESSURE
    } else {
        CHART_PRESSURE
    };
    ExtrusionLimit {
        diametral_clearance: inches * INCH,
        beyond_pressure,
        beyond_hardness: backup_rings == 0
            && !(soft.0 - HARDNESS_RESOLUTION..=hard.0 + HARDNESS_RESOLUTION).contains(&shore_a),
        hardness: shore_a,
        backup_rings,
        over_rated: pressure > rated_pressure,
        rated_pressure,
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
        let l = limit(100e5, 70.0, 0);
        assert!((l.diametral_clearance - 0.006 * 0.0254).abs() < 1e-15);
        assert!(!l.beyond_pressure && !l.beyond_hardness);
        // 90 Shore A below 500 psi: 0.028 in
        assert!((limit(20e5, 90.0, 0).diametral_clearance - 0.028 * 0.0254).abs() < 1e-15);
        // 80 Shore A at 1000 psi: halfway between 0.010 and 0.024 → 0.017 in ≥ 0.016 in
        // (Apple Rubber: 0.016 in acceptable at 80, not at 70 Shore A)
        let l = limit(1000.0 * PSI, 80.0, 0);
        assert!((l.diametral_clearance / 0.0254 - 0.017).abs() < 1e-12);
        assert!(limit(1000.0 * PSI, 70.0, 0).diametral_clearance < 0.016 * 0.0254);
        // within 2 points of a row: on it
        assert!(!limit(100e5, 68.5, 0).beyond_hardness && limit(100e5, 67.9, 0).beyond_hardness);
        // monotone: more pressure, less clearance; harder, more clearance
        let mut last = f64::INFINITY;
        for bar in [1.0, 40.0, 60.0, 90.0, 120.0, 180.0, 300.0] {
            let c = limit(bar * 1e5, 75.0, 0).diametral_clearance;
            assert!(c <= last);
            last = c;
        }
        assert!(
            limit(100e5, 85.0, 0).diametral_clearance > limit(100e5, 75.0, 0).diametral_clearance
        );
    }

    #[test]
    fn softer_than_the_chart_continues_its_trend() {
        // continuous at 70 Shore A, and softer always less clearance
        for band_psi in [200.0, 800.0, 1200.0, 1800.0, 2500.0] {
            let p = band_psi * PSI;
            let at70 = limit(p, 70.0, 0).diametral_clearance;
            assert!((limit(p, 70.0 - 1e-9, 0).diametral_clearance / at70 - 1.0).abs() < 1e-9);
            let mut last = at70;
            for s in [65.0, 60.0, 50.0, 40.0] {
                let c = limit(p, s, 0).diametral_clearance;
                assert!(c > 0.0 && c < last, "{band_psi} psi, {s} Shore A");
                last = c;
            }
        }
        // below 500 psi at 50 Shore A: 0.016 (0.016/0.028) in, 57 % of the 70 row — about the
        // Machinery's Handbook's "50 percent reduction" for soft silicone
        let c = limit(20e5, 50.0, 0).diametral_clearance / INCH;
        assert!((c - 0.016 * 0.016 / 0.028).abs() < 1e-12);
        assert!(limit(20e5, 50.0, 0).beyond_hardness);
    }

    #[test]
    fn beyond_the_chart_only_back_up_rings_hold() {
        // no back-up ring: over-rated above 3000 psi whatever the clearance
        let bare = limit(1000e5, 75.0, 0);
        assert!(bare.over_rated && bare.extrudes(0.0) && bare.beyond_pressure);
        assert!(!limit(CHART_PRESSURE, 75.0, 0).over_rated);
        // back-up rings: the 90 row to 3000 psi (Parker §6.1) whatever the ring's hardness
        let b = limit(100e5, 70.0, 2);
        assert!((b.diametral_clearance - 0.020 * INCH).abs() < 1e-15);
        assert!(!b.over_rated && !b.beyond_hardness);
        assert_eq!(
            limit(100e5, 70.0, 1),
            ExtrusionLimit {
                backup_rings: 1,
                ..b
            }
        );
        // beyond 3000 psi its last step continued (less clearance), over-rated above 40 MPa
        let at = |bar: f64| limit(bar * 1e5, 75.0, 2);
        assert!(at(300.0).diametral_clearance < 0.010 * INCH && !at(300.0).over_rated);
        let c = at(300.0).diametral_clearance / INCH;
        let psi = 300e5 / PSI;
        assert!((c - 0.010 * 0.625f64.powf((psi - 3000.0) / 1000.0)).abs() < 1e-12);
        assert!(!at(400.0).over_rated && at(400.1).over_rated && at(1000.0).extrudes(0.0));
    }
}
