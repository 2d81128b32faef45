//! The second, independent route to det DX > 0 on a closed tetrahedron (SPEC
//! `SD-L101(interval,3-D)`): interval branch-and-bound in f64 with outward rounding
//! (`numeric::interval`) over boxes of the chart (s, t, r) = (w_1, w_2, w_3), evaluated
//! from the parameters, not from the exact polynomials of `tet`:
//!
//! * Eqs. (10), (11): values Σ q_I b_I B_I and the hodograph
//!   ∂/∂s = n Σ_{|J|=n−1} (q b)_{J+e_1} − (q b)_{J+e_0}) B_J (likewise t, r) of the weighted
//!   control points (q_I b_I, q_I);
//! * Eq. (9): g_i(w_i) and g_i′(w_i)·∂w_i.
//!
//! With x_k = N_k / D, det DX = det M / D⁶, M_kj = ∂_j N_k · D − N_k · ∂_j D = (D A − N ∇Dᵀ)_kj,
//! A = ∂N, and det M = D²·(D det A − ∇Dᵀ adj(A) N) (matrix determinant lemma); a box is
//! certified when D > 0 and that last factor is > 0 on it (for Eq. (10), D = 1: det A > 0). It
//! certifies or gives up; it never refutes (a refutation needs an exact value,
//! `tet::decide_tet`).

use super::maps::multi_indices4;
use super::params::TetMap;
use crate::numeric::interval::Interval as I;
use crate::sdiff::common::interval::{enclose, IntervalVerdict};
use crate::sdiff::common::params::FamilySpec;
use crate::sdiff::common::poly1::Poly1;
use crate::sdiff::common::rational::multinomial;
use num_traits::ToPrimitive;
use std::collections::HashMap;

fn pt(x: f64) -> I {
    I::try_from((x, x)).unwrap_or(I::ENTIRE)
}

fn pow(x: I, k: usize) -> I {
    (0..k).fold(pt(1.0), |a, _| a * x)
}

/// B_J over the box (w as intervals).
fn basis(j: [usize; 4], w: &[I; 4]) -> I {
    let n: usize = j.iter().sum();
    let c = multinomial(n, &j).to_f64().unwrap_or(f64::INFINITY);
    (0..4).fold(pt(c), |acc, k| acc * pow(w[k], j[k]))
}

fn poly1_with_derivative(g: &Poly1, x: I) -> (I, I) {
    let mut v = pt(0.0);
    let mut d = pt(0.0);
    for (k, c) in g.0.iter().enumerate() {
        let ck = enclose(c);
        v = v + ck * pow(x, k);
        if k > 0 {
            d = d + ck * pt(k as f64) * pow(x, k - 1);
        }
    }
    (v, d)
}

fn det3(m: &[[I; 3]; 3]) -> I {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

/// Enclosures of (D, D det A − ∇Dᵀ adj(A) N) over the box `b` = (s, t, r) of the chart.
pub(crate) fn det_enclosure(m: &TetMap, b: [I; 3]) -> (I, I) {
    let w0 =
        (pt(1.0) - b[0] - b[1] - b[2]).intersection(I::try_from((0.0, 1.0)).unwrap_or(I::ENTIRE));
    let w = [w0, b[0], b[1], b[2]];
    // v[c], d[c][j]: value and ∂_j of N_1, N_2, N_3 (c = 0..2) and D (c = 3).
    let mut v = [pt(0.0); 4];
    let mut d = [[pt(0.0); 3]; 4];
    match m.family {
        FamilySpec::Monotonic => {
            let mut gv = [pt(0.0); 4];
            let mut gd = [pt(0.0); 4];
            for i in 0..4 {
                (gv[i], gd[i]) = poly1_with_derivative(&m.g[i], w[i]);
            }
            // ∂w_0/∂(s, t, r) = −1; ∂w_i/∂x_j = δ_ij for i ≥ 1.
            for c in 0..3 {
                v[c] = gv[c + 1];
                d[c][c] = gd[c + 1];
            }
            v[3] = gv[0] + gv[1] + gv[2] + gv[3];
            for j in 0..3 {
                d[3][j] = gd[j + 1] - gd[0];
            }
        }
        FamilySpec::Polynomial | FamilySpec::Rational => {
            let n = m.degree;
            let idx = multi_indices4(n);
            let pos: HashMap<[usize; 4], usize> =
                idx.iter().enumerate().map(|(k, i)| (*i, k)).collect();
            let wq: Vec<I> = m.weights.iter().map(enclose).collect();
            let pts: Vec<[I; 4]> = (0..idx.len())
                .map(|k| {
                    let b = &m.control[k];
                    [
                        wq[k] * enclose(&b[1]),
                        wq[k] * enclose(&b[2]),
                        wq[k] * enclose(&b[3]),
                        wq[k],
                    ]
                })
                .collect();
            for (k, i) in idx.iter().enumerate() {
                let bi = basis(*i, &w);
                for c in 0..4 {
                    v[c] = v[c] + pts[k][c] * bi;
                }
            }
            for j in multi_indices4(n.saturating_sub(1))
                .into_iter()
                .filter(|_| n > 0)
            {
                let bj = basis(j, &w) * pt(n as f64);
                let up = |e: usize| {
                    let mut i = j;
                    i[e] += 1;
                    pos.get(&i).copied().unwrap_or(0)
                };
                let e0 = up(0);
                let es: [usize; 3] = std::array::from_fn(|dir| up(dir + 1));
                for (c, dc) in d.iter_mut().enumerate() {
                    for (dir, x) in dc.iter_mut().enumerate() {
                        *x = *x + (pts[es[dir]][c] - pts[e0][c]) * bj;
                    }
                }
            }
            if m.family == FamilySpec::Polynomial {
                let a = [d[0], d[1], d[2]];
                return (pt(1.0), det3(&a));
            }
        }
    }
    // Matrix determinant lemma, as in the exact `tet::jacobian_numerator`: det M = D²·J with
    // J = D·det A − ∇Dᵀ adj(A) N (A = ∂N): fewer products than det M, so less overestimation.
    let a = [d[0], d[1], d[2]];
    let cof = |r: usize, c: usize| {
        let (r0, r1) = ([1, 0, 0][r], [2, 2, 1][r]);
        let (c0, c1) = ([1, 0, 0][c], [2, 2, 1][c]);
        let minor = a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0];
        if (r + c) % 2 == 0 {
            minor
        } else {
            -minor
        }
    };
    let mut lemma = pt(0.0);
    for (i, gi) in d[3].iter().enumerate() {
        for (j, nj) in v.iter().take(3).enumerate() {
            // ∇D_i · adj(A)_ij · N_j, adj(A)_ij = C_ji.
            lemma = lemma + *gi * cof(j, i) * *nj;
        }
    }
    (v[3], v[3] * det3(&a) - lemma)
}

