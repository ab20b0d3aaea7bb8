//! `sealsim sizes`: AS568 O-ring sizes as text and JSON — inch as transcribed, mm as inch × 25.4
//! exactly, with the table's provenance ([`crate::scenario::as568`]).

use super::ReportError;
use crate::scenario::as568::{FILE, SOURCE, Size};

/// mm of `inch` (× 25.4 exactly), printed to 0.1 µm with trailing zeros dropped.
fn mm(inch: f64) -> String {
    let text = format!("{:.4}", inch * 25.4);
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// The provenance line of one size: the table file, its line, the source.
pub fn source_line(size: &Size) -> String {
    format!("{FILE} line {}: {SOURCE}", size.line)
}

/// One size, readable: ID, cross-section and OD in inch and mm with tolerances, and the source.
pub fn describe(size: &Size) -> String {
    let od = size.id_in + 2.0 * size.cs_in;
    format!(
        "size              {} (series {})\n\
         inside diameter   {:.3} ± {:.3} in   ({} ± {} mm)\n\
         cross-section     {:.3} ± {:.3} in   ({} ± {} mm)\n\
         outside diameter  {:.3} in   ({} mm), nominal ID + 2 × cross-section\n\
         source            {}\n",
        size.name(),
        size.series() * 100,
        size.id_in,
        size.id_tol_in,
        mm(size.id_in),
        mm(size.id_tol_in),
        size.cs_in,
        size.cs_tol_in,
        mm(size.cs_in),
        mm(size.cs_tol_in),
        od,
        mm(od),
        source_line(size)
    )
}

/// Every size as a table, one row each (inch and mm, tolerances ±), the source last.
pub fn table(sizes: &[Size]) -> String {
    let mut out = format!(
        "{:<10} {:>8} {:>7} {:>6} {:>6} {:>9} {:>7} {:>7} {:>7}\n",
        "size", "ID in", "± in", "CS in", "± in", "ID mm", "± mm", "CS mm", "± mm"
    );
    for s in sizes {
        out += &format!(
            "{:<10} {:>8.3} {:>7.3} {:>6.3} {:>6.3} {:>9} {:>7} {:>7} {:>7}\n",
            s.name(),
            s.id_in,
            s.id_tol_in,
            s.cs_in,
            s.cs_tol_in,
            mm(s.id_in),
            mm(s.id_tol_in),
            mm(s.cs_in),
            mm(s.cs_tol_in)
        );
    }
    out += &format!("source: {FILE}, {SOURCE}\n");
    out
}

fn record(size: &Size) -> serde_json::Value {
    serde_json::json!({
        "size": size.name(),
        "dash": size.dash,
        "series": size.series() * 100,
        "inner_diameter_in": size.id_in,
        "inner_diameter_tolerance_in": size.id_tol_in,
        "cross_section_in": size.cs_in,
        "cross_section_tolerance_in": size.cs_tol_in,
        "inner_diameter_mm": size.id_in * 25.4,
        "inner_diameter_tolerance_mm": size.id_tol_in * 25.4,
        "cross_section_mm": size.cs_in * 25.4,
        "cross_section_tolerance_mm": size.cs_tol_in * 25.4,
        "source": source_line(size),
    })
}

/// One size as a JSON object (`size`, `dash`, `series`, `inner_diameter_in`, …`_mm`,
/// `source`).
pub fn size_json(size: &Size) -> Result<String, ReportError> {
    serde_json::to_string_pretty(&record(size))
        .map(|s| s + "\n")
        .map_err(|e| ReportError::Csv(e.to_string()))
}

/// Every size as a JSON array of the objects of [`size_json`].
pub fn table_json(sizes: &[Size]) -> Result<String, ReportError> {
    let all: Vec<serde_json::Value> = sizes.iter().map(record).collect();
    serde_json::to_string_pretty(&all)
        .map(|s| s + "\n")
        .map_err(|e| ReportError::Csv(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn millimetres_are_exact_and_trimmed() {
        assert_eq!(mm(0.984), "24.9936");
        assert_eq!(mm(0.010), "0.254");
        assert_eq!(mm(0.139), "3.5306");
        assert_eq!(mm(1.0), "25.4");
    }
}
