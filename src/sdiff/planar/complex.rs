//! Planar triangle complexes *with boundary* (Mello–Velho Sec. 1: K a simplicial complex in
//! ℝ^m, here m = 2), read from OFF/OBJ/PLY with z = 0 and validated exactly: coordinates are
//! the stored doubles taken as exact rationals.
//!
//! The closed-surface validator of Sec. 3.1 does not apply (boundary edges are allowed), so
//! this is a validator of its own: finite planar input, indices in range, purity (no vertex
//! outside every triangle), positive orientation, at most two triangles per edge, and no two
//! triangles whose interiors meet (decided by the separating-axis theorem with exact signs).

use super::poly::{from_f64, Q};
use crate::mesh::raw::RawMesh;
use crate::report::{CheckResult, Witness};
use num_traits::{Signed, Zero};
use std::collections::HashMap;

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
    let nv = points.len();
    let mut report = Vec::new();

    let mut range = CheckResult::new("SD-K-indices", "triangle vertex indices are in range");
    let mut ok_faces = Vec::new();
    for (f, t) in raw.faces.iter().enumerate() {
        range.examined += 1;
        if t.iter().any(|&v| v as usize >= nv) {
            range.offend(|| {
                Witness::new(
                    format!("{} names vertex {:?} of {nv}", raw.describe_face(f), t),
                    serde_json::json!({"face": f}),
                )
            });
        } else if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
            range.offend(|| {
                Witness::new(
                    format!("{} repeats a vertex {:?}", raw.describe_face(f), t),
                    serde_json::json!({"face": f}),
                )
            });
        } else {
            ok_faces.push(f);
        }
    }
    report.push(range);

    let mut pure = CheckResult::new(
        "SD-K-pure",
        "purity: every vertex is a vertex of some triangle",
    );
    let mut used = vec![false; nv];
    for &f in &ok_faces {
        for &v in &raw.faces[f] {
            used[v as usize] = true;
        }
    }
    for (v, u) in used.iter().enumerate() {
        pure.examined += 1;
        if !u {
            pure.offend(|| {
                Witness::new(
                    format!("{} is in no triangle", raw.describe_vertex(v)),
                    serde_json::json!({"vertex": v}),
                )
            });
        }
    }
    report.push(pure);

    let mut orientation = CheckResult::new(
        "SD-K-orientation",
        "every triangle is positively oriented (exact sign)",
    );
    for &f in &ok_faces {
        orientation.examined += 1;
        let t = raw.faces[f];
        let o = orient(
            &points[t[0] as usize],
            &points[t[1] as usize],
            &points[t[2] as usize],
        );
        if !o.is_positive() {
            let what = if o.is_zero() {
                "degenerate (collinear)"
            } else {
                "clockwise"
            };
            orientation.offend(|| {
                Witness::new(
                    format!("{} is {what}", raw.describe_face(f)),
                    serde_json::json!({"face": f, "twice_area": o.to_string()}),
                )
            });
        }
    }
    report.push(orientation);

    let mut facets = CheckResult::new(
        "SD-K-facets",
        "every edge is a face of at most two triangles",
    );
    let mut edges: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for &f in &ok_faces {
        let t = raw.faces[f];
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            edges.entry((a.min(b), a.max(b))).or_default().push(f);
        }
    }
    let mut keys: Vec<_> = edges.keys().copied().collect();
    keys.sort_unstable();
    for e in keys {
        facets.examined += 1;
        let fs = &edges[&e];
        if fs.len() > 2 {
            facets.offend(|| {
                Witness::new(
                    format!("edge {:?} is in {} triangles: {:?}", e, fs.len(), fs),
                    serde_json::json!({"edge": e, "faces": fs}),
                )
            });
        }
    }
    report.push(facets);

    let overlaps = overlap_check(raw, &points, &ok_faces);
    report.push(overlaps);

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
    // Sweep over x: bounding boxes sorted by their left end.
    let bbox = |f: usize| {
        let t = raw.faces[f];
        let xs = t.map(|v| raw.positions[v as usize][0]);
        let ys = t.map(|v| raw.positions[v as usize][1]);
        (
            xs.iter().cloned().fold(f64::INFINITY, f64::min),
            xs.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
            ys.iter().cloned().fold(f64::INFINITY, f64::min),
            ys.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
        )
    };
    let mut order: Vec<(f64, f64, f64, f64, usize)> = faces
        .iter()
        .map(|&f| {
            let (a, b, c, d) = bbox(f);
            (a, b, c, d, f)
        })
        .collect();
    order.sort_by(|p, q| p.0.total_cmp(&q.0).then(p.4.cmp(&q.4)));
    let tri = |f: usize| raw.faces[f].map(|v| points[v as usize].clone());
    let mut active: Vec<(f64, f64, f64, f64, usize)> = Vec::new();
    for cur in order {
        active.retain(|a| a.1 >= cur.0);
        for a in &active {
            if a.2 > cur.3 || cur.2 > a.3 {
                continue;
            }
            r.examined += 1;
            let (f, g) = (a.4.min(cur.4), a.4.max(cur.4));
            let (ta, tb) = (tri(f), tri(g));
            let oa = orient(&ta[0], &ta[1], &ta[2]);
            let ob = orient(&tb[0], &tb[1], &tb[2]);
            if !oa.is_positive() || !ob.is_positive() {
                continue; // reported by the orientation check
            }
            if interiors_meet(&ta, &tb) {
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
        }
        active.push(cur);
    }
    if r.examined == 0 && faces.len() > 1 {
        r.note = "no two triangles have overlapping bounding boxes".into();
    }
    if faces.len() <= 1 {
        r.skip("fewer than two triangles");
    }
    r
}

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
        let mut m: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
        for (f, t) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                m.entry((a.min(b), a.max(b))).or_default().push(f);
            }
        }
        let mut v: Vec<_> = m
            .into_iter()
            .filter(|(_, fs)| fs.len() == 2)
            .map(|((a, b), fs)| (a, b, fs[0], fs[1]))
            .collect();
        v.sort_unstable();
        v
    }
}
