//! Helpers shared by several modules of the `cli` test binary.

/// Header of the history CSV of `sealsim run`.
pub const HISTORY_HEADER: &str = "time_s,temperature_K,reduced_time_s,shift_factor,\
sealing_force_N_per_m,peak_pressure_Pa,mean_pressure_Pa,contact_width_m,u_c_m,\
leak_rate_m3_per_s,leaked_volume_m3,state,open_fraction,compression_set";

/// The `sealsim` binary as a command.
pub fn sealsim() -> assert_cmd::Command {
    assert_cmd::cargo::cargo_bin_cmd!("sealsim")
}

/// Asserts that `text` (named `what` in the message) has no NaN or infinity.
pub fn no_nan(text: &str, what: &str) {
    for bad in ["NaN", "nan", "inf"] {
        assert!(!text.contains(bad), "{what} contains {bad}:\n{text}");
    }
}
