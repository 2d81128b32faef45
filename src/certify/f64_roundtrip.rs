//! CERT-f64-rounding, the round trip of the literal membership test (Def. 4.1.9): a proven
//! bound on |ĝ_(w,u)(q̂) − p|, q̂ = ĝ_(w,u)⁻¹(p) (hats: the `f64` evaluation of the generic
//! maps of `construction::maps`), on every box meeting Ω_uw, by stage-wise error propagation
//! through the exact Jacobians instead of through the enclosures (which lose the correlation
//! of the errors: the former bound, running `Fe` through the whole round trip, was 1.50e−11 at
//! M = 8 and 1.77e−9 at M = 32; the worst seeded point used 1.3e−4 of it).
//!
//! Where the former bound was lost (measured): its return trip started from the pass-1 errors
//! hulled over all boxes and labels (box by box the same chain gave ≤ 3.4e−13 at M = 8, 45×
//! less), and each operation adds the enclosed errors' magnitudes, so atan2's propagation
//! (|e_x| + |e_y|)/r_min, multiplied by r_max·m/6 back in Π⁻¹, blows up on wide angular boxes
//! near the chart origin at high degree (9.8e−12 on one box of (32, 3)). The stage-wise bound
//! below is 8.69e−14 at M = 8 (worst (3, 3)) and 3.83e−13 at M = 32.
//!
//! ## The argument
//! The round trip is a chain of ten stages Φ_1..Φ_10, each a map R² → R² whose `f64` code
//! ends in a point of two `f64` numbers (`Ppm::g_uw_inv` then `Ppm::g_uw_formula` of the
//! reversed edge): R_(u,w), g_u, h, g_w⁻¹, R_(w,u)⁻¹ (this is q̂), R_(w,u), g_w, h, g_u⁻¹,
//! R_(u,w)⁻¹. With x̂_0 = p, x̂_s = Φ̂_s(x̂_(s−1)) and the exact tails T_s = Φ_10 ∘ … ∘ Φ_(s+1)
//! (T_10 = id), telescoping gives exactly
//!   x̂_10 − Φ(p) = Σ_s [T_s(Φ̂_s(y_s)) − T_s(Φ_s(y_s))],  y_s = x̂_(s−1),
//! and Φ(p) = p for p ∈ Ω_uw on a box with winding 0 (module `interval`). Each term is
//! bounded by the mean value theorem along the segment from Φ_s(y_s) to Φ̂_s(y_s):
//!   |term_s| ≤ N_s · δ_s,  δ_s = max |Φ̂_s(y) − Φ_s(y)| over the f64 points y the stage can
//!   receive (`Fe` on that stage alone, with an exact input enclosing x̂_(s−1)),
//! where N_s bounds the operator 2-norm of the tail's Jacobian on the segment. The Jacobians
//! have point-independent norms: rotations and h are isometries, and g_v = Π⁻¹∘f_v∘Π has
//! J = (rotation)·diag(c, c·k)·(rotation) with c = cos(π/6)/cos(π/m), k = m/6 in the radial and
//! angular frames, so ‖J‖ = c·max(1, m/6), and ‖J(g_v⁻¹)‖ = max(1, 6/m)/c; N_s is the product
//! over the tail. The mean value theorem needs the tail C¹ along each segment: every g-stage
//! of the tail must see the segment's image off Π's cut (the closed ray y = 0, x ≤ 0) and off
//! the origin. That is checked by interval images (`Iv`) of the hull of all segments, pushed
//! through the exact stages (one set per stage, [`SegmentSets`]): `Iv`'s Π decides only when
//! the whole set is in x > 0 or in y > 0 or in y < 0.
//!
//! Labels: the rotation stages' δ are bounded once per configuration for every label on the
//! square [−R, R]², R = [`ROT_RAD`] (every state they receive is checked to lie in it); R_(w,u) followed by R_(w,u)⁻¹ is exactly the
//! identity, so the sets of stages 6..9 are those of the canonical labels widened by δ_5 + δ_6.
//! The decision: f64 computes |x̂_10 − p|² with each coordinate at most the bound, then
//! compares it with tol² (`Fe::le` decides only where f64 and exact agree; the exact value is
//! 0 < tol²).
//!
//! Boxes where a check fails or the bound is above what the decision allows are bisected,
//! within a box budget; what is left is counted and the verdict is [`RoundTripVerdict::Unresolved`]
//! (or `AboveTolerance` when every box was evaluated but some bound stayed above), never
//! `Exact`.

