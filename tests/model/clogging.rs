//! Particle clogging of the critical constrictions (issue 5, docs/model.md §7): the closed form,
//! limits, convergence of the ODE and extremes; issue 17: the reach of the particles, the entry
//! cake and the re-routing bounds f Q̇_open ≤ Q̇ ≤ Q̇_open; issue 39 (item 7): the straining law,
//! continuous in particle size, against an independent quadrature, its sweep in size, its limits.

use crate::common::{PAPER, rel};
use proptest::prelude::*;
use sealsim::clogging::{
    CAKE_POROSITY, CaptureLaw, Contamination, SizeDistribution, cake_resistance,
    cake_resistance_in_wedge, kozeny_carman_permeability,
};
use sealsim::contact::{ContactSettings, PerssonContact, QuadratureSettings};
use sealsim::leak::Fidelity;
use sealsim::scenario::Scenario;
use sealsim::simulate::{LifeProblem, LifeResult, SealState, simulate};
use std::path::Path;

const NBR: &str = include_str!("../../scenarios/oring-nbr-water-80c.toml");
const DAY: f64 = 86400.0;

/// The flat seal of the physics review (2026-11-28, U1 and N8): E 7.5 MPa, 2.5 µm rms, ΔP 0.02 MPa,
/// u_c = 0.58 µm, 30 days, at the default fidelity.
const REVIEW_SEAL: &str = "name = \"cake\"
[material]
youngs_modulus = \"7.5 MPa\"
poisson_ratio = 0.5
[surface]
rms_roughness = \"2.5 um\"
hurst_exponent = 0.75
q0 = \"2e4 1/m\"
q1 = \"5e9 1/m\"
[fluid]
viscosity = \"2 mPa*s\"
pressure_difference = \"0.02 MPa\"
[seal]
nominal_pressure = \"0.25 MPa\"
width = \"2 mm\"
length = \"5 mm\"
[simulation]
duration = \"30 day\"
";

/// The paper's flat seal with an elastic rubber: constant Q̇0 and u_c over the whole run.
fn paper_problem() -> LifeProblem {
    let text = format!("{PAPER}[simulation]\nduration = \"30 day\"\npoints_per_decade = 10\n");
    let mut p = Scenario::from_str(&text, Path::new("paper.toml"))
        .unwrap()
        .life;
    p.fidelity = Fidelity::Exact;
    p
}

fn review_problem() -> LifeProblem {
    Scenario::from_str(REVIEW_SEAL, Path::new("review.toml"))
        .unwrap()
        .life
}

fn contaminated(p: LifeProblem, n_p: f64, sizes: SizeDistribution, reroute: bool) -> LifeProblem {
    with_law(p, n_p, sizes, reroute, CaptureLaw::Straining)
}

fn with_law(
    mut p: LifeProblem,
    n_p: f64,
    sizes: SizeDistribution,
    reroute: bool,
    capture: CaptureLaw,
) -> LifeProblem {
    p.contamination = Some(Contamination {
        number_concentration: n_p,
        size_distribution: sizes,
        capture,
        reroute,
        tolerance: 1e-8,
    });
    p
}

fn sieving(p: LifeProblem, n_p: f64, sizes: SizeDistribution, reroute: bool) -> LifeProblem {
    with_law(p, n_p, sizes, reroute, CaptureLaw::Sieving)
}

/// u_c, λ_c at the (uniform) pressure of the paper's seal, by the exact path.
fn paper_junction(p: &LifeProblem) -> (f64, f64) {
    let e_star = p.material.prony.long_term() / (1.0 - p.material.poisson_ratio.powi(2));
    let s = p.initial_profile().peak() / e_star;
    let j = PerssonContact::new(p.spectrum.clone(), p.contact)
        .critical_junction(s)
        .leaking()
        .copied()
        .unwrap();
    (j.u_c, j.lambda_c)
}

fn assert_clean(r: &LifeResult) {
    for row in &r.rows {
        assert!(row.leak_rate.is_finite() && row.leak_rate >= 0.0, "{row:?}");
        assert!(
            (0.0..=1.0).contains(&row.open_fraction),
            "f = {}",
            row.open_fraction
        );
        assert!(row.leaked_volume.is_finite());
    }
}

/// τ_b of an exponential decay fitted at time t.
fn decay_time(r: &LifeResult, t: f64) -> f64 {
    let q0 = r.initial_leak_rate();
    let row = r.rows.iter().find(|row| row.time >= t).unwrap();
    -row.time / (row.leak_rate / q0).ln()
}

