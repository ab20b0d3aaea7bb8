//! The model reference `docs/model.md` is the project's own: every "§" the code, the tests, the
//! scenarios, the README and the user guide cite resolves to one of its headings, and nothing points outside the
//! repository.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

/// Section numbers of `docs/model.md` (`## 3. …` → "3", `### 3.1 …` → "3.1").
fn sections() -> BTreeSet<String> {
    let text = fs::read_to_string(root().join("docs/model.md")).unwrap();
    text.lines()
        .filter_map(|l| l.strip_prefix("## ").or_else(|| l.strip_prefix("### ")))
        .filter_map(|h| h.split_whitespace().next())
        .map(|n| n.trim_end_matches('.').to_owned())
        .filter(|n| n.chars().next().is_some_and(|c| c.is_ascii_digit()))
        .collect()
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files(&path, out);
        } else if matches!(
            path.extension().and_then(|e| e.to_str()),
            Some("rs" | "toml" | "md" | "py")
        ) {
            out.push(path);
        }
    }
}

/// Lines that cite another work's sections (the paper, textbooks, articles): their "§" are
/// that work's, except those written `docs/model.md §…`.
const OTHER_WORKS: [&str; 8] = [
    "PY08",
    "paper",
    "Johnson",
    "Numerical Recipes",
    "Springer",
    "PRE 64",
    "Persson",
    "ISO",
];

/// The section numbers cited right after each "§" of `line` (`§5–6` → "5"; `§9.10` → "9.10").
fn cited(line: &str, after: &str) -> Vec<String> {
    line.match_indices(after)
        .map(|(i, _)| {
            line[i + after.len()..]
                .trim_start()
                .chars()
                .take_while(|c| c.is_ascii_digit() || *c == '.')
                .collect::<String>()
                .trim_end_matches('.')
                .to_owned()
        })
        .filter(|n| !n.is_empty())
        .collect()
}

#[test]
fn every_section_cited_resolves_to_the_model_reference() {
    let known = sections();
    for must in ["1", "2", "3.1", "3.5", "6", "7", "9.1", "9.11"] {
        assert!(known.contains(must), "docs/model.md lacks §{must}");
    }
    let mut all = Vec::new();
    for dir in ["src", "tests", "benches", "scenarios", "materials"] {
        files(&root().join(dir), &mut all);
    }
    all.push(root().join("README.md"));
    // the user guide's own pages (docs/src/model/ is generated from docs/model.md)
    let mut guide = Vec::new();
    files(&root().join("docs/src"), &mut guide);
    all.extend(
        guide
            .into_iter()
            .filter(|p| !p.starts_with(root().join("docs/src/model"))),
    );
    let mut checked = 0;
    for path in &all {
        let text = fs::read_to_string(path).unwrap();
        for (n, line) in text.lines().enumerate() {
            assert!(
                !line.contains(concat!("../", "shared")) && !line.contains(concat!("DESIGN", " §")),
                "{}:{}: points outside the repository: {line}",
                path.display(),
                n + 1
            );
            let ours = if OTHER_WORKS.iter().any(|w| line.contains(w)) {
                cited(line, "model.md §")
            } else {
                cited(line, "§")
            };
            for s in ours {
                checked += 1;
                assert!(
                    known.contains(&s),
                    "{}:{}: §{s} is not a section of docs/model.md: {line}",
                    path.display(),
                    n + 1
                );
            }
        }
    }
    assert!(checked > 100, "only {checked} citations found");
}
