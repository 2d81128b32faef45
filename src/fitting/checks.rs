//! The checks of an adaptive fit, one per stage (SPEC rows `AF-…`). Each records through the
//! harness: examined counts, NaN as an offence, nothing examined as skipped.

use super::base::{BaseMesh, Param};
use super::fit::{rounding_bound, vertex_errors, Fit};
use super::fitted::CornerFit;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::{Mp, Scalar};
use crate::report::harness::dev_max;
use crate::report::{CheckResult, Witness};
use crate::surface::sigma_v::patch::num_control_points;
use crate::surface::sigma_v::SigmaVPps;
use serde_json::json;

/// Every base vertex is a vertex of S_T at the same position (Part II: "the vertices of S̃_T
/// are vertices of S_T").
pub fn check_base_vertices(
    k: &SimplicialSurface,
    base_k: &SimplicialSurface,
    fine_of: &[u32],
) -> CheckResult {
    let mut r = CheckResult::new("AF-simplify-vertices", "base vertices are vertices of S_T");
    for (i, &f) in fine_of.iter().enumerate() {
        r.examined += 1;
        let here = base_k.position(VertexId(i as u32));
        let fine = (f as usize) < k.vertex_slots();
        if !fine || k.position(VertexId(f)) != here {
            r.offend(|| {
                Witness::new(
                    format!("base vertex {i} (fine id {f}) at {here:?} is not that vertex of S_T"),
                    json!({"base_vertex": i, "fine": f}),
                )
            });
        }
    }
    r
}

/// χ = V − E + F.
pub fn euler(k: &SimplicialSurface) -> i64 {
    k.num_vertices() as i64 - k.num_edges() as i64 + k.num_faces() as i64
}

/// S̃_T is a simplicial surface (it was validated to exist) of the same genus as S_T.
pub fn check_genus(k: &SimplicialSurface, base_k: &SimplicialSurface) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-simplify-genus",
        "the base mesh is a simplicial surface of the same genus",
    );
    r.examined = 1;
    let (a, b) = (euler(k), euler(base_k));
    if a != b {
        r.offend(|| {
            Witness::new(
                format!("Euler characteristic {b} of the base mesh, {a} of S_T"),
                json!({"base": b, "mesh": a}),
            )
        });
    }
    r
}

/// The closed star of base vertex v laid out as T_v: the plane point of a parameter in the
/// star, or None outside it.
struct StarLayout {
    v: u32,
    ring: Vec<u32>,
    faces: Vec<u32>,
    pts: Vec<[f64; 2]>,
}

impl StarLayout {
    /// T_v of the (σ, v) construction: the ring on the regular m-gon of unit circumradius, each
    /// face of the star a sector, barycentric coordinates kept (tutorial Part IV).
    fn new(base: &BaseMesh, v: u32) -> Option<Self> {
        let (ring, faces) = base.ring(v)?;
        let m = ring.len();
        let pts = (0..m)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / m as f64;
                [a.cos(), a.sin()]
            })
            .collect();
        Some(StarLayout {
            v,
            ring,
            faces,
            pts,
        })
    }

    fn place(&self, base: &BaseMesh, x: u32) -> Option<[f64; 2]> {
        if x == self.v {
            return Some([0.0, 0.0]);
        }
        if let Some(i) = self.ring.iter().position(|&u| u == x) {
            return Some(self.pts[i]);
        }
        let Param::Face { f, b } = base.params()[x as usize] else {
            return None;
        };
        let i = self.faces.iter().position(|&g| g == f)?;
        let c = base.face(f)?;
        let m = self.ring.len();
        let at = |u: u32| -> [f64; 2] {
            if u == self.v {
                [0.0, 0.0]
            } else if u == self.ring[i] {
                self.pts[i]
            } else {
                self.pts[(i + 1) % m]
            }
        };
        let p = c.map(at);
        Some([
            b[0] * p[0][0] + b[1] * p[1][0] + b[2] * p[2][0],
            b[0] * p[0][1] + b[1] * p[1][1] + b[2] * p[2][1],
        ])
    }
}

/// The parametrization is a bijection: every triangle of S_T, mapped by its vertices'
/// parameters, is positively oriented in T_v for a base vertex v whose star holds its three
/// parameters (the chart of the (σ, v) construction). Triangles whose parameters share no base
/// star are not decided here (counted; the verdict is then restricted to the decided ones).
pub fn check_param_orientation(k: &SimplicialSurface, base: &BaseMesh) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-param-bijective(polar)",
        "every triangle of S_T maps to a positively oriented triangle of the base mesh",
    );
    let o = orientations(k, base);
    r.examined = o.decided;
    for (f, c, area, v) in o.folded {
        r.offend(|| {
            Witness::new(
                format!("triangle {f:?} {c:?} maps to a triangle of signed area {area:.3e} in T_v of base vertex {v}"),
                json!({"face": f.0, "area": area, "star": v}),
            )
        });
    }
    let undecided = o.undecided;
    if undecided > 0 {
        r.restrict(format!(
            "{undecided} triangles of S_T whose parameters share no base star are not decided"
        ));
    }
    r.note = format!("decided in T_v of a base star; {undecided} undecided");
    r
}

