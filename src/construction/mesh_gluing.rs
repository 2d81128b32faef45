//! Chapter 4 on a mesh: the set of gluing data G = ((Ω_v)_{v∈I}, (Ω_uw), (φ_wu)) built from a
//! validated [`SimplicialSurface`]. I = the vertices of K; every map is evaluated through the
//! configuration (degrees and half-edge labels, Sec. 6.1.3) of the pair involved.

use super::maps::{ConfigError, EdgeConfig, MapError, Paper, Ppm, TriangleConfig, VertexPair, P2};
use crate::mesh::{FaceId, SimplicialSurface, VertexId};
use crate::numeric::{Scalar, Trit};
use thiserror::Error;

/// Errors naming the mesh elements involved.
#[derive(Debug, Error, PartialEq)]
pub enum GluingError {
    /// The vertex is not a vertex of K (an unreferenced or out-of-range slot).
    #[error("vertex {0} is not a vertex of K")]
    NoSuchVertex(VertexId),
    /// The pair is not an edge of K, where an edge configuration was needed.
    #[error("[{0}, {1}] is not an edge of K")]
    NoSuchEdge(VertexId, VertexId),
    /// The configuration of an edge or triangle is invalid (degree < 3, bad label, not a fan).
    #[error("configuration of [{u}, {w}]: {err}")]
    Config {
        /// First vertex of the oriented edge (for a triangle: its first corner).
        u: VertexId,
        /// Second vertex of the oriented edge (for a triangle: its second corner).
        w: VertexId,
        /// What is wrong with the configuration.
        err: ConfigError,
    },
    /// φ_wu could not be evaluated at the given point.
    #[error("φ_{w}{u} at the given point: {err}")]
    Map {
        /// Source vertex: the point is in Ω_u.
        u: VertexId,
        /// Target vertex: the image is in Ω_w.
        w: VertexId,
        /// Why the map failed.
        err: MapError,
    },
}

/// The PPM gluing data of a simplicial surface (Defs. 4.1.1–4.1.10).
#[derive(Debug, Clone, Copy)]
pub struct PpmGluing<'k> {
    k: &'k SimplicialSurface,
}

impl<'k> PpmGluing<'k> {
    /// The gluing data of K.
    pub fn new(k: &'k SimplicialSurface) -> Self {
        PpmGluing { k }
    }

    /// The simplicial surface K.
    pub fn surface(&self) -> &'k SimplicialSurface {
        self.k
    }

    /// m_v (Def. 4.1.1), or an error when v is not in I.
    pub fn degree(&self, v: VertexId) -> Result<u32, GluingError> {
        if self.k.contains(v) {
            Ok(self.k.degree(v))
        } else {
            Err(GluingError::NoSuchVertex(v))
        }
    }

    /// The configuration of the oriented edge [u, w]: (m_u, s_u(w), m_w, s_w(u)).
    pub fn edge_config(&self, u: VertexId, w: VertexId) -> Result<EdgeConfig, GluingError> {
        let m_u = self.degree(u)?;
        let m_w = self.degree(w)?;
        let i = self.k.s(u, w).ok_or(GluingError::NoSuchEdge(u, w))?;
        let j = self.k.s(w, u).ok_or(GluingError::NoSuchEdge(w, u))?;
        EdgeConfig::new(m_u, i, m_w, j).map_err(|err| GluingError::Config { u, w, err })
    }

    /// The pair (u, w) as Defs. 4.1.9/4.1.10 distinguish it: u = w, an edge, or neither.
    pub fn pair(&self, u: VertexId, w: VertexId) -> Result<VertexPair, GluingError> {
        let m_u = self.degree(u)?;
        self.degree(w)?;
        if u == w {
            return Ok(VertexPair::Same { m: m_u });
        }
        match self.edge_config(u, w) {
            Ok(e) => Ok(VertexPair::Edge(e)),
            Err(GluingError::NoSuchEdge(..)) => Ok(VertexPair::NotAdjacent),
            Err(e) => Err(e),
        }
    }

    /// The triangle face f = [u, w, x] (consistently oriented) as a configuration.
    pub fn triangle_config(
        &self,
        f: FaceId,
    ) -> Result<(TriangleConfig, [VertexId; 3]), GluingError> {
        let [u, w, x] = self.k.face(f);
        let (uw, wx, xu) = (
            self.edge_config(u, w)?,
            self.edge_config(w, x)?,
            self.edge_config(x, u)?,
        );
        TriangleConfig::ccw(uw.m_u, wx.m_u, xu.m_u, uw.i, wx.i, xu.i)
            .map(|t| (t, [u, w, x]))
            .map_err(|err| GluingError::Config { u, w, err })
    }

    /// Def. 4.1.1: p ∈ Ω_v.
    pub fn in_omega<S: Scalar>(&self, v: VertexId, p: &P2<S>) -> Result<Trit, GluingError> {
        let m = self.degree(v)?;
        Ok(super::maps::in_omega_v(m, p))
    }

    /// Def. 4.1.9 (literally): p ∈ Ω_uw.
    pub fn in_omega_uw<S: Scalar>(
        &self,
        u: VertexId,
        w: VertexId,
        p: &P2<S>,
    ) -> Result<Trit, GluingError> {
        Ok(Paper.in_omega_pair(&self.pair(u, w)?, p))
    }

    /// Sec. 6.1.3: the canonical-lens membership test for p ∈ Ω_uw (differs from Def. 4.1.9
    /// for m_u ≥ 11; see SPEC.md `D4.1.9-lens`).
    pub fn in_omega_uw_lens<S: Scalar>(
        &self,
        u: VertexId,
        w: VertexId,
        p: &P2<S>,
    ) -> Result<Trit, GluingError> {
        match self.pair(u, w)? {
            VertexPair::Edge(e) => Ok(Paper.in_omega_uw_lens(&e, p)),
            other => Ok(Paper.in_omega_pair(&other, p)),
        }
    }

    /// Def. 4.1.10: φ_wu : Ω_uw → Ω_wu (note the order: the map indexed wu goes *from* the
    /// gluing domain of u towards w, *to* the gluing domain of w towards u).
    pub fn phi<S: Scalar>(
        &self,
        w: VertexId,
        u: VertexId,
        p: &P2<S>,
    ) -> Result<P2<S>, GluingError> {
        let pair = self.pair(u, w)?;
        super::maps::phi_wu(&pair, p).map_err(|err| GluingError::Map { u, w, err })
    }
}
