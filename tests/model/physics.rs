//! Physics of the static engine against independent references, closed forms, limits,
//! scaling and convergence (docs/model.md §2–3.1, PY08 §2–3).

use crate::common::rel;
use sealsim::contact::{
    ContactSettings, ContactTable, CriticalJunction, Junction, PerssonContact, QuadratureSettings,
    TableSettings,
};
use sealsim::surface::Spectrum;

fn contact(h: f64, hurst: f64, q0: f64, q1: f64) -> PerssonContact {
    PerssonContact::new(
        Spectrum::self_affine(h, hurst, q0, q1, None).unwrap(),
        ContactSettings::default(),
    )
}

fn leaking(j: Junction) -> CriticalJunction {
    match j {
        Junction::Leaking(j) => j,
        Junction::Sealed => panic!("expected a leaking junction"),
    }
}

/// Values from tests/reference/persson_reference.py: scipy adaptive quadrature of the
/// paper's integrals in their original form, root finding for ζc and finite differences for
/// u1 — none of sealsim's closed forms, analytic derivatives or tables.
#[test]
fn matches_independent_reference() {
    // (h_rms, H, q0, q1, E, ν, P0) → (ζc, u_c, ū_c, h_rms(ζc), λc)
    let cases = [
        (
            (2e-6, 0.8, 1e4, 7.8e9, 10e6, 0.5, 0.2e6),
            (
                1.61860614e1,
                1.23573438e-7,
                2.78379030e-8,
                2.15633902e-7,
                3.88184943e-5,
            ),
        ),
        (
            (2e-6, 0.8, 1e4, 7.8e9, 10e6, 0.5, 0.05e6),
            (
                1.35089453,
                1.69414732e-6,
                7.08550424e-7,
                1.57229068e-6,
                4.65112942e-4,
            ),
        ),
        (
            (2e-6, 0.8, 1e4, 7.8e9, 10e6, 0.5, 1e6),
            (
                1.96276239e4,
                3.12438183e-10,
                5.06507405e-11,
                7.34742572e-10,
                3.20119508e-8,
            ),
        ),
        (
            (6e-6, 0.6, 1e4, 7.8e9, 10e6, 0.5, 0.5e6),
            (
                7.08247914,
                1.90868249e-6,
                7.83527257e-7,
                1.85370189e-6,
                8.87144908e-5,
            ),
        ),
        (
            (1e-6, 0.9, 1e5, 1e9, 3e6, 0.3, 0.1e6),
            (
                2.00007556,
                4.09409290e-7,
                1.11440520e-7,
                5.35868468e-7,
                3.14147396e-5,
            ),
        ),
    ];
    for ((h, hurst, q0, q1, e, nu, p0), (zc, uc, ub, hc, lc)) in cases {
        let c = contact(h, hurst, q0, q1);
        let j = leaking(c.critical_junction(p0 / (e / (1.0 - nu * nu))));
        // reference printed to 9 significant digits
        assert!(rel(j.zeta_c, zc) < 1e-8, "ζc {} vs {zc}", j.zeta_c);
        assert!(rel(j.lambda_c, lc) < 1e-8);
        assert!(rel(j.hrms_c, hc) < 1e-8);
        assert!(rel(j.ubar_c, ub) < 1e-7, "ū_c {} vs {ub}", j.ubar_c);
        // the reference's u1 uses a central difference with step 1e-4 ζc: ~1e-7
        assert!(rel(j.u_c, uc) < 1e-6, "u_c {} vs {uc}", j.u_c);
    }
}

/// docs/model.md §3.1 check value, the paper's wiper case (PY08 §8): ζc ≈ 16.19, u_c ≈ 0.124 µm
/// (the paper says "≈ 0.1 µm").
#[test]
fn paper_wiper_check_value() {
    let c = contact(2e-6, 0.8, 1e4, 7.8e9);
    let j = leaking(c.critical_junction(0.2e6 / (10e6 / 0.75)));
    assert!((j.zeta_c - 16.19).abs() < 0.005, "ζc = {}", j.zeta_c);
    assert!((j.u_c - 0.124e-6).abs() < 0.0005e-6, "u_c = {}", j.u_c);
}

/// Small load: A/A0 → κ P0/(E* h'_rms), κ = √(8/π) (docs/model.md §2).
#[test]
fn small_load_contact_area_is_linear_with_kappa() {
    let c = contact(2e-6, 0.8, 1e4, 7.8e9);
    let zeta1 = 7.8e9 / 1e4;
    let kappa = (8.0 / std::f64::consts::PI).sqrt();
    let slope = c.spectrum().rms_slope();
    for s in [1e-6, 1e-8] {
        let a = c.area_fraction(zeta1, s);
        assert!(rel(a, kappa * s / slope) < 1e-6, "s={s}: {a}");
    }
}

