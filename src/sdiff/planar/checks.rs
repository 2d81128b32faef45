//! The checks of Mello–Velho Secs. 2–3 on a map of a planar complex, each a [`CheckResult`]
//! carrying its SPEC ID (`SD-…`), decided exactly where the statement is algebraic.

use super::complex::PlanarComplex;
use super::interval::certify_det;
use super::maps::{Family, SimplexMap};
use super::params::ComplexMap;
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::decide::Tally;
use crate::sdiff::common::interval::IntervalVerdict;
use crate::sdiff::common::poly2::{multi_indices, Poly2};
use crate::sdiff::common::positivity::{decide, decide_on, Budget, Decision, Strictness};
use crate::sdiff::common::rational::{q, qr, to_f64, Q};
use num_traits::{Signed, Zero};
use serde_json::json;

/// Options of [`check_all`].
#[derive(Debug, Clone, Copy)]
pub struct Options {
    /// Budget of each exact positivity decision.
    pub budget: Budget,
    /// Box budget of the interval route per triangle.
    pub interval_boxes: usize,
    /// Seed of the inversion spot check.
    pub seed: u64,
    /// Target points per triangle in the inversion spot check.
    pub inversion_samples: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            budget: Budget::default(),
            interval_boxes: 20_000,
            seed: 1,
            inversion_samples: 16,
        }
    }
}

fn corner(i: usize) -> [Q; 2] {
    match i {
        0 => [q(0), q(0)],
        1 => [q(1), q(0)],
        _ => [q(0), q(1)],
    }
}

/// Def. 1 (L79) on the faces: x^k ≡ 0 on the edge w_k = 0, for every triangle and k (K-invariant
/// maps take each face into itself). Exact: on that edge the Bernstein polynomials B_I with
/// I^k = 0 are a basis, so x^k vanishes there iff every q_I b_I\[k\] with I^k = 0 is zero (for
/// Eq. (9): iff g_k(0) = 0).
pub(crate) fn faces_preserved(k: &PlanarComplex, cm: &ComplexMap) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-D1(faces)",
        "Def. 1: X maps every edge of σ into itself (exact)",
    );
    for (f, m) in cm.maps.iter().enumerate() {
        r.examined += 1;
        match m.family {
            Family::Monotonic => {
                for c in 0..3 {
                    let g0 = m.g[c].at_zero();
                    if !g0.is_zero() {
                        let v = k.triangles[f][c];
                        r.offend(|| Witness::new(format!("triangle {f}: g at vertex {v} has g(0) = {g0} ≠ 0, so x^{c} ≠ 0 on the opposite edge"), json!({"triangle": f, "vertex": v, "g0": g0.to_string()})));
                    }
                }
            }
            _ => {
                for (idx, i) in multi_indices(m.degree).into_iter().enumerate() {
                    for c in 0..3 {
                        let v = &m.weights[idx] * &m.control[idx][c];
                        if i[c] == 0 && !v.is_zero() {
                            let key = super::params::MapSpec::global_key(k, f, i);
                            r.offend(|| Witness::new(format!("triangle {f}: control point of {key:?} has barycentric coordinate {} = {} ≠ 0 off its face", c, m.control[idx][c]), json!({"triangle": f, "multiset": key, "coordinate": c, "value": m.control[idx][c].to_string()})));
                        }
                    }
                }
            }
        }
    }
    r
}

/// Def. 1 (L79) inside: X(σ) ⊂ σ, i.e. every x^c ≥ 0 on σ (given D > 0), decided exactly.
pub(crate) fn maps_into_simplex(cm: &ComplexMap, budget: Budget) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-D1(inside)",
        "Def. 1: X(σ) ⊂ σ, all x^c ≥ 0 on σ (exact)",
    );
    let mut tally = Tally::default();
    for (f, m) in cm.maps.iter().enumerate() {
        for c in 0..3 {
            r.examined += 1;
            // x^c = N_c / D: sign of N_c·D.
            let p = if m.family == Family::Polynomial {
                m.num[c].clone()
            } else {
                m.num[c].mul(&m.den)
            };
            let d = decide(&p, Strictness::NonNegative, budget);
            tally.record(&mut r, &d, |x| {
                let (v, w) = (x.value_f64, x.point_f64);
                Witness::new(
                    format!("triangle {f}: x^{c}·D = {v:.3e} < 0 at w = {w:?}"),
                    json!({"triangle": f, "component": c, "w": x.point, "value": v}),
                )
            });
        }
    }
    tally.finish(&mut r);
    r
}

