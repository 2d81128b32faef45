//! OFF reader (Geomview "Object File Format",
//! <http://www.geomview.org/docs/html/OFF.html>).
//!
//! Supported subset:
//! * header keyword `OFF`, optionally prefixed `ST`, `C`, `N` (in that order, e.g. `COFF`,
//!   `NOFF`, `CNOFF`): the extra per-vertex columns are ignored. `4OFF`, `nOFF` and
//!   `OFF BINARY` are rejected with a parse error.
//! * the counts `V F [E]` on the next content line or on the header line itself; `E` is
//!   ignored;
//! * one vertex per line: `x y z [anything…]` (columns after the third are ignored);
//! * one face per line: `n i0 … i(n-1) [colour…]` with 0-based indices;
//! * `#` comments anywhere (to the end of the line) and blank lines.
//!
//! Fewer vertices or faces than declared is [`MeshError::Truncated`]; any content after the
//! declared faces is a parse error.

use super::context::{capped_capacity, parse_coord, Ctx};
use super::polygon::FaceSink;
use super::text::Lines;
use crate::mesh::error::{Location, MeshError};
use crate::mesh::raw::{MeshFormat, RawMesh};

/// Whether the first content line of `bytes` starts with an OFF header keyword.
pub(crate) fn sniff(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(4096)];
    let mut lines = Lines::new(head, 1);
    match lines.next_content() {
        Some((_, Ok(s))) => s
            .split_ascii_whitespace()
            .next()
            .is_some_and(|k| k.ends_with("OFF")),
        _ => false,
    }
}

/// `ST`, `C`, `N` prefixes (in that order) followed by `OFF`.
fn is_off_keyword(k: &str) -> bool {
    let k = k.strip_prefix("ST").unwrap_or(k);
    let k = k.strip_prefix('C').unwrap_or(k);
    let k = k.strip_prefix('N').unwrap_or(k);
    k == "OFF"
}

fn parse_count(ctx: &Ctx<'_>, line: u64, tok: Option<&str>, what: &str) -> Result<u64, MeshError> {
    let tok =
        tok.ok_or_else(|| ctx.parse(Location::Line(line), format!("missing {what} count")))?;
    tok.parse::<u64>().map_err(|_| {
        ctx.parse(
            Location::Line(line),
            format!("invalid {what} count '{tok}' (expected a non-negative integer)"),
        )
    })
}

/// Parses a 0-based vertex index token.
pub(crate) fn parse_index(ctx: &Ctx<'_>, line: u64, tok: &str) -> Result<u32, MeshError> {
    match tok.parse::<u64>() {
        Ok(v) => u32::try_from(v).map_err(|_| {
            ctx.parse(
                Location::Line(line),
                format!("vertex index {v} exceeds 2^32-1"),
            )
        }),
        Err(_) if tok.parse::<i64>().is_ok() => {
            Err(ctx.parse(Location::Line(line), format!("negative vertex index {tok}")))
        }
        Err(_) => Err(ctx.parse(
            Location::Line(line),
            format!("invalid vertex index '{tok}'"),
        )),
    }
}

/// The next content line, or a typed error (encoding, truncation).
fn next<'a>(
    ctx: &Ctx<'_>,
    lines: &mut Lines<'a>,
    what: impl FnOnce() -> String,
) -> Result<(u64, &'a str), MeshError> {
    match lines.next_content() {
        Some((no, Ok(s))) => Ok((no, s)),
        Some((no, Err(_))) => Err(ctx.encoding(Location::Line(no))),
        None => Err(ctx.truncated(Location::Line(lines.line_no()), what())),
    }
}

