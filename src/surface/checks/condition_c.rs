//! Condition (C) of Def. 3.5.1 for the PPS (T5.4.1, f64 and multi-precision), its smooth form
//! C5.4-smooth (jets), and D5.4.1 (production membership and φ vs the literal Defs. 4.1.9/4.1.10).

use super::samples::{overlap_points, random_in_omega};
use super::tolerance::dist3;
use super::*;

/// D5.4.1: the production membership test / transition (branch + lens) agrees with the
/// literal Def. 4.1.9 / Def. 4.1.10 of `construction` (PpmGluing).
pub fn check_membership_literal(
    pps: &Pps,
    g: &PpmGluing,
    opts: &SurfaceCheckOptions,
) -> CheckResult {
    let mut r = Check::new(
        "D5.4.1",
        "Γ_uv, Ψ_uv domains: p ∈ Ω_vu and φ_uv(p) agree with literal Def. 4.1.9/4.1.10",
    )
    .with_seed(opts.seed ^ 0x51);
    let mut rng = r.sampler();
    let c = pps.consts_f64();
    for v in examined_vertices(pps, opts.max_vertices.map(|n| n.min(200)).or(Some(200))) {
        let m = pps.degree(v);
        let rad = c.degree(m).map(|d| d.radius).unwrap_or(0.5);
        let tol = COND * (m as f64 / 6.0).max(1.0) * f64::EPSILON;
        for _ in 0..opts.samples_per_vertex {
            let p = random_in_omega(&mut rng, rad, 1.0);
            let pp = P2::new(p[0], p[1]);
            for i in 0..m {
                let u = pps.link(v, i);
                let lit = g.in_omega_uw(v, u, &pp).map(|t| t.is_true());
                let ours = pps.phi_label(v, i, &pp, c);
                let fail = |what: &str, e: &dyn std::fmt::Display| {
                    let text = format!("v={v} u={u} p={p:?}: {what} failed: {e}");
                    move || Witness::new(text, json!({"v": v, "u": u, "p": p}))
                };
                match (lit, ours) {
                    (Err(e), _) => r.error(OnError::Offence, &e, fail("literal Def. 4.1.9", &e)),
                    (_, Err(e)) => r.error(OnError::Offence, &e, fail("production φ", &e)),
                    (Ok(true), Ok(Some(q))) => match g.phi(u, v, &pp) {
                        Ok(ql) => {
                            let d = ql.dist_f64(&q);
                            r.deviation_within(d, tol, || {
                                Witness::new(
                                    format!("v={v} u={u} p={p:?}: φ differs by {d:.3e}"),
                                    json!({"v": v, "u": u, "p": p, "dev": d}),
                                )
                            });
                        }
                        Err(e) => r.error(OnError::Offence, &e, fail("literal Def. 4.1.10", &e)),
                    },
                    (Ok(false), Ok(None)) => r.examined(1),
                    (Ok(a), Ok(b)) => r.holds(false, || {
                        Witness::new(
                            format!(
                                "v={v} (m={m}) u={u} p={p:?}: literal {a}, production {}",
                                b.is_some()
                            ),
                            json!({"v": v, "u": u, "p": p, "literal": a}),
                        )
                    }),
                }
            }
        }
    }
    r.finish("")
}

/// T5.4.1 / condition (C) of Def. 3.5.1: θ_v(p) = θ_u(φ_uv(p)) for p ∈ Ω_vu, in f64.
pub fn check_condition_c(pps: &Pps, opts: &SurfaceCheckOptions) -> CheckResult {
    let vs = examined_vertices(pps, opts.max_vertices);
    let scope = format!(
        "{} of {} vertices (cap {}), ≤ {} points each",
        vs.len(),
        pps.vertices().count(),
        opts.max_vertices
            .map_or("none".to_string(), |n| n.to_string()),
        opts.samples_per_vertex
    );
    check_c_generic::<f64>(
        pps,
        pps.consts_f64(),
        opts,
        "T5.4.1",
        vs,
        opts.samples_per_vertex,
        scope,
    )
}

/// Points per vertex of the multi-precision re-check (each costs a full MPFR/astro-float θ_v).
pub const MP_POINTS_PER_VERTEX: usize = 6;

