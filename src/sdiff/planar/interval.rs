//! The second, independent route to det DX > 0: interval branch-and-bound in f64 with outward
//! rounding (`numeric::interval`), evaluated from the control points through the hodograph
//! ∂x/∂s = n Σ_{|J|=n−1} (b_{J+e1} − b_{J+e0}) B_J (and likewise for t), not from the exact
//! polynomials of [`crate::sdiff::common::positivity`]. It can certify, or give up; it never refutes (a
//! refutation needs an exact value).

use super::maps::{Family, SimplexMap};
use crate::numeric::interval::Interval as I;
use crate::sdiff::common::interval::{enclose, IntervalVerdict};
use crate::sdiff::common::poly2::multi_indices;
use crate::sdiff::common::rational::multinomial;
use num_traits::ToPrimitive;

fn pt(x: f64) -> I {
    I::try_from((x, x)).unwrap_or(I::ENTIRE)
}

fn pow(x: I, k: usize) -> I {
    (0..k).fold(pt(1.0), |a, _| a * x)
}

/// B_J over the box (w as intervals).
fn basis(j: [usize; 3], w: &[I; 3]) -> I {
    let n = j[0] + j[1] + j[2];
    let c = multinomial(n, &j).to_f64().unwrap_or(f64::INFINITY);
    pt(c) * pow(w[0], j[0]) * pow(w[1], j[1]) * pow(w[2], j[2])
}

/// Interval enclosure of det DX over the box s ∈ `s`, t ∈ `t` (w_0 = 1 − s − t ∩ [0, 1]).
pub(crate) fn det_enclosure(m: &SimplexMap, s: I, t: I) -> I {
    let w0 = (pt(1.0) - s - t).intersection(I::try_from((0.0, 1.0)).unwrap_or(I::ENTIRE));
    let w = [w0, s, t];
    // value and (s, t)-derivatives of the numerators N_1, N_2 and of D.
    let (mut v, mut ds, mut dt) = ([pt(0.0); 3], [pt(0.0); 3], [pt(0.0); 3]);
    match m.family {
        Family::Monotonic => {
            for c in 0..3 {
                let g = &m.g[c];
                let (gv, gd) = poly1_with_derivative(g, w[c]);
                // ∂w_0/∂s = ∂w_0/∂t = −1; ∂w_1/∂s = 1; ∂w_2/∂t = 1.
                let (a, b) = match c {
                    0 => (pt(-1.0), pt(-1.0)),
                    1 => (pt(1.0), pt(0.0)),
                    _ => (pt(0.0), pt(1.0)),
                };
                v[c] = gv;
                ds[c] = gd * a;
                dt[c] = gd * b;
            }
            let (dv, dds, ddt) = (
                v[0] + v[1] + v[2],
                ds[0] + ds[1] + ds[2],
                dt[0] + dt[1] + dt[2],
            );
            quotient_det([v[1], v[2], dv], [ds[1], ds[2], dds], [dt[1], dt[2], ddt])
        }
        Family::Polynomial | Family::Rational => {
            let n = m.degree;
            let idx = multi_indices(n);
            let wq: Vec<I> = m.weights.iter().map(enclose).collect();
            // weighted points (q b_1, q b_2, q) per multi-index.
            let pts: Vec<[I; 3]> = idx
                .iter()
                .enumerate()
                .map(|(k, _)| {
                    let b = &m.control[k];
                    [wq[k] * enclose(&b[1]), wq[k] * enclose(&b[2]), wq[k]]
                })
                .collect();
            for (k, i) in idx.iter().enumerate() {
                let bi = basis(*i, &w);
                for c in 0..3 {
                    v[c] = v[c] + pts[k][c] * bi;
                }
            }
            if n > 0 {
                let pos = |i: [usize; 3]| crate::sdiff::common::poly2::index_of(n, i);
                for j in multi_indices(n - 1) {
                    let bj = basis(j, &w) * pt(n as f64);
                    let e0 = pos([j[0] + 1, j[1], j[2]]);
                    let e1 = pos([j[0], j[1] + 1, j[2]]);
                    let e2 = pos([j[0], j[1], j[2] + 1]);
                    for c in 0..3 {
                        ds[c] = ds[c] + (pts[e1][c] - pts[e0][c]) * bj;
                        dt[c] = dt[c] + (pts[e2][c] - pts[e0][c]) * bj;
                    }
                }
            }
            if m.family == Family::Polynomial {
                return ds[0] * dt[1] - dt[0] * ds[1];
            }
            quotient_det(v, ds, dt)
        }
    }
}

/// det of the Jacobian of (N1/D, N2/D) from values and derivatives [N1, N2, D].
fn quotient_det(v: [I; 3], ds: [I; 3], dt: [I; 3]) -> I {
    let d2 = v[2] * v[2];
    let j = |k: usize, dd: &[I; 3]| (dd[k] * v[2] - v[k] * dd[2]) / d2;
    j(0, &ds) * j(1, &dt) - j(0, &dt) * j(1, &ds)
}

fn poly1_with_derivative(g: &crate::sdiff::common::poly1::Poly1, x: I) -> (I, I) {
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

/// Branch-and-bound over boxes of [0, 1]² meeting the reference triangle, up to `max_boxes`.
pub fn certify_det(m: &SimplexMap, max_boxes: usize) -> IntervalVerdict {
    let mut stack = vec![(0.0f64, 1.0f64, 0.0f64, 1.0f64)];
    let mut boxes = 0usize;
    let mut lower = f64::INFINITY;
    while let Some((s0, s1, t0, t1)) = stack.pop() {
        if s0 + t0 > 1.0 {
            continue; // the box misses the closed triangle (corner sums are exact dyadics)
        }
        boxes += 1;
        if boxes > max_boxes {
            return IntervalVerdict::Unknown { boxes };
        }
        let d = det_enclosure(
            m,
            I::try_from((s0, s1)).unwrap_or(I::ENTIRE),
            I::try_from((t0, t1)).unwrap_or(I::ENTIRE),
        );
        if !d.is_empty() && d.inf() > 0.0 {
            lower = lower.min(d.inf());
            continue;
        }
        let (sm, tm) = ((s0 + s1) / 2.0, (t0 + t1) / 2.0);
        stack.push((s0, sm, t0, tm));
        stack.push((sm, s1, t0, tm));
        stack.push((s0, sm, tm, t1));
        stack.push((sm, s1, tm, t1));
    }
    IntervalVerdict::Certified {
        boxes,
        lower_bound: lower,
    }
}
