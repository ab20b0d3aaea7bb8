//! Compounds from supplier datasheets (`sealsim materials new`, docs/model.md §5.4; issue 40).

use sealsim::material::datasheet::{self, Datasheet, LowTemperature, SetPoint, gent_modulus};
use sealsim::material::{Ageing, Material, Prony, PronyTerm};
use sealsim::scenario::library;
use sealsim::scenario::library_check::published;
use sealsim::workflow::datasheet::class_band;

const HOUR: f64 = 3600.0;

fn shore(m: &Material) -> f64 {
    // "…, 70 Shore A (illustrative)"
    let words: Vec<&str> = m.name.split_whitespace().collect();
    let i = words.iter().position(|w| *w == "Shore").unwrap();
    words[i - 1].parse().unwrap()
}

/// E(3 s, 23 °C) from its definition (the test's own, not the code's helper).
fn modulus_3s_23c(m: &Material) -> f64 {
    m.prony.relaxation(3.0 * m.shift.ln_rate(296.15).exp())
}

/// The standard linear solid's recovery in closed form: held ε0 = 1 for ξ_h, released, the
/// strain after r is `w (1 − e^{−ξ_h/τ}) e^{−(1−w) r/τ}`, w = E1/E0; to 2e-5 (a datasheet prints
/// a set to 0.5 %).
#[test]
fn the_viscoelastic_set_of_a_standard_linear_solid_is_its_closed_form() {
    let prony = Prony::new(
        1e6,
        &[PronyTerm {
            modulus: 3e6,
            tau: 100.0,
        }],
    )
    .unwrap();
    let m = Material::user("sls", prony, 0.5);
    let w: f64 = 0.75;
    for (hold, rest) in [(1000.0, 50.0), (30.0, 10.0), (1e4, 1800.0), (5.0, 0.1)] {
        let got = datasheet::viscoelastic_set(&m, hold, 300.0, rest, 300.0);
        let want = w * (1.0 - (-hold / 100.0f64).exp()) * (-(1.0 - w) * rest / 100.0).exp();
        assert!(
            (got - want).abs() < 2e-5 * want.max(1e-12),
            "hold {hold}, rest {rest}: {got} vs {want}"
        );
    }
}

/// Each library compound's own datasheet figures — its hardness, its T10, its compression
/// set at 70 h at the rated temperature and 1000 h 25 K below, printed to 1 % as datasheets
/// do — give back a compound with T10 within 2 K, those sets within 2 % (absolute) and the
/// chemical time to 50 % force at the rating within 15 %.
#[test]
fn a_library_compound_survives_the_round_trip_through_its_own_datasheet() {
    for id in library::ids() {
        let m = library::get(id).unwrap().load().unwrap();
        let rated = published(id).unwrap().rated;
        let t10 = m.low_temperature_limit().unwrap();
        let points = [(1000.0 * HOUR, rated - 25.0), (70.0 * HOUR, rated)];
        let readings: Vec<SetPoint> = points
            .iter()
            .map(|&(time, temperature)| SetPoint {
                time,
                temperature,
                set: (datasheet::compression_set(&m, time, temperature) * 100.0).round() / 100.0,
                resolution: 0.005,
            })
            .collect();
        let sheet = Datasheet {
            name: format!("{id} from its datasheet"),
            source: "round trip".into(),
            hardness: shore(&m),
            low_temperature: LowTemperature::T10((t10 * 10.0).round() / 10.0),
            compression_set: readings.clone(),
        };
        let (new, _) = datasheet::from_datasheet(&m, class_band(&m).unwrap(), &sheet).unwrap();
        let new_t10 = new.low_temperature_limit().unwrap();
        assert!((new_t10 - t10).abs() < 2.0, "{id}: T10 {new_t10} vs {t10}");
        for (r, &(time, temperature)) in readings.iter().zip(&points) {
            let set = datasheet::compression_set(&new, time, temperature);
            let own = datasheet::compression_set(&m, time, temperature);
            assert!((set - own).abs() < 0.02, "{id}: set {set} vs {own} ({r:?})");
        }
        let t50 = |m: &Material| std::f64::consts::LN_2 / m.ageing.unwrap().rate_at(rated);
        let ratio = t50(&new) / t50(&m);
        assert!(
            (ratio - 1.0).abs() < 0.15,
            "{id}: t50 at the rating ×{ratio}"
        );
    }
}

