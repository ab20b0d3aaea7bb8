//! End-to-end: gas scenarios (docs/model.md §3.9) — the shipped helium leak test, a leaking
//! nitrogen flat seal (throughput column, JSON keys, Knudsen warnings), and bad gas input
//! (exit 2, file:line:key, nothing written).

use crate::common::{rel, scenario_path};
use crate::support::{HISTORY_HEADER, no_nan, run_text as run};
use std::fs;

/// A flat seal on Persson & Yang's surface that leaks, with nitrogen between 2 and 1 bar
/// absolute: `[fluid]` at line 10, `gas` at 11, `inlet_pressure` at 12, `outlet_pressure` at 13;
/// the rubber's own (test) permeation figure, 1 barrer, through the gasket's 1 mm edge (a gas
/// run never takes a missing figure as zero).
const FLAT_GAS: &str = r#"name = "flat gas"
[material]
youngs_modulus = "10 MPa"
poisson_ratio = 0.5
[surface]
rms_roughness = "2 um"
hurst_exponent = 0.8
q0 = "1e4 1/m"
q1 = "7.8e9 1/m"
[fluid]
gas = "nitrogen"
inlet_pressure = "2 bar"
outlet_pressure = "1 bar"
[seal]
nominal_pressure = "0.2 MPa"
width = "1 mm"
length = "1 mm"
thickness = "1 mm"
[simulation]
duration = "1 day"
[material.permeation]
nitrogen = { permeability = "1 barrer", source = "test figure" }
custom = { permeability = "1 barrer", source = "test figure" }
"#;

#[test]
fn a_leaking_gas_reports_its_throughput_and_its_knudsen_regime() {
    let (code, stdout, stderr, csv, json) = run(FLAT_GAS);
    assert_eq!(code, Some(0), "{stderr}");
    let csv = csv.unwrap();
    no_nan(&csv, "history");
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        format!("{HISTORY_HEADER},throughput_Pa_m3_per_s,permeation_Pa_m3_per_s,permeation_basis")
    );
    // the material's own figure: its basis in every row, steady from installation (no D)
    assert!(
        stderr.contains("no diffusivity known, so the steady flow"),
        "{stderr}"
    );
    // throughput = p̄ × the leak rate (the volume flow at the mean pressure), p̄ = 1.5 bar
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        let leak: f64 = cells[9].parse().unwrap();
        let q: f64 = cells[15].parse().unwrap();
        assert_eq!(cells[17], "user", "{line}");
        assert!(leak > 0.0);
        assert!(rel(q, 1.5e5 * leak) < 1e-12, "{line}");
    }
    // the summary: SI and the helium-leak-test form, 1 mbar·L/s = 0.1 Pa·m³/s
    assert!(
        stdout.contains("Pa·m³/s (") && stdout.contains("mbar·L/s)"),
        "{stdout}"
    );
    assert!(stdout.contains("mean pressure p̄ = 150000 Pa"), "{stdout}");
    let json: serde_json::Value = serde_json::from_str(&json.unwrap()).unwrap();
    let gas = &json["gas"];
    assert_eq!(gas["gas"], "nitrogen");
    assert_eq!(gas["inlet_pressure_Pa"], 2e5);
    assert_eq!(gas["outlet_pressure_Pa"], 1e5);
    let q = gas["final_throughput_Pa_m3_per_s"].as_f64().unwrap();
    let mbar = gas["final_throughput_mbar_L_per_s"].as_f64().unwrap();
    assert!(rel(mbar, 10.0 * q) < 1e-12);
    let leak = json["final_leak_rate_m3_per_s"].as_f64().unwrap();
    assert!(rel(q, 1.5e5 * leak) < 1e-12);
    // N2 at 23 °C and p̄ = 1.5 bar: λ_μ ≈ 44 nm over u_c ≈ 0.12 µm, Kn ≈ 0.36: the transition
    // regime, and only it, is named; the rarefied law is used and the summary and JSON give
    // the continuum law's figure beside it
    assert!(
        stderr.contains("transition regime (0.1 < Kn ≤ 10)"),
        "{stderr}"
    );
    assert!(!stderr.contains("slip regime"), "{stderr}");
    assert!(!stderr.contains("free-molecular regime"), "{stderr}");
    assert_eq!(gas["flow_law"], "rarefied");
    let continuum = gas["continuum_initial_throughput_Pa_m3_per_s"]
        .as_f64()
        .unwrap();
    let initial = gas["initial_throughput_Pa_m3_per_s"].as_f64().unwrap();
    // (×1.53 only, against f(Kn = 0.36) ≈ 3.5 at the outlet's u_c: the inlet side, where the
    // fluid pressure relieves the asperities, has the widest constrictions and the smallest Kn,
    // and carries most of the interface's conductance)
    assert!(
        initial > 1.2 * continuum && initial < 10.0 * continuum,
        "{initial} vs {continuum}"
    );
    assert!(
        stdout.contains("rarefied flow; the continuum law would give"),
        "{stdout}"
    );
    // rarefaction = false: the continuum law, and a warning that it underestimates the flow
    let (code, stdout, stderr, _, json) = run(&FLAT_GAS.replace(
        "gas = \"nitrogen\"",
        "gas = \"nitrogen\"\nrarefaction = false",
    ));
    assert_eq!(code, Some(0), "{stderr}");
    assert!(stderr.contains("but `rarefaction = false`"), "{stderr}");
    assert!(
        stdout.contains("(continuum law; see the Knudsen"),
        "{stdout}"
    );
    let json: serde_json::Value = serde_json::from_str(&json.unwrap()).unwrap();
    assert_eq!(json["gas"]["flow_law"], "continuum");
    let q = json["gas"]["initial_throughput_Pa_m3_per_s"]
        .as_f64()
        .unwrap();
    assert!(rel(q, continuum) < 1e-12, "{q} vs {continuum}");
}

