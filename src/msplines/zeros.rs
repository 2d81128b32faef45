//! Sec. 5.3 and Def. 11: zero points of ω, located by the winding number of the image of a
//! vertex's link, decided exactly.
//!
//! φ(w_i) − φ(v) = ω[v, w_i] for the link w_0, …, w_{n−1} in counterclockwise order. The paper
//! sums unsigned angles and asks that φ(v) be "inside this polygon"; both fail exactly at a zero
//! (the polygon winds twice), so we take the signed winding number w_v of the closed polygon
//! about the origin, counted by crossings of the positive x-axis with Shewchuk's exact
//! orientation predicate: an integer, exact for the stored f64 values. w_v = 1 is a regular
//! point, w_v ≥ 2 a zero of order w_v − 1.

use super::cochain::{face_halfedges, EdgeIndex};
use super::hodge::OneForm;
use crate::mesh::{SimplicialSurface, VertexId};
use crate::numeric::predicates::orient2_det;
use serde::Serialize;

/// The winding of one vertex, or why it is undecided (the origin on the polygon).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Winding {
    /// The integer winding number.
    Decided(i64),
    /// ω vanishes on an edge or the polygon passes through φ(v): no winding number.
    OnPolygon,
}

/// Exact winding number of the closed polygon `pts` about the origin.
pub fn winding_number(pts: &[[f64; 2]]) -> Winding {
    let o = [0.0, 0.0];
    let n = pts.len();
    let mut w = 0i64;
    for i in 0..n {
        let (a, b) = (pts[i], pts[(i + 1) % n]);
        let s = orient2_det(a, b, o);
        // The origin on the closed segment [a, b].
        if s == 0.0
            && a[0].min(b[0]) <= 0.0
            && 0.0 <= a[0].max(b[0])
            && a[1].min(b[1]) <= 0.0
            && 0.0 <= a[1].max(b[1])
        {
            return Winding::OnPolygon;
        }
        if a[1] <= 0.0 {
            if b[1] > 0.0 && s > 0.0 {
                w += 1;
            }
        } else if b[1] <= 0.0 && s < 0.0 {
            w -= 1;
        }
    }
    Winding::Decided(w)
}

/// The image polygon of v's link under ω: ω[v, w_i] in the counterclockwise link order.
pub fn link_image(
    k: &SimplicialSurface,
    ei: &EdgeIndex,
    om: &OneForm,
    v: VertexId,
) -> Vec<[f64; 2]> {
    k.outgoing(v).iter().map(|&h| om.at(ei, h)).collect()
}

/// Windings of every vertex, and the image orientation of every face.
#[derive(Debug, Clone, Serialize)]
pub struct ZeroSet {
    /// (vertex, winding) for every vertex of K.
    pub windings: Vec<(VertexId, Winding)>,
    /// Zero points: vertices with w_v ≥ 2, with their order w_v − 1.
    pub zeros: Vec<(VertexId, i64)>,
    /// Vertices with w_v ≤ 0 (impossible for a holomorphic ω: index of ω_x would be positive).
    pub non_positive: Vec<(VertexId, i64)>,
    /// Vertices whose winding is undecided.
    pub undecided: Vec<VertexId>,
    /// Faces whose image [0, ω01, ω02] is negatively oriented at every corner.
    pub flipped_faces: u64,
    /// Those faces.
    pub flipped: Vec<crate::mesh::FaceId>,
    /// Faces whose image is degenerate or whose corners disagree on the orientation.
    pub ambiguous_faces: Vec<crate::mesh::FaceId>,
}

/// Locate the zeros of ω (Sec. 5.3) and the orientation of every image face.
pub fn locate(k: &SimplicialSurface, ei: &EdgeIndex, om: &OneForm) -> ZeroSet {
    let mut windings = Vec::with_capacity(k.num_vertices());
    let (mut zeros, mut non_positive, mut undecided) = (Vec::new(), Vec::new(), Vec::new());
    for v in k.vertices() {
        let w = winding_number(&link_image(k, ei, om, v));
        match w {
            Winding::Decided(n) if n >= 2 => zeros.push((v, n - 1)),
            Winding::Decided(n) if n <= 0 => non_positive.push((v, n)),
            Winding::OnPolygon => undecided.push(v),
            _ => {}
        }
        windings.push((v, w));
    }
    let mut flipped = Vec::new();
    let mut ambiguous_faces = Vec::new();
    for f in k.faces() {
        let hs = face_halfedges(f);
        // Corner c: the image triangle [0, ω[h_c], −ω[h_{c+2}]] seen from corner c.
        let signs: Vec<f64> = (0..3)
            .map(|cc| {
                let a = om.at(ei, hs[cc]);
                let b = om.at(ei, hs[(cc + 2) % 3]);
                orient2_det([0.0, 0.0], a, [-b[0], -b[1]])
            })
            .collect();
        if signs.iter().all(|&s| s < 0.0) {
            flipped.push(f);
        } else if !signs.iter().all(|&s| s > 0.0) {
            ambiguous_faces.push(f);
        }
    }
    ZeroSet {
        windings,
        zeros,
        non_positive,
        undecided,
        flipped_faces: flipped.len() as u64,
        flipped,
        ambiguous_faces,
    }
}

impl ZeroSet {
    /// The vertices of the corrected Sec. 5.4 removal (SPEC `MS-D4-corrected`): every vertex
    /// with w_v ≠ 1 or undecided, and every corner of a face whose image is flipped or
    /// ambiguous. A vertex outside this set has w_v = 1 and a star of positively oriented
    /// image triangles, whose angles at φ(v) are in (0, π) and sum to 2π·w_v = 2π: the
    /// developed star is an embedded fan, so every sub-fan is injective.
    pub fn singular_vertices(&self, k: &SimplicialSurface) -> Vec<VertexId> {
        let mut s: std::collections::BTreeSet<VertexId> = self
            .windings
            .iter()
            .filter(|(_, w)| *w != Winding::Decided(1))
            .map(|(v, _)| *v)
            .collect();
        for f in self.flipped.iter().chain(&self.ambiguous_faces) {
            s.extend(k.face(*f));
        }
        s.into_iter().collect()
    }

    /// Σ_v (w_v − 1) over the decided vertices.
    pub fn total_order(&self) -> i64 {
        self.windings
            .iter()
            .filter_map(|(_, w)| match w {
                Winding::Decided(n) => Some(n - 1),
                Winding::OnPolygon => None,
            })
            .sum()
    }
}
