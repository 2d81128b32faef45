//! Mello–Velho Sec. 5, Eq. (12) (L213) and the linear system of L217–L219: Farin's C¹
//! condition across a shared edge applied to the numerator of f̂∘X for a rational map (11),
//!
//!   q_{J+e_0} f̂|σ(c_{J+e_0}) = Σ_i w_i q′_{J+e_i} f̂|σ′(c′_{J+e_i}),   |J| = n − 1, J^0 = 0,
//!
//! with (w_i) the barycentric coordinates of σ's opposite vertex p_0 in σ′. Reading: Sec. 5
//! uses n for the dimension and the degree and writes |J| = m − 1; we read |J| = n − 1 with n
//! the degree (Farin's condition), and f̂ − c for f̂ (the level c; the paper's applications use
//! c = 0). Weights are keyed by global vertex multisets, so shared weights are one unknown.
//!
//! Why it works: f̂∘X − c = N/D with N = Σ q_I (f̂(c_I) − c) B_I (f̂ is affine and Σ x^c = 1),
//! so (12) is Farin's condition for the piecewise polynomial N to be C¹, and on 𝒪 (N = 0)
//! ∇(f̂∘X) = ∇N/D, with D shared on δ. The verification here does not trust that argument: it
//! decides ∇N|σ ≡ ∇N|σ′ on δ and "∇(f̂∘X) agrees on δ wherever N = 0" (the gradient jump is
//! divisible by N on δ) as exact polynomial identities in the edge parameter.

use super::complex::PlanarComplex;
use super::edge::{local, restrict, trim, u_axpy, u_eval, u_mul, u_rem, Frame, UPoly};
use super::params::{ComplexMap, MapSpec};
use crate::report::{CheckResult, Witness};
use crate::sdiff::common::linsys::{positive_solution, rref, Positive, Rref};
use crate::sdiff::common::params::{FamilySpec, Multiset};
use crate::sdiff::common::poly2::{multi_indices, Poly2};
use crate::sdiff::common::rational::{q, Q};
use num_traits::Zero;
use serde_json::json;
use std::collections::{BTreeMap, HashMap};

/// One equation Σ coeff·q = 0 of the system.
#[derive(Debug, Clone)]
pub struct Equation {
    /// The edge δ (global ids).
    pub edge: [u32; 2],
    /// σ (the side of p_0) and σ′.
    pub triangles: [usize; 2],
    /// J as a global multiset on δ.
    pub j: Multiset,
    /// (unknown, coefficient).
    pub terms: Vec<(usize, Q)>,
}

/// The system of L217.
#[derive(Debug, Clone)]
pub struct System {
    /// Degree n.
    pub degree: usize,
    /// The unknowns q_I, by global multiset.
    pub unknowns: Vec<Multiset>,
    /// The equations, one per (interior edge, J).
    pub equations: Vec<Equation>,
}

fn local_index(k: &PlanarComplex, f: usize, m: &Multiset) -> Option<[usize; 3]> {
    let t = k.triangles[f];
    let mut i = [0usize; 3];
    for v in m {
        i[local(k, f, *v)?] += 1;
    }
    let _ = t;
    Some(i)
}

/// f̂|σ(c_I) − c for the control point of multiset `m` in triangle f.
fn fhat_at_control(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    c: &Q,
    f: usize,
    m: &Multiset,
) -> Option<Q> {
    let map = &cm.maps[f];
    let i = local_index(k, f, m)?;
    let b = map.b(i);
    let t = k.triangles[f];
    Some((0..3).map(|l| &b[l] * (&fv[t[l] as usize] - c)).sum())
}

/// Which edges (12) is imposed on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Scope {
    /// "all faces of the complex K" (L217), as written.
    AllInteriorEdges,
    /// Only the interior edges crossed by O (𝒪 = X⁻¹(O) meets no other edge: X keeps edges).
    CrossedEdges,
}

