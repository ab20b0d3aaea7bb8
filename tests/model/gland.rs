//! Groove-seated O-rings (docs/model.md §6.2): stretch, squeeze and gland fill of a face, a
//! piston and a rod gland against hand calculations; the AS568 table against rows copied by
//! hand from its source; the housing's thermal strain. Expected values are worked out in the
//! comments, never copied from the program's output.

use sealsim::gland::{GlandKind, Housing};
use sealsim::scenario::as568;
use sealsim::scenario::{Scenario, ScenarioError};
use sealsim::seal::SealGeometry;
use std::f64::consts::PI;
use std::path::Path;

/// A scenario whose `[seal]` is `seal` (the `[seal]` header is line 12), with the compound's
/// ageing on (so that the only warnings are the gland's).
fn scenario(seal: &str) -> String {
    format!(
        r#"name = "gland"
[material]
library = "nbr-70"
[surface]
rms_roughness = "0.8 um"
hurst_exponent = 0.7
q0 = "3e5 1/m"
q1 = "1e10 1/m"
[fluid]
viscosity = "1 mPa*s"
pressure_difference = "2 bar"
[seal]
kind = "o-ring"
{seal}
[ageing]
"#
    )
}

fn load(seal: &str) -> Result<Scenario, ScenarioError> {
    Scenario::from_str(&scenario(seal), Path::new("dir/g.toml"))
}

/// (cross-section, mean diameter, squeeze) of the life geometry.
fn oring(s: &Scenario) -> (f64, f64, f64) {
    match s.life.geometry {
        SealGeometry::ORing {
            cross_section,
            mean_diameter,
            squeeze,
        } => (cross_section, mean_diameter, squeeze),
        SealGeometry::Flat { .. } => panic!("an O-ring"),
    }
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs()
}

#[test]
fn face_gland_by_hand() {
    // AS568-214: ID 0.984 ± 0.010 in, cord 0.139 ± 0.004 in; no groove diameter given: the ring
    // lies at its free diameters, stretch 0, d′ = d = 0.139 × 25.4 = 3.5306 mm.
    // The cord is squeezed into groove depth + flange separation: h = 2.6 + 0.05 = 2.65 mm.
    // ε = 1 − 2.65/3.5306 = 0.249419362…
    // D = ID + d = 24.9936 + 3.5306 = 28.5242 mm.
    // fill = (π 3.5306²/4)/(2.65 × 4.8) = 9.79001/12.72 = 0.769662…
    // range, h = 2.65 ± 0.05, d = 3.5306 ± 0.1016 (0.135 and 0.143 in):
    //   min ε = 1 − 2.70/(0.135 × 25.4) = 1 − 2.70/3.429 = 0.212598…
    //   max ε = 1 − 2.60/(0.143 × 25.4) = 1 − 2.60/3.6322 = 0.284180…
    let s = load(
        "gland = \"face\"\nsize = \"AS568-214\"\ngroove_depth = \"2.6 mm\"\n\
         groove_depth_tolerance = \"0.05 mm\"\ngroove_width = \"4.8 mm\"\nextrusion_gap = \"0.05 mm\"\n",
    )
    .unwrap();
    let (d, mean, eps) = oring(&s);
    assert!(close(d, 3.5306e-3, 1e-12), "{d}");
    assert!(close(mean, 28.5242e-3, 1e-12), "{mean}");
    assert!(close(eps, 0.249_419_362_148, 1e-9), "{eps}");
    let g = s.gland.unwrap();
    let inst = g.installed().unwrap();
    assert_eq!(inst.stretch, 0.0);
    assert!(close(inst.fill, 0.769_661_572_6, 1e-8), "{}", inst.fill);
    let r = g.squeeze_range().unwrap();
    assert!(close(r.min, 0.212_598_425_2, 1e-8), "{r:?}");
    assert!(close(r.max, 0.284_180_386_5, 1e-8), "{r:?}");
    assert_eq!(r.nominal, eps);
    // the model's gland: kind, the flange separation as extrusion gap, k_e = 1 by default
    assert_eq!(s.life.gland.unwrap().kind, GlandKind::Face);
    assert!(close(s.life.gland.unwrap().extrusion_gap, 0.05e-3, 1e-12));
    assert_eq!(s.life.energisation_factor, 1.0);
    assert!(s.warnings.is_empty(), "{:?}", s.warnings);
}

