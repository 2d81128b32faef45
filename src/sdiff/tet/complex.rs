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
use crate::sdiff::common::complex::{self as common, OrientationWords, Words};
use crate::sdiff::common::rational::{from_f64, Q};
use num_traits::Zero;
use serde_json::{json, Map, Value};
use std::path::PathBuf;

use super::file::RawTets;
use crate::mesh::MeshError;

/// Most candidate pairs (overlapping bounding boxes) the exact overlap test examines.
pub(crate) const MAX_CANDIDATE_PAIRS: u64 = 20_000_000;

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
    let (range, ok) = common::indices(
        raw,
        "SD-K(3-D)-indices",
        "tetrahedron vertex ids are in range and distinct",
    );
    let pure = common::purity(
        raw,
        &ok,
        &WORDS,
        "SD-K(3-D)-pure",
        "purity: every vertex is a vertex of some tetrahedron",
    );
    let (orientation, positive) = common::orientation(
        raw,
        &ok,
        |t| {
            let [a, b, c, d] = t.map(|v| &points[v as usize]);
            orient3(a, b, c, d)
        },
        &OrientationWords {
            degenerate: "degenerate (coplanar)",
            negative: "negatively oriented",
            key: "six_volume",
        },
        "SD-K(3-D)-orientation",
        "every tetrahedron is positively oriented (exact sign)",
    );
    let facets = common::facets::<4, 3>(
        raw,
        &ok,
        &WORDS,
        "SD-K(3-D)-faces",
        "every triangle is a face of at most two tetrahedra",
    );
    let mut report = vec![range, pure, orientation, facets];
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

fn overlap_check(
    raw: &RawTets,
    points: &[[Q; 3]],
    tets: &[usize],
) -> Result<CheckResult, TetComplexError> {
    let mut r = CheckResult::new(
        "SD-K(3-D)-overlap",
        "no two tetrahedra have intersecting interiors (exact)",
    );
    let boxes = tets
        .iter()
        .map(|&f| common::bbox(&raw.tets[f], |v| raw.positions[v], f))
        .collect();
    let tet = |f: usize| raw.tets[f].map(|v| &points[v as usize]);
    let pairs = common::sweep_pairs::<3>(boxes, Some(MAX_CANDIDATE_PAIRS), |f, g| {
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
    });
    r.examined = pairs.map_err(|pairs| TetComplexError::TooManyPairs {
        path: raw.path.clone(),
        pairs,
    })?;
    if tets.len() <= 1 {
        r.skip("fewer than two positively oriented tetrahedra");
    } else if r.examined == 0 {
        r.note = "no two tetrahedra have overlapping bounding boxes".into();
    }
    Ok(r)
}

/// Tetrahedra as [`common::RawCells`], named by file and line.
impl common::RawCells<4> for RawTets {
    fn cells(&self) -> &[[u32; 4]] {
        &self.tets
    }
    fn vertex_count(&self) -> usize {
        self.positions.len()
    }
    fn describe_cell(&self, f: usize) -> String {
        self.describe_tet(f)
    }
    fn describe_vertex(&self, v: usize) -> String {
        RawTets::describe_vertex(self, v)
    }
    fn cell_fields(&self, f: usize) -> Map<String, Value> {
        let line = self.tet_lines.get(f).copied().unwrap_or(0);
        Map::from_iter([
            ("tet".to_string(), Value::from(f)),
            ("line".to_string(), Value::from(line)),
        ])
    }
    fn vertex_fields(&self, v: usize) -> Map<String, Value> {
        let line = self.vertex_lines.get(v).copied().unwrap_or(0);
        Map::from_iter([
            ("vertex".to_string(), Value::from(v)),
            ("line".to_string(), Value::from(line)),
        ])
    }
}

const WORDS: Words = Words {
    cell: "tetrahedron",
    cells: "tetrahedra",
    facet: "triangle",
};

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
        let m = common::facet_map::<4, 3>(&self.tets, 0..self.tets.len());
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
        let m = common::facet_map::<4, 3>(&self.tets, 0..self.tets.len());
        let mut v: Vec<_> = m
            .into_iter()
            .filter(|(_, ts)| ts.len() == 1)
            .map(|(t, _)| t)
            .collect();
        v.sort_unstable();
        v
    }
}
