//! Mello–Velho Sec. 6.2, L312–L316: after each SUBDIVIDE(K_i, σ_i) the optimiser runs over
//! st(v_k, K_{i+1}) of the new vertices, recomputing X "only in the regions of the mesh that
//! were modified by the subdivision" (`SD-L314`).
//!
//! Departures (SPEC `SD-L314`): L302's err fails as written (`SD-L302`: it measures X(θ), not
//! 𝒪 = X⁻¹(θ)), so the objective is L262's with the handle of each crossed edge at the root of
//! g on it and n(ε) a rational unit vector within 2⁻²⁰ of ∇g/‖∇g‖ there (α weights the normal
//! terms); the free β are the control points of the crossed edges incident to a new vertex
//! (those edges lie only in triangles the call created, so no other triangle's X changes);
//! the descent is `optimise::optimise_edges`. Each result is accepted only once det DX > 0 is
//! certified exactly on every created triangle (`checks::det_positive_exact`); a fold or an
//! unresolved det is reported and the edges keep λ = 1/2 (X = id along them).

use super::checks::det_positive_exact;
use super::complex::{validate, PlanarComplex};
use super::handles::quadratic_spec;
use super::implicit::Implicit;
use super::objectives::Handle;
use super::optimise::{edges, optimise_edges, Lambdas, OptimiseOptions};
use super::refine::Mesh2;
use super::subdivide::SubdivideStep;
use crate::mesh::raw::RawMesh;
use crate::report::{CheckResult, Verdict, Witness};
use crate::sdiff::common::positivity::Budget;
use crate::sdiff::common::rational::{from_f64, q, Q};
use num_traits::{Signed, Zero};
use serde::Serialize;
use serde_json::json;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// What happened to one local optimisation.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub enum Outcome {
    /// det DX > 0 certified on every created triangle; λ taken over.
    Accepted,
    /// Nothing to optimise: no crossed edge at a new vertex.
    NoFreeEdge,
    /// det DX refuted exactly on a created triangle: the result is rejected.
    Folded(String),
    /// det DX unresolved within the budget: rejected.
    Unresolved,
    /// The objective or the star could not be evaluated: rejected.
    Error(String),
}

/// One run of the optimiser of L314 after a SUBDIVIDE call.
#[derive(Debug, Clone, Serialize)]
pub struct LocalStep {
    /// Index of the SUBDIVIDE call.
    pub call: usize,
    /// v_1..v_k.
    pub new_vertices: Vec<u32>,
    /// Triangles of ∪_k st(v_k, K_{i+1}).
    pub triangles: usize,
    /// Free edges (global ids).
    pub free: Vec<[u32; 2]>,
    /// Objective at the start and at the result.
    pub objective: [f64; 2],
    /// Objective evaluations.
    pub evaluations: usize,
    /// The outcome.
    pub outcome: Outcome,
}

/// The state of the optimiser across the refinement.
#[derive(Debug, Clone, Default)]
pub struct LocalRun {
    /// Accepted λ per edge (global ids, a < b).
    pub lambdas: Lambdas,
    /// Every local optimisation.
    pub steps: Vec<LocalStep>,
}

/// The root of g on a→b as u ∈ (0, 1), exact (60 f64 bisections, then the double read
/// exactly); `None` unless g changes sign on the edge.
pub(crate) fn root_on_edge(g: &Implicit, pa: [f64; 2], pb: [f64; 2]) -> Option<Q> {
    let at = |u: f64| g.eval_f64(pa[0] + u * (pb[0] - pa[0]), pa[1] + u * (pb[1] - pa[1]));
    let neg = at(0.0) < 0.0;
    if neg == (at(1.0) < 0.0) {
        return None;
    }
    let (mut l, mut h) = (0.0f64, 1.0f64);
    for _ in 0..60 {
        let m = 0.5 * (l + h);
        if (at(m) < 0.0) == neg {
            l = m;
        } else {
            h = m;
        }
    }
    let u = from_f64(0.5 * (l + h))?;
    (u.is_positive() && u < q(1)).then_some(u)
}

