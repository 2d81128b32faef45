//! Sec. 5.4: the affine atlas on M ∖ Z. Zero points and the faces attached to them are
//! removed; chart U_α is the union of the surviving faces in the k-ring of vertex p_α, and
//! φ_α(p) = ∫_{p_α}^p ω, developed face by face (each face's image is affine in the face).
//!
//! The developing map is stored per face, so a chart that is not simply connected shows up
//! as a face reached twice with different images (the period of ω around the hole) instead of
//! being silently averaged.

use super::cochain::{face_halfedges, EdgeIndex};
use super::error::MsError;
use super::hodge::OneForm;
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use std::collections::{BTreeMap, BTreeSet, HashMap, VecDeque};

/// A point of a chart's plane.
pub type P2 = [f64; 2];

/// One chart (U_α, φ_α): its faces and their developed images.
#[derive(Debug, Clone)]
pub struct Chart {
    /// p_α.
    pub centre: VertexId,
    /// The faces of U_α (sorted), with the image of their corners (in the order of
    /// `SimplicialSurface::face`).
    pub faces: BTreeMap<FaceId, [P2; 3]>,
    /// Σ|ω| along the developing path of each face (rounding magnitude of its image).
    pub path_magnitude: BTreeMap<FaceId, f64>,
    /// Largest disagreement between the developed image of a shared vertex reached by two
    /// paths (closure rounding, or a period when U_α is not simply connected).
    pub develop_defect: f64,
    /// Faces of the k-ring not reachable from the first face through interior edges.
    pub unreached: usize,
}

impl Chart {
    /// Radius of the image: max |φ_α(v)|.
    pub fn radius(&self) -> f64 {
        self.faces
            .values()
            .flat_map(|t| t.iter())
            .map(|p| p[0].hypot(p[1]))
            // NaN-propagating: the radius scales tolerances of the atlas checks.
            .fold(0.0, crate::report::dev_max)
    }
}

/// The atlas: removed faces, charts, and the overlapping pairs.
#[derive(Debug, Clone)]
pub struct Atlas {
    /// The k of the k-rings.
    pub k_ring: u32,
    /// Zero points removed (Sec. 5.4 step 2).
    pub zeros: Vec<VertexId>,
    /// removed\[f\]: face f is attached to a zero.
    pub removed: Vec<bool>,
    /// The charts (index = chart id α).
    pub charts: Vec<Chart>,
    /// For every face, the charts containing it.
    pub charts_of_face: Vec<Vec<u32>>,
    /// Overlapping pairs (α < β), with their common faces.
    pub pairs: BTreeMap<(u32, u32), Vec<FaceId>>,
}

/// Faces within the k-ring of v: faces incident to vertices at distance < k.
fn ring_faces(k: &SimplicialSurface, v: VertexId, ring: u32) -> BTreeSet<FaceId> {
    let mut dist: HashMap<VertexId, u32> = HashMap::from([(v, 0)]);
    let mut q = VecDeque::from([v]);
    while let Some(u) = q.pop_front() {
        let d = dist[&u];
        if d + 1 >= ring {
            continue;
        }
        for &h in k.outgoing(u) {
            let w = k.dest(h);
            if let std::collections::hash_map::Entry::Vacant(e) = dist.entry(w) {
                e.insert(d + 1);
                q.push_back(w);
            }
        }
    }
    dist.keys()
        .flat_map(|&u| k.faces_around(u).iter().copied())
        .collect()
}

