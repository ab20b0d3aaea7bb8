//! `sealsim generate keys`: the scenario key reference, to standard output or atomically to a
//! file, byte for byte the committed `docs/src/reference/keys.md`; `keys` is hidden from help.
//! `sealsim generate columns` likewise, and the CSV headers `run` and `leak` write are the column
//! registry's.

use super::support::sealsim;
use std::path::Path;

/// The committed key reference.
fn committed() -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/reference/keys.md"),
    )
    .unwrap()
}

#[test]
fn keys_goes_to_stdout_or_to_a_file_and_is_the_committed_reference() {
    let out = sealsim().args(["generate", "keys"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(stdout, committed());
    assert!(stdout.contains("| `squeeze` |"), "{stdout}");

    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("keys.md");
    let out = sealsim()
        .args(["generate", "keys", "-o"])
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&file).unwrap(), stdout);
}

#[test]
fn keys_is_hidden_from_help() {
    let out = sealsim().args(["generate", "--help"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(help.contains("Usage: sealsim generate"), "{help}");
    assert!(!help.contains("keys"), "{help}");
}

/// The header line of CSV text.
fn header(csv: &str) -> Vec<String> {
    csv.lines()
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect()
}

/// The registry's columns of `file` (0 leak, 1 run) for the groups `which`.
fn registered(file: usize, which: &[usize]) -> Vec<String> {
    let groups = sealsim::report::columns::FILES[file].groups;
    let chosen: Vec<_> = which.iter().map(|&i| groups[i]).collect();
    sealsim::report::columns::names(&chosen)
        .into_iter()
        .map(str::to_owned)
        .collect()
}

#[test]
fn the_csv_headers_written_are_the_column_registry_s() {
    let dir = tempfile::tempdir().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    // (scenario, the groups of its history and of its leak table)
    let cases: [(&str, &[usize], &[usize]); 3] = [
        ("persson-yang-2008.toml", &[0], &[0]),
        ("hydrogen-line-100bar.toml", &[0, 1], &[0, 1]),
        ("hydraulic-rod-seal.toml", &[0, 2, 3], &[0, 2, 3]),
    ];
    for (scenario, history, leak) in cases {
        let csv = dir.path().join(format!("{scenario}.csv"));
        let out = sealsim()
            .arg("run")
            .arg(root.join(scenario))
            .arg("-o")
            .arg(&csv)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{scenario}");
        let text = std::fs::read_to_string(&csv).unwrap();
        assert_eq!(header(&text), registered(1, history), "run {scenario}");
        let out = sealsim()
            .arg("leak")
            .arg(root.join(scenario))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{scenario}");
        let text = String::from_utf8(out.stdout).unwrap();
        assert_eq!(header(&text), registered(0, leak), "leak {scenario}");
    }
}

#[test]
fn columns_is_the_committed_reference() {
    let out = sealsim().args(["generate", "columns"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let committed = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/reference/columns.md"),
    )
    .unwrap();
    assert_eq!(String::from_utf8(out.stdout).unwrap(), committed);
}

#[test]
fn warnings_is_the_committed_page_and_lists_every_code() {
    let out = sealsim().args(["generate", "warnings"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8(out.stdout).unwrap();
    let committed = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/src/reference/warnings.md"),
    )
    .unwrap();
    assert!(
        stdout == committed,
        "docs/src/reference/warnings.md is stale: run `sealsim generate warnings -o \
         docs/src/reference/warnings.md`"
    );
    for c in sealsim::codes::ALL {
        assert!(stdout.contains(&format!("\n## {}\n", c.code)), "{}", c.code);
    }
}

/// `python3 benches/performance.py render --check [--page PAGE]`: its exit code and stderr.
fn performance_check(page: Option<&Path>) -> (Option<i32>, String) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut cmd = std::process::Command::new("python3");
    cmd.current_dir(root)
        .args(["benches/performance.py", "render", "--check"]);
    if let Some(page) = page {
        cmd.arg("--page").arg(page);
    }
    let out = cmd
        .output()
        .expect("python3 runs (the page's generator is Python 3, standard library only)");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// docs/src/performance.md is what `benches/performance.py render` makes of the committed
/// measurements (benches/results/measurements.json) and the template (issue 43): no benchmark
/// runs here, only the rendering. Every figure row ends with its date · commit · machine, and
/// every machine named is described in the machine table.
#[test]
fn performance_page_is_rendered_from_the_store() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (code, stderr) = performance_check(None);
    assert_eq!(
        code,
        Some(0),
        "docs/src/performance.md is stale: run `python3 benches/performance.py render`\n{stderr}"
    );

    // the check can fail: a page with one figure changed is refused
    let page = std::fs::read_to_string(root.join("docs/src/performance.md")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let tampered = dir.path().join("performance.md");
    std::fs::write(&tampered, page.replacen(" ms", " µs", 1)).unwrap();
    let (code, stderr) = performance_check(Some(&tampered));
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("render"), "{stderr}");

    // every figure row states its provenance; the machines it names are described
    let provenance =
        regex::Regex::new(r"(\d{4}-\d{2}-\d{2}) · ([0-9a-f]{7,}(-dirty)?) · ([a-z0-9-]+)").unwrap();
    let machines: Vec<&str> = page
        .lines()
        .filter_map(|l| l.strip_prefix("| vm-"))
        .filter_map(|l| l.split(" |").next())
        .collect();
    assert!(!machines.is_empty(), "no machine table");
    let mut rows = 0;
    for line in page.lines().filter(|l| l.starts_with("| ")) {
        if line.starts_with("| what |")
            || line.starts_with("| machine |")
            || line.starts_with("| vm-")
        {
            continue;
        }
        let cells: Vec<&str> = line.trim_end_matches(" |").rsplit(" | ").collect();
        let last = cells[0];
        let found: Vec<_> = provenance.captures_iter(last).collect();
        assert!(
            !found.is_empty(),
            "a row without date · commit · machine: {line}"
        );
        for c in found {
            let id = c[4].strip_prefix("vm-").unwrap_or(&c[4]);
            assert!(
                machines.contains(&id),
                "machine {} not described: {line}",
                &c[4]
            );
        }
        rows += 1;
    }
    assert!(rows >= 20, "{rows} figure rows");
}
