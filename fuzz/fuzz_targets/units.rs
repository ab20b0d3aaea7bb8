//! The unit and quantity parser: any text, against every dimension the scenarios use. A result
//! is an error or a finite number.
#![no_main]

use libfuzzer_sys::fuzz_target;
use sealsim::units::{self, Dimension};

const DIMENSIONS: [Dimension; 12] = [
    Dimension::DIMENSIONLESS,
    Dimension::LENGTH,
    Dimension::WAVEVECTOR,
    Dimension::SPECTRUM,
    Dimension::TIME,
    Dimension::TEMPERATURE,
    Dimension::PRESSURE,
    Dimension::VISCOSITY,
    Dimension::VOLUME_FLOW,
    Dimension::VOLUME,
    Dimension::VELOCITY,
    Dimension::MOLAR_ENERGY,
];

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let dimension = DIMENSIONS[usize::from(selector) % DIMENSIONS.len()];
    if let Ok(v) = units::parse_quantity(text, dimension) {
        assert!(v.is_finite(), "parse_quantity({text:?}) = {v}");
    }
    if let Ok(v) = units::parse_temperature(text) {
        assert!(v.is_finite(), "parse_temperature({text:?}) = {v}");
    }
    if let Ok((factor, _)) = units::parse_unit(text) {
        assert!(factor.is_finite(), "parse_unit({text:?}) factor {factor}");
    }
});
