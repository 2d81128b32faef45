//! Local refinement of the base mesh (seed 002, Part II, "Error and refinement": where the fit
//! misses ε, refine S̃_T locally by stellar operators). The slides leave the rule open; the
//! choice here (SPEC `AF-refine-rule`): insert the vertex of S_T with the largest error of each
//! offending base face by a stellar face split, then restore the local Delaunay property of the
//! base triangles' unfolded pairs by Lawson flips (edge flips are stellar: a split then a weld),
//! which keeps the new triangles' shapes from degenerating. Every operation keeps the
//! parametrization a bijection (`base` module doc). The next round embeds again only the
//! curves and curved triangles of the faces these operations changed ([`super::local`], SPEC
//! `AF-refine-local`).

use super::base::{BaseMesh, Param};

/// Flips done by one insertion at most (Lawson's algorithm ends; this bounds a pathological
/// unfolding that is not a planar Delaunay triangulation).
const MAX_FLIPS: usize = 64;

/// Counts of one refinement step.
#[derive(Debug, Clone, Copy, Default, serde::Serialize)]
pub struct RefineStats {
    /// Vertices of S_T made base vertices.
    pub inserted: usize,
    /// Insertions refused (the vertex sat on a base edge in parameter space).
    pub refused: usize,
    /// Edge flips done.
    pub flips: usize,
}

/// Insert fine vertex x (parametrized in a base face) and legalize around it.
pub fn insert(base: &mut BaseMesh, x: u32, stats: &mut RefineStats) -> bool {
    let Ok(slots) = base.split_face(x) else {
        stats.refused += 1;
        return false;
    };
    stats.inserted += 1;
    let mut stack: Vec<(u32, u32)> = slots
        .iter()
        .filter_map(|&s| base.face(s))
        .filter_map(|c| {
            let i = c.iter().position(|&v| v == x)?;
            Some((c[(i + 1) % 3], c[(i + 2) % 3]))
        })
        .collect();
    let mut flips = 0;
    while let Some((a, b)) = stack.pop() {
        if flips >= MAX_FLIPS {
            break;
        }
        if base.is_delaunay(a, b) != Some(false) {
            continue;
        }
        let Some(d) = base
            .face_of_edge(b, a)
            .and_then(|f| base.face(f))
            .and_then(|c| c.iter().position(|&v| v == b).map(|i| c[(i + 1) % 3]))
        else {
            continue;
        };
        if base.flip(a, b).is_ok() {
            flips += 1;
            stack.push((a, d));
            stack.push((d, b));
        }
    }
    stats.flips += flips;
    true
}

/// The vertices to insert for a set of offending vertices of S_T: per base face, the one with
/// the largest error among the offenders parametrized in it; an offending base vertex names
/// the worst vertex of S_T in each face around it.
pub fn choose(base: &BaseMesh, err: &[f64], offenders: &[u32]) -> Vec<u32> {
    let mut best: std::collections::BTreeMap<u32, (f64, u32)> = Default::default();
    let mut consider = |f: u32, x: u32| {
        let e = err[x as usize];
        let e = if e.is_nan() { f64::INFINITY } else { e };
        let slot = best.entry(f).or_insert((e, x));
        if e > slot.0 {
            *slot = (e, x);
        }
    };
    for &x in offenders {
        match base.params()[x as usize] {
            Param::Face { f, .. } => consider(f, x),
            Param::Vertex => {
                for &f in base.faces_around(x) {
                    if let Some(&y) = base
                        .members(f)
                        .iter()
                        .max_by(|&&a, &&b| err[a as usize].total_cmp(&err[b as usize]))
                    {
                        consider(f, y);
                    }
                }
            }
        }
    }
    best.into_values().map(|(_, x)| x).collect()
}

/// The vertices to insert where S crosses itself (SPEC `AF-refine-embedded`): per base face
/// slot whose sample crosses, the vertex of S_T parametrized in it furthest from its flat base
/// triangle (where the fit bends most: the crossings are where the patches follow a curved
/// S_T over a large chart); a face with none takes the furthest among the faces around its
/// corners (the repair's rule for a crossing base mesh). Sorted, unique; and the slots with no
/// candidate at all (S_T's own triangles, e.g. slivers at a crease: the caller flips there).
pub fn choose_crossing(base: &BaseMesh, slots: &[u32]) -> (Vec<u32>, Vec<u32>) {
    let mut out = Vec::new();
    let mut none = Vec::new();
    for &f in slots {
        let mut cand: Vec<u32> = base.members(f).to_vec();
        if cand.is_empty() {
            for v in base.face(f).into_iter().flatten() {
                for &g in base.faces_around(v) {
                    cand.extend_from_slice(base.members(g));
                }
            }
        }
        let worst = cand
            .into_iter()
            .filter(|&x| !base.is_base(x))
            .max_by(|&a, &b| base.flat_deviation(a).total_cmp(&base.flat_deviation(b)));
        match worst {
            Some(x) => out.push(x),
            None => none.push(f),
        }
    }
    out.sort_unstable();
    out.dedup();
    (out, none)
}

/// Flip the longest edge of base face slot `f` that can be flipped (the repair's rule where
/// no vertex of S_T is left to insert). Whether one was.
pub fn flip_longest(base: &mut BaseMesh, f: u32, pos: &[[f64; 3]]) -> bool {
    let Some(c) = base.face(f) else {
        return false;
    };
    let mut edges: Vec<(f64, u32, u32)> = (0..3)
        .map(|i| {
            let (a, b) = (c[i], c[(i + 1) % 3]);
            (
                super::geodesic::dist(pos[a as usize], pos[b as usize]),
                a,
                b,
            )
        })
        .collect();
    edges.sort_by(|x, y| y.0.total_cmp(&x.0));
    edges.iter().any(|&(_, a, b)| base.flip(a, b).is_ok())
}
