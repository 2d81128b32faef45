//! X|σ⁻¹ by damped Newton in f64 (Mello–Velho Sec. 4: sampling 𝒪 needs q = X|σ⁻¹(p)), and a
//! seeded spot check of injectivity: Newton from several starts must reach one preimage.

use super::maps::SimplexMap;
use super::params::ComplexMap;
use crate::report::{Check, CheckResult, OnError, Witness};
use serde_json::json;

/// Newton's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Preimage {
    /// (s, t) of the preimage.
    pub st: [f64; 2],
    /// |X(p) − y|∞ at the answer.
    pub residual: f64,
}

/// Residual bound for a degree-n map evaluated in f64: 16 (n + 1)² ε (a sum of O(n²) terms of
/// size ≤ 1, each with a few roundings).
pub fn tolerance(m: &SimplexMap) -> f64 {
    let n = (m.degree + 1) as f64;
    16.0 * n * n * f64::EPSILON
}

/// X and its Jacobian at (s, t) of triangle `f`: [`SimplexMap::eval_f64_with_jacobian`], or a
/// planted model (the seam of the planted-fault tests, SPEC `X-planted-sdiff`). An `Err` says
/// X could not be evaluated there.
pub(crate) type MapEval<'a> =
    dyn Fn(usize, [f64; 2]) -> Result<([f64; 2], [[f64; 2]; 2]), String> + 'a;

/// Why Newton gave no preimage.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub(crate) enum NewtonError {
    /// X or its Jacobian is not finite at an iterate inside σ, where X is defined (D > 0).
    #[error("X is not finite at (s, t) = {st:?}")]
    NonFinite {
        /// The iterate.
        st: [f64; 2],
    },
    /// X could not be evaluated at an iterate inside σ.
    #[error("X could not be evaluated at (s, t) = {st:?}: {reason}")]
    Eval {
        /// The iterate.
        st: [f64; 2],
        /// The evaluator's reason.
        reason: String,
    },
    /// The Jacobian is singular at an iterate (Newton cannot step; not a fault of X by itself).
    #[error("singular Jacobian at (s, t) = {st:?}")]
    Singular {
        /// The iterate.
        st: [f64; 2],
    },
    /// Every damped step leaves the closed triangle (Newton gives up from this start).
    #[error("the Newton step leaves σ at (s, t) = {st:?}")]
    LeftTriangle {
        /// The iterate.
        st: [f64; 2],
    },
}

impl NewtonError {
    /// X itself failed (non-finite or not evaluable) at a point of σ, where it is defined: an
    /// offence of any statement about X on σ, unlike Newton giving up.
    pub(crate) fn is_evaluation_fault(&self) -> bool {
        matches!(
            self,
            NewtonError::NonFinite { .. } | NewtonError::Eval { .. }
        )
    }
}

/// Solves X(s, t) = y from `start`, staying in the closed triangle by step halving.
pub(crate) fn newton(m: &SimplexMap, y: [f64; 2], start: [f64; 2]) -> Option<Preimage> {
    newton_with(
        &|_, p| Ok(m.eval_f64_with_jacobian(p[0], p[1])),
        0,
        tolerance(m),
        y,
        start,
    )
    .ok()
}

/// [`newton`] with X of triangle `f` evaluated by `eval`, residual tolerance `tol`; says why
/// it found no preimage.
pub(crate) fn newton_with(
    eval: &MapEval,
    f: usize,
    tol: f64,
    y: [f64; 2],
    start: [f64; 2],
) -> Result<Preimage, NewtonError> {
    let inside = |p: [f64; 2]| p[0] >= -1e-12 && p[1] >= -1e-12 && p[0] + p[1] <= 1.0 + 1e-12;
    let at = |p: [f64; 2]| -> Result<([f64; 2], [[f64; 2]; 2]), NewtonError> {
        let (x, j) = eval(f, p).map_err(|reason| NewtonError::Eval { st: p, reason })?;
        if x.iter().chain(j.iter().flatten()).all(|v| v.is_finite()) {
            Ok((x, j))
        } else {
            Err(NewtonError::NonFinite { st: p })
        }
    };
    let mut p = start;
    for _ in 0..100 {
        let (x, j) = at(p)?;
        let r = [x[0] - y[0], x[1] - y[1]];
        let res = r[0].abs().max(r[1].abs());
        if res <= tol {
            return Ok(Preimage {
                st: p,
                residual: res,
            });
        }
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            return Err(NewtonError::Singular { st: p });
        }
        let d = [
            (j[1][1] * r[0] - j[0][1] * r[1]) / det,
            (-j[1][0] * r[0] + j[0][0] * r[1]) / det,
        ];
        let mut step = 1.0;
        let mut next = [p[0] - d[0], p[1] - d[1]];
        while !inside(next) && step > 1e-6 {
            step *= 0.5;
            next = [p[0] - step * d[0], p[1] - step * d[1]];
        }
        if !inside(next) {
            return Err(NewtonError::LeftTriangle { st: p });
        }
        p = next;
    }
    let (x, _) = at(p)?;
    let res = (x[0] - y[0]).abs().max((x[1] - y[1]).abs());
    Ok(Preimage {
        st: p,
        residual: res,
    })
}

