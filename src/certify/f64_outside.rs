//! CERT-f64-rounding beyond Ω_uw: the ε-neighbourhood of Ω_uw on which `phi` and `inner` hold,
//! and the literal membership test's `f64` answer on the rest of Ω_u.
//!
//! ## The neighbourhood
//! The φ pass (module `f64_bound`) bounds every polar box of u's chart (after R_(u,w)) that may
//! meet the closed ε-neighbourhood N_ε(Ω_uw), ε = [`F64_NBHD`]: [`meets_nbhd`] decides the
//! closed form of Def. 4.1.9 (module `interval`) on the box widened by ε in r and by 2ε/r₀ in θ
//! (a point within ε of a point of radius r ≥ r₀ > 2ε differs in angle by ≤ asin(ε/r₀) ≤ 2ε/r₀),
//! so a box it refuses has no point within ε of Ω_uw; the root box reaches r_u + ε. Every box
//! the pass bounds is one on which the `Fe` evaluation of the canonical chain succeeded, so the
//! exact chain is off Π's cut and the origin there (`Fe` decides a branch only for the exact and
//! the `f64` values together): φ_wu is C¹ on N_ε(Ω_uw) with ‖J‖ ≤ L(u→w) (module `f64_props`).
//! Its leaves also have winding 0 certified (module `interval`), so at their points outside
//! Ω_uw the exact test answers "out" by |p|² ≥ r_u² or |q|² ≥ r_w² alone.
//!
//! ## The rest of Ω_u
//! A box of the same branch and bound that [`meets_nbhd`] refuses (no point of it is within ε
//! of Ω_uw, so the exact literal test answers "out" at each of its points) is decided by
//! [`outside_box`], for the `f64` points â = R̂_(u,w)(p) (|â − a| ≤ δ₁, the label rotations'
//! error, a = R_(u,w)(p) in the box) taken as exact inputs (`Fe::exact`), in up to three pieces
//! where the set meets Π's cut (y > 0, y = ±0, y < 0: the `f64` Π decides each), one of:
//! * (value) the `f64` value of |q̂|² − r_w² is > 0 on the piece for every label j (the rotation
//!   R_(w,u)⁻¹ adds ≤ ρ to |q̂|, ρ bounded once for |x|, |y| ≤ 4): the `f64` test answers "out";
//! * (margin, boxes of diameter ≤ `F64_BOUND_DIAM`) the exact |b − (1,0)|² ≥ 3/4 on the box, i.e. |q|² ≥ r_w² (exact "out" by q ∉ Ω_w):
//!   the `f64` value of |q̂|² − r_w² differs from the exact one at a by ≤ `inner` (the error
//!   at â, `Fe` box by box through every label's rotation R_(w,u)⁻¹, plus Lip·δ₁
//!   with Lip = 2(1 + k_u)·k_u·max(1, m_u/6)/k_w² ≥ |∇(|q|²)|: |q|² = |c|²/k_w² with
//!   |c|² = 1 − 2k_u r cos(m_uθ/6) + k_u²r², even in θ, so Lipschitz across Π's cut as well);
//!   the `f64` test answers "out" unless |q|² − r_w² ∈ [0, `inner`];
//! * (round trip) winding ≠ 0 on the box (θ widened by 2δ₁/r₀), c_x > 0 for the exact
//!   c = h(g_u(â)) (then g_w∘g_w⁻¹(c) = c, h(c) = b and the exact round trip from â is â rotated
//!   by −12πn/m_u, n the winding: |Ψ(â) − â| = 2|â|·|sin(6πn/m_u)| ≥ 2|â|·s_min, s_min the minimum
//!   over 1 ≤ |n| ≤ m_u/12 + 1/2), and the `f64` round trip (`Fe` through g_w, h, g_u⁻¹ from
//!   q̂, the rotations R_(w,u)⁻¹, R_(w,u) as an input error δ₅ + δ₆, R_(u,w)⁻¹ as δ₁₀ at the
//!   end) stays ≥ 2·tol away from p: 2(r₀ − δ₁)s_min − δ₁ − err − δ₁₀ ≥ 2·tol, so the `f64`
//!   comparison |x̂₁₀ − p|² ≤ tol² is false and the test answers "out".
//!
//! Boxes containing the origin with r ≤ [`ORIGIN_CORE`] are decided by value in closed form:
//! |ĝ_u(â)| ≤ k_u|â|(1 + 4u) + tiny for every `f64` â (`Fe` through |â|, k_u·r and Π⁻¹ with any
//! `f64` angle), so ĉ = h(ĝ_u(â)) stays near (1, 0), where |q̂|² > r_w². A box none of these
//! decides is split; at [`OUTSIDE_MIN_DIAM`] (above the depth limit's size) it is counted as unresolved (then `inner` is
//! `None`: no claim).

