//! Sampled check of Def. 3.4.1(4), the Hausdorff condition: for (i, j) ∈ K, i ≠ j, and
//! x ∈ ∂Ω_ij ∩ Ω_i, y ∈ ∂Ω_ji ∩ Ω_j, there are open balls V_x, V_y centred at x, y such that no
//! point of V_y ∩ Ω_ji is φ_ji of a point of V_x ∩ Ω_ij.
//!
//! Method: for shrinking radii r = scale·2⁻ᵏ (k = 2, 6, …, 42) measure
//! m(r) = min |φ_ji(x') − y| over samples x' ∈ V_x ∩ Ω_ij (uniform in the ball plus points at
//! geometric distances from x), down to the scalar's resolution (1024·ε·max(scale, ‖x‖)). If
//! φ_ji extends continuously with x ↦ y, m(r) → 0 with r; the pair fails when m at the smallest
//! sampled radius r_last is below max(`SEPARATION_FACTOR`·scale, 64·r_last) (the tolerance
//! reported; it assumes φ_ji is 64-Lipschitz near x). Otherwise the radii (r, m(r)/2) for the
//! largest r with m(r) clear of that threshold are reported. The exact 1-D backend decides (4).

use super::sampling::{sampled_k, SampleConfig};
use crate::gluing::data::{dist, fmt_point, from_f64, point_json, to_f64, GluingData, Idx, Point};
use crate::report::{Check, CheckResult, Witness};
use rand::Rng;
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// Images closer to y than this (relative to the data's scale) at radius scale·2⁻⁴² count as
/// "φ_ji(x') → y". Far above the ~2⁻⁴² a Lipschitz map produces, far below any honest gap.
pub const SEPARATION_FACTOR: f64 = 1e-6;

/// Radii found for one separated pair (x, y).
#[derive(Clone, Debug)]
pub struct SampledSeparation {
    /// First chart index of the pair (i, j) ∈ K.
    pub i: Idx,
    /// Second chart index.
    pub j: Idx,
    /// x ∈ ∂Ω_ij ∩ Ω_i.
    pub x: Vec<f64>,
    /// y ∈ ∂Ω_ji ∩ Ω_j.
    pub y: Vec<f64>,
    /// Radius of V_x found.
    pub r_x: f64,
    /// Radius of V_y found.
    pub r_y: f64,
}

fn ball_samples<G: GluingData<N>, const N: usize>(
    g: &G,
    i: Idx,
    j: Idx,
    x: &Point<G::S, N>,
    r: f64,
    rng: &mut ChaCha8Rng,
) -> Vec<Point<G::S, N>> {
    let mut out = Vec::new();
    let conv = from_f64::<G::S>;
    for t in 0..96 {
        // Random direction; the radius is uniform for half of the points, geometric for the rest.
        let mut u = [0f64; N];
        for c in u.iter_mut() {
            *c = rng.gen_range(-1.0..1.0);
        }
        let n = u.iter().map(|c| c * c).sum::<f64>().sqrt();
        if n < 1e-12 {
            continue;
        }
        let rho = if t % 2 == 0 {
            r * rng.gen_range(0.0..1.0)
        } else {
            r * 2f64.powi(-((t / 2) % 40))
        } * 0.999;
        let mut p = *x;
        for m in 0..N {
            p[m] = p[m] + conv(rho * u[m] / n);
        }
        if dist(&p, x) < r && g.in_gluing_domain(i, j, &p) {
            out.push(p);
        }
    }
    out
}

