//! Exact checks of the triangular B-spline (DMS) basis of Sec. 3.1.2 over a planar
//! triangulation: partition of unity and N ≥ 0 (so 3.1.3(2) for the B-spline), completeness
//! 3.1.3(3) with poles f(X_β^I), local support 3.1.3(1), and C^{k−1} continuity across knot
//! lines, decided as a polynomial identity on the whole line.

use super::dms::{det, Dms, Pt};
use super::polar::{multi_indices, q, ProductPoly, Q};
use crate::report::{CheckResult, Witness};
use num_traits::{Signed, Zero};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;
use std::collections::BTreeSet;

fn ps(p: &Pt<Q>) -> String {
    format!("({}, {})", p[0], p[1])
}

/// A jittered n×n grid (n ≥ 2; spacing 1, vertices moved by ≤ 1/10) split along one diagonal, with
/// seeded generic rational clouds of radius ≤ `radius` (the knot clouds of eq. (1)), and
/// the triangles whose three vertices are interior (every triangle sharing a vertex with
/// them exists, so the whole 1-ring is present).
pub fn planar_grid(n: usize, k: usize, radius: Q, seed: u64) -> (Dms<Q>, Vec<usize>) {
    let n = n.max(2);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut clouds = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let v = [
                q(i as i64, 1) + q(rng.gen_range(-10..=10), 100),
                q(j as i64, 1) + q(rng.gen_range(-10..=10), 100),
            ];
            let mut c = vec![v.clone()];
            for _ in 0..k {
                c.push([
                    &v[0] + &radius * q(rng.gen_range(-997..=997), 997),
                    &v[1] + &radius * q(rng.gen_range(-997..=997), 997),
                ]);
            }
            clouds.push(c);
        }
    }
    let id = |i: usize, j: usize| j * n + i;
    let mut triangles = Vec::new();
    let mut interior = Vec::new();
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let inner = |a: usize, b: usize| a > 0 && b > 0 && a < n - 1 && b < n - 1;
            for t in [
                [id(i, j), id(i + 1, j), id(i + 1, j + 1)],
                [id(i, j), id(i + 1, j + 1), id(i, j + 1)],
            ] {
                if t.iter().all(|&v| inner(v % n, v / n)) {
                    interior.push(triangles.len());
                }
                triangles.push(t);
            }
        }
    }
    let dms = Dms {
        k,
        clouds,
        triangles,
        overrides: Default::default(),
        planted: Default::default(),
    };
    (dms, interior)
}

/// A seeded rational point strictly inside triangle I.
pub fn point_in(dms: &Dms<Q>, i: usize, rng: &mut ChaCha8Rng) -> Pt<Q> {
    let (a, b) = (rng.gen_range(1..200), rng.gen_range(1..200));
    let (a, b) = if a + b >= 200 {
        (200 - a, 200 - b)
    } else {
        (a, b)
    };
    let (la, lb) = (q(a, 201), q(b, 201));
    let lc = Q::from_integer(1.into()) - &la - &lb;
    let t = dms.triangles[i].map(|v| &dms.clouds[v][0]);
    [
        &la * &t[0][0] + &lb * &t[1][0] + &lc * &t[2][0],
        &la * &t[0][1] + &lb * &t[1][1] + &lc * &t[2][1],
    ]
}

fn skipped_if_empty(mut r: CheckResult) -> CheckResult {
    if r.examined == 0 && !r.failed() {
        r.skip("no sample examined");
    }
    r
}

