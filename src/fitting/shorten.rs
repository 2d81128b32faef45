//! Step 2 of the tutorial's two-step geodesic algorithm (seed 002, Part II, "Discrete
//! Geodesics": "iteratively modify the position of each curve vertex … distinct behavior for
//! edge nodes and vertex nodes"). SPEC `AF-geodesic-shortest`.
//!
//! * An **edge node** X on the edge a–b of S_T, between nodes P and N: the two triangles of
//!   the edge are unfolded into the plane (a at 0, b on +x, one third corner above, the other
//!   below), and X moves to where the segment P–N crosses a–b, clamped to [a, b] (at an end
//!   it becomes a vertex node). When P and N lie on one triangle, X is dropped (P–N is a
//!   segment of that triangle).
//! * A **vertex node** at v, between P and N: the fan of v is unfolded by its angles; where
//!   the angle from P to N on one side is below π, that side's unfolded wedge holds the
//!   straight segment P–N, and v is replaced by the points where it crosses the spokes of
//!   that side (edge nodes, or the spoke's far vertex where the segment passes beyond it).
//!
//! A move is made only when it gains more than the rounding bound of its gain
//! ([`gain_bound`]) and
//! the new segments meet no other curve and no other segment of the same curve (decided
//! exactly, `embed_checks`), and no new vertex node is a base vertex or a node of another
//! curve: the curves stay disjoint. Sweeps repeat until no move is made or [`MAX_SWEEPS`].

use super::base::BaseMesh;
use super::disjoint::{segments_meet_other, Near};
use super::geodesic::{common_faces, dist, Embedding, Node};
use crate::mesh::{SimplicialSurface, VertexId};
use crate::numeric::vec3::{cross, dot, norm, sub};

/// Units of roundoff per operation chain in [`gain_bound`]: the gain of a move is a
/// difference of lengths computed through a node's position (a + t(b − a)), an unfolding
/// (dot, cross, norm, a division) and a planar length, each a chain of at most ~16
/// operations on quantities bounded by the points' norms and the edge lengths; 64 covers four
/// such chains (an operation count, not a proof).
pub const ROUNDING_ULPS: f64 = 64.0;

/// The rounding bound of node i's relative gain (SPEC `AF-geodesic-shortest`):
/// `ROUNDING_ULPS`·u·(‖P‖ + ‖X‖ + ‖N‖ + Λ)·m / (|PX| + |XN|), Λ the total length of the
/// edges of S_T the move unfolds (the two triangles of an edge node's edge; the spokes and
/// rim of a vertex node's fan), m = 1 for an edge node and the fan's size for a vertex node
/// (its angles are summed). NaN when a node is not on S_T. The shortening moves a node only
/// beyond it and `AF-geodesic-shortest` accepts nothing beyond it: both derived from the
/// precision, not chosen to pass.
pub fn gain_bound(k: &SimplicialSurface, nodes: &[Node], i: usize) -> f64 {
    let pts = [i.wrapping_sub(1), i, i + 1].map(|j| nodes.get(j).and_then(|q| q.point(k)));
    let (Some(p), Some(x), Some(n)) = (pts[0], pts[1], pts[2]) else {
        return f64::NAN;
    };
    let now = dist(p, x) + dist(x, n);
    let pos = |v: u32| k.position(VertexId(v));
    let tri = |f: crate::mesh::FaceId| {
        let c = k.face(f).map(|v| pos(v.0));
        dist(c[0], c[1]) + dist(c[1], c[2]) + dist(c[2], c[0])
    };
    let (lambda, m) = match nodes[i] {
        Node::Edge { .. } => (nodes[i].faces(k).into_iter().map(tri).sum::<f64>(), 1.0),
        Node::Vertex(v) => {
            let fan = k.faces_around(VertexId(v));
            (fan.iter().map(|&f| tri(f)).sum::<f64>(), fan.len() as f64)
        }
    };
    ROUNDING_ULPS * f64::EPSILON * (norm(p) + norm(x) + norm(n) + lambda) * m / now
}

/// Sweeps over all curves at most.
pub const MAX_SWEEPS: usize = 200;

type P2 = [f64; 2];

fn len2(p: P2, q: P2) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// Unfolding of the two triangles of edge a–b: planar position of a node on either.
struct Pair {
    a: u32,
    b: u32,
    l: f64,
    third: [(u32, P2); 2],
}

