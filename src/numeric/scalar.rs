//! The scalar trait of the maps and surfaces: `f64`, the multi-precision [`super::Mp`] (pure Rust,
//! `numeric::mp`; with feature `mpfr` also `MpMpfr`, MPFR via `rug`) and the interval [`super::Iv`].
//!
//! The maps of Sec. 4.1 are written once, generic over [`Scalar`]. Every decision that the
//! maps take (a sign, a comparison deciding membership in a set, the branch of Π) goes through
//! [`Scalar::sign`], which may answer `None` ("cannot decide"). Point types (`f64`, [`super::Mp`])
//! answer `None` only for NaN; the interval type [`super::Iv`] answers `None` when the
//! enclosure contains zero, and the maps propagate that as
//! [`Trit::Unknown`] / `MapError::Undecided` (Sec. 4.1 maps) without any change to the maps.
//!
//! Precision is carried by the values: constants are built with [`Scalar::from_ratio`] etc. at
//! the precision of the operands; binary operations on [`super::Mp`] values of different precision
//! are carried out at the larger of the two precisions.

use std::cmp::Ordering;
use std::fmt::Debug;

/// Default precision of [`super::Mp`] in bits.
pub const DEFAULT_MP_PREC: u32 = 256;

/// The precisions in bits accepted for multi-precision evaluation: the one limit shared by
/// `ppm check --precision mp:BITS`, the oracle (`--bits`, `set_precision`), `ppm diff --bits`,
/// `ppm eval-map --bits` and the constructors of the multi-precision scalar types. The entry
/// points refuse a precision outside it with an error; the scalar constructors, which cannot
/// fail, round into it (and [`super::Mp`] up to whole 64-bit words, reported as the effective
/// precision). The upper end bounds time and memory per evaluation.
pub const PREC_BITS: std::ops::RangeInclusive<u32> = 2..=65_536;

/// `Err` naming the accepted range when `bits` is outside [`PREC_BITS`].
pub fn check_prec_bits(bits: u32) -> Result<u32, String> {
    if PREC_BITS.contains(&bits) {
        Ok(bits)
    } else {
        Err(format!(
            "precision {bits} bits out of range {}..={}",
            PREC_BITS.start(),
            PREC_BITS.end()
        ))
    }
}

/// Precision (significand bits) of IEEE-754 binary64.
pub const F64_PREC: u32 = 53;

/// Three-valued truth: the answer of a decision made with a scalar type that may be unable to
/// decide (intervals). Point types never produce `Unknown` except on NaN.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum Trit {
    /// Decided: holds.
    True,
    /// Decided: fails.
    False,
    /// Could not be decided at the precision used.
    Unknown,
}

impl Trit {
    /// `True` or `False`.
    pub fn from_bool(b: bool) -> Trit {
        if b {
            Trit::True
        } else {
            Trit::False
        }
    }
    /// Kleene conjunction.
    pub fn and(self, o: Trit) -> Trit {
        match (self, o) {
            (Trit::False, _) | (_, Trit::False) => Trit::False,
            (Trit::True, Trit::True) => Trit::True,
            _ => Trit::Unknown,
        }
    }
    /// Decided and true.
    pub fn is_true(self) -> bool {
        self == Trit::True
    }
    /// Decided and false.
    pub fn is_false(self) -> bool {
        self == Trit::False
    }
}

impl std::ops::Not for Trit {
    type Output = Trit;
    /// Kleene negation.
    fn not(self) -> Trit {
        match self {
            Trit::True => Trit::False,
            Trit::False => Trit::True,
            Trit::Unknown => Trit::Unknown,
        }
    }
}

