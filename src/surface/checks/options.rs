//! The options of the surface checks.

use crate::surface::profile::Profile;
use crate::surface::target::SurfaceKind;

/// Options of the surface checks.
#[derive(Debug, Clone)]
pub struct SurfaceCheckOptions {
    /// Seed of the random samples (each check derives its own stream).
    pub seed: u64,
    /// Random points per examined vertex.
    pub samples_per_vertex: usize,
    /// Examine at most this many vertices (evenly spaced over the vertex list); `None`: all.
    pub max_vertices: Option<usize>,
    /// Vertices re-checked with the multi-precision oracle.
    pub mp_vertices: usize,
    /// Precision (bits) of the multi-precision re-check.
    pub mp_prec: u32,
    /// The parameter profile of the surface under test.
    pub profile: Profile,
    /// Run the measured (C′)/(C″) patch-intersection search.
    pub intersections: bool,
    /// S′ (Sec. 6.2); with the Loop S′ its own checks run too.
    pub surface: SurfaceKind,
}

impl Default for SurfaceCheckOptions {
    fn default() -> Self {
        SurfaceCheckOptions {
            seed: 20240601,
            samples_per_vertex: 24,
            max_vertices: None,
            mp_vertices: 4,
            mp_prec: crate::numeric::DEFAULT_MP_PREC,
            profile: Profile::Paper,
            intersections: true,
            surface: SurfaceKind::Pn,
        }
    }
}
