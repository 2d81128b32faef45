//! Def. 3.5.1 (parametric pseudo-manifolds): condition (C) θ_i = θ_j ∘ φ_ji, and (C′), (C″)
//! as measured properties; Prop. 3.5.1 (Θ : M_G → M is well defined with θ_i = Θ ∘ τ_i).
//!
//! Parametrizations are plain functions θ(i, x) ∈ ℝⁿ over f64 (the Ch. 5 maps will supply
//! them). (C) is sampled; (C′)/(C″) are measured by a coincidence search: for sampled a ∈ Ω_i
//! the distance from θ_i(a) to θ_j(Ω_j) is minimised (nearest sample, then compass search
//! inside Ω_j); a distance below the tolerance is a coincidence θ_i(a) = θ_j(b).

use super::data::{fmt_point, from_f64, point_json, to_f64, GluingData, Idx, Point};
use super::exact1d::interval::{fmt_q, q_to_f64};
use super::exact1d::Exact1d;
use super::relation::{classes, GridSample};
use super::sampled::{sampled_k, SampleConfig};
use super::tolerance::tol;
use crate::report::{Check, CheckResult, OnError, Witness};
use num_traits::Float;
use serde_json::json;

fn vdist(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}
fn vnorm(a: &[f64]) -> f64 {
    a.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Def. 3.5.1(C): θ_i(x) = θ_j(φ_ji(x)) for (i, j) ∈ K and sampled x ∈ Ω_ij.
pub fn check_c<G, F, const N: usize>(g: &G, theta: F, cfg: &SampleConfig) -> CheckResult
where
    G: GluingData<N>,
    F: Fn(Idx, &Point<G::S, N>) -> Vec<f64>,
{
    let mut r = Check::new("D3.5.1(C)", "θ_i = θ_j ∘ φ_ji on Ω_ij")
        .with_note("sampled")
        .with_seed(cfg.seed);
    let mut rng = cfg.rng(20);
    for (i, j) in sampled_k(g, cfg) {
        for x in g.sample_gluing_domain(i, j, &mut rng, cfg.n) {
            let Some(y) = g.phi(j, i, &x) else {
                // The offence is D3.4.1(3)'s; here the sample cannot be examined.
                r.error(
                    OnError::Skip,
                    "φ_ji(x) undefined (reported by D3.4.1(3))",
                    || Witness::new(fmt_point(&x), point_json(&x)),
                );
                continue;
            };
            let (a, b) = (theta(i, &x), theta(j, &y));
            let d = vdist(&a, &b);
            let mag = vnorm(&a)
                .max(super::data::norm(&x))
                .max(super::data::norm(&y));
            let t = tol::<G::S>(mag);
            r.deviation_within(d, t, || {
                Witness::new(
                    format!(
                        "(i,j)=({i},{j}): θ_{i}({}) = {a:?} ≠ θ_{j}(φ_({j},{i})(x)) = {b:?}",
                        fmt_point(&x)
                    ),
                    json!({"kind": "c", "i": i, "j": j, "x": point_json(&x), "deviation": d}),
                )
            });
        }
    }
    r.finish("")
}

/// Smallest |θ_j(b) − target| over b ∈ Ω_j found from the sample cloud by compass search.
fn nearest_in_image<G, F, const N: usize>(
    g: &G,
    theta: &F,
    j: Idx,
    cloud: &[Point<G::S, N>],
    target: &[f64],
) -> Option<(Point<G::S, N>, f64)>
where
    G: GluingData<N>,
    F: Fn(Idx, &Point<G::S, N>) -> Vec<f64>,
{
    let mut best = cloud
        .iter()
        .map(|b| (*b, vdist(&theta(j, b), target)))
        .min_by(|u, v| u.1.total_cmp(&v.1))?;
    let mut step = g.scale() * 0.05;
    let floor = g.scale() * 1e-15;
    let mut iters = 0;
    while step > floor && iters < 4000 {
        iters += 1;
        let mut improved = false;
        for m in 0..N {
            for sgn in [1.0, -1.0] {
                let mut c = best.0;
                c[m] = c[m] + from_f64::<G::S>(sgn * step);
                if !g.in_p_domain(j, &c) {
                    continue;
                }
                let d = vdist(&theta(j, &c), target);
                if d < best.1 {
                    best = (c, d);
                    improved = true;
                }
            }
        }
        if !improved {
            step *= 0.5;
        }
    }
    Some(best)
}

/// Margin η = 1e-6·scale of the (C′) measurement.
pub const C_PRIME_MARGIN: f64 = 1e-6;

/// a ∈ Ω_ij, or an axis neighbour at distance η is.
fn near_gluing_domain<G: GluingData<N>, const N: usize>(
    g: &G,
    i: Idx,
    j: Idx,
    a: &Point<G::S, N>,
) -> bool {
    if g.in_gluing_domain(i, j, a) {
        return true;
    }
    let h = from_f64::<G::S>(C_PRIME_MARGIN * g.scale());
    (0..N).any(|m| {
        let (mut p, mut q) = (*a, *a);
        p[m] = p[m] + h;
        q[m] = q[m] - h;
        g.in_gluing_domain(i, j, &p) || g.in_gluing_domain(i, j, &q)
    })
}

/// Shared body of (C′) and (C″): look for a ∈ Ω_i (outside Ω_ij) and b ∈ Ω_j with
/// θ_i(a) = θ_j(b). `want_k` selects the pairs: in K for (C′), not in K for (C″).
fn coincidences<G, F, const N: usize>(
    g: &G,
    theta: F,
    cfg: &SampleConfig,
    want_k: bool,
    mut r: CheckResult,
) -> CheckResult
where
    G: GluingData<N>,
    F: Fn(Idx, &Point<G::S, N>) -> Vec<f64>,
{
    r.seed = Some(cfg.seed);
    let mut rng = cfg.rng(if want_k { 21 } else { 22 });
    let k = sampled_k(g, cfg);
    let ids = g.indices();
    let mut smallest = f64::INFINITY;
    let mut tmax: f64 = 0.0;
    for &i in &ids {
        for &j in &ids {
            if i == j || k.contains(&(i, j)) != want_k {
                continue;
            }
            let cloud = g.sample_p_domain(j, &mut rng, cfg.n);
            for a in g.sample_p_domain(i, &mut rng, cfg.n / 4 + 1) {
                if want_k && near_gluing_domain(g, i, j, &a) {
                    // (C′) allows coincidences of glued points; points of ∂Ω_ij are limits of
                    // glued points, whose images touch θ_j(Ω_j) in its closure, so a margin
                    // η keeps the measurement away from them.
                    continue;
                }
                r.examined += 1;
                let target = theta(i, &a);
                let Some((b, d)) = nearest_in_image(g, &theta, j, &cloud, &target) else {
                    continue;
                };
                // Compass search converges to ~scale·1e-15; √ε·max(1,|θ|) leaves a wide margin.
                let t = to_f64(G::S::epsilon()).sqrt() * vnorm(&target).max(1.0);
                tmax = tmax.max(t);
                smallest = smallest.min(d);
                if d <= t {
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "(i,j)=({i},{j}): θ_{i}({}) = θ_{j}({}) ≈ {target:?} (gap {d:.2e}){}",
                                fmt_point(&a),
                                fmt_point(&b),
                                if want_k { format!(" with a ∉ Ω_({i},{j})") } else { format!(" though ({i},{j}) ∉ K") }
                            ),
                            json!({"kind": "coincidence", "i": i, "j": j, "a": point_json(&a), "b": point_json(&b), "gap": d}),
                        )
                    });
                }
            }
        }
    }
    if smallest.is_finite() {
        r.worst_deviation = Some(smallest);
        r.tolerance = Some(tmax);
    }
    r
}

