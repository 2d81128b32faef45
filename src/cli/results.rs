//! The end of a `ppm sd` command: its check results printed (text or JSON) and the exit
//! status they earn (1 if a check fails), or an error and exit status 2.

use crate::report::{render_text, CheckResult};
use std::process::ExitCode;

/// An error of the command: printed, exit status 2.
pub(super) fn fail(e: String) -> ExitCode {
    eprintln!("error: {e}");
    ExitCode::from(2)
}

/// The results printed as text or JSON; exit status 1 if one of them fails.
pub(super) fn emit(results: &[CheckResult], json: bool) -> ExitCode {
    if json {
        match serde_json::to_string_pretty(results) {
            Ok(s) => println!("{s}"),
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::from(2);
            }
        }
    } else {
        print!("{}", render_text(results));
    }
    if results.iter().any(|r| r.failed()) {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
