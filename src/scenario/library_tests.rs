//! Tests of the physics types on the shipped library compounds: they read the compound files,
//! which the input layer parses, so they live here rather than beside the types in
//! `sealsim-core`.

use crate::material::compatibility::{FluidClass, Rating, rating};
use crate::material::compound::{GEHMAN_ROOM_TEMPERATURE, T10_RATIO};
use crate::scenario::library;

/// The library compound's stored ratings.
fn of(id: &str, class: FluidClass) -> Option<Rating> {
    let material = library::get(id).unwrap().load().unwrap();
    rating(&material.compatibility, class).map(|c| c.rating)
}

/// The field practice the issue names: EPDM, not standard FKM, in hot water and hot
/// coolant; EPDM not in mineral oil; NBR the mineral-oil default.
#[test]
fn hot_water_and_coolant_flag_fkm_and_mineral_oil_flags_epdm() {
    let hot = FluidClass::of("water", 353.15).unwrap();
    assert_eq!(hot, FluidClass::HotWater);
    let coolant = FluidClass::of("ethylene-glycol-water-50", 383.15).unwrap();
    assert_eq!(coolant, FluidClass::HotWater);
    for class in [hot, coolant] {
        assert_eq!(of("fkm-75", class), Some(Rating::NotRecommended));
        assert_eq!(of("epdm-70", class), Some(Rating::Recommended));
    }
    let oil = FluidClass::of("iso-vg-46", 393.15).unwrap();
    assert_eq!(of("epdm-70", oil), Some(Rating::NotRecommended));
    assert_eq!(of("nbr-70", oil), Some(Rating::Recommended));
    assert_eq!(of("fkm-75", oil), Some(Rating::Recommended));
    // below 80 °C water is water; a coolant below it is a coolant
    assert_eq!(FluidClass::of("water", 353.0), Some(FluidClass::Water));
    assert_eq!(
        FluidClass::of("ethylene-glycol-water-50", 300.0),
        Some(FluidClass::WaterGlycol)
    );
    // unrated pairs and uncovered fluids say nothing
    assert!(of("hnbr-75", oil).is_none());
    assert!(FluidClass::of("helium", 300.0).is_none());
}

#[test]
fn library_t10_solves_its_equation_and_follows_t_g() {
    let t10 = |id: &str| {
        let m = library::get(id).unwrap().load().unwrap();
        let t = m.low_temperature_limit().unwrap();
        let ratio = m.gehman_modulus(t) / m.gehman_modulus(GEHMAN_ROOM_TEMPERATURE);
        assert!((ratio / T10_RATIO - 1.0).abs() < 1e-9, "{id}: {ratio}");
        // above the WLF frozen limit and the glass transition, below room temperature
        let tg = m.glass_transition.unwrap();
        assert!(
            t > tg && t > m.shift.frozen_below().unwrap() && t < 296.15,
            "{id}"
        );
        t
    };
    let [vmq, epdm, nbr, fkm] = ["vmq-70", "epdm-70", "nbr-70", "fkm-75"].map(t10);
    assert!(
        vmq < epdm && epdm < nbr && nbr < fkm,
        "{vmq} {epdm} {nbr} {fkm}"
    );
}