/// Branch-and-bound over boxes of \[0, 1\]³ meeting the closed reference tetrahedron (split
/// into 8), up to `max_boxes`.
pub fn certify_det_tet(m: &TetMap, max_boxes: usize) -> IntervalVerdict {
    if m.family != FamilySpec::Monotonic && m.degree == 0 {
        return IntervalVerdict::Unknown { boxes: 0 };
    }
    let mut stack = vec![([0.0f64; 3], [1.0f64; 3])];
    let mut boxes = 0usize;
    let mut lower = f64::INFINITY;
    while let Some((lo, hi)) = stack.pop() {
        // Corner sums of dyadic boxes are exact: the box misses the closed tetrahedron.
        if lo[0] + lo[1] + lo[2] > 1.0 {
            continue;
        }
        boxes += 1;
        if boxes > max_boxes {
            return IntervalVerdict::Unknown { boxes };
        }
        let b: [I; 3] = std::array::from_fn(|k| I::try_from((lo[k], hi[k])).unwrap_or(I::ENTIRE));
        let (den, det) = det_enclosure(m, b);
        if !den.is_empty() && den.inf() > 0.0 && !det.is_empty() && det.inf() > 0.0 {
            lower = lower.min(det.inf());
            continue;
        }
        let mid: [f64; 3] = std::array::from_fn(|k| 0.5 * (lo[k] + hi[k]));
        for octant in 0..8 {
            let mut l = lo;
            let mut h = hi;
            for k in 0..3 {
                if octant >> k & 1 == 0 {
                    h[k] = mid[k];
                } else {
                    l[k] = mid[k];
                }
            }
            stack.push((l, h));
        }
    }
    IntervalVerdict::Certified {
        boxes,
        lower_bound: lower,
    }
}

#[cfg(test)]
mod tests {
    use super::{det_enclosure, I};
    use crate::sdiff::common::poly1::Poly1;
    use crate::sdiff::common::rational::q;
    use crate::sdiff::tet::params::TetMap;

    /// D = Σ g_i(w^i) of Eq. (9): with constant g_i = i + 1, D = 10 at every point, so the
    /// enclosure over a point box holds 10 and nothing as far as 11.
    #[test]
    fn det_enclosure_of_the_monotonic_family_encloses_the_sum_of_the_g() {
        let m = TetMap::monotonic(std::array::from_fn(|i| Poly1(vec![q(i as i64 + 1)])));
        let p = I::try_from((0.25, 0.25)).expect("a point");
        let (d, _) = det_enclosure(&m, [p, p, p]);
        assert!(d.inf() <= 10.0 && 10.0 <= d.sup(), "{d:?}");
        assert!(d.sup() < 11.0, "{d:?}");
    }

    /// The second enclosure, D·det A − ∇Dᵀ adj(A) N, over a point box holds the exact
    /// `jacobian_numerator` there, for g_i with distinct slopes (so every ∂_j D counts).
    #[test]
    fn det_enclosure_of_the_monotonic_family_encloses_the_exact_jacobian_numerator() {
        use crate::sdiff::common::rational::{qr, to_f64};
        use crate::sdiff::tet::poly::{jacobian_numerator, monotonic};
        let g: [Poly1; 4] =
            std::array::from_fn(|i| Poly1(vec![q(i as i64 + 1), q(2 * i as i64 + 3)]));
        let (n, d) = monotonic(&g);
        let x = [qr(1, 4), qr(1, 5), qr(1, 3)];
        let exact = to_f64(&jacobian_numerator(&n, &d).eval(&x));
        let m = TetMap::monotonic(g);
        let b = [0.25, 0.2, 1.0 / 3.0].map(|v| I::try_from((v, v)).expect("a point"));
        let (_, j) = det_enclosure(&m, b);
        let tol = 1e-9 * exact.abs().max(1.0);
        assert!(
            j.inf() - tol <= exact && exact <= j.sup() + tol,
            "{j:?} against {exact}"
        );
        assert!(j.sup() - j.inf() <= tol, "{j:?}");
    }
}