#[test]
fn the_gas_leak_is_the_liquid_law_at_the_gas_viscosity_for_a_small_pressure_ratio() {
    // 1.001 bar against 1 bar: the gas's volume flow at the mean pressure is the liquid's with
    // the same (constant) viscosity, to the interface-pressure weight (P_b + p_f)/p̄ = 1 ± 5e-4
    let gas = FLAT_GAS
        .replace("gas = \"nitrogen\"", "gas = \"custom\"\nmolar_mass = \"28 g/mol\"\nviscosity = \"17.9 uPa*s\"\nmolecular_diameter = \"0.37 nm\"\nrarefaction = false")
        .replace("inlet_pressure = \"2 bar\"", "inlet_pressure = \"100.1 kPa\"")
        .replace("outlet_pressure = \"1 bar\"", "outlet_pressure = \"100 kPa\"");
    let liquid = FLAT_GAS
        .replace("gas = \"nitrogen\"", "viscosity = \"17.9 uPa*s\"")
        .replace(
            "inlet_pressure = \"2 bar\"",
            "pressure_difference = \"0.1 kPa\"",
        )
        .replace("outlet_pressure = \"1 bar\"\n", "");
    let (cg, _, eg, _, jg) = run(&gas);
    let (cl, _, el, _, jl) = run(&liquid);
    assert_eq!((cg, cl), (Some(0), Some(0)), "{eg}{el}");
    let leak = |j: Option<String>| {
        let v: serde_json::Value = serde_json::from_str(&j.unwrap()).unwrap();
        v["initial_leak_rate_m3_per_s"].as_f64().unwrap()
    };
    let (g, l) = (leak(jg), leak(jl));
    assert!(rel(g, l) < 1e-6, "{g} vs {l}");
}

