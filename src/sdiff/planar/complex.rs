//! Planar triangle complexes *with boundary* (Mello–Velho Sec. 1: K a simplicial complex in
//! ℝ^m, here m = 2), read from OFF/OBJ/PLY with z = 0 and validated exactly: coordinates are
//! the stored doubles taken as exact rationals.
//!
//! The closed-surface validator of Sec. 3.1 does not apply (boundary edges are allowed), so
//! this is a validator of its own: finite planar input, indices in range, purity (no vertex
//! outside every triangle), positive orientation, at most two triangles per edge, and no two
//! triangles whose interiors meet (decided by the separating-axis theorem with exact signs).

use crate::mesh::raw::RawMesh;
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::complex::{self as common, OrientationWords, Words};
use crate::sdiff::common::rational::{from_f64, Q};
use num_traits::Signed;
use serde_json::{Map, Value};

/// A validated planar complex: every triangle positively oriented, no overlaps, ≤ 2
/// triangles per edge (only [`validate`] makes one).
#[derive(Debug, Clone)]
pub struct PlanarComplex {
    /// Vertex positions, exact.
    pub points: Vec<[Q; 2]>,
    /// Vertex positions as read.
    pub points_f64: Vec<[f64; 2]>,
    /// Triangles (global vertex ids), counterclockwise.
    pub triangles: Vec<[u32; 3]>,
}

/// Why a file is not a planar complex.
#[derive(Debug, thiserror::Error)]
pub enum ComplexError {
    /// A coordinate is not finite.
    #[error("{vertex}: coordinate {value} is not finite")]
    NotFinite {
        /// Which vertex (with its source line when known).
        vertex: String,
        /// The value.
        value: f64,
    },
    /// A z coordinate is not zero: the complex must lie in the plane z = 0.
    #[error("{vertex}: z = {z} (a planar complex needs z = 0 exactly)")]
    NotPlanar {
        /// Which vertex.
        vertex: String,
        /// Its z.
        z: f64,
    },
    /// The input has no triangle.
    #[error("the complex has no triangle")]
    Empty,
    /// The validation found offenders (the report lists them).
    #[error("the input is not a planar simplicial complex (see the report)")]
    Invalid(Vec<CheckResult>),
}

/// det(b − a, c − a), exact.
fn orient(a: &[Q; 2], b: &[Q; 2], c: &[Q; 2]) -> Q {
    crate::numeric::predicates::det2(a, b, c)
}

/// Validates `raw` as a planar simplicial complex with boundary; the report lists every check.
pub fn validate(raw: &RawMesh) -> Result<(PlanarComplex, Vec<CheckResult>), ComplexError> {
    if raw.faces.is_empty() {
        return Err(ComplexError::Empty);
    }
    let mut points = Vec::with_capacity(raw.positions.len());
    for (i, p) in raw.positions.iter().enumerate() {
        for &x in p {
            if !x.is_finite() {
                return Err(ComplexError::NotFinite {
                    vertex: raw.describe_vertex(i),
                    value: x,
                });
            }
        }
        if p[2] != 0.0 {
            return Err(ComplexError::NotPlanar {
                vertex: raw.describe_vertex(i),
                z: p[2],
            });
        }
        // Finite doubles are exact rationals.
        points.push([
            from_f64(p[0]).unwrap_or_default(),
            from_f64(p[1]).unwrap_or_default(),
        ]);
    }
    let (range, ok_faces) =
        common::indices(raw, "SD-K-indices", "triangle vertex indices are in range");
    let pure = common::purity(
        raw,
        &ok_faces,
        &WORDS,
        "SD-K-pure",
        "purity: every vertex is a vertex of some triangle",
    );
    let (orientation, positive) = common::orientation(
        raw,
        &ok_faces,
        |t| {
            let [a, b, c] = t.map(|v| &points[v as usize]);
            orient(a, b, c)
        },
        &OrientationWords {
            degenerate: "degenerate (collinear)",
            negative: "clockwise",
            key: "twice_area",
        },
        "SD-K-orientation",
        "every triangle is positively oriented (exact sign)",
    );
    let facets = common::facets::<3, 2>(
        raw,
        &ok_faces,
        &WORDS,
        "SD-K-facets",
        "every edge is a face of at most two triangles",
    );
    let overlaps = overlap_check(raw, &points, &positive);
    let report = vec![range, pure, orientation, facets, overlaps];

    if report.iter().any(|r| r.failed()) {
        return Err(ComplexError::Invalid(report));
    }
    let triangles = ok_faces.iter().map(|&f| raw.faces[f]).collect();
    let points_f64 = raw.positions.iter().map(|p| [p[0], p[1]]).collect();
    Ok((
        PlanarComplex {
            points,
            points_f64,
            triangles,
        },
        report,
    ))
}

