//! Mello–Velho Sec. 5, L197–L203: the one-sided normals of the curved isocurve 𝒪 on a shared
//! edge δ, ∇(f̂∘X)|σ(p) = ∇f̂|σ · DX|σ(p), and the derivative-jump argument: if DX|σ(p) =
//! DX|σ′(p) (X has no derivative jump at p) and O kinks at p (∇f̂|σ ∦ ∇f̂|σ′), then 𝒪 kinks at p
//! too, so a smooth 𝒪 over a kinked O needs a jump of DX on δ (L203).
//!
//! Everything is exact at a rational point p of δ. The level is taken through p (c′ = f̂∘X(p)),
//! so that p lies on 𝒪 exactly; the report prints c′ next to the requested level.

use super::complex::PlanarComplex;
use super::edge::{chart_point, local, restrict, u_axpy, u_eval, Frame, UPoly};
use super::maps::SimplexMap;
use super::params::ComplexMap;
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::poly2::Poly2;
use crate::sdiff::common::rational::{from_f64, to_f64, Q};
use num_traits::{Signed, Zero};
use serde::Serialize;
use serde_json::json;

/// One side σ of the edge at p.
#[derive(Debug, Clone, Serialize)]
pub struct Side {
    /// The triangle.
    pub triangle: usize,
    /// ∇(f̂∘X)|σ(p) in the plane (exact, as strings) and as f64.
    pub grad: [String; 2],
    /// The same, f64.
    pub grad_f64: [f64; 2],
    /// ∇f̂|σ (the normal of the linear piece θ).
    pub linear_grad: [String; 2],
    /// DX|σ(p) in the plane, f64 (exact equality is decided on the rationals).
    pub dx_f64: [[f64; 2]; 2],
}

/// The one-sided data at a point of a shared edge.
#[derive(Debug, Clone, Serialize)]
pub struct EdgePoint {
    /// The edge (global ids, a < b).
    pub edge: [u32; 2],
    /// The parameter u of p on a→b, exact.
    pub u: String,
    /// The same, f64.
    pub u_f64: f64,
    /// The level c′ = f̂∘X(p) through p.
    pub level: String,
    /// The same, f64.
    pub level_f64: f64,
    /// Both sides.
    pub sides: [Side; 2],
    /// ∇F_σ × ∇F_σ′ (zero iff 𝒪's one-sided normals are parallel at p), exact.
    pub curved_cross: String,
    /// ∇F_σ · ∇F_σ′ (> 0 with a zero cross product: 𝒪 is C¹ at p, no cusp), exact.
    pub curved_dot: String,
    /// ∇f̂|σ × ∇f̂|σ′ (zero iff O is straight across δ), exact.
    pub linear_cross: String,
    /// 𝒪 is C¹ at p: ∇F_σ × ∇F_σ′ = 0 and ∇F_σ · ∇F_σ′ > 0 (exact).
    pub curved_smooth: bool,
    /// O kinks at p: ∇f̂|σ × ∇f̂|σ′ ≠ 0 (exact).
    pub linear_kink: bool,
    /// DX|σ(p) ≠ DX|σ′(p) (exact).
    pub dx_jumps: bool,
    /// The angle between 𝒪's one-sided normals, radians (f64, for the reader).
    pub curved_angle: f64,
    /// The angle between O's one-sided normals.
    pub linear_angle: f64,
}

fn f_numerator(k: &PlanarComplex, f: usize, m: &SimplexMap, fv: &[Q]) -> Poly2 {
    // f̂∘X = Σ_c f_c x^c = (Σ_c f_c N_c) / D: f̂ is affine and Σ_c x^c = 1 (SD-L131).
    let t = k.triangles[f];
    (0..3).fold(Poly2::zero(0), |acc, c| {
        acc.add(&m.num[c].scale(&fv[t[c] as usize]))
    })
}

fn quotient_derivs(n: &Poly2, d: &Poly2, st: &[Q; 2]) -> Option<(Q, Q, Q)> {
    let (s, t) = (&st[0], &st[1]);
    let dv = d.eval(s, t);
    if dv.is_zero() {
        return None;
    }
    let nv = n.eval(s, t);
    let d2 = &dv * &dv;
    let fs = (n.ds().eval(s, t) * &dv - &nv * d.ds().eval(s, t)) / &d2;
    let ft = (n.dt().eval(s, t) * &dv - &nv * d.dt().eval(s, t)) / &d2;
    Some((&nv / &dv, fs, ft))
}

