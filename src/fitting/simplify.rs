//! Stellar simplification of S_T (seed 002, Part I, "Basic algorithm"): repeat for a number of
//! levels — rank the vertices by quadric error, select an independent set, remove each by a
//! stellar operation. Each level removes an independent set, so the hierarchy's height is the
//! number of levels (the slides' "logarithmic height" is measured, SPEC `AF-simplify-height`).
//!
//! The quadric (Garland–Heckbert 1997) of a vertex is the sum of the plane quadrics of its
//! faces in S_T, and a removed vertex's quadric is added to its ring's (the error of the region
//! a base vertex stands for). The rank of v is min over its base neighbours u of Q_v(u): the
//! error of letting a neighbour stand for v.

use super::base::{quality, BaseMesh, Refusal, RemovalLimits};
use crate::mesh::SimplicialSurface;
use serde::Serialize;

/// Simplification limits.
#[derive(Debug, Clone, Copy)]
pub struct SimplifyOptions {
    /// Per-removal limits (deviation, normals, shape, degree).
    pub limits: RemovalLimits,
    /// Stop at or below this many base vertices.
    pub min_vertices: usize,
    /// Stop after this many levels.
    pub max_levels: usize,
}

/// One level of the hierarchy.
#[derive(Debug, Clone, Serialize)]
pub struct Level {
    /// Vertices removed (an independent set of the level's base mesh).
    pub removed: usize,
    /// Candidates refused, by reason.
    pub refused: usize,
    /// Base vertices after the level.
    pub vertices_after: usize,
}

/// The hierarchy's summary (SPEC `AF-simplify-*`).
#[derive(Debug, Clone, Serialize)]
pub struct Hierarchy {
    /// The levels, finest first.
    pub levels: Vec<Level>,
    /// Smallest triangle quality of the final base mesh.
    pub min_quality: f64,
    /// Median triangle quality of the final base mesh.
    pub median_quality: f64,
}

type Quadric = [f64; 10];

fn plane_quadric(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Quadric {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if !(l > 0.0) {
        return [0.0; 10];
    }
    // Area-weighted: the unit normal times the area (l/2) enters squared over area.
    let w = 0.5 * l;
    let (x, y, z) = (n[0] / l, n[1] / l, n[2] / l);
    let d = -(x * a[0] + y * a[1] + z * a[2]);
    [
        w * x * x,
        w * x * y,
        w * x * z,
        w * x * d,
        w * y * y,
        w * y * z,
        w * y * d,
        w * z * z,
        w * z * d,
        w * d * d,
    ]
}

fn q_eval(q: &Quadric, p: [f64; 3]) -> f64 {
    let [x, y, z] = p;
    q[0] * x * x
        + 2.0 * q[1] * x * y
        + 2.0 * q[2] * x * z
        + 2.0 * q[3] * x
        + q[4] * y * y
        + 2.0 * q[5] * y * z
        + 2.0 * q[6] * y
        + q[7] * z * z
        + 2.0 * q[8] * z
        + q[9]
}

/// Simplify `base` (initially equal to `k`) level by level.
pub fn simplify(
    base: &mut BaseMesh,
    k: &SimplicialSurface,
    opts: &SimplifyOptions,
    progress: impl FnMut(usize, usize),
) -> Hierarchy {
    simplify_keeping(base, k, opts, &[], progress)
}

/// [`simplify`] with the vertices x of S_T with `keep[x]` never removed (ids past the slice's
/// end are not kept). A triangle of S_T whose three corners are kept stays a base face with no
/// vertex of S_T parametrized in it: a removal only replaces the faces around the removed
/// vertex (`super::unsimplify`).
pub fn simplify_keeping(
    base: &mut BaseMesh,
    k: &SimplicialSurface,
    opts: &SimplifyOptions,
    keep: &[bool],
    mut progress: impl FnMut(usize, usize),
) -> Hierarchy {
    let n = base.positions().len();
    let mut quad: Vec<Quadric> = vec![[0.0; 10]; n];
    for f in k.faces() {
        let c = k.face(f).map(|v| v.0 as usize);
        let p = c.map(|v| base.positions()[v]);
        let q = plane_quadric(p[0], p[1], p[2]);
        for v in c {
            for (a, b) in quad[v].iter_mut().zip(q) {
                *a += b;
            }
        }
    }
    let mut levels = Vec::new();
    let mut alive = base.base_vertices().len();
    while levels.len() < opts.max_levels && alive > opts.min_vertices {
        let mut cand: Vec<(f64, u32)> = base
            .base_vertices()
            .into_iter()
            .filter(|&v| !keep.get(v as usize).copied().unwrap_or(false))
            .filter_map(|v| {
                let (us, _) = base.ring(v)?;
                let pos = base.positions();
                let c = us
                    .iter()
                    .map(|&u| q_eval(&quad[v as usize], pos[u as usize]))
                    .fold(f64::INFINITY, f64::min);
                Some((c, v))
            })
            .collect();
        cand.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut blocked = vec![false; n];
        let (mut removed, mut refused) = (0, 0);
        for &(_, v) in &cand {
            if alive <= opts.min_vertices {
                break;
            }
            if blocked[v as usize] {
                continue;
            }
            let Some((us, _)) = base.ring(v) else {
                continue;
            };
            match base.remove_vertex(v, &opts.limits) {
                Ok(()) => {
                    removed += 1;
                    alive -= 1;
                    blocked[v as usize] = true;
                    let qv = quad[v as usize];
                    for &u in &us {
                        blocked[u as usize] = true;
                        for (a, b) in quad[u as usize].iter_mut().zip(qv) {
                            *a += b;
                        }
                    }
                }
                Err(Refusal::Missing) => {}
                Err(_) => refused += 1,
            }
        }
        levels.push(Level {
            removed,
            refused,
            vertices_after: alive,
        });
        progress(levels.len(), alive);
        if removed == 0 {
            break;
        }
    }
    let mut qs: Vec<f64> = base
        .faces()
        .map(|(_, c)| {
            let p = c.map(|v| base.positions()[v as usize]);
            quality(p[0], p[1], p[2])
        })
        .collect();
    qs.sort_by(f64::total_cmp);
    Hierarchy {
        levels,
        min_quality: qs.first().copied().unwrap_or(f64::NAN),
        median_quality: qs.get(qs.len() / 2).copied().unwrap_or(f64::NAN),
    }
}
