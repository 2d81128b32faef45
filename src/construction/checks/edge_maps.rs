//! Def. 4.1.8's running text and Props. 4.1.1–4.1.3: g_(u,w) for one edge configuration.

use super::common::*;
use super::samples::*;
use super::smooth::{smooth_test, SmoothSpec};
use crate::construction::maps::*;
use crate::construction::sampling::*;
use crate::numeric::Scalar;
use crate::report::{dev_max, Check, CheckResult, OnError, Restricted, Witness};
use serde_json::json;

// =============================================================================================
// Claims of Def. 4.1.8's running text
// =============================================================================================

/// C4.1.8-onto-intC: "g_u ∘ R_(u,w) maps Ω_u − {0} onto int(C) − {0}". Into: samples of
/// Ω_u − {0}; onto: samples q of int(C) − {0} must have a preimage p ∈ Ω_u − {0} (candidates:
/// all preimages of q under g_u, rotated back). Restricted result for m_u < 6: onto the sector
/// {|β| ≤ m_uπ/6} of int(C) − {0}.
pub fn check_c4_1_8_onto_int_c<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = GV_COND * amp(&[e.m_u]) * eps;
    let name = format!(
        "g_u∘R_(u,w) maps Ω_u − {{0}} onto int(C) − {{0}} (m_u = {})",
        e.m_u
    );
    let mut pair = Restricted::sampled("C4.1.8-onto-intC", &name, seed, tol);
    let su = omega_u_samples::<S>(e, seed, n, prec);
    for (_, p) in &su.points {
        if !in_omega_v_punctured(e.m_u, p).is_true() {
            continue;
        }
        let q = model.g_v(e.m_u, &model.r_uw(e, p));
        let ok = q
            .as_ref()
            .map(|q| in_int_c_punctured(q).is_true())
            .unwrap_or(false);
        let w = || {
            Witness::new(
                format!(
                    "into: p = {} ∈ Ω_u but g_u∘R(p) = {} ∉ int(C) − {{0}}",
                    fmt(p),
                    q.as_ref().map(fmt).unwrap_or_default()
                ),
                json!({"p": pt(p)}),
            )
        };
        pair.holds(ok, true, w);
    }
    let sc = sample_disk::<S>(
        seed ^ 0x5eed,
        n,
        &cos_pi_6::<S>(prec),
        &scalar_pi::<S>(prec),
        prec,
    );
    let bound = (e.m_u as f64 * std::f64::consts::PI / 6.0).min(std::f64::consts::PI);
    for (_, q) in &sc.points {
        if !in_int_c_punctured(q).is_true() {
            continue;
        }
        let mut best = f64::INFINITY;
        if let Ok(pre) = g_v_preimages(e.m_u, q) {
            for a in pre {
                let p = model.r_uw_inv(e, &a);
                if !in_omega_v_punctured(e.m_u, &p).is_true() {
                    continue;
                }
                if let Ok(img) = model.g_v(e.m_u, &model.r_uw(e, &p)) {
                    best = best.min(img.dist_f64(q));
                }
            }
        }
        let beta = angle_of(q).unwrap_or(0.0).abs();
        let w = || {
            Witness::new(
                format!("onto: q = {} (|β| = {beta:.6}) ∈ int(C) − {{0}} has no preimage in Ω_u − {{0}} (best residual {best:.3e})", fmt(q)),
                json!({"q": pt(q), "beta": beta, "residual": best}),
            )
        };
        pair.deviation(best, beta < bound - 1e3 * eps, w);
    }
    let note = format!(
        "Ω_u samples: {}; int(C) samples: {}; tolerance = {GV_COND}·max(1,m/6,6/m)·ε",
        su.counts_string(),
        sc.counts_string()
    );
    let domain = format!("onto the sector {{|β| < min(π, m_uπ/6) = {bound:.6}}} of int(C) − {{0}} (onto int(C) − {{0}} iff m_u ≥ 6)");
    pair.finish(note, domain, e.m_u < 6)
}

