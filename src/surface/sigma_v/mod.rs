//! The tutorial's second construction (seed 002, Parts IV–V): a parametric pseudo-surface
//! whose index set is I = {(σ, v) : σ a triangle, v a vertex of σ}, |I| = 3·n_t.
//!
//! It shares the Chapter 4 maps (Π, g_v, h, R_(u,w), g_(u,w); `construction::maps`), ξ
//! (`surface::weights`), S′ (`surface::target`), the chart rule of eval (`surface::eval`) and
//! the abstract checkers (`gluing::sampled`, `gluing::ppm`) with the vertex-indexed
//! construction; what is its own lives here:
//!
//! * [`wedge`] — r_{v,σ}, Δ_(σ,v), W_(σ,v) = D_v ∩ int Δ, the rigid maps f_(σ,v);
//! * [`gluing`] — I, the three cases of Ω_(τ,u)(η,w), K, φ (plane coordinates);
//! * [`view`] — the abstract view (Def. 3.4.1) in both versions (first attempt, fixed);
//! * [`weight`] — γ_(σ,v); [`patch`] — ψ_(σ,v) and its least-squares fit;
//! * [`surface`] — θ_(σ,v) and eval from a mesh triangle;
//! * [`checks`] — the SPEC `SV-…` rows checked on a mesh.
//!
//! Readings where the slides are figures only or ambiguous are documented at each item and in
//! SPEC.md (section "Tutorial (σ, v)-indexed construction").

pub mod checks;
pub mod compare;
pub mod errata;
pub mod gluing;
pub mod patch;
mod smooth;
pub(crate) mod surface;
pub(crate) mod view;
pub mod wedge;
pub mod weight;

pub use gluing::{Corner, CornerId, PairCase, SigmaV, SigmaVError};
pub use patch::DEFAULT_PATCH_DEGREE;
pub use surface::{SigmaVPps, SvConsts, SvFault};
pub use view::{SigmaVView, Version};
pub use wedge::DEFAULT_KAPPA;
