//! The fallback of the embedding: undo the simplification locally (seed 002, Part II,
//! "Adaptive Fitting": S̃_T = Simplify S_T, then "Embed S̃_T in |S_T|: each edge of S̃_T is
//! embedded in |S_T| as a geodesic"; the slides name no rule for a base mesh that cannot be
//! embedded beyond the AC·CB figure, `super::unblock`). SPEC `AF-unsimplify`.
//!
//! **Why it ends.** The limit of refinement is S̃_T = S_T: there every base edge is an edge of
//! S_T, and its curve is that edge (traced first, along itself, `AF-embedding`), so the curves
//! are disjoint by construction. Where a base edge has no curve, the fallback keeps a
//! neighbourhood of it as in S_T — every vertex of S_T there a base vertex, the triangles of
//! S_T there base faces — and grows that neighbourhood each time an edge is still blocked; in
//! the worst case every vertex is kept and the base mesh is S_T.
//!
//! **How (the choice, the simplest sound one).** The simplification records no history: the
//! base mesh holds only its faces and each vertex of S_T's parameter (a base face and
//! barycentric coordinates, `super::base`). Cutting S_T's triangles into the current base mesh
//! would need a stitch along base edges that cross triangles of S_T. Instead the simplification
//! is run again from S_T with the kept vertices never removed
//! ([`super::simplify::simplify_keeping`]): a removal replaces only the faces around the removed
//! vertex, so a triangle of S_T with three kept corners stays a base face, with no vertex of
//! S_T parametrized in it, and its edges are edges of S_T; the stitch to the rest is made by the
//! simplification's own removals (polar-map flattening, ears, parameters carried), so every
//! invariant of the base mesh holds as after any simplification, and every check runs
//! unchanged. The cost is that the rest of the base mesh is simplified again too (the
//! independent sets change near the kept vertices); the walk's changes are dropped.
//!
//! **The neighbourhood.** For a blocked base edge a–b, ring 0 is the strip ([`strip`]): a, b,
//! their triangles of S_T, and every triangle of S_T with corners parametrized in both of a–b's
//! base faces (the triangles the straight edge a–b crosses as the simplification maps S_T onto
//! the two faces, the part of S_T the edge's curve was to cross); ring 1 is a, b, the corners of
//! a–b's two base faces and all the vertices of S_T the simplification parametrizes in them;
//! ring r ≥ 2 is the corners and vertices of S_T of every base face around a and b, grown by
//! r − 2 rings of S_T. The same where the embedding exists but a
//! curved triangle is no disk or Floater's map folds it (`AF-curved-disk`,
//! `AF-param-bijective`, whose witnesses name the base face; the embedding's parameters are
//! then unusable): ring 0 is the face's corners and its vertices of S_T, ring r ≥ 1 starts from
//! the faces around its corners. In the limit S̃_T = S_T each curved triangle is a triangle of
//! S_T and its map is affine, so no piece folds. Each round adds the smallest ring that adds
//! a vertex of S_T not kept yet and gives a base mesh never embedded; past [`MAX_RING`] every
//! vertex is kept. The vertices the refinement inserted are kept too (so a later round does not
//! lose them).
//!
//! **After the first round** (every round once the fallback has run or a fit round has):
//! every current base vertex is kept as well ([`Restore::keep_base`]: the refined ones, the
//! repair's, and those the last simplification left), so the base mesh simplified again has
//! the current base vertices and the sites' neighbourhoods as base vertices, and its faces
//! differ from the current ones only where the newly kept vertices change the removals (a
//! vertex the last simplification left was never removed by it and a refused removal changes
//! nothing, so elsewhere the same removals are done in the same order; the change spreads from
//! the new vertices level by level). Without it every round simplified all of S_T again with
//! only the kept and refined vertices fixed, so the base mesh changed away from the sites and
//! new blocked edges appeared there (boot at 3·10⁻³: 45 rounds). After a fit round the previous
//! embedding is updated locally (`super::local::Previous::reslot`). The first round simplifies
//! all of S_T again: it is the base mesh of the first simplification that failed. The kept set
//! still grows every round by a vertex of S_T not kept before, so the loop ends.
//!
//! **When** (`super::fit_surface`): where the AC·CB walk cannot finish (it gives up, or one
//! tracing leaves more blocked edges than it has changes left), where an embedding's parameters
//! are unusable, and, once the fallback has run, at every later failure of the embedding: a
//! failure at base faces without a blocked edge, and a failing `AF-geodesic-*` check (the base
//! edges of the curves its witnesses name are the sites). Meshes that need none of this are
//! untouched.

use super::base::{BaseMesh, Param};
use super::simplify::{simplify_keeping, Hierarchy, SimplifyOptions};
use crate::mesh::{SimplicialSurface, VertexId};
use crate::report::{CheckResult, Witness};
use serde_json::json;

/// Rings of growth before every vertex of S_T is kept.
pub const MAX_RING: usize = 8;

