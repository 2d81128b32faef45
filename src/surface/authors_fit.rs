//! Sec. 5.2 as the authors' implementation computes it (the `authors-code` profile): the
//! sample grid, which grid points are kept, and the least-squares fit by the normal equations
//! solved with Crout LU. Written from a reading of `siqueirafm/PPS` (MIT; `pps.hpp`
//! `build_one_shape_function` / `find_triangle` / `get_barycentric_coordinates`, `bezier.cpp`,
//! `ludcmp.cpp`); no code of it is copied. Every floating-point operation that decides a
//! kept point or enters AᵀA is done in their order, so that the ill-conditioned normal
//! equations (κ(AᵀA) = κ(A)²) see the same rounding: the fitted control points then agree
//! with theirs far below the ≈ κ(A)²·ε by which the normal-equations solution differs from
//! the least-squares one (the `paper` profile's SVD).
//!
//! * Grid: N = 2l intervals on [−R, R], R = cos(π/m_v), spacing d = 2R/N; the i-th
//!   coordinate is −R + (d + d + … + d) (an accumulated sum, not −R + i·d); rows run over y,
//!   then x.
//! * A grid point is kept when, for some i = 0, 1, … (in that order), its barycentric
//!   coordinates w.r.t. [0, v′_i, v′_{i+1}] (v′_i = (cos iα, sin iα), α = 2·(π/m)), snapped to 0
//!   or 1 when within 10⁻¹⁴, all lie in [0, 1]; that i is its sector.
//! * A = [B_j^l(x̂) B_k^l(ŷ)] with x̂ = (x + R)/(2R), Bernstein values by the triangular
//!   recurrence, unknowns ordered k(l+1) + j (y-index major); AᵀA and Aᵀb summed over the rows
//!   in grid order; AᵀA factored once per degree.

use super::fit::Sample;
use super::target::TargetSurface;
use crate::mesh::{SimplicialSurface, VertexId};
use std::f64::consts::PI;

/// Snap a barycentric coordinate within 10⁻¹⁴ of 0 or 1 (their `get_barycentric_coordinates`).
fn snap(t: f64) -> f64 {
    if t.abs() < 1e-14 {
        0.0
    } else if (1.0 - t).abs() < 1e-14 {
        1.0
    } else {
        t
    }
}

