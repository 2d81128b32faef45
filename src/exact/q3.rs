//! The field Q(√3) = {a + b√3 : a, b ∈ Q}, exact (pairs of `BigRational`s).
//!
//! Rotations by multiples of π/3 (cos, sin ∈ {0, ±1/2, ±1, ±√3/2}), the double reflection h of
//! Def. 4.1.7, and the centres and squared radii of the disks C, D, F, G of Sec. 4.1 /
//! Appendix A.1 / Sec. 6.1.4 (radius cos(π/6) = √3/2, squared radius 3/4) all have coordinates
//! in this field, so every identity between them is decided exactly.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

pub use crate::numeric::Q;

/// `n/d` as a [`Q`]; `d` must be non-zero (callers pass literals).
pub fn q(n: i64, d: i64) -> Q {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// a + b√3 with a, b ∈ Q.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Q3 {
    /// Rational part.
    pub a: Q,
    /// Coefficient of √3.
    pub b: Q,
}

impl Q3 {
    /// a + b√3.
    pub fn new(a: Q, b: Q) -> Self {
        Q3 { a, b }
    }
    /// A rational number.
    pub fn rat(a: Q) -> Self {
        Q3 { a, b: Q::zero() }
    }
    /// n/d.
    pub fn frac(n: i64, d: i64) -> Self {
        Q3::rat(q(n, d))
    }
    /// 0.
    pub fn zero() -> Self {
        Q3::frac(0, 1)
    }
    /// 1.
    pub fn one() -> Self {
        Q3::frac(1, 1)
    }
    /// (n/d)·√3.
    pub fn sqrt3_times(n: i64, d: i64) -> Self {
        Q3 {
            a: Q::zero(),
            b: q(n, d),
        }
    }
    /// Whether this is 0.
    pub fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
    /// Exact sign of a + b√3: if a and b do not have opposite signs the sign is theirs;
    /// otherwise compare a² with 3b².
    pub fn signum(&self) -> Ordering {
        let sa = self.a.cmp(&Q::zero());
        let sb = self.b.cmp(&Q::zero());
        match (sa, sb) {
            (Ordering::Equal, s) | (s, Ordering::Equal) => s,
            (x, y) if x == y => x,
            (sa, _) => {
                let a2 = &self.a * &self.a;
                let b2 = &self.b * &self.b * q(3, 1);
                match a2.cmp(&b2) {
                    Ordering::Greater => sa,
                    Ordering::Less => sa.reverse(),
                    Ordering::Equal => Ordering::Equal,
                }
            }
        }
    }
    /// Exact comparison.
    pub fn cmp_exact(&self, other: &Q3) -> Ordering {
        (self - other).signum()
    }
    /// Multiplicative inverse, `None` for 0: 1/(a + b√3) = (a − b√3)/(a² − 3b²).
    pub fn inv(&self) -> Option<Q3> {
        if self.is_zero() {
            return None;
        }
        let n = &self.a * &self.a - &self.b * &self.b * q(3, 1);
        // n ≠ 0 because √3 is irrational.
        Some(Q3 {
            a: &self.a / &n,
            b: -(&self.b / &n),
        })
    }
    /// Quotient, `None` when dividing by 0.
    pub fn checked_div(&self, d: &Q3) -> Option<Q3> {
        d.inv().map(|i| self * &i)
    }
}

impl fmt::Display for Q3 {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.a.is_zero(), self.b.is_zero()) {
            (_, true) => write!(f, "{}", self.a),
            (true, false) => write!(f, "{}√3", self.b),
            (false, false) => {
                if self.b.is_negative() {
                    write!(f, "{} − {}√3", self.a, -&self.b)
                } else {
                    write!(f, "{} + {}√3", self.a, self.b)
                }
            }
        }
    }
}

