//! The checks of Mello–Velho Secs. 2–3 on a map of a tetrahedral complex (m = 3), each a
//! [`CheckResult`] with its SPEC ID (`SD-…(3-D)`), decided exactly where the statement is
//! algebraic: partition of unity and K-invariance on faces as polynomial identities, X(σ) ⊂ σ
//! and det DX > 0 on every closed tetrahedron by trivariate Bernstein certificates over ℚ
//! (`tet::decide_tet_with`), agreement on shared triangles as bivariate polynomial identities,
//! and the interval route of `tet::interval` compared with the exact one.
//!
//! Injectivity on σ follows from det DX > 0 on the closed σ and K-invariance (L101,
//! Meisters–Olech): X maps each face into its own plane, so DX is block-triangular there and
//! det DX ≠ 0 makes every face and edge restriction a local diffeomorphism too.

use super::complex::TetComplex;
use super::interval::certify_det_tet;
use super::maps::multi_indices4;
use super::params::{MapSpec3, TetMap};
use super::poly::{decide_tet_with, jacobian_numerator, Poly3};
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::decide::Tally;
use crate::sdiff::common::interval::IntervalVerdict;
use crate::sdiff::common::params::{FamilySpec, Multiset};
use crate::sdiff::common::positivity::{Budget, Decision, Strictness};
use crate::sdiff::common::rational::{q, qr, to_f64, Q};
use num_traits::{Signed, Zero};
use serde_json::json;

/// Options of [`check_all3`].
#[derive(Debug, Clone, Copy)]
pub struct Options3 {
    /// Budget of each exact positivity decision.
    pub budget: Budget,
    /// Box budget of the interval route per tetrahedron.
    pub interval_boxes: usize,
}

impl Default for Options3 {
    fn default() -> Self {
        Options3 {
            budget: Budget::default(),
            interval_boxes: 20_000,
        }
    }
}

fn skipped_if_empty(r: &mut CheckResult, reason: &str) {
    if r.examined == 0 {
        r.skip(reason);
    }
}

/// The corner of the reference tetrahedron for local vertex `i` in the chart (s, t, r).
pub(crate) fn corner3(i: usize) -> [Q; 3] {
    std::array::from_fn(|k| if k + 1 == i { q(1) } else { q(0) })
}

/// Eq. (1) for x (L131): Σ_c N_c ≡ D.
pub fn partition_of_unity3(maps: &[TetMap]) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L131(3-D)",
        "Eq. (1) for x: Σ_c x^c ≡ 1 on every tetrahedron (exact polynomial identity)",
    );
    let centroid = [qr(1, 4), qr(1, 4), qr(1, 4)];
    for (f, m) in maps.iter().enumerate() {
        r.examined += 1;
        let d = m.unity_defect();
        if d != Poly3::default() {
            let v = to_f64(&(d.eval(&centroid) / m.den.eval(&centroid)));
            r.offend(|| {
                Witness::new(
                    format!("tetrahedron {f}: Σ x^c − 1 is not identically 0 (at the centroid: {v:.3e})"),
                    json!({"tet": f, "at_centroid": v}),
                )
            });
        }
    }
    r
}

/// Def. 1 (L79) on the faces: x^k ≡ 0 on the face w_k = 0. Exact: the B_I with I^k = 0 are a
/// basis there, so iff q_I b_I\[k\] = 0 for every such I (Eq. (9): iff g_k(0) = 0).
pub(crate) fn faces_preserved3(k: &TetComplex, maps: &[TetMap]) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-D1(faces,3-D)",
        "Def. 1: X maps every face of σ into itself (exact)",
    );
    for (f, m) in maps.iter().enumerate() {
        r.examined += 1;
        if m.family == FamilySpec::Monotonic {
            for c in 0..4 {
                let g0 = m.g[c].at_zero();
                if !g0.is_zero() {
                    let v = k.tets[f][c];
                    r.offend(|| Witness::new(format!("tetrahedron {f}: g at vertex {v} has g(0) = {g0} ≠ 0, so x^{c} ≠ 0 on the opposite face"), json!({"tet": f, "vertex": v, "g0": g0.to_string()})));
                }
            }
            continue;
        }
        for (idx, i) in multi_indices4(m.degree).into_iter().enumerate() {
            for c in 0..4 {
                let v = &m.weights[idx] * &m.control[idx][c];
                if i[c] == 0 && !v.is_zero() {
                    let key = MapSpec3::global_key(k, f, i);
                    let b = m.control[idx][c].clone();
                    r.offend(|| Witness::new(format!("tetrahedron {f}: the control point of {key:?} has barycentric coordinate {c} = {b} ≠ 0, off its face"), json!({"tet": f, "multiset": key, "coordinate": c, "value": b.to_string()})));
                }
            }
        }
    }
    r
}

