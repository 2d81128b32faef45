//! Defs. 5.3.1–5.3.2: the scalar function ξ and the weight functions γ_v.

use super::scalar_ext::SurfaceScalar;
use crate::construction::P2;

/// The constants of ξ for a vertex of degree m (Def. 5.3.2): H₂ = cos(π/m_v) (the radius of
/// Ω_v) and H₁ = 0.25·H₂, in the scalar `S` at precision `prec`.
#[derive(Clone, Debug)]
pub struct XiConsts<S> {
    /// H₁ = H₂/4: ξ = 1 for t ≤ H₁.
    pub h1: S,
    /// H₂ = cos(π/m_v): ξ = 0 for t ≥ H₂.
    pub h2: S,
}

impl<S: SurfaceScalar> XiConsts<S> {
    /// Def. 5.3.2: H₂ = cos(π/m), H₁ = H₂/4.
    pub fn for_degree(m: u32, prec: u32) -> Self {
        let h2 = crate::construction::maps::omega_radius::<S>(m, prec);
        let h1 = h2.mul(&S::from_ratio(1, 4, prec));
        XiConsts { h1, h2 }
    }
}

/// Def. 5.3.1 evaluated at t = √(t²), given t² (so that jets are never differentiated
/// through the non-smooth √ at 0: ξ is constant for t ≤ H₁):
/// ξ(t) = 1 (t ≤ H₁), 0 (t ≥ H₂), 1/(1 + e^{2s}) otherwise, with
/// s = 1/√(1−H) − 1/√H and H = (t − H₁)/(H₂ − H₁).
pub fn xi_of_sq<S: SurfaceScalar>(k: &XiConsts<S>, t2: &S) -> S {
    let prec = t2.precision_bits();
    if t2.le(&k.h1.sqr()).is_true() {
        return S::from_i64(1, prec);
    }
    if k.h2.sqr().le(t2).is_true() {
        return S::from_i64(0, prec);
    }
    let t = t2.sqrt();
    xi_open(k, &t)
}

/// Def. 5.3.1 on (H₁, H₂), the non-constant branch, as the logistic function
/// ξ = 1/(1 + e^{2s}) = e^{−2s}/(1 + e^{−2s}), evaluated with the exponent ≤ 0 only: near H₂
/// (s → +∞) the literal form's e^{2s} overflows (f64 already where 2s > 709.8), and its
/// derivatives become ∞/∞ = NaN although ξ is C^∞ and flat there. With e^{−2|s|} ≤ 1 every
/// term of the value and of the jet's derivatives stays finite.
fn xi_open<S: SurfaceScalar>(k: &XiConsts<S>, t: &S) -> S {
    let prec = t.precision_bits();
    let one = S::from_i64(1, prec);
    let hh = t.sub(&k.h1).div(&k.h2.sub(&k.h1));
    // t² < H₂² and t² > H₁² do not imply 0 < H < 1 after rounding (t = √(t²) and the division
    // round): at H ≥ 1 the literal form takes √0 or √(negative) and every derivative is NaN.
    // ξ is flat at both ends (all derivatives vanish), so the constant is the exact limit.
    if one.le(&hh).is_true() {
        return S::from_i64(0, prec);
    }
    if hh.sign() != Some(std::cmp::Ordering::Greater) && hh.sign().is_some() {
        return one;
    }
    let s = one.div(&one.sub(&hh).sqrt()).sub(&one.div(&hh.sqrt()));
    let two = S::from_i64(2, prec);
    if s.sign() == Some(std::cmp::Ordering::Greater) {
        let e = s.mul(&two).neg().exp();
        e.div(&one.add(&e))
    } else {
        let e = s.mul(&two).exp();
        one.div(&one.add(&e))
    }
}

/// Def. 5.3.1: ξ(t) for any real t.
pub fn xi<S: SurfaceScalar>(k: &XiConsts<S>, t: &S) -> S {
    let prec = t.precision_bits();
    if t.le(&k.h1).is_true() {
        return S::from_i64(1, prec);
    }
    if k.h2.le(t).is_true() {
        return S::from_i64(0, prec);
    }
    xi_open(k, t)
}

/// Def. 5.3.2: γ_v(p) = ξ(‖p‖) with the constants of the degree of v.
pub fn gamma<S: SurfaceScalar>(k: &XiConsts<S>, p: &P2<S>) -> S {
    xi_of_sq(k, &p.norm2())
}
