//! Sec. 4.2 at triangle level: L4.2.1, L4.2.2 (the cocycle condition) and P4.2.4, and the
//! driver running every triangle-level check.

use super::common::*;
use super::samples::*;
use crate::construction::maps::*;
use crate::numeric::Scalar;
use crate::report::{Check, CheckResult, OnError, Witness};
use serde_json::json;

// =============================================================================================
// Triangle level: L4.2.1, L4.2.2, P4.2.4
// =============================================================================================

/// L4.2.1 and L4.2.2 for the triangle [u, w, x]: for t ∈ Ω_xu ∩ Ω_xw and p = φ_xu⁻¹(t)
/// (= φ_ux(t), with φ_xu(p) = t verified): p ∈ Ω_uw (L4.2.1) and φ_wu(p) = φ_wx(φ_xu(p))
/// (L4.2.2). Also the proof's equality φ_xu⁻¹(Ω_xu ∩ Ω_xw) ⊇ Ω_ux ∩ Ω_uw (`L4.2.1-proof-equality`).
/// Returns [L4.2.1, L4.2.2, L4.2.1-proof-equality].
pub fn check_l4_2_1_l4_2_2<S: Scalar, M: Ppm<S>>(
    model: &M,
    t: &TriangleConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = COMPOSITE_COND * amp(&[t.m_u, t.m_w, t.m_x]) * eps;
    let mut l1 = Check::sampled(
        "L4.2.1",
        format!("φ_xu⁻¹(Ω_xu ∩ Ω_xw) ⊆ Ω_uw ({t:?})"),
        seed,
        tol,
    );
    let mut l2 = Check::sampled(
        "L4.2.2",
        format!("φ_wu = φ_wx∘φ_xu on φ_xu⁻¹(Ω_xu ∩ Ω_xw) ({t:?})"),
        seed,
        tol,
    );
    let mut eq = Check::sampled(
        "L4.2.1-proof-equality",
        format!("Ω_ux ∩ Ω_uw ⊆ φ_xu⁻¹(Ω_xu ∩ Ω_xw) ({t:?})"),
        seed,
        0.0,
    );
    let (xu, xw, ux, uw) = (t.xu(), t.xw(), t.ux(), t.uw());
    let p_xu = VertexPair::Edge(xu); // φ_ux : Ω_xu → Ω_ux
    let p_ux = VertexPair::Edge(ux); // φ_xu : Ω_ux → Ω_xu
    let p_uw = VertexPair::Edge(uw); // φ_wu : Ω_uw → Ω_wu
    let p_xw = VertexPair::Edge(xw); // φ_wx : Ω_xw → Ω_wx
    let pts = star_samples(model, &[xu, xw], seed, n, prec);
    let mut in_both = 0u64;
    for (_, tt) in &pts {
        if !(model.in_omega_uw_literal(&xu, tt).is_true()
            && model.in_omega_uw_literal(&xw, tt).is_true())
        {
            continue;
        }
        in_both += 1;
        let p = match model.phi_wu(&p_xu, tt) {
            Ok(p) => p,
            Err(err) => {
                l1.offend(|| {
                    Witness::new(
                        format!("φ_ux({}) failed: {err}", fmt(tt)),
                        json!({"t": pt(tt)}),
                    )
                });
                continue;
            }
        };
        let t2 = model.phi_wu(&p_ux, &p);
        let dt = t2.as_ref().map(|a| a.dist_f64(tt)).unwrap_or(f64::INFINITY);
        let in_uw = model.in_omega_uw_literal(&uw, &p);
        l1.deviation(if in_uw.is_false() { f64::INFINITY } else { dt }, || {
            Witness::new(format!("t = {} ∈ Ω_xu ∩ Ω_xw, p = φ_xu⁻¹(t) = {}: p ∈ Ω_uw is {in_uw:?}; |φ_xu(p) − t| = {dt:.3e}", fmt(tt), fmt(&p)), json!({"t": pt(tt), "p": pt(&p), "in_uw": format!("{in_uw:?}")}))
        });
        if !in_uw.is_true() {
            continue;
        }
        let lhs = model.phi_wu(&p_uw, &p);
        let rhs = t2.and_then(|a| model.phi_wu(&p_xw, &a));
        let dev = match (&lhs, &rhs) {
            (Ok(a), Ok(b)) => a.dist_f64(b),
            _ => f64::INFINITY,
        };
        l2.deviation(dev, || {
            Witness::new(
                format!("p = {}: φ_wu(p) = {}, φ_wx(φ_xu(p)) = {} (difference {dev:.3e})", fmt(&p), lhs.as_ref().map(fmt).unwrap_or_else(|e| e.to_string()), rhs.as_ref().map(fmt).unwrap_or_else(|e| e.to_string())),
                json!({"p": pt(&p), "lhs": lhs.as_ref().map(pt).ok(), "rhs": rhs.as_ref().map(pt).ok(), "dev": dev}),
            )
        });
    }
    // Reverse inclusion (proof of L4.2.1): p ∈ Ω_ux ∩ Ω_uw ⇒ φ_xu(p) ∈ Ω_xw.
    let pu = star_samples(model, &[ux, uw], seed ^ 0x99, n, prec);
    for (_, p) in &pu {
        if !(model.in_omega_uw_literal(&ux, p).is_true()
            && model.in_omega_uw_literal(&uw, p).is_true())
        {
            continue;
        }
        let img = model.phi_wu(&p_ux, p);
        let ok = img
            .as_ref()
            .map(|a| !model.in_omega_uw_literal(&xw, a).is_false())
            .unwrap_or(false);
        eq.holds(ok, || {
            Witness::new(
                format!(
                    "p = {} ∈ Ω_ux ∩ Ω_uw but φ_xu(p) = {} ∉ Ω_xw",
                    fmt(p),
                    img.as_ref().map(fmt).unwrap_or_default()
                ),
                json!({"p": pt(p)}),
            )
        });
    }
    let note = format!(
        "{} samples of Ω_x, {in_both} in Ω_xu ∩ Ω_xw; tolerance = {COMPOSITE_COND}·amp·ε",
        pts.len()
    );
    vec![
        l1.finish(note.clone()),
        l2.finish(note.clone()),
        eq.finish(note),
    ]
}

