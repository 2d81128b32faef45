//! Typed element ids. Bare `usize` never crosses a module border: a vertex index cannot be
//! passed where a face index is meant.

use serde::Serialize;

macro_rules! id_type {
    ($(#[$m:meta])* $name:ident) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
        #[serde(transparent)]
        pub struct $name(pub u32);

        impl $name {
            /// The id as an index into the owning structure's arrays.
            #[inline]
            pub fn idx(self) -> usize {
                self.0 as usize
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                write!(f, "{}", self.0)
            }
        }
    };
}

id_type!(
    /// A vertex of the mesh (a 0-simplex of K; an element of the index set I of Ch. 4).
    VertexId
);
id_type!(
    /// A triangle of the mesh (a 2-simplex of K).
    FaceId
);
id_type!(
    /// A half-edge of the DCEL of Sec. 6.1.1.
    HalfedgeId
);