/// The sieve (the straining law's limit of zero spread, `capture = "sieving"`): with constant Q̇0
/// and u_c the open fraction decays as exp(−t/τ_b).
#[test]
fn sieve_decays_exponentially_at_a_constant_leak() {
    let p = paper_problem();
    let clean = simulate(&p);
    let q0 = clean.initial_leak_rate();
    assert!(clean.rows.iter().all(|r| r.leak_rate == q0), "constant Q̇0");
    let (u_c, lambda_c) = paper_junction(&p);
    let channels = p.geometry.sealing_length() / lambda_c;
    // particles all larger than u_c and within the reach (issue 17: 1.5 u_c still sieves,
    // F(d_reach) − F(u_c) = 1); τ_b = 2 days
    let tau = 2.0 * DAY;
    let n_p = channels / (tau * q0);
    let sizes = SizeDistribution::Monodisperse {
        diameter: 1.5 * u_c,
    };
    let r = simulate(&sieving(p, n_p, sizes, false));
    assert_clean(&r);
    let mut checked = 0;
    for row in &r.rows {
        if row.time < 0.01 * DAY || row.time > 20.0 * DAY {
            continue;
        }
        let expected = q0 * (-row.time / tau).exp();
        assert!(
            (row.leak_rate / expected - 1.0).abs() < 1e-6,
            "t = {}: {} vs {expected}",
            row.time,
            row.leak_rate
        );
        assert!((row.open_fraction / (-row.time / tau).exp() - 1.0).abs() < 1e-6);
        checked += 1;
    }
    assert!(checked >= 10, "{checked}");
}

/// The sieve: particles below u_c pass untouched, and τ_b is inverse in the concentration.
#[test]
fn sieve_passes_small_particles_and_concentration_scales_tau() {
    let p = paper_problem();
    let clean = simulate(&p);
    let q0 = clean.initial_leak_rate();
    let (u_c, lambda_c) = paper_junction(&p);
    let n_p = p.geometry.sealing_length() / lambda_c / (2.0 * DAY * q0);
    // all particles smaller than u_c: identical history, bit for bit
    for reroute in [false, true] {
        let small = SizeDistribution::Monodisperse {
            diameter: 0.1 * u_c,
        };
        let r = simulate(&sieving(p.clone(), n_p, small, reroute));
        assert_eq!(r.rows.len(), clean.rows.len());
        for (a, b) in r.rows.iter().zip(&clean.rows) {
            assert_eq!(a.leak_rate.to_bits(), b.leak_rate.to_bits());
            assert_eq!(a.open_fraction, 1.0);
        }
    }
    // monodisperse at the median, larger than u_c and within reach: everything is captured,
    // the fastest decay
    let median = 1.5 * u_c;
    let mono = simulate(&sieving(
        p.clone(),
        n_p,
        SizeDistribution::Monodisperse { diameter: median },
        false,
    ));
    let lognormal = simulate(&sieving(
        p.clone(),
        n_p,
        SizeDistribution::LogNormal {
            median,
            geometric_std: 3.0,
        },
        false,
    ));
    let t = 3.0 * DAY;
    assert!(mono.leak_rate_at(t).unwrap() < lognormal.leak_rate_at(t).unwrap());
    // halving the concentration doubles τ_b
    let half = simulate(&sieving(
        p.clone(),
        0.5 * n_p,
        SizeDistribution::Monodisperse { diameter: median },
        false,
    ));
    let ratio = decay_time(&half, t) / decay_time(&mono, t);
    assert!((ratio - 2.0).abs() < 2e-6, "{ratio}");
}

/// The NBR O-ring (time-varying u_c and Q̇) in dirty water: under the sieve the time at which
/// the leaked volume reaches a limit moves by < 1e-4 relative when the ODE tolerance is
/// tightened 100×; the straining law integrates each step in closed form, so the tolerance
/// leaves it bit for bit, and its time moves by < 2e-3 when the time grid is 4× finer.
#[test]
fn ode_result_is_converged() {
    // the shipped ring seals on its ground face (Ra 0.4 µm: no leak to clog for 21 years);
    // clogging needs a leak, so the ring sits on the rough face the scenario had before
    let rough = crate::common::on_former_rough_face(NBR);
    let base = Scenario::from_str(&rough, Path::new("nbr.toml"))
        .unwrap()
        .life;
    for (reroute, law) in [false, true]
        .into_iter()
        .flat_map(|r| [(r, CaptureLaw::Sieving), (r, CaptureLaw::Straining)])
    {
        let sizes = SizeDistribution::LogNormal {
            median: 0.3e-6,
            geometric_std: 1.8,
        };
        let mut p = with_law(base.clone(), 1e12, sizes, reroute, law);
        p.time.duration = 3.0e7;
        p.failure = Default::default();
        let reference = simulate(&p);
        assert_clean(&reference);
        assert!(reference.final_open_fraction() < 0.99, "clogging acts");
        p.failure.max_leaked_volume = Some(0.5 * reference.leaked_volume());
        let time = |tol: f64, points_per_decade: f64| {
            let mut q = p.clone();
            if let Some(c) = q.contamination.as_mut() {
                c.tolerance = tol;
            }
            q.time.points_per_decade = points_per_decade;
            simulate(&q).failure.unwrap().time
        };
        let ppd = p.time.points_per_decade;
        let (coarse, fine) = (time(1e-6, ppd), time(1e-8, ppd));
        match law {
            CaptureLaw::Sieving => assert!(
                (coarse / fine - 1.0).abs() < 1e-4,
                "reroute {reroute}: {coarse} vs {fine}"
            ),
            CaptureLaw::Straining => {
                assert_eq!(coarse, fine, "reroute {reroute}");
                let finer = time(1e-8, 4.0 * ppd);
                eprintln!(
                    "straining, reroute {reroute}: {fine} s at {ppd}/decade, {finer} s at 4×"
                );
                assert!(
                    rel(fine, finer) < 2e-3,
                    "reroute {reroute}: {fine} vs {finer}"
                );
            }
        }
    }
}