/// The interior edges of `scope`.
pub fn edges(k: &PlanarComplex, fv: &[Q], c: &Q, scope: Scope) -> Vec<(u32, u32, usize, usize)> {
    k.interior_edges()
        .into_iter()
        .filter(|(a, b, _, _)| {
            scope == Scope::AllInteriorEdges
                || ((&fv[*a as usize] - c) * (&fv[*b as usize] - c)) < Q::zero()
        })
        .collect()
}

/// Builds the system (12) over the interior edges of `scope` for the control points of `cm`
/// (degree n ≥ 1, polynomial or rational family), vertex values `fv` and level `c`.
pub fn build(k: &PlanarComplex, cm: &ComplexMap, fv: &[Q], c: &Q, scope: Scope) -> Option<System> {
    let n = cm.maps.first()?.degree;
    let mut index: BTreeMap<Multiset, usize> = BTreeMap::new();
    for f in 0..k.triangles.len() {
        for i in multi_indices(n) {
            let key = MapSpec::global_key(k, f, i);
            let len = index.len();
            index.entry(key).or_insert(len);
        }
    }
    let mut equations = Vec::new();
    for (a, b, f, g) in edges(k, fv, c, scope) {
        // σ = f with p_0 its vertex off δ; σ′ = g.
        let p0 = *k.triangles[f].iter().find(|&&v| v != a && v != b)?;
        let w = k.barycentric(g, &k.points[p0 as usize]);
        for ja in 0..n {
            let mut j: Multiset = std::iter::repeat(a)
                .take(ja)
                .chain(std::iter::repeat(b).take(n - 1 - ja))
                .collect();
            j.sort_unstable();
            let with = |v: u32| -> Multiset {
                let mut m = j.clone();
                m.push(v);
                m.sort_unstable();
                m
            };
            let mut terms: HashMap<usize, Q> = HashMap::new();
            let lhs = with(p0);
            *terms.entry(index[&lhs]).or_insert_with(Q::zero) +=
                fhat_at_control(k, cm, fv, c, f, &lhs)?;
            for (li, &v) in k.triangles[g].iter().enumerate() {
                let m = with(v);
                *terms.entry(index[&m]).or_insert_with(Q::zero) -=
                    &w[li] * fhat_at_control(k, cm, fv, c, g, &m)?;
            }
            let mut terms: Vec<(usize, Q)> =
                terms.into_iter().filter(|(_, x)| !x.is_zero()).collect();
            terms.sort_by_key(|(u, _)| *u);
            equations.push(Equation {
                edge: [a, b],
                triangles: [f, g],
                j,
                terms,
            });
        }
    }
    let mut unknowns = vec![Vec::new(); index.len()];
    for (m, i) in index {
        unknowns[i] = m;
    }
    Some(System {
        degree: n,
        unknowns,
        equations,
    })
}

/// What solving the system found.
#[derive(Debug, Clone)]
pub struct Solved {
    /// Equations, unknowns (all), unknowns met by some equation.
    pub counts: [usize; 3],
    /// Rank of the system.
    pub rank: usize,
    /// The RREF (over the unknowns met by some equation, in `involved` order).
    pub rref: Rref,
    /// Unknown ids met by some equation.
    pub involved: Vec<usize>,
    /// How the positive solution was decided.
    pub positive: Positive,
    /// Weights for every unknown (≥ 1), when found; unknowns met by no equation are 1.
    pub weights: Option<Vec<Q>>,
}

