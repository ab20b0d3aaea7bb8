//! The column registry: every column of the `sealsim leak` and `sealsim run` CSV files with its
//! unit and meaning, in the order the writers put them. [`markdown`] renders it as
//! `docs/src/reference/columns.md` (`sealsim generate columns`); the tests check that the headers
//! the writers produce are the registry's names, group by group.

use std::fmt::Write as _;

/// One CSV column.
#[derive(Debug, Clone, Copy)]
pub struct Column {
    /// The header cell (the unit is in the name).
    pub name: &'static str,
    /// The unit of its values ("1" for a number without one, "—" for words).
    pub unit: &'static str,
    /// Its meaning, in a line (Markdown).
    pub meaning: &'static str,
}

/// Columns that come together, after the groups before them.
#[derive(Debug, Clone, Copy)]
pub struct Group {
    /// When the file has these columns.
    pub when: &'static str,
    pub columns: &'static [Column],
}

/// One CSV file.
#[derive(Debug, Clone, Copy)]
pub struct File {
    /// The command that writes it.
    pub command: &'static str,
    /// What a row is and how the groups combine (Markdown).
    pub prose: &'static str,
    pub groups: &'static [Group],
}

const fn column(name: &'static str, unit: &'static str, meaning: &'static str) -> Column {
    Column {
        name,
        unit,
        meaning,
    }
}

const LEAK: &[Column] = &[
    column(
        "nominal_pressure_Pa",
        "Pa",
        "nominal squeezing pressure P0 (an O-ring: the peak contact pressure of its installed \
         profile, with the energisation k_e ΔP)",
    ),
    column(
        "zeta_c",
        "1",
        "critical magnification ζc, where A(ζc)/A0 reaches the percolation threshold",
    ),
    column(
        "lambda_c_m",
        "m",
        "lateral size of the critical constriction, λc = 2π/(ζc q0)",
    ),
    column(
        "u_c_m",
        "m",
        "height of the critical constriction u_c = u1(ζc) (effective-medium, numerical: the \
         effective gap)",
    ),
    column("ubar_c_m", "m", "mean interfacial separation ū(ζc)"),
    column("hrms_c_m", "m", "rms roughness left above ζc q0, h_rms(ζc)"),
    column(
        "leak_rate_m3_per_s",
        "m³/s",
        "volume leak rate with the fluid pressure inside the interface (docs/model.md §3.6); a \
         groove-seated ring's two interfaces together",
    ),
    column(
        "state",
        "—",
        "`leaking`; `sealed` (no channel percolates: the junction columns empty, the rate 0); \
         `lift_off` (ΔP reaches the contact pressure: the rate at the onset, a lower bound)",
    ),
    column(
        "area_fraction",
        "1",
        "relative contact area A/A0 at the nominal pressure at full magnification: Persson's \
         A(q1/q0)/A0 at every analytic level, the boundary-element contact fraction (ensemble \
         mean) at the numerical level; blank for an O-ring",
    ),
    column(
        "mean_gap_m",
        "m",
        "mean interfacial separation ū at the nominal pressure: Persson's ū(ζ = 1) at every \
         analytic level, the mean of the boundary-element gap (ensemble mean) at the numerical \
         level; blank for an O-ring",
    ),
];

const LEAK_GAS: &[Column] = &[
    column(
        "throughput_Pa_m3_per_s",
        "Pa·m³/s",
        "the pV flow p̄ × `leak_rate_m3_per_s` at the gas temperature, through the interface \
         only (docs/model.md §3.9)",
    ),
    column(
        "throughput_mbar_L_per_s",
        "mbar·L/s",
        "the same in the leak-test trade's unit (1 mbar·L/s = 0.1 Pa·m³/s)",
    ),
];

const LEAK_MOTION: &[Column] = &[
    column(
        "drag_leak_rate_m3_per_s",
        "m³/s",
        "the drag L_y d v at the sliding speed (a cycle: the out-stroke speed); included in \
         `leak_rate_m3_per_s` with constant sliding",
    ),
    column(
        "film_thickness_m",
        "m",
        "the film d = β u_c dragged out (PY08 eq. 16)",
    ),
    column(
        "speed_bound_m_per_s",
        "m/s",
        "the validity bound of PY08's second eq. 17 (blank when sealed)",
    ),
];

const LEAK_STROKE: &[Column] = &[
    column(
        "out_stroke_volume_m3",
        "m³",
        "volume of the out-stroke, positive from the pressurised side out (docs/model.md \
         §3.4.1)",
    ),
    column(
        "in_stroke_volume_m3",
        "m³",
        "volume of the in-stroke, likewise",
    ),
    column(
        "net_volume_per_cycle_m3",
        "m³",
        "out- plus in-stroke volume of one cycle",
    ),
    column(
        "cycle_mean_leak_rate_m3_per_s",
        "m³/s",
        "`net_volume_per_cycle_m3` over the cycle time",
    ),
    column(
        "out_stroke_film_m",
        "m",
        "inverse-hydrodynamic film h* of the out-stroke (blank without inlet gradients)",
    ),
    column(
        "in_stroke_film_m",
        "m",
        "inverse-hydrodynamic film h* of the in-stroke (blank likewise)",
    ),
    column(
        "film_parameter",
        "1",
        "the thinner h* over the rms roughness (blank likewise)",
    ),
    column(
        "speed_regime",
        "—",
        "`low_speed`, `transition`, `inverse_hydrodynamic` or `low_speed_no_profile`",
    ),
    column(
        "film_regime",
        "—",
        "`boundary`, `mixed` or `full_film` (blank without inlet gradients)",
    ),
];

