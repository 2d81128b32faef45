//! Upper bounds on what a file may declare, so hostile headers fail fast.

/// Upper bounds on declared element counts. A header announcing more is
/// [`MeshError::TooLarge`](crate::mesh::MeshError::TooLarge) before anything is allocated.
/// Independently of these limits, every preallocation is capped by what the remaining bytes
/// of the file could hold.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Maximum number of vertices (default 50 million).
    pub max_vertices: u64,
    /// Maximum number of faces, counted as declared polygons (default 50 million).
    pub max_faces: u64,
    /// Maximum number of instances of any other PLY element (default 50 million).
    pub max_other_elements: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_vertices: 50_000_000,
            max_faces: 50_000_000,
            max_other_elements: 50_000_000,
        }
    }
}
