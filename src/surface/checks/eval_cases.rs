//! Sec. 6.1.4: the consistency cases (1)–(4) of eval and the cover t ⊂ int C ∪ int D ∪ int E.

use super::tolerance::dist3;
use super::*;

/// Sec. 6.1.4 consistency cases (1)–(4): the chart points of q′ in two (three) charts are
/// related by φ and give the same θ.
pub fn check_eval_cases(pps: &Pps, opts: &SurfaceCheckOptions) -> Vec<CheckResult> {
    let names = [
        (
            "C6.1.4-case1",
            "q′ ∈ int C ∩ int D: φ_xu(q_u) = q_x, θ_u(q_u) = θ_x(q_x)",
        ),
        (
            "C6.1.4-case2",
            "q′ ∈ int C ∩ int E: φ_wu(q_u) = q_w, θ_u(q_u) = θ_w(q_w)",
        ),
        (
            "C6.1.4-case3",
            "q′ ∈ int D ∩ int E: φ_wx(q_x) = q_w, θ_x(q_x) = θ_w(q_w)",
        ),
        (
            "C6.1.4-case4",
            "q′ ∈ int C ∩ int D ∩ int E: all three agree",
        ),
    ];
    let mut res: Vec<Check> = names
        .iter()
        .map(|(i, n)| Check::new(*i, *n).with_seed(opts.seed ^ 0x6141))
        .collect();
    let c = pps.consts_f64();
    let mut rng = res[0].sampler();
    let nf = pps.num_faces();
    let nfaces = opts.max_vertices.map(|n| n.min(nf)).unwrap_or(nf);
    for fi in 0..nfaces {
        let f = FaceId(((fi as f64) * nf as f64 / nfaces as f64) as u32);
        let [u, w, x] = match pps.face(f) {
            Ok(t) => t,
            Err(e) => {
                for r in &mut res {
                    r.error(OnError::Offence, &e, || {
                        Witness::new(format!("face {f}: {e}"), json!({"face": f}))
                    });
                }
                continue;
            }
        };
        let tol = tolerance(pps, u, f64::EPSILON)
            .max(tolerance(pps, w, f64::EPSILON))
            .max(tolerance(pps, x, f64::EPSILON));
        for _ in 0..opts.samples_per_vertex {
            let bary = uniform_in_triangle(&mut rng);
            let qp = canonical_point(&bary, c);
            let ic = qp.norm2() < 0.75;
            let id = (qp.x - 1.0).powi(2) + qp.y.powi(2) < 0.75;
            let ie = (qp.x - 0.5).powi(2) + (qp.y + 0.75f64.sqrt()).powi(2) < 0.75;
            let pairs: Vec<(usize, Chart, Chart)> = {
                let mut p = vec![];
                if ic && id {
                    p.push((0, Chart::U, Chart::X));
                }
                if ic && ie {
                    p.push((1, Chart::U, Chart::W));
                }
                if id && ie {
                    p.push((2, Chart::X, Chart::W));
                }
                if ic && id && ie {
                    p.push((3, Chart::U, Chart::X));
                    p.push((3, Chart::U, Chart::W));
                    p.push((3, Chart::X, Chart::W));
                }
                p
            };
            for (case, ca, cb) in pairs {
                let r = &mut res[case];
                let (Ok((va, qa)), Ok((vb, qb))) = (
                    pps.chart_point(f, ca, &qp, c),
                    pps.chart_point(f, cb, &qp, c),
                ) else {
                    r.error(OnError::Offence, "chart point", || {
                        Witness::new(
                            format!("face {f} bary {bary:?}: chart point {ca:?} or {cb:?} failed"),
                            json!({"face": f, "bary": bary}),
                        )
                    });
                    continue;
                };
                let mapped = pps.phi(vb, va, &qa, c);
                let (ta, tb) = (pps.theta(va, &qa, c), pps.theta(vb, &qb, c));
                match (mapped, ta, tb) {
                    (Ok(Some(m)), Ok(ta), Ok(tb)) => {
                        let dq = m.dist_f64(&qb);
                        let dt = dist3(&ta, &tb);
                        let qtol = COND * 8.0 * f64::EPSILON;
                        let w = || Witness::new(format!("face {f} [{u},{w},{x}] bary {bary:?} charts {ca:?}/{cb:?}: |φ(q_a) − q_b| = {dq:.3e}, |θ_a − θ_b| = {dt:.3e}"), json!({"face": f, "bary": bary, "dq": dq, "dt": dt}));
                        if dq.is_finite() && dq <= qtol {
                            r.deviation_within(dt, tol, w);
                        } else {
                            r.holds(false, w);
                        }
                    }
                    (Ok(None), _, _) => r.holds(false, || Witness::new(format!("face {f} bary {bary:?}: q in chart {ca:?} is not in the gluing domain towards {cb:?}"), json!({"face": f, "bary": bary}))),
                    _ => r.error(OnError::Offence, "φ or θ", || Witness::new(format!("face {f} bary {bary:?}: evaluation failed"), json!({"face": f, "bary": bary}))),
                }
            }
        }
    }
    res.into_iter().map(|r| r.finish("")).collect()
}

/// C6.1.4-cover: t ⊂ int C ∪ int D ∪ int E (circles of squared radius `r2` = 3/4 centred at
/// the corners). Proof: every point of t is within the circumradius 1/√3 < √3/2 of a corner.
pub fn check_cover(r2: f64, seed: u64, n: usize) -> CheckResult {
    let mut r =
        Check::new("C6.1.4-cover", "t ⊂ int C ∪ int D ∪ int E (Sec. 6.1.4)").with_seed(seed ^ 0xC0);
    let mut rng = r.sampler();
    let s3h = 0.75f64.sqrt();
    let mut worst = 0.0f64;
    let mut pts: Vec<[f64; 3]> = vec![
        [1., 0., 0.],
        [0., 1., 0.],
        [0., 0., 1.],
        [1. / 3., 1. / 3., 1. / 3.],
        [0.5, 0.5, 0.],
        [0., 0.5, 0.5],
        [0.5, 0., 0.5],
    ];
    for _ in 0..n {
        pts.push(uniform_in_triangle(&mut rng));
    }
    for b in pts {
        let q = [b[1] * 0.5 + b[2], -b[1] * s3h];
        let d = [
            q[0] * q[0] + q[1] * q[1],
            (q[0] - 1.0).powi(2) + q[1] * q[1],
            (q[0] - 0.5).powi(2) + (q[1] + s3h).powi(2),
        ];
        let mind = d.iter().cloned().fold(f64::INFINITY, f64::min);
        worst = dev_max(worst, mind);
        // Strict: the circles are open (int C, int D, int E).
        r.holds(mind < r2, || {
            Witness::new(
                format!("bary {b:?}: q′ = {q:?} in no circle (min squared distance {mind:.4})"),
                json!({"bary": b, "q": q}),
            )
        });
    }
    let mut r =
        r.finish("worst = largest squared distance to the nearest corner (1/3 at the centroid)");
    r.worst_deviation = Some(worst);
    r.tolerance = Some(r2);
    r
}
