//! Adaptive manifold fitting (seed 002, "Adaptive Manifold Fitting", Parts I–II): given a
//! closed triangle mesh S_T and ε > 0, a C^∞ surface S — the (σ, v)-indexed PPS over a base
//! mesh S̃_T whose vertices are vertices of S_T — with ‖S(p_v) − v‖ ≤ ε at the parameter p_v
//! of every vertex v of S_T, with few charts.
//!
//! The pipeline, one module per stage:
//! 1. [`simplify`]: stellar simplification ranked by quadric error, independent sets per level;
//!    it carries the parametrization of S_T onto the base mesh ([`base`]).
//! 2. [`embedded`]: every base edge embedded in |S_T| as a geodesic ([`geodesic`]: an
//!    initial edge path, [`shorten`]: iterative shortening), S_T cut into curved triangles
//!    ([`overlay`]), each mapped onto its base triangle by Floater's mean value
//!    parametrization ([`floater`]); its parameters of the vertices of S_T are the fit's.
//! 3. [`fitted`]: the (σ, v) construction over the base mesh with ψ_(σ,v) fitted by least
//!    squares to the vertices of S_T at those parameters.
//! 4. [`refine`]: where a vertex misses ε, the base mesh is refined locally (stellar face
//!    split at the worst vertex, Lawson flips), and 2–3 are repeated: the embedding only where
//!    the base mesh changed ([`local`]; all of S_T again where that fails), the fit whole.
//!
//! Where the slides are silent, the choices are stated at each module and in SPEC.md
//! (section "Adaptive fitting", rows `AF-…`).

pub mod base;
pub mod checks;
pub mod crossing;
pub(crate) mod disjoint;
pub mod embed_checks;
pub mod embedded;
mod fit;
pub mod fitted;
pub mod floater;
pub mod format;
pub mod geodesic;
pub mod local;
pub mod overlay;
mod pipeline;
pub mod refine;
pub mod route;
pub mod shorten;
pub mod simplify;
pub mod straighten;
pub mod unblock;
pub mod unsimplify;

pub use fit::{
    memory_estimate, rounding_bound, vertex_errors, Fit, FitError, FitOptions, Round,
    BYTES_PER_FACE, DEFAULT_MEMORY_LIMIT, FIXED_BYTES,
};
pub use pipeline::fit_surface;
