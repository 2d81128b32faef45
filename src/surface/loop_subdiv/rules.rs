//! Loop's subdivision rules (Loop 1987), generic over the scalar.
//!
//! Vertex rule for a vertex of valence n: v′ = (1 − nβ(n)) v + β(n) Σ rᵢ with
//! β(n) = (5/8 − (3/8 + cos(2π/n)/4)²)/n. Edge rule: e′ = 3/8 (a + b) + 1/8 (c + d), c, d the
//! vertices opposite the edge [a, b].

use crate::numeric::Scalar;

/// (cos 2πω/n, sin 2πω/n), exact (as rationals) where the angle is a multiple of 30° with a
/// rational cosine or sine, so that exact identities of the eigen-structure (λ = 1/8 at
/// ω = n/2, λ₁² = 1/16 at n = 3, β(6) = 1/16) hold exactly in every scalar type.
pub fn cos_sin_2pi<S: Scalar>(omega: i64, n: i64, prec: u32) -> (S, S) {
    let w = omega.rem_euclid(n);
    if (12 * w) % n == 0 {
        let j = 12 * w / n;
        let c = match j {
            0 => Some((1, 1)),
            2 | 10 => Some((1, 2)),
            3 | 9 => Some((0, 1)),
            4 | 8 => Some((-1, 2)),
            6 => Some((-1, 1)),
            _ => None,
        };
        let s = match j {
            0 | 6 => Some((0, 1)),
            1 | 5 => Some((1, 2)),
            3 => Some((1, 1)),
            7 | 11 => Some((-1, 2)),
            9 => Some((-1, 1)),
            _ => None,
        };
        let ang = || S::pi(prec).mul(&S::from_ratio(2 * w, n, prec));
        let c = c.map_or_else(|| ang().cos(), |(p, q)| S::from_ratio(p, q, prec));
        let s = s.map_or_else(|| ang().sin(), |(p, q)| S::from_ratio(p, q, prec));
        return (c, s);
    }
    let ang = S::pi(prec).mul(&S::from_ratio(2 * w, n, prec));
    (ang.cos(), ang.sin())
}

/// β(n) of Loop's vertex rule.
pub fn beta<S: Scalar>(n: u32, prec: u32) -> S {
    let (c, _) = cos_sin_2pi::<S>(1, n as i64, prec);
    let t = S::from_ratio(3, 8, prec).add(&c.mul(&S::from_ratio(1, 4, prec)));
    S::from_ratio(5, 8, prec)
        .sub(&t.sqr())
        .div(&S::from_i64(n as i64, prec))
}

/// Weights of the vertex rule: (centre weight 1 − nβ, ring weight β).
pub fn vertex_weights<S: Scalar>(n: u32, prec: u32) -> (S, S) {
    let b = beta::<S>(n, prec);
    (
        S::from_i64(1, prec).sub(&b.mul(&S::from_i64(n as i64, prec))),
        b,
    )
}

/// Limit-position mask (Loop 1987; from the left eigenvector of eigenvalue 1): weights
/// (centre 3/(3 + 8nβ), ring 8β/(3 + 8nβ)).
pub fn limit_weights<S: Scalar>(n: u32, prec: u32) -> (S, S) {
    let b = beta::<S>(n, prec);
    let d = S::from_i64(3, prec).add(&S::from_i64(8 * n as i64, prec).mul(&b));
    (
        S::from_i64(3, prec).div(&d),
        S::from_i64(8, prec).mul(&b).div(&d),
    )
}
