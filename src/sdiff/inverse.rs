//! X|σ⁻¹ by damped Newton in f64 (Mello–Velho Sec. 4: sampling 𝒪 needs q = X|σ⁻¹(p)), and a
//! seeded spot check of injectivity: Newton from several starts must reach one preimage.

use super::maps::SimplexMap;
use super::params::ComplexMap;
use crate::report::{CheckResult, Witness};
use rand::SeedableRng;
use serde_json::json;

/// Newton's answer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Preimage {
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

/// Solves X(s, t) = y from `start`, staying in the closed triangle by step halving.
pub fn newton(m: &SimplexMap, y: [f64; 2], start: [f64; 2]) -> Option<Preimage> {
    let inside = |p: [f64; 2]| p[0] >= -1e-12 && p[1] >= -1e-12 && p[0] + p[1] <= 1.0 + 1e-12;
    let mut p = start;
    for _ in 0..100 {
        let (x, j) = m.eval_f64_with_jacobian(p[0], p[1]);
        let r = [x[0] - y[0], x[1] - y[1]];
        let res = r[0].abs().max(r[1].abs());
        if !res.is_finite() {
            return None;
        }
        if res <= tolerance(m) {
            return Some(Preimage {
                st: p,
                residual: res,
            });
        }
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            return None;
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
            return None;
        }
        p = next;
    }
    let (x, _) = m.eval_f64_with_jacobian(p[0], p[1]);
    let res = (x[0] - y[0]).abs().max((x[1] - y[1]).abs());
    Some(Preimage {
        st: p,
        residual: res,
    })
}

/// Seeded spot check: for random targets y in each triangle, Newton from four starts; every
/// converged start must give the same preimage (else two preimages: X is not injective).
pub fn inversion_spot_check(cm: &ComplexMap, seed: u64, per_triangle: usize) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L101(inverse)",
        "X|σ⁻¹ by Newton from several starts reaches one preimage (seeded, f64)",
    );
    r.seed = Some(seed);
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut worst = 0.0f64;
    let mut failed_to_converge = 0u64;
    for (f, m) in cm.maps.iter().enumerate() {
        let tol = tolerance(m);
        r.tolerance = Some(r.tolerance.map_or(tol, |t: f64| t.max(tol)));
        for _ in 0..per_triangle {
            let t = crate::report::uniform_in_triangle(&mut rng);
            let y = [t[1], t[2]];
            r.examined += 1;
            let starts = [y, [0.2, 0.2], [0.6, 0.2], [0.2, 0.6]];
            let sols: Vec<Preimage> = starts
                .iter()
                .filter_map(|s| newton(m, y, *s))
                .filter(|p| p.residual <= tol)
                .collect();
            if sols.is_empty() {
                failed_to_converge += 1;
                continue;
            }
            for p in &sols {
                worst = worst.max(p.residual);
                let d = (p.st[0] - sols[0].st[0])
                    .abs()
                    .max((p.st[1] - sols[0].st[1]).abs());
                if d > 1e-6 {
                    let (p0, p1) = (sols[0].st, p.st);
                    r.offend(|| Witness::new(format!("triangle {f}: y = {y:?} has two preimages (s,t) = {p0:?} and {p1:?}"), json!({"triangle": f, "y": y, "preimages": [p0, p1]})));
                    break;
                }
            }
        }
    }
    r.worst_deviation = Some(worst);
    if failed_to_converge > 0 {
        r.note = format!(
            "Newton did not converge for {failed_to_converge} target(s) (counted as unexamined)"
        );
        r.examined -= failed_to_converge;
    }
    if r.examined == 0 {
        r.skip("no target converged");
    }
    r
}
