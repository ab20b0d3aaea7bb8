//! A flat gasket in the cold end to end (issue 41 item 5): the new user's
//! `shutdown_temperature = "-30 C"` on a flat gasket now acts (review 2026-11-28, finding 40:
//! "silently ignored (no `shutdown` line, no warning)"), and a key that does not apply to the
//! seal kind or its loading exits 2 with the file, line, key and why.

use crate::support::run_text;

/// The new user's DN50 EPDM gasket in 120 °C water with a −30 °C winter shutdown
/// (`c_gasket_sd.toml` of the review), ΔP lowered to 0.1 bar so that the shutdown check, not
/// the lift-off at the service pressure, ends it. Library water at 120 °C and 1.1 bar absolute
/// would boil (refused since issue 42): the water is given by its viscosity at 120 °C instead
/// (0.232 mPa·s, IAPWS 2008), which the force and shutdown checks do not use.
const GASKET: &str = r#"name = "EPDM flat gasket DN50, hot water 120 C, -30 C shutdown"
[material]
library = "epdm-70"
[surface]
ra = "3.2 um"
short_wavelength = "stop"
[fluid]
viscosity = "0.232 mPa*s"
pressure_difference = "0.1 bar"
[seal]
kind = "flat"
nominal_pressure = "3 MPa"
width = "23 mm"
length = "264 mm"
loading = "displacement"
[environment]
temperature = "120 C"
[failure]
max_leak_rate = "1 mL/h"
shutdown_temperature = "-30 C"
[simulation]
duration = "20 years"
"#;

#[test]
fn the_reviews_shutdown_temperature_on_a_flat_gasket_acts() {
    let (code, stdout, stderr, csv, json) = run_text(GASKET);
    assert_eq!(code, Some(0), "{stderr}");
    // the summary's shutdown line at −30 °C (there was none), and the run ends by it
    let line = stdout
        .lines()
        .find(|l| l.starts_with("shutdown"))
        .unwrap_or_else(|| panic!("no shutdown line:\n{stdout}"));
    assert!(line.contains("at -30 °C"), "{line}");
    assert!(stdout.contains("by lost_interference"), "{stdout}");
    // the JSON's shutdown object and failure
    let json: serde_json::Value = serde_json::from_str(&json.unwrap()).unwrap();
    assert_eq!(json["failure_mode"], "lost_interference", "{json}");
    assert!((json["shutdown"]["temperature_K"].as_f64().unwrap() - 243.15).abs() < 1e-9);
    let cold = json["time_to_failure_s"].as_f64().unwrap();
    // the history's shutdown_squeeze column is filled: the default compression 10 % at
    // 120 °C less the contraction to −30 °C, (1 − 0.1)(e_r − α_h ΔT)/(1 + e_r) = −0.0205
    // (α_r 1.6e-4, steel 11.7e-6, ΔT = −150 K), and nothing set yet at the first row
    let csv = csv.unwrap();
    let first = csv.lines().nth(1).unwrap();
    let squeeze: f64 = first.rsplit(',').next().unwrap().parse().unwrap();
    assert!((squeeze - (0.1 - 0.020_513)).abs() < 1e-3, "{first}");
    // a warmer shutdown (10 °C) holds longer: the cold is what ends it first
    let (_, _, _, _, warm) = run_text(&GASKET.replace("\"-30 C\"", "\"10 C\""));
    let warm: serde_json::Value = serde_json::from_str(&warm.unwrap()).unwrap();
    let warm_t = warm["time_to_failure_s"].as_f64().unwrap();
    assert!(warm_t > 1.1 * cold, "{warm_t} vs {cold}");
}

/// Runs `text`, expecting exit 2; returns stderr.
fn refused(text: &str) -> String {
    let (code, _, stderr, _, _) = run_text(text);
    assert_eq!(code, Some(2), "{stderr}");
    stderr
}

#[test]
fn a_key_that_does_not_apply_to_the_seal_kind_exits_2_naming_why() {
    // a gland's key on a flat gasket (line 16)
    let e = refused(&GASKET.replace(
        "loading = \"displacement\"\n",
        "loading = \"displacement\"\ngroove_width = \"4 mm\"\n",
    ));
    assert!(
        e.contains("s.toml:16: seal.groove_width: applies to an O-ring gland, not a flat gasket"),
        "{e}"
    );
    // the shutdown check and the thermal strain do not act under force loading: refused
    let force = GASKET.replace("\"displacement\"", "\"force\"");
    let e = refused(&force);
    assert!(
        e.contains("s.toml:20: failure.shutdown_temperature: sets the shutdown check")
            && e.contains("under loading = \"force\""),
        "{e}"
    );
    let e = refused(
        &force
            .replace("shutdown_temperature = \"-30 C\"\n", "")
            .replace(
                "length = \"264 mm\"\n",
                "length = \"264 mm\"\nhousing = \"steel\"\n",
            ),
    );
    assert!(
        e.contains(
            "seal.housing: applies to the thermal strain of a gasket held at a fixed \
                    compression"
        ),
        "{e}"
    );
    // waived and set at once
    let e = refused(&GASKET.replace(
        "shutdown_temperature = \"-30 C\"\n",
        "shutdown_temperature = \"-30 C\"\nlost_interference = false\n",
    ));
    assert!(
        e.contains("failure.shutdown_temperature: sets the shutdown check that"),
        "{e}"
    );
    // a gasket's compression on an O-ring
    let oring = GASKET
        .replace("kind = \"flat\"", "kind = \"o-ring\"")
        .replace(
            "nominal_pressure = \"3 MPa\"\nwidth = \"23 mm\"\nlength = \"264 mm\"\n",
            "cross_section = \"3.53 mm\"\nmean_diameter = \"50 mm\"\nsqueeze = 0.2\ncompression = 0.1\n",
        );
    let e = refused(&oring);
    assert!(
        e.contains("seal.compression: not a key of an O-ring seal"),
        "{e}"
    );
}

#[test]
fn a_hot_flat_gasket_without_the_rubbers_expansion_is_refused_an_isothermal_one_runs() {
    // an inline compound without thermal_expansion: at 120 °C the compression would change
    // unseen, so the run is refused naming the key; at the bolting temperature it runs
    let material = "[material]\nyoungs_modulus = \"10 MPa\"\npoisson_ratio = 0.5\n";
    let hot = GASKET
        .replace("[material]\nlibrary = \"epdm-70\"\n", material)
        .replace("shutdown_temperature = \"-30 C\"\n", "");
    let e = refused(&hot);
    assert!(
        e.contains("a flat gasket under displacement loading follows the temperature")
            && e.contains("thermal_expansion"),
        "{e}"
    );
    let (code, _, stderr, _, _) = run_text(&hot.replace("\"120 C\"", "\"23 C\""));
    assert_eq!(code, Some(0), "{stderr}");
}
