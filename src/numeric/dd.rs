//! Double-word ("double-double", ≈ 106-bit) fast paths for the endpoint values of sin, cos and
//! atan2 in [`super::interval`], and an `f64` fast path for its phase test.
//!
//! Why: the interval type evaluates every transcendental endpoint with astro-float at 128 bits
//! (about 10–50 µs each, mostly allocation and series set-up). The certified provers
//! (`ppm certify`) spend > 90 % of their time there; before the pure-Rust interval type, inari
//! (MPFR at 53 bits) did the same in about a microsecond.
//!
//! What is returned is *identical* to the astro-float path, never merely close: that path
//! yields `r = RN₅₃(v)` for the 128-bit value `v` (|v − t| ≤ 2⁻¹²⁸|t|, `t` the exact value).
//! Here `t` is enclosed as `y ± E` in double-word arithmetic, with `E` a bound on the
//! evaluation error that is 2⁸ or more times the analysed error (below), and the answer is
//! returned only when the whole of `[y − E, y + E]` lies at least 2⁻²² ulp inside the rounding
//! interval of `y.hi` (Ziv's rounding test). Then `RN₅₃(t) = RN₅₃(v) = y.hi`, so both paths
//! give the same `f64` (and the interval layer widens it by the same ulp each way). In every
//! other case (zero or tiny results, arguments outside the reduction range, the rare values
//! close to a rounding boundary) the caller falls back to astro-float.
//!
//! Error analysis (u = 2⁻⁵³; relative error bounds of the double-word operations from Joldes,
//! Muller and Popescu, "Tight and rigorous error bounds for basic building blocks of
//! double-word arithmetic", ACM TOMS 44 (2017): DWPlusFP 2u², AccurateDWPlusDW 3u² + 13u³,
//! DWTimesFP3 2u², DWTimesDW3 4u², DWDivFP3 3u², DWDivDW2 15u² + 56u³; all ≤ 2⁻⁹⁸):
//! * sin/cos: k = round(2x/π) with |k| ≤ 1024, r = x − k·π/2 with π/2 as three `f64` (its
//!   truncation error times k is < 2⁻¹⁴⁵); |r| ≤ 0.8; r is exact when k = 0 and otherwise has
//!   absolute error < 2⁻¹⁰² (three additions of magnitude < 1). The Taylor polynomials to
//!   degree 29 (truncation < 2⁻¹¹²) in Horner form: 30 operations on values of magnitude ≤ 1,
//!   absolute error < 2⁻⁹³ (< 2⁻⁹³·|sin r/r| relatively for the odd series). Claimed:
//!   E = 2⁻⁸⁸ absolute, or 2⁻⁸⁸·2|y| when k = 0 (then r = x exactly and sin is relative).
//! * atan2: z = min(|x|,|y|)/max(|x|,|y|) ≤ 1, atan z = atan(j/16) + atan(u),
//!   u = (z − j/16)/(1 + z·j/16), |u| ≤ 1/32 + ε, series to degree 23 (truncation < 2⁻¹²⁵);
//!   atan(j/16), π/2 and π as double words from astro-float at 256 bits. Relative error of
//!   the result < 2⁻⁹⁰ (the result is ≥ atan(1/32)·|…| or a relatively exact series when
//!   j = 0; π/2 − · and π − · add no cancellation, their results being ≥ π/4). Claimed:
//!   E = 2⁻⁸⁵·|y|.

use super::bigfloat::{big_to_f64, with_consts};
use astro_float::{BigFloat, RoundingMode};
use std::sync::OnceLock;

/// An unevaluated sum `hi + lo` with |lo| ≤ ulp(hi)/2.
#[derive(Clone, Copy, Debug)]
struct Dd {
    hi: f64,
    lo: f64,
}

fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    Dd {
        hi: s,
        lo: (a - (s - bb)) + (b - bb),
    }
}

/// Exact when |a| ≥ |b| (or a = 0).
fn fast_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd {
        hi: s,
        lo: b - (s - a),
    }
}

fn two_prod(a: f64, b: f64) -> Dd {
    let p = a * b;
    Dd {
        hi: p,
        lo: a.mul_add(b, -p),
    }
}

