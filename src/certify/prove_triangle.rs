//! Triangle provers: L4.2.1 and L4.2.2 (the cocycle condition).

use super::bnb::{bnb, disk_box, omax, Exact, Leaf, PBox, Settings, MP_PREC};
use super::config::ConfigKey;
use super::interval;
use super::interval::{c, member, member_any, phi_polar, two_pi_frac, Deg, Domain};
use super::model::Model;
use super::prove_edge::{at_least, cocycle_gap, finite_p2, inclusion_violated, iv_point};
use super::result::{CertWitness, Outcome, PropertyResult};
use crate::construction::maps::Ppm;
use crate::construction::maps::P2;
use crate::numeric::interval::Interval as I;
use crate::numeric::Scalar;
use crate::numeric::{Iv, Mp, Trit};
use crate::report::harness::enclosure_exceeds;
use std::time::Instant;

// ---------------------------------------------------------------------------------------------
// Triangle provers.
// ---------------------------------------------------------------------------------------------

/// L4.2.1(cert) and L4.2.2(cert) for a triangle configuration, exactly and on the whole set.
///
/// Notation: for p in u's chart, θ_x and θ_w are its principal angles relative to s_u(x) and
/// s_u(w), r its radius, b = k_u r e^{iα} with α = m_uθ_x/6 (so b = g_u∘R_(u,x)(p)), and
/// c = h(b) = 1 − b. C, D are the open disks of radius √3/2 about 0 and 1 (the lens E = C ∩ D,
/// Sec. 4.1). By the closed form of Def. 4.1.9 (module `interval`), p ∈ Ω_ux ⇔ 0 < r < r_u,
/// winding(θ_x) = 0, b ∈ D (r < r_u ⇔ b ∈ C).
///
/// On a box where θ_x is one principal piece with winding 0 and c_x > 0 (so Π(c) = (β, s),
/// |β| < π/2), q = φ_xu(p) has principal angle 6β/m_x relative to s_x(u) (|6β/m_x| < π
/// certified) and radius s/k_x. If its angle θ' relative to s_x(w) is one principal piece with
/// wrap integer k' (θ' = 6β/m_x + 2π(x_u − x_w)/m_x − 2πk'), then m_xθ'/6 = β + πn_x/3 with
/// the *integer* n_x = (x_u − x_w) − m_x k', so g_x∘R_(x,w)(q) = e^{iπn_x/3}c exactly and (with
/// winding(θ') = 0 certified; if it is certified false, q ∉ Ω_xw)
///   q ∈ Ω_xw ⇔ b ∈ D ∧ |e^{iπn_x/3}(1 − b) − 1| < √3/2 ⇔ b ∈ D ∧ b ∈ disk(1 − e^{−iπn_x/3}).
/// * n_x ≡ 2, 3, 4 (mod 6): |1 − e^{−iπn_x/3}| = 2|sin(πn_x/6)| ≥ √3, so this disk and C
///   are disjoint: no point of the box is in Ω_ux ∩ φ_xu⁻¹(Ω_xw) (for m_x = 3 this is the
///   wrapped branch, tangent to C at one point: why bisection alone cannot close it).
/// * n_x ≡ ±1: 1 − e^{∓iπ/3} = e^{±iπ/3}. If θ_w is one principal piece with wrap integer k_w,
///   m_uθ_w/6 = α + πn_u/3 with n_u = (u_x − u_w) + m_u(k_x − k_w), so g_u∘R_(u,w)(p) =
///   e^{iπn_u/3}b and (winding(θ_w) = 0 certified) p ∈ Ω_uw ⇔ 0 < r < r_u ∧
///   b ∈ disk(e^{−iπn_u/3}). With n_u ≡ −n_x (mod 6) the two disks coincide:
///   Ω_ux ∩ φ_xu⁻¹(Ω_xw) = Ω_ux ∩ Ω_uw = {b ∈ C ∩ D ∩ G} on the box (App. A.1: the inclusion is
///   an *equality*, which is why direct bisection of the two memberships never separates them).
///   Cocycle: with c_w = h(e^{iγ}b), γ = ±π/3 = πn_u/3, and c'' = h(e^{−iγ}c) both in the right
///   half-plane (certified), c'' = 1 − e^{−iγ} + e^{−iγ}b = e^{iγ}c_w exactly
///   ((h∘M_{−π/3})³ = id), so |c''| = |c_w|, arg c'' = arg c_w + γ (both in (−π/2, π/2)),
///   and with s_w(u) − s_w(x) ≡ ±1 matching the sign of γ (integer check) φ_wx(φ_xu(p)) =
///   φ_wu(p) exactly.
///
/// The branch and bound covers u's whole chart: a box is done when the closed form proves it
/// disjoint from Ω_ux ∩ φ_xu⁻¹(Ω_xw), or when the case analysis above applies to the whole box
/// (the branch conditions hold with a margin on the closure of the set, so no box is left
/// unresolved and there is no δ). A box where the closed form proves p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw
/// but p ∉ Ω_uw refutes. Proven boxes are split down to `check_diam`, and at every centre in
/// the set the model's generic maps (`construction::maps`, on point intervals) are checked
/// against the closed form: its literal membership tests must all say "in" (if they show
/// p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, p ∉ Ω_uw the inclusion is refuted at that point; any other
/// disagreement makes the result inconclusive), and the enclosure of the cocycle deviation is
/// `centre_bound` (above `fail_tol` refutes).
pub fn prove_triangle(key: ConfigKey, model: &Model, s: &Settings) -> Vec<PropertyResult> {
    let t0 = Instant::now();
    let Some(t) = key.triangle() else {
        return vec![];
    };
    let (du, dw, dx) = (Deg::new(t.m_u), Deg::new(t.m_w), Deg::new(t.m_x));
    let (mu, mw, mx) = (t.m_u as i64, t.m_w as i64, t.m_x as i64);
    let sh_ux = two_pi_frac(t.u_x as i64, mu);
    let sh_uw = two_pi_frac(t.u_w as i64, mu);
    let sh_xuw = two_pi_frac(t.x_u as i64 - t.x_w as i64, mx);
    let (uw, ux, xw) = (t.uw(), t.ux(), t.xw());
    let mut cocycle_refuted: Option<(PBox, String)> = None;
    let mut model_refuted: Option<(PBox, String)> = None;
    let mut model_mismatch: u64 = 0;
    let mut first_mismatch: Option<String> = None;
    let mut centre_checks: u64 = 0;
    let cocycle = |p: &P2<Iv>| -> Option<Iv> {
        let lhs = model.g_uw_formula(&uw, p).ok()?;
        let mid = model.g_uw_formula(&ux, p).ok()?;
        if !finite_p2(&lhs) || !finite_p2(&mid) {
            // Rule 1: an unbounded image of a point (a NaN) refutes, never "undecided".
            return Some(Iv::point(f64::NAN));
        }
        let rhs = model.g_uw_formula(&xw, &mid).ok()?;
        Some(lhs.sub(&rhs).norm2().sqrt())
    };
    // Closed-form A = [p ∈ Ω_ux ∧ φ_xu(p) ∈ Ω_xw] on (θ, r), piecewise over principal angles.
    let a_of = |th: I, r: I| -> Trit {
        let mut v = Vec::with_capacity(2);
        for p in interval::principal_pieces(th - sh_ux) {
            let a1 = member(&du, p, r, Domain::Literal);
            if a1.is_false() {
                v.push(Trit::False);
                continue;
            }
            match phi_polar(&du, &dx, p, r) {
                Some((tx, rx)) => v.push(a1.and(member_any(&dx, tx + sh_xuw, rx, Domain::Literal))),
                None => v.push(Trit::Unknown),
            }
        }
        interval::all_pieces(&v)
    };
    // The exact case analysis of the doc comment, on the whole box.
    let exact = |th: I, r: I| -> Exact {
        let px = interval::principal_pieces_k(th - sh_ux);
        let [(tx, kx)] = px.as_slice() else {
            return Exact::Undecided;
        };
        match du.winding0(*tx) {
            Trit::False => return Exact::Empty,
            Trit::Unknown => return Exact::Undecided,
            Trit::True => {}
        }
        let Some((tq, rq)) = phi_polar(&du, &dx, *tx, r) else {
            return Exact::Undecided;
        };
        if tq.abs().sup() >= I::PI.inf() {
            return Exact::Undecided;
        }
        let pq = interval::principal_pieces_k(tq + sh_xuw);
        let [(tqw, kq)] = pq.as_slice() else {
            return Exact::Undecided;
        };
        match dx.winding0(*tqw) {
            Trit::False => return Exact::Empty,
            Trit::Unknown => return Exact::Undecided,
            Trit::True => {}
        }
        // g_x∘R_(x,w)(q) = e^{iπ n_x/3}·c exactly.
        let n_x = ((t.x_u as i64 - t.x_w as i64) - mx * kq).rem_euclid(6);
        if matches!(n_x, 2..=4) {
            // A ⊆ C ∩ disk(1 − e^{−iπn_x/3}): centres 2|sin(πn_x/6)| ≥ √3 apart, radii √3/2.
            return Exact::Empty;
        }
        if n_x == 0 {
            return Exact::Undecided;
        }
        let pw = interval::principal_pieces_k(th - sh_uw);
        let [(tw, kw)] = pw.as_slice() else {
            return Exact::Undecided;
        };
        // g_u∘R_(u,w)(p) = e^{iπ n_u/3}·b exactly.
        let n_u = ((t.u_x as i64 - t.u_w as i64) + mu * (kx - kw)).rem_euclid(6);
        if (n_x + n_u) % 6 != 0 || !du.winding0(*tw).is_true() {
            return Exact::Undecided;
        }
        // Equal sets. Cocycle branch conditions: c_w, c'' in the right half-plane, and the
        // angle offset ±π/3 (sign of n_u) matches the labels of u and x in w's star.
        let sgn = if n_u == 1 { 1 } else { -1 };
        let cocycle_ok = (sgn + t.w_x as i64 - t.w_u as i64).rem_euclid(mw) == 0
            && phi_polar(&du, &dw, *tw, r).is_some()
            && phi_polar(&dx, &dw, *tqw, rq).is_some();
        if cocycle_ok {
            Exact::Equal
        } else {
            Exact::Undecided
        }
    };
    let st = bnb(disk_box(t.m_u), s.max_depth, s.budget, |b| {
        let (th, r) = (b.ith(), b.ir());
        let a = a_of(th, r);
        if a.is_false() {
            return Leaf::Proven(None, None);
        }
        if a.is_true() && member_any(&du, th - sh_uw, r, Domain::Literal).is_false() {
            return Leaf::Refuted("p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, p ∉ Ω_uw (closed form)".into());
        }
        match exact(th, r) {
            Exact::Empty => return Leaf::Proven(None, None),
            Exact::Undecided => return Leaf::Split,
            Exact::Equal if b.diam() > s.check_diam => return Leaf::Split,
            Exact::Equal => {}
        }
        // Proven exactly on the box. Model cross-check at the centre, if it lies in the set.
        let (tm, rm) = b.mid();
        let mut cb = None;
        if a_of(c(tm), c(rm)).is_true() {
            centre_checks += 1;
            let p = iv_point(b.centre_xy());
            let m1 = model.in_omega_uw_literal(&ux, &p);
            let m2 = model
                .g_uw_formula(&ux, &p)
                .map(|q| model.in_omega_uw_literal(&xw, &q))
                .unwrap_or(Trit::Unknown);
            let m3 = model.in_omega_uw_literal(&uw, &p);
            if m1.is_true() && m2.is_true() && m3.is_false() {
                if model_refuted.is_none() {
                    model_refuted = Some((
                        *b,
                        "the model's literal tests: p ∈ Ω_ux, φ_xu(p) ∈ Ω_xw, p ∉ Ω_uw".into(),
                    ));
                }
            } else if m1.is_false() || m2.is_false() || m3.is_false() {
                model_mismatch += 1;
                if first_mismatch.is_none() {
                    let p = b.centre_xy();
                    first_mismatch = Some(format!(
                        "at p = ({:.9}, {:.9}) the closed form gives p ∈ Ω_ux ∩ φ_xu⁻¹(Ω_xw) ∩ Ω_uw, the model's literal tests give {m1:?}, {m2:?}, {m3:?}",
                        p[0], p[1]
                    ));
                }
            }
            match cocycle(&p) {
                Some(dv)
                    if enclosure_exceeds(dv.inf(), dv.sup(), s.fail_tol)
                        && cocycle_refuted.is_none() =>
                {
                    cocycle_refuted = Some((
                        *b,
                        format!("|φ_wu(p) − φ_wx(φ_xu(p))| {}", at_least(dv.inf())),
                    ));
                }
                Some(dv) if enclosure_exceeds(dv.inf(), dv.sup(), s.fail_tol) => {}
                Some(dv) => cb = omax(cb, Some(dv.sup())),
                None => {
                    // The model's maps fail to evaluate at a point of the set.
                    model_mismatch += 1;
                    if first_mismatch.is_none() {
                        let p = b.centre_xy();
                        first_mismatch = Some(format!(
                            "at p = ({:.9}, {:.9}) the model's maps could not evaluate the cocycle",
                            p[0], p[1]
                        ));
                    }
                }
            }
        }
        Leaf::Proven(Some(0.0), cb)
    });
    let incl_box = st.refuted.clone().or(model_refuted);
    let wit_incl = incl_box.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in u's chart, triangle {t:?}: {txt}",
                p[0], p[1]
            ),
            f64_confirms: inclusion_violated(model, &uw, &ux, &xw, &P2::<f64>::new(p[0], p[1])),
            mp_confirms: inclusion_violated(
                model,
                &uw,
                &ux,
                &xw,
                &P2::<Mp>::from_f64(p[0], p[1], MP_PREC),
            ),
        }
    });
    let wit_coc = cocycle_refuted.as_ref().map(|(b, txt)| {
        let p = b.centre_xy();
        CertWitness {
            point: p,
            text: format!(
                "p = ({:.9}, {:.9}) in u's chart, triangle {t:?}: {txt}",
                p[0], p[1]
            ),
            // `!(gap <= tol)`: a NaN gap confirms the refutation too.
            f64_confirms: !(cocycle_gap(model, &uw, &ux, &xw, &P2::<f64>::new(p[0], p[1]))
                <= s.fail_tol),
            mp_confirms: !(cocycle_gap(
                model,
                &uw,
                &ux,
                &xw,
                &P2::<Mp>::from_f64(p[0], p[1], MP_PREC),
            ) <= s.fail_tol),
        }
    });
    let ms = t0.elapsed().as_millis() as u64;
    let mismatch_note = first_mismatch
        .map(|m| format!(" INCONCLUSIVE: the model disagrees with the closed form at {model_mismatch} of {centre_checks} centres, e.g. {m}"))
        .unwrap_or_default();
    let incl_stmt = format!("φ_xu⁻¹(Ω_xu ∩ Ω_xw) = Ω_ux ∩ Ω_uw ⊆ Ω_uw at every point (literal Def. 4.1.9 via its closed form, u's chart; no δ): every box of the chart is proven disjoint from Ω_ux ∩ φ_xu⁻¹(Ω_xw) or the exact case analysis applies on it (principal pieces with integer wrap identities, winding 0, c_x > 0 certified; then both sets are C ∩ D ∩ G in g_u∘R_(u,x) coordinates, by 1 − e^{{∓iπ/3}} = e^{{±iπ/3}}, or the set is empty because two disks of radius √3/2 are ≥ √3 apart; proof at `certify::prove_triangle`); the model's literal tests agree with the closed form at every box centre in the set{mismatch_note}");
    let coc_stmt = "φ_wu = φ_wx∘φ_xu on all of φ_xu⁻¹(Ω_xu ∩ Ω_xw), exactly: on every box meeting the set the branch conditions are certified, under which c'' = e^{±iπ/3}c_w ((h∘M_{−π/3})³ = id) gives equal points; `bound` = 0 is the proven whole-domain bound; `centre_bound` = max interval enclosure of |φ_wu(p) − φ_wx(φ_xu(p))| by the model's generic maps at every box centre in the set (evaluator rounding; above fail_tol refutes)".to_string();
    let mk = |prop: &str,
              stmt: String,
              refuted: Option<CertWitness>,
              inconclusive: bool,
              bound: Option<f64>,
              cb: Option<f64>| {
        let outcome = if refuted.is_some() {
            Outcome::Refuted
        } else if inconclusive || st.refuted.is_some() || st.budget_hit {
            Outcome::Inconclusive
        } else if st.unresolved == 0 {
            Outcome::Certified
        } else {
            Outcome::CertifiedOutsideDelta
        };
        PropertyResult {
            key,
            property: prop.into(),
            outcome,
            statement: stmt,
            bound,
            centre_bound: cb,
            delta: if st.unresolved > 0 {
                Some(st.delta)
            } else {
                None
            },
            boxes: st.boxes,
            max_depth: st.max_depth,
            unresolved: st.unresolved,
            witness: refuted,
            millis: ms,
            f64_rounding: None,
            g_chart: None,
            f64_bound: None,
        }
    };
    let mismatch = model_mismatch > 0;
    let incl_out = mk("L4.2.1(cert)", incl_stmt, wit_incl, mismatch, None, None);
    let coc_out = mk(
        "L4.2.2(cert)",
        coc_stmt,
        wit_coc,
        mismatch,
        st.bound,
        st.centre,
    );
    vec![incl_out, coc_out]
}