/// Mello–Velho Sec. 3 (L99): two triangles sharing an edge define the same X on it. Exact
/// polynomial identity of (Σ N_c v_c)·D' and (Σ N'_c v'_c)·D in the edge parameter.
pub(crate) fn shared_edges_agree(k: &PlanarComplex, cm: &ComplexMap) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L99",
        "adjacent triangles define the same X on their common edge (exact)",
    );
    for (a, b, f, g) in k.interior_edges() {
        r.examined += 1;
        let ef = edge_image(k, &cm.maps[f], f, a, b);
        let eg = edge_image(k, &cm.maps[g], g, a, b);
        // (P_f / D_f) vs (P_g / D_g) for both plane coordinates.
        for axis in 0..2 {
            let lhs = ef.0[axis].mul(&eg.1);
            let rhs = eg.0[axis].mul(&ef.1);
            let diff = lhs.sub(&rhs);
            if !diff.is_zero() {
                // A nonzero polynomial of degree d has ≤ d roots: one of d + 1 points differs.
                let d = diff.deg();
                let u = (0..=d as i64)
                    .map(|j| qr(j, d.max(1) as i64))
                    .find(|u| !diff.eval(u, &q(0)).is_zero())
                    .unwrap_or_else(|| qr(1, 2));
                let xf = to_f64(&(ef.0[axis].eval(&u, &q(0)) / ef.1.eval(&u, &q(0))));
                let xg = to_f64(&(eg.0[axis].eval(&u, &q(0)) / eg.1.eval(&u, &q(0))));
                r.offend(|| Witness::new(format!("edge ({a},{b}) at u = {u}: triangle {f} gives coordinate {axis} = {xf:.17}, triangle {g} gives {xg:.17}"), json!({"edge": [a, b], "u": u.to_string(), "triangles": [f, g], "values": [xf, xg]})));
                break;
            }
        }
    }
    if r.examined == 0 {
        r.skip("the complex has no interior edge");
    }
    r
}

/// X on the edge a→b of triangle f as (plane numerators [x, y], D), polynomials in s = u.
fn edge_image(k: &PlanarComplex, m: &SimplexMap, f: usize, a: u32, b: u32) -> ([Poly2; 2], Poly2) {
    let t = k.triangles[f];
    let la = t.iter().position(|&v| v == a).unwrap_or(0);
    let lb = t.iter().position(|&v| v == b).unwrap_or(0);
    let tri = [corner(la), corner(lb), corner(lb)];
    let n: Vec<Poly2> = m.num.iter().map(|p| p.compose_affine(&tri)).collect();
    let d = m.den.compose_affine(&tri);
    let mut plane = [Poly2::zero(0), Poly2::zero(0)];
    for (c, nc) in n.iter().enumerate() {
        let v = &k.points[t[c] as usize];
        for axis in 0..2 {
            plane[axis] = plane[axis].add(&nc.scale(&v[axis]));
        }
    }
    (plane, d)
}

/// Sec. 3 (L101): det DX > 0 on every closed triangle, decided exactly (Bernstein coefficients
/// over ℚ with subdivision), with D > 0 decided first for Eqs. (9) and (11).
pub fn det_positive_exact(cm: &ComplexMap, budget: Budget) -> (CheckResult, Vec<Decision>) {
    let mut r = CheckResult::new(
        "SD-L101(det)",
        "det DX > 0 on every closed triangle (exact Bernstein certificate)",
    );
    let mut decisions = Vec::new();
    let mut tally = Tally::default();
    let mut zero_on_boundary = 0u64;
    for (f, m) in cm.maps.iter().enumerate() {
        r.examined += 1;
        if m.family != Family::Polynomial {
            let dd = decide(&m.den, Strictness::Positive, budget);
            if let Decision::Refuted {
                point_f64,
                value_f64,
                ..
            } = &dd
            {
                let (p, v) = (*point_f64, *value_f64);
                r.offend(|| {
                    Witness::new(
                        format!("triangle {f}: the denominator D = {v:.3e} ≤ 0 at w = {p:?}"),
                        json!({"triangle": f, "w": p, "D": v}),
                    )
                });
                decisions.push(dd);
                continue;
            }
            if !dd.certified() {
                tally.unresolved();
                decisions.push(dd);
                continue;
            }
        }
        let d = decide(&m.jacobian_numerator(), Strictness::Positive, budget);
        if let Decision::Refuted { point, value, .. } = &d {
            if value == "0" && point.iter().any(|x| x == "0") {
                zero_on_boundary += 1;
            }
        }
        tally.record(&mut r, &d, |x| {
            let (v, vf, p) = (x.value, x.value_f64, x.point_f64);
            Witness::new(
                format!("triangle {f}: det DX numerator = {v} (≈ {vf:.3e}) ≤ 0 at w = {p:?}"),
                json!({"triangle": f, "w": x.point, "value": v}),
            )
        });
        decisions.push(d);
    }
    r.worst_deviation = tally.worst();
    if zero_on_boundary > 0 && zero_on_boundary == r.offenders {
        r.note = format!("det vanishes only at boundary points of {zero_on_boundary} triangle(s): det > 0 can at most hold on the open triangles there");
    }
    tally.finish(&mut r);
    (r, decisions)
}

