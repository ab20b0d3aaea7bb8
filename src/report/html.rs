//! Self-contained HTML reports (`--report FILE.html`, docs/model.md §15.5): one page with inline
//! CSS and inline SVG — no scripts, no fonts or images from anywhere — that an engineer can
//! read, keep and send. The pieces here are plain text builders; what goes on a page is the
//! command's.

/// `text` with `&`, `<`, `>` and `"` escaped.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

const STYLE: &str = "
body { font-family: system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif; margin: 2em auto;
       max-width: 1000px; color: #1a1a1a; line-height: 1.45; padding: 0 1em; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; }
h2 { font-size: 1.2em; border-bottom: 1px solid #ccc; padding-bottom: 0.2em; margin-top: 1.8em; }
.meta { color: #555; font-size: 0.9em; }
.verdict { font-size: 1.15em; padding: 0.7em 1em; border-radius: 6px; margin: 1em 0; }
.verdict.fails { background: #fbe3d6; border-left: 6px solid #d55e00; }
.verdict.survives { background: #dcefe8; border-left: 6px solid #009e73; }
.verdict.info { background: #e6f0f8; border-left: 6px solid #0072b2; }
.verdict.undecided { background: #fdf3d0; border-left: 6px solid #e69f00; }
.illustrative { background: #fff3cd; border: 1px solid #e6a700; padding: 0.5em 1em; border-radius: 4px; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left; vertical-align: top; }
th { background: #f2f2f2; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
pre { background: #f7f7f7; border: 1px solid #ddd; padding: 0.7em; overflow-x: auto; font-size: 0.85em; }
figure.plot { margin: 1em 0; }
figure.plot svg { max-width: 100%; height: auto; border: 1px solid #eee; }
figcaption { color: #444; font-size: 0.9em; margin-top: 0.3em; }
ul.warnings li { margin-bottom: 0.3em; }
table.record { width: 100%; table-layout: fixed; }
table.record th { width: 28%; }
table.record td.hash { font-family: ui-monospace, 'DejaVu Sans Mono', monospace; font-size: 0.85em;
       word-break: break-all; }
@media print {
  @page { size: A4; margin: 14mm 12mm; }
  body { max-width: none; margin: 0; padding: 0; font-size: 9.5pt; }
  h2 { break-after: avoid; }
  h2:has(+ figure.plot) { break-before: page; }
  figure.plot { break-inside: avoid; }
  figure.plot svg { width: 100%; max-height: 240mm; border: none; }
  pre { white-space: pre-wrap; word-break: break-all; overflow: visible; }
  tr, .verdict { break-inside: avoid; }
  a { color: inherit; text-decoration: none; }
}
";

/// A whole page: `title` and the body's HTML.
pub fn document(title: &str, body: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta name=\"generator\" content=\"sealsim {}\">\n<title>{}</title>\n<style>{STYLE}</style>\n\
         </head>\n<body>\n{body}\n<p class=\"meta\">Written by sealsim {} — a self-contained page: \
         no scripts, fonts or images from elsewhere.</p>\n</body>\n</html>\n",
        env!("CARGO_PKG_VERSION"),
        escape(title),
        env!("CARGO_PKG_VERSION"),
    )
}

/// The sealsim commit the binary was built from (build.rs: `git rev-parse HEAD`, or
/// `SEALSIM_COMMIT`), or "unknown" (built outside a git checkout).
pub fn commit() -> &'static str {
    option_env!("SEALSIM_GIT_COMMIT").unwrap_or("unknown")
}

/// The time a report is written, as UTC ISO 8601 (`2026-11-29T10:29:09Z`): `SOURCE_DATE_EPOCH`
/// (seconds since 1970, the reproducible-builds convention) when set to an integer, else the
/// clock.
pub fn report_date() -> String {
    let seconds = std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .and_then(|s| s.trim().parse::<i64>().ok())
        .unwrap_or_else(|| {
            std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
        });
    iso_8601(seconds)
}

/// `seconds` since 1970-01-01T00:00:00Z as `YYYY-MM-DDThh:mm:ssZ` (proleptic Gregorian; the
/// days-to-civil algorithm of H. Hinnant, "chrono-Compatible Low-Level Date Algorithms").
pub fn iso_8601(seconds: i64) -> String {
    let (days, second) = (seconds.div_euclid(86_400), seconds.rem_euclid(86_400));
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097; // [0, 146096]
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365; // [0, 399]
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100); // [0, 365]
    let mp = (5 * doy + 2) / 153; // [0, 11], March first
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z",
        second / 3600,
        second % 3600 / 60,
        second % 60
    )
}

/// The SHA-256 of `bytes` as 64 lower-case hex digits (FIPS 180-4).
pub fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The "Record" of a report, for filing it: when it was written (UTC), by which sealsim
/// (version and commit) and from which input files, each with its SHA-256 (read now; a file
/// that cannot be read says why).
pub fn record(command: &str, inputs: &[&std::path::Path]) -> String {
    let mut out = String::from("<table class=\"record\">\n");
    let row = |name: &str, value: &str, class: &str| {
        format!(
            "<tr><th>{}</th><td{class}>{}</td></tr>\n",
            escape(name),
            escape(value)
        )
    };
    out += &row("written (UTC)", &report_date(), "");
    out += &row(
        "by",
        &format!(
            "sealsim {} (commit {}), {command}",
            env!("CARGO_PKG_VERSION"),
            commit()
        ),
        "",
    );
    for path in inputs {
        let hash = match std::fs::read(path) {
            Ok(bytes) => format!("SHA-256 {}", sha256_hex(&bytes)),
            Err(e) => format!("not readable now: {e}"),
        };
        out += &row(
            &format!("input {}", path.display()),
            &hash,
            " class=\"hash\"",
        );
    }
    heading("Record") + &out + "</table>\n"
}

/// A section heading.
pub fn heading(text: &str) -> String {
    format!("<h2>{}</h2>\n", escape(text))
}

/// A paragraph of plain text.
pub fn paragraph(text: &str) -> String {
    format!("<p>{}</p>\n", escape(text))
}

/// The verdict box: `kind` is `fails`, `survives`, `undecided` or `info`.
pub fn verdict(kind: &str, text: &str) -> String {
    format!("<div class=\"verdict {kind}\">{}</div>\n", escape(text))
}

/// Preformatted text (a terminal table, a scenario file).
pub fn pre(text: &str) -> String {
    format!("<pre>{}</pre>\n", escape(text))
}

/// A table; cells that read as numbers are right-aligned.
pub fn table(headers: &[String], rows: &[Vec<String>]) -> String {
    let mut out = String::from("<table>\n<tr>");
    for h in headers {
        out += &format!("<th>{}</th>", escape(h));
    }
    out += "</tr>\n";
    for row in rows {
        out += "<tr>";
        for cell in row {
            let numeric = cell.trim().parse::<f64>().is_ok();
            out += &format!(
                "<td{}>{}</td>",
                if numeric { " class=\"num\"" } else { "" },
                escape(cell)
            );
        }
        out += "</tr>\n";
    }
    out + "</table>\n"
}

/// A chart: the SVG document inline (its XML declaration dropped), with a caption.
pub fn figure(svg: &str, caption: &str) -> String {
    let svg = svg
        .trim_start()
        .strip_prefix("<?xml")
        .and_then(|rest| rest.split_once("?>").map(|(_, s)| s))
        .unwrap_or(svg);
    format!(
        "<figure class=\"plot\">\n{}\n<figcaption>{}</figcaption>\n</figure>\n",
        svg.trim(),
        escape(caption)
    )
}

/// A list of warnings (each already says when and how far), or "none".
pub fn warnings(lines: &[String]) -> String {
    if lines.is_empty() {
        return "<p>None: every validity check passed.</p>\n".to_owned();
    }
    let mut out = String::from("<ul class=\"warnings\">\n");
    for l in lines {
        out += &format!("<li>{}</li>\n", escape(l.trim_start_matches("warning: ")));
    }
    out + "</ul>\n"
}

/// The lines of a "Validity warnings" section: a scenario's input warnings (each
/// `FILE:LINE: …`), then its run's findings, each line led by `context` (a compound's id) when
/// given.
pub fn validity_lines(
    context: Option<&str>,
    scenario_warnings: &[crate::scenario::InputWarning],
    findings: &crate::validity::Findings,
) -> Vec<String> {
    let mut lines: Vec<String> = scenario_warnings
        .iter()
        .map(|w| crate::report::findings::input_line(context, w))
        .collect();
    lines.extend(
        crate::report::findings::warning_lines(context, findings)
            .lines()
            .map(str::to_owned),
    );
    lines
}

/// The "Validity warnings" section of `lines` ([`validity_lines`]).
pub fn validity(lines: &[String]) -> String {
    lines_section("Validity warnings", lines)
}

/// A heading and a list of warnings under it.
pub fn lines_section(title: &str, lines: &[String]) -> String {
    heading(title) + &warnings(lines)
}

/// The "Fidelity" section: the level, what it computes and its measured error.
pub fn fidelity(level: crate::leak::Fidelity) -> String {
    heading("Fidelity")
        + &paragraph(&format!(
            "Level {}: {}. Measured error: {}.",
            level.name(),
            level.description(),
            level.measured_error()
        ))
}

/// A file's text under `title` (a scenario: its inputs with their units and provenance).
pub fn file(title: &str, text: &str) -> String {
    heading(title) + &pre(text)
}

/// The title of a scenario file's section.
pub const SCENARIO_TITLE: &str = "Scenario (inputs with units and provenance)";

/// The `label  text` lines of a terminal summary as a two-column table.
pub fn summary_table(text: &str) -> String {
    let rows: Vec<Vec<String>> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let label: String = l.chars().take(15).collect();
            let rest: String = l.chars().skip(15).collect();
            vec![label.trim().to_owned(), rest.trim().to_owned()]
        })
        .collect();
    let mut out = String::from("<table>\n");
    for r in rows {
        out += &format!(
            "<tr><th>{}</th><td>{}</td></tr>\n",
            escape(&r[0]),
            escape(&r[1])
        );
    }
    out + "</table>\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_markup_and_inlines_svg_without_its_declaration() {
        assert_eq!(
            escape("a < b & \"c\" > d"),
            "a &lt; b &amp; &quot;c&quot; &gt; d"
        );
        let f = figure("<?xml version=\"1.0\"?>\n<svg width=\"10\"></svg>", "x <y>");
        assert!(f.starts_with("<figure class=\"plot\">\n<svg"));
        assert!(f.contains("<figcaption>x &lt;y&gt;</figcaption>"));
        let page = document("t", &f);
        assert!(!page.contains("<script"));
        assert!(!page.contains("http://") && !page.contains("https://"));
    }

    /// Dates against the calendar: the epoch, a leap day, the turn of 2000 (a leap year by the
    /// 400 rule), the day before the epoch and 2100-03-01 (2100 is not leap).
    #[test]
    fn dates_are_utc_iso_8601() {
        assert_eq!(iso_8601(0), "1970-01-01T00:00:00Z");
        assert_eq!(iso_8601(951_782_400), "2000-02-29T00:00:00Z");
        assert_eq!(iso_8601(946_684_799), "1999-12-31T23:59:59Z");
        assert_eq!(iso_8601(-1), "1969-12-31T23:59:59Z");
        // 2100 is not leap: 28 February is followed by 1 March
        assert_eq!(iso_8601(4_107_456_000), "2100-02-28T00:00:00Z");
        assert_eq!(iso_8601(4_107_542_400), "2100-03-01T00:00:00Z");
        assert_eq!(iso_8601(1_795_944_549), "2026-11-29T09:29:09Z");
    }

    /// The FIPS 180-2 example digests of "" and "abc".
    #[test]
    fn sha256_matches_the_standard_examples() {
        assert_eq!(
            sha256_hex(b""),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"
        );
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }
}
