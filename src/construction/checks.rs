//! Conformance checks of Chapter 4 on configurations (no mesh needed).
//!
//! Every check is generic over the scalar `S` and over the model `M: Ppm<S>` (the paper's
//! construction is [`Paper`]; tests pass models with planted faults). Every check samples
//! deterministically from `seed`, and reports the number of samples examined (with per-category
//! counts in the note), the worst deviation, and the tolerance used. Tolerances are
//! `COND · ε` with ε the unit roundoff of the precision in use and `COND` a named, stated
//! condition factor; they are never tuned to make a check pass.
//!
//! Statements that fail as written are reported as `Fails` with witnesses; where the paper's
//! statement holds on a smaller domain, a second result with the suffix `[restricted]` checks
//! it there and reports `HoldsRestricted { domain }`.

use super::maps::*;
use super::sampling::*;
use super::scalar::{Scalar, Trit};
use crate::report::{dev_max, Check, CheckResult, OnError, Restricted, Verdict, Witness};
use serde_json::json;

/// Condition factor of simple identities (Π round trip, the h-identity): a few dozen
/// operations, each with relative error ≤ ε, on points of norm ≤ 2.
pub const IDENTITY_COND: f64 = 64.0;
/// Condition factor of the g_v round trips: 256 · max(1, m/6, 6/m) (angle scaled by m/6 then
/// by 6/m; trigonometric functions of angles up to m·π/6).
pub const GV_COND: f64 = 256.0;
/// Condition factor of the central-difference Jacobian test (Taylor remainder h²/6·|f'''| with
/// |f'''| ≤ L·max(1,k)²/r², plus rounding ε(|F(p)| + L·r)/h), a safety factor of 16.
pub const FD_COND: f64 = 16.0;
/// Condition factor of the jump test: rounding of |f(a) − f(b)| is ≤ 64·ε·(|f| + L·|p|) (the
/// error of the early stages, ε·|p|, stretched by up to L; as in the FD test).
pub const JUMP_COND: f64 = 64.0;
/// Condition factor of compositions of several g_(u,w) (P4.2.3, L4.2.2, L4.2.3, P4.2.4):
/// 2^14 · max(1, m/6) over the degrees involved.
pub const COMPOSITE_COND: f64 = 16384.0;

fn pt<S: Scalar>(p: &P2<S>) -> serde_json::Value {
    json!([p.x.to_f64(), p.y.to_f64()])
}
fn fmt<S: Scalar>(p: &P2<S>) -> String {
    format!("({:.17e}, {:.17e})", p.x.to_f64(), p.y.to_f64())
}
fn amp(ms: &[u32]) -> f64 {
    ms.iter()
        .map(|&m| (m as f64 / 6.0).max(6.0 / m as f64))
        .fold(1.0, f64::max)
}
fn angle_of<S: Scalar>(p: &P2<S>) -> Option<f64> {
    polar(p).ok().map(|q| q.theta.to_f64())
}
/// Reflection of p across the line through 0 at angle `a`.
fn reflect<S: Scalar>(p: &P2<S>, a: &S) -> P2<S> {
    let q = rotate(p, &a.neg());
    rotate(&P2::new(q.x, q.y.neg()), a)
}
fn zero_pt<S: Scalar>(prec: u32) -> P2<S> {
    P2::new(S::from_i64(0, prec), S::from_i64(0, prec))
}
fn scalar_pi<S: Scalar>(prec: u32) -> S {
    S::pi(prec)
}
fn unit_eps<S: Scalar>(prec: u32) -> f64 {
    S::from_i64(1, prec).epsilon()
}

/// Samples of Ω_u − {0} with the cut ray at the angle where g_u ∘ R_(u,w) is cut: the ray
/// opposite u'_i, angle π + 2πi/m_u.
fn omega_u_samples<S: Scalar>(e: &EdgeConfig, seed: u64, n: usize, prec: u32) -> Samples<S> {
    let r = omega_radius::<S>(e.m_u, prec);
    let cut = scalar_pi::<S>(prec).mul(&S::from_ratio(
        e.m_u as i64 + 2 * e.i as i64,
        e.m_u as i64,
        prec,
    ));
    sample_disk(seed, n, &r, &cut, prec)
}