/// Exact Gaussian elimination of the system and the search for a solution with all q_I ≥ 1
/// (> 0 up to the scaling of a homogeneous system).
pub fn solve(sys: &System, max_inequalities: usize) -> Solved {
    let mut involved: Vec<usize> = sys
        .equations
        .iter()
        .flat_map(|e| e.terms.iter().map(|(u, _)| *u))
        .collect();
    involved.sort_unstable();
    involved.dedup();
    let col: HashMap<usize, usize> = involved.iter().enumerate().map(|(c, u)| (*u, c)).collect();
    let rows: Vec<Vec<Q>> = sys
        .equations
        .iter()
        .map(|e| {
            let mut r = vec![Q::zero(); involved.len()];
            for (u, x) in &e.terms {
                r[col[u]] = x.clone();
            }
            r
        })
        .collect();
    let red = rref(rows, involved.len());
    let (positive, sol) = positive_solution(&red, max_inequalities);
    let weights = sol.map(|x| {
        let mut w = vec![q(1); sys.unknowns.len()];
        for (c, u) in involved.iter().enumerate() {
            w[*u] = x[c].clone();
        }
        w
    });
    Solved {
        counts: [sys.equations.len(), sys.unknowns.len(), involved.len()],
        rank: red.rank(),
        rref: red,
        involved,
        positive,
        weights,
    }
}

/// The rational map (11) with the control points of `spec` and the weights `w` (by unknown).
pub fn with_weights(spec: &MapSpec, sys: &System, w: &[Q]) -> MapSpec {
    let mut s = spec.clone();
    s.family = FamilySpec::Rational;
    s.weights = sys
        .unknowns
        .iter()
        .zip(w)
        .map(|(m, x)| ((None, m.clone()), x.clone()))
        .collect();
    s
}

/// The residual of every equation at `w` (zero iff (12) holds there).
pub fn residuals(sys: &System, w: &[Q]) -> Vec<Q> {
    sys.equations
        .iter()
        .map(|e| e.terms.iter().map(|(u, x)| x * &w[*u]).sum())
        .collect()
}

fn numerator(k: &PlanarComplex, cm: &ComplexMap, fv: &[Q], c: &Q, f: usize) -> Poly2 {
    let t = k.triangles[f];
    let m = &cm.maps[f];
    (0..3).fold(Poly2::zero(0), |acc, l| {
        acc.add(&m.num[l].scale(&(&fv[t[l] as usize] - c)))
    })
}

/// Plane gradient of a chart polynomial, restricted to the edge (la → lb): two UPolys.
fn edge_gradient(p: &Poly2, frame: &Frame, la: usize, lb: usize) -> [UPoly; 2] {
    let (ps, pt) = (restrict(&p.ds(), la, lb), restrict(&p.dt(), la, lb));
    let j = &frame.j;
    let d = &frame.det;
    [
        u_axpy(
            &ps.iter().map(|x| x * &j[1][1] / d).collect(),
            &(-(&j[1][0]) / d),
            &pt,
        ),
        u_axpy(
            &pt.iter().map(|x| x * &j[0][0] / d).collect(),
            &(-(&j[0][1]) / d),
            &ps,
        ),
    ]
}

fn first_difference(p: &UPoly, r: &UPoly) -> Option<(Q, Q, Q)> {
    let diff = u_axpy(p, &q(-1), r);
    if diff.is_empty() {
        return None;
    }
    // A non-zero polynomial of degree d vanishes at ≤ d of the d + 1 points k/d.
    let d = diff.len().max(1);
    (0..=d)
        .map(|i| Q::new((i as i64).into(), (d as i64).into()))
        .find(|u| !u_eval(&diff, u).is_zero())
        .map(|u| (u_eval(p, &u), u_eval(r, &u), u))
}

