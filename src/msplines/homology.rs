//! Sec. 5.2 steps (1)–(2): a basis of H₁(M, ℤ) and the dual basis of H¹(M, ℝ) by tree–cotree.
//!
//! A spanning tree T of the vertex graph (breadth-first from the first vertex) and a spanning
//! tree C of the dual graph over the edges not in T leave exactly 2 − χ = 2g edges e_k. The
//! generator γ_k is e_k closed through T; the cocycle τ_k is 1 on e_k, 0 on T and the other
//! e_l, and on C it is fixed by peeling C from its leaves so every face sums to 0. Then
//! τ_k(γ_l) = δ_kl, and every value is an integer: the checks here are exact.

use super::cochain::{face_halfedges, EdgeIdx, EdgeIndex};
use super::error::MsError;
use crate::mesh::{FaceId, HalfedgeId, SimplicialSurface, VertexId};
use crate::report::{CheckResult, Witness};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use serde_json::json;
use std::collections::VecDeque;

/// Tree–cotree decomposition with the homology generators and the dual integer cocycles.
#[derive(Debug, Clone)]
pub struct Homology {
    /// The genus g (2g leftover edges).
    pub genus: usize,
    /// The leftover edges e_k, one per generator.
    pub leftover: Vec<EdgeIdx>,
    /// γ_k as a closed sequence of half-edges (e_k closed through T).
    pub generators: Vec<Vec<HalfedgeId>>,
    /// τ_k as integer values per edge (canonical orientation).
    pub cocycles: Vec<Vec<i64>>,
    /// The root face of the cotree (its face sum is the one not enforced by peeling).
    pub root_face: FaceId,
}

/// The name used in errors for a surface.
pub fn file_name(k: &SimplicialSurface) -> String {
    k.source()
        .map(|p| p.display().to_string())
        .unwrap_or_else(|| "<generated>".into())
}

/// Tree–cotree on a connected closed surface of genus ≥ 1 (typed refusal otherwise).
pub fn tree_cotree(k: &SimplicialSurface, ei: &EdgeIndex) -> Result<Homology, MsError> {
    let file = file_name(k);
    let verts: Vec<VertexId> = k.vertices().collect();
    let Some(&root) = verts.first() else {
        return Err(MsError::Disconnected {
            file,
            components: 0,
        });
    };
    // Primal BFS tree: parent half-edge pointing *into* each vertex.
    let mut in_tree = vec![false; ei.len()];
    let mut parent: Vec<Option<HalfedgeId>> = vec![None; k.vertex_slots()];
    let mut seen = vec![false; k.vertex_slots()];
    let mut order = Vec::with_capacity(verts.len());
    let mut q = VecDeque::from([root]);
    seen[root.idx()] = true;
    while let Some(v) = q.pop_front() {
        order.push(v);
        for &h in k.outgoing(v) {
            let w = k.dest(h);
            if !seen[w.idx()] {
                seen[w.idx()] = true;
                parent[w.idx()] = Some(h);
                in_tree[ei.edge(h).0 as usize] = true;
                q.push_back(w);
            }
        }
    }
    if order.len() != verts.len() {
        let comps = count_components(k);
        return Err(MsError::Disconnected {
            file,
            components: comps,
        });
    }
    let chi = verts.len() as i64 - ei.len() as i64 + k.num_faces() as i64;
    let genus = (2 - chi) / 2;
    if genus <= 0 {
        return Err(MsError::GenusZero { file });
    }
    // Dual BFS tree over edges not in T.
    let nf = k.num_faces();
    let mut in_cotree = vec![false; ei.len()];
    let mut fparent: Vec<Option<HalfedgeId>> = vec![None; nf];
    let mut fseen = vec![false; nf];
    let mut forder = Vec::with_capacity(nf);
    let root_face = FaceId(0);
    fseen[0] = true;
    let mut fq = VecDeque::from([root_face]);
    while let Some(f) = fq.pop_front() {
        forder.push(f);
        for h in face_halfedges(f) {
            let e = ei.edge(h).0 as usize;
            if in_tree[e] {
                continue;
            }
            let g = k.face_of(k.twin(h));
            if !fseen[g.idx()] {
                fseen[g.idx()] = true;
                // The half-edge of g across which g hangs from its parent.
                fparent[g.idx()] = Some(k.twin(h));
                in_cotree[e] = true;
                fq.push_back(g);
            }
        }
    }
    let leftover: Vec<EdgeIdx> = (0..ei.len())
        .filter(|&e| !in_tree[e] && !in_cotree[e])
        .map(|e| EdgeIdx(e as u32))
        .collect();
    // Generators: root → a (tree), a → b (e_k), b → root (tree).
    let path_to_root = |mut v: VertexId| {
        let mut p = Vec::new();
        while let Some(h) = parent[v.idx()] {
            p.push(k.twin(h));
            v = k.origin(h);
        }
        p
    };
    let generators = leftover
        .iter()
        .map(|&e| {
            let h = ei.canonical(e);
            let mut up: Vec<HalfedgeId> = path_to_root(k.origin(h))
                .into_iter()
                .rev()
                .map(|x| k.twin(x))
                .collect();
            up.push(h);
            up.extend(path_to_root(k.dest(h)));
            up
        })
        .collect();
    let cocycles = leftover
        .iter()
        .map(|&e| {
            let mut tau = vec![0i64; ei.len()];
            tau[e.0 as usize] = 1;
            for &f in forder.iter().skip(1).rev() {
                let Some(hp) = fparent[f.idx()] else { continue };
                let rest: i64 = face_halfedges(f)
                    .into_iter()
                    .filter(|&h| h != hp)
                    .map(|h| ei.eval_int(&tau, h))
                    .sum();
                tau[ei.edge(hp).0 as usize] = -ei.isign(hp) * rest;
            }
            tau
        })
        .collect();
    Ok(Homology {
        genus: genus as usize,
        leftover,
        generators,
        cocycles,
        root_face,
    })
}