/// Points of Ω_uw obtained by pulling the canonical-lens samples back by R_(u,w)⁻¹ ∘ g_u⁻¹
/// (candidates: membership is still decided by the model's literal Def. 4.1.9 test).
fn lens_pullbacks<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>, P2<S>)> {
    let lens = sample_lens::<S>(seed, n, prec);
    let mut out = Vec::new();
    for (c, q) in lens.points {
        if let Ok(a) = model.g_v_inv(e.m_u, &q) {
            out.push((c, model.r_uw_inv(e, &a), q));
        }
    }
    out
}

fn counts_of(cats: &[Category]) -> String {
    let mut m = std::collections::BTreeMap::new();
    for c in cats {
        *m.entry(*c).or_insert(0usize) += 1;
    }
    m.iter()
        .map(|(c, n)| format!("{c:?} {n}"))
        .collect::<Vec<_>>()
        .join(", ")
}

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

/// Generic smoothness test of a map F on sampled points: (a) the analytic Jacobian `jac`
/// against central differences of `f` with step h = ε^{1/3}·|p|; (b) for each point with a
/// partner across a cut, the jump ratio |F(a) − F(b)|/|a − b| against the Lipschitz bound L
/// that any C¹ map with |DF| ≤ L satisfies. `lip` = L; `kmax` bounds the angular scaling.
struct SmoothSpec<'a, S> {
    f: &'a dyn Fn(&P2<S>) -> Result<P2<S>, MapError>,
    jac: &'a dyn Fn(&P2<S>) -> Result<Jac<S>, MapError>,
    lip: f64,
    kmax: f64,
    /// For a composite F = A∘B whose outer factor A applies Π at B(p) (g_(u,w): g_w⁻¹ at
    /// h∘g_u∘R_(u,w)(p)), the radius |B(p)|. The Taylor remainder of the central difference
    /// scales with 1/ρ² for the smallest radius ρ at which a polar map is evaluated, not only
    /// 1/|p|²: near the corners of the lens, |B(p)| is a fraction of |p| (issue 8: randomized
    /// surfaces of degree ≥ 9 gave false "not smooth" verdicts for L4.2.4 and P4.1.1).
    inner_radius: Option<&'a dyn Fn(&P2<S>) -> Option<f64>>,
}

