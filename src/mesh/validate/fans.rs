//! Def. 3.1.3(ii) around vertices of high degree, in about linear time.
//!
//! The m triangles of the star of a vertex v all contain v, so their bounding boxes overlap
//! pairwise and a box search tests m²/2 pairs (degree 10,000: 21 s). Two facts make the star
//! cheap:
//!
//! * Triangles sharing v meet in a convex set containing v; they meet improperly iff it holds a
//!   segment [v, x], whose direction lies in both corners at v. On the sphere of directions at v
//!   each corner is the shorter great-circle arc between its two edge directions, so only pairs
//!   whose arcs meet are candidates ([`star_pairs`]: an R*-tree over conservative arc boxes).
//! * Every triangle not incident to v is at distance ≥ 2r_v from v (r_v from the nearest such
//!   bounding box). An improper meeting of two triangles that do not share v cannot lie within
//!   r_v of v, so the corner of each triangle at v may be cut off (at r_v/2, conservatively) from
//!   the box used in the general search ([`trimmed_box`]): the fan's boxes stop overlapping.
//!
//! Candidate pairs are then decided by the same exact predicates.

use super::predicates::triangles_meet_improperly;
use crate::mesh::RawMesh;
use rayon::prelude::*;
use rstar::{PointDistance, RTree, RTreeObject, AABB};

/// Vertices with at least this many eligible incident triangles get the star treatment.
pub(super) const HIGH_DEGREE: usize = 16;
/// Up to this many stars, the nearest non-incident box is found by a scan (no tree to build).
const FEW_STARS: usize = 8;

/// A triangle's box in an R*-tree.
#[derive(Clone)]
pub(super) struct FaceBox {
    pub face: u32,
    pub env: AABB<[f64; 3]>,
}

impl RTreeObject for FaceBox {
    type Envelope = AABB<[f64; 3]>;
    fn envelope(&self) -> Self::Envelope {
        self.env
    }
}

impl PointDistance for FaceBox {
    fn distance_2(&self, point: &[f64; 3]) -> f64 {
        self.env.distance_2(point)
    }
}

/// The high-degree vertices and their trimming radii.
pub(super) struct Fans {
    /// Eligible incident faces of each high-degree vertex (empty for the others).
    pub star: Vec<Vec<u32>>,
    /// r_v/2 (0: no trimming).
    pub cut: Vec<f64>,
}

impl Fans {
    pub(crate) fn is_high(&self, v: u32) -> bool {
        !self.star[v as usize].is_empty()
    }
}

fn bbox(points: &[[f64; 3]], pad: f64) -> AABB<[f64; 3]> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for d in 0..3 {
            lo[d] = lo[d].min(p[d] - pad);
            hi[d] = hi[d].max(p[d] + pad);
        }
    }
    AABB::from_corners(lo, hi)
}

/// The triangle's bounding box.
pub(super) fn face_box(raw: &RawMesh, t: [u32; 3]) -> AABB<[f64; 3]> {
    bbox(&t.map(|i| raw.positions[i as usize]), 0.0)
}