use super::bnb::{bnb, canon_edge, disk_box, Leaf, PBox, Settings};
use super::interval;
use super::interval::{c, iv, member_any, Deg, Domain};
use super::result::RoundTripVerdict;
use crate::construction::maps::Ppm;
use crate::construction::maps::{rotate_frac, roundtrip_tolerance, MapError};
use crate::construction::maps::{Paper, P2};
use crate::numeric::rounding::{mag, LibmModel};
use crate::numeric::Fe;
use crate::numeric::Iv;
use crate::numeric::Scalar;
use crate::report::dev_max;

/// Boxes are bounded once their diameter is at most this (the bound is a maximum of box-wise
/// enclosures, which loosen with the box).
pub const F64_BOUND_DIAM: f64 = 0.05;

/// Limits of the round-trip bisection.
#[derive(Debug, Clone, Copy)]
pub struct RoundTripBudget {
    /// Boxes evaluated at most (per configuration).
    pub boxes: u64,
    /// Boxes are not bisected below this diameter.
    pub min_diam: f64,
    /// Scale of the largest bound accepted as exact: 1 for the certificates; tests plant a
    /// smaller one to force bisection (so that the budget runs out).
    pub accept_scale: f64,
}

impl Default for RoundTripBudget {
    fn default() -> Self {
        RoundTripBudget {
            boxes: 200_000,
            min_diam: 1e-4,
            accept_scale: 1.0,
        }
    }
}

/// The rotation stages are bounded on [−R, R]² with R = this (every state they receive is
/// checked to lie there).
pub const ROT_RAD: f64 = 1.25;

/// The round-trip part of CERT-f64-rounding for one configuration.
#[derive(Debug, Clone, Default)]
pub struct RoundTripBound {
    /// max over the boxes of the bound on |x̂_10 − p| (`None`: no box bounded).
    pub bound: Option<f64>,
    /// max of δ_2 (g_u at the f64 points a = R_(u,w)(p)) over the boxes.
    pub g_v: Option<f64>,
    /// max of δ_4 (g_w⁻¹ at the f64 points h(g_u(a))) over the boxes.
    pub g_v_inv: Option<f64>,
    /// The verdict (`None`: nothing was evaluated).
    pub verdict: Option<RoundTripVerdict>,
    /// Boxes evaluated.
    pub boxes: u64,
    /// Boxes left unbounded.
    pub unresolved: u64,
    /// Boxes bounded above the decision's allowance at the minimum diameter.
    pub above: u64,
    /// max over the boxes of δ_s, s = 1..10 (index s − 1): where the bound comes from.
    pub stage_err: [f64; 10],
    /// The tail norms N_s (index s − 1).
    pub tail_norm: [f64; 10],
    /// The largest bound the decision accepts as exact.
    pub accept: f64,
}

/// Per-configuration constants of the bound.
struct Consts {
    m_u: u32,
    m_w: u32,
    /// Tail norms N_1..N_10 (index s − 1).
    n: [f64; 10],
    /// δ of the rotation stages 1, 5, 6, 10 (all labels, |x| ≤ ROT_RAD).
    rot: [f64; 4],
    /// The largest bound the decision accepts (times `accept_scale`).
    accept: f64,
}

/// Euclidean f64 error of a point (sup).
pub(super) fn err2<L: LibmModel>(p: &P2<Fe<L>>) -> f64 {
    let (x, y) = (c(p.x.err()), c(p.y.err()));
    (x.sqr() + y.sqr()).sqrt().sup()
}

/// max over labels k of the Euclidean f64 error of M_{2π·sign·k/m} on [−R, R]².
pub(super) fn rotation_error<L: LibmModel>(m: u32, sign: i64) -> f64 {
    rotation_error_on::<L>(m, sign, ROT_RAD)
}

