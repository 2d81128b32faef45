//! Def. 13 and Sec. 5.6 on a mesh: (1) the control points whose knots lie in a chart form a
//! spline patch there; (2) F_α = F_β∘φ_αβ on overlaps, measured at seeded points with a
//! tolerance derived from f64 rounding; and F defined on all of M ∖ Z with Σ N = 1.

use super::atlas::Atlas;
use super::mesh_spline::{face_ring, Evaluation, MeshPoint, MeshSpline, SplineError};
use crate::mesh::{FaceId, SimplicialSurface};
use crate::numeric::predicates::orient2_det;
use crate::report::{Check, CheckResult, OnError, Witness};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde_json::json;

/// Does chart α hold every knot of every face J of the 1-ring of F?
fn patch_complete(
    k: &SimplicialSurface,
    at: &Atlas,
    sp: &MeshSpline,
    f: FaceId,
    alpha: u32,
) -> Result<(), SplineError> {
    for j in face_ring(k, f) {
        sp.corner_clouds_in(k, at, j, alpha)?;
    }
    Ok(())
}

/// Def. 13(1) as written: for every chart, the control points whose knots lie in U_α form a
/// spline patch on all of φ_α(U_α) — every basis function non-zero on U_α (those of the
/// 1-ring of each face of U_α, Sec. 3.1.3(1)) has its knots in U_α. Corrected: on the faces
/// around p_α (the star of the chart's centre), which is what Sec. 5.6 uses. Exact
/// (combinatorial: a knot lies in U_α iff its face does).
pub fn check_d13_1(k: &SimplicialSurface, at: &Atlas, sp: &MeshSpline) -> Vec<CheckResult> {
    let generic = check_knots_generic(k, sp);
    let mut lit = CheckResult::new(
        "MS-D13(1)-mesh",
        "Def. 13(1) on M: the control points with knots in U_α form a spline patch on U_α",
    );
    let mut cor = CheckResult::new(
        "MS-D13(1)-mesh-corrected",
        "Def. 13(1) on the star of p_α: every knot its faces need lies in U_α",
    );
    let mut full = 0usize;
    for (a, ch) in at.charts.iter().enumerate() {
        let a = a as u32;
        lit.examined += 1;
        let bad = ch
            .faces
            .keys()
            .find_map(|&f| patch_complete(k, at, sp, f, a).err().map(|e| (f, e)));
        match bad {
            Some((f, e)) => lit.offend(|| {
                Witness::new(
                    format!("chart at vertex {}: on face {f} of U_α: {e}", ch.centre),
                    json!({"chart": a, "face": f.0}),
                )
            }),
            None => full += 1,
        }
        for &f in k.faces_around(ch.centre) {
            if !ch.faces.contains_key(&f) {
                continue;
            }
            cor.examined += 1;
            if let Err(e) = patch_complete(k, at, sp, f, a) {
                cor.offend(|| {
                    Witness::new(
                        format!("chart at vertex {}: face {f} of the star: {e}", ch.centre),
                        json!({"chart": a, "face": f.0}),
                    )
                });
            }
        }
    }
    let n = at.charts.len();
    vec![
        generic,
        lit.with_note(format!(
            "{full} of {n} charts (ring {}) hold every knot of their faces' 1-rings",
            at.k_ring
        )),
        skipped_if_empty(cor.with_note(format!("ring {} charts, faces around p_α", at.k_ring))),
    ]
}

fn skipped_if_empty(mut r: CheckResult) -> CheckResult {
    if r.examined == 0 && !r.failed() {
        r.skip("nothing examined");
    }
    r
}

/// Sec. 5.5 / Sec. 3.1.2: the knots of every control point, in its recorded chart, are in
/// general position — no three knots of any V_β^I collinear — and the image of I and every
/// Δ_β^I are positively oriented (the DMS conditions; exact orientation on the stored f64
/// images); faces without a recorded chart are counted, not judged.
pub fn check_knots_generic(k: &SimplicialSurface, sp: &MeshSpline) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-5.5",
        "knots of every V_β^I in general position, I and Δ_β^I positively oriented, in the recorded chart (exact)",
    );
    let betas = super::polar::multi_indices(sp.k);
    let mut unrecorded = 0usize;
    for f in k.faces() {
        let Some(rec) = &sp.recorded[f.idx()] else {
            unrecorded += 1;
            continue;
        };
        for b in &betas {
            let v: Vec<[f64; 2]> = (0..3)
                .flat_map(|c| rec[c].iter().take(b[c] + 1).copied())
                .collect();
            r.examined += 1;
            let mut bad = None;
            for x in 0..v.len() {
                for y in x + 1..v.len() {
                    for z in y + 1..v.len() {
                        if bad.is_none() && orient2_det(v[x], v[y], v[z]) == 0.0 {
                            bad = Some([x, y, z]);
                        }
                    }
                }
            }
            // DMS need Δ_β^I = [t_{0,β0}, t_{1,β1}, t_{2,β2}] proper, oriented like I.
            let d = [b[0], b[0] + b[1] + 1, b[0] + b[1] + b[2] + 2];
            let oi = orient2_det(rec[0][0], rec[1][0], rec[2][0]);
            let od = orient2_det(v[d[0]], v[d[1]], v[d[2]]);
            if bad.is_none() && !(oi > 0.0 && od > 0.0) {
                r.offend(|| {
                    Witness::new(
                        format!("face {f}, β = {b:?}: in chart {:?}, image of I has orientation {oi:.3e} and Δ_β {od:.3e} (DMS need both > 0)", sp.home[f.idx()]),
                        json!({"face": f.0, "beta": b, "kind": "orientation"}),
                    )
                });
            }
            if let Some(t) = bad {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "face {f}, β = {b:?}: knots {t:?} of V_β are collinear in chart {:?}",
                            sp.home[f.idx()]
                        ),
                        json!({"face": f.0, "beta": b, "knots": t}),
                    )
                });
            }
        }
    }
    skipped_if_empty(r.with_note(format!(
        "{unrecorded} faces without a recorded chart (Sec. 5.5 (1) impossible, see MS-5.6)"
    )))
}

