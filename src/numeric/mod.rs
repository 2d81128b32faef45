//! The bottom floor: the scalar types every layer computes with (the [`Scalar`] trait over
//! `f64`, both multi-precision backends and intervals) and the small numeric and combinatorial
//! tools every layer uses, written once.

mod bigfloat;
mod dd;
pub mod interval;
pub mod iv;
pub mod mp;
pub mod mp_backend;
#[cfg(feature = "mpfr")]
pub mod mp_mpfr;
pub mod predicates;
pub mod rounding;
pub mod scalar;
pub mod union_find;
pub mod vec3;

pub use interval::Interval;
pub use iv::Iv;
pub use mp::Mp;
pub use mp_backend::MpBackend;
#[cfg(feature = "mpfr")]
pub use mp_mpfr::MpMpfr;
pub use rounding::Fe;
pub use scalar::{check_prec_bits, Scalar, Trit, DEFAULT_MP_PREC, PREC_BITS};
pub use union_find::UnionFind;

/// Euclidean norm without overflow or underflow of the squares (scaled by the largest
/// component): a deviation of 1e300 is reported as 1e300, not ∞.
pub fn robust_norm(d: &[f64]) -> f64 {
    if d.iter().any(|x| x.is_nan()) {
        return f64::NAN;
    }
    let big = d.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if big == 0.0 || big.is_infinite() {
        return big;
    }
    d.iter().map(|x| (x / big) * (x / big)).sum::<f64>().sqrt() * big
}

/// An exact rational number (the exact backends: 1-D gluing data, Appendix A.1 replays, seeds
/// 003 and 004).
pub type Q = num_rational::BigRational;
