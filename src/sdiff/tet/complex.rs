//! Tetrahedral complexes *with boundary* (Mello–Velho Sec. 1: K a simplicial complex in ℝ^m,
//! here m = 3), read from a small text format and validated exactly: coordinates are the
//! stored doubles taken as exact rationals (SPEC `SD-K(3-D)`).
//!
//! The file format and its reader are in [`super::file`].
//!
//! The validator checks, each as a [`CheckResult`] naming the file, line and element: vertex
//! indices in range and distinct, purity (every vertex in some tetrahedron), positive
//! orientation (exact sign), every triangle a face of at most two tetrahedra, and no two
//! tetrahedra with intersecting interiors. The last is exact and complete: the interiors of two
//! tetrahedra A, B are disjoint iff 0 ∉ int(A − B), iff some facet normal of the Minkowski
//! difference weakly separates them; those normals are the face normals of A and B and the
//! cross products of an edge of A with an edge of B (zero products skipped). Candidate pairs
//! come from a sweep over bounding boxes, so the test is not quadratic on big inputs; sizes and
//! the number of candidate pairs are bounded (typed errors, never a panic).

use crate::report::{CheckResult, Witness};
use crate::sdiff::planar::poly::{from_f64, Q};
use num_traits::{Signed, Zero};
use serde_json::json;
use std::collections::HashMap;
use std::path::PathBuf;

use super::file::RawTets;
use crate::mesh::MeshError;

/// Most candidate pairs (overlapping bounding boxes) the exact overlap test examines.
pub const MAX_CANDIDATE_PAIRS: u64 = 20_000_000;

/// A validated tetrahedral complex (only [`validate`] makes one).
#[derive(Debug, Clone)]
pub struct TetComplex {
    /// Vertex positions, exact.
    pub points: Vec<[Q; 3]>,
    /// Vertex positions as read.
    pub points_f64: Vec<[f64; 3]>,
    /// Tetrahedra (global vertex ids), positively oriented.
    pub tets: Vec<[u32; 4]>,
}

