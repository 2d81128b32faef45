//! Checks of the Sec. 5.4 atlas: the topological-disk test of step (4), injective charts,
//! transitions affine (Def. 7) and translations (Thm. 4), the step (6) formula as written,
//! and Def. 3.4.1 through the sampled gluing-data checkers on neighbourhood views.

use super::atlas::{euler_of_faces, Atlas, P2};
use super::cochain::EdgeIndex;
use super::view::AtlasView;
use crate::gluing::sampled::{check_all, SampleConfig};
use crate::mesh::{FaceId, SimplicialSurface};
use crate::numeric::predicates::orient2_det;
use crate::report::{CheckResult, Verdict, Witness, MAX_WITNESSES};
use rand::{Rng, SeedableRng};
use serde_json::json;
use std::collections::BTreeSet;

/// Sec. 5.4 step (4): χ(U_α ∪ U_β) = 1 for every overlapping pair (the paper's test that the
/// union is a topological disk).
pub fn check_union_disks(k: &SimplicialSurface, ei: &EdgeIndex, at: &Atlas) -> CheckResult {
    let mut r = CheckResult::new("MS-5.4(4)", "χ(U_α ∪ U_β) = 1 for overlapping charts");
    for &(a, b) in at.pairs.keys() {
        r.examined += 1;
        let (ca, cb) = (&at.charts[a as usize], &at.charts[b as usize]);
        let faces = ca
            .faces
            .keys()
            .chain(cb.faces.keys().filter(|f| !ca.faces.contains_key(f)))
            .copied();
        let chi = euler_of_faces(k, ei, faces);
        if chi != 1 {
            r.offend(|| {
                Witness::new(
                    format!(
                        "charts at vertices {} and {}: χ(U_α ∪ U_β) = {chi}",
                        ca.centre, cb.centre
                    ),
                    json!({"alpha": a, "beta": b, "chi": chi}),
                )
            });
        }
    }
    r.with_note(format!(
        "{} overlapping pairs, k = {}; exact (combinatorial)",
        at.pairs.len(),
        at.k_ring
    ))
}

/// Do the open triangles s and t overlap? Exact: disjoint interiors iff an edge line of one
/// has the other on its closed outer side.
fn interiors_overlap(s: &[P2; 3], t: &[P2; 3]) -> bool {
    let sep = |a: &[P2; 3], b: &[P2; 3]| {
        let o = orient2_det(a[0], a[1], a[2]).signum();
        (0..3).any(|i| {
            b.iter()
                .all(|&p| orient2_det(a[i], a[(i + 1) % 3], p) * o <= 0.0)
        })
    };
    !(sep(s, t) || sep(t, s))
}

/// Def. 4 / Sec. 5.4: each φ_α is a homeomorphism onto its image — image faces positively
/// oriented (exact), pairwise interior-disjoint (exact), and the developing map consistent
/// (a vertex reached along two paths lands on one point up to rounding).
pub fn check_charts_injective(at: &Atlas) -> CheckResult {
    injective(
        at,
        "MS-D4",
        "charts φ_α injective (oriented, non-overlapping images)",
    )
    .0
}

/// `MS-D4` on the atlas of Sec. 5.4 as written, with every non-injective chart classified by
/// what the corrected atlas removes: it holds a face with flipped or degenerate image, or its
/// centre is a corner of one (a fan whose positive angles exceed 2π), or its ring touches a
/// removed star and falls apart (faces unreached), or none of these (reported as "other").
pub fn check_charts_injective_as_written(
    k: &SimplicialSurface,
    at: &Atlas,
    bad_faces: &BTreeSet<FaceId>,
) -> CheckResult {
    let (mut r, bad) = injective(
        at,
        "MS-D4",
        "charts φ_α injective (oriented, non-overlapping images)",
    );
    let (mut holds_flip, mut centre_flip, mut split, mut other) = (0, 0, 0, 0);
    for a in &bad {
        let ch = &at.charts[*a];
        if ch.faces.keys().any(|f| bad_faces.contains(f)) {
            holds_flip += 1;
        } else if bad_faces.iter().any(|f| k.face(*f).contains(&ch.centre)) {
            centre_flip += 1;
        } else if ch.unreached > 0 {
            split += 1;
        } else {
            other += 1;
        }
    }
    r.note = format!(
        "{}; {} non-injective charts: {holds_flip} hold a flipped/degenerate face image, {centre_flip} are centred at a corner of one, {split} have a ring split by the removed stars, {other} other",
        r.note,
        bad.len()
    );
    r
}

