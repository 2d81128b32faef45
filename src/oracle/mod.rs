//! The oracle interface: reference quantities of the construction, each evaluated in
//! f64 *and* in MPFR at a chosen precision, with the difference as the error estimate of the
//! f64 value. Faster implementations compare against these, point by point.
//!
//! * [`Session`] holds a validated mesh and answers [`Request`]s (the `ppm oracle` JSON-lines
//!   protocol, documented in `docs/oracle.md`).
//! * [`diff`] compares another implementation's answers against the reference (`ppm diff`).
//! * [`surface_diff`] compares another implementation's sampled surface against the reference
//!   sampling of Sec. 6.2 (`ppm diff --surface`).

pub mod diff;
pub mod protocol;
pub mod surface_diff;

pub use protocol::{OracleError, Request, Response, Session};

use crate::construction::{Mp, Scalar};

/// Render a multi-precision value with all its significant decimal digits.
pub fn mp_decimal(x: &Mp) -> String {
    x.to_decimal()
}

/// Distance between an f64 vector and an MPFR vector, computed in MPFR and rounded up to f64.
pub fn mp_distance(a: &[f64], b: &[Mp]) -> f64 {
    let mut s = 0.0f64;
    for (x, y) in a.iter().zip(b) {
        let d = y.sub(&Mp::from_f64(*x, y.precision_bits())).to_f64();
        s += d * d;
    }
    s.sqrt()
}
