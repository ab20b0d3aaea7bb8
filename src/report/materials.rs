//! Outputs of `sealsim materials`: the library table, a compound's full description with
//! provenance, its response curve as CSV, and its Prony series as Abaqus or ANSYS input.
//!
//! Units are printed only here; the model hands over SI values (Pa, s, K).

use super::ReportError;
use super::csv::{csv_error, finish};
use crate::material::curve::Curve;
use crate::material::{Material, Shift, Status};
use crate::units::human;

/// Columns of the curve CSV, in order: one row per grid point, the dynamic moduli at the
/// angular frequency ω = 1/t of the same row.
pub const CURVE_COLUMNS: [&str; 8] = [
    "time_s",
    "reduced_time_s",
    "relaxation_modulus_Pa",
    "creep_compliance_per_Pa",
    "angular_frequency_rad_per_s",
    "storage_modulus_Pa",
    "loss_modulus_Pa",
    "tan_delta",
];

/// 0 °C in kelvin.
const ZERO_CELSIUS: f64 = 273.15;

/// The curve as CSV (header plus one row per point), numbers in shortest round-trip
/// scientific notation.
pub fn curve_table(curve: &Curve) -> Result<String, ReportError> {
    let mut writer = ::csv::Writer::from_writer(Vec::new());
    writer.write_record(CURVE_COLUMNS).map_err(csv_error)?;
    for (index, p) in curve.points.iter().enumerate() {
        let values = p.values();
        let mut record = Vec::with_capacity(values.len());
        for (column, value) in CURVE_COLUMNS.into_iter().zip(values) {
            if !value.is_finite() {
                return Err(ReportError::NonFinite {
                    row: index + 1,
                    column,
                    value,
                });
            }
            record.push(format!("{value:e}"));
        }
        writer.write_record(&record).map_err(csv_error)?;
    }
    finish(writer)
}

/// `"23 °C (296.15 K)"`.
fn temperature(kelvin: f64) -> String {
    format!(
        "{} °C ({} K)",
        human(kelvin - ZERO_CELSIUS, 6),
        human(kelvin, 6)
    )
}

/// What a status means, for `show`.
fn status_meaning(status: Status) -> &'static str {
    match status {
        Status::Published => "every number traced to a publication",
        Status::Illustrative => {
            "at least one number is estimated (see the sources); not for design decisions"
        }
        Status::User => "given by the user; no claim is made",
    }
}

/// The library table of `sealsim materials list`: id, name, status, E0 and E∞ \[MPa\], T_g and
/// the low-temperature limit T10 ([`Material::low_temperature_limit`]) \[°C\].
pub fn library_table(rows: &[(&str, &Material)]) -> String {
    let header = [
        "id",
        "name",
        "status",
        "E0 [MPa]",
        "E∞ [MPa]",
        "T_g [°C]",
        "T10 [°C]",
    ];
    let cells: Vec<[String; 7]> = rows
        .iter()
        .map(|(id, m)| {
            [
                (*id).to_owned(),
                m.name.clone(),
                m.status.as_str().to_owned(),
                human(m.prony.instantaneous() / 1e6, 4),
                human(m.prony.long_term() / 1e6, 4),
                m.glass_transition
                    .map_or_else(|| "-".to_owned(), |t| human(t - ZERO_CELSIUS, 4)),
                m.low_temperature_limit()
                    .map_or_else(|| "-".to_owned(), |t| human(t - ZERO_CELSIUS, 4)),
            ]
        })
        .collect();
    let width = |i: usize| {
        cells
            .iter()
            .map(|r| r[i].chars().count())
            .chain([header[i].chars().count()])
            .max()
            .unwrap_or(0)
    };
    let widths: Vec<usize> = (0..header.len()).map(width).collect();
    let line = |row: [&str; 7]| {
        let mut out = String::new();
        for (i, cell) in row.iter().enumerate() {
            let pad = widths[i].saturating_sub(cell.chars().count());
            // text columns left-aligned, numbers right-aligned
            if i < 3 {
                out.push_str(cell);
                if i + 1 < row.len() {
                    out.push_str(&" ".repeat(pad + 2));
                }
            } else {
                out.push_str(&" ".repeat(pad));
                out.push_str(cell);
                if i + 1 < row.len() {
                    out.push_str("  ");
                }
            }
        }
        out.push('\n');
        out
    };
    let mut out = line(header);
    for r in &cells {
        out.push_str(&line([&r[0], &r[1], &r[2], &r[3], &r[4], &r[5], &r[6]]));
    }
    out
}

