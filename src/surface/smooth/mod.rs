//! One interface for "a smooth surface built from K": [`SmoothSurface`], implemented by the
//! report's vertex-indexed PPS ([`crate::surface::Pps`], Ch. 4–5), the tutorial's
//! (σ, v)-indexed PPS ([`crate::surface::sigma_v::SigmaVPps`], seed 002 Parts IV–V) and the
//! manifold spline F(M) of seed 003 (`crate::msplines::smooth::SplineSurface`, Secs. 5.5–5.6).
//!
//! The methods are what the callers of more than one construction need, and no more:
//!
//! * `ppm sample` (Sec. 6.2) samples through eval: [`SmoothSurface::sample`];
//! * `ppm diff --surface` compares against the reference sampling: the faces of K
//!   ([`SmoothSurface::face_corners`], the sampling pattern's input), eval in f64 with its
//!   error bound when the construction has an analysis ([`SmoothSurface::eval_bounded`]) and
//!   in MPFR ([`SmoothSurface::mp_eval`]);
//! * the oracle's `eval` and `ppm eval` answer with the chart eval chose
//!   ([`SmoothSurface::eval_located`], [`SmoothSurface::eval_mp`] with constants built once
//!   per precision by [`SmoothSurface::mp_consts`]);
//! * one point of M with its jets — position, tangents, normal, curvatures
//!   ([`SmoothSurface::eval_geometry`], Sec. 6.1.4 with the jets of θ);
//! * the parametric pseudo-surface's gluing data seen through Def. 3.4.1
//!   ([`SmoothSurface::gluing_view`]), what the sampled checkers of `crate::gluing::sampled`
//!   take.
//!
//! A method that does not make sense for a construction returns
//! [`SmoothError::Unsupported`] (never a panic): the manifold spline has no MPFR evaluation
//! and no jets (Sec. 5.6 evaluates F's value only), and its sampling computes positions only.
//!
//! # Why `&dyn SmoothSurface`
//!
//! The commands choose the construction at run time (`--construction`), and every method
//! does at least one whole eval (hundreds of floating-point operations, or an MPFR
//! evaluation) per call: the one indirect call per point costs nothing measurable
//! (`ppm diff --surface` of bunny.off's level-4 sampling, 470 274 points: 1.44–1.53 s with
//! the former generic reference, 1.47–1.54 s through `&dyn`, 2 cores). So the trait is object
//! safe — constants in another scalar are captured by the closure [`SmoothSurface::mp_eval`]
//! returns instead of being an associated type — and the callers hold a `&dyn SmoothSurface`
//! rather than matching on [`super::Construction`] at each use.

mod located;
mod vertex;

pub(crate) use located::{ChartAt, Located, MpConsts};

use super::eval_bound::BoundedPoint;
use super::geometry::SurfacePoint;
use super::output::{Attributes, SampledMesh};
use super::sigma_v::SigmaVError;
use super::SurfaceError;
use crate::gluing::data::{GluingData, Idx};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::Mp;
use crate::report::Progress;

/// Why a [`SmoothSurface`] method gave no answer. The construction's own error is carried
/// unchanged (its message is the one printed).
#[derive(Debug, thiserror::Error)]
pub enum SmoothError {
    /// The vertex-indexed PPS (Ch. 4–5, Sec. 6.1.4).
    #[error(transparent)]
    Vertex(#[from] SurfaceError),
    /// The (σ, v)-indexed PPS (SPEC `SV-…`).
    #[error(transparent)]
    SigmaV(#[from] SigmaVError),
    /// The manifold spline (seed 003, SPEC `MS-…`): its sampling or evaluation error.
    #[error(transparent)]
    Spline(Box<dyn std::error::Error + Send + Sync>),
    /// MPFR constants of another construction were handed to [`SmoothSurface::eval_mp`].
    #[error("the MPFR constants given are not {surface}'s")]
    ForeignConsts {
        /// The construction.
        surface: &'static str,
    },
    /// The method has no meaning for this construction (see the trait's doc).
    #[error("{what} is not available for {surface}: {why}")]
    Unsupported {
        /// The construction.
        surface: &'static str,
        /// The method.
        what: &'static str,
        /// Why, citing the paper.
        why: &'static str,
    },
}

/// eval(σ, λ, μ, ν) in MPFR at the precision [`SmoothSurface::mp_eval`] was asked for, with
/// the construction's constants at that precision built once.
pub(crate) type MpEval<'a> =
    Box<dyn Fn(FaceId, [f64; 3]) -> Result<[Mp; 3], SmoothError> + Sync + 'a>;

/// The gluing data of a set of p-domains (Def. 3.4.1), as the sampled checkers take it.
pub(crate) type GluingView<'a> = Box<dyn GluingData<2, S = f64> + 'a>;

/// One least-squares fit of a construction's shape functions, as `ppm sample` reports it:
/// per vertex degree m, the fit of Sec. 5.2 (vertex PPS, Bézier bi-degree `l`) or of SPEC
/// `SV-D11` ((σ, v) PPS, `l` = `None`: its patch degree is one for all m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitSummary {
    /// The vertex degree m.
    pub m: u32,
    /// The Bézier bi-degree l (vertex PPS only).
    pub l: Option<usize>,
    /// Samples: the rows of A.
    pub rows: usize,
    /// Unknowns per coordinate: the columns of A.
    pub unknowns: usize,
    /// The numerical rank of A.
    pub rank: usize,
    /// κ(A) = σ_max/σ_min.
    pub condition: f64,
}

/// A smooth surface built from the triangle mesh K and evaluated from a triangle of K:
/// eval(σ, λ, μ, ν) of Sec. 6.1.4 for the two PPS, F at the point of M for the manifold
/// spline (see the module doc for which caller needs which method).
///
/// `Send + Sync`: a surface is sampled by worker threads, and an oracle session holding one is
/// moved between threads (the Python layer keeps it behind a mutex).
pub trait SmoothSurface: Send + Sync {
    /// The construction, as reports name it (with its parameters).
    fn name(&self) -> String;

