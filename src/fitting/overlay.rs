//! The curved triangles (seed 002, Part II: "we map the vertices in each 'curved' triangle
//! separately"): the triangles of S_T cut along the embedded edges, grouped into one region
//! per base face. SPEC `AF-curved-disk`.
//!
//! Every triangle of S_T is cut by the segments of the curves that cross it (chords between
//! two points of its boundary) into convex polygons, each triangulated by ears of positive
//! area, decided exactly (Shewchuk's orient2d) in the triangle's reference frame (corners at
//! (0, 0), (1, 0), (0, 1)). These *pieces* are what the parametrization maps. Pieces sharing
//! an edge that is no curve segment are in one region; the side of a curve segment a piece is
//! on names its base face (left of a → b is the face holding the directed edge a → b).

use super::base::BaseMesh;
use super::geodesic::{common_faces, Embedding, Node};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::UnionFind;
use std::collections::{HashMap, HashSet};

/// A triangle of the overlay inside one triangle of S_T.
#[derive(Debug, Clone, Copy)]
pub struct Piece {
    /// The triangle of S_T it lies in.
    pub fine: FaceId,
    /// Overlay vertices, counterclockwise.
    pub v: [u32; 3],
}

/// S_T cut along the curves.
#[derive(Debug, Clone)]
pub struct Overlay {
    /// Overlay vertex positions: the vertices of S_T (same ids), then the edge nodes.
    pub points: Vec<[f64; 3]>,
    /// Overlay ids of each curve's nodes.
    pub curve_ids: Vec<Vec<u32>>,
    /// The pieces.
    pub pieces: Vec<Piece>,
    /// Region of each piece (0..regions).
    pub region: Vec<u32>,
    /// Number of regions.
    pub regions: usize,
    /// Base face slot named by each region's sides (None: unnamed or named twice).
    pub face_of_region: Vec<Option<u32>>,
    /// Regions whose sides name different base faces.
    pub conflicts: Vec<u32>,
}

/// Why the overlay could not be built (the embedding is not a set of disjoint curves on S_T).
#[derive(Debug, Clone, thiserror::Error)]
pub enum OverlayError {
    /// Two consecutive nodes share no triangle of S_T.
    #[error("curve {curve}: segment {seg} leaves the surface")]
    OffSurface {
        /// Curve index.
        curve: usize,
        /// Segment index.
        seg: usize,
    },
    /// Chords of one triangle of S_T cross.
    #[error("curves cross inside triangle {0} of S_T")]
    Crossing(u32),
    /// A piece of zero area.
    #[error("a piece of triangle {0} of S_T has no positive-area triangulation")]
    Degenerate(u32),
}

const REF: [[f64; 2]; 3] = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];

/// The orientation of (a, b, c), its sign exact (the crate's one predicate).
pub use crate::numeric::predicates::orient2_det as orient;

/// Ear triangulation of a convex polygon (points may be collinear along its sides).
fn triangulate(poly: &[usize], at: &[[f64; 2]], out: &mut Vec<[usize; 3]>) -> bool {
    let mut idx = poly.to_vec();
    let pos = |i: &[usize], j: usize| {
        let n = i.len();
        orient(at[i[(j + n - 1) % n]], at[i[j]], at[i[(j + 1) % n]]) > 0.0
    };
    while idx.len() > 3 {
        let n = idx.len();
        let ear = (0..n).find(|&j| {
            if !pos(&idx, j) {
                return false;
            }
            let mut rest = idx.clone();
            rest.remove(j);
            (0..rest.len()).any(|i| pos(&rest, i))
        });
        let Some(j) = ear else { return false };
        out.push([idx[(j + n - 1) % n], idx[j], idx[(j + 1) % n]]);
        idx.remove(j);
    }
    if idx.len() == 3 && pos(&idx, 1) {
        out.push([idx[0], idx[1], idx[2]]);
        true
    } else {
        false
    }
}

