//! Defs. 4.1.5–4.1.7: Π, the claims about g_v after Def. 4.1.6, and the h-identity of
//! Appendix A.1 (vertex level: no edge configuration needed).

use super::common::*;
use super::smooth::{smooth_test, SmoothSpec};
use crate::construction::maps::*;
use crate::construction::sampling::*;
use crate::numeric::Scalar;
use crate::report::{dev_max, Check, CheckResult, Restricted, Witness};
use serde_json::json;

// =============================================================================================
// Def. 4.1.5 — Π
// =============================================================================================

/// D4.1.5: Π⁻¹∘Π = id on R² − {0}, θ ∈ (−π, π], and θ = π on the negative x-axis (including
/// points with y = −0.0).
pub fn check_d4_1_5_polar<S: Scalar, M: Ppm<S>>(
    model: &M,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let eps = unit_eps::<S>(prec);
    let tol = IDENTITY_COND * eps;
    let mut m = Check::sampled(
        "D4.1.5",
        "Π⁻¹∘Π = id, θ ∈ (−π, π], θ = π on the negative x-axis",
        seed,
        tol,
    );
    let mut s = sample_disk::<S>(seed, n, &S::from_i64(2, prec), &scalar_pi::<S>(prec), prec);
    for k in 0..8 {
        let x = -(1.0 + k as f64) / 4.0;
        s.points.push((
            Category::OnBoundary,
            P2::new(S::from_f64(x, prec), S::from_f64(0.0, prec)),
        ));
        s.points.push((
            Category::OnBoundary,
            P2::new(S::from_f64(x, prec), S::from_f64(-0.0, prec)),
        ));
    }
    let pi = scalar_pi::<S>(prec);
    for (_, p) in &s.points {
        match model.polar(p) {
            Ok(pol) => {
                let back = polar_inv(&pol);
                let d = back.dist_f64(p) / p.norm2().sqrt().to_f64().max(1e-300);
                let in_range = pi.neg().lt(&pol.theta).and(pol.theta.le(&pi));
                let on_neg_axis = p.y.sign() == Some(std::cmp::Ordering::Equal)
                    && p.x.sign() == Some(std::cmp::Ordering::Less);
                let axis_dev = if on_neg_axis {
                    pol.theta.sub(&pi).abs().to_f64()
                } else {
                    0.0
                };
                let dev = if in_range.is_false() {
                    f64::INFINITY
                } else {
                    dev_max(d, axis_dev)
                };
                m.deviation(dev, || {
                    Witness::new(
                        format!("p = {} (y sign negative: {}): θ = {:.17e}, relative round-trip error {d:.3e}", fmt(p), p.y.to_f64().is_sign_negative(), pol.theta.to_f64()),
                        json!({"p": pt(p), "theta": pol.theta.to_f64()}),
                    )
                });
            }
            Err(err) => m.offend(|| {
                Witness::new(format!("Π({}) failed: {err}", fmt(p)), json!({"p": pt(p)}))
            }),
        }
    }
    let note = format!(
        "samples: {} + 16 on the negative x-axis (±0.0); tolerance = {IDENTITY_COND}·ε relative",
        s.counts_string()
    );
    m.finish(note)
}

// =============================================================================================
// Claims about g_v (running text after Def. 4.1.6)
// =============================================================================================

/// C4.1.6-gv-bijective: "g_v is bijective and its inverse is g_v⁻¹ = Π⁻¹∘f_v⁻¹∘Π" on R² − {0}:
/// checks g_v⁻¹∘g_v = id and g_v∘g_v⁻¹ = id. Returns the as-written result and the result on
/// the restricted domains {|θ| < 6π/m_v} (for g_v⁻¹∘g_v) and {|θ| < m_vπ/6} (for g_v∘g_v⁻¹).
pub fn check_c4_1_6_gv_bijective<S: Scalar, M: Ppm<S>>(
    model: &M,
    mdeg: u32,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let tol = GV_COND * amp(&[mdeg]) * eps;
    let name = format!("g_v (m_v = {mdeg}) bijective with the stated inverse on R² − {{0}}");
    let mut pair = Restricted::sampled("C4.1.6-gv-bijective", &name, seed, tol);
    let s = sample_disk::<S>(seed, n, &S::from_i64(1, prec), &scalar_pi::<S>(prec), prec);
    let bound_a = (6.0 * std::f64::consts::PI / mdeg as f64).min(std::f64::consts::PI);
    let bound_b = (mdeg as f64 * std::f64::consts::PI / 6.0).min(std::f64::consts::PI);
    let margin = 1e3 * eps * mdeg as f64;
    for (_, p) in &s.points {
        let th = angle_of(p).unwrap_or(0.0).abs();
        let ga = model.g_v(mdeg, p).and_then(|q| model.g_v_inv(mdeg, &q));
        let gb = model.g_v_inv(mdeg, p).and_then(|q| model.g_v(mdeg, &q));
        for (which, r, bound) in [("g_v⁻¹∘g_v", ga, bound_a), ("g_v∘g_v⁻¹", gb, bound_b)]
        {
            let dev = match &r {
                Ok(q) => q.dist_f64(p),
                Err(_) => f64::INFINITY,
            };
            let w = || {
                Witness::new(
                    format!(
                        "{which}({}) = {} (θ = {th:.6}), error {dev:.3e}",
                        fmt(p),
                        r.as_ref().map(fmt).unwrap_or_default()
                    ),
                    json!({"map": which, "p": pt(p), "image": r.as_ref().map(pt).ok(), "dev": dev}),
                )
            };
            pair.deviation(dev, th < bound - margin, w);
        }
    }
    let note = format!(
        "samples of the disk of radius 1: {}; tolerance = {GV_COND}·max(1,m/6,6/m)·ε",
        s.counts_string()
    );
    let domain = format!("g_v⁻¹∘g_v = id on {{0 < r, |θ| < {bound_a:.6}}} (= min(π, 6π/m_v)); g_v∘g_v⁻¹ = id on {{0 < r, |θ| < {bound_b:.6}}} (= min(π, m_vπ/6)); both on all of R² − {{0}} iff m_v = 6");
    pair.finish(note, domain, mdeg != 6)
}

