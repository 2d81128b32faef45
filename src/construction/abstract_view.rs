//! The Chapter 4 gluing data of a mesh seen through the abstract interface of Def. 3.4.1
//! ([`GluingData`]), so the general checkers of `crate::gluing::sampled` run on it unchanged.
//!
//! Sec. 4.1 puts every p-domain Ω_v in its own copy of R² ("we assume that Ω_u and Ω_w belong
//! to distinct copies of R²"). The abstract interface has one R², so the copies are made
//! literal: Ω_v is presented translated to its own cell of a square grid (spacing `COPY_SPACING`), and every map
//! un-translates, evaluates, and translates into the target's copy. The abstract checkers'
//! loops are over all pairs and triples of I, so a view is taken on a subset of vertices (the
//! restriction of gluing data to a subset of I is again gluing data).

use super::maps::{in_omega_v, EdgeConfig, Paper, Ppm, VertexPair, P2};
use super::mesh_gluing::PpmGluing;
use super::sampling::{sample_disk, sample_lens, sample_lens_inner_arc};
use crate::gluing::data::{GluingData, Idx, Point};
use crate::mesh::VertexId;
use rand::RngCore;
use rand_chacha::ChaCha8Rng;

/// Distance between the centres of neighbouring copies of R² (p-domains have radius < 1, so
/// copies 2.1 apart are disjoint). Copies are laid out on a square grid around the origin to
/// keep coordinates small: the sampled checkers' tolerances scale with |value|.
pub const COPY_SPACING: f64 = 2.1;

/// A transition map to use instead of the paper's (for planted-fault tests):
/// `(w, u, p) ↦ Some(φ_wu(p))` in local (un-translated) coordinates, or `None` for the paper's.
pub type PhiOverride<'a> = dyn Fn(VertexId, VertexId, [f64; 2]) -> Option<[f64; 2]> + Sync + 'a;

/// The abstract view of the PPM gluing data on a subset of the vertices.
pub struct AbstractPpm<'k> {
    g: PpmGluing<'k>,
    /// The vertices in the view; the index in this list is the copy rank.
    ids: Vec<VertexId>,
    phi_override: Option<Box<PhiOverride<'k>>>,
}

impl<'k> AbstractPpm<'k> {
    /// The view on `ids` (vertices of K; others are ignored).
    pub fn new(g: PpmGluing<'k>, ids: Vec<VertexId>) -> Self {
        let k = g.surface();
        let ids = ids.into_iter().filter(|&v| k.contains(v)).collect();
        AbstractPpm {
            g,
            ids,
            phi_override: None,
        }
    }

    /// The closed neighbourhood of v: v and its link vertices.
    pub fn star_of(g: PpmGluing<'k>, v: VertexId) -> Self {
        let k = g.surface();
        let mut ids = vec![v];
        ids.extend((0..k.degree(v)).filter_map(|i| k.link_vertex(v, i)));
        Self::new(g, ids)
    }

    /// Replace the transition maps (planted faults in tests).
    pub fn with_phi_override(mut self, f: Box<PhiOverride<'k>>) -> Self {
        self.phi_override = Some(f);
        self
    }

    fn rank(&self, i: Idx) -> Option<usize> {
        self.ids.iter().position(|v| v.0 == i)
    }
    /// Centre of the copy of R² holding Ω_i (where Ω_i's local origin is drawn).
    pub fn copy_centre(&self, i: Idx) -> Option<[f64; 2]> {
        self.offset(i)
    }

    fn offset(&self, i: Idx) -> Option<[f64; 2]> {
        let r = self.rank(i)?;
        let side = (self.ids.len() as f64).sqrt().ceil().max(1.0) as usize;
        let half = (side / 2) as f64;
        Some([
            COPY_SPACING * ((r % side) as f64 - half),
            COPY_SPACING * ((r / side) as f64 - half),
        ])
    }
    fn to_local(&self, i: Idx, p: &Point<f64, 2>) -> Option<[f64; 2]> {
        let o = self.offset(i)?;
        Some([p[0] - o[0], p[1] - o[1]])
    }
    fn to_global(&self, i: Idx, p: [f64; 2]) -> Option<Point<f64, 2>> {
        let o = self.offset(i)?;
        Some([p[0] + o[0], p[1] + o[1]])
    }
    fn edge(&self, i: Idx, j: Idx) -> Option<EdgeConfig> {
        match self.g.pair(VertexId(i), VertexId(j)).ok()? {
            VertexPair::Edge(e) => Some(e),
            _ => None,
        }
    }
    fn degree(&self, i: Idx) -> Option<u32> {
        self.g.degree(VertexId(i)).ok()
    }
}

fn p2(p: [f64; 2]) -> P2<f64> {
    P2::new(p[0], p[1])
}