#[test]
fn the_shipped_helium_leak_test_seals_at_the_interface_and_permeates() {
    // the shipped file reads no other file, so it runs from a copy
    let text = fs::read_to_string(scenario_path("helium-leak-test-flange.toml")).unwrap();
    let (code, stdout, stderr, history, json_text) = run(&text);
    assert_eq!(code, Some(0), "{stderr}");
    // the header's claim: the interface seals on this finish, throughput 0 throughout
    assert!(
        stdout.contains("throughput     ≈ 0 (below 4.09e-21 Pa·m³/s (4.09e-20 mbar·L/s), one molecule a second) at installation"),
        "{stdout}"
    );
    assert!(stdout.contains("gas helium"), "{stdout}");
    // permeation through the FKM ring: 0 at installation, positive after the day; the total
    // is what the 1e-9 mbar·L/s criterion sees, so the ring fails the test on permeation
    assert!(
        stdout.contains("permeation     0 Pa·m³/s at installation"),
        "{stdout}"
    );
    assert!(stdout.contains("time lag"), "{stdout}");
    assert!(
        stdout.contains("total          0 Pa·m³/s at installation"),
        "{stdout}"
    );
    assert!(stdout.contains("by leak_rate"), "{stdout}");
    let history = history.unwrap();
    no_nan(&history, "history");
    let mut lines = history.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .ends_with(",throughput_Pa_m3_per_s,permeation_Pa_m3_per_s,permeation_basis")
    );
    let permeation: Vec<f64> = lines
        .map(|l| l.split(',').nth(16).unwrap().parse().unwrap())
        .collect();
    assert_eq!(permeation[0], 0.0);
    assert!(permeation.windows(2).all(|w| w[1] >= w[0]));
    let json_text = json_text.unwrap();
    no_nan(&json_text, "summary");
    let json: serde_json::Value = serde_json::from_str(&json_text).unwrap();
    let gas = &json["gas"];
    assert_eq!(gas["inlet_pressure_Pa"], 1e5);
    assert!(rel(gas["outlet_pressure_Pa"].as_f64().unwrap(), 1e-4) < 1e-12);
    let q = gas["permeation_Pa_m3_per_s"].as_f64().unwrap();
    assert!(rel(q, *permeation.last().unwrap()) < 1e-12);
    // interface 0: the total is the permeation
    let total = gas["total_throughput_Pa_m3_per_s"].as_f64().unwrap();
    assert!(
        rel(
            total,
            q + gas["final_throughput_Pa_m3_per_s"].as_f64().unwrap()
        ) < 1e-12
    );
    assert!(q > 1e-10 && total == q, "{q} {total}");
    // the time lag w²/(6D), w = πd²/(4h) = 3.698 mm, h = 2.648 mm, D = 4.36e-10 m²/s (helium in
    // Viton, §13.4): 1.3676e-5/2.616e-9 ≈ 5.23e3 s (the ring's stretch moves it slightly)
    let lag = gas["permeation_time_lag_s"].as_f64().unwrap();
    assert!((5.1e3..5.35e3).contains(&lag), "{lag}");
}

/// [`FLAT_GAS`] with a liquid of 1 mPa·s at ΔP = 1 bar instead of the gas.
fn flat_liquid() -> String {
    FLAT_GAS
        .replace("gas = \"nitrogen\"", "viscosity = \"1 mPa*s\"")
        .replace(
            "inlet_pressure = \"2 bar\"",
            "pressure_difference = \"1 bar\"",
        )
        .replace("outlet_pressure = \"1 bar\"\n", "")
}

/// `text` must exit 2 with `s.toml:{line}: {key}` and `needle` in stderr, and write nothing.
fn refused(text: &str, line: usize, key: &str, needle: &str) {
    let (code, stdout, stderr, csv, json) = run(text);
    assert_eq!(code, Some(2), "{stdout}{stderr}");
    let located = format!("s.toml:{line}: {key}");
    assert!(stderr.contains(&located), "{located}: {stderr}");
    assert!(stderr.contains(needle), "{needle}: {stderr}");
    assert!(csv.is_none() && json.is_none(), "nothing may be written");
}

