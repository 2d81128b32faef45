//! Tutorial Part IV (T 1894, 2251–2627): the index set I = {(σ, v)}, the three cases of the
//! gluing domains Ω_(τ,u)(η,w), the set K and the transition maps φ, on a simplicial surface.
//!
//! Everything here works in *plane coordinates*: a point of Ω_(σ,v) is represented by its
//! image q = f_(σ,v)(p) in the plane of P_v (the abstract view adds the rigid maps and the
//! separate copies). Then, for i = (τ, u), j = (η, w) (SPEC `SV-D7`, `SV-D9`):
//! 1. u = w: q ∈ Ω_ij ⇔ q ∈ W_i ∩ W_j, and φ_ji = f_j⁻¹∘f_i is the identity on q;
//! 2. u ≠ w, [u, w] an edge and (w ∈ τ or u ∈ η): q ∈ Ω_ij ⇔ q ∈ W_i, q in the report's
//!    Ω_uw (Def. 4.1.9) and g_(u,w)(q) ∈ W_j; φ_ji = f_j⁻¹∘g_(u,w)∘f_i is g_(u,w) on q;
//! 3. otherwise Ω_ij = ∅ (declared by T 2430–2442; whether the formula of case 2 would also
//!    give ∅ for adjacent u, w is the claim `SV-H`, see [`SigmaV::case3_formula`]).
//!
//! g_(u,w) is the report's map (Def. 4.1.8, [`crate::construction::maps`]), composed from the
//! shared elementary maps; its domain Ω_uw is decided by the branch-and-lens test that
//! `surface::pps` documents as equivalent to the literal Def. 4.1.9 (cross-checked in the
//! tests against [`crate::construction::maps::Ppm::in_omega_uw_literal`]).

use super::wedge::WedgeTable;
use crate::construction::maps::{
    f_v, g_v_inv, in_canonical_lens, polar, polar_inv, rotate_frac, EdgeConfig, Paper, Ppm, P2,
};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::Scalar;
use serde::Serialize;

/// A corner (σ, v) ∈ I: v and the label k of v's outgoing half-edge whose face is σ, so
/// σ = [v, s_v⁻¹(v′_k), s_v⁻¹(v′_{k+1})].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct Corner {
    /// The vertex v.
    pub v: VertexId,
    /// The label k (0..m_v).
    pub k: u32,
}

/// Index of a corner in I (0..3·n_t), the `Idx` of the abstract view.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
pub struct CornerId(pub u32);

/// Which case of T 2251–2442 a pair (i, j) falls in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum PairCase {
    /// (1) u = w.
    SameVertex,
    /// (2) u ≠ w, [u, w] an edge, w ∈ τ or u ∈ η: the edge configuration of [u, w].
    Edge(EdgeConfig),
    /// (3) with [u, w] an edge (neither w ∈ τ nor u ∈ η): declared empty.
    DeclaredEmptyEdge(EdgeConfig),
    /// (3) with u, w not adjacent: g_(u,w) does not exist; empty.
    NotAdjacent,
}

/// Errors naming the element involved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SigmaVError {
    /// A corner index outside 0..3·n_t.
    #[error("corner index {0} is not in I (0..3·n_t)")]
    NoSuchCorner(u32),
    /// κ outside (0, 1) (r_{v,σ} must lie strictly inside D_v, behind the centre).
    #[error("overlapping-point parameter κ = {0} is not in (0, 1) (SPEC SV-D3)")]
    BadKappa(f64),
    /// A point outside Ω_(σ,v) where one was required.
    #[error("({x}, {y}) is not in Ω of corner {corner} (T 2039/2112)")]
    NotInOmega {
        /// The corner index.
        corner: u32,
        /// First coordinate (plane of P_v).
        x: f64,
        /// Second coordinate.
        y: f64,
    },
    /// A face index out of range.
    #[error("face {0} is not a face of K")]
    NoSuchFace(FaceId),
    /// Bad barycentric coordinates given to eval.
    #[error("barycentric coordinates must be ≥ 0 and sum to 1, got {0:?}")]
    BadBarycentric([f64; 3]),
    /// Σγ at a point of Ω_i not decided positive (names the corner).
    #[error("Σγ is not decided positive at a point of Ω of corner {0}")]
    ZeroWeight(u32),
    /// A sampling level whose output would exceed the memory limit of Sec. 6.2 sampling
    /// (`surface::output::SAMPLE_MEMORY_LIMIT`).
    #[error("sampling level {0} would exceed the sampling memory limit")]
    LevelTooLarge(u32),
}