/// Develop ω over `faces` starting at the first face that contains `centre` (centre ↦ 0).
pub fn develop(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    om: &OneForm,
    centre: VertexId,
    faces: &BTreeSet<FaceId>,
) -> Chart {
    let mut img: BTreeMap<FaceId, [P2; 3]> = BTreeMap::new();
    let mut mag: BTreeMap<FaceId, f64> = BTreeMap::new();
    let mut defect: f64 = 0.0;
    let mut vertex_seen: HashMap<VertexId, P2> = HashMap::new();
    let start = faces
        .iter()
        .copied()
        .find(|&f| k.face(f).contains(&centre))
        .or_else(|| faces.iter().next().copied());
    let mut q = VecDeque::new();
    // One image per vertex: a vertex reached again (closing a fan, or around a hole) keeps its
    // first image and the disagreement is recorded, so neighbouring face images share their
    // corners exactly and the exact overlap test sees no rounding slivers.
    let mut placed: HashMap<VertexId, P2> = HashMap::new();
    if let Some(f0) = start {
        let vs = k.face(f0);
        let base = vs.iter().position(|&v| v == centre).unwrap_or(0);
        let hs = face_halfedges(f0);
        let mut t = [[0.0; 2]; 3];
        let mut m = 0.0;
        // Corner base ↦ 0, then walk the face's half-edges from it.
        let mut p = [0.0, 0.0];
        for s in 0..2 {
            let h = hs[(base + s) % 3];
            let d = om.at(ei, h);
            p = [p[0] + d[0], p[1] + d[1]];
            m += d[0].abs() + d[1].abs() + om.mag[ei.edge(h).0 as usize];
            t[(base + s + 1) % 3] = p;
        }
        for (c, &v) in vs.iter().enumerate() {
            placed.insert(v, t[c]);
        }
        img.insert(f0, t);
        mag.insert(f0, m);
        q.push_back(f0);
    }
    while let Some(f) = q.pop_front() {
        let t = img[&f];
        let m0 = mag[&f];
        let vs = k.face(f);
        for (c, &v) in vs.iter().enumerate() {
            match vertex_seen.get(&v) {
                Some(p) => {
                    defect = crate::report::dev_max(defect, (p[0] - t[c][0]).hypot(p[1] - t[c][1]))
                }
                None => {
                    vertex_seen.insert(v, t[c]);
                }
            }
        }
        for (c, &h) in face_halfedges(f).iter().enumerate() {
            let tw = k.twin(h);
            let g = k.face_of(tw);
            if !faces.contains(&g) || img.contains_key(&g) {
                continue;
            }
            // g shares the edge (vs[c], vs[c+1]); its third corner is reached by ω from vs[c+1].
            let gv = k.face(g);
            let (a, b) = (vs[c], vs[(c + 1) % 3]);
            let mut tg = [[0.0; 2]; 3];
            let mut third = None;
            for (cg, &x) in gv.iter().enumerate() {
                if x == a {
                    tg[cg] = t[c];
                } else if x == b {
                    tg[cg] = t[(c + 1) % 3];
                } else {
                    third = Some(cg);
                }
            }
            let Some(cg) = third else { continue };
            let Some(hb) = k.halfedge(b, gv[cg]) else {
                continue;
            };
            let d = om.at(ei, hb);
            let pb = t[(c + 1) % 3];
            let cand = [pb[0] + d[0], pb[1] + d[1]];
            tg[cg] = match placed.get(&gv[cg]) {
                Some(p) => {
                    defect = crate::report::dev_max(defect, (p[0] - cand[0]).hypot(p[1] - cand[1]));
                    *p
                }
                None => {
                    placed.insert(gv[cg], cand);
                    cand
                }
            };
            img.insert(g, tg);
            mag.insert(
                g,
                m0 + d[0].abs() + d[1].abs() + om.mag[ei.edge(hb).0 as usize],
            );
            q.push_back(g);
        }
    }
    // Shared vertices of the last faces are compared too.
    for (f, t) in &img {
        for (c, v) in k.face(*f).iter().enumerate() {
            if let Some(p) = vertex_seen.get(v) {
                defect = crate::report::dev_max(defect, (p[0] - t[c][0]).hypot(p[1] - t[c][1]));
            }
        }
    }
    let unreached = faces.len() - img.len();
    Chart {
        centre,
        faces: img,
        path_magnitude: mag,
        develop_defect: defect,
        unreached,
    }
}