/// Every parameter of `m` with its units and provenance (`sealsim materials show`).
pub fn describe(id: &str, m: &Material) -> String {
    let mut card = Card {
        m,
        out: format!("{id}: {}\n", m.name),
    };
    card.out += &format!(
        "status: {} - {}\n\n",
        m.status.as_str(),
        status_meaning(m.status)
    );
    card.param("poisson_ratio", format!("ν = {}", m.poisson_ratio), &[]);
    card.modulus();
    card.shift();
    card.thermal();
    card.ageing();
    card.derived();
    card.compatibility();
    card.out
}

/// The indent of a parameter's further lines.
const INDENT: &str = "                    ";

/// A compound's card being written (`sealsim materials show`): one parameter at a time.
struct Card<'m> {
    m: &'m Material,
    out: String,
}

impl Card<'_> {
    /// `key` and its `value`, the `extra` lines, then the key's source.
    fn param(&mut self, key: &str, value: String, extra: &[String]) {
        self.out += &format!("{key:<19} {value}\n");
        for line in extra {
            self.out += &format!("{INDENT}{line}\n");
        }
        let source = self.m.provenance_of(key).unwrap_or("(none given)");
        self.out += &format!("{INDENT}source: {source}\n");
    }

    /// The elastic modulus, or the relaxed modulus and the Prony series term by term.
    fn modulus(&mut self) {
        let m = self.m;
        let prony = &m.prony;
        let terms = prony.terms();
        if terms.is_empty() {
            self.param(
                "youngs_modulus",
                format!("E = {} MPa (elastic)", human(prony.long_term() / 1e6, 6)),
                &[],
            );
            return;
        }
        self.param(
            "long_term_modulus",
            format!(
                "E∞ = {} MPa (relaxed; the static leak problem uses it)",
                human(prony.long_term() / 1e6, 6)
            ),
            &[],
        );
        let e0 = prony.instantaneous();
        let at = match m.shift {
            Shift::None => "no temperature dependence".to_owned(),
            Shift::Wlf { reference, .. } | Shift::Arrhenius { reference, .. } => {
                format!("at T_ref = {}", temperature(reference))
            }
        };
        let (lo, hi) = (terms[0].tau, terms[terms.len() - 1].tau);
        let mut lines = vec![
            format!(
                "E0 = E∞ + Σ E_i = {} MPa (instantaneous)",
                human(e0 / 1e6, 6)
            ),
            format!(
                "{:>4}  {:>12}  {:>12}  {:>10}",
                "i", "tau [s]", "E_i [MPa]", "E_i/E0"
            ),
        ];
        lines.extend(terms.iter().enumerate().map(|(i, t)| {
            format!(
                "{:>4}  {:>12}  {:>12}  {:>10}",
                i + 1,
                human(t.tau, 6),
                human(t.modulus / 1e6, 6),
                human(t.modulus / e0, 4)
            )
        }));
        self.param(
            "prony",
            format!(
                "{} terms, E(t) = E∞ + Σ E_i exp(−t/τ_i), τ from {} s to {} s ({} decades), {at}",
                terms.len(),
                human(lo, 4),
                human(hi, 4),
                human((hi / lo).log10(), 3)
            ),
            &lines,
        );
    }

    /// The temperature shift of the relaxation.
    fn shift(&mut self) {
        match self.m.shift {
            Shift::None => {}
            Shift::Wlf { reference, c1, c2 } => self.param(
                "shift",
                format!(
                    "WLF, log10 a_T = −C1 (T − T_ref)/(C2 + T − T_ref): T_ref = {}, C1 = {}, C2 = {} K",
                    temperature(reference),
                    human(c1, 6),
                    human(c2, 6)
                ),
                &[format!(
                    "frozen (no relaxation) at and below T_ref − C2 = {}",
                    temperature(reference - c2)
                )],
            ),
            Shift::Arrhenius {
                reference,
                activation_energy,
            } => self.param(
                "shift",
                format!(
                    "Arrhenius, ln a_T = (Ea/R)(1/T − 1/T_ref): T_ref = {}, Ea = {} kJ/mol",
                    temperature(reference),
                    human(activation_energy / 1e3, 6)
                ),
                &[],
            ),
        }
    }

    /// The glass transition and the thermal expansions.
    fn thermal(&mut self) {
        let m = self.m;
        if let Some(tg) = m.glass_transition {
            self.param(
                "glass_transition",
                format!("T_g = {}", temperature(tg)),
                &[],
            );
        }
        if let Some(alpha) = m.thermal_expansion {
            self.param(
                "thermal_expansion",
                format!("α = {} 1/K (linear)", human(alpha, 6)),
                &[],
            );
        }
        if let Some(alpha) = m.glassy_thermal_expansion {
            self.param(
                "glassy_thermal_expansion",
                format!("α_g = {} 1/K (linear, below T_g)", human(alpha, 6)),
                &[],
            );
        }
    }

    /// The two-network ageing and its basis, or why there is none.
    fn ageing(&mut self) {
        let m = self.m;
        match m.ageing {
            Some(a) => {
                let mut extra = vec![format!(
                    "two networks (docs/model.md §6.5): a new network forms at {} × k in the \
                     compressed state{}",
                    human(a.crosslinking, 4),
                    if a.crosslinking == 1.0 {
                        ": compression set = 1 − F/F0 at a constant squeeze"
                    } else {
                        ""
                    }
                )];
                if let Some(b) = &m.ageing_basis {
                    extra.push(format!("property: {}", b.property));
                    extra.push(format!("criterion: {}", b.criterion));
                    if let Some(source) = &b.source {
                        extra.push(format!("Ea source: {source}"));
                    }
                }
                let energy = if a.is_two_sided() {
                    format!(
                        "Ea = {} kJ/mol at and below it, {} kJ/mol above it (a band about the \
                         anchor: the shorter life on both sides, docs/model.md §6.5)",
                        human(a.activation_energy / 1e3, 6),
                        human(a.activation_energy_above / 1e3, 6)
                    )
                } else {
                    format!(
                        "Ea = {} kJ/mol (Arrhenius)",
                        human(a.activation_energy / 1e3, 6)
                    )
                };
                self.param(
                    "ageing",
                    format!(
                        "scission k_ref = {} 1/s at {}, {energy}",
                        human(a.rate, 6),
                        temperature(a.reference_temperature),
                    ),
                    &extra,
                );
            }
            None => {
                if let Some(why) = m.provenance_of("ageing") {
                    self.out += &format!("{:<19} none\n{INDENT}source: {why}\n", "ageing");
                }
            }
        }
    }

    /// What follows from the parameters: the low-temperature limit T10 and a library
    /// compound's helium/nitrogen permeation ratio.
    fn derived(&mut self) {
        let m = self.m;
        if let Some(t10) = m.low_temperature_limit() {
            self.out += &format!(
                "{:<19} T10 = {} (derived, not a parameter)\n",
                "low_temperature",
                temperature(t10)
            );
            self.out += &format!(
                "{INDENT}where E(10 s/a_T(T)) = 10 × E(10 s/a_T(23 °C)): the stiffening limit of a \
                 Gehman test (ASTM D1053, ISO 1432) computed from the Prony series and the shift\n"
            );
        }
        self.permeation();
    }

    /// The gas permeation figures the compound runs with (its own, else its class's), each
    /// with its source or "NOT SOURCED bound", and the He/N2 ratio (docs/model.md §13.4).
    fn permeation(&mut self) {
        let m = self.m;
        let class = m.class.as_deref();
        let gases: Vec<String> = crate::permeation::GASES
            .iter()
            .map(|g| g.replace(' ', "-"))
            .chain(
                m.permeation
                    .iter()
                    .map(|p| p.gas.clone())
                    .filter(|g| !crate::permeation::GASES.contains(&g.replace('-', " ").as_str())),
            )
            .collect();
        let rows: Vec<_> = gases
            .iter()
            .filter_map(|g| crate::permeation::figure(class, &m.permeation, g).ok())
            .collect();
        if rows.is_empty() {
            self.out += &format!(
                "{:<19} none: no `class` and no [material.permeation]; a gas run is refused \
                 until one is given (docs/model.md §13.4)\n",
                "permeation"
            );
            return;
        }
        self.out += &format!(
            "{:<19} at 23 °C{} (docs/model.md §13.4)\n",
            "permeation",
            class.map_or_else(String::new, |c| format!(", class {c}"))
        );
        for row in rows {
            let lag = match (row.diffusivity, row.diffusivity_is_bound) {
                (Some(d), true) => format!(", D ≤ {} m²/s (bound)", human(d, 3)),
                (Some(d), false) => format!(", D = {} m²/s", human(d, 3)),
                (None, _) => String::new(),
            };
            self.out += &format!(
                "{INDENT}{}: {} barrer{lag}\n{INDENT}  {}\n",
                row.gas.replace(' ', "-"),
                human(crate::permeation::si_to_barrer(row.permeability), 4),
                row.basis()
            );
        }
        if let Some((ratio, _)) = class.and_then(crate::permeation::helium_nitrogen_ratio) {
            self.out += &format!("{INDENT}He/N2 = {}\n", human(ratio, 3));
        }
    }

    /// The compound's fluid-compatibility ratings with their sources.
    fn compatibility(&mut self) {
        let m = self.m;
        self.out += &format!("{:<19} ", "compatibility");
        if m.compatibility.is_empty() {
            self.out += "not rated in any fluid class (no source read rates it)\n";
        }
        for (i, c) in m.compatibility.iter().enumerate() {
            let lead = if i == 0 {
                String::new()
            } else {
                INDENT.to_owned()
            };
            self.out += &format!(
                "{lead}{} {} ({})\n{INDENT}source: {}\n",
                c.class.key(),
                c.rating.letter(),
                c.rating.words(),
                c.source
            );
        }
    }
}