/// Cut S_T along the curves of `emb` and group the pieces (module doc).
pub fn build(
    k: &SimplicialSurface,
    base: &BaseMesh,
    emb: &Embedding,
) -> Result<Overlay, OverlayError> {
    let n = k.vertex_slots();
    let mut points: Vec<[f64; 3]> = (0..n).map(|i| k.position(VertexId(i as u32))).collect();
    // Edge nodes per edge of S_T: (t from the smaller end, overlay id).
    let mut on_edge: HashMap<(u32, u32), Vec<(f64, u32)>> = HashMap::new();
    let mut curve_ids = Vec::new();
    let mut chords: HashMap<u32, Vec<(u32, u32)>> = HashMap::new();
    for (ci, c) in emb.curves.iter().enumerate() {
        let mut ids = Vec::new();
        for node in &c.nodes {
            match *node {
                Node::Vertex(v) => ids.push(v),
                Node::Edge { a, b, t } => {
                    let id = points.len() as u32;
                    points.push(node.point(k).unwrap_or([f64::NAN; 3]));
                    on_edge.entry((a, b)).or_default().push((t, id));
                    ids.push(id);
                }
            }
        }
        for (s, w) in c.nodes.windows(2).enumerate() {
            let cf = common_faces(k, &w[0], &w[1]);
            match cf.len() {
                1 => chords
                    .entry(cf[0].0)
                    .or_default()
                    .push((ids[s], ids[s + 1])),
                2 => {}
                _ => return Err(OverlayError::OffSurface { curve: ci, seg: s }),
            }
        }
        curve_ids.push(ids);
    }
    for l in on_edge.values_mut() {
        l.sort_by(|x, y| x.0.total_cmp(&y.0));
    }
    let mut pieces = Vec::new();
    for f in k.faces() {
        let c = k.face(f).map(|v| v.0);
        let (mut ids, mut at) = (Vec::new(), Vec::new());
        for i in 0..3 {
            let (u, w) = (c[i], c[(i + 1) % 3]);
            ids.push(u);
            at.push(REF[i]);
            if let Some(l) = on_edge.get(&(u.min(w), u.max(w))) {
                let seq: Vec<(f64, u32)> = if u < w {
                    l.clone()
                } else {
                    l.iter().rev().map(|&(t, id)| (1.0 - t, id)).collect()
                };
                for (s, id) in seq {
                    let (p, q) = (REF[i], REF[(i + 1) % 3]);
                    ids.push(id);
                    at.push([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]);
                }
            }
        }
        let mut polys: Vec<Vec<usize>> = vec![(0..ids.len()).collect()];
        for &(p, q) in chords.get(&f.0).map_or(&[][..], |v| v.as_slice()) {
            let (Some(i), Some(j)) = (
                ids.iter().position(|&x| x == p),
                ids.iter().position(|&x| x == q),
            ) else {
                return Err(OverlayError::Crossing(f.0));
            };
            let Some(pi) = polys
                .iter()
                .position(|poly| poly.contains(&i) && poly.contains(&j))
            else {
                return Err(OverlayError::Crossing(f.0));
            };
            let poly = polys.swap_remove(pi);
            let (x, y) = (
                poly.iter().position(|&z| z == i).unwrap_or(0),
                poly.iter().position(|&z| z == j).unwrap_or(0),
            );
            let (x, y) = (x.min(y), x.max(y));
            let a: Vec<usize> = poly[x..=y].to_vec();
            let b: Vec<usize> = poly[y..].iter().chain(&poly[..=x]).copied().collect();
            polys.push(a);
            polys.push(b);
        }
        let mut tris = Vec::new();
        for poly in &polys {
            if !triangulate(poly, &at, &mut tris) {
                return Err(OverlayError::Degenerate(f.0));
            }
        }
        pieces.extend(tris.into_iter().map(|t| Piece {
            fine: f,
            v: t.map(|i| ids[i]),
        }));
    }
    let (region, regions) = group(&pieces, &curve_ids);
    let mut ov = Overlay {
        points,
        curve_ids,
        pieces,
        region,
        regions,
        face_of_region: Vec::new(),
        conflicts: Vec::new(),
    };
    name_regions(&mut ov, base, emb);
    Ok(ov)
}

/// Union of pieces across edges that are no curve segment.
fn group(pieces: &[Piece], curve_ids: &[Vec<u32>]) -> (Vec<u32>, usize) {
    let cut: HashSet<(u32, u32)> = curve_ids
        .iter()
        .flat_map(|ids| ids.windows(2).map(|w| (w[0].min(w[1]), w[0].max(w[1]))))
        .collect();
    let mut by_edge: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (i, p) in pieces.iter().enumerate() {
        for j in 0..3 {
            let (a, b) = (p.v[j], p.v[(j + 1) % 3]);
            by_edge.entry((a.min(b), a.max(b))).or_default().push(i);
        }
    }
    let mut classes = UnionFind::new(pieces.len());
    for (e, ps) in &by_edge {
        if cut.contains(e) {
            continue;
        }
        for w in ps.windows(2) {
            classes.union(w[0], w[1]);
        }
    }
    // Regions are numbered by their first piece, so the numbering depends only on the
    // partition (not on the hash map's order of the unions, nor on which piece is a root).
    let mut id: HashMap<usize, u32> = HashMap::new();
    let region = (0..pieces.len())
        .map(|i| {
            let r = classes.find(i);
            let next = id.len() as u32;
            *id.entry(r).or_insert(next)
        })
        .collect();
    (region, id.len())
}

