//! The default multi-precision scalar [`Mp`]: pure-Rust binary floating point (`astro-float`),
//! round-to-nearest-even, precision carried in the value. No system library is needed, so the
//! default build compiles on a machine with only the Rust toolchain (docs/multiprecision.md).
//!
//! Rounding: +, −, ×, ÷, √, sin, cos, exp, π and the conversions from `f64`/`i64` are correctly
//! rounded to the value's precision (astro-float's guarantee). `atan2` is composed of a quotient
//! and `atan` (and ±π) evaluated with [`GUARD_BITS`] extra bits and rounded once, so its error is
//! below one ulp (faithful). Conversion to `f64` is correctly rounded (round-to-odd to 64 bits,
//! then one IEEE rounding) except for results in the subnormal range, which may be rounded twice.
//!
//! Astro-float stores whole 64-bit words: a requested precision is rounded up to a multiple of
//! 64 bits, and [`Scalar::precision_bits`] reports the precision actually used, so every
//! tolerance derived from it is derived from the arithmetic really performed.

use super::bigfloat::{big_to_f64, with_consts};
use super::scalar::{Scalar, DEFAULT_MP_PREC};
use astro_float::{BigFloat, Radix, RoundingMode};
use std::cmp::Ordering;

/// Extra bits used inside composite operations (`atan2`) before the single final rounding.
pub const GUARD_BITS: u32 = 64;

/// Smallest and largest precision of an [`Mp`]: one 64-bit word up to the end of
/// [`super::scalar::PREC_BITS`] (requests are rounded into this range, then up to whole words;
/// the entry points refuse requests outside `PREC_BITS` before they get here).
pub const MP_PREC_RANGE: (u32, u32) = (64, *super::scalar::PREC_BITS.end());

const RM: RoundingMode = RoundingMode::ToEven;

/// A multi-precision float (pure Rust, round-to-nearest-even) whose precision is carried in the
/// value. The precision is stored alongside the number because NaN and ±∞ carry none.
#[derive(Clone, Debug)]
pub struct Mp {
    v: BigFloat,
    prec: u32,
}

impl PartialEq for Mp {
    fn eq(&self, o: &Self) -> bool {
        self.v.partial_cmp(&o.v) == Some(Ordering::Equal)
    }
}

impl Mp {
    /// A requested precision clamped to [`MP_PREC_RANGE`] and rounded up to whole words.
    pub fn effective_precision(prec: u32) -> u32 {
        let p = prec.clamp(MP_PREC_RANGE.0, MP_PREC_RANGE.1);
        p.div_ceil(64) * 64
    }
    fn wrap(v: BigFloat, prec: u32) -> Mp {
        Mp { v, prec }
    }
    fn p2(&self, o: &Self) -> u32 {
        self.prec.max(o.prec)
    }
    /// `x` rounded to `prec` bits; same as [`Scalar::from_f64`].
    pub fn new(prec: u32, x: f64) -> Mp {
        <Mp as Scalar>::from_f64(x, prec)
    }
    /// The underlying astro-float value.
    pub fn big(&self) -> &BigFloat {
        &self.v
    }
    /// e^self, correctly rounded.
    pub fn exp(&self) -> Mp {
        let p = self.prec;
        Mp::wrap(with_consts(|cc| self.v.exp(p as usize, RM, cc)), p)
    }
    /// All significant decimal digits (scientific notation), for reports and the oracle.
    pub fn to_decimal(&self) -> String {
        if self.v.is_nan() {
            return "NaN".into();
        }
        if self.v.is_inf() {
            return if self.v.is_negative() { "-inf" } else { "inf" }.into();
        }
        with_consts(|cc| self.v.format(Radix::Dec, RM, cc)).unwrap_or_else(|_| "NaN".into())
    }
    /// A decimal (or `inf`/`nan`) string correctly rounded to `prec` bits; `None` if it does not
    /// parse.
    pub fn parse_decimal(s: &str, prec: u32) -> Option<Mp> {
        let p = Mp::effective_precision(prec);
        let t = s.trim();
        let v = with_consts(|cc| BigFloat::parse(t, Radix::Dec, p as usize, RM, cc));
        if v.is_nan() && !t.eq_ignore_ascii_case("nan") {
            return None;
        }
        Some(Mp::wrap(v, p))
    }
}

