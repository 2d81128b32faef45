//! `ppm oracle` (JSON-lines protocol on stdin/stdout) and `ppm diff` (a table of answers, or
//! with `--surface` a sampled surface). See `docs/oracle.md`.

use crate::mesh::io::{read_mesh, ReadOptions};
use crate::oracle::diff::{diff_table, render};
use crate::oracle::surface_diff::{diff_surface, render_surface, MatchMode, SurfaceDiffOptions};
use crate::oracle::{OracleError, Request, Response, Session};
use crate::surface::Construction;
use std::io::{BufRead, Read, Write};
use std::path::Path;
use std::process::ExitCode;

/// Longest accepted request line (bounded memory per request).
pub(super) const MAX_LINE: u64 = 1 << 20;

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

/// Sets the session's reference construction from `--construction` / `--kappa` (nothing to do
/// for the default vertex construction): shared by `ppm diff` on a table and on a surface.
fn set_construction(
    s: &mut Session,
    construction: Construction,
    kappa: Option<f64>,
) -> Result<(), String> {
    if construction == Construction::Vertex && kappa.is_none() {
        return Ok(());
    }
    let req = crate::oracle::Request::SetConstruction {
        construction: construction.name().to_string(),
        kappa,
    };
    s.handle(&req)
        .map(|_| ())
        .map_err(|e| format!("--construction {}: {e}", construction.name()))
}

/// `ppm oracle [--mesh M] [--bits B] [--profile P] [--certificate C]`: answer one JSON request per stdin line
/// with one JSON response per stdout line until end of input. Exit status 0, or 2 when the
/// initial mesh/precision/profile is rejected or stdin cannot be read.
pub(crate) fn run_oracle(
    mesh: Option<&Path>,
    bits: u32,
    profile: &str,
    sprime: &str,
    certificate: Option<&Path>,
) -> ExitCode {
    let session = session(mesh, bits, profile, sprime).and_then(|mut s| {
        if let Some(path) = certificate {
            s.handle(&Request::SetCertificate {
                path: path.to_path_buf(),
            })
            .map_err(|e| format!("--certificate: {e}"))?;
        }
        Ok(s)
    });
    let mut s = match session {
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
        let line = match read_bounded_line(&mut input, &mut buf) {
            Ok(l) => l,
            Err(e) => {
                eprintln!("error: reading stdin: {e}");
                return ExitCode::from(2);
            }
        };
        let resp = match line {
            Line::End => return ExitCode::SUCCESS,
            Line::TooLong => Response::error(&OracleError::Malformed(format!(
                "line longer than 1 MiB ({MAX_LINE} bytes): skipped"
            ))),
            Line::Text => match std::str::from_utf8(&buf) {
                Ok(line) if line.trim().is_empty() => continue,
                Ok(line) => s.handle_line(line),
                Err(e) => Response::error(&OracleError::Malformed(format!(
                    "line is not valid UTF-8 (byte {} of the line)",
                    e.valid_up_to()
                ))),
            },
        };
        let text = serde_json::to_string(&resp).unwrap_or_else(|_| "{\"ok\":false}".into());
        if writeln!(out, "{text}").and_then(|_| out.flush()).is_err() {
            return ExitCode::SUCCESS; // reader went away
        }
    }
}

/// What [`read_bounded_line`] read.
#[derive(Debug, PartialEq, Eq)]
pub(super) enum Line {
    /// End of input.
    End,
    /// A line of at most [`MAX_LINE`] bytes, in the buffer (newline included if present).
    Text,
    /// A line longer than [`MAX_LINE`]: its bytes were skipped, the buffer is empty.
    TooLong,
}

/// Read one line of at most [`MAX_LINE`] bytes into `buf`; a longer one is consumed chunk by
/// chunk without being stored (memory stays bounded whatever its length).
pub(super) fn read_bounded_line(
    input: &mut impl BufRead,
    buf: &mut Vec<u8>,
) -> std::io::Result<Line> {
    buf.clear();
    let n = Read::by_ref(input).take(MAX_LINE).read_until(b'\n', buf)?;
    if n == 0 {
        return Ok(Line::End);
    }
    if buf.last() == Some(&b'\n') || (n as u64) < MAX_LINE {
        return Ok(Line::Text);
    }
    // Over-long: skip to the end of the line in the reader's own chunks.
    buf.clear();
    loop {
        let chunk = input.fill_buf()?;
        if chunk.is_empty() {
            return Ok(Line::TooLong);
        }
        match chunk.iter().position(|&b| b == b'\n') {
            Some(i) => {
                input.consume(i + 1);
                return Ok(Line::TooLong);
            }
            None => {
                let len = chunk.len();
                input.consume(len);
            }
        }
    }
}