/// `MS-D4-corrected`: the same test on the corrected atlas
/// ([`super::atlas::build_corrected`]: open stars of every vertex with w_v ≠ 1 and of every
/// corner of a flipped or degenerate face image removed, rings split into edge-connected
/// pieces); the note gives how much of M it covers.
pub fn check_charts_injective_corrected(at: &Atlas) -> CheckResult {
    let kept = at.removed.iter().filter(|&&r| !r).count();
    let n = at.removed.len();
    let (mut r, _) = injective(
        at,
        "MS-D4-corrected",
        "corrected atlas (stars of w_v ≠ 1 and of flipped faces' corners removed): charts injective",
    );
    r.note = format!(
        "{}; {} removed vertices, atlas covers {kept} of {n} faces",
        r.note,
        at.zeros.len()
    );
    r
}

/// The check and the indices of the charts that fail it.
fn injective(at: &Atlas, id: &str, name: &str) -> (CheckResult, Vec<usize>) {
    let mut r = CheckResult::new(id, name);
    let mut worst: f64 = 0.0;
    let mut bad = Vec::new();
    for (a, ch) in at.charts.iter().enumerate() {
        r.examined += 1;
        let before = r.offenders;
        let tris: Vec<(&FaceId, &[P2; 3])> = ch.faces.iter().collect();
        for (f, t) in &tris {
            // `!(o > 0)`: a NaN image (orient2_det of a NaN point is NaN) is not oriented.
            if !(orient2_det(t[0], t[1], t[2]) > 0.0) {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "chart at vertex {}: image of face {f} not positively oriented",
                            ch.centre
                        ),
                        json!({"chart": a, "face": f.0, "kind": "orientation"}),
                    )
                });
            }
        }
        for i in 0..tris.len() {
            for j in i + 1..tris.len() {
                if interiors_overlap(tris[i].1, tris[j].1) {
                    r.offend(|| Witness::new(format!("chart at vertex {}: images of faces {} and {} overlap", ch.centre, tris[i].0, tris[j].0), json!({"chart": a, "faces": [tris[i].0 .0, tris[j].0 .0], "kind": "overlap"})));
                }
            }
        }
        let mag = ch
            .path_magnitude
            .values()
            .copied()
            .fold(0.0, crate::report::dev_max);
        let tol = 64.0 * f64::EPSILON * 2.0 * mag;
        worst = crate::report::dev_max(worst, ch.develop_defect);
        if !(ch.develop_defect <= tol) {
            r.offend(|| Witness::new(format!("chart at vertex {}: developing map disagrees by {:.3e} > {tol:.3e} (U_α not simply connected, or ω not closed)", ch.centre, ch.develop_defect), json!({"chart": a, "defect": ch.develop_defect, "kind": "develop"})));
        }
        if ch.unreached > 0 {
            r.offend(|| Witness::new(format!("chart at vertex {}: {} faces of the k-ring not connected to p_α through U_α", ch.centre, ch.unreached), json!({"chart": a, "unreached": ch.unreached, "kind": "disconnected"})));
        }
        if r.offenders > before {
            bad.push(a);
        }
    }
    r.worst_deviation = Some(worst);
    (r.with_note("orientation and overlap exact (Shewchuk predicates); developing consistency to 128·ε·Σ|ω| along the path"), bad)
}

/// The translation t with φ_β = φ_α + t on a common face, and the largest deviation of the
/// other common vertices from it, with the rounding tolerance.
pub struct PairTranslation {
    /// (α, β).
    pub pair: (u32, u32),
    /// φ_β(v) − φ_α(v) at the first corner of the first common face.
    pub t: P2,
    /// max |φ_β(v) − φ_α(v) − t| over the corners of every common face.
    pub deviation: f64,
    /// 64·ε·(Σ|ω| along both developing paths), the rounding allowance.
    pub tolerance: f64,
    /// The corner where the deviation is largest.
    pub worst_face: FaceId,
}

