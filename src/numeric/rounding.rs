//! The scalar [`Fe`] ("f64 with error enclosure"): run the generic maps of Sec. 4.1 over a
//! box and obtain, besides an enclosure of the exact value, an enclosure of the difference
//! between what the `f64` instantiation of the *same generic code* computes and that exact
//! value, for every point of the box (SPEC `CERT-f64-rounding`).
//!
//! A value is a pair (V, E) of intervals: V ∋ x (the exact value), E ∋ x̂ − x (x̂ the `f64`
//! value), so W = V + E ∋ x̂. Each operation follows the standard model of IEEE binary64
//! with round to nearest, fl(a ∘ b) = (a ∘ b)(1 + δ), |δ| ≤ u = 2⁻⁵³, for + − × ÷ √
//! (correctly rounded), plus an absolute 2⁻¹⁰⁷⁴ per operation for gradual underflow, and
//! propagates E exactly as algebra dictates (× : x̂ŷ − xy = x·e_y + y·e_x + e_x·e_y; ÷ :
//! x̂/ŷ − x/y = (e_x − (x/y)·e_y)/ŷ; √ : e_x/(√x̂ + √x)). All interval operations round
//! outward (`numeric::interval`).
//!
//! sin, cos and atan2 come from the platform's libm, which is not correctly rounded: their
//! error is an explicit assumption, [`LibmModel::LIBM_ULPS`] ulps of the exact result
//! (see [`LIBM_ASSUMPTION`]), plus the propagated input error by a derivative bound
//! (|sin′|, |cos′| ≤ 1; |∇atan2| = 1/|(x, y)| over the hull of exact and `f64` arguments,
//! which must miss the origin and the cut of Π).
//!
//! Refusals: an operation whose argument or result may leave the finite range, a division by
//! an enclosure containing 0, √ of a possibly negative value, atan2 where the exact or `f64`
//! argument may lie on the cut: E becomes the whole line (callers read a non-finite E as "not
//! bounded"). [`Scalar::sign`] decides only when the exact and the `f64` value have the same
//! sign at every point, so every branch the generic code takes is the branch of both.

use super::interval::Interval;
use super::scalar::{Scalar, F64_PREC};
use std::cmp::Ordering;
use std::marker::PhantomData;

/// u = 2⁻⁵³, the unit roundoff of binary64 (round to nearest).
pub const UNIT_ROUNDOFF: f64 = 1.0 / 9_007_199_254_740_992.0;
/// 2⁻¹⁰⁷⁴: the smallest subnormal, an upper bound of the absolute error that gradual
/// underflow adds to one correctly rounded operation.
const ETA: f64 = 5e-324;

/// The claimed maximum error of the platform's `sin`, `cos`, `atan2` (binary64), in ulps of
/// the exact result: the one place where the assumption lives ([`Glibc`]).
pub const LIBM_ULPS: f64 = 2.0;

/// The libm assumption in words (printed in certificates and their summaries).
pub const LIBM_ASSUMPTION: &str = "assumption: the platform libm's binary64 sin, cos and atan2 (what Rust's f64::sin/cos/atan2 call; glibc on x86_64 Linux) err by at most 2 ulp of the exact result. glibc's manual (\"Known Maximum Errors in Math Functions\") lists at most 1 ulp for these three on x86_64; 2 is that with a margin, not a measurement of this machine. + − × ÷ √ are IEEE-754 correctly rounded (round to nearest, no FMA contraction: Rust does not contract).";

/// The accuracy model of the platform's transcendental functions.
pub trait LibmModel: Clone + Copy + std::fmt::Debug + Default + Send + Sync + 'static {
    /// Maximum error of sin, cos, atan2 in ulps of the exact result.
    const LIBM_ULPS: f64;
}

/// The model the certificates use: [`LIBM_ULPS`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Glibc;

impl LibmModel for Glibc {
    const LIBM_ULPS: f64 = LIBM_ULPS;
}

