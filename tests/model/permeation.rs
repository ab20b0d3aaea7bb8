//! Permeation through the rubber (docs/model.md §13): Fick's steady closed form, the transient of
//! an initially empty slab against an independent finite-difference solution of the diffusion
//! equation, the time lag, Arrhenius scaling, the barrer conversion, the squeezed-cord geometry,
//! and properties over wide ranges. Expected values are worked out in the comments.

use proptest::prelude::*;
use sealsim::permeation::{
    self, BARRER, BARRER_STP_VOLUME, PermeationPath, arrhenius_factor, permeability_from,
    squeezed_cord, steady_flux, time_lag, transient_amount, transient_flux_ratio,
};
use std::f64::consts::{LN_2, PI};

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

/// Explicit finite differences for u_τ = u_xx on [0, 1], u(0) = 1, u(1) = 0, u = 0 at τ = 0 —
/// the slab in units of ℓ, C1 and ℓ²/D. Returns (τ, cumulative outflow at x = 1, outflow flux)
/// at each requested τ; the flux is the second-order one-sided −u_x(1) and the outflow its
/// trapezoidal time integral.
fn finite_difference(taus: &[f64]) -> Vec<(f64, f64, f64)> {
    let n = 100;
    let dx = 1.0 / n as f64;
    let dt = 0.4 * dx * dx;
    let mut u = vec![0.0; n + 1];
    u[0] = 1.0;
    let flux = |u: &[f64]| (3.0 * u[n] - 4.0 * u[n - 1] + u[n - 2]) / (-2.0 * dx);
    let (mut tau, mut amount, mut previous) = (0.0, 0.0, 0.0);
    let mut out = Vec::new();
    let mut next = vec![0.0; n + 1];
    for &target in taus {
        while tau < target - 1e-12 {
            let step = dt.min(target - tau);
            next[0] = 1.0;
            next[n] = 0.0;
            for i in 1..n {
                next[i] = u[i] + step / (dx * dx) * (u[i + 1] - 2.0 * u[i] + u[i - 1]);
            }
            std::mem::swap(&mut u, &mut next);
            let current = flux(&u);
            amount += 0.5 * (previous + current) * step;
            previous = current;
            tau += step;
        }
        out.push((tau, amount, previous));
    }
    out
}

#[test]
fn steady_slab_is_ficks_closed_form() {
    // D = 2e-10 m²/s, S = 3e-6 mol/(m³·Pa), ℓ = 2 mm, p 1e5 → 2e4 Pa:
    // C = S p: 0.3 and 0.06 mol/m³; J = D ΔC/ℓ = 2e-10 · 0.24 / 2e-3 = 2.4e-8 mol/(m²·s)
    let pi = permeability_from(2e-10, 3e-6);
    assert!(close(steady_flux(pi, 1e5, 2e4, 2e-3), 2.4e-8, 1e-12));
    // a slab of 0.01 m² carries 2.4e-10 mol/s
    let slab = PermeationPath::slab(0.01, 2e-3).expect("slab");
    assert!(close(slab.steady_molar_flow(pi, 1e5, 2e4), 2.4e-10, 1e-12));
    // the finite-difference outflow flux at long times is the steady one (u_x = −1)
    let fd = finite_difference(&[3.0]);
    assert!((fd[0].2 - 1.0).abs() < 1e-6, "{}", fd[0].2);
}

#[test]
fn transient_matches_an_independent_finite_difference_solution() {
    let taus = [0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0];
    for (tau, amount, flux) in finite_difference(&taus) {
        // the FD error is O(dx²) ≈ 1e-4 (and O(dt) on the trapezoid); the series is exact
        assert!(
            (transient_amount(tau) - amount).abs() < 3e-4,
            "amount at τ = {tau}: series {} FD {amount}",
            transient_amount(tau)
        );
        assert!(
            (transient_flux_ratio(tau) - flux).abs() < 2e-3,
            "flux at τ = {tau}: series {} FD {flux}",
            transient_flux_ratio(tau)
        );
    }
}

