//! Whether segments of the embedded curves meet, decided exactly on each triangle of S_T in
//! its reference frame: the primitives of `AF-geodesic-disjoint` (checked in
//! `embed_checks`), kept true by the routing and every move of the shortening.

use super::geodesic::{common_faces, Embedding, Node};
use super::overlay::orient;
use crate::mesh::{FaceId, SimplicialSurface};
use std::collections::HashMap;

/// The curves touching each triangle of S_T (for [`segments_meet_other`]).
pub(super) type Near = HashMap<FaceId, Vec<usize>>;

/// The reference frame of a triangle of S_T: its corners, in stored order.
const REF: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];

/// Node `n` in the reference frame of triangle `f` (`None` when it is not on `f`).
pub(crate) fn local(k: &SimplicialSurface, f: FaceId, n: &Node) -> Option<[f64; 2]> {
    let c = k.face(f).map(|v| v.0);
    let at = |v: u32| c.iter().position(|&x| x == v).map(|i| REF[i]);
    match *n {
        Node::Vertex(v) => at(v),
        Node::Edge { a, b, t } => {
            let (p, q) = (at(a)?, at(b)?);
            Some([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])])
        }
    }
}

/// Segments p and q sharing the end x meet only at x.
pub(crate) fn only_at(p: [[f64; 2]; 2], q: [[f64; 2]; 2], x: [f64; 2]) -> bool {
    if p[0] == p[1] || q[0] == q[1] {
        return false;
    }
    let po = if p[0] == x { p[1] } else { p[0] };
    let qo = if q[0] == x { q[1] } else { q[0] };
    if orient(x, po, qo) != 0.0 {
        return true;
    }
    // Collinear: opposite directions from x (signs of differences are exact).
    (0..2).any(|i| {
        (po[i] - x[i]).signum() * (qo[i] - x[i]).signum() < 0.0 && po[i] != x[i] && qo[i] != x[i]
    })
}

/// Do the closed segments p and q meet (decided exactly on the f64 coordinates)?
pub(crate) fn meet(p: [[f64; 2]; 2], q: [[f64; 2]; 2]) -> bool {
    let (o1, o2) = (orient(p[0], p[1], q[0]), orient(p[0], p[1], q[1]));
    let (o3, o4) = (orient(q[0], q[1], p[0]), orient(q[0], q[1], p[1]));
    if o1 == 0.0 && o2 == 0.0 {
        let ax = |i: usize| {
            let (lo, hi) = (p[0][i].min(p[1][i]), p[0][i].max(p[1][i]));
            let (ql, qh) = (q[0][i].min(q[1][i]), q[0][i].max(q[1][i]));
            lo <= qh && ql <= hi
        };
        return ax(0) && ax(1);
    }
    o1 * o2 <= 0.0 && o3 * o4 <= 0.0
}

/// Does a segment of `cand` (the nodes curve `ci` would get) in `span` meet a segment of
/// another curve touching the same triangle of S_T (`near` lists them), or a segment of
/// `cand` that is not next to it, anywhere but where `check_disjoint` allows? The shortening
/// calls it before every move, so the curves stay disjoint.
pub(crate) fn segments_meet_other(
    k: &SimplicialSurface,
    emb: &Embedding,
    ci: usize,
    cand: &[Node],
    span: (usize, usize),
    near: &Near,
) -> bool {
    let last = cand.len().saturating_sub(1);
    let c = &emb.curves[ci];
    for s in span.0.min(last)..span.1.min(last) {
        let (x, y) = (&cand[s], &cand[s + 1]);
        for f in common_faces(k, x, y) {
            let (Some(p0), Some(p1)) = (local(k, f, x), local(k, f, y)) else {
                return true;
            };
            let p = [p0, p1];
            let mine = cand.windows(2).enumerate().filter(|(t, _)| *t != s);
            for (t, w) in mine {
                if !common_faces(k, &w[0], &w[1]).contains(&f) {
                    continue;
                }
                let (Some(q0), Some(q1)) = (local(k, f, &w[0]), local(k, f, &w[1])) else {
                    return true;
                };
                let q = [q0, q1];
                if meet(p, q) {
                    let shared = [p0, p1].into_iter().find(|z| *z == q0 || *z == q1);
                    let ok = t.abs_diff(s) == 1 && shared.is_some_and(|z| only_at(p, q, z));
                    if !ok {
                        return true;
                    }
                }
            }
            for &cj in near.get(&f).map_or(&[][..], |v| v.as_slice()) {
                if cj == ci {
                    continue;
                }
                let d = &emb.curves[cj];
                for w in d.nodes.windows(2) {
                    if !common_faces(k, &w[0], &w[1]).contains(&f) {
                        continue;
                    }
                    let (Some(q0), Some(q1)) = (local(k, f, &w[0]), local(k, f, &w[1])) else {
                        return true;
                    };
                    let q = [q0, q1];
                    if meet(p, q) {
                        let shared = [p0, p1].into_iter().find(|z| *z == q0 || *z == q1);
                        let common_end = [c.a, c.b].into_iter().find(|v| {
                            (*v == d.a || *v == d.b)
                                && shared.is_some()
                                && local(k, f, &Node::Vertex(*v)) == shared
                        });
                        let ok = common_end.is_some() && shared.is_some_and(|z| only_at(p, q, z));
                        if !ok {
                            return true;
                        }
                    }
                }
            }
        }
    }
    false
}