/// A number for solver input: exact (round-trip) and in a form both Abaqus and ANSYS read.
fn solver_number(v: f64) -> String {
    if v == 0.0 || (1e-3..1e7).contains(&v.abs()) {
        let text = format!("{v}");
        if text.contains('.') {
            text
        } else {
            format!("{text}.")
        }
    } else {
        format!("{v:E}")
    }
}

/// Text safe for any solver's comment lines (ASCII only).
fn ascii(text: &str) -> String {
    text.chars()
        .map(|c| match c {
            'ν' => "nu".to_owned(),
            'τ' => "tau".to_owned(),
            '∞' => "inf".to_owned(),
            'Σ' => "sum".to_owned(),
            '—' | '–' | '−' => "-".to_owned(),
            c if c.is_ascii() => c.to_string(),
            _ => "?".to_owned(),
        })
        .collect()
}

/// The comment lines common to both exports (without the comment marker). `source` names the
/// compound as the command line does (`nbr-70`, or `--file PATH`), so that the commands the
/// header quotes work as written.
fn export_header(source: &str, m: &Material, solver: &str, format: &str) -> Vec<String> {
    let prony = &m.prony;
    let e0 = prony.instantaneous();
    let sum: f64 = prony.terms().iter().map(|t| t.modulus / e0).sum();
    let mut lines = vec![
        format!(
            "sealsim materials export {} --format {format}",
            ascii(source)
        ),
        format!("material: {}", ascii(&m.name)),
        format!(
            "status: {} - provenance of every number: sealsim materials show {}",
            m.status.as_str(),
            ascii(source)
        ),
        "units: SI - moduli in Pa, times in s, temperatures in K".to_owned(),
        format!(
            "instantaneous modulus E0 = {} Pa, relaxed modulus E_inf = {} Pa, Poisson ratio {}",
            solver_number(e0),
            solver_number(prony.long_term()),
            solver_number(m.poisson_ratio)
        ),
        format!(
            "Prony coefficients are relative to the INSTANTANEOUS modulus: g_i = E_i/E0, \
             sum g_i = 1 - E_inf/E0 = {}",
            solver_number(sum)
        ),
    ];
    lines.push(match m.shift {
        Shift::None => {
            "relaxation times tau_i: the material has no time-temperature shift".to_owned()
        }
        Shift::Wlf { reference, .. } | Shift::Arrhenius { reference, .. } => format!(
            "relaxation times tau_i are at the reference temperature T_ref = {} K",
            solver_number(reference)
        ),
    });
    lines.extend([
        format!(
            "{solver} defines the Prony series for the shear modulus G; with a constant Poisson \
             ratio G(t)/G0 = E(t)/E0,"
        ),
        "so the normalised coefficients of E and G are identical.".to_owned(),
    ]);
    if m.poisson_ratio >= 0.5 {
        lines.push(
            "nu = 0.5 is exactly incompressible: most solvers need nu < 0.5 (e.g. 0.4995) with \
             hybrid/mixed elements"
                .to_owned(),
        );
    }
    lines
}