/// Measure every transition against a translation.
pub fn translations(at: &Atlas) -> Vec<PairTranslation> {
    at.pairs
        .iter()
        .filter_map(|(&(a, b), common)| {
            let (ca, cb) = (&at.charts[a as usize], &at.charts[b as usize]);
            let f0 = *common.first()?;
            let (ta, tb) = (ca.faces.get(&f0)?, cb.faces.get(&f0)?);
            let t = [tb[0][0] - ta[0][0], tb[0][1] - ta[0][1]];
            let (mut dev, mut tol, mut wf) = (0.0f64, 0.0f64, f0);
            for f in common {
                let (Some(ta), Some(tb)) = (ca.faces.get(f), cb.faces.get(f)) else {
                    continue;
                };
                let m = ca.path_magnitude.get(f).copied().unwrap_or(0.0)
                    + cb.path_magnitude.get(f).copied().unwrap_or(0.0)
                    + ca.path_magnitude.get(&f0).copied().unwrap_or(0.0)
                    + cb.path_magnitude.get(&f0).copied().unwrap_or(0.0);
                tol = tol.max(64.0 * f64::EPSILON * m);
                for i in 0..3 {
                    let d = (tb[i][0] - ta[i][0] - t[0]).hypot(tb[i][1] - ta[i][1] - t[1]);
                    if d > dev || d.is_nan() {
                        dev = d;
                        wf = *f;
                    }
                }
            }
            Some(PairTranslation {
                pair: (a, b),
                t,
                deviation: dev,
                tolerance: tol,
                worst_face: wf,
            })
        })
        .collect()
}

/// Thm. 4: every transition φ_αβ is a translation (checked, not assumed).
pub fn check_translations(at: &Atlas, tr: &[PairTranslation]) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-T4(atlas)",
        "transitions are translations (Thm. 4, eq. (9))",
    );
    let mut worst: f64 = 0.0;
    let mut worst_tol: f64 = 0.0;
    for p in tr {
        r.examined += 1;
        if p.deviation > worst || p.deviation.is_nan() {
            worst = p.deviation;
            worst_tol = p.tolerance;
        }
        if !(p.deviation <= p.tolerance) {
            let (ca, cb) = (&at.charts[p.pair.0 as usize], &at.charts[p.pair.1 as usize]);
            r.offend(|| Witness::new(format!("charts at vertices {} and {}: φ_β − φ_α varies by {:.3e} > {:.3e} (face {}); the loop p_β→p→p_α→q→p_β of eq. (9) is not null-homotopic in U_α ∪ U_β", ca.centre, cb.centre, p.deviation, p.tolerance, p.worst_face), json!({"alpha": p.pair.0, "beta": p.pair.1, "deviation": p.deviation, "tol": p.tolerance, "face": p.worst_face.0})));
        }
    }
    r.worst_deviation = Some(worst);
    r.tolerance = Some(worst_tol);
    r.with_note("tolerance per pair 64·ε·Σ|ω| along the developing paths (worst pair's shown)")
}

/// Def. 7: every transition is affine — the per-face affine maps of φ_β∘φ_α⁻¹ on the
/// common faces all agree with the one fitted on the first common face.
pub fn check_affine(at: &Atlas) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-D7",
        "transitions affine (Def. 7): one (A, b) on all of U_α ∩ U_β",
    );
    let mut worst: f64 = 0.0;
    for (&(a, b), common) in &at.pairs {
        r.examined += 1;
        let (ca, cb) = (&at.charts[a as usize], &at.charts[b as usize]);
        // A pair is overlapping because of its common faces, each in both charts: a pair
        // without one, or a common face missing from a chart, is an inconsistent atlas (an
        // offence with a witness, never a silently skipped pair).
        let Some((f0, ta, tb)) = common
            .first()
            .and_then(|f0| Some((f0, ca.faces.get(f0)?, cb.faces.get(f0)?)))
        else {
            r.offend(|| {
                Witness::new(
                    format!("pair ({a},{b}): no common face present in both charts"),
                    json!({"alpha": a, "beta": b, "kind": "missing"}),
                )
            });
            continue;
        };
        let Some((m, off, cond)) = fit_affine(ta, tb) else {
            r.offend(|| {
                Witness::new(
                    format!("pair ({a},{b}): degenerate image of face {f0}"),
                    json!({"alpha": a, "beta": b}),
                )
            });
            continue;
        };
        let scale = ca.radius().max(cb.radius()).max(f64::MIN_POSITIVE);
        let mag = common
            .iter()
            .map(|f| {
                ca.path_magnitude.get(f).copied().unwrap_or(0.0)
                    + cb.path_magnitude.get(f).copied().unwrap_or(0.0)
            })
            .fold(0.0, crate::report::dev_max);
        let tol = 64.0 * f64::EPSILON * (1.0 + cond) * (scale + mag);
        for f in common {
            let (Some(ta), Some(tb)) = (ca.faces.get(f), cb.faces.get(f)) else {
                r.offend(|| {
                    Witness::new(
                        format!("pair ({a},{b}): common face {f} missing from a chart"),
                        json!({"alpha": a, "beta": b, "face": f.0, "kind": "missing"}),
                    )
                });
                continue;
            };
            for i in 0..3 {
                let p = ta[i];
                let q = [
                    m[0][0] * p[0] + m[0][1] * p[1] + off[0],
                    m[1][0] * p[0] + m[1][1] * p[1] + off[1],
                ];
                let d = (q[0] - tb[i][0]).hypot(q[1] - tb[i][1]);
                worst = crate::report::dev_max(worst, d);
                if !(d <= tol) {
                    r.offend(|| Witness::new(format!("charts at vertices {} and {}: face {f} corner {i} misses the affine map by {d:.3e} > {tol:.3e}", ca.centre, cb.centre), json!({"alpha": a, "beta": b, "face": f.0, "dev": d, "tol": tol})));
                }
            }
        }
    }
    r.worst_deviation = Some(worst);
    r.with_note("A, b fitted on the first common face; tolerance 64·ε·(1 + cond)·(radius + Σ|ω|)")
}

