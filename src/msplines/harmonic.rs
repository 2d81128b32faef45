//! Sec. 5.2 step (3): the harmonic representative h = τ + df of each cohomology class, with the
//! cotangent Laplacian (the paper's "heat flow" converges to the same minimiser of the Dirichlet
//! energy; we solve the linear system directly).
//!
//! L f = b with L_ii = Σ_j w_ij, L_ij = −w_ij, b_i = Σ_j w_ij τ[i, j] and
//! w_ij = ½(cot α_ij + cot β_ij); L is the P1 stiffness matrix (positive semi-definite, kernel
//! the constants), so pinning f at one vertex leaves it positive definite. One sparse Cholesky
//! factorisation (faer, AMD ordering) serves all 2g right-hand sides; one step of iterative
//! refinement brings the componentwise backward error to the order of ε.

use super::cochain::{face_halfedges, EdgeIndex};
use super::error::MsError;
use super::homology::file_name;
use crate::mesh::{SimplicialSurface, VertexId};
use crate::report::{CheckResult, Witness};
use faer::sparse::linalg::solvers::SpSolver;
use faer::sparse::SparseColMat;
use faer::{Mat, Side};
use serde_json::json;

/// Cotangent weights per edge, w_e = ½ Σ cot of the angles opposite e.
pub fn cotan_weights(k: &SimplicialSurface, ei: &EdgeIndex) -> Result<Vec<f64>, MsError> {
    let mut w = vec![0.0; ei.len()];
    for f in k.faces() {
        let hs = face_halfedges(f);
        for (c, &h) in hs.iter().enumerate() {
            // The angle at the corner opposite h is at the origin of hs[c+2] (= dest of hs[c+1]).
            let apex = k.origin(hs[(c + 2) % 3]);
            let (a, b) = (k.position(k.origin(h)), k.position(k.dest(h)));
            let o = k.position(apex);
            let u = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
            let v = [b[0] - o[0], b[1] - o[1], b[2] - o[2]];
            let dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
            let cr = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let cot = dot / (cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]).sqrt();
            if !cot.is_finite() {
                return Err(MsError::NonFiniteWeight {
                    file: file_name(k),
                    face: f.0,
                });
            }
            w[ei.edge(h).0 as usize] += 0.5 * cot;
        }
    }
    Ok(w)
}

/// The harmonic 1-forms h_k = τ_k + df_k and what the solve measured.
#[derive(Debug, Clone)]
pub struct Harmonic {
    /// h_k per edge (canonical orientation).
    pub forms: Vec<Vec<f64>>,
    /// The cotangent weights used.
    pub weights: Vec<f64>,
    /// Worst componentwise backward error |b − Lf|_i / (|L||f| + |b|)_i over all k, i.
    pub backward_error: f64,
}

/// Solve for the harmonic representatives of the integer cocycles `taus`.
pub fn harmonic_forms(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    taus: &[Vec<i64>],
) -> Result<Harmonic, MsError> {
    let w = cotan_weights(k, ei)?;
    let verts: Vec<VertexId> = k.vertices().collect();
    let mut row = vec![usize::MAX; k.vertex_slots()];
    // The first vertex is pinned (f = 0): the others are the unknowns.
    for (r, v) in verts.iter().skip(1).enumerate() {
        row[v.idx()] = r;
    }
    let n = verts.len().saturating_sub(1);
    let mut diag = vec![0.0; n];
    let mut trip: Vec<(usize, usize, f64)> = Vec::with_capacity(ei.len() + n);
    // `w` has one weight per edge of `ei`.
    for (e, &we) in w.iter().enumerate() {
        let h = ei.canonical(super::cochain::EdgeIdx(e as u32));
        let (a, b) = (row[k.origin(h).idx()], row[k.dest(h).idx()]);
        if a != usize::MAX {
            diag[a] += we;
        }
        if b != usize::MAX {
            diag[b] += we;
        }
        if a != usize::MAX && b != usize::MAX {
            trip.push((a.max(b), a.min(b), -we));
        }
    }
    trip.extend(diag.iter().enumerate().map(|(i, &d)| (i, i, d)));
    let file = file_name(k);
    let fact = |reason: String| MsError::Factorisation {
        file: file.clone(),
        reason,
    };
    let mat = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &trip)
        .map_err(|e| fact(format!("{e:?}")))?;
    let chol = mat
        .sp_cholesky(Side::Lower)
        .map_err(|e| fact(format!("{e:?}")))?;
    let m = taus.len();
    // b_i = Σ_j w_ij τ[i, j], accumulated over edges.
    let rhs_of = |tau: &dyn Fn(usize) -> f64| {
        let mut b = vec![0.0; n];
        for (e, &we) in w.iter().enumerate() {
            let h = ei.canonical(super::cochain::EdgeIdx(e as u32));
            let t = we * tau(e);
            let (a, c) = (row[k.origin(h).idx()], row[k.dest(h).idx()]);
            if a != usize::MAX {
                b[a] += t;
            }
            if c != usize::MAX {
                b[c] -= t;
            }
        }
        b
    };
    let mut rhs = Mat::<f64>::zeros(n, m);
    let bs: Vec<Vec<f64>> = taus.iter().map(|t| rhs_of(&|e| t[e] as f64)).collect();
    for (c, b) in bs.iter().enumerate() {
        for (i, &x) in b.iter().enumerate() {
            rhs.write(i, c, x);
        }
    }
    let mut sol = rhs.clone();
    chol.solve_in_place(sol.as_mut());
    // Residual r = b − L f and the componentwise scale |L||f| + |b|.
    let residual = |sol: &Mat<f64>, c: usize| {
        let mut r = bs[c].clone();
        let mut s: Vec<f64> = bs[c].iter().map(|x| x.abs()).collect();
        let f = |i: usize| if i == usize::MAX { 0.0 } else { sol.read(i, c) };
        for (e, &we) in w.iter().enumerate() {
            let h = ei.canonical(super::cochain::EdgeIdx(e as u32));
            let (a, b) = (row[k.origin(h).idx()], row[k.dest(h).idx()]);
            let d = we * (f(a) - f(b));
            let ad = we.abs() * (f(a).abs() + f(b).abs());
            if a != usize::MAX {
                r[a] -= d;
                s[a] += ad;
            }
            if b != usize::MAX {
                r[b] += d;
                s[b] += ad;
            }
        }
        (r, s)
    };
    let mut corr = Mat::<f64>::zeros(n, m);
    for c in 0..m {
        let (r, _) = residual(&sol, c);
        for (i, x) in r.into_iter().enumerate() {
            corr.write(i, c, x);
        }
    }
    chol.solve_in_place(corr.as_mut());
    sol += &corr;
    let mut backward_error: f64 = 0.0;
    for c in 0..m {
        let (r, s) = residual(&sol, c);
        for (ri, si) in r.iter().zip(&s) {
            let be = if *si > 0.0 { ri.abs() / si } else { ri.abs() };
            backward_error = backward_error.max(if be.is_nan() { f64::INFINITY } else { be });
        }
    }
    let forms = taus
        .iter()
        .enumerate()
        .map(|(c, tau)| {
            let f = |v: VertexId| {
                let i = row[v.idx()];
                if i == usize::MAX {
                    0.0
                } else {
                    sol.read(i, c)
                }
            };
            (0..ei.len())
                .map(|e| {
                    let h = ei.canonical(super::cochain::EdgeIdx(e as u32));
                    tau[e] as f64 + f(k.dest(h)) - f(k.origin(h))
                })
                .collect()
        })
        .collect();
    Ok(Harmonic {
        forms,
        weights: w,
        backward_error,
    })
}