/// Interiors of two counterclockwise triangles are disjoint iff some edge line of one has the
/// other in its closed right half-plane (separating-axis theorem for convex polygons).
fn interiors_meet(a: &[[Q; 2]; 3], b: &[[Q; 2]; 3]) -> bool {
    let separated = |p: &[[Q; 2]; 3], o: &[[Q; 2]; 3]| {
        (0..3).any(|k| {
            let (u, v) = (&p[k], &p[(k + 1) % 3]);
            o.iter().all(|x| !orient(u, v, x).is_positive())
        })
    };
    !(separated(a, b) || separated(b, a))
}

fn overlap_check(raw: &RawMesh, points: &[[Q; 2]], faces: &[usize]) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-K-overlap",
        "no two triangles have intersecting interiors (exact)",
    );
    let boxes = faces
        .iter()
        .map(|&f| {
            let at = |v: usize| [raw.positions[v][0], raw.positions[v][1]];
            common::bbox(&raw.faces[f], at, f)
        })
        .collect();
    let tri = |f: usize| raw.faces[f].map(|v| points[v as usize].clone());
    // No limit on the pairs: planar inputs have never needed one (the 3-D sweep has one).
    let pairs = common::sweep_pairs::<2>(boxes, None, |f, g| {
        if interiors_meet(&tri(f), &tri(g)) {
            r.offend(|| {
                Witness::new(
                    format!(
                        "{} and {} overlap",
                        raw.describe_face(f),
                        raw.describe_face(g)
                    ),
                    serde_json::json!({"faces": [f, g]}),
                )
            });
        }
    });
    r.examined = pairs.unwrap_or_else(|n| n);
    if faces.len() <= 1 {
        r.skip("fewer than two positively oriented triangles");
    } else if r.examined == 0 {
        r.note = "no two triangles have overlapping bounding boxes".into();
    }
    r
}

/// Planar cells as [`common::RawCells`]: triangles named by face (and line, when known).
impl common::RawCells<3> for RawMesh {
    fn cells(&self) -> &[[u32; 3]] {
        &self.faces
    }
    fn vertex_count(&self) -> usize {
        self.positions.len()
    }
    fn describe_cell(&self, f: usize) -> String {
        self.describe_face(f)
    }
    fn describe_vertex(&self, v: usize) -> String {
        RawMesh::describe_vertex(self, v)
    }
    fn cell_fields(&self, f: usize) -> Map<String, Value> {
        Map::from_iter([("face".to_string(), Value::from(f))])
    }
    fn vertex_fields(&self, v: usize) -> Map<String, Value> {
        Map::from_iter([("vertex".to_string(), Value::from(v))])
    }
}

const WORDS: Words = Words {
    cell: "triangle",
    cells: "triangles",
    facet: "edge",
};

impl PlanarComplex {
    /// Barycentric coordinates of the plane point `p` with respect to triangle `f` (exact).
    pub fn barycentric(&self, f: usize, p: &[Q; 2]) -> [Q; 3] {
        let t = self.triangles[f].map(|v| &self.points[v as usize]);
        let area = orient(t[0], t[1], t[2]);
        let w0 = orient(p, t[1], t[2]) / &area;
        let w1 = orient(t[0], p, t[2]) / &area;
        let w2 = orient(t[0], t[1], p) / &area;
        [w0, w1, w2]
    }
    /// The plane point with barycentric coordinates `w` in triangle `f`.
    pub fn point(&self, f: usize, w: &[Q; 3]) -> [Q; 2] {
        let t = self.triangles[f].map(|v| &self.points[v as usize]);
        [
            &w[0] * &t[0][0] + &w[1] * &t[1][0] + &w[2] * &t[2][0],
            &w[0] * &t[0][1] + &w[1] * &t[1][1] + &w[2] * &t[2][1],
        ]
    }
    /// Interior edges as (a, b, f, g): a < b, triangles f and g share it.
    pub fn interior_edges(&self) -> Vec<(u32, u32, usize, usize)> {
        let m = common::facet_map::<3, 2>(&self.triangles, 0..self.triangles.len());
        let mut v: Vec<_> = m
            .into_iter()
            .filter(|(_, fs)| fs.len() == 2)
            .map(|([a, b], fs)| (a, b, fs[0], fs[1]))
            .collect();
        v.sort_unstable();
        v
    }
}
