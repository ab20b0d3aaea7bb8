//! `sealsim generate man|completions`: generated from the commands' own definition, so every
//! command has its page and its completion, and the scripts are valid for their shell.

use crate::support::sealsim;
use std::fs;

/// The commands `sealsim --help` lists (the source the generated files must cover).
fn commands() -> Vec<String> {
    let help = String::from_utf8(sealsim().arg("--help").output().unwrap().stdout).unwrap();
    help.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .map(|l| l.split_whitespace().next().unwrap().to_owned())
        .filter(|c| c != "help")
        .collect()
}

#[test]
fn every_command_has_a_man_page() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("man1");
    sealsim()
        .args(["generate", "man", "--out-dir"])
        .arg(&out)
        .assert()
        .success();
    let commands = commands();
    assert!(commands.len() >= 13, "{commands:?}");
    for page in
        std::iter::once("sealsim".to_owned()).chain(commands.iter().map(|c| format!("sealsim-{c}")))
    {
        let text = fs::read_to_string(out.join(format!("{page}.1")))
            .unwrap_or_else(|e| panic!("{page}.1: {e}"));
        assert!(
            text.contains(&format!(".TH {page} 1")),
            "{page}: no title line"
        );
        assert!(
            text.contains(".SH NAME") && text.contains(".SH SYNOPSIS"),
            "{page}"
        );
    }
    // subcommands of subcommands too
    for page in ["sealsim-study-merge", "sealsim-materials-show"] {
        assert!(out.join(format!("{page}.1")).is_file(), "{page}.1 missing");
    }
}

#[test]
fn completion_scripts_cover_every_command_and_are_valid_bash() {
    let commands = commands();
    let bash = sealsim()
        .args(["generate", "completions", "bash"])
        .output()
        .unwrap();
    assert!(bash.status.success());
    let script = String::from_utf8(bash.stdout).unwrap();
    for c in &commands {
        assert!(script.contains(c.as_str()), "bash completion lacks {c}");
    }
    // bash -n: the script parses
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("sealsim.bash");
    sealsim()
        .args(["generate", "completions", "bash", "-o"])
        .arg(&file)
        .assert()
        .success();
    assert_eq!(
        fs::read_to_string(&file).unwrap(),
        script,
        "-o and stdout differ"
    );
    let check = std::process::Command::new("bash")
        .arg("-n")
        .arg(&file)
        .status()
        .unwrap();
    assert!(check.success(), "bash -n rejects the completion script");
    for (shell, marker) in [
        ("zsh", "#compdef sealsim"),
        ("fish", "complete -c sealsim"),
        ("elvish", "sealsim"),
        ("powershell", "sealsim"),
    ] {
        let out = sealsim()
            .args(["generate", "completions", shell])
            .output()
            .unwrap();
        assert!(out.status.success(), "{shell}");
        assert!(
            String::from_utf8_lossy(&out.stdout).contains(marker),
            "{shell}"
        );
    }
    sealsim()
        .args(["generate", "completions", "tcsh"])
        .assert()
        .code(2);
}

/// No help text prints a stray backslash: rustdoc's `\[` escapes in argument doc comments
/// used to reach `--help` (and the man pages) verbatim.
#[test]
fn no_help_text_prints_a_backslash() {
    let mut invocations: Vec<Vec<String>> = commands().into_iter().map(|c| vec![c]).collect();
    for (command, sub) in [
        ("materials", "list"),
        ("materials", "show"),
        ("materials", "curve"),
        ("materials", "export"),
        ("materials", "check"),
        ("study", "merge"),
        ("study", "slurm"),
        ("generate", "man"),
        ("generate", "completions"),
    ] {
        invocations.push(vec![command.to_owned(), sub.to_owned()]);
    }
    for args in invocations {
        let out = sealsim().args(&args).arg("--help").output().unwrap();
        assert!(out.status.success(), "{args:?}");
        let help = String::from_utf8(out.stdout).unwrap();
        assert!(
            !help.contains('\\'),
            "{args:?} --help prints a backslash:\n{help}"
        );
    }
}