/// The comment line that explains the WLF data of both exports.
const WLF_NOTE: &str =
    "WLF shift: log10 a_T = -C1 (T - T_ref)/(C2 + T - T_ref); data: T_ref [K], C1, C2 [K]";

/// Abaqus input: `*MATERIAL`, `*ELASTIC, MODULI=INSTANTANEOUS` (E0, ν),
/// `*VISCOELASTIC, TIME=PRONY` (g_i, k_i = 0, τ_i) and, for WLF, `*TRS, DEFINITION=WLF`.
/// `id` names the material card; `source` is the compound as the command line names it.
pub fn abaqus(id: &str, source: &str, m: &Material) -> String {
    let prony = &m.prony;
    let e0 = prony.instantaneous();
    let mut out = String::new();
    for line in export_header(source, m, "Abaqus", "abaqus") {
        out += &format!("** {line}\n");
    }
    out += "** k_i = 0: no bulk relaxation (the bulk modulus is elastic)\n";
    out += &format!("*MATERIAL, NAME={}\n", abaqus_name(id));
    out += "*ELASTIC, MODULI=INSTANTANEOUS\n";
    out += &format!(
        "{}, {}\n",
        solver_number(e0),
        solver_number(m.poisson_ratio)
    );
    if !prony.terms().is_empty() {
        out += "*VISCOELASTIC, TIME=PRONY\n";
        for t in prony.terms() {
            out += &format!(
                "{}, 0., {}\n",
                solver_number(t.modulus / e0),
                solver_number(t.tau)
            );
        }
    }
    match m.shift {
        Shift::None => {}
        Shift::Wlf { reference, c1, c2 } => {
            out += &format!("** {WLF_NOTE}\n");
            out += "*TRS, DEFINITION=WLF\n";
            out += &format!(
                "{}, {}, {}\n",
                solver_number(reference),
                solver_number(c1),
                solver_number(c2)
            );
        }
        Shift::Arrhenius {
            reference,
            activation_energy,
        } => {
            for line in arrhenius_note(reference, activation_energy) {
                out += &format!("** {line}\n");
            }
        }
    }
    out
}

