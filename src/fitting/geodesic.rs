//! The embedding of the base mesh S̃_T in |S_T| (seed 002, "Adaptive Manifold Fitting",
//! Part II, "Embed S̃_T in |S_T|": "each edge of S̃_T is embedded in |S_T| as a geodesic";
//! "Discrete Geodesics", the two-step algorithm). SPEC rows `AF-geodesic-…`.
//!
//! A base edge a–b (a < b; both are vertices of S_T, Part II's remark) becomes a polyline on
//! |S_T| from a to b whose nodes are *vertex nodes* (a vertex of S_T) or *edge nodes* (a point
//! inside an edge of S_T); two consecutive nodes lie on one closed triangle of S_T, so every
//! segment lies on the surface (`AF-geodesic-on-surface`).
//!
//! **Step 1, the initial curve (a choice; the slides use fast marching and back-integration).**
//! A shortest path along edges of S_T (Dijkstra, 3-D edge lengths) restricted to the vertices
//! of S_T that the simplification's parametrization (`base`) places in the two base faces of
//! the edge, plus a and b. Why: the simplification's parameters give the topology of the
//! embedding (which side of the edge each vertex of S_T is on), so a path inside the region
//! of the two faces joins a and b on the right side of the other base vertices; a
//! fast-marching distance on all of |S_T| does not know that topology and can go around a
//! handle or past another base vertex. Paths are traced one after another (shortest base edge
//! first) and a vertex used by a traced path is blocked for the later ones, so two curves meet
//! only at common end points (`AF-geodesic-disjoint`, checked independently). Where the region
//! holds no free path, the faces around a and b are allowed too, then all of S_T (counted in
//! [`EmbedStats`]); a topology these fallbacks get wrong is caught by `AF-curved-disk`.
//!
//! **Step 2, shortening** ([`super::shorten`]): edge nodes and vertex nodes move by distinct
//! rules without crossing another curve.

use super::base::{BaseMesh, Param};
use super::embed_checks::{local, meet, only_at};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use serde::Serialize;
use std::collections::{BinaryHeap, HashMap, HashSet};

/// A node of an embedded edge.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum Node {
    /// A vertex of S_T.
    Vertex(u32),
    /// The point (1 − t)·a + t·b inside the edge a–b of S_T (a < b, 0 < t < 1).
    Edge {
        /// Smaller end.
        a: u32,
        /// Larger end.
        b: u32,
        /// Position along a → b.
        t: f64,
    },
}

impl Node {
    /// The point in R³ (None for a vertex id outside S_T).
    pub fn point(&self, k: &SimplicialSurface) -> Option<[f64; 3]> {
        let p = |v: u32| ((v as usize) < k.vertex_slots()).then(|| k.position(VertexId(v)));
        match *self {
            Node::Vertex(v) => p(v),
            Node::Edge { a, b, t } => {
                let (pa, pb) = (p(a)?, p(b)?);
                Some(std::array::from_fn(|i| pa[i] + t * (pb[i] - pa[i])))
            }
        }
    }
    /// The closed triangles of S_T holding the node (empty when it is not on S_T: an edge
    /// node on a pair that is no edge, or t outside (0, 1)).
    pub fn faces(&self, k: &SimplicialSurface) -> Vec<FaceId> {
        match *self {
            Node::Vertex(v) if (v as usize) < k.vertex_slots() => {
                k.faces_around(VertexId(v)).to_vec()
            }
            Node::Edge { a, b, t } if t > 0.0 && t < 1.0 && a < b => {
                match k.halfedge(VertexId(a), VertexId(b)) {
                    Some(h) => vec![k.face_of(h), k.face_of(k.twin(h))],
                    None => Vec::new(),
                }
            }
            _ => Vec::new(),
        }
    }
}

/// The faces of S_T holding both nodes.
pub fn common_faces(k: &SimplicialSurface, p: &Node, q: &Node) -> Vec<FaceId> {
    let fq = q.faces(k);
    p.faces(k).into_iter().filter(|f| fq.contains(f)).collect()
}

/// One embedded base edge: nodes from `a` to `b` (a < b).
#[derive(Debug, Clone, Serialize)]
pub struct Curve {
    /// Smaller base vertex (fine id).
    pub a: u32,
    /// Larger base vertex (fine id).
    pub b: u32,
    /// Nodes, first `Vertex(a)`, last `Vertex(b)`.
    pub nodes: Vec<Node>,
}

