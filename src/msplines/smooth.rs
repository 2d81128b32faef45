//! The manifold spline F(M) of Secs. 5.5–5.6 as a [`SmoothSurface`]: F evaluated at a point
//! of a face of M in a chart at a corner of that face ([`MeshSpline::evaluate_anywhere`]), the
//! charts of the affine atlas (Sec. 5.4) as its gluing data (Def. 3.4.1, [`AtlasView`]).
//!
//! What does not fit the spline, by [`SmoothError::Unsupported`]: MPFR evaluation (the knots,
//! the DMS basis and the atlas are f64 data), jets (Sec. 5.6 evaluates F's value; the
//! derivatives of the DMS basis are not implemented), and sampling with normals or
//! curvatures (positions only, for the same reason).

use super::atlas::Atlas;
use super::mesh_spline::{MeshPoint, MeshSpline};
use super::spline_sample::sample;
use super::view::AtlasView;
use crate::gluing::data::Idx;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::report::Progress;
use crate::surface::geometry::SurfacePoint;
use crate::surface::output::{Attributes, SampledMesh};
use crate::surface::smooth::{GluingView, MpEval, SmoothError, SmoothSurface};

/// The spline F with the mesh M and the atlas it is defined on (`pipeline::spline`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct SplineSurface<'a> {
    /// The domain manifold M.
    pub k: &'a SimplicialSurface,
    /// The affine atlas of Sec. 5.4.
    pub atlas: &'a Atlas,
    /// The knots and control points of Sec. 5.5.
    pub spline: &'a MeshSpline,
}

const NAME: &str = "the manifold spline F(M) (Gu–He–Qin Secs. 5.5–5.6)";

fn unsupported(what: &'static str, why: &'static str) -> SmoothError {
    SmoothError::Unsupported {
        surface: NAME,
        what,
        why,
    }
}

impl SmoothSurface for SplineSurface<'_> {
    fn name(&self) -> String {
        format!("{NAME}, degree {}", self.spline.k)
    }

    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, SmoothError> {
        Ok(self.k.faces().map(|f| self.k.face(f)).collect())
    }

    fn eval_f64(&self, f: FaceId, bary: [f64; 3]) -> Result<[f64; 3], SmoothError> {
        if f.idx() >= self.k.num_faces() {
            return Err(SmoothError::Vertex(
                crate::surface::SurfaceError::NoSuchFace(f),
            ));
        }
        let p = MeshPoint { face: f, bary };
        self.spline
            .evaluate_anywhere(self.k, self.atlas, &p)
            .map(|e| e.value)
            .map_err(|e| SmoothError::Spline(Box::new(e)))
    }

    fn mp_eval(&self, _bits: u32) -> Result<MpEval<'_>, SmoothError> {
        Err(unsupported(
            "MPFR evaluation",
            "the knots, the DMS basis and the atlas are f64 data (Secs. 5.4–5.5)",
        ))
    }

    fn eval_geometry(&self, _f: FaceId, _bary: [f64; 3]) -> Result<SurfacePoint, SmoothError> {
        Err(unsupported(
            "eval with jets",
            "Sec. 5.6 evaluates F's value; the derivatives of the DMS basis are not implemented",
        ))
    }

    /// Positions only; reports no progress.
    fn sample(
        &self,
        level: u32,
        attrs: Attributes,
        _progress: Progress,
    ) -> Result<SampledMesh, SmoothError> {
        if attrs != Attributes::Positions {
            return Err(unsupported(
                "sampling normals or curvatures",
                "Sec. 5.6 evaluates F's value; the derivatives of the DMS basis are not implemented",
            ));
        }
        sample(self.k, self.atlas, self.spline, level).map_err(|e| SmoothError::Spline(Box::new(e)))
    }

    /// The charts `ids` of the atlas (Sec. 5.4) as gluing data; `k` is not needed (the
    /// spline keeps M).
    fn gluing_view<'a>(
        &'a self,
        _k: &'a SimplicialSurface,
        ids: Vec<Idx>,
    ) -> Result<GluingView<'a>, SmoothError> {
        Ok(Box::new(AtlasView::new(self.k, self.atlas, ids)))
    }
}
