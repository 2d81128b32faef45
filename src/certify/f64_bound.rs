//! CERT-f64-rounding: proven bounds on the rounding of the `f64` evaluator (the generic maps
//! of `construction::maps` instantiated at `f64`, which the oracle and `ppm eval-map` run), per
//! edge configuration, on the whole of Ω_uw and for every pair of labels.
//!
//! The same generic code runs on [`Fe`] (exact value and `f64` error, both enclosed) over the
//! polar boxes of u's chart that meet Ω_uw (closed form of Def. 4.1.9, module `interval`):
//! `Paper::g_uw_formula` with the canonical labels, then the label rotations. Labels enter
//! only through R_(u,w) at the start and R_(w,u)⁻¹ at the end (Def. 4.1.8): the first is
//! bounded once per configuration on the disk |p| ≤ 1 for every label i (its `f64` error
//! enters the canonical evaluation as the input error of a = R_(u,w)(p), whose exact value the
//! box encloses), the second is evaluated on every box for every label j.
//!
//! The literal membership test (Def. 4.1.9, `Ppm::in_omega_uw_literal`) decides three signs:
//! |p|² − r_u² (p ∈ Ω_u), |q|² − r_w² with q = g_(w,u)⁻¹(p) (q ∈ Ω_w), and
//! |g_(w,u)(q) − p|² − tol² (the round trip). The first two `f64` errors are bounded on the
//! same boxes by `Fe`. The round trip is bounded stage by stage (module `f64_roundtrip`: each
//! stage's own rounding times the norm of the exact Jacobian of the rest), because `Fe` run
//! through the whole round trip loses the correlation of the errors (the former bound, with the
//! pass-1 errors hulled over all boxes and labels, was 1.50e−11 at M = 8 and 1.77e−9 at M = 32,
//! above the tolerance); the decision is certified exact (`Fe::le` decides only when the `f64`
//! and the exact comparison agree) where that bound allows, with g_v and g_v⁻¹ alone as
//! by-products.

// Bounds are maxima that must keep a NaN (a NaN bound is no bound), as every deviation does.
use super::bnb::{bnb, canon_edge, disk_box, Leaf, PBox, Settings};
use super::f64_outside::{finish, meets_nbhd, outside_box, winding0_box};
use super::f64_outside::{Outside, OutsideLeaf, OutsideStats, F64_NBHD};
use super::f64_roundtrip::{err2, roundtrip_bound, RoundTripBudget, F64_BOUND_DIAM};
use super::interval::{c, iv, sym, Deg};
use super::result::{F64Rounding, RoundTripVerdict};
use crate::construction::maps::Ppm;
use crate::construction::maps::{omega_radius, rotate_frac, roundtrip_tolerance};
use crate::construction::maps::{Paper, P2};
use crate::numeric::interval::Interval as I;
use crate::numeric::rounding::{mag, Glibc, LibmModel, LIBM_ULPS};
use crate::numeric::Fe;
use crate::numeric::Scalar;
use crate::report::dev_max;
use std::time::Instant;

/// max over labels i of the f64 error of R_(u,w)(p) = M_{−2πi/m_u}(p), |p_x|, |p_y| ≤ 1.
fn input_rotation_error<L: LibmModel>(m_u: u32) -> f64 {
    let unit = P2::new(Fe::<L>::exact(iv(-1.0, 1.0)), Fe::exact(iv(-1.0, 1.0)));
    (1..m_u as i64)
        .map(|i| {
            let a = rotate_frac(&unit, -i, m_u as i64);
            dev_max(a.x.err(), a.y.err())
        })
        .fold(0.0, dev_max)
}

/// CERT-f64-rounding for the edge configuration (m_u, m_w) with the libm model of the
/// certificates.
pub fn prove_f64_rounding(m_u: u32, m_w: u32, s: &Settings) -> F64Rounding {
    prove_f64_rounding_with::<Glibc>(m_u, m_w, s)
}

/// A point whose coordinates lie in [−R, R] with the f64 errors `ex`, `ey`: the hull over all
/// boxes, for the label rotations (bounded once per configuration instead of per box).
fn hull_point<L: LibmModel>(rad: f64, ex: I, ey: I) -> P2<Fe<L>> {
    P2::new(Fe::new(iv(-rad, rad), ex), Fe::new(iv(-rad, rad), ey))
}