/// An exact value and the `f64` evaluation's error, both enclosed over a box.
#[derive(Clone, Copy, Debug)]
pub struct Fe<L: LibmModel = Glibc> {
    /// Encloses the exact value.
    pub v: Interval,
    /// Encloses (`f64` value − exact value).
    pub e: Interval,
    _libm: PhantomData<L>,
}

fn pt(x: f64) -> Interval {
    Interval::try_from((x, x)).unwrap_or(Interval::ENTIRE)
}

/// [−x, x] (the whole line for NaN or ∞).
fn sym(x: f64) -> Interval {
    if x.is_finite() {
        Interval::try_from((-x, x)).unwrap_or(Interval::ENTIRE)
    } else {
        Interval::ENTIRE
    }
}

/// max |t| over the interval (∞ for the empty set or NaN endpoints).
pub fn mag(i: Interval) -> f64 {
    if i.is_empty() || i.inf().is_nan() || i.sup().is_nan() {
        f64::INFINITY
    } else {
        i.inf().abs().max(i.sup().abs())
    }
}

/// min |t| over the interval (0 if it contains 0).
fn mig(i: Interval) -> f64 {
    if i.contains(0.0) {
        0.0
    } else {
        i.inf().abs().min(i.sup().abs())
    }
}

/// Rounding error of one correctly rounded result lying in `w`: ±(u·|w| + 2⁻¹⁰⁷⁴).
fn rnd(w: Interval) -> Interval {
    sym((pt(UNIT_ROUNDOFF) * pt(mag(w)) + pt(ETA)).sup())
}

impl<L: LibmModel> Fe<L> {
    /// The pair (V, E), refused (E = the whole line) if the `f64` value may be non-finite.
    pub fn new(v: Interval, e: Interval) -> Fe<L> {
        let w = v + e;
        let finite = !v.is_empty() && mag(w) < f64::MAX / 4.0 && mag(v) < f64::MAX / 4.0;
        Fe {
            v,
            e: if finite { e } else { Interval::ENTIRE },
            _libm: PhantomData,
        }
    }
    /// An exact `f64` input over the box `v` (no error).
    pub fn exact(v: Interval) -> Fe<L> {
        Fe::new(v, pt(0.0))
    }
    /// Encloses the `f64` value: V + E.
    pub fn w(&self) -> Interval {
        self.v + self.e
    }
    /// max |f64 − exact| over the box (∞ if refused).
    pub fn err(&self) -> f64 {
        mag(self.e)
    }
    /// Error of the libm function whose exact value at the `f64` argument lies in `w`.
    fn libm(w: Interval) -> Interval {
        let ulp = pt(2.0 * UNIT_ROUNDOFF) * pt(mag(w)) + pt(ETA);
        sym((pt(L::LIBM_ULPS) * ulp).sup())
    }
    fn refused(v: Interval) -> Fe<L> {
        Fe {
            v,
            e: Interval::ENTIRE,
            _libm: PhantomData,
        }
    }
    /// The constant `f` computed by `f64` code, exact value in `v`.
    fn constant(f: f64, v: Interval) -> Fe<L> {
        Fe::new(v, pt(f) - v)
    }
}

