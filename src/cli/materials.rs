//! `sealsim materials`: the material library — list the compounds, show one with the
//! provenance of every number, compute its response curve at a temperature, export its Prony
//! series for Abaqus or ANSYS.
//!
//! A compound is named by its library id (`nbr-70`) or, with `--file PATH`, read from a
//! material file (see [`crate::scenario::material_from_str`]: a library-format file, or a user
//! material without `status` such as the output of `sealsim fit-prony`).

use super::{CliError, write_output};
use crate::material::curve::{Curve, response_curve};
use crate::material::{Material, Shift};
use crate::report::materials::{abaqus, ansys, curve_table, describe, library_table};
use crate::report::plot::{LogLogChart, Series};
use crate::scenario::{library, load_material_file};
use crate::units::{self, human, show};
use clap::{Args, Subcommand, ValueEnum};
use std::path::PathBuf;

/// Default `--points-per-decade` of `curve`.
const DEFAULT_POINTS_PER_DECADE: u32 = 10;
/// Upper limit of `--points-per-decade`.
const MAX_POINTS_PER_DECADE: i64 = 1000;

/// Arguments of `sealsim materials`.
#[derive(Debug, Clone, Args)]
pub struct MaterialsArgs {
    #[command(subcommand)]
    pub command: MaterialsCommand,
}

/// The subcommands of `sealsim materials`.
#[derive(Debug, Clone, Subcommand)]
pub enum MaterialsCommand {
    /// Table of the library's compounds: id, name, status, E0, E∞, T_g, T10 (low-temperature limit).
    List,
    /// Every parameter of a compound with its units and where it comes from.
    Show(ShowArgs),
    /// Relaxation modulus, creep compliance and dynamic moduli on a log time grid, as CSV.
    Curve(CurveArgs),
    /// The Prony series as Abaqus or ANSYS input.
    Export(ExportArgs),
    /// Every compound's figures beside the published ones: T10 against its class's
    /// low-temperature limit (±5 K), the chemical time to 50 % retained force at the rated
    /// temperature against the 1000 h rule (500–2000 h), with sources. Exit 0 when all pass.
    /// Material files (e.g. from `materials new`) are checked against their `class`'s figures.
    Check(CheckArgs),
    /// A compound from a supplier datasheet (hardness, TR-10 or T_g, compression set at one to
    /// three points): its class's master curve moved to the TR-10 and scaled to the hardness,
    /// ageing from the sets less their viscoelastic part; written as a material file.
    New(NewArgs),
}

/// Arguments of `sealsim materials check`.
#[derive(Debug, Clone, Args)]
pub struct CheckArgs {
    /// Material files to check instead of the library (each needs `[material] class`): a
    /// datasheet compound from `materials new`, a fitted one. A special grade (a
    /// low-temperature NBR, say) may differ from its class's standard compound by design.
    #[arg(value_name = "FILE.toml")]
    pub files: Vec<PathBuf>,
}

/// Arguments of `sealsim materials new`.
#[derive(Debug, Clone, Args)]
#[command(after_help = "The datasheet file (TOML, units in strings):\n\n\
    [datasheet]\n\
    name = \"Acme N7001, NBR 70\"\n\
    source = \"Acme datasheet N7001 rev. 3\"\n\
    class = \"nbr\"            # acm, cr, epdm, ffkm, fkm, fvmq, hnbr, iir, nbr, vmq\n\
    hardness = 70            # Shore A\n\
    t10 = \"-28 C\"            # TR-10 (or glass_transition = \"-35 C\")\n\
    thermal_expansion = \"2.3e-4 1/K\"   # optional: rubbery CTE (else the class's)\n\n\
    [[datasheet.compression_set]]   # ASTM D395 B / ISO 815-1; one to three\n\
    time = \"70 h\"\n\
    temperature = \"100 C\"\n\
    set = \"18 %\"\n\n\
    Readings at two temperatures give Ea (its band from the figures' rounding); at one, Ea is the \
    low end of the class's band (the faster ageing at service temperatures below the test). \
    Heat-ageing changes (ASTM D573 / ISO 188) and density are not read: the life model takes \
    ageing from the sets. docs/model.md §5.4.")]
pub struct NewArgs {
    /// The datasheet file.
    #[arg(value_name = "DATASHEET.toml")]
    pub datasheet: PathBuf,