/// Seeded spot check: for random targets y in each triangle, Newton from four starts; every
/// converged start must give the same preimage (else two preimages: X is not injective).
pub(crate) fn inversion_spot_check(cm: &ComplexMap, seed: u64, per_triangle: usize) -> CheckResult {
    inversion_spot_check_with(cm, seed, per_triangle, &|f, p| {
        Ok(cm.maps[f].eval_f64_with_jacobian(p[0], p[1]))
    })
}

/// [`inversion_spot_check`] with X evaluated by `eval`. Through the harness
/// (`report::harness`): X non-finite or not evaluable at a Newton iterate (a point of σ,
/// where X is defined) is an offence with a witness, counted in `eval_errors`; a target no
/// start converges for is a counted skipped sample (Newton gave up: no evidence either way);
/// two preimages farther apart than 1e−6 (a NaN distance included) are an offence; nothing
/// examined is skipped.
pub fn inversion_spot_check_with(
    cm: &ComplexMap,
    seed: u64,
    per_triangle: usize,
    eval: &MapEval,
) -> CheckResult {
    let mut c = Check::new(
        "SD-L101(inverse)",
        "X|σ⁻¹ by Newton from several starts reaches one preimage (seeded, f64)",
    )
    .with_seed(seed);
    let mut rng = c.sampler();
    for (f, m) in cm.maps.iter().enumerate() {
        let tol = tolerance(m);
        for _ in 0..per_triangle {
            let t = crate::report::uniform_in_triangle(&mut rng);
            let y = [t[1], t[2]];
            let starts = [y, [0.2, 0.2], [0.6, 0.2], [0.2, 0.6]];
            let runs: Vec<Result<Preimage, NewtonError>> = starts
                .iter()
                .map(|s| newton_with(eval, f, tol, y, *s))
                .collect();
            if let Some(e) = runs
                .iter()
                .filter_map(|r| r.as_ref().err())
                .find(|e| e.is_evaluation_fault())
            {
                c.error(OnError::Offence, e, || {
                    Witness::new(
                        format!("triangle {f}: y = {y:?}: evaluation failed: {e}"),
                        json!({"triangle": f, "y": y, "error": e.to_string()}),
                    )
                });
                continue;
            }
            let sols: Vec<Preimage> = runs
                .into_iter()
                .filter_map(Result::ok)
                .filter(|p| p.residual <= tol)
                .collect();
            let Some(first) = sols.first() else {
                c.error(
                    OnError::Skip,
                    format!("triangle {f}: Newton did not converge from any start for y = {y:?}"),
                    || Witness::new("", json!(null)),
                );
                continue;
            };
            // The residuals (all ≤ tol) are the measured deviation of the examined target.
            let worst = sols
                .iter()
                .map(|p| p.residual)
                .fold(0.0, crate::report::dev_max);
            c.deviation_within(worst, tol, || Witness::new("", json!(null)));
            let (d, other) = sols
                .iter()
                .map(|p| {
                    let d = crate::report::dev_max(
                        (p.st[0] - first.st[0]).abs(),
                        (p.st[1] - first.st[1]).abs(),
                    );
                    (d, p.st)
                })
                .fold((0.0, first.st), |a, b| {
                    if b.0.is_nan() || b.0 > a.0 {
                        b
                    } else {
                        a
                    }
                });
            if !(d <= 1e-6) {
                let p0 = first.st;
                c.offend(|| Witness::new(format!("triangle {f}: y = {y:?} has two preimages (s,t) = {p0:?} and {other:?}"), json!({"triangle": f, "y": y, "preimages": [p0, other]})));
            }
        }
    }
    c.finish("")
}