/// Σ_I Σ_β N_β^I(u) = 1 and every N_β^I(u) ≥ 0, exactly, at seeded points of the interior
/// triangles (all triangles whose knots' bounding box holds u are summed).
pub fn check_partition(dms: &Dms<Q>, interior: &[usize], seed: u64, trials: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-DMS-PU",
        "DMS basis: Σ_I Σ_β N_β^I(u) = 1 and N_β^I(u) ≥ 0 (Sec. 3.1.2–3.1.3(2); exact)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for t in 0..trials {
        let Some(&i) = interior.get(t % interior.len().max(1)) else {
            break;
        };
        let u = point_in(dms, i, &mut rng);
        let mut sum = Q::zero();
        for j in dms.candidates(&u) {
            for b in multi_indices(dms.k) {
                match dms.basis(j, &b, &u) {
                    Ok(n) => {
                        if n.is_negative() {
                            r.offend(|| {
                                Witness::new(
                                    format!("N_{b:?}^{j}({}) = {n} < 0", ps(&u)),
                                    json!({"u": ps(&u), "triangle": j, "kind": "negative"}),
                                )
                            });
                        }
                        sum += n;
                    }
                    Err(e) => {
                        r.eval_errors += 1;
                        r.offend(|| Witness::new(e.to_string(), json!({"triangle": j})));
                    }
                }
            }
        }
        r.examined += 1;
        if sum != Q::from_integer(1.into()) {
            r.offend(|| {
                Witness::new(
                    format!("Σ N_β^I({}) = {sum} ≠ 1 (u in triangle {i})", ps(&u)),
                    json!({"u": ps(&u), "triangle": i, "sum": sum.to_string(), "kind": "partition"}),
                )
            });
        }
    }
    skipped_if_empty(r.with_note(format!(
        "degree {}, {} interior triangles sampled, exact BigRational",
        dms.k,
        interior.len()
    )))
}

/// Sec. 3.1.3(3) for the B-spline: with c_β^I = p(X_β^I) (blossom at the knots of eq. (2),
/// `KnotClouds::x_beta` of the B-patch of I), Σ c_β^I N_β^I = P exactly.
pub fn check_reproduction(
    dms: &Dms<Q>,
    p: &ProductPoly,
    interior: &[usize],
    seed: u64,
    trials: usize,
) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-DMS-3.1.3(3)",
        "DMS completeness: poles p(X_β^I) reproduce P (exact)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for t in 0..trials {
        let Some(&i) = interior.get(t % interior.len().max(1)) else {
            break;
        };
        let u = point_in(dms, i, &mut rng);
        let c = |j: usize, b: &[usize; 3]| p.blossom(&dms.patch(j).x_beta(b));
        match dms.eval(&dms.candidates(&u), &c, &u) {
            Ok(v) if v == p.eval(&u) => r.examined += 1,
            Ok(v) => {
                r.examined += 1;
                r.offend(|| {
                    Witness::new(
                        format!("F({}) = {v} but P = {}", ps(&u), p.eval(&u)),
                        json!({"u": ps(&u), "kind": "reproduction"}),
                    )
                })
            }
            Err(e) => {
                r.eval_errors += 1;
                r.offend(|| Witness::new(e.to_string(), json!({})));
            }
        }
    }
    skipped_if_empty(r.with_note(format!("degree {}, P of degree {}", dms.k, p.k)))
}

/// Is some line through two points of `a` (or of `b`) a separating line of conv(a) and
/// conv(b) (closed sides)? Exact; true iff the interiors are disjoint (convex sets).
fn separated(a: &[Pt<Q>], b: &[Pt<Q>]) -> bool {
    let sep = |x: &[Pt<Q>], y: &[Pt<Q>]| {
        for i in 0..x.len() {
            for j in 0..x.len() {
                if i == j || x[i] == x[j] {
                    continue;
                }
                let side = |p: &Pt<Q>| det(&x[i], &x[j], p);
                if x.iter().all(|p| !side(p).is_negative())
                    && y.iter().all(|p| !side(p).is_positive())
                {
                    return true;
                }
            }
        }
        false
    };
    sep(a, b) || sep(b, a)
}

/// u ∈ conv(V) (closed), exact.
fn in_hull(v: &[Pt<Q>], u: &Pt<Q>) -> bool {
    !separated(v, std::slice::from_ref(u)) || v.contains(u)
}

