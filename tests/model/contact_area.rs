//! The corrected contact area (`[model] area = "corrected"`, docs/model.md §2) against
//! independent references: the published GFMD areas and the relations as evaluated elsewhere
//! (docs/src/validation.md), the closed-form small-load limit, and the numerical level's
//! boundary elements on band-limited spectra; and what the correction carries through (ζc, the
//! sealing pressure, A′ in u1, P(u)).

use sealsim::contact::{
    AreaModel, ContactSettings, EffectiveMediumSettings, PerssonContact, ScaleMarch,
    SeparationDistribution,
};
use sealsim::numerical::bem::{BemSettings, Boundary, solve};
use sealsim::numerical::surface::synthesize;
use sealsim::surface::Spectrum;
use std::f64::consts::PI;

fn contact(sp: &Spectrum, area: AreaModel) -> PerssonContact {
    PerssonContact::new(
        sp.clone(),
        ContactSettings {
            area,
            ..ContactSettings::default()
        },
    )
}

/// The GFMD test surface of Wang & Müser's comparison as re-evaluated in
/// `xylcsi/PerssonModelFudgeFactor` (Fig. 2): E* = 1, q_l = q_r = 1e4 1/m, q_s = 1e6 1/m,
/// H = 0.8, h_rms = 6 µm (h′_rms = 0.277), no roll-off.
fn gfmd_surface() -> Spectrum {
    Spectrum::self_affine(6e-6, 0.8, 1e4, 1e6, None).unwrap()
}

/// p̄/E*, GFMD A/A0, and the relations evaluated by that repository's MATLAB scale march
/// (500 log steps, implicit): Persson 2001, Yang–Persson γ = 0.45, Wang–Müser γ = 5/9.
const GFMD: [(f64, f64, f64, f64, f64); 6] = [
    (1e-4, 8.609e-4, 5.769e-4, 8.60e-4, 7.74e-4),
    (1e-3, 8.272e-3, 5.769e-3, 8.60e-3, 7.74e-3),
    (0.01, 0.0779, 0.0576, 0.0842, 0.0775),
    (0.04, 0.2846, 0.2276, 0.2971, 0.2995),
    (0.113, 0.6571, 0.5861, 0.6362, 0.6608),
    (0.24, 0.9406, 0.9173, 0.9212, 0.9246),
];

#[test]
fn corrected_area_reproduces_the_gfmd_reference_table() {
    let sp = gfmd_surface();
    assert!((sp.rms_slope() / 0.277 - 1.0).abs() < 2e-3);
    let zeta1 = sp.q1() / sp.q0();
    let persson = contact(&sp, AreaModel::Persson);
    let corrected = contact(&sp, AreaModel::Corrected);
    let yang_persson = ScaleMarch::yang_persson(0.45);
    let m3 = sp.total_m3();
    let mut worst = [0.0_f64; 2];
    for (s, gfmd, p01, yp, wm) in GFMD {
        let a_p = persson.area_fraction(zeta1, s);
        let a_c = corrected.area_fraction(zeta1, s);
        let a_yp = yang_persson.area(m3 / (s * s));
        // the same relations, evaluated independently (an implicit march of 500 steps, given to
        // 3–4 digits): within 0.3 % (measured ≤ 0.07 %)
        for (ours, theirs, what) in [(a_p, p01, "Persson"), (a_c, wm, "WM"), (a_yp, yp, "YP")] {
            assert!(
                (ours / theirs - 1.0).abs() < 0.003,
                "{what} at p/E* = {s}: {ours} vs {theirs}"
            );
        }
        println!(
            "| {s} | {gfmd} | {a_p:.4e} ({:.2}) | {a_yp:.4e} ({:.2}) | {a_c:.4e} ({:.2}) |",
            a_p / gfmd,
            a_yp / gfmd,
            a_c / gfmd
        );
        worst[0] = worst[0].max((a_p / gfmd - 1.0).abs());
        worst[1] = worst[1].max((a_c / gfmd - 1.0).abs());
    }
    // against GFMD: Persson's area is up to 33 % low, the corrected within 10.1 % at every load
    // (0.899 at the smallest load, 0.94–1.05 above)
    assert!(worst[0] > 0.3, "{worst:?}");
    assert!(worst[1] < 0.11, "{worst:?}");
}