/// The datasheet's figures are what the compound gives, checked against their own definitions:
/// T10 by the compound's low-temperature limit, the hardness by Gent's closed form, and an
/// Arrhenius law recovered from sets it produced (printed to 0.01 %).
#[test]
fn a_datasheet_compound_has_the_datasheets_t10_hardness_and_ageing() {
    let nbr = library::get("nbr-70").unwrap().load().unwrap();
    let truth = Material {
        ageing: Some(Ageing::arrhenius(80e3, 2e-10, 296.15, 1.0)),
        ..nbr.clone()
    };
    let points = [(168.0 * HOUR, 373.15), (1000.0 * HOUR, 353.15)];
    let sheet = Datasheet {
        name: "test".into(),
        source: "test".into(),
        hardness: 82.0,
        low_temperature: LowTemperature::T10(273.15 - 40.0),
        compression_set: points
            .iter()
            .map(|&(time, temperature)| SetPoint {
                time,
                temperature,
                set: datasheet::compression_set(&truth, time, temperature),
                resolution: 5e-5,
            })
            .collect(),
    };
    // the set points' ageing on the un-moved curve: recover it on the same curve first
    let same_curve = Datasheet {
        hardness: shore(&nbr),
        low_temperature: LowTemperature::GlassTransition(nbr.glass_transition.unwrap()),
        ..sheet.clone()
    };
    let (back, c) = datasheet::from_datasheet(&nbr, (50e3, 65e3), &same_curve).unwrap();
    assert!(c.shift.abs() < 1e-12);
    let ageing = back.ageing.unwrap();
    assert!(
        (ageing.activation_energy / 80e3 - 1.0).abs() < 1e-6,
        "{ageing:?}"
    );
    let k23 = ageing.rate_at(296.15);
    assert!((k23 / 2e-10 - 1.0).abs() < 1e-6, "{ageing:?}");
    // anchored between the readings (mean 1/T of 80 and 100 °C)
    assert!((ageing.reference_temperature - 2.0 / (1.0 / 353.15 + 1.0 / 373.15)).abs() < 1e-9);
    let band = &c.bands.activation_energy;
    assert!(
        band.low < 80e3 && band.high > 80e3 && band.high - band.low < 2e3,
        "{band:?}"
    );

    let (m, c) = datasheet::from_datasheet(&nbr, (50e3, 65e3), &sheet).unwrap();
    let t10 = m.low_temperature_limit().unwrap();
    assert!((t10 - (273.15 - 40.0)).abs() < 1e-6, "T10 {t10}");
    assert!(c.shift < -10.0, "moved {}", c.shift);
    let e = modulus_3s_23c(&m);
    assert!((e / gent_modulus(82.0) - 1.0).abs() < 1e-9, "{e}");
    // Gent's relation at 70 Shore A: 5.52 MPa (the library's own calibration figure)
    assert!((gent_modulus(70.0) / 5.5205e6 - 1.0).abs() < 1e-3);
    // the temperature-moved curve keeps the readings: each set within its printed digit
    for (p, _, _, _) in &c.points {
        let set = datasheet::compression_set(&m, p.time, p.temperature);
        assert!((set - p.set).abs() < 1e-9, "{set} vs {}", p.set);
    }
}