#[test]
fn extremes_do_not_overshoot() {
    let p = paper_problem();
    let clean = simulate(&p);
    let (u_c, _) = paper_junction(&p);
    let large = SizeDistribution::Monodisperse {
        diameter: 1.5 * u_c,
    };
    let path = straining_path(&p);
    let (_, sigma) = path.critical;
    for reroute in [false, true] {
        for law in [CaptureLaw::Sieving, CaptureLaw::Straining] {
            // zero concentration: the clean run
            let r = simulate(&with_law(p.clone(), 0.0, large.clone(), reroute, law));
            assert_eq!(r.rows, clean.rows);
            // huge concentration: f never below 0, no NaN
            let r = simulate(&with_law(p.clone(), 1e40, large.clone(), reroute, law));
            assert_clean(&r);
            let first = &r.rows[1];
            match law {
                CaptureLaw::Sieving => {
                    // every channel blocked within the first step: with re-routing the detours
                    // close too (no detour percolates for f ≤ 1 − a_c), so both give no leak
                    assert_eq!(first.leak_rate, 0.0, "reroute {reroute}: {first:?}");
                    assert_eq!(first.state, SealState::Sealed);
                    assert!(r.rows[1..].iter().all(|row| row.leak_rate == 0.0));
                    assert_eq!(r.final_open_fraction(), 0.0);
                }
                CaptureLaw::Straining => {
                    // every channel narrower than the particles is blocked within the first
                    // step, the wider ones never: f is their share of the flow (the
                    // independent quadrature; 1.5 u_c particles block 3 % of it on this
                    // surface, whose critical constrictions spread by 1.7 u_c); the leak is
                    // at most f Q̇0 without re-routing (the entry cake of the 1 % caught
                    // upstream takes more), at most Q̇0 with it
                    let wider = 1.0 - cube_below(1.0, sigma, 1.5) / cube_total(1.0, sigma);
                    assert!(wider > 0.9 && wider < 0.99, "{wider}");
                    let q0 = clean.initial_leak_rate();
                    for row in &r.rows[1..] {
                        assert!(rel(row.open_fraction, wider) < 1e-6, "{row:?} vs {wider}");
                        let bound = if reroute { q0 } else { wider * q0 };
                        assert!(row.leak_rate <= bound * (1.0 + 1e-9), "{row:?}");
                    }
                }
            }
        }
    }
    // all mass at one diameter as a table equals the monodisperse distribution there
    let d = 1.5 * u_c;
    let n_p = 1e15;
    let step = SizeDistribution::Table {
        diameter: vec![d * (1.0 - 1e-12), d],
        cdf: vec![0.0, 1.0],
    };
    for law in [CaptureLaw::Sieving, CaptureLaw::Straining] {
        let a = simulate(&with_law(p.clone(), n_p, step.clone(), false, law));
        let b = simulate(&with_law(
            p.clone(),
            n_p,
            SizeDistribution::Monodisperse { diameter: d },
            false,
            law,
        ));
        assert_clean(&a);
        // (straining: the open share agrees to 1e-12; the leak through the entry cake, whose
        // moments the table carries on its 64 nodes, to 3.5e-8 after 10 days)
        for (x, y) in a.rows.iter().zip(&b.rows) {
            assert!(
                (x.leak_rate - y.leak_rate).abs() <= 1e-7 * y.leak_rate.max(1e-300),
                "{law:?}: {x:?} vs {y:?}"
            );
            assert!((x.open_fraction - y.open_fraction).abs() <= 1e-12);
        }
    }
}