#[test]
fn series_converges_term_by_term() {
    // partial sums of the Fourier series of Q/(ℓC1) at τ = 0.2 approach the function; the
    // remainder after N terms is bounded by the first omitted term (alternating, decreasing)
    let tau = 0.2;
    let exact = transient_amount(tau);
    let mut sum = tau - 1.0 / 6.0;
    for n in 1..8 {
        let nf = n as f64;
        let sign = if n % 2 == 1 { -1.0 } else { 1.0 };
        sum -= 2.0 / (PI * PI) * sign / (nf * nf) * (-nf * nf * PI * PI * tau).exp();
        let next = (n + 1) as f64;
        let bound = 2.0 / (PI * PI) / (next * next) * (-next * next * PI * PI * tau).exp();
        assert!(
            (sum - exact).abs() <= bound * (1.0 + 1e-9) + 1e-15,
            "N = {n}"
        );
    }
}

#[test]
fn long_time_amount_is_the_line_with_the_time_lag_intercept() {
    // Q/(ℓC1) → τ − 1/6: zero at τ = 1/6, i.e. t = ℓ²/(6D)
    for tau in [1.5, 3.0, 10.0] {
        assert!((transient_amount(tau) - (tau - 1.0 / 6.0)).abs() < 1e-6);
    }
    // ℓ = 3.7 mm, D = 3e-10 m²/s: t_lag = 1.369e-5/1.8e-9 = 7605.6 s
    assert!(close(time_lag(3.7e-3, 3e-10), 1.369e-5 / 1.8e-9, 1e-12));
    // a path's permeated moles tend to steady flow × (t − t_lag)
    let path = PermeationPath::slab(1e-3, 3.7e-3).expect("slab");
    let (pi, d) = (1e-15, 3e-10);
    let t_lag = path.time_lag(d);
    for t in [10.0 * t_lag, 30.0 * t_lag] {
        let moles = path.permeated_moles(pi, d, 1e5, 0.0, t);
        let steady = path.steady_molar_flow(pi, 1e5, 0.0);
        let line = steady * (t - t_lag);
        // the remainder is the first exponential term: steady·(ℓ²/D)·(2/π²)·exp(−π²τ)
        let tau = d * t / (3.7e-3 * 3.7e-3);
        let bound = steady * 3.7e-3 * 3.7e-3 / d * 2.0 / (PI * PI) * (-PI * PI * tau).exp();
        assert!(
            (moles - line).abs() <= bound * (1.0 + 1e-6),
            "{moles} vs {line}"
        );
        // the n = 1 term, −(2/π²)(−1)exp(−π²τ), is positive: the curve approaches from above
        assert!(moles >= line * (1.0 - 1e-12));
    }
    // and the flow at time t tends to the steady flow, from below
    let steady = path.steady_molar_flow(pi, 1e5, 0.0);
    assert!(path.molar_flow_at(pi, Some(d), 1e5, 0.0, 0.1 * t_lag) < 1e-3 * steady);
    assert!(close(
        path.molar_flow_at(pi, Some(d), 1e5, 0.0, 20.0 * t_lag),
        steady,
        1e-9
    ));
    assert_eq!(path.molar_flow_at(pi, None, 1e5, 0.0, 1.0), steady);
}

#[test]
fn arrhenius_scaling_is_exact() {
    // E = R ln2 / (1/300 − 1/310) doubles the coefficient from 300 K to 310 K
    let e = permeation::GAS_CONSTANT * LN_2 / (1.0 / 300.0 - 1.0 / 310.0);
    assert!(close(arrhenius_factor(e, 310.0, 300.0), 2.0, 1e-12));
    assert!(close(arrhenius_factor(e, 300.0, 310.0), 0.5, 1e-12));
    assert_eq!(arrhenius_factor(e, 300.0, 300.0), 1.0);
    // a data row: the ratio at two temperatures is the factor between them, whatever T_ref
    let row = permeation::data("nbr", "hydrogen").expect("row");
    let ratio = row.permeability_at(353.15) / row.permeability_at(263.15);
    assert!(close(
        ratio,
        arrhenius_factor(row.permeability_activation, 353.15, 263.15),
        1e-12
    ));
    // 36 kJ/mol from 23 °C to 80 °C: exp(36000/8.3145 · (1/296.15 − 1/353.15)) = exp(2.3599) ≈ 10.59
    let hot = row.permeability_at(353.15) / row.permeability;
    assert!((hot - 10.59).abs() < 0.01, "{hot}");
}