/// The orientations of the triangles of S_T in T_v (see [`check_param_orientation`]).
pub struct Orientations {
    /// Triangles decided.
    pub decided: u64,
    /// Triangles whose parameters share no base star.
    pub undecided: u64,
    /// The folded ones: face, vertices, signed area, the base vertex of the layout.
    pub folded: Vec<(FaceId, [u32; 3], f64, u32)>,
}

/// Decide the orientation of every triangle of S_T in T_v of a base star holding its three
/// parameters (the first such star, smallest vertex id first).
pub fn orientations(k: &SimplicialSurface, base: &BaseMesh) -> Orientations {
    let mut out = Orientations {
        decided: 0,
        undecided: 0,
        folded: Vec::new(),
    };
    let mut cache: std::collections::HashMap<u32, Option<StarLayout>> = Default::default();
    for f in k.faces() {
        let c = k.face(f).map(|v| v.0);
        // Candidate base vertices: each vertex itself if a base vertex, else its face's corners.
        let mut cands: Vec<u32> = Vec::new();
        for &x in &c {
            match base.params()[x as usize] {
                Param::Vertex => cands.push(x),
                Param::Face { f, .. } => cands.extend(base.face(f).into_iter().flatten()),
            }
        }
        cands.sort_unstable();
        cands.dedup();
        let mut decided = false;
        for v in cands {
            let lay = cache.entry(v).or_insert_with(|| StarLayout::new(base, v));
            let Some(lay) = lay.as_ref() else { continue };
            let p: Vec<[f64; 2]> = c.iter().filter_map(|&x| lay.place(base, x)).collect();
            if p.len() < 3 {
                continue;
            }
            decided = true;
            out.decided += 1;
            let o = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1])
                - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
            if !(o > 0.0) {
                out.folded.push((f, c, o, v));
            }
            break;
        }
        if !decided {
            out.undecided += 1;
        }
    }
    out
}

/// Every corner's least-squares system has full rank; the worst condition number is
/// reported (SPEC `AF-fit-rank`).
pub fn check_fit_rank(corners: &[CornerFit], degree: usize) -> CheckResult {
    let n = num_control_points(degree) as u32;
    let mut r = CheckResult::new(
        "AF-fit-rank",
        "every least-squares system of the fit has full rank",
    );
    let mut worst = 0.0f64;
    for (i, c) in corners.iter().enumerate() {
        r.examined += 1;
        worst = dev_max(worst, c.condition);
        if c.rank != n || !c.condition.is_finite() {
            r.offend(|| {
                Witness::new(
                    format!(
                        "corner {i}: rank {} of {n} unknowns, condition {:.3e}",
                        c.rank, c.condition
                    ),
                    json!({"corner": i, "rank": c.rank, "condition": c.condition}),
                )
            });
        }
    }
    r.worst_deviation = Some(worst);
    r.note = format!("largest condition number {worst:.3e}");
    r
}

/// Seeded sample size of the 256-bit cross-check of the rounding bound.
pub const MP_SAMPLES: usize = 32;