/// u_c → 0: a flat seal pressed almost to its sealing pressure, its critical gap below a
/// nanometre but still wider than a water molecule (0.31 nm: narrower conducts nothing,
/// docs/model.md §8.1); every particle is captured, the decay stays finite and f in [0, 1].
#[test]
fn near_sealing_surface() {
    let mut p = paper_problem();
    let contact = PerssonContact::new(p.spectrum.clone(), p.contact);
    let e_star = p.material.prony.long_term() / (1.0 - p.material.poisson_ratio.powi(2));
    let s_seal = contact.sealing_reduced_pressure();
    let molecule = sealsim::fluid::WATER_MOLECULE_VOLUME.cbrt();
    // the nominal pressure, as a fraction of the sealing one, at which the seal's own junction has
    // u_c = 0.6 nm (u_c falls with the pressure)
    let at = |f: f64| {
        let mut q = p.clone();
        if let sealsim::seal::SealGeometry::Flat {
            nominal_pressure, ..
        } = &mut q.geometry
        {
            *nominal_pressure = f * s_seal * e_star;
        }
        q
    };
    let gap = |f: f64| {
        let q = at(f);
        let s = q.initial_profile().peak() / e_star;
        contact
            .critical_junction(s)
            .leaking()
            .map_or(0.0, |j| j.u_c)
    };
    let (mut lo, mut hi) = (0.01, 1.0);
    assert!(gap(lo) > 0.6e-9);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if gap(mid) > 0.6e-9 {
            lo = mid
        } else {
            hi = mid
        }
    }
    p = at(lo);
    let clean = simulate(&p);
    let (u_c, lambda_c) = paper_junction(&p);
    assert!(u_c < 1e-9 && u_c > molecule, "u_c = {u_c}");
    let q0 = clean.initial_leak_rate();
    assert!(q0 > 0.0);
    let n_p = p.geometry.sealing_length() / lambda_c / (DAY * q0);
    let sizes = SizeDistribution::LogNormal {
        median: 0.5e-6,
        geometric_std: 1.8,
    };
    for reroute in [false, true] {
        for law in [CaptureLaw::Sieving, CaptureLaw::Straining] {
            let r = simulate(&with_law(p.clone(), n_p, sizes.clone(), reroute, law));
            assert_clean(&r);
            // u_c < 1 nm: the 0.5 µm particles hardly reach it (they cake at the entry)
            assert!(r.final_leak_rate() <= q0);
        }
    }
}

/// An upper bound on the cake's series ratio ε = R_cake/R_seal of the paper's flat seal after
/// a clean leaked volume `volume`: every particle larger than u_c caked (d_reach ≥ u_c), at the
/// smallest Sauter diameter the cake can have (≥ u_c, Kozeny–Carman k ∝ d²), in the entry slit
/// L_y ū(ζ = 1) at the seal's pressure, against R_seal = ΔP/Q̇_open.
fn cake_bound(p: &LifeProblem, c: &Contamination, volume: f64, q_open: f64, d_min: f64) -> f64 {
    let e_star = p.material.prony.long_term() / (1.0 - p.material.poisson_ratio.powi(2));
    let s = p.initial_profile().peak() / e_star;
    let entry = PerssonContact::new(p.spectrum.clone(), p.contact)
        .separation(1.0, s)
        .mean;
    let area = p.geometry.sealing_length() * entry;
    // every particle's volume (an upper bound on the cake's)
    let solid = c.cake_volume_fraction(0.0) * volume;
    let r = cake_resistance(p.fluid.viscosity, solid, d_min, CAKE_POROSITY, area);
    r * q_open / p.fluid.pressure_difference
}

#[test]
fn kozeny_carman_closed_form() {
    // φ = 0.4, d = 1 µm: k = 1e-12 · 0.064 / (180 · 0.36) m²
    let k = kozeny_carman_permeability(1e-6, 0.4);
    assert!((k / (1e-12 * 0.064 / 64.8) - 1.0).abs() < 1e-12, "{k}");
    // R = μ V / ((1 − φ) k A²), linear in the deposited volume
    let r1 = cake_resistance(0.03, 1e-12, 1e-6, 0.4, 1e-7);
    let r2 = cake_resistance(0.03, 2e-12, 1e-6, 0.4, 1e-7);
    assert!((r2 / r1 - 2.0).abs() < 1e-12);
    assert!((r1 / (0.03 * 1e-12 / (0.6 * k * 1e-14)) - 1.0).abs() < 1e-12);
}

