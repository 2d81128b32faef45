//! Stam (1998): exact evaluation of one patch, with first and second derivatives.
//!
//! Patch parameter (x, y) on the triangle (0,0), (1,0), (0,1), the net's first point at
//! (0, 0). A regular patch is the quartic of [`super::regular`]. On a patch with an
//! extraordinary first vertex, a point with x + y ∈ (2⁻ⁿ, 2¹⁻ⁿ] lies in one of the three
//! regular sub-triangles of level n; its net is B_k Aⁿ⁻¹ C₀ ([`EigenStructure::sub_net`]),
//! evaluated at Stam's t_{k,n}(x, y) with the chain rule (factor ±2ⁿ per derivative).

use super::eigen::{powi, EigenStructure};
use super::regular::{basis_exact, ratio_to_i64, MONOMIALS};
use crate::numeric::Scalar;
use std::cmp::Ordering;

/// Position and (when defined) the derivatives ∂x, ∂y, ∂xx, ∂xy, ∂yy of a parametrized
/// surface point.
#[derive(Debug, Clone)]
pub struct PatchJet<S> {
    /// The point.
    pub p: [S; 3],
    /// [∂x, ∂y, ∂xx, ∂xy, ∂yy]; `None` at an extraordinary vertex (the parametrization has
    /// derivative 0 or ∞ there: Stam 1998, Sec. 5) or when not asked for.
    pub d: Option<[[S; 3]; 5]>,
    /// Subdivision level of the regular piece evaluated (0 on a regular face, n in Stam's
    /// tile Ω_k^n, one more after the internal step): derivative k carries a factor 2^{k·level}
    /// that rounding errors share, so tolerances scale with it.
    pub level: u32,
}

/// The 12 regular basis polynomials in the scalar type (monomial coefficients).
pub fn basis_in<S: Scalar>(prec: u32) -> Option<[[S; 15]; 12]> {
    let e = basis_exact();
    if e.len() != 12 {
        return None;
    }
    let mut out: [[S; 15]; 12] =
        std::array::from_fn(|_| std::array::from_fn(|_| S::from_i64(0, prec)));
    for (k, row) in e.iter().enumerate() {
        for (j, q) in row.iter().enumerate() {
            let (p, d) = ratio_to_i64(q)?;
            out[k][j] = S::from_ratio(p, d, prec);
        }
    }
    Some(out)
}

fn scale3<S: Scalar>(p: &[S; 3], w: &S) -> [S; 3] {
    [p[0].mul(w), p[1].mul(w), p[2].mul(w)]
}

/// The regular patch with net `net` at s = (x, y); derivatives if `derivs`.
pub fn regular_jet<S: Scalar>(
    basis: &[[S; 15]; 12],
    net: &[[S; 3]; 12],
    x: &S,
    y: &S,
    derivs: bool,
    prec: u32,
) -> PatchJet<S> {
    let zero = S::from_i64(0, prec);
    let one = S::from_i64(1, prec);
    let mut xp = vec![one.clone()];
    let mut yp = vec![one];
    for i in 1..=4 {
        xp.push(xp[i - 1].mul(x));
        yp.push(yp[i - 1].mul(y));
    }
    let nq = if derivs { 6 } else { 1 };
    // Monomial values and derivatives: q = 0 value, 1 ∂x, 2 ∂y, 3 ∂xx, 4 ∂xy, 5 ∂yy.
    let mono: Vec<[S; 15]> = (0..nq)
        .map(|q| {
            std::array::from_fn(|j| {
                let (a, b) = MONOMIALS[j];
                let (da, db) = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)][q];
                if a < da || b < db {
                    return zero.clone();
                }
                let fa = (0..da).fold(1i64, |f, i| f * (a - i) as i64);
                let fb = (0..db).fold(1i64, |f, i| f * (b - i) as i64);
                S::from_i64(fa * fb, prec)
                    .mul(&xp[(a - da) as usize])
                    .mul(&yp[(b - db) as usize])
            })
        })
        .collect();
    let mut out: Vec<[S; 3]> = vec![[zero.clone(), zero.clone(), zero.clone()]; nq];
    for (bk, pk) in basis.iter().zip(net) {
        for (q, m) in mono.iter().enumerate() {
            let phi = bk
                .iter()
                .zip(m)
                .fold(zero.clone(), |s, (c, v)| s.add(&c.mul(v)));
            for d in 0..3 {
                out[q][d] = out[q][d].add(&phi.mul(&pk[d]));
            }
        }
    }
    let p = out[0].clone();
    let d = derivs.then(|| std::array::from_fn(|q| out[q + 1].clone()));
    PatchJet { p, d, level: 0 }
}