impl Default for Mp {
    fn default() -> Self {
        Mp::new(DEFAULT_MP_PREC, 0.0)
    }
}

impl Scalar for Mp {
    fn type_name(&self) -> String {
        format!("mp{}", self.prec)
    }
    fn from_f64(x: f64, prec: u32) -> Self {
        let p = Mp::effective_precision(prec);
        Mp::wrap(BigFloat::from_f64(x, p as usize), p)
    }
    fn from_i64(x: i64, prec: u32) -> Self {
        let p = Mp::effective_precision(prec);
        Mp::wrap(BigFloat::from_i64(x, p as usize), p)
    }
    fn from_ratio(p: i64, q: i64, prec: u32) -> Self {
        let pr = Mp::effective_precision(prec);
        if q == 0 {
            return Mp::from_f64(p as f64 / 0.0, pr);
        }
        // Both integers are exact at ≥ 64 bits; one correctly rounded division.
        let a = BigFloat::from_i64(p, 64);
        let b = BigFloat::from_i64(q, 64);
        Mp::wrap(a.div(&b, pr as usize, RM), pr)
    }
    fn pi(prec: u32) -> Self {
        let p = Mp::effective_precision(prec);
        Mp::wrap(with_consts(|cc| cc.pi(p as usize, RM)), p)
    }
    fn to_f64(&self) -> f64 {
        big_to_f64(&self.v)
    }
    fn precision_bits(&self) -> u32 {
        self.prec
    }
    fn add(&self, o: &Self) -> Self {
        let p = self.p2(o);
        Mp::wrap(self.v.add(&o.v, p as usize, RM), p)
    }
    fn sub(&self, o: &Self) -> Self {
        let p = self.p2(o);
        Mp::wrap(self.v.sub(&o.v, p as usize, RM), p)
    }
    fn mul(&self, o: &Self) -> Self {
        let p = self.p2(o);
        Mp::wrap(self.v.mul(&o.v, p as usize, RM), p)
    }
    fn div(&self, o: &Self) -> Self {
        let p = self.p2(o);
        Mp::wrap(self.v.div(&o.v, p as usize, RM), p)
    }
    fn neg(&self) -> Self {
        Mp::wrap(self.v.neg(), self.prec)
    }
    fn sqrt(&self) -> Self {
        Mp::wrap(self.v.sqrt(self.prec as usize, RM), self.prec)
    }
    fn sin(&self) -> Self {
        let p = self.prec;
        Mp::wrap(with_consts(|cc| self.v.sin(p as usize, RM, cc)), p)
    }
    fn cos(&self) -> Self {
        let p = self.prec;
        Mp::wrap(with_consts(|cc| self.v.cos(p as usize, RM, cc)), p)
    }
    fn abs(&self) -> Self {
        Mp::wrap(self.v.abs(), self.prec)
    }
    fn atan2(&self, x: &Self) -> Self {
        let p = self.p2(x);
        Mp::wrap(atan2_big(&self.v, &x.v, p), p)
    }
    fn sign(&self) -> Option<Ordering> {
        if self.v.is_nan() {
            None
        } else if self.v.is_zero() {
            Some(Ordering::Equal)
        } else if self.v.is_negative() {
            Some(Ordering::Less)
        } else {
            Some(Ordering::Greater)
        }
    }
}