/// [`rotation_error`] on [−rad, rad]² (label 0 is the identity: exact, not evaluated).
pub(super) fn rotation_error_on<L: LibmModel>(m: u32, sign: i64, rad: f64) -> f64 {
    let s = Fe::<L>::exact(iv(-rad, rad));
    let p = P2::new(s, s);
    (1..m as i64)
        .map(|k| err2(&rotate_frac(&p, sign * k, m as i64)))
        .fold(0.0, dev_max)
}

/// Does f64 decide |x̂_10 − p|² ≤ tol² like the exact comparison (0 ≤ tol²) when each
/// coordinate of x̂_10 − p is at most `e`? The subtraction rounds once more.
fn decides_close<L: LibmModel>(e: f64, tol2: &Fe<L>) -> bool {
    let d = Fe::<L>::new(c(0.0), iv(-e, e) + iv(-e, e) * c(1.2e-16));
    P2::new(d, d).norm2().le(tol2).is_true()
}

impl Consts {
    fn new<L: LibmModel>(m_u: u32, m_w: u32, scale: f64) -> Consts {
        let (du, dw) = (Deg::new(m_u), Deg::new(m_w));
        let one = c(1.0);
        let lg = |d: &Deg| (d.k * d.m6.max(one)).sup();
        let lgi = |d: &Deg| (d.six_m.max(one) / d.k).sup();
        let up = |a: f64, b: f64| (c(a) * c(b)).sup();
        let mut n = [1.0; 10];
        n[7] = lgi(&du); // tail of stage 8: g_u⁻¹, R_(u,w)⁻¹
        n[6] = n[7];
        n[5] = up(lg(&dw), n[6]);
        n[4] = n[5];
        n[3] = n[4];
        n[2] = up(lgi(&dw), n[3]);
        n[1] = n[2];
        n[0] = up(lg(&du), n[1]);
        let rot = [
            rotation_error::<L>(m_u, -1),
            rotation_error::<L>(m_w, 1),
            rotation_error::<L>(m_w, -1),
            rotation_error::<L>(m_u, 1),
        ];
        let tol = Fe::<L>::from_f64(roundtrip_tolerance(&canon_edge(m_u, m_w), 1.0), 53)
            .mul(&Fe::<L>::exact(c(1.0)).unit_roundoff());
        let tol2 = tol.sqr();
        // The largest accepted bound: bisect on f64 values (decides_close is monotone in e).
        let (mut lo, mut hi) = (0.0f64, tol.v.sup());
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if decides_close(mid, &tol2) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Consts {
            m_u,
            m_w,
            n,
            rot,
            accept: if decides_close(lo, &tol2) {
                lo * scale
            } else {
                0.0
            },
        }
    }
}

/// A point of exact f64 inputs anywhere in the f64 enclosure of `p` (the next stage's input).
fn f64_points<L: LibmModel>(p: &P2<Fe<L>>) -> P2<Fe<L>> {
    P2::new(Fe::exact(p.x.w()), Fe::exact(p.y.w()))
}

/// The hull of exact and f64 values (contains every segment from Φ_s(y) to Φ̂_s(y)).
fn seg_hull<L: LibmModel>(p: &P2<Fe<L>>) -> P2<Iv> {
    P2::new(
        Iv(p.x.v.convex_hull(p.x.w())),
        Iv(p.y.v.convex_hull(p.y.w())),
    )
}

fn hull(a: &P2<Iv>, b: &P2<Iv>) -> P2<Iv> {
    P2::new(Iv(a.x.0.convex_hull(b.x.0)), Iv(a.y.0.convex_hull(b.y.0)))
}

fn widen<L: LibmModel>(p: &P2<Fe<L>>, e: f64) -> P2<Fe<L>> {
    P2::new(
        Fe::exact(p.x.w() + iv(-e, e)),
        Fe::exact(p.y.w() + iv(-e, e)),
    )
}

fn radius_ok<L: LibmModel>(p: &P2<Fe<L>>) -> bool {
    dev_max(mag(p.x.w()), mag(p.y.w())) <= ROT_RAD
}