const HISTORY: &[Column] = &[
    column("time_s", "s", "time since installation"),
    column("temperature_K", "K", "T(t)"),
    column("reduced_time_s", "s", "ξ(t) = ∫ dt / a_T"),
    column(
        "shift_factor",
        "1",
        "a_T(T) (blank where the rubber is frozen, a_T = ∞, or a_T overflows)",
    ),
    column(
        "sealing_force_N_per_m",
        "N/m",
        "sealing force per unit length, ∫ p dx (a ring's own squeeze force, without the \
         energisation)",
    ),
    column(
        "peak_pressure_Pa",
        "Pa",
        "peak nominal contact pressure, with a groove-seated ring's energisation k_e ΔP",
    ),
    column(
        "mean_pressure_Pa",
        "Pa",
        "mean nominal contact pressure over the contact width",
    ),
    column("contact_width_m", "m", "contact width L_x"),
    column(
        "u_c_m",
        "m",
        "critical constriction of the counterface where the asperities carry most (blank when \
         sealed there)",
    ),
    column(
        "leak_rate_m3_per_s",
        "m³/s",
        "leak rate through the profile with the fluid pressure inside the interface \
         (docs/model.md §3.6); a groove-seated ring's two interfaces together",
    ),
    column("leaked_volume_m3", "m³", "leaked volume since installation"),
    column(
        "state",
        "—",
        "`sealed`, `leaking`, `pressure_held` (held by the fluid pressure alone) or `lift_off` \
         (the seal is open; the rate shown is at the onset, a lower bound); docs/model.md §8.1",
    ),
    column(
        "open_fraction",
        "1",
        "open share f of the critical channels' flow under clogging (the open fraction of \
         identical channels under `capture = \"sieving\"`; 1 without `[contamination]`; \
         docs/model.md §7)",
    ),
    column(
        "compression_set",
        "1",
        "compression set of the two-network ageing model after a full recovery (blank without \
         ageing; docs/model.md §6.5)",
    ),
    column(
        "shutdown_squeeze",
        "1",
        "the squeeze the set ring keeps at the shutdown condition (blank where the check does \
         not apply; docs/model.md §8.2)",
    ),
];

const HISTORY_GAS: &[Column] = &[
    column(
        "throughput_Pa_m3_per_s",
        "Pa·m³/s",
        "p̄ × `leak_rate_m3_per_s` at the gas temperature, p̄ = (P_a + P_b)/2 (docs/model.md \
         §3.9)",
    ),
    column(
        "permeation_Pa_m3_per_s",
        "Pa·m³/s",
        "permeation through the rubber at the row's time and temperature, not in the \
         throughput (blank when the run carries none; docs/model.md §13.7)",
    ),
    column(
        "permeation_basis",
        "",
        "how the permeation figure was obtained: `published`, `illustrative` (derived or \
         secondary), `bound` (NOT SOURCED: a stated conservative bound) or `user` \
         (docs/model.md §13.4)",
    ),
];

const HISTORY_MOTION: &[Column] = &[column(
    "drag_leak_rate_m3_per_s",
    "m³/s",
    "the drag at the peak strip; included in `leak_rate_m3_per_s` for constant sliding, not for \
     a stroke cycle (its drag cancels)",
)];

const HISTORY_STROKE: &[Column] = &[
    column(
        "net_volume_per_cycle_m3",
        "m³",
        "out- plus in-stroke volume of one cycle (docs/model.md §3.4.1)",
    ),
    column(
        "out_stroke_film_m",
        "m",
        "inverse-hydrodynamic film h* of the out-stroke (blank without inlet gradients)",
    ),
    column(
        "in_stroke_film_m",
        "m",
        "inverse-hydrodynamic film h* of the in-stroke (blank likewise)",
    ),
    column(
        "speed_regime",
        "—",
        "`low_speed`, `transition`, `inverse_hydrodynamic` or `low_speed_no_profile`",
    ),
];

