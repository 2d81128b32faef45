//! Connectivity needed by Stam's evaluation, written once over a small trait: the only
//! question asked of a mesh is "which vertex completes the oriented triangle (a, b, ?)".
//!
//! Three meshes answer it: K itself ([`BaseTopology`]), K after one Loop step
//! ([`SubTopology`], without building it: its vertices are named by the vertex or edge of K
//! they come from), and the local mesh of one patch net ([`LocalMesh`]), from which the
//! subdivision matrices are derived.

use crate::mesh::{SimplicialSurface, VertexId};

/// An oriented triangle mesh seen through one query.
pub trait Topology {
    /// Vertex names.
    type P: Copy + Eq + std::fmt::Debug;
    /// The vertex c with (a, b, c) a triangle in the mesh's orientation, if [a, b] is an edge.
    fn third(&self, a: Self::P, b: Self::P) -> Option<Self::P>;
    /// [`ring`]; a mesh that stores its rings may answer faster (same answer).
    fn ring_of(
        &self,
        v: Self::P,
        start: Self::P,
        cap: usize,
    ) -> Result<Vec<Self::P>, MissingTriangle>
    where
        Self: Sized,
    {
        walk_ring(self, v, start, cap)
    }
}

/// A connectivity defect found while gathering a net (cannot happen on a closed simplicial
/// surface; reported rather than assumed).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("no triangle on the oriented edge ({a}, {b}) while gathering a Loop patch net")]
pub struct MissingTriangle {
    /// Origin of the edge (debug form of the vertex name).
    pub a: String,
    /// Destination of the edge.
    pub b: String,
}

fn third_or<T: Topology>(t: &T, a: T::P, b: T::P) -> Result<T::P, MissingTriangle> {
    t.third(a, b).ok_or_else(|| MissingTriangle {
        a: format!("{a:?}"),
        b: format!("{b:?}"),
    })
}

/// The ring of v counter-clockwise from `start`: r₀ = start, r_{i+1} = third(v, rᵢ); at most
/// `cap` vertices.
pub fn ring<T: Topology>(
    t: &T,
    v: T::P,
    start: T::P,
    cap: usize,
) -> Result<Vec<T::P>, MissingTriangle> {
    t.ring_of(v, start, cap)
}

/// [`ring`] by walking [`Topology::third`].
pub fn walk_ring<T: Topology>(
    t: &T,
    v: T::P,
    start: T::P,
    cap: usize,
) -> Result<Vec<T::P>, MissingTriangle> {
    let mut r = vec![start];
    loop {
        let next = third_or(t, v, *r.last().unwrap_or(&start))?;
        if next == start {
            return Ok(r);
        }
        if r.len() >= cap {
            return Err(MissingTriangle {
                a: format!("{v:?}"),
                b: format!("ring longer than {cap}"),
            });
        }
        r.push(next);
    }
}

/// The net of the patch over the triangle (v, a, b): [v, r₀ = a, r₁ = b, r₂, …, r_{N−1},
/// o₀, …, o₄] (N + 6 points; Stam's layout, [`super::regular::REGULAR_NET`] for N = 6).
/// a and b must have valence 6 (checked: their rings must close after o₂ resp. o₄).
pub fn gather_net<T: Topology>(
    t: &T,
    v: T::P,
    a: T::P,
    b: T::P,
    cap: usize,
) -> Result<Vec<T::P>, MissingTriangle> {
    let r = ring(t, v, a, cap)?;
    let n = r.len();
    if n < 3 || r[1] != b {
        return Err(MissingTriangle {
            a: format!("{v:?}"),
            b: format!("{a:?} not followed by {b:?}"),
        });
    }
    // Ring of a from v: v, r_{N−1}, o₀, o₁, o₂, b. Ring of b from v: v, a, o₂, o₃, o₄, r₂.
    let o0 = third_or(t, a, r[n - 1])?;
    let o1 = third_or(t, a, o0)?;
    let o2 = third_or(t, a, o1)?;
    let o3 = third_or(t, b, o2)?;
    let o4 = third_or(t, b, o3)?;
    if third_or(t, a, o2)? != b || third_or(t, b, o4)? != r[2 % n] {
        return Err(MissingTriangle {
            a: format!("{a:?}"),
            b: format!("valence of {a:?} or {b:?} is not 6"),
        });
    }
    let mut net = Vec::with_capacity(n + 6);
    net.push(v);
    net.extend(r);
    net.extend([o0, o1, o2, o3, o4]);
    Ok(net)
}

/// K with its consistent orientation.
pub struct BaseTopology<'a>(pub &'a SimplicialSurface);

