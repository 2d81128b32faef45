//! The conformance suite, by theme, compiled into the library's unit-test binary (`src/lib.rs`
//! includes this file as the module `suite`): one compilation of the crate for its unit tests
//! and the suite together, which a clean `cargo test` on two cores no longer waits for at the
//! end (docs/performance.md, "The suite inside the library's test binary"). Its tests share the
//! two test threads with the unit tests. Integration tests of their own: `proofs/`, `tests/cli`
//! (the tests that run the `ppm` binary: cargo builds it from the same sources for them) and
//! `tests/verdicts` (it reads what the others recorded, so it runs after them).
//!
//! One theme: `cargo test --lib suite::chapter4::` (or `gluing::`, `mesh::`, `seeds::`,
//! `surface::`); the whole suite: `cargo test --lib suite::`.

#[path = "../common/mod.rs"]
pub(crate) mod common;

#[path = "../chapter4/mod.rs"]
mod chapter4;
#[path = "../gluing/mod.rs"]
mod gluing;
#[path = "../mesh/mod.rs"]
mod mesh;
#[path = "../seeds/mod.rs"]
mod seeds;
#[path = "../surface/mod.rs"]
mod surface;