/// ANSYS Mechanical APDL input: `MP,EX` (E0), `MP,PRXY` (ν), `TB,PRONY,1,,N,SHEAR` with
/// `TBDATA` pairs (a_i = E_i/E0, τ_i) and, for WLF, `TB,SHIFT,1,,3` (T_ref, C1, C2).
/// `source` is the compound as the command line names it (`nbr-70`, or `--file PATH`).
pub fn ansys(source: &str, m: &Material) -> String {
    let prony = &m.prony;
    let e0 = prony.instantaneous();
    let mut out = String::new();
    for line in export_header(source, m, "ANSYS", "ansys") {
        out += &format!("! {line}\n");
    }
    out += "! shear Prony series only (no TB,PRONY,,,,BULK): no bulk relaxation\n";
    out += &format!("MP,EX,1,{}\n", solver_number(e0));
    out += &format!("MP,PRXY,1,{}\n", solver_number(m.poisson_ratio));
    let terms = prony.terms();
    if !terms.is_empty() {
        out += &format!("TB,PRONY,1,,{},SHEAR\n", terms.len());
        // TBDATA takes six constants per command: three (a_i, tau_i) pairs
        for (chunk_index, chunk) in terms.chunks(3).enumerate() {
            let values: Vec<String> = chunk
                .iter()
                .flat_map(|t| [solver_number(t.modulus / e0), solver_number(t.tau)])
                .collect();
            out += &format!("TBDATA,{},{}\n", 1 + 6 * chunk_index, values.join(","));
        }
    }
    match m.shift {
        Shift::None => {}
        Shift::Wlf { reference, c1, c2 } => {
            out += &format!("! {WLF_NOTE}\n");
            out += "TB,SHIFT,1,,3\n";
            out += &format!(
                "TBDATA,1,{},{},{}\n",
                solver_number(reference),
                solver_number(c1),
                solver_number(c2)
            );
        }
        Shift::Arrhenius {
            reference,
            activation_energy,
        } => {
            for line in arrhenius_note(reference, activation_energy) {
                out += &format!("! {line}\n");
            }
        }
    }
    out
}

