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
}

/// The face slots of `base` unchanged since `prev` (module doc).
pub fn unchanged(base: &BaseMesh, prev: &Previous) -> HashSet<u32> {
    base.faces()
        .filter(|(f, c)| prev.faces.get(f) == Some(c))
        .map(|(f, _)| f)
        .collect()
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
    let same = unchanged(base, prev);
    let kept = kept_curves(base, prev, &same);
    let old_maps: HashMap<u32, &RegionMap> = prev.emb.maps.iter().map(|m| (m.face, m)).collect();
    let n = k.vertex_slots() as u32;
    let mut kept_maps = 0;
    let e = embed_keeping(k, base, &kept, |f, pieces, ov, emb| {
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
    })?;
    let st = LocalStats {
        kept_curves: e.emb.stats.kept,
        curves: e.emb.curves.len(),
        kept_maps,
        maps: e.maps.len(),
    };
    Ok((e, st))
}
