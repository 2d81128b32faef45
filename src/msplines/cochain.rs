//! Sec. 6.1: 1-forms on a mesh as maps from oriented edges (half-edges) to numbers,
//! ω[v_i, v_j] = −ω[v_j, v_i]. Each undirected edge is stored once, on its canonical half-edge
//! (the smaller id of the pair); [`EdgeIndex`] gives the sign of every half-edge.

use crate::mesh::{HalfedgeId, SimplicialSurface, VertexId};

/// Index of an undirected edge in an [`EdgeIndex`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
pub struct EdgeIdx(pub u32);

/// The undirected edges of a surface, numbered, with the orientation of every half-edge.
#[derive(Debug, Clone)]
pub struct EdgeIndex {
    edge_of: Vec<u32>,
    positive: Vec<bool>,
    canonical: Vec<HalfedgeId>,
}

impl EdgeIndex {
    /// Number the edges of `k` by their canonical half-edges.
    pub fn new(k: &SimplicialSurface) -> Self {
        let nh = k.num_halfedges();
        let mut edge_of = vec![0u32; nh];
        let mut positive = vec![false; nh];
        let mut canonical = Vec::with_capacity(nh / 2);
        for h in 0..nh {
            let t = k.twin(HalfedgeId(h as u32)).idx();
            if h < t {
                edge_of[h] = canonical.len() as u32;
                edge_of[t] = canonical.len() as u32;
                positive[h] = true;
                canonical.push(HalfedgeId(h as u32));
            }
        }
        EdgeIndex {
            edge_of,
            positive,
            canonical,
        }
    }
    /// Number of undirected edges.
    pub fn len(&self) -> usize {
        self.canonical.len()
    }
    /// True when there are no edges.
    pub fn is_empty(&self) -> bool {
        self.canonical.is_empty()
    }
    /// The edge of half-edge h.
    pub fn edge(&self, h: HalfedgeId) -> EdgeIdx {
        EdgeIdx(self.edge_of[h.idx()])
    }
    /// +1 when h is the canonical orientation of its edge, −1 otherwise.
    pub fn sign(&self, h: HalfedgeId) -> f64 {
        if self.positive[h.idx()] {
            1.0
        } else {
            -1.0
        }
    }
    /// Integer sign of h.
    pub(crate) fn isign(&self, h: HalfedgeId) -> i64 {
        if self.positive[h.idx()] {
            1
        } else {
            -1
        }
    }
    /// The canonical half-edge of edge e.
    pub fn canonical(&self, e: EdgeIdx) -> HalfedgeId {
        self.canonical[e.0 as usize]
    }
    /// ω\[h\] for a real 1-form stored per edge.
    pub fn eval(&self, form: &[f64], h: HalfedgeId) -> f64 {
        self.sign(h) * form[self.edge(h).0 as usize]
    }
    /// ω\[h\] for an integer 1-form stored per edge.
    pub fn eval_int(&self, form: &[i64], h: HalfedgeId) -> i64 {
        self.isign(h) * form[self.edge(h).0 as usize]
    }
    /// ω[u, w] for the edge from u to w, if it exists.
    pub fn eval_uv(
        &self,
        k: &SimplicialSurface,
        form: &[f64],
        u: VertexId,
        w: VertexId,
    ) -> Option<f64> {
        k.halfedge(u, w).map(|h| self.eval(form, h))
    }
}

/// The three half-edges of face f: [v0→v1, v1→v2, v2→v0].
pub(crate) fn face_halfedges(f: crate::mesh::FaceId) -> [HalfedgeId; 3] {
    let b = 3 * f.0;
    [HalfedgeId(b), HalfedgeId(b + 1), HalfedgeId(b + 2)]
}
