//! Def. 3.1.3(ii): two simplices of K meet, if at all, in a common face. For a triangle list in
//! R³ this means: no two vertices at the same point, and two triangles meet exactly in their
//! shared vertex or edge (or not at all). Decided exactly (see [`super::predicates`]), with a
//! uniform grid (or, for inputs that do not suit one, an R*-tree) over the triangles' bounding
//! boxes so only nearby pairs are tested ([`super::grid`]: the same candidates either way).

use super::fans::{face_box, fans, search_boxes, separated, star_pairs, FaceBox, HIGH_DEGREE};
use super::grid::BoxIndex;
pub use super::predicates::triangles_meet_improperly;
use crate::mesh::RawMesh;
use crate::report::{Check, CheckResult, Witness};
use rayon::prelude::*;
use rstar::{Envelope, RTree, AABB};
use serde_json::json;
use std::cmp::Ordering;

/// Two distinct vertices of K at the same point of R³ violate Def. 3.1.3(ii) (two 0-simplices
/// meet but are not a common face).
pub fn coincident_vertices(raw: &RawMesh, referenced: &[bool]) -> CheckResult {
    let mut r = Check::new("D3.1.3(ii)(vertices)", "no two vertices at the same point");
    let mut vs: Vec<u32> = (0..raw.positions.len() as u32)
        .filter(|&v| {
            referenced.get(v as usize).copied().unwrap_or(false)
                && raw.positions[v as usize].iter().all(|c| c.is_finite())
        })
        .collect();
    r.examined(vs.len() as u64);
    // -0.0 and 0.0 are the same point: compare as numbers, not bits.
    let key = |v: &u32| raw.positions[*v as usize];
    vs.sort_by(|a, b| {
        let (pa, pb) = (key(a), key(b));
        pa.partial_cmp(&pb).unwrap_or(Ordering::Equal)
    });
    for w in vs.windows(2) {
        if key(&w[0]) == key(&w[1]) {
            r.offend(|| {
                Witness::new(
                    format!(
                        "{} and {} are both at {:?}",
                        raw.describe_vertex(w[0] as usize),
                        raw.describe_vertex(w[1] as usize),
                        key(&w[0])
                    ),
                    json!({"vertices": [w[0], w[1]]}),
                )
            });
        }
    }
    r.finish("")
}

/// Def. 3.1.3(ii) is decided by the first improper pair; counting every pair of a badly
/// tangled mesh is quadratic in time and memory (a fuzzed 500-face tangle has 23,781 crossing
/// pairs), so the search stops once this many offending pairs are found and the count is then
/// reported as a lower bound.
pub const MAX_COUNTED_INTERSECTIONS: usize = 1000;
/// Faces whose candidate pairs are tested together before the cap is looked at.
const INTERSECTION_CHUNK: usize = 16;
/// Chunks evaluated in one parallel block, at most.
const MAX_BLOCK: usize = 256;

/// A face of the general search: its index, corners and search boxes.
type SearchFace = (u32, [u32; 3], Vec<AABB<[f64; 3]>>);

/// Def. 3.1.3(ii) for triangles: every pair of triangles meets only in a common face.
/// `eligible[f]` marks the faces that are well-formed, finite and non-degenerate (the others
/// are reported by their own checks; exact predicates on a degenerate triangle answer a
/// different question). Pairs with identical vertex sets are duplicates, reported elsewhere.
pub fn triangles_meet_properly(raw: &RawMesh, eligible: &[bool]) -> CheckResult {
    triangles_meet_properly_pairs(raw, eligible).0
}

