//! Edge provers: P4.2.1 (non-empty), P4.2.3 (inverse) and L4.2.3 (Hausdorff separation).

use super::bnb::{bnb, canon_edge, disk_box, finish, Leaf, Settings, Stats, MP_PREC};
use super::config::ConfigKey;
use super::interval;
use super::interval::{c, iv, member_any, phi_polar, ratio, Deg, Domain};
use super::model::Model;
use super::result::{CertWitness, Outcome, PropertyResult};
use crate::construction::maps::{self, EdgeConfig, Ppm, P2};
use crate::numeric::interval::Interval as I;
use crate::numeric::{Iv, Mp, Scalar};
use crate::report::harness::enclosure_exceeds;
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Edge provers.
// ---------------------------------------------------------------------------------------------

pub(super) fn iv_point(p: [f64; 2]) -> P2<Iv> {
    P2::new(Iv::point(p[0]), Iv::point(p[1]))
}

/// Enclosure (sup) of |g_(w,u)(g_(u,w)(p)) − p| by the generic maps on point intervals.
pub(super) fn roundtrip_dev<S: Scalar>(
    model: &Model,
    e: &EdgeConfig,
    p: &P2<S>,
) -> Result<S, maps::MapError>
where
    Model: Ppm<S>,
{
    let q = model.g_uw_formula(e, p)?;
    let back = model.g_uw_formula(&e.reversed(), &q)?;
    Ok(back.sub(p).norm2().sqrt())
}

/// Rule 1 for enclosures: the image of a point interval is enclosed by finite bounds (an
/// unbounded one is how a NaN or an overflow shows in interval arithmetic: `Iv::point(NaN)`
/// is the entire line).
pub(super) fn finite_p2(q: &P2<Iv>) -> bool {
    [q.x.inf(), q.x.sup(), q.y.inf(), q.y.sup()]
        .iter()
        .all(|v| v.is_finite())
}

/// "≥ lo" for a refuting enclosure, or "not finite" when it is unbounded (NaN).
pub(super) fn at_least(lo: f64) -> String {
    if lo.is_finite() {
        format!("≥ {lo:.3e}")
    } else {
        "not finite (a NaN or an overflow)".into()
    }
}

/// L4.2.1 violated at p (u's chart): p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, but p ∉ Ω_uw. One generic
/// evaluation, used to confirm a witness in f64 and in MPFR.
pub(super) fn inclusion_violated<S: Scalar>(
    model: &Model,
    uw: &EdgeConfig,
    ux: &EdgeConfig,
    xw: &EdgeConfig,
    p: &P2<S>,
) -> bool
where
    Model: Ppm<S>,
{
    model.in_omega_uw_literal(ux, p).is_true()
        && model
            .g_uw_formula(ux, p)
            .map(|q| model.in_omega_uw_literal(xw, &q).is_true())
            .unwrap_or(false)
        && model.in_omega_uw_literal(uw, p).is_false()
}

/// |φ_wu(p) − φ_wx(φ_xu(p))| (L4.2.2) by the model's maps, ∞ where either side is undefined.
pub(super) fn cocycle_gap<S: Scalar>(
    model: &Model,
    uw: &EdgeConfig,
    ux: &EdgeConfig,
    xw: &EdgeConfig,
    p: &P2<S>,
) -> f64
where
    Model: Ppm<S>,
{
    let gap = || -> Option<f64> {
        let l = model.g_uw_formula(uw, p).ok()?;
        let r = model
            .g_uw_formula(xw, &model.g_uw_formula(ux, p).ok()?)
            .ok()?;
        Some(l.dist_f64(&r))
    };
    gap().unwrap_or(f64::INFINITY)
}

