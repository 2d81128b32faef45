//! Step 1 of the embedding (module doc of [`super::geodesic`]): the initial curves, traced
//! one after another in the graph of the vertices of S_T and the points inside its edges,
//! each closing its points and segments to the later ones. SPEC `AF-embedding`.
//!
//! **Rip-up (a choice; the slides' AC·CB rule, [`super::unblock`], is for an edge with no
//! path even so).** Greedy tracing can wall an edge off: curves traced before it close
//! every path between its end points in the region it is allowed. Then the edge is traced
//! once more with the earlier curves made passable at a price (each point of another curve
//! on the path, and each step meeting another curve's
//! segment, costs [`PENALTY`] diagonals of S_T, times one plus the number of times that curve
//! was taken up already); the curves it passes are taken up, the edge is kept, and they are
//! traced again right after it (in the order of the base edges). A curve is taken up at most
//! [`RIP_ROUNDS`] times, then fixed; the take-ups in all are at most the number of base
//! edges; an edge taken up twice goes wider before passing curves in its region again. An
//! edge that cannot be traced in its region (not even through other curves) is put back at
//! the end of the queue once, so it goes around the others rather than through them. An
//! edge with no path then starts the tracing again with that edge first (at most
//! [`RESTARTS`] times; it is reported, `EmbedError::NoPath`, when it has no path even traced
//! first, and `fit_surface` then changes the base mesh there). Deterministic: the order of
//! the queue, the costs and Dijkstra's ties are fixed.
//!
//! **Base edges that are edges of S_T** are traced before all others, along that edge (the
//! shortest path on |S_T| between its ends, so already the geodesic), and are never taken
//! up: traced in the greedy order, another curve could cross such an edge, and then nothing
//! joined its ends (bunny at 10⁻³ of the diagonal, anchor).

use super::base::{BaseMesh, Param};
use super::disjoint::{local, meet, only_at};
use super::geodesic::{
    common_faces, connected, dijkstra, dist, Curve, EmbedError, EmbedStats, Embedding, Graph, Node,
};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use rustc_hash::FxHashMap;
use std::collections::{HashMap, VecDeque};

/// Times a curve may be taken up; the budget of take-ups is the number of base edges.
pub const RIP_ROUNDS: usize = 2;

/// The price of passing another curve, in diagonals of S_T's bounding box.
pub const PENALTY: f64 = 1.0;

/// Times the tracing starts again with the edge that had no path first.
pub const RESTARTS: usize = 12;

/// The owner of a point no curve uses.
const FREE: u32 = u32::MAX;

/// A segment of a traced curve in a triangle's reference frame.
type Seg = (usize, [[f64; 2]; 2]);

/// The traced curves so far.
struct Traced {
    /// Owner (base edge index) of each closed point of the graph, [`FREE`] where none: an
    /// array over all points, where a map cost a hash on every point a search looks at.
    used: Vec<u32>,
    /// Segments per triangle of S_T.
    segs: FxHashMap<FaceId, Vec<Seg>>,
    /// Path and tier of each traced base edge.
    paths: Vec<Option<(usize, Vec<u32>)>>,
    /// How often each base edge was taken up.
    ripped: Vec<usize>,
    /// Edges put back at the end of the queue.
    deferred: Vec<bool>,
    /// Base edges that are edges of S_T, traced along them and never taken up.
    fixed: Vec<bool>,
}