/// Name each region by the base faces on its side of the curve segments bounding it.
fn name_regions(ov: &mut Overlay, base: &BaseMesh, emb: &Embedding) {
    let mut dir: HashMap<(u32, u32), usize> = HashMap::new();
    for (i, p) in ov.pieces.iter().enumerate() {
        for j in 0..3 {
            dir.insert((p.v[j], p.v[(j + 1) % 3]), i);
        }
    }
    let mut named: Vec<Option<u32>> = vec![None; ov.regions];
    let mut bad: HashSet<u32> = HashSet::new();
    for (c, ids) in emb.curves.iter().zip(&ov.curve_ids) {
        for w in ids.windows(2) {
            for (e, f) in [
                ((w[0], w[1]), base.face_of_edge(c.a, c.b)),
                ((w[1], w[0]), base.face_of_edge(c.b, c.a)),
            ] {
                let Some(&p) = dir.get(&e) else { continue };
                let r = ov.region[p];
                match (named[r as usize], f) {
                    (None, Some(f)) => named[r as usize] = Some(f),
                    (Some(g), Some(f)) if g == f => {}
                    _ => {
                        bad.insert(r);
                    }
                }
            }
        }
    }
    for &r in &bad {
        named[r as usize] = None;
    }
    ov.face_of_region = named;
    ov.conflicts = bad.into_iter().collect();
    ov.conflicts.sort_unstable();
}

/// Why a base face's region is not a disk bounded by its three curves.
#[derive(Debug, Clone, PartialEq)]
pub enum DiskDefect {
    /// No region, or more than one, is named by the face.
    Regions(usize),
    /// A region's sides name different base faces.
    Conflict,
    /// V − E + F of the region is not 1.
    Euler(i64),
    /// The region's boundary is not one cycle of the face's three curves.
    Boundary,
}

/// The regions of each live base face slot, and the defects of each (empty: a disk bounded
/// by the three curves of the face, in order).
pub fn disk_defects(ov: &Overlay, base: &BaseMesh, emb: &Embedding) -> Vec<(u32, Vec<DiskDefect>)> {
    let mut regions_of: HashMap<u32, Vec<u32>> = HashMap::new();
    for (r, f) in ov.face_of_region.iter().enumerate() {
        if let Some(f) = f {
            regions_of.entry(*f).or_default().push(r as u32);
        }
    }
    let mut pieces_of: Vec<Vec<usize>> = vec![Vec::new(); ov.regions];
    for (i, &r) in ov.region.iter().enumerate() {
        pieces_of[r as usize].push(i);
    }
    let mut out = Vec::new();
    for (f, c) in base.faces() {
        let mut d = Vec::new();
        let rs = regions_of.get(&f).cloned().unwrap_or_default();
        if rs.len() != 1 {
            d.push(DiskDefect::Regions(rs.len()));
            out.push((f, d));
            continue;
        }
        let r = rs[0];
        if ov.conflicts.contains(&r) {
            d.push(DiskDefect::Conflict);
        }
        let ps = &pieces_of[r as usize];
        let mut verts = HashSet::new();
        let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
        for &p in ps {
            let v = ov.pieces[p].v;
            for j in 0..3 {
                verts.insert(v[j]);
                let (a, b) = (v[j], v[(j + 1) % 3]);
                *edges.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
        let chi = verts.len() as i64 - edges.len() as i64 + ps.len() as i64;
        if chi != 1 {
            d.push(DiskDefect::Euler(chi));
        }
        // The boundary: edges of one piece of the region; expected, the segments of the
        // three curves of the face.
        let bd: HashSet<(u32, u32)> = edges
            .iter()
            .filter(|(_, &m)| m == 1)
            .map(|(&e, _)| e)
            .collect();
        let mut want: HashSet<(u32, u32)> = HashSet::new();
        let mut segs = 0;
        for i in 0..3 {
            if let Some(ci) = emb
                .index
                .get(&(c[i].min(c[(i + 1) % 3]), c[i].max(c[(i + 1) % 3])))
            {
                for w in ov.curve_ids[*ci].windows(2) {
                    want.insert((w[0].min(w[1]), w[0].max(w[1])));
                    segs += 1;
                }
            }
        }
        let mut deg: HashMap<u32, u32> = HashMap::new();
        for &(a, b) in &bd {
            *deg.entry(a).or_default() += 1;
            *deg.entry(b).or_default() += 1;
        }
        if bd != want || want.len() != segs || deg.values().any(|&x| x != 2) {
            d.push(DiskDefect::Boundary);
        }
        out.push((f, d));
    }
    out
}