impl Topology for BaseTopology<'_> {
    type P = VertexId;
    fn third(&self, a: VertexId, b: VertexId) -> Option<VertexId> {
        let k = self.0;
        k.halfedge(a, b).map(|h| k.dest(k.next(h)))
    }
    /// K stores each ring: [`link_from`] (anything else, e.g. `start` not a neighbour,
    /// walks, and reports what is missing).
    fn ring_of(
        &self,
        v: VertexId,
        start: VertexId,
        cap: usize,
    ) -> Result<Vec<VertexId>, MissingTriangle> {
        if let Some(r) = link_from(self.0, v, start).filter(|_| self.0.degree(v) as usize <= cap) {
            return Ok(r.collect());
        }
        walk_ring(self, v, start, cap)
    }
}

/// The ring of v in K from `start` ([`ring`] without walking): `SimplicialSurface::link`
/// rotated, since the link runs the way `third` walks. `None` if `start` is not in it.
pub fn link_from(
    k: &SimplicialSurface,
    v: VertexId,
    start: VertexId,
) -> Option<impl Iterator<Item = VertexId> + '_> {
    let link = k.link(v);
    let at = link.iter().position(|&x| x == start)?;
    Some(link[at..].iter().chain(&link[..at]).copied())
}

/// A vertex of K after one Loop step: the vertex point of a vertex of K, or the edge point of
/// an edge of K (endpoints sorted).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum SubPoint {
    /// The vertex point of a vertex of K.
    Vertex(VertexId),
    /// The edge point of the edge [a, b] of K, a < b.
    Edge(VertexId, VertexId),
}

impl SubPoint {
    /// The edge point of [a, b].
    pub fn edge(a: VertexId, b: VertexId) -> SubPoint {
        if a < b {
            SubPoint::Edge(a, b)
        } else {
            SubPoint::Edge(b, a)
        }
    }
}

/// K after one Loop step: each triangle (x, y, z) of K becomes (x, xy, xz), (xy, y, yz),
/// (xz, yz, z), (xy, yz, xz).
pub struct SubTopology<'a>(pub BaseTopology<'a>);

impl Topology for SubTopology<'_> {
    type P = SubPoint;
    fn third(&self, p: SubPoint, q: SubPoint) -> Option<SubPoint> {
        let base = &self.0;
        let other = |e: (VertexId, VertexId), w: VertexId| -> Option<VertexId> {
            if e.0 == w {
                Some(e.1)
            } else if e.1 == w {
                Some(e.0)
            } else {
                None
            }
        };
        match (p, q) {
            (SubPoint::Vertex(w), SubPoint::Edge(a, b)) => {
                // (x, xy) → xz; (y, yz) → xy; (z, xz) → yz: all E(w, third(w, o)).
                let o = other((a, b), w)?;
                Some(SubPoint::edge(w, base.third(w, o)?))
            }
            (SubPoint::Edge(a, b), SubPoint::Vertex(w)) => {
                // (xy, y) → yz; (xz, x) → xy: all E(w, third(o, w)).
                let o = other((a, b), w)?;
                Some(SubPoint::edge(w, base.third(o, w)?))
            }
            (SubPoint::Edge(a, b), SubPoint::Edge(c, d)) => {
                let (common, d1, d2) = if a == c {
                    (a, b, d)
                } else if a == d {
                    (a, b, c)
                } else if b == c {
                    (b, a, d)
                } else if b == d {
                    (b, a, c)
                } else {
                    return None;
                };
                if d1 == d2 {
                    return None;
                }
                if base.third(common, d1) == Some(d2) {
                    // Corner triangle (common, E(common,d1), E(common,d2)).
                    Some(SubPoint::Vertex(common))
                } else if base.third(common, d2) == Some(d1) {
                    // Middle triangle of (common, d2, d1).
                    Some(SubPoint::edge(d1, d2))
                } else {
                    None
                }
            }
            (SubPoint::Vertex(_), SubPoint::Vertex(_)) => None,
        }
    }
}

/// A small mesh given by its oriented triangles (the local mesh of a patch net).
pub struct LocalMesh(pub Vec<[usize; 3]>);

impl Topology for LocalMesh {
    type P = usize;
    fn third(&self, a: usize, b: usize) -> Option<usize> {
        self.0.iter().find_map(|t| {
            (0..3).find_map(|i| (t[i] == a && t[(i + 1) % 3] == b).then_some(t[(i + 2) % 3]))
        })
    }
}

impl LocalMesh {
    /// The local mesh of the net of valence n: the n triangles around v, the four more around
    /// r₀ and the three more around r₁ (indices as in [`gather_net`]).
    pub fn patch(n: usize) -> LocalMesh {
        let r = |i: usize| 1 + i % n;
        let o = |j: usize| n + 1 + j;
        let mut f: Vec<[usize; 3]> = (0..n).map(|i| [0, r(i), r(i + 1)]).collect();
        f.extend([
            [r(0), r(n - 1), o(0)],
            [r(0), o(0), o(1)],
            [r(0), o(1), o(2)],
            [r(0), o(2), r(1)],
            [r(1), o(2), o(3)],
            [r(1), o(3), o(4)],
            [r(1), o(4), r(2)],
        ]);
        LocalMesh(f)
    }
}
