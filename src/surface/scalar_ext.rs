//! The scalar types of Chapter 5: the Chapter 4 [`Scalar`] plus `exp`, which the weight
//! function ξ of Def. 5.3.1 needs (1/(1 + e^{2s})), and the Def. 5.2.1 patch evaluated in
//! any of them (f64 takes `bezier`'s allocation-free path).

use super::bezier::{binomial, binomial_row, eval_patch_f64, MAX_FAST_L};
use crate::numeric::{Mp, Scalar};

/// A [`Scalar`] with the exponential: `f64`, [`Mp`], and the derivative jets
/// [`super::jet::Jet`] over either.
pub trait SurfaceScalar: Scalar {
    /// e^self, rounded.
    fn exp(&self) -> Self;
    /// self · k for an f64 constant k. The default forms k in the type and multiplies; jets
    /// override it with a coefficient-wise product (a constant jet's full product would spend
    /// most of its work on zeros: the Bézier sums of Def. 5.2.1 do this per control point).
    fn scale_f64(&self, k: f64) -> Self {
        self.mul(&Self::from_f64(k, self.precision_bits()))
    }
    /// ψ(x, y) of a bi-degree (l, l) patch (Def. 5.2.1); `f64` overrides this with an
    /// allocation-free evaluator.
    fn patch(cp: &[[f64; 3]], l: usize, half: f64, x: &Self, y: &Self) -> [Self; 3] {
        eval_patch(cp, l, half, x, y)
    }
}

impl SurfaceScalar for f64 {
    fn exp(&self) -> Self {
        f64::exp(*self)
    }
    fn scale_f64(&self, k: f64) -> Self {
        self * k
    }
    fn patch(cp: &[[f64; 3]], l: usize, half: f64, x: &Self, y: &Self) -> [Self; 3] {
        if l <= MAX_FAST_L {
            eval_patch_f64(cp, l, half, *x, *y)
        } else {
            eval_patch(cp, l, half, x, y)
        }
    }
}

impl SurfaceScalar for Mp {
    fn exp(&self) -> Self {
        Mp::exp(self)
    }
}

#[cfg(feature = "mpfr")]
impl SurfaceScalar for crate::numeric::MpMpfr {
    fn exp(&self) -> Self {
        crate::numeric::MpMpfr::exp(self)
    }
}

/// Def. 5.2.1, generic: the l+1 Bernstein values at t.
#[inline(always)]
pub(crate) fn bernstein<S: SurfaceScalar>(l: usize, half: &S, t: &S) -> Vec<S> {
    let prec = t.precision_bits();
    let two_l = half.mul(&S::from_i64(2, prec));
    let u = t.add(half).div(&two_l);
    let w = half.sub(t).div(&two_l);
    let mut pu = Vec::with_capacity(l + 1);
    let mut acc = S::from_i64(1, prec);
    for _ in 0..=l {
        pu.push(acc.clone());
        acc = acc.mul(&u);
    }
    let mut pw = S::from_i64(1, prec);
    let row = binomial_row(l);
    for i in (0..=l).rev() {
        let c = row.map_or_else(|| binomial(l, i), |r| r[i]);
        pu[i] = pu[i].mul(&pw).mul(&S::from_f64(c, prec));
        pw = pw.mul(&w);
    }
    pu
}

/// ψ(x, y) = Σ_{j,k} b_{j,k} B_j^l(x) B_k^l(y) for control points `cp` (length (l+1)²).
pub(crate) fn eval_patch<S: SurfaceScalar>(
    cp: &[[f64; 3]],
    l: usize,
    half: f64,
    x: &S,
    y: &S,
) -> [S; 3] {
    eval_patch_body(cp, l, half, x, y)
}

/// [`eval_patch`] compiled for the CPU's vector extensions (runtime dispatch). The jets of
/// f64 take it (`jet.rs`): their coefficient-wise products and sums widen; products and sums
/// stay separate (never fused), so the bits do not depend on the CPU. The (σ, v) patches do
/// the same (`sigma_v::patch::eval_tri`).
pub(crate) fn eval_patch_simd<S: SurfaceScalar>(
    cp: &[[f64; 3]],
    l: usize,
    half: f64,
    x: &S,
    y: &S,
) -> [S; 3] {
    pulp::Arch::new().dispatch(EvalPatch { cp, l, half, x, y })
}

/// [`eval_patch`] as a [`pulp::WithSimd`] operation.
struct EvalPatch<'a, S> {
    cp: &'a [[f64; 3]],
    l: usize,
    half: f64,
    x: &'a S,
    y: &'a S,
}

impl<S: SurfaceScalar> pulp::WithSimd for EvalPatch<'_, S> {
    type Output = [S; 3];
    #[inline(always)]
    fn with_simd<V: pulp::Simd>(self, _: V) -> [S; 3] {
        eval_patch_body(self.cp, self.l, self.half, self.x, self.y)
    }
}

#[inline(always)]
fn eval_patch_body<S: SurfaceScalar>(cp: &[[f64; 3]], l: usize, half: f64, x: &S, y: &S) -> [S; 3] {
    let prec = x.precision_bits();
    let h = S::from_f64(half, prec);
    let bx = bernstein(l, &h, x);
    let by = bernstein(l, &h, y);
    let z = S::from_i64(0, prec);
    let mut out = [z.clone(), z.clone(), z];
    for (j, bxj) in bx.iter().enumerate() {
        let mut row = [
            S::from_i64(0, prec),
            S::from_i64(0, prec),
            S::from_i64(0, prec),
        ];
        for (k, byk) in by.iter().enumerate() {
            let c = &cp[j * (l + 1) + k];
            for d in 0..3 {
                row[d] = row[d].add(&byk.scale_f64(c[d]));
            }
        }
        for d in 0..3 {
            out[d] = out[d].add(&row[d].mul(bxj));
        }
    }
    out
}
