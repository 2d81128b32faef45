//! The two normal-based objectives of Mello–Velho: the normal deviation of Sec. 5 for
//! polynomial maps (L229–L233), err(δ, β) = Σ_{p_i ∈ δ} ‖n_{δ,β}(p_i) − n′_{δ,β}(p_i)‖², and the
//! hermite-handle error of Sec. 6.1 (L262), err(σ, β) = Σ_ε F²/‖∇F‖² + α‖∇F/‖∇F‖ − n(ε)‖²
//! over the edges ε of σ crossed by O, F = f̂_σ∘X_β, minimised over β at L268.
//!
//! Gradients are exact (rational, `normals::side_value_gradient`); a unit-normal gap
//! ‖a/‖a‖ − b/‖b‖‖² is irrational in general, so it is decided zero exactly (a × b = 0 and
//! a·b > 0) and valued in f64 from the exact sin² = (a × b)²/(‖a‖²‖b‖²), without cancellation.

use super::checks::det_positive_exact;
use super::complex::PlanarComplex;
use super::edge::local;
use super::handles::quadratic_spec;
use super::normals::side_value_gradient;
use super::params::ComplexMap;
use crate::report::{CheckResult, Verdict, Witness};
use crate::sdiff::common::positivity::Budget;
use crate::sdiff::common::rational::{to_f64, Q};
use num_traits::{One, Signed, Zero};
use serde::Serialize;
use serde_json::json;
use std::collections::HashMap;
use std::path::Path;

/// ‖a/‖a‖ − b/‖b‖‖²: exact zero test and f64 value. `None` when a or b is zero (undefined).
pub fn unit_gap(a: &[Q; 2], b: &[Q; 2]) -> Option<(bool, f64)> {
    let (na, nb) = (dot(a, a), dot(b, b));
    if na.is_zero() || nb.is_zero() {
        return None;
    }
    let (cr, d) = (&a[0] * &b[1] - &a[1] * &b[0], dot(a, b));
    let sin2 = to_f64(&(&cr * &cr / (&na * &nb))).clamp(0.0, 1.0);
    let cos_abs = (1.0 - sin2).sqrt();
    // 2 − 2cos = 2 sin²/(1 + cos) for cos ≥ 0; 2 + 2|cos| otherwise.
    let value = if d.is_positive() {
        2.0 * sin2 / (1.0 + cos_abs)
    } else {
        2.0 + 2.0 * cos_abs
    };
    Some((cr.is_zero() && d.is_positive(), value))
}

fn dot(a: &[Q; 2], b: &[Q; 2]) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1]
}

/// One sample p_i = a + u(b − a) of an interior edge δ for L231.
#[derive(Debug, Clone, Serialize)]
pub struct NormalSample {
    /// u, exact.
    pub u: String,
    /// ∇F|σ(p_i) and ∇F|σ′(p_i), exact.
    pub grads: [[String; 2]; 2],
    /// ‖n − n′‖² (f64 from the exact gradients).
    pub gap: f64,
    /// The normals agree exactly.
    pub zero: bool,
}

/// err(δ, β) of L231 on one interior edge.
#[derive(Debug, Clone, Serialize)]
pub struct EdgeDeviation {
    /// δ (global ids, a < b).
    pub edge: [u32; 2],
    /// Σ_i ‖n(p_i) − n′(p_i)‖².
    pub err: f64,
    /// Every sample's normals agree exactly.
    pub zero: bool,
    /// The samples.
    pub samples: Vec<NormalSample>,
    /// Samples where a one-sided gradient vanishes or D = 0 (the normal is undefined).
    pub undefined: usize,
}

/// L231 as written: err(δ, β) at p_i = a + i/(m + 1)(b − a), i = 1..m, on every interior edge.
pub fn normal_deviation(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    m: usize,
) -> Vec<EdgeDeviation> {
    let mut out = Vec::new();
    for (a, b, f, g) in k.interior_edges() {
        let mut e = EdgeDeviation {
            edge: [a, b],
            err: 0.0,
            zero: true,
            samples: Vec::new(),
            undefined: 0,
        };
        for i in 1..=m {
            let u = Q::new((i as i64).into(), ((m + 1) as i64).into());
            let sides = [f, g].map(|t| side_value_gradient(k, cm, fv, t, (a, b), &u));
            let [Some((_, ga)), Some((_, gb))] = sides else {
                e.undefined += 1;
                continue;
            };
            let Some((zero, gap)) = unit_gap(&ga, &gb) else {
                e.undefined += 1;
                continue;
            };
            e.err += gap;
            e.zero &= zero;
            e.samples.push(NormalSample {
                u: u.to_string(),
                grads: [ga, gb].map(|x| [x[0].to_string(), x[1].to_string()]),
                gap,
                zero,
            });
        }
        out.push(e);
    }
    out
}