impl Traced {
    /// The base edge whose curve closes point p, if any.
    fn owner(&self, p: u32) -> Option<usize> {
        match self.used.get(p as usize) {
            Some(&c) if c != FREE => Some(c as usize),
            _ => None,
        }
    }
    fn close(&mut self, p: u32, e: usize) {
        if let Some(x) = self.used.get_mut(p as usize) {
            *x = e as u32;
        }
    }
    fn commit(&mut self, g: &Graph, k: &SimplicialSurface, e: usize, tier: usize, path: Vec<u32>) {
        for &p in &path[1..path.len() - 1] {
            self.close(p, e);
        }
        for w in path.windows(2) {
            let (u, v) = (g.node(w[0]), g.node(w[1]));
            for f in common_faces(k, &u, &v) {
                if let (Some(p), Some(q)) = (local(k, f, &u), local(k, f, &v)) {
                    self.segs.entry(f).or_default().push((e, [p, q]));
                }
            }
        }
        self.paths[e] = Some((tier, path));
    }
    /// Close a kept curve (`super::local`) to the curves traced after it: its inner vertex
    /// nodes, and its segments in each triangle they lie on, as [`Traced::commit`] does for
    /// a path (its edge nodes need not be points of the graph: a step is refused where it
    /// meets one of the segments, decided exactly, as for any traced curve). Its path stays
    /// empty: the curve is taken as it is, never taken up.
    fn commit_kept(&mut self, k: &SimplicialSurface, e: usize, nodes: &[Node]) {
        for n in nodes.iter().skip(1).take(nodes.len().saturating_sub(2)) {
            if let Node::Vertex(v) = *n {
                self.close(v, e);
            }
        }
        for w in nodes.windows(2) {
            for f in common_faces(k, &w[0], &w[1]) {
                if let (Some(p), Some(q)) = (local(k, f, &w[0]), local(k, f, &w[1])) {
                    self.segs.entry(f).or_default().push((e, [p, q]));
                }
            }
        }
        self.paths[e] = Some((0, Vec::new()));
        self.fixed[e] = true;
    }
    /// Undo [`Traced::commit`] of e: only the points and triangles of e's own path are
    /// visited (a take-up used to sweep every closed point and triangle of S_T).
    fn take_up(&mut self, g: &Graph, k: &SimplicialSurface, e: usize) {
        if let Some((_, path)) = self.paths[e].take() {
            for &p in &path[1..path.len() - 1] {
                if let Some(x) = self.used.get_mut(p as usize).filter(|x| **x == e as u32) {
                    *x = FREE;
                }
            }
            for w in path.windows(2) {
                for f in common_faces(k, &g.node(w[0]), &g.node(w[1])) {
                    if let Some(l) = self.segs.get_mut(&f) {
                        l.retain(|s| s.0 != e);
                    }
                }
            }
        }
        self.ripped[e] += 1;
    }
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

/// One base edge's tracing rules.
struct Edge<'a> {
    k: &'a SimplicialSurface,
    base: &'a BaseMesh,
    g: &'a Graph<'a>,
    a: u32,
    b: u32,
    /// The two base faces of the edge.
    faces: Vec<u32>,
    /// The base faces around a and b.
    around: Vec<u32>,
    /// a and b in the frames of their triangles.
    ends: Vec<(FaceId, [f64; 2])>,
}

