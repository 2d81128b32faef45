//! A fit: its options, its result with the rounds that reached it, why one fails, and the
//! errors it is measured by (SPEC `AF-epsilon`).

use super::base::{BaseMesh, RemovalLimits};
use super::fitted::{BaseSurface, Fitted, SurfaceParam};
use super::simplify::{Hierarchy, SimplifyOptions};
use super::{embedded, local, refine, unblock, unsimplify};
use crate::mesh::SimplicialSurface;
use crate::surface::sigma_v::{SigmaVError, SigmaVPps};
use rayon::prelude::*;
use serde::Serialize;

/// Options of [`super::fit_surface`].
#[derive(Debug, Clone, Copy)]
pub struct FitOptions {
    /// ε, absolute.
    pub epsilon: f64,
    /// The simplification may leave vertices of S_T this many ε from the flat base triangles
    /// (the smooth fit then closes the gap; refinement where it does not).
    pub deviation_ratio: f64,
    /// κ of the (σ, v) construction.
    pub kappa: f64,
    /// Patch degree of ψ_(σ,v).
    pub degree: usize,
    /// Largest base vertex degree.
    pub max_degree: usize,
    /// Refinement rounds at most.
    pub max_rounds: usize,
    /// The level at which S is sampled to check that it is embedded (SPEC `AF-embedded`);
    /// base faces whose sample crosses are refined like vertices beyond ε
    /// (`AF-refine-embedded`). None: not checked in the loop.
    pub embed_level: Option<u32>,
    /// The fit is refused when [`memory_estimate`] exceeds this many bytes.
    pub memory_limit: u64,
}

/// Bytes per triangle of S_T in [`memory_estimate`]. Measured peaks (docs/fitting-scale.md,
/// `/usr/bin/time -v`) are at most 0.59 of the estimate on the corpus at three ε (armadillo
/// at 10⁻³: 73 MB of 124 MB), 0.46 on koala's two Loop steps (1.52 GB of 3.34 GB, stopped)
/// and 0.51 on armadillo's three (1.99 GB of 3.89 GB, the whole fit); the routing graph
/// alone holds ~13 points per triangle at 20 bytes each, and an embedding is held twice
/// during a local update.
pub const BYTES_PER_FACE: u64 = 2048;

/// Bytes of [`memory_estimate`] whatever the size of S_T (the (σ, v) tables, the thread pool).
pub const FIXED_BYTES: u64 = 64 << 20;

/// The default [`FitOptions::memory_limit`]: 8 GiB (a fit of 10⁶ vertices is ~2·10⁶ faces).
pub const DEFAULT_MEMORY_LIMIT: u64 = 8 << 30;

/// The memory a fit of S_T is allowed to reach, estimated from its size before anything is
/// allocated: [`FIXED_BYTES`] + [`BYTES_PER_FACE`] per triangle.
pub fn memory_estimate(k: &SimplicialSurface) -> u64 {
    FIXED_BYTES.saturating_add(BYTES_PER_FACE.saturating_mul(k.num_faces() as u64))
}

impl FitOptions {
    /// Defaults for a given ε.
    pub fn new(epsilon: f64) -> Self {
        FitOptions {
            epsilon,
            deviation_ratio: 4.0,
            kappa: crate::surface::sigma_v::DEFAULT_KAPPA,
            degree: crate::surface::sigma_v::DEFAULT_PATCH_DEGREE,
            max_degree: 12,
            max_rounds: 40,
            embed_level: Some(super::crossing::DEFAULT_EMBED_LEVEL),
            memory_limit: DEFAULT_MEMORY_LIMIT,
        }
    }
}

impl FitOptions {
    /// The simplification's options of the fit (its removal limits are the AC·CB walk's and
    /// the fallback's too).
    pub fn simplify_options(&self) -> SimplifyOptions {
        SimplifyOptions {
            limits: RemovalLimits {
                max_deviation: self.deviation_ratio * self.epsilon,
                min_normal_cos: 0.5,
                min_quality: 0.1,
                max_degree: self.max_degree,
            },
            min_vertices: 4,
            max_levels: 200,
        }
    }
}