/// The interval images of all segments of the stages so far (the mean value theorem's
/// regularity check, module docs): one set per stage.
struct SegmentSets(P2<Iv>);

impl SegmentSets {
    /// Push the set through the g-type stage `stage` (Π must decide on it), then add the
    /// segments of that stage.
    fn through(
        &mut self,
        stage: impl Fn(&P2<Iv>) -> Result<P2<Iv>, MapError>,
        own: P2<Iv>,
    ) -> bool {
        match stage(&self.0) {
            Ok(img) => {
                self.0 = hull(&img, &own);
                true
            }
            Err(_) => false,
        }
    }
}

/// Per-box result: the bound and the stage errors δ_s.
struct BoxBound {
    e: f64,
    d: [f64; 10],
}

/// Evaluate the bound on one box (module docs); `None` when a check fails.
fn box_bound<L: LibmModel>(k: &Consts, b: &PBox) -> Option<BoxBound> {
    let (th, r) = (b.ith(), b.ir());
    let pieces = interval::principal_pieces(th);
    if pieces.len() != 1 || !Deg::new(k.m_u).winding0(pieces[0]).is_true() {
        return None;
    }
    let (ax, ay) = (r * th.cos(), r * th.sin());
    if dev_max(mag(ax), mag(ay)) > ROT_RAD {
        return None;
    }
    let fin = |x: f64| x.is_finite().then_some(x);
    let [d1, d5, d6, d10] = k.rot;
    // Stage 1: â = R_(u,w)(p) in the box (exactly) plus at most δ_1.
    let a = P2::new(
        Fe::<L>::exact(ax + iv(-d1, d1)),
        Fe::exact(ay + iv(-d1, d1)),
    );
    let mut segs = SegmentSets(seg_hull(&a));
    let s2 = Paper.g_v(k.m_u, &a).ok()?;
    let d2 = fin(err2(&s2))?;
    if !segs.through(|p| Paper.g_v(k.m_u, p), seg_hull(&s2)) {
        return None;
    }
    let s3 = Paper.h(&f64_points(&s2));
    let d3 = fin(err2(&s3))?;
    segs.0 = hull(&Paper.h(&segs.0), &seg_hull(&s3));
    let s4 = Paper.g_v_inv(k.m_w, &f64_points(&s3)).ok()?;
    let d4 = fin(err2(&s4))?;
    if !segs.through(|p| Paper.g_v_inv(k.m_w, p), seg_hull(&s4)) || !radius_ok(&s4) {
        return None;
    }
    // Stages 5, 6: R_(w,u)⁻¹ then R_(w,u), exactly the identity; in canonical coordinates the
    // f64 state and the segments move by at most δ_5 + δ_6.
    let x6 = widen(&f64_points(&s4), d5 + d6);
    if !radius_ok(&widen(&f64_points(&s4), d5)) {
        return None;
    }
    segs.0 = hull(&segs.0, &seg_hull(&x6));
    let s7 = Paper.g_v(k.m_w, &x6).ok()?;
    let d7 = fin(err2(&s7))?;
    if !segs.through(|p| Paper.g_v(k.m_w, p), seg_hull(&s7)) {
        return None;
    }
    let s8 = Paper.h(&f64_points(&s7));
    let d8 = fin(err2(&s8))?;
    segs.0 = hull(&Paper.h(&segs.0), &seg_hull(&s8));
    let s9 = Paper.g_v_inv(k.m_u, &f64_points(&s8)).ok()?;
    let d9 = fin(err2(&s9))?;
    // After stage 9 only R_(u,w)⁻¹ follows: no Π, nothing more to check.
    if !segs.through(|p| Paper.g_v_inv(k.m_u, p), seg_hull(&s9)) || !radius_ok(&s9) {
        return None;
    }
    let d = [d1, d2, d3, d4, d5, d6, d7, d8, d9, d10];
    let e = d
        .iter()
        .zip(k.n.iter())
        .fold(c(0.0), |acc, (&di, &ni)| acc + c(di) * c(ni))
        .sup();
    fin(e).map(|e| BoxBound { e, d })
}