/// A few % by volume of particles 30× larger than u_c on a flat seal (docs/model.md §7): they
/// stop outside the contact and cake in the wedge the gap opens there, whose resistance grows
/// only with the logarithm of the cake's volume, so 30 days of such dirt change the leaked volume
/// by less than 5 % (as a plug in the entry slit they cut the leak 27×), and less dirt changes it
/// less.
#[test]
fn a_cake_in_its_wedge_is_bounded() {
    let p = paper_problem();
    let clean = simulate(&p);
    let (u_c, _) = paper_junction(&p);
    let d = 30.0 * u_c;
    let volume = |fraction: f64| {
        let n_p = fraction / (std::f64::consts::PI / 6.0 * d.powi(3));
        let dirty = contaminated(
            p.clone(),
            n_p,
            SizeDistribution::Monodisperse { diameter: d },
            true,
        );
        simulate(&dirty).leaked_volume()
    };
    let v_clean = clean.leaked_volume();
    assert!(v_clean > 0.0);
    let mut last = 0.0;
    for fraction in [0.01, 0.03, 0.05] {
        let change = 1.0 - volume(fraction) / v_clean;
        assert!((0.0..0.05).contains(&change), "{fraction}: {change}");
        assert!(
            change >= last,
            "more dirt, more cake: {fraction}: {change} < {last}"
        );
        last = change;
    }
    // the wedge's resistance: the slit plug's as θ → 0, logarithmic in the volume beyond
    let (mu, d32, phi, length, gap) = (0.03, 1e-6, 0.4, 0.1, 1e-6);
    let plug = |v: f64| cake_resistance(mu, v, d32, phi, length * gap);
    let wedge = |v: f64, slope: f64| cake_resistance_in_wedge(mu, v, d32, phi, length, gap, slope);
    for v in [1e-18, 1e-15, 1e-12] {
        assert!((wedge(v, 1e-12) / plug(v) - 1.0).abs() < 1e-6, "{v}");
        assert!(wedge(v, 1.0) <= plug(v) * (1.0 + 1e-12));
    }
    // V_b = 1e-9 m³ against L_y h0² = 1e-13 m³: ln(1 + 2e4)/(2 k L_y), closed form
    let k = kozeny_carman_permeability(d32, phi);
    let bulk = 1e-9 / (1.0 - phi);
    let closed = mu / (2.0 * k * length) * (2.0 * bulk / (length * gap * gap)).ln_1p();
    assert!((wedge(1e-9, 1.0) / closed - 1.0).abs() < 1e-12);
    assert!(
        wedge(1e-6, 1.0) < 2.0 * wedge(1e-9, 1.0),
        "logarithmic, not linear"
    );
}

/// d ≫ the entry gap: the particles cannot get into the contact, so nothing is blocked (f = 1
/// in every row) and they only cake at the entry, so the leaked volume changes by less than the
/// cake's series term allows: 0 ≤ V_clean − V ≤ ε_max V_clean. The review's U1 figure: particles
/// 30 u_c on its flat seal (entry gap ū(1) = 1.85 u_c, roughness 4.3 u_c) change the 30-day volume
/// by less than 0.3 % at 1e13 and 1e19 m⁻³. On the paper's seal, whose entry roughness is 16 u_c,
/// the sieve cakes particles of 30 u_c; the straining law lets a few in unless they are wider
/// than the entry's gap by ten of its spreads.
#[test]
fn particles_far_above_the_entry_gap_only_cake() {
    let review = review_problem();
    let paper = paper_problem();
    let entry = straining_path(&paper).upstream.last().copied().unwrap();
    let cases = [
        (&review, 30.0, CaptureLaw::Straining, 1e13),
        (&review, 30.0, CaptureLaw::Straining, 1e19),
        (&review, 30.0, CaptureLaw::Sieving, 1e13),
        (&paper, 30.0, CaptureLaw::Sieving, 0.0),
        (&paper, entry.0 + 10.0 * entry.1, CaptureLaw::Straining, 0.0),
    ];
    for (p, k, law, n_p) in cases {
        let clean = simulate(p);
        let q0 = clean.initial_leak_rate();
        let u_c = clean.rows[0].u_c.unwrap();
        let (_, lambda_c) = paper_junction(p);
        // 0: the concentration that would close the sieve within 2 days (τ_b) if they reached it
        let n_p = if n_p > 0.0 {
            n_p
        } else {
            p.geometry.sealing_length() / lambda_c / (2.0 * DAY * q0)
        };
        let d = k * u_c;
        for reroute in [false, true] {
            let q = with_law(
                p.clone(),
                n_p,
                SizeDistribution::Monodisperse { diameter: d },
                reroute,
                law,
            );
            let r = simulate(&q);
            assert_clean(&r);
            assert!(
                r.rows.iter().all(|row| row.open_fraction == 1.0),
                "{law:?} {k}"
            );
            let (v_clean, v) = (clean.leaked_volume(), r.leaked_volume());
            let eps = cake_bound(&q, q.contamination.as_ref().unwrap(), v_clean, q0, d);
            eprintln!(
                "{k:.1} u_c, {law:?}, n_p {n_p:.1e}: V/V_clean {:.6}; cake bound ε ≤ {eps:.3e}",
                v / v_clean
            );
            assert!(v <= v_clean * (1.0 + 1e-12), "{v} vs {v_clean}");
            assert!(
                v_clean - v <= eps * v_clean + 1e-12 * v_clean,
                "{v} vs {v_clean}, ε {eps}"
            );
            if std::ptr::eq(p, &review) {
                assert!(1.0 - v / v_clean < 3e-3, "U1: {}", v / v_clean);
            }
        }
    }
}

