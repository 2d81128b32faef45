//! Conformance checks of Chapter 4 on configurations (no mesh needed).
//!
//! Every check is generic over the scalar `S` and over the model `M: Ppm<S>` (the paper's
//! construction is [`Paper`]; tests pass models with planted faults). Every check samples
//! deterministically from `seed`, and reports the number of samples examined (with per-category
//! counts in the note), the worst deviation, and the tolerance used. Tolerances are
//! `COND · ε` with ε the unit roundoff of the precision in use and `COND` a named, stated
//! condition factor; they are never tuned to make a check pass.
//!
//! Statements that fail as written are reported as `Fails` with witnesses; where the paper's
//! statement holds on a smaller domain, a second result with the suffix `[restricted]` checks
//! it there and reports `HoldsRestricted { domain }`.

mod common;
mod edge;
mod edge_maps;
mod polar;
mod samples;
mod smooth;
mod star;
mod triangle;

pub use edge::*;
pub use edge_maps::*;
pub use polar::*;
pub use star::*;
pub use triangle::*;

pub use common::{
    inconclusive_search, membership, origin, COMPOSITE_COND, FD_COND, GV_COND, IDENTITY_COND,
    JUMP_COND, MIN_EMPTINESS_SAMPLES,
};