/// Comment lines for an Arrhenius shift, which is written as data, not as a solver card.
fn arrhenius_note(reference: f64, activation_energy: f64) -> [String; 3] {
    [
        "Arrhenius shift: ln a_T = (Ea/R)(1/T - 1/T_ref); no shift card is written, enter it in \
         your solver's own Arrhenius form:"
            .to_owned(),
        format!(
            "T_ref = {} K, Ea = {} J/mol, Ea/R = {} K (R = {} J/(mol K))",
            solver_number(reference),
            solver_number(activation_energy),
            solver_number(activation_energy / crate::material::shift::GAS_CONSTANT),
            solver_number(crate::material::shift::GAS_CONSTANT)
        ),
        "(solvers differ in sign convention and in whether they take Ea, Ea/R or an absolute-zero offset)".to_owned(),
    ]
}

/// An Abaqus material name: letters, digits and `_`, starting with a letter.
fn abaqus_name(id: &str) -> String {
    let name: String = id
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_uppercase()
            } else {
                '_'
            }
        })
        .collect();
    if name.starts_with(|c: char| c.is_ascii_alphabetic()) {
        name
    } else {
        format!("M_{name}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solver_numbers_round_trip() {
        for v in [0.5, 3809760.0, 1e-6, 1e13, 0.146_734_2, 296.15, 0.0] {
            let text = solver_number(v);
            assert_eq!(text.parse::<f64>().unwrap(), v, "{text}");
            assert!(text.contains('.') || text.contains('E'), "{text}");
        }
        assert_eq!(abaqus_name("nbr-70"), "NBR_70");
        assert_eq!(abaqus_name("70x"), "M_70X");
    }
}
