//! Tutorial Part V (T 2755–2767): the weight functions γ_(σ,v) : R² → R.
//!
//! The slides give no formula ("the product of two C^∞ curves", T 2759; "'hat' function …
//! three C^∞ curves", S 1137). Reading (SPEC `SV-D10`), in the local frame of the corner
//! (bisector on +x, [`super::wedge`]):
//! γ(p) = ξ_{ρ/4, ρ}(|p|) · ξ_{0,1}(1 − d₁(p)/c) · ξ_{0,1}(1 − d₂(p)/c),
//! with ξ the function of Def. 5.3.1 (shared, [`crate::surface::weights`]), ρ = cos(π/m_v),
//! d₁, d₂ the signed distances to the sides [r, A], [r, B] of Δ (positive inside) and c their
//! value at the centre. The radial factor is the report's γ_v (Def. 5.3.2); the two side
//! factors are one "curve" across the wedge. γ is C^∞ on R² (ξ is flat at both ends), > 0
//! exactly on W = D_v ∩ int Δ, and 1 on a neighbourhood of the centre.

use super::wedge::WedgeConsts;
use crate::construction::P2;
use crate::surface::weights::{xi, xi_of_sq, XiConsts};
use crate::surface::SurfaceScalar;

/// Constants of the three factors of γ for one degree.
#[derive(Clone, Debug)]
pub struct WeightConsts<S> {
    /// ξ_{ρ/4, ρ} (Def. 5.3.2's constants).
    pub radial: XiConsts<S>,
    /// ξ_{0,1}.
    pub unit: XiConsts<S>,
    /// 1/c.
    pub inv_c: S,
}

impl<S: SurfaceScalar> WeightConsts<S> {
    /// For the wedges of `w`'s degree.
    pub fn new(w: &WedgeConsts<S>, prec: u32) -> Self {
        WeightConsts {
            radial: XiConsts::for_degree(w.m, prec),
            unit: XiConsts {
                h1: S::from_i64(0, prec),
                h2: S::from_i64(1, prec),
            },
            inv_c: S::from_i64(1, prec).div(&w.c),
        }
    }
}

/// γ_(σ,v)(p), p in the corner's local coordinates (SPEC `SV-D10`).
pub fn gamma_local<S: SurfaceScalar>(w: &WedgeConsts<S>, k: &WeightConsts<S>, p: &P2<S>) -> S {
    let radial = xi_of_sq(&k.radial, &p.norm2());
    if radial.sign() == Some(std::cmp::Ordering::Equal) {
        return radial;
    }
    let (d1, d2) = w.side_distances(p);
    let one = S::from_i64(1, d1.precision_bits());
    let f1 = xi(&k.unit, &one.sub(&d1.mul(&k.inv_c)));
    let f2 = xi(&k.unit, &one.sub(&d2.mul(&k.inv_c)));
    radial.mul(&f1).mul(&f2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sv_d10_gamma_positive_exactly_on_wedge() {
        for m in [3u32, 4, 6, 9] {
            let w = WedgeConsts::<f64>::new(m, 0.25, 53);
            let k = WeightConsts::new(&w, 53);
            assert_eq!(gamma_local(&w, &k, &P2::new(0.0, 0.0)), 1.0);
            for a in 0..60 {
                for b in 0..60 {
                    let p = P2::new(-1.0 + a as f64 / 30.0, -1.0 + b as f64 / 30.0);
                    let g = gamma_local(&w, &k, &p);
                    // γ > 0 only on W; on W at a margin from ∂W it is positive in f64 too (ξ is
                    // flat at its ends, so within ~1e-6 of ∂W it underflows to 0).
                    if g > 0.0 {
                        assert!(w.in_wedge_local(&p), "m {m} p {p:?} γ {g}");
                    }
                    let (d1, d2) = w.side_distances(&p);
                    let margin = d1.min(d2) > 1e-3 * w.c && p.norm2() < w.rho2 * (1.0 - 1e-3);
                    if margin {
                        assert!(g > 0.0, "m {m} p {p:?} γ {g}");
                    }
                }
            }
        }
    }
}
