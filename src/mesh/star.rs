//! Def. 3.1.5 (star and link of a vertex), Def. 4.1.3 (the canonical triangulation T_v of the
//! P-polygon P_v) and the claim of Def. 4.1.4 that s_v : st(v, K) → T_v is a simplicial
//! isomorphism (Def. 3.1.7), checked element by element.
//!
//! Simplices are vertex sets (sorted), so the comparison is combinatorial and exact.

use crate::mesh::{SimplicialSurface, VertexId};
use crate::report::{CheckResult, Witness};
use serde_json::json;
use std::collections::BTreeSet;

/// A vertex of T_v: the centre v′ or the polygon vertex v′_i.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum TVertex {
    /// The centre v′ = (0, 0).
    Centre,
    /// The polygon vertex v′_i of P_v (Def. 4.1.2), by its index i.
    Corner(u32),
}

/// The simplices of a complex, grouped by dimension (sorted vertex lists).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Complex<V: Ord> {
    /// 0-simplices.
    pub vertices: BTreeSet<V>,
    /// 1-simplices, each with its two vertices sorted.
    pub edges: BTreeSet<[V; 2]>,
    /// 2-simplices, each with its three vertices sorted.
    pub triangles: BTreeSet<[V; 3]>,
}

impl<V: Ord> Default for Complex<V> {
    fn default() -> Self {
        Self::new()
    }
}

impl<V: Ord> Complex<V> {
    /// The empty complex.
    pub fn new() -> Self {
        Complex {
            vertices: BTreeSet::new(),
            edges: BTreeSet::new(),
            triangles: BTreeSet::new(),
        }
    }
}

fn sorted2<V: Ord + Copy>(a: V, b: V) -> [V; 2] {
    if a <= b {
        [a, b]
    } else {
        [b, a]
    }
}
fn sorted3<V: Ord + Copy>(a: V, b: V, c: V) -> [V; 3] {
    let mut t = [a, b, c];
    t.sort();
    t
}

/// Def. 3.1.5: st(v, K) = every face of every simplex having v as a face — computed from the
/// definition over the triangles containing v, found from the face list (not from the
/// half-edges, so the check below compares two independent constructions).
pub fn star(k: &SimplicialSurface, v: VertexId) -> Complex<VertexId> {
    let mut c = Complex::new();
    for &f in k.faces_around(v) {
        let t = k.face(f);
        if !t.contains(&v) {
            continue;
        }
        c.triangles.insert(sorted3(t[0], t[1], t[2]));
        for i in 0..3 {
            c.vertices.insert(t[i]);
            c.edges.insert(sorted2(t[i], t[(i + 1) % 3]));
        }
    }
    c
}

/// Def. 3.1.5: lk(v, K) = the simplices of st(v, K) that share no face with v.
pub fn link(k: &SimplicialSurface, v: VertexId) -> Complex<VertexId> {
    let st = star(k, v);
    Complex {
        vertices: st.vertices.iter().copied().filter(|&x| x != v).collect(),
        edges: st
            .edges
            .iter()
            .copied()
            .filter(|e| !e.contains(&v))
            .collect(),
        triangles: BTreeSet::new(),
    }
}

/// Def. 4.1.3: T_v for a vertex of degree m — centre v′, corners v′_0..v′_{m−1}, the m
/// diagonals [v′, v′_i], the m sides [v′_i, v′_{i+1}] and the m triangles [v′, v′_i, v′_{i+1}].
pub fn canonical_triangulation(m: u32) -> Complex<TVertex> {
    let mut c = Complex::new();
    c.vertices.insert(TVertex::Centre);
    for i in 0..m {
        let a = TVertex::Corner(i);
        let b = TVertex::Corner((i + 1) % m);
        c.vertices.insert(a);
        c.edges.insert(sorted2(TVertex::Centre, a));
        c.edges.insert(sorted2(a, b));
        c.triangles.insert(sorted3(TVertex::Centre, a, b));
    }
    c
}

/// Check that a labelling `s(v, x)` (x in the link of v ↦ index of v′_i) is a simplicial
/// isomorphism st(v, K) → T_v (Def. 3.1.7 / Def. 4.1.4): bijective on vertices, and maps
/// edges onto edges and triangles onto triangles, exactly. Every vertex of K is checked.
pub fn check_star_isomorphism(
    k: &SimplicialSurface,
    s: impl Fn(VertexId, VertexId) -> Option<u32>,
) -> CheckResult {
    let mut r = CheckResult::new(
        "D4.1.4",
        "s_v is a simplicial isomorphism st(v,K) → T_v (Def. 3.1.7)",
    );
    for v in k.vertices() {
        r.examined += 1;
        let m = k.degree(v);
        let st = star(k, v);
        let t = canonical_triangulation(m);
        let map = |x: VertexId| -> Option<TVertex> {
            if x == v {
                Some(TVertex::Centre)
            } else {
                s(v, x).map(TVertex::Corner)
            }
        };
        let mut problem: Option<String> = None;
        let imgs: Option<BTreeSet<TVertex>> = st.vertices.iter().map(|&x| map(x)).collect();
        match imgs {
            None => problem = Some("some link vertex has no label".into()),
            Some(img) => {
                if img.len() != st.vertices.len() {
                    problem = Some("labels are not injective".into());
                } else if img != t.vertices {
                    problem = Some("labels do not cover v′_0..v′_{m−1}".into());
                }
            }
        }
        if problem.is_none() {
            let edges: Option<BTreeSet<[TVertex; 2]>> = st
                .edges
                .iter()
                .map(|e| Some(sorted2(map(e[0])?, map(e[1])?)))
                .collect();
            let tris: Option<BTreeSet<[TVertex; 3]>> = st
                .triangles
                .iter()
                .map(|f| Some(sorted3(map(f[0])?, map(f[1])?, map(f[2])?)))
                .collect();
            if edges.as_ref() != Some(&t.edges) {
                problem = Some("edges of st(v,K) are not mapped onto the edges of T_v".into());
            } else if tris.as_ref() != Some(&t.triangles) {
                problem =
                    Some("triangles of st(v,K) are not mapped onto the triangles of T_v".into());
            }
        }
        if let Some(p) = problem {
            r.offend(|| {
                Witness::new(
                    format!("vertex {v} (degree {m}): {p}"),
                    json!({"vertex": v, "degree": m}),
                )
            });
        }
    }
    r
}
