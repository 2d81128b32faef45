//! Certified (interval-arithmetic) proofs of the Chapter 4 conditions for every
//! degree configuration up to a bound.
//!
//! The gluing data of Chapter 4 depends only on degrees and labels; after the rotations
//! R_(u,w) (Def. 4.1.8, isometries) an edge depends only on (m_u, m_w), a triangle on
//! (m_u, m_w, m_x, orientation), a star on m_x. [`ConfigKey`] names these configurations;
//! [`run`] proves every property for all keys with degrees 3..=M by branch and bound over
//! polar boxes (θ, r) of the chart (Π⁻¹ is a bijection (−π, π] × (0, r) → disk − {0}, so the
//! boxes cover every point; boxes crossing Π's cut are evaluated as two pieces,
//! [`interval::principal_pieces`]). Interval arithmetic is `inari` (outward rounding).
//!
//! Each result is a certificate (boxes, depth, bound, unresolved boxes and δ) or a
//! refutation with a witness point that the f64 and multi-precision evaluators of
//! `construction::maps` confirm. Exactly what is proven is in [`PropertyResult::statement`].

pub mod interval;

mod bnb;
mod certificate;
mod config;
mod driver;
mod f64_bound;
mod f64_outside;
mod f64_props;
mod f64_roundtrip;
mod g_chart;
mod model;
mod prove_edge;
mod prove_triangle;
mod prove_vertex;
mod result;
pub mod sector;

pub use bnb::*;
pub use certificate::*;
pub use config::*;
pub use driver::*;
pub use f64_bound::*;
pub use f64_outside::{meets_nbhd, F64_NBHD, ORIGIN_CORE, OUTSIDE_MIN_DIAM};
pub use f64_props::*;
pub use f64_roundtrip::*;
pub use g_chart::*;
pub use model::*;
pub use prove_edge::*;
pub use prove_triangle::*;
pub use prove_vertex::*;
pub use result::*;