    /// Write the compound to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE.toml")]
    pub output: Option<PathBuf>,
}

/// Which compound: a library id, or a material file.
#[derive(Debug, Clone, Args)]
pub struct MaterialRef {
    /// Library id (see `sealsim materials list`).
    #[arg(value_name = "ID", required_unless_present = "file")]
    pub id: Option<String>,

    /// Read the compound from a material file instead (the library's format; without
    /// `status` it is a user material, e.g. the output of `sealsim fit-prony`).
    #[arg(long, value_name = "PATH", conflicts_with = "id")]
    pub file: Option<PathBuf>,
}

impl MaterialRef {
    /// The compound as the command line names it, `nbr-70` or `--file PATH` (quoted for a
    /// POSIX shell when the path needs it), for commands quoted in outputs.
    pub fn command_line(&self) -> String {
        match (&self.file, &self.id) {
            (Some(path), _) => format!("--file {}", shell_word(&path.to_string_lossy())),
            (None, Some(id)) => shell_word(id),
            (None, None) => String::new(),
        }
    }
}

/// `word` as one word of a POSIX shell command: as is when it holds only safe characters,
/// else in single quotes.
fn shell_word(word: &str) -> String {
    let safe = |c: char| c.is_ascii_alphanumeric() || "-_./:=+@%,".contains(c);
    if !word.is_empty() && word.chars().all(safe) {
        word.to_owned()
    } else {
        format!("'{}'", word.replace('\'', r"'\''"))
    }
}

/// Arguments of `sealsim materials show`.
#[derive(Debug, Clone, Args)]
pub struct ShowArgs {
    #[command(flatten)]
    pub material: MaterialRef,
}

/// Arguments of `sealsim materials curve`.
#[derive(Debug, Clone, Args)]
#[command(
    after_help = "One row per grid point (CSV): time_s, reduced_time_s = t/a_T, \
    relaxation_modulus_Pa E(ξ), creep_compliance_per_Pa J(ξ), and at ω = 1/t of the same row: \
    angular_frequency_rad_per_s, storage_modulus_Pa E′(ω a_T), loss_modulus_Pa E″(ω a_T), \
    tan_delta.\nThe grid is log-uniform in reduced time over the Prony relaxation times widened \
    by two decades on each side; at --temperature T the times are t = a_T ξ, so the curve moves \
    along the time axis by exactly a_T.\nTemperatures take units (\"80C\", \"353.15 K\", \"176F\"); \
    a bare number is kelvin."
)]
pub struct CurveArgs {
    #[command(flatten)]
    pub material: MaterialRef,

    /// Temperature of the curve (default: the shift's reference temperature).
    #[arg(long, value_name = "T", value_parser = parse_temperature, allow_hyphen_values = true)]
    pub temperature: Option<f64>,

    /// Grid points per decade of time.
    #[arg(long, value_name = "N", default_value_t = DEFAULT_POINTS_PER_DECADE,
          value_parser = clap::value_parser!(u32).range(1..=MAX_POINTS_PER_DECADE))]
    pub points_per_decade: u32,

    /// Write the CSV to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,

    /// Also write a chart of E(t), 1/J(t), E′ and E″ at ω = 1/t (SVG, PNG or PDF).
    #[arg(long, value_name = "FILE.svg|png|pdf")]
    pub plot: Option<PathBuf>,
}

/// Arguments of `sealsim materials export`.
#[derive(Debug, Clone, Args)]
pub struct ExportArgs {
    #[command(flatten)]
    pub material: MaterialRef,

    /// Input format of the finite-element solver.
    #[arg(long, value_enum)]
    pub format: ExportFormat,

    /// Write to FILE (atomically) instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
}

/// `--format` values of `export`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ExportFormat {
    /// Abaqus keywords: *ELASTIC, MODULI=INSTANTANEOUS; *VISCOELASTIC, TIME=PRONY; *TRS.
    Abaqus,
    /// ANSYS Mechanical APDL commands: MP; TB,PRONY; TB,SHIFT.
    Ansys,
}

/// An absolute temperature: `"80C"`, `"353.15 K"`, or a bare number in kelvin; above 0 K.
fn parse_temperature(text: &str) -> Result<f64, String> {
    let text = text.trim();
    let kelvin = match text.parse::<f64>() {
        Ok(v) => v,
        Err(_) => units::parse_temperature(text).map_err(|e| e.to_string())?,
    };
    if kelvin.is_finite() && kelvin > 0.0 {
        Ok(kelvin)
    } else {
        Err(format!(
            "a temperature must be above absolute zero, got {} K",
            show(kelvin)
        ))
    }
}