fn smooth_test<S: Scalar>(
    m: &mut Check,
    spec: &SmoothSpec<S>,
    pts: &[P2<S>],
    partners: &[(P2<S>, P2<S>)],
    prec: u32,
) -> (u64, u64) {
    let eps = unit_eps::<S>(prec);
    let (mut fd_n, mut jump_n) = (0u64, 0u64);
    let cbrt = eps.cbrt();
    for p in pts {
        let r = p.norm2().sqrt().to_f64();
        if r == 0.0 {
            continue;
        }
        let hh = cbrt * r;
        let hs = S::from_f64(hh, prec);
        let z = S::from_i64(0, prec);
        let two_h = hs.add(&hs);
        let dirs = [P2::new(hs.clone(), z.clone()), P2::new(z, hs.clone())];
        let skip_w = || Witness::new(format!("p = {}", fmt(p)), json!({"p": pt(p)}));
        let jac = match (spec.jac)(p) {
            Ok(j) => j,
            Err(err) => {
                m.error(
                    OnError::Skip,
                    format_args!("Jacobian at {}: {err}", fmt(p)),
                    skip_w,
                );
                continue;
            }
        };
        let mut col = Vec::new();
        for d in &dirs {
            match ((spec.f)(&p.add(d)), (spec.f)(&p.sub(d))) {
                (Ok(a), Ok(b)) => col.push(P2::new(
                    a.x.sub(&b.x).div(&two_h),
                    a.y.sub(&b.y).div(&two_h),
                )),
                (Err(err), _) | (_, Err(err)) => {
                    // The stencil leaves the domain of F: no Jacobian test at p.
                    m.error(
                        OnError::Skip,
                        format_args!("stencil at {}: {err}", fmt(p)),
                        skip_w,
                    );
                    break;
                }
            }
        }
        if col.len() < 2 {
            continue;
        }
        fd_n += 1;
        let mut dev = 0.0f64;
        for c in 0..2 {
            dev = dev_max(dev, jac[0][c].sub(&col[c].x).abs().to_f64());
            dev = dev_max(dev, jac[1][c].sub(&col[c].y).abs().to_f64());
        }
        let k3 = spec.kmax.max(1.0).powi(2);
        let rho = spec.inner_radius.and_then(|g| g(p)).map_or(r, |q| q.min(r));
        let fp = (spec.f)(p)
            .map(|q| q.norm2().sqrt().to_f64())
            .unwrap_or(0.0);
        let tol = FD_COND
            * (hh * hh * spec.lip * k3 / (6.0 * rho * rho) + eps * (fp + spec.lip * r) / hh);
        let rel = dev / tol * m.tol();
        m.deviation(rel, || {
            Witness::new(
                format!("Jacobian at p = {} (|p| = {r:.3e}): analytic vs central difference (step {hh:.2e}) differ by {dev:.3e} (> {tol:.3e})", fmt(p)),
                json!({"p": pt(p), "fd_step": hh, "diff": dev, "fd_tol": tol}),
            )
        });
    }
    for (a, b) in partners {
        let (fa, fb) = match ((spec.f)(a), (spec.f)(b)) {
            (Ok(x), Ok(y)) => (x, y),
            (Err(err), _) | (_, Err(err)) => {
                let w = || {
                    Witness::new(
                        format!("a = {}, b = {}", fmt(a), fmt(b)),
                        json!({"a": pt(a), "b": pt(b)}),
                    )
                };
                m.error(
                    OnError::Skip,
                    format_args!("jump pair at {}: {err}", fmt(a)),
                    w,
                );
                continue;
            }
        };
        let dab = a.dist_f64(b);
        if dab == 0.0 {
            continue;
        }
        jump_n += 1;
        let ratio = fa.dist_f64(&fb) / dab;
        // Rounding error of one evaluation of F, as in the FD test: ε·(|F(p)| + L·|p|). The
        // L·|p| part matters when F contracts (e.g. P4.1.1 with m_u = 24, m_w = 3: |F| ≈ 0.09
        // while L·|p| ≈ 3.9): the error made in the early polar stages, of size ε·|p|, is
        // stretched by up to L, and with |F| alone the allowance was exceeded by pure rounding.
        let scale = fa.norm2().sqrt().to_f64().max(fb.norm2().sqrt().to_f64())
            + spec.lip * a.norm2().sqrt().to_f64().max(b.norm2().sqrt().to_f64());
        // L is evaluated in f64 and the ratio is formed in f64: allow 4 f64 ulps for that.
        let allowed = spec.lip * (1.0 + 4.0 * f64::EPSILON) + JUMP_COND * eps * scale / dab;
        // Express as "deviation over tolerance" on the meter's scale; a NaN ratio stays NaN.
        let dev = if ratio.is_nan() {
            f64::NAN
        } else if ratio > allowed {
            m.tol() * (1.0 + ratio / allowed)
        } else {
            0.0
        };
        m.deviation(dev, || {
            Witness::new(
                format!(
                    "jump across the cut: a = {}, b = {} (|a − b| = {dab:.3e}) have images {} and {} (|F(a) − F(b)| = {:.3e}); ratio {ratio:.3e} > Lipschitz bound {allowed:.3e}",
                    fmt(a), fmt(b), fmt(&fa), fmt(&fb), fa.dist_f64(&fb)
                ),
                json!({"a": pt(a), "b": pt(b), "Fa": pt(&fa), "Fb": pt(&fb), "ratio": ratio, "bound": allowed}),
            )
        });
    }
    (fd_n, jump_n)
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
fn guw_inner_radius<S: Scalar, M: Ppm<S>>(model: &M, e: &EdgeConfig, p: &P2<S>) -> Option<f64> {
    let q = model.g_v(e.m_u, &model.r_uw(e, p)).ok()?;
    Some(model.h(&q).norm2().sqrt().to_f64())
}

fn guw_lipschitz(e: &EdgeConfig) -> (f64, f64) {
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
        &format!("(0,0) ∉ g_(u,w)(Ω_u − {{0}}) ({e:?})"),
        seed,
        tol,
    );
    let mut step = Check::sampled(
        "P4.1.2-proof-step",
        &format!("proof step: θ(g_u∘R_(u,w)(p)) ∈ (−π/3, π/3) on Ω_u − {{0}} ({e:?})"),
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
        &format!("g_(u,w)(Ω_u − {{0}}) ∩ (Ω_w − {{0}}) ≠ ∅ ({e:?})"),
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
    if hits == 0 {
        ne.offend(|| Witness::new(format!("none of {uniform_examined} samples (disk and lens pull-backs) of Ω_u − {{0}} has g_(u,w)(p) ∈ Ω_w − {{0}}"), json!({"examined": uniform_examined})));
    }
    let note = format!("Ω_u samples: {} (+ {} lens pull-backs for the inverse part); {hits} samples (disk and lens pull-backs) map into Ω_w − {{0}}; tolerance = ROUNDTRIP_COND·amp·ε", s.counts_string(), n);
    let domain = format!("p with |θ(R_(u,w)p)| < {bound:.6} (= min(π, 6π/m_u)); for m_u ≤ 10 this is all of g_(u,w)⁻¹(Ω_w)");
    vec![ne.finish(note.clone())]
        .into_iter()
        .chain(pair.finish(note, domain, e.m_u > 10))
        .collect()
}

// =============================================================================================
// Defs. 4.1.9 / 4.1.10 and Sec. 4.2 (edge level)
// =============================================================================================

/// Samples of Ω_u for an edge: the disk sampler (cut at the ray opposite u'_i) and the lens
/// pull-backs, with category labels.
fn edge_domain_samples<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>)> {
    let mut v: Vec<(Category, P2<S>)> = omega_u_samples::<S>(e, seed, n, prec).points;
    v.extend(
        lens_pullbacks(model, e, seed ^ 0x1e75, n, prec)
            .into_iter()
            .map(|(c, p, _)| (c, p)),
    );
    v
}