/// Running hull of the errors and magnitudes of points.
#[derive(Clone, Copy)]
struct ErrHull {
    ex: I,
    ey: I,
    rad: f64,
}

impl ErrHull {
    fn new() -> ErrHull {
        ErrHull {
            ex: c(0.0),
            ey: c(0.0),
            rad: 0.0,
        }
    }
    fn add<L: LibmModel>(&mut self, p: &P2<Fe<L>>) {
        self.ex = self.ex.convex_hull(p.x.e);
        self.ey = self.ey.convex_hull(p.y.e);
        for f in [&p.x, &p.y] {
            self.rad = dev_max(dev_max(self.rad, mag(f.v)), mag(f.w()));
        }
    }
    fn point<L: LibmModel>(&self) -> P2<Fe<L>> {
        hull_point(self.rad, self.ex, self.ey)
    }
}

/// [`prove_f64_rounding`] under the libm accuracy model `L` (a smaller claim gives a smaller
/// bound: `tests/chapter4/cert_f64_rounding.rs`).
pub fn prove_f64_rounding_with<L: LibmModel>(m_u: u32, m_w: u32, s: &Settings) -> F64Rounding {
    prove_f64_rounding_budget::<L>(m_u, m_w, s, &RoundTripBudget::default())
}

/// [`prove_f64_rounding_with`] with the round trip's bisection limits (tests plant small ones:
/// an exhausted budget gives [`RoundTripVerdict::Unresolved`], never `Exact`).
pub fn prove_f64_rounding_budget<L: LibmModel>(
    m_u: u32,
    m_w: u32,
    s: &Settings,
    budget: &RoundTripBudget,
) -> F64Rounding {
    let t0 = Instant::now();
    let du = Deg::new(m_u);
    let e0 = canon_edge(m_u, m_w);
    let mw = m_w as i64;
    let eps_in = input_rotation_error::<L>(m_u);
    let unit = Fe::<L>::exact(iv(-1.0, 1.0));
    let outer = P2::new(unit, unit)
        .norm2()
        .sub(&omega_radius::<Fe<L>>(m_u, 53).sqr())
        .err();
    // Pass 1: d = g_w⁻¹∘h∘g_u(a) on every box meeting the ε-neighbourhood of Ω_uw (canonical
    // labels: both rotations are the identity), a = R_(u,w)(p) with the input rotation's error;
    // the other boxes of Ω_u go to the pass off the neighbourhood (module `f64_outside`).
    let mut leaves: Vec<(PBox, P2<Fe<L>>)> = Vec::new();
    let mut dh = ErrHull::new();
    let ok = Outside::new::<L>(m_u, m_w);
    let mut ost = OutsideStats::default();
    let mut root = disk_box(m_u);
    root.r.1 = (c(root.r.1) + c(F64_NBHD)).sup();
    let st = bnb(root, s.max_depth, s.budget, |b| {
        if meets_nbhd(&du, b, F64_NBHD).is_false() {
            return match outside_box::<L>(&ok, b, &mut ost) {
                OutsideLeaf::Done => Leaf::Proven(None, None),
                OutsideLeaf::Split => Leaf::Split,
            };
        }
        // Leaves have winding 0 certified: their points off Ω_uw are "out" by a sign alone.
        if b.diam() > F64_BOUND_DIAM || !winding0_box(&du, b) {
            return Leaf::Split;
        }
        let (th, r) = (b.ith(), b.ir());
        let a = P2::new(
            Fe::<L>::new(r * th.cos(), sym(eps_in)),
            Fe::new(r * th.sin(), sym(eps_in)),
        );
        match Paper.g_uw_formula(&e0, &a) {
            Ok(d) if d.x.err().is_finite() && d.y.err().is_finite() => {
                dh.add(&d);
                leaves.push((*b, d));
                Leaf::Proven(Some(0.0), None)
            }
            _ => Leaf::Split,
        }
    });
    let resolved = !leaves.is_empty() && st.refuted.is_none();
    // φ_wu = R_(w,u)⁻¹(d) for every label j.
    let r_w2 = omega_radius::<Fe<L>>(m_w, 53).sqr();
    let (mut phi, mut inner) = (0.0f64, 0.0f64);
    for j in 0..mw {
        let q = rotate_frac(&dh.point::<L>(), j, mw);
        phi = dev_max(phi, err2(&q));
        inner = dev_max(inner, q.norm2().sub(&r_w2).err());
    }
    // Pass 2: the round trip, stage by stage on the leaves (module `f64_roundtrip`).
    let roots: Vec<PBox> = leaves.iter().map(|(b, _)| *b).collect();
    let rt = roundtrip_bound::<L>(m_u, m_w, &roots, budget);
    let tol = Fe::<L>::from_f64(roundtrip_tolerance(&e0, 1.0), 53).mul(&unit.unit_roundoff());
    let bounded = |x: f64| (resolved && x.is_finite()).then_some(x);
    F64Rounding {
        phi: bounded(phi),
        outer,
        inner: bounded(inner),
        roundtrip: rt.bound.and_then(bounded),
        roundtrip_tol: tol.to_f64(),
        roundtrip_exact: resolved
            && st.unresolved == 0
            && rt.verdict == Some(RoundTripVerdict::Exact),
        roundtrip_verdict: rt.verdict,
        roundtrip_boxes: Some(rt.boxes),
        roundtrip_unresolved: Some(rt.unresolved),
        g_v: rt.g_v.and_then(bounded),
        g_v_inv: rt.g_v_inv.and_then(bounded),
        boxes: st.boxes,
        unresolved: st.unresolved,
        delta: (st.unresolved > 0).then_some(st.delta),
        libm_ulps: L::LIBM_ULPS,
        millis: t0.elapsed().as_millis() as u64,
        nbhd: Some(F64_NBHD),
        outside: Some(finish(&ok, &ost, st.boxes)),
    }
}

