//! The base mesh S̃_T over the dense mesh S_T, and the parametrization of S_T onto it
//! (seed 002, "Adaptive Manifold Fitting", Parts I–II).
//!
//! The base mesh's vertices are vertices of S_T (Part II: "the vertices of S̃_T are vertices
//! of S_T"), so a base vertex is named by its fine id. Every other vertex of S_T carries a
//! parameter: a base face and barycentric coordinates in it. The parameters define a
//! piecewise-linear bijection from |S_T| onto the base mesh seen as a complex of triangles,
//! which the three stellar operations below keep a bijection:
//!
//! * [`BaseMesh::remove_vertex`] (simplification; a weld after flips in stellar terms): the
//!   1-ring is flattened by the geodesic polar map (lengths kept, angles scaled to 2π; the
//!   local map of Floater's 1997 shape-preserving parametrization), the hole is
//!   re-triangulated by ears, and the points of the removed faces are re-located in the flat
//!   layout;
//! * [`BaseMesh::split_face`] (refinement, stellar face split at a vertex of S_T): points are
//!   re-expressed in the three sub-triangles, an affine computation in the face's barycentric
//!   coordinates;
//! * [`BaseMesh::flip`] (edge flip): the two faces are unfolded isometrically (lengths of the
//!   base triangles in R³) and the points re-located; refused unless the unfolded quadrilateral
//!   is strictly convex, so no point leaves the pair.
//!
//! Re-location in floating point can put a point a rounding error outside every new triangle;
//! it is then snapped to the nearest one (barycentrics clamped at 0). Each snap is counted with
//! its size ([`SnapStats`]) and reported; a point further out than `SNAP_LIMIT` is an internal
//! error, never clamped.

use crate::mesh::{SimplicialSurface, VertexId};
use crate::numeric::vec3::{cross, dot, norm, sub};
use std::collections::HashMap;

/// Largest negative barycentric coordinate a re-located point may be snapped from.
pub const SNAP_LIMIT: f64 = 1e-7;

/// Where a vertex of S_T sits on the base mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Param {
    /// It is a vertex of the base mesh.
    Vertex,
    /// In base face slot `f`, barycentric coordinates in the face's corner order.
    Face {
        /// Base face slot.
        f: u32,
        /// Barycentric coordinates (sum 1, each ≥ 0).
        b: [f64; 3],
    },
}

/// Why a stellar operation was refused (the mesh is unchanged).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Refusal {
    /// The vertex is not (or no longer) a base vertex, or the edge does not exist.
    Missing,
    /// The flattened 1-ring has an angle ≥ π (a cone too sharp to flatten).
    Flatten,
    /// No valid ear: every diagonal exists already or the polygon has no convex empty ear.
    NoEar,
    /// The new triangles are too far from the removed vertex's normal or too thin.
    Shape,
    /// A vertex would get degree < 3 or above the cap.
    Degree,
    /// Points of S_T would lie further than the deviation bound from their new triangle.
    Deviation,
    /// The unfolded quadrilateral of a flip is not strictly convex.
    NotConvex,
    /// Re-location left a point outside every new triangle by more than `SNAP_LIMIT`.
    Locate,
    /// A triangle of S_T whose three vertices lie in the changed region would fold (negative
    /// area in the region's flat layout).
    Fold,
}

/// Re-location snaps (see the module doc).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct SnapStats {
    /// Points snapped.
    pub count: u64,
    /// Largest |negative barycentric coordinate| removed by a snap.
    pub worst: f64,
}

/// Limits of a vertex removal.
#[derive(Debug, Clone, Copy)]
pub struct RemovalLimits {
    /// Largest distance from a point of S_T to its place on its base triangle.
    pub max_deviation: f64,
    /// Smallest cosine between a new triangle's normal and the removed vertex's normal.
    pub min_normal_cos: f64,
    /// Smallest triangle quality 4√3·area/Σ edge² (1 for equilateral).
    pub min_quality: f64,
    /// Largest vertex degree.
    pub max_degree: usize,
}

/// S̃_T with the parameters of S_T on it.
#[derive(Debug, Clone)]
pub struct BaseMesh {
    pos: Vec<[f64; 3]>,
    faces: Vec<Option<[u32; 3]>>,
    free: Vec<u32>,
    he: HashMap<(u32, u32), u32>,
    vfaces: Vec<Vec<u32>>,
    param: Vec<Param>,
    members: Vec<Vec<u32>>,
    fine_faces: Vec<[u32; 3]>,
    fine_around: Vec<Vec<u32>>,
    /// Re-location snaps so far.
    pub snaps: SnapStats,
}