/// Tolerance of the componentwise backward error: 64·ε·(d_max + 1), d_max the largest vertex
/// degree (the number of terms in one row of L f).
pub fn backward_tolerance(k: &SimplicialSurface) -> f64 {
    let dmax = k.vertices().map(|v| k.degree(v)).max().unwrap_or(0) as f64;
    64.0 * f64::EPSILON * (dmax + 1.0)
}

/// MS-D-harm: the solve's componentwise backward error (harmonicity residual, δh = 0 at
/// every vertex up to rounding) is within its tolerance.
pub fn check_harmonic_residual(k: &SimplicialSurface, h: &Harmonic) -> CheckResult {
    let mut r = CheckResult::new(
        "MS-5.2(3)",
        "harmonic: Lf = b solved (componentwise backward error)",
    );
    let tol = backward_tolerance(k);
    r.examined = (h.forms.len() * k.num_vertices()) as u64;
    r.worst_deviation = Some(h.backward_error);
    r.tolerance = Some(tol);
    if !(h.backward_error <= tol) {
        r.offend(|| {
            Witness::new(
                format!("backward error {:.3e} > {tol:.3e}", h.backward_error),
                json!({"backward_error": h.backward_error}),
            )
        });
    }
    r.with_note("sparse Cholesky (faer, AMD) + one refinement step; tol = 64·ε·(max degree + 1)")
}

/// Face closure of real 1-forms up to rounding. `mags[k][e]` bounds the magnitudes the value of
/// form k on edge e was computed from (|τ| for h = τ + df, Σ|λ||h| for a combination), so the
/// per-face tolerance 64·ε·Σ(|ω| + mag) covers the rounding of the computation.
pub fn check_closed(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    forms: &[Vec<f64>],
    mags: &[Vec<f64>],
    id: &str,
    what: &str,
) -> CheckResult {
    let mut r = CheckResult::new(id, format!("{what} closed: face sums 0 up to rounding"));
    let mut worst: f64 = 0.0;
    let mut worst_tol: f64 = 0.0;
    for (idx, form) in forms.iter().enumerate() {
        for f in k.faces() {
            r.examined += 1;
            let hs = face_halfedges(f);
            let vals = hs.map(|h| ei.eval(form, h));
            let mag: f64 = hs
                .iter()
                .map(|&h| {
                    mags.get(idx)
                        .and_then(|m| m.get(ei.edge(h).0 as usize))
                        .copied()
                        .unwrap_or(0.0)
                })
                .sum();
            let s = vals[0] + vals[1] + vals[2];
            let tol = 64.0 * f64::EPSILON * (vals[0].abs() + vals[1].abs() + vals[2].abs() + mag);
            if s.abs() > worst || s.is_nan() {
                worst = s.abs();
                worst_tol = tol;
            }
            if !(s.abs() <= tol) {
                r.offend(|| {
                    Witness::new(
                        format!("form {idx}: face {f} sums to {s:.3e} > {tol:.3e}"),
                        json!({"form": idx, "face": f.0, "sum": s, "tol": tol}),
                    )
                });
            }
        }
    }
    r.worst_deviation = Some(worst);
    r.tolerance = Some(worst_tol);
    r.with_note("per face: |ω01+ω12+ω20| ≤ 64·ε·Σ(|ω| + input magnitude); tolerance shown is the worst face's")
}