impl Dd {
    const fn f(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
    /// DWPlusFP.
    fn add_f(self, b: f64) -> Dd {
        let s = two_sum(self.hi, b);
        fast_two_sum(s.hi, self.lo + s.lo)
    }
    /// AccurateDWPlusDW.
    fn add(self, o: Dd) -> Dd {
        let s = two_sum(self.hi, o.hi);
        let t = two_sum(self.lo, o.lo);
        let v = fast_two_sum(s.hi, s.lo + t.hi);
        fast_two_sum(v.hi, t.lo + v.lo)
    }
    /// DWTimesFP3.
    fn mul_f(self, b: f64) -> Dd {
        let c = two_prod(self.hi, b);
        fast_two_sum(c.hi, self.lo.mul_add(b, c.lo))
    }
    /// DWTimesDW3.
    fn mul(self, o: Dd) -> Dd {
        let c = two_prod(self.hi, o.hi);
        let t = self.hi.mul_add(o.lo, self.lo * o.lo);
        let t = self.lo.mul_add(o.hi, t);
        fast_two_sum(c.hi, c.lo + t)
    }
    /// DWDivFP3.
    fn div_f(self, y: f64) -> Dd {
        let th = self.hi / y;
        let p = two_prod(th, y);
        let d = ((self.hi - p.hi) - p.lo) + self.lo;
        fast_two_sum(th, d / y)
    }
    /// DWDivDW2.
    fn div(self, y: Dd) -> Dd {
        let th = self.hi / y.hi;
        let r = y.mul_f(th);
        let d = (self.hi - r.hi) + (self.lo - r.lo);
        fast_two_sum(th, d / y.hi)
    }
}

/// `RN₅₃(t)` when |t − (y.hi + y.lo)| ≤ `err` proves it, else `None` (see the module doc).
fn round_if_decided(y: Dd, err: f64) -> Option<f64> {
    let h = y.hi;
    if !(h.is_finite() && h.abs() >= 2f64.powi(-600) && y.lo.is_finite()) {
        return None;
    }
    let up = f64::from_bits(h.abs().to_bits() + 1) - h.abs();
    let down = h.abs() - f64::from_bits(h.abs().to_bits() - 1);
    let d = up.min(down); // a power of two: the products below are exact
    let ok = y.lo.abs() <= d * 0.5 * (1.0 - 2f64.powi(-20)) && err <= d * 2f64.powi(-22);
    ok.then_some(h)
}

const RM: RoundingMode = RoundingMode::ToEven;

/// A real constant computed by astro-float at 320 bits, as the double word (RN(v), RN(v − hi)).
fn dd_of(v: &BigFloat) -> Dd {
    let hi = big_to_f64(v);
    let lo = big_to_f64(&v.sub(&BigFloat::from_f64(hi, 64), 320, RM));
    Dd { hi, lo }
}

struct Consts {
    /// π/2 as three `f64`: p[0] + p[1] + p[2], each the rounded remainder of the previous.
    pio2: [f64; 3],
    pi: Dd,
    pi_2: Dd,
    /// atan(j/16), j = 0..=16.
    atan_tab: [Dd; 17],
    /// (−1)^n/(2n+1)! and (−1)^n/(2n)!, n = 0..=14.
    sin_c: [Dd; 15],
    cos_c: [Dd; 15],
    /// (−1)^n/(2n+1), n = 0..=11.
    atan_c: [Dd; 12],
}

fn consts() -> &'static Consts {
    static C: OnceLock<Consts> = OnceLock::new();
    C.get_or_init(|| {
        let p = 320;
        let (pi, pio2, atan_tab) = with_consts(|cc| {
            let pi = cc.pi(p, RM);
            let h = pi.div(&BigFloat::from_i64(2, 64), p, RM);
            let mut rest = h.clone();
            let mut pio2 = [0.0; 3];
            for x in pio2.iter_mut() {
                *x = big_to_f64(&rest);
                rest = rest.sub(&BigFloat::from_f64(*x, 64), p, RM);
            }
            let tab: Vec<Dd> = (0..=16)
                .map(|j| dd_of(&BigFloat::from_f64(j as f64 / 16.0, 64).atan(p, RM, cc)))
                .collect();
            (pi, pio2, tab)
        });
        let pi_dd = dd_of(&pi);
        // Coefficients by repeated division (≤ 29 divisions: relative error < 2⁻⁹⁶).
        let mut fact = [Dd::f(1.0); 30]; // 1/n!
        for n in 1..30 {
            fact[n] = fact[n - 1].div_f(n as f64);
        }
        let sgn = |n: usize, d: Dd| if n % 2 == 0 { d } else { d.neg() };
        Consts {
            pio2,
            pi: pi_dd,
            pi_2: Dd {
                hi: pi_dd.hi / 2.0,
                lo: pi_dd.lo / 2.0,
            },
            atan_tab: std::array::from_fn(|j| atan_tab[j]),
            sin_c: std::array::from_fn(|n| sgn(n, fact[2 * n + 1])),
            cos_c: std::array::from_fn(|n| sgn(n, fact[2 * n])),
            atan_c: std::array::from_fn(|n| sgn(n, Dd::f(1.0).div_f((2 * n + 1) as f64))),
        }
    })
}