/// C4.1.8-lens-in-Q: the canonical lens E is contained in the quadrilateral Q with vertices
/// (0,0), (1/2, −√3/2), (1,0), (1/2, √3/2). Samples: the lens sampler and a uniform box
/// [−0.1, 1.1] × [−1, 1]; every point the model puts in E must be in (closed) Q.
pub fn check_c4_1_8_lens_in_q<S: Scalar, M: Ppm<S>>(
    model: &M,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let mut m = Check::sampled(
        "C4.1.8-lens-in-Q",
        "canonical lens E ⊂ quadrilateral Q",
        seed,
        0.0,
    );
    let mut pts: Vec<P2<S>> = sample_lens::<S>(seed, n, prec)
        .points
        .into_iter()
        .map(|(_, p)| p)
        .collect();
    let mut g = rng(seed ^ 0xb0c5);
    use rand::Rng;
    for _ in 0..n {
        pts.push(P2::from_f64(
            g.gen_range(-0.1..1.1),
            g.gen_range(-1.0..1.0),
            prec,
        ));
    }
    let mut in_e = 0u64;
    for q in &pts {
        let e = model.in_canonical_lens(q);
        if e.is_false() {
            continue;
        }
        in_e += 1;
        let ok = in_quad_q(q).is_true();
        m.holds(ok, || {
            Witness::new(
                format!("q = {} is in E but not in Q", fmt(q)),
                json!({"q": pt(q)}),
            )
        });
    }
    m.finish(format!("{} candidate points (lens sampler + uniform box), {in_e} in E; decided exactly by sign tests (tolerance 0)", pts.len()))
}

/// C4.1.8-guw-bijective: "g_(u,w) is bijective and its inverse is
/// R_(u,w)⁻¹∘g_u⁻¹∘h∘g_w∘R_(w,u)": checks g_(u,w)⁻¹∘g_(u,w) = id on Ω_u − {0}. Restricted:
/// {p ∈ Ω_u − {0} : |θ(R_(u,w) p)| < 6π/m_u} (all of Ω_u − {0} iff m_u ≤ 6).
pub fn check_c4_1_8_guw_bijective<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = ROUNDTRIP_COND * amp(&[e.m_u, e.m_w]) * eps;
    let name = format!("g_(u,w) bijective with the stated inverse on Ω_u − {{0}} ({e:?})");
    let mut pair = Restricted::sampled("C4.1.8-guw-bijective", &name, seed, tol);
    let s = omega_u_samples::<S>(e, seed, n, prec);
    let bound = (6.0 * std::f64::consts::PI / e.m_u as f64).min(std::f64::consts::PI);
    for (_, p) in &s.points {
        if !in_omega_v_punctured(e.m_u, p).is_true() {
            continue;
        }
        let r = model.g_uw(e, p).and_then(|q| model.g_uw_inv(e, &q));
        let dev = r.as_ref().map(|q| q.dist_f64(p)).unwrap_or(f64::INFINITY);
        let th = angle_of(&model.r_uw(e, p)).unwrap_or(0.0).abs();
        let w = || {
            Witness::new(
                format!(
                    "p = {} (θ(R_(u,w)p) = {th:.6}): g_(u,w)⁻¹(g_(u,w)(p)) = {}, error {dev:.3e}",
                    fmt(p),
                    r.as_ref().map(fmt).unwrap_or_default()
                ),
                json!({"p": pt(p), "back": r.as_ref().map(pt).ok(), "dev": dev}),
            )
        };
        pair.deviation(dev, th < bound - 1e3 * eps * e.m_u as f64, w);
    }
    let note = format!(
        "samples of Ω_u: {}; tolerance = ROUNDTRIP_COND({ROUNDTRIP_COND})·max(1,m/6,6/m)·ε",
        s.counts_string()
    );
    let domain = format!("{{p ∈ Ω_u − {{0}} : |θ(R_(u,w)p)| < {bound:.6}}} (= min(π, 6π/m_u)); all of Ω_u − {{0}} iff m_u ≤ 6");
    pair.finish(note, domain, e.m_u > 6)
}

// =============================================================================================
// Propositions 4.1.1–4.1.3
// =============================================================================================

