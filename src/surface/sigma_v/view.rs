//! The (σ, v)-indexed gluing data through the abstract interface of Def. 3.4.1
//! ([`GluingData`]), in both versions of the tutorial, so the general checkers of
//! `crate::gluing::sampled` and (C), (C′), (C″) of `crate::gluing::ppm` run on it unchanged.
//!
//! * [`Version::FirstAttempt`] (T 2037–2041): Ω_(σ,v) = D_v ∩ int Δ_(σ,v) literally, every wedge
//!   in the one plane of its P-polygon, all P-polygons centred at the origin (f = id). The
//!   tutorial itself finds "Ω_(σ,v) ∩ Ω_(τ,v) ≠ ∅ … So, I did NOT make it right" (T 2092–2100):
//!   `check_1` must fail with a witness (SPEC `SV-first`).
//! * [`Version::Fixed`] (T 2112–2120): Ω_(σ,v) = f_(σ,v)⁻¹(W_(σ,v)) with f_(σ,v) the rotation of
//!   [`super::wedge`] followed by a translation to the corner's own cell of a square grid
//!   (spacing [`COPY_SPACING`], as the vertex construction's view), so the envelope triangles
//!   are pairwise disjoint.
//!
//! The view is taken on a subset of I (the checkers loop over all pairs and triples).

use super::gluing::{g_uw_on_domain, Corner, CornerId, PairCase, SigmaV};
use super::wedge::WedgeTable;
use crate::construction::abstract_view::COPY_SPACING;
use crate::construction::config::EdgeConfig;
use crate::construction::maps::{g_v_inv, rotate_frac, P2};
use crate::construction::sampling::sample_lens;
use crate::gluing::data::{GluingData, Idx, Point};
use rand::{Rng, RngCore};
use rand_chacha::ChaCha8Rng;

/// Which Ω_(σ,v) of the tutorial.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum Version {
    /// T 2037–2041: all wedges in one plane (fails Def. 3.4.1(1)).
    FirstAttempt,
    /// T 2112–2120: separated by rigid maps f_(σ,v).
    Fixed,
}

/// A transition map replacing the tutorial's (planted faults): `(j, i, q) ↦ φ_ji(q)` in plane
/// coordinates, `None` for the tutorial's.
pub(crate) type SvPhiOverride<'a> =
    dyn Fn(Corner, Corner, [f64; 2]) -> Option<[f64; 2]> + Sync + 'a;

/// Per case-(2) pair (i, j): the grid points of Ω_uw found in Ω_ij, computed once.
type GridCache = std::collections::HashMap<(Idx, Idx), Vec<P2<f64>>>;

/// The abstract view on a subset of the corners.
pub struct SigmaVView<'a> {
    g: &'a SigmaV,
    t: WedgeTable<f64>,
    ids: Vec<CornerId>,
    version: Version,
    phi_override: Option<Box<SvPhiOverride<'a>>>,
    /// Per case-(2) pair: the points of a fixed grid of Ω_uw that lie in Ω_ij (see
    /// [`Self::grid_points`]).
    grid: std::sync::Mutex<GridCache>,
}

/// Side of the grid of the canonical lens whose pull-backs seed the samples of the case-(2)
/// gluing domains. The grid is invariant under h (x ↦ 1 − x, y ↦ −y), so g_(u,w) maps the
/// grid of Ω_uw onto the grid of Ω_wu: Ω_ij and Ω_ji are found non-empty together (up to
/// rounding on their boundaries), also when they are thin slivers.
pub(crate) const LENS_GRID_SIDE: usize = 64;

impl<'a> SigmaVView<'a> {
    /// The view on `ids` (ids outside I are dropped).
    pub fn new(g: &'a SigmaV, ids: Vec<CornerId>, version: Version) -> Self {
        let ids = ids.into_iter().filter(|c| g.corner(*c).is_ok()).collect();
        SigmaVView {
            t: WedgeTable::new(g.degrees().iter().copied(), g.kappa, 53),
            g,
            ids,
            version,
            phi_override: None,
            grid: Default::default(),
        }
    }

    /// The view on the corners of the given vertices.
    pub fn at_vertices(g: &'a SigmaV, vs: &[crate::mesh::VertexId], version: Version) -> Self {
        let ids = vs
            .iter()
            .flat_map(|&v| g.corners_at(v).map(|c| g.id(c)).collect::<Vec<_>>())
            .collect();
        Self::new(g, ids, version)
    }

    /// Replace the transition maps (planted faults).
    pub fn with_phi_override(mut self, f: Box<SvPhiOverride<'a>>) -> Self {
        self.phi_override = Some(f);
        self
    }

    /// The wedge constants in use.
    pub fn wedges(&self) -> &WedgeTable<f64> {
        &self.t
    }

