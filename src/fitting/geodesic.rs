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
//! first, [`super::route`]) and a point used by a traced path is blocked for the later ones, so
//! two curves meet only at common end points (`AF-geodesic-disjoint`, checked independently);
//! an edge walled off by earlier curves is traced through them and they are traced again
//! (rip-up, [`super::route`]). Where the region holds no free path, the faces around a and b
//! are allowed too, then all of S_T (counted in [`EmbedStats`]); a topology these fallbacks
//! get wrong is caught by `AF-curved-disk`.
//!
//! **Step 2, shortening** ([`super::shorten`], [`super::straighten`]): edge nodes and vertex
//! nodes move by distinct rules, runs of edge nodes are straightened in their unfolded sleeve,
//! without crossing another curve.

use crate::mesh::{FaceId, HalfedgeId, SimplicialSurface, VertexId};
use serde::Serialize;
use std::cell::RefCell;
use std::collections::{BinaryHeap, HashMap, VecDeque};
use std::ops::Deref;

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
        self.face_set(k).to_vec()
    }
    /// [`Node::faces`] without allocating (the routing asks it millions of times).
    pub fn face_set<'k>(&self, k: &'k SimplicialSurface) -> NodeFaces<'k> {
        match *self {
            Node::Vertex(v) if (v as usize) < k.vertex_slots() => {
                NodeFaces::Star(k.faces_around(VertexId(v)))
            }
            Node::Edge { a, b, t } if t > 0.0 && t < 1.0 && a < b => {
                match k.halfedge(VertexId(a), VertexId(b)) {
                    Some(h) => NodeFaces::Pair([k.face_of(h), k.face_of(k.twin(h))]),
                    None => NodeFaces::Empty,
                }
            }
            _ => NodeFaces::Empty,
        }
    }
}

/// The triangles holding a node: a vertex's star (a slice of the mesh) or an edge node's two
/// triangles, held inline.
pub enum NodeFaces<'k> {
    /// The triangles around a vertex of S_T.
    Star(&'k [FaceId]),
    /// The two triangles of an edge of S_T.
    Pair([FaceId; 2]),
    /// Not on S_T.
    Empty,
}

impl Deref for NodeFaces<'_> {
    type Target = [FaceId];
    fn deref(&self) -> &[FaceId] {
        match self {
            NodeFaces::Star(s) => s,
            NodeFaces::Pair(p) => p,
            NodeFaces::Empty => &[],
        }
    }
}

/// The faces of S_T holding both nodes.
pub fn common_faces(k: &SimplicialSurface, p: &Node, q: &Node) -> Vec<FaceId> {
    let fq = q.face_set(k);
    p.face_set(k)
        .iter()
        .copied()
        .filter(|f| fq.contains(f))
        .collect()
}

/// The triangles of one step of the graph: two distinct points of a side share its (at most)
/// two triangles, a chord lies in one; held inline.
#[derive(Clone, Copy)]
pub(super) struct StepFaces {
    f: [FaceId; 2],
    n: u8,
}

impl StepFaces {
    fn one(f: FaceId) -> Self {
        StepFaces { f: [f, f], n: 1 }
    }
    /// The common triangles of two distinct points on one side, in p's order (as
    /// [`common_faces`]).
    fn common(k: &SimplicialSurface, p: &Node, q: &Node) -> Self {
        let fq = q.face_set(k);
        let mut out = StepFaces {
            f: [FaceId(0); 2],
            n: 0,
        };
        for &f in p.face_set(k).iter().filter(|f| fq.contains(f)) {
            // Two distinct points of one edge of S_T share at most its two triangles.
            if (out.n as usize) < 2 {
                out.f[out.n as usize] = f;
                out.n += 1;
            }
        }
        out
    }
}

