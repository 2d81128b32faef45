//! One-sided calculus on a shared edge δ of a planar complex (Mello–Velho Sec. 5): the chart
//! frame of a triangle (plane gradients and plane Jacobians from chart derivatives), the
//! restriction of a chart polynomial to an edge as a univariate polynomial, and the few exact
//! univariate operations the C¹ checks need (sum, product, remainder).

use super::complex::PlanarComplex;
use crate::sdiff::common::poly2::Poly2;
use crate::sdiff::common::rational::{q, Q};
use num_traits::Zero;

/// The affine chart of triangle f: P(s, t) = v_0 + s (v_1 − v_0) + t (v_2 − v_0), i.e. the
/// matrix J = \[\[x_s, x_t\], \[y_s, y_t\]\] and det J (> 0 on a validated complex).
#[derive(Debug, Clone)]
pub(crate) struct Frame {
    /// J.
    pub j: [[Q; 2]; 2],
    /// det J.
    pub det: Q,
}

impl Frame {
    /// The frame of triangle `f`.
    pub(crate) fn of(k: &PlanarComplex, f: usize) -> Frame {
        let t = k.triangles[f].map(|v| &k.points[v as usize]);
        let j = [
            [&t[1][0] - &t[0][0], &t[2][0] - &t[0][0]],
            [&t[1][1] - &t[0][1], &t[2][1] - &t[0][1]],
        ];
        let det = &j[0][0] * &j[1][1] - &j[0][1] * &j[1][0];
        Frame { j, det }
    }
    /// The plane gradient ∇F = \[F_s, F_t\]·J⁻¹ of a function with chart derivatives (F_s, F_t).
    pub(crate) fn plane_gradient(&self, fs: &Q, ft: &Q) -> [Q; 2] {
        let j = &self.j;
        [
            (fs * &j[1][1] - ft * &j[1][0]) / &self.det,
            (ft * &j[0][0] - fs * &j[0][1]) / &self.det,
        ]
    }
    /// The plane Jacobian J·A·J⁻¹ of a map with chart Jacobian A (chart to chart).
    pub(crate) fn plane_jacobian(&self, a: &[[Q; 2]; 2]) -> [[Q; 2]; 2] {
        let j = &self.j;
        let inv = [
            [&j[1][1] / &self.det, -(&j[0][1]) / &self.det],
            [-(&j[1][0]) / &self.det, &j[0][0] / &self.det],
        ];
        let mul = |x: &[[Q; 2]; 2], y: &[[Q; 2]; 2]| -> [[Q; 2]; 2] {
            let e = |r: usize, c: usize| &x[r][0] * &y[0][c] + &x[r][1] * &y[1][c];
            [[e(0, 0), e(0, 1)], [e(1, 0), e(1, 1)]]
        };
        mul(&mul(j, a), &inv)
    }
}

/// The chart corner of local vertex `i` (0, 1, 2) of the reference triangle.
pub fn corner(i: usize) -> [Q; 2] {
    match i {
        0 => [q(0), q(0)],
        1 => [q(1), q(0)],
        _ => [q(0), q(1)],
    }
}

/// The chart point (s, t) at parameter u on the edge from local vertex `la` to `lb`.
pub(crate) fn chart_point(la: usize, lb: usize, u: &Q) -> [Q; 2] {
    let (a, b) = (corner(la), corner(lb));
    [&a[0] + u * (&b[0] - &a[0]), &a[1] + u * (&b[1] - &a[1])]
}

/// Local position of global vertex `v` in triangle `f` (it must be one of its vertices).
pub fn local(k: &PlanarComplex, f: usize, v: u32) -> Option<usize> {
    k.triangles[f].iter().position(|&x| x == v)
}

/// A univariate polynomial Σ c\[i\] u^i over ℚ.
pub(crate) type UPoly = Vec<Q>;

/// p restricted to the edge from local vertex `la` to `lb`, as a polynomial in the edge
/// parameter u (u = 0 at `la`, u = 1 at `lb`).
pub(crate) fn restrict(p: &Poly2, la: usize, lb: usize) -> UPoly {
    // The degenerate affine map (s, t) ↦ a + s (b − a) + t·0 leaves a polynomial in s only.
    let r = p.compose_affine(&[corner(la), corner(lb), corner(la)]);
    trim((0..=r.deg()).map(|a| r.get(a, 0)).collect())
}

/// Drops trailing zero coefficients.
pub fn trim(mut p: UPoly) -> UPoly {
    while p.last().is_some_and(|c| c.is_zero()) {
        p.pop();
    }
    p
}

/// p + k·r.
pub(crate) fn u_axpy(p: &UPoly, k: &Q, r: &UPoly) -> UPoly {
    let n = p.len().max(r.len());
    trim(
        (0..n)
            .map(|i| {
                let a = p.get(i).cloned().unwrap_or_else(Q::zero);
                match r.get(i) {
                    Some(b) => a + k * b,
                    None => a,
                }
            })
            .collect(),
    )
}

/// p·r.
pub(crate) fn u_mul(p: &UPoly, r: &UPoly) -> UPoly {
    if p.is_empty() || r.is_empty() {
        return Vec::new();
    }
    let mut out = vec![Q::zero(); p.len() + r.len() - 1];
    for (i, a) in p.iter().enumerate() {
        for (j, b) in r.iter().enumerate() {
            out[i + j] += a * b;
        }
    }
    trim(out)
}

/// The remainder of p modulo d (d ≠ 0), exact.
pub(crate) fn u_rem(p: &UPoly, d: &UPoly) -> UPoly {
    let d = trim(d.clone());
    let mut r = trim(p.clone());
    let Some(lead) = d.last().cloned() else {
        return r;
    };
    while r.len() >= d.len() && !r.is_empty() {
        let k = r[r.len() - 1].clone() / &lead;
        let shift = r.len() - d.len();
        for (i, c) in d.iter().enumerate() {
            r[shift + i] -= &k * c;
        }
        r = trim(r);
    }
    r
}

/// p(u), exact.
pub(crate) fn u_eval(p: &UPoly, u: &Q) -> Q {
    p.iter().rev().fold(Q::zero(), |acc, c| acc * u + c)
}