/// [`triangles_meet_properly`] with every offending pair it found (the result lists only the
/// first few as witnesses; a caller that locates them, SPEC `AF-embedded`, needs all, up to
/// [`MAX_COUNTED_INTERSECTIONS`]).
pub fn triangles_meet_properly_pairs(
    raw: &RawMesh,
    eligible: &[bool],
) -> (CheckResult, Vec<(u32, u32)>) {
    let mut r = Check::new(
        "D3.1.3(ii)(triangles)",
        "triangles meet only in common faces (no self-intersection)",
    );
    let pos = &raw.positions;
    let eligible_faces = || {
        raw.faces
            .iter()
            .enumerate()
            .filter(|(f, _)| eligible.get(*f).copied().unwrap_or(false))
            .map(|(f, t)| (f as u32, *t))
    };
    let full: Vec<FaceBox> = eligible_faces()
        .map(|(face, t)| FaceBox {
            face,
            env: face_box(raw, t),
        })
        .collect();
    r.examined(full.len() as u64);
    // Stars of high-degree vertices first (see `fans`): their pairs are decided there, and
    // their corners are cut from the boxes of the general search.
    let fans = fans(raw, eligible, full);
    let mut hits: Vec<(u32, u32)> = Vec::new();
    let mut tested = 0u64;
    for (v, star) in fans.star.iter().enumerate() {
        if star.is_empty() {
            continue;
        }
        let (h, n) = star_pairs(raw, v as u32, star);
        hits.extend(h);
        tested += n;
    }
    hits.sort_unstable();
    hits.dedup();
    hits.truncate(MAX_COUNTED_INTERSECTIONS);
    // The general search: triangles with no high-degree corner in one index; the triangles of
    // each star in a tree of their own, found through an index of the stars' boxes, so that a
    // star's own pairs (decided above) are never enumerated.
    let faces: Vec<SearchFace> = eligible_faces()
        .map(|(face, t)| (face, t, search_boxes(raw, t, &fans)))
        .collect();
    let mut plain = Vec::new();
    let mut per_star: std::collections::BTreeMap<u32, Vec<FaceBox>> = Default::default();
    for (face, t, bs) in &faces {
        let highs: Vec<u32> = t.iter().copied().filter(|&x| fans.is_high(x)).collect();
        for env in bs {
            let fb = FaceBox {
                face: *face,
                env: *env,
            };
            if highs.is_empty() {
                plain.push(fb);
            } else {
                for &v in &highs {
                    per_star.entry(v).or_default().push(fb.clone());
                }
            }
        }
    }
    let plain_index = BoxIndex::new(plain);
    let broad = match plain_index {
        BoxIndex::Grid(_) => "uniform-grid",
        BoxIndex::Tree(_) => "R*-tree",
    };
    let star_index = RTree::bulk_load(
        per_star
            .iter()
            .filter_map(|(&v, bs)| {
                let mut env = bs.first()?.env;
                for b in bs {
                    env.merge(&b.env);
                }
                Some(FaceBox { face: v, env })
            })
            .collect(),
    );
    let star_trees: std::collections::BTreeMap<u32, RTree<FaceBox>> = per_star
        .into_iter()
        .map(|(v, bs)| (v, RTree::bulk_load(bs)))
        .collect();
    let shares_high =
        |t1: [u32; 3], t2: [u32; 3]| t1.iter().any(|&x| fans.is_high(x) && t2.contains(&x));
    // Faces in index order, a chunk at a time, so that the search can stop after the chunk in
    // which the cap is reached and still give the same answer on every run and thread count.
    // The chunks are evaluated a block at a time (parallel inside a block), the blocks doubling
    // up to MAX_BLOCK chunks: one fork-join per block instead of per chunk, and at most about
    // twice the work of the chunks up to the cap when a tangled mesh stops the search early.
    let mut stopped_at = None;
    let counter = std::sync::atomic::AtomicU64::new(0);
    let counted = &counter;
    let star_capped = hits.len() >= MAX_COUNTED_INTERSECTIONS;
    let face_hits = |(f1, t1, bs): &SearchFace, cand: &mut Vec<u32>, out: &mut Vec<(u32, u32)>| {
        let (f1, t1) = (*f1, *t1);
        let mut k1 = t1;
        k1.sort_unstable();
        cand.clear();
        for env in bs {
            plain_index.each_intersecting_above(env, f1, |o| cand.push(o.face));
            for s in star_index.locate_in_envelope_intersecting(env) {
                if t1.contains(&s.face) {
                    continue;
                }
                if let Some(tr) = star_trees.get(&s.face) {
                    cand.extend(
                        tr.locate_in_envelope_intersecting(env)
                            .map(|o| o.face)
                            .filter(|&g| g > f1),
                    );
                }
            }
        }
        cand.sort_unstable();
        cand.dedup();
        let mut found = 0;
        for &f2 in cand.iter() {
            let t2 = raw.faces[f2 as usize];
            let mut k2 = t2;
            k2.sort_unstable();
            if k1 == k2 || shares_high(t1, t2) || separated(pos, t1, t2) {
                continue;
            }
            counted.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            if triangles_meet_improperly(pos, t1, t2) {
                out.push((f1, f2));
                found += 1;
                if found == MAX_COUNTED_INTERSECTIONS {
                    break;
                }
            }
        }
    };
    let chunks: Vec<&[SearchFace]> = faces.chunks(INTERSECTION_CHUNK).collect();
    let mut start = 0;
    let mut block = 1;
    'blocks: while start < chunks.len() && !star_capped {
        let end = (start + block).min(chunks.len());
        let found: Vec<Vec<(u32, u32)>> = chunks[start..end]
            .par_iter()
            .map_init(Vec::new, |cand, chunk| {
                let mut out = Vec::new();
                for face in chunk.iter() {
                    face_hits(face, cand, &mut out);
                }
                out
            })
            .collect();
        for (chunk, mut found) in chunks[start..end].iter().zip(found) {
            found.sort_unstable();
            hits.append(&mut found);
            if hits.len() >= MAX_COUNTED_INTERSECTIONS {
                stopped_at = chunk.last().map(|x| x.0);
                break 'blocks;
            }
        }
        start = end;
        block = (2 * block).min(MAX_BLOCK);
    }
    for &(a, b) in &hits {
        r.offend(|| {
            Witness::new(
                format!(
                    "{} {:?} and {} {:?} intersect outside a common face",
                    raw.describe_face(a as usize),
                    raw.faces[a as usize],
                    raw.describe_face(b as usize),
                    raw.faces[b as usize]
                ),
                json!({"faces": [a, b]}),
            )
        });
    }
    let tested = tested + counter.load(std::sync::atomic::Ordering::Relaxed);
    let high = fans.star.iter().filter(|s| !s.is_empty()).count();
    if star_capped {
        r.note = format!(
            "exact orientation predicates; search stopped in the stars of vertices of degree ≥ {HIGH_DEGREE} after {} offending pairs (cap {MAX_COUNTED_INTERSECTIONS}): the count is a lower bound",
            r.offenders
        );
        return (r.finish(""), hits);
    }
    if let Some(last) = stopped_at {
        r.note = format!(
            "exact orientation predicates; {broad} candidate pairs; search stopped after {} offending pairs (cap {MAX_COUNTED_INTERSECTIONS}, first faces up to {}): the count is a lower bound",
            r.offenders,
            raw.describe_face(last as usize)
        );
        return (r.finish(""), hits);
    }
    r.note = format!(
        "exact orientation predicates; {broad} candidate pairs: {tested} decided exactly (after a certified f64 plane-separation filter; {high} stars of degree ≥ {HIGH_DEGREE} searched by corner directions)"
    );
    (r.finish(""), hits)
}