fn horner(c: &[Dd], x: Dd) -> Dd {
    let mut p = c[c.len() - 1];
    for &ci in c[..c.len() - 1].iter().rev() {
        p = p.mul(x).add(ci);
    }
    p
}

/// sin x (`cos` = false) or cos x, rounded to nearest `f64`, when decided (module doc).
pub(super) fn sin_cos(x: f64, cos: bool) -> Option<f64> {
    sin_cos_dd(x, cos).and_then(|(y, err)| round_if_decided(y, err))
}

/// sin x or cos x as a double word with its claimed error bound.
fn sin_cos_dd(x: f64, cos: bool) -> Option<(Dd, f64)> {
    // Away from underflow (|x| ≥ 2⁻⁴⁰⁰, so |r| ≥ 2⁻⁴⁰⁰ and every neglected or underflowing
    // term is < 2⁻⁶⁰⁰|y|) and in the range of the three-part reduction.
    if !(x.is_finite() && x.abs() <= 1600.0 && x.abs() >= 2f64.powi(-400)) {
        return None;
    }
    let k = (x * std::f64::consts::FRAC_2_PI).round();
    let c = consts();
    // r = x − k(p0 + p1 + p2): x − k·p0 and k·p1 exactly as double words.
    let r = two_sum(x, -(k * c.pio2[0]))
        .add_f(-(k.mul_add(c.pio2[0], -(k * c.pio2[0]))))
        .add(two_prod(k, c.pio2[1]).neg())
        .add_f(-(k * c.pio2[2]));
    if r.hi.abs() > 0.8 {
        return None;
    }
    let r2 = r.mul(r);
    // Quadrant n = k mod 4: sin x = (sin r, cos r, −sin r, −cos r)[n], cos x = sin(x + π/2).
    let n = (k as i64 + i64::from(cos)).rem_euclid(4);
    let y = if n % 2 == 0 {
        r.mul(horner(&c.sin_c, r2))
    } else {
        horner(&c.cos_c, r2)
    };
    let y = if n >= 2 { y.neg() } else { y };
    let err = if k == 0.0 {
        2f64.powi(-88) * 2.0 * y.hi.abs()
    } else {
        2f64.powi(-88)
    };
    Some((y, err))
}

/// atan2(y, x) ∈ (−π, π] rounded to nearest `f64`, for finite nonzero x and y, when decided.
pub(super) fn atan2(y: f64, x: f64) -> Option<f64> {
    atan2_dd(y, x).and_then(|(v, err)| round_if_decided(v, err))
}

