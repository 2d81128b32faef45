//! What the renderer draws: triangles over vertices carrying a position, a unit normal and
//! optionally the Gaussian and mean curvature.

use super::error::RenderError;

/// A triangle mesh with per-vertex shading data. Normals need not be unit (they are normalised
/// after interpolation) but a zero normal marks a singular point (drawn unlit).
#[derive(Debug, Clone, Default)]
pub struct Scene {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Per-vertex normals (same length as `positions`).
    pub normals: Vec<[f64; 3]>,
    /// Gaussian curvature K per vertex, when the source carries it.
    pub gaussian: Option<Vec<f64>>,
    /// Mean curvature H per vertex (signed by `normals`), when the source carries it.
    pub mean: Option<Vec<f64>>,
    /// Triangles (vertex indices; their orientation is the surface's).
    pub faces: Vec<[u32; 3]>,
}

impl Scene {
    /// Check the array lengths and every index; the renderer relies on it.
    pub fn validate(&self) -> Result<(), RenderError> {
        let n = self.positions.len();
        let lens = [
            ("normals", Some(self.normals.len())),
            ("gaussian", self.gaussian.as_ref().map(Vec::len)),
            ("mean", self.mean.as_ref().map(Vec::len)),
        ];
        for (what, len) in lens {
            if let Some(got) = len.filter(|&l| l != n) {
                return Err(RenderError::LengthMismatch {
                    what,
                    got,
                    expected: n,
                });
            }
        }
        for (face, f) in self.faces.iter().enumerate() {
            if let Some(&index) = f.iter().find(|&&i| i as usize >= n) {
                return Err(RenderError::IndexOutOfRange {
                    face,
                    index,
                    count: n,
                });
            }
        }
        if self.faces.is_empty() {
            return Err(RenderError::Empty("no triangles".into()));
        }
        Ok(())
    }

    /// Axis-aligned bounding box of the finite positions (None if there is none).
    pub fn bbox(&self) -> Option<([f64; 3], [f64; 3])> {
        let mut it = self
            .positions
            .iter()
            .filter(|p| p.iter().all(|x| x.is_finite()));
        let first = *it.next()?;
        Some(it.fold((first, first), |(lo, hi), p| {
            (
                std::array::from_fn(|d| lo[d].min(p[d])),
                std::array::from_fn(|d| hi[d].max(p[d])),
            )
        }))
    }
}