/// The interval route for det DX > 0 and its agreement with the exact route: an interval
/// certificate where the exact route refutes is a defect of one of them.
pub(crate) fn det_positive_interval(
    cm: &ComplexMap,
    exact: &[Decision],
    boxes: usize,
) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L101(interval)",
        "det DX > 0 by interval branch-and-bound, and agreement with the exact route",
    );
    let mut unknown = 0u64;
    for (f, m) in cm.maps.iter().enumerate() {
        r.examined += 1;
        let iv = certify_det(m, boxes);
        let ex = exact.get(f);
        match (iv, ex) {
            (IntervalVerdict::Certified { .. }, Some(Decision::Refuted { point_f64, .. })) => {
                let p = *point_f64;
                r.offend(|| Witness::new(format!("triangle {f}: the interval route certifies det > 0 but the exact route refutes it at w = {p:?}"), json!({"triangle": f, "w": p})));
            }
            (IntervalVerdict::Unknown { .. }, Some(Decision::Certified { .. })) => unknown += 1,
            _ => {}
        }
    }
    if unknown > 0 {
        r.note = format!(
            "{unknown} triangle(s) certified exactly but not by intervals within {boxes} boxes"
        );
    }
    r
}

/// Sec. 3.2 "adjusted" (L137): χ(b_I) = χ(I), i.e. c_I lies in the open face supp I.
pub fn adjusted(k: &PlanarComplex, cm: &ComplexMap) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L137(adjusted)",
        "Sec. 3.2: every control point lies in the open face of its multi-index",
    );
    for (f, m) in cm.maps.iter().enumerate() {
        if m.family == Family::Monotonic {
            continue;
        }
        for (idx, i) in multi_indices(m.degree).into_iter().enumerate() {
            r.examined += 1;
            let b = &m.control[idx];
            let ok = (0..3).all(|c| {
                if i[c] > 0 {
                    b[c].is_positive()
                } else {
                    b[c].is_zero()
                }
            });
            if !ok {
                let key = super::params::MapSpec::global_key(k, f, i);
                r.offend(|| Witness::new(format!("triangle {f}: c_I for {key:?} has barycentric coordinates ({}, {}, {})", b[0], b[1], b[2]), json!({"triangle": f, "multiset": key})));
            }
        }
    }
    if r.examined == 0 {
        r.skip("not a polynomial or rational map");
    }
    r
}

/// Sec. 3.1 hypotheses (L111): every g_v has g_v(0) = 0 and g_v' > 0 on [0, 1] (exact).
pub(crate) fn monotone_hypotheses(cm: &ComplexMap, budget: Budget) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-E9(hyp)",
        "Eq. (9): g_i(0) = 0 and g_i' > 0 on [0, 1] (exact)",
    );
    for (f, m) in cm.maps.iter().enumerate() {
        for (c, g) in m.g.iter().enumerate() {
            r.examined += 1;
            if !g.at_zero().is_zero() {
                r.offend(|| {
                    Witness::new(
                        format!("triangle {f}, local vertex {c}: g(0) = {}", g.at_zero()),
                        json!({"triangle": f, "local": c}),
                    )
                });
                continue;
            }
            let d = g.decide_increasing(budget);
            if let Decision::Refuted {
                point_f64,
                value_f64,
                ..
            } = d
            {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "triangle {f}, local vertex {c}: g'({}) = {value_f64:.3e} ≤ 0",
                            point_f64[1]
                        ),
                        json!({"triangle": f, "local": c, "t": point_f64[1], "g_prime": value_f64}),
                    )
                });
            }
        }
    }
    if r.examined == 0 {
        r.skip("not a monotonic map");
    }
    r
}