/// The statement of CERT-f64-rounding (certificate summary).
pub fn f64_rounding_statement() -> String {
    format!(
        "CERT-f64-rounding: per edge configuration (m_u, m_w), for every label pair and every p in a polar box of u's chart that may meet the closed ε-neighbourhood of Ω_uw (ε = `nbhd` = {F64_NBHD:e}, ≥ every `phi`; the boxes cover that neighbourhood; diameter ≤ {F64_BOUND_DIAM}, winding 0 certified): |φ_wu(p) evaluated in f64 by the generic maps (`construction::maps`, what the oracle runs) − φ_wu(p)| ≤ `phi`; the literal membership test (Def. 4.1.9) decides p ∈ Ω_u exactly unless ||p|² − r_u²| ≤ `outer`, q ∈ Ω_w exactly unless ||q|² − r_w²| ≤ `inner` (q = g_(w,u)⁻¹(p)), the f64 round-trip point g_(w,u)(q) errs by ≤ `roundtrip` (stage-wise: each stage's rounding, enclosed alone, times the norm of the exact Jacobian of the rest of the chain; boxes bisected within a budget, what is left counted in `roundtrip_unresolved`), and where `roundtrip_exact` holds (that bound, rounded through the comparison, below the literal test's tolerance tol on every box) the round-trip decision is exact too; g_u alone errs by ≤ `g_v` at the f64 points R_(u,w)(p), g_w⁻¹ alone by ≤ `g_v_inv` at the f64 points h(g_u(R_(u,w)(p))) (round trip, g_v, g_v_inv: on the boxes meeting Ω_uw). On the rest of Ω_u (no point within ε of Ω_uw, exact answer 'out'; `outside`) the f64 literal test answers 'out' at every f64 point unless ||p|² − r_u²| ≤ `outer` or |q|² − r_w² ∈ [0, `outside.inner`]: box by box, either the f64 |q|² − r_w² is certified > 0 (`by_value`, with a closed-form core around the origin), or the exact |q|² ≥ r_w² and its f64 error is ≤ `outside.inner` (`by_margin`), or the winding is ≠ 0 and the f64 round-trip point is certified ≥ 2·tol from p (`by_roundtrip`); `outside.unresolved` boxes left (then no `outside.inner`). Model: IEEE-754 binary64, round to nearest, + − × ÷ √ correctly rounded, {LIBM_ULPS} ulp for libm sin, cos, atan2 ({})",
        crate::numeric::rounding::LIBM_ASSUMPTION
    )
}
