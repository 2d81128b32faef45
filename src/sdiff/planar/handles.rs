//! Mello–Velho Sec. 6.1 (L252): the handle p(ε) on an edge ε crossed by O, "indicating the
//! point where 𝒪 should intercept the edge", realised exactly with the quadratic map X_1 of
//! the stratified scheme (one control point per edge, Sec. 3.2).
//!
//! On ε = a→b the quadratic map is x(u) = 2u(1 − u)λ + u² (fraction towards b), with
//! c_ε = (1 − λ)a + λb. 𝒪 crosses ε at u_h iff x(u_h) = u_O (the crossing of O), i.e.
//! λ = (u_O − u_h²) / (2u_h(1 − u_h)). The map is adjusted iff 0 < λ < 1, i.e.
//! 1 − √(1 − u_O) < u_h < √u_O, and then a diffeomorphism (SD-L141). Outside, x′ ≤ 0 at a
//! vertex of ε. Each handle position is decided by the exact det certificate (SD-L101(det))
//! and the exact edge monotonicity (SD-L101(edges)), not by this closed form.

use super::checks::{det_positive_exact, edges_monotone};
use super::complex::PlanarComplex;
use super::params::MapSpec;
use crate::report::{CheckResult, Verdict, Witness};
use crate::sdiff::common::params::{FamilySpec, ParamError};
use crate::sdiff::common::positivity::Budget;
use crate::sdiff::common::rational::{q, to_f64, Q};
use num_traits::{Signed, Zero};
use serde::Serialize;
use serde_json::json;
use std::collections::HashMap;
use std::path::Path;

/// One handle position and what the exact checks said.
#[derive(Debug, Clone, Serialize)]
pub struct HandleStep {
    /// u_h, exact.
    pub u: String,
    /// u_h as f64.
    pub u_f64: f64,
    /// λ, exact.
    pub lambda: String,
    /// det DX > 0 on every closed triangle and X monotone on every edge (exact).
    pub diffeomorphism: bool,
    /// The first witness when not.
    pub witness: Option<String>,
    /// Undecided within the budget.
    pub unresolved: bool,
}

/// The sweep of a handle along one edge.
#[derive(Debug, Clone, Serialize)]
pub struct HandleSweep {
    /// The edge (global ids).
    pub edge: [u32; 2],
    /// u_O, the crossing of the linear isocurve, exact.
    pub u_linear: String,
    /// The predicted interval (1 − √(1 − u_O), √u_O), f64.
    pub predicted: [f64; 2],
    /// The positions examined.
    pub steps: Vec<HandleStep>,
}

