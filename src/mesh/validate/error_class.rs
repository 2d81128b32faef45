//! The defect classes a validation reports, named as in the corpus manifest.

use serde::Serialize;

/// Defect classes, in the vocabulary of the corpus manifest (`error_classes`), plus the
/// input-sanity classes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ErrorClass {
    /// An edge in only one face, or a vertex whose link is a path (K has a boundary).
    Boundary,
    /// An edge in more than two faces (Def. 3.1.6).
    NonmanifoldEdge,
    /// A vertex whose link is not one cycle nor a path (Def. 3.1.6).
    NonmanifoldVertex,
    /// Two faces with the same vertex set.
    DuplicateFace,
    /// A face with a repeated corner, or three collinear corners (Def. 3.1.1).
    DegenerateFace,
    /// Two triangles meeting in more than a common face (Def. 3.1.3(ii)).
    SelfIntersection,
    /// Two distinct referenced vertices at the same position.
    CoincidentVertices,
    /// No consistent orientation of the faces exists.
    NonOrientable,
    /// A face index refers to a vertex that does not exist (Def. 3.1.3(i)).
    IndexOutOfRange,
    /// A vertex coordinate is NaN or infinite.
    NonFinite,
}

impl ErrorClass {
    /// The manifest's spelling.
    pub fn name(self) -> &'static str {
        match self {
            ErrorClass::Boundary => "boundary",
            ErrorClass::NonmanifoldEdge => "nonmanifold_edge",
            ErrorClass::NonmanifoldVertex => "nonmanifold_vertex",
            ErrorClass::DuplicateFace => "duplicate_face",
            ErrorClass::DegenerateFace => "degenerate_face",
            ErrorClass::SelfIntersection => "self_intersection",
            ErrorClass::CoincidentVertices => "coincident_vertices",
            ErrorClass::NonOrientable => "non_orientable",
            ErrorClass::IndexOutOfRange => "index_out_of_range",
            ErrorClass::NonFinite => "non_finite",
        }
    }
}
