//! Manifold splines (Gu, He, Qin 2006; `../shared/seeds/003_*`): the affine atlas of a closed
//! mesh built from a holomorphic 1-form (Sec. 5), its zero points (Sec. 5.3), the atlas as a
//! set of gluing data (Def. 3.4.1 of the PPM report) so the general checkers judge it, and
//! the triangular B-spline / polar-form statements of Sec. 3.1 decided in exact rationals.
//! SPEC.md IDs carry the prefix `MS-`.
//!
//! Data flows one way: [`homology`] (tree–cotree) → [`harmonic`] (cotangent Laplacian) →
//! [`hodge`] (conjugate, ω) → [`zeros`] → [`atlas`] → [`view`] (gluing data) → checks; and
//! for the spline itself: [`dms`] (the triangular B-spline basis of Sec. 3.1.2, exact or
//! f64) → [`mesh_spline`] (Secs. 5.5–5.6 on the atlas) → [`spline_sample`] (a mesh file).

pub mod atlas;
pub mod atlas_checks;
pub mod circle;
pub mod claims;
pub mod cochain;
pub mod dms;
pub mod dms_checks;
pub(crate) mod error;
pub mod harmonic;
pub(crate) mod hodge;
pub mod homology;
pub mod mesh_spline;
pub mod mesh_spline_checks;
pub mod pipeline;
pub mod polar;
pub mod polar_checks;
pub(crate) mod poly2;
pub(crate) mod smooth;
pub mod spline_sample;
pub mod view;
pub mod zeros;

pub use error::MsError;
pub use pipeline::{forms, run, MsReport, Options};