pub(crate) fn read(bytes: &[u8], ctx: &Ctx<'_>) -> Result<RawMesh, MeshError> {
    let mut lines = Lines::new(bytes, 1);
    let (hline, header) = match lines.next_content() {
        None => return Ok(RawMesh::default()),
        Some((no, Err(_))) => return Err(ctx.encoding(Location::Line(no))),
        Some((no, Ok(s))) => (no, s),
    };
    let mut toks = header.split_ascii_whitespace();
    let kw = toks.next().unwrap_or_default();
    if !is_off_keyword(kw) {
        let msg = if kw.ends_with("OFF") {
            format!("unsupported OFF variant '{kw}' (only [ST][C][N]OFF in 3D)")
        } else {
            format!("expected an OFF header, found '{kw}'")
        };
        return Err(ctx.parse(Location::Line(hline), msg));
    }
    let mut rest: Vec<&str> = toks.collect();
    if rest.first() == Some(&"BINARY") {
        return Err(ctx.parse(Location::Line(hline), "binary OFF is not supported"));
    }
    let cline = if rest.is_empty() {
        let (no, s) = next(ctx, &mut lines, || "missing the 'V F E' counts line".into())?;
        rest = s.split_ascii_whitespace().collect();
        no
    } else {
        hline
    };
    if rest.len() > 3 {
        return Err(ctx.parse(
            Location::Line(cline),
            "expected the counts 'V F E', found more than 3 values",
        ));
    }
    let nv = parse_count(ctx, cline, rest.first().copied(), "vertex")?;
    let nf = parse_count(ctx, cline, rest.get(1).copied(), "face")?;
    if let Some(e) = rest.get(2) {
        parse_count(ctx, cline, Some(e), "edge")?;
    }
    let lim = &ctx.opts.limits;
    ctx.check_limit(Location::Line(cline), "vertex", nv, lim.max_vertices)?;
    ctx.check_limit(Location::Line(cline), "face", nf, lim.max_faces)?;

    let remaining = lines.remaining().len();
    let vcap = capped_capacity(nv, remaining, 6);
    let mut positions = Vec::with_capacity(vcap);
    let mut vertex_origin = Vec::with_capacity(vcap);
    for k in 0..nv {
        let (no, s) = next(ctx, &mut lines, || {
            format!("the file ends after {k} of {nv} declared vertices")
        })?;
        let mut t = s.split_ascii_whitespace();
        let mut p = [0.0; 3];
        for (axis, c) in p.iter_mut().enumerate() {
            let tok = t.next().ok_or_else(|| {
                ctx.parse(
                    Location::Line(no),
                    format!("vertex {k}: expected 3 coordinates, found {axis}"),
                )
            })?;
            *c = parse_coord(tok).ok_or_else(|| {
                ctx.parse(
                    Location::Line(no),
                    format!("vertex {k}: invalid coordinate '{tok}'"),
                )
            })?;
        }
        positions.push(p);
        vertex_origin.push(no);
    }

    let remaining = lines.remaining().len();
    let mut sink = FaceSink::new(ctx.opts.triangulate, capped_capacity(nf, remaining, 8));
    let mut idx: Vec<u32> = Vec::new();
    let mut toks: Vec<&str> = Vec::new();
    for k in 0..nf {
        let (no, s) = next(ctx, &mut lines, || {
            format!("the file ends after {k} of {nf} declared faces")
        })?;
        toks.clear();
        toks.extend(s.split_ascii_whitespace());
        let (first, rest) = toks
            .split_first()
            .ok_or_else(|| ctx.parse(Location::Line(no), format!("face {k}: empty face line")))?;
        let n = first.parse::<u64>().map_err(|_| {
            ctx.parse(
                Location::Line(no),
                format!("face {k}: invalid corner count '{first}'"),
            )
        })?;
        if n > rest.len() as u64 {
            return Err(ctx.parse(
                Location::Line(no),
                format!(
                    "face {k}: declares {n} corners but the line has only {} more values",
                    rest.len()
                ),
            ));
        }
        idx.clear();
        for tok in rest.iter().take(n as usize) {
            idx.push(parse_index(ctx, no, tok)?);
        }
        sink.push(ctx, &idx, no, Location::Line(no))?;
    }
    if let Some((no, line)) = lines.next_content() {
        if line.is_err() {
            return Err(ctx.encoding(Location::Line(no)));
        }
        return Err(ctx.parse(
            Location::Line(no),
            format!("unexpected data after the {nf} declared faces"),
        ));
    }
    let faces = sink.finish(ctx, &positions, true)?;
    Ok(RawMesh {
        positions,
        faces: faces.faces,
        face_origin: faces.origins,
        vertex_origin,
        source: None,
        format: Some(MeshFormat::Off),
        triangulated_polygons: faces.triangulated_polygons,
        origin_is_line: true,
        vertex_scalars: Vec::new(),
    })
}
