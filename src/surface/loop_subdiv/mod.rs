//! S′ = the Loop subdivision limit surface of K (Sec. 6.2; Loop 1987), evaluated exactly at
//! any (σ, λ, μ, ν) of the base mesh by Stam's method (1998).

pub(crate) mod eigen;
mod error;
mod fast;
mod linear;
pub(crate) mod patch;
mod plan;
pub mod regular;
pub mod rules;
pub mod stam;
pub(crate) mod surface;
pub mod topology;
mod valence_weights;

pub use error::{LoopError, MAX_VALENCE};
pub use surface::{LoopStats, LoopSurface};
pub mod checks;
