//! Tutorial Part IV (seed 002, T 1977–2120): the overlapping point r_{v,σ}, the triangle
//! Δ_(σ,v) = [r_{v,σ}, s_v(u), s_v(w)], the open wedge W_(σ,v) = D_v ∩ int Δ_(σ,v) and the
//! rigid maps f_(σ,v).
//!
//! **Local frame.** For the corner (σ, v) with σ the face of v's outgoing half-edge number k
//! (σ = [v, v_k, v_{k+1}], labels of Def. 4.1.4), f_(σ,v) is the rotation by (2k+1)π/m_v (then
//! a translation into its own copy of R², added by the abstract view). In local coordinates
//! p = f_(σ,v)⁻¹(q) every wedge of degree m is the same set: the bisector of s_v(σ) is the
//! +x axis, s_v(v_k) = A = (cos π/m, −sin π/m), s_v(v_{k+1}) = B = (cos π/m, sin π/m), and
//! r = (−δ, 0). That is why the least-squares matrix is factored once per degree.
//!
//! **r_{v,σ}** exists only in figures (T 1977–2001). Reading (SPEC `SV-D3`): r lies on the
//! bisector of s_v(σ), behind the centre, r = −κ·cos(π/m_v)·b, with the documented parameter
//! κ ∈ (0, 1) (default 1/4): any such r makes neighbouring wedges overlap ("Clearly
//! Ω_(σ,v) ∩ Ω_(τ,v) ≠ ∅", T 2092) and every wedge contain the centre.

use crate::construction::maps::{omega_radius, P2};
use crate::numeric::Scalar;

/// Default κ of r_{v,σ} = −κ·cos(π/m_v)·b_{v,σ} (SPEC `SV-D3`).
pub const DEFAULT_KAPPA: f64 = 0.25;

/// The constants of the wedges of one degree m in a scalar `S`.
#[derive(Clone, Debug)]
pub struct WedgeConsts<S> {
    /// The degree m.
    pub m: u32,
    /// ρ = cos(π/m): radius of D_v, the open disk of the inscribed circle C_v (T 2019).
    pub rho: S,
    /// ρ².
    pub rho2: S,
    /// δ = κρ: r = (−δ, 0) in local coordinates.
    pub delta: S,
    /// Unit inner normal of the side [r, A] of Δ.
    pub n1: (S, S),
    /// Unit inner normal of the side [r, B] of Δ.
    pub n2: (S, S),
    /// c: the distance from the centre 0 to the two sides [r, A], [r, B] (ramp width of γ).
    pub c: S,
    /// (cos, sin) of (2k+1)π/m, k = 0..m: the rotation part of f_(σ,v).
    pub frame: Vec<(S, S)>,
    /// Barycentric map of the envelope triangle E = [r, A, B]: λ_t = a_t·x + b_t·y + c_t.
    pub bary: [(S, S, S); 3],
}

impl<S: Scalar> WedgeConsts<S> {
    /// The constants for degree m ≥ 3 and κ at `prec` bits.
    pub fn new(m: u32, kappa: f64, prec: u32) -> Self {
        let pi = S::pi(prec);
        let rho = omega_radius::<S>(m, prec);
        let s = pi.div(&S::from_i64(m as i64, prec)).sin();
        let delta = rho.mul(&S::from_f64(kappa, prec));
        let a = rho.add(&delta); // x-extent of A − r and B − r
        let len = s.sqr().add(&a.sqr()).sqrt();
        let n1 = (s.div(&len), a.div(&len));
        let n2 = (s.div(&len), a.neg().div(&len));
        let c = s.mul(&delta).div(&len);
        let frame = (0..m)
            .map(|k| {
                let ang = pi.mul(&S::from_ratio(2 * k as i64 + 1, m as i64, prec));
                (ang.cos(), ang.sin())
            })
            .collect();
        // E = [r, A, B], r = (−δ, 0), A = (ρ, −s), B = (ρ, s) (|A| = |B| = 1).
        // λ_B = y/(2s) + (x + δ)/(2a), λ_A = −y/(2s) + (x + δ)/(2a), λ_r = 1 − λ_A − λ_B.
        let two = S::from_i64(2, prec);
        let ia = S::from_i64(1, prec).div(&two.mul(&a));
        let is = S::from_i64(1, prec).div(&two.mul(&s));
        let bary_a = (ia.clone(), is.neg(), delta.mul(&ia));
        let bary_b = (ia.clone(), is.clone(), delta.mul(&ia));
        let bary_r = (
            ia.mul(&two).neg(),
            S::from_i64(0, prec),
            S::from_i64(1, prec).sub(&delta.mul(&ia).mul(&two)),
        );
        WedgeConsts {
            m,
            rho2: rho.sqr(),
            rho,
            delta,
            n1,
            n2,
            c,
            frame,
            bary: [bary_r, bary_a, bary_b],
        }
    }