/// P4.2.1(cert): Ω_uw ≠ ∅ and Ω_wu ≠ ∅ (Def. 3.4.1(2)), by a certified interior point of each.
pub fn prove_nonempty(m_u: u32, m_w: u32, model: &Model) -> PropertyResult {
    let t0 = Instant::now();
    let mut st = Stats::default();
    let mut witness = None;
    for (a, b) in [(m_u, m_w), (m_w, m_u)] {
        let d = Deg::new(a);
        // The preimage of the lens centre (1/2, 0): θ = 0, ρ = 1/2.
        let r = c(0.5) / d.k;
        let rp = r.mid();
        let t = member_any(&d, c(0.0), c(rp), Domain::Literal);
        st.boxes += 1;
        let e = canon_edge(a, b);
        let f = model.in_omega_uw_literal(&e, &P2::<f64>::new(rp, 0.0));
        if !t.is_true() || !f.is_true() {
            witness = Some(CertWitness {
                point: [rp, 0.0],
                text: format!("p = ({rp:.9}, 0) for edge ({a},{b}): closed form {t:?}, model's literal test (f64) {f:?}"),
                f64_confirms: !f.is_true(),
                mp_confirms: !model.in_omega_uw_literal(&e, &P2::<Mp>::from_f64(rp, 0.0, MP_PREC)).is_true(),
            });
            st.refuted = Some((disk_box(a), String::new()));
        }
    }
    finish(
        ConfigKey::Edge { m_u, m_w },
        "P4.2.1(cert)",
        "Ω_uw ≠ ∅ and Ω_wu ≠ ∅: the point R_(u,w)⁻¹(ρ=1/2 preimage of the lens centre) is certified in Ω_uw (closed form) and accepted by the literal f64 test, both directions".into(),
        st,
        witness,
        t0,
    )
}

/// P4.2.3(cert): φ_uw∘φ_wu = id on Ω_uw (Def. 3.4.1(3b)), exactly, on all of Ω_uw.
///
/// Proof. Let p have principal angle θ (relative to s_u(w), after R_(u,w)) and radius r,
/// b = g_u(R_(u,w)p) = ρe^{iα} (α = m_uθ/6, ρ = k_u r), c = h(b) = 1 − b. On a box where
/// (i) θ lies in one principal piece, (ii) winding(θ) = 0, i.e. |α| < π, and (iii) c_x > 0,
/// every point satisfies: Π(c) = (β, s) with |β| < π/2, so q = φ_wu(p) has principal angle
/// 6β/m_w (|6β/m_w| < π) and radius s/k_w relative to s_w(u); q ∈ Ω_wu (closed form: |β| < π,
/// s < √3/2 since b ∈ D, |c − 1| = |b| < √3/2); g_w∘R_(w,u)(q) = s e^{iβ} = c exactly (the
/// scalings m_w/6·6/m_w and k_w/k_w cancel), h(c) = b, and Π(b) = (α, ρ) because |α| < π, so
/// φ_uw(q) = R_(u,w)⁻¹Π⁻¹(6α/m_u, ρ/k_u) = p. The prover certifies (i)–(iii) by intervals on
/// every box of u's chart that meets Ω_uw (closed form of Def. 4.1.9, module `interval`), so
/// the deviation is exactly 0 on all of Ω_uw: `bound` = 0, no δ. `centre_bound` is the
/// enclosure of |φ_uw∘φ_wu(p) − p| computed by the model's generic maps (`construction::maps`)
/// at every box centre in Ω_uw; it ties the model to the closed form (a planted fault in the
/// model is refuted there) and measures the evaluator's rounding, not the mathematics.
pub fn prove_inverse(m_u: u32, m_w: u32, model: &Model, s: &Settings) -> PropertyResult {
    let t0 = Instant::now();
    let (du, dw) = (Deg::new(m_u), Deg::new(m_w));
    let e = canon_edge(m_u, m_w);
    let st = bnb(disk_box(m_u), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        if member_any(&du, th, r, Domain::Literal).is_false() {
            return Leaf::Proven(None, None);
        }
        let pieces = interval::principal_pieces(th);
        if pieces.len() != 1
            || !du.winding0(pieces[0]).is_true()
            || phi_polar(&du, &dw, pieces[0], r).is_none()
        {
            return Leaf::Split;
        }
        // (i)–(iii) hold on the box: the identity is exact there.
        if b.diam() > s.check_diam {
            return Leaf::Split;
        }
        let (tm, rm) = b.mid();
        let mut cb = None;
        if member_any(&du, c(tm), c(rm), Domain::Literal).is_true() {
            let p = iv_point(b.centre_xy());
            // φ_wu(p) unbounded: the round trip would only see an undecidable point.
            if let Ok(q) = model.g_uw_formula(&e, &p) {
                if !finite_p2(&q) {
                    return Leaf::Refuted("φ_wu(p) is not finite (a NaN or an overflow)".into());
                }
            }
            match roundtrip_dev(model, &e, &p) {
                Ok(dv) if enclosure_exceeds(dv.inf(), dv.sup(), s.fail_tol) => {
                    return Leaf::Refuted(format!("|φ_uw(φ_wu(p)) − p| {}", at_least(dv.inf())))
                }
                Ok(dv) => cb = Some(dv.sup()),
                // A decision the point interval could not make: a smaller box may.
                Err(maps::MapError::Undecided(_)) => return Leaf::Split,
                // The centre is in Ω_uw and the branch conditions hold on the box, so both
                // maps are defined there: an evaluation error refutes (never a silent split
                // that would end as "certified outside δ").
                Err(err) => {
                    return Leaf::Refuted(format!(
                        "the model's maps fail to evaluate at a point of Ω_uw: {err}"
                    ))
                }
            }
        }
        Leaf::Proven(Some(0.0), cb)
    });
    let witness = st.refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        // `!(v <= tol)`: a NaN round trip confirms the refutation too.
        let f = roundtrip_dev(model, &e, &P2::<f64>::new(p[0], p[1]))
            .map(|v| !(v <= s.fail_tol))
            .unwrap_or(true);
        let g = roundtrip_dev(model, &e, &P2::<Mp>::from_f64(p[0], p[1], MP_PREC))
            .map(|v| !(v.to_f64() <= s.fail_tol))
            .unwrap_or(true);
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) ∈ Ω_uw, edge ({m_u},{m_w}), labels 0: {txt}",
                p[0], p[1]
            ),
            f64_confirms: f,
            mp_confirms: g,
        }
    });
    finish(
        ConfigKey::Edge { m_u, m_w },
        "P4.2.3(cert)",
        "φ_uw∘φ_wu = id on all of Ω_uw, exactly: on every box of u's chart meeting Ω_uw the branch conditions (one principal piece, winding 0, c_x > 0) are certified by intervals, and under them the round trip is the identity by exact cancellation (proof at `certify::prove_inverse`); `bound` = 0 is the proven whole-domain bound; `centre_bound` = max interval enclosure of |φ_uw∘φ_wu(p) − p| by the model's generic maps at every box centre in Ω_uw (evaluator rounding; a larger value refutes)".into(),
        st,
        witness,
        t0,
    )
}