    fn rank(&self, i: Idx) -> Option<usize> {
        self.ids.iter().position(|c| c.0 == i)
    }

    /// The corner of index i (must be in the view).
    pub fn corner(&self, i: Idx) -> Option<Corner> {
        self.rank(i)?;
        self.g.corner(CornerId(i)).ok()
    }

    /// Centre of i's copy of R² (the origin for the first attempt).
    pub fn copy_centre(&self, i: Idx) -> Option<[f64; 2]> {
        let r = self.rank(i)?;
        if self.version == Version::FirstAttempt {
            return Some([0.0, 0.0]);
        }
        let side = (self.ids.len() as f64).sqrt().ceil().max(1.0) as usize;
        let half = (side / 2) as f64;
        Some([
            COPY_SPACING * ((r % side) as f64 - half),
            COPY_SPACING * ((r / side) as f64 - half),
        ])
    }

    /// f_i: a point of i's copy → the plane of P_v.
    pub fn to_plane(&self, i: Idx, x: &Point<f64, 2>) -> Option<P2<f64>> {
        let c = self.corner(i)?;
        let o = self.copy_centre(i)?;
        let p = P2::new(x[0] - o[0], x[1] - o[1]);
        Some(match self.version {
            Version::FirstAttempt => p,
            Version::Fixed => self.t.get(self.g.degree(c.v))?.to_plane(c.k, &p),
        })
    }

    /// f_i⁻¹: the plane of P_v → i's copy.
    pub fn from_plane(&self, i: Idx, q: &P2<f64>) -> Option<Point<f64, 2>> {
        let c = self.corner(i)?;
        let o = self.copy_centre(i)?;
        let p = match self.version {
            Version::FirstAttempt => q.clone(),
            Version::Fixed => self.t.get(self.g.degree(c.v))?.to_local(c.k, q),
        };
        Some([p.x + o[0], p.y + o[1]])
    }

    fn local_to_global(&self, i: Idx, p: [f64; 2]) -> Option<Point<f64, 2>> {
        let c = self.corner(i)?;
        let w = self.t.get(self.g.degree(c.v))?;
        self.from_plane(i, &w.to_plane(c.k, &P2::new(p[0], p[1])))
    }

    /// Candidates for Ω_ij (not yet filtered), in the order they are drawn. Every random
    /// number is drawn here; the maps that bring a case-(2) candidate to the plane of P_v
    /// (g_v⁻¹, g_(w,u)) are left to [`Cand::into_plane`], so that a filter that stops early
    /// maps only the candidates it reaches (the maps were most of the sampling's time).
    fn candidates(&self, i: Corner, j: Corner, rng: &mut ChaCha8Rng, n: usize) -> Vec<Cand> {
        let mut out = Vec::new();
        match self.g.case(i, j) {
            PairCase::SameVertex => {
                let m = self.g.degree(i.v);
                if let Some(w) = self.t.get(m) {
                    out.extend(self.wedge_samples(i, rng, n).into_iter().map(Cand::Plane));
                    out.extend(self.wedge_samples(j, rng, n).into_iter().map(Cand::Plane));
                    // W_i ∩ W_j always contains a neighbourhood of the centre.
                    let r = 3.0 * w.delta;
                    for _ in 0..n {
                        let (a, t): (f64, f64) =
                            (rng.gen_range(0.0..std::f64::consts::TAU), rng.gen());
                        out.push(Cand::Plane(P2::new(
                            r * t.sqrt() * a.cos(),
                            r * t.sqrt() * a.sin(),
                        )));
                    }
                    out.push(Cand::Plane(P2::new(0.0, 0.0)));
                }
            }
            PairCase::Edge(e) => {
                for (_, q) in sample_lens::<f64>(rng.next_u64(), n, 53).points {
                    out.push(Cand::Lens(e, q));
                }
                // And from j's side (so Ω_ij and Ω_ji are found non-empty together, also
                // when they are thin slivers along a side of W_j).
                let back = e.reversed();
                for y in self.wedge_samples(j, rng, n) {
                    out.push(Cand::Back(back, y));
                }
            }
            PairCase::DeclaredEmptyEdge(_) | PairCase::NotAdjacent => {}
        }
        out
    }

