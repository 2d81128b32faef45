//! Whole-run straightening for the shortening (seed 002, Part II, "Discrete Geodesics",
//! step 2; a choice that speeds up its node-by-node rules). A run of edge nodes between two
//! anchors (vertex nodes or nodes not strictly crossing their edge) crosses a sequence of
//! edges of S_T — a sleeve of triangles. The sleeve is unfolded into the plane and the
//! shortest path in it found by the funnel algorithm (Lee–Preparata; "simple stupid funnel"):
//! straight between the sleeve's corners it wraps around. The node rules move one node at a
//! time and converge linearly along a long run (or around a vertex the curve wraps closely);
//! the funnel gives their fixed point on the sleeve in one step. Vertex nodes it creates are
//! then moved off by the vertex rule where one side's angle is below π, which changes the
//! sleeve; the shortening alternates both until nothing moves. SPEC `AF-geodesic-shortest`.

use super::base::BaseMesh;
use super::disjoint::{segments_meet_other, Near};
use super::geodesic::{common_faces, dist, Embedding, Node};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::vec3::{norm, sub};
use std::collections::HashMap;

type P2 = [f64; 2];

fn cross(o: P2, a: P2, b: P2) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// The corner of `f` that is neither u nor w.
fn third(k: &SimplicialSurface, f: FaceId, u: u32, w: u32) -> Option<u32> {
    k.face(f).iter().map(|v| v.0).find(|&v| v != u && v != w)
}

/// c placed in the plane at its 3-D distances from p and q, on the side of line p → q
/// opposite to `away`.
fn place(k: &SimplicialSurface, ids: [u32; 3], p: P2, q: P2, away: P2) -> Option<P2> {
    let x = |v: u32| k.position(VertexId(v));
    let (dp, dq) = (
        norm(sub(x(ids[2]), x(ids[0]))),
        norm(sub(x(ids[2]), x(ids[1]))),
    );
    let l = (q[0] - p[0]).hypot(q[1] - p[1]);
    if !(l > 0.0) {
        return None;
    }
    let u = [(q[0] - p[0]) / l, (q[1] - p[1]) / l];
    let along = (dp * dp - dq * dq + l * l) / (2.0 * l);
    let h = (dp * dp - along * along).max(0.0).sqrt();
    let s = if cross(p, q, away) > 0.0 { -1.0 } else { 1.0 };
    Some([
        p[0] + along * u[0] - s * h * u[1],
        p[1] + along * u[1] + s * h * u[0],
    ])
}

/// A node's planar position from the positions of its face's corners.
fn at(n: &Node, corners: &[(u32, P2)]) -> Option<P2> {
    let pos = |v: u32| corners.iter().find(|c| c.0 == v).map(|c| c.1);
    match *n {
        Node::Vertex(v) => pos(v),
        Node::Edge { a, b, t } => {
            let (p, q) = (pos(a)?, pos(b)?);
            Some([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])])
        }
    }
}

/// A portal: an edge of S_T the run crosses, its (left, right) ends as seen travelling along
/// the run, with planar positions.
type Portal = [(u32, P2); 2];

/// The unfolded sleeve of `run` (anchor, edge nodes, anchor): start, portals, end. None when
/// the run is not a strict sleeve (two nodes on one edge, a segment along an edge, a
/// triangle visited twice in a row).
fn sleeve(k: &SimplicialSurface, run: &[Node]) -> Option<(P2, Vec<Portal>, P2)> {
    let m = run.len().checked_sub(2).filter(|&m| m >= 1)?;
    let edge = |n: &Node| match *n {
        Node::Edge { a, b, .. } => Some((a, b)),
        Node::Vertex(_) => None,
    };
    // The triangle of each segment.
    let mut tri = Vec::with_capacity(m + 1);
    for w in run.windows(2) {
        let cf = common_faces(k, &w[0], &w[1]);
        if cf.len() != 1 {
            return None;
        }
        tri.push(cf[0]);
    }
    if tri.windows(2).any(|w| w[0] == w[1]) {
        return None;
    }
    let (a, b) = edge(&run[1])?;
    let (pa, pb) = (k.position(VertexId(a)), k.position(VertexId(b)));
    let mut corners: Vec<(u32, P2)> = vec![(a, [0.0, 0.0]), (b, [norm(sub(pb, pa)), 0.0])];
    let c0 = third(k, tri[0], a, b)?;
    let pc0 = place(k, [a, b, c0], corners[0].1, corners[1].1, [0.0, -1.0])?;
    corners.push((c0, pc0));
    let start = at(&run[0], &corners)?;
    let mut portals = Vec::with_capacity(m);
    for s in 1..=m {
        let (a, b) = edge(&run[s])?;
        // The corner of the triangle before the portal that is not on it.
        let behind = corners.iter().find(|x| x.0 != a && x.0 != b)?.1;
        let (pa, pb) = (
            at(&Node::Vertex(a), &corners)?,
            at(&Node::Vertex(b), &corners)?,
        );
        portals.push(if cross(behind, pa, pb) > 0.0 {
            [(b, pb), (a, pa)]
        } else {
            [(a, pa), (b, pb)]
        });
        // Unfold the triangle after the portal across it.
        let c = third(k, tri[s], a, b)?;
        let pc = place(k, [a, b, c], pa, pb, behind)?;
        corners = vec![(a, pa), (b, pb), (c, pc)];
    }
    let end = at(&run[m + 1], &corners)?;
    Some((start, portals, end))
}