    /// f_(σ,v)⁻¹ without the translation: the local point of q ∈ plane of P_v, for the corner
    /// with label k (rotation by −(2k+1)π/m).
    pub fn to_local(&self, k: u32, q: &P2<S>) -> P2<S> {
        let (c, s) = &self.frame[k as usize];
        P2::new(q.x.mul(c).add(&q.y.mul(s)), q.y.mul(c).sub(&q.x.mul(s)))
    }

    /// f_(σ,v) without the translation: local point → plane of P_v.
    pub fn to_plane(&self, k: u32, p: &P2<S>) -> P2<S> {
        let (c, s) = &self.frame[k as usize];
        P2::new(p.x.mul(c).sub(&p.y.mul(s)), p.x.mul(s).add(&p.y.mul(c)))
    }

    /// Signed distances of a local point to the sides [r, A] and [r, B] (positive inside Δ).
    pub fn side_distances(&self, p: &P2<S>) -> (S, S) {
        let xr = p.x.add(&self.delta);
        (
            self.n1.0.mul(&xr).add(&self.n1.1.mul(&p.y)),
            self.n2.0.mul(&xr).add(&self.n2.1.mul(&p.y)),
        )
    }

    /// p ∈ W = D_v ∩ int Δ, p in local coordinates (T 2039 with C_v read as its open disk).
    pub fn in_wedge_local(&self, p: &P2<S>) -> bool {
        let (d1, d2) = self.side_distances(p);
        p.norm2().lt(&self.rho2).is_true()
            && d1.sign() == Some(std::cmp::Ordering::Greater)
            && d2.sign() == Some(std::cmp::Ordering::Greater)
    }

    /// q ∈ W_(σ,v), q in the plane of P_v, σ the face of label k.
    pub fn in_wedge(&self, k: u32, q: &P2<S>) -> bool {
        self.in_wedge_local(&self.to_local(k, q))
    }

    /// Barycentric coordinates (λ_r, λ_A, λ_B) of a local point w.r.t. E = [r, A, B].
    pub fn envelope_bary(&self, p: &P2<S>) -> [S; 3] {
        // By reference: a clone of the constants was a copy of nine jets per ψ on jets.
        std::array::from_fn(|t| {
            let (a, b, c) = &self.bary[t];
            a.mul(&p.x).add(&b.mul(&p.y)).add(c)
        })
    }

    /// The vertices r, A, B of the envelope triangle, local coordinates, as f64.
    pub fn envelope_f64(&self) -> [[f64; 2]; 3] {
        let rho = self.rho.to_f64();
        let s = (std::f64::consts::PI / self.m as f64).sin();
        [[-self.delta.to_f64(), 0.0], [rho, -s], [rho, s]]
    }
}

/// Per-degree wedge constants for all degrees up to `max_m`, κ and precision fixed.
#[derive(Clone, Debug)]
pub struct WedgeTable<S> {
    /// κ of r_{v,σ}.
    pub kappa: f64,
    /// Precision in bits.
    pub prec: u32,
    by_degree: Vec<Option<WedgeConsts<S>>>,
}

impl<S: Scalar> WedgeTable<S> {
    /// Constants for the given degrees (< 3 ignored).
    pub fn new(degrees: impl IntoIterator<Item = u32>, kappa: f64, prec: u32) -> Self {
        let mut by_degree: Vec<Option<WedgeConsts<S>>> = Vec::new();
        for m in degrees {
            if m < 3 {
                continue;
            }
            let i = m as usize;
            if by_degree.len() <= i {
                by_degree.resize(i + 1, None);
            }
            if by_degree[i].is_none() {
                by_degree[i] = Some(WedgeConsts::new(m, kappa, prec));
            }
        }
        WedgeTable {
            kappa,
            prec,
            by_degree,
        }
    }
    /// The constants of degree m, if built.
    pub fn get(&self, m: u32) -> Option<&WedgeConsts<S>> {
        self.by_degree.get(m as usize).and_then(|d| d.as_ref())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sv_d5_envelope_bary_and_wedge() {
        for m in 3..12 {
            let w = WedgeConsts::<f64>::new(m, 0.25, 53);
            for (t, v) in w.envelope_f64().iter().enumerate() {
                let b = w.envelope_bary(&P2::new(v[0], v[1]));
                for (s, x) in b.iter().enumerate() {
                    let want = if s == t { 1.0 } else { 0.0 };
                    assert!((x - want).abs() < 1e-12, "m {m} vertex {t}: {b:?}");
                }
            }
            assert!(
                w.in_wedge_local(&P2::new(0.0, 0.0)),
                "centre in W (r behind 0)"
            );
            assert!(!w.in_wedge_local(&P2::new(-0.9 * w.rho, 0.0)));
            // f and f⁻¹ are inverse.
            let q = P2::new(0.3, -0.2);
            let back = w.to_plane(1, &w.to_local(1, &q));
            assert!(back.dist_f64(&q) < 1e-15);
        }
    }
}