/// |h∘g_u∘R_(u,w)(p)|: the radius at which g_(u,w) = R_(w,u)⁻¹∘g_w⁻¹∘h∘g_u∘R_(u,w)
/// (Def. 4.1.8) applies its second polar map.
pub(super) fn guw_inner_radius<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    p: &P2<S>,
) -> Option<f64> {
    let q = model.g_v(e.m_u, &model.r_uw(e, p)).ok()?;
    Some(model.h(&q).norm2().sqrt().to_f64())
}

pub(super) fn guw_lipschitz(e: &EdgeConfig) -> (f64, f64) {
    let cu = f_v_radial_factor::<f64>(e.m_u, 53);
    let cw = f_v_radial_factor::<f64>(e.m_w, 53);
    let ku = e.m_u as f64 / 6.0;
    let kw = 6.0 / e.m_w as f64;
    (cu * ku.max(1.0) * kw.max(1.0) / cw, ku.max(kw).max(1.0))
}

/// P4.1.1: g_(u,w) is C^∞ on Ω_u − {0}. Jacobian (chain rule vs central differences) and jump
/// tests on samples of Ω_u − {0} including both sides of the ray opposite u'_i (angle
/// π + 2πi/m_u), where g_u ∘ R_(u,w) meets Π's cut. Restricted: Ω_u − ({0} ∪ that ray).
pub fn check_p4_1_1_guw_smooth<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let (lip, kmax) = guw_lipschitz(e);
    let name = format!("g_(u,w) is C^∞ on Ω_u − {{0}} ({e:?})");
    let mut pair = Restricted::sampled("P4.1.1", &name, seed, 1.0);
    let s = omega_u_samples::<S>(e, seed, n, prec);
    let cut = scalar_pi::<S>(prec).mul(&S::from_ratio(
        e.m_u as i64 + 2 * e.i as i64,
        e.m_u as i64,
        prec,
    ));
    let f = |p: &P2<S>| model.g_uw(e, p);
    let jac = |p: &P2<S>| model.g_uw_jacobian(e, p);
    let inner = |p: &P2<S>| guw_inner_radius(model, e, p);
    let spec = SmoothSpec {
        f: &f,
        jac: &jac,
        lip,
        kmax,
        inner_radius: Some(&inner),
    };
    let pts: Vec<P2<S>> = s
        .points
        .iter()
        .map(|(_, p)| p.clone())
        .filter(|p| in_omega_v_punctured(e.m_u, p).is_true())
        .collect();
    let partners: Vec<(P2<S>, P2<S>)> = s
        .points
        .iter()
        .filter(|(c, _)| matches!(c, Category::NearCutCcw | Category::NearCutCw))
        .map(|(_, p)| (p.clone(), reflect(p, &cut)))
        .collect();
    let (a1, a2) = smooth_test(&mut pair.all, &spec, &pts, &partners, prec);
    let cb = eps.cbrt();
    let pts_r: Vec<P2<S>> = pts
        .iter()
        .filter(|p| {
            angle_of(&model.r_uw(e, p))
                .map(|t| std::f64::consts::PI - t.abs() > 4.0 * cb)
                .unwrap_or(false)
        })
        .cloned()
        .collect();
    let (b1, _) = smooth_test(&mut pair.restricted, &spec, &pts_r, &[], prec);
    let note = format!("samples {}; Jacobian tests {a1}, jump pairs across the ray at angle π + 2πi/m_u: {a2}; L = {lip:.6}; FD tolerance as in C4.1.6-gv-smooth (relative, tolerance 1); restricted run: {b1} Jacobian tests", s.counts_string());
    let domain = "Ω_u − ({0} ∪ {t·(−cos 2πi/m_u, −sin 2πi/m_u) : t > 0}) (the ray opposite s_u(w)); all of Ω_u − {0} iff 6 | m_u".to_string();
    pair.finish(note, domain, e.m_u % 6 != 0)
}