#[test]
fn barrer_conversion() {
    // 1 cmHg = 101325/76 Pa; 1 barrer = 1e-10 cm³(STP)·cm/(cm²·s·cmHg)
    let cm_hg = 101_325.0 / 76.0;
    let volume = 1e-10 * 1e-6 * 1e-2 / (1e-4 * cm_hg);
    assert!(close(BARRER_STP_VOLUME, volume, 1e-6));
    // the Taylor & Francis form: 7.5e-14 cm³·cm/(cm²·Pa·s) = 7.5e-14 · 1e-6 · 1e-2/1e-4 m³·m/(m²·Pa·s)
    assert!(close(BARRER_STP_VOLUME, 7.5e-18, 1e-3));
    // 22.414 L/mol at STP → 3.346e-16 mol·m/(m²·s·Pa)
    assert!(close(BARRER, volume / 0.022_414, 1e-4));
}

#[test]
fn squeezed_cord_conserves_area_and_has_the_round_limit() {
    let d = 3.53e-3;
    for eps in [0.0, 0.1, 0.25, 0.4] {
        let (h, w) = squeezed_cord(d, eps);
        assert!(close(h * w, PI * d * d / 4.0, 1e-12));
        assert!(close(h, d * (1.0 - eps), 1e-12));
    }
    let (h, w) = squeezed_cord(d, 0.0);
    assert_eq!(h, d);
    assert!(close(w, PI * d / 4.0, 1e-12));
    // whole ring: πD·Π·h·Δp/w = 4 D (1 − ε)² Π Δp, independent of the cord size
    let (mean, pi, dp) = (50.75e-3, 1e-15, 1e5);
    for eps in [0.0, 0.25] {
        let ring = PermeationPath::o_ring(d, mean, eps).expect("ring");
        let expect = 4.0 * mean * (1.0 - eps) * (1.0 - eps) * pi * dp;
        assert!(close(ring.steady_molar_flow(pi, dp, 0.0), expect, 1e-12));
        let bigger = PermeationPath::o_ring(2.0 * d, mean, eps).expect("ring");
        assert!(close(bigger.steady_molar_flow(pi, dp, 0.0), expect, 1e-12));
        // but the time lag grows with the path: w² ∝ d²
        assert!(close(
            bigger.time_lag(3e-10),
            4.0 * ring.time_lag(3e-10),
            1e-12
        ));
    }
    // a flat gasket: 2 mm edge around 0.3 m, across a 10 mm land: Π·(6e-4 m²)·Δp/0.01 m
    let gasket = PermeationPath::gasket(2e-3, 10e-3, 0.3).expect("gasket");
    assert!(close(
        gasket.steady_molar_flow(pi, dp, 0.0),
        pi * 6e-4 * dp / 0.01,
        1e-12
    ));
}

#[test]
fn fkm_air_is_within_an_order_of_the_pfeiffer_figure() {
    // Pfeiffer Vacuum know-how book §3.2.2.1: an FKM seal of DN 500 ISO-K lets ≈ 4e-7 Pa·m³/s of
    // atmospheric air (60 % humidity) permeate. Taken here: mean diameter ≈ 0.51 m (ASSUMED),
    // 25 % squeeze (ASSUMED), 1 bar of air against vacuum, 23 °C. The table is illustrative: the
    // check is a factor of 10 either way, not a calibration.
    let row = permeation::data("fkm", "air").expect("row");
    let ring = PermeationPath::o_ring(8e-3, 0.51, 0.25).expect("ring");
    let pv = permeation::pv_throughput(ring.steady_molar_flow(row.permeability, 1e5, 0.0), 296.15);
    assert!(pv > 4e-8 && pv < 4e-6, "{pv:e} Pa·m³/s");
}

