//! Integration tests, one binary per theme (each test binary links the whole crate, so
//! fewer binaries build faster): seed 002 adaptive fitting, seeds 003 (manifold splines) and
//! 004 (simplicial diffeomorphisms).

#[path = "../common/mod.rs"]
mod common;

mod fitting;
mod fitting_embedded;
mod fitting_local;
mod fitting_unblock;
mod fitting_unsimplify;
mod msplines;
mod sdiff_3d;
mod sdiff_sec6;
mod sdiff_spec;