/// D4.1.9-lens: Def. 4.1.9 read literally agrees with the Sec. 6.1.3 canonical-lens test.
/// Disagreements within `LENS_COND·ε` of the lens boundary (in the g_u∘R_(u,w) frame) are
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
        &format!("Def. 4.1.9 (literal) ⇔ Sec. 6.1.3 lens test ({e:?})"),
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

/// Points of Ω_uw (literal Def. 4.1.9) from the edge samples.
fn omega_uw_points<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>)> {
    edge_domain_samples(model, e, seed, n, prec)
        .into_iter()
        .filter(|(_, p)| model.in_omega_uw_literal(e, p).is_true())
        .collect()
}

/// P4.2.1: Ω_uw ≠ ∅ ⇔ Ω_wu ≠ ∅ (witnesses searched by sampling both domains).
pub fn check_p4_2_1<S: Scalar, M: Ppm<S>>(
    model: &M,
    e: &EdgeConfig,
    seed: u64,
    n: usize,
    prec: u32,
) -> CheckResult {
    let mut m = Check::sampled("P4.2.1", &format!("Ω_uw ≠ ∅ ⇔ Ω_wu ≠ ∅ ({e:?})"), seed, 0.0);
    let a = omega_uw_points(model, e, seed, n, prec).len();
    let b = omega_uw_points(model, &e.reversed(), seed ^ 0x77, n, prec).len();
    m.examined(2 * n as u64);
    if (a == 0) != (b == 0) {
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
        &format!("φ_uw∘φ_wu = id on Ω_uw ({e:?})"),
        seed,
        tol,
    );
    let mut d = Check::sampled(
        "D4.1.10",
        &format!("φ_wu maps Ω_uw into Ω_wu ({e:?})"),
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
                d.offend(|| {
                    Witness::new(
                        format!("φ_wu({}) failed: {err}", fmt(p)),
                        json!({"p": pt(p)}),
                    )
                });
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
    let mut m = Check::sampled("L4.2.4", &format!("φ_wu is C^∞ on Ω_uw ({e:?})"), seed, 1.0);
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
        &format!("Hausdorff separation of ∂Ω_uw ∩ Ω_u and ∂Ω_wu ∩ Ω_w ({e:?})"),
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
        r.verdict = Verdict::Skipped {
            reason: err.to_string(),
        };
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

// =============================================================================================
// Triangle level: L4.2.1, L4.2.2, P4.2.4
// =============================================================================================

/// Points of Ω_x near the gluing domains of the two edges x→a, x→b: disk samples of Ω_x plus
/// lens pull-backs for both edges.
fn star_samples<S: Scalar, M: Ppm<S>>(
    model: &M,
    edges: &[EdgeConfig],
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<(Category, P2<S>)> {
    let mut v: Vec<(Category, P2<S>)> = Vec::new();
    if let Some(e0) = edges.first() {
        v.extend(omega_u_samples::<S>(e0, seed, n, prec).points);
    }
    for (k, e) in edges.iter().enumerate() {
        v.extend(
            lens_pullbacks(model, e, seed ^ (0x51 + k as u64), n, prec)
                .into_iter()
                .map(|(c, p, _)| (c, p)),
        );
    }
    v
}

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
        &format!("φ_xu⁻¹(Ω_xu ∩ Ω_xw) ⊆ Ω_uw ({t:?})"),
        seed,
        tol,
    );
    let mut l2 = Check::sampled(
        "L4.2.2",
        &format!("φ_wu = φ_wx∘φ_xu on φ_xu⁻¹(Ω_xu ∩ Ω_xw) ({t:?})"),
        seed,
        tol,
    );
    let mut eq = Check::sampled(
        "L4.2.1-proof-equality",
        &format!("Ω_ux ∩ Ω_uw ⊆ φ_xu⁻¹(Ω_xu ∩ Ω_xw) ({t:?})"),
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
        &format!("M_∓π/3∘g_u∘R(Ω_uw/uz) = g_u∘R(Ω_uz/uw) ({e_uw:?}, {e_uz:?})"),
        seed,
        tol,
    );
    let mut b = Check::sampled(
        "P4.2.4(iii,iv)",
        &format!("Ω_uz = M_{{−2π/m_u}}(Ω_uw), Ω_uw = M_{{2π/m_u}}(Ω_uz) ({e_uw:?}, {e_uz:?})"),
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

/// The star of a vertex x for C5.4 / non-adjacent disjointness: degree m and, for each label
/// k = 0..m−1, the neighbour's degree and the label s_n(x) of x in the neighbour's star.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct StarConfig {
    /// m, the degree of x.
    pub m: u32,
    /// For label k: (degree of the k-th neighbour n, label s_n(x)).
    pub nbrs: Vec<(u32, u32)>,
}

impl StarConfig {
    /// All neighbours of degree `m_nbr`, with x at label 0 in each.
    pub fn uniform(m: u32, m_nbr: u32) -> Result<Self, ConfigError> {
        let s = StarConfig {
            m,
            nbrs: (0..m).map(|_| (m_nbr, 0)).collect(),
        };
        s.edges().map(|_| s)
    }
    /// Oriented edges x → n_k.
    pub fn edges(&self) -> Result<Vec<EdgeConfig>, ConfigError> {
        if self.nbrs.len() != self.m as usize {
            return Err(ConfigError::LabelOutOfRange {
                label: self.nbrs.len() as u32,
                m: self.m,
            });
        }
        self.nbrs
            .iter()
            .enumerate()
            .map(|(k, &(mn, j))| EdgeConfig::new(self.m, k as u32, mn, j))
            .collect()
    }
}

/// C5.4-at-most-two and C4.2-nonadjacent-disjoint: at every sampled point of Ω_x at most two
/// gluing domains Ω_xn contain it, and Ω_xa ∩ Ω_xb = ∅ when the labels of a, b differ by ≥ 2
/// (mod m_x). `use_lens` switches membership from the literal Def. 4.1.9 to the Sec. 6.1.3 test.
/// Returns [at-most-two, nonadjacent-disjoint].
pub fn check_star_overlaps<S: Scalar, M: Ppm<S>>(
    model: &M,
    star: &StarConfig,
    use_lens: bool,
    seed: u64,
    n: usize,
    prec: u32,
) -> Vec<CheckResult> {
    let suffix = if use_lens { "[sec6.1.3]" } else { "" };
    let mut a = Check::sampled(
        &format!("C5.4-at-most-two{suffix}"),
        &format!(
            "at most two Ω_xn contain any point of Ω_x (m_x = {})",
            star.m
        ),
        seed,
        0.0,
    );
    let mut b = Check::sampled(
        &format!("C4.2-nonadjacent-disjoint{suffix}"),
        &format!("Ω_xa ∩ Ω_xb = ∅ for non-adjacent a, b (m_x = {})", star.m),
        seed,
        0.0,
    );
    let edges = match star.edges() {
        Ok(e) => e,
        Err(err) => {
            a.offend(|| Witness::new(format!("invalid star: {err}"), json!({})));
            return vec![a.finish(String::new()), b.finish(String::new())];
        }
    };
    let pts = star_samples(model, &edges, seed, n, prec);
    let mm = star.m as i64;
    for (_, p) in &pts {
        let inside: Vec<u32> = edges
            .iter()
            .filter(|e| {
                let t = if use_lens {
                    model.in_omega_uw_lens(e, p)
                } else {
                    model.in_omega_uw_literal(e, p)
                };
                t.is_true()
            })
            .map(|e| e.i)
            .collect();
        a.holds(inside.len() <= 2, || {
            Witness::new(
                format!("p = {} lies in Ω_xn for labels {inside:?}", fmt(p)),
                json!({"p": pt(p), "labels": inside}),
            )
        });
        for (ka, la) in inside.iter().enumerate() {
            for lb in &inside[ka + 1..] {
                let d = (*la as i64 - *lb as i64).rem_euclid(mm);
                let adjacent = d == 1 || d == mm - 1;
                b.holds(adjacent, || Witness::new(format!("p = {} lies in Ω_xa ∩ Ω_xb for non-adjacent labels {la}, {lb} (θ = {:.6})", fmt(p), angle_of(p).unwrap_or(0.0)), json!({"p": pt(p), "a": la, "b": lb})));
            }
        }
        if inside.len() < 2 {
            b.examined(1);
        }
    }
    let note = format!(
        "{} samples of Ω_x (disk + lens pull-backs for every neighbour); membership by {}",
        pts.len(),
        if use_lens {
            "the Sec. 6.1.3 lens test"
        } else {
            "the literal Def. 4.1.9"
        }
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
            r.verdict = Verdict::Skipped {
                reason: err.to_string(),
            };
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

/// Helper for reports: the origin at precision `prec` (Π is undefined there).
pub fn origin<S: Scalar>(prec: u32) -> P2<S> {
    zero_pt(prec)
}

/// Membership as a `Trit` for the reports of the lead's mesh layer (literal Def. 4.1.9).
pub fn membership<S: Scalar>(pair: &VertexPair, p: &P2<S>) -> Trit {
    Paper.in_omega_pair(pair, p)
}