/// The folded normal density of constriction heights (centre μ, spread σ, in units of u_c).
fn folded(x: f64, mu: f64, sigma: f64) -> f64 {
    let g = |z: f64| (-0.5 * z * z).exp() / (2.0 * std::f64::consts::PI).sqrt();
    (g((x - mu) / sigma) + g((x + mu) / sigma)) / sigma
}

/// `∫_a^b f` by the composite Simpson rule on 20 000 panels.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let n = 20_000;
    let h = (b - a) / n as f64;
    let mut sum = f(a) + f(b);
    for i in 1..n {
        sum += f(a + h * i as f64) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    sum * h / 3.0
}

/// E\[u³; u < y\] of the folded normal, by quadrature (nothing of it lies beyond μ + 14σ).
fn cube_below(mu: f64, sigma: f64, y: f64) -> f64 {
    let top = y.min(mu + 14.0 * sigma);
    if top <= 0.0 {
        return 0.0;
    }
    simpson(|x| x.powi(3) * folded(x, mu, sigma), 0.0, top)
}

fn cube_total(mu: f64, sigma: f64) -> f64 {
    cube_below(mu, sigma, f64::INFINITY)
}

/// The constrictions of the straining law on a flat seal, built here from the contact theory
/// alone (docs/model.md §7): the critical level's spread h_rms(ζc)/u1(ζc), and upstream the
/// octaves ζc/2^k > 1, (u1(ζ), h_rms(ζ))/u1(ζc), then the entry, (ū(1), h_rms)/u1(ζc) — on the
/// clogging path's quadrature (panels of 2 in ln t, 4 nodes), ζc from the seal's own settings.
struct StrainingPath {
    critical: (f64, f64),
    upstream: Vec<(f64, f64)>,
}

fn straining_path(p: &LifeProblem) -> StrainingPath {
    let e_star = p.material.prony.long_term() / (1.0 - p.material.poisson_ratio.powi(2));
    let s = p.initial_profile().peak() / e_star;
    let zeta_c = PerssonContact::new(p.spectrum.clone(), p.contact)
        .critical_junction(s)
        .leaking()
        .unwrap()
        .zeta_c;
    let coarse = PerssonContact::new(
        p.spectrum.clone(),
        ContactSettings {
            quadrature: QuadratureSettings {
                panel_width: 2.0,
                order: 4,
            },
            ..p.contact
        },
    );
    let q0 = p.spectrum.q0();
    let u1c = coarse.separation(zeta_c, s).u1();
    let h = |zeta: f64| p.spectrum.rms_roughness_above(zeta * q0) / u1c;
    let mut upstream = Vec::new();
    let mut zeta = 0.5 * zeta_c;
    while zeta > 1.0 {
        upstream.push((coarse.separation(zeta, s).u1() / u1c, h(zeta)));
        zeta *= 0.5;
    }
    upstream.push((
        coarse.separation(1.0, s).mean / u1c,
        p.spectrum.rms_roughness() / u1c,
    ));
    StrainingPath {
        critical: (1.0, h(zeta_c)),
        upstream,
    }
}

/// S(y): the chance to pass every upstream constriction, each met once, captured with the share
/// of its flow (∝ u³) through heights below y.
fn survival_reference(path: &StrainingPath, y: f64) -> f64 {
    path.upstream
        .iter()
        .map(|&(mu, sigma)| 1.0 - cube_below(mu, sigma, y) / cube_total(mu, sigma))
        .product()
}

