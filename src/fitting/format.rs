//! The fitted-surface file (docs/fit-format.md): a versioned text file holding the base mesh,
//! the construction's parameters, every control point, and the parameters of the vertices of
//! S_T. Numbers are written in Rust's shortest round-trip form, so a file reads back
//! bit-exactly (SPEC `AF-format-roundtrip`). One writer, one reader.

use super::fit::Fit;
use super::fitted::SurfaceParam;
use crate::mesh::raw::RawMesh;
use crate::mesh::validate::validate;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::surface::sigma_v::{Corner, CornerId, SigmaVPps};
use std::fmt::Write as _;
use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};

/// First line of every fitted-surface file.
pub const MAGIC: &str = "ppm-fit";
/// The format version this build writes and reads.
pub const VERSION: u32 = 1;

/// Why a fitted-surface file could not be read or written.
#[derive(Debug, thiserror::Error)]
pub enum FitFormatError {
    /// I/O.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The error.
        source: std::io::Error,
    },
    /// A malformed line.
    #[error("{}:{line}: {msg}", path.display())]
    Parse {
        /// The file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// What is wrong.
        msg: String,
    },
    /// The base mesh is not a simplicial surface, or the control points do not fit it.
    #[error("{}: {msg}", path.display())]
    Invalid {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        msg: String,
    },
}

/// A fitted surface read back.
pub struct FitFile {
    /// ε it was fitted to.
    pub epsilon: f64,
    /// Vertices of S_T.
    pub fine_vertices: usize,
    /// The base mesh.
    pub k: SimplicialSurface,
    /// Fine id of each base vertex.
    pub fine_of: Vec<u32>,
    /// The PPS.
    pub pps: SigmaVPps,
    /// The parameters of the vertices of S_T.
    pub params: Vec<SurfaceParam>,
}

/// Write `fit` to `path`.
pub fn write_fit(path: &Path, fit: &Fit) -> Result<(), FitFormatError> {
    let io = |source| FitFormatError::Io {
        path: path.to_path_buf(),
        source,
    };
    let k = &fit.surface.k;
    let pps = &fit.fitted.pps;
    let mut s = String::new();
    let _ = writeln!(s, "{MAGIC} {VERSION}");
    let eps = fit.errors.len();
    let _ = writeln!(s, "epsilon {:?}", fit.epsilon);
    let _ = writeln!(s, "kappa {:?}", pps.gluing.kappa);
    let _ = writeln!(s, "patch_degree {}", pps.degree);
    let _ = writeln!(s, "fine_vertices {eps}");
    let _ = writeln!(s, "base_vertices {}", k.num_vertices());
    let _ = writeln!(s, "base_faces {}", k.num_faces());
    for (i, &f) in fit.surface.fine_of.iter().enumerate() {
        let p = k.position(VertexId(i as u32));
        let _ = writeln!(s, "v {:?} {:?} {:?} {f}", p[0], p[1], p[2]);
    }
    for f in k.faces() {
        let c = k.face(f);
        let _ = writeln!(s, "f {} {} {}", c[0].0, c[1].0, c[2].0);
    }
    for id in pps.gluing.ids() {
        let Ok(c) = pps.gluing.corner(id) else {
            continue;
        };
        let _ = writeln!(s, "c {} {}", c.v.0, c.k);
        for p in pps.patch(id) {
            let _ = writeln!(s, "p {:?} {:?} {:?}", p[0], p[1], p[2]);
        }
    }
    for (f, b) in &fit.params {
        let _ = writeln!(s, "x {} {:?} {:?} {:?}", f.0, b[0], b[1], b[2]);
    }
    let mut file = std::fs::File::create(path).map_err(io)?;
    file.write_all(s.as_bytes()).map_err(io)
}

