//! The tests that run the `ppm` binary: an integration-test binary of their own, so that cargo
//! builds `ppm` from the same sources before them and hands its path over (`CARGO_BIN_EXE_ppm`).
//! Every other test of the suite is compiled into the library's unit-test binary
//! (`tests/suite/main.rs`, see there), where that guarantee does not exist: a `ppm` found on disk
//! there could be older than the code under test. One file per file of the suite these tests
//! came from, under the same theme, name and test path (`suite/THEME/FILE.rs`).
//!
//! `cargo test --test cli` runs them all; `cargo test suite::surface::` a theme in both binaries.

#[path = "../common/mod.rs"]
mod common;

mod suite;