/// Sec. 3.1.3(1), local support: for u ∈ Δ^I only the triangles J of the 1-ring of I (sharing
/// a vertex with I) contribute. Decided exactly for every interior I, every J outside its
/// 1-ring and every β: conv(V_β^J) and Δ^I have disjoint interiors (a separating knot line),
/// since N_β^J vanishes outside conv(V_β^J) — itself checked at seeded points (every non-zero
/// N_β^J(u) has u ∈ conv(V_β^J)). A hull overlap is confirmed by a sampled u with N ≠ 0.
pub fn check_local_support(
    dms: &Dms<Q>,
    interior: &[usize],
    seed: u64,
    trials: usize,
) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-3.1.3(1)",
        "local support: N_β^J = 0 on Δ^I for J outside the 1-ring of I (exact)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let betas = multi_indices(dms.k);
    for &i in interior {
        let ti: Vec<Pt<Q>> = dms.triangles[i]
            .iter()
            .map(|&v| dms.clouds[v][0].clone())
            .collect();
        let ring: BTreeSet<usize> = (0..dms.triangles.len())
            .filter(|&j| {
                dms.triangles[j]
                    .iter()
                    .any(|v| dms.triangles[i].contains(v))
            })
            .collect();
        for j in (0..dms.triangles.len()).filter(|j| !ring.contains(j)) {
            for b in &betas {
                let Ok((v, _)) = dms.v_beta(j, b) else {
                    r.eval_errors += 1;
                    continue;
                };
                r.examined += 1;
                if separated(&v, &ti) {
                    continue;
                }
                let hit = (0..trials).find_map(|_| {
                    let u = point_in(dms, i, &mut rng);
                    match dms.basis(j, b, &u) {
                        Ok(n) if !n.is_zero() => Some((u, n)),
                        _ => None,
                    }
                });
                let msg = match &hit {
                    Some((u, n)) => format!(
                        "triangle {j} outside the 1-ring of {i}: N_{b:?}^{j}({}) = {n} ≠ 0 on Δ^{i}",
                        ps(u)
                    ),
                    None => format!(
                        "triangle {j} outside the 1-ring of {i}: conv(V_{b:?}^{j}) overlaps Δ^{i} (no sample hit N ≠ 0)"
                    ),
                };
                r.offend(|| {
                    Witness::new(
                        msg,
                        json!({"I": i, "J": j, "beta": b, "kind": "outside_ring"}),
                    )
                });
            }
        }
    }
    // Support inside the convex hull of the knots, at seeded points.
    for t in 0..trials {
        let Some(&i) = interior.get(t % interior.len().max(1)) else {
            break;
        };
        let u = point_in(dms, i, &mut rng);
        for j in 0..dms.triangles.len() {
            for b in &betas {
                let (Ok(n), Ok((v, _))) = (dms.basis(j, b, &u), dms.v_beta(j, b)) else {
                    r.eval_errors += 1;
                    continue;
                };
                r.examined += 1;
                if !n.is_zero() && !in_hull(&v, &u) {
                    r.offend(|| {
                        Witness::new(
                            format!("N_{b:?}^{j}({}) = {n} ≠ 0 outside conv(V_β^J)", ps(&u)),
                            json!({"J": j, "beta": b, "kind": "outside_hull"}),
                        )
                    });
                }
            }
        }
    }
    skipped_if_empty(r.with_note(
        "pairs (I, J ∉ 1-ring, β) decided by an exact separating knot line; hull support sampled",
    ))
}

/// The result of comparing the two pieces of N_β^I across one knot line.
struct Across {
    /// Smallest m with ∂_n^m (P₊ − P₋) ≢ 0 on the line (None: the pieces agree).
    jump: Option<usize>,
    /// The point p on the line and the line's two knots.
    p: Pt<Q>,
}