#[test]
fn piston_gland_by_hand() {
    // Ring ID 24.6 mm, cord 3.53 mm; bore 31.0 mm, gland depth 2.8 mm (bore to groove
    // bottom): groove bottom S = 31.0 − 2 × 2.8 = 25.4 mm > 24.6, so the ID is stretched onto it.
    // stretch s = 25.4/24.6 − 1 = 0.0325203…
    // Constant volume of the torus: d′²(S + d′) = d²(ID + d) = 3.53² × 28.13; by fixed-point
    // iteration d′ = 3.53 √(28.13/(25.4 + d′)), from d′ = 3.53:
    //   3.480850, 3.483811, 3.483632, 3.483643, 3.4836425 mm → d′ = 3.4836426 mm
    // D′ = 25.4 + 3.4836426 = 28.8836426 mm
    // ε = 1 − 2.8/3.4836426 = 0.196243606
    // fill = (π 3.4836426²/4)/(2.8 × 4.7) = 9.531422/13.16 = 0.724271
    // extrusion gap = diametral clearance / 2 = 0.05 mm
    let s = load(
        "gland = \"piston\"\ncross_section = \"3.53 mm\"\ninner_diameter = \"24.6 mm\"\n\
         bore_diameter = \"31.0 mm\"\ngroove_depth = \"2.8 mm\"\ngroove_width = \"4.7 mm\"\n\
         diametral_clearance = \"0.1 mm\"\n",
    )
    .unwrap();
    let (d, mean, eps) = oring(&s);
    assert!(close(d, 3.483_642_58e-3, 1e-8), "{d}");
    assert!(close(mean, 28.883_642_58e-3, 1e-9), "{mean}");
    assert!(close(eps, 0.196_243_606, 1e-7), "{eps}");
    let inst = s.gland.unwrap().installed().unwrap();
    assert!(close(inst.stretch, 0.032_520_325, 1e-8), "{}", inst.stretch);
    assert!(close(inst.inner_diameter, 25.4e-3, 1e-12));
    assert!(close(inst.fill, 0.724_271_1, 1e-6), "{}", inst.fill);
    assert!(close(s.life.gland.unwrap().extrusion_gap, 0.05e-3, 1e-12));
    // the sealing length is the installed centreline's
    assert!(close(s.problem.seal.length, PI * 28.883_642_58e-3, 1e-8));
}

#[test]
fn rod_gland_by_hand() {
    // Ring ID 20.0 mm, cord 3.53 mm on a rod of 20.4 mm (stretch 20.4/20 − 1 = 0.02), gland
    // depth 2.9 mm (rod to groove bottom), groove width 4.8 mm.
    // d′²(20.4 + d′) = 3.53² × 23.53; d′ = 3.53 √(23.53/(20.4 + d′)) from 3.53:
    //   3.500373, 3.502542, 3.502383, 3.5023946, 3.5023937 mm → d′ = 3.5023938 mm
    // D′ = 20.4 + 3.5023938 = 23.9023938 mm
    // ε = 1 − 2.9/3.5023938 = 0.171994872
    // fill = (π 3.5023938²/4)/(2.9 × 4.8) = 9.634036/13.92 = 0.692119
    let s = load(
        "gland = \"rod\"\ncross_section = \"3.53 mm\"\ninner_diameter = \"20.0 mm\"\n\
         rod_diameter = \"20.4 mm\"\ngroove_depth = \"2.9 mm\"\ngroove_width = \"4.8 mm\"\n\
         diametral_clearance = \"0.08 mm\"\nenergisation_factor = 0.5\n",
    )
    .unwrap();
    let (d, mean, eps) = oring(&s);
    assert!(close(d, 3.502_393_77e-3, 1e-8), "{d}");
    assert!(close(mean, 23.902_393_77e-3, 1e-9), "{mean}");
    assert!(close(eps, 0.171_994_872, 1e-7), "{eps}");
    let inst = s.gland.unwrap().installed().unwrap();
    assert!(close(inst.stretch, 0.02, 1e-12), "{}", inst.stretch);
    assert!(close(inst.fill, 0.692_118_7, 1e-6), "{}", inst.fill);
    assert!(close(s.life.gland.unwrap().extrusion_gap, 0.04e-3, 1e-12));
    assert_eq!(s.life.energisation_factor, 0.5);
}

