//! Fluid compatibility of a compound (docs/model.md §6.8): a rating per fluid class, stored in
//! the compound's file (`[material.compatibility]`, each with its source), printed by `run`
//! and `compare`; "not recommended" is a warning in `run` and a flag in the `compare` row.
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

    /// Every class, in the order a compound file lists them.
    pub const ALL: [FluidClass; 4] = [
        FluidClass::MineralOil,
        FluidClass::Water,
        FluidClass::HotWater,
        FluidClass::WaterGlycol,
    ];

    /// The class's key in `[material.compatibility]`.
    pub fn key(self) -> &'static str {
        match self {
            FluidClass::MineralOil => "mineral-oil",
            FluidClass::Water => "water",
            FluidClass::HotWater => "hot-water",
            FluidClass::WaterGlycol => "water-glycol",
        }
    }

    /// The class of a `[material.compatibility]` key.
    pub fn from_key(key: &str) -> Option<FluidClass> {
        FluidClass::ALL.into_iter().find(|c| c.key() == key)
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
    pub const ALL: [Rating; 3] = [Rating::Recommended, Rating::Limited, Rating::NotRecommended];

    /// The rating of a scale letter (`"A"`, `"B"`, `"X"`).
    pub fn from_letter(letter: &str) -> Option<Rating> {
        Rating::ALL
            .into_iter()
            .find(|r| letter.len() == 1 && letter.starts_with(r.letter()))
    }

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
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Compatibility {
    pub class: FluidClass,
    pub rating: Rating,
    /// Where the rating comes from, with the words it maps.
    pub source: String,
}

/// The rating in `class` among a compound's `ratings`; `None` when no source rated the pair.
pub fn rating(ratings: &[Compatibility], class: FluidClass) -> Option<&Compatibility> {
    ratings.iter().find(|c| c.class == class)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_and_letters_round_trip() {
        for class in FluidClass::ALL {
            assert_eq!(FluidClass::from_key(class.key()), Some(class));
        }
        for rating in Rating::ALL {
            assert_eq!(
                Rating::from_letter(&rating.letter().to_string()),
                Some(rating)
            );
        }
        assert_eq!(Rating::from_letter("C"), None);
        assert_eq!(Rating::from_letter("AB"), None);
        assert_eq!(FluidClass::from_key("hot water"), None);
    }
}