/// Sec. 3.3 hypothesis (L161): every weight q_I > 0.
pub(crate) fn weights_positive(cm: &ComplexMap) -> CheckResult {
    let mut r = CheckResult::new("SD-E11(hyp)", "Eq. (11): every weight q_I is positive");
    for (f, m) in cm.maps.iter().enumerate() {
        if m.family != Family::Rational {
            continue;
        }
        r.examined += m.weights.len() as u64;
        if let Some((i, w)) = m.first_nonpositive_weight() {
            r.offend(|| {
                Witness::new(
                    format!("triangle {f}: weight {i} is {w}"),
                    json!({"triangle": f, "index": i, "weight": w.to_string()}),
                )
            });
        }
    }
    if r.examined == 0 {
        r.skip("not a rational map");
    }
    r
}

/// The boundary half of the Meisters–Olech argument (L101): X restricted to each edge of σ is
/// an increasing map of the edge parameter (exact), so X|∂σ is a homeomorphism of ∂σ; with
/// det DX > 0 inside, X|σ is then a bijection by the argument principle.
pub(crate) fn edges_monotone(k: &PlanarComplex, cm: &ComplexMap, budget: Budget) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L101(edges)",
        "X restricted to every edge is strictly increasing in the edge parameter (exact)",
    );
    let mut tally = Tally::default();
    let seg = [[q(0), q(0)], [q(1), q(0)], [q(1), q(0)]];
    for (f, m) in cm.maps.iter().enumerate() {
        for la in 0..3 {
            let lb = (la + 1) % 3;
            r.examined += 1;
            let tri = [corner(la), corner(lb), corner(lb)];
            let nb = m.num[lb].compose_affine(&tri);
            let d = m.den.compose_affine(&tri);
            // d/du (N_b / D) has the sign of N_b' D − N_b D'.
            let p = nb.ds().mul(&d).sub(&nb.mul(&d.ds()));
            let d = decide_on(&p, seg.clone(), Strictness::Positive, budget);
            let (a, b) = (k.triangles[f][la], k.triangles[f][lb]);
            tally.record(&mut r, &d, |x| {
                let (u, v) = (x.point_f64[1], x.value_f64);
                Witness::new(
                    format!(
                        "triangle {f}, edge ({a}→{b}) at u = {u}: derivative numerator {v:.3e} ≤ 0"
                    ),
                    json!({"triangle": f, "edge": [a, b], "u": u}),
                )
            });
        }
    }
    // The edge checks report no lower bound (the worst deviation stays unset, as before).
    tally.finish(&mut r);
    r
}

/// Partition of unity (Eq. (1), L131): Σ_c x^c ≡ 1, i.e. Σ_c N_c − D is the zero polynomial.
pub(crate) fn partition_of_unity(cm: &ComplexMap) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L131",
        "Eq. (1) for x: Σ_c x^c ≡ 1 (exact polynomial identity)",
    );
    for (f, m) in cm.maps.iter().enumerate() {
        r.examined += 1;
        let d = m.unity_defect();
        if !d.is_zero() {
            let v = to_f64(&(d.eval(&qr(1, 3), &qr(1, 3)) / m.den.eval(&qr(1, 3), &qr(1, 3))));
            r.offend(|| {
                Witness::new(
                    format!(
                        "triangle {f}: Σ x^c − 1 is not identically 0 (at the centroid: {v:.3e})"
                    ),
                    json!({"triangle": f, "at_centroid": v}),
                )
            });
        }
    }
    r
}

/// All checks on a map of a complex, in the order of the paper.
pub fn check_all(k: &PlanarComplex, cm: &ComplexMap, opts: &Options) -> Vec<CheckResult> {
    let mut out = vec![
        partition_of_unity(cm),
        faces_preserved(k, cm),
        maps_into_simplex(cm, opts.budget),
        shared_edges_agree(k, cm),
        adjusted(k, cm),
        monotone_hypotheses(cm, opts.budget),
        weights_positive(cm),
        edges_monotone(k, cm, opts.budget),
    ];
    let (det, decisions) = det_positive_exact(cm, opts.budget);
    out.push(det);
    out.push(det_positive_interval(cm, &decisions, opts.interval_boxes));
    out.push(super::inverse::inversion_spot_check(
        cm,
        opts.seed,
        opts.inversion_samples,
    ));
    out
}
