//! Build script: the git commit the binary is built from, for the HTML report's record (issue 42:
//! a report filed with a design review names the exact program that wrote it).
//!
//! `SEALSIM_COMMIT` in the environment wins (a build from a source archive can say what it is);
//! else `git rev-parse HEAD` in the source tree; else nothing, and the report says "unknown".
//! Never fails the build: git absent or not a checkout is a normal case.

use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    if !out.status.success() {
        return None;
    }
    let text = String::from_utf8(out.stdout).ok()?;
    let text = text.trim();
    (!text.is_empty()).then(|| text.to_owned())
}

fn main() {
    println!("cargo:rerun-if-env-changed=SEALSIM_COMMIT");
    let commit = std::env::var("SEALSIM_COMMIT")
        .ok()
        .filter(|c| !c.trim().is_empty())
        .or_else(|| git(&["rev-parse", "HEAD"]));
    // rerun when HEAD moves: HEAD itself, the branch it names and the packed refs (in a worktree
    // they live in different directories, which `--git-path` resolves)
    let mut watched = vec!["HEAD".to_owned(), "packed-refs".to_owned()];
    if let Some(branch) = git(&["symbolic-ref", "-q", "HEAD"]) {
        watched.push(branch);
    }
    for name in watched {
        if let Some(path) = git(&["rev-parse", "--git-path", &name]) {
            println!("cargo:rerun-if-changed={path}");
        }
    }
    if let Some(commit) = commit {
        println!("cargo:rustc-env=SEALSIM_GIT_COMMIT={commit}");
    }
}