impl<'a> Edge<'a> {
    fn new(k: &'a SimplicialSurface, base: &'a BaseMesh, g: &'a Graph<'a>, a: u32, b: u32) -> Self {
        let faces = [(a, b), (b, a)]
            .iter()
            .filter_map(|&(u, w)| base.face_of_edge(u, w))
            .collect();
        let around = [a, b]
            .iter()
            .flat_map(|&v| base.faces_around(v).iter().copied())
            .collect();
        let ends = [a, b]
            .iter()
            .flat_map(|&v| {
                k.faces_around(VertexId(v)).iter().filter_map(move |&f| {
                    Some((f, local(k, f, &super::geodesic::Node::Vertex(v))?))
                })
            })
            .collect();
        Edge {
            k,
            base,
            g,
            a,
            b,
            faces,
            around,
            ends,
        }
    }
    /// The tries: 0 strictly inside the two faces' region, reserving the triangles at other
    /// base vertices; 1 touching it, reserving; 2 touching it; 3 touching the faces around a
    /// and b; 4 all of S_T.
    fn set(&self, tier: usize) -> Option<&[u32]> {
        match tier {
            0..=2 => Some(&self.faces),
            3 => Some(&self.around),
            _ => None,
        }
    }
    /// A vertex of S_T is in a set of base faces when the simplification places it in one
    /// (a or b counts).
    fn mine(&self, v: VertexId, set: &[u32]) -> bool {
        v.0 == self.a
            || v.0 == self.b
            || matches!(self.base.params().get(v.idx()), Some(Param::Face { f, .. }) if set.contains(f))
    }
    /// A triangle is in the set when all (tier 0) or one of its corners is.
    fn tri_in(&self, f: FaceId, tier: usize) -> bool {
        let Some(set) = self.set(tier) else {
            return true;
        };
        let c = self.k.face(f);
        if tier == 0 {
            c.iter().all(|&v| self.mine(v, set))
        } else {
            c.iter().any(|&v| self.mine(v, set))
        }
    }
    /// The triangles at a base vertex are kept for that vertex's own curves (and those of
    /// curves from a or b), so no curve closes a base vertex off from its other edges.
    fn reserved(&self, f: FaceId, tier: usize) -> bool {
        let c = self.k.face(f);
        tier < 2
            && !c.iter().any(|v| v.0 == self.a || v.0 == self.b)
            && c.iter().any(|v| self.base.is_base(v.0))
    }
    /// Whether a point may be on the path at all (other curves aside).
    fn point_ok(&self, p: u32, tier: usize) -> bool {
        let g = self.g;
        if p < g.n && self.base.is_base(p) {
            return false;
        }
        let fs = g.faces(p);
        (p < g.n || !fs.iter().all(|&f| self.reserved(f, tier)))
            && fs.iter().any(|&f| self.tri_in(f, tier))
    }
    fn step_ok(&self, fs: &[FaceId], tier: usize) -> bool {
        fs.iter()
            .all(|&f| !self.reserved(f, tier) && self.tri_in(f, tier))
    }
    /// The curves whose segments the step u → w meets anywhere but at a common end; None
    /// when the step has no position in one of its triangles.
    fn crossed(&self, t: &Traced, u: u32, w: u32, fs: &[FaceId]) -> Option<Vec<usize>> {
        let (k, g) = (self.k, self.g);
        let mut out = Vec::new();
        for &f in fs {
            let (p, q) = (local(k, f, &g.node(u))?, local(k, f, &g.node(w))?);
            let s = [p, q];
            for &(c, seg) in t.segs.get(&f).map_or(&[][..], |l| l.as_slice()) {
                let at_end = self.ends.iter().any(|&(e, x)| {
                    e == f
                        && (x == p || x == q)
                        && (x == seg[0] || x == seg[1])
                        && only_at(s, seg, x)
                });
                if meet(s, seg) && !at_end && !out.contains(&c) {
                    out.push(c);
                }
            }
        }
        Some(out)
    }
    /// The shortest path at `tier`; with `price`, through other curves at that price each
    /// (module doc), else around them.
    fn trace(&self, t: &Traced, tier: usize, price: Option<f64>) -> Option<Vec<u32>> {
        // A curve taken up RIP_ROUNDS times is fixed: two edges that each need the other's
        // place cannot alternate without end.
        let cost = |c: usize| {
            price
                .filter(|_| t.ripped[c] < RIP_ROUNDS && !t.fixed[c])
                .map(|p| p * (1 + t.ripped[c]) as f64)
        };
        let point = |p| {
            if !self.point_ok(p, tier) {
                return None;
            }
            match t.owner(p) {
                Some(c) => cost(c),
                None => Some(0.0),
            }
        };
        let step = |u, w, fs: &[FaceId]| {
            if !self.step_ok(fs, tier) {
                return None;
            }
            let crossed = self.crossed(t, u, w, fs)?;
            crossed.iter().try_fold(0.0, |s, &c| Some(s + cost(c)?))
        };
        // On all of S_T, an end walled in is found out from its own side first (`connected`).
        if self.set(tier).is_none() && !connected(self.g, self.a, self.b, point, step) {
            return None;
        }
        dijkstra(self.g, self.a, self.b, point, step)
    }
    /// The curves a path passes (its points and its steps).
    fn blockers(&self, t: &Traced, path: &[u32]) -> Vec<usize> {
        let mut out: Vec<usize> = path[1..path.len() - 1]
            .iter()
            .filter_map(|&p| t.owner(p))
            .collect();
        for w in path.windows(2) {
            let fs = common_faces(self.k, &self.g.node(w[0]), &self.g.node(w[1]));
            out.extend(self.crossed(t, w[0], w[1], &fs).unwrap_or_default());
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}

/// One tracing of all base edges (module doc): the edges `first` lead the queue, then the
/// others in the order of `edges`. Err(e): base edge e has no path.
#[allow(clippy::too_many_arguments)]
fn trace_all(
    k: &SimplicialSurface,
    base: &BaseMesh,
    g: &Graph,
    edges: &[(u32, u32)],
    kept: &[Option<&Curve>],
    first: &[usize],
    collect: bool,
    stats: &mut EmbedStats,
    tick: &mut dyn FnMut(usize, usize),
) -> Result<Traced, Vec<usize>> {
    let diag = diagonal(base.positions());
    let mut t = Traced {
        used: vec![FREE; g.points()],
        segs: FxHashMap::default(),
        paths: vec![None; edges.len()],
        ripped: vec![0; edges.len()],
        deferred: vec![false; edges.len()],
        fixed: vec![false; edges.len()],
    };
    // A base edge that is an edge of S_T is its own geodesic (no path on |S_T| between its
    // ends is shorter: the triangle inequality), so it is traced first, along that edge, and
    // never taken up; every other curve then goes around it. Traced later, another curve could
    // cross it (it is short and was often in the way), and nothing but that edge joins its
    // ends inside their faces' region (anchor, bunny: the edge walled off for good).
    // Kept curves (`super::local`) are closed first, like the edges of S_T: fixed, never
    // taken up, every later curve traced around them.
    for (e, c) in kept.iter().enumerate() {
        if let Some(c) = c {
            t.commit_kept(k, e, &c.nodes);
        }
    }
    for (e, &(a, b)) in edges.iter().enumerate() {
        if kept[e].is_some() {
            continue;
        }
        if let Some(h) = k.halfedge(VertexId(a), VertexId(b)) {
            t.commit(g, k, e, 0, g.along(h).to_vec());
            t.fixed[e] = true;
        }
    }
    let mut blocked = Vec::new();
    let mut budget = edges.len();
    let mut queue: VecDeque<usize> = first.iter().copied().filter(|&e| !t.fixed[e]).collect();
    queue.extend((0..edges.len()).filter(|e| !t.fixed[*e] && !first.contains(e)));
    'edges: while let Some(e) = queue.pop_front() {
        let (a, b) = edges[e];
        let ed = Edge::new(k, base, g, a, b);
        // Around the other curves in the region, through them there, then the same wider.
        let mut found = None;
        'tries: for tiers in [0..3, 3..5] {
            // An edge that cannot be traced in its region waits until every other edge is
            // (once), so that it goes around them rather than through them.
            if tiers.start > 0 && !t.deferred[e] && !queue.is_empty() {
                t.deferred[e] = true;
                queue.push_back(e);
                continue 'edges;
            }
            for price in [None, Some(PENALTY * diag)] {
                // An edge taken up twice already goes wider before it passes curves in its
                // region again (two edges that each need the other's place would alternate).
                let wide = tiers.start > 0;
                if price.is_some() && (budget == 0 || (!wide && t.ripped[e] >= 2)) {
                    continue;
                }
                for tier in tiers.clone() {
                    if let Some(p) = ed.trace(&t, tier, price) {
                        found = Some((tier, p));
                        break 'tries;
                    }
                }
            }
        }
        // With `collect`, an edge with no path is skipped and the others traced, so that
        // one tracing names every blocked edge.
        let Some((tier, path)) = found else {
            if collect {
                blocked.push(e);
                continue;
            }
            return Err(vec![e]);
        };
        let blockers = ed.blockers(&t, &path);
        for &c in blockers.iter().rev() {
            t.take_up(g, k, c);
            queue.push_front(c);
        }
        budget = budget.saturating_sub(blockers.len());
        stats.ripped += blockers.len();
        t.commit(g, k, e, tier, path);
        tick(edges.len() - queue.len(), edges.len());
    }
    if blocked.is_empty() {
        Ok(t)
    } else {
        Err(blocked)
    }
}