impl Curve {
    /// Length in R³ (NaN when a node is not on S_T).
    pub fn length(&self, k: &SimplicialSurface) -> f64 {
        let pts: Vec<Option<[f64; 3]>> = self.nodes.iter().map(|n| n.point(k)).collect();
        pts.windows(2)
            .map(|w| match (w[0], w[1]) {
                (Some(p), Some(q)) => dist(p, q),
                _ => f64::NAN,
            })
            .sum()
    }
}

/// How the embedding was reached.
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct EmbedStats {
    /// Curves traced in the region of their two base faces.
    pub in_region: usize,
    /// Curves that needed the faces around their end points.
    pub widened: usize,
    /// Curves traced on all of S_T.
    pub unrestricted: usize,
    /// Total length of the initial curves.
    pub initial_length: f64,
    /// Total length after shortening.
    pub length: f64,
    /// Node moves done by the shortening.
    pub moves: usize,
    /// Shortening sweeps.
    pub sweeps: usize,
}

/// The embedded base mesh.
#[derive(Debug, Clone)]
pub struct Embedding {
    /// One curve per base edge.
    pub curves: Vec<Curve>,
    /// Curve of base edge (a, b), a < b.
    pub index: HashMap<(u32, u32), usize>,
    /// Counts.
    pub stats: EmbedStats,
}

impl Embedding {
    /// The curve of base edge {u, w} and whether it runs u → w.
    pub fn curve(&self, u: u32, w: u32) -> Option<(&Curve, bool)> {
        let i = *self.index.get(&(u.min(w), u.max(w)))?;
        Some((&self.curves[i], u < w))
    }
}

/// Why no embedding was found.
#[derive(Debug, Clone, thiserror::Error)]
pub enum EmbedError {
    /// No path of S_T joins the two base vertices avoiding the curves traced before.
    #[error("no path on S_T joins base vertices {a} and {b} avoiding the other embedded edges")]
    NoPath {
        /// Base vertex.
        a: u32,
        /// Base vertex.
        b: u32,
    },
}

pub(crate) fn dist(p: [f64; 3], q: [f64; 3]) -> f64 {
    crate::numeric::robust_norm(&[p[0] - q[0], p[1] - q[1], p[2] - q[2]])
}

