//! The validator's geometric predicates on f64 coordinates (projections, segment and triangle
//! tests, whether two triangles meet improperly, Def. 3.1.3(ii)), built on the exact
//! orientation signs of [`crate::numeric::predicates`]. Inputs must be finite (the validator
//! checks finiteness first).

use crate::numeric::predicates::orient2;
use robust::Coord;
use std::cmp::Ordering;

/// A point of R³.
pub type P3 = [f64; 3];

/// Sign of the exact orientation determinant of (a, b, c, d) (finite points).
pub fn orient3(a: &P3, b: &P3, c: &P3, d: &P3) -> Ordering {
    crate::numeric::predicates::orient3(a, b, c, d).unwrap_or(Ordering::Equal)
}

/// A projection R³ → R² that drops coordinate `drop`.
#[derive(Debug, Clone, Copy)]
pub struct Proj {
    /// Index (0, 1 or 2) of the dropped coordinate.
    pub drop: usize,
}

impl Proj {
    /// Projects `p` to R² by dropping coordinate `drop` (keeping the remaining two in cyclic order).
    pub fn apply(&self, p: &P3) -> Coord<f64> {
        match self.drop {
            0 => Coord { x: p[1], y: p[2] },
            1 => Coord { x: p[2], y: p[0] },
            _ => Coord { x: p[0], y: p[1] },
        }
    }
    /// Exact sign of the 2D orientation of the projected points a, b, c.
    pub fn orient(&self, a: &P3, b: &P3, c: &P3) -> Ordering {
        let p = |x: &P3| {
            let c = self.apply(x);
            [c.x, c.y]
        };
        orient2(p(a), p(b), p(c)).unwrap_or(Ordering::Equal)
    }
}

/// Def. 3.1.1 for a triangle in R³: a, b, c are affinely independent iff (b−a)×(c−a) ≠ 0,
/// i.e. iff at least one of its three coordinate projections has non-zero exact orientation.
/// Returns a projection under which the triangle is non-degenerate, or `None` when the three
/// points are collinear (or coincide).
pub(crate) fn nondegenerate_projection(a: &P3, b: &P3, c: &P3) -> Option<Proj> {
    (0..3)
        .rev()
        .map(|drop| Proj { drop })
        .find(|p| p.orient(a, b, c) != Ordering::Equal)
}

fn sgn(o: Ordering) -> i8 {
    match o {
        Ordering::Less => -1,
        Ordering::Equal => 0,
        Ordering::Greater => 1,
    }
}

/// Closed point-in-triangle test in a 2-D projection where (a, b, c) is non-degenerate.
pub(crate) fn point_in_triangle_2d(pr: Proj, p: &P3, a: &P3, b: &P3, c: &P3) -> bool {
    let s = sgn(pr.orient(a, b, c));
    let o1 = sgn(pr.orient(a, b, p)) * s;
    let o2 = sgn(pr.orient(b, c, p)) * s;
    let o3 = sgn(pr.orient(c, a, p)) * s;
    o1 >= 0 && o2 >= 0 && o3 >= 0
}

fn on_segment_2d(pr: Proj, p: &P3, q: &P3, x: &P3) -> bool {
    // x is collinear with p, q: check it lies within their bounding box in the projection.
    let (p, q, x) = (pr.apply(p), pr.apply(q), pr.apply(x));
    x.x >= p.x.min(q.x) && x.x <= p.x.max(q.x) && x.y >= p.y.min(q.y) && x.y <= p.y.max(q.y)
}

/// Closed segment–segment intersection in a 2-D projection (all four points coplanar).
pub(crate) fn segments_intersect_2d(pr: Proj, p: &P3, q: &P3, a: &P3, b: &P3) -> bool {
    let d1 = sgn(pr.orient(a, b, p));
    let d2 = sgn(pr.orient(a, b, q));
    let d3 = sgn(pr.orient(p, q, a));
    let d4 = sgn(pr.orient(p, q, b));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    (d1 == 0 && on_segment_2d(pr, a, b, p))
        || (d2 == 0 && on_segment_2d(pr, a, b, q))
        || (d3 == 0 && on_segment_2d(pr, p, q, a))
        || (d4 == 0 && on_segment_2d(pr, p, q, b))
}