/// A seeded point of face f (dyadic barycentrics, exact in f64).
fn sample_point(f: FaceId, rng: &mut ChaCha8Rng) -> MeshPoint {
    let (a, b) = (rng.gen_range(1..255u32), rng.gen_range(1..255u32));
    let (a, b) = if a + b >= 256 {
        (256 - a, 256 - b)
    } else {
        (a, b)
    };
    let (a, b) = (f64::from(a) / 256.0, f64::from(b) / 256.0);
    MeshPoint {
        face: f,
        bary: [1.0 - a - b, a, b],
    }
}

/// Def. 13(2): F_α = F_β∘φ_αβ. At seeded points p of seeded faces, F is evaluated in every
/// chart centred at a corner of p's face that can evaluate it (Sec. 5.6) and the values
/// are compared. Tolerance (first order in the chart rounding): the charts agree with a
/// translation up to δ = 64·ε·Σ|ω| along their developing paths (`MS-T4(atlas)`); moving
/// every knot and u by δ moves each barycentric coordinate by ≤ 2δ/h (h the least height of
/// a knot triangle) and N by ≤ (k+1)·2δ/h per recurrence level, so
/// tol = 4(k+1)²·δ/h·Σ|c| + 64·ε·Σ|c|. Also Sec. 5.6 on M ∖ Z (`MS-5.6`): every face not
/// removed can be evaluated, and Σ N = 1 to 64·ε·(terms).
pub fn check_d13_2(
    k: &SimplicialSurface,
    at: &Atlas,
    sp: &MeshSpline,
    seed: u64,
    faces: usize,
) -> Vec<CheckResult> {
    check_d13_2_with(k, at, sp, seed, faces, &|p, g| sp.evaluate(k, at, p, g))
}

/// F(p) in chart γ, as [`check_d13_2_with`] evaluates it: [`MeshSpline::evaluate`], or a
/// planted model (the seam of the planted-fault tests, SPEC `X-planted-msplines`).
pub type Evaluator<'a> = dyn Fn(&MeshPoint, u32) -> Result<Evaluation, SplineError> + 'a;