#[test]
fn bad_gas_input_exits_2_with_file_line_and_key() {
    refused(
        &FLAT_GAS.replace(
            "gas = \"nitrogen\"",
            "gas = \"nitrogen\"\nlibrary = \"water\"",
        ),
        12,
        "fluid.library",
        "a liquid's viscosity key",
    );
    refused(
        &FLAT_GAS.replace("outlet_pressure = \"1 bar\"", "outlet_pressure = \"3 bar\""),
        13,
        "fluid.outlet_pressure",
        "above the inlet pressure",
    );
    refused(
        &FLAT_GAS.replace("gas = \"nitrogen\"", "gas = \"xenon\""),
        11,
        "fluid.gas",
        "unknown gas \"xenon\"",
    );
    // a throughput criterion on a liquid
    let liquid = flat_liquid();
    refused(
        &format!("{liquid}[failure]\nmax_leak_rate = \"1e-9 mbar*L/s\"\n"),
        24,
        "failure.max_leak_rate",
        "is a gas throughput, but [fluid] is a liquid",
    );
    // a volume-flow criterion on a gas (refused: at which pressure?)
    refused(
        &format!("{FLAT_GAS}[failure]\nmax_leak_rate = \"1e-9 m^3/s\"\n"),
        25,
        "failure.max_leak_rate",
        "is a volume flow, but [fluid] is a gas",
    );
    // a gauge unit on an absolute pressure
    refused(
        &FLAT_GAS.replace("inlet_pressure = \"2 bar\"", "inlet_pressure = \"1 barg\""),
        12,
        "fluid.inlet_pressure",
        "is a gauge pressure",
    );
    // a library gas with a custom key; a custom gas without its molar mass
    refused(
        &FLAT_GAS.replace(
            "gas = \"nitrogen\"",
            "gas = \"nitrogen\"\nmolar_mass = \"28 g/mol\"",
        ),
        12,
        "fluid.molar_mass",
        "only goes with gas = \"custom\"",
    );
    refused(
        &FLAT_GAS.replace(
            "gas = \"nitrogen\"",
            "gas = \"custom\"\nviscosity = \"17 uPa*s\"",
        ),
        10,
        "fluid.molar_mass",
        "missing key `molar_mass`",
    );
    // the flow law of a gas on a liquid
    refused(
        &liquid.replace(
            "pressure_difference = \"1 bar\"",
            "pressure_difference = \"1 bar\"\nrarefaction = true",
        ),
        13,
        "fluid.rarefaction",
        "the flow law of a gas",
    );
    // absolute pressures on a liquid
    refused(
        &liquid.replace(
            "pressure_difference = \"1 bar\"",
            "pressure_difference = \"1 bar\"\noutlet_pressure = \"1 bar\"",
        ),
        13,
        "fluid.gas",
        "belong to a gas",
    );
}

#[test]
fn a_throughput_criterion_fails_a_leaking_gas_seal() {
    // the leak is ≈ 7.7e-6 Pa·m³/s = 7.7e-5 mbar·L/s (rarefied): a 1e-5 mbar·L/s criterion
    // fails it at installation, a 1e-3 one (or 60 sccm ≈ 1.1e-1 Pa·m³/s) does not
    let result = |criterion: &str| {
        let (code, stdout, stderr, _, _) = run(&format!(
            "{FLAT_GAS}[failure]\nmax_leak_rate = \"{criterion}\"\n"
        ));
        assert_eq!(code, Some(0), "{stderr}");
        stdout
            .lines()
            .find(|l| l.starts_with("result"))
            .unwrap_or_default()
            .to_owned()
    };
    let fails = |criterion: &str| result(criterion).contains("FAILS at installation by leak_rate");
    assert!(fails("1e-5 mbar*L/s"));
    // 1e-4 lies between the levels (7.7e-5 here, 1.06e-4 mbar·L/s at the effective medium):
    // the model does not decide it (docs/model.md §4.1)
    assert!(
        result("1e-4 mbar*L/s").contains("UNDECIDED by the model"),
        "{}",
        result("1e-4 mbar*L/s")
    );
    assert!(!fails("1e-3 mbar*L/s"));
    assert!(!fails("60 sccm"));
    assert!(fails("1e-3 sccm"));
}

#[test]
fn a_custom_gas_with_nitrogens_constants_is_nitrogen() {
    let custom = FLAT_GAS.replace(
        "gas = \"nitrogen\"",
        "gas = \"custom\"\nmolar_mass = \"28.014 g/mol\"\nmolecular_diameter = \"0.37 nm\"\n\
         sutherland_viscosity = \"1.663e-5 Pa*s\"\nsutherland_temperature = \"273 K\"\n\
         sutherland_constant = \"107 K\"",
    );
    let (c1, _, e1, h1, _) = run(FLAT_GAS);
    let (c2, _, e2, h2, _) = run(&custom);
    assert_eq!((c1, c2), (Some(0), Some(0)), "{e1}{e2}");
    assert_eq!(h1, h2, "the same gas must give the same history");
}

