//! Chapter 5 and Sec. 6.1.4: shape functions, weight functions, parametrizations.
//!
//! * [`target`] — Sec. 5.1: the surface S′ to approximate (PN triangles; pluggable).
//! * [`bezier`], [`fit`] — Def. 5.2.1 and Sec. 5.2: shape functions ψ_v by least squares.
//! * [`weights`] — Defs. 5.3.1–5.3.2: ξ and γ_v.
//! * [`pps`] — Defs. 5.4.1–5.4.2, Eq. (5.1): θ_v, generic over the scalar; its [`options`]
//!   (membership test, planted faults) and [`error`]s.
//! * [`eval`] — Sec. 6.1.4: eval(σ, λ, μ, ν).
//! * [`jet`] — order-3 derivative jets (normals, curvature, smoothness checks).
//! * [`geometry`] — normals and curvatures from the jets of θ.
//! * [`output`] — Sec. 6.2: sampling by midpoint subdivision (written by `mesh::io`'s writers).
//! * [`smooth`] — [`smooth::SmoothSurface`], the one interface of the vertex PPS, the (σ, v)
//!   PPS and the manifold spline (eval, jets, sampling, the Def. 3.4.1 view).
//! * [`checks`] — condition (C) and the other Chapter 5 / Sec. 6.1.4 checks.
//!
//! See `SPEC.md` for statement-by-statement verdicts.

pub mod admissible;
pub(crate) mod authors_fit;
pub(crate) mod b_sigma;
pub mod bezier;
pub mod checks;
pub(crate) mod consts;
pub(crate) mod error;
pub mod eval;
pub(crate) mod eval_bound;
pub mod fit;
mod fit_linear;
pub mod geometry;
pub mod jet;
pub(crate) mod kind;
pub mod loop_subdiv;
pub(crate) mod options;
pub mod output;
pub mod pps;
pub mod profile;
pub(crate) mod scalar_ext;
pub mod sigma_v;
pub(crate) mod smooth;
mod storage;
pub mod target;
pub mod weights;

pub use b_sigma::TargetSurface;
pub use checks::{run_surface_checks, SurfaceCheckOptions};
pub use consts::Consts;
pub use eval::{Chart, EvalPoint};
pub use jet::Jet;
pub use kind::Construction;
pub use pps::{Fault, Membership, Pps, PpsOptions, SurfaceError, Term};
pub use profile::{AuthorsStages, NormalRule, Profile};
pub use scalar_ext::SurfaceScalar;
pub use target::{PnTriangles, SPrime, SurfaceKind};
