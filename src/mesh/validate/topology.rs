//! Global topology of a triangle list: connected components, orientability (with a consistent
//! orientation), Euler characteristic and genus per component, degree histogram.

use super::Incidence;
use crate::mesh::RawMesh;
use crate::report::{Check, CheckResult, Witness};
use serde::Serialize;
use serde_json::json;
use std::collections::BTreeMap;

/// Per-component invariants.
#[derive(Debug, Clone, Serialize, PartialEq)]
pub struct Component {
    /// Vertices in the component (those in some well-formed face).
    pub vertices: u64,
    /// Undirected edges in the component.
    pub edges: u64,
    /// Well-formed faces in the component.
    pub faces: u64,
    /// χ = V − E + F.
    pub euler_characteristic: i64,
    /// g = (2 − χ)/2 for a closed orientable surface; `None` otherwise.
    pub genus: Option<i64>,
    /// Whether the *whole* triangle list is orientable: the same value for every component,
    /// always `Some`.
    pub orientable: Option<bool>,
}

/// Result of orienting the faces consistently.
#[derive(Debug, Clone)]
pub(crate) struct Orientation {
    /// `flip[f]`: reverse face f to make the orientation consistent.
    pub flip: Vec<bool>,
    /// Whether a consistent orientation exists.
    pub orientable: bool,
}

/// Orient the active faces consistently by breadth-first search across manifold edges (edges
/// in exactly two faces). Non-orientable when some edge is forced both ways.
pub(crate) fn orient(raw: &RawMesh, inc: &Incidence) -> (Orientation, CheckResult) {
    let nf = raw.faces.len();
    let mut r = Check::new("X-orientable", "orientable, consistently oriented");
    let mut flip = vec![false; nf];
    let mut seen = vec![false; nf];
    let mut orientable = true;
    let mut queue = std::collections::VecDeque::new();
    let dir = |f: usize, a: u32, b: u32, flip: &[bool]| -> bool {
        // true when face f (after flipping) traverses a→b.
        let t = raw.faces[f];
        let fw = (0..3).any(|k| t[k] == a && t[(k + 1) % 3] == b);
        fw != flip[f]
    };
    let mut flipped = 0u64;
    for start in 0..nf {
        if seen[start] || !inc.active[start] {
            continue;
        }
        seen[start] = true;
        queue.push_back(start);
        while let Some(f) = queue.pop_front() {
            let t = raw.faces[f];
            for k in 0..3 {
                let (a, b) = (t[k], t[(k + 1) % 3]);
                let e = match inc.face_edge(f, k) {
                    Some(e) => e,
                    None => continue,
                };
                let fs = inc.faces_of_edge(e);
                if fs.len() != 2 {
                    continue;
                }
                let g = if fs[0] as usize == f { fs[1] } else { fs[0] } as usize;
                let f_ab = dir(f, a, b, &flip);
                if !seen[g] {
                    seen[g] = true;
                    // g must traverse the edge opposite to f.
                    if dir(g, a, b, &flip) == f_ab {
                        flip[g] = true;
                        flipped += 1;
                    }
                    queue.push_back(g);
                } else if dir(g, a, b, &flip) == f_ab && g != f {
                    if orientable {
                        r.offend(|| {
                            Witness::new(
                                format!(
                                    "edge [{a}, {b}] between {} and {} cannot be oriented consistently (non-orientable)",
                                    raw.describe_face(f),
                                    raw.describe_face(g)
                                ),
                                json!({"edge": [a, b], "faces": [f, g]}),
                            )
                        });
                    }
                    orientable = false;
                }
            }
        }
    }
    r.examined(inc.edges.len() as u64);
    let r = r.finish(format!(
        "{flipped} face(s) would be reversed for a consistent orientation"
    ));
    (Orientation { flip, orientable }, r)
}

/// Connected components (through shared vertices) with χ and genus.
pub(crate) fn components(
    raw: &RawMesh,
    inc: &Incidence,
    orientable: bool,
    closed: bool,
) -> Vec<Component> {
    let nv = raw.positions.len();
    let mut dsu = crate::numeric::UnionFind::new(nv);
    for (f, t) in raw.faces.iter().enumerate() {
        if inc.active[f] {
            dsu.union(t[0] as usize, t[1] as usize);
            dsu.union(t[1] as usize, t[2] as usize);
        }
    }
    let mut comp: BTreeMap<usize, Component> = BTreeMap::new();
    let blank = Component {
        vertices: 0,
        edges: 0,
        faces: 0,
        euler_characteristic: 0,
        genus: None,
        orientable: Some(orientable),
    };
    for v in 0..nv {
        if !inc.faces_of_vertex(v).is_empty() {
            let root = dsu.find(v);
            comp.entry(root).or_insert_with(|| blank.clone()).vertices += 1;
        }
    }
    for &(a, _) in &inc.edges {
        let root = dsu.find(a as usize);
        comp.entry(root).or_insert_with(|| blank.clone()).edges += 1;
    }
    for (f, t) in raw.faces.iter().enumerate() {
        if inc.active[f] {
            let root = dsu.find(t[0] as usize);
            comp.entry(root).or_insert_with(|| blank.clone()).faces += 1;
        }
    }
    comp.into_values()
        .map(|mut c| {
            c.euler_characteristic = c.vertices as i64 - c.edges as i64 + c.faces as i64;
            let chi = c.euler_characteristic;
            c.genus = if orientable && closed && chi <= 2 && (2 - chi) % 2 == 0 {
                Some((2 - chi) / 2)
            } else {
                None
            };
            c
        })
        .collect()
}

/// Degree (number of incident edges) histogram over the vertices of K.
pub(crate) fn degree_histogram(inc: &Incidence, nv: usize) -> BTreeMap<u32, u64> {
    let mut deg = vec![0u32; nv];
    for &(a, b) in &inc.edges {
        deg[a as usize] += 1;
        deg[b as usize] += 1;
    }
    let mut h = BTreeMap::new();
    for (v, &d) in deg.iter().enumerate() {
        if !inc.faces_of_vertex(v).is_empty() {
            *h.entry(d).or_insert(0) += 1;
        }
    }
    h
}
