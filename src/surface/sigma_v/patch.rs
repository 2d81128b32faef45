//! Tutorial Part V (T 2784–2982): the shape functions ψ_(σ,v), triangular Bézier patches whose
//! control points live on the envelope triangle E_(σ,v) = f⁻¹(Δ_(σ,v)) (T 2788, "envelope";
//! T 2120, "enclosing"), fitted by least squares (T 2916) to samples of S′ (T 2962–2982).
//!
//! Patch: ψ(p) = Σ_{a+b+c=d} P_abc · d!/(a!b!c!) · λ_r^a λ_A^b λ_B^c with λ the barycentric
//! coordinates w.r.t. E = [r, A, B] (local frame, [`super::wedge`]). The degree d is not given
//! by the slides: a parameter (SPEC `SV-D11`, default [`DEFAULT_PATCH_DEGREE`]).
//!
//! Fit (SPEC `SV-psi`): samples on the triangular grid of E with 2d intervals per side, kept
//! where |p| ≤ ρ (ψ is only used on W ⊂ D_v). A sample p of the corner (v, k) is the point
//! f(p) of P_v; it lies in a triangle s_v(σ′) = [0, v′_s, v′_{s+1}] of T_v, whose barycentric
//! coordinates give the point b_σ′(·) of S′ it is paired with (Sec. 5.2 of the report). In the
//! local frame s = k + s_rel with s_rel depending on p only, so the design matrix A and its
//! pseudo-inverse are the same for all corners of one degree: factored once per (m, d) by an
//! SVD (no normal equations), with the truncation `surface::fit::RCOND`.

use crate::construction::P2;
use crate::surface::fit::RCOND;
use crate::surface::target::cubic_bernstein;
use crate::surface::SurfaceScalar;
use serde::Serialize;

use super::wedge::WedgeConsts;

/// Default degree d of the triangular patches.
pub const DEFAULT_PATCH_DEGREE: usize = 7;
/// Largest supported patch degree (stack buffers of the f64 evaluator).
pub const MAX_PATCH_DEGREE: usize = 15;

/// Number of control points (d+1)(d+2)/2.
pub fn num_control_points(d: usize) -> usize {
    (d + 1) * (d + 2) / 2
}

/// The exponents (a, b, c) of control point number t, in storage order (a major, then b).
pub fn exponents(d: usize) -> Vec<[usize; 3]> {
    let mut out = Vec::with_capacity(num_control_points(d));
    for a in 0..=d {
        for b in 0..=d - a {
            out.push([a, b, d - a - b]);
        }
    }
    out
}

fn factorial(n: usize) -> f64 {
    (1..=n).map(|i| i as f64).product()
}

/// d!/(a!b!c!) for every control point, storage order.
pub fn multinomials(d: usize) -> Vec<f64> {
    exponents(d)
        .iter()
        .map(|e| (factorial(d) / (factorial(e[0]) * factorial(e[1]) * factorial(e[2]))).round())
        .collect()
}

/// The Bernstein basis at barycentric coordinates λ, storage order (f64).
pub fn bernstein_tri(d: usize, l: [f64; 3], coef: &[f64], out: &mut [f64]) {
    let mut pw = [[1.0f64; MAX_PATCH_DEGREE + 1]; 3];
    for t in 0..3 {
        for e in 1..=d {
            pw[t][e] = pw[t][e - 1] * l[t];
        }
    }
    let mut i = 0;
    for a in 0..=d {
        for b in 0..=d - a {
            out[i] = coef[i] * pw[0][a] * pw[1][b] * pw[2][d - a - b];
            i += 1;
        }
    }
}

/// ψ at barycentric coordinates λ (generic scalar: f64, Mp, jets).
pub fn eval_tri<S: SurfaceScalar>(d: usize, cps: &[[f64; 3]], coef: &[f64], l: &[S; 3]) -> [S; 3] {
    use crate::surface::jet::Jet;
    use std::any::TypeId;
    let t = TypeId::of::<S>();
    if t == TypeId::of::<Jet<f64, 6>>()
        || t == TypeId::of::<Jet<f64, 3>>()
        || t == TypeId::of::<Jet<f64>>()
    {
        // Jets of f64 (the sampling's normals and curvatures): the same operations compiled
        // for the CPU's vector extensions, which widen the coefficient-wise products and
        // sums of the jets; products and sums stay separate (never fused), so the bits do
        // not depend on the CPU.
        return pulp::Arch::new().dispatch(EvalTri { d, cps, coef, l });
    }
    eval_tri_body(d, cps, coef, l)
}

/// [`eval_tri`] as a [`pulp::WithSimd`] operation.
struct EvalTri<'a, S> {
    d: usize,
    cps: &'a [[f64; 3]],
    coef: &'a [f64],
    l: &'a [S; 3],
}

