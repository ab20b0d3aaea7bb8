//! End-to-end: `[fluid] volume_swell` (docs/model.md §3.8) — zero swell changes nothing, a
//! swell that overfills the gland is reported, bad input exits 2 naming file, line and key.

use crate::support::run_text;

// The piston-gland scenario of the gland tests: `[fluid]` at line 9, its last key at line 11.
use super::gland::PISTON;

/// `sealsim run` on `text` with `swell` added to `[fluid]`: (status, stdout, stderr, the
/// history CSV if written).
fn run(swell: Option<&str>) -> (Option<i32>, String, String, Option<String>) {
    let text = match swell {
        Some(s) => PISTON.replace(
            "pressure_difference = \"2 bar\"",
            &format!("pressure_difference = \"2 bar\"\nvolume_swell = {s}"),
        ),
        None => PISTON.to_owned(),
    };
    let (code, stdout, stderr, csv, _) = run_text(&text);
    (code, stdout, stderr, csv)
}

#[test]
fn zero_swell_changes_nothing_bit_for_bit() {
    let (code, stdout, stderr, csv) = run(None);
    assert_eq!(code, Some(0), "{stderr}");
    for zero in ["0", "\"0 %\""] {
        let (c, s, e, h) = run(Some(zero));
        assert_eq!(c, Some(0), "{e}");
        assert_eq!(s, stdout);
        assert_eq!(e, stderr);
        assert_eq!(h, csv, "the history must be bit-identical");
    }
}

#[test]
fn a_swell_raises_the_squeeze_and_softens_the_ring() {
    let (_, dry, _, _) = run(None);
    let (code, swollen, stderr, _) = run(Some("\"8 %\""));
    assert_eq!(code, Some(0), "{stderr}");
    // dry: ε = 17.9 % (tests/cli/gland.rs); swollen by 8 %, the seated cord is larger
    assert!(dry.contains("squeeze 17.9 %"), "{dry}");
    assert!(!swollen.contains("squeeze 17.9 %"), "{swollen}");
    // the leak changes (a bigger squeeze, a softer network)
    let leak = |s: &str| {
        s.lines()
            .find(|l| l.starts_with("leak rate"))
            .unwrap()
            .to_owned()
    };
    assert_ne!(leak(&dry), leak(&swollen));
}

#[test]
fn a_swell_that_overfills_the_gland_is_reported() {
    // the dry ring fills the groove below the 90 % guidance; swollen by 40 % it does not fit
    let (_, _, dry, _) = run(None);
    assert!(!dry.contains("gland fill"), "{dry}");
    let (code, stdout, stderr, csv) = run(Some("\"40 %\""));
    assert_eq!(code, Some(2), "{stdout}{stderr}");
    assert!(csv.is_none(), "nothing is written");
    assert!(
        stderr.contains("s.toml:1") && stderr.contains("seal.groove_width"),
        "{stderr}"
    );
    assert!(
        stderr.contains("does not fit") && stderr.contains("volume_swell of 40 %"),
        "{stderr}"
    );
    // 20 %: it fits, above the 90 % guidance, warned with the swell named
    let (code, _, stderr, _) = run(Some("0.2"));
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stderr.contains("gland fill") && stderr.contains("volume_swell of 20 %"),
        "{stderr}"
    );
    // and beyond ≈ 30 % it is out of seal practice
    assert!(!stderr.contains("beyond seal practice"), "{stderr}");
}

#[test]
fn bad_swell_exits_2_with_file_line_and_key() {
    for bad in ["\"-80 %\"", "\"500 %\"", "\"8 mm\"", "\"lots\""] {
        let (code, stdout, stderr, csv) = run(Some(bad));
        assert_eq!(code, Some(2), "{bad}: {stdout}{stderr}");
        assert!(csv.is_none(), "{bad}: nothing is written");
        assert!(
            stderr.contains("s.toml:12") && stderr.contains("fluid.volume_swell"),
            "{bad}: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{bad}: {stderr}");
    }
}