/// Def. 1 inside: X(σ) ⊂ σ, every x^c ≥ 0 on σ (sign of N_c·D), exact.
pub(crate) fn maps_into_simplex3(maps: &[TetMap], budget: Budget) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-D1(inside,3-D)",
        "Def. 1: X(σ) ⊂ σ, all x^c ≥ 0 on σ (exact)",
    );
    let mut tally = Tally::default();
    for (f, m) in maps.iter().enumerate() {
        for c in 0..4 {
            r.examined += 1;
            let p = m.num[c].mul(&m.den);
            let d = decide_tet_with(&p, Strictness::NonNegative, budget);
            tally.record(&mut r, &d, |x| {
                let (v, w) = (x.value_f64, x.point_f64);
                Witness::new(
                    format!("tetrahedron {f}: x^{c}·D² = {v:.3e} < 0 at (w_1, w_2, w_3) = {w:?}"),
                    json!({"tet": f, "component": c, "w123": x.point, "value": v}),
                )
            });
        }
    }
    tally.finish(&mut r);
    r
}

/// X on the triangle `tri` of tetrahedron f as (space numerators \[x, y, z\], D), polynomials
/// in the face chart (s, t) = (weight of tri\[1\], weight of tri\[2\]); r does not occur (the
/// frame's fourth corner is its first).
fn face_image(k: &TetComplex, m: &TetMap, f: usize, tri: &[u32; 3]) -> ([Poly3; 3], Poly3) {
    let t = k.tets[f];
    let local = tri.map(|v| t.iter().position(|&x| x == v).unwrap_or(0));
    let frame = [
        corner3(local[0]),
        corner3(local[1]),
        corner3(local[2]),
        corner3(local[0]),
    ];
    let n: Vec<Poly3> = m.num.iter().map(|p| p.compose_affine(&frame)).collect();
    let d = m.den.compose_affine(&frame);
    let mut space: [Poly3; 3] = Default::default();
    for (c, nc) in n.iter().enumerate() {
        let v = &k.points[t[c] as usize];
        for axis in 0..3 {
            space[axis] = space[axis].axpy(&v[axis], nc);
        }
    }
    (space, d)
}

/// Sec. 3 (L99): two tetrahedra sharing a triangle define the same X on it. Exact identity of
/// (Σ N_c v_c)·D′ and (Σ N′_c v′_c)·D in the triangle's chart.
pub(crate) fn shared_faces_agree3(k: &TetComplex, maps: &[TetMap]) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L99(3-D)",
        "adjacent tetrahedra define the same X on their common triangle (exact)",
    );
    for (tri, f, g) in k.interior_faces() {
        r.examined += 1;
        let ef = face_image(k, &maps[f], f, &tri);
        let eg = face_image(k, &maps[g], g, &tri);
        for axis in 0..3 {
            let diff = ef.0[axis].mul(&eg.1).axpy(&q(-1), &eg.0[axis].mul(&ef.1));
            if diff == Poly3::default() {
                continue;
            }
            // The triangular grid {(i/e, j/e) : i + j ≤ e}, e = d + 1, is unisolvent for degree
            // ≤ e, so a nonzero polynomial of degree d differs from 0 at one of its points.
            let dd = diff.deg() as i64 + 1;
            let mut at = [qr(1, 3), qr(1, 3), q(0)];
            'grid: for i in 0..=dd {
                for j in 0..=(dd - i) {
                    let p = [qr(i, dd), qr(j, dd), q(0)];
                    if !diff.eval(&p).is_zero() {
                        at = p;
                        break 'grid;
                    }
                }
            }
            let xf = to_f64(&(ef.0[axis].eval(&at) / ef.1.eval(&at)));
            let xg = to_f64(&(eg.0[axis].eval(&at) / eg.1.eval(&at)));
            let (s, t) = (at[0].to_string(), at[1].to_string());
            r.offend(|| Witness::new(format!("triangle {tri:?} at (s, t) = ({s}, {t}): tetrahedron {f} gives coordinate {axis} = {xf:.17}, tetrahedron {g} gives {xg:.17}"), json!({"face": tri, "st": [s, t], "tets": [f, g], "values": [xf, xg]})));
            break;
        }
    }
    skipped_if_empty(&mut r, "the complex has no interior triangle");
    r
}