/// The funnel's path: the portal indices (1-based; 0 start, n + 1 end) of its corners.
fn funnel(start: P2, portals: &[Portal], end: P2) -> Vec<(usize, Option<u32>, P2)> {
    let n = portals.len();
    let gate = |i: usize| -> [(Option<u32>, P2); 2] {
        if i == 0 {
            [(None, start), (None, start)]
        } else if i == n + 1 {
            [(None, end), (None, end)]
        } else {
            let [l, r] = portals[i - 1];
            [(Some(l.0), l.1), (Some(r.0), r.1)]
        }
    };
    let mut out = vec![(0, None, start)];
    let mut apex = start;
    let (mut left, mut li) = (start, 0);
    let (mut right, mut ri) = (start, 0);
    let mut i = 1;
    // Each restart moves the apex forward, so the loop ends (at most n + 2 restarts).
    while i <= n + 1 {
        let [(_, l), (_, r)] = gate(i);
        if cross(apex, right, r) >= 0.0 {
            if apex == right || cross(apex, left, r) < 0.0 {
                right = r;
                ri = i;
            } else {
                let id = gate(li)[0].0;
                out.push((li, id, left));
                apex = left;
                right = apex;
                ri = li;
                i = li + 1;
                continue;
            }
        }
        if cross(apex, left, l) <= 0.0 {
            if apex == left || cross(apex, right, l) > 0.0 {
                left = l;
                li = i;
            } else {
                let id = gate(ri)[1].0;
                out.push((ri, id, right));
                apex = right;
                left = apex;
                li = ri;
                i = ri + 1;
                continue;
            }
        }
        i += 1;
    }
    out.push((n + 1, None, end));
    out
}

/// The straightened run (anchors excluded): the nodes where the funnel's path crosses the
/// portals, vertex nodes at the corners it wraps. None when the run is no sleeve.
pub fn straighten_run(k: &SimplicialSurface, run: &[Node]) -> Option<Vec<Node>> {
    let (start, portals, end) = sleeve(k, run)?;
    let path = funnel(start, &portals, end);
    let mut out: Vec<Node> = Vec::new();
    for w in path.windows(2) {
        let ((i0, v0, p), (i1, v1, q)) = (w[0], w[1]);
        if let Some(v) = v0 {
            if out.last() != Some(&Node::Vertex(v)) {
                out.push(Node::Vertex(v));
            }
        }
        for s in i0 + 1..i1 {
            let [(l, pl), (r, pr)] = portals[s - 1];
            // A portal at a corner of the path is passed at that corner.
            if [v0, v1].iter().any(|&v| v == Some(l) || v == Some(r)) {
                continue;
            }
            // Where p → q crosses the portal l → r.
            let d = [q[0] - p[0], q[1] - p[1]];
            let den = (pr[0] - pl[0]) * d[1] - (pr[1] - pl[1]) * d[0];
            let num = (p[0] - pl[0]) * d[1] - (p[1] - pl[1]) * d[0];
            let tl = num / den;
            if !tl.is_finite() {
                return None;
            }
            let tl = tl.clamp(f64::MIN_POSITIVE, 1.0 - f64::EPSILON);
            let (a, b, t) = if l < r { (l, r, tl) } else { (r, l, 1.0 - tl) };
            out.push(Node::Edge { a, b, t });
        }
    }
    Some(out)
}

/// Length of a polyline of nodes (NaN when a node is not on S_T).
fn polyline(k: &SimplicialSurface, nodes: &[Node]) -> f64 {
    nodes
        .windows(2)
        .map(|w| match (w[0].point(k), w[1].point(k)) {
            (Some(p), Some(q)) => dist(p, q),
            _ => f64::NAN,
        })
        .sum()
}

/// What straightening one piece of a run did.
enum Piece {
    /// Replaced; the piece's last node is now at this index.
    Replaced(usize),
    /// Not shorter, not disjoint from the other curves, or no sleeve: kept.
    Kept,
    /// The funnel's path wraps this vertex, which the curve may not pass through.
    Wraps(u32),
}

