//! The optimiser of Mello–Velho L268, min_β Σ_σ err(σ, β) with err of L262, over *all* free
//! control points of the quadratic map X_1 of the stratified scheme (Sec. 3.2, L148): one
//! control point per edge ε = a→b of K, c_ε = (1 − λ_ε)a + λ_ε b, so β = (λ_ε)_ε.
//!
//! The paper gives no method ("some iterations of this optimization program", L270). Ours is
//! deterministic coordinate descent: sweep the edges in index order; on each, evaluate a grid
//! of `grid + 1` rational λ over \[lo, hi\] and refine around the best by `refine` halvings of
//! the step (moving only on a strict decrease, so ties keep the current value); stop after a
//! sweep that lowers the objective by less than `tol` (relative) or after `sweeps`. Every λ is
//! rational, so the result's det DX > 0 is decided exactly (`SD-L101(det)`).
//!
//! \[lo, hi\] ⊂ (0, 1) is the adjusted range (`SD-L268(restricted)`: a diffeomorphism by
//! `SD-L141`); a wider box is the unconstrained reading of L268 (`SD-L268`).

use super::complex::PlanarComplex;
use super::handles::quadratic_spec;
use super::objectives::{handle_errors, total, Handle, HandleErrorKind};
use crate::report::{CheckResult, Verdict, Witness};
use crate::sdiff::common::params::ParamError;
use crate::sdiff::common::rational::{qr, to_f64, Q};
use serde::Serialize;
use serde_json::json;
use std::collections::{BTreeSet, HashMap};
use std::path::Path;

/// Settings of [`optimise`].
#[derive(Debug, Clone)]
pub struct OptimiseOptions {
    /// α of L262 (weight of the normal terms).
    pub alpha: f64,
    /// Lower end of every λ_ε.
    pub lo: Q,
    /// Upper end of every λ_ε.
    pub hi: Q,
    /// Grid intervals of each one-edge search.
    pub grid: usize,
    /// Halvings of the step around the grid's best.
    pub refine: usize,
    /// Maximal sweeps over the edges.
    pub sweeps: usize,
    /// Relative decrease below which a sweep ends the descent.
    pub tol: f64,
}

impl Default for OptimiseOptions {
    fn default() -> Self {
        OptimiseOptions {
            alpha: 0.01,
            lo: qr(1, 64),
            hi: qr(63, 64),
            grid: 16,
            refine: 8,
            sweeps: 12,
            tol: 1e-9,
        }
    }
}

/// Why the optimiser cannot run.
#[derive(Debug, thiserror::Error)]
pub enum OptimiseError {
    /// lo ≥ hi, or zero grid intervals.
    #[error("empty search range [{lo}, {hi}] with {grid} grid intervals")]
    EmptyRange {
        /// lo.
        lo: String,
        /// hi.
        hi: String,
        /// grid.
        grid: usize,
    },
    /// L262 undefined at some β (names the edge).
    #[error("at λ = {lambdas}: {source}")]
    Handle {
        /// The β where it happened.
        lambdas: String,
        /// The reason.
        source: HandleErrorKind,
    },
    /// Building X_1 failed.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The objective is NaN at some β.
    #[error("objective is NaN at λ = {0}")]
    NaN(String),
}

/// The result of [`optimise`].
#[derive(Debug, Clone, Serialize)]
pub struct Optimum {
    /// λ_ε per edge (a < b), exact.
    pub lambdas: Vec<([u32; 2], String)>,
    /// Σ_σ err(σ, β) at the result.
    pub objective: f64,
    /// The objective at the start (for [`optimise`]: every λ = 1/2, X = id).
    pub start: f64,
    /// The objective after each sweep.
    pub history: Vec<f64>,
    /// Objective evaluations.
    pub evaluations: usize,
    /// Edges whose λ ended at lo or hi.
    pub at_bound: Vec<[u32; 2]>,
}

/// λ_ε per edge (a < b): β of X_1.
pub(crate) type Lambdas = HashMap<(u32, u32), Q>;

/// The edges of K (a < b), sorted.
pub fn edges(k: &PlanarComplex) -> Vec<(u32, u32)> {
    let mut s = BTreeSet::new();
    for t in &k.triangles {
        for (i, j) in [(0, 1), (1, 2), (2, 0)] {
            s.insert((t[i].min(t[j]), t[i].max(t[j])));
        }
    }
    s.into_iter().collect()
}

fn describe(l: &HashMap<(u32, u32), Q>) -> String {
    let mut v: Vec<_> = l.iter().map(|(e, x)| format!("{e:?}: {x}")).collect();
    v.sort();
    v.join(", ")
}

/// Σ_σ err(σ, β) of L268 for X_1 with control points `lambdas`.
pub fn objective(
    k: &PlanarComplex,
    fv: &[Q],
    handles: &[Handle],
    lambdas: &HashMap<(u32, u32), Q>,
    alpha: f64,
) -> Result<f64, OptimiseError> {
    let cm = quadratic_spec(k, lambdas).build(k, Path::new("(L268 optimiser)"))?;
    let cells = handle_errors(k, &cm, fv, handles).map_err(|source| OptimiseError::Handle {
        lambdas: describe(lambdas),
        source,
    })?;
    let v = total(&cells, alpha);
    if v.is_nan() {
        return Err(OptimiseError::NaN(describe(lambdas)));
    }
    Ok(v)
}