/// C4.1.6-gv-smooth: "Since f_v is clearly C^∞, so is g_v" on R² − {0}. Jacobian and jump
/// tests on samples including both sides of Π's cut (the negative x-axis). Second result: the
/// restricted domain R² − (closed negative x-axis) (no stencil or pair crossing the cut).
pub fn check_c4_1_6_gv_smooth<S: Scalar, M: Ppm<S>>(
    model: &M,
    mdeg: u32,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let eps = unit_eps::<S>(prec);
    let k = mdeg as f64 / 6.0;
    let c = f_v_radial_factor::<f64>(mdeg, 53);
    let lip = c * k.max(1.0);
    let name = format!("g_v (m_v = {mdeg}) is C^∞ on R² − {{0}}");
    let mut pair = Restricted::sampled("C4.1.6-gv-smooth", &name, seed, 1.0);
    let pi = scalar_pi::<S>(prec);
    let s = sample_disk::<S>(seed, n, &S::from_i64(1, prec), &pi, prec);
    let f = |p: &P2<S>| model.g_v(mdeg, p);
    let jac = |p: &P2<S>| g_v_jacobian(mdeg, p);
    let spec = SmoothSpec {
        f: &f,
        jac: &jac,
        lip,
        kmax: k,
        inner_radius: None,
    };
    let pts: Vec<P2<S>> = s.points.iter().map(|(_, p)| p.clone()).collect();
    let partners: Vec<(P2<S>, P2<S>)> = s
        .points
        .iter()
        .filter(|(c, _)| matches!(c, Category::NearCutCcw | Category::NearCutCw))
        .map(|(_, p)| (p.clone(), reflect(p, &S::from_i64(0, prec))))
        .collect();
    let (a1, a2) = smooth_test(&mut pair.all, &spec, &pts, &partners, prec);
    // Restricted: stencils must stay off the cut: angular distance from π at least 4·ε^{1/3}.
    let cb = eps.cbrt();
    let pts_r: Vec<P2<S>> = pts
        .iter()
        .filter(|p| {
            angle_of(*p)
                .map(|t| std::f64::consts::PI - t.abs() > 4.0 * cb)
                .unwrap_or(false)
        })
        .cloned()
        .collect();
    let (b1, _) = smooth_test(&mut pair.restricted, &spec, &pts_r, &[], prec);
    let note = format!(
        "samples {} ; Jacobian tests {a1}, jump pairs across the cut {a2}; Lipschitz bound L = cos(π/6)/cos(π/m)·max(1, m/6) = {lip:.6}; FD tolerance = {FD_COND}·(h²·L·max(1,k)²/(6r²) + ε(|F(p)| + L r)/h), h = ε^(1/3)·r (deviations reported relative to it, tolerance 1); restricted run: {b1} Jacobian tests",
        s.counts_string()
    );
    let domain = "R² − {(x, 0) : x ≤ 0} (g_v is C^∞ across the cut iff 6 | m_v)".to_string();
    pair.finish(note, domain, mdeg % 6 != 0)
}

// =============================================================================================
// h (Def. 4.1.7) and the h-identity of Appendix A.1
// =============================================================================================

/// C4.1.7-h-identity: h ∘ M_{−π/3} ∘ h ∘ M_{−π/3} ∘ h ∘ M_{−π/3} = id on R² (proof of L4.2.2),
/// and h ∘ h = id.
pub fn check_c4_1_7_h_identity<S: Scalar, M: Ppm<S>>(
    model: &M,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let eps = unit_eps::<S>(prec);
    let tol = IDENTITY_COND * eps * 3.0;
    let mut m = Check::sampled(
        "C4.1.7-h-identity",
        "(h∘M_{−π/3})³ = id and h∘h = id on R²",
        seed,
        tol,
    );
    let s = sample_disk::<S>(seed, n, &S::from_i64(2, prec), &scalar_pi::<S>(prec), prec);
    for (_, p) in &s.points {
        let mut q = p.clone();
        for _ in 0..3 {
            q = model.h(&rotate_frac(&q, -1, 6));
        }
        let d1 = q.dist_f64(p);
        let d2 = model.h(&model.h(p)).dist_f64(p);
        m.deviation(dev_max(d1, d2), || {
            Witness::new(
                format!(
                    "p = {}: (h∘M)³(p) = {}, |h∘h(p) − p| = {d2:.3e}",
                    fmt(p),
                    fmt(&q)
                ),
                json!({"p": pt(p), "lhs": pt(&q)}),
            )
        });
    }
    m.finish(format!(
        "samples of the disk of radius 2: {}; tolerance = 3·{IDENTITY_COND}·ε (|p| ≤ 2)",
        s.counts_string()
    ))
}
