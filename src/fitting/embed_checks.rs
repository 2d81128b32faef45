//! The checks of the embedding and of the parametrization (SPEC `AF-geodesic-on-surface`,
//! `AF-geodesic-disjoint`, `AF-geodesic-shortest`, `AF-curved-disk`, `AF-param-bijective`).
//! Each records through the harness: examined counts, NaN an offence, nothing examined
//! skipped.

use super::base::BaseMesh;
use super::disjoint::{local, meet, only_at};
use super::floater::RegionMap;
use super::geodesic::{common_faces, Curve, Embedding, Node};
use super::overlay::{disk_defects, orient, Overlay};
use super::shorten;
use crate::mesh::{FaceId, SimplicialSurface};
use crate::report::harness::dev_max;
use crate::report::{CheckResult, Witness};
use serde_json::json;
use std::collections::HashMap;

/// Every curve runs from its first base vertex to its second, each node is on S_T (a vertex,
/// or a point strictly inside an edge, t ∈ (0, 1)), and consecutive nodes lie on one closed
/// triangle of S_T (so each segment is on the surface).
pub fn check_on_surface(k: &SimplicialSurface, emb: &Embedding) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-geodesic-on-surface",
        "every embedded base edge is a polyline on |S_T| joining its end vertices",
    );
    for (ci, c) in emb.curves.iter().enumerate() {
        let ends = c.nodes.first() == Some(&Node::Vertex(c.a))
            && c.nodes.last() == Some(&Node::Vertex(c.b));
        r.examined += 1;
        if !ends {
            r.offend(|| {
                Witness::new(
                    format!(
                        "curve {ci} ({}, {}) does not join its end vertices",
                        c.a, c.b
                    ),
                    json!({"curve": ci}),
                )
            });
        }
        for (i, n) in c.nodes.iter().enumerate() {
            r.examined += 1;
            let ok = !n.faces(k).is_empty()
                && n.point(k).is_some_and(|p| p.iter().all(|x| x.is_finite()));
            let joined = i == 0 || !common_faces(k, &c.nodes[i - 1], n).is_empty();
            if !ok || !joined {
                r.offend(|| {
                    Witness::new(
                        format!(
                            "curve {ci} ({}, {}), node {i} {n:?}: {}",
                            c.a,
                            c.b,
                            if ok {
                                "shares no triangle of S_T with the node before"
                            } else {
                                "not on S_T"
                            }
                        ),
                        json!({"curve": ci, "node": i}),
                    )
                });
            }
        }
    }
    r
}

/// A segment in the reference frame of one triangle of S_T: curve, segment index, ends.
type Seg = (usize, usize, [[f64; 2]; 2]);