#[test]
fn squeeze_may_replace_the_groove_depth() {
    // squeeze 0.2 on the piston above: the depth follows, h = d′(1 − 0.2), and the ring
    // installed in that depth has squeeze 0.2 again
    let s = load(
        "gland = \"piston\"\ncross_section = \"3.53 mm\"\ninner_diameter = \"24.6 mm\"\n\
         bore_diameter = \"31.0 mm\"\nsqueeze = 0.2\ngroove_width = \"4.7 mm\"\n\
         diametral_clearance = \"0.1 mm\"\n",
    )
    .unwrap();
    let (d, _, eps) = oring(&s);
    assert!(close(eps, 0.2, 1e-12), "{eps}");
    let g = s.gland.unwrap();
    assert!(close(g.gland_depth, 0.8 * d, 1e-12));
    // the groove bottom moved with the depth: S = 31 − 2h, stretched onto it
    let inst = g.installed().unwrap();
    assert!(close(
        inst.inner_diameter,
        31.0e-3 - 2.0 * g.gland_depth,
        1e-12
    ));
}

#[test]
fn an_overfilled_groove_warns_and_a_full_one_is_refused() {
    // face, AS568-214 free: d = 3.5306 mm, area π d²/4 = 9.79001 mm²; h = 2.65 mm
    // width 4.0 mm: fill 9.79001/10.6 = 0.9236 > 0.90 → warning (at maximum material, the
    // cord 3.6322 mm: 10.3617/10.6 = 0.9775 < 1, so it still fits)
    let s = load(
        "gland = \"face\"\nsize = \"AS568-214\"\ngroove_depth = \"2.65 mm\"\ngroove_width = \"4.0 mm\"\n",
    )
    .unwrap();
    assert_eq!(s.warnings.len(), 1, "{:?}", s.warnings);
    assert!(
        s.warnings[0].contains("dir/g.toml:17: seal.groove_width: gland fill")
            && s.warnings[0].contains("90 %"),
        "{}",
        s.warnings[0]
    );
    // width 3.6 mm: fill 9.79001/9.54 = 1.026 ≥ 1 → the ring does not fit
    let e = load(
        "gland = \"face\"\nsize = \"AS568-214\"\ngroove_depth = \"2.65 mm\"\ngroove_width = \"3.6 mm\"\n",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("dir/g.toml:17: seal.groove_width: the ring does not fit"),
        "{e}"
    );
}

#[test]
fn a_gland_takes_the_housings_thermal_strain_by_default() {
    let seal = "gland = \"face\"\nsize = \"AS568-214\"\ngroove_depth = \"2.6 mm\"\ngroove_width = \"4.8 mm\"\n";
    let s = load(seal).unwrap();
    let th = s.life.thermal_strain.unwrap();
    // steel (AISI 1020, 11.7e-6 1/K), installed at 23 °C, the rubber's own CTE
    assert_eq!(th.housing_expansion, 11.7e-6);
    assert_eq!(th.installation_temperature, 296.15);
    assert_eq!(Some(th.rubber_expansion), s.material.thermal_expansion);
    let s = load(&format!(
        "{seal}housing = \"aluminium\"\ninstallation_temperature = \"40 C\"\n"
    ))
    .unwrap();
    let th = s.life.thermal_strain.unwrap();
    assert_eq!(th.housing_expansion, Housing::Aluminium.expansion());
    assert_eq!(th.housing_expansion, 23.6e-6);
    assert!((th.installation_temperature - 313.15).abs() < 1e-9);
    let s = load(&format!("{seal}housing_expansion = \"9e-6 1/K\"\n")).unwrap();
    assert_eq!(s.life.thermal_strain.unwrap().housing_expansion, 9e-6);
    // exclusive
    let e = load(&format!(
        "{seal}housing = \"brass\"\nhousing_expansion = \"9e-6 1/K\"\n"
    ))
    .unwrap_err()
    .to_string();
    assert!(
        e.contains(":19: seal.housing_expansion: housing and housing_expansion"),
        "{e}"
    );
    let e = load(&format!("{seal}housing = \"wood\"\n"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains(":18: seal.housing: must be one of \"steel\""),
        "{e}"
    );
    // an inline rubber without thermal_expansion: refused at the gland, saying what to add
    let inline = scenario(seal).replace(
        "library = \"nbr-70\"",
        "youngs_modulus = \"10 MPa\"\npoisson_ratio = 0.5",
    );
    let e = Scenario::from_str(&inline, Path::new("dir/g.toml"))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains(":15: seal.gland: a groove-seated ring follows the temperature by default")
            && e.contains("add `thermal_expansion` to [material]"),
        "{e}"
    );
    // without a gland, `housing` switches the thermal strain on like housing_expansion
    let plates = load(
        "cross_section = \"3.53 mm\"\nmean_diameter = \"50 mm\"\nsqueeze = 0.2\nhousing = \"titanium\"\n",
    )
    .unwrap();
    assert_eq!(
        plates.life.thermal_strain.unwrap().housing_expansion,
        8.6e-6
    );
    assert!(plates.life.gland.is_none() && plates.life.energisation_factor == 0.0);
}