/// Read a fitted-surface file.
pub fn read_fit(path: &Path) -> Result<FitFile, FitFormatError> {
    let file = std::fs::File::open(path).map_err(|source| FitFormatError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let mut lines = BufReader::new(file).lines().enumerate();
    let perr = |line: usize, msg: String| FitFormatError::Parse {
        path: path.to_path_buf(),
        line,
        msg,
    };
    let mut next = |want: &str| -> Result<(usize, Vec<String>), FitFormatError> {
        match lines.next() {
            Some((i, Ok(l))) => {
                let w: Vec<String> = l.split_whitespace().map(str::to_string).collect();
                if w.first().map(String::as_str) != Some(want) {
                    return Err(perr(i + 1, format!("expected `{want} …`, found {l:?}")));
                }
                Ok((i + 1, w))
            }
            Some((i, Err(e))) => Err(perr(i + 1, e.to_string())),
            None => Err(perr(0, format!("truncated: expected `{want} …`"))),
        }
    };
    fn num<T: std::str::FromStr>(
        w: &[String],
        i: usize,
        line: usize,
        p: &Path,
    ) -> Result<T, FitFormatError> {
        let s = w.get(i).ok_or_else(|| FitFormatError::Parse {
            path: p.to_path_buf(),
            line,
            msg: format!("missing field {i}"),
        })?;
        s.parse().map_err(|_| FitFormatError::Parse {
            path: p.to_path_buf(),
            line,
            msg: format!("field {i}: {s:?} is not a number of the expected kind"),
        })
    }
    let num3 = |w: &[String], i: usize, l: usize| -> Result<[f64; 3], FitFormatError> {
        Ok([
            num(w, i, l, path)?,
            num(w, i + 1, l, path)?,
            num(w, i + 2, l, path)?,
        ])
    };
    let (l, w) = next(MAGIC)?;
    let ver: u32 = num(&w, 1, l, path)?;
    if ver != VERSION {
        return Err(perr(
            l,
            format!("version {ver}; this build reads version {VERSION}"),
        ));
    }
    let (l, w) = next("epsilon")?;
    let epsilon: f64 = num(&w, 1, l, path)?;
    let (l, w) = next("kappa")?;
    let kappa: f64 = num(&w, 1, l, path)?;
    let (l, w) = next("patch_degree")?;
    let degree: usize = num(&w, 1, l, path)?;
    if !(1..=crate::surface::sigma_v::patch::MAX_PATCH_DEGREE).contains(&degree) {
        return Err(perr(l, format!("patch degree {degree} outside 1..=15")));
    }
    let (l, w) = next("fine_vertices")?;
    let nfine: usize = num(&w, 1, l, path)?;
    let (l, w) = next("base_vertices")?;
    let nv: usize = num(&w, 1, l, path)?;
    let (l, w) = next("base_faces")?;
    let nf: usize = num(&w, 1, l, path)?;
    // Counts bound what is allocated: a base mesh has 2(n_v + 2g − 2) faces, and every count is
    // checked against the lines actually present, so a lying header cannot reserve memory.
    let mut pos = Vec::new();
    let mut fine_of = Vec::new();
    for _ in 0..nv {
        let (l, w) = next("v")?;
        pos.push(num3(&w, 1, l)?);
        let f: u32 = num(&w, 4, l, path)?;
        if f as usize >= nfine {
            return Err(perr(l, format!("fine id {f} ≥ fine_vertices {nfine}")));
        }
        fine_of.push(f);
    }
    let mut faces = Vec::new();
    for _ in 0..nf {
        let (l, w) = next("f")?;
        faces.push([
            num(&w, 1, l, path)?,
            num(&w, 2, l, path)?,
            num(&w, 3, l, path)?,
        ]);
    }
    let invalid = |msg: String| FitFormatError::Invalid {
        path: path.to_path_buf(),
        msg,
    };
    let raw = RawMesh::from_arrays(pos, faces);
    let k = validate(&raw)
        .surface
        .ok_or_else(|| invalid("the base mesh is not a simplicial surface (Sec. 3.1)".into()))?;
    let mut pps =
        SigmaVPps::unfitted(&k, kappa, degree, super::fitted::FIT_TARGET).map_err(|e| {
            invalid(format!(
                "the (sigma, v) construction refused the base mesh: {e}"
            ))
        })?;
    let ids: Vec<CornerId> = pps.gluing.ids().collect();
    for id in ids {
        let (l, w) = next("c")?;
        let v: u32 = num(&w, 1, l, path)?;
        let kk: u32 = num(&w, 2, l, path)?;
        let want = pps.gluing.corner(id).ok();
        if want
            != Some(Corner {
                v: VertexId(v),
                k: kk,
            })
        {
            return Err(perr(
                l,
                format!(
                    "corner {} is {want:?} in the base mesh, not ({v}, {kk})",
                    id.0
                ),
            ));
        }
        let n = pps.patch(id).len();
        let mut cps = Vec::with_capacity(n);
        for _ in 0..n {
            let (l, w) = next("p")?;
            cps.push(num3(&w, 1, l)?);
        }
        pps.patch_mut(id).copy_from_slice(&cps);
    }
    let mut params = Vec::new();
    for _ in 0..nfine {
        let (l, w) = next("x")?;
        let f: u32 = num(&w, 1, l, path)?;
        if f as usize >= k.num_faces() {
            return Err(perr(l, format!("face {f} ≥ base_faces {}", k.num_faces())));
        }
        params.push((FaceId(f), num3(&w, 2, l)?));
    }
    if let Some((i, _)) = lines.next() {
        return Err(perr(
            i + 1,
            "trailing lines after the last parameter".into(),
        ));
    }
    Ok(FitFile {
        epsilon,
        fine_vertices: nfine,
        k,
        fine_of,
        pps,
        params,
    })
}

/// Does `path` start with the fitted-surface magic?
pub fn is_fit_file(path: &Path) -> bool {
    let Ok(f) = std::fs::File::open(path) else {
        return false;
    };
    let mut first = String::new();
    BufReader::new(f).read_line(&mut first).is_ok() && first.starts_with(MAGIC)
}