fn count_components(k: &SimplicialSurface) -> usize {
    let mut seen = vec![false; k.vertex_slots()];
    let mut n = 0;
    for v in k.vertices() {
        if seen[v.idx()] {
            continue;
        }
        n += 1;
        let mut st = vec![v];
        seen[v.idx()] = true;
        while let Some(u) = st.pop() {
            for &h in k.outgoing(u) {
                let w = k.dest(h);
                if !seen[w.idx()] {
                    seen[w.idx()] = true;
                    st.push(w);
                }
            }
        }
    }
    n
}

/// MS-H1 (Sec. 6.1, face condition ω\[v0,v1\]+ω\[v1,v2\]+ω\[v2,v0\] = 0): every τ_k is closed,
/// decided exactly (integer values).
pub fn check_cocycles_closed(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    forms: &[Vec<i64>],
) -> CheckResult {
    let mut r = CheckResult::new("MS-H1", "cocycles τ_k closed (face sums 0, exact integers)");
    for (idx, tau) in forms.iter().enumerate() {
        for f in k.faces() {
            r.examined += 1;
            let s: i64 = face_halfedges(f).iter().map(|&h| ei.eval_int(tau, h)).sum();
            if s != 0 {
                r.offend(|| {
                    Witness::new(
                        format!("τ_{idx}: face {f} sums to {s}"),
                        json!({"form": idx, "face": f.0, "sum": s}),
                    )
                });
            }
        }
    }
    r.with_note("exact integer arithmetic")
}

/// MS-H2: the period matrix τ_k(γ_l) is the identity (so the 2g classes are independent and
/// dual to the generators: rank 2g), decided exactly.
pub fn check_periods(h: &Homology, ei: &EdgeIndex) -> CheckResult {
    let mut r = CheckResult::new("MS-H2", "τ_k(γ_l) = δ_kl: 2g independent classes (exact)");
    for (kk, tau) in h.cocycles.iter().enumerate() {
        for (l, gamma) in h.generators.iter().enumerate() {
            r.examined += 1;
            let p: i64 = gamma.iter().map(|&x| ei.eval_int(tau, x)).sum();
            let want = i64::from(kk == l);
            if p != want {
                r.offend(|| {
                    Witness::new(
                        format!("τ_{kk}(γ_{l}) = {p}, expected {want}"),
                        json!({"k": kk, "l": l, "period": p}),
                    )
                });
            }
        }
    }
    r.with_note(format!("2g = {} generators; exact", h.generators.len()))
}