/// Straighten nodes s..=e of curve ci (anchors s and e stay) where that is shorter by more
/// than the rounding of the lengths (16 u of the piece's length) and keeps the curves
/// disjoint (the rules of a node move).
#[allow(clippy::too_many_arguments)]
fn straighten_piece(
    k: &SimplicialSurface,
    base: &BaseMesh,
    emb: &mut Embedding,
    owner: &mut HashMap<u32, usize>,
    near: &mut Near,
    ci: usize,
    s: usize,
    e: usize,
) -> Piece {
    let (nodes, ca, cb) = (&emb.curves[ci].nodes, emb.curves[ci].a, emb.curves[ci].b);
    let Some(new) = straighten_run(k, &nodes[s..=e]) else {
        return Piece::Kept;
    };
    let forbidden = new.iter().find_map(|q| match *q {
        Node::Vertex(u)
            if (base.is_base(u) && u != ca && u != cb)
                || owner.get(&u).is_some_and(|&o| o != ci) =>
        {
            Some(u)
        }
        _ => None,
    });
    if let Some(u) = forbidden {
        return Piece::Wraps(u);
    }
    let mut run = vec![nodes[s]];
    run.extend_from_slice(&new);
    run.push(nodes[e]);
    let (old, now) = (polyline(k, &nodes[s..=e]), polyline(k, &run));
    if !(now < old - 16.0 * f64::EPSILON * old) {
        return Piece::Kept;
    }
    let mut cand = nodes[..s].to_vec();
    cand.extend_from_slice(&run);
    cand.extend_from_slice(&nodes[e + 1..]);
    let span = (s, s + new.len() + 1);
    if segments_meet_other(k, emb, ci, &cand, span, near) {
        return Piece::Kept;
    }
    for q in &new {
        if let Node::Vertex(u) = *q {
            owner.insert(u, ci);
        }
    }
    for w in cand[span.0..=span.1].windows(2) {
        for f in common_faces(k, &w[0], &w[1]) {
            let l = near.entry(f).or_default();
            if !l.contains(&ci) {
                l.push(ci);
            }
        }
    }
    emb.curves[ci].nodes = cand;
    Piece::Replaced(span.1)
}

/// Replace every run of edge nodes between two vertex nodes (of the curves not `frozen`) by
/// its straightened run
/// ([`straighten_run`], [`straighten_piece`]). Where the funnel's path wraps a vertex the
/// curve may not pass through (a base vertex, or a node of another curve), the constrained
/// shortest curve passes arbitrarily close to it on the side the curve is on: the run's
/// nodes on the edges of S_T at that vertex are placed next to it ([`hug`]) and the pieces
/// before and after them are straightened on their own. Rejecting the whole run
/// instead left its other nodes to the node rules, which converge linearly: on
/// skull_low_resolution at 3·10⁻³ the shortening did not settle in 200 sweeps.
pub(super) fn straighten_runs(
    k: &SimplicialSurface,
    base: &BaseMesh,
    emb: &mut Embedding,
    owner: &mut HashMap<u32, usize>,
    near: &mut Near,
    frozen: &[bool],
) -> usize {
    let mut moved = 0;
    for ci in (0..emb.curves.len()).filter(|&ci| !frozen.get(ci).copied().unwrap_or(false)) {
        let mut i = 0;
        while i + 1 < emb.curves[ci].nodes.len() {
            let nodes = &emb.curves[ci].nodes;
            let Some(mut end) = (i + 1..nodes.len()).find(|&j| matches!(nodes[j], Node::Vertex(_)))
            else {
                break;
            };
            // The piece s..=e, then the run from `resume` to its end. Each step either moves
            // s forward or e back, so the loop ends.
            let (mut s, mut e, mut resume) = (i, end, end);
            while s < end {
                let piece = if e >= s + 2 {
                    straighten_piece(k, base, emb, owner, near, ci, s, e)
                } else {
                    Piece::Kept
                };
                match piece {
                    Piece::Replaced(ne) => {
                        moved += 1;
                        // Indices after the piece shift by its change of length.
                        end = end - e + ne;
                        s = resume - e + ne;
                        (e, resume) = (end, end);
                    }
                    Piece::Kept => {
                        s = resume;
                        (e, resume) = (end, end);
                    }
                    Piece::Wraps(u) => {
                        let nodes = &emb.curves[ci].nodes;
                        let at_u = |h: &usize| matches!(nodes[*h], Node::Edge { a, b, .. } if a == u || b == u);
                        match ((s + 1..e).find(at_u), (s + 1..e).rev().find(at_u)) {
                            (Some(h1), Some(h2)) => {
                                if hug(k, emb, near, ci, u, (h1, h2)) {
                                    moved += 1;
                                }
                                (e, resume) = (h1, h2);
                            }
                            _ => {
                                s = resume;
                                (e, resume) = (end, end);
                            }
                        }
                    }
                }
            }
            i = end;
        }
    }
    moved
}