/// The CSV files, each with its column groups in the order they are written.
pub const FILES: &[File] = &[
    File {
        command: "sealsim leak",
        prose: "One row per pressure. Numbers are in the shortest scientific form that \
                round-trips (`2e5`); a cell without a value is empty. A gas adds its group \
                after `state`; `[motion]` adds the sliding group, and a stroke cycle the stroke \
                group after it. With `--pressure-differences` (one row per fluid ΔP) two \
                columns come first, `pressure_difference_Pa` (the fluid pressure difference \
                ΔP, Pa) and `extrudes` (`yes`/`no`: the extrusion check at installation at \
                that ΔP; blank without a gland), and `nominal_pressure_Pa` is named \
                `contact_pressure_Pa`.",
        groups: &[
            Group {
                when: "always",
                columns: LEAK,
            },
            Group {
                when: "a gas",
                columns: LEAK_GAS,
            },
            Group {
                when: "with `[motion]`",
                columns: LEAK_MOTION,
            },
            Group {
                when: "a stroke cycle",
                columns: LEAK_STROKE,
            },
        ],
    },
    File {
        command: "sealsim run",
        prose: "The history (`-o`): one row per output time, the installation (t = 0) first. A \
                gas adds its group, then `[motion]` its own, and a stroke cycle the stroke \
                group.",
        groups: &[
            Group {
                when: "always",
                columns: HISTORY,
            },
            Group {
                when: "a gas",
                columns: HISTORY_GAS,
            },
            Group {
                when: "with `[motion]`",
                columns: HISTORY_MOTION,
            },
            Group {
                when: "a stroke cycle",
                columns: HISTORY_STROKE,
            },
        ],
    },
];

/// The column names of `file`'s groups in order.
pub fn names(groups: &[Group]) -> Vec<&'static str> {
    groups
        .iter()
        .flat_map(|g| g.columns.iter().map(|c| c.name))
        .collect()
}

/// The column reference in Markdown (`docs/src/reference/columns.md`).
pub fn markdown() -> String {
    let mut out = String::from(
        "<!-- Generated from src/report/columns.rs by `sealsim generate columns -o \
         docs/src/reference/columns.md`; do not edit by hand. -->\n\n# Output columns\n\nThe \
         columns of the CSV files `sealsim leak` and `sealsim run` write, in order; the unit is \
         also in each name. A test checks that the headers the code writes are these.\n",
    );
    for file in FILES {
        let _ = write!(out, "\n## `{}`\n\n{}\n\n", file.command, file.prose);
        out.push_str("| column | meaning | unit | when |\n|---|---|---|---|\n");
        for group in file.groups {
            for c in group.columns {
                let _ = writeln!(
                    out,
                    "| `{}` | {} | {} | {} |",
                    c.name,
                    c.meaning.replace('|', "\\|"),
                    c.unit,
                    group.when
                );
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::report::csv::{
        CONTACT_COLUMNS, LEAK_COLUMNS, gas_leak_table, leak_table, motion_leak_table,
    };
    use crate::report::life::{
        GAS_HISTORY_COLUMN, HISTORY_COLUMNS, MOTION_HISTORY_COLUMNS,
        PERMEATION_BASIS_HISTORY_COLUMN, PERMEATION_HISTORY_COLUMN,
    };

    /// The header row of a CSV text.
    fn header(csv: &str) -> Vec<String> {
        csv.lines()
            .next()
            .unwrap()
            .split(',')
            .map(str::to_owned)
            .collect()
    }

    #[test]
    fn the_leak_headers_the_writers_produce_are_the_registry_s() {
        let groups = FILES[0].groups;
        let always: Vec<&str> = LEAK_COLUMNS.into_iter().chain(CONTACT_COLUMNS).collect();
        assert_eq!(names(&groups[..1]), always);
        assert_eq!(header(&leak_table(&[], &[]).unwrap()), names(&groups[..1]));
        assert_eq!(
            header(&gas_leak_table(&[], &[], 1e5).unwrap()),
            names(&groups[..2])
        );
        let motion = [groups[0], groups[2]];
        assert_eq!(
            header(&motion_leak_table(&[], &[], &[], false).unwrap()),
            names(&motion)
        );
        let stroke = [groups[0], groups[2], groups[3]];
        assert_eq!(
            header(&motion_leak_table(&[], &[], &[], true).unwrap()),
            names(&stroke)
        );
    }

    #[test]
    fn the_history_header_is_the_registry_s() {
        // the history writer chains exactly these constants (report::life)
        let groups = FILES[1].groups;
        assert_eq!(names(&groups[..1]), HISTORY_COLUMNS);
        assert_eq!(
            names(&groups[1..2]),
            [
                GAS_HISTORY_COLUMN,
                PERMEATION_HISTORY_COLUMN,
                PERMEATION_BASIS_HISTORY_COLUMN
            ]
        );
        assert_eq!(names(&groups[2..]), MOTION_HISTORY_COLUMNS);
    }

    #[test]
    fn the_committed_column_reference_is_the_registry_rendered() {
        const REFERENCE: &str = "docs/src/reference/columns.md";
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(REFERENCE);
        let committed = std::fs::read_to_string(path).unwrap_or_default();
        assert!(
            committed == markdown(),
            "{REFERENCE} is not what the column registry (src/report/columns.rs) renders: \
             regenerate it with `cargo run --release -- generate columns -o {REFERENCE}`"
        );
    }
}
