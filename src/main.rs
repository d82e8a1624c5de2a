//! The `rollbem` command line: [`rollbem::cli`].

fn main() -> std::process::ExitCode {
    rollbem::cli::main()
}