/// The (σ, v)-indexed gluing data of a simplicial surface (mesh tables only; the scalar
/// constants are passed in as a [`WedgeTable`]).
#[derive(Debug, Clone)]
pub struct SigmaV {
    /// κ of r_{v,σ}.
    pub kappa: f64,
    degree: Vec<u32>,
    /// offset[v]: CornerId of (v, 0); corners of v are offset[v]..offset[v]+m_v.
    offset: Vec<u32>,
    /// corner id → vertex.
    owner: Vec<VertexId>,
    /// link[offset[v] + i] = s_v⁻¹(v′_i).
    link: Vec<VertexId>,
    /// back[offset[v] + i] = s_u(v) for u = link[..].
    back: Vec<u32>,
    /// face[offset[v] + k] = the face σ of corner (v, k).
    face: Vec<FaceId>,
    faces: Vec<[VertexId; 3]>,
    degrees: Vec<u32>,
}

impl SigmaV {
    /// The data of K with overlapping-point parameter κ ∈ (0, 1).
    pub fn new(k: &SimplicialSurface, kappa: f64) -> Result<Self, SigmaVError> {
        if !(kappa > 0.0 && kappa < 1.0) {
            return Err(SigmaVError::BadKappa(kappa));
        }
        let slots = k.vertex_slots();
        let degree: Vec<u32> = (0..slots).map(|v| k.degree(VertexId(v as u32))).collect();
        let mut offset = vec![0u32; slots + 1];
        for v in 0..slots {
            let m = if degree[v] >= 3 { degree[v] } else { 0 };
            offset[v + 1] = offset[v] + m;
        }
        let n = offset[slots] as usize;
        let mut owner = vec![VertexId(0); n];
        let mut link = vec![VertexId(0); n];
        let mut back = vec![0u32; n];
        let mut face = vec![FaceId(0); n];
        for v in k.vertices() {
            if degree[v.idx()] < 3 {
                continue;
            }
            for (i, &h) in k.outgoing(v).iter().enumerate() {
                let c = offset[v.idx()] as usize + i;
                owner[c] = v;
                link[c] = k.dest(h);
                back[c] = k.label(k.twin(h));
                face[c] = k.face_of(h);
            }
        }
        let mut degrees: Vec<u32> = degree.iter().copied().filter(|&m| m >= 3).collect();
        degrees.sort_unstable();
        degrees.dedup();
        Ok(SigmaV {
            kappa,
            degree,
            offset,
            owner,
            link,
            back,
            face,
            faces: k.faces().map(|f| k.face(f)).collect(),
            degrees,
        })
    }

    /// |I| = Σ_v m_v = 3·n_t (T 3240).
    pub fn len(&self) -> usize {
        self.owner.len()
    }
    /// I = ∅.
    pub fn is_empty(&self) -> bool {
        self.owner.is_empty()
    }
    /// Number of triangles n_t.
    pub fn num_faces(&self) -> usize {
        self.faces.len()
    }
    /// The corners of face f in stored order.
    pub fn face_corners(&self, f: FaceId) -> Result<[VertexId; 3], SigmaVError> {
        self.faces
            .get(f.idx())
            .copied()
            .ok_or(SigmaVError::NoSuchFace(f))
    }
    /// The distinct vertex degrees of K.
    pub fn degrees(&self) -> &[u32] {
        &self.degrees
    }
    /// m_v (0 if v is not a vertex of K).
    pub fn degree(&self, v: VertexId) -> u32 {
        self.degree.get(v.idx()).copied().unwrap_or(0)
    }
    /// The corner with id c.
    pub fn corner(&self, c: CornerId) -> Result<Corner, SigmaVError> {
        let v = *self
            .owner
            .get(c.0 as usize)
            .ok_or(SigmaVError::NoSuchCorner(c.0))?;
        Ok(Corner {
            v,
            k: c.0 - self.offset[v.idx()],
        })
    }
    /// The id of (v, k).
    pub fn id(&self, c: Corner) -> CornerId {
        CornerId(self.offset[c.v.idx()] + c.k)
    }
    /// The face σ of a corner.
    pub fn face_of(&self, c: Corner) -> FaceId {
        self.face[self.id(c).0 as usize]
    }
    /// The corners at v.
    pub fn corners_at(&self, v: VertexId) -> impl Iterator<Item = Corner> {
        (0..self.degree(v)).map(move |k| Corner { v, k })
    }
    /// All corner ids.
    pub fn ids(&self) -> impl Iterator<Item = CornerId> {
        (0..self.len() as u32).map(CornerId)
    }
    /// s_v⁻¹(v′_i).
    pub fn link(&self, v: VertexId, i: u32) -> VertexId {
        self.link[(self.offset[v.idx()] + i) as usize]
    }
    /// s_v(u) for u in the link of v.
    pub fn label(&self, v: VertexId, u: VertexId) -> Option<u32> {
        let a = self.offset[v.idx()] as usize;
        let b = a + self.degree(v) as usize;
        self.link
            .get(a..b)?
            .iter()
            .position(|&x| x == u)
            .map(|i| i as u32)
    }
    /// The configuration of the oriented edge [v, s_v⁻¹(v′_i)].
    pub fn edge_config(&self, v: VertexId, i: u32) -> EdgeConfig {
        let s = (self.offset[v.idx()] + i) as usize;
        let u = self.link[s];
        EdgeConfig {
            m_u: self.degree(v),
            i,
            m_w: self.degree(u),
            j: self.back[s],
        }
    }