type V3 = [f64; 3];
fn orient2(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}
/// Barycentric coordinates of x w.r.t. the planar triangle (a, b, c).
fn bary2(a: [f64; 2], b: [f64; 2], c: [f64; 2], x: [f64; 2]) -> [f64; 3] {
    let d = orient2(a, b, c);
    let l1 = orient2(x, b, c) / d;
    let l2 = orient2(a, x, c) / d;
    [l1, l2, 1.0 - l1 - l2]
}

/// Triangle quality 4√3·area/(|ab|²+|bc|²+|ca|²) ∈ [0, 1].
pub fn quality(a: V3, b: V3, c: V3) -> f64 {
    let n = cross(sub(b, a), sub(c, a));
    let s = dot(sub(b, a), sub(b, a)) + dot(sub(c, b), sub(c, b)) + dot(sub(a, c), sub(a, c));
    if s > 0.0 {
        2.0 * 3f64.sqrt() * norm(n) / s
    } else {
        0.0
    }
}

fn rot(face: [u32; 3], v: u32) -> Option<[u32; 3]> {
    let i = face.iter().position(|&x| x == v)?;
    Some([face[i], face[(i + 1) % 3], face[(i + 2) % 3]])
}
/// Barycentric coordinates `b` w.r.t. the corners `face`, re-ordered to the corners `order`
/// (0 for a corner of `order` not in `face`).
pub(crate) fn permute(face: [u32; 3], b: [f64; 3], order: [u32; 3]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (k, &o) in order.iter().enumerate() {
        if let Some(i) = face.iter().position(|&x| x == o) {
            out[k] = b[i];
        }
    }
    out
}

/// Pick the triangle of `tris` (planar corners) containing `x` best; snap if needed.
fn locate(tris: &[[[f64; 2]; 3]], x: [f64; 2], snaps: &mut SnapStats) -> Option<(usize, [f64; 3])> {
    let mut best: Option<(usize, [f64; 3], f64)> = None;
    for (t, c) in tris.iter().enumerate() {
        let b = bary2(c[0], c[1], c[2], x);
        let mn = b[0].min(b[1]).min(b[2]);
        if mn.is_finite() && best.as_ref().map_or(true, |(_, _, m)| mn > *m) {
            best = Some((t, b, mn));
        }
    }
    let (t, b, mn) = best?;
    Some((t, snap(b, mn, snaps)?))
}

/// Barycentric coordinates `b` with smallest coordinate `mn`: kept when `mn` ≥ 0, snapped to
/// the triangle (negatives to 0, renormalized; counted) when `mn` ≥ −`SNAP_LIMIT`, else None.
fn snap(b: [f64; 3], mn: f64, snaps: &mut SnapStats) -> Option<[f64; 3]> {
    if mn >= 0.0 {
        return Some(b);
    }
    if mn < -SNAP_LIMIT {
        return None;
    }
    snaps.count += 1;
    snaps.worst = snaps.worst.max(-mn);
    let b = b.map(|x| x.max(0.0));
    let s = b[0] + b[1] + b[2];
    Some(b.map(|x| x / s))
}

impl BaseMesh {
    /// The base mesh equal to S_T (every vertex a base vertex).
    pub fn new(k: &SimplicialSurface) -> Self {
        let n = k.vertex_slots();
        let pos: Vec<V3> = (0..n).map(|i| k.position(VertexId(i as u32))).collect();
        let mut b = BaseMesh {
            pos,
            faces: Vec::new(),
            free: Vec::new(),
            he: HashMap::new(),
            vfaces: vec![Vec::new(); n],
            param: vec![Param::Vertex; n],
            members: Vec::new(),
            fine_faces: Vec::new(),
            fine_around: vec![Vec::new(); n],
            snaps: SnapStats::default(),
        };
        for f in k.faces() {
            let c = k.face(f).map(|v| v.0);
            b.add_face(c);
            for v in c {
                b.fine_around[v as usize].push(b.fine_faces.len() as u32);
            }
            b.fine_faces.push(c);
        }
        b
    }