/// Sec. 5.4 steps (1)–(5) as written: remove the zeros' faces, build one chart per surviving
/// vertex on its whole surviving k-ring (connected or not).
pub fn build(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    om: &OneForm,
    zeros: &[VertexId],
    ring: u32,
) -> Result<Atlas, MsError> {
    build_with(k, ei, om, zeros, ring, false)
}

/// The corrected atlas (SPEC `MS-D4-corrected`): the open stars of `singular` (from
/// [`super::zeros::ZeroSet::singular_vertices`]) removed, and a surviving k-ring that falls
/// apart into pieces joined only at vertices gives one chart per edge-connected piece (a
/// chart must be reached face by face from its first face).
pub fn build_corrected(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    om: &OneForm,
    singular: &[VertexId],
    ring: u32,
) -> Result<Atlas, MsError> {
    build_with(k, ei, om, singular, ring, true)
}

/// The edge-connected pieces of a face set, each sorted, in order of their least face.
fn edge_components(k: &SimplicialSurface, faces: &BTreeSet<FaceId>) -> Vec<BTreeSet<FaceId>> {
    let mut seen: BTreeSet<FaceId> = BTreeSet::new();
    let mut out = Vec::new();
    for &f0 in faces {
        if !seen.insert(f0) {
            continue;
        }
        let mut comp = BTreeSet::from([f0]);
        let mut q = VecDeque::from([f0]);
        while let Some(f) = q.pop_front() {
            for h in face_halfedges(f) {
                let g = k.face_of(k.twin(h));
                if faces.contains(&g) && seen.insert(g) {
                    comp.insert(g);
                    q.push_back(g);
                }
            }
        }
        out.push(comp);
    }
    out
}

fn build_with(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    om: &OneForm,
    zeros: &[VertexId],
    ring: u32,
    split: bool,
) -> Result<Atlas, MsError> {
    if !(1..=4).contains(&ring) {
        return Err(MsError::RingRadius { k: ring });
    }
    let mut removed = vec![false; k.num_faces()];
    for &z in zeros {
        for &f in k.faces_around(z) {
            removed[f.idx()] = true;
        }
    }
    let zset: BTreeSet<VertexId> = zeros.iter().copied().collect();
    let mut charts = Vec::new();
    for v in k.vertices().filter(|v| !zset.contains(v)) {
        let faces: BTreeSet<FaceId> = ring_faces(k, v, ring)
            .into_iter()
            .filter(|f| !removed[f.idx()])
            .collect();
        if faces.is_empty() {
            continue;
        }
        if split {
            for piece in edge_components(k, &faces) {
                charts.push(develop(k, ei, om, v, &piece));
            }
        } else {
            charts.push(develop(k, ei, om, v, &faces));
        }
    }
    let mut charts_of_face = vec![Vec::new(); k.num_faces()];
    for (a, ch) in charts.iter().enumerate() {
        for f in ch.faces.keys() {
            charts_of_face[f.idx()].push(a as u32);
        }
    }
    let mut pairs: BTreeMap<(u32, u32), Vec<FaceId>> = BTreeMap::new();
    for (f, cs) in charts_of_face.iter().enumerate() {
        for (i, &a) in cs.iter().enumerate() {
            for &b in &cs[i + 1..] {
                pairs
                    .entry((a.min(b), a.max(b)))
                    .or_default()
                    .push(FaceId(f as u32));
            }
        }
    }
    Ok(Atlas {
        k_ring: ring,
        zeros: zeros.to_vec(),
        removed,
        charts,
        charts_of_face,
        pairs,
    })
}

/// χ of the closed union of a face set: V − E + F.
pub fn euler_of_faces(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    faces: impl Iterator<Item = FaceId>,
) -> i64 {
    let (mut vs, mut es, mut nf) = (BTreeSet::new(), BTreeSet::new(), 0i64);
    for f in faces {
        nf += 1;
        vs.extend(k.face(f));
        es.extend(face_halfedges(f).map(|h| ei.edge(h)));
    }
    vs.len() as i64 - es.len() as i64 + nf
}
