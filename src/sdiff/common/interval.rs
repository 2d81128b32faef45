//! What the interval routes of both dimensions share (the planar `interval`, the tetrahedral
//! `tet::interval`): their verdict, and the enclosure of an exact rational.

use super::rational::{to_f64, Q};
use crate::numeric::interval::{down, up, Interval as I};

/// Outcome of the interval route.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum IntervalVerdict {
    /// det DX > 0 on every box covering the triangle.
    Certified {
        /// Boxes in the cover.
        boxes: usize,
        /// Smallest lower bound of det over the cover.
        lower_bound: f64,
    },
    /// Some box could not be decided within the budget.
    Unknown {
        /// Boxes examined.
        boxes: usize,
    },
}

/// An interval enclosing the rational `x` (one ulp either side of the nearest f64).
pub fn enclose(x: &Q) -> I {
    let f = to_f64(x);
    if f.is_finite() && equals_f64(x, f) {
        return I::try_from((f, f)).unwrap_or(I::ENTIRE);
    }
    I::try_from((down(f), up(f))).unwrap_or(I::ENTIRE)
}

/// Whether `x = n/d` equals the finite f64 `f = s·m·2^e`, in integers: n·2^(−e) = s·m·d for
/// e < 0, n = s·m·d·2^e otherwise. Why not `Q::from_float(f) == x`: that builds and reduces
/// a fraction (a gcd of big integers) per call, most of the interval route's time.
fn equals_f64(x: &Q, f: f64) -> bool {
    use num_bigint::BigInt;
    let (m, e, s) = num_traits::Float::integer_decode(f);
    let mut rhs = BigInt::from(m) * x.denom();
    if s < 0 {
        rhs = -rhs;
    }
    if e >= 0 {
        *x.numer() == rhs << (e as usize)
    } else {
        (x.numer() << (e.unsigned_abs() as usize)) == rhs
    }
}

#[cfg(test)]
mod tests {
    use super::{equals_f64, Q};
    use num_bigint::BigInt;

    /// `equals_f64` answers as the exact comparison `Q::from_float(f) == x` it replaces:
    /// dyadic and non-dyadic rationals, signs, zero, subnormals, large exponents, a fraction
    /// not in lowest terms, and f the nearest f64 or one ulp off.
    #[test]
    fn equals_f64_is_the_exact_comparison() {
        let b = |n: i64| BigInt::from(n);
        let mut xs: Vec<Q> = vec![
            Q::new(b(3), b(4)),
            Q::new(b(-3), b(4)),
            Q::new(b(1), b(3)),
            Q::new(b(0), b(1)),
            Q::new(b(1) << 200, b(1)),
            Q::new(b(1), b(1) << 1074),
            Q::new(b(1), b(1) << 1080),
            Q::new(b(3) << 60, b(1) << 7),
            Q::new_raw(b(6), b(3)),
            Q::new_raw(b(-10), b(-4)),
        ];
        for f in [0.1, -2.5e-310, 1e300, 5e-324, 123456789.125] {
            xs.push(Q::from_float(f).expect("finite"));
        }
        for x in &xs {
            let f = super::to_f64(x);
            for g in [f, f.next_up(), f.next_down()] {
                if g.is_finite() {
                    assert_eq!(
                        equals_f64(x, g),
                        Q::from_float(g).as_ref() == Some(x),
                        "{x} against {g:e}"
                    );
                }
            }
        }
    }
}
