//! The plan of each face of K (one Stam patch, or four after one internal Loop step) and the
//! point table of one Loop step its nets index; one function for where a point of a split
//! face lands, shared by the generic evaluation, the f64 hot path (`fast`) and the weights
//! (`linear`).

use super::error::{LoopError, MAX_VALENCE};
use super::topology::{
    gather_net, ring, BaseTopology, MissingTriangle, SubPoint, SubTopology, Topology,
};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::Scalar;

/// A patch: its net (indices into the point table), first point = the patch corner at
/// (x, y) = (0, 0), and its valence (6 = regular).
#[derive(Debug, Clone)]
pub(super) struct Patch {
    pub(super) valence: u32,
    pub(super) net: Box<[u32]>,
}

#[derive(Debug, Clone)]
pub(super) enum Plan {
    /// One patch; `rot` = which stored corner is the patch's first corner.
    Direct { rot: u8, patch: Patch },
    /// Four sub-patches after one internal step: corner c₀, c₁, c₂, middle.
    Split(Box<[Patch; 4]>),
}

/// How a point of the table is computed.
#[derive(Debug, Clone)]
pub(super) enum Stencil {
    /// A vertex of K.
    Base,
    /// An entry of the point table no face uses (the vertex point of an empty vertex slot,
    /// the edge point of a halfedge a → b with a > b).
    Unused,
    /// Vertex point: centre and ring.
    Vertex(VertexId, Box<[VertexId]>),
    /// Edge point: [a, b] and the opposite vertices c, d.
    Edge([VertexId; 4]),
}

/// The point table of K after one Loop step, indexed by a function of K alone (so faces are
/// planned in parallel): the vertices of K, then the vertex point of each vertex slot, then
/// the edge point of each halfedge a → b with a < b (the other halfedges' entries are unused).
pub(super) struct PointTable<'a> {
    pub(super) k: &'a SimplicialSurface,
    pub(super) slots: usize,
}

impl PointTable<'_> {
    pub(super) fn len(&self) -> usize {
        2 * self.slots + self.k.num_halfedges()
    }

    pub(super) fn sub_index(&self, p: SubPoint) -> Result<u32, MissingTriangle> {
        let i = match p {
            SubPoint::Vertex(v) => self.slots + v.idx(),
            SubPoint::Edge(a, b) => {
                let h = self.k.halfedge(a, b).ok_or_else(|| MissingTriangle {
                    a: format!("{a:?}"),
                    b: format!("{b:?}"),
                })?;
                2 * self.slots + h.idx()
            }
        };
        // `new` checked that the table's length fits in u32.
        Ok(i as u32)
    }

    /// The stencil of entry i (`None` for an unused entry).
    pub(super) fn stencil(&self, i: usize) -> Result<Option<Stencil>, MissingTriangle> {
        let (k, slots) = (self.k, self.slots);
        let t = BaseTopology(k);
        if i < slots {
            return Ok(Some(Stencil::Base));
        }
        if i < 2 * slots {
            let v = VertexId((i - slots) as u32);
            let Some(start) = k.link_vertex(v, 0) else {
                return Ok(None);
            };
            let r = ring(&t, v, start, k.num_faces() + 3)?;
            return Ok(Some(Stencil::Vertex(v, r.into_boxed_slice())));
        }
        let h = crate::mesh::HalfedgeId((i - 2 * slots) as u32);
        let (a, b) = (k.origin(h), k.dest(h));
        if a >= b {
            return Ok(None);
        }
        let miss = || MissingTriangle {
            a: format!("{a:?}"),
            b: format!("{b:?}"),
        };
        let c = t.third(a, b).ok_or_else(miss)?;
        let d = t.third(b, a).ok_or_else(miss)?;
        Ok(Some(Stencil::Edge([a, b, c, d])))
    }
}

/// The plan of face f of K: one patch (at most one corner of valence ≠ 6) or four
/// sub-patches after one Loop step, their nets as indices into the [`PointTable`].
pub(super) fn plan_of(k: &SimplicialSurface, f: FaceId) -> Result<Plan, LoopError> {
    let table = PointTable {
        k,
        slots: k.vertex_slots(),
    };
    let cap = MAX_VALENCE as usize + 1;
    let c = k.face(f);
    let irregular: Vec<usize> = (0..3).filter(|&i| k.degree(c[i]) != 6).collect();
    let err = |source| LoopError::Net { face: f.0, source };
    if irregular.len() <= 1 {
        let rot = irregular.first().copied().unwrap_or(0);
        let (v, a, bb) = (c[rot], c[(rot + 1) % 3], c[(rot + 2) % 3]);
        let net = gather_net(&BaseTopology(k), v, a, bb, cap).map_err(err)?;
        return Ok(Plan::Direct {
            rot: rot as u8,
            patch: Patch {
                valence: k.degree(v),
                net: net.iter().map(|p| p.0).collect(),
            },
        });
    }
    let sub_t = SubTopology(BaseTopology(k));
    let e = |i: usize, j: usize| SubPoint::edge(c[i], c[j]);
    let vp = |i: usize| SubPoint::Vertex(c[i]);
    let tris = [
        (vp(0), e(0, 1), e(0, 2), k.degree(c[0])),
        (vp(1), e(1, 2), e(0, 1), k.degree(c[1])),
        (vp(2), e(0, 2), e(1, 2), k.degree(c[2])),
        (e(0, 1), e(1, 2), e(0, 2), 6),
    ];
    let mut patches = Vec::with_capacity(4);
    for (v, a, bb, valence) in tris {
        let net = gather_net(&sub_t, v, a, bb, cap).map_err(err)?;
        let idx = net
            .into_iter()
            .map(|p| table.sub_index(p))
            .collect::<Result<Box<[u32]>, _>>()
            .map_err(err)?;
        patches.push(Patch { valence, net: idx });
    }
    let arr: [Patch; 4] = patches.try_into().map_err(|_| LoopError::Eigen(0))?;
    Ok(Plan::Split(Box::new(arr)))
}

/// The sub-triangle of one Loop step that holds the point of barycentric coordinates `sb`
/// (w.r.t. the stored corners): corner triangle c when sb[c] ≥ 1/2 (first such c), else the
/// middle one, 3. One function for the generic evaluation and the f64 hot path (`fast`).
pub(super) fn split_sub_face<S: Scalar>(sb: &[S; 3], prec: u32) -> usize {
    let half = S::from_ratio(1, 2, prec);
    (0..3).find(|&c| sb[c].lt(&half).is_false()).unwrap_or(3)
}

/// In f64: the sub-triangle of a split face holding `sb` ([`split_sub_face`]) and the patch
/// coordinates there, 2·sb of the next two corners, or 1 − 2·sb in the middle (as
/// `LoopSurface::jet`); one function for the hot path (`fast`) and the weights (`linear`).
pub(super) fn split_patch_point(sb: &[f64; 3]) -> (usize, f64, f64) {
    match split_sub_face(sb, 53) {
        3 => (3, 1.0 - 2.0 * sb[0], 1.0 - 2.0 * sb[1]),
        c => (c, 2.0 * sb[(c + 1) % 3], 2.0 * sb[(c + 2) % 3]),
    }
}