/// Issue 39: the straining law at a constant Q̇0 and u_c (the paper's elastic flat seal, no
/// re-routing) against an independent quadrature of docs/model.md §7: a channel of relative
/// height x < y = d/u_c is open with probability exp(−x³ n_p κ S(y) t), κ = Q̇0 λ_c/(L_y E[x³]),
/// the wider ones stay open, so f(t) = ∫_0^y W(x) exp(−x³ n_p κ S t) dx + ∫_y^∞ W(x) dx with
/// W = x³ g/E[x³] — to 1e-6 for particles of 0.7, 1.5 and 3 u_c, the leak rate within the entry
/// cake's bound of f Q̇0.
#[test]
fn straining_matches_an_independent_quadrature_at_a_constant_leak() {
    let p = paper_problem();
    let clean = simulate(&p);
    let q0 = clean.initial_leak_rate();
    assert!(clean.rows.iter().all(|r| r.leak_rate == q0), "constant Q̇0");
    let (u_c, lambda_c) = paper_junction(&p);
    let path = straining_path(&p);
    let (_, sigma) = path.critical;
    let m3 = cube_total(1.0, sigma);
    let kappa = q0 * lambda_c / (p.geometry.sealing_length() * m3);
    for y in [0.7, 1.5, 3.0] {
        let survival = survival_reference(&path, y);
        assert!(survival > 0.01 && survival <= 1.0, "{y}: {survival}");
        // a channel of the mean cube is blocked after ≈ 2 days
        let n_p = 1.0 / (kappa * survival * 2.0 * DAY);
        let sizes = SizeDistribution::Monodisperse { diameter: y * u_c };
        let q = contaminated(p.clone(), n_p, sizes, false);
        let r = simulate(&q);
        assert_clean(&r);
        let eps = cake_bound(
            &q,
            q.contamination.as_ref().unwrap(),
            clean.leaked_volume(),
            q0,
            y * u_c,
        );
        let wider = 1.0 - cube_below(1.0, sigma, y) / m3;
        let mut checked = 0;
        for row in &r.rows {
            if row.time < 0.01 * DAY {
                continue;
            }
            let rate = n_p * kappa * survival * row.time;
            let blocked = simpson(
                |x| x.powi(3) * folded(x, 1.0, sigma) / m3 * (-x.powi(3) * rate).exp(),
                0.0,
                y,
            );
            let f = blocked + wider;
            assert!(
                rel(row.open_fraction, f) < 1e-6,
                "y {y}, t {}: {} vs {f}",
                row.time,
                row.open_fraction
            );
            assert!(row.leak_rate <= f * q0 * (1.0 + 1e-9));
            assert!(
                row.leak_rate >= f * q0 / (1.0 + eps) * (1.0 - 1e-9),
                "ε ≤ {eps}"
            );
            checked += 1;
        }
        assert!(checked >= 10, "{checked}");
        // it did clog: in 30 days, more than half of the flow the particles can block
        let last = r.final_open_fraction();
        eprintln!("{y} u_c: S {survival:.4}, wider share {wider:.4}, f after 30 days {last:.4}");
        assert!(last < 1.0 - 0.5 * (1.0 - wider), "{last} vs {wider}");
    }
}

/// Issue 39 (the review's N8): monodisperse particles from 0.5 to 5 u_c in steps of 10 % on the
/// review's flat seal, at 1e13 and 1e11 m⁻³: the 30-day leaked volume changes by no more than a
/// factor 3 between neighbouring sizes. The sieve (the law before, `capture = "sieving"`) put
/// five decades between 0.99 and 1.01 u_c: on the same grid it jumps by more than 1e4.
#[test]
fn leaked_volume_is_continuous_in_particle_size() {
    let p = review_problem();
    let clean = simulate(&p);
    let v_clean = clean.leaked_volume();
    let u_c = clean.rows[0].u_c.unwrap();
    assert!(rel(u_c, 0.5797e-6) < 1e-3, "the review's u_c: {u_c}");
    let sizes: Vec<f64> = (0..25).map(|i| 0.5 * 1.1f64.powi(i)).collect();
    assert!(sizes[24] > 4.9 && sizes[24] <= 5.0);
    let volumes = |n_p: f64, law: CaptureLaw| -> Vec<f64> {
        sizes
            .iter()
            .map(|k| {
                let d = SizeDistribution::Monodisperse { diameter: k * u_c };
                simulate(&with_law(p.clone(), n_p, d, true, law)).leaked_volume() / v_clean
            })
            .collect()
    };
    let worst = |v: &[f64]| {
        v.windows(2)
            .map(|w| (w[0] / w[1]).max(w[1] / w[0]))
            .fold(1.0f64, f64::max)
    };
    for n_p in [1e13, 1e11] {
        let v = volumes(n_p, CaptureLaw::Straining);
        for (k, x) in sizes.iter().zip(&v) {
            eprintln!("n_p {n_p:.0e}, {k:.3} u_c: V/V_clean {x:.4e}");
        }
        assert!(v.iter().all(|x| *x > 0.0 && *x <= 1.0 + 1e-9), "{v:?}");
        let w = worst(&v);
        eprintln!("n_p {n_p:.0e}: largest step between neighbours ×{w:.3}");
        assert!(w <= 3.0, "n_p {n_p:e}: ×{w}");
        // and it does clog: the largest of these particles cut the volume more than 10×
        assert!(v[24] < 0.1, "{}", v[24]);
    }
    let sieve = volumes(1e13, CaptureLaw::Sieving);
    assert!(worst(&sieve) > 1e4, "the sieve's cliff: ×{}", worst(&sieve));
}