/// The limit position of the extraordinary vertex: the component of the net on the
/// eigenvector (1, …, 1) of eigenvalue 1.
pub fn vertex_limit<S: Scalar>(es: &EigenStructure<S>, net: &[[S; 3]]) -> [S; 3] {
    es.project(net).0[0].clone()
}

/// The limit normal (unnormalised) at the extraordinary vertex: the cross product of the
/// components on the two eigenvectors (0; cos 2πi/N), (0; sin 2πi/N) of the subdominant
/// eigenvalue λ₁; oriented like ∂x × ∂y of the patch (the ring runs counter-clockwise).
pub fn vertex_normal<S: Scalar>(es: &EigenStructure<S>, net: &[[S; 3]]) -> [S; 3] {
    let cin = es.project(net).0;
    cross(&cin[2], &cin[3])
}

/// a × b.
pub fn cross<S: Scalar>(a: &[S; 3], b: &[S; 3]) -> [S; 3] {
    [
        a[1].mul(&b[2]).sub(&a[2].mul(&b[1])),
        a[2].mul(&b[0]).sub(&a[0].mul(&b[2])),
        a[0].mul(&b[1]).sub(&a[1].mul(&b[0])),
    ]
}

/// Stam's evaluation of a patch whose first net point is extraordinary (valence
/// `es.n`), at (x, y) with x, y ≥ 0, x + y ≤ 1. At x + y = 0 (or closer than 2^-(2p+64) for
/// precision p, where λ₁ⁿ < 2^-p) the vertex limit without derivatives.
pub fn extraordinary_jet<S: Scalar>(
    es: &EigenStructure<S>,
    basis: &[[S; 15]; 12],
    net: &[[S; 3]],
    x: &S,
    y: &S,
    derivs: bool,
) -> PatchJet<S> {
    extraordinary_jet_as(es, basis, net, x, y, derivs, false)
}

/// Deepest level of Stam's tiling evaluated at `bits` of precision: 2·bits + 64. Below it the
/// point is the vertex limit to the precision (derivatives `None`).
pub const fn depth_cap(bits: u32) -> u64 {
    2 * bits as u64 + 64
}

/// Stam's tile of the patch point (x, y), x, y ≥ 0: the level n ≥ 1 with x + y ∈
/// (2^−n, 2^(1−n)], the sub-triangle k ∈ {0, 1, 2} of that level, the point's coordinates in
/// it and the sign of that map (−1 for the flipped middle triangle k = 1). `None` when
/// x + y ≤ 0 or n would pass `cap`: the point is the vertex limit to the precision. One
/// function for the generic evaluation and the f64 hot path (`fast`), so they cannot drift.
pub fn stam_tile<S: Scalar>(
    x: &S,
    y: &S,
    cap: u64,
    prec: u32,
) -> Option<(u64, usize, (S, S), i64)> {
    let c = |p: i64, q: i64| S::from_ratio(p, q, prec);
    let t = x.add(y);
    if t.sign() != Some(Ordering::Greater) {
        return None;
    }
    let half = c(1, 2);
    let two = c(2, 1);
    let mut n: u64 = 1;
    let mut tt = t;
    while tt.le(&half).is_true() {
        tt = tt.mul(&two);
        n += 1;
        if n > cap {
            return None;
        }
    }
    let scale = powi(&two, n - 1, prec);
    let (xs, ys) = (x.mul(&scale), y.mul(&scale));
    let one = c(1, 1);
    Some(
        if xs.le(&half).is_false() || xs.sub(&half).sign() == Some(Ordering::Equal) {
            (n, 0, (xs.mul(&two).sub(&one), ys.mul(&two)), 1)
        } else if ys.lt(&half).is_false() {
            (n, 2, (xs.mul(&two), ys.mul(&two).sub(&one)), 1)
        } else {
            (n, 1, (one.sub(&xs.mul(&two)), one.sub(&ys.mul(&two))), -1)
        },
    )
}