/// The intersection (cup-product) matrix ∫ τ_k ∧ τ_l = Σ_f ½(τ_k\[01\]τ_l\[12\] − τ_k\[12\]τ_l\[01\])
/// of closed integer cochains, times two (so it stays an integer).
pub fn intersection_matrix_doubled(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    forms: &[Vec<i64>],
) -> Vec<Vec<i128>> {
    let n = forms.len();
    let mut m = vec![vec![0i128; n]; n];
    for f in k.faces() {
        let [h01, h12, _] = face_halfedges(f);
        let vals: Vec<(i128, i128)> = forms
            .iter()
            .map(|t| (ei.eval_int(t, h01) as i128, ei.eval_int(t, h12) as i128))
            .collect();
        for a in 0..n {
            if vals[a] == (0, 0) {
                continue;
            }
            for b in 0..n {
                m[a][b] += vals[a].0 * vals[b].1 - vals[a].1 * vals[b].0;
            }
        }
    }
    m
}

/// MS-H3: the intersection matrix of the cocycle basis is an integer, skew-symmetric,
/// unimodular matrix (Poincaré duality), decided exactly (rational Gaussian elimination).
pub fn check_intersection(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    forms: &[Vec<i64>],
) -> (CheckResult, Vec<Vec<i64>>) {
    let mut r = CheckResult::new("MS-H3", "intersection matrix integer, skew, det ±1 (exact)");
    let m2 = intersection_matrix_doubled(k, ei, forms);
    let n = m2.len();
    let mut m = vec![vec![0i64; n]; n];
    for a in 0..n {
        for b in 0..n {
            r.examined += 1;
            let v = m2[a][b];
            if v % 2 != 0 {
                r.offend(|| {
                    Witness::new(
                        format!("entry ({a},{b}) = {v}/2 not an integer"),
                        json!({"a": a, "b": b, "twice": v as i64}),
                    )
                });
            }
            m[a][b] = (v / 2) as i64;
            if m2[a][b] != -m2[b][a] {
                r.offend(|| {
                    Witness::new(
                        format!("entry ({a},{b}) ≠ −({b},{a})"),
                        json!({"a": a, "b": b}),
                    )
                });
            }
        }
    }
    let det = determinant(&m);
    if det.abs() != BigRational::one() {
        r.offend(|| {
            Witness::new(
                format!("det = {det}, not ±1"),
                json!({"det": det.to_string()}),
            )
        });
    }
    (r.with_note(format!("{n}×{n}, det = {det}")), m)
}

/// Exact determinant by rational Gaussian elimination.
pub fn determinant(m: &[Vec<i64>]) -> BigRational {
    let n = m.len();
    let mut a: Vec<Vec<BigRational>> = m
        .iter()
        .map(|row| {
            row.iter()
                .map(|&x| BigRational::from_integer(BigInt::from(x)))
                .collect()
        })
        .collect();
    let mut det = BigRational::one();
    for c in 0..n {
        let Some(p) = (c..n).find(|&r| !a[r][c].is_zero()) else {
            return BigRational::zero();
        };
        if p != c {
            a.swap(p, c);
            det = -det;
        }
        det *= a[c][c].clone();
        for r in c + 1..n {
            if a[r][c].is_zero() {
                continue;
            }
            let f = &a[r][c] / &a[c][c];
            // Rows r > c and c are distinct: split to borrow both.
            let (top, bottom) = a.split_at_mut(r);
            for (arc, acc) in bottom[0][c..n].iter_mut().zip(&top[c][c..n]) {
                let d = &f * acc;
                *arc -= d;
            }
        }
    }
    det
}