#[test]
fn a_volume_criterion_on_a_gas_is_accepted_at_its_stated_conditions() {
    // sccm is a volume flow at 0 °C and 1 atm: the same criterion written as cm³/min with that
    // reference state must give the same run, bit for bit
    let with = |failure: &str| {
        // the continuum law: the figures below are its own
        let continuum = FLAT_GAS.replace(
            "gas = \"nitrogen\"",
            "gas = \"nitrogen\"\nrarefaction = false",
        );
        let (code, stdout, stderr, csv, json) = run(&format!("{continuum}[failure]\n{failure}"));
        assert_eq!(code, Some(0), "{stderr}");
        // the JSON names its (temporary) scenario file, and the input warnings its path: drop
        // those lines
        let json: String = json
            .unwrap_or_default()
            .lines()
            .filter(|l| !l.contains("\"scenario_file\"") && !l.contains("s.toml"))
            .collect();
        (stdout, csv.unwrap_or_default(), json)
    };
    for q in ["1e-3", "60"] {
        let a = with(&format!("max_leak_rate = \"{q} sccm\"\n"));
        let b = with(&format!(
            "max_leak_rate = \"{q} cm^3/min\"\nreference_pressure = \"101325 Pa\"\n\
             reference_temperature = \"0 C\"\n"
        ));
        assert!(a == b, "{q} sccm: {}\n{}", a.0, b.0);
    }
    // a leaked amount: 1 mbar·L = 0.1 Pa·m³; 1 L at 1 bar and the gas temperature is 1e5 ×
    // 1e-3 Pa·m³; the leak is ≈ 5e-6 Pa·m³/s, so 0.1 Pa·m³ is reached after ≈ 6 h
    let a = with("max_leaked_volume = \"1 mbar*L\"\n");
    let b = with("max_leaked_volume = \"0.1 Pa*m^3\"\n");
    let c = with("max_leaked_volume = \"1 cm^3\"\nreference_pressure = \"1 bar\"\n");
    assert!(a == b, "{}\n{}", a.0, b.0);
    assert!(a == c, "{}\n{}", a.0, c.0);
    // 0.1 Pa·m³ over 5.0127e-6 Pa·m³/s = 19950 s
    assert!(
        a.0.contains("FAILS after 5.54 h") && a.0.contains("by leaked_volume"),
        "{}",
        a.0
    );
}

#[test]
fn a_volume_criterion_on_a_gas_without_its_conditions_is_refused() {
    refused(
        &format!("{FLAT_GAS}[failure]\nmax_leaked_volume = \"1 L\"\n"),
        25,
        "failure.max_leaked_volume",
        "state the conditions with `reference_pressure`",
    );
    refused(
        &format!("{FLAT_GAS}[failure]\nmax_leaked_volume = \"1 N\"\n"),
        25,
        "failure.max_leaked_volume",
        "is not an amount of gas",
    );
    refused(
        &format!(
            "{FLAT_GAS}[failure]\nmax_leak_rate = \"1 mbar*L/s\"\nreference_temperature = \"0 C\"\n"
        ),
        26,
        "failure.reference_temperature",
        "goes with `reference_pressure`",
    );
    let liquid = flat_liquid();
    refused(
        &format!(
            "{liquid}[failure]\nmax_leak_rate = \"1e-9 m^3/s\"\nreference_pressure = \"1 bar\"\n"
        ),
        25,
        "failure.reference_pressure",
        "belongs to a gas",
    );
}

#[test]
fn leak_on_a_gas_gives_the_throughput_of_the_runs_first_row() {
    // the shipped helium gasket: `leak` at the installation pressure is the run's first row,
    // and its throughput column is p̄ × the leak rate (p̄ = 0.5 bar against the vacuum)
    let scenario = scenario_path("helium-leak-test-gasket.toml");
    let out = crate::support::sealsim()
        .arg("leak")
        .arg(&scenario)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let csv = String::from_utf8(out.stdout).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(
        &header[header.len() - 2..],
        ["throughput_Pa_m3_per_s", "throughput_mbar_L_per_s"]
    );
    let row: Vec<f64> = lines
        .next()
        .unwrap()
        .split(',')
        .filter_map(|c| c.parse().ok())
        .collect();
    let (leak, q) = (row[6], row[row.len() - 2]);
    assert!(rel(q, 0.5e5 * leak) < 1e-9, "{q} vs {leak}");
    let dir = tempfile::tempdir().unwrap();
    let history = dir.path().join("h.csv");
    let status = crate::support::sealsim()
        .arg("run")
        .arg(&scenario)
        .arg("-o")
        .arg(&history)
        .output()
        .unwrap();
    assert_eq!(status.status.code(), Some(0));
    let text = fs::read_to_string(&history).unwrap();
    let first: Vec<&str> = text.lines().nth(1).unwrap().split(',').collect();
    let run_q: f64 = first[15].parse().unwrap();
    assert!(rel(q, run_q) < 1e-12, "leak {q} vs run {run_q}");
}

