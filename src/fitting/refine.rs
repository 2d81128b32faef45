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

/// How far vertex x's parameter is from the centroid of its base face (max |b_i − 1/3|).
fn off_centre(base: &BaseMesh, x: u32) -> f64 {
    match base.params()[x as usize] {
        Param::Face { b, .. } => b.iter().map(|t| (t - 1.0 / 3.0).abs()).fold(0.0, f64::max),
        Param::Vertex => f64::INFINITY,
    }
}

/// Candidates tried per crossing base face, at most (see [`insert_valid`]).
pub const CROSSING_CANDIDATES: usize = 4;

/// The vertices to insert where S crosses itself (SPEC `AF-refine-embedded`): per base face
/// slot whose sample crosses, the vertices of S_T parametrized in it, nearest the centroid of
/// the face first (the chart is split evenly: the crossings are where a chart is large against
/// the curvature or the distance to another sheet; the vertex furthest from the flat triangle
/// was tried first and sent armadillo at 10⁻² through many blocked embeddings), at most
/// [`CROSSING_CANDIDATES`]; a face with none takes
/// those of the faces around its corners (the repair's rule for a crossing base mesh). And
/// the slots with no candidate at all (S_T's own triangles, e.g. slivers at a crease: the
/// caller flips there).
pub fn choose_crossing(base: &BaseMesh, slots: &[u32]) -> (Vec<Vec<u32>>, Vec<u32>) {
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
        cand.retain(|&x| !base.is_base(x));
        cand.sort_unstable();
        cand.dedup();
        cand.sort_by(|&a, &b| off_centre(base, a).total_cmp(&off_centre(base, b)));
        cand.truncate(CROSSING_CANDIDATES);
        if cand.is_empty() {
            none.push(f);
        } else {
            out.push(cand);
        }
    }
    (out, none)
}

/// Insert the first of `cands` whose insertion leaves a base mesh `valid` accepts (the
/// validator: an insertion at a crossing of S must not make the base mesh cross, which the
/// repair would then undo by many flips); the refused ones are undone and counted. The vertex
/// inserted, if any.
pub fn insert_valid(
    base: &mut BaseMesh,
    cands: &[u32],
    stats: &mut RefineStats,
    valid: impl Fn(&BaseMesh) -> bool,
) -> Option<u32> {
    for &x in cands {
        if base.is_base(x) {
            continue;
        }
        let mut trial = base.clone();
        let mut st = RefineStats::default();
        if insert(&mut trial, x, &mut st) && valid(&trial) {
            *base = trial;
            stats.inserted += st.inserted;
            stats.flips += st.flips;
            return Some(x);
        }
        stats.refused += 1;
    }
    None
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