impl Deref for StepFaces {
    type Target = [FaceId];
    fn deref(&self) -> &[FaceId] {
        &self.f[..self.n as usize]
    }
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
    /// Curves taken up again because they walled off a later one ([`super::route`]).
    pub ripped: usize,
    /// Base edges that are edges of S_T, traced along them first ([`super::route`]).
    pub on_edges: usize,
    /// Times the tracing started again with an edge that had no path first
    /// ([`super::route`]).
    pub restarts: usize,
    /// Total length of the initial curves.
    pub initial_length: f64,
    /// Total length after shortening.
    pub length: f64,
    /// Node moves done by the shortening.
    pub moves: usize,
    /// Shortening sweeps.
    pub sweeps: usize,
    /// Curves kept from the previous round's embedding, neither traced nor shortened again
    /// ([`super::local`]).
    pub kept: usize,
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
        /// Every base edge with no path when the others are traced (a–b first; the walk of
        /// `unblock` changes the base mesh at each before embedding again).
        blocked: Vec<(u32, u32)>,
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
pub(super) struct Graph<'a> {
    k: &'a SimplicialSurface,
    pub(super) n: u32,
    /// The edge of each half-edge of S_T (its place in `edges`): a face's sides are found by
    /// index, where a map keyed by vertex pairs cost a hash per side of every step.
    he_edge: Vec<u32>,
    edges: Vec<(u32, u32)>,
    /// Dijkstra's work arrays, reused by every search ([`dijkstra`]).
    scratch: RefCell<Scratch>,
}

/// Distances and predecessors over all points of the graph, valid where `seen` holds the
/// current search's stamp: one allocation per graph, where a map per search cost a hash per
/// step and the page faults of a fresh allocation per curve (at 800k vertices of S_T).
struct Scratch {
    dist: Vec<f64>,
    from: Vec<u32>,
    seen: Vec<u32>,
    stamp: u32,
    heap: BinaryHeap<Item>,
}

impl Scratch {
    fn new(points: usize) -> Self {
        Scratch {
            dist: vec![0.0; points],
            from: vec![0; points],
            seen: vec![0; points],
            stamp: 0,
            heap: BinaryHeap::new(),
        }
    }
    /// The first of `n` stamps no point holds yet (`seen` cleared when the counter would wrap).
    fn fresh(&mut self, n: u32) -> u32 {
        if self.stamp > u32::MAX - n {
            self.seen.fill(0);
            self.stamp = 0;
        }
        self.stamp += n;
        self.stamp - n + 1
    }
}

impl<'a> Graph<'a> {
    pub(super) fn new(k: &'a SimplicialSurface) -> Self {
        // The edges in the order of `SimplicialSurface::edges` (half-edges ascending, origin
        // < dest), which numbers the points inside them.
        let nh = k.num_halfedges();
        let mut he_edge = vec![u32::MAX; nh];
        let mut edges = Vec::with_capacity(nh / 2);
        for h in (0..nh as u32).map(HalfedgeId) {
            let (u, w) = (k.origin(h), k.dest(h));
            if u < w {
                let i = edges.len() as u32;
                he_edge[h.idx()] = i;
                he_edge[k.twin(h).idx()] = i;
                edges.push((u.0, w.0));
            }
        }
        let mut g = Graph {
            k,
            n: k.vertex_slots() as u32,
            he_edge,
            edges,
            scratch: RefCell::new(Scratch::new(0)),
        };
        *g.scratch.get_mut() = Scratch::new(g.points());
        g
    }
    /// The number of points (vertices of S_T and points inside its edges).
    pub(super) fn points(&self) -> usize {
        self.n as usize + EDGE_POINTS as usize * self.edges.len()
    }
    /// The points of the edge of half-edge h, from its origin to its destination, ends
    /// included.
    pub(super) fn along(&self, h: HalfedgeId) -> [u32; EDGE_POINTS as usize + 2] {
        let (u, w) = (self.k.origin(h).0, self.k.dest(h).0);
        let base = self.n + EDGE_POINTS * self.he_edge[h.idx()];
        std::array::from_fn(|i| match i as u32 {
            0 => u,
            j if j == EDGE_POINTS + 1 => w,
            j if u < w => base + j - 1,
            j => base + EDGE_POINTS - j,
        })
    }
    pub(super) fn node(&self, p: u32) -> Node {
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
    pub(super) fn faces(&self, p: u32) -> NodeFaces<'a> {
        self.node(p).face_set(self.k)
    }
    /// Steps from p into `out` (cleared first): the next point and the triangles the step's
    /// segment lies on.
    fn steps(&self, p: u32, out: &mut Vec<(u32, StepFaces)>) {
        out.clear();
        for &f in self.faces(p).iter() {
            let c = self.k.face(f).map(|v| v.0);
            // Side i of f is its half-edge 3f + i, from corner i to corner i + 1.
            let sides: [_; 3] = std::array::from_fn(|i| self.along(HalfedgeId(3 * f.0 + i as u32)));
            for (i, side) in sides.iter().enumerate() {
                match side.iter().position(|&x| x == p) {
                    // p on this side: its neighbours along it.
                    Some(j) => {
                        for q in [j.wrapping_sub(1), j + 1] {
                            if let Some(&q) = side.get(q) {
                                let cf = StepFaces::common(self.k, &self.node(p), &self.node(q));
                                if !out.iter().any(|(x, _)| *x == q) {
                                    out.push((q, cf));
                                }
                            }
                        }
                    }
                    // Chords to the inner points of a side p is not on.
                    None => {
                        for &q in &side[1..side.len() - 1] {
                            out.push((q, StepFaces::one(f)));
                        }
                    }
                }
                // An inner point of side i: the chord to the opposite corner.
                if p >= self.n && side.contains(&p) {
                    out.push((c[(i + 2) % 3], StepFaces::one(f)));
                }
            }
        }
    }
}