fn cross(a: &[Q; 2], b: &[Q; 2]) -> Q {
    &a[0] * &b[1] - &a[1] * &b[0]
}
fn dot(a: &[Q; 2], b: &[Q; 2]) -> Q {
    &a[0] * &b[0] + &a[1] * &b[1]
}
fn angle(a: &[Q; 2], b: &[Q; 2]) -> f64 {
    let (a, b) = (
        [to_f64(&a[0]), to_f64(&a[1])],
        [to_f64(&b[0]), to_f64(&b[1])],
    );
    (a[0] * b[1] - a[1] * b[0])
        .atan2(a[0] * b[0] + a[1] * b[1])
        .abs()
}
fn strs(a: &[Q; 2]) -> [String; 2] {
    [a[0].to_string(), a[1].to_string()]
}

/// F = f̂∘X on triangle `tri` at parameter `u` of its edge a→b: the value and the plane
/// gradient ∇F|σ, exact. `None` when a or b is not a vertex of `tri` or D vanishes there.
pub fn side_value_gradient(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    tri: usize,
    (a, b): (u32, u32),
    u: &Q,
) -> Option<(Q, [Q; 2])> {
    let m = cm.maps.get(tri)?;
    let (la, lb) = (local(k, tri, a)?, local(k, tri, b)?);
    let st = chart_point(la, lb, u);
    let (val, fs, ft) = quotient_derivs(&f_numerator(k, tri, m, fv), &m.den, &st)?;
    Some((val, Frame::of(k, tri).plane_gradient(&fs, &ft)))
}

/// The one-sided data at parameter `u` of the interior edge (a, b) shared by triangles f, g,
/// for vertex values `fv`. `None` when a denominator vanishes at p.
pub fn one_sided(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    (a, b, f, g): (u32, u32, usize, usize),
    u: &Q,
) -> Option<EdgePoint> {
    let mut vals = Vec::new();
    let mut sides = Vec::new();
    let mut dxs = Vec::new();
    for tri in [f, g] {
        let m = &cm.maps[tri];
        let (la, lb) = (local(k, tri, a)?, local(k, tri, b)?);
        let st = chart_point(la, lb, u);
        let frame = Frame::of(k, tri);
        let fnum = f_numerator(k, tri, m, fv);
        let (val, fs, ft) = quotient_derivs(&fnum, &m.den, &st)?;
        let grad = frame.plane_gradient(&fs, &ft);
        let t = k.triangles[tri];
        let f0 = &fv[t[0] as usize];
        let lin = frame.plane_gradient(&(&fv[t[1] as usize] - f0), &(&fv[t[2] as usize] - f0));
        let (_, x1s, x1t) = quotient_derivs(&m.num[1], &m.den, &st)?;
        let (_, x2s, x2t) = quotient_derivs(&m.num[2], &m.den, &st)?;
        let dx = frame.plane_jacobian(&[[x1s, x1t], [x2s, x2t]]);
        sides.push((tri, grad, lin));
        dxs.push(dx);
        vals.push(val);
    }
    let level = vals[0].clone();
    let (g0, g1) = (&sides[0].1, &sides[1].1);
    let (l0, l1) = (&sides[0].2, &sides[1].2);
    let side = |i: usize| -> Side {
        let (tri, gr, lin) = &sides[i];
        Side {
            triangle: *tri,
            grad: strs(gr),
            grad_f64: [to_f64(&gr[0]), to_f64(&gr[1])],
            linear_grad: strs(lin),
            dx_f64: [
                [to_f64(&dxs[i][0][0]), to_f64(&dxs[i][0][1])],
                [to_f64(&dxs[i][1][0]), to_f64(&dxs[i][1][1])],
            ],
        }
    };
    Some(EdgePoint {
        edge: [a, b],
        u: u.to_string(),
        u_f64: to_f64(u),
        level_f64: to_f64(&level),
        level: level.to_string(),
        curved_smooth: cross(g0, g1).is_zero() && dot(g0, g1).is_positive(),
        linear_kink: !cross(l0, l1).is_zero(),
        curved_cross: cross(g0, g1).to_string(),
        curved_dot: dot(g0, g1).to_string(),
        linear_cross: cross(l0, l1).to_string(),
        dx_jumps: dxs[0] != dxs[1],
        curved_angle: angle(g0, g1),
        linear_angle: angle(l0, l1),
        sides: [side(0), side(1)],
    })
}