/// A rational unit vector within about 2⁻²⁰ of v/‖v‖ (t = tan(θ/2) rounded to 2⁻²⁰, the
/// point ((1 − t²), 2t)/(1 + t²) of the unit circle); `None` for v = 0 or non-finite.
pub fn rational_unit(v: [f64; 2]) -> Option<[Q; 2]> {
    if !(v[0].is_finite() && v[1].is_finite()) || (v[0] == 0.0 && v[1] == 0.0) {
        return None;
    }
    let th = v[1].atan2(v[0]);
    // |θ| ≤ π/2 keeps |t| ≤ 1; otherwise take the opposite vector and negate.
    let (phi, sign) = if th.abs() <= std::f64::consts::FRAC_PI_2 {
        (th, 1)
    } else {
        (th - std::f64::consts::PI.copysign(th), -1)
    };
    let den: i64 = 1 << 20;
    let t = Q::new(
        (((phi / 2.0).tan() * den as f64).round() as i64).into(),
        den.into(),
    );
    let d = q(1) + &t * &t;
    let s = q(sign);
    Some([&s * (q(1) - &t * &t) / &d, &s * q(2) * &t / &d])
}

impl LocalRun {
    /// Runs the optimiser of L314 on the star of the vertices `step` inserted (module doc).
    pub(crate) fn after_subdivide(
        &mut self,
        g: &Implicit,
        mesh: &Mesh2,
        step: &SubdivideStep,
        call: usize,
        o: &OptimiseOptions,
    ) {
        let mut rec = LocalStep {
            call,
            new_vertices: step.new_vertices.clone(),
            triangles: step.created.len(),
            free: Vec::new(),
            objective: [f64::NAN; 2],
            evaluations: 0,
            outcome: Outcome::NoFreeEdge,
        };
        if let Err(e) = self.optimise_star(g, mesh, step, o, &mut rec) {
            rec.outcome = Outcome::Error(e);
        }
        self.steps.push(rec);
    }

    fn optimise_star(
        &mut self,
        g: &Implicit,
        mesh: &Mesh2,
        step: &SubdivideStep,
        o: &OptimiseOptions,
        rec: &mut LocalStep,
    ) -> Result<(), String> {
        // The star as its own complex, vertices renumbered 0..n in increasing global id.
        let mut global: Vec<u32> = step.created.iter().flat_map(|(_, t)| *t).collect();
        global.sort_unstable();
        global.dedup();
        let local: HashMap<u32, u32> = global
            .iter()
            .enumerate()
            .map(|(i, &v)| (v, i as u32))
            .collect();
        let faces = step
            .created
            .iter()
            .map(|&(id, _)| mesh.oriented(id).map(|v| local[&v]))
            .collect::<Vec<_>>();
        let raw = RawMesh {
            positions: global
                .iter()
                .map(|&v| {
                    let p = mesh.points[v as usize];
                    [p[0], p[1], 0.0]
                })
                .collect(),
            face_origin: step.created.iter().map(|&(id, _)| id as u64).collect(),
            vertex_origin: global.iter().map(|&v| v as u64).collect(),
            faces,
            ..Default::default()
        };
        let (k, _) = validate(&raw).map_err(|e| format!("the star is not a complex: {e}"))?;
        let fv: Vec<Q> = k.points.iter().map(|p| g.eval(&p[0], &p[1])).collect();
        if let Some(i) = fv.iter().position(|x| x.is_zero()) {
            return Err(format!("g = 0 at vertex {}", global[i]));
        }
        let glob = |(a, b): (u32, u32)| {
            let (x, y) = (global[a as usize], global[b as usize]);
            (x.min(y), x.max(y))
        };
        let mut handles = Vec::new();
        let mut free = Vec::new();
        let mut start = Lambdas::new();
        for e in edges(&k) {
            if let Some(l) = self.lambdas.get(&glob(e)) {
                start.insert(e, l.clone());
            }
            let (a, b) = (e.0 as usize, e.1 as usize);
            if !(&fv[a] * &fv[b]).is_negative() {
                continue;
            }
            let (pa, pb) = (k.points_f64[a], k.points_f64[b]);
            let u = root_on_edge(g, pa, pb).ok_or(format!("no root of g on {:?}", glob(e)))?;
            let uf = crate::sdiff::common::rational::to_f64(&u);
            let p = [pa[0] + uf * (pb[0] - pa[0]), pa[1] + uf * (pb[1] - pa[1])];
            let n = rational_unit(g.grad_f64(p[0], p[1]))
                .ok_or(format!("∇g = 0 at the root on {:?}", glob(e)))?;
            handles.push(Handle { edge: e, u, n });
            if step.new_vertices.contains(&global[a]) || step.new_vertices.contains(&global[b]) {
                free.push(e);
            }
        }
        rec.free = free.iter().map(|&e| glob(e)).map(|(a, b)| [a, b]).collect();
        if free.is_empty() {
            return Ok(());
        }
        let (opt, lam) =
            optimise_edges(&k, &fv, &handles, o, &free, start).map_err(|e| e.to_string())?;
        rec.objective = [opt.start, opt.objective];
        rec.evaluations = opt.evaluations;
        rec.outcome = certify(&k, &lam, &global)?;
        if rec.outcome == Outcome::Accepted {
            for e in free {
                self.lambdas.insert(glob(e), lam[&e].clone());
            }
        }
        Ok(())
    }
}

