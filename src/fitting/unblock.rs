//! The base-mesh change where a base edge has no curve (seed 002, Part II, "Discrete
//! Geodesics", Adaptive Fitting: "when defining geodesic triangles, we can violate the
//! manifold property of the geodesic mesh … Solution: compute the geodesic curve AB as the
//! geodesic resulting from using the concatenation of geodesics AC and CB as initial
//! approximation"). SPEC `AF-embedding`.
//!
//! **The reading (a choice; the slides give a figure, no rule for C).** In the graph of the
//! initial curves (`geodesic`) a path A → C → B through a vertex C of S_T that is not a base
//! vertex is a path A → B, so where no path joins A and B, the concatenation AC·CB can only
//! help through a C the curves may not pass: a base vertex. C is therefore a vertex of S_T made
//! a base vertex on the blocked edge: the stellar edge split of AB at C (a face split at C,
//! then the flip of AB to C's opposite vertex; when that flip is refused, the face split
//! stands). The old edge AB is then embedded as the concatenation of the curves of AC and CB,
//! each traced on its own (the tutorial's "initial approximation", shortened as every curve).
//! C is the vertex of S_T the simplification parametrizes in AB's two base faces with the
//! smallest |AC| + |CB| (the one nearest AB in the sense of the concatenation's length), ties
//! by the smaller id; with none there, the same among the faces around A and B (a face split
//! next to AB, which gives AB a smaller region).
//!
//! **When no vertex of S_T is left near AB** (every one in the faces around A and B is a base
//! vertex already: anchor's flat strips), the base vertex C opposite AB with the smallest
//! |AC| + |CB| is removed from the base mesh instead (the simplification's weld, with its
//! limits): the concatenation AC·CB then runs through C as a vertex of S_T, which the curve of
//! AB may pass.
//!
//! **The walk (bounded).** The edge is flipped first, once per pair of base vertices, when the
//! flipped base mesh was never embedded (its other diagonal may have room); otherwise it is
//! split at C. No base mesh is embedded twice (the caller's record of the failed ones), a
//! vertex of S_T the walk inserted is never removed by it and one it removed never inserted,
//! so the walk ends: at most one flip per pair of vertices and one split and one removal per
//! vertex of S_T; [`MAX_CHANGES`] on top is a time bound (each round embeds S_T again). When
//! the walk gives up, [`GiveUp`] names the edge.

use super::base::{BaseMesh, Param, RemovalLimits};
use super::geodesic::dist;
use std::collections::HashSet;

/// Base-mesh changes at most per fit (a time bound: each change embeds S_T again).
pub const MAX_CHANGES: usize = 64;

/// What one change did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Change {
    /// The edge a–b was flipped.
    Flipped,
    /// No vertex of S_T was left to split a–b at: the base vertex `c` opposite it (the C of
    /// the concatenation AC·CB, already a base vertex) was removed from the base mesh, so the
    /// curve of a–b may pass through it.
    Removed {
        /// The removed base vertex.
        c: u32,
    },
    /// The edge a–b was split at vertex `c` of S_T (the AC·CB rule); `edge_split` says
    /// whether the old edge went (an edge split) or only its face was split.
    Split {
        /// The new base vertex.
        c: u32,
        /// Whether a–b was flipped away after the face split.
        edge_split: bool,
    },
}

/// One change of the walk: the blocked edge and what was done there.
pub type Step = ((u32, u32), Change);

/// Why the walk stopped with an edge still without a curve.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum GiveUp {
    /// No vertex of S_T is left near the edge to split it at, and no base vertex opposite it
    /// can be removed.
    #[error("base edge {a}-{b} has no curve, no vertex of S_T to split it at and no opposite base vertex to remove (AC·CB rule)")]
    NoSplitVertex {
        /// Base vertex.
        a: u32,
        /// Base vertex.
        b: u32,
    },
    /// The split was refused.
    #[error("base edge {a}-{b} has no curve and its split at vertex {c} of S_T was refused")]
    Refused {
        /// Base vertex.
        a: u32,
        /// Base vertex.
        b: u32,
        /// The vertex of S_T.
        c: u32,
    },
    /// [`MAX_CHANGES`] spent.
    #[error("base edge {a}-{b} has no curve after {changes} base-mesh changes (the bound)")]
    Bound {
        /// Base vertex.
        a: u32,
        /// Base vertex.
        b: u32,
        /// Changes made.
        changes: usize,
    },
}

/// The state of the walk over one fit.
#[derive(Debug, Clone, Default)]
pub struct Walk {
    /// Pairs of base vertices flipped already.
    flipped: HashSet<(u32, u32)>,
    /// Changes made.
    pub changes: usize,
    /// Of them, splits.
    pub splits: usize,
    /// Every change: the blocked edge and what was done.
    pub log: Vec<Step>,
    /// Vertices of S_T the walk made base vertices (never removed again).
    inserted: HashSet<u32>,
    /// Base vertices the walk removed (never inserted again).
    removed: HashSet<u32>,
}