    /// The least-squares fits the construction solved, one per vertex degree (empty when it
    /// fits nothing, as the manifold spline).
    fn fit_summary(&self) -> Vec<FitSummary> {
        Vec::new()
    }

    /// The corners of every face of K in stored order: the input of the Sec. 6.2 sampling
    /// pattern (`surface::output::sample_pattern_faces`).
    fn face_corners(&self) -> Result<Vec<[VertexId; 3]>, SmoothError>;

    /// The point of the surface at (σ, λ, μ, ν), in f64.
    fn eval_f64(&self, f: FaceId, bary: [f64; 3]) -> Result<[f64; 3], SmoothError>;

    /// [`Self::eval_f64`] with its forward-error bound when the construction has an f64 error
    /// analysis (the vertex PPS, SPEC `R-diff-f64-bound`; `None` otherwise). The point is
    /// exactly [`Self::eval_f64`]'s.
    fn eval_bounded(
        &self,
        f: FaceId,
        bary: [f64; 3],
    ) -> Result<([f64; 3], Option<BoundedPoint>), SmoothError> {
        Ok((self.eval_f64(f, bary)?, None))
    }

    /// [`Self::eval_f64`] with the chart eval chose and q in it (the same point).
    fn eval_located(&self, f: FaceId, bary: [f64; 3]) -> Result<Located<f64>, SmoothError> {
        Ok(Located {
            point: self.eval_f64(f, bary)?,
            chart: None,
        })
    }

    /// The construction's constants in MPFR at `bits`, for [`Self::eval_mp`].
    fn mp_consts(&self, bits: u32) -> Result<MpConsts, SmoothError>;

    /// eval in MPFR with the constants `c` of [`Self::mp_consts`] (the f64-fitted control
    /// points evaluated exactly enough, so |f64 − MPFR| measures the f64 rounding); the
    /// barycentric coordinates are read exactly at `c`'s precision.
    fn eval_mp(&self, c: &MpConsts, f: FaceId, bary: [f64; 3]) -> Result<Located<Mp>, SmoothError>;

    /// eval in MPFR at `bits` as a closure holding the constants, built here, once.
    fn mp_eval(&self, bits: u32) -> Result<MpEval<'_>, SmoothError> {
        let c = self.mp_consts(bits)?;
        Ok(Box::new(move |f, bary| {
            Ok(self.eval_mp(&c, f, bary)?.point)
        }))
    }

    /// The point with its first and second derivatives in the chart eval chose, unit normal,
    /// Gaussian and mean curvature (from order-3 jets of the parametrization; the jet
    /// constants are built per call, so a sampling uses [`Self::sample`]).
    fn eval_geometry(&self, f: FaceId, bary: [f64; 3]) -> Result<SurfacePoint, SmoothError>;

    /// Sec. 6.2: the surface sampled by midpoint subdivision at `level` through eval,
    /// computing `attrs` (the arrays of attributes not asked for stay empty); `progress` is
    /// called about ten times where the construction reports progress.
    fn sample(
        &self,
        level: u32,
        attrs: Attributes,
        progress: Progress,
    ) -> Result<SampledMesh, SmoothError>;

    /// Def. 3.4.1: the gluing data of the p-domains `ids` (indices of the construction's I:
    /// vertices of K, corners (σ, v), or charts of the atlas), each in its own copy of ℝ².
    /// `k` is the mesh the surface was built from (the vertex PPS keeps K's combinatorics
    /// only, and its gluing data are Ch. 4's on K).
    fn gluing_view<'a>(
        &'a self,
        k: &'a SimplicialSurface,
        ids: Vec<Idx>,
    ) -> Result<GluingView<'a>, SmoothError>;
}

#[cfg(test)]
mod tests;