/// P4.1.2: (0,0) ∉ g_(u,w)(Ω_u − {0}). Quantitative form checked: |h(q)| ≥ 1 − cos(π/6) for
/// q = g_u∘R_(u,w)(p) ∈ int(C), hence |g_(u,w)(p)| ≥ δ = (1 − cos π/6)·cos(π/m_w)/cos(π/6) > 0.
/// Also returns the proof step "θ(q) ∈ (−π/3, π/3)" as `P4.1.2-proof-step`.
pub fn check_p4_1_2<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = GV_COND * amp(&[e.m_u, e.m_w]) * eps;
    let delta = (1.0 - (3.0f64).sqrt() / 2.0) / f_v_radial_factor::<f64>(e.m_w, 53);
    let mut m = Check::sampled(
        "P4.1.2",
        format!("(0,0) ∉ g_(u,w)(Ω_u − {{0}}) ({e:?})"),
        seed,
        tol,
    );
    let mut step = Check::sampled(
        "P4.1.2-proof-step",
        format!("proof step: θ(g_u∘R_(u,w)(p)) ∈ (−π/3, π/3) on Ω_u − {{0}} ({e:?})"),
        seed,
        0.0,
    );
    let s = omega_u_samples::<S>(e, seed, n, prec);
    let mut min_norm = f64::INFINITY;
    for (_, p) in &s.points {
        if !in_omega_v_punctured(e.m_u, p).is_true() {
            continue;
        }
        let img = model.g_uw(e, p);
        let nrm = img
            .as_ref()
            .map(|q| q.norm2().sqrt().to_f64())
            .unwrap_or(0.0);
        min_norm = min_norm.min(nrm);
        // NaN-propagating: a non-finite |g_(u,w)(p)| is an offence, not "≥ δ".
        let dev = dev_max(delta - nrm, 0.0);
        m.deviation(dev, || {
            Witness::new(
                format!(
                    "p = {}: |g_(u,w)(p)| = {nrm:.3e} < δ = {delta:.6} (image {})",
                    fmt(p),
                    img.as_ref().map(fmt).unwrap_or_else(|er| er.to_string())
                ),
                json!({"p": pt(p), "norm": nrm}),
            )
        });
        let q = match model.g_v(e.m_u, &model.r_uw(e, p)) {
            Ok(q) => q,
            Err(err) => {
                // g_u is defined on R² − {0}: an error here is an offence of the proof step.
                step.error(OnError::Offence, &err, || {
                    Witness::new(
                        format!("p = {}: g_u∘R_(u,w)(p) failed: {err}", fmt(p)),
                        json!({"p": pt(p)}),
                    )
                });
                continue;
            }
        };
        {
            let th = angle_of(&q).unwrap_or(0.0);
            let ok = th.abs() < std::f64::consts::PI / 3.0;
            step.holds(ok, || {
                Witness::new(
                    format!(
                        "p = {}: q = g_u∘R_(u,w)(p) = {} has θ = {th:.6} ∉ (−π/3, π/3)",
                        fmt(p),
                        fmt(&q)
                    ),
                    json!({"p": pt(p), "q": pt(&q), "theta": th}),
                )
            });
        }
    }
    let note = format!(
        "samples {}; min |g_(u,w)(p)| = {min_norm:.6}, δ = {delta:.6}; tolerance = {GV_COND}·amp·ε",
        s.counts_string()
    );
    vec![m.finish(note.clone()), step.finish(note)]
}

