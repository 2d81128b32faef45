//! Chapter 4: the PPM set of gluing data built from a simplicial surface.
//!
//! This module holds the pure mathematics of Sec. 4.1 (independent of meshes), generic over
//! the scalar type ([`crate::numeric::Scalar`]: `f64`, [`crate::numeric::Mp`]), the seeded samplers, and the
//! conformance checks of Secs. 4.1–4.2. See `SPEC.md` for the statement-by-statement
//! verdicts.

pub mod abstract_view;
pub mod checks;
pub(crate) mod config;
pub mod figure;
pub mod maps;
pub(crate) mod mesh_gluing;
pub(crate) mod sampling;

pub use maps::{
    g_uw, in_omega_uw, in_omega_uw_lens, phi_wu, phi_wu_f64_vs_mp, ConfigError, Corner, EdgeConfig,
    MapError, Paper, Ppm, TriangleConfig, VertexPair, P2,
};
pub use mesh_gluing::{GluingError, PpmGluing};