/// Why a file is not a tetrahedral complex.
#[derive(Debug, thiserror::Error)]
pub enum TetComplexError {
    /// The file cannot be read: I/O, size and count limits, syntax (file and line named).
    #[error(transparent)]
    Read(#[from] MeshError),
    /// A coordinate is NaN or infinite.
    #[error("{vertex}: coordinate {value} is not finite")]
    NotFinite {
        /// Which vertex (file:line).
        vertex: String,
        /// The value.
        value: f64,
    },
    /// No tetrahedron.
    #[error("{path}: the complex has no tetrahedron")]
    Empty {
        /// The file.
        path: PathBuf,
    },
    /// More candidate pairs than [`MAX_CANDIDATE_PAIRS`]: the overlap test is not run.
    #[error("{path}: {pairs} pairs of tetrahedra with overlapping bounding boxes, above the limit {MAX_CANDIDATE_PAIRS}")]
    TooManyPairs {
        /// The file.
        path: PathBuf,
        /// Pairs met before giving up.
        pairs: u64,
    },
    /// The validation found offenders (the report lists them).
    #[error("the input is not a tetrahedral complex (see the report)")]
    Invalid(Vec<CheckResult>),
}

/// det\[b − a, c − a, d − a\] (six times the signed volume), exact.
pub fn orient3(a: &[Q; 3], b: &[Q; 3], c: &[Q; 3], d: &[Q; 3]) -> Q {
    crate::numeric::predicates::det3(a, b, c, d)
}

fn cross(u: &[Q; 3], v: &[Q; 3]) -> [Q; 3] {
    [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ]
}

fn dot(u: &[Q; 3], v: &[Q; 3]) -> Q {
    &u[0] * &v[0] + &u[1] * &v[1] + &u[2] * &v[2]
}

/// The four triangle faces of a tetrahedron, each a sorted vertex triple.
pub fn faces_of(t: &[u32; 4]) -> [[u32; 3]; 4] {
    std::array::from_fn(|skip| {
        let mut f = [0u32; 3];
        let mut j = 0;
        for (k, &v) in t.iter().enumerate() {
            if k != skip {
                f[j] = v;
                j += 1;
            }
        }
        f.sort_unstable();
        f
    })
}

/// Validates `raw` as a tetrahedral complex with boundary; the report lists every check.
pub fn validate(raw: &RawTets) -> Result<(TetComplex, Vec<CheckResult>), TetComplexError> {
    if raw.tets.is_empty() {
        return Err(TetComplexError::Empty {
            path: raw.path.clone(),
        });
    }
    let mut points = Vec::with_capacity(raw.positions.len());
    for (i, p) in raw.positions.iter().enumerate() {
        let mut q: [Q; 3] = Default::default();
        for (c, &x) in p.iter().enumerate() {
            q[c] = from_f64(x).ok_or_else(|| TetComplexError::NotFinite {
                vertex: raw.describe_vertex(i),
                value: x,
            })?;
        }
        points.push(q);
    }
    let nv = points.len();
    let mut report = Vec::new();

    let mut range = CheckResult::new(
        "SD-K(3-D)-indices",
        "tetrahedron vertex ids are in range and distinct",
    );
    let mut ok = Vec::new();
    for (f, t) in raw.tets.iter().enumerate() {
        range.examined += 1;
        if let Some(&v) = t.iter().find(|&&v| v as usize >= nv) {
            range.offend(|| {
                Witness::new(
                    format!(
                        "{} names vertex {v}, the file has {nv}",
                        raw.describe_tet(f)
                    ),
                    json!({"tet": f, "line": raw.tet_lines[f], "vertex": v}),
                )
            });
        } else if (0..4).any(|a| (a + 1..4).any(|b| t[a] == t[b])) {
            range.offend(|| {
                Witness::new(
                    format!("{} repeats a vertex: {t:?}", raw.describe_tet(f)),
                    json!({"tet": f, "line": raw.tet_lines[f]}),
                )
            });
        } else {
            ok.push(f);
        }
    }
    report.push(range);

    let mut pure = CheckResult::new(
        "SD-K(3-D)-pure",
        "purity: every vertex is a vertex of some tetrahedron",
    );
    let mut used = vec![false; nv];
    for &f in &ok {
        for &v in &raw.tets[f] {
            used[v as usize] = true;
        }
    }
    for (v, u) in used.iter().enumerate() {
        pure.examined += 1;
        if !u {
            pure.offend(|| {
                Witness::new(
                    format!("{} is in no tetrahedron", raw.describe_vertex(v)),
                    json!({"vertex": v, "line": raw.vertex_lines[v]}),
                )
            });
        }
    }
    report.push(pure);

    let tet = |f: usize| raw.tets[f].map(|v| &points[v as usize]);
    let mut orientation = CheckResult::new(
        "SD-K(3-D)-orientation",
        "every tetrahedron is positively oriented (exact sign)",
    );
    let mut positive = Vec::new();
    for &f in &ok {
        orientation.examined += 1;
        let p = tet(f);
        let o = orient3(p[0], p[1], p[2], p[3]);
        if o.is_positive() {
            positive.push(f);
        } else {
            let what = if o.is_zero() {
                "degenerate (coplanar)"
            } else {
                "negatively oriented"
            };
            orientation.offend(|| {
                Witness::new(
                    format!("{} is {what}", raw.describe_tet(f)),
                    json!({"tet": f, "line": raw.tet_lines[f], "six_volume": o.to_string()}),
                )
            });
        }
    }
    report.push(orientation);

    let mut facets = CheckResult::new(
        "SD-K(3-D)-faces",
        "every triangle is a face of at most two tetrahedra",
    );
    let mut by_face: HashMap<[u32; 3], Vec<usize>> = HashMap::new();
    for &f in &ok {
        for tri in faces_of(&raw.tets[f]) {
            by_face.entry(tri).or_default().push(f);
        }
    }
    let mut keys: Vec<_> = by_face.keys().copied().collect();
    keys.sort_unstable();
    for tri in keys {
        facets.examined += 1;
        let ts = &by_face[&tri];
        if ts.len() > 2 {
            let lines: Vec<usize> = ts.iter().map(|&f| raw.tet_lines[f]).collect();
            facets.offend(|| {
                Witness::new(
                    format!(
                        "{}: triangle {tri:?} is a face of {} tetrahedra {ts:?} (lines {lines:?})",
                        raw.path.display(),
                        ts.len()
                    ),
                    json!({"face": tri, "tets": ts, "lines": lines}),
                )
            });
        }
    }
    report.push(facets);

    report.push(overlap_check(raw, &points, &positive)?);

    if report.iter().any(|r| r.failed()) {
        return Err(TetComplexError::Invalid(report));
    }
    let tets = ok.iter().map(|&f| raw.tets[f]).collect();
    Ok((
        TetComplex {
            points,
            points_f64: raw.positions.clone(),
            tets,
        },
        report,
    ))
}

/// Do the interiors of the positively oriented tetrahedra `a` and `b` meet? Exact; see the
/// module doc for why the candidate normals are complete.
pub fn interiors_meet(a: &[&[Q; 3]; 4], b: &[&[Q; 3]; 4]) -> bool {
    let separates = |n: &[Q; 3]| {
        if n.iter().all(|x| x.is_zero()) {
            return false;
        }
        let pa: Vec<Q> = a.iter().map(|p| dot(n, p)).collect();
        let pb: Vec<Q> = b.iter().map(|p| dot(n, p)).collect();
        let (amin, amax) = min_max(&pa);
        let (bmin, bmax) = min_max(&pb);
        amax <= bmin || bmax <= amin
    };
    let face_normals = |t: &[&[Q; 3]; 4]| -> Vec<[Q; 3]> {
        (0..4)
            .map(|skip| {
                let f: Vec<&[Q; 3]> = (0..4).filter(|&k| k != skip).map(|k| t[k]).collect();
                let u: [Q; 3] = std::array::from_fn(|k| &f[1][k] - &f[0][k]);
                let v: [Q; 3] = std::array::from_fn(|k| &f[2][k] - &f[0][k]);
                cross(&u, &v)
            })
            .collect()
    };
    if face_normals(a).iter().any(&separates) || face_normals(b).iter().any(&separates) {
        return false;
    }
    let edges = |t: &[&[Q; 3]; 4]| -> Vec<[Q; 3]> {
        let mut e = Vec::with_capacity(6);
        for i in 0..4 {
            for j in (i + 1)..4 {
                e.push(std::array::from_fn(|k| &t[j][k] - &t[i][k]));
            }
        }
        e
    };
    let (ea, eb) = (edges(a), edges(b));
    !ea.iter()
        .any(|u| eb.iter().any(|v| separates(&cross(u, v))))
}

fn min_max(v: &[Q]) -> (&Q, &Q) {
    let mut lo = &v[0];
    let mut hi = &v[0];
    for x in &v[1..] {
        if x < lo {
            lo = x;
        }
        if x > hi {
            hi = x;
        }
    }
    (lo, hi)
}

type Bbox = ([f64; 3], [f64; 3], usize);

fn overlap_check(
    raw: &RawTets,
    points: &[[Q; 3]],
    tets: &[usize],
) -> Result<CheckResult, TetComplexError> {
    let mut r = CheckResult::new(
        "SD-K(3-D)-overlap",
        "no two tetrahedra have intersecting interiors (exact)",
    );
    let bbox = |f: usize| -> Bbox {
        let mut lo = [f64::INFINITY; 3];
        let mut hi = [f64::NEG_INFINITY; 3];
        for &v in &raw.tets[f] {
            let p = raw.positions[v as usize];
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        (lo, hi, f)
    };
    let mut order: Vec<Bbox> = tets.iter().map(|&f| bbox(f)).collect();
    order.sort_by(|p, q| p.0[0].total_cmp(&q.0[0]).then(p.2.cmp(&q.2)));
    let tet = |f: usize| raw.tets[f].map(|v| &points[v as usize]);
    let mut active: Vec<Bbox> = Vec::new();
    for cur in order {
        active.retain(|a| a.1[0] >= cur.0[0]);
        for a in &active {
            if (1..3).any(|k| a.0[k] > cur.1[k] || cur.0[k] > a.1[k]) {
                continue;
            }
            r.examined += 1;
            if r.examined > MAX_CANDIDATE_PAIRS {
                return Err(TetComplexError::TooManyPairs {
                    path: raw.path.clone(),
                    pairs: r.examined,
                });
            }
            let (f, g) = (a.2.min(cur.2), a.2.max(cur.2));
            if interiors_meet(&tet(f), &tet(g)) {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "{} and {} overlap",
                            raw.describe_tet(f),
                            raw.describe_tet(g)
                        ),
                        json!({"tets": [f, g], "lines": [raw.tet_lines[f], raw.tet_lines[g]]}),
                    )
                });
            }
        }
        active.push(cur);
    }
    if tets.len() <= 1 {
        r.skip("fewer than two positively oriented tetrahedra");
    } else if r.examined == 0 {
        r.note = "no two tetrahedra have overlapping bounding boxes".into();
    }
    Ok(r)
}

