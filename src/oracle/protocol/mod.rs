//! The `ppm oracle` protocol: one JSON request per line on stdin, one JSON response per line
//! on stdout. Every numerical answer carries the MPFR value (decimal strings, all digits), the
//! f64 value, the MPFR precision and |f64 − MPFR|. Bad requests get a typed error, never a
//! crash. See `docs/oracle.md` for the full list of operations with a worked example.
//!
//! Chapter 4 operations (`degree` … `rotate`) work on the validated mesh alone. Chapter 5
//! operations (`gamma`, `psi`, `psi_control`, `theta`, `theta_derivatives`, `eval`) need the
//! parametric pseudo-surface [`Pps`](crate::surface::Pps) (Defs. 5.4.1–5.4.2), which the session builds lazily on
//! first use with the current profile (`set_profile`, default `paper`) and S′ = the PN
//! triangles of the mesh (Sec. 5.1). The shape-function control points are fitted in f64
//! (Sec. 5.2); the MPFR answers evaluate the construction with *those* control points, so the
//! difference measures the rounding of the f64 evaluation, not of the fit.

mod request;
mod response;
mod session;

pub use request::{MemberTest, Request, MAX_BITS};
pub use response::{OracleError, Response};
pub use session::Session;