/// Runs `sealsim materials`.
pub fn run(args: MaterialsArgs) -> Result<(), CliError> {
    match args.command {
        MaterialsCommand::List => list(),
        MaterialsCommand::Show(args) => {
            let (id, material) = resolve(&args.material)?;
            write_output(None, describe(&id, &material).as_bytes())
        }
        MaterialsCommand::Curve(args) => curve(args),
        MaterialsCommand::Export(args) => export(args),
        MaterialsCommand::Check(args) => check(&args),
        MaterialsCommand::New(args) => new(args),
    }
}

/// `materials new`: the datasheet's compound, its summary on standard error when the compound
/// goes to a file (the summary first, then the file's text, on standard output otherwise).
fn new(args: NewArgs) -> Result<(), CliError> {
    super::guard_outputs(&[&args.datasheet], &[("--output", args.output.as_deref())])?;
    let file = crate::scenario::datasheet::DatasheetFile::load(&args.datasheet)?;
    let (material, summary) = crate::workflow::datasheet::compound(&file)
        .map_err(|e| CliError::Input(format!("{}: {e}", args.datasheet.display())))?;
    let text = crate::report::material_toml::material_toml(&material);
    match &args.output {
        Some(path) => {
            write_output(Some(path), text.as_bytes())?;
            print!("{summary}");
            Ok(())
        }
        None => write_output(None, format!("{}{text}", comment(&summary)).as_bytes()),
    }
}

/// `text` as TOML comment lines.
fn comment(text: &str) -> String {
    text.lines().map(|l| format!("# {l}\n")).collect()
}

/// The compound named on the command line, with the id used in outputs (the file stem for
/// `--file`).
fn resolve(reference: &MaterialRef) -> Result<(String, Material), CliError> {
    match (&reference.file, &reference.id) {
        (Some(path), _) => {
            let material = load_material_file(path)?;
            let id = path.file_stem().map_or_else(
                || "material".to_owned(),
                |s| s.to_string_lossy().into_owned(),
            );
            Ok((id, material))
        }
        (None, Some(id)) => {
            let entry = library::get(id).map_err(|e| CliError::Input(e.to_string()))?;
            Ok((entry.id.to_owned(), entry.load()?))
        }
        (None, None) => Err(CliError::Input(
            "name a library material (ID) or give --file PATH".into(),
        )),
    }
}

fn list() -> Result<(), CliError> {
    let mut loaded = Vec::new();
    for id in library::ids() {
        let entry = library::get(id).map_err(|e| CliError::Internal(e.to_string()))?;
        loaded.push((id, entry.load()?));
    }
    let rows: Vec<(&str, &Material)> = loaded.iter().map(|(id, m)| (*id, m)).collect();
    write_output(None, library_table(&rows).as_bytes())
}

/// The compounds `materials check` checks with the published figures of their class: the
/// library's, or the given files' (by their `[material] class`).
fn checked(
    args: &CheckArgs,
) -> Result<Vec<(String, Material, crate::scenario::library_check::Published)>, CliError> {
    use crate::scenario::library_check::published;
    let library_of = |id: &str| -> Result<(Material, _), CliError> {
        let entry = library::get(id).map_err(|e| CliError::Internal(e.to_string()))?;
        let p = published(id)
            .ok_or_else(|| CliError::Internal(format!("{id}: no published figures")))?;
        Ok((entry.load()?, p))
    };
    if args.files.is_empty() {
        return library::ids()
            .map(|id| library_of(id).map(|(m, p)| (id.to_owned(), m, p)))
            .collect();
    }
    // each class's standard compound and its published figures, read once
    let standards = library::ids()
        .map(|id| library_of(id).map(|(m, p)| (m.class, p)))
        .collect::<Result<Vec<_>, _>>()?;
    let mut out = Vec::new();
    for path in &args.files {
        let material = load_material_file(path)?;
        let Some(class) = material.class.clone() else {
            return Err(CliError::Input(format!(
                "{}: [material] has no `class`; add e.g. `class = \"nbr\"` (one of {}) so \
                 that its figures can be checked against the class's",
                path.display(),
                crate::permeation::FAMILIES.join(", ")
            )));
        };
        let standard = standards
            .iter()
            .find(|(c, _)| c.as_deref() == Some(class.as_str()));
        let Some(&(_, p)) = standard else {
            return Err(CliError::Input(format!(
                "{}: no published figures for class `{class}`",
                path.display()
            )));
        };
        out.push((path.display().to_string(), material, p));
    }
    Ok(out)
}