impl<S: SurfaceScalar> pulp::WithSimd for EvalTri<'_, S> {
    type Output = [S; 3];
    #[inline(always)]
    fn with_simd<V: pulp::Simd>(self, _: V) -> [S; 3] {
        eval_tri_body(self.d, self.cps, self.coef, self.l)
    }
}

#[inline(always)]
fn eval_tri_body<S: SurfaceScalar>(d: usize, cps: &[[f64; 3]], coef: &[f64], l: &[S; 3]) -> [S; 3] {
    let prec = l[0].precision_bits();
    // λ_t^e (e = 0..=d) of the three coordinates in one buffer, t major: one allocation per
    // patch instead of four.
    let n = d + 1;
    let mut pw: Vec<S> = Vec::with_capacity(3 * n);
    for x in l {
        pw.push(S::from_i64(1, prec));
        for _ in 1..=d {
            let next = pw[pw.len() - 1].mul(x);
            pw.push(next);
        }
    }
    let z = S::from_i64(0, prec);
    let mut acc = [z.clone(), z.clone(), z];
    let mut i = 0;
    for a in 0..=d {
        for b in 0..=d - a {
            let bern = pw[a]
                .mul(&pw[n + b])
                .mul(&pw[2 * n + d - a - b])
                .scale_f64(coef[i]);
            for (t, slot) in acc.iter_mut().enumerate() {
                *slot = slot.add(&bern.scale_f64(cps[i][t]));
            }
            i += 1;
        }
    }
    acc
}

/// ψ at barycentric coordinates λ in f64 (no allocation).
pub fn eval_tri_f64(d: usize, cps: &[[f64; 3]], coef: &[f64], l: [f64; 3]) -> [f64; 3] {
    let mut b = [0.0f64; num_cp_max()];
    let n = num_control_points(d);
    bernstein_tri(d, l, coef, &mut b[..n]);
    let mut acc = [0.0; 3];
    for (bi, c) in b[..n].iter().zip(cps) {
        acc[0] += bi * c[0];
        acc[1] += bi * c[1];
        acc[2] += bi * c[2];
    }
    acc
}

const fn num_cp_max() -> usize {
    (MAX_PATCH_DEGREE + 1) * (MAX_PATCH_DEGREE + 2) / 2
}

/// One least-squares sample (depends on the degree only).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct TriSample {
    /// The local point p ∈ E, |p| ≤ ρ.
    pub p: [f64; 2],
    /// s_rel: the T_v triangle containing f(p) is number k + s_rel for the corner (v, k).
    pub sector: u32,
    /// Barycentric coordinates of f(p) w.r.t. (0, v′_s, v′_{s+1}).
    pub bary: [f64; 3],
}

/// Summary of one factorization (reported by the checks, SPEC `SV-psi`).
#[derive(Debug, Clone, Serialize)]
pub struct TriFitInfo {
    /// Vertex degree m.
    pub m: u32,
    /// Patch degree d.
    pub d: usize,
    /// Samples (rows of A).
    pub rows: usize,
    /// Control points (columns of A).
    pub unknowns: usize,
    /// Numerical rank.
    pub rank: usize,
    /// κ(A) = σ_max/σ_min.
    pub condition: f64,
}

/// The factored least-squares problem of one degree.
#[derive(Debug, Clone)]
pub struct TriFit {
    /// Summary.
    pub info: TriFitInfo,
    /// The samples, in row order.
    pub samples: Vec<TriSample>,
    /// A⁺, unknowns × rows, row-major.
    pub pinv: Vec<f64>,
    /// The sectors s_rel some sample falls in (ascending).
    pub sectors: Vec<u32>,
    /// A⁺·W restricted to `sectors`: unknowns × (10·|sectors|), row-major; column
    /// 10·t + c weighs control point c (in `CUBIC_ORDER`) of the cubic net of sector
    /// k + sectors\[t\].
    pub net_map: Vec<f64>,
}

