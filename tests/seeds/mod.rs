//! The conformance suite's theme: seed 002 adaptive fitting, seeds 003 (manifold splines) and
//! 004 (simplicial diffeomorphisms).

mod fitting;
mod fitting_embedded;
mod fitting_local;
mod fitting_unblock;
mod fitting_unsimplify;
mod msplines;
mod sdiff_3d;
mod sdiff_sec6;
mod sdiff_spec;