/// L4.2.3(cert), Hausdorff condition (4): the inner boundary arc of Ω_uw (the arc of ∂Ω_uw
/// inside Ω_u, i.e. b = g_u∘R_(u,w)(p) on ∂D ∩ int C, c = h(b) = (√3/2)(cos t, sin t),
/// cos t > 1/√3) is mapped by g_(u,w) onto ∂Ω_w. Proven on 256 t-intervals covering the whole
/// open arc |t| < T, T = acos(1/√3), up to its ends (no δ): on every interval the branch
/// conditions c_x > 0 and |6t/m_w| < π hold with a margin (c_x ≥ 1/2 on the arc), so
/// |g_(u,w)(p)| = (√3/2)/k_w = cos(π/m_w) exactly. That the arc lies in Ω_u (|b| < √3/2) is
/// certified by intervals with a margin away from the ends; on the two end intervals, where
/// the margin tends to 0 at the lens corners b = 1/2 ± i/√2, it is the exact identity
/// |b|² = |1 − c|² = 7/4 − √3 cos t, < 3/4 ⇔ cos t > 1/√3 ⇔ |t| < T (points of an end interval
/// with |t| ≥ T are not on the arc). The intervals reach the ends: |b|² ≥ 3/4 is certified at
/// the last endpoint t_end = T⁺ + `end_offset` (T⁺ the upper bound of T's enclosure), i.e.
/// t_end ≥ T; if not (a planted negative offset), the gap is reported as δ. `bound` is the
/// interval enclosure of ||g_(u,w)(p)| − r_w| at the t-box centres via the generic maps, and
/// the separation is the certified margin min(√3/2 − |b|) over the interior intervals.
pub fn prove_hausdorff(m_u: u32, m_w: u32, model: &Model, s: &Settings) -> PropertyResult {
    prove_hausdorff_with(m_u, m_w, model, s, 1e-12)
}

