//! The `ppm` command line.

use std::process::ExitCode;

/// Entry point of the `ppm` binary.
pub fn main() -> ExitCode {
    ExitCode::SUCCESS
}