/// Sec. 3.2 "adjusted" (L137): χ(b_I) = χ(I), c_I in the open face supp I.
pub(crate) fn adjusted3(k: &TetComplex, maps: &[TetMap]) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L137(adjusted,3-D)",
        "Sec. 3.2: every control point lies in the open face of its multi-index",
    );
    for (f, m) in maps.iter().enumerate() {
        if m.family == FamilySpec::Monotonic {
            continue;
        }
        for (idx, i) in multi_indices4(m.degree).into_iter().enumerate() {
            r.examined += 1;
            let b = &m.control[idx];
            let ok = (0..4).all(|c| {
                if i[c] > 0 {
                    b[c].is_positive()
                } else {
                    b[c].is_zero()
                }
            });
            if !ok {
                let key: Multiset = MapSpec3::global_key(k, f, i);
                let bs: Vec<String> = b.iter().map(|x| x.to_string()).collect();
                r.offend(|| {
                    Witness::new(
                        format!(
                            "tetrahedron {f}: c_I for {key:?} has barycentric coordinates {bs:?}"
                        ),
                        json!({"tet": f, "multiset": key, "b": bs}),
                    )
                });
            }
        }
    }
    skipped_if_empty(&mut r, "not a polynomial or rational map");
    r
}

/// Sec. 3.1 hypotheses (L111): g_v(0) = 0 and g_v′ > 0 on \[0, 1\] (exact).
pub(crate) fn monotone_hypotheses3(k: &TetComplex, maps: &[TetMap], budget: Budget) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-E9(hyp,3-D)",
        "Eq. (9): g_v(0) = 0 and g_v' > 0 on [0, 1] (exact)",
    );
    for (f, m) in maps.iter().enumerate() {
        for (c, g) in m.g.iter().enumerate() {
            r.examined += 1;
            let v = k.tets[f][c];
            if !g.at_zero().is_zero() {
                let g0 = g.at_zero().to_string();
                r.offend(|| {
                    Witness::new(
                        format!("tetrahedron {f}, vertex {v}: g(0) = {g0}"),
                        json!({"tet": f, "vertex": v, "g0": g0}),
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
                            "tetrahedron {f}, vertex {v}: g'({}) = {value_f64:.3e} ≤ 0",
                            point_f64[1]
                        ),
                        json!({"tet": f, "vertex": v, "t": point_f64[1], "g_prime": value_f64}),
                    )
                });
            }
        }
    }
    skipped_if_empty(&mut r, "not a monotonic map");
    r
}

/// Sec. 3.3 hypothesis (L161): every weight q_I > 0.
pub(crate) fn weights_positive3(k: &TetComplex, maps: &[TetMap]) -> CheckResult {
    let mut r = CheckResult::new("SD-E11(hyp,3-D)", "Eq. (11): every weight q_I is positive");
    for (f, m) in maps.iter().enumerate() {
        if m.family != FamilySpec::Rational {
            continue;
        }
        for (idx, i) in multi_indices4(m.degree).into_iter().enumerate() {
            r.examined += 1;
            let w = &m.weights[idx];
            if !w.is_positive() {
                let key = MapSpec3::global_key(k, f, i);
                let ws = w.to_string();
                r.offend(|| {
                    Witness::new(
                        format!("tetrahedron {f}: weight of {key:?} is {ws}"),
                        json!({"tet": f, "multiset": key, "weight": ws}),
                    )
                });
            }
        }
    }
    skipped_if_empty(&mut r, "not a rational map");
    r
}

