//! The conformance suite: every integration test in one binary, by theme. Each test binary
//! links the whole crate and instantiates its generic code again, so one binary builds faster
//! than one per theme (measured in docs/performance.md, "The test suite's build"), and its
//! tests share the two test threads instead of waiting for the slowest test of each binary.
//! `tests/verdicts` stays apart: it reads what this binary recorded, so it runs after it.
//!
//! One theme: `cargo test --test suite chapter4::` (or `gluing::`, `mesh::`, `seeds::`,
//! `surface::`).

#[path = "../common/mod.rs"]
mod common;

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