/// T5.4.1 in multi-precision (oracle) on a few vertices.
pub fn check_condition_c_mp(pps: &Pps, opts: &SurfaceCheckOptions) -> CheckResult {
    let c: Consts<Mp> = pps.consts(opts.mp_prec);
    let vs = examined_vertices(pps, Some(opts.mp_vertices.max(1)));
    let per_vertex = opts.samples_per_vertex.min(MP_POINTS_PER_VERTEX);
    // The caps are part of the verdict's scope: print them, not only the counts.
    let scope = format!(
        "{} of {} vertices (cap: mp_vertices = {}), ≤ {per_vertex} points each (cap: min(samples_per_vertex = {}, {MP_POINTS_PER_VERTEX})), {} bits",
        vs.len(),
        pps.vertices().count(),
        opts.mp_vertices.max(1),
        opts.samples_per_vertex,
        opts.mp_prec
    );
    check_c_generic::<Mp>(pps, &c, opts, "T5.4.1-mp", vs, per_vertex, scope)
}

fn check_c_generic<S: SurfaceScalar>(
    pps: &Pps,
    c: &Consts<S>,
    opts: &SurfaceCheckOptions,
    id: &str,
    vs: Vec<VertexId>,
    per_vertex: usize,
    scope: String,
) -> CheckResult {
    let eps = S::from_i64(1, c.prec).epsilon();
    let mut r = Check::new(
        id,
        format!(
            "condition (C): θ_v = θ_u∘φ_uv on Ω_vu ({})",
            S::from_i64(0, c.prec).type_name()
        ),
    )
    .with_seed(opts.seed);
    let mut rng = r.sampler();
    let mut worst_rel = 0.0f64;
    for v in vs {
        let tol = tolerance(pps, v, eps);
        for p in overlap_points(pps, v, &mut rng, per_vertex, &mut r) {
            let pp = P2::new(S::from_f64(p[0], c.prec), S::from_f64(p[1], c.prec));
            let (tv, terms) = match (pps.theta(v, &pp, c), pps.terms(v, &pp, c, None)) {
                (Ok(a), Ok(b)) => (a, b),
                (Err(e), _) | (_, Err(e)) => {
                    r.error(OnError::Offence, &e, || {
                        Witness::new(format!("v={v} p={p:?}: {e}"), json!({"v": v, "p": p}))
                    });
                    continue;
                }
            };
            for t in terms.iter().filter(|t| t.u != v) {
                let u = t.u;
                match pps.theta(u, &t.q, c) {
                    Ok(tu) => {
                        let d = dist3(&tv, &tu);
                        worst_rel = dev_max(worst_rel, d / tol);
                        let q = t.q.to_f64();
                        r.deviation_within(d, tol, || {
                            Witness::new(
                                format!("v={v} u={u} p={p:?} φ_uv(p)={q:?}: |θ_v − θ_u∘φ_uv| = {d:.3e} > {tol:.3e}"),
                                json!({"v": v, "u": u, "p": p, "q": q, "dev": d, "tol": tol}),
                            )
                        });
                    }
                    Err(e) => r.error(OnError::Offence, &e, || {
                        Witness::new(
                            format!("v={v} u={u}: θ_u(φ_uv(p)) failed: {e}"),
                            json!({"v": v, "u": u, "p": p}),
                        )
                    }),
                }
            }
        }
    }
    r.finish(format!(
        "{scope}; ε = {eps:.3e}; tolerance = {COND}·max(1,m/6)·l·ε·S (S = max |control point| of the patches involved); worst deviation/tolerance = {worst_rel:.3e}"
    ))
}

/// Tolerance of the jet coefficient of ∂ˣⁱ∂ʸʲ in C5.4-smooth: tol₀·(4l)^(i+j), l the larger
/// patch degree. It depends on the order i + j only, not on how the order splits between x
/// and y (the scaling argument is the same for every direction).
fn jet_tolerance(tol0: f64, l: f64, i: usize, j: usize) -> f64 {
    tol0 * (4.0 * l).powi((i + j) as i32)
}