/// det DX > 0 of the star's X_1, decided exactly; the first refutation names the triangle by
/// its global vertices.
fn certify(k: &PlanarComplex, lam: &Lambdas, global: &[u32]) -> Result<Outcome, String> {
    let cm = quadratic_spec(k, lam)
        .build(k, Path::new("(L314 star)"))
        .map_err(|e| e.to_string())?;
    let (det, _) = det_positive_exact(&cm, Budget::default());
    if det.failed() {
        let w = det
            .witnesses
            .first()
            .map(|w| w.text.clone())
            .unwrap_or_default();
        let vs: Vec<[u32; 3]> = k
            .triangles
            .iter()
            .map(|t| t.map(|v| global[v as usize]))
            .collect();
        return Ok(Outcome::Folded(format!(
            "{w} (star triangles by global vertex: {vs:?})"
        )));
    }
    Ok(match det.verdict() {
        Verdict::Holds => Outcome::Accepted,
        _ => Outcome::Unresolved,
    })
}

/// `SD-L314`: every result of the local optimiser that is taken over has det DX > 0 certified
/// on the triangles it changes. A fold (or an error) is an offence with its witness — it was
/// rejected, but the optimiser produced it; zero optimisations is skipped.
pub fn judge(run: &LocalRun, o: &OptimiseOptions) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L314",
        "L312–L316: the optimiser over st(v_k, K_{i+1}) after each SUBDIVIDE yields a diffeomorphism",
    );
    let mut kinds = BTreeMap::<&str, usize>::new();
    let (mut evals, mut tris, mut free) = (0usize, 0usize, 0usize);
    let (mut start, mut end) = (0.0f64, 0.0f64);
    for s in &run.steps {
        let kind = match &s.outcome {
            Outcome::Accepted => "accepted",
            Outcome::NoFreeEdge => "no free edge",
            Outcome::Folded(_) => "folded (rejected)",
            Outcome::Unresolved => "unresolved (rejected)",
            Outcome::Error(_) => "error",
        };
        *kinds.entry(kind).or_default() += 1;
        if s.outcome == Outcome::NoFreeEdge {
            continue;
        }
        r.examined += 1;
        evals += s.evaluations;
        tris += s.triangles;
        free += s.free.len();
        if s.objective.iter().all(|x| x.is_finite()) {
            start += s.objective[0];
            end += s.objective[1];
        }
        match &s.outcome {
            Outcome::Folded(w) | Outcome::Error(w) => {
                let (c, w, f) = (s.call, w.clone(), s.free.clone());
                r.offend(|| {
                    Witness::new(
                        format!("call {c}, free edges {f:?}: {w}"),
                        json!({"call": c, "free": f, "reason": w}),
                    )
                });
            }
            Outcome::Unresolved => r.eval_errors += 1,
            _ => {}
        }
    }
    r.note = format!(
        "λ ∈ [{}, {}], grid {}, {} halvings, ≤ {} sweeps, α = {}; {} calls: {kinds:?}; {tris} star triangles, {free} free edges, {evals} evaluations; Σ objective {start:.3e} → {end:.3e}",
        o.lo, o.hi, o.grid, o.refine, o.sweeps, o.alpha, run.steps.len()
    );
    if r.examined == 0 {
        r.skip("no optimisation ran");
    } else if r.eval_errors > 0 && r.offenders == 0 {
        r.skip("det DX unresolved on some star");
    }
    r
}