fn check(args: &CheckArgs) -> Result<(), CliError> {
    use crate::scenario::library_check::{Check, RULE_HOURS, T10_TOLERANCE, T50_BAND};
    let compounds = checked(args)?;
    let width = compounds
        .iter()
        .map(|(id, _, _)| id.chars().count())
        .max()
        .unwrap_or(9)
        .max(9);
    let mut out = format!(
        "{:<width$} {:>9} {:>9} {:>7} {:>4}   {:>8} {:>10} {:>4}   source\n",
        "compound", "T10 [°C]", "limit", "ΔT [K]", "", "rated", "t50 [h]", ""
    );
    let mut failed = Vec::new();
    for (id, material, p) in &compounds {
        let p = *p;
        let c = Check::new(material, p);
        let mark = |ok: bool| if ok { "ok" } else { "FAIL" };
        if !c.t10_ok() || !c.t50_ok() {
            failed.push(id.as_str());
        }
        out += &format!(
            "{id:<width$} {:>9} {:>9} {:>7} {:>4}   {:>8} {:>10} {:>4}   {}\n",
            c.t10.map_or("-".into(), |t| human(t - 273.15, 3)),
            human(p.low_limit - 273.15, 3),
            c.t10.map_or("-".into(), |t| human(
                ((t - p.low_limit) * 100.0).round() / 100.0,
                2
            )),
            mark(c.t10_ok()),
            format!("{} °C", human(p.rated - 273.15, 3)),
            c.t50_hours.map_or("-".into(), |h| human(h, 3)),
            mark(c.t50_ok()),
            p.source
        );
    }
    out += &format!(
        "\nT10: the temperature at which the modulus at 10 s is ten times its 23 °C value, against \
         the class's low-temperature service limit (a chart limit, not a TR-10), within ±{} K.\n\
         t50: chemical hours to 50 % retained force at the rated temperature, ln 2/k(T_rated), \
         against the rule \"a maximum temperature for 1,000 hours continuous service\" at \
         \"30-50% loss of physical properties\" (Problem Solving Products, 'Seal thermal \
         stability'): {}–{} h around {} h. docs/model.md §6.7; quotes in \
         docs/sources/elastomer-temperatures.md.\n",
        T10_TOLERANCE, T50_BAND.0, T50_BAND.1, RULE_HOURS
    );
    write_output(None, out.as_bytes())?;
    if failed.is_empty() {
        Ok(())
    } else {
        Err(CliError::Internal(format!(
            "materials check failed for {}",
            failed.join(", ")
        )))
    }
}

fn curve(args: CurveArgs) -> Result<(), CliError> {
    super::guard_outputs(
        &args
            .material
            .file
            .iter()
            .map(PathBuf::as_path)
            .collect::<Vec<_>>(),
        &[
            ("--output", args.output.as_deref()),
            ("--plot", args.plot.as_deref()),
        ],
    )?;
    let (id, material) = resolve(&args.material)?;
    if let (Some(t), Shift::None) = (args.temperature, material.shift) {
        eprintln!(
            "warning: {id} has no time–temperature shift; the curve is the same at {} °C",
            human(t - 273.15, 6)
        );
    }
    let curve = response_curve(&material, args.temperature, args.points_per_decade)
        .map_err(|e| CliError::Input(format!("{id}: {e}")))?;
    if let (true, Some(t)) = (curve.frozen, args.temperature) {
        let limit = material
            .shift
            .frozen_below()
            .map_or_else(String::new, |limit| {
                format!(
                    " (WLF: at or below T_ref − C2 = {} °C)",
                    human(limit - 273.15, 6)
                )
            });
        eprintln!(
            "warning: {id} is frozen at {} °C{limit}: no relaxation at any finite time; the \
             curve is the instantaneous response (E = E0, E″ = 0)",
            human(t - 273.15, 6)
        );
    }
    if curve.reference_grid && !curve.frozen {
        let state = if curve.log10_shift > 0.0 {
            "effectively frozen (the instantaneous response)"
        } else {
            "effectively fully relaxed"
        };
        eprintln!(
            "warning: {id}: the shift factor a_T = 10^{} moves the relaxation outside the times \
             a double can hold; the material is {state}, given on the reference time grid with \
             ξ = t/a_T",
            human(curve.log10_shift, 6)
        );
    }
    let csv = curve_table(&curve)?;
    let svg = match &args.plot {
        Some(_) => Some(
            chart(&id, &material, &curve)
                .to_svg()
                .map_err(|e| CliError::Internal(e.to_string()))?,
        ),
        None => None,
    };
    let svg = super::plot_file(args.plot.as_deref(), svg.as_deref())?;
    // everything is computed before the first file is written
    if let (Some(path), Some(svg)) = (&args.plot, &svg) {
        write_output(Some(path), svg)?;
    }
    write_output(args.output.as_deref(), csv.as_bytes())
}