/// Def. 3.5.1(C′), measured: for (i, j) ∈ K, θ_i(Ω_i) ∩ θ_j(Ω_j) = θ_i(Ω_ij) = θ_j(Ω_ji). The
/// inclusion θ_i(Ω_ij) ⊆ θ_j(Ω_ji) is (C); here the other inclusion is searched: no
/// a ∈ Ω_i ∖ Ω_ij may have θ_i(a) ∈ θ_j(Ω_j). Only a at distance ≥ [`C_PRIME_MARGIN`]·scale
/// from Ω_ij are measured. `worst_deviation` is the smallest gap found.
pub fn check_c_prime<G, F, const N: usize>(g: &G, theta: F, cfg: &SampleConfig) -> CheckResult
where
    G: GluingData<N>,
    F: Fn(Idx, &Point<G::S, N>) -> Vec<f64>,
{
    let r = CheckResult::new(
        "D3.5.1(C')",
        "θ_i(Ω_i) ∩ θ_j(Ω_j) = θ_i(Ω_ij) for (i,j) ∈ K",
    )
    .with_note("measured: smallest gap from θ_i(Ω_i∖Ω_ij) to θ_j(Ω_j) (coincidence search)");
    coincidences(g, theta, cfg, true, r)
}

/// Def. 3.5.1(C″), measured: for (i, j) ∉ K, θ_i(Ω_i) ∩ θ_j(Ω_j) = ∅.
pub fn check_c_second<G, F, const N: usize>(g: &G, theta: F, cfg: &SampleConfig) -> CheckResult
where
    G: GluingData<N>,
    F: Fn(Idx, &Point<G::S, N>) -> Vec<f64>,
{
    let r = CheckResult::new("D3.5.1(C'')", "θ_i(Ω_i) ∩ θ_j(Ω_j) = ∅ for (i,j) ∉ K")
        .with_note("measured: smallest gap from θ_i(Ω_i) to θ_j(Ω_j) (coincidence search)");
    coincidences(g, theta, cfg, false, r)
}