/// det DX > 0 on the closed reference tetrahedron for one map, exactly (D > 0 first).
pub fn det_decision(m: &TetMap, budget: Budget) -> Decision {
    if m.family != FamilySpec::Polynomial {
        let dd = decide_tet_with(&m.den, Strictness::Positive, budget);
        if !dd.certified() {
            return dd;
        }
    }
    decide_tet_with(
        &jacobian_numerator(&m.chart_num(), &m.den),
        Strictness::Positive,
        budget,
    )
}

/// L101: det DX > 0 on every closed tetrahedron (exact Bernstein certificate, D > 0 first for
/// Eqs. (9), (11)); returns the decisions for the interval comparison.
pub(crate) fn det_positive_exact3(maps: &[TetMap], budget: Budget) -> (CheckResult, Vec<Decision>) {
    let mut r = CheckResult::new(
        "SD-L101(det,3-D)",
        "det DX > 0 on every closed tetrahedron (exact Bernstein certificate)",
    );
    let mut decisions = Vec::new();
    let mut tally = Tally::default();
    for (f, m) in maps.iter().enumerate() {
        r.examined += 1;
        let d = det_decision(m, budget);
        tally.record(&mut r, &d, |x| {
            let (v, vf, p) = (x.value, x.value_f64, x.point_f64);
            Witness::new(
                format!("tetrahedron {f}: D or the det DX numerator = {v} (≈ {vf:.3e}) ≤ 0 at (w_1, w_2, w_3) = {p:?}"),
                json!({"tet": f, "w123": x.point, "value": v}),
            )
        });
        decisions.push(d);
    }
    r.worst_deviation = tally.worst();
    if r.worst_deviation.is_some() {
        r.note = "worst deviation = smallest Bernstein coefficient of a certificate (a lower bound of the det numerator)".into();
    }
    tally.finish(&mut r);
    (r, decisions)
}

/// The interval route and its agreement with the exact one: an interval certificate where the
/// exact route refutes is a defect of one of them.
pub(crate) fn det_positive_interval3(
    maps: &[TetMap],
    exact: &[Decision],
    boxes: usize,
) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L101(interval,3-D)",
        "det DX > 0 by interval branch-and-bound, never certifying what the exact route refutes",
    );
    let (mut both, mut unknown) = (0u64, 0u64);
    for (f, m) in maps.iter().enumerate() {
        r.examined += 1;
        let iv = certify_det_tet(m, boxes);
        match (iv, exact.get(f)) {
            (IntervalVerdict::Certified { .. }, Some(Decision::Refuted { point_f64, .. })) => {
                let p = *point_f64;
                r.offend(|| Witness::new(format!("tetrahedron {f}: the interval route certifies det > 0, the exact route refutes it at (w_1, w_2, w_3) = {p:?}"), json!({"tet": f, "w123": p})));
            }
            (IntervalVerdict::Certified { .. }, Some(Decision::Certified { .. })) => both += 1,
            (IntervalVerdict::Unknown { .. }, _) => unknown += 1,
            _ => {}
        }
    }
    r.note = format!("{both} tetrahedra certified by both routes, {unknown} not decided by intervals within {boxes} boxes");
    r
}

/// All checks on a map of a tetrahedral complex, in the order of the paper.
pub fn check_all3(k: &TetComplex, maps: &[TetMap], opts: &Options3) -> Vec<CheckResult> {
    let mut out = vec![
        partition_of_unity3(maps),
        faces_preserved3(k, maps),
        maps_into_simplex3(maps, opts.budget),
        shared_faces_agree3(k, maps),
        adjusted3(k, maps),
        monotone_hypotheses3(k, maps, opts.budget),
        weights_positive3(k, maps),
    ];
    let (det, decisions) = det_positive_exact3(maps, opts.budget);
    out.push(det);
    out.push(det_positive_interval3(
        maps,
        &decisions,
        opts.interval_boxes,
    ));
    out
}
