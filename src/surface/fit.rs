//! Sec. 5.2: the least-squares fit of the shape functions ψ_v (Def. 5.2.1).
//!
//! The design matrix A (A_{i, j(l+1)+k} = B_j^l(x_i)·B_k^l(y_i)) depends only on m_v and the
//! profile, so it is factored once per degree by a thin SVD (no normal equations: the
//! Bernstein tensor basis clipped to P_v is ill-conditioned, κ(A) ≈ 10⁴–10¹², and AᵀA would
//! square that). Singular values below σ_max · max(RCOND, max(n, (l+1)²)·ε) are dropped (minimum-norm
//! least-squares solution); the numerical rank and κ are reported per degree.
//!
//! The sample set of Sec. 5.2: a uniform grid on □_v = [−L, L]², L = cos(π/m_v), both ends
//! included; points outside the closed P-polygon P_v are dropped; each kept point q lies in a
//! triangle s_v(σ) = [v′, v′_i, v′_{i+1}] of T_v, whose barycentric coordinates (λ, ν, η) give
//! the point of S′ paired with q: b_σ(λa + νb + ηc).

use super::bezier::bernstein_f64;
use super::profile::Profile;
use super::target::cubic_bernstein;
use serde::Serialize;

/// Relative truncation of the SVD: singular values ≤ RCOND·σ_max are dropped. With the
/// rank-revealing floor max(n, k)·ε alone, high-degree fits (m ≥ 19) return minimum-norm
/// solutions with control points ~10⁹ times the geometry (cancellation then costs ~10⁻⁷ in
/// every evaluation of ψ_v); 10⁻⁹ bounds the amplification of the truncated problem.
pub const RCOND: f64 = 1e-9;

/// One sample of Sec. 5.2 (depends on the degree only).
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Sample {
    /// q ∈ P_v ∩ □_v.
    pub q: [f64; 2],
    /// i: q ∈ [v′, v′_i, v′_{i+1}].
    pub sector: u32,
    /// Barycentric coordinates of q w.r.t. (v′, v′_i, v′_{i+1}).
    pub bary: [f64; 3],
}

/// Summary of the per-degree factorization (reported by `ppm sample`/checks).
#[derive(Debug, Clone, Serialize)]
pub struct DegreeFitInfo {
    pub m: u32,
    pub l: usize,
    /// L = cos(π/m): □_v = [−L, L]².
    pub half_side: f64,
    /// Grid points kept (in P_v): the rows of A.
    pub rows: usize,
    /// Unknowns per coordinate: (l+1)².
    pub unknowns: usize,
    /// Numerical rank of A (singular values > σ_max · max(RCOND, max(n, k) · ε)).
    pub rank: usize,
    /// κ(A) = σ_max/σ_min over all singular values (∞ if σ_min = 0).
    pub condition: f64,
    /// σ_max/σ_rank: the condition number of the truncated problem actually solved.
    pub effective_condition: f64,
}

/// The factored least-squares problem for one degree.
#[derive(Debug, Clone)]
pub struct DegreeFit {
    pub info: DegreeFitInfo,
    pub samples: Vec<Sample>,
    /// A⁺, (l+1)² × rows, row-major.
    pub pinv: Vec<f64>,
    /// A⁺·W for cubic-triangle targets: (l+1)² × (m·10), row-major; column i·10 + t is the
    /// weight of control point t (in `CUBIC_ORDER`) of the cubic net of sector i.
    pub net_map: Vec<f64>,
}