/// [`extraordinary_jet`], or with `authors_jordan` the authors' evaluator's Jordan-block
/// power for valence 3 ([`EigenStructure::sub_net_as`], defect D3).
pub fn extraordinary_jet_as<S: Scalar>(
    es: &EigenStructure<S>,
    basis: &[[S; 15]; 12],
    net: &[[S; 3]],
    x: &S,
    y: &S,
    derivs: bool,
    authors_jordan: bool,
) -> PatchJet<S> {
    let prec = es.prec;
    let c = |p: i64, q: i64| S::from_ratio(p, q, prec);
    let cap = depth_cap(x.precision_bits());
    let at_vertex = || PatchJet {
        p: vertex_limit(es, net),
        d: None,
        level: cap as u32,
    };
    let Some((n, k, s, sign)) = stam_tile(x, y, cap, prec) else {
        return at_vertex();
    };
    let two = c(2, 1);
    let scale = powi(&two, n - 1, prec);
    // Translate the net by its limit point ℓ (the eigenvalue-1 component): A and B_k fix
    // constants, so B_k Aᵐ (C₀ − ℓ) + ℓ is the same net, but its entries now shrink like
    // λ₁ᵐ and so do their rounding errors — the derivatives, which carry 2ⁿ, keep their
    // relative accuracy close to the vertex. W⁻¹·(1,…,1) = (1, 1, 1, −1, −1).
    let (mut cin, mut cout) = es.project(net);
    let l = cin[0].clone();
    cin[0] = [c(0, 1), c(0, 1), c(0, 1)];
    for (a, ca) in cout.iter_mut().enumerate() {
        for d in 0..3 {
            ca[d] = if a < 3 {
                ca[d].sub(&l[d])
            } else {
                ca[d].add(&l[d])
            };
        }
    }
    let q = es.sub_net_as(k, n - 1, &cin, &cout, authors_jordan);
    let mut jet = regular_jet(basis, &q, &s.0, &s.1, derivs, prec);
    for (pd, ld) in jet.p.iter_mut().zip(&l) {
        *pd = pd.add(ld);
    }
    jet.level = n as u32;
    if let Some(d) = jet.d.as_mut() {
        let f1 = scale.mul(&two).mul(&S::from_i64(sign, prec));
        let f2 = f1.sqr();
        for (i, di) in d.iter_mut().enumerate() {
            *di = scale3(di, if i < 2 { &f1 } else { &f2 });
        }
    }
    jet
}

/// The weights of the 12 net points at (x, y) of a regular patch (the box-spline basis).
pub fn regular_weights_f64(basis: &[[f64; 15]; 12], x: f64, y: f64) -> [f64; 12] {
    let (x2, y2) = (x * x, y * y);
    let (x3, y3) = (x2 * x, y2 * y);
    let m = [
        1.0,
        x,
        y,
        x2,
        x * y,
        y2,
        x3,
        x2 * y,
        x * y2,
        y3,
        x2 * x2,
        x3 * y,
        x2 * y2,
        x * y3,
        y2 * y2,
    ];
    std::array::from_fn(|k| {
        let mut phi = 0.0;
        for (c, v) in basis[k].iter().zip(&m) {
            phi += c * v;
        }
        phi
    })
}

/// [`regular_jet`] for f64 positions, without allocation (the hot path of the fit).
pub fn regular_point_f64(
    basis: &[[f64; 15]; 12],
    net: &[[f64; 3]; 12],
    x: f64,
    y: f64,
) -> [f64; 3] {
    let phi = regular_weights_f64(basis, x, y);
    let mut p = [0.0; 3];
    for (f, q) in phi.iter().zip(net) {
        p[0] += f * q[0];
        p[1] += f * q[1];
        p[2] += f * q[2];
    }
    p
}
