//! Sec. 5.3–5.4: the fit summary (D5.2.1), the weights ω_uv (C5.4-weights-sum-1), |J_v| ≤ 3,
//! supp γ_v (C5.3-support) and regularity of θ_v (measured).

use super::samples::random_in_omega;
use super::*;

/// Sec. 5.2: per-degree least-squares summary (informational; always holds unless a degree
/// could not be factored).
pub fn check_fit(pps: &Pps) -> CheckResult {
    let mut r = Check::new("D5.2.1", "shape functions fitted (rank, κ per degree)");
    let mut notes = Vec::new();
    let mut deficient = false;
    for f in pps.fit_info() {
        r.examined(1);
        notes.push(format!(
            "m={} l={} rows={} unknowns={} rank={} κ={:.2e} κ_eff={:.2e}",
            f.m, f.l, f.rows, f.unknowns, f.rank, f.condition, f.effective_condition
        ));
        deficient |= f.rank < f.unknowns;
    }
    let mut r = r.finish(notes.join("; "));
    if deficient {
        r.restrict("rank-deficient degrees solved in the minimum-norm sense");
    }
    r
}

/// C5.4-weights-sum-1: ω_uv(p) ≥ 0 and Σ_u ω_uv(p) = 1.
pub fn check_weights(pps: &Pps, opts: &SurfaceCheckOptions) -> CheckResult {
    let tol = 8.0 * f64::EPSILON;
    let mut r = Check::sampled(
        "C5.4-weights-sum-1",
        "ω_uv ≥ 0 and Σ_u ω_uv = 1 (Eq. 5.1)",
        opts.seed ^ 0x77,
        tol,
    );
    let mut rng = r.sampler();
    let c = pps.consts_f64();
    for v in examined_vertices(pps, opts.max_vertices) {
        let rad = c.degree(pps.degree(v)).map(|d| d.radius).unwrap_or(0.5);
        for _ in 0..opts.samples_per_vertex {
            let p = random_in_omega(&mut rng, rad, 1.0);
            match pps.weights(v, &P2::new(p[0], p[1]), c) {
                Ok(w) => {
                    let s: f64 = w.iter().map(|x| x.1).sum();
                    let neg = w.iter().any(|x| !(x.1 >= 0.0 && x.1.is_finite()));
                    let wit = || {
                        Witness::new(
                            format!("v={v} p={p:?}: weights {w:?}, sum {s}"),
                            json!({"v": v, "p": p, "sum": s}),
                        )
                    };
                    if neg {
                        r.holds(false, wit);
                    } else {
                        r.deviation((s - 1.0).abs(), wit);
                    }
                }
                Err(e) => r.error(OnError::Offence, &e, || {
                    Witness::new(format!("v={v} p={p:?}: {e}"), json!({"v": v, "p": p}))
                }),
            }
        }
    }
    r.finish("")
}

/// C5.4-J-le-3: |J_v(p)| ≤ 3 ("at most two p-domains overlap with Ω_v at any p").
pub fn check_j_le_3(pps: &Pps, opts: &SurfaceCheckOptions) -> CheckResult {
    let mut r = Check::sampled(
        "C5.4-J-le-3",
        "|J_v(p)| ≤ 3 for p ∈ Ω_v (Sec. 5.4)",
        opts.seed ^ 0x33,
        3.0,
    );
    let mut rng = r.sampler();
    let c = pps.consts_f64();
    for v in examined_vertices(pps, opts.max_vertices) {
        let m = pps.degree(v);
        let rad = c.degree(m).map(|d| d.radius).unwrap_or(0.5);
        for _ in 0..opts.samples_per_vertex {
            let p = random_in_omega(&mut rng, rad, 1.0);
            match pps.terms(v, &P2::new(p[0], p[1]), c, None) {
                Ok(t) => r.deviation(t.len() as f64, || {
                    let us: Vec<u32> = t.iter().map(|t| t.u.0).collect();
                    Witness::new(
                        format!("v={v} (m={m}) p={p:?}: J_v(p) = {us:?}"),
                        json!({"v": v, "m": m, "p": p, "J": us}),
                    )
                }),
                Err(e) => r.error(OnError::Offence, &e, || {
                    Witness::new(
                        format!("v={v} p={p:?}: J_v(p) failed: {e}"),
                        json!({"v": v, "p": p}),
                    )
                }),
            }
        }
    }
    r.finish(format!("membership: {:?}", pps.options.membership))
}