/// Issue 39.2 / 40.4: the compounds that had no permeation figure (they "survived" the helium
/// test on an unknown zero) now fail it on their class's figure, each row saying which: IIR on
/// polyisobutylene (Ito 1961), ACM on poly(ethyl acrylate) (Mogri & Paul 2001, a proxy),
/// FVMQ on its own compiled value (npj 2024), FFKM on a NOT SOURCED bound; and each row names
/// where its ageing activation energy comes from.
#[test]
fn no_compound_passes_a_helium_test_on_a_figure_it_does_not_have() {
    let (stdout, header, rows) = crate::support::compare_csv(
        &scenario_path("helium-leak-test-flange.toml"),
        "iir-70,ffkm-75,acm-70,fvmq-70",
    );
    let col = |name: &str| header.iter().position(|c| c == name).unwrap();
    let basis = |id: &str| -> String {
        rows.iter().find(|r| r[0] == id).unwrap()[col("permeation_source")].clone()
    };
    for row in &rows {
        assert_eq!(row[col("failure_mode")], "leak_rate", "{row:?}");
        let t: f64 = row[col("time_to_failure_s")].parse().unwrap();
        assert!(t > 0.0 && t < 86400.0, "{row:?}");
        assert!(!row[col("permeation_source")].is_empty(), "{row:?}");
        assert!(!row[col("activation_energy_source")].is_empty(), "{row:?}");
    }
    assert!(basis("iir-70").starts_with("sourced: Ito"), "{rows:?}");
    assert!(
        basis("acm-70").starts_with("sourced: Mogri & Paul") && basis("acm-70").contains("proxy"),
        "{rows:?}"
    );
    assert!(basis("fvmq-70").starts_with("sourced: npj"), "{rows:?}");
    assert!(
        basis("ffkm-75").starts_with("NOT SOURCED bound"),
        "{rows:?}"
    );
    // every helium D here is the stated upper bound (the shortest lag): said so
    assert!(
        rows.iter()
            .all(|r| r[col("permeation_source")].contains("D an upper bound"))
    );
    let ea = |id: &str| {
        rows.iter().find(|r| r[0] == id).unwrap()[col("activation_energy_source")].clone()
    };
    assert!(ea("ffkm-75").contains("ASSUMED band"), "{rows:?}");
    assert!(ea("iir-70").contains("Pazur & Mengistu"), "{rows:?}");
    // the terminal table: no survivor, the bound named beside its row
    assert!(!stdout.contains("survives"), "{stdout}");
    // (rank, material, …: the table ranks the rows)
    let ffkm = stdout
        .lines()
        .find(|l| l.split_whitespace().nth(1) == Some("ffkm-75"))
        .unwrap();
    assert!(ffkm.contains("NOT SOURCED bound"), "{ffkm}");
}

/// Issue 39.2: butyl on the 100 bar hydrogen line no longer survives ten years on a missing
/// figure: polyisobutylene's H2 permeability (Ito 1961, 6.5 barrer) fails it by leak rate,
/// as NBR and HNBR fail it.
#[test]
fn butyl_no_longer_survives_the_hydrogen_line_on_a_zero() {
    let (_, header, rows) = crate::support::compare_csv(
        &scenario_path("hydrogen-line-100bar.toml"),
        "iir-70,hnbr-75",
    );
    let col = |name: &str| header.iter().position(|c| c == name).unwrap();
    for row in &rows {
        assert_eq!(row[col("failure_mode")], "leak_rate", "{row:?}");
        assert!(!row[col("time_to_failure_s")].is_empty(), "{row:?}");
    }
    let iir = rows.iter().find(|r| r[0] == "iir-70").unwrap();
    assert!(iir[col("permeation_source")].contains("Ito"), "{iir:?}");
    let hnbr = rows.iter().find(|r| r[0] == "hnbr-75").unwrap();
    assert!(
        hnbr[col("permeation_source")].starts_with("NOT SOURCED bound"),
        "{hnbr:?}"
    );
}

