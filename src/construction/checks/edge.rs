//! Defs. 4.1.9 / 4.1.10 and Sec. 4.2 at edge level: Ω_uw, φ_wu, P4.2.1, P4.2.3, L4.2.3,
//! L4.2.4, and the driver running every edge-level check.

use super::common::*;
use super::edge_maps::*;
use super::polar::*;
use super::samples::*;
use super::smooth::{smooth_test, SmoothSpec};
use crate::construction::maps::*;
use crate::construction::sampling::*;
use crate::numeric::Scalar;
use crate::report::{Check, CheckResult, OnError, Witness};
use serde_json::json;

// =============================================================================================
// Defs. 4.1.9 / 4.1.10 and Sec. 4.2 (edge level)
// =============================================================================================

/// D4.1.9-lens: Def. 4.1.9 read literally agrees with the Sec. 6.1.3 canonical-lens test.
/// Disagreements within the rounding margin `ROUNDTRIP_COND·amp·ε` of the lens boundary (in the g_u∘R_(u,w) frame) are
/// counted as rounding-ambiguous, not as offences.
pub fn check_d4_1_9_lens_agreement<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let eps = unit_eps::<S>(prec);
    let tol = ROUNDTRIP_COND * amp(&[e.m_u, e.m_w]) * eps;
    let mut m = Check::sampled(
        "D4.1.9-lens",
        format!("Def. 4.1.9 (literal) ⇔ Sec. 6.1.3 lens test ({e:?})"),
        seed,
        tol,
    );
    let pts = edge_domain_samples(model, e, seed, n, prec);
    let (mut ambiguous, mut inside) = (0u64, 0u64);
    let three_q = cos_pi_6_sq::<f64>(53);
    let cats: Vec<Category> = pts.iter().map(|(c, _)| *c).collect();
    for (_, p) in &pts {
        let a = model.in_omega_uw_literal(e, p);
        let b = model.in_omega_uw_lens(e, p);
        if a.is_true() {
            inside += 1;
        }
        let q = model.g_v(e.m_u, &model.r_uw(e, p)).ok();
        let margin = q
            .as_ref()
            .map(|q| {
                let [x, y] = q.to_f64();
                ((x * x + y * y) - three_q)
                    .abs()
                    .min(((x - 1.0).powi(2) + y * y - three_q).abs())
            })
            .unwrap_or(0.0);
        if a != b && margin <= tol {
            ambiguous += 1;
            m.examined(1);
            continue;
        }
        let th = angle_of(&model.r_uw(e, p)).unwrap_or(0.0);
        m.holds(a == b, || {
            Witness::new(
                format!("p = {} (θ(R_(u,w)p) = {th:.6}): literal Def. 4.1.9 says {a:?}, lens test says {b:?}; g_u∘R_(u,w)(p) = {}", fmt(p), q.as_ref().map(fmt).unwrap_or_default()),
                json!({"p": pt(p), "literal": format!("{a:?}"), "lens": format!("{b:?}"), "q": q.as_ref().map(pt)}),
            )
        });
    }
    m.finish(format!("samples: {}; {inside} in Ω_uw (literal); {ambiguous} disagreements within the rounding margin {tol:.2e} of ∂E ignored", counts_of(&cats)))
}

/// P4.2.1: Ω_uw ≠ ∅ ⇔ Ω_wu ≠ ∅ (witnesses searched by sampling both domains).
pub fn check_p4_2_1<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let mut m = Check::sampled("P4.2.1", format!("Ω_uw ≠ ∅ ⇔ Ω_wu ≠ ∅ ({e:?})"), seed, 0.0);
    let a = omega_uw_points(model, e, seed, n, prec).len();
    let b = omega_uw_points(model, &e.reversed(), seed ^ 0x77, n, prec).len();
    m.examined(2 * n as u64);
    let conclusive = n >= MIN_EMPTINESS_SAMPLES;
    if (a == 0) != (b == 0) && conclusive {
        m.offend(|| {
            Witness::new(
                format!("{a} samples found in Ω_uw but {b} in Ω_wu"),
                json!({"omega_uw": a, "omega_wu": b}),
            )
        });
    }
    let mut r = m.finish(format!(
        "{a} sampled points in Ω_uw, {b} in Ω_wu (2 × {n} disk + {n} lens samples)"
    ));
    r.worst_deviation = None;
    if (a == 0 || b == 0) && !conclusive {
        r.adopt_verdict(inconclusive_search(n));
    }
    r
}