#[test]
fn gland_inputs_are_checked_where_they_are_written() {
    let piston = "gland = \"piston\"\nsize = \"AS568-214\"\nbore_diameter = \"31.75 mm\"\n\
                  groove_depth = \"2.85 mm\"\ngroove_width = \"4.7 mm\"\ndiametral_clearance = \"0.1 mm\"\n";
    assert!(load(piston).is_ok());
    let cases = [
        // groove deeper than the (stretched) cord
        (
            "groove_depth = \"2.85 mm\"",
            "groove_depth = \"3.6 mm\"",
            ":17: seal.groove_depth: groove deeper than the cross-section",
        ),
        (
            "diametral_clearance = \"0.1 mm\"",
            "diametral_clearance = \"-0.1 mm\"",
            ":19: seal.diametral_clearance: must not be negative",
        ),
        (
            "\"AS568-214\"",
            "\"AS568-290\"",
            ":15: seal.size: unknown size \"AS568-290\"; the nearest sizes of the AS568 table are AS568-283, AS568-284, AS568-309, AS568-310",
        ),
        (
            "\"AS568-214\"",
            "\"214\"",
            ":15: seal.size: expected an AS568 size such as \"AS568-214\"",
        ),
        (
            "diametral_clearance = \"0.1 mm\"\n",
            "diametral_clearance = \"0.1 mm\"\nmean_diameter = \"30 mm\"\n",
            ":20: seal.mean_diameter: not a key of a groove-seated ring",
        ),
        (
            "diametral_clearance = \"0.1 mm\"\n",
            "diametral_clearance = \"0.1 mm\"\nsqueeze = 0.2\n",
            ":20: seal.squeeze: squeeze and groove_depth are two sources of truth",
        ),
        (
            "diametral_clearance = \"0.1 mm\"\n",
            "",
            ":12: seal.diametral_clearance: missing key `diametral_clearance`",
        ),
        (
            "bore_diameter = \"31.75 mm\"\n",
            "rod_diameter = \"31.75 mm\"\n",
            ":16: seal.rod_diameter: not a key of a piston gland, which takes bore_diameter",
        ),
        (
            "gland = \"piston\"",
            "gland = \"bore\"",
            ":14: seal.gland: must be \"face\"",
        ),
        (
            "diametral_clearance = \"0.1 mm\"\n",
            "diametral_clearance = \"0.1 mm\"\nenergisation_factor = 2\n",
            ":20: seal.energisation_factor: must lie between 0 and 1.5",
        ),
        (
            "size = \"AS568-214\"\n",
            "size = \"AS568-214\"\ncross_section = \"3.53 mm\"\n",
            ":16: seal.cross_section: size (AS568-214) gives the ring's dimensions",
        ),
        (
            "diametral_clearance = \"0.1 mm\"\n",
            "extrusion_gap = \"0.05 mm\"\n",
            ":19: seal.extrusion_gap: not a key of a piston gland, which takes diametral_clearance",
        ),
    ];
    for (from, to, expected) in cases {
        let text = piston.replace(from, to);
        assert_ne!(text, piston, "{from}");
        let e = load(&text).unwrap_err().to_string();
        assert!(
            e.starts_with("dir/g.toml:") && e.contains(expected),
            "{to}: {e}"
        );
    }
    // a face gland: negative flange separation; a ring between plates refuses gland keys
    let e = load(
        "gland = \"face\"\nsize = \"AS568-214\"\ngroove_depth = \"2.6 mm\"\ngroove_width = \"4.8 mm\"\nextrusion_gap = \"-1 mm\"\n",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains(":18: seal.extrusion_gap: must not be negative"),
        "{e}"
    );
    let e = load(
        "cross_section = \"3.53 mm\"\nmean_diameter = \"50 mm\"\nsqueeze = 0.2\ngroove_width = \"4.8 mm\"\n",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains(":17: seal.groove_width: only applies to a groove-seated ring"),
        "{e}"
    );
}