/// Issue 39.2: a missing figure never reads as zero. A gas run whose compound has no class and
/// no figure of its own, a flat gasket without its thickness, a gas the table lacks: each exits
/// 2 at the key that supplies it, saying what to write, and writes nothing. Written, the class
/// gives its figure — here a NOT SOURCED bound, which the summary, the JSON, the history and
/// the HTML report all say — and the compound's own figure runs as the user's.
#[test]
fn a_missing_permeation_figure_is_refused_where_it_is_supplied() {
    let ring = fs::read_to_string(scenario_path("helium-leak-test-flange.toml")).unwrap();
    // an inline compound (the library's FKM curve, no class)
    let inline = ring.replace(
        "library = \"fkm-75\"",
        "youngs_modulus = \"7 MPa\"\npoisson_ratio = 0.5\nthermal_expansion = \"1.6e-4 1/K\"",
    );
    let material_line = 1 + inline
        .lines()
        .position(|l| l.trim_start().starts_with("[material]"))
        .unwrap();
    refused(&inline, material_line, "material.class", "class = \"nbr\"");
    refused(
        &inline,
        material_line,
        "material.class",
        "[material.permeation] helium = { permeability",
    );
    // a flat gasket without its thickness
    let gasket = fs::read_to_string(scenario_path("helium-leak-test-gasket.toml")).unwrap();
    let thin = gasket.replace("thickness = \"2.8 mm\"", "");
    let seal_line = 1 + thin
        .lines()
        .position(|l| l.trim_start().starts_with("[seal]"))
        .unwrap();
    refused(
        &thin,
        seal_line,
        "seal.thickness",
        "missing key `thickness` in [seal]",
    );
    // argon: no class has a row
    let argon = ring.replace("gas = \"helium\"", "gas = \"argon\"");
    let gas_line = 1 + argon
        .lines()
        .position(|l| l.trim_start().starts_with("[fluid]"))
        .unwrap();
    refused(
        &argon,
        gas_line,
        "fluid.gas",
        "[material.permeation] argon = {",
    );
    // the class, written: its figure is a bound, and every output says so
    let dir = tempfile::tempdir().unwrap();
    let with_class = inline.replace(
        "poisson_ratio = 0.5",
        "poisson_ratio = 0.5\nclass = \"nbr\"",
    );
    let scenario = dir.path().join("s.toml");
    fs::write(&scenario, &with_class).unwrap();
    let (csv, json, html) = (
        dir.path().join("h.csv"),
        dir.path().join("s.json"),
        dir.path().join("r.html"),
    );
    let out = crate::support::sealsim()
        .arg("run")
        .arg(&scenario)
        .arg("--verbose")
        .arg("-o")
        .arg(&csv)
        .arg("--summary")
        .arg(&json)
        .arg("--report")
        .arg(&html)
        .output()
        .unwrap();
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let permeation = stdout
        .lines()
        .find(|l| l.starts_with("permeation"))
        .unwrap();
    assert!(permeation.contains("NOT SOURCED bound"), "{permeation}");
    let summary: serde_json::Value =
        serde_json::from_str(&fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(summary["gas"]["permeation_basis"], "bound");
    assert!(
        summary["gas"]["permeation_source"]
            .as_str()
            .unwrap()
            .starts_with("NOT SOURCED bound")
    );
    let history = fs::read_to_string(&csv).unwrap();
    assert!(
        history
            .lines()
            .next()
            .unwrap()
            .ends_with(",permeation_basis")
    );
    assert!(
        history.lines().skip(1).all(|l| l.ends_with(",bound")),
        "{history}"
    );
    assert!(
        fs::read_to_string(&html)
            .unwrap()
            .contains("NOT SOURCED bound")
    );
    // argon with the compound's own figure next to its library id: the user's figure
    let own = format!(
        "{argon}\n[material.permeation]\nargon = {{ permeability = \"0.5 barrer\", source = \
         \"supplier sheet\" }}\n"
    );
    let (code, stdout, stderr, history, summary) = run(&own);
    assert_eq!(code, Some(0), "{stderr}");
    assert!(
        stdout.contains("the user's figure: supplier sheet"),
        "{stdout}"
    );
    assert!(
        history
            .unwrap()
            .lines()
            .skip(1)
            .all(|l| l.ends_with(",user"))
    );
    let summary: serde_json::Value = serde_json::from_str(&summary.unwrap()).unwrap();
    assert_eq!(summary["gas"]["permeation_basis"], "user");
}