/// P4.1.3: g_(u,w)(Ω_u − {0}) ∩ (Ω_w − {0}) ≠ ∅, and g_(u,w)⁻¹ = g_(w,u) there, checked as
/// g_(w,u)(g_(u,w)(p)) = p and g_(u,w)⁻¹(t) = g_(w,u)(t) (stated formula) for every sample p ∈
/// Ω_u − {0} whose image t lies in Ω_w − {0}. Returns [nonempty, inverse, inverse restricted].
pub fn check_p4_1_3<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = ROUNDTRIP_COND * amp(&[e.m_u, e.m_w]) * eps;
    let mut ne = Check::sampled(
        "P4.1.3",
        format!("g_(u,w)(Ω_u − {{0}}) ∩ (Ω_w − {{0}}) ≠ ∅ ({e:?})"),
        seed,
        0.0,
    );
    let name = format!("g_(u,w)⁻¹ = g_(w,u) on g_(u,w)(Ω_u − {{0}}) ∩ Ω_w ({e:?})");
    let mut pair = Restricted::sampled("P4.1.3-inverse", &name, seed, tol);
    let s = omega_u_samples::<S>(e, seed, n, prec);
    let mut hits = 0u64;
    let mut uniform_examined = 0u64;
    let bound = (6.0 * std::f64::consts::PI / e.m_u as f64).min(std::f64::consts::PI);
    let mut pts: Vec<P2<S>> = s.points.iter().map(|(_, p)| p.clone()).collect();
    pts.extend(
        lens_pullbacks(model, e, seed ^ 0x1e75, n, prec)
            .into_iter()
            .map(|(_, p, _)| p),
    );
    for p in &pts {
        if !in_omega_v_punctured(e.m_u, p).is_true() {
            continue;
        }
        let t = match model.g_uw(e, p) {
            Ok(t) => t,
            Err(err) => {
                // g_(u,w) failing on Ω_u − {0} is C4.1.8-guw-bijective's offence; here the
                // sample is outside what can be examined, and counted.
                pair.all.error(OnError::Skip, &err, || {
                    Witness::new(format!("p = {}", fmt(p)), json!({"p": pt(p)}))
                });
                continue;
            }
        };
        uniform_examined += 1;
        if !in_omega_v_punctured(e.m_w, &t).is_true() {
            continue;
        }
        // Any verified point witnesses non-emptiness, whichever sampler produced it (the
        // lens pull-backs are the constructive candidates; a few disk samples may all miss).
        hits += 1;
        let back = model.g_uw_formula(&e.reversed(), &t);
        let stated = model.g_uw_inv(e, &t);
        let d1 = back
            .as_ref()
            .map(|b| b.dist_f64(p))
            .unwrap_or(f64::INFINITY);
        let d2 = match (&back, &stated) {
            (Ok(a), Ok(b)) => a.dist_f64(b),
            _ => f64::INFINITY,
        };
        let dev = dev_max(d1, d2);
        let th = angle_of(&model.r_uw(e, p)).unwrap_or(0.0).abs();
        let w = || {
            Witness::new(
                format!("p = {} (θ(R_(u,w)p) = {th:.6}) ∈ Ω_u, t = g_(u,w)(p) = {} ∈ Ω_w, but g_(w,u)(t) = {} (|g_(w,u)(t) − p| = {d1:.3e}, |g_(w,u)(t) − g_(u,w)⁻¹(t)| = {d2:.3e})", fmt(p), fmt(&t), back.as_ref().map(fmt).unwrap_or_default()),
                json!({"p": pt(p), "t": pt(&t), "back": back.as_ref().map(pt).ok(), "dev": dev}),
            )
        };
        pair.deviation(dev, th < bound - 1e3 * eps * e.m_u as f64, w);
    }
    ne.examined(uniform_examined);
    let conclusive = n >= MIN_EMPTINESS_SAMPLES;
    if hits == 0 && conclusive {
        ne.offend(|| Witness::new(format!("none of {uniform_examined} samples (disk and lens pull-backs) of Ω_u − {{0}} has g_(u,w)(p) ∈ Ω_w − {{0}}"), json!({"examined": uniform_examined})));
    }
    let note = format!("Ω_u samples: {} (+ {} lens pull-backs for the inverse part); {hits} samples (disk and lens pull-backs) map into Ω_w − {{0}}; tolerance = ROUNDTRIP_COND·amp·ε", s.counts_string(), n);
    let domain = format!("p with |θ(R_(u,w)p)| < {bound:.6} (= min(π, 6π/m_u)); for m_u ≤ 10 this is all of g_(u,w)⁻¹(Ω_w)");
    let mut ne = ne.finish(note.clone());
    if hits == 0 && !conclusive {
        ne.adopt_verdict(inconclusive_search(n));
    }
    vec![ne]
        .into_iter()
        .chain(pair.finish(note, domain, e.m_u > 10))
        .collect()
}