impl TetComplex {
    /// Barycentric coordinates of the point `p` with respect to tetrahedron `f` (exact).
    pub fn barycentric(&self, f: usize, p: &[Q; 3]) -> [Q; 4] {
        let t = self.tets[f].map(|v| &self.points[v as usize]);
        let vol = orient3(t[0], t[1], t[2], t[3]);
        [
            orient3(p, t[1], t[2], t[3]) / &vol,
            orient3(t[0], p, t[2], t[3]) / &vol,
            orient3(t[0], t[1], p, t[3]) / &vol,
            orient3(t[0], t[1], t[2], p) / &vol,
        ]
    }
    /// Interior triangles as (sorted vertex triple, tetrahedron f, tetrahedron g), f < g.
    pub fn interior_faces(&self) -> Vec<([u32; 3], usize, usize)> {
        let mut m: HashMap<[u32; 3], Vec<usize>> = HashMap::new();
        for (f, t) in self.tets.iter().enumerate() {
            for tri in faces_of(t) {
                m.entry(tri).or_default().push(f);
            }
        }
        let mut v: Vec<_> = m
            .into_iter()
            .filter(|(_, ts)| ts.len() == 2)
            .map(|(tri, ts)| (tri, ts[0], ts[1]))
            .collect();
        v.sort_unstable();
        v
    }
    /// Triangles that are a face of exactly one tetrahedron (the boundary ∂|K|).
    pub fn boundary_faces(&self) -> Vec<[u32; 3]> {
        let mut m: HashMap<[u32; 3], usize> = HashMap::new();
        for t in &self.tets {
            for tri in faces_of(t) {
                *m.entry(tri).or_default() += 1;
            }
        }
        let mut v: Vec<_> = m
            .into_iter()
            .filter(|(_, n)| *n == 1)
            .map(|(t, _)| t)
            .collect();
        v.sort_unstable();
        v
    }
}
