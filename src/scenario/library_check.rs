//! `sealsim materials check`: every library compound's figures beside the published ones every
//! seal engineer knows (docs/model.md §6.7), and the same comparisons as tests.
//!
//! * **Low-temperature limit.** The compound's T10 (the temperature at which its modulus at 10 s
//!   is ten times its 23 °C value, [`Material::low_temperature_limit`]) against the standard
//!   compound's low-temperature service limit of one seal maker's chart for all classes: Bode
//!   Seal, "1 PROPERTIES OF ELASTOMER" (<https://www.bodeseal.com/technical-support/>; the
//!   quotes are in docs/sources/elastomer-temperatures.md). A chart limit, not a TR-10 (ASTM
//!   D1329) value: no TR-10 per class was found; the chart limits stand in. Tolerance:
//!   [`T10_TOLERANCE`].
//! * **Ageing against the rated temperature.** "The high-temperature limit for seal thermal
//!   stability is generally considered a 30–50% loss of physical properties and typically
//!   represents a maximum temperature for 1,000 hours continuous service" (Problem Solving
//!   Products, "Seal thermal stability", pspglobal.com). sealsim's two-network ageing at constant
//!   squeeze takes the force as `exp(−k t)`, so the chemical time to 50 % retained force at the
//!   rated temperature T_r is `t50 = ln 2 / k(T_r)`, `k(T) = k_ref exp(−Ea/R (1/T − 1/T_ref))`
//!   (Ea on the side of T_ref that T_r lies, [`crate::material::Ageing::rate_at`]);
//!   the rule asks about 1000 h, accepted within [`T50_BAND`] (a factor of 2).

use crate::material::Material;

/// |T10 − published limit| accepted \[K\].
pub const T10_TOLERANCE: f64 = 5.0;

/// Chemical hours to 50 % retained force at the rated temperature accepted by the rule.
pub const T50_BAND: (f64, f64) = (500.0, 2000.0);

/// The hours the rule names.
pub const RULE_HOURS: f64 = 1000.0;

/// A class's published figures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Published {
    /// Library id.
    pub id: &'static str,
    /// Low-temperature service limit of the standard compound \[K\].
    pub low_limit: f64,
    /// Rated (maximum continuous service) temperature \[K\].
    pub rated: f64,
    /// Where both come from.
    pub source: &'static str,
}

const BODE: &str = "Bode Seal, '1 PROPERTIES OF ELASTOMER' (bodeseal.com/technical-support), \
                    standard compound";

/// The published figures of every library compound's class.
pub const PUBLISHED: &[Published] = &[
    Published {
        id: "acm-70",
        low_limit: 263.15,
        rated: 423.15,
        source: "polymerdatabase.com, 'ACM': 'low temperature applications are usually limited to \
                 approximately -10°C', 'typical continuous service temperature range is -10°C to \
                 150°C'",
    },
    Published {
        id: "cr-70",
        low_limit: 233.15,
        rated: 373.15,
        source: BODE,
    },
    Published {
        id: "epdm-70",
        low_limit: 223.15,
        rated: 423.15,
        source: "Bode Seal, '1 PROPERTIES OF ELASTOMER' (bodeseal.com/technical-support), \
                 EPDM peroxide-cured",
    },
    Published {
        id: "ffkm-75",
        low_limit: 258.15,
        rated: 533.15,
        source: BODE,
    },
    Published {
        id: "fkm-75",
        low_limit: 258.15,
        rated: 473.15,
        source: BODE,
    },
    Published {
        id: "fvmq-70",
        low_limit: 218.15,
        rated: 448.15,
        source: BODE,
    },
    Published {
        id: "hnbr-75",
        low_limit: 243.15,
        rated: 423.15,
        source: BODE,
    },
    Published {
        id: "iir-70",
        low_limit: 218.15,
        rated: 378.15,
        source: "EMI Seals, '308 Butyl rubber' data sheet: 'Temperature Range: -55°C to +105°C'",
    },
    Published {
        id: "nbr-70",
        low_limit: 243.15,
        rated: 373.15,
        source: BODE,
    },
    Published {
        id: "vmq-70",
        low_limit: 218.15,
        rated: 473.15,
        source: BODE,
    },
];