/// Units of roundoff of a hugging node's distance from the vertex it hugs ([`hug`]).
const HUG_ULPS: f64 = 4.0;

/// Move nodes h.0..=h.1 of curve ci, all on edges of S_T at the vertex u the curve may not
/// pass through, to HUG_ULPS·u·(‖u‖ + l) from u along their edges (l the edge's length),
/// where that is closer than they are and keeps the curves disjoint; true when they moved.
///
/// Why that distance: the constrained shortest curve passes arbitrarily close to u, and the
/// node rules only approach it geometrically (each node moves to the crossing of its
/// neighbours' chord, which for a chain of nodes around u is a fixed fraction closer). With
/// every node of the chain within δ_i of u, a node's rule gains at most
/// 2·(δ_P + δ_X + δ_N) (triangle inequality through u: |PX| ≤ |Pu| + δ_X, and the shortened
/// length is at least |Pu| − δ_N for a neighbour P off the chain, at least 0 otherwise),
/// which is at most 2·HUG_ULPS·u·(3‖u‖ + Λ) ≤ [`super::shorten::gain_bound`]·(|PX| + |XN|)/8
/// (Λ holds the edges of the neighbours on the chain, they share a triangle with X): the
/// gain is below the rounding bound of `AF-geodesic-shortest` by construction.
fn hug(
    k: &SimplicialSurface,
    emb: &mut Embedding,
    near: &Near,
    ci: usize,
    u: u32,
    h: (usize, usize),
) -> bool {
    let nodes = &emb.curves[ci].nodes;
    let pu = k.position(VertexId(u));
    let mut cand = nodes.clone();
    let mut closer = false;
    for q in &mut cand[h.0..=h.1] {
        let Node::Edge { a, b, t } = *q else {
            return false;
        };
        if a != u && b != u {
            return false;
        }
        let l = norm(sub(k.position(VertexId(b)), k.position(VertexId(a))));
        let tau = HUG_ULPS * f64::EPSILON * (norm(pu) + l) / l;
        // Closer as stored: 1 − τ rounds, so compare the parameters themselves.
        let (to, nearer) = if a == u {
            (tau, tau < t)
        } else {
            (1.0 - tau, 1.0 - tau > t)
        };
        if !(tau < 0.5) || !nearer {
            continue;
        }
        closer = true;
        *q = Node::Edge { a, b, t: to };
    }
    let span = (h.0.saturating_sub(1), h.1 + 1);
    if !closer || segments_meet_other(k, emb, ci, &cand, span, near) {
        return false;
    }
    emb.curves[ci].nodes = cand;
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fitting::shorten::{gain_bound, relative_gain};
    use crate::mesh::generate;
    use crate::mesh::validate::validate;

    /// [`hug`]'s claim (SPEC `AF-geodesic-shortest`): a chain of nodes on the spokes of a
    /// vertex u, each HUG_ULPS·u·(‖u‖ + l) from u, gains at most an eighth of its rounding
    /// bound, whichever node of the chain moves. The chain wraps the apex of a bipyramid
    /// between two equator vertices, as a curve wraps a base vertex it may not pass through.
    #[test]
    fn af_geodesic_shortest_hugging_nodes_gain_below_an_eighth_of_the_bound() {
        let Some(k) = validate(&generate::bipyramid(8)).surface else {
            panic!("the bipyramid is a simplicial surface");
        };
        let u = 0u32;
        let pu = k.position(VertexId(u));
        let mut nodes = vec![Node::Vertex(2)];
        for b in 3..=5u32 {
            let l = norm(sub(k.position(VertexId(b)), pu));
            let t = HUG_ULPS * f64::EPSILON * (norm(pu) + l) / l;
            nodes.push(Node::Edge { a: u, b, t });
        }
        nodes.push(Node::Vertex(6));
        // Control: the same chain a quarter of the way out is far beyond the bound.
        let mut far = nodes.clone();
        for q in &mut far[1..4] {
            if let Node::Edge { t, .. } = q {
                *t = 0.25;
            }
        }
        assert!((1..4).any(|i| relative_gain(&k, &far, i) > gain_bound(&k, &far, i)));
        for i in 1..nodes.len() - 1 {
            let (g, bound) = (relative_gain(&k, &nodes, i), gain_bound(&k, &nodes, i));
            assert!(
                g <= bound / 8.0,
                "node {i}: relative gain {g:e}, bound {bound:e}"
            );
        }
    }
}
