//! `sealsim` command-line entry point: parse arguments, run, map errors to exit codes.

/// mimalloc: a study's cases allocate on every thread at once (states, histories, findings),
/// where the system allocator's arenas cost the second thread ≈ 10 % of its time.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    std::process::exit(sealsim::cli::main());
}