/// C5.3-support: supp γ_v = closure of Ω_v: γ_v > 0 on Ω_v, = 0 outside (f64 and Mp).
pub fn check_support(pps: &Pps, opts: &SurfaceCheckOptions) -> CheckResult {
    let mut r = Check::new(
        "C5.3-support",
        "γ_v > 0 exactly on Ω_v (supp γ_v = closure of Ω_v)",
    );
    let c = pps.consts_f64();
    let cm: Consts<Mp> = pps.consts(opts.mp_prec);
    let mut degs: Vec<u32> = pps.vertices().map(|v| pps.degree(v)).collect();
    degs.sort_unstable();
    degs.dedup();
    let mut f64_gap = 0.0f64;
    for m in degs {
        let Some(v) = pps.vertices().find(|&v| pps.degree(v) == m) else {
            continue;
        };
        let rad = c.degree(m).map(|d| d.radius).unwrap_or(0.5);
        // Radii approaching the rim from inside (1 − 10^-k) and outside.
        for k in 0..=12 {
            for sgn in [-1.0f64, 1.0] {
                let t = rad * (1.0 + sgn * 10f64.powi(-k - 1));
                for a in [0.1f64, 1.3, 2.9] {
                    let p = [t * a.cos(), t * a.sin()];
                    let fail = |what: &str, e: &dyn std::fmt::Display| {
                        let text = format!("m={m} p={p:?}: {what} failed: {e}");
                        move || Witness::new(text, json!({"m": m, "p": p}))
                    };
                    let inside = match pps.in_omega(v, &P2::new(p[0], p[1]), c) {
                        Ok(x) => x,
                        Err(e) => {
                            r.error(OnError::Offence, &e, fail("p ∈ Ω_v", &e));
                            continue;
                        }
                    };
                    let mp = P2::new(Mp::new(opts.mp_prec, p[0]), Mp::new(opts.mp_prec, p[1]));
                    let gm = match pps.gamma(v, &mp, &cm) {
                        Ok(g) => g.sign() == Some(std::cmp::Ordering::Greater),
                        Err(e) => {
                            r.error(OnError::Offence, &e, fail("γ_v (Mp)", &e));
                            continue;
                        }
                    };
                    r.holds(inside == gm, || {
                        Witness::new(
                            format!("m={m} p={p:?}: p ∈ Ω_v is {inside}, γ_v(p) > 0 (mp) is {gm}"),
                            json!({"m": m, "p": p}),
                        )
                    });
                    // The f64 underflow gap is a measurement; an f64 error there is not a
                    // statement about supp γ_v (the Mp evaluation above decides it).
                    let gf = pps.gamma(v, &P2::new(p[0], p[1]), c).unwrap_or(0.0);
                    if inside && gf == 0.0 {
                        f64_gap = f64_gap.max(rad - (p[0] * p[0] + p[1] * p[1]).sqrt());
                    }
                }
            }
        }
    }
    let mut r = r.finish("");
    if f64_gap > 0.0 {
        r.restrict(format!("in f64, γ_v underflows to 0 on the rim annulus of width ≤ {f64_gap:.1e} inside Ω_v (e^(2s) overflows); holds in Mp"));
    }
    r.worst_deviation = Some(f64_gap);
    r
}

/// C5.4-regular (measured, not claimed by the paper): θ_v has a rank-2 Jacobian and the
/// sampled points show no fold (normal flips relative to the vertex normal of S′).
pub fn check_regular(pps: &Pps, opts: &SurfaceCheckOptions) -> CheckResult {
    let mut r = Check::new("C5.4-regular", "θ_v regular (rank-2 Jacobian) [measured]")
        .with_seed(opts.seed ^ 0x1234);
    let mut rng = r.sampler();
    let cj: Consts<Jet<f64>> = pps.consts(53);
    let c = pps.consts_f64();
    // The smallest area element relative to S² (NaN-propagating: a NaN is the worst).
    let mut worst = f64::INFINITY;
    for v in examined_vertices(pps, opts.max_vertices) {
        let rad = c.degree(pps.degree(v)).map(|d| d.radius).unwrap_or(0.5);
        let scale = local_scale(pps, &[v]);
        for _ in 0..(opts.samples_per_vertex / 4).max(2) {
            let p = random_in_omega(&mut rng, rad, 0.99);
            match pps.theta_geometry(v, p, &cj) {
                Ok(g) => {
                    let rel = g.area_element / (scale * scale).max(f64::MIN_POSITIVE);
                    worst = if rel.is_nan() || worst.is_nan() {
                        f64::NAN
                    } else {
                        worst.min(rel)
                    };
                    r.holds(g.area_element > 1e3 * f64::EPSILON * scale * scale, || {
                        Witness::new(
                            format!("v={v} p={p:?}: ‖θ_x × θ_y‖ = {:.3e}", g.area_element),
                            json!({"v": v, "p": p}),
                        )
                    });
                }
                Err(e) => r.error(OnError::Offence, &e, || {
                    Witness::new(
                        format!("v={v} p={p:?}: θ_v geometry failed: {e}"),
                        json!({"v": v, "p": p}),
                    )
                }),
            }
        }
    }
    let mut r =
        r.finish_as_warning("not guaranteed by the paper (Sec. 5.4); reported as a measurement");
    r.worst_deviation = Some(worst);
    r
}