use super::bnb::{canon_edge, PBox};
use super::f64_roundtrip::{err2, rotation_error, rotation_error_on, F64_BOUND_DIAM, ROT_RAD};
use super::interval::{c, iv, lt, member_any, principal_pieces, ratio, sym, Deg, Domain};
use super::result::F64Outside;
use crate::construction::maps::{f_v_radial_factor, omega_radius, polar_inv, Polar};
use crate::construction::maps::{rotate_frac, roundtrip_tolerance};
use crate::construction::maps::{Paper, Ppm, P2};
use crate::numeric::interval::Interval as I;
use crate::numeric::rounding::{mag, LibmModel, UNIT_ROUNDOFF};
use crate::numeric::{Fe, Scalar, Trit};
use crate::report::dev_max;

/// ε: CERT-f64-rounding's `phi` and `inner` hold on every box meeting the closed
/// ε-neighbourhood of Ω_uw (far above every `phi` up to M = 32, 5.65e−13, which the
/// `L4.2.1(cert)` and `L4.2.2(cert)` bounds need covered: `certify::f64_props`).
pub const F64_NBHD: f64 = 1e-9;

/// Boxes around the origin up to this radius are decided in closed form (module docs).
pub const ORIGIN_CORE: f64 = 0.02;

/// Boxes off the neighbourhood are not bisected below this diameter.
pub const OUTSIDE_MIN_DIAM: f64 = 2e-3;

/// Can the box meet the closed ε-neighbourhood of Ω_uw? (`False`: no point of it is within ε
/// of Ω_uw; module docs.)
pub fn meets_nbhd(du: &Deg, b: &PBox, eps: f64) -> Trit {
    let r = iv(
        (c(b.r.0) - c(eps)).inf().max(0.0),
        (c(b.r.1) + c(eps)).sup(),
    );
    let th = if b.r.0 > 2.0 * eps {
        let dth = (c(2.0) * c(eps) / c(b.r.0)).sup();
        b.ith() + iv(-dth, dth)
    } else {
        iv(-I::PI.sup(), I::PI.sup())
    };
    if th.sup() - th.inf() >= 6.0 {
        return member_any(du, iv(-I::PI.sup(), I::PI.sup()), r, Domain::Literal);
    }
    member_any(du, th, r, Domain::Literal)
}

/// Per-configuration constants of the pass off the neighbourhood.
pub(super) struct Outside {
    du: Deg,
    m_u: u32,
    m_w: u32,
    /// δ₁: R_(u,w) (all labels, |x|, |y| ≤ ROT_RAD, ⊇ Ω_u).
    d1: f64,
    /// δ₅ + δ₆ and δ₁₀ (module `f64_roundtrip`).
    d56: f64,
    d10: f64,
    /// ρ: R_(w,u)⁻¹ on |x|, |y| ≤ 4 (all labels j; label 0 is the identity, exact).
    rho: f64,
    /// The `f64` value of r_w² (enclosed).
    rw2: I,
    /// s_min = min |sin(6πn/m_u)| over 1 ≤ n ≤ m_u/12 + 1/2 (`None`: m_u ≤ 6, winding 0).
    s_min: Option<f64>,
    /// 2·tol (the literal test's tolerance, its `f64` value enclosed).
    two_tol: f64,
    /// Lip of |q|² in a (module docs).
    lip_q: f64,
}

/// Running results of the pass.
#[derive(Debug, Clone, Default)]
pub(super) struct OutsideStats {
    /// max over the margin boxes and labels of the `f64` error of |q|² − r_w² at â.
    pub(super) inner: f64,
    pub(super) by_value: u64,
    pub(super) by_margin: u64,
    pub(super) by_roundtrip: u64,
    pub(super) unresolved: u64,
}

