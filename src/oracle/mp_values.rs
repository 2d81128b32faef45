//! The MPFR side of an answer: a reference value in all its decimal digits, and the
//! distance of an f64 answer from it, computed in MPFR.

use crate::numeric::{Mp, Scalar};

/// Render a multi-precision value with all its significant decimal digits.
pub(crate) fn mp_decimal(x: &Mp) -> String {
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
