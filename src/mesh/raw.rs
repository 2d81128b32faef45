//! The raw triangle list as read from a file, before any validation (Sec. 3.1 has not been
//! checked yet: this is a "set of simplices" that may or may not be a simplicial complex).

use std::path::PathBuf;

/// File formats the readers understand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MeshFormat {
    /// OFF (`.off`), ASCII.
    Off,
    /// Wavefront OBJ (`.obj`); only vertex (`v`) and face (`f`, `fo`) records are used.
    Obj,
    /// PLY, ASCII encoding.
    PlyAscii,
    /// PLY, binary little-endian encoding.
    PlyBinaryLittleEndian,
    /// PLY, binary big-endian encoding.
    PlyBinaryBigEndian,
}

/// A triangle list exactly as stored: no welding, no reordering, no removal of anything.
#[derive(Debug, Clone, Default)]
pub struct RawMesh {
    /// Vertex positions in file order.
    pub positions: Vec<[f64; 3]>,
    /// Triangles as 0-based vertex indices in file order. Indices are *not* yet checked to be
    /// in range: the validator reports every out-of-range index (check `indices_in_range`).
    pub faces: Vec<[u32; 3]>,
    /// For each face, where it came from: the 1-based source line for text formats, the
    /// 0-based face element index for binary PLY. Same length as `faces`.
    pub face_origin: Vec<u64>,
    /// For each vertex, its source line (text) or element index (binary). Same length as
    /// `positions`.
    pub vertex_origin: Vec<u64>,
    /// Provenance.
    pub source: Option<PathBuf>,
    /// The detected format, if read from a file.
    pub format: Option<MeshFormat>,
    /// Number of polygons with more than 3 sides that were fan-split (only with
    /// `--triangulate`; otherwise such polygons are an error).
    pub triangulated_polygons: u64,
    /// Whether `face_origin`/`vertex_origin` are lines (`true`) or element indices (`false`).
    pub origin_is_line: bool,
    /// Per-vertex scalar properties kept from the file besides the position (PLY vertex
    /// properties named in `io::ply::VERTEX_SCALARS`, e.g. the curvatures `ppm sample` writes),
    /// as (name, one value per vertex).
    pub vertex_scalars: Vec<(String, Vec<f64>)>,
}

impl RawMesh {
    /// A mesh built in code (tests, generators): origins are element indices.
    pub fn from_arrays(positions: Vec<[f64; 3]>, faces: Vec<[u32; 3]>) -> Self {
        let face_origin = (0..faces.len() as u64).collect();
        let vertex_origin = (0..positions.len() as u64).collect();
        RawMesh {
            positions,
            faces,
            face_origin,
            vertex_origin,
            source: None,
            format: None,
            triangulated_polygons: 0,
            origin_is_line: false,
            vertex_scalars: Vec::new(),
        }
    }

    /// "face 12 (line 40)" or "face 12" for generated meshes.
    pub fn describe_face(&self, f: usize) -> String {
        match (self.origin_is_line, self.face_origin.get(f)) {
            (true, Some(l)) => format!("face {f} (line {l})"),
            _ => format!("face {f}"),
        }
    }

    /// "vertex 3 (line 5)" or "vertex 3".
    pub fn describe_vertex(&self, v: usize) -> String {
        match (self.origin_is_line, self.vertex_origin.get(v)) {
            (true, Some(l)) => format!("vertex {v} (line {l})"),
            _ => format!("vertex {v}"),
        }
    }
}
