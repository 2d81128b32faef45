//! A forward-error bound for the f64 eval of Sec. 6.1.4, per point.
//!
//! eval(σ, λ, μ, ν) = θ_v(q) = Σ_u Γ_uv(q) ψ_u(q_u) / Σ_u Γ_uv(q) (Def. 5.4.2). Its f64 error
//! has two parts of different nature:
//!
//! * **The patches** (Def. 5.2.1). ψ_u(x, y) = Σ_{j,k} b_jk B_j^l(x) B_k^l(y) is a sum of
//!   (l+1)² terms whose control points can be many orders of magnitude larger than the surface
//!   (a least-squares fit of high bi-degree cancels: on the corpus's anchor, |b| reaches 4.7e6
//!   for a surface of size 0.55). Counting roundings in [`super::bezier::eval_patch_f64`]
//!   (u = (t+L)/2L: 2; uⁱ and w^{l−i}: 3i and 3(l−i); the binomial and the product: 2; each
//!   Bernstein value is within θ_{3l+2}; the two contractions add l+1 each; one more for a
//!   binomial above 2⁵³), with Higham's γ_n = nu/(1 − nu), u = ε/2:
//!   |fl(ψ)(q̂) − ψ(q̂)| ≤ γ_{8l+8} · A(q̂), A(q̂) = max_d Σ_{j,k} |b_jk\[d\]| B_j(x̂) B_k(ŷ).
//!   A grows with the fit's conditioning (|b| against the surface) and its degree; this is
//!   the part that a bound proportional to the surface's size misses.
//! * **The maps and the blend** (g, h, φ, γ of Ch. 4–5, the weighted mean): ~10² operations on
//!   quantities of the size of the surface, with the transition maps' moderate derivatives;
//!   bounded by [`MAP_BOUND_ULPS`]·ε·scale (scale = max |coordinate| of the sampled surface).
//!
//! The bound is `Σ_u ω_u γ_{8l_u+8} A_u(q̂_u) + MAP_BOUND_ULPS·ε·scale`, the ω_u being the
//! normalised weights. The second part is an operation count, not a proof: `ppm diff
//! --surface` re-evaluates spot checks at 256 bits and reports every point where the f64
//! error exceeds the bound (SPEC `R-diff-f64-bound`), so a wrong analysis cannot pass silently.

use super::pps::{Pps, Term};
use super::SurfaceError;
use crate::mesh::FaceId;

/// The map-and-blend part of the bound in units of ε·scale (see the module doc).
pub(crate) const MAP_BOUND_ULPS: f64 = 4096.0;

/// Higham's γ_n = nu/(1 − nu), u = ε/2: the relative error bound of n roundings.
pub(crate) fn gamma_n(n: usize) -> f64 {
    let nu = n as f64 * f64::EPSILON / 2.0;
    nu / (1.0 - nu)
}

/// An f64 eval with the patch part of its forward-error bound.
#[derive(Debug, Clone, Copy)]
pub struct BoundedPoint {
    /// eval(σ, λ, μ, ν) in f64.
    pub point: [f64; 3],
    /// Σ_u ω_u γ_{8l_u+8} A_u(q̂_u): the bound on the patches' rounding (module doc).
    pub patch_bound: f64,
    /// Σ_u ω_u A_u(q̂_u): the patches' absolute size at the point (the conditioning).
    pub abs_size: f64,
}

impl BoundedPoint {
    /// The whole bound: the patch part plus [`MAP_BOUND_ULPS`]·ε·scale.
    pub fn bound(&self, scale: f64) -> f64 {
        self.patch_bound + MAP_BOUND_ULPS * f64::EPSILON * scale.max(1.0)
    }
}

/// A(x, y) = max_d Σ_{j,k} |b_jk\[d\]| B_j^l(x) B_k^l(y), rounded up by its own γ_{8l+8}.
pub(crate) fn abs_patch_f64(cp: &[[f64; 3]], l: usize, half: f64, x: f64, y: f64) -> f64 {
    let l1 = l + 1;
    let bx = super::bezier::bernstein_vec_f64(l, half, x);
    let by = super::bezier::bernstein_vec_f64(l, half, y);
    let mut out = [0.0f64; 3];
    for (j, &b) in bx.iter().enumerate() {
        for (k, &c) in by.iter().enumerate() {
            let w = b.abs() * c.abs();
            let p = &cp[j * l1 + k];
            for d in 0..3 {
                out[d] += w * p[d].abs();
            }
        }
    }
    out.iter().fold(0.0f64, |a, &b| a.max(b)) * (1.0 + 2.0 * gamma_n(8 * l + 8))
}

impl Pps {
    /// eval in f64 with the patch part of its forward-error bound (module doc). The point is
    /// exactly [`Pps::eval_f64`]'s.
    pub fn eval_f64_bounded(
        &self,
        f: FaceId,
        bary: [f64; 3],
    ) -> Result<BoundedPoint, SurfaceError> {
        // One eval; its blended terms (u, q_u, Γ_u) are read in the same pass.
        let mut terms: Vec<Term<f64>> = Vec::with_capacity(4);
        let e = self.eval_visiting(f, &bary, self.consts_f64(), |t| terms.push(t.clone()))?;
        let den: f64 = terms.iter().map(|t| t.gamma).sum();
        if !(den > 0.0) {
            return Err(SurfaceError::ZeroWeight(e.vertex));
        }
        let (mut patch_bound, mut abs_size) = (0.0f64, 0.0f64);
        for t in &terms {
            if t.gamma == 0.0 {
                continue;
            }
            let (cp, l) = self.patch(t.u);
            let a = abs_patch_f64(cp, l, self.half_side(t.u), t.q.x, t.q.y);
            let w = t.gamma / den;
            patch_bound += w * gamma_n(8 * l + 8) * a;
            abs_size += w * a;
        }
        // The weights ω are themselves rounded (a few ulps): inflate once.
        let up = 1.0 + gamma_n(8);
        Ok(BoundedPoint {
            point: e.point,
            patch_bound: patch_bound * up,
            abs_size,
        })
    }
}
