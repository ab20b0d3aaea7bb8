//! The shipped material library: one TOML file per compound in `materials/`, embedded at
//! compile time so that the binary works from any directory. A compound's id is its file stem
//! (`nbr-70` ↔ `materials/nbr-70.toml`); the file format is the material schema of
//! [`crate::material::compound`] with `name`, `status` and complete provenance required.

use std::fmt;
use std::path::PathBuf;

/// (id, file text) of every library compound, sorted by id. A new file in `materials/` must be
/// added here (a unit test checks that the two agree).
pub const FILES: &[(&str, &str)] = &[
    ("acm-70", include_str!("../../materials/acm-70.toml")),
    ("cr-70", include_str!("../../materials/cr-70.toml")),
    ("epdm-70", include_str!("../../materials/epdm-70.toml")),
    ("ffkm-75", include_str!("../../materials/ffkm-75.toml")),
    ("fkm-75", include_str!("../../materials/fkm-75.toml")),
    ("fvmq-70", include_str!("../../materials/fvmq-70.toml")),
    ("hnbr-75", include_str!("../../materials/hnbr-75.toml")),
    ("iir-70", include_str!("../../materials/iir-70.toml")),
    ("nbr-70", include_str!("../../materials/nbr-70.toml")),
    ("vmq-70", include_str!("../../materials/vmq-70.toml")),
];

/// The ids of the library compounds, sorted.
pub fn ids() -> impl Iterator<Item = &'static str> {
    FILES.iter().map(|(id, _)| *id)
}

/// One library compound, not yet parsed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Entry {
    /// The id (file stem), e.g. `nbr-70`.
    pub id: &'static str,
    /// The embedded TOML text.
    pub text: &'static str,
}

impl Entry {
    /// The file the entry was embedded from, relative to the crate root (used in messages).
    pub fn path(&self) -> PathBuf {
        PathBuf::from(format!("materials/{}.toml", self.id))
    }
}

/// The library compound `id`, or an error listing the known ids.
pub fn get(id: &str) -> Result<Entry, UnknownMaterial> {
    FILES
        .iter()
        .find(|(known, _)| *known == id)
        .map(|&(id, text)| Entry { id, text })
        .ok_or_else(|| UnknownMaterial { id: id.to_owned() })
}

/// An id that is not in the library.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownMaterial {
    pub id: String,
}

impl fmt::Display for UnknownMaterial {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "unknown library material {:?}; the library has: {}",
            self.id,
            ids().collect::<Vec<_>>().join(", ")
        )
    }
}

impl std::error::Error for UnknownMaterial {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Status;
    use crate::scenario::material::PARAMETERS;

    #[test]
    fn every_file_in_materials_is_embedded() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("materials");
        let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .filter_map(|e| {
                let path = e.unwrap().path();
                (path.extension()? == "toml")
                    .then(|| path.file_stem().map(|s| s.to_string_lossy().into_owned()))?
            })
            .collect();
        on_disk.sort();
        let embedded: Vec<&str> = ids().collect();
        assert_eq!(
            on_disk, embedded,
            "materials/*.toml and library::FILES differ"
        );
        assert!(
            embedded.windows(2).all(|w| w[0] < w[1]),
            "FILES must be sorted by id"
        );
    }

    #[test]
    fn every_library_file_parses_with_complete_provenance_and_wide_prony() {
        assert!(!FILES.is_empty());
        for entry in FILES.iter().map(|&(id, text)| Entry { id, text }) {
            let m = entry.load().unwrap_or_else(|e| panic!("{e}"));
            assert!(!m.name.is_empty(), "{}", entry.id);
            assert!(
                matches!(m.status, Status::Published | Status::Illustrative),
                "{}",
                entry.id
            );
            // a provenance for every parameter the compound gives, and only for those
            let given: Vec<&str> = PARAMETERS
                .into_iter()
                .filter(|&p| match p {
                    "poisson_ratio" => true,
                    "youngs_modulus" => false,
                    "long_term_modulus" | "prony" => !m.prony.terms().is_empty(),
                    "shift" => m.shift != crate::material::Shift::None,
                    "glass_transition" => m.glass_transition.is_some(),
                    "thermal_expansion" => m.thermal_expansion.is_some(),
                    "glassy_thermal_expansion" => m.glassy_thermal_expansion.is_some(),
                    "ageing" => m.ageing.is_some(),
                    _ => false,
                })
                .collect();
            for p in &given {
                let text = m.provenance_of(p).unwrap_or_default();
                assert!(
                    !text.trim().is_empty(),
                    "{}: no provenance for {p}",
                    entry.id
                );
            }
            // a viscoelastic series covering at least ten decades of relaxation times
            let terms = m.prony.terms();
            assert!(terms.len() >= 2, "{}: not viscoelastic", entry.id);
            let decades = (terms[terms.len() - 1].tau / terms[0].tau).log10();
            assert!(
                decades >= 10.0,
                "{}: τ spans only {decades} decades",
                entry.id
            );
            assert!(m.prony.long_term() > 0.0, "{}: E∞ = 0", entry.id);
        }
    }

    #[test]
    fn unknown_ids_list_the_known_ones() {
        let e = get("nbr-99").unwrap_err().to_string();
        assert!(e.contains("\"nbr-99\""), "{e}");
        for id in ids() {
            assert!(e.contains(id), "{e}");
        }
        assert_eq!(get("nbr-70").map(|e| e.id), Ok("nbr-70"));
    }
}