/// What [`outside_box`] says about a box.
pub(super) enum OutsideLeaf {
    Done,
    Split,
}

impl Outside {
    pub(super) fn new<L: LibmModel>(m_u: u32, m_w: u32) -> Outside {
        let (du, dw) = (Deg::new(m_u), Deg::new(m_w));
        let s_min = (m_u > 6).then(|| {
            let nmax = (m_u as i64 + 6) / 12;
            (1..=nmax.max(1))
                .map(|n| (I::PI * ratio(6 * n, m_u as i64)).sin().abs().inf())
                .fold(f64::INFINITY, f64::min)
        });
        let tol = Fe::<L>::from_f64(roundtrip_tolerance(&canon_edge(m_u, m_w), 1.0), 53)
            .mul(&Fe::<L>::exact(c(1.0)).unit_roundoff());
        let lip_q = (c(2.0) * (c(1.0) + du.k) * du.k * du.m6.max(c(1.0)) / dw.k.sqr()).sup();
        Outside {
            du,
            m_u,
            m_w,
            d1: rotation_error::<L>(m_u, -1),
            d56: rotation_error::<L>(m_w, 1) + rotation_error::<L>(m_w, -1),
            d10: rotation_error::<L>(m_u, 1),
            rho: rotation_error_on::<L>(m_w, 1, 4.0),
            rw2: omega_radius::<Fe<L>>(m_w, 53).sqr().w(),
            s_min,
            two_tol: (c(2.0) * tol.w()).sup(),
            lip_q,
        }
    }

    /// The `f64` value of |q̂|² − r_w² is > 0 for every label, q̂ = R̂_(w,u)⁻¹(d̂), d̂ ∈ `d`.
    fn positive_by_value<L: LibmModel>(&self, d: &P2<Fe<L>>) -> bool {
        let (wx, wy) = (d.x.w(), d.y.w());
        let nd = (wx.sqr() + wy.sqr()).sqrt();
        let nq = nd + sym(self.rho);
        let u = UNIT_ROUNDOFF;
        let q2 = nq.sqr() * (c(1.0) + iv(-3.0 * u, 3.0 * u)) + sym(1e-300);
        (q2 - self.rw2).inf() > 0.0
    }

    /// The round-trip argument of the module docs on one piece (`a`: exact inputs â).
    fn far_by_roundtrip<L: LibmModel>(&self, b: &PBox, a: &P2<Fe<L>>) -> bool {
        let Some(s_min) = self.s_min else {
            return false;
        };
        let r0 = b.r.0 - self.d1;
        if r0 <= 2.0 * self.d1 || r0 <= 0.0 {
            return false;
        }
        // Winding ≠ 0 at every â (|arg â − arg a| ≤ 2δ₁/r₀).
        let dth = (c(2.0) * c(self.d1) / c(r0)).sup();
        let th = b.ith() + iv(-dth, dth);
        if th.sup() - th.inf() >= 6.0
            || !principal_pieces(th)
                .iter()
                .all(|p| self.du.winding0(*p).is_false())
        {
            return false;
        }
        let Ok(bb) = Paper.g_v(self.m_u, a) else {
            return false;
        };
        let cc = Paper.h(&bb);
        if cc.x.v.inf() <= 0.0 {
            return false;
        }
        let Ok(d) = Paper.g_v_inv(self.m_w, &cc) else {
            return false;
        };
        let fin = |x: f64| x.is_finite();
        // Euclidean: the rotated states' coordinates then stay in the square the rotation
        // errors are bounded on.
        let norm = |x: I, y: I| (c(mag(x)).sqr() + c(mag(y)).sqr()).sqrt().sup();
        if !fin(err2(&d)) || norm(d.x.w(), d.y.w()) + self.d56 > ROT_RAD {
            return false;
        }
        let x6 = P2::new(
            Fe::<L>::new(d.x.v, d.x.e + sym(self.d56)),
            Fe::new(d.y.v, d.y.e + sym(self.d56)),
        );
        let Ok(s7) = Paper.g_v(self.m_w, &x6) else {
            return false;
        };
        let s8 = Paper.h(&s7);
        let Ok(s9) = Paper.g_v_inv(self.m_u, &s8) else {
            return false;
        };
        let e9 = err2(&s9);
        if !fin(e9) || norm(s9.x.w(), s9.y.w()) > ROT_RAD {
            return false;
        }
        let sep = c(2.0) * c(r0) * c(s_min) - c(self.d1) - c(e9) - c(self.d10);
        sep.inf() >= self.two_tol
    }
}