/// Limits of φ_ji at x along a few random directions into Ω_ij (linear extrapolation from
/// φ_ji at distances t and 2t, t = scale·2⁻²⁰), kept when they lie in Ω_j with margin
/// `LIMIT_MARGIN`·scale (a limit on ∂Ω_j is not a point of Ω_j) and outside Ω_ji.
fn limit_candidates<G: GluingData<N>, const N: usize>(
    g: &G,
    i: Idx,
    j: Idx,
    x: &Point<G::S, N>,
    rng: &mut ChaCha8Rng,
) -> Vec<Point<G::S, N>> {
    let t = (g.scale() * 2f64.powi(-20)).max(
        1024.0
            * to_f64(<G::S as num_traits::Float>::epsilon())
            * g.scale().max(crate::gluing::data::norm(x)),
    );
    let eta = from_f64::<G::S>(LIMIT_MARGIN * g.scale());
    let mut out: Vec<Point<G::S, N>> = Vec::new();
    for _ in 0..8 {
        let mut u = [0f64; N];
        for c in u.iter_mut() {
            *c = rng.gen_range(-1.0..1.0);
        }
        let n = u.iter().map(|c| c * c).sum::<f64>().sqrt();
        if n < 1e-9 {
            continue;
        }
        let at = |s: f64| {
            let mut p = *x;
            for m in 0..N {
                p[m] = p[m] + from_f64::<G::S>(s * u[m] / n);
            }
            p
        };
        let (p1, p2) = (at(t), at(2.0 * t));
        if !(g.in_gluing_domain(i, j, &p1) && g.in_gluing_domain(i, j, &p2)) {
            continue;
        }
        let (Some(y1), Some(y2)) = (g.phi(j, i, &p1), g.phi(j, i, &p2)) else {
            continue;
        };
        let mut y = y1;
        for m in 0..N {
            y[m] = y1[m] + y1[m] - y2[m];
        }
        let inside_with_margin = g.in_p_domain(j, &y)
            && (0..N).all(|m| {
                let (mut a, mut b) = (y, y);
                a[m] = a[m] + eta;
                b[m] = b[m] - eta;
                g.in_p_domain(j, &a) && g.in_p_domain(j, &b)
            });
        let fresh = out.iter().all(|o| dist(o, &y) > LIMIT_MARGIN * g.scale());
        if inside_with_margin && !g.in_gluing_domain(j, i, &y) && fresh {
            out.push(y);
        }
    }
    out
}

/// Margin for deciding that an extrapolated limit lies in the open set Ω_j.
pub const LIMIT_MARGIN: f64 = 1e-6;