/// `ppm diff --mesh M TABLE`: compare a JSON-lines table of answers against the reference.
/// Exit status 0 within tolerance, 1 outside (or items not compared), 2 on a usage error.
pub(super) fn run_diff(mesh: &Path, table: &Path, a: &TableArgs) -> ExitCode {
    let (tolerance, worst, json) = (a.tolerance, a.worst, a.json);
    if tolerance.is_nan() || tolerance < 0.0 {
        eprintln!("error: --tolerance must be a non-negative number");
        return ExitCode::from(2);
    }
    let mut s = match session(Some(mesh), a.bits, &a.profile, &a.sprime) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    // The reference construction is fixed here, on the command line: a table line cannot
    // change it (SPEC R-diff-two-sided).
    if let Err(e) = set_construction(&mut s, a.construction, a.kappa) {
        eprintln!("error: {e}");
        return ExitCode::from(2);
    }
    let text = match crate::oracle::read_text_table(table) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: {}: {e}", table.display());
            return ExitCode::from(2);
        }
    };
    let r = diff_table(&mut s, &text, tolerance, worst);
    if !json {
        match a.construction {
            Construction::Vertex => {}
            Construction::SigmaV => println!(
                "reference construction of the eval lines: {} (SPEC SV-D13), κ = {}",
                a.construction.name(),
                a.kappa.unwrap_or(crate::surface::sigma_v::DEFAULT_KAPPA)
            ),
            Construction::ManifoldSpline => println!(
                "reference construction of the eval lines: {} (Secs. 5.5–5.6; it has no MPFR evaluation, so its eval lines are refused)",
                a.construction.name()
            ),
        }
    }
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

/// The `ppm diff TABLE` options for a JSON-lines table (see `crate::cli`).
pub(super) struct TableArgs {
    /// MPFR precision of the reference.
    pub bits: u32,
    /// Largest accepted deviation.
    pub tolerance: f64,
    /// How many worst items to list.
    pub worst: usize,
    /// JSON output.
    pub json: bool,
    /// Chapter 5 profile of the reference.
    pub profile: String,
    /// S′ of the reference: `pn` | `loop`.
    pub sprime: String,
    /// Reference construction of the eval lines: `vertex` | `sigma-v`.
    pub construction: Construction,
    /// κ of the (σ, v) construction (`None`: its default).
    pub kappa: Option<f64>,
}

/// The `ppm diff --surface` options (see `crate::cli`).
pub(super) struct SurfaceArgs {
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
    /// Reference construction: `vertex` | `sigma-v`.
    pub construction: Construction,
    /// κ of the (σ, v) construction (`None`: its default).
    pub kappa: Option<f64>,
    /// S′ of the reference: `pn` | `loop`.
    pub sprime: String,
}

/// `ppm diff --surface OTHER --mesh M [--level N]`: compare a sampled surface against the
/// reference sampling (Sec. 6.2). Exit status 0 within tolerance, 1 outside, 2 on a usage
/// error (unreadable files, unknown level or option).
pub(crate) fn run_diff_surface(mesh: &Path, surface: &Path, a: &SurfaceArgs) -> ExitCode {
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
    let sigma_v = a.construction != Construction::Vertex || a.kappa.is_some();
    if sigma_v && (a.profile != "paper" || a.sprime != "pn") {
        return fail(format!(
            "--construction {}: its reference has S′ = PN triangles and no Chapter 5 profile; --profile {} / --sprime {} do not apply",
            a.construction.name(), a.profile, a.sprime
        ));
    }
    let mut s = match session(Some(mesh), a.bits, &a.profile, &a.sprime) {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    if let Err(e) = set_construction(&mut s, a.construction, a.kappa) {
        return fail(e);
    }
    let other = match read_mesh(surface, &ReadOptions::default()) {
        Ok(m) => m,
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
    let reference = match s.reference() {
        Ok(p) => p,
        Err(e) => return fail(e.to_string()),
    };
    let r = match diff_surface(reference, &other.positions, Some(&other.faces), &opts) {
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