/// The embedded edges meet only at common end points: no vertex of S_T is a node of two
/// curves unless it is an end of both, no base vertex is an inner node, and no two segments
/// on one triangle of S_T meet (in its reference frame, exactly) except consecutive segments
/// of one curve at their node and two curves at a common end.
pub fn check_disjoint(k: &SimplicialSurface, base: &BaseMesh, emb: &Embedding) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-geodesic-disjoint",
        "the embedded base edges meet only at common end points",
    );
    let mut owner: HashMap<u32, usize> = HashMap::new();
    let mut by_face: HashMap<FaceId, Vec<Seg>> = HashMap::new();
    for (ci, c) in emb.curves.iter().enumerate() {
        let last = c.nodes.len().saturating_sub(1);
        for (i, n) in c.nodes.iter().enumerate() {
            let Node::Vertex(v) = *n else { continue };
            if i == 0 || i == last {
                continue;
            }
            r.examined += 1;
            let prior = owner.insert(v, ci);
            if prior.is_some_and(|o| o != ci) || base.is_base(v) {
                r.offend(|| {
                    Witness::new(
                        format!("vertex {v} of S_T is an inner node of curve {ci} and lies on another curve or is a base vertex"),
                        json!({"vertex": v, "curve": ci, "other": prior}),
                    )
                });
            }
        }
        for (s, w) in c.nodes.windows(2).enumerate() {
            for f in common_faces(k, &w[0], &w[1]) {
                if let (Some(p), Some(q)) = (local(k, f, &w[0]), local(k, f, &w[1])) {
                    by_face.entry(f).or_default().push((ci, s, [p, q]));
                }
            }
        }
    }
    let curves = &emb.curves;
    let ends = |c: &Curve| [c.a, c.b];
    let mut faces: Vec<&FaceId> = by_face.keys().collect();
    faces.sort();
    for f in faces {
        let segs = &by_face[f];
        for (i, &(c1, s1, p)) in segs.iter().enumerate() {
            for &(c2, s2, q) in &segs[i + 1..] {
                r.examined += 1;
                if !meet(p, q) {
                    continue;
                }
                // The one point two segments may share: a node of both (consecutive
                // segments of one curve, or a common end of two curves), met only there.
                let x = [p[0], p[1]].into_iter().find(|x| *x == q[0] || *x == q[1]);
                let allowed = x.is_some_and(|x| {
                    let permitted = if c1 == c2 {
                        s1.abs_diff(s2) == 1
                    } else {
                        let (e1, e2) = (ends(&curves[c1]), ends(&curves[c2]));
                        e1.iter()
                            .any(|&v| e2.contains(&v) && local(k, *f, &Node::Vertex(v)) == Some(x))
                    };
                    permitted && only_at(p, q, x)
                });
                if !allowed {
                    r.offend(|| {
                        Witness::new(
                            format!("curves {c1} and {c2} (segments {s1}, {s2}) meet inside triangle {} of S_T", f.0),
                            json!({"curves": [c1, c2], "segments": [s1, s2], "face": f.0}),
                        )
                    });
                }
            }
        }
    }
    r
}

/// No node of a curve can be moved to shorten it by more than the rounding bound of that
/// gain (`shorten::gain_bound`, derived from the precision; measured by the shortening's own
/// local rules: an edge node along its edge in the unfolded pair of triangles, a vertex node
/// off its vertex where the angle on one side is below π). The worst deviation is the
/// largest gain in units of its node's bound (≤ 1 holds).
pub fn check_shortest(k: &SimplicialSurface, emb: &Embedding) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-geodesic-shortest",
        "no node of an embedded edge can move to shorten it beyond the rounding bound of the gain",
    );
    r.tolerance = Some(1.0);
    let (mut worst, mut worst_gain, mut lo, mut hi) = (0.0f64, 0.0f64, f64::INFINITY, 0.0f64);
    for (ci, c) in emb.curves.iter().enumerate() {
        for i in 1..c.nodes.len().saturating_sub(1) {
            r.examined += 1;
            let g = shorten::relative_gain(k, &c.nodes, i);
            let b = shorten::gain_bound(k, &c.nodes, i);
            let ratio = g / b;
            worst = dev_max(worst, ratio);
            worst_gain = dev_max(worst_gain, g);
            lo = lo.min(b);
            hi = hi.max(b);
            if !(ratio <= 1.0) {
                r.offend(|| {
                    Witness::new(
                        format!("curve {ci} ({}, {}), node {i} {:?}: a local move shortens it by {g:.3e} of its two segments, bound {b:.1e}", c.a, c.b, c.nodes[i]),
                        json!({"curve": ci, "node": i, "gain": g, "bound": b}),
                    )
                });
            }
        }
    }
    r.worst_deviation = Some(worst);
    r.note = format!(
        "largest relative gain {worst_gain:.3e}; largest gain / its rounding bound {worst:.3}; bounds {lo:.1e}..{hi:.1e} (64 u·(|P|+|X|+|N|+Λ)·m/(|PX|+|XN|))"
    );
    r
}

