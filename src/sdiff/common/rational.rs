//! Exact rationals of the simplicial-diffeomorphism engines (both dimensions): small
//! constructors, the multinomial coefficients of the Bernstein bases, and the conversions to
//! and from f64.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed};

pub use crate::numeric::Q;

/// `n` as a rational.
pub fn q(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

/// `p/d` as a rational (`d ≠ 0`).
pub fn qr(p: i64, d: i64) -> Q {
    Q::new(BigInt::from(p), BigInt::from(d))
}

/// The values as integers over one common denominator: `(n, d)` with `xs[i] = n[i] / d` and
/// `d > 0` the lcm of their denominators. Why: `BigRational` reduces by a gcd after every
/// operation, which was most of the exact engines' time in sums of products (polynomial
/// products, determinants); over a common denominator a product of two polynomials needs one
/// reduction per coefficient of the result, and the values are the same rationals.
pub(crate) fn over_common_denominator<'a>(
    xs: impl Iterator<Item = &'a Q> + Clone,
) -> (Vec<BigInt>, BigInt) {
    let d = xs.clone().fold(BigInt::one(), |d, x| {
        if x.denom().is_one() {
            d
        } else {
            d.lcm(x.denom())
        }
    });
    let n = xs
        .map(|x| {
            if x.denom() == &d {
                x.numer().clone()
            } else {
                x.numer() * (&d / x.denom())
            }
        })
        .collect();
    (n, d)
}

/// The multinomial coefficient n! / (k_0! k_1! …), Σ k = n.
pub(crate) fn multinomial(n: usize, ks: &[usize]) -> BigInt {
    let mut r = factorial(n);
    for &k in ks {
        r /= factorial(k);
    }
    r
}

fn factorial(n: usize) -> BigInt {
    (1..=n).fold(BigInt::one(), |acc, k| acc * BigInt::from(k))
}

/// Nearest f64 of a rational (huge or tiny values saturate to ±∞ / 0 as f64 does).
pub fn to_f64(x: &Q) -> f64 {
    use num_traits::ToPrimitive;
    x.to_f64().unwrap_or(if x.is_negative() {
        f64::NEG_INFINITY
    } else {
        f64::INFINITY
    })
}

/// The exact rational value of a finite f64 (`None` for NaN/∞).
pub fn from_f64(x: f64) -> Option<Q> {
    Q::from_float(x)
}
