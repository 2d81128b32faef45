//! Wavefront OBJ reader (polygonal geometry subset of the OBJ specification,
//! <https://paulbourke.net/dataformats/obj/>).
//!
//! Supported subset:
//! * `v x y z [w]` (extra columns such as `w` or vertex colours are ignored);
//! * `f` (and the old `fo`) with corners `a`, `a/b`, `a//c` or `a/b/c`; only the vertex index
//!   `a` is used. Indices are 1-based; negative indices are relative to the vertices read so
//!   far (`-1` is the last one);
//! * ignored statements: `vt`, `vn`, `vp`, `l`, `p`, `o`, `g`, `s`, `mg`, `mtllib`,
//!   `usemtl`, `usemap`, `maplib`, `bevel`, `c_interp`, `d_interp`, `lod`, `shadow_obj`,
//!   `trace_obj`; `#` comments and blank lines.
//!
//! Not supported (parse error naming the line): free-form geometry (`cstype`, `curv`, `surf`,
//! …), `call`/`csh`, line continuation with `\`, and any unknown statement.
//! Index 0, a relative index before the first vertex, an index beyond 2^32 and a non-integer
//! index are parse errors; a positive index beyond the vertex count is not (the validator
//! reports it).

use super::context::{parse_coord, Ctx};
use super::polygon::FaceSink;
use super::text::Lines;
use crate::mesh::error::{Location, MeshError};
use crate::mesh::raw::{MeshFormat, RawMesh};

const IGNORED: &[&str] = &[
    "vt",
    "vn",
    "vp",
    "l",
    "p",
    "o",
    "g",
    "s",
    "mg",
    "mtllib",
    "usemtl",
    "usemap",
    "maplib",
    "bevel",
    "c_interp",
    "d_interp",
    "lod",
    "shadow_obj",
    "trace_obj",
];

const FREE_FORM: &[&str] = &[
    "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
    "end", "con", "ctech", "stech", "call", "csh",
];

/// Resolves one face corner token to a 0-based vertex index.
fn parse_corner(ctx: &Ctx<'_>, line: u64, tok: &str, nverts: u64) -> Result<u32, MeshError> {
    let at = || Location::Line(line);
    let v = tok.split('/').next().unwrap_or_default();
    let i: i64 = v.parse().map_err(|_| {
        ctx.parse(
            at(),
            format!("invalid vertex index '{v}' in face corner '{tok}'"),
        )
    })?;
    let zero_based = if i > 0 {
        i.unsigned_abs() - 1
    } else if i < 0 {
        // -1 is the last vertex read so far: nverts − |i|, which exists only when |i| ≤ nverts.
        nverts.checked_sub(i.unsigned_abs()).ok_or_else(|| {
            ctx.parse(
                at(),
                format!("relative vertex index {i} refers before the first vertex ({nverts} vertices so far)"),
            )
        })?
    } else {
        return Err(ctx.parse(at(), "vertex index 0 (OBJ indices are 1-based)"));
    };
    u32::try_from(zero_based).map_err(|_| ctx.parse(at(), format!("vertex index {i} exceeds 2^32")))
}

pub(crate) fn read(bytes: &[u8], ctx: &Ctx<'_>) -> Result<RawMesh, MeshError> {
    let mut lines = Lines::new(bytes, 1);
    let mut positions: Vec<[f64; 3]> = Vec::new();
    let mut vertex_origin = Vec::new();
    let mut sink = FaceSink::new(ctx.opts.triangulate, 0);
    let mut idx: Vec<u32> = Vec::new();
    let lim = &ctx.opts.limits;
    let mut nfaces: u64 = 0;
    while let Some((no, line)) = lines.next_content() {
        let s = line.map_err(|_| ctx.encoding(Location::Line(no)))?;
        let mut t = s.split_ascii_whitespace();
        let Some(kw) = t.next() else { continue };
        match kw {
            "v" => {
                ctx.check_limit(
                    Location::Line(no),
                    "vertex",
                    positions.len() as u64 + 1,
                    lim.max_vertices,
                )?;
                let mut p = [0.0; 3];
                for (axis, c) in p.iter_mut().enumerate() {
                    let tok = t.next().ok_or_else(|| {
                        ctx.parse(
                            Location::Line(no),
                            format!("expected 3 coordinates, found {axis}"),
                        )
                    })?;
                    *c = parse_coord(tok).ok_or_else(|| {
                        ctx.parse(Location::Line(no), format!("invalid coordinate '{tok}'"))
                    })?;
                }
                positions.push(p);
                vertex_origin.push(no);
            }
            "f" | "fo" => {
                nfaces += 1;
                ctx.check_limit(Location::Line(no), "face", nfaces, lim.max_faces)?;
                idx.clear();
                let nv = positions.len() as u64;
                for tok in t {
                    idx.push(parse_corner(ctx, no, tok, nv)?);
                }
                sink.push(ctx, &idx, no, Location::Line(no))?;
            }
            k if IGNORED.contains(&k) => {}
            k if FREE_FORM.contains(&k) => {
                return Err(ctx.parse(
                    Location::Line(no),
                    format!("unsupported OBJ statement '{k}' (free-form geometry)"),
                ));
            }
            k => {
                let k: String = k.chars().take(32).collect();
                return Err(ctx.parse(Location::Line(no), format!("unknown OBJ statement '{k}'")));
            }
        }
    }
    let faces = sink.finish(ctx, &positions, true)?;
    Ok(RawMesh {
        positions,
        faces: faces.faces,
        face_origin: faces.origins,
        vertex_origin,
        source: None,
        format: Some(MeshFormat::Obj),
        triangulated_polygons: faces.triangulated_polygons,
        origin_is_line: true,
        vertex_scalars: Vec::new(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::io::ReadOptions;
    use std::path::Path;

    fn read_str(text: &str) -> Result<RawMesh, MeshError> {
        let opts = ReadOptions::default();
        let ctx = Ctx {
            path: Path::new("t.obj"),
            opts: &opts,
        };
        read(text.as_bytes(), &ctx)
    }

    #[test]
    fn relative_indices_count_back_from_the_last_vertex_read() {
        let m = read_str("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf -4 -3 -2\nf 2 -1 -3\n")
            .expect("valid relative indices");
        assert_eq!(m.faces, vec![[0, 1, 2], [1, 3, 1]]);
        for bad in ["-5", "-9223372036854775808", "0"] {
            let e = read_str(&format!(
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 {bad}\n"
            ))
            .expect_err(bad);
            assert!(matches!(e, MeshError::Parse { .. }), "{bad}: {e}");
            assert!(e.to_string().contains("line 5"), "{bad}: {e}");
        }
    }
}
