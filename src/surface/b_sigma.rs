//! Sec. 5.1: S′ as the construction sees it, patches b_σ over the common frame Δ (barycentric
//! coordinates of σ), and the linear form of the fit's fast path. The surfaces themselves
//! (PN triangles, the choice of S′) are in `target`; the Loop surface in `loop_subdiv`.

use crate::mesh::{FaceId, SimplicialSurface, VertexId};

/// Sec. 5.1: S′ as a union of patches b_σ over the common frame Δ.
pub trait TargetSurface: Sync {
    /// Name for reports ("pn-triangles").
    fn name(&self) -> &str;
    /// b_σ(r) for σ = `f`, r with barycentric coordinates `bary` w.r.t. `corners`, which is
    /// the corner list of `f` in any order.
    fn eval(&self, f: FaceId, corners: [VertexId; 3], bary: [f64; 3]) -> [f64; 3];
    /// When b_σ is a cubic Bézier triangle: its control points w.r.t. `corners`, in
    /// [`super::target::CUBIC_ORDER`]. The fit then uses the precomputed linear map from
    /// control nets to shape-function control points (same result as sampling [`Self::eval`]).
    fn cubic_net(&self, _f: FaceId, _corners: [VertexId; 3]) -> Option<[[f64; 3]; 10]> {
        None
    }
    /// When b_σ is linear in the vertex positions of K with weights fixed by the local
    /// combinatorics (the Loop limit surface): the fit then applies one precomputed matrix
    /// per (degree, sector, [`FaceStencil::key`]) instead of sampling [`Self::eval`].
    fn linear(&self) -> Option<&dyn LinearTarget> {
        None
    }
}

/// The vertices of K that b_σ on one face depends on, seen from an ordered corner list, with
/// a key: two faces seen from corner lists with equal keys have equal weights at equal
/// barycentric coordinates ([`LinearTarget::weights`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FaceStencil {
    /// The local combinatorics (what the weights depend on).
    pub key: Vec<u32>,
    /// The vertices, in the order of the weights.
    pub verts: Vec<VertexId>,
}

/// A target surface that is a fixed linear combination of vertex positions on each face.
pub trait LinearTarget: Sync {
    /// The stencil of f seen from `corners`, written into `out` (its buffers reused: the fit
    /// asks for one stencil per sector, ~6 per vertex, where two fresh vectors each time
    /// showed in profiles); `None` when the face has no such form.
    fn stencil_into(
        &self,
        k: &SimplicialSurface,
        f: FaceId,
        corners: [VertexId; 3],
        out: &mut FaceStencil,
    ) -> Option<()>;
    /// The stencil of f seen from `corners`, in fresh buffers ([`Self::stencil_into`]).
    fn stencil(
        &self,
        k: &SimplicialSurface,
        f: FaceId,
        corners: [VertexId; 3],
    ) -> Option<FaceStencil> {
        let mut out = FaceStencil {
            key: Vec::new(),
            verts: Vec::new(),
        };
        self.stencil_into(k, f, corners, &mut out)?;
        Some(out)
    }
    /// Row-major |barys| × |verts|: the weights of a stencil's vertices `verts`
    /// ([`FaceStencil::verts`]) at each point (barycentric w.r.t. `corners`); `None` when a
    /// point cannot be expressed.
    fn weights(
        &self,
        f: FaceId,
        corners: [VertexId; 3],
        verts: &[VertexId],
        barys: &[[f64; 3]],
    ) -> Option<Vec<f64>>;
    /// The positions of K's vertices, indexed by [`VertexId`].
    fn positions(&self) -> &[[f64; 3]];
    /// Builds what [`Self::weights`] needs on first use, so the fit can do it beside other
    /// work (default: nothing).
    fn prepare(&self) {}
}