/// Does the closed segment [p, q] meet the closed, non-degenerate triangle (a, b, c)? Exact.
pub(crate) fn segment_meets_triangle(p: &P3, q: &P3, a: &P3, b: &P3, c: &P3) -> bool {
    let op = sgn(orient3(a, b, c, p));
    let oq = sgn(orient3(a, b, c, q));
    if op * oq > 0 {
        return false;
    }
    if op == 0 && oq == 0 {
        let pr = match nondegenerate_projection(a, b, c) {
            Some(pr) => pr,
            None => return false,
        };
        return point_in_triangle_2d(pr, p, a, b, c)
            || point_in_triangle_2d(pr, q, a, b, c)
            || segments_intersect_2d(pr, p, q, a, b)
            || segments_intersect_2d(pr, p, q, b, c)
            || segments_intersect_2d(pr, p, q, c, a);
    }
    // The line pq crosses the plane in one point, which lies on the segment; it is in the
    // triangle iff the three signed volumes around the line agree in sign (zeros allowed).
    let s1 = sgn(orient3(p, q, a, b));
    let s2 = sgn(orient3(p, q, b, c));
    let s3 = sgn(orient3(p, q, c, a));
    (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0)
}

/// For a triangle (v, b1, b2) and a point x coplanar with it: does the segment from v towards
/// x enter the triangle beyond v, i.e. does x lie in the closed cone of the triangle at v?
pub(crate) fn in_cone_at(v: &P3, b1: &P3, b2: &P3, x: &P3) -> bool {
    let pr = match nondegenerate_projection(v, b1, b2) {
        Some(pr) => pr,
        None => return false,
    };
    let s = sgn(pr.orient(v, b1, b2));
    sgn(pr.orient(v, b1, x)) * s >= 0 && sgn(pr.orient(v, x, b2)) * s >= 0
}

/// Exact test: does the intersection of triangles t1 and t2 (non-degenerate, distinct vertex
/// sets) contain a point that is not in a common face?
pub fn triangles_meet_improperly(pos: &[P3], t1: [u32; 3], t2: [u32; 3]) -> bool {
    let p = |i: u32| &pos[i as usize];
    let mut shared = [0u32; 3];
    let mut n_shared = 0;
    for &x in &t1 {
        if t2.contains(&x) {
            shared[n_shared] = x;
            n_shared += 1;
        }
    }
    let shared = &shared[..n_shared];
    match shared.len() {
        0 => {
            (0..3).any(|k| {
                segment_meets_triangle(p(t1[k]), p(t1[(k + 1) % 3]), p(t2[0]), p(t2[1]), p(t2[2]))
            }) || (0..3).any(|k| {
                segment_meets_triangle(p(t2[k]), p(t2[(k + 1) % 3]), p(t1[0]), p(t1[1]), p(t1[2]))
            })
        }
        1 => {
            let v = shared[0];
            let check = |a: [u32; 3], b: [u32; 3]| -> bool {
                // Rotate `a` so that a[0] = v.
                let k = a.iter().position(|&x| x == v).unwrap_or(0);
                let (a1, a2) = (a[(k + 1) % 3], a[(k + 2) % 3]);
                let kb = b.iter().position(|&x| x == v).unwrap_or(0);
                let (b1, b2) = (b[(kb + 1) % 3], b[(kb + 2) % 3]);
                // The edge of `a` opposite v: any common point is not v.
                if segment_meets_triangle(p(a1), p(a2), p(v), p(b1), p(b2)) {
                    return true;
                }
                // An edge [v, a_i] meets b beyond v only if it lies in b's plane and points
                // into b's corner at v.
                [a1, a2].iter().any(|&ai| {
                    orient3(p(v), p(b1), p(b2), p(ai)) == Ordering::Equal
                        && in_cone_at(p(v), p(b1), p(b2), p(ai))
                })
            };
            check(t1, t2) || check(t2, t1)
        }
        2 => {
            // Sharing the edge [s0, s1]: the triangles overlap iff they are coplanar and the
            // opposite corners lie on the same side of the edge.
            let (s0, s1) = (shared[0], shared[1]);
            let o1 = t1
                .iter()
                .copied()
                .find(|x| !shared.contains(x))
                .unwrap_or(s0);
            let o2 = t2
                .iter()
                .copied()
                .find(|x| !shared.contains(x))
                .unwrap_or(s0);
            if orient3(p(t1[0]), p(t1[1]), p(t1[2]), p(o2)) != Ordering::Equal {
                return false;
            }
            match nondegenerate_projection(p(t1[0]), p(t1[1]), p(t1[2])) {
                Some(pr) => pr.orient(p(s0), p(s1), p(o1)) == pr.orient(p(s0), p(s1), p(o2)),
                None => false,
            }
        }
        _ => false,
    }
}
