//! `ppm`: the command-line front end of the pseudomanifold reference implementation.

fn main() -> std::process::ExitCode {
    pseudomanifold::cli::main()
}
