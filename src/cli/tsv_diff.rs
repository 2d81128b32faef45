//! `ppm diff --mesh M TABLE.tsv`: a table of eval and S′ points against ours
//! (`crate::oracle::tsv_diff`).

use crate::oracle::tsv_diff::{diff_tsv_files_with, render_tsv};
use crate::surface::{Profile, SurfaceKind};
use std::path::Path;
use std::process::ExitCode;

/// Whether `table` is a TSV table of points (first line starts with `face<TAB>`).
pub(crate) fn is_tsv(table: &Path) -> bool {
    use std::io::Read;
    let mut head = [0u8; 64];
    let n = std::fs::File::open(table)
        .and_then(|mut f| f.read(&mut head))
        .unwrap_or(0);
    crate::oracle::tsv_diff::looks_like_tsv(&String::from_utf8_lossy(&head[..n]))
}

/// Run the comparison; exit 0 within tolerance, 1 beyond, 2 on bad input.
pub(super) fn run(
    mesh: &Path,
    table: &Path,
    profile: &str,
    sprime: &str,
    tolerance: f64,
    worst: usize,
    json: bool,
) -> ExitCode {
    let Some(profile) = Profile::parse(profile) else {
        eprintln!("error: unknown profile {profile:?} (paper | authors-code)");
        return ExitCode::from(2);
    };
    let Some(kind) = SurfaceKind::parse(sprime) else {
        eprintln!("error: unknown S′ {sprime:?} (pn | loop)");
        return ExitCode::from(2);
    };
    if tolerance.is_nan() || tolerance < 0.0 {
        eprintln!("error: --tolerance must be a non-negative number");
        return ExitCode::from(2);
    }
    let r = match diff_tsv_files_with(mesh, table, profile, kind, tolerance, worst) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&r).unwrap_or_else(|_| "{}".into())
        );
    } else {
        print!("{}", render_tsv(&r));
    }
    if r.within_tolerance {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