/// `SD-L231`: err(δ, β) of L231 vanishes where 𝒪 is C¹ across δ. `c1_holds`: 𝒪 = (f̂∘X)⁻¹(c)
/// is C¹ on every interior edge crossed by O (decided exactly by `c1::verify`, `SD-E12`);
/// `crossed` tells which edges O crosses. An offence is an edge crossed by O with 𝒪 C¹ and
/// err > 0 (exact); an undefined normal is an evaluation error, never a pass.
pub fn judge_l231(devs: &[EdgeDeviation], crossed: &[[u32; 2]], c1_holds: bool) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L231",
        "L231: err(δ, β) = Σ_{p_i ∈ δ} ‖n − n′‖² is 0 where 𝒪 is C¹ across δ",
    );
    let mut worst = 0.0f64;
    for d in devs.iter().filter(|d| crossed.contains(&d.edge)) {
        r.examined += d.samples.len() as u64;
        r.eval_errors += d.undefined as u64;
        worst = crate::report::dev_max(worst, d.err);
        if d.undefined > 0 {
            let e = d.edge;
            r.offend(|| {
                Witness::new(
                    format!(
                        "edge {e:?}: the normal is undefined at {} samples (∇F = 0 or D = 0)",
                        d.undefined
                    ),
                    json!({"edge": e}),
                )
            });
        }
        if c1_holds && !d.zero {
            let s = d.samples.iter().find(|s| !s.zero).cloned();
            let e = d.edge;
            r.offend(|| {
                let (u, gap, gr) = s
                    .map(|s| (s.u, s.gap, s.grads))
                    .unwrap_or_else(|| (String::new(), f64::NAN, Default::default()));
                Witness::new(
                    format!(
                        "edge {e:?}: 𝒪 is C¹ across δ, yet err(δ) = {:.6e}; at u = {u}: ‖n − n′‖² = {gap:.6e}, ∇F = {:?} vs {:?}",
                        d.err, gr[0], gr[1]
                    ),
                    json!({"edge": e, "err": d.err, "u": u, "gap": gap, "grads": gr}),
                )
            });
        }
    }
    r.worst_deviation = Some(worst);
    r.note = format!(
        "{} crossed interior edges, {} samples; largest err(δ) {worst:.6e}; 𝒪 C¹ on every crossed edge: {c1_holds}",
        devs.iter().filter(|d| crossed.contains(&d.edge)).count(),
        r.examined
    );
    if r.examined == 0 && !r.failed() {
        r.skip("no sample on an interior edge crossed by O");
    }
    r
}

/// A hermite handle of Sec. 6.1 (L252–L254) on an edge ε = {v_0, v_1} crossed by O: the point
/// p(ε) = v_0 + u(v_1 − v_0) and the unit normal n(ε).
#[derive(Debug, Clone)]
pub struct Handle {
    /// ε (global ids, a < b); u is measured from a.
    pub edge: (u32, u32),
    /// p(ε)'s parameter on a→b.
    pub u: Q,
    /// n(ε), a unit vector (‖n‖² = 1 exactly).
    pub n: [Q; 2],
}

/// Why L262 cannot be evaluated.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HandleErrorKind {
    /// A crossed edge has no handle.
    #[error("edge ({0}, {1}) is crossed by O but has no handle")]
    Missing(u32, u32),
    /// n(ε) is not a unit vector (L254).
    #[error("handle of edge ({0}, {1}): ‖n(ε)‖² = {2}, not 1 (L254: a unit vector)")]
    NotUnit(u32, u32, String),
    /// ∇F vanishes or D = 0 at p(ε): the quotients of L262 are undefined.
    #[error("triangle {0}, edge ({1}, {2}): ∇F(p(ε)) = 0 or D = 0, L262 undefined")]
    Undefined(usize, u32, u32),
}

/// L262 for every triangle: (Σ position terms F²/‖∇F‖² exact, Σ normal terms f64, every
/// normal term exactly zero).
#[derive(Debug, Clone, Serialize)]
pub struct CellError {
    /// σ.
    pub triangle: usize,
    /// Σ_ε F²/‖∇F‖², exact.
    pub position: String,
    /// The same, f64.
    pub position_f64: f64,
    /// Σ_ε ‖∇F/‖∇F‖ − n(ε)‖², f64 from exact gradients.
    pub normal: f64,
    /// Every normal term is exactly zero.
    pub normal_zero: bool,
}

