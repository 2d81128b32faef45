//! The atlas of Sec. 5.4 seen as gluing data (Def. 3.4.1 of the PPM report), so the sampled
//! checkers of `crate::gluing::sampled` run on it unchanged.
//!
//! Ω_α = o_α + φ_α(int U_α)/R and Ω_αβ = o_α + φ_α(int(U_α ∩ U_β))/R, with R the largest chart
//! radius of the view (coordinates of size ≤ 1, as the checkers' tolerances expect) and o_α
//! the centre of α's own copy of ℝ² (Def. 3.4.1(1) asks for disjoint p-domains). The
//! transition is literally φ_βα = φ_β∘φ_α⁻¹: locate the face of U_α∩U_β holding the point,
//! carry its barycentric coordinates to the face's image in chart β. Whether that is affine
//! (Def. 7) or a translation (Thm. 4) is checked separately (`checks`), not assumed.

use super::atlas::{Atlas, P2};
use crate::gluing::data::{GluingData, Idx, Point};
use crate::mesh::{FaceId, SimplicialSurface};
use crate::numeric::predicates::orient2_det;
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Distance between the copies of ℝ² relative to the (normalised) chart radius 1.
pub const COPY_SPACING: f64 = 2.5;

/// A replacement transition for planted-fault tests: (β, α, local point) ↦ φ_βα(point).
pub type PhiOverride<'a> = dyn Fn(u32, u32, P2) -> Option<P2> + Sync + 'a;

/// The gluing data of a set of charts of an [`Atlas`].
pub struct AtlasView<'a> {
    k: &'a SimplicialSurface,
    atlas: &'a Atlas,
    ids: Vec<u32>,
    radius: f64,
    phi_override: Option<Box<PhiOverride<'a>>>,
}

/// Barycentric coordinates of p in t (f64), and whether p is in the closed triangle (exact).
fn locate(t: &[P2; 3], p: P2) -> Option<[f64; 3]> {
    let area = orient2_det(t[0], t[1], t[2]);
    if area == 0.0 {
        return None;
    }
    let s = [
        orient2_det(t[1], t[2], p),
        orient2_det(t[2], t[0], p),
        orient2_det(t[0], t[1], p),
    ];
    if s.iter().any(|&x| x * area < 0.0) {
        return None;
    }
    Some([s[0] / area, s[1] / area, s[2] / area])
}

/// Whether p lies strictly outside the axis-aligned box of the triangle's corners (exact:
/// comparisons only).
fn outside_box(t: &[P2; 3], p: P2) -> bool {
    (0..2).any(|d| {
        let (lo, hi) = t
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), c| {
                (l.min(c[d]), h.max(c[d]))
            });
        p[d] < lo || p[d] > hi
    })
}

