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
use crate::numeric::Mp;
use crate::report::Progress;
use crate::surface::geometry::SurfacePoint;
use crate::surface::output::{Attributes, SampledMesh};
use crate::surface::smooth::{GluingView, Located, MpConsts, SmoothError, SmoothSurface};

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

fn no_mpfr() -> SmoothError {
    unsupported(
        "MPFR evaluation",
        "the knots, the DMS basis and the atlas are f64 data (Secs. 5.4–5.5)",
    )
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

    fn mp_consts(&self, _bits: u32) -> Result<MpConsts, SmoothError> {
        Err(no_mpfr())
    }

    fn eval_mp(
        &self,
        _c: &MpConsts,
        _f: FaceId,
        _bary: [f64; 3],
    ) -> Result<Located<Mp>, SmoothError> {
        Err(no_mpfr())
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

/// The parameters of the manifold spline a command builds (`ppm msplines sample`'s): the
/// basis form ω_k (Sec. 5.1 step 2), the DMS degree (Sec. 3.1.2) and the seed of the knot
/// clouds (Sec. 5.5), on ring-3 charts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SplineParams {
    /// Which basis form.
    pub form: usize,
    /// Degree k of the DMS spline.
    pub degree: usize,
    /// Seed of the knot clouds.
    pub seed: u64,
}

impl Default for SplineParams {
    fn default() -> Self {
        SplineParams {
            form: 0,
            degree: 2,
            seed: 0x5eed,
        }
    }
}

/// The k of the k-ring charts the spline is built on (Sec. 5.4 step 3; `ppm msplines
/// sample`'s).
pub(crate) const SPLINE_RING: u32 = 3;

/// [`SplineSurface`] owning M, its atlas and the spline: the form a command holds as a boxed
/// `SmoothSurface` (the construction chosen at run time).
#[derive(Debug)]
pub(crate) struct OwnedSpline {
    k: SimplicialSurface,
    atlas: Atlas,
    spline: MeshSpline,
}

impl OwnedSpline {
    /// The spline of `p` on M = `k` (`pipeline::spline`).
    pub(crate) fn build(
        k: SimplicialSurface,
        p: SplineParams,
    ) -> Result<Self, super::error::MsError> {
        let (atlas, spline) = super::pipeline::spline(&k, p.form, SPLINE_RING, p.degree, p.seed)?;
        Ok(OwnedSpline { k, atlas, spline })
    }

    fn view(&self) -> SplineSurface<'_> {
        SplineSurface {
            k: &self.k,
            atlas: &self.atlas,
            spline: &self.spline,
        }
    }
}

impl SmoothSurface for OwnedSpline {
    fn name(&self) -> String {
        self.view().name()
    }
    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, SmoothError> {
        self.view().face_corners()
    }
    fn eval_f64(&self, f: FaceId, bary: [f64; 3]) -> Result<[f64; 3], SmoothError> {
        self.view().eval_f64(f, bary)
    }
    fn mp_consts(&self, bits: u32) -> Result<MpConsts, SmoothError> {
        self.view().mp_consts(bits)
    }
    fn eval_mp(&self, c: &MpConsts, f: FaceId, bary: [f64; 3]) -> Result<Located<Mp>, SmoothError> {
        self.view().eval_mp(c, f, bary)
    }
    fn eval_geometry(&self, f: FaceId, bary: [f64; 3]) -> Result<SurfacePoint, SmoothError> {
        self.view().eval_geometry(f, bary)
    }
    fn sample(
        &self,
        level: u32,
        attrs: Attributes,
        progress: Progress,
    ) -> Result<SampledMesh, SmoothError> {
        self.view().sample(level, attrs, progress)
    }
    fn gluing_view<'a>(
        &'a self,
        _k: &'a SimplicialSurface,
        ids: Vec<Idx>,
    ) -> Result<GluingView<'a>, SmoothError> {
        Ok(Box::new(AtlasView::new(&self.k, &self.atlas, ids)))
    }
}