impl<L: LibmModel> Scalar for Fe<L> {
    fn type_name(&self) -> String {
        "f64-error-enclosure".into()
    }
    fn from_f64(x: f64, _prec: u32) -> Self {
        Fe::exact(pt(x))
    }
    fn from_i64(x: i64, prec: u32) -> Self {
        Fe::constant(x as f64, super::Iv::from_i64(x, prec).0)
    }
    fn from_ratio(p: i64, q: i64, prec: u32) -> Self {
        Fe::constant(
            <f64 as Scalar>::from_ratio(p, q, prec),
            super::Iv::from_ratio(p, q, prec).0,
        )
    }
    fn pi(_prec: u32) -> Self {
        Fe::constant(std::f64::consts::PI, Interval::PI)
    }
    fn to_f64(&self) -> f64 {
        self.w().mid()
    }
    fn precision_bits(&self) -> u32 {
        F64_PREC
    }
    fn add(&self, o: &Self) -> Self {
        Fe::new(self.v + o.v, self.e + o.e + rnd(self.w() + o.w()))
    }
    fn sub(&self, o: &Self) -> Self {
        Fe::new(self.v - o.v, self.e - o.e + rnd(self.w() - o.w()))
    }
    fn mul(&self, o: &Self) -> Self {
        let e = self.v * o.e + o.v * self.e + self.e * o.e;
        Fe::new(self.v * o.v, e + rnd(self.w() * o.w()))
    }
    fn div(&self, o: &Self) -> Self {
        let (wo, v) = (o.w(), self.v / o.v);
        if o.v.contains(0.0) || wo.contains(0.0) {
            return Fe::refused(v);
        }
        let e = (self.e - v * o.e) / wo;
        Fe::new(v, e + rnd(self.w() / wo))
    }
    fn neg(&self) -> Self {
        Fe::new(-self.v, -self.e)
    }
    fn sqrt(&self) -> Self {
        let (v, w) = (self.v, self.w());
        if v.inf() < 0.0 || w.inf() < 0.0 {
            return Fe::refused(v.sqrt());
        }
        let e = if v.inf() > 0.0 && w.inf() > 0.0 {
            self.e / (v.sqrt() + w.sqrt())
        } else {
            // |√a − √b| ≤ √|a − b| for a, b ≥ 0.
            sym(pt(mag(self.e)).sqrt().sup())
        };
        Fe::new(v.sqrt(), e + rnd(w.sqrt()))
    }
    fn sin(&self) -> Self {
        Fe::new(self.v.sin(), sym(self.err()) + Self::libm(self.w().sin()))
    }
    fn cos(&self) -> Self {
        Fe::new(self.v.cos(), sym(self.err()) + Self::libm(self.w().cos()))
    }
    fn abs(&self) -> Self {
        let e = match (self.sign(), self.sign_of(self.w())) {
            (Some(Ordering::Greater), _) => self.e,
            (Some(Ordering::Less), _) => -self.e,
            // ||x̂| − |x|| ≤ |x̂ − x|.
            _ => sym(self.err()),
        };
        Fe::new(self.v.abs(), e)
    }
    fn atan2(&self, x: &Self) -> Self {
        let v = super::Iv(self.v).atan2(&super::Iv(x.v)).0;
        // The hull of exact and f64 arguments: the mean value theorem on the segment between
        // them needs atan2 smooth there (off the origin and the cut {y = 0, x ≤ 0}).
        let (hy, hx) = (self.v.convex_hull(self.w()), x.v.convex_hull(x.w()));
        if hx.inf() <= 0.0 && hy.contains(0.0) {
            return Fe::refused(v);
        }
        // Exact arguments (a query point itself): nothing propagates, the segment is a point,
        // and no distance from the origin is needed (it underflows next to it).
        let prop = if x.err() == 0.0 && self.err() == 0.0 {
            0.0
        } else {
            let rmin = (pt(mig(hx)).sqr() + pt(mig(hy)).sqr()).sqrt().inf();
            if rmin.is_nan() || rmin <= 0.0 {
                return Fe::refused(v);
            }
            ((pt(x.err()) + pt(self.err())) / pt(rmin)).sup()
        };
        let wv = self.w().atan2(x.w());
        Fe::new(v, sym(prop) + Self::libm(wv))
    }
    fn sqr(&self) -> Self {
        let e = pt(2.0) * self.v * self.e + self.e.sqr();
        Fe::new(self.v.sqr(), e + rnd(self.w().sqr()))
    }
    fn is_nan(&self) -> bool {
        self.v.is_empty() || self.v.inf().is_nan() || self.v.sup().is_nan()
    }
    fn sign(&self) -> Option<Ordering> {
        if !self.err().is_finite() {
            return None;
        }
        let (a, b) = (self.sign_of(self.v), self.sign_of(self.w()));
        if a == b {
            a
        } else {
            None
        }
    }
}