/// The limits of the straining law on the review's seal: (i) d → 0, no capture — the blocked
/// share of the flow, once the narrow channels are saturated, is their flow share, which
/// vanishes as d⁴ (doubling d from 0.02 to 0.04 u_c multiplies it by ≈ 16), and particles of
/// 0.01 u_c move the volume by less than 1e-6; (ii) more particles never leak more: the volume
/// and the final open fraction do not rise with the concentration, at 0.8, 2, 5 and 8 u_c.
#[test]
fn straining_limits_small_particles_and_concentration() {
    let p = review_problem();
    let clean = simulate(&p);
    let v_clean = clean.leaked_volume();
    let u_c = clean.rows[0].u_c.unwrap();
    let run = |k: f64, n_p: f64| {
        let d = SizeDistribution::Monodisperse { diameter: k * u_c };
        simulate(&contaminated(p.clone(), n_p, d, false))
    };
    let loss = |k: f64| {
        let r = run(k, 1e17);
        (
            1.0 - r.leaked_volume() / v_clean,
            1.0 - r.final_open_fraction(),
        )
    };
    let (l1, l2, l4) = (loss(0.01), loss(0.02), loss(0.04));
    eprintln!("saturated (volume, blocked share): {l1:?} (0.01 u_c), {l2:?} (0.02), {l4:?} (0.04)");
    assert!((0.0..1e-6).contains(&l1.0), "{l1:?}");
    // the blocked share as d⁴; the volume as fast or faster (the few caught upstream, also
    // ∝ d⁴, cake at the entry with a resistance per volume ∝ 1/d²)
    assert!(
        l2.1 > 0.0 && (14.0..18.0).contains(&(l4.1 / l2.1)),
        "{l2:?} {l4:?}"
    );
    assert!(l2.0 > 0.0 && l4.0 / l2.0 >= 14.0, "{l2:?} {l4:?}");
    for k in [0.8, 2.0, 5.0, 8.0] {
        let mut last = (v_clean * (1.0 + 1e-12), 1.0);
        for n_p in [1e9, 1e11, 1e13, 1e15] {
            let r = run(k, n_p);
            let now = (r.leaked_volume(), r.final_open_fraction());
            assert!(
                now.0 <= last.0 * (1.0 + 1e-12),
                "{k} u_c, {n_p:e}: {now:?} after {last:?}"
            );
            assert!(
                now.1 <= last.1 + 1e-12,
                "{k} u_c, {n_p:e}: {now:?} after {last:?}"
            );
            last = now;
        }
        assert!(last.0 < v_clean, "{k} u_c clogs at 1e15");
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    /// Issue 17: with re-routing on, f Q̇_open/(1 + ε) ≤ Q̇ ≤ Q̇_open at every history point over
    /// concentrations, size distributions (log-normal medians 0.3–30 u_c, σg 1.2–3, and
    /// monodisperse) and contact pressures of the paper's flat seal; ε the cake bound above
    /// (0 when no particle exceeds the reach).
    #[test]
    fn rerouted_leak_stays_within_its_bounds(
        tau_days in 0.05f64..50.0,
        median in 0.3f64..30.0,
        sigma in 1.2f64..3.0,
        mono in any::<bool>(),
        pressure in 0.5f64..1.5,
    ) {
        let mut p = paper_problem();
        if let sealsim::seal::SealGeometry::Flat { nominal_pressure, .. } = &mut p.geometry {
            *nominal_pressure *= pressure;
        }
        let clean = simulate(&p);
        let q_open = clean.initial_leak_rate();
        prop_assume!(q_open > 0.0);
        let (u_c, lambda_c) = paper_junction(&p);
        let n_p = p.geometry.sealing_length() / lambda_c / (tau_days * DAY * q_open);
        let sizes = if mono {
            SizeDistribution::Monodisperse { diameter: median * u_c }
        } else {
            SizeDistribution::LogNormal { median: median * u_c, geometric_std: sigma }
        };
        let q = contaminated(p.clone(), n_p, sizes, true);
        let r = simulate(&q);
        assert_clean(&r);
        // the cake's Sauter diameter is at least the distribution's own: the share of each size
        // that stops upstream, 1 − S(d), does not fall with d (nor does it for the sieve)
        let sauter = q.contamination.as_ref().map(|c| {
            c.size_distribution.partial_moment(3, 0.0) / c.size_distribution.partial_moment(2, 0.0)
        }).unwrap();
        let eps = cake_bound(&q, q.contamination.as_ref().unwrap(), clean.leaked_volume(), q_open, sauter.min(u_c));
        for row in &r.rows {
            let f = row.open_fraction;
            prop_assert!(row.leak_rate <= q_open * (1.0 + 1e-9), "{row:?}");
            prop_assert!(
                row.leak_rate >= f * q_open / (1.0 + eps) * (1.0 - 1e-9),
                "Q̇ {} < f Q̇_open {} (ε ≤ {eps})", row.leak_rate, f * q_open
            );
        }
    }
}