/// Why a fit failed.
#[derive(Debug, thiserror::Error)]
pub enum FitError {
    /// ε must be a positive finite number.
    #[error("epsilon must be positive and finite, got {0}")]
    BadEpsilon(f64),
    /// The fit of S_T would need more memory than allowed ([`memory_estimate`]).
    #[error("a fit of {faces} triangles is estimated at {estimate} bytes, over the limit of {limit} bytes (--max-memory)")]
    TooLarge {
        /// Triangles of S_T.
        faces: usize,
        /// The estimate.
        estimate: u64,
        /// The limit.
        limit: u64,
    },
    /// The (σ, v) construction refused the base mesh.
    #[error("the (sigma, v) construction refused the base mesh: {0}")]
    SigmaV(#[from] SigmaVError),
    /// The base mesh stayed invalid (classes) after the repair rounds.
    #[error("the base mesh is not a simplicial surface after {rounds} repair rounds: {classes}")]
    BaseInvalid {
        /// Rounds spent.
        rounds: usize,
        /// The validator's defect classes.
        classes: String,
    },
    /// The AC·CB walk made more base edges lose their curve than it found (`unblock`): the
    /// base mesh is simplified again with half the deviation allowance (`fit_surface`).
    #[error(
        "the AC·CB walk diverges: {before} base edges without a curve, {after} after its changes"
    )]
    WalkDiverges {
        /// Base edges without a curve before the walk's changes.
        before: usize,
        /// After them.
        after: usize,
    },
    /// ε was not reached in the allowed rounds.
    #[error("epsilon {epsilon} not reached after {rounds} refinement rounds: {offenders} vertices still further (worst {worst}), {folds} triangles of S_T folded, {crossing_faces} base faces whose sample crosses (AF-embedded)")]
    NotReached {
        /// ε.
        epsilon: f64,
        /// Rounds spent.
        rounds: usize,
        /// Vertices still beyond ε.
        offenders: usize,
        /// Largest error.
        worst: f64,
        /// Triangles of S_T still folded in T_v.
        folds: usize,
        /// Base faces whose sample still crosses (SPEC `AF-embedded`; 0 when not checked).
        crossing_faces: usize,
    },
    /// ε holds, but S is not embedded at the sample level after the allowed rounds.
    #[error("the fitted surface is not embedded after {rounds} refinement rounds: its level-{level} sample has {triangles} offending triangles at {faces} base faces (AF-embedded)")]
    NotEmbedded {
        /// Rounds spent.
        rounds: usize,
        /// The sample level.
        level: u32,
        /// Offending sample triangles.
        triangles: usize,
        /// Base faces they sample.
        faces: usize,
    },
}

/// One round of fit and refinement.
#[derive(Debug, Clone, Serialize)]
pub struct Round {
    /// Base vertices (charts: one p-domain per corner, |I| = 3·faces; the vertex count is
    /// what refinement adds to).
    pub base_vertices: usize,
    /// Largest ‖S(p_v) − v‖ over the vertices of S_T.
    pub max_error: f64,
    /// Its 99th percentile.
    pub p99_error: f64,
    /// Vertices beyond ε (error plus rounding bound).
    pub offenders: usize,
    /// Pieces of triangles of S_T folded by Floater's maps (`AF-param-bijective`), reported.
    pub folds: usize,
    /// Offending triangles of the round's sample of S (SPEC `AF-embedded`; None: not checked).
    pub crossing_triangles: Option<usize>,
    /// The base faces they sample.
    pub crossing_faces: Option<usize>,
    /// Refinement done after the round (None for the last).
    pub refine: Option<refine::RefineStats>,
    /// What the round's embedding kept from the previous round's (None: all of S_T was
    /// embedded, [`local`]).
    pub local: Option<local::LocalStats>,
    /// Seconds spent in the round.
    pub seconds: f64,
}

/// A fit and how it was reached.
pub struct Fit {
    /// ε (absolute).
    pub epsilon: f64,
    /// The base mesh with the parametrization of S_T.
    pub base: BaseMesh,
    /// The base mesh as a validated surface.
    pub surface: BaseSurface,
    /// Parameters of the vertices of S_T in the surface's ids (Floater's).
    pub params: Vec<SurfaceParam>,
    /// The embedded base mesh and Floater's maps, or why there are none.
    pub embedded: Result<embedded::Embedded, embedded::Failure>,
    /// Whether `params` are Floater's (else the simplification's: the embedding failed).
    pub floater_params: bool,
    /// The fitted PPS.
    pub fitted: Fitted,
    /// The sample level of `AF-embedded` (None: not checked).
    pub embed_level: Option<u32>,
    /// Error of every vertex of S_T.
    pub errors: Vec<f64>,
    /// Bound on the f64 rounding of eval (added to each error before comparing with ε).
    pub rounding_bound: f64,
    /// The simplification.
    pub hierarchy: Hierarchy,
    /// Repair rounds spent on an invalid base mesh.
    pub repairs: usize,
    /// The rounds.
    pub rounds: Vec<Round>,
    /// The base-mesh changes where a base edge had no curve (the AC·CB rule, `unblock`).
    pub unblock: unblock::Walk,
    /// The fallback where the walk could not finish: the vertices of S_T kept as in S_T and the
    /// simplifications run again (`unsimplify`, SPEC `AF-unsimplify`; no round when unused).
    pub restore: unsimplify::Restore,
}

/// A bound on |fl(eval) − eval| for the fitted PPS: the operation count of
/// `surface::eval_bound` (patches of degree d: γ_{8d+8}; maps and blend: `MAP_BOUND_ULPS` ulps)
/// times the largest control point. An operation count, not a proof; the checks compare it
/// with 256-bit evaluations on a seeded sample (SPEC `AF-epsilon`).
pub fn rounding_bound(pps: &SigmaVPps) -> f64 {
    use crate::surface::eval_bound::{gamma_n, MAP_BOUND_ULPS};
    (gamma_n(8 * pps.degree + 8) + MAP_BOUND_ULPS * f64::EPSILON) * pps.scale()
}

/// ‖S(p_x) − x‖ for every vertex x of S_T (NaN when eval fails).
pub fn vertex_errors(pps: &SigmaVPps, pos: &[[f64; 3]], params: &[SurfaceParam]) -> Vec<f64> {
    params
        .par_iter()
        .zip(pos.par_iter())
        .map(|(&(f, b), x)| match pps.eval_f64(f, b) {
            Ok(s) => crate::numeric::robust_norm(&[s[0] - x[0], s[1] - x[1], s[2] - x[2]]),
            Err(_) => f64::NAN,
        })
        .collect()
}