    /// Plane-coordinate samples of W_i: uniform, near the arc, near the two sides.
    fn wedge_samples(&self, i: Corner, rng: &mut ChaCha8Rng, n: usize) -> Vec<P2<f64>> {
        let Some(w) = self.t.get(self.g.degree(i.v)) else {
            return vec![];
        };
        let [r, a, b] = w.envelope_f64();
        let mut out = Vec::with_capacity(n);
        let mut tries = 0;
        while out.len() < n && tries < 50 * n {
            tries += 1;
            let kind = tries % 4;
            let kexp = 1 + (tries / 4) % 14;
            let eps = 10f64.powi(-(kexp as i32)) * rng.gen_range(0.5..1.0);
            let p = match kind {
                0 | 1 => {
                    let (s, t): (f64, f64) = (rng.gen(), rng.gen());
                    let (s, t) = if s + t > 1.0 {
                        (1.0 - s, 1.0 - t)
                    } else {
                        (s, t)
                    };
                    [
                        r[0] + s * (a[0] - r[0]) + t * (b[0] - r[0]),
                        r[1] + s * (a[1] - r[1]) + t * (b[1] - r[1]),
                    ]
                }
                2 => {
                    let ang = rng.gen_range(-0.6..0.6) * std::f64::consts::PI;
                    let rad = w.rho * (1.0 - eps);
                    [rad * ang.cos(), rad * ang.sin()]
                }
                _ => {
                    let s: f64 = rng.gen();
                    let (end, nrm) = if rng.gen::<bool>() {
                        (a, w.n1)
                    } else {
                        (b, w.n2)
                    };
                    [
                        r[0] + s * (end[0] - r[0]) + eps * nrm.0,
                        r[1] + s * (end[1] - r[1]) + eps * nrm.1,
                    ]
                }
            };
            let p = P2::new(p[0], p[1]);
            if w.in_wedge_local(&p) {
                out.push(w.to_plane(i.k, &p));
            }
        }
        out
    }

    /// The grid points of Ω_ij (case (2)), cached per pair.
    fn grid_points(&self, i: Idx, j: Idx, a: Corner, b: Corner) -> Vec<P2<f64>> {
        let PairCase::Edge(e) = self.g.case(a, b) else {
            return vec![];
        };
        if let Ok(m) = self.grid.lock() {
            if let Some(v) = m.get(&(i, j)) {
                return v.clone();
            }
        }
        let pts: Vec<P2<f64>> = super::gluing::omega_uw_grid(&e, LENS_GRID_SIDE)
            .into_iter()
            .filter(|q| self.in_gluing_plane(a, b, q))
            .collect();
        if let Ok(mut m) = self.grid.lock() {
            m.insert((i, j), pts.clone());
        }
        pts
    }

    fn phi_plane(&self, j: Corner, i: Corner, q: &P2<f64>) -> Option<P2<f64>> {
        if let Some(f) = &self.phi_override {
            if let Some(y) = f(j, i, q.to_f64()) {
                return self.g.phi(&self.t, j, i, q).map(|_| P2::new(y[0], y[1]));
            }
        }
        self.g.phi(&self.t, j, i, q)
    }

    fn in_gluing_plane(&self, i: Corner, j: Corner, q: &P2<f64>) -> bool {
        self.g.phi(&self.t, j, i, q).is_some()
    }
}

/// A candidate of [`SigmaVView::candidates`]: a point of the plane of P_v, or a point the
/// case-(2) maps bring there (a point of the canonical lens, by g_v⁻¹ and the rotation to the
/// edge's label; a point of W_j, by g_(w,u) of the reversed edge).
enum Cand {
    Plane(P2<f64>),
    Lens(EdgeConfig, P2<f64>),
    Back(EdgeConfig, P2<f64>),
}

impl Cand {
    /// The point in the plane of P_v; `None` where the map is undefined (such a candidate
    /// was never one).
    fn into_plane(self) -> Option<P2<f64>> {
        match self {
            Cand::Plane(q) => Some(q),
            Cand::Lens(e, q) => g_v_inv(e.m_u, &q)
                .ok()
                .map(|p| rotate_frac(&p, e.i as i64, e.m_u as i64)),
            Cand::Back(back, y) => g_uw_on_domain(&back, &y),
        }
    }
}