impl Pair {
    fn new(k: &SimplicialSurface, a: u32, b: u32) -> Option<Self> {
        let h = k.halfedge(VertexId(a), VertexId(b))?;
        let c1 = k.dest(k.next(h)).0;
        let c2 = k.dest(k.next(k.twin(h))).0;
        let p = |v: u32| k.position(VertexId(v));
        let ab = sub(p(b), p(a));
        let l = norm(ab);
        let place = |x: u32, sign: f64| {
            let ax = sub(p(x), p(a));
            [dot(ax, ab) / l, sign * norm(cross(ab, ax)) / l]
        };
        Some(Pair {
            a,
            b,
            l,
            third: [(c1, place(c1, 1.0)), (c2, place(c2, -1.0))],
        })
    }
    fn vertex(&self, v: u32, side: usize) -> Option<P2> {
        if v == self.a {
            Some([0.0, 0.0])
        } else if v == self.b {
            Some([self.l, 0.0])
        } else if v == self.third[side].0 {
            Some(self.third[side].1)
        } else {
            None
        }
    }
    /// The node's position on triangle `side`, if it lies on it.
    fn at(&self, n: &Node, side: usize) -> Option<P2> {
        match *n {
            Node::Vertex(v) => self.vertex(v, side),
            Node::Edge { a, b, t } => {
                let (p, q) = (self.vertex(a, side)?, self.vertex(b, side)?);
                Some([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])])
            }
        }
    }
}

/// The best local move of node i and its gain (absolute).
fn best_move(k: &SimplicialSurface, nodes: &[Node], i: usize) -> Option<(Vec<Node>, f64)> {
    let (p, x, n) = (
        nodes.get(i.wrapping_sub(1))?,
        nodes.get(i)?,
        nodes.get(i + 1)?,
    );
    let (pp, px, pn) = (p.point(k)?, x.point(k)?, n.point(k)?);
    let now = dist(pp, px) + dist(px, pn);
    match *x {
        Node::Edge { a, b, .. } => {
            if !common_faces(k, p, n).is_empty() {
                return Some((Vec::new(), now - dist(pp, pn)));
            }
            let pair = Pair::new(k, a, b)?;
            let (s1, s2) = if pair.at(p, 0).is_some() && pair.at(n, 1).is_some() {
                (0, 1)
            } else {
                (1, 0)
            };
            let (u, w) = (pair.at(p, s1)?, pair.at(n, s2)?);
            // Where P–N crosses the x-axis, clamped to the edge.
            let s = if u[1] == w[1] {
                0.5 * (u[0] + w[0])
            } else {
                u[0] + (w[0] - u[0]) * u[1] / (u[1] - w[1])
            };
            let s = s.clamp(0.0, pair.l);
            let t = s / pair.l;
            let new = if t <= 0.0 {
                Node::Vertex(a)
            } else if t >= 1.0 {
                Node::Vertex(b)
            } else {
                Node::Edge { a, b, t }
            };
            let xs = [s, 0.0];
            Some((vec![new], now - len2(u, xs) - len2(xs, w)))
        }
        Node::Vertex(v) => vertex_move(k, p, v, n, now),
    }
}