/// [`check_d13_2`] with the evaluation of F in a chart given by `eval`. Every finding goes
/// through the harness (`report::harness`): a non-finite deviation or Σ N is an offence; F
/// undefined on a face of M ∖ Z is an offence of `MS-5.6` (its evaluation errors counted);
/// a chart at a corner that cannot evaluate F while another can is a counted skipped
/// comparison of `MS-D13(2)-mesh` (that chart does not hold the knots, Sec. 5.6); nothing
/// examined is skipped.
pub fn check_d13_2_with(
    k: &SimplicialSurface,
    at: &Atlas,
    sp: &MeshSpline,
    seed: u64,
    faces: usize,
    eval: &Evaluator,
) -> Vec<CheckResult> {
    let mut r = Check::new(
        "MS-D13(2)-mesh",
        "Def. 13(2) on M: F_α = F_β∘φ_αβ at seeded points (charts at the face's corners)",
    )
    .with_seed(seed);
    let mut ev56 = Check::new(
        "MS-5.6",
        "Sec. 5.6: F evaluable on every face of M ∖ Z (a chart at a corner holds its knots)",
    )
    .with_seed(seed);
    let mut ls = Check::new(
        "MS-3.1.3(1)-mesh",
        "local support on M: basis functions of faces outside the 1-ring of F vanish on F",
    )
    .with_seed(seed);
    let mut pu = Check::new(
        "MS-DMS-PU-mesh",
        "DMS partition of unity on M: Σ_J Σ_β N_β^J = 1 in every evaluating chart",
    )
    .with_seed(seed);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let nf = k.num_faces();
    let eps = f64::EPSILON;
    let (mut undefined, mut removed) = (0usize, 0usize);
    for _ in 0..faces {
        if nf == 0 {
            break;
        }
        let f = FaceId(rng.gen_range(0..nf) as u32);
        let p = sample_point(f, &mut rng);
        // Z's stars are not in M ∖ Z: outside every statement here (counted in the note).
        if at.removed[f.idx()] {
            removed += 1;
            continue;
        }
        let mut vals = Vec::new();
        let mut errs = Vec::new();
        for v in k.face(f) {
            let Some(&g) = sp.chart_of_vertex.get(&v) else {
                continue;
            };
            match eval(&p, g) {
                Ok(e) => vals.push((g, e)),
                Err(e) => errs.push((g, e)),
            }
        }
        if vals.is_empty() {
            undefined += 1;
            let witness = |why: &str| {
                Witness::new(
                    format!("face {f} (not removed): F undefined at {:?}: {why}", p.bary),
                    json!({"face": f.0, "kind": "undefined"}),
                )
            };
            match errs.first() {
                // Sec. 5.6 claims F defined here: the error is an offence, every one counted.
                Some((_, e)) => {
                    ev56.error(OnError::Offence, e, || witness(&e.to_string()));
                    ev56.eval_errors += errs.len() as u64 - 1;
                }
                None => ev56.holds(false, || witness("no chart at its corners")),
            }
            continue;
        }
        ev56.holds(true, || unreachable_witness(f));
        for (g, e) in &errs {
            r.error(OnError::Skip, format!("face {f}, chart {g}: {e}"), || {
                unreachable_witness(f)
            });
        }
        for (g, e) in &vals {
            match sp.outside_ring_mass(k, at, &p, *g) {
                Ok((mass, n)) => {
                    ls.examined(n as u64);
                    if !(mass == 0.0) {
                        ls.offend(|| {
                            Witness::new(
                                format!("face {f} at {:?}, chart {g}: Σ|N_β^J| = {mass:.3e} over faces J outside the 1-ring", p.bary),
                                json!({"face": f.0, "chart": g, "mass": mass}),
                            )
                        });
                    }
                }
                Err(err) => ls.error(OnError::Offence, &err, || {
                    Witness::new(format!("face {f}, chart {g}: {err}"), json!({"face": f.0}))
                }),
            }
            // The knot triangles' least height h against the chart radius R is the
            // conditioning of the barycentric coordinates of the recurrence (k levels).
            let pu_tol = 64.0 * eps * (1.0 + e.radius / e.min_height).powi(sp.k as i32);
            let d = (e.sum_n - 1.0).abs();
            pu.deviation_within(d, pu_tol, || {
                Witness::new(
                    format!(
                        "face {f}, chart {g}: Σ N = {} (|Σ N − 1| > {pu_tol:.1e})",
                        e.sum_n
                    ),
                    json!({"face": f.0, "chart": g, "kind": "partition"}),
                )
            });
        }
        let (g0, e0) = &vals[0];
        for (g1, e1) in &vals[1..] {
            let path = |g: u32| {
                at.charts[g as usize]
                    .path_magnitude
                    .values()
                    .copied()
                    .fold(0.0f64, crate::report::dev_max)
            };
            let delta =
                64.0 * eps * (path(*g0) + path(*g1) + crate::report::dev_max(e0.radius, e1.radius));
            let h = e0.min_height.min(e1.min_height);
            let mass = crate::report::dev_max(e0.control_mass, e1.control_mass);
            let kk = (sp.k + 1) as f64;
            let tol = 4.0 * kk * kk * delta / h * mass + 64.0 * eps * mass;
            let d = (0..3)
                .map(|a| (e0.value[a] - e1.value[a]).abs())
                .fold(0.0f64, crate::report::dev_max);
            r.deviation_within(d, tol, || {
                Witness::new(
                    format!(
                        "face {f} at {:?}: F in chart {g0} = {:?}, in chart {g1} = {:?}, differ by {d:.3e} > {tol:.3e}",
                        p.bary, e0.value, e1.value
                    ),
                    json!({"face": f.0, "charts": [g0, g1], "deviation": d, "tol": tol}),
                )
            });
        }
    }
    vec![
        r.finish(format!(
            "{faces} seeded faces (seed {seed}); tolerance 4(k+1)²·δ/h·Σ|c| + 64ε·Σ|c|, δ = 64ε·(Σ|ω| + radius); largest shown"
        )),
        ev56.finish(format!(
            "{undefined} sampled faces of M ∖ Z where no chart evaluates F; {removed} sampled faces in the removed stars of Z (not in M ∖ Z)"
        )),
        ls.finish(
            "exact zero required (the base case of a basis function outside its knots' hull is 0)",
        ),
        pu.finish(
            "tolerance 64ε·(1 + R/h)^k (R chart radius, h least knot-triangle height), largest shown",
        ),
    ]
}

/// The witness of a passing sample or a skipped comparison (never listed: the harness lists
/// witnesses of offences only).
fn unreachable_witness(f: FaceId) -> Witness {
    Witness::new(format!("face {f}"), json!({"face": f.0}))
}