/// Small load: ū ≈ u0 ln(β E*/P0) with u0 ≈ 0.4255 h_rms for H = 0.8, γ = 0.4 (docs/model.md §2).
#[test]
fn small_load_mean_separation_is_logarithmic() {
    let c = contact(2e-6, 0.8, 1e4, 7.8e9);
    let (s1, s2) = (1e-9, 1e-10);
    let u0 = (c.separation(1.0, s2).mean - c.separation(1.0, s1).mean) / (s1 / s2).ln();
    assert!(
        (u0 / 2e-6 - 0.4255).abs() < 2e-4,
        "u0/h_rms = {}",
        u0 / 2e-6
    );
}

/// ζc and u_c/h_rms depend on P0/(E* h_rms) only: doubling h_rms and P0 together leaves ζc
/// unchanged and doubles u_c (docs/model.md §2, "Scaling").
#[test]
fn scaling_with_roughness_and_pressure() {
    for (hurst, p0) in [(0.8, 0.2e6), (0.6, 0.05e6), (0.9, 0.3e6)] {
        let es = 10e6 / 0.75;
        let a = leaking(contact(2e-6, hurst, 1e4, 7.8e9).critical_junction(p0 / es));
        let b = leaking(contact(4e-6, hurst, 1e4, 7.8e9).critical_junction(2.0 * p0 / es));
        assert!(rel(b.zeta_c, a.zeta_c) < 1e-12);
        assert!(
            rel(b.u_c, 2.0 * a.u_c) < 1e-9,
            "{} vs {}",
            b.u_c,
            2.0 * a.u_c
        );
        assert!(rel(b.ubar_c, 2.0 * a.ubar_c) < 1e-9);
    }
}

/// Above the sealing pressure no channel percolates: sealed, not NaN.
#[test]
fn sealed_above_sealing_pressure() {
    let c = contact(2e-6, 0.8, 1e4, 7.8e9);
    let s_seal = c.sealing_reduced_pressure();
    // at s_seal, A(q1/q0)/A0 is exactly the threshold
    assert!(rel(c.area_fraction(7.8e5, s_seal), 0.4) < 1e-12);
    assert_eq!(c.critical_junction(s_seal * 1.001), Junction::Sealed);
    assert!(c.critical_junction(s_seal * 0.9).leaking().is_some());
}

fn with_quadrature(c: &PerssonContact, q: QuadratureSettings) -> PerssonContact {
    PerssonContact::new(
        c.spectrum().clone(),
        ContactSettings {
            quadrature: q,
            ..*c.settings()
        },
    )
}

/// Refining the quadrature 4× changes u_c by < 1e-4 relative (measured: < 1e-9).
#[test]
fn exact_path_is_converged() {
    let surfaces = [
        (2e-6, 0.8, 1e4, 7.8e9),
        (1e-9, 0.05, 1e4, 1e12),
        (1e-3, 0.95, 1e2, 1e3),
        (1e-6, 0.5, 1e3, 1e11),
    ];
    for (h, hurst, q0, q1) in surfaces {
        let c = contact(h, hurst, q0, q1);
        let fine = with_quadrature(&c, c.settings().quadrature.refined(4.0));
        let s_seal = c.sealing_reduced_pressure();
        for r in [1e-7, 1e-3, 0.1, 0.5, 0.9] {
            let a = leaking(c.critical_junction(r * s_seal));
            let b = leaking(fine.critical_junction(r * s_seal));
            assert!(
                rel(a.u_c, b.u_c) < 1e-9,
                "H={hurst} r={r}: {} vs {}",
                a.u_c,
                b.u_c
            );
            assert!(rel(a.ubar_c, b.ubar_c) < 1e-9);
        }
    }
}

/// The contact table agrees with the exact path within 1e-3 relative over its whole range,
/// for self-affine, rolled-off and tabulated spectra.
#[test]
fn table_agrees_with_exact_path() {
    let mut spectra = vec![
        Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None).unwrap(),
        Spectrum::self_affine(1e-9, 0.05, 1e4, 1e12, None).unwrap(),
        Spectrum::self_affine(1e-3, 0.95, 1e2, 1e3, None).unwrap(),
        Spectrum::self_affine(5e-6, 0.7, 1e3, 1e9, Some(3e4)).unwrap(),
    ];
    let q: Vec<f64> = (0..25).map(|i| 1e3 * 10f64.powf(i as f64 / 4.0)).collect();
    let c: Vec<f64> = q
        .iter()
        .map(|&q: &f64| 1e-20 * (1.0 + (q / 1e5).powi(2)).powf(-1.8))
        .collect();
    spectra.push(Spectrum::tabulated(&q, &c).unwrap());
    for sp in spectra {
        let exact = PerssonContact::new(sp, ContactSettings::default());
        let table = ContactTable::build(exact.clone(), TableSettings::default());
        let (lo, hi) = table.range().expect("a table");
        let mut worst: f64 = 0.0;
        for k in 0..=400 {
            let s = lo * (hi / lo).powf(k as f64 / 400.0);
            let a = leaking(exact.critical_junction(s));
            let b = leaking(table.critical_junction(s));
            assert_eq!(a.zeta_c, b.zeta_c);
            worst = worst.max(rel(b.u_c, a.u_c)).max(rel(b.ubar_c, a.ubar_c));
        }
        assert!(worst < 1e-3, "worst table error {worst}");
        // outside the range the table falls back to the exact path
        assert_eq!(
            table.critical_junction(lo * 0.5),
            exact.critical_junction(lo * 0.5)
        );
        assert_eq!(
            table.critical_junction(hi * 1.001),
            exact.critical_junction(hi * 1.001)
        );
    }
}