/// The boxes of u's chart meeting Ω_uw at diameter ≤ [`F64_BOUND_DIAM`] (the φ pass's
/// leaves without its evaluation), and those left at the depth limit or the budget.
fn cover(m_u: u32, s: &Settings) -> (Vec<PBox>, u64) {
    let du = Deg::new(m_u);
    let mut v = Vec::new();
    let st = bnb(disk_box(m_u), s.max_depth, s.budget, |b| {
        if member_any(&du, b.ith(), b.ir(), Domain::Literal).is_false() {
            return Leaf::Proven(None, None);
        }
        if b.diam() > F64_BOUND_DIAM {
            return Leaf::Split;
        }
        v.push(*b);
        Leaf::Proven(Some(0.0), None)
    });
    (v, st.unresolved)
}

/// [`roundtrip_bound`] on the whole of Ω_uw for the libm model `L` (the stage errors and
/// norms it reports are what tests and docs quote; the certificate runs the same bound on the
/// φ pass's leaves).
pub fn roundtrip_bound_on_omega<L: LibmModel>(
    m_u: u32,
    m_w: u32,
    s: &Settings,
    budget: &RoundTripBudget,
) -> RoundTripBound {
    let (roots, left) = cover(m_u, s);
    let mut rt = roundtrip_bound::<L>(m_u, m_w, &roots, budget);
    if left > 0 {
        rt.unresolved += left;
        rt.verdict = Some(RoundTripVerdict::Unresolved);
    }
    rt
}

