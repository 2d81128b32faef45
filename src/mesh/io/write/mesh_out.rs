//! A triangle mesh with its optional per-vertex attributes, as every writer takes it.

/// The integer type of PLY's `vertex_indices` list, as the header names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum PlyIndex {
    /// `uint` (a mesh as read).
    #[default]
    UInt,
    /// `int` (the sampled surfaces of Sec. 6.2).
    Int,
}

/// A triangle mesh with optional per-vertex attributes, as the writers take it. An attribute
/// array that is empty is not written; which formats hold which attribute: OBJ positions and
/// normals (`vn`, faces `a//a`), OFF positions and normals (`NOFF`), PLY everything (with the
/// mean curvature also as vertex colours, clipped at its 98th percentile).
#[derive(Debug, Clone, Copy, Default)]
pub struct MeshOut<'a> {
    /// Vertex positions.
    pub positions: &'a [[f64; 3]],
    /// Unit normals (PLY writes them only when there is one per vertex).
    pub normals: &'a [[f64; 3]],
    /// Gaussian curvature per vertex (PLY, with normals and mean curvature).
    pub gaussian: &'a [f64],
    /// Mean curvature per vertex (PLY, with normals; also the colours).
    pub mean: &'a [f64],
    /// Triangles, 0-based indices into the per-vertex arrays.
    pub faces: &'a [[u32; 3]],
    /// A header comment (OBJ `# …`, PLY `comment …`; OFF has none).
    pub comment: Option<&'a str>,
    /// PLY's index type.
    pub ply_index: PlyIndex,
}

impl<'a> MeshOut<'a> {
    /// Positions and triangles only, with the header of a mesh as read
    /// (`comment written by pseudomanifold` in PLY).
    pub fn plain(positions: &'a [[f64; 3]], faces: &'a [[u32; 3]]) -> Self {
        MeshOut {
            positions,
            faces,
            comment: None,
            ..MeshOut::default()
        }
    }
}