fn across(dms: &Dms<Q>, i: usize, b: &[usize; 3], a: usize, c: usize, s: &Q) -> Option<Across> {
    let (v, _) = dms.v_beta(i, b).ok()?;
    let (pa, pc) = (&v[a], &v[c]);
    let d = [&pc[0] - &pa[0], &pc[1] - &pa[1]];
    let p = [&pa[0] + s * &d[0], &pa[1] + s * &d[1]];
    let n = [-d[1].clone(), d[0].clone()];
    // δ below every crossing of the normal through p with another knot line of V_β^I.
    let mut delta: Option<Q> = None;
    for x in 0..v.len() {
        for y in x + 1..v.len() {
            let on = |w: &Pt<Q>| det(&v[x], &v[y], w).is_zero();
            if (on(pa) && on(pc)) || v[x] == v[y] {
                continue;
            }
            let dp = det(&v[x], &v[y], &p);
            if dp.is_zero() {
                return None;
            }
            let e = [&v[y][0] - &v[x][0], &v[y][1] - &v[x][1]];
            let cr = &e[0] * &n[1] - &e[1] * &n[0];
            if cr.is_zero() {
                continue;
            }
            let t = (dp / cr).abs() / q(2, 1);
            delta = Some(match delta {
                Some(x) if x < t => x,
                _ => t,
            });
        }
    }
    let delta = delta.unwrap_or_else(|| q(1, 1));
    let up = [&p[0] + &delta * &n[0], &p[1] + &delta * &n[1]];
    let dn = [&p[0] - &delta * &n[0], &p[1] - &delta * &n[1]];
    let diff = dms
        .basis_piece(i, b, &up)
        .ok()?
        .sub(&dms.basis_piece(i, b, &dn).ok()?);
    let mut jump = None;
    let mut dd = diff;
    for m in 0..=dms.k {
        if !dd.on_line(&p, &d).is_empty() {
            jump = Some(m);
            break;
        }
        dd = dd.derivative(&n);
    }
    Some(Across { jump, p })
}

/// C^{k−1} across knot lines: for seeded (I, β) and pairs of knots a, c of V_β^I, the pieces
/// P₊, P₋ of N_β^I on the two sides of the line ac at a rational point p of the segment
/// satisfy ∂_n^m (P₊ − P₋) ≡ 0 on the whole line for m = 0..k−1 — a polynomial identity in
/// the line parameter, i.e. value and derivatives up to order k−1 agree along the line. The
/// k-th normal derivative's jump is counted (it shows the line is a true break).
pub fn check_continuity(dms: &Dms<Q>, tris: &[usize], seed: u64, trials: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-DMS-Ck-1",
        "DMS basis C^{k−1} across knot lines (polynomial identity on the line; exact)",
    );
    r.seed = Some(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let betas = multi_indices(dms.k);
    let (mut kth, mut skipped) = (0usize, 0usize);
    for t in 0..trials {
        let Some(&i) = tris.get(t % tris.len().max(1)) else {
            break;
        };
        let b = betas[rng.gen_range(0..betas.len())];
        let nv = dms.k + 3;
        let a = rng.gen_range(0..nv);
        let c = (a + rng.gen_range(1..nv)) % nv;
        let s = q(rng.gen_range(1..97), 97);
        let Some(x) = across(dms, i, &b, a, c, &s) else {
            skipped += 1;
            continue;
        };
        r.examined += 1;
        match x.jump {
            Some(m) if m < dms.k => r.offend(|| {
                Witness::new(
                    format!(
                        "N_{b:?}^{i}: derivative of order {m} jumps across the knot line through knots {a}, {c} of V_β at {} (C^{} only)",
                        ps(&x.p),
                        m as i64 - 1
                    ),
                    json!({"triangle": i, "beta": b, "knots": [a, c], "order": m}),
                )
            }),
            Some(_) => kth += 1,
            None => {}
        }
    }
    let examined = r.examined;
    skipped_if_empty(r.with_note(format!(
        "degree {}: {examined} lines examined, the k-th normal derivative jumps on {kth} of them (true breaks); {skipped} skipped (point on a second knot line)",
        dms.k
    )))
}