/// atan2(y, x) as a double word with its claimed error bound.
fn atan2_dd(y: f64, x: f64) -> Option<(Dd, f64)> {
    // Away from underflow and overflow: 2⁻⁴⁰⁰ ≤ z (below, the result ≥ z·π/4).
    let range = |t: f64| (2f64.powi(-200)..=2f64.powi(200)).contains(&t.abs());
    if !(range(x) && range(y)) {
        return None;
    }
    let (a, b) = (x.abs(), y.abs());
    let swap = b > a;
    let (num, den) = if swap { (a, b) } else { (b, a) };
    let c = consts();
    let z = Dd::f(num).div_f(den);
    if !(z.hi <= 1.0) {
        return None;
    }
    let j = (z.hi * 16.0).round();
    let cj = j / 16.0;
    let u = z.add_f(-cj).div(z.mul_f(cj).add_f(1.0));
    let base = c.atan_tab[j as usize].add(u.mul(horner(&c.atan_c, u.mul(u))));
    let base = if swap { c.pi_2.add(base.neg()) } else { base };
    let base = if x < 0.0 { c.pi.add(base.neg()) } else { base };
    let v = if y < 0.0 { base.neg() } else { base };
    Some((v, 2f64.powi(-85) * v.hi.abs()))
}

/// Whether `[a, b]` (a ≤ b, |a|, |b| ≤ 2²⁰) may contain a point `k·π/2 + 2πn`, decided in
/// `f64` when no candidate point is within 2⁻²⁰ (in units of 2π) of either end: then the
/// answer equals the 256-bit test of the interval module, whose own error and margin (2⁻⁶⁰)
/// are far smaller, as is the `f64` error here (< 2⁻³²). `None`: too close to decide.
pub(super) fn may_contain_phase(a: f64, b: f64, k: i64) -> Option<bool> {
    if !(a <= b && a.abs() <= 1048576.0 && b.abs() <= 1048576.0) {
        return None;
    }
    const INV_2PI: f64 = 0.5 * std::f64::consts::FRAC_1_PI;
    let shift = k as f64 / 4.0;
    let ta = a * INV_2PI - shift;
    let tb = b * INV_2PI - shift;
    let m = 2f64.powi(-20);
    // Integers in [ta − m, tb + m] ⊇ the tested set; in [ta + m, tb − m] ⊆ it.
    if (ta - m).ceil() > tb + m {
        Some(false)
    } else if (ta + m).ceil() <= tb - m {
        Some(true)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The astro-float path of the interval module: RN₅₃ of the 128-bit value.
    fn astro_sin_cos(x: f64, cos: bool) -> f64 {
        with_consts(|cc| {
            let b = BigFloat::from_f64(x, 128);
            big_to_f64(&if cos {
                b.cos(128, RM, cc)
            } else {
                b.sin(128, RM, cc)
            })
        })
    }

    fn xs() -> impl Iterator<Item = f64> {
        // A deterministic spread over the reduction range, plus multiples of π/12 and nearby.
        let mut s = 0x9E37_79B9_7F4A_7C15u64;
        let rand = (0..4000).map(move |_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        });
        let pis = (-48..=48).flat_map(|i| {
            let t = i as f64 * std::f64::consts::PI / 12.0;
            [
                t,
                f64::from_bits(t.to_bits() + 1),
                f64::from_bits(t.to_bits().wrapping_sub(1)),
            ]
        });
        rand.map(|u| (u - 0.5) * 40.0)
            .chain(pis)
            .chain([0.0, 1e-300, 1e-20, -3e-9, 0.5, 1600.0, -1599.9])
    }

    #[test]
    fn sin_cos_agree_with_astro_whenever_decided() {
        let mut decided = 0;
        for x in xs() {
            for cos in [false, true] {
                if let Some(r) = sin_cos(x, cos) {
                    decided += 1;
                    assert_eq!(
                        r.to_bits(),
                        astro_sin_cos(x, cos).to_bits(),
                        "x = {x:e}, cos = {cos}"
                    );
                }
            }
        }
        assert!(decided > 7000, "{decided}");
    }

    #[test]
    fn atan2_agrees_with_astro_whenever_decided() {
        let mut decided = 0;
        let v: Vec<f64> = xs().filter(|x| x.abs() < 1e3).step_by(7).collect();
        for &y in &v {
            for &x in v.iter().step_by(5) {
                let Some(r) = atan2(y, x) else { continue };
                decided += 1;
                let a = with_consts(|cc| {
                    let (yb, xb) = (BigFloat::from_f64(y, 128), BigFloat::from_f64(x, 128));
                    big_to_f64(&super::super::interval::atan2_point(&yb, &xb, cc))
                });
                assert_eq!(r.to_bits(), a.to_bits(), "atan2({y:e}, {x:e})");
            }
        }
        assert!(decided > 10000, "{decided}");
    }

    /// |(y.hi + y.lo) − exact| in units of the claimed bound, against astro-float at 320 bits
    /// (0 for an exact result with a zero bound).
    fn err_ratio(y: Dd, err: f64, exact: BigFloat) -> f64 {
        let p = 320;
        let s = BigFloat::from_f64(y.hi, 64).add(&BigFloat::from_f64(y.lo, 64), p, RM);
        let d = big_to_f64(&s.sub(&exact, p, RM)).abs();
        if d == 0.0 {
            0.0
        } else {
            d / err
        }
    }

    /// The analysed errors are at least 2⁸ times below the claimed bounds (module doc): the
    /// measured ones must be too, on every sample (a gross slip in the analysis shows here).
    #[test]
    fn measured_errors_are_far_below_the_claimed_bounds() {
        let mut worst: f64 = 0.0;
        for x in xs() {
            for cos in [false, true] {
                let Some((y, err)) = sin_cos_dd(x, cos) else {
                    continue;
                };
                let e = with_consts(|cc| {
                    let b = BigFloat::from_f64(x, 320);
                    if cos {
                        b.cos(320, RM, cc)
                    } else {
                        b.sin(320, RM, cc)
                    }
                });
                let q = err_ratio(y, err, e);
                assert!(q < 2f64.powi(-8), "sin_cos({x:e}, {cos}): {q:e}");
                worst = worst.max(q);
            }
        }
        let v: Vec<f64> = xs().filter(|x| x.abs() < 1e3).step_by(7).collect();
        for &y in &v {
            for &x in v.iter().step_by(5) {
                let Some((d, err)) = atan2_dd(y, x) else {
                    continue;
                };
                let e = with_consts(|cc| {
                    let (yb, xb) = (BigFloat::from_f64(y, 320), BigFloat::from_f64(x, 320));
                    let t = yb.div(&xb, 640, RM).atan(640, RM, cc);
                    let pi = cc.pi(640, RM);
                    match (x < 0.0, y < 0.0) {
                        (false, _) => t,
                        (true, false) => t.add(&pi, 640, RM),
                        (true, true) => t.sub(&pi, 640, RM),
                    }
                });
                let q = err_ratio(d, err, e);
                assert!(q < 2f64.powi(-8), "atan2({y:e}, {x:e}): {q:e}");
                worst = worst.max(q);
            }
        }
        assert!(
            worst > 0.0 && worst < 2f64.powi(-8),
            "worst error / claimed bound = {worst:e}"
        );
        eprintln!("worst error / claimed bound = {worst:e}");
    }

    #[test]
    fn pi_over_2_split_is_exact_to_160_bits() {
        let c = consts();
        // p0 is RN(π/2) and each later part the rounded remainder: decreasing by ≥ 2⁻⁵³.
        assert_eq!(c.pio2[0], std::f64::consts::FRAC_PI_2);
        assert!(c.pio2[1].abs() <= c.pio2[0] * 2f64.powi(-53));
        assert!(c.pio2[2].abs() <= c.pio2[1].abs() * 2f64.powi(-53));
        assert_eq!(c.pi.hi, std::f64::consts::PI);
    }

    #[test]
    fn phase_fast_path_never_contradicts_the_exact_test() {
        for x in xs().filter(|x| x.abs() < 100.0) {
            for w in [0.0, 1e-12, 1e-3, 0.7, 2.0] {
                for k in 0..4 {
                    if let Some(f) = may_contain_phase(x, x + w, k) {
                        assert_eq!(
                            f,
                            super::super::interval::may_contain_phase_exact(x, x + w, k),
                            "[{x:e}, +{w:e}], k = {k}"
                        );
                    }
                }
            }
        }
    }
}
