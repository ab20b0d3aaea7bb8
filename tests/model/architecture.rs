//! The layering of the library's top-level modules (ARCHITECTURE.md), checked on the source:
//! every `crate::module` reference outside unit tests — code and doc links alike, since a doc
//! link across a future crate boundary breaks too — is an edge. No edge may point from a lower
//! layer to a higher one, and the module graph has no cycle. `sealsim-math` is a crate of its
//! own, so an edge from it into the physics is a compile error. Inside the input layer the
//! submodules of `src/scenario/` form no cycle either, and the seal geometry's variants are
//! named only in the seal module and where the input builds them.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The intended layer of every top-level module, inner to outer: dependencies point inwards
/// (to a lower or equal layer). `math` is the `sealsim-math` crate.
const LAYERS: &[(&str, u8)] = &[
    ("math", 0),
    ("units", 1),
    ("codes", 1),
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
    ("plausibility", 3),
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
    // every node with an edge (a node without one is in no cycle)
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
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

/// The part of a source file before its unit-test module.
fn without_unit_tests(text: &str) -> &str {
    text.find("#[cfg(test)]\nmod tests")
        .map_or(text, |i| &text[..i])
}

/// The names a path prefix `prefix` (`super::`, `crate::scenario::`) is followed by in `text`:
/// the identifier right after it, or each first identifier of a `{…}` group.
fn names_after(text: &str, prefix: &str) -> BTreeSet<String> {
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect()
    };
    let mut found = BTreeSet::new();
    for (i, _) in text.match_indices(prefix) {
        let rest = &text[i + prefix.len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for part in group[..end].split(',') {
                found.insert(ident(part.trim()));
            }
        } else {
            found.insert(ident(rest));
        }
    }
    found.remove("");
    found
}

/// The graph of the input layer's submodules (`src/scenario/*.rs`, a folder counting as one
/// node; the unit-test-only modules `*_tests` and every `mod tests` left out), from every
/// `super::NAME` and `crate::scenario::NAME` in code and doc links alike:
///
/// * NAME a submodule: an edge to it;
/// * NAME re-exported by `mod.rs` from a submodule (`pub use x::Name`): an edge to `x`, its home;
/// * NAME an alias of a lower layer's module (`pub use crate::…`): no edge;
/// * otherwise NAME is an item of `mod.rs` itself: an edge to `mod`.
///
/// `mod.rs` declares every submodule, so it has an edge to each: it is the top, and a
/// submodule that uses an item of `mod.rs` (not a re-export) closes a cycle through it.
fn scenario_graph(dir: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let module_of = |path: &Path| -> String {
        let rel = path.strip_prefix(dir).unwrap();
        let first = rel.components().next().unwrap().as_os_str();
        first.to_string_lossy().trim_end_matches(".rs").to_string()
    };
    let mut files = Vec::new();
    rust_files(dir, &mut files);
    let submodules: BTreeSet<String> = files
        .iter()
        .map(|f| module_of(f))
        .filter(|m| m != "mod" && !m.ends_with("_tests"))
        .collect();
    let root = fs::read_to_string(dir.join("mod.rs")).unwrap();
    let root = without_unit_tests(&root);
    // re-exports: `pub use x::{A, B};`, `pub use x::A;` (x a submodule) and aliases
    let mut home: BTreeMap<String, Option<String>> = BTreeMap::new();
    for line in root.lines() {
        let Some(rest) = line.trim().strip_prefix("pub use ") else {
            continue;
        };
        let rest = rest.trim_end_matches(';');
        let (from, names) = rest.split_once("::{").map_or_else(
            || {
                let (from, name) = rest.rsplit_once("::").unwrap();
                (from.to_string(), vec![name.to_string()])
            },
            |(from, names)| {
                let names = names.trim_end_matches('}').split(',');
                (
                    from.to_string(),
                    names.map(|n| n.trim().to_string()).collect(),
                )
            },
        );
        for name in names {
            let module = submodules.contains(from.as_str()).then(|| from.clone());
            home.insert(name, module);
        }
    }
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    graph.insert("mod".into(), submodules.clone());
    for file in &files {
        let me = module_of(file);
        if !submodules.contains(&me) {
            continue;
        }
        let text = fs::read_to_string(file).unwrap();
        let code = without_unit_tests(&text);
        let mut names = names_after(code, "super::");
        names.extend(names_after(code, "crate::scenario::"));
        for name in names {
            let to = if submodules.contains(&name) {
                Some(name)
            } else if name == "self" {
                Some("mod".to_string())
            } else {
                match home.get(&name) {
                    Some(module) => module.clone(),
                    None => Some("mod".to_string()),
                }
            };
            if let Some(to) = to.filter(|to| *to != me) {
                graph.entry(me.clone()).or_default().insert(to);
            }
        }
    }
    graph
}

