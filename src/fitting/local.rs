//! Re-embedding after a refinement round only where the base mesh changed (seed 002, Part II,
//! "Error and refinement": S̃_T is refined locally, so its embedding changes locally). SPEC
//! `AF-refine-local`.
//!
//! A round's refinement (face splits and Lawson flips, [`super::refine`]; the repair's and the
//! AC·CB walk's changes alike) leaves most base faces as they were. A base face is *unchanged*
//! when its slot holds the same corners, in the same order, as when the previous embedding was
//! made. The curve of a base edge is *kept* — node for node, bit-identical — when the edge's
//! two faces are unchanged and none of its inner nodes is a base vertex now (an inserted vertex
//! of S_T on an old curve would break `AF-geodesic-disjoint`). Every other base edge is traced
//! again, the kept curves closed to it as any earlier curve is ([`super::route`]), and shortened
//! with the kept curves as obstacles that do not move ([`super::shorten`]). S_T is cut along
//! all curves again ([`super::overlay`], linear in S_T). A face that is unchanged and whose
//! three curves are kept keeps its Floater map (its images, under the new overlay's ids of its
//! curves' nodes), so the vertices of S_T inside it keep their parameters; the other faces are
//! mapped again ([`super::floater`]).
//!
//! A base vertex inserted since (by the refinement or the walk) inside the curved triangle of a
//! face whose corners did not change would be walled in by that face's kept curves, so such a
//! face counts as changed too. Where the update still fails at a place — a base edge with no
//! path (the kept curves wall it off), or base faces (a curved triangle that is no disk, a
//! curve off the surface, a map that cannot be solved) — the faces around the edge's ends or
//! the faces' corners, in the base mesh as it is and the curved triangles of the previous
//! embedding that hold those vertices, count as changed and the update is tried again, up to
//! [`MAX_OPENINGS`] times, each time one ring wider when the same vertices fail again.
//!
//! Nothing is skipped downstream: [`super::fit_surface`] runs every check of the embedding on
//! the whole result, as after a global embedding, and embeds all of S_T again (saying so) when
//! the local update fails or one of those checks fails on it. The fit may differ from a global
//! re-embedding: the new curves are traced and shortened around fixed old ones, where the global
//! tracing would have traced and shortened every curve afresh.

use super::base::BaseMesh;
use super::embedded::{embed_keeping, Embedded, Failure};
use super::floater::RegionMap;
use super::geodesic::{Curve, Node};
use crate::mesh::SimplicialSurface;
use serde::Serialize;
use std::collections::{HashMap, HashSet};

/// The previous round's embedding and the base faces it was made for.
#[derive(Debug, Clone)]
pub struct Previous {
    /// Corners of every live face slot when it was embedded.
    pub faces: HashMap<u32, [u32; 3]>,
    /// The embedding.
    pub emb: Embedded,
}

impl Previous {
    /// The embedding `emb` of the base mesh `base` as it is now.
    pub fn new(base: &BaseMesh, emb: Embedded) -> Self {
        Previous {
            faces: base.faces().collect(),
            emb,
        }
    }

    /// The same embedding for `base`, a base mesh simplified again by the fallback
    /// (`super::unsimplify`), whose face slots are numbered afresh: a face of `base` with the
    /// corners, in the same order, of a face embedded before takes that face's place (with its
    /// Floater map, whose corner images follow the order); the others count as changed. So a
    /// fallback round after refinement re-embeds only where the base mesh changed, and every
    /// check still runs on the whole result.
    pub fn reslot(self, base: &BaseMesh) -> Previous {
        let new: HashMap<[u32; 3], u32> = base.faces().map(|(f, c)| (c, f)).collect();
        let to: HashMap<u32, u32> = self
            .faces
            .iter()
            .filter_map(|(&old, c)| Some((old, *new.get(c)?)))
            .collect();
        let faces = self
            .faces
            .iter()
            .filter_map(|(old, &c)| Some((*to.get(old)?, c)))
            .collect();
        let mut emb = self.emb;
        emb.maps.retain_mut(|m| match to.get(&m.face) {
            Some(&f) => {
                m.face = f;
                true
            }
            None => false,
        });
        Previous { faces, emb }
    }
}

/// What a local update kept and what it did again.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct LocalStats {
    /// Curves kept.
    pub kept_curves: usize,
    /// Curves in all.
    pub curves: usize,
    /// Curved triangles whose Floater map was kept.
    pub kept_maps: usize,
    /// Curved triangles in all.
    pub maps: usize,
    /// Tries after the first, each opening the faces around where the one before failed.
    pub openings: usize,
}

/// Tries of a local update after the first, each opening the faces where the one before failed.
pub const MAX_OPENINGS: usize = 3;

/// The face slots of `base` unchanged since `prev`: the same corners in the same order, and no
/// base vertex inserted since inside their previous curved triangle (module doc).
pub fn unchanged(base: &BaseMesh, prev: &Previous) -> HashSet<u32> {
    let corners: HashSet<u32> = prev.faces.values().flatten().copied().collect();
    let new: HashSet<u32> = base
        .faces()
        .flat_map(|(_, c)| c)
        .filter(|v| !corners.contains(v))
        .collect();
    let mut same: HashSet<u32> = base
        .faces()
        .filter(|(f, c)| prev.faces.get(f) == Some(c))
        .map(|(f, _)| f)
        .collect();
    for f in held(prev, &new) {
        same.remove(&f);
    }
    same
}

/// The face slots of the previous embedding's curved triangles that hold one of `vertices` of
/// S_T (inside or on their curves).
fn held(prev: &Previous, vertices: &HashSet<u32>) -> Vec<u32> {
    if vertices.is_empty() {
        return Vec::new();
    }
    prev.emb
        .maps
        .iter()
        .filter(|m| vertices.iter().any(|v| m.uv.contains_key(v)))
        .map(|m| m.face)
        .collect()
}