/// P4.2.3 / D3.4.1(3b): φ_uw(φ_wu(p)) = p for p ∈ Ω_uw, and D4.1.10: φ_wu(p) ∈ Ω_wu.
/// Returns [P4.2.3, D4.1.10].
pub fn check_p4_2_3<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = COMPOSITE_COND * amp(&[e.m_u, e.m_w]) * eps;
    let mut m = Check::sampled(
        "P4.2.3",
        format!("φ_uw∘φ_wu = id on Ω_uw ({e:?})"),
        seed,
        tol,
    );
    let mut d = Check::sampled(
        "D4.1.10",
        format!("φ_wu maps Ω_uw into Ω_wu ({e:?})"),
        seed,
        0.0,
    );
    let pw = VertexPair::Edge(*e);
    let pu = VertexPair::Edge(e.reversed());
    let pts = omega_uw_points(model, e, seed, n, prec);
    for (_, p) in &pts {
        let t = model.phi_wu(&pw, p);
        let t = match t {
            Ok(t) => t,
            Err(err) => {
                // φ_wu is claimed defined on Ω_uw: an offence of both statements.
                let w = || {
                    Witness::new(
                        format!("φ_wu({}) failed: {err}", fmt(p)),
                        json!({"p": pt(p)}),
                    )
                };
                d.error(OnError::Offence, &err, w);
                m.error(OnError::Offence, &err, w);
                continue;
            }
        };
        let in_wu = model.in_omega_uw_literal(&e.reversed(), &t);
        d.holds(!in_wu.is_false(), || {
            Witness::new(
                format!("p = {} ∈ Ω_uw but φ_wu(p) = {} ∉ Ω_wu", fmt(p), fmt(&t)),
                json!({"p": pt(p), "t": pt(&t)}),
            )
        });
        let back = model.phi_wu(&pu, &t);
        let dev = back
            .as_ref()
            .map(|b| b.dist_f64(p))
            .unwrap_or(f64::INFINITY);
        m.deviation(dev, || {
            Witness::new(
                format!(
                    "p = {}: φ_wu(p) = {}, φ_uw(φ_wu(p)) = {} (error {dev:.3e})",
                    fmt(p),
                    fmt(&t),
                    back.as_ref().map(fmt).unwrap_or_else(|e| e.to_string())
                ),
                json!({"p": pt(p), "t": pt(&t), "dev": dev}),
            )
        });
    }
    let note = format!(
        "{} sampled points of Ω_uw; tolerance = {COMPOSITE_COND}·amp·ε",
        pts.len()
    );
    vec![m.finish(note.clone()), d.finish(note)]
}

/// L4.2.4: φ_wu is C^∞ on Ω_uw: Jacobian (chain rule vs central differences of φ_wu itself)
/// and jump test across the lens axis (partners: mirror images in the g_u∘R_(u,w) frame).
pub fn check_l4_2_4<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let (lip, kmax) = guw_lipschitz(e);
    let mut m = Check::sampled("L4.2.4", format!("φ_wu is C^∞ on Ω_uw ({e:?})"), seed, 1.0);
    let pair = VertexPair::Edge(*e);
    let f = |p: &P2<S>| model.phi_wu(&pair, p);
    let jac = |p: &P2<S>| model.g_uw_jacobian(e, p);
    let inner = |p: &P2<S>| guw_inner_radius(model, e, p);
    let spec = SmoothSpec {
        f: &f,
        jac: &jac,
        lip,
        kmax,
        inner_radius: Some(&inner),
    };
    let lp = lens_pullbacks(model, e, seed, n, prec);
    let pts: Vec<P2<S>> = lp
        .iter()
        .map(|(_, p, _)| p.clone())
        .filter(|p| model.in_omega_uw_literal(e, p).is_true())
        .collect();
    let partners: Vec<(P2<S>, P2<S>)> = lp
        .iter()
        .filter(|(c, _, _)| *c == Category::NearLensAxis)
        .filter_map(|(_, p, q)| {
            let qm = P2::new(q.x.clone(), q.y.neg());
            model
                .g_v_inv(e.m_u, &qm)
                .ok()
                .map(|a| (p.clone(), model.r_uw_inv(e, &a)))
        })
        .collect();
    let (a1, a2) = smooth_test(&mut m, &spec, &pts, &partners, prec);
    m.finish(format!("{} points of Ω_uw (lens pull-backs); Jacobian tests {a1}, jump pairs across the lens axis {a2}; L = {lip:.6}", pts.len()))
}

