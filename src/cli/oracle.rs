//! `ppm oracle` (JSON-lines protocol on stdin/stdout) and `ppm diff` (a table of answers, or
//! with `--surface` a sampled surface). See `docs/oracle.md`.

use crate::mesh::io::{read_mesh, ReadOptions};
use crate::oracle::diff::{diff_table, render};
use crate::oracle::surface_diff::{diff_surface, render_surface, MatchMode, SurfaceDiffOptions};
use crate::oracle::{Request, Session};
use std::io::{BufRead, Read, Write};
use std::path::Path;
use std::process::ExitCode;

/// Longest accepted request line (bounded memory per request).
const MAX_LINE: u64 = 1 << 20;

fn session(mesh: Option<&Path>, bits: u32, profile: &str, sprime: &str) -> Result<Session, String> {
    let mut s = Session::new();
    s.handle(&Request::SetSurface {
        surface: sprime.to_string(),
    })
    .map_err(|e| e.to_string())?;
    s.handle(&Request::SetPrecision { bits })
        .map_err(|e| e.to_string())?;
    s.handle(&Request::SetProfile {
        profile: profile.to_string(),
    })
    .map_err(|e| e.to_string())?;
    if let Some(m) = mesh {
        s.handle(&Request::Load {
            path: m.to_path_buf(),
        })
        .map_err(|e| e.to_string())?;
    }
    Ok(s)
}

/// `ppm oracle [--mesh M] [--bits B] [--profile P]`: answer one JSON request per stdin line
/// with one JSON response per stdout line until end of input. Exit status 0, or 2 when the
/// initial mesh/precision/profile is rejected or stdin cannot be read.
pub fn run_oracle(mesh: Option<&Path>, bits: u32, profile: &str, sprime: &str) -> ExitCode {
    let mut s = match session(mesh, bits, profile, sprime) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let stdin = std::io::stdin();
    let mut input = stdin.lock();
    let stdout = std::io::stdout();
    let mut out = stdout.lock();
    let mut buf = Vec::new();
    loop {
        buf.clear();
        let n = match Read::by_ref(&mut input)
            .take(MAX_LINE)
            .read_until(b'\n', &mut buf)
        {
            Ok(n) => n,
            Err(e) => {
                eprintln!("error: reading stdin: {e}");
                return ExitCode::from(2);
            }
        };
        if n == 0 {
            return ExitCode::SUCCESS;
        }
        let resp = if buf.last() != Some(&b'\n') && n as u64 == MAX_LINE {
            // Skip the rest of the over-long line.
            let mut sink = Vec::new();
            let _ = input.read_until(b'\n', &mut sink);
            s.handle_line("{\"op\":\"line too long (over 1 MiB)\"}")
        } else {
            match std::str::from_utf8(&buf) {
                Ok(line) if line.trim().is_empty() => continue,
                Ok(line) => s.handle_line(line),
                Err(_) => s.handle_line("not utf-8"),
            }
        };
        let text = serde_json::to_string(&resp).unwrap_or_else(|_| "{\"ok\":false}".into());
        if writeln!(out, "{text}").and_then(|_| out.flush()).is_err() {
            return ExitCode::SUCCESS; // reader went away
        }
    }
}

/// `ppm diff --mesh M TABLE`: compare a JSON-lines table of answers against the reference.
/// Exit status 0 within tolerance, 1 outside (or items not compared), 2 on a usage error.
pub fn run_diff(
    mesh: &Path,
    table: &Path,
    bits: u32,
    tolerance: f64,
    worst: usize,
    json: bool,
    sprime: &str,
) -> ExitCode {
    let mut s = match session(Some(mesh), bits, "paper", sprime) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let text = match std::fs::read_to_string(table) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: {}: {e}", table.display());
            return ExitCode::from(2);
        }
    };
    let r = diff_table(&mut s, &text, tolerance, worst);
    if json {
        println!(
            "{}",
            serde_json::to_string_pretty(&r).unwrap_or_else(|_| "{}".into())
        );
    } else {
        print!("{}", render(&r));
    }
    if r.within_tolerance {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}

/// The `ppm diff --surface` options (see `crate::cli`).
pub struct SurfaceArgs {
    /// Subdivision level (`None`: inferred from the vertex count).
    pub level: Option<u32>,
    /// `order` | `nearest`.
    pub matching: String,
    /// Chapter 5 profile name.
    pub profile: String,
    /// Largest accepted deviation (`None`: twice the f64 bound).
    pub tolerance: Option<f64>,
    /// MPFR precision of the spot checks.
    pub bits: u32,
    /// How many worst items to list.
    pub worst: usize,
    /// JSON output.
    pub json: bool,
    /// S′ of the reference: `pn` | `loop`.
    pub sprime: String,
}

/// `ppm diff --surface OTHER --mesh M [--level N]`: compare a sampled surface against the
/// reference sampling (Sec. 6.2). Exit status 0 within tolerance, 1 outside, 2 on a usage
/// error (unreadable files, unknown level or option).
pub fn run_diff_surface(mesh: &Path, surface: &Path, a: &SurfaceArgs) -> ExitCode {
    let fail = |msg: String| {
        eprintln!("error: {msg}");
        ExitCode::from(2)
    };
    let Some(matching) = MatchMode::parse(&a.matching) else {
        return fail(format!(
            "--match {:?}: expected order or nearest",
            a.matching
        ));
    };
    if a.tolerance.is_some_and(|t| t.is_nan() || t < 0.0) {
        return fail("--tolerance must be a non-negative number".into());
    }
    let mut s = match session(Some(mesh), a.bits, &a.profile, &a.sprime) {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    let other = match read_mesh(surface, &ReadOptions::default()) {
        Ok(m) => m,
        Err(e) => return fail(e.to_string()),
    };
    let pps = match s.pps() {
        Ok(p) => p,
        Err(e) => return fail(e.to_string()),
    };
    let opts = SurfaceDiffOptions {
        level: a.level,
        tolerance: a.tolerance,
        matching,
        worst: a.worst,
        bits: a.bits,
        ..SurfaceDiffOptions::default()
    };
    let r = match diff_surface(pps, &other.positions, Some(&other.faces), &opts) {
        Ok(r) => r,
        Err(e) => return fail(e.to_string()),
    };
    if a.json {
        println!(
            "{}",
            serde_json::to_string_pretty(&r).unwrap_or_else(|_| "{}".into())
        );
    } else {
        print!("{}", render_surface(&r));
    }
    if r.within_tolerance {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
