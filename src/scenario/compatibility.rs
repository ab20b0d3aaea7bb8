//! Fluid compatibility of the library compounds (docs/model.md §6.8): a rating per compound class
//! × fluid class from cited public charts and seal makers' guides, printed by `run` and
//! `compare`; "not recommended" is a warning in `run` and a flag in the `compare` row.
//!
//! Scale (one for every source, mapped from each source's words): **A** recommended
//! ("excellent", "the correct default", "required for"), **B** limited ("good", "fair",
//! "short-term only"), **X** not recommended ("poor", "incompatible", "not … hot water").
//! A pair no source rated is *not rated* (`None`), and says so. The quotes are in
//! docs/sources/compatibility-permeation.md; most sources are secondary (distributors,
//! glossaries): replace them with your supplier's chart for a design.

use std::fmt;

/// A fluid class the ratings are given for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FluidClass {
    /// Mineral (petroleum) oil: the `iso-vg-*` library oils.
    MineralOil,
    /// Water below [`HOT_WATER`].
    Water,
    /// Water, or an aqueous coolant (water–glycol), at or above [`HOT_WATER`]: hydrolysis and
    /// steam attack are the hot-water hazards, whatever the glycol.
    HotWater,
    /// Water–ethylene-glycol coolant below [`HOT_WATER`].
    WaterGlycol,
}

/// The temperature from which water counts as hot \[K\]: 80 °C. No source read gives the
/// threshold; it is taken at the low end of "hot water" service so that a ring at 80 °C is
/// judged against the hot-water ratings (the conservative choice).
pub const HOT_WATER: f64 = 353.15;

impl FluidClass {
    /// The class of library fluid `id` at the run's highest temperature `t_max` \[K\]; `None`
    /// for a fluid the ratings do not cover (gases, inline fluids).
    pub fn of(id: &str, t_max: f64) -> Option<FluidClass> {
        let hot = t_max >= HOT_WATER;
        match id {
            "water" if hot => Some(FluidClass::HotWater),
            "water" => Some(FluidClass::Water),
            "ethylene-glycol-water-50" if hot => Some(FluidClass::HotWater),
            "ethylene-glycol-water-50" => Some(FluidClass::WaterGlycol),
            _ if id.starts_with("iso-vg-") => Some(FluidClass::MineralOil),
            _ => None,
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            FluidClass::MineralOil => "mineral oil",
            FluidClass::Water => "water",
            FluidClass::HotWater => "hot water or aqueous coolant (≥ 80 °C)",
            FluidClass::WaterGlycol => "water–glycol coolant",
        }
    }
}

/// A rating on the A/B/X scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rating {
    Recommended,
    Limited,
    NotRecommended,
}

impl Rating {
    pub fn letter(self) -> char {
        match self {
            Rating::Recommended => 'A',
            Rating::Limited => 'B',
            Rating::NotRecommended => 'X',
        }
    }

    pub fn words(self) -> &'static str {
        match self {
            Rating::Recommended => "recommended",
            Rating::Limited => "limited",
            Rating::NotRecommended => "NOT RECOMMENDED",
        }
    }
}

/// One compound's rating in one fluid class, with its source.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Compatibility {
    pub class: FluidClass,
    pub rating: Rating,
    /// Where the rating comes from, with the words it maps.
    pub source: &'static str,
}

impl fmt::Display for Compatibility {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({}) in {} — {}",
            self.rating.letter(),
            self.rating.words(),
            self.class.as_str(),
            self.source
        )
    }
}