/// L4.2.3 (condition (4)): for x on ∂Ω_uw ∩ Ω_u (pull-back of the arc ∂D ∩ int C), the limit
/// g_(u,w)(x) lies on ∂Ω_w (|·| = cos(π/m_w)), hence outside Ω_w ⊇ ∂Ω_wu ∩ Ω_w, which gives the
/// separating balls. Also checks x ∈ Ω_u. Same for the reversed edge.
pub fn check_l4_2_3<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let eps = unit_eps::<S>(prec);
    let tol = COMPOSITE_COND * amp(&[e.m_u, e.m_w]) * eps;
    let mut m = Check::sampled(
        "L4.2.3",
        format!("Hausdorff separation of ∂Ω_uw ∩ Ω_u and ∂Ω_wu ∩ Ω_w ({e:?})"),
        seed,
        tol,
    );
    let arc = sample_lens_inner_arc::<S>(seed, n, prec);
    for edge in [*e, e.reversed()] {
        let rw = omega_radius::<S>(edge.m_w, prec);
        for (_, q) in &arc.points {
            let x = match model.g_v_inv(edge.m_u, q) {
                Ok(a) => model.r_uw_inv(&edge, &a),
                Err(err) => {
                    // g_u⁻¹ is defined on R² − {0} and the arc avoids 0: an offence.
                    m.error(OnError::Offence, &err, || {
                        Witness::new(
                            format!("arc point q = {}: g_u⁻¹(q) failed: {err}", fmt(q)),
                            json!({"q": pt(q)}),
                        )
                    });
                    continue;
                }
            };
            if !in_omega_v_punctured(edge.m_u, &x).is_true() {
                m.offend(|| {
                    Witness::new(
                        format!("boundary point x = {} of Ω_uw is not in Ω_u", fmt(&x)),
                        json!({"x": pt(&x)}),
                    )
                });
                continue;
            }
            let y = model.g_uw_formula(&edge, &x);
            let dev = y
                .as_ref()
                .map(|y| y.norm2().sqrt().sub(&rw).abs().to_f64())
                .unwrap_or(f64::INFINITY);
            m.deviation(dev, || Witness::new(format!("x = {} ∈ ∂Ω_uw ∩ Ω_u ({edge:?}): g_(u,w)(x) = {} is at distance {dev:.3e} from ∂Ω_w", fmt(&x), y.as_ref().map(fmt).unwrap_or_default()), json!({"x": pt(&x), "dev": dev})));
        }
    }
    m.finish(format!("{} arc points per orientation (exactly on ∂D ∩ int C, pulled back); tolerance = {COMPOSITE_COND}·amp·ε", arc.len()))
}

/// All edge-level checks for one configuration. Invalid configurations give one `Skipped`.
pub fn run_edge_checks_with<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    if let Err(err) = e.validate() {
        let mut r = CheckResult::new("D4.1.8", "edge configuration");
        r.skip(err.to_string());
        return vec![r];
    }
    let mut v = vec![check_d4_1_5_polar(model, seed, n, prec)];
    v.extend(check_c4_1_6_gv_bijective(model, e.m_u, seed, n, prec));
    v.extend(check_c4_1_6_gv_smooth(model, e.m_u, seed, n, prec));
    v.push(check_c4_1_7_h_identity(model, seed, n, prec));
    v.extend(check_c4_1_8_onto_int_c(model, e, seed, n, prec));
    v.push(check_c4_1_8_lens_in_q(model, seed, n, prec));
    v.extend(check_c4_1_8_guw_bijective(model, e, seed, n, prec));
    v.extend(check_p4_1_1_guw_smooth(model, e, seed, n, prec));
    v.extend(check_p4_1_2(model, e, seed, n, prec));
    v.extend(check_p4_1_3(model, e, seed, n, prec));
    v.push(check_d4_1_9_lens_agreement(model, e, seed, n, prec));
    v.push(check_p4_2_1(model, e, seed, n, prec));
    v.extend(check_p4_2_3(model, e, seed, n, prec));
    v.push(check_l4_2_3(model, e, seed, n, prec));
    v.push(check_l4_2_4(model, e, seed, n, prec));
    for r in &mut v {
        r.note = format!("[{}] {}", S::from_i64(0, prec).type_name(), r.note);
    }
    v
}

/// All edge-level checks for the paper's construction, scalar type `S` at `prec` bits
/// (ignored for f64).
pub fn run_edge_checks<S: Scalar>(
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    run_edge_checks_with::<S, Paper>(&Paper, e, seed, n, prec)
}