/// Def. 3.4.1(4), sampled. Returns the result and, for separated pairs, the radii found.
pub fn check_4_with_radii<G: GluingData<N>, const N: usize>(
    g: &G,
    cfg: &SampleConfig,
) -> (CheckResult, Vec<SampledSeparation>) {
    let mut r = Check::new("D3.4.1(4)", "Hausdorff condition (separating balls)");
    r.seed = Some(cfg.seed);
    let scale = g.scale();
    let thr = SEPARATION_FACTOR * scale;
    let mut tol_used = thr;
    let mut rng = cfg.rng(9);
    let mut seps = Vec::new();
    let nb = (cfg.n / 10).clamp(2, 16);
    for (i, j) in sampled_k(g, cfg) {
        if i == j {
            continue;
        }
        let xs = g.gluing_boundary_points(i, j, &mut rng, nb);
        let ys = g.gluing_boundary_points(j, i, &mut rng, nb);
        for x in &xs {
            // The sampler cannot hit the one y that φ_ji's limit at x may be; so estimate that
            // limit and add it as a candidate y when it lies in Ω_j with a margin.
            let mut ys_x = ys.clone();
            ys_x.extend(limit_candidates(g, i, j, x, &mut rng));
            // m(r) does not depend on y's choice of samples, so compute images once per radius.
            // Radii below the scalar's resolution at x would sample nothing but x itself.
            let r_min = 1024.0
                * to_f64(<G::S as num_traits::Float>::epsilon())
                * scale.max(crate::gluing::data::norm(x));
            let radii: Vec<f64> = (0..11)
                .map(|s| scale * 2f64.powi(-(2 + 4 * s)))
                .filter(|&rad| rad >= r_min)
                .collect();
            let images: Vec<Vec<Point<G::S, N>>> = radii
                .iter()
                .map(|&rad| {
                    ball_samples(g, i, j, x, rad, &mut rng)
                        .iter()
                        .filter_map(|p| g.phi(j, i, p))
                        .collect()
                })
                .collect();
            // Rule 1 of the harness: a non-finite image is an offence (a NaN distance would
            // otherwise read as "nothing sampled near x" below).
            if let Some(z) = images
                .iter()
                .flatten()
                .find(|z| !z.iter().all(|c| to_f64(*c).is_finite()))
            {
                r.holds(false, || {
                    Witness::new(
                        format!(
                            "(i,j)=({i},{j}): φ_({j},{i}) near x = {} is not finite: {}",
                            fmt_point(x),
                            fmt_point(z)
                        ),
                        json!({"kind": "non_finite", "i": i, "j": j, "x": point_json(x)}),
                    )
                });
                continue;
            }
            for y in &ys_x {
                r.examined += 1;
                let m: Vec<f64> = images
                    .iter()
                    .map(|im| im.iter().map(|z| dist(z, y)).fold(f64::INFINITY, f64::min))
                    .collect();
                // The smallest radius at which V_x ∩ Ω_ij was actually sampled.
                let Some(k) = (0..m.len()).rev().find(|&k| m[k].is_finite()) else {
                    r.examined -= 1; // nothing sampled near x: no evidence either way
                    continue;
                };
                let (last, r_last) = (m[k], radii[k]);
                // If φ_ji extends with x ↦ y, m(r) ≤ Lip·r; 64·r_last allows Lip ≤ 64.
                let thr = thr.max(64.0 * r_last);
                tol_used = tol_used.max(thr);
                if last <= thr {
                    let worst = r.worst_deviation.map_or(last, |w| w.min(last));
                    r.worst_deviation = Some(worst);
                    r.offend(|| {
                        Witness::new(
                            format!(
                                "(i,j)=({i},{j}): x = {} ∈ ∂Ω_({i},{j}) ∩ Ω_{i}, y = {} ∈ ∂Ω_({j},{i}) ∩ Ω_{j}: images of V_x ∩ Ω_({i},{j}) come within {last:.3e} of y at radius {r_last:.3e}",
                                fmt_point(x), fmt_point(y)
                            ),
                            json!({"kind": "not_separated", "i": i, "j": j, "x": point_json(x), "y": point_json(y), "gap": last}),
                        )
                    });
                } else if let Some(s) = (0..radii.len()).find(|&s| m[s].is_finite() && m[s] > thr) {
                    seps.push(SampledSeparation {
                        i,
                        j,
                        x: x.iter().map(|c| to_f64(*c)).collect(),
                        y: y.iter().map(|c| to_f64(*c)).collect(),
                        r_x: radii[s],
                        r_y: m[s] / 2.0,
                    });
                }
            }
        }
    }
    r.tolerance = Some(tol_used);
    let listed: Vec<String> = seps
        .iter()
        .take(4)
        .map(|s| {
            format!(
                "({},{}) x={:?} y={:?}: r_x={:.3e}, r_y={:.3e}",
                s.i, s.j, s.x, s.y, s.r_x, s.r_y
            )
        })
        .collect();
    r.note = format!(
        "sampled; {} separated pairs{}{}",
        seps.len(),
        if listed.is_empty() { "" } else { "; radii " },
        listed.join("; ")
    );
    (r.finish(""), seps)
}

/// Def. 3.4.1(4), sampled (see [`check_4_with_radii`]).
pub fn check_4<G: GluingData<N>, const N: usize>(g: &G, cfg: &SampleConfig) -> CheckResult {
    check_4_with_radii(g, cfg).0
}

#[cfg(test)]
#[path = "hausdorff_tests.rs"]
mod tests;