/// (compound class prefix, fluid class, rating, source and the words mapped).
const RATINGS: &[(&str, FluidClass, Rating, &str)] = &[
    (
        "nbr",
        FluidClass::MineralOil,
        Rating::Recommended,
        "'NBR (nitrile rubber) is the correct default for mineral oil-based hydraulic fluids': \
         kingdaflex.com, 'Hydraulic fluid' (secondary)",
    ),
    (
        "nbr",
        FluidClass::HotWater,
        Rating::Limited,
        "steam 'Up to +120°C … NBR (short-term only) or EPDM': O-Ring Supply Co., 'Best O-ring \
         material for steam' (secondary)",
    ),
    (
        "fkm",
        FluidClass::HotWater,
        Rating::NotRecommended,
        "'FKM — oils/fuels/acids/most chemicals (not amines, ketones, hot water)': PTI seal \
         chemical compatibility glossary, pti-latam.com (secondary); only special grades have \
         'some water immersion capability' (McNally Institute, O-ring selection)",
    ),
    (
        "epdm",
        FluidClass::MineralOil,
        Rating::NotRecommended,
        "EPDM 'is incompatible with mineral oils and will swell rapidly if used with them': \
         kingdaflex.com, 'Hydraulic fluid' (secondary); 'poor in mineral oils/fuels' (poesia.ch)",
    ),
    (
        "epdm",
        FluidClass::Water,
        Rating::Recommended,
        "'EPDM — water/steam/acids/bases (not mineral oils)': PTI seal chemical compatibility \
         glossary, pti-latam.com (secondary)",
    ),
    (
        "epdm",
        FluidClass::HotWater,
        Rating::Recommended,
        "'EPDM: excellent in hot water/steam and alkalis': Poesia, 'Chemical resistance' \
         lexicon, poesia.ch (secondary)",
    ),
    (
        "epdm",
        FluidClass::WaterGlycol,
        Rating::Recommended,
        "EPDM 'is required for water-based fluids, glycol solutions, and phosphate ester \
         fluids': kingdaflex.com, 'Hydraulic fluid' (secondary)",
    ),
    (
        "vmq",
        FluidClass::HotWater,
        Rating::Limited,
        "'silicone — wide temperature extremes (not steam, hydrocarbon solvents)': PTI seal \
         chemical compatibility glossary, pti-latam.com (secondary)",
    ),
];

/// The rating of library compound `id` (its class is the id's prefix, `fkm-75` → `fkm`) in
/// `class`; `None` when no source rated the pair.
pub fn rating(id: &str, class: FluidClass) -> Option<Compatibility> {
    let prefix = id.split('-').next().unwrap_or(id);
    RATINGS
        .iter()
        .find(|(p, c, _, _)| *p == prefix && *c == class)
        .map(|&(_, class, rating, source)| Compatibility {
            class,
            rating,
            source,
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The field practice the issue names: EPDM, not standard FKM, in hot water and hot
    /// coolant; EPDM not in mineral oil; NBR the mineral-oil default.
    #[test]
    fn hot_water_and_coolant_flag_fkm_and_mineral_oil_flags_epdm() {
        let hot = FluidClass::of("water", 353.15).unwrap();
        assert_eq!(hot, FluidClass::HotWater);
        let coolant = FluidClass::of("ethylene-glycol-water-50", 383.15).unwrap();
        assert_eq!(coolant, FluidClass::HotWater);
        for class in [hot, coolant] {
            assert_eq!(
                rating("fkm-75", class).unwrap().rating,
                Rating::NotRecommended
            );
            assert_eq!(
                rating("epdm-70", class).unwrap().rating,
                Rating::Recommended
            );
        }
        let oil = FluidClass::of("iso-vg-46", 393.15).unwrap();
        assert_eq!(
            rating("epdm-70", oil).unwrap().rating,
            Rating::NotRecommended
        );
        assert_eq!(rating("nbr-70", oil).unwrap().rating, Rating::Recommended);
        // below 80 °C water is water; a coolant below it is a coolant
        assert_eq!(FluidClass::of("water", 353.0), Some(FluidClass::Water));
        assert_eq!(
            FluidClass::of("ethylene-glycol-water-50", 300.0),
            Some(FluidClass::WaterGlycol)
        );
        // unrated pairs and uncovered fluids say nothing
        assert!(rating("hnbr-75", oil).is_none());
        assert!(FluidClass::of("helium", 300.0).is_none());
    }
}