/// The SVG chart of a curve: E(t), 1/J(t), E′ and E″ at ω = 1/t against t.
fn chart(id: &str, material: &Material, curve: &Curve) -> LogLogChart {
    let series = |label: &str, value: fn(&crate::material::curve::CurvePoint) -> f64| Series {
        label: label.to_owned(),
        points: curve.points.iter().map(|p| (p.time, value(p))).collect(),
    };
    let at = match curve.temperature {
        Some(t) => format!("{} °C", human(t - 273.15, 6)),
        None => match material.shift {
            Shift::Wlf { reference, .. } | Shift::Arrhenius { reference, .. } => {
                format!("{} °C (reference)", human(reference - 273.15, 6))
            }
            Shift::None => "any temperature".to_owned(),
        },
    };
    LogLogChart {
        title: format!("{id} at {at}"),
        x_label: "time t [s]  (E′, E″ at ω = 1/t)".to_owned(),
        y_label: "modulus [Pa]".to_owned(),
        series: vec![
            series("relaxation modulus E(t)", |p| p.relaxation),
            series("1/J(t), inverse creep compliance", |p| 1.0 / p.compliance),
            series("storage modulus E′(ω)", |p| p.storage),
            series("loss modulus E″(ω)", |p| p.loss),
        ],
    }
}

fn export(args: ExportArgs) -> Result<(), CliError> {
    super::guard_outputs(
        &args
            .material
            .file
            .iter()
            .map(PathBuf::as_path)
            .collect::<Vec<_>>(),
        &[("--output", args.output.as_deref())],
    )?;
    let (id, material) = resolve(&args.material)?;
    let text = match args.format {
        ExportFormat::Abaqus => abaqus(&id, &args.material.command_line(), &material),
        ExportFormat::Ansys => ansys(&args.material.command_line(), &material),
    };
    if material.prony.long_term() == 0.0 {
        eprintln!(
            "warning: {id} has no relaxed modulus (E∞ = 0): Σ g_i = 1, which solvers reject for \
             a solid"
        );
    }
    if let Shift::Arrhenius { .. } = material.shift {
        eprintln!(
            "warning: {id} has an Arrhenius shift; no shift card is written, its constants are \
             in a comment of the export"
        );
    }
    write_output(args.output.as_deref(), text.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compounds_are_named_as_on_the_command_line() {
        let by_id = MaterialRef {
            id: Some("nbr-70".into()),
            file: None,
        };
        assert_eq!(by_id.command_line(), "nbr-70");
        let by_file = |path: &str| MaterialRef {
            id: None,
            file: Some(PathBuf::from(path)),
        };
        assert_eq!(by_file("fit/my.toml").command_line(), "--file fit/my.toml");
        assert_eq!(
            by_file("my fit.toml").command_line(),
            "--file 'my fit.toml'"
        );
        assert_eq!(
            by_file("it's.toml").command_line(),
            r"--file 'it'\''s.toml'"
        );
    }

    #[test]
    fn temperatures_take_units_or_kelvin() {
        assert_eq!(parse_temperature("80C"), Ok(353.15));
        assert_eq!(parse_temperature(" 300 "), Ok(300.0));
        assert_eq!(parse_temperature("300 K"), Ok(300.0));
        assert!(parse_temperature("-300 C").is_err());
        assert!(parse_temperature("0").is_err());
        assert!(parse_temperature("10 m").is_err());
    }
}