/// Whether a path a → b exists under the same refusals as [`dijkstra`] (a point refused by
/// `point`, a step by `step`; a and b always allowed): searched from both ends in turn, so an
/// end walled in by fixed curves is found out after about twice its own small component,
/// where the search from the other end sweeps all of S_T first (1–2 s per edge at 800k
/// vertices). The steps of the graph and their refusals are symmetric (a chord and its
/// reverse lie on the same triangles and meet the same segments), so the answer is
/// [`dijkstra`]'s `is_some()`.
pub(super) fn connected(
    g: &Graph,
    a: u32,
    b: u32,
    point: impl Fn(u32) -> Option<f64>,
    step: impl Fn(u32, u32, &[FaceId]) -> Option<f64>,
) -> bool {
    let mut scratch = g.scratch.borrow_mut();
    let sa = scratch.fresh(2);
    let sb = sa + 1;
    let seen = &mut scratch.seen;
    let (ai, bi) = (a as usize, b as usize);
    if ai >= seen.len() || bi >= seen.len() {
        return false;
    }
    if a == b {
        return true;
    }
    seen[ai] = sa;
    seen[bi] = sb;
    let mut fronts = [VecDeque::from([a]), VecDeque::from([b])];
    let mut steps = Vec::new();
    loop {
        for (front, mine, theirs) in [(0, sa, sb), (1, sb, sa)] {
            let Some(u) = fronts[front].pop_front() else {
                return false;
            };
            g.steps(u, &mut steps);
            for &(w, fs) in &steps {
                let wi = w as usize;
                if seen[wi] == mine {
                    continue;
                }
                let ok = (w == a || w == b || point(w).is_some()) && step(u, w, &fs[..]).is_some();
                if !ok {
                    continue;
                }
                if seen[wi] == theirs {
                    return true;
                }
                seen[wi] = mine;
                fronts[front].push_back(w);
            }
        }
    }
}