/// Verifies C¹ of 𝒪 across the interior edges of `scope` as polynomial identities in the edge parameter:
/// `SD-E12(N)`: ∇N|σ ≡ ∇N|σ′ on δ (Farin); `SD-E12`: ∇(f̂∘X)|σ = ∇(f̂∘X)|σ′ at every point of
/// δ where f̂∘X = c, i.e. the numerator of the gradient jump is divisible by N|δ.
pub fn verify(
    k: &PlanarComplex,
    cm: &ComplexMap,
    fv: &[Q],
    c: &Q,
    scope: Scope,
) -> [CheckResult; 2] {
    let mut rn = CheckResult::new(
        "SD-E12(N)",
        "Eq. (12): the numerator N of f̂∘X − c is C¹ across every interior edge (exact identity)",
    );
    let mut rf = CheckResult::new(
        "SD-E12",
        "Eq. (12) ⇒ ∇(f̂∘X) agrees across δ at every point of 𝒪 ∩ δ (exact divisibility)",
    );
    let mut whole_edge = 0usize;
    for (a, b, f, g) in edges(k, fv, c, scope) {
        rn.examined += 1;
        rf.examined += 1;
        let mut grads_n = Vec::new();
        let mut grads_d = Vec::new();
        let mut n_edge = Vec::new();
        let mut d_edge = Vec::new();
        for tri in [f, g] {
            let (Some(la), Some(lb)) = (local(k, tri, a), local(k, tri, b)) else {
                continue;
            };
            let frame = Frame::of(k, tri);
            let nm = numerator(k, cm, fv, c, tri);
            grads_n.push(edge_gradient(&nm, &frame, la, lb));
            grads_d.push(edge_gradient(&cm.maps[tri].den, &frame, la, lb));
            n_edge.push(restrict(&nm, la, lb));
            d_edge.push(restrict(&cm.maps[tri].den, la, lb));
        }
        if grads_n.len() != 2 {
            rn.eval_errors += 1;
            continue;
        }
        for axis in 0..2 {
            if let Some((x, y, u)) = first_difference(&grads_n[0][axis], &grads_n[1][axis]) {
                rn.offend(|| Witness::new(format!("edge ({a}, {b}), triangles {f}|{g}: ∂N/∂{} = {x} vs {y} at u = {u}", ["x", "y"][axis]), json!({"edge": [a, b], "triangles": [f, g], "axis": axis, "u": u.to_string(), "values": [x.to_string(), y.to_string()]})));
                break;
            }
        }
        // Gradient jump of F = N/D, times D² (D and N agree on δ by SD-L99):
        // (∇N_σ − ∇N_σ′)·D − N·(∇D_σ − ∇D_σ′).
        let mut divisible = true;
        let mut identically = true;
        for axis in 0..2 {
            let dn = u_axpy(&grads_n[0][axis], &q(-1), &grads_n[1][axis]);
            let dd = u_axpy(&grads_d[0][axis], &q(-1), &grads_d[1][axis]);
            let jump = u_axpy(&u_mul(&dn, &d_edge[0]), &q(-1), &u_mul(&n_edge[0], &dd));
            if !jump.is_empty() {
                identically = false;
            }
            let n0 = trim(n_edge[0].clone());
            if n0.is_empty() {
                // N ≡ 0 on δ: δ lies in 𝒪; the jump must vanish identically.
                divisible &= jump.is_empty();
            } else if !u_rem(&jump, &n0).is_empty() {
                divisible = false;
            }
        }
        if !divisible {
            rf.offend(|| Witness::new(format!("edge ({a}, {b}), triangles {f}|{g}: the jump of ∇(f̂∘X) is not divisible by N on δ, so the one-sided gradients differ at some point of 𝒪 ∩ δ (complex or real)"), json!({"edge": [a, b], "triangles": [f, g]})));
        }
        if identically {
            whole_edge += 1;
        }
    }
    rf.note = format!("∇(f̂∘X) agrees along the whole edge on {whole_edge} of {} edges (elsewhere only on 𝒪 ∩ δ: D's derivative jumps, L203)", rf.examined);
    for r in [&mut rn, &mut rf] {
        if r.examined == 0 {
            r.skip("no interior edge in scope");
        }
    }
    [rn, rf]
}

/// L221: err = Σ_δ Σ_J (residual of (12))², exact. Homogeneous of degree 2 in the weights.
pub fn err(sys: &System, w: &[Q]) -> Q {
    residuals(sys, w).iter().map(|r| r * r).sum()
}

