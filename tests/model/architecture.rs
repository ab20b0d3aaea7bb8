//! The layering of the library's top-level modules (ARCHITECTURE.md), checked on the source:
//! every `crate::module` reference outside unit tests — code and doc links alike, since a doc
//! link across a future crate boundary breaks too — is an edge. No edge may point from a lower
//! layer to a higher one, and the module graph has no cycle. `sealsim-math` is a crate of its
//! own, so an edge from it into the physics is a compile error.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The intended layer of every top-level module, inner to outer: dependencies point inwards
/// (to a lower or equal layer). `math` is the `sealsim-math` crate.
const LAYERS: &[(&str, u8)] = &[
    ("math", 0),
    ("units", 1),
    ("gas", 2),
    ("fluid", 2),
    ("interface", 2),
    ("surface", 2),
    ("roughness", 2),
    ("contact", 3),
    ("seal", 3),
    ("gland", 3),
    ("extrusion", 3),
    ("fits", 3),
    ("gland_design", 3),
    ("permeation", 3),
    ("material", 3),
    ("clogging", 3),
    ("pressure", 3),
    ("numerical", 4),
    ("profile", 4),
    ("leak", 4),
    ("dynamic", 4),
    ("validity", 4),
    ("simulate", 5),
    ("study", 6),
    ("scenario", 7),
    ("workflow", 8),
    ("report", 9),
    ("cli", 10),
];

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The identifiers right after `crate::` (and inside `crate::{…}` groups) in `text`.
fn referenced_modules(text: &str) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect()
    };
    for (i, _) in text.match_indices("crate::") {
        let rest = &text[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for part in group[..end].split(',') {
                found.insert(ident(part.trim()));
            }
        } else {
            found.insert(ident(rest));
        }
    }
    found
}

/// Module → the modules it references, from the library's source (unit-test modules left out).
fn edges() -> BTreeMap<String, BTreeSet<String>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let modules: BTreeSet<&str> = LAYERS.iter().map(|(m, _)| *m).collect();
    let mut files = Vec::new();
    // the root package (input, workflow, report, cli) and the physics crate
    for src in [root.join("src"), root.join("crates/sealsim-core/src")] {
        let mut found = Vec::new();
        rust_files(&src, &mut found);
        files.extend(found.into_iter().map(|f| (src.clone(), f)));
    }
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut seen = BTreeSet::new();
    for (src, file) in files {
        let rel = file.strip_prefix(&src).unwrap();
        let first = rel
            .components()
            .next()
            .unwrap()
            .as_os_str()
            .to_string_lossy();
        let top = first.trim_end_matches(".rs").to_string();
        if top == "lib" || top == "main" {
            continue;
        }
        assert!(
            modules.contains(top.as_str()),
            "module `{top}` has no layer in LAYERS"
        );
        seen.insert(top.clone());
        let text = fs::read_to_string(&file).unwrap();
        let code = text
            .find("#[cfg(test)]\nmod tests")
            .map_or(text.as_str(), |i| &text[..i]);
        for m in referenced_modules(code) {
            if m != top && modules.contains(m.as_str()) {
                graph.entry(top.clone()).or_default().insert(m);
            }
        }
    }
    // every module with a layer was found (the walk covers the whole library)
    let missing: Vec<_> = modules
        .iter()
        .filter(|m| **m != "math" && !seen.contains(**m))
        .collect();
    assert!(
        missing.is_empty(),
        "modules not found in the source: {missing:?}"
    );
    graph
}

/// Strongly connected components with more than one module (Tarjan), each sorted.
fn cycles(graph: &BTreeMap<String, BTreeSet<String>>) -> BTreeSet<Vec<String>> {
    struct State<'a> {
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        next: usize,
        found: BTreeSet<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        s.index.insert(v, s.next);
        s.low.insert(v, s.next);
        s.next += 1;
        s.stack.push(v);
        let graph = s.graph;
        for w in graph.get(v).into_iter().flatten() {
            let w = w.as_str();
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if s.stack.contains(&w) {
                let iw = s.index[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                component.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                s.found.insert(component);
            }
        }
    }
    let mut s = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        next: 0,
        found: BTreeSet::new(),
    };
    for v in LAYERS.iter().map(|(m, _)| *m) {
        if !s.index.contains_key(v) {
            visit(&mut s, v);
        }
    }
    s.found
}