/// Barycentric coordinates of p w.r.t. [0, a, b], in the operation order of their code (the
/// terms with the zero corner vanish exactly).
fn bary_origin(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> [f64; 3] {
    let det = b[0] * a[1] - a[0] * b[1];
    let u = ((((b[0] * a[1]) - (p[0] * a[1])) - (a[0] * b[1])) + (p[0] * b[1])) + (a[0] * p[1])
        - (b[0] * p[1]);
    let u = snap(u / det);
    let v = snap((-(p[0] * b[1]) + (b[0] * p[1])) / det);
    let w = snap((1.0 - u) - v);
    [u, v, w]
}

/// The kept grid points of degree m, in their row order, with sector and barycentric
/// coordinates w.r.t. (v′, v′_i, v′_{i+1}).
pub(crate) fn authors_samples(m: u32, l: usize) -> Vec<Sample> {
    let n = 2 * l;
    let r = (PI / m as f64).cos();
    let d = (2.0 * r) / n as f64;
    let alpha = 2.0 * (PI / m as f64);
    let corner = |i: u32| {
        let a = i as f64 * alpha;
        [a.cos(), a.sin()]
    };
    let mut out = Vec::new();
    let mut dy = 0.0;
    for _ in 0..=n {
        let y = -r + dy;
        let mut dx = 0.0;
        for _ in 0..=n {
            let x = -r + dx;
            for i in 0..m {
                let b = bary_origin(corner(i), corner(i + 1), [x, y]);
                if b.iter().all(|t| (0.0..=1.0).contains(t)) {
                    out.push(Sample {
                        q: [x, y],
                        sector: i,
                        bary: b,
                    });
                    break;
                }
            }
            dx += d;
        }
        dy += d;
    }
    out
}

/// B_0^l(t) … B_l^l(t) by the triangular recurrence B_k^j = (1−t)B_k^{j−1} + tB_{k−1}^{j−1}.
fn bernstein_all(l: usize, t: f64, out: &mut [f64]) {
    out[0] = 1.0;
    let t1 = 1.0 - t;
    for j in 1..=l {
        let mut carry = 0.0;
        for o in out.iter_mut().take(j) {
            let prev = *o;
            *o = carry + t1 * prev;
            carry = t * prev;
        }
        out[j] = carry;
    }
}

/// A Crout LU factorization with implicit (row-scaled) partial pivoting of a square matrix,
/// row-major; `perm[j]` is the row swapped with j at step j.
#[derive(Debug, Clone)]
struct CroutLu {
    n: usize,
    a: Vec<f64>,
    perm: Vec<usize>,
}

impl CroutLu {
    /// Factor; `None` if a row is zero (their code stops with an error there).
    fn new(mut a: Vec<f64>, n: usize) -> Option<CroutLu> {
        let mut scale = vec![0.0; n];
        for i in 0..n {
            let big =
                a[i * n..(i + 1) * n]
                    .iter()
                    .fold(0.0f64, |b, x| if x.abs() > b { x.abs() } else { b });
            if big == 0.0 {
                return None;
            }
            scale[i] = 1.0 / big;
        }
        let mut perm = vec![0; n];
        for j in 0..n {
            for i in 0..j {
                let mut s = a[i * n + j];
                for k in 0..i {
                    s -= a[i * n + k] * a[k * n + j];
                }
                a[i * n + j] = s;
            }
            let mut big = 0.0;
            let mut imax = j;
            for i in j..n {
                let mut s = a[i * n + j];
                for k in 0..j {
                    s -= a[i * n + k] * a[k * n + j];
                }
                a[i * n + j] = s;
                let d = scale[i] * s.abs();
                if d >= big {
                    big = d;
                    imax = i;
                }
            }
            if imax != j {
                for k in 0..n {
                    a.swap(imax * n + k, j * n + k);
                }
                scale[imax] = scale[j];
            }
            perm[j] = imax;
            if a[j * n + j] == 0.0 {
                // Their choice for an exactly singular pivot (kept to compute what they do).
                a[j * n + j] = 1e-20;
            }
            if j + 1 != n {
                let inv = 1.0 / a[j * n + j];
                for i in j + 1..n {
                    a[i * n + j] *= inv;
                }
            }
        }
        Some(CroutLu { n, a, perm })
    }

    /// Solve in place (forward substitution skipping the leading zeros of b, then back).
    fn solve(&self, b: &mut [f64]) {
        let n = self.n;
        let mut first: Option<usize> = None;
        for i in 0..n {
            let ip = self.perm[i];
            let mut s = b[ip];
            b[ip] = b[i];
            if let Some(f) = first {
                for (j, bj) in b.iter().enumerate().take(i).skip(f) {
                    s -= self.a[i * n + j] * bj;
                }
            } else if s != 0.0 {
                first = Some(i);
            }
            b[i] = s;
        }
        for i in (0..n).rev() {
            let mut s = b[i];
            for (j, bj) in b.iter().enumerate().take(n).skip(i + 1) {
                s -= self.a[i * n + j] * bj;
            }
            b[i] = s / self.a[i * n + i];
        }
    }
}

/// The authors' least-squares problem for one degree: samples, A and the LU of AᵀA.
#[derive(Debug, Clone)]
pub(crate) struct AuthorsDegreeFit {
    /// l, the bi-degree.
    pub l: usize,
    /// The kept grid points, in row order.
    pub samples: Vec<Sample>,
    /// A, rows × (l+1)², unknowns in their order k(l+1) + j.
    a: Vec<f64>,
    lu: Option<CroutLu>,
}

impl AuthorsDegreeFit {
    /// Build A and factor AᵀA for degree m with bi-degree l.
    pub(crate) fn new(m: u32, l: usize) -> AuthorsDegreeFit {
        let samples = authors_samples(m, l);
        let r = (PI / m as f64).cos();
        let (rx, sx) = (-r, r);
        let l1 = l + 1;
        let ncp = l1 * l1;
        let mut a = vec![0.0; samples.len() * ncp];
        let (mut bu, mut bv) = (vec![0.0; l1], vec![0.0; l1]);
        for (row, s) in a.chunks_mut(ncp).zip(&samples) {
            bernstein_all(l, (s.q[0] - rx) / (sx - rx), &mut bu);
            bernstein_all(l, (s.q[1] - rx) / (sx - rx), &mut bv);
            for k in 0..l1 {
                for j in 0..l1 {
                    row[k * l1 + j] = bu[j] * bv[k];
                }
            }
        }
        let mut ata = vec![0.0; ncp * ncp];
        for i in 0..ncp {
            for k in 0..ncp {
                let mut s = 0.0;
                for row in a.chunks(ncp) {
                    s += row[i] * row[k];
                }
                ata[i * ncp + k] = s;
            }
        }
        let lu = CroutLu::new(ata, ncp);
        AuthorsDegreeFit { l, samples, a, lu }
    }

    /// Control points from the S′ values at the samples (in sample order), in our storage
    /// order j(l+1) + k; `None` if AᵀA was not factored or `data` has the wrong length.
    pub(crate) fn solve(&self, data: &[[f64; 3]]) -> Option<Vec<[f64; 3]>> {
        let lu = self.lu.as_ref()?;
        if data.len() != self.samples.len() {
            return None;
        }
        let l1 = self.l + 1;
        let ncp = l1 * l1;
        let mut out = vec![[0.0; 3]; ncp];
        let mut y = vec![0.0; ncp];
        for d in 0..3 {
            for (i, yi) in y.iter_mut().enumerate() {
                let mut s = 0.0;
                for (row, p) in self.a.chunks(ncp).zip(data) {
                    s += row[i] * p[d];
                }
                *yi = s;
            }
            lu.solve(&mut y);
            for k in 0..l1 {
                for j in 0..l1 {
                    out[j * l1 + k][d] = y[k * l1 + j];
                }
            }
        }
        Some(out)
    }
}

/// Fit ψ_v as the authors' code does: S′ at the kept samples (sector i of their numbering is
/// our label (i + `offset`) mod m_v), then the normal equations. `out` gets the control
/// points in our storage order; returns false (out untouched) when their fit is undefined
/// (AᵀA not factored).
pub(crate) fn fit_vertex_authors(
    k: &SimplicialSurface,
    target: &dyn TargetSurface,
    v: VertexId,
    offset: u32,
    fit: &AuthorsDegreeFit,
    out: &mut [[f64; 3]],
) -> bool {
    let outgoing = k.outgoing(v);
    let m = outgoing.len();
    if m == 0 {
        return false;
    }
    let data: Vec<[f64; 3]> = fit
        .samples
        .iter()
        .map(|s| {
            let i = (s.sector as usize + offset as usize) % m;
            let h = outgoing[i];
            let a = k.dest(h);
            let b = k.dest(outgoing[(i + 1) % m]);
            target.eval(k.face_of(h), [v, a, b], s.bary)
        })
        .collect();
    match fit.solve(&data) {
        Some(cp) if cp.len() == out.len() => {
            out.copy_from_slice(&cp);
            true
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The normal-equations fit reproduces a polynomial of bi-degree ≤ l (exact data) to
    /// rounding, and its samples cover each sector.
    #[test]
    fn authors_fit_reproduces_polynomials() {
        for m in [3u32, 4, 5, 6, 7, 9] {
            let l = (m as usize + 1).min(7);
            let f = AuthorsDegreeFit::new(m, l);
            assert!(f.lu.is_some(), "m = {m}");
            let sectors: std::collections::BTreeSet<u32> =
                f.samples.iter().map(|s| s.sector).collect();
            assert_eq!(sectors.len(), m as usize, "m = {m}");
            let poly = |x: f64, y: f64| [x * x * y, 1.0 + x - 2.0 * y * y * y, x * y];
            let data: Vec<[f64; 3]> = f.samples.iter().map(|s| poly(s.q[0], s.q[1])).collect();
            let cp = f.solve(&data).expect("solved");
            let half = (PI / m as f64).cos();
            for s in f.samples.iter().step_by(7) {
                let v = super::super::bezier::eval_patch_f64(&cp, l, half, s.q[0], s.q[1]);
                let e = poly(s.q[0], s.q[1]);
                for d in 0..3 {
                    assert!((v[d] - e[d]).abs() < 1e-8, "m {m}: {v:?} vs {e:?}");
                }
            }
        }
    }

    /// Planted fault: wrong data length and a zero matrix are refused, not solved.
    #[test]
    fn authors_fit_refuses_bad_input() {
        let f = AuthorsDegreeFit::new(5, 6);
        assert!(f.solve(&[[0.0; 3]; 3]).is_none());
        assert!(CroutLu::new(vec![0.0; 4], 2).is_none());
    }

    /// Crout LU solves a small pivoting-dependent system exactly.
    #[test]
    fn crout_lu_solves() {
        let lu = CroutLu::new(vec![0.0, 2.0, 1.0, 1.0], 2).expect("factored");
        let mut b = vec![4.0, 3.0];
        lu.solve(&mut b);
        assert_eq!(b, vec![1.0, 2.0]);
    }
}
