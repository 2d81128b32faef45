//! Chapter 4: the PPM set of gluing data built from a simplicial surface.
//!
//! This module holds the pure mathematics of Sec. 4.1 (independent of meshes), generic over
//! the scalar type ([`scalar::Scalar`]: `f64`, [`scalar::Mp`]), the seeded samplers, and the
//! conformance checks of Secs. 4.1–4.2. See `SPEC.md` for the statement-by-statement
//! verdicts.

pub mod abstract_view;
pub mod checks;
pub mod config;
mod dd;
pub mod figure;
pub mod interval;
pub mod maps;
pub mod mesh_gluing;
pub mod mp;
pub mod mp_backend;
#[cfg(feature = "mpfr")]
pub mod mp_mpfr;
pub mod sampling;
pub mod scalar;
pub mod sigma_v;

pub use maps::{
    g_uw, in_omega_uw, in_omega_uw_lens, phi_wu, phi_wu_f64_vs_mp, ConfigError, Corner, EdgeConfig,
    MapError, Paper, Ppm, TriangleConfig, VertexPair, P2,
};
pub use mesh_gluing::{GluingError, PpmGluing};
pub use mp_backend::MpBackend;
#[cfg(feature = "mpfr")]
pub use scalar::MpMpfr;
pub use scalar::{check_prec_bits, Iv, Mp, Scalar, Trit, DEFAULT_MP_PREC, PREC_BITS};