/// The faces `open` makes count as changed: around each of its base vertices in `base`, and
/// the previous curved triangles holding it.
fn opened(base: &BaseMesh, prev: &Previous, open: &HashSet<u32>) -> HashSet<u32> {
    let mut faces: HashSet<u32> = open
        .iter()
        .flat_map(|&v| base.faces_around(v).iter().copied())
        .collect();
    faces.extend(held(prev, open));
    faces
}

/// The curves of `prev` to keep (module doc), by base edge (a, b), a < b.
pub fn kept_curves(
    base: &BaseMesh,
    prev: &Previous,
    same: &HashSet<u32>,
) -> HashMap<(u32, u32), Curve> {
    prev.emb
        .emb
        .curves
        .iter()
        .filter(|c| {
            let faces = [base.face_of_edge(c.a, c.b), base.face_of_edge(c.b, c.a)];
            let mut inner = c.nodes.iter().skip(1).take(c.nodes.len().saturating_sub(2));
            faces.iter().all(|f| f.is_some_and(|f| same.contains(&f)))
                && !inner.any(|n| matches!(*n, Node::Vertex(v) if base.is_base(v)))
        })
        .map(|c| ((c.a, c.b), c.clone()))
        .collect()
}

/// Embed `base` keeping what `prev` embedded where the base mesh did not change (module doc).
pub fn embed_local(
    k: &SimplicialSurface,
    base: &BaseMesh,
    prev: &Previous,
) -> Result<(Embedded, LocalStats), Failure> {
    embed_local_ticking(k, base, prev, &mut |_, _| {})
}

/// [`embed_local`] with `tick` following each tracing ([`super::route::curves_keeping`]).
pub fn embed_local_ticking(
    k: &SimplicialSurface,
    base: &BaseMesh,
    prev: &Previous,
    tick: &mut dyn FnMut(usize, usize),
) -> Result<(Embedded, LocalStats), Failure> {
    let unch = unchanged(base, prev);
    let mut open: HashSet<u32> = HashSet::new();
    let mut openings = 0;
    loop {
        let mut same = unch.clone();
        for f in opened(base, prev, &open) {
            same.remove(&f);
        }
        match embed_with(k, base, prev, &same, tick) {
            Ok((e, st)) => return Ok((e, LocalStats { openings, ..st })),
            Err(f) if openings < MAX_OPENINGS && (f.edge.is_some() || !f.faces.is_empty()) => {
                let ends: Vec<u32> = f
                    .edge
                    .iter()
                    .chain(&f.blocked)
                    .flat_map(|&(a, b)| [a, b])
                    .chain(f.faces.iter().filter_map(|&g| base.face(g)).flatten())
                    .collect();
                let before = open.len();
                open.extend(ends);
                if open.len() == before {
                    // The same ends again: one ring wider.
                    let ring: Vec<u32> = opened(base, prev, &open)
                        .into_iter()
                        .filter_map(|f| base.face(f))
                        .flatten()
                        .collect();
                    open.extend(ring);
                }
                openings += 1;
            }
            Err(f) => return Err(f),
        }
    }
}

/// One try of [`embed_local`] with the faces `same` taken as unchanged.
fn embed_with(
    k: &SimplicialSurface,
    base: &BaseMesh,
    prev: &Previous,
    same: &HashSet<u32>,
    tick: &mut dyn FnMut(usize, usize),
) -> Result<(Embedded, LocalStats), Failure> {
    let kept = kept_curves(base, prev, same);
    let old_maps: HashMap<u32, &RegionMap> = prev.emb.maps.iter().map(|m| (m.face, m)).collect();
    let n = k.vertex_slots() as u32;
    let mut kept_maps = 0;
    let e = embed_keeping(
        k,
        base,
        &kept,
        |f, pieces, ov, emb| {
            if !same.contains(&f) {
                return None;
            }
            let c = base.face(f)?;
            let old = old_maps.get(&f)?;
            if old.pieces.len() != pieces.len() {
                return None;
            }
            // Overlay ids of the nodes of the face's three curves, old to new (the vertices of S_T
            // keep theirs: the overlay numbers them first).
            let mut ids: HashMap<u32, u32> = HashMap::new();
            for i in 0..3 {
                let (u, w) = (c[i], c[(i + 1) % 3]);
                let key = (u.min(w), u.max(w));
                if !kept.contains_key(&key) {
                    return None;
                }
                let old_ids = prev
                    .emb
                    .overlay
                    .curve_ids
                    .get(*prev.emb.emb.index.get(&key)?)?;
                let new_ids = ov.curve_ids.get(*emb.index.get(&key)?)?;
                if old_ids.len() != new_ids.len() {
                    return None;
                }
                ids.extend(old_ids.iter().copied().zip(new_ids.iter().copied()));
            }
            let mut uv = HashMap::with_capacity(old.uv.len());
            for (&id, &p) in &old.uv {
                let to = if id < n { id } else { *ids.get(&id)? };
                uv.insert(to, p);
            }
            if pieces
                .iter()
                .any(|&p| ov.pieces[p].v.iter().any(|v| !uv.contains_key(v)))
            {
                return None;
            }
            kept_maps += 1;
            Some(RegionMap {
                face: f,
                pieces: pieces.to_vec(),
                uv,
                interior: old.interior,
            })
        },
        tick,
    )?;
    let st = LocalStats {
        kept_curves: e.emb.stats.kept,
        curves: e.emb.curves.len(),
        kept_maps,
        maps: e.maps.len(),
        openings: 0,
    };
    Ok((e, st))
}