#[test]
fn corrected_small_load_slope_is_persson_kappa_over_root_gamma() {
    // A/A0 → κ s/h′_rms with κ = √(8/π) (Persson) and √(8/π)/√(5/9) = 2.1413 (Wang–Müser)
    let sp = gfmd_surface();
    let zeta1 = sp.q1() / sp.q0();
    let s = 1e-7;
    let kappa = |area: AreaModel| contact(&sp, area).area_fraction(zeta1, s) * sp.rms_slope() / s;
    let k0 = (8.0 / PI).sqrt();
    assert!((kappa(AreaModel::Persson) / k0 - 1.0).abs() < 1e-6);
    assert!((kappa(AreaModel::Corrected) / (k0 / (5.0_f64 / 9.0).sqrt()) - 1.0).abs() < 1e-4);
}

#[test]
fn corrected_area_carries_through_the_junction_and_the_sealing_pressure() {
    let sp = Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None).unwrap();
    let (p, c) = (
        contact(&sp, AreaModel::Persson),
        contact(&sp, AreaModel::Corrected),
    );
    let zeta1 = sp.q1() / sp.q0();
    let a_c = ContactSettings::default().percolation_threshold;
    // the sealing pressure is where the area at full magnification reaches a_c; more area
    // seals at a lower pressure
    let (sp_seal, sc_seal) = (p.sealing_reduced_pressure(), c.sealing_reduced_pressure());
    assert!((c.area_fraction(zeta1, sc_seal) / a_c - 1.0).abs() < 1e-9);
    assert!(sc_seal < 0.95 * sp_seal, "{sc_seal} vs {sp_seal}");
    let s_half = c.reduced_pressure_at_area(0.5);
    assert!((c.area_fraction(zeta1, s_half) - 0.5).abs() < 1e-9);
    for r in [1e-4, 1e-3, 0.01, 0.03, 0.1, 0.2, 0.3, 0.5, 0.8] {
        let s = r * sc_seal;
        let (jp, jc) = (
            *p.critical_junction(s).leaking().unwrap(),
            *c.critical_junction(s).leaking().unwrap(),
        );
        // ζc is where the corrected area reaches a_c: later in magnification than Persson's,
        // so a narrower, lower constriction (less leak: Persson's is the conservative side).
        // Where ζc < 1.1 (the lowest pressures) the smaller |A′| of the corrected area lifts
        // u1 = ū + ū′A/A′ about as much as the later ζc lowers it: u_c within +1.1 % (measured
        // 1.0103 at 1 % of the sealing pressure), then 0.99 at 3 %, 0.75 at 10 %, 0.44 at 80 %.
        assert!((c.area_fraction(jc.zeta_c, s) / a_c - 1.0).abs() < 1e-9);
        assert!(jc.zeta_c > jp.zeta_c, "{r}: {jc:?} vs {jp:?}");
        let bound = if r < 0.03 {
            1.011
        } else if r < 0.1 {
            1.0
        } else {
            0.8
        };
        assert!(jc.u_c < bound * jp.u_c, "{r}: {}", jc.u_c / jp.u_c);
        // the threshold path agrees with the settings' own
        assert_eq!(
            c.critical_junction_at_threshold(s, a_c),
            c.critical_junction(s)
        );
    }
    // u1 needs A′: the analytic ln ζ derivatives match finite differences
    let s = 0.2 * sc_seal;
    for zeta in [3.0, 16.0, 500.0] {
        let h = 1e-5_f64;
        let (a, b, m) = (
            c.separation(zeta * (-h).exp(), s),
            c.separation(zeta * h.exp(), s),
            c.separation(zeta, s),
        );
        let fd_a = (b.area - a.area) / (2.0 * h);
        let fd_u = (b.mean - a.mean) / (2.0 * h);
        assert!(
            (fd_a / m.area_dlnzeta - 1.0).abs() < 1e-6,
            "{fd_a} vs {m:?}"
        );
        assert!(
            (fd_u / m.mean_dlnzeta - 1.0).abs() < 1e-6,
            "{fd_u} vs {m:?}"
        );
    }
    // the mean gap of the whole interface, ū(ζ = 1), is p(1) = P0's: the correction does not
    // move it (the quantity the boundary elements confirm to 2–6 %)
    assert_eq!(c.separation(1.0, s).mean, p.separation(1.0, s).mean);
}

