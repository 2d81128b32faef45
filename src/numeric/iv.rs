//! The interval scalar [`Iv`]: [`Interval`] behind the [`Scalar`] trait, so the generic maps
//! run unchanged on boxes for the certified provers (`certify`).

use super::interval::Interval;
use super::scalar::{Scalar, F64_PREC};
use std::cmp::Ordering;

/// A closed interval with outward-rounded endpoints ([`Interval`], IEEE 1788 semantics), for the certified
/// provers (`crate::certify`). Every operation returns an enclosure of the exact
/// result over all points of the operands, so a decision taken by [`Scalar::sign`] (which
/// answers `None` when the enclosure contains 0) holds for every point of the inputs.
///
/// `atan2` follows Π's range (−π, π] (Def. 4.1.5): for a box that meets the negative x-axis
/// with `y` strictly straddling 0 the enclosure is the hull [−π, π]; the generic `maps::polar`
/// reports such a box as undecided (the sign of `y` is unknown), and the provers split it
/// (`certify::interval::principal_pieces`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Iv(pub Interval);

impl Iv {
    /// `[lo, hi]`; an invalid pair (lo > hi, NaN) gives the entire line (a sound enclosure).
    pub fn new(lo: f64, hi: f64) -> Iv {
        Iv(Interval::try_from((lo, hi)).unwrap_or(Interval::ENTIRE))
    }
    /// The degenerate interval [x, x].
    pub fn point(x: f64) -> Iv {
        Iv::new(x, x)
    }
    /// Lower endpoint.
    pub fn inf(&self) -> f64 {
        self.0.inf()
    }
    /// Upper endpoint.
    pub fn sup(&self) -> f64 {
        self.0.sup()
    }
}

impl Scalar for Iv {
    fn type_name(&self) -> String {
        "interval-f64".into()
    }
    fn from_f64(x: f64, _prec: u32) -> Self {
        Iv::point(x)
    }
    fn from_i64(x: i64, _prec: u32) -> Self {
        // |x| ≤ 2^53 is exact; larger values are enclosed by their two neighbours.
        let f = x as f64;
        if f.abs() <= 9_007_199_254_740_992.0 {
            Iv::point(f)
        } else {
            Iv::new(f.next_down_compat(), f.next_up_compat())
        }
    }
    fn from_ratio(p: i64, q: i64, prec: u32) -> Self {
        Iv(Self::from_i64(p, prec).0 / Self::from_i64(q, prec).0)
    }
    fn pi(_prec: u32) -> Self {
        Iv(Interval::PI)
    }
    fn to_f64(&self) -> f64 {
        self.0.mid()
    }
    fn precision_bits(&self) -> u32 {
        F64_PREC
    }
    fn add(&self, o: &Self) -> Self {
        Iv(self.0 + o.0)
    }
    fn sub(&self, o: &Self) -> Self {
        Iv(self.0 - o.0)
    }
    fn mul(&self, o: &Self) -> Self {
        Iv(self.0 * o.0)
    }
    fn div(&self, o: &Self) -> Self {
        Iv(self.0 / o.0)
    }
    fn neg(&self) -> Self {
        Iv(-self.0)
    }
    fn sqrt(&self) -> Self {
        Iv(self.0.sqrt())
    }
    fn sin(&self) -> Self {
        Iv(self.0.sin())
    }
    fn cos(&self) -> Self {
        Iv(self.0.cos())
    }
    fn abs(&self) -> Self {
        Iv(self.0.abs())
    }
    fn atan2(&self, x: &Self) -> Self {
        let (y, xx) = (self.0, x.0);
        if xx.sup() < 0.0 && y.inf() < 0.0 && y.sup() > 0.0 {
            // Straddles the cut of Π: the principal angles lie near ±π.
            return Iv(Interval::PI.convex_hull(-Interval::PI));
        }
        Iv(y.atan2(xx))
    }
    fn sqr(&self) -> Self {
        Iv(self.0.sqr())
    }
    fn is_nan(&self) -> bool {
        self.0.is_empty() || self.0.inf().is_nan() || self.0.sup().is_nan()
    }
    fn sign(&self) -> Option<Ordering> {
        let (lo, hi) = (self.0.inf(), self.0.sup());
        if self.0.is_empty() || lo.is_nan() || hi.is_nan() {
            None
        } else if lo > 0.0 {
            Some(Ordering::Greater)
        } else if hi < 0.0 {
            Some(Ordering::Less)
        } else if lo == 0.0 && hi == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

/// `next_up`/`next_down` for f64 on the crate's MSRV (stable since 1.86).
trait NextF64 {
    fn next_up_compat(self) -> f64;
    fn next_down_compat(self) -> f64;
}
impl NextF64 for f64 {
    fn next_up_compat(self) -> f64 {
        if self.is_nan() || self == f64::INFINITY {
            return self;
        }
        if self == 0.0 {
            return f64::from_bits(1);
        }
        let b = self.to_bits();
        f64::from_bits(if self > 0.0 { b + 1 } else { b - 1 })
    }
    fn next_down_compat(self) -> f64 {
        -(-self).next_up_compat()
    }
}