/// What `ppm sd c1` reports: the system's counts and rank (`SD-L219`), the positive solution
/// (`SD-L219(positive)`), and, with it, the exact C¹ verification (`SD-E12(N)`, `SD-E12`).
pub struct C1Run {
    /// The checks.
    pub report: Vec<CheckResult>,
    /// The system.
    pub system: System,
    /// The solution.
    pub solved: Solved,
    /// The rational map with the solved weights.
    pub solution: Option<MapSpec>,
}

/// Builds, solves and verifies (12) for the control points of `spec` on `k`.
pub fn run(
    k: &PlanarComplex,
    spec: &MapSpec,
    fv: &[Q],
    c: &Q,
    scope: Scope,
    max_inequalities: usize,
) -> Result<C1Run, crate::sdiff::common::params::ParamError> {
    let path = std::path::Path::new("(C¹ system)");
    let mut base = spec.clone();
    base.family = FamilySpec::Rational;
    base.weights.clear();
    let cm = base.build(k, path)?;
    let mut report = Vec::new();
    let Some(system) = build(k, &cm, fv, c, scope) else {
        let mut r = CheckResult::new("SD-L219", "L217–L219: the system (12) is underdetermined");
        r.skip("a control point or vertex of an edge is missing");
        report.push(r);
        return Ok(C1Run {
            report,
            system: System {
                degree: spec.degree,
                unknowns: Vec::new(),
                equations: Vec::new(),
            },
            solved: solve(
                &System {
                    degree: spec.degree,
                    unknowns: Vec::new(),
                    equations: Vec::new(),
                },
                max_inequalities,
            ),
            solution: None,
        });
    };
    let solved = solve(&system, max_inequalities);
    let [eqs, unk, inv] = solved.counts;
    let mut r = CheckResult::new(
        "SD-L219",
        "L217–L219: the system (12) is underdetermined (rank < unknowns)",
    );
    r.examined = eqs as u64;
    r.note = format!(
        "degree {}, scope {scope:?}: {eqs} equations, {unk} unknowns ({inv} in some equation), rank {}, solution space of dimension {}; by count {}",
        system.degree,
        solved.rank,
        unk - solved.rank,
        if eqs < unk { "underdetermined" } else { "NOT underdetermined (equations ≥ unknowns)" }
    );
    if solved.rank >= unk {
        r.offend(|| {
            Witness::new(
                format!(
                    "rank {} = number of unknowns: only q = 0 solves (12)",
                    solved.rank
                ),
                json!({"rank": solved.rank, "unknowns": unk}),
            )
        });
    }
    report.push(r);
    let mut p = CheckResult::new(
        "SD-L219(positive)",
        "L219: a solution with every weight q_I > 0 exists (exact LP by Fourier–Motzkin)",
    );
    p.examined = inv as u64;
    p.note = format!("{:?}", solved.positive);
    match &solved.positive {
        Positive::Infeasible { .. } => {
            p.mark_warning();
            p.offend(|| {
                Witness::new(
                    "Fourier–Motzkin derives 0 ≥ r > 0 from A q = 0, q ≥ 1: no positive weights make N C¹ on the edges in scope",
                    json!({"positive": "infeasible"}),
                )
            });
        }
        Positive::Undecided { inequalities } => {
            p.skip(format!(
                "Fourier–Motzkin exceeded {inequalities} inequalities (budget {max_inequalities})"
            ));
        }
        _ => {}
    }
    report.push(p);
    if eqs == 0 {
        for r in report.iter_mut() {
            r.skip("no interior edge in scope: no equation");
        }
    }
    let solution = solved
        .weights
        .as_ref()
        .map(|w| with_weights(spec, &system, w));
    if let Some(s) = &solution {
        let cm2 = s.build(k, path)?;
        report.extend(verify(k, &cm2, fv, c, scope));
    }
    Ok(C1Run {
        report,
        system,
        solved,
        solution,
    })
}