proptest! {
    #[test]
    fn flux_is_linear_in_the_pressure_difference_and_falls_with_thickness(
        thickness in 1e-4f64..0.1,
        pi in 1e-18f64..1e-12,
        dp in 1.0f64..1e8,
        k in 0.01f64..100.0,
    ) {
        let j = steady_flux(pi, dp, 0.0, thickness);
        prop_assert!(j > 0.0);
        prop_assert!(close(steady_flux(pi, k * dp, 0.0, thickness), k * j, 1e-12));
        // only the difference matters
        prop_assert!(close(steady_flux(pi, dp + 3e5, 3e5, thickness), j, 1e-9));
        prop_assert!(steady_flux(pi, dp, 0.0, 2.0 * thickness) < j);
    }

    #[test]
    fn transient_is_monotone_and_bounded(
        thickness in 1e-4f64..0.05,
        d in 1e-12f64..1e-8,
        t in 1.0f64..1e9,
        dp in 1.0f64..1e8,
    ) {
        let tau = d * t / (thickness * thickness);
        let later = 1.5 * tau;
        let (q, f) = (transient_amount(tau), transient_flux_ratio(tau));
        prop_assert!(q.is_finite() && f.is_finite());
        prop_assert!((0.0..=1.0).contains(&f));
        prop_assert!(transient_flux_ratio(later) >= f - 1e-15);
        prop_assert!(transient_amount(later) >= q);
        // between the steady line and the line through the origin
        prop_assert!(q <= tau + 1e-15 && q >= tau - 1.0 / 6.0 - 1e-12);
        let path = PermeationPath::slab(1e-4, thickness).expect("slab");
        let flow = path.molar_flow_at(1e-15, Some(d), dp, 0.0, t);
        let steady = path.steady_molar_flow(1e-15, dp, 0.0);
        prop_assert!(flow >= 0.0 && flow <= steady * (1.0 + 1e-12));
        // linear in Δp at every time
        let twice = path.molar_flow_at(1e-15, Some(d), 2.0 * dp, 0.0, t);
        prop_assert!((twice - 2.0 * flow).abs() <= 1e-12 * twice.abs().max(1e-300));
    }

    #[test]
    fn o_ring_flow_falls_with_squeeze(
        d in 1e-3f64..1e-2,
        mean in 5e-3f64..1.0,
        eps in 0.0f64..0.5,
    ) {
        let a = PermeationPath::o_ring(d, mean, eps).expect("ring");
        let b = PermeationPath::o_ring(d, mean, eps + 0.05).expect("ring");
        prop_assert!(b.steady_molar_flow(1e-15, 1e5, 0.0) < a.steady_molar_flow(1e-15, 1e5, 0.0));
        prop_assert!(close(a.area * a.length, PI * mean * PI * d * d / 4.0, 1e-12));
    }
}

const HELIUM_FLANGE: &str = include_str!("../../scenarios/helium-leak-test-flange.toml");
const NBR_WATER: &str = include_str!("../../scenarios/oring-nbr-water-80c.toml");

/// J/J_ss of an initially empty slab at τ = D t/ℓ², written out here from the Fourier series of
/// docs/model.md §13.2 (independent of the library's two-branch evaluation).
fn flux_ratio_series(tau: f64) -> f64 {
    1.0 + 2.0
        * (1..200)
            .map(|n| {
                let n = n as f64;
                let sign = if n as i64 % 2 == 1 { -1.0 } else { 1.0 };
                sign * (-n * n * PI * PI * tau).exp()
            })
            .sum::<f64>()
}