impl<L: LibmModel> Fe<L> {
    /// The sign of every point of `i`, if it is the same.
    fn sign_of(&self, i: Interval) -> Option<Ordering> {
        if i.is_empty() || i.inf().is_nan() || i.sup().is_nan() {
            None
        } else if i.inf() > 0.0 {
            Some(Ordering::Greater)
        } else if i.sup() < 0.0 {
            Some(Ordering::Less)
        } else if i.inf() == 0.0 && i.sup() == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::Mp;

    /// A libm model claiming correct rounding to 0 ulp (impossible): the planted fault.
    #[derive(Clone, Copy, Debug, Default)]
    struct ZeroUlp;
    impl LibmModel for ZeroUlp {
        const LIBM_ULPS: f64 = 0.0;
    }

    fn mp_err(f: f64, exact: &Mp) -> f64 {
        exact
            .sub(&Mp::from_f64(f, exact.precision_bits()))
            .abs()
            .to_f64()
    }

    /// A short generic expression with every operation, evaluated in f64, Mp and Fe at
    /// seeded points: the f64 − exact difference lies within the Fe bound (CERT-f64-rounding).
    fn expr<S: Scalar>(x: &S, y: &S) -> S {
        let p = S::pi(x.precision_bits());
        let a = x.mul(y).add(&x.div(&y.add(&S::from_i64(3, 53))));
        let b = a.sqr().add(&y.sqr()).sqrt();
        let c = y.atan2(x).mul(&S::from_ratio(7, 6, 53)).sin();
        b.sub(&c.mul(&p).cos()).abs().neg()
    }

    #[test]
    fn cert_f64_rounding_fe_encloses_the_f64_error_of_every_op() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(7);
        let mut worst_ratio: f64 = 0.0;
        for _ in 0..2000 {
            let (x, y) = (rng.gen_range(-2.0..2.0), rng.gen_range(0.1..2.0));
            let f = expr(&x, &y);
            let m = expr(&Mp::from_f64(x, 256), &Mp::from_f64(y, 256));
            let fe: Fe = expr(&Fe::exact(pt(x)), &Fe::exact(pt(y)));
            let d = mp_err(f, &m);
            assert!(
                fe.v.contains(m.to_f64()),
                "x={x} y={y}: exact value outside V"
            );
            assert!(
                d <= fe.err(),
                "x={x} y={y}: |f64 − mp| = {d:e} > {:e}",
                fe.err()
            );
            worst_ratio = worst_ratio.max(d / fe.err());
        }
        // The bound is not vacuous: some point uses a sizeable part of it.
        assert!(worst_ratio > 1e-3, "{worst_ratio}");
    }

    #[test]
    fn cert_f64_rounding_fe_planted_zero_ulp_libm_is_violated() {
        // Claiming a correctly-rounded-to-0-ulp sin: the f64 sin differs from the exact one
        // at almost every point, so the claimed bound (underflow term only) is violated.
        let mut violated = 0;
        for k in 1..200 {
            let x = k as f64 * 0.01;
            let fe: Fe<ZeroUlp> = Fe::exact(pt(x)).sin();
            let d = mp_err(x.sin(), &Mp::from_f64(x, 256).sin());
            if d > fe.err() {
                violated += 1;
            }
        }
        assert!(violated > 50, "{violated}");
    }

    #[test]
    fn cert_f64_rounding_fe_refuses_division_by_zero_and_the_cut() {
        let z: Fe = Fe::exact(Interval::try_from((-1.0, 1.0)).unwrap());
        let one: Fe = Fe::from_i64(1, 53);
        assert!(!one.div(&z).err().is_finite());
        assert!(!z.atan2(&one.neg()).err().is_finite());
        assert_eq!(z.sign(), None);
        assert_eq!(one.sign(), Some(Ordering::Greater));
        let big: Fe = Fe::from_f64(f64::MAX / 2.0, 53);
        assert!(!big.mul(&big).err().is_finite());
    }
}