#[test]
fn module_edges_point_inwards() {
    let layer: BTreeMap<&str, u8> = LAYERS.iter().copied().collect();
    let upward: Vec<(String, String)> = edges()
        .into_iter()
        .flat_map(|(from, tos)| tos.into_iter().map(move |to| (from.clone(), to)))
        .filter(|(from, to)| layer[from.as_str()] < layer[to.as_str()])
        .collect();
    assert!(
        upward.is_empty(),
        "edges from an inner layer to an outer one (ARCHITECTURE.md): {upward:?}"
    );
}

#[test]
fn the_module_graph_has_no_cycle() {
    let found = cycles(&edges());
    assert!(found.is_empty(), "module cycles: {found:?}");
}

/// The detector itself, on a graph with a known answer.
#[test]
fn the_cycle_finder_finds_a_planted_cycle_and_nothing_else() {
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut edge = |a: &str, b: &str| {
        graph.entry(a.into()).or_default().insert(b.into());
    };
    edge("units", "surface");
    edge("surface", "contact");
    edge("contact", "units");
    edge("leak", "contact");
    let found = cycles(&graph);
    assert_eq!(
        found,
        BTreeSet::from([vec![
            "contact".to_string(),
            "surface".into(),
            "units".into()
        ]])
    );
    assert_eq!(
        referenced_modules("use crate::{leak, seal::Seal};\nlet x = crate::units::human(1.0, 3);"),
        BTreeSet::from(["leak".to_string(), "seal".into(), "units".into()])
    );
}

/// `[[package]]` name → its dependencies' names, from Cargo.lock.
fn locked_graph() -> BTreeMap<String, Vec<String>> {
    let lock =
        fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.lock")).unwrap();
    let mut graph = BTreeMap::new();
    for block in lock.split("[[package]]").skip(1) {
        let name = block
            .lines()
            .find_map(|l| l.strip_prefix("name = \""))
            .and_then(|n| n.strip_suffix('"'))
            .unwrap()
            .to_string();
        let deps = block
            .split_once("dependencies = [")
            .map(|(_, rest)| {
                rest.split(']')
                    .next()
                    .unwrap_or("")
                    .split(',')
                    .filter_map(|d| d.trim().trim_matches('"').split(' ').next())
                    .filter(|d| !d.is_empty())
                    .map(str::to_string)
                    .collect()
            })
            .unwrap_or_default();
        graph.insert(name, deps);
    }
    graph
}

/// The packages reachable from `root` in Cargo.lock, not entering those in `skip`. The lock
/// does not tell normal from dev-dependencies, so a crate's dev-dependencies go in `skip`.
fn closure(graph: &BTreeMap<String, Vec<String>>, root: &str, skip: &[&str]) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    let mut todo = vec![root.to_string()];
    while let Some(p) = todo.pop() {
        if skip.contains(&p.as_str()) || !seen.insert(p.clone()) {
            continue;
        }
        todo.extend(graph.get(&p).into_iter().flatten().cloned());
    }
    seen
}

/// The physics crate knows no file format, command line, chart or progress bar: none of serde,
/// toml, csv, clap, plotters or indicatif is among its dependencies. The one exception is
/// serde inside `ode_solvers` (a specified crate whose serde dependency is not optional): left
/// out `ode_solvers`, the closure has none of them. `sealsim-math` has none at all.
#[test]
fn the_core_crates_depend_on_no_io_or_cli_crate() {
    let graph = locked_graph();
    let forbidden = [
        "serde",
        "serde_core",
        "serde_derive",
        "serde_json",
        "toml",
        "csv",
        "clap",
        "plotters",
        "indicatif",
    ];
    // proptest: sealsim-core's only dev-dependency
    let core = closure(&graph, "sealsim-core", &["ode_solvers", "proptest"]);
    assert!(
        core.contains("sealsim-math") && core.contains("statrs"),
        "{core:?}"
    );
    let math = closure(&graph, "sealsim-math", &[]);
    for name in forbidden {
        assert!(!core.contains(name), "sealsim-core depends on {name}");
        assert!(!math.contains(name), "sealsim-math depends on {name}");
    }
    // and the exception is what it says: serde comes in through ode_solvers only
    assert!(closure(&graph, "ode_solvers", &[]).contains("serde"));
    // the root package does use them (the check can see a dependency)
    assert!(closure(&graph, "sealsim", &[]).contains("toml"));
}