/// One compound's check.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    pub published: Published,
    /// The compound's T10 \[K\] (`None`: no shift, no limit).
    pub t10: Option<f64>,
    /// Chemical hours to 50 % retained force at the rated temperature (`None`: no ageing
    /// constants).
    pub t50_hours: Option<f64>,
}

impl Check {
    /// The check of `material` against `published`.
    pub fn new(material: &Material, published: Published) -> Self {
        let t50_hours = material
            .ageing
            .map(|a| std::f64::consts::LN_2 / a.rate_at(published.rated) / 3600.0);
        Check {
            published,
            t10: material.low_temperature_limit(),
            t50_hours,
        }
    }

    /// Whether T10 lies within [`T10_TOLERANCE`] of the published limit.
    pub fn t10_ok(&self) -> bool {
        self.t10
            .is_some_and(|t| (t - self.published.low_limit).abs() <= T10_TOLERANCE)
    }

    /// Whether t50 lies in [`T50_BAND`].
    pub fn t50_ok(&self) -> bool {
        self.t50_hours
            .is_some_and(|h| (T50_BAND.0..=T50_BAND.1).contains(&h))
    }
}

/// The published figures of library compound `id`.
pub fn published(id: &str) -> Option<Published> {
    PUBLISHED.iter().copied().find(|p| p.id == id)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::library;

    /// The gas constant R \[J/(mol K)\] (CODATA 2018, exact).
    const R_GAS: f64 = 8.314_462_618;

    fn check(id: &str) -> Check {
        let material = library::get(id).unwrap().load().unwrap();
        Check::new(&material, published(id).unwrap())
    }

    #[test]
    fn every_library_compound_has_published_figures() {
        for id in library::ids() {
            assert!(published(id).is_some(), "{id}");
        }
        assert_eq!(PUBLISHED.len(), library::ids().count());
    }

    /// T10 of every compound within 5 K of its class's published low-temperature limit.
    #[test]
    fn t10_meets_the_published_low_temperature_limit() {
        for id in library::ids() {
            let c = check(id);
            assert!(
                c.t10_ok(),
                "{id}: T10 {:?} K vs {} K",
                c.t10,
                c.published.low_limit
            );
        }
    }

    /// The chemical time to 50 % retained force at the rated temperature within a factor of 2
    /// of the 1000 h rule.
    #[test]
    fn ageing_meets_the_rated_temperature_rule() {
        for id in library::ids() {
            let c = check(id);
            assert!(c.t50_ok(), "{id}: t50 {:?} h", c.t50_hours);
        }
    }

    /// The closed form on a made-up compound: k_ref = ln 2/(1000 h) at T_r gives 1000 h.
    #[test]
    fn t50_is_ln2_over_k_at_the_rated_temperature() {
        let mut m = library::get("nbr-70").unwrap().load().unwrap();
        let ageing = m.ageing.as_mut().unwrap();
        ageing.rate = std::f64::consts::LN_2 / (RULE_HOURS * 3600.0);
        ageing.reference_temperature = 373.15;
        let c = Check::new(&m, published("nbr-70").unwrap());
        assert!((c.t50_hours.unwrap() / RULE_HOURS - 1.0).abs() < 1e-12);
        // 10 K above T_r: faster by exp(Ea/R (1/T_r − 1/(T_r + 10)))
        let hot = Published {
            rated: 383.15,
            ..c.published
        };
        let ea = m.ageing.unwrap().activation_energy;
        let factor = (ea / R_GAS * (1.0 / 373.15 - 1.0 / 383.15)).exp();
        let h = Check::new(&m, hot).t50_hours.unwrap();
        assert!((h * factor / RULE_HOURS - 1.0).abs() < 1e-12);
    }
}