/// Find the high-degree vertices among the eligible faces and their trimming radii.
pub(super) fn fans(raw: &RawMesh, eligible: &[bool], full: Vec<FaceBox>) -> Fans {
    let n = raw.positions.len();
    let mut count = vec![0usize; n];
    let faces = || {
        raw.faces
            .iter()
            .enumerate()
            .filter(|(f, _)| eligible.get(*f).copied().unwrap_or(false))
    };
    for (_, t) in faces() {
        for &v in t {
            count[v as usize] += 1;
        }
    }
    let mut star = vec![Vec::new(); n];
    for (f, t) in faces() {
        for &v in t {
            if count[v as usize] >= HIGH_DEGREE {
                star[v as usize].push(f as u32);
            }
        }
    }
    // The nearest box of a triangle not incident to v (boxes are below triangles): a scan of
    // the boxes for a few stars, an R*-tree for many (the same minimum either way).
    let highs = star.iter().filter(|s| !s.is_empty()).count();
    let tree = (highs > FEW_STARS).then(|| RTree::bulk_load(full.clone()));
    let nearest = |v: usize, p: &[f64; 3]| -> f64 {
        let incident = |fb: &FaceBox| raw.faces[fb.face as usize].contains(&(v as u32));
        match &tree {
            Some(tree) => tree
                .nearest_neighbor_iter_with_distance_2(p)
                .find(|(fb, _)| !incident(fb))
                .map_or(f64::INFINITY, |(_, d2)| d2),
            None => full
                .par_iter()
                .filter(|fb| !incident(fb))
                .map(|fb| fb.env.distance_2(p))
                .reduce(|| f64::INFINITY, f64::min),
        }
    };
    let cut: Vec<f64> = (0..n)
        .into_par_iter()
        .map(|v| {
            if star[v].is_empty() {
                return 0.0;
            }
            let p = raw.positions[v];
            let d2 = nearest(v, &p);
            // r_v = √d2/2 (shrunk for rounding); cut at r_v/2.
            let r = 0.5 * d2.sqrt() * (1.0 - 1e-6);
            if r.is_finite() {
                0.5 * r
            } else {
                0.0
            }
        })
        .collect();
    Fans { star, cut }
}

/// The box of the triangle with its corners at high-degree vertices cut at r_v/2 (padded for
/// rounding): it contains every point of the triangle outside the balls B(v, r_v).
pub(super) fn trimmed_box(raw: &RawMesh, t: [u32; 3], fans: &Fans) -> AABB<[f64; 3]> {
    let p = |i: u32| raw.positions[i as usize];
    let mut pts: Vec<[f64; 3]> = Vec::with_capacity(6);
    let mut scale = 0.0f64;
    for k in 0..3 {
        let x = t[k];
        scale = p(x).iter().fold(scale, |a, c| a.max(c.abs()));
        let cut = fans.cut[x as usize];
        if !fans.is_high(x) || cut <= 0.0 {
            pts.push(p(x));
            continue;
        }
        for y in [t[(k + 1) % 3], t[(k + 2) % 3]] {
            let (a, b) = (p(x), p(y));
            let e = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let len = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt();
            let s = if len > 0.0 { (cut / len).min(0.5) } else { 0.0 };
            pts.push([a[0] + s * e[0], a[1] + s * e[1], a[2] + s * e[2]]);
        }
    }
    bbox(&pts, 16.0 * f64::EPSILON * scale)
}

/// Boxes covering the part of triangle `t` that the general search needs (outside the balls
/// B(v, r_v) of its high-degree corners). A triangle with one high-degree corner v is cut into
/// slices between lines parallel to its far edge, halving toward that edge until a slice is
/// about as long as the edge: a fan's long, thin triangles then have small boxes where they meet
/// their neighbours, instead of boxes that overlap a large part of the fan. Others: one box.
pub(super) fn search_boxes(raw: &RawMesh, t: [u32; 3], fans: &Fans) -> Vec<AABB<[f64; 3]>> {
    let highs: Vec<usize> = (0..3).filter(|&k| fans.is_high(t[k])).collect();
    let [k] = highs.as_slice() else {
        return vec![trimmed_box(raw, t, fans)];
    };
    let cut = fans.cut[t[*k] as usize];
    if cut <= 0.0 {
        return vec![trimmed_box(raw, t, fans)];
    }
    let p = |i: u32| raw.positions[i as usize];
    let (v, a, b) = (p(t[*k]), p(t[(k + 1) % 3]), p(t[(k + 2) % 3]));
    let dist = |x: [f64; 3], y: [f64; 3]| {
        ((x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2) + (x[2] - y[2]).powi(2)).sqrt()
    };
    let (la, lb, w) = (dist(a, v), dist(b, v), dist(a, b));
    let scale = [v, a, b]
        .iter()
        .flat_map(|q| q.iter())
        .fold(0.0f64, |m, c| m.max(c.abs()));
    let pad = 16.0 * f64::EPSILON * scale;
    // The corner {t < t0} lies inside the cut corner triangle, so the slices from t0 cover
    // everything the trimmed box covers.
    let mut lo = (cut / la).min(cut / lb).min(0.5);
    if !(lo.is_finite() && lo >= 0.0) {
        return vec![trimmed_box(raw, t, fans)];
    }
    let at = |s: f64, q: [f64; 3]| -> [f64; 3] {
        if s >= 1.0 {
            q
        } else {
            [
                v[0] + s * (q[0] - v[0]),
                v[1] + s * (q[1] - v[1]),
                v[2] + s * (q[2] - v[2]),
            ]
        }
    };
    let long = la.max(lb);
    let mut out = Vec::new();
    for _ in 0..64 {
        let mut hi = 1.0 - (1.0 - lo) / 2.0;
        if (1.0 - lo) * long <= 2.0 * w || out.len() == 63 {
            hi = 1.0;
        }
        out.push(bbox(&[at(lo, a), at(lo, b), at(hi, a), at(hi, b)], pad));
        if hi >= 1.0 {
            break;
        }
        lo = hi;
    }
    out
}