/// P4.2.4 for [u, w, z] with s_u(z) = s_u(w) − 1 (mod m_u): `e_uw`, `e_uz` the two edges.
/// Claims: (i) M_{−π/3}∘g_u∘R_(u,w)(Ω_uw) = g_u∘R_(u,w)(Ω_uz); (ii) M_{π/3}∘g_u∘R_(u,z)(Ω_uz) =
/// g_u∘R_(u,z)(Ω_uw); (iii) Ω_uz = M_{−2π/m_u}(Ω_uw) and (iv) Ω_uw = M_{2π/m_u}(Ω_uz).
/// Set equalities are checked in both directions on samples; image membership uses all
/// preimages under g_u. Returns [P4.2.4(i,ii), P4.2.4(iii,iv)].
pub fn check_p4_2_4<S: Scalar, M: Ppm<S>>(
    model: &M,
    e_uw: &EdgeConfig,
    e_uz: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = COMPOSITE_COND * amp(&[e_uw.m_u]) * eps;
    let mut a = Check::sampled(
        "P4.2.4(i,ii)",
        format!("M_∓π/3∘g_u∘R(Ω_uw/uz) = g_u∘R(Ω_uz/uw) ({e_uw:?}, {e_uz:?})"),
        seed,
        tol,
    );
    let mut b = Check::sampled(
        "P4.2.4(iii,iv)",
        format!("Ω_uz = M_{{−2π/m_u}}(Ω_uw), Ω_uw = M_{{2π/m_u}}(Ω_uz) ({e_uw:?}, {e_uz:?})"),
        seed,
        0.0,
    );
    if e_uw.m_u != e_uz.m_u || (e_uz.i + 1) % e_uw.m_u != e_uw.i {
        a.offend(|| Witness::new("precondition: s_u(z) must be s_u(w) − 1 mod m_u", json!({})));
        return vec![a.finish(String::new()), b.finish(String::new())];
    }
    let mu = e_uw.m_u;
    let in_image = |y: &P2<S>, e_frame: &EdgeConfig, e_set: &EdgeConfig| -> bool {
        // ∃ p' ∈ Ω_{u,set} with g_u∘R_frame(p') = y ?
        g_v_preimages(mu, y)
            .map(|pre| {
                pre.iter().any(|c| {
                    let p2 = model.r_uw_inv(e_frame, c);
                    model.in_omega_uw_literal(e_set, &p2).is_true()
                        && model
                            .g_v(mu, &model.r_uw(e_frame, &p2))
                            .map(|z| z.dist_f64(y) <= tol)
                            .unwrap_or(false)
                })
            })
            .unwrap_or(false)
    };
    let dom_w = omega_uw_points(model, e_uw, seed, n, prec);
    let dom_z = omega_uw_points(model, e_uz, seed ^ 0x2, n, prec);
    // (i): frame R_(u,w), rotation −1/6 turn maps image of Ω_uw onto image of Ω_uz.
    // (ii): frame R_(u,z), rotation +1/6 turn maps image of Ω_uz onto image of Ω_uw.
    for (frame, rot, from, to, from_e, to_e, label) in [
        (e_uw, -1i64, &dom_w, &dom_z, e_uw, e_uz, "(i)"),
        (e_uz, 1i64, &dom_z, &dom_w, e_uz, e_uw, "(ii)"),
    ] {
        for (_, p) in from.iter() {
            match model.g_v(mu, &model.r_uw(frame, p)) {
                Err(err) => a.error(OnError::Offence, &err, || {
                    Witness::new(
                        format!("{label}: g_u∘R({}) failed: {err}", fmt(p)),
                        json!({"p": pt(p)}),
                    )
                }),
                Ok(q) => {
                    let y = rotate_frac(&q, rot, 6);
                    let ok = in_image(&y, frame, to_e);
                    a.holds(ok, || Witness::new(format!("{label} ⊆: p = {} ∈ Ω of {from_e:?}; M(g_u∘R(p)) = {} is not in g_u∘R(Ω of {to_e:?})", fmt(p), fmt(&y)), json!({"p": pt(p), "y": pt(&y)})));
                }
            }
        }
        for (_, p) in to.iter() {
            match model.g_v(mu, &model.r_uw(frame, p)) {
                Err(err) => a.error(OnError::Offence, &err, || {
                    Witness::new(
                        format!("{label}: g_u∘R({}) failed: {err}", fmt(p)),
                        json!({"p": pt(p)}),
                    )
                }),
                Ok(y) => {
                    let y0 = rotate_frac(&y, -rot, 6);
                    let ok = in_image(&y0, frame, from_e);
                    a.holds(ok, || Witness::new(format!("{label} ⊇: p' = {} ∈ Ω of {to_e:?} has g_u∘R(p') = {} (θ = {:.6}) not in M(g_u∘R(Ω of {from_e:?}))", fmt(p), fmt(&y), angle_of(&y).unwrap_or(0.0)), json!({"p": pt(p), "y": pt(&y)})));
                }
            }
        }
    }
    for (_, p) in &dom_w {
        let q = rotate_frac(p, -1, mu as i64);
        let ok = !model.in_omega_uw_literal(e_uz, &q).is_false();
        b.holds(ok, || {
            Witness::new(
                format!(
                    "(iii): p = {} ∈ Ω_uw but M_{{−2π/m}}(p) = {} ∉ Ω_uz",
                    fmt(p),
                    fmt(&q)
                ),
                json!({"p": pt(p)}),
            )
        });
    }
    for (_, p) in &dom_z {
        let q = rotate_frac(p, 1, mu as i64);
        let ok = !model.in_omega_uw_literal(e_uw, &q).is_false();
        b.holds(ok, || {
            Witness::new(
                format!(
                    "(iv): p = {} ∈ Ω_uz but M_{{2π/m}}(p) = {} ∉ Ω_uw",
                    fmt(p),
                    fmt(&q)
                ),
                json!({"p": pt(p)}),
            )
        });
    }
    let note = format!(
        "{} points of Ω_uw, {} of Ω_uz; image tolerance = {COMPOSITE_COND}·amp·ε",
        dom_w.len(),
        dom_z.len()
    );
    vec![a.finish(note.clone()), b.finish(note)]
}

/// All triangle-level checks for the paper's construction.
pub fn run_triangle_checks<S: Scalar>(
    t: &TriangleConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    run_triangle_checks_with::<S, Paper>(&Paper, t, seed, n, prec)
}

/// All triangle-level checks for a model. P4.2.4 is run at u with (w, z) chosen so that
/// s_u(z) precedes s_u(w).
pub fn run_triangle_checks_with<S: Scalar, M: Ppm<S>>(
    model: &M,
    t: &TriangleConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let orient = match t.orientation() {
        Ok(o) => o,
        Err(err) => {
            let mut r = CheckResult::new("L4.2.2", "triangle configuration");
            r.skip(err.to_string());
            return vec![r];
        }
    };
    let mut v = check_l4_2_1_l4_2_2(model, t, seed, n, prec);
    let (e_w, e_z) = match orient {
        FanOrientation::Ccw => (t.ux(), t.uw()),
        FanOrientation::Cw => (t.uw(), t.ux()),
    };
    v.extend(check_p4_2_4(model, &e_w, &e_z, seed, n, prec));
    for r in &mut v {
        r.note = format!("[{}] {}", S::from_i64(0, prec).type_name(), r.note);
    }
    v
}