#[test]
fn corrected_separation_distribution_keeps_its_mass() {
    // P(u): the weights −A′ of the corrected area integrate with the contact fraction to 1
    let sp = Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None).unwrap();
    let c = contact(&sp, AreaModel::Corrected);
    for r in [1e-3, 0.1, 0.6] {
        let s = r * c.reduced_pressure_at_area(0.5);
        let d = SeparationDistribution::persson(&c, s, EffectiveMediumSettings::default());
        assert!(
            (d.total_probability() - 1.0).abs() < 1e-6,
            "{r}: {}",
            d.total_probability()
        );
    }
}

/// Boundary-element A/A0 on `seeds` realisations of `sp` (band q1/q0 = 32) at `ppw` pixels per
/// shortest wavelength: the mean over the seeds.
fn bem_area(sp: &Spectrum, ppw: usize, e_star: f64, p0: f64, seeds: std::ops::Range<u64>) -> f64 {
    let n = 32 * ppw;
    let settings = BemSettings::default();
    let count = seeds.end - seeds.start;
    seeds
        .map(|seed| {
            let map = synthesize(sp, n, seed);
            solve(&map, e_star, p0, Boundary::Periodic, &settings)
                .unwrap()
                .contact_fraction
        })
        .sum::<f64>()
        / count as f64
}

/// The corrected area and the boundary elements on two band-limited spectra (H = 0.8 and
/// H = 0.5, q1/q0 = 32, roll-off 4 q0 as the numerical level's studies), at loads where the
/// corrected A/A0 is 1, 3, 10 and 30 %. The boundary elements converge from above about first
/// order in the pixel (docs/src/validation.md): extrapolated from 8 and 16 pixels per
/// wavelength, `A∞ ≈ 2 A16 − A8`, mean of four realisations.
#[test]
fn corrected_area_is_within_ten_percent_of_the_boundary_elements() {
    let e_star = 1e7 / 0.75;
    let q0 = 1e5;
    for hurst in [0.8, 0.5] {
        let sp = Spectrum::self_affine(1e-6, hurst, q0, 32.0 * q0, Some(4.0 * q0)).unwrap();
        let zeta1 = 32.0;
        let c = contact(&sp, AreaModel::Corrected);
        let p = contact(&sp, AreaModel::Persson);
        for target in [0.01, 0.03, 0.1, 0.3] {
            let s = c.reduced_pressure_at_area(target);
            let a8 = bem_area(&sp, 8, e_star, s * e_star, 1..5);
            let a16 = bem_area(&sp, 16, e_star, s * e_star, 1..5);
            let bem = 2.0 * a16 - a8;
            let (ac, ap) = (c.area_fraction(zeta1, s), p.area_fraction(zeta1, s));
            println!(
                "H = {hurst} A/A0 {target}: BEM 8 ppw {a8:.4}, 16 ppw {a16:.4}, extrapolated \
                 {bem:.4}; corrected {ac:.4} ({:+.1} %), Persson {ap:.4} ({:+.1} %)",
                100.0 * (ac / bem - 1.0),
                100.0 * (ap / bem - 1.0)
            );
            assert!((ac / bem - 1.0).abs() < 0.10, "H {hurst}, {target}");
            // and Persson's own area is the further one (below the boundary elements)
            assert!(ap < ac && (ap / bem - 1.0).abs() > (ac / bem - 1.0).abs());
        }
    }
}
