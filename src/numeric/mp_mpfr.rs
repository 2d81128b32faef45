//! The second multi-precision backend [`MpMpfr`]: MPFR through `rug` (feature `mpfr`), kept as
//! an independent implementation that the default pure-Rust [`super::Mp`] is checked against
//! (tests/chapter4/mp_backends.rs). Every operation is correctly rounded (MPFR's guarantee).

use super::scalar::Scalar;
use std::cmp::Ordering;

/// A multi-precision float (MPFR, round-to-nearest) whose precision is carried in the value.
#[derive(Clone, Debug, PartialEq)]
pub struct MpMpfr(pub rug::Float);

impl MpMpfr {
    /// Round a requested precision into [`super::scalar::PREC_BITS`] (which MPFR accepts); the
    /// entry points refuse requests outside it before they get here.
    fn clamp(prec: u32) -> u32 {
        let r = &super::scalar::PREC_BITS;
        prec.clamp(
            rug::float::prec_min().max(*r.start()),
            rug::float::prec_max().min(*r.end()),
        )
    }
    fn p2(&self, o: &Self) -> u32 {
        self.0.prec().max(o.0.prec())
    }
    /// `x` rounded to `prec` bits (`prec` rounded into [`super::scalar::PREC_BITS`]); same as
    /// [`Scalar::from_f64`].
    pub fn new(prec: u32, x: f64) -> MpMpfr {
        MpMpfr(rug::Float::with_val(Self::clamp(prec), x))
    }
}

impl Scalar for MpMpfr {
    fn type_name(&self) -> String {
        format!("mp{}", self.0.prec())
    }
    fn from_f64(x: f64, prec: u32) -> Self {
        MpMpfr(rug::Float::with_val(Self::clamp(prec), x))
    }
    fn from_i64(x: i64, prec: u32) -> Self {
        MpMpfr(rug::Float::with_val(Self::clamp(prec), x))
    }
    fn from_ratio(p: i64, q: i64, prec: u32) -> Self {
        let prec = Self::clamp(prec);
        if q == 0 {
            return MpMpfr(rug::Float::with_val(prec, p) / rug::Float::with_val(prec, 0));
        }
        MpMpfr(rug::Float::with_val(prec, rug::Rational::from((p, q))))
    }
    fn pi(prec: u32) -> Self {
        MpMpfr(rug::Float::with_val(
            Self::clamp(prec),
            rug::float::Constant::Pi,
        ))
    }
    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }
    fn precision_bits(&self) -> u32 {
        self.0.prec()
    }
    fn add(&self, o: &Self) -> Self {
        MpMpfr(rug::Float::with_val(self.p2(o), &self.0 + &o.0))
    }
    fn sub(&self, o: &Self) -> Self {
        MpMpfr(rug::Float::with_val(self.p2(o), &self.0 - &o.0))
    }
    fn mul(&self, o: &Self) -> Self {
        MpMpfr(rug::Float::with_val(self.p2(o), &self.0 * &o.0))
    }
    fn div(&self, o: &Self) -> Self {
        MpMpfr(rug::Float::with_val(self.p2(o), &self.0 / &o.0))
    }
    fn neg(&self) -> Self {
        MpMpfr(-self.0.clone())
    }
    fn sqrt(&self) -> Self {
        MpMpfr(self.0.clone().sqrt())
    }
    fn sin(&self) -> Self {
        MpMpfr(self.0.clone().sin())
    }
    fn cos(&self) -> Self {
        MpMpfr(self.0.clone().cos())
    }
    fn abs(&self) -> Self {
        MpMpfr(self.0.clone().abs())
    }
    fn atan2(&self, x: &Self) -> Self {
        MpMpfr(rug::Float::with_val(self.p2(x), self.0.atan2_ref(&x.0)))
    }
    fn sign(&self) -> Option<Ordering> {
        if self.0.is_nan() {
            None
        } else if self.0.is_zero() {
            Some(Ordering::Equal)
        } else if self.0.is_sign_negative() {
            Some(Ordering::Less)
        } else {
            Some(Ordering::Greater)
        }
    }
}

impl MpMpfr {
    /// e^self, correctly rounded.
    pub fn exp(&self) -> MpMpfr {
        MpMpfr(self.0.clone().exp())
    }
    /// All significant decimal digits, for reports and the oracle.
    pub fn to_decimal(&self) -> String {
        let digits = (f64::from(self.0.prec()) * std::f64::consts::LOG10_2).ceil() as usize + 2;
        self.0.to_string_radix(10, Some(digits))
    }
    /// A decimal string correctly rounded to `prec` bits; `None` if it does not parse.
    pub fn parse_decimal(s: &str, prec: u32) -> Option<MpMpfr> {
        rug::Float::parse(s.trim())
            .ok()
            .map(|p| MpMpfr(rug::Float::with_val(Self::clamp(prec), p)))
    }
}
