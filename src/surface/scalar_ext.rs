//! The scalar types of Chapter 5: the Chapter 4 [`Scalar`] plus `exp`, which the weight
//! function ξ of Def. 5.3.1 needs (1/(1 + e^{2s})).

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
        super::bezier::eval_patch(cp, l, half, x, y)
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
        if l <= super::bezier::MAX_FAST_L {
            super::bezier::eval_patch_f64(cp, l, half, *x, *y)
        } else {
            super::bezier::eval_patch(cp, l, half, x, y)
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
