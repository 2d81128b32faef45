//! The `.tets` file of a tetrahedral complex (documented in `docs/sdiff-3d.md`): one record per
//! line, `#` starts a comment, blank lines are ignored.
//!
//! ```text
//! tets                 # the first record: the magic word
//! v 0 0 0              # a vertex x y z; ids 0, 1, 2, … in order of appearance
//! v 1 0 0
//! v 0 1 0
//! v 0 0 1
//! t 0 1 2 3            # a tetrahedron by 0-based vertex ids, positively oriented:
//!                      # det[v1 − v0, v2 − v0, v3 − v0] > 0
//! ```
//!
//! Read like the mesh formats (SPEC `SD-K(3-D)`): the line splitter, the count bounds
//! ([`Limits`]: vertices, and tetrahedra under `max_faces`, the top-dimensional cells) and the
//! typed [`MeshError`]s naming file and line are those of `mesh::io`, so a `.tets` file and an
//! OFF file fail in the same words. `mesh::io` has no bound on the file size; this reader keeps
//! its own ([`MAX_FILE_BYTES`]), because nothing else bounds what `std::fs::read` allocates.

use crate::mesh::io::text::Lines;
use crate::mesh::io::{parse_coord, Ctx, Limits, ReadOptions};
use crate::mesh::{Location, MeshError};
use std::io::Read;
use std::path::{Path, PathBuf};

/// Largest file accepted.
pub const MAX_FILE_BYTES: u64 = 64 << 20;

/// A tetrahedral complex as read, before validation.
#[derive(Debug, Clone, Default)]
pub struct RawTets {
    /// The file (names it in messages).
    pub path: PathBuf,
    /// Vertex positions as read.
    pub positions: Vec<[f64; 3]>,
    /// Source line of each vertex (1-based).
    pub vertex_lines: Vec<usize>,
    /// Tetrahedra as read (vertex ids, unchecked).
    pub tets: Vec<[u32; 4]>,
    /// Source line of each tetrahedron (1-based).
    pub tet_lines: Vec<usize>,
}

impl RawTets {
    /// "FILE:LINE vertex V".
    pub(crate) fn describe_vertex(&self, v: usize) -> String {
        let line = self.vertex_lines.get(v).copied().unwrap_or(0);
        format!("{}:{line}: vertex {v}", self.path.display())
    }
    /// "FILE:LINE tetrahedron T".
    pub(crate) fn describe_tet(&self, t: usize) -> String {
        let line = self.tet_lines.get(t).copied().unwrap_or(0);
        format!("{}:{line}: tetrahedron {t}", self.path.display())
    }
}

/// Reads a `.tets` file under the default [`Limits`] (at most [`MAX_FILE_BYTES`] are read).
pub fn read(path: &Path) -> Result<RawTets, MeshError> {
    let io = |source| MeshError::Io {
        path: path.into(),
        source,
    };
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .map_err(io)?
        .take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    let opts = ReadOptions::default();
    let ctx = Ctx { path, opts: &opts };
    ctx.check_limit(Location::File, "byte", bytes.len() as u64, MAX_FILE_BYTES)?;
    parse_bytes(&bytes, &ctx)
}

/// Parses the text of a `.tets` file under the default [`Limits`] (`path` only names it in
/// errors).
pub fn parse(text: &str, path: &Path) -> Result<RawTets, MeshError> {
    parse_with(text, path, Limits::default())
}

/// Parses the text of a `.tets` file under `limits`.
pub fn parse_with(text: &str, path: &Path, limits: Limits) -> Result<RawTets, MeshError> {
    let opts = ReadOptions {
        limits,
        ..ReadOptions::default()
    };
    parse_bytes(text.as_bytes(), &Ctx { path, opts: &opts })
}

fn parse_bytes(bytes: &[u8], ctx: &Ctx<'_>) -> Result<RawTets, MeshError> {
    let mut raw = RawTets {
        path: ctx.path.into(),
        ..RawTets::default()
    };
    let lim = &ctx.opts.limits;
    let mut lines = Lines::new(bytes, 1);
    let mut seen_magic = false;
    while let Some((no, line)) = lines.next_content() {
        let at = Location::Line(no);
        let body = line.map_err(|_| ctx.encoding(at.clone()))?;
        let mut words = body.split_whitespace();
        let Some(tag) = words.next() else {
            continue;
        };
        let rest: Vec<&str> = words.collect();
        if !seen_magic {
            if tag != "tets" || !rest.is_empty() {
                let found: String = body.trim().chars().take(32).collect();
                return Err(ctx.parse(at, format!("expected the header `tets`, found `{found}`")));
            }
            seen_magic = true;
            continue;
        }
        // Line numbers come from a u64 counter over a buffer that fits in memory.
        let line_no = usize::try_from(no).unwrap_or(usize::MAX);
        match tag {
            "v" => {
                if rest.len() != 3 {
                    let msg = format!("`v` needs 3 coordinates, found {}", rest.len());
                    return Err(ctx.parse(at, msg));
                }
                let count = raw.positions.len() as u64 + 1;
                ctx.check_limit(at.clone(), "vertex", count, lim.max_vertices)?;
                let mut p = [0.0; 3];
                for (c, w) in rest.iter().enumerate() {
                    p[c] = parse_coord(w)
                        .ok_or_else(|| ctx.parse(at.clone(), format!("`{w}` is not a number")))?;
                }
                raw.positions.push(p);
                raw.vertex_lines.push(line_no);
            }
            "t" => {
                if rest.len() != 4 {
                    let msg = format!("`t` needs 4 vertex ids, found {}", rest.len());
                    return Err(ctx.parse(at, msg));
                }
                let count = raw.tets.len() as u64 + 1;
                ctx.check_limit(at.clone(), "tetrahedron", count, lim.max_faces)?;
                let mut t = [0u32; 4];
                for (c, w) in rest.iter().enumerate() {
                    t[c] = w.parse::<u32>().map_err(|_| {
                        let msg = format!("`{w}` is not a vertex id (0 ≤ id < 2³²)");
                        ctx.parse(at.clone(), msg)
                    })?;
                }
                raw.tets.push(t);
                raw.tet_lines.push(line_no);
            }
            other => {
                let other: String = other.chars().take(32).collect();
                return Err(ctx.parse(at, format!("unknown record `{other}` (v or t)")));
            }
        }
    }
    if !seen_magic {
        return Err(ctx.parse(Location::Line(1), "no header `tets`"));
    }
    Ok(raw)
}