#[test]
fn the_helium_flange_run_carries_permeation_building_up_to_the_closed_form() {
    use sealsim::scenario::Scenario;
    use sealsim::seal::SealGeometry;
    use sealsim::simulate::{FailureMode, simulate};
    use std::path::Path;
    let mut problem = Scenario::from_str(HELIUM_FLANGE, Path::new("helium.toml"))
        .unwrap()
        .life;
    let seal = problem.permeation.clone().expect("FKM + helium has data");
    let SealGeometry::ORing {
        cross_section,
        mean_diameter,
        squeeze,
    } = problem.geometry
    else {
        panic!("an O-ring")
    };
    // 23 °C; 1 bar of helium against 1e-6 mbar = 1e-4 Pa
    let (temperature, pa, pb) = (296.15, 1e5, 1e-4);
    assert!(close(seal.p_high, pa, 1e-12) && close(seal.p_low, pb, 1e-9));
    let data = permeation::data("fkm", "helium").unwrap();
    let pi = data.permeability_at(temperature);
    let d = data.diffusivity_at(temperature).unwrap();
    let path = PermeationPath::o_ring(cross_section, mean_diameter, squeeze).unwrap();
    let r = permeation::GAS_CONSTANT;
    let steady = path.steady_molar_flow(pi, pa, pb) * r * temperature;
    // the hand value of docs/model.md §13.3: ṅ = 4·D_mean·(1 − ε)²·Π·Δp, Q = ṅ R T
    let hand = 4.0 * mean_diameter * (1.0 - squeeze).powi(2) * pi * (pa - pb) * r * temperature;
    assert!(close(steady, hand, 1e-9), "{steady} vs {hand}");
    // FKM helium = 436e-8 cm²/s · 0.093/76 cmHg = 53.4 barrer, D ≈ 50.7 mm, ε = 0.25:
    // ≈ 5.0e-7 Pa·m³/s (the NBR headline's 2.5e-8 × 53.4/2.70)
    assert!((4.5e-7..5.5e-7).contains(&steady), "{steady}");

    // the shipped day: 0 at installation, rising, each row the build-up at its time
    let day = simulate(&problem);
    assert_eq!(day.rows[0].permeation, Some(0.0));
    let lag = path.time_lag(d);
    for pair in day.rows.windows(2) {
        let (a, b) = (pair[0].permeation.unwrap(), pair[1].permeation.unwrap());
        assert!(b >= a && b <= steady * (1.0 + 1e-12), "{a} {b}");
    }
    for row in &day.rows {
        let tau = row.time / (6.0 * lag);
        let expected = steady * flux_ratio_series(tau).clamp(0.0, 1.0);
        let got = row.permeation.unwrap();
        assert!(
            (got - expected).abs() <= 1e-9 * steady,
            "t = {}: {got} vs {expected}",
            row.time
        );
    }
    // at t = t_lag (τ = 1/6) the flow is the library's molar_flow_at and the series' value
    let at_lag = seal.throughput(lag, temperature);
    let library = path.molar_flow_at(pi, Some(d), pa, pb, lag) * r * temperature;
    assert!(close(at_lag, library, 1e-12));
    assert!(close(at_lag, steady * flux_ratio_series(1.0 / 6.0), 1e-9));
    // the interface seals, so the criterion (1e-9 mbar·L/s = 1e-10 Pa·m³/s) is crossed by the
    // permeation alone: a helium detector sees the sum
    assert!(day.rows.iter().all(|r| r.leak_rate == 0.0));
    let failure = day.failure.expect("the permeation crosses 1e-10 Pa·m³/s");
    assert_eq!(failure.mode, FailureMode::LeakRate);
    let at_failure = seal.throughput(failure.time, temperature);
    assert!(close(at_failure, 1e-10, 1e-6), "{at_failure}");

    // a month: the steady closed form (τ ≈ 57, the transient below 1e-300)
    problem.time.duration = 30.0 * 86400.0;
    let month = simulate(&problem);
    let last = month.rows.last().unwrap().permeation.unwrap();
    assert!(close(last, steady, 1e-9), "{last} vs {steady}");
}

#[test]
fn a_liquid_run_carries_no_permeation() {
    use sealsim::scenario::Scenario;
    use sealsim::simulate::simulate;
    use std::path::Path;
    let problem = Scenario::from_str(NBR_WATER, Path::new("nbr.toml"))
        .unwrap()
        .life;
    assert!(problem.permeation.is_none());
    let mut short = problem;
    short.time.duration = 86400.0;
    assert!(simulate(&short).rows.iter().all(|r| r.permeation.is_none()));
}