/// Errors of a handle sweep.
#[derive(Debug, thiserror::Error)]
pub enum HandleError {
    /// The edge is not an edge of K or O does not cross it.
    #[error("edge ({0}, {1}) is not an edge of K crossed by O")]
    NotCrossed(u32, u32),
    /// Building the map failed.
    #[error(transparent)]
    Param(#[from] ParamError),
}

/// λ placing 𝒪's crossing of the edge at u_h (u_h in (0, 1)).
pub fn lambda_for(u_linear: &Q, u_h: &Q) -> Q {
    (u_linear - u_h * u_h) / (q(2) * u_h * (q(1) - u_h))
}

/// The quadratic spec with the given edge control points (by sorted global pair, λ from the
/// smaller id).
pub fn quadratic_spec(k: &PlanarComplex, lambdas: &HashMap<(u32, u32), Q>) -> MapSpec {
    let control = lambdas
        .iter()
        .map(|(&(a, b), l)| {
            let (pa, pb) = (&k.points[a as usize], &k.points[b as usize]);
            let p = [
                &pa[0] + l * (&pb[0] - &pa[0]),
                &pa[1] + l * (&pb[1] - &pa[1]),
            ];
            ((None, vec![a, b]), p)
        })
        .collect();
    MapSpec {
        family: FamilySpec::Polynomial,
        degree: 2,
        control,
        weights: HashMap::new(),
        g: HashMap::new(),
        iso: None,
    }
}

/// Sweeps the handle of edge (a, b) over u_h = i/steps, i = 1..steps − 1, for vertex values
/// `fv` and level `c`.
pub fn sweep(
    k: &PlanarComplex,
    fv: &[Q],
    c: &Q,
    (a, b): (u32, u32),
    steps: usize,
    budget: Budget,
) -> Result<HandleSweep, HandleError> {
    let (a, b) = (a.min(b), a.max(b));
    let is_edge = k.triangles.iter().any(|t| t.contains(&a) && t.contains(&b));
    let (Some(fa), Some(fb)) = (fv.get(a as usize), fv.get(b as usize)) else {
        return Err(HandleError::NotCrossed(a, b));
    };
    let (fa, fb) = (fa - c, fb - c);
    if !is_edge || fa.is_positive() == fb.is_positive() || fa.is_zero() || fb.is_zero() {
        return Err(HandleError::NotCrossed(a, b));
    }
    let u_o = -&fa / (&fb - &fa);
    let uo = to_f64(&u_o);
    let mut out = HandleSweep {
        edge: [a, b],
        u_linear: u_o.to_string(),
        predicted: [1.0 - (1.0 - uo).sqrt(), uo.sqrt()],
        steps: Vec::new(),
    };
    let path = Path::new("(handle sweep)");
    for i in 1..steps {
        let u_h = Q::new((i as i64).into(), (steps as i64).into());
        let l = lambda_for(&u_o, &u_h);
        let spec = quadratic_spec(k, &HashMap::from([((a, b), l.clone())]));
        let cm = spec.build(k, path)?;
        let (det, _) = det_positive_exact(&cm, budget);
        let edges = edges_monotone(k, &cm, budget);
        let failed = det.failed() || edges.failed();
        let witness = det
            .witnesses
            .first()
            .or(edges.witnesses.first())
            .map(|w| w.text.clone());
        out.steps.push(HandleStep {
            u_f64: to_f64(&u_h),
            u: u_h.to_string(),
            lambda: l.to_string(),
            diffeomorphism: !failed && !matches!(det.verdict(), Verdict::Skipped { .. }),
            witness,
            unresolved: !failed && matches!(det.verdict(), Verdict::Skipped { .. }),
        });
    }
    Ok(out)
}

/// `SD-6.1(handle)`: as written, every handle position on the open edge is realised by a
/// diffeomorphism of the family; `[restricted]`: exactly the positions inside the predicted
/// interval are, and every position outside is refuted.
pub fn judge(s: &HandleSweep) -> [CheckResult; 2] {
    let mut w = CheckResult::new(
        "SD-6.1(handle)",
        "Sec. 6.1: every handle position on ε is met by a diffeomorphism X_1 (exact)",
    );
    let mut r = CheckResult::new(
        "SD-6.1(handle)[restricted]",
        "the handle is met by a diffeomorphism X_1 iff 1 − √(1 − u_O) < u_h < √u_O",
    );
    let mut inside = [f64::INFINITY, f64::NEG_INFINITY];
    for st in &s.steps {
        w.examined += 1;
        r.examined += 1;
        let predicted = st.u_f64 > s.predicted[0] && st.u_f64 < s.predicted[1];
        if st.diffeomorphism {
            inside = [inside[0].min(st.u_f64), inside[1].max(st.u_f64)];
        } else {
            let (u, l, wt) = (st.u.clone(), st.lambda.clone(), st.witness.clone());
            w.offend(|| {
                Witness::new(
                    format!(
                        "edge {:?}: handle u_h = {u} needs λ = {l}: {}",
                        s.edge,
                        wt.clone().unwrap_or_default()
                    ),
                    json!({"edge": s.edge, "u": u, "lambda": l, "witness": wt}),
                )
            });
        }
        if st.diffeomorphism != predicted && !st.unresolved {
            let (u, d) = (st.u.clone(), st.diffeomorphism);
            r.offend(|| {
                Witness::new(
                    format!(
                        "edge {:?}: u_h = {u}: diffeomorphism = {d}, predicted {predicted}",
                        s.edge
                    ),
                    json!({"edge": s.edge, "u": u}),
                )
            });
        }
    }
    let note = format!(
        "u_O = {}; certified handle positions span [{:.6}, {:.6}], predicted ({:.6}, {:.6})",
        s.u_linear, inside[0], inside[1], s.predicted[0], s.predicted[1]
    );
    w.note = note.clone();
    r.note = note;
    if r.examined == 0 {
        for x in [&mut w, &mut r] {
            x.skip("no handle position examined");
        }
    }
    [w, r]
}
