//! Sec. 3.1: triangle meshes in, simplicial surfaces out.
//!
//! * [`io`] reads and writes OFF, OBJ and PLY into a [`RawMesh`] (no validation).
//! * [`validate`] runs the named checks of Sec. 3.1 and is the only way to obtain a
//!   [`SimplicialSurface`] — the type says the Def. 3.1.6 conditions were verified.
//! * [`halfedge`] is the DCEL of Sec. 6.1.1 with the labelling s_v of Sec. 6.1.2.

pub(crate) mod error;
pub mod generate;
pub(crate) mod halfedge;
pub(crate) mod ids;
pub mod io;
pub(crate) mod load;
pub mod raw;
pub mod star;
pub mod validate;

pub use error::{Location, MeshError};
pub use halfedge::SimplicialSurface;
pub use ids::{FaceId, HalfedgeId, VertexId};
pub use load::{load_surface, LoadError};
pub use raw::{MeshFormat, RawMesh};