/// A real-number type for the maps of Chapter 4.
///
/// Arithmetic is by methods on references (no HRTB operator bounds needed). Constants take the
/// precision in bits (`prec`), which `f64` ignores.
pub trait Scalar: Clone + Debug + Send + Sync + 'static {
    /// Human-readable name of the type ("f64", "mp256").
    fn type_name(&self) -> String;
    /// `x` rounded to `prec` bits (exact for `Mp` with `prec >= 53`).
    fn from_f64(x: f64, prec: u32) -> Self;
    /// `x` rounded to `prec` bits.
    fn from_i64(x: i64, prec: u32) -> Self;
    /// `p/q` correctly rounded to `prec` bits. `q` must be non-zero (a zero `q` gives ±∞/NaN).
    fn from_ratio(p: i64, q: i64, prec: u32) -> Self;
    /// π rounded to `prec` bits.
    fn pi(prec: u32) -> Self;
    /// Nearest `f64` (the midpoint for interval types).
    fn to_f64(&self) -> f64;
    /// Significand bits of this value.
    fn precision_bits(&self) -> u32;
    /// Unit roundoff `2^-precision_bits` of this value's precision, as `f64`: exact down to
    /// 2^-1074 (the smallest subnormal; `2f64.powi(-bits)` overflows 2^bits and gives 0 from
    /// 1024 bits on), 0 beyond. Decisions at any precision use [`Scalar::unit_roundoff`].
    fn epsilon(&self) -> f64 {
        pow2_neg_f64(self.precision_bits())
    }
    /// Unit roundoff `2^-precision_bits` in this scalar type (exact: a power of two), so that
    /// tolerances of decisions scale with the precision at any precision.
    fn unit_roundoff(&self) -> Self {
        let prec = self.precision_bits();
        let step = Self::from_f64(pow2_neg_f64(64), prec);
        let mut u = Self::from_i64(1, prec);
        for _ in 0..prec / 64 {
            u = u.mul(&step);
        }
        u.mul(&Self::from_f64(pow2_neg_f64(prec % 64), prec))
    }

    /// self + o, rounded (for `Mp`: at the larger precision).
    fn add(&self, o: &Self) -> Self;
    /// self − o, rounded.
    fn sub(&self, o: &Self) -> Self;
    /// self · o, rounded.
    fn mul(&self, o: &Self) -> Self;
    /// self / o, rounded.
    fn div(&self, o: &Self) -> Self;
    /// −self (exact).
    fn neg(&self) -> Self;
    /// √self, rounded.
    fn sqrt(&self) -> Self;
    /// sin(self), rounded.
    fn sin(&self) -> Self;
    /// cos(self), rounded.
    fn cos(&self) -> Self;
    /// |self| (exact).
    fn abs(&self) -> Self;
    /// `atan2(self, x)`: the angle of the point `(x, self)` in `[-π, π]` (IEEE/MPFR semantics,
    /// including signed zeros). The maps never rely on the sign of zero: see `maps::polar`.
    fn atan2(&self, x: &Self) -> Self;

    /// Sign of the value: `Some(Less|Equal|Greater)`, or `None` when it cannot be decided
    /// (NaN; an interval containing 0). Both zeros give `Some(Equal)`.
    fn sign(&self) -> Option<Ordering>;

    /// True when the value is not a number (a NaN point, an empty or NaN enclosure): the one
    /// case where [`Scalar::sign`] is `None` for point types. Interval types override it, as
    /// their `sign` is also `None` for an enclosure that merely contains 0.
    fn is_nan(&self) -> bool {
        self.sign().is_none()
    }

    /// self², as `self.mul(self)`.
    fn sqr(&self) -> Self {
        self.mul(self)
    }
    /// Three-valued comparison `self ? o`, via the sign of the difference.
    fn cmp3(&self, o: &Self) -> Option<Ordering> {
        self.sub(o).sign()
    }
    /// `self < o` as a [`Trit`].
    fn lt(&self, o: &Self) -> Trit {
        match self.cmp3(o) {
            Some(Ordering::Less) => Trit::True,
            Some(_) => Trit::False,
            None => Trit::Unknown,
        }
    }
    /// `self <= o` as a [`Trit`].
    fn le(&self, o: &Self) -> Trit {
        match self.cmp3(o) {
            Some(Ordering::Greater) => Trit::False,
            Some(_) => Trit::True,
            None => Trit::Unknown,
        }
    }
    /// Same type and precision as `self`, value `x`.
    fn like_f64(&self, x: f64) -> Self {
        Self::from_f64(x, self.precision_bits())
    }
    /// `p/q` at the precision of `self`.
    fn like_ratio(&self, p: i64, q: i64) -> Self {
        Self::from_ratio(p, q, self.precision_bits())
    }
}

/// 2^-k as `f64`, built from its bits (exact for k ≤ 1074, 0 beyond).
pub fn pow2_neg_f64(k: u32) -> f64 {
    match k {
        0..=1022 => f64::from_bits(u64::from(1023 - k) << 52),
        1023..=1074 => f64::from_bits(1u64 << (1074 - k)),
        _ => 0.0,
    }
}

impl Scalar for f64 {
    fn type_name(&self) -> String {
        "f64".into()
    }
    fn from_f64(x: f64, _prec: u32) -> Self {
        x
    }
    fn from_i64(x: i64, _prec: u32) -> Self {
        x as f64
    }
    fn from_ratio(p: i64, q: i64, _prec: u32) -> Self {
        // One IEEE division of exactly representable operands is correctly rounded.
        (p as f64) / (q as f64)
    }
    fn pi(_prec: u32) -> Self {
        std::f64::consts::PI
    }
    fn to_f64(&self) -> f64 {
        *self
    }
    fn precision_bits(&self) -> u32 {
        F64_PREC
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn div(&self, o: &Self) -> Self {
        self / o
    }
    fn neg(&self) -> Self {
        -self
    }
    fn sqrt(&self) -> Self {
        f64::sqrt(*self)
    }
    fn sin(&self) -> Self {
        f64::sin(*self)
    }
    fn cos(&self) -> Self {
        f64::cos(*self)
    }
    fn abs(&self) -> Self {
        f64::abs(*self)
    }
    fn atan2(&self, x: &Self) -> Self {
        f64::atan2(*self, *x)
    }
    fn sign(&self) -> Option<Ordering> {
        self.partial_cmp(&0.0)
    }
}
