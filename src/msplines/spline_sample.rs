//! The manifold spline surface F(M) sampled to a triangle mesh: the barycentric grid of every
//! face of M at 2^level (the pattern `surface::output::sample_pattern_faces` shares with
//! `ppm sample`: points on edges and corners are listed once, so the output closes up
//! whenever M does), each point evaluated by Sec. 5.6 in a chart at a corner of its face.

use super::atlas::Atlas;
use super::mesh_spline::{MeshPoint, MeshSpline, SplineError};
use crate::mesh::SimplicialSurface;
use crate::surface::output::{sample_pattern_faces, SampledMesh};
use crate::surface::pps::SurfaceError;

/// Why the spline surface cannot be sampled.
#[derive(Debug, thiserror::Error)]
pub enum SampleError {
    /// The level is refused by the sampling pattern (memory budget).
    #[error(transparent)]
    Pattern(#[from] SurfaceError),
    /// F is undefined at a sample point (near a zero point on genus ≥ 2: `MS-5.6`).
    #[error("sample point in face {face} at {bary:?}: {source}")]
    Undefined {
        /// The face of M.
        face: u32,
        /// Barycentric coordinates.
        bary: [f64; 3],
        /// Why.
        source: SplineError,
    },
}

/// Sample F at every point of the level-`level` pattern of M (positions only).
pub fn sample(
    k: &SimplicialSurface,
    at: &Atlas,
    sp: &MeshSpline,
    level: u32,
) -> Result<SampledMesh, SampleError> {
    let faces: Vec<_> = k.faces().map(|f| k.face(f)).collect();
    let pat = sample_pattern_faces(&faces, level)?;
    let mut out = SampledMesh {
        faces: pat.faces,
        title: "ppm msplines sample: manifold spline surface (Gu-He-Qin, Sec. 5.6)",
        ..SampledMesh::default()
    };
    for sp_pt in &pat.points {
        let p = MeshPoint {
            face: sp_pt.face,
            bary: sp_pt.bary,
        };
        let e = sp
            .evaluate_anywhere(k, at, &p)
            .map_err(|source| SampleError::Undefined {
                face: p.face.0,
                bary: p.bary,
                source,
            })?;
        out.positions.push(e.value);
    }
    Ok(out)
}