/// A table built on one spectrum's shape serves every amplitude of it (docs/model.md §2:
/// the contact of k²C at P0/E* is that of C at P0/(k E*) with every length times k): the
/// tables of a self-affine surface at Ra 0.2, 0.4 and 0.9 µm agree with each one's own exact
/// path to the table's tolerance over the whole range, and with each other under the scaling
/// to rounding — the nodes are computed once, on the unit shape, whichever surface comes first.
#[test]
fn one_table_shape_serves_every_amplitude() {
    let settings = ContactSettings::default();
    let build = |h: f64| {
        let exact = PerssonContact::new(
            Spectrum::self_affine(h, 0.8, 7.85e3, 6.3e8, None).unwrap(),
            settings,
        );
        (
            ContactTable::build(exact.clone(), TableSettings::default()),
            exact,
        )
    };
    let (base, _) = build(0.5e-6);
    let (lo, hi) = base.range().expect("a table");
    for k in [0.4, 1.0, 1.8] {
        let (table, exact) = build(0.5e-6 * k);
        let (lo_k, hi_k) = table.range().expect("a table");
        assert!(rel(lo_k, k * lo) < 1e-12 && rel(hi_k, k * hi) < 1e-12);
        let mut worst: f64 = 0.0;
        for i in 0..=200 {
            let s = lo * (hi / lo).powf((i as f64 + 0.37) / 201.0);
            let scaled = table.critical_gap(k * s).unwrap();
            // the scaling law, through two different surfaces' lookups
            assert!(
                rel(scaled, k * base.critical_gap(s).unwrap()) < 1e-11,
                "k = {k}, s = {s}"
            );
            worst = worst.max(rel(scaled, leaking(exact.critical_junction(k * s)).u_c));
        }
        assert!(worst < 1e-3, "k = {k}: worst table error {worst}");
    }
    // the same shape gives the same unit spectrum to the bit
    let a = Spectrum::self_affine(0.3e-6, 0.8, 7.85e3, 6.3e8, Some(2e4)).unwrap();
    let b = Spectrum::self_affine(1.7e-6, 0.8, 7.85e3, 6.3e8, Some(2e4)).unwrap();
    assert_eq!(a.unit_shape(), b.unit_shape());
    assert!(rel(a.unit_shape().rms_roughness(), 1e-6) < 1e-14);
    assert_ne!(
        a.unit_shape(),
        Spectrum::self_affine(0.3e-6, 0.7, 7.85e3, 6.3e8, Some(2e4))
            .unwrap()
            .unit_shape()
    );
}

/// The exact level's cache of quadrature nodes ([`TableSettings::exact_cache`], 96 per decade)
/// interpolates u_c far below the critical-junction table's error, so that `exact` stays the
/// table's reference (docs/model.md §4).
#[test]
fn exact_cache_is_far_more_accurate_than_the_table() {
    let spectra = [
        Spectrum::self_affine(2e-6, 0.8, 1e4, 7.8e9, None).unwrap(),
        Spectrum::self_affine(1e-9, 0.05, 1e4, 1e12, None).unwrap(),
        Spectrum::self_affine(5e-6, 0.7, 1e3, 1e9, Some(3e4)).unwrap(),
    ];
    for sp in spectra {
        let exact = PerssonContact::new(sp, ContactSettings::default());
        let cache = ContactTable::build(exact.clone(), TableSettings::exact_cache());
        let table = ContactTable::build(exact.clone(), TableSettings::default());
        let (lo, hi) = cache.range().expect("a table");
        let (mut worst, mut worst_table): (f64, f64) = (0.0, 0.0);
        for k in 0..=600 {
            // off the nodes, over the range and its extension
            let s = lo * (hi / lo).powf((k as f64 + 0.31) / 601.0);
            let a = leaking(exact.critical_junction(s)).u_c;
            worst = worst.max(rel(cache.critical_gap(s).unwrap(), a));
            worst_table = worst_table.max(rel(table.critical_gap(s).unwrap(), a));
        }
        eprintln!("u_c: exact cache {worst:.2e}, table {worst_table:.2e}");
        assert!(worst < 1e-6, "exact cache error {worst:e}");
        assert!(worst < 0.01 * worst_table, "{worst:e} vs {worst_table:e}");
    }
}