/// Pairs of triangles of the star of v that meet improperly, and the number of candidate pairs
/// decided exactly. Candidates: corners at v whose direction arcs have overlapping
/// (conservative, padded) boxes.
pub(super) fn star_pairs(raw: &RawMesh, v: u32, star: &[u32]) -> (Vec<(u32, u32)>, u64) {
    let pos = &raw.positions;
    let pv = pos[v as usize];
    let dir = |i: u32| {
        let q = pos[i as usize];
        let d = [q[0] - pv[0], q[1] - pv[1], q[2] - pv[2]];
        let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        [d[0] / l, d[1] / l, d[2] / l]
    };
    const PAD: f64 = 1e-9;
    let arcs: Vec<FaceBox> = star
        .iter()
        .map(|&f| {
            let t = raw.faces[f as usize];
            let others: Vec<u32> = t.iter().copied().filter(|&x| x != v).collect();
            let (a, b) = (dir(others[0]), dir(others[1]));
            let c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            // The shorter arc from a to b lies in the triangle (a, b, w), w the meeting point of
            // the tangents at a and b; near-opposite directions: the whole sphere's box.
            let env = if c > -0.99 && c.is_finite() {
                let w = [
                    (a[0] + b[0]) / (1.0 + c),
                    (a[1] + b[1]) / (1.0 + c),
                    (a[2] + b[2]) / (1.0 + c),
                ];
                bbox(&[a, b, w], PAD)
            } else {
                bbox(&[[-1.0; 3], [1.0; 3]], PAD)
            };
            FaceBox { face: f, env }
        })
        .collect();
    let tree = RTree::bulk_load(arcs.clone());
    let found: Vec<(Vec<(u32, u32)>, u64)> = arcs
        .par_iter()
        .map(|fb| {
            let t1 = raw.faces[fb.face as usize];
            let mut k1 = t1;
            k1.sort_unstable();
            let mut hits = Vec::new();
            let mut tested = 0u64;
            for o in tree.locate_in_envelope_intersecting(&fb.env) {
                if o.face <= fb.face {
                    continue;
                }
                let t2 = raw.faces[o.face as usize];
                let mut k2 = t2;
                k2.sort_unstable();
                if k1 == k2 {
                    continue;
                }
                if separated(pos, t1, t2) {
                    continue;
                }
                tested += 1;
                if triangles_meet_improperly(pos, t1, t2) {
                    hits.push((fb.face, o.face));
                }
            }
            (hits, tested)
        })
        .collect();
    let tested = found.iter().map(|x| x.1).sum();
    (found.into_iter().flat_map(|x| x.0).collect(), tested)
}