impl<'a> Add<&'a Q3> for &'a Q3 {
    type Output = Q3;
    fn add(self, o: &Q3) -> Q3 {
        Q3 {
            a: &self.a + &o.a,
            b: &self.b + &o.b,
        }
    }
}
impl<'a> Sub<&'a Q3> for &'a Q3 {
    type Output = Q3;
    fn sub(self, o: &Q3) -> Q3 {
        Q3 {
            a: &self.a - &o.a,
            b: &self.b - &o.b,
        }
    }
}
impl<'a> Mul<&'a Q3> for &'a Q3 {
    type Output = Q3;
    fn mul(self, o: &Q3) -> Q3 {
        Q3 {
            a: &self.a * &o.a + &self.b * &o.b * q(3, 1),
            b: &self.a * &o.b + &self.b * &o.a,
        }
    }
}
impl Neg for &Q3 {
    type Output = Q3;
    fn neg(self) -> Q3 {
        Q3 {
            a: -&self.a,
            b: -&self.b,
        }
    }
}
impl Add for Q3 {
    type Output = Q3;
    fn add(self, o: Q3) -> Q3 {
        &self + &o
    }
}
impl Sub for Q3 {
    type Output = Q3;
    fn sub(self, o: Q3) -> Q3 {
        &self - &o
    }
}
impl Mul for Q3 {
    type Output = Q3;
    fn mul(self, o: Q3) -> Q3 {
        &self * &o
    }
}
impl Neg for Q3 {
    type Output = Q3;
    fn neg(self) -> Q3 {
        -&self
    }
}

/// cos and sin of k·π/6 (k any integer), exactly in Q(√3).
pub fn cos_sin_sixth_pi(k: i64) -> (Q3, Q3) {
    // Table over k mod 12 of (cos, sin) of kπ/6.
    let h = |n| Q3::frac(n, 2);
    let r = |n| Q3::sqrt3_times(n, 2);
    match k.rem_euclid(12) {
        0 => (Q3::one(), Q3::zero()),
        1 => (r(1), h(1)),
        2 => (h(1), r(1)),
        3 => (Q3::zero(), Q3::one()),
        4 => (h(-1), r(1)),
        5 => (r(-1), h(1)),
        6 => (-Q3::one(), Q3::zero()),
        7 => (r(-1), h(-1)),
        8 => (h(-1), r(-1)),
        9 => (Q3::zero(), -Q3::one()),
        10 => (h(1), r(-1)),
        _ => (r(1), h(-1)),
    }
}

/// Whether a rational is an integer.
pub fn is_integer(x: &Q) -> bool {
    x.denom().is_one()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn field_axioms_on_samples_and_exact_sign() {
        let x = Q3::new(q(1, 2), q(-1, 3));
        let y = Q3::new(q(-7, 5), q(2, 1));
        assert_eq!(&(&x * &y) * &y.inv().unwrap(), x);
        assert_eq!(&(&x + &y) - &y, x);
        // 1 − √3/2 > 0, 3/4 − √3/2 < 0 (√3 ≈ 1.732).
        assert_eq!(Q3::new(q(1, 1), q(-1, 2)).signum(), Ordering::Greater);
        assert_eq!(Q3::new(q(3, 4), q(-1, 2)).signum(), Ordering::Less);
        assert_eq!(Q3::new(q(-3, 1), q(1, 1)).signum(), Ordering::Less);
        assert!(Q3::zero().inv().is_none());
        for k in -12..24 {
            let (c, s) = cos_sin_sixth_pi(k);
            assert_eq!(&(&c * &c) + &(&s * &s), Q3::one());
            // The signs too (c² + s² = 1 does not see them): against f64 cos and sin.
            let f = |x: &Q3| {
                use num_traits::ToPrimitive;
                let r = |v: &Q| v.to_f64().unwrap_or(f64::NAN);
                r(&x.a) + r(&x.b) * 3f64.sqrt()
            };
            let t = k as f64 * std::f64::consts::PI / 6.0;
            assert!((f(&c) - t.cos()).abs() < 1e-12, "cos({k}π/6)");
            assert!((f(&s) - t.sin()).abs() < 1e-12, "sin({k}π/6)");
        }
    }
}
