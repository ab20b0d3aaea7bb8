//! The user guide's commands, run and their quoted outputs checked (issue 33).
//!
//! Every ```` ```console ```` block of every Markdown file under `docs/src/` (the book, generated
//! chapters included when present) and of `README.md` is run by [trycmd]: a line `$ sealsim …`
//! is a command (`> ` continues it), an optional `? N` line its exit status (default: success),
//! and the lines after it up to the next command are its expected output — stdout and stderr
//! together, as a terminal shows them when both go to one pipe (sealsim's stderr notes come
//! first). The comparison is exact, except that `...` on a line of its own stands for any number
//! of lines and `[..]` inside a line for any text in that line.
//!
//! Commands run as if from the repository root (`scenarios/…` paths), but not in it: each
//! Markdown file runs in its own temporary directory holding symbolic links to the repository's
//! top-level entries (trycmd's sandbox: a `NAME.in` template and an empty `NAME.out`), so a
//! command's outputs (`-o hist.csv`, `--report r.html`) land in the temporary directory and
//! nothing is written into the repository. The blocks of one file run in order in the same
//! directory, so a later command may read what an earlier one wrote.
//!
//! Only `sealsim` can be run. A block of other commands (`cargo install …`) must be marked
//! ```` ```console,ignore ```` or use another info string (`sh`, `text`).
//!
//! Run: `cargo test --release --test guide`. A failure shows the block's file (a copy in the
//! temporary directory named after the original, `docs__src__tutorials__face-gland.md`), the
//! command and a diff of the expected and the actual output. After a deliberate change of an
//! output, `TRYCMD=overwrite cargo test --release --test guide` writes the actual outputs into
//! the Markdown files (keeping the `...`/`[..]` elisions where they still match); review the
//! diff before committing it.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    reason = "tests: a failure is a test failure"
)]

use std::fs;
use std::path::{Path, PathBuf};

/// The repository root (the package's manifest directory).
fn repo() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Markdown files under `dir`, recursively, sorted.
fn markdown_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.map(|e| e.unwrap().path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            markdown_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "md") {
            out.push(path);
        }
    }
}

/// Whether `text` has a fenced block that trycmd runs: info string `console` (or `trycmd`)
/// without `ignore`.
fn has_console_block(text: &str) -> bool {
    text.lines().any(|line| {
        let Some(info) = line.trim_start().strip_prefix("```") else {
            return false;
        };
        let mut parts = info.split(',').map(str::trim);
        matches!(parts.next(), Some("console" | "trycmd")) && !parts.any(|p| p == "ignore")
    })
}

/// The Markdown files the guide test covers, with the number of console blocks in each.
fn guide_files() -> Vec<PathBuf> {
    let root = repo();
    let mut files = Vec::new();
    markdown_files(&root.join("docs/src"), &mut files);
    files.push(root.join("README.md"));
    files
        .into_iter()
        .filter(|p| has_console_block(&fs::read_to_string(p).unwrap()))
        .collect()
}

#[test]
fn guide_commands_and_outputs() {
    let root = repo();
    let files = guide_files();
    // The tutorials alone quote commands in eight files: finding fewer means the walk is broken,
    // not that the guide has no commands.
    assert!(
        files.len() >= 8,
        "only {} Markdown files with console blocks under {}",
        files.len(),
        root.join("docs/src").display()
    );
    let work = tempfile::Builder::new()
        .prefix("sealsim-guide.")
        .tempdir()
        .unwrap();
    let cases = work.path().join("cases");
    fs::create_dir_all(&cases).unwrap();
    // The sandbox template: links to the repository's top-level entries, minus the build
    // output and the version control data.
    let template: Vec<PathBuf> = fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy();
            name != "target" && !name.starts_with('.')
        })
        .collect();
    let mut copies = Vec::new();
    for file in &files {
        let rel = file.strip_prefix(&root).unwrap();
        let name = rel.to_string_lossy().replace(['/', '\\'], "__");
        let copy = cases.join(&name);
        copies.push((copy.clone(), file.clone()));
        fs::copy(file, &copy).unwrap();
        let stem = copy.with_extension("");
        let input = stem.with_extension("in");
        fs::create_dir_all(&input).unwrap();
        for entry in &template {
            std::os::unix::fs::symlink(entry, input.join(entry.file_name().unwrap())).unwrap();
        }
        // An empty expected-output directory: trycmd then runs in a temporary copy of the
        // template and checks no file.
        fs::create_dir_all(stem.with_extension("out")).unwrap();
    }
    trycmd::TestCases::new()
        .register_bin("sealsim", PathBuf::from(env!("CARGO_BIN_EXE_sealsim")))
        .env("NO_COLOR", "1")
        .env("RAYON_NUM_THREADS", "2")
        .timeout(std::time::Duration::from_secs(120))
        .case(cases.join("*.md"))
        .run();
    // TRYCMD=overwrite rewrote the copies: bring the new outputs back to the sources.
    if std::env::var_os("TRYCMD").is_some_and(|m| m == "overwrite") {
        for (copy, source) in &copies {
            let new = fs::read_to_string(copy).unwrap();
            if new != fs::read_to_string(source).unwrap() {
                fs::write(source, new).unwrap();
                eprintln!("guide: updated {}", source.display());
            }
        }
    }
}

/// The shipped fitted material of the lab-data tutorial is what the tutorial's `fit-prony`
/// command writes today (the guide test runs the command; this compares its file).
#[test]
fn shipped_lab_material_is_the_fit() {
    let root = repo();
    let work = tempfile::tempdir().unwrap();
    let out = work.path().join("nbr-lab.toml");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_sealsim"))
        .current_dir(&root)
        .args([
            "fit-prony",
            "scenarios/lab-data/csr-nbr-70c.csv",
            "--kind",
            "relaxation",
            "--test-piece",
            "ring",
            "--cross-section",
            "3.53mm",
            "--mean-diameter",
            "28.52mm",
            "--squeeze",
            "25%",
            "--temperature",
            "70C",
            "--like",
            "nbr-70",
            "--name",
            "nbr-lab",
            "-o",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(status.status.success(), "{status:?}");
    let fitted = fs::read_to_string(&out).unwrap();
    let shipped = fs::read_to_string(root.join("scenarios/lab-data/nbr-lab.toml")).unwrap();
    assert!(
        fitted == shipped,
        "scenarios/lab-data/nbr-lab.toml is not what the tutorial's fit-prony writes; \
         re-make it with the command in docs/src/tutorials/lab-data.md"
    );
}