/// `atan2(y, x)` with IEEE/MPFR semantics (signed zeros, infinities), rounded to `p` bits.
/// Finite non-zero cases: atan(y/x), plus ±π when x < 0, all at `p + GUARD_BITS` bits.
fn atan2_big(y: &BigFloat, x: &BigFloat, p: u32) -> BigFloat {
    let (pu, pg) = (p as usize, (p + GUARD_BITS) as usize);
    if y.is_nan() || x.is_nan() {
        return BigFloat::nan(None);
    }
    let yneg = y.is_negative();
    let signed = |v: BigFloat| if yneg { v.neg() } else { v };
    with_consts(|cc| {
        let pi = cc.pi(pg, RM);
        let frac = |n: u64, d: u64| {
            pi.mul(&BigFloat::from_u64(n, 64), pg, RM)
                .div(&BigFloat::from_u64(d, 64), pu, RM)
        };

        if y.is_inf() {
            if x.is_inf() {
                if x.is_negative() {
                    signed(frac(3, 4))
                } else {
                    signed(frac(1, 4))
                }
            } else {
                signed(frac(1, 2))
            }
        } else if x.is_inf() {
            if x.is_negative() {
                signed(frac(1, 1))
            } else {
                signed(BigFloat::from_u64(0, pu))
            }
        } else if x.is_zero() {
            if y.is_zero() {
                // atan2(±0, +0) = ±0, atan2(±0, −0) = ±π.
                if x.is_negative() {
                    signed(frac(1, 1))
                } else {
                    y.clone()
                }
            } else {
                signed(frac(1, 2))
            }
        } else if y.is_zero() {
            if x.is_negative() {
                signed(frac(1, 1))
            } else {
                y.clone()
            }
        } else {
            let t = y.div(x, pg, RM).atan(pg, RM, cc);
            if x.is_negative() {
                if yneg {
                    t.sub(&pi, pu, RM)
                } else {
                    t.add(&pi, pu, RM)
                }
            } else {
                let mut t = t;
                // Reduce to p bits with one rounding.
                let _ = t.set_precision(pu, RM);
                t
            }
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_round_trip_and_round_correctly() {
        // astro-float has no negative zero: −0 becomes +0 (the maps never rely on the sign of
        // zero, see maps::polar).
        assert_eq!(Mp::from_f64(-0.0, 256).to_f64(), 0.0);
        for x in [0.0, 1.0, -2.5, 1e-300, 3.0e300, std::f64::consts::PI, 0.1] {
            let m = Mp::from_f64(x, 256);
            assert_eq!(m.to_f64().to_bits(), x.to_bits(), "{x}");
        }
        // 1/3 at 256 bits rounds to the f64 nearest 1/3.
        assert_eq!(Mp::from_ratio(1, 3, 256).to_f64(), 1.0 / 3.0);
        assert_eq!(Mp::from_ratio(-7, 10, 100).to_f64(), -0.7);
        assert_eq!(Mp::from_ratio(-7, 10, 100).precision_bits(), 128);
        assert!(Mp::from_ratio(0, 0, 256).sign().is_none());
        assert_eq!(Mp::pi(256).to_f64(), std::f64::consts::PI);
    }

    #[test]
    fn elementary_functions_agree_with_f64() {
        let xs = [0.3, -1.7, 2.9, 10.0, -0.001];
        for &x in &xs {
            let m = Mp::from_f64(x, 256);
            for (a, b) in [
                (m.sin().to_f64(), x.sin()),
                (m.cos().to_f64(), x.cos()),
                (m.exp().to_f64(), x.exp()),
                (m.abs().sqrt().to_f64(), x.abs().sqrt()),
            ] {
                assert!(
                    (a - b).abs() <= 2.0 * f64::EPSILON * b.abs().max(1e-300),
                    "{x}: {a} {b}"
                );
            }
        }
        for (y, x) in [
            (1.0, 1.0),
            (1.0, -1.0),
            (-1.0, -1.0),
            (-1.0, 1.0),
            (0.0, -1.0),
            (2.0, 0.0),
            (-2.0, 0.0),
            (0.0, 0.0),
            (1e-20, -1.0),
        ] {
            let a = Mp::from_f64(y, 256).atan2(&Mp::from_f64(x, 256)).to_f64();
            let b = f64::atan2(y, x);
            assert!(
                (a - b).abs() <= 2.0 * f64::EPSILON * b.abs(),
                "atan2({y},{x}): {a} {b}"
            );
            eprintln!("atan2({y}, {x}) = {a}");
            assert_eq!(a.is_sign_negative(), b.is_sign_negative(), "atan2({y},{x})");
        }
    }

    #[test]
    fn decimal_strings_round_trip() {
        let t = Mp::from_ratio(2, 3, 256);
        let s = t.to_decimal();
        let back = Mp::parse_decimal(&s, 256).expect("parses");
        let d = back.sub(&t).abs().to_f64();
        assert!(d < 1e-70, "{s}: {d}");
        assert!(Mp::parse_decimal("not a number", 256).is_none());
    }
}