/// Rows copied by hand from the source (CrispyConductor/waterproof-geocache-container,
/// oring.scad @ 0681441): dash, ID in, ±ID in, CS in, ±CS in.
const FROM_THE_SOURCE: [(u16, f64, f64, f64, f64); 24] = [
    (1, 0.029, 0.004, 0.040, 0.003),
    (4, 0.070, 0.005, 0.070, 0.003),
    (10, 0.239, 0.005, 0.070, 0.003),
    (16, 0.614, 0.009, 0.070, 0.003),
    (30, 1.614, 0.013, 0.070, 0.003),
    (50, 5.239, 0.037, 0.070, 0.003),
    (102, 0.049, 0.005, 0.103, 0.003),
    (115, 0.674, 0.009, 0.103, 0.003),
    (130, 1.612, 0.015, 0.103, 0.003),
    (150, 2.862, 0.022, 0.103, 0.003),
    (178, 9.737, 0.055, 0.103, 0.003),
    (201, 0.171, 0.005, 0.139, 0.004),
    (214, 0.984, 0.010, 0.139, 0.004),
    (222, 1.484, 0.015, 0.139, 0.004),
    (250, 4.984, 0.035, 0.139, 0.004),
    (284, 17.955, 0.085, 0.139, 0.004),
    (309, 0.412, 0.005, 0.210, 0.005),
    (325, 1.475, 0.015, 0.210, 0.005),
    (350, 4.600, 0.030, 0.210, 0.005),
    (390, 20.955, 0.095, 0.210, 0.005),
    (425, 4.475, 0.033, 0.275, 0.006),
    (429, 4.975, 0.037, 0.275, 0.006),
    (450, 10.475, 0.060, 0.275, 0.006),
    (467, 18.955, 0.090, 0.275, 0.006),
];

#[test]
fn the_as568_table_matches_its_source() {
    for (dash, id, id_tol, cs, cs_tol) in FROM_THE_SOURCE {
        let s = as568::lookup(&format!("AS568-{dash:03}")).unwrap();
        assert_eq!(
            (s.dash, s.id_in, s.id_tol_in, s.cs_in, s.cs_tol_in),
            (dash, id, id_tol, cs, cs_tol)
        );
    }
    // -377: the source's inch entry 9.925 contradicts its own mm entry 253.37 = 9.975 × 25.4
    // and the .250 in steps of the series (-376 9.725, -378 10.475); 9.975 is used
    let s377 = as568::lookup("AS568-377").unwrap();
    assert_eq!(s377.id_in, 9.975);
    assert!(
        (253.37_f64 - 9.975 * 25.4).abs() <= 0.005 + 1e-9,
        "the mm entry rounds 253.365"
    );
    // metric = inch × 25.4 exactly: -214 is 24.9936 × 3.5306 mm
    let r = as568::lookup("AS568-214").unwrap().ring();
    assert!((r.inner_diameter - 24.9936e-3).abs() < 1e-15);
    assert!((r.cross_section - 3.5306e-3).abs() < 1e-15);
    assert!((r.cross_section_tolerance - 0.1016e-3).abs() < 1e-15);
}