/// C5.4-smooth: derivatives of order ≤ 3 of θ_v and of θ_u∘φ_uv agree on Ω_vu (two charts).
/// Each pair (p, u) is one sample; its deviation is the largest coefficient difference relative
/// to that coefficient's tolerance (so the tolerance is 1).
pub fn check_smooth_charts(pps: &Pps, opts: &SurfaceCheckOptions) -> CheckResult {
    let mut r = Check::sampled(
        "C5.4-smooth",
        "∂^k θ_v = ∂^k (θ_u∘φ_uv) for k ≤ 3 on Ω_vu (jets)",
        opts.seed ^ 0x99,
        1.0,
    );
    let mut rng = r.sampler();
    let cj: Consts<Jet<f64>> = pps.consts(53);
    let per = (opts.samples_per_vertex / 4).max(2);
    let vs = examined_vertices(pps, opts.max_vertices.map(|n| n.min(100)).or(Some(100)));
    let scope = format!(
        "{} of {} vertices (cap: min(max_vertices, 100)), ≤ {per} points each (max(samples_per_vertex/4, 2))",
        vs.len(),
        pps.vertices().count()
    );
    for v in vs {
        let tol0 = tolerance(pps, v, f64::EPSILON);
        for p in overlap_points(pps, v, &mut rng, per, &mut r) {
            let (x, y) = Jet::variables(p[0], p[1]);
            let pj = P2::new(x, y);
            let fail = |what: &str, e: &dyn std::fmt::Display| {
                let text = format!("v={v} p={p:?}: {what} failed: {e}");
                move || Witness::new(text, json!({"v": v, "p": p}))
            };
            let tv = match pps.theta(v, &pj, &cj) {
                Ok(t) => t,
                Err(e) => {
                    r.error(OnError::Offence, &e, fail("θ_v (jet)", &e));
                    continue;
                }
            };
            let terms = match pps.terms(v, &pj, &cj, None) {
                Ok(t) => t,
                Err(e) => {
                    r.error(OnError::Offence, &e, fail("J_v (jet)", &e));
                    continue;
                }
            };
            for t in terms.iter().filter(|t| t.u != v) {
                let u = t.u;
                let tu = match pps.theta(u, &t.q, &cj) {
                    Ok(x) => x,
                    Err(e) => {
                        r.error(OnError::Offence, &e, fail("θ_u∘φ_uv (jet)", &e));
                        continue;
                    }
                };
                // Compare every coefficient, scaled by the order (derivatives of order k of a
                // polynomial of degree l on [−L, L] are bounded by (l/L)^k · S).
                let l = pps.patch(v).1.max(pps.patch(u).1) as f64;
                let mut rel = 0.0f64;
                let mut at = (0, 0, 0.0, 0.0);
                for (kidx, &(i, j)) in crate::surface::jet::MONOMIALS
                    .iter()
                    .enumerate()
                    .take(JET_LEN)
                {
                    let tol = jet_tolerance(tol0, l, i, j);
                    let mut d = 0.0f64;
                    for dd in 0..3 {
                        d = dev_max(d, (tv[dd].c[kidx] - tu[dd].c[kidx]).abs());
                    }
                    let q = d / tol;
                    if q.is_nan() || (!rel.is_nan() && q > rel) {
                        rel = q;
                        at = (i, j, d, tol);
                    }
                }
                let (i, j, d, tol) = at;
                r.deviation(rel, || Witness::new(format!("v={v} u={u} p={p:?}: Taylor coefficient x^{i}y^{j} differs by {d:.3e} > {tol:.3e}"), json!({"v": v, "u": u, "p": p, "i": i, "j": j, "dev": d})));
            }
        }
    }
    r.finish(format!(
        "{scope}; deviation reported relative to the per-order tolerance tol(C)·(4l)^k"
    ))
}

#[cfg(test)]
mod tests {
    use super::jet_tolerance;

    /// C5.4-smooth's tolerance per jet coefficient: one value per order, growing by 4l per
    /// order, whatever the split between x and y.
    #[test]
    fn c5_4_smooth_tolerance_depends_on_the_order_only() {
        let (t, l) = (1e-12, 7.0);
        for k in 0..=3usize {
            let v: Vec<f64> = (0..=k).map(|i| jet_tolerance(t, l, i, k - i)).collect();
            assert!(v.iter().all(|&x| x == v[0]), "order {k}: {v:?}");
            assert_eq!(v[0], t * (4.0 * l).powi(k as i32));
        }
    }
}