/// The samples of one degree.
pub fn tri_samples(w: &WedgeConsts<f64>, d: usize) -> Vec<TriSample> {
    let n = 2 * d.max(1);
    let [r, a, b] = w.envelope_f64();
    let m = w.m as f64;
    let tau = 2.0 * std::f64::consts::PI;
    let rho = w.rho;
    let mut out = Vec::new();
    for i in 0..=n {
        for j in 0..=n - i {
            let (s, t) = (i as f64 / n as f64, j as f64 / n as f64);
            let p = [
                r[0] + s * (a[0] - r[0]) + t * (b[0] - r[0]),
                r[1] + s * (a[1] - r[1]) + t * (b[1] - r[1]),
            ];
            if p[0] * p[0] + p[1] * p[1] > rho * rho * (1.0 + 1e-12) {
                continue;
            }
            // f(p) for k = 0: rotation by π/m.
            let q = w.to_plane(0, &P2::new(p[0], p[1]));
            let mut ang = q.y.atan2(q.x);
            if ang < 0.0 {
                ang += tau;
            }
            let sec = ((ang * m / tau).floor() as u32).min(w.m - 1);
            let c0 = (tau * sec as f64 / m).sin_cos();
            let c1 = (tau * (sec + 1) as f64 / m).sin_cos();
            let (p0, p1) = ([c0.1, c0.0], [c1.1, c1.0]);
            let det = p0[0] * p1[1] - p0[1] * p1[0];
            let nu = (q.x * p1[1] - q.y * p1[0]) / det;
            let eta = (p0[0] * q.y - p0[1] * q.x) / det;
            out.push(TriSample {
                p,
                sector: sec,
                bary: [1.0 - nu - eta, nu, eta],
            });
        }
    }
    out
}

/// Factor the fit of degree `w.m` with patch degree d (once per (m, d)).
pub fn factor(w: &WedgeConsts<f64>, d: usize) -> TriFit {
    let samples = tri_samples(w, d);
    let nc = num_control_points(d);
    let coef = multinomials(d);
    let rows = samples.len();
    let mut a = nalgebra::DMatrix::<f64>::zeros(rows, nc);
    let mut buf = vec![0.0; nc];
    for (r, s) in samples.iter().enumerate() {
        let l = w.envelope_bary(&P2::new(s.p[0], s.p[1]));
        bernstein_tri(d, l, &coef, &mut buf);
        for c in 0..nc {
            a[(r, c)] = buf[c];
        }
    }
    let svd = a.svd(true, true);
    let sv = &svd.singular_values;
    let smax = sv.iter().cloned().fold(0.0f64, crate::report::dev_max);
    let smin = sv.iter().cloned().fold(f64::INFINITY, f64::min);
    let cut = smax * RCOND.max(rows.max(nc) as f64 * f64::EPSILON);
    let rank = sv.iter().filter(|&&s| s > cut).count();
    let pinv_m = svd
        .pseudo_inverse(cut)
        .unwrap_or_else(|_| nalgebra::DMatrix::zeros(nc, rows));
    let mut pinv = vec![0.0; nc * rows];
    for c in 0..nc {
        for r in 0..rows {
            pinv[c * rows + r] = pinv_m[(c, r)];
        }
    }
    let mut sectors: Vec<u32> = samples.iter().map(|s| s.sector).collect();
    sectors.sort_unstable();
    sectors.dedup();
    let cols = 10 * sectors.len();
    let mut net_map = vec![0.0; nc * cols];
    for (r, s) in samples.iter().enumerate() {
        let t = sectors.iter().position(|&x| x == s.sector).unwrap_or(0);
        let bern = cubic_bernstein(s.bary);
        for c in 0..nc {
            let wgt = pinv[c * rows + r];
            for (q, bq) in bern.iter().enumerate() {
                net_map[c * cols + 10 * t + q] += wgt * bq;
            }
        }
    }
    TriFit {
        info: TriFitInfo {
            m: w.m,
            d,
            rows,
            unknowns: nc,
            rank,
            condition: if smin > 0.0 {
                smax / smin
            } else {
                f64::INFINITY
            },
        },
        samples,
        pinv,
        sectors,
        net_map,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sv_d11_sv_psi_full_rank_and_reproduces_linear_data() {
        for m in [3u32, 5, 6, 8, 12] {
            let w = WedgeConsts::<f64>::new(m, 0.25, 53);
            let f = factor(&w, DEFAULT_PATCH_DEGREE);
            assert_eq!(f.info.rank, f.info.unknowns, "{:?}", f.info);
            // Least squares reproduces a polynomial of degree ≤ d exactly: fit x + 2y.
            let nc = f.info.unknowns;
            let rows = f.samples.len();
            let data: Vec<f64> = f.samples.iter().map(|s| s.p[0] + 2.0 * s.p[1]).collect();
            let cps: Vec<[f64; 3]> = (0..nc)
                .map(|c| {
                    let v: f64 = (0..rows).map(|r| f.pinv[c * rows + r] * data[r]).sum();
                    [v, 0.0, 0.0]
                })
                .collect();
            let coef = multinomials(DEFAULT_PATCH_DEGREE);
            let p = P2::new(0.1, -0.05);
            let l = w.envelope_bary(&p);
            let y = eval_tri_f64(DEFAULT_PATCH_DEGREE, &cps, &coef, l);
            assert!((y[0] - 0.0).abs() < 1e-9, "m {m}: {y:?}");
            let yg = eval_tri::<f64>(DEFAULT_PATCH_DEGREE, &cps, &coef, &l);
            assert!((yg[0] - y[0]).abs() < 1e-12);
        }
    }
}