/// err(σ, β) of L262 on every triangle of K for vertex values `fv` (level 0: s(v) = sign f(v),
/// L250) and the given handles; the objective of L268 is Σ_σ (position + α·normal).
pub fn handle_errors(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    handles: &[Handle],
) -> Result<Vec<CellError>, HandleErrorKind> {
    for h in handles {
        let n2 = dot(&h.n, &h.n);
        if !n2.is_one() {
            return Err(HandleErrorKind::NotUnit(h.edge.0, h.edge.1, n2.to_string()));
        }
    }
    let mut out = Vec::new();
    for (tri, t) in k.triangles.iter().enumerate() {
        let mut c = CellError {
            triangle: tri,
            position: String::new(),
            position_f64: 0.0,
            normal: 0.0,
            normal_zero: true,
        };
        let mut pos = Q::zero();
        for (i, j) in [(0, 1), (1, 2), (2, 0)] {
            let (a, b) = (t[i].min(t[j]), t[i].max(t[j]));
            let (fa, fb) = (&fv[a as usize], &fv[b as usize]);
            if (fa * fb).is_positive() || local(k, tri, a).is_none() {
                continue;
            }
            let h = handles
                .iter()
                .find(|h| h.edge == (a, b))
                .ok_or(HandleErrorKind::Missing(a, b))?;
            let (val, grad) = side_value_gradient(k, cm, fv, tri, (a, b), &h.u)
                .ok_or(HandleErrorKind::Undefined(tri, a, b))?;
            let g2 = dot(&grad, &grad);
            if g2.is_zero() {
                return Err(HandleErrorKind::Undefined(tri, a, b));
            }
            pos += &val * &val / &g2;
            let (zero, gap) = unit_gap(&grad, &h.n).ok_or(HandleErrorKind::Undefined(tri, a, b))?;
            c.normal += gap;
            c.normal_zero &= zero;
        }
        c.position_f64 = to_f64(&pos);
        c.position = pos.to_string();
        out.push(c);
    }
    Ok(out)
}

/// Σ_σ err(σ, β) of L268 with weight α, f64 (the position part is exact before rounding).
pub fn total(cells: &[CellError], alpha: f64) -> f64 {
    cells
        .iter()
        .map(|c| c.position_f64 + alpha * c.normal)
        .sum()
}

/// The minimiser of a scan and the exact det verdict of its map.
pub(crate) type Judged = (ScanPoint, CheckResult);

/// One point of the L268 scan over X_1's control point c_ε = (1 − λ)a + λb on one edge.
#[derive(Debug, Clone, Serialize)]
pub struct ScanPoint {
    /// λ, exact.
    pub lambda: String,
    /// λ as f64.
    pub lambda_f64: f64,
    /// Σ_σ err(σ, β) (L268) with the given α.
    pub objective: f64,
    /// Σ of the position terms, exact.
    pub position: String,
}

/// The minimiser of L268 over λ ∈ `lambdas` for X_1 with one free edge control point (the other
/// control points at the edge midpoints: X = id there), and the exact det verdict of that
/// minimiser (`SD-L101(det)`). `Err` when L262 is undefined at some λ.
pub fn scan_l268(
    k: &PlanarComplex,
    fv: &[Q],
    handles: &[Handle],
    edge: (u32, u32),
    alpha: f64,
    lambdas: &[Q],
) -> Result<(Vec<ScanPoint>, Option<Judged>), String> {
    let mut pts: Vec<ScanPoint> = Vec::new();
    let path = Path::new("(L268 scan)");
    for l in lambdas {
        let spec = quadratic_spec(k, &HashMap::from([(edge, l.clone())]));
        let cm = spec.build(k, path).map_err(|e| e.to_string())?;
        let cells = handle_errors(k, &cm, fv, handles).map_err(|e| e.to_string())?;
        let pos = cells.iter().fold(Q::zero(), |acc, c| {
            acc + c.position.parse::<Q>().unwrap_or_else(|_| Q::zero())
        });
        pts.push(ScanPoint {
            lambda: l.to_string(),
            lambda_f64: to_f64(l),
            objective: total(&cells, alpha),
            position: pos.to_string(),
        });
    }
    let best = pts
        .iter()
        .filter(|p| p.objective.is_finite())
        .min_by(|a, b| a.objective.total_cmp(&b.objective))
        .cloned();
    let judged = match best {
        Some(b) => {
            let l: Q = b
                .lambda
                .parse()
                .map_err(|_| "λ does not parse".to_string())?;
            let cm = quadratic_spec(k, &HashMap::from([(edge, l)]))
                .build(k, path)
                .map_err(|e| e.to_string())?;
            Some((b, det_positive_exact(&cm, Budget::default()).0))
        }
        None => None,
    };
    Ok((pts, judged))
}

/// `SD-L268`: the minimiser of Σ_σ err(σ, β) over β is a diffeomorphism (the purpose of β,
/// L256). An offence is a minimiser whose det DX is refuted exactly; an unresolved det is
/// skipped, never a pass.
pub fn judge_l268(best: &ScanPoint, det: &CheckResult, alpha: f64) -> CheckResult {
    let mut r = CheckResult::new(
        "SD-L268",
        "L268: the minimiser of Σ_σ err(σ, β) over β is a diffeomorphism",
    );
    r.examined = 1;
    r.note = format!(
        "α = {alpha}; minimiser λ = {} ({:.6}), objective {:.6e}, position part {}",
        best.lambda, best.lambda_f64, best.objective, best.position
    );
    if det.failed() {
        let wt = det
            .witnesses
            .first()
            .map(|w| w.text.clone())
            .unwrap_or_default();
        let (l, o) = (best.lambda.clone(), best.objective);
        r.offend(|| {
            Witness::new(
                format!("the minimiser λ = {l} (objective {o:.6e}) is not a diffeomorphism: {wt}"),
                json!({"lambda": l, "objective": o, "det": wt}),
            )
        });
    } else if !matches!(det.verdict(), Verdict::Holds) {
        r.skip("det DX of the minimiser unresolved within the budget");
    }
    r
}