/// Step 1 (module doc): the initial curves. The base edges are traced in the order of
/// [`base_edges`] (shortest first); when one has no path, the tracing starts again with that
/// edge first (before the edges promoted earlier), at most [`RESTARTS`] times.
pub fn initial_curves(k: &SimplicialSurface, base: &BaseMesh) -> Result<Embedding, EmbedError> {
    curves_keeping(k, base, &HashMap::new(), &mut |_, _| {})
}

/// [`initial_curves`] with the curves in `kept` (by base edge (a, b), a < b) taken as they
/// are (a refinement round's unchanged curves, `super::local`): closed before any other is
/// traced, never taken up; only the other base edges are traced. A kept curve whose edge is
/// no base edge is ignored. `tick(done, total)` follows each tracing (edges done of the edges
/// in the queue; a restart starts again from 0).
pub fn curves_keeping(
    k: &SimplicialSurface,
    base: &BaseMesh,
    kept: &HashMap<(u32, u32), Curve>,
    tick: &mut dyn FnMut(usize, usize),
) -> Result<Embedding, EmbedError> {
    let g = Graph::new(k);
    let edges = base_edges(base);
    let kept_of: Vec<Option<&Curve>> = edges.iter().map(|e| kept.get(e)).collect();
    let mut stats = EmbedStats::default();
    let mut first: Vec<usize> = Vec::new();
    let t = loop {
        let mut s = EmbedStats::default();
        match trace_all(k, base, &g, &edges, &kept_of, &first, false, &mut s, tick) {
            Ok(t) => {
                stats.ripped = s.ripped;
                break t;
            }
            Err(es) => {
                let e = es[0];
                if stats.restarts >= RESTARTS || first.first() == Some(&e) {
                    // The same tracing once more, past the blocked edges, to name them all.
                    let mut all =
                        trace_all(k, base, &g, &edges, &kept_of, &first, true, &mut s, tick)
                            .err()
                            .unwrap_or_default();
                    all.retain(|&x| x != e);
                    all.insert(0, e);
                    let (a, b) = edges[e];
                    return Err(EmbedError::NoPath {
                        a,
                        b,
                        blocked: all.into_iter().map(|x| edges[x]).collect(),
                    });
                }
                stats.restarts += 1;
                first.retain(|&x| x != e);
                first.insert(0, e);
            }
        }
    };
    let mut curves = Vec::new();
    let mut index = HashMap::new();
    for (e, p) in t.paths.into_iter().enumerate() {
        let (a, b) = edges[e];
        let (tier, path) = p.ok_or(EmbedError::NoPath {
            a,
            b,
            blocked: vec![(a, b)],
        })?;
        if let Some(c) = kept_of[e] {
            stats.kept += 1;
            index.insert((a, b), curves.len());
            curves.push(c.clone());
            continue;
        }
        match tier {
            0..=2 => stats.in_region += 1,
            3 => stats.widened += 1,
            _ => stats.unrestricted += 1,
        }
        if t.fixed[e] {
            stats.on_edges += 1;
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

/// The diagonal of the bounding box of the points (the price's unit).
fn diagonal(pos: &[[f64; 3]]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in pos {
        for i in 0..3 {
            lo[i] = lo[i].min(p[i]);
            hi[i] = hi[i].max(p[i]);
        }
    }
    dist(lo, hi)
}