#[test]
fn the_as568_table_keeps_its_series_invariants() {
    // nominal cross-section and its tolerance per series [in] (Global O-Ring's chart; the
    // tolerances ±.003/.003/.004/.005/.006); -001…-003 are the small exceptions of the 0 series
    let series = [
        (0, 0.070, 0.003),
        (1, 0.103, 0.003),
        (2, 0.139, 0.004),
        (3, 0.210, 0.005),
        (4, 0.275, 0.006),
    ];
    let table = as568::sizes().unwrap();
    // -001…-050, -102…-178, -201…-284, -309…-395, -425…-475
    assert_eq!(table.len(), 50 + 77 + 84 + 87 + 51);
    for s in table {
        let (_, cs, tol) = series[usize::from(s.series())];
        if s.dash > 3 {
            assert_eq!(s.cs_in, cs, "AS568-{:03}", s.dash);
        }
        assert_eq!(s.cs_tol_in, tol, "AS568-{:03}", s.dash);
        // the ID tolerance grows with the ID, from .004 in to under 1 % of the larger IDs
        // (.120 in at 25.94 in, -395 and -475)
        assert!(
            s.id_tol_in >= 0.004 && s.id_tol_in <= 0.12,
            "AS568-{:03}",
            s.dash
        );
    }
    for pair in table.windows(2) {
        if pair[0].series() == pair[1].series() {
            assert!(
                pair[1].id_in > pair[0].id_in && pair[1].id_tol_in >= pair[0].id_tol_in,
                "AS568-{:03} → AS568-{:03}",
                pair[0].dash,
                pair[1].dash
            );
        }
    }
    // first and last ID of each series as Global O-Ring's chart gives them
    let first_last = [
        (1, 50, 0.029, 5.239),
        (102, 178, 0.049, 9.737),
        (201, 284, 0.171, 17.955),
    ];
    for (a, b, ia, ib) in first_last {
        assert_eq!(as568::lookup(&format!("AS568-{a}")).unwrap().id_in, ia);
        assert_eq!(as568::lookup(&format!("AS568-{b}")).unwrap().id_in, ib);
    }
    assert_eq!(as568::lookup("AS568-309").unwrap().id_in, 0.412);
}

#[test]
fn two_interfaces_leak_in_parallel() {
    // the shipped piston seal: honed bore ([surface]) and turned groove bottom ([groove_surface]);
    // each interface sees the same contact, so Q̇(bore, groove) = (Q̇(bore, bore) + Q̇(groove,
    // groove))/2 exactly, whatever the leak law
    use sealsim::simulate::{GrooveInterface, Simulator};
    let s = sealsim::scenario::Scenario::load(
        &crate::common::scenarios_dir().join("oring-nbr-piston-hydraulic.toml"),
    )
    .unwrap();
    let mut mixed = s.life.clone();
    // the drawn finishes (honed bore Ra 0.2 µm, turned groove bottom Ra 1.6 µm) both seal; two
    // rough surfaces that leak stand in for them: a bore of 0.8 µm rms, smoother than a groove
    // bottom of 1.6 µm rms (H 0.7, q1 = 1e10 1/m: rms slopes 8.3 and 16.7, beyond machined faces)
    assert!(
        matches!(mixed.groove, GrooveInterface::Own(_)),
        "the piston scenario has its own groove surface"
    );
    mixed.spectrum = sealsim::surface::Spectrum::self_affine(0.8e-6, 0.7, 3e5, 1e10, None).unwrap();
    let groove = sealsim::surface::Spectrum::self_affine(1.6e-6, 0.7, 3e5, 1e10, None).unwrap();
    mixed.groove = GrooveInterface::Own(groove.clone());
    let mut bore_bore = mixed.clone();
    bore_bore.groove = GrooveInterface::Counterface;
    let mut groove_groove = mixed.clone();
    groove_groove.spectrum = groove;
    groove_groove.groove = GrooveInterface::Counterface;
    let leak = |p: &sealsim::simulate::LifeProblem| {
        let sim = Simulator::new(p);
        sim.installed_leak(sim.installed_peak()).0
    };
    let (q_mixed, q_bb, q_gg) = (leak(&mixed), leak(&bore_bore), leak(&groove_groove));
    assert!(q_bb > 0.0 && q_gg > q_bb, "{q_bb} {q_gg}");
    assert!(
        (q_mixed / (0.5 * (q_bb + q_gg)) - 1.0).abs() < 1e-12,
        "{q_mixed} vs ({q_bb} + {q_gg})/2"
    );
    // a ring between plates keeps one interface: half of the same surface on both faces
    let mut plates = bore_bore.clone();
    plates.groove = GrooveInterface::None;
    assert!((leak(&plates) / (0.5 * q_bb) - 1.0).abs() < 1e-12);
}
