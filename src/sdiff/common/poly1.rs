//! The univariate polynomials g(t) of the monotonic maps (Mello–Velho Eq. (9)), in both
//! dimensions.

use super::poly2::Poly2;
use super::positivity::{decide_on, Budget, Decision, Strictness};
use super::rational::{q, Q};
use num_traits::Zero;

/// A univariate polynomial g(t) = Σ coeffs\[k\] t^k (the g_i of Eq. (9)).
#[derive(Debug, Clone, PartialEq)]
pub struct Poly1(pub Vec<Q>);

impl Poly1 {
    /// g(t) = t.
    pub fn identity() -> Self {
        Poly1(vec![q(0), q(1)])
    }
    /// g as a polynomial in (s, t) after substituting w.
    pub(crate) fn compose(&self, w: &Poly2) -> Poly2 {
        let mut acc = Poly2::zero(0);
        for c in self.0.iter().rev() {
            acc = acc.mul(w).add(&Poly2::constant(c.clone()));
        }
        acc
    }
    /// g as a polynomial in s only (t absent): for deciding g' > 0 on [0, 1].
    pub(crate) fn as_poly2(&self) -> Poly2 {
        self.compose(&Poly2::s())
    }
    /// g(0).
    pub(crate) fn at_zero(&self) -> Q {
        self.0.first().cloned().unwrap_or_else(Q::zero)
    }
    /// Decides g′ > 0 on \[0, 1\] exactly (the hypothesis of Eq. (9), both dimensions): g′ in
    /// s on the triangle collapsed onto the segment s ∈ \[0, 1\], t = 0 (a refutation's t is
    /// its `point_f64[1]`).
    pub(crate) fn decide_increasing(&self, budget: Budget) -> Decision {
        let seg = [[q(0), q(0)], [q(1), q(0)], [q(1), q(0)]];
        decide_on(&self.as_poly2().ds(), seg, Strictness::Positive, budget)
    }
}