/// The vertices of S_T kept as base vertices, and what the fallback did.
#[derive(Debug, Clone, Default)]
pub struct Restore {
    keep: Vec<bool>,
    /// Simplifications run again.
    pub rounds: usize,
    /// Vertices of S_T kept.
    pub kept: usize,
    /// The ring of each round (`MAX_RING + 1`: every vertex kept).
    pub rings: Vec<usize>,
    /// The base mesh the last round returned, before the repair and the refinement change it
    /// (their flips may take an edge of S_T away again): what [`check_restored`] is run on.
    pub restored: Option<BaseMesh>,
}

impl Restore {
    /// Has the fallback run (then every blocked edge goes to it, not to the walk)?
    pub fn active(&self) -> bool {
        self.rounds > 0
    }

    /// `keep[x]`: vertex x of S_T is never removed.
    pub fn keep(&self) -> &[bool] {
        &self.keep
    }

    /// Keep the vertices `xs`; returns how many were not kept before.
    pub fn add(&mut self, n: usize, xs: impl IntoIterator<Item = u32>) -> usize {
        if self.keep.len() < n {
            self.keep.resize(n, false);
        }
        let mut added = 0;
        for x in xs {
            if let Some(k) = self.keep.get_mut(x as usize) {
                if !*k {
                    *k = true;
                    added += 1;
                }
            }
        }
        self.kept += added;
        added
    }

    /// Keep every base vertex of `base`; returns how many were not kept before. Called before
    /// every round but the first (module doc, "After the first round"), so that S_T simplified
    /// again keeps the current base vertices and changes only near the sites.
    pub fn keep_base(&mut self, base: &BaseMesh) -> usize {
        let n = base.positions().len();
        self.add(n, base.base_vertices())
    }
}

/// Where the embedding failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Site {
    /// A base edge with no curve (`AF-embedding`).
    Edge(u32, u32),
    /// A base face (slot) whose curved triangle is no disk or whose Floater map folds
    /// (`AF-curved-disk`, `AF-param-bijective`).
    Face(u32),
}

impl std::fmt::Display for Site {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Site::Edge(a, b) => write!(f, "base edge {a}-{b}"),
            Site::Face(g) => write!(f, "base face {g}"),
        }
    }
}

/// The neighbourhood of a site at `ring` (module doc; an edge's ring 0 is its strip and its
/// ring r ≥ 1 a face's ring r − 1 around its two faces; a face's ring 0 is its corners and the
/// vertices of S_T in it, ring r ≥ 1 starts from the faces around its corners), as vertices of
/// S_T.
pub fn region(k: &SimplicialSurface, base: &BaseMesh, site: Site, ring: usize) -> Vec<u32> {
    // An edge's ring 0 is the strip; its ring r ≥ 1 is ring r − 1 of the code below (its two
    // faces at 1, the faces around its ends from 2 on).
    let ring = match site {
        Site::Edge(a, b) if ring == 0 => return strip(k, base, a, b),
        Site::Edge(..) => ring - 1,
        Site::Face(_) => ring,
    };
    let (ends, own): (Vec<u32>, Vec<u32>) = match site {
        Site::Edge(a, b) => (
            vec![a, b],
            [(a, b), (b, a)]
                .iter()
                .filter_map(|&(u, w)| base.face_of_edge(u, w))
                .collect(),
        ),
        Site::Face(f) => (base.face(f).map_or(Vec::new(), |c| c.to_vec()), vec![f]),
    };
    let faces: Vec<u32> = if ring == 0 {
        own
    } else {
        ends.iter()
            .flat_map(|&v| base.faces_around(v).iter().copied())
            .collect()
    };
    let mut out = ends;
    for &f in &faces {
        out.extend(base.face(f).into_iter().flatten());
        out.extend_from_slice(base.members(f));
    }
    let n = k.vertex_slots();
    let mut seen = vec![false; n];
    for &x in &out {
        if let Some(s) = seen.get_mut(x as usize) {
            *s = true;
        }
    }
    let mut front: Vec<u32> = out.clone();
    for _ in 1..ring {
        let mut next = Vec::new();
        for &x in &front {
            if (x as usize) >= n {
                continue;
            }
            for &f in k.faces_around(VertexId(x)) {
                for y in k.face(f) {
                    if !seen[y.idx()] {
                        seen[y.idx()] = true;
                        next.push(y.0);
                    }
                }
            }
        }
        out.extend_from_slice(&next);
        front = next;
    }
    out
}