/// [`prove_hausdorff`] with the end of the covered t-range moved by `end_offset` from the
/// arc end (the paper's run: 1e−12 beyond it; a negative offset leaves a gap, never certified).
pub fn prove_hausdorff_with(
    m_u: u32,
    m_w: u32,
    model: &Model,
    s: &Settings,
    end_offset: f64,
) -> PropertyResult {
    let t0 = Instant::now();
    let dw = Deg::new(m_w);
    let e = canon_edge(m_u, m_w);
    let s3h = c(3.0).sqrt() / c(2.0);
    let tarc = (c(1.0) / c(3.0).sqrt()).acos();
    let t_end = tarc.sup() + end_offset;
    // |b|² = 7/4 − √3 cos t at t_end: ≥ 3/4 certifies t_end ≥ T (|b|² increases with |t|).
    let b2_end = ratio(7, 4) - c(3.0).sqrt() * c(t_end).cos();
    let reaches_end = b2_end.inf() >= 0.75;
    let n = 256usize;
    let mut st = Stats::default();
    let mut sep = f64::INFINITY;
    let mut worst: f64 = 0.0;
    let lo = -t_end;
    let h = 2.0 * t_end / n as f64;
    let mut refuted = None;
    for k in 0..n {
        st.boxes += 1;
        let t = iv(lo + h * k as f64, (lo + h * (k + 1) as f64).min(t_end));
        let cx = s3h * t.cos();
        let cy = s3h * t.sin();
        let bx = c(1.0) - cx;
        let by = -cy;
        let bnorm = (bx.sqr() + by.sqr()).sqrt();
        let margin = (s3h - bnorm).inf();
        // An end interval reaches |t| ≥ T⁻: b ∈ C there by the exact identity of the doc.
        let end_box = t.abs().sup() >= tarc.inf();
        let branch =
            cx.inf() > 0.0 && (dw.six_m * t).abs().sup() < I::PI.inf() && (margin > 0.0 || end_box);
        if !branch {
            st.unresolved += 1;
            continue;
        }
        if !end_box {
            sep = sep.min(margin);
        }
        // Centre point p = (g_u∘R)⁻¹(b) via the generic stated inverse, then g_(u,w).
        let tm = t.mid();
        let bpt = P2::<Iv>::new(Iv(c(1.0) - s3h * c(tm).cos()), Iv(-(s3h * c(tm).sin())));
        let p = match model.g_v_inv(m_u, &bpt) {
            Ok(p) => p,
            Err(_) => {
                st.unresolved += 1;
                continue;
            }
        };
        let q = match model.g_uw_formula(&e, &p) {
            Ok(q) => q,
            Err(_) => {
                st.unresolved += 1;
                continue;
            }
        };
        let dev = Iv(q.norm2().0.sqrt() - dw.rm).abs();
        if enclosure_exceeds(dev.inf(), dev.sup(), s.fail_tol) {
            let pf = [p.x.to_f64(), p.y.to_f64()];
            refuted = Some((
                pf,
                format!(
                    "arc point p = ({:.9}, {:.9}): ||g_(u,w)(p)| − cos(π/m_w)| ≥ {:.3e}",
                    pf[0],
                    pf[1],
                    dev.inf()
                ),
            ));
            break;
        }
        worst = worst.max(dev.sup());
    }
    st.bound = Some(worst);
    st.centre = if sep.is_finite() { Some(sep) } else { None };
    let gap = (tarc - c(t_end)).sup();
    let witness = refuted.map(|(pf, txt)| {
        let chk = |v: f64| !((v - dw.rm.mid()).abs() <= s.fail_tol);
        let f = model
            .g_uw_formula(&e, &P2::<f64>::new(pf[0], pf[1]))
            .map(|q| chk(q.norm2().sqrt()))
            .unwrap_or(true);
        let g = model
            .g_uw_formula(&e, &P2::<Mp>::from_f64(pf[0], pf[1], MP_PREC))
            .map(|q| chk(q.norm2().sqrt().to_f64()))
            .unwrap_or(true);
        st.refuted = Some((disk_box(m_u), String::new()));
        CertWitness {
            point: pf,
            text: txt,
            f64_confirms: f,
            mp_confirms: g,
        }
    });
    let mut r = finish(
        ConfigKey::Edge { m_u, m_w },
        "L4.2.3(cert)",
        format!("g_(u,w) maps the whole open inner arc of ∂Ω_uw (|t| < acos(1/√3), up to the lens corners: exact identity |b|² = 7/4 − √3 cos t on the end intervals) onto ∂Ω_w; `bound` = max enclosure of ||g_(u,w)(p)| − r_w| at {n} arc points; `centre_bound` = separation: the arc away from its two end intervals lies ≥ this inside Ω_u's canonical image (|b| ≤ √3/2 − sep)"),
        st,
        witness,
        t0,
    );
    if r.outcome != Outcome::Refuted && r.unresolved == 0 && !reaches_end {
        // The t-intervals stop short of the arc ends: proven outside that gap only.
        r.delta = Some(gap.max(f64::MIN_POSITIVE));
        r.outcome = Outcome::CertifiedOutsideDelta;
    }
    r
}