    /// The case of T 2251–2442 for i = (τ, u), j = (η, w).
    pub fn case(&self, i: Corner, j: Corner) -> PairCase {
        if i.v == j.v {
            return PairCase::SameVertex;
        }
        let Some(l) = self.label(i.v, j.v) else {
            return PairCase::NotAdjacent;
        };
        let e = self.edge_config(i.v, l);
        let (mu, mw) = (e.m_u, e.m_w);
        let w_in_tau = l == i.k || l == (i.k + 1) % mu;
        let u_in_eta = e.j == j.k || e.j == (j.k + 1) % mw;
        if w_in_tau || u_in_eta {
            PairCase::Edge(e)
        } else {
            PairCase::DeclaredEmptyEdge(e)
        }
    }

    /// q ∈ W_i, q in the plane of P_v.
    pub fn in_wedge<S: Scalar>(&self, t: &WedgeTable<S>, i: Corner, q: &P2<S>) -> bool {
        t.get(self.degree(i.v)).is_some_and(|w| w.in_wedge(i.k, q))
    }

    /// Ω_ij in plane coordinates (the module doc's three cases); `Some(φ_ji(q))` when q ∈ Ω_ij.
    pub fn phi<S: Scalar>(
        &self,
        t: &WedgeTable<S>,
        j: Corner,
        i: Corner,
        q: &P2<S>,
    ) -> Option<P2<S>> {
        if !self.in_wedge(t, i, q) {
            return None;
        }
        match self.case(i, j) {
            PairCase::SameVertex => self.in_wedge(t, j, q).then(|| q.clone()),
            PairCase::Edge(e) => {
                let y = g_uw_on_domain(&e, q)?;
                self.in_wedge(t, j, &y).then_some(y)
            }
            PairCase::DeclaredEmptyEdge(_) | PairCase::NotAdjacent => None,
        }
    }

    /// The formula of case (2) applied to a case-(3) pair with [u, w] an edge: the point
    /// φ would map q to if the pair were not declared empty (`SV-H` checks this is never
    /// `Some`).
    pub fn case3_formula<S: Scalar>(
        &self,
        t: &WedgeTable<S>,
        j: Corner,
        i: Corner,
        q: &P2<S>,
    ) -> Option<P2<S>> {
        match self.case(i, j) {
            PairCase::DeclaredEmptyEdge(e) if self.in_wedge(t, i, q) => {
                let y = g_uw_on_domain(&e, q)?;
                self.in_wedge(t, j, &y).then_some(y)
            }
            _ => None,
        }
    }
}

/// g_(u,w)(q) (Def. 4.1.8) when q lies in the report's Ω_uw (Def. 4.1.9), else `None`:
/// a = R_(u,w)(q) ≠ 0 with polar angle |θ| < min(π, 6π/m_u) (the branch on which g_u is
/// injective), g_u(a) in the canonical lens E; then R_(w,u)⁻¹∘g_w⁻¹∘h (composed from the
/// shared maps of Sec. 4.1).
pub fn g_uw_on_domain<S: Scalar>(e: &EdgeConfig, q: &P2<S>) -> Option<P2<S>> {
    let a = Ppm::<S>::r_uw(&Paper, e, q);
    let pol = polar(&a).ok()?;
    let prec = q.prec();
    let pi = S::pi(prec);
    let branch = if e.m_u <= 6 {
        pi
    } else {
        pi.mul(&S::from_ratio(6, e.m_u as i64, prec))
    };
    if !pol.theta.abs().lt(&branch).is_true() {
        return None;
    }
    let b = polar_inv(&f_v(e.m_u, &pol));
    let c = Ppm::<S>::h(&Paper, &b);
    if !in_canonical_lens(&c).is_true() {
        return None;
    }
    let d = Ppm::<S>::g_v_inv(&Paper, e.m_w, &c).ok()?;
    Some(Ppm::<S>::r_uw_inv(&Paper, &e.reversed(), &d))
}

/// Grid points of the report's Ω_uw (plane coordinates of P_u): a `side`² grid over the
/// canonical lens, pulled back by R_(u,w)⁻¹∘g_u⁻¹.
pub fn omega_uw_grid(e: &EdgeConfig, side: usize) -> Vec<P2<f64>> {
    let mut out = Vec::with_capacity(side * side);
    for a in 0..side {
        for b in 0..side {
            let x = 0.1339 + 0.7322 * (a as f64 + 0.5) / side as f64;
            let y = -0.7072 + 1.4144 * (b as f64 + 0.5) / side as f64;
            let z = P2::new(x, y);
            if !in_canonical_lens(&z).is_true() {
                continue;
            }
            if let Ok(p) = g_v_inv(e.m_u, &z) {
                out.push(rotate_frac(&p, e.i as i64, e.m_u as i64));
            }
        }
    }
    out
}