impl GluingData<2> for AbstractPpm<'_> {
    type S = f64;

    fn indices(&self) -> Vec<Idx> {
        self.ids.iter().map(|v| v.0).collect()
    }

    /// Def. 4.1.1 in the copy of v.
    fn in_p_domain(&self, i: Idx, p: &Point<f64, 2>) -> bool {
        match (self.degree(i), self.to_local(i, p)) {
            (Some(m), Some(q)) => in_omega_v(m, &p2(q)).is_true(),
            _ => false,
        }
    }

    /// Def. 4.1.9, literally.
    fn in_gluing_domain(&self, i: Idx, j: Idx, p: &Point<f64, 2>) -> bool {
        if self.rank(j).is_none() {
            return false;
        }
        match self.to_local(i, p) {
            Some(q) => self
                .g
                .in_omega_uw(VertexId(i), VertexId(j), &p2(q))
                .map(|t| t.is_true())
                .unwrap_or(false),
            None => false,
        }
    }

    /// Def. 4.1.10: φ_ji : Ω_ij → Ω_ji.
    fn phi(&self, j: Idx, i: Idx, p: &Point<f64, 2>) -> Option<Point<f64, 2>> {
        let q = self.to_local(i, p)?;
        self.rank(j)?;
        if let Some(f) = &self.phi_override {
            if let Some(r) = f(VertexId(j), VertexId(i), q) {
                return self.to_global(j, r);
            }
        }
        let r = self.g.phi::<f64>(VertexId(j), VertexId(i), &p2(q)).ok()?;
        self.to_global(j, r.to_f64())
    }

    fn sample_p_domain(&self, i: Idx, rng: &mut ChaCha8Rng, n: usize) -> Vec<Point<f64, 2>> {
        let Some(m) = self.degree(i) else {
            return vec![];
        };
        let rho = super::maps::omega_radius::<f64>(m, 53);
        sample_disk::<f64>(rng.next_u64(), n, &rho, &std::f64::consts::PI, 53)
            .points
            .into_iter()
            .map(|(_, p)| p.to_f64())
            .filter(|q| in_omega_v(m, &p2(*q)).is_true())
            .filter_map(|q| self.to_global(i, q))
            .collect()
    }

    /// Samples of Ω_ij: lens points pulled back by R_(i,j)⁻¹∘g_i⁻¹ (Ω_ij's image under
    /// g_i∘R_(i,j) lies in the canonical lens E), kept when Def. 4.1.9 literally accepts them.
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
        let Some(e) = self.edge(i, j) else {
            return vec![];
        };
        sample_lens::<f64>(rng.next_u64(), n.max(8), 53)
            .points
            .into_iter()
            .filter_map(|(_, q)| {
                let p = Paper.r_uw_inv(&e, &Paper.g_v_inv(e.m_u, &q).ok()?);
                Paper
                    .in_omega_uw_literal(&e, &p)
                    .is_true()
                    .then(|| p.to_f64())
            })
            .filter_map(|q| self.to_global(i, q))
            .collect()
    }

    /// ∂Ω_ij ∩ Ω_i: the pull-back of the arc ∂D ∩ int(C) of the canonical lens.
    fn gluing_boundary_points(
        &self,
        i: Idx,
        j: Idx,
        rng: &mut ChaCha8Rng,
        n: usize,
    ) -> Vec<Point<f64, 2>> {
        let (Some(e), Some(_)) = (self.edge(i, j), self.rank(j)) else {
            return vec![];
        };
        sample_lens_inner_arc::<f64>(rng.next_u64(), n.max(4), 53)
            .points
            .into_iter()
            .filter_map(|(_, q)| {
                let p = Paper.r_uw_inv(&e, &Paper.g_v_inv(e.m_u, &q).ok()?);
                in_omega_v(e.m_u, &p).is_true().then(|| p.to_f64())
            })
            .filter_map(|q| self.to_global(i, q))
            .collect()
    }

    fn scale(&self) -> f64 {
        1.0
    }

    /// φ_wu = R⁻¹∘g_w⁻¹∘h∘g_u∘R scales angles by m_u/6 (g_u) and 6/m_w (g_w⁻¹); rotations and
    /// h are isometries and the radial factors are ≤ 2. An angular rounding error is thus
    /// amplified by at most a = max(1, m_max/6)·max(1, 6/m_min) per transition, and by a² for
    /// the compositions the cocycle checks compare (also the factor the Chapter 4 checks use,
    /// `construction::checks`).
    fn amplification(&self) -> f64 {
        let degrees: Vec<f64> = self
            .ids
            .iter()
            .filter_map(|v| self.g.degree(*v).ok())
            .map(f64::from)
            .collect();
        let hi = degrees.iter().copied().fold(6.0, f64::max);
        let lo = degrees.iter().copied().fold(6.0, f64::min);
        let a = (hi / 6.0).max(1.0) * (6.0 / lo).max(1.0);
        a * a
    }
}