/// Prop. 3.5.1: the θ_i induce Θ : M_G → M with θ_i = Θ ∘ τ_i, i.e. θ is constant on every
/// class \[x\] of M_G. Checked on the classes of a grid sample of exact 1-D data; a class with two
/// different θ-values is a witness that Θ is not well defined (which (C) excludes).
pub fn check_p3_5_1(g: &Exact1d, theta: impl Fn(Idx, f64) -> Vec<f64>, m: u32) -> CheckResult {
    let mut r = Check::new("P3.5.1", "Θ well defined on M_G, θ_i = Θ ∘ τ_i")
        .with_note("on the classes of a grid sample (exact ∼, f64 θ); examined = pairs in a class");
    let s = GridSample::new(g, m);
    for c in classes(g, &s) {
        let Some(first) = c.first() else { continue };
        let v0 = theta(first.0, q_to_f64(&first.1));
        for p in &c[1..] {
            let v = theta(p.0, q_to_f64(&p.1));
            let d = vdist(&v0, &v);
            let t = tol::<f64>(
                vnorm(&v0)
                    .max(q_to_f64(&p.1).abs())
                    .max(q_to_f64(&first.1).abs()),
            );
            r.deviation_within(d, t, || {
                Witness::new(
                    format!(
                        "[{}∈Ω_{}] = [{}∈Ω_{}] in M_G but θ_{}({}) = {v0:?} ≠ θ_{}({}) = {v:?}",
                        fmt_q(&first.1),
                        first.0,
                        fmt_q(&p.1),
                        p.0,
                        first.0,
                        fmt_q(&first.1),
                        p.0,
                        fmt_q(&p.1)
                    ),
                    json!({"kind": "theta_not_constant", "deviation": d}),
                )
            });
        }
    }
    r.finish("")
}
