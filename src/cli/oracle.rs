//! `ppm oracle` (JSON-lines protocol on stdin/stdout) and `ppm diff`.

use crate::oracle::diff::{diff_table, render};
use crate::oracle::{Request, Session};
use std::io::{BufRead, Read, Write};
use std::path::Path;
use std::process::ExitCode;

/// Longest accepted request line (bounded memory per request).
const MAX_LINE: u64 = 1 << 20;

fn session(mesh: Option<&Path>, bits: u32) -> Result<Session, String> {
    let mut s = Session::new();
    s.handle(&Request::SetPrecision { bits })
        .map_err(|e| e.to_string())?;
    if let Some(m) = mesh {
        s.handle(&Request::Load {
            path: m.to_path_buf(),
        })
        .map_err(|e| e.to_string())?;
    }
    Ok(s)
}

pub fn run_oracle(mesh: Option<&Path>, bits: u32) -> ExitCode {
    let mut s = match session(mesh, bits) {
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

pub fn run_diff(
    mesh: &Path,
    table: &Path,
    bits: u32,
    tolerance: f64,
    worst: usize,
    json: bool,
) -> ExitCode {
    let mut s = match session(Some(mesh), bits) {
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