/// Coordinate descent of L268 over every edge's λ (module doc).
pub fn optimise(
    k: &PlanarComplex,
    fv: &[Q],
    handles: &[Handle],
    o: &OptimiseOptions,
) -> Result<(Optimum, Lambdas), OptimiseError> {
    let es = edges(k);
    let start = es.iter().map(|&e| (e, qr(1, 2))).collect();
    optimise_edges(k, fv, handles, o, &es, start)
}

/// The same descent over the λ of the edges `free` only, from `start` (every edge of K needs a
/// value; a missing one is 1/2): the local optimiser of L314 (`SD-L314`).
pub(crate) fn optimise_edges(
    k: &PlanarComplex,
    fv: &[Q],
    handles: &[Handle],
    o: &OptimiseOptions,
    free: &[(u32, u32)],
    start: Lambdas,
) -> Result<(Optimum, Lambdas), OptimiseError> {
    if o.lo >= o.hi || o.grid == 0 {
        return Err(OptimiseError::EmptyRange {
            lo: o.lo.to_string(),
            hi: o.hi.to_string(),
            grid: o.grid,
        });
    }
    let mut lam = start;
    for e in edges(k) {
        lam.entry(e).or_insert_with(|| qr(1, 2));
    }
    let es: Vec<_> = free
        .iter()
        .copied()
        .filter(|e| lam.contains_key(e))
        .collect();
    // A free λ starts inside the search box (nearest end), so the result lies in it.
    for e in &es {
        if let Some(x) = lam.get_mut(e) {
            if *x < o.lo {
                *x = o.lo.clone();
            } else if *x > o.hi {
                *x = o.hi.clone();
            }
        }
    }
    let mut evaluations = 0usize;
    let mut eval = |l: &HashMap<(u32, u32), Q>| -> Result<f64, OptimiseError> {
        evaluations += 1;
        objective(k, fv, handles, l, o.alpha)
    };
    let start = eval(&lam)?;
    let mut best = start;
    let mut history = Vec::new();
    let step0 = (&o.hi - &o.lo) / Q::from_integer((o.grid as i64).into());
    for _ in 0..o.sweeps {
        let before = best;
        for &e in &es {
            let mut try_at = |x: Q, best: &mut f64, lam: &mut HashMap<(u32, u32), Q>| {
                if x < o.lo || x > o.hi {
                    return Ok::<(), OptimiseError>(());
                }
                let mut cand = lam.clone();
                cand.insert(e, x.clone());
                let v = eval(&cand)?;
                if v < *best {
                    *best = v;
                    lam.insert(e, x);
                }
                Ok(())
            };
            for j in 0..=o.grid {
                let x = &o.lo + &step0 * Q::from_integer((j as i64).into());
                try_at(x, &mut best, &mut lam)?;
            }
            let mut h = step0.clone();
            for _ in 0..o.refine {
                h *= qr(1, 2);
                let c = lam[&e].clone();
                try_at(&c - &h, &mut best, &mut lam)?;
                let c = lam[&e].clone();
                try_at(&c + &h, &mut best, &mut lam)?;
            }
        }
        history.push(best);
        if before - best <= o.tol * before.abs().max(f64::MIN_POSITIVE) {
            break;
        }
    }
    let at_bound = es
        .iter()
        .filter(|e| lam[e] == o.lo || lam[e] == o.hi)
        .map(|&(a, b)| [a, b])
        .collect();
    let opt = Optimum {
        lambdas: es
            .iter()
            .map(|&(a, b)| ([a, b], lam[&(a, b)].to_string()))
            .collect(),
        objective: best,
        start,
        history,
        evaluations,
        at_bound,
    };
    Ok((opt, lam))
}

/// λ as f64 per edge (for reports).
pub fn lambdas_f64(l: &HashMap<(u32, u32), Q>) -> Vec<([u32; 2], f64)> {
    let mut v: Vec<_> = l.iter().map(|(&(a, b), x)| ([a, b], to_f64(x))).collect();
    v.sort_by_key(|x| x.0);
    v
}

/// `SD-L268(full)` / `SD-L268(full, restricted)`: the optimiser's result is a diffeomorphism
/// (the purpose of β, L256). An offence is a result whose det DX is refuted exactly (`det`, from
/// `checks::det_positive_exact`); an unresolved det is skipped, never a pass.
pub fn judge(id: &str, opt: &Optimum, det: &CheckResult, alpha: f64) -> CheckResult {
    let mut r = CheckResult::new(
        id,
        "L268: the minimiser over all control points of X_1 is a diffeomorphism",
    );
    r.examined = 1;
    r.note = format!(
        "α = {alpha}; objective {:.6e} (X = id: {:.6e}) after {} sweeps, {} evaluations; λ at a bound on {:?}; λ = {:?}",
        opt.objective,
        opt.start,
        opt.history.len(),
        opt.evaluations,
        opt.at_bound,
        opt.lambdas
    );
    if det.failed() {
        let wt = det
            .witnesses
            .first()
            .map(|w| w.text.clone())
            .unwrap_or_default();
        let o = opt.objective;
        let l = opt.lambdas.clone();
        r.offend(|| {
            Witness::new(
                format!("the minimiser (objective {o:.6e}) is not a diffeomorphism: {wt}"),
                json!({"lambdas": l, "objective": o, "det": wt}),
            )
        });
    } else if !matches!(det.verdict(), Verdict::Holds) {
        r.skip("det DX of the minimiser unresolved within the budget");
    }
    r
}