/// The vertex-node rule (module doc).
fn vertex_move(
    k: &SimplicialSurface,
    p: &Node,
    v: u32,
    n: &Node,
    now: f64,
) -> Option<(Vec<Node>, f64)> {
    let ring = k.link(VertexId(v));
    let m = ring.len();
    let pv = k.position(VertexId(v));
    let pos = |u: VertexId| sub(k.position(u), pv);
    let ang: Vec<f64> = (0..m)
        .map(|j| {
            let (x, y) = (pos(ring[j]), pos(ring[(j + 1) % m]));
            norm(cross(x, y)).atan2(dot(x, y))
        })
        .collect();
    let mut start = vec![0.0];
    for a in &ang {
        start.push(start[start.len() - 1] + a);
    }
    let total = start[m];
    // Polar position (angle, radius) of a node on the fan: in face j = (v, l_j, l_{j+1}).
    let polar = |q: &Node| -> Option<(f64, f64)> {
        for j in 0..m {
            let (l0, l1) = (ring[j].0, ring[(j + 1) % m].0);
            let local = |u: u32| -> Option<P2> {
                if u == v {
                    Some([0.0, 0.0])
                } else if u == l0 {
                    Some([norm(pos(ring[j])), 0.0])
                } else if u == l1 {
                    let r = norm(pos(ring[(j + 1) % m]));
                    Some([r * ang[j].cos(), r * ang[j].sin()])
                } else {
                    None
                }
            };
            let at = match *q {
                Node::Vertex(u) => local(u),
                Node::Edge { a, b, t } => match (local(a), local(b)) {
                    (Some(x), Some(y)) => {
                        Some([x[0] + t * (y[0] - x[0]), x[1] + t * (y[1] - x[1])])
                    }
                    _ => None,
                },
            };
            if let Some(z) = at {
                return Some((start[j] + z[1].atan2(z[0]), z[0].hypot(z[1])));
            }
        }
        None
    };
    let ((fp, rp), (fnn, rn)) = (polar(p)?, polar(n)?);
    let ccw = (fnn - fp).rem_euclid(total);
    let mut best: Option<(Vec<Node>, f64)> = None;
    for (from, sweep, dir) in [(fp, ccw, 1.0), (fp, total - ccw, -1.0)] {
        if !(sweep < std::f64::consts::PI) || sweep <= 0.0 {
            continue;
        }
        let straight = (rp * rp + rn * rn - 2.0 * rp * rn * sweep.cos())
            .max(0.0)
            .sqrt();
        let gain = now - straight;
        if best.as_ref().is_some_and(|b| b.1 >= gain) {
            continue;
        }
        // P at angle 0, N at angle `sweep`; spokes strictly between, in order from P.
        let (u, w) = ([rp, 0.0], [rn * sweep.cos(), rn * sweep.sin()]);
        let mut out = Vec::new();
        let mut spokes: Vec<(f64, usize)> = (0..m)
            .filter_map(|j| {
                let rel = (dir * (start[j] - from)).rem_euclid(total);
                (rel > 0.0 && rel < sweep).then_some((rel, j))
            })
            .collect();
        spokes.sort_by(|x, y| x.0.total_cmp(&y.0));
        for (rel, j) in spokes {
            let d = [rel.cos(), rel.sin()];
            // Ray ρ·d meets segment u + s(w − u): solve by 2-D cross products.
            let e = [w[0] - u[0], w[1] - u[1]];
            let den = d[0] * e[1] - d[1] * e[0];
            let rho = (u[0] * e[1] - u[1] * e[0]) / den;
            let l = ring[j].0;
            let len = norm(pos(ring[j]));
            out.push(if !(rho < len) {
                Node::Vertex(l)
            } else if v < l {
                Node::Edge {
                    a: v,
                    b: l,
                    t: (rho / len).max(f64::MIN_POSITIVE),
                }
            } else {
                Node::Edge {
                    a: l,
                    b: v,
                    t: (1.0 - rho / len).min(1.0 - f64::EPSILON),
                }
            });
        }
        best = Some((out, gain));
    }
    best
}

/// The relative gain of the best local move of node i (0 when none shortens).
pub fn relative_gain(k: &SimplicialSurface, nodes: &[Node], i: usize) -> f64 {
    let (Some(p), Some(x), Some(n)) = (
        nodes.get(i.wrapping_sub(1)).and_then(|q| q.point(k)),
        nodes.get(i).and_then(|q| q.point(k)),
        nodes.get(i + 1).and_then(|q| q.point(k)),
    ) else {
        return f64::NAN;
    };
    let now = dist(p, x) + dist(x, n);
    match best_move(k, nodes, i) {
        Some((_, g)) => (g / now).max(0.0),
        None => 0.0,
    }
}

/// Shorten every curve (module doc); the embedding's stats get the moves and sweeps.
pub fn shorten(k: &SimplicialSurface, base: &BaseMesh, emb: &mut Embedding) {
    shorten_except(k, base, emb, &[]);
}

