//! The `rollbem` command line with a solver of one's own plugged in: the one line that adds it is the `register`
//! call; everything else (scenes naming it in `[solvers] use`, `[solvers.lcp_pgs]` settings, `rollbem solvers`,
//! `run`, `check`, `sweep`, reports) comes with it. The solver is `tests/plugin/lcp_pgs.rs` (tests/solver_plugin.rs
//! runs this program).
//!
//! `cargo run --release --example cli_with_plugin -- solvers`

#[path = "../tests/plugin/lcp_pgs.rs"]
mod lcp_pgs;

fn main() -> std::process::ExitCode {
    if let Err(e) = rollbem::solvers::register(&lcp_pgs::ENTRY) {
        eprintln!("error: {e}");
        return std::process::ExitCode::from(rollbem::exit::BAD_INPUT);
    }
    rollbem::cli::main()
}