/// Each base face's curved triangle is one region of S_T cut along the curves, a disk
/// (V − E + F = 1) bounded by one cycle made of exactly the three curves of the face, every
/// side of which names the face.
pub fn check_curved_disk(ov: &Overlay, base: &BaseMesh, emb: &Embedding) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-curved-disk",
        "each curved triangle is a disk bounded by the three embedded edges of its base face",
    );
    for (f, d) in disk_defects(ov, base, emb) {
        r.examined += 1;
        if !d.is_empty() {
            r.offend(|| {
                Witness::new(
                    format!("base face {f}: {d:?}"),
                    json!({"face": f, "defects": format!("{d:?}")}),
                )
            });
        }
    }
    r
}

/// Floater's map is a bijection of each curved triangle onto its base triangle: every piece
/// positively oriented (exact orient2d on the stored image coordinates), the boundary on the
/// three sides in order, and the images' areas summing to the triangle's 1/2 (degree one)
/// within the rounding bound (n + 6)·u·Σ|area|. Affine, orientation-preserving maps carry
/// the orientation into every T_v (`floater` module doc).
pub fn check_bijective(ov: &Overlay, base: &BaseMesh, maps: &[RegionMap]) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-param-bijective",
        "every piece of a triangle of S_T maps to a positively oriented triangle of its base triangle (so of every T_v)",
    );
    let mut worst = 0.0f64;
    let mapped: std::collections::HashSet<u32> = maps.iter().map(|m| m.face).collect();
    for (f, _) in base.faces() {
        if !mapped.contains(&f) {
            r.examined += 1;
            r.offend(|| Witness::new(format!("base face {f} has no map"), json!({"face": f})));
        }
    }
    for m in maps {
        let (mut sum, mut abs) = (0.0, 0.0);
        for &pi in &m.pieces {
            r.examined += 1;
            let v = ov.pieces[pi].v;
            let uv = v.map(|x| m.uv.get(&x).copied().unwrap_or([f64::NAN; 2]));
            let o = orient(uv[0], uv[1], uv[2]);
            sum += o / 2.0;
            abs += o.abs() / 2.0;
            if !(o > 0.0) {
                r.offend(|| {
                    Witness::new(
                        format!("base face {}: piece {v:?} of triangle {} of S_T maps to signed area {:.3e}", m.face, ov.pieces[pi].fine.0, o / 2.0),
                        json!({"face": m.face, "piece": v, "fine": ov.pieces[pi].fine.0, "area": o / 2.0}),
                    )
                });
            }
        }
        let tol = (m.pieces.len() as f64 + 6.0) * f64::EPSILON * abs;
        let dev = (sum - 0.5).abs();
        worst = dev_max(worst, dev);
        r.examined += 1;
        if !(dev <= tol) {
            r.offend(|| {
                Witness::new(
                    format!(
                        "base face {}: the images cover area {sum:.17} ≠ 1/2 (tolerance {tol:.1e})",
                        m.face
                    ),
                    json!({"face": m.face, "area": sum, "tolerance": tol}),
                )
            });
        }
    }
    r.worst_deviation = Some(worst);
    r.note = format!("orientation exact (Shewchuk orient2d); largest |Σ area − 1/2| {worst:.1e}");
    r
}

/// The checks of an embedding that exists (stage order).
pub fn run(
    k: &SimplicialSurface,
    base: &BaseMesh,
    e: &super::embedded::Embedded,
) -> Vec<CheckResult> {
    vec![
        check_on_surface(k, &e.emb),
        check_disjoint(k, base, &e.emb),
        check_shortest(k, &e.emb),
        check_curved_disk(&e.overlay, base, &e.emb),
        check_bijective(&e.overlay, base, &e.maps),
    ]
}

/// The embedding exists: an offence naming the failure when it does not (the base mesh
/// could not be embedded; the simplification's parameters were used instead).
pub fn check_embedded(failure: Option<&super::embedded::Failure>) -> CheckResult {
    let mut r = CheckResult::new(
        "AF-embedding",
        "every base edge is embedded in S_T and the curved triangles are mapped",
    );
    r.examined = 1;
    if let Some(f) = failure {
        r.offend(|| {
            Witness::new(
                format!("no embedding: {} (base faces {:?})", f.what, f.faces),
                json!({"what": f.what, "faces": f.faces}),
            )
        });
    }
    r
}