/// The affine map sending triangle s onto t: (A, b, condition number of s's edge matrix).
pub fn fit_affine(s: &[P2; 3], t: &[P2; 3]) -> Option<([[f64; 2]; 2], P2, f64)> {
    let (s1, s2) = (
        [s[1][0] - s[0][0], s[1][1] - s[0][1]],
        [s[2][0] - s[0][0], s[2][1] - s[0][1]],
    );
    let (t1, t2) = (
        [t[1][0] - t[0][0], t[1][1] - t[0][1]],
        [t[2][0] - t[0][0], t[2][1] - t[0][1]],
    );
    let det = s1[0] * s2[1] - s2[0] * s1[1];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    // S⁻¹ = [[s2y, −s2x], [−s1y, s1x]] / det; A = T S⁻¹.
    let inv = [[s2[1] / det, -s2[0] / det], [-s1[1] / det, s1[0] / det]];
    let m = [
        [
            t1[0] * inv[0][0] + t2[0] * inv[1][0],
            t1[0] * inv[0][1] + t2[0] * inv[1][1],
        ],
        [
            t1[1] * inv[0][0] + t2[1] * inv[1][0],
            t1[1] * inv[0][1] + t2[1] * inv[1][1],
        ],
    ];
    let off = [
        t[0][0] - m[0][0] * s[0][0] - m[0][1] * s[0][1],
        t[0][1] - m[1][0] * s[0][0] - m[1][1] * s[0][1],
    ];
    let ns = (s1[0].powi(2) + s1[1].powi(2) + s2[0].powi(2) + s2[1].powi(2)).sqrt();
    let ni = (inv[0][0].powi(2) + inv[0][1].powi(2) + inv[1][0].powi(2) + inv[1][1].powi(2)).sqrt();
    Some((m, off, ns * ni))
}

/// Sec. 5.4 step (6) as written: "φ_αβ = ∫_{p_α}^{p_β} ω" read as the translation vector of
/// φ_αβ = φ_β∘φ_α⁻¹ (Def. 7). `literal = false` checks the corrected sign −∫_{p_α}^{p_β} ω.
pub fn check_step6(
    k: &SimplicialSurface,
    at: &Atlas,
    tr: &[PairTranslation],
    literal: bool,
) -> CheckResult {
    let (id, name) = if literal {
        (
            "MS-5.4(6)",
            "step (6) as written: φ_αβ translates by +∫_{p_α}^{p_β} ω",
        )
    } else {
        (
            "MS-5.4(6)-corrected",
            "corrected: φ_αβ = φ_β∘φ_α⁻¹ translates by −∫_{p_α}^{p_β} ω",
        )
    };
    let mut r = CheckResult::new(id, name);
    let mut worst: f64 = 0.0;
    for p in tr {
        let (ca, cb) = (&at.charts[p.pair.0 as usize], &at.charts[p.pair.1 as usize]);
        // ∫_{p_α}^{p_β} ω along a path in U_α: φ_α(p_β), read from any face of U_α at p_β.
        let Some(int) = ca.faces.iter().find_map(|(f, t)| {
            k.face(*f)
                .iter()
                .position(|&v| v == cb.centre)
                .map(|i| t[i])
        }) else {
            continue;
        };
        r.examined += 1;
        let want = if literal { int } else { [-int[0], -int[1]] };
        let d = (p.t[0] - want[0]).hypot(p.t[1] - want[1]);
        worst = crate::report::dev_max(worst, d);
        let tol = p.tolerance.max(64.0 * f64::EPSILON * int[0].hypot(int[1]));
        if !(d <= tol) {
            r.offend(|| Witness::new(format!("charts at vertices {} and {}: φ_β − φ_α = ({:.6}, {:.6}) but ∫_{{p_α}}^{{p_β}} ω = ({:.6}, {:.6})", ca.centre, cb.centre, p.t[0], p.t[1], int[0], int[1]), json!({"alpha": p.pair.0, "beta": p.pair.1, "translation": p.t, "integral": int})));
        }
    }
    r.worst_deviation = Some(worst);
    r
}