    /// Positions of S_T.
    pub fn positions(&self) -> &[V3] {
        &self.pos
    }
    /// Parameter of every vertex of S_T.
    pub fn params(&self) -> &[Param] {
        &self.param
    }
    /// Live base faces as (slot, corners).
    pub fn faces(&self) -> impl Iterator<Item = (u32, [u32; 3])> + '_ {
        self.faces
            .iter()
            .enumerate()
            .filter_map(|(i, f)| f.map(|c| (i as u32, c)))
    }
    /// Corners of a live face slot.
    pub fn face(&self, f: u32) -> Option<[u32; 3]> {
        self.faces.get(f as usize).copied().flatten()
    }
    /// Number of base faces.
    pub fn num_faces(&self) -> usize {
        self.faces.len() - self.free.len()
    }
    /// Is fine vertex `v` a base vertex?
    pub fn is_base(&self, v: u32) -> bool {
        !self.vfaces[v as usize].is_empty()
    }
    /// Base vertices, ascending fine ids.
    pub fn base_vertices(&self) -> Vec<u32> {
        (0..self.pos.len() as u32)
            .filter(|&v| self.is_base(v))
            .collect()
    }
    /// The vertices of S_T parametrized in base face slot `f`.
    pub fn members(&self, f: u32) -> &[u32] {
        self.members.get(f as usize).map_or(&[], |m| m.as_slice())
    }
    /// The base face slots around base vertex v.
    pub fn faces_around(&self, v: u32) -> &[u32] {
        self.vfaces.get(v as usize).map_or(&[], |f| f.as_slice())
    }
    /// Degree of a base vertex.
    pub fn degree(&self, v: u32) -> usize {
        self.vfaces[v as usize].len()
    }
    /// The face holding the directed edge a → b.
    pub fn face_of_edge(&self, a: u32, b: u32) -> Option<u32> {
        self.he.get(&(a, b)).copied()
    }
    /// The point of the base triangle `f` at barycentric coordinates `b` (in R³).
    pub fn flat_point(&self, f: u32, b: [f64; 3]) -> Option<V3> {
        let c = self.face(f)?;
        let p = c.map(|v| self.pos[v as usize]);
        Some(std::array::from_fn(|i| {
            b[0] * p[0][i] + b[1] * p[1][i] + b[2] * p[2][i]
        }))
    }

    fn add_face(&mut self, c: [u32; 3]) -> u32 {
        let slot = match self.free.pop() {
            Some(s) => {
                self.faces[s as usize] = Some(c);
                self.members[s as usize].clear();
                s
            }
            None => {
                self.faces.push(Some(c));
                self.members.push(Vec::new());
                (self.faces.len() - 1) as u32
            }
        };
        for i in 0..3 {
            self.he.insert((c[i], c[(i + 1) % 3]), slot);
            self.vfaces[c[i] as usize].push(slot);
        }
        slot
    }

    fn remove_face(&mut self, f: u32) -> Vec<u32> {
        let Some(c) = self.faces[f as usize].take() else {
            return Vec::new();
        };
        for i in 0..3 {
            self.he.remove(&(c[i], c[(i + 1) % 3]));
            self.vfaces[c[i] as usize].retain(|&x| x != f);
        }
        self.free.push(f);
        std::mem::take(&mut self.members[f as usize])
    }

    fn set_param(&mut self, x: u32, p: Param) {
        if let Param::Face { f, .. } = p {
            self.members[f as usize].push(x);
        }
        self.param[x as usize] = p;
    }

    /// Overwrite the parameter of vertex x of S_T, keeping the face membership consistent:
    /// for planted-fault tests of the checks (a folded parametrization), never used by the
    /// pipeline.
    pub fn plant_param(&mut self, x: u32, p: Param) {
        if let Param::Face { f, .. } = self.param[x as usize] {
            if let Some(m) = self.members.get_mut(f as usize) {
                m.retain(|&y| y != x);
            }
        }
        self.set_param(x, p);
    }

    /// The 1-ring of base vertex v: neighbours u_0..u_{m−1} in the faces' order and the faces
    /// (v, u_i, u_{i+1}).
    pub fn ring(&self, v: u32) -> Option<(Vec<u32>, Vec<u32>)> {
        let f0 = *self.vfaces.get(v as usize)?.first()?;
        let c = rot(self.face(f0)?, v)?;
        let (mut us, mut fs) = (vec![c[1]], vec![f0]);
        let mut cur = c[2];
        while cur != us[0] {
            let f = self.face_of_edge(v, cur)?;
            let c = rot(self.face(f)?, v)?;
            us.push(cur);
            fs.push(f);
            cur = c[2];
            if us.len() > self.vfaces[v as usize].len() {
                return None;
            }
        }
        Some((us, fs))
    }

    /// The points of face `f` with barycentric coordinates in the order `order`.
    fn points_in(&self, f: u32, order: [u32; 3]) -> Vec<(u32, [f64; 3])> {
        let c = self.faces[f as usize].unwrap_or(order);
        self.members[f as usize]
            .iter()
            .filter_map(|&x| match self.param[x as usize] {
                Param::Face { b, .. } => Some((x, permute(c, b, order))),
                Param::Vertex => None,
            })
            .collect()
    }

    /// Distance of vertex x of S_T from its place on its flat base triangle (0 for a base
    /// vertex).
    pub fn flat_deviation(&self, x: u32) -> f64 {
        match self.param[x as usize] {
            Param::Face { f, b } => self
                .face(f)
                .map_or(f64::INFINITY, |c| self.deviation(c, x, b)),
            Param::Vertex => 0.0,
        }
    }

    fn deviation(&self, tri: [u32; 3], x: u32, b: [f64; 3]) -> f64 {
        let p = tri.map(|v| self.pos[v as usize]);
        let q: V3 = std::array::from_fn(|i| b[0] * p[0][i] + b[1] * p[1][i] + b[2] * p[2][i]);
        norm(sub(q, self.pos[x as usize]))
    }

    /// Remove base vertex v (see the module doc). On refusal nothing changes.
    pub fn remove_vertex(&mut self, v: u32, lim: &RemovalLimits) -> Result<(), Refusal> {
        let (us, fs) = self.ring(v).ok_or(Refusal::Missing)?;
        let m = us.len();
        let pv = self.pos[v as usize];
        let d: Vec<V3> = us.iter().map(|&u| sub(self.pos[u as usize], pv)).collect();
        let ang: Vec<f64> = (0..m)
            .map(|i| {
                let (a, b) = (d[i], d[(i + 1) % m]);
                norm(cross(a, b)).atan2(dot(a, b))
            })
            .collect();
        let total: f64 = ang.iter().sum();
        let scale = std::f64::consts::TAU / total;
        if !(total > 0.0) || ang.iter().any(|a| a * scale >= std::f64::consts::PI - 1e-3) {
            return Err(Refusal::Flatten);
        }
        let mut alpha = 0.0f64;
        let poly: Vec<[f64; 2]> = (0..m)
            .map(|i| {
                let r = norm(d[i]);
                let p = [r * alpha.cos(), r * alpha.sin()];
                alpha += ang[i] * scale;
                p
            })
            .collect();
        // Normal of v: area-weighted normal of its faces.
        let mut nv = [0.0; 3];
        for i in 0..m {
            let n = cross(d[i], d[(i + 1) % m]);
            nv = [nv[0] + n[0], nv[1] + n[1], nv[2] + n[2]];
        }
        let nvn = norm(nv);
        let tris = self.ears(&us, &poly, nv, nvn, lim)?;
        // Degrees after: each u loses v and gains its diagonals.
        let mut deg: HashMap<u32, usize> = us.iter().map(|&u| (u, self.degree(u) - 1)).collect();
        for t in &tris {
            for i in 0..3 {
                let (a, b) = (t[i], t[(i + 1) % 3]);
                if (a + 1) % m != b && (b + 1) % m != a {
                    *deg.entry(us[a]).or_default() += 1;
                }
            }
        }
        // Each diagonal was counted from both of its triangles: halve the extra count.
        for &u in &us {
            let base = self.degree(u) - 1;
            let e = deg[&u] - base;
            let dd = base + e / 2;
            if dd < 3 || dd > lim.max_degree {
                return Err(Refusal::Degree);
            }
        }
        let flat: Vec<[[f64; 2]; 3]> = tris.iter().map(|t| t.map(|i| poly[i])).collect();
        let corners: Vec<[u32; 3]> = tris.iter().map(|t| t.map(|i| us[i])).collect();
        // Re-locate v and the points of the removed faces.
        let mut snaps = self.snaps;
        let mut moved: Vec<(u32, usize, [f64; 3])> = Vec::new();
        let (t, b) = locate(&flat, [0.0, 0.0], &mut snaps).ok_or(Refusal::Locate)?;
        moved.push((v, t, b));
        for (i, &f) in fs.iter().enumerate() {
            let order = [v, us[i], us[(i + 1) % m]];
            let (p1, p2) = (poly[i], poly[(i + 1) % m]);
            for (x, b) in self.points_in(f, order) {
                let q = [b[1] * p1[0] + b[2] * p2[0], b[1] * p1[1] + b[2] * p2[1]];
                let (t, bb) = locate(&flat, q, &mut snaps).ok_or(Refusal::Locate)?;
                moved.push((x, t, bb));
            }
        }
        for &(x, t, b) in &moved {
            if self.deviation(corners[t], x, b) > lim.max_deviation {
                return Err(Refusal::Deviation);
            }
        }
        let mut placed: HashMap<u32, [f64; 2]> =
            us.iter().copied().zip(poly.iter().copied()).collect();
        for &(x, t, b) in &moved {
            let c = flat[t];
            placed.insert(
                x,
                std::array::from_fn(|i| b[0] * c[0][i] + b[1] * c[1][i] + b[2] * c[2][i]),
            );
        }
        if self.folds(&placed, moved.iter().map(|m| m.0)) {
            return Err(Refusal::Fold);
        }
        // Commit.
        self.snaps = snaps;
        for &f in &fs {
            self.remove_face(f);
        }
        let slots: Vec<u32> = corners.iter().map(|&c| self.add_face(c)).collect();
        for (x, t, b) in moved {
            self.set_param(x, Param::Face { f: slots[t], b });
        }
        Ok(())
    }

    /// Ear-clipping triangulation of the flattened ring (indices into `us`), best 3-D quality
    /// first; diagonals that are edges already are refused (they would make K non-simplicial).
    fn ears(
        &self,
        us: &[u32],
        poly: &[[f64; 2]],
        nv: V3,
        nvn: f64,
        lim: &RemovalLimits,
    ) -> Result<Vec<[usize; 3]>, Refusal> {
        let m = us.len();
        if m == 3 {
            // The one triangle must not be a face already (the tetrahedron case).
            if let Some(f) = self.face_of_edge(us[1], us[0]) {
                if self.face(f).is_some_and(|c| c.contains(&us[2])) {
                    return Err(Refusal::NoEar);
                }
            }
        }
        let mut idx: Vec<usize> = (0..m).collect();
        let mut out = Vec::new();
        let scale = poly
            .iter()
            .map(|p| p[0].abs().max(p[1].abs()))
            .fold(0.0, f64::max);
        let mut shape_refused = false;
        while idx.len() > 3 {
            let n = idx.len();
            let mut best: Option<(usize, f64)> = None;
            for j in 0..n {
                let (a, b, c) = (idx[(j + n - 1) % n], idx[j], idx[(j + 1) % n]);
                if orient2(poly[a], poly[b], poly[c]) <= 1e-12 * scale * scale {
                    continue;
                }
                let (ua, uc) = (us[a], us[c]);
                if self.he.contains_key(&(ua, uc)) || self.he.contains_key(&(uc, ua)) {
                    continue;
                }
                let empty = idx.iter().all(|&o| {
                    o == a
                        || o == b
                        || o == c
                        || bary2(poly[a], poly[b], poly[c], poly[o])
                            .iter()
                            .any(|&l| l < -1e-12)
                });
                if !empty {
                    continue;
                }
                let q = self.tri_ok([us[a], us[b], us[c]], nv, nvn, lim);
                let Some(q) = q else {
                    shape_refused = true;
                    continue;
                };
                if best.map_or(true, |(_, bq)| q > bq) {
                    best = Some((j, q));
                }
            }
            let Some((j, _)) = best else {
                return Err(if shape_refused {
                    Refusal::Shape
                } else {
                    Refusal::NoEar
                });
            };
            let n = idx.len();
            out.push([idx[(j + n - 1) % n], idx[j], idx[(j + 1) % n]]);
            idx.remove(j);
        }
        let last = [idx[0], idx[1], idx[2]];
        if self.tri_ok(last.map(|i| us[i]), nv, nvn, lim).is_none() {
            return Err(Refusal::Shape);
        }
        out.push(last);
        Ok(out)
    }

    /// The quality of a candidate triangle, or None if it breaks the shape limits.
    fn tri_ok(&self, t: [u32; 3], nv: V3, nvn: f64, lim: &RemovalLimits) -> Option<f64> {
        let p = t.map(|v| self.pos[v as usize]);
        let n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        let c = dot(n, nv) / (norm(n) * nvn);
        let q = quality(p[0], p[1], p[2]);
        (c >= lim.min_normal_cos && q >= lim.min_quality).then_some(q)
    }

    /// Split at the vertex x of S_T (a stellar split; x becomes a base vertex): the face of its
    /// parameter 1→3, or, when x lies on a base edge (one barycentric coordinate 0), the two
    /// faces of that edge 2→4. Returns the new face slots.
    pub fn split_face(&mut self, x: u32) -> Result<Vec<u32>, Refusal> {
        let Param::Face { f, b: bx } = self.param[x as usize] else {
            return Err(Refusal::Missing);
        };
        let c = self.face(f).ok_or(Refusal::Missing)?;
        let zeros: Vec<usize> = (0..3).filter(|&t| !(bx[t] > 0.0)).collect();
        let mut parts = vec![(f, c, bx)];
        match zeros.as_slice() {
            [] => {}
            [t] => {
                let (e0, e1) = (c[(t + 1) % 3], c[(t + 2) % 3]);
                let g = self.face_of_edge(e1, e0).ok_or(Refusal::Missing)?;
                let cg = self.face(g).ok_or(Refusal::Missing)?;
                parts.push((g, cg, permute(c, bx, cg)));
            }
            _ => return Err(Refusal::Locate),
        }
        let mut snaps = self.snaps;
        let mut plan = Vec::new();
        for &(face, corners, xb) in &parts {
            let moved = self.split_points(face, corners, xb, x, &mut snaps)?;
            plan.push((face, corners, xb, moved));
        }
        self.snaps = snaps;
        let mut out = Vec::new();
        for (face, corners, xb, moved) in plan {
            self.remove_face(face);
            let mut slot_of = [u32::MAX; 3];
            for t in (0..3).filter(|&t| xb[t] > 0.0) {
                let mut sub = corners;
                sub[t] = x;
                slot_of[t] = self.add_face(sub);
                out.push(slot_of[t]);
            }
            for (y, t, l) in moved {
                self.set_param(
                    y,
                    Param::Face {
                        f: slot_of[t],
                        b: l,
                    },
                );
            }
        }
        self.param[x as usize] = Param::Vertex;
        Ok(out)
    }

    /// The points of `face` re-expressed in the sub-triangles that replace one corner t (with
    /// xb[t] > 0) by x: λ_t = β_t/xb_t at x and β_s − λ_t·xb_s at the kept corners s.
    fn split_points(
        &self,
        face: u32,
        corners: [u32; 3],
        xb: [f64; 3],
        x: u32,
        snaps: &mut SnapStats,
    ) -> Result<Vec<(u32, usize, [f64; 3])>, Refusal> {
        let mut moved = Vec::new();
        for (y, beta) in self.points_in(face, corners) {
            if y == x {
                continue;
            }
            let mut best: Option<(usize, [f64; 3], f64)> = None;
            for t in (0..3).filter(|&t| xb[t] > 0.0) {
                let lt = beta[t] / xb[t];
                let l: [f64; 3] =
                    std::array::from_fn(|s| if s == t { lt } else { beta[s] - lt * xb[s] });
                let mn = l[0].min(l[1]).min(l[2]);
                if best.as_ref().map_or(true, |(_, _, m)| mn > *m) {
                    best = Some((t, l, mn));
                }
            }
            let (t, l, mn) = best.ok_or(Refusal::Locate)?;
            moved.push((y, t, snap(l, mn, snaps).ok_or(Refusal::Locate)?));
        }
        Ok(moved)
    }

    /// Flip the edge a–b of the faces (a, b, c) and (b, a, d) to c–d (see the module doc).
    pub fn flip(&mut self, a: u32, b: u32) -> Result<(), Refusal> {
        let f1 = self.face_of_edge(a, b).ok_or(Refusal::Missing)?;
        let f2 = self.face_of_edge(b, a).ok_or(Refusal::Missing)?;
        let c = rot(self.face(f1).ok_or(Refusal::Missing)?, a).ok_or(Refusal::Missing)?[2];
        let d = rot(self.face(f2).ok_or(Refusal::Missing)?, b).ok_or(Refusal::Missing)?[2];
        if c == d || self.he.contains_key(&(c, d)) || self.he.contains_key(&(d, c)) {
            return Err(Refusal::Missing);
        }
        if self.degree(a) <= 3 || self.degree(b) <= 3 {
            return Err(Refusal::Degree);
        }
        let [la, lc, ld] = self.unfold(a, b, c, d);
        let lb = [norm(sub(self.pos[b as usize], self.pos[a as usize])), 0.0];
        let t1 = [la, ld, lc];
        let t2 = [ld, lb, lc];
        let s = lb[0] * lb[0];
        if orient2(t1[0], t1[1], t1[2]) <= 1e-12 * s || orient2(t2[0], t2[1], t2[2]) <= 1e-12 * s {
            return Err(Refusal::NotConvex);
        }
        let flat = [t1, t2];
        let mut snaps = self.snaps;
        let mut moved = Vec::new();
        for (f, order, p) in [(f1, [a, b, c], [la, lb, lc]), (f2, [b, a, d], [lb, la, ld])] {
            for (x, bb) in self.points_in(f, order) {
                let q = [
                    bb[0] * p[0][0] + bb[1] * p[1][0] + bb[2] * p[2][0],
                    bb[0] * p[0][1] + bb[1] * p[1][1] + bb[2] * p[2][1],
                ];
                let (t, l) = locate(&flat, q, &mut snaps).ok_or(Refusal::Locate)?;
                moved.push((x, t, l));
            }
        }
        let mut placed: HashMap<u32, [f64; 2]> =
            [(a, la), (b, lb), (c, lc), (d, ld)].into_iter().collect();
        for &(x, t, l) in &moved {
            let c = flat[t];
            placed.insert(
                x,
                std::array::from_fn(|i| l[0] * c[0][i] + l[1] * c[1][i] + l[2] * c[2][i]),
            );
        }
        if self.folds(&placed, moved.iter().map(|m| m.0)) {
            return Err(Refusal::Fold);
        }
        self.snaps = snaps;
        self.remove_face(f1);
        self.remove_face(f2);
        let s1 = self.add_face([a, d, c]);
        let s2 = self.add_face([d, b, c]);
        for (x, t, l) in moved {
            self.set_param(
                x,
                Param::Face {
                    f: [s1, s2][t],
                    b: l,
                },
            );
        }
        Ok(())
    }

    /// Does a triangle of S_T at one of `movers`, with all three vertices `placed` in a flat
    /// layout of the changed region, have non-positive area there?
    fn folds(&self, placed: &HashMap<u32, [f64; 2]>, movers: impl Iterator<Item = u32>) -> bool {
        for x in movers {
            for &t in &self.fine_around[x as usize] {
                let c = self.fine_faces[t as usize];
                if let (Some(a), Some(b), Some(d)) =
                    (placed.get(&c[0]), placed.get(&c[1]), placed.get(&c[2]))
                {
                    if !(orient2(*a, *b, *d) > 0.0) {
                        return true;
                    }
                }
            }
        }
        false
    }

    /// Isometric layout of the faces (a, b, c), (b, a, d): a at 0, b on +x, c above, d below.
    fn unfold(&self, a: u32, b: u32, c: u32, d: u32) -> [[f64; 2]; 3] {
        let p = |v: u32| self.pos[v as usize];
        let ab = sub(p(b), p(a));
        let l = norm(ab);
        let place = |x: u32, sign: f64| {
            let ax = sub(p(x), p(a));
            let t = dot(ax, ab) / l;
            let h = norm(cross(ab, ax)) / l;
            [t, sign * h]
        };
        [[0.0, 0.0], place(c, 1.0), place(d, -1.0)]
    }

    /// Is the edge a–b (faces (a, b, c), (b, a, d)) locally Delaunay in the unfolded layout?
    pub fn is_delaunay(&self, a: u32, b: u32) -> Option<bool> {
        let f1 = self.face_of_edge(a, b)?;
        let f2 = self.face_of_edge(b, a)?;
        let c = rot(self.face(f1)?, a)?[2];
        let d = rot(self.face(f2)?, b)?[2];
        let p = |v: u32| self.pos[v as usize];
        let angle = |o: u32| {
            let (x, y) = (sub(p(a), p(o)), sub(p(b), p(o)));
            norm(cross(x, y)).atan2(dot(x, y))
        };
        Some(angle(c) + angle(d) <= std::f64::consts::PI + 1e-12)
    }
}
