//! Where eval evaluated a point: the chart it chose and the point q of that chart's
//! p-domain, in the precision of the evaluation ([`Located`]); and the MPFR constants of a
//! construction held apart from the surface ([`MpConsts`]), so that a caller answering many
//! queries (the oracle session) builds them once per precision.

use crate::mesh::VertexId;
use crate::surface::eval::Chart;
use std::any::Any;

/// The chart eval chose for a point of a face σ and q in its p-domain.
#[derive(Debug, Clone, PartialEq)]
pub enum ChartAt<S> {
    /// The vertex PPS (Sec. 6.1.4): Ω_u, Ω_x or Ω_w of σ's canonical triangle (Fig. 6.2),
    /// the p-domain of `vertex`.
    Vertex {
        /// Which of the three charts.
        chart: Chart,
        /// The vertex of K whose p-domain holds q.
        vertex: VertexId,
        /// q ∈ Ω_vertex.
        q: [S; 2],
    },
    /// The (σ, v) PPS (SPEC `SV-D13`): the corner (σ, v), given by its vertex and label.
    Corner {
        /// The vertex v.
        v: VertexId,
        /// Its label k (0..m_v).
        k: u32,
        /// q in the plane of the corner's p-domain.
        q: [S; 2],
    },
}

/// A point of the surface with the chart eval chose (`None` for a construction without
/// charts to name, the manifold spline).
#[derive(Debug, Clone, PartialEq)]
pub struct Located<S> {
    /// The point of the surface.
    pub point: [S; 3],
    /// The chart and q.
    pub chart: Option<ChartAt<S>>,
}

/// A construction's constants at one MPFR precision, owned apart from the surface: built by
/// `SmoothSurface::mp_consts`, read back only by the same construction's
/// `SmoothSurface::eval_mp` (a mismatch is a typed error, never a panic).
pub struct MpConsts {
    bits: u32,
    consts: Box<dyn Any + Send + Sync>,
}

impl std::fmt::Debug for MpConsts {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MpConsts({} bits)", self.bits)
    }
}

impl MpConsts {
    /// Constants `c` at `bits`.
    pub(crate) fn new<T: Any + Send + Sync>(bits: u32, c: T) -> Self {
        MpConsts {
            bits,
            consts: Box::new(c),
        }
    }
    /// The precision they were built at.
    pub fn bits(&self) -> u32 {
        self.bits
    }
    /// The constants, if they are a `T`.
    pub(crate) fn get<T: Any>(&self) -> Option<&T> {
        self.consts.downcast_ref()
    }
}