/// The vertex C of the AC·CB rule for base edge a–b (module doc), or None.
pub fn split_vertex(base: &BaseMesh, a: u32, b: u32, removed: &HashSet<u32>) -> Option<u32> {
    let pos = base.positions();
    let own: Vec<u32> = [(a, b), (b, a)]
        .iter()
        .filter_map(|&(u, w)| base.face_of_edge(u, w))
        .collect();
    let around: Vec<u32> = [a, b]
        .iter()
        .flat_map(|&v| base.faces_around(v).iter().copied())
        .collect();
    let best = |faces: &[u32]| {
        faces
            .iter()
            .flat_map(|&f| base.members(f).iter().copied())
            .filter(|&c| {
                !removed.contains(&c)
                    && matches!(base.params().get(c as usize), Some(Param::Face { .. }))
            })
            .map(|c| {
                let p = pos[c as usize];
                (dist(pos[a as usize], p) + dist(p, pos[b as usize]), c)
            })
            .min_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)))
            .map(|(_, c)| c)
    };
    best(&own).or_else(|| best(&around))
}

impl Walk {
    /// Change the base mesh at base edge a–b, which has no curve (module doc). `tried` says
    /// whether a base mesh (its sorted faces) was embedded before.
    pub fn change(
        &mut self,
        base: &mut BaseMesh,
        a: u32,
        b: u32,
        lim: &RemovalLimits,
        tried: impl Fn(&BaseMesh) -> bool,
    ) -> Result<Change, GiveUp> {
        if self.changes >= MAX_CHANGES {
            return Err(GiveUp::Bound {
                a,
                b,
                changes: self.changes,
            });
        }
        let pair = (a.min(b), a.max(b));
        if self.flipped.insert(pair) {
            let before = base.clone();
            if base.flip(a, b).is_ok() && !tried(base) {
                self.changes += 1;
                self.log.push(((a, b), Change::Flipped));
                return Ok(Change::Flipped);
            }
            *base = before;
        }
        let Some(c) = split_vertex(base, a, b, &self.removed) else {
            return self.weld(base, a, b, lim, tried);
        };
        let mut m = base.clone();
        if m.split_face(c).is_err() {
            return Err(GiveUp::Refused { a, b, c });
        }
        // The face split at C leaves a–b with C opposite on one side; flipping it away gives
        // the edge split (a–C, C–b instead of a–b). A split on the edge in parameter space
        // (`split_face`'s 2 → 4) has removed it already.
        let opposite = [(a, b), (b, a)].iter().any(|&(u, w)| {
            m.face_of_edge(u, w)
                .and_then(|f| m.face(f))
                .is_some_and(|t| t.contains(&c))
        });
        let edge_split = m.face_of_edge(a, b).is_none() || (opposite && m.flip(a, b).is_ok());
        if tried(&m) {
            return self.weld(base, a, b, lim, tried);
        }
        *base = m;
        self.inserted.insert(c);
        self.changes += 1;
        self.splits += 1;
        let ch = Change::Split { c, edge_split };
        self.log.push(((a, b), ch));
        Ok(ch)
    }

    /// [`Walk::change`] at every blocked edge still in the base mesh, in order, each change kept
    /// only when `valid` accepts the base mesh with it (and the changes kept before it); a
    /// refused change is undone, walk state included, so it costs the others nothing. Returns
    /// the changes kept and the first reason the walk gave up at an edge. (All changes at once,
    /// undone together when the result was refused, cost koala at ε = 10⁻² one whole embedding
    /// of S_T per change: 17 blocked edges, one of whose changes the validator refused.)
    pub fn change_all(
        &mut self,
        base: &mut BaseMesh,
        blocked: &[(u32, u32)],
        lim: &RemovalLimits,
        tried: impl Fn(&BaseMesh) -> bool,
        valid: impl Fn(&BaseMesh) -> bool,
    ) -> (Vec<Step>, Option<GiveUp>) {
        let mut done = Vec::new();
        let mut gave_up = None;
        for &(a, b) in blocked {
            // An earlier change of this call may have taken the edge away already.
            if base.face_of_edge(a, b).is_none() {
                continue;
            }
            let (before, walk_before) = (base.clone(), self.clone());
            match self.change(base, a, b, lim, &tried) {
                Ok(ch) if valid(base) => done.push(((a, b), ch)),
                Ok(_) => {
                    *base = before;
                    *self = walk_before;
                }
                Err(g) => {
                    gave_up.get_or_insert(g);
                }
            }
        }
        (done, gave_up)
    }

    /// Where no vertex of S_T is left near a–b (every one nearby is a base vertex), the base
    /// vertex C opposite a–b with the shortest |AC| + |CB| whose removal (the simplification's
    /// weld, with its limits) gives a base mesh never embedded is removed: then the curve of
    /// a–b may pass through C, a vertex of S_T like any other.
    fn weld(
        &mut self,
        base: &mut BaseMesh,
        a: u32,
        b: u32,
        lim: &RemovalLimits,
        tried: impl Fn(&BaseMesh) -> bool,
    ) -> Result<Change, GiveUp> {
        let pos = base.positions();
        let mut opposite: Vec<(f64, u32)> = [(a, b), (b, a)]
            .iter()
            .filter_map(|&(u, w)| base.face_of_edge(u, w).and_then(|f| base.face(f)))
            .flat_map(|t| t.into_iter().filter(|&c| c != a && c != b))
            .map(|c| {
                let p = pos[c as usize];
                (dist(pos[a as usize], p) + dist(p, pos[b as usize]), c)
            })
            .collect();
        opposite.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        for (_, c) in opposite {
            if self.inserted.contains(&c) {
                continue;
            }
            let mut m = base.clone();
            if m.remove_vertex(c, lim).is_ok() && !tried(&m) {
                *base = m;
                self.removed.insert(c);
                self.changes += 1;
                let ch = Change::Removed { c };
                self.log.push(((a, b), ch));
                return Ok(ch);
            }
        }
        Err(GiveUp::NoSplitVertex { a, b })
    }
}