impl GluingData<2> for SigmaVView<'_> {
    type S = f64;

    fn indices(&self) -> Vec<Idx> {
        self.ids.iter().map(|c| c.0).collect()
    }

    fn in_p_domain(&self, i: Idx, p: &Point<f64, 2>) -> bool {
        match (self.corner(i), self.to_plane(i, p)) {
            (Some(c), Some(q)) => self.g.in_wedge(&self.t, c, &q),
            _ => false,
        }
    }

    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<f64, 2>) -> bool {
        match (self.corner(i), self.corner(j), self.to_plane(i, p)) {
            (Some(a), Some(b), Some(q)) => self.in_gluing_plane(a, b, &q),
            _ => false,
        }
    }

    fn phi(&self, j: Idx, i: Idx, p: &Point<f64, 2>) -> Option<Point<f64, 2>> {
        let (a, b) = (self.corner(i)?, self.corner(j)?);
        let q = self.to_plane(i, p)?;
        let y = self.phi_plane(b, a, &q)?;
        self.from_plane(j, &y)
    }

    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<f64, 2>> {
        let Some(c) = self.corner(i) else {
            return vec![];
        };
        self.wedge_samples(c, rng, n)
            .iter()
            .filter_map(|q| self.from_plane(i, q))
            .collect()
    }

    /// Candidates (wedge and centre samples for case 1, the report's lens pulled back for
    /// case 2) filtered by membership; when few are kept, a second round samples the
    /// bounding box of the kept points (the Ω_ij are small near the centre and along spokes).
    fn sample_gluing_domain(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, 2>> {
        let (Some(a), Some(b)) = (self.corner(i), self.corner(j)) else {
            return vec![];
        };
        if i == j {
            return self.sample_p_domain(i, rng, n);
        }
        let want = n.max(1);
        let cand = self.candidates(a, b, rng, (4 * want).max(400));
        // Only the first `want` members are returned, so the filter stops there: the same
        // points (the candidates draw every random number before it runs).
        let mut kept: Vec<P2<f64>> = cand
            .into_iter()
            .filter_map(Cand::into_plane)
            .filter(|q| self.in_gluing_plane(a, b, q))
            .take(want)
            .collect();
        if !kept.is_empty() && kept.len() < want {
            let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
            for q in &kept {
                lo = [lo[0].min(q.x), lo[1].min(q.y)];
                hi = [hi[0].max(q.x), hi[1].max(q.y)];
            }
            let pad = [0.1 * (hi[0] - lo[0]) + 1e-9, 0.1 * (hi[1] - lo[1]) + 1e-9];
            for _ in 0..8 * want {
                let q = P2::new(
                    rng.gen_range(lo[0] - pad[0]..hi[0] + pad[0]),
                    rng.gen_range(lo[1] - pad[1]..hi[1] + pad[1]),
                );
                if self.in_gluing_plane(a, b, &q) {
                    kept.push(q);
                }
            }
        }
        if kept.len() < want {
            let grid = self.grid_points(i, j, a, b);
            let step = (grid.len() / want).max(1);
            kept.extend(grid.into_iter().step_by(step));
        }
        kept.truncate(want);
        kept.iter().filter_map(|q| self.from_plane(i, q)).collect()
    }

    /// Points of ∂Ω_ij ∩ Ω_i: bisection between a point of Ω_ij and a point of Ω_i ∖ Ω_ij
    /// (60 halvings); the outer end is kept when it lies in Ω_i.
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, 2>> {
        let (Some(a), Some(b)) = (self.corner(i), self.corner(j)) else {
            return vec![];
        };
        if i == j {
            return vec![];
        }
        let inside = self.sample_gluing_domain(i, j, rng, n.max(4));
        if inside.is_empty() {
            return vec![];
        }
        let outside: Vec<P2<f64>> = self
            .wedge_samples(a, rng, 4 * n.max(4))
            .into_iter()
            .filter(|q| !self.in_gluing_plane(a, b, q))
            .collect();
        let mut out = Vec::new();
        for (t, o) in outside.iter().enumerate().take(n.max(4)) {
            let Some(mut x) = self.to_plane(i, &inside[t % inside.len()]) else {
                continue;
            };
            let mut y = o.clone();
            for _ in 0..60 {
                let mid = P2::new(0.5 * (x.x + y.x), 0.5 * (x.y + y.y));
                if self.in_gluing_plane(a, b, &mid) {
                    x = mid;
                } else {
                    y = mid;
                }
            }
            if self.g.in_wedge(&self.t, a, &y) {
                if let Some(p) = self.from_plane(i, &y) {
                    out.push(p);
                }
            }
        }
        out
    }

    /// As the vertex construction's view: angles are scaled by m_u/6 and 6/m_w in g_(u,w);
    /// the rigid maps are isometries.
    fn amplification(&self) -> f64 {
        let ds: Vec<f64> = self
            .ids
            .iter()
            .filter_map(|c| self.g.corner(*c).ok())
            .map(|c| f64::from(self.g.degree(c.v)))
            .collect();
        let hi = ds.iter().copied().fold(6.0, f64::max);
        let lo = ds.iter().copied().fold(6.0, f64::min);
        let a = (hi / 6.0).max(1.0) * (6.0 / lo).max(1.0);
        a * a
    }
}

/// Local point helper for tests: a point of i's copy from local (un-rotated) coordinates.
impl SigmaVView<'_> {
    /// The global point of a local point p of corner i.
    pub fn global_of_local(&self, i: Idx, p: [f64; 2]) -> Option<Point<f64, 2>> {
        self.local_to_global(i, p)
    }
}