/// ‖S(p_v) − v‖ + (rounding bound) ≤ ε at every vertex v of S_T (the fitting problem's
/// statement, Part II), and the rounding bound itself checked against 256-bit evaluations at
/// a seeded sample of vertices.
pub fn check_epsilon(
    pps: &SigmaVPps,
    pos: &[[f64; 3]],
    params: &[(FaceId, [f64; 3])],
    epsilon: f64,
    seed: u64,
) -> CheckResult {
    let errors = vertex_errors(pps, pos, params);
    let bound = rounding_bound(pps);
    let mut r = CheckResult::new(
        "AF-epsilon",
        "every vertex of S_T is within epsilon of the fitted surface at its parameter",
    );
    r.tolerance = Some(epsilon);
    let mut worst = 0.0f64;
    for (i, &e) in errors.iter().enumerate() {
        r.examined += 1;
        worst = dev_max(worst, e);
        if !(e + bound <= epsilon) {
            r.offend(|| {
                Witness::new(
                    format!("vertex {i}: error {e:.3e} + rounding bound {bound:.1e} > epsilon {epsilon:.3e}"),
                    json!({"vertex": i, "error": e, "bound": bound}),
                )
            });
        }
    }
    r.worst_deviation = Some(worst);
    // The bound against 256 bits.
    let n = params.len();
    let mut broken = 0;
    let consts = pps.consts::<Mp>(256);
    // The harness's sampler (`report::harness`), so the printed seed reproduces the sample.
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed);
    for _ in 0..MP_SAMPLES.min(n) {
        let x = rand::Rng::gen_range(&mut rng, 0..n);
        let (f, b) = params[x];
        let bm = b.map(|t| Mp::from_f64(t, 256));
        let (Ok(lo), Ok(hi)) = (pps.eval_f64(f, b), pps.eval(f, &bm, &consts)) else {
            broken += 1;
            continue;
        };
        let d = crate::numeric::robust_norm(&[
            lo[0] - hi.2[0].to_f64(),
            lo[1] - hi.2[1].to_f64(),
            lo[2] - hi.2[2].to_f64(),
        ]);
        if !(d <= bound) {
            broken += 1;
            r.offend(|| {
                Witness::new(
                    format!("vertex {x}: f64 and 256-bit eval differ by {d:.3e} > rounding bound {bound:.3e}"),
                    json!({"vertex": x, "difference": d, "bound": bound}),
                )
            });
        }
    }
    r.seed = Some(seed);
    r.note = format!(
        "max error {worst:.3e}; rounding bound {bound:.1e} (operation count), checked at 256 bits on {} seeded vertices, {broken} broken",
        MP_SAMPLES.min(n)
    );
    r
}

/// Every check `ppm fit` runs on a fit of S_T = `k`: those of each stage (SPEC `AF-…`) and those
/// of the (σ, v) construction on the fitted PPS over the base mesh (SPEC `SV-…`: Def. 3.4.1,
/// condition (C), smoothness, eval).
pub fn run_all_checks(k: &SimplicialSurface, fit: &Fit, seed: u64) -> Vec<CheckResult> {
    let mut out = run_fit_checks(k, fit, seed);
    out.extend(fitted_pps_checks(&fit.surface.k, &fit.fitted.pps, seed));
    out
}

/// The failures of a fit's checks that make `ppm fit` exit 1: those that are not documented
/// errata of the (σ, v) construction, the rule of `ppm check --spec --construction sigma-v`.
pub use crate::surface::sigma_v::checks::unexpected_failures;

/// The (σ, v) checks (Def. 3.4.1, condition (C), smoothness, eval) on a fitted PPS over its
/// base mesh `base` (also what `ppm check --spec` runs on a fit file read back).
pub fn fitted_pps_checks(base: &SimplicialSurface, pps: &SigmaVPps, seed: u64) -> Vec<CheckResult> {
    use crate::surface::sigma_v::checks::{check_built, SvCheckOptions};
    let o = SvCheckOptions {
        seed,
        kappa: pps.gluing.kappa,
        patch_degree: pps.degree,
        ..SvCheckOptions::default()
    };
    check_built(base, &pps.gluing, pps, &o)
}

/// Every check of a fit's stages on S_T = `k` (SPEC `AF-…`).
pub fn run_fit_checks(k: &SimplicialSurface, fit: &Fit, seed: u64) -> Vec<CheckResult> {
    let mut out = vec![
        check_base_vertices(k, &fit.surface.k, &fit.surface.fine_of),
        check_genus(k, &fit.surface.k),
        super::embed_checks::check_embedded(fit.embedded.as_ref().err()),
    ];
    match &fit.embedded {
        // Floater's parameters: AF-param-bijective on the pieces, among the embedding's.
        Ok(e) if fit.floater_params => {
            out.extend(super::embed_checks::run(k, &fit.base, e));
        }
        // The simplification's parameters: their orientation in T_v, and the checks of the
        // embedding that exists (its failure is why it was not used).
        Ok(e) => {
            out.extend(
                super::embed_checks::run(k, &fit.base, e)
                    .into_iter()
                    .filter(|r| r.id != "AF-param-bijective"),
            );
            out.push(check_param_orientation(k, &fit.base));
        }
        Err(_) => out.push(check_param_orientation(k, &fit.base)),
    }
    // Where the fallback ran, the part of S_T it restored (SPEC `AF-unsimplify`), on the base
    // mesh it returned last.
    if let Some(b) = &fit.restore.restored {
        out.push(super::unsimplify::check_restored(k, b, fit.restore.keep()));
    }
    out.extend([
        check_fit_rank(&fit.fitted.corners, fit.fitted.pps.degree),
        check_epsilon(
            &fit.fitted.pps,
            fit.base.positions(),
            &fit.params,
            fit.epsilon,
            seed,
        ),
    ]);
    // S embedded at the sample level the fit was made with (SPEC `AF-embedded`).
    if let Some(level) = fit.embed_level {
        out.push(super::crossing::check_embedded(&fit.fitted.pps, level).result);
    }
    out
}