/// The input layer's submodules import each other in no circle (ARCHITECTURE.md, "How it got
/// there"): shared pieces live in a lower submodule (`text`, `field`, `seal_spec`, …), never
/// in `mod.rs`, which only declares, re-exports and holds the entry points.
#[test]
fn the_scenario_submodules_have_no_cycle() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/scenario");
    let graph = scenario_graph(&dir);
    // the walk sees the graph (the key registry names the tables' modules, validate reads the
    // life tables with them)
    assert!(graph["keys"].contains("life") && graph["validate"].contains("life"));
    let found = cycles(&graph);
    assert!(
        found.is_empty(),
        "import cycles among src/scenario's submodules: {found:?}; edges: {graph:?}"
    );
}

/// The scenario graph's reading of names, on a planted module tree.
#[test]
fn the_scenario_graph_resolves_re_exports_and_items_of_the_root() {
    let dir = std::env::temp_dir().join(format!("sealsim-arch-{}", std::process::id()));
    fs::create_dir_all(dir.join("folder")).unwrap();
    let write = |name: &str, text: &str| fs::write(dir.join(name), text).unwrap();
    write(
        "mod.rs",
        "mod a;\nmod b;\nmod c;\nmod folder;\npub use c::{Thing, Other};\n\
         pub use crate::x::alias;\npub fn helper() {}\n",
    );
    write("a.rs", "use super::b::B;\n");
    write("c.rs", "/// no edge: [`Vec`]\n");
    write("b.rs", "use super::alias;\nfn f() { super::helper(); }\n");
    write("folder/mod.rs", "use crate::scenario::Thing;\n");
    write("c_tests.rs", "use super::helper;\n");
    let graph = scenario_graph(&dir);
    fs::remove_dir_all(&dir).unwrap();
    let set = |names: &[&str]| names.iter().map(|n| n.to_string()).collect::<BTreeSet<_>>();
    assert_eq!(graph["mod"], set(&["a", "b", "c", "folder"]));
    assert_eq!(graph["a"], set(&["b"]));
    assert_eq!(
        graph["b"],
        set(&["mod"]),
        "an item of mod.rs: an edge to mod"
    );
    assert_eq!(
        graph["folder"],
        set(&["c"]),
        "a re-export: an edge to its home"
    );
    assert!(!graph.contains_key("c") && !graph.contains_key("c_tests"));
    // b → mod → a → b: the cycle a helper in mod.rs closes (c and folder are outside it)
    assert_eq!(
        cycles(&graph),
        BTreeSet::from([vec!["a".to_string(), "b".into(), "mod".into()]])
    );
}

/// Where the seal geometry's variants may be named outside the seal module
/// (`crates/sealsim-core/src/seal/`): the input's construction sites, a ring between plates or a
/// flat seal in `seal_kind.rs` and a groove-seated ring in `gland.rs` — three in all. Every other
/// use of a kind's behaviour is a method of `SealGeometry`, so a new seal kind touches the seal
/// module and the input's kind file, not every file that matched on the kinds before.
const SEAL_VARIANT_SITES: &[(&str, usize)] = &[
    ("src/scenario/gland.rs", 1),
    ("src/scenario/seal_kind.rs", 2),
];

#[test]
fn seal_kinds_are_matched_only_in_the_seal_module() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for src in ["src", "crates/sealsim-core/src"] {
        rust_files(&root.join(src), &mut files);
    }
    let seal_module = root.join("crates/sealsim-core/src/seal");
    let mut found: Vec<(String, usize)> = files
        .iter()
        .filter(|f| !f.starts_with(&seal_module))
        .filter_map(|f| {
            let text = fs::read_to_string(f).unwrap();
            let n = without_unit_tests(&text).matches("SealGeometry::").count();
            let rel = f
                .strip_prefix(root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            (n > 0).then_some((rel, n))
        })
        .collect();
    found.sort();
    let allowed: Vec<(String, usize)> = SEAL_VARIANT_SITES
        .iter()
        .map(|(f, n)| (f.to_string(), *n))
        .collect();
    assert_eq!(
        found, allowed,
        "`SealGeometry::` outside crates/sealsim-core/src/seal/ (unit tests left out): a kind's \
         behaviour belongs in its kind file behind a method of SealGeometry"
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