/// The `f64` input sets of a box: the Cartesian enclosure of a = R_(u,w)(p) widened by δ₁, in
/// pieces on which the `f64` Π takes one branch (y > 0, y = ±0, y < 0 where the set meets the
/// negative x-axis).
fn input_pieces<L: LibmModel>(b: &PBox, d1: f64) -> Vec<P2<Fe<L>>> {
    let (th, r) = (b.ith(), b.ir());
    let (ax, ay) = (r * th.cos() + sym(d1), r * th.sin() + sym(d1));
    let tiny = f64::from_bits(1);
    let ys = if ax.inf() <= 0.0 && ay.inf() < 0.0 && ay.sup() > 0.0 {
        vec![iv(tiny, ay.sup()), c(0.0), iv(ay.inf(), -tiny)]
    } else {
        vec![ay]
    };
    ys.into_iter()
        .map(|y| P2::new(Fe::exact(ax), Fe::exact(y)))
        .collect()
}

/// The closed-form core around the origin (module docs): every `f64` â with |â| ≤ `rad`
/// gives |q̂|² > r_w² for every label.
fn origin_core<L: LibmModel>(k: &Outside, rad: f64) -> bool {
    // r̂ = fl(√fl(fl(x²) + fl(y²))) ≤ √2·rad·(1 + u)² + √(3·2⁻¹⁰⁷⁴)(1 + u) for |x|, |y| ≤ rad.
    let u = UNIT_ROUNDOFF;
    let r_hat = (c(rad) * c(2.0).sqrt() * c(1.0 + 4.0 * u)).sup() + 1e-160;
    let rho = f_v_radial_factor::<Fe<L>>(k.m_u, 53).mul(&Fe::exact(iv(0.0, r_hat)));
    let bb = polar_inv(&Polar {
        theta: Fe::<L>::exact(iv(-20.0, 20.0)),
        r: Fe::exact(iv(0.0, rho.w().sup())),
    });
    let bs = P2::new(Fe::<L>::exact(bb.x.w()), Fe::exact(bb.y.w()));
    match Paper.g_v_inv(k.m_w, &Paper.h(&bs)) {
        Ok(d) => k.positive_by_value(&d),
        Err(_) => false,
    }
}

/// Decide one box that no point of is within ε of Ω_uw (module docs).
pub(super) fn outside_box<L: LibmModel>(
    k: &Outside,
    b: &PBox,
    st: &mut OutsideStats,
) -> OutsideLeaf {
    // No point of Ω_u (|p| < r_u): nothing to decide.
    if b.r.0 >= k.du.rm.sup() {
        return OutsideLeaf::Done;
    }
    if b.r.0 <= k.d1 {
        if b.r.1 + k.d1 <= ORIGIN_CORE && origin_core::<L>(k, b.r.1 + k.d1) {
            st.by_value += 1;
            return OutsideLeaf::Done;
        }
        return split_or_give_up(b, st);
    }
    // Exact |b − (1,0)|² ≥ 3/4 on the whole box (q ∉ Ω_w at every point).
    let lens_out = principal_pieces(b.ith()).iter().all(|&th| {
        let (rho, al) = (k.du.k * b.ir(), k.du.m6 * th);
        let dq = rho.sqr() - c(2.0) * rho * al.cos() + c(1.0);
        lt(dq, ratio(3, 4)).is_false()
    });
    let mut margin: Vec<P2<Fe<L>>> = Vec::new();
    let mut by_rt = false;
    for a in input_pieces::<L>(b, k.d1) {
        let d = Paper
            .g_v(k.m_u, &a)
            .and_then(|bb| Paper.g_v_inv(k.m_w, &Paper.h(&bb)));
        let ok_d = d
            .as_ref()
            .ok()
            .filter(|d| d.x.err().is_finite() && d.y.err().is_finite());
        if let Some(d) = ok_d {
            if k.positive_by_value(d) {
                continue;
            }
            // A margin is a maximum of box-wise enclosures: taken on small boxes only.
            if lens_out && b.diam() <= F64_BOUND_DIAM {
                margin.push(d.clone());
                continue;
            }
        }
        if k.far_by_roundtrip(b, &a) {
            by_rt = true;
            continue;
        }
        return split_or_give_up(b, st);
    }
    if by_rt {
        st.by_roundtrip += 1;
    }
    if margin.is_empty() {
        st.by_value += (!by_rt) as u64;
    } else {
        st.by_margin += 1;
        // Box by box, every label j (hulling over the boxes first would mix the large |q| of
        // some boxes with the large errors of others).
        let r_w2 = omega_radius::<Fe<L>>(k.m_w, 53).sqr();
        for d in &margin {
            for j in 0..k.m_w as i64 {
                let q = rotate_frac(d, j, k.m_w as i64);
                st.inner = dev_max(st.inner, q.norm2().sub(&r_w2).err());
            }
        }
    }
    OutsideLeaf::Done
}