#[derive(PartialEq)]
struct Item(f64, u32);
impl Eq for Item {}
impl PartialOrd for Item {
    fn partial_cmp(&self, o: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Item {
    fn cmp(&self, o: &Self) -> std::cmp::Ordering {
        o.0.total_cmp(&self.0).then(o.1.cmp(&self.1))
    }
}

/// Points per edge of S_T in the graph of the initial curves.
pub const EDGE_POINTS: u32 = 3;

/// The graph of the initial curves: the vertices of S_T and [`EDGE_POINTS`] points inside
/// each edge at t = j/(EDGE_POINTS + 1) (ids n + EDGE_POINTS·edge + j − 1); a step joins two
/// points of one triangle of S_T, along an edge (consecutive points of it) or through the
/// triangle (a chord). A point used by one curve is closed to the later ones, and a step
/// whose segment meets a segment of an earlier curve (exactly, in the triangle's reference
/// frame) is refused, so the curves are disjoint but for common ends.
struct Graph<'a> {
    k: &'a SimplicialSurface,
    n: u32,
    edge_id: HashMap<(u32, u32), u32>,
    edges: Vec<(u32, u32)>,
}

impl<'a> Graph<'a> {
    fn new(k: &'a SimplicialSurface) -> Self {
        let edges: Vec<(u32, u32)> = k.edges().map(|(a, b)| (a.0, b.0)).collect();
        let edge_id = edges
            .iter()
            .enumerate()
            .map(|(i, &e)| (e, i as u32))
            .collect();
        Graph {
            k,
            n: k.vertex_slots() as u32,
            edge_id,
            edges,
        }
    }
    /// The points of edge {u, w} from u to w, ends included.
    fn along(&self, u: u32, w: u32) -> Vec<u32> {
        let base = self.n + EDGE_POINTS * self.edge_id[&(u.min(w), u.max(w))];
        let mut inner: Vec<u32> = (0..EDGE_POINTS).map(|j| base + j).collect();
        if u > w {
            inner.reverse();
        }
        let mut out = vec![u];
        out.extend(inner);
        out.push(w);
        out
    }
    fn node(&self, p: u32) -> Node {
        if p < self.n {
            Node::Vertex(p)
        } else {
            let (a, b) = self.edges[((p - self.n) / EDGE_POINTS) as usize];
            let j = (p - self.n) % EDGE_POINTS + 1;
            Node::Edge {
                a,
                b,
                t: j as f64 / (EDGE_POINTS + 1) as f64,
            }
        }
    }
    fn point(&self, p: u32) -> [f64; 3] {
        self.node(p).point(self.k).unwrap_or([f64::NAN; 3])
    }
    /// The triangles a point lies on.
    fn faces(&self, p: u32) -> Vec<FaceId> {
        self.node(p).faces(self.k)
    }
    /// Steps from p: the next point and the triangles the step's segment lies on.
    fn steps(&self, p: u32) -> Vec<(u32, Vec<FaceId>)> {
        let mut out = Vec::new();
        for f in self.faces(p) {
            let c = self.k.face(f).map(|v| v.0);
            let sides: Vec<Vec<u32>> = (0..3).map(|i| self.along(c[i], c[(i + 1) % 3])).collect();
            for (i, side) in sides.iter().enumerate() {
                match side.iter().position(|&x| x == p) {
                    // p on this side: its neighbours along it.
                    Some(j) => {
                        for q in [j.wrapping_sub(1), j + 1] {
                            if let Some(&q) = side.get(q) {
                                let cf = common_faces(self.k, &self.node(p), &self.node(q));
                                if !out.iter().any(|(x, _)| *x == q) {
                                    out.push((q, cf));
                                }
                            }
                        }
                    }
                    // Chords to the inner points of a side p is not on.
                    None => {
                        for &q in &side[1..side.len() - 1] {
                            out.push((q, vec![f]));
                        }
                    }
                }
                // An inner point of side i: the chord to the opposite corner.
                if p >= self.n && side.contains(&p) {
                    out.push((c[(i + 2) % 3], vec![f]));
                }
            }
        }
        out
    }
}

/// Shortest path a → b in the graph through points and steps `ok` accepts.
fn dijkstra(
    g: &Graph,
    a: u32,
    b: u32,
    ok_point: impl Fn(u32) -> bool,
    ok_step: impl Fn(u32, u32, &[FaceId]) -> bool,
) -> Option<Vec<u32>> {
    let mut d: HashMap<u32, (f64, u32)> = HashMap::new();
    let mut heap = BinaryHeap::new();
    d.insert(a, (0.0, a));
    heap.push(Item(0.0, a));
    while let Some(Item(du, u)) = heap.pop() {
        if u == b {
            let mut path = vec![b];
            let mut x = b;
            while x != a {
                x = d[&x].1;
                path.push(x);
            }
            path.reverse();
            return Some(path);
        }
        if d.get(&u).is_some_and(|&(x, _)| du > x) {
            continue;
        }
        let pu = g.point(u);
        for (w, fs) in g.steps(u) {
            if (w != b && !ok_point(w)) || !ok_step(u, w, &fs) {
                continue;
            }
            let nd = du + dist(pu, g.point(w));
            if d.get(&w).map_or(true, |&(x, _)| nd < x) {
                d.insert(w, (nd, u));
                heap.push(Item(nd, w));
            }
        }
    }
    None
}

/// The base edges {a, b}, a < b, shortest (in R³) first.
fn base_edges(base: &BaseMesh) -> Vec<(u32, u32)> {
    let pos = base.positions();
    let mut e: Vec<(u32, u32)> = base
        .faces()
        .flat_map(|(_, c)| (0..3).map(move |i| (c[i], c[(i + 1) % 3])))
        .filter(|&(a, b)| a < b)
        .collect();
    e.sort_by(|x, y| {
        let l = |(a, b): (u32, u32)| dist(pos[a as usize], pos[b as usize]);
        l(*x).total_cmp(&l(*y)).then(x.cmp(y))
    });
    e
}

/// Step 1 (module doc): the initial curves.
pub fn initial_curves(k: &SimplicialSurface, base: &BaseMesh) -> Result<Embedding, EmbedError> {
    let g = Graph::new(k);
    let mut used: HashSet<u32> = HashSet::new();
    let mut segs: HashMap<FaceId, Vec<[[f64; 2]; 2]>> = HashMap::new();
    let region = |x: u32| match base.params().get(x as usize) {
        Some(Param::Face { f, .. }) => Some(*f),
        _ => None,
    };
    let mut stats = EmbedStats::default();
    let mut curves = Vec::new();
    let mut index = HashMap::new();
    for (a, b) in base_edges(base) {
        let faces: Vec<u32> = [(a, b), (b, a)]
            .iter()
            .filter_map(|&(u, w)| base.face_of_edge(u, w))
            .collect();
        let around: Vec<u32> = [a, b]
            .iter()
            .flat_map(|&v| base.faces_around(v).iter().copied())
            .collect();
        // A triangle of S_T is in a set of base faces when one of its corners is (a base
        // vertex of the edge counts); a point when one of its triangles is.
        let mine = |v: VertexId, set: &[u32]| {
            v.0 == a || v.0 == b || region(v.0).is_some_and(|r| set.contains(&r))
        };
        let strict = std::cell::Cell::new(true);
        let keep = std::cell::Cell::new(true);
        let tri_in = |f: FaceId, set: &[u32]| {
            let c = k.face(f);
            if strict.get() {
                c.iter().all(|&v| mine(v, set))
            } else {
                c.iter().any(|&v| mine(v, set))
            }
        };
        // The triangles at a base vertex are kept for that vertex's own curves (and those of
        // curves from a or b), so no curve closes a base vertex off from its other edges.
        let reserved = |f: FaceId| {
            let c = k.face(f);
            keep.get()
                && !c.iter().any(|v| v.0 == a || v.0 == b)
                && c.iter().any(|v| base.is_base(v.0))
        };
        let pt_in = |p: u32, set: &[u32]| g.faces(p).into_iter().any(|f| tri_in(f, set));
        let free = |p: u32| {
            let closed = used.contains(&p) || (p < g.n && base.is_base(p));
            !closed && (p < g.n || !g.faces(p).into_iter().all(reserved))
        };
        // The tries: (strictly inside the two faces' region, reserving), (touching it,
        // reserving), (touching it), (touching the faces around a and b), (all of S_T).
        let set_of = |i: usize| match i {
            0..=2 => Some(faces.as_slice()),
            3 => Some(around.as_slice()),
            _ => None,
        };

        let ends: Vec<(FaceId, [f64; 2])> = [a, b]
            .iter()
            .flat_map(|&v| {
                k.faces_around(VertexId(v))
                    .iter()
                    .filter_map(move |&f| Some((f, local(k, f, &Node::Vertex(v))?)))
            })
            .collect();
        // The step's segment meets no earlier segment but at a common end.
        let clear = |u: u32, w: u32, fs: &[FaceId]| {
            fs.iter().all(|&f| {
                let (Some(p), Some(q)) = (local(k, f, &g.node(u)), local(k, f, &g.node(w))) else {
                    return false;
                };
                let s = [p, q];
                segs.get(&f).map_or(true, |l| {
                    l.iter().all(|&t| {
                        !meet(s, t)
                            || ends.iter().any(|&(e, x)| {
                                e == f
                                    && (x == p || x == q)
                                    && (x == t[0] || x == t[1])
                                    && only_at(s, t, x)
                            })
                    })
                })
            })
        };
        let mut found = None;
        for i in 0..5 {
            let set = set_of(i);
            strict.set(i == 0);
            keep.set(i < 2);
            let p = dijkstra(
                &g,
                a,
                b,
                |p| free(p) && set.map_or(true, |s| pt_in(p, s)),
                |u, w, fs| {
                    fs.iter()
                        .all(|&f| !reserved(f) && set.map_or(true, |s| tri_in(f, s)))
                        && clear(u, w, fs)
                },
            );
            if let Some(p) = p {
                found = Some((i, p));
                break;
            }
        }
        let (i, path) = found.ok_or(EmbedError::NoPath { a, b })?;
        match i {
            0..=2 => stats.in_region += 1,
            3 => stats.widened += 1,
            _ => stats.unrestricted += 1,
        }
        used.extend(path[1..path.len() - 1].iter().copied());
        for w in path.windows(2) {
            let (u, v) = (g.node(w[0]), g.node(w[1]));
            for f in common_faces(k, &u, &v) {
                if let (Some(p), Some(q)) = (local(k, f, &u), local(k, f, &v)) {
                    segs.entry(f).or_default().push([p, q]);
                }
            }
        }
        index.insert((a, b), curves.len());
        curves.push(Curve {
            a,
            b,
            nodes: path.into_iter().map(|p| g.node(p)).collect(),
        });
    }
    let mut e = Embedding {
        curves,
        index,
        stats,
    };
    e.stats.initial_length = e.curves.iter().map(|c| c.length(k)).sum();
    e.stats.length = e.stats.initial_length;
    Ok(e)
}