/// The round-trip bound on the boxes `roots` (the leaves of the φ pass, which cover the
/// boxes meeting Ω_uw), bisecting as the module docs say.
pub(super) fn roundtrip_bound<L: LibmModel>(
    m_u: u32,
    m_w: u32,
    roots: &[PBox],
    budget: &RoundTripBudget,
) -> RoundTripBound {
    let k = Consts::new::<L>(m_u, m_w, budget.accept_scale);
    let du = Deg::new(m_u);
    let mut out = RoundTripBound {
        tail_norm: k.n,
        accept: k.accept,
        ..RoundTripBound::default()
    };
    let mut stack: Vec<PBox> = roots.iter().rev().copied().collect();
    let opt = |a: Option<f64>, x: f64| Some(a.map_or(x, |y| dev_max(y, x)));
    while let Some(b) = stack.pop() {
        if out.boxes >= budget.boxes {
            out.unresolved += 1 + stack.len() as u64;
            break;
        }
        out.boxes += 1;
        if member_any(&du, b.ith(), b.ir(), Domain::Literal).is_false() {
            continue;
        }
        let bb = box_bound::<L>(&k, &b);
        let ok = bb.as_ref().is_some_and(|x| x.e <= k.accept);
        if !ok && b.diam() > budget.min_diam {
            let [l, h] = b.split();
            stack.push(h);
            stack.push(l);
            continue;
        }
        match bb {
            Some(x) => {
                out.bound = opt(out.bound, x.e);
                out.g_v = opt(out.g_v, x.d[1]);
                out.g_v_inv = opt(out.g_v_inv, x.d[3]);
                for (m, d) in out.stage_err.iter_mut().zip(x.d) {
                    *m = dev_max(*m, d);
                }
                out.above += (!ok) as u64;
            }
            None => out.unresolved += 1,
        }
    }
    out.verdict = Some(if out.unresolved > 0 || out.bound.is_none() {
        RoundTripVerdict::Unresolved
    } else if out.above > 0 {
        RoundTripVerdict::AboveTolerance
    } else {
        RoundTripVerdict::Exact
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construction::maps::{g_v_inv_jacobian, g_v_jacobian, Jac};
    use crate::numeric::rounding::Glibc;

    /// The 2-norm of a 2×2 matrix (largest singular value).
    fn norm2(j: &Jac<f64>) -> f64 {
        let [[a, b], [c2, d]] = *j;
        let s = a * a + b * b + c2 * c2 + d * d;
        let det = a * d - b * c2;
        (0.5 * (s + (s * s - 4.0 * det * det).max(0.0).sqrt())).sqrt()
    }

    fn leaves(m_u: u32) -> Vec<PBox> {
        cover(m_u, &Settings::default()).0
    }

    /// The tail norms rest on ‖J(g_v)‖ = c·max(1, m/6) and ‖J(g_v⁻¹)‖ = max(1, 6/m)/c at
    /// every point off the origin: checked against the analytic Jacobians of
    /// `construction::maps` (bounded everywhere, attained somewhere).
    #[test]
    fn cert_f64_rounding_roundtrip_tail_norms_match_the_jacobians() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(5);
        for m in [3u32, 4, 5, 6, 7, 11, 32] {
            let k = Consts::new::<Glibc>(m, m, 1.0);
            // N_8 = ‖g_u⁻¹‖, N_6 / N_8 = ‖g_w‖ (here u = w).
            let (li, lg) = (k.n[7], k.n[5] / k.n[7]);
            let (mut wi, mut wg): (f64, f64) = (0.0, 0.0);
            for _ in 0..200 {
                let (t, r): (f64, f64) = (rng.gen_range(-3.1..3.1), rng.gen_range(0.05..1.0));
                let p = P2::new(r * t.cos(), r * t.sin());
                let (jg, ji) = (
                    g_v_jacobian(m, &p).expect("off the origin"),
                    g_v_inv_jacobian(m, &p).expect("off the origin"),
                );
                wg = wg.max(norm2(&jg));
                wi = wi.max(norm2(&ji));
            }
            assert!(
                wg <= lg * (1.0 + 1e-9) && wg >= lg * (1.0 - 1e-9),
                "m={m}: {wg} vs {lg}"
            );
            assert!(
                wi <= li * (1.0 + 1e-9) && wi >= li * (1.0 - 1e-9),
                "m={m}: {wi} vs {li}"
            );
        }
    }

    #[test]
    fn cert_f64_rounding_roundtrip_exact_where_the_enclosure_chain_was_not() {
        // (3, 3): the former bound (Fe through the whole round trip) was above the tolerance
        // even box by box (3.4e−13 > 3.2e−13 accepted); the stage-wise bound is below.
        let s = Settings::default();
        let rt = roundtrip_bound_on_omega::<Glibc>(3, 3, &s, &RoundTripBudget::default());
        assert_eq!(rt.verdict, Some(RoundTripVerdict::Exact), "{rt:?}");
        let b = rt.bound.expect("bounded");
        assert!(b < rt.accept && b > 1e-15, "{rt:?}");
        assert!(rt.g_v.is_some_and(|g| g < 1e-14) && rt.g_v_inv.is_some_and(|g| g < 1e-14));
    }

    #[test]
    fn cert_f64_rounding_roundtrip_budget_exhausted_is_unresolved_never_exact() {
        let roots = leaves(4);
        // Too few boxes for the leaves.
        let small = RoundTripBudget {
            boxes: 10,
            ..RoundTripBudget::default()
        };
        let rt = roundtrip_bound::<Glibc>(4, 7, &roots, &small);
        assert_eq!(rt.verdict, Some(RoundTripVerdict::Unresolved), "{rt:?}");
        assert!(rt.unresolved > 0);
        // A planted allowance no box meets: bisection runs until the budget is spent.
        let planted = RoundTripBudget {
            boxes: 3 * roots.len() as u64,
            accept_scale: 1e-6,
            ..RoundTripBudget::default()
        };
        let rt = roundtrip_bound::<Glibc>(4, 7, &roots, &planted);
        assert_eq!(rt.verdict, Some(RoundTripVerdict::Unresolved), "{rt:?}");
        // The same allowance with room to reach the minimum diameter: above, not exact.
        let coarse = RoundTripBudget {
            min_diam: 0.04,
            accept_scale: 1e-6,
            ..RoundTripBudget::default()
        };
        let rt = roundtrip_bound::<Glibc>(4, 7, &roots, &coarse);
        assert_eq!(rt.verdict, Some(RoundTripVerdict::AboveTolerance), "{rt:?}");
    }
}