/// [`shorten`], the curves i with `frozen[i]` left as they are (kept from the previous
/// round, `super::local`): they are obstacles to the others' moves like any curve, and are
/// not moved themselves (a kept curve converged in its own round; moving it would change the
/// curved triangles that are not re-mapped).
pub fn shorten_except(
    k: &SimplicialSurface,
    base: &BaseMesh,
    emb: &mut Embedding,
    frozen: &[bool],
) {
    let is_frozen = |ci: usize| frozen.get(ci).copied().unwrap_or(false);
    let mut owner: std::collections::HashMap<u32, usize> = Default::default();
    for (ci, c) in emb.curves.iter().enumerate() {
        for n in &c.nodes {
            if let Node::Vertex(v) = *n {
                owner.insert(v, ci);
            }
        }
    }
    let mut near: std::collections::HashMap<crate::mesh::FaceId, Vec<usize>> = Default::default();
    for (ci, c) in emb.curves.iter().enumerate() {
        for w in c.nodes.windows(2) {
            for f in common_faces(k, &w[0], &w[1]) {
                let l = near.entry(f).or_default();
                if !l.contains(&ci) {
                    l.push(ci);
                }
            }
        }
    }
    for sweep in 0..MAX_SWEEPS {
        let mut moved = 0;
        for ci in (0..emb.curves.len()).filter(|&ci| !is_frozen(ci)) {
            let mut i = 1;
            while i + 1 < emb.curves[ci].nodes.len() {
                let nodes = &emb.curves[ci].nodes;
                let Some((new, gain)) = best_move(k, nodes, i) else {
                    i += 1;
                    continue;
                };
                let now = match (
                    nodes[i - 1].point(k),
                    nodes[i].point(k),
                    nodes[i + 1].point(k),
                ) {
                    (Some(p), Some(x), Some(n)) => dist(p, x) + dist(x, n),
                    _ => f64::NAN,
                };
                let (ca, cb) = (emb.curves[ci].a, emb.curves[ci].b);
                let blocked = new.iter().any(|q| match *q {
                    Node::Vertex(u) => {
                        (base.is_base(u) && u != ca && u != cb)
                            || owner.get(&u).is_some_and(|&o| o != ci)
                    }
                    Node::Edge { .. } => false,
                });
                if !(gain > gain_bound(k, nodes, i) * now) || blocked {
                    i += 1;
                    continue;
                }
                let mut cand = nodes[..i].to_vec();
                cand.extend_from_slice(&new);
                cand.extend_from_slice(&nodes[i + 1..]);
                cand.dedup();
                let span = (i - 1, i - 1 + new.len() + 1);
                if segments_meet_other(k, emb, ci, &cand, span, &near) {
                    i += 1;
                    continue;
                }
                if let Node::Vertex(v) = emb.curves[ci].nodes[i] {
                    owner.remove(&v);
                }
                for q in &new {
                    if let Node::Vertex(u) = *q {
                        owner.insert(u, ci);
                    }
                }
                for w in cand.windows(2) {
                    for f in common_faces(k, &w[0], &w[1]) {
                        let l = near.entry(f).or_default();
                        if !l.contains(&ci) {
                            l.push(ci);
                        }
                    }
                }
                emb.curves[ci].nodes = cand;
                moved += 1;
            }
        }
        moved += drop_turns(k, emb, &mut owner, &near, frozen);
        moved += super::straighten::straighten_runs(k, base, emb, &mut owner, &mut near, frozen);
        emb.stats.moves += moved;
        emb.stats.sweeps = sweep + 1;
        if moved == 0 {
            break;
        }
    }
    emb.stats.length = emb.curves.iter().map(|c| c.length(k)).sum();
}

/// Two consecutive segments on one triangle (a turn inside it) would make a piece with its
/// three corners on one side of the base triangle, which Floater's map flattens: the node
/// between them is dropped whatever the gain, where the straight segment is clear.
fn drop_turns(
    k: &SimplicialSurface,
    emb: &mut Embedding,
    owner: &mut std::collections::HashMap<u32, usize>,
    near: &Near,
    frozen: &[bool],
) -> usize {
    let mut dropped = 0;
    for ci in (0..emb.curves.len()).filter(|&ci| !frozen.get(ci).copied().unwrap_or(false)) {
        let mut i = 1;
        while i + 1 < emb.curves[ci].nodes.len() {
            let nodes = &emb.curves[ci].nodes;
            if common_faces(k, &nodes[i - 1], &nodes[i + 1]).is_empty() {
                i += 1;
                continue;
            }
            let mut cand = nodes[..i].to_vec();
            cand.extend_from_slice(&nodes[i + 1..]);
            if segments_meet_other(k, emb, ci, &cand, (i - 1, i), near) {
                i += 1;
                continue;
            }
            if let Node::Vertex(v) = emb.curves[ci].nodes[i] {
                owner.remove(&v);
            }
            emb.curves[ci].nodes = cand;
            dropped += 1;
            i = i.saturating_sub(1).max(1);
        }
    }
    dropped
}