/// Shortest path a → b in the graph: a step costs its length plus what `point` charges for
/// its end (b excepted) and `step` for itself; None refuses the point or the step.
pub(super) fn dijkstra(
    g: &Graph,
    a: u32,
    b: u32,
    point: impl Fn(u32) -> Option<f64>,
    step: impl Fn(u32, u32, &[FaceId]) -> Option<f64>,
) -> Option<Vec<u32>> {
    let mut scratch = g.scratch.borrow_mut();
    let now = scratch.fresh(1);
    let Scratch {
        dist: d,
        from,
        seen,
        heap,
        ..
    } = &mut *scratch;
    heap.clear();
    let mut steps = Vec::new();
    let (ai, bi) = (a as usize, b as usize);
    if ai >= d.len() || bi >= d.len() {
        return None;
    }
    d[ai] = 0.0;
    from[ai] = a;
    seen[ai] = now;
    heap.push(Item(0.0, a));
    while let Some(Item(du, u)) = heap.pop() {
        if u == b {
            let mut path = vec![b];
            let mut x = b;
            while x != a {
                x = from[x as usize];
                path.push(x);
            }
            path.reverse();
            return Some(path);
        }
        if seen[u as usize] == now && du > d[u as usize] {
            continue;
        }
        let pu = g.point(u);
        g.steps(u, &mut steps);
        for &(w, fs) in &steps {
            let pc = if w == b { Some(0.0) } else { point(w) };
            let (Some(pc), Some(sc)) = (pc, step(u, w, &fs[..])) else {
                continue;
            };
            let nd = du + dist(pu, g.point(w)) + pc + sc;
            let wi = w as usize;
            if seen[wi] != now || nd < d[wi] {
                d[wi] = nd;
                from[wi] = u;
                seen[wi] = now;
                heap.push(Item(nd, w));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::generate;
    use crate::mesh::validate::validate;
    use std::collections::HashSet;

    /// [`connected`] answers as [`dijkstra`]`(..).is_some()` does (the shortcut must never
    /// refuse a path the search would find, nor pass a walled-in end): on the 12 × 6 torus
    /// with the link of vertex 0 closed (a wall around its star) and with seeded random
    /// closures, for every pair of a fixed set of points. Both answers occur, so neither
    /// side of the comparison is vacuous.
    #[test]
    fn connected_agrees_with_dijkstra_on_walled_and_random_closures() {
        let Some(k) = validate(&generate::torus(12, 6)).surface else {
            panic!("the torus is a simplicial surface");
        };
        let g = Graph::new(&k);
        let mut wall: HashSet<u32> = HashSet::new();
        for &f in k.faces_around(VertexId(0)) {
            for i in 0..3 {
                let h = HalfedgeId(3 * f.0 + i);
                if k.origin(h).0 != 0 && k.dest(h).0 != 0 {
                    wall.extend(g.along(h));
                }
            }
        }
        let spoke = g.along(k.outgoing(VertexId(0))[0])[2];
        let ends: Vec<u32> = [0, spoke, 20, 41, 57]
            .into_iter()
            .chain((0..6).map(|i| g.n + 7 * i + 1))
            .collect();
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut closures = vec![wall];
        for _ in 0..6 {
            closures.push(
                (0..g.points() as u32)
                    .filter(|_| {
                        seed = seed
                            .wrapping_mul(6_364_136_223_846_793_005)
                            .wrapping_add(1_442_695_040_888_963_407);
                        (seed >> 33) % 5 < 2
                    })
                    .collect(),
            );
        }
        let (mut yes, mut no) = (0, 0);
        for closed in &closures {
            let point = |p: u32| (!closed.contains(&p)).then_some(0.0);
            let step = |_: u32, _: u32, _: &[FaceId]| Some(0.0);
            for &a in &ends {
                for &b in &ends {
                    let d = dijkstra(&g, a, b, point, step).is_some();
                    assert_eq!(connected(&g, a, b, point, step), d, "{a} → {b}");
                    if d {
                        yes += 1;
                    } else {
                        no += 1;
                    }
                }
            }
        }
        assert!(yes > 0 && no > 0, "{yes} connected, {no} not");
        // The wall holds: vertex 0 reaches the spoke's point, not vertex 20.
        let point = |p: u32| (!closures[0].contains(&p)).then_some(0.0);
        let step = |_: u32, _: u32, _: &[FaceId]| Some(0.0);
        assert!(connected(&g, 0, spoke, point, step));
        assert!(!connected(&g, 0, 20, point, step));
    }
}
