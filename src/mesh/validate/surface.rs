//! Def. 3.1.6: a 2-complex is a simplicial surface when every edge is a face of exactly two
//! triangles and the link of every vertex is homeomorphic to S¹ (one simple cycle).

use super::error_class::ErrorClass;
use super::incidence::Incidence;
use crate::mesh::RawMesh;
use crate::report::{Check, CheckResult, Witness};
use serde_json::json;

/// Def. 3.1.6, first half: every 1-simplex is a face of precisely two 2-simplices.
/// Offenders are classified: one face = boundary, more than two = non-manifold edge.
pub fn edges_in_two_triangles(raw: &RawMesh, inc: &Incidence) -> (CheckResult, Vec<ErrorClass>) {
    let mut r = Check::new("D3.1.6(edges)", "every edge in exactly two triangles");
    r.examined(inc.edges.len() as u64);
    let mut classes = Vec::new();
    for (e, &(a, b)) in inc.edges.iter().enumerate() {
        let fs = inc.faces_of_edge(e);
        if fs.len() != 2 {
            let class = if fs.len() < 2 {
                ErrorClass::Boundary
            } else {
                ErrorClass::NonmanifoldEdge
            };
            if !classes.contains(&class) {
                classes.push(class);
            }
            r.offend(|| {
                let listed: Vec<String> = fs
                    .iter()
                    .take(4)
                    .map(|&f| raw.describe_face(f as usize))
                    .collect();
                Witness::new(
                    format!(
                        "edge [{a}, {b}] is in {} triangle(s): {}{}",
                        fs.len(),
                        listed.join(", "),
                        if fs.len() > 4 { ", ..." } else { "" }
                    ),
                    json!({"edge": [a, b], "faces": fs}),
                )
            });
        }
    }
    (r.finish(""), classes)
}

/// Shape of a vertex link (as a multigraph on the link vertices).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LinkShape {
    /// One simple cycle with at least three vertices: homeomorphic to S¹.
    Cycle,
    /// One simple path: the vertex is on the boundary.
    Path,
    /// Anything else (several components, branching, repeated edges, a 2-cycle).
    Other,
}

/// Classify the link of `v`, given the link edges (the edge opposite v in each face of v).
pub fn link_shape(v: u32, link_edges: &[(u32, u32)]) -> LinkShape {
    let mut verts: Vec<u32> = link_edges.iter().flat_map(|&(a, b)| [a, b]).collect();
    verts.sort_unstable();
    verts.dedup();
    if verts.contains(&v) || link_edges.is_empty() {
        return LinkShape::Other;
    }
    let idx = |x: u32| verts.binary_search(&x).unwrap_or(0);
    let mut deg = vec![0u32; verts.len()];
    let mut uniq: Vec<(u32, u32)> = link_edges
        .iter()
        .map(|&(a, b)| (a.min(b), a.max(b)))
        .collect();
    uniq.sort_unstable();
    uniq.dedup();
    if uniq.len() != link_edges.len() {
        return LinkShape::Other;
    }
    // Union-find over link vertices for connectivity.
    let mut sets = crate::numeric::UnionFind::new(verts.len());
    for &(a, b) in &uniq {
        let (ia, ib) = (idx(a), idx(b));
        deg[ia] += 1;
        deg[ib] += 1;
        sets.union(ia, ib);
    }
    let root = sets.find(0);
    let connected = (0..verts.len()).all(|i| sets.find(i) == root);
    if !connected {
        return LinkShape::Other;
    }
    let n = verts.len();
    if deg.iter().all(|&d| d == 2) && uniq.len() == n && n >= 3 {
        LinkShape::Cycle
    } else if deg.iter().filter(|&&d| d == 1).count() == 2
        && deg.iter().all(|&d| d == 1 || d == 2)
        && uniq.len() + 1 == n
    {
        LinkShape::Path
    } else {
        LinkShape::Other
    }
}

/// Def. 3.1.6, second half: |lk(v, K)| ≅ S¹ for every vertex v of K, i.e. the link is one
/// simple cycle (so deg v ≥ 3). A link that is one path marks a boundary vertex; anything else
/// a non-manifold vertex.
pub fn links_are_cycles(raw: &RawMesh, inc: &Incidence) -> (CheckResult, Vec<ErrorClass>) {
    let mut r = Check::new("D3.1.6(link)", "link of every vertex is one simple cycle");
    let mut classes = Vec::new();
    let mut buf = Vec::new();
    for v in 0..raw.positions.len() {
        let fs = inc.faces_of_vertex(v);
        if fs.is_empty() {
            continue; // not a vertex of K
        }
        r.examined(1);
        buf.clear();
        for &f in fs {
            if let Some(t) = raw.faces.get(f as usize) {
                let k = t.iter().position(|&x| x as usize == v).unwrap_or(0);
                buf.push((t[(k + 1) % 3], t[(k + 2) % 3]));
            }
        }
        let shape = link_shape(v as u32, &buf);
        if shape != LinkShape::Cycle {
            let class = if shape == LinkShape::Path {
                ErrorClass::Boundary
            } else {
                ErrorClass::NonmanifoldVertex
            };
            if !classes.contains(&class) {
                classes.push(class);
            }
            r.offend(|| {
                Witness::new(
                    format!(
                        "{}: link ({} edges) is {}",
                        raw.describe_vertex(v),
                        buf.len(),
                        match shape {
                            LinkShape::Path => "a path (boundary vertex)",
                            _ => "neither one cycle nor one path (non-manifold vertex)",
                        }
                    ),
                    json!({"vertex": v, "link_edges": buf.len(), "shape": format!("{shape:?}")}),
                )
            });
        }
    }
    (r.finish(""), classes)
}