/// Ring 0 of a blocked base edge a–b (module doc): a, b, the corners of their triangles of S_T,
/// and the corners of every triangle of S_T with corners parametrized in both of a–b's base
/// faces — the triangles of S_T that the edge's curve was to cross, as the simplification maps
/// S_T onto the two faces.
pub fn strip(k: &SimplicialSurface, base: &BaseMesh, a: u32, b: u32) -> Vec<u32> {
    let n = k.vertex_slots();
    let fs: Vec<u32> = [(a, b), (b, a)]
        .iter()
        .filter_map(|&(u, w)| base.face_of_edge(u, w))
        .collect();
    let side = |x: VertexId| match base.params().get(x.idx()) {
        Some(Param::Face { f, .. }) => fs.iter().position(|g| g == f),
        _ => None,
    };
    let mut seen = vec![false; n];
    let mut out = Vec::new();
    let mut take = |c: [VertexId; 3], out: &mut Vec<u32>| {
        for y in c {
            if let Some(s) = seen.get_mut(y.idx()) {
                if !*s {
                    *s = true;
                    out.push(y.0);
                }
            }
        }
    };
    for x in [a, b].into_iter().filter(|&x| (x as usize) < n) {
        for &t in k.faces_around(VertexId(x)) {
            take(k.face(t), &mut out);
        }
    }
    for &g in &fs {
        for &x in base.members(g) {
            if (x as usize) >= n {
                continue;
            }
            for &t in k.faces_around(VertexId(x)) {
                let c = k.face(t);
                let sides = c.map(side);
                if sides.contains(&Some(0)) && sides.contains(&Some(1)) {
                    take(c, &mut out);
                }
            }
        }
    }
    out
}

/// One round of the fallback for the sites where the embedding of `base` failed: the smallest ring that
/// keeps a vertex of S_T not kept yet and whose simplification `tried` says was never embedded
/// (module doc). Returns the new base mesh and its hierarchy, or None when every vertex is
/// kept already and S_T itself was tried.
pub fn restore(
    k: &SimplicialSurface,
    base: &BaseMesh,
    sites: &[Site],
    opts: &SimplifyOptions,
    state: &mut Restore,
    tried: impl Fn(&BaseMesh) -> bool,
) -> Option<(BaseMesh, Hierarchy)> {
    let n = k.vertex_slots();
    let mut ring = 0;
    loop {
        let added = if ring > MAX_RING {
            state.add(n, 0..n as u32)
        } else {
            let xs: Vec<u32> = sites
                .iter()
                .flat_map(|&s| region(k, base, s, ring))
                .collect();
            state.add(n, xs)
        };
        if added == 0 {
            if ring > MAX_RING {
                return None;
            }
            ring += 1;
            continue;
        }
        let mut m = BaseMesh::new(k);
        let h = simplify_keeping(&mut m, k, opts, state.keep(), |_, _| {});
        state.rounds += 1;
        state.rings.push(ring);
        if !tried(&m) {
            state.restored = Some(m.clone());
            return Some((m, h));
        }
        ring += 1;
    }
}

/// SPEC `AF-unsimplify`: every vertex of S_T the fallback keeps is a base vertex, and every
/// triangle of S_T with three kept corners is a base face (same orientation) in which no vertex
/// of S_T is parametrized — the part of S_T restored as it is, whose base edges are edges of
/// S_T. Nothing kept is nothing examined (skipped).
pub fn check_restored(k: &SimplicialSurface, base: &BaseMesh, keep: &[bool]) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-unsimplify",
        "every vertex of S_T the fallback keeps is a base vertex and every triangle of S_T with three kept corners is a base face with no vertex of S_T in it",
    );
    let kept = |x: u32| keep.get(x as usize).copied().unwrap_or(false);
    for x in (0..keep.len() as u32).filter(|&x| kept(x)) {
        r.examined += 1;
        if !base.is_base(x) {
            r.offend(|| {
                Witness::new(
                    format!("kept vertex {x} of S_T is not a base vertex"),
                    json!({"vertex": x}),
                )
            });
        }
    }
    let mut restored = 0u64;
    for f in k.faces() {
        let c = k.face(f).map(|v| v.0);
        if !c.iter().all(|&x| kept(x)) {
            continue;
        }
        r.examined += 1;
        restored += 1;
        let slot = base
            .face_of_edge(c[0], c[1])
            .filter(|&g| base.face(g).is_some_and(|t| t.contains(&c[2])));
        match slot {
            Some(g) if base.members(g).is_empty() => {}
            Some(g) => r.offend(|| {
                Witness::new(
                    format!(
                        "triangle {} {c:?} of S_T is base face {g}, with {} vertices of S_T in it",
                        f.0,
                        base.members(g).len()
                    ),
                    json!({"triangle": f.0, "face": g, "members": base.members(g)}),
                )
            }),
            None => r.offend(|| {
                Witness::new(
                    format!(
                        "triangle {} {c:?} of S_T has three kept corners and is no base face",
                        f.0
                    ),
                    json!({"triangle": f.0, "corners": c}),
                )
            }),
        }
    }
    r.note = format!(
        "{} vertices of S_T kept, {restored} triangles of S_T with three kept corners",
        keep.iter().filter(|&&b| b).count()
    );
    r
}