/// The Sec. 5.2 sample set for degree m.
pub fn sample_set(m: u32, profile: Profile) -> Vec<Sample> {
    let l = profile.bezier_degree(m);
    let n = profile.grid_side(l);
    let mf = m as f64;
    let half = (std::f64::consts::PI / mf).cos();
    let corner = |i: u32| {
        let a = 2.0 * std::f64::consts::PI * (i % m) as f64 / mf;
        [a.cos(), a.sin()]
    };
    let mut out = Vec::with_capacity(n * n);
    for a in 0..n {
        for b in 0..n {
            let x = -half + 2.0 * half * a as f64 / (n - 1) as f64;
            let y = -half + 2.0 * half * b as f64 / (n - 1) as f64;
            let mut ang = y.atan2(x);
            if ang < 0.0 {
                ang += 2.0 * std::f64::consts::PI;
            }
            let i = ((ang * mf / (2.0 * std::f64::consts::PI)).floor() as u32).min(m - 1);
            let (p, r) = (corner(i), corner(i + 1));
            // q = ν p + η r.
            let det = p[0] * r[1] - p[1] * r[0];
            let nu = (x * r[1] - y * r[0]) / det;
            let eta = (p[0] * y - p[1] * x) / det;
            let lam = 1.0 - nu - eta;
            if lam < -1e-12 {
                continue; // outside P_v
            }
            out.push(Sample {
                q: [x, y],
                sector: i,
                bary: [lam.max(0.0), nu, eta],
            });
        }
    }
    out
}

/// Factor the least-squares problem of degree m (thin SVD) and precompute A⁺ and A⁺·W.
pub fn factor_degree(m: u32, profile: Profile) -> DegreeFit {
    let l = profile.bezier_degree(m);
    let k = (l + 1) * (l + 1);
    let samples = sample_set(m, profile);
    let n = samples.len();
    let half = (std::f64::consts::PI / m as f64).cos();
    let mut bx = vec![0.0; l + 1];
    let mut by = vec![0.0; l + 1];
    let mut a = nalgebra::DMatrix::<f64>::zeros(n, k);
    for (i, s) in samples.iter().enumerate() {
        bernstein_f64(l, half, s.q[0], &mut bx);
        bernstein_f64(l, half, s.q[1], &mut by);
        for j in 0..=l {
            for kk in 0..=l {
                a[(i, j * (l + 1) + kk)] = bx[j] * by[kk];
            }
        }
    }
    let svd = a.svd(true, true);
    let sv = &svd.singular_values;
    let smax = sv.iter().cloned().fold(0.0, f64::max);
    let smin_all = if n >= k {
        sv.iter().cloned().fold(f64::INFINITY, f64::min)
    } else {
        0.0
    };
    let tol = smax * RCOND.max(n.max(k) as f64 * f64::EPSILON);
    let rank = sv.iter().filter(|&&s| s > tol).count();
    let smin_kept = sv
        .iter()
        .cloned()
        .filter(|&s| s > tol)
        .fold(f64::INFINITY, f64::min);
    let mut pinv = vec![0.0; k * n];
    if let (Some(u), Some(vt)) = (&svd.u, &svd.v_t) {
        // A⁺ = V Σ⁺ Uᵀ.
        for (r, &s) in sv.iter().enumerate() {
            if s <= tol {
                continue;
            }
            let inv = 1.0 / s;
            for c in 0..k {
                let vc = vt[(r, c)] * inv;
                if vc == 0.0 {
                    continue;
                }
                let row = &mut pinv[c * n..(c + 1) * n];
                for (i, slot) in row.iter_mut().enumerate() {
                    *slot += vc * u[(i, r)];
                }
            }
        }
    }
    let cols = m as usize * 10;
    let mut net_map = vec![0.0; k * cols];
    for (i, s) in samples.iter().enumerate() {
        let w = cubic_bernstein(s.bary);
        let base = s.sector as usize * 10;
        for c in 0..k {
            let a = pinv[c * n + i];
            if a == 0.0 {
                continue;
            }
            let row = &mut net_map[c * cols + base..c * cols + base + 10];
            for t in 0..10 {
                row[t] += a * w[t];
            }
        }
    }
    DegreeFit {
        info: DegreeFitInfo {
            m,
            l,
            half_side: half,
            rows: n,
            unknowns: k,
            rank,
            condition: if smin_all > 0.0 {
                smax / smin_all
            } else {
                f64::INFINITY
            },
            effective_condition: smax / smin_kept,
        },
        samples,
        pinv,
        net_map,
    }
}