fn split_or_give_up(b: &PBox, st: &mut OutsideStats) -> OutsideLeaf {
    if b.diam() > OUTSIDE_MIN_DIAM {
        OutsideLeaf::Split
    } else {
        st.unresolved += 1;
        OutsideLeaf::Done
    }
}

/// The result of the pass: the margin `inner` (`None` if a box was left unresolved).
pub(super) fn finish(k: &Outside, st: &OutsideStats, boxes: u64) -> F64Outside {
    // Plus Lip·δ₁: from the exact value at â to the exact value at a (module docs).
    let inner = Some((c(st.inner) + c(k.lip_q) * c(k.d1)).sup());
    F64Outside {
        inner: inner.filter(|x| x.is_finite() && st.unresolved == 0),
        eps: F64_NBHD,
        by_value: st.by_value,
        by_margin: st.by_margin,
        by_roundtrip: st.by_roundtrip,
        unresolved: st.unresolved,
        boxes,
    }
}

/// Is the box in the region of the neighbourhood pass (may meet N_ε, winding 0 certified)?
pub(super) fn winding0_box(du: &Deg, b: &PBox) -> bool {
    principal_pieces(b.ith())
        .iter()
        .all(|p| du.winding0(*p).is_true())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A thin polar box at angle θ, radii [r, r + 1e−15].
    fn thin(th: f64, r: f64) -> PBox {
        PBox {
            th: (th, th),
            r: (r, r + 1e-15),
        }
    }

    /// The neighbourhood test never refuses a box within ε of Ω_uw (radially 0.5·ε beyond the
    /// last point of Ω_uw on a ray), and the ε matters: a planted ε = 0 refuses such boxes (they
    /// lie outside Ω_uw); boxes far from Ω_uw are refused.
    #[test]
    fn cert_f64_rounding_outside_nbhd_test_sound_and_planted_zero_eps_refuses() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(23);
        let (mut checked, mut refused_at_zero) = (0, 0);
        for m in [3u32, 8, 13, 32] {
            let du = Deg::new(m);
            let wmax = 2.0 * std::f64::consts::PI / m as f64;
            for _ in 0..200 {
                let th: f64 = rng.gen_range(-wmax..wmax);
                let inside = |r: f64| member_any(&du, c(th), c(r), Domain::Literal).is_true();
                let r0: f64 = rng.gen_range(0.1..1.0) * du.rm.inf();
                if !inside(r0) {
                    continue;
                }
                // The last point of Ω_uw on the ray (bisection on the closed form).
                let (mut lo, mut hi) = (r0, 1.0);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if inside(mid) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let b = thin(th, lo + 0.5 * F64_NBHD);
                assert!(
                    !meets_nbhd(&du, &b, F64_NBHD).is_false(),
                    "m = {m}: {b:?} is within ε of Ω_uw"
                );
                checked += 1;
                refused_at_zero += meets_nbhd(&du, &b, 0.0).is_false() as u32;
            }
            // Around the origin (|b − (1,0)| ≈ 1 there) and on the far side of the chart.
            for b in [
                PBox {
                    th: (-3.0, 3.0),
                    r: (0.0, 0.01),
                },
                thin(3.0, 0.5),
            ] {
                assert!(meets_nbhd(&du, &b, F64_NBHD).is_false(), "m = {m}: {b:?}");
            }
        }
        assert!(checked > 400, "{checked}");
        assert!(
            refused_at_zero * 2 > checked,
            "{refused_at_zero} of {checked}"
        );
    }
}