/// The crossing of 𝒪 = (f̂∘X)⁻¹(c) with the interior edge (a, b) as seen from triangle f: the
/// rational nearest (in f64) to the root of f̂∘X − c on the edge, by bisection; `None` when O
/// does not cross the edge.
pub fn crossing(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    c: &Q,
    (a, b, f, _): (u32, u32, usize, usize),
) -> Option<Q> {
    let (fa, fb) = (&fv[a as usize] - c, &fv[b as usize] - c);
    if fa.is_positive() == fb.is_positive() {
        return None;
    }
    let m = &cm.maps[f];
    let (la, lb) = (local(k, f, a)?, local(k, f, b)?);
    // (f̂∘X − c)·D restricted to the edge: N − c·D.
    let nf: UPoly = u_axpy(
        &restrict(&f_numerator(k, f, m, fv), la, lb),
        &(-c.clone()),
        &restrict(&m.den, la, lb),
    );
    let at = |x: f64| -> f64 { to_f64(&u_eval(&nf, &from_f64(x).unwrap_or_default())) };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    let neg_lo = at(lo) < 0.0;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (at(mid) < 0.0) == neg_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    from_f64(0.5 * (lo + hi))
}

/// L203 on one record: 𝒪 smooth at p while O kinks at p and DX has no jump there contradicts
/// the argument of L201–L203.
pub(crate) fn l203_offence(p: &EdgePoint) -> bool {
    p.curved_smooth && p.linear_kink && !p.dx_jumps
}

/// Sec. 5, L203, on every interior edge crossed by O: the one-sided data at 𝒪's crossing
/// (level through the nearest rational point), and the derivative-jump claim.
pub fn check_l203(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    c: &Q,
) -> (CheckResult, Vec<EdgePoint>) {
    let mut r = CheckResult::new(
        "SD-L203",
        "Sec. 5: 𝒪 smooth across δ where O kinks ⇒ DX jumps on δ (exact one-sided normals)",
    );
    let mut points = Vec::new();
    let mut worst_level = 0.0f64;
    for e in k.interior_edges() {
        let Some(u) = crossing(k, cm, fv, c, e) else {
            continue;
        };
        let Some(p) = one_sided(k, cm, fv, e, &u) else {
            r.eval_errors += 1;
            continue;
        };
        r.examined += 1;
        let shift = (p.level_f64 - to_f64(c)).abs();
        worst_level = crate::report::dev_max(worst_level, shift);
        record(&mut r, &p);
        points.push(p);
    }
    let kinks = points.iter().filter(|p| p.linear_kink).count();
    let smooth = points.iter().filter(|p| p.curved_smooth).count();
    let jumps = points.iter().filter(|p| p.dx_jumps).count();
    r.note = format!(
        "{} crossings: O kinks at {kinks}, 𝒪 is C¹ at {smooth}, DX jumps at {jumps}; levels through the rational crossing points differ from c by ≤ {worst_level:.3e}",
        points.len()
    );
    if r.examined == 0 && !r.failed() {
        r.skip("O crosses no interior edge");
    }
    (r, points)
}

/// Records `p` in `r`: an offence when [`l203_offence`].
pub fn record(r: &mut CheckResult, p: &EdgePoint) {
    if l203_offence(p) {
        let (e, u) = (p.edge, p.u.clone());
        r.offend(|| {
            Witness::new(
                format!("edge {e:?} at u = {u}: 𝒪 is C¹ and O kinks, yet DX|σ = DX|σ′"),
                json!({"edge": e, "u": u, "point": serde_json::to_value(p).unwrap_or_default()}),
            )
        });
    }
}