/// Readings at one temperature take the low end of the class's Ea band (the faster ageing
/// below the reading: less life) and carry the band; a set no larger than the viscoelastic
/// part is refused.
#[test]
fn one_reading_temperature_takes_the_conservative_end_of_the_class_band() {
    let hnbr = library::get("hnbr-75").unwrap().load().unwrap();
    let (lo, hi) = class_band(&hnbr).unwrap();
    assert!(lo < hi);
    let reading = |set: f64| SetPoint {
        time: 70.0 * HOUR,
        temperature: 423.15,
        set,
        resolution: 0.005,
    };
    let sheet = Datasheet {
        name: "test".into(),
        source: "test".into(),
        hardness: 75.0,
        low_temperature: LowTemperature::T10(hnbr.low_temperature_limit().unwrap()),
        compression_set: vec![reading(0.30)],
    };
    let (m, c) = datasheet::from_datasheet(&hnbr, (lo, hi), &sheet).unwrap();
    assert_eq!(m.ageing.unwrap().activation_energy, lo);
    assert_eq!(
        (
            c.bands.activation_energy.low,
            c.bands.activation_energy.high
        ),
        (lo, hi)
    );
    // at 60 °C the low end ages faster than the high end would
    assert!(c.bands.rate.high > m.ageing.unwrap().rate * 0.999);
    let refused = Datasheet {
        compression_set: vec![reading(0.01)],
        ..sheet
    };
    let err = datasheet::from_datasheet(&hnbr, (lo, hi), &refused).unwrap_err();
    assert!(err.to_string().contains("viscoelasticity alone"), "{err}");
}

#[test]
fn gent_is_monotone_in_hardness() {
    let mut last = 0.0;
    for s in 30..=95 {
        let e = gent_modulus(s as f64);
        assert!(e > last);
        last = e;
    }
}

/// The compound file keeps a datasheet compound's Ea band (`[material.bands]`, docs/model.md
/// §5.4): written by `material_toml`, read back to the same bits; the reader refuses a band
/// whose `min` is not below its `max`, and a band of a figure a study cannot draw.
#[test]
fn a_datasheet_compounds_band_survives_its_file() {
    use sealsim::report::material_toml::material_toml;
    use sealsim::scenario::material_from_str;
    let nbr = library::get("nbr-70").unwrap().load().unwrap();
    let points = [(70.0 * HOUR, 373.15), (70.0 * HOUR, 398.15)];
    let sheet = Datasheet {
        name: "band".into(),
        source: "test".into(),
        hardness: 70.0,
        low_temperature: LowTemperature::T10(273.15 - 30.0),
        compression_set: points
            .iter()
            .map(|&(time, temperature)| SetPoint {
                time,
                temperature,
                set: datasheet::compression_set(&nbr, time, temperature),
                resolution: 5e-3,
            })
            .collect(),
    };
    let (m, c) = datasheet::from_datasheet(&nbr, class_band(&nbr).unwrap(), &sheet).unwrap();
    assert_eq!(m.bands.len(), 1);
    let band = &m.bands[0];
    assert_eq!(
        (band.min, band.max),
        (
            c.bands.activation_energy.low,
            c.bands.activation_energy.high
        )
    );
    let text = material_toml(&m);
    let path = std::path::Path::new("compound.toml");
    let back = material_from_str(&text, path).unwrap();
    assert_eq!(back.bands, m.bands);
    let swapped = text.replace(
        &format!("min = \"{:e} J/mol\"", band.min),
        &format!("min = \"{:e} J/mol\"", band.max + 1.0),
    );
    assert_ne!(swapped, text);
    let err = material_from_str(&swapped, path).unwrap_err().to_string();
    assert!(
        err.contains("material.bands") && err.contains("below"),
        "{err}"
    );
    let unknown = text.replace(
        "\"ageing.activation_energy\" = { min",
        "\"ageing.rate\" = { min",
    );
    let err = material_from_str(&unknown, path).unwrap_err().to_string();
    assert!(err.contains("ageing.activation_energy"), "{err}");
}