/// Fold `new` into `acc` by SPEC ID: counts add, witnesses are kept up to [`MAX_WITNESSES`],
/// the worst deviation is the maximum, a failure anywhere fails the merged result.
pub fn merge(acc: &mut Vec<CheckResult>, new: Vec<CheckResult>) {
    for n in new {
        match acc.iter_mut().find(|a| a.id == n.id && a.name == n.name) {
            Some(a) => {
                let n_verdict = n.stored_verdict().clone();
                a.examined += n.examined;
                a.offenders += n.offenders;
                a.eval_errors += n.eval_errors;
                for w in n.witnesses {
                    if a.witnesses.len() < MAX_WITNESSES {
                        a.witnesses.push(w);
                    }
                }
                a.worst_deviation = match (a.worst_deviation, n.worst_deviation) {
                    (Some(x), Some(y)) => Some(if x.is_nan() || y.is_nan() {
                        f64::NAN
                    } else {
                        x.max(y)
                    }),
                    (x, y) => x.or(y),
                };
                a.tolerance = match (a.tolerance, n.tolerance) {
                    (Some(x), Some(y)) => Some(x.max(y)),
                    (x, y) => x.or(y),
                };
                if n_verdict.is_failure() {
                    a.adopt_verdict(Verdict::Fails);
                } else if matches!(a.stored_verdict(), Verdict::Skipped { .. })
                    && !matches!(n_verdict, Verdict::Skipped { .. })
                {
                    a.adopt_verdict(n_verdict);
                }
            }
            None => acc.push(n),
        }
    }
}

/// Def. 3.4.1 by the sampled checkers, on the neighbourhood views of `views` charts chosen
/// by the seed (all charts when there are fewer).
pub fn check_gluing_data(
    k: &SimplicialSurface,
    at: &Atlas,
    cfg: &SampleConfig,
    views: usize,
) -> Vec<CheckResult> {
    let n = at.charts.len();
    let mut chosen: Vec<u32> = (0..n as u32).collect();
    if n > views {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(cfg.seed);
        for i in 0..views {
            let j = rng.gen_range(i..n);
            chosen.swap(i, j);
        }
        chosen.truncate(views);
        chosen.sort_unstable();
    }
    let mut acc = Vec::new();
    for &a in &chosen {
        let v = AtlasView::neighbourhood(k, at, a);
        merge(&mut acc, check_all(&v, cfg));
    }
    for r in &mut acc {
        r.note = format!(
            "{} (on {} neighbourhood views of {n} charts, seed {})",
            r.note,
            chosen.len(),
            cfg.seed
        );
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::interiors_overlap;

    /// `MS-D4`'s overlap test: triangles sharing an edge or touching boxes do not overlap,
    /// crossing ones do, boxes that overlap with disjoint triangles do not, and one image
    /// inside another does, in either order.
    #[test]
    fn ms_d4_interiors_overlap_exactly() {
        let a = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        let cases = [
            ([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], false), // shares the edge
            ([[1.0, 0.0], [2.0, 0.0], [2.0, 1.0]], false), // boxes touch at x = 1
            ([[0.6, 0.6], [1.0, 0.6], [0.6, 1.0]], false), // boxes overlap, beyond the edge
            ([[0.2, 0.2], [2.0, 0.2], [0.2, 2.0]], true),  // crossing
            ([[0.1, 0.1], [0.3, 0.1], [0.1, 0.3]], true),  // inside
            ([[-1.0, -1.0], [3.0, -1.0], [-1.0, 3.0]], true), // around
        ];
        for (b, want) in cases {
            assert_eq!(interiors_overlap(&a, &b), want, "{b:?}");
            assert_eq!(interiors_overlap(&b, &a), want, "{b:?} (swapped)");
        }
    }
}