/// Whether the vertices of `t2` not in `t1` lie strictly on one side of the plane of `t1` (or
/// vice versa), decided in f64 with a certified error bound: the sign of n·(q − a) is trusted
/// only beyond 32ε·|b − a|·|c − a|·|q − a|, above the rounding of the two differences, the cross
/// product and the dot product (a, b, c the corners of the plane's triangle, any one as a).
/// Then the two triangles meet at most in their shared vertices, which span a common face (the
/// shared corner or edge, or nothing), so the pair meets properly and the exact predicates are
/// skipped for it; anything undecided goes to the exact test. Neighbouring triangles of a
/// smooth mesh share a vertex or an edge and are almost all decided here.
pub(super) fn separated(pos: &[[f64; 3]], t1: [u32; 3], t2: [u32; 3]) -> bool {
    side_of_plane(pos, t1, t2) || side_of_plane(pos, t2, t1)
}

fn side_of_plane(pos: &[[f64; 3]], t: [u32; 3], o: [u32; 3]) -> bool {
    let p = |i: u32| pos[i as usize];
    let sub = |x: [f64; 3], y: [f64; 3]| [x[0] - y[0], x[1] - y[1], x[2] - y[2]];
    let norm = |x: [f64; 3]| (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
    // A shared corner as the base point a (it lies on the plane and is skipped below).
    let base = (0..3).find(|&k| o.contains(&t[k])).unwrap_or(0);
    let a = p(t[base]);
    let e1 = sub(p(t[(base + 1) % 3]), a);
    let e2 = sub(p(t[(base + 2) % 3]), a);
    let n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    let scale = 32.0 * f64::EPSILON * norm(e1) * norm(e2);
    let mut sign = 0i8;
    for &q in o.iter().filter(|q| !t.contains(q)) {
        let d = sub(p(q), a);
        let s = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        let err = scale * norm(d);
        let here = if s > err {
            1
        } else if s < -err {
            -1
        } else {
            return false;
        };
        if !(s.is_finite() && err.is_finite()) || (sign != 0 && here != sign) {
            return false;
        }
        sign = here;
    }
    // Nothing left off the plane: identical vertex sets (reported as duplicates elsewhere).
    sign != 0
}

#[cfg(test)]
mod tests {
    use super::{search_boxes, separated, star_pairs, trimmed_box, Fans};
    use crate::mesh::validate::predicates::triangles_meet_improperly;
    use crate::mesh::RawMesh;
    use rstar::Envelope;

    /// `star_pairs` finds exactly the pairs of a star that meet improperly (all pairs decided
    /// by the exact predicate as the reference), on seeded random fans folded over themselves,
    /// their centre far from the origin (a direction must be taken from the centre).
    #[test]
    fn star_pairs_are_the_improperly_meeting_pairs_of_random_folded_fans() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let mut found = 0;
        let mut whole = 0;
        for _ in 0..40 {
            let c: [f64; 3] = std::array::from_fn(|_| rng.gen_range(-100.0..100.0));
            let mut positions = vec![c];
            let mut faces = Vec::new();
            for i in 0..18u32 {
                for _ in 0..2 {
                    // Directions in one half-space, lengths over three decades: many corners overlap.
                    let d = [
                        rng.gen_range(0.1..1.0),
                        rng.gen_range(-1.0..1.0),
                        rng.gen_range(-0.3..0.3),
                    ];
                    let l = 10f64.powf(rng.gen_range(-2.0..1.0));
                    positions.push(std::array::from_fn(|k| c[k] + l * d[k]));
                }
                faces.push([0, 2 * i + 1, 2 * i + 2]);
            }
            let raw = RawMesh::from_arrays(positions, faces);
            let star: Vec<u32> = (0..raw.faces.len() as u32).collect();
            let (mut got, _) = star_pairs(&raw, 0, &star);
            got.sort_unstable();
            let mut want = Vec::new();
            for f in 0..star.len() {
                for g in f + 1..star.len() {
                    if triangles_meet_improperly(&raw.positions, raw.faces[f], raw.faces[g]) {
                        want.push((f as u32, g as u32));
                    }
                }
            }
            assert_eq!(got, want, "centre {c:?}");
            // The whole search (the star's pairs and the general one): each pair once.
            let (_, mut all) = super::super::intersect::triangles_meet_properly_pairs(
                &raw,
                &vec![true; raw.faces.len()],
            );
            all.sort_unstable();
            whole += usize::from(!all.is_empty());
            assert_eq!(all, want, "centre {c:?} (whole search)");
            found += want.len();
        }
        assert!(whole > 10, "the whole search found pairs in {whole} fans");
        assert!(
            found > 40,
            "only {found} improper pairs: the fans do not fold"
        );
        // A corner of almost π (its arc bulges far from its end directions, here toward +y)
        // over a narrow corner at that bulge: the pair meets along a segment from the centre
        // (not mirror-symmetric: a wrong tangent point of such a pair can land on the same
        // coordinate for both arcs).
        let c = [3.0, -2.0, 5.0];
        let at = |d: [f64; 3]| std::array::from_fn(|k| c[k] + d[k]);
        let raw = RawMesh::from_arrays(
            vec![
                c,
                at([1.0, 0.1, 0.0]),
                at([-1.0, 0.15, 0.0]),
                at([0.05, 1.0, 0.3]),
                at([-0.1, 1.2, -0.2]),
            ],
            vec![[0, 1, 2], [0, 3, 4]],
        );
        assert!(triangles_meet_improperly(
            &raw.positions,
            raw.faces[0],
            raw.faces[1]
        ));
        assert_eq!(star_pairs(&raw, 0, &[0, 1]).0, vec![(0, 1)]);
    }

    /// The trimmed box (and the slices of `search_boxes`) must hold every point of the
    /// triangle at distance ≥ cut from its high-degree corner: the points at exactly that
    /// distance along both edges from the corner, and a grid of the triangle's points beyond
    /// it. Edges with a negative z component, so a wrong length of the edge moves the cut.
    #[test]
    fn trimmed_boxes_cover_the_triangle_outside_the_cut_ball() {
        let raw = RawMesh::from_arrays(
            vec![[0.0, 0.0, 0.0], [3.0, 0.5, -1.3], [0.5, 2.0, -1.7]],
            vec![[0, 1, 2]],
        );
        let cut = 0.8;
        let fans = Fans {
            star: vec![vec![0], vec![], vec![]],
            cut: vec![cut, 0.0, 0.0],
        };
        let p = &raw.positions;
        let dist = |a: [f64; 3], b: [f64; 3]| {
            ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
        };
        let mut points = Vec::new();
        for y in [1, 2] {
            let s = cut / dist(p[0], p[y]);
            points.push(std::array::from_fn(|i| p[0][i] + s * (p[y][i] - p[0][i])));
        }
        // A grid of n steps per side over triangle p, the points at distance ≥ cut from p[0].
        let beyond_cut = |p: &[[f64; 3]], n: usize| {
            let mut out = Vec::new();
            for i in 0..=n {
                for j in 0..=n - i {
                    let (u, w) = (i as f64 / n as f64, j as f64 / n as f64);
                    let q: [f64; 3] = std::array::from_fn(|d| {
                        p[0][d] + u * (p[1][d] - p[0][d]) + w * (p[2][d] - p[0][d])
                    });
                    if dist(q, p[0]) >= cut {
                        out.push(q);
                    }
                }
            }
            out
        };
        points.extend(beyond_cut(p, 40));
        let t = [0, 1, 2];
        let tb = trimmed_box(&raw, t, &fans);
        let slices = search_boxes(&raw, t, &fans);
        let full = super::face_box(&raw, t);
        // Trimmed: the corner at 0 is cut off, and the box is the cut points' and the far
        // corners' box (padded for rounding only).
        assert!(tb.lower()[0] > full.lower()[0], "{tb:?} vs {full:?}");
        for d in 0..3 {
            let at = |pick: fn(f64, f64) -> f64| {
                [points[0], points[1], p[1], p[2]]
                    .iter()
                    .map(|x| x[d])
                    .fold(points[0][d], pick)
            };
            assert!((tb.lower()[d] - at(f64::min)).abs() < 1e-12, "{tb:?}");
            assert!((tb.upper()[d] - at(f64::max)).abs() < 1e-12, "{tb:?}");
        }
        for q in &points {
            assert!(tb.contains_point(q), "{q:?} not in {tb:?}");
            assert!(
                slices.iter().any(|b| b.contains_point(q)),
                "{q:?} in no slice"
            );
        }
        // A fan's long thin triangle is cut into slices halving toward the far edge, so the
        // box at that edge is a small part of the trimmed box (the point of the slices).
        let thin = RawMesh::from_arrays(
            vec![[0.0, 0.0, 0.0], [10.0, 0.1, 0.0], [10.0, -0.1, 0.05]],
            vec![[0, 1, 2]],
        );
        let tb = trimmed_box(&thin, t, &fans);
        let slices = search_boxes(&thin, t, &fans);
        let len = |b: &rstar::AABB<[f64; 3]>| b.upper()[0] - b.lower()[0];
        assert!(slices.len() >= 4, "{slices:?}");
        let last = slices.last().map_or(f64::INFINITY, len);
        assert!(last < len(&tb) / 8.0, "{slices:?} vs {tb:?}");
        assert!(slices.iter().all(|b| tb.contains_envelope(b)), "{slices:?}");
        // ... and together they still hold every point of the thin triangle beyond the cut,
        // each slice meeting the next (no gap between them).
        for x in beyond_cut(&thin.positions, 200) {
            assert!(
                slices.iter().any(|b| b.contains_point(&x)),
                "{x:?} in no slice"
            );
        }
        assert!(
            slices.windows(2).all(|w| w[0].intersects(&w[1])),
            "{slices:?}"
        );
    }

    /// D3.1.3(ii): the f64 filter may only skip pairs that meet properly. Pairs sharing a
    /// corner or an edge: skipped exactly when the other corners lie clearly on one side;
    /// crossing, coplanar-overlapping and nearly coplanar pairs go to the exact test.
    #[test]
    fn d3_1_3_ii_filter_skips_only_proper_pairs_sharing_a_corner_or_an_edge() {
        let pos = [
            [0.0, 0.0, 0.0],   // 0: shared corner
            [1.0, 0.0, 0.0],   // 1
            [0.0, 1.0, 0.0],   // 2
            [0.3, 0.3, 1.0],   // 3: above the plane z = 0
            [0.3, 0.3, -1.0],  // 4: below
            [0.2, 0.2, 0.0],   // 5: in the plane, inside the corner at 0
            [0.5, 0.5, 1e-30], // 6: above, within rounding of the plane
            [-1.0, 0.5, 1.0],  // 7: above
        ];
        let t1 = [0, 1, 2];
        let cases: [([u32; 3], bool); 6] = [
            ([0, 3, 7], true),  // corner shared, others above: proper
            ([0, 4, 3], false), // corner shared, crosses the plane through t1
            ([0, 5, 3], false), // corner shared, an edge inside t1's corner
            ([0, 1, 3], true),  // edge shared, opposite corner above: proper
            ([0, 1, 5], false), // edge shared, folded onto t1
            ([0, 1, 6], false), // edge shared, nearly coplanar: left to the exact test
        ];
        for (t2, skip) in cases {
            assert_eq!(separated(&pos, t1, t2), skip, "{t2:?}");
            assert_eq!(separated(&pos, t2, t1), skip, "{t2:?} (swapped)");
            if skip {
                assert!(!triangles_meet_improperly(&pos, t1, t2), "{t2:?}");
            }
        }
        assert!(triangles_meet_improperly(&pos, t1, [0, 4, 3]));
        assert!(triangles_meet_improperly(&pos, t1, [0, 5, 3]));
        assert!(triangles_meet_improperly(&pos, t1, [0, 1, 5]));
        assert!(!triangles_meet_improperly(&pos, t1, [0, 1, 6]));
        // A side that overflows (n·(q − a) = ∞ while its error bound, rounded in another
        // order, is finite) is undecided: the pair goes to the exact test.
        let huge = [
            [0.0, 0.0, 0.0],
            [1.2e154, 0.0, 0.0],
            [0.0, 1.2e154, 0.0],
            [0.0, 0.0, 1e10],
            [1e10, 1e10, 1e10],
        ];
        assert!(!separated(&huge, [0, 1, 2], [0, 3, 4]));
    }
}