impl<'a> AtlasView<'a> {
    /// The view on the charts `ids` (chart indices of `atlas`).
    pub fn new(k: &'a SimplicialSurface, atlas: &'a Atlas, ids: Vec<u32>) -> Self {
        let ids: Vec<u32> = ids
            .into_iter()
            .filter(|&i| (i as usize) < atlas.charts.len())
            .collect();
        let radius = ids
            .iter()
            .map(|&i| atlas.charts[i as usize].radius())
            .fold(0.0, crate::report::dev_max);
        AtlasView {
            k,
            atlas,
            ids,
            radius: if radius > 0.0 { radius } else { 1.0 },
            phi_override: None,
        }
    }
    /// Chart α and every chart overlapping it.
    pub fn neighbourhood(k: &'a SimplicialSurface, atlas: &'a Atlas, alpha: u32) -> Self {
        let mut ids: Vec<u32> = vec![alpha];
        for (&(a, b), _) in atlas.pairs.range((alpha, 0)..=(alpha, u32::MAX)) {
            debug_assert_eq!(a, alpha);
            ids.push(b);
        }
        ids.extend(
            atlas
                .pairs
                .keys()
                .filter(|(_, b)| *b == alpha)
                .map(|(a, _)| *a),
        );
        ids.sort_unstable();
        ids.dedup();
        Self::new(k, atlas, ids)
    }
    /// Replace the transitions (planted faults).
    pub fn with_phi_override(mut self, f: Box<PhiOverride<'a>>) -> Self {
        self.phi_override = Some(f);
        self
    }
    fn rank(&self, i: Idx) -> Option<usize> {
        self.ids.iter().position(|&x| x == i)
    }
    fn offset(&self, i: Idx) -> Option<P2> {
        let r = self.rank(i)?;
        let side = (self.ids.len() as f64).sqrt().ceil().max(1.0) as usize;
        let half = (side / 2) as f64;
        Some([
            COPY_SPACING * ((r % side) as f64 - half),
            COPY_SPACING * ((r / side) as f64 - half),
        ])
    }
    /// Global (view) coordinates → chart coordinates φ_α.
    fn to_local(&self, i: Idx, p: &P2) -> Option<P2> {
        let o = self.offset(i)?;
        Some([(p[0] - o[0]) * self.radius, (p[1] - o[1]) * self.radius])
    }
    fn to_global(&self, i: Idx, p: P2) -> Option<P2> {
        let o = self.offset(i)?;
        Some([p[0] / self.radius + o[0], p[1] / self.radius + o[1]])
    }
    /// The face of chart i holding chart point q (interior of the face union), with its
    /// barycentric coordinates, restricted to faces accepted by `keep`.
    fn find(&self, i: Idx, q: P2, keep: &dyn Fn(FaceId) -> bool) -> Option<(FaceId, [f64; 3])> {
        let ch = self.atlas.charts.get(i as usize)?;
        for (&f, t) in &ch.faces {
            // Outside the triangle's box is outside the closed triangle: `locate`'s exact
            // signs would refuse it too, at four orientation tests (most of a chart's faces).
            if outside_box(t, q) || !keep(f) {
                continue;
            }
            let Some(b) = locate(t, q) else { continue };
            if b.iter().all(|&x| x > 0.0) {
                return Some((f, b));
            }
            // On the face's boundary: inside the union only if every face around the located
            // edge or vertex is in the set.
            let vs = self.k.face(f);
            let on: Vec<usize> = (0..3).filter(|&c| b[c] > 0.0).collect();
            let around: Vec<FaceId> = match on.as_slice() {
                [a, b2] => {
                    let (u, w) = (vs[*a], vs[*b2]);
                    self.k
                        .faces_around(u)
                        .iter()
                        .copied()
                        .filter(|g| self.k.face(*g).contains(&w))
                        .collect()
                }
                [a] => self.k.faces_around(vs[*a]).to_vec(),
                _ => vec![],
            };
            if !around.is_empty() && around.iter().all(|g| ch.faces.contains_key(g) && keep(*g)) {
                return Some((f, b));
            }
        }
        None
    }
    fn common(&self, i: Idx, j: Idx) -> Option<&Vec<FaceId>> {
        self.atlas.pairs.get(&(i.min(j), i.max(j)))
    }
}

