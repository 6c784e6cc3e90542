//! The `pipelens` binary: see `pipelens --help`.

fn main() -> std::process::ExitCode {
    pipelens::cli::main()
}