impl GluingData<2> for AtlasView<'_> {
    type S = f64;

    fn indices(&self) -> Vec<Idx> {
        self.ids.clone()
    }

    fn in_p_domain(&self, i: Idx, p: &Point<f64, 2>) -> bool {
        self.to_local(i, p)
            .is_some_and(|q| self.find(i, q, &|_| true).is_some())
    }

    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<f64, 2>) -> bool {
        if i == j {
            return self.in_p_domain(i, p);
        }
        let (Some(q), Some(_)) = (self.to_local(i, p), self.rank(j)) else {
            return false;
        };
        let Some(common) = self.common(i, j) else {
            return false;
        };
        self.find(i, q, &|f| common.binary_search(&f).is_ok())
            .is_some()
    }

    fn phi(&self, j: Idx, i: Idx, p: &Point<f64, 2>) -> Option<Point<f64, 2>> {
        let q = self.to_local(i, p)?;
        self.rank(j)?;
        if i == j {
            return self.in_p_domain(i, p).then_some(*p);
        }
        let common = self.common(i, j)?;
        let (f, b) = self.find(i, q, &|f| common.binary_search(&f).is_ok())?;
        if let Some(ov) = &self.phi_override {
            if let Some(r) = ov(j, i, q) {
                return self.to_global(j, r);
            }
        }
        let t = self.atlas.charts.get(j as usize)?.faces.get(&f)?;
        let r = [
            b[0] * t[0][0] + b[1] * t[1][0] + b[2] * t[2][0],
            b[0] * t[0][1] + b[1] * t[1][1] + b[2] * t[2][1],
        ];
        self.to_global(j, r)
    }

    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<f64, 2>> {
        let Some(ch) = self.atlas.charts.get(i as usize) else {
            return vec![];
        };
        let faces: Vec<FaceId> = ch.faces.keys().copied().collect();
        self.sample_faces(i, &faces, rng, n)
    }

    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, 2>> {
        if i == j {
            return self.sample_p_domain(i, rng, n);
        }
        if self.rank(j).is_none() {
            return vec![];
        }
        let Some(common) = self.common(i, j) else {
            return vec![];
        };
        let common = common.clone();
        self.sample_faces(i, &common, rng, n)
            .into_iter()
            .filter(|p| self.in_gluing_domain(i, j, p))
            .collect()
    }

    /// Points of ∂Ω_ij ∩ Ω_i: on the edges between a common face and a face of U_i ∖ U_j.
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, 2>> {
        let (Some(ch), Some(common), Some(_)) = (
            self.atlas.charts.get(i as usize),
            self.common(i, j),
            self.rank(j),
        ) else {
            return vec![];
        };
        let mut edges = Vec::new();
        for &f in common {
            let Some(t) = ch.faces.get(&f) else { continue };
            let vs = self.k.face(f);
            for cc in 0..3 {
                let (u, w) = (vs[cc], vs[(cc + 1) % 3]);
                let other = self
                    .k
                    .faces_around(u)
                    .iter()
                    .copied()
                    .find(|g| *g != f && self.k.face(*g).contains(&w));
                if let Some(g) = other {
                    if ch.faces.contains_key(&g) && common.binary_search(&g).is_err() {
                        edges.push((t[cc], t[(cc + 1) % 3]));
                    }
                }
            }
        }
        if edges.is_empty() {
            return vec![];
        }
        (0..n)
            .filter_map(|_| {
                let (a, b) = edges[rng.gen_range(0..edges.len())];
                let s: f64 = rng.gen_range(0.05..0.95);
                self.to_global(i, [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])])
            })
            .filter(|p| self.in_p_domain(i, p))
            .collect()
    }

    fn scale(&self) -> f64 {
        1.0
    }
}

impl AtlasView<'_> {
    /// Uniform samples in random faces of chart i, plus points near the faces' edges.
    fn sample_faces(&self, i: Idx, faces: &[FaceId], rng: &mut ChaCha8Rng, n: usize) -> Vec<P2> {
        let Some(ch) = self.atlas.charts.get(i as usize) else {
            return vec![];
        };
        if faces.is_empty() {
            return vec![];
        }
        let mut out = Vec::with_capacity(n);
        for s in 0..n {
            let f = faces[rng.gen_range(0..faces.len())];
            let Some(t) = ch.faces.get(&f) else { continue };
            let (mut a, mut b): (f64, f64) = (rng.gen_range(0.0..1.0), rng.gen_range(0.0..1.0));
            if a + b > 1.0 {
                a = 1.0 - a;
                b = 1.0 - b;
            }
            if s % 4 == 3 {
                // Near an edge: one barycentric coordinate small.
                b *= 1e-6;
            }
            let q = [
                t[0][0] + a * (t[1][0] - t[0][0]) + b * (t[2][0] - t[0][0]),
                t[0][1] + a * (t[1][1] - t[0][1]) + b * (t[2][1] - t[0][1]),
            ];
            if let Some(p) = self.to_global(i, q) {
                if self.in_p_domain(i, &p) {
                    out.push(p);
                }
            }
        }
        out
    }
}
